"""The Python surface of the position analysis: every fixed name, the errors,
and solve_many against solve."""

import math

import numpy as np
import pytest

import burmester
from burmester import AssemblyError, BurmesterError, FourBar, InvalidInputError


def fb4(ground, crank, coupler, rocker, **kw):
    """A FourBar from its lengths in the order ground, crank, coupler, rocker."""
    return FourBar(ground=ground, crank=crank, coupler=coupler, rocker=rocker, **kw)


def test_exception_hierarchy():
    assert issubclass(BurmesterError, ValueError)
    for cls in (InvalidInputError, AssemblyError, burmester.DegenerateError):
        assert issubclass(cls, BurmesterError)
    assert burmester.__version__


def test_norton_example_4_1():
    fb = fb4(100.0, 40.0, 120.0, 80.0)
    t3, t4 = fb.solve(math.radians(40))
    assert isinstance(t3, float) and isinstance(t4, float)
    assert round(math.degrees(t3), 3) == 20.298
    assert round(math.degrees(t4), 3) == 57.325
    t3, t4 = fb.solve(math.radians(40), mode="crossed")
    assert round(math.degrees(t3), 3) == -60.978
    assert round(math.degrees(t4), 3) == -98.005


def test_second_cross_check():
    fb = fb4(4, 1, 3, 3)
    t3, t4 = fb.solve(math.radians(60), "open")
    assert round(math.degrees(t3), 9) == 39.165923859
    assert round(math.degrees(t4), 9) == 113.038303645
    t3, t4 = fb.solve(math.radians(60), "crossed")
    assert round(math.degrees(t3), 9) == -66.961696355
    assert round(math.degrees(t4), 9) == -140.834076141


@pytest.mark.parametrize(
    "lengths, kind",
    [
        ((4, 1, 3, 3), "crank-rocker"),
        ((1, 4, 3, 3), "double-crank"),
        ((4, 3, 3, 1), "rocker-crank"),
        ((4, 3, 1, 3), "double-rocker"),
        ((3, 2, 1.5, 1), "triple-rocker"),
        ((2, 1, 2, 1), "change-point"),
    ],
)
def test_grashof(lengths, kind):
    assert fb4(*lengths).grashof == kind


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf, -math.inf])
@pytest.mark.parametrize("which", range(4))
def test_bad_lengths_raise_invalid_input(bad, which):
    lengths = [4.0, 1.0, 3.0, 3.0]
    lengths[which] = bad
    name = ["ground", "crank", "coupler", "rocker"][which]
    with pytest.raises(InvalidInputError, match=name):
        fb4(*lengths)


def test_never_closes_raises_assembly_error():
    with pytest.raises(AssemblyError, match="never be assembled"):
        fb4(10, 1, 2, 3)


def test_solve_errors():
    fb = fb4(3, 2, 1.5, 1)  # triple-rocker
    with pytest.raises(AssemblyError, match="does not close"):
        fb.solve(math.pi)
    with pytest.raises(InvalidInputError, match="finite"):
        fb.solve(math.nan)
    with pytest.raises(InvalidInputError, match="open"):
        fb.solve(0.1, mode="sideways")
    with pytest.raises(TypeError):
        fb.solve("zero")  # type: ignore[arg-type]
    with pytest.raises(AssemblyError, match="indeterminate"):
        fb4(1, 1, 2, 2).solve(0.0)


def test_solve_many_matches_solve():
    fb = fb4(3, 2, 1.5, 1)
    ts = np.linspace(-4, 4, 1001)
    for mode in ("open", "crossed"):
        t3, t4, ok = fb.solve_many(ts, mode=mode)
        assert t3.dtype == np.float64 and ok.dtype == np.bool_
        assert t3.shape == ts.shape == t4.shape == ok.shape
        assert ok.any() and not ok.all()
        assert np.array_equal(np.isnan(t3), ~ok) and np.array_equal(np.isnan(t4), ~ok)
        for t, a, b, v in zip(ts, t3, t4, ok):
            if v:
                assert fb.solve(float(t), mode) == (a, b)
            else:
                with pytest.raises(AssemblyError):
                    fb.solve(float(t), mode)


