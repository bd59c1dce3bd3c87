"""burmester.design(..., input="motor") (issue 23 item 3): every design a
motor can turn. On the built-in example some of the best linkages by the
balanced score are triple-rockers whose input swings: each design either turns fully or carries a
drive whose six-bar reaches the poses (checked here from the six-bar's own
joints at the drive's crank angles, against the task's poses) with both
loops' transmission angles at least the limit; drives pickle with their
designs; a drive that cannot exist passes the design over; bad input names
the field; the command line prints and draws the six-bar.

The independent check of the drives (driven through a full crank turn by a
separate loop-closure solver) is the Rust test
``design_with_a_motor_turns_every_design`` in tests/rust/drive.rs."""

import json
import math
import pickle

import pytest

import burmester
from burmester import InvalidInputError, Task
from conftest import POSES

#: A quicker search than the default (the coarse pass and the starts).
QUICK = dict(rank_by="balanced", coarse_driven=5, coarse_driving=16, starts=12)


def _angle_gap(a, b):
    return abs((a - b + math.pi) % (2 * math.pi) - math.pi)


def test_motor_designs_on_the_example_are_driven_or_turn_fully():
    t = Task(POSES)
    r = burmester.design(t, input="motor", **QUICK)
    assert r.motor and r.swing_margin_deg == 0.0 and r.max_time_ratio == math.inf
    assert 1 <= len(r) <= 5 and r.limits.input == "any"
    limit = r.limits.min_transmission_deg
    drives = 0
    for d in r:
        if d.figures.input_full:
            assert d.drive is None
            continue
        drive = d.drive
        assert isinstance(drive, burmester.Drive)
        drives += 1
        assert drive.linkage == d.linkage and drive.acceptable and drive.sixbar.crank_turns_fully
        assert drive.drive_transmission_deg >= limit and drive.motion_transmission_deg >= limit
        assert drive.min_transmission_deg >= limit
        # The six-bar's coupler at the drive's crank angles is at the poses,
        # the angles in the motor's direction within one stroke.
        angles = drive.pose_crank_angles
        sign = 1.0 if drive.direction == "ccw" else -1.0
        assert all((b - a) * sign > 0 for a, b in zip(angles, angles[1:]))
        assert (angles[-1] - drive.stroke_start) * sign <= drive.stroke + 1e-9
        for phi, (x, y, a) in zip(angles, POSES):
            px, py, pa = drive.pose_at(phi)
            assert math.hypot(px - x, py - y) < 1e-9 * t.span and _angle_gap(pa, a) < 1e-9
    assert drives >= 1, "one of the example's designs swings: it needs a drive"
    # Without a motor: the same linkages, no drives (none was passed over).
    if r.undriven == 0:
        plain = burmester.design(t, **QUICK)
        assert [d.linkage for d in plain] == [d.linkage for d in r]
        assert all(d.drive is None for d in plain) and not plain.motor and plain.undriven == 0


def test_drives_pickle_with_their_designs():
    t = Task(POSES)
    r = burmester.design(t, input="motor", **QUICK)
    back = pickle.loads(pickle.dumps(r))
    assert back == r and back.undriven == r.undriven and back.motor
    for d, e in zip(r, back):
        assert e == d and (e.drive is None) == (d.drive is None)
        if d.drive is not None:
            assert e.drive == d.drive and e.drive.drive_pivot == d.drive.drive_pivot
            assert e.drive.time_ratio == d.drive.time_ratio
            assert pickle.loads(pickle.dumps(d)) == d
    assert any(d.drive is not None for d in back)


def test_input_overrides_the_limits_input():
    t = Task(POSES)
    cranks = burmester.design(t, input="crank", top=3, **QUICK)
    assert cranks.limits.input == "crank" and not cranks.motor
    assert all(d.figures.input_full and d.drive is None for d in cranks)
    rockers = burmester.design(t, input="rocker", top=3, **QUICK)
    assert rockers.limits.input == "rocker"
    assert len(rockers) >= 1 and all(not d.figures.input_full and d.drive is None for d in rockers)


