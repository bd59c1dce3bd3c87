"""CAD export: a synthesized four-bar, or a center-point or circle-point
plane, to DXF (with ezdxf) and to SVG (with the standard library).

- :func:`linkage_dxf`, :func:`linkage_svg` (or :func:`linkage`, by the
  file's suffix): the fixed pivots, the ground link, the linkage at each
  pose, the poses, the coupler curve, the coupler-point path over the
  travel and, optionally, the linkage sampled over the travel.
- :func:`burmester_plane_dxf`, :func:`burmester_plane_svg` (or
  :func:`burmester_plane`): four or five poses, as
  :func:`burmester.plot.burmester_plane` draws them: the center-point curve
  by crank order with the points ``Q_jk`` (and, given a driven pivot, the
  branch-free driving pivots on it), or the Burmester points on their two
  curves; the poles and the poses.
- :func:`plane_dxf`, :func:`plane_svg` (or :func:`plane`): the driving
  crank's center-point plane (branch-free regions as polygons with holes,
  the transformed Filemon conics, the poles, the pole triangle and circle,
  ``C0``, and optionally the acceptable region of a solution map and the
  best pivots), or its circle-point plane (Filemon's lines and branch-free
  double wedge, the image poles and their circle, ``C1`` and ``C'k``).

The slider-crank (:func:`slider_crank`), the linkage driven by a linear
actuator (:func:`actuator`) and the inverted slider-crank
(:func:`inverted_slider_crank`: the slot through the block on its swivel)
have their own functions and layers (their docstrings, and the README's
table).

Every file is written whole to a temporary file beside its target and moved
into place when complete (:mod:`burmester._io`): a write error, a full disk
or Ctrl-C leaves no partial file and an existing one as it was.

Every coordinate comes from the core (joints, coupler paths, travel, conic
polylines, poles, sectors); nothing is computed again here. Lengths are
written as they are, in the task's unit, which ``units=`` records (DXF
``$INSUNITS``, SVG ``width``/``height``); it does not scale anything.

**Units.** ``units=`` (default :data:`DEFAULT_UNITS`) takes any unit name
(see :func:`burmester.units.check_units`): DXF ``$INSUNITS`` and
``$MEASUREMENT`` for a unit ezdxf knows, else unitless with the name
written into the drawing; None: unitless.

One layer (DXF) or ``<g id=...>`` group (SVG) per concept, with the same
names in both, each in its own colour (drawings: ``center`` and ``circle``,
the planes of three poses, ``4``/``5`` four or five poses, ``linkage``):

========================= ============ ==================================================
layer                     drawing      what
========================= ============ ==================================================
``VIEW``                  all planes   the view's rectangle
``BRANCH_FREE``           planes of 3  branch-free driving pivots (center plane) or
                                       circle points (circle plane): region outlines,
                                       closed polylines, outer boundaries and holes
``BRANCH_FREE_FILL``      planes of 3  the same regions filled (DXF: a solid HATCH with
                                       holes; SVG: ``fill-rule="evenodd"``)
``ACCEPTABLE``            center       branch-free pivots that also meet the limits
                                       (``acceptable=``), outlines
``ACCEPTABLE_FILL``       center       the same, filled
``TRANSMISSION``          center       contours of a transmission angle
                                       (``transmission=``), each level labelled in
                                       degrees
``CONIC_k``               center       Filemon's line of pose k transformed, every branch
                                       in view (two of k = 1, 2, 3)
``POLES``                 center, 4-5  the poles ``P12, P13, P23`` (the finite ``Pjk`` of
                                       four or five poses)
``POLE_TRIANGLE``         center       the pole triangle
``POLE_CIRCLE``           center       the circle through the poles (a line when they are
                                       collinear)
``DRIVEN_PIVOT``          center, 4    the driven crank's fixed pivot ``C0``
``BEST_PIVOTS``           center       given pivots (``pivots=``), numbered
``LINE_k``                circle       the line through ``C1`` and ``C'k``, k = 1, 2, 3
                                       (and 4 in the circle plane of four poses)
``IMAGE_POLES``           circle       the image poles ``P12, P13, P'23``
``IMAGE_POLE_CIRCLE``     circle       the circle through them
``FIXED_PIVOT_IMAGES``    circle       ``C'1 = C0, C'2, C'3``
``DRIVEN_CIRCLE_POINT``   circle       ``C1``
``CURVE_CCW``             4            the center-point curve where the crank meets the
                                       poses in order counter-clockwise
``CURVE_CW``              4            ... clockwise
``CURVE_ORDER_DEFECT``    4            ... with an order defect
``COINCIDENCE_POINTS``    4            the points ``Q_jk`` where crank positions j and k
                                       coincide
``BRANCH_FREE_ARCS``      4            driving pivots on the curve branch-free with
                                       ``driven=``
``CURVE_1234``            5            the center-point curve of poses 1, 2, 3, 4
``CURVE_1235``            5            the center-point curve of poses 1, 2, 3, 5
``BURMESTER_POINTS``      5            the Burmester points (center points)
``GROUND``                linkage      the ground link ``A0 C0``
``PIVOTS``                linkage      the fixed pivots ``A0`` and ``C0``
``LINKAGE_k``             linkage      the linkage at pose k: crank ``A0 A``, coupler
                                       triangle ``A B P``, rocker ``B C0``, and the
                                       moving joints ``A`` and ``B``
``POSES``                 linkage, 4-5 each pose: its point and a flag along its angle
``COUPLER_CURVE``         linkage      the coupler point over the input's whole range in
                                       the mode of pose 1: one closed polyline when the
                                       input turns fully, else one per arc of
                                       :attr:`burmester.FourBar.input_range`
``COUPLER_PATH``          linkage      the coupler point over the travel, one polyline
                                       per leg from pose k to pose k + 1 (its ends are
                                       the poses); only for a feasible linkage
``TRAVEL``                linkage      the linkage at ``travel_samples`` positions over
                                       the travel (optional)
``TEXT``                  all          labels (``A0``, ``C0``, ``P12``, pose numbers)
========================= ============ ==================================================

Markers (pivots, poles, poses) are circles centred on the exact point; their
radius (0.6 % of the drawing's larger side) and the text height (1.8 %) only
make them visible. The drawing's extent is, for a linkage, the bounding box
of everything drawn and, for a plane, its view (as in the pictures: curves
and regions are clipped to it, points outside it are left out, a pole
circle is drawn whole), grown by 3 % of its larger side for the markers and
labels; DXF ``$LIMMIN``/``$LIMMAX`` and ``$EXTMIN``/``$EXTMAX`` and the
SVG ``viewBox`` are that box.

**SVG coordinates.** The picture is upright: a model point ``(x, y)`` is
written at SVG user coordinates ``(x, -y)`` (SVG's y axis points down), and
the ``viewBox`` is ``xmin -ymax width height``. Paths are ``M``/``L``
commands with absolute coordinates in full precision; ``<title>`` elements
name the things drawn.

**Accuracy.** The region polygons are contours of the core's branch map
(:meth:`burmester.Filemon.branch_map`, or the map given) at its samples,
traced with contourpy midway between a branch-free sample and a defective
one: accurate to a grid cell. The conics, lines, poles, pivots and the
linkage are exact (the core's polylines within their chord tolerance).

Needs ezdxf for DXF and contourpy for the regions (both in
``pip install "burmester[plot]"``); ``import burmester`` imports neither.
"""

from __future__ import annotations

import functools
import inspect
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Dict, Iterator, List, Literal, NamedTuple, Optional, Sequence, Tuple, Union, cast

import numpy as np
import numpy.typing as npt

import burmester
from burmester import _io, _scene, _view
from burmester._burmester import Filemon, Grid, SynthesizedFourBar, Task, clip_line
from burmester.units import check_units, dxf_imperial, dxf_units, format_length

if TYPE_CHECKING:
    from typing_extensions import ParamSpec

    from burmester._burmester import Method, Mode

    _P = ParamSpec("_P")

__all__ = [
    "DEFAULT_PATH_SAMPLES",
    "DEFAULT_TRANSMISSION_LEVELS",
    "DEFAULT_UNITS",
    "LAYERS",
    "MAX_SAMPLES",
    "UNITS",
    "Layer",
    "burmester_plane",
    "burmester_plane_dxf",
    "burmester_plane_svg",
    "linkage",
    "linkage_dxf",
    "linkage_svg",
    "plane",
    "plane_dxf",
    "plane_svg",
]

Point = Tuple[float, float]
Extent = Tuple[float, float, float, float]
Array = npt.NDArray[np.float64]
PathLike = Union[str, Path]
#: A view: a :class:`burmester.Grid`, or ``(xmin, xmax, ymin, ymax)``.
ViewLike = Union[Grid, Sequence[float]]
Plane = Literal["center", "circle"]

#: The usual units of a drawing, with their DXF ``$INSUNITS`` code (any
#: other name is accepted too: :func:`burmester.units.dxf_units` gives the
#: code of those ezdxf knows, and a drawing in a unit it does not know is
#: unitless with the unit's name written into it).
UNITS: Dict[str, int] = {"unitless": 0, "in": 1, "ft": 2, "mm": 4, "cm": 5, "m": 6}
#: The units recorded unless told otherwise: the usual unit of mechanical drawings.
DEFAULT_UNITS = "mm"
#: SVG ``width``/``height`` of one drawing unit: ``(factor, SVG unit)``.
#: ``unitless`` drawings are 800 px along their larger side instead.
_SVG_UNITS: Dict[str, Tuple[float, str]] = {
    "in": (1.0, "in"), "ft": (12.0, "in"), "mm": (1.0, "mm"), "cm": (1.0, "cm"), "m": (1000.0, "mm"),
}
_SVG_NS = "http://www.w3.org/2000/svg"

#: Largest ``travel_samples`` and ``path_samples``.
MAX_SAMPLES = 100_000
#: Contour levels of the transmission angle, degrees, by default (as :func:`burmester.plot.center_plane`).
DEFAULT_TRANSMISSION_LEVELS: Tuple[float, ...] = (30.0, 45.0, 60.0, 75.0)
#: Samples of the coupler curve over a full turn of the input, by default.
DEFAULT_PATH_SAMPLES = 720

_MARKER = 0.006  # marker radius, of the drawing's larger side
_TEXT = 0.018  # text height, of the drawing's larger side
_MARGIN = 0.03  # extent grown by this, of the drawing's larger side
_STROKE = 0.0015  # SVG line width, of the drawing's larger side

_MISSING = 'burmester.export needs {what}: pip install "burmester[plot]"'


class Layer(NamedTuple):
    """A layer: its DXF colour index (ACI), its true colour and what it holds."""

    aci: int
    color: str
    description: str


_POSE_COLORS = {1: (1, "#d62728"), 2: (6, "#9467bd"), 3: (5, "#1f77b4"), 4: (3, "#2ca02c"), 5: (32, "#8c564b")}

