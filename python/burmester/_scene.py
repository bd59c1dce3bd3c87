"""What a picture shows, built once for both renderers (issue 25): the
matplotlib pictures (:mod:`burmester.plot`) and the CAD export
(:mod:`burmester.export`, DXF and SVG) draw the same scene, each in its own
style.

A scene holds the things to draw in task coordinates, each under the
name of its CAD layer (the table in :mod:`burmester.export`): every point
and polyline comes from the core, computed here and nowhere else. The
choice by pose count (three poses: the poles' triangle and circle; four:
the center-point curve by crank order; five: the Burmester points) is made
here, in :func:`poses_scene` and :func:`curve_scene`, and nowhere else in
the drawing modules.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, List, Literal, NamedTuple, Optional, Sequence, Tuple

import numpy as np
import numpy.typing as npt

from burmester import _counts, _view
from burmester._burmester import (
    Drive, Filemon, Grid, InvalidInputError, SixBar, SynthesizedFourBar, Task, clip_line,
)
from burmester._view import ViewLike
from burmester.taskfile import (
    DEFAULT_GRID, default_circle_view, default_curve_view, default_view, has_pole_triangle,
)

if TYPE_CHECKING:
    from burmester._burmester import Actuator, Method, Mode, SliderCrank, SliderDyad, SynthesizedSliderCrank
    from burmester._burmester import InvertedSliderCrank, SynthesizedInvertedSliderCrank

    Array = npt.NDArray[np.float64]

Point = Tuple[float, float]
Extent = Tuple[float, float, float, float]
Pair = Tuple[int, int]
Segment = Tuple[Point, Point]
Plane = Literal["center", "circle"]

#: The layer of each crank-order class of a curve of four poses (the
#: direction of :meth:`burmester.Task.order_arcs`).
ORDER_LAYERS = {"counterclockwise": "CURVE_CCW", "clockwise": "CURVE_CW", None: "CURVE_ORDER_DEFECT"}


class PosesScene(NamedTuple):
    """A task at a glance: its poses and poles."""

    #: ``"Three"``, ``"Four"`` or ``"Five"`` poses.
    count_word: str
    #: The finite poles, ``((j, k), point)`` (layer ``POLES``).
    poles: List[Tuple[Pair, Point]]
    #: The poles at infinity (a pure translation between two poses).
    at_infinity: List[Pair]
    #: Three poses: the pole triangle and the pole circle are drawn.
    pole_triangle: bool


def poses_scene(task: Task) -> PosesScene:
    """The poses and poles of ``task`` (three to five poses)."""
    poles = [(p.pair, p.point) for p in task.poles if p.point is not None]
    at_infinity = [p.pair for p in task.poles if p.point is None]
    return PosesScene(count_word(len(task)), poles, at_infinity, _counts.of(task).filemon)


def count_word(n: int) -> str:
    """``"Three"``, ``"Four"``, ``"Five"`` (poses), or ``n`` in digits."""
    row = _counts.COUNTS.get(n)
    return str(n) if row is None else row.word.capitalize()


class Construction(NamedTuple):
    """Filemon's construction for a driven dyad in the circle-point plane
    of four poses: its circle point ``C1`` (layer ``DRIVEN_CIRCLE_POINT``),
    the fixed pivot's images ``C'k = D_k1(C0)`` (``FIXED_PIVOT_IMAGES``) and
    the lines through ``C1`` and ``C'k`` clipped to the view (``LINE_k``;
    None where ``C'k`` is ``C1`` or the line misses the view)."""

    c1: Point
    images: List[Point]
    lines: List[Optional[Segment]]


def construction(c1: Point, lines: Sequence[Tuple[Point, Point]], images: Sequence[Point],
                 extent: Extent) -> Construction:
    """A :class:`Construction` from its lines as ``(point, direction)``,
    clipped to ``extent`` (a line of no direction is none)."""
    segments = [clip_line(p, d, extent) if d != (0.0, 0.0) else None for p, d in lines]
    return Construction(c1, list(images), segments)


