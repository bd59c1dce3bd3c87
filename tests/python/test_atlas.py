"""The pivot-pair atlas (burmester.pivot_atlas): against the solution maps it
reduces, in process and on a real Dask cluster (bit for bit)."""

import math
import os
import pickle
import signal
import time

import numpy as np
import pytest

import burmester
from burmester import Grid, InvalidInputError, Task, pivot_atlas
from conftest import POSES

DRIVEN = (-6.0, 6.0, -6.0, 6.0, 7, 6)
DRIVING = Grid(-9.0, 9.0, -9.0, 9.0, 36, 30)
LIMITS = dict(min_transmission_deg=25.0, max_link_ratio=15.0, input="any")


@pytest.fixture(scope="module")
def atlas():
    return pivot_atlas(Task(POSES), DRIVEN, DRIVING, **LIMITS)


def _same(a, b):
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


def test_cells_equal_the_reduced_solution_maps(atlas):
    """An independent check: every cell against task.filemon(C0).solution_map
    over the same driving grid (count of acceptable, best_pivots(1))."""
    t = Task(POSES)
    driven = Grid(*DRIVEN)
    assert atlas.shape == (6, 7) and atlas.best_driving.shape == (6, 7, 2)
    with_best = 0
    for j in range(driven.ny):
        for i in range(driven.nx):
            c0 = driven.point(j, i)
            try:
                f = t.filemon(c0)
            except burmester.BurmesterError:
                assert not atlas.valid[j, i] and atlas.count[j, i] == 0
                assert math.isnan(atlas.best_transmission_deg[j, i])
                continue
            m = f.solution_map(DRIVING, **LIMITS)
            assert atlas.valid[j, i]
            assert atlas.count[j, i] == int(m.acceptable.sum())
            assert atlas.branch_free_fraction[j, i] == m.branch_free.sum() / DRIVING.size
            best = m.best_pivots(1, rank_by=atlas.rank_by)
            if not best:
                assert math.isnan(atlas.best_transmission_deg[j, i])
                assert np.isnan(atlas.best_driving[j, i]).all()
                continue
            with_best += 1
            (p,) = best
            assert tuple(atlas.best_driving[j, i]) == p.center
            assert tuple(atlas.best_index[j, i]) == p.index
            assert atlas.best_transmission_deg[j, i] == np.degrees(np.float64(m.min_transmission_rad[p.index]))
            assert atlas.best_score[j, i] == p.score
            assert atlas.best_size_ratio[j, i] == np.float64(m.size_ratio[p.index])
            assert atlas.best_margin[j, i] == p.margin
            assert atlas.best_link_ratio[j, i] == np.float64(m.link_ratio[p.index])
    assert with_best >= 20


def test_grid_tuples_and_grids_agree(atlas):
    again = pivot_atlas(Task(POSES), Grid(*DRIVEN), tuple([DRIVING.xmin, DRIVING.xmax, DRIVING.ymin,
                                                            DRIVING.ymax, DRIVING.nx, DRIVING.ny]),
                        limits=burmester.DesignLimits(25.0, 15.0, "any"))
    for name in ("valid", "count", "best_transmission_deg", "best_driving", "best_margin"):
        assert _same(getattr(again, name), getattr(atlas, name)), name


def test_best_pairs_pickle_and_repr(atlas):
    pairs = atlas.best_pairs(3)
    assert len(pairs) == 3
    # By the atlas's ranking (balanced by default), best first.
    assert atlas.rank_by == "balanced"
    assert pairs[0].score == np.nanmax(atlas.best_score)
    assert pairs[0].score >= pairs[1].score >= pairs[2].score
    lk = pairs[0].linkage(Task(POSES))
    assert abs(lk.figures.min_transmission_deg - pairs[0].min_transmission_deg) < 1e-3
    assert abs(lk.score("balanced") - pairs[0].score) < 1e-6
    # By transmission, the old order.
    by_mu = pivot_atlas(Task(POSES), DRIVEN, DRIVING, rank_by="transmission", **LIMITS)
    top = by_mu.best_pairs(2)
    assert top[0].min_transmission_deg == np.nanmax(by_mu.best_transmission_deg)
    assert by_mu.rank_by == "transmission" and "rank_by='transmission'" in repr(by_mu)
    back = pickle.loads(pickle.dumps(atlas))
    assert back == atlas and repr(back) == repr(atlas)
    assert "PivotAtlas(driven=7x6" in repr(atlas)
    assert atlas.best_pairs(0) == []


