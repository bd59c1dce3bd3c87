"""The CAD export: DXF read back with ezdxf, SVG with ElementTree, checked
against the core's model (joints, poses, poles, conics, branch maps)."""

import math
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import burmester
from burmester import Grid
from burmester.cli import main

ezdxf = pytest.importorskip("ezdxf")
pytest.importorskip("contourpy")
export = pytest.importorskip("burmester.export")

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SVG = "{http://www.w3.org/2000/svg}"
#: A branch-free driving pivot of the example (a double-rocker; its input
#: rocks in two arcs).
PIVOT = (-7.98, -5.18)
GRID = Grid(-8, 8, -8, 8, 120, 120)


# ---------------------------------------------------------------------------
# Reading the files back


def polylines(doc, layer):
    """The LWPOLYLINEs of a layer: ``[(points (n, 2), closed)]``, in file order."""
    return [
        (np.array(list(e.get_points("xy")), dtype=float), bool(e.closed))
        for e in doc.modelspace().query(f'LWPOLYLINE[layer=="{layer}"]')
    ]


def circles(doc, layer):
    """The centers and radii of a layer's CIRCLEs."""
    return [(np.array(e.dxf.center)[:2], e.dxf.radius) for e in doc.modelspace().query(f'CIRCLE[layer=="{layer}"]')]


def texts(doc):
    return sorted(e.dxf.text for e in doc.modelspace().query('TEXT[layer=="TEXT"]'))


def layers(doc):
    return {layer.dxf.name for layer in doc.layers} - {"0", "Defpoints"}


def svg_groups(path):
    """``{id: <g> element}`` of an SVG file's layers (the root's groups), and its root."""
    root = ET.parse(path).getroot()
    assert root.tag == f"{SVG}svg"
    return {g.get("id"): g for g in root.findall(f"{SVG}g")}, root


def svg_rings(d):
    """Path data ``M x y L x y ... [Z]`` back to model coordinates: ``[(n, 2)]``,
    through the documented transform (model ``(x, y)`` is at SVG ``(x, -y)``)."""
    rings = []
    for part in d.split("M")[1:]:
        pts = part.replace("Z", "").split("L")
        xy = np.array([[float(v) for v in p.split()] for p in pts])
        rings.append(np.column_stack([xy[:, 0], -xy[:, 1]]))
    return rings


def close(a, b, tol=1e-9):
    return np.allclose(np.asarray(a, dtype=float), np.asarray(b, dtype=float), rtol=0.0, atol=tol)


def find(items, first=None, last=None, n=None):
    """The one polyline with the given first/last vertex and vertex count."""
    hits = [
        pts for pts, _ in items
        if (first is None or close(pts[0], first)) and (last is None or close(pts[-1], last))
        and (n is None or len(pts) == n)
    ]
    assert len(hits) == 1, hits
    return hits[0]


def dimension_points(doc):
    """The corners of the box around the DIMENSION entities as drawn (their
    lines, arrows and texts: ezdxf's bounding box of their blocks)."""
    from ezdxf import bbox

    dims = doc.modelspace().query("DIMENSION")
    if not len(dims):
        return []
    box = bbox.extents(dims, fast=True)
    return [np.array(box.extmin)[:2], np.array(box.extmax)[:2]]


def all_points(doc):
    pts = [pts for layer in layers(doc) for pts, _ in polylines(doc, layer)]
    pts += [c[None, :] for layer in layers(doc) for c, _ in circles(doc, layer)]
    pts += [p[None, :] for p in dimension_points(doc)]
    return np.vstack(pts)


def check_valid(doc):
    """ezdxf's audit finds nothing to fix."""
    auditor = doc.audit()
    assert not auditor.has_errors and not auditor.has_fixes, [str(e) for e in auditor.errors + auditor.fixes]


def check_extent(doc):
    """``$LIMMIN/$LIMMAX`` = ``$EXTMIN/$EXTMAX``, around everything drawn, by a small margin."""
    lo, hi = np.array(doc.header["$LIMMIN"]), np.array(doc.header["$LIMMAX"])
    assert close(doc.header["$EXTMIN"][:2], lo) and close(doc.header["$EXTMAX"][:2], hi)
    pts = all_points(doc)
    assert (pts >= lo - 1e-9).all() and (pts <= hi + 1e-9).all()
    size = float(max(hi - lo))
    assert (pts.min(axis=0) - lo).max() <= 0.05 * size and (hi - pts.max(axis=0)).max() <= 0.05 * size
    return lo, hi


