"""
The center-point plane of the built-in example
==============================================

`burmester map -o map.png` draws this picture, the README's first: the
driving crank's center-point plane of the built-in example (three poses,
the driven crank's fixed pivot `C0 = (4, -1)`). The pivots `A0` that give a
linkage free of the branch problem are shaded; the two curves are Filemon's
lines transformed exactly into this plane (Borm & Kim's Fig. 10 and 12),
and they pass through the three poles and `C0`.
"""

import matplotlib.pyplot as plt

import burmester
import burmester.plot as bp

task = burmester.Task([(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)])  # x, y, angle (rad)
filemon = task.filemon((4.0, -1.0))  # the driven crank's fixed pivot C0
grid = burmester.Grid(-8, 8, -8, 8, 400, 400)  # xmin, xmax, ymin, ymax, nx, ny
ax = bp.center_plane(filemon, grid)
print(f"{100 * filemon.branch_map(grid).mean():.1f}% of the plane is branch-free")
plt.show()
