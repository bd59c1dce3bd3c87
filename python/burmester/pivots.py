"""Ranking candidate driving pivots by their distance to the branch-defect boundary.

Until the solution-space map exists, the best driving fixed pivots ``A0`` are
the branch-free grid points farthest from the transformed Filemon curves, by
:meth:`burmester.Filemon.margin_map`. The margin grows away from the curves,
so in an unbounded free region the best points lie on the edge of the view:
choose the view as the space you allow for the pivot.
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

    def violations(self, limits: Limits) -> List[str]:
        """The limits this pivot's four-bar does not meet, in words (empty when it meets all)."""
        out = []
        worst = min(self.transmission_deg)
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
    return Pivot(
        center=(float(center[0]), float(center[1])),
        margin=float(margin),
        lengths=fb.lengths,
        grashof=fb.grashof(),
        link_ratio=fb.link_ratio(),
        transmission_deg=(mus[0], mus[1], mus[2]),
        modes=sfb.modes,
    )


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
