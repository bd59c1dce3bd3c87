"""Pictures of a three-position synthesis, after Borm & Kim's figures, and
of the Burmester curves and points of four and five poses.

- :func:`center_plane`: the driving crank's center-point plane (the paper's
  Fig. 10 and 12): branch-free pivots shaded, the two transformed Filemon
  curves drawn exactly, the poles, the pole triangle and circle, the driven
  crank's fixed pivot, and optional overlays.
- :func:`circle_plane`: the circle-point plane (Fig. 3 and 11): the three
  lines through ``C1``, Filemon's double wedges, the image poles and their circle.
- :func:`burmester_plane`: four or five poses: the center-point curve
  coloured by the crank's order class, the poles and the points ``Q_jk``;
  the Burmester points of five poses on their two curves.
- :func:`pair_map`: four poses: the pair map, every linkage of the task on
  one picture (driving dyad across, driven dyad up), by category, with
  transmission contours and the best pairs.
- :func:`linkage`: a synthesized four-bar drawn at the poses.
- :func:`animate`: a GIF or MP4 of the four-bar driven through the poses.
- :func:`poses`, :func:`four_bar`, :func:`solution_map`, :func:`atlas`: one
  object at a glance (a task, a four-bar at an input angle, a solution map,
  a pivot-pair atlas); with :func:`center_plane` and :func:`linkage` they
  are the pictures the objects show in Jupyter (``_repr_png_``).
- :func:`explore`: the interactive explorer (:mod:`burmester.explorer`):
  drag the poses and pivots, and the map and the linkage follow.
- :func:`drive_map`, :func:`sixbar`, :func:`animate_sixbar`: a motor for a
  linkage whose input swings (the Watt II six-bar): where the drive's crank
  pivot may go, the six-bar at the poses, and a full crank turn animated.
- :func:`slider_crank`, :func:`animate_slider_crank`: a slider-crank (the
  guide as a line, the slider as a block on it), alone or synthesized for a
  task at its poses, and driven through them.
- :func:`inverted_slider_crank`, :func:`animate_inverted_slider_crank`: an
  inverted slider-crank (the slotted coupler and the block on its swivel),
  alone or synthesized for a task, and driven over its range or through the
  poses.

Needs matplotlib (``pip install "burmester[plot]"``). Every drawing function
takes an optional ``ax`` to draw into and returns the Axes, so you can keep
editing; ``ax.figure.savefig("out.png")`` saves it. The artists carry gids
(``"branch-map"``, ``"conic-1"`` ... ``"conic-3"`` by pose, ``"poles"``,
``"pole-circle"``, ...) to find and restyle them: ``[a for a in
ax.get_children() if a.get_gid() == "poles"]``.

Common parameters: ``labels`` (default True) writes the names of the
points (or joints) and a title; ``legend`` (default True) draws a legend to
the right of the axes; ``units``, the unit of the lengths (``"mm"``), is
written on the axes (``x [mm]``; None: plain ``x`` and ``y``); ``ax`` is the
Axes to draw into (default: a new figure).

Lengths: every drawing with lengths on its axes takes ``units="mm"`` (any
unit name; :mod:`burmester.units`) and labels its axes ``x [mm]``, ``y
[mm]`` (plain ``x``, ``y`` without one); :func:`linkage` and :func:`four_bar`
label each link with its length (:func:`label_lengths`, gid
``"link-length"``). Nothing is cut silently: a point a plane marks that
lies outside its view is noted on the picture (:func:`note_outside`, gids
``"out-of-view"`` and ``"out-of-view-marks"``).

Colours follow the poses throughout: pose 1 red, pose 2 purple, pose 3 blue
(pose 4 green, pose 5 brown);
a transformed Filemon curve has the colour of its line's pose.
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Dict, List, Literal, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

try:
    import matplotlib
    import matplotlib.pyplot as plt
    from matplotlib.animation import FFMpegWriter, FuncAnimation, PillowWriter
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.colors import ListedColormap, to_hex
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, Patch, PathPatch, Polygon
    from matplotlib.text import Annotation
    from matplotlib.path import Path as MplPath
except ImportError as e:  # pragma: no cover - exercised in a subprocess test
    raise ImportError(
        'burmester.plot needs matplotlib; install it with: pip install "burmester[plot]"'
    ) from e

import burmester
from burmester import _io, _scene, _view
from burmester._burmester import Filemon, Grid, PairMap, SynthesizedFourBar, Task, clip_line
from burmester.taskfile import (
    DEFAULT_GRID, curve_plane_points, default_curve_view, default_view, describe_outside, outside_view,
)
from burmester.units import format_length, label_axes

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from burmester._burmester import Method, Mode, RankBy
    from burmester.explorer import Explorer

Point = Tuple[float, float]
Extent = Tuple[float, float, float, float]
#: A view: a :class:`burmester.Grid`, or ``(xmin, xmax, ymin, ymax)``.
ViewLike = Union[Grid, Sequence[float]]

#: Colour of each pose (1 to 5); lines, curves and linkages use them.
POSE_COLORS: Dict[int, str] = {1: "#d62728", 2: "#9467bd", 3: "#1f77b4", 4: "#2ca02c", 5: "#8c564b"}
#: Shading of branch-defective pivots (the page), branch-free pivots, and
#: branch-free pivots that also meet the limits (the ``acceptable`` overlay).
DEFECT_COLOR = "#ffffff"
FREE_COLOR = "#c7e9b4"
ACCEPT_COLOR = "#41ab5d"
POLE_COLOR = "#000000"
CIRCLE_COLOR = "#7f7f7f"


# ---------------------------------------------------------------------------
# Helpers


def _as_grid(filemon: Filemon, view: Optional[ViewLike], grid: Optional[Tuple[int, int]],
             samples: int = DEFAULT_GRID) -> Grid:
    """A :class:`burmester.Grid` from a Grid, an ``(xmin, xmax, ymin, ymax)``
    sequence or None (the default view), both with ``samples`` along the
    longer side, or ``grid = (nx, ny)`` samples when given (:mod:`burmester._view`)."""
    return _view.view_grid(view, grid, lambda: default_view(filemon, samples), samples)


def _new_axes(ax: Optional[Axes], figsize: Tuple[float, float] = (8.0, 6.4)) -> Axes:
    if ax is not None:
        return ax
    _, new = plt.subplots(figsize=figsize)
    return new


def _draw_circle(ax: Axes, circle: Dict[str, Any], extent: Extent, gid: str, label: str) -> Artist:
    """A pole circle (or the line it becomes when the poles are collinear)."""
    art: Artist
    if circle["kind"] == "circle":
        patch = Circle(
            circle["center"], circle["radius"], fill=False, color=CIRCLE_COLOR,
            linestyle="--", linewidth=1.0, label=label, zorder=2,
        )
        ax.add_patch(patch)
        art = patch
    else:
        seg = clip_line(circle["point"], circle["direction"], extent)
        xs, ys = ([seg[0][0], seg[1][0]], [seg[0][1], seg[1][1]]) if seg else ([], [])
        (art,) = ax.plot(
            xs, ys, color=CIRCLE_COLOR, linestyle="--", linewidth=1.0, label=label, zorder=2
        )
    art.set_gid(gid)
    return art


def _markers(ax: Axes, points: npt.ArrayLike, gid: str, label: Optional[str], **style: Any) -> Artist:
    """Points drawn as markers without a line, tagged with ``gid``."""
    pts = np.asarray(points, dtype=float).reshape(-1, 2)
    (art,) = ax.plot(pts[:, 0], pts[:, 1], linestyle="none", label=label, **style)
    art.set_gid(gid)
    return art


def _label(ax: Axes, p: Point, text: str, color: str = "black") -> None:
    ax.annotate(
        text, p, xytext=(4, 4), textcoords="offset points", fontsize=9, color=color, zorder=6
    )


def _legend(ax: Axes, handles: Optional[List[Any]] = None) -> None:
    """The legend, to the right of the axes (of ``handles`` when given)."""
    kwargs: Dict[str, Any] = {} if handles is None else {"handles": handles}
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, fontsize="small", **kwargs)


def _finish(ax: Axes, extent: Extent, legend: bool, handles: List[Any]) -> None:
    """Limits to ``extent``, equal aspect, and the legend of ``handles``."""
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(extent[2], extent[3])
    ax.set_aspect("equal")
    if legend:
        _legend(ax, handles)


def note_outside(ax: Axes, extent: Extent, points: Sequence[Tuple[str, Optional[Sequence[float]]]],
                 units: Optional[str] = None) -> List[Tuple[str, Point]]:
    """Say on the picture which of the named points (``(name, (x, y))``,
    None for a point at infinity) lie outside the view ``extent``: a note
    in the corner of the axes with the fewest drawn points, listing them
    with their coordinates (gid
    ``"out-of-view"``, the words of
    :func:`burmester.taskfile.describe_outside`) and, inside the view's
    edge, an arrow toward each, named (points in about the same direction
    share one; gid ``"out-of-view-marks"``). Returns the points outside
    (empty: nothing drawn), so that a caller can say the same in words."""
    outside = outside_view(points, extent)
    if not outside:
        return outside
    x0, x1, y0, y1 = extent
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    hw, hh = (x1 - x0) / 2, (y1 - y0) / 2
    groups: List[Tuple[Tuple[float, float], List[str]]] = []
    for name, (px, py) in outside:
        dx, dy = (px - cx) / hw, (py - cy) / hh  # in half-widths: the edge is where max(|dx|, |dy|) = 1
        t = 1.0 / max(abs(dx), abs(dy))
        at = (dx * t, dy * t)
        for place, names in groups:
            if math.hypot(place[0] - at[0], place[1] - at[1]) < 0.15:
                names.append(name)
                break
        else:
            groups.append((at, [name]))
    for (ex, ey), names in groups:
        tip = (cx + 0.98 * ex * hw, cy + 0.98 * ey * hh)
        tail = (cx + 0.86 * ex * hw, cy + 0.86 * ey * hh)
        arrow = ax.annotate(
            ", ".join(names), xy=tip, xytext=tail, fontsize=7, color="0.2", ha="center", va="center", zorder=9,
            bbox={"boxstyle": "round,pad=0.2", "facecolor": "white", "edgecolor": "0.6", "alpha": 0.85},
            arrowprops={"arrowstyle": "->", "color": "0.2", "lw": 1.0},
        )
        arrow.set_gid("out-of-view-marks")
    # Words to wrap at, a name and its coordinates ("B4 (28.569, -40.158)", "x [-6, 12],") kept whole.
    words = re.findall(r"[^\s(\[]+ [(\[][^)\]]*[)\]],?|\S+", describe_outside(outside, extent, units))
    lines, line = [], ""
    for w in words:  # wrap at about 60 characters
        if line and len(line) + 1 + len(w) > 60:
            lines.append(line)
            line = w
        else:
            line = f"{line} {w}" if line else w
    lines.append(line)
    # Inside the axes (a note under them would run into a neighbouring
    # axes), in the corner where the fewest drawn points are.
    drawn = [np.asarray(a.get_xydata(), dtype=float).reshape(-1, 2) for a in ax.lines]
    pts = np.vstack(drawn) if drawn else np.zeros((0, 2))
    fx = (pts[:, 0] - x0) / (x1 - x0)
    fy = (pts[:, 1] - y0) / (y1 - y0)
    tall = 0.06 * len(lines)
    corners = [(0.01, 0.01, "left", "bottom"), (0.99, 0.01, "right", "bottom"),
               (0.01, 0.99, "left", "top"), (0.99, 0.99, "right", "top")]

    def crowd(corner: Tuple[float, float, str, str]) -> int:
        cx_, cy_, ha, va = corner
        xs = (fx < 0.6) if ha == "left" else (fx > 0.4)
        ys = (fy < tall + 0.02) if va == "bottom" else (fy > 0.98 - tall)
        return int(np.count_nonzero(xs & ys))

    ax_, ay_, ha, va = min(corners, key=crowd)
    note = ax.text(ax_, ay_, "\n".join(lines), transform=ax.transAxes, fontsize=7, ha=ha, va=va,
                   color="#8a1c1c", zorder=10, bbox={"boxstyle": "round,pad=0.3", "facecolor": "white",
                                                     "edgecolor": "#8a1c1c", "linewidth": 0.6, "alpha": 0.9})
    note.set_gid("out-of-view")
    return outside


def _renderer(ax: Axes) -> Any:
    """The figure's renderer, to measure text (None where the canvas has none)."""
    get = getattr(ax.figure.canvas, "get_renderer", None)
    try:
        return get() if get is not None else None
    except Exception:  # pragma: no cover - a backend without a renderer
        return None


def _text_box(t: Any, renderer: Any) -> Any:
    """A text's box on the screen, its background box's padding included
    and an annotation's leader left out (a leader may cross a label)."""
    from matplotlib.text import Text

    if isinstance(t, Annotation):
        t.update_positions(renderer)  # where its offset puts it now
    box = Text.get_window_extent(t, renderer)
    patch = t.get_bbox_patch()
    pad = 0.3 * t.get_fontsize() * t.figure.dpi / 72.0 if patch is not None else 0.0
    return box.expanded(1.0, 1.0).padded(pad)


def _overlap(a: Any, b: Any) -> float:
    """The area two display boxes share (0 when apart)."""
    w = min(a.x1, b.x1) - max(a.x0, b.x0)
    h = min(a.y1, b.y1) - max(a.y0, b.y0)
    return w * h if w > 0 and h > 0 else 0.0


#: Where a link's length label may sit: fractions along the link, and
#: offsets across it in points (tried in order, the first that overlaps
#: nothing is taken).
_ALONG = (0.5, 0.38, 0.62, 0.26, 0.74, 0.15, 0.85)
_ACROSS = (8.0, 18.0, 30.0, 45.0)


def label_lengths(ax: Axes, links: Sequence[Tuple[str, Sequence[float], Sequence[float]]],
                  units: Optional[str] = None, gid: str = "link-length", fontsize: float = 8.0,
                  color: str = "black", avoid: Sequence[Sequence[float]] = ()) -> List[Artist]:
    """Label each link ``(name, p, q)`` with its name and length (``"crank
    40 mm"``, :func:`burmester.units.format_length`) beside it, a thin
    leader from the label to the link, placed so that no two labels
    overlap, nor a label and a text already on the axes or a point of
    ``avoid`` (markers), and each stays inside the axes: the first free
    place of a few along the link (from its middle out) and across it
    (either side, nearest first). The labels have gid ``gid``; set the
    axes' limits first. Returns the labels."""
    renderer = _renderer(ax)
    taken = []
    if renderer is not None:
        from matplotlib.transforms import Bbox

        taken = [_text_box(t, renderer) for t in ax.texts if t.get_visible() and t.get_text()]
        r = 6.0 * ax.figure.dpi / 72.0  # a marker: about 12 points across
        for x, y in ax.transData.transform(np.asarray(avoid, dtype=float).reshape(-1, 2)):
            taken.append(Bbox([[x - r, y - r], [x + r, y + r]]))
    inside = ax.get_window_extent(renderer) if renderer is not None else None
    placed: List[Artist] = []
    for name, p, q in links:
        p_ = np.asarray(p, dtype=float)
        q_ = np.asarray(q, dtype=float)
        text = f"{name} {format_length(float(np.hypot(*(q_ - p_))), units)}"
        # The link's normal on the screen (points across it).
        sp, sq = ax.transData.transform([p_, q_])
        d = sq - sp
        n = np.array([-d[1], d[0]]) / (float(np.hypot(*d)) or 1.0)
        best: Optional[Tuple[float, Annotation]] = None
        places = [(t, side * across * n) for across in _ACROSS for t in _ALONG for side in (1.0, -1.0)]
        for t, off in places:
            at = p_ + t * (q_ - p_)
            ha = "left" if off[0] > 2 else "right" if off[0] < -2 else "center"
            va = "bottom" if off[1] > 2 else "top" if off[1] < -2 else "center"
            art = ax.annotate(text, (float(at[0]), float(at[1])), xytext=(float(off[0]), float(off[1])),
                              textcoords="offset points", ha=ha, va=va, fontsize=fontsize, zorder=9, color=color,
                              bbox={"boxstyle": "round,pad=0.2", "facecolor": "white", "edgecolor": color,
                                    "linewidth": 0.5, "alpha": 0.85},
                              arrowprops={"arrowstyle": "-", "color": color, "lw": 0.6, "shrinkA": 0.0,
                                          "shrinkB": 0.0})
            if renderer is None:  # nothing to measure with: the first place
                best = (0.0, art)
                break
            box = _text_box(art, renderer)
            cost = sum(_overlap(box, o) for o in taken)
            if inside is not None and not (box.x0 >= inside.x0 and box.x1 <= inside.x1
                                           and box.y0 >= inside.y0 and box.y1 <= inside.y1):
                cost += box.width * box.height  # partly outside the axes: as bad as covering a label
            if best is None or cost < best[0]:
                if best is not None:
                    best[1].remove()
                best = (cost, art)
            else:
                art.remove()
            if cost == 0.0:
                break
        assert best is not None
        chosen = best[1]
        chosen.set_gid(gid)
        if renderer is not None:
            taken.append(_text_box(chosen, renderer))
        placed.append(chosen)
    return placed


