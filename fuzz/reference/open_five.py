"""The exact Burmester points (tests/python/burmester_reference.py: sympy,
mpmath at 60 digits) of the five-pose tasks of the `burmester_points`
findings, beside the library's answer (issue 24, fuzz32).

Reads the lines of the ignored test that replays the open findings:

    cargo test -p burmester --test fuzz_corpus -- --ignored --nocapture \\
        open_findings > open.txt
    python fuzz/reference/open_five.py < open.txt

For each task (as given, and moved to the finding's other frame) it prints
the library's count (finite points with multiplicity, sliders) or its
error, the reference's real finite points and points at infinity, and for
each library point its distance to the nearest real reference point in
task sizes.
"""

import ast
import os
import sys

import mpmath

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "python"))
from burmester_reference import reference  # noqa: E402


def size(poses):
    cx = sum(p[0] for p in poses) / 5
    cy = sum(p[1] for p in poses) / 5
    return max(((p[0] - cx) ** 2 + (p[1] - cy) ** 2) ** 0.5 for p in poses)


def judge(poses, answer):
    s = size(poses)
    ref = reference(poses)
    if ref is None:
        return "reference: not isolated"
    common, inf = ref
    real, cplx = [], []
    for cx, cy in common:
        im = max(abs(mpmath.im(cx)), abs(mpmath.im(cy)))
        if im <= 1e-30 * (1 + abs(cx) + abs(cy)):
            real.append((mpmath.re(cx), mpmath.re(cy)))
        else:
            cplx.append(float(im) / s)
    out = f"reference: {len(real)} real, {inf} at infinity, complex (imag / size) {['%.1e' % c for c in cplx]}"
    if answer.startswith("points"):
        pts = ast.literal_eval(answer.split(" sliders")[0][len("points ") :])
        dist = []
        for x, y in pts:
            d = min((float(mpmath.sqrt((rx - x) ** 2 + (ry - y) ** 2)) / s for rx, ry in real), default=float("inf"))
            dist.append("%.1e" % d)
        out += f"; library points off by (task sizes) {dist}"
    return out


lines = sys.stdin.read().splitlines()
for i, line in enumerate(lines):
    if "burmester_points:" in line and ("passes" in line or "fails" in line):
        print(line.split("fuzz/open/")[-1])
    elif line.startswith("  task ") or line.startswith("  moved "):
        name, rest = line.strip().split(" ", 1)
        poses = ast.literal_eval(rest)
        answer = lines[i + 1].strip()
        print(f"  {name}: library {answer[:160]}")
        try:
            print(f"    {judge(poses, answer)}")
        except Exception as e:  # the reference's own failure, reported
            print(f"    reference failed: {e!r}")
