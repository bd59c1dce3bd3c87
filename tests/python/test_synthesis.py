"""The Python surface of the synthesis and the branch problem."""

import math

import numpy as np
import pytest

import burmester
from burmester import Conic, DegenerateError, Filemon, InvalidInputError, Task
from conftest import POSES, C0


def rot(v, a):
    c, s = math.cos(a), math.sin(a)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])


def poles(task):
    """The finite poles' points, in pair order."""
    return [p.point for p in task.poles]


def test_poles_are_fixed_points(task):
    assert [p.pair for p in task.poles] == [(1, 2), (1, 3), (2, 3)]
    assert not any(p.at_infinity or p.direction is not None for p in task.poles)
    p12, p13, p23 = poles(task)
    for p, (i, j) in ((p12, (1, 2)), (p13, (1, 3)), (p23, (2, 3))):
        assert task.displace(p, i, j) == pytest.approx(p, abs=1e-12)
    ip = task.image_poles()
    assert ip[0] == p12 and ip[1] == p13
    assert ip[2] == pytest.approx(task.displace(p23, 2, 1))
    assert task.image_poles_in(1) == ip
    with pytest.raises(InvalidInputError):
        task.image_poles_in(4)
    a = task.pole_triangle_angles()
    for got, want in zip(a, [r / 2 for r in task.rotations]):
        d = (got - want) % math.pi
        assert min(d, math.pi - d) < 1e-9
    pc = task.pole_circle()
    assert pc["kind"] == "circle"
    for p in poles(task):
        assert math.dist(p, pc["center"]) == pytest.approx(pc["radius"])
    assert task.rotations == pytest.approx([0.4, 1.1, 0.7])
    assert [task.rotation(i, j) for i, j in ((1, 2), (1, 3), (2, 3))] == task.rotations
    assert task.rotation(2, 1) == pytest.approx(-0.4)


def test_maps_round_trip(task):
    y = (1.0, -2.0)
    x = task.circle_point(y)
    assert task.center_point(x) == pytest.approx(y)
    ys = np.array([[1.0, -2.0], [0.5, 3.0], list(poles(task)[0])])
    xs, ok = task.circle_points(ys)
    assert xs.shape == (3, 2) and list(ok) == [True, True, False]
    assert np.isnan(xs[2]).all()
    back, ok2 = task.center_points(xs[:2])
    assert ok2.all() and np.allclose(back, ys[:2])
    assert task.dyad(y) == (y, pytest.approx(x))
    with pytest.raises(InvalidInputError):
        task.circle_points(np.zeros((3, 3)))


def test_degenerate_and_invalid_inputs(task):
    with pytest.raises(DegenerateError, match="at infinity"):
        pc = task.pole_circle()
        c, r = pc["center"], pc["radius"]
        task.circle_point((c[0] + r, c[1]))
    with pytest.raises(DegenerateError, match="not unique"):
        task.circle_point(poles(task)[0])
    with pytest.raises(DegenerateError, match="translation"):
        Task([(0, 0, 0.3), (1, 0, 0.3), (2, 2, 0.3)])
    with pytest.raises(DegenerateError, match="translation"):
        Task([(0, 0, 0.3), (1, 0, 0.3), (2, 2, 1.0)]).pole_circle()
    with pytest.raises(DegenerateError, match="equal"):
        Task([(0, 0, 0.3), (0, 0, 0.3), (2, 2, 1.0)])
    with pytest.raises(InvalidInputError, match="3 to 5 poses"):
        Task([(0, 0, 0.3), (2, 2, 1.0)])
    with pytest.raises(InvalidInputError, match="finite"):
        Task([(0, 0, math.nan), (1, 0, 0.3), (2, 2, 1.0)])
    with pytest.raises(TypeError, match="point"):
        task.circle_point("here")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="point"):
        task.circle_point((1.0, 2.0, 3.0))  # type: ignore[arg-type]


def test_filemon_fixed_names(task):
    f = task.filemon((4.0, -1.0))
    assert isinstance(f, Filemon)
    c1 = task.circle_point((4.0, -1.0))
    assert f.driven_circle == pytest.approx(c1)
    assert isinstance(f.all_defective, bool)
    if not f.all_defective:
        assert len(f.lines) == 2 and len(f.conics) == 2
        for (point, direction), conic in zip(f.lines, f.conics):
            assert point == pytest.approx(c1)
            assert math.hypot(*direction) > 0
            assert isinstance(conic, Conic)
            assert len(conic.coefficients) == 6
            assert conic.kind in ("ellipse", "hyperbola", "parabola", "degenerate")
            # Property 2: through the poles and C0.
            for p in poles(task) + [(4.0, -1.0)]:
                assert conic.distance(p) < 1e-9
    for method in ("conic", "direct", "simulate"):
        assert isinstance(f.is_branch_free((1.0, 1.0), method=method), bool)
    with pytest.raises(InvalidInputError, match="method"):
        f.is_branch_free((1.0, 1.0), method="guess")  # type: ignore[arg-type]


