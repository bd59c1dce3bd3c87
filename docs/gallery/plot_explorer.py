"""
The interactive explorer after a drag
=====================================

The README's picture of the explorer (`docs/explorer.png`, written by
`python examples/explorer_picture.py`). `burmester.plot.explore` opens the
center-point plane as a figure you can drag; here the drags are made from
code (`Explorer.drag`) with the mouse events a user's drag sends: pose 2 a
little right and down, then the driving pivot `A0` onto the moved task's
best pivot.
"""

import matplotlib.pyplot as plt

import burmester
from burmester import plot
from burmester.taskfile import example


spec = example()
ex = plot.explore(spec.task, spec.driven_center, (-8, 8, -8, 8),
                  limits=burmester.DesignLimits(min_transmission_deg=35))
ex.figure.canvas.draw()
ex.drag((2.0, 0.5), (2.3, 0.3))            # pose 2
best = ex.solution_map.best_pivots(1)[0]   # the moved task's best driving pivot
ex.drag(ex.driving_center, best.center)    # A0 onto it
print("A0 =", ex.driving_center, ex.linkage().figures.grashof)
plt.show()
