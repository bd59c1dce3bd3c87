"""Ctrl-C and progress: a long sweep stops within a fraction of a second
with KeyboardInterrupt, says what it left in out=, and the progress hook
sees the same samples as one call without it."""

import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import burmester
from burmester import Grid
from conftest import C0, POSES, VP, interrupt_child

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")

#: The child: starts a sweep that takes seconds, says so, and reports the
#: KeyboardInterrupt it gets (then lets it end the process).
CHILD = textwrap.dedent(
    """
    import json, sys, time
    import numpy as np
    import burmester
    POSES, C0, VP = {poses!r}, {c0!r}, {vp!r}
    f = burmester.Task(POSES).filemon(C0)
    kind, use_out = sys.argv[1], sys.argv[2] == "out"
    if kind == "branch":
        g = burmester.Grid(*VP, 3000, 3000)     # "simulate" drives each linkage: about 15 s
        out = np.zeros(g.shape, dtype=bool) if use_out else None
        run = lambda: f.branch_map(g, "simulate", out=out)
    elif kind == "margin":
        g = burmester.Grid(*VP, 3000, 3000)
        out = np.full(g.shape, 7.0, dtype=np.float32) if use_out else None
        run = lambda: [f.margin_map(g, out=out) for _ in range(2000)]   # many short calls: seconds
    else:
        g = burmester.Grid(*VP, 600, 600)       # clearance over 256 travel samples: about 20 s
        obstacle = [(-1.0, -3.0), (0.5, -3.0), (0.5, -2.0), (-1.0, -2.0)]
        run = lambda: f.solution_map(g, obstacles=[obstacle], link_width=0.3, travel_samples=256)
    print("started", flush=True)
    t0 = time.monotonic()
    try:
        run()
    except KeyboardInterrupt as e:
        done = None
        if use_out and kind == "branch":
            done = int(out.any(axis=1).sum())
        print(json.dumps({{"message": str(e), "ran": time.monotonic() - t0, "rows_touched": done}}), flush=True)
        raise
    print(json.dumps({{"finished": time.monotonic() - t0}}), flush=True)
    """
).format(poses=POSES, c0=C0, vp=VP)


def interrupt(kind, out="none", after=0.3):
    """Run the child, send SIGINT ``after`` seconds into the sweep: (report,
    seconds from the signal to the report, return code, stderr)."""
    return interrupt_child(CHILD, kind, out, after=after)


@pytest.mark.parametrize("kind", ["branch", "solution"])
def test_ctrl_c_stops_a_long_sweep_within_half_a_second(kind):
    report, latency, code, err = interrupt(kind)
    assert "finished" not in report, "the sweep ended before the signal; make it longer"
    assert latency < 0.5, latency
    # The process ends by the KeyboardInterrupt (Python re-raises SIGINT to exit).
    assert code == -signal.SIGINT and "KeyboardInterrupt" in err
    done, total = map(int, report["message"].split("interrupted after ")[1].split(" rows")[0].split(" of "))
    assert 0 <= done < total, report
    assert "partial" not in report["message"]  # nothing of the caller's was written


def test_ctrl_c_says_what_it_left_in_out():
    report, latency, code, err = interrupt("branch", "out")
    assert latency < 0.5, latency
    assert code == -signal.SIGINT
    msg = report["message"]
    assert "out holds a partial result" in msg and "keep their old values" in msg
    done, total = map(int, msg.split("interrupted after ")[1].split(" rows")[0].split(" of "))
    assert done < total == 3000
    # The rows it names as done may hold results; none beyond them was written.
    assert report["rows_touched"] <= done


def test_ctrl_c_between_short_calls_is_a_plain_keyboard_interrupt():
    report, latency, code, err = interrupt("margin", "out")
    assert latency < 0.5, latency
    assert code == -signal.SIGINT and "KeyboardInterrupt" in err


