"""Designer-range five-pose tasks against the exact reference (issue 24, stop 41).

The fuzz target `burmester_points` probes extreme floats (coordinates 1e12
from a task of size 1, angles of 1e5 rad); this script asks what a designer
meets: each task's library answer (the Python package) judged against the
exact points of its float task (tests/python/burmester_reference.py, sympy
and mpmath at 60 digits). Families, `k` from 2 to 7:

- `known`: a crank-rocker in millimetres (ground 50 to 300) driven to five
  crank angles, the coupler frame's poses moved up to 500 mm and turned; its
  two fixed pivots are Burmester points (`pivots_found`);
- `known-near`: the same with two crank angles `10^-k` rad apart;
- `random`: poses in a 100 mm square, any angles;
- `random-near`: two poses `10^-k` task sizes apart, angles as close;
- `random-angle`: two poses of one angle within `10^-k` rad.

A listed point over `1e-6` of `size + d` off every exact real point is
wrong (ghost or inaccurate), as is an exact real point within `1e4` task
sizes with no listed point that near (missing), or an exact simple point
listed twice. One JSON line per task:

    python fuzz/reference/moderate_five.py SEED COUNT OUT.jsonl
"""
import json
import math
import os
import random
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "python"))
import mpmath  # noqa: E402
from burmester_reference import reference  # noqa: E402

import burmester  # noqa: E402


def crank_rocker(rng):
    """Link lengths (ground, crank, coupler, rocker) of a crank-rocker with
    its Grashof margin above a thousandth of the ground."""
    while True:
        g = rng.uniform(50, 300)
        a = rng.uniform(0.1, 0.5) * g
        b = rng.uniform(0.6, 1.6) * g
        c = rng.uniform(0.5, 1.5) * g
        links = sorted([g, a, b, c])
        if a == links[0] and links[0] + links[3] < links[1] + links[2] - 1e-3 * g:
            return g, a, b, c


def known(rng, near=None):
    """Five poses of a crank-rocker's coupler (open mode) and its two fixed
    pivots, moved and turned; with ``near``, two crank angles ``10^-near``
    apart. ``None`` where the linkage does not assemble."""
    g, a, b, c = crank_rocker(rng)
    pivots = [(0.0, 0.0), (g, 0.0)]
    px, py = rng.uniform(-1, 1) * b, rng.uniform(0.2, 1) * b
    th0 = rng.uniform(0, 2 * math.pi)
    ths = [th0] + [th0 + x for x in sorted(rng.uniform(0.2, 2 * math.pi - 0.2) for _ in range(4))]
    if near is not None:
        ths[2] = ths[1] + 10.0**-near * rng.choice([-1, 1])
    poses = []
    for t in ths:
        ax, ay = a * math.cos(t), a * math.sin(t)
        dx, dy = g - ax, -ay
        d = math.hypot(dx, dy)
        ca = (b * b + d * d - c * c) / (2 * b * d)
        if abs(ca) > 1:
            return None
        phi = math.atan2(dy, dx) + math.acos(ca)
        poses.append((ax + px * math.cos(phi) - py * math.sin(phi), ay + px * math.sin(phi) + py * math.cos(phi), phi))
    r = rng.uniform(-math.pi, math.pi)
    tx, ty = rng.uniform(-500, 500), rng.uniform(-500, 500)
    cr, sr = math.cos(r), math.sin(r)

    def mv(x, y):
        return (cr * x - sr * y + tx, sr * x + cr * y + ty)

    return [(*mv(x, y), p + r) for x, y, p in poses], [mv(*q) for q in pivots]


def rand(rng, kind=None, k=None):
    """Five poses in a 100 mm square; ``kind`` ``"near"``: poses 1 and 2
    ``10^-k`` task sizes apart (angles as close), ``"angle"``: poses 3 and 4
    of one angle within ``10^-k``."""
    p = [(rng.uniform(0, 100), rng.uniform(0, 100), rng.uniform(-math.pi, math.pi)) for _ in range(5)]
    if kind == "near":
        e = 10.0**-k * 100
        p[1] = (p[0][0] + rng.uniform(-e, e), p[0][1] + rng.uniform(-e, e), p[0][2] + rng.uniform(-1, 1) * 10.0**-k)
    elif kind == "angle":
        p[3] = (p[3][0], p[3][1], p[2][2] + rng.uniform(-1, 1) * 10.0**-k)
    return p


