"""The commands: one function ``cmd_NAME(args)`` per ``burmester NAME``,
returning the exit status."""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Dict, List, Literal, Optional, Tuple

import numpy as np

import burmester
from burmester import _counts as counts
from burmester import pivots as pv
from burmester import taskfile
from burmester._burmester import Grid
from burmester.cli.base import (
    PAIR_SAMPLES,
    ProgressBar,
    UsageError,
    _check_memory,
    _fmt_point,
    _lengths_in,
    _limits_text,
    _load,
    _outside_note,
    _pair_map,
    _solution_map,
    _spacing,
    _with_grid,
    _with_units,
    progress_for,
)
from burmester.cli import slider_map
from burmester.cli.files import (
    ANIMATION_TYPES,
    CAD_TYPES,
    PICTURE_TYPES,
    _export_module,
    _is_cad,
    _output,
    _picture_dpi,
    _plot_module,
    _save,
    _types,
    _units,
    _write_cad,
    _written,
)
from burmester.cli.tables import (
    _motor_document,
    _pair_record,
    burmester_table,
    design_document,
    design_table,
    motor_table,
    pair_table,
    pivot_table,
    position_table,
)
from burmester.taskfile import TaskSpec
from burmester.units import format_length

if TYPE_CHECKING:
    from types import ModuleType

    from burmester._burmester import Mode, RankBy

#: The built-in example four-bar: Norton, *Design of Machinery*, Example 4-1 (mm).
#: ``(ground, crank, coupler, rocker)``.
EXAMPLE_FOURBAR = (100.0, 40.0, 120.0, 80.0)


def cmd_map(args: argparse.Namespace) -> int:
    """``burmester map``: draw the center-point (or circle-point) plane."""
    spec = _with_units(_with_grid(_load(args.task), args.grid), args)  # the task file's errors first
    spec = slider_map.with_driven_slider(spec, getattr(args, "driven_slider", None))
    if spec.driven_slider is not None:  # a driven slider: its slider-cranks' map
        return slider_map.map_slider(args, spec)
    _output(args.output, _types(PICTURE_TYPES, CAD_TYPES), args.force)
    units = _units(args, spec)
    cad = _is_cad(args.output)
    count = counts.of(spec.poses)
    if count.filemon:  # the grid is the branch map's (four and five poses trace curves)
        design = "+design" if args.design or args.pivots > 0 else ""
        _check_memory(spec.view.nx, spec.view.ny, ("cad" if cad else "picture") + design,
                      f"drawing {args.output}", "--grid")
    export = _export_module(args.output) if cad else None
    plot = None if cad else _plot_module()
    if not count.filemon:
        return _map_many(args, spec, plot, export, units)
    filemon = spec.filemon()
    view = spec.view
    if args.plane == "circle":
        if export is not None:
            _write_cad(export.plane, args.output, args.force, filemon, args.output, plane="circle",
                       units=units)
        else:
            assert plot is not None
            ax = plot.circle_plane(filemon, units=spec.units)
        summary = f"circle-point plane of {spec.source}{_lengths_in(spec)}"
    else:
        smap = _solution_map(spec, filemon) if args.design or args.pivots > 0 else None
        if smap is not None and args.method == "conic":
            free = smap.branch_free  # the branch map, computed once (with the solution map)
        else:
            free = filemon.branch_map(
                view, method=args.method, progress=progress_for(view, "branch map")
            )
        marks = None
        acceptable = transmission = None
        if args.design and smap is not None:
            acceptable = smap.acceptable
            transmission = np.degrees(smap.min_transmission_rad)
        if args.pivots > 0 and smap is not None:
            ranked, _ = pv.rank(smap, args.pivots, pv.default_spacing(view))
            marks = [p.center for p in ranked]
        if export is not None:
            _write_cad(export.plane, args.output, args.force, filemon, args.output, view, free=free, pivots=marks,
                       acceptable=acceptable, transmission=transmission, units=units)
        else:
            assert plot is not None
            ax = plot.center_plane(
                filemon, view, free=free, pivots=marks, acceptable=acceptable, transmission=transmission,
                units=spec.units,
            )
        summary = (
            f"center-point plane of {spec.source}{_lengths_in(spec)}: {100 * free.mean():.1f}% of the "
            f"{view.nx} x {view.ny} grid is branch-free"
        )
        if smap is not None:
            summary += f", {100 * np.mean(smap.acceptable):.1f}% acceptable ({_limits_text(spec)})"
        task = filemon.task
        summary += _outside_note(spec, [(f"P{p.pair[0]}{p.pair[1]}", p.point) for p in task.poles]
                                 + [("C0", filemon.driven_center)])
    if export is None:
        _save(ax.figure, args.output, _picture_dpi(args), args.force)
    print(f"wrote {args.output}: {summary}")
    return 0