def inside_even_odd(rings, points):
    """Even-odd containment of points in a set of rings (outer boundaries and holes)."""
    from matplotlib.path import Path as MplPath

    inside = np.zeros(len(points), dtype=bool)
    for ring in rings:
        inside ^= MplPath(ring).contains_points(points)
    return inside


# ---------------------------------------------------------------------------
# The linkage


@pytest.fixture
def sfb(f):
    return f.four_bar(PIVOT)


LINKAGE_LAYERS = {"GROUND", "PIVOTS", "LINKAGE_1", "LINKAGE_2", "LINKAGE_3", "POSES", "COUPLER_CURVE",
                  "COUPLER_PATH", "TRAVEL", "DIMENSIONS", "TEXT"}


def test_linkage_dxf_holds_the_cores_linkage_at_each_pose(tmp_path, task, sfb):
    out = tmp_path / "l.dxf"
    assert export.linkage_dxf(sfb, out, task=task, travel_samples=5) == out
    doc = ezdxf.readfile(out)
    assert layers(doc) == LINKAGE_LAYERS
    assert doc.header["$INSUNITS"] == 4 and doc.header["$MEASUREMENT"] == 1  # mm, metric
    fb = sfb.fourbar
    a0, c0 = sfb.driving[0], sfb.driven[0]
    centers = [c for c, _ in circles(doc, "PIVOTS")]
    assert len(centers) == 2 and close(centers[0], a0) and close(centers[1], c0)
    assert close(find(polylines(doc, "GROUND")), [a0, c0])
    for k, (theta2, mode, pose) in enumerate(zip(sfb.input_angles, sfb.modes, task.poses), start=1):
        items = polylines(doc, f"LINKAGE_{k}")
        assert len(items) == 3
        _, a, b, _ = fb.joints(theta2, mode)
        crank = find(items, first=a0, n=2)
        assert close(crank[1], a)
        rocker = find(items, last=c0, n=2)
        assert close(rocker[0], b)
        coupler = find(items, n=3)
        # The coupler triangle A B P, closed; P is the task's pose: the linkage reaches it.
        assert close(coupler, [a, b, pose[:2]]) and [c for _, c in items] == [False, True, False]
        assert close([c for c, _ in circles(doc, f"LINKAGE_{k}")], [a, b])
    poses = circles(doc, "POSES")
    assert close([c for c, _ in poses], [p[:2] for p in task.poses])
    for (flag, _), pose in zip(polylines(doc, "POSES"), task.poses):
        d = flag[1] - flag[0]
        assert close(flag[0], pose[:2]) and math.isclose(math.atan2(d[1], d[0]), pose[2], abs_tol=1e-9)
    assert texts(doc) == sorted(["A0", "C0", "1", "2", "3"])
    check_extent(doc)
    check_valid(doc)


def test_linkage_dxf_coupler_curve_path_and_travel(tmp_path, task, sfb):
    out = tmp_path / "l.dxf"
    export.linkage_dxf(sfb, out, task=task, travel_samples=4, path_samples=360)
    doc = ezdxf.readfile(out)
    fb, p = sfb.fourbar, sfb.coupler_point
    mode = sfb.modes[0]
    # The coupler curve: one polyline per arc of the input's range, from end to end.
    curve = polylines(doc, "COUPLER_CURVE")
    arcs = fb.input_range
    assert len(curve) == len(arcs) == 2
    for (pts, closed), (start, end) in zip(curve, arcs):
        assert not closed
        assert close(pts[0], fb.coupler_point(start, p, mode))
        assert close(pts[-1], fb.coupler_point(end, p, mode))
    # The coupler path over the travel: a leg from each pose to the next.
    legs = polylines(doc, "COUPLER_PATH")
    assert len(legs) == 2
    for k, (pts, _) in enumerate(legs):
        assert close(pts[0], task.poses[k][:2]) and close(pts[-1], task.poses[k + 1][:2])
    # The linkage sampled over the travel, both ends included.
    travel = polylines(doc, "TRAVEL")
    angles = sfb.travel_angles(4)
    assert len(travel) == 3 * 4
    for i, theta2 in enumerate(angles):
        _, a, b, _ = fb.joints(theta2, mode)
        crank, coupler, rocker = (pts for pts, _ in travel[3 * i:3 * i + 3])
        assert close(crank, [sfb.driving[0], a]) and close(rocker, [b, sfb.driven[0]])
        assert close(coupler[2], sfb.pose_at(theta2, mode)[:2])
    assert close(travel[2][0][0], fb.joints(angles[0], mode)[2])  # the first sample is pose 1's
    assert close(travel[1][0][2], task.poses[0][:2]) and close(travel[-2][0][2], task.poses[-1][:2])


