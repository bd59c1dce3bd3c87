"""burmester.plot: what the pictures contain, checked on the rendered pixels and the artists."""

import functools
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

mpl = pytest.importorskip("matplotlib")
mpl.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import to_rgba  # noqa: E402
from PIL import Image  # noqa: E402

import burmester  # noqa: E402
import burmester.plot as bp  # noqa: E402
from burmester import Grid  # noqa: E402
from burmester.taskfile import example  # noqa: E402

DPI = 100


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


@pytest.fixture
def spec():
    return example()


@pytest.fixture
def f(spec):
    return spec.filemon()


def render(ax):
    """The figure's pixels (H, W, 3) as ints, drawn by Agg at DPI."""
    fig = ax.figure
    fig.set_dpi(DPI)
    fig.canvas.draw()
    return np.asarray(fig.canvas.buffer_rgba())[:, :, :3].astype(int)


def axes_pixels(ax, buf):
    """Rows, columns and data coordinates of the pixels inside the axes."""
    h = buf.shape[0]
    bb = ax.get_window_extent()
    cols = np.arange(math.ceil(bb.x0), math.floor(bb.x1))
    rows = np.arange(math.ceil(h - bb.y1), math.floor(h - bb.y0))
    c, r = np.meshgrid(cols, rows)
    r, c = r.ravel(), c.ravel()
    disp = np.column_stack([c + 0.5, h - (r + 0.5)])
    return r, c, ax.transData.inverted().transform(disp)


def rgb(color):
    return (np.array(to_rgba(color)[:3]) * 255).round().astype(int)


def cells(view, data):
    """The grid cell (j, i) each data point falls in."""
    i = np.floor((data[:, 0] - view.xmin) / (view.xmax - view.xmin) * view.nx).astype(int)
    j = np.floor((data[:, 1] - view.ymin) / (view.ymax - view.ymin) * view.ny).astype(int)
    return j.clip(0, view.ny - 1), i.clip(0, view.nx - 1)


def by_gid(ax, gid):
    return [a for a in ax.get_children() if a.get_gid() == gid]


def polyline_distance(p, poly):
    """Distance from point p to a polyline (n, 2)."""
    a, b = poly[:-1], poly[1:]
    ab = b - a
    t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-300), 0, 1)
    return float(np.min(np.hypot(*(a + t[:, None] * ab - p).T)))


# ---------------------------------------------------------------------------
# center_plane


def poles(task):
    return [p.point for p in task.poles]


def test_shaded_pixels_are_the_branch_map(spec, f):
    v = spec.view
    m = f.branch_map(v)
    ax = bp.center_plane(f, v)
    (img,) = by_gid(ax, "branch-map")
    assert np.array_equal(np.asarray(img.get_array()), m.astype(np.int8))
    assert tuple(img.get_extent()) == v.extent

    # Every pixel showing the shading's colours shows the map at that place.
    buf = render(ax)
    r, c, data = axes_pixels(ax, buf)
    px = buf[r, c]
    free = (px == rgb(bp.FREE_COLOR)).all(axis=1)
    defect = (px == rgb(bp.DEFECT_COLOR)).all(axis=1)
    shown = free | defect
    assert shown.mean() > 0.9  # the curves, points and labels cover the rest
    expected = m[cells(v, data)]
    assert np.mean(free[shown] == expected[shown]) > 0.999

    # With all else hidden (curves, labels, spines), the shaded fraction of
    # the axes is the map's.
    for a in ax.get_children():
        if a is not img:
            a.set_visible(False)
    buf = render(ax)
    r, c, _ = axes_pixels(ax, buf)
    shaded = (buf[r, c] == rgb(bp.FREE_COLOR)).all(axis=1).mean()
    assert abs(shaded - m.mean()) < 0.005, (shaded, m.mean())