def test_solve_many_accepts_lists_ints_and_shapes():
    fb = fb4(100, 40, 120, 80)
    t3, t4, ok = fb.solve_many([0, 1, 2])
    assert t3.shape == (3,) and ok.all()
    t3, _, ok = fb.solve_many(np.zeros((2, 3), dtype=np.float32))
    assert t3.shape == (2, 3)
    t3, _, ok = fb.solve_many([math.nan, math.inf, 0.5])
    assert list(ok) == [False, False, True]
    assert np.isnan(t3[:2]).all()
    t3, _, ok = fb.solve_many(np.array([]))
    assert t3.shape == (0,)


def test_configuration_and_geometry():
    fb = fb4(3, 2, 1.5, 1)
    ((start, end),) = fb.input_range
    assert fb.dead_positions == [start, end]
    c = fb.configuration(start)
    assert c.toggle and c.transmission_angle < 1e-6
    c = fb.configuration(0.5 * (start + end), "crossed")
    assert not c.toggle and c.mode == "crossed" and c.coupler_rocker_angle < 0
    assert "Configuration(" in repr(c)
    assert fb4(4, 1, 3, 3).input_range is None
    assert fb4(4, 1, 3, 3).input_turns_fully
    assert fb4(4, 1, 3, 3).dead_positions == []

    fb = fb4(100, 40, 120, 80, origin=(1.0, 2.0), ground_angle=0.3)
    o2, a_, b_, o4 = fb.joints(1.0)
    assert o2 == (1.0, 2.0) == fb.input_pivot
    assert o4 == pytest.approx(fb.output_pivot)
    assert math.dist(o2, a_) == pytest.approx(40)
    assert math.dist(a_, b_) == pytest.approx(120)
    assert math.dist(b_, o4) == pytest.approx(80)
    assert fb.transmission_angle(1.0) == pytest.approx(fb.configuration(1.0).transmission_angle)
    p = fb.coupler_point(1.0, (120.0, 0.0))
    assert p == pytest.approx(b_)
    xs, ys, ok = fb.coupler_path((120.0, 0.0), [1.0, 2.0])
    assert ok.all() and (xs[0], ys[0]) == pytest.approx(b_)
    with pytest.raises(InvalidInputError):
        fb.coupler_path((math.nan, 0.0), [1.0])
    assert fb.lengths == (100.0, 40.0, 120.0, 80.0)
    assert "origin=" in repr(fb)
    assert fb4(1, 2, 3, 3) == fb4(1.0, 2.0, 3.0, 3.0)
    g = FourBar.from_pivots((0, 0), (3, 4), 1, 5, 5)
    assert g.ground == 5 and g.ground_angle == pytest.approx(math.atan2(4, 3))
    assert fb4(4, 1, 3, 3).link_ratio == 4


def test_solve_command_prints_a_table(capsys):
    from burmester.cli import main

    assert main(["solve"]) == 0
    out = capsys.readouterr().out
    assert "crank-rocker" in out and "20.298" not in out.splitlines()[0]


def test_lengths_go_by_keyword_only():
    with pytest.raises(TypeError, match=r"by name.*ground=\.\.\., crank=\.\.\., coupler=\.\.\., rocker=\.\.\."):
        FourBar(100.0, 40.0, 120.0, 80.0)  # type: ignore[misc]
    with pytest.raises(TypeError, match="1 positional"):
        FourBar(100.0, crank=40.0, coupler=120.0, rocker=80.0)  # type: ignore[misc]
    with pytest.raises(TypeError, match="all four lengths"):
        FourBar(ground=100.0, crank=40.0, coupler=120.0)  # type: ignore[call-arg]
    with pytest.raises(TypeError):
        FourBar(ground=100.0, crank=40.0, coupler=120.0, rocker=80.0, lenght=1.0)  # type: ignore[call-arg]
    # Any order of the keywords is the same linkage.
    a = FourBar(rocker=80.0, coupler=120.0, crank=40.0, ground=100.0)
    assert a == FourBar(ground=100.0, crank=40.0, coupler=120.0, rocker=80.0)
    assert a.lengths == (100.0, 40.0, 120.0, 80.0)
    assert repr(a) == "FourBar(ground=100.0, crank=40.0, coupler=120.0, rocker=80.0)"
    assert eval(repr(a), {"FourBar": FourBar}) == a

