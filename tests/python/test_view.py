"""The one view/grid parser (burmester._view) and the scene builder
(burmester._scene) of issue 25: every drawing and the atlas raise the same
error for the same bad view, and the scene holds the core's points."""

import math

import numpy as np
import pytest

import burmester
from burmester import _scene, _view

pytest.importorskip("matplotlib")
pytest.importorskip("contourpy")

import matplotlib  # noqa: E402

matplotlib.use("Agg")

from burmester import export  # noqa: E402
from burmester import plot as bp  # noqa: E402

POSES = [(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)]
FB = burmester.FourBar.from_pivots((0, 0), (4, 0), 1.5, 3.5, 3.0)


def pose(deg):
    """The coupler pose of the known crank-rocker at a crank angle (the README's)."""
    _, a, b, _ = FB.joints(math.radians(deg))
    phi = math.atan2(b[1] - a[1], b[0] - a[0])
    return (a[0] + math.cos(phi) - 1.5 * math.sin(phi), a[1] + math.sin(phi) + 1.5 * math.cos(phi), phi)


@pytest.mark.parametrize(
    "view, error, words",
    [
        ((1.0, 0.0, 0.0, 1.0), burmester.InvalidInputError, "xmin < xmax"),
        ((0.0, math.inf, 0.0, 1.0), burmester.InvalidInputError, "finite"),
        ((0.0, 1.0, 0.0), _view.ViewTypeError, "view must be"),
        ("everything", _view.ViewTypeError, "view must be"),
    ],
)
def test_every_drawing_says_the_same_about_a_bad_view(view, error, words, tmp_path):
    task = burmester.Task(POSES)
    f = task.filemon((4.0, -1.0))
    four = burmester.Task([pose(d) for d in (20, 70, 120, 170)])
    calls = [
        lambda: bp.center_plane(f, view),
        lambda: bp.circle_plane(f, view),
        lambda: bp.poses(task, view),
        lambda: bp.burmester_plane(four, view),
        lambda: export.plane(f, tmp_path / "a.svg", view),
        lambda: export.plane(f, tmp_path / "a.svg", view, plane="circle"),
        lambda: export.burmester_plane(four, tmp_path / "a.svg", view),
    ]
    messages = set()
    for call in calls:
        with pytest.raises(error, match=words) as e:
            call()
        assert isinstance(e.value, burmester.InvalidInputError) and isinstance(e.value, ValueError)
        messages.add(str(e.value))
    assert len(messages) == 1, messages  # one parser, one message
    if error is _view.ViewTypeError:  # what is not a view at all is also a TypeError (the atlas's grids)
        assert issubclass(error, TypeError)
        with pytest.raises(TypeError):
            burmester.pivot_atlas(task, (1, 2, 3), (0, 1, 0, 1, 4, 4))


def test_samples_are_checked_once_for_plot_and_export(tmp_path):
    f = burmester.Task(POSES).filemon((4.0, -1.0))
    for call in (lambda g: bp.center_plane(f, (-8, 8, -8, 8), grid=g),
                 lambda g: export.plane(f, tmp_path / "a.svg", (-8, 8, -8, 8), grid=g)):
        with pytest.raises(burmester.InvalidInputError, match="grid nx must be from 2 to 100000, got 1"):
            call((1, 5))
        with pytest.raises(TypeError, match="grid ny must be an int"):
            call((5, 2.5))
    g = _view.resample(burmester.Grid(0, 1, 0, 1, 3, 3), (20000, 2), "--grid", most=20000)
    assert (g.nx, g.ny, g.extent) == (20000, 2, (0.0, 1.0, 0.0, 1.0))
    with pytest.raises(burmester.InvalidInputError, match="--grid nx must be from 2 to 20000, got 20001"):
        _view.resample(g, (20001, 2), "--grid", most=20000)


def test_the_scene_holds_the_cores_points():
    """The pose-count choice is the scene's: four poses give the curve by
    crank order and Q_jk, five the Burmester curves and points, three the
    core's needs_poses; the points are the core's own."""
    four = burmester.Task([pose(d) for d in (20, 70, 120, 170)])
    sc = _scene.curve_scene(four, (-6, 12, -5, 8), (4.0, 0.0), "center")
    assert (sc.n_poses, sc.title, sc.curves, sc.burmester_points) == (4, "center-point curve", [], [])
    assert sc.driven == (4.0, 0.0) and sc.free_arcs and sc.order_arcs
    assert [q for q, _ in sc.coincidence] == [q.pair for q in four.coincidence_points() if q.center is not None]
    circle = _scene.curve_scene(four, None, (4.0, 0.0), "circle")
    assert circle.poles == [] and circle.driven is None and circle.construction is not None
    assert circle.construction.c1 == four.circle_point((4.0, 0.0))
    five = burmester.Task([pose(d) for d in (20, 70, 120, 170, 230)])
    sc5 = _scene.curve_scene(five, None, None, "center")
    assert sc5.title == "Burmester points" and [w for w, _ in sc5.curves] == ["1234", "1235"]
    assert sc5.burmester_points == [c for c, _ in five.burmester_points()] and sc5.order_arcs == []
    for task, plane in ((burmester.Task(POSES), "center"), (five, "circle")):
        with pytest.raises(burmester.InvalidInputError) as e:
            _scene.curve_scene(task, None, None, plane)
        assert e.value.cause == "needs_poses"
    words = [_scene.poses_scene(burmester.Task(POSES)).count_word, _scene.poses_scene(four).count_word,
             _scene.poses_scene(five).count_word]
    assert words == ["Three", "Four", "Five"]
    assert _scene.poses_scene(burmester.Task(POSES)).pole_triangle and not _scene.poses_scene(four).pole_triangle


def test_the_linkage_scene_is_the_linkage_at_its_poses():
    task = burmester.Task(POSES)
    f = task.filemon((4.0, -1.0))
    smap = f.solution_map(burmester.Grid(-8, 8, -8, 8, 40, 40))
    sfb = smap.best_pivots(1)[0].linkage
    sc = _scene.linkage_scene(sfb, task)
    assert (sc.a0, sc.c0) == (sfb.driving[0], sfb.driven[0])
    for (theta2, mode, at), p in zip(sc.at_poses, task.poses):
        assert at[:4] == sfb.fourbar.joints(theta2, mode or "open")
        assert math.dist(at.p, p[:2]) < 1e-9 * task.scale  # the coupler point reaches each pose
    assert sc.flag == pytest.approx(0.3 * min(sfb.fourbar.lengths))
    assert np.allclose(sc.poses, task.poses)
