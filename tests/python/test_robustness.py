"""The public API under extreme floats, NaN, infinities, huge ints, wrong
types and wrong shapes (hypothesis).

Every call either returns finite values (NaN only where a validity mask
says so), or raises a ``BurmesterError`` subclass whose message says what to
change, or a ``TypeError`` for an argument of the wrong type. Nothing else
escapes (no ``OverflowError``, no plain ``ValueError``, no Rust panic) and
nothing crashes the interpreter.
"""

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import burmester
from burmester import BurmesterError, Conic, DesignLimits, FourBar, Grid, InvalidInputError, Task
from conftest import POSES


def fb4(ground, crank, coupler, rocker, **kw):
    """FourBar with its lengths by keyword, in the order ground, crank, coupler, rocker."""
    return FourBar(ground=ground, crank=crank, coupler=coupler, rocker=rocker, **kw)

# A warning (NumPy dropping an imaginary part, say) is a silent coercion: fail.
pytestmark = pytest.mark.filterwarnings("error")

SETTINGS = settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# Numbers as a user might pass them: any double (NaN, infinities, subnormals,
# huge), ints far beyond a double, and ordinary values.
numbers = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(min_value=-(10**400), max_value=10**400),
    st.floats(min_value=-10, max_value=10),
    st.sampled_from([0.0, -0.0, 5e-324, 1e-300, 1e300, 1.7976931348623157e308]),
)
moderate = st.floats(min_value=-20, max_value=20, allow_nan=False)
# Not numbers at all.
junk = st.one_of(
    st.none(),
    st.text(max_size=3),
    st.complex_numbers(allow_nan=False, max_magnitude=10).filter(lambda z: z.imag != 0),
    st.binary(max_size=2),
    st.dictionaries(st.integers(), st.integers(), max_size=1),
    st.just(object()),
)


def finite(*values):
    for v in values:
        if isinstance(v, tuple):
            finite(*v)
        else:
            assert math.isfinite(v), values


def acceptable(exc):
    """The error types a call may raise, with a message that says something."""
    assert isinstance(exc, (BurmesterError, TypeError)), repr(exc)
    assert str(exc), repr(exc)
    if isinstance(exc, BurmesterError):
        # It says why, as data.
        assert isinstance(exc.cause, str) and exc.cause, repr(exc)
        # The message says what to change.
        msg = str(exc)
        assert any(
            w in msg
            for w in ("pass", "choose", "rotate", "move", "rescale", "shorten", "step", "use one of", "reduce", "but")
        ), msg


def call(fn, *args, **kwargs):
    try:
        return fn(*args, **kwargs), None
    except Exception as exc:  # noqa: BLE001 - checked by acceptable()
        acceptable(exc)
        return None, exc


@SETTINGS
@given(st.lists(numbers, min_size=4, max_size=4), numbers, numbers, numbers, st.lists(numbers, max_size=5))
def test_fourbar_with_any_numbers(lengths, ox, angle, theta2, thetas):
    fb, err = call(fb4, *lengths, origin=(ox, 0.0), ground_angle=angle)
    if err is not None:
        return
    finite(fb.lengths, fb.input_pivot, fb.output_pivot, fb.link_ratio)
    for arc in fb.input_range or []:
        finite(arc)
    finite(*fb.dead_positions)
    for mode in ("open", "crossed"):
        r, err = call(fb.solve, theta2, mode)
        if r is not None:
            finite(r)
            finite(call(fb.joints, theta2, mode)[0])
            c = fb.configuration(theta2, mode)
            if not c.toggle:
                # The mode asked for is the mode returned.
                assert c.coupler_rocker_angle * (1 if mode == "open" else -1) > -1e-9
        r, _ = call(fb.coupler_point, theta2, (1.0, 0.5), mode)
        if r is not None:
            finite(r)
    r, err = call(fb.solve_many, thetas)
    if r is not None:
        t3, t4, ok = r
        assert np.array_equal(np.isfinite(t3), ok) and np.array_equal(np.isfinite(t4), ok)


