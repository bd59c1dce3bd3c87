"""burmester.plot.explore: the interactive explorer, driven by synthetic mouse
and key events on the Agg backend. After every move the figure must show
exactly what the core computes for the moved task, from scratch."""

import gc
import math
import sys

import numpy as np
import pytest

mpl = pytest.importorskip("matplotlib")
mpl.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.backend_bases import KeyEvent, MouseEvent  # noqa: E402
from PIL import Image  # noqa: E402

import burmester  # noqa: E402
import burmester.plot as bp  # noqa: E402
from burmester import Grid, Task  # noqa: E402
from burmester import taskfile  # noqa: E402
from burmester.explorer import ANGLE_STEP_DEG, LIVE_SAMPLES, Explorer  # noqa: E402

POSES = [(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)]
C0 = (4.0, -1.0)
#: A small grid, so that each move is quick.
VIEW = Grid(-8.0, 8.0, -8.0, 8.0, 96, 96)


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


@pytest.fixture
def ex(monkeypatch):
    """An explorer of the example on VIEW. Its canvas counts the redraws it
    is asked for (``canvas.idle_draws``) instead of drawing each one: on Agg
    ``draw_idle`` draws at once, a quarter of a second a move."""
    e = bp.explore(Task(POSES), C0, VIEW)
    e.figure.canvas.draw()  # lay out, so that data and pixels map as on screen
    canvas = e.figure.canvas
    canvas.idle_draws = 0

    def count():
        canvas.idle_draws += 1

    monkeypatch.setattr(canvas, "draw_idle", count)
    return e


def mouse(ex, name, xy, button=1, **kwargs):
    """Send a mouse event at data point ``xy`` of the map's axes; returns it
    (its ``xdata``, ``ydata`` are where matplotlib puts the pointer)."""
    px, py = ex.ax_map.transData.transform(xy)
    event = MouseEvent(name, ex.figure.canvas, px, py, button=button, **kwargs)
    ex.figure.canvas.callbacks.process(name, event)
    return event


def drag(ex, start, end, steps=3):
    """Press at ``start``, move in ``steps`` to ``end``, release there;
    returns the last motion event."""
    mouse(ex, "button_press_event", start)
    last = None
    for t in np.linspace(0.0, 1.0, steps + 1)[1:]:
        p = (start[0] + t * (end[0] - start[0]), start[1] + t * (end[1] - start[1]))
        last = mouse(ex, "motion_notify_event", p)
    mouse(ex, "button_release_event", end)
    return last


def key(ex, k):
    ex.figure.canvas.callbacks.process("key_press_event", KeyEvent("key_press_event", ex.figure.canvas, k))


def by_gid(ax, gid):
    return [a for a in ax.get_children() if a.get_gid() == gid]


def image(ex):
    (img,) = by_gid(ex.ax_map, "branch-map")
    return np.asarray(img.get_array())


def assert_shows(ex, task, c0):
    """The map's image, curves, poles and handles are those of ``task`` and
    ``c0`` computed from scratch."""
    f = task.filemon(c0)
    free = f.branch_map(VIEW)
    smap = f.solution_map(VIEW)
    img = image(ex)
    assert img.shape == VIEW.shape
    assert np.array_equal(img > 0, free)  # bit for bit
    assert np.array_equal(img == 2, free & smap.acceptable)
    assert 0 < free.sum() < free.size
    for pose, conic in zip(f.extreme_poses, f.conics):
        drawn = [a.get_xydata() for a in by_gid(ex.ax_map, f"conic-{pose}")]
        expected = conic.polylines(*VIEW.extent)
        assert len(drawn) == len(expected) > 0
        for d, e in zip(drawn, expected):
            np.testing.assert_array_equal(d, e)
    finite = [p for p in task.poles if p.point is not None]  # a pure translation's is at infinity
    (poles,) = by_gid(ex.ax_map, "poles")
    np.testing.assert_array_equal(poles.get_xydata().reshape(-1, 2), np.reshape([p.point for p in finite], (-1, 2)))
    labels = {t.get_text(): t for t in ex.ax_map.texts}
    for p in task.poles:
        label = labels["P{}{}".format(*p.pair)]
        assert label.get_visible() == (p.point is not None)
        if p.point is not None:
            assert label.xy == p.point
    for k, (x, y, _) in enumerate(task.poses, start=1):
        (dot,) = by_gid(ex.ax_map, f"pose-{k}")
        np.testing.assert_array_equal(dot.get_xydata(), [[x, y]])
    (c,) = by_gid(ex.ax_map, "driven-pivot")
    np.testing.assert_array_equal(c.get_xydata(), [c0])


