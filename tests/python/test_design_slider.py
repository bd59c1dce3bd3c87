"""``burmester.design(..., driven="slider")`` (issue 27): slider-cranks
from poses in one call, checked against a known slider-crank (its coupler
poses by the textbook closed form, written here), a slider-crank solver
written here driving every design through its travel, pickling, the
command line and the task file's ``[design] driven``."""

from __future__ import annotations

import json
import math
import pickle
from pathlib import Path

import pytest

import burmester
from burmester import InvalidInputError, Task

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

#: The known slider-crank: crank pivot, crank, coupler, offset (the guide
#: along x at y = E in the pivot's frame), the frame turned by PHI.
A0, R, L, E, PHI = (0.3, -0.2), 1.0, 3.2, 0.5, 0.4
LOCAL = (1.2, 0.9)


def textbook(theta: float):
    """Norton's closed form of the offset slider-crank (Design of
    Machinery, section 4.6) in the pivot's frame: the crank pin, the pin
    (ahead of the crank pin along the guide) and the coupler angle."""
    ax, ay = R * math.cos(theta), R * math.sin(theta)
    th3 = math.asin((E - ay) / L)
    return (ax, ay), (ax + L * math.cos(th3), E), th3


def world(p):
    c, s = math.cos(PHI), math.sin(PHI)
    return (A0[0] + c * p[0] - s * p[1], A0[1] + s * p[0] + c * p[1])


def known_task(thetas):
    poses = []
    for t in thetas:
        (ax, ay), _, th3 = textbook(t)
        c, s = math.cos(th3), math.sin(th3)
        x, y = world((ax + c * LOCAL[0] - s * LOCAL[1], ay + s * LOCAL[0] + c * LOCAL[1]))
        poses.append((x, y, th3 + PHI + 0.25))
    return Task(poses), world(textbook(thetas[0])[1])


def own_pose(sc: burmester.SynthesizedSliderCrank, theta: float):
    """The coupler pose by the solver here: the pin where the circle of the
    coupler about the crank pin meets the guide (the library's modes:
    "open" puts the pin behind the crank pin along the guide)."""
    lk = sc.linkage
    (fx, fy), (ux, uy) = lk.foot, lk.guide
    px, py = lk.pivot
    ax, ay = px + lk.crank * math.cos(theta), py + lk.crank * math.sin(theta)
    wx, wy = ax - fx, ay - fy
    along, h = wx * ux + wy * uy, -wx * uy + wy * ux
    sign = -1.0 if sc.modes[0] == "open" else 1.0
    s = along + sign * math.sqrt(lk.coupler**2 - h * h)
    cx, cy = fx + s * ux, fy + s * uy
    th3 = math.atan2(cy - ay, cx - ax)
    qx, qy = sc.coupler_point
    c, sn = math.cos(th3), math.sin(th3)
    return ax + c * qx - sn * qy, ay + sn * qx + c * qy, th3 + sc.coupler_angle_offset


def wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


def check(task: Task, report: burmester.DesignReport) -> None:
    """Every design a slider-crank that reaches the poses at its travel
    stops (the solver here and pose_at) within the limits."""
    assert len(report) > 0
    span = task.span
    for d in report:
        sc = d.linkage
        assert isinstance(sc, burmester.SynthesizedSliderCrank)
        assert d.driven_kind == "slider" and d.figures is None and d.driven_pivot is None
        assert sc.feasible and d.found_by in ("slider_circle", "slider_point")
        assert sc.min_transmission_deg >= report.limits.min_transmission_deg - 1e-9
        for k, theta in enumerate(sc.travel_stops):
            x, y, a = own_pose(sc, theta)
            px, py, pa = task.poses[k]
            assert math.hypot(x - px, y - py) < 1e-9 * span
            assert abs(wrap(a - pa)) < 1e-9
            qx, qy, qa = sc.pose_at(theta, sc.modes[0])
            assert math.hypot(qx - px, qy - py) < 1e-9 * span and abs(wrap(qa - pa)) < 1e-9
        assert d.size_ratio == pytest.approx(sc.size_ratio, rel=1e-12)


