"""Slider linkages and the linear actuator on paper (issue 27, item 4): the
CAD export (DXF read back with ezdxf, SVG with ElementTree) checked against
the core's numbers and against independent ones (a slider-crank built by
hand, the task's rigid displacement of the actuator's point), the
actuator's animation, the task file's ``[actuator]`` table and the
``burmester actuator`` command that reads it."""

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import burmester
from burmester import SliderCrank, Task, taskfile
from burmester.cli import main

ezdxf = pytest.importorskip("ezdxf")
mpl = pytest.importorskip("matplotlib")
mpl.use("Agg")
export = pytest.importorskip("burmester.export")
from burmester import plot  # noqa: E402

HOOD = Path(__file__).resolve().parents[2] / "examples" / "hood.toml"
SVG = "{http://www.w3.org/2000/svg}"


def polylines(doc, layer):
    return [np.array(list(e.get_points("xy")), dtype=float)
            for e in doc.modelspace().query(f'LWPOLYLINE[layer=="{layer}"]')]


def circles(doc, layer):
    return [np.array(e.dxf.center)[:2] for e in doc.modelspace().query(f'CIRCLE[layer=="{layer}"]')]


def measurements(doc):
    return [e.get_measurement() for e in doc.modelspace().query("DIMENSION")]


def assert_svg_is_dxf(doc, svg, layers):
    """Each layer's SVG paths are its DXF polylines, y flipped back."""
    for layer in layers:
        for x, y in zip(polylines(doc, layer), svg_paths(svg, layer)):
            np.testing.assert_allclose(y, x, atol=1e-12)


def svg_paths(path, layer):
    """The polylines of an SVG layer in model coordinates (y flipped back)."""
    root = ET.parse(path).getroot()
    (g,) = [g for g in root.findall(f"{SVG}g") if g.get("id") == layer]
    out = []
    for el in g.findall(f"{SVG}path"):
        pts = [tuple(float(v) for v in p.strip().split()) for p in el.get("d").strip("MZ ").split("L")]
        out.append(np.array([(x, -y) for x, y in pts]))
    return out


# ---------------------------------------------------------------------------
# A slider-crank made by hand: its task, its synthesized linkage


@pytest.fixture(scope="module")
def known():
    """A slider-crank (crank 1, coupler 3, the guide at 0.2 rad through
    (0, 0.4)), three poses of its coupler, and the linkage synthesized back
    from its driving crank and its slider."""
    sc = SliderCrank(crank=1.0, coupler=3.0, guide_point=(0.0, 0.4), guide=(math.cos(0.2), math.sin(0.2)))
    angles = (0.2, 1.0, 2.1)
    poses = []
    for t2 in angles:
        x, y = sc.coupler_point(t2, (0.5, 0.7), "open")
        poses.append((x, y, sc.solve(t2, "open").theta3 + 0.3))
    _, a1, b1 = sc.joints(angles[0], "open")
    s = Task(poses).slider_crank(((0.0, 0.0), a1), (b1, sc.guide))
    assert s.feasible
    return sc, angles, s


def on_guide(sc, p):
    """The distance of ``p`` from the hand-made guide line."""
    u = sc.guide
    return abs((p[0] - 0.0) * u[1] - (p[1] - 0.4) * u[0])


def test_slider_crank_dxf_is_the_hand_made_linkage_at_its_poses(tmp_path, known):
    sc, angles, s = known
    path = export.slider_crank_dxf(s, tmp_path / "s.dxf", travel_samples=7)
    doc = ezdxf.readfile(path)
    assert {"GUIDE", "SLIDER", "PIVOTS", "LINKAGE_1", "LINKAGE_3", "POSES", "COUPLER_PATH", "TRAVEL",
            "DIMENSIONS"} <= {layer.dxf.name for layer in doc.layers}
    assert doc.header["$INSUNITS"] == 4  # mm by default
    # The guide: one line on the hand-made guide, covering the slider pin at every pose.
    (guide,) = polylines(doc, "GUIDE")
    assert max(on_guide(sc, p) for p in guide) < 1e-12
    u = np.array(sc.guide)
    lo, hi = sorted(guide @ u)
    for k, t2 in enumerate(angles, start=1):
        a0, a, b = sc.joints(t2, "open")  # the hand-made linkage, not the synthesized one
        crank, plate = polylines(doc, f"LINKAGE_{k}")
        np.testing.assert_allclose(crank, [a0, a], atol=1e-9)
        np.testing.assert_allclose(plate[:2], [a, b], atol=1e-9)
        np.testing.assert_allclose(plate[2], sc.coupler_point(t2, (0.5, 0.7), "open"), atol=1e-9)
        assert lo < float(np.dot(b, u)) < hi
        # The block: centred on the pin, its long sides along the guide.
        block = polylines(doc, "SLIDER")[k - 1]
        np.testing.assert_allclose(block.mean(axis=0), b, atol=1e-12)
        assert abs(float(np.dot(block[1] - block[0], u))) == pytest.approx(np.linalg.norm(block[1] - block[0]))
    assert len(polylines(doc, "TRAVEL")) == 7
    # The dimensions: crank 1, coupler 3, the plate's sides, the offset, A0's ordinates.
    got = measurements(doc)
    for want in (1.0, 3.0, abs(sc.offset), math.hypot(0.5, 0.7), math.hypot(2.5, 0.7)):
        assert min(abs(m - want) for m in got if isinstance(m, float)) < 1e-9, want


