"""Four- and five-pose synthesis from Python: the Burmester curves (a
``Cubic``), their maps, the points ``Q_jk``, the dyads along the curves and
the Burmester points, checked against things computed independently of the
core: tasks made by driving a known four-bar (its two dyads must be found),
the concyclicity of every traced point's circle point over the poses, and
the worked example of ``shared/notes/positions-4-5.md``."""

import math
import pickle

import numpy as np
import pytest

import burmester
from burmester import Cubic, DegenerateError, FourBar, InvalidInputError, SynthesizedFourBar, Task

# The known linkage of the worked example: crank-rocker A0 = (0, 0),
# B0 = (4, 0), crank 1.5, coupler 3.5, rocker 3; the coupler frame at the
# crank joint A, x toward the rocker joint B; the coupler point (1, 1.5).
A0, B0 = (0.0, 0.0), (4.0, 0.0)
LINKAGE = FourBar.from_pivots(A0, B0, 1.5, 3.5, 3.0)
POINT = (1.0, 1.5)
ANGLES_DEG = (20.0, 70.0, 120.0, 170.0, 230.0)

# positions-4-5.md, section 6: the five poses (angles in degrees) and the
# four Burmester points (center; circle point at pose 1; radius).
NOTES_POSES = [
    (1.049199280691, 2.279426358634, 45.220037141544),
    (0.734502065472, 3.198658887874, 26.633426990744),
    (-0.378159188147, 3.063048993013, 21.786789298262),
    (-1.268710439724, 2.051150142014, 27.048624103934),
    (-1.411118156972, 0.597429126400, 48.044287536536),
]
NOTES_BURMESTER = [
    ((0.0, 0.0), (1.4095389312, 0.5130302150), 1.5),
    ((4.0, 0.0), (3.8748900012, 2.9973901128), 3.0),
    ((9.1415535429, 5.4771377313), (10.0779175389, 7.0028629572), 1.7901438484),
    ((28.5694893347, -40.1577865973), (-3.2276569999, 12.3029832658), 61.3448521854),
]


def drive(angles_deg, linkage=LINKAGE, point=POINT, mode="open"):
    """The coupler poses of a four-bar driven to the crank angles, and its
    two moving pivots at the first: ``(poses, A1, B1)``."""
    poses, first = [], None
    for d in angles_deg:
        _, a, b, _ = linkage.joints(math.radians(d), mode)
        phi = math.atan2(b[1] - a[1], b[0] - a[0])
        c, s = math.cos(phi), math.sin(phi)
        poses.append((a[0] + c * point[0] - s * point[1], a[1] + s * point[0] + c * point[1], phi))
        if first is None:
            first = (a, b)
    return poses, first[0], first[1]


def close(p, q, tol):
    return math.hypot(p[0] - q[0], p[1] - q[1]) <= tol


def radii(task, center, circle):
    """The distances of the circle point's positions at every pose from the center."""
    return [math.dist(task.displace(circle, 1, k), center) for k in range(1, len(task) + 1)]


def spread(rs):
    return (max(rs) - min(rs)) / max(rs)


FOUR, A1, B1 = drive(ANGLES_DEG[:4])
FIVE, _, _ = drive(ANGLES_DEG)


def test_the_generated_poses_are_those_of_the_notes():
    for (x, y, a), (nx, ny, na) in zip(FIVE, NOTES_POSES):
        assert (x, y) == pytest.approx((nx, ny), abs=1e-11)
        assert math.degrees(a) == pytest.approx(na, abs=1e-10)


# ---------------------------------------------------------------------------
# Four poses