def _map_many(args: argparse.Namespace, spec: TaskSpec, plot: Optional[ModuleType],
              export: Optional[ModuleType], units: str) -> int:
    """``burmester map`` of four or five poses: the center-point curve
    coloured by crank order, or the Burmester points on their curves (a
    picture with ``plot``, a CAD export with ``export``)."""
    count = counts.of(spec.poses)
    circle = args.plane == "circle"
    for flag, given in (("--plane circle", circle and not count.circle_plane), ("--design", args.design),
                        ("--pivots", args.pivots > 0)):
        if given:
            what = ("three poses (Filemon's construction) or four (the circle-point curve)"
                    if flag == "--plane circle" else "three poses (Filemon's construction)")
            raise UsageError(f"{flag} is for {what}; {spec.source} has {count.poses} poses")
    task = spec.task
    driven = spec.driven_center  # four poses: a driven dyad on the curve, or None
    if export is not None:
        _write_cad(export.burmester_plane, args.output, args.force, task, args.output, spec.view.extent,
                   driven=driven, plane=args.plane, units=units)
    elif circle:
        assert plot is not None
        ax = plot.circle_curve_plane(task, spec.view.extent, driven=driven, units=spec.units)
    else:
        assert plot is not None
        ax = plot.burmester_plane(task, spec.view.extent, driven=driven, units=spec.units)
    if count.curves:
        plane: Literal["center", "circle"] = "circle" if circle else "center"
        arcs = task.order_arcs(*spec.view.extent, plane=plane)
        ordered = sum(1 for _, d, _ in arcs if d is not None)
        summary = (
            f"{plane}-point curve of {spec.source}{_lengths_in(spec)}: {len(arcs)} pieces in "
            f"view, {ordered} of them with the crank meeting the poses in order"
        )
        if driven is not None:
            free = task.branch_free_arcs(driven, *spec.view.extent, plane=plane)
            summary += (f"; {len(free)} arcs of driving dyads branch-free with the driven dyad at C0 "
                        f"{_fmt_point(driven)}")
    else:
        pts = task.burmester_points()
        listed = ", ".join(_fmt_point(c) for c, _ in pts)
        summary = (f"Burmester points of {spec.source}{_lengths_in(spec)}: {len(pts)}"
                   + (f": {listed}" if pts else ""))
    summary += _outside_note(spec, taskfile.curve_plane_points(task, driven, args.plane))
    if export is None:
        _save(ax.figure, args.output, _picture_dpi(args), args.force)
    print(f"wrote {args.output}: {summary}")
    return 0


#: Default driven and driving grids of ``burmester atlas`` (over the task's view).
ATLAS_DRIVEN_GRID = (24, 24)
ATLAS_DRIVING_GRID = (80, 80)


def _atlas_client(address: Optional[str]) -> Any:
    if address is None:
        return None
    try:
        import importlib

        distributed = importlib.import_module("distributed")
    except ImportError:
        raise ImportError('--scheduler needs Dask: pip install "burmester[dask]"') from None
    try:
        return distributed.Client(address, timeout=10)
    except (OSError, TimeoutError) as e:
        raise UsageError(f"cannot reach the Dask scheduler at {address}: {e}") from None


def cmd_atlas(args: argparse.Namespace) -> int:
    """``burmester atlas``: the best driving pivot for every driven center."""
    output = args.output if args.output is not None else (None if args.json else "atlas.png")
    spec = _with_units(_load(args.task), args)  # the task file's errors first
    if output is not None:
        _output(output, PICTURE_TYPES, args.force)
    v = spec.view
    grids = []
    for flag, given, default in (("--driven-grid", args.driven_grid, ATLAS_DRIVEN_GRID),
                                 ("--driving-grid", args.driving_grid, ATLAS_DRIVING_GRID)):
        nx, ny = given if given is not None else default
        for name, n in (("NX", nx), ("NY", ny)):
            if not 2 <= n <= 4000:
                raise UsageError(f"{flag} {name} must be from 2 to 4000, got {n}")
        grids.append(Grid(v.xmin, v.xmax, v.ymin, v.ymax, nx, ny))
    driven, driving = grids
    plot = _plot_module() if output is not None else None
    client = _atlas_client(args.scheduler)
    bar = progress_for(driven, "atlas", driving.size) if client is None else None
    try:
        atlas = burmester.pivot_atlas(spec.task, driven, driving, client=client,
                                      limits=spec.limits, rank_by=args.rank_by, progress=bar)
    except TimeoutError as e:  # a cluster without workers
        raise UsageError(str(e)) from None
    finally:
        if client is not None:
            client.close()
    best = atlas.best_pairs(1)
    if args.json:
        lim = spec.limits
        doc = {
            "task": spec.source,
            "units": spec.units,
            "driven_grid": [driven.nx, driven.ny],
            "driving_grid": [driving.nx, driving.ny],
            "view": {"x": [v.xmin, v.xmax], "y": [v.ymin, v.ymax]},
            "limits": pv.limits_dict(lim),
            "ranking": atlas.rank_by,
            "valid": int(atlas.valid.sum()),
            "with_acceptable": int(np.count_nonzero(atlas.count)),
            "best": [p._asdict() for p in atlas.best_pairs(args.top)],
        }
        print(json.dumps(doc, indent=2))
    if plot is not None and output is not None:
        ax = plot.atlas(atlas, units=spec.units)
        ax.set_title(f"pivot-pair atlas of {spec.source}")
        _save(ax.figure, output, args.dpi, args.force)
        summary = (f"{int(np.count_nonzero(atlas.count))} of {driven.size} driven centers "
                   f"have an acceptable driving pivot ({_limits_text(spec)}{_lengths_in(spec)}); "
                   f"{pv.describe_ranking(atlas.rank_by)}")
        if best:
            summary += (f"; best at C0 {_fmt_point(best[0].driven)}, A0 {_fmt_point(best[0].driving)}: "
                        f"{best[0].min_transmission_deg:.1f} deg, {best[0].size_ratio:.1f}x the task's size")
        print(f"wrote {output}: {summary}", file=sys.stderr if args.json else sys.stdout)
    return 0


def _pivots_five(args: argparse.Namespace, spec: TaskSpec) -> int:
    """``burmester pivots`` of five poses: the four-bars of the Burmester points."""
    if args.rank_by == "pareto":
        raise UsageError("five poses have at most twelve Burmester four-bars, listed whole: rank them by "
                         "balanced, transmission or compact")
    if args.json:
        print(json.dumps(pv.report_burmester(spec, args.rank_by), indent=2))
    else:
        ranked = pv.rank_burmester(spec.task, spec.limits, args.rank_by)
        print(burmester_table(spec, ranked[: args.top], args.rank_by))
    return 0