@SETTINGS
@given(st.lists(st.lists(numbers, min_size=0, max_size=4), min_size=0, max_size=6), st.tuples(numbers, numbers))
def test_task_with_any_numbers(poses, point):
    t, err = call(Task, poses)
    if err is not None:
        return
    finite(t.scale, tuple(t.rotations))
    for pole in t.poles:
        finite(pole.point if pole.point is not None else pole.direction)
    if len(t) != 3:
        return
    finite(t.image_poles(), t.pole_triangle_angles())
    for m in (t.circle_point, t.center_point):
        r, err = call(m, point)
        if r is not None:
            finite(r)
    r, err = call(t.filemon, point)
    if r is not None:
        finite(r.driven_circle)


@SETTINGS
@given(st.tuples(numbers, numbers), st.text(max_size=8) | st.sampled_from(["conic", "direct", "simulate", "Direct"]))
def test_classify_with_any_point_and_method(point, method):
    f = Task(POSES).filemon((4.0, -1.0))
    r, err = call(f.classify, point, method)
    if r is not None:
        assert r in ("free", "defective", "boundary")
    if all(isinstance(v, float) or abs(v) < 1e300 for v in point):
        m, err = call(f.margin, point)
        if m is not None and all(math.isfinite(float(v)) for v in point):
            assert not math.isnan(m)


@SETTINGS
@given(
    st.lists(numbers, min_size=4, max_size=4),
    st.integers(min_value=-3, max_value=9) | st.integers(min_value=2**62, max_value=2**80),
    st.integers(min_value=-3, max_value=9),
    st.sampled_from(["conic", "direct", "simulate", "fast"]),
)
def test_branch_and_margin_maps_with_any_grid(bounds, nx, ny, method):
    f = Task(POSES).filemon((4.0, -1.0))
    m, err = call(f.branch_map, *bounds, nx, ny, method)
    if m is not None:
        assert m.shape == (ny, nx) and m.dtype == np.bool_
    mm, err = call(f.margin_map, *bounds, nx, ny)
    if mm is not None:
        assert mm.shape == (ny, nx) and not np.isnan(mm).any()


@SETTINGS
@given(
    hnp.arrays(
        dtype=st.sampled_from([np.float64, np.float32, np.int64, np.bool_]),
        shape=hnp.array_shapes(min_dims=0, max_dims=3, max_side=3),
        elements=None,
    )
)
def test_point_arrays_of_any_shape_and_values(a):
    t = Task(POSES)
    r, err = call(t.circle_points, a)
    if a.ndim == 0 or a.shape[-1] != 2:
        assert isinstance(err, InvalidInputError), (a.shape, err)
        return
    pts, ok = r
    assert pts.shape == a.shape and ok.shape == a.shape[:-1]
    assert np.array_equal(np.isfinite(pts).all(axis=-1), ok)
    v, err = call(Conic(1, 0, -1, 0, 0, -1).evaluate_many, a)
    finite_in = np.isfinite(a.astype(np.float64)).all(axis=-1)
    if finite_in.all():
        # Finite points: finite values, of the input's leading shape.
        assert err is None and v.shape == a.shape[:-1]
        assert np.isfinite(v).all()
    else:
        # A non-finite point is refused (no NaN handed back), naming it.
        assert isinstance(err, InvalidInputError) and err.cause == "not_finite", err
        assert not math.isfinite(err.value)


@SETTINGS
@given(st.lists(numbers, min_size=6, max_size=6), st.lists(numbers, min_size=4, max_size=4), st.tuples(numbers, numbers))
def test_conic_with_any_coefficients(q, vp, point):
    c, err = call(Conic, *q)
    if err is not None:
        return
    finite(c.coefficients, c.axis_angle)
    if c.center is not None:
        finite(c.center)
    v, err = call(c.evaluate, point)
    if v is not None and all(math.isfinite(float(p)) for p in point):
        assert math.isfinite(v)
    lines, err = call(c.polylines, *vp)
    if lines is not None:
        xmin, xmax, ymin, ymax = (float(b) for b in vp)
        slack = 1e-9 * (abs(xmax) + abs(xmin) + abs(ymax) + abs(ymin)) + 1e-6 * (xmax - xmin + ymax - ymin)
        for l in lines:
            assert np.isfinite(l).all()
            assert (l[:, 0] >= xmin - slack).all() and (l[:, 0] <= xmax + slack).all()
            assert (l[:, 1] >= ymin - slack).all() and (l[:, 1] <= ymax + slack).all()