def test_the_known_dyads_lie_on_the_curves():
    t = Task(FOUR)
    cpc, cic = t.center_point_curve(), t.circle_point_curve()
    assert isinstance(cpc, Cubic) and cpc.degree == 3 and cpc.is_circular and cic.is_circular
    # "Zero" relative to the curve's size around the task: its values on a
    # ring of points at the task's scale.
    ring = [(3 * t.scale * math.cos(a), 3 * t.scale * math.sin(a)) for a in np.linspace(0, 2 * math.pi, 24)]
    for curve, points in ((cpc, (A0, B0)), (cic, (A1, B1))):
        typical = max(abs(curve.evaluate(q)) for q in ring)
        for p in points:
            assert abs(curve.evaluate(p)) <= 1e-12 * typical
            assert curve(p) == curve.evaluate(p)
            assert curve.distance(p) <= 1e-10 * t.scale
    # The maps between the curves give the known linkage's pivots.
    assert close(t.circle_point(A0), A1, 1e-9)
    assert close(t.circle_point(B0), B1, 1e-9)
    assert close(t.center_point(A1), A0, 1e-9)
    assert close(t.center_point(B1), B0, 1e-9)
    assert t.dyad(B0)[1] == pytest.approx(B1, abs=1e-9)
    # Arrays too.
    pts, ok = t.circle_points([A0, B0, (50.0, 50.0)])
    assert ok.tolist() == [True, True, False]
    assert pts[0] == pytest.approx(A1, abs=1e-9) and np.isnan(pts[2]).all()
    # The poles lie on the center-point curve.
    for pole in t.poles:
        assert pole.point is not None and cpc.distance(pole.point) <= 1e-9 * t.scale


def test_the_four_bar_of_the_known_dyads_is_the_linkage():
    t = Task(FOUR)
    sfb = t.four_bar(A0, B0)
    assert sfb.fourbar.lengths == pytest.approx((4.0, 1.5, 3.5, 3.0), abs=1e-9)
    assert sfb.input_angles == pytest.approx([math.radians(d) for d in ANGLES_DEG[:4]], abs=1e-9)
    assert sfb.branch_free and sfb.modes == ["open"] * 4
    assert sfb.figures.direction == "ccw"
    # Driving it to its input angles reaches the poses.
    for theta, pose in zip(sfb.input_angles, FOUR):
        assert sfb.pose_at(theta, "open") == pytest.approx(pose, abs=1e-9)
    assert t.crank_angles(A0) == pytest.approx(sfb.input_angles, abs=1e-9)


def test_every_traced_point_is_a_center_point():
    """Every vertex of the traced center-point curve has a circle point whose
    four positions are on one circle about it (to a relative 1e-7)."""
    t = Task(FOUR)
    cpc = t.center_point_curve()
    lines = cpc.polylines(-12.0, 12.0, -12.0, 12.0, tolerance=1e-3)
    assert lines and all(pl.ndim == 2 and pl.shape[1] == 2 for pl in lines)
    checked = 0
    for pl in lines:
        for g in pl:
            g = (float(g[0]), float(g[1]))
            try:
                z = t.circle_point(g)
            except DegenerateError as e:  # where the circle point is at infinity or undefined
                assert e.cause in ("at_infinity", "undefined")
                continue
            assert spread(radii(t, g, z)) <= 1e-7, g
            checked += 1
    assert checked > 200
    # The same for the circle-point curve and its center points.
    for pl in t.circle_point_curve().polylines(-12.0, 12.0, -12.0, 12.0):
        for z in pl[::5]:
            z = (float(z[0]), float(z[1]))
            try:
                g = t.center_point(z)
            except DegenerateError:
                continue
            assert spread(radii(t, g, z)) <= 1e-7, z


def test_a_finer_tolerance_gives_more_points_on_the_same_curve():
    cpc = Task(FOUR).center_point_curve()
    coarse = sum(len(p) for p in cpc.polylines(-12, 12, -12, 12))
    fine = cpc.polylines(-12, 12, -12, 12, tolerance=1e-5)
    assert sum(len(p) for p in fine) > coarse
    assert max(cpc.distance(tuple(q)) for p in fine for q in p) <= 1e-9
    with pytest.raises(InvalidInputError) as e:
        cpc.polylines(-12, 12, -12, 12, tolerance=-1.0)
    assert e.value.cause == "outside_range" and e.value.name == "tolerance"


def test_coincidence_points_are_where_two_crank_positions_meet():
    t = Task(FOUR)
    qs = t.coincidence_points()
    assert [q.pair for q in qs] == [(1, 2), (1, 3), (1, 4), (2, 3), (2, 4), (3, 4)]
    cpc = t.center_point_curve()
    found = 0
    for q in qs:
        (j, k), center, circle = q.pair, q.center, q.circle
        assert repr(q).startswith(f"<CoincidencePoint Q{j}{k} ")
        if center is None or circle is None:
            continue
        found += 1
        size = t.scale + math.hypot(*center)
        assert cpc.distance(center) <= 1e-9 * size
        # Its circle point is the pole P_jk seen from pose 1: the moving
        # pivot is at the same place at poses j and k.
        assert close(t.circle_point(center), circle, 1e-7 * size)
        assert close(t.displace(circle, 1, j), t.displace(circle, 1, k), 1e-9 * size)
        assert spread(radii(t, center, circle)) <= 1e-9
    assert found >= 4


