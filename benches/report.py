#!/usr/bin/env python3
"""Write BENCHMARKS.md from criterion's output (never typed by hand).

    python benches/report.py --run          # run the benches, then write the report
    python benches/report.py                # only write the report from target/criterion
    python benches/report.py --run --only drive_map   # one section, the others kept

``--run`` runs ``cargo bench`` for every bench named in SECTIONS and, when the
``burmester`` package is importable, the Python-side timings that SECTIONS
names (they are stored beside criterion's output, in
``target/criterion/python/``), so that every figure and ratio of the report
comes from one run on this machine.
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Optional

ROOT = Path(__file__).resolve().parent.parent
# Where cargo (run from ROOT) and criterion write: CARGO_TARGET_DIR if set.
CRITERION = ROOT / os.environ.get("CARGO_TARGET_DIR", "target") / "criterion"
OUT = ROOT / "BENCHMARKS.md"


@dataclass
class Ratio:
    """``numerator / denominator`` of two benchmark ids (mean times)."""

    name: str
    numerator: str
    denominator: str
    goal: str
    #: Pass when the ratio satisfies this predicate.
    ok: Callable[[float], bool]


@dataclass
class Section:
    title: str
    #: criterion id prefixes whose figures are listed.
    prefixes: list[str]
    #: cargo bench target names to run for this section (none: its figures
    #: are Python timings or another section's bench's).
    benches: list[str] = field(default_factory=list)
    ratios: list[Ratio] = field(default_factory=list)
    #: Python timings: id -> (setup, statement, elements); run with timeit.
    python: dict[str, tuple[str, str, int]] = field(default_factory=dict)
    note: str = ""
    #: Python timings: warm-up calls, calls per batch, batches (None: --python-repeat).
    python_runs: tuple[int, int, Optional[int]] = (5, 10, None)
    #: More lines after the tables, computed from the figures.
    extra: Optional[Callable[[dict[str, "Figure"]], list[str]]] = None


def bench_section(bench: str, title: str, **rest: Any) -> Section:
    """The section of the cargo bench ``bench``: runs it and lists its
    figures (the criterion ids under ``bench/``)."""
    return Section(title=title, benches=[bench], prefixes=[f"{bench}/"], **rest)


SECTIONS: list[Section] = [
    bench_section(
        "position",
        "Position analysis (`position`)",
        ratios=[
            Ratio(
                "four-bar 7.0.5 `pos()` / burmester `solve`",
                "position/single/four_bar_pos",
                "position/single/solve",
                ">= 2.5 (issue 13)",
                lambda r: r >= 2.5,
            ),
            Ratio(
                "four-bar 7.0.5 `pos()` / burmester `joints_at` + coupler point",
                "position/single/four_bar_pos",
                "position/single/joints_coupler",
                "(like for like, no goal)",
                lambda r: True,
            ),
            Ratio(
                "four-bar sweep / burmester `solve_into` sweep (3600 angles)",
                "position/sweep/four_bar_pos/3600",
                "position/sweep/solve_into/3600",
                ">= 4 (issue 13)",
                lambda r: r >= 4.0,
            ),
        ],
        note=(
            "`four-bar` is the Rust crate `four-bar` 7.0.5, measured in the same run on "
            "the same linkage (Norton's Example 4-1 with a coupler point). Its `pos()` "
            "returns five points, so `joints_coupler` does the same work; `solve` "
            "returns the two angles. `solve_into` is the batch kernel (loop closure and "
            "both `atan2` (the crate's own, two dependent divisions) on SIMD lanes picked at "
            "run time by `pulp`, AVX2 here; `sin` and "
            "`cos` from `libm` per angle), one thread below 2^14 angles, so the 3600-angle "
            "sweep is single-threaded like four-bar's. Pure-Python pylinkage is about 3.7 us "
            "per solve (figure from the issue, not measured here)."
        ),
    ),
]


SWEEP_SETUP = """
import numpy as np, burmester
from burmester._burmester import Task
t = Task([(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)])
f = t.filemon((4.0, -1.0))
vp = (-8.0, 8.0, -8.0, 8.0)
out = np.empty((4096, 4096), dtype=bool)
"""

SECTIONS.append(
    Section(
        title="Dense grid branch sweep (`branch_sweep`)",
        benches=["branch_sweep"],
        # Not "python/branch_map" alone: its `direct` figure belongs to the
        # solution map's section (below), timed by another run.
        prefixes=["branch_sweep/", "python/branch_map/fresh/", "python/branch_map/np_ones/",
                  "python/branch_map/out/", "python/branch_map/out_fill/"],
        ratios=[
            Ratio(
                "`conic` / `memset` at 4096^2",
                "branch_sweep/conic/4096",
                "branch_sweep/memset/4096",
                "<= 2",
                lambda r: r <= 2.0,
            ),
            Ratio(
                "`direct` / `conic` at 4096^2",
                "branch_sweep/direct/4096",
                "branch_sweep/conic/4096",
                ">= 10",
                lambda r: r >= 10.0,
            ),
            Ratio(
                "`simulate` / `conic` at 1024^2",
                "branch_sweep/simulate/1024",
                "branch_sweep/conic/1024",
                ">= 100",
                lambda r: r >= 100.0,
            ),
            Ratio(
                "`conic_pointwise` / `conic` at 4096^2 (runs against point by point)",
                "branch_sweep/conic_pointwise/4096",
                "branch_sweep/conic/4096",
                "(no goal)",
                lambda r: True,
            ),
            Ratio(
                "Python `branch_map(...)` / Rust `branch_map` (both allocate), 4096^2",
                "python/branch_map/fresh/4096",
                "branch_sweep/conic_alloc/4096",
                "<= 1.2",
                lambda r: r <= 1.2,
            ),
            Ratio(
                "Python `branch_map(..., out=)` / Rust `branch_map_into`, 4096^2",
                "python/branch_map/out/4096",
                "branch_sweep/conic/4096",
                "<= 1.2",
                lambda r: r <= 1.2,
            ),
            Ratio(
                "Python `branch_map(...)` (fresh) / `np.ones((4096, 4096), bool)`",
                "python/branch_map/fresh/4096",
                "python/branch_map/np_ones/4096",
                "<= 2",
                lambda r: r <= 2.0,
            ),
            Ratio(
                "Python `branch_map(..., out=)` / `out.fill(True)`, 4096^2",
                "python/branch_map/out/4096",
                "python/branch_map/out_fill/4096",
                "<= 1.5 (issue 13)",
                lambda r: r <= 1.5,
            ),
        ],
        python={
            "python/branch_map/fresh/4096": (
                SWEEP_SETUP,
                "f.branch_map(*vp, 4096, 4096)",
                4096 * 4096,
            ),
            "python/branch_map/out/4096": (
                SWEEP_SETUP,
                "f.branch_map(*vp, 4096, 4096, out=out)",
                4096 * 4096,
            ),
            "python/branch_map/np_ones/4096": (
                SWEEP_SETUP,
                "np.ones((4096, 4096), bool)",
                4096 * 4096,
            ),
            "python/branch_map/out_fill/4096": (
                SWEEP_SETUP,
                "out.fill(True)",
                4096 * 4096,
            ),
        },
        note=(
            "The built-in example task over (-8, 8)^2, throughput in grid points, rayon on "
            "all cores. `memset` fills a byte buffer of the same size (one thread): the "
            "floor for writing the map. `conic` writes into an existing buffer; "
            "`conic_alloc` allocates the map as `branch_map` does (fresh pages from the "
            "kernel). The Python figures are the mean over batches of back-to-back calls "
            "of the installed wheel (`pip install .`, release profile)."
        ),
    )
)


SECTIONS.append(
    Section(
        title="Solution-space map (`branch_sweep/solution_map`)",
        prefixes=[
            "branch_sweep/solution_map/",
            "branch_sweep/solution_map_into/",
            "python/solution_map/",
            "python/branch_map/direct/",
        ],
        ratios=[
            Ratio(
                "`solution_map` / `conic` branch map at 1024^2",
                "branch_sweep/solution_map/1024",
                "branch_sweep/conic/1024",
                "(<= 20 withdrawn by issue 13)",
                lambda r: True,
            ),
            Ratio(
                "Python `solution_map` / Python `branch_map(method=\"direct\")` at 1024^2 "
                "(both fresh arrays: the issue's figure)",
                "python/solution_map/fresh/1024",
                "python/branch_map/direct/1024",
                "<= 1 (issue 13)",
                lambda r: r <= 1.0,
            ),
            Ratio(
                "Rust `solution_map_into` / `direct` branch map at 1024^2 (both into "
                "existing buffers: the per-point cost)",
                "branch_sweep/solution_map_into/1024",
                "branch_sweep/direct/1024",
                "<= 1 (issue 13)",
                lambda r: r <= 1.0,
            ),
            Ratio(
                "Rust `solution_map` (fresh columns from the allocator) / `direct` into "
                "its buffer at 1024^2",
                "branch_sweep/solution_map/1024",
                "branch_sweep/direct/1024",
                "(unlike for like, no goal)",
                lambda r: True,
            ),
        ],
        python={
            "python/solution_map/fresh/1024": (
                SWEEP_SETUP,
                "f.solution_map(*vp, 1024, 1024)",
                1024 * 1024,
            ),
            "python/branch_map/direct/1024": (
                SWEEP_SETUP,
                "f.branch_map(*vp, 1024, 1024, method='direct')",
                1024 * 1024,
            ),
        },
        python_runs=(2, 5, None),
        note=(
            "The full designer's map (branch-free flag from the conic sweep, Grashof "
            "class, input type, order and circuit, exact minimum transmission angle over "
            "the travel, link ratio, acceptable mask; no constraints) for the built-in "
            "example, measured in the `branch_sweep` run beside the branch-only sweeps. "
            "The per-sample figures come from the per-pivot kernel (`design/kernel.rs`): "
            "the circle point, the motion, the lengths, the input bounds, order and "
            "circuit, the worst transmission and the Grashof class on SIMD lanes chosen "
            "at run time by `pulp` (AVX2 here), bit for bit the scalar path, with the "
            "crate's own `acos` and the limits on the lanes too; a row is then written "
            "column by column from the lanes. Issue 13 withdrew the old goal against the "
            "`conic` sweep (which fills rows by runs at about `memset` speed) and set the "
            "goal against the point-by-point `direct` branch sweep, which computes the same "
            "circle point per sample: at most 1x. The columns (18 bytes a sample, 19 MB at "
            "1024^2) are where the maps differ: Rust `solution_map` takes fresh pages from "
            "the allocator (4 KiB page faults, zeroed by the kernel), while `direct` writes "
            "1 MB into an existing buffer; `solution_map_into` writes into an earlier map's "
            "columns, the like-for-like per-point figure. From Python both maps are fresh "
            "NumPy arrays (`numpy.empty`, which asks for huge pages on large arrays), the "
            "issue's own measurement; the Python figures use another task (`SWEEP_SETUP`) "
            "than the Rust rows, so compare them with each other only."
        ),
    )
)


SECTIONS.append(
    bench_section(
        "design",
        "From poses to the best linkage (`design`)",
        ratios=[
            Ratio(
                "brute force over both pivots at 4x resolution / `Task::design` (the design's "
                "best score at least the brute force's, checked in the same run)",
                "design/example/brute_force_4x",
                "design/example/design",
                ">= 10 (issue 22)",
                lambda r: r >= 10.0,
            ),
        ],
        note=(
            "`Task::design` with its default options on the built-in example (balanced "
            "ranking, default limits with the Grashof margin of 0.01, pivots anywhere): the "
            "coarse pass (the pivot-pair atlas, 12 driven x 48 driving pivots along the search "
            "box's side), then 48 starts refined by Nelder-Mead on the exact figures (up to 3000 "
            "iterations each, and two more phases across the margin's band where the first met it). The brute force is the "
            "loop a designer would "
            "write: for every driven pivot of a 48 x 48 grid over the same box, the solution map "
            "over 192 x 192 driving pivots and its best pivot by the same score (both grids four "
            "times finer than the design's coarse pass). The bench asserts, before timing, that "
            "the design's best score is at least the brute force's (it prints both)."
        ),
    )
)


SOLVE_MANY_SETUP = """
import numpy as np
from burmester._burmester import FourBar
L1, L2, L3, L4 = 4.0, 1.0, 3.0, 3.0
fb = FourBar(ground=L1, crank=L2, coupler=L3, rocker=L4)
th = np.random.default_rng(1).uniform(-np.pi, np.pi, 10**6)