def test_progress_and_bad_input():
    seen = []
    pivot_atlas(Task(POSES), DRIVEN, (-9, 9, -9, 9, 8, 8), progress=lambda d, t: seen.append((d, t)))
    assert seen and seen[-1] == (6, 6)
    with pytest.raises(InvalidInputError) as e:
        pivot_atlas(Task(POSES), DRIVEN, DRIVING, min_transmission_deg=120.0)
    assert e.value.cause == "outside_range"
    with pytest.raises(InvalidInputError) as e:
        pivot_atlas(Task(POSES + [(4.0, 2.0, 1.3)]), DRIVEN, DRIVING)
    assert e.value.cause == "needs_poses"
    with pytest.raises(TypeError):
        pivot_atlas(Task(POSES), (1, 2, 3), DRIVING)


def test_client_without_dask_says_how_to_install(monkeypatch):
    import importlib

    real = importlib.import_module

    def fake(name, *a, **k):
        if name.split(".")[0] in ("distributed", "dask"):
            raise ImportError(name)
        return real(name, *a, **k)

    monkeypatch.setattr(importlib, "import_module", fake)
    with pytest.raises(ImportError, match=r'pip install "burmester\[dask\]"'):
        pivot_atlas(Task(POSES), DRIVEN, DRIVING, client=object())


# ---------------------------------------------------------------------------
# On a real Dask cluster


def test_dask_equals_in_process_bit_for_bit(client, atlas):
    for tile_rows in (None, 1, 4):
        d = pivot_atlas(Task(POSES), DRIVEN, DRIVING, client=client, tile_rows=tile_rows, **LIMITS)
        assert d == atlas, tile_rows
        for name in ("valid", "count", "best_transmission_deg", "best_driving", "best_margin",
                     "best_link_ratio", "best_index"):
            assert _same(getattr(d, name), getattr(atlas, name)), (tile_rows, name)
        assert np.array_equal(d.branch_free_fraction, atlas.branch_free_fraction, equal_nan=True)


def test_dask_bad_input_raises_the_in_process_error(client):
    with pytest.raises(InvalidInputError) as e:
        pivot_atlas(Task(POSES), DRIVEN, DRIVING, client=client, min_transmission_deg=120.0)
    assert e.value.cause == "outside_range"
    with pytest.raises(InvalidInputError) as e:
        pivot_atlas(Task(POSES + [(4.0, 2.0, 1.3)]), DRIVEN, DRIVING, client=client)
    assert e.value.cause == "needs_poses"


def _slow_pid():
    return os.getpid()


def test_a_worker_killed_mid_run_is_retried(client):
    """Kill one worker process while tiles run: Dask reruns its tiles on the
    other (or a restarted) worker and the result is identical."""
    driven = (-6.0, 6.0, -6.0, 6.0, 8, 12)
    driving = (-9.0, 9.0, -9.0, 9.0, 90, 80)
    want = pivot_atlas(Task(POSES), driven, driving, **LIMITS)
    pids = list(client.run(_slow_pid).values())
    killed = []

    def kill_one(done, total):
        if not killed and done >= 1:
            killed.append(pids[0])
            os.kill(pids[0], signal.SIGKILL)

    got = pivot_atlas(Task(POSES), driven, driving, client=client, tile_rows=1,
                      progress=kill_one, **LIMITS)
    assert killed
    assert got == want
    # The cluster recovers for the tests after this one.
    deadline = time.time() + 30
    while len(client.scheduler_info()["workers"]) < 2 and time.time() < deadline:
        time.sleep(0.2)


# ---------------------------------------------------------------------------
# burmester atlas (the command line)


