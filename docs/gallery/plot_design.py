"""
The one-call design: a car hood's hinge
=======================================

Three poses of a car hood in millimetres (its front edge travels 89 mm
while the hood tips back 60 degrees), both fixed pivots on the body below
the closed hood, at least 40 degrees of transmission, at most five times
the motion's size (`examples/hood.toml`). `burmester.design` searches both
pivots, refines the best candidates on the exact figures, and answers with
the best linkage, drawn here at the three poses (dotted: the box the pivots
must lie in).
`burmester design examples/hood.toml -o hood.png` draws the same.
"""

import math

import matplotlib.pyplot as plt

import burmester
import burmester.plot as bp

hood = burmester.Task([(0.0, 0.0, 0.0), (-25.0, 45.0, math.radians(30)), (-40.0, 80.0, math.radians(60))])
space = burmester.Space(pivot_box=(-150.0, 50.0, -100.0, 0.0))  # xmin, xmax, ymin, ymax (mm)
limits = burmester.DesignLimits(min_transmission_deg=40, max_size_ratio=5)  # Grashof margin 0.01 by default

report = burmester.design(hood, space=space, limits=limits, top=3)
for k, d in enumerate(report, start=1):
    f = d.figures
    print(f"design {k}: {f.grashof}, links (ground, crank, coupler, rocker) "
          f"{', '.join(f'{v:.1f}' for v in f.lengths)} mm, "
          f"min transmission {f.min_transmission_deg:.1f} deg, size {d.size_ratio:.2f}x the motion, "
          f"Grashof margin {f.grashof_margin:.3f}, score {d.score:.3f}")

best = report[0]
print(f"best: A0 = ({best.driving_pivot[0]:.1f}, {best.driving_pivot[1]:.1f}) mm, "
      f"C0 = ({best.driven_pivot[0]:.1f}, {best.driven_pivot[1]:.1f}) mm")
ax = bp.linkage(best.linkage, task=hood, units="mm")
x0, x1, y0, y1 = space.pivot_box
ax.add_patch(plt.Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, linestyle=":", color="grey",
                           label="pivot box"))
plt.show()