class CurveScene(NamedTuple):
    """The center- or circle-point plane of four or five poses: what
    :func:`burmester.plot.burmester_plane`,
    :func:`burmester.plot.circle_curve_plane` and
    :func:`burmester.export.burmester_plane` draw, bottom first."""

    plane: Plane
    #: The number of poses.
    n_poses: int
    extent: Extent
    #: ``"center-point curve"``, ``"Burmester points"`` or ``"circle-point
    #: curve (coupler frame at pose 1)"``.
    title: str
    #: Four poses with a driven dyad: the driving pivots (or their circle
    #: points) branch-free with it (``BRANCH_FREE_ARCS``).
    free_arcs: List[Array]
    #: Four poses, center plane: the driven dyad's fixed pivot (``DRIVEN_PIVOT``).
    driven: Optional[Point]
    #: Four poses, circle plane, with a driven dyad: Filemon's construction.
    construction: Optional[Construction]
    #: Four poses: the curve in pieces ``(order, direction, points)`` by the
    #: crank's order class (layers :data:`ORDER_LAYERS`).
    order_arcs: List[Tuple[str, Optional[str], Array]]
    #: Four poses: the points ``Q_jk`` (their circle points ``Q'jk`` in the
    #: circle plane), ``((j, k), point)`` (``COINCIDENCE_POINTS``).
    coincidence: List[Tuple[Pair, Point]]
    #: Five poses: the center-point curves of poses 1-2-3-4 and 1-2-3-5,
    #: ``(which, polylines)`` (``CURVE_1234``, ``CURVE_1235``).
    curves: List[Tuple[str, List[Array]]]
    #: Five poses: the Burmester points' center points (``BURMESTER_POINTS``).
    burmester_points: List[Point]
    #: The center plane: the finite poles, ``((j, k), point)`` (``POLES``).
    poles: List[Tuple[Pair, Point]]

    @property
    def prime(self) -> str:
        """``"'"`` in the circle plane (``Q'jk``), else ``""``."""
        return "'" if self.plane == "circle" else ""


def curve_scene(task: Task, view: Optional[ViewLike], driven: Optional[Point], plane: Plane) -> CurveScene:
    """The :class:`CurveScene` of ``task`` in ``view`` (default:
    :func:`burmester.taskfile.default_curve_view`). Raises the core's typed
    error (``cause == "needs_poses"``) for a task the plane has no curve for
    (the circle plane: four poses; the center plane: four or five), then
    the view's (:mod:`burmester._view`)."""
    if plane == "circle":
        task.circle_point_curve()
    elif _counts.of(task).filemon:
        task.center_point_curve()
    extent = default_curve_view(task) if view is None else _view.extent(view)
    circle = plane == "circle"
    four = _counts.of(task).curves
    arcs: List[Array] = []
    made: Optional[Construction] = None
    if four and driven is not None:
        arcs = list(task.branch_free_arcs(driven, *extent, plane=plane))
        if circle:
            c1 = task.circle_point(driven)
            images = [task.displace(driven, k, 1) for k in range(1, len(task) + 1)]
            made = construction(c1, [(c1, (p[0] - c1[0], p[1] - c1[1])) for p in images], images, extent)
    order_arcs: List[Tuple[str, Optional[str], Array]] = []
    coincidence: List[Tuple[Pair, Point]] = []
    curves: List[Tuple[str, List[Array]]] = []
    points: List[Point] = []
    if four:
        order_arcs = list(task.order_arcs(*extent, plane=plane))
        for q in task.coincidence_points():
            p = q.circle if circle else q.center
            if p is not None:
                coincidence.append((q.pair, p))
        title = "circle-point curve (coupler frame at pose 1)" if circle else "center-point curve"
    else:
        curves = [(which, list(curve.polylines(*extent)))
                  for curve, which in zip(task.burmester_curves(), ("1234", "1235"))]
        points = [center for center, _ in task.burmester_points()]
        title = "Burmester points"
    # In the circle-point plane the poles P1k are the points Q'1k.
    poles = [] if circle else [(p.pair, p.point) for p in task.poles if p.point is not None]
    return CurveScene(plane, len(task), extent, title, arcs, driven if four and not circle else None, made,
                      order_arcs, coincidence, curves, points, poles)


