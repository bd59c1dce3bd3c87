"""Issue 24, item 7: a far point's cubic gradient, and pickled state that no
object has (a Grashof code of 200, a direction of 5, a bool byte of 3, a
dyad or figures that do not hang together) refused with a typed error, for
every class of the binding that rebuilds itself from state
(``__reduce__`` / ``__getnewargs__`` in crates/burmester-py)."""

import math
import pickle

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import burmester
from burmester import InvalidInputError

POSES = [(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)]
FOUR = [(0, 0, 0), (2, 0.5, 0.4), (3, 2, 1.1), (4, 2, 0.9)]


def test_far_cubic_gradient_is_finite():
    """``Cubic([0..9]).gradient((-1e308, 1e308))`` was ``(nan, nan)``; it
    is scaled as the value is (the factor of ``evaluate``), finite, and
    ``|f| / |grad f|`` is the distance estimate there."""
    c = burmester.Cubic(list(range(10)))
    for p in [(-1e308, 1e308), (1.7e308, -1.7e308), (1e200, 3e150), (-1e150, 0.0)]:
        g = c.gradient(p)
        assert all(math.isfinite(v) for v in g) and g != (0.0, 0.0), (p, g)
        d = abs(c.evaluate(p)) / math.hypot(*g)
        assert d == pytest.approx(c.distance(p), rel=1e-12), p
    # Near points keep the plain gradient: f = x + 2y + 3x^2 + 4xy + 5y^2 +
    # 6x^3 + 7x^2 y + 8x y^2 + 9y^3 up to the stored positive factor.
    x, y = 0.5, -1.0
    want = (1 + 6 * x + 4 * y + 18 * x * x + 14 * x * y + 8 * y * y,
            2 + 4 * x + 10 * y + 7 * x * x + 16 * x * y + 27 * y * y)
    g = c.gradient((x, y))
    k = g[0] / want[0]
    assert k > 0 and g[1] == pytest.approx(k * want[1], rel=1e-12)


@settings(max_examples=300, deadline=None)
@given(x=st.floats(allow_nan=False, allow_infinity=False),
       y=st.floats(allow_nan=False, allow_infinity=False),
       coefficients=st.lists(st.floats(-10, 10), min_size=10, max_size=10))
def test_any_finite_point_has_a_finite_gradient(x, y, coefficients):
    check_gradient(x, y, coefficients)


def test_a_subnormal_gradient_far_out():
    """The case Hypothesis drew: the gradient at x = 8e287 is 1.4e-315
    (subnormal), the distance estimate still ``|f| / |grad f|`` within
    that precision."""
    check_gradient(8.010182652438835e+287, 0.0, [0.0] * 6 + [3.7241418191263805e-28, 0.0, 0.0, 1.0])


def check_gradient(x, y, coefficients):
    """Hypothesis (the target that would have found it): any finite point,
    any cubic, a finite gradient, and ``|f| / |grad f|`` the distance."""
    try:
        c = burmester.Cubic(coefficients)
    except burmester.BurmesterError:
        return
    g = c.gradient((x, y))
    assert all(math.isfinite(v) for v in g), (x, y, g)
    d, v = c.distance((x, y)), abs(c.evaluate((x, y)))
    n = math.hypot(*g)
    if v > 0 and n > 0 and math.isfinite(d) and d > 0:
        # Far out the gradient (scaled like the value, by 1/m^3) can be
        # subnormal, held to an absolute 5e-324: relative 1e-323 / |grad|
        # (Hypothesis found |grad| = 1.4e-315 at x = 8e287, 7e-9 relative).
        assert v / n == pytest.approx(d, rel=1e-9 + 1e-323 / n)


def refused(call):
    with pytest.raises(InvalidInputError) as e:
        call()
    assert e.value.cause == "inconsistent_state", e.value
    return str(e.value)


@pytest.fixture(scope="module")
def smap():
    task = burmester.Task(POSES)
    return task.filemon((4.0, -1.0)).solution_map(-8, 8, -8, 8, 24, 20, min_transmission_deg=25)


@pytest.fixture(scope="module")
def pmap():
    return burmester.Task(FOUR).pair_map(24, 20)


def tampered(m, column, k, value, view=None):
    """The rebuild of map ``m`` with sample ``k`` of ``column`` set to
    ``value`` (written through a ``view`` dtype, for bytes)."""
    f, args = m.__reduce__()[:2]
    args = list(args)
    cols = {name: np.array(a) for name, a in args[-1].items()}
    a = cols[column]
    (a.view(view) if view else a).reshape(-1)[k] = value
    args[-1] = cols
    return lambda: f(*args)


@pytest.mark.parametrize("which", ["smap", "pmap"])
def test_map_columns_no_map_holds_are_refused(which, request):
    m = request.getfixturevalue(which)
    valid = np.flatnonzero(np.asarray(m.valid).reshape(-1))
    invalid = np.flatnonzero(~np.asarray(m.valid).reshape(-1))
    assert len(valid)
    k = int(valid[0])
    # The pickle as it is rebuilds an equal map.
    f, args = m.__reduce__()[:2]
    assert f(*args) == m
    msg = refused(tampered(m, "grashof", k, 200))
    assert "grashof" in msg and "200" in msg and "row" in msg
    assert "direction" in refused(tampered(m, "direction", k, 5))
    for col in ("valid", "branch_free", "input_full", "one_circuit", "acceptable"):
        msg = refused(tampered(m, col, k, 3, view=np.uint8))
        assert col in msg and "byte 3" in msg
    # Values a sample cannot hold, and rows that do not hang together.
    refused(tampered(m, "min_transmission_rad", k, 2.0))
    refused(tampered(m, "link_ratio", k, 0.5))
    refused(tampered(m, "size_ratio", k, -1.0))
    refused(tampered(m, "grashof", k, 255))                      # valid without a class
    refused(tampered(m, "valid", k, False))                      # invalid with values
    if len(invalid):
        refused(tampered(m, "link_ratio", int(invalid[0]), 2.0))
    free = np.flatnonzero(np.asarray(m.direction).reshape(-1) != 0)
    refused(tampered(m, "direction", int(free[0]), 0))           # a travel without a direction
    not_ok = np.flatnonzero(np.asarray(m.valid).reshape(-1) & ~np.asarray(m.branch_free).reshape(-1))
    refused(tampered(m, "acceptable", int(not_ok[0]), True))     # acceptable, not branch-free