#: Every layer, in drawing order (bottom first); see the module's table.
LAYERS: Dict[str, Layer] = {
    "VIEW": Layer(253, "#b0b0b0", "the view's rectangle"),
    "BRANCH_FREE_FILL": Layer(71, "#c7e9b4", "branch-free region, filled"),
    "ACCEPTABLE_FILL": Layer(84, "#74c476", "branch-free and acceptable region, filled"),
    "BRANCH_FREE": Layer(94, "#31a354", "branch-free region, outlines (outer boundaries and holes)"),
    "ACCEPTABLE": Layer(96, "#006d2c", "branch-free and acceptable region, outlines"),
    "TRANSMISSION": Layer(252, "#636363", "contours of the minimum transmission angle, degrees"),
    "COUPLER_CURVE": Layer(9, "#999999", "coupler point over the input's range, mode of pose 1"),
    "TRAVEL": Layer(254, "#cccccc", "the linkage sampled over its travel"),
    "COUPLER_PATH": Layer(4, "#17becf", "coupler point over the travel, pose k to k + 1"),
    "GROUND": Layer(8, "#666666", "ground link A0 C0"),
    **{f"CONIC_{k}": Layer(a, c, f"Filemon line of pose {k} transformed")
       for k, (a, c) in _POSE_COLORS.items() if k <= 3},
    **{f"LINE_{k}": Layer(a, c, f"line through C1 and C'{k}") for k, (a, c) in _POSE_COLORS.items() if k <= 4},
    **{f"LINKAGE_{k}": Layer(a, c, f"the linkage at pose {k}") for k, (a, c) in _POSE_COLORS.items()},
    "BRANCH_FREE_ARCS": Layer(71, "#a1d99b", "driving pivots on the curve, branch-free with C0"),
    "CURVE_CCW": Layer(94, "#1a9850", "center points, crank meets the poses in order (ccw)"),
    "CURVE_CW": Layer(150, "#2166ac", "center points, crank meets the poses in order (cw)"),
    "CURVE_ORDER_DEFECT": Layer(9, "#bdbdbd", "center points with an order defect"),
    "CURVE_1234": Layer(150, "#2166ac", "center-point curve of poses 1, 2, 3, 4"),
    "CURVE_1235": Layer(12, "#b2182b", "center-point curve of poses 1, 2, 3, 5"),
    "POLE_CIRCLE": Layer(251, "#7f7f7f", "circle through the poles"),
    "IMAGE_POLE_CIRCLE": Layer(251, "#7f7f7f", "circle through the image poles"),
    "POLE_TRIANGLE": Layer(250, "#333333", "pole triangle"),
    "POLES": Layer(7, "#000000", "poles P12, P13, P23"),
    "IMAGE_POLES": Layer(7, "#000000", "image poles P12, P13, P'23"),
    "FIXED_PIVOT_IMAGES": Layer(30, "#ff7f0e", "fixed pivot seen from the coupler, C'k"),
    "DRIVEN_CIRCLE_POINT": Layer(130, "#1b9e77", "driven crank's moving pivot C1"),
    "DRIVEN_PIVOT": Layer(30, "#ff7f0e", "driven crank's fixed pivot C0"),
    "BEST_PIVOTS": Layer(2, "#e6ab02", "best driving pivots, numbered"),
    "COINCIDENCE_POINTS": Layer(251, "#4d4d4d", "Q_jk: crank positions j and k coincide"),
    "BURMESTER_POINTS": Layer(2, "#e6ab02", "Burmester points (center points)"),
    "POSES": Layer(40, "#e66101", "poses: point and a flag along the coupler angle"),
    "PIVOTS": Layer(7, "#000000", "fixed pivots A0, C0 (and an actuator's ground pivot G)"),
    "DIMENSIONS": Layer(5, "#0b5394", "dimensions: link lengths at pose 1, fixed pivots from the origin "
                       "(an actuator: its pin-to-pin lengths at the first and last pose)"),
    "TEXT": Layer(250, "#404040", "labels"),
}


# ---------------------------------------------------------------------------
# The drawing: what both writers draw


@dataclass
class _Polyline:
    layer: str
    points: Array
    closed: bool
    title: str


@dataclass
class _Region:
    """A polygon with holes: the outer ring first, rings not repeating their first point."""

    layer: str
    rings: List[Array]
    title: str


@dataclass
class _Circle:
    layer: str
    center: Point
    radius: float
    title: str


@dataclass
class _Marker:
    """A point, drawn as a small circle whose radius the writer chooses."""

    layer: str
    point: Point
    title: str


@dataclass
class _Label:
    point: Point
    text: str


@dataclass
class _Dimension:
    """A dimension (layer ``DIMENSIONS``). ``"aligned"``: the distance from
    ``p1`` to ``p2``, its dimension line ``offset`` text heights to the left
    of ``p1 -> p2`` (negative: to the right). ``"x"``, ``"y"``: the
    ordinate of ``p1`` from the origin, its leader running down (``x``) or
    left (``y``) to beyond the drawing (``p2`` and ``offset`` unused)."""

    kind: Literal["aligned", "x", "y"]
    p1: Point
    p2: Point
    offset: float
    title: str

    @property
    def measurement(self) -> float:
        """What it measures: the length, or the coordinate."""
        if self.kind == "aligned":
            return math.hypot(self.p2[0] - self.p1[0], self.p2[1] - self.p1[1])
        return self.p1[0] if self.kind == "x" else self.p1[1]


@dataclass
class _Drawing:
    """The things to draw, by layer, in model coordinates."""

    title: str
    #: A plane's view: the extent, and markers outside it are left out.
    frame: Optional[Extent] = None
    polylines: List[_Polyline] = field(default_factory=list)
    regions: List[_Region] = field(default_factory=list)
    circles: List[_Circle] = field(default_factory=list)
    markers: List[_Marker] = field(default_factory=list)
    labels: List[_Label] = field(default_factory=list)
    dimensions: List[_Dimension] = field(default_factory=list)

    def polyline(self, layer: str, points: npt.ArrayLike, title: str, closed: bool = False) -> None:
        self.polylines.append(_Polyline(layer, np.asarray(points, dtype=float).reshape(-1, 2), closed, title))

    def marker(self, layer: str, point: Sequence[float], title: str, label: Optional[str] = None) -> None:
        p = (float(point[0]), float(point[1]))
        if self.frame is not None:
            x0, x1, y0, y1 = self.frame
            if not (x0 <= p[0] <= x1 and y0 <= p[1] <= y1):
                return
        self.markers.append(_Marker(layer, p, title))
        if label is not None:
            self.labels.append(_Label(p, label))

    def layers(self) -> List[str]:
        """The layers used, in drawing order."""
        used = {p.layer for p in self.polylines} | {c.layer for c in self.circles}
        used |= {m.layer for m in self.markers}
        for r in self.regions:
            used |= {r.layer, r.layer + "_FILL"}
        if self.labels:
            used.add("TEXT")
        if self.dimensions:
            used.add("DIMENSIONS")
        return [name for name in LAYERS if name in used]

    def bounds(self) -> Extent:
        """The frame if any, else the bounding box of the geometry (markers
        and labels by their points)."""
        if self.frame is not None:
            return self.frame
        pts: List[Array] = [p.points for p in self.polylines]
        pts += [ring for r in self.regions for ring in r.rings]
        pts += [np.array([[c.center[0] - c.radius, c.center[1] - c.radius],
                          [c.center[0] + c.radius, c.center[1] + c.radius]]) for c in self.circles]
        pts += [np.array([m.point]) for m in self.markers] + [np.array([t.point]) for t in self.labels]
        allpts = np.vstack([p for p in pts if len(p)])
        lo, hi = allpts.min(axis=0), allpts.max(axis=0)
        return (float(lo[0]), float(hi[0]), float(lo[1]), float(hi[1]))

    def sizes(self, units: str = "unitless") -> Tuple[Extent, float, float]:
        """``(extent, marker radius, text height)``: the bounds grown by the
        margin, and around the dimensions' lines and texts (their texts
        show ``units``)."""
        x0, x1, y0, y1 = self.bounds()
        size = max(x1 - x0, y1 - y0)
        if not size > 0.0:
            size = 1.0
        m = _MARGIN * size
        text = _TEXT * size
        ex = [x0 - m, x1 + m, y0 - m, y1 + m]
        for place in self.dimension_layout(text, units):
            (tx, ty), (hx, hy) = place.text_at, place.half
            boxes = [(px, py, text, text) for px, py in place.points] + [(tx, ty, hx + text, hy + text)]
            for px, py, rx, ry in boxes:
                ex = [min(ex[0], px - rx), max(ex[1], px + rx), min(ex[2], py - ry), max(ex[3], py + ry)]
        return (ex[0], ex[1], ex[2], ex[3]), _MARKER * size, text

    def dimension_layout(self, text: float, units: str = "unitless") -> List["_DimensionPlace"]:
        """Where each dimension goes for text height ``text``
        (:class:`_DimensionPlace`): an aligned one's dimension line
        ``offset`` text heights off the measured points, its text over the
        line's middle; an ordinate's leader to beyond the geometry's bounds
        (down for x, left for y), its text running on along the leader, a
        row further out where it would meet one already placed."""
        if not self.dimensions:
            return []
        x0, _, y0, _ = self.bounds()
        decimals = _dimension_decimals(self)
        out: List[_DimensionPlace] = []
        placed: List[Tuple[str, int, float]] = []  # ordinates: kind, row, where across the leader
        for dim in self.dimensions:
            label = _dimension_text(dim, decimals, units)
            length = _CHAR * text * len(label)  # the text's length, about
            if dim.kind == "aligned":
                dx, dy = dim.p2[0] - dim.p1[0], dim.p2[1] - dim.p1[1]
                n = math.hypot(dx, dy) or 1.0
                ux, uy = -dy / n, dx / n  # the unit normal to the left
                ox, oy = ux * dim.offset * text, uy * dim.offset * text
                a = (dim.p1[0] + ox, dim.p1[1] + oy)
                b = (dim.p2[0] + ox, dim.p2[1] + oy)
                side = 1.0 if dim.offset >= 0.0 else -1.0  # the text on the line's outer side
                at = ((a[0] + b[0]) / 2 + side * ux * 0.8 * text, (a[1] + b[1]) / 2 + side * uy * 0.8 * text)
                half = 0.5 * length + text
                out.append(_DimensionPlace([a, b], at, (half, half), label))
                continue
            across = dim.p1[0] if dim.kind == "x" else dim.p1[1]
            level = 0
            while any(k == dim.kind and lv == level and abs(w - across) < 1.6 * text for k, lv, w in placed):
                level += 1
            placed.append((dim.kind, level, across))
            reach = 3.0 * text + level * (length + 1.5 * text)
            if dim.kind == "x":
                end = (dim.p1[0], y0 - reach)
                out.append(_DimensionPlace([end], (end[0], end[1] - 0.5 * text - 0.5 * length),
                                           (0.6 * text, 0.5 * length), label))
            else:
                end = (x0 - reach, dim.p1[1])
                out.append(_DimensionPlace([end], (end[0] - 0.5 * text - 0.5 * length, end[1]),
                                           (0.5 * length, 0.6 * text), label))
        return out


class _DimensionPlace(NamedTuple):
    """Where a dimension goes: ``points``, the dimension line's two ends
    (aligned) or the leader's end (ordinate); ``text_at``, the text's middle
    and ``half`` its half extent along x and y, about; ``label``, the text."""

    points: List[Point]
    text_at: Point
    half: Tuple[float, float]
    label: str


_CHAR = 1.0  # a character's width, of the text height (at most, for the extent)


def _dimension_decimals(d: _Drawing) -> int:
    """Decimals of a dimension's text: about five significant digits of
    the drawing's size (2 for a linkage of a few hundred mm), 0 to 8."""
    x0, x1, y0, y1 = d.bounds()
    size = max(x1 - x0, y1 - y0)
    return min(8, max(0, 5 - math.ceil(math.log10(size)))) if size > 0.0 else 3


def _dimension_text(dim: _Dimension, decimals: int, units: str) -> str:
    """What a dimension shows: ``"40.81 mm"``, ``"x = -7.98 mm"``."""
    unit = "" if units == "unitless" else f" {units}"
    value = f"{abs(dim.measurement) if dim.kind != 'aligned' else dim.measurement:.{decimals}f}{unit}"
    if dim.kind == "aligned":
        return value
    return f"{dim.kind} = {'-' if dim.measurement < 0.0 else ''}{value}"


# ---------------------------------------------------------------------------
# Checks


def _units(units: Optional[str]) -> str:
    """A unit name, checked (:func:`burmester.units.check_units`); None is
    ``"unitless"``."""
    name = check_units(units, "units")
    return "unitless" if name is None else name


def _samples(name: str, value: Any, lo: int) -> int:
    """``value`` as an int from ``lo`` to :data:`MAX_SAMPLES`, or InvalidInputError."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an int, got {type(value).__name__}")
    if not lo <= int(value) <= MAX_SAMPLES:
        raise burmester.InvalidInputError(f"{name} must be from {lo} to {MAX_SAMPLES}, got {int(value)}")
    return int(value)


def _target(path: PathLike, suffixes: Sequence[str]) -> Path:
    """The output path, checked: one of ``suffixes``, in a folder that exists."""
    p = Path(path)
    if p.suffix.lower() not in suffixes:
        got = f"'{p.suffix}'" if p.suffix else "no extension"
        raise burmester.InvalidInputError(
            f"{p.name!r} has {got}; end the file name in {' or '.join(suffixes)}"
        )
    if not p.parent.is_dir():
        raise burmester.InvalidInputError(
            f"cannot write {p}: the folder {str(p.parent)!r} does not exist; create it first"
        )
    return p


# ---------------------------------------------------------------------------
# Geometry helpers (drawing only: the core gives the points)


def _rectangle(extent: Extent) -> Array:
    x0, x1, y0, y1 = extent
    return np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])


def _regions(grid: Grid, mask: npt.NDArray[np.bool_]) -> Iterator[List[Array]]:
    """The regions where ``mask`` is True as polygons with holes (outer ring
    first), traced by contourpy midway between samples; the samples are
    extended to the view's edges, so a region reaching an edge ends on it."""
    try:
        import contourpy
    except ImportError:
        raise ImportError(_MISSING.format(what="contourpy for the region polygons")) from None
    xs, ys = grid.cell_centers()
    x = np.concatenate([[grid.xmin], xs, [grid.xmax]])
    y = np.concatenate([[grid.ymin], ys, [grid.ymax]])
    z = np.pad(mask.astype(np.float64), 1, mode="edge")
    gen = contourpy.contour_generator(x, y, z, fill_type=contourpy.FillType.OuterOffset)
    # FillType.OuterOffset: per polygon, its points and the offsets of its rings.
    points, offsets = cast(Tuple[List[Array], List[npt.NDArray[np.uint32]]], gen.filled(0.5, 1.5))
    for pts, offs in zip(points, offsets):
        rings = [np.asarray(pts[a:b], dtype=float) for a, b in zip(offs[:-1], offs[1:])]
        yield [r[:-1] if len(r) > 1 and np.array_equal(r[0], r[-1]) else r for r in rings]


