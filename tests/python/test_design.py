"""The solution-space map from Python: arrays, limits, constraints, best pivots."""

import math

import numpy as np
import pytest

import burmester
from burmester import InvalidInputError
from conftest import POSES, C0, VP


def test_arrays_shapes_dtypes_and_consistency(f):
    m = f.solution_map(*VP, 64, 48)
    assert m.shape == (48, 64) and m.extent == VP and m.varying == "driving"
    for name, dtype in [
        ("valid", np.bool_), ("branch_free", np.bool_), ("grashof", np.uint8),
        ("input_full", np.bool_), ("direction", np.int8), ("one_circuit", np.bool_),
        ("min_transmission", np.float32), ("link_ratio", np.float32), ("acceptable", np.bool_),
    ]:
        a = getattr(m, name)
        assert a.shape == (48, 64) and a.dtype == dtype, name
        assert not a.flags["WRITEABLE"]
        assert getattr(m, name) is a or np.shares_memory(getattr(m, name), a)
    assert np.array_equal(m.branch_free, f.branch_map(*VP, 64, 48))
    assert not (m.acceptable & ~m.branch_free).any()
    assert not (m.acceptable & (m.direction == 0)).any()
    assert np.isnan(m.min_transmission[m.direction == 0]).all()
    ok = m.acceptable
    assert (m.min_transmission[ok] >= math.radians(30) - 1e-6).all()
    assert (m.link_ratio[ok] <= 10).all()
    assert set(np.unique(m.grashof[m.valid])) <= set(range(6))
    assert len(m.grashof_names) == 6 and m.grashof_names[0] == "crank-rocker"


def test_sample_linkage_matches_the_map(f):
    m = f.solution_map(*VP, 40, 40)
    js, is_ = np.nonzero(m.acceptable)
    assert len(js) > 0
    j, i = js[len(js) // 2], is_[len(is_) // 2]
    fb = m.linkage(int(j), int(i))
    assert fb.driving[0] == pytest.approx(m.point(int(j), int(i)))
    assert fb.fourbar.grashof() == m.grashof_names[m.grashof[j, i]]
    assert fb.is_branch_free()
    with pytest.raises(InvalidInputError):
        m.point(40, 0)


def test_limits_tighten_the_mask(f):
    loose = f.solution_map(*VP, 50, 50, min_transmission_deg=0, max_link_ratio=math.inf)
    strict = f.solution_map(*VP, 50, 50, min_transmission_deg=45, max_link_ratio=4, input="crank")
    assert strict.acceptable.sum() < loose.acceptable.sum()
    assert not (strict.acceptable & ~loose.acceptable).any()
    assert (strict.input_full[strict.acceptable]).all()
    with pytest.raises(InvalidInputError, match="input requirement"):
        f.solution_map(*VP, 8, 8, input="motor")
    with pytest.raises(InvalidInputError, match="90"):
        f.solution_map(*VP, 8, 8, min_transmission_deg=120)
    with pytest.raises(InvalidInputError):
        f.solution_map(*VP, 8, 8, max_link_ratio=0.5)


def test_constraints(f):
    plate = [(-8, -8), (0, -8), (0, 8), (-8, 8)]
    m = f.solution_map(*VP, 40, 40, base_plate=plate)
    xmin, xmax, ymin, ymax = VP
    xs = xmin + (np.arange(40) + 0.5) * (xmax - xmin) / 40
    assert not m.acceptable[:, xs > 0].any()
    ob = f.solution_map(*VP, 40, 40, obstacles=[[(-1, -3), (0.5, -3), (0.5, -2), (-1, -2)]], link_width=0.3)
    free = f.solution_map(*VP, 40, 40)
    assert ob.acceptable.sum() < free.acceptable.sum()
    with pytest.raises(InvalidInputError):
        f.solution_map(*VP, 8, 8, obstacles=[[(0, 0), (1, 1)]], link_width=0.1)


def test_best_pivots_pick_a_linkage_that_passes_the_poses(f):
    task = burmester.Task(POSES)
    m = f.solution_map(*VP, 160, 160)
    best = m.best_pivots(5)
    assert 1 <= len(best) <= 5
    scores = [p["min_transmission_deg"] for p in best]
    assert scores == sorted(scores, reverse=True)
    for p in best:
        assert p["direction"] in ("ccw", "cw") and p["mode"] in ("open", "crossed")
        assert p["min_transmission_deg"] >= 30 and p["link_ratio"] <= 10
        fb = task.four_bar(p["center"], C0)
        for k, pose in enumerate(POSES):
            x, y, a = fb.pose_at(fb.input_angles[k], p["mode"])
            assert (x, y) == pytest.approx(pose[:2], abs=1e-9)
    for a in best:
        for b in best:
            if a is not b:
                assert math.dist(a["center"], b["center"]) >= 0.02 * math.hypot(16, 16) - 1e-12


def test_the_other_direction(f):
    task = burmester.Task(POSES)
    m = task.driven_solution_map((-3.0, 4.0), *VP, 40, 40)
    assert m.varying == "driven"
    js, is_ = np.nonzero(m.branch_free)
    for j, i in list(zip(js, is_))[:20]:
        fb = task.four_bar((-3.0, 4.0), m.point(int(j), int(i)))
        assert fb.is_branch_free()
    assert isinstance(m.best_pivots(2), list)
