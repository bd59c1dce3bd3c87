"""``burmester map`` with a driven slider: the slider solution map of a
three-pose task whose driven dyad is a slider (``[driven] slider = [x, y]``
in the task file, or ``--driven-slider X Y``), drawn by
:func:`burmester.plot.solution_map`, and its best slider-cranks
(:meth:`burmester.SolutionMap.best_slider_pivots`) printed."""

from __future__ import annotations

import argparse
import dataclasses
from typing import Sequence

import burmester
from burmester import _counts as counts
from burmester import pivots as pv
from burmester.cli.base import (
    UsageError,
    _check_memory,
    _fmt_point,
    _fmt_size,
    _lengths_in,
    _limits_text,
    progress_for,
)
from burmester.cli.files import PICTURE_TYPES, _output, _picture_dpi, _plot_module, _save, _types
from burmester.cli.tables import table
from burmester.taskfile import TaskSpec
from burmester.units import format_length

__all__ = ["map_slider", "with_driven_slider"]


def with_driven_slider(spec: TaskSpec, given: Sequence[float] | None) -> TaskSpec:
    """The task with the slider of ``--driven-slider X Y`` (its pin at pose
    1, on the task's slider circle) in place of the task file's
    ``[driven]``, when given."""
    if given is None:
        return spec
    if not counts.of(spec.poses).filemon:
        raise UsageError(f"--driven-slider is for three poses (the slider solution map); "
                         f"{spec.source} has {len(spec.poses)} poses")
    try:
        dyad = spec.task.slider_dyad((float(given[0]), float(given[1])))
    except burmester.InvalidInputError as e:
        raise UsageError(f"--driven-slider: not a slider point of the three poses: {e}") from None
    return dataclasses.replace(spec, driven_center=None, driven_slider=(dyad.circle, dyad.guide))


def slider_table(spec: TaskSpec, pivots: Sequence[burmester.SliderPivot], ranked_by: str) -> str:
    """The ranked slider-cranks: crank pivot, size, margin, the links, the
    smallest transmission angle (coupler to the guide's normal) over the
    travel, the stroke used and the drive."""
    head = pv.describe_ranking(ranked_by)
    if ranked_by != "margin":
        head += " (acceptable under the limits)"
    columns = [("#", "right"), ("A0 (x, y)", "right"), ("size", "right"), ("margin", "right"),
               ("crank", "right"), ("coupler", "right"), ("offset", "right"), ("mu min", "right"),
               ("stroke", "right"), ("drive", "left")]
    rows = []
    for k, p in enumerate(pivots, start=1):
        s = p.linkage
        mu = f"{s.min_transmission_deg:.1f}" if s.min_transmission_deg is not None else "-"
        stroke = f"{s.stroke_used:.3f}" if s.stroke_used is not None else "-"
        rows.append([str(k), _fmt_point(p.center), _fmt_size(p.size_ratio), f"{p.margin:.3f}",
                     f"{s.linkage.crank:.3f}", f"{s.linkage.coupler:.3f}", f"{s.linkage.offset:.3f}", mu,
                     stroke, f"{s.direction} {s.modes[0] or ''}".strip()])
    size = format_length(spec.task.span, spec.units, 3)
    empty = "" if pivots else "\n(no acceptable crank pivot in the view: widen [view] or relax [limits])"
    return (f"Crank pivots A0 of slider-cranks for {spec.source} (task size {size}{_lengths_in(spec)}), "
            f"{head}; {_limits_text(spec)}\n{table(columns, rows)}{empty}\n"
            "mu min: the smallest angle between the coupler and the guide's normal over the travel; "
            "stroke: the slider's travel along its guide from pose 1 to the last")


def map_slider(args: argparse.Namespace, spec: TaskSpec) -> int:
    """``burmester map`` of a task with a driven slider: the picture of the
    slider solution map (branch-free and acceptable crank pivots, the
    transmission contours, the guide, the best pivots numbered) and the
    table of the best slider-cranks (``--pivots N``, default 5)."""
    assert spec.driven_slider is not None
    for flag, given in (("--plane circle", args.plane == "circle"), ("--method", args.method != "conic")):
        if given:
            raise UsageError(f"{flag} is for a driven crank; a driven slider's map is its center-point plane "
                             "with the conic branch map (leave {flag} out)".replace("{flag}", flag))
    _output(args.output, _types(PICTURE_TYPES), args.force)
    view = spec.view
    _check_memory(view.nx, view.ny, "picture+design", f"drawing {args.output}", "--grid")
    c1, u = spec.driven_slider
    smap = burmester.SliderFilemon(spec.task, c1, u).solution_map(
        view, limits=spec.limits, progress=progress_for(view, "solution map", 16)
    )
    top = args.pivots if args.pivots > 0 else 5
    best = smap.best_slider_pivots(top)  # the default separation: the picture's stars
    plot = _plot_module()
    ax = plot.solution_map(smap, pivots=len(best), units=spec.units)
    _save(ax.figure, args.output, _picture_dpi(args), args.force)
    print(slider_table(spec, best, "balanced"))
    free = float(smap.branch_free.mean())
    acceptable = float(smap.acceptable.mean())
    print(f"wrote {args.output}: slider solution map of {spec.source}{_lengths_in(spec)}: "
          f"{100 * free:.1f}% of the {view.nx} x {view.ny} grid is branch-free, {100 * acceptable:.1f}% "
          f"acceptable ({_limits_text(spec)}); driven slider's pin C1 {_fmt_point(c1)} on a guide along "
          f"{_fmt_point(u)}")
    return 0