def test_conics_pass_within_a_pixel_of_the_poles_and_c0(spec, f):
    ax = bp.center_plane(f, spec.view)
    render(ax)
    targets = poles(f.task) + [f.driven_center]
    to_px = ax.transData.transform
    for pose, conic in zip(f.extreme_poses, f.conics):
        lines = by_gid(ax, f"conic-{pose}")
        assert len(lines) == len(conic.polylines(*spec.view.extent)) >= 1
        polys = [to_px(ln.get_xydata()) for ln in lines]
        for p in targets:
            d = min(polyline_distance(to_px([p])[0], poly) for poly in polys)
            assert d < 1.0, (pose, p, d)
        # The drawn points are on the exact conic (distance in pixels).
        px_per_unit = to_px([(1, 0)])[0, 0] - to_px([(0, 0)])[0, 0]
        for ln in lines:
            xy = ln.get_xydata()
            assert max(conic.distance(tuple(q)) for q in xy) * px_per_unit < 0.05
    # One curve is a hyperbola: both branches are drawn, clipped to the view.
    kinds = {c.kind for c in f.conics}
    assert kinds == {"hyperbola", "ellipse"}
    xmin, xmax, ymin, ymax = spec.view.extent
    for ln in by_gid(ax, "conic-3") + by_gid(ax, "conic-1"):
        xy = ln.get_xydata()
        assert xy[:, 0].min() >= xmin - 1e-9 and xy[:, 0].max() <= xmax + 1e-9
        assert xy[:, 1].min() >= ymin - 1e-9 and xy[:, 1].max() <= ymax + 1e-9


def test_poles_triangle_circle_and_driven_pivot(f, spec):
    ax = bp.center_plane(f, spec.view)
    poles_ = np.array(poles(f.task))
    (pts,) = by_gid(ax, "poles")
    assert np.allclose(pts.get_xydata(), poles_)
    (tri,) = by_gid(ax, "pole-triangle")
    assert np.allclose(tri.get_xydata(), np.vstack([poles_, poles_[:1]]))
    (circ,) = by_gid(ax, "pole-circle")
    pc = f.task.pole_circle()
    assert np.allclose(circ.center, pc["center"]) and circ.radius == pytest.approx(pc["radius"])
    (c0,) = by_gid(ax, "driven-pivot")
    assert np.allclose(c0.get_xydata(), [f.driven_center])
    # The extended sides of the pole triangle lie in the defective region
    # (the paper's property 5): no sample of them is branch-free.
    for side in by_gid(ax, "pole-triangle-sides"):
        (x0, y0), (x1, y1) = side.get_xydata()
        ts = np.linspace(0.0, 1.0, 401)
        for t in ts:
            p = (x0 + t * (x1 - x0), y0 + t * (y1 - y0))
            if min(np.hypot(*(poles_ - p).T)) > 1e-6:
                assert not f.is_branch_free(p)


def test_overlays_acceptable_transmission_pivots(spec, f):
    v = Grid(-8.0, 8.0, -8.0, 8.0, 160, 120)
    xs, ys = v.cell_centers()
    X, Y = np.meshgrid(xs, ys)
    acceptable = X > 0.0                       # synthetic: the right half
    transmission = 10.0 * np.hypot(X, Y)       # synthetic: circles of radius level / 10
    pivots = [(-6.0, -6.0), (6.5, 7.0)]
    ax = bp.center_plane(
        f, v, acceptable=acceptable, transmission=transmission,
        transmission_levels=[20.0, 50.0], pivots=pivots,
    )
    m = f.branch_map(v)
    (img,) = by_gid(ax, "branch-map")
    cat = np.asarray(img.get_array())
    assert np.array_equal(cat == 2, m & acceptable)
    assert np.array_equal(cat == 1, m & ~acceptable)
    assert np.array_equal(cat == 0, ~m)

    # The darker shading is on screen exactly where the cells are acceptable and free.
    buf = render(ax)
    r, c, data = axes_pixels(ax, buf)
    px = buf[r, c]
    acc_px = (px == rgb(bp.ACCEPT_COLOR)).all(axis=1)
    free_px = (px == rgb(bp.FREE_COLOR)).all(axis=1)
    expected = cat[cells(v, data)]
    assert acc_px.sum() > 1000
    assert np.mean(expected[acc_px] == 2) > 0.999
    assert np.mean(expected[free_px] == 1) > 0.999

    (cs,) = by_gid(ax, "transmission")
    assert list(cs.levels) == [20.0, 50.0]
    for level, path in zip(cs.levels, cs.get_paths()):
        r_ = np.hypot(*path.vertices.T)
        assert len(r_) > 10 and np.allclose(r_, level / 10.0, atol=0.1)

    (stars,) = by_gid(ax, "pivots")
    assert np.allclose(stars.get_xydata(), pivots)