# ---------------------------------------------------------------------------
# Dragging


def test_opens_on_the_task_with_the_best_pivot(ex):
    task = Task(POSES)
    assert ex.task == task and ex.driven_center == C0
    assert ex.live is True and ex.error is None
    assert_shows(ex, task, C0)
    best = task.filemon(C0).solution_map(VIEW).best_pivots(1)[0]
    assert ex.driving_center == best.center
    assert ex.linkage() == best.linkage


def test_dragging_a_pose_moves_it_and_redraws_the_map(ex):
    before = image(ex).copy()
    last = drag(ex, (2.0, 0.5), (2.6, 0.9))
    x, y = last.xdata, last.ydata
    assert (x, y) == pytest.approx((2.6, 0.9), abs=1e-9)
    moved = [POSES[0], (x, y, POSES[1][2]), POSES[2]]
    assert ex.task.poses == moved
    assert ex.error is None
    assert_shows(ex, Task(moved), C0)
    assert not np.array_equal(image(ex), before)  # the map did change
    assert ex.figure.canvas.idle_draws == 3  # one redraw a motion
    ex.figure.canvas.draw()
    # The linkage is rebuilt for the moved task, with the same A0.
    assert ex.linkage() == Task(moved).filemon(C0).four_bar(ex.driving_center)
    assert ex.solution_map == Task(moved).filemon(C0).solution_map(VIEW)


def test_the_drag_method_sends_a_user_s_drag(ex):
    """Explorer.drag (the scripted pictures' drag) against this file's own
    event-by-event drag on a second explorer: the same poses, pivots and
    linkage, and one redraw a motion."""
    twin = bp.explore(Task(POSES), C0, VIEW)
    twin.figure.canvas.draw()
    ex.drag((2.0, 0.5), (2.6, 0.9), steps=3)
    drag(twin, (2.0, 0.5), (2.6, 0.9), steps=3)
    assert ex.figure.canvas.idle_draws == 3
    assert ex.task.poses == twin.task.poses != POSES
    ex.drag(ex.driving_center, (-5.0, 6.0))
    drag(twin, twin.driving_center, (-5.0, 6.0), steps=4)
    assert ex.driving_center == twin.driving_center == pytest.approx((-5.0, 6.0), abs=1e-9)
    assert ex.linkage() == twin.linkage()
    assert ex.error is None


def test_dragging_c0_moves_the_driven_pivot(ex):
    a0 = ex.driving_center
    last = drag(ex, C0, (4.5, -1.8))
    c0 = (last.xdata, last.ydata)
    assert c0 == pytest.approx((4.5, -1.8), abs=1e-9)
    assert ex.driven_center == c0
    assert ex.filemon == Task(POSES).filemon(c0)
    assert_shows(ex, Task(POSES), c0)
    assert ex.linkage().driven[0] == c0
    assert ex.driving_center == a0


