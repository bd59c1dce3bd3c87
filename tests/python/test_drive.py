"""A motor for a linkage whose input swings (the Watt II six-bar) from
Python: SixBar, the drive map, Drive records, best_drive, the pictures, the
export and ``burmester drive``. The kinematics are checked independently in
``tests/rust/drive.rs``; here the API: shapes, pickling, errors, Ctrl-C,
and that what the records say is what the six-bar does."""

import json
import math
import pickle
import signal
import sys
import textwrap

import numpy as np
import pytest

import burmester
from burmester import Grid
from burmester.cli import main
from conftest import C0, POSES, VP, interrupt_child


@pytest.fixture(scope="module")
def rocker():
    """The example's best linkage by transmission: a triple-rocker."""
    f = burmester.Task(POSES).filemon(C0)
    smap = f.solution_map(Grid(*VP, 400, 400), min_transmission_deg=30)
    sfb = smap.best_pivots(1, rank_by="transmission")[0].linkage
    assert sfb.fourbar.grashof == "triple-rocker" and not sfb.figures.input_full
    return sfb


@pytest.fixture(scope="module")
def dmap(rocker):
    a0, a1 = rocker.driving
    h = 4.0 * math.dist(a0, a1)
    return rocker.drive_map(a0[0] - h, a0[0] + h, a0[1] - h, a0[1] + h, 160, 160)


def test_drive_map_columns_are_readonly_numpy(dmap):
    assert dmap.columns == ["valid", "min_transmission_rad", "drive_transmission_rad", "time_ratio",
                            "link_ratio", "size_ratio", "acceptable"]
    for name in dmap.columns:
        col = getattr(dmap, name)
        assert col.shape == (160, 160) == dmap.shape and not col.flags.writeable
    assert dmap.valid.any() and (~dmap.valid).any()
    assert np.all(dmap.acceptable <= dmap.valid)
    v = dmap.valid
    assert np.all(dmap.time_ratio[v] >= 1.0) and np.all(np.isnan(dmap.time_ratio[~v]))
    assert np.all(dmap.min_transmission_rad[v] <= dmap.drive_transmission_rad[v])
    assert np.all(np.degrees(dmap.min_transmission_rad[v]) <= dmap.motion_transmission_deg + 1e-3)
    assert dmap.attachment == dmap.linkage.driving[1]


def test_best_drives_reach_the_poses_in_order(dmap):
    task = dmap.linkage.task if hasattr(dmap.linkage, "task") else burmester.Task(POSES)
    drives = dmap.best_drives(3)
    assert drives and all(d.acceptable for d in drives)
    scores = [d.score for d in drives]
    assert scores == sorted(scores, reverse=True)
    for d in drives:
        six = d.sixbar
        assert six.crank_turns_fully and six.drive_grashof == "crank-rocker"
        assert d.min_transmission_deg >= 30 - 1e-9
        j, i = d.index
        assert dmap.point(j, i) == d.drive_pivot
        assert abs(math.radians(d.min_transmission_deg) - float(dmap.min_transmission_rad[j, i])) < 1e-6
        for phi, pose in zip(d.pose_crank_angles, task.poses):
            x, y, a = d.pose_at(phi)
            assert math.dist((x, y), pose[:2]) < 1e-9 * task.span
            assert abs(math.remainder(a - pose[2], 2 * math.pi)) < 1e-9
        steps = np.diff(d.pose_crank_angles) * (1 if d.direction == "ccw" else -1)
        assert np.all(steps > 0)
        # The figures are the six-bar's own.
        assert abs(six.time_ratio - d.time_ratio) < 1e-9
        assert max(abs(a - b) for a, b in zip(six.min_transmission_deg,
                                                 (d.drive_transmission_deg, d.motion_transmission_deg))) < 1e-9
        # Dense stepping of the six-bar's position analysis finds no smaller angle.
        dense = np.array([six.transmission_angles(t) for t in d.turn_angles(3600)])
        assert math.degrees(dense.min()) >= d.min_transmission_deg - 1e-6


def test_pickles_to_equal_objects(dmap):
    d = dmap.best_drives(1)[0]
    for obj in (dmap, d, d.sixbar):
        again = pickle.loads(pickle.dumps(obj))
        assert again == obj
    assert pickle.loads(pickle.dumps(dmap)).best_drives(1)[0] == d


