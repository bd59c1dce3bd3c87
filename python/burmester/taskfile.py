"""Task files: a three-, four- or five-position synthesis job written in TOML.

A task file gives the three poses of the coupler (angles in **degrees**), the
driven dyad, the part of the center-point plane to show and sweep, and the
limits a good linkage must meet. Only ``[[pose]]`` and ``[driven]`` are
required::

    # Lengths in any one unit; angles in degrees, counter-clockwise from +x.
    units = "mm"          # optional: the unit's name, said in tables, on axes, in CAD files

    [[pose]]              # pose 1: where the coupler point is, and the coupler's angle
    x = 0.0
    y = 0.0
    angle_deg = 0.0

    [[pose]]              # pose 2
    x = 2.0
    y = 0.5
    angle_deg = 22.918

    [[pose]]              # pose 3
    x = 3.0
    y = 2.0
    angle_deg = 63.025

    [driven]              # the driven dyad, by its fixed pivot C0 ...
    center = [4.0, -1.0]
    # circle = [x, y]     # ... or by its moving pivot C1 at pose 1 (not both)
    # slider = [x, y]     # ... or a slider: its pin C1 at pose 1 (burmester map only)

    [view]                # the driving crank's center-point plane: shown and swept
    x = [-8.0, 8.0]       # xmin, xmax
    y = [-8.0, 8.0]       # ymin, ymax
    grid = [400, 400]     # samples along x and along y

    [limits]              # what a good linkage must meet
    min_transmission_deg = 30.0
    max_link_ratio = 10.0
    input = "any"         # "any", "crank" (turns fully) or "rocker"
    min_grashof_margin = 0.01   # |s + l - p - q| / link sum: off the change point

``units`` (top level, before the tables) names the unit of every length
in the file: any name (``"mm"``, ``"in"``, ``"m"``); it scales nothing, and
is only said (see :mod:`burmester.units`). Without it lengths are bare
numbers (CAD exports record millimetres unless told otherwise).

``[driven] slider = [x, y]`` (three poses) makes the driven dyad a slider:
its pin ``C1`` at pose 1, a point of the task's slider circle
(:meth:`burmester.Task.slider_circle`, within the core's tolerance: take one
of :meth:`burmester.Task.slider_dyads`), its guide the line through the
pin's three positions. ``burmester map`` then draws the slider solution map
(every crank pivot ``A0`` a slider-crank) and ranks its slider-cranks; the
commands that build a four-bar refuse it.

Without ``[driven]``, a three-pose file leaves both fixed pivots to
``burmester design``, which searches them (the other commands need a driven
pivot). ``min_grashof_margin`` (default 0.01) keeps every acceptable
linkage off the Grashof change point ``s + l = p + q``
(:attr:`burmester.LinkageFigures.grashof_margin`; 0: no limit).
``[limits]`` may also bound the linkage's size: ``max_size_ratio`` (its
size over the task's) and ``max_link_length`` (the longest link, in the
task's units). A ``[space]`` table (any number of poses) says where the
linkage may be, for ``burmester design``::

    [space]
    pivot_x = [-60.0, 60.0]          # both fixed pivots inside this box ...
    pivot_y = [-120.0, -10.0]
    # pivot_polygon = [[x, y], ...]  # ... or inside this simple polygon
    obstacles = [[[0, 0], [10, 0], [10, 10]]]   # convex keep-out polygons
    link_width = 8.0                 # the moving links' width
    envelope = [[x, y], ...]         # the moving links stay inside (around the poses)

Four or five ``[[pose]]`` tables make a four- or five-position task (the
Burmester curves and points, drawn by ``burmester map``): it takes
``[[pose]]``, ``[view]``, ``[limits]`` (for four poses those of the pair map,
``burmester pairs``; for five, those the four-bars of the Burmester points
are judged by, ``burmester pivots``) and, for four poses, an optional
``[driven]``: a driven dyad on the curves (``center`` on the center-point
curve, or ``circle`` on the circle-point curve, each within the core's
tolerance), for which ``burmester map`` draws the arcs of driving dyads
branch-free with it. Five poses take no ``[driven]`` (their dyads are the
Burmester points). Its default view is :func:`default_curve_view`.

The view becomes a :class:`burmester.Grid` and the limits a
:class:`burmester.DesignLimits` (which validates them); older files may say
``require_crank = true`` instead of ``input = "crank"``.

A bad file raises :class:`TaskFileError` (a ``ValueError``) whose message
names the file, the key, what was expected and what was found.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Dict, List, Literal, Mapping, Optional, Sequence, Tuple, Union

from burmester import _counts as counts
from burmester._burmester import BurmesterError, DesignLimits, Filemon, Grid, InvalidInputError, Space, Task
from burmester.units import check_units

if TYPE_CHECKING:
    from burmester._burmester import RankBy

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - exercised on Python < 3.11 only
    import tomli as tomllib

Point = Tuple[float, float]

#: The default number of grid samples along the longer side of the view.
DEFAULT_GRID = 400

#: The built-in example (the same as the Rust ``burmester::example``):
#: poses ``(x, y, angle in radians)``, the driven crank's fixed pivot, the view.
EXAMPLE_POSES: Tuple[Tuple[float, float, float], ...] = (
    (0.0, 0.0, 0.0),
    (2.0, 0.5, 0.4),
    (3.0, 2.0, 1.1),
)
EXAMPLE_DRIVEN_CENTER: Point = (4.0, -1.0)
EXAMPLE_VIEW: Tuple[float, float, float, float] = (-8.0, 8.0, -8.0, 8.0)


#: The values of ``input`` in ``[limits]``.
INPUTS = ("any", "crank", "rocker")


class TaskFileError(ValueError):
    """A task file that cannot be used; the message says where and why."""


def grid_for(
    xmin: float, xmax: float, ymin: float, ymax: float, samples: int = DEFAULT_GRID
) -> Grid:
    """A :class:`burmester.Grid` over the rectangle with ``samples`` samples
    along its longer side and about square cells (at least 2 along the
    shorter side). Raises :class:`burmester.InvalidInputError` for an empty
    or inverted rectangle."""
    w, h = xmax - xmin, ymax - ymin
    if not (w > 0 and h > 0):
        # Let the core say what is wrong, with its fields.
        return Grid(xmin, xmax, ymin, ymax, samples, samples)
    nx = samples if w >= h else max(2, round(samples * w / h))
    ny = samples if h >= w else max(2, round(samples * h / w))
    return Grid(xmin, xmax, ymin, ymax, nx, ny)


@dataclass(frozen=True)
class TaskSpec:
    """A loaded task: poses (angles in radians), the driven dyad's fixed
    pivot, the view (a :class:`burmester.Grid`) and the limits (a
    :class:`burmester.DesignLimits`)."""

    poses: Tuple[Tuple[float, float, float], ...]
    #: The driven crank's fixed pivot: required for three poses, optional
    #: for four (on the center-point curve), None for five.
    driven_center: Optional[Point]
    view: Grid
    limits: DesignLimits = field(default_factory=DesignLimits)
    source: str = "<example>"
    #: The unit of the task's lengths (``units = "mm"`` in the file), or
    #: None: said in tables, on axes and in CAD files, never scaled.
    units: Optional[str] = None
    #: Where the linkage may be (``[space]``), for ``burmester design``;
    #: None: anywhere.
    space: Optional[Space] = None
    #: A linear actuator to place (``[actuator]``), for ``burmester
    #: actuator``; None: the command's defaults.
    actuator: Optional["ActuatorSpec"] = None
    #: A driven slider (``[driven] slider = [x, y]``, three poses): its pin
    #: ``C1`` at pose 1 and the guide's direction ``u`` (the line through
    #: the pin's positions), for ``burmester map``; None: a driven crank.
    driven_slider: Optional[Tuple[Point, Point]] = None
    #: The driven dyad ``burmester design`` searches (``[design] driven``):
    #: ``"revolute"`` (four-bars) or ``"slider"`` (slider-cranks); None:
    #: not given (revolute, unless ``--driven`` says otherwise).
    design_driven: Optional[str] = None

    @property
    def task(self) -> Task:
        """The :class:`burmester.Task` of the poses (a property, as the
        results of the native classes are)."""
        return Task(list(self.poses))

    def filemon(self) -> Filemon:
        """Filemon's construction for the driven dyad. Raises
        :class:`TaskFileError` for a task of four or five poses (no driven
        dyad: only ``burmester map`` draws those)."""
        offers = counts.of(self.poses).filemon
        if self.driven_slider is not None:
            raise TaskFileError(
                f"{self.source}: [driven] names a slider (slider = [x, y]): only 'burmester map' takes "
                "a driven slider (its slider-cranks); give the driven crank's fixed pivot "
                "(center = [x, y]) for this command"
            )
        if offers and self.driven_center is None:
            raise TaskFileError(
                f"{self.source}: has no [driven] table: give the driven crank's fixed pivot "
                "(center = [x, y]) for this command, or run 'burmester design', which searches "
                "both fixed pivots"
            )
        if not offers or self.driven_center is None:
            raise TaskFileError(
                f"{self.source}: has {len(self.poses)} poses; Filemon's construction, the maps, "
                "pivots and linkages need three (burmester map draws four or five poses)"
            )
        return self.task.filemon(self.driven_center)


def example() -> TaskSpec:
    """The built-in example task (the one ``burmester map`` draws without a file)."""
    return TaskSpec(
        poses=EXAMPLE_POSES,
        driven_center=EXAMPLE_DRIVEN_CENTER,
        view=Grid(*EXAMPLE_VIEW, DEFAULT_GRID, DEFAULT_GRID),
        source="<example>",
    )


def default_curve_view(task: Task) -> Tuple[float, float, float, float]:
    """A square ``(xmin, xmax, ymin, ymax)`` around the poses of a four- or
    five-pose task, its finite poles and its points ``Q_jk`` (four poses) or
    Burmester centers (five poses), leaving out those more than eight task
    sizes from the poses' centroid (a pole or center point near infinity
    would shrink the rest to a dot)."""
    poses = [(p[0], p[1]) for p in task.poses]
    cx = sum(p[0] for p in poses) / len(poses)
    cy = sum(p[1] for p in poses) / len(poses)
    scale = task.scale
    pts: List[Point] = list(poses) + [p.point for p in task.poles if p.point is not None]
    count = counts.of(task)
    if count.curves:
        pts += [q.center for q in task.coincidence_points() if q.center is not None]
    elif count.burmester_points:
        pts += [b[0] for b in task.burmester_points()]
    near = [p for p in pts if math.hypot(p[0] - cx, p[1] - cy) <= 8.0 * scale]
    xs = [p[0] for p in near]
    ys = [p[1] for p in near]
    mx, my = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    half = 0.6 * max(max(xs) - min(xs), max(ys) - min(ys), scale)
    return (mx - half, mx + half, my - half, my + half)


def has_pole_triangle(task: Task) -> bool:
    """Whether a task of three poses has three finite poles (no two poses
    differ by a pure translation): then it has a pole triangle, pole circles
    and image poles (``Task.pole_circle`` and the like raise otherwise)."""
    return counts.of(task).filemon and all(p.point is not None for p in task.poles)


def default_task_view(task: Task, grid: int = DEFAULT_GRID) -> Grid:
    """A square view around the poses and poles of a three-pose task
    without a driven dyad, twice as wide as the box around them."""
    pts: List[Point] = [p.point for p in task.poles if p.point is not None]
    pts += [(p[0], p[1]) for p in task.poses]
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    half = max(max(xs) - min(xs), max(ys) - min(ys), task.scale)
    return Grid(cx - half, cx + half, cy - half, cy + half, grid, grid)


def default_view(filemon: Filemon, grid: int = DEFAULT_GRID) -> Grid:
    """A square view around the poles, the task's points and both pivots of the
    driven dyad, twice as wide as the box around them, with ``grid`` samples
    along each side."""
    task = filemon.task
    pts: List[Point] = [p.point for p in task.poles if p.point is not None]
    pts += [(p[0], p[1]) for p in task.poses]
    pts += [filemon.driven_center, filemon.driven_circle]
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    half = max(max(xs) - min(xs), max(ys) - min(ys), task.scale)
    return Grid(cx - half, cx + half, cy - half, cy + half, grid, grid)


def default_circle_view(filemon: Filemon) -> Tuple[float, float, float, float]:
    """A square ``(xmin, xmax, ymin, ymax)`` around the driven crank's moving
    pivot ``C1``, the fixed pivot's images ``C'k`` and the image poles (when
    the task has them): the default view of the circle-point plane (a
    picture or a CAD export)."""
    pts: List[Point] = [filemon.driven_circle, *filemon.fixed_pivot_images]
    if has_pole_triangle(filemon.task):
        pts += filemon.task.image_poles()
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    half = max(max(xs) - min(xs), max(ys) - min(ys), filemon.task.scale) * 0.75
    return (cx - half, cx + half, cy - half, cy + half)


def in_view(point: Sequence[float], extent: Sequence[float]) -> bool:
    """Whether ``point`` lies in the view ``(xmin, xmax, ymin, ymax)``
    (its edges included)."""
    x0, x1, y0, y1 = extent
    return x0 <= point[0] <= x1 and y0 <= point[1] <= y1


def outside_view(points: Sequence[Tuple[str, Optional[Sequence[float]]]],
                 extent: Sequence[float]) -> List[Tuple[str, Point]]:
    """The named points (``(name, (x, y))``; None for a point at infinity,
    left out) that lie outside the view ``(xmin, xmax, ymin, ymax)``, in
    order: what a picture of that view cannot show, and the summary must
    say."""
    return [(name, (float(p[0]), float(p[1]))) for name, p in points
            if p is not None and not in_view(p, extent)]


def curve_plane_points(task: Task, driven: Optional[Point] = None,
                       plane: str = "center") -> List[Tuple[str, Optional[Point]]]:
    """The named points a picture of four or five poses marks (None for a
    pole at infinity): the poses; in the center-point plane the poles, and
    for four poses the points ``Q_jk`` and the driven pivot ``C0``, for five
    the Burmester points ``Bk``; in the circle-point plane of four poses the
    points ``Q'jk``, and for a driven dyad its ``C1`` and ``C'k``."""
    circle = plane == "circle"
    pts: List[Tuple[str, Optional[Point]]] = [(f"pose {k}", (q[0], q[1])) for k, q in enumerate(task.poses, start=1)]
    if not circle:
        pts += [(f"P{p.pair[0]}{p.pair[1]}", p.point) for p in task.poles]
    count = counts.of(task)
    if count.curves:
        prime = "'" if circle else ""
        pts += [("Q{}{}{}".format(prime, *q.pair), q.circle if circle else q.center)
                for q in task.coincidence_points()]
        if driven is not None:
            if circle:
                pts.append(("C1", task.circle_point(driven)))
                pts += [(f"C'{k}", task.displace(driven, k, 1)) for k in range(1, count.poses + 1)]
            else:
                pts.append(("C0", driven))
    elif count.burmester_points and not circle:
        pts += [(f"B{k}", c) for k, (c, _) in enumerate(task.burmester_points(), start=1)]
    return pts


def describe_outside(outside: Sequence[Tuple[str, Sequence[float]]], extent: Sequence[float],
                     units: Optional[str] = None) -> str:
    """The points outside the view in words, for a summary or a note on a
    picture: ``"B3 (12.300, 40.100) lies outside the view x [-5, 5], y [-5,
    5]"`` (``""`` when none)."""
    if not outside:
        return ""
    x0, x1, y0, y1 = extent
    listed = ", ".join(f"{name} ({round(p[0], 3) + 0.0:.3f}, {round(p[1], 3) + 0.0:.3f})" for name, p in outside)
    verb = "lies" if len(outside) == 1 else "lie"
    unit = f" {units}" if units else ""
    return f"{listed} {verb} outside the view x [{x0:.4g}, {x1:.4g}], y [{y0:.4g}, {y1:.4g}]{unit}"


