//! The refinement's Nelder–Mead: the steps of `argmin`'s `NelderMead`
//! (0.11) under its `Executor`, the same arithmetic in the same order, on
//! points of at most [`MAX_DIM`] coordinates kept in place.
//!
//! The search refines tens of starts of thousands of iterations each; in
//! `argmin`'s executor every iteration allocated its trial points
//! (`Vec` arithmetic), formatted its action into a key-value log and
//! counted each cost evaluation in a hash map, a quarter of the whole
//! refinement's time, measured with `perf` on the `design` bench. Here a
//! step allocates nothing. The sequence of points judged, and so every
//! design, is the one `argmin` gave (the search's tests and bench compare
//! against the same brute force as before).

/// The most coordinates of a point: four (both fixed pivots), two (the
/// curve parameters of four poses).
pub(super) const MAX_DIM: usize = 4;

/// A point of the simplex (its first `dim` coordinates used).
pub(super) type Point = [f64; MAX_DIM];

/// Nelder–Mead's coefficients adapted to the dimension `dim`: reflection
/// 1, expansion `1 + 2 / dim`, contraction 1/2, shrink `1 - 1 / dim` (Gao
/// and Han, 2012; their contraction, above the classic bound of 1/2 for
/// `dim > 2`, is left at 1/2).
pub(super) fn coefficients(dim: usize) -> [f64; 4] {
    let n = dim as f64;
    [1.0, 1.0 + 2.0 / n, 0.5, 1.0 - 1.0 / n]
}

/// How a run of [`minimize`] ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum End {
    /// The simplex's costs have a sample standard deviation under the
    /// tolerance, or the iterations are spent, or `stop` said so.
    Done,
    /// A cost was not comparable (NaN), where `argmin` reports a
    /// potential bug and gives no result.
    Failed,
}

/// Minimises `cost` from the simplex `start` (`dim + 1` points), with the
/// [`coefficients`] of `dim`, for at most `max_iters` iterations, ending early when the sample standard
/// deviation of the simplex's costs is under `sd_tolerance` or `stop()`
/// (checked before each iteration) is true.
pub(super) fn minimize(
    start: &[Point],
    dim: usize,
    sd_tolerance: f64,
    max_iters: usize,
    mut cost: impl FnMut(&Point) -> f64,
    stop: impl Fn() -> bool,
) -> End {
    let n = start.len();
    debug_assert!(n == dim + 1 && dim <= MAX_DIM);
    let [alpha, gamma, rho, sigma] = coefficients(dim);
    let mut s: [(Point, f64); MAX_DIM + 1] = [([0.0; MAX_DIM], f64::NAN); MAX_DIM + 1];
    for (slot, p) in s.iter_mut().zip(start) {
        *slot = (*p, cost(p));
    }
    let s = &mut s[..n];
    sort(s);
    // x0 + (a - b) * f, coordinate by coordinate (argmin's `Vec` arithmetic).
    let step = |x0: &Point, a: &Point, b: &Point, f: f64| -> Point {
        let mut out = [0.0; MAX_DIM];
        for i in 0..dim {
            out[i] = x0[i] + (a[i] - b[i]) * f;
        }
        out
    };
    for _ in 0..max_iters {
        if sd(s) < sd_tolerance || stop() {
            return End::Done;
        }
        // The centroid of all but the worst: summed from the best, then
        // scaled by 1 / dim.
        let mut x0 = s[0].0;
        for p in &s[1..n - 1] {
            for (c, v) in x0[..dim].iter_mut().zip(&p.0) {
                *c += v;
            }
        }
        let inv = 1.0 / (n - 1) as f64;
        for v in &mut x0[..dim] {
            *v *= inv;
        }
        let (best, second_worst, worst) = (s[0].1, s[n - 2].1, s[n - 1]);
        let xr = step(&x0, &x0, &worst.0, alpha);
        let xr_cost = cost(&xr);
        let last = n - 1;
        if xr_cost < second_worst && xr_cost >= best {
            s[last] = (xr, xr_cost);
        } else if xr_cost < best {
            let xe = step(&x0, &xr, &x0, gamma);
            let xe_cost = cost(&xe);
            s[last] = if xe_cost < xr_cost {
                (xe, xe_cost)
            } else {
                (xr, xr_cost)
            };
        } else if xr_cost >= second_worst {
            // Outside (towards the reflection) or inside (towards the
            // worst); kept if no worse than what it contracts, else a
            // shrink.
            let (xc, keep) = if xr_cost < worst.1 {
                let xc = step(&x0, &xr, &x0, rho);
                let c = cost(&xc);
                ((xc, c), c <= xr_cost)
            } else {
                let xc = step(&x0, &worst.0, &x0, rho);
                let c = cost(&xc);
                ((xc, c), c < worst.1)
            };
            if keep {
                s[last] = xc;
            } else {
                shrink(s, dim, sigma, &mut cost);
            }
        } else {
            return End::Failed;
        }
        sort(s);
    }
    // argmin checks the tolerance once more before it stops at the
    // iteration limit; either way the run ends here.
    End::Done
}

