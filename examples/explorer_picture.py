"""Writes docs/explorer.png, the README's picture of the interactive
explorer: ``python examples/explorer_picture.py`` (needs the ``plot``
extra). It opens the explorer on the built-in example, drags pose 2, then
the driving pivot A0 onto the moved task's best pivot, with the mouse
events a user's drag sends, and saves the figure."""

import sys
from pathlib import Path
from typing import Optional

import matplotlib

matplotlib.use("Agg")

import burmester  # noqa: E402
from burmester import plot  # noqa: E402
from burmester.taskfile import example  # noqa: E402


def main(out: Optional[Path] = None) -> Path:
    out = Path(__file__).resolve().parents[1] / "docs" / "explorer.png" if out is None else out
    spec = example()
    ex = plot.explore(spec.task, spec.driven_center, (-8, 8, -8, 8),
                      limits=burmester.DesignLimits(min_transmission_deg=35))
    ex.figure.canvas.draw()
    ex.drag((2.0, 0.5), (2.3, 0.3))            # pose 2, a little right and down
    best = ex.solution_map.best_pivots(1)[0]   # the moved task's best driving pivot
    ex.drag(ex.driving_center, best.center)    # A0 onto it
    ex.save(out, dpi=72)
    print(f"wrote {out} ({out.stat().st_size // 1024} KiB): A0 = {ex.driving_center}, "
          f"{ex.linkage().figures.grashof}, error = {ex.error}", file=sys.stderr)
    return out


if __name__ == "__main__":
    main()