def cmd_pivots(args: argparse.Namespace) -> int:
    """``burmester pivots``: rank the branch-free driving pivots (five
    poses: the four-bars of the Burmester points)."""
    spec = _with_units(_load(args.task), args)
    if counts.of(spec.poses).burmester_points:
        return _pivots_five(args, spec)
    spec = _with_grid(spec, args.grid)
    _check_memory(spec.view.nx, spec.view.ny, "ranking", "the solution map", "--grid")
    spacing = _spacing(spec, args.spacing)
    if args.json:
        doc = pv.report(spec, args.top, spacing, progress_for(spec.view, "solution map", 16), args.rank_by)
        print(json.dumps(doc, indent=2))
    else:
        smap = _solution_map(spec, spec.filemon())
        pivots, ranked_by = pv.rank(smap, args.top, spacing, args.rank_by)
        print(pivot_table(spec, pivots, ranked_by))
    return 0


def cmd_batch(args: argparse.Namespace) -> int:
    """``burmester batch``: each task file's best pivots, one JSON line each
    (the document of ``burmester pivots --json``, or ``{"task", "error"}``);
    status 2 when any file failed, after all of them ran."""
    if args.spacing is not None and not args.spacing >= 0.0:
        raise UsageError(f"--spacing must be at least 0, got {args.spacing:g}")
    client = _atlas_client(args.scheduler)
    try:
        records = burmester.best_pivots_batch(args.tasks, client=client, top=args.top,
                                              spacing=args.spacing, rank_by=args.rank_by)
    except TimeoutError as e:  # a cluster without workers
        raise UsageError(str(e)) from None
    finally:
        if client is not None:
            client.close()
    failed = 0
    for rec in records:
        print(json.dumps(rec), flush=True)
        if "error" in rec:
            failed += 1
            print(f"burmester batch: error: {rec['error']}", file=sys.stderr)
    return 2 if failed else 0


def cmd_linkage(args: argparse.Namespace) -> int:
    """``burmester linkage``: draw or animate the four-bar of one driving pivot."""
    spec = _with_units(_load(args.task), args)  # the task file's errors first
    _output(args.output, _types(PICTURE_TYPES, CAD_TYPES, ANIMATION_TYPES), args.force)
    units = _units(args, spec)
    out: str = args.output
    cad = _is_cad(out)
    animated = out.lower().endswith(ANIMATION_TYPES)
    for flag, given in (("--frames", args.frames), ("--fps", args.fps)):
        if given is not None and not animated:
            extra = "; for a CAD export, --travel N draws the linkage at N positions" if cad else ""
            raise UsageError(f"{flag} is for animations (.gif, .mp4), not {out}{extra}")
    if args.travel is not None and not cad:
        raise UsageError(f"--travel is for CAD exports (.dxf, .svg), not {out}; animate with -o linkage.gif")
    export = _export_module(out) if cad else None
    sfb, what = _chosen_linkage(args, spec, "balanced", "draws")
    task = spec.task
    _draw_linkage(args, sfb, task, spec.units, out, export, None, units)
    state = "branch-free" if sfb.branch_free else "has a branch defect"
    lengths = ", ".join(f"{name} {format_length(v, spec.units)}"
                        for name, v in zip(("ground", "crank", "coupler", "rocker"), sfb.fourbar.lengths))
    pivots = [("A0", sfb.driving[0]), ("C0", sfb.driven[0])]
    print(f"wrote {out}: four-bar with {what}, {sfb.fourbar.grashof}, {state}: {lengths}"
          f"{_outside_note(spec, pivots)}")
    return 0


def _best_burmester_linkage(args: argparse.Namespace, spec: TaskSpec) -> Tuple[burmester.SynthesizedFourBar, str]:
    """The four-bar ``burmester linkage`` draws for five poses: the best of
    :func:`burmester.pivots.rank_burmester` that carries the coupler through
    the poses in order, and how to name it."""
    if args.pivot is not None:
        raise UsageError("five poses: the linkage is built from two Burmester points; drop --pivot "
                         "(burmester pivots lists them all)")
    ranked = [b for b in pv.rank_burmester(spec.task, spec.limits) if b.linkage.figures.direction != "none"]
    if not ranked:
        raise UsageError(f"{spec.source}: no four-bar of two Burmester points carries the coupler through "
                         "the five poses in order")
    b = ranked[0]
    return b.linkage, f"Burmester points B{b.driving + 1} driving, B{b.driven + 1} driven"


def cmd_pairs(args: argparse.Namespace) -> int:
    """``burmester pairs``: rank the pairs of dyads of a four-pose task (the
    pair map), and draw the map."""
    spec = _with_units(_load(args.task), args)  # the task file's errors first
    if args.output is not None:
        _output(args.output, PICTURE_TYPES, args.force)
        _check_memory(args.samples, args.samples, "picture", f"drawing {args.output}", "--samples")
    pmap = _pair_map(spec, args.samples)
    pairs = pmap.best_pairs(args.top, rank_by=args.rank_by)
    if args.output is not None:
        ax = _plot_module().pair_map(pmap, pairs=args.top, rank_by=args.rank_by)
        _save(ax.figure, args.output, _picture_dpi(args), args.force)
    if args.json:
        doc = {
            "task": spec.source,
            "units": spec.units,
            "limits": pv.limits_dict(spec.limits),
            "samples": list(pmap.shape),
            "acceptable_fraction": float(np.mean(pmap.acceptable)),
            "branch_free_fraction": float(np.mean(pmap.branch_free)),
            "pairs": [_pair_record(p) for p in pairs],
        }
        print(json.dumps(doc, indent=2))
    else:
        print(pair_table(spec, pairs, args.rank_by))
    if args.output is not None and not args.json:
        print(f"wrote {args.output}: pair map of {spec.source}, {pmap.shape[1]} x {pmap.shape[0]} pairs, "
              f"{100 * np.mean(pmap.acceptable):.1f}% acceptable ({_limits_text(spec)})")
    return 0