class Position(NamedTuple):
    """A four-bar at one input angle (the core's joints): ``A0``, ``A``,
    ``B``, ``C0`` and the coupler point ``P``."""

    a0: Point
    a: Point
    b: Point
    c0: Point
    p: Point


def position(sfb: SynthesizedFourBar, theta2: float, mode: Mode) -> Position:
    """``sfb`` at input angle ``theta2`` in assembly ``mode``."""
    o2, a, b, o4 = sfb.fourbar.joints(theta2, mode)
    x, y, _ = sfb.pose_at(theta2, mode)
    return Position(o2, a, b, o4, (x, y))


class AtPose(NamedTuple):
    """The linkage at pose k: its input angle, its assembly mode (None: a
    toggle, drawn open) and its :class:`Position` (layer ``LINKAGE_k``)."""

    theta2: float
    mode: Optional[Mode]
    position: Position


class LinkageScene(NamedTuple):
    """A synthesized four-bar at its poses: what
    :func:`burmester.plot.linkage` and :func:`burmester.export.linkage` draw
    (each adds its own coupler curve)."""

    #: The fixed pivots (layer ``PIVOTS``, the ground ``GROUND`` between them).
    a0: Point
    c0: Point
    #: The poses marked (``POSES``): the task's, or those the linkage reaches.
    poses: List[Tuple[float, float, float]]
    #: A pose's flag length: 0.3 of the shortest link.
    flag: float
    #: The linkage at each pose, in order.
    at_poses: List[AtPose]


def linkage_scene(sfb: SynthesizedFourBar, task: Optional[Task]) -> LinkageScene:
    """The :class:`LinkageScene` of ``sfb`` with the poses of ``task`` (default: those it reaches)."""
    at = [AtPose(t, m, position(sfb, t, m or "open")) for t, m in zip(sfb.input_angles, sfb.modes)]
    poses = list(task.poses) if task is not None else [sfb.pose_at(t, m or "open")
                                                      for t, m in zip(sfb.input_angles, sfb.modes)]
    return LinkageScene(sfb.driving[0], sfb.driven[0], poses, 0.3 * min(sfb.fourbar.lengths), at)


class SixBarScene(NamedTuple):
    """A six-bar (the Watt II of a drive): what :func:`burmester.plot.sixbar`
    and :func:`burmester.export.sixbar` draw under the moving links."""

    #: The fixed pivots: the motor's ``D0``, ``A0`` and ``C0`` (``PIVOTS``).
    d0: Point
    a0: Point
    c0: Point
    #: The radius of the motor crank's circle about ``D0`` (``CRANK_CIRCLE``).
    crank_radius: float
    #: The poses (``POSES``): the task's, or the drive's; none without a drive.
    poses: List[Tuple[float, float, float]]
    #: A pose's flag length: 0.3 of the four-bar's shortest link.
    flag: float
    #: The crank angle at each pose (a drive's), in order.
    pose_angles: List[float]


def sixbar_scene(six: SixBar, drive: Optional[Drive], task: Optional[Task] = None) -> SixBarScene:
    """The :class:`SixBarScene` of ``six`` (of ``drive`` when given)."""
    j = six.joints(drive.pose_crank_angles[0] if drive is not None else 0.0)
    poses: List[Tuple[float, float, float]] = []
    if drive is not None:
        poses = list(task.poses if task is not None else drive.task.poses)
    angles = list(drive.pose_crank_angles) if drive is not None else []
    return SixBarScene(j[0], j[3], j[6], six.lengths[1], poses, 0.3 * min(six.motion.lengths), angles)


