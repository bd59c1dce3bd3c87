"""Task files: a three-, four- or five-position synthesis job written in TOML.

A task file gives the three poses of the coupler (angles in **degrees**), the
driven dyad, the part of the center-point plane to show and sweep, and the
limits a good linkage must meet. Only ``[[pose]]`` and ``[driven]`` are
required::

    # Lengths in any one unit; angles in degrees, counter-clockwise from +x.
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

    [view]                # the driving crank's center-point plane: shown and swept
    x = [-8.0, 8.0]       # xmin, xmax
    y = [-8.0, 8.0]       # ymin, ymax
    grid = [400, 400]     # samples along x and along y

    [limits]              # what a good linkage must meet
    min_transmission_deg = 30.0
    max_link_ratio = 10.0
    input = "any"         # "any", "crank" (turns fully) or "rocker"

Four or five ``[[pose]]`` tables make a four- or five-position task (the
Burmester curves and points, drawn by ``burmester map``): it takes only
``[[pose]]``, ``[view]`` and, for four poses, ``[limits]`` (those of the pair
map, ``burmester pairs``) and an optional ``[driven]``: a driven dyad on the
curves (``center`` on the center-point curve, or ``circle`` on the
circle-point curve, each within the core's tolerance), for which ``burmester
map`` draws the arcs of driving dyads branch-free with it. Five poses take
neither. Its default view is :func:`default_curve_view`.

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
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import burmester
from burmester._burmester import DesignLimits, Filemon, Grid, Task

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

    def task(self) -> Task:
        """The :class:`burmester.Task` of the poses."""
        return Task(list(self.poses))

    def filemon(self) -> Filemon:
        """Filemon's construction for the driven dyad. Raises
        :class:`TaskFileError` for a task of four or five poses (no driven
        dyad: only ``burmester map`` draws those)."""
        if len(self.poses) != 3 or self.driven_center is None:
            raise TaskFileError(
                f"{self.source}: has {len(self.poses)} poses; Filemon's construction, the maps, "
                "pivots and linkages need three (burmester map draws four or five poses)"
            )
        return self.task().filemon(self.driven_center)


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
    if len(task) == 4:
        pts += [q.center for q in task.coincidence_points() if q.center is not None]
    elif len(task) == 5:
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
    return len(task) == 3 and all(p.point is not None for p in task.poles)


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
                expected = ", ".join(allowed)
                raise self.fail(
                    f"{where}.{key}", f"unknown key (expected one of: {expected}){hint}"
                )

    def number(self, where: str, value: object, what: str = "a number") -> float:
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
        if not math.isfinite(x):
            raise self.fail(where, f"expected a finite number, found {value}")
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
        if key not in ("pose", "driven", "view", "limits"):
            hint = " (the poses are [[pose]] tables)" if key in ("poses", "task") else ""
            raise r.fail(key, f"unknown top-level key (expected [[pose]], [driven], [view], [limits]){hint}")

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
    except burmester.BurmesterError as e:
        raise r.fail("[[pose]]", f"the {len(poses)} poses cannot be used: {e}") from None
    if len(poses) > 3:
        return _parse_many(r, doc, task, tuple(poses), source)

    # [driven]
    center = _driven(r, doc, task, required=True)
    assert center is not None
    try:
        filemon = task.filemon(center)
    except burmester.BurmesterError as e:
        raise r.fail("driven.center", f"cannot be used: {e}") from None

    # [view]
    view = _view(r, doc, default_view(filemon).extent)

    limits = _limits(r, doc)
    return TaskSpec(tuple(poses), center, view, limits, source)


def _limits(r: _Reader, doc: Mapping[str, Any]) -> DesignLimits:
    """The ``[limits]`` table as a DesignLimits (the defaults when absent)."""
    lim_t = r.table(doc, "limits", required=False) or {}
    keys = ["min_transmission_deg", "max_link_ratio", "input", "require_crank"]
    r.only_keys("limits", lim_t, keys)
    defaults = DesignLimits()
    mu = defaults.min_transmission_deg
    if "min_transmission_deg" in lim_t:
        mu = r.number("limits.min_transmission_deg", lim_t["min_transmission_deg"], "a number of degrees")
    ratio = defaults.max_link_ratio
    if "max_link_ratio" in lim_t:
        ratio = r.number("limits.max_link_ratio", lim_t["max_link_ratio"], "a number")
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
    try:
        limits = DesignLimits(mu, ratio, input_)
    except burmester.InvalidInputError as e:
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
    r.only_keys("driven", driven, ["center", "circle"])
    if ("center" in driven) == ("circle" in driven):
        found = "both" if "center" in driven else "neither"
        raise r.fail(
            "[driven]",
            f"expected exactly one of center = [x, y] (the fixed pivot C0) or "
            f"circle = [x, y] (the moving pivot C1 at pose 1), found {found}",
        )
    if "center" in driven:
        center = r.point("driven.center", driven["center"])
        if len(task.poses) == 4:
            try:
                task.circle_point(center)
            except burmester.BurmesterError as e:
                raise r.fail("driven.center", f"is not a center point of the four poses: {e}") from None
        return center
    circle = r.point("driven.circle", driven["circle"])
    try:
        return task.center_point(circle)
    except burmester.BurmesterError as e:
        raise r.fail("driven.circle", f"has no center point: {e}") from None


def _parse_many(
    r: _Reader, doc: Mapping[str, Any], task: Task, poses: Tuple[Tuple[float, float, float], ...], source: str
) -> TaskSpec:
    """The rest of a task file of four or five poses: ``[view]``, and for
    four ``[limits]`` (the pair map's) and ``[driven]`` (a driven dyad on
    the curve, whose branch-free driving arcs ``burmester map`` draws)."""
    if len(poses) == 5:
        for key, what in (("driven", "or four poses (a driven dyad on the center-point curve)"),
                          ("limits", "or four poses (the pair map)")):
            if key in doc:
                raise r.fail(
                    f"[{key}]",
                    f"is for three ({what}), found 5 poses; leave [{key}] out of a five-pose task",
                )
    try:
        default = default_curve_view(task)
    except burmester.BurmesterError as e:
        raise r.fail("[[pose]]", f"the {len(poses)} poses cannot be used: {e}") from None
    limits = _limits(r, doc) if len(poses) == 4 else DesignLimits()
    driven = _driven(r, doc, task, required=False) if len(poses) == 4 else None
    return TaskSpec(poses, driven, _view(r, doc, default), limits, source)


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
    """The text of a task file for ``spec`` (angles written in degrees)."""
    lines = [
        "# burmester task file (TOML).",
        "# Lengths in any one unit; angles in DEGREES, counter-clockwise from +x.",
        "",
    ]
    for k, (x, y, a) in enumerate(spec.poses, start=1):
        note = ": x, y where the coupler point is, angle_deg the coupler's angle" if k == 1 else ""
        lines += [f"[[pose]]  # pose {k}{note}", f"x = {x!r}", f"y = {y!r}", f"angle_deg = {math.degrees(a)!r}", ""]
    if spec.driven_center is not None:
        cx, cy = spec.driven_center
        lines += [
            "[driven]  # the driven dyad: its fixed pivot C0 (or circle = [x, y], its moving pivot at pose 1)",
            f"center = [{cx!r}, {cy!r}]",
            "",
        ]
    v = spec.view
    lines += [
        "[view]  # the driving crank's center-point plane: drawn, and searched for pivots",
        f"x = [{v.xmin!r}, {v.xmax!r}]  # xmin, xmax",
        f"y = [{v.ymin!r}, {v.ymax!r}]  # ymin, ymax",
        f"grid = [{v.nx}, {v.ny}]  # samples along x and y",
        "",
    ]
    four_with_limits = len(spec.poses) == 4 and spec.limits != DesignLimits()
    if len(spec.poses) > 3 and not four_with_limits:
        return "\n".join(lines)
    lim = spec.limits
    lines += [
        "[limits]  # what an acceptable linkage must meet",
        f"min_transmission_deg = {lim.min_transmission_deg!r}  # over the whole travel through the poses, degrees",
        f"max_link_ratio = {lim.max_link_ratio!r}  # longest link / shortest link",
        f'input = "{lim.input}"  # the driving link: "any", "crank" (turns fully) or "rocker"',
        "",
    ]
    return "\n".join(lines)


def save(spec: TaskSpec, path: Union[str, Path], *, overwrite: bool = True) -> Path:
    """Write ``spec`` as a task file (:func:`dumps`) to ``path``: whole to a
    temporary file beside it, moved into place when complete
    (:mod:`burmester._io`), so a write error or Ctrl-C leaves no partial
    file. ``overwrite=False`` raises :class:`FileExistsError` when ``path``
    exists at the move (an existing file is never replaced). Returns the
    path."""
    from burmester import _io

    return _io.write_text(path, dumps(spec), overwrite=overwrite)
