"""Ranking candidate driving pivots.

:func:`rank_pivots` ranks the driving fixed pivots ``A0`` of the grid with the
solution-space map (:meth:`burmester.Filemon.solution_map`): among the
pivots that are branch-free, carry the coupler through the poses in order on
one circuit, and meet the limits, the best have the largest minimum
transmission angle over the whole travel (ties: the larger margin to the
branch-defect boundary), kept apart from each other.

When no pivot meets the limits, :func:`rank_by_margin` lists the branch-free
grid points farthest from the transformed Filemon curves
(:meth:`burmester.Filemon.margin_map`), with the limits each one misses. The
margin grows away from the curves, so in an unbounded free region those lie
on the edge of the view: choose the view as the space you allow for the pivot.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Tuple

import numpy as np
import numpy.typing as npt

import burmester
from burmester._burmester import Filemon
from burmester.taskfile import Limits, View

Point = Tuple[float, float]


@dataclass(frozen=True)
class Pivot:
    """A candidate driving fixed pivot and the four-bar it makes.

    ``center``: the pivot ``A0``. ``margin``: its signed distance to the
    nearer transformed Filemon curve (first order). ``lengths``: ``(ground,
    crank, coupler, rocker)`` of the four-bar (the crank drives). ``grashof``:
    its Grashof type. ``transmission_deg``: the transmission angle at each
    pose, degrees. ``modes``: the assembly mode at each pose.
    """

    center: Point
    margin: float
    lengths: Tuple[float, float, float, float]
    grashof: str
    link_ratio: float
    transmission_deg: Tuple[float, float, float]
    modes: Tuple[Optional[str], Optional[str], Optional[str]]
    #: The smallest transmission angle over the travel from pose 1 through
    #: pose 2 to pose 3, degrees (None when no input direction carries the
    #: coupler through the poses in order).
    min_transmission_deg: Optional[float] = None
    #: The input rotation that drives the coupler 1 -> 2 -> 3: "ccw", "cw" or "none".
    direction: str = "none"

    def violations(self, limits: Limits) -> List[str]:
        """The limits this pivot's four-bar does not meet, in words (empty when it meets all)."""
        out = []
        if self.direction == "none":
            out.append("no input direction passes the poses in order")
        worst = (
            self.min_transmission_deg
            if self.min_transmission_deg is not None
            else min(self.transmission_deg)
        )
        if not worst >= limits.min_transmission_deg:
            out.append(f"transmission {worst:.0f} < {limits.min_transmission_deg:g} deg")
        if self.link_ratio > limits.max_link_ratio:
            out.append(f"link ratio {self.link_ratio:.1f} > {limits.max_link_ratio:g}")
        if limits.require_crank and self.grashof not in ("crank-rocker", "double-crank"):
            out.append("input is not a crank")
        return out

    def as_dict(self, limits: Optional[Limits] = None) -> Dict[str, Any]:
        """A JSON-friendly dict (with ``"violations"`` when ``limits`` is given)."""
        d: Dict[str, Any] = {
            "center": list(self.center),
            "margin": self.margin,
            "ground": self.lengths[0],
            "crank": self.lengths[1],
            "coupler": self.lengths[2],
            "rocker": self.lengths[3],
            "grashof": self.grashof,
            "link_ratio": self.link_ratio,
            "transmission_deg": list(self.transmission_deg),
            "min_transmission_deg": self.min_transmission_deg,
            "direction": self.direction,
            "modes": list(self.modes),
        }
        if limits is not None:
            d["violations"] = self.violations(limits)
        return d


def local_maxima(values: npt.NDArray[Any]) -> npt.NDArray[np.bool_]:
    """True where a grid value is positive and no smaller than its eight neighbours."""
    v = np.asarray(values, dtype=np.float64)
    padded = np.pad(v, 1, constant_values=-np.inf)
    ny, nx = v.shape
    peak = v > 0
    for dj in (-1, 0, 1):
        for di in (-1, 0, 1):
            if dj or di:
                peak &= v >= padded[1 + dj : 1 + dj + ny, 1 + di : 1 + di + nx]
    return peak


