"""Exact Burmester points of the two class C tasks that the choice rule of
fuzz32 fixed (the moved frames of `open/burmester_points/
point-not-found-in-another-frame-d1f9937d` and `-f5e30d14`, kept in
`regressions/burmester_points/`), for `issue24_a_choice_that_lost_roots_
is_not_preferred` in tests/rust/curves.rs: tests/python/burmester_reference.py
(sympy, mpmath at 60 digits) on the float tasks.

    python fuzz/reference/class_c_fixed.py
"""

import os
import sys

import mpmath

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "python"))
from burmester_reference import reference  # noqa: E402

TASKS = {
    "d1f9937d moved": [
        (-4.6390625e-8, -1.2975096765358978e-7, -1.0),
        (-4.7390624999999994e-8, -1.2660937499999998e-7, -2.220446049250313e-16),
        (2.201099952609375, -2.201100126609375, 0.0),
        (-4.7390624999999994e-8, -1.2660937499999998e-7, -3.141592653589793),
        (-4.42490323464102e-8, -1.27609375e-7, -1.0),
    ],
    "f5e30d14 moved": [
        (1e-15, -1e-15, -3.141592653589793),
        (0.0, -2.1692000000000002e-15, -2.169199999977308),
        (2.1854000000000003e-6, -2.1854000000000003e-6, 0.0),
        (3.141592653589793e-15, -1e-15, -1.0),
        (3.141592653589793e-15, 3.970625e-13, 0.0),
    ],
}

for name, poses in TASKS.items():
    common, inf = reference(poses)
    print(f"{name}: at infinity {inf}")
    for cx, cy in common:
        print("  ", mpmath.nstr(cx, 17), mpmath.nstr(cy, 17))
