"""Three-pose tasks with a pure translation between two poses (a pole at
infinity): the Python surface, the pictures and the CLI."""

import math

import numpy as np
import pytest

import burmester
from burmester import DegenerateError, Grid, Task
from conftest import circumcenter, task_toml

# Poses 1 and 2 have one angle: a pure translation by (2, 0.5).
TRANSLATED = [(0.0, 0.0, 0.3), (2.0, 0.5, 0.3), (3.0, 2.0, 1.1)]
C0 = (4.0, -1.0)


def carry(poses, k, z):
    """``D_1k(z)``, written here from the poses."""
    a = poses[k][2] - poses[0][2]
    c, s = math.cos(a), math.sin(a)
    dx, dy = z[0] - poses[0][0], z[1] - poses[0][1]
    return (poses[k][0] + c * dx - s * dy, poses[k][1] + s * dx + c * dy)


def test_a_translation_is_a_task_whose_pole_is_a_direction():
    t = Task(TRANSLATED)
    p12 = t.poles[0]
    assert p12.pair == (1, 2) and p12.at_infinity and p12.point is None
    dx, dy = p12.direction
    assert abs(dx * 2.0 + dy * 0.5) < 1e-12  # perpendicular to the translation
    assert all(p.point is not None for p in t.poles[1:])
    # The scale: the largest distance between pose positions and finite poles.
    pts = [p[:2] for p in TRANSLATED] + [p.point for p in t.poles[1:]]
    assert t.scale == pytest.approx(max(math.dist(a, b) for a in pts for b in pts), rel=1e-15)
    # What needs three finite poles says which pair is the translation.
    for call in (t.pole_circle, t.image_pole_circle, t.image_poles, t.pole_triangle_angles):
        with pytest.raises(DegenerateError) as e:
            call()
        assert (e.value.cause, e.value.i, e.value.j) == ("pure_translation", 1, 2)
        assert "pole triangle" in str(e.value)


def test_all_translations_are_refused():
    with pytest.raises(DegenerateError) as e:
        Task([(0.0, 0.0, 0.3), (2.0, 0.5, 0.3), (3.0, 2.0, 0.3)])
    assert e.value.cause == "all_translations"
    assert "parallelogram" in str(e.value)


def test_dyads_built_by_hand_come_back():
    t = Task(TRANSLATED)
    rng = np.random.default_rng(7)
    zs = rng.uniform(-6.0, 6.0, size=(200, 2))
    centers = np.array([circumcenter(z, carry(TRANSLATED, 1, z), carry(TRANSLATED, 2, z)) for z in zs])
    keep = np.hypot(centers[:, 0], centers[:, 1]) < 1e4
    zs, centers = zs[keep], centers[keep]
    got, ok = t.center_points(zs)
    assert ok.all()
    np.testing.assert_allclose(got, centers, atol=1e-8)
    back, ok = t.circle_points(centers)
    assert ok.all()
    np.testing.assert_allclose(back, zs, atol=1e-8)
    for g in centers[:20]:
        center, circle = t.dyad(tuple(g))
        radii = [math.dist(center, carry(TRANSLATED, k, circle)) for k in range(3)]
        assert max(radii) - min(radii) < 1e-9 * max(radii)


def test_branch_maps_agree_with_the_built_linkages():
    t = Task(TRANSLATED)
    f = t.filemon(C0)
    g = Grid(-8.0, 10.0, -8.0, 10.0, 40, 40)
    conic = f.branch_map(g, method="conic")
    direct = f.branch_map(g, method="direct")
    simulate = f.branch_map(g, method="simulate")
    checked = 0
    xs, ys = g.cell_centers()
    for j, y in enumerate(ys):
        for i, x in enumerate(xs):
            p = (float(x), float(y))
            try:
                fb = f.four_bar(p)
            except burmester.BurmesterError:
                continue
            if abs(f.margin(p)) < 1e-6:  # within rounding of a curve
                continue
            built = fb.branch_free
            assert conic[j, i] == built and direct[j, i] == built, p
            # Driving the linkage also sees the circuit defect: only stricter.
            assert simulate[j, i] == built or (built and not simulate[j, i]), p
            checked += 1
    assert checked > 1000
    assert conic.any() and not conic.all()


def test_the_solution_map_and_margin_work():
    f = Task(TRANSLATED).filemon(C0)
    g = Grid(-8.0, 10.0, -8.0, 10.0, 48, 48)
    m = f.solution_map(g)
    np.testing.assert_array_equal(m.branch_free, f.branch_map(g))
    assert m.valid.sum() > 1000
    assert (m.acceptable <= m.branch_free).all()
    assert m.acceptable.any()
    j, i = np.argwhere(m.acceptable)[0]
    xs, ys = g.cell_centers()
    assert f.margin((float(xs[i]), float(ys[j]))) > 0.0
    assert f.four_bar((float(xs[i]), float(ys[j]))).branch_free


TASK_FILE = "\n" + task_toml([(0.0, 0.0, 17.0), (2.0, 0.5, 17.0), (3.0, 2.0, 63.0)], driven=(4.0, -1.0),
                              x=(-8.0, 10.0), y=(-8.0, 10.0), grid=(120, 120))


def test_the_cli_draws_a_task_with_a_translation(tmp_path):
    pytest.importorskip("matplotlib")
    from burmester.cli import main

    task = tmp_path / "translated.toml"
    task.write_text(TASK_FILE)
    png = tmp_path / "map.png"
    assert main(["map", str(task), "-o", str(png)]) == 0
    assert png.stat().st_size > 1000


def test_the_pictures_draw_what_exists():
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    from burmester import plot

    f = Task(TRANSLATED).filemon(C0)
    ax = plot.center_plane(f, (-8.0, 10.0, -8.0, 10.0), grid=(60, 60))
    gids = {a.get_gid() for a in ax.get_children()}
    assert {"branch-map", "poles", "driven-pivot"} <= gids
    assert "pole-triangle" not in gids and "pole-circle" not in gids
    ax = plot.circle_plane(f)
    gids = {a.get_gid() for a in ax.get_children()}
    assert "image-poles" not in gids and "fixed-pivot-images" in gids
