"""From poses to the best buildable linkage in one call: :func:`design`.

The search itself is the core's (``Task::design``): for three poses a coarse
pass over both fixed pivots (the pivot-pair atlas, ranked by the chosen
score) whose best cells are refined continuously on the exact figures (both
pivots moved together by Nelder-Mead, staying branch-free, in order, inside
the limits and the space); for four poses the pair map, refined along both
curve parameters; for five poses every ordered pair of Burmester points.
This module only adds the Dask route of the three-pose coarse pass: with
``client=`` the atlas tiles run as Dask tasks (:mod:`burmester.atlas`) and
the refinement runs here, with the same result as in process, bit for bit.

With ``input="motor"`` every design can be turned by a motor: a design whose
input swings carries the best drive the core finds for it
(:attr:`burmester.Design.drive`, the Watt II six-bar of an added
crank-rocker), one without an acceptable drive is passed over
(:attr:`burmester.DesignReport.undriven`).

With ``input="actuator"`` every design is driven by a linear actuator (a
cylinder, a gas strut) placed with it: its ground pivot searched over the
space's pivot region, its moving point on the chosen link, the placement
monotone, within the stroke ratio and the limits, and clear of the links,
obstacles and envelope over the travel (:attr:`burmester.Design.actuator`);
one without such a placement is passed over
(:attr:`burmester.DesignReport.unplaced`).
"""

from __future__ import annotations

import importlib
import math
from typing import Any, Callable, Dict, Literal, Optional, Tuple

from burmester import _counts as counts
from burmester._burmester import (
    DesignLimits,
    DesignReport,
    Space,
    Task,
    _atlas_tile,
    _design,
    _design_from_atlas,
    _design_plan,
)

__all__ = ["design"]

Progress = Callable[[int, int], object]


