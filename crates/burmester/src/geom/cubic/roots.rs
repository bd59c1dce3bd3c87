//! Real roots of polynomials of low degree and of binary forms.
//!
//! Polynomials are coefficient slices in ascending order,
//! `p(x) = p[0] + p[1] x + ... + p[n] x^n`. A **binary form** of degree `d`
//! is `F(wx, wy) = sum_i f[i] wx^(d - i) wy^i`; its real roots are
//! directions, returned as angles in `[0, pi)`.
//!
//! The roots of a polynomial on an interval are isolated by the roots of its
//! derivative (found the same way, recursively): between two consecutive
//! critical points the polynomial is monotone, so a sign change brackets
//! exactly one root, which bisection finds to the last bit. A critical point
//! where the value is within rounding of zero is reported as a (double)
//! root. No starting guesses, no random restarts.

use core::f64::consts::PI;

/// A value within this many machine epsilons of the magnitude of its terms
/// (`sum |p_i| |x|^i`) counts as zero.
const ZERO_FACTOR: f64 = crate::tolerance::ROOT_ZERO_EPS;

/// Horner evaluation of `p` at `x`.
#[inline]
pub(crate) fn eval(p: &[f64], x: f64) -> f64 {
    p.iter().rev().fold(0.0, |acc, &c| acc * x + c)
}

/// `sum |p_i| |x|^i`: a bound on the terms, the scale of the rounding error
/// of [`eval`].
#[inline]
pub(crate) fn magnitude(p: &[f64], x: f64) -> f64 {
    let ax = x.abs();
    p.iter().rev().fold(0.0, |acc, &c| acc * ax + c.abs())
}

fn derivative(p: &[f64]) -> Vec<f64> {
    (1..p.len()).map(|i| p[i] * i as f64).collect()
}

/// Whether `p(x)` is zero within rounding.
#[inline]
fn is_zero_at(p: &[f64], x: f64) -> bool {
    eval(p, x).abs() <= ZERO_FACTOR * f64::EPSILON * magnitude(p, x)
}

/// `p` without its leading zero coefficients, or `None` when there is no
/// root to look for in `[lo, hi]`: a constant, an empty (or NaN) interval,
/// a coefficient that is not finite.
fn trimmed(p: &[f64], lo: f64, hi: f64) -> Option<&[f64]> {
    let mut n = p.len();
    while n > 0 && p[n - 1] == 0.0 {
        n -= 1;
    }
    let p = &p[..n];
    (n > 1 && lo <= hi && p.iter().all(|c| c.is_finite())).then_some(p)
}

/// The real roots of `p` in `[lo, hi]`, sorted. A double root (a critical
/// point where `p` vanishes within rounding) is reported once.
pub(crate) fn roots_in(p: &[f64], lo: f64, hi: f64) -> Vec<f64> {
    let Some(p) = trimmed(p, lo, hi) else {
        return Vec::new();
    };
    let n = p.len();
    if n == 2 {
        let r = -p[0] / p[1];
        return if r >= lo && r <= hi {
            vec![r]
        } else {
            Vec::new()
        };
    }
    let crit = roots_in(&derivative(p), lo, hi);
    let mut knots = Vec::with_capacity(crit.len() + 2);
    knots.push(lo);
    knots.extend(crit.into_iter().filter(|&c| c > lo && c < hi));
    knots.push(hi);
    let mut roots = Vec::new();
    let zero: Vec<bool> = knots.iter().map(|&k| is_zero_at(p, k)).collect();
    for (k, &z) in knots.iter().zip(&zero) {
        if z {
            roots.push(*k);
        }
    }
    for i in 0..knots.len() - 1 {
        if zero[i] || zero[i + 1] {
            continue;
        }
        let (a, b) = (knots[i], knots[i + 1]);
        let (fa, fb) = (eval(p, a), eval(p, b));
        if (fa < 0.0) != (fb < 0.0) {
            roots.push(bisect(p, a, b, fa));
        }
    }
    roots.sort_by(f64::total_cmp);
    roots.dedup_by(|x, y| (*x - *y).abs() <= 4.0 * f64::EPSILON * x.abs().max(y.abs()));
    roots
}

