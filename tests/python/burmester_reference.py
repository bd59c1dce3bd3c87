"""An independent reference for the Burmester points of five poses (issue
24): exact elimination in rational arithmetic (sympy) of the two
center-point cubics of poses 1-2-3-4 and 1-2-3-5, roots to 40 digits
(mpmath), every complex common point, the poles P12, P13, P23 taken out,
and the points at infinity counted by Bezout. Nothing of the library is
used: the cosines and sines of the angle differences are taken to 60
digits and made exact rationals, so the task is the float task to 1e-55.

``reference(poses)`` returns ``(finite, at_infinity)``: the four-minus-
``at_infinity`` Burmester centers as complex pairs ``(x, y)`` (mpmath
numbers; a real point has both imaginary parts at rounding of 40 digits)
and how many Burmester points are at infinity (sliders). ``None`` when the
two cubics share a component (not isolated)."""

import mpmath
import sympy as sp

mpmath.mp.dps = 60


def _rat(v):
    """An mpmath or float number as an exact rational."""
    return sp.Rational(mpmath.nstr(mpmath.mpf(v), 60, min_fixed=-1000, max_fixed=1000))


def _exact(v):
    """A float as the exact rational it is."""
    return sp.Rational(*float(v).as_integer_ratio())


def _mp(c):
    """A sympy rational as an mpmath number."""
    c = sp.Rational(c)
    return mpmath.mpf(c.p) / c.q


def _displacements(poses):
    """Each pose ``k >= 2``'s displacement from pose 1, exact: the rotation's
    ``(cos, sin)`` (the angle difference's, to 60 digits, as rationals) and
    the translation ``t_k = p_k - R_k p_1``, as ``(c, s, tx, ty)``."""
    p1 = (_exact(poses[0][0]), _exact(poses[0][1]))
    out = []
    for px, py, a in poses[1:]:
        d = mpmath.mpf(a) - mpmath.mpf(poses[0][2])
        c, s = _rat(mpmath.cos(d)), _rat(mpmath.sin(d))
        pk = (_exact(px), _exact(py))
        out.append((c, s, pk[0] - (c * p1[0] - s * p1[1]), pk[1] - (s * p1[0] + c * p1[1])))
    return out


def _rows(poses, x, y):
    """The rows ``(a_k . G-linear, b_k)`` of the dyad condition as sympy
    polynomials in the center ``G = (x, y)``: for each pose k >= 2,
    ``a_k(G) . z = b_k(G)`` with ``a_k(G) = conj(R_k) t_k + (1 - conj(R_k)) G``
    and ``b_k(G) = t_k . G - |t_k|^2 / 2``."""
    rows = []
    for c, s, tx, ty in _displacements(poses):
        # conj(R_k) t_k
        ckx, cky = c * tx + s * ty, -s * tx + c * ty
        mr, mi = 1 - c, s  # 1 - conj(R_k) = (1 - c) + i s
        ax = ckx + mr * x - mi * y
        ay = cky + mi * x + mr * y
        b = tx * x + ty * y - (tx * tx + ty * ty) / 2
        rows.append((ax, ay, b))
    return rows


def _det3(r1, r2, r3):
    return sp.expand(
        r1[0] * (r2[1] * r3[2] - r3[1] * r2[2])
        - r1[1] * (r2[0] * r3[2] - r3[0] * r2[2])
        + r1[2] * (r2[0] * r3[1] - r3[0] * r2[1])
    )


def _poles(poses):
    """The finite poles P12, P13, P23 (complex pairs), exact to 60 digits."""
    out = []
    for j, k in [(0, 1), (0, 2), (1, 2)]:
        xj, yj, aj = (mpmath.mpf(v) for v in poses[j])
        xk, yk, ak = (mpmath.mpf(v) for v in poses[k])
        th = ak - aj
        s = mpmath.sin(th / 2)
        if s == 0:
            continue
        cot = mpmath.cos(th / 2) / s
        mx, my = (xj + xk) / 2, (yj + yk) / 2
        hx, hy = (xk - xj) / 2, (yk - yj) / 2
        out.append((mx - hy * cot, my + hx * cot))
    return out


def reference(poses):
    x, y = sp.symbols("x y")
    r = _rows(poses, x, y)
    f1 = sp.Poly(_det3(r[0], r[1], r[2]), x, y)
    f2 = sp.Poly(_det3(r[0], r[1], r[3]), x, y)
    g = sp.gcd(f1, f2)
    if g.total_degree() > 0:
        return None
    # A generic shear so that no two common points share an x.
    u = sp.Rational(3, 7)
    X, Y = sp.symbols("X Y")
    s1 = sp.Poly(f1.as_expr().subs({x: X + u * Y, y: Y}), X, Y)
    s2 = sp.Poly(f2.as_expr().subs({x: X + u * Y, y: Y}), X, Y)
    res = sp.Poly(sp.resultant(s1.as_expr(), s2.as_expr(), Y), X)
    coeffs = [_mp(c) for c in res.all_coeffs()]
    roots = mpmath.polyroots(coeffs, maxsteps=500, extraprec=400) if len(coeffs) > 1 else []
    # The first curve as a cubic in Y with coefficients polynomials in X.
    in_y = [[_mp(k) for k in sp.Poly(c, X).all_coeffs()] for c in sp.Poly(s1.as_expr(), Y).all_coeffs()]
    terms = [(m, _mp(c)) for m, c in zip(s2.monoms(), s2.coeffs())]

    def second(xv, yv):
        return abs(sum(c * xv ** m[0] * yv ** m[1] for m, c in terms))

    common = []
    for x0 in roots:
        cs = [mpmath.polyval(c, x0) for c in in_y]
        while len(cs) > 1 and cs[0] == 0:
            cs.pop(0)
        ys = mpmath.polyroots(cs, maxsteps=500, extraprec=400) if len(cs) > 1 else []
        if not ys:
            continue
        best = min(ys, key=lambda yv: second(x0, yv))
        common.append((x0 + u * best, best))
    # Take out the poles P12, P13, P23.
    for p in _poles(poses):
        if not common:
            break
        k = min(range(len(common)), key=lambda i: abs(common[i][0] - p[0]) + abs(common[i][1] - p[1]))
        common.pop(k)
    # Bezout: 9 = 2 circular points + 3 poles + 4 Burmester points.
    at_infinity = 4 - len(common)
    return common, at_infinity


def real_points(poses, rel=1e-25):
    """The real finite Burmester centers (floats) and the count of points
    at infinity; complex pairs are left out."""
    ref = reference(poses)
    if ref is None:
        return None
    common, inf = ref
    out = []
    for cx, cy in common:
        size = 1 + abs(cx) + abs(cy)
        if abs(mpmath.im(cx)) <= rel * size and abs(mpmath.im(cy)) <= rel * size:
            out.append((float(mpmath.re(cx)), float(mpmath.re(cy))))
    return out, inf
