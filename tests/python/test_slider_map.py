"""The solution map with a slider driven dyad (``SliderFilemon.solution_map``)
and the ``simulate`` branch method for it, checked against driving the built
slider-crank with the solver written in ``test_slider_branch`` (a press in
millimetres made from a known slider-crank), the slider-crank's own figures,
moving and scaling the task, pickling, typed errors and the picture."""

import math
import pickle

import numpy as np
import pytest

from burmester import Grid, InvalidInputError, SliderFilemon, SolutionMap, Task
from test_slider_branch import A0, L, PHIS, R, U, _displace, _drive, _parts, _press_task

# 41 x 41 driving pivots 15 mm apart, A0 = (0, 0) on the middle sample.
GRID = (-307.5, 307.5, -307.5, 307.5, 41, 41)
MID = 20


@pytest.fixture(scope="module")
def press():
    task, b1 = _press_task()
    f = SliderFilemon(task, b1, U)
    return task, b1, f, f.solution_map(Grid(*GRID))


def test_the_generating_crank_is_acceptable(press):
    task, b1, f, m = press
    assert m.point(MID, MID) == (0.0, 0.0)
    assert m.fixed_kind == "slider" and m.varying == "driving"
    assert m.fixed_dyad[0] == b1 and m.fixed_dyad[1] == pytest.approx(U, rel=1e-15)
    assert m.valid[MID, MID] and m.branch_free[MID, MID] and m.acceptable[MID, MID]
    sc = m.slider_crank(MID, MID)
    assert sc.linkage.crank == pytest.approx(R, rel=1e-9)
    assert sc.linkage.coupler == pytest.approx(L, rel=1e-9)
    assert sc.driving[0] == A0 and sc.feasible
    # Grashof's law is a four-bar's: 255 everywhere.
    assert (m.grashof == 255).all()


def _walk_direction(a0, a1, b1, poses):
    """The crank rotation (1, -1, 0) that meets the poses in order from
    pose 1 with the loop closed, walking every 2e-3 rad; None within 1e-6
    l^2 of a dead position."""
    r, l = math.dist(a0, a1), math.dist(a1, b1)
    phis = []
    for k in range(len(poses)):
        a = _displace(poses, k, a1)
        phis.append(math.atan2(a[1] - a0[1], a[0] - a0[0]))
    found = 0
    for d in (1, -1):
        dist = [((p - phis[0]) * d) % (2 * math.pi) for p in phis]
        n = max(1, math.ceil(dist[-1] / 2e-3))
        low = min(_parts(a0, r, l, b1, U, phis[0] + d * dist[-1] * s / n)[1] for s in range(n + 1))
        if abs(low) <= 1e-6 * l * l:
            return None
        if all(x < y for x, y in zip(dist, dist[1:])) and low > 0:
            found = d
    return found


def test_branch_order_and_simulate_agree_with_driving(press):
    task, b1, f, m = press
    poses = task.poses
    counts = dict(branch=0, simulate=0, direction=0, circuit=0)
    for j in range(41):
        for i in range(41):
            if not m.valid[j, i]:
                continue
            a0 = m.point(j, i)
            a1 = task.circle_point(a0)
            if math.dist(a0, a1) > 1e5:
                continue
            verdict = _drive(poses, a0, a1, b1, U)
            if verdict is None:
                continue
            assert m.branch_free[j, i] == (verdict != "defective"), (a0, verdict)
            counts["branch"] += 1
            sim = f.classify(a0, "simulate")
            assert (sim == "free") == (verdict == "free"), (a0, verdict, sim)
            # simulate is the exact map's branch flag and circuit flag.
            assert (sim == "free") == bool(m.branch_free[j, i] and m.one_circuit[j, i])
            counts["simulate"] += 1
            counts["circuit"] += verdict == "circuit"
            if (j + i) % 3 == 0:
                d = _walk_direction(a0, a1, b1, poses)
                if d is not None:
                    assert m.direction[j, i] == d, a0
                    counts["direction"] += 1
    print(counts)
    assert counts["branch"] > 1000 and counts["direction"] > 300
    sim_map = f.branch_map(Grid(*GRID), method="simulate")
    assert ((sim_map & ~m.branch_free) == False).all()  # noqa: E712


def test_columns_are_the_slider_cranks_figures(press):
    task, _, _, m = press
    seen = 0
    for j in range(0, 41, 3):
        for i in range(0, 41, 3):
            if not m.valid[j, i]:
                with pytest.raises(InvalidInputError):
                    m.slider_crank(j, i)
                continue
            sc = m.slider_crank(j, i)
            lk = sc.linkage
            assert m.input_full[j, i] == lk.turns_fully
            assert m.direction[j, i] == {"ccw": 1, "cw": -1, "none": 0}[sc.direction]
            assert m.one_circuit[j, i] == sc.one_circuit
            mu = sc.min_transmission_deg
            if mu is None:
                assert math.isnan(m.min_transmission_rad[j, i])
            else:
                assert math.degrees(m.min_transmission_rad[j, i]) == pytest.approx(mu, rel=1e-6)
            assert m.link_ratio[j, i] == pytest.approx(lk.link_ratio, rel=1e-6)
            assert m.size_ratio[j, i] == pytest.approx(sc.size_ratio, rel=1e-6)
            seen += 1
    assert seen > 100


