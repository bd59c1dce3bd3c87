"""Filemon.branch_map and margin_map: the grid convention, the methods, out=."""

import numpy as np
import pytest

import burmester
from burmester import InvalidInputError
from conftest import VP


def test_shape_dtype_and_orientation(f):
    m = f.branch_map(*VP, 40, 30)
    assert m.dtype == np.bool_ and m.shape == (30, 40)
    assert m.flags["C_CONTIGUOUS"] and m.flags["WRITEABLE"]
    xmin, xmax, ymin, ymax = VP
    for j in range(0, 30, 7):
        for i in range(0, 40, 5):
            x = xmin + (i + 0.5) * (xmax - xmin) / 40
            y = ymin + (j + 0.5) * (ymax - ymin) / 30
            assert m[j, i] == f.is_branch_free((x, y))


def test_methods_agree_off_the_curves(f):
    n = 96
    conic = f.branch_map(*VP, n, n)
    direct = f.branch_map(*VP, n, n, "direct")
    sim = f.branch_map(*VP, n, n, method="simulate")
    xmin, xmax, ymin, ymax = VP
    ga, gb = f.conics
    for j, i in zip(*np.nonzero((conic != direct) | (conic != sim))):
        p = (xmin + (i + 0.5) * (xmax - xmin) / n, ymin + (j + 0.5) * (ymax - ymin) / n)
        assert min(ga.distance(p), gb.distance(p)) < 1e-8
    assert 0.05 < conic.mean() < 0.95


def test_out_is_filled_and_returned(f):
    out = np.empty((64, 32), dtype=bool)
    r = f.branch_map(*VP, 32, 64, out=out)
    assert r is out
    assert np.array_equal(out, f.branch_map(*VP, 32, 64))
    with pytest.raises(InvalidInputError, match="shape"):
        f.branch_map(*VP, 32, 32, out=out)
    with pytest.raises(InvalidInputError, match="contiguous"):
        f.branch_map(*VP, 32, 64, out=np.empty((32, 64), dtype=bool).T)
    with pytest.raises(TypeError):
        f.branch_map(*VP, 32, 64, out=np.empty((64, 32), dtype=np.int8))
    mo = np.empty((64, 32), dtype=np.float32)
    assert f.margin_map(*VP, 32, 64, out=mo) is mo


def test_margin_map(f):
    mm = f.margin_map(*VP, 50, 40)
    m = f.branch_map(*VP, 50, 40)
    assert mm.dtype == np.float32 and mm.shape == (40, 50)
    assert not np.isnan(mm).any()
    assert np.array_equal(mm > 0, m)
    assert f.margin((1.0, 1.0)) == pytest.approx(float(f.margin_map(1.0 - 0.5, 1.5, 0.5, 1.5, 1, 1)[0, 0]), rel=1e-6)


def test_bad_grids_raise(f):
    with pytest.raises(InvalidInputError, match="nx"):
        f.branch_map(*VP, 0, 10)
    with pytest.raises(InvalidInputError, match="xmin < xmax"):
        f.branch_map(1.0, 0.0, 0.0, 1.0, 10, 10)
    with pytest.raises(InvalidInputError, match="finite"):
        f.branch_map(0.0, float("nan"), 0.0, 1.0, 10, 10)
    with pytest.raises(InvalidInputError, match="method"):
        f.branch_map(*VP, 10, 10, "fast")
    with pytest.raises(InvalidInputError, match="non-negative integer"):
        f.branch_map(*VP, -1, 10)
    with pytest.raises(InvalidInputError, match="out of range"):
        f.margin_map(*VP, 10, 2**70)
    with pytest.raises(InvalidInputError, match="2\\^32"):
        f.branch_map(*VP, 2**40, 2**40)
    with pytest.raises(TypeError):
        f.branch_map(*VP, 10.5, 10)
