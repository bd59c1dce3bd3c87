"""Ranking a solution map whose driven dyad is a slider
(``SolutionMap.best_slider_pivots``, ``slider_pareto_front``,
``SliderPivot``), obstacles and an envelope on it, the CLI's
``burmester map`` with a driven slider, and the solution map's legend kept
whole by a default ``savefig``. The ranking is checked against rescoring
every cell from the exact slider-crank (``Task.slider_crank``), its best
pivot against driving it with the solver of ``test_slider_branch`` (the
press in millimetres of ``test_slider_map``)."""

import io
import math
import pickle
import sys

import numpy as np
import pytest

import burmester
from burmester import Grid, InvalidInputError, SliderFilemon, SliderPivot
from test_slider_branch import U, _drive, _press_task, _slider

GRID = (-307.5, 307.5, -307.5, 307.5, 41, 41)
#: The columns are f32: a score read from them is within a few of its ulps.
F32 = 4 * float(np.finfo(np.float32).eps)


@pytest.fixture(scope="module")
def press():
    task, b1 = _press_task()
    f = SliderFilemon(task, b1, U)
    return task, b1, f, f.solution_map(Grid(*GRID))


def _exact(task, b1, center):
    """The slider-crank of the crank pivot ``center`` built from the task."""
    return task.slider_crank((center, task.circle_point(center)), (b1, U))


def _score(sc, rank_by):
    mu = math.radians(sc.min_transmission_deg)
    if rank_by == "balanced":
        return math.sin(mu) / math.sqrt(sc.size_ratio * sc.linkage.link_ratio)
    return mu if rank_by == "transmission" else -sc.size_ratio


def test_the_best_pivots_are_the_best_of_every_cell_rescored(press):
    task, b1, f, m = press
    ny, nx = m.shape
    cells = []
    for j in range(ny):
        for i in range(nx):
            if m.acceptable[j, i]:
                cells.append(_exact(task, b1, m.point(j, i)))
    assert len(cells) > 100
    for rank_by in ("balanced", "transmission", "compact"):
        best = m.best_slider_pivots(3, rank_by=rank_by)
        assert len(best) == 3 and all(isinstance(p, SliderPivot) for p in best)
        b = best[0]
        exact = _exact(task, b1, b.center)
        assert b.linkage == exact and b.center == m.point(*b.index)
        assert b.size_ratio == pytest.approx(exact.size_ratio, rel=1e-12)
        assert exact.feasible and exact.branch_free
        # The independent solver reaches the poses in one mode, the crank
        # turning between them.
        a1 = task.circle_point(b.center)
        assert _drive(task.poses, b.center, a1, b1, U) == "free"
        for k, pose in enumerate(task.poses):
            x, y, _ = exact.pose_at(exact.input_angles[k], exact.modes[k])
            assert math.hypot(x - pose[0], y - pose[1]) < 1e-9 * task.span
        brute = max(_score(sc, rank_by) for sc in cells)
        assert b.score == pytest.approx(brute, rel=F32, abs=1e-6)
        assert _score(exact, rank_by) == pytest.approx(brute, rel=F32)
    front = m.slider_pareto_front()
    assert len(front) >= 2 and all(p.ranked_by == "pareto" for p in front)
    sizes = [p.size_ratio for p in front]
    mus = [p.linkage.min_transmission_deg for p in front]
    assert sizes == sorted(sizes) and mus == sorted(mus)
    for p in front:
        dominated = [sc for sc in cells if sc.min_transmission_deg > p.linkage.min_transmission_deg + 1e-4
                     and sc.size_ratio < p.size_ratio * (1 - 1e-6)]
        assert not dominated
    margin = m.best_slider_pivots(2, rank_by="margin")
    assert margin[0].margin > 0 and margin[0].margin == m.margin(*margin[0].index)
    # The documented maximum: every candidate (k without a bound).
    every = m.best_slider_pivots(sys.maxsize, min_separation=0.0)
    assert len(every) == int(m.acceptable.sum())


