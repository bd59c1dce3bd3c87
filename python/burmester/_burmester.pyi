"""Type stubs and documentation of the native core, ``burmester._burmester``.

Angles are in radians, counter-clockwise, absolute (measured from the fixed
+x axis). Points are ``(x, y)`` tuples. Array arguments accept anything
NumPy can turn into a float64 array, of any shape; array results have the
shape of the input.
"""

from typing import Any, Literal, Optional, Sequence, Tuple, Union, final

import numpy as np
import numpy.typing as npt

__all__ = [
    "AssemblyError",
    "BurmesterError",
    "DegenerateError",
    "InvalidInputError",
    "Configuration",
    "FourBar",
    "Conic",
    "Filemon",
    "SolutionMap",
    "SynthesizedFourBar",
    "Task",
    "__version__",
]

__version__: str

Point = Tuple[float, float]
Mode = Literal["open", "crossed"]
GrashofType = Literal[
    "crank-rocker", "double-crank", "rocker-crank", "double-rocker", "triple-rocker", "change-point"
]
FloatArray = npt.NDArray[np.float64]
BoolArray = npt.NDArray[np.bool_]
ArrayLike = Union[npt.ArrayLike, Sequence[float]]

class BurmesterError(ValueError):
    """Base of every error raised by burmester (a ``ValueError``)."""

class InvalidInputError(BurmesterError):
    """A number or name passed in is not acceptable: NaN, infinite, zero or
    negative length, an int too large for a float, a negative or too large
    count or index, a ragged array, a number out of the supported range,
    unknown name. The message says which and what to pass.

    An argument of the wrong type (a string, ``None``, a complex number where
    a real one goes) raises :class:`TypeError` instead."""

class AssemblyError(BurmesterError):
    """The linkage cannot be assembled as asked: the loop does not close at
    that input angle, or never closes for those lengths."""

class DegenerateError(BurmesterError):
    """The geometry is degenerate: an answer lies at infinity (for example a
    center point on the pole circle), or the task has no unique answer."""

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
        """The acute angle between coupler and rocker, in [0, pi/2]."""
    @property
    def coupler_rocker_angle(self) -> float:
        """theta4 - theta3 wrapped into (-pi, pi]; its sign is the mode."""

