"""burmester.design(..., input="actuator") (issue 27 item 3): every design
driven by a linear actuator placed with it, on the hood of
``examples/hood.toml`` in millimetres.

Each verdict is checked here by an independent route: the built linkage
driven densely by its input angle (4 000 steps) from its own joints
(``FourBar.joints``), the actuator's moving point carried in the coupler's
frame by this test, its length, its speed by central differences, and the
strut's distance to the links by this test's own segment distance (numpy):
the length is monotone, the stroke ratio and the force transmission angle
are within the limits, and the strut clears the links by more than their
width. Moving and scaling the task moves and scales the answer. Designs
with their actuators pickle; bad input names the field; the command line
prints and draws them. The Rust tests in tests/rust/actuator.rs check the
clearance against dense driving over random linkages (with obstacles and
link widths) and under rotations."""

import json
import math
import pickle
from pathlib import Path

import numpy as np
import pytest

import burmester
from burmester import InvalidInputError, taskfile

HOOD = Path(__file__).resolve().parents[2] / "examples" / "hood.toml"
#: The hood's limits with room for the open strut (the hinge alone is 3.8
#: task sizes).
LIMITS = dict(min_transmission_deg=40.0, max_link_ratio=10.0, min_grashof_margin=0.01, max_size_ratio=8.0)
QUICK = dict(top=3, starts=12)


def _hood(shift=(0.0, 0.0), scale=1.0, width=15.0):
    spec = taskfile.load(str(HOOD))
    poses = [(scale * x + shift[0], scale * y + shift[1], a) for x, y, a in spec.task.poses]
    x0, x1, y0, y1 = spec.space.pivot_box
    box = (scale * x0 + shift[0], scale * x1 + shift[0], scale * y0 + shift[1], scale * y1 + shift[1])
    space = burmester.Space(pivot_box=box, link_width=width * scale)
    return burmester.Task(poses), space, burmester.DesignLimits(**LIMITS)


def _seg_dist(p1, p2, q1, q2):
    """The distance between two segments, by sampling one and projecting
    onto the other (this test's own route, exact to the sampling)."""
    t = np.linspace(0.0, 1.0, 2001)[:, None]
    pts = p1 + t * (p2 - p1)
    d = q2 - q1
    u = np.clip(((pts - q1) @ d) / (d @ d), 0.0, 1.0)[:, None]
    return float(np.min(np.linalg.norm(pts - (q1 + u * d), axis=1)))


def _dense(a, steps=4000):
    """``(lengths, transmission angles, least strut-to-link distance)`` over
    the travel, from the linkage's own joints."""
    sfb = a.linkage
    mode = sfb.modes[0]
    start, span = sfb.travel
    o2, ja, jb, _ = sfb.fourbar.joints(start, mode)
    ja, jb = np.array(ja), np.array(jb)
    ux = (jb - ja) / np.linalg.norm(jb - ja)
    uy = np.array([-ux[1], ux[0]])
    local = np.array(a.point) - ja
    local = np.array([local @ ux, local @ uy])
    g = np.array(a.ground)

    def q_at(t):
        _, pa, pb, _ = sfb.fourbar.joints(t, mode)
        pa, pb = np.array(pa), np.array(pb)
        x = (pb - pa) / np.linalg.norm(pb - pa)
        return pa + local[0] * x + local[1] * np.array([-x[1], x[0]])

    # The links that carry Q (at a joint: the crank at A, the rocker at C)
    # may only not cross the strut away from Q; the others must clear it.
    carries = [_seg_dist(np.array(a.point), np.array(a.point), np.array(c), np.array(m)) < 1e-9 * sfb.size
               for c, m in (sfb.driving, sfb.driven)]
    s, mu, gap, crossed = [], [], math.inf, False
    h = 1e-6 * math.copysign(1.0, span)
    for k in range(steps + 1):
        t = start + span * k / steps
        q = q_at(t)
        v = (q_at(t + h) - q_at(t - h)) / (2 * h)
        d = q - g
        s.append(float(np.linalg.norm(d)))
        mu.append(math.asin(min(1.0, abs(d @ v) / (np.linalg.norm(d) * np.linalg.norm(v)))))
        if k % 40 == 0:
            p0, pa, pb, p4 = (np.array(p) for p in sfb.fourbar.joints(t, mode))
            short = q - 1e-3 * d
            for carried, (c, m) in zip(carries, ((p0, pa), (p4, pb))):
                if carried:
                    crossed = crossed or _seg_dist(g, short, c, m) < 1e-9 * sfb.size
                else:
                    gap = min(gap, _seg_dist(g, q, c, m))
    return np.array(s), np.array(mu), gap, crossed


def test_hood_designs_carry_a_clear_actuator():
    task, space, limits = _hood()
    # The strut as wide as the links (what the gap below takes off).
    r = burmester.design(task, space=space, limits=limits, input="actuator", actuator_width=space.link_width,
                         **QUICK)
    assert r.actuator and len(r) >= 1 and r.limits.input == "any"
    box = space.pivot_box
    for d in r:
        a = d.actuator
        assert isinstance(a, burmester.Actuator) and a.linkage == d.linkage and a.link == "coupler"
        assert a.monotone and a.acceptable and a.clear and a.min_clearance > 0
        assert box[0] <= a.ground[0] <= box[1] and box[2] <= a.ground[1] <= box[3]
        s, mu, gap, crossed = _dense(a)
        steps = np.diff(s)
        assert np.all(steps > 0) if a.extends else np.all(steps < 0)
        assert s.max() / s.min() <= 1.8 + 1e-9
        assert s.max() / s.min() == pytest.approx(a.stroke_ratio, rel=1e-6)
        assert s.min() == pytest.approx(a.min_length, rel=1e-6)
        assert math.degrees(mu.min()) >= 40.0 - 1e-3
        assert math.degrees(mu.min()) == pytest.approx(a.min_transmission_deg, abs=1e-2)
        # The links that do not carry Q clear the strut by more than the
        # links' width (two half widths); those that do never cross it.
        assert not crossed
        if math.isfinite(gap):
            assert gap - space.link_width >= a.min_clearance - 1e-6 * task.span
            assert gap > space.link_width
    assert pickle.loads(pickle.dumps(r)) == r


