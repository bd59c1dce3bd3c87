"""A motor drive in words and as JSON: what ``burmester drive`` prints.

The numbers are the core's (:class:`burmester.Drive` and its
:class:`burmester.SixBar`); this module only formats them.
"""

from __future__ import annotations

import math
from typing import Any, Dict, List, Optional

import burmester

#: The names of the eight links of :attr:`burmester.SixBar.lengths`, in order.
LINK_NAMES = (
    "drive_ground", "crank", "drive_coupler", "rocker", "input", "coupler", "output", "ground",
)


def _pt(p: Any) -> List[float]:
    return [float(p[0]), float(p[1])]


def _deg(a: float) -> float:
    return math.degrees(a)


def drive_record(drive: burmester.Drive) -> Dict[str, Any]:
    """A drive as a JSON-ready dict (angles in degrees)."""
    six = drive.sixbar
    lengths = dict(zip(LINK_NAMES, six.lengths))
    lengths["attachment_side"] = six.attachment_side
    sw0, sw1 = drive.swing
    return {
        "drive_pivot": _pt(drive.drive_pivot),
        "attachment": _pt(drive.attachment),
        "input_pivot": _pt(drive.linkage.driving[0]),
        "output_pivot": _pt(drive.linkage.driven[0]),
        "lengths": lengths,
        "drive_grashof": six.drive_grashof,
        "drive_mode": six.drive_mode,
        "motion_mode": six.motion_mode,
        "direction": drive.direction,
        "min_transmission_deg": drive.min_transmission_deg,
        "drive_transmission_deg": drive.drive_transmission_deg,
        "motion_transmission_deg": drive.motion_transmission_deg,
        "time_ratio": drive.time_ratio,
        "link_ratio": drive.link_ratio,
        "size_ratio": drive.size_ratio,
        "swing_deg": [_deg(sw0), _deg(sw1)],
        "swing_margin_deg": drive.swing_margin_deg,
        "stroke_deg": _deg(drive.stroke),
        "pose_crank_angles_deg": [_deg(a) for a in drive.pose_crank_angles],
        "acceptable": drive.acceptable,
        "ranked_by": drive.ranked_by,
    }


def linkage_record(sfb: burmester.SynthesizedFourBar) -> Dict[str, Any]:
    """The driven linkage as a JSON-ready dict."""
    f = sfb.figures
    return {
        "driving": [_pt(p) for p in sfb.driving],
        "driven": [_pt(p) for p in sfb.driven],
        "lengths": dict(zip(("ground", "crank", "coupler", "rocker"), f.lengths)),
        "grashof": f.grashof,
        "input_full": f.input_full,
        "direction": f.direction,
        "min_transmission_deg": f.min_transmission_deg,
    }


def drive_table(drive: burmester.Drive, source: Optional[str] = None) -> str:
    """A drive in words: the linkage, the added dyad and what to check."""
    sfb = drive.linkage
    f = sfb.figures
    six = drive.sixbar
    ln = dict(zip(LINK_NAMES, six.lengths))

    def p(q: Any) -> str:
        return f"({q[0] + 0.0:.3f}, {q[1] + 0.0:.3f})"

    travel = sfb.travel
    turns = f"the input turns {abs(math.degrees(travel[1])):.1f} deg from pose 1 to the last" if travel else ""
    if f.input_full:
        turns += " (its input turns fully: a motor could also turn it directly)"
    lines = [
        f"Motor drive for {source or 'the linkage'}: a {f.grashof} (A0 {p(sfb.driving[0])}, "
        f"C0 {p(sfb.driven[0])}); {turns}",
        f"  added dyad: motor crank pivot D0 {p(drive.drive_pivot)}, crank {ln['crank']:.4f}, "
        f"coupler {ln['drive_coupler']:.4f} to E {p(drive.attachment)} on the input link "
        f"(|A0 E| {ln['rocker']:.4f}, |E A| {six.attachment_side:.4f})",
        f"  drive loop: {six.drive_grashof}, {six.drive_mode}; motor turns {drive.direction}, "
        f"working stroke {math.degrees(drive.stroke):.1f} deg of crank, time ratio {drive.time_ratio:.3f}",
        f"  transmission over a full crank turn: drive {drive.drive_transmission_deg:.1f} deg, "
        f"linkage {drive.motion_transmission_deg:.1f} deg (limit {drive.limits.min_transmission_deg:g})",
        f"  six-bar: link ratio {drive.link_ratio:.2f}, size {drive.size_ratio:.1f}x the task, "
        f"{'acceptable' if drive.acceptable else 'NOT acceptable'} under the limits",
        "  crank angle at each pose: "
        + ", ".join(f"{k}: {math.degrees(a) % 360:.1f} deg" for k, a in enumerate(drive.pose_crank_angles, 1)),
    ]
    return "\n".join(lines)
