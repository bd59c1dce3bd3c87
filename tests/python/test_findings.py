"""The adversary's findings of issue 15, one test each (or a pointer to the
test that holds it): nothing aborts, no panic reaches Python, every work
parameter is bounded, and bad input is a typed error whose message helps."""

import math
import subprocess
import sys
import textwrap
import threading

import numpy as np
import pytest

import burmester
from burmester import Grid, InvalidInputError, Task
from burmester.taskfile import example


@pytest.fixture(scope="module")
def f():
    return example().filemon()


# 1. The interpreter aborts -------------------------------------------------


@pytest.mark.parametrize("tolerance", [1e-16, 1e-15, 1e-12])
def test_polylines_refuse_a_tolerance_finer_than_1e_9_of_the_view(f, tolerance):
    # Once 4 GiB asked for and an abort (1e-16), or 80 M points after 10 s (1e-15).
    with pytest.raises(InvalidInputError, match=r"1e-9 to 1 times the viewport's diagonal") as e:
        f.conics[0].polylines(-8, 8, -8, 8, tolerance)
    assert e.value.cause == "outside_range"
    # The finest tolerance allowed still returns a bounded answer.
    diag = math.hypot(16, 16)
    lines = f.conics[0].polylines(-8, 8, -8, 8, 1e-9 * diag)
    assert 0 < sum(len(p) for p in lines) <= 10**7


MEMORY_CHILD = textwrap.dedent(
    """
    import resource, sys
    import burmester
    from burmester.taskfile import example
    f = example().filemon()
    resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))  # a 2 GiB address space
    for name, call in [
        ("solution_map", lambda: f.solution_map(burmester.Grid(-8, 8, -8, 8, 20000, 20000))),
        ("branch_map", lambda: f.branch_map(burmester.Grid(-8, 8, -8, 8, 60000, 60000))),
        ("margin_map", lambda: f.margin_map(burmester.Grid(-8, 8, -8, 8, 40000, 40000))),
    ]:
        try:
            call()
        except MemoryError as e:
            print(name, "MemoryError", str(e)[:200], flush=True)
        else:
            print(name, "returned", flush=True)
    """
)


