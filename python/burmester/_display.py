"""Pictures of the objects in Jupyter: the ``_repr_png_`` of ``Task``,
``Filemon``, ``FourBar``, ``SynthesizedFourBar``, ``SolutionMap`` (through
the native classes) and ``PivotAtlas``.

Each picture is the object's natural figure from :mod:`burmester.plot`,
drawn with the Agg renderer on a :class:`matplotlib.figure.Figure` of its
own (not a pyplot figure: the user's current figure, backend and list of
figures stay as they were) and returned as PNG bytes:

===================== =============================================
``Task``              :func:`burmester.plot.poses`: the poses and poles
``Filemon``           :func:`burmester.plot.center_plane` (default view)
``FourBar``           :func:`burmester.plot.four_bar` (default input angle)
``SynthesizedFourBar`` :func:`burmester.plot.linkage`: the linkage at the poses
``SolutionMap``       :func:`burmester.plot.solution_map`
``PivotAtlas``        :func:`burmester.plot.atlas`
``Drive``, ``SixBar`` :func:`burmester.plot.sixbar`
``DriveMap``          :func:`burmester.plot.drive_map`
===================== =============================================

matplotlib is imported when a picture is asked for, not before: ``import
burmester`` does not import it. Without matplotlib, ``repr_png`` returns
None and IPython shows the object's ``repr`` instead.
"""

from __future__ import annotations

import io
from typing import TYPE_CHECKING, Any, Callable, Optional, Tuple

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

#: Size of the figure a notebook picture is drawn on, inches, and its
#: resolution (the picture is then cut to its content: :func:`png`).
FIGSIZE: Tuple[float, float] = (7.0, 5.0)
DPI = 80


def drawer(obj: object) -> Callable[[Axes], Any]:
    """The plot function that draws ``obj``, as a function of the Axes.
    Raises TypeError for an object without a picture."""
    import burmester
    from burmester import plot

    if isinstance(obj, burmester.Task):
        return lambda ax: plot.poses(obj, ax=ax)
    if isinstance(obj, burmester.Filemon):
        return lambda ax: plot.center_plane(obj, ax=ax)
    if isinstance(obj, burmester.FourBar):
        return lambda ax: plot.four_bar(obj, ax=ax)
    if isinstance(obj, burmester.SynthesizedFourBar):
        return lambda ax: plot.linkage(obj, ax=ax)
    if isinstance(obj, burmester.SolutionMap):
        return lambda ax: plot.solution_map(obj, ax=ax)
    if isinstance(obj, burmester.PivotAtlas):
        return lambda ax: plot.atlas(obj, ax=ax)
    if isinstance(obj, (burmester.Drive, burmester.SixBar)):
        return lambda ax: plot.sixbar(obj, ax=ax)
    if isinstance(obj, burmester.DriveMap):
        return lambda ax: plot.drive_map(obj, ax=ax)
    raise TypeError(f"no picture for a {type(obj).__name__}")


def figure(draw: Callable[[Axes], Any]) -> Figure:
    """A figure of :data:`FIGSIZE` at :data:`DPI` on the Agg canvas, not
    known to pyplot, with one Axes drawn by ``draw``."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=FIGSIZE, dpi=DPI)
    FigureCanvasAgg(fig)
    draw(fig.add_subplot())
    return fig


#: The margin around a picture's content, inches (the picture is cut to its
#: content, as IPython's inline backend does, so that a legend beside the
#: axes is never cut off).
PAD_INCHES = 0.1


def png(fig: Figure) -> bytes:
    """The figure as PNG bytes at its resolution, cut to its content with
    :data:`PAD_INCHES` around it (``bbox_inches="tight"``)."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=fig.dpi, bbox_inches="tight", pad_inches=PAD_INCHES)
    return buf.getvalue()


def repr_png(obj: object) -> Optional[bytes]:
    """The PNG picture of ``obj`` (see the module), or None when matplotlib
    is not installed."""
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return None
    return png(figure(drawer(obj)))