def test_dyads_sampled_along_the_curve():
    t = Task(FOUR)
    runs = t.curve_dyads(120)
    assert runs and sum(len(r) for r in runs) >= 100
    for run in runs:
        for d in run:
            center, circle, beta2, branch, order = d.center, d.circle, d.beta2, d.branch, d.order
            assert d.dyad == (center, circle)
            size = t.scale + math.hypot(*center)
            assert spread(radii(t, center, circle)) <= 1e-8
            assert t.center_point_curve().distance(center) <= 1e-8 * size
            assert -math.pi < beta2 <= math.pi
            assert branch in ("open", "crossed", None)
            assert sorted(order.split("-")) == ["1", "2", "3", "4"] and order.startswith("1-")
            assert d.direction == {"1-2-3-4": "counterclockwise", "1-4-3-2": "clockwise"}.get(order)
    # One dyad by its center: the known crank turns by 50 degrees from pose 1 to 2.
    d = t.curve_dyad(A0)
    assert d.center == A0 and d.circle == pytest.approx(A1, abs=1e-9)
    assert d.beta2 == pytest.approx(math.radians(50.0), abs=1e-9)
    assert (d.order, d.direction, d.branch) == ("1-2-3-4", "counterclockwise", "open")
    assert pickle.loads(pickle.dumps(d)) == d and d != runs[0][0]
    with pytest.raises(InvalidInputError) as e:
        t.curve_dyads(0)
    assert e.value.cause == "count_out_of_range"


def _crank_order(angles):
    """The cyclic order of crank angles, counter-clockwise from pose 1."""
    off = [((a - angles[0]) % (2 * math.pi), k + 1) for k, a in enumerate(angles)]
    return "-".join(str(k) for _, k in sorted(off))


