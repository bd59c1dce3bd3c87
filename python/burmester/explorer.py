"""The interactive explorer of a three-position task.

:class:`Explorer` (opened by :func:`burmester.plot.explore`) is a matplotlib
figure of two axes. On the left, the driving crank's center-point plane as
:func:`burmester.plot.center_plane` draws it: the branch-free driving pivots
shaded, those that also meet the limits shaded darker (the solution map's
``acceptable``), the transformed Filemon curves, the poles, the pole
triangle and circle; over it the handles you drag:

- each pose: a dot in its colour (drag to move the pose) and a square at the
  end of its flag (drag to turn the pose; the scroll wheel over either turns
  it by :data:`ANGLE_STEP_DEG` a step);
- ``C0``, the driven crank's fixed pivot (an orange triangle);
- ``A0``, the driving crank's fixed pivot (a gold star); a click on the
  plane away from every handle puts ``A0`` there.

On the right, the linkage of ``A0`` and ``C0`` drawn at the poses
(:func:`burmester.plot.linkage`), and below both its figures (Grashof type,
minimum transmission angle over the travel, input direction, feasible,
branch-free) or, when a move is refused, why.

Every move rebuilds the task with the core (``Task``, ``Task.filemon``,
``Filemon.solution_map``, ``Filemon.four_bar``): nothing is computed here.
A move the core refuses (a pose dragged onto another, ``C0`` onto a pole,
``A0`` onto the pole circle, ...) shows the error and keeps the last good
state; the handles go back to it.

Recomputing the solution map is fast (about 4 ms for 256 x 256 samples in
BENCHMARKS.md, some 20 ms for the default 240 x 240 on a busy two-core
machine; drawing the figure costs more), so for grids up to
:data:`LIVE_SAMPLES` samples the map follows the pointer
while you drag; for larger grids (``live=False``) the dragged handle follows
the pointer and the map is recomputed when you let go. Moving ``A0`` only
rebuilds the linkage, and always follows the pointer.

Keys (with the pointer over the figure): ``b`` puts ``A0`` on the best pivot
of the map (:meth:`burmester.SolutionMap.best_pivots`), ``r`` goes back to
the state the explorer opened with (and, as matplotlib's home key, to the
first view), ``e`` saves to ``export_to`` (see
:meth:`Explorer.save`). The toolbar's zoom and pan modes take the mouse
while they are on.

The explorer uses only matplotlib's backend-independent event API
(``mpl_connect`` and ``draw_idle``), so it works in any interactive backend:
a desktop window (``python -i``, ``plt.show()``) or Jupyter with
``%matplotlib widget`` (ipympl, installed by ``pip install
"burmester[plot]"``). With a non-interactive backend (Agg) it draws the
figure and takes events given to ``fig.canvas.callbacks.process``, which is
how the tests drive it.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.backend_bases import KeyEvent, MouseEvent
from matplotlib.figure import Figure
from matplotlib.image import AxesImage
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.text import Annotation, Text

import burmester
from burmester import _io
from burmester import pivots as pv
from burmester import plot as bp
from burmester._burmester import DesignLimits, Filemon, Grid, SolutionMap, SynthesizedFourBar, Task
from burmester.taskfile import TaskSpec, save as save_task

__all__ = ["ANGLE_STEP_DEG", "EXPLORE_SAMPLES", "LIVE_SAMPLES", "PICK_PIXELS", "Explorer"]

Point = Tuple[float, float]
Pose = Tuple[float, float, float]

#: Samples along the longer side of the view when neither a Grid nor
#: ``grid`` is given (fewer than a picture's 400, for speed).
EXPLORE_SAMPLES = 240
#: Largest grid (``nx * ny``) whose map is recomputed while dragging;
#: larger grids are recomputed when the mouse button is released.
LIVE_SAMPLES = 90_000
#: How near, in pixels, a press must be to a handle to grab it.
PICK_PIXELS = 10.0
#: How far one scroll step turns a pose, degrees.
ANGLE_STEP_DEG = 2.0

#: Handle names: ``"A0"``, ``"C0"``, ``"pose-k"`` and ``"angle-k"`` (k = 1, 2, 3).
_FIXED_HANDLES = ("A0", "C0")


class _State:
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


def _point(p: Sequence[float], what: str) -> Point:
    try:
        x, y = (float(v) for v in p)
    except (TypeError, ValueError):
        raise TypeError(f"{what} must be a point (x, y), got {p!r}") from None
    return (x, y)


def _view_grid(filemon: Filemon, view: Optional[bp.ViewLike], grid: Optional[Tuple[int, int]]) -> Grid:
    """The explorer's grid: a Grid as given, else the view (default: the
    pictures' default view) with :data:`EXPLORE_SAMPLES` along the longer
    side, or ``grid = (nx, ny)`` samples."""
    return bp._as_grid(filemon, view, grid, EXPLORE_SAMPLES)


def _near_angle(angle: float, reference: float) -> float:
    """``angle`` plus the multiple of 2 pi that brings it within pi of ``reference``."""
    return reference + math.remainder(angle - reference, 2.0 * math.pi)


def _fmt(p: Point) -> str:
    return f"({p[0]:.4g}, {p[1]:.4g})"


class Explorer:
    """An interactive figure of a three-position task: drag the poses, the
    driven crank's fixed pivot ``C0`` and the driving crank's fixed pivot
    ``A0``; the branch map, the acceptable region, the Filemon curves and
    the linkage follow. See the module's documentation for the handles,
    keys and backends.

    Parameters:
        task: three poses.
        driven_center: ``C0``.
        view: a :class:`burmester.Grid` (used as is), ``(xmin, xmax, ymin,
            ymax)`` (:data:`EXPLORE_SAMPLES` samples along the longer side)
            or None (a square around the poles and ``C0``). The view stays
            put while things move.
        driving_center: ``A0`` to start with; default: the best pivot of
            the map (:meth:`burmester.SolutionMap.best_pivots`), or the one
            farthest from the branch-defect boundary when none is acceptable.
        limits: the :class:`burmester.DesignLimits` behind the acceptable
            region; default: ``DesignLimits()``.
        grid: ``(nx, ny)`` samples, instead of the view's.
        live: recompute the map while dragging (True) or on release
            (False); default: True for grids of up to :data:`LIVE_SAMPLES`
            samples.
        export_to: where the ``e`` key saves (any type :meth:`save` writes).
        fig: the figure to draw into (it is cleared); default: a new pyplot
            figure.

    Raises:
        burmester.BurmesterError: the task, ``C0`` or the view is refused by
            the core, or no ``A0`` in the view gives a linkage.
    """

    def __init__(
        self,
        task: Task,
        driven_center: Point,
        view: Optional[bp.ViewLike] = None,
        *,
        driving_center: Optional[Point] = None,
        limits: Optional[DesignLimits] = None,
        grid: Optional[Tuple[int, int]] = None,
        live: Optional[bool] = None,
        export_to: Optional[Union[str, Path]] = None,
        fig: Optional[Figure] = None,
    ) -> None:
        if not isinstance(task, Task):
            raise TypeError(f"task must be a burmester.Task, got {type(task).__name__}")
        c0 = _point(driven_center, "driven_center")
        self.limits: DesignLimits = DesignLimits() if limits is None else limits
        filemon = task.filemon(c0)
        self.grid: Grid = _view_grid(filemon, view, grid)
        self.live: bool = self.grid.size <= LIVE_SAMPLES if live is None else bool(live)
        self.export_to: Optional[Path] = None if export_to is None else Path(export_to)
        smap = self._solution_map(filemon)
        a0 = self._start_pivot(filemon, smap, driving_center)
        self._state = _State(task, filemon, smap, a0, filemon.four_bar(a0))
        self._initial = self._state
        #: The message of the last refused move; None after a good one.
        self.error: Optional[str] = None
        self._dragging: Optional[str] = None
        self._pending: Optional[Tuple[List[Pose], Point, Point]] = None

        self.figure: Figure = plt.figure(figsize=(13.0, 6.2)) if fig is None else fig
        self.figure.clear()
        self.ax_map: Axes = self.figure.add_subplot(1, 2, 1)
        self.ax_linkage: Axes = self.figure.add_subplot(1, 2, 2)
        self.figure.subplots_adjust(left=0.06, right=0.98, top=0.9, bottom=0.2, wspace=0.15)
        self._map_artists: List[Artist] = []
        self._build()
        self._draw_state()
        self._cids: List[int] = []
        self._connect()

    # ------------------------------------------------------------------
    # The state

    @property
    def task(self) -> Task:
        """The task as it is now."""
        return self._state.task

    @property
    def driven_center(self) -> Point:
        """``C0`` as it is now."""
        return self._state.filemon.driven_center

    @property
    def driving_center(self) -> Point:
        """``A0`` as it is now."""
        return self._state.driving_center

    @property
    def filemon(self) -> Filemon:
        """Filemon's construction of the task and ``C0`` as they are now."""
        return self._state.filemon

    @property
    def solution_map(self) -> SolutionMap:
        """The solution map of the view as it is now (its ``branch_free``
        is the shaded branch map)."""
        return self._state.smap

    def linkage(self) -> SynthesizedFourBar:
        """The chosen linkage: ``filemon.four_bar(driving_center)``."""
        return self._state.linkage

    def _solution_map(self, filemon: Filemon) -> SolutionMap:
        return filemon.solution_map(self.grid, limits=self.limits)

    def _start_pivot(self, filemon: Filemon, smap: SolutionMap, given: Optional[Point]) -> Point:
        if given is not None:
            return _point(given, "driving_center")
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

    def _propose(self, poses: Sequence[Pose], c0: Point, a0: Point) -> bool:
        """Move to the state of these poses and pivots if the core accepts
        it; otherwise keep the state and show the error. Redraws."""
        old = self._state
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
            self._draw_state(map_changed=False)
            return False
        self.error = None
        self._state = _State(task, filemon, smap, a0, linkage)
        self._draw_state(map_changed=smap is not old.smap)
        return True

    def move_pose(self, k: int, x: Optional[float] = None, y: Optional[float] = None,
                  angle: Optional[float] = None) -> bool:
        """Move pose ``k`` (1, 2 or 3) to ``x``, ``y`` and turn it to
        ``angle`` (radians); what is not given stays. Returns whether the
        core accepted the move (else :attr:`error` says why and nothing
        changed), as a drag does."""
        poses = self._moved_pose(k, x, y, angle)
        return self._propose(poses, self.driven_center, self.driving_center)

    def move_driven_center(self, point: Point) -> bool:
        """Move ``C0``; returns whether the core accepted it (see :meth:`move_pose`)."""
        return self._propose(self.task.poses, _point(point, "driven_center"), self.driving_center)

    def move_driving_center(self, point: Point) -> bool:
        """Move ``A0``; returns whether the core accepted it (see :meth:`move_pose`)."""
        return self._propose(self.task.poses, self.driven_center, _point(point, "driving_center"))

    def best_pivot(self) -> bool:
        """Put ``A0`` on the map's best pivot (the ``b`` key): the best
        acceptable one, else the branch-free one farthest from the
        branch-defect boundary. Returns False (and says so) when the map
        has neither."""
        smap = self.solution_map
        best = smap.best_pivots(1) or smap.best_pivots(1, rank_by="margin")
        if best:
            return self.move_driving_center(best[0].center)
        self.error = "no branch-free driving pivot in the view"
        self._draw_state(map_changed=False)
        return False

    def reset(self) -> None:
        """Go back to the state the explorer opened with (the ``r`` key)."""
        self.error = None
        changed = self._state.smap is not self._initial.smap
        self._state = self._initial
        self._draw_state(map_changed=changed)

    def _moved_pose(self, k: int, x: Optional[float], y: Optional[float], angle: Optional[float]) -> List[Pose]:
        poses = [tuple(p) for p in self.task.poses]
        if not 1 <= k <= len(poses):
            raise burmester.InvalidInputError(f"pose must be from 1 to {len(poses)}, got {k}")
        px, py, pa = poses[k - 1]
        poses[k - 1] = (
            px if x is None else float(x),
            py if y is None else float(y),
            pa if angle is None else float(angle),
        )
        return [(p[0], p[1], p[2]) for p in poses]

    # ------------------------------------------------------------------
    # Saving

    def save(self, path: Union[str, Path], *, dpi: float = 100.0) -> Path:
        """Write what the explorer shows now, by the file type:

        - ``.png``, ``.pdf``: the figure (matplotlib, at ``dpi``);
        - ``.svg``, ``.dxf``: the linkage, by ``burmester.export``
          (``linkage_svg`` / ``linkage_dxf``, with the task's poses);
        - ``.toml``: the task file of the task, ``C0``, the view and the
          limits (:func:`burmester.taskfile.dumps`), which ``burmester map``
          and the other commands read.

        Returns the path. Raises :class:`burmester.InvalidInputError` for
        another type or a folder that does not exist, and ImportError for
        ``.dxf`` when ezdxf is not installed (``pip install "burmester[plot]"``).
        """
        p = Path(path)
        suffix = p.suffix.lower()
        if suffix not in (".png", ".pdf", ".svg", ".dxf", ".toml"):
            raise burmester.InvalidInputError(
                f"the explorer saves .png or .pdf (the figure), .svg or .dxf (the linkage) "
                f"or .toml (the task file), got {p.name!r}"
            )
        if not p.parent.is_dir():
            raise burmester.InvalidInputError(
                f"cannot write {p}: the folder {str(p.parent)!r} does not exist; create it first"
            )
        # Each file whole to a temporary file beside it, moved into place
        # when complete (burmester._io).
        if suffix in (".png", ".pdf"):
            with _io.atomic_path(p) as tmp:
                self.figure.savefig(tmp, dpi=dpi)
        elif suffix == ".toml":
            spec = TaskSpec(
                poses=tuple((x, y, a) for x, y, a in self.task.poses),
                driven_center=self.driven_center,
                view=self.grid,
                limits=self.limits,
                source="<explorer>",
            )
            save_task(spec, p)
        else:
            from burmester import export  # ezdxf only for .dxf, and only now

            writer = export.linkage_svg if suffix == ".svg" else export.linkage_dxf
            writer(self.linkage(), p, task=self.task)
        return p

    # ------------------------------------------------------------------
    # Drawing

    def _build(self) -> None:
        """The artists that stay: the map image, the handles, the texts."""
        ax = self.ax_map
        extent = self.grid.extent
        st = self._state
        self._image: AxesImage = ax.imshow(
            bp.map_categories(st.smap.branch_free, st.smap.acceptable), origin="lower", extent=extent,
            cmap=bp.MAP_CMAP, vmin=0, vmax=2, interpolation="nearest", zorder=0,
        )
        self._image.set_gid("branch-map")
        (self._triangle,) = ax.plot([], [], color=bp.POLE_COLOR, linewidth=1.0, zorder=4)
        self._triangle.set_gid("pole-triangle")
        (self._poles,) = ax.plot([], [], linestyle="none", marker="o", markersize=5, color=bp.POLE_COLOR, zorder=5)
        self._poles.set_gid("poles")
        self._pose_dots: List[Line2D] = []
        self._pose_flags: List[Line2D] = []
        self._angle_handles: List[Line2D] = []
        self._labels: Dict[str, Annotation] = {}
        for k in range(1, len(st.task) + 1):
            color = bp.POSE_COLORS[k]
            (flag,) = ax.plot([], [], color=color, linewidth=2.0, zorder=7)
            flag.set_gid(f"pose-flag-{k}")
            (dot,) = ax.plot([], [], linestyle="none", marker="o", markersize=9, color=color,
                             markeredgecolor="black", zorder=8)
            dot.set_gid(f"pose-{k}")
            (tip,) = ax.plot([], [], linestyle="none", marker="s", markersize=6, color="white",
                             markeredgecolor=color, markeredgewidth=1.5, zorder=8)
            tip.set_gid(f"pose-angle-{k}")
            self._pose_flags.append(flag)
            self._pose_dots.append(dot)
            self._angle_handles.append(tip)
            self._labels[f"pose-{k}"] = ax.annotate(
                str(k), (0.0, 0.0), xytext=(6, 6), textcoords="offset points", fontsize=9,
                color=color, zorder=9,
            )
        (self._c0,) = ax.plot([], [], linestyle="none", marker="^", markersize=11, color="#ff7f0e",
                              markeredgecolor="black", zorder=8)
        self._c0.set_gid("driven-pivot")
        (self._a0,) = ax.plot([], [], linestyle="none", marker="*", markersize=16, color="#ffd700",
                              markeredgecolor="black", zorder=9)
        self._a0.set_gid("driving-pivot")
        for name in ("P12", "P13", "P23"):
            self._labels[name] = ax.annotate(
                name, (0.0, 0.0), xytext=(4, 4), textcoords="offset points", fontsize=8, zorder=6,
            )
        for name in _FIXED_HANDLES:
            self._labels[name] = ax.annotate(
                name, (0.0, 0.0), xytext=(7, 7), textcoords="offset points", fontsize=9, zorder=9,
            )
        ax.legend(
            handles=[
                Patch(facecolor=bp.FREE_COLOR, edgecolor="0.5", label="branch-free A0"),
                Patch(facecolor=bp.ACCEPT_COLOR, edgecolor="0.5", label="and acceptable"),
                Line2D([], [], color="0.3", linewidth=1.6, label="Filemon curves"),
            ],
            loc="lower left", fontsize="small", framealpha=0.85,
        )
        ax.set_xlim(extent[0], extent[1])
        ax.set_ylim(extent[2], extent[3])
        ax.set_aspect("equal")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_title(
            "drag the poses (dots: move, squares: turn), C0 (triangle) and A0 (star)", fontsize=9,
        )
        self.figure.suptitle("Driving crank center-point plane and the linkage")
        # The footer: the figures and the verdict under the limits, wrapped
        # to the figure's width (_footer), above the status line.
        self._figures_text: Text = self.figure.text(
            0.06, 0.05, "", fontsize=9, va="bottom", family="monospace", wrap=True
        )
        self._figures_text.set_gid("figures")
        self._status_text: Text = self.figure.text(0.06, 0.015, "", fontsize=9, va="bottom", color="#b2182b")
        self._status_text.set_gid("status")
        self._help_text: Text = self.figure.text(
            0.98, 0.015, "keys: b best pivot, r reset, e save", fontsize=8, ha="right", va="bottom", color="0.4",
        )
        self._help_text.set_gid("help")
        self._flag_length = 0.06 * max(extent[1] - extent[0], extent[3] - extent[2])

    def _draw_state(self, map_changed: bool = True) -> None:
        """Redraw from the state: the map in place (when it changed), the
        curves, poles, handles, linkage and texts."""
        st = self._state
        extent = self.grid.extent
        ax = self.ax_map
        if map_changed or not self._map_artists:
            self._image.set_data(bp.map_categories(st.smap.branch_free, st.smap.acceptable))
            for art in self._map_artists:
                art.remove()
            self._map_artists = bp.draw_conics(ax, st.filemon, extent)
            # A pure translation between two poses puts their pole at
            # infinity: no pole circle, no pole triangle, one label hidden.
            finite = [(p.pair, p.point) for p in st.task.poles if p.point is not None]
            if len(finite) == 3:
                self._map_artists.append(
                    bp._draw_circle(ax, st.task.pole_circle(), extent, "pole-circle", "pole circle")
                )
            poles = [p for _, p in finite]
            self._poles.set_data([p[0] for p in poles], [p[1] for p in poles])
            shown = {f"P{i}{j}": p for (i, j), p in finite}
            for name in ("P12", "P13", "P23"):
                self._labels[name].set_visible(name in shown)
                if name in shown:
                    self._labels[name].xy = shown[name]
            closed = poles + poles[:1] if len(poles) == 3 else []
            self._triangle.set_data([p[0] for p in closed], [p[1] for p in closed])
        self._draw_handles(st.task.poses, st.filemon.driven_center, st.driving_center)

        self.ax_linkage.clear()
        bp.linkage(st.linkage, task=st.task, ax=self.ax_linkage, legend=False)
        self._figures_text.set_text(self._footer())
        self._status_text.set_text("" if self.error is None else f"refused: {self.error}")
        self._fit_footer()
        self.figure.canvas.draw_idle()

    def _fit_footer(self) -> None:
        """Keep the axes, their tick labels and x labels above the footer:
        on a narrow figure the footer wraps to more lines, and the axes'
        bottom rises by what it needs (never below the layout's 0.2)."""
        get_renderer = getattr(self.figure.canvas, "get_renderer", None)
        if get_renderer is None:
            return
        renderer = get_renderer()
        height = self.figure.bbox.height
        if height <= 0:
            return
        top = self._figures_text.get_window_extent(renderer).y1
        below = 0.0
        for ax in (self.ax_map, self.ax_linkage):
            tight = ax.get_tightbbox(renderer)
            if tight is not None:
                below = max(below, ax.get_window_extent(renderer).y0 - tight.y0)
        bottom = min(0.45, max(0.2, (top + below + 6.0) / height))
        if abs(bottom - self.figure.subplotpars.bottom) > 1e-3:
            self.figure.subplots_adjust(bottom=bottom)

    def verdict(self) -> str:
        """The linkage's verdict under the explorer's limits, in words: what
        :attr:`burmester.SolutionMap.acceptable` decides for it
        (:func:`burmester.pivots.violations`), ``"acceptable under the
        limits (...)"`` or ``"not acceptable: ..."`` with every limit it
        misses."""
        lim = self.limits
        bad = pv.violations(self._state.linkage.figures, lim)
        if bad:
            return "not acceptable: " + "; ".join(bad)
        need = f"transmission >= {lim.min_transmission_deg:g} deg, link ratio <= {lim.max_link_ratio:g}"
        if lim.input != "any":
            need += f", {lim.input} input"
        return f"acceptable under the limits ({need})"

    def _footer(self) -> str:
        """The footer's text: the linkage's figures, then :meth:`verdict`
        (the text is wrapped to the figure's width when drawn)."""
        st = self._state
        fig = st.linkage.figures
        mt = fig.min_transmission_deg
        turns = "turns fully" if fig.input_full else "rocks"
        parts = [
            f"A0 {_fmt(st.driving_center)}  C0 {_fmt(st.filemon.driven_center)}  {fig.grashof}, input {turns}",
            "min transmission " + ("-" if mt is None else f"{mt:.1f} deg"),
            f"direction {fig.direction or 'none'}",
            "branch-free" if fig.branch_free else "branch defect",
            f"link ratio {fig.link_ratio:.3g}",
        ]
        # Two lines, each wrapped by matplotlib to the figure's width
        # (``wrap=True``) when the figure is narrow.
        return ";  ".join(parts) + "\n" + self.verdict()

    def _draw_handles(self, poses: Sequence[Sequence[float]], c0: Point, a0: Point) -> None:
        for k, (x, y, a) in enumerate(poses):
            tx, ty = x + self._flag_length * math.cos(a), y + self._flag_length * math.sin(a)
            self._pose_dots[k].set_data([x], [y])
            self._pose_flags[k].set_data([x, tx], [y, ty])
            self._angle_handles[k].set_data([tx], [ty])
            self._labels[f"pose-{k + 1}"].xy = (x, y)
        self._c0.set_data([c0[0]], [c0[1]])
        self._a0.set_data([a0[0]], [a0[1]])
        self._labels["C0"].xy = c0
        self._labels["A0"].xy = a0

    # ------------------------------------------------------------------
    # Events

    def _connect(self) -> None:
        canvas = self.figure.canvas
        # Plain functions, not bound methods: matplotlib keeps only weak
        # references to bound methods, and the figure must keep the
        # explorer alive even when the caller drops it.
        self._cids = [
            canvas.mpl_connect("button_press_event", lambda e: self._on_press(e)),
            canvas.mpl_connect("motion_notify_event", lambda e: self._on_motion(e)),
            canvas.mpl_connect("button_release_event", lambda e: self._on_release(e)),
            canvas.mpl_connect("scroll_event", lambda e: self._on_scroll(e)),
            canvas.mpl_connect("key_press_event", lambda e: self._on_key(e)),
        ]

    def disconnect(self) -> None:
        """Stop taking events (the figure stays as it is)."""
        for cid in self._cids:
            self.figure.canvas.mpl_disconnect(cid)
        self._cids = []

    def _toolbar_busy(self) -> bool:
        toolbar = getattr(self.figure.canvas, "toolbar", None)
        return bool(getattr(toolbar, "mode", ""))

    def _handle_points(self) -> List[Tuple[str, Point]]:
        """Every handle's name and position, in the order a tie is broken."""
        st = self._state
        out: List[Tuple[str, Point]] = [("A0", st.driving_center), ("C0", st.filemon.driven_center)]
        for k, (x, y, a) in enumerate(st.task.poses, start=1):
            out.append((f"angle-{k}", (x + self._flag_length * math.cos(a), y + self._flag_length * math.sin(a))))
        for k, (x, y, _) in enumerate(st.task.poses, start=1):
            out.append((f"pose-{k}", (x, y)))
        return out

    def _hit(self, x_px: float, y_px: float) -> Optional[str]:
        """The handle within :data:`PICK_PIXELS` of a pixel, the nearest (ties: first)."""
        names = self._handle_points()
        disp = self.ax_map.transData.transform(np.array([p for _, p in names], dtype=float))
        d = np.hypot(disp[:, 0] - x_px, disp[:, 1] - y_px)
        k = int(np.argmin(d))
        return names[k][0] if d[k] <= PICK_PIXELS else None

    def _candidate(self, name: str, x: float, y: float) -> Tuple[List[Pose], Point, Point]:
        """The poses and pivots with handle ``name`` moved to ``(x, y)``."""
        poses = [(p[0], p[1], p[2]) for p in self.task.poses]
        c0, a0 = self.driven_center, self.driving_center
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
                poses[int(k) - 1] = (px, py, _near_angle(math.atan2(y - py, x - px), pa))
        return poses, c0, a0

    def _drag_to(self, x: float, y: float) -> None:
        assert self._dragging is not None
        poses, c0, a0 = self._candidate(self._dragging, x, y)
        if self.live or self._dragging == "A0":
            self._propose(poses, c0, a0)
        else:
            self._pending = (poses, c0, a0)
            self._draw_handles(poses, c0, a0)
            self.figure.canvas.draw_idle()

    def _on_press(self, event: MouseEvent) -> None:
        if event.inaxes is not self.ax_map or event.button != 1:
            return
        if event.xdata is None or event.ydata is None or self._toolbar_busy():
            return
        self._dragging = self._hit(event.x, event.y) or "A0"
        self._pending = None
        if self._dragging == "A0":
            self._drag_to(float(event.xdata), float(event.ydata))

    def _on_motion(self, event: MouseEvent) -> None:
        if self._dragging is None:
            return
        if event.inaxes is not self.ax_map or event.xdata is None or event.ydata is None:
            return  # outside the plane: the handle waits where it was last
        self._drag_to(float(event.xdata), float(event.ydata))

    def _on_release(self, event: MouseEvent) -> None:
        if self._dragging is None:
            return
        self._dragging = None
        pending, self._pending = self._pending, None
        if pending is not None:
            # The last position inside the plane, wherever the button went up.
            self._propose(*pending)

    def _on_scroll(self, event: MouseEvent) -> None:
        if event.inaxes is not self.ax_map or self._dragging is not None:
            return
        name = self._hit(event.x, event.y)
        if name is None or name in _FIXED_HANDLES:
            return
        k = int(name.split("-")[1])
        angle = self.task.poses[k - 1][2] + math.radians(ANGLE_STEP_DEG) * float(event.step)
        self.move_pose(k, angle=angle)

    def _on_key(self, event: KeyEvent) -> None:
        if self._dragging is not None:
            return
        if event.key == "b":
            self.best_pivot()
        elif event.key == "r":
            self.reset()
        elif event.key == "e":
            if self.export_to is None:
                self.error = "nothing to save to: give explore(..., export_to=path) or call save(path)"
                self._draw_state(map_changed=False)
                return
            try:
                self.save(self.export_to)
            except (burmester.BurmesterError, ImportError, OSError) as e:
                self.error = f"saving {self.export_to} failed: {e}"
                self._draw_state(map_changed=False)
            else:
                self.error = None
                self._status_text.set_text(f"saved {self.export_to}")
                self.figure.canvas.draw_idle()

    def __repr__(self) -> str:
        a0, c0 = self.driving_center, self.driven_center
        return f"<Explorer A0={_fmt(a0)} C0={_fmt(c0)} grid={self.grid.nx}x{self.grid.ny} live={self.live}>"
