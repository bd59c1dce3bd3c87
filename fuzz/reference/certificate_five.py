"""An exact count certificate for the five-pose Burmester points (cert43,
issue 24): the number of real finite Burmester points and of real points at
infinity (sliders) of the float task, and root intervals that isolate the
finite ones, in exact integer/rational arithmetic, as a Rust port with
`num-bigint` would compute it. Nothing of the library is used.

The task within rounding: each pose k's rotation from pose 1 is the
library's own f64 `(a_k - a_1).sin_cos()` (here `math.sin`/`math.cos`),
moved onto the unit circle by its half-angle tangent (`tau = s/(1+c)`, or
`(1-c)/s` for `c < 0`, rounded to the nearest double; then `c = (1-tau^2)/(1+tau^2)`,
`s = 2 tau/(1+tau^2)`, within an ulp of the float pair). On the unit circle
exactly, the poles are exact common points of the two cubics (with
`c^2 + s^2 != 1` they are not, and could not be divided out exactly).
Positions are the floats as the exact dyadic rationals they are.

Steps (`certify_order(poses)`; `certify` tries the six choices of the
shared poses `1, i, j` and takes the first that certifies):
1. The rows of the dyad condition (tests/python/burmester_reference.py's
   convention: `a_k(G) . z = b_k(G)`, `a_k(G) = conj(R_k) t_k +
   (1 - conj(R_k)) G`, `b_k(G) = t_k . G - |t_k|^2 / 2`), and the two
   center-point cubics `f1 = det(rows 2,3,4)`, `f2 = det(rows 2,3,5)`, as
   integer polynomials in `(x, y)` (denominators cleared).
   Degenerate: a cubic of degree < 3 (its cubic part `(x^2+y^2) L` with
   `L = 0`: the line at infinity is a component) -> cannot certify.
2. A rational shear `x = X + u Y` (u from a fixed list) with `f1, f2`'s
   `Y^3` coefficients nonzero (`L(u, 1) != 0`: no common point is sent to
   the shear's point at infinity); the resultant `R(X) = res_Y(f1, f2)` by
   evaluation at 10 integer points (6x6 integer Sylvester determinants,
   Bareiss) and interpolation. `R = 0` -> a common component: cannot
   certify. `deg R` is the number of finite common points with
   multiplicity; `9 - deg R` the ones at infinity.
3. The poles P12, P13, P23 (exact rationals: the fixed points of the
   displacements 1->2, 1->3, 2->3) are checked to lie on both cubics and
   their linear factors `X - (x_p - u y_p)` divided out, once per pole
   (coincident poles: the factor repeatedly); the quotient `Q` must not
   vanish at any pole (else a Burmester point at a pole, coincident poles
   of higher multiplicity, or a tangency there: cannot certify). A pole at
   infinity (two of poses 1, 2, 3 with equal rotation: a translation) is
   a real common point at infinity, not a factor of `R`: allowed alone and
   with at most one Burmester point at infinity (a slider in the pole's
   direction: the circular points take an even number), else cannot
   certify.
4. `Q` must be squarefree (`gcd(Q, Q') = 1`): then each root of `Q` is one
   common point of multiplicity one, and a real root is a real point (its
   conjugate lies over the same X). If not, the next shear is tried; if no
   shear gives a squarefree `Q`, a multiple common point: cannot certify.
5. Real roots of `Q` by a Sturm sequence (exact rationals), isolated by
   bisection; the number of real finite Burmester points is their count.
   At infinity: `4 - deg Q` Burmester points. The circular points are
   common points of every such pair of cubics (each once at least); the
   real common direction is the kernel of `L1` where `L1 || L2`. With
   `L1` not parallel to `L2` all are at the circular points (complex:
   no sliders). With `L1 || L2`, the real point at infinity takes
   `m >= 1` and the circular points `2 (mc - 1)`: `4 - deg Q` = 1 -> one
   slider; 2 -> a double slider (a common asymptote, listed twice); 3 or
   4 -> ambiguous: cannot certify.
6. (`points_of`, for `check`) each isolated root refined by exact
   bisection and its point's y, the common root of the two cubics there.

`check(poses, points, sliders)` compares a library answer with it:
refused when the count of points within `1e4` task sizes differs, when
those do not pair one to one with the exact near points each within
`1e-3 (size + d)`, or when the total (listed + sliders) differs from the
exact total (real finite + real at infinity); certified with a mark when
a point is over `1e-6 (size + d)` off (the judge's accuracy).

    python fuzz/reference/certificate_five.py --random N [seed]
    python fuzz/reference/certificate_five.py --designer N [seed]

measure ordinary and designer tasks (see `random_main`).

    python fuzz/reference/certificate_five.py dump.txt [more dumps]

reads `open_findings`' dump lines (task/moved frames and answers) and
prints, per frame, the certificate's verdict on the answer and the mpmath
judge's class (fuzz/reference/balance_five.py).
"""