def test_classic_drive_has_time_ratio_one(rocker, dmap):
    for beyond_first in (True, False):
        d = rocker.classic_drive(beyond_first=beyond_first, drive_transmission_deg=45)
        assert abs(d.time_ratio - 1.0) < 1e-9 and abs(d.drive_transmission_deg - 45) < 1e-9
        assert abs(d.stroke - math.pi) < 1e-9
        again = dmap.classic_drive(beyond_first, 45)
        assert again.drive_pivot == d.drive_pivot
    g, r, c, rho = burmester.unit_time_ratio_crank_rocker(2.0, 45.0, 40.0)
    assert abs(r - 2.0 * math.sin(math.radians(22.5))) < 1e-15 and rho == 2.0
    with pytest.raises(burmester.InvalidInputError):
        burmester.unit_time_ratio_crank_rocker(1.0, 45.0, 70.0)  # beyond 90 - 45/2


def test_best_drive_and_why_none(rocker):
    d = rocker.best_drive(min_transmission_deg=30)
    assert d.acceptable and d.sixbar.crank_turns_fully and d.ranked_by == "balanced"
    with pytest.raises(burmester.DriveError) as e:
        rocker.best_drive(min_transmission_deg=89)
    assert e.value.cause == "no_acceptable_drive" and e.value.valid > 0
    assert e.value.best_transmission_deg < 89 and "relax the limits" in str(e.value)
    assert isinstance(e.value, ValueError)
    with pytest.raises(burmester.DriveError) as e:
        rocker.drive_map(-1, 1, -1, 1, 4, 4, swing_margin_deg=80)
    assert e.value.cause in ("travel_too_large", "outside_input_range")
    found = rocker.drive_search(ratios=[1.0, 2.0], angles_deg=[0, 90], samples=48)
    assert [x.score for x in found] == sorted((x.score for x in found), reverse=True)


def test_bad_input_is_typed(rocker, dmap):
    a0 = rocker.driving[0]
    with pytest.raises(burmester.DegenerateError):
        rocker.drive_map(-1, 1, -1, 1, 4, 4, attachment=a0)
    with pytest.raises(burmester.InvalidInputError):
        rocker.drive_map(-1, 1, -1, 1, 4, 4, swing_margin_deg=-1)
    with pytest.raises(burmester.InvalidInputError):
        rocker.drive_map(-1, 1, -1, 1, 4, 4, max_time_ratio=0.5)
    with pytest.raises(burmester.InvalidInputError):
        rocker.drive_map(-1, 1, -1, 1, 4, 4, attachment=(math.nan, 0.0))
    with pytest.raises(TypeError):
        rocker.drive_map(-1, 1, -1, 1, 4, 4, 5)
    with pytest.raises(burmester.DriveError) as e:
        rocker.drive(a0)  # D0 on A0: no crank-rocker
    assert e.value.cause == "not_a_crank_rocker"
    with pytest.raises(burmester.InvalidInputError):
        dmap.best_drives(2, min_separation=-1.0)
    with pytest.raises(burmester.InvalidInputError):
        rocker.drive_search(samples=1025)
    with pytest.raises(TypeError):
        burmester.SixBar((0, 0), (1, 0), (1, 1), (0, 0), (1, 1), (2, 1), (3, 0))


