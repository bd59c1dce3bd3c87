"""The commands' output files: checked before the work, written whole beside
their target and moved into place (:mod:`burmester._io`), pictures by
matplotlib and CAD exports by :mod:`burmester.export`."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Sequence, Tuple

from burmester import _io
from burmester.cli.base import UsageError
from burmester.taskfile import TaskSpec

if TYPE_CHECKING:
    from types import ModuleType

#: File types ``map`` and ``linkage`` draw still pictures in.
PICTURE_TYPES = (".png", ".svg", ".pdf", ".jpg", ".jpeg", ".tif", ".tiff", ".eps", ".ps")
#: File types ``linkage`` writes animations in.
ANIMATION_TYPES = (".gif", ".mp4")
#: File types ``map`` and ``linkage`` write CAD exports in (:mod:`burmester.export`),
#: not matplotlib pictures: ``.svg`` is one of them.
CAD_TYPES = (".dxf", ".svg")


def _plot_module() -> ModuleType:
    """``burmester.plot`` with the Agg backend (files only, no windows)."""
    try:
        import matplotlib
    except ImportError:
        raise ImportError(
            'this command draws pictures and needs matplotlib: pip install "burmester[plot]"'
        ) from None
    matplotlib.use("Agg")
    import burmester.plot as plot

    return plot


def _written(path: str, force: bool, write: Callable[[Path], Any]) -> None:
    """Write an output by ``write(tmp)`` through :mod:`burmester._io`: whole
    to a temporary file beside it, moved into place when complete, never
    replacing an existing file without ``--force`` (decided at the move);
    on an error or Ctrl-C nothing is left and an existing file is kept."""
    try:
        with _io.atomic_path(path, overwrite=force) as tmp:
            write(tmp)
    except FileExistsError:
        raise UsageError(
            f"{path} exists (it was created while this command ran); give another file name, "
            "or --force to replace it"
        ) from None
    except OSError as e:
        kept = f"; {path} is unchanged" if Path(path).exists() else ""
        raise UsageError(f"cannot write {path}: {e.strerror or e}{kept}") from None


def _save(fig: Any, path: str, dpi: int, force: bool) -> None:
    import matplotlib.pyplot as plt

    try:
        _written(path, force, lambda tmp: fig.savefig(tmp, dpi=dpi, bbox_inches="tight"))
    finally:
        plt.close(fig)


def _types(*groups: Sequence[str]) -> Tuple[str, ...]:
    """The file types of ``groups``, each once, in order."""
    return tuple(dict.fromkeys(t for g in groups for t in g))


def _is_cad(path: str) -> bool:
    return Path(path).suffix.lower() in CAD_TYPES


def _export_module(path: str) -> ModuleType:
    """``burmester.export``, with ezdxf checked for a ``.dxf`` before any work."""
    import burmester.export as export

    if Path(path).suffix.lower() == ".dxf":
        try:
            import ezdxf  # noqa: F401
        except ImportError:
            raise ImportError('writing .dxf needs ezdxf: pip install "burmester[plot]"') from None
    return export


def _units(args: argparse.Namespace, spec: TaskSpec) -> str:
    """The unit a CAD export records: the task's (``--units``, else the
    task file's ``units``), else mm; ``--dpi`` refused for a CAD export."""
    if args.dpi is not None and _is_cad(args.output):
        raise UsageError(
            f"--dpi is for pictures (.png, .pdf, ...); a CAD export ({args.output}) has exact coordinates"
        )
    return spec.units if spec.units is not None else "mm"


#: ``--dpi`` of ``map`` and ``linkage`` when not given.
DEFAULT_DPI = 100


def _picture_dpi(args: argparse.Namespace) -> int:
    return DEFAULT_DPI if args.dpi is None else int(args.dpi)


def _write_cad(write: Callable[..., Any], out: str, force: bool, *args: Any, **kwargs: Any) -> None:
    """Call an export function with the output ``out`` (among ``args``)
    through :func:`_written`."""
    _written(out, force, lambda tmp: write(*(tmp if a is out else a for a in args), **kwargs))


def _output(path: str, types: Sequence[str], force: bool) -> str:
    """Check an output file name before any work: one of ``types``, in a
    folder that exists, not a folder itself, and not an existing file unless
    ``force`` (one policy for every command: never overwrite silently)."""
    listed = ", ".join(types)
    if path == "-":
        raise UsageError(f"-o - (standard output) is not supported here; give a file name ending in {listed}")
    p = Path(path)
    if p.is_dir():
        raise UsageError(f"{path} is a folder; give a file name in it, such as {p / ('out' + types[0])}")
    if p.suffix.lower() not in types:
        got = f"'{p.suffix}'" if p.suffix else "no extension"
        raise UsageError(f"-o {path} has {got}; end the file name in one of {listed}")
    if not p.parent.is_dir():
        raise UsageError(f"cannot write {path}: the folder {str(p.parent)!r} does not exist")
    if p.exists() and not force:
        raise UsageError(f"{path} exists; give another file name, or --force to replace it")
    return path
