"""The inverted slider-crank from Python (issue 27): position analysis against
Norton's closed form (Design of Machinery, section 4.7, eq. 4.18: the tangent
half-angle quadratic in theta4, both roots; eq. 4.20: the slider length b),
the stroke along the slot and the swing against dense sampling, the quick
return of a shaper in millimetres against its textbook time ratio, the
inverted slider-crank of a task made from a known one (the swivel found among
the task's inverted sliders, the poses reached), typed errors, pickling, the
documented maximum and the picture."""

import math
import pickle

import numpy as np
import pytest

import burmester
from burmester import AssemblyError, InvalidInputError, InvertedSliderCrank, Task


def wrap(a):
    return (a + math.pi) % (2 * math.pi) - math.pi


def norton(a, c, d, gamma, t2):
    """Norton's inverted slider-crank (crank a, ground d along +x, rocker c at
    gamma to the slider axis): both (theta3, b)."""
    p = a * math.sin(t2) * math.sin(gamma) + (a * math.cos(t2) - d) * math.cos(gamma)
    q = -a * math.sin(t2) * math.cos(gamma) + (a * math.cos(t2) - d) * math.sin(gamma)
    r = -c * math.sin(gamma)
    s, t, u = r - q, 2 * p, q + r
    disc = t * t - 4 * s * u
    if disc < 0:
        return []
    out = []
    for sg in (1.0, -1.0):
        t4 = 2 * math.atan((-t + sg * math.sqrt(disc)) / (2 * s))
        t3 = t4 + gamma
        out.append((t3, (a * math.sin(t2) - c * math.sin(t4)) / math.sin(t3)))
    return out


@pytest.mark.parametrize("a,c,d,gamma", [(40.0, 0.0, 100.0, math.pi / 2), (40.0, 15.0, 100.0, math.pi / 2),
                                         (130.0, 20.0, 60.0, 2.0)])
def test_norton_closed_form_both_modes(a, c, d, gamma):
    q = InvertedSliderCrank(crank=a, swivel=(d, 0.0), offset=c * math.sin(gamma))
    n = 0
    for t2 in np.linspace(-math.pi, math.pi, 181)[:-1] + 0.0123:
        book = norton(a, c, d, gamma, t2)
        for mode in ("open", "crossed"):
            try:
                conf = q.solve(t2, mode)
            except AssemblyError:
                assert not book
                continue
            b = -conf.slot - c * math.cos(gamma)
            assert any(abs(wrap(t3 - conf.theta3)) < 1e-9 and abs(bb - b) < 1e-9 * (a + d) for t3, bb in book)
            assert (conf.slot > 0) == (mode == "open")
            n += 1
    assert n > 200


def test_shaper_quick_return_in_millimetres():
    # A shaper: crank 100 mm, the slotted lever's swivel 300 mm below the
    # crank pivot, the slot through the crank pin. Textbook (e.g. Shigley &
    # Uicker, the crank-shaper): the lever swings by 2 asin(r/g) and the
    # time ratio is (180 + 2 asin(r/g)) / (180 - 2 asin(r/g)).
    q = InvertedSliderCrank(crank=100.0, swivel=(0.0, -300.0))
    beta = math.degrees(2 * math.asin(100.0 / 300.0))
    (lo, hi) = q.swing("crossed")
    assert math.degrees(hi[2] - lo[2]) == pytest.approx(beta, abs=1e-9)
    assert q.time_ratio("crossed") == pytest.approx((180 + beta) / (180 - beta), rel=1e-12)
    assert q.stroke == pytest.approx(200.0)
    assert q.turns_fully and q.input_range is None and q.dead_positions == []
    # A slot through the crank pin transmits at 90 degrees throughout.
    assert q.solve(0.3, "crossed").transmission_angle == pytest.approx(math.pi / 2)
    # Dense sampling agrees with the stroke and the swing.
    ts = np.linspace(-math.pi, math.pi, 20001)
    confs = [q.solve(t, "crossed") for t in ts]
    slots = [c.slot for c in confs]
    assert max(slots) - min(slots) == pytest.approx(q.stroke, abs=1e-3)
    ref = confs[0].theta3
    angs = [ref + wrap(c.theta3 - ref) for c in confs]
    assert math.degrees(max(angs) - min(angs)) == pytest.approx(beta, abs=1e-3)
    # The Whitworth layout (crank longer than the ground): the lever turns fully.
    assert InvertedSliderCrank(crank=100.0, swivel=(0.0, -40.0)).swing("open") is None


