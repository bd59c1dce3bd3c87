"""The branch problem with a slider as the driven dyad (issue 27, part 2):
``burmester.SliderFilemon``, checked against a task made from a known
slider-crank (a press in millimetres), an independent slider-crank solver
written here, the revolute construction with its center far along the
guide's normal, and the circle-point-plane test."""

import math
import pickle

import numpy as np
import pytest

import burmester
from burmester import Filemon, Grid, InvalidInputError, SliderFilemon, Task

# A press: crank A0 = (0, 0), r = 60 mm; coupler A-B, 200 mm; the slider pin
# B on a guide through (20, 0) at 80 degrees (nearly vertical).
A0 = (0.0, 0.0)
R, L = 60.0, 200.0
G = (20.0, 0.0)
U = (math.cos(math.radians(80.0)), math.sin(math.radians(80.0)))
MODE = 1.0
PHIS = [math.radians(a) for a in (-30.0, 20.0, 75.0)]


def _parts(a0, r, l, g, u, phi):
    ax, ay = a0[0] + r * math.cos(phi) - g[0], a0[1] + r * math.sin(phi) - g[1]
    q = u[0] * ay - u[1] * ax
    return u[0] * ax + u[1] * ay, l * l - q * q


def _slider(a0, r, l, g, u, phi, mode):
    p, disc = _parts(a0, r, l, g, u, phi)
    t = p + mode * math.sqrt(disc)
    return (g[0] + t * u[0], g[1] + t * u[1])


def _press_task():
    poses = []
    for phi in PHIS:
        a = (A0[0] + R * math.cos(phi), A0[1] + R * math.sin(phi))
        b = _slider(A0, R, L, G, U, phi, MODE)
        poses.append((a[0], a[1], math.atan2(b[1] - a[1], b[0] - a[0])))
    return Task(poses), _slider(A0, R, L, G, U, PHIS[0], MODE)


def _displace(poses, k, z):
    (x1, y1, t1), (xk, yk, tk) = poses[0], poses[k]
    c, s = math.cos(tk - t1), math.sin(tk - t1)
    vx, vy = z[0] - x1, z[1] - y1
    return (xk + c * vx - s * vy, yk + s * vx + c * vy)


def _drive(poses, a0, a1, b1, u):
    """The assembly mode that reaches each pose at its crank angle (the
    solver above), and whether the crank turns between the poses without a
    dead position (every 5e-3 rad, either way round): "free", "defective",
    "circuit" or None (a pose within rounding of a dead position)."""
    r = math.dist(a0, a1)
    l = math.dist(a1, b1)
    modes, phis = [], []
    for k in range(len(poses)):
        a, b = _displace(poses, k, a1), _displace(poses, k, b1)
        phi = math.atan2(a[1] - a0[1], a[0] - a0[0])
        p, disc = _parts(a0, r, l, b1, u, phi)
        t = u[0] * (b[0] - b1[0]) + u[1] * (b[1] - b1[1])
        if disc <= 1e-6 * l * l or abs(t - p) <= 1e-6 * l:
            return None
        modes.append(math.copysign(1.0, t - p))
        phis.append(phi)
    if len(set(modes)) > 1:
        return "defective"

    def turns(f, t):
        d = (t - f) % (2 * math.pi)
        for delta in (d, d - 2 * math.pi):
            n = max(1, math.ceil(abs(delta) / 5e-3))
            if all(_parts(a0, r, l, b1, u, f + delta * s / n)[1] > 0 for s in range(n + 1)):
                return True
        return False

    return "free" if all(turns(phis[k], phis[k + 1]) for k in range(len(phis) - 1)) else "circuit"


@pytest.fixture(scope="module")
def press():
    task, b1 = _press_task()
    return task, b1, SliderFilemon(task, b1, U)


