"""Large inputs are not copied: a C-contiguous float64 array is read in
place and the results are written straight into the arrays handed back, so
a call grows the process by about the size of its output (issue 15, item 9).
Other inputs (lists, other dtypes, strided or Fortran-ordered views) are
converted once and give the same results."""

import json
import subprocess
import sys
import textwrap

import numpy as np
import pytest

from burmester import Conic, FourBar, Task
from conftest import POSES

#: The child: makes the input, warms the call up on a tiny one, then reports
#: the growth of its peak RSS over one call on the large input.
CHILD = textwrap.dedent(
    """
    import json, resource, sys
    import numpy as np
    from burmester import Conic, FourBar, Task

    def peak():
        r = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        return r if sys.platform == "darwin" else r * 1024   # bytes on macOS, KiB on Linux

    which, n = sys.argv[1], int(sys.argv[2])
    rng = np.random.default_rng(0)
    if which == "circle_points":
        f = Task({poses!r}).circle_points
        a = rng.standard_normal((n, 2))
    elif which == "evaluate_many":
        f = Conic(1, 0, -1, 0, 0, -1).evaluate_many
        a = rng.standard_normal((n, 2))
    else:
        f = FourBar(ground=4, crank=1, coupler=3, rocker=3).solve_many
        a = rng.uniform(-4.0, 4.0, n)
    f(a[:4].copy())
    before = peak()
    r = f(a)
    grown = peak() - before
    out = sum(x.nbytes for x in r) if isinstance(r, tuple) else r.nbytes
    print(json.dumps({{"grown": grown, "out": out, "in": a.nbytes}}))
    """
).format(poses=POSES)


@pytest.mark.skipif(sys.platform == "win32", reason="resource.getrusage")
@pytest.mark.parametrize("which", ["circle_points", "evaluate_many", "solve_many"])
def test_large_input_is_not_copied(which):
    n = 2_000_000  # 32 MB of points in (16 MB of angles for solve_many)
    p = subprocess.run(
        [sys.executable, "-c", CHILD, which, str(n)], capture_output=True, text=True, timeout=60
    )
    assert p.returncode == 0, p.stderr
    r = json.loads(p.stdout)
    # The output arrays and a little slack; a copy of the input (or a
    # Rust-side buffer for the results) would grow it by another 16-32 MB.
    assert r["grown"] <= 1.25 * r["out"], r


def _same(a, b):
    for x, y in zip(a if isinstance(a, tuple) else (a,), b if isinstance(b, tuple) else (b,)):
        assert x.shape == y.shape and x.dtype == y.dtype
        np.testing.assert_array_equal(x, y)


def test_any_layout_gives_the_same_results():
    t = Task(POSES)
    c = Conic(1, 0, -1, 0, 0, -2)
    fb = FourBar(ground=4, crank=1, coupler=3, rocker=3)
    pts = np.random.default_rng(1).standard_normal((4, 3, 2)) * 3
    pts[0, 0] = np.nan
    ths = np.random.default_rng(2).uniform(-4.0, 4.0, (4, 3))
    readonly = pts.copy()
    readonly.flags.writeable = False
    variants = [
        pts.tolist(),
        np.asfortranarray(pts),
        pts.astype(">f8"),
        readonly,
        np.repeat(pts, 2, axis=1)[:, ::2],  # strided
        np.frombuffer(b"\0" + pts.tobytes(), dtype=np.float64, offset=1).reshape(pts.shape),  # misaligned
    ]
    for v in variants:
        _same(t.circle_points(v), t.circle_points(pts))
        _same(t.center_points(v), t.center_points(pts))
    finite = pts[1:]
    strided = np.repeat(finite, 2, axis=1)[:, ::2]
    for v in [finite.tolist(), np.asfortranarray(finite), finite.astype(">f8"), strided]:
        _same(c.evaluate_many(v), c.evaluate_many(finite))
    strided = np.repeat(ths, 2, axis=1)[:, ::2]
    for v in [ths.tolist(), np.asfortranarray(ths), ths.astype(">f8"), ths.T.copy().T, strided]:
        _same(fb.solve_many(v), fb.solve_many(ths))
        _same(fb.coupler_path((1.0, 0.5), v), fb.coupler_path((1.0, 0.5), ths))
    # float32 and ints: converted once, as float64.
    _same(fb.solve_many(ths.astype(np.float32)), fb.solve_many(ths.astype(np.float32).astype(np.float64)))


def test_input_is_read_not_written_and_outputs_are_fresh():
    t = Task(POSES)
    fb = FourBar(ground=4, crank=1, coupler=3, rocker=3)
    pts = np.random.default_rng(3).standard_normal((50, 2))
    keep = pts.copy()
    out, ok = t.circle_points(pts)
    np.testing.assert_array_equal(pts, keep)
    assert not np.shares_memory(out, pts)
    assert out.flags.writeable and out.flags.c_contiguous and ok.dtype == np.bool_
    ths = np.linspace(-3, 3, 40)
    t3, t4, ok = fb.solve_many(ths)
    assert np.array_equal(ths, np.linspace(-3, 3, 40))
    assert not np.shares_memory(t3, ths) and not np.shares_memory(t3, t4)
    # Writing into a result leaves the input and the other results alone.
    t3[:] = 7.0
    assert np.array_equal(ths, np.linspace(-3, 3, 40)) and not (t4 == 7.0).any()