def _contours(grid: Grid, values: Array, levels: Sequence[float]) -> Iterator[Tuple[float, Array]]:
    """``(level, line)``: the contour lines of ``values`` (NaN where undefined)
    on the grid's samples, by contourpy, one ``(n, 2)`` array per piece."""
    try:
        import contourpy
    except ImportError:
        raise ImportError(_MISSING.format(what="contourpy for the contours")) from None
    xs, ys = grid.cell_centers()
    gen = contourpy.contour_generator(xs, ys, np.ma.masked_invalid(values), line_type=contourpy.LineType.Separate)
    for level in sorted(levels):
        for line in cast(List[Array], gen.lines(level)):
            yield level, np.asarray(line, dtype=float)


def _clip_polygon(poly: Array, extent: Extent) -> Array:
    """A polygon clipped to the rectangle ``extent`` (Sutherland-Hodgman)."""
    x0, x1, y0, y1 = extent
    edges = ((0, x0, 1.0), (0, x1, -1.0), (1, y0, 1.0), (1, y1, -1.0))  # axis, value, inside sign
    out = [tuple(p) for p in poly.tolist()]
    for axis, value, sign in edges:
        src, out = out, []
        for i, cur in enumerate(src):
            prev = src[i - 1]
            cin = sign * (cur[axis] - value) >= 0.0
            pin = sign * (prev[axis] - value) >= 0.0
            if cin != pin:
                t = (value - prev[axis]) / (cur[axis] - prev[axis])
                out.append(tuple(prev[k] + t * (cur[k] - prev[k]) for k in range(2)))
            if cin:
                out.append(cur)
        if not out:
            break
    return np.array(out, dtype=float).reshape(-1, 2)


def _circle_or_line(d: _Drawing, layer: str, circle: Dict[str, Any], extent: Extent, title: str) -> None:
    """A pole circle, or the line (clipped to ``extent``) it becomes when the poles are collinear."""
    if circle["kind"] == "circle":
        d.circles.append(_Circle(layer, tuple(circle["center"]), float(circle["radius"]), title))
    else:
        seg = clip_line(circle["point"], circle["direction"], extent)
        if seg is not None:
            d.polyline(layer, seg, title)


def _runs(x: Array, y: Array, valid: npt.NDArray[np.bool_]) -> Iterator[Array]:
    """The runs of at least two valid samples, as ``(n, 2)`` arrays."""
    pts = np.column_stack([x, y])
    idx = np.flatnonzero(np.diff(np.concatenate([[0], valid.astype(np.int8), [0]])))
    for a, b in zip(idx[::2], idx[1::2]):
        if b - a >= 2:
            yield pts[a:b]


# ---------------------------------------------------------------------------
# The linkage


def _links(d: _Drawing, layer: str, at: _scene.Position, what: str, joints: bool) -> None:
    """Crank, coupler triangle and rocker of a position (the core's joints)."""
    o2, a, b, o4, p = at
    d.polyline(layer, [o2, a], f"crank A0 A, {what}")
    d.polyline(layer, [a, b, p], f"coupler A B P, {what}", closed=True)
    d.polyline(layer, [b, o4], f"rocker B C0, {what}")
    if joints:
        d.marker(layer, a, f"moving pivot A, {what}")
        d.marker(layer, b, f"moving pivot B, {what}")


def _input_arcs(sfb: SynthesizedFourBar) -> List[Tuple[float, float, bool]]:
    """The input's range as ``(start, end, closed)``, counter-clockwise."""
    ranges = sfb.fourbar.input_range
    if ranges is None:
        return [(0.0, 2.0 * math.pi, True)]
    return [(a, b if b > a else b + 2.0 * math.pi, False) for a, b in ranges]


def _linkage_drawing(sfb: SynthesizedFourBar, task: Optional[Task], travel_samples: int,
                     path_samples: int, labels: bool, dimensions: bool = True) -> _Drawing:
    travel_samples = _samples("travel_samples", travel_samples, 0)
    if travel_samples == 1:
        raise burmester.InvalidInputError("travel_samples must be 0 (none) or at least 2, got 1")
    path_samples = _samples("path_samples", path_samples, 8)
    figures = sfb.figures
    if travel_samples and not figures.feasible:
        raise burmester.AssemblyError(
            "the linkage cannot be driven from pose 1 through the poses in order (a branch, order "
            "or circuit defect), so it has no travel to sample: draw it without travel samples "
            "(travel_samples=0, no --travel) or choose another driving pivot"
        )
    fb = sfb.fourbar
    sc = _scene.linkage_scene(sfb, task)
    a0, c0 = sc.a0, sc.c0
    n = len(sc.at_poses)
    d = _Drawing(f"four-bar at {n} poses: {fb.grashof}, A0 {a0}, C0 {c0}")
    d.polyline("GROUND", [a0, c0], "ground A0 C0")
    d.marker("PIVOTS", a0, "fixed pivot A0", "A0" if labels else None)
    d.marker("PIVOTS", c0, "fixed pivot C0", "C0" if labels else None)

    mode: Mode = sfb.modes[0] or "open"
    for a, b, closed in _input_arcs(sfb):
        count = max(8, math.ceil(path_samples * (b - a) / (2.0 * math.pi)))
        ts = np.linspace(a, b, count + 1)[:-1] if closed else np.linspace(a, b, count + 1)
        x, y, ok = fb.coupler_path(sfb.coupler_point, ts, mode)
        for run in _runs(x, y, ok):
            d.polyline("COUPLER_CURVE", run, f"coupler curve ({mode})", closed=closed and bool(ok.all()))

    stops = sfb.travel_stops
    if figures.feasible and stops is not None:
        for k, (a, b) in enumerate(zip(stops[:-1], stops[1:]), start=1):
            count = max(2, math.ceil(path_samples * abs(b - a) / (2.0 * math.pi)))
            x, y, ok = fb.coupler_path(sfb.coupler_point, np.linspace(a, b, count + 1), mode)
            for run in _runs(x, y, ok):
                d.polyline("COUPLER_PATH", run, f"coupler path, pose {k} to pose {k + 1}")
        if travel_samples:
            for i, t in enumerate(sfb.travel_angles(travel_samples).tolist(), start=1):
                _links(d, "TRAVEL", _scene.position(sfb, t, mode), f"travel sample {i} of {travel_samples}", False)

    for k, (_, m, at) in enumerate(sc.at_poses, start=1):
        _links(d, f"LINKAGE_{k}", at, f"pose {k} ({m or 'toggle'})", True)

    _poses(d, sc.poses, sc.flag, labels)
    if dimensions:
        _dimensions(d, sc.at_poses[0].position)
    return d


def _dimensions(d: _Drawing, pose1: _scene.Position) -> None:
    """The dimensions of a linkage (layer ``DIMENSIONS``): the ground
    ``A0 C0``, and at pose 1 the crank ``A0 A``, the coupler ``A B`` and its
    triangle's sides ``A P``, ``B P`` to the coupler point, and the rocker
    ``C0 B`` (aligned), each dimension line 2.5, 5 or 7.5 text heights off
    its link, on the side away from the linkage's middle (the coupler
    triangle's for its sides) first, at the first place where its text
    meets no text placed before; the fixed pivots' x and y from the origin
    (ordinates)."""
    o2, a, b, o4, p = pose1
    mid = ((o2[0] + a[0] + b[0] + o4[0]) / 4, (o2[1] + a[1] + b[1] + o4[1]) / 4)
    tri = ((a[0] + b[0] + p[0]) / 3, (a[1] + b[1] + p[1]) / 3)
    x0, x1, y0, y1 = d.bounds()
    text = _TEXT * (max(x1 - x0, y1 - y0) or 1.0)  # as the writers will size it
    decimals = _dimension_decimals(d)
    texts: List[Array] = []  # the placed texts, each as the centers of circles of radius 0.6 text along it
    for name, p1, p2, ref in (("ground A0 C0", o2, o4, mid), ("crank A0 A", o2, a, mid),
                              ("coupler A B", a, b, mid), ("coupler A P", a, p, tri),
                              ("coupler B P", b, p, tri), ("rocker C0 B", o4, b, mid)):
        dx, dy = p2[0] - p1[0], p2[1] - p1[1]
        length = math.hypot(dx, dy)
        if length == 0.0:
            continue  # a coupler point on a joint: no side to dimension
        # To the left of p1 -> p2 is (-dy, dx): the side away from the middle first.
        away = 1.0 if -dy * (ref[0] - p1[0]) + dx * (ref[1] - p1[1]) < 0.0 else -1.0
        ux, uy = dx / length, dy / length
        half = 0.5 * _CHAR * text * (len(f"{length:.{decimals}f}") + 4)  # the text, a unit included
        along = np.linspace(-half, half, max(2, math.ceil(2 * half / text) + 1))
        best: Optional[Tuple[int, float, Array]] = None
        for level in (2.5, 5.0, 7.5):
            for side in (away, -away):
                offset = side * level
                cx = (p1[0] + p2[0]) / 2 + (-uy) * (offset + math.copysign(0.8, offset)) * text
                cy = (p1[1] + p2[1]) / 2 + ux * (offset + math.copysign(0.8, offset)) * text
                circles = np.column_stack([cx + along * ux, cy + along * uy])
                hits = sum(int(np.any(np.hypot(*(circles[:, None, :] - t[None, :, :]).transpose(2, 0, 1))
                                      < 1.2 * text)) for t in texts)
                if best is None or hits < best[0]:
                    best = (hits, offset, circles)
                if hits == 0:
                    break
            if best is not None and best[0] == 0:
                break
        assert best is not None
        _, offset, circles = best
        texts.append(circles)
        if dx < 0.0 or (dx == 0.0 and dy < 0.0):
            # Measured left to right (or upward), so that the text reads upright; the same side.
            p1, p2, offset = p2, p1, -offset
        d.dimensions.append(_Dimension("aligned", (float(p1[0]), float(p1[1])), (float(p2[0]), float(p2[1])),
                                       offset, f"{name}, pose 1"))
    for name, pivot in (("A0", o2), ("C0", o4)):
        at = (float(pivot[0]), float(pivot[1]))
        d.dimensions.append(_Dimension("x", at, at, 0.0, f"fixed pivot {name}: x from the origin"))
        d.dimensions.append(_Dimension("y", at, at, 0.0, f"fixed pivot {name}: y from the origin"))


# ---------------------------------------------------------------------------
# The planes


class _Overlays(NamedTuple):
    """What a solution map adds to the center-point plane."""

    acceptable: Optional[npt.ArrayLike]
    transmission: Optional[npt.ArrayLike]
    levels: Sequence[float]
    pivots: Optional[Sequence[Point]]


