"""The one toggle criterion (issue 28) against mpmath at 300 bits.

The documented band (``tolerance::heron_tolerance`` in the core, the
README's band table): a loop with coupler ``L3``, rocker ``L4``, crank tip
to output pivot ``r`` and ground plus crank ``rho = L1 + L2`` is at a
toggle where

    |H| <= tol = k (|B| E_A + |A| E_B) + k^2 E_A E_B,   k = 4 eps,
    A = (L3 + L4)^2 - r^2,  B = r^2 - (L3 - L4)^2,  H = A B = (2 L3 L4 sin mu)^2,
    E_A = (L3 + L4)^2 + r^2 + 2 r rho,  E_B = |L3 - L4| (L3 + L4) + r^2 + 2 r rho,

that is ``|sin mu| <= band = sqrt(tol) / (2 L3 L4)``. Here ``H``, ``tol``
and ``band`` are evaluated exactly (mpmath, 300 bits) for the linkage as
given (its double lengths, placement and input angle), and the library's
answers are held to them: no position called a toggle whose ``|sin mu|``
exceeds the band by more than a factor of 2, none missed (a position whose
``|sin mu|`` is below half the band is a toggle), no loop refused that
closes by more than half the band, and every mode the figures of a built
linkage report is the mode in which the exact linkage reaches the pose.
"""

import math

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import burmester

mp = pytest.importorskip("mpmath")
mp.mp.prec = 300

K = 4 * 2.0**-52  # tolerance::LOOP_EPS eps

