"""Exact distances of points from the Burmester curves of four float poses
(issue 24, classes A and B of `open/curves`, curv33).

The center-point curve is ``det [a_k(G) b_k(G)] = 0`` (k = 2, 3, 4) with
the rows of tests/python/burmester_reference.py (``a_k(G) . z = b_k(G)``);
the circle-point curve is the same with the roles swapped: a circle point
``z`` (pose 1) is on a circle about ``G`` at every pose exactly when
``((R_k - I) z + t_k) . G = (R_k z) . t_k + |t_k|^2 / 2`` for k = 2, 3, 4 are
consistent. Both are expanded exactly in rational arithmetic (sympy) from
the float task (the cosines and sines of the angle differences taken to 60
digits, so the task is the float task to 1e-55); nothing of the library is
used. A point's distance from the exact curve is found by Newton steps
along the gradient in mpmath at 60 digits (the first-order distance
``|f| / |grad f|`` at the point, and the distance to the root found).

``condition`` measures how far the exact curve moves at a point when
every coordinate and angle of the task is moved by one ulp (16 random sign
patterns): the accuracy that the float task itself allows there.

    python fuzz/reference/open_curves.py
"""

import os
import random
import sys

import mpmath
import sympy as sp

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "python"))
from burmester_reference import _det3, _displacements, _rows  # noqa: E402

mpmath.mp.dps = 60


def _circle_rows(poses, x, y):
    """The rows ``(a_k, b_k)`` of the circle-point condition, linear in the
    circle point ``z = (x, y)``: ``a_k(z) . G = b_k(z)``."""
    rows = []
    for c, s, tx, ty in _displacements(poses):
        rzx, rzy = c * x - s * y, s * x + c * y
        ax = rzx - x + tx
        ay = rzy - y + ty
        b = rzx * tx + rzy * ty + (tx * tx + ty * ty) / 2
        rows.append((ax, ay, b))
    return rows


def curve(poses, circle):
    """The exact cubic as a list of ``((i, j), mpf coefficient)``."""
    x, y = sp.symbols("x y")
    r = (_circle_rows if circle else _rows)(poses, x, y)
    f = sp.Poly(_det3(r[0], r[1], r[2]), x, y)
    return [(m, mpmath.mpf(c.p) / c.q) for m, c in zip(f.monoms(), f.coeffs())]


def _eval(terms, px, py):
    f = mpmath.mpf(0)
    gx = mpmath.mpf(0)
    gy = mpmath.mpf(0)
    for (i, j), c in terms:
        f += c * px**i * py**j
        if i:
            gx += c * i * px ** (i - 1) * py**j
        if j:
            gy += c * j * px**i * py ** (j - 1)
    return f, gx, gy


def distance(terms, point):
    """``(first-order distance, distance to the root along the gradient
    line)`` of the float point from the exact curve."""
    px, py = mpmath.mpf(point[0]), mpmath.mpf(point[1])
    f, gx, gy = _eval(terms, px, py)
    g = mpmath.sqrt(gx * gx + gy * gy)
    first = abs(f) / g if g else mpmath.inf
    if g == 0:
        return first, first
    ux, uy = gx / g, gy / g
    t = -f / g
    for _ in range(100):
        fv, hx, hy = _eval(terms, px + ux * t, py + uy * t)
        slope = hx * ux + hy * uy
        if slope == 0:
            break
        step = fv / slope
        t -= step
        if abs(step) <= mpmath.mpf(10) ** -50 * (1 + abs(t)):
            break
    return first, abs(t)


def condition(poses, point, circle, patterns=16, seed=1):
    """The largest exact distance of ``point``'s nearest curve point from
    the curves of the task moved by one ulp per number (random signs)."""
    base = distance(curve(poses, circle), point)[1]
    rnd = random.Random(seed)
    worst = mpmath.mpf(0)
    for _ in range(patterns):
        moved = [
            tuple(v + rnd.choice((-1, 1)) * abs(v) * 2.0**-52 if v else v for v in p) for p in poses
        ]
        d = distance(curve(moved, circle), point)[1]
        worst = max(worst, abs(d - base))
    return worst


CASES = {
    # (poses, point, circle plane?, the library's distance and tolerance)
    "traced-vertex-1.5-tolerances-off-ordinary-task": (
        [
            (-0.02275390625, -0.042015625, -0.04274609375),
            (0.038853572944153, -0.9227064419647494, 0.08583984375),
            (7.206768634628719, 6.860268617578484, 17.1875),
            (0.046768867136560394, -0.28195069777709586, -0.0078125),
        ],
        (6.879749194537926, -6.505866381759142),
        False,
    ),
    "traced-vertex-1.5-tolerances-off-moderate-task": (
        [
            (73.11328125, -105.09375, -23.93359375),
            (-86.0720594203068, -127.75386565142762, -9.000000000000001e-9),
            (64.86776245339738, 112.08311298228749, 28.06640625),
            (-139.66718578418778, -81.98453299989845, 37.19921875),
        ],
        (-23.057505622825122, 0.0297661273105021),
        False,
    ),
    "traced-vertex-1000-tolerances-off-far-pose": (
        [
            (0.00680005931015625, -3851.1718750001564, -0.205),
            (-19099999.99320039, -3851.17187437, -96.0),
            (0.00680025931015625, -3851.1701934, -49.0),
            (0.008481209310156251, -3851.1718767417, 75.51),
        ],
        (-66.14193582814187, -3851.167216437248),
        True,
    ),
}


