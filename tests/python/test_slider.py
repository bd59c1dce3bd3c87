"""The slider-crank from Python: position analysis against Norton's closed
form (Design of Machinery, section 4.6, eqs. 4.16-4.17, both circuits), the
stroke against the textbook formula, the slider-crank of a task made from a
known one, typed errors, pickling and the documented maximum."""

import math
import pickle

import numpy as np
import pytest

import burmester
from burmester import AssemblyError, InvalidInputError, SliderCrank, Task


def norton(a, b, c, t2):
    """Norton's offset slider-crank: crank a, coupler b, guide at height c
    along +x; (theta3, d) of his solutions 1 (eq. 4.16a) and 2 (4.16b), theta3
    from the slider pin to the crank pin."""
    q = (a * math.sin(t2) - c) / b
    t31 = math.asin(q)
    t32 = math.asin(-q) + math.pi
    return [(t, a * math.cos(t2) - b * math.cos(t)) for t in (t31, t32)]


def wrap(a):
    return (a + math.pi) % (2 * math.pi) - math.pi


@pytest.mark.parametrize("a,b,c", [(40.0, 120.0, -20.0), (40.0, 120.0, 20.0), (2.0, 2.5, 0.4)])
def test_norton_closed_form_both_modes(a, b, c):
    sc = SliderCrank(crank=a, coupler=b, guide_point=(3.0, c))
    assert sc.offset == -c and sc.foot == (0.0, c)
    for t2 in np.linspace(-math.pi, math.pi, 181):
        for mode, (t3, d) in zip(("open", "crossed"), norton(a, b, c, t2)):
            conf = sc.solve(t2, mode)
            assert conf.mode == mode
            assert conf.slider == pytest.approx(d, abs=1e-12 * (a + b))
            assert wrap(conf.theta3 - (t3 + math.pi)) == pytest.approx(0.0, abs=1e-11)
            mu = math.acos(abs(a * math.sin(t2) - c) / b)
            assert conf.transmission_angle == pytest.approx(mu, abs=1e-11)
            _, tip, pin = sc.joints(t2, mode)
            assert pin == pytest.approx((d, c), abs=1e-12 * (a + b))
            assert math.dist(tip, pin) == pytest.approx(b)


def test_stroke_limits_and_dead_positions():
    # A press: crank 40 mm, rod 150 mm, offset 10 mm.
    sc = SliderCrank(crank=40.0, coupler=150.0, guide_point=(0.0, 40.0), pivot=(100.0, 50.0))
    assert sc.turns_fully and sc.input_range is None and sc.dead_positions == []
    book = math.sqrt(190.0**2 - 100.0) - math.sqrt(110.0**2 - 100.0)
    for mode in ("open", "crossed"):
        assert sc.stroke(mode) == pytest.approx(book, rel=1e-13)
        (t_lo, s_lo), (t_hi, s_hi) = sc.limits(mode)
        assert sc.solve(t_lo, mode).slider == pytest.approx(s_lo, abs=1e-9)
        assert sc.solve(t_hi, mode).slider == pytest.approx(s_hi, abs=1e-9)
        dense = [sc.solve(t, mode).slider for t in np.linspace(0, 2 * math.pi, 20001)]
        assert min(dense) >= s_lo - 1e-9 and max(dense) <= s_hi + 1e-9
        assert min(dense) - s_lo < 1e-3 and s_hi - max(dense) < 1e-3
    assert len(sc.collinear_positions) == 4
    # A rocking crank: its dead positions are toggles.
    rock = SliderCrank(crank=2.0, coupler=1.5, guide_point=(0.0, 1.0))
    assert not rock.turns_fully and len(rock.dead_positions) == 2
    for t in rock.dead_positions:
        conf = rock.solve(t)
        assert conf.toggle and conf.transmission_angle < 1e-6
    with pytest.raises(AssemblyError) as e:
        rock.solve(-math.pi / 2)
    assert e.value.cause == "slider_out_of_reach" and "input range" in str(e.value)


