"""A linear actuator as the input: placing it, in words, and in a picture.

The numbers are the core's (:meth:`burmester.SynthesizedFourBar.actuator_map`,
:class:`burmester.ActuatorMap`, :class:`burmester.Actuator`); this module
picks a view, formats and draws them. The actuator is drawn as a cylinder:
a body from the ground pivot ``G`` and a rod to the moving point ``Q``,
coaxial rectangles whose lengths follow from the stroke (the body holds
the retracted rod).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Dict, List, Optional, Sequence, Tuple

import numpy as np
import numpy.typing as npt

from burmester import _scene
from burmester._burmester import Actuator, ActuatorMap, InvalidInputError, SynthesizedFourBar
from burmester.units import label_axes

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from burmester._burmester import RankBy

Point = Tuple[float, float]
Extent = Tuple[float, float, float, float]

#: The cylinder's proportions (:func:`cylinder`), kept in :mod:`burmester._scene`.
BODY_SHARE = _scene.BODY_SHARE
PISTON_OVERLAP = _scene.PISTON_OVERLAP
#: The cylinder's geometry, computed once for the pictures, the animation and the CAD export.
cylinder = _scene.cylinder


def _linkage_of(obj: Any) -> SynthesizedFourBar:
    """The four-bar of a :class:`burmester.SynthesizedFourBar` or of a
    design (anything with a ``linkage``)."""
    if isinstance(obj, SynthesizedFourBar):
        return obj
    sfb = getattr(obj, "linkage", None)
    if isinstance(sfb, SynthesizedFourBar):
        return sfb
    raise TypeError(f"expected a SynthesizedFourBar or a design with a linkage, got {type(obj).__name__}")


def default_view(sfb: SynthesizedFourBar, reach: float = 1.0) -> Extent:
    """A square view about the linkage over its travel: its pivots and the
    moving joints at the poses, widened by ``reach`` times its size on each
    side (where a strut's ground pivot may go)."""
    pts = [sfb.driving[0], sfb.driven[0]]
    mode = sfb.modes[0] or "open"
    for t in sfb.input_angles:
        _, a, b, _ = sfb.fourbar.joints(t, mode)
        x, y, _ = sfb.pose_at(t, mode)
        pts += [a, b, (x, y)]
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    cx, cy = 0.5 * (min(xs) + max(xs)), 0.5 * (min(ys) + max(ys))
    h = 0.5 * max(max(xs) - min(xs), max(ys) - min(ys)) * (1.0 + 2.0 * reach)
    return (cx - h, cx + h, cy - h, cy + h)


def actuator_map(
    linkage: Any,
    view: Optional[Sequence[float]] = None,
    samples: Tuple[int, int] = (200, 200),
    **options: Any,
) -> ActuatorMap:
    """The placement map of an actuator for ``linkage`` (a
    :class:`burmester.SynthesizedFourBar` or a design) over ``view``
    (default :func:`default_view`) on ``samples`` ``(nx, ny)``; ``options``
    as :meth:`burmester.SynthesizedFourBar.actuator_map` (``link``,
    ``point``, ``max_stroke_ratio``, ``actuator_width``, ``min_gap``, the
    limits, ``base_plate``, ``link_width``)."""
    sfb = _linkage_of(linkage)
    v = tuple(view) if view is not None else default_view(sfb)
    return sfb.actuator_map(*v, *samples, **options)


def design_actuator(
    linkage: Any,
    view: Optional[Sequence[float]] = None,
    *,
    samples: Tuple[int, int] = (200, 200),
    rank_by: "RankBy" = "balanced",
    **options: Any,
) -> Actuator:
    """The best actuator for ``linkage`` (a
    :class:`burmester.SynthesizedFourBar`, or the design
    :func:`burmester.design` returns): its placement map over ``view``
    (:func:`actuator_map`) and the best placement by ``rank_by``. Raises
    :class:`burmester.DriveError` (``"no_acceptable_actuator"``-like: its
    message says what to relax) when no sample is acceptable."""
    amap = actuator_map(linkage, view, samples, **options)
    best = amap.best_placements(1, rank_by=rank_by)
    if not best:
        mono = int(np.count_nonzero(amap.monotone))
        raise InvalidInputError(
            f"no acceptable actuator placement in the view ({mono} of {amap.monotone.size} ground "
            f"pivots give a monotone stroke); widen the view, move the point, or relax "
            f"max_stroke_ratio ({amap.max_stroke_ratio:g}), min_transmission_deg "
            f"({amap.limits.min_transmission_deg:g}) or min_gap ({amap.min_gap:g}; "
            f"{clear_count(amap)} of them keep it)"
        )
    return best[0]


def clear_count(amap: ActuatorMap) -> int:
    """How many monotone samples of ``amap`` keep its least gap."""
    with np.errstate(invalid="ignore"):
        ok = amap.monotone & (amap.clearance > 0.0) & (amap.clearance >= amap.min_gap)
    return int(np.count_nonzero(ok))


def actuator_record(a: Actuator) -> Dict[str, Any]:
    """A placement as a JSON-ready dict (angles in degrees)."""
    return {
        "link": a.link,
        "ground": [a.ground[0], a.ground[1]],
        "point": [a.point[0], a.point[1]],
        "pose_lengths": list(a.pose_lengths),
        "monotone": a.monotone,
        "extends": a.extends,
        "turning_points_deg": [math.degrees(t) for t in a.turning_points],
        "closed_length": a.min_length,
        "open_length": a.max_length,
        "stroke": a.stroke,
        "stroke_ratio": a.stroke_ratio,
        "max_stroke_ratio": a.max_stroke_ratio,
        "min_transmission_deg": a.min_transmission_deg,
        "link_ratio": a.link_ratio,
        "size_ratio": a.size_ratio,
        "acceptable": a.acceptable,
        "ranked_by": a.ranked_by,
        "min_clearance": a.min_clearance,
        "clear": a.clear,
        "actuator_width": a.actuator_width,
        "min_gap": a.min_gap,
    }


def actuator_table(a: Actuator, source: Optional[str] = None, units: str = "") -> str:
    """A placement in words: where it goes and what a designer checks."""
    u = f" {units}" if units else ""

    def p(q: Sequence[float]) -> str:
        return f"({q[0] + 0.0:.1f}, {q[1] + 0.0:.1f})"

    sfb = a.linkage
    f = sfb.figures
    lines = [
        f"Linear actuator for {source or 'the linkage'}: a {f.grashof} (A0 {p(sfb.driving[0])}, "
        f"C0 {p(sfb.driven[0])}), its own transmission {f.min_transmission_deg:.1f} deg over the travel",
        f"  ground pivot G {p(a.ground)}, on the {a.link} at Q {p(a.point)} (pose 1)",
        f"  length at the poses: " + ", ".join(f"{s:.1f}{u}" for s in a.pose_lengths)
        + f" ({'extends' if a.extends else 'retracts'} from the first to the last)",
        f"  closed {a.min_length:.1f}{u}, open {a.max_length:.1f}{u}: stroke {a.stroke:.1f}{u}, "
        f"stroke ratio {a.stroke_ratio:.3f} (limit {a.max_stroke_ratio:g})",
    ]
    if a.monotone:
        lines.append(f"  monotone over the travel; force transmission at least {a.min_transmission_deg:.1f} deg "
                     f"(limit {a.limits.min_transmission_deg:g})")
    else:
        lines.append("  NOT monotone: the length turns back at input angle(s) "
                     + ", ".join(f"{math.degrees(t):.1f} deg" for t in a.turning_points))
    lines.append(f"  link ratio {a.link_ratio:.2f}, size {a.size_ratio:.1f}x the task, "
                 f"{'acceptable' if a.acceptable else 'NOT acceptable'} under the limits")
    lines.append(f"  {'clear' if a.clear else 'NOT clear'} over the travel: the strut's least gap to the links "
                 f"(not those carrying Q), obstacles and envelope {a.min_clearance:.1f}{u} "
                 f"(at input angle {math.degrees(a.clearance_angle):.1f} deg; strut {a.actuator_width:g}{u} "
                 f"wide, links {_link_width(a):g}{u}, least gap {a.min_gap:g}{u})")
    return "\n".join(lines)


def _link_width(a: Actuator) -> float:
    """The links' width the placement's clearance was measured with."""
    return float(a.link_width)


def draw_map(amap: ActuatorMap, *, best: int = 3, rank_by: "RankBy" = "balanced",
             transmission_levels: Sequence[float] = (30.0, 45.0, 60.0, 75.0),
             ax: Optional["Axes"] = None, legend: bool = True, units: Optional[str] = None) -> "Axes":
    """Draw an actuator placement map: the ground pivots with a monotone
    stroke (light), those that meet the limits (dark), contours of the
    actuator's minimum force transmission angle (shaded and contoured by
    :func:`burmester.plot.placement_map`, as the drive map is), the moving
    point's path, the linkage's pivots and the best placements as numbered
    stars; the axes say ``units`` (``x [mm]``)."""
    import matplotlib.pyplot as plt

    from burmester import plot

    if ax is None:
        _, ax = plt.subplots(figsize=(8.0, 6.4))
    extent = amap.extent
    mu = np.degrees(np.where(amap.monotone, amap.min_transmission_rad, np.nan))
    handles: List[Any] = plot.placement_map(ax, amap.grid, amap.monotone, amap.acceptable, mu, plot.ACTUATOR_MAP_CMAP,
                                            ("monotone stroke", "meets the limits"), "actuator-map",
                                            transmission_levels)
    gap = max(amap.min_gap, 0.0)
    with np.errstate(invalid="ignore"):
        near = np.where(amap.monotone, amap.clearance, np.nan)
    if np.isfinite(near).any() and np.nanmin(near) < gap < np.nanmax(near):
        xs, ys = amap.grid.cell_centers()
        cs = ax.contour(xs, ys, near, levels=[gap], colors="#00897b", linewidths=1.2, linestyles="--", zorder=4)
        cs.set_gid("clearance")
        from matplotlib.lines import Line2D

        handles.append(Line2D([], [], color="#00897b", linestyle="--",
                              label=f"strut's gap = {gap:g} (min_gap; clear on the far side)"))
    sfb = amap.linkage
    placements = amap.best_placements(best, rank_by=rank_by) if best > 0 else []
    if placements:
        _, xq, yq, _ = placements[0].travel(96)
        (path,) = ax.plot(xq, yq, color="#d94801", linewidth=2.5, zorder=5,
                          label=f"Q's path on the {amap.link}")
        path.set_gid("point-path")
        handles.append(path)
        stars = np.array([a.ground for a in placements])
        (st,) = ax.plot(stars[:, 0], stars[:, 1], "*", markersize=13, color="#ffd700",
                        markeredgecolor="black", zorder=7, label=f"best ground pivots ({rank_by})")
        handles.append(st)
        for k, a in enumerate(placements, start=1):
            ax.annotate(str(k), a.ground, textcoords="offset points", xytext=(6, 6), fontsize=9)
    piv = np.array([sfb.driving[0], sfb.driven[0]])
    (pv,) = ax.plot(piv[:, 0], piv[:, 1], "^", color="0.2", markersize=9, zorder=6,
                    label="four-bar pivots A0, C0")
    handles.append(pv)
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(extent[2], extent[3])
    ax.set_aspect("equal")
    label_axes(ax, units)
    ax.set_title(f"Actuator map: the ground pivot G (stroke ratio at most {amap.max_stroke_ratio:g})")
    if legend:
        ax.legend(handles=handles, loc="lower left", fontsize="x-small")
    return ax


def draw_actuator(a: Actuator, *, ax: Optional["Axes"] = None, legend: bool = True,
                  width: Optional[float] = None, units: Optional[str] = None) -> "Axes":
    """Draw the linkage at its poses with the actuator as a cylinder (body
    and rod) at each: the four-bar's links, the coupler, the actuator's
    ground pivot and moving point (the scene of
    :func:`burmester._scene.actuator_scene`, which the CAD export and the
    animation draw too); the axes say ``units`` (``x [mm]``)."""
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(8.0, 6.4))
    scene = _scene.actuator_scene(a, width)
    colors = ["#2171b5", "#6a51a3", "#cb181d", "#238b45", "#d94801"]
    for k, at in enumerate(scene.at_poses):
        c = colors[k % len(colors)]
        o2, ja, jb, o4, p = at.position
        ax.plot([o2[0], ja[0], jb[0], o4[0]], [o2[1], ja[1], jb[1], o4[1]], "-o", color=c,
                linewidth=2.0, markersize=4, zorder=4, label=f"pose {k + 1}", gid=f"linkage-{k + 1}")
        ax.fill([ja[0], jb[0], p[0]], [ja[1], jb[1], p[1]], color=c, alpha=0.15, zorder=3)
        q = at.q
        if a.link == "coupler":  # the bracket that carries Q on the coupler
            ax.plot([ja[0], q[0], jb[0]], [ja[1], q[1], jb[1]], "--", color=c, linewidth=1.0, zorder=4)
        ax.fill(at.body[:, 0], at.body[:, 1], facecolor="0.35", edgecolor="black", linewidth=0.8,
                zorder=6, alpha=0.9, gid=f"actuator-body-{k + 1}")
        ax.fill(at.rod[:, 0], at.rod[:, 1], facecolor="#bdbdbd", edgecolor="black", linewidth=0.8,
                zorder=5, gid=f"actuator-rod-{k + 1}")
        ax.plot([q[0]], [q[1]], "o", color=c, markersize=5, zorder=7)
    _, xq, yq, _ = a.travel(96)
    ax.plot(xq, yq, ":", color="#d94801", linewidth=1.2, zorder=2, label="Q's path")
    ax.plot([a.ground[0]], [a.ground[1]], "^", color="black", markersize=10, zorder=8,
            label="actuator ground pivot G")
    piv = np.array([scene.linkage.a0, scene.linkage.c0])
    ax.plot(piv[:, 0], piv[:, 1], "^", color="0.2", markersize=9, zorder=8)
    ax.set_aspect("equal")
    ax.autoscale()
    label_axes(ax, units)
    u = f" {units}" if units else ""
    ax.set_title(f"The {a.link} driven by a cylinder: stroke {a.stroke:.0f}{u}, ratio {a.stroke_ratio:.2f}, "
                 f"force transmission \u2265 {a.min_transmission_deg:.0f}\u00b0")
    if legend:
        ax.legend(loc="lower left", fontsize="x-small")
    return ax