def link_segments(fb: burmester.FourBar, joints: Sequence[Sequence[float]]) -> List[Tuple[str, Sequence[float], Sequence[float]]]:
    """``(name, p, q)`` of the four links of a four-bar at its joints
    ``(O2, A, B, O4)`` (:meth:`burmester.FourBar.joints`): the ground
    ``O2 O4``, the crank ``O2 A``, the coupler ``A B`` and the rocker
    ``O4 B``; their lengths are ``fb.lengths``."""
    o2, a, b, o4 = joints
    return [("ground", o2, o4), ("crank", o2, a), ("coupler", a, b), ("rocker", o4, b)]


#: Largest ``frames`` of :func:`animate` and :func:`drive_angles`.
MAX_FRAMES = 10_000
#: Largest ``fps`` of :func:`animate`.
MAX_FPS = 240
#: Largest ``dpi`` of :func:`animate`.
MAX_DPI = 2400


def _count_in(name: str, value: Any, lo: int, hi: int) -> int:
    """``value`` as an int from ``lo`` to ``hi``, or InvalidInputError."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an int, got {type(value).__name__}")
    if not lo <= int(value) <= hi:
        raise burmester.InvalidInputError(f"{name} must be from {lo} to {hi}, got {int(value)}")
    return int(value)


def draw_conics(ax: Axes, filemon: Filemon, extent: Extent) -> List[Artist]:
    """The transformed Filemon curves clipped to ``extent``, every branch,
    in the colour of their line's pose (gid ``"conic-k"``; the first branch
    of each labelled), or, when every circle point is defective, a note
    saying so. Returns the artists drawn."""
    if filemon.all_defective:
        note = ax.text(
            0.5, 0.5, "every driving pivot has a branch defect",
            transform=ax.transAxes, ha="center", va="center", color="0.3",
        )
        note.set_gid("all-defective")
        return [note]
    drawn: List[Artist] = []
    for pose, kind, polylines in _scene.conics(filemon, extent):
        color = POSE_COLORS[pose]
        for k, pl in enumerate(polylines):
            (line,) = ax.plot(pl[:, 0], pl[:, 1], color=color, linewidth=1.6, zorder=3)
            line.set_gid(f"conic-{pose}")
            if k == 0:
                line.set_label(f"Filemon line {pose} transformed ({kind})")
            drawn.append(line)
    return drawn


def map_categories(free: npt.ArrayLike, acceptable: Optional[npt.ArrayLike] = None) -> npt.NDArray[np.int8]:
    """The shading of a branch map: 0 defective, 1 branch-free, 2
    branch-free and acceptable (where ``acceptable`` is given and true), the
    image data of :func:`center_plane`'s ``"branch-map"``."""
    free_b = np.asarray(free).astype(bool)
    cat = free_b.astype(np.int8)
    if acceptable is not None:
        cat[free_b & np.asarray(acceptable).astype(bool)] = 2
    return cat


#: The colour map of :func:`map_categories`.
MAP_CMAP = ListedColormap([DEFECT_COLOR, FREE_COLOR, ACCEPT_COLOR])


# ---------------------------------------------------------------------------
# The center-point plane


def center_plane(
    filemon: Filemon,
    view: Optional[ViewLike] = None,
    grid: Optional[Tuple[int, int]] = None,
    *,
    method: Method = "conic",
    free: Optional[npt.ArrayLike] = None,
    acceptable: Optional[npt.ArrayLike] = None,
    transmission: Optional[npt.ArrayLike] = None,
    transmission_levels: Sequence[float] = (30.0, 45.0, 60.0, 75.0),
    pivots: Optional[Sequence[Point]] = None,
    labels: bool = True, legend: bool = True, units: Optional[str] = None, ax: Optional[Axes] = None,
) -> Axes:
    """Draw the driving crank's center-point plane, as in Borm & Kim's Fig. 10 and 12.

    Draws, bottom to top: the branch-free driving pivots shaded (gid
    ``"branch-map"``, an image of the grid: 0 defective, 1 branch-free,
    2 branch-free and acceptable); the transformed Filemon curves, exact and
    every branch, clipped to the view (gid ``"conic-k"`` for the line of pose
    k, one Line2D per branch); the pole triangle (``"pole-triangle"``) and its
    side lines extended (``"pole-triangle-sides"``, always defective: the
    paper's property 5); the pole circle (``"pole-circle"``); the poles
    (``"poles"``); the driven crank's fixed pivot ``C0`` (``"driven-pivot"``);
    and the overlays given. When two poses differ by a pure translation (a
    pole at infinity) there is no pole triangle or circle: the finite poles
    are drawn alone.

    Parameters:
        filemon: Filemon's construction for the driven dyad
            (``task.filemon(C0)``).
        view: a :class:`burmester.Grid` or ``(xmin, xmax, ymin, ymax)``;
            default: a square around the poles and the pivots.
        grid: ``(nx, ny)`` samples of the branch map; default: the Grid's, or
            400 along the longer side.
        method: how :meth:`Filemon.branch_map` classifies (``"conic"``,
            ``"direct"``, ``"simulate"``).
        free: a branch map already computed on this view, shape ``(ny, nx)``
            (for example a solution map's ``branch_free``; then ``method`` is
            not used, and when neither a Grid nor ``grid`` is given, the
            samples are taken from its shape).
        acceptable: optional bool array ``(ny, nx)``: pivots that meet the
            limits (from the solution-space map); shaded darker where also
            branch-free.
        transmission: optional float array ``(ny, nx)``: a transmission angle
            in degrees per grid point (NaN where undefined), drawn as
            labelled contours at ``transmission_levels`` (gid ``"transmission"``).
        pivots: optional ``(x, y)`` points, best first: drawn as numbered stars
            (gid ``"pivots"``).
        labels, legend, units, ax: as every drawing (the module's *Common parameters*; the
            labels name the points).

    Returns:
        The Axes.
    """
    sc = _scene.center_scene(filemon, view, grid, method, free, acceptable, transmission)
    v = sc.grid
    extent = v.extent
    free_b, acc, trans = sc.free, sc.acceptable, sc.transmission

    ax = _new_axes(ax)
    img = ax.imshow(
        map_categories(free_b, acc),
        origin="lower",
        extent=extent,
        cmap=MAP_CMAP,
        vmin=0,
        vmax=2,
        interpolation="nearest",
        zorder=0,
    )
    img.set_gid("branch-map")
    handles: List[Artist] = [Patch(facecolor=FREE_COLOR, edgecolor="0.5", label="branch-free driving pivot")]
    if acc is not None:
        handles.append(Patch(facecolor=ACCEPT_COLOR, edgecolor="0.5", label="branch-free and acceptable"))

    # The transformed Filemon curves.
    handles.extend(
        a for a in draw_conics(ax, filemon, extent)
        if isinstance(a, Line2D) and not str(a.get_label()).startswith("_")
    )

    # The poles, the pole triangle, its extended sides and the pole circle;
    # with a pure translation between two poses (a pole at infinity) there
    # is no triangle or circle: only the finite poles are drawn.
    task = filemon.task
    named = sc.poles
    poles = [pt for _, pt in named if pt is not None]
    if sc.pole_triangle:
        for a, b in ((0, 1), (1, 2), (2, 0)):
            seg = clip_line(poles[a], (poles[b][0] - poles[a][0], poles[b][1] - poles[a][1]), extent)
            if seg:
                (side,) = ax.plot(
                    [seg[0][0], seg[1][0]], [seg[0][1], seg[1][1]],
                    color="0.55", linestyle=":", linewidth=0.8, zorder=2,
                )
                side.set_gid("pole-triangle-sides")
                if not any(h.get_gid() == "pole-triangle-sides" for h in handles):
                    side.set_label("pole triangle's sides, extended (always defective)")
                    handles.append(side)
        tri_x = [p[0] for p in poles] + [poles[0][0]]
        tri_y = [p[1] for p in poles] + [poles[0][1]]
        (tri,) = ax.plot(tri_x, tri_y, color=POLE_COLOR, linewidth=1.0, zorder=4, label="pole triangle")
        tri.set_gid("pole-triangle")
        handles.append(tri)
        handles.append(_draw_circle(ax, task.pole_circle(), extent, "pole-circle", "pole circle"))
    handles.append(_markers(ax, poles, "poles", "poles", marker="o", markersize=5, color=POLE_COLOR, zorder=5))
    c0 = sc.c0
    handles.append(_markers(
        ax, [c0], "driven-pivot", "driven crank's fixed pivot C0",
        marker="^", markersize=9, color="#ff7f0e", markeredgecolor="black", zorder=5,
    ))
    if labels:
        for name, p in named:
            if p is not None:
                _label(ax, p, name)
        _label(ax, c0, "C0")

    # Overlays from the solution-space map.
    if trans is not None:
        xs, ys = v.cell_centers()
        cs = ax.contour(
            xs, ys, trans, levels=sorted(transmission_levels),
            colors="#636363", linewidths=0.8, zorder=3,
        )
        cs.set_gid("transmission")
        ax.clabel(cs, fmt="%g°", fontsize=7)
        handles.append(Line2D([], [], color="#636363", linewidth=0.8, label="transmission angle, deg"))
    if pivots is not None and len(pivots) > 0:
        pts = np.asarray(pivots, dtype=float).reshape(-1, 2)
        handles.append(_markers(
            ax, pts, "pivots", "best driving pivots",
            marker="*", markersize=13, color="#ffd700", markeredgecolor="black", zorder=6,
        ))
        for k, (px, py) in enumerate(pts.tolist(), start=1):
            _label(ax, (px, py), str(k))

    if labels:
        ax.set_title("Driving crank center-point plane")
    if labels or units:
        label_axes(ax, units)
    note_outside(ax, extent, [*named, ("C0", c0)]
                 + [(str(k), p) for k, p in enumerate(np.asarray(pivots if pivots is not None else [],
                                                                    dtype=float).reshape(-1, 2).tolist(), start=1)],
                 units)
    _finish(ax, extent, legend, handles)
    return ax


# ---------------------------------------------------------------------------
# Four and five poses: the Burmester curves and points

#: Colours of the center-point curve's pieces by crank order: the crank meets
#: the poses in their order counter-clockwise, clockwise, or not at all (an
#: order defect).
ORDER_COLORS: Dict[Optional[str], str] = {
    "counterclockwise": "#1a9850",
    "clockwise": "#2166ac",
    None: "#bdbdbd",
}
ORDER_LABELS: Dict[Optional[str], str] = {
    "counterclockwise": "center points, crank meets the poses in order (ccw)",
    "clockwise": "center points, crank meets the poses in order (cw)",
    None: "center points with an order defect",
}
BURMESTER_COLOR = "#ffd700"


def _draw_poses(ax: Axes, task: Task, labels: bool) -> Artist:
    """The poses as black dots with a flag along the coupler angle (gid ``"poses"``)."""
    art = _draw_flags(ax, task.poses, 0.12 * task.scale, labels, 6, "poses", 4)
    assert art is not None
    art.set_label("poses (coupler point and angle)")
    return art


def _draw_free_arcs(ax: Axes, sc: _scene.CurveScene, handles: List[Any]) -> None:
    """Four poses: the branch-free arcs of the driving dyads for the driven
    dyad as a wide band under the curve of the scene's plane (gid
    ``"branch-free-arcs"``)."""
    what = "pivots" if sc.plane == "center" else "circle points"
    for k, pts in enumerate(sc.free_arcs):
        (band,) = ax.plot(pts[:, 0], pts[:, 1], color=FREE_COLOR, linewidth=9.0,
                          solid_capstyle="butt", zorder=2)
        band.set_gid("branch-free-arcs")
        if k == 0:
            band.set_label(f"branch-free driving {what} for C0")
            handles.append(band)


def _draw_order_arcs(ax: Axes, sc: _scene.CurveScene, labels: bool, handles: List[Any]) -> None:
    """Four poses: the curve of the scene's plane cut by crank order and
    coloured by it (gid ``"center-point-curve"`` or ``"circle-point-curve"``),
    and the points ``Q_jk`` (their circle points ``Q'jk`` in the
    circle-point plane; gid ``"coincidence-points"``)."""
    circle = sc.plane == "circle"
    labelled: Dict[Optional[str], bool] = {}
    for _, direction, pts in sc.order_arcs:
        (line,) = ax.plot(pts[:, 0], pts[:, 1], color=ORDER_COLORS[direction], linewidth=2.0, zorder=3)
        line.set_gid(f"{sc.plane}-point-curve")
        if direction not in labelled:
            labelled[direction] = True
            label = ORDER_LABELS[direction]
            line.set_label(label.replace("center points", "circle points") if circle else label)
            handles.append(line)
    if sc.coincidence:
        legend = ("Q'jk: moving pivot on P_jk at poses j, k" if circle
                  else "Q_jk: crank positions j, k coincide")
        handles.append(_markers(
            ax, [p for _, p in sc.coincidence], "coincidence-points", legend,
            marker="D", markersize=6, color="white", markeredgecolor="black", zorder=5,
        ))
        if labels:
            for (j, k), p in sc.coincidence:
                _label(ax, p, f"Q{sc.prime}{j}{k}", "0.3")


def _note_curve_points(ax: Axes, task: Task, extent: Extent, driven: Optional[Point],
                       plane: Literal["center", "circle"], units: Optional[str]) -> None:
    """Four or five poses: :func:`note_outside` for the points the plane
    marks (:func:`burmester.taskfile.curve_plane_points`)."""
    note_outside(ax, extent, curve_plane_points(task, driven, plane), units)