@pytest.mark.skipif(sys.platform != "linux", reason="RLIMIT_AS")
def test_maps_too_large_for_memory_raise_memory_error_not_abort():
    # Once "memory allocation of ... failed" and an abort for solution_map.
    p = subprocess.run([sys.executable, "-c", MEMORY_CHILD], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr[-2000:]
    lines = p.stdout.strip().splitlines()
    assert [ln.split()[:2] for ln in lines] == [
        ["solution_map", "MemoryError"], ["branch_map", "MemoryError"], ["margin_map", "MemoryError"],
    ], p.stdout


# 2. A panic reaches Python: tests/python/test_interrupt.py
#    (test_ctrl_c_during_the_first_array_call_of_a_process_is_a_keyboard_interrupt).


# 3. Work without bounds ----------------------------------------------------


@pytest.mark.parametrize("samples", [10**7, 4097, 1, 0])
def test_travel_samples_are_bounded(f, samples):
    # Once 10**7 ran for minutes and could not be interrupted.
    with pytest.raises(InvalidInputError, match="travel_samples must be from 2 to 4096") as e:
        f.solution_map(Grid(-1, 1, -1, 1, 3, 3), travel_samples=samples)
    assert e.value.cause == "count_out_of_range"
    f.solution_map(Grid(-1, 1, -1, 1, 3, 3), travel_samples=4096)  # the bound itself


# `burmester solve --step 1e-9`: tests/python/test_cli.py (test_solve_bad_input).


# 4. Clearance between samples: tests/rust/design.rs checks every accepted
#    pivot against dense driving of the built linkage; here, from Python, a
#    pivot accepted with an obstacle is clear at 800 angles of its travel
#    (the finding: one pivot collided at 62 of 5,000 dense angles and at none
#    of the 64 samples then checked).


def _segment_distance(p, a, b):
    ab = b - a
    t = np.clip(np.dot(p - a, ab) / max(np.dot(ab, ab), 1e-300), 0.0, 1.0)
    return float(np.linalg.norm(p - (a + t * ab)))


def test_accepted_pivots_clear_the_obstacle_over_the_whole_travel(f):
    obstacle = [(-1.0, -3.0), (0.5, -3.0), (0.5, -2.0), (-1.0, -2.0)]
    width = 0.3
    g = Grid(-8, 8, -8, 8, 24, 24)
    m = f.solution_map(g, obstacles=[obstacle], link_width=width)
    free = f.solution_map(g)
    ok = np.argwhere(m.acceptable)
    assert len(ok) > 5 and (free.acceptable & ~m.acceptable).any()  # the obstacle bites
    corners = np.array(obstacle)
    box = (corners.min(axis=0), corners.max(axis=0))
    for j, i in ok[:: max(1, len(ok) // 8)]:
        sfb = f.four_bar(g.point(int(j), int(i)))
        stops = sfb.travel_stops
        mode = sfb.modes[0]
        for theta in np.linspace(stops[0], stops[-1], 800):
            o2, a, b, o4 = (np.array(q) for q in sfb.fourbar.joints(float(theta), mode))
            for s0, s1 in ((o2, a), (a, b), (b, o4)):
                # Distance from the link's axis to the obstacle (a box): no
                # corner and no box edge point within half the width.
                for k in range(4):
                    c0, c1 = corners[k], corners[(k + 1) % 4]
                    for q in (s0, s1):
                        assert _segment_distance(q, c0, c1) > width / 2 - 1e-9 or not (
                            box[0][0] <= q[0] <= box[1][0] and box[0][1] <= q[1] <= box[1][1]
                        )
                    assert _segment_distance(c0, s0, s1) > width / 2 - 1e-9, (j, i, theta)


# 6. NaN out, or bad input accepted (see also test_robustness.py) ------------


@pytest.mark.parametrize("width", [math.nan, math.inf, -1.0])
def test_link_width_is_checked_without_obstacles_too(f, width):
    with pytest.raises(InvalidInputError, match="link_width must be between 0 and 1e100"):
        f.solution_map(Grid(-1, 1, -1, 1, 3, 3), link_width=width)


def test_a_self_intersecting_base_plate_is_refused(f):
    with pytest.raises(InvalidInputError, match="two of its edges cross"):
        f.solution_map(Grid(-1, 1, -1, 1, 3, 3), base_plate=[(0, 0), (2, 2), (2, 0), (0, 2)])


# 7. Messages that do not help ----------------------------------------------


@pytest.mark.parametrize(
    "out, words",
    [
        (np.zeros((3, 3)), "out has dtype float64 (native), but this map is written as bool"),
        (np.zeros((3, 3), dtype=">f8"), "swapped byte order"),
        (np.zeros((3, 3, 1), dtype=bool), "shape"),
    ],
)
def test_out_arrays_of_the_wrong_kind_say_what_to_pass(f, out, words):
    with pytest.raises(InvalidInputError) as e:
        f.branch_map(Grid(-1, 1, -1, 1, 3, 3), out=out)
    assert words in str(e.value) and "ndarray' object is not an instance" not in str(e.value)


def test_task_of_a_string_says_what_a_task_takes():
    with pytest.raises(TypeError, match="a task takes a sequence of poses") as e:
        Task("abc")
    assert "Can't extract" not in str(e.value)


def test_numbers_in_messages_are_short(f):
    with pytest.raises(InvalidInputError) as e:
        Grid(1e308, -1e308, 0, 1, 3, 3)
    assert len(str(e.value)) < 200, str(e.value)


def test_a_finite_input_is_not_called_infinite(f):
    with pytest.raises(InvalidInputError) as e:
        f.four_bar((1e200, 0))
    assert "overflows" in str(e.value) and "got inf" not in str(e.value)


def test_one_out_array_from_several_threads_says_it_is_in_use(f):
    out = np.zeros((300, 300), dtype=bool)
    g = Grid(-8, 8, -8, 8, 300, 300)
    errors = []

    def run():
        try:
            f.branch_map(g, "direct", out=out)
        except InvalidInputError as e:
            errors.append(str(e))

    threads = [threading.Thread(target=run) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for e in errors:  # whichever calls overlapped
        assert "being written by another call" in e and "pass a writeable array" not in e
    assert np.array_equal(out, f.branch_map(g, "direct"))


# 8. CLI and plotting: tests/python/test_cli.py and test_plot.py.
# 9. Copies of large inputs: tests/python/test_memory.py.
