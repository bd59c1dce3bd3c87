"""The pivot-pair atlas: search both fixed pivots at once.

For every candidate driven center point ``C0`` on a grid, the three-position
solution map over candidate driving center points ``A0`` on another grid
(``task.filemon(C0).solution_map(driving, ...)``), reduced to: the number of
acceptable driving pivots, the best of them by ``rank_by`` (``"balanced"``
by default, ``"transmission"`` or ``"compact"``; scores within ``1e-9`` tie
and go to the smaller linkage, then the wider margin to the nearest
branch-defect boundary: exactly ``best_pivots(1, rank_by=rank_by)``), its
driving center, figures and score, and the branch-free fraction.

The work is done by the native kernel one tile (rows of driven centers) at
a time; :func:`pivot_atlas` runs it in this process (rayon threads, the GIL
released, Ctrl-C and ``progress`` honoured) or, with ``client=`` a
``dask.distributed.Client``, as Dask tasks. Each driven center is computed
from its grid indices alone, so both give the same arrays, bit for bit.
"""

from __future__ import annotations

import importlib
import math
import os
import uuid
from typing import (
    TYPE_CHECKING, Any, Callable, Dict, List, NamedTuple, Optional, Sequence, Tuple, Union,
)

import numpy as np
import numpy.typing as npt

from burmester import _view
from burmester._burmester import DesignLimits, Grid, InvalidInputError, SynthesizedFourBar, Task, _atlas_tile

if TYPE_CHECKING:
    from typing_extensions import Unpack

    from burmester._burmester import MapOptions

__all__ = ["AtlasPair", "PivotAtlas", "pivot_atlas"]

GridArg = Union[Grid, Tuple[float, float, float, float, int, int], Sequence[float]]
Progress = Callable[[int, int], object]

#: The arrays a tile returns, in order.
_KEYS = ("valid", "count", "branch_free", "best_transmission_rad", "best_link_ratio",
         "best_margin", "best_size_ratio", "best_score", "best_driving", "best_index")

#: Driving-sample evaluations one thread does in about a second (measured:
#: about 3.8e7 with the default limits in a release build on an AVX2 CPU with
#: the SIMD per-pivot kernel, without obstacles, which cost more; fewer
#: where the CPU has no AVX2); sizes the Dask tasks.
_SAMPLES_PER_SECOND = 30_000_000

_DASK_MISSING = 'pivot_atlas(client=...) needs Dask: pip install "burmester[dask]"'

#: Seconds a Dask client without workers is given for one to join before
#: :func:`pivot_atlas` and :func:`burmester.best_pivots_batch` give up (a
#: cluster without workers would wait for ever).
DASK_WORKER_TIMEOUT = 30.0


def _require_workers(client: Any) -> None:
    """Return when the client's cluster has a worker; wait up to
    :data:`DASK_WORKER_TIMEOUT` seconds for one to join, then raise
    :class:`TimeoutError` saying so."""
    if client.scheduler_info().get("workers"):
        return
    try:
        client.wait_for_workers(1, timeout=DASK_WORKER_TIMEOUT)
    except TimeoutError:
        address = getattr(getattr(client, "scheduler", None), "address", None) or "the scheduler"
        raise TimeoutError(
            f"the Dask cluster at {address} has no workers (none joined in {DASK_WORKER_TIMEOUT:g} s), so "
            "its tasks would wait for ever: start workers (dask worker <address>), or run without client="
        ) from None


class AtlasPair(NamedTuple):
    """A driven center with its best driving center (one cell of an atlas)."""

    driven: Tuple[float, float]
    """The driven center point ``C0``."""
    driving: Tuple[float, float]
    """The best driving center point ``A0`` for it."""
    min_transmission_deg: float
    """Minimum transmission angle over the travel, degrees."""
    link_ratio: float
    """Longest over shortest link."""
    margin: float
    """The driving center's margin to the nearest branch-defect boundary."""
    n_acceptable: int
    """Acceptable driving centers of this driven center."""
    driven_index: Tuple[int, int]
    """``(j, i)`` on the driven grid."""
    driving_index: Tuple[int, int]
    """``(j, i)`` on the driving grid."""
    score: float = math.nan
    """Its score by the atlas's ranking (``PivotAtlas.rank_by``)."""
    size_ratio: float = math.nan
    """The linkage's size over the task's."""

    def linkage(self, task: Task) -> SynthesizedFourBar:
        """The four-bar of this pair for ``task`` (the atlas's task)."""
        return task.four_bar(self.driving, self.driven)


