"""Every file burmester writes is written whole to a temporary file beside
the target and moved into place only when complete (``burmester._io``,
issue 24 item 11): a write error, a full disk or Ctrl-C leaves no partial
file and never damages an existing one; without ``--force`` an existing
file is never replaced, decided at the move (a file created while the
command ran is kept)."""

import errno
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import burmester
from burmester import _io, cli, taskfile

pytest.importorskip("matplotlib")
ezdxf = pytest.importorskip("ezdxf")

OLD = b"a user's file that must survive\n"


def leftovers(folder: Path, keep=()):
    """Files in ``folder`` other than ``keep`` (temporary files left behind)."""
    return sorted(p.name for p in folder.iterdir() if p.name not in keep)


# ---------------------------------------------------------------------------
# The helper


def test_a_complete_file_is_moved_into_place(tmp_path):
    target = tmp_path / "out.txt"
    with _io.atomic_path(target, overwrite=False) as tmp:
        assert tmp.parent == tmp_path and tmp.suffix == ".txt" and tmp.name.startswith(".out.txt.")
        assert not target.exists()  # nothing at the target while writing
        tmp.write_bytes(b"new")
    assert target.read_bytes() == b"new"
    assert leftovers(tmp_path) == ["out.txt"]


@pytest.mark.parametrize("error", [OSError(errno.ENOSPC, "No space left on device"), KeyboardInterrupt()])
@pytest.mark.parametrize("existing", [False, True])
def test_an_error_while_writing_leaves_nothing_and_keeps_the_old_file(tmp_path, error, existing):
    target = tmp_path / "out.dxf"
    if existing:
        target.write_bytes(OLD)
    with pytest.raises(type(error)):
        with _io.atomic_path(target, overwrite=True) as tmp:
            tmp.write_bytes(b"half a fi")
            raise error
    assert (target.read_bytes() == OLD) if existing else not target.exists()
    assert leftovers(tmp_path) == (["out.dxf"] if existing else [])


def test_without_overwrite_a_file_created_meanwhile_is_kept(tmp_path):
    target = tmp_path / "out.png"
    with pytest.raises(FileExistsError):
        with _io.atomic_path(target, overwrite=False) as tmp:
            tmp.write_bytes(b"ours")
            target.write_bytes(OLD)  # another program, while we write
    assert target.read_bytes() == OLD
    assert leftovers(tmp_path) == ["out.png"]


def test_without_hard_links_the_name_is_claimed_exclusively(tmp_path, monkeypatch):
    def no_links(src, dst):
        raise OSError(errno.EPERM, "Operation not permitted")

    monkeypatch.setattr(os, "link", no_links)
    target = tmp_path / "out.svg"
    _io.write_bytes(target, b"first", overwrite=False)
    assert target.read_bytes() == b"first"
    with pytest.raises(FileExistsError):
        _io.write_bytes(target, b"second", overwrite=False)
    assert target.read_bytes() == b"first"
    _io.write_bytes(target, b"third", overwrite=True)
    assert target.read_bytes() == b"third"
    assert leftovers(tmp_path) == ["out.svg"]


def test_a_new_file_gets_the_usual_permissions(tmp_path):
    old = os.umask(0o022)
    try:
        _io.write_bytes(tmp_path / "a.toml", b"x")
    finally:
        os.umask(old)
    assert (tmp_path / "a.toml").stat().st_mode & 0o777 == 0o644


# ---------------------------------------------------------------------------
# The command line: an injected write error


def _partial_then(err):
    """A writer that writes part of a file to the path it is given, then fails."""

    def write(path, *args, **kwargs):
        Path(path).write_bytes(b"0\nSECTION\n2\nHEA")
        raise err

    return write


ENOSPC = OSError(errno.ENOSPC, "No space left on device")


def _inject(monkeypatch, kind):
    """Make the writer of ``kind`` fail half way with a full disk."""
    import matplotlib.animation
    import matplotlib.figure

    import burmester.export

    if kind == "dxf":
        monkeypatch.setattr(burmester.export, "_WRITERS", {**burmester.export._WRITERS,
                                                           ".dxf": lambda d, path, units: _partial_then(ENOSPC)(path)})
    elif kind == "png":
        monkeypatch.setattr(matplotlib.figure.Figure, "savefig",
                            lambda self, path, **kw: _partial_then(ENOSPC)(path))
    elif kind == "gif":
        monkeypatch.setattr(matplotlib.animation.Animation, "save",
                            lambda self, path, **kw: _partial_then(ENOSPC)(path))
    elif kind == "toml":
        monkeypatch.setattr(Path, "write_text", lambda self, *a, **kw: _partial_then(ENOSPC)(self))


COMMANDS = {
    "dxf": ["map", "--grid", "60", "60", "-o", "{out}"],
    "png": ["map", "--grid", "60", "60", "-o", "{out}"],
    "gif": ["linkage", "--frames", "4", "-o", "{out}"],
    "toml": ["example", "-o", "{out}"],
}


