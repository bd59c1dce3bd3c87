"""The inverted slider-crank on paper (issue 27): the notebook pictures,
the animation, the CAD export (DXF read back with ezdxf, SVG with
ElementTree) and ``burmester inverted``.

The references are independent of the export: the position analysis in
closed form written here (the slot's line is ``|e|`` from the crank pin and
passes through the swivel: ``theta3 = phi - asin(e / rho)`` open, ``phi - pi
+ asin(e / rho)`` crossed, ``phi`` the direction and ``rho`` the distance
from the pin to the swivel), a hand-made linkage whose coupler made the task
(its poses are reached where it put them), and the slot position sampled
densely by the core's ``solve`` for the stroke."""

import json
import math
import pickle
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import burmester
from burmester import InvertedSliderCrank, Task, taskfile
from burmester.cli import main

ezdxf = pytest.importorskip("ezdxf")
mpl = pytest.importorskip("matplotlib")
mpl.use("Agg")
export = pytest.importorskip("burmester.export")
from burmester import plot  # noqa: E402
from test_slider_actuator_cad import SVG, circles, polylines, svg_paths  # noqa: E402  (DXF and SVG read back)

HOOD = Path(__file__).resolve().parents[2] / "examples" / "hood.toml"
POINT = (0.5, 0.8)  # the hand-made coupler point, in the coupler frame


def measurements(doc):
    return [e.get_measurement() for e in doc.modelspace().query("DIMENSION")
            if isinstance(e.get_measurement(), float)]


def svg_group(path, layer):
    (g,) = [g for g in ET.parse(path).getroot().findall(f"{SVG}g") if g.get("id") == layer]
    return g


def closed_form(q, theta2, mode):
    """``(A, theta3, F)`` of an inverted slider-crank by the closed form of
    the module's docstring (not the library's)."""
    x0, y0 = q.pivot
    a = np.array([x0 + q.crank * math.cos(theta2), y0 + q.crank * math.sin(theta2)])
    d = np.array(q.swivel) - a
    rho, phi = float(np.hypot(*d)), math.atan2(d[1], d[0])
    beta = math.asin(q.offset / rho)
    theta3 = phi - beta if mode == "open" else phi - math.pi + beta
    u = np.array([math.cos(theta3), math.sin(theta3)])
    t = float(d @ u)
    return a, theta3, np.array(q.swivel) - t * u


@pytest.fixture(scope="module")
def known():
    """A hand-made inverted slider-crank (crank 1, swivel (2.5, 0.3),
    offset 0.2), three poses of its coupler, and the linkage synthesized
    back from its crank and its slot at pose 1."""
    q = InvertedSliderCrank(crank=1.0, swivel=(2.5, 0.3), offset=0.2)
    angles = (0.3, 1.1, 2.0)
    poses = []
    for t2 in angles:
        x, y = q.coupler_point(t2, POINT, "open")
        poses.append((x, y, q.solve(t2, "open").theta3 + 0.3))
    _, a1, s, _ = q.joints(angles[0], "open")
    th = q.solve(angles[0], "open").theta3
    syn = Task(poses).inverted_slider_crank(((0.0, 0.0), a1), (s, (math.cos(th), math.sin(th))))
    assert syn.feasible and syn.modes == ["open"] * 3
    np.testing.assert_allclose(syn.input_angles, angles, atol=1e-12)
    return q, angles, syn


def assert_slot_through_swivel(slot, swivel, u):
    """The slot's two ends on the line through the swivel along ``u``."""
    for p in slot:
        d = p - np.array(swivel)
        assert abs(float(u[0] * d[1] - u[1] * d[0])) < 1e-9
    along = sorted(float((p - np.array(swivel)) @ u) for p in slot)
    assert along[0] < 0.0 < along[1]  # the swivel lies inside the drawn slot


# ---------------------------------------------------------------------------
# The CAD export


