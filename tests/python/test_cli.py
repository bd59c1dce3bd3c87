"""The command line: good and bad input, exit codes, messages, outputs."""

import io
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import burmester
from burmester import Grid, cli, pivots, taskfile
from burmester.cli import main

EXAMPLE_FILE = Path(__file__).resolve().parents[2] / "examples" / "task.toml"


def run(*args, cwd=None):
    """``python -m burmester ARGS`` in a subprocess: (exit code, stdout, stderr)."""
    p = subprocess.run(
        [sys.executable, "-m", "burmester", *map(str, args)], capture_output=True, text=True, cwd=cwd
    )
    return p.returncode, p.stdout, p.stderr


def test_no_arguments_prints_help(capsys):
    assert main([]) == 0
    out = capsys.readouterr().out
    for cmd in ("map", "pivots", "linkage", "solve", "example"):
        assert cmd in out
    assert "Without arguments, burmester prints this help" in out


def test_example_command_writes_a_loadable_task(tmp_path, capsys):
    assert main(["example"]) == 0
    text = capsys.readouterr().out
    assert text == EXAMPLE_FILE.read_text()
    out = tmp_path / "t.toml"
    assert main(["example", "-o", str(out)]) == 0
    assert taskfile.load(out).view == taskfile.example().view
    assert main(["example", "-o", str(out)]) == 2  # never overwrites
    assert "exists" in capsys.readouterr().err


# ---------------------------------------------------------------------------
# solve


def test_solve_one_position_matches_norton(capsys):
    args = ["solve", "--ground", "100", "--crank", "40", "--coupler", "120", "--rocker", "80", "--theta2", "40"]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "crank-rocker" in out
    assert "theta3 =    20.298 deg, theta4 =    57.325 deg" in out
    assert "theta3 =   -60.978 deg, theta4 =   -98.005 deg" in out
    assert main(args + ["--mode", "crossed"]) == 0
    out = capsys.readouterr().out
    assert "-60.978" in out and "20.298" not in out


def test_solve_full_turn_table(capsys):
    assert main(["solve"]) == 0  # no lengths: Norton's example
    out = capsys.readouterr().out
    assert "Example 4-1" in out and "crank-rocker" in out
    assert main(["solve", "--ground", "4", "--crank", "1", "--coupler", "3", "--rocker", "3", "--step", "60"]) == 0
    rows = [ln for ln in capsys.readouterr().out.splitlines() if ln.strip().startswith("60.0 |")]
    assert "39.166" in rows[0] and "113.038" in rows[0] and "-66.962" in rows[0]