# ---------------------------------------------------------------------------
# burmester design: from poses (and a space) to the best linkage


def cmd_design(args: argparse.Namespace) -> int:
    """``burmester design``: the best linkages for the task's poses inside its
    space, both fixed pivots searched (three poses), drawn with ``-o``; with
    ``--motor`` each design whose input swings carries its drive (the
    six-bar), which ``-o`` then draws, animates or exports."""
    spec = _with_units(_load(args.task), args)  # the task file's errors first
    margin = args.margin if args.margin is not None else 0.0
    max_time_ratio = args.max_time_ratio if args.max_time_ratio is not None else math.inf
    strut = _design_strut(args, spec.actuator)
    if not args.motor and (args.margin is not None or args.max_time_ratio is not None):
        raise UsageError("--margin and --max-time-ratio set the motor's drive: give --motor with them")
    if not 0.0 <= margin < 90.0:
        raise UsageError(f"--margin must be from 0 to 90 degrees, got {margin:g}")
    if not max_time_ratio >= 1.0:
        raise UsageError(f"--max-time-ratio must be at least 1, got {max_time_ratio:g}")
    out: Optional[str] = args.output
    export: Optional[ModuleType] = None
    plot: Optional[ModuleType] = None
    animated = False
    if out is not None:
        _output(out, _types(PICTURE_TYPES, CAD_TYPES, ANIMATION_TYPES), args.force)
        units = _units(args, spec)
        animated = out.lower().endswith(ANIMATION_TYPES)
        for flag, given in (("--frames", args.frames), ("--fps", args.fps)):
            if given is not None and not animated:
                raise UsageError(f"{flag} is for animations (.gif, .mp4), not {out}")
        if args.travel is not None and not _is_cad(out):
            raise UsageError(f"--travel is for CAD exports (.dxf, .svg), not {out}")
        export = _export_module(out) if _is_cad(out) else None
        plot = None if export is not None else _plot_module()
    elif args.dpi is not None or args.frames is not None or args.fps is not None or args.travel is not None:
        raise UsageError("--dpi, --frames, --fps and --travel are for the drawing: give -o best.png "
                         "(or .gif, .svg, .dxf)")
    task = spec.task
    client = _atlas_client(args.scheduler)
    bar = (ProgressBar(sys.stderr, "burmester: design") if sys.stderr.isatty() and client is None
           and counts.of(spec.poses).design_progress else None)
    try:
        report = burmester.design(task, space=spec.space, limits=spec.limits, rank_by=args.rank_by,
                                  top=args.top, client=client, progress=bar,
                                  input=strut.pop("input", "motor" if args.motor else None),
                                  swing_margin_deg=margin, max_time_ratio=max_time_ratio,
                                  driven=_design_driven(args, spec), **strut)
    finally:
        if client is not None:
            client.close()
    if args.json:
        doc = design_document(spec, report)
        doc = _actuator_document(doc, report) if report.actuator else doc
        print(json.dumps(_motor_document(doc, report) if report.motor else doc, indent=2))
    else:
        print(design_table(spec, report))
        if report.motor:
            print(motor_table(report))
        if report.actuator:
            print(_actuator_section(report, spec.units or ""))
    if out is None:
        return 0
    said = sys.stderr if args.json else sys.stdout
    if not len(report):
        print(f"nothing drawn: no linkage fits, so {out} was not written", file=said)
        return 0
    sfb = report[0].linkage
    drive = report[0].drive
    strut_placed = report[0].actuator
    if strut_placed is not None and export is None and not animated:
        from burmester import actuators

        ax = actuators.draw_actuator(strut_placed)
        _save(ax.figure, out, _picture_dpi(args), args.force)
        print(f"wrote {out}: the best design with its linear actuator, stroke {strut_placed.stroke:.1f}, "
              f"ratio {strut_placed.stroke_ratio:.3f}", file=said)
        return 0
    if drive is not None:
        _draw_sixbar(args, drive, out, export, plot, units, args.travel,
                     title=f"best design with its motor drive ({drive.ranked_by or 'drive'})")
        print(f"wrote {out}: the best design's six-bar, motor crank at {_fmt_point(drive.drive_pivot)}, "
              f"transmission >= {drive.min_transmission_deg:.1f} deg over a crank turn, time ratio "
              f"{drive.time_ratio:.3f}", file=said)
        return 0
    if isinstance(sfb, burmester.SynthesizedSliderCrank):
        _draw_slider_design(args, sfb, out, export, plot, spec.units,
                            title=f"best design of {spec.source} ({report.rank_by})")
        print(f"wrote {out}: the best design, a slider-crank, {report[0].size_ratio:.1f}x the task's size, "
              f"transmission >= {sfb.min_transmission_deg or 0.0:.1f} deg, stroke "
              f"{format_length(sfb.stroke_used or 0.0, spec.units)}", file=said)
        return 0
    _draw_linkage(args, sfb, task, spec.units, out, export, plot, units,
                  title=f"best design of {spec.source} ({report.rank_by})")
    f = sfb.figures
    lengths = ", ".join(f"{name} {format_length(v, spec.units)}"
                        for name, v in zip(("ground", "crank", "coupler", "rocker"), f.lengths))
    print(f"wrote {out}: the best design, {f.grashof}, {report[0].size_ratio:.1f}x the task's size, "
          f"transmission >= {f.min_transmission_deg:.1f} deg: {lengths}", file=said)
    return 0