def test_the_press_crank_is_free_and_the_construction_is_the_slider(press):
    task, b1, f = press
    assert f.classify(A0) == "free" and f.classify(A0, "direct") == "free"
    assert f.circle == pytest.approx(b1, abs=0) and f.guide == pytest.approx(U, rel=1e-15)
    assert f.normal == pytest.approx((-U[1], U[0]), rel=1e-15)
    # n_k: the normal turned by theta_1 - theta_k.
    for k, d in enumerate(f.directions):
        t = task.poses[0][2] - task.poses[k][2]
        n = (-U[1], U[0])
        assert d == pytest.approx((math.cos(t) * n[0] - math.sin(t) * n[1],
                                   math.sin(t) * n[0] + math.cos(t) * n[1]), abs=1e-15)
    assert len(f.all_lines) == 3 and all(line[0] == f.circle for line in f.all_lines)
    assert f.all_defective is False and len(f.lines) == 2 and len(f.conics) == 2
    a, b = f.extreme_poses
    assert {a, b, f.middle_pose} == {1, 2, 3}
    # The conics pass through the poles.
    for c in f.conics:
        for p in task.poles:
            if p.point is not None:
                assert abs(c.evaluate(p.point)) <= 1e-9 * max(1.0, abs(c.evaluate((0.0, 0.0))))


def test_verdicts_agree_with_driving_the_built_slider_crank(press):
    task, b1, f = press
    rng = np.random.default_rng(27)
    counts = {"free": 0, "defective": 0, "circuit": 0, None: 0}
    for x, y in rng.uniform(-400, 400, size=(800, 2)):
        try:
            a1 = task.circle_point((x, y))
        except burmester.DegenerateError:
            continue
        verdict = _drive(task.poses, (x, y), a1, b1, f.guide)
        counts[verdict] += 1
        if verdict is None:
            continue
        want = "defective" if verdict == "defective" else "free"
        assert f.classify((x, y)) == want, (x, y, verdict)
        assert f.classify((x, y), "direct") == want, (x, y, verdict)
    assert counts["free"] > 300 and counts["defective"] > 50, counts


def test_the_limit_of_the_revolute_construction(press):
    task, b1, f = press
    n = f.normal
    c0 = (b1[0] + 1e7 * n[0], b1[1] + 1e7 * n[1])
    rev = task.filemon(c0)
    # The circle point of a center R away approaches C1 as 1/R.
    assert math.dist(rev.driven_circle, b1) < 1e-3 * task.scale
    rng = np.random.default_rng(5)
    compared = 0
    for x, y in rng.uniform(-400, 400, size=(2000, 2)):
        values = f.conic_values((x, y))
        if values is None or min(abs(v) for v in values) < 1e-6 * max(1.0, abs(values[0]) + abs(values[1])):
            continue
        # Away from the curves (a margin of 1 mm) the classes agree.
        if abs(rev.margin((x, y))) < 1.0:
            continue
        assert f.classify((x, y)) == rev.classify((x, y)), (x, y)
        compared += 1
    assert compared > 1500


def test_conic_agrees_with_the_circle_point_plane(press):
    task, b1, f = press
    rng = np.random.default_rng(7)
    pts = rng.uniform(-500, 500, size=(3000, 2))
    agree = 0
    for x, y in pts:
        try:
            a1 = task.circle_point((x, y))
        except burmester.DegenerateError:
            continue
        s = f.circle_signs(a1)
        if min(abs(v) for v in s) <= 1e-9 * (1.0 + math.dist(a1, b1)):
            continue
        assert f.classify((x, y)) == f.classify_circle_point(a1)
        agree += 1
    assert agree > 2900


def test_branch_map_is_the_pointwise_classification(press):
    _, _, f = press
    grid = Grid(-400, 400, -300, 300, 41, 31)
    for method in ("conic", "direct"):
        m = f.branch_map(grid, method=method)
        assert m.shape == (31, 41)
        want = np.array([[f.classify(grid.point(j, i), method) == "free" for i in range(41)] for j in range(31)])
        assert np.array_equal(m, want), method
    assert np.array_equal(f.branch_map(-400, 400, -300, 300, 41, 31), f.branch_map(grid))
    out = np.zeros((31, 41), dtype=bool)
    assert f.branch_map(grid, out=out) is out


def test_invariant_under_moving_rotating_and_scaling(press):
    task, b1, f = press
    s, rot, t = 0.001, 1.1, (350.0, -20.0)
    c, sn = math.cos(rot), math.sin(rot)

    def move(p):
        return (s * (c * p[0] - sn * p[1]) + t[0], s * (sn * p[0] + c * p[1]) + t[1])

    moved = Task([(*move(p[:2]), p[2] + rot) for p in task.poses])
    g = SliderFilemon(moved, move(b1), (c * U[0] - sn * U[1], sn * U[0] + c * U[1]))
    rng = np.random.default_rng(11)
    compared = 0
    for x, y in rng.uniform(-400, 400, size=(1000, 2)):
        vals = f.conic_values((x, y))
        if vals is None or min(abs(v) for v in vals) < 1e-6 * sum(abs(v) for v in vals):
            continue
        assert f.classify((x, y)) == g.classify(move((x, y)))
        compared += 1
    assert compared > 900