def test_progress_sees_every_row_and_the_same_samples():
    f = burmester.Task(POSES).filemon(C0)
    g = Grid(*VP, 2048, 3001)
    calls = []
    m = f.branch_map(g, "direct", progress=lambda done, total: calls.append((done, total)))
    assert np.array_equal(m, f.branch_map(g, "direct"))
    assert calls[-1] == (3001, 3001) and len(calls) >= 2
    assert all(t == 3001 for _, t in calls) and [d for d, _ in calls] == sorted(d for d, _ in calls)
    s = f.solution_map(Grid(*VP, 900, 700), progress=lambda d, t: None)
    assert s == f.solution_map(Grid(*VP, 900, 700))


def test_an_exception_in_the_progress_hook_stops_the_sweep():
    f = burmester.Task(POSES).filemon(C0)

    def hook(done, total):
        raise RuntimeError(f"stop at {done} of {total}")

    out = np.zeros((3000, 3000), dtype=bool)
    t0 = time.monotonic()
    with pytest.raises(RuntimeError, match="stop at"):
        f.branch_map(Grid(*VP, 3000, 3000), "simulate", out=out, progress=hook)
    assert time.monotonic() - t0 < 2.0  # not the whole sweep (about 15 s)


#: The child of the first-call test: nothing of NumPy's C API used yet when
#: the first array-returning call starts.
FIRST_CALL = textwrap.dedent(
    """
    import sys
    import burmester
    f = burmester.Task({poses!r}).filemon({c0!r})
    g = burmester.Grid(*{vp!r}, 400, 400)
    print("started", flush=True)
    try:
        for _ in range(200):
            f.branch_map(g, "direct")
    except KeyboardInterrupt:
        print("interrupted", flush=True)
        sys.exit(0)
    print("finished", flush=True)
    """
).format(poses=POSES, c0=C0, vp=VP)


@pytest.mark.parametrize("after", [0.0, 0.001, 0.005, 0.02])
def test_ctrl_c_during_the_first_array_call_of_a_process_is_a_keyboard_interrupt(after):
    # Once: "PanicException: Failed to access NumPy array API capsule", which
    # `except Exception` does not catch (NumPy's API was loaded lazily, inside
    # the first call, with the signal pending). It is loaded at import now.
    p = subprocess.Popen(
        [sys.executable, "-c", FIRST_CALL], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
        text=True, cwd=os.path.dirname(__file__),
    )
    try:
        assert p.stdout.readline().strip() == "started", p.stderr.read()
        time.sleep(after)
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            p.kill()
    assert "Panic" not in err and "panicked" not in err, err
    assert p.returncode == 0 and out.strip() == "interrupted", (p.returncode, out, err)


#: The child for burmester.design: a search that takes seconds (the coarse
#: pass at its largest grids, then many refinements), interrupted in the
#: coarse pass or in the refinement.
DESIGN_CHILD = textwrap.dedent(
    """
    import json, sys, time
    import burmester
    t = burmester.Task({poses!r})
    said = []

    def progress(done, total):
        if done > 800 and not said:
            said.append(print("refining", flush=True))

    if sys.argv[1] == "coarse":
        kw = dict(coarse_driven=64, coarse_driving=256, starts=4)
    else:
        # A quick coarse pass, then 1000 refinements of 20000 iterations.
        kw = dict(coarse_driven=16, coarse_driving=32, starts=1000, min_separation=0.0,
                  max_iterations=20000, progress=progress)
    print("started", flush=True)
    t0 = time.monotonic()
    try:
        burmester.design(t, **kw)
    except KeyboardInterrupt as e:
        print(json.dumps({{"message": str(e), "ran": time.monotonic() - t0}}), flush=True)
        raise
    print(json.dumps({{"finished": time.monotonic() - t0}}), flush=True)
    """
).format(poses=POSES)


@pytest.mark.parametrize("phase", ["coarse", "refine"])
def test_ctrl_c_stops_design_within_half_a_second(phase):
    # With "refine", the progress hook says when the refinement has begun.
    ready = ["refining"] if phase == "refine" else []
    report, latency, returncode, err = interrupt_child(DESIGN_CHILD, phase, ready=ready)
    assert "finished" not in report, "the search ended before the signal; make it longer"
    assert latency < 0.5, latency
    assert returncode == -signal.SIGINT and "KeyboardInterrupt" in err
