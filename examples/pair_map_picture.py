"""Writes docs/pair-map.png, the README's picture of the four-pose pair map:
``python examples/pair_map_picture.py`` (needs the ``plot`` extra)."""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from burmester import plot  # noqa: E402
from notes_linkage import task  # noqa: E402


def main() -> None:
    out = Path(__file__).resolve().parents[1] / "docs" / "pair-map.png"
    four = task(20, 70, 120, 170)
    ax = plot.pair_map(four.pair_map(400), pairs=5)
    ax.figure.savefig(out, dpi=72, bbox_inches="tight")
    print(f"wrote {out} ({out.stat().st_size // 1024} KiB)")


if __name__ == "__main__":
    main()