@SETTINGS
@given(st.lists(moderate, min_size=2, max_size=2), moderate)
def test_curves_and_maps_on_ordinary_input_never_hand_back_nan(p, theta):
    t = Task(POSES)
    f = t.filemon((4.0, -1.0))
    for conic in f.conics:
        finite(conic.evaluate(tuple(p)), conic.distance(tuple(p)) if conic.evaluate(tuple(p)) else 0.0)
    finite(f.margin(tuple(p)))
    fb = fb4(4, 1, 3, 3)
    finite(fb.solve(theta), fb.joints(theta))


# Every public callable, with each argument replaced by something that is not
# what it should be.
def _targets():
    fb = fb4(4.0, 1.0, 3.0, 3.0)
    t = Task(POSES)
    f = t.filemon((4.0, -1.0))
    c = f.conics[0]
    s = t.four_bar((-1.0, 3.0), (4.0, -1.0))
    sm = f.solution_map(-8.0, 8.0, -8.0, 8.0, 6, 5)
    g = Grid(-1.0, 1.0, -1.0, 1.0, 4, 3)
    return [
        (fb4, (4.0, 1.0, 3.0, 3.0)),
        (FourBar.from_pivots, ((0.0, 0.0), (4.0, 0.0), 1.0, 3.0, 3.0)),
        (fb.solve, (0.5, "open")),
        (fb.configuration, (0.5, "open")),
        (fb.solve_many, ([0.5, 1.0], "open")),
        (fb.transmission_angle, (0.5, "open")),
        (fb.joints, (0.5, "open")),
        (fb.coupler_point, (0.5, (1.0, 0.0), "open")),
        (fb.coupler_path, ((1.0, 0.0), [0.5], "open")),
        (Task, (POSES,)),
        (t.displace, ((1.0, 2.0), 1, 2)),
        (t.rotation, (1, 2)),
        (t.image_poles_in, (2,)),
        (t.circle_point, ((1.0, -2.0),)),
        (t.center_point, ((1.0, -2.0),)),
        (t.circle_points, ([[1.0, -2.0]],)),
        (t.center_points, ([[1.0, -2.0]],)),
        (t.dyad, ((1.0, -2.0),)),
        (t.crank_angles, ((1.0, -2.0),)),
        (t.filemon, ((4.0, -1.0),)),
        (t.four_bar, ((-1.0, 3.0), (4.0, -1.0))),
        (t.line_to_conic, ((0.0, 0.0), (1.0, 0.5))),
        (f.line_conic, (1,)),
        (f.is_branch_free, ((1.0, 1.0), "conic")),
        (f.classify, ((1.0, 1.0), "direct")),
        (f.classify_circle_point, ((1.0, 1.0),)),
        (f.circle_signs, ((1.0, 1.0),)),
        (f.conic_values, ((1.0, 1.0),)),
        (f.branch_map, (-1.0, 1.0, -1.0, 1.0, 4, 3, "conic")),
        (f.branch_map, (g, "direct")),
        (f.margin_map, (-1.0, 1.0, -1.0, 1.0, 4, 3)),
        (f.margin_map, (g,)),
        (f.margin, ((1.0, 1.0),)),
        (f.four_bar, ((-1.0, 3.0),)),
        (Conic, (1.0, 0.0, -1.0, 0.0, 0.0, -1.0)),
        (c.evaluate, ((1.0, 1.0),)),
        (c.evaluate_many, ([[1.0, 1.0]],)),
        (c.side, ((1.0, 1.0),)),
        (c.distance, ((1.0, 1.0),)),
        (c.polylines, (-5.0, 5.0, -5.0, 5.0, 0.1)),
        (s.pose_at, (0.5, "open")),
        (s.travel_angles, (16,)),
        (f.solution_map, (-1.0, 1.0, -1.0, 1.0, 4, 3)),
        (f.solution_map, (g,)),
        (t.driven_solution_map, ((-1.0, 3.0), -1.0, 1.0, -1.0, 1.0, 4, 3)),
        (t.driven_solution_map, ((-1.0, 3.0), g)),
        (sm.best_pivots, (3, 0.1, "margin")),
        (sm.point, (1, 2)),
        (sm.linkage, (1, 2)),
        (sm.margin, (1, 2)),
        (Grid, (-1.0, 1.0, -1.0, 1.0, 4, 3)),
        (g.point, (1, 2)),
        (g.nearest, ((0.3, 0.2),)),
        (DesignLimits, (30.0, 10.0, "crank")),
        (burmester.Pole, ((1, 2), (0.0, 1.0))),
        (burmester.Pole, ((1, 2), None, (0.0, 1.0))),
        (burmester.Pivot, ((1.0, 2.0), (1, 2), s, 0.5, "margin")),
        (burmester.clip_line, ((0.0, 0.0), (1.0, 1.0), (-1.0, 1.0, -1.0, 1.0))),
    ]


