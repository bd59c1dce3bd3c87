"""The exact coefficients of the four-pose curves of a float task, in the
library's local frame (issue 24, curv37): the reference for
``issue24_curve_coefficients_keep_their_digits_on_poses_at_one_position``
(tests/rust/curves.rs).

The library's frame is replayed in floats (origin the centroid of the pose
points as `LocalMotion::new` sums it, scale the largest distance from it);
from there on everything is exact: the local positions ``(p - origin) /
scale`` in rationals, the cosines and sines of the exact angle differences
to 100 digits (mpmath) made rationals, the rows of the dyad condition
(`LinearForm::row_poly`, the inverted motion's for the circle-point
curve) and their 3x3 determinant expanded in `fractions.Fraction`.

``condition`` moves every coordinate and angle of the task by one ulp
(random signs) and reports the largest change of the exact coefficients
(of the largest): the accuracy the float task allows. ``plain`` replays the
library's plain f64 expansion (`LinearForm::cubic`) for comparison.

    python fuzz/reference/coefficients.py
"""

import math
import random
from fractions import Fraction as F

import mpmath

mpmath.mp.dps = 100

MONOMIALS = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2), (3, 0), (2, 1), (1, 2), (0, 3)]
PERMS = [
    ([0, 1, 2], 1),
    ([1, 2, 0], 1),
    ([2, 0, 1], 1),
    ([0, 2, 1], -1),
    ([2, 1, 0], -1),
    ([1, 0, 2], -1),
]


def _frac(x):
    """An mpmath number as the exact rational it is."""
    sign, man, exp, _ = mpmath.mpf(x)._mpf_
    v = F(man) * (F(2) ** exp if exp >= 0 else F(1, 2 ** (-exp)))
    return -v if sign else v


def frame(poses):
    """The library's local frame (floats): origin and scale."""
    n = len(poses)
    ox = oy = 0.0
    for p in poses:
        ox += p[0] / n
        oy += p[1] / n
    scale = max(math.sqrt((p[0] - ox) ** 2 + (p[1] - oy) ** 2) for p in poses)
    return ox, oy, scale


def _mul2(p, q):
    return [
        p[0] * q[0],
        p[0] * q[1] + p[1] * q[0],
        p[0] * q[2] + p[2] * q[0],
        p[1] * q[1],
        p[1] * q[2] + p[2] * q[1],
        p[2] * q[2],
    ]


def _mul3(q, a):
    return [
        q[0] * a[0],
        q[0] * a[1] + q[1] * a[0],
        q[0] * a[2] + q[2] * a[0],
        q[1] * a[1] + q[3] * a[0],
        q[1] * a[2] + q[2] * a[1] + q[4] * a[0],
        q[2] * a[2] + q[5] * a[0],
        q[3] * a[1],
        q[3] * a[2] + q[4] * a[1],
        q[4] * a[2] + q[5] * a[1],
        q[5] * a[2],
    ]


def _expand(rot, trans, circle, zero):
    if circle:
        rot, trans = (
            [(c, -s) for c, s in rot],
            [(-(c * tx + s * ty), -(-s * tx + c * ty)) for (c, s), (tx, ty) in zip(rot, trans)],
        )
    rows = []
    for k in (1, 2, 3):
        c, s = rot[k]
        tx, ty = trans[k]
        ckx, cky = c * tx + s * ty, -s * tx + c * ty
        mr, mi = 1 - c, s
        rows.append([[ckx, mr, -mi], [cky, mi, mr], [-(tx * tx + ty * ty) / 2, tx, ty]])
    out = [zero] * 10
    for p, sign in PERMS:
        t = _mul3(_mul2(rows[0][p[0]], rows[1][p[1]]), rows[2][p[2]])
        out = [o + sign * x for o, x in zip(out, t)]
    return out


def exact(poses, circle, fr=None):
    """The exact local coefficients (Fractions) in the frame ``fr``
    (default: the library's frame of ``poses``)."""
    ox, oy, scale = (F(v) for v in (fr or frame(poses)))
    pos = [((F(p[0]) - ox) / scale, (F(p[1]) - oy) / scale) for p in poses]
    a0 = F(poses[0][2])
    rot = []
    for p in poses:
        d = F(p[2]) - a0
        d = mpmath.mpf(d.numerator) / d.denominator
        rot.append((_frac(mpmath.cos(d)), _frac(mpmath.sin(d))))
    x0, y0 = pos[0]
    trans = [(q[0] - (c * x0 - s * y0), q[1] - (s * x0 + c * y0)) for q, (c, s) in zip(pos, rot)]
    return _expand(rot, trans, circle, F(0))


def plain(poses, circle):
    """The library's plain f64 expansion, replayed (up to libm's last bit)."""
    ox, oy, scale = frame(poses)
    pos = [((p[0] - ox) / scale, (p[1] - oy) / scale) for p in poses]
    rot = []
    for p in poses:
        t = math.remainder(p[2] - poses[0][2], 2 * math.pi)
        rot.append((math.cos(t), math.sin(t)))
    x0, y0 = pos[0]
    trans = [(q[0] - (c * x0 - s * y0), q[1] - (s * x0 + c * y0)) for q, (c, s) in zip(pos, rot)]
    return _expand(rot, trans, circle, 0.0)


def normalised(c):
    m = max(abs(v) for v in c)
    return [float(F(v) / m) for v in c]


def error(c, ref):
    """The largest difference of ``c`` from ``ref``, of ``ref``'s largest."""
    m = max(abs(v) for v in ref)
    return float(max(abs(F(a) - r) for a, r in zip(c, ref)) / m)


def condition(poses, circle, patterns=8, seed=1):
    fr = frame(poses)
    ref = exact(poses, circle, fr)
    rnd = random.Random(seed)
    worst = 0.0
    for _ in range(patterns):
        moved = [tuple(v + rnd.choice((-1, 1)) * math.ulp(v) if v else v for v in p) for p in poses]
        worst = max(worst, error([float(v) for v in exact(moved, circle, fr)], ref))
    return worst


CASES = {
    "free-arc-chord-passes-defective-point-near-c0-poses-at-one-position-4279ce91": [
        (80996.09375, -9.6875e-10, 8.99609375),
        (-0.09438671875, 0.28515625, 0.0),
        (0.0, -3.8671875e-10, -3.90625e-6),
        (0.0, 0.0, -0.005),
    ],
}

if __name__ == "__main__":
    for name, poses in CASES.items():
        print(name, "frame", frame(poses))
        for circle in (False, True):
            ref = exact(poses, circle)
            print(
                " circle" if circle else " center",
                "exact (normalised):",
                normalised(ref),
                f"\n   plain f64 off by {error(plain(poses, circle), ref):.2e},"
                f" one ulp of the task moves it {condition(poses, circle):.2e}",
            )
