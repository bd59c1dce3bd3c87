"""Filemon.branch_map and margin_map: the grid convention, the methods, out=,
a Grid or its six numbers."""

import numpy as np
import pytest

import burmester
from burmester import Grid, InvalidInputError
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
    g = Grid(*VP, n, n)
    conic = f.branch_map(g)
    direct = f.branch_map(*VP, n, n, "direct")
    sim = f.branch_map(g, method="simulate")
    assert np.array_equal(f.branch_map(g, "simulate"), sim)
    ga, gb = f.conics
    for j, i in zip(*np.nonzero(conic != direct)):
        p = g.point(int(j), int(i))
        assert min(ga.distance(p), gb.distance(p)) < 1e-8
    circuit = 0
    for j, i in zip(*np.nonzero(conic != sim)):
        p = g.point(int(j), int(i))
        if min(ga.distance(p), gb.distance(p)) < 1e-8:
            continue
        # Off the curves simulate differs only where it sees the circuit
        # defect of an input rocking in two arcs (poses on both).
        assert conic[j, i] and not sim[j, i], p
        sfb = f.four_bar(p)
        assert len(sfb.fourbar.input_range or []) == 2 and not sfb.figures.one_circuit, p
        circuit += 1
    assert circuit < 0.05 * n * n
    assert 0.05 < conic.mean() < 0.95


@pytest.mark.parametrize("method", ["conic", "direct", "simulate"])
def test_every_sample_is_written(f, method):
    # A fresh map is made by numpy.empty (as out= may be): whatever out held
    # before, the map is the same.
    n = 48 if method == "simulate" else 1100   # 1100^2 bytes > 1 MiB: the numpy.empty path
    g = Grid(*VP, n, n)
    a = f.branch_map(g, method, out=np.ones((n, n), bool))
    b = f.branch_map(g, method, out=np.zeros((n, n), bool))
    assert np.array_equal(a, b)
    assert np.array_equal(f.branch_map(g, method), a)
    m = f.margin_map(g, out=np.full((n, n), 7.0, np.float32))
    assert np.array_equal(m, f.margin_map(g, out=np.zeros((n, n), np.float32)), equal_nan=True)
    assert np.array_equal(m, f.margin_map(g), equal_nan=True)


def test_out_is_filled_and_returned(f):
    out = np.empty((64, 32), dtype=bool)
    r = f.branch_map(*VP, 32, 64, out=out)
    assert r is out
    assert np.array_equal(out, f.branch_map(*VP, 32, 64))
    with pytest.raises(InvalidInputError, match="shape"):
        f.branch_map(*VP, 32, 32, out=out)
    with pytest.raises(InvalidInputError, match="contiguous"):
        f.branch_map(*VP, 32, 64, out=np.empty((32, 64), dtype=bool).T)
    with pytest.raises(InvalidInputError, match="dtype int8") as e:
        f.branch_map(*VP, 32, 64, out=np.empty((64, 32), dtype=np.int8))
    assert e.value.cause == "out_array"
    with pytest.raises(InvalidInputError, match="read-only"):
        ro = np.empty((64, 32), dtype=bool)
        ro.setflags(write=False)
        f.branch_map(Grid(*VP, 32, 64), out=ro)
    with pytest.raises(TypeError, match="NumPy array"):
        f.branch_map(*VP, 32, 64, out=[[False] * 32] * 64)
    mo = np.empty((64, 32), dtype=np.float32)
    assert f.margin_map(*VP, 32, 64, out=mo) is mo
    assert f.margin_map(Grid(*VP, 32, 64), out=mo) is mo


def test_margin_map(f):
    mm = f.margin_map(*VP, 50, 40)
    m = f.branch_map(*VP, 50, 40)
    assert mm.dtype == np.float32 and mm.shape == (40, 50)
    assert not np.isnan(mm).any()
    assert np.array_equal(mm > 0, m)
    assert f.margin((1.0, 1.0)) == pytest.approx(float(f.margin_map(1.0 - 0.5, 1.5, 0.5, 1.5, 1, 1)[0, 0]), rel=1e-6)
    assert np.array_equal(f.margin_map(Grid(*VP, 50, 40)).view(np.uint32), mm.view(np.uint32))


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
    with pytest.raises(InvalidInputError, match="at most 4294967296") as e:
        f.branch_map(*VP, 2**40, 2**40)
    assert (e.value.cause, e.value.nx, e.value.ny, e.value.max) == ("grid_size", 2**40, 2**40, 2**32)
    with pytest.raises(InvalidInputError) as e:
        f.branch_map(1.0, 0.0, 0.0, 1.0, 10, 10)
    assert (e.value.cause, e.value.xmin, e.value.xmax) == ("viewport", 1.0, 0.0)
    with pytest.raises(TypeError):
        f.branch_map(*VP, 10.5, 10)
    with pytest.raises(TypeError, match="grid"):
        f.branch_map(*VP, 10)
    with pytest.raises(TypeError, match="once"):
        f.branch_map(Grid(*VP, 10, 10), "conic", method="conic")
    with pytest.raises(TypeError, match="grid"):
        f.margin_map(Grid(*VP, 10, 10), 3)
    with pytest.raises(TypeError, match="grid"):
        f.solution_map(Grid(*VP, 10, 10), 30.0)


def test_a_grid_or_its_six_numbers_give_the_same_maps(f, task):
    g = Grid(-7.0, 9.0, -6.0, 5.0, 37, 23)
    six = (-7.0, 9.0, -6.0, 5.0, 37, 23)
    for method in ("conic", "direct", "simulate"):
        assert np.array_equal(f.branch_map(g, method), f.branch_map(*six, method=method))
    assert np.array_equal(f.margin_map(g).view(np.uint32), f.margin_map(*six).view(np.uint32))
    assert f.solution_map(g) == f.solution_map(*six)
    assert task.driven_solution_map((-3.0, 4.0), g) == task.driven_solution_map((-3.0, 4.0), *six)
    assert f.solution_map(g).grid == g
