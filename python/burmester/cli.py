"""The ``burmester`` command line (also ``python -m burmester``).

Commands::

    burmester design [TASK.toml] -o best.png  # the best linkage for the poses (and [space]): both pivots searched
    burmester map [TASK.toml] -o map.png      # the center-point plane (Fig. 10/12)
    burmester map five.toml -o five.png       # four or five poses: the Burmester curve or points
    burmester pivots [TASK.toml] --top 5      # the best driving pivots, as a table (--json)
    burmester linkage [TASK.toml] -o l.gif    # a four-bar at the poses (.png) or animated (.gif/.mp4)
    burmester map -o plane.dxf                # CAD export (.dxf or .svg): a layer per concept
    burmester linkage -o linkage.dxf --travel 12
    burmester atlas [TASK.toml] -o atlas.png  # both pivots at once: the best driving pivot per driven center
    burmester batch A.toml B.toml --top 5     # each task's best pivots, one JSON line per file
    burmester solve --ground 100 --crank 40 --coupler 120 --rocker 80 --theta2 40
    burmester drive [TASK.toml] -o six.gif    # a motor for the best linkage (an added dyad: a six-bar)
    burmester example > task.toml             # a task file to start from

Without a task file, the commands use the built-in example. Without any
arguments, ``burmester`` prints this help. Bad input exits with status 2 and
a one-line message saying what to change; a missing optional dependency
(matplotlib, ezdxf) exits with status 1. No command replaces an existing file
unless given ``--force``, decided when the finished file is moved into place
(:mod:`burmester._io`): outputs are written whole beside their target, so a
write error, a full disk or Ctrl-C leaves no partial file and keeps an
existing one.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import os
import signal
import sys
import threading
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any, Callable, Dict, List, Literal, NoReturn, Optional, Sequence, Tuple

import numpy as np

import burmester
from burmester import _io
from burmester import pivots as pv
from burmester import taskfile
from burmester._burmester import Grid, Pivot
from burmester.taskfile import TaskFileError, TaskSpec, describe_outside, outside_view
from burmester.units import check_units, format_length

if TYPE_CHECKING:
    from types import ModuleType

    from burmester._burmester import Mode, Progress

#: The built-in example four-bar: Norton, *Design of Machinery*, Example 4-1 (mm).
#: ``(ground, crank, coupler, rocker)``.
EXAMPLE_FOURBAR = (100.0, 40.0, 120.0, 80.0)

#: A branch map of at least this many samples shows a progress bar on stderr
#: when it is a terminal; a solution map (about sixteen times the work per
#: sample) from a sixteenth of it.
PROGRESS_MIN_POINTS = 2_000_000


class UsageError(Exception):
    """Bad command-line input; the message says what to change."""


class _Parser(argparse.ArgumentParser):
    """An ArgumentParser whose errors are one line (and exit status 2)."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


# ---------------------------------------------------------------------------
# Progress


class ProgressBar:
    """A progress bar with the share done, the rate and the time left, drawn
    in place on a terminal stream by tqdm.

    It is the ``progress(done, total)`` hook of the core's sweeps
    (:meth:`burmester.Filemon.branch_map`, :meth:`~burmester.Filemon.solution_map`):
    the sweep runs as one call, so its samples are those of a call without
    a bar, bit for bit. The bar opens on the first call and closes (ending
    its line) when all rows are done, or on :meth:`close`.
    """

    def __init__(self, stream: IO[str], label: str, unit: str = "row", mininterval: float = 0.1) -> None:
        self.stream = stream
        self.label = label
        self.unit = unit
        self.mininterval = mininterval
        self._bar: Any = None

    def __call__(self, done: int, total: int) -> None:
        """Show ``done`` of ``total`` rows."""
        if self._bar is None:
            from tqdm import tqdm

            self._bar = tqdm(total=total, desc=self.label, unit=self.unit, file=self.stream,
                             leave=True, dynamic_ncols=True, mininterval=self.mininterval)
        bar = self._bar
        if bar.disable:  # closed: the sweep is done
            return
        step = min(max(done, 0), total) - bar.n
        if step > 0:
            bar.update(step)
        if done >= total:
            bar.close()

    def close(self) -> None:
        """End the bar's line (an interrupted sweep leaves it open)."""
        if self._bar is not None:
            self._bar.close()


def progress_for(grid: Grid, label: str, work_per_sample: int = 1) -> Optional[Progress]:
    """A :class:`ProgressBar` on stderr for a sweep of ``grid`` that is large
    enough to wait for (``work_per_sample``: 16 for a solution map), when
    stderr is a terminal; else None."""
    big = grid.size * work_per_sample >= PROGRESS_MIN_POINTS
    return ProgressBar(sys.stderr, f"burmester: {label}") if big and sys.stderr.isatty() else None


# ---------------------------------------------------------------------------
# Helpers


def _load(path: Optional[str]) -> TaskSpec:
    return taskfile.example() if path is None else taskfile.load(path)


def _with_grid(spec: TaskSpec, grid: Optional[Sequence[int]]) -> TaskSpec:
    if grid is None:
        return spec
    nx, ny = grid
    for name, n in (("NX", nx), ("NY", ny)):
        if not 2 <= n <= 20000:
            raise UsageError(f"--grid {name} must be from 2 to 20000, got {n}")
    v = spec.view
    view = Grid(v.xmin, v.xmax, v.ymin, v.ymax, nx, ny)
    return dataclasses.replace(spec, view=view)


def _with_units(spec: TaskSpec, args: argparse.Namespace) -> TaskSpec:
    """The task with ``--units`` (any unit name) in place of the task
    file's ``units``, when given."""
    given = getattr(args, "units", None)
    if given is None:
        return spec
    try:
        units = check_units(given, "--units")
    except burmester.InvalidInputError as e:
        raise UsageError(str(e)) from None
    return dataclasses.replace(spec, units=units)


def _lengths_in(spec: TaskSpec) -> str:
    """``", lengths in mm"`` for a task with units; ``""`` without."""
    return f", lengths in {spec.units}" if spec.units else ""


def _limits_text(spec: TaskSpec) -> str:
    """Every limit of the task in words, lengths in its unit
    (:func:`burmester.pivots.describe_limits`): what a table prints beside
    its verdicts."""
    return pv.describe_limits(spec.limits, spec.units)


def _outside_note(spec: TaskSpec, points: Sequence[Tuple[str, Optional[Sequence[float]]]]) -> str:
    """``"; B3 (...) lies outside the view x [..], y [..]"`` for the named
    points outside the task's view (``""`` when all are in it): what a
    summary adds so that nothing is silently left out of a picture."""
    text = describe_outside(outside_view(points, spec.view.extent), spec.view.extent, spec.units)
    return f"; {text}" if text else ""


def _solution_map(spec: TaskSpec, filemon: burmester.Filemon) -> burmester.SolutionMap:
    """The solution-space map of the task's view under its limits, with a
    progress bar when it is large."""
    return filemon.solution_map(
        spec.view, limits=spec.limits, progress=progress_for(spec.view, "solution map", 16)
    )


def _spacing(spec: TaskSpec, spacing: Optional[float]) -> float:
    """The least distance between listed pivots: given, or a tenth of the view."""
    if spacing is None:
        return pv.default_spacing(spec.view)
    if not spacing >= 0.0:
        raise UsageError(f"--spacing must be at least 0, got {spacing:g}")
    return spacing


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


#: File types ``map`` and ``linkage`` draw still pictures in.
PICTURE_TYPES = (".png", ".svg", ".pdf", ".jpg", ".jpeg", ".tif", ".tiff", ".eps", ".ps")
#: File types ``linkage`` writes animations in.
ANIMATION_TYPES = (".gif", ".mp4")
#: File types ``map`` and ``linkage`` write CAD exports in (:mod:`burmester.export`),
#: not matplotlib pictures: ``.svg`` is one of them.
CAD_TYPES = (".dxf", ".svg")


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


def table(columns: Sequence[Tuple[str, str]], rows: Sequence[Sequence[str]]) -> str:
    """A text table drawn by rich: ``columns`` are ``(header, justify)``
    with justify ``"left"`` or ``"right"``, ``rows`` the cells as text.
    ASCII only, columns apart by ``|``, a rule under the header, as wide as
    its content (not cut to the terminal: the output is for pipes too),
    without trailing spaces."""
    import io

    from rich import box
    from rich.console import Console
    from rich.table import Table

    t = Table(box=box.ASCII2, show_edge=False, pad_edge=False, highlight=False)
    for header, justify in columns:
        t.add_column(header, justify="right" if justify == "right" else "left", no_wrap=True)
    for row in rows:
        t.add_row(*row)
    buf = io.StringIO()
    Console(file=buf, width=100_000, color_system=None, highlight=False, emoji=False, markup=False,
            force_terminal=False, legacy_windows=False).print(t)
    return "\n".join(line.rstrip() for line in buf.getvalue().splitlines())


# ---------------------------------------------------------------------------
# Memory: what cannot fit is refused before the work


#: What a command holds at its peak besides its grid (the interpreter,
#: NumPy, matplotlib), bytes.
MEMORY_BASE = 128 * 2**20

#: Peak bytes per grid sample (measured with ``ru_maxrss`` on 1000 x 1000
#: and 2000 x 2000 grids, rounded up): a picture of the center-point plane
#: (the branch map and matplotlib's image buffers, about 60), with the
#: solution map overlaid (about 110), a CAD export (about 30), a solution
#: map ranked (``pivots``, ``linkage``: about 20).
MEMORY_PER_SAMPLE = {"picture": 64, "picture+design": 128, "cad": 32, "cad+design": 64, "ranking": 32}