def describe(filemon: Filemon, center: Point, margin: float) -> Pivot:
    """The :class:`Pivot` for one driving center point. Raises
    :class:`burmester.BurmesterError` where no four-bar can be built."""
    sfb = filemon.four_bar(center)
    fb = sfb.fourbar
    mus = []
    for theta2, mode in zip(sfb.input_angles, sfb.modes):
        conf = fb.configuration(theta2, mode or "open")
        mus.append(math.degrees(conf.transmission_angle))
    # The figures over the travel, from a one-sample solution-space map.
    x, y = float(center[0]), float(center[1])
    one = filemon.solution_map(x - 0.5, x + 0.5, y - 0.5, y + 0.5, 1, 1,
                               min_transmission_deg=0.0, max_link_ratio=math.inf)
    d = int(one.direction[0, 0])
    mt = float(one.min_transmission[0, 0])
    return Pivot(
        center=(x, y),
        margin=float(margin),
        lengths=fb.lengths,
        grashof=fb.grashof(),
        link_ratio=fb.link_ratio(),
        transmission_deg=(mus[0], mus[1], mus[2]),
        modes=sfb.modes,
        min_transmission_deg=None if math.isnan(mt) else math.degrees(mt),
        direction={1: "ccw", -1: "cw"}.get(d, "none"),
    )


def solution_map(filemon: Filemon, view: View, limits: Limits) -> "burmester.SolutionMap":
    """The solution-space map of ``view`` under ``limits``."""
    return filemon.solution_map(
        *view.extent,
        view.nx,
        view.ny,
        min_transmission_deg=limits.min_transmission_deg,
        max_link_ratio=limits.max_link_ratio,
        input="crank" if limits.require_crank else "any",
    )


def rank_pivots(
    filemon: Filemon,
    view: View,
    limits: Limits,
    top: int = 5,
    *,
    spacing: Optional[float] = None,
    smap: Optional["burmester.SolutionMap"] = None,
) -> List[Pivot]:
    """The ``top`` acceptable driving pivots on the grid of ``view``, best first.

    Acceptable: branch-free, driven through the poses in order on one circuit,
    and within ``limits``. Ranked by the minimum transmission angle over the
    travel, ties by the margin to the branch-defect boundary
    (:meth:`burmester.SolutionMap.best_pivots`), at least ``spacing`` apart
    (default: a tenth of the view's shorter side). Empty when nothing in the
    view is acceptable. ``smap`` is the solution-space map of ``view`` if
    already computed.
    """
    if top < 1:
        return []
    if smap is None:
        smap = solution_map(filemon, view, limits)
    if spacing is None:
        spacing = 0.1 * min(view.xmax - view.xmin, view.ymax - view.ymin)
    out = []
    for p in smap.best_pivots(top, spacing):
        pivot = describe(filemon, p["center"], p["margin"])
        out.append(pivot)
    return out


def rank_by_margin(
    filemon: Filemon,
    view: View,
    top: int = 5,
    *,
    spacing: Optional[float] = None,
    margin: Optional[npt.NDArray[np.float32]] = None,
) -> List[Pivot]:
    """The ``top`` branch-free pivots on the grid of ``view``, best first.

    Candidates are the grid points where the margin map has a local maximum;
    they are taken in order of decreasing margin, skipping any closer than
    ``spacing`` (default: a tenth of the view's shorter side) to one already
    taken, and any whose four-bar cannot be built or is not branch-free.
    ``margin`` is the margin map of ``view`` if already computed.
    """
    if top < 1:
        return []
    if margin is None:
        margin = filemon.margin_map(*view.extent, view.nx, view.ny)
    if spacing is None:
        spacing = 0.1 * min(view.xmax - view.xmin, view.ymax - view.ymin)
    xs, ys = view.cell_centers()
    js, is_ = np.nonzero(local_maxima(margin))
    order = np.argsort(-margin[js, is_], kind="stable")
    chosen: List[Pivot] = []
    for k in order:
        p = (float(xs[is_[k]]), float(ys[js[k]]))
        if any(math.hypot(p[0] - c.center[0], p[1] - c.center[1]) < spacing for c in chosen):
            continue
        try:
            pivot = describe(filemon, p, float(margin[js[k], is_[k]]))
        except burmester.BurmesterError:
            continue
        if None in pivot.modes or len(set(pivot.modes)) != 1:
            continue
        chosen.append(pivot)
        if len(chosen) == top:
            break
    return chosen
