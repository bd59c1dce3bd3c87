"""The text tables and JSON documents the commands print."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Dict, List, Optional, Sequence, Tuple

import burmester
from burmester import pivots as pv
from burmester import taskfile
from burmester._burmester import Pivot
from burmester.cli.base import _fmt_point, _fmt_size, _lengths_in, _limits_text
from burmester.taskfile import TaskSpec, describe_outside, outside_view
from burmester.units import format_length

if TYPE_CHECKING:
    from burmester._burmester import Mode

def table(columns: Sequence[Tuple[str, str]], rows: Sequence[Sequence[str]]) -> str:
    """A text table drawn by rich: ``columns`` are ``(header, justify)``
    with justify ``"left"`` or ``"right"``, ``rows`` the cells as text.
    ASCII only, columns apart by ``|``, a rule under the header, as wide as
    its content (not cut to the terminal: the output is for pipes too),
    without trailing spaces."""
    import io

    from rich import box
    from rich.console import Console
    from rich.table import Table

    t = Table(box=box.ASCII2, show_edge=False, pad_edge=False, highlight=False)
    for header, justify in columns:
        t.add_column(header, justify="right" if justify == "right" else "left", no_wrap=True)
    for row in rows:
        t.add_row(*row)
    buf = io.StringIO()
    Console(file=buf, width=100_000, color_system=None, highlight=False, emoji=False, markup=False,
            force_terminal=False, legacy_windows=False).print(t)
    return "\n".join(line.rstrip() for line in buf.getvalue().splitlines())


# ---------------------------------------------------------------------------
# Each command's table


def pivot_table(spec: TaskSpec, pivots: Sequence[Pivot], ranked_by: str = "balanced") -> str:
    """The text table of ``burmester pivots``: a line naming the ranking,
    the table (:func:`table`), a line saying what the columns mean."""
    head = pv.describe_ranking(ranked_by)
    if ranked_by != "margin":
        head += " (acceptable under the limits)"
    span = spec.task.span
    columns = [("#", "right"), ("A0 (x, y)", "right"), ("size", "right"), ("margin", "right"),
               ("ground", "right"), ("crank", "right"), ("coupler", "right"), ("rocker", "right"),
               ("Grashof type", "left"), ("mu min", "right"), ("mu1", "right"), ("mu2", "right"),
               ("mu3", "right"), ("drive", "left"), (_limits_text(spec), "left")]
    rows = []
    for k, p in enumerate(pivots, start=1):
        f = p.figures
        mus = [f"{m:.0f}" if m is not None else "-" for m in pv.transmission_at_poses_deg(p.linkage)]
        mt = f"{f.min_transmission_deg:.1f}" if f.min_transmission_deg is not None else "-"
        drive = f"{f.direction} {f.modes[0] or ''}".strip()
        bad = pv.linkage_violations(p.linkage, spec.limits, spec.units)
        rows.append([str(k), _fmt_point(p.center), _fmt_size(p.size_ratio), f"{p.margin:.3f}",
                     *(f"{v:.3f}" for v in f.lengths), f.grashof, mt, *mus, drive, "; ".join(bad) or "ok"])
    lines = [
        f"Driving pivots A0 for {spec.source} (task size {format_length(span, spec.units, 3)}: the largest "
        f"distance between two poses{_lengths_in(spec)}), {head}",
        table(columns, rows),
    ]
    if not pivots:
        lines.append("(no branch-free pivot in the view)")
    c0 = spec.filemon().driven_center
    outside = describe_outside(outside_view([("the driven pivot C0", c0)], spec.view.extent), spec.view.extent,
                               spec.units)
    if outside:
        lines.append(f"note: {outside} (the view is where A0 is searched; C0 is the task's)")
    lines.append(
        "size: the total length of the links (the coupler as its triangle with the coupler "
        "point) in task sizes. mu min: smallest transmission angle over the travel 1 -> 2 -> 3; "
        "mu1-3: at the poses (degrees). drive: input rotation and assembly mode. ok: meets the "
        "limits in the header"
    )
    return "\n".join(lines)


def burmester_table(spec: TaskSpec, ranked: Sequence[pv.BurmesterLinkage], ranked_by: str) -> str:
    """The text table of ``burmester pivots`` for five poses: the ranking,
    the Burmester points, the table of their four-bars (:func:`table`),
    what the columns mean."""
    task = spec.task
    points = task.burmester_points()
    extent = spec.view.extent
    lines = [
        f"Four-bars of the {len(points)} Burmester points of {spec.source} (task size "
        f"{format_length(task.span, spec.units, 3)}{_lengths_in(spec)}), {pv.describe_ranking(ranked_by)}, "
        "acceptable ones first",
    ]
    lines += [f"  B{k}: center {_fmt_point(c)}, circle point {_fmt_point(z)}"
              + ("" if taskfile.in_view(c, extent) else " (outside the view)")
              for k, (c, z) in enumerate(points, start=1)]
    columns = [("#", "right"), ("drive", "right"), ("size", "right"), ("ground", "right"),
               ("crank", "right"), ("coupler", "right"), ("rocker", "right"), ("Grashof type", "left"),
               ("mu min", "right"), ("ratio", "right"), ("motion", "left"), (_limits_text(spec), "left")]
    rows = []
    for k, b in enumerate(ranked, start=1):
        f = b.linkage.figures
        mt = f"{f.min_transmission_deg:.1f}" if f.min_transmission_deg is not None else "-"
        motion = f"{f.direction} {f.modes[0] or ''}".strip() if f.branch_free else "branch defect"
        rows.append([str(k), f"B{b.driving + 1} -> B{b.driven + 1}", _fmt_size(b.linkage.size_ratio),
                     *(f"{v:.3f}" for v in f.lengths), f.grashof, mt, f"{f.link_ratio:.1f}", motion,
                     "; ".join(b.violations) or "ok"])
    lines.append(table(columns, rows))
    if not ranked:
        lines.append("(no Burmester four-bar: the task has fewer than two real Burmester points)")
    outside = describe_outside(outside_view([(f"B{k}", c) for k, (c, _) in enumerate(points, start=1)], extent),
                               extent, spec.units)
    if outside:
        lines.append(f"note: {outside}; 'burmester map' draws only the view: widen [view] to see all")
    lines.append("drive: the driving dyad's Burmester point -> the driven one's. size: the total length of the "
                 "links in task sizes. mu min: smallest transmission angle over the travel through the five "
                 "poses. ok: meets the limits in the header")
    return "\n".join(lines)


def _pair_record(p: burmester.Pair) -> Dict[str, Any]:
    """One pair of ``burmester pairs --json``."""
    f = p.figures

    def dyad(d: burmester.CurveDyad) -> Dict[str, Any]:
        return {"center": list(d.center), "circle": list(d.circle), "beta2_deg": math.degrees(d.beta2),
                "branch": d.branch}

    return {
        "index": list(p.index),
        "driving": dyad(p.driving),
        "driven": dyad(p.driven),
        "lengths": dict(zip(("ground", "crank", "coupler", "rocker"), f.lengths)),
        "grashof": f.grashof,
        "direction": f.direction,
        "min_transmission_deg": f.min_transmission_deg,
        "link_ratio": f.link_ratio,
        "size_ratio": p.size_ratio,
        "margin": p.margin,
        "score": p.score,
        "ranked_by": p.ranked_by,
    }


def pair_table(spec: TaskSpec, pairs: Sequence[burmester.Pair], ranked_by: str) -> str:
    """The text table of ``burmester pairs``: the ranking, the table
    (:func:`table`), what the columns mean."""
    columns = [("#", "right"), ("A0 (x, y)", "right"), ("C0 (x, y)", "right"), ("size", "right"),
               ("ground", "right"), ("crank", "right"), ("coupler", "right"), ("rocker", "right"),
               ("Grashof type", "left"), ("mu min", "right"), ("drive", "left")]
    rows = []
    for k, p in enumerate(pairs, start=1):
        f = p.figures
        mt = f"{f.min_transmission_deg:.1f}" if f.min_transmission_deg is not None else "-"
        drive = f"{f.direction} {f.modes[0] or ''}".strip()
        rows.append([str(k), _fmt_point(p.driving.center), _fmt_point(p.driven.center), _fmt_size(p.size_ratio),
                     *(f"{v:.3f}" for v in f.lengths), f.grashof, mt, drive])
    lines = [
        f"Pairs of dyads for {spec.source} (task size {format_length(spec.task.span, spec.units, 3)}"
        f"{_lengths_in(spec)}), {pv.describe_ranking(ranked_by)}, acceptable under the "
        f"{_limits_text(spec)}",
        table(columns, rows),
    ]
    if not pairs:
        lines.append("(no acceptable pair of dyads)")
    named = [(f"{name} of pair {k}", p_) for k, p in enumerate(pairs, start=1)
             for name, p_ in (("A0", p.driving.center), ("C0", p.driven.center))]
    outside = describe_outside(outside_view(named, spec.view.extent), spec.view.extent, spec.units)
    if outside:
        lines.append(f"note: {outside} ('burmester map' draws the view)")
    lines.append(
        "A0, C0: the driving and driven fixed pivots. size: the total length of the links in task "
        "sizes. mu min: smallest transmission angle over the travel 1 -> 2 -> 3 -> 4 (degrees)."
    )
    return "\n".join(lines)


def _space_words(space: Optional[burmester.Space], units: Optional[str] = None) -> str:
    """The space a design fits, in words (lengths with ``units``)."""
    if space is None or (space.region == "anywhere" and not space.obstacles and space.envelope is None):
        return "pivots anywhere"
    words = []
    if space.pivot_box is not None:
        x0, x1, y0, y1 = space.pivot_box
        words.append(f"pivots in x {x0:g}..{x1:g}, y {y0:g}..{y1:g}" + (f" {units}" if units else ""))
    elif space.pivot_polygon is not None:
        words.append(f"pivots in a polygon of {len(space.pivot_polygon)} vertices")
    else:
        words.append("pivots anywhere")
    if space.obstacles:
        words.append(f"{len(space.obstacles)} obstacle(s) cleared")
    if space.envelope is not None:
        words.append("inside the envelope")
    if space.link_width:
        words.append(f"links {format_length(space.link_width, units)} wide")
    return ", ".join(words)


def _design_row(k: int, linkage: burmester.SynthesizedFourBar, size_ratio: float, last: str) -> List[str]:
    """One row of :func:`design_table`: the pivots, size, lengths, type,
    transmission, link ratio, drive, and ``last`` (the score, or what a
    near miss misses)."""
    f = linkage.figures
    mu = f.min_transmission_deg
    drive = f"{f.direction} {f.modes[0] or ''}".strip() if f.branch_free else "branch defect"
    return [str(k), _fmt_point(linkage.driving[0]), _fmt_point(linkage.driven[0]), _fmt_size(size_ratio),
            *(f"{v:.3f}" for v in f.lengths), f.grashof, f"{mu:.1f}" if mu is not None else "-",
            f"{f.link_ratio:.2f}", drive, last]


#: The columns of a slider design's row (:func:`_slider_row`).
_SLIDER_COLUMNS = [("#", "right"), ("A0 (x, y)", "right"), ("guide: C1 (x, y)", "right"),
                   ("direction", "right"), ("size", "right"), ("crank", "right"), ("coupler", "right"),
                   ("offset", "right"), ("stroke", "right"), ("mu min", "right"), ("ratio", "right"),
                   ("drive", "left")]


def _slider_row(k: int, sc: burmester.SynthesizedSliderCrank, size_ratio: float, last: str) -> List[str]:
    """One row of a slider design: the crank pivot, the guide (the pin at
    pose 1 and the guide's direction), size, crank, coupler, offset, stroke
    used, transmission, link ratio, drive, and ``last``."""
    lk = sc.linkage
    mu = sc.min_transmission_deg
    drive = f"{sc.direction} {sc.modes[0] or ''}".strip() if sc.branch_free else "branch defect"
    ratio = max(lk.crank, lk.coupler) / min(lk.crank, lk.coupler)
    stroke = sc.stroke_used
    return [str(k), _fmt_point(sc.driving[0]), _fmt_point(sc.driven[0]),
            f"({sc.driven[1][0]:.3f}, {sc.driven[1][1]:.3f})", _fmt_size(size_ratio),
            f"{lk.crank:.3f}", f"{lk.coupler:.3f}", f"{lk.offset:.3f}",
            f"{stroke:.3f}" if stroke is not None else "-", f"{mu:.1f}" if mu is not None else "-",
            f"{ratio:.2f}", drive, last]


def _slider_violations(sc: burmester.SynthesizedSliderCrank, limits: burmester.DesignLimits) -> List[str]:
    """The limits a slider-crank misses, in words (the search's reading:
    crank and coupler for the link ratio, crank, coupler and offset for the
    link length)."""
    lk = sc.linkage
    bad = []
    mu = sc.min_transmission_deg
    if mu is not None and mu < limits.min_transmission_deg:
        bad.append(f"transmission {mu:.1f} < {limits.min_transmission_deg:g} deg")
    ratio = max(lk.crank, lk.coupler) / min(lk.crank, lk.coupler)
    if ratio > limits.max_link_ratio:
        bad.append(f"link ratio {ratio:.2f} > {limits.max_link_ratio:g}")
    if sc.size_ratio > limits.max_size_ratio:
        bad.append(f"size ratio {sc.size_ratio:.2f} > {limits.max_size_ratio:g}")
    if max(lk.crank, lk.coupler, abs(lk.offset)) > limits.max_link_length:
        bad.append(f"a link longer than {limits.max_link_length:g}")
    return bad


def slider_dict(sc: burmester.SynthesizedSliderCrank) -> Dict[str, Any]:
    """A JSON-friendly dict of a designed slider-crank: its crank pivot,
    guide (the pin at pose 1 and the direction), size, lengths, stroke,
    transmission and drive."""
    lk = sc.linkage
    return {
        "driving_center": list(sc.driving[0]),
        "guide_point": list(sc.driven[0]),
        "guide_direction": list(sc.driven[1]),
        "size": sc.size,
        "size_ratio": sc.size_ratio,
        "crank": lk.crank,
        "coupler": lk.coupler,
        "offset": lk.offset,
        "stroke_used": sc.stroke_used,
        "input_full": lk.turns_fully,
        "link_ratio": max(lk.crank, lk.coupler) / min(lk.crank, lk.coupler),
        "min_transmission_deg": sc.min_transmission_deg,
        "direction": sc.direction,
        "modes": list(sc.modes),
    }


def _found_dict(linkage: Any, limits: burmester.DesignLimits) -> Dict[str, Any]:
    """:func:`slider_dict` or the four-bar's ``linkage_dict``."""
    if isinstance(linkage, burmester.SynthesizedSliderCrank):
        return {"driven": "slider", **slider_dict(linkage), "violations": _slider_violations(linkage, limits)}
    return pv.linkage_dict(linkage, limits)


def design_table(spec: TaskSpec, report: burmester.DesignReport) -> str:
    """The text table of ``burmester design``: the task and ranking, the
    limits and the space every verdict was judged by, the designs (or the
    nearest misses with what each misses), what the columns mean."""
    task = spec.task
    lines = [
        f"Designs for {spec.source} ({len(task)} poses, task size {format_length(task.span, spec.units, 3)}: "
        f"the largest distance between two poses{_lengths_in(spec)}), {pv.describe_ranking(report.rank_by)}",
        f"{pv.describe_limits(report.limits, spec.units)}; space: {_space_words(report.space, spec.units)}",
    ]
    columns = [("#", "right"), ("A0 (x, y)", "right"), ("C0 (x, y)", "right"), ("size", "right"),
               ("ground", "right"), ("crank", "right"), ("coupler", "right"), ("rocker", "right"),
               ("Grashof type", "left"), ("mu min", "right"), ("ratio", "right"), ("drive", "left")]
    found = [d.linkage for d in report] + [m.linkage for m in report.near_misses]
    sliders = any(isinstance(x, burmester.SynthesizedSliderCrank) for x in found)
    if sliders:
        columns = _SLIDER_COLUMNS

    def row(k: int, linkage: Any, size_ratio: float, last: str) -> List[str]:
        if isinstance(linkage, burmester.SynthesizedSliderCrank):
            return _slider_row(k, linkage, size_ratio, last)
        return _design_row(k, linkage, size_ratio, last)

    if len(report) and sliders:
        rows = [row(k, d.linkage, d.size_ratio, f"{d.score:.4f}") for k, d in enumerate(report, start=1)]
        lines.append(table(columns + [("score", "right")], rows))
        lines.append(
            "Slider-cranks: A0 the crank's fixed pivot; the slider's pin runs on a straight guide fixed to "
            "the ground, through C1 (the pin at pose 1) along the direction given (no pivot to place). "
            "size: the links, the offset and the guide's run in task sizes. offset: the guide's distance "
            "from A0. stroke: the slider's travel along the guide from the first pose to the last. mu "
            "min: the smallest angle between coupler and the guide's normal over the travel (degrees). "
            "ratio: the longer of crank and coupler over the shorter. Each meets the limits above, judged "
            "exactly, refined from the best of a coarse search."
        )
    elif len(report):
        rows = [_design_row(k, d.linkage, d.size_ratio, f"{d.score:.4f}")  # type: ignore[arg-type]
                for k, d in enumerate(report, start=1)]
        lines.append(table(columns + [("score", "right")], rows))
        lines.append(
            "A0: the driving crank's fixed pivot, C0: the driven one's. size: the total length of the "
            "links (the coupler as its triangle with the coupler point) in task sizes. mu min: the "
            "smallest transmission angle over the whole travel (degrees). ratio: longest link / shortest. "
            "Each meets the limits above, judged exactly, refined from the best of a coarse search."
        )
    else:
        main = report.main_rejection
        rej = ", ".join(f"{name.replace('_', ' ')} {n}" for name, n in report.rejections)
        lines.append(
            f"No linkage fits. Of {report.census} candidates judged against every limit, the one "
            f"rejecting the most is {main.replace('_', ' ') if main else 'none'} ({rej or 'none'}); "
            "nothing was relaxed."
        )
        if report.near_misses:
            lines.append("Nearest misses (a feasible motion, missing the limits by the least):")
            rows = []
            for k, m in enumerate(report.near_misses, start=1):
                lk = m.linkage
                bad = (_slider_violations(lk, report.limits) if isinstance(lk, burmester.SynthesizedSliderCrank)
                       else pv.linkage_violations(lk, report.limits, spec.units))
                bad += [w.replace("_", " ") for w in m.misses if w in ("pivot_region", "obstacles", "envelope")]
                rows.append(row(k, lk, m.size_ratio, "; ".join(bad)))
            lines.append(table(columns + [("misses", "left")], rows))
    return "\n".join(lines)


def design_document(spec: TaskSpec, report: burmester.DesignReport) -> Dict[str, Any]:
    """The JSON document of ``burmester design --json``."""
    lim, space = report.limits, report.space
    return {
        "task": spec.source,
        "units": spec.units,
        "poses": len(spec.poses),
        "span": spec.task.span,
        "ranking": report.rank_by,
        "limits": pv.limits_dict(lim),
        "space": {
            "region": space.region,
            "pivot_box": space.pivot_box,
            "pivot_polygon": space.pivot_polygon,
            "obstacles": space.obstacles,
            "link_width": space.link_width,
            "envelope": space.envelope,
        },
        "search_box": report.search_box,
        "coarse_candidates": report.coarse_candidates,
        "coarse_acceptable": report.coarse_acceptable,
        "evaluations": report.evaluations,
        "min_separation": report.min_separation,
        "designs": [
            {"score": d.score, "found_by": d.found_by, "coarse": d.coarse, "refined": d.refined,
             "coarse_score": d.coarse_score, **_found_dict(d.linkage, lim)}
            for d in report
        ],
        "rejections": dict(report.rejections),
        "census": report.census,
        "near_misses": [
            {"misses": m.misses, "shortfall": m.shortfall, **_found_dict(m.linkage, lim)}
            for m in report.near_misses
        ],
    }


def motor_table(report: burmester.DesignReport) -> str:
    """The motor section of ``burmester design --motor``: for each design its
    drive (:func:`burmester.drives.drive_table`) or that its input turns
    fully, and the designs passed over for want of a drive."""
    from burmester import drives

    ratio = report.max_time_ratio
    lines = [
        f"With a motor (swing margin {report.swing_margin_deg or 0.0:g} deg, time ratio "
        f"{'no limit' if ratio is None or math.isinf(ratio) else f'<= {ratio:g}'}):"
    ]
    for k, d in enumerate(report, start=1):
        if d.drive is None:
            lines.append(f"Design {k}: its input turns fully: the motor turns it at A0 "
                         f"{_fmt_point(d.driving_pivot)} directly.")
        else:
            lines.append(drives.drive_table(d.drive, f"design {k}"))
    if report.undriven:
        lines.append(f"{report.undriven} candidate design(s) passed over: no acceptable drive for them under "
                     "these limits and this space.")
    return "\n".join(lines)


def _motor_document(doc: Dict[str, Any], report: burmester.DesignReport) -> Dict[str, Any]:
    """``doc`` (:func:`design_document`) with each design's ``"drive"``
    (None where the input turns fully) and the motor's options."""
    from burmester import drives

    for entry, d in zip(doc["designs"], report):
        entry["drive"] = drives.drive_record(d.drive) if d.drive is not None else None
    ratio = report.max_time_ratio
    doc["motor"] = {
        "swing_margin_deg": report.swing_margin_deg,
        "max_time_ratio": None if ratio is None or math.isinf(ratio) else ratio,
        "undriven": report.undriven,
    }
    return doc


def position_table(fourbar: burmester.FourBar, step_deg: float = 30.0) -> str:
    """A text table (:func:`table`) of both assembly modes over a full turn
    of the input."""
    columns = [("theta2", "right"), ("open theta3", "right"), ("theta4", "right"), ("mu", "right"),
               ("crossed theta3", "right"), ("theta4", "right"), ("mu", "right")]
    n = max(1, round(360.0 / step_deg))
    both: Tuple[Mode, Mode] = ("open", "crossed")
    rows = []
    for k in range(n):
        t2 = k * 360.0 / n
        row = [f"{t2:.1f}"]
        for mode in both:
            try:
                c = fourbar.configuration(math.radians(t2), mode)
            except burmester.AssemblyError:
                row += ["(does not close)", "", ""]
            else:
                row += [f"{math.degrees(c.theta3):.3f}", f"{math.degrees(c.theta4):.3f}",
                        f"{math.degrees(c.transmission_angle):.1f}"]
        rows.append(row)
    return "\n".join([f"{fourbar!r}: {fourbar.grashof}", table(columns, rows),
                      "angles in degrees; mu is the transmission angle"])
