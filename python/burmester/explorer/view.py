"""The explorer's figure: the drawing and the events (see :mod:`burmester.explorer`).

:class:`Explorer` draws an :class:`~burmester.explorer.state.ExplorerState` and
turns mouse and key events into its moves."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Dict, List, Optional, Sequence, Tuple, Union

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.backend_bases import KeyEvent, MouseButton, MouseEvent
from matplotlib.figure import Figure
from matplotlib.image import AxesImage
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.text import Annotation, Text

import burmester
from burmester import _io
from burmester import plot as bp
from burmester._burmester import DesignLimits, Filemon, Grid, SolutionMap, SynthesizedFourBar, Task
from burmester.explorer.state import FIXED_HANDLES, ExplorerState, Point, Pose, fmt, point
from burmester.taskfile import has_pole_triangle, save as save_task

__all__ = ["ANGLE_STEP_DEG", "EXPLORE_SAMPLES", "LIVE_SAMPLES", "PICK_PIXELS", "Explorer"]

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


def _view_grid(filemon: Filemon, view: Optional[bp.ViewLike], grid: Optional[Tuple[int, int]]) -> Grid:
    """The explorer's grid: a Grid as given, else the view (default: the
    pictures' default view) with :data:`EXPLORE_SAMPLES` along the longer
    side, or ``grid = (nx, ny)`` samples."""
    return bp._as_grid(filemon, view, grid, EXPLORE_SAMPLES)


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
        c0 = point(driven_center, "driven_center")
        lim = DesignLimits() if limits is None else limits
        filemon = task.filemon(c0)
        view_grid = _view_grid(filemon, view, grid)
        self.live: bool = view_grid.size <= LIVE_SAMPLES if live is None else bool(live)
        self.export_to: Optional[Path] = None if export_to is None else Path(export_to)
        #: What is shown: the task, the pivots, the map, the linkage.
        self.state = ExplorerState(task, filemon, view_grid, lim, driving_center)
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
        return self.state.now.task

    @property
    def driven_center(self) -> Point:
        """``C0`` as it is now."""
        return self.state.now.filemon.driven_center

    @property
    def driving_center(self) -> Point:
        """``A0`` as it is now."""
        return self.state.now.driving_center

    @property
    def filemon(self) -> Filemon:
        """Filemon's construction of the task and ``C0`` as they are now."""
        return self.state.now.filemon

    @property
    def solution_map(self) -> SolutionMap:
        """The solution map of the view as it is now (its ``branch_free``
        is the shaded branch map)."""
        return self.state.now.smap

    @property
    def grid(self) -> Grid:
        """The grid of the view (it stays put while things move)."""
        return self.state.grid

    @property
    def limits(self) -> DesignLimits:
        """The :class:`burmester.DesignLimits` behind the acceptable region."""
        return self.state.limits

    @property
    def error(self) -> Optional[str]:
        """The message of the last refused move; None after a good one."""
        return self.state.error

    @error.setter
    def error(self, message: Optional[str]) -> None:
        self.state.error = message

    def linkage(self) -> SynthesizedFourBar:
        """The chosen linkage: ``filemon.four_bar(driving_center)``."""
        return self.state.now.linkage

    def _propose(self, poses: Sequence[Pose], c0: Point, a0: Point) -> bool:
        """Move to the state of these poses and pivots if the core accepts
        it; otherwise keep the state and show the error. Redraws."""
        accepted, changed = self.state.propose(poses, c0, a0)
        self._draw_state(map_changed=changed)
        return accepted

    def move_pose(self, k: int, x: Optional[float] = None, y: Optional[float] = None,
                  angle: Optional[float] = None) -> bool:
        """Move pose ``k`` (1, 2 or 3) to ``x``, ``y`` and turn it to
        ``angle`` (radians); what is not given stays. Returns whether the
        core accepted the move (else :attr:`error` says why and nothing
        changed), as a drag does."""
        poses = self.state.moved_pose(k, x, y, angle)
        return self._propose(poses, self.driven_center, self.driving_center)

    def move_driven_center(self, at: Point) -> bool:
        """Move ``C0``; returns whether the core accepted it (see :meth:`move_pose`)."""
        return self._propose(self.task.poses, point(at, "driven_center"), self.driving_center)

    def move_driving_center(self, at: Point) -> bool:
        """Move ``A0``; returns whether the core accepted it (see :meth:`move_pose`)."""
        return self._propose(self.task.poses, self.driven_center, point(at, "driving_center"))

    def best_pivot(self) -> bool:
        """Put ``A0`` on the map's best pivot (the ``b`` key): the best
        acceptable one, else the branch-free one farthest from the
        branch-defect boundary. Returns False (and says so) when the map
        has neither."""
        best = self.state.best_pivot()
        if best is not None:
            return self.move_driving_center(best)
        self.error = "no branch-free driving pivot in the view"
        self._draw_state(map_changed=False)
        return False

    def reset(self) -> None:
        """Go back to the state the explorer opened with (the ``r`` key)."""
        self._draw_state(map_changed=self.state.reset())

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
            save_task(self.state.task_spec(), p)
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
        st = self.state.now
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
        for name in self.state.pole_names():
            self._labels[name] = ax.annotate(
                name, (0.0, 0.0), xytext=(4, 4), textcoords="offset points", fontsize=8, zorder=6,
            )
        for name in FIXED_HANDLES:
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
        # to the figure's width (_fit_footer), above the status line.
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

    def _draw_state(self, map_changed: bool = True) -> None:
        """Redraw from the state: the map in place (when it changed), the
        curves, poles, handles, linkage and texts."""
        st = self.state.now
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
            triangle = has_pole_triangle(st.task)
            if triangle:
                self._map_artists.append(
                    bp._draw_circle(ax, st.task.pole_circle(), extent, "pole-circle", "pole circle")
                )
            poles = [p for _, p in finite]
            self._poles.set_data([p[0] for p in poles], [p[1] for p in poles])
            shown = {f"P{i}{j}": p for (i, j), p in finite}
            for name in self.state.pole_names():
                self._labels[name].set_visible(name in shown)
                if name in shown:
                    self._labels[name].xy = shown[name]
            closed = poles + poles[:1] if triangle else []
            self._triangle.set_data([p[0] for p in closed], [p[1] for p in closed])
        self._draw_handles(st.task.poses, st.filemon.driven_center, st.driving_center)

        self.ax_linkage.clear()
        bp.linkage(st.linkage, task=st.task, ax=self.ax_linkage, legend=False)
        # Two lines, each wrapped by matplotlib to the figure's width
        # (``wrap=True``) when the figure is narrow.
        self._figures_text.set_text(self.state.footer())
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
        return self.state.verdict()

    def _draw_handles(self, poses: Sequence[Sequence[float]], c0: Point, a0: Point) -> None:
        for k, (x, y, a) in enumerate(poses):
            tx, ty = self.state.flag_end(x, y, a)
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

    def drag(self, start: Point, end: Point, steps: int = 4) -> None:
        """Drag from ``start`` to ``end`` (task coordinates) with the mouse
        events a user's left-button drag sends: a press at ``start``,
        ``steps`` motions along the straight line to ``end``, a release
        there. For scripted pictures (the README's and the gallery's) and
        tests: the events go through the figure's canvas as a user's do."""
        canvas = self.figure.canvas
        (x0, y0), (x1, y1) = point(start, "start"), point(end, "end")
        path = [(x0 + (x1 - x0) * k / steps, y0 + (y1 - y0) * k / steps) for k in range(1, steps + 1)]
        names = ["button_press_event"] + ["motion_notify_event"] * steps
        for name, xy in list(zip(names, [(x0, y0)] + path)) + [("button_release_event", (x1, y1))]:
            px, py = self.ax_map.transData.transform(xy)
            canvas.callbacks.process(name, MouseEvent(name, canvas, px, py, button=MouseButton.LEFT))

    def _toolbar_busy(self) -> bool:
        toolbar = getattr(self.figure.canvas, "toolbar", None)
        return bool(getattr(toolbar, "mode", ""))

    def _hit(self, x_px: float, y_px: float) -> Optional[str]:
        """The handle within :data:`PICK_PIXELS` of a pixel, the nearest (ties: first)."""
        names = self.state.handle_points()
        disp = self.ax_map.transData.transform(np.array([p for _, p in names], dtype=float))
        d = np.hypot(disp[:, 0] - x_px, disp[:, 1] - y_px)
        k = int(np.argmin(d))
        return names[k][0] if d[k] <= PICK_PIXELS else None

    def _drag_to(self, x: float, y: float) -> None:
        assert self._dragging is not None
        poses, c0, a0 = self.state.candidate(self._dragging, x, y)
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
        if name is None or name in FIXED_HANDLES:
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
        return f"<Explorer A0={fmt(a0)} C0={fmt(c0)} grid={self.grid.nx}x{self.grid.ny} live={self.live}>"