def test_dxf_holds_the_linkage_of_the_closed_form_at_its_poses(tmp_path, known):
    q, angles, syn = known
    doc = ezdxf.readfile(export.inverted_slider_crank_dxf(syn, tmp_path / "q.dxf", travel_samples=7))
    names = {layer.dxf.name for layer in doc.layers}
    assert {"SLOT", "SWIVEL_BLOCK", "PIVOTS", "LINKAGE_1", "LINKAGE_3", "POSES", "COUPLER_PATH", "TRAVEL",
            "DIMENSIONS"} <= names
    assert doc.header["$INSUNITS"] == 4  # mm by default
    for name in ("SLOT", "SWIVEL_BLOCK"):  # described, as the slider-crank's layers are
        assert export.LAYERS[name].description
    pivots = circles(doc, "PIVOTS")
    np.testing.assert_allclose(pivots, [q.pivot, q.swivel], atol=1e-12)
    slots, blocks = polylines(doc, "SLOT"), polylines(doc, "SWIVEL_BLOCK")
    assert len(slots) == len(blocks) == 3
    for k, t2 in enumerate(angles, start=1):
        a, theta3, f = closed_form(q, t2, "open")
        u = np.array([math.cos(theta3), math.sin(theta3)])
        crank, plate = polylines(doc, f"LINKAGE_{k}")
        np.testing.assert_allclose(crank, [q.pivot, a], atol=1e-9)
        np.testing.assert_allclose(plate[:2], [a, f], atol=1e-9)
        # The task's coupler point where the hand-made linkage put it (the pose).
        np.testing.assert_allclose(plate[2], a + POINT[0] * u + POINT[1] * np.array([-u[1], u[0]]), atol=1e-9)
        np.testing.assert_allclose(plate[2], syn.pose_at(t2, "open")[:2], atol=1e-12)
        # The core's joints agree with the closed form.
        np.testing.assert_allclose(np.array(q.joints(t2, "open")), [q.pivot, a, q.swivel, f], atol=1e-9)
        # The slot: through the swivel along theta3; the block centred on the swivel, along the slot.
        assert_slot_through_swivel(slots[k - 1], q.swivel, u)
        block = blocks[k - 1]
        np.testing.assert_allclose(block.mean(axis=0), q.swivel, atol=1e-12)
        side = block[1] - block[0]
        assert abs(float(side @ u)) == pytest.approx(float(np.linalg.norm(side)), rel=1e-12)
        # The offset: the pin is |e| from the slot's line.
        assert float(np.linalg.norm(a - f)) == pytest.approx(abs(q.offset), abs=1e-12)
    assert len(polylines(doc, "TRAVEL")) == 7
    for chain in polylines(doc, "TRAVEL"):  # A0 A F, the pin on the crank's circle
        assert float(np.linalg.norm(chain[1] - np.array(q.pivot))) == pytest.approx(q.crank, abs=1e-12)


def test_dimensions_are_the_linkage_lengths_and_the_stroke(tmp_path, known):
    q, angles, syn = known
    got = measurements(ezdxf.readfile(export.inverted_slider_crank(syn, tmp_path / "q.dxf")))
    # The stroke used, independently: the slot position sampled densely over the travel.
    ts = syn.travel_angles(20001)
    slots = [q.solve(float(t), "open").slot for t in ts]
    dense = max(slots) - min(slots)
    assert syn.stroke_used == pytest.approx(dense, abs=1e-6)
    for want in (q.crank, q.ground, abs(q.offset), math.hypot(*POINT), syn.stroke_used):
        assert min(abs(m - want) for m in got) < 1e-9, want
    # A linkage alone: its whole stroke between its slot limits.
    alone = measurements(ezdxf.readfile(export.inverted_slider_crank(q, tmp_path / "alone.dxf")))
    for want in (q.crank, q.ground, abs(q.offset), q.stroke):
        assert min(abs(m - want) for m in alone) < 1e-9, want


def test_svg_is_the_dxf_upright(tmp_path, known):
    q, _, syn = known
    doc = ezdxf.readfile(export.inverted_slider_crank(syn, tmp_path / "q.dxf", travel_samples=3))
    svg = export.inverted_slider_crank(syn, tmp_path / "q.svg", travel_samples=3)
    for layer in ("SLOT", "SWIVEL_BLOCK", "LINKAGE_1", "LINKAGE_2", "LINKAGE_3", "COUPLER_PATH", "TRAVEL", "POSES"):
        dxf, got = polylines(doc, layer), svg_paths(svg, layer)
        assert len(dxf) == len(got) > 0, layer
        for x, y in zip(dxf, got):
            np.testing.assert_allclose(y, x, atol=1e-12)
    marks = [(float(c.get("cx")), -float(c.get("cy"))) for c in svg_group(svg, "PIVOTS").findall(f"{SVG}circle")]
    np.testing.assert_allclose(marks, circles(doc, "PIVOTS"), atol=1e-12)
    dims = [float(g.get("data-measurement")) for g in svg_group(svg, "DIMENSIONS").findall(f"{SVG}g")
            if g.get("data-kind") == "aligned"]
    assert sorted(dims) == pytest.approx(sorted(measurements(doc)), abs=1e-12)


