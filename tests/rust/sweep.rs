//! The dense grid branch sweep: the fast run-based `conic` kernel against
//! the point-by-point kernel and `Filemon::classify` (bit for bit), and the
//! three methods against each other away from the curves.

use std::f64::consts::PI;

mod common;

use burmester::{Control, Grid, Method, Point2, Pose, Task};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;

#[test]
fn grid_convention_and_errors() {
    let g = Grid::from_bounds(-1.0, 3.0, 10.0, 12.0, 4, 2).unwrap();
    assert_eq!(g.len(), 8);
    assert_eq!(g.x(0), -0.5);
    assert_eq!(g.x(3), 2.5);
    assert_eq!(g.y(0), 10.5);
    assert_eq!(g.y(1), 11.5);
    assert!(Grid::from_bounds(0.0, 1.0, 0.0, 1.0, 0, 4).is_err());
    assert!(Grid::from_bounds(1.0, 0.0, 0.0, 1.0, 4, 4).is_err());
    assert!(Grid::from_bounds(0.0, f64::NAN, 0.0, 1.0, 4, 4).is_err());
    assert!(Grid::from_bounds(0.0, 1.0, 0.0, 1.0, 1 << 20, 1 << 20).is_err());
    let t = Task::from_xya(&[[0.0, 0.0, 0.0], [2.0, 0.5, 0.4], [3.0, 2.0, 1.1]]).unwrap();
    let f = t.filemon(Point2::new(4.0, -1.0)).unwrap();
    let mut short = vec![false; 7];
    assert!(
        f.branch_map_into(&g, Method::Conic, &mut short, &Control::new())
            .is_err()
    );
    let mut shortf = vec![0.0f32; 9];
    assert!(f.margin_map_into(&g, &mut shortf, &Control::new()).is_err());
    // Row-major, row j for y_j.
    let g = Grid::from_bounds(-8.0, 8.0, -8.0, 8.0, 37, 23).unwrap();
    let m = f.branch_map(&g, Method::Conic);
    for j in 0..23 {
        for i in 0..37 {
            let want = f.is_branch_free(g.point(i, j), Method::Conic).unwrap();
            assert_eq!(m[j * 37 + i], want, "({i}, {j})");
        }
    }
}

/// The run-based kernel gives exactly the point-by-point answers, and
/// exactly `classify` at the grid points, on rows of 4096 samples: nothing
/// drifts along a row.
#[test]
fn runs_match_pointwise_bit_for_bit_over_4096_wide_rows() {
    let mut runner = TestRunner::deterministic();
    for case in 0..40 {
        let f = common::filemon(&mut runner, 8.0);
        let half = [2.0, 10.0, 40.0][case % 3];
        let g = Grid::from_bounds(-half, half, -half, half, 4096, 24).unwrap();
        let runs = f.branch_map(&g, Method::Conic);
        let mut pw = vec![false; g.len()];
        f.branch_map_pointwise_into(&g, &mut pw).unwrap();
        let diff = runs.iter().zip(&pw).filter(|(a, b)| a != b).count();
        assert_eq!(diff, 0, "case {case}: {diff} samples differ");
        for j in (0..24).step_by(5) {
            for i in (0..4096).step_by(97) {
                let c = f.is_branch_free(g.point(i, j), Method::Conic).unwrap();
                assert_eq!(runs[j * 4096 + i], c);
            }
        }
        assert!(runs.iter().any(|&b| b) || runs.iter().all(|&b| !b));
    }
}

/// Near-double roots and points right on the curves: a fine grid around a
/// pole, where both conics pass, still matches point by point.
#[test]
fn runs_match_pointwise_at_the_poles_and_c0() {
    let mut runner = TestRunner::deterministic();
    for _ in 0..20 {
        let f = common::filemon(&mut runner, 8.0);
        let t = f.task();
        for p in t
            .cremona()
            .unwrap()
            .poles()
            .iter()
            .chain(&f.driven().finite_center())
        {
            let r = 1e-6 * t.scale();
            let g = Grid::from_bounds(p.x - r, p.x + r, p.y - r, p.y + r, 257, 257).unwrap();
            let runs = f.branch_map(&g, Method::Conic);
            let mut pw = vec![false; g.len()];
            f.branch_map_pointwise_into(&g, &mut pw).unwrap();
            assert_eq!(runs, pw);
            assert_eq!(
                runs[128 * 257 + 128],
                f.is_branch_free(g.point(128, 128), Method::Conic).unwrap()
            );
            // The pole itself lies on both curves: never free, in the map too.
            assert!(!f.is_branch_free(*p, Method::Conic).unwrap());
            let one = Grid::from_bounds(p.x - 1.0, p.x + 1.0, p.y - 1.0, p.y + 1.0, 1, 1).unwrap();
            assert_eq!(f.branch_map(&one, Method::Conic), vec![false]);
            let mut pw = vec![true];
            f.branch_map_pointwise_into(&one, &mut pw).unwrap();
            assert_eq!(pw, vec![false]);
            assert!(f.margin_map(&one)[0] <= 0.0);
        }
    }
}