@pytest.mark.parametrize("kind", sorted(COMMANDS))
@pytest.mark.parametrize("force", [False, True])
def test_a_write_error_leaves_no_partial_file_and_keeps_the_old_one(tmp_path, monkeypatch, capsys, kind, force):
    out = tmp_path / f"out.{kind}"
    if force:
        out.write_bytes(OLD)
    _inject(monkeypatch, kind)
    argv = [a.format(out=out) for a in COMMANDS[kind]] + (["--force"] if force else [])
    assert cli.main(argv) == 2
    err = capsys.readouterr().err
    assert f"cannot write {out}" in err and "No space left on device" in err, err
    if force:
        assert out.read_bytes() == OLD and "is unchanged" in err
        assert leftovers(tmp_path) == [out.name]
    else:
        assert not out.exists()
        assert leftovers(tmp_path) == []


@pytest.mark.parametrize("kind", ["dxf", "png", "toml"])
def test_a_file_created_while_the_command_runs_is_not_replaced(tmp_path, monkeypatch, capsys, kind):
    out = tmp_path / f"out.{kind}"
    import matplotlib.figure

    import burmester.export

    # Another program creates the output after the command checked the name
    # and before it moves its file into place.
    if kind == "dxf":
        real = burmester.export._WRITERS[".dxf"]

        def meanwhile(d, path, units):
            out.write_bytes(OLD)
            real(d, path, units)

        monkeypatch.setattr(burmester.export, "_WRITERS", {**burmester.export._WRITERS, ".dxf": meanwhile})
    elif kind == "png":
        real_save = matplotlib.figure.Figure.savefig

        def meanwhile_png(self, path, **kw):
            out.write_bytes(OLD)
            real_save(self, path, **kw)

        monkeypatch.setattr(matplotlib.figure.Figure, "savefig", meanwhile_png)
    else:
        real_text = Path.write_text

        def meanwhile_text(self, *a, **kw):
            out.write_bytes(OLD)
            return real_text(self, *a, **kw)

        monkeypatch.setattr(Path, "write_text", meanwhile_text)
    argv = [a.format(out=out) for a in COMMANDS[kind]]
    assert cli.main(argv) == 2
    err = capsys.readouterr().err
    assert f"{out} exists (it was created while this command ran)" in err and "--force" in err
    assert out.read_bytes() == OLD
    assert leftovers(tmp_path) == [out.name]


def test_force_replaces_the_file_with_a_complete_one(tmp_path, capsys):
    out = tmp_path / "plane.dxf"
    out.write_bytes(OLD)
    assert cli.main(["map", "--grid", "60", "60", "-o", str(out)]) == 2  # exists, no --force
    assert out.read_bytes() == OLD
    assert cli.main(["map", "--grid", "60", "60", "-o", str(out), "--force"]) == 0
    doc = ezdxf.readfile(out)
    assert "BRANCH_FREE" in [layer.dxf.name for layer in doc.layers]
    assert leftovers(tmp_path) == ["plane.dxf"]


def test_library_writers_replace_whole_files(tmp_path):
    """``burmester.export``, ``taskfile.save`` and the explorer's ``save``
    write through the helper too (replacing by default, as documented)."""
    spec = taskfile.example()
    p = tmp_path / "task.toml"
    p.write_bytes(OLD)
    taskfile.save(spec, p)
    back = [v for pose in taskfile.load(p).poses for v in pose]
    assert back == pytest.approx([v for pose in spec.poses for v in pose])  # degrees and back
    with pytest.raises(FileExistsError):
        taskfile.save(spec, p, overwrite=False)
    from burmester import export

    sfb = spec.filemon().four_bar((-3.0, 4.0))
    export.linkage(sfb, tmp_path / "l.svg", task=spec.task)
    assert (tmp_path / "l.svg").read_text().startswith("<?xml")
    assert leftovers(tmp_path) == ["l.svg", "task.toml"]


# ---------------------------------------------------------------------------
# A real full disk: a small tmpfs (needs root and mount; skipped otherwise)


@pytest.fixture
def tiny_disk(tmp_path):
    mnt = tmp_path / "tiny"
    mnt.mkdir()
    if sys.platform != "linux" or os.geteuid() != 0:
        pytest.skip("mounting a tmpfs needs root on Linux")
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=48k", "tmpfs", str(mnt)],
                       capture_output=True, text=True)
    if r.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs: {r.stderr.strip()}")
    try:
        yield mnt
    finally:
        subprocess.run(["umount", str(mnt)], capture_output=True)