/// The real roots in `[lo, hi]` of a function known as a polynomial `p`
/// and, more accurately, by `value(x) = (v, band)`: its value and the
/// rounding band of that value (zero within rounding where `|v| <= band`).
/// Sorted, each with its multiplicity (1 or 2). Between the critical points
/// of `p` the function is monotone (to rounding): a change of sign of `v`
/// between two of them is a simple root (found by bisection on `v`); a
/// critical point where `v` is zero within its band is a double root (two
/// roots that merge, or a pair of complex roots, within rounding). So the
/// count with multiplicity changes only where the data decide it. A root
/// within rounding of `lo` or `hi` is simple unless it is a critical point:
/// search a wider interval than the one wanted.
pub(crate) fn roots_in_mult(
    p: &[f64],
    lo: f64,
    hi: f64,
    value: &dyn Fn(f64) -> (f64, f64),
) -> Vec<(f64, usize)> {
    let Some(p) = trimmed(p, lo, hi) else {
        return Vec::new();
    };
    let crit = roots_in(&derivative(p), lo, hi);
    let mut knots = Vec::with_capacity(crit.len() + 2);
    knots.push((lo, false));
    knots.extend(
        crit.into_iter()
            .filter(|&c| c > lo && c < hi)
            .map(|c| (c, true)),
    );
    knots.push((hi, false));
    let vals: Vec<(f64, bool)> = knots
        .iter()
        .map(|&(k, _)| {
            let (v, band) = value(k);
            (v, v.abs() <= band)
        })
        .collect();
    let mut roots = Vec::new();
    for (&(k, critical), &(_, zero)) in knots.iter().zip(&vals) {
        if zero {
            roots.push((k, if critical { 2 } else { 1 }));
        }
    }
    for i in 0..knots.len() - 1 {
        let ((va, za), (vb, zb)) = (vals[i], vals[i + 1]);
        if za || zb || (va < 0.0) == (vb < 0.0) {
            continue;
        }
        // Bisection on the accurate value.
        let (mut a, mut b) = (knots[i].0, knots[i + 1].0);
        let mut fa = va;
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if !(m > a && m < b) {
                break;
            }
            let (v, _) = value(m);
            if v == 0.0 {
                a = m;
                b = m;
                break;
            }
            if (v < 0.0) == (fa < 0.0) {
                a = m;
                fa = v;
            } else {
                b = m;
            }
        }
        roots.push((0.5 * (a + b), 1));
    }
    roots.sort_by(|x, y| x.0.total_cmp(&y.0));
    roots.dedup_by(|x, y| (x.0 - y.0).abs() <= 4.0 * f64::EPSILON * x.0.abs().max(y.0.abs()));
    roots
}

/// The real roots of a binary form with their multiplicity, as angles in
/// `[0, pi)`, sorted, with its accurate value and rounding band at a
/// direction given by `value(wx, wy)` (see [`roots_in_mult`]). The two charts
/// of [`form_roots`], each searched beyond its half (`|u| <= 3/2`) so that
/// no root of the half lies at an end of the interval searched.
pub(crate) fn form_roots_mult(
    f: &[f64],
    value: &dyn Fn(f64, f64) -> (f64, f64),
) -> Vec<(f64, usize)> {
    if f.iter().all(|&c| c == 0.0) || f.iter().any(|c| !c.is_finite()) {
        return Vec::new();
    }
    let mut angles: Vec<(f64, usize)> = roots_in_mult(f, -1.5, 1.5, &|u| value(1.0, u))
        .into_iter()
        .filter(|(u, _)| u.abs() <= 1.0)
        .map(|(u, m)| (u.atan().rem_euclid(PI), m))
        .collect();
    let rev: Vec<f64> = f.iter().rev().copied().collect();
    angles.extend(
        roots_in_mult(&rev, -1.5, 1.5, &|v| value(v, 1.0))
            .into_iter()
            .filter(|(v, _)| v.abs() < 1.0)
            .map(|(v, m)| (1.0f64.atan2(v), m)),
    );
    angles.sort_by(|a, b| a.0.total_cmp(&b.0));
    angles.dedup_by(|x, y| (x.0 - y.0).abs() <= 1e-13);
    if angles.len() > 1 && angles[0].0 + PI - angles[angles.len() - 1].0 <= 1e-13 {
        angles.pop();
    }
    angles
}