def test_order_arcs_carry_the_order_of_their_dyads():
    t = Task(FOUR)
    arcs = t.order_arcs(-12, 12, -12, 12)
    assert len(arcs) >= 2
    directions = {"1-2-3-4": "counterclockwise", "1-4-3-2": "clockwise"}
    qs = [q.center for q in t.coincidence_points()]
    checked = 0
    for order, direction, pts in arcs:
        assert direction == directions.get(order)
        mid = tuple(map(float, pts[len(pts) // 2]))
        # At a Q_jk two crank positions coincide and the order is undefined
        # (an arc of two points ends there on both sides).
        if min(math.dist(mid, q) for q in qs) < 1e-6:
            continue
        try:
            angles = t.crank_angles(mid)
        except burmester.BurmesterError:
            continue
        assert _crank_order(angles) == order
        checked += 1
    assert checked >= len(arcs) - 2, (checked, len(arcs))
    # The known crank meets the poses in order, counter-clockwise.
    assert _crank_order(t.crank_angles(A0)) == "1-2-3-4"


def test_branch_free_arcs_against_the_built_linkages():
    """Filemon's construction with four lines against the assembly modes of
    the four-bars built at sampled driving pivots (a direct computation)."""
    t = Task(FOUR)
    arcs = t.branch_free_arcs(B0, -12, 12, -12, 12)
    assert arcs
    # The known crank is branch-free with the known rocker.
    assert t.curve_branch(B0, A0) == "free"
    checked = 0
    for pts in arcs:
        for g in pts[1:-1]:
            g = (float(g[0]), float(g[1]))
            try:
                sfb = t.four_bar(g, B0)
            except burmester.BurmesterError:
                continue
            assert sfb.branch_free, g
            assert t.curve_branch(B0, g) == "free"
            checked += 1
    assert checked > 20
    # Off the arcs, on the curve: defective where the built linkage is.
    defective = 0
    for pl in t.center_point_curve().polylines(-12, 12, -12, 12):
        for g in pl[::9]:
            g = (float(g[0]), float(g[1]))
            try:
                cls, sfb = t.curve_branch(B0, g), t.four_bar(g, B0)
            except burmester.BurmesterError:
                continue
            if cls == "defective":
                assert not sfb.branch_free, g
                defective += 1
    assert defective > 5
    with pytest.raises(InvalidInputError) as e:
        t.branch_free_arcs((5.0, 5.0), -12, 12, -12, 12)
    assert e.value.cause == "off_curve"


# ---------------------------------------------------------------------------
# Five poses


def test_the_known_dyads_are_burmester_points():
    t = Task(FIVE)
    points = t.burmester_points()
    assert len(points) == 4
    for center, circle in points:
        assert spread(radii(t, center, circle)) <= 1e-12
    for known in ((A0, A1), (B0, B1)):
        assert any(close(c, known[0], 1e-9) and close(z, known[1], 1e-9) for c, z in points), known


def test_the_worked_example_of_the_notes():
    t = Task([(x, y, math.radians(a)) for x, y, a in NOTES_POSES])
    points = t.burmester_points()
    assert len(points) == len(NOTES_BURMESTER)
    for (c, z), (nc, nz, r) in zip(points, NOTES_BURMESTER):
        size = 1.0 + math.hypot(*nc)
        assert c == pytest.approx(nc, abs=2e-9 * size)
        assert z == pytest.approx(nz, abs=2e-9 * size)
        assert math.dist(c, z) == pytest.approx(r, rel=1e-9)
    # The Burmester centers are common points of the two four-pose curves.
    for curve in t.burmester_curves():
        for c, _ in points:
            assert curve.distance(c) <= 1e-9 * (t.scale + math.hypot(*c))


def test_burmester_four_bars():
    t = Task(FIVE)
    points = t.burmester_points()
    bars = t.burmester_four_bars()
    assert {(i, j) for i, j, _ in bars} <= {(i, j) for i in range(4) for j in range(4) if i != j}
    assert len(bars) == 12
    ia = next(k for k, (c, _) in enumerate(points) if close(c, A0, 1e-9))
    ib = next(k for k, (c, _) in enumerate(points) if close(c, B0, 1e-9))
    by_pair = {(i, j): f for i, j, f in bars}
    known = by_pair[(ia, ib)]
    assert isinstance(known, SynthesizedFourBar)
    assert known.fourbar.lengths == pytest.approx((4.0, 1.5, 3.5, 3.0), abs=1e-9)
    # The generating pair, A0 driving, passes the five poses in one mode and
    # in order counter-clockwise (the notes); with B0 driving it does not.
    assert known.branch_free and known.figures.direction == "ccw"
    assert not (by_pair[(ib, ia)].branch_free and by_pair[(ib, ia)].figures.direction != "none")
    # Task.four_bar of two Burmester centers is the same linkage.
    assert t.four_bar(A0, B0).fourbar.lengths == pytest.approx(known.fourbar.lengths, abs=1e-12)
    assert t.dyad(A0)[1] == pytest.approx(A1, abs=1e-9)


# ---------------------------------------------------------------------------
# Errors


def test_off_curve_points_say_how_far():
    t = Task(FOUR)
    for call, what in ((t.circle_point, "center point"), (t.center_point, "circle point"),
                       (t.dyad, "center point"), (t.curve_dyad, "center point")):
        with pytest.raises(InvalidInputError) as e:
            call((5.0, 5.0))
        err = e.value
        assert err.cause == "off_curve" and err.what == what
        assert err.distance > err.tolerance > 0.0
        assert "from its curve" in str(err)
        back = pickle.loads(pickle.dumps(err))
        assert back.cause == "off_curve" and back.distance == err.distance
    with pytest.raises(InvalidInputError) as e:
        t.four_bar(A0, (5.0, 5.0))
    assert e.value.cause == "off_curve"
    # Five poses: a point of the curve of poses 1-4 that is no Burmester point.
    t5 = Task(FIVE)
    g = tuple(map(float, Task(FIVE[:4]).center_point_curve().polylines(-12, 12, -12, 12)[0][3]))
    with pytest.raises(InvalidInputError) as e:
        t5.four_bar(A0, g)
    assert e.value.cause == "not_a_dyad" and e.value.spread > e.value.tolerance
    with pytest.raises(InvalidInputError) as e:
        t5.dyad((5.0, 5.0))
    assert e.value.cause == "off_curve"


@pytest.mark.parametrize("n, methods, required", [
    (3, ["center_point_curve", "circle_point_curve", "coincidence_points", "order_arcs", "curve_dyads"], 4),
    (5, ["center_point_curve", "circle_point_curve", "coincidence_points", "order_arcs", "curve_dyads"], 4),
    (3, ["burmester_points", "burmester_curves", "burmester_four_bars"], 5),
    (4, ["burmester_points", "burmester_curves", "burmester_four_bars"], 5),
])
def test_methods_for_one_pose_count_say_which(n, methods, required):
    t = Task(FIVE[:n])
    args = {"order_arcs": (-1.0, 1.0, -1.0, 1.0)}
    for name in methods:
        with pytest.raises(InvalidInputError, match=f"needs a task of {required} poses") as e:
            getattr(t, name)(*args.get(name, ()))
        err = e.value
        assert (err.cause, err.required, err.found) == ("needs_poses", required, n), name
        assert err.method == f"Task.{name}"
    with pytest.raises(InvalidInputError) as e:
        Task(FIVE[:3]).curve_dyad(A0)
    assert (e.value.cause, e.value.required) == ("needs_poses", 4)


def test_cubic_records():
    # y^2 = x^3 - x: an oval and an unbounded branch.
    c = Cubic([0.0, -1.0, 0.0, 0.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0])
    assert c.evaluate((1.0, 0.0)) == 0.0 and c((2.0, math.sqrt(6.0))) == pytest.approx(0.0, abs=1e-12)
    assert c.coefficients == pytest.approx((0.0, -1.0, 0.0, 0.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0))
    assert c.degree == 3 and not c.is_circular
    lines = c.polylines(-3, 3, -3, 3)
    closed = [p for p in lines if (p[0] == p[-1]).all()]
    assert len(closed) == 1 and len(lines) == 2  # the oval, and the branch from edge to edge
    assert c.gradient((0.0, 0.0)) == pytest.approx((-1.0, 0.0))
    assert [p[1] for p in c.intersect_line((0.0, 0.0), (1.0, 0.0))] == pytest.approx([0.0] * 3)
    assert sorted(p[0] for p in c.intersect_line((0.0, 0.0), (1.0, 0.0))) == pytest.approx([-1.0, 0.0, 1.0])
    assert c == Cubic(list(c.coefficients)) and c != Task(FOUR).center_point_curve()
    assert repr(c).startswith("Cubic([")
    with pytest.raises(TypeError, match="ten coefficients"):
        Cubic([1.0, 2.0])
    with pytest.raises(InvalidInputError) as e:
        Cubic([math.nan] + [1.0] * 9)
    assert e.value.cause == "not_finite"
    with pytest.raises(InvalidInputError) as e:
        Cubic([1.0] + [0.0] * 9)
    assert e.value.cause == "cubic_coefficients"
    with pytest.raises(InvalidInputError) as e:
        c.evaluate((math.inf, 0.0))
    assert e.value.cause == "not_finite"


def test_curves_and_linkages_pickle():
    t = Task(FOUR)
    for curve in (t.center_point_curve(), t.circle_point_curve(), *Task(FIVE).burmester_curves()):
        back = pickle.loads(pickle.dumps(curve))
        assert back == curve and repr(back) == repr(curve)
        assert back.evaluate((1.0, 2.0)) == curve.evaluate((1.0, 2.0))
    for sfb in (t.four_bar(A0, B0), Task(FIVE).burmester_four_bars()[0][2]):
        back = pickle.loads(pickle.dumps(sfb))
        assert back == sfb and back.figures == sfb.figures


# ---------------------------------------------------------------------------
# Pictures


def test_the_picture_draws_the_curve_the_poles_and_the_points():
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from burmester import plot

    t = Task(FOUR)
    ax = plot.burmester_plane(t, (-12, 12, -12, 12))
    by_gid = {}
    for a in ax.get_children():
        by_gid.setdefault(a.get_gid(), []).append(a)
    curve = by_gid["center-point-curve"]
    assert len(curve) == len(t.order_arcs(-12, 12, -12, 12))
    cpc = t.center_point_curve()
    for line in curve:
        for x, y in line.get_xydata()[::7]:
            assert cpc.distance((x, y)) <= 1e-9
    colors = {line.get_color() for line in curve}
    assert plot.ORDER_COLORS["counterclockwise"] in colors  # the known crank's arc
    (poles,) = by_gid["poles"]
    assert len(poles.get_xdata()) == 6
    (qs,) = by_gid["coincidence-points"]
    assert len(qs.get_xdata()) == sum(1 for q in t.coincidence_points() if q.center is not None)
    assert "poses" in by_gid
    plt.close(ax.figure)
    ax = plot.burmester_plane(t, (-12, 12, -12, 12), driven=B0, legend=False)
    bands = [a for a in ax.get_children() if a.get_gid() == "branch-free-arcs"]
    assert len(bands) == len(t.branch_free_arcs(B0, -12, 12, -12, 12))
    assert any(a.get_gid() == "driven-pivot" for a in ax.get_children())
    plt.close(ax.figure)

    t5 = Task(FIVE)
    ax = plot.burmester_plane(t5)
    (stars,) = [a for a in ax.get_children() if a.get_gid() == "burmester-points"]
    drawn = np.column_stack([stars.get_xdata(), stars.get_ydata()])
    assert drawn.tolist() == [list(c) for c, _ in t5.burmester_points()]
    assert any(a.get_gid() == "curve-1234" for a in ax.get_children())
    assert any(a.get_gid() == "curve-1235" for a in ax.get_children())
    plt.close(ax.figure)

    with pytest.raises(InvalidInputError) as e:
        plot.burmester_plane(Task(FIVE[:3]))
    assert e.value.cause == "needs_poses"


def test_the_circle_point_curve_by_order_and_branch():
    """The circle-point plane of four poses: its pieces are circle points
    whose dyads (from their center points) have the piece's order, and its
    branch-free arcs are the circle points of the branch-free driving dyads
    (against the built linkages)."""
    t = Task(FOUR)
    view = (-12, 12, -12, 12)
    arcs = t.order_arcs(*view, plane="circle")
    assert len(arcs) >= 2
    circle_curve = t.circle_point_curve()
    cuts = [q.circle for q in t.coincidence_points() if q.circle is not None]
    checked = 0
    for order, direction, pts in arcs:
        for z in pts[::5]:
            assert circle_curve.distance((float(z[0]), float(z[1]))) <= 1e-9
        mid = (float(pts[len(pts) // 2][0]), float(pts[len(pts) // 2][1]))
        if min(math.dist(mid, q) for q in cuts) < 1e-6:
            continue
        try:
            center = t.center_point(mid)
            angles = t.crank_angles(center)
        except burmester.BurmesterError:
            continue
        assert _crank_order(angles) == order
        checked += 1
    assert checked >= len(arcs) - 2
    # The known crank's circle point lies on a piece in order counter-clockwise.
    near = [(math.dist(A1, tuple(z)), d) for _, d, pts in arcs for z in pts]
    assert min(near)[1] == "counterclockwise"
    # Branch-free circle points: the built linkage with B0 driven is branch-free.
    free = t.branch_free_arcs(B0, *view, plane="circle")
    assert free
    built = 0
    for pts in free:
        for z in pts[1:-1:3]:
            try:
                sfb = t.four_bar(t.center_point((float(z[0]), float(z[1]))), B0)
            except burmester.BurmesterError:
                continue
            assert sfb.branch_free
            built += 1
    assert built > 10
    with pytest.raises(InvalidInputError) as e:
        t.order_arcs(*view, plane="coupler")
    assert e.value.cause == "unknown_name"


def test_the_circle_plane_picture_and_command(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from burmester import plot
    from burmester.cli import main

    t = Task(FOUR)
    view = (-12, 12, -12, 12)
    ax = plot.circle_curve_plane(t, view, driven=B0)
    by_gid = {}
    for a in ax.get_children():
        by_gid.setdefault(a.get_gid(), []).append(a)
    assert len(by_gid["circle-point-curve"]) == len(t.order_arcs(*view, plane="circle"))
    assert len(by_gid["branch-free-arcs"]) == len(t.branch_free_arcs(B0, *view, plane="circle"))
    (c1,) = by_gid["driven-circle-point"]
    assert tuple(c1.get_xydata()[0]) == pytest.approx(t.circle_point(B0))
    (images,) = by_gid["fixed-pivot-images"]
    for k, xy in enumerate(images.get_xydata(), start=1):
        assert tuple(xy) == pytest.approx(t.displace(B0, k, 1))
    # Filemon's lines pass through C1 and the image of C0 at their pose.
    for k in range(2, 5):
        (line,) = by_gid[f"filemon-line-{k}"]
        (x0, y0), (x1, y1) = line.get_xydata()
        for p in (t.circle_point(B0), t.displace(B0, k, 1)):
            cross = (x1 - x0) * (p[1] - y0) - (y1 - y0) * (p[0] - x0)
            assert abs(cross) <= 1e-9 * math.hypot(x1 - x0, y1 - y0) * (1 + math.dist(p, (x0, y0)))
    (qs,) = by_gid["coincidence-points"]
    assert len(qs.get_xdata()) == sum(1 for q in t.coincidence_points() if q.circle is not None)
    plt.close(ax.figure)
    with pytest.raises(InvalidInputError) as e:
        plot.circle_curve_plane(Task(FIVE))
    assert e.value.cause == "needs_poses"

    # burmester map --plane circle on a four-pose task file.
    lines = "".join(f"[[pose]]\nx = {x!r}\ny = {y!r}\nangle_deg = {math.degrees(a)!r}\n\n" for x, y, a in FOUR)
    path = tmp_path / "four.toml"
    path.write_text(lines)
    out = tmp_path / "circle.png"
    assert main(["map", str(path), "--plane", "circle", "-o", str(out)]) == 0
    assert out.stat().st_size > 1000
    assert main(["map", str(path), "--plane", "circle", "-o", str(tmp_path / "c.svg")]) == 0  # test_export
    five = tmp_path / "five.toml"
    five.write_text("".join(f"[[pose]]\nx = {x!r}\ny = {y!r}\nangle_deg = {math.degrees(a)!r}\n\n"
                            for x, y, a in FIVE))
    assert main(["map", str(five), "--plane", "circle", "-o", str(tmp_path / "f.png")]) == 2


def test_five_pose_task_files_rank_and_draw_their_burmester_four_bars(tmp_path, capsys):
    """``burmester pivots`` and ``linkage`` on a five-pose task file: every
    four-bar of two Burmester points, the known linkage (A0 driving, B0
    driven: branch-free, in order counter-clockwise) first."""
    import json

    from burmester import pivots as pv
    from burmester.cli import main

    path = tmp_path / "five.toml"
    path.write_text("".join(f"[[pose]]\nx = {x!r}\ny = {y!r}\nangle_deg = {math.degrees(a)!r}\n\n"
                            for x, y, a in FIVE))
    t = Task(FIVE)
    ranked = pv.rank_burmester(t, burmester.DesignLimits())
    assert len(ranked) == len(t.burmester_four_bars()) == 12
    best = ranked[0]
    points = t.burmester_points()
    assert close(points[best.driving][0], A0, 1e-8) and close(points[best.driven][0], B0, 1e-8)
    assert best.violations == [] and best.linkage.figures.direction == "ccw"
    assert best.score == best.linkage.score("balanced")
    # Acceptable first, each part by its score.
    flags = [bool(b.violations) for b in ranked]
    assert flags == sorted(flags)
    ok = [b.score for b in ranked if not b.violations]
    assert ok == sorted(ok, reverse=True)
    # The score is the documented formula of the linkage's figures.
    f = best.linkage.figures
    want = math.sin(math.radians(f.min_transmission_deg)) / math.sqrt(best.linkage.size_ratio * f.link_ratio)
    assert best.score == pytest.approx(want, rel=1e-12)
    assert best.linkage.score("transmission") == pytest.approx(math.radians(f.min_transmission_deg))
    with pytest.raises(InvalidInputError):
        best.linkage.score("pareto")

    assert main(["pivots", str(path), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert len(doc["burmester_points"]) == 4 and len(doc["linkages"]) == 12
    first = doc["linkages"][0]
    assert (first["driving"], first["driven"]) == (best.driving, best.driven)
    # The file's angles went through degrees: the same linkage to rounding.
    assert close(first["driving_center"], best.linkage.driving[0], 1e-9) and first["violations"] == []
    assert main(["pivots", str(path), "--top", "2"]) == 0
    table = capsys.readouterr().out
    assert f"B{best.driving + 1} -> B{best.driven + 1}" in table.splitlines()[7]  # after the header and its rule
    assert main(["pivots", str(path), "--rank-by", "pareto"]) == 2
    capsys.readouterr()

    out = tmp_path / "five.png"
    assert main(["linkage", str(path), "-o", str(out)]) == 0
    assert "B1 driving, B2 driven" in capsys.readouterr().out and out.stat().st_size > 1000
    assert main(["linkage", str(path), "--pivot", "0", "0", "-o", str(tmp_path / "p.png")]) == 2
