"""Batches of task files (burmester.best_pivots_batch, burmester batch): the
same records as 'burmester pivots --json' per file, in process and on a real
Dask cluster; a bad file gives its error line and status 2."""

import json

import pytest

import burmester
from burmester import Grid, taskfile
from burmester.cli import main
from burmester.taskfile import TaskSpec

CENTERS = [(4.0, -1.0), (5.0, 1.0), (-3.0, -4.0)]


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("batch")
    ex = taskfile.example()
    v = ex.view
    paths = []
    for n, c0 in enumerate(CENTERS):
        spec = TaskSpec(ex.poses, c0, Grid(v.xmin, v.xmax, v.ymin, v.ymax, 48 + 8 * n, 40), ex.limits)
        p = d / f"task{n}.toml"
        p.write_text(taskfile.dumps(spec), encoding="utf-8")
        paths.append(str(p))
    return paths


@pytest.fixture(scope="module")
def bad(tmp_path_factory):
    p = tmp_path_factory.mktemp("bad") / "bad.toml"
    p.write_text("[[pose]]\nx = 0.0\n", encoding="utf-8")
    return str(p)


def _pivots_json(path, capsys, *extra):
    capsys.readouterr()
    assert main(["pivots", path, "--json", *extra]) == 0
    return json.loads(capsys.readouterr().out)


def _lines(text):
    return [json.loads(line) for line in text.splitlines()]


def test_in_process_equals_pivots_json_per_file(files, capsys):
    want = [_pivots_json(p, capsys, "--top", "3") for p in files]
    assert all(w["pivots"] for w in want)
    assert burmester.best_pivots_batch(files, top=3) == want
    # TaskSpecs give the same records as their files.
    specs = [taskfile.load(p) for p in files]
    assert burmester.best_pivots_batch(specs, top=3) == want
    # The command: one JSON line per file, in order.
    assert main(["batch", *files, "--top", "3"]) == 0
    out = capsys.readouterr().out
    assert out.count("\n") == len(files)
    assert _lines(out) == want


def test_spacing_is_passed_through(files, capsys):
    want = _pivots_json(files[0], capsys, "--top", "4", "--spacing", "0.5")
    assert burmester.best_pivots_batch(files[:1], top=4, spacing=0.5) == [want]
    with pytest.raises(ValueError, match="top"):
        burmester.best_pivots_batch(files, top=0)
    with pytest.raises(ValueError, match="spacing"):
        burmester.best_pivots_batch(files, spacing=-1.0)


def test_a_bad_file_gives_its_error_line_and_status_2(files, bad, tmp_path, capsys):
    missing = str(tmp_path / "missing.toml")
    four = tmp_path / "four.toml"
    four.write_text(
        "".join(f"[[pose]]\nx = {x}\ny = {y}\nangle_deg = {a}\n\n"
                for x, y, a in ((0, 0, 0), (2, 0.5, 20), (3, 2, 60), (2, 4, 100))),
        encoding="utf-8",
    )
    capsys.readouterr()
    assert main(["batch", files[0], bad, missing, str(four), files[1], "--top", "2"]) == 2
    cap = capsys.readouterr()
    lines = _lines(cap.out)
    assert len(lines) == 5
    assert lines[0] == _pivots_json(files[0], capsys, "--top", "2")
    assert lines[4] == _pivots_json(files[1], capsys, "--top", "2")
    for line, path, words in ((lines[1], bad, "pose"), (lines[2], missing, "no such file"),
                              (lines[3], str(four), "three")):
        assert set(line) == {"task", "error"} and line["task"] == path
        assert words in line["error"], line
    assert cap.err.count("burmester batch: error:") == 3
    # The usage errors of the command itself: status 2 before any work.
    assert main(["batch"]) == 2
    assert main(["batch", files[0], "--spacing", "-1"]) == 2


def test_client_without_dask_says_how_to_install(files, monkeypatch):
    import importlib

    real = importlib.import_module

    def no_dask(name, *a, **k):
        if name == "distributed":
            raise ImportError(name)
        return real(name, *a, **k)

    monkeypatch.setattr(importlib, "import_module", no_dask)
    with pytest.raises(ImportError, match=r"burmester\[dask\]"):
        burmester.best_pivots_batch(files, client=object())


def test_dask_gives_identical_lines(files, bad, client, capsys):
    items = [files[0], bad, files[1], files[2]]
    here = burmester.best_pivots_batch(items, top=3)
    there = burmester.best_pivots_batch(items, top=3, client=client)
    assert json.dumps(there) == json.dumps(here)
    assert "error" in there[1] and all("pivots" in r for r in there[::2])
    # The command on the cluster's scheduler: the same lines, status 2.
    capsys.readouterr()
    assert main(["batch", *items, "--top", "3"]) == 2
    local = capsys.readouterr().out
    assert main(["batch", *items, "--top", "3", "--scheduler", client.scheduler.address]) == 2
    remote = capsys.readouterr().out
    assert remote == local and len(local.splitlines()) == 4