import math
import sys
import time
from fractions import Fraction as F

SHEARS = [F(3, 7), F(-5, 11), F(7, 13), F(-2, 9), F(11, 17), F(-13, 19)]

# Statistics on the last certificate (sizes for a Rust estimate).
STATS = {}


class CannotCertify(Exception):
    pass


# ---------------------------------------------------------------- rationals

def exact(v):
    return F(*float(v).as_integer_ratio())


def unit_rotation(d):
    """The library's f64 `(cos d, sin d)` moved onto the unit circle exactly."""
    c, s = math.cos(d), math.sin(d)
    if s == 0.0:
        return (F(1), F(0)) if c > 0 else (F(-1), F(0))
    c, s = exact(c), exact(s)
    tau = exact(float(s / (1 + c) if c >= 0 else (1 - c) / s))  # to 53 bits: fewer bits below
    t2 = tau * tau
    return (1 - t2) / (1 + t2), 2 * tau / (1 + t2)


# ---------------------------------------------------- bivariate polynomials
# A polynomial in (x, y) is a dict {(i, j): coefficient}.

def padd(p, q):
    r = dict(p)
    for k, v in q.items():
        r[k] = r.get(k, 0) + v
    return {k: v for k, v in r.items() if v != 0}


def pmul(p, q):
    r = {}
    for (i, j), a in p.items():
        for (k, l), b in q.items():
            r[(i + k, j + l)] = r.get((i + k, j + l), 0) + a * b
    return {k: v for k, v in r.items() if v != 0}


def pscale(p, c):
    return {k: v * c for k, v in p.items() if v * c != 0}


def peval(p, x, y):
    return sum(v * x ** i * y ** j for (i, j), v in p.items())


def det3(r1, r2, r3):
    def m2(a, b, c, d):
        return padd(pmul(a, d), pscale(pmul(b, c), -1))
    t1 = pmul(r1[0], m2(r2[1], r2[2], r3[1], r3[2]))
    t2 = pmul(r1[1], m2(r2[0], r2[2], r3[0], r3[2]))
    t3 = pmul(r1[2], m2(r2[0], r2[1], r3[0], r3[1]))
    return padd(padd(t1, pscale(t2, -1)), t3)


