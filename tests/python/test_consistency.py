"""API consistency of the 0.2.0 turn: every grid-taking method takes a
``Grid``, its six numbers as one tuple (as ``pivot_atlas`` does) or the six
numbers one by one, with the same result; ``TaskSpec.task`` is a property;
the task file writer keeps its comments and round-trips; the extras; the
command line's tables."""

import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest

import burmester
from burmester import Grid, Task, cli, taskfile

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[2]
POSES = [(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)]
SIX = (-8.0, 8.0, -8.0, 8.0, 48, 40)


def test_every_grid_taking_method_takes_a_grid_a_tuple_or_six_numbers():
    task = Task(POSES)
    f = task.filemon((4.0, -1.0))
    grid = Grid(*SIX)
    for name, call in [
        ("branch_map", lambda g: f.branch_map(*g)),
        ("margin_map", lambda g: f.margin_map(*g)),
        ("solution_map", lambda g: f.solution_map(*g, min_transmission_deg=35)),
        ("driven_solution_map", lambda g: task.driven_solution_map((-7.98, -5.18), *g)),
    ]:
        by_grid, by_tuple, by_list, by_numbers = call((grid,)), call((SIX,)), call((list(SIX),)), call(SIX)
        if isinstance(by_grid, np.ndarray):
            for other in (by_tuple, by_list, by_numbers):
                assert np.array_equal(by_grid.view(np.uint8), other.view(np.uint8)), name
        else:
            assert by_grid == by_tuple == by_list == by_numbers, name
            assert by_tuple.grid == grid
    # The method may follow the tuple, as it follows the six numbers.
    assert np.array_equal(f.branch_map(SIX, "direct"), f.branch_map(*SIX, method="direct"))
    # The same as pivot_atlas's tuples.
    atlas = burmester.pivot_atlas(task, (-8, 8, -8, 8, 6, 6), SIX)
    assert atlas.driving == grid
    # A tuple of another length is a TypeError naming both forms; a bad number is the core's error.
    with pytest.raises(TypeError, match=r"six numbers .* \(as a tuple or one by one\)"):
        f.solution_map((-8, 8, -8, 8, 48))
    with pytest.raises(TypeError, match="as a tuple or one by one"):
        f.branch_map("grid")
    with pytest.raises(burmester.InvalidInputError, match="ymax must be a finite number"):
        f.branch_map((-8, 8, -8, math.nan, 48, 40))
    with pytest.raises(burmester.InvalidInputError):
        f.margin_map((8, -8, -8, 8, 48, 40))
    with pytest.raises(TypeError):
        f.solution_map(SIX, SIX)


def test_taskspec_task_is_a_property():
    spec = taskfile.example()
    assert isinstance(type(spec).__dict__["task"], property)
    assert isinstance(spec.task, Task) and spec.task == Task(list(spec.poses))
    assert len(spec.task.poles) == 3


def test_the_task_file_writer_keeps_comments_and_round_trips():
    spec = taskfile.example()
    text = taskfile.dumps(spec)
    assert text == (ROOT / "examples" / "task.toml").read_text()
    assert "[[pose]]  # pose 1: x, y where the coupler point is" in text
    assert 'input = "any"  # the driving link' in text
    back = taskfile.loads(text)
    assert np.allclose(back.poses, spec.poses, rtol=0, atol=1e-15)
    assert (back.view, back.limits, back.driven_center) == (spec.view, spec.limits, spec.driven_center)
    # Four poses with limits; awkward floats (tiny, huge, negative zero) are TOML floats that read back.
    four = taskfile.TaskSpec(POSES + [(1e-7, -0.0, 1.3)], None, Grid(-1e3, 2.5e-5, -8, 8, 7, 9),
                             burmester.DesignLimits(40.0, 6.5, "crank"), "<four>")
    text = taskfile.dumps(four)
    doc = tomllib.loads(text)
    assert doc["limits"] == {"min_transmission_deg": 40.0, "max_link_ratio": 6.5, "input": "crank", "min_grashof_margin": 0.01}
    back = taskfile.loads(text)
    assert back.view == four.view and back.limits == four.limits
    assert np.allclose(back.poses, four.poses, rtol=1e-15, atol=0)


def test_extras_keep_ipython_out_of_plot():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    extras = project["optional-dependencies"]
    names = {k: [re.split(r"[<>=\[; ]", d)[0].lower() for d in v] for k, v in extras.items()}
    assert {"matplotlib", "ezdxf"} <= set(names["plot"])
    assert not {"ipympl", "ipython", "ipywidgets", "notebook", "jupyter"} & set(names["plot"])
    assert {"ipympl", "ipywidgets", "burmester"} <= set(names["notebook"])
    assert "dask" in names["dask"]
    assert extras["all"] == ["burmester[plot,notebook,dask]"]
    assert project["license"] == "MIT OR Apache-2.0"
    assert project["license-files"] == ["LICENSE-MIT", "LICENSE-APACHE"]
    deps = [re.split(r"[<>=; ]", d)[0] for d in project["dependencies"]]
    assert {"tqdm", "rich", "tomlkit"} <= set(deps)


def test_cli_tables_are_aligned_ascii():
    rows = [["1", "(0.000, 1.000)", "crank-rocker"], ["12", "(-10.500, 3.250)", "triple-rocker"]]
    text = cli.table([("#", "right"), ("A0 (x, y)", "right"), ("Grashof type", "left")], rows)
    lines = text.splitlines()
    assert text.isascii() and len(lines) == 4 and all(ln == ln.rstrip() for ln in lines)
    assert [c.strip() for c in lines[0].split("|")] == ["#", "A0 (x, y)", "Grashof type"]
    assert set(lines[1]) == {"-", "+"}
    # Columns line up: every "|" at the same place in every line.
    bars = {tuple(i for i, ch in enumerate(ln) if ch == "|") for ln in (lines[0], *lines[2:])}
    assert len(bars) == 1
    assert lines[3].split("|")[0] == "12 " and lines[2].split("|")[0] == " 1 "  # right-justified
    assert lines[3].split("|")[2].strip() == "triple-rocker"
    # A table wider than any terminal is not cut or wrapped.
    wide = cli.table([("x", "left")], [["y" * 500]])
    assert wide.splitlines()[2] == "y" * 500
