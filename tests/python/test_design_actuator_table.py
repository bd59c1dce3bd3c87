"""``burmester design TASK.toml --input actuator`` and the task file's
``[actuator]`` table: its ``link``, ``point``, ``max_stroke_ratio``,
``width`` and ``min_gap`` are the defaults, each flag overrides its key,
and a bad value is refused naming the key (or the flag).

The task is ``examples/hood.toml`` with ``[limits] max_size_ratio`` raised
to 8 (the table's own size limit for ``burmester actuator``): under 5 no
hinge takes a strut on the table's bracket point (the README). Each answer
is read from the command's JSON: the placement's own link, point, stroke
ratio limit, width and gap, and its stroke ratio within the limit."""

import argparse
import json
import math
import re
from pathlib import Path

import pytest

from burmester.cli import main
from burmester.cli.base import UsageError
from burmester.cli.commands import _design_strut
from burmester.taskfile import ActuatorSpec

HOOD = Path(__file__).resolve().parents[2] / "examples" / "hood.toml"
#: The table's bracket point, the strut's pin at pose 1.
BRACKET = (-40.0, -20.0)


def _hood(tmp_path, name="hood.toml", **lines):
    """The hood's task file, its design size limit 8, each ``[actuator]``
    key of ``lines`` replaced by its line (None: removed)."""
    text = HOOD.read_text().replace("max_size_ratio = 5.0 ", "max_size_ratio = 8.0 ")
    out = []
    for line in text.splitlines():
        key = line.split("=")[0].strip()
        if key in lines and ("[actuator]" in text[: text.index(line)]):
            if lines[key] is not None:
                out.append(f"{key} = {lines[key]}")
            continue
        out.append(line)
    path = tmp_path / name
    path.write_text("\n".join(out) + "\n")
    return path


def _placements(capsys, path, *flags):
    """The placements of ``design --input actuator --top 1 --json``, and
    the count passed over."""
    assert main(["design", str(path), "--input", "actuator", "--top", "1", "--json", *flags]) == 0
    doc = json.loads(capsys.readouterr().out)
    return [d["actuator"] for d in doc["designs"]], doc["unplaced"]


def _check(a, link, point, ratio):
    """``a`` is placed on ``link`` (at ``point`` where given) within the
    stroke ratio limit ``ratio``, clear by the table's width and gap."""
    assert a["link"] == link
    if point is not None:
        assert a["point"] == pytest.approx(list(point), abs=1e-9)
    assert a["max_stroke_ratio"] == ratio and a["stroke_ratio"] <= ratio
    assert a["monotone"] and a["acceptable"] and a["clear"]
    assert (a["actuator_width"], a["min_gap"]) == (20.0, 3.0) and a["min_clearance"] >= 3.0


def test_the_table_gives_link_point_and_stroke_ratio(tmp_path, capsys):
    # The file's table as it is: the coupler at its bracket, ratio 1.8.
    found, _ = _placements(capsys, _hood(tmp_path))
    assert found
    for a in found:
        _check(a, "coupler", BRACKET, 1.8)
    # Its link and ratio changed, its point removed: the crank, a few of
    # its points tried (the bracket is not on it), ratio 1.85.
    crank = _hood(tmp_path, "crank.toml", link='"crank"', point=None, max_stroke_ratio="1.85")
    found, _ = _placements(capsys, crank)
    assert found
    for a in found:
        _check(a, "crank", None, 1.85)
        assert a["point"] != pytest.approx(list(BRACKET))
    # The flags override each key.
    found, _ = _placements(capsys, crank, "--actuator-link", "coupler", "--actuator-point", "-40", "-20",
                           "--max-stroke-ratio", "1.8")
    assert found
    for a in found:
        _check(a, "coupler", BRACKET, 1.8)
    # The file's ratio binds: at 1.5 no hinge keeps a strut on the bracket
    # (each passed over); the flag lifts it.
    tight = _hood(tmp_path, "tight.toml", max_stroke_ratio="1.5")
    found, unplaced = _placements(capsys, tight)
    assert not found and unplaced > 0
    found, _ = _placements(capsys, tight, "--max-stroke-ratio", "1.8")
    assert found
    for a in found:
        _check(a, "coupler", BRACKET, 1.8)


