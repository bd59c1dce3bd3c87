"""Candidate driving pivots: which ranking to show, and what to say about each.

The rankings themselves are the core's, :meth:`burmester.SolutionMap.best_pivots`:
among the pivots that are branch-free, carry the coupler through the poses
in order on one circuit and meet the limits, the best by a documented score
(``"balanced"`` by default: force transmission, a small linkage relative to
the task and even links together; ``"transmission"``, ``"compact"``, or the
``"pareto"`` front of transmission and size), kept apart from each other.
When no pivot meets the limits, :func:`rank` falls back to the core's
ranking by margin (``rank_by="margin"``): the branch-free pivots farthest
from the transformed Filemon curves, with the limits each one misses
(:func:`violations`). The margin grows away from the curves, so in an
unbounded free region those lie on the edge of the view: choose the view as
the space you allow for the pivot.

This module only chooses between the two rankings and formats the
:class:`burmester.Pivot` records (words, JSON-friendly dicts).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Dict, List, NamedTuple, Optional, Tuple

from burmester.taskfile import in_view
from burmester.units import format_length
from burmester._burmester import (
    DesignLimits,
    Grid,
    InvalidInputError,
    LinkageFigures,
    Pivot,
    SolutionMap,
    SynthesizedFourBar,
    Task,
)

if TYPE_CHECKING:
    from burmester._burmester import Progress, RankBy
    from burmester.taskfile import TaskSpec

__all__ = ["RANKINGS", "BurmesterLinkage", "default_spacing", "rank", "rank_burmester", "check_ranking",
           "describe_ranking", "describe_limits", "limits_dict", "transmission_at_poses_deg",
           "violations", "size_violation", "linkage_violations", "linkage_dict", "as_dict", "report",
           "report_burmester"]

#: The rankings a designer chooses from (``"margin"`` is the fallback when
#: nothing is acceptable), the default first.
RANKINGS: Tuple[str, ...] = ("balanced", "transmission", "compact", "pareto")

_WORDS = {
    "balanced": "ranked by the balanced score sin(mu min) / sqrt(size x link ratio): force "
                "transmission, a small linkage and even links together",
    "transmission": "ranked by the minimum transmission angle over the travel",
    "compact": "ranked by size relative to the task, smallest first",
    "pareto": "the Pareto front of transmission and size, from the most compact to the best "
              "transmission",
    "margin": "none meets the limits: branch-free pivots ranked by margin (distance to the "
              "branch-defect boundary)",
}


def check_ranking(rank_by: str) -> None:
    """Raises :class:`burmester.InvalidInputError` for a ranking other than
    :data:`RANKINGS` and ``"margin"`` (before any map is computed)."""
    if rank_by not in RANKINGS + ("margin",):
        names = ", ".join(f'"{r}"' for r in RANKINGS + ("margin",))
        raise InvalidInputError(f"unknown ranking {rank_by!r}; use one of {names}")


def describe_ranking(ranked_by: str) -> str:
    """What a ranking orders by, in words (for tables and reports)."""
    return _WORDS[ranked_by]


def limits_dict(limits: DesignLimits) -> Dict[str, Any]:
    """The limits as JSON: ``min_transmission_deg``, ``max_link_ratio``,
    ``input``, ``min_grashof_margin``, ``max_size_ratio`` and
    ``max_link_length`` (the last three None: no limit; JSON has no
    infinity) and ``defaults`` (whether they are
    :class:`DesignLimits`'s defaults). The ``"limits"`` of every ``--json``
    document: every limit its verdicts (``violations``, ``acceptable``)
    were judged by."""
    return {
        "min_transmission_deg": limits.min_transmission_deg,
        "max_link_ratio": limits.max_link_ratio if math.isfinite(limits.max_link_ratio) else None,
        "input": limits.input,
        "min_grashof_margin": limits.min_grashof_margin,
        "max_size_ratio": limits.max_size_ratio if math.isfinite(limits.max_size_ratio) else None,
        "max_link_length": limits.max_link_length if math.isfinite(limits.max_link_length) else None,
        "defaults": limits == DesignLimits(),
    }


def describe_limits(limits: DesignLimits, units: Optional[str] = None) -> str:
    """Every limit in words, as every table prints them beside its verdicts:
    ``"limits: transmission >= 40 deg, link ratio <= 6, crank input,
    Grashof margin >= 0.01, size <= 5x the task, links <= 120 mm"`` (the
    size limits only when given, lengths with ``units``), or ``"default
    limits: ..."`` when they are :class:`DesignLimits`'s defaults (whether
    a task file gave them or not)."""
    which = "default limits" if limits == DesignLimits() else "limits"
    words = [f"transmission >= {limits.min_transmission_deg:g} deg", f"link ratio <= {limits.max_link_ratio:g}",
             f"{limits.input} input", f"Grashof margin >= {limits.min_grashof_margin:g}"]
    if math.isfinite(limits.max_size_ratio):
        words.append(f"size <= {limits.max_size_ratio:g}x the task")
    if math.isfinite(limits.max_link_length):
        words.append(f"links <= {format_length(limits.max_link_length, units)}")
    return f"{which}: " + ", ".join(words)


def default_spacing(grid: Grid) -> float:
    """The least distance between listed pivots the command line uses: a
    tenth of the view's shorter side."""
    return 0.1 * min(grid.xmax - grid.xmin, grid.ymax - grid.ymin)