def test_a_driven_dyad_that_is_not_the_tasks_is_refused(smap):
    f, args = smap.__reduce__()[:2]
    args = list(args)
    center, circle = args[3]
    args[3] = (center, (circle[0] + 1e-3, circle[1]))
    assert "dyad" in refused(lambda: f(*args))
    args[3] = (center, circle)
    args[5] = (None, [], -1.0, 64)                               # a negative link width
    with pytest.raises(InvalidInputError):
        f(*args)


def test_figures_that_no_linkage_has_are_refused():
    sfb = burmester.Task(POSES).four_bar((-7.98, -5.18), (4.0, -1.0))
    fig = sfb.figures
    f, args = fig.__reduce__()[:2]
    assert f(*args) == fig
    others = [g for g in ("crank-rocker", "double-crank", "double-rocker", "triple-rocker")
              if g != fig.grashof]

    def with_(k, v):
        a = list(args)
        a[k] = v
        return lambda: f(*a)

    refused(with_(1, others[0]))                                 # not the lengths' Grashof type
    refused(with_(2, not fig.input_full))
    refused(with_(7, fig.link_ratio * 1.5))
    refused(with_(6, 2.0))                                       # beyond pi/2
    refused(with_(6, math.nan))                                  # a direction without a travel
    refused(with_(4, "none"))                                    # a travel without a direction
    with pytest.raises(InvalidInputError):
        with_(1, "no-such-type")()
    with pytest.raises(burmester.AssemblyError):
        with_(0, (1.0, 1.0, 1.0, 5.0))()                         # never closes
    with pytest.raises(InvalidInputError):
        with_(0, (1.0, -1.0, 1.0, 1.0))()


def test_curve_records_that_no_curve_has_are_refused():
    task = burmester.Task(FOUR)
    d = next(x for row in task.curve_dyads(8) for x in row if x is not None)
    f, args = d.__reduce__()[:2]
    assert f(*args) == d

    def with_(k, v):
        a = list(args)
        a[k] = v
        return lambda: f(*a)

    for order in ("1-2-3", "2-1-3-4", "1-2-2-4", "1-2-3-x", ""):
        refused(with_(4, order))
    # An order with a direction that is not its own.
    a = list(args)
    a[4], a[5] = "1-3-2-4", "clockwise"
    refused(lambda: f(*a))
    a[4], a[5] = "1-2-3-4", None
    refused(lambda: f(*a))
    a[4], a[5] = "1-4-3-2", "clockwise"
    assert f(*a).direction == "clockwise"
    refused(with_(2, math.nan))
    refused(with_(2, 4.0))
    q = task.coincidence_points()[0]
    f, args = q.__reduce__()[:2]
    assert f(*args) == q
    for pair in ((0, 1), (2, 1), (1, 5), (3, 3)):
        refused(lambda: f(pair, *args[1:]))
    refused(lambda: f(args[0], (math.inf, 0.0), args[2]))


def test_a_pivot_off_its_linkage_is_refused(smap):
    p = smap.best_pivots(1)[0]
    back = pickle.loads(pickle.dumps(p))
    assert back == p
    x, y = p.center
    msg = refused(lambda: burmester.Pivot((x + 1.0, y), p.index, p.linkage, p.margin, p.score,
                                          p.ranked_by))
    assert "pivot" in msg.lower()


# A fuzz target that would have found the bytes: any byte of any column.

@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                   HealthCheck.function_scoped_fixture])
@given(column=st.sampled_from(burmester.SolutionMap.columns), k=st.integers(0, 24 * 20 - 1),
       byte=st.integers(0, 7), value=st.integers(0, 255))
def test_any_damaged_byte_is_refused_or_harmless(smap, column, k, byte, value):
    """One byte of one sample of one column set to any value: the map is
    refused with a typed error, or it is a map whose every row a map can
    hold (checked here again, in NumPy)."""
    f, args = smap.__reduce__()[:2]
    args = list(args)
    cols = {name: np.array(a) for name, a in args[-1].items()}
    raw = cols[column].view(np.uint8).reshape(-1)
    size = cols[column].dtype.itemsize
    raw[(k * size + byte % size)] = value
    args[-1] = cols
    try:
        m = f(*args)
    except InvalidInputError as e:
        assert e.cause == "inconsistent_state"
        return
    valid, g, d = np.asarray(m.valid), np.asarray(m.grashof), np.asarray(m.direction)
    assert set(np.unique(g)) <= {0, 1, 2, 3, 4, 5, 255}
    assert set(np.unique(d)) <= {-1, 0, 1}
    for name in ("valid", "branch_free", "input_full", "one_circuit", "acceptable"):
        assert set(np.unique(np.asarray(getattr(m, name)).view(np.uint8))) <= {0, 1}
    assert not (np.asarray(m.acceptable) & ~np.asarray(m.branch_free)).any()
    assert (g[~valid] == 255).all() and (g[valid] != 255).all()
    mt = np.asarray(m.min_transmission_rad)
    assert ((d != 0) == ~np.isnan(mt))[valid].all()