# ---------------------------------------------------------------------------
# Parsing


def _describe(value: object) -> str:
    """What was found, for an error message: the value and its TOML type."""
    kinds = {
        bool: "a boolean",
        int: "an integer",
        float: "a float",
        str: "a string",
        list: "an array",
        dict: "a table",
    }
    kind = kinds.get(type(value), type(value).__name__)
    text = ("true" if value else "false") if isinstance(value, bool) else repr(value)
    if len(text) > 40:
        text = text[:37] + "..."
    return f"{text} ({kind})"


class _Reader:
    """Reads values out of the parsed TOML, raising TaskFileError with context."""

    def __init__(self, source: str) -> None:
        self.source = source

    def fail(self, where: str, message: str) -> TaskFileError:
        return TaskFileError(f"{self.source}: {where}: {message}")

    def table(self, doc: Mapping[str, Any], key: str, required: bool) -> Optional[Dict[str, Any]]:
        if key not in doc:
            if required:
                raise self.fail(f"[{key}]", f"missing; add a [{key}] table")
            return None
        value = doc[key]
        if not isinstance(value, dict):
            raise self.fail(key, f"expected a table [{key}], found {_describe(value)}")
        return value

    def only_keys(self, where: str, table: Mapping[str, Any], allowed: Sequence[str]) -> None:
        for key in table:
            if key not in allowed:
                hint = ""
                if key in ("angle", "angle_rad", "theta", "phi"):
                    hint = "; angles in task files are in degrees: use angle_deg"
                if key == "units":
                    hint = "; units = \"...\" goes at the top of the file, before the first table"
                expected = ", ".join(allowed)
                raise self.fail(
                    f"{where}.{key}", f"unknown key (expected one of: {expected}){hint}"
                )

    def number(self, where: str, value: object, what: str = "a number", no_limit: bool = False) -> float:
        """A number; ``no_limit``: TOML's ``inf`` is accepted too (a limit
        that does not bind, as the core's ``DesignLimits`` takes it)."""
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(where, f"expected {what}, found {_describe(value)}")
        try:
            x = float(value)
        except OverflowError:
            # An integer beyond a float's range (about 1.8e308).
            digits = len(str(abs(int(value))))
            raise self.fail(
                where,
                f"expected {what} within +-1.8e308, found an integer of {digits} digits; "
                "write the value you mean (as a float, for example 1.5e30)",
            ) from None
        if no_limit and x == math.inf:
            return x
        if not math.isfinite(x):
            hint = " (or inf: no limit)" if no_limit else ""
            raise self.fail(where, f"expected a finite number{hint}, found {value}")
        return x

    def required_number(self, where: str, table: Mapping[str, Any], key: str, what: str) -> float:
        if key not in table:
            raise self.fail(f"{where}.{key}", f"missing; expected {what}")
        return self.number(f"{where}.{key}", table[key], what)

    def point(self, where: str, value: object) -> Point:
        if not isinstance(value, list) or len(value) != 2:
            raise self.fail(where, f"expected a point [x, y], found {_describe(value)}")
        return (
            self.number(f"{where}[0]", value[0], "a number (x)"),
            self.number(f"{where}[1]", value[1], "a number (y)"),
        )

    def interval(self, where: str, value: object) -> Tuple[float, float]:
        if not isinstance(value, list) or len(value) != 2:
            raise self.fail(where, f"expected [min, max], found {_describe(value)}")
        lo = self.number(f"{where}[0]", value[0], "a number (min)")
        hi = self.number(f"{where}[1]", value[1], "a number (max)")
        if not lo < hi:
            raise self.fail(where, f"expected min < max, found [{lo:g}, {hi:g}]")
        return lo, hi

    def grid(self, where: str, value: object) -> Tuple[int, int]:
        if not isinstance(value, list) or len(value) != 2:
            raise self.fail(where, f"expected [nx, ny], found {_describe(value)}")
        out = []
        for i, n in enumerate(value):
            if isinstance(n, bool) or not isinstance(n, int):
                raise self.fail(f"{where}[{i}]", f"expected a whole number, found {_describe(n)}")
            if not 2 <= n <= 20000:
                found = str(n) if len(str(n)) <= 20 else f"an integer of {len(str(abs(n)))} digits"
                raise self.fail(f"{where}[{i}]", f"expected 2 to 20000 samples, found {found}")
            out.append(n)
        return out[0], out[1]


