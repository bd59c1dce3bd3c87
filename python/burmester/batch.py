"""Batches of three-pose tasks: each task's best driving pivots.

:func:`best_pivots_batch` takes task files (paths) or
:class:`burmester.taskfile.TaskSpec` objects (a :class:`burmester.Task`
with its driven center, view and limits) and returns, for each, the JSON
document of ``burmester pivots --json`` (:func:`burmester.pivots.report`:
the ranking is the core's :meth:`burmester.SolutionMap.best_pivots`). A
task that cannot be done gives ``{"task": ..., "error": message}`` in its
place, and the others still run.

Without ``client`` the tasks run one after another in this process (each
solution map on all cores); with ``client=`` a ``dask.distributed.Client``,
one Dask task per task, each calling the same in-process code on a worker,
so both give the same records. Task files are read here, so the workers
need not see them.
"""

from __future__ import annotations

import importlib
import os
import uuid
from typing import TYPE_CHECKING, Any, Dict, List, Optional, Sequence, Union

from burmester import pivots as pv
from burmester import taskfile
from burmester.taskfile import TaskSpec

if TYPE_CHECKING:
    from burmester._burmester import RankBy

__all__ = ["BatchItem", "best_pivots_batch"]

#: A task of a batch: the path of a task file, or a loaded task.
BatchItem = Union[str, "os.PathLike[str]", TaskSpec]

_DASK_MISSING = 'best_pivots_batch(client=...) needs Dask: pip install "burmester[dask]"'


def _source(item: BatchItem) -> str:
    return item.source if isinstance(item, TaskSpec) else os.fspath(item)


def _error(source: str, e: BaseException) -> Dict[str, Any]:
    return {"task": source, "error": str(e)}


def _one(spec: TaskSpec, top: int, spacing: Optional[float], rank_by: "RankBy" = "balanced") -> Dict[str, Any]:
    """One task's record (also the body of one Dask task)."""
    try:
        return pv.report(spec, top, spacing, rank_by=rank_by)
    except (ValueError, MemoryError) as e:  # TaskFileError, BurmesterError, ...
        if isinstance(e, MemoryError):
            return {"task": spec.source, "error": "not enough memory for this task's view; use a coarser grid"}
        return _error(spec.source, e)


def best_pivots_batch(
    specs: Sequence[BatchItem],
    *,
    client: Any = None,
    top: int = 5,
    spacing: Optional[float] = None,
    rank_by: "RankBy" = "balanced",
) -> List[Dict[str, Any]]:
    """The ``top`` best driving pivots of each task, in the order given.

    Each record is the document of ``burmester pivots --json`` for that task
    (keys ``task``, ``view``, ``limits``, ``spacing``, ``ranking``,
    ``pivots``), or ``{"task": ..., "error": message}`` when its file cannot
    be loaded or its task cannot be done (four or five poses, a degenerate
    task). ``spacing`` is the least distance between listed pivots (default:
    a tenth of each view's shorter side); ``rank_by`` the ranking (see
    :meth:`burmester.SolutionMap.best_pivots`). With ``client`` (a
    ``dask.distributed.Client``) one Dask task per task; the records are the
    same.
    """
    if top < 1:
        raise ValueError(f"top must be at least 1, got {top}")
    if spacing is not None and not spacing >= 0.0:
        raise ValueError(f"spacing must be at least 0, got {spacing:g}")
    pv.check_ranking(rank_by)
    loaded: List[Union[TaskSpec, Dict[str, Any]]] = []
    for item in specs:
        if isinstance(item, TaskSpec):
            loaded.append(item)
            continue
        try:
            loaded.append(taskfile.load(os.fspath(item)))
        except ValueError as e:
            loaded.append(_error(_source(item), e))
    if client is None:
        return [_one(s, top, spacing, rank_by) if isinstance(s, TaskSpec) else s for s in loaded]
    try:
        importlib.import_module("distributed")
    except ImportError:
        raise ImportError(_DASK_MISSING) from None
    from burmester.atlas import _require_workers

    _require_workers(client)
    run = uuid.uuid4().hex
    futures = {
        n: client.submit(_one, s, top, spacing, rank_by, key=f"burmester-batch-{run}-{n}", retries=2)
        for n, s in enumerate(loaded) if isinstance(s, TaskSpec)
    }
    try:
        done = dict(zip(futures, client.gather(list(futures.values()))))
    except BaseException:
        client.cancel(list(futures.values()))
        raise
    return [done[n] if isinstance(s, TaskSpec) else s for n, s in enumerate(loaded)]