def test_pickles_to_an_equal_object(press):
    _, _, f = press
    for protocol in range(2, pickle.HIGHEST_PROTOCOL + 1):
        back = pickle.loads(pickle.dumps(f, protocol=protocol))
        assert type(back) is SliderFilemon and back == f and repr(back) == repr(f)
        assert np.array_equal(back.branch_map(-400, 400, -300, 300, 20, 10), f.branch_map(-400, 400, -300, 300, 20, 10))
    assert "SliderFilemon" in repr(f)


def test_errors_are_typed(press):
    task, b1, f = press
    with pytest.raises(InvalidInputError) as e:
        SliderFilemon(task, b1, (0.0, 0.0))
    assert e.value.cause == "zero_direction" and "slider guide direction" in str(e.value)
    with pytest.raises(InvalidInputError) as e:
        SliderFilemon(task, b1, (-U[1], U[0]))  # not the line of the pin's positions
    assert e.value.cause == "not_a_dyad" and "slider" in str(e.value)
    with pytest.raises(InvalidInputError) as e:
        SliderFilemon(task, (math.nan, 0.0), U)
    assert isinstance(e.value, ValueError)
    # The simulate method drives the slider-crank (test_slider_map).
    assert f.classify(A0, "simulate") == "free"
    assert f.branch_map(-1, 1, -1, 1, 3, 3, method="simulate").shape == (3, 3)
    with pytest.raises(InvalidInputError):
        f.classify(A0, "exact")
    four = Task([(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1), (4.0, 2.5, 1.5)])
    with pytest.raises(InvalidInputError) as e:
        SliderFilemon(four, (0.0, 0.0), (1.0, 0.0))
    assert e.value.cause == "needs_poses"
    assert isinstance(f, SliderFilemon) and not isinstance(f, Filemon)


def test_four_poses_arcs_agree_with_driving_the_slider_crank():
    phis = [math.radians(a) for a in (-30.0, 10.0, 45.0, 80.0)]
    poses = []
    for phi in phis:
        a = (A0[0] + R * math.cos(phi), A0[1] + R * math.sin(phi))
        b = _slider(A0, R, L, G, U, phi, MODE)
        poses.append((a[0], a[1], math.atan2(b[1] - a[1], b[0] - a[0])))
    task = Task(poses)
    b1 = _slider(A0, R, L, G, U, phis[0], MODE)
    assert burmester.slider_curve_branch(task, b1, U, A0) == "free"
    view = (-400.0, 400.0, -400.0, 400.0)
    arcs = burmester.slider_branch_free_arcs(task, b1, U, *view)
    assert arcs and all(a.shape[1] == 2 for a in arcs)
    for arc in arcs:
        for p in arc[1:-1:4]:
            assert burmester.slider_curve_branch(task, b1, U, tuple(p)) != "defective"
    counts = {"free": 0, "defective": 0, "circuit": 0, None: 0}
    for line in task.center_point_curve().polylines(*view):
        for x, y in line:
            try:
                a1 = task.circle_point((x, y))
            except burmester.BurmesterError:
                continue
            if math.dist(a1, b1) < 1e-6 or math.dist(a1, (x, y)) > 1e5:
                continue
            verdict = _drive(poses, (x, y), a1, b1, U)
            counts[verdict] += 1
            if verdict is not None:
                want = "defective" if verdict == "defective" else "free"
                assert burmester.slider_curve_branch(task, b1, U, (x, y)) == want, (x, y, verdict)
    assert counts["free"] > 40 and counts["defective"] > 15, counts
    with pytest.raises(InvalidInputError) as e:
        burmester.slider_curve_branch(task, b1, (-U[1], U[0]), A0)
    assert e.value.cause == "not_a_dyad"
    with pytest.raises(InvalidInputError) as e:
        burmester.slider_curve_branch(_press_task()[0], b1, U, A0)
    assert e.value.cause == "needs_poses"
