"""Writes docs/four-five.png, the README's picture of four and five poses:
``python examples/four_five_picture.py`` (needs the ``plot`` extra)."""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from burmester import plot  # noqa: E402
from notes_linkage import task  # noqa: E402


def main() -> None:
    out = Path(__file__).resolve().parents[1] / "docs" / "four-five.png"
    fig, (left, right) = plt.subplots(2, 1, figsize=(8.0, 11.0))
    four = task(20, 70, 120, 170)
    plot.burmester_plane(four, (-6, 12, -5, 8), driven=(4.0, 0.0), ax=left)   # the known rocker's pivot
    plot.burmester_plane(task(20, 70, 120, 170, 230), (-6, 12, -5, 8), ax=right)
    fig.savefig(out, dpi=72, bbox_inches="tight")
    print(f"wrote {out} ({out.stat().st_size // 1024} KiB)")


if __name__ == "__main__":
    main()
