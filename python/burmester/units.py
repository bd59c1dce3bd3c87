"""The unit of a task's lengths, and how tables, pictures and CAD files show it.

A task file may name the unit its lengths are in, at the top level::

    units = "mm"

Any unit name is accepted (``"mm"``, ``"in"``, ``"m"``, ``"furlong"``); it
scales nothing (the numbers are used as they are) and is only said: after
every length the command line prints, on the axes of every picture
(``x [mm]``), and in the header of a DXF file (``$INSUNITS``, where ezdxf
knows the unit; otherwise the name is written into the drawing). Without a
unit the axes read plain ``x`` and ``y`` and lengths are bare numbers.

Two functions are all a table or a picture needs:

- :func:`format_length`: ``format_length(123.456, "mm") == "123.5 mm"``;
- :func:`label_axes`: ``label_axes(ax, "mm")`` writes ``x [mm]`` and
  ``y [mm]`` (or ``x``, ``y``) on a matplotlib Axes; :func:`axis_label`
  gives one such label as text.

:func:`check_units` validates a name (a :class:`burmester.InvalidInputError`
naming what to change); :func:`dxf_units` gives the DXF ``$INSUNITS`` code
of a name ezdxf knows (imported only then).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Dict, Optional, Tuple

from burmester._burmester import InvalidInputError

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["MAX_UNITS_LENGTH", "axis_label", "check_units", "dxf_imperial", "dxf_units", "format_length", "label_axes", "suffix"]

#: The longest unit name accepted, in characters.
MAX_UNITS_LENGTH = 32


def check_units(units: Any, where: str = "units") -> Optional[str]:
    """``units`` as a unit name (a string stripped of surrounding spaces), or
    None for None (no unit given).

    Raises :class:`burmester.InvalidInputError` (naming ``where``) for
    something other than a string, an empty name, one longer than
    :data:`MAX_UNITS_LENGTH` characters, or one with a control character
    (a newline, a tab) or a bracket, which would break a table or an axis
    label.
    """
    if units is None:
        return None
    if not isinstance(units, str):
        raise InvalidInputError(
            f'{where} must be a unit name such as "mm" or "in", got {units!r} ({type(units).__name__})'
        )
    name = units.strip()
    if not name:
        raise InvalidInputError(
            f'{where} must be a unit name such as "mm" or "in", got an empty name; leave it out for no unit'
        )
    if len(name) > MAX_UNITS_LENGTH:
        raise InvalidInputError(
            f"{where} must be at most {MAX_UNITS_LENGTH} characters, got {len(name)} ({name[:12]!r}...)"
        )
    bad = [c for c in name if not c.isprintable() or c in "[]"]
    if bad:
        raise InvalidInputError(
            f"{where} must be a plain unit name without control characters or brackets, got {name!r}"
        )
    return name


def suffix(units: Optional[str]) -> str:
    """``" mm"`` after a number for ``"mm"``; ``""`` without a unit."""
    return f" {units}" if units else ""


def format_length(value: Optional[float], units: Optional[str] = None, digits: int = 4) -> str:
    """A length with its unit: ``format_length(123.456, "mm") == "123.5 mm"``,
    ``format_length(0.5) == "0.5"``.

    ``digits`` significant digits (``%g`` style; at least the integer part
    of a length below 10^digits, so 12345.6 mm reads ``12346 mm``, not
    ``1.235e+04 mm``). None and non-finite lengths read ``-``, ``inf`` or
    ``nan``, without a unit.
    """
    if value is None:
        return "-"
    v = float(value)
    if not math.isfinite(v):
        return str(v)
    magnitude = int(math.floor(math.log10(abs(v)))) + 1 if v != 0.0 else 1
    text = f"{v:.{max(digits, magnitude)}g}" if magnitude <= 12 else f"{v:.{digits}g}"
    if text in ("-0", "-0.0"):
        text = "0"
    return text + suffix(units)


def axis_label(axis: str, units: Optional[str] = None) -> str:
    """``"x [mm]"`` for ``axis_label("x", "mm")``; ``"x"`` without a unit."""
    return f"{axis} [{units}]" if units else axis


def label_axes(ax: Axes, units: Optional[str] = None, x: str = "x", y: str = "y") -> Tuple[str, str]:
    """Write the axis labels of a matplotlib Axes with the unit:
    ``x [mm]`` and ``y [mm]`` (``x`` and ``y`` without a unit; ``x`` and
    ``y`` name the axes, e.g. ``"driven center x"``). Returns the two labels."""
    xl, yl = axis_label(x, units), axis_label(y, units)
    ax.set_xlabel(xl)
    ax.set_ylabel(yl)
    return xl, yl


def _dxf_names() -> Dict[str, int]:
    """Unit names ezdxf knows, lower case, with their ``$INSUNITS`` code:
    its abbreviations (``mm``, ``in``, ``yd``, ``µm``) and its full names,
    plural and singular (``millimeters``, ``millimeter``)."""
    from ezdxf import units as ezu
    from ezdxf.enums import InsertUnits

    names: Dict[str, int] = {"unitless": 0}
    for code in InsertUnits:
        value = int(code)
        abbreviation = ezu.decode(value) if value else None
        if abbreviation:
            names[abbreviation.lower()] = value
        full = code.name.lower()
        for name in (full, full[:-1] if full.endswith("s") else full):
            names.setdefault(name, value)
    # Common spellings ezdxf's tables leave out.
    for alias, abbreviation in (("um", "µm"), ("micrometer", "µm"), ("micrometers", "µm"),
                                ("millimetre", "mm"), ("millimetres", "mm"), ("centimetre", "cm"),
                                ("centimetres", "cm"), ("metre", "m"), ("metres", "m"),
                                ("kilometre", "km"), ("kilometres", "km"), ("inch", "in"), ("foot", "ft")):
        if abbreviation in names:
            names.setdefault(alias, names[abbreviation])
    return names


def dxf_units(units: Optional[str]) -> Optional[int]:
    """The DXF ``$INSUNITS`` code of a unit name that ezdxf knows, in any
    case (``"mm"`` 4, ``"in"`` 1, ``"yd"`` 10, ``"Millimeters"`` 4,
    ``"unitless"`` 0), or None for a name it does not know (and for None).
    Needs ezdxf."""
    if units is None:
        return None
    return _dxf_names().get(units.strip().lower())


def dxf_imperial(code: int) -> bool:
    """Whether a ``$INSUNITS`` code is an imperial unit (ezdxf's
    ``IMPERIAL_UNITS``): the drawing's ``$MEASUREMENT`` is then 0
    (English), else 1 (metric). Needs ezdxf."""
    from ezdxf import units as ezu

    return code in {int(u) for u in ezu.IMPERIAL_UNITS}