@pytest.mark.parametrize(
    "args, words",
    [
        (["--ground", "3", "--crank", "2", "--coupler", "1.5", "--rocker", "1", "--theta2", "180"],
         ["does not close at theta2 = 180 deg", "rocks within [-55.8, 55.8] deg"]),
        (["--ground", "3"], ["missing --crank, --coupler, --rocker"]),
        (["--ground", "0", "--crank", "2", "--coupler", "1.5", "--rocker", "1"], ["ground length", "greater than zero"]),
        (["--ground", "10", "--crank", "1", "--coupler", "1", "--rocker", "1"], ["can never be assembled"]),
        (["--theta2", "abc"], ["argument --theta2", "expected a number, got 'abc'"]),
        (["--theta2", "inf"], ["finite"]),
        (["--mode", "sideways"], ["argument --mode", "invalid choice"]),
        (["--step", "0"], ["--step must be from 0.01 to 360 degrees"]),
        (["--step", "1e-9"], ["--step must be from 0.01", "at most 36000 rows"]),
    ],
)
def test_solve_bad_input(args, words, capsys):
    assert main(["solve", *args]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    for w in words:
        assert w in err, (w, err)


def test_solve_help_says_degrees(capsys):
    assert main(["solve", "--help"]) == 0
    out = capsys.readouterr().out
    assert "DEGREES" in out and "--mode {open,crossed}" in out


# ---------------------------------------------------------------------------
# pivots


def test_pivots_table_and_json(capsys):
    assert main(["pivots", str(EXAMPLE_FILE), "--top", "3", "--rank-by", "transmission"]) == 0
    table = capsys.readouterr().out.splitlines()
    assert table[0].startswith(f"Driving pivots A0 for {EXAMPLE_FILE}")
    assert "minimum transmission angle over the travel" in table[0]
    assert set(table[2]) == {"-", "+"}  # the rule under the header
    assert [ln.split("|")[0].strip() for ln in table[3:6]] == ["1", "2", "3"]

    assert main(["pivots", "--top", "4", "--json", "--rank-by", "transmission"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["ranking"] == "transmission" and doc["spacing"] == pytest.approx(1.6)
    assert doc["limits"] == {"min_transmission_deg": 30.0, "max_link_ratio": 10.0, "input": "any",
                             "min_grashof_margin": 0.01, "max_size_ratio": None, "max_link_length": None,
                             "defaults": True}
    assert doc["units"] is None  # the example gives no unit
    listed = doc["pivots"]
    assert len(listed) == 4
    scores = [p["min_transmission_deg"] for p in listed]
    assert scores == sorted(scores, reverse=True)
    spec = taskfile.example()
    f = spec.filemon()
    smap = f.solution_map(spec.view)
    # The same pivots as the core's ranking, with the CLI's spacing.
    assert [p["center"] for p in listed] == [list(q.center) for q in smap.best_pivots(4, 1.6, "transmission")]
    for p in listed:
        center = tuple(p["center"])
        assert f.is_branch_free(center)
        # Each listed pivot is an acceptable sample of the solution-space map.
        j, i = p["index"]
        assert smap.point(j, i) == center and smap.acceptable[j, i]
        assert math.degrees(smap.min_transmission_rad[j, i]) == pytest.approx(p["min_transmission_deg"], abs=1e-4)
        assert p["violations"] == [] and p["direction"] in ("ccw", "cw") and p["ranked_by"] == "transmission"
        assert f.margin(center) == pytest.approx(p["margin"], rel=1e-4)
        sfb = f.four_bar(center)
        fb = sfb.fourbar
        assert [p["ground"], p["crank"], p["coupler"], p["rocker"]] == pytest.approx(list(fb.lengths))
        assert p["grashof"] == fb.grashof and p["input_full"] == fb.input_turns_fully
        mus = [math.degrees(fb.transmission_angle(t, m)) for t, m in zip(sfb.input_angles, sfb.modes)]
        assert p["transmission_deg"] == pytest.approx(mus)
        # The minimum over the travel is at most the angle at any pose.
        assert p["min_transmission_deg"] <= min(mus) + 1e-4
    # The pivots are apart, not neighbouring grid cells.
    pts = np.array([p["center"] for p in listed])
    d = np.hypot(*(pts[:, None, :] - pts[None, :, :]).transpose(2, 0, 1))
    assert d[np.triu_indices(4, 1)].min() >= 1.6 - 1e-9


def test_pivots_fall_back_to_the_margin_when_nothing_meets_the_limits(tmp_path, capsys):
    text = EXAMPLE_FILE.read_text()
    strict = text.replace("min_transmission_deg = 30.0", "min_transmission_deg = 89.9")
    assert strict != text
    path = tmp_path / "strict.toml"
    path.write_text(strict)
    assert main(["pivots", str(path), "--top", "2", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["ranking"] == "margin"
    assert doc["pivots"] and all(p["violations"] for p in doc["pivots"])
    assert all(p["ranked_by"] == "margin" for p in doc["pivots"])
    # One spacing for both rankings: the CLI's, passed to the core.
    spec = taskfile.load(path)
    smap = spec.filemon().solution_map(spec.view, limits=spec.limits)
    want = smap.best_pivots(2, pivots.default_spacing(spec.view), rank_by="margin")
    assert [p["center"] for p in doc["pivots"]] == [list(q.center) for q in want]
    assert main(["pivots", str(path), "--top", "2", "--spacing", "5", "--json"]) == 0
    wide = json.loads(capsys.readouterr().out)["pivots"]
    assert math.dist(wide[0]["center"], wide[1]["center"]) >= 5
    assert main(["pivots", str(path), "--top", "2"]) == 0
    assert "none meets the limits" in capsys.readouterr().out


def test_pivots_say_the_size_and_the_ranking(capsys):
    spec = taskfile.example()
    smap = spec.filemon().solution_map(spec.view)
    span = spec.task.span
    assert main(["pivots", "--top", "3", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["ranking"] == "balanced" and doc["span"] == span
    want = smap.best_pivots(3, 1.6)
    assert [p["center"] for p in doc["pivots"]] == [list(q.center) for q in want]
    for p, q in zip(doc["pivots"], want):
        assert p["ranked_by"] == "balanced" and p["score"] == q.score
        assert p["size"] == q.linkage.size and p["size_ratio"] == q.size_ratio
        assert p["size_ratio"] == pytest.approx(q.linkage.size / span)
    # The table names the ranking and the task's size, and lists each
    # linkage's size in task sizes.
    assert main(["pivots", "--top", "3"]) == 0
    table = capsys.readouterr().out.splitlines()
    assert "balanced score" in table[0] and f"task size {span:.3g}" in table[0]
    assert "size" in table[1].split("|")[2]
    sizes = [float(ln.split("|")[2].strip().rstrip("x")) for ln in table[3:6]]
    assert sizes == pytest.approx([q.size_ratio for q in want], abs=0.05)
    # The Pareto front, from compact to transmitting.
    assert main(["pivots", "--top", "4", "--rank-by", "pareto", "--json"]) == 0
    front = json.loads(capsys.readouterr().out)["pivots"]
    assert [p["ranked_by"] for p in front] == ["pareto"] * len(front) and len(front) >= 2
    assert [p["size_ratio"] for p in front] == sorted(p["size_ratio"] for p in front)
    assert [p["min_transmission_deg"] for p in front] == sorted(p["min_transmission_deg"] for p in front)
    assert main(["pivots", "--rank-by", "compact", "--top", "1"]) == 0
    assert "size relative to the task, smallest first" in capsys.readouterr().out
    assert main(["pivots", "--rank-by", "beauty"]) == 2
    assert "invalid choice" in capsys.readouterr().err


def test_pivots_rank_matches_the_margin_map():
    spec = taskfile.example()
    f = spec.filemon()
    v = spec.view
    mm = f.margin_map(v)
    smap = f.solution_map(v, min_transmission_deg=90)
    (best,), ranked_by = pivots.rank(smap, 1)
    assert ranked_by == "margin" and best.ranked_by == "margin"
    assert best.margin == pytest.approx(float(mm.max()), rel=1e-6)
    assert mm[best.index] == mm.max()


# ---------------------------------------------------------------------------
# map and linkage (need matplotlib)


def test_map_writes_the_center_plane(tmp_path):
    pytest.importorskip("matplotlib")
    from PIL import Image

    out = tmp_path / "map.png"
    code, stdout, stderr = run("map", "-o", out, "--grid", "120", "90", "--dpi", "50")
    assert code == 0, stderr
    m = taskfile.example().filemon().branch_map(-8, 8, -8, 8, 120, 90)
    assert f"{100 * m.mean():.1f}% of the 120 x 90 grid is branch-free" in stdout
    with Image.open(out) as im:
        assert im.format == "PNG" and 200 < im.width < 800


def test_map_design_overlay_reports_the_acceptable_share(tmp_path):
    pytest.importorskip("matplotlib")
    code, stdout, stderr = run("map", "--design", "--pivots", "2", "--grid", "60", "60", "-o", tmp_path / "d.png")
    assert code == 0, stderr
    smap = taskfile.example().filemon().solution_map(-8, 8, -8, 8, 60, 60)
    assert f"{100 * np.mean(smap.acceptable):.1f}% acceptable" in stdout


def test_map_of_a_task_file_with_pivots_and_the_circle_plane(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    out = tmp_path / "c.svg"
    assert main(["map", str(EXAMPLE_FILE), "--plane", "circle", "-o", str(out)]) == 0
    assert out.read_text().lstrip().startswith("<?xml")
    assert main(["map", "--pivots", "3", "--grid", "80", "80", "-o", str(tmp_path / "p.png")]) == 0
    assert "branch-free" in capsys.readouterr().out


def test_linkage_still_and_animated(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    from PIL import Image

    assert main(["linkage", "--pivot", "-7.98", "-5.18", "-o", str(tmp_path / "l.png")]) == 0
    assert "double-rocker, branch-free" in capsys.readouterr().out
    gif = tmp_path / "l.gif"
    assert main(["linkage", "--frames", "6", "-o", str(gif)]) == 0
    with Image.open(gif) as im:
        assert im.n_frames > 6
    assert main(["linkage", "--pivot", "0", "0", "-o", str(tmp_path / "d.gif")]) == 2
    assert "branch defect" in capsys.readouterr().err


def bad_task(tmp_path, old, new):
    text = EXAMPLE_FILE.read_text()
    assert old in text
    path = tmp_path / "bad.toml"
    path.write_text(text.replace(old, new, 1))
    return path


@pytest.mark.parametrize("command", ["map", "pivots"])
def test_bad_task_files_exit_2_with_one_line(tmp_path, command):
    cases = [
        (("angle_deg = 22.918311805232932", 'angle_deg = "x"'), "pose 2.angle_deg: expected a number"),
        (("center = [4.0, -1.0]", "centre = [4.0, -1.0]"), "driven.centre: unknown key"),
        (("grid = [400, 400]", "grid = [400]"), "view.grid: expected [nx, ny]"),
        (("max_link_ratio = 10.0", "max_link_ratio = -1"), "limits.max_link_ratio"),
        (("[[pose]]  # pose 3", "[[pose]  # pose 3"), "not valid TOML"),
    ]
    for (old, new), words in cases:
        path = bad_task(tmp_path, old, new)
        code, out, err = run(command, path, "-o" if command == "map" else "--top", tmp_path / "m.png" if command == "map" else "2")
        assert code == 2, (old, err)
        assert err.startswith(f"burmester {command}: error: {path}: ")
        assert words in err and len(err.strip().splitlines()) == 1 and "Traceback" not in err
        assert out == ""


def test_other_bad_input_exits_2(tmp_path):
    code, _, err = run("map", tmp_path / "none.toml")
    assert code == 2 and "none.toml: no such file" in err
    code, _, err = run("map", "--grid", "10", "x")
    assert code == 2 and "argument --grid" in err and len(err.strip().splitlines()) == 1
    code, _, err = run("frobnicate")
    assert code == 2 and "invalid choice" in err
    code, _, err = run("pivots", "--top", "0")
    assert code == 2 and "at least 1" in err


def test_bad_output_files_exit_2(tmp_path):
    pytest.importorskip("matplotlib")
    code, _, err = run("map", "-o", tmp_path / "no" / "dir" / "m.png", "--grid", "20", "20")
    assert code == 2 and "cannot write" in err and "Traceback" not in err
    code, _, err = run("map", "-o", tmp_path / "m.xyz", "--grid", "20", "20")
    assert code == 2 and "xyz" in err and "Traceback" not in err


def test_map_without_matplotlib_exits_1_and_says_what_to_install():
    code = (
        "import sys; sys.modules['matplotlib'] = None\n"
        "from burmester.cli import main\n"
        "sys.exit(main(['map', '-o', 'never.png']))\n"
    )
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert p.returncode == 1
    assert 'pip install "burmester[plot]"' in p.stderr and "Traceback" not in p.stderr


# ---------------------------------------------------------------------------
# The progress bar: the core's hook on one call


def test_progress_bar_gets_the_samples_of_one_call_bit_for_bit():
    """The CLI's progress bar follows one call through the core's hook, so a
    large grid's samples are those of a call without it (the old banded
    sweep moved sample coordinates in their last bits on a 3001-row view)."""
    f = taskfile.example().filemon()
    g = Grid(-8.0, 8.0, -8.0, 8.0, 1200, 3001)
    buf = io.StringIO()
    bar = cli.ProgressBar(buf, "burmester: branch map")
    seen = []

    def hook(done, total):
        seen.append((done, total))
        bar(done, total)

    with_bar = f.branch_map(g, progress=hook)
    whole = f.branch_map(g)
    assert np.array_equal(with_bar, whole)
    assert seen and seen[-1] == (3001, 3001) and all(t == 3001 for _, t in seen)
    assert [d for d, _ in seen] == sorted(d for d, _ in seen)
    last = buf.getvalue().split("\r")[-1]
    assert last.startswith("burmester: branch map: 100%|") and "3001/3001" in last and last.endswith("\n")
    mm = f.margin_map(g, progress=lambda d, t: None)
    assert np.array_equal(mm.view(np.uint32), f.margin_map(g).view(np.uint32))
    s1 = f.solution_map(Grid(-8.0, 8.0, -8.0, 8.0, 300, 301), progress=lambda d, t: None)
    assert s1 == f.solution_map(Grid(-8.0, 8.0, -8.0, 8.0, 300, 301))


def test_progress_bar_draws_in_place():
    """tqdm draws the bar in place (a carriage return before each redraw),
    with the rows done, the rate and the time left, and ends its line when
    all rows are done; later calls draw nothing."""
    buf = io.StringIO()
    bar = cli.ProgressBar(buf, "burmester: branch map", mininterval=0.0)
    for done in (0, 50, 50, 100):
        bar(done, 100)
    text = buf.getvalue()
    frames = text.split("\r")[1:]
    assert frames and text.endswith("\n") and text.count("\n") == 1
    half = [f for f in frames if " 50%|" in f]
    assert half and "50/100" in half[0] and "<" in half[0]  # elapsed<left (the ETA)
    assert frames[-1].startswith("burmester: branch map: 100%|") and "100/100" in frames[-1]
    bar(100, 100)
    assert buf.getvalue() == text
    # An interrupted sweep's bar is ended by close().
    buf2 = io.StringIO()
    bar2 = cli.ProgressBar(buf2, "x", mininterval=0.0)
    bar2(3, 10)
    bar2.close()
    assert buf2.getvalue().endswith("\n") and "3/10" in buf2.getvalue().split("\r")[-1]


def test_progress_only_for_large_grids_on_a_terminal(monkeypatch):
    small, big = Grid(0, 1, 0, 1, 100, 100), Grid(0, 1, 0, 1, 2000, 1000)
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True, raising=False)
    assert cli.progress_for(small, "x") is None
    assert isinstance(cli.progress_for(big, "x"), cli.ProgressBar)
    assert isinstance(cli.progress_for(Grid(0, 1, 0, 1, 400, 400), "x", 16), cli.ProgressBar)
    monkeypatch.setattr(sys.stderr, "isatty", lambda: False, raising=False)
    assert cli.progress_for(big, "x") is None


class _Counting:
    """A Filemon that counts the sweeps asked of it."""

    def __init__(self, inner):
        self._inner = inner
        self.calls = []

    def __getattr__(self, name):
        attr = getattr(self._inner, name)
        if name in ("branch_map", "margin_map", "solution_map"):
            def counted(*args, **kwargs):
                self.calls.append(name)
                return attr(*args, **kwargs)
            return counted
        return attr


@pytest.mark.parametrize("extra, calls", [
    ([], ["branch_map"]),
    (["--design"], ["solution_map"]),
    (["--design", "--pivots", "3"], ["solution_map"]),
    (["--pivots", "2"], ["solution_map"]),
    (["--design", "--method", "direct"], ["solution_map", "branch_map"]),
])
def test_map_computes_each_map_once(tmp_path, monkeypatch, capsys, extra, calls):
    pytest.importorskip("matplotlib")
    made = []
    original = taskfile.TaskSpec.filemon

    def filemon(self):
        made.append(_Counting(original(self)))
        return made[-1]

    monkeypatch.setattr(taskfile.TaskSpec, "filemon", filemon)
    assert main(["map", "--grid", "60", "50", "-o", str(tmp_path / "m.png"), *extra]) == 0
    assert len(made) == 1 and made[0].calls == calls
    f = original(taskfile.example())
    free = f.branch_map(Grid(-8, 8, -8, 8, 60, 50), method="direct" if "direct" in extra else "conic")
    assert f"{100 * free.mean():.1f}% of the 60 x 50 grid is branch-free" in capsys.readouterr().out


@pytest.mark.parametrize(
    "command, name, words",
    [
        ("map", "-", ["-o - (standard output) is not supported", ".png"]),
        ("map", "{tmp}", ["is a folder", "out.png"]),
        ("map", "{tmp}/noext", ["has no extension", ".png, .svg, .pdf"]),
        ("map", "{tmp}/map.txt", ["has '.txt'", ".png"]),
        ("map", "{tmp}/missing/map.png", ["does not exist"]),
        ("linkage", "{tmp}/l.bmp", ["has '.bmp'", ".gif, .mp4"]),
        ("example", "{tmp}/task.txt", ["has '.txt'", ".toml"]),
    ],
)
def test_output_names_are_checked_before_any_work(command, name, words, tmp_path, capsys):
    # -o NAME without an extension once wrote NAME.png and reported NAME;
    # -o - wrote "-.png" and -o /tmp wrote /tmp.png.
    before = sorted(tmp_path.iterdir())
    assert main([command, "-o", name.format(tmp=tmp_path)]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    for w in words:
        assert w in err, (w, err)
    assert sorted(tmp_path.iterdir()) == before  # nothing written


@pytest.mark.parametrize("command, name", [("map", "map.svg"), ("example", "task.toml")])
def test_no_command_replaces_a_file_without_force(command, name, tmp_path, capsys):
    out = tmp_path / name
    out.write_text("mine")
    args = [command, "-o", str(out)] + (["--grid", "20", "20"] if command == "map" else [])
    assert main(args) == 2
    err = capsys.readouterr().err
    assert "exists" in err and "--force" in err, err
    assert out.read_text() == "mine"
    assert main(args + ["--force"]) == 0
    assert out.read_text() != "mine" and out.stat().st_size > 0


@pytest.mark.parametrize(
    "args, words",
    [
        (["map", "--dpi", "100000"], ["--dpi", "from 10 to 2400"]),
        (["linkage", "--frames", "0"], ["--frames", "from 2 to 10000"]),
        (["linkage", "--fps", "0"], ["--fps", "from 1 to 240"]),
    ],
)
def test_work_parameters_are_bounded(args, words, capsys):
    assert main(args) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    for w in words:
        assert w in err, (w, err)


def test_a_map_too_large_for_memory_is_one_line_and_status_2(monkeypatch, tmp_path, capsys):
    # A grid of 20000 x 20000 asks for more memory than a small machine has:
    # one line and status 2, not a traceback. The allocation failure is the
    # core's MemoryError (tested in test_findings.py); here it is forced.
    import burmester.cli as cli

    def no_memory(*args, **kwargs):
        raise MemoryError
    monkeypatch.setattr(cli.commands, "_solution_map", no_memory)
    assert main(["map", "--design", "-o", str(tmp_path / "m.png")]) == 2
    err = capsys.readouterr().err
    assert err.strip().splitlines() == ["burmester map: error: not enough memory for this; use a coarser --grid"]


FOUR_TASK = """
[[pose]]
x = 1.049199280691
y = 2.279426358634
angle_deg = 45.220037141544
[[pose]]
x = 0.734502065472
y = 3.198658887874
angle_deg = 26.633426990744
[[pose]]
x = -0.378159188147
y = 3.063048993013
angle_deg = 21.786789298262
[[pose]]
x = -1.268710439724
y = 2.051150142014
angle_deg = 27.048624103934
"""
FIFTH_POSE = "[[pose]]\nx = -1.411118156972\ny = 0.597429126400\nangle_deg = 48.044287536536\n"


def test_map_of_four_and_five_poses(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    four = tmp_path / "four.toml"
    four.write_text(FOUR_TASK)
    assert main(["map", str(four), "-o", str(tmp_path / "four.png")]) == 0
    out = capsys.readouterr().out
    assert "center-point curve of" in out and "pieces in view" in out
    assert (tmp_path / "four.png").stat().st_size > 1000
    five = tmp_path / "five.toml"
    five.write_text(FOUR_TASK + FIFTH_POSE)
    assert main(["map", str(five), "-o", str(tmp_path / "five.png")]) == 0
    out = capsys.readouterr().out
    assert "Burmester points of" in out and ": 4: (0.000, 0.000), (4.000, 0.000)" in out
    # What needs Filemon's construction says so.
    assert main(["map", str(four), "--design", "-o", str(tmp_path / "x.png")]) == 2
    assert "--design is for three poses" in capsys.readouterr().err
    assert main(["pivots", str(four)]) == 2
    assert "has 4 poses" in capsys.readouterr().err
    # Five poses list the four-bars of their Burmester points (test_four_five).
    assert main(["pivots", str(five), "--top", "1"]) == 0
    assert "Four-bars of the 4 Burmester points" in capsys.readouterr().out


def test_four_pose_file_with_a_driven_dyad(tmp_path, capsys):
    """A four-pose task file may name a driven dyad on the curve: ``map``
    draws (and exports) the branch-free arcs of the driving dyads with it,
    as many as Task.branch_free_arcs gives; the file round-trips."""
    pytest.importorskip("matplotlib")
    b0 = (4.0, 0.0)  # the known rocker's fixed pivot: a Burmester point, on the curve
    four = tmp_path / "four.toml"
    four.write_text(FOUR_TASK + "[driven]\ncenter = [4.0, 0.0]\n")
    spec = taskfile.load(four)
    assert spec.driven_center == pytest.approx(b0)
    back = taskfile.loads(taskfile.dumps(spec))
    assert back.driven_center == pytest.approx(b0) and np.allclose(back.poses, spec.poses, atol=1e-12)
    task = spec.task
    c1 = task.circle_point(b0)
    by_circle = taskfile.loads(FOUR_TASK + f"[driven]\ncircle = [{c1[0]!r}, {c1[1]!r}]\n")
    assert by_circle.driven_center == pytest.approx(b0, abs=1e-9)
    with pytest.raises(taskfile.TaskFileError, match="driven.center.*not a center point of the four poses"):
        taskfile.loads(FOUR_TASK + "[driven]\ncenter = [5.0, 5.0]\n")
    with pytest.raises(taskfile.TaskFileError, match=r"\[driven\].*found 5 poses"):
        taskfile.loads(FOUR_TASK + FIFTH_POSE + "[driven]\ncenter = [4.0, 0.0]\n")
    for plane in ("center", "circle"):
        out = tmp_path / f"{plane}.png"
        assert main(["map", str(four), "--plane", plane, "-o", str(out)]) == 0
        text = capsys.readouterr().out
        arcs = task.branch_free_arcs(b0, *spec.view.extent, plane=plane)
        assert arcs and f"; {len(arcs)} arcs of driving dyads branch-free with the driven dyad at C0" in text
    pytest.importorskip("ezdxf")
    assert main(["map", str(four), "-o", str(tmp_path / "four.dxf")]) == 0
    assert "branch-free with the driven dyad" in capsys.readouterr().out
    import ezdxf
    layers = {e.dxf.layer for e in ezdxf.readfile(tmp_path / "four.dxf").modelspace()}
    assert {"BRANCH_FREE_ARCS", "DRIVEN_PIVOT"} <= layers
