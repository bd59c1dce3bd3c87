"""The solution-space map from Python: arrays, limits, constraints, best pivots."""

import math
import pickle

import numpy as np
import pytest

import burmester
from burmester import DesignLimits, Grid, InvalidInputError, Pivot
from conftest import POSES, C0, VP


def test_arrays_shapes_dtypes_and_consistency(f):
    m = f.solution_map(*VP, 64, 48)
    assert m.shape == (48, 64) and m.extent == VP and m.varying == "driving"
    for name, dtype in [
        ("valid", np.bool_), ("branch_free", np.bool_), ("grashof", np.uint8),
        ("input_full", np.bool_), ("direction", np.int8), ("one_circuit", np.bool_),
        ("min_transmission_rad", np.float32), ("link_ratio", np.float32), ("size_ratio", np.float32),
        ("acceptable", np.bool_),
    ]:
        a = getattr(m, name)
        assert a.shape == (48, 64) and a.dtype == dtype, name
        assert not a.flags["WRITEABLE"]
        assert getattr(m, name) is a or np.shares_memory(getattr(m, name), a)
    assert np.array_equal(m.branch_free, f.branch_map(*VP, 64, 48))
    assert not (m.acceptable & ~m.branch_free).any()
    assert not (m.acceptable & (m.direction == 0)).any()
    assert np.isnan(m.min_transmission_rad[m.direction == 0]).all()
    ok = m.acceptable
    assert (m.min_transmission_rad[ok] >= math.radians(30) - 1e-6).all()
    assert (m.min_transmission_rad[m.valid & ~np.isnan(m.min_transmission_rad)] <= math.pi / 2 + 1e-6).all()
    assert (m.link_ratio[ok] <= 10).all()
    assert set(np.unique(m.grashof[m.valid])) <= set(range(6))
    assert len(m.grashof_names) == 6 and m.grashof_names[0] == "crank-rocker"
    assert m.columns == ["valid", "branch_free", "grashof", "input_full", "direction",
                         "one_circuit", "min_transmission_rad", "link_ratio", "size_ratio", "acceptable"]
    assert m.grid == Grid(*VP, 64, 48) and m.limits == DesignLimits()
    assert m.task == burmester.Task(POSES) and m.fixed_dyad == ((4.0, -1.0), pytest.approx(f.driven_circle))
    assert (m.grashof[~m.valid] == 255).all()