def test_slider_crank_svg_is_the_dxf_upright(tmp_path, known):
    sc, angles, s = known
    d = ezdxf.readfile(export.slider_crank(s, tmp_path / "s.dxf"))
    assert_svg_is_dxf(d, export.slider_crank(s, tmp_path / "s.svg"), ("GUIDE", "SLIDER", "LINKAGE_2"))


def test_a_slider_crank_alone_at_an_angle(tmp_path, known):
    sc, _, _ = known
    doc = ezdxf.readfile(export.slider_crank(sc, tmp_path / "sc.dxf", 0.4, "crossed"))
    crank, coupler = polylines(doc, "LINKAGE_1")
    a0, a, b = sc.joints(0.4, "crossed")
    np.testing.assert_allclose(np.vstack([crank, coupler]), [a0, a, a, b], atol=1e-12)
    (guide,) = polylines(doc, "GUIDE")
    assert max(on_guide(sc, p) for p in guide) < 1e-12
    with pytest.raises(burmester.InvalidInputError, match="travel_samples"):
        export.slider_crank(sc, tmp_path / "x.dxf", travel_samples=1)
    with pytest.raises(burmester.InvalidInputError, match=".dxf or .svg"):
        export.slider_crank(sc, tmp_path / "x.png")
    with pytest.raises(burmester.InvalidInputError):
        export.slider_crank_svg(sc, tmp_path / "x.dxf")
    with pytest.raises(TypeError):
        export.slider_crank(object(), tmp_path / "x.dxf")
    assert not list(tmp_path.glob("x.*"))


# ---------------------------------------------------------------------------
# The hood's strut


@pytest.fixture(scope="module")
def strut():
    """The README's hood strut from the task file's [actuator] table (a coarser grid)."""
    spec = taskfile.load(HOOD)
    t = spec.actuator
    assert t is not None and t.point == (-40.0, -20.0)
    hinge = burmester.design(spec.task, space=spec.space, limits=spec.limits, top=1)[0].linkage
    limits = burmester.DesignLimits(spec.limits.min_transmission_deg, spec.limits.max_link_ratio,
                                    spec.limits.input, t.max_size_ratio)
    amap = hinge.actuator_map(*t.view, 64, 64, link=t.link, point=t.point, max_stroke_ratio=t.max_stroke_ratio,
                              limits=limits, base_plate=list(t.base_plate))
    (a,) = amap.best_placements(1)
    assert a.acceptable and a.monotone
    return spec, amap, a