def _curve_plane(task: Task, view: Optional[Sequence[float]], driven: Optional[Point], plane: _scene.Plane,
                 labels: bool, legend: bool, units: Optional[str], ax: Optional[Axes]) -> Axes:
    """:func:`burmester_plane` (``plane="center"``) or :func:`circle_curve_plane`
    (``"circle"``): the scene (:func:`burmester._scene.curve_scene`) drawn, bottom first."""
    sc = _scene.curve_scene(task, view, driven, plane)
    extent = sc.extent
    ax = _new_axes(ax)
    handles: List[Any] = []
    _draw_free_arcs(ax, sc, handles)
    made = sc.construction
    if made is not None:
        for k, seg in enumerate(made.lines, start=1):
            if seg is None:
                continue
            (line,) = ax.plot([seg[0][0], seg[1][0]], [seg[0][1], seg[1][1]], color=POSE_COLORS[k],
                              linewidth=0.9, zorder=2, label=f"line C1 C'{k} (pose {k})")
            line.set_gid(f"filemon-line-{k}")
            handles.append(line)
        handles.append(_markers(ax, made.images, "fixed-pivot-images", "C'k = D_k1(C0)", marker="^",
                                markersize=6, color="white", markeredgecolor="#ff7f0e", zorder=5))
        handles.append(_markers(ax, [made.c1], "driven-circle-point", "driven crank's circle point C1", marker="o",
                                markersize=8, color="#ff7f0e", markeredgecolor="black", zorder=6))
        if labels:
            _label(ax, made.c1, "C1")
            for k, image in enumerate(made.images, start=1):
                _label(ax, image, f"C'{k}", "0.3")
    if sc.driven is not None:
        handles.append(_markers(
            ax, [sc.driven], "driven-pivot", "driven crank's fixed pivot C0",
            marker="^", markersize=9, color="#ff7f0e", markeredgecolor="black", zorder=6,
        ))
        if labels:
            _label(ax, sc.driven, "C0")
    _draw_order_arcs(ax, sc, labels, handles)
    for which, polylines in sc.curves:
        first = True
        for pl in polylines:
            (line,) = ax.plot(pl[:, 0], pl[:, 1], color="#2166ac" if which == "1234" else "#b2182b",
                              linestyle="-" if which == "1234" else "--", linewidth=1.4, zorder=3)
            line.set_gid(f"curve-{which}")
            if first:
                line.set_label(f"center-point curve of poses {', '.join(which)}")
                handles.append(line)
                first = False
    if sc.burmester_points:
        handles.append(_markers(
            ax, sc.burmester_points, "burmester-points", "Burmester points (center points)",
            marker="*", markersize=15, color=BURMESTER_COLOR, markeredgecolor="black", zorder=7,
        ))
        if labels:
            for k, c in enumerate(sc.burmester_points, start=1):
                _label(ax, c, f"B{k}")
    if sc.poles:
        handles.append(_markers(
            ax, [p for _, p in sc.poles], "poles", "poles", marker="o", markersize=5, color=POLE_COLOR, zorder=5,
        ))
        if labels:
            for (i, j), p in sc.poles:
                _label(ax, p, f"P{i}{j}")
    handles.append(_draw_poses(ax, task, labels))
    if labels:
        ax.set_title(f"{sc.n_poses} poses: {sc.title}")
    if labels or units:
        label_axes(ax, units)
    _note_curve_points(ax, task, extent, driven, plane, units)
    _finish(ax, extent, legend, handles)
    return ax


def burmester_plane(
    task: Task,
    view: Optional[Sequence[float]] = None,
    *,
    driven: Optional[Point] = None,
    labels: bool = True, legend: bool = True, units: Optional[str] = None, ax: Optional[Axes] = None,
) -> Axes:
    """Draw the center-point plane of four or five poses.

    **Four poses**: the center-point curve, every component in view, cut
    into pieces at the points ``Q_jk`` where two crank positions coincide
    and coloured by the crank's order class (:meth:`burmester.Task.order_arcs`:
    green where the crank meets the poses in order counter-clockwise, blue
    clockwise, grey with an order defect; gid ``"center-point-curve"``, one
    Line2D per piece); the poles (gid ``"poles"``, labelled ``Pjk``); the
    points ``Q_jk`` (gid ``"coincidence-points"``); the poses (gid ``"poses"``).
    With ``driven`` (the center point of a driven dyad, on the curve), the
    driving center points that pass the poses in one assembly mode with it
    are drawn under the curve as a wide band (:meth:`burmester.Task.branch_free_arcs`,
    gid ``"branch-free-arcs"``) and the driven pivot as a triangle (gid
    ``"driven-pivot"``).

    **Five poses**: the center-point curves of poses 1-4 and 1-2-3-5 (gids
    ``"curve-1234"``, ``"curve-1235"``), whose common points other than
    ``P12, P13, P23`` are the Burmester points (gid ``"burmester-points"``,
    stars labelled ``B1`` ...); the poles; the poses.

    Parameters:
        task: a :class:`burmester.Task` of four or five poses.
        view: ``(xmin, xmax, ymin, ymax)``; default:
            :func:`burmester.taskfile.default_curve_view`.
        driven: four poses: the driven dyad's center point ``C0``, to show
            the branch-free driving pivots.
        labels, legend, units, ax: as every drawing (the module's *Common parameters*; the
            labels name the points).

    Returns:
        The Axes.

    Raises:
        burmester.InvalidInputError: a task of three poses (``cause ==
            "needs_poses"``; draw it with :func:`center_plane`), or an empty
            view.
    """
    return _curve_plane(task, view, driven, "center", labels, legend, units, ax)


# ---------------------------------------------------------------------------
# The circle-point plane


def circle_curve_plane(task: Task, view: Optional[Sequence[float]] = None, *, driven: Optional[Point] = None,
                       labels: bool = True, legend: bool = True, units: Optional[str] = None,
                       ax: Optional[Axes] = None) -> Axes:
    """Draw the circle-point plane of four poses (the coupler frame at pose 1).

    The circle-point curve, every component in view, cut into pieces of
    constant crank order and coloured as :func:`burmester_plane` colours the
    center-point curve (:meth:`burmester.Task.order_arcs` with
    ``plane="circle"``; gid ``"circle-point-curve"``); the circle points of
    the points ``Q_jk`` (gid ``"coincidence-points"``, labelled ``Q'jk``:
    the moving pivot on the pole ``P_jk`` at poses j and k, so ``Q'1k`` is
    the pole ``P1k``); the poses. With ``driven``
    (the driven dyad's center point ``C0``, on the center-point curve):
    Filemon's construction with four lines, the lines through its circle
    point ``C1`` and the fixed pivot's images ``C'k = D_k1(C0)`` (gids
    ``"filemon-line-k"``, ``"fixed-pivot-images"``, ``"driven-circle-point"``),
    and under the curve, as a wide band, the circle points of the driving
    dyads that pass the poses in one assembly mode with it
    (:meth:`burmester.Task.branch_free_arcs` with ``plane="circle"``, gid
    ``"branch-free-arcs"``; their ends are exact).

    Parameters:
        task: a :class:`burmester.Task` of four poses.
        view: ``(xmin, xmax, ymin, ymax)``; default:
            :func:`burmester.taskfile.default_curve_view`.
        driven: the driven dyad's center point ``C0``.
        labels, legend, units, ax: as every drawing (the module's *Common parameters*; the
            labels name the points).

    Returns:
        The Axes.

    Raises:
        burmester.InvalidInputError: a task of three or five poses
            (``cause == "needs_poses"``), or an empty view.
    """
    return _curve_plane(task, view, driven, "circle", labels, legend, units, ax)


# ---------------------------------------------------------------------------
# The pair map of four poses


#: Shading of the pair map's categories: no linkage, a branch defect,
#: branch-free, branch-free and acceptable.
PAIR_COLORS = ("#d9d9d9", DEFECT_COLOR, FREE_COLOR, ACCEPT_COLOR)
PAIR_LABELS = ("no linkage", "branch defect", "branch-free", "branch-free and acceptable")


def pair_map(
    pmap: PairMap,
    *,
    pairs: Optional[int] = 5,
    rank_by: RankBy = "balanced",
    transmission_levels: Sequence[float] = (30.0, 45.0, 60.0, 75.0),
    labels: bool = True, legend: bool = True, ax: Optional[Axes] = None,
) -> Axes:
    """Draw a four-pose pair map (:meth:`burmester.Task.pair_map`): every
    linkage of the task on one picture.

    Across, the driving dyad's curve parameter; up, the driven dyad's; both
    in degrees of crank rotation (the ``beta2`` arcs laid end to end, the
    ``"open"`` solution branch then the ``"crossed"`` one, split by a dotted
    line, gid ``"branches"``). Draws, bottom to top: the pairs by category
    (gid ``"pair-map"``, an image: 0 no linkage, 1 a branch defect,
    2 branch-free, 3 branch-free and acceptable); contours of the minimum
    transmission angle over the travel where the motion is feasible, at
    ``transmission_levels`` degrees (gid ``"transmission"``); and the
    ``pairs`` best pairs by ``rank_by`` (:meth:`PairMap.best_pairs`) as
    numbered stars (gid ``"pairs"``; ``None`` or 0: none).

    Parameters:
        pmap: the pair map.
        pairs: how many of the best pairs to mark.
        rank_by: their ranking (as :meth:`SolutionMap.best_pivots`).
        transmission_levels: contour levels, degrees.
        labels: a title and axis labels.
        legend: draw a legend to the right of the axes.
        ax: the Axes to draw into; default: a new figure.

    Returns:
        The Axes.
    """
    cat = np.zeros(pmap.shape, dtype=np.int8)
    cat[pmap.valid] = 1
    cat[pmap.branch_free] = 2
    cat[pmap.acceptable] = 3
    x0, x1, y0, y1 = (math.degrees(v) for v in pmap.extent)
    extent = (x0, x1, y0, y1)
    ax = _new_axes(ax, figsize=(8.0, 6.4))
    img = ax.imshow(
        cat, origin="lower", extent=extent, cmap=ListedColormap(list(PAIR_COLORS)), vmin=0, vmax=3,
        interpolation="nearest", zorder=0,
    )
    img.set_gid("pair-map")
    handles: List[Any] = [
        Patch(facecolor=c, edgecolor="0.5", label=lab) for c, lab in zip(PAIR_COLORS, PAIR_LABELS)
    ]
    # The two solution branches meet at half the parameter's length.
    half_x, half_y = (x0 + x1) / 2, (y0 + y1) / 2
    (split,) = ax.plot([half_x, half_x, math.nan, x0, x1], [y0, y1, math.nan, half_y, half_y],
                       color="0.35", linestyle=":", linewidth=0.9, zorder=2)
    split.set_gid("branches")
    feasible = pmap.branch_free & pmap.one_circuit & (pmap.direction != 0)
    mu = np.where(feasible, np.degrees(pmap.min_transmission_rad.astype(float)), np.nan)
    if np.isfinite(mu).any():
        g = pmap.grid
        xs, ys = g.cell_centers()
        cs = ax.contour(
            np.degrees(xs), np.degrees(ys), mu, levels=sorted(transmission_levels),
            colors="#636363", linewidths=0.8, zorder=3,
        )
        cs.set_gid("transmission")
        ax.clabel(cs, fmt="%g°", fontsize=7)
        handles.append(Line2D([], [], color="#636363", linewidth=0.8, label="transmission angle, deg"))
    best = pmap.best_pairs(pairs, rank_by=rank_by) if pairs else []
    if best:
        g = pmap.grid
        pts: List[Point] = []
        for pair in best:
            x, y = g.point(*pair.index)
            pts.append((math.degrees(x), math.degrees(y)))
        handles.append(_markers(
            ax, pts, "pairs", f"best pairs ({rank_by})",
            marker="*", markersize=13, color="#ffd700", markeredgecolor="black", zorder=6,
        ))
        for k, pt in enumerate(pts, start=1):
            _label(ax, pt, str(k))
    if labels:
        ax.set_title("Pair map: every four-bar of the four poses")
        ax.set_xlabel("driving dyad: crank-rotation parameter, deg (open branch | crossed branch)")
        ax.set_ylabel("driven dyad: parameter, deg")
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("auto")
    if legend:
        _legend(ax, handles)
    return ax


def _sector_polygon(center: Point, a0: float, a1: float, radius: float) -> npt.NDArray[np.float64]:
    """A pie slice from angle a0 to a1 (counter-clockwise) as a polygon."""
    ts = np.linspace(a0, a1, max(3, int(64 * (a1 - a0) / math.pi) + 2))
    pts = np.column_stack([center[0] + radius * np.cos(ts), center[1] + radius * np.sin(ts)])
    return np.vstack([[center], pts, [center]])


def filemon_wedges(filemon: Filemon, radius: float) -> Tuple[List[npt.NDArray[np.float64]], List[npt.NDArray[np.float64]]]:
    """Filemon's sectors around ``C1`` (:attr:`burmester.Filemon.sectors`) as
    polygons of the given radius: ``(free, defective)``. The free ones are
    the two opposite sectors where all three lines see the driving circle
    point on one side."""
    c1 = filemon.driven_circle
    free: List[npt.NDArray[np.float64]] = []
    defective: List[npt.NDArray[np.float64]] = []
    for a0, a1, is_free in filemon.sectors:
        (free if is_free else defective).append(_sector_polygon(c1, a0, a1, radius))
    return free, defective


def circle_plane(
    filemon: Filemon,
    view: Optional[ViewLike] = None,
    *,
    labels: bool = True, legend: bool = True, units: Optional[str] = None, ax: Optional[Axes] = None,
) -> Axes:
    """Draw the driving crank's circle-point plane, as in Borm & Kim's Fig. 3 and 11.

    Draws Filemon's construction for the driven dyad ``(C0, C1)``: the three
    lines through ``C1`` and ``C'k`` (gid ``"line-k"``; the two Filemon lines
    solid, the middle one dashed), the branch-free double wedge between the
    Filemon lines shaded (gid ``"free-wedge"``) and the defective one hatched
    (``"defect-wedge"``), ``C1`` and the fixed pivot's images ``C'1 = C0,
    C'2, C'3`` (``"fixed-pivot-images"``), the image poles ``P12, P13, P'23``
    (``"image-poles"``) and the image-pole circle (``"image-pole-circle"``),
    on which circle points have their center point at infinity (neither when
    two poses differ by a pure translation: a pole is at infinity).

    Parameters:
        filemon: Filemon's construction for the driven dyad.
        view: ``(xmin, xmax, ymin, ymax)`` or a :class:`burmester.Grid`;
            default: a square around ``C1``, the ``C'k`` and the image poles.
        labels, legend, units, ax: as every drawing (the module's *Common parameters*; the
            labels name the points).

    Returns:
        The Axes.
    """
    sc = _scene.circle_scene(filemon, view)
    extent, c1 = sc.extent, sc.construction.c1
    ax = _new_axes(ax)
    free, defective = filemon_wedges(filemon, sc.radius)
    handles: List[Artist] = []
    if free:
        patch = PathPatch(
            MplPath.make_compound_path(*(MplPath(p, closed=True) for p in free)),
            facecolor=FREE_COLOR, edgecolor="none", zorder=0, label="branch-free driving circle points",
        )
        patch.set_gid("free-wedge")
        ax.add_patch(patch)
        handles.append(patch)
    if defective:
        hatch = PathPatch(
            MplPath.make_compound_path(*(MplPath(p, closed=True) for p in defective)),
            facecolor="none", edgecolor="0.75", hatch="////", linewidth=0.0, zorder=0,
            label="branch defect (Filemon)",
        )
        hatch.set_gid("defect-wedge")
        ax.add_patch(hatch)
        handles.append(hatch)

    middle = sc.middle
    for k, seg in enumerate(sc.construction.lines, start=1):
        if seg is None:
            continue
        (line,) = ax.plot(
            [seg[0][0], seg[1][0]], [seg[0][1], seg[1][1]], color=POSE_COLORS[k],
            linestyle="--" if k == middle else "-", linewidth=1.4, zorder=3,
            label=f"line C1 C'{k} (pose {k})" + (", middle" if k == middle else ""),
        )
        line.set_gid(f"line-{k}")
        handles.append(line)

    ip = sc.image_poles
    if ip:
        handles.append(_draw_circle(
            ax, filemon.task.image_pole_circle(), extent, "image-pole-circle", "image-pole circle",
        ))
        handles.append(_markers(
            ax, ip, "image-poles", "image poles", marker="s", markersize=5, color=POLE_COLOR, zorder=5,
        ))
    images = sc.construction.images
    handles.append(_markers(
        ax, images, "fixed-pivot-images", "fixed pivot seen from the coupler, C'k",
        marker="^", markersize=8, color="#ff7f0e", markeredgecolor="black", zorder=5,
    ))
    handles.append(_markers(
        ax, [c1], "circle-point", "driven crank's moving pivot C1",
        marker="o", markersize=7, color="white", markeredgecolor="black", zorder=5,
    ))
    if labels:
        for name, p in zip(("P12", "P13", "P'23"), ip):
            _label(ax, p, name)
        for k, p in enumerate(images, start=1):
            _label(ax, p, f"C'{k}" + (" = C0" if k == 1 else ""), POSE_COLORS[k])
        _label(ax, c1, "C1")
        ax.set_title("Driving crank circle-point plane (pose 1)")
    if labels or units:
        label_axes(ax, units)
    note_outside(ax, extent, list(zip(("P12", "P13", "P'23"), ip))
                 + [(f"C'{k}", p) for k, p in enumerate(images, start=1)] + [("C1", c1)], units)
    _finish(ax, extent, legend, handles)
    return ax


