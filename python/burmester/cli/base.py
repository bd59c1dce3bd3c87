"""What every command of :mod:`burmester.cli` shares: the usage error, the
progress bar, the task with the command line's options, the memory check
before the work."""

from __future__ import annotations

import argparse
import dataclasses
import math
import sys
from typing import IO, TYPE_CHECKING, Any, Optional, Sequence, Tuple

import burmester
from burmester import _counts as counts
from burmester import _view
from burmester import pivots as pv
from burmester import taskfile
from burmester._burmester import Grid
from burmester.taskfile import TaskSpec, describe_outside, outside_view
from burmester.units import check_units

if TYPE_CHECKING:
    from burmester._burmester import Progress

#: A branch map of at least this many samples shows a progress bar on stderr
#: when it is a terminal; a solution map (about sixteen times the work per
#: sample) from a sixteenth of it.
PROGRESS_MIN_POINTS = 2_000_000


class UsageError(Exception):
    """Bad command-line input; the message says what to change."""


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
# The task, with the command line's options


def _load(path: Optional[str]) -> TaskSpec:
    return taskfile.example() if path is None else taskfile.load(path)


def _with_grid(spec: TaskSpec, grid: Optional[Sequence[int]]) -> TaskSpec:
    if grid is None:
        return spec
    try:
        view = _view.resample(spec.view, grid, "--grid", most=20000)
    except burmester.InvalidInputError as e:
        raise UsageError(str(e)) from None
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


# ---------------------------------------------------------------------------
# Numbers in words, the pair map


def _fmt_point(p: Sequence[float]) -> str:
    """``(x, y)`` to three decimals; a coordinate that rounds to zero reads
    0.000, not -0.000."""
    x, y = (round(v, 3) + 0.0 for v in p[:2])
    return f"({x:.3f}, {y:.3f})"


def _fmt_size(ratio: float) -> str:
    """A size ratio as ``12.3x``."""
    return f"{ratio:.1f}x"


#: Samples of each axis of ``burmester pairs`` (and of ``linkage`` for four poses).
PAIR_SAMPLES = 400


def _pair_map(spec: TaskSpec, samples: int) -> burmester.PairMap:
    """The pair map of a four-pose task under its limits, with a progress
    bar when it is large."""
    count = counts.of(spec.poses)
    if not count.curves:
        raise UsageError(f"pairs is for four poses (the pair map); {spec.source} has {count.poses} poses")
    if not 2 <= samples <= 20000:
        raise UsageError(f"--samples must be from 2 to 20000, got {samples}")
    _check_memory(samples, samples, "ranking", "the pair map", "--samples")
    big = samples * samples >= PROGRESS_MIN_POINTS
    bar = ProgressBar(sys.stderr, "burmester: pair map") if big and sys.stderr.isatty() else None
    return spec.task.pair_map(samples, limits=spec.limits, progress=bar)
