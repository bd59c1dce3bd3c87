"""
Position analysis: both assembly modes
======================================

Norton's Example 4-1 (ground 100, crank 40, coupler 120, rocker 80 mm) at
an input angle of 40 degrees, in the open and the crossed assembly mode,
with the published angles checked.
"""

import math

import matplotlib.pyplot as plt

import burmester
import burmester.plot as bp

fb = burmester.FourBar(ground=100.0, crank=40.0, coupler=120.0, rocker=80.0)
for mode in ("open", "crossed"):
    t3, t4 = fb.solve(math.radians(40), mode=mode)
    print(f"{mode:8} theta3 = {math.degrees(t3):8.3f} deg, theta4 = {math.degrees(t4):8.3f} deg")
fig, (left, right) = plt.subplots(1, 2, figsize=(11.0, 4.5))
bp.four_bar(fb, math.radians(40), "open", ax=left)
bp.four_bar(fb, math.radians(40), "crossed", ax=right)
plt.show()