def test_linkage_of_a_full_turning_crank_has_one_closed_coupler_curve(tmp_path, task, f):
    smap = f.solution_map(GRID, min_transmission_deg=30, input="crank")
    sfb = smap.best_pivots(1)[0].linkage
    assert sfb.fourbar.input_range is None
    out = tmp_path / "crank.dxf"
    export.linkage(sfb, out, path_samples=100)
    (curve, closed), = polylines(ezdxf.readfile(out), "COUPLER_CURVE")
    assert closed and len(curve) == 100
    assert close(curve[0], sfb.fourbar.coupler_point(0.0, sfb.coupler_point, sfb.modes[0]))


def test_linkage_svg_is_the_dxf_upright(tmp_path, task, sfb):
    dxf, svg = tmp_path / "l.dxf", tmp_path / "l.svg"
    export.linkage_dxf(sfb, dxf, task=task, travel_samples=3, units="in")
    export.linkage_svg(sfb, svg, task=task, travel_samples=3, units="in")
    doc = ezdxf.readfile(dxf)
    assert doc.header["$INSUNITS"] == 1 and doc.header["$MEASUREMENT"] == 0
    groups, root = svg_groups(svg)
    assert set(groups) == layers(doc)
    # The viewBox is the DXF's limits, y flipped; the size is in the units.
    lo, hi = check_extent(doc)
    assert close([float(v) for v in root.get("viewBox").split()], [lo[0], -hi[1], hi[0] - lo[0], hi[1] - lo[1]])
    assert root.get("width").endswith("in") and math.isclose(float(root.get("width")[:-2]), hi[0] - lo[0], rel_tol=1e-5)
    assert root.get("data-units") == "in"
    for layer in layers(doc) - {"TEXT"}:
        paths = [svg_rings(p.get("d"))[0] for p in groups[layer].iter(f"{SVG}path")]
        dxf_lines = polylines(doc, layer)
        assert len(paths) == len(dxf_lines) and all(close(a, b) for a, (b, _) in zip(paths, dxf_lines))
        marks = [(float(c.get("cx")), -float(c.get("cy"))) for c in groups[layer].iter(f"{SVG}circle")]
        assert close(marks, [c for c, _ in circles(doc, layer)]) if marks else not circles(doc, layer)
    titles = [t.text for t in groups["LINKAGE_2"].iter(f"{SVG}title")]
    assert "crank A0 A, pose 2 (open)" in titles
    assert sorted(t.text for t in groups["TEXT"].iter(f"{SVG}text")) == texts(doc)


# ---------------------------------------------------------------------------
# The center-point plane


def region_rings(doc, layer):
    rings = polylines(doc, layer)
    assert rings and all(closed for _, closed in rings)
    return [pts for pts, _ in rings]


def check_boundary(rings, grid, mask):
    """Every vertex off the view's edge lies between a sample where ``mask``
    is True and one where it is False, within a cell."""
    dx, dy = grid.dx, grid.dy
    xs, ys = grid.cell_centers()
    for ring in rings:
        for x, y in ring:
            on_edge = min(abs(x - grid.xmin), abs(x - grid.xmax), abs(y - grid.ymin), abs(y - grid.ymax)) < 1e-12
            if on_edge:
                continue
            near = mask[np.ix_(np.abs(ys - y) <= dy * 1.0001, np.abs(xs - x) <= dx * 1.0001)]
            assert near.any() and not near.all(), (x, y)


