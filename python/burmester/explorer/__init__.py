"""The interactive explorer of a three-position task.

:class:`Explorer` (opened by :func:`burmester.plot.explore`) is a matplotlib
figure of two axes. On the left, the driving crank's center-point plane as
:func:`burmester.plot.center_plane` draws it: the branch-free driving pivots
shaded, those that also meet the limits shaded darker (the solution map's
``acceptable``), the transformed Filemon curves, the poles, the pole
triangle and circle; over it the handles you drag:

- each pose: a dot in its colour (drag to move the pose) and a square at the
  end of its flag (drag to turn the pose; the scroll wheel over either turns
  it by :data:`ANGLE_STEP_DEG` a step);
- ``C0``, the driven crank's fixed pivot (an orange triangle);
- ``A0``, the driving crank's fixed pivot (a gold star); a click on the
  plane away from every handle puts ``A0`` there.

On the right, the linkage of ``A0`` and ``C0`` drawn at the poses
(:func:`burmester.plot.linkage`), and below both its figures (Grashof type,
minimum transmission angle over the travel, input direction, feasible,
branch-free) or, when a move is refused, why.

Every move rebuilds the task with the core (``Task``, ``Task.filemon``,
``Filemon.solution_map``, ``Filemon.four_bar``): nothing is computed here.
A move the core refuses (a pose dragged onto another, ``C0`` onto a pole,
``A0`` onto the pole circle, ...) shows the error and keeps the last good
state; the handles go back to it.

Recomputing the solution map is fast (about 4 ms for 256 x 256 samples in
BENCHMARKS.md, some 20 ms for the default 240 x 240 on a busy two-core
machine; drawing the figure costs more), so for grids up to
:data:`LIVE_SAMPLES` samples the map follows the pointer
while you drag; for larger grids (``live=False``) the dragged handle follows
the pointer and the map is recomputed when you let go. Moving ``A0`` only
rebuilds the linkage, and always follows the pointer.

Keys (with the pointer over the figure): ``b`` puts ``A0`` on the best pivot
of the map (:meth:`burmester.SolutionMap.best_pivots`), ``r`` goes back to
the state the explorer opened with (and, as matplotlib's home key, to the
first view), ``e`` saves to ``export_to`` (see
:meth:`Explorer.save`). The toolbar's zoom and pan modes take the mouse
while they are on.

The explorer uses only matplotlib's backend-independent event API
(``mpl_connect`` and ``draw_idle``), so it works in any interactive backend:
a desktop window (``python -i``, ``plt.show()``) or Jupyter with
``%matplotlib widget`` (ipympl, installed by ``pip install
"burmester[plot]"``). With a non-interactive backend (Agg) it draws the
figure and takes events given to ``fig.canvas.callbacks.process``, which is
how the tests drive it.

The package: :mod:`burmester.explorer.state` (the task, the pivots, the map
and the linkage, each move checked by the core; no matplotlib) and
:mod:`burmester.explorer.view` (the figure: drawing and events). Importing
``burmester.explorer.state`` alone does not import matplotlib.
"""


from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from burmester.explorer.view import ANGLE_STEP_DEG, EXPLORE_SAMPLES, LIVE_SAMPLES, PICK_PIXELS, Explorer

__all__ = ["ANGLE_STEP_DEG", "EXPLORE_SAMPLES", "LIVE_SAMPLES", "PICK_PIXELS", "Explorer"]


def __getattr__(name: str) -> Any:
    """The view's names, imported (with matplotlib) when first asked for."""
    if name in __all__:
        from burmester.explorer import view

        return getattr(view, name)
    raise AttributeError(f"module 'burmester.explorer' has no attribute {name!r}")
