"""``burmester design TASK.toml --input actuator`` and the task file's
``[actuator]`` table: its ``link``, ``point``, ``max_stroke_ratio``,
``width`` and ``min_gap`` are the defaults, each flag overrides its key,
and a bad value is refused naming the key (or the flag).

The first tests take ``examples/hood.toml`` with ``[limits]
max_size_ratio`` raised to 8, the table's own size limit (written when the
strut stage held the strut to ``[limits]``: under 5 no hinge took a strut on
the table's bracket point). The last ones take the file as it is: the
table's ``max_size_ratio`` bounds the hinge with its open strut, the
limits' 5 the hinge alone, ``--actuator-max-size-ratio`` overrides the key,
a bad value is named, and ``burmester.design``'s keyword has its default,
its most (no bound), its pickle. Each answer is read from the command's
JSON (or the report): the placement's own link, point, stroke ratio limit,
width and gap, and its stroke ratio within the limit."""

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
                try_actuator_points=False, max_stroke_ratio=None, actuator_max_size_ratio=None,
                actuator_width=None, min_gap=None)
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


# ---------------------------------------------------------------------------
# The table's max_size_ratio: the strut stage's own size bound.


def _sized(tmp_path, name, size=None, limits="5.0"):
    """The hood's task file as it is (its ``[limits] max_size_ratio`` 5,
    or ``limits``), its ``[actuator] max_size_ratio`` line set to ``size``
    (None: removed)."""
    out = []
    section = ""
    for line in HOOD.read_text().splitlines():
        if line.startswith("["):
            section = line.split("]")[0] + "]"
        if line.split("=")[0].strip() == "max_size_ratio":
            value = limits if section == "[limits]" else size
            if value is None:
                continue
            line = f"max_size_ratio = {value}"
        out.append(line)
    path = tmp_path / name
    path.write_text("\n".join(out) + "\n")
    return path


def _document(capsys, path, *flags):
    """The JSON of ``design --input actuator --top 1``."""
    assert main(["design", str(path), "--input", "actuator", "--top", "1", "--json", *flags]) == 0
    return json.loads(capsys.readouterr().out)


def test_the_tables_size_ratio_bounds_the_strut_not_the_hinge(capsys, tmp_path):
    # The file as it is: [limits] 5 for the hinge, [actuator] 8 for the
    # hinge with its open strut. The strut on the bracket makes more than 5
    # task sizes (so 5 would refuse it), the hinge alone at most 5.
    doc = _document(capsys, HOOD)
    assert doc["actuator_max_size_ratio"] == 8.0 and doc["limits"]["max_size_ratio"] == 5.0
    assert doc["designs"]
    for d in doc["designs"]:
        a = d["actuator"]
        _check(a, "coupler", BRACKET, 1.8)
        assert 5.0 < a["size_ratio"] <= 8.0 and d["size_ratio"] <= 5.0
    # The key set to 5, or removed (the limits' 5): every hinge passed over.
    for path in (_sized(tmp_path, "five.toml", "5.0"), _sized(tmp_path, "none.toml")):
        doc = _document(capsys, path)
        assert not doc["designs"] and doc["unplaced"] > 0 and doc["actuator_max_size_ratio"] == 5.0
        # The flag overrides the key (or the limits).
        doc = _document(capsys, path, "--actuator-max-size-ratio", "8")
        assert doc["designs"] and doc["actuator_max_size_ratio"] == 8.0
        assert all(5.0 < d["actuator"]["size_ratio"] <= 8.0 for d in doc["designs"])
    # The flag binds over the file's 8.
    doc = _document(capsys, HOOD, "--actuator-max-size-ratio", "5")
    assert not doc["designs"] and doc["unplaced"] > 0
    # TOML's inf: no bound on the strut (JSON null), the header says so.
    doc = _document(capsys, _sized(tmp_path, "inf.toml", "inf"))
    assert doc["actuator_max_size_ratio"] is None and doc["designs"]
    assert main(["design", str(HOOD), "--input", "actuator", "--top", "1"]) == 0
    assert "with the open actuator at most 8x the task" in capsys.readouterr().out