def _center_drawing(sc: _scene.CenterScene, filemon: Filemon, pivots: Optional[Sequence[Point]],
                    levels: Sequence[float], labels: bool) -> _Drawing:
    grid = sc.grid
    extent = grid.extent
    d = _Drawing("driving crank center-point plane", extent)
    d.polyline("VIEW", _rectangle(extent), "view", closed=True)
    for rings in _regions(grid, sc.free):
        d.regions.append(_Region("BRANCH_FREE", rings, "branch-free driving pivots"))
    if sc.acceptable is not None:
        for rings in _regions(grid, sc.free & sc.acceptable):
            d.regions.append(_Region("ACCEPTABLE", rings, "branch-free and acceptable driving pivots"))
    values = sc.transmission
    if values is not None:
        longest: Dict[float, Array] = {}
        for level, line in _contours(grid, values, levels):
            d.polyline("TRANSMISSION", line, f"transmission angle {level:g} deg")
            if len(line) > len(longest.get(level, ())):
                longest[level] = line
        if labels:  # each level once, at the middle of its longest piece
            for level, line in longest.items():
                d.labels.append(_Label((float(line[len(line) // 2][0]), float(line[len(line) // 2][1])), f"{level:g}"))
    for pose, kind, polylines in _scene.conics(filemon, extent):
        for pl in polylines:
            d.polyline(f"CONIC_{pose}", pl, f"Filemon line {pose} transformed ({kind})")
    poles = [(name, p) for name, p in sc.poles if p is not None]
    for name, p in poles:
        d.marker("POLES", p, f"pole {name}", name if labels else None)
    if sc.pole_triangle:  # not with a pole at infinity
        d.polyline("POLE_TRIANGLE", [p for _, p in poles], "pole triangle", closed=True)
        _circle_or_line(d, "POLE_CIRCLE", filemon.task.pole_circle(), extent, "pole circle")
    d.marker("DRIVEN_PIVOT", sc.c0, "driven crank's fixed pivot C0", "C0" if labels else None)
    for k, p in enumerate(pivots or [], start=1):
        d.marker("BEST_PIVOTS", p, f"driving pivot {k}", str(k) if labels else None)
    return d


def _circle_drawing(sc: _scene.CircleScene, task: Task, labels: bool) -> _Drawing:
    extent = sc.extent
    d = _Drawing("driving crank circle-point plane (pose 1)", extent)
    d.polyline("VIEW", _rectangle(extent), "view", closed=True)
    c1, radius = sc.construction.c1, sc.radius
    for a0, a1, is_free in sc.sectors:
        if not is_free:
            continue
        # Arc points 5 degrees apart at this radius lie outside the view, so the clipped wedge is exact.
        ts = np.linspace(a0, a1, max(2, math.ceil((a1 - a0) / math.radians(5.0))) + 1)
        wedge = np.vstack([[c1], np.column_stack([c1[0] + radius * np.cos(ts), c1[1] + radius * np.sin(ts)])])
        clipped = _clip_polygon(wedge, extent)
        if len(clipped) >= 3:
            d.regions.append(_Region("BRANCH_FREE", [clipped], "branch-free driving circle points"))
    if sc.image_poles:  # not with a pole at infinity
        for name, p in zip(("P12", "P13", "P'23"), sc.image_poles):
            d.marker("IMAGE_POLES", p, f"image pole {name}", name if labels else None)
        _circle_or_line(d, "IMAGE_POLE_CIRCLE", task.image_pole_circle(), extent, "image-pole circle")
    _filemon_construction(d, sc.construction, labels, sc.middle)
    return d


def _filemon_construction(d: _Drawing, made: _scene.Construction, labels: bool, middle: Optional[int] = None) -> None:
    """Filemon's construction in the circle-point plane: its lines (one per
    pose, clipped to the view; layers ``LINE_k``), the fixed pivot's images
    ``C'k`` and the driven circle point ``C1``."""
    for k, seg in enumerate(made.lines, start=1):
        if seg is not None:
            d.polyline(f"LINE_{k}", seg, f"line C1 C'{k} (pose {k})" + (", middle" if k == middle else ""))
    for k, p in enumerate(made.images, start=1):
        name = f"C'{k}" + (" = C0" if k == 1 else "")
        d.marker("FIXED_PIVOT_IMAGES", p, f"fixed pivot image {name}", name if labels else None)
    d.marker("DRIVEN_CIRCLE_POINT", made.c1, "driven crank's moving pivot C1", "C1" if labels else None)



def _poses(d: _Drawing, poses: Sequence[Sequence[float]], flag: float, labels: bool) -> None:
    """Each pose: a flag along its angle and a marker at its point (layer ``POSES``)."""
    for k, (px, py, angle) in enumerate(poses, start=1):
        d.polyline("POSES", [(px, py), (px + flag * math.cos(angle), py + flag * math.sin(angle))],
                   f"pose {k}: flag along the coupler angle")
        d.marker("POSES", (px, py), f"pose {k}", str(k) if labels else None)


def _curve_drawing(task: Task, view: Optional[ViewLike], driven: Optional[Point], labels: bool,
                   plane: Plane) -> _Drawing:
    """The scene of a plane of four or five poses (:func:`burmester._scene.curve_scene`) as a drawing."""
    if plane not in ("center", "circle"):
        raise burmester.InvalidInputError(f"plane must be 'center' or 'circle', got {plane!r}")
    sc = _scene.curve_scene(task, view, driven, plane)
    extent = sc.extent
    d = _Drawing(f"{sc.n_poses} poses: {sc.title}", extent)
    d.polyline("VIEW", _rectangle(extent), "view", closed=True)
    what = "circle points" if plane == "circle" else "pivots"
    for pts in sc.free_arcs:
        d.polyline("BRANCH_FREE_ARCS", pts, f"branch-free driving {what} for C0")
    if sc.construction is not None:
        _filemon_construction(d, sc.construction, labels)
    if sc.driven is not None:
        d.marker("DRIVEN_PIVOT", sc.driven, "driven crank's fixed pivot C0", "C0" if labels else None)
    for order, direction, pts in sc.order_arcs:
        d.polyline(_scene.ORDER_LAYERS[direction], pts, f"{plane}-point curve, crank order {order}")
    for pair, point in sc.coincidence:
        name = "Q{}{}{}".format(sc.prime, *pair)
        d.marker("COINCIDENCE_POINTS", point, name, name if labels else None)
    for which, polylines in sc.curves:
        for pts in polylines:
            d.polyline(f"CURVE_{which}", pts, f"center-point curve of poses {', '.join(which)}")
    for k, center in enumerate(sc.burmester_points, start=1):
        d.marker("BURMESTER_POINTS", center, f"Burmester point B{k}", f"B{k}" if labels else None)
    for (i, j), point in sc.poles:
        d.marker("POLES", point, f"pole P{i}{j}", f"P{i}{j}" if labels else None)
    _poses(d, task.poses, 0.12 * task.scale, labels)
    return d


def _plane_drawing(filemon: Filemon, view: Optional[ViewLike], plane: str, grid: Optional[Tuple[int, int]],
                   method: Method, free: Optional[npt.ArrayLike], over: _Overlays, labels: bool) -> _Drawing:
    if plane == "circle":
        return _circle_drawing(_scene.circle_scene(filemon, view), filemon.task, labels)
    if plane != "center":
        raise burmester.InvalidInputError(f"plane must be 'center' or 'circle', got {plane!r}")
    sc = _scene.center_scene(filemon, view, grid, method, free, over.acceptable, over.transmission)
    return _center_drawing(sc, filemon, over.pivots, over.levels, labels)


# ---------------------------------------------------------------------------
# Writers


def _rgb(color: str) -> Tuple[int, int, int]:
    return (int(color[1:3], 16), int(color[3:5], 16), int(color[5:7], 16))


def _write_dxf(d: _Drawing, path: Path, units: str) -> None:
    """Write the drawing as DXF R2010: a layer per concept, ``$INSUNITS``, limits and extents."""
    try:
        from ezdxf import colors, const
        from ezdxf.filemanagement import new
    except ImportError:
        raise ImportError(_MISSING.format(what="ezdxf to write DXF")) from None
    extent, marker, text = d.sizes(units)
    doc = new("R2010")
    code = dxf_units(units)
    doc.units = 0 if code is None else code  # a unit ezdxf does not know: unitless, its name in the drawing
    doc.header["$MEASUREMENT"] = 0 if code is not None and dxf_imperial(code) else 1
    doc.header.custom_vars.append("UNITS", units)
    for name in d.layers():
        spec = LAYERS[name]
        layer = doc.layers.add(name, color=spec.aci, true_color=colors.rgb2int(_rgb(spec.color)))
        layer.description = spec.description
    msp = doc.modelspace()
    for r in d.regions:
        for ring in r.rings:
            _lwpolyline(msp, ring, True, r.layer)
        hatch = msp.add_hatch(color=colors.BYLAYER, dxfattribs={"layer": r.layer + "_FILL"})
        for k, ring in enumerate(r.rings):
            flags = const.BOUNDARY_PATH_EXTERNAL if k == 0 else const.BOUNDARY_PATH_DEFAULT
            hatch.paths.add_polyline_path(ring.tolist(), is_closed=True, flags=flags)
    for p in d.polylines:
        _lwpolyline(msp, p.points, p.closed, p.layer)
    for c in d.circles:
        msp.add_circle(c.center, c.radius, dxfattribs={"layer": c.layer})
    for m in d.markers:
        msp.add_circle(m.point, marker, dxfattribs={"layer": m.layer})
    for t in d.labels:
        at = (t.point[0] + marker, t.point[1] + marker)
        msp.add_text(t.text, height=text, dxfattribs={"layer": "TEXT", "insert": at})
    if d.dimensions:
        _dxf_dimensions(doc, d, text, units)
    x0, x1, y0, y1 = extent
    msp.reset_limits((x0, y0), (x1, y1))
    msp.reset_extents((x0, y0, 0.0), (x1, y1, 0.0))
    doc.set_modelspace_vport(height=y1 - y0, center=((x0 + x1) / 2, (y0 + y1) / 2))
    doc.saveas(path)


def _lwpolyline(msp: Any, points: Array, closed: bool, layer: str) -> None:
    """An LWPOLYLINE of ``points`` ``(n, 2)`` on ``layer``, its vertices
    set in one step: ezdxf's ``add_lwpolyline`` appends them one at a
    time, each copying those before (quadratic: 100 000 vertices took
    minutes)."""
    pl = msp.add_lwpolyline([], close=closed, dxfattribs={"layer": layer})
    # ezdxf's vertex layout: x, y, start width, end width, bulge.
    pl.lwpoints.set(np.column_stack([np.asarray(points, dtype=float).reshape(-1, 2), np.zeros((len(points), 3))]))


def _dxf_dimensions(doc: Any, d: _Drawing, text: float, units: str) -> None:
    """The drawing's dimensions as DXF DIMENSION entities (layer
    ``DIMENSIONS``, dimension style ``BURMESTER``: text ``text`` high, the
    unit after the number, an ordinate's sign before it), each rendered
    (its block holds the lines, arrows and text, so that a reader that does
    not compute dimensions shows them too)."""
    unit = "" if units == "unitless" else f" {units}"
    style = doc.dimstyles.new("BURMESTER")
    for key, value in {
        "dimtxt": text, "dimasz": 0.6 * text, "dimexo": 0.3 * text, "dimexe": 0.5 * text,
        "dimgap": 0.3 * text, "dimdec": _dimension_decimals(d), "dimdsep": ord("."), "dimlfac": 1.0,
        "dimpost": f"<>{unit}", "dimtad": 1, "dimtih": 0, "dimtoh": 0, "dimzin": 8,
        "dimclrd": 256, "dimclre": 256, "dimclrt": 256, "dimtxsty": "Standard",
    }.items():
        style.dxf.set(key, value)
    msp = doc.modelspace()
    for dim, place in zip(d.dimensions, d.dimension_layout(text, units)):
        attribs = {"layer": "DIMENSIONS"}
        if dim.kind == "aligned":
            # ezdxf's distance is to the left of p1 -> p2 when positive, as the offset.
            # The unit as the dimension's own override too: ezdxf writes no DIMPOST into the style's record.
            made = msp.add_aligned_dim(dim.p1, dim.p2, distance=dim.offset * text, dimstyle="BURMESTER",
                                       dxfattribs=attribs, override={"dimpost": f"<>{unit}"})
        else:
            sign = "-" if dim.measurement < 0.0 else ""
            end = place.points[-1]
            offset = (end[0] - dim.p1[0], end[1] - dim.p1[1])
            add = msp.add_ordinate_x_dim if dim.kind == "x" else msp.add_ordinate_y_dim
            made = add(dim.p1, offset, dimstyle="BURMESTER", dxfattribs=attribs,
                       override={"dimpost": f"{dim.kind} = {sign}<>{unit}"})
        made.render()


def _num(v: float) -> str:
    """A coordinate in full precision (shortest round-trip form)."""
    return repr(float(v) + 0.0)


def _path_data(rings: Sequence[Array], closed: bool) -> str:
    """SVG path data of polylines, y flipped: ``M x -y L ...`` (``Z`` when closed)."""
    parts = []
    for ring in rings:
        pts = " L ".join(f"{_num(x)} {_num(-y)}" for x, y in ring.tolist())
        parts.append(f"M {pts}" + (" Z" if closed else ""))
    return " ".join(parts)


def _titled(parent: ET.Element, tag: str, attrib: Dict[str, str], title: str) -> ET.Element:
    el = ET.SubElement(parent, tag, attrib)
    ET.SubElement(el, "title").text = title
    return el


def _write_svg(d: _Drawing, path: Path, units: str) -> None:
    """Write the drawing as SVG: a ``<g id=LAYER>`` per concept, y flipped, viewBox the extent."""
    (x0, x1, y0, y1), marker, text = d.sizes(units)
    w, h = x1 - x0, y1 - y0
    size = max(w, h)
    if units not in _SVG_UNITS:  # unitless, or a unit SVG has no length for: 800 px along the larger side
        f, unit = 800.0 / max(w, h), ""
    else:
        f, unit = _SVG_UNITS[units]
    svg = ET.Element("svg", {
        "xmlns": _SVG_NS, "version": "1.1",
        "width": f"{w * f:.6g}{unit}", "height": f"{h * f:.6g}{unit}",
        "viewBox": f"{_num(x0)} {_num(-y1)} {_num(w)} {_num(h)}",
        "data-units": units,
    })
    ET.SubElement(svg, "title").text = d.title
    ET.SubElement(svg, "desc").text = (
        f"burmester export, lengths in {units}. A model point (x, y) is at SVG user "
        "coordinates (x, -y); the viewBox is (xmin, -ymax, width, height) of the drawing's extent."
    )
    for name in d.layers():
        spec = LAYERS[name]
        style = {"id": name, "data-description": spec.description}
        if name.endswith("_FILL"):
            style.update({"fill": spec.color, "stroke": "none", "fill-rule": "evenodd"})
        elif name == "TEXT":
            style.update({"fill": spec.color, "font-family": "sans-serif", "font-size": _num(text)})
        else:
            style.update({"fill": "none", "stroke": spec.color, "stroke-width": _num(_STROKE * size),
                          "stroke-linejoin": "round", "stroke-linecap": "round"})
        g = ET.SubElement(svg, "g", style)
        for r in d.regions:
            if name == r.layer + "_FILL":
                _titled(g, "path", {"d": _path_data(r.rings, True)}, r.title)
            elif name == r.layer:
                _titled(g, "path", {"d": _path_data(r.rings, True)}, r.title)
        for p in d.polylines:
            if p.layer == name:
                _titled(g, "path", {"d": _path_data([p.points], p.closed)}, p.title)
        for c in d.circles:
            if c.layer == name:
                _titled(g, "circle", {"cx": _num(c.center[0]), "cy": _num(-c.center[1]),
                                      "r": _num(c.radius)}, c.title)
        for m in d.markers:
            if m.layer == name:
                _titled(g, "circle", {"cx": _num(m.point[0]), "cy": _num(-m.point[1]), "r": _num(marker),
                                      "fill": spec.color, "fill-opacity": "0.35"}, m.title)
        if name == "DIMENSIONS":
            _svg_dimensions(g, d, text, units)
        if name == "TEXT":
            for t in d.labels:
                el = ET.SubElement(g, "text", {"x": _num(t.point[0] + marker), "y": _num(-(t.point[1] + marker))})
                el.text = t.text
    ET.indent(svg)
    ET.ElementTree(svg).write(path, encoding="utf-8", xml_declaration=True)


def _svg_dimensions(g: ET.Element, d: _Drawing, text: float, units: str) -> None:
    """The drawing's dimensions in SVG, in the ``DIMENSIONS`` group, placed
    as in DXF: per dimension a ``<g>`` (``data-kind``: aligned, x or y;
    ``data-measurement``: the length or coordinate in full precision) with
    its extension lines and dimension line, or its leader, as ``<line>``
    elements, and its text (an x ordinate's upright, along its leader)."""
    for dim, place in zip(d.dimensions, d.dimension_layout(text, units)):
        el = _titled(g, "g", {"data-kind": dim.kind, "data-measurement": _num(dim.measurement)},
                     f"{dim.title}: {place.label}")
        if dim.kind == "aligned":
            a, b = place.points
            segments = [(dim.p1, a), (dim.p2, b), (a, b)]
        else:
            segments = [(dim.p1, place.points[0])]
        for (ax_, ay_), (bx_, by_) in segments:
            ET.SubElement(el, "line", {"x1": _num(ax_), "y1": _num(-ay_), "x2": _num(bx_), "y2": _num(-by_)})
        tx, ty = place.text_at
        attrib = {"x": _num(tx), "y": _num(-ty), "text-anchor": "middle", "dominant-baseline": "central",
                  "font-family": "sans-serif", "font-size": _num(text), "stroke": "none",
                  "fill": LAYERS["DIMENSIONS"].color}
        if dim.kind == "x":
            attrib["transform"] = f"rotate(-90 {_num(tx)} {_num(-ty)})"
        ET.SubElement(el, "text", attrib).text = place.label


_WRITERS = {".dxf": _write_dxf, ".svg": _write_svg}


def _write(d: _Drawing, path: Path, units: str) -> Path:
    if units not in UNITS:
        # A unit DXF may not know: its name written into the drawing (by both writers), in a corner.
        x0, _, y0, _ = d.bounds()
        d.labels.append(_Label((x0, y0), f"lengths in {units}"))
    # Whole to a temporary file beside it, moved into place when complete
    # (burmester._io): a write error or Ctrl-C leaves no partial file and
    # an existing one as it was.
    with _io.atomic_path(path) as tmp:
        _WRITERS[path.suffix.lower()](d, tmp, units)
    return path


def _export(path: PathLike, units: Optional[str], drawing: Callable[[], _Drawing]) -> Path:
    """The checked target (``.dxf`` or ``.svg``) and units first, then the
    drawing, written (:func:`_write`)."""
    target = _target(path, (".dxf", ".svg"))
    checked = _units(units)
    return _write(drawing(), target, checked)


def _only(suffix: str, export: Callable[_P, Path]) -> Callable[_P, Path]:
    """``export`` for one suffix: another is an InvalidInputError (``linkage_dxf``
    is :func:`linkage` for ``.dxf`` files); the same arguments."""
    signature = inspect.signature(export)

    @functools.wraps(export)
    def only(*args: _P.args, **kwargs: _P.kwargs) -> Path:
        _target(signature.bind(*args, **kwargs).arguments["path"], (suffix,))
        return export(*args, **kwargs)

    only.__name__ = only.__qualname__ = f"{export.__name__}_{suffix[1:]}"
    only.__doc__ = (f":func:`{export.__name__}` to a ``{suffix}`` file (another suffix is an "
                    "InvalidInputError): the same arguments.")
    return only


# ---------------------------------------------------------------------------
# The public functions


def linkage(
    sfb: SynthesizedFourBar,
    path: PathLike,
    *,
    task: Optional[Task] = None,
    travel_samples: int = 0,
    path_samples: int = DEFAULT_PATH_SAMPLES,
    labels: bool = True,
    units: Optional[str] = DEFAULT_UNITS,
    dimensions: bool = True,
) -> Path:
    """Write a synthesized four-bar to a DXF or SVG file, by the path's suffix.

    Layers (the module's table): ``GROUND``, ``PIVOTS``, ``LINKAGE_k`` at
    each pose k (in its assembly mode; a toggle drawn open), ``POSES``,
    ``COUPLER_CURVE``, ``COUPLER_PATH`` (when the linkage is feasible:
    :attr:`burmester.LinkageFigures.feasible`), ``TRAVEL`` (with
    ``travel_samples``), ``DIMENSIONS`` and ``TEXT``.

    ``DIMENSIONS`` (with ``dimensions``): in DXF, true dimension entities
    (ezdxf, dimension style ``BURMESTER``, the unit after the number): an
    aligned dimension of each link at pose 1 (the ground ``A0 C0``, the
    crank ``A0 A``, the coupler ``A B`` and the sides ``A P``, ``B P`` of its
    triangle to the coupler point, the rocker ``C0 B``), and ordinate
    dimensions of the fixed pivots' x and y from the origin; their
    measurements are the exact lengths and coordinates. In SVG, the same
    as lines and texts (a ``<g>`` each, with ``data-kind`` and
    ``data-measurement``). Every point is the core's:
    :meth:`burmester.FourBar.joints` and :meth:`~burmester.SynthesizedFourBar.pose_at`
    at the input angles, :meth:`burmester.FourBar.coupler_path`,
    :attr:`~burmester.SynthesizedFourBar.travel_stops` and
    :meth:`~burmester.SynthesizedFourBar.travel_angles`.

    Parameters:
        sfb: the four-bar, from :meth:`burmester.Filemon.four_bar` or
            :meth:`burmester.Task.four_bar`.
        path: the file to write, ending in ``.dxf`` or ``.svg`` (replaced if
            it exists; written whole to a temporary file beside it and moved
            into place when complete, so an error leaves no partial file).
        task: the task, to mark the poses it asks for; default: the poses
            the linkage reaches at its input angles.
        travel_samples: also draw the linkage at this many input angles
            evenly spaced over its travel, both ends included (0: none; else
            2 to :data:`MAX_SAMPLES`).
        path_samples: samples of the coupler curve per full turn of the
            input (8 to :data:`MAX_SAMPLES`; default
            :data:`DEFAULT_PATH_SAMPLES`).
        labels: write ``A0``, ``C0`` and the pose numbers (layer ``TEXT``).
        dimensions: dimension the links and the fixed pivots (layer ``DIMENSIONS``).
        units: the unit of the lengths, recorded in the file (the module's *Units*).

    Returns:
        The path written.

    Raises:
        burmester.InvalidInputError: another suffix, a folder that does not
            exist, unknown units or a sample count out of range.
        burmester.AssemblyError: ``travel_samples`` for a linkage that cannot
            be driven through the poses in order (no travel).
        ImportError: ezdxf (for ``.dxf``) is not installed.
    """
    return _export(path, units, lambda: _linkage_drawing(sfb, task, travel_samples, path_samples, labels, dimensions))


def plane(
    filemon: Filemon,
    path: PathLike,
    view: Optional[ViewLike] = None,
    *,
    plane: Plane = "center",
    grid: Optional[Tuple[int, int]] = None,
    method: Method = "conic",
    free: Optional[npt.ArrayLike] = None,
    acceptable: Optional[npt.ArrayLike] = None,
    transmission: Optional[npt.ArrayLike] = None,
    transmission_levels: Sequence[float] = DEFAULT_TRANSMISSION_LEVELS,
    pivots: Optional[Sequence[Point]] = None,
    labels: bool = True,
    units: Optional[str] = DEFAULT_UNITS,
) -> Path:
    """Write the driving crank's center-point or circle-point plane to a DXF
    or SVG file, by the path's suffix.

    **Center-point plane** (``plane="center"``, what
    :func:`burmester.plot.center_plane` draws): ``VIEW``; the branch-free
    driving pivots as polygons with holes (``BRANCH_FREE`` outlines,
    ``BRANCH_FREE_FILL``), contoured from the branch map (accurate to a grid
    cell); with ``acceptable``, the branch-free pivots that meet the limits
    likewise (``ACCEPTABLE``, ``ACCEPTABLE_FILL``); the two transformed
    Filemon conics, every branch clipped to the view, exact
    (:meth:`burmester.Conic.polylines`; ``CONIC_k`` for the line of pose
    k); the poles, the pole triangle and circle; ``C0``
    (``DRIVEN_PIVOT``); the ``pivots`` given (``BEST_PIVOTS``); labels.

    **Circle-point plane** (``plane="circle"``, as
    :func:`burmester.plot.circle_plane`): ``VIEW``; the branch-free double
    wedge between Filemon's lines, clipped to the view (``BRANCH_FREE``);
    the three lines through ``C1`` (``LINE_k``); the image poles and their
    circle; ``C'k`` and ``C1``.

    Parameters:
        filemon: Filemon's construction for the driven dyad (``task.filemon(C0)``).
        path: the file to write, ending in ``.dxf`` or ``.svg``.
        view: a :class:`burmester.Grid` or ``(xmin, xmax, ymin, ymax)``
            (400 samples along the longer side); default: the view of
            :func:`burmester.taskfile.default_view` (center plane) or
            :func:`burmester.taskfile.default_circle_view` (circle plane).
        plane: ``"center"`` or ``"circle"``.
        grid: ``(nx, ny)`` samples of the branch map (center plane).
        method: how :meth:`burmester.Filemon.branch_map` classifies, when
            ``free`` is not given.
        free: a branch map already computed on this view, shape ``(ny, nx)``
            (for example a solution map's ``branch_free``); its shape gives
            the samples when neither a Grid nor ``grid`` is given.
        acceptable: a bool array ``(ny, nx)``: pivots that meet the limits
            (a solution map's ``acceptable``).
        transmission: a float array ``(ny, nx)``: a transmission angle in
            degrees per sample (NaN where undefined), drawn as contours at
            ``transmission_levels`` (``TRANSMISSION``; for example
            ``numpy.degrees(smap.min_transmission_rad)``).
        transmission_levels: the contour levels, degrees.
        pivots: ``(x, y)`` points to mark, numbered from 1 (for example
            ``[p.center for p in smap.best_pivots()]``).
        labels: write the names of the points (layer ``TEXT``).
        units: the unit of the lengths, recorded in the file (the module's *Units*).

    Returns:
        The path written.

    Raises:
        burmester.InvalidInputError: another suffix, a folder that does not
            exist, unknown units, a view that is not ``(xmin, xmax, ymin,
            ymax)`` with ``xmin < xmax`` and ``ymin < ymax``, a ``plane``
            other than ``"center"`` or ``"circle"``, or arrays of another
            shape than the grid's.
        ImportError: ezdxf (for ``.dxf``) or contourpy is not installed.
    """
    over = _Overlays(acceptable, transmission, transmission_levels, pivots)
    return _export(path, units, lambda: _plane_drawing(filemon, view, plane, grid, method, free, over, labels))


def burmester_plane(
    task: Task,
    path: PathLike,
    view: Optional[ViewLike] = None,
    *,
    driven: Optional[Point] = None,
    plane: Literal["center", "circle"] = "center",
    labels: bool = True,
    units: Optional[str] = DEFAULT_UNITS,
) -> Path:
    """Write the center-point plane of four or five poses (or the
    circle-point plane of four) to a DXF or SVG file, by the path's suffix
    (what :func:`burmester.plot.burmester_plane` and
    :func:`burmester.plot.circle_curve_plane` draw).

    **Four poses**: the center-point curve, every component in view, in
    pieces by the crank's order class (:meth:`burmester.Task.order_arcs`;
    layers ``CURVE_CCW``, ``CURVE_CW``, ``CURVE_ORDER_DEFECT``), the points
    ``Q_jk`` (``COINCIDENCE_POINTS``) and, with ``driven``, the driving
    pivots branch-free with it (:meth:`burmester.Task.branch_free_arcs`,
    ``BRANCH_FREE_ARCS``) and ``C0`` (``DRIVEN_PIVOT``). **Five poses**: the
    center-point curves of poses 1-4 and 1-2-3-5 (``CURVE_1234``,
    ``CURVE_1235``) and the Burmester points (``BURMESTER_POINTS``). Both:
    ``VIEW``, the finite poles (``POLES``), the poses (``POSES``), labels.
    **Four poses, ``plane="circle"``** (the coupler frame at pose 1): the
    circle-point curve in the same layers by order, the circle points
    ``Q'jk`` of the ``Q_jk`` (``COINCIDENCE_POINTS``; ``Q'1k`` is the pole
    ``P1k``), the poses and, with ``driven``, the circle points of the
    branch-free driving dyads (``BRANCH_FREE_ARCS``), Filemon's lines through
    ``C1`` and ``C'k`` (``LINE_1`` to ``LINE_4``), ``C'k``
    (``FIXED_PIVOT_IMAGES``) and ``C1`` (``DRIVEN_CIRCLE_POINT``). The curves
    are exact (the core's polylines, vertices on the curve).

    Parameters:
        task: a :class:`burmester.Task` of four or five poses.
        path: the file to write, ending in ``.dxf`` or ``.svg``.
        view: ``(xmin, xmax, ymin, ymax)`` or a :class:`burmester.Grid`;
            default: :func:`burmester.taskfile.default_curve_view`.
        driven: four poses: the driven dyad's center point ``C0``, on the curve.
        plane: ``"center"`` or, for four poses, ``"circle"``.
        labels: write the names of the points (layer ``TEXT``).
        units: the unit of the lengths, recorded in the file (the module's *Units*).

    Returns:
        The path written.

    Raises:
        burmester.InvalidInputError: a task of three poses (``cause ==
            "needs_poses"``; export it with :func:`plane`), the circle plane of
            five poses (``"needs_poses"``), another plane, another suffix, a
            folder that does not exist, unknown units or a view that is not a view.
    """
    return _export(path, units, lambda: _curve_drawing(task, view, driven, labels, plane))


# ---------------------------------------------------------------------------
# The six-bar: a linkage driven from a motor by an added dyad

LAYERS.update({
    "CRANK_CIRCLE": Layer(30, "#fdae6b", "circle of the motor's crank joint D"),
    "ATTACHMENT_ARC": Layer(30, "#fd8d3c", "E over a full crank turn (the swing)"),
    "TURN": Layer(254, "#cccccc", "the six-bar sampled over a full crank turn"),
    **{f"DRIVE_{k}": Layer(30, "#e6550d", f"the drive (crank D0 D, coupler D E) at pose {k}")
       for k in _POSE_COLORS},
})


def _sixbar_links(d: _Drawing, six: burmester.SixBar, phi: float, layers: Tuple[str, str], what: str,
                  joints: bool) -> None:
    """The drive ``D0 D E``, the ternary input link ``A0 A E``, the coupler
    triangle ``A C P`` and the rocker ``C C0`` at crank angle ``phi`` (the
    core's joints)."""
    d0, dj, e, a0, a, c, c0, p = six.joints(phi)
    drive, motion = layers
    d.polyline(drive, [d0, dj], f"crank D0 D, {what}")
    d.polyline(drive, [dj, e], f"drive coupler D E, {what}")
    d.polyline(motion, [a0, a, e], f"input link A0 A E, {what}", closed=True)
    d.polyline(motion, [a, c, p], f"coupler A C P, {what}", closed=True)
    d.polyline(motion, [c, c0], f"rocker C C0, {what}")
    if joints:
        for q, name in ((dj, "D"), (e, "E"), (a, "A"), (c, "C")):
            d.marker(motion if name in ("A", "C") else drive, q, f"moving joint {name}, {what}")


def _sixbar_drawing(drive: burmester.Drive, turn_samples: int, path_samples: int, labels: bool) -> _Drawing:
    turn_samples = _samples("turn_samples", turn_samples, 0)
    if turn_samples == 1:
        raise burmester.InvalidInputError("turn_samples must be 0 (none) or at least 2, got 1")
    path_samples = _samples("path_samples", path_samples, 8)
    six = drive.sixbar
    sc = _scene.sixbar_scene(six, drive)
    d0, a0, c0 = sc.d0, sc.a0, sc.c0
    d = _Drawing(f"six-bar: motor at D0 {d0}, A0 {a0}, C0 {c0}, time ratio {drive.time_ratio:.3f}")
    d.polyline("GROUND", [d0, a0], "drive ground D0 A0")
    d.polyline("GROUND", [a0, c0], "ground A0 C0")
    for q, name in ((d0, "D0"), (a0, "A0"), (c0, "C0")):
        d.marker("PIVOTS", q, f"fixed pivot {name}", name if labels else None)
    d.circles.append(_Circle("CRANK_CIRCLE", (float(d0[0]), float(d0[1])), sc.crank_radius, "crank circle"))
    ts = np.asarray(drive.turn_angles(path_samples), dtype=float)
    ts = np.append(ts, ts[0])
    x, y, ok = six.coupler_path(ts)
    for run in _runs(x, y, ok):
        d.polyline("COUPLER_PATH", run, "coupler point over a full crank turn", closed=bool(ok.all()))
    es = np.array([six.joints(float(t))[2] for t in ts])
    d.polyline("ATTACHMENT_ARC", es, "E over a full crank turn")
    if turn_samples:
        for i, t in enumerate(drive.turn_angles(turn_samples), start=1):
            _sixbar_links(d, six, t, ("TURN", "TURN"), f"crank sample {i} of {turn_samples}", False)
    for k, phi in enumerate(sc.pose_angles, start=1):
        _sixbar_links(d, six, phi, (f"DRIVE_{k}", f"LINKAGE_{k}"), f"pose {k}", True)
    _poses(d, sc.poses, sc.flag, labels)
    return d


def sixbar(
    drive: burmester.Drive,
    path: PathLike,
    *,
    turn_samples: int = 0,
    path_samples: int = DEFAULT_PATH_SAMPLES,
    labels: bool = True,
    units: str = DEFAULT_UNITS,
) -> Path:
    """Write a motor-driven six-bar (a :class:`burmester.Drive`) to a DXF
    or SVG file, by the path's suffix, written beside it and moved into
    place when complete.

    Layers: ``GROUND`` (``D0 A0`` and ``A0 C0``), ``PIVOTS`` (``D0``, ``A0``,
    ``C0``), ``CRANK_CIRCLE``, ``DRIVE_k`` (crank ``D0 D`` and drive coupler
    ``D E`` at pose k) and ``LINKAGE_k`` (the input link ``A0 A E``, the
    coupler triangle ``A C P`` and the rocker ``C C0`` at pose k),
    ``COUPLER_PATH`` and ``ATTACHMENT_ARC`` (the coupler point and ``E`` over
    a full crank turn), ``TURN`` (with ``turn_samples``), ``POSES`` and
    ``TEXT``. Every point is the core's (:meth:`burmester.SixBar.joints`,
    :meth:`burmester.SixBar.coupler_path`).

    Parameters:
        drive: the drive.
        path: the file, ending in ``.dxf`` or ``.svg`` (replaced if it exists).
        turn_samples: also draw the six-bar at this many crank angles over a
            full turn (0: none; else 2 to :data:`MAX_SAMPLES`).
        path_samples: samples of the paths per crank turn (8 to
            :data:`MAX_SAMPLES`).
        labels: write the pivots' names and the pose numbers.
        units: the unit recorded (:data:`UNITS`).

    Returns:
        The path written.

    Raises:
        burmester.InvalidInputError: another suffix, a folder that does not
            exist, unknown units or a sample count out of range.
        ImportError: ezdxf (for ``.dxf``) is not installed.
    """
    if not isinstance(drive, burmester.Drive):
        raise TypeError(f"expected a burmester.Drive, got {type(drive).__name__}")
    return _export(path, units, lambda: _sixbar_drawing(drive, turn_samples, path_samples, labels))


__all__ += ["sixbar", "sixbar_dxf", "sixbar_svg"]

# Each drawing for one suffix: the same arguments, another suffix an InvalidInputError.
linkage_dxf, linkage_svg = _only(".dxf", linkage), _only(".svg", linkage)
plane_dxf, plane_svg = _only(".dxf", plane), _only(".svg", plane)
burmester_plane_dxf, burmester_plane_svg = _only(".dxf", burmester_plane), _only(".svg", burmester_plane)
sixbar_dxf, sixbar_svg = _only(".dxf", sixbar), _only(".svg", sixbar)


# ---------------------------------------------------------------------------
# Slider linkages and the linear actuator (issue 27)

LAYERS.update({
    "GUIDE": Layer(8, "#4d4d4d", "the slider's guide: a straight line fixed to the ground"),
    "SLIDER": Layer(9, "#969696", "the slider block on its guide, at each pose"),
    "ACTUATOR_PATH": Layer(30, "#d94801", "the actuator's moving point Q over the travel"),
    "ACTUATOR_AXIS": Layer(30, "#d94801", "the actuator's axis, ground pivot G to moving point Q, at each pose"),
    "ACTUATOR_BODY": Layer(250, "#595959", "the actuator's body (cylinder) from G, at each pose"),
    "ACTUATOR_ROD": Layer(252, "#bdbdbd", "the actuator's rod to Q, at each pose"),
})


def _crank_coupler(d: _Drawing, layer: str, s: Any, joint: Sequence[float], name: str, p: Optional[Point],
                   what: str) -> None:
    """Crank ``A0 A``, the coupler from ``A`` to its other joint ``joint``
    (called ``name``; with a coupler point ``p``: the plate ``A joint P``)
    and the moving pivot ``A``, on ``layer``, of the position ``s`` of a
    crank-driven linkage."""
    d.polyline(layer, [s.pivot, s.crank_joint], f"crank A0 A, {what}")
    if p is None:
        d.polyline(layer, [s.crank_joint, joint], f"coupler A {name}, {what}")
    else:
        d.polyline(layer, [s.crank_joint, joint, p], f"coupler A {name} P, {what}", closed=True)
    d.marker(layer, s.crank_joint, f"moving pivot A, {what}")


def _slider_links(d: _Drawing, layer: str, s: _scene.SliderScene, p: Optional[Point], what: str) -> None:
    """Crank ``A0 A``, the coupler ``A B`` (with a coupler point ``p``: the
    plate ``A B P``), the joints ``A`` and ``B`` (layer ``layer``) and the
    slider block (``SLIDER``) of a slider-crank position (the core's joints)."""
    _crank_coupler(d, layer, s, s.slider_joint, "B", p, what)
    d.marker(layer, s.slider_joint, f"slider pin B, {what}")
    d.polyline("SLIDER", s.block, f"slider block, {what}", closed=True)


def _aligned(d: _Drawing, name: str, p1: Sequence[float], p2: Sequence[float], offset: float) -> None:
    """An aligned dimension of ``p1 p2`` (none when they coincide), measured
    left to right so that its text reads upright, ``offset`` text heights to
    the left of ``p1 -> p2`` as given."""
    dx, dy = p2[0] - p1[0], p2[1] - p1[1]
    if dx == 0.0 and dy == 0.0:
        return
    if dx < 0.0 or (dx == 0.0 and dy < 0.0):
        p1, p2, offset = p2, p1, -offset
    d.dimensions.append(_Dimension("aligned", (float(p1[0]), float(p1[1])), (float(p2[0]), float(p2[1])),
                                   offset, name))


def _ordinates(d: _Drawing, name: str, point: Sequence[float]) -> None:
    """Ordinate dimensions of a fixed pivot's x and y from the origin."""
    at = (float(point[0]), float(point[1]))
    d.dimensions.append(_Dimension("x", at, at, 0.0, f"fixed pivot {name}: x from the origin"))
    d.dimensions.append(_Dimension("y", at, at, 0.0, f"fixed pivot {name}: y from the origin"))


def _crank_samples(travel_samples: int, path_samples: int) -> Tuple[int, int]:
    """``(travel_samples, path_samples)`` of a crank-driven linkage's
    drawing, checked: 0 or 2 to :data:`MAX_SAMPLES`, and 8 to it."""
    travel_samples = _samples("travel_samples", travel_samples, 0)
    if travel_samples == 1:
        raise burmester.InvalidInputError("travel_samples must be 0 (none) or at least 2, got 1")
    return travel_samples, _samples("path_samples", path_samples, 8)


def _crank_parts(obj: Any, synthesized: bool, at_poses: Callable[[Any], Any], at_angle: Callable[[Any, float, Mode], Any],
                 angle: Callable[[Any, Optional[float]], float], theta2: Optional[float], mode: Mode, what: str,
                 travel_samples: int) -> Tuple[Any, Any, Any, Optional[Point], List[Tuple[str, Any, Optional[Point], str]]]:
    """``(linkage, scene at the poses or None, scene at pose 1, coupler
    point at pose 1 or None, at)`` of a crank-driven linkage ``obj`` (the
    kind's scene functions: ``at_poses(obj)``, ``at_angle(linkage, t,
    mode)``, ``angle(linkage, theta2)``); ``at`` holds ``(layer, scene,
    coupler point, what)`` of each position drawn. AssemblyError for
    ``travel_samples`` of a synthesized one without a travel (``what``
    names the kind)."""
    if not synthesized:
        t = angle(obj, theta2)
        pose1 = at_angle(obj, t, mode)
        return obj, None, pose1, None, [("LINKAGE_1", pose1, None, f"crank angle {math.degrees(t):.2f} deg ({mode})")]
    if travel_samples and obj.travel is None:
        raise burmester.AssemblyError(
            f"the {what} cannot be driven from pose 1 through the poses in order in one mode (a branch, "
            "order or circuit defect), so it has no travel to sample: draw it without travel samples "
            "(travel_samples=0)"
        )
    scene = at_poses(obj)
    at = [(f"LINKAGE_{k}", x.scene, x.p, f"pose {k} ({x.mode or 'toggle'})")
          for k, x in enumerate(scene.at_poses, start=1)]
    return obj.linkage, scene, scene.at_poses[0].scene, scene.at_poses[0].p, at


def _crank_paths(d: _Drawing, obj: Any, mode: Mode, path_samples: int, travel_samples: int,
                 chain: Callable[[float], Sequence[Point]]) -> None:
    """A synthesized crank-driven linkage's coupler path over the travel,
    pose k to k + 1 (``COUPLER_PATH``, ``path_samples`` a crank turn), and
    ``chain(theta2)`` at ``travel_samples`` crank angles over it (``TRAVEL``)."""
    stops = obj.travel_stops
    if stops is None:
        return
    for k, (a, b) in enumerate(zip(stops[:-1], stops[1:]), start=1):
        count = max(2, math.ceil(path_samples * abs(b - a) / (2.0 * math.pi)))
        x, y, ok = obj.linkage.coupler_path(obj.coupler_point, np.linspace(a, b, count + 1), mode)
        for run in _runs(x, y, ok):
            d.polyline("COUPLER_PATH", run, f"coupler path, pose {k} to pose {k + 1}")
    for i, t in enumerate(obj.travel_angles(travel_samples).tolist() if travel_samples else [], start=1):
        d.polyline("TRAVEL", chain(t), f"crank and coupler, travel sample {i} of {travel_samples}")


def _crank_body(title: str, obj: Any, scene: Any, pose1: Any, at: Sequence[Tuple[str, Any, Optional[Point], str]],
                links: Callable[[_Drawing, str, Any, Optional[Point], str], None], at_angle: Callable[[Any, float, Mode], Any],
                mode: Mode, samples: Tuple[int, int], labels: bool, dimensions: bool) -> _Drawing:
    """The drawing of a crank-driven linkage, what its kind shares with the
    other's: the crank pivot ``A0``, for a synthesized one (``scene``, its
    scene at the poses, not None) the coupler path and the travel
    (:func:`_crank_paths`; ``samples``: travel and path samples), the
    linkage at each entry of ``at`` (``links``), the poses and, with
    ``dimensions``, the crank at pose 1 (``pose1``); the kind adds the rest."""
    d = _Drawing(title)
    d.marker("PIVOTS", pose1.pivot, "crank pivot A0", "A0" if labels else None)
    if scene is not None:
        _crank_paths(d, obj, scene.mode, samples[1], samples[0],
                     lambda t: _scene.crank_chain(at_angle(obj.linkage, t, scene.mode)))
    for layer, s, p, what in at:
        links(d, layer, s, p, what)
    if scene is not None:
        _poses(d, scene.poses, scene.flag, labels)
    if dimensions:
        _aligned(d, "crank A0 A, pose 1", pose1.pivot, pose1.crank_joint, 2.5)
    return d


def _slider_drawing(obj: Union[burmester.SliderCrank, burmester.SynthesizedSliderCrank], theta2: Optional[float],
                    mode: Mode, travel_samples: int, path_samples: int, labels: bool, dimensions: bool) -> _Drawing:
    travel_samples, path_samples = _crank_samples(travel_samples, path_samples)
    sc, scene, guide_scene, pose1_p, at = _crank_parts(
        obj, isinstance(obj, burmester.SynthesizedSliderCrank), _scene.synthesized_slider_scene, _scene.slider_scene,
        _scene.slider_crank_angle, theta2, mode, "slider-crank", travel_samples)
    if scene is not None:
        title = f"slider-crank at {len(at)} poses: crank {sc.crank:g}, coupler {sc.coupler:g}, A0 {sc.pivot}"
    else:
        title = f"slider-crank: crank {sc.crank:g}, coupler {sc.coupler:g}, offset {sc.offset:g}, A0 {sc.pivot}"
    d = _crank_body(title, obj, scene, guide_scene, at, _slider_links, _scene.slider_scene, mode,
                    (travel_samples, path_samples), labels, dimensions)
    d.polyline("GUIDE", guide_scene.guide, "guide")
    if dimensions:
        s = guide_scene
        _aligned(d, "coupler A B, pose 1", s.crank_joint, s.slider_joint, 2.5)
        if pose1_p is not None:
            _aligned(d, "coupler A P, pose 1", s.crank_joint, pose1_p, -2.5)
            _aligned(d, "coupler B P, pose 1", s.slider_joint, pose1_p, -2.5)
        _aligned(d, "offset: A0 to the guide", sc.pivot, sc.foot, 2.5)
        _ordinates(d, "A0", sc.pivot)
    return d


def slider_crank(
    obj: Union[burmester.SliderCrank, burmester.SynthesizedSliderCrank, burmester.InvertedSliderCrank,
               burmester.SynthesizedInvertedSliderCrank],
    path: PathLike,
    theta2: Optional[float] = None,
    mode: Mode = "open",
    *,
    travel_samples: int = 0,
    path_samples: int = DEFAULT_PATH_SAMPLES,
    labels: bool = True,
    dimensions: bool = True,
    units: Optional[str] = DEFAULT_UNITS,
) -> Path:
    """Write a slider-crank to a DXF or SVG file, by the path's suffix
    (what :func:`burmester.plot.slider_crank` draws), written beside it and
    moved into place when complete.

    Layers: ``GUIDE`` (the guide, over the slider's limit positions with a
    margin: :func:`burmester._scene.slider_scene`), ``PIVOTS`` (``A0``),
    ``LINKAGE_k`` (the crank ``A0 A``, the coupler ``A B``, or the plate
    ``A B P`` to the task's coupler point, and the joints ``A`` and ``B`` at
    pose k; a :class:`burmester.SliderCrank` alone: ``LINKAGE_1`` at
    ``theta2``), ``SLIDER`` (the slider block around ``B``, each pose),
    ``POSES``, ``COUPLER_PATH`` (the coupler point over the travel, pose k
    to k + 1), ``TRAVEL`` (with ``travel_samples``), ``DIMENSIONS`` (at pose
    1: the crank, the coupler and its plate's sides, the offset from ``A0``
    to the guide's foot :attr:`burmester.SliderCrank.foot`; ``A0``'s
    ordinates) and ``TEXT``. Every point is the core's
    (:meth:`burmester.SliderCrank.joints`,
    :meth:`~burmester.SliderCrank.coupler_path`,
    :meth:`burmester.SynthesizedSliderCrank.pose_at`).

    Parameters:
        obj: a :class:`burmester.SynthesizedSliderCrank` (drawn at its
            poses; ``theta2`` and ``mode`` unused) or a
            :class:`burmester.SliderCrank` (drawn at ``theta2``, default as
            :func:`burmester.plot.slider_crank`, in ``mode``); an inverted
            one is drawn as :func:`inverted_slider_crank` says.
        path: the file, ending in ``.dxf`` or ``.svg`` (replaced if it exists).
        travel_samples: a synthesized one: also draw crank and coupler at
            this many crank angles over the travel (0: none; else 2 to
            :data:`MAX_SAMPLES`).
        path_samples: samples of the coupler path per crank turn (8 to
            :data:`MAX_SAMPLES`).
        labels: write ``A0`` and the pose numbers.
        dimensions: dimension the links, the offset and ``A0``.
        units: the unit recorded (the module's *Units*).

    Returns:
        The path written.

    Raises:
        burmester.InvalidInputError: another suffix, a folder that does not
            exist, unknown units or a sample count out of range.
        burmester.AssemblyError: the loop does not close at ``theta2``, or
            ``travel_samples`` for a linkage without a travel.
        ImportError: ezdxf (for ``.dxf``) is not installed.
    """
    drawing = _CRANK_DRAWINGS.get(type(obj))
    if drawing is None:
        raise TypeError("expected a burmester.SliderCrank or SynthesizedSliderCrank (or an inverted one), got "
                        f"{type(obj).__name__}")
    return _export(path, units, lambda: drawing(obj, theta2, mode, travel_samples, path_samples, labels,
                                                dimensions))


def _actuator_drawing(a: burmester.Actuator, width: Optional[float], travel_samples: int, path_samples: int,
                      labels: bool, dimensions: bool) -> _Drawing:
    sfb = a.linkage
    d = _linkage_drawing(sfb, None, travel_samples, path_samples, labels, dimensions)
    scene = _scene.actuator_scene(a, width)
    d.title = (f"four-bar driven by a linear actuator on the {a.link}: G {a.ground}, closed {a.min_length:g}, "
               f"open {a.max_length:g}, stroke {a.stroke:g}")
    d.marker("PIVOTS", a.ground, "actuator ground pivot G", "G" if labels else None)
    _, xq, yq, _ = a.travel(path_samples)
    d.polyline("ACTUATOR_PATH", np.column_stack([xq, yq]), "actuator point Q over the travel")
    for k, at in enumerate(scene.at_poses, start=1):
        what = f"pose {k}, length {at.length:g}"
        d.polyline("ACTUATOR_AXIS", [a.ground, at.q], f"actuator axis G Q, {what}")
        d.polyline("ACTUATOR_BODY", at.body[:-1], f"actuator body, {what}", closed=True)
        d.polyline("ACTUATOR_ROD", at.rod[:-1], f"actuator rod, {what}", closed=True)
        d.marker("ACTUATOR_AXIS", at.q, f"actuator point Q, {what}")
        if a.link == "coupler":  # the bracket that carries Q on the coupler
            p = at.position
            d.polyline(f"LINKAGE_{k}", [p.a, at.q, p.b], f"bracket A Q B on the coupler, pose {k}")
    if dimensions:
        last = len(scene.at_poses)
        _aligned(d, "actuator G Q at pose 1 (pin to pin)", a.ground, scene.at_poses[0].q, -2.5)
        if last > 1:
            _aligned(d, f"actuator G Q at pose {last} (pin to pin)", a.ground, scene.at_poses[-1].q, 2.5)
        _ordinates(d, "G", a.ground)
    return d


def actuator(
    a: burmester.Actuator,
    path: PathLike,
    *,
    units: Optional[str] = DEFAULT_UNITS,
    width: Optional[float] = None,
    labels: bool = True,
    dimensions: bool = True,
    travel_samples: int = 0,
    path_samples: int = DEFAULT_PATH_SAMPLES,
) -> Path:
    """Write a four-bar driven by a linear actuator (a
    :class:`burmester.Actuator`) to a DXF or SVG file, by the path's
    suffix, written beside it and moved into place when complete.

    The four-bar's layers as :func:`linkage` draws them (at the poses it
    reaches), and: ``PIVOTS`` also holds the actuator's ground pivot ``G``;
    ``ACTUATOR_AXIS`` the line ``G Q`` at each pose (its length the
    actuator's pin-to-pin length there, :attr:`burmester.Actuator.pose_lengths`)
    and ``Q``; ``ACTUATOR_BODY`` and ``ACTUATOR_ROD`` the cylinder at each
    pose (closed outlines, :func:`burmester._scene.cylinder`: the body
    0.85 of the closed length from ``G``, the rod to ``Q``);
    ``ACTUATOR_PATH``, ``Q`` over the travel (:meth:`burmester.Actuator.travel`);
    with ``link == "coupler"`` the bracket ``A Q B`` in ``LINKAGE_k``;
    ``DIMENSIONS`` adds the pin-to-pin lengths at the first and last pose
    and ``G``'s ordinates.

    Parameters:
        a: the actuator.
        path: the file, ending in ``.dxf`` or ``.svg`` (replaced if it exists).
        width: the cylinder's width (default 0.06 of its closed length).
        travel_samples, path_samples, labels, dimensions, units: as
            :func:`linkage` (``path_samples``, 8 to :data:`MAX_SAMPLES`,
            also samples ``Q``'s path over the travel).

    Returns:
        The path written.

    Raises:
        burmester.InvalidInputError: another suffix, a folder that does not
            exist, unknown units or a sample count out of range.
        burmester.AssemblyError: ``travel_samples`` for a four-bar without a travel.
        ImportError: ezdxf (for ``.dxf``) is not installed.
    """
    if not isinstance(a, burmester.Actuator):
        raise TypeError(f"expected a burmester.Actuator, got {type(a).__name__}")
    return _export(path, units, lambda: _actuator_drawing(a, width, travel_samples, path_samples, labels,
                                                          dimensions))


__all__ += ["actuator", "actuator_dxf", "actuator_svg", "slider_crank", "slider_crank_dxf", "slider_crank_svg"]

slider_crank_dxf, slider_crank_svg = _only(".dxf", slider_crank), _only(".svg", slider_crank)
actuator_dxf, actuator_svg = _only(".dxf", actuator), _only(".svg", actuator)


# ---------------------------------------------------------------------------
# The inverted slider-crank (issue 27): a crank whose coupler's slot slides
# through a block pivoted on the ground at the swivel.

LAYERS.update({
    "SLOT": Layer(8, "#4d4d4d", "the slotted coupler's slot (the body line the block slides on), at each pose"),
    "SWIVEL_BLOCK": Layer(9, "#969696", "the block turning on the swivel S, along the slot, at each pose"),
})


def _inverted_links(d: _Drawing, layer: str, s: _scene.InvertedScene, p: Optional[Point], what: str) -> None:
    """Crank ``A0 A``, the coupler from the pin to the slot ``A F`` (with a
    coupler point ``p``: the plate ``A F P``), the joint ``A`` (layer
    ``layer``), the slot (``SLOT``) and the block on the swivel
    (``SWIVEL_BLOCK``) of an inverted slider-crank position (the core's
    joints)."""
    _crank_coupler(d, layer, s, s.foot, "F", p, what)
    d.polyline("SLOT", s.slot, f"slot through the swivel, {what}")
    d.polyline("SWIVEL_BLOCK", s.block, f"block on the swivel, {what}", closed=True)


def _slot_along(q: burmester.InvertedSliderCrank, ts: Array, mode: Mode) -> Array:
    """The slot position ``<S - A, u3>`` at the crank angles ``ts`` (the
    core's coupler path of the pin ``(0, 0)`` and of ``(1, 0)``, one along
    the slot); NaN where the loop does not close."""
    ax, ay, _ = q.coupler_path((0.0, 0.0), ts, mode)
    bx, by, _ = q.coupler_path((1.0, 0.0), ts, mode)
    sx, sy = q.swivel
    return (sx - ax) * (bx - ax) + (sy - ay) * (by - ay)


def _inverted_drawing(obj: Union[burmester.InvertedSliderCrank, burmester.SynthesizedInvertedSliderCrank],
                      theta2: Optional[float], mode: Mode, travel_samples: int, path_samples: int, labels: bool,
                      dimensions: bool) -> _Drawing:
    travel_samples, path_samples = _crank_samples(travel_samples, path_samples)
    synthesized = isinstance(obj, burmester.SynthesizedInvertedSliderCrank)
    stroke: Optional[Tuple[float, float]] = None  # the block's run along the slot at pose 1: from, length
    q, scene, pose1, pose1_p, at = _crank_parts(
        obj, synthesized, _scene.synthesized_inverted_scene, _scene.inverted_scene, _scene.inverted_crank_angle,
        theta2, mode, "inverted slider-crank", travel_samples)
    title = (f"inverted slider-crank{f' at {len(at)} poses' if synthesized else ''}: crank {q.crank:g}, ground "
             f"{q.ground:g}, offset {q.offset:g}, A0 {q.pivot}, S {q.swivel}")
    if not isinstance(obj, burmester.SynthesizedInvertedSliderCrank):
        (lo, hi) = q.slot_limits(mode)
        stroke = (lo[1], hi[1] - lo[1])
    elif obj.stroke_used is not None and obj.travel is not None:
        # Where the block's run starts: the lowest slot position over the travel, sampled.
        count = max(2, math.ceil(path_samples * abs(obj.travel[1]) / (2.0 * math.pi)) + 1)
        slots = _slot_along(q, obj.travel_angles(count), scene.mode)
        stroke = (float(np.nanmin(slots)), obj.stroke_used)
    d = _crank_body(title, obj, scene, pose1, at, _inverted_links, _scene.inverted_scene, mode,
                    (travel_samples, path_samples), labels, dimensions)
    d.marker("PIVOTS", q.swivel, "swivel S (the block's ground pivot)", "S" if labels else None)
    if dimensions:
        s = pose1
        _aligned(d, "ground A0 S", q.pivot, q.swivel, -2.5)
        _aligned(d, "offset: the crank pin A to the slot, pose 1", s.crank_joint, s.foot, 2.5)
        if pose1_p is not None:
            _aligned(d, "coupler A P, pose 1", s.crank_joint, pose1_p, -2.5)
        if stroke is not None:
            (t0, along), (ux, uy) = stroke, s.direction
            start = (s.foot[0] + t0 * ux, s.foot[1] + t0 * uy)
            what = "used over the travel" if synthesized else "over the crank's range"
            _aligned(d, f"stroke: the block's run along the slot {what}, at pose 1", start,
                     (start[0] + along * ux, start[1] + along * uy), -4.0)
        _ordinates(d, "A0", q.pivot)
        _ordinates(d, "S", q.swivel)
    return d


def _for_kinds(kinds: Tuple[type, ...], export: Callable[_P, Path], name: str, doc: str) -> Callable[_P, Path]:
    """``export`` for the objects of ``kinds`` only (another is a
    TypeError), named ``name`` and documented by ``doc``: the same
    arguments."""

    @functools.wraps(export)
    def only(*args: _P.args, **kwargs: _P.kwargs) -> Path:
        obj = args[0] if args else kwargs.get("obj")
        if not isinstance(obj, kinds):
            raise TypeError(f"expected a burmester.{' or '.join(k.__name__ for k in kinds)}, got "
                            f"{type(obj).__name__}")
        return export(*args, **kwargs)

    only.__name__ = only.__qualname__ = name
    only.__doc__ = doc
    return only


#: The drawing of each kind of crank-driven slider linkage (:func:`slider_crank`).
_CRANK_DRAWINGS: Dict[type, Callable[..., _Drawing]] = {
    burmester.SliderCrank: _slider_drawing, burmester.SynthesizedSliderCrank: _slider_drawing,
    burmester.InvertedSliderCrank: _inverted_drawing, burmester.SynthesizedInvertedSliderCrank: _inverted_drawing,
}

inverted_slider_crank = _for_kinds((burmester.InvertedSliderCrank, burmester.SynthesizedInvertedSliderCrank),
                                   slider_crank, "inverted_slider_crank", """Write an inverted slider-crank to a DXF or SVG file, by the path's
    suffix (what :func:`burmester.plot.inverted_slider_crank` draws),
    written beside it and moved into place when complete.

    Layers: ``PIVOTS`` (the crank pivot ``A0`` and the swivel ``S``),
    ``LINKAGE_k`` (the crank ``A0 A``, the coupler from the pin ``A`` to the
    slot's foot ``F``, or the plate ``A F P`` to the task's coupler point,
    and the joint ``A`` at pose k; a :class:`burmester.InvertedSliderCrank`
    alone: ``LINKAGE_1`` at ``theta2``), ``SLOT`` (the slot: the body line
    through ``F`` and ``S``, from beyond the foot to beyond the swivel's
    farthest slot position, each pose: :func:`burmester._scene.inverted_scene`),
    ``SWIVEL_BLOCK`` (the block centred on ``S``, along the slot, each
    pose), ``POSES``, ``COUPLER_PATH`` (the coupler point over the travel,
    pose k to k + 1), ``TRAVEL`` (with ``travel_samples``: the chain ``A0
    A F``), ``DIMENSIONS`` (at pose 1: the crank, the ground ``A0 S``, the
    slot's offset ``A F``, the coupler's ``A P``, and the stroke: the
    block's run along the slot, :attr:`~burmester.SynthesizedInvertedSliderCrank.stroke_used`
    over the travel, from the lowest slot position sampled over it, or for a
    linkage alone :attr:`~burmester.InvertedSliderCrank.stroke` between its
    :meth:`~burmester.InvertedSliderCrank.slot_limits`; ``A0``'s and
    ``S``'s ordinates) and ``TEXT``. Every point is the core's
    (:meth:`burmester.InvertedSliderCrank.joints`, ``solve``,
    ``coupler_path``, :meth:`burmester.SynthesizedInvertedSliderCrank.pose_at`).

    Parameters:
        obj: a :class:`burmester.SynthesizedInvertedSliderCrank` (drawn at
            its poses; ``theta2`` and ``mode`` unused) or a
            :class:`burmester.InvertedSliderCrank` (drawn at ``theta2``,
            default the crank pointing away from the swivel, in ``mode``).
        path: the file, ending in ``.dxf`` or ``.svg`` (replaced if it exists).
        travel_samples: a synthesized one: also draw crank and coupler at
            this many crank angles over the travel (0: none; else 2 to
            :data:`MAX_SAMPLES`).
        path_samples: samples of the coupler path (and of the slot position
            that places the stroke's dimension) per crank turn (8 to
            :data:`MAX_SAMPLES`).
        labels: write ``A0``, ``S`` and the pose numbers.
        dimensions: dimension the links, the offset, the stroke and the pivots.
        units: the unit recorded (the module's *Units*).

    Returns:
        The path written.

    Raises:
        burmester.InvalidInputError: another suffix, a folder that does not
            exist, unknown units, a sample count out of range or an unknown mode.
        burmester.AssemblyError: the loop does not close at ``theta2``, or
            ``travel_samples`` for a linkage without a travel.
        ImportError: ezdxf (for ``.dxf``) is not installed.
""")

__all__ += ["inverted_slider_crank", "inverted_slider_crank_dxf", "inverted_slider_crank_svg"]

inverted_slider_crank_dxf = _only(".dxf", inverted_slider_crank)
inverted_slider_crank_svg = _only(".svg", inverted_slider_crank)
