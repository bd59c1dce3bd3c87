"""The strut's clearance a designer can trust (issue 27): the strut's own
diameter (``actuator_width``) and the links' width (``link_width``) in the
gap, a least gap (``min_gap``), the actuator map's ``clearance`` column, on
the hood of ``examples/hood.toml`` in millimetres. The gap is checked
against this file's own computation: the built linkage driven densely by
its own position analysis (its joints, the coupler frame taken from them),
segment-to-segment distances by sampling one segment and projecting on the
other, less the two half widths."""

import math
import pickle
from pathlib import Path

import numpy as np
import pytest

import burmester
from burmester import InvalidInputError, actuators, taskfile
from burmester.cli import main

ROOT = Path(__file__).resolve().parents[2]
HOOD = ROOT / "examples" / "hood.toml"
PLATE = [(-150.0, -100.0), (50.0, -100.0), (50.0, 0.0), (-150.0, 0.0)]
POINT = (-40.0, -20.0)
LIMITS = burmester.DesignLimits(min_transmission_deg=40.0, max_link_ratio=10.0, max_size_ratio=8.0)
VIEW = (-250.0, 150.0, -200.0, 200.0)
#: A 20 mm gas spring, 10 mm straps, 3 mm apart at least.
STRUT = dict(actuator_width=20.0, min_gap=3.0, link_width=10.0)


@pytest.fixture(scope="module")
def hinge():
    spec = taskfile.load(str(HOOD))
    return burmester.design(spec.task, space=spec.space, limits=spec.limits, top=1)[0].linkage


@pytest.fixture(scope="module")
def maps(hinge):
    kw = dict(point=POINT, limits=LIMITS, base_plate=PLATE)
    bare = actuators.actuator_map(hinge, VIEW, (96, 96), **kw)
    sized = actuators.actuator_map(hinge, VIEW, (96, 96), **kw, **STRUT)
    return bare, sized


def _seg_dist(p1, p2, q1, q2, n=1001):
    t = np.linspace(0.0, 1.0, n)[:, None]
    pts = p1 + t * (p2 - p1)
    d = q2 - q1
    u = np.clip(((pts - q1) @ d) / (d @ d), 0.0, 1.0)[:, None]
    return float(np.min(np.linalg.norm(pts - (q1 + u * d), axis=1)))


def _own_gap(a, steps=1500):
    """The least distance over the travel from the strut's line to the crank
    and the rocker (the links that do not carry a coupler point), by this
    file's own driving."""
    sfb = a.linkage
    mode = sfb.modes[0]
    start, span = sfb.travel
    _, ja, jb, _ = (np.array(p) for p in sfb.fourbar.joints(start, mode))
    ux = (jb - ja) / np.linalg.norm(jb - ja)
    local = np.array([(np.array(a.point) - ja) @ ux, (np.array(a.point) - ja) @ np.array([-ux[1], ux[0]])])
    g = np.array(a.ground)
    least = math.inf
    for k in range(steps + 1):
        t = start + span * k / steps
        p0, pa, pb, p4 = (np.array(p) for p in sfb.fourbar.joints(t, mode))
        x = (pb - pa) / np.linalg.norm(pb - pa)
        q = pa + local[0] * x + local[1] * np.array([-x[1], x[0]])
        least = min(least, _seg_dist(g, q, p0, pa), _seg_dist(g, q, p4, pb))
    return least


def test_the_clearance_column(maps):
    bare, sized = maps
    assert "clearance" in burmester.ActuatorMap.columns
    for m in maps:
        c = m.clearance
        assert c.dtype == np.float32 and c.shape == m.shape and not c.flags.writeable
        # Computed where the rest of the limits are met: monotone, every
        # acceptable sample among them.
        assert not (np.isfinite(c) & ~m.monotone).any() and np.isfinite(c[m.acceptable]).all()
    # The widths move every gap by their two halves (the links that do not
    # carry Q: the nearest one sets the gap where it is positive).
    assert (sized.actuator_width, sized.min_gap) == (20.0, 3.0)
    with np.errstate(invalid="ignore"):
        far = np.isfinite(bare.clearance) & (bare.clearance > 20.0)
        assert np.allclose(sized.clearance[far], bare.clearance[far] - 15.0, atol=1e-3)
        # acceptable: the bare map's acceptable samples whose gap reaches 3 mm
        # (the rest of the limits alike), exactly.
        tie = np.abs(sized.clearance - 3.0) < 1e-4
        keep = bare.acceptable & (sized.clearance >= 3.0) & (sized.clearance > 0.0)
    assert np.array_equal(sized.acceptable[~tie], keep[~tie])
    assert keep.any() and (bare.acceptable & ~keep).any()


def test_placements_agree_with_own_driving(maps):
    _, sized = maps
    picked = sized.best_placements(3) + [sized.placement(j, i)
                                         for j, i in np.argwhere(np.isfinite(sized.clearance))[::97]]
    for a in picked:
        own = _own_gap(a) - 0.5 * (20.0 + 10.0)
        j, i = a.index
        # The refined gap is at most the sampled one, and both near this
        # file's own (a sample step of the travel and of the segments).
        assert a.min_clearance <= float(sized.clearance[j, i]) + 1e-4
        if own < 20.0:  # where the crank or the rocker is nearest (else the coupler's bar)
            assert a.min_clearance == pytest.approx(own, abs=0.3), (a.ground, own)
        assert a.clear == (a.min_clearance > 0.0 and a.min_clearance >= 3.0)
        assert (a.actuator_width, a.min_gap, a.link_width) == (20.0, 3.0, 10.0)
    best = sized.best_placements(1)[0]
    assert best.acceptable and best.clear and best.min_clearance >= 3.0