def test_slider_pivots_pickle_and_refuse_what_is_wrong(press):
    task, b1, f, m = press
    p = m.best_slider_pivots(1)[0]
    back = pickle.loads(pickle.dumps(p))
    assert back == p and back.linkage == p.linkage and back.score == p.score
    assert p != m.best_slider_pivots(2)[1]
    assert repr(p).startswith("<SliderPivot center=(") and "by balanced" in repr(p)
    other = m.slider_crank(0, 0) if m.valid[0, 0] else m.slider_crank(20, 21)
    with pytest.raises(InvalidInputError) as e:
        SliderPivot((1.0, 2.0), (0, 0), other, 0.1, 0.2, "balanced")
    assert e.value.cause == "inconsistent_state"
    with pytest.raises(InvalidInputError):
        m.best_slider_pivots(3, rank_by="fastest")
    with pytest.raises(InvalidInputError):
        m.best_slider_pivots(3, min_separation=-1.0)
    with pytest.raises(InvalidInputError) as e:
        m.best_pivots(3)
    assert e.value.cause == "driven_kind" and "best_slider_pivots" in str(e.value)
    revolute = task.filemon((300.0, -200.0)).solution_map(Grid(*GRID))
    with pytest.raises(InvalidInputError) as e:
        revolute.best_slider_pivots(3)
    assert e.value.cause == "driven_kind" and "best_pivots" in str(e.value)
    with pytest.raises(InvalidInputError):
        revolute.slider_pareto_front()


def test_obstacles_take_away_colliding_slider_cranks(press):
    task, b1, f, m = press
    block = [(60.0, 40.0), (110.0, 40.0), (110.0, 80.0), (60.0, 80.0)]
    # (The maps' Python options have no envelope: the core's is checked in
    # tests/rust/slider_branch.rs.)
    c = f.solution_map(Grid(*GRID), obstacles=[block], link_width=8.0)
    assert not (c.acceptable & ~m.acceptable).any()
    assert 0 < c.acceptable.sum() < m.acceptable.sum()
    best = c.best_slider_pivots(1)[0]
    # Its crank and coupler clear the block over the travel (dense check).
    # Driven by the solver of test_slider_branch (its mode: the one that
    # puts the pin on C1 at pose 1).
    sc = best.linkage
    a0, r, l = best.center, sc.linkage.crank, sc.linkage.coupler
    phi1 = sc.input_angles[0]
    mode = min((1, -1), key=lambda s: math.dist(_slider(a0, r, l, b1, U, phi1, s), b1))
    assert math.dist(_slider(a0, r, l, b1, U, phi1, mode), b1) < 1e-9 * task.span
    start, span = sc.travel
    for t in np.linspace(start, start + span, 2001):
        a = (a0[0] + r * math.cos(t), a0[1] + r * math.sin(t))
        b = _slider(a0, r, l, b1, U, float(t), mode)
        for p, q in ((a0, a), (a, b)):
            assert _segment_box_gap(p, q, (60.0, 110.0, 40.0, 80.0)) > 4.0 - 0.5


def _segment_box_gap(a, b, box):
    """The distance from the segment ``a b`` to an axis-aligned box (0 when
    they meet), by dense sampling of the segment (fine enough here)."""
    x0, x1, y0, y1 = box
    gap = math.inf
    for s in np.linspace(0.0, 1.0, 401):
        x, y = a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])
        dx, dy = max(x0 - x, 0.0, x - x1), max(y0 - y, 0.0, y - y1)
        gap = min(gap, math.hypot(dx, dy))
    return gap


def _legend_inside(ax, fig):
    fig.savefig(io.BytesIO(), format="png")  # a default savefig lays the figure out
    (leg,) = fig.legends  # the figure's legend, outside the axes
    assert ax.get_legend() is None and len(leg.get_texts()) >= 5
    bb, fb = leg.get_window_extent(), fig.bbox
    return bb.x0 >= fb.x0 - 0.5 and bb.x1 <= fb.x1 + 0.5 and bb.y0 >= fb.y0 - 0.5 and bb.y1 <= fb.y1 + 0.5


def test_the_legend_is_whole_in_a_default_savefig(press):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from burmester import plot

    task, _, _, m = press
    for smap in (m, task.filemon((300.0, -200.0)).solution_map(Grid(-300, 300, -300, 300, 30, 30))):
        ax = plot.solution_map(smap, units="mm")
        assert _legend_inside(ax, ax.figure), smap.fixed_kind
        plt.close(ax.figure)
    # The best slider pivots are drawn (numbered stars).
    ax = plot.solution_map(m, pivots=3)
    stars = [a for a in ax.get_children() if a.get_gid() == "pivots"]
    assert stars and len(stars[0].get_xdata()) == 3
    plt.close(ax.figure)