def test_dead_positions_and_typed_errors():
    q = InvertedSliderCrank(crank=50.0, swivel=(45.0, 0.0), offset=20.0)
    assert not q.turns_fully and len(q.dead_positions) == 2
    for d in q.dead_positions:
        c = q.solve(d, "open")
        assert c.toggle and abs(c.slot) < 1e-6 and c.transmission_angle < 1e-6
    with pytest.raises(AssemblyError) as e:
        q.solve(0.0)
    assert e.value.cause == "slot_out_of_reach" and "input range" in str(e.value)
    assert isinstance(e.value, ValueError)
    for make, exc, cause in [
        (lambda: InvertedSliderCrank(crank=1.0, swivel=(2.0, 0.0), offset=3.5), AssemblyError,
         "swivel_out_of_reach"),
        (lambda: InvertedSliderCrank(crank=-1.0, swivel=(2.0, 0.0)), InvalidInputError, "not_positive"),
        (lambda: InvertedSliderCrank(crank=1.0, swivel=(math.nan, 0.0)), InvalidInputError, "not_finite"),
        (lambda: InvertedSliderCrank(crank=1e301, swivel=(1.0, 0.0)), InvalidInputError, "too_large"),
        (lambda: q.solve(math.inf), InvalidInputError, "not_finite"),
        (lambda: q.solve(2e9), InvalidInputError, "too_large"),
        (lambda: q.solve(math.pi, "sideways"), InvalidInputError, None),
    ]:
        with pytest.raises(exc) as e:
            make()
        if cause:
            assert e.value.cause == cause
    with pytest.raises(TypeError):
        InvertedSliderCrank(1.0, (2.0, 0.0))  # type: ignore[misc]
    # At the documented maximum it builds and solves.
    big = InvertedSliderCrank(crank=2e299, swivel=(4e299, 0.0))
    assert big.solve(1e9, "open").slot > 0


def _lid_task():
    """A task made from a known inverted slider-crank in millimetres: a lid
    on a slotted arm through a swivelling sleeve."""
    q = InvertedSliderCrank(crank=100.0, swivel=(30.0, -300.0), offset=12.0)
    poses = []
    for t2 in (-0.4, 0.3, 1.1, 1.9):
        c = q.solve(t2, "open")
        x, y = q.coupler_point(t2, (180.0, 40.0), "open")
        poses.append((x, y, c.theta3 + 0.4))
    return q, poses


@pytest.mark.parametrize("n", [3, 4])
def test_task_from_a_known_inverted_slider_crank(n):
    q, poses = _lid_task()
    t = Task(poses[:n])
    if n == 3:
        inv = t.inverted_slider((30.0, -300.0))
    else:
        inv = min(t.inverted_sliders(1), key=lambda i: math.dist(i.swivel, (30.0, -300.0)))
        assert math.dist(inv.swivel, (30.0, -300.0)) < 1e-6
    _, a1, _, _ = q.joints(-0.4, "open")
    s = t.inverted_slider_crank(((0.0, 0.0), a1), (inv.swivel, inv.direction))
    assert s.branch_free and s.feasible and s.direction == "ccw"
    assert s.linkage.crank == pytest.approx(100.0) and abs(s.linkage.offset) == pytest.approx(12.0)
    for k, (angle, mode) in enumerate(zip(s.input_angles, s.modes)):
        x, y, a = s.pose_at(angle, mode)
        assert (x, y) == pytest.approx(poses[k][:2], abs=1e-7)
        assert wrap(a - poses[k][2]) == pytest.approx(0.0, abs=1e-9)
    # Driving densely over the travel: no toggle, and the smallest
    # transmission angle is the one reported.
    ts = s.travel_angles(4001)
    mus = [s.linkage.solve(float(x), s.modes[0]).transmission_angle for x in ts]
    assert math.degrees(min(mus)) == pytest.approx(s.min_transmission_deg, abs=1e-3)
    assert s.stroke_used > 0 and s.swing_used_deg > 0
    # Pickles to an equal object; the linkage and a configuration too.
    for obj in (s, s.linkage, s.linkage.solve(0.5, "crossed")):
        assert pickle.loads(pickle.dumps(obj)) == obj
    # A line that leaves the swivel is refused, with a typed error.
    with pytest.raises(InvalidInputError) as e:
        t.inverted_slider_crank(((0.0, 0.0), a1), ((inv.swivel[0] + 5, inv.swivel[1]), inv.direction))
    assert e.value.cause == "not_a_slider"
    with pytest.raises(InvalidInputError) as e:
        t.inverted_slider_crank(((0.0, 0.0), a1), (inv.swivel, (0.0, 0.0)))
    assert e.value.cause == "zero_direction"
    with pytest.raises(InvalidInputError):
        s.travel_angles(2**20 + 1)
    assert len(s.travel_angles(2**20)) == 2**20


def test_picture():
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    from burmester import plot

    q, poses = _lid_task()
    t = Task(poses[:3])
    inv = t.inverted_slider((30.0, -300.0))
    _, a1, _, _ = q.joints(-0.4, "open")
    s = t.inverted_slider_crank(((0.0, 0.0), a1), (inv.swivel, inv.direction))
    for obj in (q, s, InvertedSliderCrank(crank=50.0, swivel=(45.0, 0.0), offset=20.0)):
        ax = plot.inverted_slider_crank(obj, units="mm")
        gids = {a.get_gid() for a in ax.get_children()}
        assert "fixed-pivots" in gids
        assert ("linkage-block" in gids) or ("linkage-1-block" in gids)
        assert ("linkage-slot" in gids) or ("linkage-1-slot" in gids)
        if obj is s:
            assert {"pose-1", "pose-3", "coupler-curve"} <= gids
        ax.figure.canvas.draw()
        matplotlib.pyplot.close(ax.figure)
    assert burmester.InvertedSliderCrank is InvertedSliderCrank