if __name__ == "__main__":
    extra = sys.argv[1:]

    for name, (poses, point, circle) in CASES.items():
        if extra and not any(e in name for e in extra):
            continue
        terms = curve(poses, circle)
        first, root = distance(terms, point)
        cond = condition(poses, point, circle)
        print(
            f"{name}: {'circle' if circle else 'center'} point {point}: exact distance "
            f"{mpmath.nstr(root, 6)} (first order {mpmath.nstr(first, 6)}), "
            f"one ulp of the task moves the curve there by {mpmath.nstr(cond, 6)}"
        )


def _motion(poses):
    """Per pose k (0-based, pose 1 first): the exact rotation ``(c, s)`` of
    ``theta_k - theta_1`` (60 digits) and ``t_k = p_k - R_k p_1``, mpmath."""
    x1, y1 = mpmath.mpf(poses[0][0]), mpmath.mpf(poses[0][1])
    out = []
    for px, py, a in poses:
        d = mpmath.mpf(a) - mpmath.mpf(poses[0][2])
        c, s = mpmath.cos(d), mpmath.sin(d)
        out.append((c, s, mpmath.mpf(px) - (c * x1 - s * y1), mpmath.mpf(py) - (s * x1 + c * y1)))
    return out


def project(terms, point):
    """The exact curve's point nearest ``point`` along its gradient line."""
    px, py = mpmath.mpf(point[0]), mpmath.mpf(point[1])
    f, gx, gy = _eval(terms, px, py)
    g = mpmath.sqrt(gx * gx + gy * gy)
    ux, uy = gx / g, gy / g
    t = _root_on_line(terms, px, py, ux, uy, -f / g, 55)
    return px + ux * t, py + uy * t


def _root_on_line(terms, px, py, dx, dy, t, digits):
    """Newton's method for the exact curve along the line ``p + t d`` from
    ``t``, to ``digits`` digits."""
    for _ in range(200):
        fv, hx, hy = _eval(terms, px + dx * t, py + dy * t)
        step = fv / (hx * dx + hy * dy)
        t -= step
        if abs(step) <= mpmath.mpf(10) ** -digits * (1 + abs(t)):
            break
    return t


def exact_circle_point(poses, gx, gy):
    """The circle point of an exact center ``(gx, gy)`` on the exact
    center-point curve: ``|D_1k(z) - G| = |z - G|`` for k = 2, 3, 4,
    linear in ``z``; least squares of the three (consistent on the
    curve)."""
    rows = []
    for c, s, tx, ty in _motion(poses)[1:]:
        # |R z + t - G|^2 = |z - G|^2:  2 z . (R^T (t - G) + G) = |G|^2 - |t - G|^2
        ux, uy = tx - gx, ty - gy
        ax = c * ux + s * uy + gx
        ay = -s * ux + c * uy + gy
        b = (gx * gx + gy * gy - ux * ux - uy * uy) / 2
        rows.append((ax, ay, b))
    a = mpmath.matrix([[r[0], r[1]] for r in rows])
    b = mpmath.matrix([r[2] for r in rows])
    z = mpmath.lu_solve(a.T * a, a.T * b)
    return z[0], z[1]


def branch_signs(poses, c0, c1, a1):
    """The exact branch signs ``cross(C'_k - C1, A1 - C1)`` with
    ``C'_k = D_k1(C0)`` (Filemon's construction, ``C'_1 = C0``)."""
    out = []
    c0x, c0y = mpmath.mpf(c0[0]), mpmath.mpf(c0[1])
    c1x, c1y = mpmath.mpf(c1[0]), mpmath.mpf(c1[1])
    for c, s, tx, ty in _motion(poses):
        wx, wy = c0x - tx, c0y - ty
        kx, ky = c * wx + s * wy, -s * wx + c * wy
        dx, dy = kx - c1x, ky - c1y
        out.append(dx * (a1[1] - c1y) - dy * (a1[0] - c1x))
    return out

# Class B (curv34): the input `free-arc-chord-passes-defective-point-poses-at-one-position-3e4ebdb6`
# (now in regressions/curves/): poses 2, 3, 4 at nearly one position, the
# driven dyad of the fuzz check, and the line of centers near x = 3.2998.
CLASS_B = (
    [
        (6.5996180078125, -8.2421875e-8, 66.99609375),
        (8.550393225e-6, -8.3984375e-14, 0.058484375),
        (8.6328125e-6, 0.0, 0.31640625),
        (8.6328125e-6, 0.0, -8.242187500000001e-10),
    ],
    (6.045784821440137e-6, 4.125328799852609e-6),
    (3.299814766909, 0.48602449227914374),
)


def class_b_changes(poses, c0, c1, x=3.2998, ys=None):
    """Where the exact class changes along the line of centers near
    ``x``: each sample ``(x, y)`` is taken onto the exact center-point curve
    along its gradient, its exact circle point and Filemon signs decide
    free (all four signs agree) or not, and each change is bisected
    (60 steps) to the exact curve's ``y``."""
    terms = curve(poses, False)

    def free(y):
        gx, gy = project(terms, (mpmath.mpf(x), mpmath.mpf(y)))
        s = branch_signs(poses, c0, c1, exact_circle_point(poses, gx, gy))
        return all(v > 0 for v in s) or all(v < 0 for v in s), gy

    ys = ys or [-(10 ** (e / 20)) for e in range(-20, 60)]
    out = []
    prev = None
    for y in ys:
        f = free(y)[0]
        if prev is not None and f != prev[1]:
            lo, hi = prev[0], y
            for _ in range(60):
                mid = (lo + hi) / 2
                if free(mid)[0] == prev[1]:
                    lo = mid
                else:
                    hi = mid
            out.append(("free to defective" if prev[1] else "defective to free", free(lo)[1]))
        prev = (y, f)
    return out