def rank(smap: SolutionMap, top: int, spacing: Optional[float] = None,
         rank_by: "RankBy" = "balanced") -> Tuple[List[Pivot], "RankBy"]:
    """The ``top`` best pivots of a solution map and what ranked them.

    The acceptable pivots by ``rank_by`` (see
    :meth:`burmester.SolutionMap.best_pivots`); when none is acceptable, the
    branch-free pivots by their margin to the branch-defect boundary
    (``"margin"``). Both keep the pivots ``spacing`` apart (default: the
    core's, 2% of the view's diagonal).
    """
    if top < 1:
        return [], rank_by
    best = smap.best_pivots(top, spacing, rank_by=rank_by)
    if best or rank_by == "margin":
        return best, rank_by
    return smap.best_pivots(top, spacing, rank_by="margin"), "margin"


class BurmesterLinkage(NamedTuple):
    """A four-bar of two Burmester points of a five-pose task, as
    :func:`rank_burmester` lists it."""

    driving: int
    """Index of the driving dyad in :meth:`burmester.Task.burmester_points`."""
    driven: int
    """Index of the driven dyad."""
    linkage: SynthesizedFourBar
    """The four-bar."""
    score: Optional[float]
    """Its score by the ranking (:meth:`burmester.SynthesizedFourBar.score`)."""
    violations: List[str]
    """The limits it misses, in words (:func:`violations`); empty when
    acceptable."""


def rank_burmester(task: Task, limits: DesignLimits, rank_by: "RankBy" = "balanced") -> List[BurmesterLinkage]:
    """Every four-bar of two Burmester points of a five-pose task (both
    choices of the driving dyad, :meth:`burmester.Task.burmester_four_bars`),
    best first: the acceptable ones (no :func:`violations` of ``limits``) by
    their score, then the others by their score (None last). ``rank_by`` is
    ``"balanced"``, ``"transmission"`` or ``"compact"`` (a list of at most
    twelve has no map to take a Pareto front or margins of)."""
    if rank_by not in ("balanced", "transmission", "compact"):
        raise InvalidInputError(
            f"five poses rank their Burmester four-bars by \"balanced\", \"transmission\" or "
            f"\"compact\", got {rank_by!r}"
        )
    out = [
        BurmesterLinkage(i, j, sfb, sfb.score(rank_by), linkage_violations(sfb, limits))
        for i, j, sfb in task.burmester_four_bars()
    ]
    out.sort(key=lambda b: (bool(b.violations), b.score is None, -(b.score or 0.0)))
    return out


def transmission_at_poses_deg(linkage: SynthesizedFourBar) -> List[Optional[float]]:
    """The transmission angle at each pose, degrees (None where the linkage
    cannot be assembled there in that pose's mode)."""
    fb = linkage.fourbar
    out: List[Optional[float]] = []
    for theta, mode in zip(linkage.input_angles, linkage.modes):
        try:
            out.append(math.degrees(fb.transmission_angle(theta, mode or "open")))
        except ValueError:
            out.append(None)
    return out


def violations(figures: LinkageFigures, limits: DesignLimits, units: Optional[str] = None) -> List[str]:
    """The limits a linkage misses, in words (empty when it meets them all):
    the words for what :attr:`burmester.SolutionMap.acceptable` decides."""
    out = []
    if not figures.branch_free:
        out.append("branch defect (the poses are in different assembly modes)")
    if figures.direction == "none":
        out.append("no input direction passes the poses in order")
    elif not figures.one_circuit:
        out.append("the poses lie on two circuits")
    worst = figures.min_transmission_deg
    if worst is not None and worst < limits.min_transmission_deg:
        out.append(f"transmission {worst:.0f} < {limits.min_transmission_deg:g} deg")
    if figures.link_ratio > limits.max_link_ratio:
        out.append(f"link ratio {figures.link_ratio:.1f} > {limits.max_link_ratio:g}")
    if limits.input == "crank" and not figures.input_full:
        out.append("input is not a crank (it does not turn fully)")
    if limits.input == "rocker" and figures.input_full:
        out.append("input is not a rocker (it turns fully)")
    if figures.grashof_margin < limits.min_grashof_margin:
        out.append(f"Grashof margin {figures.grashof_margin:.2g} < {limits.min_grashof_margin:g} "
                   "(near the change point s + l = p + q)")
    if math.isfinite(limits.max_link_length) and max(figures.lengths) > limits.max_link_length:
        out.append(f"a link {format_length(max(figures.lengths), units, 3)} long > "
                   f"{format_length(limits.max_link_length, units)}")
    return out


