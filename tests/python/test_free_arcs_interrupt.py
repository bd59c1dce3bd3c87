"""Ctrl-C in ``Task.branch_free_arcs`` (issue 24 item 10): on a degenerate
task whose center-point trace in view has about a million vertices (a second
or more a call), SIGINT stops the call itself with KeyboardInterrupt."""

import signal
import sys
import textwrap

import pytest

from conftest import interrupt_child

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")

#: ``fuzz/open/curves/slow-1.5-s-free-arcs-was-0.9-s-454464bc``: poses,
#: driven center and view.
SLOW_POSES = [
    (130.2796224988182, 78.12500000555079, 3.981436403589793),
    (6.625753534563728, 78.12500000555079, -74.9834073464102),
    (156.0410816761015, 78.12500000555079, 3.068444216089793),
    (83.79937388360848, 78.12500000555079, -17.2060635964063),
]
SLOW_C0 = (74.11694667838805, 72.28322417205871)
SLOW_VIEW = (73.24133963475096, 74.99255372202514, 71.40761712842162, 73.1588312156958)

#: The child: calls ``branch_free_arcs`` on the slow task over and over
#: (each call is one traced million vertices), says so, and reports the
#: KeyboardInterrupt it gets.
CHILD = textwrap.dedent(
    """
    import json, time
    import burmester
    task = burmester.Task({poses!r})
    c0, view = {c0!r}, {view!r}
    t0 = time.monotonic()
    task.branch_free_arcs(c0, *view)
    one = time.monotonic() - t0
    print("started", flush=True)
    t0 = time.monotonic()
    try:
        for _ in range(1000):
            task.branch_free_arcs(c0, *view)
    except KeyboardInterrupt as e:
        print(json.dumps({{"message": str(e), "one": one}}), flush=True)
        raise
    print(json.dumps({{"finished": time.monotonic() - t0}}), flush=True)
    """
).format(poses=SLOW_POSES, c0=SLOW_C0, view=SLOW_VIEW)


def test_ctrl_c_stops_branch_free_arcs():
    report, latency, code, err = interrupt_child(CHILD, after=0.5)
    assert "finished" not in report, "the calls ended before the signal"
    # The interrupt came from inside the call (its watcher says how far it
    # got), not from the interpreter between two calls.
    msg = report["message"]
    assert msg.startswith("interrupted"), msg
    if " of " in msg:
        done, total = map(int, msg.split("interrupted after ")[1].split(" traced")[0].split(" of "))
        assert 0 <= done < total, msg
    # The trace itself (about half of a call) is not polled: the call stops
    # at its first check after it, well before a whole call's time.
    assert latency < max(1.0, report["one"]), (latency, report["one"])
    assert code == -signal.SIGINT and "KeyboardInterrupt" in err