def test_plane_dxf_regions_conics_and_poles(tmp_path, task, f):
    out = tmp_path / "p.dxf"
    export.plane_dxf(f, out, GRID, units="m")
    doc = ezdxf.readfile(out)
    assert layers(doc) == {"VIEW", "BRANCH_FREE", "BRANCH_FREE_FILL", "CONIC_1", "CONIC_3", "POLES",
                           "POLE_TRIANGLE", "POLE_CIRCLE", "DRIVEN_PIVOT", "TEXT"}
    assert doc.header["$INSUNITS"] == 6
    assert close(find(polylines(doc, "VIEW")), [(-8, -8), (8, -8), (8, 8), (-8, 8)])
    poles = [p.point for p in task.poles]
    assert close([c for c, _ in circles(doc, "POLES")], poles, 1e-12)
    (tri, closed), = polylines(doc, "POLE_TRIANGLE")
    assert closed and close(tri, poles, 1e-12)
    (center, radius), = circles(doc, "POLE_CIRCLE")
    pc = task.pole_circle()
    assert close(center, pc["center"]) and math.isclose(radius, pc["radius"], rel_tol=1e-12)
    assert close(circles(doc, "DRIVEN_PIVOT")[0][0], f.driven_center)
    assert texts(doc) == sorted(["P12", "P13", "P23", "C0"])
    # The conics: every branch the core gives, each vertex on the conic.
    for pose, conic in zip(f.extreme_poses, f.conics):
        lines = polylines(doc, f"CONIC_{pose}")
        assert len(lines) == len(conic.polylines(*GRID.extent)) >= 1
        for pts, _ in lines:
            assert max(conic.distance(tuple(p)) for p in pts) < 1e-12 * (1 + np.abs(pts).max())
    # The regions: on the branch map's boundary to a cell, on the conics to a cell.
    rings = region_rings(doc, "BRANCH_FREE")
    free = f.branch_map(GRID)
    check_boundary(rings, GRID, free)
    cell = math.hypot(GRID.dx, GRID.dy)
    off_edge = [p for r in rings for p in r if -8 < p[0] < 8 and -8 < p[1] < 8]
    assert max(min(c.distance(tuple(p)) for c in f.conics) for p in off_edge) < cell
    # The filled regions are the same rings, holes included.
    hatches = doc.modelspace().query('HATCH[layer=="BRANCH_FREE_FILL"]')
    paths = [np.array(p.vertices)[:, :2] for h in hatches for p in h.paths]
    assert len(paths) == len(rings) and all(close(a, b) for a, b in zip(paths, rings))
    # Inside the rings (even-odd) is branch-free, away from the boundary.
    rng = np.random.default_rng(7)
    pts = rng.uniform(-8, 8, size=(2000, 2))
    far = np.array([min(c.distance(tuple(p)) for c in f.conics) > 2 * cell for p in pts])
    want = np.array([f.is_branch_free(tuple(p)) for p in pts[far]])
    assert want.any() and not want.all()
    assert (inside_even_odd(rings, pts[far]) == want).all()
    check_extent(doc)
    check_valid(doc)


def test_plane_svg_agrees_with_the_model(tmp_path, task, f):
    out = tmp_path / "p.svg"
    export.plane_svg(f, out, GRID, labels=False)
    groups, root = svg_groups(out)
    assert "TEXT" not in groups and {"BRANCH_FREE", "BRANCH_FREE_FILL", "POLES", "CONIC_1"} <= set(groups)
    assert root.get("width").endswith("mm")
    x0, y0, w, h = (float(v) for v in root.get("viewBox").split())
    poles = np.array([p.point for p in task.poles])
    got = [(float(c.get("cx")), -float(c.get("cy"))) for c in groups["POLES"].iter(f"{SVG}circle")]
    assert close(got, poles)
    # Everything drawn is in the viewBox (model y in [-(y0 + h), -y0]).
    assert x0 <= -8 and x0 + w >= 8 and -(y0 + h) <= -8 and -y0 >= 8
    conic = f.conics[list(f.extreme_poses).index(1)]
    for p in groups["CONIC_1"].iter(f"{SVG}path"):
        for ring in svg_rings(p.get("d")):
            assert max(conic.distance(tuple(q)) for q in ring) < 1e-12 * (1 + np.abs(ring).max())
    fills = list(groups["BRANCH_FREE_FILL"].iter(f"{SVG}path"))
    assert groups["BRANCH_FREE_FILL"].get("fill-rule") == "evenodd"
    rings = [r for p in fills for r in svg_rings(p.get("d"))]
    assert all(p.get("d").rstrip().endswith("Z") for p in fills)
    check_boundary(rings, GRID, f.branch_map(GRID))


