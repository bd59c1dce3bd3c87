"""A linear actuator added to a synthesized four-bar, from Python: the
placement map, placements, pickling, errors, the one-call helper, the
picture and ``burmester actuator``. The kinematics are checked against
dense driving in ``tests/rust/actuator.rs``; here again on the hood task in
millimetres, by this file's own driving of the built linkage (its joints,
the coupler frame taken from them, numerical velocities)."""

import json
import math
import pickle
from pathlib import Path

import numpy as np
import pytest

import burmester
from burmester import actuators, taskfile
from burmester.cli import main

ROOT = Path(__file__).resolve().parents[2]
HOOD = ROOT / "examples" / "hood.toml"


@pytest.fixture(scope="module")
def hood():
    spec = taskfile.load(str(HOOD))
    report = burmester.design(spec.task, space=spec.space, limits=spec.limits, top=1)
    return spec, report[0].linkage


#: The strut's ground pivot on the body (the task's pivot space), its
#: point on a bracket under the hood, and the hinge's limits with room for
#: the strut's length in the size.
PLATE = [(-150.0, -100.0), (50.0, -100.0), (50.0, 0.0), (-150.0, 0.0)]
POINT = (-40.0, -20.0)
LIMITS = burmester.DesignLimits(min_transmission_deg=40.0, max_link_ratio=10.0, max_size_ratio=8.0)


@pytest.fixture(scope="module")
def amap(hood):
    _, sfb = hood
    return actuators.actuator_map(sfb, (-250.0, 150.0, -200.0, 200.0), (120, 120), point=POINT,
                                  limits=LIMITS, max_stroke_ratio=1.8, base_plate=PLATE)


def _coupler_point(sfb, q, t, mode):
    """The point of the coupler that is at ``q`` at pose 1, at input ``t``
    (the coupler frame from the joints A and B)."""
    _, a1, b1, _ = sfb.fourbar.joints(sfb.input_angles[0], mode)
    ang1 = math.atan2(b1[1] - a1[1], b1[0] - a1[0])
    dx, dy = q[0] - a1[0], q[1] - a1[1]
    lx = math.cos(-ang1) * dx - math.sin(-ang1) * dy
    ly = math.sin(-ang1) * dx + math.cos(-ang1) * dy
    _, a, b, _ = sfb.fourbar.joints(t, mode)
    ang = math.atan2(b[1] - a[1], b[0] - a[0])
    return (a[0] + math.cos(ang) * lx - math.sin(ang) * ly, a[1] + math.sin(ang) * lx + math.cos(ang) * ly)


def _dense(sfb, q, g, n=4000):
    """Monotone, stroke ratio and minimum transmission angle (degrees) by
    driving the linkage densely."""
    mode = sfb.modes[0]
    start, span = sfb.travel
    ts = start + span * np.linspace(0.0, 1.0, n + 1)
    pts = np.array([_coupler_point(sfb, q, t, mode) for t in ts])
    s = np.hypot(pts[:, 0] - g[0], pts[:, 1] - g[1])
    ds = np.diff(s)
    monotone = bool(np.all(ds > 0) or np.all(ds < 0))
    h = 1e-6 * math.copysign(1.0, span)
    mu = []
    for t, p in zip(ts, pts):
        a = np.array(_coupler_point(sfb, q, t + h, mode))
        b = np.array(_coupler_point(sfb, q, t - h, mode))
        v = (a - b) / (2 * h)
        d = p - np.asarray(g)
        c = abs(d @ v) / (np.linalg.norm(d) * np.linalg.norm(v))
        mu.append(90.0 - math.degrees(math.acos(min(1.0, c))))
    return monotone, s.max() / s.min(), min(mu)


def test_map_columns(amap):
    assert amap.shape == (120, 120)
    for name in burmester.ActuatorMap.columns:
        col = getattr(amap, name)
        assert col.shape == (120, 120) and not col.flags.writeable
    assert amap.monotone.dtype == np.bool_ and amap.stroke_ratio.dtype == np.float32
    assert amap.monotone.any() and (~amap.monotone & amap.valid).any()
    assert not (amap.acceptable & ~amap.monotone).any()
    ok = amap.acceptable
    assert (amap.stroke_ratio[ok] <= 1.8 + 1e-6).all()
    assert (np.degrees(amap.min_transmission_rad[ok]) >= 40.0 - 1e-4).all()
    assert amap.link == "coupler" and len(amap.point_at_poses) == 3