def test_the_three_methods_agree_on_a_grid(task):
    rng = np.random.default_rng(1)
    checked = circuit = 0
    for c0 in rng.uniform(-6, 6, size=(10, 2)):
        try:
            f = task.filemon(tuple(c0))
        except DegenerateError:
            continue
        if f.all_defective:
            continue
        ga, gb = f.conics
        for a0 in rng.uniform(-8, 8, size=(40, 2)):
            p = tuple(a0)
            if ga.distance(p) < 1e-6 or gb.distance(p) < 1e-6:
                continue
            try:
                d = f.classify(p, "direct")
                s = f.classify(p, "simulate")
            except DegenerateError:
                continue
            c = f.classify(p, "conic")
            assert c == d, p
            if s != "boundary" and s != c:
                # simulate also sees the circuit defect of an input that
                # rocks in two arcs (poses on both), which the sign tests
                # cannot; beyond that the methods agree.
                assert (c, s) == ("free", "defective"), p
                sfb = f.four_bar(p)
                assert len(sfb.fourbar.input_range or []) == 2, p
                assert not sfb.figures.one_circuit and not sfb.figures.feasible, p
                circuit += 1
            checked += 1
    assert checked > 100
    assert circuit < checked / 4


def test_built_four_bar_passes_through_the_poses(task):
    fb = task.four_bar((-1.0, 3.0), (4.0, -1.0))
    for k in range(3):
        mode = fb.modes[k]
        assert mode in ("open", "crossed")
        x, y, a = fb.pose_at(fb.input_angles[k], mode)
        px, py, pa = POSES[k]
        assert (x, y) == pytest.approx((px, py), abs=1e-9)
        assert math.remainder(a - pa, 2 * math.pi) == pytest.approx(0, abs=1e-9)
    assert isinstance(fb.fourbar, burmester.FourBar)
    f = task.filemon((4.0, -1.0))
    assert f.is_branch_free((-1.0, 3.0)) == fb.branch_free


def test_conic_api():
    h = Conic(1, 0, -1, 0, 0, -1)
    assert h.kind == "hyperbola"
    assert h((1.0, 0.0)) == pytest.approx(0)
    assert h.side((0.0, 0.0)) == -1 and h.side((3.0, 0.0)) == 1
    assert h.center == pytest.approx((0, 0))
    lines = h.polylines(-5, 5, -5, 5)
    assert len(lines) == 2
    for l in lines:
        assert l.shape[1] == 2
        assert np.allclose(l[:, 0] ** 2 - l[:, 1] ** 2, 1, atol=1e-6)
    v = h.evaluate_many([[1.0, 0.0], [0.0, 0.0]])
    assert v.shape == (2,)
    with pytest.raises(InvalidInputError):
        h.polylines(1, 0, 0, 1)
    with pytest.raises(InvalidInputError):
        Conic(0, 0, 0, 0, 0, 1)
    assert Conic(1, 0, 1, 0, 0, -1).kind == "ellipse"
    assert Conic(1, 0, 0, 0, -1, 0).kind == "parabola"
    assert Conic(1, 0, -1, 0, 0, 0).kind == "degenerate"


def test_invariance_under_moving_rotating_and_scaling(task):
    k, ang, off = 3.7, 0.9, (10.0, -4.0)

    def T(p):
        q = rot((p[0] * k, p[1] * k), ang)
        return (q[0] + off[0], q[1] + off[1])

    t2 = Task([(*T((x, y)), a + ang) for x, y, a in POSES])
    for p, q in zip(poles(task), poles(t2)):
        assert T(p) == pytest.approx(q)
    f1, f2 = task.filemon((4.0, -1.0)), t2.filemon(T((4.0, -1.0)))
    rng = np.random.default_rng(7)
    for a0 in rng.uniform(-8, 8, size=(200, 2)):
        p = tuple(a0)
        assert f1.classify(p) == f2.classify(T(p))