def test_actuator_dxf_holds_the_strut_at_the_poses(tmp_path, strut):
    spec, _, a = strut
    doc = ezdxf.readfile(export.actuator_dxf(a, tmp_path / "strut.dxf"))
    assert {"ACTUATOR_AXIS", "ACTUATOR_BODY", "ACTUATOR_ROD", "ACTUATOR_PATH", "PIVOTS", "GROUND",
            "LINKAGE_1", "DIMENSIONS"} <= {layer.dxf.name for layer in doc.layers}
    assert doc.header["$INSUNITS"] == 4
    # G among the fixed pivots, with A0 and C0.
    pivots = circles(doc, "PIVOTS")
    for p in (a.ground, a.linkage.driving[0], a.linkage.driven[0]):
        assert min(np.linalg.norm(c - p) for c in pivots) < 1e-12
    axes = polylines(doc, "ACTUATOR_AXIS")
    bodies = polylines(doc, "ACTUATOR_BODY")
    rods = polylines(doc, "ACTUATOR_ROD")
    assert len(axes) == len(bodies) == len(rods) == len(spec.task)
    for k, (axis, body, rod) in enumerate(zip(axes, bodies, rods), start=1):
        # Independent of the linkage: Q on the hood is where the task's rigid
        # displacement from pose 1 puts it.
        q = spec.task.displace(a.point, 1, k)
        np.testing.assert_allclose(axis, [a.ground, q], atol=1e-8)
        assert np.linalg.norm(axis[1] - axis[0]) == pytest.approx(a.pose_lengths[k - 1], abs=1e-9)
        # The body starts at G and the rod ends at Q, on the axis.
        np.testing.assert_allclose(0.5 * (body[0] + body[3]), a.ground, atol=1e-9)
        np.testing.assert_allclose(0.5 * (rod[1] + rod[2]), q, atol=1e-8)
    # Q's path runs from Q at pose 1 to Q at the last pose.
    (path,) = polylines(doc, "ACTUATOR_PATH")
    np.testing.assert_allclose(path[[0, -1]], [a.point, spec.task.displace(a.point, 1, 3)], atol=1e-8)
    # The pin-to-pin lengths closed and open are dimensioned (a monotone extending strut).
    got = [m for m in measurements(doc) if isinstance(m, float)]
    for want in (a.min_length, a.max_length):
        assert min(abs(m - want) for m in got) < 1e-9
    assert_svg_is_dxf(doc, export.actuator(a, tmp_path / "strut.svg"), ("ACTUATOR_AXIS", "ACTUATOR_BODY",
                                                                          "ACTUATOR_ROD"))


def test_actuator_export_at_the_documented_maximum_and_its_errors(tmp_path, strut):
    _, _, a = strut
    doc = ezdxf.readfile(export.actuator(a, tmp_path / "max.dxf", path_samples=export.MAX_SAMPLES))
    (path,) = polylines(doc, "ACTUATOR_PATH")
    assert len(path) == export.MAX_SAMPLES
    with pytest.raises(burmester.InvalidInputError, match="path_samples"):
        export.actuator(a, tmp_path / "x.dxf", path_samples=export.MAX_SAMPLES + 1)
    with pytest.raises(TypeError):
        export.actuator(a.linkage, tmp_path / "x.dxf")
    assert not (tmp_path / "x.dxf").exists()


def test_actuator_animation_moves_the_cylinder(tmp_path, strut):
    from PIL import Image

    _, _, a = strut
    out = tmp_path / "strut.gif"
    anim = plot.animate_actuator(a, out, frames=6, fps=5, dpi=30, units="mm")
    with Image.open(out) as im:
        assert im.n_frames >= 8
    fig = anim._fig
    ax = fig.axes[0]
    gids = {x.get_gid() for x in ax.get_children()}
    assert {"moving-linkage", "moving-actuator-body", "moving-actuator-rod", "point-path"} <= gids
    assert ax.get_xlabel() == "x [mm]"
    with pytest.raises(burmester.InvalidInputError):
        plot.animate_actuator(a, tmp_path / "x.gif", frames=plot.MAX_FRAMES + 1)
    with pytest.raises(burmester.InvalidInputError):
        plot.animate_actuator(a, tmp_path / "x.png")


def test_actuator_animation_interrupted_leaves_no_file(tmp_path, strut, monkeypatch):
    import matplotlib.animation as animation

    _, _, a = strut
    calls = []

    def grab_frame(self, **kw):
        calls.append(1)
        if len(calls) == 2:
            raise KeyboardInterrupt

    monkeypatch.setattr(animation.PillowWriter, "grab_frame", grab_frame)
    target = tmp_path / "strut.gif"
    target.write_bytes(b"old")
    with pytest.raises(KeyboardInterrupt):
        plot.animate_actuator(a, target, frames=6, dpi=20)
    assert target.read_bytes() == b"old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["strut.gif"]


# ---------------------------------------------------------------------------
# The pictures: the map drawn by the helper shared with the drive map, units