def _design_driven(args: argparse.Namespace, spec: Any) -> Literal["revolute", "slider"]:
    """The driven dyad's kind of ``design``: ``--driven``, else the task
    file's ``[design] driven``, else ``"revolute"``."""
    given = args.driven if args.driven is not None else getattr(spec, "design_driven", None)
    return "slider" if given == "slider" else "revolute"


def _draw_slider_design(args: argparse.Namespace, sc: burmester.SynthesizedSliderCrank, out: str,
                        export: Optional[ModuleType], plot: Optional[ModuleType], task_units: Optional[str],
                        title: Optional[str] = None) -> None:
    """``design --driven slider -o``: the slider-crank exported (``export``;
    at ``--travel`` positions too), animated through the poses (``.gif``,
    ``.mp4``) or drawn at pose 1 (with ``title``)."""
    if export is not None:
        _write_cad(export.slider_crank, out, args.force, sc, out, travel_samples=args.travel or 0)
        return
    plot = _plot_module() if plot is None else plot
    if out.lower().endswith(ANIMATION_TYPES):
        _animated(out, args.force, lambda tmp: plot.animate_slider_crank(sc, tmp, frames=args.frames or 60,
                                                                         fps=args.fps or 20, units=task_units))
        return
    ax = plot.slider_crank(sc, units=task_units)
    if title is not None:
        ax.set_title(title)
    _save(ax.figure, out, _picture_dpi(args), args.force)


def _design_strut(args: argparse.Namespace, spec_actuator: Any = None) -> Dict[str, Any]:
    """The keywords of ``burmester.design`` for ``design --input``:
    ``--input motor`` sets ``args.motor``; ``--input actuator`` gives the
    actuator's keywords, which are refused without it. The task file's
    ``[actuator]`` table (``spec_actuator``) gives their defaults: its
    ``link``, ``point``, ``max_stroke_ratio``, ``max_size_ratio``, ``width``
    and ``min_gap``, each overridden by its flag (``--actuator-link``,
    ``--actuator-point`` or ``--try-actuator-points``,
    ``--max-stroke-ratio``, ``--actuator-max-size-ratio``,
    ``--actuator-width``, ``--min-gap``); a bad value is a
    :class:`UsageError` naming the flag or the key."""
    which = args.design_input
    if which == "motor":
        args.motor = True
        return {}
    given = [flag for flag, v in (("--actuator-link", args.actuator_link), ("--actuator-point", args.actuator_point),
                                  ("--try-actuator-points", args.try_actuator_points or None),
                                  ("--max-stroke-ratio", args.max_stroke_ratio),
                                  ("--actuator-max-size-ratio", args.actuator_max_size_ratio),
                                  ("--actuator-width", args.actuator_width), ("--min-gap", args.min_gap))
             if v is not None]
    if which != "actuator":
        if given:
            raise UsageError(f"{', '.join(given)} set the linear actuator: give --input actuator with them")
        return {}
    if args.motor:
        raise UsageError("--motor and --input actuator: a design has one input, give one of them")
    if args.actuator_point is not None and args.try_actuator_points:
        raise UsageError("--actuator-point and --try-actuator-points: give one of them (a point, or a few "
                         "points of the link tried)")
    table = spec_actuator
    kw: Dict[str, Any] = {"input": "actuator"}
    link = _flag_or_key(args.actuator_link, "--actuator-link", table, "link")
    if link is not None:
        flag, value = link
        if value not in ("coupler", "crank", "rocker"):
            raise UsageError(f"{flag} must be \"coupler\", \"crank\" or \"rocker\", got {value!r}")
        kw["actuator_link"] = value
    point = None if args.try_actuator_points else _flag_or_key(args.actuator_point, "--actuator-point", table,
                                                               "point")
    if point is not None:
        flag, value = point
        try:
            x, y = (float(c) for c in value)
        except (TypeError, ValueError):
            raise UsageError(f"{flag} must be a point [x, y], got {value!r}") from None
        if not (math.isfinite(x) and math.isfinite(y)):
            raise UsageError(f"{flag} must be a finite point [x, y], got {value!r}")
        kw["actuator_point"] = (x, y)
    ratio = _flag_or_key(args.max_stroke_ratio, "--max-stroke-ratio", table, "max_stroke_ratio")
    if ratio is not None:
        flag, value = ratio
        if not value >= 1.0:
            raise UsageError(f"{flag} must be at least 1 (open over closed length), got {value:g}")
        kw["max_stroke_ratio"] = value
    size = _flag_or_key(args.actuator_max_size_ratio, "--actuator-max-size-ratio", table, "max_size_ratio")
    if size is not None:
        flag, value = size
        if not value >= 1.0:
            raise UsageError(f"{flag} must be at least 1 (the linkage with the open actuator over the task's "
                             f"span; inf: no limit), got {value:g}")
        kw["actuator_max_size_ratio"] = value
    kw.update(_strut_gap(args.actuator_width, args.min_gap, table))
    return kw


def _flag_or_key(flag_value: Any, flag: str, table: Any, key: str) -> Optional[Tuple[str, Any]]:
    """``(what, value)``: the flag's value where given, else the task file's
    ``[actuator]`` ``key`` where set (``what`` naming it for an error), else
    None."""
    if flag_value is not None:
        return flag, flag_value
    value = getattr(table, key, None) if table is not None else None
    if value is None:
        return None
    return f"[actuator] {key} (in the task file; or give {flag})", value