def test_invariance_under_moves_rotations_and_scaling(hinge):
    """The hinge moved, turned and scaled (built from its own centers in the
    moved task): the gap scales, the verdict stays."""
    spec = taskfile.load(str(HOOD))
    k, phi, (dx, dy) = 2.0, 0.7, (300.0, -120.0)
    c, s = math.cos(phi), math.sin(phi)

    def move(p):
        return (k * (c * p[0] - s * p[1]) + dx, k * (s * p[0] + c * p[1]) + dy)

    moved = burmester.Task([(*move((x, y)), t + phi) for x, y, t in spec.task.poses])
    sfb2 = moved.four_bar(move(hinge.driving[0]), move(hinge.driven[0]))
    for g in ((-50.625, -88.125), (-20.0, -60.0), (10.0, -95.0)):
        a = hinge.actuator(g, point=POINT, **STRUT)
        b = sfb2.actuator(move(g), point=move(POINT), actuator_width=20.0 * k, min_gap=3.0 * k,
                          link_width=10.0 * k)
        assert b.min_clearance == pytest.approx(k * a.min_clearance, rel=1e-6, abs=1e-6 * k * 100.0)
        assert b.clear == a.clear and b.monotone == a.monotone


def test_pickles_and_old_pickles(maps, hinge):
    bare, sized = maps
    a = sized.best_placements(1)[0]
    for x in (a, sized):
        y = pickle.loads(pickle.dumps(x))
        assert y == x and (y.actuator_width, y.min_gap) == (20.0, 3.0)
    assert pickle.loads(pickle.dumps(bare)) != sized
    # A pickle from before the strut's diameter and gap (no such state) reads
    # as 0, 0.
    f, args = a.__reduce__()
    old = f(*args[:8])
    assert (old.actuator_width, old.min_gap) == (0.0, 0.0) and old.ground == a.ground
    spec = taskfile.load(str(HOOD))
    r = burmester.design(spec.task, space=spec.space, limits=spec.limits, input="actuator", top=1, starts=4,
                         actuator_width=20.0, min_gap=3.0)
    again = pickle.loads(pickle.dumps(r))
    assert again == r and again[0].actuator.actuator_width == 20.0
    f, args = r.__reduce__()
    assert f(*args[:-1], args[-1][:2]) != r  # the old form: the strut's terms read as 0, 0


def test_typed_errors(hinge):
    for kw, name in ((dict(actuator_width=-1.0), "actuator_width"), (dict(min_gap=-0.5), "min_gap"),
                     (dict(actuator_width=math.nan), "actuator_width"), (dict(min_gap=math.inf), "min_gap")):
        with pytest.raises(InvalidInputError, match=f"{name} must be between 0 and .*pass a value in that range"):
            hinge.actuator((0.0, -50.0), **kw)
        with pytest.raises(InvalidInputError, match=name):
            hinge.actuator_map(*VIEW, 4, 4, **kw)
        spec = taskfile.load(str(HOOD))
        with pytest.raises(InvalidInputError, match=name):
            burmester.design(spec.task, input="actuator", **kw)
        with pytest.raises(InvalidInputError, match='input="actuator"'):
            burmester.design(spec.task, **kw)


def test_task_file_and_command_line(tmp_path, capsys):
    import json

    text = HOOD.read_text()
    assert "min_gap = 3.0" in text and "width = 20.0" in text and "link_width = 10.0" in text
    spec = taskfile.load(str(HOOD))
    assert (spec.actuator.width, spec.actuator.min_gap) == (20.0, 3.0)
    assert taskfile.loads(taskfile.dumps(spec)).actuator == spec.actuator  # written out and read back
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace("min_gap = 3.0", "min_gap = -3.0"))
    with pytest.raises(taskfile.TaskFileError, match=r"actuator\.min_gap.*at least 0"):
        taskfile.load(str(bad))
    old = tmp_path / "old.toml"  # a file from before min_gap: it reads, the gap 0
    old.write_text(text.replace("min_gap = 3.0", ""))
    assert taskfile.load(str(old)).actuator.min_gap is None
    # design --input actuator takes the table's width and gap; the flags
    # override them.
    assert main(["design", str(HOOD), "--input", "actuator", "--top", "1", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    for d in doc["designs"]:
        a = d["actuator"]
        assert (a["actuator_width"], a["min_gap"]) == (20.0, 3.0) and a["clear"] and a["min_clearance"] >= 3.0
    # No hinge keeps 25 mm on the file's bracket: a few points of the
    # coupler tried, so that a design is judged by the flag's gap.
    assert main(["design", str(HOOD), "--input", "actuator", "--try-actuator-points", "--top", "1", "--min-gap", "25",
                 "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert all(d["actuator"]["min_clearance"] >= 25.0 for d in doc["designs"])
    assert main(["design", str(HOOD), "--input", "actuator", "--min-gap", "-1"]) == 2
    assert "--min-gap must be at least 0" in capsys.readouterr().err
    assert main(["design", str(HOOD), "--actuator-width", "20"]) == 2
    assert "give --input actuator" in capsys.readouterr().err
