"""Every native function at its documented maximum under an address-space
limit (``resource.setrlimit(RLIMIT_AS)``) in a child process: the answer or
``MemoryError``, never an abort of the interpreter (issue 24, item 9:
``curve_dyads(10**7)`` under 2 GB died with "memory allocation of
1120000112 bytes failed"). Every allocation sized by the input goes through
the fallible path: the core's ``try_vec`` family, NumPy's allocator, or
Python's."""

import json
import os
import subprocess
import sys
import textwrap

import pytest

from conftest import C0, FOUR, POSES, VP

pytestmark = pytest.mark.skipif(sys.platform != "linux", reason="RLIMIT_AS and /proc")

#: The child: builds what the call needs (small), uses every thread once
#: (rayon's pool, allocators), then limits its address space to what it
#: uses now plus ``headroom`` MiB and makes the call.
CHILD = textwrap.dedent(
    """
    import json, math, resource, sys
    import numpy as np
    import burmester
    from burmester import Conic, Cubic, FourBar, Grid, Task, pivot_atlas
    POSES, C0, VP, FOUR = {poses!r}, {c0!r}, {vp!r}, {four!r}
    name, headroom = sys.argv[1], int(sys.argv[2])
    t3 = Task(POSES)
    f = t3.filemon(C0)
    t4 = Task(FOUR)
    big = Grid(*VP, 65536, 65536)            # 2**32 samples: Grid's documented maximum
    row = Grid(*VP, 2**32, 1)
    small_map = f.solution_map(Grid(*VP, 256, 256))
    small_pairs = t4.pair_map(256)
    f.branch_map(Grid(*VP, 512, 512))        # the thread pool started before the limit
    fb = FourBar(ground=4, crank=1, coupler=3, rocker=3)
    slider = t3.slider_dyads(1)[0]
    sf = burmester.SliderFilemon(t3, slider.circle, slider.guide)
    sf.solution_map(Grid(*VP, 64, 64))
    calls = {{
        "branch_map": lambda: f.branch_map(big),
        "branch_map_row": lambda: f.branch_map(row),
        "branch_map_wide": lambda: f.branch_map(Grid(*VP, 2**27, 1)),
        "branch_map_simulate": lambda: f.branch_map(big, "simulate"),
        "margin_map": lambda: f.margin_map(big),
        "margin_map_wide": lambda: f.margin_map(Grid(*VP, 2**27, 1)),
        "solution_map": lambda: f.solution_map(big),
        "solution_map_wide": lambda: f.solution_map(Grid(*VP, 2**25, 1)),
        "driven_solution_map": lambda: t3.driven_solution_map((-3.0, 4.0), big),
        "cell_centers": lambda: row.cell_centers(),
        "curve_dyads": lambda: t4.curve_dyads(10**7),
        "pair_map": lambda: t4.pair_map(65536, 65536),
        "pair_map_long": lambda: t4.pair_map(10**7, 429),
        "atlas_driven": lambda: pivot_atlas(t3, big, (-8, 8, -8, 8, 2, 2)),
        "atlas_driving": lambda: pivot_atlas(t3, (-8, 8, -8, 8, 1, 1), row),
        "best_pivots": lambda: small_map.best_pivots(2**62, 0.0),
        "best_pivots_margin": lambda: small_map.best_pivots(2**62, 0.0, rank_by="margin"),
        "pareto_front": lambda: small_map.pareto_front(),
        "best_pairs": lambda: small_pairs.best_pairs(2**62, 0.0),
        "best_pairs_margin": lambda: small_pairs.best_pairs(2**62, 0.0, rank_by="margin"),
        "margins": lambda: small_pairs.margins(),
        "conic_polylines": lambda: Conic(1, 0, 1, 0, 0, -1).polylines(-2, 2, -2, 2, tolerance=4e-9 * math.sqrt(2)),
        "cubic_polylines": lambda: t4.center_point_curve().polylines(-50, 50, -50, 50, tolerance=1e-9 * 100 * math.sqrt(2)),
        "circle_points": lambda: t3.circle_points(np.zeros((2 * 10**7, 2))),
        "evaluate_many": lambda: Conic(1, 0, 1, 0, 0, -1).evaluate_many(np.zeros((2 * 10**7, 2))),
        "solve_many": lambda: fb.solve_many(np.zeros(4 * 10**7)),
        "coupler_path": lambda: fb.coupler_path((1.0, 0.5), np.zeros(4 * 10**7)),
        "travel_angles": lambda: f.four_bar((-3.0, 4.0)).travel_angles(2**20),
        "slider_solution_map": lambda: sf.solution_map(big),
    }}
    call = calls[name]
    def vm():
        with open("/proc/self/status") as fh:
            for line in fh:
                if line.startswith("VmSize:"):
                    return int(line.split()[1]) * 1024
    limit = vm() + headroom * 2**20
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    try:
        call()
        out = "ok"
    except MemoryError as e:
        out = "memory: " + str(e)
    except burmester.InvalidInputError as e:
        out = "invalid: " + e.cause
    print(json.dumps(out), flush=True)
    """
).format(poses=POSES, c0=C0, vp=VP, four=FOUR)