/// `p(x)` and `p'(x)` by Horner's scheme.
#[inline]
fn eval_with_slope(p: &[f64], x: f64) -> (f64, f64) {
    let mut v = 0.0;
    let mut d = 0.0;
    for &c in p.iter().rev() {
        d = d * x + v;
        v = v * x + c;
    }
    (v, d)
}

/// The root of `p` in `[a, b]`, where `p(a)` (= `fa`) and `p(b)` have
/// opposite signs and `p` is monotone: Newton's method kept inside the
/// bracket (a step that leaves it, or does not halve the last one, is a
/// bisection instead), until the bracket is a few ulps wide or a Newton
/// step is below rounding. As sure as bisection, to the last bits, in a
/// handful of steps instead of fifty to a thousand.
fn bisect(p: &[f64], mut a: f64, mut b: f64, mut fa: f64) -> f64 {
    let mut x = 0.5 * (a + b);
    let mut last_step = b - a;
    for _ in 0..2200 {
        let (fx, dx) = eval_with_slope(p, x);
        if fx == 0.0 {
            return x;
        }
        if (fx < 0.0) == (fa < 0.0) {
            a = x;
            fa = fx;
        } else {
            b = x;
        }
        let width = b - a;
        if width <= 4.0 * f64::EPSILON * a.abs().max(b.abs()) || !(width > 0.0) {
            break;
        }
        let newton = x - fx / dx;
        let step = (newton - x).abs();
        if newton > a && newton < b && step <= 0.5 * last_step {
            if step <= f64::EPSILON * x.abs() || step == 0.0 {
                return newton;
            }
            last_step = step;
            x = newton;
        } else {
            let m = 0.5 * (a + b);
            if m <= a || m >= b {
                break;
            }
            last_step = width;
            x = m;
        }
    }
    if eval(p, a).abs() <= eval(p, b).abs() {
        a
    } else {
        b
    }
}

/// All real roots of `p` on the real line, sorted: the roots in `[-1, 1]`
/// and the reciprocals of the roots of the reversed polynomial in
/// `[-1, 1]`, so that no bound on the roots is needed.
pub(crate) fn real_roots(p: &[f64]) -> Vec<f64> {
    let mut n = p.len();
    while n > 0 && p[n - 1] == 0.0 {
        n -= 1;
    }
    let p = &p[..n];
    let mut roots = roots_in(p, -1.0, 1.0);
    let rev: Vec<f64> = p.iter().rev().copied().collect();
    for u in roots_in(&rev, -1.0, 1.0) {
        if u != 0.0 {
            let t = 1.0 / u;
            if t.abs() > 1.0 && t.is_finite() {
                roots.push(t);
            }
        }
    }
    roots.sort_by(f64::total_cmp);
    roots.dedup_by(|x, y| (*x - *y).abs() <= 4.0 * f64::EPSILON * x.abs().max(y.abs()));
    roots
}