def test_placements_agree_with_dense_driving(hood, amap):
    _, sfb = hood
    rng = np.random.default_rng(7)
    seen = {True: 0, False: 0}
    for _ in range(12):
        j, i = (int(v) for v in rng.integers(0, 120, 2))
        if not amap.valid[j, i]:
            continue
        a = amap.placement(j, i)
        mono, ratio, mu = _dense(sfb, a.point, a.ground)
        assert a.monotone == mono == bool(amap.monotone[j, i])
        seen[mono] += 1
        assert a.stroke_ratio == pytest.approx(ratio, rel=1e-6)
        if mono:
            assert a.min_transmission_deg == pytest.approx(mu, abs=1e-3)
        else:
            assert a.min_transmission_deg == 0.0 and a.turning_points
    assert seen[True] and seen[False]


def test_best_placements_and_pickling(hood, amap):
    _, sfb = hood
    best = amap.best_placements(3)
    assert best and all(a.acceptable and a.monotone for a in best)
    assert [a.score for a in best] == sorted((a.score for a in best), reverse=True)
    a = best[0]
    again = sfb.actuator(a.ground, point=a.point, max_stroke_ratio=1.8, limits=amap.limits, base_plate=PLATE)
    assert again.stroke_ratio == a.stroke_ratio and again.pose_lengths == a.pose_lengths
    assert pickle.loads(pickle.dumps(a)) == a
    assert pickle.loads(pickle.dumps(amap)) == amap
    assert amap.pareto_front()
    theta, xs, ys, s = a.travel(16)
    assert len(theta) == 16 and s[0] == pytest.approx(a.pose_lengths[0])
    assert "Actuator" in repr(a) and "ActuatorMap" in repr(amap)


def test_typed_errors(hood):
    _, sfb = hood
    with pytest.raises(burmester.InvalidInputError, match="actuator link"):
        sfb.actuator((0.0, -50.0), link="piston")
    with pytest.raises(burmester.InvalidInputError, match="max_stroke_ratio"):
        sfb.actuator((0.0, -50.0), max_stroke_ratio=0.5)
    with pytest.raises(burmester.InvalidInputError):
        sfb.actuator((0.0, -50.0), samples=2)
    with pytest.raises(TypeError, match="obstacles"):
        sfb.actuator((0.0, -50.0), obstacles=[])
    with pytest.raises(burmester.InvalidInputError):
        sfb.actuator_map(-1, 1, -1, 1, 1025, 1024)
    with pytest.raises(burmester.DegenerateError):
        sfb.actuator(sfb.driving[0], link="crank", point=sfb.driving[0])
    q = sfb.driven[1]
    with pytest.raises(burmester.DegenerateError):
        sfb.actuator(q, link="rocker", point=q)


def test_design_actuator_and_picture(hood, tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    spec, sfb = hood
    a = burmester.design_actuator(sfb, samples=(60, 60), point=POINT, limits=LIMITS, base_plate=PLATE)
    assert a.acceptable
    body, rod = actuators.cylinder(a.ground, a.point, a.min_length, a.stroke, 5.0)
    # The body starts at the ground pivot, the rod ends at the point, on one axis.
    assert np.allclose(0.5 * (body[0] + body[3]), a.ground)
    assert np.allclose(0.5 * (rod[1] + rod[2]), a.point)
    rec = actuators.actuator_record(a)
    json.dumps(rec)
    assert "stroke ratio" in actuators.actuator_table(a, units="mm")
    fig, (l, r) = plt.subplots(1, 2)
    actuators.draw_map(sfb.actuator_map(-250, 150, -200, 200, 40, 40), ax=l)
    actuators.draw_actuator(a, ax=r)
    gids = {x.get_gid() for x in r.get_children()}
    assert "actuator-body-1" in gids and "actuator-rod-3" in gids
    fig.savefig(tmp_path / "a.png")
    plt.close(fig)


def test_cli_actuator(tmp_path, capsys):
    hood = [str(HOOD), "--point", "-40", "-20", "--max-size-ratio", "8"]
    assert main(["actuator", *hood, "--map-grid", "60", "60", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["actuator"]["monotone"] and doc["actuator"]["stroke_ratio"] <= 1.8
    out = tmp_path / "strut.png"
    assert main(["actuator", *hood, "--map-grid", "40", "40", "-o", str(out)]) == 0
    assert out.stat().st_size > 0
    assert "Linear actuator" in capsys.readouterr().out
