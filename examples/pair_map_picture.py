"""Writes docs/pair-map.png, the README's picture of the four-pose pair map:
``python examples/pair_map_picture.py`` (needs the ``plot`` extra)."""

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import burmester  # noqa: E402
from burmester import plot  # noqa: E402

# The known crank-rocker of the README and of the four- and five-position notes.
FB = burmester.FourBar.from_pivots((0, 0), (4, 0), 1.5, 3.5, 3.0)


def pose(deg: float) -> tuple:
    """The coupler pose at a crank angle: the point (1, 1.5) in the frame at
    the crank joint A, x toward the rocker joint B."""
    _, a, b, _ = FB.joints(math.radians(deg))
    phi = math.atan2(b[1] - a[1], b[0] - a[0])
    return (a[0] + math.cos(phi) - 1.5 * math.sin(phi), a[1] + math.sin(phi) + 1.5 * math.cos(phi), phi)


def main() -> None:
    out = Path(__file__).resolve().parents[1] / "docs" / "pair-map.png"
    four = burmester.Task([pose(d) for d in (20, 70, 120, 170)])
    ax = plot.pair_map(four.pair_map(400), pairs=5)
    ax.figure.savefig(out, dpi=72, bbox_inches="tight")
    print(f"wrote {out} ({out.stat().st_size // 1024} KiB)")


if __name__ == "__main__":
    main()