def test_coupler_path_matches_coupler_point():
    sc = SliderCrank(crank=1.0, coupler=3.0, guide_point=(0.0, 0.4), guide=(2.0, 0.3))
    t = np.linspace(-3.0, 3.0, 24).reshape(4, 6)
    xs, ys, ok = sc.coupler_path((0.5, 0.7), t, "crossed")
    assert xs.shape == ys.shape == ok.shape == (4, 6) and ok.all()
    for (i, j), t2 in np.ndenumerate(t):
        assert sc.coupler_point(t2, (0.5, 0.7), "crossed") == pytest.approx((xs[i, j], ys[i, j]), abs=1e-15)
    with pytest.raises(InvalidInputError):
        sc.coupler_path((math.nan, 0.0), t)
    rock = SliderCrank(crank=2.0, coupler=1.5, guide_point=(0.0, 1.0))
    xs, ys, ok = rock.coupler_path((0.0, 0.0), [0.0, -math.pi / 2])
    assert ok.tolist() == [True, False] and math.isnan(xs[1])


def test_bad_input_is_typed():
    with pytest.raises(TypeError):
        SliderCrank(1.0, 3.0, (0.0, 0.0))
    cases = [
        (lambda: SliderCrank(crank=-1.0, coupler=3.0, guide_point=(0, 0)), InvalidInputError, "not_positive"),
        (lambda: SliderCrank(crank=1.0, coupler=3.0, guide_point=(0, 0), guide=(0, 0)), InvalidInputError,
         "zero_direction"),
        (lambda: SliderCrank(crank=1.0, coupler=2.0, guide_point=(0, 3.5)), AssemblyError, "guide_out_of_reach"),
        (lambda: SliderCrank(crank=1.0, coupler=2.0, guide_point=(0, 0)).solve(math.inf), InvalidInputError,
         "not_finite"),
        (lambda: SliderCrank(crank=1.0, coupler=2.0, guide_point=(0, 0)).solve(0.0, "sideways"), InvalidInputError,
         "unknown_name"),
    ]
    for fn, cls, cause in cases:
        with pytest.raises(cls) as e:
            fn()
        assert e.value.cause == cause, str(e.value)
    with pytest.raises(AssemblyError) as e:
        SliderCrank(crank=1.0, coupler=2.0, guide_point=(0, 3.5))
    assert "move the guide nearer" in str(e.value)


def known_task(mode="open", angles=(0.2, 1.0, 2.1, 3.0)):
    sc = SliderCrank(crank=1.0, coupler=3.0, guide_point=(0.0, 0.4), guide=(math.cos(0.2), math.sin(0.2)))
    poses = []
    for t2 in angles:
        conf = sc.solve(t2, mode)
        x, y = sc.coupler_point(t2, (0.5, 0.7), mode)
        poses.append((x, y, conf.theta3 + 0.3))
    _, a1, b1 = sc.joints(angles[0], mode)
    return sc, Task(poses), ((0.0, 0.0), a1), (b1, sc.guide)


@pytest.mark.parametrize("n", [3, 4])
@pytest.mark.parametrize("mode", ["open", "crossed"])
def test_task_from_a_known_slider_crank(n, mode):
    angles = (0.2, 1.0, 2.1, 3.0)[:n]
    sc, task, driving, driven = known_task(mode, angles)
    s = task.slider_crank(driving, driven)
    assert s.modes == [mode] * n and s.branch_free and s.feasible
    assert s.direction == "ccw" and s.order == "-".join(str(k) for k in range(1, n + 1))
    assert s.linkage.crank == pytest.approx(1.0) and s.linkage.coupler == pytest.approx(3.0)
    for k, pose in enumerate(task.poses):
        assert s.input_angles[k] == pytest.approx(angles[k])
        assert s.pose_at(s.input_angles[k], mode) == pytest.approx(pose, abs=1e-9)
    # The stroke used: the slider's span over the travel, densely.
    sl = [s.linkage.solve(t, mode).slider for t in s.travel_angles(4001)]
    assert max(sl) - min(sl) == pytest.approx(s.stroke_used, abs=1e-6)
    mu = min(s.linkage.solve(t, mode).transmission_angle for t in s.travel_angles(4001))
    assert math.degrees(mu) == pytest.approx(s.min_transmission_deg, abs=0.1)
    assert s.size > 4.0 and s.size_ratio == pytest.approx(s.size / task.span)
    assert repr(s).startswith("<SynthesizedSliderCrank") and "branch_free=True" in repr(s)


