"""The four-position pair map from Python, checked against what is computed
apart from it: the known crank-rocker behind the notes' worked example (its
two dyads must make a branch-free, counter-clockwise cell, and not with the
rocker driving), ``Task.four_bar`` of each cell's two dyads, Filemon's
construction with four lines (``Task.curve_branch``), and driving the built
linkage through the poses."""

import math
import pickle

import numpy as np
import pytest

import burmester
from burmester import DesignLimits, InvalidInputError, PairMap, Task

NOTES_POSES = [
    (1.049199280691, 2.279426358634, 45.220037141544),
    (0.734502065472, 3.198658887874, 26.633426990744),
    (-0.378159188147, 3.063048993013, 21.786789298262),
    (-1.268710439724, 2.051150142014, 27.048624103934),
]
FOUR = [(x, y, math.radians(a)) for x, y, a in NOTES_POSES]
A0, B0 = (0.0, 0.0), (4.0, 0.0)


@pytest.fixture(scope="module")
def task():
    return Task(FOUR)


@pytest.fixture(scope="module")
def pmap(task):
    return task.pair_map(360, 300)


def _nearest(dyads, p):
    d = [math.inf if c is None else math.dist(c.center, p) for c in dyads]
    i = int(np.argmin(d))
    return i, d[i]


def test_shape_columns_and_parameter_plane(pmap):
    assert pmap.shape == (300, 360)
    for col in PairMap.columns:
        a = getattr(pmap, col)
        assert a.shape == (300, 360) and not a.flags["WRITEABLE"], col
    assert len(pmap.driving_dyads) == 360 and len(pmap.driven_dyads) == 300
    x0, x1, y0, y1 = pmap.extent
    assert x0 == 0.0 and y0 == 0.0 and x1 == y1 > 0
    g = pmap.grid
    assert (g.nx, g.ny) == (360, 300)
    # The columns' parameters run along the branches in order of beta2.
    open_ = [d for d in pmap.driving_dyads if d is not None and d.branch == "open"]
    assert open_ and all(d.branch == "crossed" for d in pmap.driving_dyads[len(open_) + 2:] if d is not None)


def test_the_generating_pair_is_a_feasible_ccw_cell(pmap):
    i, da = _nearest(pmap.driving_dyads, A0)
    j, db = _nearest(pmap.driven_dyads, B0)
    assert da < 0.1 and db < 0.1
    assert pmap.valid[j, i] and pmap.branch_free[j, i] and pmap.acceptable[j, i]
    assert pmap.direction[j, i] == 1 and pmap.input_full[j, i]
    assert pmap.grashof_names[pmap.grashof[j, i]] == "crank-rocker"
    # The rocker driving the same two dyads has a branch defect.
    i2, _ = _nearest(pmap.driving_dyads, B0)
    j2, _ = _nearest(pmap.driven_dyads, A0)
    assert pmap.valid[j2, i2] and not pmap.branch_free[j2, i2]


def test_cells_are_the_linkages_of_their_dyads(task, pmap):
    rng = np.random.default_rng(3)
    checked = 0
    for _ in range(300):
        j, i = int(rng.integers(300)), int(rng.integers(360))
        a, c = pmap.driving_dyads[i], pmap.driven_dyads[j]
        if a is None or c is None or not pmap.valid[j, i]:
            continue
        sfb = task.four_bar(a.center, c.center)
        f = sfb.figures
        assert pmap.branch_free[j, i] == f.branch_free
        assert pmap.direction[j, i] == {"ccw": 1, "cw": -1, "none": 0}[f.direction]
        assert pmap.input_full[j, i] == f.input_full
        assert pmap.grashof_names[pmap.grashof[j, i]] == f.grashof
        assert pmap.link_ratio[j, i] == np.float32(f.link_ratio)
        if f.min_transmission_deg is None:
            assert np.isnan(pmap.min_transmission_rad[j, i])
        else:
            assert pmap.min_transmission_rad[j, i] == np.float32(math.radians(f.min_transmission_deg))
        assert math.isclose(pmap.size_ratio[j, i], sfb.size_ratio, rel_tol=1e-6)
        # Task.four_bar recomputes each circle point from its center.
        got = pmap.linkage(j, i).fourbar.lengths
        assert all(math.isclose(u, v, rel_tol=1e-9) for u, v in zip(got, sfb.fourbar.lengths))
        checked += 1
    assert checked > 150


def test_branch_free_agrees_with_filemons_four_lines(task, pmap):
    """Row j's branch flags are Task.curve_branch of its driven dyad."""
    seen = {"free": 0, "defective": 0}
    for j in range(0, 300, 37):
        c = pmap.driven_dyads[j]
        if c is None:
            continue
        for i in range(0, 360, 7):
            a = pmap.driving_dyads[i]
            if a is None or not pmap.valid[j, i]:
                continue
            cls = task.curve_branch(c.center, a.center)
            if cls == "boundary":
                continue
            assert pmap.branch_free[j, i] == (cls == "free"), (j, i)
            seen[cls] += 1
    assert seen["free"] > 20 and seen["defective"] > 20


