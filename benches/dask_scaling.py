"""The pivot-pair atlas on a many-core machine: in process on 1 and all
threads, and on a Dask ``LocalCluster`` of one worker process per core.

Run it where there are many cores (``benches/report.py --run`` does not: a
2-core machine cannot show scaling)::

    python benches/dask_scaling.py --out benches/scaling/atlas-dask-16core.log \\
        --machine "16-core ..."

It writes a console log in the shape of the ``scaling`` bench's
(``scaling/<bench>/<threads>`` then ``time: [low mean high]``), so
``benches/report.py`` turns it into a table beside the Rust ones; the Dask
parallel efficiency (the in-process time on all threads over the Dask time
on as many single-thread worker processes) is a ``#`` line of its header.

Each configuration runs in a fresh interpreter (rayon's pool is sized by
``RAYON_NUM_THREADS`` at first use); each timing is one call of
``burmester.pivot_atlas``, repeated ``--runs`` times after one warm-up call;
the cluster is started before the warm-up and its start is not timed.
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import statistics
import subprocess
import sys
import time

TASK = [(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)]


def child(mode: str, workers: int, driven_n: int, driving_n: int, runs: int) -> None:
    import burmester
    from burmester import Grid, Task

    t = Task(TASK)
    driven = Grid(-8.0, 8.0, -8.0, 8.0, driven_n, driven_n)
    driving = Grid(-8.0, 8.0, -8.0, 8.0, driving_n, driving_n)
    limits = burmester.DesignLimits(30.0, 10.0, "any")
    kwargs = {}
    cluster = None
    if mode == "dask":
        import distributed

        cluster = distributed.LocalCluster(
            n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None
        )
        kwargs["client"] = distributed.Client(cluster)
    atlas = burmester.pivot_atlas(t, driven, driving, limits=limits, **kwargs)
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        again = burmester.pivot_atlas(t, driven, driving, limits=limits, **kwargs)
        times.append(time.perf_counter() - start)
    # The answer must not depend on where it ran.
    assert again.best_pairs(1) == atlas.best_pairs(1)
    print(json.dumps({"times": times, "best": repr(atlas.best_pairs(1))}))
    if cluster is not None:
        kwargs["client"].close()
        cluster.close()


def run(mode: str, workers: int, args: argparse.Namespace) -> list[float]:
    env = dict(os.environ, RAYON_NUM_THREADS=str(workers if mode == "process" else 1))
    cmd = [sys.executable, __file__, "--child", mode, str(workers),
           str(args.driven), str(args.driving), str(args.runs)]
    out = subprocess.run(cmd, env=env, check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])["times"]


def main() -> None:
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        mode, workers, driven_n, driving_n, runs = sys.argv[2:7]
        child(mode, int(workers), int(driven_n), int(driving_n), int(runs))
        return
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--out", required=True, help="the log to write")
    p.add_argument("--machine", required=True, help="the machine, in words")
    p.add_argument("--driven", type=int, default=128, help="driven grid side (default 128)")
    p.add_argument("--driving", type=int, default=256, help="driving grid side (default 256)")
    p.add_argument("--runs", type=int, default=3, help="timed calls per configuration")
    args = p.parse_args()
    cores = os.cpu_count() or 1
    bench = f"pivot_atlas/{args.driven}x{args.driving}"
    rows = []
    measured = {}
    for label, mode, n in [
        ("in process (rayon threads)", "process", 1),
        ("in process (rayon threads)", "process", cores),
        ("Dask LocalCluster (worker processes x 1 thread)", "dask", cores),
    ]:
        times = run(mode, n, args)
        measured[(mode, n)] = statistics.mean(times)
        rows.append((label, n, times))
    eff = measured[("process", cores)] / measured[("dask", cores)]
    pairs = args.driven**2 * args.driving**2
    lines = [
        f"# machine: {args.machine}",
        f"# date: {datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M')} UTC; "
        f"command: python benches/dask_scaling.py (the installed wheel, release build)",
        f"# task: the built-in example, {args.driven}^2 driven x {args.driving}^2 driving "
        f"centers over (-8, 8)^2 ({pairs:.3g} pairs), limits 30 deg / 10 / any; "
        f"one warm-up call then {args.runs} timed calls each",
        f"# Dask parallel efficiency on {cores} cores (in process on {cores} threads / "
        f"Dask {cores} x 1): {eff:.2f}; cost in process on 1 thread "
        f"{measured[('process', 1)] / pairs * 1e9:.1f} ns per pair",
    ]
    label_prev = None
    for label, n, times in rows:
        if label != label_prev:
            lines.append(f"== {label}")
            label_prev = label
        lo, mid, hi = min(times), statistics.mean(times), max(times)
        lines.append(f"scaling/{bench}/{n}")
        lines.append(f"                        time:   [{lo:.4f} s {mid:.4f} s {hi:.4f} s]")
    text = "\n".join(lines) + "\n"
    tmp = args.out + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, args.out)
    print(text)


if __name__ == "__main__":
    main()
