"""Task files (TOML): what a good file gives, and what a bad one says."""

import math
from pathlib import Path

import numpy as np
import pytest

import burmester
from burmester import DesignLimits, Grid, taskfile
from burmester.taskfile import TaskFileError

EXAMPLE_FILE = Path(__file__).resolve().parents[2] / "examples" / "task.toml"

GOOD = """
[[pose]]
x = 0
y = 0.0
angle_deg = 0.0
[[pose]]
x = 2.0
y = 0.5
angle_deg = 22.918311805232932
[[pose]]
x = 3.0
y = 2.0
angle_deg = 63.02535746439056
[driven]
center = [4.0, -1.0]
[view]
x = [-8.0, 8.0]
y = [-6.0, 6.0]
grid = [200, 150]
[limits]
min_transmission_deg = 40
max_link_ratio = 6.5
require_crank = true
"""


def test_good_file():
    spec = taskfile.loads(GOOD, "good.toml")
    assert [p[:2] for p in spec.poses] == [(0.0, 0.0), (2.0, 0.5), (3.0, 2.0)]
    assert [p[2] for p in spec.poses] == pytest.approx([0.0, 0.4, 1.1], abs=1e-15)
    assert spec.driven_center == (4.0, -1.0)
    assert spec.view == Grid(-8.0, 8.0, -6.0, 6.0, 200, 150)
    assert spec.limits == DesignLimits(40.0, 6.5, "crank")
    assert spec.filemon().driven_circle == pytest.approx(
        burmester.Task([(0, 0, 0), (2, 0.5, 0.4), (3, 2, 1.1)]).circle_point((4.0, -1.0))
    )


def test_example_file_is_the_built_in_example():
    spec = taskfile.load(EXAMPLE_FILE)
    ex = taskfile.example()
    assert spec.view == ex.view and spec.limits == ex.limits
    assert spec.driven_center == ex.driven_center
    for p, q in zip(spec.poses, ex.poses):
        assert p == pytest.approx(q, abs=1e-15)
    assert taskfile.loads(taskfile.dumps(ex)).view == ex.view


def test_optional_sections_and_the_driven_circle_point():
    minimal = GOOD.split("[view]")[0]
    spec = taskfile.loads(minimal)
    assert spec.limits == DesignLimits()
    assert spec.limits.min_transmission_deg == 30.0
    v = spec.view  # a default square view around the poles and the pivots
    assert v.xmax - v.xmin == pytest.approx(v.ymax - v.ymin) and (v.nx, v.ny) == (400, 400)
    for p in [pole.point for pole in spec.task.poles] + [spec.driven_center]:
        assert v.xmin < p[0] < v.xmax and v.ymin < p[1] < v.ymax
    # The driven dyad by its circle point gives the same C0.
    c1 = spec.filemon().driven_circle
    by_circle = taskfile.loads(minimal.replace("center = [4.0, -1.0]", f"circle = [{c1[0]!r}, {c1[1]!r}]"))
    assert by_circle.driven_center == pytest.approx((4.0, -1.0), abs=1e-9)
    # A non-square view gets square grid cells.
    wide = taskfile.loads(minimal + "[view]\nx = [0.0, 20.0]\ny = [0.0, 5.0]\n")
    assert (wide.view.nx, wide.view.ny) == (400, 100)


def edit(old, new):
    assert old in GOOD
    return GOOD.replace(old, new, 1)