class PivotAtlas:
    """The pivot-pair atlas: NumPy arrays over the driven grid (shape
    ``(ny, nx)``; ``best_driving`` ``(ny, nx, 2)``). Where a driven center
    has no Filemon construction (``valid`` false) or no acceptable driving
    pivot, the ``best_*`` arrays hold NaN (``best_index``: -1)."""

    task: Task
    driven: Grid
    driving: Grid
    options: Dict[str, Any]
    valid: npt.NDArray[np.bool_]
    count: npt.NDArray[np.int64]
    branch_free_count: npt.NDArray[np.int64]
    best_transmission_deg: npt.NDArray[np.float64]
    best_link_ratio: npt.NDArray[np.float64]
    best_margin: npt.NDArray[np.float64]
    best_size_ratio: npt.NDArray[np.float64]
    best_score: npt.NDArray[np.float64]
    best_driving: npt.NDArray[np.float64]
    best_index: npt.NDArray[np.int64]

    def __init__(self, task: Task, driven: Grid, driving: Grid, options: Dict[str, Any],
                 arrays: Dict[str, npt.NDArray[Any]]) -> None:
        self.task, self.driven, self.driving, self.options = task, driven, driving, dict(options)
        self.best_size_ratio = arrays["best_size_ratio"]
        self.best_score = arrays["best_score"]
        self.valid = arrays["valid"]
        self.count = arrays["count"]
        self.branch_free_count = arrays["branch_free"]
        # The kernel's f32 radians, widened exactly, then converted.
        self.best_transmission_deg = np.degrees(arrays["best_transmission_rad"])
        self.best_link_ratio = arrays["best_link_ratio"]
        self.best_margin = arrays["best_margin"]
        self.best_driving = arrays["best_driving"]
        self.best_index = arrays["best_index"]

    @property
    def branch_free_fraction(self) -> npt.NDArray[np.float64]:
        """Branch-free driving samples over all driving samples (NaN where
        not valid)."""
        frac = self.branch_free_count / float(self.driving.size)
        return np.where(self.valid, frac, np.nan)

    @property
    def shape(self) -> Tuple[int, int]:
        """``(ny, nx)`` of the driven grid."""
        return self.driven.shape

    @property
    def rank_by(self) -> str:
        """What chose each cell's best driving pivot (``"balanced"``,
        ``"transmission"`` or ``"compact"``)."""
        return str(self.options.get("rank_by", "balanced"))

    #: Each array's attribute, dtype and trailing shape (after ``(ny, nx)``).
    _LAYOUT: Tuple[Tuple[str, Any, Tuple[int, ...]], ...] = (
        ("valid", np.bool_, ()), ("count", np.int64, ()), ("branch_free_count", np.int64, ()),
        ("best_transmission_deg", np.float64, ()), ("best_link_ratio", np.float64, ()),
        ("best_margin", np.float64, ()), ("best_size_ratio", np.float64, ()),
        ("best_score", np.float64, ()), ("best_driving", np.float64, (2,)), ("best_index", np.int64, (2,)),
    )

    def __setstate__(self, state: Dict[str, Any]) -> None:
        """Unpickling: the state is checked before it is taken (issue 24,
        item 7: no object holds state no atlas has)."""
        self.__dict__.clear()
        self.__dict__.update(state)
        try:
            self._check()
        except InvalidInputError:
            self.__dict__.clear()
            raise

    def _check(self) -> None:
        """Refuse state that no atlas has, with an
        :class:`~burmester.InvalidInputError` of cause
        ``"inconsistent_state"``: the types of the task and grids, every
        array's dtype and shape against the driven grid, counts within the
        driving grid, best indices inside it, the ranking's name."""
        def bad(what: str) -> InvalidInputError:
            e = InvalidInputError(f"a PivotAtlas's pickled state is inconsistent: {what}; "
                                  "unpickle only what pivot_atlas wrote")
            e.cause = "inconsistent_state"
            return e

        missing = {"task", "driven", "driving", "options"} - self.__dict__.keys()
        missing |= {name for name, _, _ in self._LAYOUT} - self.__dict__.keys()
        if missing:
            raise bad(f"it lacks {', '.join(sorted(missing))}")
        if not isinstance(self.task, Task) or not isinstance(self.driven, Grid) \
                or not isinstance(self.driving, Grid) or not isinstance(self.options, dict):
            raise bad("task, driven, driving and options must be a Task, two Grids and a dict")
        if self.options.get("rank_by", "balanced") not in ("balanced", "transmission", "compact"):
            raise bad(f"rank_by {self.options.get('rank_by')!r} is not a ranking")
        shape = self.driven.shape
        for name, dtype, tail in self._LAYOUT:
            a = getattr(self, name)
            if not isinstance(a, np.ndarray) or a.dtype != dtype or a.shape != shape + tail:
                got = f"{a.dtype} {a.shape}" if isinstance(a, np.ndarray) else type(a).__name__
                raise bad(f"{name} must be {np.dtype(dtype)} of shape {shape + tail}, got {got}")
        n = self.driving.size
        for name in ("count", "branch_free_count"):
            a = getattr(self, name)
            if a.size and (a.min() < 0 or a.max() > n):
                raise bad(f"{name} must be from 0 to the driving grid's {n} samples")
        if np.any(self.branch_free_count < self.count):
            raise bad("count (acceptable pivots) exceeds branch_free_count")
        has = self.best_index[..., 0] >= 0
        ny, nx = self.driving.shape
        if np.any(has & ~self.valid) or np.any(has & ((self.best_index[..., 0] >= ny)
                                                      | (self.best_index[..., 1] < 0)
                                                      | (self.best_index[..., 1] >= nx))):
            raise bad("best_index must index the driving grid, and only at valid cells")
        if np.any(np.isnan(self.best_score) != ~has):
            raise bad("best_score must be a number exactly where best_index is set")

    def _arrays(self) -> List[npt.NDArray[Any]]:
        return [self.valid, self.count, self.branch_free_count, self.best_transmission_deg,
                self.best_link_ratio, self.best_margin, self.best_size_ratio, self.best_score,
                self.best_driving, self.best_index]

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, PivotAtlas):
            return NotImplemented
        return (
            (self.task, self.driven, self.driving, self.options)
            == (other.task, other.driven, other.driving, other.options)
            and all(a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()
                    for a, b in zip(self._arrays(), other._arrays()))
        )

    __hash__ = None  # type: ignore[assignment]

    def best_pairs(self, k: int = 5) -> List[AtlasPair]:
        """The ``k`` best cells, best first: by their best pivot's score
        (:attr:`rank_by`), ties (scores within ``1e-9``, as the maps rank)
        by the smaller linkage, then the wider margin, then by row and
        column."""
        if k < 0:
            raise ValueError(f"k must be at least 0, got {k}")
        js, iis = np.nonzero(~np.isnan(self.best_score))
        if len(js) == 0 or k == 0:
            return []
        score = self.best_score[js, iis]
        # Scores within the tie tolerance rank alike: bucket them by runs.
        by = np.argsort(-score, kind="stable")
        run = np.zeros(len(score), dtype=np.int64)
        for n in range(1, len(by)):
            run[by[n]] = run[by[n - 1]] + int(score[by[n - 1]] - score[by[n]] > 1e-9)
        m = self.best_margin[js, iis]
        size = self.best_size_ratio[js, iis]
        order = np.lexsort((iis, js, -m, size, run))[:k]
        out = []
        for o in order:
            j, i = int(js[o]), int(iis[o])
            dj, di = (int(v) for v in self.best_index[j, i])
            out.append(AtlasPair(
                driven=self.driven.point(j, i),
                driving=(float(self.best_driving[j, i, 0]), float(self.best_driving[j, i, 1])),
                min_transmission_deg=float(self.best_transmission_deg[j, i]),
                link_ratio=float(self.best_link_ratio[j, i]),
                margin=float(self.best_margin[j, i]),
                n_acceptable=int(self.count[j, i]),
                driven_index=(j, i),
                driving_index=(dj, di),
                score=float(self.best_score[j, i]),
                size_ratio=float(self.best_size_ratio[j, i]),
            ))
        return out

    def _repr_png_(self) -> Optional[bytes]:
        """The atlas's picture for Jupyter (:func:`burmester.plot.atlas`),
        or None without matplotlib (see :mod:`burmester._display`)."""
        from burmester._display import repr_png

        return repr_png(self)

    def __repr__(self) -> str:
        n_best = int(np.count_nonzero(~np.isnan(self.best_transmission_deg)))
        top = np.nanmax(self.best_transmission_deg) if n_best else math.nan
        return (f"PivotAtlas(driven={self.driven.nx}x{self.driven.ny}, "
                f"driving={self.driving.nx}x{self.driving.ny}, valid={int(self.valid.sum())}, "
                f"with_best={n_best}, best_transmission_deg={top:.6g}, rank_by={self.rank_by!r})")


