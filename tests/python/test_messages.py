"""Messages that named the wrong thing or none (issue 24, item 12): each
names the field and what to change."""

import math
import subprocess
import sys

import pytest

import burmester
from burmester import DegenerateError, InvalidInputError, Task, cli, taskfile
from burmester.taskfile import TaskFileError
from conftest import FOUR


def test_four_poses_of_one_angle_are_translations_not_rotations_about_their_centroid():
    # Was: "the three poses are rotations about one point (0.75, 1)", the
    # centroid, which is no pole.
    t = Task([(0.0, 0.0, 0.3), (1.0, 0.0, 0.3), (1.0, 2.0, 0.3), (1.0, 2.0001, 0.3)])
    for call in (t.center_point_curve, t.circle_point_curve, lambda: t.curve_dyads(10),
                 lambda: t.pair_map(8), lambda: t.circle_point((3.0, 4.0))):
        with pytest.raises(DegenerateError) as e:
            call()
        assert e.value.cause == "all_translations", e.value
        assert "same angle" in str(e.value) and "rotate a pose" in str(e.value)
        assert "rotations about one point" not in str(e.value)


def test_poses_rotating_about_one_point_name_that_point_for_any_count():
    p = (2.0, -1.0)

    def about(angle, r=(3.0, 1.0)):
        c, s = math.cos(angle), math.sin(angle)
        return (p[0] + c * r[0] - s * r[1], p[1] + s * r[0] + c * r[1], angle)

    with pytest.raises(DegenerateError) as e:
        Task([about(a) for a in (0.0, 0.4, 0.9, 1.5)])
    assert e.value.cause == "coincident_poles"
    assert e.value.x == pytest.approx(2.0) and e.value.y == pytest.approx(-1.0)
    assert str(e.value).startswith("the poses are rotations about one point (")


@pytest.mark.parametrize("gap", [1e-9, 1e-8])
def test_a_pair_map_of_nearly_coincident_first_poses_says_which_poses(gap):
    # Was: "the viewport x from 0 to 0, y from 0 to 0 is empty".
    poses = list(FOUR)
    poses[1] = (poses[0][0] + gap, poses[0][1], poses[0][2] + gap)
    with pytest.raises(InvalidInputError) as e:
        Task(poses).pair_map(8)
    msg = str(e.value)
    assert e.value.cause == "too_small", msg
    assert "pose 1 to pose 2" in msg and "move pose 2 away from pose 1" in msg and "viewport" not in msg
    # Far enough apart, the map is made.
    poses[1] = (poses[0][0] + 1e-3, poses[0][1], poses[0][2] + 1e-3)
    assert Task(poses).pair_map(8).shape == (8, 8)


BIG = "1" + "0" * 400


def _task_text(x2="2.0"):
    return taskfile.dumps(taskfile.example()).replace("x = 2.0\n", f"x = {x2}\n", 1)


def test_a_huge_integer_in_a_task_file_names_the_key(tmp_path):
    # Was: an OverflowError traceback (status 1).
    p = tmp_path / "big.toml"
    p.write_text(_task_text(BIG))
    with pytest.raises(TaskFileError) as e:
        taskfile.load(p)
    msg = str(e.value)
    assert "pose 2.x" in msg and "an integer of 401 digits" in msg and len(msg) < 300, msg
    grid = _task_text().replace("grid = [400, 400]", f"grid = [{BIG}, 400]")
    with pytest.raises(TaskFileError, match=r"view.grid\[0\].*an integer of 401 digits"):
        taskfile.loads(grid, "g.toml")


def test_the_cli_and_batch_report_a_huge_integer_and_go_on(tmp_path, capsys):
    good, big = tmp_path / "good.toml", tmp_path / "big.toml"
    good.write_text(_task_text().replace("grid = [400, 400]", "grid = [40, 40]"))
    big.write_text(_task_text(BIG))
    assert cli.main(["map", str(big), "-o", str(tmp_path / "m.png")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "401 digits" in err and "Traceback" not in err
    # Was: `burmester batch good big good` printed nothing at all.
    p = subprocess.run([sys.executable, "-m", "burmester", "batch", str(good), str(big), str(good), "--top", "1"],
                       capture_output=True, text=True, timeout=300)
    lines = p.stdout.strip().splitlines()
    assert p.returncode == 2 and len(lines) == 3, (p.returncode, p.stdout, p.stderr)
    assert '"pivots"' in lines[0] and '"pivots"' in lines[2]
    assert '"error"' in lines[1] and "401 digits" in lines[1]


def test_a_task_file_with_a_byte_order_mark_is_read(tmp_path):
    # Was: "not valid TOML" for a UTF-8 file some editors save with a BOM.
    text = _task_text()
    plain, bom = tmp_path / "plain.toml", tmp_path / "bom.toml"
    plain.write_text(text, encoding="utf-8")
    bom.write_bytes(b"\xef\xbb\xbf" + text.encode("utf-8"))
    assert taskfile.load(bom).poses == taskfile.load(plain).poses
    assert taskfile.loads("\ufeff" + text).poses == taskfile.loads(text).poses


# ---------------------------------------------------------------------------
# A Dask cluster without workers (a real LocalCluster, n_workers=0)


@pytest.fixture(scope="module")
def empty_client():
    distributed = pytest.importorskip("distributed")
    cluster = distributed.LocalCluster(n_workers=0, processes=True, dashboard_address=None)
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()


def test_a_cluster_without_workers_says_so(empty_client, monkeypatch, tmp_path):
    # Was: waiting for ever.
    import burmester.atlas

    monkeypatch.setattr(burmester.atlas, "DASK_WORKER_TIMEOUT", 1.0)
    task = Task([(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)])
    with pytest.raises(TimeoutError) as e:
        burmester.pivot_atlas(task, (-8, 8, -8, 8, 4, 4), (-8, 8, -8, 8, 8, 8), client=empty_client)
    msg = str(e.value)
    assert "has no workers (none joined in 1 s)" in msg and "start workers" in msg, msg
    assert empty_client.scheduler.address in msg
    with pytest.raises(TimeoutError, match="has no workers"):
        burmester.best_pivots_batch([taskfile.example()], client=empty_client)


def test_the_cli_says_a_scheduler_has_no_workers(empty_client, monkeypatch, capsys):
    import burmester.atlas

    monkeypatch.setattr(burmester.atlas, "DASK_WORKER_TIMEOUT", 1.0)
    address = empty_client.scheduler.address
    assert cli.main(["atlas", "--json", "--driven-grid", "4", "4", "--driving-grid", "8", "8",
                     "--scheduler", address]) == 2
    err = capsys.readouterr().err
    assert "burmester atlas: error: the Dask cluster at" in err and "has no workers" in err, err
