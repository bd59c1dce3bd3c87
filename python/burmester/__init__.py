"""burmester: planar four-bar linkages for mechanism designers.

Position analysis, Burmester synthesis of three to five poses, and the exact
elimination of the branch problem in the driving crank's center-point plane.
The heavy lifting is in Rust (``burmester._burmester``); this package
re-exports it and adds pure-Python parsing, formatting and drawing.

Angles are in radians, counter-clockwise, measured from the fixed +x axis,
except where a name says ``_deg``.
"""

from burmester._burmester import (
    AssemblyError,
    BurmesterError,
    Configuration,
    CoincidencePoint,
    Conic,
    Cubic,
    CurveDyad,
    DegenerateError,
    Design,
    DesignLimits,
    DesignReport,
    Drive,
    DriveError,
    DriveMap,
    Filemon,
    FourBar,
    Grid,
    InvalidInputError,
    LinkageFigures,
    NearMiss,
    Pair,
    PairMap,
    Pivot,
    Pole,
    SixBar,
    SliderFilemon,
    SliderConfiguration,
    SliderCrank,
    SolutionMap,
    Space,
    SynthesizedFourBar,
    SynthesizedSliderCrank,
    Task,
    __version__,
    clip_line,
    slider_branch_free_arcs,
    slider_curve_branch,
    unit_time_ratio_crank_rocker,
)
from burmester.atlas import AtlasPair, PivotAtlas, pivot_atlas
from burmester.batch import best_pivots_batch
from burmester.design import design
from burmester._burmester import Actuator, ActuatorMap
from burmester.actuators import design_actuator
from burmester._burmester import InvertedSlider, SliderDyad
from burmester._burmester import InvertedConfiguration, InvertedSliderCrank, SynthesizedInvertedSliderCrank
from burmester._burmester import SliderPivot

__all__ = [
    "AtlasPair",
    "PivotAtlas",
    "AssemblyError",
    "BurmesterError",
    "Configuration",
    "CoincidencePoint",
    "Conic",
    "Cubic",
    "CurveDyad",
    "DegenerateError",
    "DesignLimits",
    "Drive",
    "DriveError",
    "DriveMap",
    "Filemon",
    "FourBar",
    "Grid",
    "InvalidInputError",
    "LinkageFigures",
    "Pair",
    "PairMap",
    "Pivot",
    "Pole",
    "SixBar",
    "SliderFilemon",
    "SolutionMap",
    "SynthesizedFourBar",
    "Task",
    "__version__",
    "best_pivots_batch",
    "clip_line",
    "design",
    "Design",
    "DesignReport",
    "NearMiss",
    "Space",
    "pivot_atlas",
    "slider_branch_free_arcs",
    "slider_curve_branch",
    "unit_time_ratio_crank_rocker",
    "Actuator",
    "ActuatorMap",
    "design_actuator",
    "SliderConfiguration",
    "SliderCrank",
    "SynthesizedSliderCrank",
    "InvertedSlider",
    "SliderDyad",
    "InvertedConfiguration",
    "InvertedSliderCrank",
    "SynthesizedInvertedSliderCrank",
    "SliderPivot",
]