def _options(options: MapOptions, rank_by: str) -> Dict[str, Any]:
    """The keywords of :func:`_atlas_tile`: the map options with the
    defaults of those that have one spelled out, the polygons as tuples."""
    opts: Dict[str, Any] = {"link_width": 0.0, "travel_samples": 64, "rank_by": rank_by}
    opts.update((k, v) for k, v in options.items() if v is not None)
    if "base_plate" in opts:
        opts["base_plate"] = [tuple(p) for p in opts["base_plate"]]
    if "obstacles" in opts:
        opts["obstacles"] = [[tuple(p) for p in o] for o in opts["obstacles"]]
    return opts


def _tile(task: Task, driven: Grid, r0: int, r1: int, driving: Grid, opts: Dict[str, Any],
          host_threads: Dict[str, int]) -> Dict[str, npt.NDArray[Any]]:
    """One Dask task: rows ``r0..r1``, on as many rayon threads as leaves
    (Dask threads on this host) x (rayon threads) <= cores."""
    threads = 1
    try:
        distributed = importlib.import_module("distributed")
        host = distributed.get_worker().address.rsplit(":", 1)[0]
        per_host = host_threads.get(host, 1)
        threads = max(1, (os.cpu_count() or 1) // max(1, per_host))
    except (ImportError, ValueError, AttributeError):
        pass
    return dict(_atlas_tile(task, driven, r0, r1, driving, threads=threads, **opts))


def _on_dask(client: Any, task: Task, driven: Grid, driving: Grid, opts: Dict[str, Any],
             progress: Optional[Progress], tile_rows: Optional[int]) -> Dict[str, npt.NDArray[Any]]:
    try:
        distributed = importlib.import_module("distributed")
    except ImportError:
        raise ImportError(_DASK_MISSING) from None
    _require_workers(client)
    workers = client.scheduler_info().get("workers", {})
    host_threads: Dict[str, int] = {}
    for addr, w in workers.items():
        host = str(addr).rsplit(":", 1)[0]
        host_threads[host] = host_threads.get(host, 0) + int(w.get("nthreads", 1))
    total_threads = max(1, sum(host_threads.values()))
    ny = driven.ny
    if tile_rows is None:
        per_row = driven.nx * driving.size
        by_time = max(1, _SAMPLES_PER_SECOND // max(1, per_row))
        tile_rows = max(1, min(by_time, math.ceil(ny / (2 * total_threads))))
    if tile_rows < 1:
        raise ValueError(f"tile_rows must be at least 1, got {tile_rows}")
    bounds = [(r, min(r + tile_rows, ny)) for r in range(0, ny, tile_rows)]
    run = uuid.uuid4().hex
    futures = [
        client.submit(_tile, task, driven, r0, r1, driving, opts, host_threads,
                      key=f"burmester-atlas-{run}-{r0}", retries=2)
        for r0, r1 in bounds
    ]
    index = {f.key: n for n, f in enumerate(futures)}
    parts: List[Optional[Dict[str, npt.NDArray[Any]]]] = [None] * len(futures)
    done = 0
    try:
        for fut in distributed.as_completed(futures):
            n = index[fut.key]
            parts[n] = fut.result()
            done += bounds[n][1] - bounds[n][0]
            if progress is not None:
                progress(done, ny)
    except BaseException:
        client.cancel(futures)
        raise
    return {key: np.concatenate([p[key] for p in parts if p is not None], axis=0) for key in _KEYS}


def pivot_atlas(
    task: Task,
    driven: GridArg,
    driving: GridArg,
    *,
    client: Any = None,
    rank_by: str = "balanced",
    progress: Optional[Progress] = None,
    tile_rows: Optional[int] = None,
    **options: Unpack[MapOptions],
) -> PivotAtlas:
    """The pivot-pair atlas of a three-pose ``task``: for every driven center
    on ``driven``, its solution map over ``driving`` reduced (module docs).

    ``driven`` and ``driving`` are :class:`burmester.Grid` objects or
    ``(xmin, xmax, ymin, ymax, nx, ny)``. The limit keywords are those of
    :meth:`Filemon.solution_map`; ``rank_by`` chooses each driven center's
    best driving pivot (``"balanced"``, ``"transmission"`` or
    ``"compact"``). Without ``client`` it runs in this process;
    with a ``dask.distributed.Client`` it runs as Dask tasks of
    ``tile_rows`` driven rows (default: about a second each), with the same
    result bit for bit. ``progress(done_rows, total_rows)`` is called as it
    goes. Bad input raises the same errors either way, before any work. A
    client whose cluster has no workers is given
    :data:`DASK_WORKER_TIMEOUT` seconds for one to join, then
    :class:`TimeoutError` says so (its tasks would wait for ever).
    """
    dg, vg = _view.grid(driven, "driven"), _view.grid(driving, "driving")
    opts = _options(options, rank_by)
    if client is None:
        rows: Optional[Progress] = None
        if progress is not None:
            cb = progress
            # The kernel counts driving rows over all driven centers (a
            # center's map can take seconds); report driven rows, as on Dask.
            def rows(done: int, total: int) -> object:
                return cb(done * dg.ny // max(total, 1), dg.ny)
        arrays = dict(_atlas_tile(task, dg, 0, dg.ny, vg, progress=rows, **opts))
    else:
        try:
            importlib.import_module("distributed")
        except ImportError:
            raise ImportError(_DASK_MISSING) from None
        # Validates the task and the options here, with in-process errors.
        _atlas_tile(task, dg, 0, 0, vg, **opts)
        arrays = _on_dask(client, task, dg, vg, opts, progress, tile_rows)
    return PivotAtlas(task, dg, vg, opts, arrays)