def _available_memory() -> Optional[int]:
    """Bytes this process can still allocate: the memory the system has
    available (``MemAvailable``) and what an address-space limit leaves,
    whichever is less; None where neither can be read."""
    avail: Optional[int] = None
    try:
        with open("/proc/meminfo", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    avail = int(line.split()[1]) * 1024
    except (OSError, ValueError):
        pass
    try:
        import resource

        soft, _ = resource.getrlimit(resource.RLIMIT_AS)
        if soft != resource.RLIM_INFINITY:
            used = 0
            with open("/proc/self/status", encoding="ascii") as fh:
                for line in fh:
                    if line.startswith("VmSize:"):
                        used = int(line.split()[1]) * 1024
            left = max(0, soft - used)
            avail = left if avail is None else min(avail, left)
    except (ImportError, OSError, ValueError):
        pass
    return avail


def _fmt_bytes(n: float) -> str:
    return f"{n / 2**30:.1f} GB" if n >= 2**30 else f"{n / 2**20:.0f} MB"


def _check_memory(nx: int, ny: int, kind: str, what: str, flag: str) -> None:
    """Refuse up front a grid of ``nx`` by ``ny`` samples whose work of
    ``kind`` (:data:`MEMORY_PER_SAMPLE`) cannot fit in the memory left,
    saying how much it needs and what fits."""
    per = MEMORY_PER_SAMPLE[kind]
    need = MEMORY_BASE + nx * ny * per
    avail = _available_memory()
    if avail is None or need <= avail:
        return
    side = max(2, math.isqrt(max(0, avail - MEMORY_BASE) // per))
    raise UsageError(
        f"{what} on {nx} x {ny} samples needs about {_fmt_bytes(need)} of memory ({per} bytes a "
        f"sample), more than the {_fmt_bytes(avail)} available; use a coarser {flag} (about "
        f"{side} x {side} fits)"
    )


def _fmt_point(p: Sequence[float]) -> str:
    """``(x, y)`` to three decimals; a coordinate that rounds to zero reads
    0.000, not -0.000."""
    x, y = (round(v, 3) + 0.0 for v in p[:2])
    return f"({x:.3f}, {y:.3f})"


# ---------------------------------------------------------------------------
# Commands


def cmd_map(args: argparse.Namespace) -> int:
    """``burmester map``: draw the center-point (or circle-point) plane."""
    spec = _with_units(_with_grid(_load(args.task), args.grid), args)  # the task file's errors first
    _output(args.output, _types(PICTURE_TYPES, CAD_TYPES), args.force)
    units = _units(args, spec)
    cad = _is_cad(args.output)
    if len(spec.poses) == 3:  # the grid is the branch map's (four and five poses trace curves)
        design = "+design" if args.design or args.pivots > 0 else ""
        _check_memory(spec.view.nx, spec.view.ny, ("cad" if cad else "picture") + design,
                      f"drawing {args.output}", "--grid")
    export = _export_module(args.output) if cad else None
    plot = None if cad else _plot_module()
    if len(spec.poses) > 3:
        return _map_many(args, spec, plot, export, units)
    filemon = spec.filemon()
    view = spec.view
    if args.plane == "circle":
        if export is not None:
            _write_cad(export.plane, args.output, args.force, filemon, args.output, plane="circle",
                       units=units)
        else:
            assert plot is not None
            ax = plot.circle_plane(filemon, units=spec.units)
        summary = f"circle-point plane of {spec.source}{_lengths_in(spec)}"
    else:
        smap = _solution_map(spec, filemon) if args.design or args.pivots > 0 else None
        if smap is not None and args.method == "conic":
            free = smap.branch_free  # the branch map, computed once (with the solution map)
        else:
            free = filemon.branch_map(
                view, method=args.method, progress=progress_for(view, "branch map")
            )
        marks = None
        acceptable = transmission = None
        if args.design and smap is not None:
            acceptable = smap.acceptable
            transmission = np.degrees(smap.min_transmission_rad)
        if args.pivots > 0 and smap is not None:
            ranked, _ = pv.rank(smap, args.pivots, pv.default_spacing(view))
            marks = [p.center for p in ranked]
        if export is not None:
            _write_cad(export.plane, args.output, args.force, filemon, args.output, view, free=free, pivots=marks,
                       acceptable=acceptable, transmission=transmission, units=units)
        else:
            assert plot is not None
            ax = plot.center_plane(
                filemon, view, free=free, pivots=marks, acceptable=acceptable, transmission=transmission,
                units=spec.units,
            )
        summary = (
            f"center-point plane of {spec.source}{_lengths_in(spec)}: {100 * free.mean():.1f}% of the "
            f"{view.nx} x {view.ny} grid is branch-free"
        )
        if smap is not None:
            summary += f", {100 * np.mean(smap.acceptable):.1f}% acceptable ({_limits_text(spec)})"
        task = filemon.task
        summary += _outside_note(spec, [(f"P{p.pair[0]}{p.pair[1]}", p.point) for p in task.poles]
                                 + [("C0", filemon.driven_center)])
    if export is None:
        _save(ax.figure, args.output, _picture_dpi(args), args.force)
    print(f"wrote {args.output}: {summary}")
    return 0


def _map_many(args: argparse.Namespace, spec: TaskSpec, plot: Optional[ModuleType],
              export: Optional[ModuleType], units: str) -> int:
    """``burmester map`` of four or five poses: the center-point curve
    coloured by crank order, or the Burmester points on their curves (a
    picture with ``plot``, a CAD export with ``export``)."""
    n = len(spec.poses)
    circle = args.plane == "circle"
    for flag, given in (("--plane circle", circle and n == 5), ("--design", args.design),
                        ("--pivots", args.pivots > 0)):
        if given:
            what = ("three poses (Filemon's construction) or four (the circle-point curve)"
                    if flag == "--plane circle" else "three poses (Filemon's construction)")
            raise UsageError(f"{flag} is for {what}; {spec.source} has {n} poses")
    task = spec.task
    driven = spec.driven_center  # four poses: a driven dyad on the curve, or None
    if export is not None:
        _write_cad(export.burmester_plane, args.output, args.force, task, args.output, spec.view.extent,
                   driven=driven, plane=args.plane, units=units)
    elif circle:
        assert plot is not None
        ax = plot.circle_curve_plane(task, spec.view.extent, driven=driven, units=spec.units)
    else:
        assert plot is not None
        ax = plot.burmester_plane(task, spec.view.extent, driven=driven, units=spec.units)
    if n == 4:
        plane: Literal["center", "circle"] = "circle" if circle else "center"
        arcs = task.order_arcs(*spec.view.extent, plane=plane)
        ordered = sum(1 for _, d, _ in arcs if d is not None)
        summary = (
            f"{plane}-point curve of {spec.source}{_lengths_in(spec)}: {len(arcs)} pieces in "
            f"view, {ordered} of them with the crank meeting the poses in order"
        )
        if driven is not None:
            free = task.branch_free_arcs(driven, *spec.view.extent, plane=plane)
            summary += (f"; {len(free)} arcs of driving dyads branch-free with the driven dyad at C0 "
                        f"{_fmt_point(driven)}")
    else:
        pts = task.burmester_points()
        listed = ", ".join(_fmt_point(c) for c, _ in pts)
        summary = (f"Burmester points of {spec.source}{_lengths_in(spec)}: {len(pts)}"
                   + (f": {listed}" if pts else ""))
    summary += _outside_note(spec, taskfile.curve_plane_points(task, driven, args.plane))
    if export is None:
        _save(ax.figure, args.output, _picture_dpi(args), args.force)
    print(f"wrote {args.output}: {summary}")
    return 0


#: Default driven and driving grids of ``burmester atlas`` (over the task's view).
ATLAS_DRIVEN_GRID = (24, 24)
ATLAS_DRIVING_GRID = (80, 80)


def _atlas_client(address: Optional[str]) -> Any:
    if address is None:
        return None
    try:
        import importlib

        distributed = importlib.import_module("distributed")
    except ImportError:
        raise ImportError('--scheduler needs Dask: pip install "burmester[dask]"') from None
    try:
        return distributed.Client(address, timeout=10)
    except (OSError, TimeoutError) as e:
        raise UsageError(f"cannot reach the Dask scheduler at {address}: {e}") from None


def cmd_atlas(args: argparse.Namespace) -> int:
    """``burmester atlas``: the best driving pivot for every driven center."""
    output = args.output if args.output is not None else (None if args.json else "atlas.png")
    spec = _with_units(_load(args.task), args)  # the task file's errors first
    if output is not None:
        _output(output, PICTURE_TYPES, args.force)
    v = spec.view
    grids = []
    for flag, given, default in (("--driven-grid", args.driven_grid, ATLAS_DRIVEN_GRID),
                                 ("--driving-grid", args.driving_grid, ATLAS_DRIVING_GRID)):
        nx, ny = given if given is not None else default
        for name, n in (("NX", nx), ("NY", ny)):
            if not 2 <= n <= 4000:
                raise UsageError(f"{flag} {name} must be from 2 to 4000, got {n}")
        grids.append(Grid(v.xmin, v.xmax, v.ymin, v.ymax, nx, ny))
    driven, driving = grids
    plot = _plot_module() if output is not None else None
    client = _atlas_client(args.scheduler)
    bar = progress_for(driven, "atlas", driving.size) if client is None else None
    try:
        atlas = burmester.pivot_atlas(spec.task, driven, driving, client=client,
                                      limits=spec.limits, rank_by=args.rank_by, progress=bar)
    except TimeoutError as e:  # a cluster without workers
        raise UsageError(str(e)) from None
    finally:
        if client is not None:
            client.close()
    best = atlas.best_pairs(1)
    if args.json:
        lim = spec.limits
        doc = {
            "task": spec.source,
            "units": spec.units,
            "driven_grid": [driven.nx, driven.ny],
            "driving_grid": [driving.nx, driving.ny],
            "view": {"x": [v.xmin, v.xmax], "y": [v.ymin, v.ymax]},
            "limits": pv.limits_dict(lim),
            "ranking": atlas.rank_by,
            "valid": int(atlas.valid.sum()),
            "with_acceptable": int(np.count_nonzero(atlas.count)),
            "best": [p._asdict() for p in atlas.best_pairs(args.top)],
        }
        print(json.dumps(doc, indent=2))
    if plot is not None and output is not None:
        ax = plot.atlas(atlas, units=spec.units)
        ax.set_title(f"pivot-pair atlas of {spec.source}")
        _save(ax.figure, output, args.dpi, args.force)
        summary = (f"{int(np.count_nonzero(atlas.count))} of {driven.size} driven centers "
                   f"have an acceptable driving pivot ({_limits_text(spec)}{_lengths_in(spec)}); "
                   f"{pv.describe_ranking(atlas.rank_by)}")
        if best:
            summary += (f"; best at C0 {_fmt_point(best[0].driven)}, A0 {_fmt_point(best[0].driving)}: "
                        f"{best[0].min_transmission_deg:.1f} deg, {best[0].size_ratio:.1f}x the task's size")
        print(f"wrote {output}: {summary}", file=sys.stderr if args.json else sys.stdout)
    return 0


def pivot_table(spec: TaskSpec, pivots: Sequence[Pivot], ranked_by: str = "balanced") -> str:
    """The text table of ``burmester pivots``: a line naming the ranking,
    the table (:func:`table`), a line saying what the columns mean."""
    head = pv.describe_ranking(ranked_by)
    if ranked_by != "margin":
        head += " (acceptable under the limits)"
    span = spec.task.span
    columns = [("#", "right"), ("A0 (x, y)", "right"), ("size", "right"), ("margin", "right"),
               ("ground", "right"), ("crank", "right"), ("coupler", "right"), ("rocker", "right"),
               ("Grashof type", "left"), ("mu min", "right"), ("mu1", "right"), ("mu2", "right"),
               ("mu3", "right"), ("drive", "left"), (_limits_text(spec), "left")]
    rows = []
    for k, p in enumerate(pivots, start=1):
        f = p.figures
        mus = [f"{m:.0f}" if m is not None else "-" for m in pv.transmission_at_poses_deg(p.linkage)]
        mt = f"{f.min_transmission_deg:.1f}" if f.min_transmission_deg is not None else "-"
        drive = f"{f.direction} {f.modes[0] or ''}".strip()
        bad = pv.linkage_violations(p.linkage, spec.limits, spec.units)
        rows.append([str(k), _fmt_point(p.center), _fmt_size(p.size_ratio), f"{p.margin:.3f}",
                     *(f"{v:.3f}" for v in f.lengths), f.grashof, mt, *mus, drive, "; ".join(bad) or "ok"])
    lines = [
        f"Driving pivots A0 for {spec.source} (task size {format_length(span, spec.units, 3)}: the largest "
        f"distance between two poses{_lengths_in(spec)}), {head}",
        table(columns, rows),
    ]
    if not pivots:
        lines.append("(no branch-free pivot in the view)")
    c0 = spec.filemon().driven_center
    outside = describe_outside(outside_view([("the driven pivot C0", c0)], spec.view.extent), spec.view.extent,
                               spec.units)
    if outside:
        lines.append(f"note: {outside} (the view is where A0 is searched; C0 is the task's)")
    lines.append(
        "size: the total length of the links (the coupler as its triangle with the coupler "
        "point) in task sizes. mu min: smallest transmission angle over the travel 1 -> 2 -> 3; "
        "mu1-3: at the poses (degrees). drive: input rotation and assembly mode. ok: meets the "
        "limits in the header"
    )
    return "\n".join(lines)


def _fmt_size(ratio: float) -> str:
    """A size ratio as ``12.3x``."""
    return f"{ratio:.1f}x"


def burmester_table(spec: TaskSpec, ranked: Sequence[pv.BurmesterLinkage], ranked_by: str) -> str:
    """The text table of ``burmester pivots`` for five poses: the ranking,
    the Burmester points, the table of their four-bars (:func:`table`),
    what the columns mean."""
    task = spec.task
    points = task.burmester_points()
    extent = spec.view.extent
    lines = [
        f"Four-bars of the {len(points)} Burmester points of {spec.source} (task size "
        f"{format_length(task.span, spec.units, 3)}{_lengths_in(spec)}), {pv.describe_ranking(ranked_by)}, "
        "acceptable ones first",
    ]
    lines += [f"  B{k}: center {_fmt_point(c)}, circle point {_fmt_point(z)}"
              + ("" if taskfile.in_view(c, extent) else " (outside the view)")
              for k, (c, z) in enumerate(points, start=1)]
    columns = [("#", "right"), ("drive", "right"), ("size", "right"), ("ground", "right"),
               ("crank", "right"), ("coupler", "right"), ("rocker", "right"), ("Grashof type", "left"),
               ("mu min", "right"), ("ratio", "right"), ("motion", "left"), (_limits_text(spec), "left")]
    rows = []
    for k, b in enumerate(ranked, start=1):
        f = b.linkage.figures
        mt = f"{f.min_transmission_deg:.1f}" if f.min_transmission_deg is not None else "-"
        motion = f"{f.direction} {f.modes[0] or ''}".strip() if f.branch_free else "branch defect"
        rows.append([str(k), f"B{b.driving + 1} -> B{b.driven + 1}", _fmt_size(b.linkage.size_ratio),
                     *(f"{v:.3f}" for v in f.lengths), f.grashof, mt, f"{f.link_ratio:.1f}", motion,
                     "; ".join(b.violations) or "ok"])
    lines.append(table(columns, rows))
    if not ranked:
        lines.append("(no Burmester four-bar: the task has fewer than two real Burmester points)")
    outside = describe_outside(outside_view([(f"B{k}", c) for k, (c, _) in enumerate(points, start=1)], extent),
                               extent, spec.units)
    if outside:
        lines.append(f"note: {outside}; 'burmester map' draws only the view: widen [view] to see all")
    lines.append("drive: the driving dyad's Burmester point -> the driven one's. size: the total length of the "
                 "links in task sizes. mu min: smallest transmission angle over the travel through the five "
                 "poses. ok: meets the limits in the header")
    return "\n".join(lines)


def _pivots_five(args: argparse.Namespace, spec: TaskSpec) -> int:
    """``burmester pivots`` of five poses: the four-bars of the Burmester points."""
    if args.rank_by == "pareto":
        raise UsageError("five poses have at most twelve Burmester four-bars, listed whole: rank them by "
                         "balanced, transmission or compact")
    if args.json:
        print(json.dumps(pv.report_burmester(spec, args.rank_by), indent=2))
    else:
        ranked = pv.rank_burmester(spec.task, spec.limits, args.rank_by)
        print(burmester_table(spec, ranked[: args.top], args.rank_by))
    return 0


def cmd_pivots(args: argparse.Namespace) -> int:
    """``burmester pivots``: rank the branch-free driving pivots (five
    poses: the four-bars of the Burmester points)."""
    spec = _with_units(_load(args.task), args)
    if len(spec.poses) == 5:
        return _pivots_five(args, spec)
    spec = _with_grid(spec, args.grid)
    _check_memory(spec.view.nx, spec.view.ny, "ranking", "the solution map", "--grid")
    spacing = _spacing(spec, args.spacing)
    if args.json:
        doc = pv.report(spec, args.top, spacing, progress_for(spec.view, "solution map", 16), args.rank_by)
        print(json.dumps(doc, indent=2))
    else:
        smap = _solution_map(spec, spec.filemon())
        pivots, ranked_by = pv.rank(smap, args.top, spacing, args.rank_by)
        print(pivot_table(spec, pivots, ranked_by))
    return 0


def cmd_batch(args: argparse.Namespace) -> int:
    """``burmester batch``: each task file's best pivots, one JSON line each
    (the document of ``burmester pivots --json``, or ``{"task", "error"}``);
    status 2 when any file failed, after all of them ran."""
    if args.spacing is not None and not args.spacing >= 0.0:
        raise UsageError(f"--spacing must be at least 0, got {args.spacing:g}")
    client = _atlas_client(args.scheduler)
    try:
        records = burmester.best_pivots_batch(args.tasks, client=client, top=args.top,
                                              spacing=args.spacing, rank_by=args.rank_by)
    except TimeoutError as e:  # a cluster without workers
        raise UsageError(str(e)) from None
    finally:
        if client is not None:
            client.close()
    failed = 0
    for rec in records:
        print(json.dumps(rec), flush=True)
        if "error" in rec:
            failed += 1
            print(f"burmester batch: error: {rec['error']}", file=sys.stderr)
    return 2 if failed else 0


def cmd_linkage(args: argparse.Namespace) -> int:
    """``burmester linkage``: draw or animate the four-bar of one driving pivot."""
    spec = _with_units(_load(args.task), args)  # the task file's errors first
    _output(args.output, _types(PICTURE_TYPES, CAD_TYPES, ANIMATION_TYPES), args.force)
    units = _units(args, spec)
    out: str = args.output
    cad = _is_cad(out)
    animated = out.lower().endswith(ANIMATION_TYPES)
    for flag, given in (("--frames", args.frames), ("--fps", args.fps)):
        if given is not None and not animated:
            extra = "; for a CAD export, --travel N draws the linkage at N positions" if cad else ""
            raise UsageError(f"{flag} is for animations (.gif, .mp4), not {out}{extra}")
    if args.travel is not None and not cad:
        raise UsageError(f"--travel is for CAD exports (.dxf, .svg), not {out}; animate with -o linkage.gif")
    export = _export_module(out) if cad else None
    if len(spec.poses) == 5:
        sfb, what = _best_burmester_linkage(args, spec)
        task = spec.task
    elif len(spec.poses) == 4:
        if args.pivot is not None:
            raise UsageError("--pivot is for three poses; a four-pose task draws its best pair of dyads "
                             "(see 'burmester pairs')")
        task = spec.task
        best_pairs = _pair_map(spec, PAIR_SAMPLES).best_pairs(1)
        if not best_pairs:
            raise UsageError(f"no acceptable pair of dyads for {spec.source} ({_limits_text(spec)}); "
                             "see 'burmester pairs'")
        sfb = best_pairs[0].linkage
        what = f"the best pair of dyads, driving pivot A0 = {_fmt_point(best_pairs[0].driving.center)}"
    else:
        filemon = spec.filemon()
        if args.pivot is None:
            best, _ = pv.rank(_solution_map(spec, filemon), 1, pv.default_spacing(spec.view))
            if not best:
                raise UsageError("no branch-free driving pivot in the view; give one with --pivot X Y")
            pivot = best[0].center
        else:
            pivot = (args.pivot[0], args.pivot[1])
        sfb = filemon.four_bar(pivot)
        task = filemon.task
        what = f"driving pivot A0 = {_fmt_point(pivot)}"
    if export is not None:
        _write_cad(export.linkage, out, args.force, sfb, out, task=task, travel_samples=args.travel or 0,
                   units=units)
    elif animated:
        plot = _plot_module()
        frames = 60 if args.frames is None else args.frames
        fps = 20 if args.fps is None else args.fps
        try:
            _written(out, args.force,
                     lambda tmp: plot.animate(sfb, tmp, task=task, frames=frames, fps=fps, units=spec.units))
        except RuntimeError as e:
            raise UsageError(str(e)) from None
        import matplotlib.pyplot as plt

        plt.close("all")
    else:
        ax = _plot_module().linkage(sfb, task=task, units=spec.units)
        _save(ax.figure, out, _picture_dpi(args), args.force)
    state = "branch-free" if sfb.branch_free else "has a branch defect"
    lengths = ", ".join(f"{name} {format_length(v, spec.units)}"
                        for name, v in zip(("ground", "crank", "coupler", "rocker"), sfb.fourbar.lengths))
    pivots = [("A0", sfb.driving[0]), ("C0", sfb.driven[0])]
    print(f"wrote {out}: four-bar with {what}, {sfb.fourbar.grashof}, {state}: {lengths}"
          f"{_outside_note(spec, pivots)}")
    return 0


def _best_burmester_linkage(args: argparse.Namespace, spec: TaskSpec) -> Tuple[burmester.SynthesizedFourBar, str]:
    """The four-bar ``burmester linkage`` draws for five poses: the best of
    :func:`burmester.pivots.rank_burmester` that carries the coupler through
    the poses in order, and how to name it."""
    if args.pivot is not None:
        raise UsageError("five poses: the linkage is built from two Burmester points; drop --pivot "
                         "(burmester pivots lists them all)")
    ranked = [b for b in pv.rank_burmester(spec.task, spec.limits) if b.linkage.figures.direction != "none"]
    if not ranked:
        raise UsageError(f"{spec.source}: no four-bar of two Burmester points carries the coupler through "
                         "the five poses in order")
    b = ranked[0]
    return b.linkage, f"Burmester points B{b.driving + 1} driving, B{b.driven + 1} driven"


#: Samples of each axis of ``burmester pairs`` (and of ``linkage`` for four poses).
PAIR_SAMPLES = 400


def _pair_map(spec: TaskSpec, samples: int) -> burmester.PairMap:
    """The pair map of a four-pose task under its limits, with a progress
    bar when it is large."""
    n = len(spec.poses)
    if n != 4:
        raise UsageError(f"pairs is for four poses (the pair map); {spec.source} has {n} poses")
    if not 2 <= samples <= 20000:
        raise UsageError(f"--samples must be from 2 to 20000, got {samples}")
    _check_memory(samples, samples, "ranking", "the pair map", "--samples")
    big = samples * samples >= PROGRESS_MIN_POINTS
    bar = ProgressBar(sys.stderr, "burmester: pair map") if big and sys.stderr.isatty() else None
    return spec.task.pair_map(samples, limits=spec.limits, progress=bar)


def _pair_record(p: burmester.Pair) -> Dict[str, Any]:
    """One pair of ``burmester pairs --json``."""
    f = p.figures

    def dyad(d: burmester.CurveDyad) -> Dict[str, Any]:
        return {"center": list(d.center), "circle": list(d.circle), "beta2_deg": math.degrees(d.beta2),
                "branch": d.branch}

    return {
        "index": list(p.index),
        "driving": dyad(p.driving),
        "driven": dyad(p.driven),
        "lengths": dict(zip(("ground", "crank", "coupler", "rocker"), f.lengths)),
        "grashof": f.grashof,
        "direction": f.direction,
        "min_transmission_deg": f.min_transmission_deg,
        "link_ratio": f.link_ratio,
        "size_ratio": p.size_ratio,
        "margin": p.margin,
        "score": p.score,
        "ranked_by": p.ranked_by,
    }


def pair_table(spec: TaskSpec, pairs: Sequence[burmester.Pair], ranked_by: str) -> str:
    """The text table of ``burmester pairs``: the ranking, the table
    (:func:`table`), what the columns mean."""
    columns = [("#", "right"), ("A0 (x, y)", "right"), ("C0 (x, y)", "right"), ("size", "right"),
               ("ground", "right"), ("crank", "right"), ("coupler", "right"), ("rocker", "right"),
               ("Grashof type", "left"), ("mu min", "right"), ("drive", "left")]
    rows = []
    for k, p in enumerate(pairs, start=1):
        f = p.figures
        mt = f"{f.min_transmission_deg:.1f}" if f.min_transmission_deg is not None else "-"
        drive = f"{f.direction} {f.modes[0] or ''}".strip()
        rows.append([str(k), _fmt_point(p.driving.center), _fmt_point(p.driven.center), _fmt_size(p.size_ratio),
                     *(f"{v:.3f}" for v in f.lengths), f.grashof, mt, drive])
    lines = [
        f"Pairs of dyads for {spec.source} (task size {format_length(spec.task.span, spec.units, 3)}"
        f"{_lengths_in(spec)}), {pv.describe_ranking(ranked_by)}, acceptable under the "
        f"{_limits_text(spec)}",
        table(columns, rows),
    ]
    if not pairs:
        lines.append("(no acceptable pair of dyads)")
    named = [(f"{name} of pair {k}", p_) for k, p in enumerate(pairs, start=1)
             for name, p_ in (("A0", p.driving.center), ("C0", p.driven.center))]
    outside = describe_outside(outside_view(named, spec.view.extent), spec.view.extent, spec.units)
    if outside:
        lines.append(f"note: {outside} ('burmester map' draws the view)")
    lines.append(
        "A0, C0: the driving and driven fixed pivots. size: the total length of the links in task "
        "sizes. mu min: smallest transmission angle over the travel 1 -> 2 -> 3 -> 4 (degrees)."
    )
    return "\n".join(lines)


def cmd_pairs(args: argparse.Namespace) -> int:
    """``burmester pairs``: rank the pairs of dyads of a four-pose task (the
    pair map), and draw the map."""
    spec = _with_units(_load(args.task), args)  # the task file's errors first
    if args.output is not None:
        _output(args.output, PICTURE_TYPES, args.force)
        _check_memory(args.samples, args.samples, "picture", f"drawing {args.output}", "--samples")
    pmap = _pair_map(spec, args.samples)
    pairs = pmap.best_pairs(args.top, rank_by=args.rank_by)
    if args.output is not None:
        ax = _plot_module().pair_map(pmap, pairs=args.top, rank_by=args.rank_by)
        _save(ax.figure, args.output, _picture_dpi(args), args.force)
    if args.json:
        doc = {
            "task": spec.source,
            "units": spec.units,
            "limits": pv.limits_dict(spec.limits),
            "samples": list(pmap.shape),
            "acceptable_fraction": float(np.mean(pmap.acceptable)),
            "branch_free_fraction": float(np.mean(pmap.branch_free)),
            "pairs": [_pair_record(p) for p in pairs],
        }
        print(json.dumps(doc, indent=2))
    else:
        print(pair_table(spec, pairs, args.rank_by))
    if args.output is not None and not args.json:
        print(f"wrote {args.output}: pair map of {spec.source}, {pmap.shape[1]} x {pmap.shape[0]} pairs, "
              f"{100 * np.mean(pmap.acceptable):.1f}% acceptable ({_limits_text(spec)})")
    return 0


# ---------------------------------------------------------------------------
# burmester design: from poses (and a space) to the best linkage


#: The rankings ``burmester design`` offers (those with a score).
DESIGN_RANKINGS = ("balanced", "transmission", "compact")


def _space_words(space: Optional[burmester.Space], units: Optional[str] = None) -> str:
    """The space a design fits, in words (lengths with ``units``)."""
    if space is None or (space.region == "anywhere" and not space.obstacles and space.envelope is None):
        return "pivots anywhere"
    words = []
    if space.pivot_box is not None:
        x0, x1, y0, y1 = space.pivot_box
        words.append(f"pivots in x {x0:g}..{x1:g}, y {y0:g}..{y1:g}" + (f" {units}" if units else ""))
    elif space.pivot_polygon is not None:
        words.append(f"pivots in a polygon of {len(space.pivot_polygon)} vertices")
    else:
        words.append("pivots anywhere")
    if space.obstacles:
        words.append(f"{len(space.obstacles)} obstacle(s) cleared")
    if space.envelope is not None:
        words.append("inside the envelope")
    if space.link_width:
        words.append(f"links {format_length(space.link_width, units)} wide")
    return ", ".join(words)


def _design_row(k: int, linkage: burmester.SynthesizedFourBar, size_ratio: float, last: str) -> List[str]:
    """One row of :func:`design_table`: the pivots, size, lengths, type,
    transmission, link ratio, drive, and ``last`` (the score, or what a
    near miss misses)."""
    f = linkage.figures
    mu = f.min_transmission_deg
    drive = f"{f.direction} {f.modes[0] or ''}".strip() if f.branch_free else "branch defect"
    return [str(k), _fmt_point(linkage.driving[0]), _fmt_point(linkage.driven[0]), _fmt_size(size_ratio),
            *(f"{v:.3f}" for v in f.lengths), f.grashof, f"{mu:.1f}" if mu is not None else "-",
            f"{f.link_ratio:.2f}", drive, last]


def design_table(spec: TaskSpec, report: burmester.DesignReport) -> str:
    """The text table of ``burmester design``: the task and ranking, the
    limits and the space every verdict was judged by, the designs (or the
    nearest misses with what each misses), what the columns mean."""
    task = spec.task
    lines = [
        f"Designs for {spec.source} ({len(task)} poses, task size {format_length(task.span, spec.units, 3)}: "
        f"the largest distance between two poses{_lengths_in(spec)}), {pv.describe_ranking(report.rank_by)}",
        f"{pv.describe_limits(report.limits, spec.units)}; space: {_space_words(report.space, spec.units)}",
    ]
    columns = [("#", "right"), ("A0 (x, y)", "right"), ("C0 (x, y)", "right"), ("size", "right"),
               ("ground", "right"), ("crank", "right"), ("coupler", "right"), ("rocker", "right"),
               ("Grashof type", "left"), ("mu min", "right"), ("ratio", "right"), ("drive", "left")]
    if len(report):
        rows = [_design_row(k, d.linkage, d.size_ratio, f"{d.score:.4f}") for k, d in enumerate(report, start=1)]
        lines.append(table(columns + [("score", "right")], rows))
        lines.append(
            "A0: the driving crank's fixed pivot, C0: the driven one's. size: the total length of the "
            "links (the coupler as its triangle with the coupler point) in task sizes. mu min: the "
            "smallest transmission angle over the whole travel (degrees). ratio: longest link / shortest. "
            "Each meets the limits above, judged exactly, refined from the best of a coarse search."
        )
    else:
        main = report.main_rejection
        rej = ", ".join(f"{name.replace('_', ' ')} {n}" for name, n in report.rejections)
        lines.append(
            f"No linkage fits. Of {report.census} candidates judged against every limit, the one "
            f"rejecting the most is {main.replace('_', ' ') if main else 'none'} ({rej or 'none'}); "
            "nothing was relaxed."
        )
        if report.near_misses:
            lines.append("Nearest misses (a feasible motion, missing the limits by the least):")
            rows = []
            for k, m in enumerate(report.near_misses, start=1):
                bad = pv.linkage_violations(m.linkage, report.limits, spec.units)
                bad += [w.replace("_", " ") for w in m.misses if w in ("pivot_region", "obstacles", "envelope")]
                rows.append(_design_row(k, m.linkage, m.size_ratio, "; ".join(bad)))
            lines.append(table(columns + [("misses", "left")], rows))
    return "\n".join(lines)


def design_document(spec: TaskSpec, report: burmester.DesignReport) -> Dict[str, Any]:
    """The JSON document of ``burmester design --json``."""
    lim, space = report.limits, report.space
    return {
        "task": spec.source,
        "units": spec.units,
        "poses": len(spec.poses),
        "span": spec.task.span,
        "ranking": report.rank_by,
        "limits": pv.limits_dict(lim),
        "space": {
            "region": space.region,
            "pivot_box": space.pivot_box,
            "pivot_polygon": space.pivot_polygon,
            "obstacles": space.obstacles,
            "link_width": space.link_width,
            "envelope": space.envelope,
        },
        "search_box": report.search_box,
        "coarse_candidates": report.coarse_candidates,
        "coarse_acceptable": report.coarse_acceptable,
        "evaluations": report.evaluations,
        "min_separation": report.min_separation,
        "designs": [
            {"score": d.score, "found_by": d.found_by, "coarse": d.coarse, "refined": d.refined,
             "coarse_score": d.coarse_score, **pv.linkage_dict(d.linkage, lim)}
            for d in report
        ],
        "rejections": dict(report.rejections),
        "census": report.census,
        "near_misses": [
            {"misses": m.misses, "shortfall": m.shortfall, **pv.linkage_dict(m.linkage, lim)}
            for m in report.near_misses
        ],
    }


def motor_table(report: burmester.DesignReport) -> str:
    """The motor section of ``burmester design --motor``: for each design its
    drive (:func:`burmester.drives.drive_table`) or that its input turns
    fully, and the designs passed over for want of a drive."""
    from burmester import drives

    ratio = report.max_time_ratio
    lines = [
        f"With a motor (swing margin {report.swing_margin_deg or 0.0:g} deg, time ratio "
        f"{'no limit' if ratio is None or math.isinf(ratio) else f'<= {ratio:g}'}):"
    ]
    for k, d in enumerate(report, start=1):
        if d.drive is None:
            lines.append(f"Design {k}: its input turns fully: the motor turns it at A0 "
                         f"{_fmt_point(d.driving_pivot)} directly.")
        else:
            lines.append(drives.drive_table(d.drive, f"design {k}"))
    if report.undriven:
        lines.append(f"{report.undriven} candidate design(s) passed over: no acceptable drive for them under "
                     "these limits and this space.")
    return "\n".join(lines)


def _motor_document(doc: Dict[str, Any], report: burmester.DesignReport) -> Dict[str, Any]:
    """``doc`` (:func:`design_document`) with each design's ``"drive"``
    (None where the input turns fully) and the motor's options."""
    from burmester import drives

    for entry, d in zip(doc["designs"], report):
        entry["drive"] = drives.drive_record(d.drive) if d.drive is not None else None
    ratio = report.max_time_ratio
    doc["motor"] = {
        "swing_margin_deg": report.swing_margin_deg,
        "max_time_ratio": None if ratio is None or math.isinf(ratio) else ratio,
        "undriven": report.undriven,
    }
    return doc


def cmd_design(args: argparse.Namespace) -> int:
    """``burmester design``: the best linkages for the task's poses inside its
    space, both fixed pivots searched (three poses), drawn with ``-o``; with
    ``--motor`` each design whose input swings carries its drive (the
    six-bar), which ``-o`` then draws, animates or exports."""
    spec = _with_units(_load(args.task), args)  # the task file's errors first
    margin = args.margin if args.margin is not None else 0.0
    max_time_ratio = args.max_time_ratio if args.max_time_ratio is not None else math.inf
    if not args.motor and (args.margin is not None or args.max_time_ratio is not None):
        raise UsageError("--margin and --max-time-ratio set the motor's drive: give --motor with them")
    if not 0.0 <= margin < 90.0:
        raise UsageError(f"--margin must be from 0 to 90 degrees, got {margin:g}")
    if not max_time_ratio >= 1.0:
        raise UsageError(f"--max-time-ratio must be at least 1, got {max_time_ratio:g}")
    out: Optional[str] = args.output
    export: Optional[ModuleType] = None
    plot: Optional[ModuleType] = None
    animated = False
    if out is not None:
        _output(out, _types(PICTURE_TYPES, CAD_TYPES, ANIMATION_TYPES), args.force)
        units = _units(args, spec)
        animated = out.lower().endswith(ANIMATION_TYPES)
        for flag, given in (("--frames", args.frames), ("--fps", args.fps)):
            if given is not None and not animated:
                raise UsageError(f"{flag} is for animations (.gif, .mp4), not {out}")
        if args.travel is not None and not _is_cad(out):
            raise UsageError(f"--travel is for CAD exports (.dxf, .svg), not {out}")
        export = _export_module(out) if _is_cad(out) else None
        plot = None if export is not None else _plot_module()
    elif args.dpi is not None or args.frames is not None or args.fps is not None or args.travel is not None:
        raise UsageError("--dpi, --frames, --fps and --travel are for the drawing: give -o best.png "
                         "(or .gif, .svg, .dxf)")
    task = spec.task
    client = _atlas_client(args.scheduler)
    bar = (ProgressBar(sys.stderr, "burmester: design") if sys.stderr.isatty() and client is None
           and len(spec.poses) < 5 else None)
    try:
        report = burmester.design(task, space=spec.space, limits=spec.limits, rank_by=args.rank_by,
                                  top=args.top, client=client, progress=bar,
                                  input="motor" if args.motor else None, swing_margin_deg=margin,
                                  max_time_ratio=max_time_ratio)
    finally:
        if client is not None:
            client.close()
    if args.json:
        doc = design_document(spec, report)
        print(json.dumps(_motor_document(doc, report) if report.motor else doc, indent=2))
    else:
        print(design_table(spec, report))
        if report.motor:
            print(motor_table(report))
    if out is None:
        return 0
    said = sys.stderr if args.json else sys.stdout
    if not len(report):
        print(f"nothing drawn: no linkage fits, so {out} was not written", file=said)
        return 0
    sfb = report[0].linkage
    drive = report[0].drive
    if drive is not None:
        _draw_design_drive(args, drive, out, export, plot, units, animated)
        return 0
    if export is not None:
        _write_cad(export.linkage, out, args.force, sfb, out, task=task, travel_samples=args.travel or 0,
                   units=units)
    elif animated:
        assert plot is not None
        try:
            _written(out, args.force, lambda tmp: plot.animate(sfb, tmp, task=task, frames=args.frames or 60,
                                                               fps=args.fps or 20, units=spec.units))
        except RuntimeError as e:
            raise UsageError(str(e)) from None
        import matplotlib.pyplot as plt

        plt.close("all")
    else:
        assert plot is not None
        ax = plot.linkage(sfb, task=task, units=spec.units)
        ax.set_title(f"best design of {spec.source} ({report.rank_by})")
        _save(ax.figure, out, _picture_dpi(args), args.force)
    f = sfb.figures
    lengths = ", ".join(f"{name} {format_length(v, spec.units)}"
                        for name, v in zip(("ground", "crank", "coupler", "rocker"), f.lengths))
    print(f"wrote {out}: the best design, {f.grashof}, {report[0].size_ratio:.1f}x the task's size, "
          f"transmission >= {f.min_transmission_deg:.1f} deg: {lengths}", file=said)
    return 0


def _draw_design_drive(args: argparse.Namespace, drive: burmester.Drive, out: str, export: Optional[ModuleType],
                       plot: Optional[ModuleType], units: str, animated: bool) -> None:
    """``design --motor -o``: the best design's six-bar drawn (at its poses),
    animated over a crank turn or exported, as ``burmester drive`` does."""
    if export is not None:
        _write_cad(export.sixbar, out, args.force, drive, out, turn_samples=args.travel or 0, units=units)
    elif animated:
        assert plot is not None
        try:
            _written(out, args.force,
                     lambda tmp: plot.animate_sixbar(drive, tmp, frames=args.frames or 120, fps=args.fps or 24))
        except RuntimeError as e:
            raise UsageError(str(e)) from None
        import matplotlib.pyplot as plt

        plt.close("all")
    else:
        assert plot is not None
        ax = plot.sixbar(drive)
        ax.set_title(f"best design with its motor drive ({drive.ranked_by or 'drive'})")
        _save(ax.figure, out, _picture_dpi(args), args.force)
    print(f"wrote {out}: the best design's six-bar, motor crank at {_fmt_point(drive.drive_pivot)}, "
          f"transmission >= {drive.min_transmission_deg:.1f} deg over a crank turn, time ratio "
          f"{drive.time_ratio:.3f}", file=sys.stderr if args.json else sys.stdout)


#: The finest ``solve --step``: 36,000 rows over a turn.
MIN_STEP_DEG = 0.01


def position_table(fourbar: burmester.FourBar, step_deg: float = 30.0) -> str:
    """A text table (:func:`table`) of both assembly modes over a full turn
    of the input."""
    columns = [("theta2", "right"), ("open theta3", "right"), ("theta4", "right"), ("mu", "right"),
               ("crossed theta3", "right"), ("theta4", "right"), ("mu", "right")]
    n = max(1, round(360.0 / step_deg))
    both: Tuple[Mode, Mode] = ("open", "crossed")
    rows = []
    for k in range(n):
        t2 = k * 360.0 / n
        row = [f"{t2:.1f}"]
        for mode in both:
            try:
                c = fourbar.configuration(math.radians(t2), mode)
            except burmester.AssemblyError:
                row += ["(does not close)", "", ""]
            else:
                row += [f"{math.degrees(c.theta3):.3f}", f"{math.degrees(c.theta4):.3f}",
                        f"{math.degrees(c.transmission_angle):.1f}"]
        rows.append(row)
    return "\n".join([f"{fourbar!r}: {fourbar.grashof}", table(columns, rows),
                      "angles in degrees; mu is the transmission angle"])


def cmd_solve(args: argparse.Namespace) -> int:
    """``burmester solve``: position analysis of a four-bar."""
    given = [args.ground, args.crank, args.coupler, args.rocker]
    if all(v is None for v in given):
        lengths = EXAMPLE_FOURBAR
        print("(no lengths given: the example four-bar of Norton, Design of Machinery, Example 4-1)")
    elif any(v is None for v in given):
        missing = [n for n, v in zip(("--ground", "--crank", "--coupler", "--rocker"), given) if v is None]
        raise UsageError(f"missing {', '.join(missing)}: give all four link lengths, or none for the example")
    else:
        lengths = (args.ground, args.crank, args.coupler, args.rocker)
    if args.step is not None and not MIN_STEP_DEG <= args.step <= 360.0:
        raise UsageError(
            f"--step must be from {MIN_STEP_DEG:g} to 360 degrees (at most "
            f"{round(360 / MIN_STEP_DEG)} rows), got {args.step:g}"
        )
    ground, crank, coupler, rocker = lengths
    fb = burmester.FourBar(ground=ground, crank=crank, coupler=coupler, rocker=rocker)
    if args.theta2 is None:
        print(position_table(fb, args.step or 30.0))
        return 0
    t2 = math.radians(args.theta2)
    modes: List[Mode] = [args.mode] if args.mode else ["open", "crossed"]
    lines = [f"{fb!r}: {fb.grashof}", f"theta2 = {args.theta2:g} deg"]
    for mode in modes:
        try:
            c = fb.configuration(t2, mode)
        except burmester.AssemblyError:
            ranges = fb.input_range or []
            arcs = " or ".join(f"[{math.degrees(a):.1f}, {math.degrees(b):.1f}]" for a, b in ranges)
            raise UsageError(
                f"the loop does not close at theta2 = {args.theta2:g} deg; "
                f"this input only rocks within {arcs} deg: choose --theta2 there"
            ) from None
        o2, a, b, o4 = fb.joints(t2, mode)
        lines.append(
            f"{mode + ':':<8} theta3 = {math.degrees(c.theta3):9.3f} deg, theta4 = "
            f"{math.degrees(c.theta4):9.3f} deg, transmission angle = "
            f"{math.degrees(c.transmission_angle):6.2f} deg"
            + (" (toggle)" if c.toggle else "")
            + f"; A = {_fmt_point(a)}, B = {_fmt_point(b)}"
        )
    print("\n".join(lines))
    return 0


def cmd_example(args: argparse.Namespace) -> int:
    """``burmester example``: print (or write) the built-in example as a task file."""
    text = taskfile.dumps(taskfile.example())
    if args.output is None or args.output == "-":
        sys.stdout.write(text)
        return 0
    _output(args.output, (".toml",), args.force)
    _written(args.output, args.force, lambda tmp: tmp.write_text(text, encoding="utf-8"))
    print(f"wrote {args.output}")
    return 0


# ---------------------------------------------------------------------------
# The parser and main


def _count(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number, got {text!r}") from None
    if n < 0:
        raise argparse.ArgumentTypeError(f"expected a whole number of at least 0, got {n}")
    return n


def _ranged(lo: int, hi: int) -> Callable[[str], int]:
    """An argparse type: a whole number from ``lo`` to ``hi``."""

    def parse(text: str) -> int:
        n = _count(text)
        if not lo <= n <= hi:
            raise argparse.ArgumentTypeError(f"expected a whole number from {lo} to {hi}, got {n}")
        return n

    return parse


#: The usual ``--units`` (:data:`burmester.export.UNITS`, kept here so
#: that ``burmester --help`` does not import the export module); any other
#: unit name is accepted too.
UNIT_CHOICES = ("mm", "cm", "m", "in", "ft", "unitless")
#: The help of ``--units``.
UNITS_HELP = ("the unit of the task's lengths, any name (" + ", ".join(UNIT_CHOICES[:-1]) + ", ...), in place of "
              "the task file's units = \"...\": said after the lengths printed, on the picture's axes and in a "
              ".dxf or .svg (default: the task file's; none: bare numbers, and a CAD export records mm)")

#: The range of ``--dpi`` (matplotlib cannot draw much past 2^16 pixels a side).
MIN_DPI, MAX_DPI = 10, 2400
_dpi = _ranged(MIN_DPI, MAX_DPI)


def _positive_int(text: str) -> int:
    n = _count(text)
    if n < 1:
        raise argparse.ArgumentTypeError(f"expected a whole number of at least 1, got {n}")
    return n


def _finite(text: str) -> float:
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not math.isfinite(x):
        raise argparse.ArgumentTypeError(f"expected a finite number, got {text!r}")
    return x


# ---------------------------------------------------------------------------
# burmester drive: a motor for a linkage whose input swings


def _drive_linkage(args: argparse.Namespace, spec: TaskSpec) -> Tuple[burmester.SynthesizedFourBar, str]:
    """The linkage ``burmester drive`` drives: the given pivot's, or the
    best by ``--rank-by`` under the task's limits (three poses), the best
    pair (four), the best Burmester linkage (five)."""
    n = len(spec.poses)
    if n == 5:
        return _best_burmester_linkage(args, spec)
    if n == 4:
        if args.pivot is not None:
            raise UsageError("--pivot is for three poses; a four-pose task drives its best pair of dyads")
        best_pairs = _pair_map(spec, PAIR_SAMPLES).best_pairs(1, rank_by=args.rank_by)
        if not best_pairs:
            raise UsageError(f"no acceptable pair of dyads for {spec.source}; see 'burmester pairs'")
        return best_pairs[0].linkage, f"the best pair of dyads, A0 = {_fmt_point(best_pairs[0].driving.center)}"
    filemon = spec.filemon()
    if args.pivot is None:
        best, _ = pv.rank(_solution_map(spec, filemon), 1, pv.default_spacing(spec.view), args.rank_by)
        if not best:
            raise UsageError("no branch-free driving pivot in the view; give one with --pivot X Y")
        pivot = best[0].center
    else:
        pivot = (args.pivot[0], args.pivot[1])
    return filemon.four_bar(pivot), f"driving pivot A0 = {_fmt_point(pivot)}"


def cmd_drive(args: argparse.Namespace) -> int:
    """``burmester drive``: a motor for the task's linkage: the best added
    dyad (the Watt II six-bar), as a table or JSON, drawn, animated or
    exported."""
    from burmester import drives

    spec = _with_units(_with_grid(_load(args.task), args.grid), args)
    out: Optional[str] = args.output
    if out is not None:
        _output(out, _types(PICTURE_TYPES, CAD_TYPES, ANIMATION_TYPES), args.force)
        if args.map and (_is_cad(out) or out.lower().endswith(ANIMATION_TYPES)):
            raise UsageError(f"--map draws a picture (.png, .pdf, ...), not {out}")
    if not 0.0 <= args.margin < 90.0:
        raise UsageError(f"--margin must be from 0 to 90 degrees, got {args.margin:g}")
    if not args.max_time_ratio >= 1.0:
        raise UsageError(f"--max-time-ratio must be at least 1, got {args.max_time_ratio:g}")
    export = _export_module(out) if out is not None and _is_cad(out) and not args.map else None
    sfb, what = _drive_linkage(args, spec)
    bar = ProgressBar(sys.stderr, "burmester: drive search") if sys.stderr.isatty() else None
    drive = sfb.best_drive(limits=spec.limits, swing_margin_deg=args.margin,
                           max_time_ratio=args.max_time_ratio, rank_by=args.drive_rank_by,
                           progress=bar)
    if args.json:
        doc = {
            "task": spec.source,
            "linkage": drives.linkage_record(sfb),
            "drive": drives.drive_record(drive),
        }
        print(json.dumps(doc, indent=2))
    else:
        print(drives.drive_table(drive, f"{spec.source} ({what})"))
    if out is None:
        return 0
    shown = sys.stderr if args.json else sys.stdout
    if export is not None:
        _write_cad(export.sixbar, out, args.force, drive, out, turn_samples=args.turn or 0, units=_units(args, spec))
    elif args.map:
        plot = _plot_module()
        e = drive.attachment
        a0 = sfb.driving[0]
        h = 1.25 * max(math.dist(a0, drive.drive_pivot), math.dist(a0, e))
        dmap = sfb.drive_map(a0[0] - h, a0[0] + h, a0[1] - h, a0[1] + h, 400, 400, attachment=e,
                             limits=spec.limits, swing_margin_deg=args.margin,
                             max_time_ratio=args.max_time_ratio)
        ax = plot.drive_map(dmap, rank_by=args.drive_rank_by)
        _save(ax.figure, out, _picture_dpi(args), args.force)
    elif out.lower().endswith(ANIMATION_TYPES):
        plot = _plot_module()
        try:
            _written(out, args.force,
                     lambda tmp: plot.animate_sixbar(drive, tmp, frames=args.frames or 120, fps=args.fps or 24))
        except RuntimeError as err:
            raise UsageError(str(err)) from None
    else:
        ax = _plot_module().sixbar(drive)
        _save(ax.figure, out, _picture_dpi(args), args.force)
    print(f"wrote {out}", file=shown)
    return 0


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``burmester`` command."""
    parser = _Parser(
        prog="burmester",
        description=(
            "Four-bar linkages for three given coupler poses, free of the branch problem "
            "(Borm & Kim). Lengths in any one unit; angles on the command line and in task "
            "files are in degrees."
        ),
        epilog=(
            "examples:\n"
            "  burmester design -o best.png        the best linkage for the built-in example's poses\n"
            "  burmester map -o map.png            center-point plane of the built-in example\n"
            "  burmester example > task.toml       a task file to edit\n"
            "  burmester map task.toml -o map.png  center-point plane of your task\n"
            "  burmester pivots task.toml --top 5  the best acceptable driving pivots\n"
            "  burmester linkage task.toml -o linkage.gif\n"
            "  burmester pairs four.toml -o pairs.png  four poses: the best pairs of dyads and the pair map\n"
            "  burmester map task.toml -o plane.dxf   CAD export (.dxf, .svg), a layer per concept\n"
            "  burmester solve --ground 100 --crank 40 --coupler 120 --rocker 80 --theta2 40\n"
            "Without arguments, burmester prints this help."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action="version", version=f"burmester {burmester.__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    task_help = "task file (TOML; see 'burmester example'); default: the built-in example"

    p = sub.add_parser("map", help="draw the driving crank's center-point plane (or circle-point plane)",
                       description="Draw the driving crank's center-point plane as in Borm & Kim's "
                       "Fig. 10 and 12: branch-free pivots shaded, the transformed Filemon curves, "
                       "the poles, the pole triangle and circle, the driven crank's fixed pivot. "
                       "A task of four poses draws its center-point curve coloured by the crank's "
                       "order, with the poles and the points Q_jk; five poses, the Burmester points "
                       "on their two center-point curves.")
    p.add_argument("task", nargs="?", metavar="TASK.toml", help=task_help)
    p.add_argument("-o", "--output", default="map.png",
                   help="picture to write (.png, .pdf, ...; matplotlib), or CAD export (.dxf, .svg: a layer "
                   "or group per concept, exact coordinates); default: map.png")
    p.add_argument("--plane", choices=("center", "circle"), default="center",
                   help="center: center-point plane (Fig. 10/12); circle: circle-point plane (Fig. 3/11; "
                   "four poses: the circle-point curve by crank order)")
    p.add_argument("--method", choices=("conic", "direct", "simulate"), default="conic",
                   help="how grid points are classified (default: conic)")
    p.add_argument("--grid", nargs=2, type=_positive_int, metavar=("NX", "NY"),
                   help="grid samples along x and y (default: the task file's, or 400)")
    p.add_argument("--pivots", type=_count, default=0, metavar="N",
                   help="also mark the N best driving pivots (ranked as by 'burmester pivots')")
    p.add_argument("--design", action="store_true",
                   help="overlay the solution-space map: pivots acceptable under the task's limits "
                   "shaded darker, contours of the minimum transmission angle over the travel")
    p.add_argument("--dpi", type=_dpi, default=None,
                   help=f"resolution of a picture, dots per inch, {MIN_DPI} to {MAX_DPI} (default: 100)")
    p.add_argument("--units", default=None, metavar="NAME", help=UNITS_HELP)
    p.add_argument("--force", action="store_true", help="replace the output file if it exists")
    p.set_defaults(func=cmd_map)

    p = sub.add_parser("design", help="from poses (and a space) to the best linkage: both pivots searched",
                       description="Search the best linkages for the task's poses: three poses search both "
                       "fixed pivots (a coarse pass, then each candidate refined continuously on its exact "
                       "figures), four poses both curve parameters, five poses every pair of Burmester "
                       "points. Every design is branch-free, passes the poses in order on one circuit, meets "
                       "the task file's [limits] (printed) and fits its [space]. A task file needs no "
                       "[driven] table for this. When nothing fits, it says which limit rejected the most "
                       "candidates and lists the nearest misses.")
    p.add_argument("task", nargs="?", metavar="TASK.toml", help=task_help)
    p.add_argument("--top", type=_ranged(1, 100), default=5, help="how many designs, 1 to 100 (default: 5)")
    p.add_argument("--rank-by", choices=DESIGN_RANKINGS, default="balanced",
                   help="balanced (default): sin(mu min) / sqrt(size x link ratio); transmission: the minimum "
                   "transmission angle; compact: the smallest linkage relative to the task")
    p.add_argument("--json", action="store_true", help="print JSON instead of a table")
    p.add_argument("-o", "--output", default=None,
                   help="also draw the best design: a picture (.png, .pdf, ...), an animation (.gif, .mp4) or "
                   "a CAD export (.dxf, .svg)")
    p.add_argument("--frames", type=_ranged(2, 10_000), default=None,
                   help="animation frames from the first pose to the last, 2 to 10000 (default: 60)")
    p.add_argument("--fps", type=_ranged(1, 240), default=None,
                   help="animation frames per second, 1 to 240 (default: 20)")
    p.add_argument("--travel", type=_ranged(2, 10_000), default=None, metavar="N",
                   help="CAD export: also draw the linkage at N positions over its travel")
    p.add_argument("--units", default=None, metavar="NAME", help=UNITS_HELP)
    p.add_argument("--dpi", type=_dpi, default=None,
                   help=f"resolution of a picture, {MIN_DPI} to {MAX_DPI} (default: 100)")
    p.add_argument("--scheduler", metavar="ADDRESS", default=None,
                   help="run the three-pose coarse pass on a Dask cluster (tcp://host:8786); needs burmester[dask]")
    p.add_argument("--motor", action="store_true",
                   help="every design turned by a motor: one whose input swings gets the best added crank-rocker "
                   "(the six-bar; the limits and the space apply to it too; -o then draws, animates over a "
                   "crank turn (--frames per turn, default 120) or exports the six-bar, --travel N giving N "
                   "crank angles of a CAD export); one "
                   "without an acceptable drive is passed over")
    p.add_argument("--margin", type=_finite, default=None, metavar="DEG",
                   help="with --motor: swing the input this much beyond the first and last pose (default: 0)")
    p.add_argument("--max-time-ratio", type=_finite, default=None, metavar="R",
                   help="with --motor: largest acceptable time ratio of the strokes (default: no limit)")
    p.add_argument("--force", action="store_true", help="replace the output file if it exists")
    p.set_defaults(func=cmd_design)

    p = sub.add_parser("pivots", help="rank the acceptable driving pivots",
                       description="Rank the driving pivots A0 that are branch-free, pass the poses "
                       "in order on one circuit and meet the task's limits (the solution-space map) "
                       "by --rank-by, and show each one's four-bar and its size relative to the "
                       "task. When none is acceptable, list branch-free pivots by their "
                       "distance to the branch-defect boundary, with the limits they miss.")
    p.add_argument("task", nargs="?", metavar="TASK.toml", help=task_help)
    p.add_argument("--top", type=_positive_int, default=5, help="how many pivots (default: 5)")
    p.add_argument("--spacing", type=_finite, default=None,
                   help="least distance between listed pivots, whichever the ranking "
                   "(default: a tenth of the view's shorter side)")
    p.add_argument("--grid", nargs=2, type=_positive_int, metavar=("NX", "NY"),
                   help="grid samples along x and y (default: the task file's, or 400)")
    p.add_argument("--rank-by", choices=pv.RANKINGS, default="balanced",
                   help="balanced (default): sin(mu min) / sqrt(size x link ratio); transmission: the "
                   "minimum transmission angle; compact: the smallest linkage relative to the task; "
                   "pareto: the front of transmission and size, compact to transmitting")
    p.add_argument("--json", action="store_true", help="print JSON instead of a table")
    p.add_argument("--units", default=None, metavar="NAME", help=UNITS_HELP)
    p.set_defaults(func=cmd_pivots)

    p = sub.add_parser("pairs", help="four poses: rank the pairs of dyads (the pair map)",
                       description="For a task of four poses, the pair map: every pair of a driving and "
                       "a driven dyad sampled along the center-point curve, with the solution map's "
                       "figures; list the best acceptable pairs by --rank-by and draw the map with -o.")
    p.add_argument("task", metavar="TASK.toml", help="task file of four poses (TOML)")
    p.add_argument("--samples", type=_positive_int, default=PAIR_SAMPLES, metavar="N",
                   help=f"dyads sampled along the curve for each pivot, 2 to 20000 (default: {PAIR_SAMPLES})")
    p.add_argument("--top", type=_positive_int, default=5, help="how many pairs (default: 5)")
    p.add_argument("--rank-by", choices=pv.RANKINGS, default="balanced",
                   help="the ranking, as for 'burmester pivots' (default: balanced)")
    p.add_argument("--json", action="store_true", help="print JSON instead of a table")
    p.add_argument("-o", "--output", default=None,
                   help="also draw the pair map as a picture (.png, .pdf, ...; matplotlib)")
    p.add_argument("--dpi", type=_dpi, default=None,
                   help=f"resolution of the picture, {MIN_DPI} to {MAX_DPI} (default: 100)")
    p.add_argument("--units", default=None, metavar="NAME", help=UNITS_HELP)
    p.add_argument("--force", action="store_true", help="replace the output file if it exists")
    p.set_defaults(func=cmd_pairs)

    p = sub.add_parser("linkage", help="draw or animate the four-bar of a driving pivot",
                       description="Draw the four-bar at the three poses (.png, .pdf, ...), "
                       "animate it driven through them (.gif, or .mp4 with ffmpeg), or export it to CAD "
                       "(.dxf, .svg: a layer or group per concept, exact coordinates).")
    p.add_argument("task", nargs="?", metavar="TASK.toml", help=task_help)
    p.add_argument("--pivot", nargs=2, type=_finite, metavar=("X", "Y"),
                   help="the driving crank's fixed pivot A0 (default: the best, as by 'burmester pivots')")
    p.add_argument("-o", "--output", default="linkage.png",
                   help="file to write: a picture (.png, .pdf, ...), an animation (.gif, .mp4) or a CAD "
                   "export (.dxf, .svg); default: linkage.png")
    p.add_argument("--frames", type=_ranged(2, 10_000), default=None,
                   help="animation frames from the first pose to the last, 2 to 10000 (default: 60)")
    p.add_argument("--fps", type=_ranged(1, 240), default=None,
                   help="animation frames per second, 1 to 240 (default: 20)")
    p.add_argument("--travel", type=_ranged(2, 10_000), default=None, metavar="N",
                   help="CAD export: also draw the linkage at N positions over its travel, 2 to 10000")
    p.add_argument("--units", default=None, metavar="NAME", help=UNITS_HELP)
    p.add_argument("--dpi", type=_dpi, default=None,
                   help=f"resolution of a picture, {MIN_DPI} to {MAX_DPI} (default: 100)")
    p.add_argument("--force", action="store_true", help="replace the output file if it exists")
    p.set_defaults(func=cmd_linkage)

    p = sub.add_parser("atlas", help="both pivots at once: the best driving pivot of every driven center",
                       description="For every driven center on a grid over the view, the solution map over "
                                   "driving centers reduced: shaded by the best achievable transmission angle, "
                                   "the count of acceptable driving pivots as contours, the best pair drawn.")
    p.add_argument("task", nargs="?", metavar="TASK.toml", help=task_help)
    p.add_argument("-o", "--output", default=None, help="picture to write (.png, .svg, .pdf; matplotlib, "
                   "an image of the atlas, not a CAD export); default: atlas.png (none with --json unless given)")
    p.add_argument("--json", action="store_true", help="print the best pairs as JSON")
    p.add_argument("--top", type=_positive_int, default=5, help="how many pairs in the JSON (default: 5)")
    p.add_argument("--scheduler", metavar="ADDRESS", default=None,
                   help="run on a Dask cluster (tcp://host:8786); needs burmester[dask]")
    p.add_argument("--driven-grid", nargs=2, type=_positive_int, metavar=("NX", "NY"),
                   help=f"driven centers over the view (default: {ATLAS_DRIVEN_GRID[0]} {ATLAS_DRIVEN_GRID[1]})")
    p.add_argument("--driving-grid", nargs=2, type=_positive_int, metavar=("NX", "NY"),
                   help=f"driving centers over the view (default: {ATLAS_DRIVING_GRID[0]} {ATLAS_DRIVING_GRID[1]})")
    p.add_argument("--rank-by", choices=DESIGN_RANKINGS, default="balanced",
                   help="how each driven center's best driving pivot is chosen: balanced (default), "
                   "transmission or compact, as for 'burmester pivots'")
    p.add_argument("--dpi", type=_dpi, default=100, help=f"resolution, {MIN_DPI} to {MAX_DPI} (default: 100)")
    p.add_argument("--units", default=None, metavar="NAME", help=UNITS_HELP)
    p.add_argument("--force", action="store_true", help="replace the output file if it exists")
    p.set_defaults(func=cmd_atlas)

    p = sub.add_parser("batch", help="the best driving pivots of many task files, one JSON line each",
                       description="Rank the driving pivots of each task file as 'burmester pivots "
                       "--json' does, printing one JSON line per file (JSON lines), in order. A file "
                       "that fails gives a line with an \"error\" field; the others still run, and the "
                       "exit status is 2 at the end. With --scheduler, one Dask task per file.")
    p.add_argument("tasks", nargs="+", metavar="TASK.toml", help="task files (TOML; see 'burmester example')")
    p.add_argument("--top", type=_positive_int, default=5, help="how many pivots per task (default: 5)")
    p.add_argument("--spacing", type=_finite, default=None,
                   help="least distance between listed pivots (default: a tenth of each view's shorter side)")
    p.add_argument("--rank-by", choices=pv.RANKINGS, default="balanced",
                   help="the ranking, as for 'burmester pivots' (default: balanced)")
    p.add_argument("--scheduler", metavar="ADDRESS", default=None,
                   help="run on a Dask cluster (tcp://host:8786); needs burmester[dask]")
    p.set_defaults(func=cmd_batch)

    p = sub.add_parser("solve", help="position analysis of a four-bar (angles in degrees)",
                       description="Solve a four-bar's position: the coupler and rocker angles for "
                       "an input angle, in both assembly modes. Without --theta2, a table over a "
                       "full turn. Without lengths, Norton's Example 4-1 (100, 40, 120, 80).")
    p.add_argument("--ground", type=_finite, help="ground link length L1 (input pivot to output pivot)")
    p.add_argument("--crank", type=_finite, help="crank (input) length L2")
    p.add_argument("--coupler", type=_finite, help="coupler length L3")
    p.add_argument("--rocker", type=_finite, help="rocker (output) length L4")
    p.add_argument("--theta2", type=_finite, metavar="DEG",
                   help="input (crank) angle in DEGREES, counter-clockwise from the ground link")
    p.add_argument("--mode", choices=("open", "crossed"),
                   help="assembly mode (default: both); open: sin(theta4 - theta3) > 0")
    p.add_argument("--step", type=_finite, default=None, metavar="DEG",
                   help="input angle step of the full-turn table, degrees (default: 30)")
    p.set_defaults(func=cmd_solve)

    p = sub.add_parser("example", help="print the built-in example as a task file",
                       description="Print the built-in example task as a TOML task file, to edit.")
    p.add_argument("-o", "--output", default=None, help="write to this .toml file instead of stdout")
    p.add_argument("--force", action="store_true", help="replace the output file if it exists")
    p.set_defaults(func=cmd_example)

    p = sub.add_parser("drive", help="a motor for a linkage whose input swings: an added dyad (six-bar)",
                       description="Find the best motor drive for the task's linkage: a crank-rocker "
                                   "added to its input link (the Watt II six-bar), so a motor turning "
                                   "a crank drives it through the poses.",
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("task", nargs="?", metavar="TASK.toml", help=task_help)
    p.add_argument("-o", "--output", default=None,
                   help="also write the six-bar: a picture (.png, .pdf, ...), an animation over a "
                        "crank turn (.gif, .mp4) or a CAD export (.dxf, .svg); with --map, the drive map")
    p.add_argument("--json", action="store_true", help="print JSON instead of a table")
    p.add_argument("--pivot", nargs=2, type=_finite, metavar=("X", "Y"),
                   help="three poses: the linkage's driving pivot A0 (default: the best by --rank-by)")
    p.add_argument("--rank-by", choices=pv.RANKINGS, default="balanced",
                   help="which linkage of the task to drive (default: balanced)")
    p.add_argument("--drive-rank-by", choices=("balanced", "transmission", "compact"), default="balanced",
                   help="which drive to pick (default: balanced)")
    p.add_argument("--margin", type=_finite, default=0.0, metavar="DEG",
                   help="swing the input this much beyond the first and last pose (default: 0, the "
                        "strokes end at the poses)")
    p.add_argument("--max-time-ratio", type=_finite, default=math.inf, metavar="Q",
                   help="largest acceptable time ratio of the strokes (default: no limit)")
    p.add_argument("--grid", nargs=2, type=_positive_int, metavar=("NX", "NY"),
                   help="samples of the view when choosing the linkage")
    p.add_argument("--map", action="store_true", help="-o draws the drive map of the best drive's attachment")
    p.add_argument("--turn", type=_ranged(2, 10_000), default=None, metavar="N",
                   help="CAD export: also draw the six-bar at N crank angles over a turn")
    p.add_argument("--frames", type=_ranged(2, 10_000), default=None, help="animation: frames per crank turn (default 120)")
    p.add_argument("--fps", type=_ranged(1, 240), default=None, help="animation: frames per second (default 24)")
    p.add_argument("--units", default=None, metavar="NAME", help=UNITS_HELP)
    p.add_argument("--dpi", type=_dpi, default=None, help=f"picture resolution, {MIN_DPI} to {MAX_DPI}")
    p.add_argument("--force", action="store_true", help="replace the output file if it exists")
    p.set_defaults(func=cmd_drive)
    return parser


def _remember_sigint(seen: List[int]) -> Any:
    """On the main thread, handle SIGINT as Python does (KeyboardInterrupt)
    and note it in ``seen``; returns the handler it replaced (None
    elsewhere, where signals cannot be handled)."""
    if threading.current_thread() is not threading.main_thread():
        return None

    def on_sigint(signum: int, frame: Any) -> None:
        seen.append(signum)
        raise KeyboardInterrupt

    try:
        return signal.signal(signal.SIGINT, on_sigint)
    except ValueError:
        return None


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Entry point of ``python -m burmester`` and the ``burmester`` script.

    Returns the exit status: 0 on success, 2 for bad input (with a one-line
    message on stderr saying what to change), 1 when matplotlib or ezdxf is missing.
    """
    parser = build_parser()
    args_list = list(sys.argv[1:] if argv is None else argv)
    if not args_list:
        parser.print_help()
        return 0
    try:
        args = parser.parse_args(args_list)
    except SystemExit as e:  # argparse: --help, --version, or a usage error (already printed)
        return int(e.code or 0) if not isinstance(e.code, str) else 2
    if args.command is None:
        parser.print_help()
        return 0
    prog = f"burmester {args.command}"
    # Ctrl-C is remembered: a library's C code that runs the signal handler
    # may turn the KeyboardInterrupt into an error of its own (matplotlib:
    # "Invalid affine transformation matrix"); after a SIGINT any error is
    # the interruption.
    interrupted: List[int] = []
    previous = _remember_sigint(interrupted)
    try:
        try:
            return int(args.func(args))
        except Exception:
            if interrupted:
                raise KeyboardInterrupt from None
            raise
        finally:
            if previous is not None:
                signal.signal(signal.SIGINT, previous)
    except (UsageError, TaskFileError, burmester.BurmesterError) as e:
        print(f"{prog}: error: {e}", file=sys.stderr)
        return 2
    except MemoryError:
        print(f"{prog}: error: not enough memory for this; use a coarser --grid", file=sys.stderr)
        return 2
    except ImportError as e:
        print(f"{prog}: error: {e}", file=sys.stderr)
        return 1
    except ValueError as e:  # e.g. an output format matplotlib does not know
        print(f"{prog}: error: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"\n{prog}: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # e.g. `burmester pivots --json | head`
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 1