if __name__ == "__main__" and sys.argv[1:] == ["class-b"]:
    # python fuzz/reference/open_curves.py class-b
    for kind, y in class_b_changes(*CLASS_B):
        print(f"class B line x = 3.2998: {kind} at y = {mpmath.nstr(y, 15)}")


# curv39: the open inputs of 2026-11-27 (trace38's round).
#
# Class A: each refused traced vertex is an edge crossing; its exact
# distance, the exact curve's crossing of that edge (Newton along it), and
# how far one ulp of the task moves the curve there. Values: poses, the
# refused vertex, circle plane?, whether the edge is horizontal (y fixed).
CURV39_A = {
    "462b0310": ([(0.4811328144407864, 2.9339650901794435e-7, 0.3), (0.48113347558341263, 1.06454076802063e-6, 0.3),
                  (0.48113413622760665, 1.8351036651763917e-6, 0.3), (0.4811347978232121, 2.6067762706451417e-6, -0.09371093750000001)],
                 (0.48130940421703694, -0.00021997469210108082), False, True),
    "32bb3f83": ([(350.7375049901827, 12412.904608977884, 0.0), (350.8348838964327, 12760.259609075263, -2.6139396203106458e-11),
                  (350.9322628026827, 13107.614609172642, 3.141592653589793), (351.0296417089327, 13454.969609270021, 3.141592653589793)],
                 (888.1983602397233, 12933.801499400006), True, False),
    "a0c838da": ([(65980.46875, -3.125e-11, 0.0), (65980.46875000073, 2.923515628304813e-7, 0.0),
                  (51807.298986901114, 40870.330931820965, 0.66796875), (51807.298986901405, 40870.330638813444, 0.66796875)],
                 (7117.250695282906, -3257710.9797775005), True, True),
    "0b584ef8": ([(-448.4375000000008, 7.345703125, 0.99609375), (-448.4368571484375, 7.34625, 0.02734375),
                  (-448.4375, 7.345703124999191, 100.0), (-448.4375, 7.345703124999181, 41.0)],
                 (-448.42378872024807, 7.346694153160071), True, False),
    "1adec857": ([(-0.23734876171875, -0.00010509374999999999, 0.00099609375), (-0.2373488666699115, -0.00010516652559744242, 0.0),
                  (-0.23754917297355035, 1.3712038398777763e-5, 73.1132813419961), (-0.23744995257071805, -0.0001249079846856963, 62.00390625)],
                 (-0.23740489217118688, -0.001693510899327509), True, True),
    "23b0b972": ([(-5719.914563671875, -400.4011343769531, 47.99609375), (-5719.914728009607, -400.4012468196019, 73.11328124999609),
                  (-5719.921541005625, -400.3778269189091, 0.23828125), (-5719.9129256280585, -400.381870545572, 30.90625)],
                 (-5719.830467605168, -399.9136084517557), True, True),
    "32450c8c": ([(-4803059.73828125, 499.99999834882817, 0.28515625), (-4803061.4241018435, 485.3352358788436, 0.058484375),
                  (-4803059.767863187, 502.0391289619362, 0.31640625), (-4803041.77176926, 502.0391223212631, 0.3164061599960937)],
                 (-4803116.001904903, 270.46504067808485), False, True),
    "e295bc14": ([(-41993473828.125, 15042886.328125, 73.03515625), (-42004646249.84896, 19625902.49269017, -8.3984375e-10),
                  (-42004647968.12623, 19624159.82289651, 0.000375), (-42008781796.727806, 19625898.372381777, 0.0)],
                 (-42002067405.50264, -354200972.20397985), False, True),
}


def edge_crossing(terms, point, horizontal):
    """The exact curve's crossing of the edge through ``point`` (the line
    ``y = point.y`` when ``horizontal``, else ``x = point.x``) nearest it,
    by Newton along the edge."""
    px, py = mpmath.mpf(point[0]), mpmath.mpf(point[1])
    dx, dy = (1, 0) if horizontal else (0, 1)
    t = _root_on_line(terms, px, py, dx, dy, mpmath.mpf(0), 50)
    return px + dx * t, py + dy * t