def test_sample_linkage_matches_the_map(f):
    m = f.solution_map(*VP, 40, 40)
    js, is_ = np.nonzero(m.acceptable)
    assert len(js) > 0
    j, i = js[len(js) // 2], is_[len(is_) // 2]
    fb = m.linkage(int(j), int(i))
    assert fb.driving[0] == pytest.approx(m.point(int(j), int(i)))
    assert m.point(int(j), int(i)) == m.grid.point(int(j), int(i))
    assert fb.fourbar.grashof == m.grashof_names[m.grashof[j, i]]
    assert fb.branch_free
    # The sample's figures are the linkage's, column by column.
    fig = fb.figures
    assert fig.grashof == m.grashof_names[m.grashof[j, i]]
    assert fig.input_full == m.input_full[j, i] and fig.one_circuit == m.one_circuit[j, i]
    assert {"ccw": 1, "cw": -1, "none": 0}[fig.direction] == m.direction[j, i]
    assert math.radians(fig.min_transmission_deg) == pytest.approx(float(m.min_transmission_rad[j, i]), rel=1e-6)
    assert fig.link_ratio == pytest.approx(float(m.link_ratio[j, i]), rel=1e-6)
    assert fb.size_ratio == pytest.approx(float(m.size_ratio[j, i]), rel=1e-6)
    assert fig.feasible and fig.branch_free
    assert m.margin(int(j), int(i)) == pytest.approx(f.margin(m.point(int(j), int(i))))
    with pytest.raises(InvalidInputError):
        m.point(40, 0)


def test_limits_tighten_the_mask(f):
    loose = f.solution_map(*VP, 50, 50, min_transmission_deg=0, max_link_ratio=math.inf)
    strict = f.solution_map(*VP, 50, 50, min_transmission_deg=45, max_link_ratio=4, input="crank")
    assert strict.acceptable.sum() < loose.acceptable.sum()
    assert not (strict.acceptable & ~loose.acceptable).any()
    assert (strict.input_full[strict.acceptable]).all()
    assert strict.limits == DesignLimits(45, 4, "crank")
    # limits= is the same as its three keywords, and not both.
    assert f.solution_map(*VP, 50, 50, limits=DesignLimits(45, 4, "crank")) == strict
    with pytest.raises(TypeError, match="not both"):
        f.solution_map(*VP, 8, 8, limits=DesignLimits(), max_link_ratio=4)
    rocker = f.solution_map(*VP, 50, 50, input="rocker")
    assert not (rocker.input_full[rocker.acceptable]).any()
    with pytest.raises(InvalidInputError, match="input requirement"):
        f.solution_map(*VP, 8, 8, input="motor")
    with pytest.raises(InvalidInputError, match="90"):
        f.solution_map(*VP, 8, 8, min_transmission_deg=120)
    with pytest.raises(InvalidInputError):
        f.solution_map(*VP, 8, 8, max_link_ratio=0.5)


def test_constraints(f):
    plate = [(-8, -8), (0, -8), (0, 8), (-8, 8)]
    m = f.solution_map(*VP, 40, 40, base_plate=plate)
    xs, _ = m.grid.cell_centers()
    assert not m.acceptable[:, xs > 0].any()
    ob = f.solution_map(*VP, 40, 40, obstacles=[[(-1, -3), (0.5, -3), (0.5, -2), (-1, -2)]], link_width=0.3)
    free = f.solution_map(*VP, 40, 40)
    assert ob.acceptable.sum() < free.acceptable.sum()
    with pytest.raises(InvalidInputError) as e:
        f.solution_map(*VP, 8, 8, obstacles=[[(0, 0), (1, 1)]], link_width=0.1)
    assert e.value.cause == "polygon" and e.value.vertices == 2


def test_best_pivots_pick_a_linkage_that_passes_the_poses(f):
    task = burmester.Task(POSES)
    m = f.solution_map(*VP, 160, 160)
    best = m.best_pivots(5, rank_by="transmission")
    assert 1 <= len(best) <= 5
    assert all(isinstance(p, Pivot) and p.ranked_by == "transmission" for p in best)
    scores = [p.figures.min_transmission_deg for p in best]
    assert scores == sorted(scores, reverse=True)
    for p in best:
        j, i = p.index
        assert m.acceptable[j, i] and p.center == m.point(j, i)
        fig = p.figures
        assert fig == p.linkage.figures
        assert fig.direction in ("ccw", "cw") and fig.modes[0] in ("open", "crossed")
        assert fig.min_transmission_deg >= 30 and fig.link_ratio <= 10
        assert p.margin == pytest.approx(m.margin(j, i)) and p.margin > 0
        fb = task.four_bar(p.center, C0)
        assert fb == p.linkage
        for k, pose in enumerate(POSES):
            x, y, a = fb.pose_at(fb.input_angles[k], fig.modes[k])
            assert (x, y) == pytest.approx(pose[:2], abs=1e-9)
    for a in best:
        for b in best:
            if a is not b:
                assert math.dist(a.center, b.center) >= 0.02 * math.hypot(16, 16) - 1e-12
    # A wider spacing keeps them farther apart.
    for a, b in zip(m.best_pivots(3, 4.0), m.best_pivots(3, 4.0)[1:]):
        assert math.dist(a.center, b.center) >= 4.0
    with pytest.raises(InvalidInputError, match="ranking"):
        m.best_pivots(3, rank_by="beauty")  # type: ignore[arg-type]
    with pytest.raises(InvalidInputError):
        m.best_pivots(3, -1.0)


def test_best_pivots_by_margin(f):
    m = f.solution_map(*VP, 120, 120, min_transmission_deg=89.9)
    assert not m.acceptable.any()
    assert m.best_pivots(3) == []
    best = m.best_pivots(3, 1.6, rank_by="margin")
    assert len(best) == 3 and all(p.ranked_by == "margin" for p in best)
    margins = [p.margin for p in best]
    assert margins == sorted(margins, reverse=True)
    mm = f.margin_map(m.grid)
    # The best is the branch-free sample farthest from the curves.
    assert best[0].margin == pytest.approx(float(mm[m.valid & m.branch_free].max()), rel=1e-6)
    for p in best:
        j, i = p.index
        assert m.valid[j, i] and m.branch_free[j, i]
        assert p.margin == pytest.approx(f.margin(p.center))
    for a, b in zip(best, best[1:]):
        assert math.dist(a.center, b.center) >= 1.6


def test_the_other_direction(f):
    task = burmester.Task(POSES)
    m = task.driven_solution_map((-3.0, 4.0), *VP, 40, 40)
    assert m.varying == "driven"
    assert m.fixed_dyad == task.dyad((-3.0, 4.0))
    js, is_ = np.nonzero(m.branch_free)
    for j, i in list(zip(js, is_))[:20]:
        fb = task.four_bar((-3.0, 4.0), m.point(int(j), int(i)))
        assert fb.branch_free
        assert m.linkage(int(j), int(i)) == fb
    for p in m.best_pivots(2):
        assert isinstance(p, Pivot) and p.linkage.driving[0] == (-3.0, 4.0)
        assert p.linkage.driven[0] == p.center
    # The driven map's margin: the distance to the nearest sample of the other class.
    j, i = int(js[0]), int(is_[0])
    assert m.margin(j, i) > 0


# ---------------------------------------------------------------------------
# Rankings designers accept


def _size(task, sfb):
    """The total length of the members, computed here from the joints at
    pose 1: ground, crank, rocker and the coupler triangle."""
    (a0, a1), (c0, c1) = sfb.driving, sfb.driven
    p = task.poses[0][:2]
    return sum(math.dist(u, v) for u, v in [(a0, c0), (a0, a1), (c0, c1), (a1, c1), (a1, p), (c1, p)])


def test_size_ratio_is_the_members_over_the_task_span(f):
    task = burmester.Task(POSES)
    pts = [pose[:2] for pose in POSES]
    assert task.span == max(math.dist(u, v) for u in pts for v in pts)
    m = f.solution_map(*VP, 40, 40)
    js, is_ = np.nonzero(m.valid)
    for j, i in list(zip(js, is_))[::37]:
        sfb = m.linkage(int(j), int(i))
        assert sfb.size == pytest.approx(_size(task, sfb), rel=1e-12)
        assert float(m.size_ratio[j, i]) == pytest.approx(sfb.size / task.span, rel=1e-6)
    assert np.isnan(m.size_ratio[~m.valid]).all()
    # Scale-free: the task and its view twice as large give the same ratios.
    big = burmester.Task([(2 * x, 2 * y, a) for x, y, a in POSES]).filemon((2 * C0[0], 2 * C0[1]))
    m2 = big.solution_map(*(2 * v for v in VP), 40, 40)
    assert np.allclose(m2.size_ratio, m.size_ratio, rtol=1e-5, equal_nan=True)


@pytest.mark.parametrize("rank_by", ["balanced", "transmission", "compact"])
def test_rankings_take_the_best_score_among_the_acceptable(f, rank_by):
    m = f.solution_map(*VP, 100, 100)
    ok = m.acceptable
    mu = m.min_transmission_rad.astype(float)
    s, r = m.size_ratio.astype(float), m.link_ratio.astype(float)
    # The documented scores, from the columns.
    score = {"balanced": np.sin(mu) / np.sqrt(s * r), "transmission": mu, "compact": -s}[rank_by]
    best = m.best_pivots(5, 0.0, rank_by=rank_by)
    assert len(best) == 5 and all(p.ranked_by == rank_by for p in best)
    assert best[0].score == pytest.approx(float(score[ok].max()), rel=1e-6)
    for p in best:
        assert ok[p.index] and p.score == pytest.approx(float(score[p.index]), rel=1e-6)
    assert [p.score for p in best] == sorted((p.score for p in best), reverse=True)


def test_balanced_is_default_and_smaller_than_the_best_transmission():
    spec = burmester.taskfile.example()
    m = spec.filemon().solution_map(spec.view, limits=spec.limits)
    (balanced,) = m.best_pivots(1)
    (by_mu,) = m.best_pivots(1, rank_by="transmission")
    assert balanced.ranked_by == "balanced"
    # The issue that asked for it: the transmission winner of the built-in
    # example is a linkage many times the task's size.
    assert by_mu.size_ratio > 15 and balanced.size_ratio < 0.8 * by_mu.size_ratio
    assert balanced.figures.min_transmission_deg > 60


def test_pareto_front_is_nondominated(f):
    m = f.solution_map(*VP, 80, 80)
    front = m.pareto_front()
    assert len(front) >= 2 and all(p.ranked_by == "pareto" for p in front)
    mu, s = m.min_transmission_rad, m.size_ratio
    ok = m.acceptable & ~np.isnan(mu)
    for p in front:
        dominated = ok & (mu >= mu[p.index]) & (s <= s[p.index]) & ((mu > mu[p.index]) | (s < s[p.index]))
        assert not dominated.any()
    for a, b in zip(front, front[1:]):
        assert s[a.index] <= s[b.index] and mu[a.index] < mu[b.index]
    # Every acceptable sample is matched or beaten by a member of the front.
    fm = np.array([mu[p.index] for p in front])
    fs = np.array([s[p.index] for p in front])
    covered = ((fm[:, None] >= mu[ok][None, :]) & (fs[:, None] <= s[ok][None, :])).any(axis=0)
    assert covered.all()
    assert m.best_pivots(3, rank_by="pareto") == m.best_pivots(3, rank_by="pareto")
    with pytest.raises(InvalidInputError, match="balanced"):
        m.best_pivots(3, rank_by="beauty")  # type: ignore[arg-type]


def test_large_maps_are_numpy_arrays_the_core_fills_in_place(f):
    # Above 1 MiB a column is allocated by numpy.empty (huge pages on large
    # arrays) and written by the core in place: the arrays own their data.
    m = f.solution_map(*VP, 1100, 1000)
    for name in m.columns:
        a = getattr(m, name)
        assert a.shape == (1000, 1100) and a.flags["C_CONTIGUOUS"] and a.flags["OWNDATA"], name
        assert not a.flags["WRITEABLE"], name
    assert np.array_equal(m.branch_free, f.branch_map(*VP, 1100, 1000))
    assert not (m.acceptable & ~m.branch_free).any()
    assert (m.grashof[~m.valid] == 255).all() and m.valid.any()
    # Every value is written: the same map again (NumPy may hand back the
    # pages of a freed one) is the same bits, and pickles to an equal map.
    again = f.solution_map(*VP, 1100, 1000)
    assert again == m
    assert pickle.loads(pickle.dumps(m)) == m
