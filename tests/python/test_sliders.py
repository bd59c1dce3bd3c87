"""Slider dyads and inverted sliders of a task from Python (issue 27),
checked against things computed here, independently of the core: tasks made
by driving a slider-crank (and an inverted slider-crank) built by hand with
the textbook closed form, whose pin and guide (swivel and body line) must be
found; the collinearity of every slider dyad's positions, computed from the
poses with NumPy; pickling, repr and typed errors."""

import math
import pickle

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import burmester
from burmester import BurmesterError, InvalidInputError, InvertedSlider, SliderDyad, Task
from test_four_five import NOTES_POSES  # a crank-rocker's five poses: four finite Burmester points

ANGLES = (0.3, 0.9, 1.6, 2.2, 2.9)

def turn(v, a):
    c, s = math.cos(a), math.sin(a)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


def slider_crank(angles, r=1.0, l=3.2, g0=(0.5, -0.4), gamma=0.2, point=(1.0, 0.8)):
    """Poses of the coupler of a slider-crank (crank A0 = (0, 0) of length
    ``r``, coupler ``l``, pin B on the guide through ``g0`` at angle
    ``gamma``), by the closed form ``B = g0 + s u``, ``|B - A| = l`` (the
    larger root); and the pins B."""
    u = np.array([math.cos(gamma), math.sin(gamma)])
    poses, pins = [], []
    for t in angles:
        a = np.array([r * math.cos(t), r * math.sin(t)])
        w = np.asarray(g0) - a
        h = u @ w
        disc = h * h - w @ w + l * l
        assert disc > 0
        b = np.asarray(g0) + u * (-h + math.sqrt(disc))
        phi = math.atan2(*(b - a)[::-1])
        p = a + turn(point, phi)
        poses.append((p[0], p[1], phi))
        pins.append(b)
    return poses, pins, u


def positions(task, z):
    """``z``'s positions at the poses, from the poses themselves."""
    poses = np.array(task.poses)
    p1 = poses[0]
    return [pk[:2] + turn(np.asarray(z) - p1[:2], pk[2] - p1[2]) for pk in poses]


def off_guide(task, s):
    u = np.asarray(s.guide)
    z = np.asarray(s.circle)
    return max(abs(u[0] * (q - z)[1] - u[1] * (q - z)[0]) for q in positions(task, z))


def cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


@pytest.mark.parametrize("n", [3, 4, 5])
def test_slider_crank_pin_and_guide_are_found(n):
    poses, pins, u = slider_crank(ANGLES[:n])
    task = Task(poses)
    b1 = pins[0]
    if n == 3:
        c = task.slider_circle()
        assert c["kind"] == "circle"
        assert abs(math.dist(b1, c["center"]) - c["radius"]) < 1e-12 * task.span
        s = task.slider_dyad(tuple(b1))
    else:
        near = [s for s in task.slider_dyads() if math.dist(s.circle, b1) < 1e-8 * task.span]
        assert near, task.slider_dyads()
        s = near[0]
    assert abs(cross(s.guide, u)) < 1e-8
    assert off_guide(task, s) < 1e-9 * task.span
    for s in task.slider_dyads(50):
        reach = math.dist(s.circle, task.poses[0][:2])
        assert off_guide(task, s) < 1e-9 * (task.span + reach)


@pytest.mark.parametrize("n", [3, 4, 5])
def test_inverted_slider_crank_swivel_is_found(n):
    swivel = np.array([3.5, 0.6])
    poses = []
    for t in ANGLES[:n]:
        a = np.array([math.cos(t), math.sin(t)])
        phi = math.atan2(*(swivel - a)[::-1])
        p = a + turn((1.2, 0.7), phi)
        poses.append((p[0], p[1], phi))
    task = Task(poses)
    a1 = np.array([math.cos(ANGLES[0]), math.sin(ANGLES[0])])
    if n == 3:
        inv = task.inverted_slider(tuple(swivel))
    else:
        inv = next(i for i in task.inverted_sliders() if math.dist(i.swivel, swivel) < 1e-8)
    assert abs(cross(inv.direction, (swivel - a1) / np.linalg.norm(swivel - a1))) < 1e-8
    for k in range(1, n + 1):
        point, direction = inv.body_line_at(task, k)
        assert abs(cross(direction, swivel - np.asarray(point))) < 1e-8
    assert isinstance(task.inverted(), Task)


