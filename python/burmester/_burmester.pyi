"""Type stubs and documentation of the native core, ``burmester._burmester``.

Angles are in radians, counter-clockwise, absolute (measured from the fixed
+x axis). Points are ``(x, y)`` tuples. Array arguments accept anything
NumPy can turn into a float64 array, of any shape; array results have the
shape of the input.
"""

from typing import Literal, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

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
    negative length, unknown name. The message says which and what to pass."""

class AssemblyError(BurmesterError):
    """The linkage cannot be assembled as asked: the loop does not close at
    that input angle, or never closes for those lengths."""

class DegenerateError(BurmesterError):
    """The geometry is degenerate: an answer lies at infinity (for example a
    center point on the pole circle), or the task has no unique answer."""

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

class FourBar:
    """A planar four-bar linkage.

    The ground link runs from the input pivot ``O2`` to the output pivot
    ``O4``; the crank (input) turns about ``O2``, the rocker (output) about
    ``O4``, and the coupler joins their tips. The loop is::

        L2 e^{i theta2} + L3 e^{i theta3} - L1 e^{i theta1} - L4 e^{i theta4} = 0

    The two assembly modes are named by the sign of ``sin(theta4 - theta3)``:
    ``"open"`` where it is positive, ``"crossed"`` where it is negative.

    Raises :class:`InvalidInputError` for a zero, negative, NaN or infinite
    length, and :class:`AssemblyError` when the longest link is longer than
    the other three together.

    >>> fb = FourBar(100.0, 40.0, 120.0, 80.0)   # Norton, Example 4-1
    >>> [round(math.degrees(a), 3) for a in fb.solve(math.radians(40))]
    [20.298, 57.325]
    """

    def __init__(
        self,
        ground: float,
        crank: float,
        coupler: float,
        rocker: float,
        *,
        origin: Point = (0.0, 0.0),
        ground_angle: float = 0.0,
    ) -> None:
        """A four-bar from its link lengths; the input pivot is at ``origin``
        and the ground link at ``ground_angle`` radians from +x."""
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
    def __eq__(self, other: object) -> bool: ...