# Class B (center plane, lines of centers with nearly one circle point): the
# poses, the driven center and circle point, the line's x and the ys to
# sample for ``class_b_changes``.
CURV39_B = {
    "144ad15d": ([(65171.875, -0.00082421875, 0.28515625), (1.2600000000000002e-07, 1.0599609375e-07, 0.058484375),
                  (0.0, 0.0005625000000000001, 0.31640625), (0.0, 0.0, -0.01405859375)],
                 (-0.0018821909034159034, 0.0002852882436733973), (32585.93553837174, -3709.0527018913294),
                 32585.9368, [-4000 + 50 * k for k in range(80)]),
    "aaa7b4d6": ([(77171.875, -0.00082421875, 0.28515625), (2.6e-08, 1.0599609375e-07, 0.058484375),
                  (0.0, 6.25e-05, 0.31640625), (0.0, 0.0, -0.01405859375)],
                 (-0.0002089953050017357, 3.169590654379797e-05), (38585.93724048216, -4391.995036204313),
                 38585.9374, [-4000 + 50 * k for k in range(80)]),
    "910507b9": ([(-412423437.5, 8359.292578125, 0.03515625), (-416640624.9999974, 8359.37501059961, -81.98046875),
                  (-416640625.0, 8359.375, 81.00390625), (-416640625.0, 8359.375, 4.5000000000000006e-08)],
                 (-416640624.9999601, 8359.375190142902), (-414532031.0056545, 12508835.180179331),
                 -414532031.25, [-3.1e7 + 1e6 * k for k in range(63)]),
}


def class_a_report(name, poses, point, circle, horizontal, more=False):
    """One class A row: the refused vertex's exact distance, its edge's
    exact crossing and how far one ulp of the task moves the curve there
    (``more``: also the first-order distance and the exact terms)."""
    terms = curve(poses, circle)
    first, root = distance(terms, point)
    cx, cy = edge_crossing(terms, point, horizontal)
    extra = f" (first order {mpmath.nstr(first, 4)})" if more else ""
    line = (f"class A {name}: {'circle' if circle else 'center'} vertex {point} exact distance "
            f"{mpmath.nstr(root, 4)}{extra}; the edge's exact crossing ({mpmath.nstr(cx, 20)}, {mpmath.nstr(cy, 20)}); "
            f"one ulp moves the curve {mpmath.nstr(condition(poses, point, circle, 8), 3)}")
    if more:
        line += "; terms " + ", ".join(f"{m}: {mpmath.nstr(c, 5)}" for m, c in terms)
    print(line)


if __name__ == "__main__" and sys.argv[1:] == ["curv39"]:
    # python fuzz/reference/open_curves.py curv39
    for name, case in CURV39_A.items():
        class_a_report(name, *case)
    for name, (poses, c0, c1, x, ys) in CURV39_B.items():
        for kind, y in class_b_changes(poses, c0, c1, x, ys):
            print(f"class B {name}: line x = {x}: {kind} at y = {mpmath.nstr(y, 12)}")


# curv40 (the tracer's fold on a nearly straight piece): the poses, the
# plane (circle?), the view (xmin xmax ymin ymax), and the traced
# polylines' ends on the view's edges; each end's exact crossing of its edge.
CURV40 = {
    "e067e5da": ([(-0.00200390625, 107.5, 31.25), (-17.631854817288307, 106.02446735641578, -0.001),
                  (-17.737756948394164, 106.00667311471496, 0.0), (-29.205900296226382, 103.41768675652295, 0.10955078125)],
                 True, (-798.3274965931357, 779.8362538419599, -683.3446684106343, 894.8190820244613),
                 [(779.8362538419599, 270.71128608102333), (-798.3274965931357, -276.96287193752573)]),
    "719363d5": ([(-0.06526562500000001, -0.00082421875, 0.28515625), (2.6e-8, -8.3984375e-10, 0.058160156250000004),
                  (2.6e-8, -8.3984375e-10, 0.31640625), (0.0, 0.0, -3.90625e-12)],
                 False, (-41.447670459778394, 1.0803654727651093, -41.42202070338598, 1.1060152291575172),
                 [(-0.046605511608247524, 1.1060152291575172), (0.49046644167890086, -41.42202070338598)]),
    "5a77a1d1": ([(35836.490347108884, -0.10002734375, 2.145498903589793), (35840.234375, -0.10002734375, 3.141592653589793),
                  (35840.23430756839, -0.10002734375, 3.145647341089793), (35840.229306159425, -0.10002734375, 3.106436446445262)],
                 True, (35484.80055236068, 38282.7663499924, -1397.7099957011076, 1400.255801930611),
                 [(35484.80055236068, 186.38558794412592), (38282.7663499924, -1279.1542721118733)]),
    "5855fc72": ([(-2417.96875, 0.00025, -0.8515625), (0.00025002675, -9.648437500000001e-10, 0.058484375),
                  (0.0, 0.0005, 0.31640625), (0.00025002675, -9.648437500000001e-10, 0.000500045)],
                 True, (-789093.6007922697, 786364.2714849757, -1534229.613022059, 41228.25925518642),
                 [(-1209.038713549146, 41228.25925518642), (-1206.7094062735025, -1534229.613022059)]),
    "3633626e": ([(6526171874999.915, -82422.0004921875, 0.28515625), (-82419.3603359375, -83984.5004921875, 0.0),
                  (1171874.9146640624, -0.1254921875, 81.00390625), (-0.0853359375, 599999.8745078126, -0.04266796875)],
                 True, (-4137669216922467.0, 114539408766058.5, -4149784452624695.0, 102424173063830.25),
                 [(3267196043912.9863, -4149784452624695.0), (3263011393493.4907, 102424173063830.25)]),
}