/// The three methods agree at 512 x 512 on every point farther than 1e-9
/// of the viewport's size from a curve (and, for the methods that need a
/// circle point, off the pole circle and the poles).
#[test]
fn the_three_methods_agree_at_512_squared() {
    let mut runner = TestRunner::deterministic();
    let n = 512;
    let mut checked = 0usize;
    for case in 0..12 {
        let f = common::filemon(&mut runner, 8.0);
        let half = [6.0, 12.0, 25.0][case % 3];
        let g = Grid::from_bounds(-half, half, -half, half, n, n).unwrap();
        let size = 2.0 * half;
        let conic = f.branch_map(&g, Method::Conic);
        let direct = f.branch_map(&g, Method::Direct);
        let sim = if case % 4 == 0 {
            Some(f.branch_map(&g, Method::Simulate))
        } else {
            None
        };
        let [ga, gb] = f.conics().unwrap();
        let t = f.task();
        let pc = t.cremona().unwrap().pole_circle();
        for j in 0..n {
            for i in 0..n {
                let k = j * n + i;
                if conic[k] == direct[k] && sim.as_ref().is_none_or(|s| s[k] == conic[k]) {
                    continue;
                }
                let p = g.point(i, j);
                // The simulation also sees the circuit defect of a Grashof
                // double-rocker input, which the sign tests cannot: a
                // branch-free point whose poses lie on both arcs of the
                // input.
                if conic[k] == direct[k]
                    && conic[k]
                    && sim.as_ref().is_some_and(|s| !s[k])
                    && common::poses_on_both_arcs(&f, p)
                {
                    continue;
                }
                let near_curve = ga.distance_estimate(p).min(gb.distance_estimate(p)) < 1e-9 * size;
                let near_pc = pc.side(p).abs() < 1e-9 * size;
                assert!(
                    near_curve || near_pc,
                    "case {case}: methods disagree at {p} (conic {}, direct {}, simulate {:?})",
                    conic[k],
                    direct[k],
                    sim.as_ref().map(|s| s[k])
                );
            }
        }
        checked += n * n;
        assert!(
            conic.iter().any(|&b| b),
            "case {case}: some point should be free"
        );
    }
    assert!(checked >= 12 * 512 * 512);
}

#[test]
fn margin_map_signs_and_distances() {
    let mut runner = TestRunner::deterministic();
    for _ in 0..10 {
        let f = common::filemon(&mut runner, 8.0);
        let g = Grid::from_bounds(-9.0, 9.0, -7.0, 7.0, 180, 140).unwrap();
        let m = f.margin_map(&g);
        let b = f.branch_map(&g, Method::Conic);
        for (k, (&mk, &bk)) in m.iter().zip(&b).enumerate() {
            assert!(!mk.is_nan(), "NaN at {k}");
            assert_eq!(mk > 0.0, bk, "sign at {k}: {mk} vs {bk}");
        }
        // The margin is the first-order distance to the nearer curve.
        let [ga, gb] = f.conics().unwrap();
        for k in (0..g.len()).step_by(131) {
            let p = g.point(k % 180, k / 180);
            let want = ga.distance_estimate(p).min(gb.distance_estimate(p));
            let got = f.margin(p).unwrap().abs();
            assert!((got - want).abs() <= 1e-9 * (1.0 + want), "{got} vs {want}");
            assert!(((m[k] as f64).abs() - got).abs() <= 1e-6 * (1.0 + got));
        }
    }
}

#[test]
fn all_defective_maps_are_false_and_minus_infinity() {
    let mut runner = TestRunner::deterministic();
    loop {
        let t = common::task().new_tree(&mut runner).unwrap().current();
        let Ok(f) = t.filemon(Point2::new(1.0, -3.0)) else {
            continue;
        };
        if !f.all_defective() {
            continue;
        }
        let g = Grid::from_bounds(-5.0, 5.0, -5.0, 5.0, 33, 17).unwrap();
        for m in [Method::Conic, Method::Direct, Method::Simulate] {
            assert!(f.branch_map(&g, m).iter().all(|&b| !b));
        }
        assert!(f.margin_map(&g).iter().all(|&v| v == f32::NEG_INFINITY));
        break;
    }
}