BAD = [
    None,
    "x",
    1j,
    [1.0, 2.0, 3.0],
    {},
    object(),
    b"",
    10**400,
    -(10**400),
    -1,
    2**70,
    math.nan,
    math.inf,
    -math.inf,
    np.array([[1.0, 2.0], [3.0, 4.0]]),
    np.array(["a", "b"]),
    np.array([1 + 2j, 3j]),
    np.complex64(1 + 1j),
    np.array([np.complex128(1j), 2.0]),
    [[1.0], [2.0, 3.0]],
    [None, None],
    (math.nan, 0.0),
    (10**400, 0.0),
]


@pytest.mark.parametrize("target", range(len(_targets())))
def test_every_argument_replaced_by_something_wrong(target):
    fn, args = _targets()[target]
    for k in range(len(args)):
        for bad in BAD:
            new = list(args)
            new[k] = bad
            r, err = call(fn, *new)
            if err is None:
                # Accepted: the bad value was a legitimate input here (a
                # list of numbers where an array goes, -1 as an angle).
                continue


@pytest.mark.parametrize(
    "key", ["limits", "min_transmission_deg", "max_link_ratio", "input", "base_plate", "obstacles", "link_width",
            "travel_samples", "progress"]
)
def test_solution_map_keywords_replaced_by_something_wrong(key):
    f = Task(POSES).filemon((4.0, -1.0))
    good = {"obstacles": [[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]], "link_width": 0.1}
    for bad in BAD:
        kwargs = dict(good)
        kwargs[key] = bad
        call(f.solution_map, -8.0, 8.0, -8.0, 8.0, 5, 4, **kwargs)


def test_documented_error_types_and_messages():
    def raises(cls, match, fn, cause, **fields):
        with pytest.raises(cls, match=match) as e:
            fn()
        assert e.value.cause == cause, e.value.cause
        for name, value in fields.items():
            assert getattr(e.value, name) == value, (name, getattr(e.value, name))

    raises(InvalidInputError, "too large to be a float", lambda: fb4(10**400, 1, 1, 1), "too_large")
    raises(InvalidInputError, "non-negative integer", lambda: Task(POSES).displace((0, 0), -1, 2),
           "count_out_of_range")
    raises(InvalidInputError, "pose 2 must be", lambda: Task([(0, 0, 0), (1, 2), (3, 2, 1.1)]), "pose_shape")
    with pytest.raises(TypeError, match="complex"):
        Task(POSES).circle_points(np.array([[1j, 0]]))
    with pytest.raises(TypeError, match="real number"):
        Task(POSES).circle_points(np.array([[None, 0]], dtype=object))
    raises(InvalidInputError, "one shape", lambda: fb4(4, 1, 3, 3).solve_many([[1.0], [2.0, 3.0]]),
           "not_rectangular")
    raises(InvalidInputError, "beyond the limit of 1e100",
           lambda: Task([(1e101, 0, 0), (2, 0.5, 0.4), (3, 2, 1.1)]),
           "too_large", name="pose 1 x", value=1e101, limit=1e100)
    raises(burmester.DegenerateError, "1e-6",
           lambda: Task([(0, 0, 0.3), (1, 0, 0.3 + 1e-7), (3, 2, 1.1)]).pole_triangle_angles(),
           "pure_translation", i=1, j=2)
    raises(burmester.DegenerateError, "parallelogram",
           lambda: Task([(0, 0, 0.3), (1, 0, 0.3 + 1e-7), (3, 2, 0.3)]), "all_translations")
    raises(InvalidInputError, "1e300", lambda: fb4(1e300, 1e300, 1e300, 1e300), "too_large")


