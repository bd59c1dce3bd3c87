"""
Four and five poses
===================

The README's picture of four and five poses (`docs/four-five.png`, written
by `python examples/four_five_picture.py`). The poses come from driving a
known crank-rocker (fixed pivots `(0, 0)` and `(4, 0)`). Top: the
center-point curve of four poses coloured by the crank's order, the poles
and the points `Q_jk`, and the driving pivots branch-free with the rocker's
pivot `(4, 0)` as a band. Bottom: five poses, the two four-pose curves and
their Burmester points, the generating linkage's pivots among them.
"""

import math

import matplotlib.pyplot as plt

import burmester
import burmester.plot as bp

fb = burmester.FourBar.from_pivots((0, 0), (4, 0), 1.5, 3.5, 3.0)  # crank, coupler, rocker


def pose(deg):
    """The coupler point (1, 1.5) in the frame at the crank joint A, x toward B."""
    _, a, b, _ = fb.joints(math.radians(deg))
    phi = math.atan2(b[1] - a[1], b[0] - a[0])
    return (a[0] + math.cos(phi) - 1.5 * math.sin(phi), a[1] + math.sin(phi) + 1.5 * math.cos(phi), phi)


fig, (top, bottom) = plt.subplots(2, 1, figsize=(8.0, 11.0))
four = burmester.Task([pose(d) for d in (20, 70, 120, 170)])
bp.burmester_plane(four, (-6, 12, -5, 8), driven=(4.0, 0.0), ax=top)
five = burmester.Task([pose(d) for d in (20, 70, 120, 170, 230)])
bp.burmester_plane(five, (-6, 12, -5, 8), ax=bottom)
print("Burmester points:", [tuple(round(v, 6) + 0.0 for v in c) for c, _ in five.burmester_points()])
plt.show()
