"""Shared fixtures: the built-in example task, its driven crank and view."""

import json
import math
import os
import signal
import subprocess
import sys
import threading
import time

import pytest
from hypothesis import settings

import burmester

# Hypothesis draws the same examples on every run of the test command (the
# README's, which CI runs): a run's verdict depends on the code, not on the
# draw. Set BURMESTER_EXPLORE=1 to draw fresh examples (a search for new
# cases, as the fuzz rounds are); a case found that way is pinned as a test
# of its own.
settings.register_profile("reproducible", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile("explore" if os.environ.get("BURMESTER_EXPLORE") else "reproducible")

#: The example's poses (x, y, angle in radians), driven center and view.
POSES = [(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)]
C0 = (4.0, -1.0)
VP = (-8.0, 8.0, -8.0, 8.0)

#: Four poses of a crank-rocker's coupler (pivots (0, 0) and (4, 0); the
#: notes' worked example and the README's).
FOUR = [(1.049199280691, 2.279426358634, math.radians(45.220037141544)),
        (0.734502065472, 3.198658887874, math.radians(26.633426990744)),
        (-0.378159188147, 3.063048993013, math.radians(21.786789298262)),
        (-1.268710439724, 2.051150142014, math.radians(27.048624103934))]


def circumcenter(a, b, c):
    """The center of the circle through the points ``a``, ``b``, ``c``
    (the tests' own construction, independent of the crate's)."""
    ux, uy = b[0] - a[0], b[1] - a[1]
    vx, vy = c[0] - a[0], c[1] - a[1]
    d = 2.0 * (ux * vy - uy * vx)
    uu, vv = ux * ux + uy * uy, vx * vx + vy * vy
    return (a[0] + (vy * uu - uy * vv) / d, a[1] + (ux * vv - vx * uu) / d)


#: How long a child of :func:`interrupt_child` may take, beyond its wait
#: and its timeout, before the watchdog kills it (a loaded machine starts
#: an interpreter and imports burmester in seconds, not minutes).
CHILD_WATCHDOG_S = 180.0


def interrupt_child(child, *args, after=0.3, timeout=60, ready=()):
    """Run ``python -c child *args`` here, wait for its line ``started``
    (then for each line of ``ready`` in turn), send it SIGINT ``after``
    seconds later and read the line it reports: (that line as JSON,
    seconds from the signal to the line, return code, stderr). A child not done
    ``CHILD_WATCHDOG_S + after + timeout`` seconds after its start (one that
    ignores SIGINT, say) is killed and the test fails: it never hangs the
    suite."""
    p = subprocess.Popen([sys.executable, "-c", child, *args], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, cwd=os.path.dirname(__file__))
    # The reads below block: a watchdog kills a child that stops answering,
    # which ends them with an empty line.
    watchdog = threading.Timer(CHILD_WATCHDOG_S + after + timeout, p.kill)
    watchdog.start()
    try:
        assert p.stdout.readline().strip() == "started", p.stderr.read()
        for expected in ready:
            assert p.stdout.readline().strip() == expected, p.stderr.read()
        time.sleep(after)
        sent = time.monotonic()
        p.send_signal(signal.SIGINT)
        line = p.stdout.readline()
        latency = time.monotonic() - sent
        _, err = p.communicate(timeout=timeout)
    finally:
        watchdog.cancel()
        if p.poll() is None:
            p.kill()
    assert line, f"the child gave no line after SIGINT (killed by the watchdog?): {err}"
    return json.loads(line), latency, p.returncode, err


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


def task_toml(poses, driven, x, y, grid, units=None, sep="\n"):
    """The text of a task file (TOML) of three or more ``poses`` ``(x, y,
    angle_deg)``, the driven pivot and the view, numbers as Python writes
    them; ``sep`` between the tables (``"\\n"`` for a blank line, ``""`` for
    none). The one writer of the tests' task files (the parser's own tests
    keep their literal text)."""
    tables = [f'units = "{units}"\n'] if units is not None else []
    tables += [f"[[pose]]\nx = {px!r}\ny = {py!r}\nangle_deg = {a!r}\n" for px, py, a in poses]
    tables.append(f"[driven]\ncenter = [{driven[0]!r}, {driven[1]!r}]\n")
    tables.append(f"[view]\nx = [{x[0]!r}, {x[1]!r}]\ny = [{y[0]!r}, {y[1]!r}]\ngrid = [{grid[0]}, {grid[1]}]\n")
    return sep.join(tables)
