"""The release artefacts, as a user gets them: run by ``.ci/run`` after it
builds them (not part of ``python -m pytest``, which reads tests/python).

- The wheel, the sdist and the crate archive each carry both licence files,
  the same texts as the repository's.
- The wheel installs into a clean virtual environment whose ``PATH`` has no
  Rust toolchain (no ``cargo``, no ``rustc``, no rustup environment), with
  its ``plot`` extra, and there ``burmester map -o map.png`` draws the
  built-in example; the ``plot`` extra does not install IPython.

The artefacts are found in ``$BURMESTER_DIST`` (default ``dist/``: the
wheel and the sdist) and ``target/package/`` (the ``.crate`` of ``cargo
package -p burmester``).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path

import pytest

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[2]
DIST = Path(os.environ.get("BURMESTER_DIST", ROOT / "dist"))
LICENCES = ("LICENSE-MIT", "LICENSE-APACHE")
VERSION = tomllib.loads((ROOT / "Cargo.toml").read_text())["workspace"]["package"]["version"]


def one(folder: Path, pattern: str) -> Path:
    found = sorted(folder.glob(pattern))
    if len(found) != 1:
        pytest.fail(f"expected one {pattern} in {folder}, found {[p.name for p in found]}; "
                    "build it first (see .ci/run)")
    return found[0]


def licence_text(name: str) -> bytes:
    return (ROOT / name).read_bytes()


def test_the_licence_files_are_the_licences():
    mit, apache = licence_text("LICENSE-MIT"), licence_text("LICENSE-APACHE")
    assert mit.startswith(b"MIT License") and b"Permission is hereby granted, free of charge" in mit
    assert b"Apache License" in apache and b"Version 2.0, January 2004" in apache
    assert b"END OF TERMS AND CONDITIONS" in apache
    # The crate's copies are links to the same files (cargo package follows them).
    for name in LICENCES:
        assert (ROOT / "crates" / "burmester" / name).read_bytes() == licence_text(name)


def test_wheel_has_both_licences_and_the_version():
    wheel = one(DIST, f"burmester-{VERSION}-*.whl")
    with zipfile.ZipFile(wheel) as z:
        names = z.namelist()
        for name in LICENCES:
            path = f"burmester-{VERSION}.dist-info/licenses/{name}"
            assert path in names, names
            assert z.read(path) == licence_text(name)
        meta = z.read(f"burmester-{VERSION}.dist-info/METADATA").decode()
    assert f"Version: {VERSION}\n" in meta
    assert "License-Expression: MIT OR Apache-2.0" in meta
    assert "License-File: LICENSE-MIT" in meta and "License-File: LICENSE-APACHE" in meta
    # The extras: plot without the notebook's pieces.
    plot = [ln for ln in meta.splitlines() if ln.startswith("Requires-Dist:") and "extra == 'plot'" in ln]
    assert plot and not any(w in ln.lower() for ln in plot for w in ("ipympl", "ipython", "ipywidgets"))
    assert any("ipympl" in ln and "extra == 'notebook'" in ln for ln in meta.splitlines())


def test_sdist_has_both_licences():
    sdist = one(DIST, f"burmester-{VERSION}.tar.gz")
    with tarfile.open(sdist) as t:
        for name in LICENCES:
            member = t.extractfile(f"burmester-{VERSION}/{name}")
            assert member is not None and member.read() == licence_text(name)


def test_crate_has_both_licences():
    target = Path(os.environ.get("CARGO_TARGET_DIR") or ROOT / "target")  # where cargo package wrote it
    crate = one(target / "package", f"burmester-{VERSION}.crate")
    with tarfile.open(crate) as t:
        names = t.getnames()
        for name in LICENCES:
            member = t.extractfile(f"burmester-{VERSION}/{name}")
            assert member is not None and member.read() == licence_text(name), names
        assert f"burmester-{VERSION}/examples/three_pose.rs" in names
        assert f"burmester-{VERSION}/examples/four_five_pose.rs" in names


def without_rust(env: dict) -> dict:
    """``env`` with every ``PATH`` entry that holds cargo or rustc left out
    and the rustup and cargo variables removed."""
    out = {k: v for k, v in env.items() if not k.startswith(("CARGO", "RUSTUP", "RUSTC", "RUST_"))}
    keep = [d for d in env.get("PATH", "").split(os.pathsep)
            if d and not any(Path(d, tool).exists() for tool in ("cargo", "rustc", "rustup"))]
    out["PATH"] = os.pathsep.join(keep)
    return out


def test_wheel_runs_the_main_command_in_a_clean_venv_without_rust(tmp_path):
    wheel = one(DIST, f"burmester-{VERSION}-*.whl")
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    bindir = venv / ("Scripts" if os.name == "nt" else "bin")
    env = without_rust(dict(os.environ))
    env["PATH"] = os.pathsep.join([str(bindir), env["PATH"]])
    env.pop("PYTHONPATH", None)
    env.pop("VIRTUAL_ENV", None)
    assert shutil.which("cargo", path=env["PATH"]) is None and shutil.which("rustc", path=env["PATH"]) is None
    py = str(bindir / "python")
    # Only binary wheels: nothing may be compiled, and there is no Rust to compile with.
    subprocess.run([py, "-m", "pip", "install", "-q", "--disable-pip-version-check", "--only-binary", ":all:",
                    f"{wheel}[plot]"], check=True, env=env, cwd=tmp_path)
    work = tmp_path / "work"
    work.mkdir()
    run = subprocess.run([str(bindir / "burmester"), "map", "-o", "map.png"], env=env, cwd=work,
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    assert run.stdout.startswith("wrote map.png: center-point plane of <example>"), run.stdout
    png = (work / "map.png").read_bytes()
    assert png.startswith(b"\x89PNG\r\n\x1a\n") and len(png) > 20_000
    # The package that ran is the installed wheel's, not the source tree's.
    where = subprocess.run([py, "-c", "import burmester, sys; print(burmester.__file__, burmester.__version__)"],
                           env=env, cwd=work, capture_output=True, text=True, check=True).stdout.split()
    assert Path(where[0]).is_relative_to(venv) and where[1] == VERSION
    # The plot extra does not pull in IPython (it moved to the notebook extra).
    ipy = subprocess.run([py, "-c", "import importlib.util as u; print(u.find_spec('IPython') is None)"],
                         env=env, cwd=work, capture_output=True, text=True, check=True)
    assert ipy.stdout.strip() == "True"


def test_the_site_has_every_gallery_picture_and_the_readmes():
    """After ``mkdocs build --strict`` (which fails when a gallery script
    raises): every ``docs/gallery/plot_*.py`` has its page and at least one
    picture that is not blank, and the README's pictures are in the site."""
    site = Path(os.environ.get("BURMESTER_SITE", ROOT / "site"))
    gallery = site / "generated" / "gallery"
    scripts = sorted((ROOT / "docs" / "gallery").glob("plot_*.py"))
    assert len(scripts) >= 9
    for script in scripts:
        name = script.stem
        assert (gallery / name / "index.html").is_file(), name
        pictures = sorted((gallery / "images").glob(f"mkd_glr_{name}_*.png"))
        assert pictures, f"{name} drew no picture"
        for picture in pictures:
            data = picture.read_bytes()
            assert data.startswith(b"\x89PNG\r\n\x1a\n") and len(data) > 10_000, picture.name
    for readme_picture in ("map.png", "four-five.png", "explorer.png", "pair-map.png"):
        assert (site / readme_picture).read_bytes() == (ROOT / "docs" / readme_picture).read_bytes()
    # The API reference was generated from the stub: a native class and its docstring.
    api = (site / "reference" / "python" / "index.html").read_text(encoding="utf-8")
    assert "burmester.SolutionMap" in api or "SolutionMap" in api
    assert "best_pivots" in api and "Three to five poses of the coupler" in api