# ---------------------------------------------------------------------------
# The linkage


def _flag(pose: Tuple[float, float, float], length: float) -> Tuple[List[float], List[float]]:
    x, y, a = pose
    return [x, x + length * math.cos(a)], [y, y + length * math.sin(a)]


def _animation_target(path: Union[str, Path], frames: int, fps: int, dpi: int) -> Tuple[Path, int, int, int]:
    """The animation's path (``.gif`` or ``.mp4``, in a folder that exists)
    and its counts, checked; InvalidInputError otherwise."""
    path = Path(path)
    if path.suffix.lower() not in (".gif", ".mp4"):
        raise burmester.InvalidInputError(f"animation file must end in .gif or .mp4, got {path.name!r}")
    frames = _count_in("frames", frames, 2, MAX_FRAMES)
    fps = _count_in("fps", fps, 1, MAX_FPS)
    dpi = _count_in("dpi", dpi, 1, MAX_DPI)
    if not path.parent.is_dir():
        raise burmester.InvalidInputError(
            f"cannot write {path}: the folder {str(path.parent)!r} does not exist; create it first"
        )
    return path, frames, fps, dpi


def _check_ffmpeg(path: Path) -> None:
    """RuntimeError for an ``.mp4`` without ffmpeg on the PATH."""
    if path.suffix.lower() == ".mp4" and not matplotlib.animation.writers.is_available("ffmpeg"):
        raise RuntimeError("writing .mp4 needs ffmpeg on the PATH; install it, or write a .gif")


def _around_data(ax: Axes, labels: bool, units: Optional[str]) -> None:
    """Axis names (with ``labels`` or ``units``), equal aspect, limits
    around the data with a margin of 8 %."""
    if labels or units:
        label_axes(ax, units)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.margins(0.08)


def _fit_frames(ax: Axes, polys: Sequence[Sequence[npt.NDArray[np.float64]]]) -> None:
    """Limits around every frame's polylines, 8 % of the larger side
    beyond, equal aspect: the moving linkage stays in view."""
    allpts = np.vstack([np.vstack(p) for p in polys])
    lo, hi = allpts.min(axis=0), allpts.max(axis=0)
    pad = 0.08 * float(max(hi - lo))
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal")


def _save_animation(anim: FuncAnimation, path: Path, fps: int, dpi: int) -> None:
    """Write ``anim`` (GIF by Pillow, MP4 by ffmpeg) whole to a temporary
    file beside ``path``, moved into place when complete (burmester._io):
    Ctrl-C or a write error leaves no partial file."""
    writer = PillowWriter(fps=fps) if path.suffix.lower() == ".gif" else FFMpegWriter(fps=fps)
    with _io.atomic_path(path) as tmp:
        try:
            anim.save(str(tmp), writer=writer, dpi=dpi)
        except Exception as e:
            # The writer finishes its file in a `finally`; after Ctrl-C that
            # can fail too (no frames yet) and hide the interrupt.
            cause: Optional[BaseException] = e
            while cause is not None:
                if isinstance(cause, KeyboardInterrupt):
                    raise cause from None
                cause = cause.__context__
            raise


def _draw_flags(ax: Axes, poses: Sequence[Sequence[float]], flag: float, labels: bool, zorder: int,
                gid: Optional[str] = None, markersize: float = 5) -> Optional[Artist]:
    """Each pose as a dot with a flag along its angle (gid ``gid``, or
    ``"pose-k"``), numbered with ``labels``; returns the last dot."""
    dot: Optional[Artist] = None
    for k, pose in enumerate(poses, start=1):
        fx, fy = _flag((pose[0], pose[1], pose[2]), flag)
        (mk,) = ax.plot(fx, fy, color="black", linewidth=2.0, zorder=zorder)
        mk.set_gid(gid or f"pose-{k}")
        (dot,) = ax.plot([pose[0]], [pose[1]], marker="o", markersize=markersize, color="black", zorder=zorder)
        dot.set_gid(gid or f"pose-{k}")
        if labels:
            _label(ax, (pose[0], pose[1]), str(k))
    return dot


def _draw_static(ax: Axes, sfb: SynthesizedFourBar, sc: _scene.LinkageScene, curve: bool, labels: bool) -> None:
    """Ground pivots, coupler curve and the pose markers of the scene."""
    fb = sfb.fourbar
    a0, c0 = sc.a0, sc.c0
    if curve:
        mode = sfb.modes[0] or "open"
        ts = np.linspace(0.0, 2 * math.pi, 1441)
        x, y, _ = fb.coupler_path(sfb.coupler_point, ts, mode)
        (cc,) = ax.plot(x, y, color="0.6", linewidth=0.8, zorder=1, label=f"coupler curve ({mode})")
        cc.set_gid("coupler-curve")
    (g,) = ax.plot([a0[0], c0[0]], [a0[1], c0[1]], color="0.3", linestyle="--", linewidth=1.0, zorder=2)
    g.set_gid("ground")
    _markers(
        ax, [a0, c0], "fixed-pivots", "fixed pivots A0, C0",
        marker="^", markersize=10, color="0.2", zorder=6,
    )
    _draw_flags(ax, sc.poses, sc.flag, labels, 7)
    if labels:
        _label(ax, a0, "A0")
        _label(ax, c0, "C0")


def _linkage_polys(sfb: SynthesizedFourBar, theta2: float, mode: Mode) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """``(chain, coupler)``: the polyline O2-A-B-O4 and the coupler triangle A-B-P."""
    return _chain_and_coupler(_scene.position(sfb, theta2, mode))


def _chain_and_coupler(at: _scene.Position) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """``(chain, coupler)`` of a position: the polyline O2-A-B-O4 and the coupler triangle A-B-P."""
    return np.array(at[:4], dtype=float), np.array([at.a, at.b, at.p], dtype=float)


def linkage(
    sfb: SynthesizedFourBar,
    *,
    task: Optional[Task] = None,
    coupler_curve: bool = True,
    labels: bool = True, legend: bool = True, units: Optional[str] = None, ax: Optional[Axes] = None,
) -> Axes:
    """Draw a synthesized four-bar at the task's poses.

    Draws the fixed pivots ``A0`` and ``C0`` with the ground line, the path of
    the coupler point over a full turn of the input in the mode of pose 1
    (gid ``"coupler-curve"``), and at each pose k, in its colour and assembly
    mode: the crank, the coupler (a triangle through both moving pivots and
    the coupler point) and the rocker (gids ``"linkage-k"`` and
    ``"coupler-k"``). The poses themselves are black markers, a dot and a flag
    along the coupler angle (gid ``"pose-k"``), so you can see the coupler
    reach each one. With ``labels``, the links at pose 1 are labelled with
    their names and lengths (``"crank 40 mm"``, gid ``"link-length"``,
    placed by :func:`label_lengths` so that no two labels overlap).

    Parameters:
        sfb: the four-bar, from :meth:`burmester.Filemon.four_bar` or
            :meth:`burmester.Task.four_bar`.
        task: the task, to mark the poses it asks for; default: the poses the
            linkage reaches at its input angles.
        coupler_curve: draw the coupler curve.
        labels, legend, units, ax: as every drawing (the module's *Common parameters*; the
            labels name the points).

    Returns:
        The Axes.
    """
    ax = _new_axes(ax, (7.5, 6.0))
    sc = _scene.linkage_scene(sfb, task)
    _draw_static(ax, sfb, sc, coupler_curve, labels)
    for k, (theta2, mode, at) in enumerate(sc.at_poses, start=1):
        chain, coupler = _chain_and_coupler(at)
        color = POSE_COLORS[k]
        (ln,) = ax.plot(
            chain[:, 0], chain[:, 1], color=color, linewidth=2.0, marker="o", markersize=4,
            zorder=4, label=f"pose {k}: theta2 = {math.degrees(theta2):.1f} deg, {mode or 'toggle'}",
        )
        ln.set_gid(f"linkage-{k}")
        tri = Polygon(coupler, closed=True, facecolor=color, edgecolor=color, alpha=0.25, zorder=3)
        tri.set_gid(f"coupler-{k}")
        ax.add_patch(tri)
    if labels:
        state = "branch-free" if sfb.branch_free else "branch defect (modes differ)"
        count = _scene.count_word(len(sfb.input_angles)).lower()
        ax.set_title(f"Four-bar at the {count} poses: {sfb.fourbar.grashof}, {state}")
    _around_data(ax, labels, units)
    if labels:
        # The link lengths, on the links at pose 1 (the axes' limits and
        # aspect first: the labels are placed on the screen).
        ax.apply_aspect()
        joints = sc.at_poses[0].position[:4]
        label_lengths(ax, link_segments(sfb.fourbar, joints), units, color=POSE_COLORS[1],
                      avoid=[*joints, *((q[0], q[1]) for q in sc.poses)])
    if legend:
        _legend(ax)
    return ax


def drive_angles(sfb: SynthesizedFourBar, frames: int = 60) -> Tuple[npt.NDArray[np.float64], Tuple[int, ...]]:
    """Input angles that drive the linkage from pose 1 through the poses in
    order to the last, along its travel (:attr:`burmester.SynthesizedFourBar.travel_stops`).

    The input turns one way (the travel's direction) in about ``frames``
    equal steps; the input angles of the poses are among the samples,
    exactly. Returns the angles and the index of each pose in them.

    Raises:
        burmester.AssemblyError: no input direction carries the coupler
            through the poses in order (the linkage has no travel).
        burmester.InvalidInputError: ``frames`` is not from 2 to :data:`MAX_FRAMES`.
    """
    frames = _count_in("frames", frames, 2, MAX_FRAMES)
    stops = sfb.travel_stops
    if stops is None:
        raise burmester.AssemblyError(
            "no input direction carries the coupler through the poses in order (an order or "
            "circuit defect); choose another driving pivot"
        )
    total = abs(stops[-1] - stops[0])
    n = frames
    parts: List[npt.NDArray[np.float64]] = []
    idx = [0]
    for a, b in zip(stops[:-1], stops[1:]):
        steps = max(1, round(n * abs(b - a) / total)) if total > 0 else 1
        seg = np.linspace(a, b, steps + 1)
        parts.append(seg if not parts else seg[1:])
        idx.append(idx[-1] + steps)
    return np.concatenate(parts), tuple(idx)


def animate(
    sfb: SynthesizedFourBar,
    path: Union[str, Path],
    *,
    task: Optional[Task] = None,
    frames: int = 60, fps: int = 20, dpi: int = 80,
    units: Optional[str] = None,
) -> FuncAnimation:
    """Write an animation of the four-bar driven through the poses.

    The input turns from pose 1 through the poses in order to the last
    (see :func:`drive_angles`) and back, so the animation loops smoothly; the
    moving linkage (gid ``"moving-linkage"``, ``"moving-coupler"``) is drawn
    over the coupler curve and the pose markers (as in :func:`linkage`).

    Parameters:
        sfb: a branch-free four-bar.
        path: where to write: ``.gif`` (Pillow) or ``.mp4`` (needs ffmpeg).
        task: the task, to mark its poses; default: the poses the linkage reaches.
        frames: about how many frames from the first pose to the last.
        fps: frames per second.
        dpi: resolution of the frames.
        units: the unit of the lengths (``"mm"``): on the axes (``x [mm]``)
            and after the link lengths, which the title lists (``ground
            100 mm, crank 40 mm, ...``; the links move, so their labels are
            there rather than on them).

    Returns:
        The matplotlib animation (already saved).

    Raises:
        burmester.AssemblyError: the linkage has a branch defect, or its input
            cannot turn from pose 1 through the poses in order without passing
            a dead position (:attr:`burmester.LinkageFigures.feasible`).
        burmester.InvalidInputError: the file type is neither ``.gif`` nor
            ``.mp4``, its folder does not exist, or ``frames`` (2 to
            :data:`MAX_FRAMES`), ``fps`` (1 to :data:`MAX_FPS`) or ``dpi``
            (1 to :data:`MAX_DPI`) is out of range.
        RuntimeError: ``.mp4`` was asked for and ffmpeg is not installed.
    """
    path, frames, fps, dpi = _animation_target(path, frames, fps, dpi)
    _check_ffmpeg(path)
    figures = sfb.figures
    if not figures.branch_free:
        raise burmester.AssemblyError(
            f"the linkage meets the poses in modes {figures.modes}: it has a branch defect "
            "and cannot be driven through all of them; choose a branch-free driving pivot"
        )
    if not figures.feasible:
        raise burmester.AssemblyError(
            "the input cannot turn from pose 1 through the poses in order without passing a "
            "dead position (an order or circuit defect); choose another driving pivot"
        )
    mode: Mode = figures.modes[0] or "open"
    angles, _ = drive_angles(sfb, frames)
    sequence = np.concatenate([angles, angles[-2:0:-1]])

    fig, ax = plt.subplots(figsize=(6.0, 5.0))
    _draw_static(ax, sfb, _scene.linkage_scene(sfb, task), True, True)
    polys = [_linkage_polys(sfb, float(t), mode) for t in sequence]
    _fit_frames(ax, polys)
    lengths = ", ".join(f"{name} {format_length(v, units)}"
                        for name, v in zip(("ground", "crank", "coupler", "rocker"), sfb.fourbar.lengths))
    title = ax.set_title(f"{sfb.fourbar.grashof}, driven through the poses ({mode})\n{lengths}", fontsize=10)
    title.set_gid("link-lengths")
    label_axes(ax, units)
    (chain_art,) = ax.plot([], [], color="#333333", linewidth=2.5, marker="o", markersize=5, zorder=8)
    chain_art.set_gid("moving-linkage")
    tri = Polygon(polys[0][1], closed=True, facecolor="#ff7f0e", edgecolor="#b35806", alpha=0.6, zorder=8)
    tri.set_gid("moving-coupler")
    ax.add_patch(tri)

    def update(i: int) -> List[Artist]:
        chain, coupler = polys[i]
        chain_art.set_data(chain[:, 0], chain[:, 1])
        tri.set_xy(coupler)
        return [chain_art, tri]

    anim = FuncAnimation(fig, update, frames=len(sequence), interval=1000.0 / fps, blit=False)
    _save_animation(anim, path, fps, dpi)
    return anim


# ---------------------------------------------------------------------------
# One object at a glance: the pictures of the notebook display