def test_grids_beyond_2_32_samples_are_refused_before_any_allocation():
    f = Task(POSES).filemon((4.0, -1.0))
    for call_ in (lambda: f.margin_map(-1, 1, -1, 1, 2**32 + 1, 1),
                  lambda: f.branch_map(-1, 1, -1, 1, 2**17, 2**17),
                  lambda: f.solution_map(Grid(-1, 1, -1, 1, 2**17, 2**17))):
        with pytest.raises(InvalidInputError, match="at most 4294967296") as e:
            call_()
        assert e.value.cause == "grid_size" and e.value.max == 2**32


# ---------------------------------------------------------------------------
# Points and angles the accessors once took (issue 15, item 6)


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_point_accessors_refuse_non_finite_points(bad):
    from burmester.taskfile import example

    f = example().filemon()
    c = f.conics[0]
    for call in (
        lambda p: f.task.displace(p, 1, 2),  # once NaN or inf out
        f.margin,
        f.conic_values,
        f.circle_signs,
        c.evaluate,
        c.distance,
    ):
        for p in ((bad, 0.0), (0.0, bad)):
            with pytest.raises(InvalidInputError, match="finite"):
                call(p)


def test_conic_distance_with_tiny_coefficients_is_finite():
    # Once inf: the gradient's norm underflowed.
    d = Conic(1, 0, 0, 1e-300, 1e-300, 1e-300).distance((0, 0))
    assert d == pytest.approx(math.sqrt(0.5), rel=1e-12)


@pytest.mark.parametrize("theta2", [1e300, -2e9, 1e10])
def test_input_angles_beyond_1e9_are_refused_as_for_a_task(theta2):
    fb = fb4(4, 1, 3, 3)
    fb.configuration(1e9, "open")  # the bound itself is fine
    for call in (lambda: fb.configuration(theta2, "open"), lambda: fb.joints(theta2, "crossed")):
        with pytest.raises(InvalidInputError, match="theta2") as e:
            call()
        assert "limit of 1000000000" in str(e.value) and "modulo 2 pi" in str(e.value)
    with pytest.raises(InvalidInputError, match="limit of 1000000000"):
        Task([(0, 0, 0), (1, 0, theta2), (0, 1, 1)])  # the same bound


# ---------------------------------------------------------------------------
# One toggle criterion (issue 15, item 5)


def _on_curve(conic, p, n):
    """A root of the conic on the line p + t n, by bisection on its sign."""
    lo, hi = -1.0, 1.0
    slo = math.copysign(1.0, conic.evaluate((p[0] + lo * n[0], p[1] + lo * n[1])))
    shi = math.copysign(1.0, conic.evaluate((p[0] + hi * n[0], p[1] + hi * n[1])))
    if slo == shi:
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        s = math.copysign(1.0, conic.evaluate((p[0] + mid * n[0], p[1] + mid * n[1])))
        if s == slo:
            lo = mid
        else:
            hi = mid
    return (p[0] + lo * n[0], p[1] + lo * n[1])


