"""Type stubs and documentation of the native core, ``burmester._burmester``.

Angles are in radians, counter-clockwise, absolute (measured from the fixed
+x axis), except where a name ends in ``_deg``. Points are ``(x, y)``
tuples. Array arguments accept anything NumPy can turn into a float64
array, of any shape; array results have the shape of the input.

One naming rule holds throughout: a **property** is a value the object
holds or derives without arguments and that cannot fail; anything that
takes an argument, can fail or does real work is a **method**.

Every class is immutable and pickles to an equal object (so tasks, Filemon
constructions and maps can go to worker processes).
"""

from typing import (
    Any, Callable, Iterator, Literal, Optional, Sequence, Tuple, TypedDict, Union, final, overload,
)

import numpy as np
import numpy.typing as npt
from typing_extensions import Unpack
from typing import type_check_only

__all__ = [
    "Actuator",
    "ActuatorMap",
    "AssemblyError",
    "BurmesterError",
    "DegenerateError",
    "InvalidInputError",
    "Configuration",
    "Conic",
    "CoincidencePoint",
    "Cubic",
    "CurveDyad",
    "DesignLimits",
    "Drive",
    "DriveError",
    "DriveMap",
    "Filemon",
    "FourBar",
    "Grid",
    "LinkageFigures",
    "Pair",
    "PairMap",
    "Pivot",
    "Pole",
    "SixBar",
    "SliderFilemon",
    "SolutionMap",
    "SynthesizedFourBar",
    "Task",
    "clip_line",
    "slider_branch_free_arcs",
    "slider_curve_branch",
    "unit_time_ratio_crank_rocker",
    "_atlas_tile",
    "Space",
    "Design",
    "NearMiss",
    "DesignReport",
    "_design",
    "_design_plan",
    "_design_from_atlas",
    "__version__",
    "SliderConfiguration",
    "SliderCrank",
    "SynthesizedSliderCrank",
    "InvertedSlider",
    "SliderDyad",
    "InvertedConfiguration",
    "InvertedSliderCrank",
    "SynthesizedInvertedSliderCrank",
    "SliderPivot",
]

__version__: str

Point = Tuple[float, float]
Pose = Tuple[float, float, float]
Line = Tuple[Point, Point]
Extent = Tuple[float, float, float, float]
#: A grid's six numbers ``(xmin, xmax, ymin, ymax, nx, ny)``: every
#: grid-taking method takes a :class:`Grid`, this tuple, or the six numbers
#: one by one.
GridTuple = Tuple[float, float, float, float, int, int]
Mode = Literal["open", "crossed"]
Method = Literal["conic", "direct", "simulate"]
BranchClass = Literal["free", "defective", "boundary"]
Direction = Literal["ccw", "cw", "none"]
InputRequirement = Literal["any", "crank", "rocker"]
RankBy = Literal["balanced", "transmission", "compact", "pareto", "margin"]
GrashofType = Literal[
    "crank-rocker", "double-crank", "rocker-crank", "double-rocker", "triple-rocker", "change-point"
]
FloatArray = npt.NDArray[np.float64]
BoolArray = npt.NDArray[np.bool_]
ArrayLike = Union[npt.ArrayLike, Sequence[float]]
#: ``progress(done_rows, total_rows)``: called from the calling thread while
#: a sweep runs (the GIL released in between); an exception it raises stops
#: the sweep and is raised by the call.
Progress = Callable[[int, int], object]

class LimitOptions(TypedDict, total=False):
    """The limits keywords of the maps and drives (each may be left out):
    ``limits=DesignLimits(...)``, or its keywords ``min_transmission_deg``
    (default 30) and ``max_link_ratio`` (default 10), not both."""

    limits: Optional[DesignLimits]
    min_transmission_deg: Optional[float]
    max_link_ratio: Optional[float]

class DriveMapOptions(LimitOptions, total=False):
    """The limits keywords and the constraints: the fixed pivot inside
    ``base_plate`` (a simple polygon; default: anywhere), the moving links,
    as capsules ``link_width`` wide (default 0.0), clear of ``obstacles``
    (convex polygons) at ``travel_samples`` input angles of the travel
    (default 64)."""

    base_plate: Optional[Sequence[Point]]
    obstacles: Optional[Sequence[Sequence[Point]]]
    link_width: float
    travel_samples: int

class _DriveKeywords(TypedDict, total=False):
    """A drive's own keywords: ``swing_margin_deg`` (default 0.0), the
    rocker's swing extended at each end, and ``max_time_ratio`` (default
    None: no limit)."""

    swing_margin_deg: float
    max_time_ratio: Optional[float]

class DriveOptions(DriveMapOptions, _DriveKeywords, total=False):
    """The keywords of the drives (:meth:`SynthesizedFourBar.drive_map` and
    the others): the limits but ``input``, the constraints and the drive's
    own."""

class ClassicDriveOptions(LimitOptions, _DriveKeywords, total=False):
    """The keywords of :meth:`SynthesizedFourBar.classic_drive`: the limits
    but ``input`` and the drive's own."""

class ActuatorMapOptions(LimitOptions, total=False):
    """The keywords of the actuator placements
    (:meth:`SynthesizedFourBar.actuator_map`): the limits but ``input`` (the
    actuator drives), ``base_plate`` (the ground pivot inside it) and
    ``link_width`` (the links' width in the strut's clearance)."""

    base_plate: Optional[Sequence[Point]]
    link_width: float

class MapOptions(DriveMapOptions, total=False):
    """The map option keywords of the solution maps, the pair map and the
    atlas: those of :class:`DriveMapOptions` and ``input`` (``"any"``, the
    default, ``"crank"`` or ``"rocker"``; one of the limits' keywords)."""

    input: Optional[InputRequirement]

# ---------------------------------------------------------------------------
# Errors

class BurmesterError(ValueError):
    """Base of every error raised by burmester (a ``ValueError``).

    Every instance carries ``cause``, the reason in snake case (for example
    ``"not_finite"``, ``"out_of_reach"``, ``"at_infinity"``,
    ``"needs_poses"``), and one attribute per field of the core's error
    (for example ``name`` and ``value``; ``dir_x`` and ``dir_y``, the
    direction of an answer at infinity). The message says what to change.
    """

    cause: str
    def __getattr__(self, name: str) -> Any:
        """The error's fields (which depend on its ``cause``)."""

class InvalidInputError(BurmesterError):
    """A number or name passed in is not acceptable: NaN, infinite, zero or
    negative length, an int too large for a float, a negative or too large
    count or index, a ragged array, a number out of the supported range, an
    unknown name, a method called on a task of the wrong number of poses
    (``cause == "needs_poses"``). The message says which and what to pass.

    An argument of the wrong type (a string, ``None``, a complex number where
    a real one goes) raises :class:`TypeError` instead."""

class AssemblyError(BurmesterError):
    """The linkage cannot be assembled as asked: the loop does not close at
    that input angle (``cause == "out_of_reach"``), never closes for those
    lengths (``"never_closes"``), or the position is indeterminate."""

class DegenerateError(BurmesterError):
    """The geometry is degenerate: an answer lies at infinity
    (``cause == "at_infinity"``, with its unit direction ``dir_x``,
    ``dir_y``; for example a center point on the pole circle), or the task
    has no unique answer (``"undefined"``, ``"coincident_poses"``, ...)."""

class DriveError(BurmesterError):
    """A six-bar cannot be built as asked, or a linkage cannot be driven
    from a motor by an added dyad. ``cause`` says why: ``"no_travel"`` (the
    linkage does not pass its poses in order), ``"travel_too_large"`` (its
    input turns through 180 degrees or more with the margins: no
    crank-rocker swings that far), ``"outside_input_range"`` (the margins
    take the input past a dead position), ``"not_a_crank_rocker"`` (no drive
    with its crank pivot there), ``"no_acceptable_drive"`` (none searched
    meets the limits; with ``searched``, ``valid``,
    ``best_transmission_deg`` and ``min_transmission_deg``),
    ``"pivot_mismatch"``, ``"toggle_joints"``."""

# ---------------------------------------------------------------------------
# geom

@final
class Grid:
    """A grid of ``nx`` by ``ny`` sample points at cell centers over the
    rectangle ``xmin <= x <= xmax``, ``ymin <= y <= ymax``:
    ``x_i = xmin + (i + 0.5) dx`` and ``y_j = ymin + (j + 0.5) dy``.

    Maps over a grid have shape ``(ny, nx)``, row ``j`` for ``y_j``, so
    that ``plt.imshow(m, origin="lower", extent=grid.extent)`` shows them
    the right way up.

    Raises :class:`InvalidInputError` for non-finite bounds, ``xmin >= xmax``
    or ``ymin >= ymax`` (``cause == "viewport"``), and for ``nx`` or ``ny``
    below 1 or more than ``2^32`` samples in all (``"grid_size"``).
    """

    def __new__(cls, xmin: float, xmax: float, ymin: float, ymax: float, nx: int, ny: int) -> Grid: ...
    @property
    def xmin(self) -> float:
        """Left edge."""
    @property
    def xmax(self) -> float:
        """Right edge."""
    @property
    def ymin(self) -> float:
        """Bottom edge."""
    @property
    def ymax(self) -> float:
        """Top edge."""
    @property
    def nx(self) -> int:
        """Samples per row."""
    @property
    def ny(self) -> int:
        """Rows."""
    @property
    def dx(self) -> float:
        """The spacing of the columns, ``(xmax - xmin) / nx``."""
    @property
    def dy(self) -> float:
        """The spacing of the rows, ``(ymax - ymin) / ny``."""
    @property
    def extent(self) -> Extent:
        """``(xmin, xmax, ymin, ymax)``, the order ``imshow`` takes."""
    @property
    def shape(self) -> Tuple[int, int]:
        """``(ny, nx)``, the shape of a map over the grid."""
    @property
    def size(self) -> int:
        """``nx * ny``."""
    def cell_centers(self) -> Tuple[FloatArray, FloatArray]:
        """``(xs, ys)``: the sample coordinates of the columns (length
        ``nx``) and of the rows (length ``ny``), exactly those the maps use."""
    def point(self, j: int, i: int) -> Point:
        """The sample ``[j, i]``: ``(x_i, y_j)``. Raises
        :class:`InvalidInputError` outside the grid."""
    def nearest(self, point: Point) -> Tuple[int, int]:
        """The index ``(j, i)`` of the sample nearest to a point (clamped to
        the grid). Raises :class:`InvalidInputError` for a non-finite point."""
    def __eq__(self, other: object, /) -> bool: ...
    def __getnewargs__(self) -> Tuple[float, float, float, float, int, int]: ...

@final
class Conic:
    """A conic ``A x^2 + B x y + C y^2 + D x + E y + F = 0``; its value is
    defined up to a positive factor, so its sign tells the side."""

    def __new__(cls, a: float, b: float, c: float, d: float, e: float, f: float) -> Conic: ...
    @property
    def coefficients(self) -> Tuple[float, float, float, float, float, float]:
        """``(A, B, C, D, E, F)`` in the fixed frame."""
    @property
    def kind(self) -> Literal["ellipse", "hyperbola", "parabola", "degenerate"]:
        """The kind (``B^2 - 4AC`` within a relative 1e-12 of zero is a parabola)."""
    @property
    def center(self) -> Optional[Point]:
        """The center, if unique (not for parabolas)."""
    @property
    def axis_angle(self) -> float:
        """The direction of a principal axis, in (-pi/2, pi/2] (the other is at
        right angles)."""
    @property
    def asymptotes(self) -> Optional[Tuple[Point, Point, Point]]:
        """For a hyperbola: ``(center, direction1, direction2)``."""
    def evaluate(self, point: Point) -> float:
        """The value at a point (zero on the curve), up to a positive factor;
        finite for every finite point (far points are evaluated scaled)."""
    def __call__(self, point: Point) -> float:
        """:meth:`evaluate`."""
    def evaluate_many(self, points: ArrayLike) -> FloatArray:
        """The values at an array of points of shape ``(..., 2)``."""
    def side(self, point: Point) -> int:
        """The sign of the value: 1, -1 or 0."""
    def distance(self, point: Point) -> float:
        """First-order distance to the curve, ``|q| / |grad q|``."""
    def polylines(
        self, xmin: float, xmax: float, ymin: float, ymax: float, tolerance: Optional[float] = None
    ) -> list[FloatArray]:
        """The curve clipped to the viewport, as arrays of shape ``(n, 2)``:
        each branch separately, never joined across infinity, the parts near
        the asymptotes included. ``tolerance`` is the largest chord error
        (default: a thousandth of the viewport's diagonal)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...
    @staticmethod
    def _from_parts(
        q: Sequence[float], origin: Point, scale: float, known: Optional[Point]
    ) -> Conic:
        """Rebuilds a conic from its exact stored form (for pickling)."""

@final
class Cubic:
    """A plane cubic curve ``f(x, y) = c00 + c10 x + c01 y + c20 x^2 + c11 x y
    + c02 y^2 + c30 x^3 + c21 x^2 y + c12 x y^2 + c03 y^3 = 0``: the
    center-point and circle-point curves of four poses
    (:meth:`Task.center_point_curve`). Its value is defined up to a positive
    factor, so its sign tells the side. It is stored in a local frame with
    its largest coefficient 1, so no evaluation overflows."""

    def __new__(cls, coefficients: Sequence[float]) -> Cubic:
        """A cubic from its ten coefficients ``(c00, c10, c01, c20, c11, c02,
        c30, c21, c12, c03)`` in the fixed frame; a conic or a line (zero
        higher coefficients) is accepted. Raises :class:`InvalidInputError`
        for a non-finite coefficient or no curve (every coefficient but
        ``c00`` zero), ``TypeError`` for another count than ten."""
    @property
    def coefficients(self) -> Tuple[float, ...]:
        """The ten coefficients in the fixed frame, in the order of the
        constructor (exact from the poses for a Burmester curve, up to a
        positive factor; they may overflow for a curve far from the origin)."""
    @property
    def degree(self) -> int:
        """3, or less when the higher coefficients vanish (within a relative 1e-12)."""
    @property
    def is_circular(self) -> bool:
        """Whether it passes through the circular points at infinity (the
        Burmester curves do)."""
    @property
    def asymptotic_directions(self) -> list[Point]:
        """The real asymptotic directions (unit vectors): one for a circular
        cubic, up to three in general."""
    def evaluate(self, point: Point) -> float:
        """The value at a point (zero on the curve), up to a positive factor;
        finite for every finite point (far points are evaluated scaled).
        Raises :class:`InvalidInputError` for a non-finite point."""
    def __call__(self, point: Point) -> float:
        """:meth:`evaluate`."""
    def gradient(self, point: Point) -> Point:
        """The gradient of the value at a point (same factor as :meth:`evaluate`)."""
    def distance(self, point: Point) -> float:
        """First-order distance to the curve, ``|f| / |grad f|`` (zero on
        the curve, infinite where the gradient vanishes off it)."""
    def intersect_line(self, point: Point, direction: Point) -> list[Point]:
        """The points where the line ``point + t * direction`` meets the
        curve (up to three, in the order of ``t``); none for a line that is a
        component of the curve."""
    def polylines(
        self, xmin: float, xmax: float, ymin: float, ymax: float, tolerance: Optional[float] = None
    ) -> list[FloatArray]:
        """Every component of the curve that crosses the viewport (ovals and
        unbounded branches, found exactly, none missed), as arrays of shape
        ``(n, 2)`` whose vertices lie on the curve to rounding; a component
        wholly in view is one closed polyline (last point equal to the
        first). ``tolerance`` is the largest chord error (default: a
        thousandth of the viewport's diagonal; 1e-9 to 1 times the
        diagonal)."""
    def _repr_png_(self) -> Optional[bytes]:
        """The picture Jupyter shows (see :mod:`burmester._display`): every
        component in the frame the cubic is kept in; PNG bytes, or None
        when matplotlib is not installed."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...
    @staticmethod
    def _from_parts(coefficients: Sequence[float], origin: Point, scale: float) -> Cubic:
        """Rebuilds a cubic from its exact stored form (for pickling)."""

def clip_line(point: Point, direction: Point, extent: Extent) -> Optional[Tuple[Point, Point]]:
    """The part of the infinite line ``point + t * direction`` inside the
    rectangle ``extent = (xmin, xmax, ymin, ymax)``, as its two ends, or
    None when it misses the rectangle (or the direction is zero). Raises
    :class:`InvalidInputError` for an empty or inverted rectangle."""

# ---------------------------------------------------------------------------
# linkage

