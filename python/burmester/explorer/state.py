"""The explorer's state, without matplotlib: the task, the driven crank's
fixed pivot ``C0``, the solution map of the view, the chosen driving pivot
``A0`` and its linkage; each move rebuilt by the core and kept only when the
core accepts it.

:class:`ExplorerState` is what :class:`burmester.explorer.Explorer` draws
and what its events change: a move (:meth:`ExplorerState.propose`) either
gives a new consistent state or keeps the last good one and says why
(:attr:`ExplorerState.error`). The handles a pointer can grab are named here
too (``"A0"``, ``"C0"``, ``"pose-k"``, ``"angle-k"``), with where each one
is in the task's coordinates and what moving it to a point proposes.
"""

from __future__ import annotations

import math
from typing import List, Optional, Sequence, Tuple

import numpy as np

import burmester
from burmester import pivots as pv
from burmester._burmester import DesignLimits, Filemon, Grid, SolutionMap, SynthesizedFourBar, Task
from burmester.taskfile import TaskSpec

__all__ = ["FIXED_HANDLES", "ExplorerState", "Snapshot"]

Point = Tuple[float, float]
Pose = Tuple[float, float, float]

#: Handle names: ``"A0"``, ``"C0"``, ``"pose-k"`` and ``"angle-k"`` (k = 1, 2, 3).
FIXED_HANDLES = ("A0", "C0")


class Snapshot:
    """One consistent state: the task, its Filemon construction for ``C0``,
    the solution map of the view and the linkage of ``A0``."""

    __slots__ = ("task", "filemon", "smap", "driving_center", "linkage")

    def __init__(self, task: Task, filemon: Filemon, smap: SolutionMap, driving_center: Point,
                 linkage: SynthesizedFourBar) -> None:
        self.task = task
        self.filemon = filemon
        self.smap = smap
        self.driving_center = driving_center
        self.linkage = linkage


def point(p: Sequence[float], what: str) -> Point:
    """``p`` as a point ``(x, y)``; TypeError naming ``what`` otherwise."""
    try:
        x, y = (float(v) for v in p)
    except (TypeError, ValueError):
        raise TypeError(f"{what} must be a point (x, y), got {p!r}") from None
    return (x, y)


def near_angle(angle: float, reference: float) -> float:
    """``angle`` plus the multiple of 2 pi that brings it within pi of ``reference``."""
    return reference + math.remainder(angle - reference, 2.0 * math.pi)


def fmt(p: Point) -> str:
    """A point to four significant digits."""
    return f"({p[0]:.4g}, {p[1]:.4g})"