def test_dragging_a0_changes_the_linkage_and_its_figures(ex):
    smap = ex.solution_map
    img = image(ex).copy()
    last = drag(ex, ex.driving_center, (-6.0, -5.0))
    a0 = (last.xdata, last.ydata)
    assert ex.driving_center == a0
    sfb = ex.linkage()
    expected = Task(POSES).filemon(C0).four_bar(a0)
    assert sfb == expected
    assert sfb.driving[0] == a0 == sfb.fourbar.input_pivot
    assert sfb.figures == expected.figures
    # The map does not depend on A0: not recomputed, not redrawn.
    assert ex.solution_map is smap
    assert np.array_equal(image(ex), img)
    (star,) = by_gid(ex.ax_map, "driving-pivot")
    np.testing.assert_array_equal(star.get_xydata(), [a0])
    # The figures in words, and the linkage drawn at the poses.
    (text,) = [t for t in ex.figure.texts if t.get_gid() == "figures"]
    fig = expected.figures
    words = text.get_text()
    assert fig.grashof in words
    assert f"min transmission {fig.min_transmission_deg:.1f} deg" in words
    assert ("branch-free" if fig.branch_free else "branch defect") in words
    # The verdict under the explorer's limits (issue 24: it said "feasible").
    flat = " ".join(words.split())
    assert ex.verdict() in flat
    assert ("not acceptable" in flat) == bool(burmester.pivots.violations(fig, ex.limits))
    for k, (theta, mode) in enumerate(zip(expected.input_angles, expected.modes), start=1):
        (chain,) = by_gid(ex.ax_linkage, f"linkage-{k}")
        np.testing.assert_allclose(chain.get_xydata(), expected.fourbar.joints(theta, mode or "open"))


def test_a_click_on_the_plane_puts_a0_there(ex):
    event = mouse(ex, "button_press_event", (-5.0, 6.0))
    mouse(ex, "button_release_event", (-5.0, 6.0))
    assert ex.driving_center == (event.xdata, event.ydata)
    assert ex.linkage() == Task(POSES).filemon(C0).four_bar((event.xdata, event.ydata))


def test_the_square_turns_the_pose(ex):
    x, y, a = POSES[2]
    tip = by_gid(ex.ax_map, "pose-angle-3")[0].get_xydata()[0]
    assert math.atan2(tip[1] - y, tip[0] - x) == pytest.approx(a)
    last = drag(ex, tip, (x - 0.3, y + 1.0))
    angle = ex.task.poses[2][2]
    assert angle == pytest.approx(math.atan2(last.ydata - y, last.xdata - x), abs=1e-12)
    assert ex.task.poses[2][:2] == (x, y)
    assert_shows(ex, Task([POSES[0], POSES[1], (x, y, angle)]), C0)


def test_scrolling_over_a_pose_turns_it(ex):
    mouse(ex, "scroll_event", POSES[0][:2], button="up", step=1)
    assert ex.task.poses[0][2] == pytest.approx(math.radians(ANGLE_STEP_DEG))
    mouse(ex, "scroll_event", POSES[0][:2], button="down", step=-3)
    assert ex.task.poses[0][2] == pytest.approx(-2 * math.radians(ANGLE_STEP_DEG))
    assert_shows(ex, Task([ex.task.poses[0], POSES[1], POSES[2]]), C0)
    # Away from the poses the wheel does nothing.
    mouse(ex, "scroll_event", (-6.0, 6.0), button="up", step=1)
    assert ex.task.poses[0][2] == pytest.approx(-2 * math.radians(ANGLE_STEP_DEG))


# ---------------------------------------------------------------------------
# Bad moves


