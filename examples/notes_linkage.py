"""The known crank-rocker of the README and of the four- and five-position
notes, and the coupler poses it carries: shared by the picture scripts
(``four_five_picture.py``, ``pair_map_picture.py``)."""

import math

import burmester

FB = burmester.FourBar.from_pivots((0, 0), (4, 0), 1.5, 3.5, 3.0)


def pose(deg: float) -> tuple:
    """The coupler pose at a crank angle: the point (1, 1.5) in the frame at
    the crank joint A, x toward the rocker joint B."""
    _, a, b, _ = FB.joints(math.radians(deg))
    phi = math.atan2(b[1] - a[1], b[0] - a[0])
    return (a[0] + math.cos(phi) - 1.5 * math.sin(phi), a[1] + math.sin(phi) + 1.5 * math.cos(phi), phi)


def task(*degrees: float) -> burmester.Task:
    """The task of the coupler poses at these crank angles (degrees)."""
    return burmester.Task([pose(d) for d in degrees])
