"""``burmester pairs`` and ``burmester linkage`` for a task of four poses
(the pair map), through ``burmester.cli.main`` as a user runs them."""

import json
import math

import pytest

from burmester import Task
from burmester.cli import main

# Four poses of the notes' worked example (positions-4-5.md, section 6): the
# coupler of the crank-rocker A0 = (0, 0), B0 = (4, 0).
POSES = [
    (1.049199280691, 2.279426358634, 45.220037141544),
    (0.734502065472, 3.198658887874, 26.633426990744),
    (-0.378159188147, 3.063048993013, 21.786789298262),
    (-1.268710439724, 2.051150142014, 27.048624103934),
]
FOUR_TASK = "".join(f"[[pose]]\nx = {x!r}\ny = {y!r}\nangle_deg = {a!r}\n" for x, y, a in POSES)


@pytest.fixture
def four(tmp_path):
    p = tmp_path / "four.toml"
    p.write_text(FOUR_TASK)
    return p


def test_pairs_json_is_the_pair_map_best_pairs(four, capsys):
    assert main(["pairs", str(four), "--json", "--samples", "120", "--top", "3", "--rank-by", "transmission"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["samples"] == [120, 120] and len(doc["pairs"]) == 3
    task = Task([(x, y, math.radians(a)) for x, y, a in POSES])
    want = task.pair_map(120).best_pairs(3, rank_by="transmission")
    for rec, p in zip(doc["pairs"], want):
        assert rec["index"] == list(p.index) and rec["ranked_by"] == "transmission"
        assert rec["driving"]["center"] == list(p.driving.center)
        assert rec["driven"]["center"] == list(p.driven.center)
        assert rec["min_transmission_deg"] == p.figures.min_transmission_deg
        assert rec["direction"] in ("ccw", "cw")
    mus = [r["min_transmission_deg"] for r in doc["pairs"]]
    assert mus == sorted(mus, reverse=True) and mus[0] >= 30.0


def test_pairs_table_and_picture(four, tmp_path, capsys):
    pytest.importorskip("matplotlib")
    out = tmp_path / "pairs.png"
    assert main(["pairs", str(four), "--samples", "150", "-o", str(out)]) == 0
    text = capsys.readouterr().out
    assert "Pairs of dyads for" in text and "crank-rocker" in text
    assert f"wrote {out}: pair map of" in text and "150 x 150 pairs" in text
    assert out.stat().st_size > 1000
    # An existing picture is kept without --force.
    assert main(["pairs", str(four), "--samples", "20", "-o", str(out)]) == 2
    assert "--force" in capsys.readouterr().err


def test_the_pair_map_picture_has_its_parts(four):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import burmester.plot as plot

    task = Task([(x, y, math.radians(a)) for x, y, a in POSES])
    pmap = task.pair_map(120)
    ax = plot.pair_map(pmap, pairs=3)
    gids = {a.get_gid() for a in ax.get_children()} | {c.get_gid() for c in ax.collections}
    assert {"pair-map", "branches", "pairs"} <= gids
    img = next(a for a in ax.get_children() if a.get_gid() == "pair-map")
    cat = img.get_array()
    assert cat.shape == pmap.shape
    assert ((cat == 3) == pmap.acceptable).all() and ((cat >= 2) == pmap.branch_free).all()


def test_linkage_of_four_poses_draws_the_best_pair(four, tmp_path, capsys):
    pytest.importorskip("matplotlib")
    out = tmp_path / "l.png"
    assert main(["linkage", str(four), "-o", str(out)]) == 0
    assert "branch-free" in capsys.readouterr().out and out.stat().st_size > 1000
    assert main(["linkage", str(four), "--pivot", "0", "0", "-o", str(tmp_path / "m.png")]) == 2
    assert "--pivot is for three poses" in capsys.readouterr().err


def test_pairs_refuses_other_pose_counts(tmp_path, capsys):
    five = tmp_path / "five.toml"
    five.write_text(FOUR_TASK + "[[pose]]\nx = -1.411118156972\ny = 0.5974291264\nangle_deg = 48.044287536536\n")
    assert main(["pairs", str(five)]) == 2
    err = capsys.readouterr().err
    assert "pairs is for four poses" in err and "has 5 poses" in err
    four = tmp_path / "four.toml"
    four.write_text(FOUR_TASK)
    assert main(["pairs", str(four), "--samples", "1"]) == 2
    assert "--samples must be from 2 to 20000" in capsys.readouterr().err


def test_a_four_pose_task_file_carries_limits(tmp_path, capsys):
    from burmester import DesignLimits, taskfile

    text = FOUR_TASK + '[limits]\nmin_transmission_deg = 50.0\nmax_link_ratio = 6.0\ninput = "crank"\n'
    spec = taskfile.loads(text, "four.toml")
    assert spec.limits == DesignLimits(50.0, 6.0, "crank")
    assert taskfile.loads(taskfile.dumps(spec)).limits == spec.limits
    four = tmp_path / "four.toml"
    four.write_text(text)
    assert main(["pairs", str(four), "--json", "--samples", "150", "--top", "5"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["pairs"]
    for rec in doc["pairs"]:
        assert rec["min_transmission_deg"] >= 50.0 and rec["link_ratio"] <= 6.0
        assert rec["grashof"] in ("crank-rocker", "double-crank")