def _toggle_band(l3, l4, r2, rho):
    """The documented toggle band in |sin mu| (issue 28,
    ``tolerance::heron_tolerance``): the rounding of the loop closure, with
    ``rho`` the ground plus the crank. It replaced ``sqrt(8 eps) ((L3 +
    L4)^2 + r^2) / (2 L3 L4)``, which grows like ``L3 / L4``."""
    k = 4 * np.finfo(float).eps
    r = math.sqrt(r2)
    a, b = (l3 + l4) ** 2 - r2, r2 - (l3 - l4) ** 2
    ea = (l3 + l4) ** 2 + r2 + 2 * r * rho
    eb = abs(l3 - l4) * (l3 + l4) + r2 + 2 * r * rho
    return math.sqrt(k * (abs(b) * ea + abs(a) * eb) + k * k * ea * eb) / (2 * l3 * l4)


def test_modes_and_configuration_toggle_agree_and_poses_are_reached_near_toggles():
    # Driving pivots at 1e-2 down to 1e-11 task sizes from the transformed
    # Filemon curves, where a design pose is at a toggle. Once the modes
    # could be all "open" while configuration(theta_k, mode).toggle was True,
    # and pose_at missed the pose by 1e-4 task sizes (the loop was snapped
    # onto the toggle). Now: outside the band's own rounding (a factor of 2
    # either side), both say the same; every pose is reached to rounding.
    from burmester.taskfile import example

    f = example().filemon()
    scale = f.task.scale
    checked = toggles = 0
    for conic in f.conics:
        for line in conic.polylines(-8, 8, -8, 8):
            for p in line[:: max(1, len(line) // 12)]:
                h = 1e-6
                gx = (conic.evaluate((p[0] + h, p[1])) - conic.evaluate((p[0] - h, p[1]))) / (2 * h)
                gy = (conic.evaluate((p[0], p[1] + h)) - conic.evaluate((p[0], p[1] - h))) / (2 * h)
                g = math.hypot(gx, gy)
                if g == 0:
                    continue
                n = (gx / g * 0.01, gy / g * 0.01)
                root = _on_curve(conic, p, n)
                if root is None:
                    continue
                for d in (1e-2, 1e-4, 1e-6, 1e-7, 1e-8, 1e-9, 1e-11, 0.0):
                    for side in (-1, 1):
                        a0 = (root[0] + side * d * scale * gx / g, root[1] + side * d * scale * gy / g)
                        try:
                            sfb = f.four_bar(a0)
                        except BurmesterError:
                            continue
                        fb = sfb.fourbar
                        for k, (theta, mode) in enumerate(zip(sfb.input_angles, sfb.modes)):
                            for m in ("open", "crossed"):
                                c = fb.configuration(theta, m)
                                _, a, b, o4 = fb.joints(theta, m)
                                l3, l4 = fb.coupler, fb.rocker
                                r2 = (o4[0] - a[0]) ** 2 + (o4[1] - a[1]) ** 2
                                tau = _toggle_band(l3, l4, r2, fb.ground + fb.crank)
                                sin_mu = math.sin(c.transmission_angle)
                                if sin_mu < 0.5 * tau:
                                    assert c.toggle and mode is None, (a0, k, sin_mu, tau)
                                    toggles += 1
                                elif sin_mu > 2 * tau:
                                    assert not c.toggle and mode is not None, (a0, k, sin_mu, tau)
                            # The pose is reached in its mode; at a toggle
                            # (mode None) in one of the two. Near a toggle
                            # the loop is as ill-conditioned as a square root
                            # (rounding of eps moves it by about sqrt(eps)):
                            # a few 1e-7 of the task's size, not the 1e-4 of
                            # a loop snapped onto the toggle.
                            px, py, pa = f.task.poses[k]
                            misses = []
                            for m in (mode,) if mode else ("open", "crossed"):
                                x, y, ang = sfb.pose_at(theta, m)
                                misses.append(max(math.hypot(x - px, y - py) / scale,
                                                  abs(math.remainder(ang - pa, 2 * math.pi))))
                            near = math.sin(fb.configuration(theta, mode or "open").transmission_angle) < 1e-3
                            assert min(misses) < (1e-6 if near else 1e-9), (a0, k, misses)
                            checked += 1
    assert checked > 500 and toggles > 0, (checked, toggles)