def test_a_linkage_alone_in_either_mode(tmp_path, known):
    q, _, _ = known
    for mode in ("open", "crossed"):
        doc = ezdxf.readfile(export.inverted_slider_crank(q, tmp_path / f"{mode}.dxf", 0.7, mode, units="in"))
        assert doc.header["$INSUNITS"] == 1
        a, theta3, f = closed_form(q, 0.7, mode)
        crank, coupler = polylines(doc, "LINKAGE_1")
        np.testing.assert_allclose(np.vstack([crank, coupler]), [q.pivot, a, a, f], atol=1e-9)
        (slot,) = polylines(doc, "SLOT")
        assert_slot_through_swivel(slot, q.swivel, np.array([math.cos(theta3), math.sin(theta3)]))
    # The default angle: the crank pointing away from the swivel.
    doc = ezdxf.readfile(export.inverted_slider_crank(q, tmp_path / "d.dxf"))
    away = math.atan2(-q.swivel[1], -q.swivel[0])
    np.testing.assert_allclose(polylines(doc, "LINKAGE_1")[0][1], closed_form(q, away, "open")[0], atol=1e-9)


@pytest.mark.parametrize("write, error, words", [
    (lambda q, syn, d: export.inverted_slider_crank(syn, d / "x.dxf", travel_samples=1),
     burmester.InvalidInputError, "travel_samples"),
    (lambda q, syn, d: export.inverted_slider_crank(q, d / "x.png"), burmester.InvalidInputError, ".dxf or .svg"),
    (lambda q, syn, d: export.inverted_slider_crank_svg(q, d / "x.dxf"), burmester.InvalidInputError, ".svg"),
    (lambda q, syn, d: export.inverted_slider_crank(q, d / "x.dxf", mode="sideways"),
     burmester.InvalidInputError, "sideways"),
    # The pin nearer the swivel than the offset: the slot does not reach it.
    (lambda q, syn, d: export.inverted_slider_crank(
        InvertedSliderCrank(crank=1.0, swivel=(1.2, 0.0), offset=0.5), d / "x.dxf", 0.0), burmester.AssemblyError, "nearer than the slot"),
    (lambda q, syn, d: export.inverted_slider_crank(q.pivot, d / "x.dxf"), TypeError, "InvertedSliderCrank"),
])
def test_export_errors_leave_no_file(tmp_path, known, write, error, words):
    q, _, syn = known
    with pytest.raises(error, match=words):
        write(q, syn, tmp_path)
    assert not list(tmp_path.iterdir())


def test_export_at_the_documented_maximum(tmp_path, known):
    q, angles, syn = known
    doc = ezdxf.readfile(export.inverted_slider_crank(syn, tmp_path / "max.dxf", path_samples=export.MAX_SAMPLES))
    # One leg a pose to the next, MAX_SAMPLES a crank turn, from pose to pose (the hand-made coupler point).
    legs = polylines(doc, "COUPLER_PATH")
    stops = np.array(syn.travel_stops)
    assert len(stops) == len(angles)
    assert [len(leg) for leg in legs] == [math.ceil(export.MAX_SAMPLES * abs(d) / (2 * math.pi)) + 1
                                          for d in np.diff(stops)]
    at_poses = np.array([q.coupler_point(float(t), POINT, "open") for t in stops])
    np.testing.assert_allclose([leg[0] for leg in legs], at_poses[:-1], atol=1e-9)
    np.testing.assert_allclose([leg[-1] for leg in legs], at_poses[1:], atol=1e-9)
    assert min(abs(m - syn.stroke_used) for m in measurements(doc)) < 1e-9
    for bad in (7, export.MAX_SAMPLES + 1):
        with pytest.raises(burmester.InvalidInputError, match="path_samples"):
            export.inverted_slider_crank(syn, tmp_path / "x.svg", path_samples=bad)
    with pytest.raises(burmester.InvalidInputError, match="travel_samples"):
        export.inverted_slider_crank(syn, tmp_path / "x.svg", travel_samples=export.MAX_SAMPLES + 1)


# ---------------------------------------------------------------------------
# The pictures and the animation


def test_notebook_pictures(known):
    q, _, syn = known
    for obj in (q, syn):
        png = obj._repr_png_()
        assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 1000
    assert pickle.loads(pickle.dumps(syn)) == syn and pickle.loads(pickle.dumps(q)) == q


def moving(anim):
    ax = anim._fig.axes[0]
    return {a.get_gid(): a for a in ax.get_children()}


