"""What each pose count offers: the one place the Python package decides by
the number of poses.

A task of three poses has Filemon's construction for a driven dyad (the
branch and solution maps, ranked driving pivots, the atlas, the explorer, a
design search whose coarse pass runs on Dask); four poses have the center-
and circle-point curves (the pair map, a driven dyad on the curve); five
poses have finitely many dyads, the Burmester points. The command line, the
task files, :func:`burmester.design` and the explorer ask :func:`of` what a
task offers instead of testing ``len(task.poses)``; a new pose count is a new
row of :data:`COUNTS`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Dict, Sized

from burmester._burmester import InvalidInputError

__all__ = ["COUNTS", "PoseCount", "of"]


@dataclass(frozen=True)
class PoseCount:
    """What a task of :attr:`poses` poses offers."""

    #: The number of poses.
    poses: int
    #: The number in words, for messages (``"three"``).
    word: str
    #: Filemon's construction for a driven dyad ``C0``: the branch and
    #: solution maps of the driving pivot's plane, the pole triangle and
    #: circle, the explorer, the atlas, the design search on Dask.
    filemon: bool
    #: The center- and circle-point curves: dyads along them, the pair map.
    curves: bool
    #: Finitely many dyads: the Burmester points, every four-bar of two.
    burmester_points: bool

    @property
    def driven(self) -> bool:
        """Whether a task file may give a driven dyad (``[driven]``): on the
        plane (three poses) or on the center-point curve (four)."""
        return self.filemon or self.curves

    @property
    def circle_plane(self) -> bool:
        """Whether the circle-point plane can be drawn (``--plane circle``)."""
        return self.filemon or self.curves

    @property
    def design_progress(self) -> bool:
        """Whether :func:`burmester.design` reports progress (a search over
        a map; the Burmester four-bars of five poses are listed at once)."""
        return not self.burmester_points


#: Every pose count a task may have, by its number of poses.
COUNTS: Dict[int, PoseCount] = {
    3: PoseCount(3, "three", filemon=True, curves=False, burmester_points=False),
    4: PoseCount(4, "four", filemon=False, curves=True, burmester_points=False),
    5: PoseCount(5, "five", filemon=False, curves=False, burmester_points=True),
}


def of(poses: Sized) -> PoseCount:
    """What a task of ``len(poses)`` poses offers (a :class:`burmester.Task`,
    or its poses). Raises :class:`burmester.InvalidInputError` for a count
    no task has."""
    n = len(poses)
    try:
        return COUNTS[n]
    except KeyError:
        raise InvalidInputError(f"a task has three to five poses, got {n}") from None