@pytest.mark.parametrize("thetas", [(0.3, 1.2, 2.0), (0.3, 1.0, 1.8, 2.7), (0.1, 0.8, 1.5, 2.3, 3.0)])
def test_known_slider_crank_tasks(thetas):
    task, c1 = known_task(thetas)
    report = burmester.design(task, driven="slider", top=100 if len(thetas) == 5 else 5,
                              min_separation=0.0 if len(thetas) == 5 else None)
    check(task, report)
    if len(thetas) == 5:  # every acceptable pair: the known one among them
        assert any(math.dist(d.driving_pivot, A0) < 1e-6 and math.dist(d.linkage.driven[0], c1) < 1e-6
                   for d in report)
    # Pickles to an equal report, designs and all.
    again = pickle.loads(pickle.dumps(report))
    assert again == report and again[0] == report[0]
    assert "slider-crank" in repr(report[0]) and "guide=" in repr(report[0])


def test_refusals_and_census():
    task, _ = known_task((0.3, 1.2, 2.0))
    with pytest.raises(InvalidInputError) as e:
        burmester.design(task, driven="crank")  # type: ignore[arg-type]
    assert e.value.cause == "unknown_name"
    with pytest.raises(InvalidInputError) as e:
        burmester.design(task, driven="slider", input="motor")
    assert e.value.cause == "driven_kind" and "motor" in str(e.value)
    five = Task([(1.049199280691, 2.279426358634, math.radians(45.220037141544)),
                 (0.734502065472, 3.198658887874, math.radians(26.633426990744)),
                 (-0.378159188147, 3.063048993013, math.radians(21.786789298262)),
                 (-1.268710439724, 2.051150142014, math.radians(27.048624103934)),
                 (-1.411118156972, 0.597429126400, math.radians(48.044287536536))])
    with pytest.raises(InvalidInputError) as e:
        burmester.design(five, driven="slider")
    assert e.value.cause == "no_slider_point"
    # Nothing fits: a census and near misses that are slider-cranks, pickled.
    report = burmester.design(task, driven="slider", limits=burmester.DesignLimits(min_transmission_deg=89.0))
    assert len(report) == 0 and report.main_rejection == "transmission"
    assert report.near_misses and all(m.driven_kind == "slider" for m in report.near_misses)
    assert pickle.loads(pickle.dumps(report)) == report


def test_press_from_the_command_line(tmp_path, capsys):
    """The press example in mm through the CLI: the table names the guide
    and the stroke, the JSON the guide's point and direction, -o draws."""
    from burmester import taskfile
    from burmester.cli import main

    press = EXAMPLES / "clamp.toml"
    spec = taskfile.load(press)
    assert spec.design_driven == "slider"
    assert main(["design", str(press)]) == 0
    text = capsys.readouterr().out
    assert "guide: C1" in text and "stroke" in text
    assert main(["design", str(press), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    best = doc["designs"][0]
    assert best["driven"] == "slider" and len(best["guide_direction"]) == 2 and best["violations"] == []
    # --driven overrides the file.
    assert main(["design", str(press), "--driven", "revolute", "--json"]) == 0
    assert "driven_center" in json.loads(capsys.readouterr().out)["designs"][0]
    pytest.importorskip("matplotlib")
    for name in ("press.png", "press.dxf"):
        out = tmp_path / name
        assert main(["design", str(press), "-o", str(out)]) == 0
        assert out.stat().st_size > 500
    capsys.readouterr()


def test_task_file_design_table():
    from burmester import taskfile

    spec = taskfile.load(EXAMPLES / "clamp.toml")
    again = taskfile.loads(taskfile.dumps(spec), spec.source)
    assert again == spec and again.design_driven == "slider"
    text = taskfile.dumps(spec).replace('driven = "slider"', 'driven = "prismatic"')
    with pytest.raises(taskfile.TaskFileError, match=r"design\.driven"):
        taskfile.loads(text)
    text = taskfile.dumps(spec).replace('driven = "slider"', 'drivn = "slider"')
    with pytest.raises(taskfile.TaskFileError, match=r"design\.drivn"):
        taskfile.loads(text)