def test_moving_and_scaling_the_hood_moves_and_scales_the_actuator():
    # The hinge search's own starts need not map exactly (its coarse grid
    # is laid over the box), so the designs of both are matched by their
    # pivots; the actuator of each matched hinge must map.
    task, space, limits = _hood()
    # A 20 mm strut 3 mm clear, scaled with the rest.
    r = burmester.design(task, space=space, limits=limits, input="actuator", top=5, starts=12,
                         actuator_width=20.0, min_gap=3.0)
    (dx, dy), k = (250.0, -40.0), 2.5
    task2, space2, limits2 = _hood((dx, dy), k)
    r2 = burmester.design(task2, space=space2, limits=limits2, input="actuator", top=5, starts=12,
                          actuator_width=20.0 * k, min_gap=3.0 * k)

    def moved(p):
        return np.array([k * p[0] + dx, k * p[1] + dy])

    matched = 0
    for d in r:
        for e in r2:
            near = max(np.linalg.norm(moved(d.driving_pivot) - e.driving_pivot),
                       np.linalg.norm(moved(d.driven_pivot) - e.driven_pivot))
            if near > 1e-3 * task2.span:
                continue
            matched += 1
            a, b = d.actuator, e.actuator
            assert b.ground == pytest.approx(tuple(moved(a.ground)), abs=1e-6 * task2.span)
            assert b.point == pytest.approx(tuple(moved(a.point)), abs=1e-3 * task2.span)
            assert b.stroke_ratio == pytest.approx(a.stroke_ratio, rel=1e-4)
            assert b.stroke == pytest.approx(k * a.stroke, rel=1e-4)
            assert b.min_clearance == pytest.approx(k * a.min_clearance, rel=1e-3, abs=1e-3 * task2.span)
            assert b.clear == a.clear and b.monotone == a.monotone
            assert a.min_clearance >= 3.0 and (b.actuator_width, b.min_gap) == (20.0 * k, 3.0 * k)
    assert matched >= 1


def test_a_given_point_at_the_documented_maximum_of_samples():
    task, space, limits = _hood()
    r = burmester.design(task, space=space, limits=limits, input="actuator", top=1, starts=4,
                         actuator_point=(-40.0, -20.0), actuator_samples=512)
    for d in r:
        assert d.actuator.point == (-40.0, -20.0) and d.actuator.clear
    with pytest.raises(InvalidInputError, match="actuator samples"):
        burmester.design(task, space=space, limits=limits, input="actuator", top=1, actuator_samples=513)


def test_an_impossible_actuator_passes_designs_over():
    task, space, limits = _hood()
    # A stroke ratio of 1.01 is no actuator for a hood that lifts 90 mm.
    r = burmester.design(task, space=space, limits=limits, input="actuator", max_stroke_ratio=1.01, **QUICK)
    assert len(r) == 0 and r.unplaced >= 1
    assert pickle.loads(pickle.dumps(r)) == r and pickle.loads(pickle.dumps(r)).unplaced == r.unplaced


def test_bad_actuator_input_names_the_field():
    task, space, limits = _hood()
    for kw in (dict(actuator_link="rocker"), dict(actuator_point=(0.0, 0.0)), dict(max_stroke_ratio=2.0),
               dict(actuator_samples=10)):
        with pytest.raises(InvalidInputError, match='input="actuator"'):
            burmester.design(task, space=space, **kw)
    with pytest.raises(InvalidInputError, match="max_stroke_ratio"):
        burmester.design(task, space=space, input="actuator", max_stroke_ratio=0.5)
    with pytest.raises(InvalidInputError, match="wheel"):
        burmester.design(task, space=space, input="actuator", actuator_link="wheel")
    with pytest.raises(InvalidInputError) as e:
        burmester.design(task, input="cylinder")
    assert "actuator" in str(e.value) and isinstance(e.value, ValueError)


def test_the_command_line_prints_and_draws_the_actuator(tmp_path, capsys):
    from burmester.cli import main

    args = ["design", str(HOOD), "--input", "actuator", "--top", "2"]
    assert main([*args, "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert "unplaced" in doc and doc["designs"]
    for d in doc["designs"]:
        a = d["actuator"]
        assert a["monotone"] and a["acceptable"] and a["clear"] and a["stroke_ratio"] <= 1.8
    assert main(args) == 0
    text = capsys.readouterr().out
    assert "With a linear actuator" in text and "clear over the travel" in text
    assert main(["design", str(HOOD), "--max-stroke-ratio", "1.5"]) == 2
    assert main([*args, "--motor"]) == 2
    capsys.readouterr()
    pytest.importorskip("matplotlib")
    png = tmp_path / "strut.png"
    assert main([*args, "-o", str(png)]) == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "linear actuator" in capsys.readouterr().out