@final
class Configuration:
    """One solved position of a four-bar (from :meth:`FourBar.configuration`)."""

    @property
    def theta2(self) -> float:
        """Input (crank) angle, as given."""
    @property
    def theta3(self) -> float:
        """Coupler angle, in (-pi, pi]."""
    @property
    def theta4(self) -> float:
        """Output (rocker) angle, in (-pi, pi]."""
    @property
    def mode(self) -> Mode:
        """The assembly mode asked for."""
    @property
    def toggle(self) -> bool:
        """True at a toggle (dead) position, where both modes coincide."""
    @property
    def transmission_angle(self) -> float:
        """The acute angle between coupler and rocker, in [0, pi/2] radians."""
    @property
    def coupler_rocker_angle(self) -> float:
        """theta4 - theta3 wrapped into (-pi, pi]; its sign is the mode."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...

@final
class FourBar:
    """A planar four-bar linkage.

    The ground link runs from the input pivot ``O2`` to the output pivot
    ``O4``; the crank (input) turns about ``O2``, the rocker (output) about
    ``O4``, and the coupler joins their tips. The loop is::

        L2 e^{i theta2} + L3 e^{i theta3} - L1 e^{i theta1} - L4 e^{i theta4} = 0

    The lengths go **by keyword only** (books order the four links
    differently): ``FourBar(ground=..., crank=..., coupler=..., rocker=...)``;
    positional lengths raise :class:`TypeError`.

    The two assembly modes are named by the sign of ``sin(theta4 - theta3)``:
    ``"open"`` where it is positive, ``"crossed"`` where it is negative.

    Raises :class:`InvalidInputError` for a zero, negative, NaN or infinite
    length or a linkage larger than 1e300 (origin distance plus lengths), and
    :class:`AssemblyError` when the longest link is longer than the other
    three together.

    >>> fb = FourBar(ground=100.0, crank=40.0, coupler=120.0, rocker=80.0)  # Norton, Example 4-1
    >>> [round(math.degrees(a), 3) for a in fb.solve(math.radians(40))]
    [20.298, 57.325]
    """

    def __new__(
        cls,
        *,
        ground: float,
        crank: float,
        coupler: float,
        rocker: float,
        origin: Point = ...,
        ground_angle: float = 0.0,
    ) -> FourBar:
        """A four-bar from its link lengths; the input pivot is at ``origin``
        (default ``(0.0, 0.0)``) and the ground link at ``ground_angle``
        radians from +x."""
    @staticmethod
    def from_pivots(
        input_pivot: Point, output_pivot: Point, crank: float, coupler: float, rocker: float
    ) -> FourBar:
        """A four-bar between two given fixed pivots."""
    @property
    def ground(self) -> float:
        """Ground length L1 (input pivot to output pivot)."""
    @property
    def crank(self) -> float:
        """Crank (input) length L2."""
    @property
    def coupler(self) -> float:
        """Coupler length L3."""
    @property
    def rocker(self) -> float:
        """Rocker (output) length L4."""
    @property
    def lengths(self) -> Tuple[float, float, float, float]:
        """``(ground, crank, coupler, rocker)``."""
    @property
    def input_pivot(self) -> Point:
        """The input pivot O2."""
    @property
    def output_pivot(self) -> Point:
        """The output pivot O4."""
    @property
    def ground_angle(self) -> float:
        """The angle of the ground link, theta1."""
    @property
    def link_ratio(self) -> float:
        """Ratio of the longest to the shortest link."""
    @property
    def grashof_margin(self) -> float:
        """How far the linkage is from the Grashof change point,
        ``|s + l - p - q| / (s + l + p + q)`` in [0, 1) (see
        :attr:`LinkageFigures.grashof_margin`)."""
    @property
    def grashof(self) -> GrashofType:
        """Grashof type, the input being the crank link: ``"crank-rocker"``,
        ``"double-crank"``, ``"rocker-crank"``, ``"double-rocker"``
        (Grashof, coupler shortest), ``"triple-rocker"`` (non-Grashof) or
        ``"change-point"``."""
    @property
    def input_turns_fully(self) -> bool:
        """Whether the input link turns all the way round."""
    @property
    def input_range(self) -> Optional[list[Tuple[float, float]]]:
        """``None`` when the input turns fully, else the one or two arcs
        ``(start, end)`` (counter-clockwise) it can rock within."""
    @property
    def dead_positions(self) -> list[float]:
        """The input angles bounding the arcs of :attr:`input_range` (toggle
        positions); empty when the input turns fully."""
    def solve(self, theta2: float, mode: Mode = "open") -> Tuple[float, float]:
        """``(theta3, theta4)`` at input angle ``theta2`` in ``mode``.

        Raises :class:`AssemblyError` where the loop does not close (or the
        position is indeterminate), :class:`InvalidInputError` for a
        non-finite angle or an unknown mode."""
    def configuration(self, theta2: float, mode: Mode = "open") -> Configuration:
        """Like :meth:`solve`, with the toggle flag and the transmission angle."""
    def solve_many(
        self, theta2s: ArrayLike, mode: Mode = "open"
    ) -> Tuple[FloatArray, FloatArray, BoolArray]:
        """``(theta3, theta4, valid)`` for every input angle, arrays of the
        input's shape. The angles are NaN exactly where ``valid`` is False
        (the loop does not close there, or the angle is not finite or beyond
        ``1e9`` rad), and elsewhere the very values of :meth:`solve`. The GIL
        is released during the computation, which runs four angles at a time
        in SIMD lanes and, from 16384 angles on, on all cores."""
    def transmission_angle(self, theta2: float, mode: Mode = "open") -> float:
        """The transmission angle (acute angle between coupler and rocker),
        radians."""
    def joints(
        self, theta2: float, mode: Mode = "open"
    ) -> Tuple[Point, Point, Point, Point]:
        """``(O2, A, B, O4)``: input pivot, crank tip, rocker tip, output pivot."""
    def coupler_point(self, theta2: float, point: Point, mode: Mode = "open") -> Point:
        """Where a coupler point is. ``point`` is in the coupler frame: origin
        at the crank tip A, x-axis from A toward the rocker tip B."""
    def coupler_path(
        self, point: Point, theta2s: ArrayLike, mode: Mode = "open"
    ) -> Tuple[FloatArray, FloatArray, BoolArray]:
        """``(x, y, valid)``: the path of a coupler point over input angles,
        NaN exactly where ``valid`` is False."""
    def _repr_png_(self) -> Optional[bytes]:
        """The picture Jupyter shows (see :mod:`burmester._display`): PNG
        bytes, or None when matplotlib is not installed."""
    def __eq__(self, other: object, /) -> bool: ...
    def __getnewargs_ex__(self) -> Tuple[Tuple[()], dict[str, Any]]: ...

@final
class LinkageFigures:
    """What a designer checks of one linkage that must pass a task's poses
    in order (from :attr:`SynthesizedFourBar.figures` or :attr:`Pivot.figures`).

    :attr:`min_transmission_deg` is exact over the whole travel, not only at
    the poses."""

    @property
    def lengths(self) -> Tuple[float, float, float, float]:
        """``(ground, crank, coupler, rocker)``."""
    @property
    def grashof(self) -> GrashofType:
        """Grashof type, the driving link being the input."""
    @property
    def input_full(self) -> bool:
        """Whether the driving link turns fully (a crank)."""
    @property
    def modes(self) -> list[Optional[Mode]]:
        """The assembly mode at each pose (None at a toggle)."""
    @property
    def direction(self) -> Direction:
        """The input rotation that carries the coupler from pose 1 through
        the poses in order to the last: ``"ccw"``, ``"cw"``, or ``"none"``
        (an order defect, or poses on different circuits)."""
    @property
    def one_circuit(self) -> bool:
        """Whether the input angles at the poses lie on one circuit (one arc
        of the input range; always True for an input that turns fully)."""
    @property
    def min_transmission_deg(self) -> Optional[float]:
        """The smallest transmission angle over the travel through the poses,
        degrees in [0, 90]; None when there is no travel (direction ``"none"``)."""
    @property
    def link_ratio(self) -> float:
        """Longest over shortest link."""
    @property
    def grashof_margin(self) -> float:
        """How far the linkage is from the Grashof change point, as a part of
        the links' total length: ``|s + l - p - q| / (s + l + p + q)`` in
        [0, 1) (``s`` the shortest link, ``l`` the longest). Zero at a change
        point (every kite, two pairs of equal adjacent links, is one), where
        the type flips with the smallest error of a link and a fully turning
        input passes the flat position where the linkage can switch
        circuits. The type holds for every set of link errors adding up to
        less than the margin times the links' total length (each link off by
        less than the margin times its own length);
        :attr:`DesignLimits.min_grashof_margin` is the limit on it."""
    @property
    def branch_free(self) -> bool:
        """Every pose in one assembly mode (no branch defect, no toggle at a pose)."""
    @property
    def feasible(self) -> bool:
        """Branch-free, on one circuit, and with a driving direction: the
        motion through the poses in order can be driven."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...
    @staticmethod
    def _from_fields(
        lengths: Sequence[float],
        grashof: str,
        input_full: bool,
        modes: Sequence[Optional[str]],
        direction: str,
        one_circuit: bool,
        min_transmission: float,
        link_ratio: float,
    ) -> LinkageFigures:
        """Rebuilds figures from their fields (for pickling)."""

# ---------------------------------------------------------------------------
# synthesis