if __name__ == "__main__" and sys.argv[1:2] == ["curv40"]:
    # python fuzz/reference/open_curves.py curv40 [x,y ...]: the exact
    # crossings of the traced ends' edges, and the exact distance of any
    # further points given (name:x,y).
    pts = {}
    for a in sys.argv[2:]:
        n, xy = a.split(":")
        pts.setdefault(n, []).append(tuple(float(v) for v in xy.split(",")))
    for name, (poses, circle, (x0, x1, y0, y1), ends) in CURV40.items():
        terms = curve(poses, circle)
        for e in ends:
            horizontal = e[1] in (y0, y1)
            cx, cy = edge_crossing(terms, e, horizontal)
            print(f"{name}: end {e} exact crossing ({mpmath.nstr(cx, 20)}, {mpmath.nstr(cy, 20)}) "
                  f"off by {mpmath.nstr(abs(cx - e[0]) + abs(cy - e[1]), 3)}")
        for p in pts.get(name, []):
            first, root = distance(terms, p)
            print(f"{name}: point {p} exact distance {mpmath.nstr(root, 4)} (first order {mpmath.nstr(first, 4)})")
    # The exact curve's points next to the chord between the two ends, at
    # fractions 0.1, 0.3, 0.5, 0.7, 0.9 of it (along the gradient line).
    for name, (poses, circle, _view, (e0, e1)) in CURV40.items():
        if pts:
            break
        terms = curve(poses, circle)
        out = []
        for f in (0.1, 0.3, 0.5, 0.7, 0.9):
            x, y = project(terms, (e0[0] + f * (e1[0] - e0[0]), e0[1] + f * (e1[1] - e0[1])))
            out.append(f"{mpmath.nstr(x, 20)} {mpmath.nstr(y, 20)}")
        print(f"{name}: exact points " + "  ".join(out))