def parse_task(doc: Mapping[str, Any], source: str = "<task>") -> TaskSpec:
    """A :class:`TaskSpec` from a parsed TOML document (a dict).

    Raises :class:`TaskFileError` naming ``source``, the key, what was
    expected and what was found.
    """
    r = _Reader(source)
    for key in doc:
        if key not in ("pose", "driven", "view", "limits", "space", "units", "actuator", "design"):
            hint = " (the poses are [[pose]] tables)" if key in ("poses", "task") else ""
            if key in ("unit", "length_unit", "lengths"):
                hint = ' (the unit of the lengths is units = "mm")'
            raise r.fail(key, f"unknown top-level key (expected units, [[pose]], [driven], [view], [limits], [space], "
                              f"[actuator], [design]){hint}")
    units = _units(r, doc)

    # [[pose]] x3 (the branch maps of Filemon's construction need three), or
    # x4, x5 (the Burmester curves and points)
    if "pose" not in doc:
        raise r.fail("[[pose]]", "missing; give three (to five) [[pose]] tables with x, y and angle_deg")
    raw_poses = doc["pose"]
    if not isinstance(raw_poses, list) or not all(isinstance(p, dict) for p in raw_poses):
        raise r.fail("pose", f"expected three to five [[pose]] tables, found {_describe(raw_poses)}")
    if not 3 <= len(raw_poses) <= 5:
        raise r.fail(
            "[[pose]]",
            f"expected 3 to 5 poses (3 for Filemon's construction and the maps, 4 or 5 for the "
            f"Burmester curves and points), found {len(raw_poses)}",
        )
    poses = []
    for k, p in enumerate(raw_poses, start=1):
        where = f"pose {k}"
        r.only_keys(where, p, ["x", "y", "angle_deg"])
        x = r.required_number(where, p, "x", "a number (the coupler point's x)")
        y = r.required_number(where, p, "y", "a number (the coupler point's y)")
        a = r.required_number(where, p, "angle_deg", "a number (the coupler angle, degrees)")
        poses.append((x, y, math.radians(a)))
    try:
        task = Task(poses)
    except BurmesterError as e:
        raise r.fail("[[pose]]", f"the {len(poses)} poses cannot be used: {e}") from None
    if not counts.of(poses).filemon:
        return _parse_many(r, doc, task, tuple(poses), source, units)

    # [driven]: optional; without it `burmester design` searches both pivots
    center = _driven(r, doc, task, required=False)
    slider = _driven_slider(r, doc, task)
    if center is not None:
        try:
            filemon = task.filemon(center)
        except BurmesterError as e:
            raise r.fail("driven.center", f"cannot be used: {e}") from None
        default = default_view(filemon).extent
    else:
        default = default_task_view(task).extent

    # [view]
    view = _view(r, doc, default)

    limits = _limits(r, doc)
    return TaskSpec(tuple(poses), center, view, limits, source, units=units, space=_space(r, doc),
                    actuator=_actuator(r, doc), design_driven=_design_driven(r, doc),
                    driven_slider=slider)


