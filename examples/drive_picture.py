"""Writes docs/drive.png and docs/drive.gif, the README's pictures of a
motor for a linkage whose input swings: ``python examples/drive_picture.py``
(needs the ``plot`` extra).

The linkage is the built-in example's best by transmission angle, a
triple-rocker (its input link only swings); ``best_drive`` adds a
crank-rocker to its input link, making a Watt II six-bar that a motor turns
round and round. The picture shows the drive map of the chosen attachment
(left: where the motor's pivot may go) and the six-bar at the three poses
(right); the animation runs one full crank turn.
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

import burmester  # noqa: E402
from burmester import plot, taskfile  # noqa: E402


def main() -> None:
    docs = Path(__file__).resolve().parents[1] / "docs"
    spec = taskfile.example()
    smap = spec.filemon().solution_map(spec.view, limits=spec.limits)
    rocker = smap.best_pivots(1, rank_by="transmission")[0].linkage
    drive = rocker.best_drive(limits=spec.limits)
    a0 = rocker.driving[0]
    h = 1.25 * max(abs(drive.drive_pivot[0] - a0[0]), abs(drive.drive_pivot[1] - a0[1]),
                   abs(drive.attachment[0] - a0[0]), abs(drive.attachment[1] - a0[1]))
    dmap = rocker.drive_map(a0[0] - h, a0[0] + h, a0[1] - h, a0[1] + h, 400, 400,
                            attachment=drive.attachment, limits=spec.limits)
    fig, (left, right) = plt.subplots(1, 2, figsize=(15.0, 6.2))
    plot.drive_map(dmap, best=1, ax=left, legend=False)
    left.legend(loc="lower left", fontsize="x-small")
    plot.sixbar(drive, ax=right, legend=False)
    right.legend(loc="lower left", fontsize="x-small")
    fig.tight_layout()
    out = docs / "drive.png"
    fig.savefig(out, dpi=64, bbox_inches="tight")
    plt.close(fig)
    print(f"wrote {out} ({out.stat().st_size // 1024} KiB)")
    gif = docs / "drive.gif"
    plot.animate_sixbar(drive, gif, frames=48, fps=16, dpi=56)
    print(f"wrote {gif} ({gif.stat().st_size // 1024} KiB)")


if __name__ == "__main__":
    main()
