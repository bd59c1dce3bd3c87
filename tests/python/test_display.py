"""Notebook display: the objects' ``_repr_png_`` pictures, what they show,
that they leave pyplot alone, and that matplotlib is imported only when a
picture is asked for."""

import io
import math
import subprocess
import sys

import numpy as np
import pytest

mpl = pytest.importorskip("matplotlib")
mpl.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402
from matplotlib.colors import to_rgb  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from PIL import Image  # noqa: E402

import burmester  # noqa: E402
import burmester._display as display  # noqa: E402
import burmester.plot as bp  # noqa: E402
from burmester import Grid, Task  # noqa: E402
from conftest import FOUR  # noqa: E402

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
POSES = [(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)]
C0 = (4.0, -1.0)
A0 = (-7.98, -5.18)  # a branch-free driving pivot (the README's)
GRID = Grid(-8.0, 8.0, -8.0, 8.0, 96, 96)


def make(name):
    task = Task(POSES)
    f = task.filemon(C0)
    return {
        "task": lambda: task,
        "task4": lambda: Task(POSES + [(4.0, 2.0, 1.3)]),
        "filemon": lambda: f,
        "fourbar": lambda: burmester.FourBar(ground=100.0, crank=40.0, coupler=120.0, rocker=80.0),
        "rocker": lambda: burmester.FourBar(ground=3, crank=2, coupler=1.5, rocker=1),
        "linkage": lambda: f.four_bar(A0),
        "driving-map": lambda: f.solution_map(GRID, min_transmission_deg=35),
        "driven-map": lambda: task.driven_solution_map(A0, GRID),
        "atlas": lambda: burmester.pivot_atlas(task, (-8, 8, -8, 8, 12, 12), (-8, 8, -8, 8, 32, 32)),
        "pairmap": lambda: Task(FOUR).pair_map(64),
        "cubic": lambda: Task(FOUR).center_point_curve(),
        "slider-crank": lambda: burmester.SliderCrank(crank=30.0, coupler=100.0, guide_point=(0.0, 10.0)),
        "synthesized-slider-crank": _synthesized_slider_crank,
        "slider-dyad": lambda: burmester.SliderDyad((1.0, 2.0), (0.6, 0.8)),
        "actuator": lambda: _strut()[1],
        "actuator-map": lambda: _strut()[0],
    }[name]()


def _synthesized_slider_crank():
    """A slider-crank synthesized back from three poses of a known one."""
    sc = burmester.SliderCrank(crank=1.0, coupler=3.0, guide_point=(0.0, 0.4))
    poses = [(*sc.coupler_point(t, (0.5, 0.7)), sc.solve(t).theta3 + 0.3) for t in (0.2, 1.0, 2.1)]
    _, a1, b1 = sc.joints(0.2)
    return Task(poses).slider_crank(((0.0, 0.0), a1), (b1, sc.guide))


def _strut():
    """An actuator map over the README's linkage and its best placement."""
    sfb = Task(POSES).filemon(C0).four_bar(A0)
    amap = sfb.actuator_map(-10.0, 10.0, -10.0, 10.0, 48, 48, max_stroke_ratio=2.5, min_transmission_deg=10)
    return amap, amap.best_placements(1)[0]



#: Colours each picture must contain (RGB of the library's palette).
COLOURS = {
    "task": [bp.CIRCLE_COLOR, bp.POLE_COLOR],
    "task4": [bp.POLE_COLOR],
    "filemon": [bp.FREE_COLOR, bp.POSE_COLORS[1], bp.POSE_COLORS[3]],
    "fourbar": [bp.POSE_COLORS[3]],
    "rocker": [bp.POSE_COLORS[3]],
    "linkage": [bp.POSE_COLORS[1], bp.POSE_COLORS[2], bp.POSE_COLORS[3]],
    "driving-map": [bp.FREE_COLOR, bp.ACCEPT_COLOR],
    "driven-map": [bp.FREE_COLOR, "#ff7f0e"],
    "atlas": ["#fde725"],  # viridis at 90 degrees, the colour bar's top
    "pairmap": [bp.FREE_COLOR, bp.ACCEPT_COLOR],
    "cubic": ["#1f77b4"],  # the first component's colour (C0)
    "slider-crank": [bp.POSE_COLORS[3]],
    "synthesized-slider-crank": [bp.POSE_COLORS[1], bp.POSE_COLORS[2], bp.POSE_COLORS[3]],
    "slider-dyad": [bp.POSE_COLORS[1]],
    "actuator": ["#2171b5", "#595959"],  # pose 1's linkage, the cylinder's body
    "actuator-map": ["#c7e9c0", "#41ab5d"],  # monotone, acceptable
}