def _units(r: _Reader, doc: Mapping[str, Any]) -> Optional[str]:
    """The top-level ``units`` (a unit name), or None when absent."""
    if "units" not in doc:
        return None
    value = doc["units"]
    if isinstance(value, dict):
        raise r.fail("[units]", 'expected units = "mm" (a name, at the top of the file, before the tables), '
                                "found a table")
    try:
        return check_units(value, "units")
    except InvalidInputError as e:
        raise r.fail("units", f"{e}; found {_describe(value)}") from None


def _space(r: _Reader, doc: Mapping[str, Any]) -> Optional[Space]:
    """The ``[space]`` table as a :class:`burmester.Space` (None when
    absent)."""
    t = r.table(doc, "space", required=False)
    if t is None:
        return None
    keys = ["pivot_x", "pivot_y", "pivot_polygon", "obstacles", "link_width", "envelope",
            "travel_samples"]
    r.only_keys("space", t, keys)
    if ("pivot_x" in t) != ("pivot_y" in t):
        missing = "pivot_y" if "pivot_x" in t else "pivot_x"
        raise r.fail(f"space.{missing}", "missing; give both pivot_x = [min, max] and pivot_y = [min, max]")
    if "pivot_x" in t and "pivot_polygon" in t:
        raise r.fail("[space]", "expected a pivot box (pivot_x, pivot_y) or a pivot_polygon, found both")

    def polygon(key: str, value: object) -> List[Point]:
        if not isinstance(value, list) or len(value) < 3:
            raise r.fail(f"space.{key}", f"expected a polygon [[x, y], ...] of at least 3 points, "
                                         f"found {_describe(value)}")
        return [r.point(f"space.{key}[{k}]", p) for k, p in enumerate(value)]

    kw: Dict[str, Any] = {}
    if "pivot_x" in t:
        x0, x1 = r.interval("space.pivot_x", t["pivot_x"])
        y0, y1 = r.interval("space.pivot_y", t["pivot_y"])
        kw["pivot_box"] = (x0, x1, y0, y1)
    if "pivot_polygon" in t:
        kw["pivot_polygon"] = polygon("pivot_polygon", t["pivot_polygon"])
    if "obstacles" in t:
        obs = t["obstacles"]
        if not isinstance(obs, list):
            raise r.fail("space.obstacles", f"expected a list of polygons, found {_describe(obs)}")
        kw["obstacles"] = [polygon(f"obstacles[{k}]", o) for k, o in enumerate(obs)]
    if "envelope" in t:
        kw["envelope"] = polygon("envelope", t["envelope"])
    if "link_width" in t:
        w = r.number("space.link_width", t["link_width"], "a number (the links' width, task units)")
        if w < 0:
            raise r.fail("space.link_width", f"expected a width of at least 0, found {w:g}")
        kw["link_width"] = w
    if "travel_samples" in t:
        n = t["travel_samples"]
        if isinstance(n, bool) or not isinstance(n, int) or not 2 <= n <= 4096:
            raise r.fail("space.travel_samples", f"expected a whole number from 2 to 4096, found {_describe(n)}")
        kw["travel_samples"] = n
    try:
        return Space(**kw)
    except BurmesterError as e:
        # The core names the field: "pivot_box xmax", "pivot_polygon",
        # "envelope", "obstacle 2", "link_width", ...
        name = str(getattr(e, "name", "") or "")
        where = "[space]"
        if name.startswith("pivot_box"):
            where = "space.pivot_y" if name.endswith(("ymin", "ymax")) else "space.pivot_x"
        elif name.startswith("obstacle"):
            where = "space.obstacles"
        elif name in keys:
            where = f"space.{name}"
        raise r.fail(where, str(e)) from None


