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

curv38 adds two tests' references: ``KITE`` (the circle point of
``a_kite_s_circle_point_is_near_a_nearly_singular_curve``: its first-order
distance from the exact curve, and from the exact curves of the task moved
by one ulp) and ``OVAL`` (case 2 of
``issue24_traced_vertices_are_settled_on_the_curve``: the exact circle-point
curve's point of zero gradient next to pose 1, its value and Hessian there,
and the radius of the small oval around it, in the task as given and moved
by one ulp).

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
    "free-arc-chord-passes-defective-point-coefficients-lost-digits-near-c0-4279ce91": [
        (80996.09375, -9.6875e-10, 8.99609375),
        (-0.09438671875, 0.28515625, 0.0),
        (0.0, -3.8671875e-10, -3.90625e-6),
        (0.0, 0.0, -0.005),
    ],
}

KITE = (
    [
        (1.3213009141945586, 2.5756735452511808, -3.0483368593531375),
        (-2.6627289721045644, 0.99858480792809, -1.3504078528429135),
        (-2.839100574547616, -0.09277486550263747, -0.9582181914208807),
        (-2.5817168842097593, -1.1703830590883881, -0.5638922936465993),
    ],
    (0.0010844377299954466, 0.0594241297943962),
)

OVAL = (
    [
        (0.00680005931015625, -3851.1718750001564, -0.205),
        (-19099999.99320039, -3851.17187437, -96.0),
        (0.00680025931015625, -3851.1701934, -49.0),
        (0.008481209310156251, -3851.1718767417, 75.51),
    ],
    (0.0019102776423096657, -3851.1674948594928),
)


def _mp(v):
    v = F(v)
    return mpmath.mpf(v.numerator) / v.denominator


def _value_gradient_hessian(c, x, y):
    m = max(abs(v) for v in c)
    c = [_mp(v) / _mp(m) for v in c]
    terms = list(zip(c, MONOMIALS))
    v = sum(k * x**i * y**j for k, (i, j) in terms)
    gx = sum(k * i * x ** (i - 1) * y**j for k, (i, j) in terms if i)
    gy = sum(k * j * x**i * y ** (j - 1) for k, (i, j) in terms if j)
    hxx = sum(k * i * (i - 1) * x ** (i - 2) * y**j for k, (i, j) in terms if i > 1)
    hxy = sum(k * i * j * x ** (i - 1) * y ** (j - 1) for k, (i, j) in terms if i and j)
    hyy = sum(k * j * (j - 1) * x**i * y ** (j - 2) for k, (i, j) in terms if j > 1)
    return v, (gx, gy), (hxx, hxy, hyy)


def first_order(c, p, fr):
    """The first-order distance |f| / |grad f| of the point ``p`` (plane
    coordinates) from the curve of the local coefficients ``c``."""
    ox, oy, s = (mpmath.mpf(v) for v in fr)
    x, y = (mpmath.mpf(p[0]) - ox) / s, (mpmath.mpf(p[1]) - oy) / s
    v, (gx, gy), _ = _value_gradient_hessian(c, x, y)
    return float(abs(v) / mpmath.sqrt(gx**2 + gy**2) * s)


def oval(c, near, fr):
    """The point of zero gradient of the curve ``c`` next to ``near``, the
    curve's value (of its largest coefficient) and Hessian there, and the
    radius of the oval around it (where the Hessian is about a multiple of
    the identity and the value has its opposite sign), in the plane."""
    ox, oy, s = (mpmath.mpf(v) for v in fr)
    x0, y0 = (mpmath.mpf(near[0]) - ox) / s, (mpmath.mpf(near[1]) - oy) / s
    r = mpmath.findroot(lambda x, y: _value_gradient_hessian(c, x, y)[1], (x0, y0))
    v, _, h = _value_gradient_hessian(c, r[0], r[1])
    radius = mpmath.sqrt(-2 * v / h[0]) * s if v * h[0] < 0 else mpmath.mpf(0)
    return (r[0] * s + ox, r[1] * s + oy), v, h, radius


def _moved(poses, rnd):
    return [tuple(v + rnd.choice((-1, 1)) * math.ulp(v) if v else v for v in p) for p in poses]


def kite():
    poses, point = KITE
    fr = frame(poses)
    print("kite: circle point", point, "first-order distance from the exact curve",
          f"{first_order(exact(poses, True), point, fr):.2e},",
          f"from the plain f64 curve {first_order(plain(poses, True), point, fr):.2e}")
    rnd = random.Random(1)
    moved = [first_order(exact(_moved(poses, rnd), True, fr), point, fr) for _ in range(8)]
    print("  in the task moved by one ulp (8 sign patterns):", ", ".join(f"{d:.2e}" for d in moved))


def traced_oval():
    poses, near = OVAL
    fr = frame(poses)
    (cx, cy), v, h, radius = oval(exact(poses, True), near, fr)
    print("oval: center", mpmath.nstr(cx, 20), mpmath.nstr(cy, 20), "value", mpmath.nstr(v, 5),
          "Hessian", [mpmath.nstr(t, 6) for t in h], "radius", mpmath.nstr(radius, 12))
    off = abs(mpmath.hypot(near[0] - cx, near[1] - cy) - radius)
    print("  the vertex", near, "is", mpmath.nstr(off, 3), "off it; its first-order distance from the plain f64 curve",
          f"{first_order(plain(poses, True), near, fr):.3g}")
    rnd = random.Random(1)
    for _ in range(8):
        (mx, my), _, _, mr = oval(exact(_moved(poses, rnd), True, fr), near, fr)
        print("  moved by one ulp: center moved", mpmath.nstr(mpmath.hypot(mx - cx, my - cy), 3),
              "radius", mpmath.nstr(mr, 6))


if __name__ == "__main__":
    kite()
    traced_oval()
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