def numpy_closed_form(th, s=1.0):
    # Circle intersection and two arctan2: the plain NumPy baseline.
    ax, ay = L2 * np.cos(th), L2 * np.sin(th)
    dx, dy = L1 - ax, -ay
    r2 = dx * dx + dy * dy
    a = (L3 * L3 - L4 * L4 + r2) / (2 * r2)
    h = np.sqrt(L3 * L3 / r2 - a * a)
    bx = ax + a * dx - s * h * dy
    by = ay + a * dy + s * h * dx
    return np.arctan2(by - ay, bx - ax), np.arctan2(by, bx - L1), ~np.isnan(h)
"""

SECTIONS.append(
    Section(
        title="Batch position analysis (`FourBar.solve_many`)",
        prefixes=["python/solve_many/"],
        ratios=[
            Ratio(
                "NumPy closed form / `solve_many`, 10^6 angles",
                "python/solve_many/numpy_closed_form/1000000",
                "python/solve_many/solve_many/1000000",
                ">= 5",
                lambda r: r >= 5.0,
            ),
        ],
        python={
            "python/solve_many/solve_many/1000000": (
                SOLVE_MANY_SETUP,
                "fb.solve_many(th)",
                10**6,
            ),
            "python/solve_many/numpy_closed_form/1000000": (
                SOLVE_MANY_SETUP,
                "numpy_closed_form(th)",
                10**6,
            ),
        },
        note=(
            "Norton-like crank-rocker (4, 1, 3, 3), 10^6 uniform angles in (-pi, pi). "
            "The baseline is the textbook circle intersection written in plain NumPy "
            "(cos, sin, sqrt and two arctan2 over whole arrays, with temporaries). "
            "`solve_many` runs the batch kernel of `FourBar::solve_into` (SIMD lanes picked "
            "at run time, bit for bit `solve`), with rayon on all cores."
        ),
    )
)


def burmester_points_completeness(figures: dict[str, Figure]) -> list[str]:
    """The completeness line the `burmester_points` bench writes."""
    f = CRITERION / "burmester_points" / "completeness.json"
    if not f.exists():
        return ["Completeness: (not measured yet: run the `burmester_points` bench)", ""]
    d = json.loads(f.read_text())
    return [
        "| completeness (worked example, 4 Burmester points) | found | goal | met |",
        "|---|---|---|---|",
        f"| exact `FivePositions::new` | {d['exact_found']} of {d['burmester_points']} "
        f"(worst crank-length spread {d['exact_worst_residual']:.1e}) | all | "
        f"{'yes' if d['exact_found'] == d['burmester_points'] else 'NO'} |",
        f"| grid search ({d['grid_candidates']} candidates) | {d['grid_found']} of "
        f"{d['burmester_points']} within {d['tolerance_sizes']:g} task sizes; "
        f"{d['grid_accepted']} candidates accepted, "
        f"{d['grid_accepted_within_0.1_size']} of them within 0.1 task sizes of one | "
        "(baseline) | |",
        "",
    ]


#: The atlas bench's grids: the issue asks for 256^2 driven x 256^2 driving
#: (4.3e9 pairs: about a minute a run in process on 2 cores at the cost
#: measured here, several for the Python loop, each timed 4 times), scaled
#: down to 64^2 x 256^2 (2.7e8 pairs) so that each run takes seconds here;
#: the Dask tiles are then a few tenths of a second each.
ATLAS_DRIVEN = int(os.environ.get("BURMESTER_BENCH_ATLAS_DRIVEN", "64"))
ATLAS_DRIVING = int(os.environ.get("BURMESTER_BENCH_ATLAS_DRIVING", "256"))
ATLAS_PAIRS = ATLAS_DRIVEN**2 * ATLAS_DRIVING**2
ATLAS_ID = f"{ATLAS_DRIVEN}x{ATLAS_DRIVEN}_{ATLAS_DRIVING}x{ATLAS_DRIVING}"

ATLAS_SETUP = f"""
import os, burmester
from burmester import Grid, Task
t = Task([(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)])
driven = Grid(-8.0, 8.0, -8.0, 8.0, {ATLAS_DRIVEN}, {ATLAS_DRIVEN})
driving = Grid(-8.0, 8.0, -8.0, 8.0, {ATLAS_DRIVING}, {ATLAS_DRIVING})
limits = burmester.DesignLimits(30.0, 10.0, "any")

