"""Shared fixtures: the built-in example task, its driven crank and view."""

import pytest

import burmester

#: The example's poses (x, y, angle in radians), driven center and view.
POSES = [(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)]
C0 = (4.0, -1.0)
VP = (-8.0, 8.0, -8.0, 8.0)


@pytest.fixture
def task():
    """The example task."""
    return burmester.Task(POSES)


@pytest.fixture
def f(task):
    """Filemon's construction of the example's driven crank."""
    return task.filemon(C0)


@pytest.fixture(scope="module")
def client():
    """A real Dask cluster (worker processes, not the synchronous
    scheduler), one per test module: a module that kills a worker does not
    share its cluster. Skips when Dask is not installed."""
    distributed = pytest.importorskip("distributed")
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None)
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()