# curv41: the 13 open class B inputs of stop 39's rounds. Each: circle
# plane?, the library's class of the check's point (`classify`), the poses,
# the driven dyad's C0 and C1, the failing chord's ends (on a11cbfa) and
# the check's point (the float curve's point at the chord's middle).
CURV41 = {
    "31324d87": (True, "Defective",
                 [(0.05825367578124999, 6403515.625, 32.99609375), (-0.08979319921875, -9.648437500000002e-08, 0.058484375), (9800.000050550781, 0.05, 0.00390625), (0.05825367578124999, 6403515.625, 33.8359375)],
                 (715809.4476516463, 3220175.7585907504), (7260.515008336862, 6439565.881922528),
                 ((-16955.41386695779, 6516559.222124699), (182219.03322689005, 6289994.032878297)), (92.24922208031603, 6403723.650372982)),
    "364854dc": (True, "Defective",
                 [(0.015625000000000187, 6.403515625e-08, 34.99609375), (0.015624999999999101, -9.6484375e-22, 0.058484375), (0.015625, 3.125e-14, 0.00390625), (0.015624999872, -1.2800000000099998e-10, 4.7000000000000004e-08)],
                 (0.015624984886440116, 1.4678505772004302e-08), (0.015624941179273462, 8.640351830569613e-08),
                 ((0.015623950566913687, 4.5261806339641523e-07), (0.015626143191377846, -3.5769370204132076e-07)), (0.015625046738564505, 4.708139736580192e-08)),
    "39a73d5f": (True, "Defective",
                 [(6517187500000000.0, 8517578124.999999, 0.08533203125), (6493360236821671.0, -556530050163462.5, 8e-09), (6485765796789330.0, 640616571750944.9, 0.18359375), (6343807809267905.0, 1494648987540833.0, 0.31640625)],
                 (-284938511019519.0, 324798650228.1875), (-12802286733404.0, 799906376543.3125),
                 ((-12455162131033.0, 383028641473.6875), (-11773259266824.0, 1157977528051.625)), (-12550861775246.0, 759135857208.0)),
    "46b64ec4": (False, "Defective",
                 [(-0.10675390625, 64.1015625, -0.10675392912109376), (-6.623145950926372, 57.86495073645306, 0.0), (-9.900053661252608, 54.16408072579688, 0.058484375), (-21.610188072305288, 35.823635733390226, 0.31640625)],
                 (54.999982276682786, -3.233386279077877e-05), (61.36466118195946, 10.284069449524097),
                 ((54.89935710156645, -0.6128190572919849), (55.05876264929795, 0.6127543895664034)), (54.97912445993883, -4.0743415098631885e-05)),
    "7afa44b8": (True, "Defective",
                 [(0.00199609375, 5.7324218750000004e-08, -3.90625e-12), (-3.90625e-12, -3.90625e-06, 0.01499609375), (80550.78125, 1.99609375, 0.0234375), (0.0, 2.6e-08, 0.04837890625)],
                 (0.001176699162897421, -0.1388673164097718), (860460.9468367817, 38465535.662195235),
                 ((0.009218004033755278, 0.1366094783081399), (0.019801638500211993, -0.40264514728242196)), (0.0012656906401389278, -0.13327776797051538)),
    "7cf7d3a1": (False, "Boundary",
                 [(0.0, 0.0, 0.3203125), (0.0, 0.99609375, -35.140625), (0.0, 0.99609375, 0.0), (0.0, 0.0, 18.97265625)],
                 (-0.4980468749999999, 0.49804687500000006), (-1.3423717870212386e-16, 5.551115123125783e-17),
                 ((0.2908186388220465, 0.48401634096579566), (0.2908186388220467, 0.512077409034204)), (0.2908186388220466, 0.4980468749999562)),
    "9b4f278e": (True, "Defective",
                 [(-8.088671875e-08, -3.90625e-12, 0.00099609375), (5.46875e-05, 64.96484375, 0.02734375), (0.0, -8.088671875e-08, 0.1), (0.0, 0.0, 0.0)],
                 (1.0000790322566579e-06, -5.39372188157472e-06), (-0.42796905477327596, -32.482426922189475),
                 ((4.9896005843900486e-06, -0.00014473302261208687), (1.8327314351902597e-06, 1.60181078996402e-05)), (-5.374119654469956e-07, -6.443500131325663e-05)),
    "c6291f2d": (True, "Defective",
                 [(2.675e-08, 6.0390625e-09, -0.00241792075), (2.675e-08, 6.0390625e-09, 0.058484375), (0.9765625, -0.00241789975390625, -41.0), (0.0, 8.945312500000001e-10, -0.023)],
                 (-1.6588177059739806e-07, 8.967687649876627e-07), (3.1510313424466823, -17.07077049498886),
                 ((1.2047344416510342e-07, -6.654412698092749e-07), (-5.621126174804036e-07, 2.4455333356115765e-06)), (-1.4440337073318155e-07, 9.068126874603585e-07)),
    "eb1a5faa": (False, "Defective",
                 [(-412423437.5, 8359.292578125, 0.03515625), (-416640624.9999974, 8359.37501059961, -81.98046875), (-416640625.0, 8359.375, 81.07421875), (-416640625.0, 8359.375, 4.5000000000000006e-08)],
                 (-416640624.99995935, 8359.37523463886), (-414532031.0056545, 12508835.180179333),
                 ((-414532031.0279528, 12126002.27959664), (-414532031.4361088, -9520124.859531816)), (-414532031.22480667, 1302938.7100324116)),
    "f04da194": (True, "Defective",
                 [(59999999550.78125, 312500001.0, 32.99609375), (-8984824.21875, 0.9999999815507813, 0.0), (59999999550.78125, 312500001.0, 1.0), (-449.21875, 312500001.0, 0.34765625)],
                 (29989079575.76145, 87146984866.71089), (61172210616.46568, -1319630143.5197957),
                 ((60709049561.38364, 908612749.8238901), (59216996557.29637, -1005636676.7861879)), (59676291058.78953, 325980190.8880736)),
    "f18da199": (True, "Defective",
                 [(-41164.04375, 6403474.4609375, 32.99609375), (-41164.15234375, -41.16406259648438, 0.058484375), (-41164.0625, 58.4453125, 0.00390625), (-53964.0625, -12841.164062599999, 0.0)],
                 (-3406061.4395085876, 3177914.1100782314), (-3312064.7534788013, 3088121.416369059),
                 ((-3399434.971931344, 3150168.792097484), (-3307199.852221628, 3084605.9008044787)), (-3330081.4581103995, 3124136.344894786)),
    "f783a3c5": (False, "Boundary",
                 [(-3.274627761523147e-14, 8.515625e-12, -34.0029385964102), (-3.2825261473097346e-14, 8.515625e-12, -34.0068448464102), (-3.851953221875e-14, 8.515625e-12, 3.141592653589793), (-3.8519238338422617e-14, 8.515625e-12, 3.137686403589793)],
                 (-3.5661147692263743e-14, 8.525666968399642e-12), (-3.563275797682738e-14, 8.525691705076074e-12),
                 ((-6.47155753728142e-14, 8.533907969269178e-12), (-6.589579449936511e-15, 8.517486639365457e-12)), (-3.5652577411375357e-14, 8.525697304317317e-12)),
    "5856f48f": (False, "Defective",
                 [(-0.42998948867187503, 1.05128125e-05, 0.0), (-0.42998951473198416, 1.053638031280996e-05, 0.0022460937500000003), (-0.4299899297156499, 1.0897792971164332e-05, 0.03742578125), (-0.429988530030535, 9.971394888299404e-06, -0.05016796875)],
                 (-0.4299997991841345, -1.0754844431235276e-06), (-0.429999994496634, -1.0778125070485094e-06),
                 ((-0.4299997991851563, -5.598873792390182e-06), (-0.42999979918515635, -6.108584684234303e-06)), (-0.42999979918515635, -5.8537292383122425e-06)),
}