def size_c(poses):
    cx = sum(q[0] for q in poses) / 5
    cy = sum(q[1] for q in poses) / 5
    return max(math.hypot(q[0] - cx, q[1] - cy) for q in poses), (cx, cy)


def judge(poses, pts):
    """The answer against the exact points: ``verdict`` right or wrong, what
    is wrong, the worst distance of a listed point (units of ``size + d``)."""
    s, (cx, cy) = size_c(poses)
    ref = reference(poses)
    if ref is None:
        return dict(verdict="ref-not-isolated")
    common, inf = ref
    real, cplx = [], []
    for x, y in common:
        im = max(abs(mpmath.im(x)), abs(mpmath.im(y)))
        if im <= 1e-30 * (1 + abs(x) + abs(y)):
            real.append((mpmath.re(x), mpmath.re(y)))
        else:
            cplx.append(float(im) / s)

    def dist(q, x, y):
        return float(mpmath.sqrt((q[0] - x) ** 2 + (q[1] - y) ** 2))

    worst, bad = 0.0, []
    for x, y in pts:
        d = math.hypot(x - cx, y - cy)
        off = min((dist(q, x, y) for q in real), default=math.inf) / (s + d)
        worst = max(worst, off)
        if off > 1e-6:
            bad.append(("ghost or inaccurate", x, y, off))
    for rx, ry in real:
        d = math.hypot(float(rx) - cx, float(ry) - cy)
        if d > 1e4 * s:
            continue
        off = min((dist((rx, ry), x, y) for x, y in pts), default=math.inf) / (s + d)
        if off > 1e-6:
            bad.append(("missing", float(rx), float(ry), off))
    for i in range(len(pts)):
        for j in range(i + 1, len(pts)):
            if pts[i] == pts[j]:
                r = 1e-6 * (s + math.hypot(pts[i][0] - cx, pts[i][1] - cy))
                if sum(dist(q, *pts[i]) <= r for q in real) < 2 and not any(c < 1e-6 for c in cplx):
                    bad.append(("simple point listed twice", pts[i][0], pts[i][1], 0.0))
    return dict(verdict="wrong" if bad else "right", bad=bad, worst=worst, real=len(real), inf=inf, cplx=cplx)


FAMILIES = ["known"] * 3 + ["known-near"] * 2 + ["random"] * 2 + ["random-near"] * 2 + ["random-angle"]


def main(seed, n, out):
    rng = random.Random(seed)
    with open(out, "a") as f:
        done = 0
        while done < n:
            fam = rng.choice(FAMILIES)
            k = rng.randint(2, 7)
            pivots = None
            if fam.startswith("known"):
                r = known(rng, k if fam == "known-near" else None)
                if r is None:
                    continue
                poses, pivots = r
            else:
                poses = rand(rng, {"random": None, "random-near": "near", "random-angle": "angle"}[fam], k)
            t0 = time.time()
            try:
                pts = [tuple(c) for c, _ in burmester.Task(poses).burmester_points()]
                ans = "points"
            except ValueError as e:
                pts, ans = [], type(e).__name__ + ": " + str(getattr(e, "cause", ""))
            rec = dict(fam=fam, k=k, poses=poses, ans=ans, pts=pts)
            if ans == "points":
                rec.update(judge(poses, pts))
                if pivots:
                    s, (cx, cy) = size_c(poses)
                    rec["pivots_found"] = all(
                        min((math.hypot(px - x, py - y) for x, y in pts), default=math.inf)
                        <= 1e-6 * (s + math.hypot(px - cx, py - cy))
                        for px, py in pivots
                    )
            rec["t"] = time.time() - t0
            f.write(json.dumps(rec) + "\n")
            f.flush()
            done += 1


def summary(path):
    from collections import Counter

    c, worst = Counter(), {}
    for line in open(path):
        r = json.loads(line)
        c[(r["fam"], r["ans"] if r["ans"] != "points" else r["verdict"])] += 1
        if r.get("pivots_found") is False:
            c[(r["fam"], "pivot lost")] += 1
        if "worst" in r:
            worst[r["fam"]] = max(worst.get(r["fam"], 0.0), r["worst"])
    for key, v in sorted(c.items()):
        print(*key, v, sep="\t")
    for fam, w in sorted(worst.items()):
        print(fam, "worst listed point off", f"{w:.1e}", "of size + d", sep="\t")


if __name__ == "__main__":
    if sys.argv[1] == "--summary":
        summary(sys.argv[2])
    else:
        main(int(sys.argv[1]), int(sys.argv[2]), sys.argv[3])
