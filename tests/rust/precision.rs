//! The `conic` classifier against an exact evaluation (rational arithmetic)
//! of the closed form, on points near the curves.
//!
//! # The reference
//!
//! For a task and a driven dyad, the transformed Filemon curve of the line
//! through `C1` with direction `d` is, in the task's local frame (origin
//! `P12`, unit `Task::scale`),
//!
//! ```text
//! g(y) = cross(d, u) kappa - cross(d, c1) den,   u = R(-theta12/2) y,
//! v = R(-theta13/2) (y - q13),  den = cross(u, v),  kappa = cross(q13, v)
//! ```
//!
//! The reference evaluates this exactly (num-rational's `BigRational`) from
//! the same double parameters the library starts from (the half-angle cosines
//! and sines, `q13`, the local `C1`, `d`) at the exact local coordinates of
//! the double point `Y`. So it sees every rounding the library makes after
//! those parameters: the conic's coefficients, the local coordinates of `Y`,
//! and the evaluation.
//!
//! # The band
//!
//! Points are put on a curve (`Conic::intersect_line`) and stepped off it
//! along the normal by `delta` task sizes, `delta` from `1e-16` to `1e-6`,
//! both ways. The stated band (README, `Filemon::classify`) is:
//!
//! ```text
//! |Y - P12| <= R task sizes, distance from the curve >= 1e-13 (1 + R)^2 task sizes
//!     => the f64 sign of each conic is the exact sign
//! ```
//!
//! This test checks it on random tasks (R up to 10); it also records the
//! largest `delta` at which a sign differed (about `1e-15 (1 + R)^2` in the
//! runs made so far; the band has a margin of about 100 over it).

use burmester::{Conic, Filemon, Line, Point2, Task, Vector2};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
mod common;

use common::filemon;
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;

/// The poles `[P12, P13, P23]` of a three-pose task.
fn poles(t: &Task) -> [Point2<f64>; 3] {
    t.cremona().unwrap().poles()
}

/// The stated band, in task sizes, for a point `r` task sizes from `P12`.
fn band(r: f64) -> f64 {
    1e-13 * (1.0 + r) * (1.0 + r)
}

fn q(v: f64) -> BigRational {
    BigRational::from_float(v).expect("finite")
}

type V = (BigRational, BigRational);

fn cross(a: &V, b: &V) -> BigRational {
    &a.0 * &b.1 - &a.1 * &b.0
}

/// `R(-alpha) w` with `(c, s) = (cos alpha, sin alpha)`.
fn rot_neg(c: &BigRational, s: &BigRational, w: &V) -> V {
    (c * &w.0 + s * &w.1, c * &w.1 - s * &w.0)
}

/// A random construction, its task, its exact reference, the task's scale
/// and the construction's Filemon lines and conics.
fn case(runner: &mut TestRunner) -> (Filemon, Task, Exact, f64, [Line; 2], [Conic; 2]) {
    let f = filemon(runner, 8.0);
    let t = *f.task();
    let ex = Exact::new(&t, &f);
    let (lines, conics) = (f.lines().unwrap(), f.conics().unwrap());
    (f, t, ex, t.scale(), lines, conics)
}

/// The closed form's parameters, exactly as doubles.
struct Exact {
    origin: Point2<f64>,
    scale: f64,
    h12: (BigRational, BigRational),
    h13: (BigRational, BigRational),
    q13: V,
    c1: V,
}

impl Exact {
    fn new(t: &Task, f: &Filemon) -> Self {
        let r = t.rotations();
        let (t12, t13) = (r[0], r[1]);
        let half = |a: f64| {
            let (s, c) = (0.5 * a).sin_cos();
            (q(c), q(s))
        };
        let [origin, p13, _] = poles(t);
        let scale = t.scale();
        let p13 = (p13 - origin) / scale;
        let c1 = (f.driven_circle() - origin) / scale;
        Exact {
            origin,
            scale,
            h12: half(t12),
            h13: half(t13),
            q13: (q(p13.x), q(p13.y)),
            c1: (q(c1.x), q(c1.y)),
        }
    }

    /// The exact sign of `g` for direction `d` at the double point `p`.
    fn sign(&self, d: Vector2<f64>, p: Point2<f64>) -> i8 {
        let s = q(self.scale);
        let y = (
            (q(p.x) - q(self.origin.x)) / &s,
            (q(p.y) - q(self.origin.y)) / &s,
        );
        let d = (q(d.x), q(d.y));
        let u = rot_neg(&self.h12.0, &self.h12.1, &y);
        let w = (&y.0 - &self.q13.0, &y.1 - &self.q13.1);
        let v = rot_neg(&self.h13.0, &self.h13.1, &w);
        let den = cross(&u, &v);
        let kappa = cross(&self.q13, &v);
        let g = cross(&d, &u) * kappa - cross(&d, &self.c1) * den;
        if g.is_zero() {
            0
        } else if g.is_positive() {
            1
        } else {
            -1
        }
    }
}