def to_integer(p):
    """`p` (Fraction coefficients) times the lcm of its denominators, made
    primitive (divided by the gcd of the numerators)."""
    den = 1
    for v in p.values():
        den = den * v.denominator // math.gcd(den, v.denominator)
    q = {k: int(v * den) for k, v in p.items()}
    g = 0
    for v in q.values():
        g = math.gcd(g, v)
    return {k: v // g for k, v in q.items()} if g else q


# --------------------------------------------------- univariate polynomials
# A polynomial in X is a list of coefficients, lowest degree first.

def trim(a):
    a = list(a)
    while a and a[-1] == 0:
        a.pop()
    return a


def udiv(a, b):
    """Quotient and remainder of `a / b` over the rationals."""
    a = [F(v) for v in a]
    b = trim([F(v) for v in b])
    q = [F(0)] * max(len(a) - len(b) + 1, 0)
    while len(trim(a)) >= len(b):
        a = trim(a)
        k = len(a) - len(b)
        c = a[-1] / b[-1]
        q[k] = c
        for i, v in enumerate(b):
            a[i + k] -= c * v
        a = trim(a)
    return q, trim(a)


def uderiv(a):
    return [i * a[i] for i in range(1, len(a))]


def ugcd(a, b):
    a, b = trim(a), trim(b)
    while b:
        a, b = b, udiv(a, b)[1]
    return a


def ueval(a, x):
    r = 0
    for v in reversed(a):
        r = r * x + v
    return r


def sturm(a):
    seq = [trim(a), trim(uderiv(a))]
    while True:
        r = udiv(seq[-2], seq[-1])[1]
        if not r:
            break
        seq.append([-v for v in r])
    return seq


def sign_changes(vals):
    s = [v for v in vals if v != 0]
    return sum(1 for i in range(1, len(s)) if (s[i] > 0) != (s[i - 1] > 0))


def at_inf(seq, sign):
    return sign_changes([p[-1] * (sign ** (len(p) - 1)) for p in seq])


def count_in(seq, lo, hi):
    """Real roots in (lo, hi] (neither a root: lo, hi are not roots here)."""
    return sign_changes([ueval(p, lo) for p in seq]) - sign_changes([ueval(p, hi) for p in seq])


def isolate(q):
    """Sorted disjoint intervals (lo, hi), one real root of the squarefree
    `q` each, with separators between consecutive roots."""
    seq = sturm(q)
    n = at_inf(seq, -1) - at_inf(seq, 1)
    if n == 0:
        return [], seq
    bound = 1 + max(abs(F(v) / q[-1]) for v in q[:-1])  # Cauchy
    bound = F(2) ** (math.ceil(math.log2(bound)) + 1)
    out = []
    stack = [(-bound, bound, n)]
    while stack:
        lo, hi, k = stack.pop()
        if k == 0:
            continue
        if k == 1:
            out.append((lo, hi))
            continue
        mid = (lo + hi) / 2
        if ueval(q, mid) == 0:  # move off a root: a nearby dyadic
            mid = (lo + 3 * hi) / 4 if ueval(q, (lo + 3 * hi) / 4) != 0 else (3 * lo + hi) / 4
        left = count_in(seq, lo, mid)
        stack.append((lo, mid, left))
        stack.append((mid, hi, k - left))
    out.sort()
    return out, seq


# ------------------------------------------------------------ the resultant

def shear(p, u):
    """`p(X + u Y, Y)` as coefficients in Y, each a list in X (rationals)."""
    out = {}
    for (i, j), v in p.items():
        # (X + uY)^i Y^j = sum_k C(i,k) X^k (uY)^(i-k) Y^j
        for k in range(i + 1):
            c = v * math.comb(i, k) * u ** (i - k)
            key = (k, i - k + j)
            out[key] = out.get(key, 0) + c
    deg_y = max((b for (a, b), v in out.items() if v != 0), default=0)
    cols = []
    for b in range(deg_y + 1):
        cols.append(trim([out.get((a, b), 0) for a in range(4)]))
    return cols


def det_bareiss(m):
    m = [row[:] for row in m]
    n = len(m)
    sign = 1
    prev = 1
    for k in range(n - 1):
        if m[k][k] == 0:
            for r in range(k + 1, n):
                if m[r][k] != 0:
                    m[k], m[r] = m[r], m[k]
                    sign = -sign
                    break
            else:
                return 0
        for i in range(k + 1, n):
            for j in range(k + 1, n):
                m[i][j] = (m[i][j] * m[k][k] - m[i][k] * m[k][j]) // prev
                STATS["mults"] = STATS.get("mults", 0) + 2
        prev = m[k][k]
    return sign * m[n - 1][n - 1]


def resultant_y(c1, c2):
    """`res_Y` of two polynomials given as coefficient lists in Y (each a
    list in X, integers), both of degree 3 in Y with constant leading
    coefficients: evaluation at X = 0..9 and interpolation."""
    n1, n2 = len(c1) - 1, len(c2) - 1
    size = n1 + n2
    xs = list(range(10))
    vals = []
    for x in xs:
        a = [ueval(c, x) for c in c1]  # low to high in Y
        b = [ueval(c, x) for c in c2]
        rows = []
        for i in range(n2):
            row = [0] * size
            for k in range(n1 + 1):
                row[i + k] = a[n1 - k]
            rows.append(row)
        for i in range(n1):
            row = [0] * size
            for k in range(n2 + 1):
                row[i + k] = b[n2 - k]
            rows.append(row)
        vals.append(det_bareiss(rows))
    # Newton interpolation, then to monomial coefficients.
    coef = [F(v) for v in vals]
    for j in range(1, len(xs)):
        for i in range(len(xs) - 1, j - 1, -1):
            coef[i] = (coef[i] - coef[i - 1]) / (xs[i] - xs[i - j])
    poly = [F(0)]
    for i in range(len(xs) - 1, -1, -1):
        # poly = poly * (X - xs[i]) + coef[i]
        new = [F(0)] * (len(poly) + 1)
        for k, v in enumerate(poly):
            new[k + 1] += v
            new[k] -= v * xs[i]
        new[0] += coef[i]
        poly = new
    assert all(v.denominator == 1 for v in poly)
    return trim([int(v) for v in poly])


# ------------------------------------------------------------ the certificate

def cubics(poses):
    """The two center-point cubics (integer, primitive), the exact
    displacements `(c, s, tx, ty)` of poses 2..5 from pose 1, and the poles."""
    p1x, p1y, a1 = (exact(v) for v in poses[0])
    disp = []
    for px, py, a in poses[1:]:
        c, s = unit_rotation(float(a) - float(poses[0][2]))
        tx = exact(px) - (c * p1x - s * p1y)
        ty = exact(py) - (s * p1x + c * p1y)
        disp.append((c, s, tx, ty))
    rows = []
    for c, s, tx, ty in disp:
        ckx, cky = c * tx + s * ty, -s * tx + c * ty
        mr, mi = 1 - c, s
        ax = {(0, 0): ckx, (1, 0): mr, (0, 1): -mi}
        ay = {(0, 0): cky, (1, 0): mi, (0, 1): mr}
        b = {(1, 0): tx, (0, 1): ty, (0, 0): -(tx * tx + ty * ty) / 2}
        rows.append(tuple({k: v for k, v in r.items() if v != 0} for r in (ax, ay, b)))
    f1 = det3(rows[0], rows[1], rows[2])
    f2 = det3(rows[0], rows[1], rows[3])
    return f1, f2, disp


def fixed_point(c, s, tx, ty):
    """The fixed point of `G -> R G + t` (None: a translation)."""
    # (1 - c) x + s y = tx ; -s x + (1 - c) y = ty
    det = (1 - c) ** 2 + s * s
    if det == 0:
        return None
    return (((1 - c) * tx - s * ty) / det, (s * tx + (1 - c) * ty) / det)


def poles(disp):
    (c2, s2, t2x, t2y), (c3, s3, t3x, t3y) = disp[0], disp[1]
    # 2 -> 3: R = R3 R2^-1, t = t3 - R t2
    c, s = c3 * c2 + s3 * s2, s3 * c2 - c3 * s2
    tx, ty = t3x - (c * t2x - s * t2y), t3y - (s * t2x + c * t2y)
    return [fixed_point(*disp[0]), fixed_point(*disp[1]), fixed_point(c, s, tx, ty)]


def cubic_part_line(f):
    """`L` with `f`'s degree-3 part `(x^2 + y^2) L`: (Lx, Ly), checked."""
    c30, c21, c12, c03 = (f.get(k, 0) for k in [(3, 0), (2, 1), (1, 2), (0, 3)])
    lx, ly = c30, c03
    if c21 != ly or c12 != lx:
        raise AssertionError("cubic part is not circular")
    return lx, ly


def certify(poses):
    """`certify_order` on poses 1, i, j, k, l for each choice of the shared
    poses `1, i, j` (6 choices; the rotations from pose 1 and so the exact
    task are the same for each): the first that certifies. The reasons of
    all when none does."""
    reasons = []
    for i, j in [(1, 2), (1, 3), (1, 4), (2, 3), (2, 4), (3, 4)]:
        rest = [k for k in (1, 2, 3, 4) if k not in (i, j)]
        order = [0, i, j] + rest
        try:
            out = certify_order([poses[k] for k in order])
            STATS["order"] = order
            return out
        except CannotCertify as e:
            reasons.append(str(e))
    raise CannotCertify("; ".join(sorted(set(reasons))))


def certify_order(poses):
    """`(finite, sliders, info)`: the count of real finite Burmester points,
    of real points at infinity, and `info` (u, the root intervals in
    `X = x - u y`, the degrees, bit lengths). Raises CannotCertify."""
    STATS.clear()
    f1q, f2q, disp = cubics(poses)
    allp = poles(disp)
    pl = [p for p in allp if p is not None]
    inf_poles = 3 - len(pl)
    if inf_poles > 1:
        raise CannotCertify("poles at infinity (poses 1, 2, 3 all with one rotation)")
    for p in pl:
        assert peval(f1q, *p) == 0 and peval(f2q, *p) == 0, "pole off a cubic"
    f1, f2 = to_integer(f1q), to_integer(f2q)
    STATS["cubic_bits"] = max((abs(v).bit_length() for v in list(f1.values()) + list(f2.values())), default=0)
    L1, L2 = cubic_part_line(f1), cubic_part_line(f2)
    if L1 == (0, 0) or L2 == (0, 0):
        raise CannotCertify("a cubic of degree < 3 (the line at infinity a component)")
    parallel = L1[0] * L2[1] - L1[1] * L2[0] == 0
    last = None
    for u in SHEARS:
        if L1[0] * u + L1[1] == 0 or L2[0] * u + L2[1] == 0:
            continue
        # u has denominator q: scale to integers by q^3 (X, Y integer-coef.)
        q = u.denominator
        c1 = [[int(F(v) * q ** 3) for v in col] for col in shear_int(f1, u)]
        c2 = [[int(F(v) * q ** 3) for v in col] for col in shear_int(f2, u)]
        R = resultant_y(c1, c2)
        if not R:
            raise CannotCertify("a common component (the resultant vanishes)")
        STATS["res_bits"] = max(abs(v).bit_length() for v in R)
        STATS["res_degree"] = len(R) - 1
        Q = [F(v) for v in R]
        xs = [p[0] - u * p[1] for p in pl]
        for xp in xs:
            Q, r = udiv(Q, [-xp, 1])
            if r:
                raise AssertionError("pole factor does not divide the resultant")
        if any(ueval(Q, xp) == 0 for xp in xs):
            raise CannotCertify("a Burmester point at a pole (or coincident poles of higher multiplicity)")
        g = ugcd(Q, uderiv(Q))
        if len(g) > 1:
            last = "a multiple common point (Q not squarefree for any shear)"
            continue
        deg = len(Q) - 1
        infinite = 4 - deg
        if infinite < 0:
            raise AssertionError("more than four Burmester points")
        if inf_poles:
            # A pole at infinity is a real common point at infinity (the
            # direction normal to the translation): `L1 || L2`, and any
            # further point at infinity may be there or at the circular
            # points.
            if infinite > 1:
                raise CannotCertify("a pole at infinity and more than one Burmester point at infinity")
            sliders = infinite  # at the pole's direction (one) or none
        elif not parallel:
            # the only common points at infinity are the circular points:
            # any Burmester point at infinity is there (not real)
            sliders = 0
        elif infinite == 0:
            raise AssertionError("common asymptotic direction without a point at infinity")
        elif infinite <= 2:
            # `m + 2 (mc - 1) = infinite` with `m >= 1`: m = infinite (a
            # double slider: a common asymptote, listed twice)
            sliders = infinite
        else:
            raise CannotCertify("3 or 4 Burmester points at infinity (at the real direction or the circular points)")
        # integer Q for isolation, primitive
        den = 1
        for v in Q:
            den = den * v.denominator // math.gcd(den, v.denominator)
        Qi = [int(v * den) for v in Q]
        gg = 0
        for v in Qi:
            gg = math.gcd(gg, v)
        Qi = [v // gg for v in Qi]
        STATS["q_bits"] = max(abs(v).bit_length() for v in Qi)
        ivs, seq = isolate(Qi)
        return len(ivs), sliders, {"u": u, "intervals": ivs, "Q": Qi, "sturm": seq, "sliders": sliders,
                                   "sheared": (c1, c2)}
    raise CannotCertify(last or "no admissible shear")


def shear_int(p, u):
    """`q^3 p(X + u Y, Y)`'s Y-coefficients for integer `p`, u = a/q."""
    return shear({k: F(v) for k, v in p.items()}, u)


def size_c(poses):
    cx = sum(p[0] for p in poses) / 5
    cy = sum(p[1] for p in poses) / 5
    return max(math.hypot(p[0] - cx, p[1] - cy) for p in poses), (cx, cy)


def points_of(info):
    """Each isolated root's point `(x, y)` (mpmath, 50 digits): the root
    refined by exact bisection to 1e-40 relative, then the one common root
    in Y of the two sheared cubics there (the nearest to a root of the
    second). For a Rust port: the first subresultant's `Y = -S0(X)/S1(X)`
    in interval arithmetic."""
    import mpmath
    mpmath.mp.dps = 50
    q = info["Q"]
    u = info["u"]
    out = []
    for lo, hi in info["intervals"]:
        slo = ueval(q, lo) > 0
        while hi - lo > F(1, 10 ** 40) * (1 + abs(lo)):
            mid = (lo + hi) / 2
            v = ueval(q, mid)
            if v == 0:
                lo = hi = mid
                break
            if (v > 0) == slo:
                lo = mid
            else:
                hi = mid
        x0 = mpmath.mpf(((lo + hi) / 2).numerator) / ((lo + hi) / 2).denominator
        c1, c2 = info["sheared"]
        def at(cols, yv):
            return sum(mpmath.polyval([mpmath.mpf(int(v)) for v in reversed(col)] or [0], x0) * yv ** j
                       for j, col in enumerate(cols))
        ys = mpmath.polyroots([mpmath.polyval([mpmath.mpf(int(v)) for v in reversed(col)] or [0], x0)
                               for col in reversed(c1)], maxsteps=200, extraprec=200)
        y0 = mpmath.re(min(ys, key=lambda yv: abs(at(c2, yv))))
        out.append((x0 + u.numerator * y0 / u.denominator, y0))
    return out


def mpmath_abs(p, q):
    import mpmath
    return mpmath.sqrt((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2)


def check(poses, points, sliders, cert=None):
    """The certificate's verdict on a library answer: ('certified', ''),
    ('refuse', why) or ('cannot', why). By the library's contract a point
    beyond `1e4` task sizes (`BURMESTER_NEAR`) is known only within
    rounding of a slider: the points within `1e4` task sizes must match
    the exact near ones one to one (each within `1e-3 (size + d)` of its
    own, the exact point from the isolated root), and the total (finite
    listed + sliders) must be the exact total (real finite + real at
    infinity). Certified answers with a point over `1e-6 (size + d)` off
    are marked (`why` non-empty)."""
    try:
        nf, ns, info = cert if cert is not None else certify(poses)
    except CannotCertify as e:
        return "cannot", str(e)
    s, (cx, cy) = size_c(poses)
    exact_pts = points_of(info)
    near_roots = [float(((px - cx) ** 2 + (py - cy) ** 2) ** 0.5) <= 1e4 * s for px, py in exact_pts]
    listed_near = [(x, y) for x, y in points if math.hypot(x - cx, y - cy) <= 1e4 * s]
    # the closest two exact real points, relative to `size + d` (a cluster:
    # a count that the rounding of the task can change)
    sep = min((float(mpmath_abs(p, q) / (s + float(((p[0] - cx) ** 2 + (p[1] - cy) ** 2) ** 0.5)))
               for i, p in enumerate(exact_pts) for q in exact_pts[i + 1:]), default=math.inf)
    info["separation"] = sep
    if len(listed_near) != sum(near_roots):
        return "refuse", (f"near count: listed {len(listed_near)}, exact {sum(near_roots)} (total listed "
                          f"{len(points)}+{sliders}, exact {nf}+{ns}; closest exact pair {sep:.1e})")
    if len(points) + sliders != nf + ns:
        return "refuse", f"total count (far points or sliders): listed {len(points)}+{sliders}, exact {nf}+{ns}; closest exact pair {sep:.1e}"
    # maximal intervals: split at the midpoints between consecutive isolating intervals
    # Isolation: the near listed points matched one to one with the near
    # exact points (any of the at most 24 pairings), each within the
    # judge's `1e-3 (size + d)` of its own (a double point listed for two
    # exact points that nearly merge passes; a point with the right X and
    # a wrong y does not). The exact points are the isolated roots refined
    # exactly and their y from the two cubics (`points_of`).
    import itertools
    near_pts = [p for p, n in zip(exact_pts, near_roots) if n]
    best = math.inf
    for perm in itertools.permutations(range(len(near_pts))):
        worst = 0.0
        for (x, y), k in zip(listed_near, perm):
            px, py = near_pts[k]
            d = math.hypot(x - cx, y - cy)
            worst = max(worst, float(mpmath_abs((px, py), (x, y))) / (s + d))
        best = min(best, worst)
    if best > 1e-3:
        return "refuse", f"no pairing of the near listed points with the exact ones within 1e-3 (best {best:.1e})"
    # the judge's accuracy (reported, not a refusal)
    return "certified", "" if best <= 1e-6 else f"a listed point {best:.1e} of size + d off its exact point"


# ------------------------------------------------------------------ driver

def parse(path):
    import ast
    out = []
    name = None
    lines = open(path).read().splitlines()
    for i, line in enumerate(lines):
        if line.startswith("burmester_points: /"):
            name = line.split("burmester_points/")[-1].split()[0]
        elif name and (line.startswith("  task ") or line.startswith("  moved ")):
            frame, rest = line.strip().split(" ", 1)
            out.append((f"{name} {frame}", ast.literal_eval(rest), lines[i + 1].strip()))
    return out


def main():
    import ast
    import os
    from collections import Counter
    sys.path.insert(0, os.path.dirname(__file__))
    from balance_five import judge
    counts = Counter()
    for path in sys.argv[1:]:
        for label, poses, ans in parse(path):
            try:
                cls, detail = judge(poses, ans)
            except Exception as e:
                cls, detail = "ref-failed", repr(e)[:60]
            t0 = time.perf_counter()
            if ans.startswith("points"):
                pts = ast.literal_eval(ans.split(" sliders")[0][len("points "):])
                sl = int(ans.split(" sliders")[1])
                verdict, why = check(poses, pts, sl)
                if verdict == "certified" and why:
                    verdict = "certified*"  # certified, a point over 1e-6 off
            else:
                try:
                    nf, ns, _ = certify(poses)
                    verdict, why = "lib-refused", f"exact {nf}+{ns}"
                except CannotCertify as e:
                    verdict, why = "lib-refused", f"cannot: {e}"
            dt = time.perf_counter() - t0
            counts[(cls, verdict)] += 1
            print(f"{label}: judge {cls} [{detail}] cert {verdict} [{why}] {dt*1e3:.0f} ms")
            sys.stdout.flush()
    print("judge x certificate:")
    for k, v in sorted(counts.items()):
        print(f"  {k[0]:>10} {k[1]:>12}: {v}")


def crank_rocker_task(rng, k):
    """A designer task (`moderate_five.py`'s `known-near`, the same draws):
    a crank-rocker in mm, its coupler driven to five crank angles, two of
    them `10^-k` apart, moved and turned; `None` where it does not
    assemble."""
    import os

    sys.path.insert(0, os.path.dirname(__file__))
    from moderate_five import known

    task = known(rng, k)
    return None if task is None else task[0]


def random_main(kind, n, seed):
    """`--random N`: ordinary tasks (positions in a square of side 10,
    angles within 3 rad); `--designer N`: crank-rocker tasks, two crank
    angles 10^-k apart (k = 1..8). The library's answer (Python binding)
    certified; every answer the certificate refuses or cannot certify is
    judged by the mpmath reference (right answers refused are counted)."""
    import os
    import random
    from collections import Counter
    import burmester
    sys.path.insert(0, os.path.dirname(__file__))
    from balance_five import judge
    rng = random.Random(seed)
    counts = Counter()
    times = []
    bits = Counter()
    done = 0
    while done < n:
        if kind == "random":
            poses = [(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-1.5, 1.5)) for _ in range(5)]
            k = None
        else:
            k = 1 + done % 8
            poses = crank_rocker_task(rng, k)
            if poses is None:
                continue
        done += 1
        try:
            pts = [tuple(c) for c, _ in burmester.Task(poses).burmester_points()]
            lib = "points"
        except Exception as e:  # the library's refusal
            pts, lib = [], type(e).__name__
        t0 = time.perf_counter()
        if lib == "points":
            verdict, why = check(poses, pts, 0)
            if verdict == "certified" and why:
                verdict = "certified*"
        else:
            try:
                certify(poses)
                verdict, why = "lib-refused", ""
            except CannotCertify as e:
                verdict, why = "lib-refused", f"cannot: {e}"
        times.append(time.perf_counter() - t0)
        bits[("cubic", STATS.get("cubic_bits", 0) // 64 * 64)] += 1
        bits[("res", STATS.get("res_bits", 0) // 256 * 256)] += 1
        if verdict in ("refuse", "cannot", "certified*"):
            ans = f"points {pts} sliders 0"
            cls, detail = judge(poses, ans)
            print(f"k={k} {poses}: lib {lib} cert {verdict} [{why}] judge {cls} [{detail}]")
        else:
            cls = "unjudged"
        counts[(verdict, cls)] += 1
    times.sort()
    print(f"{kind}: {n} tasks; certificate time per task: median {times[len(times)//2]*1e3:.1f} ms, "
          f"p99 {times[int(len(times)*0.99)]*1e3:.1f} ms, max {times[-1]*1e3:.1f} ms")
    for key, v in sorted(counts.items()):
        print(f"  {key}: {v}")
    print("  bit lengths (cubic coefficients by 64, resultant by 256):", sorted(bits.items()))


if __name__ == "__main__":
    if sys.argv[1] in ("--random", "--designer"):
        random_main(sys.argv[1][2:], int(sys.argv[2]), int(sys.argv[3]) if len(sys.argv) > 3 else 1)
    else:
        main()