def poses(task: Task, view: Optional[Sequence[float]] = None, *, labels: bool = True, legend: bool = True,
          units: Optional[str] = None, ax: Optional[Axes] = None) -> Axes:
    """Draw a task: its poses and poles.

    Draws each pose as a dot with a flag along the coupler angle (gid
    ``"poses"``, as :func:`burmester_plane`), the finite poles (gid
    ``"poles"``, labelled ``Pjk``; a pole at infinity, of a pure
    translation, is named in the title), and for three poses the pole
    triangle (``"pole-triangle"``) and the pole circle (``"pole-circle"``).

    Parameters:
        task: three to five poses.
        view: ``(xmin, xmax, ymin, ymax)``; default: a square around the
            poses and the poles near them
            (:func:`burmester.taskfile.default_curve_view`).
        labels, legend, units, ax: as every drawing (the module's *Common parameters*; the
            labels name the points).

    Returns:
        The Axes.
    """
    extent: Extent = default_curve_view(task) if view is None else _view.extent(view)
    ax = _new_axes(ax, (7.0, 6.0))
    handles: List[Artist] = [_draw_poses(ax, task, labels)]
    sc = _scene.poses_scene(task)
    pts = [p for _, p in sc.poles]
    if sc.pole_triangle:
        tri = np.array(pts + pts[:1], dtype=float)
        (side,) = ax.plot(tri[:, 0], tri[:, 1], color=POLE_COLOR, linewidth=1.0, zorder=4, label="pole triangle")
        side.set_gid("pole-triangle")
        handles.append(side)
        handles.append(_draw_circle(ax, task.pole_circle(), extent, "pole-circle", "pole circle"))
    if pts:
        handles.append(_markers(
            ax, pts, "poles", "poles",
            marker="o", markersize=5, color=POLE_COLOR, zorder=5,
        ))
    names = [(f"P{i}{j}", p) for (i, j), p in sc.poles]
    if labels:
        for name, p in names:
            _label(ax, p, name)
        title = f"{sc.count_word} poses and their poles"
        if sc.at_infinity:
            title += " (at infinity: " + ", ".join(f"P{i}{j}" for i, j in sc.at_infinity) + ")"
        ax.set_title(title)
    if labels or units:
        label_axes(ax, units)
    points: List[Tuple[str, Optional[Sequence[float]]]] = list(names)
    note_outside(ax, extent, points + [(f"pose {k}", q[:2]) for k, q in enumerate(task.poses, start=1)], units)
    _finish(ax, extent, legend, handles)
    return ax


def _default_input_angle(fb: burmester.FourBar) -> float:
    """0 when the input turns fully, else the middle of its first arc."""
    arcs = fb.input_range
    if not arcs:
        return 0.0
    lo, hi = arcs[0]
    return lo + 0.5 * ((hi - lo) % (2 * math.pi))


def four_bar(
    fb: burmester.FourBar,
    theta2: Optional[float] = None,
    mode: Mode = "open",
    *,
    labels: bool = True, legend: bool = True, units: Optional[str] = None, ax: Optional[Axes] = None,
) -> Axes:
    """Draw a four-bar at one input angle.

    Draws the ground (gid ``"ground"``), the fixed pivots (``"fixed-pivots"``),
    the chain ``O2 A B O4`` at ``theta2`` in ``mode`` (``"linkage"``), and the
    paths of the crank tip and the rocker tip over the input's range in that
    mode (``"crank-path"``, ``"rocker-path"``). With ``labels``, each link
    is labelled with its name and length (gid ``"link-length"``,
    :func:`label_lengths`) and the title lists the four lengths.

    Parameters:
        fb: the four-bar.
        theta2: the input angle, radians; default: 0 when the input turns
            fully, else the middle of its first arc (:attr:`FourBar.input_range`).
        mode: the assembly mode, ``"open"`` or ``"crossed"``.
        labels, legend, units, ax: as every drawing (the module's *Common parameters*; the
            labels name the joints).

    Returns:
        The Axes.

    Raises:
        burmester.AssemblyError: the loop does not close at ``theta2``.
    """
    t = _default_input_angle(fb) if theta2 is None else float(theta2)
    o2, a, b, o4 = fb.joints(t, mode)
    ax = _new_axes(ax, (7.0, 6.0))
    arcs = fb.input_range or [(0.0, 2 * math.pi)]
    for k, (lo, hi) in enumerate(arcs):
        span = (hi - lo) % (2 * math.pi) or 2 * math.pi
        ts = lo + np.linspace(0.0, span, 721)
        # The crank tip A is the coupler frame's origin, the rocker tip B its
        # point (coupler, 0).
        ax_, ay_, aok = fb.coupler_path((0.0, 0.0), ts, mode)
        bx_, by_, bok = fb.coupler_path((fb.coupler, 0.0), ts, mode)
        (cp,) = ax.plot(ax_[aok], ay_[aok], color="0.6", linewidth=0.8, zorder=1,
                        label="crank tip path" if k == 0 else None)
        cp.set_gid("crank-path")
        (rp,) = ax.plot(bx_[bok], by_[bok], color="0.6", linestyle="--", linewidth=0.8, zorder=1,
                        label="rocker tip path" if k == 0 else None)
        rp.set_gid("rocker-path")
    (g,) = ax.plot([o2[0], o4[0]], [o2[1], o4[1]], color="0.3", linestyle="--", linewidth=1.0, zorder=2)
    g.set_gid("ground")
    _markers(ax, [o2, o4], "fixed-pivots", "fixed pivots O2, O4", marker="^", markersize=10, color="0.2", zorder=6)
    chain = np.array([o2, a, b, o4], dtype=float)
    (ln,) = ax.plot(chain[:, 0], chain[:, 1], color=POSE_COLORS[3], linewidth=2.2, marker="o", markersize=5,
                    zorder=4, label=f"theta2 = {math.degrees(t):.1f} deg, {mode}")
    ln.set_gid("linkage")
    if labels:
        for name, p in zip(("O2", "A", "B", "O4"), (o2, a, b, o4)):
            _label(ax, p, name)
        l1, l2, l3, l4 = (format_length(v, units) for v in fb.lengths)
        ax.set_title(f"Four-bar ({fb.grashof}): ground {l1}, crank {l2}, coupler {l3}, rocker {l4}",
                     fontsize=10)
    _around_data(ax, labels, units)
    if labels:
        ax.apply_aspect()  # the final limits: the length labels are placed on the screen
        label_lengths(ax, link_segments(fb, (o2, a, b, o4)), units, avoid=[o2, a, b, o4])
    if legend:
        _legend(ax)
    return ax


def solution_map(
    smap: burmester.SolutionMap,
    *,
    pivots: int = 3,
    transmission_levels: Sequence[float] = (30.0, 45.0, 60.0, 75.0),
    labels: bool = True, legend: bool = True, units: Optional[str] = None, ax: Optional[Axes] = None,
) -> Axes:
    """Draw a solution-space map: what ``burmester map --design`` draws.

    A map of driving pivots (:meth:`burmester.Filemon.solution_map`) is drawn
    by :func:`center_plane` with its overlays: the branch map
    (``smap.branch_free``), the acceptable pivots, contours of the minimum
    transmission angle over the travel, and the best pivots
    (:meth:`burmester.SolutionMap.best_pivots`, numbered stars). A map of
    driving pivots with a driven slider
    (:meth:`burmester.SliderFilemon.solution_map`) is drawn with the same
    overlays, the slider's guide (gid ``"guide"``) and pin ``C1``
    (``"driven-pin"``) in place of the curves, and its best crank pivots
    (:meth:`burmester.SolutionMap.best_slider_pivots`). A map of
    driven pivots (:meth:`burmester.Task.driven_solution_map`) is drawn the
    same way over the driven plane (gids ``"branch-map"``,
    ``"transmission"``, ``"pivots"``), with the fixed driving pivot
    (``"driving-pivot"``) and the poses (``"poses"``).

    Parameters:
        smap: the map.
        pivots: how many of the best pivots to mark (0: none).
        transmission_levels: the contour levels, degrees.
        labels, legend, units, ax: as every drawing (the module's *Common parameters*; the
            labels name the points).

    Returns:
        The Axes. On a figure it makes, the layout is constrained so that the
        legend (right of the axes) lies inside the figure: a default
        ``savefig`` keeps it whole.
    """
    slider = smap.fixed_kind == "slider"
    # A map with a driven slider ranks its slider-cranks (SliderPivot records).
    ranked: Sequence[Union[burmester.Pivot, burmester.SliderPivot]] = []
    if pivots > 0:
        ranked = smap.best_slider_pivots(pivots) if slider else smap.best_pivots(pivots)
    best = [p.center for p in ranked]
    transmission = np.degrees(smap.min_transmission_rad)
    fixed = smap.fixed_dyad[0]
    if smap.varying == "driving" and not slider:
        drawn = center_plane(
            smap.task.filemon(fixed), smap.grid, free=smap.branch_free, acceptable=smap.acceptable,
            transmission=transmission, transmission_levels=transmission_levels, pivots=best or None,
            labels=labels, legend=legend, units=units, ax=ax,
        )
        return _fit_legend(drawn, ax is None)
    new_figure = ax is None
    ax = _new_axes(ax)
    extent = smap.extent
    img = ax.imshow(
        map_categories(smap.branch_free, smap.acceptable), origin="lower", extent=extent,
        cmap=MAP_CMAP, vmin=0, vmax=2, interpolation="nearest", zorder=0,
    )
    img.set_gid("branch-map")
    handles: List[Artist] = [
        Patch(facecolor=FREE_COLOR, edgecolor="0.5",
              label="branch-free crank pivot A0" if slider else "branch-free driven pivot"),
        Patch(facecolor=ACCEPT_COLOR, edgecolor="0.5", label="branch-free and acceptable"),
    ]
    if np.isfinite(transmission).any():
        xs, ys = smap.grid.cell_centers()
        cs = ax.contour(xs, ys, transmission, levels=sorted(transmission_levels),
                        colors="#636363", linewidths=0.8, zorder=3)
        cs.set_gid("transmission")
        ax.clabel(cs, fmt="%g°", fontsize=7)
        handles.append(Line2D([], [], color="#636363", linewidth=0.8, label="transmission angle, deg"))
    handles.append(_draw_poses(ax, smap.task, labels))
    if slider:
        handles.extend(_draw_slider_guide(ax, smap, extent))
    else:
        handles.append(_markers(
            ax, [fixed], "driving-pivot", "driving crank's fixed pivot A0",
            marker="^", markersize=9, color="#ff7f0e", markeredgecolor="black", zorder=5,
        ))
    if best:
        handles.append(_markers(
            ax, best, "pivots", "best driving pivots A0" if slider else "best driven pivots",
            marker="*", markersize=13, color="#ffd700", markeredgecolor="black", zorder=6,
        ))
    name = "C1" if slider else "A0"
    if labels:
        _label(ax, fixed, name)
        for k, p in enumerate(best, start=1):
            _label(ax, p, str(k))
        ax.set_title("Driving crank center-point plane, driven slider" if slider
                     else "Driven crank center-point plane")
    if labels or units:
        label_axes(ax, units)
    note_outside(ax, extent, [(name, fixed)] + [(str(k), p) for k, p in enumerate(best, start=1)]
                 + [(f"pose {k}", q[:2]) for k, q in enumerate(smap.task.poses, start=1)], units)
    _finish(ax, extent, legend, handles)
    return _fit_legend(ax, new_figure)


def _fit_legend(ax: Axes, new_figure: bool) -> Axes:
    """On a figure :func:`solution_map` made, the legend to the right of the
    axes becomes the figure's (``loc="outside right upper"``) under
    constrained layout, which makes room for it: a default ``savefig`` keeps
    it whole (an axes' legend outside it is cut off, and with the map's equal
    aspect constrained layout alone does not place it inside). A figure the
    caller gave is left as it is."""
    from matplotlib.figure import Figure as TopFigure

    leg, fig = ax.get_legend(), ax.get_figure()
    if not new_figure or leg is None or not isinstance(fig, TopFigure):
        return ax
    fig.set_layout_engine("constrained")
    handles = [h for h in leg.legend_handles if h is not None]
    labels = [t.get_text() for h, t in zip(leg.legend_handles, leg.get_texts()) if h is not None]
    leg.remove()
    fig.legend(handles, labels, loc="outside right upper", fontsize="small")
    return ax


def _draw_slider_guide(ax: Axes, smap: burmester.SolutionMap, extent: Extent) -> List[Artist]:
    """The driven slider of a solution map: its guide through ``C1`` (gid
    ``"guide"``, clipped to the view) and the pin ``C1`` (``"driven-pin"``)."""
    c1, u = smap.fixed_dyad
    out: List[Artist] = []
    seg = clip_line(c1, u, extent)
    if seg:
        (line,) = ax.plot([seg[0][0], seg[1][0]], [seg[0][1], seg[1][1]], color="#ff7f0e",
                          linewidth=1.2, zorder=4, label="driven slider's guide")
        line.set_gid("guide")
        out.append(line)
    out.append(_markers(
        ax, [c1], "driven-pin", "driven slider's pin C1",
        marker="s", markersize=8, color="#ff7f0e", markeredgecolor="black", zorder=5,
    ))
    return out


def atlas(
    pivot_atlas: burmester.PivotAtlas,
    *,
    labels: bool = True, legend: bool = True, units: Optional[str] = None, ax: Optional[Axes] = None,
) -> Axes:
    """Draw a pivot-pair atlas: what ``burmester atlas`` draws.

    The driven plane shaded by the best minimum transmission angle of each
    driven center (gid ``"best-transmission"``, with a colour bar), the count
    of acceptable driving pivots as contours (``"count"``), and the best pair
    (:meth:`burmester.PivotAtlas.best_pairs`): its driven and driving pivots
    joined by a dashed line (``"best-pair"``).

    Parameters:
        pivot_atlas: the atlas, from :func:`burmester.pivot_atlas`.
        labels: write the axis names and a title.
        legend: draw a legend (inside the axes).
        units: the unit of the lengths (``"mm"``), written on the axes
            (``x [mm]``); None: plain ``x`` and ``y``.
        ax: the Axes to draw into; default: a new figure.

    Returns:
        The Axes.
    """
    ax = _new_axes(ax, (7.0, 6.0))
    driven = pivot_atlas.driven
    im = ax.imshow(pivot_atlas.best_transmission_deg, origin="lower", extent=driven.extent,
                   cmap="viridis", vmin=0.0, vmax=90.0, interpolation="nearest")
    im.set_gid("best-transmission")
    ax.figure.colorbar(im, ax=ax, label="best minimum transmission angle (deg)")
    xs, ys = driven.cell_centers()
    if np.ptp(pivot_atlas.count) > 0:
        cs = ax.contour(xs, ys, pivot_atlas.count, levels=6, colors="white", linewidths=0.7)
        cs.set_gid("count")
        ax.clabel(cs, fontsize=7, fmt="%d")
    best = pivot_atlas.best_pairs(1)
    if best:
        b = best[0]
        (line,) = ax.plot([b.driven[0], b.driving[0]], [b.driven[1], b.driving[1]], "r--", lw=1)
        line.set_gid("best-pair")
        _markers(ax, [b.driven], "best-pair", f"driven C0 ({b.driven[0]:.4g}, {b.driven[1]:.4g})",
                 marker="^", markersize=9, color="red")
        _markers(ax, [b.driving], "best-pair", f"driving A0 ({b.driving[0]:.4g}, {b.driving[1]:.4g})",
                 marker="s", markersize=8, color="red")
        if legend:
            ax.legend(loc="upper right", fontsize=8)
    ax.set_xlim(driven.xmin, driven.xmax)
    ax.set_ylim(driven.ymin, driven.ymax)
    ax.set_aspect("equal")
    if labels:
        ax.set_title("Pivot-pair atlas")
    if labels or units:
        label_axes(ax, units, "driven center x", "driven center y")
    return ax


# ---------------------------------------------------------------------------
# The interactive explorer