def test_records_pickle_compare_and_print():
    task = Task([(0, 0, 0), (2, 0.5, 0.4), (3, 2, 1.1)])
    for s in task.slider_dyads(7):
        back = pickle.loads(pickle.dumps(s))
        assert back == s and back.guide == s.guide
        assert repr(s).startswith("SliderDyad(circle=(")
    for i in task.inverted_sliders(7):
        assert pickle.loads(pickle.dumps(i)) == i
        assert "swivel=" in repr(i)
    s = SliderDyad((1.0, 2.0), (3.0, 4.0))
    assert s.guide == pytest.approx((0.6, 0.8)) and s.normal == pytest.approx((-0.8, 0.6))
    assert InvertedSlider((0.0, 0.0), (0.0, 2.0)).direction == (0.0, 1.0)
    assert burmester.SliderDyad is SliderDyad
    with pytest.raises(InvalidInputError) as e:
        SliderDyad((0.0, 0.0), (0.0, 0.0))
    assert e.value.cause == "zero_direction"
    with pytest.raises(InvalidInputError) as e:
        SliderDyad._from_fields((0.0, 0.0), (2.0, 0.0))
    assert e.value.cause == "inconsistent_state"


def test_errors_say_what_to_change():
    task = Task([(0, 0, 0), (2, 0.5, 0.4), (3, 2, 1.1)])
    with pytest.raises(InvalidInputError) as e:
        task.slider_dyad((10.0, 10.0))
    assert isinstance(e.value, BurmesterError) and isinstance(e.value, ValueError)
    assert e.value.cause == "not_a_slider_point"
    assert e.value.distance > e.value.tolerance
    assert "slider circle" in str(e.value) and "P'23" in str(e.value)
    with pytest.raises(InvalidInputError) as e:
        task.inverted_slider((10.0, 10.0))
    assert "swivel point" in str(e.value) and "pole circle" in str(e.value)
    for n in (0, 10_001):
        with pytest.raises(InvalidInputError) as e:
            task.slider_dyads(n)
        assert e.value.cause == "count_out_of_range"
    five = Task([(x, y, math.radians(a)) for x, y, a in NOTES_POSES])
    assert five.slider_dyads() == []
    with pytest.raises(InvalidInputError) as e:
        five.slider_dyad((0.0, 0.0))
    assert e.value.cause == "no_slider_point"
    assert "finite center point" in e.value.why
    with pytest.raises(InvalidInputError) as e:
        five.slider_circle()
    assert e.value.cause == "needs_poses"


def test_a_pure_translation_gives_a_line():
    task = Task([(0, 0, 0), (2, 0.5, 0.4), (3, 2, 0.4)])
    c = task.slider_circle()
    assert c["kind"] == "line"
    for t in (-20.0, 0.0, 3.0):
        z = np.asarray(c["point"]) + t * np.asarray(c["direction"])
        s = task.slider_dyad(tuple(z))
        assert off_guide(task, s) < 1e-12 * (task.span + abs(t))


def test_slider_dyads_at_the_maximum():
    task = Task([(0, 0, 0), (2, 0.5, 0.4), (3, 2, 1.1)])
    sliders = task.slider_dyads(10_000)
    assert len(sliders) == 10_000
    assert len(task.inverted_sliders(10_000)) == 10_000
    for s in sliders[::499]:
        assert off_guide(task, s) < 1e-12 * task.span * 10


@settings(max_examples=40, deadline=None)
@given(
    angle=st.floats(-math.pi, math.pi),
    factor=st.floats(0.01, 100.0),
    ox=st.floats(-50, 50),
    oy=st.floats(-50, 50),
    phi=st.lists(st.floats(-math.pi, math.pi), min_size=4, max_size=4),
)
def test_points_on_the_slider_circle_are_slider_points_in_any_frame(angle, factor, ox, oy, phi):
    base = [(0, 0, 0), (2, 0.5, 0.4), (3, 2, 1.1)]
    task = Task(
        [
            (*(factor * turn((x, y), angle) + (ox, oy)), a + angle)
            for x, y, a in base
        ]
    )
    c = task.slider_circle()
    assert c["kind"] == "circle"
    for a in phi:
        z = np.asarray(c["center"]) + c["radius"] * np.array([math.cos(a), math.sin(a)])
        s = task.slider_dyad(tuple(z))
        reach = math.dist(z, task.poses[0][:2])
        assert off_guide(task, s) < 1e-9 * (task.span + reach)
