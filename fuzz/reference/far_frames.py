"""Exact Burmester points of the merging five-pose task of
`issue24_a_double_root_that_is_two_real_points_gives_both`
(tests/rust/curves.rs) as given and moved far out (issue 24, fuzz32).

The moved task is the float task the test builds: each coordinate moved by
the offset in binary floating point (Python's float addition rounds as
Rust's), so its points differ from the given task's by what that rounding
does. The elimination is `tests/python/burmester_reference.py` (sympy,
mpmath at 60 digits); the points are printed relative to the offset.

    python fuzz/reference/far_frames.py

Output (2026-11-26):

    given (0, 0): at infinity 0
       -0.69600730882415316 2.669388663365832
       -0.6959737536494554 2.6694419215526419
       complex pair (-0.808458... +- 0.278j, 2.382441... +- 0.130j)
    moved (1e6, -1e6): at infinity 0
       -0.69600364661650447 2.6693944759134464
       -0.6959774158014583 2.6694361090047146
       complex pair (-0.808458... +- 0.278j, ...)
    moved (-3e6, 2e6): at infinity 0
       complex pair (-0.69599053047967283 +- 1.7172581309181425e-5j,
                     2.6694152929435544 +- 2.7256021138119819e-5j)
       complex pair (-0.808458... +- 0.278j, ...)
"""

import os
import sys

import mpmath

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "python"))
from burmester_reference import reference  # noqa: E402

POSES = [
    (0.2558734599461988, -3.8836557689762725, 2.1596700471934955),
    (1.5138333624383653, -3.75371689369933, 2.404112512166885),
    (2.6829498241096728, -3.150577449352146, 2.6017096951878065),
    (2.979515336818101, -2.8520483505789826, 2.6618014815462043),
    (3.9867349059821655, -2.2514849554763976, 2.8333410696332884),
]

for name, (ox, oy) in [("given", (0.0, 0.0)), ("moved", (1e6, -1e6)), ("moved", (-3e6, 2e6))]:
    task = [(x + ox, y + oy, a) for x, y, a in POSES]
    common, inf = reference(task)
    print(f"{name} ({ox:g}, {oy:g}): at infinity {inf}")
    for cx, cy in common:
        print("  ", mpmath.nstr(cx - ox, 17), mpmath.nstr(cy - oy, 17))