def test_an_impossible_drive_passes_designs_over():
    t = Task(POSES)
    r = burmester.design(t, input="motor", swing_margin_deg=5.0, max_time_ratio=1.0, top=3, **QUICK)
    assert r.undriven >= 1 and r.swing_margin_deg == pytest.approx(5.0) and r.max_time_ratio == 1.0
    assert all(d.figures.input_full and d.drive is None for d in r)


def test_bad_input_names_the_field():
    t = Task(POSES)
    with pytest.raises(InvalidInputError) as e:
        burmester.design(t, input="engine", **QUICK)
    msg = str(e.value)
    assert isinstance(e.value, ValueError)
    assert "input" in msg and "engine" in msg and all(w in msg for w in ("any", "crank", "rocker", "motor"))
    with pytest.raises(InvalidInputError, match="swing_margin_deg"):
        burmester.design(t, swing_margin_deg=5.0, **QUICK)
    with pytest.raises(InvalidInputError, match="max_time_ratio"):
        burmester.design(t, input="crank", max_time_ratio=2.0, **QUICK)
    with pytest.raises(InvalidInputError, match="swing_margin_deg"):
        burmester.design(t, input="motor", swing_margin_deg=-1.0, **QUICK)
    with pytest.raises(InvalidInputError, match="max_time_ratio"):
        burmester.design(t, input="motor", max_time_ratio=0.5, **QUICK)
    with pytest.raises(InvalidInputError, match="max_time_ratio"):
        burmester.design(t, input="motor", max_time_ratio=math.nan, **QUICK)


def test_the_command_line_prints_and_draws_the_six_bar(tmp_path, capsys):
    from burmester.cli import main

    # By the compact score the example's best design is a triple-rocker: it
    # gets a drive, which -o draws.
    args = ["design", "--motor", "--rank-by", "compact"]
    assert main([*args, "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["motor"] == {"swing_margin_deg": 0.0, "max_time_ratio": None, "undriven": doc["motor"]["undriven"]}
    assert all("drive" in d for d in doc["designs"])
    driven = [d for d in doc["designs"] if d["drive"] is not None]
    assert driven, "one of the example's designs swings"
    for d in driven:
        dr = d["drive"]
        assert dr["acceptable"] and dr["min_transmission_deg"] >= doc["limits"]["min_transmission_deg"]
        assert dr["input_pivot"] == d["driving_center"] and dr["time_ratio"] >= 1.0
        assert set(dr["lengths"]) >= {"crank", "drive_coupler", "drive_ground", "rocker"}
    assert main(args) == 0
    text = capsys.readouterr().out
    assert "With a motor" in text and "Motor drive for design" in text and "added dyad: motor crank pivot D0" in text
    assert "drive loop:" in text and "time ratio" in text
    # Without --motor the margin is refused.
    assert main(["design", "--margin", "5"]) == 2
    capsys.readouterr()
    pytest.importorskip("matplotlib")
    pytest.importorskip("ezdxf")
    import ezdxf

    assert doc["designs"][0]["drive"] is not None
    gif, dxf = tmp_path / "x.gif", tmp_path / "x.dxf"
    assert main([*args, "--frames", "6", "-o", str(gif)]) == 0
    assert gif.read_bytes()[:6] in (b"GIF89a", b"GIF87a")
    assert main([*args, "--travel", "4", "-o", str(dxf)]) == 0
    out = capsys.readouterr().out
    layers = {layer.dxf.name for layer in ezdxf.readfile(dxf).layers}
    assert "six-bar" in out
    assert {"CRANK_CIRCLE", "DRIVE_1", "ATTACHMENT_ARC", "TURN"} <= layers
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.dxf", "x.gif"]
    assert main([*args, "-o", str(gif)]) == 2  # exists: --force replaces it
    assert main([*args, "--force", "--frames", "4", "-o", str(gif)]) == 0
    capsys.readouterr()