def decode(png):
    with Image.open(io.BytesIO(png)) as im:
        assert im.format == "PNG"
        return np.asarray(im.convert("RGB")).astype(int)


def has_colour(rgb, colour):
    want = np.round(np.array(to_rgb(colour)) * 255).astype(int)
    return bool((np.abs(rgb - want).max(axis=2) <= 2).any())


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


@pytest.mark.parametrize("name", sorted(COLOURS))
def test_each_object_shows_its_picture(name):
    obj = make(name)
    png = obj._repr_png_()
    assert isinstance(png, bytes) and png.startswith(PNG_SIGNATURE)
    rgb = decode(png)
    # The size: the figure cut to its content, at the notebook resolution.
    fig = display.figure(display.drawer(obj))
    fig.canvas.draw()
    box = fig.get_tightbbox(fig.canvas.get_renderer()).padded(display.PAD_INCHES)
    h, w, _ = rgb.shape
    assert abs(w - box.width * display.DPI) <= 1 and abs(h - box.height * display.DPI) <= 1
    assert 150 <= h <= display.FIGSIZE[1] * display.DPI * 1.2
    # Not blank, and drawn in the library's colours.
    assert rgb.std() > 20
    for colour in COLOURS[name]:
        assert has_colour(rgb, colour), colour


def test_pictures_are_the_plot_functions_drawn_the_same_way():
    """The linkage's picture is :func:`burmester.plot.linkage` on an Agg
    figure of the notebook size, cut to its content; the Filemon
    construction's is :func:`center_plane`'s."""
    f = Task(POSES).filemon(C0)
    for obj, draw in ((f.four_bar(A0), lambda ax: bp.linkage(f.four_bar(A0), ax=ax)),
                      (f, lambda ax: bp.center_plane(f, ax=ax))):
        fig = Figure(figsize=display.FIGSIZE, dpi=display.DPI)
        FigureCanvasAgg(fig)
        draw(fig.add_subplot())
        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=display.DPI, bbox_inches="tight", pad_inches=display.PAD_INCHES)
        assert np.array_equal(decode(obj._repr_png_()), decode(buf.getvalue()))


def test_task_picture_shows_the_poses_and_poles():
    task = Task(POSES)
    ax = bp.poses(task)
    (poles,) = [a for a in ax.get_children() if a.get_gid() == "poles"]
    np.testing.assert_array_equal(poles.get_xydata(), [p.point for p in task.poles])
    dots = [a.get_xydata() for a in ax.get_children() if a.get_gid() == "poses" and len(a.get_xydata()) == 1]
    np.testing.assert_array_equal(np.vstack(dots), [p[:2] for p in POSES])
    assert ax.get_title() == "Three poses and their poles"
    assert [a for a in ax.get_children() if a.get_gid() == "pole-circle"]
    # Four poses, 3 and 4 a pure translation: their pole is at infinity, named in the title.
    four = Task(POSES + [(4.0, 2.0, 1.1)])
    ax = bp.poses(four)
    (poles,) = [a for a in ax.get_children() if a.get_gid() == "poles"]
    np.testing.assert_array_equal(poles.get_xydata(), [p.point for p in four.poles[:5]])
    assert ax.get_title() == "Four poses and their poles (at infinity: P34)"
    assert decode(four._repr_png_()).std() > 20


def test_four_bar_picture_shows_the_joints():
    fb = make("rocker")
    (lo, hi), = fb.input_range[:1]
    ax = bp.four_bar(fb)
    (chain,) = [a for a in ax.get_children() if a.get_gid() == "linkage"]
    theta = lo + 0.5 * ((hi - lo) % (2 * np.pi))  # the middle of the input's arc
    np.testing.assert_allclose(chain.get_xydata(), fb.joints(theta))
    ax2 = bp.four_bar(fb, 0.3, "crossed")
    (chain2,) = [a for a in ax2.get_children() if a.get_gid() == "linkage"]
    np.testing.assert_allclose(chain2.get_xydata(), fb.joints(0.3, "crossed"))
    with pytest.raises(burmester.AssemblyError):
        bp.four_bar(fb, np.pi)