def test_try_points_overrides_the_tables_point(tmp_path, capsys):
    found, _ = _placements(capsys, _hood(tmp_path), "--try-actuator-points")
    assert found
    for a in found:
        _check(a, "coupler", None, 1.8)
        assert a["point"] != pytest.approx(list(BRACKET))
    assert main(["design", str(HOOD), "--input", "actuator", "--try-actuator-points", "--actuator-point", "0",
                 "0"]) == 2
    assert "--actuator-point and --try-actuator-points" in capsys.readouterr().err
    assert main(["design", str(HOOD), "--try-actuator-points"]) == 2
    assert "give --input actuator" in capsys.readouterr().err


@pytest.mark.parametrize("key, value, says", [
    ("link", '"wheel"', r'actuator\.link.*"coupler", "crank", "rocker"'),
    ("max_stroke_ratio", "0.5", r"actuator\.max_stroke_ratio.*at least 1"),
    ("point", '"bracket"', r"actuator\.point"),
    ("stroke", "1.5", r"stroke"),
])
def test_a_bad_key_in_the_file_is_named(tmp_path, capsys, key, value, says):
    path = tmp_path / "bad.toml"
    path.write_text(HOOD.read_text().replace("[actuator]", f"[actuator]\n{key} = {value}", 1)
                    if key == "stroke" else _hood(tmp_path, **{key: value}).read_text())
    assert main(["design", str(path), "--input", "actuator"]) == 2
    err = capsys.readouterr().err
    assert re.search(says, err), err


def _args(**flags):
    """The ``design`` flags of the actuator, ``--input actuator``."""
    base = dict(design_input="actuator", motor=False, actuator_link=None, actuator_point=None,
                try_actuator_points=False, max_stroke_ratio=None, actuator_width=None, min_gap=None)
    base.update(flags)
    return argparse.Namespace(**base)


@pytest.mark.parametrize("table, says", [
    (ActuatorSpec(link="wheel"), r"\[actuator\] link .*\"coupler\", \"crank\" or \"rocker\", got 'wheel'"),
    (ActuatorSpec(point=(math.nan, 0.0)), r"\[actuator\] point .*finite point"),
    (ActuatorSpec(point=(1.0,)), r"\[actuator\] point .*a point \[x, y\]"),
    (ActuatorSpec(max_stroke_ratio=0.5), r"\[actuator\] max_stroke_ratio .*at least 1.*got 0.5"),
    (ActuatorSpec(width=-1.0), r"\[actuator\] width .*at least 0"),
    (ActuatorSpec(min_gap=math.nan), r"\[actuator\] min_gap .*at least 0"),
])
def test_a_bad_table_value_names_its_key(table, says):
    # A table made in Python (not read from a file, which checks it first).
    with pytest.raises(UsageError, match=says):
        _design_strut(_args(), table)
    # Its flag given instead, the key is not read.
    flag = {"link": ("actuator_link", "rocker"), "point": ("actuator_point", [1.0, 2.0]),
            "max_stroke_ratio": ("max_stroke_ratio", 1.5), "width": ("actuator_width", 2.0),
            "min_gap": ("min_gap", 1.0)}
    key = says.split("]")[1].split()[0]
    name, value = flag[key]
    kw = _design_strut(_args(**{name: value}), table)
    assert kw["input"] == "actuator"


def test_the_flags_and_the_table_as_keywords():
    table = ActuatorSpec(link="rocker", point=(1.0, 2.0), max_stroke_ratio=1.6, width=4.0, min_gap=0.5)
    assert _design_strut(_args(), table) == dict(input="actuator", actuator_link="rocker", actuator_point=(1.0, 2.0),
                                                 max_stroke_ratio=1.6, actuator_width=4.0, min_gap=0.5)
    kw = _design_strut(_args(actuator_link="crank", actuator_point=[3.0, 4.0], max_stroke_ratio=1.7,
                             actuator_width=5.0, min_gap=0.0), table)
    assert kw == dict(input="actuator", actuator_link="crank", actuator_point=(3.0, 4.0), max_stroke_ratio=1.7,
                      actuator_width=5.0, min_gap=0.0)
    kw = _design_strut(_args(try_actuator_points=True), table)
    assert "actuator_point" not in kw and kw["actuator_link"] == "rocker"
    # Without a table: the flags alone, the defaults of burmester.design.
    assert _design_strut(_args(), None) == dict(input="actuator", actuator_width=0.0, min_gap=0.0)