def explore(
    task: Task,
    driven_center: Point,
    view: Optional[ViewLike] = None,
    *,
    driving_center: Optional[Point] = None,
    limits: Optional[burmester.DesignLimits] = None,
    grid: Optional[Tuple[int, int]] = None,
    live: Optional[bool] = None,
    export_to: Optional[Union[str, Path]] = None,
    fig: Optional[Figure] = None,
) -> Explorer:
    """Open the interactive explorer of a three-position task: drag the
    poses, ``C0`` and ``A0`` and watch the branch map, the acceptable region
    (under ``limits``), the Filemon curves and the linkage follow.

    In a desktop window (``plt.show()`` after the call, or ``python -i``) or
    in Jupyter with ``%matplotlib widget`` (ipympl, in the ``plot`` extra);
    the keywords, handles and keys are those of
    :class:`burmester.explorer.Explorer`.

    Returns:
        The :class:`~burmester.explorer.Explorer`: read the state
        (``.task``, ``.driven_center``, ``.driving_center``, ``.linkage()``),
        move things from code (``.move_pose(k, x, y, angle)``, ...) and save
        (``.save("linkage.dxf")``, ``.save("task.toml")``, ``.save("explorer.png")``).
    """
    from burmester.explorer import Explorer

    return Explorer(
        task, driven_center, view, driving_center=driving_center, limits=limits, grid=grid,
        live=live, export_to=export_to, fig=fig,
    )


# ---------------------------------------------------------------------------
# The motor drive: the Watt II six-bar (a crank-rocker added to a linkage
# whose input swings)

#: Colours of the drive map's categories: no drive, a drive (the six-bar
#: turns fully), a drive that meets the limits.
DRIVE_MAP_CMAP = ListedColormap(["#eeeeee", "#c6dbef", "#4292c6"])
#: The actuator map's shading: no monotone stroke, a monotone stroke, one that meets the limits.
ACTUATOR_MAP_CMAP = ListedColormap(["#f7f7f7", "#c7e9c0", "#41ab5d"])
#: Colour of the drive (crank, drive coupler) in the pictures of a six-bar.
DRIVE_COLOR = "#e6550d"


def _drive_of(obj: Any) -> Tuple[burmester.SixBar, Optional[burmester.Drive]]:
    if isinstance(obj, burmester.Drive):
        return obj.sixbar, obj
    if isinstance(obj, burmester.SixBar):
        return obj, None
    raise TypeError(f"expected a burmester.Drive or a burmester.SixBar, got {type(obj).__name__}")


def _sixbar_polys(six: burmester.SixBar, phi: float) -> Tuple[npt.NDArray[np.float64], ...]:
    """``(drive, ternary, motion, coupler)`` at crank angle ``phi``: the
    polyline D0-D-E, the input link's triangle A0-A-E, the polyline A-C-C0
    and the coupler triangle A-C-P (the core's joints)."""
    d0, d, e, a0, a, c, c0, p = (np.asarray(q, dtype=float) for q in six.joints(phi))
    return (
        np.array([d0, d, e]), np.array([a0, a, e]), np.array([a, c, c0]), np.array([a, c, p]),
    )


def _turn_angles(six: burmester.SixBar, drive: Optional[burmester.Drive], n: int) -> npt.NDArray[np.float64]:
    if drive is not None:
        return np.asarray(drive.turn_angles(n), dtype=float)
    return np.asarray(six.crank_angles(0.0, n), dtype=float)


def _draw_sixbar_static(ax: Axes, six: burmester.SixBar, drive: Optional[burmester.Drive],
                        task: Optional[Task], curve: bool, labels: bool) -> List[Artist]:
    """Fixed pivots, crank circle, E's swing, the coupler path over a turn
    and the poses; returns legend handles."""
    handles: List[Artist] = []
    sc = _scene.sixbar_scene(six, drive, task)
    d0, a0, c0 = sc.d0, sc.a0, sc.c0
    crank = Circle(d0, sc.crank_radius, fill=False, color=DRIVE_COLOR, linestyle=":", linewidth=1.0, zorder=2,
                   label="crank circle")
    crank.set_gid("crank-circle")
    ax.add_patch(crank)
    handles.append(crank)
    if curve:
        ts = _turn_angles(six, drive, 720)
        x, y, ok = six.coupler_path(ts)
        (cc,) = ax.plot(x[ok], y[ok], color="0.55", linewidth=1.0, zorder=1,
                        label="coupler path over a crank turn")
        cc.set_gid("coupler-path")
        handles.append(cc)
        es = np.array([six.joints(float(t))[2] for t in ts[::4]])
        (arc,) = ax.plot(es[:, 0], es[:, 1], color=DRIVE_COLOR, linewidth=1.0, alpha=0.6, zorder=1,
                         label="E over a crank turn")
        arc.set_gid("attachment-arc")
        handles.append(arc)
    (g,) = ax.plot([d0[0], a0[0], c0[0]], [d0[1], a0[1], c0[1]], color="0.3", linestyle="--",
                   linewidth=1.0, zorder=2)
    g.set_gid("ground")
    handles.append(_markers(ax, [d0, a0, c0], "fixed-pivots", "fixed pivots D0 (motor), A0, C0",
                            marker="^", markersize=10, color="0.2", zorder=6))
    _draw_flags(ax, sc.poses, sc.flag, labels, 9)
    if labels:
        _label(ax, d0, "D0")
        _label(ax, a0, "A0")
        _label(ax, c0, "C0")
    return handles


def _draw_sixbar_at(ax: Axes, six: burmester.SixBar, phi: float, color: str, gid: str,
                    label: Optional[str], alpha: float = 0.25) -> Artist:
    drive, ternary, motion, coupler = _sixbar_polys(six, phi)
    (dl,) = ax.plot(drive[:, 0], drive[:, 1], color=DRIVE_COLOR, linewidth=1.8, marker="o",
                    markersize=3, zorder=4)
    dl.set_gid(f"drive-{gid}")
    (ml,) = ax.plot(motion[:, 0], motion[:, 1], color=color, linewidth=2.0, marker="o", markersize=4,
                    zorder=4, label=label)
    ml.set_gid(f"linkage-{gid}")
    for poly, name in ((ternary, "input"), (coupler, "coupler")):
        tri = Polygon(poly, closed=True, facecolor=color, edgecolor=color, alpha=alpha, zorder=3)
        tri.set_gid(f"{name}-{gid}")
        ax.add_patch(tri)
    return ml


def sixbar(
    obj: Union[burmester.Drive, burmester.SixBar],
    *,
    task: Optional[Task] = None,
    coupler_path: bool = True,
    labels: bool = True, legend: bool = True, units: Optional[str] = None, ax: Optional[Axes] = None,
) -> Axes:
    """Draw a six-bar: a drive at the crank angles of its poses, or a
    :class:`burmester.SixBar` at four crank angles a quarter turn apart.

    Draws the fixed pivots ``D0`` (the motor), ``A0`` and ``C0``, the crank
    circle (gid ``"crank-circle"``), the coupler point's path and ``E``'s
    swing over a full crank turn (``"coupler-path"``, ``"attachment-arc"``),
    and at each position the drive ``D0 D E`` (orange, ``"drive-k"``), the
    ternary input link ``A0 A E`` and the coupler triangle ``A C P``
    (``"input-k"``, ``"coupler-k"``) and the motion loop ``A C C0``
    (``"linkage-k"``) in the pose's colour; the poses as black flags
    (``"pose-k"``). Every point is the core's (:meth:`burmester.SixBar.joints`).
    With ``labels``, the moving links at the first position drawn are
    labelled with their names and lengths (``"crank 40 mm"``, gid
    ``"link-length"``, as :func:`linkage` does).

    Parameters:
        obj: a :class:`burmester.Drive` (from
            :meth:`burmester.SynthesizedFourBar.best_drive`,
            :meth:`burmester.DriveMap.best_drives`, ...) or a
            :class:`burmester.SixBar`.
        task: the task whose poses to mark (a drive knows its own).
        coupler_path: draw the paths over a full crank turn.
        labels, legend, units, ax: as every drawing (the module's *Common parameters*; the
            labels name the pivots and the links).

    Returns:
        The Axes.
    """
    six, drive = _drive_of(obj)
    ax = _new_axes(ax, (7.5, 6.0))
    handles = _draw_sixbar_static(ax, six, drive, task, coupler_path, labels)
    drawn: List[Tuple[float, str]] = []
    if drive is not None:
        for k, phi in enumerate(drive.pose_crank_angles, start=1):
            handles.append(_draw_sixbar_at(
                ax, six, phi, POSE_COLORS[k], str(k),
                f"pose {k}: crank at {math.degrees(phi) % 360:.1f} deg",
            ))
            drawn.append((phi, POSE_COLORS[k]))
    else:
        for k in range(4):
            phi = k * math.pi / 2
            try:
                handles.append(_draw_sixbar_at(ax, six, phi, POSE_COLORS[k + 1], str(k + 1),
                                               f"crank at {90 * k} deg"))
            except burmester.BurmesterError:
                continue
            drawn.append((phi, POSE_COLORS[k + 1]))
    if labels:
        if drive is not None:
            ax.set_title(
                f"Driven by a motor: min transmission {drive.min_transmission_deg:.1f} deg, "
                f"time ratio {drive.time_ratio:.2f}"
            )
        else:
            ax.set_title(f"Six-bar: drive {six.drive_grashof}, "
                         f"{'turns fully' if six.crank_turns_fully else 'does not turn fully'}")
    _around_data(ax, labels, units)
    if labels and drawn:
        # The link lengths, on the links at the first position drawn (the
        # axes' limits and aspect first: the labels are placed on the screen).
        ax.apply_aspect()
        phi, color = drawn[0]
        d0, d, e, a0, a, c, c0, _ = (tuple(map(float, q)) for q in six.joints(phi))
        links = [("crank", d0, d), ("drive coupler", d, e), ("input", a0, a), ("coupler", a, c),
                 ("rocker", c, c0)]
        label_lengths(ax, links, units, color=color, avoid=[d0, d, e, a0, a, c, c0])
    if legend:
        _legend(ax, handles)
    return ax


def placement_map(ax: Axes, grid: Grid, possible: npt.ArrayLike, acceptable: npt.ArrayLike,
                  transmission_deg: npt.ArrayLike, cmap: ListedColormap, names: Tuple[str, str], gid: str,
                  transmission_levels: Sequence[float], transmission_name: Optional[str] = None) -> List[Artist]:
    """Shade a map of candidate pivots and contour its transmission angle:
    the image of three categories (none, ``possible``, ``acceptable``: the
    colours of ``cmap``, gid ``gid``) over the grid's extent and the
    contours of ``transmission_deg`` (degrees, NaN where undefined) at
    ``transmission_levels``, labelled (gid ``"transmission"``). Returns the
    legend handles: a patch for each of the two categories (``names``) and,
    with ``transmission_name``, a line for the contours. The drive map
    (:func:`drive_map`) and the actuator map
    (:func:`burmester.actuators.draw_map`) are drawn by it."""
    cat = np.where(acceptable, 2, np.where(possible, 1, 0)).astype(np.int8)
    img = ax.imshow(cat, origin="lower", extent=grid.extent, cmap=cmap, vmin=0, vmax=2,
                    interpolation="nearest", zorder=0)
    img.set_gid(gid)
    handles: List[Artist] = [Patch(facecolor=to_hex(cmap(k)), edgecolor="0.5", label=name)
                             for k, name in zip((1, 2), names)]
    mu = np.asarray(transmission_deg, dtype=float)
    if np.isfinite(mu).any():
        xs, ys = grid.cell_centers()
        cs = ax.contour(xs, ys, mu, levels=sorted(transmission_levels), colors="#636363",
                        linewidths=0.8, zorder=3)
        cs.set_gid("transmission")
        ax.clabel(cs, fmt="%g°", fontsize=7)
        if transmission_name is not None:
            handles.append(Line2D([], [], color="#636363", linewidth=0.8, label=transmission_name))
    return handles


def drive_map(
    dmap: burmester.DriveMap,
    *,
    best: int = 3,
    rank_by: RankBy = "balanced",
    transmission_levels: Sequence[float] = (30.0, 45.0, 60.0, 75.0),
    labels: bool = True, legend: bool = True, ax: Optional[Axes] = None,
) -> Axes:
    """Draw a drive map: where the motor's crank pivot ``D0`` may go.

    Shades the candidate pivots with a drive (the six-bar turns fully, gid
    ``"drive-map"``) and those that meet the limits, draws contours of the
    smaller minimum transmission angle of the two loops over a crank turn
    (``"transmission"``), ``A0``, ``E``'s swing from the first pose's end to
    the last (``"attachment-swing"``), the line through its two ends where
    the time ratio is 1 (``"unit-time-ratio"``, the classic construction),
    and the best drives by ``rank_by`` as numbered stars (``"drives"``).

    Parameters:
        dmap: the map (:meth:`burmester.SynthesizedFourBar.drive_map`).
        best: how many of the best drives to mark (0: none).
        rank_by: their ranking (:meth:`burmester.DriveMap.best_drives`).
        transmission_levels: the contour levels, degrees.
        labels, legend, ax: as every drawing (the module's *Common parameters*; the
            labels name the points).

    Returns:
        The Axes.
    """
    ax = _new_axes(ax)
    extent = dmap.extent
    handles = placement_map(ax, dmap.grid, dmap.valid, dmap.acceptable, np.degrees(dmap.min_transmission_rad),
                            DRIVE_MAP_CMAP, ("crank pivot with a drive", "a drive that meets the limits"),
                            "drive-map", transmission_levels, "min transmission of both loops, deg")
    a0 = dmap.linkage.driving[0]
    ea, eb = dmap.attachment_ends
    rho = math.dist(a0, ea)
    t0 = math.atan2(ea[1] - a0[1], ea[0] - a0[0])
    t1 = math.atan2(eb[1] - a0[1], eb[0] - a0[0])
    sweep = (t1 - t0 + math.pi) % (2 * math.pi) - math.pi
    ts = t0 + sweep * np.linspace(0.0, 1.0, 64)
    (sw,) = ax.plot(a0[0] + rho * np.cos(ts), a0[1] + rho * np.sin(ts), color=DRIVE_COLOR,
                    linewidth=2.5, zorder=5, label="E's swing (first pose to last)")
    sw.set_gid("attachment-swing")
    handles.append(sw)
    seg = clip_line(ea, (eb[0] - ea[0], eb[1] - ea[1]), extent)
    if seg:
        (ln,) = ax.plot([seg[0][0], seg[1][0]], [seg[0][1], seg[1][1]], color=DRIVE_COLOR,
                        linestyle="--", linewidth=0.9, zorder=4, label="time ratio 1 (beyond the ends)")
        ln.set_gid("unit-time-ratio")
        handles.append(ln)
    handles.append(_markers(ax, [a0], "input-pivot", "input pivot A0", marker="^", markersize=9,
                            color="0.2", zorder=6))
    drives = dmap.best_drives(best, rank_by=rank_by) if best > 0 else []
    if drives:
        handles.append(_markers(ax, [d.drive_pivot for d in drives], "drives", f"best drives ({rank_by})",
                                marker="*", markersize=13, color="#ffd700", markeredgecolor="black",
                                zorder=7))
    if labels:
        _label(ax, a0, "A0")
        _label(ax, ea, "E1")
        for k, d in enumerate(drives, start=1):
            _label(ax, d.drive_pivot, str(k))
        ax.set_title(f"Drive map: the motor's crank pivot D0 (swing margin {dmap.swing_margin_deg:g} deg)")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
    _finish(ax, extent, legend, handles)
    return ax