def test_sixbar_from_joints(dmap):
    d = dmap.best_drives(1)[0]
    phi = d.pose_crank_angles[1] + 0.3
    joints = d.sixbar.joints(phi)
    six = burmester.SixBar(**dict(zip(("d0", "d", "e", "a0", "a", "c", "c0", "p"), joints)))
    assert six.crank_turns_fully and six.drive_grashof == "crank-rocker"
    assert six.dead_positions == [] and abs(six.time_ratio - d.time_ratio) < 1e-9
    for t in np.linspace(0, 2 * math.pi, 13):
        assert math.dist(six.pose_at(t)[:2], d.sixbar.pose_at(t)[:2]) < 1e-9 * d.task.span
    for got, want in zip(six.joints(phi), joints):
        assert math.dist(got, want) < 1e-9 * d.task.span
    xs, ys, ok = six.coupler_path(np.linspace(0, 2 * math.pi, 50))
    assert ok.all() and xs.shape == (50,)
    assert pickle.loads(pickle.dumps(six)) == six
    # Joints of a six-bar whose drive swings the input past its dead positions.
    odd = burmester.SixBar(d0=(-1.0, 3.0), d=(-0.6, 3.0), e=(1.53, 1.29), a0=(0.0, 0.0), a=(1.53, 1.29),
                           c=(2.6, 0.9), c0=(3.0, 0.0), p=(2.0, 1.5))
    assert not odd.crank_turns_fully and odd.min_transmission_deg is None
    assert odd.dead_positions
    with pytest.raises(burmester.AssemblyError):
        for t in np.linspace(0, 2 * math.pi, 721):
            odd.solve(t)
    with pytest.raises(burmester.DegenerateError):
        burmester.SixBar(d0=(0, 0), d=(0, 0), e=(1, 1), a0=(0, 1), a=(1, 1), c=(2, 1), c0=(3, 0))


def test_progress_and_the_largest_search(rocker):
    calls = []
    a0 = rocker.driving[0]
    m = rocker.drive_map(a0[0] - 5, a0[0] + 5, a0[1] - 5, a0[1] + 5, 700, 300,
                         progress=lambda d, t: calls.append((d, t)))
    assert calls[-1] == (300, 300)
    assert m == rocker.drive_map(a0[0] - 5, a0[0] + 5, a0[1] - 5, a0[1] + 5, 700, 300)
    # The documented maximum of a search side, on one attachment.
    found = rocker.drive_search(ratios=[1.0], angles_deg=[0.0], samples=1024, min_transmission_deg=0)
    assert len(found) == 1


CHILD = textwrap.dedent(
    """
    import json, math, time
    import burmester
    f = burmester.Task({poses!r}).filemon({c0!r})
    smap = f.solution_map(burmester.Grid(*{vp!r}, 400, 400), min_transmission_deg=30)
    sfb = smap.best_pivots(1, rank_by="transmission")[0].linkage
    a0 = sfb.driving[0]
    wall = [(a0[0] + 0.5, a0[1] - 9.0), (a0[0] + 0.8, a0[1] - 9.0), (a0[0] + 0.8, a0[1] + 9.0),
            (a0[0] + 0.5, a0[1] + 9.0)]
    print("started", flush=True)
    t0 = time.monotonic()
    try:
        sfb.drive_map(a0[0] - 9, a0[0] + 9, a0[1] - 9, a0[1] + 9, 1500, 1500, min_transmission_deg=0,
                      max_link_ratio=math.inf, obstacles=[wall], link_width=0.05, travel_samples=128)
    except KeyboardInterrupt as e:
        print(json.dumps({{"message": str(e), "ran": time.monotonic() - t0}}), flush=True)
        raise
    print(json.dumps({{"finished": time.monotonic() - t0}}), flush=True)
    """
).format(poses=POSES, c0=C0, vp=VP)


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
def test_ctrl_c_stops_a_drive_map():
    report, latency, returncode, err = interrupt_child(CHILD, after=0.5)
    assert "finished" not in report, "the map ended before the signal; make it longer"
    assert latency < 0.5, latency
    assert returncode == -signal.SIGINT and "KeyboardInterrupt" in err
    assert "interrupted after" in report["message"]