def _strut_gap(width: Optional[float], min_gap: Optional[float], table: Any) -> Dict[str, float]:
    """``actuator_width`` and ``min_gap``: the flags', else the task file's
    ``[actuator]`` ``width`` and ``min_gap``, else 0 (refused below 0,
    naming the flag or the key)."""
    w = _flag_or_key(width, "--actuator-width", table, "width") or ("", 0.0)
    g = _flag_or_key(min_gap, "--min-gap", table, "min_gap") or ("", 0.0)
    if not w[1] >= 0.0:
        raise UsageError(f"{w[0]} must be at least 0 (the strut's diameter), got {w[1]:g}")
    if not g[1] >= 0.0:
        raise UsageError(f"{g[0]} must be at least 0, got {g[1]:g}")
    return {"actuator_width": w[1], "min_gap": g[1]}


def _actuator_section(report: burmester.DesignReport, units: str) -> str:
    """The actuator section of ``burmester design --input actuator``: each
    design's placement (:func:`burmester.actuators.actuator_table`) and the
    designs passed over for want of one."""
    from burmester import actuators

    size = report.actuator_max_size_ratio
    bound = f"at most {size:g}x the task" if size is not None and math.isfinite(size) else "of any size"
    lines = [f"With a linear actuator (the linkage with the open actuator {bound}):"]
    for k, d in enumerate(report, start=1):
        if d.actuator is not None:
            lines.append(actuators.actuator_table(d.actuator, f"design {k}", units))
    if report.unplaced:
        lines.append(f"{report.unplaced} candidate design(s) passed over: no clear, acceptable actuator "
                     "placement for them under these limits and this space.")
    return "\n".join(lines)


def _actuator_document(doc: Dict[str, Any], report: burmester.DesignReport) -> Dict[str, Any]:
    """``doc`` with each design's ``"actuator"`` and the count passed over."""
    from burmester import actuators

    for entry, d in zip(doc["designs"], report):
        entry["actuator"] = actuators.actuator_record(d.actuator) if d.actuator is not None else None
    doc["unplaced"] = report.unplaced
    size = report.actuator_max_size_ratio
    doc["actuator_max_size_ratio"] = size if size is not None and math.isfinite(size) else None
    return doc


def _draw_linkage(args: argparse.Namespace, sfb: burmester.SynthesizedFourBar, task: burmester.Task,
                  task_units: Optional[str], out: str, export: Optional[ModuleType], plot: Optional[ModuleType],
                  units: str, title: Optional[str] = None) -> None:
    """``linkage -o``, ``design -o``: the four-bar exported (``export``; at
    ``--travel`` positions too), animated through the poses (``.gif``,
    ``.mp4``: ``--frames``, ``--fps``) or drawn at them (with ``title``)."""
    if export is not None:
        _write_cad(export.linkage, out, args.force, sfb, out, task=task, travel_samples=args.travel or 0,
                   units=units)
        return
    plot = _plot_module() if plot is None else plot
    if out.lower().endswith(ANIMATION_TYPES):
        _animated(out, args.force, lambda tmp: plot.animate(sfb, tmp, task=task, frames=args.frames or 60,
                                                            fps=args.fps or 20, units=task_units))
        return
    ax = plot.linkage(sfb, task=task, units=task_units)
    if title is not None:
        ax.set_title(title)
    _save(ax.figure, out, _picture_dpi(args), args.force)


def _draw_sixbar(args: argparse.Namespace, drive: burmester.Drive, out: str, export: Optional[ModuleType],
                 plot: Optional[ModuleType], units: str, turn: Optional[int], title: Optional[str] = None) -> None:
    """``drive -o``, ``design --motor -o``: the six-bar exported
    (``export``; at ``turn`` crank angles too), animated over a crank turn
    (``.gif``, ``.mp4``: ``--frames``, ``--fps``) or drawn at its poses
    (with ``title``)."""
    if export is not None:
        _write_cad(export.sixbar, out, args.force, drive, out, turn_samples=turn or 0, units=units)
        return
    plot = _plot_module() if plot is None else plot
    if out.lower().endswith(ANIMATION_TYPES):
        _animated(out, args.force,
                  lambda tmp: plot.animate_sixbar(drive, tmp, frames=args.frames or 120, fps=args.fps or 24))
        return
    ax = plot.sixbar(drive, units=units)
    if title is not None:
        ax.set_title(title)
    _save(ax.figure, out, _picture_dpi(args), args.force)


def _animated(out: str, force: bool, write: Callable[[Path], Any]) -> None:
    """Write an animation by ``write(tmp)`` (:func:`_written`); a missing
    writer (ffmpeg for ``.mp4``) is a usage error."""
    try:
        _written(out, force, write)
    except RuntimeError as e:
        raise UsageError(str(e)) from None
    import matplotlib.pyplot as plt

    plt.close("all")


#: The finest ``solve --step``: 36,000 rows over a turn.
MIN_STEP_DEG = 0.01


