"""Writes docs/actuator.png, the README's picture of a hood lifted by a
strut: ``python examples/actuator_picture.py`` (needs the ``plot`` extra).

The linkage is the one-call design's best hinge for ``examples/hood.toml``
(millimetres). A gas strut is added from a ground pivot on the body (inside
the task's ``[space]``: below the closed hood) to the middle of the hood
link (the coupler's ``A C``). The picture shows the placement map (left:
where the strut's ground pivot may go; the dark region meets a stroke
ratio of at most 1.8 and a force transmission angle of at least the task's
40 degrees) and the chosen design at the three poses with the strut drawn
as a cylinder (right). The table printed is the README's.
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

import burmester  # noqa: E402
from burmester import actuators, taskfile  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def hood_strut() -> "tuple[burmester.ActuatorMap, burmester.Actuator]":
    """The hood's best hinge, its strut placement map and the best strut."""
    spec = taskfile.load(str(ROOT / "examples" / "hood.toml"))
    report = burmester.design(spec.task, space=spec.space, limits=spec.limits, top=1)
    sfb = report[0].linkage
    # The strut's ground pivot on the body: the task's pivot space. Its
    # moving point on a bracket 20 mm under the hood, 40 mm behind the
    # front edge. The hinge's limits, with room for the strut in the size.
    (x0, x1), (y0, y1) = (-150.0, 50.0), (-100.0, 0.0)
    plate = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    lim = spec.limits
    limits = burmester.DesignLimits(lim.min_transmission_deg, lim.max_link_ratio, lim.input, 8.0)
    amap = actuators.actuator_map(sfb, (-250.0, 150.0, -200.0, 200.0), (320, 320),
                                  link="coupler", point=(-40.0, -20.0), max_stroke_ratio=1.8,
                                  limits=limits, base_plate=plate)
    best = amap.best_placements(1, rank_by="balanced")
    if not best:
        raise SystemExit("no acceptable strut placement")
    return amap, best[0]


def main() -> None:
    amap, strut = hood_strut()
    print(actuators.actuator_table(strut, "examples/hood.toml (its best design)", "mm"))
    fig, (left, right) = plt.subplots(1, 2, figsize=(15.0, 6.2))
    actuators.draw_map(amap, best=3, ax=left)
    actuators.draw_actuator(strut, ax=right)
    fig.tight_layout()
    out = ROOT / "docs" / "actuator.png"
    fig.savefig(out, dpi=64, bbox_inches="tight")
    plt.close(fig)
    print(f"wrote {out} ({out.stat().st_size // 1024} KiB)")


if __name__ == "__main__":
    main()