@final
class Pole:
    """The pole of two poses: the fixed point of the displacement between
    them, or, when they differ by a pure translation, the direction in which
    it lies at infinity."""

    def __new__(
        cls, pair: Tuple[int, int], point: Optional[Point] = None, direction: Optional[Point] = None
    ) -> Pole:
        """A pole has exactly one of ``point`` and ``direction``."""
    @property
    def pair(self) -> Tuple[int, int]:
        """The poses ``(i, j)``, 1-based, ``i < j``."""
    @property
    def point(self) -> Optional[Point]:
        """The pole ``P_ij``; None when it is at infinity."""
    @property
    def direction(self) -> Optional[Point]:
        """The unit direction of a pole at infinity (of the translation);
        None for a finite pole."""
    @property
    def at_infinity(self) -> bool:
        """True for a pole at infinity (a pure translation between the poses)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __getnewargs__(self) -> Tuple[Tuple[int, int], Optional[Point], Optional[Point]]: ...

@final
class Task:
    """Three to five poses of the coupler, ``(x, y, angle)`` with angles in
    radians. ``len(task)`` is the number of poses.

    What holds for any number of poses (the poses, displacements, rotations
    and poles, poles at infinity included) works on every task; the
    three-position maps (image poles, pole circles, Filemon's construction
    and the maps built on it) need three poses; the Burmester curves
    (:meth:`center_point_curve`, :meth:`coincidence_points`,
    :meth:`curve_dyads`, ...) need four; the Burmester points
    (:meth:`burmester_points`) five. Circle and center points and dyads
    work for three and four poses, :meth:`dyad` and :meth:`four_bar` for
    every count. A method called on a task of another size raises
    :class:`InvalidInputError` with ``cause == "needs_poses"`` and the
    fields ``method``, ``required`` and ``found``.

    Raises :class:`InvalidInputError` for NaN or infinite numbers or fewer
    than three or more than five poses (``cause == "pose_count"``), and
    :class:`DegenerateError` when two poses are equal, when all poses are
    rotations about one point, or when all have one angle
    (``cause == "all_translations"``: with three poses every dyad's crank
    would be the same vector).

    Two poses whose angles agree within 1e-6 rad (modulo 2 pi) differ by a
    pure translation: their pole is at infinity (:attr:`poles` gives its
    direction). A three-pose task with one works: the circle and center
    points, dyads, four-bars, Filemon's construction, the branch maps and
    the solution maps run by the linear form, which needs no pole; only
    what needs three finite poles (:meth:`image_poles`,
    :meth:`image_poles_in`, :meth:`pole_circle`, :meth:`image_pole_circle`,
    :meth:`pole_triangle_angles`) raises :class:`DegenerateError` with
    ``cause == "pure_translation"`` and the pair as ``i``, ``j``.

    The three-position maps run in a frame attached to the pole triangle (or
    to a finite pole and the task's scale), so results do not depend on
    where the task is or how large it is.
    """

    def __new__(cls, poses: Sequence[Sequence[float]]) -> Task:
        """Three to five poses, each a sequence of three numbers (tuples,
        lists or an n x 3 array). Coordinates must be at most 1e100 and
        angles at most 1e9 rad in magnitude."""
    def __len__(self) -> int:
        """The number of poses."""
    @property
    def poses(self) -> list[Pose]:
        """The poses."""
    @property
    def rotations(self) -> list[float]:
        """The rotation ``theta_ij`` of each pair in pair order (``(1, 2), (1,
        3), ..., (2, 3), ...``, as :attr:`poles`), each wrapped into (-pi, pi]."""
    @property
    def scale(self) -> float:
        """The size of the task: the unit of the relative tolerances. For
        three poses the pole triangle's longest side, or, with a pure
        translation between two poses, the largest distance between two of
        the pose positions and the finite poles; for four or five poses the
        largest distance between two pose positions."""
    @property
    def span(self) -> float:
        """The task's size as a designer reads it: the largest distance
        between two pose positions. The unit of
        :attr:`SynthesizedFourBar.size_ratio`."""
    @property
    def poles(self) -> list[Pole]:
        """The pole of every pair of poses, in pair order ``(1, 2), (1, 3),
        ..., (2, 3), ...``; a pair that differs by a pure translation has its
        pole at infinity."""
    def rotation(self, i: int, j: int) -> float:
        """``theta_ij``: the rotation from pose ``i`` to pose ``j`` (1-based),
        wrapped into (-pi, pi]."""
    def image_poles(self) -> Tuple[Point, Point, Point]:
        """Three poses only: ``(P12, P13, P'23)`` in the pose-1 frame;
        ``P'23`` is the reflection of ``P23`` across the line ``P12 P13``."""
    def image_poles_in(self, frame: int) -> Tuple[Point, Point, Point]:
        """Three poses only: the image poles ``(P12^k, P13^k, P23^k)`` in
        the frame of pose ``k`` (1, 2 or 3)."""
    def pole_circle(self) -> dict[str, Any]:
        """Three poses only: the circle through the poles: ``{"kind":
        "circle", "center": (x, y), "radius": r}`` (or ``{"kind": "line",
        "point", "direction"}`` when collinear). Center points on it have
        their circle point at infinity."""
    def image_pole_circle(self) -> dict[str, Any]:
        """Three poses only: the circle through the image poles (same form).
        Circle points on it have their center point at infinity."""
    def pole_triangle_angles(self) -> Tuple[float, float, float]:
        """Three poses only: the signed angles of the pole triangle at P12,
        P13, P23, modulo pi in (-pi/2, pi/2]; they equal theta12/2,
        theta13/2, theta23/2 mod pi."""
    def displace(self, point: Point, i: int, j: int) -> Point:
        """``D_ij(z)``: where the coupler point at ``point`` in pose ``i`` is in
        pose ``j`` (1-based)."""
    def circle_point(self, center: Point) -> Point:
        """Three or four poses: the circle point (moving pivot at pose 1) of
        a center point (fixed pivot). Three poses: raises
        :class:`DegenerateError` on the pole circle (the answer is at
        infinity: ``cause == "at_infinity"``, its direction in ``dir_x``,
        ``dir_y``) or at a pole (``"undefined"``). Four poses: the center
        point must lie on :meth:`center_point_curve` (within 1e-9 of the task
        size plus its distance from the task), else
        :class:`InvalidInputError` with ``cause == "off_curve"`` and the
        fields ``what``, ``distance`` (its first-order distance from the
        curve) and ``tolerance``; :class:`DegenerateError` where the circle
        point is at infinity or undefined."""
    def center_point(self, circle: Point) -> Point:
        """Three or four poses: the center point of a circle point. Three
        poses: raises :class:`DegenerateError` on the image-pole circle (the
        center is at infinity: a slider) or at an image pole. Four poses: the
        circle point must lie on :meth:`circle_point_curve` (as
        :meth:`circle_point`)."""
    def circle_points(self, centers: ArrayLike) -> Tuple[FloatArray, BoolArray]:
        """:meth:`circle_point` of an array of shape ``(..., 2)``: the points
        (NaN where undefined) and a validity mask of shape ``(...)``."""
    def center_points(self, circles: ArrayLike) -> Tuple[FloatArray, BoolArray]:
        """:meth:`center_point` of an array of shape ``(..., 2)``."""
    def dyad(self, center: Point) -> Tuple[Point, Point]:
        """``(center, circle)``: the dyad with this center point. Three and
        four poses as :meth:`circle_point`; five poses: the Burmester point
        at ``center`` (within 1e-7 relative), else the dyad of the curve of
        poses 1 to 4 when it passes the fifth too (else
        :class:`InvalidInputError`, ``cause`` ``"off_curve"`` or
        ``"not_a_dyad"``)."""
    def crank_angles(self, center: Point) -> list[float]:
        """The crank angle of the dyad with this center point at each pose."""
    def center_point_curve(self) -> Cubic:
        """Four poses only: the center-point curve, the fixed pivots of every
        dyad that passes the four poses: a circular cubic through the six
        poles, its coefficients expanded exactly from the poses. Raises
        :class:`DegenerateError` (``"coincident_poles"``) when the poses are
        rotations about one point."""
    def circle_point_curve(self) -> Cubic:
        """Four poses only: the circle-point curve (moving pivots at pose 1),
        the same construction for the inverted motion."""
    def coincidence_points(self) -> list[CoincidencePoint]:
        """Four poses only: the six points ``Q_jk`` of the center-point curve
        where the crank positions at poses ``j`` and ``k`` coincide, pairs in
        the order ``12, 13, 14, 23, 24, 34``. Between them the cyclic order
        of the crank positions is constant."""
    def curve_dyad(self, center: Point) -> CurveDyad:
        """Four poses only: the dyad of a center point on the curve, with its
        crank rotation from pose 1 to pose 2, its solution branch and its
        crank order. Errors as :meth:`circle_point`."""
    def curve_dyads(self, samples: int = 200) -> list[list[CurveDyad]]:
        """Four poses only: dyads sampled along the curves by the crank
        rotation ``beta2`` (about ``samples`` values over its range, for each
        solution branch), as runs in order of ``beta2``; a dyad at infinity
        splits a run. Raises :class:`DegenerateError`
        (``"not_parametrizable"``) when the poses have no compatibility
        linkage, :class:`InvalidInputError` for ``samples`` outside 1 to
        1e7. Ten million samples take seconds: the GIL is released and
        Ctrl-C raises :class:`KeyboardInterrupt` within a fraction of a
        second; dyads that cannot be allocated are a ``MemoryError``."""
    def order_arcs(
        self, xmin: float, xmax: float, ymin: float, ymax: float, *, plane: Literal["center", "circle"] = "center"
    ) -> list[Tuple[str, Optional[Literal["counterclockwise", "clockwise"]], FloatArray]]:
        """Four poses only: the center-point curve in the viewport cut into
        pieces of constant crank order, as ``(order, direction, points)``:
        ``direction`` is the way the crank meets the poses in their order
        (``None``: out of order); the cuts are the exact points ``Q_jk``.
        ``plane="circle"``: the circle-point curve likewise (each point's
        dyad from its center point), cut at the circle points of the
        ``Q_jk`` (and where the center point passes through infinity,
        between two traced points)."""
    def branch_free_arcs(
        self,
        driven_center: Point,
        xmin: float,
        xmax: float,
        ymin: float,
        ymax: float,
        *,
        plane: Literal["center", "circle"] = "center",
    ) -> list[FloatArray]:
        """Four poses only: the pieces of the center-point curve in the
        viewport whose driving dyads pass the four poses in one assembly mode
        with the driven dyad of ``driven_center`` (a point of the curve):
        Filemon's construction with four lines, the arc ends exact (each line
        meets the circle-point curve in the roots of one quadratic).
        ``plane="circle"``: the same driving dyads' circle points, pieces of
        the circle-point curve. The arc ends and ``C0`` (never free) are
        vertices of the traced curve, so the arcs are the same in every view:
        those of a smaller view are those of a larger one, clipped."""
    def curve_branch(self, driven_center: Point, center: Point) -> BranchClass:
        """Four poses only: the branch class of the driving dyad of
        ``center`` (on the curve) with the driven dyad of ``driven_center``:
        ``"free"`` (one assembly mode at the four poses), ``"defective"``, or
        ``"boundary"`` (a toggle at a pose)."""
    def burmester_points(self) -> list[Tuple[Point, Point]]:
        """Five poses only: the Burmester points with a finite center, as
        dyads ``(center, circle)`` (nearest the task first): the circle
        point's five positions are concyclic about the center to about 1e-14.
        Two, four or none; a double point (two points that merge, or a pair
        of complex ones, within the rounding of the elimination) is listed
        twice, as two equal dyads. A Burmester point at infinity (a slider: a
        circle point whose five positions are collinear, as the reference
        point of poses with collinear positions) is not listed, so such tasks
        have one or three. The count does not depend on the frame the poses
        are given in. Raises :class:`DegenerateError` when the points are not
        isolated: four poses rotations about one point (``cause``
        ``"coincident_poles"``), three (``"rotations_about_one_point"``, with
        the poses ``i``, ``j``, ``k``), three of one angle on a line
        (``"collinear_translations"``), or a common component of the curves
        (``"infinitely_many_burmester_points"``, for example Cardan motion);
        or when all poses have one angle; and where no choice of the shared
        poses gives a clean elimination (an even count of at most four:
        ``"unresolved_burmester_points"``, nearly coincident poses or angles),
        or where the points computed with each pose in turn as the reference
        pose disagree (the same cause: the rounding decides them; the answer
        is checked so on every call, and no ordinary task is refused), or
        where the answer's points within 1e4 task sizes are not those of the
        float task solved in exact integer arithmetic (the same cause; a
        double point may stand for a complex pair within 1e-5 of the size
        of the real plane)."""
    def burmester_curves(self) -> Tuple[Cubic, Cubic]:
        """Five poses only: the center-point curves of poses 1, 2, 3, 4 and
        1, 2, 3, 5; the Burmester centers are their common points other than
        the poles P12, P13, P23."""
    def burmester_four_bars(self) -> list[Tuple[int, int, SynthesizedFourBar]]:
        """Five poses only: the four-bar of every ordered pair of Burmester
        points, as ``(i, j, four_bar)`` with dyad ``i`` driving and ``j``
        driven (indices into :meth:`burmester_points`); a pair whose linkage
        cannot be built (a link of zero length) is left out."""
    def filemon(self, driven_center: Point) -> Filemon:
        """Three poses only: Filemon's construction for the driven dyad with
        this center point (``C0``). Raises :class:`DegenerateError` where
        ``C0`` has no circle point (pole circle, poles)."""
    def four_bar(self, driving_center: Point, driven_center: Point) -> SynthesizedFourBar:
        """The four-bar built from the dyads with these center points (their
        circle points as :meth:`dyad`), with its figures at every pose."""
    def slider_crank(
        self, driving: Tuple[Point, Point], driven: Tuple[Point, Point]
    ) -> SynthesizedSliderCrank:
        """The slider-crank of the driving crank ``(A0, A1)`` (its circle
        point ``A1`` a circle point of ``A0``) and the driven slider
        ``(C1, u)``: its pin ``C1`` at pose 1 and the guide's direction
        ``u`` (the guide is the line through ``C1`` along ``u``; ``u`` need
        not be unit). Raises :class:`InvalidInputError` (``cause``
        ``"not_a_dyad"``) when ``A1`` is not a circle point of ``A0``, or
        (``"not_a_slider"``) when the slider's positions over the poses
        leave its guide (take a slider point of the task and the line
        through its positions), and :class:`DegenerateError` for a coupler
        of no length."""
    def inverted_slider_crank(
        self, driving: Tuple[Point, Point], driven: Tuple[Point, Point]
    ) -> SynthesizedInvertedSliderCrank:
        """The inverted slider-crank of the driving crank ``(A0, A1)`` and
        the inverted slider ``(S, d)``: its swivel ``S`` (the block's ground
        pivot) and the slot's direction ``d`` at pose 1 (as
        :attr:`InvertedSlider.swivel` and :attr:`InvertedSlider.direction`;
        ``d`` need not be unit). The slot's offset from the crank pin is
        ``cross(d, S - A1)``. Raises :class:`InvalidInputError` (``cause``
        ``"not_a_dyad"``) when ``A1`` is not a circle point of ``A0``,
        (``"not_a_slider"``) when the body line leaves the swivel at a pose
        (take one of :meth:`inverted_sliders`), (``"zero_direction"``) for a
        zero direction, and :class:`AssemblyError` when the slot can never
        be assembled."""
    @overload
    def driven_solution_map(
        self,
        driving_center: Point,
        grid: Union[Grid, GridTuple],
        *,
        progress: Optional[Progress] = None,
        **options: Unpack[MapOptions],
    ) -> SolutionMap:
        """The solution-space map the other way round: the driving dyad with
        this center point is fixed and the candidates are driven center
        points ``C0`` on ``grid`` (a :class:`Grid`, or its six numbers
        ``xmin, xmax, ymin, ymax, nx, ny`` as a tuple or one by one); the branch-free flag is the sign
        test at the poses. Keywords as :meth:`Filemon.solution_map`."""
    @overload
    def driven_solution_map(
        self,
        driving_center: Point,
        xmin: float,
        xmax: float,
        ymin: float,
        ymax: float,
        nx: int,
        ny: int,
        *,
        progress: Optional[Progress] = None,
        **options: Unpack[MapOptions],
    ) -> SolutionMap: ...
    def pair_map(
        self,
        n_driving: int = 256,
        n_driven: Optional[int] = None,
        *,
        progress: Optional[Progress] = None,
        **options: Unpack[MapOptions],
    ) -> PairMap:
        """Four poses only: the pair map, every linkage of the task on one
        picture. ``n_driving`` driving dyads and ``n_driven`` (default: as
        many) driven dyads are sampled along the center-point curve by its
        parameter ``s`` (radians of crank rotation: the arcs of ``beta2``
        laid end to end, first on the ``"open"`` solution branch, then on the
        ``"crossed"`` one; samples at the middles of equal steps), and every
        pair gets the columns of :class:`SolutionMap`. Keywords as
        :meth:`Filemon.solution_map` (both pivots must lie on the base
        plate). Raises :class:`InvalidInputError` (``"needs_poses"``) unless
        the task has four poses, (``"grid_size"``) for a count of 0, above
        1e7, or more than 2**32 pairs, (``"too_small"``) when poses 1 and 2
        nearly coincide (the range of crank rotations between them, the
        map's parameter, is below 2e-6 rad); :class:`DegenerateError`
        (``"not_parametrizable"``) when the poses have no compatibility
        linkage, (``"all_translations"``) when the four poses have one
        angle."""
    def line_to_conic(self, point: Point, direction: Point) -> Conic:
        """Three poses only: the exact image in the center-point plane of a
        line of the circle-point plane: a conic through the three poles."""
    def _repr_png_(self) -> Optional[bytes]:
        """The picture Jupyter shows (see :mod:`burmester._display`): PNG
        bytes, or None when matplotlib is not installed."""
    def __eq__(self, other: object, /) -> bool: ...
    def __getnewargs__(self) -> Tuple[list[Pose]]: ...
    # Slider dyads and inverted sliders (issue 27).
    def slider_circle(self) -> dict[str, Any]:
        """Three poses only: the slider circle, the circle points whose three
        positions are collinear: the circle through P12, P13 and the image
        pole P'23 (``{"kind": "circle", "center": (x, y), "radius": r}``), or
        a line (``{"kind": "line", "point", "direction"}``) when two poses
        differ by a pure translation. Computed from the collinearity
        condition in a frame at pose 1, so it holds at small rotations and
        with a pole at infinity. Raises :class:`InvalidInputError`
        (``"needs_poses"``) for four or five poses."""
    def slider_dyads(self, samples: int = 200) -> list[SliderDyad]:
        """The slider dyads (a pin on a straight guide fixed to the ground):
        three poses, ``samples`` of them along :meth:`slider_circle` (at
        equal angles from its point nearest pose 1; on a line crowded near
        pose 1); four poses, the slider points of the circle-point curve;
        five poses, the slider Burmester points (an empty list when every
        real Burmester point is finite). Each pin's positions lie on its
        guide. ``samples`` from 1 to 10000 (else
        :class:`InvalidInputError`, ``"count_out_of_range"``), used for three
        poses only. Four or five poses without curves or points raise the
        errors of :meth:`center_point_curve` / :meth:`burmester_points`."""
    def slider_dyad(self, circle: Point) -> SliderDyad:
        """The slider dyad whose pin is at ``circle`` at pose 1, its guide the
        line through the pin's positions. Three poses: ``circle`` must lie on
        :meth:`slider_circle` (within 1e-9 of the task's scale plus its
        distance from pose 1); four or five: it must be one of
        :meth:`slider_dyads` (within 1e-7 relative). Else
        :class:`InvalidInputError` with ``cause`` ``"not_a_slider_point"``
        (fields ``distance``, ``tolerance``, ``hint``) or, where the task has
        none, ``"no_slider_point"`` (field ``why``)."""
    def inverted(self) -> Task:
        """The inverted task: the ground's motion seen from the body, pose
        ``k`` replaced by the inverse displacement ``D_k1`` (pose 1 becomes
        ``(0, 0, 0)``), so its moving plane at pose 1 is the ground."""
    def inverted_sliders(self, samples: int = 200) -> list[InvertedSlider]:
        """The inverted sliders (a line of the body through a fixed swivel
        at every pose): the slider dyads of :meth:`inverted`, each pin a
        swivel in the ground and each guide the body line at pose 1. Three
        poses: ``samples`` along the pole circle (through P12, P13, P23).
        Errors as :meth:`slider_dyads`."""
    def inverted_slider(self, swivel: Point) -> InvertedSlider:
        """The inverted slider whose swivel is ``swivel``, checked as
        :meth:`slider_dyad` checks a pin (three poses: on the pole circle);
        the errors name the swivel point."""

@final
class SliderDyad:
    """A slider dyad: a pin on a straight guide fixed to the ground, the
    revolute dyad whose center point is at infinity (from
    :meth:`Task.slider_dyads` and :meth:`Task.slider_dyad`). ``circle`` is the
    pin at pose 1, on the guide; ``guide`` the guide's unit direction
    (normalized; :class:`InvalidInputError` for a zero or non-finite one).
    Pickles to an equal object."""

    def __new__(cls, circle: Point, guide: Point) -> SliderDyad: ...
    @property
    def circle(self) -> Point:
        """The pin (moving pivot) at pose 1, a point of the guide."""
    @property
    def guide(self) -> Point:
        """The guide's unit direction."""
    @property
    def normal(self) -> Point:
        """The guide's unit normal (the guide turned by +90 degrees): where
        the center point is at infinity."""
    def __eq__(self, other: object, /) -> bool: ...
    def _repr_png_(self) -> Optional[bytes]:
        """A picture for Jupyter (:mod:`burmester._display`): PNG bytes, or None without matplotlib."""
    def __reduce__(self) -> Tuple[Any, ...]: ...
    @staticmethod
    def _from_fields(circle: Point, guide: Point) -> SliderDyad:
        """Rebuilds a record from its fields (for pickling), bit for bit."""

@final
class InvertedSlider:
    """An inverted slider: a line fixed in the moving body that passes
    through one fixed pivot, the swivel, at every pose (a slotted coupler on
    a ground pin, a rod through a swivelling sleeve); from
    :meth:`Task.inverted_sliders` and :meth:`Task.inverted_slider`. The body
    line at pose 1 runs through ``swivel`` along the unit ``direction``
    (normalized; :class:`InvalidInputError` for a zero or non-finite one).
    Pickles to an equal object."""

    def __new__(cls, swivel: Point, direction: Point) -> InvertedSlider: ...
    def body_line_at(self, task: Task, k: int) -> Tuple[Point, Point]:
        """``(point, direction)`` of the body line at pose ``k`` (1-based) of
        ``task``: the line at pose 1 moved with the body; it passes through
        the swivel. :class:`InvalidInputError` (``"pose_index"``) for an
        index out of range."""
    @property
    def swivel(self) -> Point:
        """The swivel: the fixed pivot, in the ground."""
    @property
    def direction(self) -> Point:
        """The unit direction of the body line where it is at pose 1 (at
        pose ``k`` it is turned with the body: :meth:`body_line_at`)."""
    @staticmethod
    def _from_fields(swivel: Point, direction: Point) -> InvertedSlider:
        """Rebuilds a record from its fields (for pickling), bit for bit."""
    def __reduce__(self) -> Tuple[Any, ...]: ...
    def __eq__(self, other: object, /) -> bool: ...

@final
class CoincidencePoint:
    """A point ``Q_jk`` of the center-point curve of four poses (from
    :meth:`Task.coincidence_points`): the crank positions at poses ``j`` and
    ``k`` coincide there, ``Q_jk = (P_lj P_lk) x (P_mj P_mk)`` with ``{l,
    m}`` the other two poses. Its circle point is the pole ``P_jk`` carried
    back to pose 1, so the moving pivot sits on ``P_jk`` at both poses."""

    @property
    def pair(self) -> Tuple[int, int]:
        """``(j, k)``, 1-based, ``j < k``."""
    @property
    def center(self) -> Optional[Point]:
        """``Q_jk``; None when it is at infinity or undefined (coincident poles)."""
    @property
    def circle(self) -> Optional[Point]:
        """Its circle point (moving pivot at pose 1); None when ``P_jk`` is at infinity."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...
    @staticmethod
    def _from_fields(
        pair: Tuple[int, int], center: Optional[Point], circle: Optional[Point]
    ) -> CoincidencePoint:
        """Rebuilds a record from its fields (for pickling)."""

@final
class CurveDyad:
    """A dyad of four poses with its place on the Burmester curves (from
    :meth:`Task.curve_dyad` and :meth:`Task.curve_dyads`)."""

    @property
    def center(self) -> Point:
        """The center point (fixed pivot), on the center-point curve."""
    @property
    def circle(self) -> Point:
        """The circle point (moving pivot at pose 1), on the circle-point curve."""
    @property
    def dyad(self) -> Tuple[Point, Point]:
        """``(center, circle)``."""
    @property
    def beta2(self) -> float:
        """The crank rotation from pose 1 to pose 2, in (-pi, pi]."""
    @property
    def branch(self) -> Optional[Mode]:
        """The solution branch: the assembly mode of the compatibility
        linkage (Sandor & Erdman) at this ``beta2``; None at one of its
        toggles, where the two branches meet, or when the poses have none."""
    @property
    def order(self) -> str:
        """The cyclic order of the crank's positions at the four poses,
        counter-clockwise from pose 1, such as ``"1-2-3-4"``."""
    @property
    def direction(self) -> Optional[Literal["counterclockwise", "clockwise"]]:
        """The way the crank meets the poses in their order (``"1-2-3-4"``
        counter-clockwise, ``"1-4-3-2"`` clockwise), or None (an order defect)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...
    @staticmethod
    def _from_fields(
        center: Point,
        circle: Point,
        beta2: float,
        branch: Optional[str],
        order: str,
        direction: Optional[str],
    ) -> CurveDyad:
        """Rebuilds a record from its fields (for pickling)."""

@final
class Filemon:
    """Filemon's construction for a driven dyad ``(C0, C1)`` of a three-pose
    task, and its two lines transformed exactly into conics in the driving
    crank's center-point plane (from :meth:`Task.filemon`).

    A driving center point ``A0`` is branch-free exactly where the two conics
    have values of one sign (``g_a(A0) * g_b(A0) > 0``).
    """

    @property
    def task(self) -> Task:
        """The task."""
    @property
    def driven_center(self) -> Point:
        """``C0``, the driven crank's fixed pivot."""
    @property
    def driven_circle(self) -> Point:
        """``C1``, the driven crank's moving pivot at pose 1 (its circle point)."""
    @property
    def fixed_pivot_images(self) -> Tuple[Point, Point, Point]:
        """``(C'1, C'2, C'3)``, ``C'k = D_k1(C0)``."""
    @property
    def all_defective(self) -> bool:
        """True when every driving circle point has a branch defect (the
        directions ``C'k - C1`` do not lie in an open half-plane); then
        :attr:`lines` and :attr:`conics` are empty."""
    @property
    def lines(self) -> list[Line]:
        """The two Filemon lines, each ``(point, direction)`` with point ``C1``
        and direction ``C'k - C1`` of an extreme pose (empty when all are
        defective)."""
    @property
    def all_lines(self) -> list[Line]:
        """The three lines through ``C1`` and ``C'k``, ``k = 1, 2, 3``."""
    @property
    def sectors(self) -> list[Tuple[float, float, bool]]:
        """The sectors around ``C1`` cut by the three lines (each line gives
        two rays), counter-clockwise: ``(start, end, free)``, angles in
        radians increasing, the last ending a full turn after the first
        begins. ``free`` where every line sees the sector's points on one
        side (the double wedge between the Filemon lines; none when all are
        defective)."""
    @property
    def conics(self) -> list[Conic]:
        """The two transformed Filemon lines (empty when all are defective)."""
    @property
    def extreme_poses(self) -> Optional[Tuple[int, int]]:
        """The poses (1-based) whose lines are the Filemon lines."""
    @property
    def middle_pose(self) -> Optional[int]:
        """The pose whose line lies between the Filemon lines."""
    def line_conic(self, pose: int) -> Conic:
        """The transformed line of pose ``k`` (any of the three)."""
    def is_branch_free(self, center: Point, method: Method = "conic") -> bool:
        """Whether the driving center point is free of the branch defect.

        ``"conic"``: the signs of the two conics (defined everywhere);
        ``"direct"``: the circle point, then the sign test at the three poses;
        ``"simulate"``: build the four-bar and drive it from pose to pose
        inside its input range, in pose 1's assembly mode (this also sees
        the circuit defect of an input that rocks in two separate arcs, which the sign tests
        cannot). Beyond the bands of the README's table the methods agree
        (but for that circuit defect). A point on a curve is not free.
        ``"direct"`` and ``"simulate"`` raise :class:`DegenerateError` on the
        pole circle and at the poles."""
    def classify(self, center: Point, method: Method = "conic") -> BranchClass:
        """``"free"``, ``"defective"`` or ``"boundary"`` (on a curve, or a toggle
        at a design pose)."""
    def classify_circle_point(self, circle: Point) -> BranchClass:
        """Filemon's test of a driving circle point in the circle-point plane."""
    def circle_signs(self, circle: Point) -> Tuple[float, float, float]:
        """``cross(C'k - C1, A1 - C1)`` for ``k = 1, 2, 3``."""
    def conic_values(self, center: Point) -> Optional[Tuple[float, float]]:
        """The two conics' values at a center point (None when all defective)."""
    def four_bar(self, driving_center: Point) -> SynthesizedFourBar:
        """The four-bar with this driven dyad and the driving dyad whose center
        point is given."""
    @overload
    def branch_map(
        self,
        grid: Union[Grid, GridTuple],
        /,
        *,
        method: Method = "conic",
        out: Optional[BoolArray] = None,
        progress: Optional[Progress] = None,
    ) -> BoolArray:
        """Classify every candidate driving center point of a grid.

        ``grid`` is a :class:`Grid`, or its six numbers ``xmin, xmax, ymin,
        ymax, nx, ny`` as a tuple or one by one; ``method`` (``"conic"``, ``"direct"`` or
        ``"simulate"``, as :meth:`is_branch_free`) may follow them
        positionally. The result has shape ``(ny, nx)``, row ``j`` for
        ``y_j``, True where strictly branch-free. Points on a curve, at a
        pole or at ``C0`` are False; ``"direct"`` and ``"simulate"`` are also
        False where the circle point does not exist (on the pole circle).

        The GIL is released during the computation; the result is handed to
        NumPy without a copy, or written into ``out`` (a C-contiguous bool
        array of shape ``(ny, nx)``), which is returned. ``progress(done,
        total)`` follows the rows; the samples are the same with or without
        it, bit for bit. Ctrl-C raises :class:`KeyboardInterrupt` within a
        fraction of a second; its message says when ``out`` holds a partial
        result.

        ``"conic"`` at 4096 x 4096 takes about as long as filling the array
        with a constant (see BENCHMARKS.md)."""
    @overload
    def branch_map(
        self,
        grid: Union[Grid, GridTuple],
        method: Method,
        /,
        *,
        out: Optional[BoolArray] = None,
        progress: Optional[Progress] = None,
    ) -> BoolArray: ...
    @overload
    def branch_map(
        self,
        xmin: float,
        xmax: float,
        ymin: float,
        ymax: float,
        nx: int,
        ny: int,
        /,
        *,
        method: Method = "conic",
        out: Optional[BoolArray] = None,
        progress: Optional[Progress] = None,
    ) -> BoolArray: ...
    @overload
    def branch_map(
        self,
        xmin: float,
        xmax: float,
        ymin: float,
        ymax: float,
        nx: int,
        ny: int,
        method: Method,
        /,
        *,
        out: Optional[BoolArray] = None,
        progress: Optional[Progress] = None,
    ) -> BoolArray: ...
    @overload
    def margin_map(
        self,
        grid: Union[Grid, GridTuple],
        /,
        *,
        out: Optional[npt.NDArray[np.float32]] = None,
        progress: Optional[Progress] = None,
    ) -> npt.NDArray[np.float32]:
        """The signed margin on a grid (float32, like :meth:`branch_map`):
        the first-order distance to the nearer transformed Filemon curve,
        positive where branch-free and negative elsewhere; ``-inf``
        everywhere when all circle points are defective. For contour plots."""
    @overload
    def margin_map(
        self,
        xmin: float,
        xmax: float,
        ymin: float,
        ymax: float,
        nx: int,
        ny: int,
        /,
        *,
        out: Optional[npt.NDArray[np.float32]] = None,
        progress: Optional[Progress] = None,
    ) -> npt.NDArray[np.float32]: ...
    def margin(self, center: Point) -> float:
        """The signed margin at one point (float64)."""
    @overload
    def solution_map(
        self,
        grid: Union[Grid, GridTuple],
        /,
        *,
        progress: Optional[Progress] = None,
        **options: Unpack[MapOptions],
    ) -> SolutionMap:
        """The designer's solution-space map over candidate driving center
        points ``A0`` on a grid (as :meth:`branch_map`).

        For each candidate: whether the linkage exists, the branch-free flag
        (exactly :meth:`branch_map`), the Grashof class, whether the driving
        link turns fully, the input rotation direction that carries the
        coupler from pose 1 through pose 2 to pose 3 (or none), whether the
        input angles lie on one circuit, the minimum transmission angle over
        the whole travel (exact, not only at the poses), the link ratio, and
        an ``acceptable`` mask.

        The limits are ``limits=DesignLimits(...)`` or its three keywords
        ``min_transmission_deg`` (default 30), ``max_link_ratio`` (default
        10) and ``input`` (``"any"``, ``"crank"``: turns fully, or
        ``"rocker"``), not both. The constraints: the fixed pivot inside
        ``base_plate`` (a simple polygon), and the moving links, as capsules
        ``link_width`` wide, clear of ``obstacles`` (convex polygons) at
        ``travel_samples`` input angles of the travel; each polygon has at
        most 4096 vertices (``cause == "polygon"``, ``problem == "too many
        vertices"`` beyond). The GIL is released, ``progress`` and Ctrl-C as
        in :meth:`branch_map` (a linkage's clearance test checks for Ctrl-C
        too)."""
    @overload
    def solution_map(
        self,
        xmin: float,
        xmax: float,
        ymin: float,
        ymax: float,
        nx: int,
        ny: int,
        /,
        *,
        progress: Optional[Progress] = None,
        **options: Unpack[MapOptions],
    ) -> SolutionMap: ...
    def _repr_png_(self) -> Optional[bytes]:
        """The picture Jupyter shows (see :mod:`burmester._display`): PNG
        bytes, or None when matplotlib is not installed."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...

@final
class SliderFilemon:
    """Filemon's construction for a slider driven dyad of a three-pose task:
    the pin ``C1`` on a straight ground guide of direction ``u`` (the
    dyad's center at infinity along the normal ``n = i u``), and the lines
    transformed exactly into conics in the driving crank's center-point
    plane.

    The line of pose ``k`` runs through ``C1`` in the direction ``n_k``, the
    guide's normal seen from the coupler frame of pose 1 while at pose
    ``k``; the branch sign of a driving circle point ``A1`` is
    ``cross(n_k, A1 - C1) = <C1 - A1, u_k>``: which side of the
    perpendicular to the guide through the crank pin the slider pin is on
    (the slider-crank's assembly mode). It is the limit of :class:`Filemon`
    with ``C0 = C1 + R n``, ``R`` to infinity. ``circle`` must be a slider
    point of the task (its three positions on the guide, within 1e-9 of the
    task's size): else :class:`InvalidInputError` (``cause``
    ``"not_a_dyad"``); a zero guide is :class:`InvalidInputError` too.
    """

    def __new__(cls, task: Task, circle: Point, guide: Point) -> SliderFilemon: ...
    @property
    def task(self) -> Task:
        """The task."""
    @property
    def circle(self) -> Point:
        """``C1``, the slider's pin at pose 1 (a point of the guide)."""
    @property
    def guide(self) -> Point:
        """The guide's unit direction ``u``."""
    @property
    def normal(self) -> Point:
        """``n = i u``, where the dyad's center is at infinity."""
    @property
    def directions(self) -> list[Point]:
        """The lines' unit directions ``n_k``, ``k = 1, 2, 3``."""
    @property
    def all_defective(self) -> bool:
        """True when every driving circle point has a branch defect (the
        directions ``n_k`` do not lie in an open half-plane); then
        :attr:`lines` and :attr:`conics` are empty."""
    @property
    def lines(self) -> list[Line]:
        """The two Filemon lines (the extreme ones), each ``(C1, n_k)``."""
    @property
    def all_lines(self) -> list[Line]:
        """The three lines ``(C1, n_k)``."""
    @property
    def sectors(self) -> list[Tuple[float, float, bool]]:
        """The sectors around ``C1`` cut by the lines, as
        :attr:`Filemon.sectors`."""
    @property
    def conics(self) -> list[Conic]:
        """The two transformed Filemon lines: conics through the finite
        poles (empty when all are defective)."""
    @property
    def extreme_poses(self) -> Optional[Tuple[int, int]]:
        """The poses (1-based) whose lines are the Filemon lines."""
    @property
    def middle_pose(self) -> Optional[int]:
        """The pose whose line lies between the Filemon lines."""
    def line_conic(self, pose: int) -> Conic:
        """The transformed line of pose ``k`` (any of the three)."""
    def classify(self, center: Point, method: Method = "conic") -> BranchClass:
        """The branch class of a driving center point: ``"conic"`` (the signs
        of the two conics) or ``"direct"`` (its circle point, then the signs
        at the three poses). ``"simulate"`` builds the slider-crank
        (:meth:`Task.slider_crank`) and drives it by crank angle from pose to
        pose, in pose 1's assembly mode, as :meth:`Filemon.classify` drives a
        four-bar: it also sees the circuit defect of a crank rocking on two
        arcs."""
    def classify_circle_point(self, circle: Point) -> BranchClass:
        """Filemon's test of a driving circle point in the circle-point plane."""
    def circle_signs(self, circle: Point) -> list[float]:
        """``cross(n_k, A1 - C1)`` for ``k = 1, 2, 3``."""
    def conic_values(self, center: Point) -> Optional[Tuple[float, float]]:
        """The two conics' values at a center point (None when all defective)."""
    @overload
    def branch_map(
        self,
        grid: Union[Grid, GridTuple],
        /,
        *,
        method: Method = "conic",
        out: Optional[BoolArray] = None,
        progress: Optional[Progress] = None,
    ) -> BoolArray:
        """Classify every candidate driving center point of a grid, as
        :meth:`Filemon.branch_map` (``"conic"``, ``"direct"`` or
        ``"simulate"``; the method by name only). Shape ``(ny, nx)``, True
        where strictly branch-free."""
    @overload
    def branch_map(
        self,
        xmin: float,
        xmax: float,
        ymin: float,
        ymax: float,
        nx: int,
        ny: int,
        /,
        *,
        method: Method = "conic",
        out: Optional[BoolArray] = None,
        progress: Optional[Progress] = None,
    ) -> BoolArray: ...
    def solution_map(
        self,
        *grid: Union[Grid, GridTuple, float],
        progress: Optional[Progress] = None,
        **options: Unpack[MapOptions],
    ) -> SolutionMap:
        """The solution map over candidate driving center points ``A0`` with
        this driven slider: the columns of :meth:`Filemon.solution_map`, each
        sample's linkage the slider-crank :meth:`SolutionMap.slider_crank`
        (:attr:`SolutionMap.fixed_kind` is ``"slider"``, :attr:`SolutionMap.fixed_dyad`
        is ``(C1, u)``).

        ``branch_free`` is exactly :meth:`branch_map`; ``grashof`` is 255
        everywhere (Grashof's law is a four-bar's): the crank's own
        rotatability is ``input_full`` (it turns fully exactly when
        ``r + |e| <= l``, :meth:`SliderCrank.turns_fully`); ``direction``,
        ``one_circuit`` and ``min_transmission_rad`` (the angle between the
        coupler and the guide's normal, over the travel) are the
        slider-crank's (:class:`SynthesizedSliderCrank`); ``link_ratio`` is
        longest over shortest of the crank and the coupler; ``size_ratio`` is
        :attr:`SynthesizedSliderCrank.size` over :attr:`Task.span`.
        ``acceptable`` applies the limits as to a four-bar, the longest link
        among crank, coupler and offset, and ``min_grashof_margin`` to the
        distance from the slider-crank's change points,
        ``min(|l - r - e|, |l - r + e|) / (r + l + |e|)``. A ``base_plate``
        holds ``A0``; ``obstacles`` (and an envelope) are checked over a
        four-bar's travel and raise :class:`InvalidInputError` (``cause``
        ``"driven_kind"``) here, as :meth:`SolutionMap.best_pivots` and
        :meth:`SolutionMap.linkage` do on this map (rank it by
        :meth:`SolutionMap.best_slider_pivots`). Grid, GIL, progress and
        Ctrl-C as :meth:`Filemon.solution_map` (the grid a :class:`Grid`,
        its tuple or its six numbers)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...

def slider_branch_free_arcs(
    task: Task,
    circle: Point,
    guide: Point,
    xmin: float,
    xmax: float,
    ymin: float,
    ymax: float,
    *,
    plane: Literal["center", "circle"] = "center",
) -> list[FloatArray]:
    """Four poses: the branch-free arcs in view of the center-point curve
    (``plane="circle"``: the circle-point curve) for the slider driven dyad
    with pin ``circle`` at pose 1 on a guide along ``guide``, as
    :meth:`Task.branch_free_arcs` (Filemon's four lines through ``C1`` in
    the directions ``n_k``, exact arc ends). :class:`InvalidInputError` for
    a task of three or five poses, a zero guide, or a pin whose four
    positions are not on the guide (``cause`` ``"not_a_dyad"``)."""

def slider_curve_branch(task: Task, circle: Point, guide: Point, center: Point) -> BranchClass:
    """Four poses: the branch class of a driving center point on the
    center-point curve for the slider driven dyad ``(circle, guide)``, as
    :meth:`Task.curve_branch`."""

@final
class SynthesizedFourBar:
    """A four-bar built from a driving dyad ``(A0, A1)`` and a driven dyad
    ``(C0, C1)``; driving it to ``input_angles[k]`` in ``modes[k]`` places
    the task's coupler point and angle at pose ``k + 1``."""

    @property
    def fourbar(self) -> FourBar:
        """The linkage (input pivot ``A0``, output pivot ``C0``)."""
    @property
    def size(self) -> float:
        """The linkage's size: the total length of its members, the ground
        ``A0 C0``, the crank, the rocker and the three sides of the coupler
        triangle (the moving pivots and the task's coupler point, which the
        coupler plate carries)."""
    @property
    def size_ratio(self) -> float:
        """:attr:`size` over the task's :attr:`Task.span`: how many times the
        task's size the linkage's members add up to (scale-free)."""
    def score(self, rank_by: RankBy = "balanced") -> Optional[float]:
        """Its score by a ranking of :meth:`SolutionMap.best_pivots`
        (``"balanced"``, ``"transmission"`` or ``"compact"``; larger is
        better), from its figures and :attr:`size_ratio`; None without a
        feasible travel. ``"pareto"`` and ``"margin"`` raise
        :class:`InvalidInputError` (they rank a map, not one linkage)."""
    @property
    def driving(self) -> Tuple[Point, Point]:
        """``(A0, A1)``."""
    @property
    def driven(self) -> Tuple[Point, Point]:
        """``(C0, C1)``."""
    @property
    def input_angles(self) -> list[float]:
        """The input angle at each pose, in (-pi, pi]."""
    @property
    def modes(self) -> list[Optional[Mode]]:
        """The assembly mode at each pose (None at a toggle)."""
    @property
    def coupler_point(self) -> Point:
        """The task's coupler point in the linkage's coupler frame."""
    @property
    def coupler_angle_offset(self) -> float:
        """Task coupler angle minus the linkage's theta3."""
    @property
    def figures(self) -> LinkageFigures:
        """What a designer checks of it: Grashof type, order and circuit,
        the minimum transmission angle over the travel, the link ratio."""
    @property
    def branch_free(self) -> bool:
        """Whether the poses are all in one assembly mode (no toggle at a pose)."""
    @property
    def travel(self) -> Optional[Tuple[float, float]]:
        """``(start, span)``: the input angle at pose 1 and the signed angle
        the input turns through the poses to the last (positive
        counter-clockwise); None when no direction carries the coupler
        through the poses in order."""
    @property
    def travel_stops(self) -> Optional[list[float]]:
        """The input angle at each pose along the :attr:`travel`, unwrapped
        (starting at pose 1's and moving monotonically in the travel's
        direction); None when there is no travel."""
    def travel_angles(self, samples: int) -> FloatArray:
        """``samples`` input angles evenly spaced over the :attr:`travel`,
        both ends included; empty when there is no travel. Raises
        :class:`InvalidInputError` for fewer than 2 samples."""
    def pose_at(self, theta2: float, mode: Mode = "open") -> Pose:
        """``(x, y, angle)`` of the task's coupler point when driven to ``theta2``."""
    # Driving it from a motor by an added dyad (the Watt II six-bar).
    def drive_map(
        self,
        *grid: Any,
        attachment: Optional[Point] = None,
        progress: Optional[Progress] = None,
        **options: Unpack[DriveOptions],
    ) -> DriveMap:
        """The drive map: for every candidate crank pivot ``D0`` on the grid
        (a :class:`Grid` or its six numbers), the crank-rocker ``D0 D E A0``
        whose rocker ``A0 E`` swings exactly over the input's travel from the
        first pose to the last, extended by ``swing_margin_deg`` at each end
        (``E``, the ``attachment``, is rigid with the input link; default:
        the input joint ``A`` itself). Each sample is exact (closed form): a
        drive exists where the line through ``A0`` and ``D0`` misses ``E``'s
        swing; its columns are the minimum transmission angle of both loops
        over a full crank turn, the drive's own, the time ratio, the
        six-bar's link ratio and size ratio, and ``acceptable`` under the
        limits (transmission, link ratio), ``max_time_ratio`` and the
        constraints (``D0`` on ``base_plate``; the moving links clear of
        ``obstacles`` over the whole turn); ``max_time_ratio=None``: no limit. Releases the GIL; ``progress``
        and Ctrl-C as :meth:`Filemon.solution_map`.

        Raises :class:`DriveError` when no drive can exist (no travel, a
        travel of 180 degrees or more, margins past a dead position),
        :class:`DegenerateError` for an attachment on ``A0``,
        :class:`InvalidInputError` for bad limits, options or constraints."""
    def drive(
        self,
        drive_pivot: Point,
        attachment: Optional[Point] = None,
        **options: Unpack[DriveOptions],
    ) -> Drive:
        """The drive with its crank pivot at ``drive_pivot`` (one sample of
        :meth:`drive_map`); :class:`DriveError` (``"not_a_crank_rocker"``)
        where there is none."""
    def classic_drive(
        self,
        attachment: Optional[Point] = None,
        *,
        beyond_first: bool = True,
        drive_transmission_deg: Optional[float] = None,
        **options: Unpack[ClassicDriveOptions],
    ) -> Drive:
        """The closed-form drive of time ratio 1 (Norton's construction,
        Brodell and Soni's equations): the crank pivot on the line through
        ``E``'s two end positions, beyond the first pose's end
        (``beyond_first``) or the last's, at the distance that gives the
        drive loop the transmission angle ``drive_transmission_deg`` over a
        full turn (default: halfway between the limit and ``90 - swing/2``,
        the best a time-ratio-1 drive reaches, at infinite size). Its figures
        are the drive map's sample there."""
    def drive_search(
        self,
        *,
        ratios: Optional[Sequence[float]] = None,
        angles_deg: Optional[Sequence[float]] = None,
        reach: float = 4.0,
        samples: int = 96,
        rank_by: RankBy = "balanced",
        progress: Optional[Progress] = None,
        **options: Unpack[DriveOptions],
    ) -> list[Drive]:
        """Searches attachments and crank pivots: ``E`` at ``ratio * |A - A0|``
        from ``A0``, turned ``angle`` from the input link (along it at 0,
        behind ``A0`` at 180), for every ratio (default 0.5, 1, 1.5, 2) and
        angle (default every 30 degrees); for each, the drive map of
        ``samples`` x ``samples`` crank pivots over the square of half-width
        ``reach * |E - A0|`` about ``A0``. Returns the best acceptable drive
        of each attachment that has one, best first by ``rank_by``
        (``"balanced"``, ``"transmission"`` or ``"compact"``)."""
    def best_drive(
        self,
        *,
        rank_by: RankBy = "balanced",
        progress: Optional[Progress] = None,
        **options: Unpack[DriveOptions],
    ) -> Drive:
        """The best drive of :meth:`drive_search` with its defaults: a
        motor for this linkage (what ``burmester.design(..., input="motor")``
        asks for a linkage whose input swings). The limits' ``input``
        requirement does not apply: a drive's crank always turns fully.
        Raises :class:`DriveError` saying why there is none
        (``"no_acceptable_drive"`` with the best transmission angle found,
        or why no drive can exist)."""
    # Driving it by a linear actuator added between the ground and a link.
    def actuator_map(
        self,
        *grid: Any,
        link: Literal["coupler", "crank", "rocker"] = "coupler",
        point: Optional[Point] = None,
        max_stroke_ratio: float = 1.8,
        samples: int = 256,
        actuator_width: float = 0.0,
        min_gap: float = 0.0,
        progress: Optional[Progress] = None,
        **options: Unpack[ActuatorMapOptions],
    ) -> ActuatorMap:
        """The actuator placement map: for every candidate ground pivot
        ``G`` on the grid (a :class:`Grid` or its six numbers), a linear
        actuator from ``G`` to ``point`` (where it is at pose 1) of ``link``
        (default: the coupler's ``A C`` middle, the crank's ``A``, the
        rocker's ``C``), added to this four-bar (whose own branch and order
        verdicts stand: it must be feasible). Each sample samples the travel
        from the first pose to the last at ``samples`` input angles (8 to
        16384): whether the length ``s = |Q - G|`` is monotone (no sign
        change of ``ds/dtheta2``), the stroke and the stroke ratio (longest
        over shortest, at most ``max_stroke_ratio``; a cylinder's is below
        2), the actuator's minimum force transmission angle (90 degrees
        minus the angle between its line and the velocity of ``Q``; at
        least the limits' ``min_transmission_deg``), the link and size
        ratios with the actuator, the strut's ``clearance`` (its least gap
        over the travel, refined as a placement's: its capsule ``actuator_width`` wide, its
        diameter in task units, default 0, against the links' capsules
        ``link_width`` wide, the obstacles and the envelope) and
        ``acceptable`` (the limits, and the clearance above 0 and at least
        ``min_gap``, task units, default 0). At most 2**20 samples
        (1024 x 1024). Releases the GIL; ``progress`` and Ctrl-C as
        :meth:`Filemon.solution_map`.

        Raises :class:`DriveError` (``"no_travel"``) for an infeasible
        linkage, :class:`DegenerateError` for a point on the crank's or the
        rocker's fixed pivot, :class:`InvalidInputError` for bad options (an
        unknown link, a stroke ratio limit below 1, a grid too large, a
        negative ``actuator_width`` or ``min_gap``)."""
    def actuator(
        self,
        ground: Point,
        link: Literal["coupler", "crank", "rocker"] = "coupler",
        point: Optional[Point] = None,
        max_stroke_ratio: float = 1.8,
        samples: int = 256,
        actuator_width: float = 0.0,
        min_gap: float = 0.0,
        **options: Unpack[ActuatorMapOptions],
    ) -> Actuator:
        """The actuator from the ground pivot ``ground`` (see
        :meth:`actuator_map`), its turning points refined by bisection and
        its minimum transmission angle by golden section. Raises
        :class:`DegenerateError` for a ground pivot on the point's path."""
    def _repr_png_(self) -> Optional[bytes]:
        """The picture Jupyter shows (see :mod:`burmester._display`): PNG
        bytes, or None when matplotlib is not installed."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...

# ---------------------------------------------------------------------------
# design

@final
class DesignLimits:
    """The designer's limits behind a solution map's ``acceptable`` mask.

    ``min_transmission_deg``: the smallest transmission angle allowed over
    the whole travel through the poses, degrees in [0, 90];
    ``max_link_ratio``: the largest ratio of the longest to the shortest
    link, at least 1 (``math.inf``: no limit); ``input``: ``"any"``,
    ``"crank"`` (the driving link must turn fully) or ``"rocker"`` (it must
    not); ``max_size_ratio``: the largest linkage relative to the task (its
    size, the total length of its members, over :attr:`Task.span`), at
    least 1 (default ``math.inf``: no limit); ``max_link_length``: the
    longest link in the task's units, above 0 (default ``math.inf``);
    ``min_grashof_margin``: the smallest distance from the Grashof change
    point, :attr:`LinkageFigures.grashof_margin`, in [0, 1] (default 0.01:
    every link may be off by 1% of its length, 1 mm on a 100 mm link,
    without the type flipping; 0: no limit). A change-point linkage (every
    kite) is one no designer builds: the balanced score's even links would
    otherwise pull the best designs onto it.
    Raises :class:`InvalidInputError` (``cause == "outside_range"``, with
    ``name``, ``value``, ``min``, ``max``) for a limit out of range.
    """

    def __new__(
        cls,
        min_transmission_deg: float = 30.0,
        max_link_ratio: float = 10.0,
        input: InputRequirement = "any",
        max_size_ratio: float = ...,
        max_link_length: float = ...,
        min_grashof_margin: float = 0.01,
    ) -> DesignLimits: ...
    @property
    def min_transmission_deg(self) -> float:
        """The smallest acceptable transmission angle, degrees."""
    @property
    def max_link_ratio(self) -> float:
        """The largest acceptable link ratio."""
    @property
    def input(self) -> InputRequirement:
        """Which input the design requires."""
    @property
    def max_size_ratio(self) -> float:
        """The largest acceptable size ratio (``math.inf``: no limit)."""
    @property
    def max_link_length(self) -> float:
        """The longest acceptable link, task units (``math.inf``: no limit)."""
    @property
    def min_grashof_margin(self) -> float:
        """The smallest acceptable Grashof margin (0: no limit)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __getnewargs__(self) -> Tuple[float, float, str, float, float, float]: ...

@final
class Pivot:
    """A candidate pivot of a solution map with its linkage (from
    :meth:`SolutionMap.best_pivots`)."""

    def __new__(
        cls,
        center: Point,
        index: Tuple[int, int],
        linkage: SynthesizedFourBar,
        margin: float,
        score: float,
        ranked_by: RankBy,
    ) -> Pivot: ...
    @property
    def center(self) -> Point:
        """The candidate center point (``A0`` for a driving map, ``C0`` for a
        driven one)."""
    @property
    def index(self) -> Tuple[int, int]:
        """Its sample ``(j, i)`` in the map: row ``j``, column ``i``."""
    @property
    def linkage(self) -> SynthesizedFourBar:
        """The complete linkage."""
    @property
    def figures(self) -> LinkageFigures:
        """The linkage's figures (``linkage.figures``)."""
    @property
    def margin(self) -> float:
        """Its signed margin to the nearest branch-defect boundary (see
        :meth:`SolutionMap.margin`)."""
    @property
    def size_ratio(self) -> float:
        """The linkage's size relative to the task's
        (:attr:`SynthesizedFourBar.size_ratio`)."""
    @property
    def score(self) -> float:
        """Its score by the ranking that chose it (see
        :meth:`SolutionMap.best_pivots`; the minimum transmission angle in
        radians on the Pareto front, the margin when ranked by margin)."""
    @property
    def ranked_by(self) -> RankBy:
        """What ranked it (see :meth:`SolutionMap.best_pivots`)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __getnewargs__(self) -> Tuple[Point, Tuple[int, int], SynthesizedFourBar, float, float, str]: ...

@final
class SliderPivot:
    """A candidate crank pivot of a solution map with a driven slider, with
    its slider-crank (from :meth:`SolutionMap.best_slider_pivots`)."""

    def __new__(
        cls,
        center: Point,
        index: Tuple[int, int],
        linkage: SynthesizedSliderCrank,
        margin: float,
        score: float,
        ranked_by: RankBy,
    ) -> SliderPivot: ...
    @property
    def center(self) -> Point:
        """The candidate crank pivot ``A0``."""
    @property
    def index(self) -> Tuple[int, int]:
        """Its sample ``(j, i)`` in the map: row ``j``, column ``i``."""
    @property
    def linkage(self) -> SynthesizedSliderCrank:
        """The complete slider-crank (:meth:`Task.slider_crank` of the crank
        of ``A0`` and the map's slider)."""
    @property
    def margin(self) -> float:
        """Its signed margin to the slider's transformed Filemon conic (see
        :meth:`SolutionMap.margin`)."""
    @property
    def size_ratio(self) -> float:
        """The slider-crank's size relative to the task's
        (:attr:`SynthesizedSliderCrank.size_ratio`)."""
    @property
    def score(self) -> float:
        """Its score by the ranking that chose it (as :attr:`Pivot.score`)."""
    @property
    def ranked_by(self) -> RankBy:
        """What ranked it (see :meth:`SolutionMap.best_slider_pivots`)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __getnewargs__(
        self,
    ) -> Tuple[Point, Tuple[int, int], SynthesizedSliderCrank, float, float, str]: ...

@final
class SolutionMap:
    """The solution-space map (from :meth:`Filemon.solution_map`,
    :meth:`SliderFilemon.solution_map` or :meth:`Task.driven_solution_map`): one read-only NumPy array per column,
    of shape ``(ny, nx)``, row ``j`` for ``y_j``, like
    :meth:`Filemon.branch_map` (allocated by NumPy and filled in place by the
    core, no copy)."""

    columns: list[str]
    """The names of the columns, in order."""
    grashof_names: list[str]
    """The Grashof class of each code of :attr:`grashof`."""
    @property
    def valid(self) -> BoolArray:
        """The linkage exists (a circle point, links of nonzero length)."""
    @property
    def branch_free(self) -> BoolArray:
        """Free of the branch defect."""
    @property
    def grashof(self) -> npt.NDArray[np.uint8]:
        """Grashof class as an index into :attr:`grashof_names`; 255 where invalid."""
    @property
    def input_full(self) -> BoolArray:
        """The driving link turns fully."""
    @property
    def direction(self) -> npt.NDArray[np.int8]:
        """The input rotation that carries the coupler through the poses in
        order: 1 ccw, -1 cw, 0 none (order defect or poses on different
        circuits)."""
    @property
    def one_circuit(self) -> BoolArray:
        """The input angles at the poses lie on one circuit (one arc of the
        input range)."""
    @property
    def min_transmission_rad(self) -> npt.NDArray[np.float32]:
        """Minimum transmission angle over the travel, **radians**; NaN where
        there is no feasible travel or no linkage."""
    @property
    def link_ratio(self) -> npt.NDArray[np.float32]:
        """Longest over shortest link; NaN where there is no linkage."""
    @property
    def size_ratio(self) -> npt.NDArray[np.float32]:
        """The linkage's size relative to the task's: the total length of its
        members (:attr:`SynthesizedFourBar.size`) over :attr:`Task.span`;
        NaN where there is no linkage."""
    @property
    def acceptable(self) -> BoolArray:
        """Feasible, branch-free, and within the limits and constraints."""
    @property
    def grid(self) -> Grid:
        """The grid of candidates."""
    @property
    def extent(self) -> Extent:
        """``(xmin, xmax, ymin, ymax)``, for ``imshow(..., extent=...)``."""
    @property
    def shape(self) -> Tuple[int, int]:
        """``(ny, nx)``."""
    @property
    def varying(self) -> Literal["driving", "driven"]:
        """Which center point the map varies."""
    @property
    def fixed_dyad(self) -> Tuple[Point, Point]:
        """The dyad that stays fixed: the driven ``(C0, C1)`` of a driving
        map, the driving ``(A0, A1)`` of a driven one; ``(C1, u)`` of a
        driven slider (:meth:`SliderFilemon.solution_map`)."""
    @property
    def fixed_kind(self) -> Literal["revolute", "slider"]:
        """The kind of the fixed dyad: ``"slider"`` for a map of
        :meth:`SliderFilemon.solution_map` (its linkages are slider-cranks,
        :meth:`slider_crank`), else ``"revolute"``."""
    @property
    def task(self) -> Task:
        """The task."""
    @property
    def limits(self) -> DesignLimits:
        """The limits behind :attr:`acceptable`."""
    def point(self, j: int, i: int) -> Point:
        """The candidate center point of sample ``[j, i]``."""
    def linkage(self, j: int, i: int) -> SynthesizedFourBar:
        """The linkage of sample ``[j, i]``; :class:`InvalidInputError`
        (``cause`` ``"driven_kind"``) on a map with a driven slider (use
        :meth:`slider_crank`)."""
    def slider_crank(self, j: int, i: int) -> SynthesizedSliderCrank:
        """The slider-crank of sample ``[j, i]`` of a map with a driven
        slider (:meth:`SliderFilemon.solution_map`); :class:`InvalidInputError`
        (``cause`` ``"driven_kind"``) on a map with a driven crank, as
        :meth:`linkage` for an invalid sample."""
    def margin(self, j: int, i: int) -> float:
        """The signed margin of sample ``[j, i]``: positive where branch-free.
        For a driving map the first-order distance to the nearer transformed
        Filemon curve (:meth:`Filemon.margin`); for a driven map the distance
        to the nearest sample of the other class."""
    def best_pivots(
        self, k: int = 5, min_separation: Optional[float] = None, rank_by: RankBy = "balanced"
    ) -> list[Pivot]:
        """The ``k`` best candidates, best first, as :class:`Pivot` records.

        With ``mu`` the minimum transmission angle over the travel, ``s`` the
        size ratio (:attr:`size_ratio`) and ``r`` the link ratio, the
        acceptable candidates are ordered by a score, larger is better:

        * ``"balanced"`` (default): ``sin(mu) / sqrt(s * r)``. ``sin(mu)`` is
          the share of the coupler's force that turns the output (0.64 at
          the classical 40 degree limit); the size and link ratios are
          scale-free and weighed alike on a log scale, so halving the
          linkage's size is worth what halving its link ratio is, and either
          what going from 45 to 90 degrees is.
        * ``"transmission"``: ``mu``.
        * ``"compact"``: ``-s``, the smallest linkage first.
        * ``"pareto"``: the Pareto front over ``mu`` and ``s`` (no acceptable
          candidate is as good in both and better in one), from the most
          compact to the best transmission (:meth:`pareto_front` gives all).
        * ``"margin"``: the valid, branch-free candidates (acceptable or
          not) by their margin, the fallback when nothing is acceptable.

        Scores within 1e-9 go to the smaller size ratio, then the larger margin. Candidates closer than
        ``min_separation`` (default: 2% of the viewport's diagonal) to a
        better one are skipped, so the list offers distinct options.

        The candidates are selected, not sorted (``O(n log k)`` for ``n``
        samples; the Pareto front sorts them); a large ``k`` or map releases
        the GIL and Ctrl-C raises :class:`KeyboardInterrupt`. A map with a
        driven slider raises :class:`InvalidInputError` (``cause``
        ``"driven_kind"``: a :class:`Pivot` carries a four-bar); rank it
        by :meth:`best_slider_pivots`."""
    def pareto_front(self) -> list[Pivot]:
        """Every acceptable candidate on the Pareto front of the minimum
        transmission angle (larger is better) and the size ratio (smaller is
        better), from the most compact to the best transmission:
        ``best_pivots(k=all, min_separation=0, rank_by="pareto")``."""
    def best_slider_pivots(
        self, k: int = 5, min_separation: Optional[float] = None, rank_by: RankBy = "balanced"
    ) -> list[SliderPivot]:
        """The ``k`` best candidate crank pivots ``A0`` of a map with a driven
        slider (:meth:`SliderFilemon.solution_map`), best first, as
        :class:`SliderPivot` records each with its slider-crank: the
        rankings of :meth:`best_pivots` (every ``rank_by``) on the
        slider-crank's columns: ``mu`` the transmission angle between the
        coupler and the guide's normal over the travel, the size ratio of
        :attr:`SynthesizedSliderCrank.size` (crank, coupler, the coupler
        triangle, the offset and the guide used), the link ratio of crank and
        coupler; the margin is the distance to the slider's transformed
        Filemon conic. :meth:`best_pivots` refuses such a map
        (:class:`InvalidInputError`, ``cause`` ``"driven_kind"``: its
        :class:`Pivot` carries a four-bar), and this method refuses a map with
        a driven crank the same way (rank it by :meth:`best_pivots`). ``k``
        has no upper bound (all candidates); a long ranking polls Ctrl-C."""
    def slider_pareto_front(self) -> list[SliderPivot]:
        """The Pareto front of a map with a driven slider (as
        :meth:`pareto_front`), as :class:`SliderPivot` records:
        ``best_slider_pivots(k=all, min_separation=0, rank_by="pareto")``."""
    def _repr_png_(self) -> Optional[bytes]:
        """The picture Jupyter shows (see :mod:`burmester._display`): PNG
        bytes, or None when matplotlib is not installed."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...
    @staticmethod
    def _from_state(
        grid: Grid,
        task: Task,
        varying: str,
        fixed: Tuple[Point, Point],
        limits: DesignLimits,
        constraints: Tuple[Optional[Sequence[Point]], Sequence[Sequence[Point]], float, int],
        columns: dict[str, Any],
    ) -> SolutionMap:
        """Rebuilds a map from its state (for pickling)."""


@final
class Pair:
    """A pair of dyads of a pair map with its linkage (from
    :meth:`PairMap.best_pairs`)."""

    def __new__(
        cls,
        driving: CurveDyad,
        driven: CurveDyad,
        index: Tuple[int, int],
        linkage: SynthesizedFourBar,
        margin: float,
        score: float,
        ranked_by: RankBy,
    ) -> Pair: ...
    @property
    def driving(self) -> CurveDyad:
        """The driving dyad ``(A0, A1)`` with its place on the curve."""
    @property
    def driven(self) -> CurveDyad:
        """The driven dyad ``(C0, C1)`` with its place on the curve."""
    @property
    def index(self) -> Tuple[int, int]:
        """Its pair ``(j, i)`` in the map: driven sample ``j`` (row), driving
        sample ``i`` (column)."""
    @property
    def linkage(self) -> SynthesizedFourBar:
        """The complete linkage: ``task.four_bar(driving.center, driven.center)``."""
    @property
    def figures(self) -> LinkageFigures:
        """The linkage's figures (``linkage.figures``)."""
    @property
    def margin(self) -> float:
        """Its signed margin (see :meth:`PairMap.margins`)."""
    @property
    def size_ratio(self) -> float:
        """The linkage's size relative to the task's
        (:attr:`SynthesizedFourBar.size_ratio`)."""
    @property
    def score(self) -> float:
        """Its score by the ranking that chose it (see
        :meth:`SolutionMap.best_pivots`)."""
    @property
    def ranked_by(self) -> RankBy:
        """What ranked it."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...
    @staticmethod
    def _from_state(
        task: Task,
        driving: CurveDyad,
        driven: CurveDyad,
        index: Tuple[int, int],
        margin: float,
        score: float,
        ranked_by: RankBy,
    ) -> Pair:
        """Rebuilds a pair from its state (for pickling)."""

@final
class PairMap:
    """The four-position pair map (from :meth:`Task.pair_map`): the columns
    of :class:`SolutionMap` over pairs of dyads, one read-only NumPy array
    per column of shape ``(n_driven, n_driving)``: row ``j`` is the driven
    dyad :attr:`driven_dyads` ``[j]``, column ``i`` the driving dyad
    :attr:`driving_dyads` ``[i]``. A pair of a dyad with itself is invalid
    (its ground has no length)."""

    columns: list[str]
    """The names of the columns, in order."""
    grashof_names: list[str]
    """The Grashof class of each code of :attr:`grashof`."""
    @property
    def valid(self) -> BoolArray:
        """The linkage exists (both dyads finite, links of nonzero length)."""
    @property
    def branch_free(self) -> BoolArray:
        """One assembly mode at the four poses."""
    @property
    def grashof(self) -> npt.NDArray[np.uint8]:
        """Grashof class as an index into :attr:`grashof_names`; 255 where invalid."""
    @property
    def input_full(self) -> BoolArray:
        """The driving link turns fully."""
    @property
    def direction(self) -> npt.NDArray[np.int8]:
        """The input rotation that carries the coupler through the four poses
        in order: 1 ccw, -1 cw, 0 none."""
    @property
    def one_circuit(self) -> BoolArray:
        """The input angles at the poses lie on one circuit."""
    @property
    def min_transmission_rad(self) -> npt.NDArray[np.float32]:
        """Minimum transmission angle over the travel, **radians**; NaN where
        there is no feasible travel or no linkage."""
    @property
    def link_ratio(self) -> npt.NDArray[np.float32]:
        """Longest over shortest link; NaN where there is no linkage."""
    @property
    def size_ratio(self) -> npt.NDArray[np.float32]:
        """The linkage's size over :attr:`Task.span`; NaN where there is no
        linkage."""
    @property
    def acceptable(self) -> BoolArray:
        """Feasible, branch-free, and within the limits and constraints."""
    @property
    def grid(self) -> Grid:
        """The parameter plane: ``x`` the driving dyad's curve parameter,
        ``y`` the driven dyad's, both over ``[0, 2L)`` radians of crank
        rotation (``grid.x(i)`` is the parameter of column ``i``)."""
    @property
    def extent(self) -> Extent:
        """``(0, 2L, 0, 2L)``, for ``imshow(..., extent=...)``."""
    @property
    def shape(self) -> Tuple[int, int]:
        """``(n_driven, n_driving)``."""
    @property
    def driving_dyads(self) -> list[Optional[CurveDyad]]:
        """The driving dyad of each column (its ``beta2`` and ``branch`` give
        its parameter); ``None`` where it is at infinity, or where
        :meth:`Task.four_bar` would refuse it (a sample of an ill-conditioned
        task that misses the poses by more than the dyad tolerance)."""
    @property
    def driven_dyads(self) -> list[Optional[CurveDyad]]:
        """The driven dyad of each row; ``None`` as for :attr:`driving_dyads`."""
    @property
    def task(self) -> Task:
        """The task."""
    @property
    def limits(self) -> DesignLimits:
        """The limits behind :attr:`acceptable`."""
    def linkage(self, j: int, i: int) -> SynthesizedFourBar:
        """The linkage of pair ``[j, i]`` (driven ``j``, driving ``i``):
        ``task.four_bar`` of the two dyads. Raises :class:`InvalidInputError`
        (``cause == "grid_index"``) for an index outside the map, naming it."""
    def margins(self) -> FloatArray:
        """The signed margin of every pair, shape :attr:`shape`: the distance
        in the parameter plane (radians of crank rotation) to the nearest
        pair of the other class in :attr:`branch_free`, positive where
        branch-free, infinite where the other class is empty."""
    def best_pairs(
        self, k: int = 5, min_separation: Optional[float] = None, rank_by: RankBy = "balanced"
    ) -> list[Pair]:
        """The ``k`` best pairs, best first, as :class:`Pair` records, by the
        rankings of :meth:`SolutionMap.best_pivots` (ties to the smaller
        linkage, then the larger margin of :meth:`margins`). Pairs closer
        than ``min_separation`` in the parameter plane (default: 2% of its
        diagonal) to a better one are skipped. Selected in ``O(n log k)``,
        Ctrl-C as :meth:`SolutionMap.best_pivots`."""
    def pareto_front(self) -> list[Pair]:
        """Every acceptable pair on the Pareto front of the minimum
        transmission angle and the size ratio, from the most compact to the
        best transmission."""
    def _repr_png_(self) -> Optional[bytes]:
        """The picture Jupyter shows (see :mod:`burmester._display`,
        :func:`burmester.plot.pair_map`): PNG bytes, or None when matplotlib
        is not installed."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...
    @staticmethod
    def _from_state(
        task: Task,
        shape: Tuple[int, int],
        limits: DesignLimits,
        constraints: Tuple[Optional[Sequence[Point]], Sequence[Sequence[Point]], float, int],
        columns: dict[str, Any],
    ) -> PairMap:
        """Rebuilds a map from its state (for pickling)."""

# ---------------------------------------------------------------------------
# The pivot-pair atlas (the public API is burmester.atlas)

def _atlas_tile(
    task: Task,
    driven: Grid,
    row_start: int,
    row_end: int,
    driving: Grid,
    *,
    rank_by: RankBy = "balanced",
    envelope: Optional[Sequence[Point]] = None,
    threads: Optional[int] = None,
    progress: Optional[Progress] = None,
    **options: Unpack[MapOptions],
) -> dict[str, npt.NDArray[Any]]:
    """Rows ``row_start..row_end`` of the pivot-pair atlas over the driven
    grid, as arrays of shape ``(rows, nx)`` (``best_driving``,
    ``best_index``: ``(rows, nx, 2)``): ``valid``, ``count``,
    ``branch_free``, ``best_transmission_rad``, ``best_link_ratio``,
    ``best_margin``, ``best_size_ratio``, ``best_score``, ``best_driving``,
    ``best_index``, each cell's best driving pivot by ``rank_by`` (a ranking
    with a score); on ``threads`` rayon threads (default: all cores). See
    :func:`burmester.pivot_atlas`."""

# ---------------------------------------------------------------------------
# The design search (the public API is burmester.design)

FoundBy = Literal["pivots", "parameters", "burmester", "slider_circle", "slider_point"]
LimitName = Literal[
    "branch_defect", "order", "transmission", "link_ratio", "input", "grashof_margin",
    "size_ratio", "link_length", "pivot_region", "obstacles", "envelope",
]

@final
class Space:
    """The space a design must fit in: where both fixed pivots may go
    (``pivot_box=(xmin, xmax, ymin, ymax)`` or a simple polygon
    ``pivot_polygon=[(x, y), ...]``; neither: anywhere), convex
    ``obstacles`` the moving links (capsules ``link_width`` wide) must clear
    over the whole travel, and an ``envelope`` (a simple polygon) the moving
    links and the coupler triangle with the coupler point must stay inside
    over the whole travel (it must contain every pose). Both are checked
    exactly over the travel (``travel_samples`` starting samples, then
    halving with a certified bound). The largest linkage is a limit:
    :attr:`DesignLimits.max_size_ratio`, :attr:`DesignLimits.max_link_length`.

    Raises :class:`InvalidInputError` naming the field: an inverted or
    empty box (``"pivot_box xmax"``), a polygon that is not simple
    (``"pivot_polygon"``, ``"envelope"``), an obstacle without an area,
    non-finite numbers."""

    def __new__(
        cls,
        pivot_box: Optional[Extent] = None,
        pivot_polygon: Optional[Sequence[Point]] = None,
        obstacles: Optional[Sequence[Sequence[Point]]] = None,
        link_width: float = 0.0,
        envelope: Optional[Sequence[Point]] = None,
        travel_samples: int = 64,
    ) -> Space: ...
    @property
    def region(self) -> Literal["anywhere", "box", "polygon"]:
        """What bounds the pivots."""
    @property
    def pivot_box(self) -> Optional[Extent]:
        """The pivot box, or None."""
    @property
    def pivot_polygon(self) -> Optional[list[Point]]:
        """The pivot polygon, or None."""
    @property
    def obstacles(self) -> list[list[Point]]:
        """The obstacles."""
    @property
    def link_width(self) -> float:
        """The moving links' width."""
    @property
    def envelope(self) -> Optional[list[Point]]:
        """The envelope, or None."""
    @property
    def travel_samples(self) -> int:
        """Where the motion's checks start along the travel."""
    def contains_pivot(self, p: Point) -> bool:
        """Whether a fixed pivot may go at ``p``."""
    def search_box(self, task: Task, limits: Optional[DesignLimits]) -> Extent:
        """The box the three-pose coarse pass samples pivots in: the
        region's bounds, or three task sizes around the poses, cut by the
        size limit's reach."""
    def __eq__(self, other: object, /) -> bool: ...
    def __getnewargs__(
        self,
    ) -> Tuple[Optional[Extent], Optional[list[Point]], list[list[Point]], float, Optional[list[Point]], int]: ...

@final
class Design:
    """One answer of :func:`burmester.design`: a linkage that is
    branch-free, carries the coupler through the poses in order on one
    circuit, meets the limits and fits the space, judged on its exact
    figures."""

    @property
    def linkage(self) -> Union[SynthesizedFourBar, SynthesizedSliderCrank]:
        """The linkage (its driving dyad drives): a four-bar, or with
        ``design(..., driven="slider")`` a slider-crank."""
    @property
    def figures(self) -> Optional[LinkageFigures]:
        """A four-bar's ``linkage.figures`` (None for a slider-crank, whose
        figures are the linkage's own properties)."""
    @property
    def driven_kind(self) -> Literal["revolute", "slider"]:
        """``"revolute"`` for a four-bar, ``"slider"`` for a slider-crank."""
    @property
    def score(self) -> float:
        """Its score by the ranking (exact figures)."""
    @property
    def size_ratio(self) -> float:
        """Its size over the task's."""
    @property
    def ranked_by(self) -> RankBy:
        """What ranked it."""
    @property
    def driving_pivot(self) -> Point:
        """The driving crank's fixed pivot ``A0``."""
    @property
    def driven_pivot(self) -> Optional[Point]:
        """The driven crank's fixed pivot ``C0`` (None for a slider-crank:
        its guide, ``linkage.driven``, needs no pivot)."""
    @property
    def found_by(self) -> FoundBy:
        """What ``coarse`` and ``refined`` hold: the fixed pivots
        ``(A0, C0)`` (three poses), the curve parameters ``(s_driving,
        s_driven)`` (four) or the Burmester points' indices (five)."""
    @property
    def coarse(self) -> Any:
        """Where the coarse pass found it."""
    @property
    def refined(self) -> Any:
        """Where the refinement took it."""
    @property
    def coarse_score(self) -> float:
        """The coarse sample's score."""
    @property
    def evaluations(self) -> int:
        """Linkages its refinement judged."""
    @property
    def drive(self) -> Optional[Drive]:
        """With a motor (``design(..., input="motor")``): the drive added to
        a linkage whose input swings, the six-bar a motor turns through the
        poses (found under the report's limits, ranking and space: the
        drive's crank pivot on the pivot region, its links clear of the
        obstacles over a full crank turn); None without a motor, or when the
        input turns fully (the motor turns it directly)."""
    @property
    def actuator(self) -> Optional[Actuator]:
        """With a linear actuator (``design(..., input="actuator")``): its
        placement, found with the linkage (monotone, within the stroke
        ratio and the limits, clear of the links, obstacles and envelope
        over the travel); None without."""
    @staticmethod
    def _from_state(
        task: Task,
        driving: Tuple[Point, Point],
        driven: Tuple[Point, Point],
        score: float,
        size_ratio: float,
        ranked_by: str,
        kind: str,
        coarse: Tuple[Sequence[float], float],
        refined: Sequence[float],
        evaluations: int,
        attached: Tuple[Optional[Drive], Optional[Actuator]] = ...,
    ) -> Design:
        """Rebuilds a design from its state (for pickling)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]: ...
    def _repr_png_(self) -> Optional[bytes]:
        """The linkage's picture for Jupyter, or None without matplotlib."""

@final
class NearMiss:
    """A candidate with a feasible motion that misses limits (listed when
    nothing fits): ``shortfall`` is its worst relative shortfall."""

    @property
    def linkage(self) -> Union[SynthesizedFourBar, SynthesizedSliderCrank]:
        """The linkage (a four-bar, or a slider-crank)."""
    @property
    def figures(self) -> Optional[LinkageFigures]:
        """A four-bar's ``linkage.figures`` (None for a slider-crank)."""
    @property
    def driven_kind(self) -> Literal["revolute", "slider"]:
        """``"revolute"`` for a four-bar, ``"slider"`` for a slider-crank."""
    @property
    def size_ratio(self) -> float:
        """Its size over the task's."""
    @property
    def misses(self) -> list[LimitName]:
        """The limits it misses."""
    @property
    def shortfall(self) -> float:
        """How far it misses them (0 would be acceptable)."""
    @staticmethod
    def _from_state(
        task: Task,
        driving: Tuple[Point, Point],
        driven: Tuple[Point, Point],
        size_ratio: float,
        misses: Sequence[str],
        shortfall: float,
        driven_kind: str = "revolute",
    ) -> NearMiss:
        """Rebuilds a near miss from its state (for pickling)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]: ...

@final
class DesignReport:
    """What :func:`burmester.design` found: a sequence of :class:`Design`,
    best first and distinct (``len``, indexing, iteration), with the limits,
    space and ranking it ran under. Without designs, ``rejections`` says how
    many census candidates failed each limit (the most first) and
    ``near_misses`` the nearest misses."""

    @property
    def task(self) -> Task:
        """The task."""
    @property
    def designs(self) -> list[Design]:
        """The designs, best first."""
    @property
    def near_misses(self) -> list[NearMiss]:
        """When nothing fits: the nearest misses, nearest first."""
    @property
    def rejections(self) -> list[Tuple[LimitName, int]]:
        """When nothing fits: census candidates failing each limit."""
    @property
    def main_rejection(self) -> Optional[LimitName]:
        """The limit that rejected the most census candidates."""
    @property
    def census(self) -> int:
        """Candidates the census judged (0 when designs were found)."""
    @property
    def limits(self) -> DesignLimits:
        """The limits used."""
    @property
    def space(self) -> Space:
        """The space used."""
    @property
    def rank_by(self) -> RankBy:
        """The ranking used."""
    @property
    def min_separation(self) -> float:
        """The least distance between two designs' pivots."""
    @property
    def search_box(self) -> Optional[Extent]:
        """Three poses: the coarse pass's box."""
    @property
    def coarse_candidates(self) -> int:
        """Candidates of the coarse pass."""
    @property
    def coarse_acceptable(self) -> int:
        """Of them acceptable."""
    @property
    def evaluations(self) -> int:
        """Linkages the refinements judged."""
    @property
    def undriven(self) -> int:
        """With a motor: candidates passed over because no drive for them
        was acceptable (each would otherwise have been a design); 0
        without a motor."""
    @property
    def motor(self) -> bool:
        """Whether the designs were searched with a motor
        (``input="motor"``)."""
    @property
    def swing_margin_deg(self) -> Optional[float]:
        """The motor's swing margin, degrees (None without a motor)."""
    @property
    def max_time_ratio(self) -> Optional[float]:
        """The motor's largest time ratio (None without a motor)."""
    @property
    def actuator(self) -> bool:
        """Whether the designs were searched with a linear actuator
        (``input="actuator"``)."""
    @property
    def unplaced(self) -> int:
        """With a linear actuator: candidates passed over because no clear,
        acceptable placement was found for them; 0 without."""
    @property
    def actuator_max_size_ratio(self) -> Optional[float]:
        """With a linear actuator: the largest size ratio of a design with
        its open actuator (the ``actuator_max_size_ratio`` keyword of
        :func:`burmester.design`, else :attr:`limits`'
        ``max_size_ratio``; ``inf``: no limit); None without."""
    def __len__(self) -> int: ...
    def __getitem__(self, index: int, /) -> Design: ...
    def __iter__(self) -> Iterator[Design]: ...
    @staticmethod
    def _from_state(
        task: Task,
        designs: Sequence[Design],
        limits: DesignLimits,
        space: Space,
        rank_by: str,
        min_separation: float,
        search_box: Optional[Extent],
        counts: Tuple[int, int, int, int],
        rejections: Sequence[Tuple[str, int]],
        near_misses: Sequence[NearMiss],
        inputs: Tuple[
            Optional[Tuple[float, float]],
            Optional[
                Union[
                    Tuple[str, float, int, Optional[Point], int, Optional[float]],
                    Tuple[str, float, int, Optional[Point], int],
                ]
            ],
        ] = ...,
        passed: Union[Tuple[int, int], Tuple[int, int, Optional[Tuple[float, float]]]] = ...,
    ) -> DesignReport:
        """Rebuilds a report from its state (for pickling)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]: ...

class _DesignOptions(TypedDict, total=False):
    """The keywords of the native design functions: those of
    :func:`burmester.design`, with its defaults (space None, limits None,
    rank_by "balanced", top 5, min_separation None, coarse_driven 12,
    coarse_driving 48, coarse_pairs 120, starts 48, max_iterations 3000,
    input None, swing_margin_deg 0.0, max_time_ratio None, actuator_link
    "coupler", actuator_point None, max_stroke_ratio 1.8, actuator_samples
    64, actuator_width 0.0, min_gap 0.0, actuator_max_size_ratio None,
    driven "revolute")."""

    space: Optional[Space]
    limits: Optional[DesignLimits]
    rank_by: RankBy
    top: int
    min_separation: Optional[float]
    coarse_driven: int
    coarse_driving: int
    coarse_pairs: int
    starts: int
    max_iterations: int
    input: Optional[Literal["any", "crank", "rocker", "motor", "actuator"]]
    swing_margin_deg: float
    max_time_ratio: Optional[float]
    actuator_link: str
    actuator_point: Optional[Point]
    max_stroke_ratio: float
    actuator_samples: int
    actuator_width: float
    min_gap: float
    actuator_max_size_ratio: Optional[float]
    driven: Literal["revolute", "slider"]

def _design(
    task: Task,
    *,
    progress: Optional[Progress] = None,
    **options: Unpack[_DesignOptions],
) -> DesignReport:
    """The design search in this process (see :func:`burmester.design`,
    whose defaults these keywords share: top 5, coarse_driven 12,
    coarse_driving 48, coarse_pairs 120, starts 48, max_iterations 3000)."""

def _design_plan(
    task: Task,
    *,
    progress: Optional[Progress] = None,
    **options: Unpack[_DesignOptions],
) -> dict[str, Any]:
    """The three-pose coarse pass: ``driven`` and ``driving`` grids and the
    ``atlas`` keywords of :func:`_atlas_tile`."""

def _design_from_atlas(
    task: Task,
    arrays: dict[str, Any],
    *,
    progress: Optional[Progress] = None,
    **options: Unpack[_DesignOptions],
) -> DesignReport:
    """The refinement of a three-pose coarse pass computed elsewhere
    (``arrays``: :func:`_atlas_tile`'s arrays over the plan's driven grid)."""

# ---------------------------------------------------------------------------
# A motor for a linkage whose input swings: the Watt II six-bar

@final
class SixBar:
    """A Watt II six-bar: a drive four-bar ``D0 D E A0`` (the motor's crank
    ``D0 D``, the drive coupler ``D E``, the rocker ``A0 E``) whose rocker is
    rigid with the input link ``A0 A`` of a motion four-bar ``A0 A C C0``
    (coupler ``A C`` carrying the coupler point ``P``, rocker ``C0 C``).

    Built from where its joints are in one position (keywords only: the
    letters name the joints); the lengths, each loop's assembly mode and the
    angle of the ternary link ``A0 A E`` are read from them. ``p`` defaults
    to ``C``. Raises :class:`DegenerateError` (``"zero_length_link"``) for
    two joints of a link that coincide, :class:`DriveError`
    (``"toggle_joints"``) for a loop at a toggle there.

    The crank angle ``phi`` is absolute (the direction of ``D - D0``).
    Position analysis solves the drive loop at ``phi`` and then the motion
    loop at ``theta2 = psi - delta`` (``psi = arg(E - A0)``), both by
    :meth:`FourBar.solve` in their own modes."""

    def __new__(
        cls, *, d0: Point, d: Point, e: Point, a0: Point, a: Point, c: Point, c0: Point,
        p: Optional[Point] = None,
    ) -> SixBar: ...
    @staticmethod
    def _from_parts(
        drive: FourBar, motion: FourBar, attachment_angle: float, drive_mode: Mode,
        motion_mode: Mode, coupler_point: Point, coupler_angle_offset: float,
    ) -> SixBar:
        """Rebuilds a six-bar from its two loops (for pickling)."""
    def __reduce__(self) -> Tuple[Any, ...]: ...
    def __eq__(self, other: object, /) -> bool: ...
    @property
    def drive(self) -> FourBar:
        """The drive loop (input pivot ``D0``, output pivot ``A0``)."""
    @property
    def motion(self) -> FourBar:
        """The motion loop (input pivot ``A0``, output pivot ``C0``)."""
    @property
    def drive_mode(self) -> Mode:
        """The drive loop's assembly mode."""
    @property
    def motion_mode(self) -> Mode:
        """The motion loop's assembly mode."""
    @property
    def attachment_angle(self) -> float:
        """``delta = arg(E - A0) - arg(A - A0)``, radians."""
    @property
    def coupler_point(self) -> Point:
        """The coupler point in the coupler's frame (origin ``A``, x toward ``C``)."""
    @property
    def coupler_angle_offset(self) -> float:
        """The pose angle minus the coupler angle."""
    @property
    def drive_pivot(self) -> Point:
        """``D0``, the motor's pivot."""
    @property
    def lengths(self) -> list[float]:
        """The eight links: drive ground ``|A0 D0|``, crank, drive coupler,
        rocker ``|A0 E|``, input ``|A0 A|``, coupler, output rocker, ground
        ``|A0 C0|``."""
    @property
    def attachment_side(self) -> float:
        """``|E - A|``, the third side of the ternary input link (0 when
        ``E`` is ``A``)."""
    @property
    def link_ratio(self) -> float:
        """Longest over shortest of the eight links."""
    @property
    def size(self) -> float:
        """The total length of the members (the links, ``|E - A|`` and the
        coupler triangle's sides to ``P``)."""
    @property
    def drive_grashof(self) -> GrashofType:
        """The drive loop's Grashof type (``"crank-rocker"`` for a motor drive)."""
    @property
    def crank_turns_fully(self) -> bool:
        """The drive is a crank-rocker and the motion loop's input stays
        strictly inside its input range over the swing: the motor turns the
        crank round and round, neither loop toggling."""
    @property
    def limit_positions(self) -> Optional[list[Tuple[float, float, float, bool]]]:
        """The two limit positions (crank and drive coupler collinear, where
        the input reverses), extended first: ``(crank_angle, rocker_angle,
        input_angle, extended)``; None unless the drive is a crank-rocker."""
    @property
    def swing(self) -> Optional[Tuple[float, float]]:
        """``(start, end)`` of the motion input's swing, counter-clockwise;
        None unless the drive is a crank-rocker."""
    @property
    def stroke_angle(self) -> Optional[float]:
        """The crank's turn from the extended limit position to the folded one."""
    @property
    def time_ratio(self) -> Optional[float]:
        """The slower stroke over the faster at a constant crank speed (at least 1)."""
    @property
    def min_transmission_deg(self) -> Optional[Tuple[float, float]]:
        """``(drive, motion)``: each loop's smallest transmission angle over
        a full crank turn, degrees (exact); None unless the crank turns fully."""
    @property
    def dead_positions(self) -> list[float]:
        """Crank angles where a loop toggles (empty when the crank turns fully)."""
    def solve(self, phi: float) -> Tuple[float, float, float, float]:
        """``(psi, theta2, theta3, theta4)`` at crank angle ``phi``: the
        rocker ``A0 E``, the motion loop's input, coupler and rocker angles.
        Raises :class:`AssemblyError` where a loop does not close."""
    def transmission_angles(self, phi: float) -> Tuple[float, float]:
        """``(drive, motion)`` transmission angles at ``phi``, radians in [0, pi/2]."""
    def toggle(self, phi: float) -> bool:
        """Whether a loop is at a toggle at ``phi``."""
    def joints(self, phi: float) -> list[Point]:
        """``[D0, D, E, A0, A, C, C0, P]`` at crank angle ``phi``."""
    def pose_at(self, phi: float) -> Pose:
        """``(x, y, angle)`` of the coupler point at crank angle ``phi``."""
    def coupler_path(self, phis: ArrayLike) -> Tuple[FloatArray, FloatArray, BoolArray]:
        """The coupler point at each crank angle: ``(xs, ys, valid)`` of the
        input's shape (NaN and False where a loop does not close)."""
    def crank_angles(self, start: float = 0.0, samples: int = 360) -> list[float]:
        """``samples`` crank angles over one turn from ``start`` (2 to 2^20)."""
    def crank_angles_for_input(self, theta2: float) -> list[float]:
        """The crank angles (0, 1 or 2, one per stroke) at which the motion
        loop's input is ``theta2``."""
    def _repr_png_(self) -> Optional[bytes]:
        """The picture Jupyter shows (:func:`burmester.plot.sixbar`)."""

# A drive's or drive map's options as pickled: the limits, (swing margin,
# time ratio), the constraints (base plate, obstacles, link width, travel samples).
_DriveState = Tuple[
    DesignLimits,
    Tuple[float, float],
    Tuple[Optional[Sequence[Point]], Sequence[Sequence[Point]], float, int],
]

@final
class Drive:
    """A drive for a linkage: the six-bar, the crank angles at the poses and
    what a designer checks (from :meth:`SynthesizedFourBar.best_drive`,
    :meth:`DriveMap.best_drives`, :meth:`SynthesizedFourBar.drive`, ...)."""

    @staticmethod
    def _from_state(
        linkage: SynthesizedFourBar, drive_pivot: Point, attachment: Point, state: _DriveState,
        ranked: Tuple[Optional[Tuple[int, int]], float, float, Optional[str]],
    ) -> Drive:
        """Rebuilds a drive from its state (for pickling)."""
    def __reduce__(self) -> Tuple[Any, ...]: ...
    def __eq__(self, other: object, /) -> bool: ...
    @property
    def sixbar(self) -> SixBar:
        """The six-bar: the drive loop and the linkage as its motion loop."""
    @property
    def linkage(self) -> SynthesizedFourBar:
        """The linkage driven."""
    @property
    def task(self) -> Task:
        """The linkage's task."""
    @property
    def drive_pivot(self) -> Point:
        """``D0``, the motor's crank pivot."""
    @property
    def attachment(self) -> Point:
        """``E`` where it is at pose 1."""
    @property
    def pose_crank_angles(self) -> list[float]:
        """The crank angle at each pose on the working stroke, from its start
        in the motor's direction (monotone, unwrapped)."""
    @property
    def stroke_start(self) -> float:
        """The crank angle where the working stroke starts (a limit position)."""
    @property
    def direction(self) -> Direction:
        """The motor's direction: the one that makes the working stroke
        (first pose to last) the slower."""
    @property
    def acceptable(self) -> bool:
        """It meets the limits, the time ratio and the constraints it was
        found under."""
    @property
    def index(self) -> Optional[Tuple[int, int]]:
        """Its sample ``(j, i)`` in a drive map, if it came from one."""
    @property
    def margin(self) -> float:
        """Its distance to the nearest map sample without a drive (NaN
        unless it came from a map)."""
    @property
    def score(self) -> float:
        """Its score by the ranking that chose it (NaN otherwise)."""
    @property
    def ranked_by(self) -> Optional[RankBy]:
        """The ranking that chose it."""
    @property
    def limits(self) -> DesignLimits:
        """The limits it was judged under."""
    @property
    def swing_margin_deg(self) -> float:
        """The swing margin at each end, degrees."""
    @property
    def min_transmission_deg(self) -> float:
        """The smaller of both loops' minimum transmission angles over a full
        crank turn, degrees."""
    @property
    def drive_transmission_deg(self) -> float:
        """The drive loop's minimum over a full turn, degrees."""
    @property
    def motion_transmission_deg(self) -> float:
        """The motion loop's minimum over the swing, degrees."""
    @property
    def time_ratio(self) -> float:
        """The working stroke's time over the return's (at least 1)."""
    @property
    def link_ratio(self) -> float:
        """The six-bar's longest over shortest link."""
    @property
    def size_ratio(self) -> float:
        """The six-bar's size over the task's span."""
    @property
    def swing(self) -> Tuple[float, float]:
        """The motion input's angle at the start and the end of the working
        stroke (the travel extended by the margins)."""
    @property
    def stroke(self) -> float:
        """The crank's turn over the working stroke, radians (pi at time ratio 1)."""
    def turn_angles(self, samples: int = 120) -> list[float]:
        """``samples`` crank angles over one turn from the working stroke's
        start in the motor's direction."""
    def pose_at(self, phi: float) -> Pose:
        """``(x, y, angle)`` of the coupler point at crank angle ``phi``."""
    def _repr_png_(self) -> Optional[bytes]:
        """The picture Jupyter shows (:func:`burmester.plot.sixbar`)."""

@final
class DriveMap:
    """A drive map (from :meth:`SynthesizedFourBar.drive_map`): one read-only
    NumPy array per column, of shape ``(ny, nx)``, over candidate crank
    pivots ``D0``."""

    columns: list[str]
    """The names of the columns, in order."""
    @property
    def valid(self) -> BoolArray:
        """A drive exists: a crank-rocker whose rocker swings exactly over
        the travel with its margins, the six-bar turning fully."""
    @property
    def min_transmission_rad(self) -> npt.NDArray[np.float32]:
        """The smaller of both loops' minimum transmission angles over a
        full crank turn, **radians**; NaN where there is no drive."""
    @property
    def drive_transmission_rad(self) -> npt.NDArray[np.float32]:
        """The drive loop's own minimum over a full turn, radians."""
    @property
    def time_ratio(self) -> npt.NDArray[np.float32]:
        """The slower stroke over the faster (at least 1)."""
    @property
    def link_ratio(self) -> npt.NDArray[np.float32]:
        """The six-bar's longest over shortest link."""
    @property
    def size_ratio(self) -> npt.NDArray[np.float32]:
        """The six-bar's size over the task's span."""
    @property
    def acceptable(self) -> BoolArray:
        """A drive within the limits, the time ratio and the constraints."""
    @property
    def grid(self) -> Grid:
        """The grid of candidate crank pivots."""
    @property
    def extent(self) -> Extent:
        """``(xmin, xmax, ymin, ymax)``."""
    @property
    def shape(self) -> Tuple[int, int]:
        """``(ny, nx)``."""
    @property
    def linkage(self) -> SynthesizedFourBar:
        """The linkage driven."""
    @property
    def attachment(self) -> Point:
        """``E`` at pose 1."""
    @property
    def attachment_ends(self) -> Tuple[Point, Point]:
        """Where ``E`` is at the two ends of the swing, the first pose's first."""
    @property
    def swing(self) -> Tuple[float, float]:
        """The motion input's angle at the two ends of the swing."""
    @property
    def motion_transmission_deg(self) -> float:
        """The motion loop's minimum transmission angle over the swing (the
        same for every drive of the map), degrees."""
    @property
    def limits(self) -> DesignLimits:
        """The limits behind :attr:`acceptable`."""
    @property
    def swing_margin_deg(self) -> float:
        """The swing margin at each end, degrees."""
    @property
    def max_time_ratio(self) -> float:
        """The largest acceptable time ratio."""
    def point(self, j: int, i: int) -> Point:
        """The candidate crank pivot of sample ``[j, i]``."""
    def drive(self, j: int, i: int) -> Drive:
        """The drive of sample ``[j, i]`` (:class:`DriveError` where there is none)."""
    def best_drives(
        self, k: int = 5, min_separation: Optional[float] = None, rank_by: RankBy = "balanced"
    ) -> list[Drive]:
        """The ``k`` best drives, best first, by the rankings of
        :meth:`SolutionMap.best_pivots` over the acceptable samples (``mu``
        the smaller transmission angle of both loops, ``s`` the six-bar's
        size ratio, ``r`` its link ratio); ``"margin"`` orders the valid
        samples by their distance to the nearest sample without a drive."""
    def pareto_front(self) -> list[Drive]:
        """The acceptable drives on the Pareto front of transmission and size."""
    def classic_drive(
        self, beyond_first: bool = True, drive_transmission_deg: Optional[float] = None
    ) -> Drive:
        """The closed-form drive of time ratio 1 in this map's context (see
        :meth:`SynthesizedFourBar.classic_drive`)."""
    def _repr_png_(self) -> Optional[bytes]:
        """The picture Jupyter shows (:func:`burmester.plot.drive_map`)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...
    @staticmethod
    def _from_state(
        linkage: SynthesizedFourBar, attachment: Point, grid: Grid, state: _DriveState,
        columns: dict[str, Any],
    ) -> DriveMap:
        """Rebuilds a map from its state (for pickling)."""

def unit_time_ratio_crank_rocker(
    rocker: float, swing_deg: float, min_transmission_deg: float
) -> Tuple[float, float, float, float]:
    """``(ground, crank, coupler, rocker)`` of the crank-rocker with time
    ratio 1 whose rocker swings ``swing_deg`` and whose smallest
    transmission angle over a full turn is ``min_transmission_deg`` (below
    ``90 - swing_deg / 2``): Norton's construction (*Design of Machinery*,
    Example 3-1), Brodell and Soni's equations."""

@final
class Actuator:
    """A linear actuator added between a ground pivot and a point of a
    moving link of a four-bar (from :meth:`SynthesizedFourBar.actuator` or
    :meth:`ActuatorMap.best_placements`). Lengths in the task's units,
    angles in radians unless named ``_deg``."""

    @property
    def linkage(self) -> SynthesizedFourBar:
        """The four-bar it drives."""
    @property
    def link(self) -> str:
        """``"coupler"``, ``"crank"`` or ``"rocker"``."""
    @property
    def ground(self) -> Tuple[float, float]:
        """The ground pivot ``G``."""
    @property
    def point(self) -> Tuple[float, float]:
        """The moving point ``Q``, where it is at pose 1."""
    @property
    def pose_lengths(self) -> list[float]:
        """The actuator's length at each pose (exact)."""
    @property
    def monotone(self) -> bool:
        """Its length is monotone from the first pose to the last."""
    @property
    def extends(self) -> bool:
        """Its length grows from the first pose to the last."""
    @property
    def turning_points(self) -> list[float]:
        """The input angles inside the travel where ``ds/dtheta2`` changes
        sign (dead points; empty when monotone)."""
    @property
    def min_length(self) -> float:
        """The shortest length over the travel (closed)."""
    @property
    def max_length(self) -> float:
        """The longest length over the travel (open)."""
    @property
    def stroke(self) -> float:
        """``max_length - min_length``."""
    @property
    def stroke_ratio(self) -> float:
        """``max_length / min_length``."""
    @property
    def min_transmission_deg(self) -> float:
        """The minimum force transmission angle over the travel, degrees
        (0 when not monotone)."""
    @property
    def worst_angle(self) -> float:
        """The input angle where it is reached, radians."""
    @property
    def link_ratio(self) -> float:
        """The longest over the shortest member, the actuator among them."""
    @property
    def size_ratio(self) -> float:
        """The linkage and the open actuator over the task's span."""
    @property
    def acceptable(self) -> bool:
        """Monotone and within the limits it was placed under."""
    @property
    def index(self) -> Optional[Tuple[int, int]]:
        """Its sample ``(j, i)`` in a map, if it came from one."""
    @property
    def margin(self) -> float:
        """Its distance to the nearest non-monotone sample, grid units (NaN
        when not from a map)."""
    @property
    def score(self) -> float:
        """Its score by the ranking that chose it (NaN otherwise)."""
    @property
    def ranked_by(self) -> Optional[str]:
        """The ranking that chose it."""
    @property
    def max_stroke_ratio(self) -> float:
        """The stroke ratio limit it was placed under."""
    @property
    def limits(self) -> DesignLimits:
        """The limits it was placed under."""
    @property
    def min_clearance(self) -> float:
        """The smallest gap over the travel between the strut (its line
        from ``G`` to ``Q``, a capsule :attr:`actuator_width` wide) and the
        links that do not carry ``Q`` (capsules :attr:`link_width` wide),
        the obstacles and the envelope's boundary; negative where they
        overlap (a strut through its own link's bar counts as an
        overlap)."""
    @property
    def clearance_angle(self) -> float:
        """The input angle where the gap is smallest, radians."""
    @property
    def clear(self) -> bool:
        """The strut stays clear over the travel: ``min_clearance`` above 0
        and at least :attr:`min_gap` (``acceptable`` requires it)."""
    @property
    def actuator_width(self) -> float:
        """The strut's diameter its clearance was measured with (task
        units; one diameter for the strut: its body's)."""
    @property
    def min_gap(self) -> float:
        """The least gap it had to keep (task units)."""
    @property
    def link_width(self) -> float:
        """The links' width its clearance was measured with (task units)."""
    def at(self, theta2: float) -> Tuple[Tuple[float, float], float]:
        """``((x, y), s)``: the moving point and the length at input angle
        ``theta2``."""
    def travel(
        self, samples: int = 64
    ) -> Tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
        """``(theta2, x, y, s)`` over the travel, first pose to last."""
    def __eq__(self, other: object, /) -> bool: ...
    def _repr_png_(self) -> Optional[bytes]:
        """A picture for Jupyter (:mod:`burmester._display`): PNG bytes, or None without matplotlib."""
    def __reduce__(self) -> Tuple[Any, ...]: ...
    @staticmethod
    def _from_state(
        linkage: SynthesizedFourBar, point: Point, ground: Point, limits: DesignLimits,
        options: Tuple[str, float, int],
        constraints: Tuple[Optional[Sequence[Point]], Sequence[Sequence[Point]], float, int],
        extra: Tuple[Optional[Tuple[int, int]], float, float, Optional[str]],
        envelope: Optional[Sequence[Point]] = None,
        strut: Optional[Tuple[float, float]] = None,
    ) -> Actuator:
        """Rebuilds a placement from its state (for pickling)."""

@final
class ActuatorMap:
    """An actuator placement map (from
    :meth:`SynthesizedFourBar.actuator_map`): one read-only NumPy array per
    column, of shape ``(ny, nx)``, over candidate ground pivots ``G``."""

    columns: list[str]
    """The names of the columns, in order."""
    @property
    def valid(self) -> BoolArray:
        """The actuator has a length over the whole travel."""
    @property
    def monotone(self) -> BoolArray:
        """Its length is monotone from the first pose to the last."""
    @property
    def extends(self) -> BoolArray:
        """Its length grows from the first pose to the last."""
    @property
    def min_transmission_rad(self) -> npt.NDArray[np.float32]:
        """The minimum force transmission angle over the sampled travel,
        **radians**; NaN where not valid."""
    @property
    def stroke_ratio(self) -> npt.NDArray[np.float32]:
        """Longest over shortest length over the travel."""
    @property
    def stroke(self) -> npt.NDArray[np.float32]:
        """Longest minus shortest length."""
    @property
    def closed_length(self) -> npt.NDArray[np.float32]:
        """The shortest length."""
    @property
    def link_ratio(self) -> npt.NDArray[np.float32]:
        """Longest over shortest member, the actuator among them."""
    @property
    def size_ratio(self) -> npt.NDArray[np.float32]:
        """The linkage and the open actuator over the task's span."""
    @property
    def clearance(self) -> npt.NDArray[np.float32]:
        """The strut's least gap over the travel, task units: its capsule
        (:attr:`actuator_width`) to the links' capsules (``link_width``),
        the obstacles and the envelope; negative where they overlap.
        Computed where the rest of ``acceptable`` holds (monotone, within
        the limits, on the base plate); NaN elsewhere. Refined as the
        sample's placement's: its :attr:`Actuator.min_clearance`."""
    @property
    def acceptable(self) -> BoolArray:
        """Monotone and within the limits and the base plate, and clear:
        ``clearance`` above 0 and at least :attr:`min_gap`; judged as the
        sample's placement is (on its refined gap and transmission angle),
        so a ranked placement is acceptable by its own figures."""
    @property
    def grid(self) -> Grid:
        """The grid of candidate ground pivots."""
    @property
    def extent(self) -> Tuple[float, float, float, float]:
        """``(xmin, xmax, ymin, ymax)``."""
    @property
    def shape(self) -> Tuple[int, int]:
        """``(ny, nx)``."""
    @property
    def linkage(self) -> SynthesizedFourBar:
        """The four-bar driven."""
    @property
    def link(self) -> str:
        """The link the actuator acts on."""
    @property
    def point(self) -> Tuple[float, float]:
        """The moving point ``Q`` at pose 1."""
    @property
    def point_at_poses(self) -> list[Tuple[float, float]]:
        """Where ``Q`` is at each pose."""
    @property
    def limits(self) -> DesignLimits:
        """The limits behind ``acceptable``."""
    @property
    def max_stroke_ratio(self) -> float:
        """The stroke ratio limit."""
    @property
    def samples(self) -> int:
        """The input angles sampling the travel."""
    @property
    def actuator_width(self) -> float:
        """The strut's diameter behind ``clearance`` (task units)."""
    @property
    def min_gap(self) -> float:
        """The least gap behind ``acceptable`` (task units)."""
    def ground(self, j: int, i: int) -> Tuple[float, float]:
        """The candidate ground pivot of sample ``(j, i)``."""
    def placement(self, j: int, i: int) -> Actuator:
        """The placement of sample ``(j, i)`` (refined)."""
    def best_placements(
        self, /, k: int = 5, min_separation: Optional[float] = None,
        rank_by: RankBy = "balanced",
    ) -> list[Actuator]:
        """The ``k`` best placements by ``rank_by`` over the acceptable
        samples (``"margin"``: the monotone ones by their distance to the
        nearest non-monotone sample), at least ``min_separation`` apart
        (default 2% of the view's diagonal)."""
    def pareto_front(self) -> list[Actuator]:
        """The acceptable placements on the Pareto front of transmission
        and size."""
    def __eq__(self, other: object, /) -> bool: ...
    def _repr_png_(self) -> Optional[bytes]:
        """A picture for Jupyter (:mod:`burmester._display`): PNG bytes, or None without matplotlib."""
    def __reduce__(self) -> Tuple[Any, ...]: ...
    @staticmethod
    def _from_state(
        linkage: SynthesizedFourBar, point: Point, grid: Grid, limits: DesignLimits,
        options: Tuple[str, float, int],
        constraints: Tuple[Optional[Sequence[Point]], Sequence[Sequence[Point]], float, int],
        strut: Optional[Tuple[float, float]] = None,
    ) -> ActuatorMap:
        """Rebuilds a map from its state (for pickling): computed again."""

# slider linkages (issue 27)

@final
class SliderConfiguration:
    """One solved position of a slider-crank (from :meth:`SliderCrank.solve`)."""

    @property
    def theta2(self) -> float:
        """The crank angle, as given."""
    @property
    def theta3(self) -> float:
        """The coupler angle (from the crank tip ``A`` to the slider pin
        ``B``), in (-pi, pi]."""
    @property
    def slider(self) -> float:
        """The slider's position: ``B``'s signed distance along the guide's
        direction from the foot of the perpendicular from the crank pivot."""
    @property
    def mode(self) -> Mode:
        """The assembly mode asked for."""
    @property
    def toggle(self) -> bool:
        """True at a toggle (a dead position of the crank: the coupler
        perpendicular to the guide), where both modes coincide."""
    @property
    def transmission_angle(self) -> float:
        """The angle between the coupler and the normal to the guide, in
        [0, pi/2] radians (pi/2 ideal, 0 at a dead position)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...

@final
class SliderCrank:
    """A slider-crank (RRRP): a crank about ``pivot`` (``A0``), a coupler,
    and a slider pin on a straight guide fixed to the ground, the line
    through ``guide_point`` in the direction ``guide``.

    Parts go by keyword only: ``SliderCrank(crank=..., coupler=...,
    guide_point=(x, y), guide=(1, 0), pivot=(0, 0))``.

    The two assembly modes carry the four-bar's names in the limit of a
    rocker pivot far along the guide's normal ``n = i·u``: ``"open"`` where
    the slider pin is behind the foot of the perpendicular from the crank
    tip (``<B - A, u> < 0``; Norton's first solution ``theta3_1`` of the
    offset slider-crank, eq. 4.16a), ``"crossed"`` where it is ahead (so a
    slider ahead of the crank along ``guide``, the usual layout, is
    ``"crossed"``). Turning the guide's direction round swaps the names.

    Raises :class:`InvalidInputError` for a length that is not positive and
    finite, a point that is not finite, a zero direction or a linkage
    larger than 1e300, and :class:`AssemblyError` (``cause``
    ``"guide_out_of_reach"``) when the guide is farther from the pivot than
    crank and coupler reach.
    """

    def __new__(
        cls,
        *,
        crank: float,
        coupler: float,
        guide_point: Point,
        guide: Point = (1.0, 0.0),
        pivot: Point = (0.0, 0.0),
    ) -> "SliderCrank": ...
    def __getnewargs_ex__(self) -> Tuple[Tuple[()], dict[str, Any]]: ...
    @property
    def crank(self) -> float:
        """The crank length ``r``."""
    @property
    def coupler(self) -> float:
        """The coupler length ``l``."""
    @property
    def pivot(self) -> Point:
        """The crank pivot ``A0``."""
    @property
    def guide(self) -> Point:
        """The guide's unit direction ``u``."""
    @property
    def guide_normal(self) -> Point:
        """The guide's unit normal ``n = i·u``."""
    @property
    def foot(self) -> Point:
        """The foot of the perpendicular from the pivot to the guide: where
        the slider's position is zero."""
    @property
    def offset(self) -> float:
        """``e``: the pivot's signed distance from the guide (along ``n``)."""
    @property
    def link_ratio(self) -> float:
        """Longest over shortest of the crank and the coupler."""
    @property
    def turns_fully(self) -> bool:
        """Whether the crank turns fully: ``r + |e| <= l``."""
    @property
    def input_range(self) -> Optional[list[Tuple[float, float]]]:
        """None when the crank turns fully, else its ``(start, end)`` arcs
        (counter-clockwise), bounded by the dead positions where the coupler
        is perpendicular to the guide."""
    @property
    def dead_positions(self) -> list[float]:
        """The crank angles that bound the input range (empty for a crank
        that turns fully): the dead positions of a crank input."""
    @property
    def collinear_positions(self) -> list[Tuple[float, float, Mode]]:
        """``(theta2, slider, mode)`` where crank and coupler are collinear
        (``|B - A0| = l + r`` or ``|l - r|``): the slider's limit positions,
        the dead positions of a slider input."""
    def guide_point(self, slider: float) -> Point:
        """The point of the guide at this slider position."""
    def solve(self, theta2: float, mode: Mode = "open") -> SliderConfiguration:
        """The position at crank angle ``theta2``. Raises
        :class:`AssemblyError` (``cause`` ``"slider_out_of_reach"``) where
        the crank tip is farther from the guide than the coupler is long,
        :class:`InvalidInputError` for an angle that is not finite or beyond
        1e9 in magnitude."""
    def joints(self, theta2: float, mode: Mode = "open") -> Tuple[Point, Point, Point]:
        """``(A0, A, B)``: the crank pivot, the crank tip and the slider pin."""
    def coupler_point(self, theta2: float, point: Point, mode: Mode = "open") -> Point:
        """Where the coupler point ``point`` (in the coupler frame: origin at
        the crank tip, x toward the slider pin) is."""
    def coupler_path(
        self, point: Point, theta2s: ArrayLike, mode: Mode = "open"
    ) -> Tuple[FloatArray, FloatArray, BoolArray]:
        """``(xs, ys, ok)`` of the coupler point over the crank angles (NaN
        and False where the loop does not close); arrays of the input's
        shape. Raises :class:`InvalidInputError` for a point that is not
        finite and ``MemoryError`` when the arrays cannot be allocated."""
    def limits(self, mode: Mode = "open") -> Tuple[Tuple[float, float], Tuple[float, float]]:
        """``((theta2, slider), (theta2, slider))``: the lowest and the
        highest slider position in ``mode`` over the input range."""
    def stroke(self, mode: Mode = "open") -> float:
        """The distance between the :meth:`limits`; for a crank that turns
        fully ``sqrt((l + r)^2 - e^2) - sqrt((l - r)^2 - e^2)``."""
    def __eq__(self, other: object, /) -> bool: ...
    def _repr_png_(self) -> Optional[bytes]:
        """A picture for Jupyter (:mod:`burmester._display`): PNG bytes, or None without matplotlib."""

@type_check_only
class _CrankSynthesized:
    """What :class:`SynthesizedSliderCrank` and
    :class:`SynthesizedInvertedSliderCrank` share: the properties of a
    linkage of a task driven by a crank (in the stub only: the native
    classes define each; the reference pages list them with each class)."""

    @property
    def driving(self) -> Tuple[Point, Point]:
        """``(A0, A1)``."""
    @property
    def input_angles(self) -> list[float]:
        """The crank angle at each pose, in (-pi, pi]."""
    @property
    def modes(self) -> list[Optional[Mode]]:
        """The assembly mode at each pose (None at a toggle)."""
    @property
    def coupler_point(self) -> Point:
        """The task's coupler point in the coupler frame."""
    @property
    def coupler_angle_offset(self) -> float:
        """Task coupler angle minus the linkage's theta3."""
    @property
    def direction(self) -> Direction:
        """The crank rotation that carries the coupler through the poses in
        order (``"none"``: an order defect or poses on two circuits)."""
    @property
    def one_circuit(self) -> bool:
        """Whether the crank angles at the poses lie on one arc of its range."""
    @property
    def min_transmission_deg(self) -> Optional[float]:
        """The smallest transmission angle over the travel, degrees; None
        without a travel."""
    @property
    def size_ratio(self) -> float:
        """:attr:`size` over the task's :attr:`Task.span`."""
    @property
    def branch_free(self) -> bool:
        """Whether the poses are all in one assembly mode (none at a toggle)."""
    @property
    def feasible(self) -> bool:
        """Branch-free, on one circuit and with a driving direction."""
    @property
    def order(self) -> str:
        """The cyclic order of the crank's positions, ``"1-2-3"``."""
    @property
    def travel(self) -> Optional[Tuple[float, float]]:
        """``(start, span)`` of the crank's travel through the poses, or None."""
    @property
    def travel_stops(self) -> Optional[list[float]]:
        """The crank angle at each pose along the travel, unwrapped, or None."""

@final
class SynthesizedSliderCrank(_CrankSynthesized):
    """A slider-crank built from a driving crank ``(A0, A1)`` and a driven
    slider ``(C1, u)`` of a task (:meth:`Task.slider_crank`); driving it to
    ``input_angles[k]`` in ``modes[k]`` places the task's coupler point and
    angle at pose ``k + 1``."""

    @property
    def linkage(self) -> SliderCrank:
        """The linkage (crank pivot ``A0``, the guide through ``C1``)."""
    @property
    def driven(self) -> Tuple[Point, Point]:
        """``(C1, u)``: the slider's pin at pose 1 and the guide's unit
        direction."""
    @property
    def slider_positions(self) -> list[float]:
        """The slider's position at each pose."""
    @property
    def stroke_used(self) -> Optional[float]:
        """How far the slider runs along its guide over the travel; None
        without a travel or with a branch defect."""
    @property
    def size(self) -> float:
        """Crank, coupler, the two other sides of the coupler triangle, the
        offset and the guide length the slider runs on."""
    def travel_angles(self, samples: int) -> FloatArray:
        """``samples`` crank angles evenly spaced over the travel, both ends
        included (2 to 2**20; empty without a travel)."""
    def pose_at(self, theta2: float, mode: Mode = "open") -> Pose:
        """The coupler pose ``(x, y, angle)`` at crank angle ``theta2``."""
    def __eq__(self, other: object, /) -> bool: ...
    def _repr_png_(self) -> Optional[bytes]:
        """A picture for Jupyter (:mod:`burmester._display`): PNG bytes, or None without matplotlib."""
    def __reduce__(self) -> Tuple[Any, ...]: ...


# the inverted slider-crank (issue 27)

@final
class InvertedConfiguration:
    """One solved position of an inverted slider-crank (from
    :meth:`InvertedSliderCrank.solve`)."""

    @property
    def theta2(self) -> float:
        """The crank angle, as given."""
    @property
    def theta3(self) -> float:
        """The coupler angle: the slot's direction, in (-pi, pi]."""
    @property
    def slot(self) -> float:
        """The slot position ``t = <S - A, u3>``: the swivel's signed
        distance along the slot from the foot of the perpendicular from the
        crank pin (positive in ``"open"``)."""
    @property
    def mode(self) -> Mode:
        """The assembly mode asked for."""
    @property
    def toggle(self) -> bool:
        """True at a toggle (a dead position of the crank: the crank pin
        ``|e|`` from the swivel, ``t = 0``), where both modes coincide."""
    @property
    def transmission_angle(self) -> float:
        """The angle between the force the block and slot carry (normal to
        the slot) and the line from the swivel to the crank pin, in
        [0, pi/2] radians: ``cos mu = |e| / |S - A|`` (pi/2 ideal, always so
        for a slot through the pin; 0 at a dead position)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...

@final
class InvertedSliderCrank:
    """An inverted slider-crank (RRPR): a crank about ``pivot`` (``A0``)
    whose coupler carries a straight slot that slides through a block
    pivoted on the ground at ``swivel`` (``S``): the slotted lever of a
    shaper's quick return, the rod of an oscillating cylinder. The slot is
    the line ``y = offset`` of the coupler frame (origin the crank pin
    ``A``, x along the slot); ``offset = 0`` puts the pin on the slot's
    line.

    Parts go by keyword only: ``InvertedSliderCrank(crank=...,
    swivel=(x, y), offset=0.0, pivot=(0, 0))``.

    The position analysis is Norton's (*Design of Machinery*, section 4.7,
    eqs. 4.18-4.20), in closed form. The two assembly modes carry the
    four-bar's names in the limit of a coupler pin far along the slot's
    normal: ``"open"`` where the swivel is ahead of the crank pin along the
    slot (``t > 0``), ``"crossed"`` where it is behind.

    Raises :class:`InvalidInputError` for a crank that is not positive and
    finite, a point or offset that is not finite or a linkage larger than
    1e300, and :class:`AssemblyError` (``cause`` ``"swivel_out_of_reach"``)
    when the offset is larger than ground plus crank.
    """

    def __new__(
        cls,
        *,
        crank: float,
        swivel: Point,
        offset: float = 0.0,
        pivot: Point = (0.0, 0.0),
    ) -> "InvertedSliderCrank": ...
    def __getnewargs_ex__(self) -> Tuple[Tuple[()], dict[str, Any]]: ...
    @property
    def crank(self) -> float:
        """The crank length ``r``."""
    @property
    def pivot(self) -> Point:
        """The crank pivot ``A0``."""
    @property
    def swivel(self) -> Point:
        """The swivel ``S``: the block's ground pivot."""
    @property
    def offset(self) -> float:
        """``e``: the slot's signed offset from the crank pin."""
    @property
    def ground(self) -> float:
        """``g = |S - A0|``."""
    @property
    def turns_fully(self) -> bool:
        """Whether the crank turns fully: ``|g - r| >= |e|``."""
    @property
    def input_range(self) -> Optional[list[Tuple[float, float]]]:
        """None when the crank turns fully, else its ``(start, end)`` arc
        (counter-clockwise, pointing away from the swivel), bounded by the
        dead positions where the crank pin is ``|e|`` from the swivel."""
    @property
    def dead_positions(self) -> list[float]:
        """The crank angles that bound the input range (empty for a crank
        that turns fully)."""
    @property
    def stroke(self) -> float:
        """How far the block runs along the slot over the crank's range:
        ``sqrt((g + r)^2 - e^2) - sqrt(max((g - r)^2, e^2) - e^2)``, the
        same in either mode."""
    def solve(self, theta2: float, mode: Mode = "open") -> InvertedConfiguration:
        """The position at crank angle ``theta2``. Raises
        :class:`AssemblyError` (``cause`` ``"slot_out_of_reach"``) where the
        crank pin is nearer the swivel than the offset,
        :class:`InvalidInputError` for an angle that is not finite or beyond
        1e9 in magnitude."""
    def joints(self, theta2: float, mode: Mode = "open") -> Tuple[Point, Point, Point, Point]:
        """``(A0, A, S, F)``: the crank pivot, the crank pin, the swivel and
        the foot of the perpendicular from the pin to the slot."""
    def coupler_point(self, theta2: float, point: Point, mode: Mode = "open") -> Point:
        """Where the coupler point ``point`` (in the coupler frame: origin at
        the crank pin, x along the slot) is."""
    def coupler_path(
        self, point: Point, theta2s: ArrayLike, mode: Mode = "open"
    ) -> Tuple[FloatArray, FloatArray, BoolArray]:
        """``(xs, ys, ok)`` of the coupler point over the crank angles (NaN
        and False where the loop does not close); arrays of the input's
        shape. Raises :class:`InvalidInputError` for a point that is not
        finite and ``MemoryError`` when the arrays cannot be allocated."""
    def slot_limits(
        self, mode: Mode = "open"
    ) -> Tuple[Tuple[float, float, float], Tuple[float, float, float]]:
        """``((theta2, slot, theta3), (theta2, slot, theta3))``: the lowest
        and the highest slot position in ``mode``."""
    def swing(
        self, mode: Mode = "open"
    ) -> Optional[Tuple[Tuple[float, float, float], Tuple[float, float, float]]]:
        """The slotted link's swing in ``mode``: its ends ``(theta2, slot,
        theta3)``, lowest and highest ``theta3`` (unwrapped), where the crank
        is perpendicular to the slot (or at a dead position); None where the
        slotted link turns fully (``r > g + |e|``, Whitworth)."""
    def time_ratio(self, mode: Mode = "open") -> Optional[float]:
        """The quick-return ratio: the longer over the shorter crank angle
        between the swing's ends; None without a swing or a full-turning
        crank."""
    def __eq__(self, other: object, /) -> bool: ...
    def _repr_png_(self) -> Optional[bytes]:
        """A picture for Jupyter (:mod:`burmester._display`): PNG bytes, or None without matplotlib."""

@final
class SynthesizedInvertedSliderCrank(_CrankSynthesized):
    """An inverted slider-crank built from a driving crank ``(A0, A1)`` and
    an inverted slider ``(S, d)`` of a task
    (:meth:`Task.inverted_slider_crank`); driving it to ``input_angles[k]``
    in ``modes[k]`` places the task's coupler point and angle at pose
    ``k + 1``."""

    @property
    def linkage(self) -> InvertedSliderCrank:
        """The linkage (crank pivot ``A0``, the swivel ``S``, the offset)."""
    @property
    def driven(self) -> Tuple[Point, Point]:
        """``(S, d)``: the swivel and the slot's unit direction at pose 1."""
    @property
    def slot_positions(self) -> list[float]:
        """The slot position at each pose."""
    @property
    def stroke_used(self) -> Optional[float]:
        """How far the block runs along the slot over the travel; None
        without a travel or with a branch defect."""
    @property
    def swing_used_deg(self) -> Optional[float]:
        """How far the slotted link swings over the travel, degrees; None
        without a travel or with a branch defect."""
    @property
    def size(self) -> float:
        """Crank, ground, the coupler point's distances from the crank pin
        and the swivel at pose 1, and the slot length the block runs on."""
    def travel_angles(self, samples: int) -> FloatArray:
        """``samples`` crank angles evenly spaced over the travel, both ends
        included (2 to 2**20; empty without a travel)."""
    def pose_at(self, theta2: float, mode: Mode = "open") -> Pose:
        """The coupler pose ``(x, y, angle)`` at crank angle ``theta2``."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...
    def _repr_png_(self) -> Optional[bytes]:
        """A picture for Jupyter (:mod:`burmester._display`): PNG bytes, or None without matplotlib."""