def test_actuator_pictures_share_the_map_helper_and_say_units(strut):
    import matplotlib.pyplot as plt

    from burmester import actuators

    _, amap, a = strut
    fig, (left, right) = plt.subplots(1, 2)
    actuators.draw_map(amap, ax=left, units="mm")
    actuators.draw_actuator(a, ax=right, units="mm")
    assert left.get_xlabel() == "x [mm]" and right.get_ylabel() == "y [mm]"
    (img,) = [c for c in left.get_children() if c.get_gid() == "actuator-map"]
    cat = np.asarray(img.get_array())
    assert np.array_equal(cat == 2, amap.acceptable) and np.array_equal(cat >= 1, amap.monotone | amap.acceptable)
    assert [c for c in left.get_children() if c.get_gid() == "transmission"]
    # The same helper draws a drive map: its categories and contours.
    fig2, ax = plt.subplots()
    helper = plot.placement_map(ax, amap.grid, amap.monotone, amap.acceptable,
                                np.degrees(np.where(amap.monotone, amap.min_transmission_rad, np.nan)),
                                plot.ACTUATOR_MAP_CMAP, ("a", "b"), "actuator-map", (30.0, 45.0))
    assert [h.get_label() for h in helper] == ["a", "b"]
    (img2,) = [c for c in ax.get_children() if c.get_gid() == "actuator-map"]
    assert np.array_equal(np.asarray(img2.get_array()), cat)
    plt.close(fig)
    plt.close(fig2)


# ---------------------------------------------------------------------------
# The task file's [actuator] table


ACTUATOR = """
[actuator]
link = "rocker"
point = [1.5, -2.0]
max_stroke_ratio = 1.6
max_size_ratio = inf
rank_by = "margin"
x = [-5.0, 5.0]
y = [-4.0, 6.0]
grid = [1024, 1024]
base_plate = [[-5, -4], [5, -4], [0, 6]]
width = 0.5
"""


def three_poses(extra=""):
    return taskfile.dumps(taskfile.example()) + extra


def test_the_actuator_table_round_trips():
    spec = taskfile.loads(three_poses(ACTUATOR))
    t = spec.actuator
    assert t == taskfile.ActuatorSpec("rocker", (1.5, -2.0), 1.6, math.inf, "margin", (-5.0, 5.0, -4.0, 6.0),
                                      (1024, 1024), ((-5.0, -4.0), (5.0, -4.0), (0.0, 6.0)), 0.5)
    again = taskfile.loads(taskfile.dumps(spec))
    assert again == spec
    # The defaults, written out and read back.
    bare = taskfile.loads(three_poses("\n[actuator]\n"))
    assert bare.actuator == taskfile.ActuatorSpec()
    assert taskfile.loads(taskfile.dumps(bare)) == bare
    with pytest.raises(taskfile.TaskFileError, match="actuator: expected a table"):
        taskfile.loads('actuator = "coupler"\n' + three_poses())
    # The hood's file has one.
    assert taskfile.load(HOOD).actuator.grid == (320, 320)


#: A bad line of [actuator] | the field its error names | words of the message.
BAD_LINES = r"""
link = "slider"                  | actuator.link             | "coupler", "crank", "rocker"
rank_by = "best"                 | actuator.rank_by          | "margin"
point = [1.0]                    | actuator.point            | [x, y]
max_stroke_ratio = 0.9           | actuator.max_stroke_ratio | at least 1
max_stroke_ratio = nan           | actuator.max_stroke_ratio | finite
max_size_ratio = 0.5             | actuator.max_size_ratio   | at least 1
x = [1.0, 2.0]                   | actuator.y                | missing
x = [2.0, 1.0]\ny = [0.0, 1.0]   | actuator.x                | min < max
grid = [1025, 10]                | actuator.grid[0]          | 2 to 1024
grid = [10, 1]                   | actuator.grid[1]          | 2 to 20000
base_plate = [[0, 0], [1, 0]]    | actuator.base_plate       | at least 3 points
stroke = 10                      | actuator.stroke           | unknown key
width = -1                       | actuator.width            | above 0
min_gap = -1                     | actuator.min_gap          | at least 0
"""


@pytest.mark.parametrize("line, where, words", [
    tuple(part.strip().replace("\\n", "\n") for part in row.split("|")) for row in BAD_LINES.strip().splitlines()
])
def test_a_bad_actuator_table_names_the_field(line, where, words):
    with pytest.raises(taskfile.TaskFileError) as e:
        taskfile.loads(three_poses(f"\n[actuator]\n{line}\n"), "t.toml")
    assert isinstance(e.value, ValueError)
    assert f"t.toml: {where}" in str(e.value) and words in str(e.value), str(e.value)