def conics(filemon: Filemon, extent: Extent) -> List[Tuple[int, str, List[Array]]]:
    """Filemon's three lines transformed into the center-point plane
    (``CONIC_k``): ``(pose, kind, polylines in extent)`` for each, every
    branch; none when every driving pivot is defective."""
    extreme = filemon.extreme_poses
    if extreme is None:
        return []
    return [(pose, conic.kind, list(conic.polylines(*extent))) for pose, conic in zip(extreme, filemon.conics)]


class CenterScene(NamedTuple):
    """The driving crank's center-point plane of three poses: what
    :func:`burmester.plot.center_plane` and :func:`burmester.export.plane`
    draw (each shades the branch map its own way)."""

    grid: Grid
    #: Branch-free driving pivots on the grid (``BRANCH_FREE``).
    free: npt.NDArray[np.bool_]
    #: Branch-free pivots that also meet the limits (``ACCEPTABLE``), when given.
    acceptable: Optional[npt.NDArray[np.bool_]]
    #: The minimum transmission angle, degrees (``TRANSMISSION``), when given.
    transmission: Optional[npt.NDArray[np.float64]]
    #: Every pole, named ``P12``, ``P13``, ``P23`` (None at infinity; ``POLES``).
    poles: List[Tuple[str, Optional[Point]]]
    #: Three finite poles: the pole triangle and circle are drawn
    #: (``POLE_TRIANGLE``, ``POLE_CIRCLE``).
    pole_triangle: bool
    #: The driven crank's fixed pivot ``C0`` (``DRIVEN_PIVOT``).
    c0: Point


def center_scene(filemon: Filemon, view: Optional[ViewLike], samples: Optional[Sequence[Any]], method: Method,
                 free: Optional[npt.ArrayLike], acceptable: Optional[npt.ArrayLike],
                 transmission: Optional[npt.ArrayLike], side: int = DEFAULT_GRID) -> CenterScene:
    """The :class:`CenterScene` of ``filemon`` over ``view`` (a Grid, four
    numbers with ``side`` samples along the longer side, or None: the default
    view), ``samples = (nx, ny)`` when given, else a given ``free`` map's
    shape over four numbers; the branch map of ``method`` unless ``free`` is
    given. Each given map must have the grid's shape (InvalidInputError)."""
    if free is not None and samples is None and not isinstance(view, Grid):
        shape = np.shape(free)
        if len(shape) != 2:
            raise InvalidInputError(f"free must be a 2-D array (ny, nx), got shape {shape}")
        samples = (shape[1], shape[0])
    g = _view.view_grid(view, samples, lambda: default_view(filemon, side), side)
    given = _view.on_grid("free", free, g)
    free_b = (filemon.branch_map(g, method=method) if given is None else given).astype(bool)
    acc = _view.on_grid("acceptable", acceptable, g)
    trans = _view.on_grid("transmission", transmission, g)
    task = filemon.task
    poles = [(f"P{i}{j}", p.point) for p, (i, j) in ((p, p.pair) for p in task.poles)]
    return CenterScene(g, free_b, None if acc is None else acc.astype(bool),
                       None if trans is None else np.asarray(trans, dtype=float), poles,
                       has_pole_triangle(task), filemon.driven_center)


class CircleScene(NamedTuple):
    """The driving crank's circle-point plane of three poses (the coupler
    frame at pose 1): what :func:`burmester.plot.circle_plane` and
    :func:`burmester.export.plane` (``plane="circle"``) draw."""

    extent: Extent
    #: Filemon's sectors about ``C1``, ``(start, end, branch-free)``
    #: (:attr:`burmester.Filemon.sectors`; ``BRANCH_FREE``).
    sectors: List[Tuple[float, float, bool]]
    #: A radius about ``C1`` beyond every corner of the view: a sector's
    #: wedge of this radius covers its part of the view.
    radius: float
    #: Filemon's construction: ``C1``, ``C'k`` and the lines through them.
    construction: Construction
    #: The middle pose's line (drawn dashed), if any.
    middle: Optional[int]
    #: The image poles ``P12, P13, P'23`` (``IMAGE_POLES``); none with a pole at infinity.
    image_poles: List[Point]