BAD = [
    # (file text, words the message must contain)
    ("x = [", ["not valid TOML"]),
    ("[driven]\ncenter = [0, 0]\n", ["[[pose]]", "missing", "three"]),
    (edit("[[pose]]\nx = 0\ny = 0.0\nangle_deg = 0.0\n", ""), ["3 to 5 poses", "found 2"]),
    ("[[pose]]\nx = 0\ny = 0\nangle_deg = 0\n" * 6, ["3 to 5 poses", "found 6"]),
    (GOOD.replace("[driven]", "[[pose]]\nx = 5.0\ny = 1.0\nangle_deg = 80.0\n[driven]"),
     ["driven.center", "not a center point of the four poses"]),
    (GOOD.replace("[driven]",
                  "[[pose]]\nx = 5.0\ny = 1.0\nangle_deg = 80.0\n[[pose]]\nx = 1.0\ny = 4.0\nangle_deg = 120.0\n"
                  "[driven]"),
     ["[driven]", "is for three or four poses (a driven dyad on the center-point curve), found 5 poses",
      "leave [driven] out"]),
    (GOOD.replace("[[pose]]", 'units = ""\n[[pose]]', 1), ["units", "empty name", "'' (a string)"]),
    (GOOD.replace("[[pose]]", "units = 4\n[[pose]]", 1), ["units", "unit name", "4 (an integer)"]),
    (GOOD.replace("[[pose]]", 'units = "m]m"\n[[pose]]', 1), ["units", "brackets"]),
    (GOOD.replace("[[pose]]", 'units = "%s"\n[[pose]]' % ("m" * 33), 1), ["units", "at most 32 characters"]),
    (GOOD.replace("[[pose]]", "[units]\nname = 'mm'\n[[pose]]", 1), ["[units]", 'expected units = "mm"']),
    (GOOD + 'units = "mm"\n', ["limits.units", "unknown key", "at the top of the file"]),
    (GOOD.replace("[[pose]]", 'unit = "mm"\n[[pose]]', 1), ["unit", "unknown top-level key", 'units = "mm"']),
    (edit("angle_deg = 22.918311805232932", 'angle_deg = "23"'),
     ["pose 2.angle_deg", "expected a number", "'23' (a string)"]),
    (edit("angle_deg = 22.918311805232932", "angle = 0.4"), ["pose 2.angle", "unknown key", "angle_deg"]),
    (edit("x = 3.0\n", ""), ["pose 3.x", "missing"]),
    (edit("y = 0.5", "y = true"), ["pose 2.y", "expected a number", "true (a boolean)"]),
    (edit("y = 0.5", "y = nan"), ["pose 2.y", "finite"]),
    (GOOD.replace("angle_deg = 22.918311805232932", "angle_deg = 0.0").replace(
        "angle_deg = 63.02535746439056", "angle_deg = 0.0"), ["[[pose]]", "pure translation"]),
    (edit("center = [4.0, -1.0]", "center = [4.0]"), ["driven.center", "expected a point [x, y]"]),
    (edit("center = [4.0, -1.0]", "center = [4.0, -1.0]\ncircle = [1.0, 1.0]"), ["[driven]", "exactly one", "both"]),
    (edit("center = [4.0, -1.0]", "center = [-0.23328871889672342, 5.183154875586894]"),
     ["driven.center", "cannot be used", "pole P12"]),
    (edit("x = [-8.0, 8.0]", "x = [8.0, -8.0]"), ["view.x", "min < max", "found [8, -8]"]),
    (edit("y = [-6.0, 6.0]\n", ""), ["view.y", "missing", "both"]),
    (edit("grid = [200, 150]", "grid = [200.5, 150]"), ["view.grid[0]", "whole number", "200.5 (a float)"]),
    (edit("grid = [200, 150]", "grid = [200, 1]"), ["view.grid[1]", "2 to 20000", "found 1"]),
    (edit("min_transmission_deg = 40", "min_transmission_deg = 120"),
     ["limits.min_transmission_deg", "expected 0 to 90 degrees", "found 120"]),
    (edit("min_transmission_deg = 40", "min_transmission_deg = -1"),
     ["limits.min_transmission_deg", "expected 0 to 90 degrees", "found -1"]),
    (edit("max_link_ratio = 6.5", "max_link_ratio = 0.5"), ["limits.max_link_ratio", "expected at least 1", "found 0.5"]),
    (edit("require_crank = true", 'input = "motor"'), ["limits.input", '"any", "crank" or "rocker"', "'motor' (a string)"]),
    (edit("require_crank = true", "require_crank = true\ninput = \"crank\""), ["[limits]", "found both"]),
    (edit("require_crank = true", 'require_crank = "yes"'),
     ["limits.require_crank", "true or false", "'yes' (a string)"]),
    (edit("require_crank = true", "min_transmission = 30"), ["limits.min_transmission", "unknown key"]),
    (edit("require_crank = true", "require_crank = true\nmin_grashof_margin = 1.5"),
     ["limits.min_grashof_margin", "expected 0 to 1", "found 1.5"]),
    (edit("require_crank = true", "require_crank = true\nmin_grashof_margin = -0.1"),
     ["limits.min_grashof_margin", "expected 0 to 1", "found -0.1"]),
    (edit("require_crank = true", 'require_crank = true\nmin_grashof_margin = "x"'),
     ["limits.min_grashof_margin", "expected a number"]),
    (GOOD + "\n[poses]\nx = 1\n", ["poses", "unknown top-level key", "[[pose]]"]),
]


@pytest.mark.parametrize("text, words", BAD)
def test_bad_files_say_which_key_what_was_expected_and_found(text, words):
    with pytest.raises(TaskFileError) as info:
        taskfile.loads(text, "bad.toml")
    msg = str(info.value)
    assert msg.startswith("bad.toml: ") and "\n" not in msg
    for w in words:
        assert w in msg, (w, msg)


def test_unreadable_files(tmp_path):
    with pytest.raises(TaskFileError, match="no such file"):
        taskfile.load(tmp_path / "missing.toml")
    (tmp_path / "latin1.toml").write_bytes(b"# caf\xe9\n")
    with pytest.raises(TaskFileError, match="cannot read"):
        taskfile.load(tmp_path / "latin1.toml")