def test_overlay_shapes_are_checked(spec, f):
    v = Grid(-8.0, 8.0, -8.0, 8.0, 50, 40)
    with pytest.raises(ValueError, match="acceptable.*shape"):
        bp.center_plane(f, v, acceptable=np.zeros((50, 40), bool))
    with pytest.raises(ValueError, match="transmission.*shape"):
        bp.center_plane(f, v, transmission=np.zeros((10, 10)))
    free = f.branch_map(v)
    ax = bp.center_plane(f, v, free=free)  # a precomputed map sets the grid
    assert np.array_equal(np.asarray(by_gid(ax, "branch-map")[0].get_array()), free)
    # A view as four numbers: 400 samples along the longer side.
    (img,) = by_gid(bp.center_plane(f, (-8.0, 8.0, -4.0, 4.0)), "branch-map")
    assert np.asarray(img.get_array()).shape == (200, 400)
    with pytest.raises(ValueError, match="xmin < xmax"):
        bp.center_plane(f, (8.0, -8.0, -4.0, 4.0))


def test_all_defective_draws_no_curves():
    # C'k directions that do not lie in a half-plane: search a few driven centers.
    t = burmester.Task([(0, 0, 0), (1, 0, 2.0), (0, 1, 4.0)])
    for x in np.linspace(-3, 3, 13):
        for y in np.linspace(-3, 3, 13):
            try:
                f = t.filemon((x, y))
            except burmester.BurmesterError:
                continue
            if f.all_defective:
                ax = bp.center_plane(f, (-5, 5, -5, 5), (40, 40))
                assert not any(str(a.get_gid()).startswith("conic") for a in ax.get_children())
                assert not np.asarray(by_gid(ax, "branch-map")[0].get_array()).any()
                return
    pytest.skip("no all-defective driven center found in the search")


# ---------------------------------------------------------------------------
# circle_plane


def test_circle_plane_wedges_lines_and_image_poles(f):
    ax = bp.circle_plane(f)
    render(ax)
    (free,) = by_gid(ax, "free-wedge")
    (defect,) = by_gid(ax, "defect-wedge")
    to_px = ax.transData.transform
    xmin, xmax = ax.get_xlim()
    ymin, ymax = ax.get_ylim()
    rng = np.random.default_rng(7)
    lines = f.all_lines
    checked = 0
    for _ in range(400):
        p = (rng.uniform(xmin, xmax), rng.uniform(ymin, ymax))
        # skip points within a few pixels of a line (the polygons' edges)
        dists = [abs(d[0] * (p[1] - q[1]) - d[1] * (p[0] - q[0])) / math.hypot(*d) for q, d in lines]
        if min(dists) * (to_px([(1, 0)])[0, 0] - to_px([(0, 0)])[0, 0]) < 3:
            continue
        disp = to_px([p])[0]
        is_free = f.classify_circle_point(p) == "free"
        assert free.contains_point(disp) == is_free, p
        assert defect.contains_point(disp) == (not is_free), p
        checked += 1
    assert checked > 300
    # The image poles lie in the defective wedge (the paper's property 4).
    for p in f.task.image_poles():
        assert not free.contains_point(to_px([p])[0])
    # Each line passes within a pixel of C1 and of its C'k.
    c1 = to_px([f.driven_circle])[0]
    for k, ck in enumerate(f.fixed_pivot_images, start=1):
        (ln,) = by_gid(ax, f"line-{k}")
        seg = to_px(ln.get_xydata())
        assert polyline_distance(c1, seg) < 1.0
        assert polyline_distance(to_px([ck])[0], seg) < 1.0
        assert ln.get_linestyle() == ("--" if k == f.middle_pose else "-")
    (ip,) = by_gid(ax, "image-poles")
    assert np.allclose(ip.get_xydata(), f.task.image_poles())
    (ipc,) = by_gid(ax, "image-pole-circle")
    assert ipc.radius == pytest.approx(f.task.image_pole_circle()["radius"])


def test_wedges_are_the_core_sectors(f):
    free, defective = bp.filemon_wedges(f, 10.0)
    sectors = f.sectors
    assert len(free) == sum(s[2] for s in sectors) == 2
    assert len(free) + len(defective) == len(sectors) == 6
    assert sectors[-1][1] == pytest.approx(sectors[0][0] + 2 * math.pi)
    c1 = f.driven_circle
    for (a0, a1, is_free), poly in zip([s for s in sectors if s[2]] + [s for s in sectors if not s[2]],
                                        free + defective):
        mid = 0.5 * (a0 + a1)
        p = (c1[0] + math.cos(mid), c1[1] + math.sin(mid))
        assert (f.classify_circle_point(p) == "free") == is_free
        assert np.allclose(poly[0], c1) and np.allclose(poly[-1], c1)


