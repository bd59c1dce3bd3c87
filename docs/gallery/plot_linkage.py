"""
The best pivot's linkage at the three poses
===========================================

The lid of the previous picture with the best driving pivot by the balanced
score: the four-bar drawn at each pose, the coupler point's path between
them. Driven to its input angle at each pose, in that pose's assembly mode,
it carries the coupler point onto the pose (checked below).
`burmester linkage lid.toml -o lid.png` draws the same.
"""

import math

import matplotlib.pyplot as plt

import burmester
import burmester.plot as bp

task = burmester.Task([(0, 0, 0), (60, 55, math.radians(40)), (90, 140, math.radians(85))])
filemon = task.filemon((-60.0, -40.0))
best = filemon.solution_map((-250, 250, -250, 250, 300, 300), min_transmission_deg=40).best_pivots(1)[0]
linkage = best.linkage
print("lengths (ground, crank, coupler, rocker):", [round(v, 1) for v in linkage.fourbar.lengths])
for theta, mode, pose in zip(linkage.input_angles, linkage.modes, task.poses):
    x, y, _ = linkage.pose_at(theta, mode)
    print(f"{mode:8} input {math.degrees(theta):7.2f} deg: {math.dist((x, y), pose[:2]):.1e} mm from the pose")
bp.linkage(linkage, task=task)
plt.show()
