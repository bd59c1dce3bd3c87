"""
Filemon's construction in the circle-point plane
================================================

The circle-point plane of the built-in example (Borm & Kim's Fig. 3 and
11): the driven crank's moving pivot `C1`, the images `C'k` of its fixed
pivot, the three lines through them, and the double wedge of driving circle
points free of the branch problem. `burmester map --plane circle` draws it.
"""

import matplotlib.pyplot as plt

import burmester
import burmester.plot as bp

task = burmester.Task([(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)])
filemon = task.filemon((4.0, -1.0))
print("C1 =", filemon.driven_circle, "extreme poses:", filemon.extreme_poses)
bp.circle_plane(filemon)
plt.show()