#: Each call with its address-space headroom (MiB) and what it may answer
#: ("ok": success, "memory": MemoryError, "too_large": the documented
#: budget of the polylines). Headrooms are chosen so that the call's
#: largest buffer does not fit (every path to a MemoryError is taken) but
#: its smaller ones do.
CASES = {
    "branch_map": (512, {"memory"}),
    "branch_map_row": (512, {"memory"}),
    "branch_map_wide": (512, {"memory"}),          # the output fits, a row's abscissae do not
    "branch_map_simulate": (512, {"memory"}),
    "margin_map": (512, {"memory"}),
    "margin_map_wide": (900, {"memory"}),          # 512 MiB of output, 1 GiB of abscissae
    "solution_map": (512, {"memory"}),
    "solution_map_wide": (1200, {"memory"}),       # 640 MiB of columns, 2.4 GiB of row lanes
    "driven_solution_map": (512, {"memory"}),
    "cell_centers": (512, {"memory"}),
    "curve_dyads": (256, {"memory"}),              # 560 MB of dyads for one branch
    "pair_map": (512, {"memory"}),
    "pair_map_long": (256, {"memory"}),            # ten million dyads on one axis
    "atlas_driven": (512, {"memory"}),
    "atlas_driving": (512, {"memory"}),
    "best_pivots": (256, {"ok"}),
    "best_pivots_margin": (256, {"ok"}),
    "pareto_front": (256, {"ok"}),
    "best_pairs": (256, {"ok"}),
    "best_pairs_margin": (256, {"ok"}),
    "margins": (256, {"ok"}),
    "conic_polylines": (512, {"ok", "too_large"}),
    "cubic_polylines": (512, {"ok", "too_large"}),
    "circle_points": (256, {"memory"}),            # 320 MB in, as much out
    "evaluate_many": (96, {"memory"}),             # 160 MB of values
    "solve_many": (256, {"memory"}),
    "coupler_path": (256, {"memory"}),
    "travel_angles": (256, {"ok"}),
    "slider_solution_map": (512, {"memory"}),      # a driven slider's map at Grid's maximum
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_the_documented_maximum_under_an_address_space_limit(name):
    headroom, allowed = CASES[name]
    env = {**os.environ, "MALLOC_ARENA_MAX": "2"}
    p = subprocess.run([sys.executable, "-c", CHILD, name, str(headroom)], capture_output=True, text=True,
                       timeout=600, env=env, cwd=os.path.dirname(__file__))
    assert p.returncode == 0, f"the interpreter died ({p.returncode}): {p.stderr[-2000:]}"
    assert "panicked" not in p.stderr, p.stderr
    out = json.loads(p.stdout.strip().splitlines()[-1])
    kind = out.split(":")[0] if not out.startswith("invalid: too_large") else "too_large"
    assert kind in allowed, out
    if kind == "memory":
        # The message says what could not be allocated (the core's, or NumPy's).
        assert len(out) > len("memory: "), out