@final
class FourBar:
    """A planar four-bar linkage.

    The ground link runs from the input pivot ``O2`` to the output pivot
    ``O4``; the crank (input) turns about ``O2``, the rocker (output) about
    ``O4``, and the coupler joins their tips. The loop is::

        L2 e^{i theta2} + L3 e^{i theta3} - L1 e^{i theta1} - L4 e^{i theta4} = 0

    The two assembly modes are named by the sign of ``sin(theta4 - theta3)``:
    ``"open"`` where it is positive, ``"crossed"`` where it is negative.

    Raises :class:`InvalidInputError` for a zero, negative, NaN or infinite
    length or a linkage larger than 1e300 (origin distance plus lengths), and
    :class:`AssemblyError` when the longest link is longer than the other
    three together.

    >>> fb = FourBar(100.0, 40.0, 120.0, 80.0)   # Norton, Example 4-1
    >>> [round(math.degrees(a), 3) for a in fb.solve(math.radians(40))]
    [20.298, 57.325]
    """

    def __new__(
        cls,
        ground: float,
        crank: float,
        coupler: float,
        rocker: float,
        *,
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
    def link_ratio(self) -> float:
        """Ratio of the longest to the shortest link."""
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
        (the loop does not close there, or the angle is not finite). The GIL
        is released during the computation."""
    def grashof(self) -> GrashofType:
        """Grashof type, the input being the crank link: ``"crank-rocker"``,
        ``"double-crank"``, ``"rocker-crank"``, ``"double-rocker"``
        (Grashof, coupler shortest), ``"triple-rocker"`` (non-Grashof) or
        ``"change-point"``."""
    def input_turns_fully(self) -> bool:
        """Whether the input link turns all the way round."""
    def input_range(self) -> Optional[list[Tuple[float, float]]]:
        """``None`` when the input turns fully, else the one or two arcs
        ``(start, end)`` (counter-clockwise) it can rock within."""
    def dead_positions(self) -> list[float]:
        """The input angles bounding the arcs of :meth:`input_range` (toggle
        positions); empty when the input turns fully."""
    def transmission_angle(self, theta2: float, mode: Mode = "open") -> float:
        """The transmission angle (acute angle between coupler and rocker)."""
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
    def __eq__(self, other: object, /) -> bool: ...

Pose = Tuple[float, float, float]
Line = Tuple[Point, Point]
Method = Literal["conic", "direct", "simulate"]
BranchClass = Literal["free", "defective", "boundary"]

@final
class Task:
    """Three poses of the coupler, ``(x, y, angle)`` with angles in radians.

    Raises :class:`InvalidInputError` for NaN or infinite numbers or not
    exactly three poses, and :class:`DegenerateError` when two poses are
    equal, when two poses differ by a pure translation (their angles agree
    within 1e-6 rad, so their pole is at infinity: rotate one pose by at
    least 1e-6 rad), or when the three poses are rotations about one point.

    The maps run in a frame attached to the pole triangle, so results do not
    depend on where the task is or how large it is.
    """

    def __new__(cls, poses: Sequence[Sequence[float]]) -> Task:
        """Three poses, each a sequence of three numbers (tuples, lists or a
        3 x 3 array). Coordinates must be at most 1e100 and angles at most 1e9
        rad in magnitude, and two angles must differ by more than 1e-6 rad
        (mod 2 pi)."""
    @property
    def poses(self) -> list[Pose]:
        """The three poses."""
    @property
    def rotations(self) -> Tuple[float, float, float]:
        """``(theta12, theta13, theta23)``, each wrapped into (-pi, pi]."""
    @property
    def scale(self) -> float:
        """The size of the pole triangle (unit of the relative tolerances)."""
    def poles(self) -> Tuple[Point, Point, Point]:
        """``(P12, P13, P23)``: the fixed points of the displacements."""
    def image_poles(self) -> Tuple[Point, Point, Point]:
        """``(P12, P13, P'23)`` in the pose-1 frame; ``P'23`` is the
        reflection of ``P23`` across the line ``P12 P13``."""
    def image_poles_in(self, frame: int) -> Tuple[Point, Point, Point]:
        """The image poles ``(P12^k, P13^k, P23^k)`` in the frame of pose
        ``k`` (1, 2 or 3)."""
    def pole_circle(self) -> dict[str, object]:
        """The circle through the poles: ``{"kind": "circle", "center": (x, y),
        "radius": r}`` (or ``{"kind": "line", "point", "direction"}`` when
        collinear). Center points on it have their circle point at infinity."""
    def image_pole_circle(self) -> dict[str, object]:
        """The circle through the image poles (same form). Circle points on it
        have their center point at infinity."""
    def pole_triangle_angles(self) -> Tuple[float, float, float]:
        """The signed angles of the pole triangle at P12, P13, P23, modulo pi
        in (-pi/2, pi/2]; they equal theta12/2, theta13/2, theta23/2 mod pi."""
    def displace(self, point: Point, i: int, j: int) -> Point:
        """``D_ij(z)``: where the coupler point at ``point`` in pose ``i`` is in
        pose ``j`` (1-based)."""
    def circle_point(self, center: Point) -> Point:
        """The circle point (moving pivot at pose 1) of a center point (fixed
        pivot). Raises :class:`DegenerateError` on the pole circle (the answer
        is at infinity; the message gives its direction) or at a pole."""
    def center_point(self, circle: Point) -> Point:
        """The center point of a circle point. Raises :class:`DegenerateError`
        on the image-pole circle (the center is at infinity: a slider) or at an
        image pole."""
    def circle_points(self, centers: ArrayLike) -> Tuple[FloatArray, BoolArray]:
        """:meth:`circle_point` of an array of shape ``(..., 2)``: the points
        (NaN where undefined) and a validity mask of shape ``(...)``."""
    def center_points(self, circles: ArrayLike) -> Tuple[FloatArray, BoolArray]:
        """:meth:`center_point` of an array of shape ``(..., 2)``."""
    def dyad(self, center: Point) -> Tuple[Point, Point]:
        """``(center, circle)``: the dyad with this center point."""
    def crank_angles(self, center: Point) -> Tuple[float, float, float]:
        """The crank angle of the dyad with this center point at each pose."""
    def filemon(self, driven_center: Point) -> Filemon:
        """Filemon's construction for the driven dyad with this center point
        (``C0``). Raises :class:`DegenerateError` where ``C0`` has no circle
        point (pole circle, poles)."""
    def four_bar(self, driving_center: Point, driven_center: Point) -> SynthesizedFourBar:
        """The four-bar built from the dyads with these center points."""
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
        min_transmission_deg: float = 30.0,
        max_link_ratio: float = 10.0,
        input: Literal["any", "crank", "rocker"] = "any",
        base_plate: Optional[Sequence[Point]] = None,
        obstacles: Optional[Sequence[Sequence[Point]]] = None,
        link_width: float = 0.0,
        travel_samples: int = 64,
    ) -> SolutionMap:
        """The same map the other way round: the driving dyad with this center
        point is fixed and the candidates are driven center points ``C0``; the
        branch-free flag is the sign test at the three poses."""
    def line_to_conic(self, point: Point, direction: Point) -> Conic:
        """The exact image in the center-point plane of a line of the
        circle-point plane: a conic through the three poles."""

@final
class Filemon:
    """Filemon's construction for a driven dyad ``(C0, C1)`` and its two lines
    transformed exactly into conics in the driving crank's center-point plane.

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
    def circle_point(self) -> Point:
        """``C1``, the driven crank's moving pivot at pose 1."""
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
        ``"simulate"``: build the four-bar and drive it through the poses.
        The methods agree except within about 1e-9 of the task's size from
        a conic. A point on a curve is not free. ``"direct"`` and
        ``"simulate"`` raise :class:`DegenerateError` on the pole circle and
        at the poles."""
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
    def branch_map(
        self,
        xmin: float,
        xmax: float,
        ymin: float,
        ymax: float,
        nx: int,
        ny: int,
        method: Method = "conic",
        *,
        out: Optional[BoolArray] = None,
    ) -> BoolArray:
        """Classify every candidate driving center point on a grid.

        Samples sit at cell centers, ``x_i = xmin + (i + 0.5) (xmax - xmin) / nx``
        and likewise ``y_j``; the result has shape ``(ny, nx)``, row ``j`` for
        ``y_j``, True where strictly branch-free, so that
        ``plt.imshow(m, origin="lower", extent=(xmin, xmax, ymin, ymax))``
        shows it the right way up. Points on a curve, at a pole or at ``C0``
        are False; ``"direct"`` and ``"simulate"`` are also False where the
        circle point does not exist (on the pole circle). The GIL is released
        during the computation; the result is handed to NumPy without a copy,
        or written into ``out`` (a C-contiguous bool array of shape
        ``(ny, nx)``), which is returned.

        ``"conic"`` at 4096 x 4096 takes about as long as filling the array
        with a constant (see BENCHMARKS.md)."""
    def margin_map(
        self,
        xmin: float,
        xmax: float,
        ymin: float,
        ymax: float,
        nx: int,
        ny: int,
        *,
        out: Optional[npt.NDArray[np.float32]] = None,
    ) -> npt.NDArray[np.float32]:
        """The signed margin on the same grid (float32): the first-order
        distance to the nearer transformed Filemon curve, positive where
        branch-free and negative elsewhere; ``-inf`` everywhere when all
        circle points are defective. For contour plots and ranking pivots."""
    def margin(self, center: Point) -> float:
        """The signed margin at one point (float64)."""
    def solution_map(
        self,
        xmin: float,
        xmax: float,
        ymin: float,
        ymax: float,
        nx: int,
        ny: int,
        *,
        min_transmission_deg: float = 30.0,
        max_link_ratio: float = 10.0,
        input: Literal["any", "crank", "rocker"] = "any",
        base_plate: Optional[Sequence[Point]] = None,
        obstacles: Optional[Sequence[Sequence[Point]]] = None,
        link_width: float = 0.0,
        travel_samples: int = 64,
    ) -> SolutionMap:
        """The designer's solution-space map over candidate driving center
        points ``A0`` on the same grid as :meth:`branch_map`.

        For each candidate: whether the linkage exists, the branch-free flag
        (exactly :meth:`branch_map`), the Grashof class, whether the driving
        link turns fully, the input rotation direction that carries the coupler
        from pose 1 through pose 2 to pose 3 (or none), whether the three
        input angles lie on one circuit, the minimum transmission angle over
        the whole travel (exact, not only at the poses), the link ratio, and an
        ``acceptable`` mask from the limits (``min_transmission_deg``,
        ``max_link_ratio``, ``input`` = ``"any"``, ``"crank"`` (turns fully) or
        ``"rocker"``) and constraints: the fixed pivot inside ``base_plate`` (a
        simple polygon), and the moving links, as capsules ``link_width`` wide,
        clear of ``obstacles`` (convex polygons) at ``travel_samples`` input
        angles of the travel. The GIL is released during the computation."""

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
    def __call__(self, point: Point) -> float: ...
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

@final
class SynthesizedFourBar:
    """A four-bar built from a driving dyad ``(A0, A1)`` and a driven dyad
    ``(C0, C1)``; driving it to ``input_angles[k]`` in ``modes[k]`` places
    the task's coupler point and angle at pose ``k + 1``."""

    @property
    def fourbar(self) -> FourBar:
        """The linkage (input pivot ``A0``, output pivot ``C0``)."""
    @property
    def driving(self) -> Tuple[Point, Point]:
        """``(A0, A1)``."""
    @property
    def driven(self) -> Tuple[Point, Point]:
        """``(C0, C1)``."""
    @property
    def input_angles(self) -> Tuple[float, float, float]:
        """The input angle at each pose."""
    @property
    def modes(self) -> Tuple[Optional[Mode], Optional[Mode], Optional[Mode]]:
        """The assembly mode at each pose (None at a toggle)."""
    @property
    def coupler_point(self) -> Point:
        """The task's coupler point in the linkage's coupler frame."""
    @property
    def coupler_angle_offset(self) -> float:
        """Task coupler angle minus the linkage's theta3."""
    def is_branch_free(self) -> bool:
        """Whether the three poses are in one assembly mode."""
    def pose_at(self, theta2: float, mode: Mode = "open") -> Pose:
        """``(x, y, angle)`` of the task's coupler point when driven to ``theta2``."""

@final
class SolutionMap:
    """The solution-space map: read-only arrays of shape ``(ny, nx)``, row
    ``j`` for ``y_j``, like :meth:`Filemon.branch_map` (handed to NumPy
    without a copy)."""

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
        """The input rotation that carries the coupler 1 -> 2 -> 3: 1 ccw, -1 cw,
        0 none (order defect or poses on different circuits)."""
    @property
    def one_circuit(self) -> BoolArray:
        """The three input angles lie on one circuit (one arc of the input range)."""
    @property
    def min_transmission(self) -> npt.NDArray[np.float32]:
        """Minimum transmission angle over the travel, radians; NaN where there
        is no feasible travel or no linkage."""
    @property
    def link_ratio(self) -> npt.NDArray[np.float32]:
        """Longest over shortest link; NaN where there is no linkage."""
    @property
    def acceptable(self) -> BoolArray:
        """Feasible, branch-free, and within the limits and constraints."""
    @property
    def extent(self) -> Tuple[float, float, float, float]:
        """``(xmin, xmax, ymin, ymax)``, for ``imshow(..., extent=...)``."""
    @property
    def shape(self) -> Tuple[int, int]:
        """``(ny, nx)``."""
    @property
    def varying(self) -> Literal["driving", "driven"]:
        """Which center point the map varies."""
    def point(self, j: int, i: int) -> Point:
        """The candidate center point of sample ``[j, i]``."""
    def linkage(self, j: int, i: int) -> SynthesizedFourBar:
        """The linkage of sample ``[j, i]``."""
    def best_pivots(self, k: int = 5, min_separation: Optional[float] = None) -> list[dict[str, Any]]:
        """The ``k`` best acceptable candidates, best first, as plain dicts:
        ``center``, ``driving`` and ``driven`` dyads, ``lengths``, ``grashof``,
        ``input_full``, ``direction`` (``"ccw"``/``"cw"``),
        ``min_transmission_deg``, ``link_ratio``, ``margin``, ``input_angles``,
        ``mode``, ``index``.

        Ranked by the minimum transmission angle over the travel, ties by the
        margin to the nearest branch-defect boundary; candidates closer than
        ``min_separation`` (default 2% of the viewport's diagonal) to a better
        one are skipped, so the list offers distinct options."""
