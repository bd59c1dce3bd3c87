"""
Both pivots at once: the atlas
==============================

For every driven pivot `C0` on a 24 x 24 grid, the solution map over a
64 x 64 grid of driving pivots, reduced: shaded by the best transmission
angle to be had, the count of acceptable driving pivots as contours, the
best pair drawn. `burmester atlas -o atlas.png` draws it for a task file.
"""

import matplotlib.pyplot as plt

import burmester
import burmester.plot as bp

task = burmester.Task([(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)])
atlas = burmester.pivot_atlas(task, (-8, 8, -8, 8, 24, 24), (-8, 8, -8, 8, 64, 64),
                              min_transmission_deg=35, input="crank")
pair = atlas.best_pairs(1)[0]
print(f"best: C0 = {pair.driven}, A0 = {pair.driving}, mu min {pair.min_transmission_deg:.1f} deg")
bp.atlas(atlas)
plt.show()
