"""
The pair map: every linkage of four poses
=========================================

The README's pair map (`docs/pair-map.png`, written by `python
examples/pair_map_picture.py`): a four-bar of four poses is a pair of dyads
on the center-point curve, so its linkages fill a plane, the driving dyad's
place on the curve across and the driven dyad's up. Each pair is shaded by
category (no linkage, branch defect, branch-free, acceptable), with
transmission contours and the best pairs numbered.
"""

import math

import matplotlib.pyplot as plt

import burmester
import burmester.plot as bp

fb = burmester.FourBar.from_pivots((0, 0), (4, 0), 1.5, 3.5, 3.0)


def pose(deg):
    _, a, b, _ = fb.joints(math.radians(deg))
    phi = math.atan2(b[1] - a[1], b[0] - a[0])
    return (a[0] + math.cos(phi) - 1.5 * math.sin(phi), a[1] + math.sin(phi) + 1.5 * math.cos(phi), phi)


four = burmester.Task([pose(d) for d in (20, 70, 120, 170)])
pmap = four.pair_map(300)
for p in pmap.best_pairs(3):
    print(p.linkage.fourbar.grashof, [round(v, 3) for v in p.linkage.fourbar.lengths])
bp.pair_map(pmap, pairs=5)
plt.show()