def test_a_bad_size_ratio_is_named(capsys, tmp_path):
    # The file's key below 1: refused as the file is read (the library's
    # limits take no size ratio below 1), named, nothing searched.
    assert main(["design", str(_sized(tmp_path, "half.toml", "0.5")), "--input", "actuator"]) == 2
    assert re.search(r"actuator\.max_size_ratio: expected a ratio of at least 1.*found 0\.5",
                     capsys.readouterr().err)
    assert main(["design", str(HOOD), "--input", "actuator", "--actuator-max-size-ratio", "0.9"]) == 2
    assert re.search(r"--actuator-max-size-ratio must be at least 1.*got 0\.9", capsys.readouterr().err)
    assert main(["design", str(HOOD), "--actuator-max-size-ratio", "8"]) == 2
    assert "--actuator-max-size-ratio set the linear actuator" in capsys.readouterr().err
    for bad in (0.5, math.nan, -math.inf):
        with pytest.raises(UsageError, match=r"\[actuator\] max_size_ratio .*at least 1"):
            _design_strut(_args(), ActuatorSpec(max_size_ratio=bad))
        # Its flag given instead, the key is not read.
        assert _design_strut(_args(actuator_max_size_ratio=2.0), ActuatorSpec(max_size_ratio=bad))[
            "actuator_max_size_ratio"] == 2.0
    assert _design_strut(_args(), ActuatorSpec(max_size_ratio=8.0))["actuator_max_size_ratio"] == 8.0
    assert "actuator_max_size_ratio" not in _design_strut(_args(), ActuatorSpec())


def _bracket_design(**kw):
    """``burmester.design`` on the hood's file (its limits' size 5) with the
    strut on the bracket, one design, a short search."""
    import burmester
    from burmester import taskfile

    spec = taskfile.load(str(HOOD))
    return burmester.design(spec.task, space=spec.space, limits=spec.limits, input="actuator", top=1,
                            starts=12, actuator_point=BRACKET, actuator_width=20.0, min_gap=3.0, **kw)


def test_the_keyword_its_default_its_most_and_its_pickle():
    import pickle

    import burmester
    from burmester import InvalidInputError

    # Default None: the limits' 5, the strut refused on every hinge.
    five = _bracket_design()
    assert len(five) == 0 and five.unplaced > 0 and five.actuator_max_size_ratio == 5.0
    eight = _bracket_design(actuator_max_size_ratio=8.0)
    assert len(eight) == 1 and eight.actuator_max_size_ratio == 8.0 and eight.limits.max_size_ratio == 5.0
    a = eight[0].actuator
    assert a.point == BRACKET and a.acceptable and a.clear and 5.0 < a.size_ratio <= 8.0
    # The size with the open strut, from the linkage and the strut's
    # length; the placement carries the limits it was judged under.
    assert a.size_ratio == pytest.approx((a.linkage.size + a.max_length) / eight.task.span, rel=1e-9)
    assert eight[0].size_ratio <= 5.0 and a.limits.max_size_ratio == 8.0
    assert a.limits == burmester.DesignLimits(eight.limits.min_transmission_deg, eight.limits.max_link_ratio,
                                              eight.limits.input, 8.0, eight.limits.max_link_length,
                                              eight.limits.min_grashof_margin)
    # The pickle keeps the bound: equal, and 8 again.
    back = pickle.loads(pickle.dumps(eight))
    assert back == eight and back.actuator_max_size_ratio == 8.0 and back[0].actuator == a
    # A pickle from before the bound (its actuator state of five) reads as
    # the limits': a different report, its bound 5.
    rebuild, state = eight.__reduce__()
    state = list(state)
    motor, strut = state[10]
    assert len(strut) == 6 and strut[5] == 8.0
    state[10] = (motor, strut[:5])
    old = rebuild(*state)
    assert old != eight and old.actuator_max_size_ratio == 5.0 and len(old) == 1
    # Infinity, the documented most (no bound), is searched once.
    unbounded = _bracket_design(actuator_max_size_ratio=math.inf)
    assert unbounded.actuator_max_size_ratio == math.inf and len(unbounded) == 1
    assert unbounded[0].score >= eight[0].score
    # Below 1 or NaN: refused naming it; without input="actuator": refused.
    for bad in (0.5, math.nan, -math.inf):
        with pytest.raises(InvalidInputError, match="actuator max_size_ratio"):
            _bracket_design(actuator_max_size_ratio=bad)
    with pytest.raises(InvalidInputError, match='actuator_max_size_ratio set the linear actuator.*input="actuator"'):
        burmester.design(eight.task, actuator_max_size_ratio=8.0)