def cmd_solve(args: argparse.Namespace) -> int:
    """``burmester solve``: position analysis of a four-bar."""
    given = [args.ground, args.crank, args.coupler, args.rocker]
    if all(v is None for v in given):
        lengths = EXAMPLE_FOURBAR
        print("(no lengths given: the example four-bar of Norton, Design of Machinery, Example 4-1)")
    elif any(v is None for v in given):
        missing = [n for n, v in zip(("--ground", "--crank", "--coupler", "--rocker"), given) if v is None]
        raise UsageError(f"missing {', '.join(missing)}: give all four link lengths, or none for the example")
    else:
        lengths = (args.ground, args.crank, args.coupler, args.rocker)
    if args.step is not None and not MIN_STEP_DEG <= args.step <= 360.0:
        raise UsageError(
            f"--step must be from {MIN_STEP_DEG:g} to 360 degrees (at most "
            f"{round(360 / MIN_STEP_DEG)} rows), got {args.step:g}"
        )
    ground, crank, coupler, rocker = lengths
    fb = burmester.FourBar(ground=ground, crank=crank, coupler=coupler, rocker=rocker)
    if args.theta2 is None:
        print(position_table(fb, args.step or 30.0))
        return 0
    t2 = math.radians(args.theta2)
    modes: List[Mode] = [args.mode] if args.mode else ["open", "crossed"]
    lines = [f"{fb!r}: {fb.grashof}", f"theta2 = {args.theta2:g} deg"]
    for mode in modes:
        try:
            c = fb.configuration(t2, mode)
        except burmester.AssemblyError:
            ranges = fb.input_range or []
            arcs = " or ".join(f"[{math.degrees(a):.1f}, {math.degrees(b):.1f}]" for a, b in ranges)
            raise UsageError(
                f"the loop does not close at theta2 = {args.theta2:g} deg; "
                f"this input only rocks within {arcs} deg: choose --theta2 there"
            ) from None
        o2, a, b, o4 = fb.joints(t2, mode)
        lines.append(
            f"{mode + ':':<8} theta3 = {math.degrees(c.theta3):9.3f} deg, theta4 = "
            f"{math.degrees(c.theta4):9.3f} deg, transmission angle = "
            f"{math.degrees(c.transmission_angle):6.2f} deg"
            + (" (toggle)" if c.toggle else "")
            + f"; A = {_fmt_point(a)}, B = {_fmt_point(b)}"
        )
    print("\n".join(lines))
    return 0


def cmd_example(args: argparse.Namespace) -> int:
    """``burmester example``: print (or write) the built-in example as a task file."""
    text = taskfile.dumps(taskfile.example())
    if args.output is None or args.output == "-":
        sys.stdout.write(text)
        return 0
    _output(args.output, (".toml",), args.force)
    _written(args.output, args.force, lambda tmp: tmp.write_text(text, encoding="utf-8"))
    print(f"wrote {args.output}")
    return 0


# ---------------------------------------------------------------------------
# burmester drive: a motor for a linkage whose input swings


def _chosen_linkage(args: argparse.Namespace, spec: TaskSpec, rank_by: RankBy,
                    verb: Literal["draws", "drives"]) -> Tuple[burmester.SynthesizedFourBar, str]:
    """The four-bar ``burmester linkage`` draws and ``burmester drive``
    drives (``verb``), and how to name it: three poses, the ``--pivot``
    given or the best driving pivot by ``rank_by`` under the task's limits;
    four, the best pair of dyads; five, the best Burmester four-bar."""
    count = counts.of(spec.poses)
    if count.burmester_points:
        return _best_burmester_linkage(args, spec)
    if count.curves:
        drawn = verb == "draws"
        if args.pivot is not None:
            raise UsageError(f"--pivot is for three poses; a four-pose task {verb} its best pair of dyads"
                             + (" (see 'burmester pairs')" if drawn else ""))
        best_pairs = _pair_map(spec, PAIR_SAMPLES).best_pairs(1, rank_by=rank_by)
        if not best_pairs:
            judged = f" ({_limits_text(spec)})" if drawn else ""
            raise UsageError(f"no acceptable pair of dyads for {spec.source}{judged}; see 'burmester pairs'")
        named = "driving pivot A0" if drawn else "A0"
        return best_pairs[0].linkage, f"the best pair of dyads, {named} = {_fmt_point(best_pairs[0].driving.center)}"
    filemon = spec.filemon()
    if args.pivot is None:
        best, _ = pv.rank(_solution_map(spec, filemon), 1, pv.default_spacing(spec.view), rank_by)
        if not best:
            raise UsageError("no branch-free driving pivot in the view; give one with --pivot X Y")
        pivot = best[0].center
    else:
        pivot = (args.pivot[0], args.pivot[1])
    return filemon.four_bar(pivot), f"driving pivot A0 = {_fmt_point(pivot)}"


def cmd_drive(args: argparse.Namespace) -> int:
    """``burmester drive``: a motor for the task's linkage: the best added
    dyad (the Watt II six-bar), as a table or JSON, drawn, animated or
    exported."""
    from burmester import drives

    spec = _with_units(_with_grid(_load(args.task), args.grid), args)
    out: Optional[str] = args.output
    if out is not None:
        _output(out, _types(PICTURE_TYPES, CAD_TYPES, ANIMATION_TYPES), args.force)
        if args.map and (_is_cad(out) or out.lower().endswith(ANIMATION_TYPES)):
            raise UsageError(f"--map draws a picture (.png, .pdf, ...), not {out}")
    if not 0.0 <= args.margin < 90.0:
        raise UsageError(f"--margin must be from 0 to 90 degrees, got {args.margin:g}")
    if not args.max_time_ratio >= 1.0:
        raise UsageError(f"--max-time-ratio must be at least 1, got {args.max_time_ratio:g}")
    export = _export_module(out) if out is not None and _is_cad(out) and not args.map else None
    sfb, what = _chosen_linkage(args, spec, args.rank_by, "drives")
    bar = ProgressBar(sys.stderr, "burmester: drive search") if sys.stderr.isatty() else None
    drive = sfb.best_drive(limits=spec.limits, swing_margin_deg=args.margin,
                           max_time_ratio=args.max_time_ratio, rank_by=args.drive_rank_by,
                           progress=bar)
    if args.json:
        doc = {
            "task": spec.source,
            "linkage": drives.linkage_record(sfb),
            "drive": drives.drive_record(drive),
        }
        print(json.dumps(doc, indent=2))
    else:
        print(drives.drive_table(drive, f"{spec.source} ({what})"))
    if out is None:
        return 0
    shown = sys.stderr if args.json else sys.stdout
    if args.map:
        plot = _plot_module()
        e = drive.attachment
        a0 = sfb.driving[0]
        h = 1.25 * max(math.dist(a0, drive.drive_pivot), math.dist(a0, e))
        dmap = sfb.drive_map(a0[0] - h, a0[0] + h, a0[1] - h, a0[1] + h, 400, 400, attachment=e,
                             limits=spec.limits, swing_margin_deg=args.margin,
                             max_time_ratio=args.max_time_ratio)
        ax = plot.drive_map(dmap, rank_by=args.drive_rank_by)
        _save(ax.figure, out, _picture_dpi(args), args.force)
    else:
        _draw_sixbar(args, drive, out, export, None, _units(args, spec), args.turn)
    print(f"wrote {out}", file=shown)
    return 0