/// The inverse of a similarity (test helper).
fn inverse(sim: &burmester::Similarity, q: Point2<f64>) -> Point2<f64> {
    let (s, c) = sim.angle.sin_cos();
    let w = q - sim.offset;
    let v = burmester::Vector2::new(c * w.x + s * w.y, -s * w.x + c * w.y) / sim.factor;
    Point2::new(v.x, if sim.mirror { -v.y } else { v.y })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, failure_persistence: None, rng_seed: common::seed(), ..ProptestConfig::default() })]

    /// The branch map is invariant under moving, rotating, scaling and
    /// mirroring, up to resampling: the map of the transformed task on its
    /// own (axis-aligned) grid equals `classify` of the original task at
    /// the pulled-back samples, except within `1e-9` of the task's size of
    /// a curve; and equals the original map at its nearest sample except
    /// within a cell of a curve.
    #[test]
    fn the_branch_map_is_invariant_up_to_resampling(
        seed in 0u32..1000, k in 1e-3f64..1e3, ang in -PI..PI,
        ox in -100.0f64..100.0, oy in -100.0f64..100.0, mirror in any::<bool>(),
    ) {
        let mut runner = TestRunner::new_with_rng(
            ProptestConfig::default(),
            proptest::test_runner::TestRng::from_seed(
                proptest::test_runner::RngAlgorithm::ChaCha,
                &[seed as u8; 32],
            ),
        );
        let f = common::filemon(&mut runner, 8.0);
        let t = f.task();
        let mut sim = burmester::Similarity::new(k, ang, burmester::Vector2::new(ox, oy)).unwrap();
        if mirror { sim = sim.mirrored(); }
        let poses: Vec<Pose> = t.poses().iter().map(|p| sim.pose(p)).collect();
        let t2 = Task::new(&poses).unwrap();
        let f2 = t2.filemon(sim.point(f.driven().finite_center().unwrap())).unwrap();
        let n = 96;
        let half = 8.0;
        let g1 = Grid::from_bounds(-half, half, -half, half, n, n).unwrap();
        let m1 = f.branch_map(&g1, Method::Conic);
        // The transformed viewport's bounding box.
        let corners = [(-half, -half), (half, -half), (-half, half), (half, half)]
            .map(|(x, y)| sim.point(Point2::new(x, y)));
        let xs = corners.map(|p| p.x);
        let ys = corners.map(|p| p.y);
        let fold = |v: [f64; 4], f: fn(f64, f64) -> f64, init: f64| v.iter().copied().fold(init, f);
        let g2 = Grid::from_bounds(
            fold(xs, f64::min, f64::INFINITY), fold(xs, f64::max, f64::NEG_INFINITY),
            fold(ys, f64::min, f64::INFINITY), fold(ys, f64::max, f64::NEG_INFINITY), n, n,
        ).unwrap();
        let m2 = f2.branch_map(&g2, Method::Conic);
        let cell = 2.0 * half / n as f64;
        let mut compared = 0;
        for j in 0..n {
            for i in 0..n {
                let p = inverse(&sim, g2.point(i, j));
                if p.x.abs() >= half || p.y.abs() >= half { continue; }
                let got = m2[j * n + i];
                let margin = f.margin(p).unwrap().abs();
                if margin > 1e-9 * t.scale() {
                    prop_assert_eq!(got, f.classify(p, Method::Conic).unwrap().is_free(), "at {}", p);
                }
                // Nearest sample of the original map.
                let ii = (((p.x + half) / cell) as usize).min(n - 1);
                let jj = (((p.y + half) / cell) as usize).min(n - 1);
                if margin > cell * std::f64::consts::SQRT_2 {
                    prop_assert_eq!(got, m1[jj * n + ii], "resampled at {}", p);
                }
                compared += 1;
            }
        }
        prop_assert!(compared > n * n / 4, "{}", compared);
    }
}

/// Samples right on a curve: grids placed so that a column falls on a
/// crossing of a conic with the row (within rounding), fine enough that
/// its neighbours are within a few ulps, match point by point: the samples
/// inside a root's rounding band are evaluated, and the runs on either side
/// of a band that holds no sample still end there.
#[test]
fn runs_match_pointwise_with_samples_on_the_curves() {
    let mut runner = TestRunner::deterministic();
    let mut crossings = 0;
    for _ in 0..30 {
        let f = common::filemon(&mut runner, 8.0);
        let Some(conics) = f.conics() else { continue };
        for c in conics {
            for y in [-3.0, -0.7, 0.4, 2.5] {
                let row = burmester::Line {
                    point: Point2::new(0.0, y),
                    direction: burmester::Vector2::new(1.0, 0.0),
                };
                for p in c.intersect_line(&row) {
                    if p.x.abs() >= 50.0 || p.x.is_nan() {
                        continue;
                    }
                    crossings += 1;
                    // Column 64 of 129 at p.x, row 2 of 5 at p.y, for cell
                    // sizes from far above to far below p's spacing.
                    for h in [1e-2, 1e-9, 1e-13, 1e-15] {
                        let (dx, dy) = (h * (1.0 + p.x.abs()), h * (1.0 + p.y.abs()));
                        let g = Grid::from_bounds(
                            p.x - 64.5 * dx,
                            p.x + 64.5 * dx,
                            p.y - 2.5 * dy,
                            p.y + 2.5 * dy,
                            129,
                            5,
                        )
                        .unwrap();
                        let runs = f.branch_map(&g, Method::Conic);
                        let mut pw = vec![false; g.len()];
                        f.branch_map_pointwise_into(&g, &mut pw).unwrap();
                        assert_eq!(runs, pw, "crossing {p}, cell {h}");
                        for j in 0..5 {
                            for i in [0, 63, 64, 65, 128] {
                                let want = f.is_branch_free(g.point(i, j), Method::Conic).unwrap();
                                assert_eq!(runs[j * 129 + i], want, "crossing {p}, cell {h}");
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(crossings > 50, "{crossings} crossings");
}
