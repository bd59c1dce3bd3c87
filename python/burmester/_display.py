"""Pictures of the objects in Jupyter: the ``_repr_png_`` of ``Task``,
``Filemon``, ``FourBar``, ``SynthesizedFourBar``, ``SolutionMap`` (through
the native classes), ``PairMap``, ``Cubic`` and ``PivotAtlas``.

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
``PairMap``           :func:`burmester.plot.pair_map`
``Cubic``             :func:`cubic`: every component in :func:`cubic_view`
``PivotAtlas``        :func:`burmester.plot.atlas`
``Design``            :func:`burmester.plot.linkage` of its linkage
``Drive``, ``SixBar`` :func:`burmester.plot.sixbar`
``DriveMap``          :func:`burmester.plot.drive_map`
``SliderCrank``       :func:`burmester.plot.slider_crank` (alone)
``SynthesizedSliderCrank`` :func:`burmester.plot.slider_crank` (at its poses)
``SliderDyad``        :func:`burmester.plot.slider_dyad`
``Actuator``          :func:`burmester.actuators.draw_actuator`
``ActuatorMap``       :func:`burmester.actuators.draw_map`
``InvertedSliderCrank`` :func:`burmester.plot.inverted_slider_crank` (alone)
``SynthesizedInvertedSliderCrank`` :func:`burmester.plot.inverted_slider_crank` (at its poses)
===================== =============================================

matplotlib is imported when a picture is asked for, not before: ``import
burmester`` does not import it. Without matplotlib, ``repr_png`` returns
None and IPython shows the object's ``repr`` instead.
"""

from __future__ import annotations

import importlib
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

    if isinstance(obj, burmester.Design):  # the picture of its linkage, of either kind
        return drawer(obj.linkage)
    # The picture of each kind: its type's name in burmester, the plot function's name (in order).
    pictures = (("Task", "poses"), ("Filemon", "center_plane"), ("FourBar", "four_bar"),
                ("SynthesizedFourBar", "linkage"), ("SolutionMap", "solution_map"), ("PairMap", "pair_map"),
                ("Cubic", None), ("PivotAtlas", "atlas"), ("Design", "linkage"), ("Drive", "sixbar"),
                ("SixBar", "sixbar"), ("DriveMap", "drive_map"), ("SliderCrank", "slider_crank"),
                ("SynthesizedSliderCrank", "slider_crank"), ("SliderDyad", "slider_dyad"),
                ("Actuator", "actuators.draw_actuator"), ("ActuatorMap", "actuators.draw_map"),
                ("InvertedSliderCrank", "inverted_slider_crank"),
                ("SynthesizedInvertedSliderCrank", "inverted_slider_crank"))
    for kind, name in pictures:
        if not isinstance(obj, getattr(burmester, kind)):
            continue
        if name is None:
            return lambda ax: cubic(obj, ax)
        module, _, function = name.rpartition(".")
        draw = getattr(importlib.import_module(f"burmester.{module}") if module else plot, function)
        shown = obj.linkage if isinstance(obj, burmester.Design) else obj
        return lambda ax: draw(shown, ax=ax)
    raise TypeError(f"no picture for a {type(obj).__name__}")


#: Half the side of :func:`cubic_view`, in units of the cubic's own scale.
CUBIC_VIEW_HALF = 4.0


def cubic_view(curve: Any) -> Tuple[float, float, float, float]:
    """The square ``(xmin, xmax, ymin, ymax)`` a cubic is drawn in: the
    frame it is kept in (for a Burmester curve, about the task: its origin
    and size, see :meth:`burmester.Cubic.__reduce__`), :data:`CUBIC_VIEW_HALF`
    of its scale each way."""
    _, (_, (ox, oy), scale) = curve.__reduce__()
    h = CUBIC_VIEW_HALF * scale
    return (ox - h, ox + h, oy - h, oy + h)


def cubic(curve: Any, ax: Axes) -> Axes:
    """Draw every component of a :class:`burmester.Cubic` in
    :func:`cubic_view` (:meth:`burmester.Cubic.polylines`: exact, none
    missed), one colour per component."""
    xmin, xmax, ymin, ymax = view = cubic_view(curve)
    for k, line in enumerate(curve.polylines(*view)):
        ax.plot(line[:, 0], line[:, 1], color=f"C{k % 10}", lw=1.5)
    ax.set_xlim(xmin, xmax)
    ax.set_ylim(ymin, ymax)
    ax.set_aspect("equal")
    kind = "circular cubic" if curve.is_circular else f"curve of degree {curve.degree}"
    ax.set_title(f"a {kind}")
    return ax


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
