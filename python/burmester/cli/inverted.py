"""``burmester inverted``: the inverted slider-cranks of a task (a crank
whose coupler carries a slot sliding through a block pivoted on the ground
at the swivel; issue 27).

The candidates are every driving crank of the task with every inverted
slider (:meth:`burmester.Task.inverted_sliders`), each built exactly by
:meth:`burmester.Task.inverted_slider_crank`; only those the crank carries
through the poses in order in one mode (``feasible``), with both fixed
pivots where the task file's ``[space]`` allows them and within its
``[limits]`` (the smallest transmission angle over the travel, the size
over the task's span, crank over ground or its inverse as the link ratio,
and with ``input = "crank"`` a crank that turns fully) are kept, ranked like the one-call design's ``balanced``: ``sin(mu min) /
sqrt(size ratio)``. The driving cranks: three poses, the crank pivots on a
grid over the ``[space]`` search box (else the task file's ``[view]``);
four poses, the center-point curve's dyads; five, the Burmester points.
``--pivot`` and ``--swivel`` fix either. The space's obstacles and
envelope are not checked over the travel (only where the pivots go).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from typing import Any, Dict, List, NamedTuple, Optional, Sequence, Tuple

import numpy as np

import burmester
from burmester import _counts
from burmester.cli.base import UsageError, _fmt_point, _load, _with_units
from burmester.cli import files
from burmester.cli.tables import table
from burmester.taskfile import TaskSpec
from burmester.units import format_length

Point = Tuple[float, float]

#: The inverted sliders sampled along the pole circle of three poses, and
#: the crank pivots along each side of the grid, by default.
DEFAULT_SAMPLES, DEFAULT_GRID = 72, 24
#: The most candidates (driving cranks times inverted sliders) one search
#: builds: about five seconds on one core.
MAX_CANDIDATES = 250_000


class Candidate(NamedTuple):
    """A kept inverted slider-crank and its score (larger is better)."""

    score: float
    linkage: burmester.SynthesizedInvertedSliderCrank


def _cranks(task: burmester.Task, spec: TaskSpec, pivot: Optional[Point], grid: int) -> List[Tuple[Point, Point]]:
    """The driving cranks ``(A0, A1)`` tried: ``pivot``'s alone when given."""
    if pivot is not None:
        return [task.dyad(pivot)]
    offers = _counts.of(task)
    if offers.curves:
        return [d.dyad for run in task.curve_dyads(grid * grid // 4 or 1) for d in run]
    if offers.burmester_points:
        return [(c, a) for c, a in task.burmester_points()]
    if spec.space is not None:
        x0, x1, y0, y1 = spec.space.search_box(task, spec.limits)
    else:
        v = spec.view
        x0, x1, y0, y1 = v.xmin, v.xmax, v.ymin, v.ymax
    out = []
    for y in np.linspace(y0, y1, grid):
        for x in np.linspace(x0, x1, grid):
            try:
                out.append(task.dyad((float(x), float(y))))
            except burmester.BurmesterError:  # a pole, or a center point without a circle point
                continue
    return out


def candidates(spec: TaskSpec, *, pivot: Optional[Point] = None, swivel: Optional[Point] = None,
               samples: int = DEFAULT_SAMPLES, grid: int = DEFAULT_GRID) -> Tuple[List[Candidate], int]:
    """The kept candidates, best first, and how many were built."""
    task = spec.task
    sliders = [task.inverted_slider(swivel)] if swivel is not None else task.inverted_sliders(samples)
    if not sliders:
        raise UsageError(f"{spec.source}: the task has no inverted slider (a line of the body through a fixed "
                         "point at every pose): four or five poses have one only where the inverted motion's "
                         "circle-point curve or Burmester points reach infinity; try three of the poses")
    cranks = _cranks(task, spec, pivot, grid)
    if len(cranks) * len(sliders) > MAX_CANDIDATES:
        raise UsageError(f"{len(cranks)} driving cranks x {len(sliders)} inverted sliders is more than the "
                         f"{MAX_CANDIDATES} candidates one search builds; give fewer --samples or a smaller "
                         "--pivot-grid, or fix one with --pivot or --swivel")
    space, lim = spec.space, spec.limits
    if space is not None:
        sliders = [s for s in sliders if swivel is not None or space.contains_pivot(s.swivel)]
    kept: List[Candidate] = []
    built = 0
    for a0, a1 in cranks:
        if space is not None and pivot is None and not space.contains_pivot(a0):
            continue
        for s in sliders:
            try:
                q = task.inverted_slider_crank((a0, a1), (s.swivel, s.direction))
            except burmester.BurmesterError:  # the slot never assembles, a crank of no length
                continue
            built += 1
            mu = q.min_transmission_deg
            if not q.feasible or mu is None or mu < lim.min_transmission_deg:
                continue
            l = q.linkage
            if not l.ground > 0.0 or max(l.crank, l.ground) / min(l.crank, l.ground) > lim.max_link_ratio:
                continue
            if q.size_ratio > lim.max_size_ratio or (lim.input == "crank" and not l.turns_fully):
                continue
            kept.append(Candidate(math.sin(math.radians(mu)) / math.sqrt(q.size_ratio), q))
    kept.sort(key=lambda c: -c.score)
    return kept, built


def record(q: burmester.SynthesizedInvertedSliderCrank) -> Dict[str, Any]:
    """One inverted slider-crank as a JSON record."""
    l = q.linkage
    return {"pivot": list(l.pivot), "swivel": list(l.swivel), "crank": l.crank, "ground": l.ground,
            "offset": l.offset, "slot_direction": list(q.driven[1]), "circle_point": list(q.driving[1]),
            "input_angles_deg": [math.degrees(t) for t in q.input_angles], "modes": list(q.modes),
            "direction": q.direction, "stroke_used": q.stroke_used, "swing_used_deg": q.swing_used_deg,
            "min_transmission_deg": q.min_transmission_deg, "size_ratio": q.size_ratio}


def inverted_table(kept: Sequence[Candidate], units: Optional[str]) -> str:
    """The ranked inverted slider-cranks as a text table."""
    def length(v: Optional[float]) -> str:
        return "-" if v is None else format_length(v, units)

    rows = []
    for k, c in enumerate(kept, start=1):
        q, l = c.linkage, c.linkage.linkage
        rows.append([str(k), _fmt_point(l.pivot), _fmt_point(l.swivel), length(l.crank), length(l.ground),
                     length(l.offset), length(q.stroke_used),
                     "-" if q.swing_used_deg is None else f"{q.swing_used_deg:.1f}",
                     f"{q.min_transmission_deg:.1f}", f"{q.size_ratio:.2f}", q.direction, f"{c.score:.3f}"])
    cols = [("#", "right"), ("crank pivot A0", "left"), ("swivel S", "left"), ("crank", "right"),
            ("ground", "right"), ("offset", "right"), ("stroke", "right"), ("swing deg", "right"),
            ("mu min deg", "right"), ("size ratio", "right"), ("turns", "left"), ("score", "right")]
    return table(cols, rows)


def cmd_inverted(args: argparse.Namespace) -> int:
    """``burmester inverted``: the task's best inverted slider-cranks, as a
    table or JSON; with ``-o`` the best drawn at its poses (``.png`` ...),
    exported (``.dxf``, ``.svg``) or animated through the poses (``.gif``,
    ``.mp4``)."""
    spec = _with_units(_load(args.task), args)  # the task file's errors first
    out: Optional[str] = args.output
    animated = out is not None and out.lower().endswith(files.ANIMATION_TYPES)
    cad = out is not None and files._is_cad(out)
    if out is not None:
        files._output(out, files._types(files.PICTURE_TYPES, files.CAD_TYPES, files.ANIMATION_TYPES), args.force)
    for flag, given in (("--frames", args.frames), ("--fps", args.fps)):
        if given is not None and not animated:
            raise UsageError(f"{flag} is for animations (-o ... .gif or .mp4)")
    if args.travel is not None and not cad:
        raise UsageError("--travel is for CAD exports (-o ... .dxf or .svg)")
    export = files._export_module(out) if out is not None and cad else None
    units = files._units(args, spec) if out is not None else None
    pivot = None if args.pivot is None else (args.pivot[0], args.pivot[1])
    swivel = None if args.swivel is None else (args.swivel[0], args.swivel[1])
    kept, built = candidates(spec, pivot=pivot, swivel=swivel, samples=args.samples, grid=args.pivot_grid)
    if not kept:
        raise UsageError(
            f"{spec.source}: none of the {built} inverted slider-cranks built is driven through the poses in "
            f"order in one mode within the limits ({spec.limits.min_transmission_deg:g} deg transmission, "
            "link and size ratios) and the space; try another --pivot or --swivel, more --samples, or "
            "relax the task file's [limits]"
        )
    best = kept[:args.top]
    if args.json:
        print(json.dumps({"task": spec.source, "units": spec.units, "built": built, "kept": len(kept),
                          "linkages": [record(c.linkage) for c in best]}, indent=2))
    else:
        print(f"{spec.source}: {len(kept)} of {built} inverted slider-cranks driven through the poses in order "
              f"within the limits; the best {len(best)}:")
        print(inverted_table(best, spec.units))
    if out is None:
        return 0
    q = best[0].linkage
    if export is not None:
        files._write_cad(export.inverted_slider_crank, out, args.force, q, out, units=units,
                   travel_samples=args.travel or 0)
    elif animated:
        plot = files._plot_module()
        try:
            files._written(out, args.force, lambda tmp: plot.animate_inverted_slider_crank(
                q, tmp, frames=args.frames or 60, fps=args.fps or 20, dpi=args.dpi or 80, units=spec.units))
        except RuntimeError as e:  # no ffmpeg for .mp4
            raise UsageError(str(e)) from None
    else:
        ax = files._plot_module().inverted_slider_crank(q, units=spec.units)
        files._save(ax.figure, out, files._picture_dpi(args), args.force)
    print(f"wrote {out}: the best inverted slider-crank", file=sys.stderr if args.json else sys.stdout)
    return 0