def test_branch_defect_is_found():
    sc = SliderCrank(crank=1.0, coupler=3.0, guide_point=(0.0, 0.4), guide=(math.cos(0.2), math.sin(0.2)))
    poses, modes = [], ["open", "crossed", "open"]
    for t2, m in zip((0.2, 1.0, 2.1), modes):
        conf = sc.solve(t2, m)
        x, y = sc.coupler_point(t2, (0.5, 0.7), m)
        poses.append((x, y, conf.theta3 + 0.3))
    _, a1, b1 = sc.joints(0.2, "open")
    s = Task(poses).slider_crank(((0.0, 0.0), a1), (b1, sc.guide))
    assert s.modes == modes and not s.branch_free and not s.feasible and s.stroke_used is None


def test_task_errors_say_what_to_change():
    _, task, driving, driven = known_task()
    with pytest.raises(InvalidInputError) as e:
        task.slider_crank(driving, (driven[0], (0.0, 1.0)))
    assert e.value.cause == "not_a_slider" and "slider point" in str(e.value)
    with pytest.raises(InvalidInputError) as e:
        task.slider_crank((driving[0], (driving[1][0] + 0.1, driving[1][1])), driven)
    assert e.value.cause == "not_a_dyad"


def test_pickles_to_equal_objects():
    sc, task, driving, driven = known_task()
    s = task.slider_crank(driving, driven)
    for obj in (sc, sc.solve(0.3, "crossed"), s):
        back = pickle.loads(pickle.dumps(obj))
        assert back == obj and repr(back) == repr(obj)
    assert pickle.loads(pickle.dumps(s)).travel == s.travel


def test_travel_angles_at_the_documented_maximum():
    _, task, driving, driven = known_task()
    s = task.slider_crank(driving, driven)
    t = s.travel_angles(2**20)
    assert t.shape == (2**20,) and t[0] == pytest.approx(s.input_angles[0])
    with pytest.raises(InvalidInputError):
        s.travel_angles(2**20 + 1)
    with pytest.raises(InvalidInputError):
        s.travel_angles(1)


def test_pictures(tmp_path):
    plot = pytest.importorskip("burmester.plot")
    import matplotlib

    matplotlib.use("Agg")
    sc, task, driving, driven = known_task()
    ax = plot.slider_crank(sc, 0.4, "crossed", units="mm")
    gids = {a.get_gid() for a in ax.get_children()}
    assert {"guide", "linkage", "linkage-block", "crank-path", "fixed-pivots"} <= gids
    # The block sits on the guide around the slider pin.
    (block,) = [a for a in ax.get_children() if a.get_gid() == "linkage-block"]
    _, _, pin = sc.joints(0.4, "crossed")
    assert np.allclose(block.get_xy()[:4].mean(axis=0), pin)
    s = task.slider_crank(driving, driven)
    ax = plot.slider_crank(s)
    gids = {a.get_gid() for a in ax.get_children()}
    assert {"guide", "coupler-curve", "linkage-1", "linkage-4", "pose-1", "pose-4"} <= gids
    out = tmp_path / "slider.gif"
    plot.animate_slider_crank(s, out, frames=12, dpi=40)
    assert out.stat().st_size > 0 and not list(tmp_path.glob("*.tmp*"))
    sc2, bad_task, d2, g2 = known_task(angles=(0.2, 2.1, 1.0, 3.0))  # out of cyclic order
    bad = bad_task.slider_crank(d2, g2)
    assert not bad.feasible
    with pytest.raises(InvalidInputError):
        plot.animate_slider_crank(bad, tmp_path / "bad.gif")
