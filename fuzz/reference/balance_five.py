"""The balance of a change to the five-pose points (five42): every frame of
`fuzz/open/burmester_points` and `fuzz/regressions/burmester_points` whose
answer changed, both answers judged against the exact points of its float
task (tests/python/burmester_reference.py).

The answers come from a dump of `five_answers` over every input (a
temporary ignored test that prints, for each file, a line
`burmester_points: <dir>/<name>` and then `five_answers`' lines), one
dump on the base and one on the change:

    python fuzz/reference/balance_five.py base.txt change.txt

A frame's answer is *refused* (an error), *right*, or *wrong*: an exact
real point within `1e4` task sizes with no listed point within `1e-3` of
`size + d` (missing), a listed point within `1e4` task sizes with no exact
point within `1e-3` (ghost), more listed points within `1e-3` of an exact
point than exact points there (dup: a simple point listed twice), or a
listed point over `1e-6` of `size + d` off its exact one (inaccurate).
Prints each changed frame (base class -> change class, with what is
wrong) and the counts of each transition.
"""
import ast
import math
import os
import sys
from collections import Counter

import mpmath

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "python"))
from burmester_reference import reference  # noqa: E402


def parse(path):
    out = {}
    name = None
    lines = open(path).read().splitlines()
    for i, line in enumerate(lines):
        if line.startswith("burmester_points: "):
            name = line.split(" ", 1)[1].strip()
        elif name and (line.startswith("  task ") or line.startswith("  moved ")):
            frame, rest = line.strip().split(" ", 1)
            # Keyed by the frame's poses: an input renamed (moved to
            # `regressions/`) is the same frame.
            out[rest] = (ast.literal_eval(rest), lines[i + 1].strip(), f"{name} {frame}")
    return out


def size_c(poses):
    cx = sum(p[0] for p in poses) / 5
    cy = sum(p[1] for p in poses) / 5
    return max(math.hypot(p[0] - cx, p[1] - cy) for p in poses), (cx, cy)


_refs = {}


def exact(poses):
    key = tuple(map(tuple, poses))
    if key not in _refs:
        ref = reference(poses)
        if ref is None:
            _refs[key] = None
        else:
            common, inf = ref
            real = []
            for x, y in common:
                im = max(abs(mpmath.im(x)), abs(mpmath.im(y)))
                if im <= 1e-30 * (1 + abs(x) + abs(y)):
                    real.append((mpmath.re(x), mpmath.re(y)))
            _refs[key] = (real, inf)
    return _refs[key]


def judge(poses, answer):
    """('refused' | 'right' | 'wrong', detail)."""
    if not answer.startswith("points"):
        kind = answer.split(":")[0].replace("error ", "")
        return "refused", kind[:60]
    pts = ast.literal_eval(answer.split(" sliders")[0][len("points "):])
    ref = exact(poses)
    if ref is None:
        return "right", "not isolated"
    real, _ = ref
    s, (cx, cy) = size_c(poses)
    def reach_off(x, y, among):
        """`size + d` at `(x, y)` (within `1e4` task sizes, else None) and the
        distance from it to the nearest of `among` (exact where mpmath)."""
        d = math.hypot(float(x) - cx, float(y) - cy)
        if d > 1e4 * s:
            return None, None
        off = min((float(mpmath.sqrt((qx - x) ** 2 + (qy - y) ** 2)) for qx, qy in among), default=math.inf)
        return s + d, off

    bad = []
    worst = 0.0
    for rx, ry in real:
        reach, off = reach_off(rx, ry, pts)
        if reach is None:
            continue
        fx, fy = float(rx), float(ry)
        if off > 1e-3 * reach:
            bad.append(f"missing ({fx:.6g},{fy:.6g})")
        here = sum(1 for x, y in pts if math.hypot(x - fx, y - fy) <= 1e-3 * reach)
        there = sum(1 for qx, qy in real if math.hypot(float(qx) - fx, float(qy) - fy) <= 1e-3 * reach)
        if here > there:
            bad.append(f"dup ({fx:.6g},{fy:.6g})")
    for x, y in pts:
        reach, off = reach_off(x, y, real)
        if reach is None:
            continue
        if off > 1e-3 * reach:
            bad.append(f"ghost ({x:.6g},{y:.6g})")
        elif off > 1e-6 * reach:
            worst = max(worst, off / reach)
    if worst > 0:
        bad.append(f"inaccurate {worst:.1e}")
    return ("wrong", "; ".join(sorted(set(bad)))) if bad else ("right", f"{len(pts)} pts")


def main():
    base, new = parse(sys.argv[1]), parse(sys.argv[2])
    counts = Counter()
    for key in sorted(base, key=lambda k: base[k][2]):
        if key not in new or base[key][1] == new[key][1]:
            continue
        label = new[key][2]
        poses = base[key][0]
        try:
            a, b = judge(poses, base[key][1]), judge(poses, new[key][1])
        except Exception as e:  # the reference's own failure, reported
            print(f"{label}: reference failed {e!r}")
            continue
        counts[(a[0], b[0])] += 1
        print(f"{label}: {a[0]} -> {b[0]}   [{a[1]}] -> [{b[1]}]")
        sys.stdout.flush()
    print("transitions:")
    for (a, b), n in sorted(counts.items()):
        print(f"  {a} -> {b}: {n}")


if __name__ == "__main__":
    main()