def python_loop():
    # What a user writes without the atlas: one solution map per C0.
    best = []
    for j in range(driven.ny):
        for i in range(driven.nx):
            try:
                f = t.filemon(driven.point(j, i))
            except burmester.BurmesterError:
                continue
            best.append(f.solution_map(driving, limits=limits).best_pivots(1, rank_by="transmission"))
    return best
"""

ATLAS_DASK_SETUP = ATLAS_SETUP + """
import distributed
cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                   dashboard_address=None)
client = distributed.Client(cluster)
"""

#: Cores per machine and machine counts of the extrapolation table.
ATLAS_CORES_PER_MACHINE = 16
ATLAS_MACHINES = (1, 4, 16, 64)
ATLAS_BIG = 1024


def dask_efficiency_16core() -> tuple[Optional[float], str]:
    """The Dask parallel efficiency in the header of the 16-core log of
    ``benches/dask_scaling.py`` (``benches/scaling/atlas-dask-16core.log``),
    with where it comes from; ``(None, "")`` without the log."""
    log = ROOT / "benches" / "scaling" / "atlas-dask-16core.log"
    if not log.exists():
        return None, ""
    m = re.search(r"Dask parallel efficiency on (\d+) cores[^:]*: ([0-9.]+)", log.read_text())
    if m is None:
        return None, ""
    return float(m.group(2)), f"measured on a {m.group(1)}-core machine, `{log.name}`"


def atlas_extrapolation(figures: dict[str, Figure]) -> list[str]:
    """The expected time of a 1024^2 x 1024^2 atlas on N 16-core machines,
    from the measured in-process cost per (driven, driving) pair."""
    inproc = figures.get(f"python/atlas/in_process/{ATLAS_ID}")
    if inproc is None:
        return []
    cores = os.cpu_count() or 1
    per_pair_core_ns = inproc.mean_ns * cores / ATLAS_PAIRS
    # The machines of the table have 16 cores: the Dask efficiency measured
    # on a 16-core machine (the committed log) when there is one, else this
    # run's (this machine's cores, capped at 1).
    eff, where = dask_efficiency_16core()
    if eff is None:
        dask = figures.get(f"python/atlas/dask_2x1/{ATLAS_ID}")
        eff = min(1.0, inproc.mean_ns / dask.mean_ns) if dask is not None else 1.0
        where = f"measured in this run on {cores} cores"
    pairs = ATLAS_BIG**4
    core_s = pairs * per_pair_core_ns * 1e-9
    lines = [
        f"Measured cost: {per_pair_core_ns:.1f} core-ns per (driven, driving) pair "
        f"(in process, {fmt_time(inproc.mean_ns)} x {cores} cores / {ATLAS_PAIRS:.3g} pairs). "
        f"A {ATLAS_BIG}^2 x {ATLAS_BIG}^2 atlas is {pairs:.3g} pairs, {core_s / 3600:.3g} "
        f"core-hours; on N machines of {ATLAS_CORES_PER_MACHINE} cores at the Dask "
        f"parallel efficiency e = {eff:.2f} ({where}): T = pairs x cost / (N x "
        f"{ATLAS_CORES_PER_MACHINE} x e), assuming a core there costs what one does here.",
        "",
        "| machines (16 cores each) | expected time |",
        "|---|---|",
    ]
    for n in ATLAS_MACHINES:
        t_ns = core_s * 1e9 / (n * ATLAS_CORES_PER_MACHINE * eff)
        lines.append(f"| {n} | {t_ns / 3.6e12:.3g} h |")
    lines.append("")
    return lines


SECTIONS.append(
    bench_section(
        "burmester_points",
        "Four and five poses: curves and Burmester points (`burmester_points`)",
        ratios=[
            Ratio(
                "grid search / Burmester points",
                "burmester_points/points/grid_search",
                "burmester_points/points/exact",
                ">= 100",
                lambda r: r >= 100.0,
            ),
        ],
        extra=burmester_points_completeness,
        note=(
            "The worked example of the notes (`positions-4-5.md`, section 6). `trace` traces "
            "the center-point curve of poses 1-4 over a square of half-width three task "
            "sizes about the poses' centroid (default polyline tolerance). `curves/new` is "
            "`FourPositions::new` of poses 1-4 (the cubics in double-double); "
            "`curves/free_center_arcs` and `free_circle_arcs` the branch-free arcs of both "
            "curves in that view for the driven dyad of the example's crank-rocker "
            "(`C0 = (4, 0)`). `points/exact` "
            "is `FivePositions::new` on the five poses (curves, candidates, Newton, "
            "checks: since stop 42 the last check is the exact count, "
            "`points/certificate`, the five poses' Burmester points counted and placed in "
            "exact integer arithmetic; `points/certificate_mixed` the same on a task whose "
            "positions mix magnitudes `1e300` and `1e-300`). `points/grid_search` is the "
            "search other tools use, written in the "
            "bench and measured in the same run: candidate circle points on 12 radii "
            "(task size / 6 to 2 task sizes) x 48 angles about each pose's position "
            "(2880 candidates), each moved through the five poses, the circle fitted "
            "through its positions at poses 1, 3, 5 and the candidate accepted when the "
            "positions at poses 2 and 4 lie within 1 % of its radius of it. A Burmester "
            "point counts as found by the grid when an accepted candidate's circle point "
            "(at pose 1) lies within 1e-3 task sizes of it. The 1024^2 pair map is in "
            "its own section (`pair_map`)."
        ),
    )
)

SECTIONS.append(
    bench_section(
        "pair_map",
        "Four poses: the pair map (`pair_map`)",
        note=(
            "`Task::pair_map` on poses 1-4 of the worked example of the notes "
            "(`positions-4-5.md`, section 6): n x n pairs of dyads sampled along the "
            "center-point curve by the crank-rotation parameter, each with the solution "
            "map's columns (figures at the four poses, limits, ranking inputs), default "
            "limits, no constraints, on every core; throughput in pairs. The samples of "
            "both axes (2n dyads) are included."
        ),
    )
)

SECTIONS.append(
    Section(
        title="Pivot-pair atlas (`burmester.pivot_atlas`)",
        prefixes=["python/atlas/"],
        ratios=[
            Ratio(
                "Python loop of `solution_map` + `best_pivots(1, rank_by=\"transmission\")` / atlas in process",
                f"python/atlas/python_loop/{ATLAS_ID}",
                f"python/atlas/in_process/{ATLAS_ID}",
                ">= 5",
                lambda r: r >= 5.0,
            ),
            Ratio(
                "Dask LocalCluster (2 workers x 1 thread) / atlas in process, same cores "
                "(parallel efficiency = 1 / this)",
                f"python/atlas/dask_2x1/{ATLAS_ID}",
                f"python/atlas/in_process/{ATLAS_ID}",
                "<= 1.25 (efficiency >= 0.8)",
                lambda r: r <= 1.25,
            ),
        ],
        python={
            f"python/atlas/in_process/{ATLAS_ID}": (
                ATLAS_SETUP,
                "burmester.pivot_atlas(t, driven, driving, limits=limits)",
                ATLAS_PAIRS,
            ),
            f"python/atlas/python_loop/{ATLAS_ID}": (
                ATLAS_SETUP,
                "python_loop()",
                ATLAS_PAIRS,
            ),
            f"python/atlas/dask_2x1/{ATLAS_ID}": (
                ATLAS_DASK_SETUP,
                "burmester.pivot_atlas(t, driven, driving, limits=limits, client=client)",
                ATLAS_PAIRS,
            ),
        },
        python_runs=(1, 1, 3),
        note=(
            f"The built-in example task, driven and driving centers on grids over (-8, 8)^2: "
            f"{ATLAS_DRIVEN}^2 driven x {ATLAS_DRIVING}^2 driving ({ATLAS_PAIRS:.3g} pairs; "
            "throughput in pairs). The issue's 256^2 x 256^2 is scaled down: it is 4.3e9 "
            "pairs, minutes per run on this 2-core machine (several times that for the Python "
            "loop, and every figure is timed four times), while the cost per pair hardly "
            "depends on the grid sizes (each driven center is one solution map of the "
            "driving grid). The atlas runs the per-pivot SIMD kernel only on the groups of "
            "lanes that hold a branch-free driving sample, computes what depends on the "
            "driving candidate alone (circle point, crank, its pseudo-angles) once per row "
            "for 16 driven centers, and takes the `acos` only where "
            "the other limits pass. The Python loop is what a user writes without the "
            "atlas: `task.filemon(C0).solution_map(driving)` and `best_pivots(1, rank_by='transmission')` (the atlas's ranking) for every "
            "`C0`; its `solution_map` calls run the same per-pivot kernel as the atlas, so "
            "a faster kernel speeds both sides and this ratio measures only what the atlas "
            "saves over the loop (reduction in the kernel, shared driving lanes). "
            "The Dask figure is a `LocalCluster(n_workers=2, threads_per_worker=1, "
            "processes=True)` started beforehand, on the same 2 cores as the in-process run "
            "(rayon on all cores); it includes shipping the task and the arrays. "
            "Each timing is one call, three times, after one warm-up call."
        ),
        extra=atlas_extrapolation,
    )
)


SECTIONS.append(
    bench_section(
        "drive_map",
        "A motor for a swinging input: the drive map (`drive_map`)",
        ratios=[
            Ratio(
                "drive map / solution map per sample, 1024^2 each, into given columns, same run",
                "drive_map/drive_map_into/1024",
                "drive_map/solution_map_into/1024",
                "<= 2 (issue 23)",
                lambda r: r <= 2.0,
            ),
            Ratio(
                "drive map / solution map per sample, 256^2 each, into given columns, same run",
                "drive_map/drive_map_into/256",
                "drive_map/solution_map_into/256",
                "<= 2 (issue 23)",
                lambda r: r <= 2.0,
            ),
        ],
        note=(
            "`DriveContext::map` for the built-in example's best linkage by transmission (a "
            "triple-rocker, its input swinging), the attachment at its input joint, candidate "
            "crank pivots over a square of half-width 4 |A - A0| about A0, default limits, no "
            "constraints; against the example's solution map (`Filemon::solution_map_into`) "
            "over its view on a grid of the same size, in the same run, so their ratio is the "
            "cost per sample of one over the other. Each drive sample is exact and closed form: "
            "the crank-rocker with the swing asked for, the drive loop's minimum transmission "
            "over a full crank turn, the time ratio, the six-bar's link and size ratios (three "
            "square roots, one `acos`, one `atan2`), on SIMD lanes picked at run time like the "
            "solution map's kernel (the scalar path's bits). `drive_map` allocates its columns; "
            "the `_into` figures reuse them."
        ),
    )
)

@dataclass
class Figure:
    id: str
    mean_ns: float
    low_ns: float
    high_ns: float
    elements: Optional[int]


def load_criterion() -> dict[str, Figure]:
    figures: dict[str, Figure] = {}
    if not CRITERION.exists():
        return figures
    for bench in CRITERION.rglob("new/benchmark.json"):
        est = bench.parent / "estimates.json"
        if not est.exists():
            continue
        meta = json.loads(bench.read_text())
        e = json.loads(est.read_text())
        mean = e["mean"]
        tp = meta.get("throughput") or {}
        elements = tp.get("Elements") or tp.get("Bytes")
        figures[meta["full_id"]] = Figure(
            meta["full_id"],
            mean["point_estimate"],
            mean["confidence_interval"]["lower_bound"],
            mean["confidence_interval"]["upper_bound"],
            elements,
        )
    py = CRITERION / "python"
    if py.exists():
        for f in py.glob("*.json"):
            d = json.loads(f.read_text())
            figures[d["id"]] = Figure(d["id"], d["mean_ns"], d["low_ns"], d["high_ns"], d["elements"])
    return figures


def run_benches(sections: list[Section], extra: list[str]) -> None:
    for s in sections:
        for b in s.benches:
            cmd = ["cargo", "bench", "-p", "burmester", "--bench", b, "--", *extra]
            print("+", " ".join(cmd), flush=True)
            subprocess.run(cmd, cwd=ROOT, check=True)


def run_python(sections: list[Section], repeat: int) -> None:
    try:
        import burmester  # noqa: F401
    except ImportError:
        print("burmester is not importable: Python timings skipped", file=sys.stderr)
        return
    out = CRITERION / "python"
    out.mkdir(parents=True, exist_ok=True)
    for s in sections:
        for pid, (setup, stmt, elements) in s.python.items():
            env: dict = {}
            try:
                exec(setup, env)
            except ImportError as e:  # e.g. Dask not installed
                print(f"python {pid}: skipped ({e})", file=sys.stderr)
                continue
            code = compile(stmt, pid, "exec")
            warmup, batch, batches = s.python_runs
            for _ in range(warmup):
                exec(code, env)  # warm up
            # Like criterion: batches of back-to-back calls, per-call time
            # of each batch.
            times = []
            for _ in range(batches or repeat):
                t0 = time.perf_counter_ns()
                for _ in range(batch):
                    exec(code, env)
                times.append((time.perf_counter_ns() - t0) / batch)
            times.sort()
            mean = statistics.fmean(times)
            rec = {
                "id": pid,
                "mean_ns": mean,
                "low_ns": times[0],
                "high_ns": times[-1],
                "elements": elements,
                "median_ns": statistics.median(times),
            }
            print(f"python {pid}: {mean / 1e6:.3f} ms", flush=True)
            (out / (pid.replace("/", "__") + ".json")).write_text(json.dumps(rec))


def fmt_time(ns: float) -> str:
    if ns < 1e3:
        return f"{ns:.2f} ns"
    if ns < 1e6:
        return f"{ns / 1e3:.2f} µs"
    if ns < 1e9:
        return f"{ns / 1e6:.3f} ms"
    return f"{ns / 1e9:.3f} s"


def fmt_rate(elements: Optional[int], ns: float) -> str:
    if not elements:
        return ""
    per_s = elements / (ns * 1e-9)
    for unit, k in (("G", 1e9), ("M", 1e6), ("K", 1e3)):
        if per_s >= k:
            return f"{per_s / k:.2f} {unit}elem/s"
    return f"{per_s:.1f} elem/s"


def machine() -> list[str]:
    cpu = "unknown"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    rustc = subprocess.run(["rustc", "-V"], capture_output=True, text=True).stdout.strip()
    return [
        f"- CPU: {cpu}, {os.cpu_count()} logical cores",
        f"- OS: {platform.system()} {platform.release()}",
        f"- {rustc}; Python {platform.python_version()}",
        f"- written: {datetime.datetime.now().strftime('%Y-%m-%d %H:%M')}",
    ]


SCALING = ROOT / "benches" / "scaling"
NOTES = ROOT / "benches" / "notes.md"


def notes_lines() -> list[str]:
    """``benches/notes.md`` as it is (a ``## `` section written by hand: what
    changed between full runs and the goals not met), or nothing."""
    if not NOTES.exists():
        return []
    return [NOTES.read_text().strip("\n"), ""]


def parse_scaling_log(path: Path) -> tuple[list[str], list[tuple[str, str, int, float, float, float]]]:
    """The ``# `` header lines and the ``(label, bench, threads, low, mean, high)``
    rows (ns) of a console log of the ``scaling`` bench; ``label`` is the last
    ``== ...`` line before a row (empty when there is none)."""
    header: list[str] = []
    rows: list[tuple[str, str, int, float, float, float]] = []
    label, name = "", None
    units = {"ns": 1.0, "µs": 1e3, "us": 1e3, "ms": 1e6, "s": 1e9}
    for line in path.read_text().splitlines():
        if line.startswith("# "):
            header.append(line[2:])
        elif line.startswith("== "):
            label = line[3:]
        elif line.startswith("scaling/"):
            name = line.split()[0]
            if "time:" not in line:
                continue
        if "time:" in line and name is not None and "%" not in line:
            v = line.split("[", 1)[1].split("]", 1)[0].split()
            lo, mid, hi = (float(v[i]) * units[v[i + 1]] for i in (0, 2, 4))
            bench, threads = name.rsplit("/", 1)
            rows.append((label, bench.removeprefix("scaling/"), int(threads), lo, mid, hi))
            name = None
    return header, rows


def scaling_lines() -> list[str]:
    """Thread scaling from the committed logs of ``benches/scaling.rs`` run
    on a many-core machine (this machine has too few cores to measure it)."""
    logs = sorted(SCALING.glob("*.log")) if SCALING.exists() else []
    if not logs:
        return []
    lines = [
        "## Thread scaling (`scaling`, a 16-core machine)",
        "",
        "Not measured by `--run` (it needs many cores): `benches/scaling.rs` run on a",
        "16-core machine, its console output committed in `benches/scaling/` and turned",
        "into these tables by this script. Speed-up is the 1-thread mean over the",
        "n-thread mean of the same run (a rayon pool of n threads around each call).",
        "Goals (issue 13): the solution map >= 13x and `solve_into` (what",
        "`FourBar.solve_many` runs) >= 10x at 16 threads.",
        "`atlas-dask-16core.log` is `benches/dask_scaling.py` (the installed wheel): the",
        "pivot-pair atlas in process on 1 and 16 rayon threads (`RAYON_NUM_THREADS`, a",
        "fresh interpreter each) and on a Dask `LocalCluster` of 16 single-thread worker",
        "processes started beforehand; its header gives the Dask parallel efficiency.",
        "",
    ]
    for log in logs:
        header, rows = parse_scaling_log(log)
        lines += [f"### `{log.name}`", ""]
        lines += [f"- {h}" for h in header]
        lines += ["", "| run | benchmark | threads | time | interval | speed-up |", "|---|---|---|---|---|---|"]
        one = {(lab, b): mid for lab, b, t, _, mid, _ in rows if t == 1}
        for lab, b, t, lo, mid, hi in rows:
            base = one.get((lab, b))
            up = f"{base / mid:.1f}x" if base else ""
            lines.append(
                f"| {lab} | `{b}` | {t} | {fmt_time(mid)} | {fmt_time(lo)} to {fmt_time(hi)} | {up} |"
            )
        lines.append("")
    return lines


def write(figures: dict[str, Figure]) -> str:
    lines = [
        "# Benchmarks",
        "",
        "Written by `benches/report.py` from criterion's output of one run on this",
        "machine; do not edit by hand. Times are criterion's mean with its 95% interval.",
        "",
        "To reproduce (about ten minutes):",
        "",
        "```sh",
        "pip install .            # for the Python-side timings",
        "python benches/report.py --run",
        "```",
        "",
        "## Machine",
        "",
        *machine(),
        "",
        *notes_lines(),
    ]
    for s in SECTIONS:
        lines += [f"## {s.title}", ""]
        if s.note:
            lines += [s.note, ""]
        rows = sorted(
            (f for f in figures.values() if any(f.id.startswith(p) for p in s.prefixes)),
            key=lambda f: f.id,
        )
        if not rows:
            lines += ["(not measured yet: run `python benches/report.py --run`)", ""]
            continue
        lines += ["| benchmark | time | interval | throughput |", "|---|---|---|---|"]
        for f in rows:
            lines.append(
                f"| `{f.id}` | {fmt_time(f.mean_ns)} | {fmt_time(f.low_ns)} to "
                f"{fmt_time(f.high_ns)} | {fmt_rate(f.elements, f.mean_ns)} |"
            )
        lines.append("")
        if s.ratios:
            lines += ["| ratio | value | goal | met |", "|---|---|---|---|"]
            for r in s.ratios:
                a, b = figures.get(r.numerator), figures.get(r.denominator)
                if a is None or b is None:
                    lines.append(f"| {r.name} | (missing) | {r.goal} | |")
                    continue
                v = a.mean_ns / b.mean_ns
                lines.append(f"| {r.name} | {v:.2f} | {r.goal} | {'yes' if r.ok(v) else 'NO'} |")
            lines.append("")
        if s.extra is not None:
            lines += s.extra(figures)
    lines += scaling_lines()
    return "\n".join(lines)


def section_text(text: str) -> dict[str, str]:
    """The ``## `` sections of a report, by title, each with its heading."""
    parts: dict[str, str] = {}
    title = None
    for block in text.split("\n## ")[1:]:
        title, _, body = block.partition("\n")
        parts[title] = "## " + title + "\n" + body.rstrip("\n") + "\n"
    return parts