def test_a_pure_translation_is_drawn_and_all_translations_are_refused(ex):
    good = drag(ex, (2.0, 0.5), (2.4, 0.7))
    # Turn pose 3 to pose 1's angle (0): a pure translation between them,
    # which the core takes (its pole is at infinity: no pole triangle).
    x3, y3, _ = ex.task.poses[2]
    mouse(ex, "button_press_event", by_gid(ex.ax_map, "pose-angle-3")[0].get_xydata()[0])
    mouse(ex, "motion_notify_event", (x3 + 1.0, y3))
    mouse(ex, "button_release_event", (x3 + 1.0, y3))
    assert ex.error is None and ex.task.poses[2][2] == pytest.approx(0.0, abs=1e-12)
    assert_shows(ex, ex.task, C0)
    assert [p.point is None for p in ex.task.poles] == [False, True, False]
    (triangle,) = by_gid(ex.ax_map, "pole-triangle")
    assert len(triangle.get_xydata()) == 0
    good_poses = ex.task.poses
    img = image(ex).copy()
    linkage = ex.linkage()
    # Then pose 2 to the same angle: every pose one angle, refused by the core.
    x, y, _ = good_poses[1]
    mouse(ex, "button_press_event", by_gid(ex.ax_map, "pose-angle-2")[0].get_xydata()[0])
    mouse(ex, "motion_notify_event", (x + 1.0, y))
    with pytest.raises(burmester.DegenerateError) as refused:
        Task([good_poses[0], (x, y, 0.0), good_poses[2]])
    assert ex.error is not None and "translation" in ex.error
    assert str(refused.value) in ex.error
    (status,) = [t for t in ex.figure.texts if t.get_gid() == "status"]
    assert status.get_text() == f"refused: {ex.error}"
    # Nothing moved, the handle included; the figure still draws.
    assert ex.task.poses == good_poses
    assert np.array_equal(image(ex), img)
    assert ex.linkage() == linkage
    tip = by_gid(ex.ax_map, "pose-angle-2")[0].get_xydata()[0]
    assert math.atan2(tip[1] - y, tip[0] - x) == pytest.approx(good_poses[1][2])
    ex.figure.canvas.draw()
    # Dragging on to a good angle goes on from there and clears the error.
    mouse(ex, "motion_notify_event", (x + 1.0, y + 0.5))
    mouse(ex, "button_release_event", (x + 1.0, y + 0.5))
    assert ex.error is None and status.get_text() == ""
    assert ex.task.poses[1][2] == pytest.approx(math.atan2(0.5, 1.0), abs=1e-12)
    assert good.xdata == ex.task.poses[1][0]


def test_c0_dragged_onto_a_pole_is_refused(ex):
    p12 = ex.task.poles[0].point
    drag(ex, C0, p12, steps=1)
    assert ex.error is not None
    assert ex.driven_center == C0
    assert_shows(ex, Task(POSES), C0)


def test_releasing_outside_the_axes_is_harmless(ex):
    mouse(ex, "button_press_event", (2.0, 0.5))
    inside = mouse(ex, "motion_notify_event", (2.3, 0.8))
    # Out of the map: into the linkage's axes, then off the figure.
    for name, (px, py) in (
        ("motion_notify_event", ex.ax_linkage.transAxes.transform((0.5, 0.5))),
        ("motion_notify_event", (-50.0, -50.0)),
        ("button_release_event", (-50.0, -50.0)),
    ):
        event = MouseEvent(name, ex.figure.canvas, px, py, button=1)
        assert event.inaxes is not ex.ax_map
        ex.figure.canvas.callbacks.process(name, event)
    moved = [POSES[0], (inside.xdata, inside.ydata, POSES[1][2]), POSES[2]]
    assert ex.task.poses == moved and ex.error is None
    assert_shows(ex, Task(moved), C0)
    # The drag is over: moving the mouse moves nothing.
    mouse(ex, "motion_notify_event", (5.0, 5.0))
    assert ex.task.poses == moved


def test_other_buttons_and_release_without_press_do_nothing(ex):
    state = (ex.task, ex.driven_center, ex.driving_center)
    mouse(ex, "button_release_event", (2.0, 0.5))
    mouse(ex, "button_press_event", (2.0, 0.5), button=3)
    mouse(ex, "motion_notify_event", (3.0, 3.0), button=3)
    mouse(ex, "button_release_event", (3.0, 3.0), button=3)
    assert (ex.task, ex.driven_center, ex.driving_center) == state


def test_a_big_grid_recomputes_on_release():
    big = Grid(-8.0, 8.0, -8.0, 8.0, 320, 320)
    assert big.size > LIVE_SAMPLES
    ex = bp.explore(Task(POSES), C0, big)
    assert ex.live is False
    ex.figure.canvas.draw()
    before = image(ex).copy()
    mouse(ex, "button_press_event", (2.0, 0.5))
    last = mouse(ex, "motion_notify_event", (2.5, 1.0))
    # While dragging: the handle follows, the task and the map wait.
    assert ex.task == Task(POSES)
    np.testing.assert_array_equal(by_gid(ex.ax_map, "pose-2")[0].get_xydata(), [[last.xdata, last.ydata]])
    assert np.array_equal(image(ex), before)
    mouse(ex, "button_release_event", (2.5, 1.0))
    moved = Task([POSES[0], (last.xdata, last.ydata, POSES[1][2]), POSES[2]])
    assert ex.task == moved
    assert np.array_equal(image(ex) > 0, moved.filemon(C0).branch_map(big))


