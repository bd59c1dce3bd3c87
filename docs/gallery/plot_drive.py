"""
A motor for a swinging input: the six-bar
=========================================

The hood hinge of the one-call design with `input="motor"`: every design
must be turnable by a motor. The best hinge swings its input 157 degrees,
which no crank-rocker drives well, so it is passed over; the next one,
a triple-rocker, gets the best added crank-rocker (`best_drive`): an
11 mm motor crank on the body turns round and round and swings the input
link through the poses once per stroke (the Watt II six-bar). Drawn at
the crank angles of the three poses, with the crank circle and the
attachment's swing. `burmester design examples/hood.toml --motor -o six.gif`
animates it.
"""

import math

import matplotlib.pyplot as plt

import burmester
import burmester.plot as bp

hood = burmester.Task([(0.0, 0.0, 0.0), (-25.0, 45.0, math.radians(30)), (-40.0, 80.0, math.radians(60))])
space = burmester.Space(pivot_box=(-150.0, 50.0, -100.0, 0.0))
limits = burmester.DesignLimits(min_transmission_deg=40, max_size_ratio=5)

report = burmester.design(hood, space=space, limits=limits, input="motor", top=1)
print(f"designs passed over for want of a drive: {report.undriven}")
design = report[0]
drive = design.drive  # None would mean the input turns fully: the motor turns A0 directly
six = drive.sixbar
names = ["drive ground |A0 D0|", "crank", "drive coupler", "|A0 E|", "input |A0 A|", "coupler",
         "rocker", "ground |A0 C0|"]
print("six-bar links (mm): " + ", ".join(f"{n} {v:.1f}" for n, v in zip(names, six.lengths)))
print(f"motor pivot D0 = ({drive.drive_pivot[0]:.1f}, {drive.drive_pivot[1]:.1f}) mm, "
      f"drive loop {six.drive_grashof}, turns {drive.direction}")
print(f"transmission over a full crank turn: drive {drive.drive_transmission_deg:.1f} deg, "
      f"linkage {drive.motion_transmission_deg:.1f} deg (limit {limits.min_transmission_deg:.0f})")
print(f"time ratio {drive.time_ratio:.3f}, working stroke {math.degrees(drive.stroke):.1f} deg of crank, "
      f"size {drive.size_ratio:.2f}x the motion, link ratio {drive.link_ratio:.2f}")
print("crank angle at each pose: "
      + ", ".join(f"{k}: {math.degrees(phi) % 360:.1f} deg" for k, phi in enumerate(drive.pose_crank_angles, 1)))
bp.sixbar(drive)
plt.show()