def test_best_pairs_drive_through_the_poses(task, pmap):
    best = pmap.best_pairs(5)
    assert len(best) == 5
    assert [p.score for p in best] == sorted((p.score for p in best), reverse=True)
    for p in best:
        j, i = p.index
        assert pmap.acceptable[j, i] and p.margin > 0 and p.ranked_by == "balanced"
        assert p.driving == pmap.driving_dyads[i] and p.driven == pmap.driven_dyads[j]
        sfb = p.linkage
        again = task.four_bar(p.driving.center, p.driven.center).fourbar.lengths
        assert all(math.isclose(u, v, rel_tol=1e-9) for u, v in zip(sfb.fourbar.lengths, again))
        mode = sfb.modes[0]
        for theta, (x, y, a) in zip(sfb.input_angles, FOUR):
            q = sfb.pose_at(theta, mode)
            assert math.dist(q[:2], (x, y)) < 1e-8
            assert abs(math.remainder(q[2] - a, math.tau)) < 1e-8
    for rank_by in ("transmission", "compact", "pareto", "margin"):
        assert all(p.ranked_by == rank_by for p in pmap.best_pairs(3, rank_by=rank_by))
    front = pmap.pareto_front()
    assert len(front) >= 2
    assert all(a.size_ratio <= b.size_ratio + 1e-6 and a.score < b.score for a, b in zip(front, front[1:]))
    m = pmap.margins()
    assert m.shape == pmap.shape and np.array_equal(m > 0, pmap.branch_free)


def test_keywords_as_the_solution_map(task):
    strict = task.pair_map(80, min_transmission_deg=60.0, input="crank")
    loose = task.pair_map(80, limits=DesignLimits(10.0, 20.0))
    assert strict.shape == (80, 80)
    assert strict.limits == DesignLimits(60.0, 10.0, "crank")
    assert strict.acceptable.sum() < loose.acceptable.sum()
    assert not (strict.acceptable & ~strict.input_full).any()
    fm = strict.min_transmission_rad[strict.acceptable]
    assert (fm >= np.float32(math.radians(60.0)) - 1e-6).all()
    # A base plate that holds neither pivot leaves nothing acceptable.
    far = task.pair_map(60, base_plate=[(100, 100), (101, 100), (101, 101)])
    assert far.valid.any() and not far.acceptable.any()
    with pytest.raises(TypeError):
        task.pair_map(60, limits=DesignLimits(), min_transmission_deg=30.0)


def test_progress_pickling_and_equality(task):
    seen = []
    m = task.pair_map(64, 48, progress=lambda d, t: seen.append((d, t)))
    assert seen and seen[-1] == (48, 48)
    assert m == task.pair_map(64, 48)
    assert m != task.pair_map(64, 49)
    back = pickle.loads(pickle.dumps(m))
    assert back == m and repr(back) == repr(m)
    assert back.best_pairs(3) == m.best_pairs(3)
    p = m.best_pairs(1)[0]
    assert pickle.loads(pickle.dumps(p)) == p


def test_a_raising_progress_callback_stops_the_map(task):
    def stop(done, total):
        raise RuntimeError("stop")

    with pytest.raises(RuntimeError, match="stop"):
        task.pair_map(1500, 1500, progress=stop)


def test_bad_input(task):
    with pytest.raises(InvalidInputError) as e:
        Task(FOUR[:3]).pair_map(16)
    assert e.value.cause == "needs_poses"
    for n in (0, 10**7 + 1):
        with pytest.raises(InvalidInputError) as e:
            task.pair_map(n, 8)
        assert e.value.cause == "grid_size"
    with pytest.raises(InvalidInputError):
        task.pair_map(2**20, 2**20)
    with pytest.raises(InvalidInputError):
        task.pair_map(-1)
    m = task.pair_map(8)
    # A typed error naming the index (issue 24: it was an IndexError).
    for j, i, name in ((8, 0, "j (the driven sample)"), (0, 8, "i (the driving sample)")):
        with pytest.raises(InvalidInputError, match=r"must be from 0 to 7") as e:
            m.linkage(j, i)
        assert e.value.cause == "grid_index" and name in str(e.value)
    with pytest.raises(InvalidInputError):
        m.best_pairs(3, rank_by="best")
    assert isinstance(m.best_pairs(0), list) and not m.best_pairs(0)
    assert burmester.Pair is type(task.pair_map(64).best_pairs(1)[0])


def test_a_large_pair_map_is_numpy_arrays_the_core_fills_in_place(task):
    m = task.pair_map(1100, 1000)
    for col in PairMap.columns:
        a = getattr(m, col)
        assert a.shape == (1000, 1100) and a.flags["C_CONTIGUOUS"] and a.flags["OWNDATA"], col
        assert not a.flags["WRITEABLE"], col
    assert m.valid.any() and not (m.acceptable & ~m.branch_free).any()
    assert task.pair_map(1100, 1000) == m