def _limits(r: _Reader, doc: Mapping[str, Any]) -> DesignLimits:
    """The ``[limits]`` table as a DesignLimits (the defaults when absent)."""
    lim_t = r.table(doc, "limits", required=False) or {}
    keys = ["min_transmission_deg", "max_link_ratio", "input", "require_crank", "min_grashof_margin",
            "max_size_ratio", "max_link_length"]
    r.only_keys("limits", lim_t, keys)
    defaults = DesignLimits()
    mu = defaults.min_transmission_deg
    if "min_transmission_deg" in lim_t:
        mu = r.number("limits.min_transmission_deg", lim_t["min_transmission_deg"], "a number of degrees")
    ratio = defaults.max_link_ratio
    if "max_link_ratio" in lim_t:
        ratio = r.number("limits.max_link_ratio", lim_t["max_link_ratio"], "a number", no_limit=True)
    if "input" in lim_t and "require_crank" in lim_t:
        raise r.fail(
            "[limits]", 'expected one of input = "any" | "crank" | "rocker" or require_crank, found both'
        )
    input_ = defaults.input
    if "input" in lim_t:
        value = lim_t["input"]
        if value not in INPUTS:
            raise r.fail("limits.input", f'expected "any", "crank" or "rocker", found {_describe(value)}')
        input_ = value
    if "require_crank" in lim_t:
        crank = lim_t["require_crank"]
        if not isinstance(crank, bool):
            raise r.fail("limits.require_crank", f"expected true or false, found {_describe(crank)}")
        input_ = "crank" if crank else "any"
    sizes = []
    for key in ("max_size_ratio", "max_link_length"):
        v = math.inf
        if key in lim_t:
            v = r.number(f"limits.{key}", lim_t[key], "a number", no_limit=True)
        sizes.append(v)
    margin = defaults.min_grashof_margin
    if "min_grashof_margin" in lim_t:
        margin = r.number("limits.min_grashof_margin", lim_t["min_grashof_margin"], "a number")
    try:
        limits = DesignLimits(mu, ratio, input_, sizes[0], sizes[1], margin)
    except InvalidInputError as e:
        # The core validates; its error names the limit and its range.
        if e.cause != "outside_range":
            raise r.fail("[limits]", str(e)) from None
        unit = f" {e.unit}" if e.unit else ""
        expected = (
            f"at least {e.min:g}{unit}" if math.isinf(e.max) else f"{e.min:g} to {e.max:g}{unit}"
        )
        raise r.fail(f"limits.{e.name}", f"expected {expected}, found {e.value:g}") from None
    return limits


def _view(r: _Reader, doc: Mapping[str, Any], default: Tuple[float, float, float, float]) -> Grid:
    """The ``[view]`` table as a Grid (``default`` when it gives no x, y)."""
    view_t = r.table(doc, "view", required=False) or {}
    r.only_keys("view", view_t, ["x", "y", "grid"])
    if ("x" in view_t) != ("y" in view_t):
        missing = "y" if "x" in view_t else "x"
        raise r.fail(f"view.{missing}", "missing; give both x = [min, max] and y = [min, max], or neither")
    if "x" in view_t:
        xmin, xmax = r.interval("view.x", view_t["x"])
        ymin, ymax = r.interval("view.y", view_t["y"])
    else:
        xmin, xmax, ymin, ymax = default
    if "grid" in view_t:
        nx, ny = r.grid("view.grid", view_t["grid"])
        return Grid(xmin, xmax, ymin, ymax, nx, ny)
    return grid_for(xmin, xmax, ymin, ymax)