def test_plane_with_a_solution_maps_overlays(tmp_path, f):
    smap = f.solution_map(GRID, min_transmission_deg=35)
    best = [p.center for p in smap.best_pivots(3)]
    out = tmp_path / "d.dxf"
    export.plane_dxf(f, out, free=smap.branch_free, acceptable=smap.acceptable, pivots=best,
                     transmission=np.degrees(smap.min_transmission_rad), transmission_levels=(35, 60))
    doc = ezdxf.readfile(out)
    assert {"ACCEPTABLE", "ACCEPTABLE_FILL", "BEST_PIVOTS", "TRANSMISSION"} <= layers(doc)
    check_valid(doc)
    # free= gave the grid: 120 x 120 over the default view of the example.
    g = Grid(*burmester.taskfile.default_view(f).extent, 120, 120)
    check_boundary(region_rings(doc, "ACCEPTABLE"), g, smap.branch_free & smap.acceptable)
    assert close([c for c, _ in circles(doc, "BEST_PIVOTS")], best)
    assert {"1", "2", "3", "35", "60"} <= set(texts(doc))
    # A contour vertex lies between samples above and below its level.
    trans = np.degrees(smap.min_transmission_rad)
    xs, ys = g.cell_centers()
    for pts, _ in polylines(doc, "TRANSMISSION"):
        x, y = pts[len(pts) // 2]
        near = trans[np.ix_(np.abs(ys - y) <= g.dy, np.abs(xs - x) <= g.dx)]
        near = near[np.isfinite(near)]
        assert near.min() <= 60 and near.max() >= 35


# ---------------------------------------------------------------------------
# The circle-point plane


def test_circle_plane_dxf(tmp_path, task, f):
    out = tmp_path / "c.dxf"
    view = (-6.0, 6.0, -5.0, 7.0)
    export.plane(f, out, view, plane="circle")
    doc = ezdxf.readfile(out)
    assert {"LINE_1", "LINE_2", "LINE_3", "BRANCH_FREE", "BRANCH_FREE_FILL", "IMAGE_POLES",
            "IMAGE_POLE_CIRCLE", "FIXED_PIVOT_IMAGES", "DRIVEN_CIRCLE_POINT"} <= layers(doc)
    check_valid(doc)
    c1 = np.array(f.driven_circle)
    assert close(circles(doc, "DRIVEN_CIRCLE_POINT")[0][0], c1)
    assert close([c for c, _ in circles(doc, "IMAGE_POLES")], task.image_poles())
    assert close([c for c, _ in circles(doc, "FIXED_PIVOT_IMAGES")], f.fixed_pivot_images)
    for k, image in enumerate(f.fixed_pivot_images, start=1):
        seg = find(polylines(doc, f"LINE_{k}"), n=2)
        u, v = seg[1] - seg[0], np.array(image) - c1
        assert abs(u[0] * v[1] - u[1] * v[0]) < 1e-9 * np.linalg.norm(u) * np.linalg.norm(v)  # on the line C1 C'k
    # The branch-free wedges: inside is exactly where Filemon's test says free.
    rings = region_rings(doc, "BRANCH_FREE")
    assert len(rings) == 2
    rng = np.random.default_rng(3)
    pts = rng.uniform([-6, -5], [6, 7], size=(1500, 2))
    signs = np.array([f.circle_signs(tuple(p)) for p in pts])
    far = np.abs(signs).min(axis=1) > 1e-6
    want = np.array([f.classify_circle_point(tuple(p)) == "free" for p in pts[far]])
    assert want.any() and not want.all()
    assert (inside_even_odd(rings, pts[far]) == want).all()


# ---------------------------------------------------------------------------
# Four and five poses


@pytest.fixture
def task5():
    return burmester.taskfile.load(EXAMPLES / "five.toml").task


def test_five_poses_burmester_points_on_both_curves(tmp_path, task5):
    out = tmp_path / "five.dxf"
    view = (-4.0, 12.0, -6.0, 10.0)
    export.burmester_plane_dxf(task5, out, view)
    doc = ezdxf.readfile(out)
    assert layers(doc) == {"VIEW", "CURVE_1234", "CURVE_1235", "BURMESTER_POINTS", "POLES", "POSES", "TEXT"}
    check_valid(doc)
    # The Burmester points in view (the fourth, near (28.6, -40.2), is not).
    inside = [c for c, _ in task5.burmester_points() if -4 <= c[0] <= 12 and -6 <= c[1] <= 10]
    assert len(inside) == 3
    assert close([c for c, _ in circles(doc, "BURMESTER_POINTS")], inside)
    for curve, layer in zip(task5.burmester_curves(), ("CURVE_1234", "CURVE_1235")):
        lines = polylines(doc, layer)
        assert len(lines) == len(curve.polylines(*view))
        for pts, _ in lines:
            assert max(curve.distance(tuple(p)) for p in pts) < 1e-9
        # Each Burmester point lies on both curves.
        assert all(curve.distance(tuple(c)) < 1e-9 for c in inside)
    assert close([c for c, _ in circles(doc, "POSES")], [p[:2] for p in task5.poses])
    lo, hi = np.array(doc.header["$LIMMIN"]), np.array(doc.header["$LIMMAX"])
    assert close(lo, [-4 - 0.48, -6 - 0.48]) and close(hi, [12 + 0.48, 10 + 0.48])  # the view, 3 % more


def test_four_poses_curve_by_crank_order_and_branch_free_arcs(tmp_path, task5):
    task4 = burmester.Task(task5.poses[:4])
    out = tmp_path / "four.svg"
    view = burmester.taskfile.default_curve_view(task4)
    export.burmester_plane_svg(task4, out, driven=(4.0, 0.0))
    groups, root = svg_groups(out)
    curve = task4.center_point_curve()
    arcs = task4.order_arcs(*view)
    by_layer = {"CURVE_CCW": "counterclockwise", "CURVE_CW": "clockwise", "CURVE_ORDER_DEFECT": None}
    for layer, direction in by_layer.items():
        want = [pts for _, d, pts in arcs if d == direction]
        got = [svg_rings(p.get("d"))[0] for p in groups[layer].iter(f"{SVG}path")] if want else []
        assert len(got) == len(want) and all(close(a, b) for a, b in zip(got, want))
    band = [svg_rings(p.get("d"))[0] for p in groups["BRANCH_FREE_ARCS"].iter(f"{SVG}path")]
    assert band and all(curve.distance(tuple(v)) < 1e-9 for ring in band for v in ring)
    qs = [q.center for q in task4.coincidence_points() if q.center is not None
          and view[0] <= q.center[0] <= view[1] and view[2] <= q.center[1] <= view[3]]
    got = [(float(c.get("cx")), -float(c.get("cy"))) for c in groups["COINCIDENCE_POINTS"].iter(f"{SVG}circle")]
    assert qs and close(got, qs)
    pivot = [(float(c.get("cx")), -float(c.get("cy"))) for c in groups["DRIVEN_PIVOT"].iter(f"{SVG}circle")]
    assert close(pivot, [(4, 0)])


def test_four_poses_circle_plane(tmp_path, task5):
    """The circle-point plane of four poses: the circle-point curve by crank
    order (Task.order_arcs(plane="circle")), the circle points Q'jk, and for
    a driven dyad the circle points of the branch-free driving dyads, C1 and
    Filemon's four lines through C1 and C'k."""
    task4 = burmester.Task(task5.poses[:4])
    view = burmester.taskfile.default_curve_view(task4)
    out = tmp_path / "circle.dxf"
    export.burmester_plane(task4, out, view, driven=(4.0, 0.0), plane="circle")
    doc = ezdxf.readfile(out)
    check_valid(doc)
    assert {"BRANCH_FREE_ARCS", "FIXED_PIVOT_IMAGES", "DRIVEN_CIRCLE_POINT", "COINCIDENCE_POINTS", "POSES",
            "LINE_1", "LINE_2", "LINE_3", "LINE_4"} <= layers(doc)
    assert "POLES" not in layers(doc) and "DRIVEN_PIVOT" not in layers(doc)
    curve = task4.circle_point_curve()
    arcs = task4.order_arcs(*view, plane="circle")
    got = sum(len(polylines(doc, layer)) for layer in ("CURVE_CCW", "CURVE_CW", "CURVE_ORDER_DEFECT"))
    assert got == len(arcs) > 0
    for layer in ("CURVE_CCW", "CURVE_CW", "CURVE_ORDER_DEFECT", "BRANCH_FREE_ARCS"):
        for pts, _ in polylines(doc, layer):
            assert max(curve.distance(tuple(p)) for p in pts) < 1e-9, layer
    c1 = task4.circle_point((4.0, 0.0))
    assert close([c for c, _ in circles(doc, "DRIVEN_CIRCLE_POINT")], [c1])
    images = [task4.displace((4.0, 0.0), k, 1) for k in range(1, 5)]
    inside = [p for p in images if view[0] <= p[0] <= view[1] and view[2] <= p[1] <= view[3]]
    assert close([c for c, _ in circles(doc, "FIXED_PIVOT_IMAGES")], inside)
    for k in range(1, 5):
        ((pts, _),) = polylines(doc, f"LINE_{k}")
        (x0, y0), (x1, y1) = pts[0], pts[-1]
        for p in (c1, images[k - 1]):
            cross = (x1 - x0) * (p[1] - y0) - (y1 - y0) * (p[0] - x0)
            assert abs(cross) <= 1e-9 * math.hypot(x1 - x0, y1 - y0) * (1 + math.dist(p, (x0, y0)))
    # Five poses have no circle-point curve; other planes are refused.
    with pytest.raises(burmester.InvalidInputError) as e:
        export.burmester_plane(task5, tmp_path / "five.dxf", plane="circle")
    assert e.value.cause == "needs_poses"
    with pytest.raises(burmester.InvalidInputError, match="plane must be"):
        export.burmester_plane(task4, tmp_path / "x.dxf", plane="coupler")


def test_cli_map_of_five_poses_exports_the_burmester_points(tmp_path, capsys):
    out = tmp_path / "five.dxf"
    assert main(["map", str(EXAMPLES / "five.toml"), "-o", str(out)]) == 0
    assert "Burmester points of" in capsys.readouterr().out
    doc = ezdxf.readfile(out)
    assert {"CURVE_1234", "CURVE_1235", "BURMESTER_POINTS"} <= layers(doc)
    with pytest.raises(burmester.InvalidInputError, match="needs a task of"):
        export.burmester_plane(burmester.taskfile.example().task, tmp_path / "three.dxf")


# ---------------------------------------------------------------------------
# Bad input


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda s, f, d: export.linkage(s, d / "a.dxf", units=""), ["units must be a unit name", "empty name"]),
        (lambda s, f, d: export.linkage(s, d / "a.dxf", units="m\nm"), ["units", "control characters"]),
        (lambda s, f, d: export.plane(f, d / "a.svg", units=4), ["units must be a unit name", "(int)"]),
        (lambda s, f, d: export.linkage(s, d / "a.dxf", travel_samples=-1), ["travel_samples", "from 0"]),
        (lambda s, f, d: export.linkage(s, d / "a.dxf", travel_samples=1), ["0 (none) or at least 2"]),
        (lambda s, f, d: export.linkage(s, d / "a.dxf", path_samples=0), ["path_samples", "from 8"]),
        (lambda s, f, d: export.linkage(s, d / "a.png"), ["'.png'", ".dxf or .svg"]),
        (lambda s, f, d: export.linkage_dxf(s, d / "a.svg"), ["'.svg'", ".dxf"]),
        (lambda s, f, d: export.plane_svg(f, d / "a"), ["no extension", ".svg"]),
        (lambda s, f, d: export.plane(f, d / "missing" / "a.svg"), ["does not exist"]),
        (lambda s, f, d: export.plane(f, d / "a.svg", "everything"), ["view must be"]),
        (lambda s, f, d: export.plane(f, d / "a.svg", (1, 0, 0, 1)), ["xmin < xmax"]),
        (lambda s, f, d: export.plane(f, d / "a.svg", (0, 1, 0)), ["view must be"]),
        (lambda s, f, d: export.plane(f, d / "a.svg", (0, math.inf, 0, 1)), ["finite"]),
        (lambda s, f, d: export.plane(f, d / "a.svg", plane="side"), ["'center' or 'circle'"]),
        (lambda s, f, d: export.plane(f, d / "a.svg", GRID, free=np.ones((3, 3))), ["shape", "(120, 120)"]),
        (lambda s, f, d: export.plane(f, d / "a.svg", grid=(1, 5)), ["grid nx", "from 2"]),
    ],
)
def test_bad_input_says_what_to_change(call, words, tmp_path, sfb, f):
    with pytest.raises(burmester.InvalidInputError) as e:
        call(sfb, f, tmp_path)
    for w in words:
        assert w in str(e.value), (w, str(e.value))
    assert list(tmp_path.iterdir()) == []