# ---------------------------------------------------------------------------
# Keys, code, saving


def test_keys_and_methods(ex):
    start = (ex.task, ex.driven_center, ex.driving_center, ex.linkage())
    assert ex.move_pose(1, x=0.2, angle=0.1) is True
    assert ex.task.poses[0] == (0.2, 0.0, 0.1)
    assert ex.move_driven_center((4.2, -1.2)) is True
    assert ex.move_driving_center((-6.0, 5.0)) is True
    smap = ex.solution_map
    key(ex, "b")
    best = smap.best_pivots(1)[0]
    assert ex.driving_center == best.center and ex.linkage() == best.linkage
    key(ex, "r")
    assert (ex.task, ex.driven_center, ex.driving_center, ex.linkage()) == start
    assert_shows(ex, Task(POSES), C0)
    assert ex.move_pose(2, x=0.0, y=0.0, angle=0.0) is False  # pose 1 itself: refused
    assert ex.error and ex.task == Task(POSES)
    with pytest.raises(burmester.InvalidInputError, match="pose must be from 1 to 3"):
        ex.move_pose(4, x=1.0)


def test_explorer_lives_as_long_as_its_figure():
    fig = bp.explore(Task(POSES), C0, VIEW).figure  # the Explorer itself is dropped
    gc.collect()
    fig.canvas.draw()
    (ax,) = [a for a in fig.axes if any(c.get_gid() == "branch-map" for c in a.get_children())]
    px, py = ax.transData.transform((2.0, 0.5))
    qx, qy = ax.transData.transform((2.5, 1.0))
    for name, x, y in (("button_press_event", px, py), ("motion_notify_event", qx, qy),
                       ("button_release_event", qx, qy)):
        fig.canvas.callbacks.process(name, MouseEvent(name, fig.canvas, x, y, button=1))
    (dot,) = [c for c in ax.get_children() if c.get_gid() == "pose-2"]
    assert dot.get_xydata()[0] == pytest.approx((2.5, 1.0))


def test_save_writes_the_figure_and_the_task_file(ex, tmp_path):
    drag(ex, (2.0, 0.5), (2.4, 0.8))
    png = ex.save(tmp_path / "explorer.png", dpi=50)
    with Image.open(png) as im:
        w, h = ex.figure.get_size_inches() * 50
        assert im.size == (round(w), round(h))
        assert np.asarray(im.convert("L")).std() > 10
    assert ex.save(tmp_path / "explorer.pdf").read_bytes().startswith(b"%PDF")
    spec = taskfile.load(ex.save(tmp_path / "task.toml"))
    assert spec.driven_center == ex.driven_center and spec.view == VIEW and spec.limits == ex.limits
    for got, want in zip(spec.poses, ex.task.poses):
        assert got == pytest.approx(want, abs=1e-12)


