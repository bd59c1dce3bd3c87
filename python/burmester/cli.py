"""The ``burmester`` command line."""

from __future__ import annotations

import argparse
import math
import sys
from typing import Sequence

import burmester

#: The built-in example four-bar: Norton, *Design of Machinery*, Example 4-1 (mm).
EXAMPLE_FOURBAR = (100.0, 40.0, 120.0, 80.0)


def position_table(fourbar: burmester.FourBar, step_deg: float = 30.0) -> str:
    """A text table of both assembly modes over a full turn of the input."""
    lines = [
        f"{fourbar!r}: {fourbar.grashof()}",
        f"{'theta2':>8} | {'open theta3':>11} {'theta4':>8} {'mu':>6} | "
        f"{'crossed theta3':>14} {'theta4':>8} {'mu':>6}",
    ]
    n = max(1, round(360.0 / step_deg))
    for k in range(n):
        t2 = k * 360.0 / n
        row = f"{t2:8.1f} |"
        for mode in ("open", "crossed"):
            try:
                c = fourbar.configuration(math.radians(t2), mode)
            except burmester.AssemblyError:
                cell = f"{'(does not close)':>27}"
            else:
                cell = (
                    f"{math.degrees(c.theta3):{11 if mode == 'open' else 14}.3f} "
                    f"{math.degrees(c.theta4):8.3f} {math.degrees(c.transmission_angle):6.1f}"
                )
            row += f" {cell} |"
        lines.append(row.rstrip(" |"))
    lines.append("angles in degrees; mu is the transmission angle")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``python -m burmester`` and the ``burmester`` script."""
    parser = argparse.ArgumentParser(
        prog="burmester",
        description="Four-bar linkage analysis and branch-free three-position synthesis.",
    )
    parser.add_argument(
        "--step", type=float, default=30.0, help="input angle step of the table, degrees"
    )
    args = parser.parse_args(argv)
    try:
        fb = burmester.FourBar(*EXAMPLE_FOURBAR)
        print(position_table(fb, args.step))
    except burmester.BurmesterError as e:
        print(f"burmester: error: {e}", file=sys.stderr)
        return 2
    return 0