def test_clip_line():
    seg = burmester.clip_line((0.0, 0.0), (1.0, 1.0), (-1.0, 2.0, -3.0, 0.5))
    assert np.allclose(seg, [(-1.0, -1.0), (0.5, 0.5)])
    assert burmester.clip_line((0.0, 5.0), (1.0, 0.0), (-1.0, 1.0, -1.0, 1.0)) is None
    assert np.allclose(burmester.clip_line((0.0, 0.5), (0.0, 2.0), (-1, 1, -1, 1)), [(0, -1), (0, 1)])
    assert burmester.clip_line((0.0, 0.0), (0.0, 0.0), (-1, 1, -1, 1)) is None
    with pytest.raises(burmester.InvalidInputError):
        burmester.clip_line((0.0, 0.0), (1.0, 0.0), (1, -1, -1, 1))
    assert not hasattr(bp, "clip_line") or bp.clip_line is burmester.clip_line


# ---------------------------------------------------------------------------
# linkage and animate

FREE_PIVOT = (-7.98, -5.18)     # branch-free for the example (a double rocker)
DEFECT_PIVOT = (0.0, 0.0)       # branch-defective for the example
ORDER_DEFECT_PIVOT = (-2.375, 4.125)  # branch-free, but no input direction passes 1 -> 2 -> 3


def test_linkage_reaches_the_poses(f):
    sfb = f.four_bar(FREE_PIVOT)
    ax = bp.linkage(sfb, task=f.task)
    a0, c0 = sfb.driving[0], sfb.driven[0]
    fb = sfb.fourbar
    for k, pose in enumerate(f.task.poses, start=1):
        (chain,) = by_gid(ax, f"linkage-{k}")
        o2, a, b, o4 = chain.get_xydata()
        assert np.allclose(o2, a0) and np.allclose(o4, c0)
        assert math.dist(o2, a) == pytest.approx(fb.crank)
        assert math.dist(a, b) == pytest.approx(fb.coupler)
        assert math.dist(b, o4) == pytest.approx(fb.rocker)
        (tri,) = by_gid(ax, f"coupler-{k}")
        assert np.allclose(tri.get_xy()[2], pose[:2], atol=1e-9)  # the coupler point at pose k
        marks = by_gid(ax, f"pose-{k}")
        flag = marks[0].get_xydata()
        assert np.allclose(flag[0], pose[:2])
        assert math.atan2(*(flag[1] - flag[0])[::-1]) == pytest.approx(math.remainder(pose[2], 2 * math.pi))
    curve = by_gid(ax, "coupler-curve")[0].get_xydata()
    for pose in f.task.poses:  # the coupler curve passes through the poses
        assert np.nanmin(np.hypot(*(curve - pose[:2]).T)) < 0.05


def test_drive_angles_hit_the_poses(f):
    sfb = f.four_bar(FREE_PIVOT)
    angles, idx = bp.drive_angles(sfb, 40)
    assert idx[0] == 0 and idx[2] == len(angles) - 1 and 0 < idx[1] < idx[2]
    steps = np.diff(angles)
    assert (steps > 0).all() or (steps < 0).all()
    # Along the core's travel: its direction, its stops.
    start, span = sfb.travel
    assert np.sign(steps[0]) == np.sign(span) == {"ccw": 1, "cw": -1}[sfb.figures.direction]
    assert [angles[i] for i in idx] == sfb.travel_stops
    assert angles[-1] == pytest.approx(start + span)
    # No travel: nothing to drive.
    with pytest.raises(burmester.AssemblyError, match="order"):
        bp.drive_angles(f.four_bar(ORDER_DEFECT_PIVOT))
    for k, i in enumerate(idx):
        x, y, a = sfb.pose_at(float(angles[i]), sfb.modes[k])
        px, py, pa = f.task.poses[k]
        assert (x, y) == pytest.approx((px, py), abs=1e-9)
        assert math.remainder(a - pa, 2 * math.pi) == pytest.approx(0.0, abs=1e-9)