def test_animation_through_the_poses(tmp_path, known):
    from PIL import Image

    q, angles, syn = known
    out = tmp_path / "q.gif"
    anim = plot.animate_inverted_slider_crank(syn, out, frames=6, fps=5, dpi=30, units="mm")
    with Image.open(out) as im:
        assert im.n_frames >= 8  # there and back
    arts = moving(anim)
    assert {"moving-linkage", "moving-linkage-slot", "moving-linkage-block", "moving-coupler", "coupler-curve",
            "pose-1"} <= set(arts)
    assert anim._fig.axes[0].get_xlabel() == "x [mm]"
    # The first frame: the linkage at pose 1 (the closed form), the slot through the swivel.
    anim._func(0)
    a, theta3, f = closed_form(q, angles[0], "open")
    np.testing.assert_allclose(np.array(arts["moving-linkage"].get_xydata()), [q.pivot, a, f], atol=1e-9)
    assert_slot_through_swivel(np.array(arts["moving-linkage-slot"].get_xydata()), q.swivel,
                               np.array([math.cos(theta3), math.sin(theta3)]))
    # The coupler plate A F P moves with it, P on pose 1; every pose and the coupler curve in view.
    np.testing.assert_allclose(arts["moving-coupler"].get_xy()[:3], [a, f, syn.pose_at(angles[0])[:2]], atol=1e-9)
    (x0, x1), (y0, y1) = anim._fig.axes[0].get_xlim(), anim._fig.axes[0].get_ylim()
    curve = np.array(arts["coupler-curve"].get_xydata())
    assert (x0 < curve[:, 0]).all() and (curve[:, 0] < x1).all() and (y0 < curve[:, 1]).all() and (curve[:, 1] < y1).all()
    # A linkage alone: over its crank's range.
    plot.animate_inverted_slider_crank(q, tmp_path / "alone.gif", "crossed", frames=5, dpi=20)
    with Image.open(tmp_path / "alone.gif") as im:
        assert im.n_frames == 5  # a full turn: one way
    swinging = InvertedSliderCrank(crank=2.0, swivel=(2.5, 0.0), offset=1.0)  # |g - r| < |e|: dead positions
    assert not swinging.turns_fully
    plot.animate_inverted_slider_crank(swinging, tmp_path / "swing.gif", frames=5, dpi=20)
    with Image.open(tmp_path / "swing.gif") as im:
        assert im.n_frames == 8  # between the dead positions and back


def test_animation_errors(tmp_path, known):
    q, _, syn = known
    with pytest.raises(burmester.InvalidInputError):
        plot.animate_inverted_slider_crank(syn, tmp_path / "x.gif", frames=plot.MAX_FRAMES + 1)
    with pytest.raises(burmester.InvalidInputError):
        plot.animate_inverted_slider_crank(syn, tmp_path / "x.png")
    with pytest.raises(burmester.InvalidInputError):
        plot.animate_inverted_slider_crank(q, tmp_path / "x.gif", "sideways")
    with pytest.raises(TypeError):
        plot.animate_inverted_slider_crank(q.pivot, tmp_path / "x.gif")
    # A synthesized one that cannot be driven through its poses in order.
    q2 = InvertedSliderCrank(crank=1.0, swivel=(2.5, 0.3), offset=0.2)
    # The crank meets them at 0.3, 1.5, 1.0, 2.0: in neither turning order (an order defect).
    task = Task([(*q2.coupler_point(t, POINT), q2.solve(t).theta3) for t in (0.3, 1.5, 1.0, 2.0)])
    _, a1, s, _ = q2.joints(0.3)
    th = q2.solve(0.3).theta3
    bad = task.inverted_slider_crank(((0.0, 0.0), a1), (s, (math.cos(th), math.sin(th))))
    assert not bad.feasible
    with pytest.raises(burmester.InvalidInputError, match="feasible"):
        plot.animate_inverted_slider_crank(bad, tmp_path / "x.gif")
    assert not list(tmp_path.iterdir())


def test_interrupted_animation_keeps_the_old_file(tmp_path, known, monkeypatch):
    """Ctrl-C at the third frame, two frames already written to the
    temporary file: the old file stays as it was, nothing else is left."""
    import matplotlib.animation as animation

    _, _, syn = known
    written = iter(range(2))
    grab = animation.PillowWriter.grab_frame

    def grab_then_interrupt(self, **kw):
        if next(written, None) is None:
            raise KeyboardInterrupt
        grab(self, **kw)

    monkeypatch.setattr(animation.PillowWriter, "grab_frame", grab_then_interrupt)
    (tmp_path / "q.gif").write_bytes(b"old")
    with pytest.raises(KeyboardInterrupt):
        plot.animate_inverted_slider_crank(syn, tmp_path / "q.gif", frames=6, dpi=20)
    assert (tmp_path / "q.gif").read_bytes() == b"old"
    assert [p.name for p in tmp_path.iterdir()] == ["q.gif"]