def write_only(figures: dict[str, Figure], sections: list[Section]) -> str:
    """The existing report with only ``sections`` rewritten from this run's
    figures (added at the end when new); every other section is kept as it
    was, and each rewritten one says when it was measured."""
    old = OUT.read_text() if OUT.exists() else write({})
    fresh = section_text(write(figures))
    stamp = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    head, _, _ = old.partition("\n## ")
    kept = section_text(old)
    for s in sections:
        note = (f"(This section alone measured {stamp}, `python benches/report.py --run --only "
                f"{' '.join(s.benches)}`; the others come from an earlier run. Its ratios are "
                "within this one run.)\n\n")
        body = fresh[s.title]
        heading, _, rest = body.partition("\n\n")
        kept[s.title] = heading + "\n\n" + note + rest
    # The scaling tables come from the committed logs, not from this run:
    # always as the logs say.
    kept.update(section_text("\n" + "\n".join(scaling_lines())))
    # The notes by hand: always as `benches/notes.md` says, after the machine.
    notes = section_text("\n" + "\n".join(notes_lines()))
    for title in notes:
        kept.pop(title, None)
    first = dict(list(kept.items())[:1])
    rest = dict(list(kept.items())[1:])
    kept = {**first, **notes, **rest}
    return head.rstrip("\n") + "\n\n" + "\n".join(kept.values()).rstrip("\n")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--run", action="store_true", help="run the benches first")
    ap.add_argument("--only", nargs="+", metavar="BENCH", default=None,
                    help="only the sections of these cargo benches: run them (with --run) and rewrite "
                         "their sections of BENCHMARKS.md, keeping the others ('scaling' alone: "
                         "rewrite the thread-scaling tables from the logs in benches/scaling/)")
    ap.add_argument("--python-repeat", type=int, default=20)
    ap.add_argument("criterion_args", nargs="*", help="passed to criterion (after --)")
    args = ap.parse_args()
    if args.only == ["scaling"]:
        # Only the thread-scaling tables, from the logs in benches/scaling/.
        text = write_only({}, [])
        OUT.write_text(text + "\n")
        print(text)
        return 0
    if args.only is not None:
        chosen = [s for s in SECTIONS if set(s.benches) & set(args.only)]
        if not chosen:
            ap.error(f"no section runs the benches {args.only}")
        if args.run:
            for s in chosen:
                for b in s.benches:
                    shutil.rmtree(CRITERION / b, ignore_errors=True)
            run_benches(chosen, args.criterion_args)
            run_python(chosen, args.python_repeat)
        text = write_only(load_criterion(), chosen)
        OUT.write_text(text + "\n")
        print(text)
        return 0
    if args.run:
        # Every figure of the report comes from this one run.
        shutil.rmtree(CRITERION, ignore_errors=True)
        run_benches(SECTIONS, args.criterion_args)
        run_python(SECTIONS, args.python_repeat)
    text = write(load_criterion())
    OUT.write_text(text + "\n")
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
