"""Writes docs/explorer.png, the README's picture of the interactive
explorer: ``python examples/explorer_picture.py`` (needs the ``plot``
extra). It opens the explorer on the built-in example, drags pose 2, then
the driving pivot A0 onto the moved task's best pivot, with the mouse
events a user's drag sends, and saves the figure."""

import sys
from pathlib import Path
from typing import Optional, Tuple

import matplotlib

matplotlib.use("Agg")
from matplotlib.backend_bases import MouseEvent  # noqa: E402

import burmester  # noqa: E402
from burmester import plot  # noqa: E402
from burmester.explorer import Explorer  # noqa: E402
from burmester.taskfile import example  # noqa: E402


def drag(ex: Explorer, start: Tuple[float, float], end: Tuple[float, float], steps: int = 4) -> None:
    """Press the left button at ``start``, move to ``end``, release: as a user would."""
    canvas = ex.figure.canvas
    path = [start] + [(start[0] + (end[0] - start[0]) * k / steps, start[1] + (end[1] - start[1]) * k / steps)
                      for k in range(1, steps + 1)]
    names = ["button_press_event"] + ["motion_notify_event"] * steps
    for name, xy in list(zip(names, path)) + [("button_release_event", end)]:
        px, py = ex.ax_map.transData.transform(xy)
        canvas.callbacks.process(name, MouseEvent(name, canvas, px, py, button=1))


def main(out: Optional[Path] = None) -> Path:
    out = Path(__file__).resolve().parents[1] / "docs" / "explorer.png" if out is None else out
    spec = example()
    ex = plot.explore(spec.task, spec.driven_center, (-8, 8, -8, 8),
                      limits=burmester.DesignLimits(min_transmission_deg=35))
    ex.figure.canvas.draw()
    drag(ex, (2.0, 0.5), (2.3, 0.3))           # pose 2, a little right and down
    best = ex.solution_map.best_pivots(1)[0]   # the moved task's best driving pivot
    drag(ex, ex.driving_center, best.center)   # A0 onto it
    ex.save(out, dpi=72)
    print(f"wrote {out} ({out.stat().st_size // 1024} KiB): A0 = {ex.driving_center}, "
          f"{ex.linkage().figures.grashof}, error = {ex.error}", file=sys.stderr)
    return out


if __name__ == "__main__":
    main()
