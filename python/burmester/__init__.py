"""burmester: planar four-bar linkages for mechanism designers.

Position analysis, three-position Burmester synthesis, and the exact
elimination of the branch problem in the driving crank's center-point plane.
The heavy lifting is in Rust (``burmester._burmester``); this package
re-exports it and adds pure-Python conveniences.

Angles are in radians, counter-clockwise, measured from the fixed +x axis.
"""

from burmester._burmester import (
    AssemblyError,
    BurmesterError,
    Configuration,
    Conic,
    DegenerateError,
    Filemon,
    FourBar,
    InvalidInputError,
    SolutionMap,
    SynthesizedFourBar,
    Task,
    __version__,
)

__all__ = [
    "AssemblyError",
    "BurmesterError",
    "Configuration",
    "Conic",
    "DegenerateError",
    "Filemon",
    "FourBar",
    "InvalidInputError",
    "SolutionMap",
    "SynthesizedFourBar",
    "Task",
    "__version__",
]