def test_pictures_and_export(tmp_path, dmap):
    pytest.importorskip("matplotlib")
    ezdxf = pytest.importorskip("ezdxf")
    import burmester.export as export
    import burmester.plot as bp

    d = dmap.best_drives(1)[0]
    for obj in (d, d.sixbar, dmap):
        png = obj._repr_png_()
        assert png is not None and png[:8] == b"\x89PNG\r\n\x1a\n"
    ax = bp.drive_map(dmap)
    gids = {a.get_gid() for a in ax.get_children()}
    assert {"drive-map", "attachment-swing", "drives"} <= gids
    ax = bp.sixbar(d)
    gids = {a.get_gid() for a in ax.get_children()}
    assert {"crank-circle", "coupler-path", "drive-1", "linkage-3", "pose-2"} <= gids
    gif = tmp_path / "six.gif"
    bp.animate_sixbar(d, gif, frames=8, fps=4, dpi=30)
    assert gif.read_bytes()[:6] in (b"GIF89a", b"GIF87a")
    assert [p.name for p in tmp_path.iterdir()] == ["six.gif"]  # nothing left beside it
    dxf = export.sixbar(d, tmp_path / "six.dxf", turn_samples=6)
    layers = {layer.dxf.name for layer in ezdxf.readfile(dxf).layers}
    assert {"GROUND", "PIVOTS", "CRANK_CIRCLE", "DRIVE_1", "LINKAGE_3", "COUPLER_PATH", "ATTACHMENT_ARC",
            "TURN", "POSES", "TEXT"} <= layers
    svg = export.sixbar_svg(d, tmp_path / "six.svg")
    text = svg.read_text()
    assert 'id="DRIVE_2"' in text and 'id="ATTACHMENT_ARC"' in text
    with pytest.raises(burmester.InvalidInputError):
        export.sixbar(d, tmp_path / "six.png")
    with pytest.raises(burmester.InvalidInputError):
        export.sixbar(d, tmp_path / "big.svg", turn_samples=export.MAX_SAMPLES + 1)
    with pytest.raises(burmester.InvalidInputError):
        bp.animate_sixbar(d, tmp_path / "x.gif", frames=bp.MAX_FRAMES + 1)
    with pytest.raises(burmester.InvalidInputError):
        bp.animate_sixbar(d, tmp_path / "none" / "six.gif")


def test_the_sixbar_picture_has_units_and_link_lengths(dmap):
    """The six-bar picture labels its axes with the unit and its moving
    links with their lengths (issue 22: every picture in the task's units),
    the lengths read back equal to the core's joints at the first pose."""
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    import burmester.plot as bp

    d = dmap.best_drives(1)[0]
    ax = bp.sixbar(d, units="mm")
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("x [mm]", "y [mm]")
    labels = {t.get_text().rsplit(" ", 2)[0]: float(t.get_text().split()[-2])
              for t in ax.texts if t.get_gid() == "link-length"}
    d0, dd, e, a0, a, c, c0, _ = d.sixbar.joints(d.pose_crank_angles[0])
    want = {"crank": math.dist(d0, dd), "drive coupler": math.dist(dd, e), "input": math.dist(a0, a),
            "coupler": math.dist(a, c), "rocker": math.dist(c, c0)}
    assert labels.keys() == want.keys()
    for name, v in want.items():
        assert math.isclose(labels[name], v, rel_tol=2e-3), (name, labels[name], v)
    ax = bp.sixbar(d.sixbar, labels=False)
    assert ax.get_xlabel() == "" and not [t for t in ax.texts if t.get_gid() == "link-length"]
    plt.close("all")


def test_cli_drive(tmp_path, capsys):
    assert main(["drive", "--rank-by", "transmission", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["linkage"]["grashof"] == "triple-rocker"
    drv = doc["drive"]
    assert drv["acceptable"] and drv["drive_grashof"] == "crank-rocker" and drv["time_ratio"] >= 1
    assert len(drv["pose_crank_angles_deg"]) == 3
    assert main(["drive", "--rank-by", "transmission"]) == 0
    out = capsys.readouterr().out
    assert "Motor drive" in out and "time ratio" in out
    pytest.importorskip("matplotlib")
    pytest.importorskip("ezdxf")
    for name in ("six.png", "six.dxf", "six.svg"):
        assert main(["drive", "--rank-by", "transmission", "-o", str(tmp_path / name)]) == 0
        assert (tmp_path / name).exists()
    assert main(["drive", "--rank-by", "transmission", "--frames", "6", "-o", str(tmp_path / "a.gif")]) == 0
    assert main(["drive", "--rank-by", "transmission", "--map", "-o", str(tmp_path / "map.png")]) == 0
    capsys.readouterr()
    # Never overwrites; bad options; no acceptable drive: status 2 and one line.
    assert main(["drive", "-o", str(tmp_path / "six.png")]) == 2
    assert main(["drive", "--margin", "-3"]) == 2
    assert main(["drive", "--map", "-o", str(tmp_path / "m.dxf")]) == 2
    err = capsys.readouterr().err
    assert err.count("error:") == 3