def _driven(r: _Reader, doc: Mapping[str, Any], task: Task, required: bool) -> Optional[Point]:
    """The driven dyad's fixed pivot ``C0`` of ``[driven]``: ``center``, or
    the center point of ``circle``. For four poses both lie on their curves
    (the center- and circle-point curves), within the core's tolerance."""
    driven = r.table(doc, "driven", required=required)
    if driven is None:
        return None
    r.only_keys("driven", driven, ["center", "circle", "slider"])
    given = [key for key in ("center", "circle", "slider") if key in driven]
    if len(given) != 1:
        found = ("both " if len(given) == 2 else "all of ") + " and ".join(given) if given else "neither"
        raise r.fail(
            "[driven]",
            f"expected exactly one of center = [x, y] (the fixed pivot C0), "
            f"circle = [x, y] (the moving pivot C1 at pose 1) or slider = [x, y] (a slider's pin at "
            f"pose 1), found {found}",
        )
    if "slider" in driven:
        return None  # _driven_slider reads it
    if "center" in driven:
        center = r.point("driven.center", driven["center"])
        if counts.of(task).curves:
            try:
                task.circle_point(center)
            except BurmesterError as e:
                raise r.fail("driven.center", f"is not a center point of the four poses: {e}") from None
        return center
    circle = r.point("driven.circle", driven["circle"])
    try:
        return task.center_point(circle)
    except BurmesterError as e:
        raise r.fail("driven.circle", f"has no center point: {e}") from None


def _driven_slider(r: _Reader, doc: Mapping[str, Any], task: Task) -> Optional[Tuple[Point, Point]]:
    """The driven slider of ``[driven] slider = [x, y]`` (three poses): the
    pin ``C1`` at pose 1, which must lie on the task's slider circle
    (:meth:`burmester.Task.slider_dyad`), and its guide's direction (the
    line through the pin's positions)."""
    driven = doc.get("driven")
    if not isinstance(driven, Mapping) or "slider" not in driven:
        return None
    pin = r.point("driven.slider", driven["slider"])
    if not counts.of(task).filemon:
        raise r.fail("driven.slider", "a driven slider is for three poses (the slider solution map)")
    try:
        dyad = task.slider_dyad(pin)
    except BurmesterError as e:
        raise r.fail("driven.slider", f"is not a slider point of the three poses: {e}") from None
    return dyad.circle, dyad.guide


def _parse_many(
    r: _Reader, doc: Mapping[str, Any], task: Task, poses: Tuple[Tuple[float, float, float], ...], source: str,
    units: Optional[str] = None,
) -> TaskSpec:
    """The rest of a task file of four or five poses: ``[view]``,
    ``[limits]`` (the pair map's, or those the Burmester four-bars of five
    poses are judged by) and, for four, ``[driven]`` (a driven dyad on the
    curve, whose branch-free driving arcs ``burmester map`` draws)."""
    count = counts.of(poses)
    if not count.driven and "driven" in doc:
        raise r.fail(
            "[driven]",
            "is for three or four poses (a driven dyad on the center-point curve), found 5 poses: "
            "the dyads of five poses are their Burmester points; leave [driven] out",
        )
    try:
        default = default_curve_view(task)
    except BurmesterError as e:
        raise r.fail("[[pose]]", f"the {len(poses)} poses cannot be used: {e}") from None
    limits = _limits(r, doc)
    driven = _driven(r, doc, task, required=False) if count.driven else None
    _driven_slider(r, doc, task)  # refused: a driven slider is for three poses
    return TaskSpec(poses, driven, _view(r, doc, default), limits, source, units=units, space=_space(r, doc),
                    actuator=_actuator(r, doc), design_driven=_design_driven(r, doc))


def loads(text: str, source: str = "<task>") -> TaskSpec:
    """A :class:`TaskSpec` from the text of a task file (a leading UTF-8
    byte-order mark, which some editors write, is ignored)."""
    if text.startswith("\ufeff"):
        text = text[1:]
    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise TaskFileError(f"{source}: not valid TOML: {e}") from None
    return parse_task(doc, source)