def test_cli_atlas_picture_json_and_errors(tmp_path, capsys):
    import json

    from burmester.cli import main

    pytest.importorskip("matplotlib")
    out = tmp_path / "atlas.png"
    small = ["--driven-grid", "6", "5", "--driving-grid", "20", "16"]
    assert main(["atlas", "-o", str(out), *small]) == 0
    assert out.stat().st_size > 1000
    assert "driven centers have an acceptable driving pivot" in capsys.readouterr().out
    # The output is checked before any work: one line, status 2.
    assert main(["atlas", "-o", str(out), *small]) == 2
    assert main(["atlas", "-o", str(tmp_path / "a.txt"), *small]) == 2
    assert main(["atlas", "--driven-grid", "1", "5"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 3 and "exists" in err and "--force" in err
    assert main(["atlas", "-o", str(out), "--force", *small]) == 0
    capsys.readouterr()
    assert main(["atlas", "--json", "--top", "2", *small]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["driven_grid"] == [6, 5] and len(doc["best"]) == 2
    v = doc["view"]
    from burmester import taskfile

    want = pivot_atlas(taskfile.example().task, (*v["x"], *v["y"], 6, 5), (*v["x"], *v["y"], 20, 16),
                       min_transmission_deg=doc["limits"]["min_transmission_deg"],
                       max_link_ratio=doc["limits"]["max_link_ratio"], input=doc["limits"]["input"])
    assert doc["best"][0]["min_transmission_deg"] == want.best_pairs(1)[0].min_transmission_deg


@pytest.mark.skipif(os.name != "posix", reason="POSIX signals")
def test_ctrl_c_stops_an_in_process_atlas():
    import json
    import subprocess
    import sys
    import textwrap

    child = textwrap.dedent(
        f"""
        import json, time, burmester
        t = burmester.Task({POSES!r})
        print("started", flush=True)
        t0 = time.monotonic()
        try:
            burmester.pivot_atlas(t, (-8, 8, -8, 8, 400, 400), (-8, 8, -8, 8, 200, 200))
        except KeyboardInterrupt as e:
            print(json.dumps({{"message": str(e), "ran": time.monotonic() - t0}}), flush=True)
            raise
        print(json.dumps({{"finished": time.monotonic() - t0}}), flush=True)
        """
    )
    p = subprocess.Popen([sys.executable, "-c", child], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    assert p.stdout is not None
    assert p.stdout.readline().strip() == "started"
    time.sleep(0.5)
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=60)
    report = json.loads(out.strip().splitlines()[-1])
    assert "message" in report, report
    assert "interrupted after" in report["message"]
    assert p.returncode != 0 and "KeyboardInterrupt" in err and "PanicException" not in err


def test_cli_atlas_on_a_running_scheduler(client, capsys):
    """``burmester atlas --scheduler ADDRESS`` against the address of a real
    scheduler (the LocalCluster's, worker processes): the same JSON as in
    process; an address where nothing listens is one line, status 2."""
    import json

    from burmester.cli import main

    small = ["--driven-grid", "6", "5", "--driving-grid", "20", "16", "--json", "--top", "3"]
    assert main(["atlas", *small]) == 0
    local = json.loads(capsys.readouterr().out)
    assert main(["atlas", *small, "--scheduler", client.scheduler.address]) == 0
    remote = json.loads(capsys.readouterr().out)
    assert remote == local and len(remote["best"]) == 3
    assert main(["atlas", *small, "--scheduler", "tcp://127.0.0.1:9"]) == 2
    err = capsys.readouterr().err
    assert "cannot reach the Dask scheduler" in err and err.count("\n") == 1


def test_unpickling_refuses_state_no_atlas_has():
    """Issue 24, item 7 for the Python-side PivotAtlas: pickled state whose
    arrays do not fit its grids, counts beyond the driving grid, a best
    index outside it or where the cell is not valid, a score without an
    index, an unknown ranking, or a missing part is refused with
    ``InvalidInputError(cause="inconsistent_state")``; the true state loads."""
    atlas = pivot_atlas(Task(POSES), Grid(-8, 8, -8, 8, 6, 5), Grid(-8, 8, -8, 8, 30, 30))
    assert pickle.loads(pickle.dumps(atlas)) == atlas
    j, i = np.argwhere(atlas.best_index[..., 0] >= 0)[0]

    def tampered(edit):
        state = {k: (v.copy() if isinstance(v, np.ndarray) else v) for k, v in atlas.__dict__.items()}
        state["options"] = dict(state["options"])
        edit(state)
        blob = pickle.dumps(atlas)
        back = pickle.loads(blob)  # a fresh object to hand the tampered state
        with pytest.raises(InvalidInputError) as e:
            back.__setstate__(state)
        assert e.value.cause == "inconsistent_state" and "PivotAtlas" in str(e.value), e.value
        return str(e.value)

    assert "count" in tampered(lambda s: s["count"].__setitem__((j, i), 10**6))
    assert "shape" in tampered(lambda s: s.__setitem__("best_score", s["best_score"][:, :-1]))
    assert "int64" in tampered(lambda s: s.__setitem__("best_index", s["best_index"].astype(np.int32)))
    assert "best_index" in tampered(lambda s: s["best_index"].__setitem__((j, i, 1), 30))
    assert "best_index" in tampered(lambda s: s["valid"].__setitem__((j, i), False))
    assert "best_score" in tampered(lambda s: s["best_score"].__setitem__((j, i), np.nan))
    assert "rank_by" in tampered(lambda s: s["options"].__setitem__("rank_by", "fastest"))
    assert "lacks" in tampered(lambda s: s.pop("driving"))
    assert "Task" in tampered(lambda s: s.__setitem__("task", "not a task"))
    # A pickle stream carrying bad state is refused when loaded.
    bad = pickle.loads(pickle.dumps(atlas))
    bad.__dict__["best_margin"] = bad.best_margin.astype(np.float32)
    with pytest.raises(InvalidInputError):
        pickle.loads(pickle.dumps(bad))