def circle_scene(filemon: Filemon, view: Optional[ViewLike]) -> CircleScene:
    """The :class:`CircleScene` of ``filemon`` in ``view`` (default:
    :func:`burmester.taskfile.default_circle_view`)."""
    extent = default_circle_view(filemon) if view is None else _view.extent(view)
    c1 = filemon.driven_circle
    corners = [(x, y) for x in extent[:2] for y in extent[2:]]
    radius = 2.0 * max(math.hypot(x - c1[0], y - c1[1]) for x, y in corners) + 1.0
    made = construction(c1, filemon.all_lines, filemon.fixed_pivot_images, extent)
    task = filemon.task
    # A task with a pure translation between two poses has no image poles.
    images = list(task.image_poles()) if has_pole_triangle(task) else []
    return CircleScene(extent, list(filemon.sectors), radius, made, filemon.middle_pose, images)


# ---------------------------------------------------------------------------
# Slider linkages (issue 27)


class SliderScene(NamedTuple):
    """A slider-crank at one crank angle: the crank pivot, the crank tip
    and the slider pin, the guide drawn as a line over the slider's limit
    positions with a margin (layer ``GUIDE``), and the slider as a block
    along the guide around its pin (layer ``SLIDER``)."""

    pivot: Point
    crank_joint: Point
    slider_joint: Point
    #: The guide's two ends.
    guide: Segment
    #: The block's four corners.
    block: List[Point]