def test_wrong_types_and_an_undrivable_travel(tmp_path, f):
    with pytest.raises(TypeError, match="travel_samples must be an int"):
        export.linkage(f.four_bar(PIVOT), tmp_path / "a.svg", travel_samples=2.5)
    defect = f.four_bar((0.0, 0.0))  # a branch defect: no travel to sample
    assert not defect.figures.feasible
    with pytest.raises(burmester.AssemblyError, match="no travel to sample"):
        export.linkage(defect, tmp_path / "a.svg", travel_samples=3)
    export.linkage(defect, tmp_path / "a.svg")  # without samples it is drawn, without a coupler path
    groups, _ = svg_groups(tmp_path / "a.svg")
    assert "COUPLER_PATH" not in groups and "TRAVEL" not in groups and "LINKAGE_3" in groups


def test_without_ezdxf_the_message_says_what_to_install(tmp_path, f, monkeypatch):
    monkeypatch.setitem(sys.modules, "ezdxf", None)
    with pytest.raises(ImportError, match=r'pip install "burmester\[plot\]"'):
        export.plane_dxf(f, tmp_path / "a.dxf", GRID)
    assert main(["map", "-o", str(tmp_path / "m.dxf")]) == 1
    export.plane_svg(f, tmp_path / "a.svg", (-8, 8, -8, 8), grid=(20, 20))  # SVG needs no ezdxf