def load(path: Union[str, Path]) -> TaskSpec:
    """A :class:`TaskSpec` from a task file. Raises :class:`TaskFileError`
    when the file cannot be read or is not a valid task."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise TaskFileError(f"{p}: no such file; give the path of a task file (.toml)") from None
    except (OSError, UnicodeDecodeError) as e:
        raise TaskFileError(f"{p}: cannot read it: {e}") from None
    return loads(text, str(p))


def dumps(spec: TaskSpec) -> str:
    """The text of a task file for ``spec`` (angles written in degrees),
    with comments saying what each table and key is: the file
    ``burmester example`` prints, to edit. Written by tomlkit (a
    maintained TOML writer that keeps comments); :func:`loads` reads it
    back to the same task."""
    import tomlkit

    def note(item: Any, text: str) -> Any:
        """``item`` with the comment ``text`` after it, two spaces apart."""
        item.comment(text)
        item.trivia.comment_ws = "  "
        return item

    doc = tomlkit.document()
    doc.add(tomlkit.comment("burmester task file (TOML)."))
    doc.add(tomlkit.comment("Lengths in any one unit; angles in DEGREES, counter-clockwise from +x."))
    if spec.units is not None:
        doc.add("units", note(tomlkit.item(spec.units),
                              "the unit of the lengths: said in tables, on axes and in CAD files, never scaled"))
    else:
        doc.add(tomlkit.comment('units = "mm"  # the unit of the lengths, if you name one: said in tables, on axes '
                                "and in CAD files"))
    doc.add(tomlkit.nl())
    poses = tomlkit.aot()
    for k, (x, y, a) in enumerate(spec.poses, start=1):
        what = ": x, y where the coupler point is, angle_deg the coupler's angle" if k == 1 else ""
        pose = note(tomlkit.table(), f"pose {k}{what}")
        pose.add("x", float(x))
        pose.add("y", float(y))
        pose.add("angle_deg", math.degrees(a))
        poses.append(pose)
    doc.add("pose", poses)
    if spec.driven_center is not None:
        driven = note(tomlkit.table(),
                      "the driven dyad: its fixed pivot C0 (or circle = [x, y], its moving pivot at pose 1)")
        driven.add("center", [float(c) for c in spec.driven_center])
        doc.add("driven", driven)
    v = spec.view
    view = note(tomlkit.table(), "the driving crank's center-point plane: drawn, and searched for pivots")
    view.add("x", note(tomlkit.item([v.xmin, v.xmax]), "xmin, xmax"))
    view.add("y", note(tomlkit.item([v.ymin, v.ymax]), "ymin, ymax"))
    view.add("grid", note(tomlkit.item([v.nx, v.ny]), "samples along x and y"))
    doc.add("view", view)
    if counts.of(spec.poses).filemon or spec.limits != DesignLimits():  # four and five poses: when not the defaults
        lim = spec.limits
        limits = note(tomlkit.table(), "what an acceptable linkage must meet")
        limits.add("min_transmission_deg", note(tomlkit.item(float(lim.min_transmission_deg)),
                                                "over the whole travel through the poses, degrees"))
        limits.add("max_link_ratio", note(tomlkit.item(float(lim.max_link_ratio)), "longest link / shortest link"))
        limits.add("input", note(tomlkit.item(str(lim.input)),
                                 'the driving link: "any", "crank" (turns fully) or "rocker"'))
        limits.add("min_grashof_margin", note(tomlkit.item(float(lim.min_grashof_margin)),
                                              "|s + l - p - q| / link sum: off the change point"))
        if math.isfinite(lim.max_size_ratio):
            limits.add("max_size_ratio", note(tomlkit.item(float(lim.max_size_ratio)),
                                              "the linkage's size / the task's size"))
        if math.isfinite(lim.max_link_length):
            limits.add("max_link_length", note(tomlkit.item(float(lim.max_link_length)),
                                               "the longest link, task units"))
        doc.add("limits", limits)
    if spec.space is not None:
        doc.add("space", _dump_space(spec.space, note))
    if spec.actuator is not None:
        doc.add("actuator", _dump_actuator(spec.actuator, note))
    if spec.design_driven is not None:
        design = note(tomlkit.table(), "burmester design (its flags override these)")
        design.add("driven", note(tomlkit.item(spec.design_driven),
                                  '"revolute" (four-bars) or "slider" (slider-cranks: a pin on a straight guide)'))
        doc.add("design", design)
    return tomlkit.dumps(doc)


def _dump_space(space: Space, note: Any) -> Any:
    """The ``[space]`` table (tomlkit), ``note`` adding a comment to an item."""
    import tomlkit

    def poly(p: Sequence[Point]) -> List[List[float]]:
        return [[float(x), float(y)] for x, y in p]

    t = note(tomlkit.table(), "where the linkage may be (burmester design)")
    if space.pivot_box is not None:
        x0, x1, y0, y1 = space.pivot_box
        t.add("pivot_x", note(tomlkit.item([float(x0), float(x1)]), "both fixed pivots inside this box"))
        t.add("pivot_y", tomlkit.item([float(y0), float(y1)]))
    if space.pivot_polygon is not None:
        t.add("pivot_polygon", tomlkit.item(poly(space.pivot_polygon)))
    if space.obstacles:
        t.add("obstacles", tomlkit.item([poly(o) for o in space.obstacles]))
    if space.link_width:
        t.add("link_width", float(space.link_width))
    if space.envelope is not None:
        t.add("envelope", tomlkit.item(poly(space.envelope)))
    if space.travel_samples != 64:
        t.add("travel_samples", int(space.travel_samples))
    return t


def save(spec: TaskSpec, path: Union[str, Path], *, overwrite: bool = True) -> Path:
    """Write ``spec`` as a task file (:func:`dumps`) to ``path``: whole to a
    temporary file beside it, moved into place when complete
    (:mod:`burmester._io`), so a write error or Ctrl-C leaves no partial
    file. ``overwrite=False`` raises :class:`FileExistsError` when ``path``
    exists at the move (an existing file is never replaced). Returns the
    path."""
    from burmester import _io

    return _io.write_text(path, dumps(spec), overwrite=overwrite)


# ---------------------------------------------------------------------------
# [actuator]: a linear actuator to place (issue 27)

#: The links an actuator may act on, and the rankings of its placements
#: (as ``burmester actuator``'s ``--link`` and ``--actuator-rank-by``).
ACTUATOR_LINKS = ("coupler", "crank", "rocker")
ACTUATOR_RANKINGS = ("balanced", "transmission", "compact", "margin")
#: Largest samples of the ground-pivot grid along x and along y (``grid``;
#: the core's map takes at most 2**20 samples in all).
MAX_ACTUATOR_GRID = 1024


@dataclass(frozen=True)
class ActuatorSpec:
    """The ``[actuator]`` table: a linear actuator (a cylinder, a gas
    strut) for ``burmester actuator`` to place on the task's linkage. Every
    field has the command's default; its flags override them.
    ``burmester design --input actuator`` reads its ``link``, ``point``,
    ``max_stroke_ratio``, ``max_size_ratio``, ``width`` and ``min_gap``
    (the same point on every design; ``--try-actuator-points`` tries a few
    points of the link instead), each overridden by its flag; the other
    keys are ``burmester actuator``'s::

        [actuator]
        link = "coupler"             # the link it acts on: "coupler", "crank" or "rocker"
        point = [-40.0, -20.0]       # its moving point Q at pose 1 (default: the link's middle)
        max_stroke_ratio = 1.8       # open over closed length, at least 1 (a cylinder's is below 2)
        max_size_ratio = 8.0         # the linkage with the open actuator over the task's span
        rank_by = "balanced"         # "balanced", "transmission", "compact" or "margin"
        x = [-250.0, 150.0]          # where its ground pivot G is searched: xmin, xmax ...
        y = [-200.0, 200.0]          # ... ymin, ymax (default: about the linkage)
        grid = [320, 320]            # ground pivots sampled along x and y, 2 to 1024 each
        base_plate = [[-150, -100], [50, -100], [50, 0], [-150, 0]]   # G inside this polygon
        width = 18.0                 # the strut's diameter (its body's): its clearance, as drawn and exported
        min_gap = 3.0                # the least gap to the links, obstacles and envelope over the travel

    ``width`` is the strut's real diameter: its capsule in the clearance
    (against the links, ``[space] link_width`` wide) and the cylinder drawn
    and exported (without it: a line in the clearance, 0.06 of its closed
    length as drawn). ``min_gap`` (default 0) is the least gap a placement
    keeps; both in task units.
    """

    link: Literal["coupler", "crank", "rocker"] = "coupler"
    point: Optional[Point] = None
    max_stroke_ratio: float = 1.8
    #: The linkage with the open actuator over the task's span, at least 1
    #: where used (``burmester actuator`` and ``design --input actuator``:
    #: the linkage alone still meets ``[limits]``); None: the task's
    #: ``[limits]`` ``max_size_ratio``.
    max_size_ratio: Optional[float] = None
    rank_by: "RankBy" = "balanced"
    #: ``(xmin, xmax, ymin, ymax)`` of the ground pivots searched; None:
    #: :func:`burmester.actuators.default_view`.
    view: Optional[Tuple[float, float, float, float]] = None
    grid: Tuple[int, int] = (200, 200)
    base_plate: Optional[Tuple[Point, ...]] = None
    #: The strut's diameter: its capsule in the clearance and the
    #: cylinder's width in the pictures, the animation and the CAD export
    #: (its rod is 0.45 of it); None: a line in the clearance, 0.06 of its
    #: closed length as drawn.
    width: Optional[float] = None
    #: The least gap over the travel (task units); None: 0.
    min_gap: Optional[float] = None


def _actuator(r: _Reader, doc: Mapping[str, Any]) -> Optional[ActuatorSpec]:
    """The ``[actuator]`` table as an :class:`ActuatorSpec` (None when absent)."""
    t = r.table(doc, "actuator", required=False)
    if t is None:
        return None
    r.only_keys("actuator", t, ["link", "point", "max_stroke_ratio", "max_size_ratio", "rank_by", "x", "y",
                                "grid", "base_plate", "width", "min_gap"])
    kw: Dict[str, Any] = {}
    for key, allowed in (("link", ACTUATOR_LINKS), ("rank_by", ACTUATOR_RANKINGS)):
        if key in t:
            if t[key] not in allowed:
                names = ", ".join(f'"{a}"' for a in allowed)
                raise r.fail(f"actuator.{key}", f"expected one of {names}, found {_describe(t[key])}")
            kw[key] = t[key]
    if "point" in t:
        kw["point"] = r.point("actuator.point", t["point"])
    # Each number: (its lowest value, whether that is allowed, what it is), TOML's inf for no size limit.
    for key, (low, closed, what) in (("max_stroke_ratio", (1.0, True, "at least 1 (open over closed length)")),
                                     ("max_size_ratio", (1.0, True, "a ratio of at least 1 (or inf: no limit)")),
                                     ("width", (0.0, False, "a width above 0 (task units)")),
                                     ("min_gap", (0.0, True, "a gap of at least 0 (task units)"))):
        if key in t:
            value = r.number(f"actuator.{key}", t[key], "a number", no_limit=key == "max_size_ratio")
            if value < low or (value == low and not closed):
                raise r.fail(f"actuator.{key}", f"expected {what}, found {value:g}")
            kw[key] = value
    if ("x" in t) != ("y" in t):
        missing = "y" if "x" in t else "x"
        raise r.fail(f"actuator.{missing}", "missing; give both x = [min, max] and y = [min, max] (where the "
                                            "ground pivot is searched), or neither")
    if "x" in t:
        kw["view"] = (*r.interval("actuator.x", t["x"]), *r.interval("actuator.y", t["y"]))
    if "grid" in t:
        nx, ny = r.grid("actuator.grid", t["grid"])
        for k, n in enumerate((nx, ny)):
            if n > MAX_ACTUATOR_GRID:
                raise r.fail(f"actuator.grid[{k}]", f"expected 2 to {MAX_ACTUATOR_GRID} ground pivots, found {n}")
        kw["grid"] = (nx, ny)
    if "base_plate" in t:
        plate = t["base_plate"]
        if not isinstance(plate, list) or len(plate) < 3:
            raise r.fail("actuator.base_plate", f"expected a polygon [[x, y], ...] of at least 3 points, "
                                                f"found {_describe(plate)}")
        kw["base_plate"] = tuple(r.point(f"actuator.base_plate[{k}]", p) for k, p in enumerate(plate))
    return ActuatorSpec(**kw)


def _dump_actuator(a: ActuatorSpec, note: Any) -> Any:
    """The ``[actuator]`` table (tomlkit), ``note`` adding a comment to an item."""
    import tomlkit

    t = note(tomlkit.table(), "a linear actuator to place (burmester actuator; design --input actuator reads "
                              "link, point, max_stroke_ratio, max_size_ratio, width, min_gap; the flags override these)")
    t.add("link", note(tomlkit.item(a.link), 'the link it acts on: "coupler", "crank" or "rocker"'))
    if a.point is not None:
        t.add("point", note(tomlkit.item([float(c) for c in a.point]), "its moving point Q at pose 1"))
    t.add("max_stroke_ratio", note(tomlkit.item(float(a.max_stroke_ratio)), "open over closed length"))
    if a.max_size_ratio is not None:
        t.add("max_size_ratio", note(tomlkit.item(float(a.max_size_ratio)),
                                     "the linkage with the open actuator over the task's span"))
    t.add("rank_by", note(tomlkit.item(a.rank_by), '"balanced", "transmission", "compact" or "margin"'))
    if a.view is not None:
        x0, x1, y0, y1 = a.view
        t.add("x", note(tomlkit.item([float(x0), float(x1)]), "where its ground pivot G is searched"))
        t.add("y", tomlkit.item([float(y0), float(y1)]))
    t.add("grid", note(tomlkit.item([int(a.grid[0]), int(a.grid[1])]), "ground pivots sampled along x and y"))
    if a.base_plate is not None:
        t.add("base_plate", note(tomlkit.item([[float(x), float(y)] for x, y in a.base_plate]),
                                 "G inside this polygon"))
    if a.width is not None:
        t.add("width", note(tomlkit.item(float(a.width)), "the strut's diameter: its clearance, as drawn"))
    if a.min_gap is not None:
        t.add("min_gap", note(tomlkit.item(float(a.min_gap)), "the least gap over the travel"))
    return t


#: The driven dyads ``[design] driven`` names.
DESIGN_DRIVEN = ("revolute", "slider")


def _design_driven(r: _Reader, doc: Mapping[str, Any]) -> Optional[str]:
    """The ``[design]`` table's ``driven`` (None when absent)."""
    t = r.table(doc, "design", required=False)
    if t is None:
        return None
    r.only_keys("design", t, ["driven"])
    if "driven" not in t:
        return None
    value = t["driven"]
    if value not in DESIGN_DRIVEN:
        names = ", ".join(f'"{a}"' for a in DESIGN_DRIVEN)
        raise r.fail("design.driven", f"expected one of {names}, found {_describe(value)}")
    return str(value)