def test_limits_input_and_the_older_require_crank():
    for text, want in [
        (GOOD, "crank"),
        (edit("require_crank = true", "require_crank = false"), "any"),
        (edit("require_crank = true", 'input = "rocker"'), "rocker"),
        (edit("require_crank = true", 'input = "crank"'), "crank"),
        (edit("require_crank = true", 'input = "any"'), "any"),
    ]:
        assert taskfile.loads(text).limits == DesignLimits(40.0, 6.5, want)
    # What dumps writes loads back to the same limits (the input by name).
    spec = taskfile.loads(edit("require_crank = true", 'input = "rocker"'))
    text = taskfile.dumps(spec)
    assert 'input = "rocker"' in text and "require_crank" not in text
    again = taskfile.loads(text)
    assert again.limits == spec.limits and again.view == spec.view


def test_grid_for_picks_square_cells():
    assert taskfile.grid_for(0.0, 20.0, 0.0, 5.0) == Grid(0.0, 20.0, 0.0, 5.0, 400, 100)
    assert taskfile.grid_for(0.0, 1.0, 0.0, 3.0, 300) == Grid(0.0, 1.0, 0.0, 3.0, 100, 300)
    assert taskfile.grid_for(0.0, 1000.0, 0.0, 1.0, 10).shape == (2, 10)
    with pytest.raises(burmester.InvalidInputError) as e:
        taskfile.grid_for(1.0, 0.0, 0.0, 1.0)
    assert e.value.cause == "viewport"


def test_view_cell_centers_match_branch_map():
    spec = taskfile.loads(GOOD)
    f = spec.filemon()
    v = spec.view
    xs, ys = v.cell_centers()
    m = f.branch_map(v)
    for j in range(0, v.ny, 37):
        for i in range(0, v.nx, 41):
            assert m[j, i] == f.is_branch_free((xs[i], ys[j]))
    assert math.isclose(xs[0], -8.0 + 16.0 / 400)


FOUR_POSES = GOOD.split("[driven]")[0] + "[[pose]]\nx = 5.0\ny = 1.0\nangle_deg = 80.0\n"


def test_four_and_five_pose_files():
    spec = taskfile.loads(FOUR_POSES, "four.toml")
    assert len(spec.poses) == 4 and spec.driven_center is None
    assert spec.poses[3] == pytest.approx((5.0, 1.0, math.radians(80.0)))
    # The default view holds the poses and the nearby poles.
    v = spec.view
    for p in spec.poses:
        assert v.xmin < p[0] < v.xmax and v.ymin < p[1] < v.ymax
    assert v.xmax - v.xmin == pytest.approx(v.ymax - v.ymin)
    # A given view is kept; the text round-trips without [driven] and [limits].
    spec = taskfile.loads(FOUR_POSES + "[view]\nx = [-5.0, 5.0]\ny = [-4.0, 4.0]\n")
    assert spec.view.extent == (-5.0, 5.0, -4.0, 4.0)
    text = taskfile.dumps(spec)
    assert "[driven]" not in text and "[limits]" not in text
    back = taskfile.loads(text)
    assert np.allclose(back.poses, spec.poses, rtol=0, atol=1e-12) and back.view == spec.view
    # Filemon's construction needs three poses: a clear error.
    with pytest.raises(TaskFileError, match="has 4 poses"):
        spec.filemon()
    five = taskfile.loads(FOUR_POSES + "[[pose]]\nx = 1.0\ny = 4.0\nangle_deg = 120.0\n")
    assert len(five.poses) == 5 and five.task.burmester_points() is not None


def test_the_five_pose_example_file():
    spec = taskfile.load(EXAMPLE_FILE.parent / "five.toml")
    assert len(spec.poses) == 5 and spec.driven_center is None
    assert len(spec.task.burmester_points()) == 4


@pytest.mark.parametrize("field", ["max_link_ratio", "max_size_ratio", "max_link_length"])
def test_limits_without_a_bound_round_trip(field):
    """A limit the core takes as infinite (no bound) is written as TOML's
    ``inf`` (or left out where that is its default) and read back equal;
    the JSON of the limits says None (JSON has no infinity)."""
    import dataclasses
    import json

    from burmester import pivots

    base = DesignLimits(max_link_ratio=8.0, max_size_ratio=5.0, max_link_length=40.0)
    lim = DesignLimits(**{**{k: getattr(base, k) for k in ("max_link_ratio", "max_size_ratio", "max_link_length")},
                          field: math.inf})
    spec = dataclasses.replace(taskfile.example(), limits=lim)
    back = taskfile.loads(taskfile.dumps(spec))
    assert back.limits == lim
    doc = json.loads(json.dumps(pivots.limits_dict(lim), allow_nan=False))
    assert doc[field] is None
    with pytest.raises(TaskFileError, match=r"finite number \(or inf: no limit\), found -inf"):
        taskfile.loads(taskfile.dumps(spec).replace(f"{field} = inf", f"{field} = -inf")
                       if field == "max_link_ratio" else
                       taskfile.dumps(spec).replace("[limits]", f"[limits]\n{field} = -inf"))
    with pytest.raises(TaskFileError, match="expected a finite number, found inf"):
        taskfile.loads(taskfile.dumps(spec).replace("min_transmission_deg = 30.0", "min_transmission_deg = inf"))