def slider_scene(sc: "SliderCrank", theta2: float, mode: "Mode") -> SliderScene:
    """The slider-crank ``sc`` at ``theta2`` in ``mode`` (AssemblyError where
    the loop does not close there)."""
    pivot, a, b = sc.joints(theta2, mode)
    (_, lo), (_, hi) = sc.limits(mode)
    size = sc.crank + sc.coupler
    margin = 0.15 * size
    guide = (sc.guide_point(lo - margin), sc.guide_point(hi + margin))
    (ux, uy), (nx, ny) = sc.guide, sc.guide_normal
    w, h = 0.09 * size, 0.05 * size
    block = [(b[0] + su * w * ux + sn * h * nx, b[1] + su * w * uy + sn * h * ny)
             for su, sn in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    return SliderScene(pivot, a, b, guide, block)


def slider_crank_pose_angles(s: "SynthesizedSliderCrank | SynthesizedInvertedSliderCrank", frames: int,
                             what: str = "slider-crank") -> List[float]:
    """About ``frames`` crank angles from pose 1 through the poses in order
    to the last, the poses' own angles among them (the drive of a picture
    or an animation); InvalidInputError (naming the linkage as ``what``)
    for a linkage without a travel."""
    stops = s.travel_stops
    if stops is None:
        raise InvalidInputError(
            f"the {what} does not pass its poses in order in one mode (a branch, order or "
            "circuit defect), so it has no travel to draw; pick a feasible one (.feasible)"
        )
    angles: List[float] = []
    total = abs(stops[-1] - stops[0]) or 1.0
    for t0, t1 in zip(stops[:-1], stops[1:]):
        n = max(2, int(round(frames * abs(t1 - t0) / total)))
        angles.extend(float(t) for t in np.linspace(t0, t1, n)[:-1])
    angles.append(float(stops[-1]))
    return angles


def slider_crank_angle(sc: "SliderCrank", theta2: Optional[float]) -> float:
    """The crank angle a slider-crank alone is drawn at: ``theta2`` when
    given, else 0 when the crank turns fully, else the middle of its first
    arc (:attr:`burmester.SliderCrank.input_range`)."""
    if theta2 is not None:
        return float(theta2)
    arcs = sc.input_range
    return 0.0 if not arcs else arcs[0][0] + 0.5 * ((arcs[0][1] - arcs[0][0]) % (2 * math.pi))


class CrankAtPose(NamedTuple):
    """A synthesized crank-driven linkage (a slider-crank, an inverted one)
    at pose k: its crank angle, its mode (None: a toggle, drawn in the first
    pose's mode), its kind's scene there (:class:`SliderScene`,
    :class:`InvertedScene`) and the coupler point (the coupler plate is the
    crank pin, the coupler's other joint and this point)."""

    theta2: float
    mode: Optional["Mode"]
    scene: Any
    p: Point


class SynthesizedCrankScene(NamedTuple):
    """A synthesized crank-driven linkage at its poses: what
    :func:`burmester.plot.slider_crank` and :func:`burmester.export.slider_crank`
    (or their inverted kin) draw. A slider-crank's guide (layer ``GUIDE``)
    is the first pose's scene's."""

    #: The mode of pose 1 (``"open"`` at a toggle): the coupler path's.
    mode: "Mode"
    at_poses: List[CrankAtPose]
    #: The poses the linkage reaches (``POSES``), and a flag's length.
    poses: List[Tuple[float, float, float]]
    flag: float


def _synthesized_crank_scene(s: Any, scene_at: Any, size: float) -> SynthesizedCrankScene:
    """The :class:`SynthesizedCrankScene` of ``s``, its kind's scene at an
    angle ``scene_at(linkage, theta2, mode)`` and its size (the flags are
    0.12 of it)."""
    first: "Mode" = s.modes[0] or "open"
    at: List[CrankAtPose] = []
    poses: List[Tuple[float, float, float]] = []
    for t, m in zip(s.input_angles, s.modes):
        x, y, a = s.pose_at(t, m or first)
        at.append(CrankAtPose(t, m, scene_at(s.linkage, t, m or first), (x, y)))
        poses.append((x, y, a))
    return SynthesizedCrankScene(first, at, poses, 0.12 * size)


def synthesized_slider_scene(s: "SynthesizedSliderCrank") -> SynthesizedCrankScene:
    """The :class:`SynthesizedCrankScene` of a slider-crank (its scenes :class:`SliderScene`)."""
    return _synthesized_crank_scene(s, slider_scene, s.linkage.crank + s.linkage.coupler)


def slider_dyad_guide(dyad: "SliderDyad", task: Optional[Task] = None) -> Segment:
    """The stretch of a slider dyad's guide to draw: over the pin's
    positions at the poses of ``task`` (:meth:`burmester.Task.displace` of
    the pin), 15 % of their span beyond each end; without a task, or where
    the pin stays put, the pin's distance from the origin (at least 1) each
    way."""
    c = dyad.circle
    u = dyad.guide
    along = [0.0]
    if task is not None:
        for k in range(2, len(task) + 1):
            p = task.displace(c, 1, k)
            along.append((p[0] - c[0]) * u[0] + (p[1] - c[1]) * u[1])
    lo, hi = min(along), max(along)
    span = hi - lo
    if not span > 0.0:
        half = max(1.0, math.hypot(*c))
        lo, hi, span = -half, half, 0.0
    lo, hi = lo - 0.15 * span, hi + 0.15 * span
    return ((c[0] + lo * u[0], c[1] + lo * u[1]), (c[0] + hi * u[0], c[1] + hi * u[1]))


# ---------------------------------------------------------------------------
# The inverted slider-crank (issue 27): a crank whose coupler's slot slides
# through a block pivoted on the ground at the swivel.


class InvertedScene(NamedTuple):
    """An inverted slider-crank at one crank angle (the core's
    :meth:`burmester.InvertedSliderCrank.joints` and ``solve``): the crank
    pivot ``A0``, the crank pin ``A``, the swivel ``S`` and the slot's foot
    ``F`` (the foot of the perpendicular from ``A`` to the slot's line), the
    slot's unit direction; the slot drawn from beyond the foot to beyond the
    swivel's farthest slot position in the mode (layer ``SLOT``), and the
    block on the swivel, along the slot (layer ``BLOCK``)."""

    pivot: Point
    crank_joint: Point
    swivel: Point
    foot: Point
    #: The slot's unit direction (the coupler angle ``theta3``), its two
    #: ends (on the line through ``F`` and ``S``) and the block's four
    #: corners (centred on ``S``).
    direction: Point
    slot: Segment
    block: List[Point]


def crank_chain(s: "SliderScene | InvertedScene") -> List[Point]:
    """The chain of joints of a crank-driven linkage's scene: ``A0 A B``
    of a slider-crank, ``A0 A F`` of an inverted one (the coupler to the
    slot)."""
    return [s.pivot, s.crank_joint, s.slider_joint if isinstance(s, SliderScene) else s.foot]


#: The slot's margin beyond the foot and the swivel's extreme positions, and
#: the block's half length and half width, of crank plus ground.
SLOT_MARGIN, BLOCK_HALF_LENGTH, BLOCK_HALF_WIDTH = 0.08, 0.06, 0.03


def inverted_scene(q: "InvertedSliderCrank", theta2: float, mode: "Mode") -> InvertedScene:
    """The inverted slider-crank ``q`` at ``theta2`` in ``mode``
    (AssemblyError where the loop does not close there)."""
    a0, a, s, f = q.joints(theta2, mode)
    c = q.solve(theta2, mode)
    ux, uy = math.cos(c.theta3), math.sin(c.theta3)
    (lo, hi) = q.slot_limits(mode)
    size = q.crank + q.ground
    pad = SLOT_MARGIN * size
    t0, t1 = min(lo[1], hi[1], 0.0) - pad, max(lo[1], hi[1], 0.0) + pad
    slot = ((f[0] + t0 * ux, f[1] + t0 * uy), (f[0] + t1 * ux, f[1] + t1 * uy))
    w, h = BLOCK_HALF_LENGTH * size, BLOCK_HALF_WIDTH * size
    block = [(s[0] + su * w * ux - sn * h * uy, s[1] + su * w * uy + sn * h * ux)
             for su, sn in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    return InvertedScene(a0, a, s, f, (ux, uy), slot, block)


def inverted_crank_angle(q: "InvertedSliderCrank", theta2: Optional[float]) -> float:
    """The crank angle an inverted slider-crank alone is drawn at:
    ``theta2`` when given, else the crank pointing away from the swivel
    (inside its range always: the pin is then farthest from the swivel)."""
    if theta2 is not None:
        return float(theta2)
    return math.atan2(q.pivot[1] - q.swivel[1], q.pivot[0] - q.swivel[0])


def inverted_range_angles(q: "InvertedSliderCrank", frames: int) -> List[float]:
    """About ``frames`` crank angles over the crank's whole range: one turn
    from the angle :func:`inverted_crank_angle` draws at when the crank
    turns fully (the last frame one step short of the first), else from one
    dead position to the other (:attr:`burmester.InvertedSliderCrank.input_range`)."""
    arcs = q.input_range
    if not arcs:
        t = inverted_crank_angle(q, None)
        return [float(v) for v in t + np.linspace(0.0, 2.0 * math.pi, frames + 1)[:-1]]
    lo, hi = arcs[0]
    span = (hi - lo) % (2.0 * math.pi)
    return [float(v) for v in lo + np.linspace(0.0, span, frames)]


def synthesized_inverted_scene(s: "SynthesizedInvertedSliderCrank") -> SynthesizedCrankScene:
    """The :class:`SynthesizedCrankScene` of an inverted slider-crank (its
    scenes :class:`InvertedScene`)."""
    return _synthesized_crank_scene(s, inverted_scene, s.linkage.crank + s.linkage.ground)


# ---------------------------------------------------------------------------
# The linear actuator (issue 27)

#: How much of the closed length the cylinder's body takes (the rest: the rod's eye).
BODY_SHARE = 0.85
#: How far the piston stays inside the body at full extension, as a share
#: of the closed length.
PISTON_OVERLAP = 0.05
#: The cylinder's width by default, of its closed length.
CYLINDER_WIDTH = 0.06


def cylinder(ground: Sequence[float], q: Sequence[float], closed: float, stroke: float,
             width: float) -> Tuple["Array", "Array"]:
    """``(body, rod)``: the actuator from ``ground`` to ``q`` as two coaxial
    rectangles (closed polygons of 5 points): the body from the ground
    pivot, :data:`BODY_SHARE` of the ``closed`` length long and ``width``
    wide; the rod from ``q`` back into the body, long enough to stay
    :data:`PISTON_OVERLAP` of the closed length inside it at full extension
    (``stroke`` beyond closed), 0.45 ``width`` wide."""
    g = np.asarray(ground, dtype=float)
    p = np.asarray(q, dtype=float)
    d = p - g
    s = float(np.hypot(*d))
    u = d / s
    n = np.array([-u[1], u[0]])
    body = BODY_SHARE * closed
    rod = min(stroke + (1.0 - BODY_SHARE + PISTON_OVERLAP) * closed, s)

    def rect(a: "Array", b: "Array", w: float) -> "Array":
        h = 0.5 * w * n
        return np.array([a + h, b + h, b - h, a - h, a + h])

    return rect(g, g + u * body, width), rect(p - u * rod, p, 0.45 * width)


class ActuatorAt(NamedTuple):
    """An actuator-driven four-bar at one input angle: the four-bar's
    :class:`Position`, the actuator's moving point ``Q`` and length, and
    its cylinder (layers ``ACTUATOR_BODY``, ``ACTUATOR_ROD``;
    :func:`cylinder`)."""

    theta2: float
    position: Position
    q: Point
    length: float
    body: "Array"
    rod: "Array"


def actuator_at(a: "Actuator", theta2: float, width: float) -> ActuatorAt:
    """``a`` at input angle ``theta2`` (the mode of its linkage's pose 1),
    its cylinder ``width`` wide: the core's joints
    (:meth:`burmester.FourBar.joints`, :meth:`burmester.Actuator.at`)."""
    sfb = a.linkage
    q, s = a.at(theta2)
    body, rod = cylinder(a.ground, q, a.min_length, a.stroke, width)
    return ActuatorAt(theta2, position(sfb, theta2, sfb.modes[0] or "open"), q, s, body, rod)


class ActuatorScene(NamedTuple):
    """A four-bar driven by a linear actuator, at its poses: what
    :func:`burmester.actuators.draw_actuator`,
    :func:`burmester.actuators.animate` and
    :func:`burmester.export.actuator` draw (the four-bar as
    :class:`LinkageScene`)."""

    linkage: LinkageScene
    #: The actuator's ground pivot ``G`` (layer ``PIVOTS``).
    ground: Point
    #: ``"coupler"``, ``"crank"`` or ``"rocker"``: the link ``Q`` is on.
    link: str
    #: The cylinder's width.
    width: float
    #: The actuator at each pose, in order.
    at_poses: List[ActuatorAt]


def actuator_scene(a: "Actuator", width: Optional[float] = None) -> ActuatorScene:
    """The :class:`ActuatorScene` of ``a``, its cylinder ``width`` wide
    (default :data:`CYLINDER_WIDTH` of its closed length)."""
    if width is None and a.actuator_width > 0.0:  # the strut's diameter, as its clearance took it
        width = a.actuator_width
    w = CYLINDER_WIDTH * a.min_length if width is None else float(width)
    at = [actuator_at(a, t, w) for t in a.linkage.input_angles]
    return ActuatorScene(linkage_scene(a.linkage, None), a.ground, a.link, w, at)
