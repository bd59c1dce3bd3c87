"""Writes docs/actuator.png, the README's picture of a hood lifted by a
strut: ``python examples/actuator_picture.py`` (needs the ``plot`` extra).

The linkage is the one-call design's best hinge for ``examples/hood.toml``
(millimetres). A gas strut is added as the file's ``[actuator]`` table
says: from a ground pivot on the body (its ``base_plate``: the task's
``[space]``, below the closed hood) to a bracket on the hood. The picture shows the placement map (left:
where the strut's ground pivot may go; the dark region meets a stroke
ratio of at most 1.8, a force transmission angle of at least the task's
40 degrees and the strut's clearance from the links) and the chosen design at the three poses with the strut drawn
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
    # The strut: the task file's [actuator] table. Its ground pivot on the
    # body (the base plate: the task's pivot space), its moving point on a
    # bracket 20 mm under the hood, 40 mm behind the front edge; the
    # hinge's limits, with room for the strut in the size.
    t = spec.actuator
    assert t is not None and t.view is not None and t.base_plate is not None
    lim = spec.limits
    limits = burmester.DesignLimits(lim.min_transmission_deg, lim.max_link_ratio, lim.input, t.max_size_ratio)
    # Its clearance: the gas spring's body (``width``) against the hinge's
    # links (``[space] link_width``), at least ``min_gap`` apart.
    amap = actuators.actuator_map(sfb, t.view, t.grid, link=t.link, point=t.point,
                                  max_stroke_ratio=t.max_stroke_ratio, limits=limits,
                                  base_plate=list(t.base_plate), link_width=spec.space.link_width,
                                  actuator_width=t.width or 0.0, min_gap=t.min_gap or 0.0)
    best = amap.best_placements(1, rank_by="balanced")
    if not best:
        raise SystemExit("no acceptable strut placement")
    return amap, best[0]


def main() -> None:
    amap, strut = hood_strut()
    print(actuators.actuator_table(strut, "examples/hood.toml (its best design)", "mm"))
    fig, (left, right) = plt.subplots(1, 2, figsize=(15.0, 6.2))
    actuators.draw_map(amap, best=3, ax=left, units="mm")
    actuators.draw_actuator(strut, ax=right, units="mm")
    fig.tight_layout()
    out = ROOT / "docs" / "actuator.png"
    fig.savefig(out, dpi=64, bbox_inches="tight")
    plt.close(fig)
    print(f"wrote {out} ({out.stat().st_size // 1024} KiB)")


if __name__ == "__main__":
    main()