def test_animate_writes_a_gif(tmp_path, f):
    sfb = f.four_bar(FREE_PIVOT)
    out = tmp_path / "linkage.gif"
    bp.animate(sfb, out, task=f.task, frames=12, fps=10, dpi=40)
    angles, _ = bp.drive_angles(sfb, 12)
    with Image.open(out) as im:
        assert im.n_frames == 2 * len(angles) - 2  # there and back
        assert im.info["duration"] == 100
        im.seek(0)
        first = np.asarray(im.convert("RGB")).copy()
        im.seek(len(angles) - 1)
        last = np.asarray(im.convert("RGB")).copy()
    assert (first != last).any()  # the linkage moved


def test_animate_refuses_what_it_cannot_drive(tmp_path, f):
    with pytest.raises(burmester.AssemblyError, match="branch defect"):
        bp.animate(f.four_bar(DEFECT_PIVOT), tmp_path / "x.gif")
    with pytest.raises(ValueError, match=r"\.gif or \.mp4"):
        bp.animate(f.four_bar(FREE_PIVOT), tmp_path / "x.avi")
    order = f.four_bar(ORDER_DEFECT_PIVOT)
    assert order.branch_free and order.figures.direction == "none" and order.travel is None
    with pytest.raises(burmester.AssemblyError, match="order"):
        bp.animate(order, tmp_path / "x.gif")
    assert not (tmp_path / "x.gif").exists()


# ---------------------------------------------------------------------------
# matplotlib is optional


def test_import_burmester_does_not_import_matplotlib():
    code = (
        "import sys, burmester, burmester.cli, burmester.taskfile, burmester.pivots; "
        "print('matplotlib' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


def test_plot_without_matplotlib_says_what_to_install():
    code = (
        "import sys; sys.modules['matplotlib'] = None\n"
        "try:\n    import burmester.plot\n"
        "except ImportError as e:\n    print(e)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert 'pip install "burmester[plot]"' in out.stdout


def test_readme_pictures_example_runs(tmp_path, monkeypatch):
    readme = (Path(__file__).resolve().parents[2] / "README.md").read_text()
    blocks = [b.split("```")[0] for b in readme.split("```python\n")[1:]]
    (code,) = [b for b in blocks if "import burmester.plot" in b]
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(bp, "animate", functools.partial(bp.animate, frames=8, dpi=40))  # quicker
    exec(compile(code, "README.md", "exec"), {})
    for name in ("center.png", "circle.png", "linkage.png", "linkage.gif"):
        assert (tmp_path / name).stat().st_size > 1000


@pytest.mark.parametrize(
    "kwargs, words",
    [
        ({"frames": 0}, "frames must be from 2 to 10000, got 0"),
        ({"fps": 0}, "fps must be from 1 to 240, got 0"),  # was ZeroDivisionError
        ({"dpi": 0}, "dpi must be from 1 to 2400, got 0"),
    ],
)
def test_animate_rejects_bad_work_parameters(tmp_path, f, kwargs, words):
    sfb = f.four_bar(FREE_PIVOT)
    with pytest.raises(burmester.InvalidInputError, match=words):
        bp.animate(sfb, tmp_path / "a.gif", **kwargs)
    with pytest.raises(TypeError, match="frames must be an int"):
        bp.drive_angles(sfb, 2.5)  # type: ignore[arg-type]
    assert not (tmp_path / "a.gif").exists()


def test_plot_errors_are_burmester_errors(tmp_path, f):
    sfb = f.four_bar(FREE_PIVOT)
    with pytest.raises(burmester.InvalidInputError, match="does not exist"):  # was FileNotFoundError
        bp.animate(sfb, tmp_path / "missing" / "a.gif")
    with pytest.raises(burmester.InvalidInputError, match=r"\.gif or \.mp4"):
        bp.animate(sfb, tmp_path / "a.png")
    with pytest.raises(burmester.InvalidInputError, match="xmin < xmax"):
        bp.center_plane(f, (1.0, 0.0, 0.0, 1.0))
    g = Grid(-1.0, 1.0, -1.0, 1.0, 5, 4)
    for name in ("free", "acceptable", "transmission"):
        with pytest.raises(burmester.InvalidInputError, match=rf"{name} must have the grid's shape \(ny, nx\) = \(4, 5\)"):
            bp.center_plane(f, g, **{name: np.zeros((5, 4))})