def design(
    task: Task,
    *,
    space: Optional[Space] = None,
    limits: Optional[DesignLimits] = None,
    rank_by: str = "balanced",
    top: int = 5,
    client: Any = None,
    progress: Optional[Progress] = None,
    min_separation: Optional[float] = None,
    coarse_driven: int = 12,
    coarse_driving: int = 48,
    coarse_pairs: int = 120,
    starts: int = 48,
    max_iterations: int = 3000,
    tile_rows: Optional[int] = None,
    input: Optional[Literal["any", "crank", "rocker", "motor", "actuator"]] = None,
    swing_margin_deg: float = 0.0,
    max_time_ratio: float = math.inf,
    actuator_link: Literal["coupler", "crank", "rocker"] = "coupler",
    actuator_point: Optional[Tuple[float, float]] = None,
    max_stroke_ratio: float = 1.8,
    actuator_samples: int = 64,
    actuator_width: float = 0.0,
    min_gap: float = 0.0,
    actuator_max_size_ratio: Optional[float] = None,
    driven: Literal["revolute", "slider"] = "revolute",
) -> DesignReport:
    """The best linkages for ``task`` (three to five poses) inside ``space``
    (a :class:`burmester.Space`; default: pivots anywhere, no obstacles)
    under ``limits`` (a :class:`burmester.DesignLimits`; default: its
    defaults, which the report carries), ranked by ``rank_by``
    (``"balanced"``, ``"transmission"`` or ``"compact"``).

    Returns a :class:`burmester.DesignReport`: a sequence of at most ``top``
    :class:`burmester.Design` records, best first, each a different linkage
    (its fixed pivots at least ``min_separation`` from a better one's;
    default a fifth of the task's size). When nothing fits it is empty and
    says which limit rejected the most candidates (``rejections``) and the
    nearest misses (``near_misses``); no limit is ever relaxed.

    ``coarse_driven`` and ``coarse_driving`` (three poses) and
    ``coarse_pairs`` (four) set the coarse pass; ``starts`` of its best
    cells are refined with ``max_iterations`` Nelder-Mead iterations each.
    ``progress(done, total)`` follows the search (in thousandths) and
    Ctrl-C stops it. With ``client`` (a ``dask.distributed.Client``) the
    three-pose coarse pass runs as Dask tasks of ``tile_rows`` driven rows
    (``progress`` then counts those rows) and the refinement in this
    process; four and five poses always run in this process.

    ``input`` overrides the limits' input requirement: ``"any"``,
    ``"crank"`` (the input turns fully) or ``"rocker"``; ``None`` (default)
    keeps the limits' own. ``"motor"`` takes any input and makes every
    design motor-driven: one whose input swings gets its best drive
    (:attr:`burmester.Design.drive`: a crank-rocker added to the input link,
    searched under the same limits, ranking and space: the drive's crank
    pivot on the space's pivot region and its links clear of the obstacles
    over a full crank turn; the envelope applies to the four-bar over its
    travel), with ``swing_margin_deg`` (the input swings that far beyond the
    first and last pose) and ``max_time_ratio`` (slower stroke over faster);
    a design without an acceptable drive is passed over for the next
    distinct one (counted in :attr:`burmester.DesignReport.undriven`).
    Both are refused without ``input="motor"``. A bad ``input`` raises
    :class:`burmester.InvalidInputError`.

    ``input="actuator"`` takes any input and drives every design by a linear
    actuator (:attr:`burmester.Design.actuator`, a
    :class:`burmester.Actuator`): between a ground pivot on the space's
    pivot region (``actuator_samples`` candidates along the longer side of
    its box, 2 to 512; with pivots anywhere, the linkage's box widened by
    its size) and the point ``actuator_point`` of ``actuator_link`` where it
    is at pose 1 (default: a few points of the link tried, the coupler's
    moving pivots, points between them and the task's coupler point). The
    placement is the best by ``rank_by`` whose length is monotone through
    the poses, whose stroke ratio is at most ``max_stroke_ratio`` and which
    meets ``limits`` (its force transmission angle, the link and size
    ratios with the open actuator; the size ratio's bound is
    ``actuator_max_size_ratio``, default None: the limits'
    ``max_size_ratio``, which the linkage alone meets too), and whose line
    stays clear of the links that do not carry its point, the space's
    obstacles and envelope over the travel (:attr:`burmester.Actuator.clear`). A design without one is
    passed over (:attr:`burmester.DesignReport.unplaced`). These keywords
    are refused without ``input="actuator"``.

    ``actuator_width`` is the strut's diameter (task units, default 0: its
    center line; give the body's, the thicker part) and ``min_gap`` the least
    gap (task units, default 0) its capsule must keep from the links'
    capsules (the space's ``link_width``), the obstacles and the envelope over
    the travel: a placement nearer than that is not clear. Both at least 0
    (:class:`burmester.InvalidInputError` otherwise). ``actuator_max_size_ratio``
    (at least 1, ``math.inf``: no limit; :class:`burmester.InvalidInputError`
    naming ``actuator max_size_ratio`` otherwise) lets the linkage with its
    open strut be larger than the linkage alone may be (a task file's
    ``[actuator]`` ``max_size_ratio``); the report gives the bound applied
    (:attr:`burmester.DesignReport.actuator_max_size_ratio`).

    ``driven="slider"`` designs slider-cranks: a driving crank of the task
    driving a slider dyad of the task (its pin on a straight guide fixed to
    the ground; :meth:`burmester.Task.slider_dyads`). Each
    :attr:`burmester.Design.linkage` is then a
    :class:`burmester.SynthesizedSliderCrank`, judged exactly as
    :meth:`burmester.Task.slider_crank` builds it (one assembly mode at
    every pose with no toggle between, the order, the transmission angle
    between coupler and the guide's normal over the travel, the link ratio
    of crank and coupler, the size with the stroke, ``A0`` in the pivot
    region). Three poses search ``A0`` (``coarse_driving``) and the pin
    along the slider circle (``coarse_driven``), refined over both; four
    poses the center-point curve (``coarse_pairs``) times the slider points;
    five poses the Burmester points times the slider Burmester points (a
    task without slider points raises
    :class:`burmester.InvalidInputError`, saying why). The space's
    obstacles and envelope are checked over the slider-crank's travel (the
    crank and the coupler as capsules of the links' width; the block is the
    pin at the coupler's end). A motor and an actuator are refused with a
    slider (they are searched on a four-bar), and the search runs in this
    process (``client`` is not used).
    """
    kw: Dict[str, Any] = dict(space=space, limits=limits, rank_by=rank_by, top=top, min_separation=min_separation,
              coarse_driven=coarse_driven, coarse_driving=coarse_driving, coarse_pairs=coarse_pairs,
              starts=starts, max_iterations=max_iterations, input=input, swing_margin_deg=swing_margin_deg,
              max_time_ratio=max_time_ratio, actuator_link=actuator_link, actuator_point=actuator_point,
              max_stroke_ratio=max_stroke_ratio, actuator_samples=actuator_samples, driven=driven)
    kw.update(actuator_width=actuator_width, min_gap=min_gap, actuator_max_size_ratio=actuator_max_size_ratio)
    # The coarse pass on Dask is the four-bars' atlas.
    if client is None or not counts.of(task).filemon or driven == "slider":
        return _design(task, progress=progress, **kw)
    from burmester.atlas import _DASK_MISSING, _on_dask

    try:
        importlib.import_module("distributed")
    except ImportError:
        raise ImportError(_DASK_MISSING) from None
    # Validates everything here, with in-process errors, before any task.
    plan = _design_plan(task, **kw)
    driven_grid, driving, opts = plan["driven"], plan["driving"], dict(plan["atlas"])
    _atlas_tile(task, driven_grid, 0, 0, driving, **opts)
    arrays = _on_dask(client, task, driven_grid, driving, opts, progress, tile_rows)
    return _design_from_atlas(task, arrays, **kw)