# ---------------------------------------------------------------------------
# burmester inverted


def test_the_cli_on_the_hood(tmp_path, capsys):
    """The hood of examples/hood.toml (mm, both pivots on the body below the
    closed hood, the limits' 40 degrees): the best inverted slider-crank,
    rebuilt from the JSON's pivots, is the one the export draws."""
    spec = taskfile.load(HOOD)
    assert main(["inverted", str(HOOD), "--pivot-grid", "12", "--top", "3", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["units"] == "mm" and len(doc["linkages"]) == 3 and doc["kept"] <= doc["built"]
    best = doc["linkages"][0]
    for p in (best["pivot"], best["swivel"]):
        assert spec.space.contains_pivot(tuple(p))
    assert best["min_transmission_deg"] >= spec.limits.min_transmission_deg
    assert best["size_ratio"] <= spec.limits.max_size_ratio
    q = spec.task.inverted_slider_crank((tuple(best["pivot"]), tuple(best["circle_point"])),
                                        (tuple(best["swivel"]), tuple(best["slot_direction"])))
    assert q.feasible and q.linkage.crank == pytest.approx(best["crank"], rel=1e-12)
    # The poses are reached: the hood's front edge and angle at each.
    for (x, y, a), t, m in zip(spec.task.poses, q.input_angles, q.modes):
        px, py, pa = q.pose_at(t, m)
        assert math.hypot(px - x, py - y) < 1e-9 and abs(math.remainder(pa - a, 2 * math.pi)) < 1e-9
    out = tmp_path / "hood.dxf"
    assert main(["inverted", str(HOOD), "--pivot-grid", "12", "--top", "1", "-o", str(out), "--travel", "4"]) == 0
    text = capsys.readouterr().out
    assert "crank pivot A0" in text and "wrote" in text
    dxf = ezdxf.readfile(out)
    assert dxf.header["$INSUNITS"] == 4
    np.testing.assert_allclose(circles(dxf, "PIVOTS"), [best["pivot"], best["swivel"]], atol=1e-12)
    assert len(polylines(dxf, "TRAVEL")) == 4
    for name, args in (("hood.png", []), ("hood.gif", ["--frames", "4", "--dpi", "30"])):
        assert main(["inverted", str(HOOD), "--pivot-grid", "12", "--top", "1", "-o", str(tmp_path / name),
                     *args]) == 0
        assert (tmp_path / name).stat().st_size > 1000
    # An existing file is kept without --force.
    assert main(["inverted", str(HOOD), "--pivot-grid", "12", "-o", str(out)]) == 2
    assert "exists" in capsys.readouterr().err


@pytest.mark.parametrize("args, words", [
    (["--swivel", "500", "500"], "swivel"),
    (["--frames", "5"], "--frames is for animations"),
    (["--travel", "5"], "--travel is for CAD exports"),
    (["--pivot-grid", "1"], "pivot-grid"),
    (["-o", "x.txt"], ".png"),
])
def test_the_cli_says_what_to_change(args, words, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["inverted", str(HOOD), *args]) == 2
    assert words in capsys.readouterr().err
    assert not list(tmp_path.iterdir())


def test_the_cli_search_at_its_documented_maximum(capsys):
    """MAX_CANDIDATES driving cranks times swivels are built; one more set is refused, saying what to change."""
    from burmester.cli import inverted

    spec = taskfile.load(HOOD)
    swivels = inverted.MAX_CANDIDATES // 24 ** 2  # the default pivot grid: 24 x 24 crank pivots, all in the box
    kept, built = inverted.candidates(spec, samples=swivels)
    assert built <= inverted.MAX_CANDIDATES and len(kept) > 0
    assert main(["inverted", str(HOOD), "--samples", str(swivels + 1)]) == 2
    assert "more than the 250000 candidates" in capsys.readouterr().err


def test_the_cli_on_five_poses_says_there_is_none(capsys):
    five = Path(__file__).resolve().parents[2] / "examples" / "five.toml"
    assert main(["inverted", str(five)]) == 2
    assert "no inverted slider" in capsys.readouterr().err