def animate_sixbar(
    obj: Union[burmester.Drive, burmester.SixBar],
    path: Union[str, Path],
    *,
    task: Optional[Task] = None,
    frames: int = 120, fps: int = 24, dpi: int = 80,
) -> FuncAnimation:
    """Write an animation of a six-bar over one full crank turn (the motor
    turning at a constant speed), from pose 1 in the motor's direction for a
    drive. The file is written beside ``path`` and moved into place when
    complete.

    Parameters:
        obj: a :class:`burmester.Drive` or a :class:`burmester.SixBar` whose
            crank turns fully.
        path: ``.gif`` (Pillow) or ``.mp4`` (ffmpeg).
        task: the task whose poses to mark (a drive knows its own).
        frames: frames per crank turn (2 to :data:`MAX_FRAMES`).
        fps: frames per second (1 to :data:`MAX_FPS`).
        dpi: resolution (1 to :data:`MAX_DPI`).

    Returns:
        The matplotlib animation (already saved).

    Raises:
        burmester.InvalidInputError: another file type, a folder that does
            not exist, a count out of range, or a six-bar whose crank does
            not turn fully.
        RuntimeError: ``.mp4`` without ffmpeg.
    """

    six, drive = _drive_of(obj)
    path, frames, fps, dpi = _animation_target(path, frames, fps, dpi)
    if not six.crank_turns_fully:
        raise burmester.InvalidInputError(
            "the six-bar's crank does not turn fully (its drive is not a crank-rocker, or a loop "
            f"toggles at crank angles {[round(math.degrees(a), 2) for a in six.dead_positions]} deg)"
        )
    _check_ffmpeg(path)
    angles = _turn_angles(six, drive, frames)
    polys = [_sixbar_polys(six, float(t)) for t in angles]
    fig, ax = plt.subplots(figsize=(6.0, 5.0))
    _draw_sixbar_static(ax, six, drive, task, True, True)
    _fit_frames(ax, polys)
    title = "Six-bar over a crank turn"
    if drive is not None:
        title = f"Motor-driven: time ratio {drive.time_ratio:.2f}, min transmission {drive.min_transmission_deg:.0f} deg"
    ax.set_title(title)
    (drive_art,) = ax.plot([], [], color=DRIVE_COLOR, linewidth=2.5, marker="o", markersize=5, zorder=8)
    drive_art.set_gid("moving-drive")
    (motion_art,) = ax.plot([], [], color="#333333", linewidth=2.5, marker="o", markersize=5, zorder=8)
    motion_art.set_gid("moving-linkage")
    tern = Polygon(polys[0][1], closed=True, facecolor="#fdae6b", edgecolor="#e6550d", alpha=0.6, zorder=7)
    tern.set_gid("moving-input")
    ax.add_patch(tern)
    tri = Polygon(polys[0][3], closed=True, facecolor="#ff7f0e", edgecolor="#b35806", alpha=0.6, zorder=8)
    tri.set_gid("moving-coupler")
    ax.add_patch(tri)

    def update(i: int) -> List[Artist]:
        dr, te, mo, co = polys[i]
        drive_art.set_data(dr[:, 0], dr[:, 1])
        motion_art.set_data(mo[:, 0], mo[:, 1])
        tern.set_xy(te)
        tri.set_xy(co)
        return [drive_art, motion_art, tern, tri]

    anim = FuncAnimation(fig, update, frames=len(polys), interval=1000.0 / fps, blit=False)
    try:
        _save_animation(anim, path, fps, dpi)
    finally:
        plt.close(fig)
    return anim


# ---------------------------------------------------------------------------
# Slider linkages (issue 27)


def _draw_crank_poses(ax: Axes, obj: Union[burmester.SynthesizedSliderCrank,
                                              burmester.SynthesizedInvertedSliderCrank],
                      draw_at: Callable[[float, Mode, str, str], Any],
                      plate: Callable[[float, Mode], Sequence[Tuple[float, float]]], flag: float,
                      labels: bool) -> None:
    """A synthesized crank-driven linkage (the slider-crank, the inverted
    one) at each of its poses: ``draw_at(theta2, mode, colour, gid)``, the
    coupler plate (gid ``"coupler-k"``) through the two joints
    ``plate(theta2, mode)`` and the task's coupler point, the coupler point's
    path over the travel (``"coupler-curve"``) and the task's poses as flags
    of size ``flag``."""
    modes = obj.modes
    first: Mode = modes[0] or "open"
    for k, (t, m) in enumerate(zip(obj.input_angles, modes), start=1):
        draw_at(t, m or first, POSE_COLORS[k], f"linkage-{k}")
        px, py, _ = obj.pose_at(t, m or first)
        patch = Polygon(np.array([*plate(t, m or first), (px, py)]), closed=True, facecolor=POSE_COLORS[k],
                        edgecolor=POSE_COLORS[k], alpha=0.15, zorder=3)
        patch.set_gid(f"coupler-{k}")
        ax.add_patch(patch)
    if obj.travel is not None:
        ts = np.array(obj.travel_angles(361))
        xs, ys, ok = obj.linkage.coupler_path(obj.coupler_point, ts, first)
        (cc,) = ax.plot(xs[ok], ys[ok], color="#ff7f0e", linewidth=1.2, zorder=3, label="coupler curve")
        cc.set_gid("coupler-curve")
    poses = [obj.pose_at(t, m or first) for t, m in zip(obj.input_angles, modes)]
    _draw_flags(ax, poses, flag, labels, zorder=7)


def _draw_slider_at(ax: Axes, sc: burmester.SliderCrank, theta2: float, mode: Mode, color: str, gid: str,
                    alpha: float = 1.0, zorder: int = 4) -> Tuple[Line2D, Polygon]:
    """The chain ``A0 A B`` and the slider block at ``theta2`` (gids
    ``gid`` and ``gid + "-block"``)."""
    s = _scene.slider_scene(sc, theta2, mode)
    chain = np.array([s.pivot, s.crank_joint, s.slider_joint], dtype=float)
    (ln,) = ax.plot(chain[:, 0], chain[:, 1], color=color, linewidth=2.2, marker="o", markersize=5,
                    alpha=alpha, zorder=zorder)
    ln.set_gid(gid)
    block = Polygon(np.array(s.block), closed=True, facecolor="#bdbdbd", edgecolor=color, alpha=alpha,
                    zorder=zorder - 1)
    block.set_gid(gid + "-block")
    ax.add_patch(block)
    return ln, block


def _draw_guide(ax: Axes, sc: burmester.SliderCrank, theta2: float, mode: Mode) -> None:
    """The guide (gid ``"guide"``) and the crank pivot (``"fixed-pivots"``)."""
    s = _scene.slider_scene(sc, theta2, mode)
    (g0, g1) = s.guide
    (gl,) = ax.plot([g0[0], g1[0]], [g0[1], g1[1]], color="0.3", linewidth=1.2, zorder=2, label="guide")
    gl.set_gid("guide")
    _markers(ax, [s.pivot], "fixed-pivots", "crank pivot A0", marker="^", markersize=10, color="0.2", zorder=6)


def slider_crank(
    obj: Union[burmester.SliderCrank, burmester.SynthesizedSliderCrank],
    theta2: Optional[float] = None,
    mode: Mode = "open",
    *,
    labels: bool = True, legend: bool = True, units: Optional[str] = None, ax: Optional[Axes] = None,
) -> Axes:
    """Draw a slider-crank: the guide as a line (gid ``"guide"``), the
    slider as a block on it (``"linkage-block"``), the crank and coupler
    (``"linkage"``) and the crank pivot (``"fixed-pivots"``).

    A :class:`burmester.SliderCrank` is drawn at ``theta2`` (default: 0 when
    the crank turns fully, else the middle of its first arc) in ``mode``,
    with the crank tip's path. A :class:`burmester.SynthesizedSliderCrank`
    is drawn at each of its poses (pose colours, gid ``"linkage-k"``), with
    the task's poses as flags (``"pose-k"``) and the coupler point's path
    over the travel (``"coupler-curve"``); ``theta2`` and ``mode`` are then
    unused.

    Raises:
        burmester.AssemblyError: the loop does not close at ``theta2``.
    """
    ax = _new_axes(ax, (7.0, 6.0))
    if isinstance(obj, burmester.SynthesizedSliderCrank):
        sc = obj.linkage
        modes = obj.modes
        first: Mode = modes[0] or "open"
        _draw_guide(ax, sc, obj.input_angles[0], first)
        # The coupler plate: the crank tip, the slider pin and the task's coupler point.
        _draw_crank_poses(ax, obj, lambda t, m, c, g: _draw_slider_at(ax, sc, t, m, c, g, alpha=0.85),
                          lambda t, m: sc.joints(t, m)[1:], 0.12 * (sc.crank + sc.coupler), labels)
        if labels:
            r, l = format_length(sc.crank, units), format_length(sc.coupler, units)
            stroke = "" if obj.stroke_used is None else f", stroke used {format_length(obj.stroke_used, units)}"
            ax.set_title(f"Slider-crank: crank {r}, coupler {l}{stroke}\nmodes {modes}, direction {obj.direction}",
                         fontsize=10)
    else:
        sc = obj
        arcs = sc.input_range
        t = _scene.slider_crank_angle(sc, theta2)
        _draw_guide(ax, sc, t, mode)
        for k, (lo, hi) in enumerate(arcs or [(0.0, 2 * math.pi)]):
            span = (hi - lo) % (2 * math.pi) or 2 * math.pi
            xs, ys, ok = sc.coupler_path((0.0, 0.0), lo + np.linspace(0.0, span, 721), mode)
            (cp,) = ax.plot(xs[ok], ys[ok], color="0.6", linewidth=0.8, zorder=1,
                            label="crank tip path" if k == 0 else None)
            cp.set_gid("crank-path")
        arts = _draw_slider_at(ax, sc, t, mode, POSE_COLORS[3], "linkage")
        arts[0].set_label(f"theta2 = {math.degrees(t):.1f} deg, {mode}")
        if labels:
            s = _scene.slider_scene(sc, t, mode)
            for name, p in zip(("A0", "A", "B"), (s.pivot, s.crank_joint, s.slider_joint)):
                _label(ax, p, name)
            ax.set_title(f"Slider-crank: crank {format_length(sc.crank, units)}, coupler "
                         f"{format_length(sc.coupler, units)}, offset {format_length(sc.offset, units)}, "
                         f"stroke {format_length(sc.stroke(mode), units)}", fontsize=10)
    return _framed(ax, labels, legend, units)


def animate_slider_crank(
    s: burmester.SynthesizedSliderCrank,
    path: Union[str, Path],
    *,
    frames: int = 60, fps: int = 20, dpi: int = 80,
    units: Optional[str] = None,
) -> FuncAnimation:
    """Write an animation of a synthesized slider-crank driven by its crank
    from pose 1 through the poses in order and back (``.gif`` or ``.mp4``):
    the moving chain (gid ``"moving-linkage"``) and slider block
    (``"moving-linkage-block"``) over the guide, the poses and the coupler
    curve (as :func:`slider_crank`).

    Raises:
        burmester.InvalidInputError: the linkage has no travel through the
            poses in order in one mode (:attr:`SynthesizedSliderCrank.feasible`
            is False), the file type is neither ``.gif`` nor ``.mp4``, its
            folder does not exist, or ``frames``, ``fps`` or ``dpi`` is out of
            range (as :func:`animate`).
        RuntimeError: ``.mp4`` was asked for and ffmpeg is not installed.
    """
    path, frames, fps, dpi = _animation_target(path, frames, fps, dpi)
    _check_ffmpeg(path)
    if not s.feasible:
        raise burmester.InvalidInputError(
            f"the slider-crank meets its poses in modes {s.modes} and direction {s.direction!r}: it "
            "cannot be driven through them in order in one mode; pick a feasible one (.feasible)"
        )
    angles = _scene.slider_crank_pose_angles(s, frames)
    sequence = angles + angles[-2:0:-1]
    mode: Mode = s.modes[0] or "open"
    sc = s.linkage
    fig, ax = plt.subplots(figsize=(6.0, 5.0))
    slider_crank(s, labels=False, legend=False, units=units, ax=ax)
    for art in list(ax.get_children()):  # the linkage at the poses (not the coupler curve): it moves now
        if str(art.get_gid()).startswith(("linkage-", "coupler-")) and art.get_gid() != "coupler-curve":
            art.remove()
    scenes = [_scene.slider_scene(sc, t, mode) for t in sequence]
    polys = [(np.array([x.pivot, x.crank_joint, x.slider_joint]), np.array(x.block)) for x in scenes]
    _fit_frames(ax, polys)
    label_axes(ax, units)
    ax.set_title(f"Slider-crank driven through the poses ({mode}): crank {format_length(sc.crank, units)}, "
                 f"coupler {format_length(sc.coupler, units)}", fontsize=10)
    # The moving chain and block: drawn at the first frame, moved by each.
    moving = _draw_slider_at(ax, sc, sequence[0], mode, "#333333", "moving-linkage", zorder=8)

    def update(i: int) -> List[Artist]:
        chain, corners = polys[i]
        moving[0].set_data(chain[:, 0], chain[:, 1])
        moving[1].set_xy(corners)
        return [moving[0], moving[1]]

    anim = FuncAnimation(fig, update, frames=len(sequence), interval=1000.0 / fps, blit=False)
    _save_animation(anim, path, fps, dpi)
    return anim


# ---------------------------------------------------------------------------
# The inverted slider-crank (issue 27): a crank whose coupler's slot slides
# through a block pivoted on the ground.


def _draw_inverted_at(ax: Axes, q: burmester.InvertedSliderCrank, theta2: float, mode: Mode, color: str,
                      gid: str, alpha: float = 1.0, zorder: int = 4) -> Tuple[Line2D, Line2D, Polygon]:
    """The crank ``A0 A``, the slotted coupler (from the pin ``A`` to the
    slot's foot ``F``, gid ``gid``, and along the slot over the block's
    travel in ``mode``, ``gid + "-slot"``) and the block on the swivel
    (``gid + "-block"``) at ``theta2`` (:func:`burmester._scene.inverted_scene`)."""
    sc = _scene.inverted_scene(q, theta2, mode)
    chain = np.array(_scene.crank_chain(sc), dtype=float)
    (ln,) = ax.plot(chain[:, 0], chain[:, 1], color=color, linewidth=2.2, marker="o", markersize=5,
                    alpha=alpha, zorder=zorder)
    ln.set_gid(gid)
    (p0, p1) = sc.slot
    (slot,) = ax.plot([p0[0], p1[0]], [p0[1], p1[1]], color=color, linewidth=4.0, alpha=0.55 * alpha,
                      solid_capstyle="round", zorder=zorder)
    slot.set_gid(gid + "-slot")
    block = Polygon(np.array(sc.block), closed=True, facecolor="#bdbdbd", edgecolor=color, alpha=alpha,
                    zorder=zorder - 1)
    block.set_gid(gid + "-block")
    ax.add_patch(block)
    return ln, slot, block