def cmd_actuator(args: argparse.Namespace) -> int:
    """``burmester actuator``: a linear actuator for the task's best design:
    its placement map and the best placement, as a table or JSON; with
    ``-o``, drawn (the map and the design, ``.png`` ...), exported (the
    design with its cylinder, ``.dxf``, ``.svg``) or animated (``.gif``,
    ``.mp4``). The task file's ``[actuator]`` table gives the defaults;
    the flags override it."""
    from burmester import actuators
    from burmester.taskfile import ActuatorSpec

    spec = _with_units(_load(args.task), args)
    out: Optional[str] = args.output
    export: Optional[ModuleType] = None
    if out is not None:
        _output(out, _types(PICTURE_TYPES, CAD_TYPES, ANIMATION_TYPES), args.force)
        animated = out.lower().endswith(ANIMATION_TYPES)
        for flag, value in (("--frames", args.frames), ("--fps", args.fps)):
            if value is not None and not animated:
                raise UsageError(f"{flag} is for animations (.gif, .mp4), not {out}")
        export = _export_module(out) if _is_cad(out) else None
    table = spec.actuator or ActuatorSpec()
    link = args.link or table.link
    given = args.point if args.point is not None else table.point
    point = (given[0], given[1]) if given is not None else None
    ratio = args.max_stroke_ratio if args.max_stroke_ratio is not None else table.max_stroke_ratio
    if not ratio >= 1.0:
        raise UsageError(f"--max-stroke-ratio must be at least 1, got {ratio:g}")
    rank_by = args.actuator_rank_by or table.rank_by
    report = burmester.design(spec.task, space=spec.space, limits=spec.limits, top=1)
    if not len(report):
        raise UsageError(f"no linkage fits {spec.source}; see 'burmester design'")
    sfb = report[0].linkage
    lim = spec.limits
    size = args.max_size_ratio if args.max_size_ratio is not None else table.max_size_ratio
    if size is not None:
        lim = burmester.DesignLimits(lim.min_transmission_deg, lim.max_link_ratio, lim.input,
                                     size, lim.max_link_length, lim.min_grashof_margin)
    nx, ny = args.map_grid if args.map_grid is not None else table.grid
    plate = list(table.base_plate) if table.base_plate is not None else None
    width = args.width if args.width is not None else table.width
    if width is not None and not width > 0.0:
        raise UsageError(f"--actuator-width must be above 0, got {width:g}")
    gap = _strut_gap(width, args.min_gap, table)
    amap = actuators.actuator_map(sfb, table.view, (nx, ny), link=link, point=point, max_stroke_ratio=ratio,
                                  limits=lim, base_plate=plate, link_width=spec.space.link_width if spec.space is not None else 0.0, **gap)
    best = amap.best_placements(1, rank_by=rank_by)
    if not best:
        mono = int(np.count_nonzero(amap.monotone))
        clear = actuators.clear_count(amap)
        raise UsageError(f"no acceptable actuator placement for {spec.source}: {mono} of {amap.monotone.size} "
                         f"ground pivots give a monotone stroke, {clear} keep the strut's least gap "
                         f"({amap.min_gap:g}); try another --point or --link, or relax "
                         f"--max-stroke-ratio, --min-gap or the limits")
    a = best[0]
    if args.json:
        doc = {"task": spec.source, "actuator": actuators.actuator_record(a)}
        print(json.dumps(doc, indent=2))
    else:
        print(actuators.actuator_table(a, f"{spec.source} (its best design)", spec.units or ""))
    if out is None:
        return 0
    if export is not None:
        _write_cad(export.actuator, out, args.force, a, out, units=_units(args, spec), width=width)
    elif out.lower().endswith(ANIMATION_TYPES):
        plot = _plot_module()
        _animated(out, args.force, lambda tmp: plot.animate_actuator(a, tmp, frames=args.frames or 60,
                                                                     fps=args.fps or 20, width=width,
                                                                     dpi=args.dpi or 80, units=spec.units))
    else:
        _plot_module()
        import matplotlib.pyplot as plt

        fig, (left, right) = plt.subplots(1, 2, figsize=(15.0, 6.2))
        actuators.draw_map(amap, best=3, rank_by=rank_by, ax=left, units=spec.units)
        actuators.draw_actuator(a, ax=right, units=spec.units, width=width)
        fig.tight_layout()
        _save(fig, out, _picture_dpi(args), args.force)
    print(f"wrote {out}", file=sys.stderr if args.json else sys.stdout)
    return 0