def test_the_cli_offers_the_units_the_export_knows():
    from burmester import cli

    assert sorted(cli.UNIT_CHOICES) == sorted(export.UNITS)
    assert export.DEFAULT_UNITS == "mm" and export.UNITS["mm"] == ezdxf.units.MM


def test_importing_burmester_imports_no_drawing_library():
    code = ("import sys, burmester, burmester.export; "
            "print(sorted(m for m in ('ezdxf', 'matplotlib', 'contourpy') if m in sys.modules))")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert p.stdout.strip() == "[]"


# ---------------------------------------------------------------------------
# The command line


def test_cli_map_writes_the_plane_as_dxf(tmp_path, capsys, task):
    out = tmp_path / "plane.dxf"
    assert main(["map", "--grid", "60", "60", "--pivots", "2", "-o", str(out)]) == 0
    assert f"wrote {out}: center-point plane" in capsys.readouterr().out
    doc = ezdxf.readfile(out)
    assert {"BRANCH_FREE", "CONIC_1", "CONIC_3", "POLES", "DRIVEN_PIVOT", "BEST_PIVOTS"} <= layers(doc)
    assert close([c for c, _ in circles(doc, "POLES")], [p.point for p in task.poles])
    free = burmester.taskfile.example().filemon().branch_map(Grid(-8, 8, -8, 8, 60, 60))
    check_boundary(region_rings(doc, "BRANCH_FREE"), Grid(-8, 8, -8, 8, 60, 60), free)
    circ = tmp_path / "circle.svg"
    assert main(["map", "--plane", "circle", "--units", "cm", "-o", str(circ)]) == 0
    groups, root = svg_groups(circ)
    assert "LINE_2" in groups and root.get("data-units") == "cm"