/// The real roots of `a t^2 + b t + c`, sorted; a discriminant within
/// rounding of zero gives one double root, a negligible `a` the linear root.
pub(crate) fn quadratic_roots(a: f64, b: f64, c: f64) -> Vec<f64> {
    let size = a.abs().max(b.abs()).max(c.abs());
    if !(size > 0.0) || !size.is_finite() {
        return Vec::new();
    }
    let (a, b, c) = (a / size, b / size, c / size);
    if a == 0.0 {
        return if b == 0.0 { Vec::new() } else { vec![-c / b] };
    }
    let disc = b * b - 4.0 * a * c;
    let tol = 8.0 * f64::EPSILON * (b * b + 4.0 * (a * c).abs());
    if disc < -tol {
        return Vec::new();
    }
    if disc <= tol {
        return vec![-b / (2.0 * a)];
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    let mut r = vec![q / a];
    if q != 0.0 {
        r.push(c / q);
    }
    r.retain(|v| v.is_finite());
    r.sort_by(f64::total_cmp);
    r
}

/// The value of the binary form `f` at `(wx, wy)`.
pub(crate) fn form_eval(f: &[f64], wx: f64, wy: f64) -> f64 {
    let d = f.len().saturating_sub(1);
    let mut acc = 0.0;
    let mut py = 1.0;
    for (i, &c) in f.iter().enumerate() {
        acc += c * wx.powi((d - i) as i32) * py;
        py *= wy;
    }
    acc
}

/// The product of two binary forms.
pub(crate) fn form_mul(a: &[f64], b: &[f64]) -> Vec<f64> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![0.0; a.len() + b.len() - 1];
    for (i, &x) in a.iter().enumerate() {
        for (j, &y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

/// `a - b` for two binary forms of one degree.
pub(crate) fn form_sub(a: &[f64], b: &[f64]) -> Vec<f64> {
    a.iter().zip(b).map(|(x, y)| x - y).collect()
}

/// The real roots of a binary form, as angles in `[0, pi)`, sorted. Empty
/// for a form that vanishes identically.
///
/// Two charts: `w = (1, u)` for `|u| <= 1` and `w = (v, 1)` for `|v| < 1`,
/// so that every root is found on a bounded interval.
pub(crate) fn form_roots(f: &[f64]) -> Vec<f64> {
    if f.iter().all(|&c| c == 0.0) || f.iter().any(|c| !c.is_finite()) {
        return Vec::new();
    }
    let mut angles: Vec<f64> = roots_in(f, -1.0, 1.0)
        .into_iter()
        .map(|u| u.atan().rem_euclid(PI))
        .collect();
    let rev: Vec<f64> = f.iter().rev().copied().collect();
    angles.extend(
        roots_in(&rev, -1.0, 1.0)
            .into_iter()
            .filter(|v| v.abs() < 1.0)
            .map(|v| 1.0f64.atan2(v)),
    );
    angles.sort_by(f64::total_cmp);
    angles.dedup_by(|x, y| (*x - *y).abs() <= 1e-13);
    if angles.len() > 1 && angles[0] + PI - angles[angles.len() - 1] <= 1e-13 {
        angles.pop();
    }
    angles
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_of_products() {
        // (x - 0.3)(x + 0.7)(x - 0.31)
        let p = form_mul(&form_mul(&[-0.3, 1.0], &[0.7, 1.0]), &[-0.31, 1.0]);
        let r = roots_in(&p, -1.0, 1.0);
        assert_eq!(r.len(), 3);
        for (a, b) in r.iter().zip([-0.7, 0.3, 0.31]) {
            assert!((a - b).abs() < 1e-14, "{r:?}");
        }
        // Roots far out: (x - 1e6)(x + 3)
        let r = real_roots(&form_mul(&[-1e6, 1.0], &[3.0, 1.0]));
        assert_eq!(r.len(), 2);
        assert!((r[0] + 3.0).abs() < 1e-12 && (r[1] / 1e6 - 1.0).abs() < 1e-14);
        // A double root is reported once.
        let r = real_roots(&form_mul(&[-0.5, 1.0], &[-0.5, 1.0]));
        assert_eq!(r.len(), 1);
        assert!((r[0] - 0.5).abs() < 1e-7);
        assert!(real_roots(&[1.0, 0.0, 1.0]).is_empty());
        assert_eq!(quadratic_roots(0.0, 2.0, -1.0), vec![0.5]);
        assert!(quadratic_roots(1.0, 0.0, 1.0).is_empty());
    }

    #[test]
    fn form_roots_cover_both_charts() {
        // Directions 0.2, 1.3 and 2.9 rad: product of cross(d_k, w).
        let f = [0.2f64, 1.3, 2.9]
            .iter()
            .map(|a| vec![-a.sin(), a.cos()])
            .fold(vec![1.0], |acc, l| form_mul(&acc, &l));
        let r = form_roots(&f);
        assert_eq!(r.len(), 3, "{r:?}");
        for (a, b) in r.iter().zip([0.2, 1.3, 2.9]) {
            assert!((a - b).abs() < 1e-13, "{r:?}");
        }
        // A root exactly on the chart boundary and one vertical.
        let f = form_mul(&[-1.0, 1.0], &[1.0, 0.0]);
        let r = form_roots(&f);
        assert_eq!(r.len(), 2, "{r:?}");
        assert!((r[0] - PI / 4.0).abs() < 1e-15 && (r[1] - PI / 2.0).abs() < 1e-15);
        assert!((form_eval(&[1.0, 2.0, 3.0], 2.0, 1.0) - 11.0).abs() < 1e-15);
    }
}