def test_map_pictures_show_the_map():
    smap = make("driving-map")
    ax = bp.solution_map(smap, pivots=2)
    (img,) = [a for a in ax.get_children() if a.get_gid() == "branch-map"]
    a = np.asarray(img.get_array())
    assert np.array_equal(a > 0, smap.branch_free) and np.array_equal(a == 2, smap.branch_free & smap.acceptable)
    (stars,) = [c for c in ax.get_children() if c.get_gid() == "pivots"]
    np.testing.assert_array_equal(stars.get_xydata(), [p.center for p in smap.best_pivots(2)])
    driven = make("driven-map")
    ax = bp.solution_map(driven)
    (img,) = [c for c in ax.get_children() if c.get_gid() == "branch-map"]
    assert np.array_equal(np.asarray(img.get_array()) > 0, driven.branch_free)
    (a0,) = [c for c in ax.get_children() if c.get_gid() == "driving-pivot"]
    np.testing.assert_array_equal(a0.get_xydata(), [A0])
    atlas = make("atlas")
    ax = bp.atlas(atlas)
    (img,) = [c for c in ax.get_children() if c.get_gid() == "best-transmission"]
    np.testing.assert_array_equal(np.ma.filled(img.get_array(), np.nan), atlas.best_transmission_deg)


def test_pictures_leave_pyplot_alone():
    fig = plt.figure()
    before = (plt.get_fignums(), plt.gcf(), mpl.get_backend())
    for name in COLOURS:
        make(name)._repr_png_()
    assert (plt.get_fignums(), plt.gcf(), mpl.get_backend()) == before
    assert plt.gcf() is fig


def test_ipython_shows_the_picture():
    ip = pytest.importorskip("IPython.core.formatters")
    png = ip.PNGFormatter()
    sfb = make("linkage")
    assert png(sfb) == sfb._repr_png_()
    assert png(make("atlas")).startswith(PNG_SIGNATURE)


def test_cubic_picture_draws_every_component_in_its_frame():
    curve = make("cubic")
    ax = display.cubic(curve, Figure().add_subplot())
    view = display.cubic_view(curve)
    assert ax.get_xlim() == view[:2] and ax.get_ylim() == view[2:]
    lines = [ln.get_xydata() for ln in ax.get_lines()]
    want = curve.polylines(*view)
    assert len(lines) == len(want) >= 1
    for got, line in zip(lines, want):
        np.testing.assert_array_equal(got, line)
        assert max(abs(curve(tuple(p))) for p in got[:: max(1, len(got) // 50)]) < 1e-9
    # The view is the frame the cubic is kept in: the poles of the task lie in it.
    for p in Task(FOUR).poles:
        if p.point is not None and math.dist(p.point, (0, 0)) < 5:
            assert view[0] < p.point[0] < view[1] and view[2] < p.point[1] < view[3]


def test_pair_map_picture_is_the_plot_functions():
    pmap = make("pairmap")
    fig = Figure(figsize=display.FIGSIZE, dpi=display.DPI)
    FigureCanvasAgg(fig)
    bp.pair_map(pmap, ax=fig.add_subplot())
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=display.DPI, bbox_inches="tight", pad_inches=display.PAD_INCHES)
    assert np.array_equal(decode(pmap._repr_png_()), decode(buf.getvalue()))


def test_no_picture_for_other_objects():
    with pytest.raises(TypeError, match="no picture for a Grid"):
        display.drawer(GRID)


# ---------------------------------------------------------------------------
# Lazy: matplotlib only when a picture is asked for


def run(code):
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return out.stdout.split()


def test_import_burmester_does_not_import_matplotlib_until_a_picture_is_asked_for():
    code = (
        "import sys, burmester\n"
        f"t = burmester.Task({POSES!r}); f = t.filemon({C0!r}); s = f.four_bar({A0!r})\n"
        "print('matplotlib' in sys.modules, 'burmester._display' in sys.modules)\n"
        "r = (repr(t), repr(f), repr(s))\n"
        "print('matplotlib' in sys.modules)\n"
        "png = s._repr_png_()\n"
        "print('matplotlib' in sys.modules, png[:8] == b'\\x89PNG\\r\\n\\x1a\\n')\n"
    )
    assert run(code) == ["False", "False", "False", "True", "True"]


def test_without_matplotlib_the_pictures_are_none():
    code = (
        "import sys; sys.modules['matplotlib'] = None\n"
        "import burmester\n"
        f"t = burmester.Task({POSES!r}); f = t.filemon({C0!r})\n"
        f"objs = [t, f, f.four_bar({A0!r}), f.four_bar({A0!r}).fourbar, f.solution_map(-8, 8, -8, 8, 8, 8),\n"
        "        burmester.pivot_atlas(t, (-8, 8, -8, 8, 4, 4), (-8, 8, -8, 8, 8, 8))]\n"
        "print(*[o._repr_png_() is None for o in objs])\n"
    )
    assert run(code) == ["True"] * 6
