"""burmester: planar four-bar linkages for mechanism designers.

Position analysis, Burmester synthesis of three to five poses, and the exact
elimination of the branch problem in the driving crank's center-point plane.
The heavy lifting is in Rust (``burmester._burmester``); this package
re-exports it and adds pure-Python parsing, formatting and drawing.

Angles are in radians, counter-clockwise, measured from the fixed +x axis,
except where a name says ``_deg``.
"""

from burmester import _burmester
from burmester._burmester import *  # noqa: F403 (the native module's names: its __all__)
from burmester.atlas import AtlasPair, PivotAtlas, pivot_atlas
from burmester.batch import best_pivots_batch
from burmester.design import design
from burmester.actuators import design_actuator

# The package's names: the pure-Python ones and the native module's public
# ones (its __all__, which the stub lists and stubtest checks, less its
# private functions).
__all__ = [
    "AtlasPair",
    "PivotAtlas",
    "best_pivots_batch",
    "design",
    "design_actuator",
    "pivot_atlas",
]
__all__ += _burmester.__all__
__all__.remove("_atlas_tile")
__all__.remove("_design")
__all__.remove("_design_plan")
__all__.remove("_design_from_atlas")