fn side(c: &Conic, p: Point2<f64>) -> i8 {
    c.side(p)
}

/// The conic sign agrees with the exact sign outside the band, on points
/// stepped off the curves; the largest disagreeing step is recorded.
#[test]
fn conic_signs_match_the_exact_closed_form_outside_the_band() {
    let mut runner = TestRunner::deterministic();
    let mut worst = 0.0f64; // largest delta / (1 + R)^2 with a wrong sign
    let mut checked = 0usize;
    let mut wrong_inside = 0usize;
    for _ in 0..24 {
        let (_, t, ex, s, [la, lb], [ga, gb]) = case(&mut runner);
        for (line, g) in [(la, ga), (lb, gb)] {
            for k in 0..12 {
                // A line through a point near the poles, in some direction.
                let a = k as f64 * 0.9;
                let base = poles(&t)[k % 3] + Vector2::new(a.sin(), a.cos()) * (0.7 * s);
                let probe = Line {
                    point: base,
                    direction: Vector2::new(a.cos(), a.sin()),
                };
                for p0 in g.intersect_line(&probe) {
                    let r = (p0 - poles(&t)[0]).norm() / s;
                    if r > 10.0 {
                        continue;
                    }
                    let n = g.gradient(p0).normalize();
                    for e in 0..=20 {
                        let delta = 10f64.powf(-16.0 + 0.5 * e as f64);
                        for sg in [1.0, -1.0] {
                            let p = p0 + n * (sg * delta * s);
                            let exact = ex.sign(line.direction, p);
                            let got = side(&g, p);
                            checked += 1;
                            if exact != got {
                                worst = worst.max(delta / ((1.0 + r) * (1.0 + r)));
                                assert!(
                                    delta < band(r),
                                    "sign differs {delta} task sizes off the curve at {p} \
                                     (R = {r}): exact {exact}, f64 {got}"
                                );
                                wrong_inside += 1;
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(checked > 10_000, "{checked}");
    // The band is not vacuous: rounding does flip signs inside it.
    assert!(wrong_inside > 0);
    println!(
        "checked {checked} points; {wrong_inside} wrong signs, all within the band; \
         the largest at {worst:e} (1 + R)^2 task sizes (band: 1e-13 (1 + R)^2)"
    );
}

/// `classify(conic)` agrees with the exact classification (from the exact
/// signs of the two conics) at random points outside the band of both
/// curves and away from the special points.
#[test]
fn classify_matches_the_exact_classification_at_random_points() {
    use burmester::{Branch, Method};
    let mut runner = TestRunner::deterministic();
    let mut checked = 0;
    for _ in 0..30 {
        let (f, t, ex, s, [la, lb], [ga, gb]) = case(&mut runner);
        for _ in 0..100 {
            let (x, y) = (-8.0f64..8.0, -8.0f64..8.0)
                .new_tree(&mut runner)
                .unwrap()
                .current();
            let p = Point2::new(x, y);
            let r = (p - poles(&t)[0]).norm() / s;
            let d = ga.distance_estimate(p).min(gb.distance_estimate(p)) / s;
            if d < 10.0 * band(r) {
                continue;
            }
            let (sa, sb) = (ex.sign(la.direction, p), ex.sign(lb.direction, p));
            let want = if sa == sb {
                Branch::Free
            } else {
                Branch::Defective
            };
            assert_eq!(f.classify(p, Method::Conic).unwrap(), want, "at {p}");
            checked += 1;
        }
    }
    assert!(checked > 2000, "{checked}");
}

#[test]
fn the_exact_reference_vanishes_at_the_known_points() {
    let mut runner = TestRunner::deterministic();
    for _ in 0..10 {
        let f = filemon(&mut runner, 8.0);
        let t = *f.task();
        let ex = Exact::new(&t, &f);
        let [la, _] = f.lines().unwrap();
        // P12 is the local origin: g(0) = 0 exactly.
        assert_eq!(ex.sign(la.direction, poles(&t)[0]), 0);
        // And the reference has the sign of the library far from the curves.
        let g = f.conics().unwrap()[0];
        let p = poles(&t)[0] + Vector2::new(3.0, 1.0) * t.scale();
        if g.distance_estimate(p) > 1e-3 * t.scale() {
            assert_eq!(ex.sign(la.direction, p), g.side(p));
        }
    }
    let _ = BigInt::from(0); // (num-bigint backs BigRational)
}