def test_the_cli_reads_the_table_and_the_flags_override_it(tmp_path, capsys):
    import json

    # The hood's table alone: the README's strut (its grid made coarser by the flag).
    assert main(["actuator", str(HOOD), "--map-grid", "64", "64", "--json"]) == 0
    from_file = json.loads(capsys.readouterr().out)["actuator"]
    assert from_file["point"] == [-40.0, -20.0] and from_file["max_stroke_ratio"] == 1.8
    # The ground pivot inside the table's base plate.
    gx, gy = from_file["ground"]
    assert -150.0 <= gx <= 50.0 and -100.0 <= gy <= 0.0
    # A flag overrides the table.
    assert main(["actuator", str(HOOD), "--map-grid", "64", "64", "--max-stroke-ratio", "1.9", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["actuator"]["max_stroke_ratio"] == 1.9
    # The strut's diameter is the table's width (20 mm) in its clearance
    # too; --width overrides it there as well.
    assert from_file["actuator_width"] == 20.0 and from_file["min_gap"] == 3.0
    assert from_file["min_clearance"] >= 3.0
    assert main(["actuator", str(HOOD), "--map-grid", "64", "64", "--width", "18", "--json"]) == 0
    thinner = json.loads(capsys.readouterr().out)["actuator"]
    assert thinner["actuator_width"] == 18.0 and thinner["min_clearance"] >= 3.0
    gx, gy = thinner["ground"]
    # -o writes the CAD export and the animation too.
    out = tmp_path / "strut.dxf"
    assert main(["actuator", str(HOOD), "--map-grid", "64", "64", "-o", str(out), "--width", "18"]) == 0
    doc = ezdxf.readfile(out)
    (axis, *_) = polylines(doc, "ACTUATOR_AXIS")
    assert np.allclose(axis, [(gx, gy), (-40.0, -20.0)])
    body = polylines(doc, "ACTUATOR_BODY")[0]
    assert np.linalg.norm(body[1] - body[2]) == pytest.approx(18.0)  # the --width asked for
    gif = tmp_path / "strut.gif"
    assert main(["actuator", str(HOOD), "--map-grid", "32", "32", "-o", str(gif), "--frames", "4", "--fps", "4",
                 "--dpi", "40"]) == 0
    from PIL import Image

    with Image.open(gif) as im:
        assert im.n_frames >= 6 and im.size[0] < 400  # the frames, at the --dpi asked for
    assert main(["actuator", str(HOOD), "--map-grid", "64", "64", "-o", str(tmp_path / "b.dxf"), "--frames", "5"]) == 2
    assert "--frames is for animations" in capsys.readouterr().err


def test_slider_crank_export_at_the_documented_maximum(tmp_path, known):
    sc, angles, s = known
    doc = ezdxf.readfile(export.slider_crank(s, tmp_path / "max.dxf", path_samples=export.MAX_SAMPLES))
    stops = s.travel_stops
    pieces = polylines(doc, "COUPLER_PATH")
    assert len(pieces) == len(angles) - 1
    for (a, b), piece in zip(zip(stops[:-1], stops[1:]), pieces):
        assert len(piece) == math.ceil(export.MAX_SAMPLES * abs(b - a) / (2 * math.pi)) + 1
        # Each leg runs from a pose's coupler point to the next (the hand-made linkage's).
        np.testing.assert_allclose(piece[[0, -1]], [sc.coupler_point(a, (0.5, 0.7), "open"),
                                                    sc.coupler_point(b, (0.5, 0.7), "open")], atol=1e-9)
    with pytest.raises(burmester.InvalidInputError, match="path_samples"):
        export.slider_crank(s, tmp_path / "x.svg", path_samples=7)


def test_slider_dyad_picture_puts_the_pins_on_its_guide(known):
    import matplotlib.pyplot as plt

    sc, angles, s = known
    task = Task([s.pose_at(t, "open") for t in angles])
    dyad = task.slider_dyad(s.driven[0])
    ax = plot.slider_dyad(dyad, task, units="mm")
    (guide,) = [a for a in ax.get_children() if a.get_gid() == "guide"]
    ends = guide.get_xydata()
    (pins,) = [a for a in ax.get_children() if a.get_gid() == "slider-positions"]
    for k, pin in enumerate(pins.get_xydata(), start=2):
        _, _, b = sc.joints(angles[k - 1], "open")  # the hand-made slider's pin at pose k
        np.testing.assert_allclose(pin, b, atol=1e-9)
        assert on_guide(sc, pin) < 1e-9
    assert max(on_guide(sc, p) for p in ends) < 1e-9
    assert ax.get_xlabel() == "x [mm]"
    plt.close(ax.figure)


def test_the_actuator_table_pickles_to_an_equal_object():
    import pickle

    spec = taskfile.load(HOOD)
    assert pickle.loads(pickle.dumps(spec.actuator)) == spec.actuator