def test_save_hands_the_linkage_to_burmester_export(ex, tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    drag(ex, (2.0, 0.5), (2.4, 0.8))
    sfb = ex.linkage()
    # The DXF read back: the fixed pivots of the linkage shown, the moved task's poses.
    doc = ezdxf.readfile(ex.save(tmp_path / "l.dxf"))
    msp = doc.modelspace()
    pivots = sorted(tuple(c.dxf.center)[:2] for c in msp.query('CIRCLE[layer=="PIVOTS"]'))
    assert np.allclose(pivots, sorted([sfb.driving[0], sfb.driven[0]]), rtol=0, atol=1e-12)
    poses = sorted(tuple(c.dxf.center)[:2] for c in msp.query('CIRCLE[layer=="POSES"]'))
    assert np.allclose(poses, sorted((x, y) for x, y, _ in ex.task.poses), rtol=0, atol=1e-12)
    # The SVG: one group per concept, the same names.
    import xml.etree.ElementTree as ET

    root = ET.parse(ex.save(tmp_path / "l.svg")).getroot()
    ids = {g.get("id") for g in root.iter("{http://www.w3.org/2000/svg}g")}
    assert {"PIVOTS", "POSES", "GROUND"} <= ids


def test_save_says_what_is_wrong(ex, tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "ezdxf", None)  # not installed
    with pytest.raises(ImportError, match=r"burmester\[plot\]"):
        ex.save(tmp_path / "l.dxf")
    with pytest.raises(burmester.InvalidInputError, match=r"\.png or \.pdf"):
        ex.save(tmp_path / "l.gif")
    with pytest.raises(burmester.InvalidInputError, match="does not exist"):
        ex.save(tmp_path / "missing" / "l.png")
    assert list(tmp_path.iterdir()) == []


def test_the_e_key_saves_to_export_to(tmp_path):
    ex = bp.explore(Task(POSES), C0, VIEW, export_to=tmp_path / "task.toml")
    key(ex, "e")
    assert taskfile.load(tmp_path / "task.toml").driven_center == C0
    (status,) = [t for t in ex.figure.texts if t.get_gid() == "status"]
    assert "saved" in status.get_text()
    no_target = bp.explore(Task(POSES), C0, VIEW)
    key(no_target, "e")
    assert "export_to" in no_target.error


def test_bad_arguments():
    four = Task(POSES + [(4.0, 2.0, 1.3)])
    with pytest.raises(burmester.InvalidInputError, match="needs a task of 3 poses"):
        bp.explore(four, C0)
    with pytest.raises(burmester.InvalidInputError, match="xmin < xmax"):
        bp.explore(Task(POSES), C0, (1.0, 0.0, 0.0, 1.0))
    with pytest.raises(TypeError, match="driven_center must be a point"):
        bp.explore(Task(POSES), "C0")
    assert isinstance(bp.explore(Task(POSES), C0, driving_center=(-6.0, -5.0), grid=(40, 30)), Explorer)


def test_readme_picture_script_runs(tmp_path):
    sys.path.insert(0, str(__import__("pathlib").Path(__file__).resolve().parents[2] / "examples"))
    try:
        import explorer_picture
    finally:
        sys.path.pop(0)
    out = explorer_picture.main(tmp_path / "explorer.png")
    with Image.open(out) as im:
        assert im.size[0] > 600 and np.asarray(im.convert("L")).std() > 10


def test_readme_explorer_example_runs(tmp_path, monkeypatch):
    from pathlib import Path

    readme = (Path(__file__).resolve().parents[2] / "README.md").read_text()
    blocks = [b.split("```")[0] for b in readme.split("```python\n")[1:]]
    (code,) = [b for b in blocks if "from burmester.plot import explore" in b]
    monkeypatch.chdir(tmp_path)
    scope = {}
    exec(compile(code, "README.md", "exec"), scope)
    ex = scope["ex"]
    assert isinstance(ex, Explorer)
    assert scope["sfb"] == Task(POSES).filemon(C0).four_bar(ex.driving_center)  # before the move
    moved = Task([POSES[0], (2.3, 0.3, POSES[1][2]), POSES[2]])
    assert ex.task == moved and ex.linkage() == moved.filemon(C0).four_bar(ex.driving_center)
    assert (tmp_path / "explorer.png").stat().st_size > 1000


IPYMPL_SESSION = """
import matplotlib
matplotlib.use("module://ipympl.backend_nbagg")
from matplotlib.backend_bases import MouseEvent
import burmester, burmester.plot as bp

task = burmester.Task({poses!r})
ex = bp.explore(task, {c0!r}, burmester.Grid(-8, 8, -8, 8, 64, 64))
canvas = ex.figure.canvas
print(type(canvas).__module__)
canvas.draw()

def drag(start, end):
    for name, xy in (("button_press_event", start), ("motion_notify_event", end),
                     ("button_release_event", end)):
        px, py = ex.ax_map.transData.transform(xy)
        canvas.callbacks.process(name, MouseEvent(name, canvas, px, py, button=1))

canvas.toolbar.pan()          # the toolbar's pan mode takes the mouse
drag((2.0, 0.5), (2.4, 0.8))
print(ex.task == task)
canvas.toolbar.pan()          # off again: the drag moves pose 2
drag((2.0, 0.5), (2.4, 0.8))
print([round(v, 9) for v in ex.task.poses[1]], ex.error)
"""


def test_works_on_the_jupyter_widget_canvas():
    """The ipympl canvas (``%matplotlib widget``) takes the same events; its
    toolbar's pan mode keeps the mouse from the handles."""
    pytest.importorskip("ipympl")
    import subprocess

    code = IPYMPL_SESSION.format(poses=POSES, c0=C0)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split("\n")[:3] == ["ipympl.backend_nbagg", "True", "[2.4, 0.8, 0.4] None"]


def _acceptable_but_for_transmission(m, limit_deg):
    """A driving pivot of map ``m`` that is branch-free and feasible, within
    the link ratio, but whose minimum transmission angle is below
    ``limit_deg`` (and above 20 degrees)."""
    mu = np.degrees(m.min_transmission_rad)
    ok = m.branch_free & (m.direction != 0) & m.one_circuit & (m.link_ratio <= 10)
    js, iis = np.nonzero(ok & (mu > 20) & (mu < limit_deg - 2))
    assert len(js), "no such pivot on the grid"
    return m.point(int(js[0]), int(iis[0]))


def test_the_footer_gives_the_verdict_under_the_limits():
    # A linkage that is feasible and branch-free but transmits worse than
    # the limit: the footer said "feasible", read as a pass.
    limits = burmester.DesignLimits(min_transmission_deg=35.0)
    e = bp.explore(Task(POSES), C0, VIEW, limits=limits)
    a0 = _acceptable_but_for_transmission(e.solution_map, 35.0)
    e.move_driving_center(a0)
    fig = e.linkage().figures
    assert fig.feasible and fig.branch_free and fig.min_transmission_deg < 35.0
    (text,) = [t for t in e.figure.texts if t.get_gid() == "figures"]
    words = " ".join(text.get_text().split())
    assert "not acceptable:" in words and f"transmission {fig.min_transmission_deg:.0f} < 35 deg" in words
    assert "feasible" not in words.replace("not acceptable", "")
    # Under a looser limit the same linkage is acceptable.
    e2 = bp.explore(Task(POSES), C0, VIEW, limits=burmester.DesignLimits(min_transmission_deg=15.0))
    e2.move_driving_center(a0)
    (text2,) = [t for t in e2.figure.texts if t.get_gid() == "figures"]
    assert "acceptable under the limits (transmission >= 15 deg, link ratio <= 10)" in " ".join(
        text2.get_text().split())


@pytest.mark.parametrize("width", [13.0, 8.0])
def test_the_footer_stays_inside_the_figure(width):
    # A linkage that misses several limits has the longest verdict.
    limits = burmester.DesignLimits(min_transmission_deg=80.0, max_link_ratio=1.5, input="crank")
    fig = plt.figure(figsize=(width, 6.2))
    e = bp.explore(Task(POSES), C0, VIEW, limits=limits, fig=fig)
    e.move_driving_center((-7.5, -7.5))
    e.figure.canvas.draw()
    renderer = e.figure.canvas.get_renderer()
    box = e.figure.bbox
    for t in e.figure.texts:
        if not t.get_text():
            continue
        b = t.get_window_extent(renderer)
        assert box.x0 <= b.x0 and b.x1 <= box.x1 and box.y0 <= b.y0 and b.y1 <= box.y1, (t.get_gid(), b, box)
    # Nor over the axes' labels.
    (text,) = [t for t in e.figure.texts if t.get_gid() == "figures"]
    top = text.get_window_extent(renderer).y1
    for ax in (e.ax_map, e.ax_linkage):
        assert top <= ax.get_tightbbox(renderer).y0 + 1.0