def curv41_exact(name, steps=32, case=None):
    """The exact class of the check's point (taken onto the exact curve
    along the gradient; its exact circle point in the center plane; the
    exact Filemon signs), the exact class of the exact curve's points next
    to the chord at ``1/steps`` steps, and each change along it bisected
    (50 steps) to the exact curve's point there."""
    circle, _lib, poses, c0, c1, (a, b), q = case or CURV41[name]
    terms = curve(poses, circle)

    def cls(p):
        x, y = project(terms, p)
        a1 = (x, y) if circle else exact_circle_point(poses, x, y)
        s = branch_signs(poses, c0, c1, a1)
        return all(v > 0 for v in s) or all(v < 0 for v in s), (x, y), s

    at = lambda t: (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
    free_q, pq, signs = cls(q)
    ts = [k / steps for k in range(steps + 1)]
    fs = [cls(at(t))[0] for t in ts]
    changes = []
    for k in range(steps):
        if fs[k] != fs[k + 1]:
            lo, hi = ts[k], ts[k + 1]
            for _ in range(50):
                mid = (lo + hi) / 2
                if cls(at(mid))[0] == fs[k]:
                    lo = mid
                else:
                    hi = mid
            changes.append((lo, cls(at(lo))[1]))
    return free_q, pq, signs, fs, changes


def curv41_report(name, case, steps=32):
    """Prints :func:`curv41_exact` of one case (``CURV41``'s layout)."""
    free_q, pq, signs, fs, changes = curv41_exact(name, steps, case)
    print(f"{name} ({'circle' if case[0] else 'center'} plane): the check's point is {case[1]} by the "
          f"library, exactly {'free' if free_q else 'defective'} (signs "
          f"{', '.join(mpmath.nstr(v, 3) for v in signs)}; on the exact curve at "
          f"({mpmath.nstr(pq[0], 17)}, {mpmath.nstr(pq[1], 17)}))")
    print(f"  exactly free (F) or not (d) along the chord: {''.join('F' if f else 'd' for f in fs)}")
    for t, p in changes:
        print(f"  exact change at {t:.6f} of the chord: ({mpmath.nstr(p[0], 17)}, {mpmath.nstr(p[1], 17)})")


if __name__ == "__main__" and sys.argv[1:2] == ["curv41"]:
    # python fuzz/reference/open_curves.py curv41 [name ...]
    for name, case in CURV41.items():
        if sys.argv[2:] and name not in sys.argv[2:]:
            continue
        curv41_report(name, case)


# curv41's libFuzzer round: two class A findings (a traced center point on
# the view's edge refused by `circle_point`), as CURV39_A: the poses, the
# refused vertex, circle plane?, whether its edge is horizontal.
CURV41_A = {
    "11e1f642": ([(2.676510399999996e22, 2.919304e21, 0.0), (5.78085420887002e19, 2.919304e21, 0.0),
                  (1.8506102137499996e23, 2.919304e21, 3.141592653589793),
                  (1.1561654231082068e20, 2.919304e21, 3.141592653589793)],
                 (52999887614849670000000.0, 2919304000000000000000.0), False, True),
    "aefd216a": ([(2.8713e18, 3.1415926455116683, 0.0), (6.644645503795821e18, 7.270145734513581, 0.0),
                  (3.2158560000000004e19, 35.18583763176272, 3.141592653589793),
                  (3.0256323750000005e19, 33.10453250397926, 3.141592653589793)],
                 (17982707313448956000.0, 32.0), False, True),
}


if __name__ == "__main__" and sys.argv[1:] == ["curv41-a"]:
    # python fuzz/reference/open_curves.py curv41-a
    for name, case in CURV41_A.items():
        class_a_report(name, *case, more=True)


# curv42: the two CURV41_A inputs traced again: the line's end at the line
# pair's node settled onto the curve off the edge (`settle_near`); the new
# end's exact distance and how far one ulp of the task moves the curve there.
CURV42 = {
    "11e1f642": (52999887322202690000000.0, 2919303562022854000000.0),
    "aefd216a": (17982707308237832000.0, 7798999068.793272),
}


if __name__ == "__main__" and sys.argv[1:] == ["curv42"]:
    # python fuzz/reference/open_curves.py curv42
    for name, point in CURV42.items():
        poses, _old, circle, _h = CURV41_A[name]
        terms = curve(poses, circle)
        first, root = distance(terms, point)
        print(f"curv42 {name}: new end {point} exact distance {mpmath.nstr(root, 4)} "
              f"(first order {mpmath.nstr(first, 4)}); one ulp moves the curve "
              f"{mpmath.nstr(condition(poses, point, circle, 8), 3)}")


# curv43: stop 40's final round's class B input (`401a552c`, center plane, a
# view 4e7 wide): the failing chord on 77077b9 and the check's point.
CURV43 = {
    "401a552c": (False, "Defective",
                 [(0.0001875, 64035.15625, 34.98046875), (-0.0008984375, 0.00018749903515625, 0.058484375),
                  (0.015625, 0.03125, 0.53515625), (-128.0, -128.000000001, 0.015625047)],
                 (-10417.623221495787, 30901.13359319052), (-4860.702347340231, 74064.6507156851),
                 ((-822086.8293539063, 238112.70838937772), (828694.605832389, -195810.3315813626)),
                 (338.0852884343815, 10608.22704690533)),
}


# The view of the fuzz check, and two short chords of the oval next to the
# origin (vertices of a11cbfa's trace in that view) across which the exact
# class changes: the exact arc ends' centers there.
CURV43_VIEW = (-40658163.91094275, 1092545.0087307617, -20859377.66481233, 20891331.25486118)
CURV43_OVAL = [((3275.1885548101504, 10673.540706404745), (4903.571358538844, 10360.635982675305)),
               ((-3907.6146605670215, 5556.133574833442), (-3867.308412309909, 6708.559317533442))]


def edge_roots(terms, fixed, value):
    """The exact curve's real points on the line ``x = value`` (``fixed``
    ``"x"``) or ``y = value``: the free coordinate's real roots."""
    coeffs = {}
    for (i, j), c in terms:
        k, v = (j, c * mpmath.mpf(value) ** i) if fixed == "x" else (i, c * mpmath.mpf(value) ** j)
        coeffs[k] = coeffs.get(k, 0) + v
    poly = [coeffs.get(k, 0) for k in range(max(coeffs), -1, -1)]
    roots = mpmath.polyroots(poly, maxsteps=400, extraprec=400)
    return [mpmath.re(r) for r in roots if abs(mpmath.im(r)) <= mpmath.mpf(10) ** -40 * (1 + abs(r))]


if __name__ == "__main__" and sys.argv[1:2] == ["curv43"]:
    # python fuzz/reference/open_curves.py curv43 [steps]
    steps = int(sys.argv[2]) if sys.argv[2:] else 64
    for name, case in CURV43.items():
        curv41_report(name, case, steps)
        terms = curve(case[2], case[0])
        x0, x1, y0, y1 = CURV43_VIEW
        for fixed, value, lo, hi in [("x", x0, y0, y1), ("x", x1, y0, y1), ("y", y0, x0, x1), ("y", y1, x0, x1)]:
            inside = [r for r in edge_roots(terms, fixed, value) if lo <= r <= hi]
            print(f"  exact crossings of the edge {fixed} = {value}: {[mpmath.nstr(r, 17) for r in inside]}")
        for a, b in CURV43_OVAL:
            oval = (case[0], case[1], case[2], case[3], case[4], (a, b), a)
            for t, p in curv41_exact(name, 16, oval)[4]:
                print(f"  exact change on the oval's chord {a} - {b}: ({mpmath.nstr(p[0], 17)}, {mpmath.nstr(p[1], 17)})")


# curv44: the two open class B inputs of curv43's round (center plane, views
# `5e-7` and `6e-6` wide about (0.00281, 0.00281)): the failing chord on
# c281397 and the check's point (the float curve's point next to its middle).
CURV44 = {
    "1e3714ac": (False, "Defective",
                 [(0.0028109375000000382, 0.0028109375, -0.00390625), (0.002810935470970648, 0.002810939687366846, -0.0789765625),
                  (0.002810937610016462, 0.0028109373904124904, 0.0), (0.0028109981436248515, 0.0028109891285376274, 28.109375)],
                 (0.0028109656093750763, 0.002810965609374931), (0.0028109632723313073, 0.0028109675381688586),
                 ((0.0028109364281778534, 0.002810995071647829), (0.0028109278477387797, 0.002811003652082263)),
                 (0.0028109321379583166, 0.002810999361865046)),
    "9df66c48": (False, "Defective",
                 [(0.0028109375000000382, 0.0028109375, -3.90625e-6), (0.0028109375000000382, 0.002810937500000002, 0.04790234375),
                  (0.0028109375000000382, 0.0028109375000000022, 0.064), (0.0028109656093749623, 0.0028109656093750065, 28.109375)],
                 (0.0028109374999999077, 0.0028109375000000257), (0.002810994700845522, 0.00281092105499147),
                 ((0.0028109499897716692, 0.002810953119603331), (0.0028109503378418188, 0.0028109527715331818)),
                 (0.0028109501638067438, 0.0028109529455682563)),
}

def _ulp_moved(values, rnd):
    """``values`` each moved by one ulp (``2^-52`` of itself), random sign."""
    return tuple(v + rnd.choice((-1, 1)) * abs(v) * 2.0**-52 if v else v for v in values)


def curv44_moved(name, patterns=16, seed=1):
    """The exact class of the check's point and of the chord's ends (each
    the float point taken onto the exact curve along the gradient) with
    every number of the task and of the driven dyad moved by one ulp
    (random signs, ``patterns`` times): ``(free at a, q, b; the smallest
    |sign| / |C'_k - C1| at q)`` per pattern, and the largest move of the
    exact circle point of ``q``'s curve point."""
    circle, _lib, poses, c0, c1, (a, b), q = CURV44[name]
    rnd = random.Random(seed)
    out = []
    base = None
    for k in range(patterns + 1):
        if k == 0:
            mp, m0, m1 = poses, c0, c1
        else:
            mp = [_ulp_moved(p, rnd) for p in poses]
            m0, m1 = _ulp_moved(c0, rnd), _ulp_moved(c1, rnd)
        terms = curve(mp, False)
        row = []
        for p in (a, q, b):
            x, y = project(terms, p)
            z = exact_circle_point(mp, x, y)
            s = branch_signs(mp, m0, m1, z)
            row.append(all(v > 0 for v in s) or all(v < 0 for v in s))
            if p is q:
                imgs = [_motion(mp)[j] for j in range(4)]
                room = min(abs(v) / mpmath.hypot(*_image_minus_c1(c, sn, tx, ty, m0, m1))
                           for v, (c, sn, tx, ty) in zip(s, imgs))
                zq = z
        base = base or zq
        out.append((row, room, mpmath.hypot(zq[0] - base[0], zq[1] - base[1])))
    return out


def _image_minus_c1(c, s, tx, ty, c0, c1):
    """``C'_k - C1`` (as :func:`branch_signs`)."""
    wx, wy = mpmath.mpf(c0[0]) - tx, mpmath.mpf(c0[1]) - ty
    return c * wx + s * wy - mpmath.mpf(c1[0]), -s * wx + c * wy - mpmath.mpf(c1[1])


if __name__ == "__main__" and sys.argv[1:2] == ["curv44"]:
    # python fuzz/reference/open_curves.py curv44 [steps]
    steps = int(sys.argv[2]) if sys.argv[2:] else 32
    for name, case in CURV44.items():
        curv41_report(name, case, steps)
        moved = curv44_moved(name)
        for k, (row, room, dz) in enumerate(moved):
            print(f"  {'float task' if k == 0 else f'moved {k:2d}'}: exactly free at the chord's start, "
                  f"the check's point, its end: {row}; q's room {mpmath.nstr(room, 3)}, "
                  f"its circle point moved {mpmath.nstr(dz, 3)}")