@pytest.mark.parametrize("force", [False, True])
def test_a_full_disk_leaves_no_partial_file(tiny_disk, capsys, force):
    out = tiny_disk / "plane.dxf"
    if force:
        out.write_bytes(OLD)
    argv = ["map", "--grid", "200", "200", "-o", str(out)] + (["--force"] if force else [])
    assert cli.main(argv) == 2
    err = capsys.readouterr().err
    assert "No space left on device" in err, err
    assert (out.read_bytes() == OLD) if force else not out.exists()
    assert leftovers(tiny_disk) == (["plane.dxf"] if force else [])


# ---------------------------------------------------------------------------
# Ctrl-C while writing (a real SIGINT to the command)


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
@pytest.mark.parametrize("force", [False, True])
def test_ctrl_c_while_writing_leaves_no_partial_file(tmp_path, force):
    out = tmp_path / "l.gif"
    if force:
        out.write_bytes(OLD)
    argv = [sys.executable, "-m", "burmester", "linkage", "--frames", "400", "-o", str(out)]
    p = subprocess.Popen(argv + (["--force"] if force else []), stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, env={**os.environ, "MPLBACKEND": "Agg"})
    try:
        # The temporary file appears when the writing starts.
        deadline = time.monotonic() + 60
        while not any(n.startswith(".l.gif.") for n in os.listdir(tmp_path)):
            assert p.poll() is None, p.communicate()
            assert time.monotonic() < deadline
            time.sleep(0.005)
        time.sleep(0.3)
        assert p.poll() is None, "the animation was written before the signal; make it longer"
        p.send_signal(signal.SIGINT)
        _, err = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            p.kill()
    assert p.returncode == 130 and "interrupted" in err, (p.returncode, err)
    assert (out.read_bytes() == OLD) if force else not out.exists()
    assert leftovers(tmp_path) == (["l.gif"] if force else [])


# ---------------------------------------------------------------------------
# What cannot fit in memory is refused up front (issue 24, item 9:
# `map --grid 20000 20000 -o x.png` grew to 24 GB and was killed)


@pytest.mark.skipif(sys.platform != "linux", reason="RLIMIT_AS and /proc")
@pytest.mark.parametrize("argv", [
    ["map", "--grid", "20000", "20000", "-o", "{dir}/x.png"],
    ["map", "--grid", "20000", "20000", "-o", "{dir}/x.dxf"],
    ["pivots", "--grid", "20000", "20000"],
])
def test_a_grid_that_cannot_fit_is_refused_before_the_work(tmp_path, argv):
    # A real limit: 2 GiB of address space for the command.
    child = ("import resource, sys; resource.setrlimit(resource.RLIMIT_AS, (2**31, 2**31)); "
             "from burmester.cli import main; sys.exit(main(sys.argv[1:]))")
    args = [a.format(dir=tmp_path) for a in argv]
    t0 = time.monotonic()
    p = subprocess.run([sys.executable, "-c", child, *args], capture_output=True, text=True, timeout=120,
                       env={**os.environ, "MPLBACKEND": "Agg"})
    assert p.returncode == 2, (p.returncode, p.stderr[-2000:])
    assert "on 20000 x 20000 samples needs about" in p.stderr and "use a coarser --grid" in p.stderr, p.stderr
    assert "fits)" in p.stderr
    assert leftovers(tmp_path) == []


def test_the_memory_check_uses_the_memory_left(monkeypatch, tmp_path, capsys):
    monkeypatch.setattr(cli.base, "_available_memory", lambda: 4 * 2**30)
    out = tmp_path / "x.png"
    assert cli.main(["map", "--grid", "20000", "20000", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    # 128 MiB + 4e8 samples x 64 bytes = 24.0 GiB, against 4 GiB: the
    # square that fits is sqrt((4 GiB - 128 MiB) / 64) = 8062 a side.
    assert "needs about 24.0 GB of memory (64 bytes a sample), more than the 4.0 GB available" in err, err
    assert "about 8062 x 8062 fits" in err, err
    assert not out.exists()
    # A grid that fits goes on.
    assert cli.main(["map", "--grid", "100", "100", "-o", str(out)]) == 0 and out.exists()


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
def test_an_interrupt_a_library_turns_into_another_error_is_still_an_interrupt(tmp_path, monkeypatch, capsys):
    # matplotlib's C code, running the signal handler, can replace the
    # KeyboardInterrupt by "Invalid affine transformation matrix" (seen once
    # in the SIGINT test above); the command still ends as interrupted.
    import matplotlib.figure

    def savefig(self, path, **kw):
        Path(path).write_bytes(b"\x89PNG half")
        try:
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(5)
        except KeyboardInterrupt:
            raise ValueError("Invalid affine transformation matrix") from None

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", savefig)
    out = tmp_path / "x.png"
    assert cli.main(["map", "--grid", "40", "40", "-o", str(out)]) == 130
    assert "burmester map: interrupted" in capsys.readouterr().err
    assert leftovers(tmp_path) == []
    # The handler the command put in place is gone again.
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