def inverted_slider_crank(
    obj: Union[burmester.InvertedSliderCrank, burmester.SynthesizedInvertedSliderCrank],
    theta2: Optional[float] = None,
    mode: Mode = "open",
    *,
    labels: bool = True, legend: bool = True, units: Optional[str] = None, ax: Optional[Axes] = None,
) -> Axes:
    """Draw an inverted slider-crank: the crank and the slotted coupler
    (gid ``"linkage"``, its slot ``"linkage-slot"``), the block on the
    swivel (``"linkage-block"``), and the crank pivot and the swivel
    (``"fixed-pivots"``).

    A :class:`burmester.InvertedSliderCrank` is drawn at ``theta2``
    (default: the crank pointing away from the swivel) in ``mode``, with the
    crank pin's path. A :class:`burmester.SynthesizedInvertedSliderCrank` is
    drawn at each of its poses (pose colours, gid ``"linkage-k"``), with the
    task's poses as flags (``"pose-k"``) and the coupler point's path over
    the travel (``"coupler-curve"``); ``theta2`` and ``mode`` are then
    unused.

    Raises:
        burmester.AssemblyError: the loop does not close at ``theta2``.
    """
    ax = _new_axes(ax, (7.0, 6.0))
    q = obj.linkage if isinstance(obj, burmester.SynthesizedInvertedSliderCrank) else obj
    _markers(ax, [q.pivot, q.swivel], "fixed-pivots", "crank pivot A0, swivel S", marker="^", markersize=10,
             color="0.2", zorder=6)
    if isinstance(obj, burmester.SynthesizedInvertedSliderCrank):
        modes = obj.modes
        # The coupler plate: the crank pin, the slot's foot and the task's coupler point.
        _draw_crank_poses(ax, obj, lambda t, m, c, g: _draw_inverted_at(ax, q, t, m, c, g, alpha=0.85),
                          lambda t, m: q.joints(t, m)[1::2], 0.12 * (q.crank + q.ground), labels)
        if labels:
            stroke = "" if obj.stroke_used is None else f", stroke used {format_length(obj.stroke_used, units)}"
            swing = "" if obj.swing_used_deg is None else f", swing {obj.swing_used_deg:.1f} deg"
            ax.set_title(f"Inverted slider-crank: crank {format_length(q.crank, units)}, ground "
                         f"{format_length(q.ground, units)}, offset {format_length(q.offset, units)}{stroke}"
                         f"{swing}\nmodes {modes}, direction {obj.direction}", fontsize=10)
    else:
        t = _scene.inverted_crank_angle(q, theta2)
        arcs = q.input_range
        for k, (lo, hi) in enumerate(arcs or [(0.0, 2 * math.pi)]):
            span = (hi - lo) % (2 * math.pi) or 2 * math.pi
            ang = lo + np.linspace(0.0, span, 721)
            (cp,) = ax.plot(q.pivot[0] + q.crank * np.cos(ang), q.pivot[1] + q.crank * np.sin(ang), color="0.6",
                            linewidth=0.8, zorder=1, label="crank pin path" if k == 0 else None)
            cp.set_gid("crank-path")
        arts = _draw_inverted_at(ax, q, t, mode, POSE_COLORS[3], "linkage")
        arts[0].set_label(f"theta2 = {math.degrees(t):.1f} deg, {mode}")
        if labels:
            a0, a, s, f = q.joints(t, mode)
            for name, p in zip(("A0", "A", "S"), (a0, a, s)):
                _label(ax, p, name)
            sw = q.swing(mode)
            swing = "" if sw is None else f", swing {math.degrees(sw[1][2] - sw[0][2]):.1f} deg"
            ax.set_title(f"Inverted slider-crank: crank {format_length(q.crank, units)}, ground "
                         f"{format_length(q.ground, units)}, offset {format_length(q.offset, units)}, "
                         f"stroke {format_length(q.stroke, units)}{swing}", fontsize=10)
    return _framed(ax, labels, legend, units)


def slider_dyad(dyad: burmester.SliderDyad, task: Optional[Task] = None, *, labels: bool = True,
                legend: bool = True, units: Optional[str] = None, ax: Optional[Axes] = None) -> Axes:
    """Draw a slider dyad: its guide as a line (gid ``"guide"``, over the
    pin's positions at the poses of ``task`` when given:
    :func:`burmester._scene.slider_dyad_guide`), the pin ``C1`` at pose 1
    (``"slider-pin"``) and, with ``task``, the pin at the other poses
    (``"slider-positions"``) and the poses (``"pose-k"``)."""
    ax = _new_axes(ax, (7.0, 6.0))
    (g0, g1) = _scene.slider_dyad_guide(dyad, task)
    (gl,) = ax.plot([g0[0], g1[0]], [g0[1], g1[1]], color="0.3", linewidth=1.2, zorder=2, label="guide")
    gl.set_gid("guide")
    c = dyad.circle
    _markers(ax, [c], "slider-pin", "pin C1 (pose 1)", marker="s", markersize=9, color=POSE_COLORS[1], zorder=6)
    if task is not None:
        pins = [task.displace(c, 1, k) for k in range(2, len(task) + 1)]
        _markers(ax, pins, "slider-positions", "pin at the other poses", marker="s", markersize=7,
                 color=POSE_COLORS[3], zorder=5)
        _draw_flags(ax, task.poses, 0.12 * task.scale, labels, zorder=7)
    if labels:
        _label(ax, c, "C1")
        u = dyad.guide
        ax.set_title(f"Slider dyad: pin C1 ({format_length(c[0], units)}, {format_length(c[1], units)}), "
                     f"guide at {math.degrees(math.atan2(u[1], u[0])):.1f} deg", fontsize=10)
    return _framed(ax, labels, legend, units)


def _framed(ax: Axes, labels: bool, legend: bool, units: Optional[str]) -> Axes:
    """The picture's frame: axis names, limits around the data
    (:func:`_around_data`) and the legend; returns ``ax``."""
    _around_data(ax, labels, units)
    if legend:
        _legend(ax)
    return ax


def animate_actuator(
    a: burmester.Actuator,
    path: Union[str, Path],
    *,
    frames: int = 60, fps: int = 20, dpi: int = 80,
    width: Optional[float] = None,
    units: Optional[str] = None,
) -> FuncAnimation:
    """Write an animation of a four-bar driven by a linear actuator: the
    cylinder extends (or retracts) from pose 1 through the poses in order
    and back, so the animation loops (``.gif`` or ``.mp4``). The moving
    linkage (gid ``"moving-linkage"``, ``"moving-coupler"``) and the
    cylinder's body and rod (``"moving-actuator-body"``,
    ``"moving-actuator-rod"``) are drawn over the coupler curve, the poses,
    ``Q``'s path (``"point-path"``) and the ground pivot ``G``
    (``"actuator-ground"``); the coupler carries ``Q`` on a bracket ``A Q B``
    when the actuator acts on it; every position is the core's
    (:func:`burmester._scene.actuator_at`). The file is written beside
    ``path`` and moved into place when complete (Ctrl-C leaves none).

    Parameters:
        a: the actuator (:meth:`burmester.SynthesizedFourBar.actuator`,
            :meth:`burmester.ActuatorMap.best_placements`,
            :func:`burmester.design_actuator`).
        path: ``.gif`` (Pillow) or ``.mp4`` (ffmpeg).
        frames: about how many frames from the first pose to the last (2
            to :data:`MAX_FRAMES`; :func:`drive_angles`).
        fps: frames per second (1 to :data:`MAX_FPS`).
        dpi: resolution (1 to :data:`MAX_DPI`).
        width: the cylinder's width (default: 0.06 of its closed length).
        units: the unit of the lengths: on the axes and in the title.

    Returns:
        The matplotlib animation (already saved).

    Raises:
        burmester.AssemblyError: the four-bar has no travel through the
            poses in order (:attr:`burmester.LinkageFigures.feasible`).
        burmester.InvalidInputError: another file type, a folder that does
            not exist, or a count out of range.
        RuntimeError: ``.mp4`` without ffmpeg.
    """
    if not isinstance(a, burmester.Actuator):
        raise TypeError(f"expected a burmester.Actuator, got {type(a).__name__}")
    path, frames, fps, dpi = _animation_target(path, frames, fps, dpi)
    _check_ffmpeg(path)
    sfb = a.linkage
    angles, _ = drive_angles(sfb, frames)
    sequence = np.concatenate([angles, angles[-2:0:-1]])
    scene = _scene.actuator_scene(a, width)
    frames_at = [_scene.actuator_at(a, float(t), scene.width) for t in sequence]
    fig, ax = plt.subplots(figsize=(6.0, 5.0))
    try:
        _draw_static(ax, sfb, scene.linkage, True, True)
        _, xq, yq, _ = a.travel(96)
        (qp,) = ax.plot(xq, yq, ":", color="#d94801", linewidth=1.2, zorder=2, label="Q's path")
        qp.set_gid("point-path")
        _markers(ax, [a.ground], "actuator-ground", "actuator ground pivot G", marker="^", markersize=10,
                 color="black", zorder=9)
        _label(ax, a.ground, "G")
        # The chain A0 A B C0, the coupler A B P (with the bracket A Q B when Q is on it), the cylinder.
        bracket = a.link == "coupler"
        polys = [(np.array(f.position[:4], dtype=float),
                  np.array([f.position.a, f.position.b, f.position.p]
                           + ([f.position.b, f.q, f.position.a] if bracket else [])),
                  f.body, f.rod) for f in frames_at]
        _fit_frames(ax, polys)
        label_axes(ax, units)
        state = "monotone" if a.monotone else "NOT monotone"
        ax.set_title(f"Driven by a cylinder on the {a.link}: {format_length(a.min_length, units)} closed, "
                     f"stroke {format_length(a.stroke, units)}\n{state}, force transmission at least "
                     f"{a.min_transmission_deg:.0f} deg", fontsize=10)
        (chain_art,) = ax.plot([], [], color="#333333", linewidth=2.5, marker="o", markersize=5, zorder=8,
                               gid="moving-linkage")
        patches: List[Polygon] = []
        for k, (gid, style) in enumerate((
            ("moving-coupler", dict(facecolor="#ff7f0e", edgecolor="#b35806", alpha=0.6, zorder=8)),
            ("moving-actuator-body", dict(facecolor="0.35", edgecolor="black", linewidth=0.8, zorder=10)),
            ("moving-actuator-rod", dict(facecolor="#bdbdbd", edgecolor="black", linewidth=0.8, zorder=9)),
        ), start=1):
            patch = Polygon(polys[0][k], closed=True, gid=gid, **style)
            ax.add_patch(patch)
            patches.append(patch)
        tri, body, rod = patches

        def update(i: int) -> List[Artist]:
            chain, coupler, b, r = polys[i]
            chain_art.set_data(chain[:, 0], chain[:, 1])
            tri.set_xy(coupler)
            body.set_xy(b)
            rod.set_xy(r)
            return [chain_art, tri, body, rod]

        anim = FuncAnimation(fig, update, frames=len(polys), interval=1000.0 / fps, blit=False)
        _save_animation(anim, path, fps, dpi)
    finally:
        plt.close(fig)
    return anim


def animate_inverted_slider_crank(
    obj: Union[burmester.InvertedSliderCrank, burmester.SynthesizedInvertedSliderCrank],
    path: Union[str, Path],
    mode: Mode = "open",
    *,
    frames: int = 60, fps: int = 20, dpi: int = 80,
    units: Optional[str] = None,
) -> FuncAnimation:
    """Write an animation of an inverted slider-crank driven by its crank
    (``.gif`` or ``.mp4``): the moving crank and slotted coupler (gid
    ``"moving-linkage"``, its plate to the task's coupler point
    ``"moving-coupler"``), its slot (``"moving-linkage-slot"``) and the
    block turning on the swivel (``"moving-linkage-block"``), over the
    fixed pivots (as :func:`inverted_slider_crank` draws them; every
    position is the core's, :func:`burmester._scene.inverted_scene`).

    A :class:`burmester.SynthesizedInvertedSliderCrank` is driven from pose
    1 through the poses in order and back (the poses, the coupler curve
    beneath; ``mode`` unused: the poses' own); an
    :class:`burmester.InvertedSliderCrank` alone in ``mode`` over its
    crank's range: one turn when the crank turns fully, else from one dead
    position to the other and back (:func:`burmester._scene.inverted_range_angles`).
    The file is written beside ``path`` and moved into place when complete
    (Ctrl-C leaves none, and an existing file as it was).

    Parameters:
        obj: the linkage.
        path: ``.gif`` (Pillow) or ``.mp4`` (ffmpeg).
        mode: the assembly mode of a linkage alone.
        frames: about how many frames from the first pose to the last (a
            linkage alone: over its range), 2 to :data:`MAX_FRAMES`.
        fps: frames per second (1 to :data:`MAX_FPS`).
        dpi: resolution (1 to :data:`MAX_DPI`).
        units: the unit of the lengths: on the axes and in the title.

    Returns:
        The matplotlib animation (already saved).

    Raises:
        burmester.InvalidInputError: a synthesized one without a travel
            through the poses in order in one mode (``.feasible`` is False),
            another file type, a folder that does not exist, a count out of
            range or an unknown mode.
        RuntimeError: ``.mp4`` without ffmpeg.
    """
    if not isinstance(obj, (burmester.InvertedSliderCrank, burmester.SynthesizedInvertedSliderCrank)):
        raise TypeError(f"expected a burmester.InvertedSliderCrank or SynthesizedInvertedSliderCrank, "
                        f"got {type(obj).__name__}")
    path, frames, fps, dpi = _animation_target(path, frames, fps, dpi)
    _check_ffmpeg(path)
    if mode not in ("open", "crossed"):
        raise burmester.InvalidInputError(f"mode must be 'open' or 'crossed', got {mode!r}")
    if isinstance(obj, burmester.SynthesizedInvertedSliderCrank):
        if not obj.feasible:
            raise burmester.InvalidInputError(
                f"the inverted slider-crank meets its poses in modes {obj.modes} and direction "
                f"{obj.direction!r}: it cannot be driven through them in order in one mode; pick a feasible "
                "one (.feasible)"
            )
        angles = _scene.slider_crank_pose_angles(obj, frames, "inverted slider-crank")
        sequence = angles + angles[-2:0:-1]
        mode = obj.modes[0] or "open"
        q = obj.linkage
        what = "driven through the poses"
    else:
        q = obj
        angles = _scene.inverted_range_angles(q, frames)
        sequence = angles if q.turns_fully else angles + angles[-2:0:-1]
        what = "over a crank turn" if q.turns_fully else "between its dead positions"
    scenes = [_scene.inverted_scene(q, t, mode) for t in sequence]
    fig, ax = plt.subplots(figsize=(6.0, 5.0))
    try:
        inverted_slider_crank(obj, sequence[0], mode, labels=False, legend=False,
                              units=units, ax=ax)
        for art in list(ax.get_children()):  # the linkage at the poses: it moves now
            if str(art.get_gid()).startswith(("linkage", "coupler-")) and art.get_gid() != "coupler-curve":
                art.remove()
        # The coupler plate A F P of a synthesized one (P the task's coupler point), else the pin and foot.
        points = [obj.pose_at(t, mode)[:2] for t in sequence] if isinstance(obj, burmester.SynthesizedInvertedSliderCrank) \
            else [None] * len(sequence)
        plates = [np.array([x.crank_joint, x.foot, *([p] if p is not None else [])]) for x, p in zip(scenes, points)]
        polys = [(np.array(_scene.crank_chain(x)), np.array(x.slot), np.array(x.block), plate)
                 for x, plate in zip(scenes, plates)]
        _fit_frames(ax, [*polys, *((np.array(ax_line.get_xydata()),) for ax_line in ax.get_lines()
                                   if ax_line.get_gid() == "coupler-curve")])
        label_axes(ax, units)
        ax.set_title(f"Inverted slider-crank {what} ({mode})\ncrank {format_length(q.crank, units)}, "
                     f"ground {format_length(q.ground, units)}, offset {format_length(q.offset, units)}",
                     fontsize=10)
        # The moving chain, slot, block and plate: drawn at the first frame, moved by each.
        chain_art, slot_art, block_art = _draw_inverted_at(ax, q, sequence[0], mode, "#333333", "moving-linkage",
                                                           zorder=8)
        plate_art = Polygon(plates[0], closed=True, facecolor="#ff7f0e", edgecolor="#b35806", alpha=0.5, zorder=7,
                            gid="moving-coupler")
        ax.add_patch(plate_art)
        anim = _play(fig, path, [chain_art, slot_art, block_art, plate_art], polys, fps, dpi)
    finally:
        plt.close(fig)
    return anim


def _play(fig: Figure, path: Path, arts: Sequence[Union[Line2D, Polygon]],
          frames: Sequence[Sequence[npt.NDArray[np.float64]]], fps: int, dpi: int) -> FuncAnimation:
    """Move each of ``arts`` to its array of each frame (a line's points,
    a polygon's corners) and write the animation (:func:`_save_animation`)."""
    def update(i: int) -> List[Artist]:
        for art, xy in zip(arts, frames[i]):
            if isinstance(art, Polygon):
                art.set_xy(xy)
            else:
                art.set_data(xy[:, 0], xy[:, 1])
        return list(arts)

    anim = FuncAnimation(fig, update, frames=len(frames), interval=1000.0 / fps, blit=False)
    _save_animation(anim, path, fps, dpi)
    return anim