SETTINGS = settings(max_examples=400, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


def exact_loop(fb, theta2):
    """Exact ``(H, tol, band, sin_mu, d, l3, l4, r2)`` of ``fb`` at ``theta2``
    (all mpf), in units of the longest link."""
    g, c, l3, l4 = (mp.mpf(x) for x in fb.lengths)
    s = max(g, c, l3, l4)
    g, c, l3, l4 = g / s, c / s, l3 / s, l4 / s
    t1, t2 = mp.mpf(fb.ground_angle), mp.mpf(theta2)
    dx = g * mp.cos(t1) - c * mp.cos(t2)
    dy = g * mp.sin(t1) - c * mp.sin(t2)
    r2 = dx * dx + dy * dy
    r = mp.sqrt(r2)
    a = (l3 + l4) ** 2 - r2
    b = r2 - (l3 - l4) ** 2
    rho = g + c
    ea = (l3 + l4) ** 2 + r2 + 2 * r * rho
    eb = abs(l3 - l4) * (l3 + l4) + r2 + 2 * r * rho
    tol = K * (abs(b) * ea + abs(a) * eb) + K * K * ea * eb
    h = a * b
    band = mp.sqrt(tol) / (2 * l3 * l4)
    sin_mu = mp.sqrt(h) / (2 * l3 * l4) if h > 0 else mp.mpf(0)
    return h, tol, band, sin_mu, (dx, dy), l3, l4, r2, s


def exact_rocker_tip(fb, theta2, mode):
    """The exact rocker tip ``B`` of ``fb`` at ``theta2`` in ``mode`` (the
    position analysis' circle intersection, exact), in the fixed frame."""
    h, _, _, _, (dx, dy), l3, l4, r2, s = exact_loop(fb, theta2)
    sign = 1 if mode == "open" else -1
    root = mp.sqrt(max(h, 0))
    k4 = (l3 * l3 - l4 * l4) - r2
    vx = dx * k4 - sign * root * dy
    vy = dy * k4 + sign * root * dx
    n = mp.sqrt(vx * vx + vy * vy)
    o4x, o4y = (mp.mpf(v) for v in fb.output_pivot)
    return o4x + vx / n * l4 * s, o4y + vy / n * l4 * s


def check_position(fb, theta2):
    """Both modes of ``fb`` at ``theta2`` against the exact band; returns
    whether a toggle was reported."""
    h, tol, band, sin_mu, *_ = exact_loop(fb, theta2)
    toggled = False
    for mode in ("open", "crossed"):
        try:
            c = fb.configuration(theta2, mode)
        except burmester.AssemblyError as e:
            if e.cause == "indeterminate":
                # The crank tip on the output pivot of a coupler as long as
                # the rocker: a folded toggle, every coupler angle closes.
                assert sin_mu <= 2 * band, (fb, theta2)
                continue
            assert e.cause == "out_of_reach", e
            # Refused only where the exact loop misses closing by more than
            # a quarter of the band's tolerance (|H| > tol / 4).
            assert h < -tol / 4, (fb, theta2, float(h / tol))
            continue
        # A returned position closes the exact loop within the band's
        # tolerance (``>=``: a folded rhombus whose crank tip is exactly on
        # the output pivot has H = tol = 0, an exact toggle).
        assert h >= -4 * tol, (fb, theta2, float(h), float(tol))
        if c.toggle:
            toggled = True
            assert sin_mu <= 2 * band, (fb, theta2, float(sin_mu), float(band))
        else:
            assert sin_mu >= band / 2, (fb, theta2, float(sin_mu), float(band))
            sign = 1 if mode == "open" else -1
            assert sign * math.sin(c.theta4 - c.theta3) > 0
    return toggled


def linkage(log_ratio, which, ground_angle=0.0):
    """A four-bar whose link `which` (0 ground, 1 crank, 2 coupler, 3
    rocker) is `10**log_ratio` times shorter than the others, which are
    near 1, placed off the origin at `ground_angle`."""
    base = [1.0, 0.83, 1.21, 0.97]
    base[which] = 10.0 ** -log_ratio
    return burmester.FourBar(ground=base[0], crank=base[1], coupler=base[2], rocker=base[3],
                             origin=(0.3, -0.2), ground_angle=ground_angle)


def near_dead(fb):
    """Input angles near the dead positions of ``fb`` (or, for an input
    that turns fully, where the transmission angle is least), from 1e-18 to
    1e-1 rad away, both sides."""
    dead = fb.dead_positions or [fb.ground_angle, fb.ground_angle + math.pi]
    for t0 in dead:
        for e in range(-72, -3):
            for side in (-1, 1):
                yield t0 + side * 10.0 ** (e / 4)


@pytest.mark.parametrize("which", [0, 1, 2, 3])
@pytest.mark.parametrize("log_ratio", [0, 1, 3, 5, 7, 9])
def test_dead_positions_at_link_ratios_from_1_to_1e9(log_ratio, which):
    """Near every dead position of linkages with one link 1 to 1e9 times
    shorter than the others: the toggle flag and the refusals follow the
    exact band, and the band is reached (some positions are toggles)."""
    try:
        fb = linkage(log_ratio, which, ground_angle=0.4)
    except burmester.AssemblyError:
        pytest.skip("never closes")
    toggles = sum(check_position(fb, t) for t in near_dead(fb))
    if fb.dead_positions:
        assert toggles > 0


def test_the_band_is_the_root_of_the_rounding_not_the_link_ratio():
    """At a link ratio of 4.6e7 (issue 28's linkage) the band is about 4e-4
    in sin(mu), the square root of the rocker angle's rounding; the earlier
    band, growing like the ratio, was about 1."""
    fb = burmester.FourBar.from_pivots((79.35079574269099, 74.89249517819286),
                                       (0.9270498928708832, -2.456011695005893),
                                       1502669804.6436944, 1502669676.747299, 32.832706862152556)
    for t0 in fb.dead_positions:
        band = float(exact_loop(fb, t0)[2])
        assert 1e-4 < band < 1e-3, band
        l3, l4 = fb.coupler, fb.rocker
        old = math.sqrt(8 * 2.0**-52) * 2 * (l3 + l4) ** 2 / (2 * l3 * l4)
        assert old > 1.0


def test_a_folded_rhombus_exactly_at_its_fold_is_a_toggle_or_indeterminate():
    """Hypothesis found it: the unit rhombus at ground angle 2.5 driven to
    the ground angle (its crank tip on the output pivot, H = tol = 0
    exactly) is either refused as indeterminate or a toggle, in both
    modes."""
    fb = burmester.FourBar(ground=1.0, crank=1.0, coupler=1.0, rocker=1.0,
                           origin=(0.0, 0.0), ground_angle=2.5)
    assert fb.dead_positions == []
    h, tol, *_ = exact_loop(fb, 2.5)
    assert h == 0 and tol == 0
    check_position(fb, 2.5)
    for mode in ("open", "crossed"):
        try:
            assert fb.configuration(2.5, mode).toggle
        except burmester.AssemblyError as e:
            assert e.cause == "indeterminate"


@st.composite
def linkages(draw):
    """Four-bars with link ratios up to 1e9: each length 10**U(-9, 0) (of a
    random unit), placed anywhere near the origin at any ground angle; only
    those whose loop closes somewhere."""
    spread = draw(st.sampled_from([0.5, 3.0, 6.0, 9.0]))
    lengths = [10.0 ** draw(st.floats(-spread, 0.0)) for _ in range(4)]
    assume(max(lengths) < sum(lengths) - max(lengths))
    unit = 10.0 ** draw(st.floats(-3.0, 3.0))
    lengths = [x * unit for x in lengths]
    origin = (draw(st.floats(-2.0, 2.0)) * unit, draw(st.floats(-2.0, 2.0)) * unit)
    angle = draw(st.floats(-math.pi, math.pi))
    return burmester.FourBar(ground=lengths[0], crank=lengths[1], coupler=lengths[2],
                             rocker=lengths[3], origin=origin, ground_angle=angle)


@SETTINGS
@given(fb=linkages(), pick=st.integers(0, 3), log_off=st.floats(-18.0, -0.5),
       side=st.sampled_from([-1.0, 1.0]))
def test_toggle_flag_follows_the_exact_band(fb, pick, log_off, side):
    """Hypothesis: any linkage with link ratios up to 1e9, near one of its
    dead positions (or least transmission angles) by 1e-18 to 0.3 rad."""
    dead = fb.dead_positions or [fb.ground_angle, fb.ground_angle + math.pi]
    t = dead[pick % len(dead)] + side * 10.0 ** log_off
    check_position(fb, t)


# Tasks with driving pivots approaching the pole circle.

@st.composite
def tasks(draw):
    """Three poses within 5 of the origin, rotations at least 0.1 rad apart
    (mod 2 pi), poles within 300 of the origin (as tests/rust/common)."""
    poses = [(draw(st.floats(-5, 5)), draw(st.floats(-5, 5)), draw(st.floats(-math.pi, math.pi)))
             for _ in range(3)]
    try:
        task = burmester.Task(poses)
        poles = [p.point for p in task.poles]
    except burmester.BurmesterError:
        assume(False)
    rot = [poses[j][2] - poses[i][2] for i, j in ((0, 1), (0, 2), (1, 2))]
    assume(all(abs(math.remainder(r, 2 * math.pi)) >= 0.1 for r in rot))
    assume(all(p is not None and math.hypot(*p) < 300 for p in poles))
    assume(task.scale > 0.05)
    return task


def check_synthesized(task, sfb):
    """Every pose of a built linkage against the exact linkage: a mode is
    reported only where |sin mu| is beyond half the band, and it is the
    mode in which the exact linkage's rocker tip is the driven moving pivot
    at the pose; a toggle only where |sin mu| is within twice the band."""
    fb = sfb.fourbar
    c1 = sfb.driven[1]
    for k, (t, mode) in enumerate(zip(sfb.input_angles, sfb.modes)):
        h, tol, band, sin_mu, *_ = exact_loop(fb, t)
        if mode is None:
            assert sin_mu <= 2 * band, (k, float(sin_mu), float(band))
            continue
        assert sin_mu >= band / 2, (k, float(sin_mu), float(band))
        ck = task.displace(c1, 1, k + 1)
        want = exact_rocker_tip(fb, t, mode)
        other = exact_rocker_tip(fb, t, "crossed" if mode == "open" else "open")
        dist = lambda b: mp.sqrt((b[0] - ck[0]) ** 2 + (b[1] - ck[1]) ** 2)
        assert dist(want) <= dist(other), (k, mode, float(dist(want)), float(dist(other)))
        # And the library assembles there, in that mode.
        fb.configuration(t, mode)


@settings(max_examples=300, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(task=tasks(), c0=st.tuples(st.floats(-6, 6), st.floats(-6, 6)),
       angle=st.floats(0, 2 * math.pi), log_dist=st.floats(-9.0, 0.0),
       side=st.sampled_from([-1.0, 1.0]))
def test_driving_pivots_approaching_the_pole_circle(task, c0, angle, log_dist, side):
    """Hypothesis: driving centers 1e-9 to 1 task sizes off the pole circle
    (circle points far away, link ratios up to about 1e9): the modes at the
    poses follow the exact band, and a branch-free linkage's modes agree
    with driving it (`simulate`) and with the sign tests."""
    try:
        f = task.filemon(c0)
        circle = task.pole_circle()
    except burmester.BurmesterError:
        assume(False)
    assume(circle["kind"] == "circle")
    center, radius = circle["center"], circle["radius"]
    d = side * 10.0 ** log_dist * task.scale
    a0 = (center[0] + (radius + d) * math.cos(angle), center[1] + (radius + d) * math.sin(angle))
    try:
        sfb = f.four_bar(a0)
    except burmester.BurmesterError:
        assume(False)
    check_synthesized(task, sfb)


def test_issue_28_case():
    """Issue 28: 1.8e-7 task sizes from the pole circle; crank and coupler
    4.6e7 times the rocker. Crossed at all three poses, branch-free, and
    the three classifiers agree."""
    task = burmester.Task([(-1.8622594211157373, -2.700165078206026, -2.5318845477482217),
                           (-1.242879680464385, -1.390640844394518, -3.035693045691944),
                           (2.538761869305141, -1.4705020035742344, -2.8394644775952194)])
    f = task.filemon((0.9270498928708832, -2.456011695005893))
    a0 = (79.35079574269099, 74.89249517819286)
    sfb = f.four_bar(a0)
    assert sfb.modes == ["crossed"] * 3
    assert sfb.branch_free
    assert [f.classify(a0, m) for m in ("conic", "direct", "simulate")] == ["free"] * 3
    check_synthesized(task, sfb)
    for t in sfb.input_angles:
        c = sfb.fourbar.configuration(t, "crossed")
        assert not c.toggle and math.degrees(c.transmission_angle) > 49