def test_limits_and_base_plate(press):
    task, b1, f, m = press
    rocker = f.solution_map(Grid(*GRID), input="rocker")
    assert not (rocker.acceptable & m.input_full).any()
    crank = f.solution_map(Grid(*GRID), input="crank")
    assert (crank.acceptable <= m.input_full).all() and crank.acceptable[MID, MID]
    short = f.solution_map(Grid(*GRID), limits=None, min_transmission_deg=89.0)
    assert not short.acceptable.any()
    plate = [(-40.0, -40.0), (40.0, -40.0), (40.0, 40.0), (-40.0, 40.0)]
    held = f.solution_map(Grid(*GRID), base_plate=plate)
    xs, ys = Grid(*GRID).cell_centers()
    inside = (np.abs(xs)[None, :] < 40) & (np.abs(ys)[:, None] < 40)
    assert (held.acceptable == (m.acceptable & inside)).all() and held.acceptable[MID, MID]


def test_invariant_under_moving_and_scaling(press):
    task, b1, f, m = press
    s, t = 1e-3, (2.5, -1.25)  # millimetres to metres, moved
    move = lambda p: (p[0] * s + t[0], p[1] * s + t[1])  # noqa: E731
    task2 = Task([(*move(p[:2]), p[2]) for p in task.poses])
    f2 = SliderFilemon(task2, move(b1), U)
    g = GRID
    m2 = f2.solution_map(Grid(g[0] * s + t[0], g[1] * s + t[0], g[2] * s + t[1], g[3] * s + t[1], 41, 41))
    for name in ("valid", "branch_free", "input_full", "direction", "one_circuit", "acceptable"):
        diff = int((getattr(m, name) != getattr(m2, name)).sum())
        assert diff <= 2, (name, diff)  # a sample within rounding of a curve at most
    both = m.valid & m2.valid & np.isfinite(m.min_transmission_rad) & np.isfinite(m2.min_transmission_rad)
    assert both.sum() > 500
    for name in ("min_transmission_rad", "link_ratio", "size_ratio"):
        np.testing.assert_allclose(getattr(m, name)[both], getattr(m2, name)[both], rtol=1e-4, atol=1e-5)


def test_pickles_to_an_equal_object(press):
    _, _, _, m = press
    for protocol in range(2, pickle.HIGHEST_PROTOCOL + 1):
        back = pickle.loads(pickle.dumps(m, protocol=protocol))
        assert type(back) is SolutionMap and back == m and repr(back) == repr(m)
        assert back.fixed_kind == "slider" and back.fixed_dyad == m.fixed_dyad
        assert back.slider_crank(MID, MID) == m.slider_crank(MID, MID)


def test_errors_are_typed(press):
    task, b1, f, m = press
    # Obstacles are checked over the slider-crank's travel now
    # (test_slider_rank); a Pivot still carries a four-bar.
    for call in (lambda: m.linkage(MID, MID), lambda: m.best_pivots(3), lambda: m.pareto_front()):
        with pytest.raises(InvalidInputError) as e:
            call()
        assert e.value.cause == "driven_kind" and "slider" in str(e.value)
        assert isinstance(e.value, ValueError)
    revolute = task.filemon((300.0, -200.0)).solution_map(Grid(*GRID))
    assert revolute.fixed_kind == "revolute"
    with pytest.raises(InvalidInputError) as e:
        revolute.slider_crank(MID, MID)
    assert e.value.cause == "driven_kind" and "revolute" in str(e.value)
    with pytest.raises(InvalidInputError):
        m.slider_crank(41, 0)
    with pytest.raises(InvalidInputError):
        f.solution_map(Grid(*GRID), min_transmission_deg=95.0)
    # A damaged pickle: a zero guide.
    state = m.__reduce__()[1]
    bad = list(state)
    bad[3] = (bad[3][0], (0.0, 0.0))
    with pytest.raises(InvalidInputError) as e:
        SolutionMap._from_state(*bad)
    assert e.value.cause == "zero_direction"
    with pytest.raises(TypeError):
        f.solution_map(Grid(*GRID), 3)


def test_the_picture(press):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    from burmester import plot

    _, _, _, m = press
    ax = plot.solution_map(m, units="mm")
    gids = {a.get_gid() for a in ax.get_children()}
    assert {"branch-map", "guide", "driven-pin", "poses"} <= gids
    assert "slider" in ax.get_title()
    import matplotlib.pyplot as plt

    plt.close(ax.figure)


def test_progress_and_interrupt(press):
    _, _, f, _ = press
    calls = []

    def progress(done, total):
        calls.append((done, total))
        if len(calls) > 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        f.solution_map(Grid(-300, 300, -300, 300, 1000, 1000), progress=progress)
    assert len(calls) == 3 and calls[0][1] == 1000  # rows


def test_a_lid_turned_100_degrees_has_at_most_40_degrees_transmission():
    """The coupler turns with the task: over a travel that turns it by 100
    degrees its angle to the guide's normal comes within 90 - 50 degrees of
    it somewhere, whatever the pivot: the map's best is 40 degrees."""
    task = Task([(0.0, 0.0, 0.0), (30.0, 60.0, math.radians(45)), (40.0, 140.0, math.radians(100))])
    best = []
    for s in task.slider_dyads(6):
        m = SliderFilemon(task, s.circle, s.guide).solution_map(Grid(-400, 400, -400, 400, 80, 80))
        mu = np.degrees(m.min_transmission_rad[m.valid & (m.direction != 0)])
        best.append(float(np.nanmax(mu)))
        assert (mu <= 40.0 + 1e-4).all()
    assert min(best) > 39.0  # reached within the grid's spacing
