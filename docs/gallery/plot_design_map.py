"""
The solution map of a lid, in millimetres
=========================================

A lid's front edge must pass three poses; the driven crank is hinged at
`C0 = (-60, -40)` mm. Every candidate driving pivot `A0` is mapped:
branch-free (light), also acceptable under the limits (dark: transmission
angle at least 40 degrees over the whole travel, link ratio at most 10),
with contours of the minimum transmission angle and the three best pivots by
the balanced score. `burmester map lid.toml --design --pivots 3` draws the
same.
"""

import math

import matplotlib.pyplot as plt
import numpy as np

import burmester
import burmester.plot as bp

task = burmester.Task([(0, 0, 0), (60, 55, math.radians(40)), (90, 140, math.radians(85))])
filemon = task.filemon((-60.0, -40.0))
grid = (-250, 250, -250, 250, 300, 300)  # a Grid or its six numbers
smap = filemon.solution_map(grid, min_transmission_deg=40)
best = smap.best_pivots(3)
for k, p in enumerate(best, start=1):
    f = p.figures
    print(f"#{k}: A0 = ({p.center[0]:.1f}, {p.center[1]:.1f}) mm, {f.grashof}, "
          f"mu min {f.min_transmission_deg:.1f} deg, {p.size_ratio:.1f} x the task")
bp.center_plane(filemon, smap.grid, free=smap.branch_free, acceptable=smap.acceptable,
                transmission=np.degrees(smap.min_transmission_rad), pivots=[p.center for p in best])
plt.show()
