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
    burmester inverted [TASK.toml] -o q.gif   # inverted slider-cranks (a slotted coupler on a ground swivel)
    burmester example > task.toml             # a task file to start from

Without a task file, the commands use the built-in example. Without any
arguments, ``burmester`` prints this help. Bad input exits with status 2 and
a one-line message saying what to change; a missing optional dependency
(matplotlib, ezdxf) exits with status 1. No command replaces an existing file
unless given ``--force``, decided when the finished file is moved into place
(:mod:`burmester._io`): outputs are written whole beside their target, so a
write error, a full disk or Ctrl-C leaves no partial file and keeps an
existing one.

The package: :mod:`~burmester.cli.parser` (the arguments of each command),
:mod:`~burmester.cli.commands` (one function a command),
:mod:`~burmester.cli.tables` (the tables and JSON documents they print),
:mod:`~burmester.cli.files` (the files they write) and
:mod:`~burmester.cli.base` (what they share: the usage error, progress,
the task with the options, the memory check).
"""

from __future__ import annotations

import os
import signal
import sys
import threading
from typing import Any, List, Optional, Sequence

import burmester
from burmester.cli import base, commands, files, parser, tables
from burmester.cli.base import ProgressBar, UsageError, progress_for
from burmester.cli.files import _save  # noqa: F401  (the commands' picture writer, as cli._save)
from burmester.cli.parser import UNIT_CHOICES, build_parser
from burmester.cli.tables import table
from burmester.taskfile import TaskFileError

__all__ = ["ProgressBar", "UNIT_CHOICES", "UsageError", "base", "build_parser", "commands", "files", "main",
           "parser", "progress_for", "table", "tables"]


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
    command_line = build_parser()
    args_list = list(sys.argv[1:] if argv is None else argv)
    if not args_list:
        command_line.print_help()
        return 0
    try:
        args = command_line.parse_args(args_list)
    except SystemExit as e:  # argparse: --help, --version, or a usage error (already printed)
        return int(e.code or 0) if not isinstance(e.code, str) else 2
    if args.command is None:
        command_line.print_help()
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