def test_cli_linkage_writes_svg_with_travel(tmp_path, capsys):
    out = tmp_path / "l.svg"
    assert main(["linkage", "--pivot", *map(str, PIVOT), "--travel", "4", "-o", str(out)]) == 0
    assert "double-rocker, branch-free" in capsys.readouterr().out
    groups, _ = svg_groups(out)
    assert LINKAGE_LAYERS <= set(groups)
    assert len(list(groups["TRAVEL"].iter(f"{SVG}path"))) == 3 * 4
    sfb = burmester.taskfile.example().filemon().four_bar(PIVOT)
    a = sfb.fourbar.joints(sfb.input_angles[0], sfb.modes[0])[1]
    cranks = [svg_rings(p.get("d"))[0] for p in groups["LINKAGE_1"].iter(f"{SVG}path")]
    assert close(cranks[0], [sfb.driving[0], a])


@pytest.mark.parametrize(
    "args, words",
    [
        (["map", str(EXAMPLES / "five.toml"), "--plane", "circle", "-o", "{tmp}/m.dxf"],
         ["--plane circle is for three poses", "5 poses"]),
        (["linkage", "--frames", "5", "-o", "{tmp}/l.dxf"], ["--frames is for animations", "--travel N"]),
        (["linkage", "--fps", "5", "-o", "{tmp}/l.svg"], ["--fps is for animations"]),
        (["linkage", "--travel", "5", "-o", "{tmp}/l.png"], ["--travel is for CAD exports"]),
        (["map", "--units", "", "-o", "{tmp}/m.png"], ["--units must be a unit name", "empty name"]),
        (["map", "--dpi", "300", "-o", "{tmp}/m.svg"], ["--dpi is for pictures"]),
        (["linkage", "--dpi", "300", "-o", "{tmp}/l.dxf"], ["--dpi is for pictures"]),
        (["map", "--units", "m[m]", "-o", "{tmp}/m.dxf"], ["--units", "brackets"]),
        (["linkage", "--pivot", "0", "0", "--travel", "3", "-o", "{tmp}/l.dxf"], ["no travel to sample"]),
    ],
)
def test_cli_refuses_what_a_cad_export_cannot_do(args, words, tmp_path, capsys):
    assert main([a.format(tmp=tmp_path) for a in args]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1
    for w in words:
        assert w in err, (w, err)
    assert list(tmp_path.iterdir()) == []


def test_cli_never_replaces_an_export_without_force(tmp_path, capsys):
    out = tmp_path / "l.dxf"
    out.write_text("mine")
    assert main(["linkage", "--pivot", *map(str, PIVOT), "-o", str(out)]) == 2
    assert "--force" in capsys.readouterr().err and out.read_text() == "mine"
    assert main(["linkage", "--pivot", *map(str, PIVOT), "-o", str(out), "--force"]) == 0
    assert "LINKAGE_1" in layers(ezdxf.readfile(out))
