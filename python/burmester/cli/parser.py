"""The argument parser of the ``burmester`` command."""

from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING, Callable, NoReturn, Optional, Sequence

import burmester
from burmester import pivots as pv
from burmester.cli.base import PAIR_SAMPLES
from burmester.cli.commands import (
    ATLAS_DRIVEN_GRID,
    ATLAS_DRIVING_GRID,
    cmd_atlas,
    cmd_batch,
    cmd_design,
    cmd_drive,
    cmd_actuator,
    cmd_example,
    cmd_linkage,
    cmd_map,
    cmd_pairs,
    cmd_pivots,
    cmd_solve,
)
from burmester.cli.inverted import DEFAULT_GRID as INVERTED_GRID
from burmester.cli.inverted import DEFAULT_SAMPLES as INVERTED_SAMPLES
from burmester.cli.inverted import MAX_CANDIDATES as INVERTED_MOST
from burmester.cli.inverted import cmd_inverted


class _Parser(argparse.ArgumentParser):
    """An ArgumentParser whose errors are one line (and exit status 2)."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


# ---------------------------------------------------------------------------
# Argument types


def _count(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number, got {text!r}") from None
    if n < 0:
        raise argparse.ArgumentTypeError(f"expected a whole number of at least 0, got {n}")
    return n


def _ranged(lo: int, hi: int) -> Callable[[str], int]:
    """An argparse type: a whole number from ``lo`` to ``hi``."""

    def parse(text: str) -> int:
        n = _count(text)
        if not lo <= n <= hi:
            raise argparse.ArgumentTypeError(f"expected a whole number from {lo} to {hi}, got {n}")
        return n

    return parse


#: The usual ``--units`` (:data:`burmester.export.UNITS`, kept here so
#: that ``burmester --help`` does not import the export module); any other
#: unit name is accepted too.
UNIT_CHOICES = ("mm", "cm", "m", "in", "ft", "unitless")
#: The help of ``--units``.
UNITS_HELP = ("the unit of the task's lengths, any name (" + ", ".join(UNIT_CHOICES[:-1]) + ", ...), in place of "
              "the task file's units = \"...\": said after the lengths printed, on the picture's axes and in a "
              ".dxf or .svg (default: the task file's; none: bare numbers, and a CAD export records mm)")

#: The range of ``--dpi`` (matplotlib cannot draw much past 2^16 pixels a side).
MIN_DPI, MAX_DPI = 10, 2400
_dpi = _ranged(MIN_DPI, MAX_DPI)


def _positive_int(text: str) -> int:
    n = _count(text)
    if n < 1:
        raise argparse.ArgumentTypeError(f"expected a whole number of at least 1, got {n}")
    return n


def _finite(text: str) -> float:
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not math.isfinite(x):
        raise argparse.ArgumentTypeError(f"expected a finite number, got {text!r}")
    return x


#: The rankings ``burmester design`` offers (those with a score).
DESIGN_RANKINGS = ("balanced", "transmission", "compact")

#: The help of a command's optional task file.
TASK_HELP = "task file (TOML; see 'burmester example'); default: the built-in example"

if TYPE_CHECKING:
    #: What ``add_subparsers`` returns: a command is added to it.
    _Commands = argparse._SubParsersAction[_Parser]


def _task_arg(p: argparse.ArgumentParser) -> None:
    """The optional task file (the built-in example without one)."""
    p.add_argument("task", nargs="?", metavar="TASK.toml", help=TASK_HELP)


def _units_arg(p: argparse.ArgumentParser) -> None:
    p.add_argument("--units", default=None, metavar="NAME", help=UNITS_HELP)


def _force_arg(p: argparse.ArgumentParser) -> None:
    p.add_argument("--force", action="store_true", help="replace the output file if it exists")


def _command(sub: _Commands, name: str, func: Callable[[argparse.Namespace], int], help: str,
             description: str) -> argparse.ArgumentParser:
    """The parser of the command ``name`` (``help`` in the list of commands,
    ``description`` in its own help), run by ``func``."""
    p = sub.add_parser(name, help=help, description=description)
    p.set_defaults(func=func)
    return p


def _output_arg(p: argparse.ArgumentParser, text: str, default: Optional[str] = None) -> None:
    """``-o``/``--output``: the file a command writes (``default`` when not given)."""
    p.add_argument("-o", "--output", default=default, help=text)


def _xy_arg(p: argparse.ArgumentParser, flag: str, text: str) -> None:
    """A point given as ``flag X Y`` (two finite numbers), ``None`` when not given."""
    p.add_argument(flag, nargs=2, type=_finite, metavar=("X", "Y"), help=text)


def _drawing_args(p: argparse.ArgumentParser, travel_range: str) -> None:
    """``--frames``, ``--fps``, ``--travel``, ``--units`` and ``--dpi`` of a
    command that draws, animates or exports a linkage (``travel_range``:
    said after ``--travel``'s help)."""
    p.add_argument("--frames", type=_ranged(2, 10_000), default=None,
                   help="animation frames from the first pose to the last, 2 to 10000 (default: 60)")
    p.add_argument("--fps", type=_ranged(1, 240), default=None,
                   help="animation frames per second, 1 to 240 (default: 20)")
    p.add_argument("--travel", type=_ranged(2, 10_000), default=None, metavar="N",
                   help=f"CAD export: also draw the linkage at N positions over its travel{travel_range}")
    _units_arg(p)
    p.add_argument("--dpi", type=_dpi, default=None,
                   help=f"resolution of a picture, {MIN_DPI} to {MAX_DPI} (default: 100)")


def _animation_args(p: argparse.ArgumentParser, frames: str, fps: int) -> None:
    """``--frames`` (animation frames ``frames``), ``--fps`` (``fps`` when
    not given), ``--units``, ``--dpi`` and ``--force`` of a command that
    draws, animates or exports the linkage it designs a drive for."""
    p.add_argument("--frames", type=_ranged(2, 10_000), default=None, help=f"animation: frames {frames}")
    p.add_argument("--fps", type=_ranged(1, 240), default=None, help=f"animation: frames per second (default {fps})")
    _units_arg(p)
    p.add_argument("--dpi", type=_dpi, default=None, help=f"picture resolution, {MIN_DPI} to {MAX_DPI}")
    _force_arg(p)


def _json_arg(p: argparse.ArgumentParser, text: str = "print JSON instead of a table") -> None:
    p.add_argument("--json", action="store_true", help=text)


def _top_arg(p: argparse.ArgumentParser, what: str, kind: Callable[[str], int] = _positive_int) -> None:
    """``--top``: how many ``what`` (5 when not given)."""
    p.add_argument("--top", type=kind, default=5, help=f"how many {what} (default: 5)")


def _rank_by_arg(p: argparse.ArgumentParser, choices: Sequence[str], text: str) -> None:
    p.add_argument("--rank-by", choices=choices, default="balanced", help=text)


def _scheduler_arg(p: argparse.ArgumentParser, what: str) -> None:
    """``--scheduler``: ``what`` on a Dask cluster."""
    p.add_argument("--scheduler", metavar="ADDRESS", default=None,
                   help=f"{what} on a Dask cluster (tcp://host:8786); needs burmester[dask]")


def _grid_arg(p: argparse.ArgumentParser, text: str) -> None:
    p.add_argument("--grid", nargs=2, type=_positive_int, metavar=("NX", "NY"), help=text)


def _picture_args(p: argparse.ArgumentParser, dpi_help: str, dpi_default_help: str,
                  default: Optional[int] = None) -> None:
    """``--dpi`` (its help: ``dpi_help``, the range, ``dpi_default_help``),
    ``--units`` and ``--force`` of a command that writes a picture."""
    p.add_argument("--dpi", type=_dpi, default=default, help=f"{dpi_help}{MIN_DPI} to {MAX_DPI}{dpi_default_help}")
    _units_arg(p)
    _force_arg(p)


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``burmester`` command."""
    parser = _Parser(
        prog="burmester",
        description=(
            "Four-bar linkages for three given coupler poses, free of the branch problem "
            "(Borm & Kim). Lengths in any one unit; angles on the command line and in task "
            "files are in degrees."
        ),
        epilog=(
            "examples:\n"
            "  burmester design -o best.png        the best linkage for the built-in example's poses\n"
            "  burmester map -o map.png            center-point plane of the built-in example\n"
            "  burmester example > task.toml       a task file to edit\n"
            "  burmester map task.toml -o map.png  center-point plane of your task\n"
            "  burmester pivots task.toml --top 5  the best acceptable driving pivots\n"
            "  burmester linkage task.toml -o linkage.gif\n"
            "  burmester pairs four.toml -o pairs.png  four poses: the best pairs of dyads and the pair map\n"
            "  burmester map task.toml -o plane.dxf   CAD export (.dxf, .svg), a layer per concept\n"
            "  burmester solve --ground 100 --crank 40 --coupler 120 --rocker 80 --theta2 40\n"
            "Without arguments, burmester prints this help."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action="version", version=f"burmester {burmester.__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for add in (_add_map, _add_design, _add_pivots, _add_pairs, _add_linkage, _add_atlas, _add_batch, _add_solve,
                _add_example, _add_drive, _add_actuator, _add_inverted):
        add(sub)
    return parser


def _add_map(sub: _Commands) -> None:
    p = _command(sub, "map", cmd_map, help="draw the driving crank's center-point plane (or circle-point plane)",
                 description="""
        Draw the driving crank's center-point plane as in Borm & Kim's Fig. 10 and 12: branch-free
        pivots shaded, the transformed Filemon curves, the poles, the pole triangle and circle, the
        driven crank's fixed pivot. A task of four poses draws its center-point curve coloured by the
        crank's order, with the poles and the points Q_jk; five poses, the Burmester points on their two
        center-point curves.
    """)
    _task_arg(p)
    _output_arg(p, "picture to write (.png, .pdf, ...; matplotlib), or CAD export (.dxf, .svg: a layer "
                "or group per concept, exact coordinates); default: map.png",
                default="map.png")
    p.add_argument("--plane", choices=("center", "circle"), default="center",
                   help="center: center-point plane (Fig. 10/12); circle: circle-point plane (Fig. 3/11; "
                   "four poses: the circle-point curve by crank order)")
    p.add_argument("--method", choices=("conic", "direct", "simulate"), default="conic",
                   help="how grid points are classified (default: conic)")
    _grid_arg(p, "grid samples along x and y (default: the task file's, or 400)")
    p.add_argument("--pivots", type=_count, default=0, metavar="N",
                   help="also mark the N best driving pivots (ranked as by 'burmester pivots')")
    p.add_argument("--design", action="store_true",
                   help="overlay the solution-space map: pivots acceptable under the task's limits "
                   "shaded darker, contours of the minimum transmission angle over the travel")
    p.add_argument("--driven-slider", type=float, nargs=2, metavar=("X", "Y"), default=None,
                   help="three poses: make the driven dyad a slider whose pin is at (X, Y) at pose 1 (a "
                   "point of the task's slider circle; its guide is the line through the pin's positions), "
                   "in place of the task file's [driven] (which may name one: slider = [x, y]). Draws the "
                   "slider solution map (every crank pivot A0 a slider-crank: branch-free and acceptable "
                   "pivots, transmission contours, the guide) and prints the best slider-cranks (--pivots N, "
                   "default 5)")
    _picture_args(p, "resolution of a picture, dots per inch, ", " (default: 100)")


def _add_design(sub: _Commands) -> None:
    p = _command(sub, "design", cmd_design, help="from poses (and a space) to the best linkage: both pivots searched",
                 description="""
        Search the best linkages for the task's poses: three poses search both fixed pivots (a coarse
        pass, then each candidate refined continuously on its exact figures), four poses both curve
        parameters, five poses every pair of Burmester points. Every design is branch-free, passes the
        poses in order on one circuit, meets the task file's [limits] (printed) and fits its [space]. A
        task file needs no [driven] table for this. When nothing fits, it says which limit rejected the
        most candidates and lists the nearest misses.
    """)
    _task_arg(p)
    _top_arg(p, "designs, 1 to 100", _ranged(1, 100))
    _rank_by_arg(p, DESIGN_RANKINGS,
                 "balanced (default): sin(mu min) / sqrt(size x link ratio); transmission: the minimum "
                 "transmission angle; compact: the smallest linkage relative to the task")
    _json_arg(p)
    _output_arg(p, "also draw the best design: a picture (.png, .pdf, ...), an animation (.gif, .mp4) or "
                "a CAD export (.dxf, .svg)")
    _drawing_args(p, "")
    _scheduler_arg(p, "run the three-pose coarse pass")
    p.add_argument("--motor", action="store_true",
                   help="every design turned by a motor: one whose input swings gets the best added crank-rocker "
                   "(the six-bar; the limits and the space apply to it too; -o then draws, animates over a "
                   "crank turn (--frames per turn, default 120) or exports the six-bar, --travel N giving N "
                   "crank angles of a CAD export); one "
                   "without an acceptable drive is passed over")
    p.add_argument("--margin", type=_finite, default=None, metavar="DEG",
                   help="with --motor: swing the input this much beyond the first and last pose (default: 0)")
    p.add_argument("--max-time-ratio", type=_finite, default=None, metavar="R",
                   help="with --motor: largest acceptable time ratio of the strokes (default: no limit)")
    p.add_argument("--input", choices=("motor", "actuator"), default=None, dest="design_input",
                   help="motor: as --motor; actuator: every design driven by a linear actuator (a cylinder, "
                   "a gas strut) placed with it: its ground pivot on the [space] pivot region, its length "
                   "monotone through the poses, within --max-stroke-ratio and the limits, its line clear of "
                   "the links, obstacles and envelope over the travel (-o then draws the best design with "
                   "its actuator); one without such a placement is passed over. The task file's [actuator] "
                   "table gives its link, point, max_stroke_ratio, max_size_ratio, width and min_gap (each "
                   "flag below overrides its key; the table's other keys are burmester actuator's)")
    p.add_argument("--actuator-link", choices=("coupler", "crank", "rocker"), default=None,
                   help="with --input actuator: the link it acts on (default: [actuator] link, else coupler)")
    p.add_argument("--actuator-point", type=_finite, nargs=2, default=None, metavar=("X", "Y"),
                   help="with --input actuator: its moving point where it is at pose 1, the same point for "
                   "every design (default: [actuator] point, else a few points of the link are tried)")
    p.add_argument("--try-actuator-points", action="store_true",
                   help="with --input actuator: try a few points of the link on each design (the moving pivots, "
                   "points between them, the coupler point), not [actuator] point")
    p.add_argument("--max-stroke-ratio", type=_finite, default=None, metavar="R",
                   help="with --input actuator: largest open over closed length (default: [actuator] "
                   "max_stroke_ratio, else 1.8)")
    p.add_argument("--actuator-max-size-ratio", type=_finite, default=None, metavar="R",
                   help="with --input actuator: largest size of the linkage with the open actuator over the "
                   "task's span, at least 1 (default: [actuator] max_size_ratio, else [limits] "
                   "max_size_ratio, which the linkage alone meets)")
    _strut_gap_args(p, "with --input actuator: ", "else 0: its center line", dest=None)
    p.add_argument("--driven", choices=("revolute", "slider"), default=None,
                   help="the driven dyad: revolute (a crank: four-bars) or slider (a pin on a straight guide "
                   "fixed to the ground: slider-cranks, the guide and the stroke in the table); default: the "
                   "task file's [design] driven, else revolute. A slider takes no motor or actuator; "
                   "the space's obstacles and envelope are checked over its travel")
    _force_arg(p)


def _add_pivots(sub: _Commands) -> None:
    p = _command(sub, "pivots", cmd_pivots, help="rank the acceptable driving pivots",
                 description="""
        Rank the driving pivots A0 that are branch-free, pass the poses in order on one circuit and meet
        the task's limits (the solution-space map) by --rank-by, and show each one's four-bar and its
        size relative to the task. When none is acceptable, list branch-free pivots by their distance to
        the branch-defect boundary, with the limits they miss.
    """)
    _task_arg(p)
    _top_arg(p, "pivots")
    p.add_argument("--spacing", type=_finite, default=None,
                   help="least distance between listed pivots, whichever the ranking "
                   "(default: a tenth of the view's shorter side)")
    _grid_arg(p, "grid samples along x and y (default: the task file's, or 400)")
    _rank_by_arg(p, pv.RANKINGS,
                 "balanced (default): sin(mu min) / sqrt(size x link ratio); transmission: the "
                 "minimum transmission angle; compact: the smallest linkage relative to the task; "
                 "pareto: the front of transmission and size, compact to transmitting")
    _json_arg(p)
    _units_arg(p)


def _add_pairs(sub: _Commands) -> None:
    p = _command(sub, "pairs", cmd_pairs, help="four poses: rank the pairs of dyads (the pair map)",
                 description="""
        For a task of four poses, the pair map: every pair of a driving and a driven dyad sampled along
        the center-point curve, with the solution map's figures; list the best acceptable pairs by
        --rank-by and draw the map with -o.
    """)
    p.add_argument("task", metavar="TASK.toml", help="task file of four poses (TOML)")
    p.add_argument("--samples", type=_positive_int, default=PAIR_SAMPLES, metavar="N",
                   help=f"dyads sampled along the curve for each pivot, 2 to 20000 (default: {PAIR_SAMPLES})")
    _top_arg(p, "pairs")
    _rank_by_arg(p, pv.RANKINGS,
                 "the ranking, as for 'burmester pivots' (default: balanced)")
    _json_arg(p)
    _output_arg(p, "also draw the pair map as a picture (.png, .pdf, ...; matplotlib)")
    _picture_args(p, "resolution of the picture, ", " (default: 100)")


def _add_linkage(sub: _Commands) -> None:
    p = _command(sub, "linkage", cmd_linkage, help="draw or animate the four-bar of a driving pivot",
                 description="""
        Draw the four-bar at the three poses (.png, .pdf, ...), animate it driven through them (.gif, or
        .mp4 with ffmpeg), or export it to CAD (.dxf, .svg: a layer or group per concept, exact
        coordinates).
    """)
    _task_arg(p)
    _xy_arg(p, "--pivot", "the driving crank's fixed pivot A0 (default: the best, as by 'burmester pivots')")
    _output_arg(p, "file to write: a picture (.png, .pdf, ...), an animation (.gif, .mp4) or a CAD "
                "export (.dxf, .svg); default: linkage.png",
                default="linkage.png")
    _drawing_args(p, ", 2 to 10000")
    _force_arg(p)


def _add_atlas(sub: _Commands) -> None:
    p = _command(sub, "atlas", cmd_atlas, help="both pivots at once: the best driving pivot of every driven center",
                 description="""
        For every driven center on a grid over the view, the solution map over driving centers reduced:
        shaded by the best achievable transmission angle, the count of acceptable driving pivots as
        contours, the best pair drawn.
    """)
    _task_arg(p)
    _output_arg(p, "picture to write (.png, .svg, .pdf; matplotlib, "
                "an image of the atlas, not a CAD export); default: atlas.png (none with --json unless given)")
    _json_arg(p, "print the best pairs as JSON")
    _top_arg(p, "pairs in the JSON")
    _scheduler_arg(p, "run")
    p.add_argument("--driven-grid", nargs=2, type=_positive_int, metavar=("NX", "NY"),
                   help=f"driven centers over the view (default: {ATLAS_DRIVEN_GRID[0]} {ATLAS_DRIVEN_GRID[1]})")
    p.add_argument("--driving-grid", nargs=2, type=_positive_int, metavar=("NX", "NY"),
                   help=f"driving centers over the view (default: {ATLAS_DRIVING_GRID[0]} {ATLAS_DRIVING_GRID[1]})")
    _rank_by_arg(p, DESIGN_RANKINGS,
                 "how each driven center's best driving pivot is chosen: balanced (default), "
                 "transmission or compact, as for 'burmester pivots'")
    _picture_args(p, "resolution, ", " (default: 100)", default=100)


def _add_batch(sub: _Commands) -> None:
    p = _command(sub, "batch", cmd_batch, help="the best driving pivots of many task files, one JSON line each",
                 description="""
        Rank the driving pivots of each task file as 'burmester pivots --json' does, printing one JSON
        line per file (JSON lines), in order. A file that fails gives a line with an "error" field; the
        others still run, and the exit status is 2 at the end. With --scheduler, one Dask task per file.
    """)
    p.add_argument("tasks", nargs="+", metavar="TASK.toml", help="task files (TOML; see 'burmester example')")
    _top_arg(p, "pivots per task")
    p.add_argument("--spacing", type=_finite, default=None,
                   help="least distance between listed pivots (default: a tenth of each view's shorter side)")
    _rank_by_arg(p, pv.RANKINGS,
                 "the ranking, as for 'burmester pivots' (default: balanced)")
    _scheduler_arg(p, "run")


def _add_solve(sub: _Commands) -> None:
    p = _command(sub, "solve", cmd_solve, help="position analysis of a four-bar (angles in degrees)",
                 description="""
        Solve a four-bar's position: the coupler and rocker angles for an input angle, in both assembly
        modes. Without --theta2, a table over a full turn. Without lengths, Norton's Example 4-1 (100,
        40, 120, 80).
    """)
    p.add_argument("--ground", type=_finite, help="ground link length L1 (input pivot to output pivot)")
    p.add_argument("--crank", type=_finite, help="crank (input) length L2")
    p.add_argument("--coupler", type=_finite, help="coupler length L3")
    p.add_argument("--rocker", type=_finite, help="rocker (output) length L4")
    p.add_argument("--theta2", type=_finite, metavar="DEG",
                   help="input (crank) angle in DEGREES, counter-clockwise from the ground link")
    p.add_argument("--mode", choices=("open", "crossed"),
                   help="assembly mode (default: both); open: sin(theta4 - theta3) > 0")
    p.add_argument("--step", type=_finite, default=None, metavar="DEG",
                   help="input angle step of the full-turn table, degrees (default: 30)")


def _add_example(sub: _Commands) -> None:
    p = _command(sub, "example", cmd_example, help="print the built-in example as a task file",
                 description="Print the built-in example task as a TOML task file, to edit.")
    _output_arg(p, "write to this .toml file instead of stdout")
    _force_arg(p)


def _add_drive(sub: _Commands) -> None:
    p = _command(sub, "drive", cmd_drive, help="a motor for a linkage whose input swings: an added dyad (six-bar)",
                 description="Find the best motor drive for the task's linkage: a crank-rocker "
                             "added to its input link (the Watt II six-bar), so a motor turning "
                             "a crank drives it through the poses.")
    _task_arg(p)
    _output_arg(p, "also write the six-bar: a picture (.png, .pdf, ...), an animation over a "
                "crank turn (.gif, .mp4) or a CAD export (.dxf, .svg); with --map, the drive map")
    _json_arg(p)
    _xy_arg(p, "--pivot", "three poses: the linkage's driving pivot A0 (default: the best by --rank-by)")
    _rank_by_arg(p, pv.RANKINGS,
                 "which linkage of the task to drive (default: balanced)")
    p.add_argument("--drive-rank-by", choices=("balanced", "transmission", "compact"), default="balanced",
                   help="which drive to pick (default: balanced)")
    p.add_argument("--margin", type=_finite, default=0.0, metavar="DEG",
                   help="swing the input this much beyond the first and last pose (default: 0, the "
                        "strokes end at the poses)")
    p.add_argument("--max-time-ratio", type=_finite, default=math.inf, metavar="Q",
                   help="largest acceptable time ratio of the strokes (default: no limit)")
    _grid_arg(p, "samples of the view when choosing the linkage")
    p.add_argument("--map", action="store_true", help="-o draws the drive map of the best drive's attachment")
    p.add_argument("--turn", type=_ranged(2, 10_000), default=None, metavar="N",
                   help="CAD export: also draw the six-bar at N crank angles over a turn")
    _animation_args(p, "per crank turn (default 120)", 24)


def _strut_gap_args(p: argparse.ArgumentParser, when: str, default: str, dest: Optional[str]) -> None:
    """``--actuator-width`` (also ``--width`` where ``dest`` is ``"width"``,
    as ``burmester actuator`` has always had it) and ``--min-gap``."""
    names = ("--actuator-width",) if dest is None else ("--actuator-width", "--width")
    p.add_argument(*names, type=_finite, default=None, metavar="W", dest=dest or "actuator_width",
                   help=f"{when}the strut's diameter (its body's), task units: its capsule in the clearance to "
                   f"the links ([space] link_width wide), the obstacles and the envelope, and the cylinder "
                   f"drawn (default: [actuator] width, {default})")
    p.add_argument("--min-gap", type=_finite, default=None, metavar="G",
                   help=f"{when}the least gap the strut keeps over the travel, task units (default: "
                   f"[actuator] min_gap, else 0)")


def _add_actuator(sub: _Commands) -> None:
    p = _command(sub, "actuator", cmd_actuator,
                 help="a linear actuator (cylinder, gas strut) to drive the task's linkage",
                 description="Place a linear actuator between a ground pivot and a point of a moving "
                             "link of the task's best design (the one-call design): the placement map "
                             "over ground pivots (monotone stroke, stroke ratio, force transmission "
                             "angle, size) and the best placement. The task file's [actuator] table "
                             "gives the defaults (also where the ground pivot is searched, x, y, and "
                             "base_plate); these flags override it.")
    _task_arg(p)
    _output_arg(p, "also draw the placement map and the chosen design (.png, .pdf, ...), export the "
                "design with its cylinder (.dxf, .svg) or animate it (.gif, .mp4)")
    _json_arg(p)
    p.add_argument("--link", choices=("coupler", "crank", "rocker"), default=None,
                   help="the link the actuator acts on (default: [actuator] link, else coupler)")
    _xy_arg(p, "--point", "the actuator's moving point where it is at pose 1 (default: [actuator] point, else "
            "the middle of the coupler's A C, the crank's A or the rocker's C)")
    p.add_argument("--max-stroke-ratio", type=_finite, default=None, metavar="R",
                   help="largest acceptable open over closed length (default: [actuator] max_stroke_ratio, "
                        "else 1.8; a cylinder's is below 2)")
    p.add_argument("--max-size-ratio", type=_finite, default=None, metavar="R",
                   help="largest size of the linkage with the open actuator over the task's span "
                        "(default: [actuator] max_size_ratio, else the task's limits')")
    p.add_argument("--actuator-rank-by", choices=("balanced", "transmission", "compact", "margin"),
                   default=None, help="which placement to pick (default: [actuator] rank_by, else balanced)")
    p.add_argument("--map-grid", nargs=2, type=_ranged(2, 1024), default=None, metavar=("NX", "NY"),
                   help="ground pivots sampled over the map's view (default: [actuator] grid, else 200 200)")
    _strut_gap_args(p, "", "else a line in the clearance, 0.06 of its closed length as drawn and exported",
                    dest="width")
    _animation_args(p, "from the first pose to the last (default 60)", 20)


def _add_inverted(sub: _Commands) -> None:
    p = _command(sub, "inverted", cmd_inverted,
                 help="inverted slider-cranks for the poses (a crank, a slotted coupler, a block on a ground swivel)",
                 description=f"""
        Find the task's inverted slider-cranks: a crank whose coupler carries a straight slot that slides
        through a block pivoted on the ground at the swivel S (a slotted lever, an oscillating cylinder).
        Every driving crank of the task (three poses: crank pivots A0 on a grid over the [space] search
        box, else the [view]; four poses: the center-point curve; five: the Burmester points) is combined
        with every inverted slider (three poses: swivels sampled on the pole circle; four and five: the
        task's few), each built exactly; those the crank drives through the poses in order in one mode,
        with both pivots in the [space] and within the [limits] (transmission angle, crank over ground
        as the link ratio, size), are ranked by sin(mu min) / sqrt(size ratio) and printed. -o draws the
        best at its poses (.png, .pdf, ...), animates it through them (.gif, .mp4) or exports it to CAD
        (.dxf, .svg: the slot, the block on the swivel, the links, dimensioned). No task-file table:
        --pivot and --swivel fix either fixed pivot. The [space]'s obstacles and envelope are not
        checked over the travel (only where the pivots go): look at the picture, where the coupler
        point's path over the travel is drawn.
    """)
    _task_arg(p)
    _xy_arg(p, "--pivot", "the driving crank's fixed pivot A0 (default: searched)")
    _xy_arg(p, "--swivel", "the block's ground pivot S, a point of the task's inverted sliders (three poses: on the "
            "pole circle; default: searched)")
    p.add_argument("--samples", type=_ranged(1, 10_000), default=INVERTED_SAMPLES,
                   help=f"three poses: swivels sampled along the pole circle, 1 to 10000 (default: {INVERTED_SAMPLES})")
    p.add_argument("--pivot-grid", type=_ranged(2, 200), default=INVERTED_GRID, metavar="N",
                   help=f"three poses: crank pivots on an N x N grid; four poses: about N*N/4 dyads along the "
                   f"curve; 2 to 200 (default: {INVERTED_GRID}); at most {INVERTED_MOST} candidates (cranks "
                   "times swivels) are built")
    _top_arg(p, "inverted slider-cranks, 1 to 100", _ranged(1, 100))
    _json_arg(p)
    _output_arg(p, "also draw the best: a picture (.png, .pdf, ...), an animation through the poses (.gif, "
                ".mp4) or a CAD export (.dxf, .svg)")
    _drawing_args(p, ", 2 to 10000")
    _force_arg(p)