class ExplorerState:
    """The explorer's state over the grid ``grid`` under ``limits``: opened
    on ``task`` and its ``filemon`` (for ``C0``) with ``A0`` at
    ``driving_center`` (default: the map's best pivot, else the one farthest
    from the branch-defect boundary, else any that gives a linkage).

    Raises :class:`burmester.BurmesterError` when no ``A0`` in the view
    gives a linkage.
    """

    def __init__(self, task: Task, filemon: Filemon, grid: Grid, limits: DesignLimits,
                 driving_center: Optional[Point] = None) -> None:
        self.grid = grid
        self.limits = limits
        smap = self._solution_map(filemon)
        a0 = self._start_pivot(filemon, smap, driving_center)
        self.now = Snapshot(task, filemon, smap, a0, filemon.four_bar(a0))
        self.initial = self.now
        #: The message of the last refused move; None after a good one.
        self.error: Optional[str] = None
        #: The length of a pose's flag, whose end turns the pose: 6 % of the view.
        extent = grid.extent
        self.flag_length = 0.06 * max(extent[1] - extent[0], extent[3] - extent[2])

    def _solution_map(self, filemon: Filemon) -> SolutionMap:
        return filemon.solution_map(self.grid, limits=self.limits)

    @staticmethod
    def _start_pivot(filemon: Filemon, smap: SolutionMap, given: Optional[Point]) -> Point:
        if given is not None:
            return point(given, "driving_center")
        candidates = [p.center for p in smap.best_pivots(1)]
        candidates += [p.center for p in smap.best_pivots(1, rank_by="margin")]
        js, iis = np.nonzero(smap.valid)
        if len(js):
            mid = len(js) // 2
            candidates.append(smap.point(int(js[mid]), int(iis[mid])))
        for c in candidates:
            try:
                filemon.four_bar(c)
            except burmester.BurmesterError:
                continue
            return c
        raise burmester.InvalidInputError(
            "no driving pivot in the view gives a linkage; widen the view or pass driving_center="
        )

    # ------------------------------------------------------------------
    # Moves

    def propose(self, poses: Sequence[Pose], c0: Point, a0: Point) -> Tuple[bool, bool]:
        """Move to the state of these poses and pivots if the core accepts
        it; otherwise keep the state and say why in :attr:`error`. Returns
        whether it was accepted and whether the map changed."""
        old = self.now
        try:
            if [tuple(p) for p in poses] == [tuple(p) for p in old.task.poses] and c0 == old.filemon.driven_center:
                task, filemon, smap = old.task, old.filemon, old.smap
            else:
                task = Task([tuple(p) for p in poses])
                filemon = task.filemon(c0)
                smap = self._solution_map(filemon)
            linkage = filemon.four_bar(a0)
        except burmester.BurmesterError as e:
            self.error = f"{type(e).__name__}: {e}"
            return False, False
        self.error = None
        self.now = Snapshot(task, filemon, smap, a0, linkage)
        return True, smap is not old.smap

    def moved_pose(self, k: int, x: Optional[float], y: Optional[float], angle: Optional[float]) -> List[Pose]:
        """The poses with pose ``k`` (from 1) moved to ``x``, ``y`` and
        turned to ``angle``; what is not given stays."""
        poses = [tuple(p) for p in self.now.task.poses]
        if not 1 <= k <= len(poses):
            raise burmester.InvalidInputError(f"pose must be from 1 to {len(poses)}, got {k}")
        px, py, pa = poses[k - 1]
        poses[k - 1] = (
            px if x is None else float(x),
            py if y is None else float(y),
            pa if angle is None else float(angle),
        )
        return [(p[0], p[1], p[2]) for p in poses]

    def best_pivot(self) -> Optional[Point]:
        """The map's best pivot: the best acceptable one, else the
        branch-free one farthest from the branch-defect boundary; None when
        the map has neither."""
        smap = self.now.smap
        best = smap.best_pivots(1) or smap.best_pivots(1, rank_by="margin")
        return best[0].center if best else None

    def reset(self) -> bool:
        """Go back to the state opened with; returns whether the map changed."""
        self.error = None
        changed = self.now.smap is not self.initial.smap
        self.now = self.initial
        return changed

    # ------------------------------------------------------------------
    # Handles and labels

    def pole_names(self) -> List[str]:
        """The poles' labels, ``"P12"``, ``"P13"``, ..., in the task's order."""
        return ["P{}{}".format(*p.pair) for p in self.now.task.poles]

    def handle_points(self) -> List[Tuple[str, Point]]:
        """Every handle's name and position, in the order a tie is broken."""
        st = self.now
        out: List[Tuple[str, Point]] = [("A0", st.driving_center), ("C0", st.filemon.driven_center)]
        for k, (x, y, a) in enumerate(st.task.poses, start=1):
            out.append((f"angle-{k}", self.flag_end(x, y, a)))
        for k, (x, y, _) in enumerate(st.task.poses, start=1):
            out.append((f"pose-{k}", (x, y)))
        return out

    def flag_end(self, x: float, y: float, a: float) -> Point:
        """Where the flag of a pose at ``(x, y)`` turned by ``a`` ends (its angle handle)."""
        return (x + self.flag_length * math.cos(a), y + self.flag_length * math.sin(a))

    def candidate(self, name: str, x: float, y: float) -> Tuple[List[Pose], Point, Point]:
        """The poses and pivots with handle ``name`` moved to ``(x, y)``."""
        st = self.now
        poses = [(p[0], p[1], p[2]) for p in st.task.poses]
        c0, a0 = st.filemon.driven_center, st.driving_center
        if name == "A0":
            a0 = (x, y)
        elif name == "C0":
            c0 = (x, y)
        else:
            kind, k = name.split("-")
            px, py, pa = poses[int(k) - 1]
            if kind == "pose":
                poses[int(k) - 1] = (x, y, pa)
            elif (x, y) != (px, py):
                poses[int(k) - 1] = (px, py, near_angle(math.atan2(y - py, x - px), pa))
        return poses, c0, a0

    # ------------------------------------------------------------------
    # In words, and as a task file

    def verdict(self) -> str:
        """The linkage's verdict under the limits, in words (see
        :meth:`burmester.explorer.Explorer.verdict`)."""
        lim = self.limits
        bad = pv.violations(self.now.linkage.figures, lim)
        if bad:
            return "not acceptable: " + "; ".join(bad)
        need = f"transmission >= {lim.min_transmission_deg:g} deg, link ratio <= {lim.max_link_ratio:g}"
        if lim.input != "any":
            need += f", {lim.input} input"
        return f"acceptable under the limits ({need})"

    def footer(self) -> str:
        """The linkage's figures, then :meth:`verdict`: two lines."""
        st = self.now
        fig = st.linkage.figures
        mt = fig.min_transmission_deg
        turns = "turns fully" if fig.input_full else "rocks"
        parts = [
            f"A0 {fmt(st.driving_center)}  C0 {fmt(st.filemon.driven_center)}  {fig.grashof}, input {turns}",
            "min transmission " + ("-" if mt is None else f"{mt:.1f} deg"),
            f"direction {fig.direction or 'none'}",
            "branch-free" if fig.branch_free else "branch defect",
            f"link ratio {fig.link_ratio:.3g}",
        ]
        return ";  ".join(parts) + "\n" + self.verdict()

    def task_spec(self) -> TaskSpec:
        """The task file of the task, ``C0``, the grid and the limits."""
        st = self.now
        return TaskSpec(
            poses=tuple((x, y, a) for x, y, a in st.task.poses),
            driven_center=st.filemon.driven_center,
            view=self.grid,
            limits=self.limits,
            source="<explorer>",
        )
