"""
The interactive explorer after a drag
=====================================

The README's picture of the explorer (`docs/explorer.png`, written by
`python examples/explorer_picture.py`). `burmester.plot.explore` opens the
center-point plane as a figure you can drag; here the drags are made from
code with the mouse events a user's drag sends: pose 2 a little right and
down, then the driving pivot `A0` onto the moved task's best pivot.
"""

import matplotlib.pyplot as plt
from matplotlib.backend_bases import MouseEvent

import burmester
from burmester import plot
from burmester.taskfile import example


def drag(ex, start, end, steps=4):
    """Press at ``start``, move to ``end``, release: as a user would."""
    canvas = ex.figure.canvas
    path = [start] + [(start[0] + (end[0] - start[0]) * k / steps, start[1] + (end[1] - start[1]) * k / steps)
                      for k in range(1, steps + 1)]
    names = ["button_press_event"] + ["motion_notify_event"] * steps
    for name, xy in list(zip(names, path)) + [("button_release_event", end)]:
        px, py = ex.ax_map.transData.transform(xy)
        canvas.callbacks.process(name, MouseEvent(name, canvas, px, py, button=1))


spec = example()
ex = plot.explore(spec.task, spec.driven_center, (-8, 8, -8, 8),
                  limits=burmester.DesignLimits(min_transmission_deg=35))
ex.figure.canvas.draw()
drag(ex, (2.0, 0.5), (2.3, 0.3))           # pose 2
best = ex.solution_map.best_pivots(1)[0]   # the moved task's best driving pivot
drag(ex, ex.driving_center, best.center)   # A0 onto it
print("A0 =", ex.driving_center, ex.linkage().figures.grashof)
plt.show()