def size_violation(linkage: SynthesizedFourBar, limits: DesignLimits) -> List[str]:
    """The size limit a linkage misses, in words (its size ratio over
    :attr:`burmester.DesignLimits.max_size_ratio`), or nothing."""
    if linkage.size_ratio > limits.max_size_ratio:
        return [f"size {linkage.size_ratio:.1f}x > {limits.max_size_ratio:g}x"]
    return []


def linkage_violations(linkage: SynthesizedFourBar, limits: DesignLimits, units: Optional[str] = None) -> List[str]:
    """Every limit a linkage misses, in words: :func:`violations` of its
    figures and :func:`size_violation`; empty exactly when it meets every
    limit :func:`describe_limits` prints."""
    return violations(linkage.figures, limits, units) + size_violation(linkage, limits)


def linkage_dict(linkage: SynthesizedFourBar, limits: Optional[DesignLimits] = None) -> Dict[str, Any]:
    """A JSON-friendly dict of a four-bar's figures: its pivots, size, link
    lengths, Grashof type, transmission and drive (with ``"violations"``
    when ``limits`` is given)."""
    f = linkage.figures
    g, c, cp, r = f.lengths
    d: Dict[str, Any] = {
        "driving_center": list(linkage.driving[0]),
        "driven_center": list(linkage.driven[0]),
        "size": linkage.size,
        "size_ratio": linkage.size_ratio,
        "ground": g,
        "crank": c,
        "coupler": cp,
        "rocker": r,
        "grashof": f.grashof,
        "input_full": f.input_full,
        "link_ratio": f.link_ratio,
        "grashof_margin": f.grashof_margin,
        "transmission_deg": transmission_at_poses_deg(linkage),
        "min_transmission_deg": f.min_transmission_deg,
        "direction": f.direction,
        "modes": list(f.modes),
    }
    if limits is not None:
        d["violations"] = linkage_violations(linkage, limits)
    return d


def as_dict(pivot: Pivot, limits: Optional[DesignLimits] = None) -> Dict[str, Any]:
    """A JSON-friendly dict of a pivot and its four-bar (:func:`linkage_dict`
    with the pivot's place in the map, margin, score and ranking)."""
    d: Dict[str, Any] = {
        "center": list(pivot.center),
        "index": list(pivot.index),
        "margin": pivot.margin,
        "score": pivot.score,
        "ranked_by": pivot.ranked_by,
    }
    d.update(linkage_dict(pivot.linkage, limits))
    return d


def report_burmester(spec: "TaskSpec", rank_by: "RankBy" = "balanced") -> Dict[str, Any]:
    """The JSON document of ``burmester pivots --json`` for a task of five
    poses: its Burmester points and every four-bar of two of them,
    :func:`rank_burmester` order, each with its indices, score and
    :func:`linkage_dict`."""
    task = spec.task
    lim = spec.limits
    v = spec.view
    extent = v.extent
    points = task.burmester_points()
    return {
        "task": spec.source,
        "units": spec.units,
        "span": task.span,
        "view": {"x": [v.xmin, v.xmax], "y": [v.ymin, v.ymax]},
        "ranking": rank_by,
        "limits": limits_dict(lim),
        "burmester_points": [{"center": list(c), "circle": list(z), "in_view": in_view(c, extent)}
                             for c, z in points],
        "linkages": [
            {"driving": b.driving, "driven": b.driven, "score": b.score, **linkage_dict(b.linkage, lim),
             "pivots_in_view": all(in_view(p, extent) for p in (b.linkage.driving[0], b.linkage.driven[0]))}
            for b in rank_burmester(task, lim, rank_by)
        ],
    }


def report(spec: "TaskSpec", top: int, spacing: Optional[float] = None,
           progress: Optional["Progress"] = None, rank_by: "RankBy" = "balanced") -> Dict[str, Any]:
    """The JSON document of ``burmester pivots --json`` for a task: its view,
    its size (``span``, the largest distance between two pose positions),
    limits, the spacing, which ranking (:func:`rank` by ``rank_by``) and the
    ``top`` best pivots (:func:`as_dict`). ``spacing`` defaults to
    :func:`default_spacing` of the view; ``progress`` goes to the solution
    map. Raises :class:`burmester.taskfile.TaskFileError` for a task of four
    or five poses and ``ValueError`` for a negative spacing or an unknown
    ranking."""
    check_ranking(rank_by)
    if spacing is None:
        spacing = default_spacing(spec.view)
    elif not spacing >= 0.0:
        raise ValueError(f"spacing must be at least 0, got {spacing:g}")
    smap = spec.filemon().solution_map(spec.view, limits=spec.limits, progress=progress)
    pivots, ranked_by = rank(smap, top, spacing, rank_by)
    v, lim = spec.view, spec.limits
    return {
        "task": spec.source,
        "units": spec.units,
        "span": smap.task.span,
        "view": {"x": [v.xmin, v.xmax], "y": [v.ymin, v.ymax], "grid": [v.nx, v.ny]},
        "driven_center_in_view": in_view(spec.filemon().driven_center, v.extent),
        "limits": limits_dict(lim),
        "spacing": spacing,
        "ranking": ranked_by,
        "pivots": [as_dict(p, lim) for p in pivots],
    }