/// Moves every point but the best towards it by `sigma`, judging each.
fn shrink(s: &mut [(Point, f64)], dim: usize, sigma: f64, cost: &mut impl FnMut(&Point) -> f64) {
    let x0 = s[0].0;
    for (p, c) in &mut s[1..] {
        for i in 0..dim {
            p[i] = x0[i] + (p[i] - x0[i]) * sigma;
        }
        *c = cost(p);
    }
}

/// Best first (stable; incomparable costs keep their order).
fn sort(s: &mut [(Point, f64)]) {
    s.sort_by(|a, b| a.1.partial_cmp(&b.1).unwrap_or(core::cmp::Ordering::Equal));
}

/// The sample standard deviation of the simplex's costs.
fn sd(s: &[(Point, f64)]) -> f64 {
    let n = s.len() as f64;
    let mean: f64 = s.iter().map(|(_, c)| *c).sum::<f64>() / n;
    (1.0 / (n - 1.0) * s.iter().map(|(_, c)| (*c - mean).powi(2)).sum::<f64>()).sqrt()
}

#[cfg(test)]
mod tests {
    use core::cell::RefCell;

    use argmin::core::{CostFunction, Error, Executor};
    use argmin::solver::neldermead::NelderMead;

    use super::*;

    /// A valley with a wall (a barrier like the refinement's), a kink
    /// and a plateau: every branch of a step is taken.
    fn f(x: &[f64]) -> f64 {
        if x[0] > 1.3 {
            return 1e300;
        }
        let mut c = 0.0;
        for w in x.windows(2) {
            c += 100.0 * (w[1] - w[0] * w[0]).powi(2) + (1.0 - w[0]).powi(2);
        }
        c + 0.1 * x.iter().map(|v| v.abs()).sum::<f64>()
    }

    /// Records every point judged.
    struct Recorded(RefCell<Vec<Vec<f64>>>);

    impl CostFunction for Recorded {
        type Param = Vec<f64>;
        type Output = f64;
        fn cost(&self, x: &Vec<f64>) -> Result<f64, Error> {
            self.0.borrow_mut().push(x.clone());
            Ok(f(x))
        }
    }

    /// The same points judged, bit for bit, as `argmin`'s `NelderMead`
    /// under its `Executor`, in two and four dimensions, ending at the
    /// iteration limit and at the tolerance.
    #[test]
    fn steps_are_argmins() {
        // (40 iterations from (-1.2, -0.9) end at the limit, far from the
        // valley's floor; the others at the tolerance or the limit.)
        for (dim, iters, tol) in [
            (2, 40, 1e-13),
            (2, 3000, 1e-13),
            (4, 2000, 1e-13),
            (4, 5000, 1e-6),
        ] {
            let [_, gamma, _, sigma] = coefficients(dim);
            let x0: Vec<f64> = (0..dim).map(|i| -1.2 + 0.3 * i as f64).collect();
            let mut start = vec![x0.clone()];
            for i in 0..dim {
                let mut v = x0.clone();
                v[i] += 0.4;
                start.push(v);
            }
            let solver = NelderMead::new(start.clone())
                .with_sd_tolerance(tol)
                .and_then(|s| s.with_gamma(gamma))
                .and_then(|s| s.with_sigma(sigma))
                .unwrap();
            let theirs = Executor::new(Recorded(RefCell::new(Vec::new())), solver)
                .configure(|s| s.max_iters(iters))
                .timer(false)
                .run()
                .unwrap()
                .problem
                .take_problem()
                .unwrap()
                .0
                .into_inner();
            let pts: Vec<Point> = start
                .iter()
                .map(|v| {
                    let mut p = [0.0; MAX_DIM];
                    p[..dim].copy_from_slice(v);
                    p
                })
                .collect();
            let mut ours = Vec::new();
            let end = minimize(
                &pts,
                dim,
                tol,
                iters as usize,
                |p| {
                    ours.push(p[..dim].to_vec());
                    f(&p[..dim])
                },
                || false,
            );
            assert_eq!(end, End::Done);
            assert_eq!(ours.len(), theirs.len(), "{dim}: evaluations");
            for (a, b) in ours.iter().zip(&theirs) {
                let same = a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits());
                assert!(same, "{dim}: {a:?} != {b:?}");
            }
        }
    }
}
