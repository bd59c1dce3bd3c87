"""Writing files safely: every writer of burmester (the command line,
:mod:`burmester.export`, :func:`burmester.plot.animate`, the explorer's
``save``, :func:`burmester.taskfile.save`) writes through this module.

The file is written whole to a temporary file beside the target (same
folder, so the move cannot cross file systems; same suffix, so that
matplotlib and ezdxf see the type), flushed to the disk, and only then
moved into place:

- ``overwrite=True``: :func:`os.replace`, atomic: readers see the old file
  or the complete new one, never a part;
- ``overwrite=False``: :func:`os.link` of the complete file to the target
  name, which fails when the name exists, so the decision not to replace a
  file is taken at the move, not by a check before the work (a file created
  in the meantime is kept, and the call raises :class:`FileExistsError`).
  Where the file system has no hard links, the name is claimed with
  ``O_CREAT | O_EXCL`` and the complete file moved over the claim.

On any error (a full disk, a write error, Ctrl-C) the temporary file is
removed and the target is left as it was: a user's existing file is never
lost and no partial file is left behind.
"""

from __future__ import annotations

import contextlib
import errno
import os
import secrets
from pathlib import Path
from typing import Iterator, Union

PathLike = Union[str, "os.PathLike[str]"]

__all__ = ["atomic_path", "write_bytes", "write_text", "temporary_name"]

#: Temporary files are named ``.<target name>.<random>.part<suffix>``.
_PART = ".part"


def temporary_name(target: Path) -> Path:
    """A fresh name for a temporary file beside ``target`` (hidden, with the
    target's suffix)."""
    return target.with_name(f".{target.name}.{secrets.token_hex(6)}{_PART}{target.suffix}")


def _create(target: Path) -> Path:
    """Create an empty temporary file beside ``target`` (``O_EXCL``, the
    permissions the process's umask gives a new file) and return its path."""
    for _ in range(100):
        tmp = temporary_name(target)
        try:
            fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        except FileExistsError:
            continue
        os.close(fd)
        return tmp
    raise FileExistsError(errno.EEXIST, "cannot create a temporary file", str(target.parent))


def _sync(path: Path) -> None:
    """Flush a complete file to the disk, so that an error the disk reports
    late (a full disk on a network file system) comes before the move."""
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _sync_folder(folder: Path) -> None:
    """Flush the folder's entry for a moved file (best effort: some
    systems cannot open a folder)."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


#: ``os.link`` errors that mean the file system has no hard links (not that
#: the name exists).
_NO_LINKS = {errno.EPERM, errno.EOPNOTSUPP, errno.ENOTSUP, errno.EXDEV, errno.EMLINK, errno.ENOSYS}


def _move(tmp: Path, target: Path, overwrite: bool) -> None:
    """Move the complete file ``tmp`` to ``target`` (see the module docs)."""
    if overwrite:
        os.replace(tmp, target)
        return
    try:
        os.link(tmp, target)
    except FileExistsError:
        raise FileExistsError(errno.EEXIST, "the file exists", str(target)) from None
    except OSError as e:
        if e.errno not in _NO_LINKS:
            raise
        # No hard links here: claim the name, then move the file over it.
        fd = os.open(target, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        os.close(fd)
        try:
            os.replace(tmp, target)
        except BaseException:
            with contextlib.suppress(OSError):
                os.unlink(target)
            raise
        return
    os.unlink(tmp)


@contextlib.contextmanager
def atomic_path(target: PathLike, *, overwrite: bool = True) -> Iterator[Path]:
    """A temporary path beside ``target`` to write the whole file to; when
    the block ends without an error, the file is flushed to the disk and
    moved to ``target`` (replacing an existing file only with
    ``overwrite``; else :class:`FileExistsError` when the name exists at
    the move). On an error or Ctrl-C the temporary file is removed and the
    target is untouched.

    >>> with atomic_path("plot.png", overwrite=False) as tmp:   # doctest: +SKIP
    ...     fig.savefig(tmp)
    """
    target = Path(os.fspath(target))
    tmp = _create(target)
    try:
        yield tmp
        _sync(tmp)
        _move(tmp, target, overwrite)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise
    _sync_folder(target.parent)


def write_bytes(target: PathLike, data: bytes, *, overwrite: bool = True) -> Path:
    """Write ``data`` to ``target`` through :func:`atomic_path`."""
    with atomic_path(target, overwrite=overwrite) as tmp:
        with open(tmp, "wb") as fh:
            fh.write(data)
    return Path(os.fspath(target))


def write_text(target: PathLike, text: str, *, overwrite: bool = True, encoding: str = "utf-8") -> Path:
    """Write ``text`` to ``target`` through :func:`atomic_path`."""
    return write_bytes(target, text.encode(encoding), overwrite=overwrite)