def test_the_cli_maps_and_ranks_a_driven_slider(press, tmp_path, capsys):
    pytest.importorskip("matplotlib")
    from burmester.cli import main

    task, b1, _, _ = press
    poses = "\n".join(
        f"[[pose]]\nx = {x!r}\ny = {y!r}\nangle_deg = {math.degrees(t)!r}\n" for x, y, t in task.poses
    )
    path = tmp_path / "press.toml"
    path.write_text(f'units = "mm"\n{poses}\n[driven]\nslider = [{b1[0]!r}, {b1[1]!r}]\n\n'
                    "[view]\nx = [-300.0, 300.0]\ny = [-300.0, 300.0]\ngrid = [60, 60]\n")
    out = tmp_path / "map.png"
    assert main(["map", str(path), "-o", str(out), "--pivots", "3"]) == 0
    text = capsys.readouterr().out
    assert out.exists() and "slider solution map" in text and "Crank pivots A0 of slider-cranks" in text
    assert text.count("forward") + text.count("backward") + text.count("ccw") + text.count("cw") >= 3
    # The flag in place of the table: the same map.
    plain = tmp_path / "plain.toml"
    plain.write_text(f"{poses}\n[driven]\ncenter = [300.0, -200.0]\n")
    out2 = tmp_path / "flag.png"
    assert main(["map", str(plain), "-o", str(out2), "--grid", "60", "60",
                 "--driven-slider", repr(b1[0]), repr(b1[1])]) == 0
    assert "slider solution map" in capsys.readouterr().out
    # A point off the slider circle, and commands that need a four-bar.
    assert main(["map", str(plain), "-o", str(tmp_path / "x.png"), "--driven-slider", "1", "2"]) == 2
    assert "not a slider point" in capsys.readouterr().err
    assert main(["pivots", str(path)]) == 2
    assert "only 'burmester map' takes a driven slider" in capsys.readouterr().err


def test_the_press_example_ranks_a_slider_crank_a_designer_would_build(tmp_path, capsys):
    """examples/press.toml (mm, a motor that turns fully): the best
    slider-crank turns fully, passes the poses on one branch in order, keeps
    the rod well off the guide's normal, and is smaller than the 40/160 mm
    one the poses were made from."""
    pytest.importorskip("matplotlib")
    from pathlib import Path

    from burmester import taskfile
    from burmester.cli import main

    path = Path(__file__).resolve().parents[2] / "examples" / "press.toml"
    spec = taskfile.load(path)
    c1, u = spec.driven_slider
    smap = SliderFilemon(spec.task, c1, u).solution_map(spec.view, limits=spec.limits)
    best = smap.best_slider_pivots(1)[0]
    sc = best.linkage
    assert sc.linkage.turns_fully and sc.feasible and sc.min_transmission_deg > 60.0
    made_from = spec.task.slider_crank(((0.0, 0.0), spec.task.circle_point((0.0, 0.0))), (c1, u))
    assert made_from.feasible and sc.size_ratio < made_from.size_ratio
    assert main(["map", str(path), "-o", str(tmp_path / "press.png")]) == 0
    assert f"{sc.linkage.crank:.3f}" in capsys.readouterr().out


def test_task_files_name_a_slider_or_say_what_is_wrong(press):
    from burmester import taskfile

    task, b1, _, _ = press
    poses = "\n".join(f"[[pose]]\nx = {x!r}\ny = {y!r}\nangle_deg = {math.degrees(t)!r}\n" for x, y, t in task.poses)
    spec = taskfile.loads(f"{poses}\n[driven]\nslider = [{b1[0]!r}, {b1[1]!r}]\n", "press.toml")
    c1, u = spec.driven_slider
    assert c1 == pytest.approx(b1, abs=1e-9) and abs(u[0] * U[1] - u[1] * U[0]) < 1e-9
    assert spec.driven_center is None
    with pytest.raises(taskfile.TaskFileError, match="only 'burmester map' takes a driven slider"):
        spec.filemon()
    with pytest.raises(taskfile.TaskFileError, match=r"driven\.slider.*not a slider point"):
        taskfile.loads(f"{poses}\n[driven]\nslider = [1.0, 2.0]\n", "off.toml")
    with pytest.raises(taskfile.TaskFileError, match="both center and slider"):
        taskfile.loads(f"{poses}\n[driven]\ncenter = [1.0, 2.0]\nslider = [1.0, 2.0]\n", "two.toml")
    four = poses + "\n[[pose]]\nx = 1.0\ny = 2.0\nangle_deg = 3.0\n"
    with pytest.raises(taskfile.TaskFileError, match="three poses"):
        taskfile.loads(f"{four}\n[driven]\nslider = [1.0, 2.0]\n", "four.toml")
