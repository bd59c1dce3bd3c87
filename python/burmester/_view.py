"""The one parser of views and grids for the pictures, the CAD export and
the atlas (issue 25): a view is a :class:`burmester.Grid` or ``(xmin,
xmax, ymin, ymax)``, a grid a Grid or ``(xmin, xmax, ymin, ymax, nx, ny)``,
samples ``(nx, ny)``.

The core's :class:`burmester.Grid` checks the numbers (finite bounds,
``xmin < xmax``, ``ymin < ymax``, the sample counts); this module only
unpacks what it is given, and bounds a grid's ``(nx, ny)`` given on its
own (:func:`resample`: 2 to :data:`MAX_SIDE`, as the CAD export always had).
Every error is a :class:`burmester.InvalidInputError` (a ``ValueError``);
an argument that is not a view or a grid at all (a string, three numbers,
a sample count that is not an int) raises :class:`ViewTypeError`, which is
also a ``TypeError``.
"""

from __future__ import annotations

from typing import Any, Callable, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from burmester._burmester import Grid, InvalidInputError

Extent = Tuple[float, float, float, float]
#: A view: a :class:`burmester.Grid`, or ``(xmin, xmax, ymin, ymax)``.
ViewLike = Union[Grid, Sequence[float]]
#: A grid: a :class:`burmester.Grid`, or ``(xmin, xmax, ymin, ymax, nx, ny)``.
GridLike = Union[Grid, Sequence[float]]

#: Most samples along one side of a grid given as ``(nx, ny)``.
MAX_SIDE = 100_000


class ViewTypeError(InvalidInputError, TypeError):
    """A view or grid that is not one (not a Grid, nor a sequence of the
    right count of numbers): a :class:`burmester.InvalidInputError` and a
    ``TypeError``."""

    cause = "viewport"


def _numbers(value: Any, count: int) -> Optional[Tuple[float, ...]]:
    """``value`` as ``count`` floats, or None when it is not that."""
    if isinstance(value, (str, bytes)):
        return None
    try:
        numbers = tuple(float(t) for t in value)
    except (TypeError, ValueError):
        return None
    return numbers if len(numbers) == count else None


def extent(view: Any, what: str = "view") -> Extent:
    """``(xmin, xmax, ymin, ymax)`` of a Grid or of four numbers, checked by
    the core (:class:`burmester.Grid`: finite, ``xmin < xmax`` and ``ymin < ymax``)."""
    if isinstance(view, Grid):
        return view.extent
    numbers = _numbers(view, 4)
    if numbers is None:
        raise ViewTypeError(f"{what} must be a burmester.Grid or (xmin, xmax, ymin, ymax), got {view!r}")
    xmin, xmax, ymin, ymax = numbers
    return Grid(xmin, xmax, ymin, ymax, 1, 1).extent


def grid(value: GridLike, what: str = "grid") -> Grid:
    """A Grid from a Grid or ``(xmin, xmax, ymin, ymax, nx, ny)``."""
    if isinstance(value, Grid):
        return value
    numbers = _numbers(value, 6)
    if numbers is None:
        raise ViewTypeError(f"{what}: expected a burmester.Grid or (xmin, xmax, ymin, ymax, nx, ny), got {value!r}")
    x0, x1, y0, y1, nx, ny = numbers
    return Grid(x0, x1, y0, y1, int(nx), int(ny))


def resample(g: Grid, samples: Sequence[Any], what: str = "grid", most: int = MAX_SIDE) -> Grid:
    """``g`` with ``samples = (nx, ny)``, each an int from 2 to ``most``."""
    if isinstance(samples, (str, bytes)) or len(samples) != 2:
        raise ViewTypeError(f"{what} must be (nx, ny), got {samples!r}")
    counts = []
    for name, n in zip((f"{what} nx", f"{what} ny"), samples):
        if isinstance(n, bool) or not hasattr(n, "__index__"):
            raise ViewTypeError(f"{name} must be an int, got {type(n).__name__}")
        if not 2 <= int(n) <= most:
            raise InvalidInputError(f"{name} must be from 2 to {most}, got {int(n)}")
        counts.append(int(n))
    return Grid(g.xmin, g.xmax, g.ymin, g.ymax, counts[0], counts[1])


def view_grid(view: Optional[ViewLike], samples: Optional[Sequence[Any]], default: Callable[[], Grid],
              side: int) -> Grid:
    """The grid of a plane: ``view`` (a Grid as it is; four numbers with
    ``side`` samples along the longer side, :func:`burmester.taskfile.grid_for`)
    or ``default()`` when None; ``samples = (nx, ny)`` when given."""
    from burmester.taskfile import grid_for

    if view is None:
        g = default()
    elif isinstance(view, Grid):
        g = view
    else:
        g = grid_for(*extent(view), side)
    return g if samples is None else resample(g, samples)


def on_grid(name: str, array: Optional[npt.ArrayLike], g: Grid) -> Optional[npt.NDArray[Any]]:
    """``array`` as a NumPy array of the grid's shape ``(ny, nx)``
    (InvalidInputError naming ``name`` otherwise), or None when not given."""
    if array is None:
        return None
    a = np.asarray(array)
    if a.shape != g.shape:
        raise InvalidInputError(f"{name} must have the grid's shape (ny, nx) = {g.shape}, got {a.shape}")
    return a
