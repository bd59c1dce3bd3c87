//! Four- and five-position synthesis: the Burmester curves, the Burmester
//! points, crank order and the exact branch arcs, checked against the
//! notes' worked example, linkages built and driven by the position
//! analysis, the three-pose maps, dense sign scans and invariance.
//!
//! Proptest case counts default to modest values; set `PROPTEST_CASES` for
//! longer runs.

use std::f64::consts::{PI, TAU};

mod common;

use burmester::geom::Cubic;
use burmester::synthesis::{Drive, FilemonArcs, FivePositions, FourPositions, Turn};
use burmester::tolerance::ON_CURVE_TOLERANCE;
use burmester::{
    AssemblyMode, Branch, DegenerateError, Dyad, Error, FourBar, InvalidInput, Point2, Pose,
    Similarity, Task, Vector2, Viewport,
};
use proptest::prelude::*;

/// Proptest cases: `PROPTEST_CASES` if set, else `default`.
fn cases(default: u32) -> ProptestConfig {
    let n = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default);
    ProptestConfig {
        max_global_rejects: 1 << 20,
        ..common::config(n)
    }
}

// ---------------------------------------------------------------------------
// Tasks made from known linkages.
// ---------------------------------------------------------------------------

/// A task made by driving a known four-bar: its poses and its two dyads.
#[derive(Debug, Clone)]
struct Made {
    poses: Vec<Pose>,
    /// The input dyad `(A0, A1)`.
    a: Dyad,
    /// The output dyad `(B0, B1)`.
    b: Dyad,
    fourbar: FourBar,
}

/// The parameters of a random linkage and of the input angles. The
/// default is zero everywhere (input pivot at the origin, ground along +x,
/// coupler point at the crank pin, no angle offset, a fully turning
/// crank's first angle at 0): the found cases below name what differs.
#[derive(Debug, Clone, Default)]
struct LinkParams {
    lengths: [f64; 4],
    origin: (f64, f64),
    ground_angle: f64,
    local: (f64, f64),
    offset: f64,
    mode: bool,
    start: f64,
    steps: [f64; 5],
}

fn link_params() -> impl Strategy<Value = LinkParams> {
    (
        (2.0f64..5.0, 0.4f64..2.0, 1.0f64..5.0, 1.0f64..5.0),
        (-3.0f64..3.0, -3.0f64..3.0),
        -PI..PI,
        (-3.0f64..3.0, -3.0f64..3.0),
        -PI..PI,
        any::<bool>(),
        0.0f64..1.0,
        prop::array::uniform5(0.0f64..1.0),
    )
        .prop_map(
            |(l, origin, ground_angle, local, offset, mode, start, steps)| LinkParams {
                lengths: [l.0, l.1, l.2, l.3],
                origin,
                ground_angle,
                local,
                offset,
                mode,
                start,
                steps,
            },
        )
}

/// Drives the linkage of `p` to `n` input angles spread over its input
/// range (increasing) and reads the coupler poses; `None` when the linkage
/// does not assemble there or the task is ill-conditioned (two poses
/// rotated by less than `min_rotation`).
fn made(p: &LinkParams, n: usize, min_rotation: f64) -> Option<Made> {
    let [g, c, l3, l4] = p.lengths;
    let fb = FourBar::placed(
        g,
        c,
        l3,
        l4,
        Point2::new(p.origin.0, p.origin.1),
        p.ground_angle,
    )
    .ok()?;
    let range = fb.input_range();
    let (start, span) = match range {
        burmester::InputRange::Full => (p.start * TAU, TAU - 0.4),
        _ => {
            let (arcs, _) = range.arcs_array();
            let a = arcs[0];
            if a.span() < 0.8 {
                return None;
            }
            (a.start + 0.02 * a.span(), 0.96 * a.span())
        }
    };
    // Increasing input angles, at least 6% of the span apart.
    let w: Vec<f64> = p.steps[..n].iter().map(|s| 0.3 + s).collect();
    let total: f64 = w.iter().sum::<f64>();
    let mut angles = Vec::with_capacity(n);
    let mut acc = 0.0;
    for wk in &w {
        angles.push(start + span * acc / total);
        acc += wk;
    }
    let mode = if p.mode {
        AssemblyMode::Open
    } else {
        AssemblyMode::Crossed
    };
    let local = Vector2::new(p.local.0, p.local.1);
    let mut poses = Vec::with_capacity(n);
    let mut joints1 = None;
    for &t in &angles {
        let conf = fb.solve(t, mode).ok()?;
        if conf.toggle {
            return None;
        }
        let position = fb.coupler_point(&conf, local);
        poses.push(Pose {
            position,
            angle: conf.theta3 + p.offset,
        });
        if joints1.is_none() {
            joints1 = Some(fb.joints(&conf));
        }
    }
    for i in 0..n {
        for j in i + 1..n {
            if common::wrap(poses[j].angle - poses[i].angle).abs() < min_rotation {
                return None;
            }
        }
    }
    let j = joints1?;
    Some(Made {
        poses,
        a: Dyad::new(fb.input_pivot(), j.crank_joint),
        b: Dyad::new(fb.output_pivot(), j.rocker_joint),
        fourbar: fb,
    })
}

/// [`made`] inside a proptest, at the tests' smallest rotation (0.05 rad):
/// a linkage that makes no task rejects the case.
fn made_case(p: &LinkParams, n: usize) -> Result<Made, TestCaseError> {
    made(p, n, 0.05).ok_or_else(|| TestCaseError::reject("the linkage makes no task"))
}

/// [`made_case`] of four poses, with their curves.
fn made_four(p: &LinkParams) -> Result<(Made, FourPositions), TestCaseError> {
    let m = made_case(p, 4)?;
    let four = FourPositions::new(&m.poses).unwrap();
    Ok((m, four))
}

/// Random poses within 5 of the origin.
fn random_poses(n: usize) -> impl Strategy<Value = Vec<Pose>> {
    prop::collection::vec((-5.0f64..5.0, -5.0f64..5.0, -PI..PI), n)
        .prop_map(|v| v.into_iter().map(|(x, y, a)| Pose::new(x, y, a)).collect())
}

/// Whether the rotations between every two poses are at least `min` (mod 2 pi).
fn rotations_at_least(poses: &[Pose], min: f64) -> bool {
    (0..poses.len()).all(|i| {
        (i + 1..poses.len()).all(|j| common::wrap(poses[j].angle - poses[i].angle).abs() >= min)
    })
}

// ---------------------------------------------------------------------------
// Small geometric helpers.
// ---------------------------------------------------------------------------

use common::centroid;
use common::five_count::{slider_positions, sound_count, total};

/// A square viewport of half-width `h` task sizes around the poses.
fn view_around(four: &FourPositions, h: f64) -> Viewport {
    let c = centroid(four.poses());
    let r = h * four.size();
    Viewport::new(c.x - r, c.x + r, c.y - r, c.y + r).unwrap()
}

/// Pieces of a curve cut by crank order: where two pieces meet the order
/// changes, exactly at one of `cuts`; inside a piece each point's dyad
/// (`dyad_of`) has the piece's order, away from ties of two crank angles.
fn check_order_arcs(
    four: &FourPositions,
    arcs: &[burmester::synthesis::OrderArc],
    cuts: &[Point2<f64>],
    dyad_of: impl Fn(Point2<f64>) -> Dyad,
) -> Result<(), TestCaseError> {
    let s = four.size();
    for w in arcs.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        let end = *a.points.last().unwrap();
        if end != b.points[0] {
            continue;
        }
        prop_assert!(a.order != b.order);
        let at_cut = cuts.iter().any(|c| (c - end).norm() <= 1e-9 * s);
        prop_assert!(at_cut, "a cut at {} is none of {:?}", end, cuts);
    }
    for a in arcs {
        for p in &a.points[1..a.points.len() - 1] {
            let d = dyad_of(*p);
            let ang = four.crank_angles(&d);
            let tie =
                (0..4).any(|j| (j + 1..4).any(|k| common::wrap(ang[j] - ang[k]).abs() < 1e-9));
            if !tie {
                prop_assert_eq!(four.crank_order(&d), a.order);
            }
        }
    }
    Ok(())
}

use common::seg_dist;

/// Distance from `p` to the nearest chord of `polylines`.
fn poly_dist(polylines: &[Vec<Point2<f64>>], p: Point2<f64>) -> f64 {
    let mut best = f64::INFINITY;
    for l in polylines {
        if l.len() == 1 {
            best = best.min((l[0] - p).norm());
        }
        for w in l.windows(2) {
            best = best.min(seg_dist(p, w[0], w[1]));
        }
    }
    best
}

/// The relative spread of the crank length of a dyad over the poses.
fn spread(poses: &[Pose], d: &Dyad) -> f64 {
    let (_, min, max) = crank_lengths(poses, d.center, d.circle);
    (max - min) / max
}

/// The distances of a dyad's moving pivot (its circle point `circle`
/// carried from pose 1 to each pose) from its center `center`: each, the
/// smallest, the largest.
fn crank_lengths(poses: &[Pose], center: Point2<f64>, circle: Point2<f64>) -> (Vec<f64>, f64, f64) {
    let p1 = poses[0];
    let r: Vec<f64> = poses
        .iter()
        .map(|p| {
            let (s, c) = (p.angle - p1.angle).sin_cos();
            let v = circle - p1.position;
            let q = p.position + Vector2::new(c * v.x - s * v.y, s * v.x + c * v.y);
            (q - center).norm()
        })
        .collect();
    let max = r.iter().copied().fold(0.0, f64::max);
    let min = r.iter().copied().fold(f64::INFINITY, f64::min);
    (r, min, max)
}

/// Whether `p` is within the on-curve tolerance of `curve` for `four`.
/// On the curve by the crate's rule ([`ON_CURVE_TOLERANCE`]): within the
/// tolerance by the first-order distance, or with the value zero within
/// rounding (at a singular point, where the distance means nothing).
fn on_curve(curve: &Cubic, four: &FourPositions, p: Point2<f64>, factor: f64) -> bool {
    let tol = factor * ON_CURVE_TOLERANCE * (four.size() + (p - centroid(four.poses())).norm());
    curve.is_on(p, tol).0
}

// ---------------------------------------------------------------------------
// The worked example.
// ---------------------------------------------------------------------------

// The notes' worked example (positions-4-5.md, section 6).
use common::notes_poses as example_poses;

#[test]
fn the_worked_example_has_its_four_burmester_points() {
    let five = FivePositions::new(&example_poses()).unwrap();
    let pts = five.burmester_points();
    let want = [
        (0.0, 0.0, 1.4095389312, 0.5130302150, 1.5),
        (4.0, 0.0, 3.8748900012, 2.9973901128, 3.0),
        (
            9.1415535429,
            5.4771377313,
            10.0779175389,
            7.0028629572,
            1.7901438484,
        ),
        (
            28.5694893347,
            -40.1577865973,
            -3.2276569999,
            12.3029832658,
            61.3448521854,
        ),
    ];
    assert_eq!(pts.len(), 4);
    for (p, w) in pts.iter().zip(want) {
        assert!((p.center - Point2::new(w.0, w.1)).norm() < 1e-8, "{p:?}");
        assert!((p.circle - Point2::new(w.2, w.3)).norm() < 1e-8, "{p:?}");
        assert!((p.length() - w.4).abs() < 1e-8);
        assert!(five.residual(p) < 1e-13, "{}", five.residual(p));
    }
    // Six four-bars; the generating pair: A0 driving is branch-free and
    // meets the poses in order counter-clockwise, B0 driving is not.
    let bars = five.four_bars();
    assert_eq!(bars.len(), 6);
    let generating = bars.iter().find(|b| b.indices == [0, 1]).unwrap();
    let [a_drives, b_drives] = &generating.drives;
    assert!(a_drives.is_branch_free());
    assert_eq!(a_drives.in_order(), Some(Turn::Counterclockwise));
    assert!(a_drives.is_defect_free());
    assert!(!b_drives.is_branch_free());
    assert!((a_drives.fourbar.crank() - 1.5).abs() < 1e-8);
    assert!((a_drives.fourbar.rocker() - 3.0).abs() < 1e-8);
    assert!((a_drives.fourbar.coupler() - 3.5).abs() < 1e-8);
    assert!((a_drives.fourbar.ground() - 4.0).abs() < 1e-8);
    // The crank angles are the example's (20, 70, 120, 170, 230 degrees).
    for (t, want) in a_drives
        .input_angles
        .iter()
        .zip([20.0f64, 70.0, 120.0, 170.0, 230.0])
    {
        assert!(common::wrap(t - want.to_radians()).abs() < 1e-8);
    }
    // Both curves of the five poses pass through every Burmester center.
    for c in five.center_point_curves() {
        for p in pts {
            assert!(c.distance_estimate(p.center) < 1e-9 * (1.0 + p.center.coords.norm()));
        }
    }
}

#[test]
fn the_example_curves_hold_the_generating_dyads() {
    let poses = example_poses();
    let four = FourPositions::new(&poses[..4]).unwrap();
    let a = Dyad::new(
        Point2::new(0.0, 0.0),
        Point2::new(1.4095389312, 0.5130302150),
    );
    let b = Dyad::new(
        Point2::new(4.0, 0.0),
        Point2::new(3.8748900012, 2.9973901128),
    );
    for d in [a, b] {
        let z = four.circle_point(d.center).unwrap();
        assert!((z - d.circle).norm() < 1e-8, "{z} {d:?}");
        let g = four.center_point(d.circle).unwrap();
        assert!((g - d.center).norm() < 1e-8, "{g} {d:?}");
    }
    assert!(four.center_point_curve().is_circular());
    assert!(four.circle_point_curve().is_circular());
    // The example linkage turns fully and meets poses 1..4 in order.
    let drive = four.drive(&a, &b).unwrap();
    assert!(drive.is_branch_free());
    assert_eq!(drive.in_order(), Some(Turn::Counterclockwise));
    assert_eq!(drive.order.sequence(), &[1, 2, 3, 4]);
}

// ---------------------------------------------------------------------------
// Known linkages: their dyads are on the curves and among the Burmester
// points; three-pose subsets agree.
// ---------------------------------------------------------------------------

/// The Burmester points of five poses made by a linkage: two or four,
/// the linkage's dyads among them, all concyclic, a four-bar per pair.
fn linkage_burmester_points(m: &Made) -> Result<(), TestCaseError> {
    let five = FivePositions::new(&m.poses).unwrap();
    let s = five.size();
    let pts = five.burmester_points();
    prop_assert!(pts.len() == 2 || pts.len() == 4, "{} points", pts.len());
    for d in [m.a, m.b] {
        let hit = pts.iter().any(|q| {
            (q.center - d.center).norm() <= 1e-6 * (s + d.center.coords.norm())
                && (q.circle - d.circle).norm() <= 1e-6 * (s + d.circle.coords.norm())
        });
        prop_assert!(hit, "{:?} not in {:?}", d, pts);
    }
    for q in pts {
        prop_assert!(five.residual(q) < 1e-11, "{}", five.residual(q));
        prop_assert!(spread(&m.poses, q) < 1e-11);
    }
    prop_assert_eq!(five.four_bars().len(), pts.len() * (pts.len() - 1) / 2);
    Ok(())
}

proptest! {
    #![proptest_config(cases(96))]

    #[test]
    fn a_linkage_s_dyads_lie_on_both_curves(p in link_params()) {
        let (m, four) = made_four(&p)?;
        let s = four.size();
        for d in [m.a, m.b] {
            // Ten times the tolerance: next to a near-singular point of a
            // curve (|grad f| a millionth of its scale) the cubic's
            // coefficients, computed with cancellation, put an exact dyad
            // up to five times it off by first-order distance
            // (`a_kite_s_circle_point_is_near_a_nearly_singular_curve`).
            prop_assert!(on_curve(four.center_point_curve(), &four, d.center, 10.0));
            prop_assert!(on_curve(four.circle_point_curve(), &four, d.circle, 10.0));
            let z = four.circle_point(d.center).unwrap();
            prop_assert!((z - d.circle).norm() <= 1e-7 * (s + d.circle.coords.norm()), "{} {:?}", z, d);
            let g = four.center_point(d.circle).unwrap();
            prop_assert!((g - d.center).norm() <= 1e-7 * (s + d.center.coords.norm()), "{} {:?}", g, d);
            // Every three-pose subset with pose 1 gives the same circle point.
            for (j, k) in [(1, 2), (1, 3), (2, 3)] {
                let t = Task::new(&[m.poses[0], m.poses[j], m.poses[k]]).unwrap();
                let x = t.circle_point(d.center).unwrap();
                prop_assert!((x - d.circle).norm() <= 1e-7 * (s + d.circle.coords.norm()));
            }
            // And the subset without pose 1, in the frame of pose 2.
            let t = Task::new(&[m.poses[1], m.poses[2], m.poses[3]]).unwrap();
            let x2 = t.circle_point(d.center).unwrap();
            let want = four.displace(d.circle, 1, 2).unwrap();
            prop_assert!((x2 - want).norm() <= 1e-7 * (s + want.coords.norm()));
        }
        // The branch and order of the generating linkage as built.
        let drive = four.drive(&m.a, &m.b).unwrap();
        prop_assert!(drive.is_branch_free());
        prop_assert!(drive.in_order().is_some(), "{:?}", drive.order);
        let _ = m.fourbar;
    }

    #[test]
    fn a_linkage_s_dyads_are_burmester_points(p in link_params()) {
        linkage_burmester_points(&made_case(&p, 5)?)?;
    }

    #[test]
    fn burmester_points_of_random_tasks_are_concyclic_and_complete(poses in random_poses(5)) {
        prop_assume!(rotations_at_least(&poses, 0.05));
        let five = FivePositions::new(&poses).unwrap();
        let pts = five.burmester_points();
        prop_assert!(pts.len() <= 4 && pts.len() % 2 == 0, "{}", pts.len());
        for q in pts {
            prop_assert!(five.residual(q) < 1e-10, "{}", five.residual(q));
        }
        // Completeness, independently: wherever the curve of poses 1235
        // changes sign along the traced curve of poses 1234 (away from the
        // poles P12, P13, P23 that both pass through), a Burmester center
        // lies on that chord.
        let [f, h] = five.center_point_curves();
        let c = centroid(&poses);
        let r = 20.0 * five.size();
        let view = Viewport::new(c.x - r, c.x + r, c.y - r, c.y + r).unwrap();
        let four = FourPositions::new(&poses[..4]).unwrap();
        let poles: Vec<Point2<f64>> = four.poles().iter().filter(|p| matches!(p.poses, [1, 2] | [1, 3] | [2, 3])).filter_map(|p| p.point).collect();
        for l in f.trace(&view, Some(1e-4 * r)).unwrap().polylines() {
            for w in l.windows(2) {
                let (a, b) = (h.evaluate(w[0]), h.evaluate(w[1]));
                if a == 0.0 || b == 0.0 || (a < 0.0) == (b < 0.0) {
                    continue;
                }
                let len = (w[1] - w[0]).norm();
                if poles.iter().any(|p| seg_dist(*p, w[0], w[1]) <= 2.0 * len + 1e-9 * r) {
                    continue;
                }
                let found = pts.iter().any(|q| seg_dist(q.center, w[0], w[1]) <= 2.0 * len + 1e-9 * r);
                prop_assert!(found, "a crossing near {} is not among {:?}", w[0], pts);
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Traced points, poles and the points Q_jk.
// ---------------------------------------------------------------------------

proptest! {
    #![proptest_config(cases(48))]

    #[test]
    fn every_traced_point_is_concyclic(poses in random_poses(4), h in 1.0f64..6.0) {
        prop_assume!(rotations_at_least(&poses, 0.05));
        let four = FourPositions::new(&poses).unwrap();
        let view = view_around(&four, h);
        let (mut checked, mut skipped) = (0, 0);
        for l in four.center_point_curve().polylines(&view) {
            for g in l {
                match four.circle_point(g) {
                    Ok(z) => {
                        let d = Dyad::new(g, z);
                        prop_assert!(spread(&poses, &d) < 1e-8, "{} at {}", spread(&poses, &d), g);
                        // The three-pose maps of the subsets agree.
                        let t = Task::new(&[poses[0], poses[1], poses[2]]);
                        if let Ok(x) = t.and_then(|t| t.circle_point(g)) {
                            prop_assert!((x - z).norm() <= 1e-6 * (four.size() + z.coords.norm()));
                        }
                        checked += 1;
                    }
                    Err(Error::Degenerate(_)) => skipped += 1,
                    Err(e) => prop_assert!(false, "{e}"),
                }
            }
        }
        for l in four.circle_point_curve().polylines(&view) {
            for z in l {
                if let Ok(g) = four.center_point(z) {
                    let d = Dyad::new(g, z);
                    prop_assert!(spread(&poses, &d) < 1e-8, "{}", spread(&poses, &d));
                }
            }
        }
        prop_assert!(skipped <= checked / 100 + 1, "{skipped} of {checked}");
    }

    #[test]
    fn poles_and_coincidence_points_lie_on_the_curve(poses in random_poses(4)) {
        prop_assume!(rotations_at_least(&poses, 0.05));
        let four = FourPositions::new(&poses).unwrap();
        let curve = four.center_point_curve();
        for pole in four.poles() {
            let p = pole.point.unwrap();
            prop_assert!(on_curve(curve, &four, p, 1.0), "{:?}", pole);
            // A pole is a fixed point of its displacement.
            let [j, k] = pole.poses;
            prop_assert!((four.displace(p, j, k).unwrap() - p).norm() <= 1e-9 * (1.0 + p.coords.norm()));
        }
        for q in four.coincidence_points() {
            let Some(c) = q.center else { continue };
            prop_assume!(c.coords.norm() < 1e4 * four.size());
            prop_assert!(on_curve(curve, &four, c, 10.0), "{:?}", q);
            let [j, k] = q.poses;
            let z = four.circle_point(c).unwrap();
            let want = q.circle.unwrap();
            prop_assert!((z - want).norm() <= 1e-6 * (four.size() + want.coords.norm()), "{} {}", z, want);
            let a = four.crank_angles(&Dyad::new(c, z));
            prop_assert!(common::wrap(a[j - 1] - a[k - 1]).abs() < 1e-6, "{:?}", a);
        }
    }

    #[test]
    fn the_crank_order_changes_only_at_the_coincidence_points(poses in random_poses(4)) {
        prop_assume!(rotations_at_least(&poses, 0.1));
        let four = FourPositions::new(&poses).unwrap();
        let Ok(runs) = four.dyad_runs(3000) else { return Ok(()); };
        let qs: Vec<Point2<f64>> = four.coincidence_points().iter().filter_map(|q| q.center).collect();
        let s = four.size();
        let mut changes = 0;
        for run in &runs {
            for w in run.windows(2) {
                let (a, b) = (&w[0], &w[1]);
                // Every sample is a dyad of the four poses.
                prop_assert!(spread(&poses, &a.dyad()) < 1e-8, "{}", spread(&poses, &a.dyad()));
                // The samples come from the compatibility linkage, not the
                // cubic: dyads to the 1e-8 of the spread, which near its
                // toggles is up to ten times the curve tolerance off the
                // cubic (`a_compatibility_sample_is_near_the_cubic`).
                if a.center.coords.norm() < 1e3 * s {
                    prop_assert!(on_curve(four.center_point_curve(), &four, a.center, 10.0));
                }
                if a.order == b.order {
                    continue;
                }
                let chord = (b.center - a.center).norm();
                if chord > 0.5 * s || a.center.coords.norm().max(b.center.coords.norm()) > 1e3 * s {
                    continue; // through (or near) infinity
                }
                changes += 1;
                let near = qs.iter().any(|q| seg_dist(*q, a.center, b.center) <= 2.0 * chord + 1e-9 * s);
                prop_assert!(near, "order {} -> {} between {} and {}, Q = {:?}", a.order, b.order, a.center, b.center, qs);
            }
        }
        let _ = changes;
        // The pieces of constant order in view are cut exactly at the Q_jk.
        let view = view_around(&four, 3.0);
        check_order_arcs(&four, &four.order_arcs(&view), &qs, |p| four.dyad_from_center(p).unwrap())?;
    }

    #[test]
    fn the_circle_point_curve_is_cut_by_order_at_the_images_of_the_coincidence_points(
        poses in random_poses(4),
    ) {
        prop_assume!(rotations_at_least(&poses, 0.1));
        let four = FourPositions::new(&poses).unwrap();
        let s = four.size();
        let mut zs: Vec<Point2<f64>> = four.coincidence_points().iter().filter_map(|q| q.circle).collect();
        // Where the center point passes through infinity (a slider): on the
        // circle-point curve, and the limit of the circle points of centers
        // going out along the asymptote.
        let sliders = four.slider_circle_points();
        let o = centroid(four.poses());
        for z in &sliders {
            prop_assert!(on_curve(four.circle_point_curve(), &four, *z, 1.0), "{} off the circle-point curve", z);
        }
        for u in four.center_point_curve().asymptotic_directions() {
            // The circle point of the curve's point nearest the asymptote's
            // direction, at a distance `d` far out.
            let circle_at = |d: f64| {
                let far = four.center_point_curve().intersect_line(&burmester::Line {
                    point: o + u * (d * s),
                    direction: Vector2::new(-u.y, u.x),
                });
                let g = far.iter().min_by(|a, b| (*a - o).norm().total_cmp(&(*b - o).norm()))?;
                four.circle_point(*g).ok()
            };
            let gap = |z: Point2<f64>| {
                sliders.iter().map(|w| (z - w).norm() / (s + w.coords.norm())).fold(f64::INFINITY, f64::min)
            };
            // It tends to a slider's circle point like 1/d (with a constant
            // of some thousand task sizes on some tasks: a proptest found
            // one 7e-4 away at 1e6 task sizes, 7e-5 at 1e7).
            if let (Some(a), Some(b)) = (circle_at(1e6), circle_at(1e7)) {
                let (ga, gb) = (gap(a), gap(b));
                prop_assert!(
                    ga <= 1e-4 || gb <= 1e-4 || gb <= 0.2 * ga,
                    "{} and {} tend to no slider's circle point {:?}",
                    a,
                    b,
                    sliders
                );
            }
        }
        zs.extend(sliders);
        let view = view_around(&four, 3.0);
        let arcs = four.circle_order_arcs(&view);
        // Each point is a circle point of the four poses: its dyad (from the
        // center point) passes them.
        for z in arcs.iter().flat_map(|a| &a.points[1..a.points.len() - 1]) {
            let d = four.dyad_from_circle(*z).unwrap();
            prop_assert!(spread(&poses, &d) < 1e-6, "{}", spread(&poses, &d));
        }
        check_order_arcs(&four, &arcs, &zs, |z| four.dyad_from_circle(z).unwrap())?;
    }
}

#[test]
fn the_crank_rotation_parametrisation_matches_the_curve_dyads() {
    let four = FourPositions::new(&example_poses()[..4]).unwrap();
    let runs = four.dyad_runs(2000).unwrap();
    let mut n = 0;
    for run in &runs {
        for d in run {
            let again = four.curve_dyad(d.center).unwrap();
            assert!((again.circle - d.circle).norm() < 1e-7 * (1.0 + d.circle.coords.norm()));
            assert!(common::wrap(again.beta2 - d.beta2).abs() < 1e-7);
            if let (Some(a), Some(b)) = (again.branch, d.branch) {
                assert_eq!(a, b, "{d:?}");
            }
            // The order, away from ties (the points Q_jk, where two crank
            // positions coincide).
            let a = four.crank_angles(&d.dyad());
            let tie = (0..4).any(|j| (j + 1..4).any(|k| common::wrap(a[j] - a[k]).abs() < 1e-6));
            if !tie {
                assert_eq!(again.order, d.order);
            }
            n += 1;
        }
    }
    assert!(n > 1000);
    // The example's dyads at their crank rotations.
    let a = Dyad::new(
        Point2::new(0.0, 0.0),
        Point2::new(1.4095389312, 0.5130302150),
    );
    let ca = four.curve_dyad(a.center).unwrap();
    assert!(common::wrap(ca.beta2 - 50f64.to_radians()).abs() < 1e-8);
    let back = four.dyad_at(ca.beta2, ca.branch.unwrap()).unwrap();
    assert!((back.center - a.center).norm() < 1e-7, "{back:?}");
}

// ---------------------------------------------------------------------------
// Branch: Filemon with four lines, exact arc ends, against driving the
// linkage densely.
// ---------------------------------------------------------------------------

/// Whether driving `d`'s linkage from pose 1 in pose 1's assembly mode,
/// densely (steps of 0.02 rad) in either direction without a loop that
/// fails to close, reaches every pose (its output joint where the poses
/// put it). `None` at a toggle at pose 1, and where the simulation cannot
/// decide: at a pose so near a toggle that the two assembly modes put the
/// output joint within 1e-4 of the linkage's size of each other (the
/// joints then meet the pose within the tolerance in either mode; a
/// dyad 1e-5 from an arc end, found by a proptest in CI, was such a case).
fn reaches_every_pose(d: &Drive, four_poses: &[Pose]) -> Option<bool> {
    let mode = d.modes[0]?;
    let fb = &d.fourbar;
    let size = fb.lengths().iter().sum::<f64>();
    for &t in &d.input_angles {
        let [open, crossed] =
            AssemblyMode::BOTH.map(|m| fb.joints_at(t, m).map(|j| j.rocker_joint));
        if let (Ok(o), Ok(c)) = (open, crossed) {
            if (o - c).norm() < 1e-4 * size {
                return None;
            }
        }
    }
    let t1 = d.input_angles[0];
    let p1 = four_poses[0];
    let target = |k: usize| {
        let p = four_poses[k];
        let (s, c) = (p.angle - p1.angle).sin_cos();
        let v = d.driven.circle - p1.position;
        p.position + Vector2::new(c * v.x - s * v.y, s * v.x + c * v.y)
    };
    for k in 1..four_poses.len() {
        let mut reached = false;
        for dir in [1.0, -1.0] {
            let delta = (dir * (d.input_angles[k] - t1)).rem_euclid(TAU);
            let steps = (delta / 0.02).ceil() as usize + 1;
            let closes = (1..steps).all(|i| {
                fb.solve(t1 + dir * delta * i as f64 / steps as f64, mode)
                    .is_ok()
            });
            if !closes {
                continue;
            }
            if let Ok(j) = fb.joints_at(d.input_angles[k], mode) {
                if (j.rocker_joint - target(k)).norm() <= 1e-6 * size {
                    reached = true;
                    break;
                }
            }
        }
        if !reached {
            return Some(false);
        }
    }
    Some(true)
}

/// The checks of the branch construction for one driven dyad.
fn check_branch(four: &FourPositions, driven: &Dyad, samples: usize) -> Result<(), TestCaseError> {
    let arcs: FilemonArcs = match four.filemon(driven) {
        Ok(a) => a,
        Err(_) => return Ok(()),
    };
    let s = four.size();
    let c1 = driven.circle;
    // The exact ends: on the circle-point curve and on their Filemon lines.
    for e in arcs.arc_ends() {
        prop_assert!(
            on_curve(four.circle_point_curve(), four, e.circle, 1.0),
            "{:?}",
            e
        );
        let line = arcs.all_lines()[e.pose - 1];
        let dn = line.direction / line.direction.norm();
        let off = (dn.x * (e.circle - c1).y - dn.y * (e.circle - c1).x).abs();
        prop_assert!(off <= 1e-9 * (s + (e.circle - c1).norm()), "{off}");
        // Its center: on the center-point curve, or (where the inverse
        // map is ill-conditioned: poles within a tenth of the task of each
        // other) the center of the circle point's positions to 1e-8.
        if let Some(g) = e.center {
            prop_assert!(
                on_curve(four.center_point_curve(), four, g, 10.0)
                    || spread(four.poses(), &Dyad::new(g, e.circle)) <= 1e-8,
                "{:?}",
                e
            );
        }
    }
    if arcs.all_defective() {
        prop_assert!(arcs.arc_ends().is_empty());
    }
    // The verdict changes along the circle-point curve only at an arc end or C1.
    let view = view_around(four, 3.0);
    let mut cuts: Vec<Point2<f64>> = arcs.arc_ends().iter().map(|e| e.circle).collect();
    cuts.push(c1);
    for l in four.circle_point_curve().polylines(&view) {
        for w in l.windows(2) {
            let (u, v) = (
                arcs.classify_circle_point(w[0]),
                arcs.classify_circle_point(w[1]),
            );
            if u == Branch::Boundary || v == Branch::Boundary || u == v {
                continue;
            }
            let len = (w[1] - w[0]).norm();
            let near = cuts
                .iter()
                .any(|c| seg_dist(*c, w[0], w[1]) <= len + 1e-9 * s);
            prop_assert!(
                near,
                "verdict {:?} -> {:?} between {} and {}",
                u,
                v,
                w[0],
                w[1]
            );
        }
    }
    for arc in arcs.free_circle_arcs(&view).unwrap() {
        for p in &arc[1..arc.len() - 1] {
            prop_assert_eq!(arcs.classify_circle_point(*p), Branch::Free);
        }
    }
    // Driving dyads along the curve: the verdict against the built linkage.
    let Ok(runs) = four.dyad_runs(samples) else {
        return Ok(());
    };
    for d in runs.iter().flatten() {
        let a = d.dyad();
        if (a.center - driven.center).norm() < 1e-3 * s
            || (a.circle - driven.circle).norm() < 1e-3 * s
            || a.center.coords.norm() > 1e3 * s
        {
            continue;
        }
        let verdict = arcs.classify_circle_point(a.circle);
        if verdict == Branch::Boundary {
            continue;
        }
        let Ok(drive) = four.drive(&a, driven) else {
            continue;
        };
        if drive.modes.iter().any(|m| m.is_none()) {
            continue;
        }
        // The sign test with four lines is the assembly mode test.
        prop_assert_eq!(verdict == Branch::Free, drive.is_branch_free());
        // Driving the linkage densely.
        let Some(sim) = reaches_every_pose(&drive, four.poses()) else {
            continue;
        };
        if verdict == Branch::Defective {
            prop_assert!(!sim, "defective but reached every pose: {:?}", d);
        } else if drive.fourbar.input_turns_fully() {
            prop_assert!(sim, "free but did not reach every pose: {:?}", d);
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(cases(24))]

    #[test]
    fn the_branch_verdict_matches_driving_the_linkage(p in link_params()) {
        check_made_branch(&p)?;
    }

    #[test]
    fn the_branch_verdict_matches_for_random_driven_dyads(poses in random_poses(4), pick in 0usize..1000) {
        prop_assume!(rotations_at_least(&poses, 0.1));
        let four = FourPositions::new(&poses).unwrap();
        let Ok(runs) = four.dyad_runs(200) else { return Ok(()); };
        let all: Vec<_> = runs.iter().flatten().collect();
        prop_assume!(!all.is_empty());
        let driven = all[pick % all.len()].dyad();
        // A driven dyad longer than a thousand task sizes (a circle point
        // far out, where its center nears a slider's) is all but a slider:
        // the Filemon lines through it are parallel to within 1e-6 at the
        // poses (see `an_arc_end_from_a_far_circle_point_lies_on_the_curve`).
        prop_assume!(
            driven.length() > 1e-2 * four.size()
                && driven.length() < 1e3 * four.size()
                && driven.center.coords.norm() < 100.0
        );
        check_branch(&four, &driven, 80)?;
    }
}

// ---------------------------------------------------------------------------
// Pure translations between two poses.
// ---------------------------------------------------------------------------

/// The input angle other than `t` where the coupler has the same angle as
/// at `t` (the coupler angle takes each value twice over a turn), found by
/// scanning and bisection.
fn same_coupler_angle(fb: &FourBar, mode: AssemblyMode, t: f64) -> Option<f64> {
    let th3 = |x: f64| fb.solve(x, mode).ok().map(|c| c.theta3);
    let target = th3(t)?;
    let f = |x: f64| th3(x).map(|v| common::wrap(v - target));
    let n = 720;
    let mut prev = (t + 0.2, f(t + 0.2)?);
    for i in 1..n {
        let x = t + 0.2 + (TAU - 0.4) * i as f64 / n as f64;
        let fx = f(x)?;
        if (fx < 0.0) != (prev.1 < 0.0) && (fx - prev.1).abs() < 1.0 {
            let (mut a, mut b, mut fa) = (prev.0, x, prev.1);
            for _ in 0..200 {
                let m = 0.5 * (a + b);
                let fm = f(m)?;
                if (fm < 0.0) == (fa < 0.0) {
                    a = m;
                    fa = fm;
                } else {
                    b = m;
                }
            }
            return Some(0.5 * (a + b));
        }
        prev = (x, fx);
    }
    None
}

proptest! {
    #![proptest_config(cases(48))]

    #[test]
    fn a_pure_translation_between_two_poses_works(poses in random_poses(5), pair in 0usize..10) {
        let pairs = [(0, 1), (0, 2), (0, 3), (0, 4), (1, 2), (1, 3), (1, 4), (2, 3), (2, 4), (3, 4)];
        let (i, j) = pairs[pair];
        let mut poses = poses;
        poses[j].angle = poses[i].angle;
        // Four poses (the pair included when it lies in the first four).
        let four_poses = &poses[..4];
        let ok = (0..4).all(|a| (a + 1..4).all(|b| (a, b) == (i, j)
            || common::wrap(four_poses[b].angle - four_poses[a].angle).abs() >= 0.05));
        prop_assume!(ok);
        let four = FourPositions::new(four_poses).unwrap();
        if j < 4 {
            let pole = four.poles().into_iter().find(|p| p.poses == [i + 1, j + 1]).unwrap();
            prop_assert!(pole.point.is_none());
        }
        // The view around the poses and the finite poles (the curve passes
        // through them, so it is in view even when it runs far from the
        // poses).
        let around = view_around(&four, 3.0);
        let (mut x0, mut x1, mut y0, mut y1) = (around.xmin, around.xmax, around.ymin, around.ymax);
        for p in four.poles().iter().filter_map(|p| p.point) {
            prop_assert!(on_curve(four.center_point_curve(), &four, p, 10.0), "pole {} off the curve", p);
            let m = 0.1 * four.size();
            (x0, x1, y0, y1) = (x0.min(p.x - m), x1.max(p.x + m), y0.min(p.y - m), y1.max(p.y + m));
        }
        let view = Viewport::new(x0, x1, y0, y1).unwrap();
        let mut n = 0;
        for g in four.center_point_curve().polylines(&view).into_iter().flatten() {
            if let Ok(z) = four.circle_point(g) {
                prop_assert!(spread(four_poses, &Dyad::new(g, z)) < 1e-8);
                n += 1;
            }
        }
        prop_assert!(n > 0);
        let okf = (0..5).all(|a| (a + 1..5).all(|b| (a, b) == (i, j)
            || common::wrap(poses[b].angle - poses[a].angle).abs() >= 0.05));
        prop_assume!(okf);
        let five = FivePositions::new(&poses).unwrap();
        for q in five.burmester_points() {
            prop_assert!(five.residual(q) < 1e-10);
        }
    }

    #[test]
    fn a_linkage_with_a_pure_translation_keeps_its_dyads(p in link_params(), which in 0usize..4) {
        let [g, c, l3, l4] = p.lengths;
        let Ok(fb) = FourBar::placed(g, c, l3, l4, Point2::new(p.origin.0, p.origin.1), p.ground_angle) else { return Ok(()); };
        prop_assume!(fb.input_turns_fully());
        let mode = if p.mode { AssemblyMode::Open } else { AssemblyMode::Crossed };
        let t0 = p.start * TAU;
        let Some(t1) = same_coupler_angle(&fb, mode, t0) else { return Ok(()); };
        // Three more angles away from the pair.
        let mut angles = vec![t0, t1];
        for k in 1..=3 {
            angles.push(t0 + (t1 - t0).rem_euclid(TAU) * 0.25 * k as f64 + 0.3 * p.steps[k]);
        }
        angles.swap(1, 1 + which);
        let local = Vector2::new(p.local.0, p.local.1);
        let mut poses = Vec::new();
        for &t in &angles {
            let Ok(conf) = fb.solve(t, mode) else { return Ok(()); };
            poses.push(Pose { position: fb.coupler_point(&conf, local), angle: conf.theta3 + p.offset });
        }
        let ok = (0..5).all(|a| (a + 1..5).all(|b| {
            let r = common::wrap(poses[b].angle - poses[a].angle).abs();
            !(1e-12..0.05).contains(&r)
        }));
        prop_assume!(ok);
        let conf = fb.solve(angles[0], mode).unwrap();
        let j = fb.joints(&conf);
        let dyads = [Dyad::new(fb.input_pivot(), j.crank_joint), Dyad::new(fb.output_pivot(), j.rocker_joint)];
        let four = FourPositions::new(&poses[..4]).unwrap();
        for d in dyads {
            let z = four.circle_point(d.center).unwrap();
            prop_assert!((z - d.circle).norm() <= 1e-7 * (four.size() + z.coords.norm()));
        }
        let five = FivePositions::new(&poses).unwrap();
        for d in dyads {
            let hit = five.burmester_points().iter().any(|q| (q.center - d.center).norm() <= 1e-6 * (five.size() + d.center.coords.norm()));
            prop_assert!(hit, "{:?} not in {:?}", d, five.burmester_points());
        }
    }
}

// ---------------------------------------------------------------------------
// Invariance.
// ---------------------------------------------------------------------------

fn similarity() -> impl Strategy<Value = Similarity> {
    (
        prop_oneof![Just(1e-3), Just(1.0), Just(1e3), 0.1f64..10.0],
        -PI..PI,
        (-50.0f64..50.0, -50.0f64..50.0),
        any::<bool>(),
    )
        .prop_map(|(f, a, (x, y), m)| {
            let s = Similarity::new(f, a, Vector2::new(x * f, y * f)).unwrap();
            if m { s.mirrored() } else { s }
        })
}

proptest! {
    #![proptest_config(cases(48))]

    #[test]
    fn curves_and_points_move_with_the_task(p in link_params(), t in similarity()) {
        let m = made_case(&p, 5)?;
        let moved: Vec<Pose> = m.poses.iter().map(|q| t.pose(q)).collect();
        // Five poses: the Burmester points are the images.
        let (a, b) = (FivePositions::new(&m.poses).unwrap(), FivePositions::new(&moved).unwrap());
        prop_assert_eq!(a.burmester_points().len(), b.burmester_points().len());
        for q in a.burmester_points() {
            let want = t.point(q.center);
            // Beyond 1e4 task sizes the curves meet at a small angle and a
            // point moves by more (`a_far_burmester_point_moves_with_the_task`).
            let far = (q.center - centroid(&m.poses)).norm() > 1e4 * a.size();
            let rel = if far { 1e-6 } else { 1e-7 };
            let hit = b.burmester_points().iter().any(|r| {
                (r.center - want).norm() <= rel * (b.size() + want.coords.norm())
                    && (r.circle - t.point(q.circle)).norm() <= rel * (b.size() + r.circle.coords.norm())
            });
            prop_assert!(hit, "{:?} -> {}", q, want);
        }
        // Four poses: curve points, circle points and Q_jk are the images.
        let (fa, fb) = (FourPositions::new(&m.poses[..4]).unwrap(), FourPositions::new(&moved[..4]).unwrap());
        let view = view_around(&fa, 2.0);
        for g in fa.center_point_curve().polylines(&view).into_iter().flatten().step_by(7) {
            let g2 = t.point(g);
            prop_assert!(on_curve(fb.center_point_curve(), &fb, g2, 10.0));
            if let (Ok(z), Ok(z2)) = (fa.circle_point(g), fb.circle_point(g2)) {
                prop_assert!((t.point(z) - z2).norm() <= 1e-6 * (fb.size() + z2.coords.norm()));
            }
        }
        for (q, q2) in fa.coincidence_points().iter().zip(fb.coincidence_points()) {
            if let (Some(c), Some(c2)) = (q.center, q2.center) {
                prop_assert!((t.point(c) - c2).norm() <= 1e-6 * (fb.size() + c2.coords.norm()));
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Tracing: every component in view, against a dense sign scan; scale-free.
// ---------------------------------------------------------------------------

/// `(l0 + l1 x + l2 y)(q0 + q1 x + q2 y + q3 x^2 + q4 xy + q5 y^2)`: two
/// singular points where the line meets the conic.
fn line_times_conic(l: [f64; 3], q: [f64; 6]) -> Cubic {
    let k = [
        l[0] * q[0],
        l[0] * q[1] + l[1] * q[0],
        l[0] * q[2] + l[2] * q[0],
        l[0] * q[3] + l[1] * q[1],
        l[0] * q[4] + l[1] * q[2] + l[2] * q[1],
        l[0] * q[5] + l[2] * q[2],
        l[1] * q[3],
        l[1] * q[4] + l[2] * q[3],
        l[1] * q[5] + l[2] * q[4],
        l[2] * q[5],
    ];
    Cubic::new(k).unwrap()
}

/// Every sign change of `f` between neighbours of an `n` by `n` grid over
/// `view` has a traced chord within the grid step plus twice the chord
/// tolerance; every traced vertex is on the curve.
fn check_against_scan(c: &Cubic, view: &Viewport, n: usize) -> Result<usize, TestCaseError> {
    let trace = c.trace(view, None).unwrap();
    let polys = trace.polylines();
    let (w, h) = view.size();
    let (dx, dy) = (w / n as f64, h / n as f64);
    let at = |i: usize, j: usize| Point2::new(view.xmin + dx * i as f64, view.ymin + dy * j as f64);
    let vals: Vec<Vec<f64>> = (0..=n)
        .map(|j| (0..=n).map(|i| c.evaluate(at(i, j))).collect())
        .collect();
    let mut changes = 0;
    for j in 0..=n {
        for i in 0..=n {
            for (i2, j2) in [(i + 1, j), (i, j + 1)] {
                if i2 > n || j2 > n {
                    continue;
                }
                let (a, b) = (vals[j][i], vals[j2][i2]);
                if a == 0.0 || b == 0.0 || (a < 0.0) == (b < 0.0) {
                    continue;
                }
                changes += 1;
                let mid = Point2::from((at(i, j).coords + at(i2, j2).coords) * 0.5);
                let d = poly_dist(&polys, mid);
                prop_assert!(
                    d <= dx.max(dy) + 2.0 * trace.tolerance,
                    "sign change at {} has no trace within {}",
                    mid,
                    d
                );
            }
        }
    }
    let diag = view.diagonal();
    let (k, o, s) = c.local_coefficients();
    let kmax = k.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for p in polys.iter().flatten() {
        // On the curve: by the first-order distance, or (at a singular
        // point, where that means nothing) by the value at rounding level.
        let r = (p - o).norm() / s;
        let on = c.distance_estimate(*p) <= 1e-9 * diag
            || c.evaluate(*p).abs() <= 1e-13 * kmax * (1.0 + r).powi(3);
        prop_assert!(on, "{} off the curve by {}", p, c.distance_estimate(*p));
        prop_assert!(
            view.contains(*p)
                || (p.x - p.x.clamp(view.xmin, view.xmax))
                    .abs()
                    .max((p.y - p.y.clamp(view.ymin, view.ymax)).abs())
                    <= 1e-9 * diag
        );
    }
    // A component with a closed polyline is bounded and closes exactly.
    for k in &trace.components {
        if k.closed {
            prop_assert!(k.bounded);
            let l = &k.polylines[0];
            prop_assert_eq!(l[0], l[l.len() - 1]);
        }
    }
    Ok(changes)
}

proptest! {
    #![proptest_config(cases(64))]

    #[test]
    fn the_trace_finds_every_component_of_a_center_point_curve(poses in random_poses(4), h in 0.5f64..20.0, off in (-3.0f64..3.0, -3.0f64..3.0)) {
        prop_assume!(rotations_at_least(&poses, 0.02));
        let four = FourPositions::new(&poses).unwrap();
        let c = centroid(four.poses()) + Vector2::new(off.0, off.1) * four.size();
        let r = h * four.size();
        let view = Viewport::new(c.x - r, c.x + r, c.y - r, c.y + r).unwrap();
        check_against_scan(four.center_point_curve(), &view, 160)?;
        check_against_scan(four.circle_point_curve(), &view, 160)?;
    }

    #[test]
    fn the_trace_finds_every_component_of_a_random_cubic(k in prop::array::uniform10(-1.0f64..1.0), h in 0.2f64..10.0) {
        prop_assume!(k[6..].iter().any(|v| v.abs() > 0.05));
        let c = Cubic::new(k).unwrap();
        let view = Viewport::new(-h, h, -0.7 * h, 1.3 * h).unwrap();
        check_against_scan(&c, &view, 160)?;
    }

    #[test]
    fn the_trace_finds_every_component_of_a_line_times_a_conic(
        l in prop::array::uniform3(-1.0f64..1.0),
        q in prop::array::uniform6(-1.0f64..1.0),
        h in 0.5f64..5.0,
    ) {
        prop_assume!(l[1].abs() + l[2].abs() > 0.1);
        let view = Viewport::new(-h, h, -h, 1.1 * h).unwrap();
        check_against_scan(&line_times_conic(l, q), &view, 160)?;
    }

    #[test]
    fn the_trace_is_scale_free(poses in random_poses(4), h in 0.5f64..6.0) {
        prop_assume!(rotations_at_least(&poses, 0.05));
        let four = FourPositions::new(&poses).unwrap();
        let base = view_around(&four, h);
        let traced: Vec<_> = [1e-3, 1e3].iter().map(|&f| {
            let s = Similarity::new(f, 0.0, Vector2::zeros()).unwrap();
            let scaled: Vec<Pose> = poses.iter().map(|p| s.pose(p)).collect();
            let four = FourPositions::new(&scaled).unwrap();
            let v = Viewport::new(base.xmin * f, base.xmax * f, base.ymin * f, base.ymax * f).unwrap();
            let t = four.center_point_curve().trace(&v, None).unwrap();
            // Back to the unit scale.
            let polys: Vec<Vec<Point2<f64>>> = t.polylines().into_iter()
                .map(|l| l.into_iter().map(|p| Point2::from(p.coords / f)).collect()).collect();
            (t.in_view(), polys, t.tolerance / f)
        }).collect();
        prop_assert_eq!(traced[0].0, traced[1].0);
        let tol = traced[0].2;
        for (a, b) in [(0, 1), (1, 0)] {
            for p in traced[a].1.iter().flatten() {
                let d = poly_dist(&traced[b].1, *p);
                prop_assert!(d <= 2.0 * tol, "{} is {} from the other trace", p, d);
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Errors.
// ---------------------------------------------------------------------------

#[test]
fn bad_input_is_a_typed_error() {
    let poses = example_poses();
    // The wrong number of poses: the error names what is needed and what
    // was passed.
    assert!(matches!(
        FourPositions::new(&poses[..3]),
        Err(Error::InvalidInput(InvalidInput::NeedsPoses {
            required: 4,
            found: 3,
            ..
        }))
    ));
    assert!(matches!(
        FivePositions::new(&poses[..4]),
        Err(Error::InvalidInput(InvalidInput::NeedsPoses {
            required: 5,
            found: 4,
            ..
        }))
    ));
    let mut bad = poses;
    bad[2].position.x = f64::NAN;
    assert!(matches!(
        FourPositions::new(&bad[..4]),
        Err(Error::InvalidInput(InvalidInput::NotFinite { .. }))
    ));
    let mut same = poses;
    same[3] = same[1];
    assert!(matches!(
        FourPositions::new(&same[..4]),
        Err(Error::Degenerate(DegenerateError::CoincidentPoses {
            i: 2,
            j: 4
        }))
    ));
    // Rotations about one point.
    let c = Point2::new(1.0, -2.0);
    let rot: Vec<Pose> = [0.0f64, 0.5, 1.3, 2.0, -1.0]
        .iter()
        .map(|&a| {
            let v = Vector2::new(3.0, 1.0);
            let (s, co) = a.sin_cos();
            Pose {
                position: c + Vector2::new(co * v.x - s * v.y, s * v.x + co * v.y),
                angle: a + 0.2,
            }
        })
        .collect();
    assert!(matches!(
        FourPositions::new(&rot[..4]),
        Err(Error::Degenerate(DegenerateError::CoincidentPoles { .. }))
    ));
    // Four of five poses rotations about one point: a continuum of dyads.
    for at in 0..5 {
        let mut five_rot: Vec<Pose> = rot[..4].to_vec();
        five_rot.insert(at, Pose::new(7.0, 3.0, 0.4));
        assert!(matches!(
            FivePositions::new(&five_rot),
            Err(Error::Degenerate(DegenerateError::CoincidentPoles { .. }))
        ));
    }
    // All one angle.
    let flat: Vec<Pose> = poses.iter().map(|p| Pose { angle: 0.3, ..*p }).collect();
    assert!(FivePositions::new(&flat).is_err());
    // Off the curve: the error carries the distance.
    let four = FourPositions::new(&poses[..4]).unwrap();
    let e = four.circle_point(Point2::new(2.0, 1.0)).unwrap_err();
    assert!(matches!(
        e,
        Error::InvalidInput(InvalidInput::OffCurve { .. })
    ));
    assert!(e.to_string().contains("from its curve"), "{e}");
    assert!(four.center_point(Point2::new(f64::INFINITY, 0.0)).is_err());
    assert!(four.displace(Point2::origin(), 0, 2).is_err());
    assert!(four.dyad_runs(0).is_err());
    // A dyad that does not pass the poses.
    let good = Dyad::new(
        Point2::new(0.0, 0.0),
        Point2::new(1.4095389312, 0.5130302150),
    );
    let wrong = Dyad::new(Point2::new(0.5, 0.0), Point2::new(1.4, 0.5));
    assert!(four.drive(&good, &wrong).is_err());
    assert!(four.drive(&good, &good).is_err());
    assert!(four.filemon(&wrong).is_err());
}

/// The case a proptest found in CI: a driving dyad 1e-5 from the end of a
/// branch arc, pose 3 within 1e-13 rad of the input's limit. The library
/// calls it defective (pose 3 is, barely, in the other assembly mode); the
/// dense simulation cannot tell the modes apart there and is not asked.
#[test]
fn a_dyad_next_to_an_arc_end_is_not_judged_by_simulation() {
    let p = LinkParams {
        lengths: [
            2.4009348297807223,
            1.950676302701005,
            1.9015306081725472,
            2.927401672198105,
        ],
        mode: true,
        steps: [
            0.2442556875482497,
            0.9389568054421229,
            0.4394077574987419,
            0.4180496178509726,
            0.0,
        ],
        ..LinkParams::default()
    };
    check_made_branch(&p).unwrap();
}

/// Found by a proptest at 6000 cases: the line meets the conic almost
/// tangentially, and a Newton step from a vertex already on the curve to
/// rounding, where the gradient is at rounding level too, threw it 4e-6
/// off. A step is now kept only when it lowers `|f|`.
#[test]
fn a_trace_next_to_a_near_tacnode_keeps_its_vertices_on_the_curve() {
    let l = [-0.3768814766514796, 0.724486559805408, -0.3684458072965749];
    let q = [
        -0.0055934709858228415,
        0.4800742363433919,
        0.3998486504770526,
        -0.7265224617434285,
        0.9215757520607185,
        0.3680641172861042,
    ];
    let h = 1.5047661321638894;
    let view = Viewport::new(-h, h, -h, 1.1 * h).unwrap();
    check_against_scan(&line_times_conic(l, q), &view, 160).unwrap();
}

/// Found by a proptest at 6000 cases: a driven circle point 450 task
/// sizes away, whose Filemon lines met the circle-point curve 1.6e-7 off
/// it (the restriction of the cubic to a line from so far loses digits).
/// The ends are now refined on the curve's own value.
#[test]
fn the_arc_ends_of_a_far_driven_circle_point_lie_on_the_curve() {
    let poses = [
        Pose::new(1.8371786857363674, -1.0059924690702386, 2.6187775901390733),
        Pose::new(
            -3.3928518147162623,
            -3.8703916971560206,
            -0.21029050079088368,
        ),
        Pose::new(-2.875901523528294, -4.904670886061615, 0.12995289982316804),
        Pose::new(2.9642855728779325, 3.8268150254888513, 0.7129450846503972),
    ];
    let four = FourPositions::new(&poses).unwrap();
    let runs = four.dyad_runs(200).unwrap();
    let all: Vec<_> = runs.iter().flatten().collect();
    let driven = all[298 % all.len()].dyad();
    assert!(driven.circle.coords.norm() > 400.0 * four.size());
    assert!(!four.filemon(&driven).unwrap().arc_ends().is_empty());
    check_branch(&four, &driven, 80).unwrap();
}

/// Found by a proptest at 8000 cases: a fourth Burmester center 4e4 task
/// sizes away (nearly a slider), where Newton's steps wandered at rounding
/// level and never passed the step test, so only three were reported.
#[test]
fn a_burmester_point_far_away_is_found() {
    let p = LinkParams {
        lengths: [
            4.139678597554209,
            1.2244154065317534,
            1.2283177285174358,
            3.845488805709637,
        ],
        origin: (1.8520941560589466, 2.371859856562954),
        ground_angle: -2.582971492668893,
        local: (0.0, -2.341572886232787),
        mode: false,
        steps: [
            0.35408369617892926,
            0.654575652077299,
            0.2668776781367882,
            0.04258549813998431,
            0.16097427992558913,
        ],
        ..LinkParams::default()
    };
    let m = made(&p, 5, 0.05).unwrap();
    linkage_burmester_points(&m).unwrap();
    let five = FivePositions::new(&m.poses).unwrap();
    assert_eq!(five.burmester_points().len(), 4);
    let far = five.burmester_points()[3];
    assert!(far.center.coords.norm() > 1e4 * five.size(), "{far:?}");
}

/// Found by a proptest at 8000 cases: all six poles within a tenth of
/// the task of each other, where the circle-to-center map is so
/// ill-conditioned that exact arc ends' centers lie 3e-7 off the
/// center-point curve while their circle points' positions are concyclic
/// about them to 1e-10; the test now accepts either.
#[test]
fn arc_ends_of_a_task_with_clustered_poles_have_their_centers() {
    let p = LinkParams {
        lengths: [
            3.6554986846927826,
            1.353807071077848,
            1.2036300128016872,
            3.5095096521896996,
        ],
        origin: (-2.6028813812279616, 0.0),
        ground_angle: 1.634484193703516,
        local: (-0.8738919061070446, 2.2882187084173116),
        mode: false,
        steps: [0.6742261564121641, 0.0, 0.0, 0.7657387520633812, 0.0],
        ..LinkParams::default()
    };
    check_made_branch(&p).unwrap();
}

/// The five-pose task made from `p` and the same task moved by `t`, each
/// with its four Burmester points (asserted).
fn four_points_here_and_moved(
    p: &LinkParams,
    t: &Similarity,
) -> (Made, FivePositions, FivePositions) {
    let m = made(p, 5, 0.05).unwrap();
    let a = FivePositions::new(&m.poses).unwrap();
    let b = FivePositions::new(&moved(&m.poses, t)).unwrap();
    assert_eq!(a.burmester_points().len(), 4);
    assert_eq!(b.burmester_points().len(), 4);
    (m, a, b)
}

/// Found by a proptest at 8000 cases: the same task scaled by 1e-3 found
/// three Burmester points where the original found four (the fourth 50
/// task sizes away, where Newton stalled at rounding level).
#[test]
fn a_scaled_task_keeps_its_far_burmester_point() {
    let p = LinkParams {
        lengths: [
            3.9361170721782024,
            1.3720121934984193,
            1.0440024700927335,
            3.9484796593431506,
        ],
        origin: (-0.8070931334949566, 0.0),
        ground_angle: -0.531762453575318,
        local: (2.860326328990715, -0.5699760760505732),
        offset: 1.2337597139419272,
        mode: false,
        steps: [
            0.9197864874507639,
            0.12541726827279356,
            0.0,
            0.9904258295751533,
            0.34616014599613404,
        ],
        ..LinkParams::default()
    };
    let t = Similarity::new(0.001, 1.071435421936352, Vector2::zeros()).unwrap();
    let (_, a, b) = four_points_here_and_moved(&p, &t);
    for q in a.burmester_points() {
        let want = t.point(q.center);
        assert!(
            b.burmester_points()
                .iter()
                .any(|r| (r.center - want).norm() <= 1e-7 * (b.size() + want.coords.norm())),
            "{q:?}"
        );
    }
}

/// Found by a proptest at 10000 cases: the circle points of centers going
/// out along an asymptote approach the slider's circle point like
/// 4e3 task sizes / d, so at 1e6 task sizes still 7e-4 away.
#[test]
fn circle_points_tend_to_the_slider_s_along_a_slow_asymptote() {
    let poses = [
        Pose::new(2.259021809470926, -3.9957391249050564, 1.2707903453229306),
        Pose::new(2.4037236749343225, 4.532968551538142, -0.8811662141069733),
        Pose::new(-3.4161065004816096, -2.0098274178247593, 2.863692112197072),
        Pose::new(-2.2356538019160417, 3.9649591141074634, -2.0548479948593625),
    ];
    let four = FourPositions::new(&poses).unwrap();
    let (s, o) = (four.size(), centroid(four.poses()));
    let sliders = four.slider_circle_points();
    assert_eq!(sliders.len(), 1);
    let u = four.center_point_curve().asymptotic_directions()[0];
    let gaps: Vec<f64> = [1e5, 1e6, 1e7]
        .iter()
        .map(|d| {
            let far = four.center_point_curve().intersect_line(&burmester::Line {
                point: o + u * (d * s),
                direction: Vector2::new(-u.y, u.x),
            });
            let z = four.circle_point(far[0]).unwrap();
            (z - sliders[0]).norm() / s
        })
        .collect();
    for w in gaps.windows(2) {
        assert!(w[1] < 0.2 * w[0], "{gaps:?}");
    }
}

/// [`check_branch`] for both dyads of the linkage `p` makes (four poses).
fn check_made_branch(p: &LinkParams) -> Result<(), TestCaseError> {
    let (m, four) = made_four(p)?;
    check_branch(&four, &m.b, 120)?;
    check_branch(&four, &m.a, 120)
}

/// Found by a proptest at 3000 cases: a random driven dyad whose circle
/// point lies two million units (some 10^5 task sizes) out, so that pose
/// 1's Filemon line meets the circle-point curve near the poses only after
/// many Newton steps from the restriction's roots (four left the arc ends
/// 0.15 off). The branch verdict along the curve is not checked here: with
/// the lines parallel to within 1e-6 it changes once away from the arc ends
/// (the random-dyad proptest keeps to dyads under a thousand task sizes).
#[test]
fn an_arc_end_from_a_far_circle_point_lies_on_the_curve() {
    let poses = [
        Pose::new(4.641360405143269, -1.7165934782247947, 3.120288350885408),
        Pose::new(2.3648246473083474, 0.003006680240371271, -2.803691951680992),
        Pose::new(-1.261870370866735, -3.506028890705129, 2.0049922778209663),
        Pose::new(-4.966618338463879, -4.95605368513093, 0.9942321485511808),
    ];
    let four = FourPositions::new(&poses).unwrap();
    let runs = four.dyad_runs(200).unwrap();
    let all: Vec<_> = runs.iter().flatten().collect();
    let driven = all[324 % all.len()].dyad();
    assert!(driven.length() > 1e5 * four.size());
    let arcs = four.filemon(&driven).unwrap();
    assert!(!arcs.arc_ends().is_empty());
    for l in arcs.all_lines() {
        for h in four.circle_point_curve().intersect_line(&l) {
            assert!(on_curve(four.circle_point_curve(), &four, h, 1.0), "{h}");
        }
    }
    for e in arcs.arc_ends() {
        assert!(
            on_curve(four.circle_point_curve(), &four, e.circle, 1.0),
            "{e:?}"
        );
    }
}

/// Found by a proptest at 6000 cases: a sample of the compatibility
/// linkage (a dyad to 1e-8 by its spread) 5.4 times the curve tolerance off
/// the center-point cubic by first-order distance (no longer given: see the
/// last assertion).
#[test]
fn a_compatibility_sample_is_near_the_cubic() {
    let poses = [
        Pose::new(3.4082565049608227, -2.090866596928837, 0.7952378556904827),
        Pose::new(-4.044187607465545, 1.5787099676903678, 2.9538587336093656),
        Pose::new(-3.3845653682438424, 3.1181191963766173, 2.800116595547681),
        Pose::new(4.104106623170131, 1.863725163670292, -0.9910282066134453),
    ];
    let four = FourPositions::new(&poses).unwrap();
    let s = four.size();
    let c = four.center_point_curve();
    let (mut worst, mut n) = (0.0f64, 0);
    for a in four.dyad_runs(3000).unwrap().iter().flatten() {
        if a.center.coords.norm() < 1e3 * s {
            assert!(spread(&poses, &a.dyad()) < 1e-8);
            assert!(on_curve(c, &four, a.center, 10.0), "{}", a.center);
            let tol = ON_CURVE_TOLERANCE * (s + (a.center - centroid(four.poses())).norm());
            worst = worst.max(c.distance_estimate(a.center) / tol);
            n += 1;
        }
    }
    // Since `dyad_at` gives only dyads that the on-curve test takes back
    // (issue 24), the samples that were up to 5.4 tolerances off by the
    // first-order distance are not given: every sample is now within the
    // tolerance by that distance alone (it was `1 < worst < 10`).
    assert!(n > 1000 && worst <= 1.0, "{n} samples, worst {worst}");
}

/// Found by a proptest at 6000 cases: a linkage close to a kite (ground
/// about the rocker, crank about the coupler), whose circle point sits next
/// to a near-singular point of the circle-point curve: its value is 1.5e-13
/// but its gradient 6e-6, so its first-order distance was 4.4 times the
/// tolerance. That was the rounding of the plain f64 coefficients, not the
/// curve (curv38, last assertion): the exact curve of this float task
/// (`fuzz/reference/coefficients.py`, `kite`) puts the circle point
/// `4.9e-15` off by first-order distance, and the exact curves of the task
/// with every number moved by one ulp (8 sign patterns) `1.0e-15` to
/// `1.1e-14`; the plain coefficients were `4.1e-13` of the largest off the
/// exact ones (`2.4e-8` of first-order distance there).
#[test]
fn a_kite_s_circle_point_is_near_a_nearly_singular_curve() {
    let p = LinkParams {
        lengths: [
            3.6082039414409532,
            1.5565291780617119,
            1.5487947772530977,
            3.6076089507115108,
        ],
        local: (0.0, -2.3823764193486823),
        mode: false,
        steps: [0.9766049468817277, 0.0, 0.0, 0.0, 0.0],
        ..LinkParams::default()
    };
    let m = made(&p, 4, 0.05).unwrap();
    let four = FourPositions::new(&m.poses).unwrap();
    let c = four.circle_point_curve();
    for d in [m.a, m.b] {
        assert!(on_curve(four.center_point_curve(), &four, d.center, 1.0));
        assert!(on_curve(c, &four, d.circle, 10.0), "{}", d.circle);
        assert!(c.evaluate(d.circle).abs() < 1e-12);
    }
    // The library's coefficients against the exact ones (normalised by the
    // largest; one ulp of the task moves them `2.8e-13`): measured `9.7e-15`
    // off. The circle point's first-order distance within a hundredth of
    // the tolerance: what the coefficients' own rounding to doubles allows
    // there (an ulp of the largest over the gradient, `5e-11`; measured
    // `1.4e-12`), where the plain ones put it 4.4 tolerances off.
    #[rustfmt::skip]
    let exact = [
        0.04781491940384491, -0.21047417100697288, 0.3003670833127072, 0.29379429146073865,
        -0.9747697889118524, 0.4838604342125753, -0.10344856156660247, 1.0,
        -0.10344856156660247, 1.0,
    ];
    let (local, _, _) = c.local_coefficients();
    let err = local
        .iter()
        .zip(exact)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(err <= 3e-14, "{local:?} is {err:e} off");
    let tol = ON_CURVE_TOLERANCE * (four.size() + (m.b.circle - centroid(four.poses())).norm());
    let d = c.distance_estimate(m.b.circle);
    assert!(d <= 1e-2 * tol, "{d:e} against a tolerance of {tol:e}");
}

/// Found by a proptest at 6000 cases: a Burmester point 5e4 task sizes
/// out, found again in the task scaled by 1e-3, rotated and mirrored, 1.7e-7
/// of its distance away (both with residual zero): the curves meet there
/// at a small angle.
#[test]
fn a_far_burmester_point_moves_with_the_task() {
    let p = LinkParams {
        lengths: [
            2.3239301051696053,
            1.15496072205427,
            1.0508018189192656,
            2.2952575496547136,
        ],
        mode: false,
        steps: [
            0.5785779627324169,
            0.7046771697198466,
            0.24878669880456908,
            0.1682964988384916,
            0.6048728776739899,
        ],
        ..LinkParams::default()
    };
    let t = Similarity::new(0.001, 0.24495795146937174, Vector2::zeros())
        .unwrap()
        .mirrored();
    let (m, a, b) = four_points_here_and_moved(&p, &t);
    let mut far = 0;
    for q in a.burmester_points() {
        let want = t.point(q.center);
        let d = (q.center - centroid(&m.poses)).norm() / a.size();
        let err = b
            .burmester_points()
            .iter()
            .map(|r| (r.center - want).norm() / (b.size() + want.coords.norm()))
            .fold(f64::INFINITY, f64::min);
        if d > 1e4 {
            far += 1;
            assert!(err > 1e-7 && err < 1e-6, "{err}");
        } else {
            assert!(err < 1e-10, "{err} at {d} task sizes");
        }
    }
    assert_eq!(far, 1);
}

// ---------------------------------------------------------------------------
// Issue 24: the branch-free arcs in any view (item 1), the library's own
// points on its curves (item 4), the Burmester points near merging and of
// degenerate tasks (items 2 and 3).
// ---------------------------------------------------------------------------

/// The poses of issue 24, item 1.
fn issue24_arc_poses() -> Vec<Pose> {
    [
        (0.3870923432120442, -2.0070733230239854, -0.9799744195923201),
        (1.5137605007600652, -2.3672949991117136, -1.0598686177589811),
        (0.7569053408785356, -1.3360742238078, -1.2807591739581474),
        (0.573766942241772, -1.346572992188627, -1.2235828399262854),
    ]
    .iter()
    .map(|&(x, y, a)| Pose::new(x, y, a))
    .collect()
}

/// Where `p` lies on the polylines: the line, the segment and the distance
/// of the nearest segment.
fn locate(lines: &[Vec<Point2<f64>>], p: Point2<f64>) -> Option<(usize, usize, f64)> {
    let mut best: Option<(usize, usize, f64)> = None;
    for (li, l) in lines.iter().enumerate() {
        for (i, w) in l.windows(2).enumerate() {
            let d = seg_dist(p, w[0], w[1]);
            if best.is_none_or(|b| d < b.2) {
                best = Some((li, i, d));
            }
        }
    }
    best
}

/// The branch-free arcs of `fa` in `view` (the circle-point plane or the
/// center-point plane) against the curve traced 50 times finer and
/// classified point by point (`curve_branch`): every point of the fine
/// trace between two consecutive vertices of an arc is free, and every free
/// point of the fine trace lies on an arc (away from the exact arc ends and
/// `C0`/`C1`, within a millionth of the view of which the class is
/// rounding). Returns the number of fine points checked.
fn check_free_arcs_dense(
    four: &FourPositions,
    fa: &FilemonArcs,
    view: &Viewport,
    circle: bool,
) -> Result<usize, TestCaseError> {
    let (arcs, curve) = if circle {
        (
            fa.free_circle_arcs(view).unwrap(),
            four.circle_point_curve(),
        )
    } else {
        (
            fa.free_center_arcs(view).unwrap(),
            four.center_point_curve(),
        )
    };
    let class = |p: Point2<f64>| -> Option<Branch> {
        if circle {
            Some(fa.classify_circle_point(p))
        } else {
            fa.classify_center_point(p).ok()
        }
    };
    let mut marks: Vec<Point2<f64>> = fa
        .arc_ends()
        .iter()
        .filter_map(|e| if circle { Some(e.circle) } else { e.center })
        .collect();
    let driven = fa.driven().crank("the test").unwrap();
    marks.push(if circle { driven.circle } else { driven.center });
    let diag = (view.xmax - view.xmin).hypot(view.ymax - view.ymin);
    let near_mark = |p: Point2<f64>| marks.iter().any(|m| (m - p).norm() <= 1e-6 * diag);
    let fine = curve.trace(view, Some(2e-5 * diag)).unwrap().polylines();
    // Between two vertices of an arc: free.
    for arc in &arcs {
        for w in arc.windows(2) {
            let (Some((la, sa, da)), Some((lb, sb, db))) =
                (locate(&fine, w[0]), locate(&fine, w[1]))
            else {
                continue;
            };
            if la != lb || da > 1e-6 * diag || db > 1e-6 * diag {
                continue;
            }
            let line = &fine[la];
            let (lo, hi) = (sa.min(sb), sa.max(sb));
            // The shorter way round a closed line.
            let closed = line[0] == line[line.len() - 1];
            let idx: Vec<usize> = if closed && 2 * (hi - lo) > line.len() {
                (hi + 1..line.len()).chain(0..=lo).collect()
            } else {
                (lo + 1..=hi).collect()
            };
            for i in idx {
                let p = line[i];
                if near_mark(p) {
                    continue;
                }
                let c = class(p);
                prop_assert!(
                    c == Some(Branch::Free) || c.is_none(),
                    "the chord {} - {} of an arc passes {} ({:?}) in view {:?}",
                    w[0],
                    w[1],
                    p,
                    c,
                    view
                );
            }
        }
    }
    // Every free point on an arc.
    let mut n = 0;
    for p in fine.iter().flatten() {
        if near_mark(*p) {
            continue;
        }
        n += 1;
        if class(*p) == Some(Branch::Free) {
            let d = poly_dist(&arcs, *p);
            prop_assert!(
                d <= 2e-3 * diag,
                "free point {} is {} from every arc in view {:?}",
                p,
                d,
                view
            );
        }
    }
    Ok(n)
}

/// Driving dyads at vertices of the center-point arcs (and at fine points
/// off them) against the built linkage: free on an arc, defective off.
fn check_free_arcs_by_driving(
    four: &FourPositions,
    fa: &FilemonArcs,
    view: &Viewport,
) -> Result<(), TestCaseError> {
    let driven = fa.driven().crank("the test").unwrap();
    let s = four.size();
    let arcs = fa.free_center_arcs(view).unwrap();
    let fine = four.center_point_curve().polylines(view);
    let diag = (view.xmax - view.xmin).hypot(view.ymax - view.ymin);
    for p in fine.iter().flatten().step_by(5) {
        if (p - driven.center).norm() < 1e-3 * s || p.coords.norm() > 1e3 * s {
            continue;
        }
        let Ok(a) = four.dyad_from_center(*p) else {
            continue;
        };
        if (a.circle - driven.circle).norm() < 1e-3 * s {
            continue;
        }
        let Ok(drive) = four.drive(&a, &driven) else {
            continue;
        };
        if drive.modes.iter().any(|m| m.is_none()) {
            continue;
        }
        let on_arc = poly_dist(&arcs, *p) <= 1e-9 * diag;
        if on_arc {
            prop_assert!(
                drive.is_branch_free(),
                "{} is on an arc: {:?}",
                p,
                drive.modes
            );
        } else if !drive.is_branch_free() {
            prop_assert!(fa.classify_center_point(*p).unwrap() != Branch::Free);
        }
    }
    Ok(())
}

#[test]
fn issue24_free_arcs_next_to_c0_are_the_same_in_every_view() {
    let poses = issue24_arc_poses();
    let four = FourPositions::new(&poses).unwrap();
    let c0 = Point2::new(3.832759076400307, -0.5455110379995003);
    let driven = four.dyad_from_center(c0).unwrap();
    let fa = four.filemon(&driven).unwrap();
    let big = Viewport::new(-15.84, 17.46, -18.42, 14.89).unwrap();
    let small = Viewport::new(c0.x - 0.6, c0.x + 0.6, c0.y - 0.6, c0.y + 0.6).unwrap();
    // The defective stretch from C0 to the arc end near (3.46561, -0.49479):
    // the curve's point near (3.612795, -0.522647) is defective, and on no
    // arc of either view.
    let target = Point2::new(3.612795, -0.522647);
    let curve = four.center_point_curve();
    let m = curve
        .intersect_line(&burmester::Line {
            point: target,
            direction: curve.gradient(target),
        })
        .into_iter()
        .min_by(|a, b| (a - target).norm().total_cmp(&(b - target).norm()))
        .unwrap();
    assert!((m - target).norm() < 1e-6);
    assert_eq!(fa.classify_center_point(m).unwrap(), Branch::Defective);
    let a = four.dyad_from_center(m).unwrap();
    assert!(!four.drive(&a, &driven).unwrap().is_branch_free());
    for view in [&big, &small] {
        let arcs = fa.free_center_arcs(view).unwrap();
        assert!(!arcs.is_empty());
        assert!(poly_dist(&arcs, m) > 1e-3, "{view:?}");
        // The arc next to C0 starts at the arc end, in both views.
        let end = arcs
            .iter()
            .flat_map(|a| [a[0], a[a.len() - 1]])
            .min_by(|a, b| (a - c0).norm().total_cmp(&(b - c0).norm()))
            .unwrap();
        assert!(
            (end - Point2::new(3.46561, -0.49479)).norm() < 1e-4,
            "{end} in {view:?}"
        );
        check_free_arcs_dense(&four, &fa, view, false).unwrap();
        check_free_arcs_dense(&four, &fa, view, true).unwrap();
        check_free_arcs_by_driving(&four, &fa, view).unwrap();
    }
}

/// The driven center of random tasks and views: `t` picks a driven dyad
/// on the curve, `view` a viewport (its center in task sizes from the
/// centroid and its half-width in task sizes, or around `C0`).
fn check_arcs_in_views(
    poses: &[Pose],
    pick: usize,
    views: &[(f64, f64, f64, bool)],
) -> Result<(), TestCaseError> {
    let Ok(four) = FourPositions::new(poses) else {
        return Ok(());
    };
    let Ok(runs) = four.dyad_runs(100) else {
        return Ok(());
    };
    let all: Vec<_> = runs.iter().flatten().collect();
    if all.is_empty() {
        return Ok(());
    }
    let driven = all[pick % all.len()].dyad();
    let s = four.size();
    if !(driven.length() > 1e-2 * s && driven.length() < 1e3 * s) {
        return Ok(());
    }
    let Ok(fa) = four.filemon(&driven) else {
        return Ok(());
    };
    let c = centroid(four.poses());
    for &(x, y, h, at_c0) in views {
        let center = if at_c0 {
            driven.center + Vector2::new(x, y) * (0.1 * h * s)
        } else {
            c + Vector2::new(x, y) * s
        };
        let r = h * s;
        let view = Viewport::new(center.x - r, center.x + r, center.y - r, center.y + r).unwrap();
        check_free_arcs_dense(&four, &fa, &view, false)?;
        check_free_arcs_dense(&four, &fa, &view, true)?;
        check_free_arcs_by_driving(&four, &fa, &view)?;
    }
    Ok(())
}

fn views() -> impl Strategy<Value = Vec<(f64, f64, f64, bool)>> {
    prop::collection::vec(
        (
            -3.0f64..3.0,
            -3.0f64..3.0,
            prop_oneof![0.05f64..0.5, 0.5f64..8.0],
            any::<bool>(),
        ),
        2,
    )
}

proptest! {
    #![proptest_config(cases(24))]

    /// Item 1's target: the arcs against `curve_branch` on a fine trace
    /// and against the built linkage, in views of any size and place
    /// (around `C0` too).
    #[test]
    fn issue24_free_arcs_match_curve_branch_in_any_view(
        p in link_params(), pick in 0usize..1000, v in views(), t in similarity(),
    ) {
        let m = made_case(&p, 4)?;
        let moved: Vec<Pose> = m.poses.iter().map(|q| t.pose(q)).collect();
        check_arcs_in_views(&moved, pick, &v)?;
    }

    #[test]
    fn issue24_free_arcs_of_random_tasks_match_curve_branch(
        poses in random_poses(4), pick in 0usize..1000, v in views(),
    ) {
        prop_assume!(rotations_at_least(&poses, 0.1));
        check_arcs_in_views(&poses, pick, &v)?;
    }
}

/// The poses of issue 24, item 4, moved by `(dx, dy)`.
fn issue24_near_poses(dx: f64, dy: f64) -> Vec<Pose> {
    [
        (-0.701010693048561, 4.993010936525712, -1.3224198951516195),
        (-1.2501494308566816, 4.943533773269543, -1.2288929794391865),
        (-1.7983933700082968, 4.823460975776655, -1.1353740707007742),
        (-2.3357200981193205, 4.631763723094262, -1.041618308198372),
    ]
    .iter()
    .map(|&(x, y, a)| Pose::new(x + dx, y + dy, a))
    .collect()
}

/// Every dyad the library puts on the curves is accepted back: the
/// crank-rotation samples and parameter samples (the pair map's), the
/// traced vertices of both curves, the poles and the arc ends. Returns how
/// many points were checked.
fn check_own_points(four: &FourPositions, n: usize) -> Result<usize, TestCaseError> {
    let mut count = 0;
    let dyads = common::curve_dyads::own_curve_dyads(four, n);
    for d in &dyads {
        count += 1;
        let z = four.circle_point(d.center);
        prop_assert!(
            z.is_ok() || matches!(z, Err(Error::Degenerate(_))),
            "center {} refused: {:?}",
            d.center,
            z
        );
        prop_assert!(four.curve_dyad(d.center).is_ok() || z.is_err());
        let g = four.center_point(d.circle);
        prop_assert!(
            g.is_ok() || matches!(g, Err(Error::Degenerate(_))),
            "circle point {} refused: {:?}",
            d.circle,
            g
        );
    }
    let view = view_around(four, 4.0);
    // Each curve's traced vertices, mapped to the other curve.
    type Map = fn(&FourPositions, Point2<f64>) -> burmester::Result<Point2<f64>>;
    let curves: [(&Cubic, Map); 2] = [
        (four.center_point_curve(), FourPositions::circle_point),
        (four.circle_point_curve(), FourPositions::center_point),
    ];
    for (curve, map) in curves {
        for v in curve.polylines(&view).into_iter().flatten() {
            count += 1;
            let w = map(four, v);
            prop_assert!(!matches!(w, Err(Error::InvalidInput(_))), "{}: {:?}", v, w);
        }
    }
    for p in four.poles().iter().filter_map(|p| p.point) {
        count += 1;
        let z = four.circle_point(p);
        prop_assert!(
            !matches!(z, Err(Error::InvalidInput(_))),
            "pole {}: {:?}",
            p,
            z
        );
    }
    for d in dyads.iter().step_by(dyads.len().max(8) / 8) {
        if let Ok(fa) = four.filemon(&d.dyad()) {
            for e in fa.arc_ends() {
                count += 1;
                let g = four.center_point(e.circle);
                prop_assert!(
                    !matches!(g, Err(Error::InvalidInput(_))),
                    "{:?}: {:?}",
                    e,
                    g
                );
            }
        }
    }
    Ok(count)
}

#[test]
fn issue24_the_library_accepts_its_own_dyads_in_every_frame() {
    for (dx, dy) in [(0.0, 0.0), (0.0, 1.0), (1e3, -1e3), (0.5, 0.25)] {
        let four = FourPositions::new(&issue24_near_poses(dx, dy)).unwrap();
        let runs = four.dyad_runs(200).unwrap();
        let dyads: Vec<_> = runs.iter().flatten().collect();
        assert_eq!(dyads.len(), 404);
        for d in &dyads {
            four.circle_point(d.center).unwrap();
            four.curve_dyad(d.center).unwrap();
            four.center_point(d.circle).unwrap();
            let fa = four.filemon(&d.dyad());
            assert!(!matches!(
                fa,
                Err(Error::InvalidInput(InvalidInput::OffCurve { .. }))
            ));
        }
        // Pairs of them build (the drive of `four_bar`).
        for w in dyads.windows(2).step_by(13) {
            let r = four.drive(&w[0].dyad(), &w[1].dyad());
            assert!(!matches!(
                r,
                Err(Error::InvalidInput(InvalidInput::OffCurve { .. }))
            ));
        }
        check_own_points(&four, 200).unwrap();
    }
    // The on-curve test moves with the task: a point accepted in one frame
    // is accepted moved, turned, scaled and mirrored.
    let four = FourPositions::new(&issue24_near_poses(0.0, 0.0)).unwrap();
    let dyads: Vec<_> = four.dyad_runs(200).unwrap().into_iter().flatten().collect();
    for t in [
        Similarity::new(1.0, 0.0, Vector2::new(0.0, 1.0)).unwrap(),
        Similarity::new(1e3, 1.0, Vector2::new(-3.0, 7.0)).unwrap(),
        Similarity::new(1e-3, -2.0, Vector2::new(0.1, 0.0))
            .unwrap()
            .mirrored(),
    ] {
        let moved: Vec<Pose> = four.poses().iter().map(|q| t.pose(q)).collect();
        let f2 = FourPositions::new(&moved).unwrap();
        for d in &dyads {
            f2.circle_point(t.point(d.center)).unwrap();
        }
    }
}

/// Four poses that are nearly rotations about one point (the issue's
/// case: the coefficients of the curves cancel to a thousandth of their
/// terms and the curve has a nearly singular point): rotations about a
/// random center by random small or large steps, each pose then moved by
/// a random fraction (down to `1e-4`) of the task.
fn near_rotations() -> impl Strategy<Value = Vec<Pose>> {
    (
        (-5.0f64..5.0, -5.0f64..5.0),
        0.5f64..6.0,
        -PI..PI,
        prop::array::uniform3(prop_oneof![0.02f64..0.2, -0.2f64..-0.02, 0.2f64..2.0]),
        prop::array::uniform4((-1.0f64..1.0, -1.0f64..1.0)),
        -4.0f64..-1.0,
    )
        .prop_map(|(c, r, a0, steps, jitter, e)| {
            let mut a = a0;
            let mut out = Vec::new();
            for k in 0..4 {
                if k > 0 {
                    a += steps[k - 1];
                }
                let j = 10f64.powf(e) * r;
                let p = Point2::new(
                    c.0 + r * a.cos() + j * jitter[k].0,
                    c.1 + r * a.sin() + j * jitter[k].1,
                );
                out.push(Pose::new(p.x, p.y, a - 1.0));
            }
            out
        })
}

proptest! {
    #![proptest_config(cases(48))]

    /// Item 4's target: every point the library computes on the curves is
    /// accepted back by them, for tasks of nearly equal rotations (curves
    /// with nearly singular points, coefficients that cancel) moved,
    /// turned, scaled and mirrored anywhere.
    #[test]
    fn issue24_own_points_are_on_the_curves_in_any_frame(
        poses in prop_oneof![near_rotations(), random_poses(4)],
        t in similarity(),
    ) {
        let moved: Vec<Pose> = poses.iter().map(|q| t.pose(q)).collect();
        let Ok(four) = FourPositions::new(&moved) else { return Ok(()); };
        check_own_points(&four, 60)?;
    }
}

/// The poses of issue 24, item 2: two real Burmester points and a pair of
/// complex ones with an imaginary part of 2.3e-6 (mpmath reference,
/// `tests/python/burmester_reference.py`).
fn issue24_merging_poses(x5: f64) -> Vec<Pose> {
    [
        (-1.2496027059316173, 0.7130452692752762, -0.6572924231027988),
        (0.27468559919591734, 0.7224592815050642, -3.019408291601917),
        (-2.318244562336992, 2.2813029947864187, -1.6503688624061708),
        (
            -1.7723011037557788,
            3.7378394481945625,
            -0.11145257321306046,
        ),
        (x5, -0.03637049136529685, 1.09643912732506),
    ]
    .iter()
    .map(|&(x, y, a)| Pose::new(x, y, a))
    .collect()
}

/// Five poses in the frame of `t`.
fn moved(poses: &[Pose], t: &Similarity) -> Vec<Pose> {
    poses.iter().map(|q| t.pose(q)).collect()
}

/// Some frames: as given, moved, turned, scaled, mirrored.
fn frames() -> Vec<Similarity> {
    vec![
        Similarity::new(1.0, 0.0, Vector2::zeros()).unwrap(),
        Similarity::new(1.0, 0.0, Vector2::new(0.0, 1.0)).unwrap(),
        Similarity::new(3.0, 0.0, Vector2::zeros()).unwrap(),
        Similarity::new(1.0, 1.0, Vector2::new(0.3, -0.2)).unwrap(),
        Similarity::new(1e-3, -2.5, Vector2::new(7.0, 5.0)).unwrap(),
        Similarity::new(1e3, 0.7, Vector2::new(-4e3, 1e2))
            .unwrap()
            .mirrored(),
        Similarity::new(1.0, 0.0, Vector2::new(1e6, -1e6)).unwrap(),
    ]
}

/// Exactly two finite Burmester points and no slider, one within `1e-8`
/// (task sizes plus distance) of each of `want` (given in the task's frame)
/// moved by `t`.
fn two_points_at(five: &FivePositions, t: &Similarity, want: &[Point2<f64>]) {
    let pts = five.burmester_points();
    assert_eq!(pts.len(), 2, "{pts:?} in {t:?}");
    assert!(five.sliders().is_empty(), "{five:?}");
    for w in want {
        let w = t.point(*w);
        assert!(
            pts.iter()
                .any(|d| (d.center - w).norm() <= 1e-8 * (five.size() + w.coords.norm())),
            "{w} not in {pts:?} in {t:?}"
        );
    }
}

#[test]
fn issue24_nearly_merging_burmester_points_count_two_or_four() {
    let want = [
        Point2::new(2.1845468030272426, 3.9286531345231968),
        Point2::new(9.309375812216743, 7.340419877156631),
    ];
    for t in frames() {
        // A complex pair 2.3e-6 off the real plane: two points, in every frame.
        let five =
            FivePositions::new(&moved(&issue24_merging_poses(1.4085852732973474), &t)).unwrap();
        two_points_at(&five, &t, &want);
        // A hair away (pose 5 moved by 1.76e-10): the pair is real, 1.1e-8 to
        // 6.4e-8 apart: four points, the near two within 1e-7 of where they
        // merge (each listed, or one double point listed twice).
        let mut x5 = 1.4085852731213095f64;
        for _ in 0..14 {
            let five = FivePositions::new(&moved(&issue24_merging_poses(x5), &t)).unwrap();
            let pts = five.burmester_points();
            assert_eq!(pts.len(), 4, "x5 = {x5:?}: {pts:?} in {t:?}");
            let merge = t.point(Point2::new(-0.3808193887, 1.748174366));
            let near = pts
                .iter()
                .filter(|d| (d.center - merge).norm() <= 1e-7 * (five.size() + merge.coords.norm()))
                .count();
            assert_eq!(near, 2, "x5 = {x5:?}: {pts:?}");
            x5 = x5.next_up();
        }
    }
}

#[test]
fn issue24_degenerate_five_pose_tasks_say_so_in_every_frame() {
    let task = |p: &[(f64, f64, f64)]| -> Vec<Pose> {
        p.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect()
    };
    // Poses 1, 2, 3 are rotations about (0, 0) (and a line of Burmester
    // centers exists: sympy's Groebner basis).
    let a = task(&[
        (0.0, 0.0, 0.0),
        (0.0, 0.0, 1.0),
        (0.0, 0.0, 2.0),
        (0.0, 1.0, 0.0),
        (0.0, 1.0, 1.0),
    ]);
    for t in frames() {
        let e = FivePositions::new(&moved(&a, &t)).unwrap_err();
        assert!(
            matches!(
                e,
                Error::Degenerate(DegenerateError::RotationsAboutOnePoint {
                    i: 1,
                    j: 2,
                    k: 3,
                    ..
                })
            ),
            "{e:?} in {t:?}"
        );
        assert!(e.to_string().contains("rotations about one point"));
    }
    // Two pure translations and two poses at one position: one real
    // Burmester point, at (0.4783670579, 49.79082622) (mpmath reference),
    // and one at infinity (a slider), in every frame; no ghost.
    let b = task(&[
        (0.0, 0.0, 2.0),
        (0.0, 1.0, 1.0),
        (0.0, 0.0, 0.0),
        (1.0, 1.0, 1.0),
        (4.76953125, 0.0, 0.0),
    ]);
    for t in frames() {
        let five = FivePositions::new(&moved(&b, &t)).unwrap();
        let pts = five.burmester_points();
        assert_eq!(pts.len(), 1, "{pts:?} in {t:?}");
        let w = t.point(Point2::new(0.4783670578728627, 49.790826221674784));
        assert!(
            (pts[0].center - w).norm() <= 1e-8 * (five.size() + w.coords.norm()),
            "{pts:?}"
        );
        assert_eq!(five.sliders().len(), 1, "{:?}", five.sliders());
        check_slider(&five, &moved(&b, &t));
    }
    // Collinear positions: the reference point is a slider; three finite
    // points (mpmath), in every frame, none beyond the task's scale.
    let c = task(&[
        (0.0, 0.0, 0.1),
        (1.0, 0.0, 0.5),
        (2.0, 0.0, 1.2),
        (3.5, 0.0, 2.0),
        (5.0, 0.0, -1.0),
    ]);
    let want = [
        (1.028311028, 11.71531754),
        (0.7822684224, 1.870124483),
        (2.135913452, 1.304640045),
    ];
    for t in frames() {
        let poses = moved(&c, &t);
        let five = FivePositions::new(&poses).unwrap();
        let pts = five.burmester_points();
        assert_eq!(pts.len(), 3, "{pts:?} in {t:?}");
        for (x, y) in want {
            let w = t.point(Point2::new(x, y));
            assert!(
                pts.iter()
                    .any(|d| (d.center - w).norm() <= 1e-8 * (five.size() + w.coords.norm())),
                "{w}: {pts:?}"
            );
        }
        assert_eq!(five.sliders().len(), 1);
        check_slider(&five, &poses);
        let s = five.sliders()[0];
        assert!(
            (s.circle - poses[0].position).norm() <= 1e-9 * five.size(),
            "{s:?}"
        );
    }
    // Cardan motion (a rod with its ends on two perpendicular lines): every
    // point of the moving circle runs on a line, a family of sliders.
    let cardan: Vec<Pose> = [0.3f64, 0.9, 1.4, 2.2, 2.9]
        .iter()
        .map(|&f| Pose::new(2.0 * f.cos(), 0.0, PI - f))
        .collect();
    for t in frames() {
        let e = FivePositions::new(&moved(&cardan, &t)).unwrap_err();
        assert!(
            matches!(
                e,
                Error::Degenerate(DegenerateError::InfinitelyManyBurmesterPoints { .. })
            ),
            "{e:?} in {t:?}"
        );
    }
    // Three poses of one angle on a line: every dyad through them is a slider.
    let d = task(&[
        (0.0, 0.0, 0.3),
        (1.0, 0.0, 0.3),
        (2.5, 0.0, 0.3),
        (1.0, 2.0, 1.0),
        (-1.0, 1.0, 2.0),
    ]);
    for t in frames() {
        let e = FivePositions::new(&moved(&d, &t)).unwrap_err();
        assert!(
            matches!(
                e,
                Error::Degenerate(DegenerateError::CollinearTranslations { i: 1, j: 2, k: 3 })
            ),
            "{e:?}"
        );
    }
}

/// A slider's circle point has five collinear positions, on the line
/// normal to its direction.
fn check_slider(five: &FivePositions, poses: &[Pose]) {
    for s in five.sliders() {
        let p = slider_positions(five, s);
        for q in &p[1..] {
            let off = (q - p[0]).dot(&s.direction);
            assert!(off.abs() <= 1e-9 * five.size(), "{s:?}: {off}");
        }
        let _ = poses;
    }
}

/// Whether a five-pose answer is sound on its own: the count with
/// multiplicity (finite points and sliders) is 0, 2 or 4; every finite
/// point's circle point is concyclic over the poses (a double point to
/// the square of its rounding); every slider's circle point has collinear
/// positions.
fn check_five_sound(five: &FivePositions, poses: &[Pose]) -> Result<(), TestCaseError> {
    sound_count(five).map_err(TestCaseError::fail)?;
    for d in five.burmester_points() {
        prop_assert!(spread(poses, d) <= 1e-8, "{:?}: {}", d, spread(poses, d));
    }
    for s in five.sliders() {
        let p = slider_positions(five, s);
        let span = p.iter().map(|q| (q - p[0]).norm()).fold(0.0, f64::max);
        for q in &p[1..] {
            prop_assert!(
                (q - p[0]).dot(&s.direction).abs() <= 1e-7 * span.max(five.size()),
                "{:?}",
                s
            );
        }
    }
    Ok(())
}

/// The points of `a` farther than `1e-2` (relative) from every other point
/// of `a` are, moved by `t`, points of `b` (within `1e-6`), and the same
/// for `b` back to `a`; the points nearer one another (a pair near
/// merging, a double point: whether it is one is decided within rounding,
/// which the frame changes) may be there or not, two at a time.
fn check_separated_points_move(
    a: &FivePositions,
    b: &FivePositions,
    t: &Similarity,
) -> Result<(), TestCaseError> {
    let separated = |f: &FivePositions| -> Vec<Point2<f64>> {
        let pts = f.burmester_points();
        let c = centroid(f.poses());
        pts.iter()
            .enumerate()
            .filter(|(i, p)| {
                let scale = f.size() + (p.center - c).norm();
                pts.iter()
                    .enumerate()
                    .all(|(j, q)| j == *i || (q.center - p.center).norm() > 1e-2 * scale)
            })
            .map(|(_, p)| p.center)
            .collect()
    };
    let (sa, sb) = (separated(a), separated(b));
    let near = |p: Point2<f64>, q: Point2<f64>, f: &FivePositions| {
        let d = (p - centroid(f.poses())).norm();
        let rel = if d > 1e4 * f.size() { 1e-5 } else { 1e-6 };
        (p - q).norm() <= rel * (f.size() + d)
    };
    for p in &sa {
        let w = t.point(*p);
        prop_assert!(
            b.burmester_points().iter().any(|q| near(w, q.center, b)),
            "{} (moved {}) not among {:?}; poses {:?} and {:?}",
            p,
            w,
            b.burmester_points(),
            a.poses()
                .iter()
                .map(|p| (p.position.x, p.position.y, p.angle))
                .collect::<Vec<_>>(),
            b.poses()
                .iter()
                .map(|p| (p.position.x, p.position.y, p.angle))
                .collect::<Vec<_>>()
        );
    }
    for q in &sb {
        prop_assert!(
            a.burmester_points()
                .iter()
                .any(|p| near(t.point(p.center), *q, b)),
            "{} not among {:?} moved",
            q,
            a.burmester_points()
        );
    }
    Ok(())
}

/// Tasks near a merge of two Burmester points: pose 5 moved along `dir` by
/// `lambda` task sizes, `lambda` on a grid over `[-span, span]`; where the
/// count changes between two neighbours, `lambda` is bisected to the
/// spacing of doubles, and the tasks at the two ends and at `1e-4`,
/// `1e-7`, `1e-10` and `1e-13` task sizes either side of the change are
/// returned (pairs of points from `1e-2` apart to merged, real or complex).
fn near_merges(poses: &[Pose], dir: Vector2<f64>, span: f64) -> Vec<Vec<Pose>> {
    let size = FivePositions::new(poses).map(|f| f.size()).unwrap_or(1.0);
    let at = |l: f64| {
        let mut p = poses.to_vec();
        p[4].position += dir * (l * size);
        p
    };
    let count = |l: f64| FivePositions::new(&at(l)).ok().map(|f| total(&f));
    let grid: Vec<f64> = (0..=40)
        .map(|i| -span + 2.0 * span * i as f64 / 40.0)
        .collect();
    let counts: Vec<Option<usize>> = grid.iter().map(|&l| count(l)).collect();
    for i in 0..40 {
        let (Some(ca), Some(cb)) = (counts[i], counts[i + 1]) else {
            continue;
        };
        if ca == cb {
            continue;
        }
        let (mut lo, mut hi) = (grid[i], grid[i + 1]);
        for _ in 0..60 {
            let m = 0.5 * (lo + hi);
            if !(m > lo && m < hi) {
                break;
            }
            match count(m) {
                Some(c) if c == ca => lo = m,
                Some(_) => hi = m,
                None => break,
            }
        }
        let mut out = vec![at(lo), at(hi)];
        for k in [4, 7, 10, 13] {
            let d = 10f64.powi(-k);
            out.push(at(lo - d));
            out.push(at(hi + d));
        }
        return out;
    }
    Vec::new()
}

proptest! {
    // A fixed seed: CI must not depend on the draw. With random seeds this
    // target found a task bisected to where two points merge that the
    // library refused as unresolved (fixed: a double root that is two real
    // points is split, `issue24_a_double_root_that_is_two_real_points_gives_both`)
    // and, once in 288 draws after that fix, a far pair of points off by
    // 1.5e-6 of their distance in a scaled frame (open, fuzz/README.md).
    // Change the seed (or set `BURMESTER_EXPLORE=1`: fresh draws) to search
    // further.
    #![proptest_config(ProptestConfig {
        rng_seed: common::seed_or(0x0b24_0024),
        ..cases(24)
    })]

    /// Items 2 and 3's target for merging points: tasks bisected to where
    /// two Burmester points merge (made from linkages, pose 5 moved), in
    /// random frames: the count is 0, 2 or 4, every point concyclic, and
    /// the points apart from the merging pair move with the task.
    #[test]
    fn issue24_burmester_points_near_merging_in_any_frame(
        p in link_params(),
        a in -PI..PI,
        t in similarity(),
    ) {
        let m = made_case(&p, 5)?;
        let tasks = near_merges(&m.poses, Vector2::new(a.cos(), a.sin()), 0.5);
        for poses in tasks {
            let r = FivePositions::new(&poses);
            prop_assert!(
                !matches!(r, Err(Error::Degenerate(DegenerateError::UnresolvedBurmesterPoints { .. }))),
                "{:?}: {:?}", poses, r
            );
            let Ok(five) = r else { continue };
            check_five_sound(&five, &poses)?;
            let mv = moved(&poses, &t);
            let Ok(other) = FivePositions::new(&mv) else { continue };
            check_five_sound(&other, &mv)?;
            check_separated_points_move(&five, &other, &t)?;
        }
    }
}

/// A degenerate five-pose task and what it must give: `kind` 0, three
/// rotations about one point (poses `which`); 1, three poses of one angle
/// on a line; 2, five positions on a line (the reference point a slider);
/// 3, two pairs of poses of one angle and two poses at one position;
/// 4, Cardan motion (a family of sliders).
#[derive(Debug, Clone)]
struct Degenerate {
    kind: usize,
    poses: Vec<Pose>,
    which: [usize; 3],
}

fn degenerate_task() -> impl Strategy<Value = Degenerate> {
    (
        0usize..5,
        (-3.0f64..3.0, -3.0f64..3.0),
        (0.5f64..3.0, -PI..PI),
        prop::array::uniform5((-1.0f64..1.0, -PI..PI)),
        prop::array::uniform4((-3.0f64..3.0, -3.0f64..3.0)),
        Just([0usize, 1, 2, 3, 4]).prop_shuffle(),
    )
        .prop_filter_map(
            "rotations too close",
            |(kind, c, (r, phi), v, extra, perm)| {
                let c = Point2::new(c.0, c.1);
                let arm = Vector2::new(r * phi.cos(), r * phi.sin());
                let base: Vec<Pose> = match kind {
                    0 => {
                        // Rotations about c by angles at least 0.2 apart.
                        let ang = [v[0].1, v[1].1, v[2].1];
                        let ok = (0..3)
                            .all(|i| (i + 1..3).all(|j| common::wrap(ang[i] - ang[j]).abs() > 0.2));
                        if !ok {
                            return None;
                        }
                        let mut p: Vec<Pose> = ang
                            .iter()
                            .map(|&a| {
                                let (s, co) = a.sin_cos();
                                Pose::new(
                                    c.x + co * arm.x - s * arm.y,
                                    c.y + s * arm.x + co * arm.y,
                                    a + 0.3,
                                )
                            })
                            .collect();
                        p.push(Pose::new(extra[0].0, extra[0].1, v[3].1));
                        p.push(Pose::new(extra[1].0, extra[1].1, v[4].1));
                        p
                    }
                    1 => {
                        let ts = [0.0, 0.4 + v[0].0.abs(), -0.4 - v[1].0.abs()];
                        let mut p: Vec<Pose> = ts
                            .iter()
                            .map(|&t| Pose::new(c.x + t * arm.x, c.y + t * arm.y, v[2].1))
                            .collect();
                        p.push(Pose::new(extra[0].0, extra[0].1, v[3].1));
                        p.push(Pose::new(extra[1].0, extra[1].1, v[4].1));
                        p
                    }
                    2 => {
                        let ts = [
                            0.0,
                            1.0,
                            2.0 + v[0].0.abs(),
                            -1.0 - v[1].0.abs(),
                            3.5 + v[2].0.abs(),
                        ];
                        let ang = v.map(|x| x.1);
                        let ok = (0..5)
                            .all(|i| (i + 1..5).all(|j| common::wrap(ang[i] - ang[j]).abs() > 0.1));
                        if !ok {
                            return None;
                        }
                        ts.iter()
                            .zip(ang)
                            .map(|(&t, a)| Pose::new(c.x + t * arm.x, c.y + t * arm.y, a))
                            .collect()
                    }
                    3 => {
                        let (a1, a2, a3) = (v[0].1, v[1].1, v[2].1);
                        let ok = [a1 - a2, a1 - a3, a2 - a3]
                            .iter()
                            .all(|d| common::wrap(*d).abs() > 0.1);
                        if !ok {
                            return None;
                        }
                        vec![
                            Pose::new(c.x, c.y, a1),
                            Pose::new(extra[0].0, extra[0].1, a2),
                            Pose::new(c.x, c.y, a3),
                            Pose::new(extra[1].0, extra[1].1, a2),
                            Pose::new(extra[2].0, extra[2].1, a3),
                        ]
                    }
                    _ => {
                        let phis = v.map(|x| x.1);
                        let ok = (0..5).all(|i| {
                            (i + 1..5).all(|j| common::wrap(phis[i] - phis[j]).abs() > 0.1)
                        });
                        if !ok {
                            return None;
                        }
                        // The rod's end on the x axis of a frame at c turned by phi.
                        phis.iter()
                            .map(|&f| {
                                let e = Vector2::new(r * f.cos(), 0.0);
                                let (s, co) = phi.sin_cos();
                                Pose::new(
                                    c.x + co * e.x - s * e.y,
                                    c.y + s * e.x + co * e.y,
                                    PI - f + phi,
                                )
                            })
                            .collect()
                    }
                };
                let poses: Vec<Pose> = perm.iter().map(|&i| base[i]).collect();
                let mut which: Vec<usize> = (0..3)
                    .map(|k| perm.iter().position(|&i| i == k).unwrap() + 1)
                    .collect();
                which.sort();
                Some(Degenerate {
                    kind,
                    poses,
                    which: [which[0], which[1], which[2]],
                })
            },
        )
}

proptest! {
    #![proptest_config(cases(96))]

    /// Item 3's target: degenerate five-pose tasks (three rotations about
    /// one point, three poses of one angle on a line, collinear positions,
    /// pure translations with poses at one position, Cardan motion) in
    /// random frames: a typed error naming the poses, or a sound answer
    /// with a slider where the positions are collinear, the same in every
    /// frame.
    #[test]
    fn issue24_degenerate_five_pose_tasks_in_any_frame(d in degenerate_task(), t in similarity()) {
        let poses = moved(&d.poses, &t);
        let r = FivePositions::new(&poses);
        match d.kind {
            0 => {
                let [i, j, k] = d.which;
                prop_assert!(
                    matches!(r, Err(Error::Degenerate(DegenerateError::RotationsAboutOnePoint { i: a, j: b, k: c, .. })) if [a, b, c] == [i, j, k]),
                    "{:?}", r
                );
            }
            1 => {
                let [i, j, k] = d.which;
                prop_assert!(
                    matches!(r, Err(Error::Degenerate(DegenerateError::CollinearTranslations { i: a, j: b, k: c })) if [a, b, c] == [i, j, k]),
                    "{:?}", r
                );
            }
            4 => {
                prop_assert!(
                    matches!(r, Err(Error::Degenerate(DegenerateError::InfinitelyManyBurmesterPoints { .. }))),
                    "{:?}", r
                );
            }
            _ => {
                let Ok(five) = r else {
                    // Only what the four-pose subsets refuse.
                    prop_assert!(matches!(r, Err(Error::Degenerate(_))), "{:?}", r);
                    return Ok(());
                };
                check_five_sound(&five, &poses)?;
                if d.kind == 2 {
                    prop_assert!(
                        five.sliders().iter().any(|s| (s.circle - poses[0].position).norm() <= 1e-6 * five.size()),
                        "{:?}", five.sliders()
                    );
                    prop_assert!(five.burmester_points().len() % 2 == 1);
                }
                // The same in the original frame.
                let base = FivePositions::new(&d.poses).unwrap();
                prop_assert_eq!(total(&base), total(&five));
                prop_assert_eq!(base.sliders().len(), five.sliders().len());
                check_separated_points_move(&base, &five, &t)?;
            }
        }
    }
}

/// Found by the `curves` fuzz target: three of four poses of one angle on
/// a line. Every dyad through them is a slider; the curve was the line at
/// infinity twice and a line of centers whose circle points are at
/// infinity, and its traced points were refused by the on-curve test.
#[test]
fn issue24_three_of_four_poses_of_one_angle_on_a_line_are_degenerate() {
    let poses = [
        Pose::new(9.89296875e-8, -1.70703125e-8, 0.3),
        Pose::new(9.892983203125e-8, -1.70703125e-8, 0.3),
        Pose::new(9.89299765625e-8, -1.70703125e-8, 0.3),
        Pose::new(9.893012109374999e-8, -1.70703125e-8, 0.0),
    ];
    let e = FourPositions::new(&poses).unwrap_err();
    assert!(
        matches!(
            e,
            Error::Degenerate(DegenerateError::CollinearTranslations { i: 1, j: 2, k: 3 })
        ),
        "{e:?}"
    );
}

/// Found by the `curves` fuzz target: rotations of about 1e-7 rad between
/// the poses. The crank-rotation formulas divide by the square of the
/// angle; their dyads were off the curve by 15 task sizes (their three
/// conditions off by half their terms) and refused by it. Now a dyad is
/// given only when its conditions hold (after the Gauss-Newton
/// corrections) to 1e-8 of their terms, and then it is on the curve.
#[test]
fn issue24_dyads_of_nearly_equal_angles_are_on_their_curve_or_not_given() {
    let poses = [
        Pose::new(1.015625e-22, -3.515625e-14, 5.296484375e-8),
        Pose::new(
            -5.537033081054664e-21,
            -3.515624999999956e-14,
            -1.07421875e-7,
        ),
        Pose::new(-1.897125244140626e-22, -3.515625e-14, 4.46796875e-8),
        Pose::new(-1.7604827880859368e-21, -3.515624999999996e-14, 0.0),
    ];
    let four = FourPositions::new(&poses).unwrap();
    for d in four.dyad_runs(50).unwrap().into_iter().flatten() {
        four.circle_point(d.center).unwrap();
        assert!(spread(&poses, &d.dyad()) <= 1e-6, "{d:?}");
    }
    for d in four.parameter_samples(50).unwrap().into_iter().flatten() {
        four.circle_point(d.center).unwrap();
    }
}

/// Found by the `curves` fuzz target: four poses of one angle. Every dyad's
/// crank is then one vector over the poses (its circle point's positions
/// are the point translated), so a dyad passes the four only when the
/// translations are concyclic; the curve degenerated to rounding and its
/// traced points were refused. Now a typed error that says what to change,
/// in any frame and at any size.
#[test]
fn issue24_four_poses_of_one_angle_are_all_translations() {
    let found = [
        Pose::new(2.211328125e-14, 2.911328125e-11, 0.02911328125),
        Pose::new(2.911328125e-14, 2.924609375e-14, 0.02911328125),
        Pose::new(1.1328125e-16, 2.911328125e-14, 0.02911328125),
        Pose::new(2.9503906249999996e-14, 2.911328125e-14, 0.02911328125),
    ];
    // A lid moved without turning, in millimetres.
    let lid = [
        Pose::new(0.0, 0.0, 0.3),
        Pose::new(120.0, 15.0, 0.3),
        Pose::new(40.0, 90.0, 0.3),
        Pose::new(70.0, 35.0, 0.3 + TAU),
    ];
    for (poses, size) in [(&found[..], 3e-11), (&lid[..], 100.0)] {
        for t in frames_of_size(size) {
            let e = FourPositions::new(&moved(poses, &t)).unwrap_err();
            assert!(
                matches!(e, Error::Degenerate(DegenerateError::AllTranslations)),
                "{e:?}"
            );
            assert!(e.to_string().contains("rotate a pose"), "{e}");
        }
    }
    // One pose turned by a thousandth of a radian: a proper task again.
    let mut turned = lid;
    turned[3] = Pose::new(70.0, 35.0, 0.301);
    FourPositions::new(&turned).unwrap();
}

/// Found by the `curves` fuzz target: rotations of 2.6e-8 to 1e-6 rad. A
/// crank-rotation dyad solved its three conditions to 1e-8 of their terms
/// (accepted by `dyad_at`) but its center was off the curve by more than
/// the on-curve test allows, so the library refused its own dyad. Now
/// `dyad_at` gives a dyad only when the on-curve test takes its center and
/// its circle point back; checked here by the crank lengths over the four
/// poses, evaluated directly.
#[test]
fn issue24_dyads_of_nearly_equal_angles_are_taken_back_or_not_given() {
    let poses = [
        Pose::new(-2.228750000374531e-10, -1.15453125e-10, PI),
        Pose::new(-2.2287500003745308e-10, -1.15453125e-10, 3.141592627696793),
        Pose::new(-2.2287500003739538e-10, -1.15453125e-10, 3.141591653589793),
        Pose::new(-2.2287500003745308e-10, -1.15453125e-10, 3.141592681089793),
    ];
    let off_curve = |r: &Result<Point2<f64>, Error>| {
        matches!(r, Err(Error::InvalidInput(InvalidInput::OffCurve { .. })))
    };
    let mut total = 0;
    for t in frames_of_size(1e-10) {
        let moved_poses = moved(&poses, &t);
        let four = FourPositions::new(&moved_poses).unwrap();
        let mut dyads = Vec::new();
        for k in 0..720 {
            let beta2 = k as f64 * TAU / 720.0;
            for mode in [AssemblyMode::Open, AssemblyMode::Crossed] {
                if let Ok(d) = four.dyad_at(beta2, mode) {
                    dyads.push(d);
                }
            }
        }
        let given = dyads.len();
        if let Ok(runs) = four.dyad_runs(50) {
            dyads.extend(runs.into_iter().flatten());
        }
        if let Ok(s) = four.parameter_samples(50) {
            dyads.extend(s.into_iter().flatten());
        }
        total += given;
        for d in &dyads {
            let r = four.circle_point(d.center);
            assert!(!off_curve(&r), "own center {} refused: {r:?}", d.center);
            let r = four.center_point(d.circle);
            assert!(
                !off_curve(&r),
                "own circle point {} refused: {r:?}",
                d.circle
            );
            // The dyad's conditions: one crank length at the four poses,
            // within a millionth of the crank plus the task, or within the
            // rounding of the coordinates (the poses are nearly at one
            // point: the task's size is a few ulps of its place).
            let p1 = moved_poses[0];
            let (r, min, max) = crank_lengths(&moved_poses, d.center, d.circle);
            let place = d.center.coords.norm() + d.circle.coords.norm() + p1.position.coords.norm();
            let band = 1e-6 * (max + four.size()) + 64.0 * f64::EPSILON * place;
            assert!(max - min <= band, "{d:?}: {r:?}");
        }
    }
    // Where the angles' digits allow (the task scaled up), some are given.
    assert!(total > 0);
}

/// Found by the `curves` fuzz target: a driven dyad whose circle point is
/// the first pose's reference point, on a line of centers. At `C1` every
/// branch sign `cross(C'k - C1, A1 - C1)` is zero, so the class of a
/// driving circle point there (and of the stretch of that line next to it)
/// was decided by rounding. `C1` is a boundary (never free) within
/// `tolerance::POINT` task sizes, in every frame, and no free arc passes
/// it.
#[test]
fn issue24_the_driven_circle_point_is_a_boundary() {
    let poses = [
        Pose::new(8.66640625e-14, 7.33203125e-12, 0.0),
        Pose::new(0.0, 0.0, 40.0),
        Pose::new(0.0, 0.0, 7.33203125),
        Pose::new(8.66640625e-14, 7.33203125e-12, 0.0101640625),
    ];
    let driven = Dyad::new(
        Point2::new(4.3332031250003845e-14, 3.666015624999997e-12),
        Point2::new(8.666406249999107e-14, 7.332031250000002e-12),
    );
    for t in frames_of_size(1e-11) {
        let four = FourPositions::new(&moved(&poses, &t)).unwrap();
        let size = four.size();
        let d = Dyad::new(t.point(driven.center), t.point(driven.circle));
        let arcs = four.filemon(&d).unwrap();
        let c1 = arcs.driven().circle();
        // Every sign vanishes at C1 (against their size a task away).
        let far = arcs.circle_signs(c1 + Vector2::new(size, 0.0));
        let scale = far.iter().map(|v| v.abs()).fold(0.0, f64::max);
        for s in arcs.circle_signs(c1) {
            assert!(s.abs() <= 1e-12 * scale, "{s} against {scale}");
        }
        for k in 0..8 {
            let a = k as f64 * PI / 4.0;
            let p = c1 + Vector2::new(a.cos(), a.sin()) * (0.5e-12 * size);
            assert_eq!(arcs.classify_circle_point(p), Branch::Boundary);
        }
        assert_eq!(arcs.classify_circle_point(c1), Branch::Boundary);
        let h = 2.0 * size;
        let vp = Viewport::new(c1.x - h, c1.x + h, c1.y - h, c1.y + h).unwrap();
        for l in arcs.free_circle_arcs(&vp).unwrap() {
            for p in &l[1..l.len() - 1] {
                assert!(
                    (p - c1).norm() > 1e-12 * size,
                    "a free arc passes C1 at {p}"
                );
            }
        }
    }
}

/// Found by the `curves` fuzz target: three nearly collinear translations
/// and a pose turned by 2.3e-8 rad. The circle-point curve is a line times
/// a conic whose terms other than the constant are rounding; the conic's
/// kind (relative to its matrix's norm) said "degenerate" and a line was
/// drawn across the view where the curve is not (a hundredth of the task
/// away). Now every traced vertex is on the curve.
#[test]
fn issue24_a_line_times_a_constant_conic_traces_only_the_line() {
    let poses = [
        Pose::new(2.699609375e-11, -3.9062500000000004e-24, 2.274609375e-8),
        Pose::new(-8.083593980090955e-11, -5.756572150067078e-19, 0.0),
        Pose::new(2.7992185199090447e-11, -6.140595587567076e-19, 0.0),
        Pose::new(2.6996091449090445e-11, -6.140595587567076e-19, 0.0),
    ];
    let four = FourPositions::new(&poses).unwrap();
    let vp = Viewport::new(
        -5.241228251844396e-13,
        1.0983381238201081e-12,
        -8.112309254473336e-13,
        8.112300235572142e-13,
    )
    .unwrap();
    let curve = four.circle_point_curve();
    let lines = curve.polylines(&vp);
    assert_eq!(lines.len(), 1, "{lines:?}");
    for l in &lines {
        for &c in l {
            assert!(on_curve(curve, &four, c, 1.0), "{c} off the curve");
            let g = four.center_point(c);
            assert!(
                !matches!(g, Err(Error::InvalidInput(InvalidInput::OffCurve { .. }))),
                "{c}: {g:?}"
            );
        }
    }
}

/// Frames for a task of about `size`: as given, moved (by a few sizes),
/// turned, scaled, mirrored; the moves are within the task's own digits.
fn frames_of_size(size: f64) -> Vec<Similarity> {
    vec![
        Similarity::new(1.0, 0.0, Vector2::zeros()).unwrap(),
        Similarity::new(1.0, 0.0, Vector2::new(0.0, 2.0 * size)).unwrap(),
        Similarity::new(3.0, 0.0, Vector2::zeros()).unwrap(),
        Similarity::new(1.0, 1.0, Vector2::new(0.3, -0.2) * size).unwrap(),
        Similarity::new(1e-3, -2.5, Vector2::new(7.0, 5.0) * size).unwrap(),
        Similarity::new(1e3, 0.7, Vector2::new(-4.0, 1.0) * size)
            .unwrap()
            .mirrored(),
    ]
}

/// Found by the `curves` fuzz target: a view 700 task sizes wide whose
/// center is far from the curve. The tracer's pencil point (a vertex of the
/// trace) was a root of the curve on a line from the view's center, found
/// to the rounding of that distance: 0.0044 off the curve (against an
/// on-curve tolerance of 6.6e-5, a task of size 66,000) and refused by
/// `circle_point`. It is now refined by Newton on the curve's own value;
/// every vertex is on the curve, in this view and in smaller ones.
#[test]
fn issue24_a_huge_view_traces_vertices_on_the_curve() {
    let poses = [
        Pose::new(65996.09375, -824.21875, 0.032996093750000004),
        Pose::new(0.12496484375, 51.0078125, 2.84765625e-9),
        Pose::new(-0.7421875, 35.15625, 35.15624999999609),
        Pose::new(0.12496484375, 51.0078125, 73.16015625),
    ];
    let four = FourPositions::new(&poses).unwrap();
    let curve = four.center_point_curve();
    let (x0, x1, y0, y1) = (
        -36827307.97171515,
        8033420.454465505,
        -36820774.80875893,
        8039953.617421731,
    );
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let mut count = 0;
    for k in [1.0, 1e-2, 1e-4] {
        let (hx, hy) = (0.5 * (x1 - x0) * k, 0.5 * (y1 - y0) * k);
        let vp = Viewport::new(cx - hx, cx + hx, cy - hy, cy + hy).unwrap();
        for g in curve.polylines(&vp).into_iter().flatten() {
            count += 1;
            // Independent of the on-curve test: the first-order distance
            // within the rounding of a task size.
            assert!(curve.distance_estimate(g) <= 1e-9 * four.size(), "{g}");
            let z = four.circle_point(g);
            assert!(
                !matches!(z, Err(Error::InvalidInput(InvalidInput::OffCurve { .. }))),
                "traced {g} refused: {z:?}"
            );
        }
    }
    assert!(count > 0);
}

/// Found by the `curves` fuzz target: a nearly singular circle-point curve
/// with an oval 1.2e-14 across (a task of size 9.4e-8) at an arc end. The
/// extreme Filemon line crosses the oval twice where the arc ends do not
/// resolve it (two roots 6e-8 task sizes apart), so the classes changed
/// between traced vertices; the free run was cut at the middle of that
/// chord and so reached into the defective stretch. A free run now ends at
/// a vertex or an exact mark. Checked against the branch signs
/// `cross(C'k - C1, A1 - C1)` evaluated here, at points of the curve along
/// every chord of every free arc.
#[test]
fn issue24_a_free_arc_never_ends_mid_chord_in_a_defective_stretch() {
    let poses = [
        Pose::new(-4.200390625e-14, -4.216796875e-14, -0.03816796875),
        Pose::new(-4.216796875e-14, -4.25234375e-14, 0.04683203125),
        Pose::new(-1.2524999999999999e-7, -6.401171875e-14, 34.1484375),
        Pose::new(-4.216796875e-14, -4.25234375e-14, -42.88671875),
    ];
    let four = FourPositions::new(&poses).unwrap();
    let driven = Dyad::new(
        Point2::new(-3.7484288237342264e-14, -4.502291198845822e-14),
        Point2::new(-2.8392127636848383e-7, 5.572602386567654e-7),
    );
    let arcs = four.filemon(&driven).unwrap();
    let c1 = arcs.driven().circle();
    let images = arcs.fixed_pivot_images().unwrap();
    let signs = |p: Point2<f64>| {
        images.map(|c| {
            let (u, v) = (c - c1, p - c1);
            u.x * v.y - u.y * v.x
        })
    };
    let curve = four.circle_point_curve();
    let mut checked = 0;
    let found = Viewport::new(
        -9.39412168438642e-10,
        9.393371998621672e-10,
        -9.39419707062393e-10,
        9.393296612384162e-10,
    )
    .unwrap();
    let views = [1e-11, 1e-13].map(|h| Viewport::new(-h, h, -h, h).unwrap());
    for vp in std::iter::once(found).chain(views) {
        let diag = vp.diagonal();
        let near = |p: Point2<f64>| {
            (p - c1).norm() <= 1e-6 * diag
                || arcs
                    .arc_ends()
                    .iter()
                    .any(|e| (e.circle - p).norm() <= 1e-6 * diag)
        };
        for l in arcs.free_circle_arcs(&vp).unwrap() {
            for w in l.windows(2) {
                for k in 0..=4 {
                    let m = w[0] + (w[1] - w[0]) * (k as f64 / 4.0);
                    let Some(q) = curve
                        .intersect_line(&burmester::Line {
                            point: m,
                            direction: curve.gradient(m),
                        })
                        .into_iter()
                        .min_by(|a, b| (a - m).norm().total_cmp(&(b - m).norm()))
                    else {
                        continue;
                    };
                    if near(q) || (q - m).norm() > 2e-3 * diag {
                        continue;
                    }
                    let s = signs(q);
                    assert!(
                        s.iter().all(|v| *v > 0.0) || s.iter().all(|v| *v < 0.0),
                        "{q} on the free chord {} - {} has signs {s:?}",
                        w[0],
                        w[1]
                    );
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 0);
}

/// The circle point's five positions (the dyad's moving pivot at each pose),
/// computed here from the poses.
fn positions_of(poses: &[Pose], circle: Point2<f64>) -> Vec<Point2<f64>> {
    let p1 = poses[0];
    poses
        .iter()
        .map(|p| {
            let (s, c) = (p.angle - p1.angle).sin_cos();
            let v = circle - p1.position;
            p.position + Vector2::new(c * v.x - s * v.y, s * v.x + c * v.y)
        })
        .collect()
}

/// Issue 24, five poses (fuzz inputs of `burmester_points`, kept in
/// `fuzz/regressions/burmester_points/`): tasks with pairs of poses of one
/// angle or half a turn apart, where the elimination's rounding band held
/// several critical points of the resultant (each a double root) and a
/// root gave a finite point and a slider, counted 6, 8 and 10 Burmester
/// points; others gave sliders whose five positions were far off any line.
/// Now the count with multiplicity is at most four and even, or the task
/// is refused as unresolved within rounding; every point is concyclic and
/// every slider's positions are on its line, both computed here from the
/// poses.
#[test]
fn issue24_five_pose_counts_never_exceed_four_and_sliders_are_on_their_lines() {
    let tasks: [[(f64, f64, f64); 5]; 8] = [
        // count 10
        [
            (0.000100609375, 0.0, 0.0),
            (-0.007399390625, 0.0, 0.0),
            (6.09375e-7, 0.0, PI),
            (0.000100609375, 0.0, PI),
            (0.0003147686403589793, 2.2204460492503132e-20, -2.4306e-6),
        ],
        // count 6
        [
            (1e-6, 0.0, 0.0),
            (-25.444, 1e-6, PI),
            (0.0, 2.220446049250313e-22, 1e-12),
            (-1.6e-19, 1e-6, 1.0),
            (1e-6, 1e-6, 1.0),
        ],
        // count 8
        [
            (1e-12, -1e-10, PI),
            (1e-12, -1e-10, 2.220446049250313e-16),
            (-9.998001598555674e-25, 1e-12, PI),
            (0.0, 2.220446049250313e-28, 2.220446049250313e-16),
            (-4.977795539507508e-26, -2.5444e-19, 4.712656542480727e-13),
        ],
        // count 6, a moderate task
        [
            (1.0, 0.0, 0.0),
            (-74.0, 0.0, 0.0),
            (0.0, 0.0, PI),
            (1.0, 0.0, PI),
            (PI, 2.220446049250313e-16, 1.4e-11),
        ],
        // count 6
        [
            (1.0, 0.0, 0.0),
            (-10.0, 1.0, PI),
            (0.0, 2.220446049250313e-16, 2.220446049250313e-16),
            (-1.6e-13, 1.0, 1.0),
            (1.0, 1.0, 1.0),
        ],
        // a slider off its line by 8e-19 in a task of 1e-12
        [
            (1e-12, 1e-12, PI),
            (0.0, 0.0, 2.220446049250313e-16),
            (-5e-26, -2.5444e-19, 0.0),
            (0.0, 0.0, 1.0),
            (9.999999999999999e-19, 1e-12, 1.0),
        ],
        // a slider off its line by 2.6e9 in a task of 3e10
        [
            (10000000000.0, 10000000000.0, 1e-6),
            (10000000000.0, 10000000000.0, 1.0),
            (10000.000000609374, 31415926535.89793, 1.0),
            (10000.000000609374, 31415926535.89793, TAU),
            (62831853071.79586, -97000000000.00002, 1.0000013e-6),
        ],
        // a slider off its line by 1731 in a task of 1800
        [
            (0.0, 2.220446049250313e-15, 2.220446049250313e-16),
            (-9.998001598555676e-12, 10.0, 1.0),
            (10.0, 31.41592653589793, 0.0),
            (
                2.220446049250313e-15,
                2.220446049250313e-15,
                -2.089800158765785e-12,
            ),
            (-1817.03125, 10.0, 1.0),
        ],
    ];
    let mut answered = 0;
    for t in tasks {
        let poses: Vec<Pose> = t.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
        let f = match FivePositions::new(&poses) {
            Ok(f) => f,
            Err(Error::Degenerate(DegenerateError::UnresolvedBurmesterPoints { .. })) => continue,
            Err(e) => panic!("{t:?}: {e}"),
        };
        answered += 1;
        let n = f.burmester_points().len() + f.sliders().len();
        assert!(n % 2 == 0 && n <= 4, "{t:?}: count {n}: {f:?}");
        for d in f.burmester_points() {
            assert!(spread(&poses, d) <= 1e-8, "{t:?}: {d:?} not concyclic");
        }
        for s in f.sliders() {
            let p = positions_of(&poses, s.circle);
            let span = p.iter().map(|q| (q - p[0]).norm()).fold(0.0, f64::max);
            let coords = p.iter().map(|q| q.coords.norm()).fold(0.0, f64::max);
            for q in &p[1..] {
                let off = (q - p[0]).dot(&s.direction).abs();
                assert!(
                    off <= 1e-9 * span + 1e3 * f64::EPSILON * coords,
                    "{t:?}: {s:?} off its line by {off} (span {span})"
                );
            }
        }
    }
    // Not every task refused: the slider tasks and the moderate count-6
    // task with a half turn answer.
    assert!(answered >= 1, "every task refused");
}

/// Issue 24, five poses: a task (a fuzz input that counted 6) whose
/// Burmester points the exact elimination of `tests/python/burmester_reference.py`
/// (sympy, mpmath to 40 digits) gives as (-5, 0.5), (-4.5, 0.5) and two
/// points about 1e9 task sizes out (on either side, along the y axis: at
/// infinity within rounding, two sliders).
#[test]
fn issue24_a_count_six_task_has_the_reference_s_points() {
    let poses = [
        Pose::new(1.0, 0.0, 0.0),
        Pose::new(-10.0, 1.0, PI),
        Pose::new(0.0, 2.220446049250313e-16, 2.220446049250313e-16),
        Pose::new(-1.6e-13, 1.0, 1.0),
        Pose::new(1.0, 1.0, 1.0),
    ];
    let f = FivePositions::new(&poses).unwrap();
    let reference = [
        Point2::new(-5.000000000000414, 0.49999999999991657),
        Point2::new(-4.499999999999627, 0.49999999999991607),
    ];
    let n = f.burmester_points().len() + f.sliders().len();
    assert_eq!(n, 4, "{f:?}");
    for r in reference {
        assert!(
            f.burmester_points()
                .iter()
                .any(|d| (d.center - r).norm() <= 1e-9),
            "{r} not among {f:?}"
        );
    }
    // The other two: far along the y axis, as points or as sliders.
    for d in f.burmester_points() {
        if reference.iter().all(|r| (d.center - r).norm() > 1e-9) {
            assert!(d.center.y.abs() > 1e8 && d.center.x.abs() < 1.0, "{d:?}");
        }
    }
    for s in f.sliders() {
        assert!(s.direction.x.abs() < 1e-6, "{s:?}");
    }
}

/// The merging five-pose task of issue 24 (fuzz/README): two real
/// Burmester points 6.3e-5 apart and a complex pair (x, y, angle).
const MERGING_POSES: [(f64, f64, f64); 5] = [
    (0.2558734599461988, -3.8836557689762725, 2.1596700471934955),
    (1.5138333624383653, -3.75371689369933, 2.404112512166885),
    (2.6829498241096728, -3.150577449352146, 2.6017096951878065),
    (2.979515336818101, -2.8520483505789826, 2.6618014815462043),
    (3.9867349059821655, -2.2514849554763976, 2.8333410696332884),
];

/// Issue 24, the merging task that was refused (found by
/// `issue24_burmester_points_near_merging_in_any_frame` with a random seed,
/// fuzz/README.md): two real Burmester points `6.3e-5` apart (in a task of
/// size 3) that the resultant's rounding band took for one double root,
/// whose estimate missed both by `1.5e-5`, so every choice of the shared
/// poses lost it and the task was `UnresolvedBurmesterPoints`. The exact
/// elimination of `tests/python/burmester_reference.py` (sympy, mpmath)
/// gives these two real points and a complex pair. Now the double root is
/// split (Newton's method from the estimate and from its reflection) into
/// the two points, in every frame (moved, turned, scaled, mirrored).
#[test]
fn issue24_a_double_root_that_is_two_real_points_gives_both() {
    let poses: Vec<Pose> = MERGING_POSES
        .iter()
        .map(|&(x, y, a)| Pose::new(x, y, a))
        .collect();
    // mpmath, 50 digits (the reference's elimination).
    let reference = [
        Point2::new(-0.696_007_308_824_153_2, 2.669_388_663_365_832),
        Point2::new(-0.695_973_753_649_455_4, 2.669_441_921_552_642),
    ];
    // The frame moved by (1e6, -1e6) is a slightly different task: the
    // poses' own rounding there (1.2e-10) moves the two points by about
    // 6e-6, to these (the exact reference of the moved float task,
    // fuzz/reference/far_frames.py, relative to the offset). The check of a
    // point runs in the task's own frame (tolerance::BURMESTER_ROUNDING):
    // before, its allowance of 64 eps of the global coordinates passed two
    // double points 2e-4 off, four points in all.
    let moved_reference = [
        Point2::new(-0.696_003_646_616_504_5, 2.669_394_475_913_446_4),
        Point2::new(-0.695_977_415_801_458_3, 2.669_436_109_004_714_6),
    ];
    for t in frames() {
        let five =
            FivePositions::new(&moved(&poses, &t)).unwrap_or_else(|e| panic!("{e:?} in {t:?}"));
        // Two roots 6.3e-5 apart are known to about eps over their
        // separation: 1e-8 of the task's size and position.
        two_points_at(&five, &t, &reference);
        if t.offset.norm() > 1e5 {
            // And to 1e-8 of the task's size (not its position) of the
            // moved task's own points.
            let pts = five.burmester_points();
            for w in moved_reference {
                let w = w + t.offset;
                assert!(
                    pts.iter()
                        .any(|d| (d.center - w).norm() <= 1e-8 * five.size()),
                    "{w} not in {pts:?} in {t:?}"
                );
            }
        }
        let pts = five.burmester_points();
        // Concyclic to 1e-10, or in the far frame to the rounding of its
        // coordinates (1.4e6: 3e-10 over a crank of about one; the fuzz
        // target's bound, 1e3 eps of the coordinates over the crank).
        let allowed = |d: &Dyad| {
            let radius = (d.center - d.circle).norm().max(five.size());
            1e-10f64.max(1e3 * f64::EPSILON * t.offset.norm() / radius)
        };
        assert!(
            pts.iter().all(|d| five.residual(d) <= allowed(d)),
            "{pts:?}"
        );
    }
}

/// The merging task of the test above moved by `(-3e6, 2e6)`: the rounding
/// of the moved coordinates (4.7e-10) makes its two real points a complex
/// pair `1.7e-5` off the real plane (exact reference,
/// `fuzz/reference/far_frames.py`: `-0.69599053047967283 +- 1.7172581309181425e-5 i`,
/// `2.6694152929435544 +- 2.7256021138119819e-5 i` relative to the offset,
/// and the pair `0.278` off as given): no real Burmester point. The
/// library, which lists a complex pair within rounding as a double point,
/// does not resolve it (the double point's crank spread is over the check,
/// and Newton's method finds no real point): a typed refusal that says the
/// poses lie far from the origin, never two or four points.
#[test]
fn issue24_a_far_frame_that_makes_a_merging_pair_complex_is_refused_with_what_to_do() {
    let poses: Vec<Pose> = MERGING_POSES
        .iter()
        .map(|&(x, y, a)| Pose::new(x - 3e6, y + 2e6, a))
        .collect();
    match FivePositions::new(&poses) {
        Err(e @ Error::Degenerate(DegenerateError::UnresolvedBurmesterPoints { .. })) => {
            assert!(e.to_string().contains("far from the origin"), "{e}");
        }
        other => panic!("{other:?}"),
    }
}

/// Class C of fuzz/README.md (issue 24, fuzz32): a badly conditioned choice
/// of the shared poses found fewer roots than a better conditioned one had
/// verified (it lost others) and was taken as clean: 0 points where the
/// exact reference has two real ones (the moved frames of the kept inputs
/// `point-not-found-in-another-frame-d1f9937d` and `-f5e30d14`), and 2 where
/// it has four (`-c79b068d`). Now a clean choice must list at least the
/// near points a better one verified. References: the exact elimination of
/// the float tasks, `fuzz/reference/class_c_fixed.py` (sympy, mpmath at 60
/// digits; the other two common points a complex pair, 0.3 and 31 task
/// sizes off the real plane).
#[test]
fn issue24_a_choice_that_lost_roots_is_not_preferred() {
    let task = |p: &[(f64, f64, f64)]| -> Vec<Pose> {
        p.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect()
    };
    // Pairs of poses of one angle (2.2e-16 and pi apart) and at one
    // position: the points are known to about 1e-8 task sizes (the library
    // is 1.9e-8 off the far one), so 1e-7.
    let d1f9937d = task(&[
        (-4.6390625e-8, -1.2975096765358978e-7, -1.0),
        (
            -4.7390624999999994e-8,
            -1.2660937499999998e-7,
            -2.220446049250313e-16,
        ),
        (2.201099952609375, -2.201100126609375, 0.0),
        (-4.7390624999999994e-8, -1.2660937499999998e-7, -PI),
        (-4.42490323464102e-8, -1.27609375e-7, -1.0),
    ]);
    let d1f9937d_ref = [
        Point2::new(-4.664_947_170_124_832_3e-8, -1.300_098_143_581_163_4e-7),
        Point2::new(1.100_549_951_279_728_5, -1.100_550_127_939_021_4),
    ];
    let f5e30d14 = task(&[
        (1e-15, -1e-15, -PI),
        (0.0, -2.1692000000000002e-15, -2.169199999977308),
        (2.1854000000000003e-6, -2.1854000000000003e-6, 0.0),
        (3.141592653589793e-15, -1e-15, -1.0),
        (3.141592653589793e-15, 3.970625e-13, 0.0),
    ]);
    let f5e30d14_ref = [
        Point2::new(6.064_425_392_903_35e-16, -3.049_718_026_157_612e-15),
        Point2::new(2.205_607_954_946_681e-6, 2.020_795_375_002_273_5e-8),
    ];
    for (poses, want, tol) in [
        (&d1f9937d, &d1f9937d_ref, 1e-7),
        (&f5e30d14, &f5e30d14_ref, 1e-8),
    ] {
        let five = FivePositions::new(poses).unwrap_or_else(|e| panic!("{e:?}: {poses:?}"));
        let pts = five.burmester_points();
        assert_eq!(pts.len(), 2, "{pts:?}");
        assert!(five.sliders().is_empty(), "{five:?}");
        for w in want {
            assert!(
                pts.iter()
                    .any(|d| (d.center - w).norm() <= tol * five.size()),
                "{w} not in {pts:?}"
            );
        }
    }
    // Four real points by the reference (0.25, 1, 2.3e3 and 1.6e15 task
    // sizes out, the last a slider within rounding); the library gave two,
    // then (fuzz32) refused; since the resultant's roots are found again
    // where they crowd (five33), the reference's three and the slider.
    let c79b068d = task(&[
        (410002949.94890356, 286177534.1168439, 0.609375),
        (0.0002865683181789234, -0.0004097301869864115, 0.609375),
        (
            0.0002865683181789234,
            -0.0004097301869864115,
            -2.532217653589793,
        ),
        (820005899.8975207, 572355068.2340975, -2.532217653589793),
        (2576124511.0177245, 1798106477.6100028, 0.602875),
    ]);
    assert_reference_points(
        &c79b068d,
        &[
            (307385939.84208846, 214799732.90572417),
            (2576124511.0177, 1798106477.6099858),
            (2923316118472.32, -4187543008582.1743),
        ],
        Some((2.089347297581494e24, -2.993381566858419e24)),
    );
}

/// Class A of the `curves` fuzz target's open findings (issue 24, item 4:
/// the library refuses its own points): traced vertices of the
/// center-point or circle-point curve refused by `circle_point` /
/// `center_point` as off the curve. The exact curves of the float tasks
/// (`fuzz/reference/open_curves.py`, sympy and mpmath at 60 digits) put
/// them 2.5e-8 (an edge crossing of a curve traced as a line and a conic,
/// whose conic's vertices were 5e-7 off: the product holds only to 1e-9
/// of the coefficients), 6.3e-3 (a nearly singular stretch in a view 1000
/// wide) and 66 (a spurious oval around a singular point in a view 4e9
/// wide, a pose 1.9e7 away) from the curve, where one ulp of the task moves
/// the curve by 1.4e-14, 4.4e-13 and 2.4e-12: the tracer's points were off,
/// not the test. The tracer now settles every vertex onto the curve
/// (Newton on its own value within a tenth of the chord tolerance; an
/// inner vertex it cannot settle is left out). Checked: every vertex is
/// taken back, lies on the curve within the bounds below (the exact
/// distances after the fix, by the reference: at most 2.1e-10, 3.8e-6 and
/// 0.12, the last the float curve's resolution of its singular point), and
/// on the well-conditioned task its dyad passes the four poses (crank
/// lengths equal to 1e-9 of the crank plus the task size, the rule of
/// `tolerance::DYAD`), which does not use the on-curve test.
#[test]
fn issue24_traced_vertices_are_settled_on_the_curve() {
    type Case = ([(f64, f64, f64); 4], [f64; 4], bool, f64);
    let cases: [Case; 3] = [
        (
            [
                (-0.02275390625, -0.042015625, -0.04274609375),
                (0.038853572944153, -0.9227064419647494, 0.08583984375),
                (7.206768634628719, 6.860268617578484, 17.1875),
                (0.046768867136560394, -0.28195069777709586, -0.0078125),
            ],
            [
                -6.072682076259581,
                9.745848613677023,
                -6.505866381759142,
                9.31266430817746,
            ],
            false,
            1e-9,
        ),
        (
            [
                (73.11328125, -105.09375, -23.93359375),
                (
                    -86.0720594203068,
                    -127.75386565142762,
                    -9.000000000000001e-9,
                ),
                (64.86776245339738, 112.08311298228749, 28.06640625),
                (-139.66718578418778, -81.98453299989845, 37.19921875),
            ],
            [
                -589.7223939957682,
                148.16327225722787,
                -419.6300920437577,
                318.2555742092384,
            ],
            false,
            1e-7,
        ),
        (
            [
                (0.00680005931015625, -3851.1718750001564, -0.205),
                (-19099999.99320039, -3851.17187437, -96.0),
                (0.00680025931015625, -3851.1701934, -49.0),
                (0.008481209310156251, -3851.1718767417, 75.51),
            ],
            [
                -1897966440.4780638,
                1907111684.6336782,
                -1902533566.1052554,
                1902544559.0064867,
            ],
            true,
            1e-8,
        ),
    ];
    for (k, (poses, v, circle, bound)) in cases.into_iter().enumerate() {
        let poses = poses.map(|(x, y, a)| Pose::new(x, y, a));
        let four = FourPositions::new(&poses).unwrap();
        let vp = Viewport::new(v[0], v[1], v[2], v[3]).unwrap();
        let curve = if circle {
            four.circle_point_curve()
        } else {
            four.center_point_curve()
        };
        let mut count = 0;
        let mut worst = 0.0f64;
        let mut near = 0;
        for p in curve.polylines(&vp).into_iter().flatten() {
            count += 1;
            // Case 2 (curv38): next to pose 1's position the exact curve is
            // an oval of radius `0.00437` around a point where its gradient
            // vanishes (the reference, `fuzz/reference/coefficients.py`,
            // `oval`: its value there `-6.2e-20` of the largest coefficient,
            // its Hessian `1.3337` times the identity to `4e-10`, the same
            // to 4 digits in the task moved by one ulp of every number), a
            // feature the curve in doubles cannot hold (its coefficients'
            // rounding alone is `1e-17` there), so the library's curve has
            // an oval of about `0.12` around it, and its first-order
            // distance means nothing there (`1.47` and `27.7`, the gradient
            // all but zero). Its vertices are measured against the exact
            // oval instead (within 1 of its center the cubic's terms beyond
            // the second order are below `1e-8` of the value): at most
            // `0.1215` off, within the bound.
            let oval = Point2::new(0.003361205601754295, -3851.1674592572485);
            let d = if k == 2 && (p - oval).norm() < 1.0 {
                near += 1;
                ((p - oval).norm() - 0.00436759646342).abs()
            } else {
                curve.distance_estimate(p)
            };
            worst = worst.max(d);
            assert!(d <= bound * four.size(), "case {k}: {p} is {d} off");
            let other = taken_back(&four, p, circle, &format!("case {k}"));
            if k == 0 {
                let z = other.unwrap();
                let r: Vec<f64> = (1..=4)
                    .map(|j| (four.displace(z, 1, j).unwrap() - p).norm())
                    .collect();
                let spread = r.iter().fold(0.0f64, |m, x| m.max((x - r[0]).abs()));
                assert!(
                    spread <= 1e-9 * (r[0] + four.size()),
                    "case {k}: {p}: crank lengths {r:?}"
                );
            }
        }
        // Case 1 (curv40): the tracer's point lies on a piece that is a line
        // within the chord tolerance across the view; the trace was two
        // tangles `0.1` across next to it (55 vertices on the curve, the
        // piece across the view untraced: the loops of its pencil are
        // rounding), and is now that piece, edge to edge (2 vertices, each
        // on the curve, as checked above).
        if k == 1 {
            assert!(count >= 2, "case {k}: {count} vertices");
        } else {
            assert!(count > 50, "case {k}: {count} vertices");
        }
        assert!(
            k != 2 || near > 200,
            "case {k}: {near} vertices at the oval"
        );
        eprintln!("case {k}: {count} vertices ({near} at the oval), worst distance {worst:e}");
    }
}

/// The other plane's point of a traced point `p` of the center-point curve
/// (or, `circle`, of the circle-point curve), asserted not refused as off
/// the curve.
fn taken_back(
    four: &FourPositions,
    p: Point2<f64>,
    circle: bool,
    what: &str,
) -> Result<Point2<f64>, Error> {
    let other = if circle {
        four.center_point(p)
    } else {
        four.circle_point(p)
    };
    assert!(
        !matches!(
            other,
            Err(Error::InvalidInput(InvalidInput::OffCurve { .. }))
        ),
        "{what}: traced {p} refused: {other:?}"
    );
    other
}

/// Poses from `(x, y, angle)`.
fn poses_of(p: &[(f64, f64, f64)]) -> Vec<Pose> {
    p.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect()
}

/// The library's Burmester points of `poses` are the exact reference's
/// (`fuzz/reference/open_five.py`'s elimination, sympy and mpmath at 60
/// digits, of this float task): one listed point within `1e-8` task sizes
/// of each real point in `near` (the points are further apart, so each is
/// a different one), none other, and one slider whose direction is that
/// of the reference's point `far` (beyond `1e15` task sizes: at infinity
/// within the rounding of the poses) from the poses' centroid.
fn assert_reference_points(poses: &[Pose], near: &[(f64, f64)], far: Option<(f64, f64)>) {
    let five = FivePositions::new(poses).unwrap_or_else(|e| panic!("{e:?}: {poses:?}"));
    let pts = five.burmester_points();
    assert_eq!(pts.len(), near.len(), "{five:?}");
    for &(x, y) in near {
        assert!(
            pts.iter()
                .any(|d| (d.center - Point2::new(x, y)).norm() <= 1e-8 * five.size()),
            "({x}, {y}) not in {five:?}"
        );
    }
    let sliders = five.sliders();
    assert_eq!(sliders.len(), usize::from(far.is_some()), "{five:?}");
    if let Some((x, y)) = far {
        let n = poses.len() as f64;
        let c = poses
            .iter()
            .fold(Vector2::zeros(), |a, p| a + p.position.coords / n);
        let out = (Vector2::new(x, y) - c).normalize();
        let u = sliders[0].direction;
        assert!(
            (out.x * u.y - out.y * u.x).abs() <= 1e-6,
            "slider {u} against the far point's direction {out}"
        );
    }
}

/// Issue 24 (five33): tasks whose four real Burmester points were listed
/// two (or three and a slider) in a turned frame, each against the exact
/// reference of that frame's float task. Seen from the elimination's pole
/// `Q`, two to four of the common points lie within `2e-5` rad of one
/// direction (three Burmester points and a pole nearly on one line), at a
/// `tan` of `0.4` from the chart's axis: the resultant's expanded
/// coefficients cancelled to noise there, its critical points were noise,
/// and the crowd's roots were lost with an even count (taken). Given with
/// that line along an axis, all four were found. Now the roots are found
/// again from the forms turned to each crowd. `21ea384e` also had a pole
/// `1.5e12` task sizes out along the curves' common asymptote taken for a
/// slider (the root it made lost a point near the task, the count even):
/// such a pole is at infinity for the elimination and is matched there.
#[test]
fn issue24_roots_crowded_on_one_line_are_found_in_every_frame() {
    // fuzz/open/burmester_points/point-not-found-in-another-frame-392c3f6d,
    // moved (was 2 of 4).
    assert_reference_points(
        &poses_of(&[
            (920026676.147771, -391856310.4035118, 60.8584073464102),
            (246.09414185723062, 0.0009200260381097809, 62.4292036732051),
            (-2403.310290970858, -14237.617488571055, 60.8584073464102),
            (1166.1197881967908, -391.85723042954976, 63.0),
            (920026676.147771, -391856310.4035118, 62.99859999999986),
        ]),
        &[
            (-10896.630147236332, -3578.3760586466537),
            (592238612.8443569, 114526164.1258541),
            (476909598.4540268, -156263885.0920471),
            (-50689043.682273656, -1395010540.0550835),
        ],
        None,
    );
    // d2493702, moved (was 2 of 4).
    assert_reference_points(
        &poses_of(&[
            (-9923.464039179265, -79.0070602912994, -99.87109375),
            (-9923.464118186386, -79.00712159280621, -99.77109375),
            (-9984.765563698493, -7.900712157919454e-5, -132.87109375),
            (-9923.464118186386, -79.00712159280621, -100.98909375000117),
            (-9984.765625, -3.9314362386005865e-15, -100.87109375),
        ]),
        &[
            (-9974.698284022657, -55.47313473224922),
            (-9949.795032660908, -36.15201043328233),
            (-9923.462319478016, -79.00735286880719),
            (-9863.62643811539, 30.706620716431257),
        ],
        None,
    );
    // d5f76a33, moved (was 2 of 4).
    assert_reference_points(
        &poses_of(&[
            (-32226.768378512574, -94664.85831546837, -3.469717653589793),
            (
                -0.01611333685684324,
                -0.047332445271165716,
                -0.3281250000000002,
            ),
            (
                -0.016113431521764185,
                -0.047332413044270376,
                -2.8724250000000002,
            ),
            (0.015105550000964009, -0.11077825761027467, 0.671875),
            (-32226.863043348127, -94664.82608860212, -0.32812405000085),
        ]),
        &[
            (-39803.786453475295, -39267.520168790135),
            (-0.016585812595031658, -0.06335403648499772),
            (-4365.749212716005, -51331.72114294462),
            (157627.2308556607, -106479.12828285935),
        ],
        None,
    );
    // 0067c67e, moved (was 2: a near point missed); the fourth point
    // 3.5e17 task sizes out, a slider within rounding (as given: 3 and a
    // slider).
    assert_reference_points(
        &poses_of(&[
            (-7651734.772242906, -24266192.346044935, -99.265625),
            (-7651734.772242906, -24266192.346044935, -102.4072176535898),
            (0.9537097958385649, -0.3007284910372859, -99.265625),
            (3.940934106430938, 2.051401270095176, -100.265625),
            (1.8984762140064462, 2.695439197225771, -102.4072176535898),
        ]),
        &[
            (-6471725.530353457, -11298790.269818287),
            (1.4849442166142335, 1.383992066143203),
            (9295007.975106942, -16270434.680280777),
        ],
        Some((5.115790715766024e24, -1.6131364374444255e24)),
    );
    // 533082da, moved (was 2: the point 89 task sizes out missed).
    assert_reference_points(
        &poses_of(&[
            (-0.008567884056360787, 0.005156681374368464, 71.71484375),
            (-0.02570365216908236, 0.015470044123105391, 71.71484375),
            (0.0, 0.0, 68.5732510964102),
            (
                -0.008567884056360787,
                0.005156681374368464,
                68.5732510964102,
            ),
            (-0.02691680160827217, 0.016200192322619288, 71.71344375),
        ]),
        &[
            (-0.7553442496436515, -1.2307725633645383),
            (-0.02691680160827066, 0.016200192322618396),
            (-0.010692967579462326, 0.006473910474028521),
        ],
        Some((1021825509795433.2, 1697774568208847.8)),
    );
    // 21ea384e, moved (was 2 and 2 sliders: a near point missed, a far
    // pole a slider).
    assert_reference_points(
        &poses_of(&[
            (9.377734375000001e-14, 6.2390625e-14, 6.8e-13),
            (1.7109375e-14, 6.237568359374999e-14, -PI),
            (
                -5.955859375000001e-14,
                6.23607421875e-14,
                -2.220446049250313e-16,
            ),
            (-1.362265625e-13, 6.234580078125e-14, -PI),
            (-2.1289453125e-13, 6.2330859375e-14, -1.0),
        ]),
        &[
            (-2.134625340884397e-14, 6.865531680012397e-13),
            (-2.1289453125010605e-13, 6.233085937507822e-14),
            (-2.1224609375031813e-14, 6.236821289060544e-14),
        ],
        Some((-0.18156912545425133, 931.6750915794414)),
    );
}

/// Issue 24 (five37): two pairs of poses at one position each, half a turn
/// apart (`P13 = P24` within rounding: a Burmester center, the two
/// rotations about it leave two conditions on the circle point). Every
/// choice of the shared poses whose `Q` or shared pole is at that point is
/// blind to it (it is `Q`, a double common point there, or taken out as the
/// pole); the first clean such choice was taken and the point left out, an
/// even count. Now, where the answer lacks the point at coincident poles
/// (verified, concyclic to rounding), the choices are tried again with the
/// blind ones last, the one taken listing it. Each task is the fuzz
/// finding's other frame, against the exact reference of its float task
/// (`fuzz/reference/open_five.py`): the reference's real points within
/// `1e4` task sizes listed within `1e-8` of `size + d`, the farther ones
/// listed within `1e-6` of `size + d` or as sliders, four in all.
#[test]
fn issue24_a_point_at_coincident_poles_is_required_of_every_choice() {
    let check = |poses: &[(f64, f64, f64)], reference: &[(f64, f64)], at_infinity: usize| {
        let poses = poses_of(poses);
        let five = FivePositions::new(&poses).unwrap_or_else(|e| panic!("{e:?}: {poses:?}"));
        let (c, size) = (centroid(&poses), five.size());
        let pts = five.burmester_points();
        assert_eq!(pts.len() + five.sliders().len(), 4, "{five:?}");
        let mut far = 0;
        for &(x, y) in reference {
            let p = Point2::new(x, y);
            let d = (p - c).norm();
            let listed = |tol: f64| {
                pts.iter()
                    .any(|q| (q.center - p).norm() <= tol * (size + d))
            };
            // A point whose circle point is beyond `1e8` task sizes (nearly
            // a slider) is known to about `1e-7` of `size + d` (a3403902's
            // third point, its circle point `2e16` out).
            let slider_like = pts.iter().any(|q| {
                (q.center - p).norm() <= 1e-6 * (size + d) && (q.circle - c).norm() > 1e8 * size
            });
            if d <= 1e4 * size {
                let tol = if slider_like { 1e-6 } else { 1e-8 };
                assert!(listed(tol), "({x}, {y}) not in {five:?}");
            } else if !listed(1e-6) {
                far += 1;
            }
        }
        assert_eq!(five.sliders().len(), far + at_infinity, "{five:?}");
    };
    // a3403902, moved (was a far point listed twice in place of the point
    // at `P13 = P24`, `-994.62`).
    check(
        &[
            (-991.5112602957687, 7.827697195087474, -126492.1875),
            (-997.734375, 0.0, -126492.1875),
            (-997.734375, 0.0, -126495.32909265358),
            (-991.5112602957687, 7.827697195087474, -126495.32909265358),
            (-14883015.641675306, 11831385.67568453, -126495.37307495074),
        ],
        &[
            (-7442003.576467793, 5915696.751690872),
            (-994.6228024692488, 3.9138676898742717),
            (268828881.83208185, 338145606.21986604),
        ],
        1,
    );
    // beafcbe6, moved (was two points near the far one in place of the
    // point at `P13 = P24`, `-99.58`).
    check(
        &[
            (-99.77792776795152, -0.9219525833453068, 85.99609375),
            (-99.390625, 0.0, 85.99609375),
            (-99.390625, 0.0, 82.8545010964102),
            (-99.77792776795152, -0.9219525833453068, 82.8545010964102),
            (175182.23452060972, -73634.00224294447, 82.81051879925981),
        ],
        &[
            (-99.58427638391255, -0.460976291522193),
            (-1673193.354319753, -3982706.6306969426),
            (87541.22829642099, -36817.462097763644),
        ],
        1,
    );
}

/// Issue 24 (five33): a double root of the resultant whose direction from
/// `Q` holds two common points, one on each root of `f`'s quadratic (the
/// quadratics proportional, beyond the rounding band's test): the point
/// that `h`'s quadratic was nearest zero at was listed twice and the other
/// lost. Each moved frame against the exact reference of its float task.
#[test]
fn issue24_two_points_on_one_line_from_q_are_both_listed() {
    // fuzz/open/burmester_points/point-not-found-in-another-frame-23b098df,
    // moved: both real points were listed twice (4 for 2), `3.5e-6` and
    // `7.4e-6` task sizes off; poses 2, 3 and 5 within `1e-11` task sizes
    // of one position.
    assert_reference_points(
        &poses_of(&[
            (-43421.83527723327, -134590.27692938136, 60.734375),
            (-6.707766915776246e-9, 0.005859374999910994, 61.734375),
            (3.865672158030011e-7, 0.005858387731671675, 61.234375),
            (-0.234036564135073, -0.22635374650369577, 61.734374999999),
            (-9.483919170690497e-7, 0.005858892718912664, 61.73436442),
        ]),
        &[
            (-0.06213956355321914, 0.11155031771031864),
            (108430.05430328513, -109281.67820035576),
        ],
        None,
    );
    // db462cb9, moved: `(-2.5e-5, -0.010016)` listed twice, `(0.005,
    // 1.98781)` missing; the reference has a point at infinity too (the
    // positions of poses 1 and 3, and of 2 and 4, coincide).
    let db462cb9 = poses_of(&[
        (3.316796875e-11, -1.2890625e-10, 0.0),
        (0.010000000033167969, 3.9756249998710937, 0.0),
        (3.316796875e-11, -1.2890625e-10, -PI),
        (0.010000000033167969, 3.9756249998710937, -PI),
        (3.316796875e-11, -0.010000000128906249, -1.0),
    ]);
    let five = FivePositions::new(&db462cb9).unwrap_or_else(|e| panic!("{e:?}"));
    let pts = five.burmester_points();
    assert_eq!(pts.len(), 3, "{five:?}");
    assert_eq!(five.sliders().len(), 1, "{five:?}");
    for (x, y) in [
        (0.0050000000331679685, 1.9878124998710937),
        (-2.5193709610618778e-5, -0.010016087492318454),
        (792.2725195312831, -0.0050000001289062495),
    ] {
        assert!(
            pts.iter()
                .any(|d| (d.center - Point2::new(x, y)).norm() <= 1e-8 * five.size()),
            "({x}, {y}) not in {five:?}"
        );
    }
}

/// Issue 24, class B of `fuzz/open/curves` (curv34): poses 2, 3 and 4 at
/// nearly one position put a line of centers (`x = 3.2998...`) on the
/// center-point curve whose circle points all lie within `1e-5` of pose
/// 1's reference point. The exact arc ends' centers there are known only
/// to rounding along the line (the library put them at `y = -6.78` and
/// `-1.71`), but the class of each center is well decided. The exact
/// reference (`fuzz/reference/open_curves.py`, `class_b_changes`: the
/// exact curve, circle points and Filemon signs of the float task in
/// mpmath) puts the free stretch of the line at `y` in
/// `(-16.2836851391207, -8.76198556324864)`; before the fix a free arc
/// ran from `y = -10.47` to the false end at `-6.78`, over defective
/// centers (`y = -8.62`).
#[test]
fn issue24_a_line_of_centers_with_one_circle_point_has_its_exact_free_stretch() {
    let poses = [
        Pose::new(6.5996180078125, -8.2421875e-8, 66.99609375),
        Pose::new(8.550393225e-6, -8.3984375e-14, 0.058484375),
        Pose::new(8.6328125e-6, 0.0, 0.31640625),
        Pose::new(8.6328125e-6, 0.0, -8.242187500000001e-10),
    ];
    let four = FourPositions::new(&poses).unwrap();
    let driven = Dyad::new(
        Point2::new(6.045784821440137e-6, 4.125328799852609e-6),
        Point2::new(3.299814766909, 0.48602449227914374),
    );
    let fa = four.filemon(&driven).unwrap();
    let (lo, hi) = (-16.2836851391207, -8.76198556324864);
    let big = Viewport::new(
        -245.06204990381906,
        248.36187182795828,
        -246.71196088649415,
        246.7119608452832,
    )
    .unwrap();
    let small = Viewport::new(-10.0, 16.0, -30.0, 10.0).unwrap();
    for view in [&big, &small] {
        // The free arcs' points on the line (x within 1e-3 of 3.2998,
        // y from -100 to 0): from the exact stretch's one end to the other.
        let on_line: Vec<f64> = fa
            .free_center_arcs(view)
            .unwrap()
            .iter()
            .flatten()
            .filter(|p| (p.x - 3.2998).abs() < 1e-3 && (-100.0..0.0).contains(&p.y))
            .map(|p| p.y)
            .collect();
        let top = on_line.iter().copied().fold(f64::MIN, f64::max);
        let bottom = on_line.iter().copied().fold(f64::MAX, f64::min);
        // Inside the exact stretch (to 1e-5, 1.5e-6 task sizes: the signs
        // move by 1.4e-7 per unit of y there and are the float circle
        // points' rounding to about 1e-12), and most of it. Since the
        // accurate coefficients (curv38) the arc ends' centers on the line,
        // known only to rounding along it, land `0.034` and `0.002` inside
        // the exact class changes, and the free arcs leave those stretches
        // out: omitted, which is safe (nothing defective is called free:
        // `check_free_arcs_dense` below), where a free end beyond the exact
        // one would not be. (Before, the ends were within `4.4e-6` and
        // `1.0e-6` of the exact ones; curv37's probe of the points between
        // an arc end and its chord gave them back but cost fuzz findings.)
        eprintln!("free on the line from {bottom} to {top}, exact {lo} to {hi}");
        assert!(
            bottom >= lo - 1e-5 && top <= hi + 1e-5 && top - bottom >= 0.99 * (hi - lo),
            "free on the line from {bottom} to {top}, exact {lo} to {hi}, in {view:?}"
        );
        check_free_arcs_dense(&four, &fa, view, false).unwrap();
        check_free_arcs_dense(&four, &fa, view, true).unwrap();
    }
}

/// Issue 24 (five34): a line from the elimination's pole `Q` that lies on
/// one of the two center-point curves within rounding (poses 1 and 2 at
/// one position, poses 3 and 4 at another: the curve of those four holds
/// the line through `Q` normal to them). Along it the common points are
/// the other curve's roots, but the finite one was taken from the
/// vanishing curve's own linear part (noise, next to `Q`), matched the pole
/// `P23` there, and the pole's root then listed the point at `P12`'s
/// position twice while the point `0.9` task sizes out was lost (the count
/// with multiplicity right: a wrong answer, not a refusal). Against the
/// exact reference of each frame's float task.
#[test]
fn issue24_a_line_on_one_curve_takes_the_other_curve_s_points() {
    // fuzz/open/burmester_points/point-not-found-in-another-frame-62d691aa,
    // moved (was `(1.0e-15, -1.0e-15)` twice, `(-1.57e-8, -1.57e-8)`
    // missing).
    assert_reference_points(
        &poses_of(&[
            (1e-15, -1e-15, -1.0),
            (1e-15, -1e-15, -1e-6),
            (1e-21, -1e-21, -1e-6),
            (1e-21, -1e-21, -PI),
            (6.283185307179586e-15, -3.1411e-8, -1.0),
        ]),
        &[
            (-1.5705502141592713e-08, -1.5705503141593712e-08),
            (1.0000007879762248e-15, -9.999997688010414e-16),
        ],
        None,
    );
    // The same task as given (it passed before).
    assert_reference_points(
        &poses_of(&[
            (1e-12, 1e-12, 1.0),
            (1e-12, 1e-12, 1e-6),
            (9.999999999999999e-19, 9.999999999999999e-19, 1e-6),
            (9.999999999999999e-19, 9.999999999999999e-19, PI),
            (6.283185307179586e-12, 3.1411e-5, 1.0),
        ]),
        &[
            (-1.570550214159271e-05, 1.5705503141593713e-05),
            (1.0000007879762246e-12, 9.999997688010413e-13),
        ],
        None,
    );
}

/// Issue 24 (five34): the merging task the near-merging proptest found
/// refused (fuzz/README.md, five33): two real points and a complex pair
/// `7.03e-5` task sizes off the real plane (exact reference,
/// `fuzz/reference/open_five.py`'s elimination of each float task). The
/// pair's double root was read as two real points on one line from `Q`
/// (`h`'s quadratic nearly a square there, so small at both of `f`'s
/// roots), one of them lost, and every later choice listed fewer points
/// than that one verified: refused as given. Scaled by `1e-3` it was a
/// real double point. Now the pair is resolved as complex (Newton's method
/// in complex coordinates) in both frames: the two real points only.
#[test]
fn issue24_a_complex_pair_near_merging_is_resolved_in_every_frame() {
    let given = [
        (
            -2.9489567245432173,
            -0.7887938318836317,
            -0.3914901592154247,
        ),
        (-3.73333800625165, -0.14731374972875755, -1.496645303625363),
        (-2.8642072888479575, 0.9147138331772993, -1.7233671264788746),
        (-2.943971508646116, 1.2069410485978338, -1.4046151311856172),
        (-2.968472198538632, 0.32128774255266146, -0.5087171719459153),
    ];
    assert_reference_points(
        &poses_of(&given),
        &[
            (-2.0218552359775654, 1.3501024777406698),
            (-2.9348798330879786, -1.4252591020991716),
        ],
        None,
    );
    let scaled: Vec<(f64, f64, f64)> = given
        .iter()
        .map(|&(x, y, a)| (x * 1e-3, y * 1e-3, a))
        .collect();
    assert_reference_points(
        &poses_of(&scaled),
        &[
            (-0.002021855235977565, 0.0013501024777406697),
            (-0.0029348798330879793, -0.0014252591020991721),
        ],
        None,
    );
}

/// The task, driven center and view of `fuzz/regressions/curves/trace-spent-
/// its-budget-far-outside-the-view-30957a36` (issue 24 item 10; curv38):
/// poses at one height (collinear positions). Its center-point trace in
/// that view placed the most vertices a trace may (its budget, about a
/// million: 9 s in a debug build), so that the free arcs took seconds; that
/// was a tracer defect (trace38: an oval `1e15` across, wholly outside the
/// view, refined far out), and the trace is 65 vertices since. No slow
/// input for the free arcs is known (they take no tolerance: at the default
/// one an honest trace is a few hundred vertices); the trace's own cancel
/// flag is tested on a long trace at the finest tolerance
/// (`geom::cubic::trace::tests::a_long_trace_stops_when_cancelled`).
fn issue24_degenerate_free_arcs() -> (FourPositions, FilemonArcs, Viewport) {
    let poses = [
        Pose::new(-0.0050156325192544544, -0.04285546875, 2.145498903589793),
        Pose::new(-0.024261718749999998, -0.04285546875, PI),
        Pose::new(0.04552510321552368, -0.04285546875, -69.9716886884063),
        Pose::new(-0.0242356624321997, -0.04285546875, 3.106436403589793),
    ];
    let four = FourPositions::new(&poses).unwrap();
    let driven = four
        .dyad_from_center(Point2::new(0.018279447201332996, 0.010930869792860197))
        .unwrap();
    let fa = four.filemon(&driven).unwrap();
    let view = Viewport::new(
        -0.029242633635673303,
        0.0658015280383393,
        -0.0365912110441461,
        0.058452950629866496,
    )
    .unwrap();
    (four, fa, view)
}

/// Issue 24 item 10: the free arcs follow a control. Without cancelling,
/// progress up to `(total, total)`; a
/// control that cancels at its `n`-th progress report stops there with
/// `Cancelled` (before the end), and one cancelled before the call stops
/// before tracing, in both planes.
#[test]
fn issue24_free_arcs_stop_when_cancelled() {
    use std::sync::Mutex;
    use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

    use burmester::Control;

    let (_, fa, view) = issue24_degenerate_free_arcs();
    let stop = AtomicBool::new(false);
    let last = Mutex::new((0, 0));
    let hook = |d: usize, t: usize| *last.lock().unwrap() = (d, t);
    let control = Control::new().with_cancel(&stop).with_progress(&hook);
    // (`free_center_arcs` is this call without a flag.)
    fa.free_arcs_with(&view, false, &control).unwrap();
    let (done, total) = *last.lock().unwrap();
    assert_eq!(done, total);
    assert!(total > 0, "{total} traced vertices");
    // (A cancel at the first progress report of the vertices' classes:
    // the trace is 65 vertices, one report every 1024.)
    let n = 1;
    let (stop, polls) = (AtomicBool::new(false), AtomicUsize::new(0));
    let hook = |_: usize, _: usize| {
        if polls.fetch_add(1, Ordering::Relaxed) + 1 >= n {
            stop.store(true, Ordering::Relaxed);
        }
    };
    let control = Control::new().with_cancel(&stop).with_progress(&hook);
    let r = fa.free_arcs_with(&view, false, &control);
    assert!(
        matches!(r, Err(Error::Cancelled { done, total: t }) if done < t && t == total),
        "{r:?}"
    );
    assert_eq!(polls.load(Ordering::Relaxed), n);
    let stop = AtomicBool::new(true);
    let control = Control::new().with_cancel(&stop);
    for r in [
        fa.free_arcs_with(&view, false, &control),
        fa.free_arcs_with(&view, true, &control),
    ] {
        assert!(
            matches!(r, Err(Error::Cancelled { done: 0, total: 0 })),
            "{r:?}"
        );
    }
}

/// Issue 24 (curv37, class A, `fuzz/open/curves/...-8166567f`, `-ff0c767c`,
/// `-ccfd9a3e`): the circle-point trace of each task in the fuzz check's
/// view, every vertex taken back by `center_point` (never `OffCurve`). The
/// refused vertices were edge crossings: the crossing, found in the
/// curve's local frame, came back to the plane an ulp outside the view's
/// edge, so the settling took it for an inner point and left it where it
/// was (`1.53e-18` off the exact curve against a tolerance of `8.6e-19`
/// in a task of `1e-10`: `fuzz/reference/open_curves.py`).
#[test]
fn issue24_edge_crossings_are_settled_on_the_curve() {
    type Case = ([(f64, f64, f64); 4], [f64; 4]);
    let cases: [Case; 3] = [
        (
            [
                (-9.36796875e-11, -3.9062500000000004e-24, 0.00803125),
                (-1.00390625e-21, -9.90078125e-20, -3.90625),
                (
                    -3.9062500000000004e-24,
                    -3.9062500000000004e-24,
                    0.00999609375,
                ),
                (-1.00390625e-21, -9.90078125e-20, -0.9453125),
            ],
            [
                -8.139118066402761e-10,
                7.669329199109081e-10,
                -7.904256210728244e-10,
                7.904191054783599e-10,
            ],
        ),
        (
            [
                (45.0, -0.015625, -0.205),
                (-1910000000000000.0, 63.0, -96.0),
                (65.0, 86240.0, 38.0),
                (86240.0, -174.17000000000002, 1.7406999999999998e-5),
            ],
            [
                -4.234718635805716e17,
                4.225984489321785e17,
                -4.2394305908839846e17,
                4.221272534243516e17,
            ],
        ),
        (
            [
                (3.112109375e-8, -3.5156250000000004e-5, 23.0),
                (0.0, 1.571640625e-7, -8.984375000000001e-10),
                (-4.0007812500000005e-8, -6.89375e-8, 0.0675546875),
                (31433.59375, -76.0, 0.0),
            ],
            [
                -69155.60879098617,
                84820.33564295432,
                -77033.00723725096,
                76942.93719668953,
            ],
        ),
    ];
    for (k, (poses, v)) in cases.into_iter().enumerate() {
        let poses = poses.map(|(x, y, a)| Pose::new(x, y, a));
        let four = FourPositions::new(&poses).unwrap();
        let vp = Viewport::new(v[0], v[1], v[2], v[3]).unwrap();
        for circle in [false, true] {
            let curve = if circle {
                four.circle_point_curve()
            } else {
                four.center_point_curve()
            };
            let mut count = 0;
            for p in curve.polylines(&vp).into_iter().flatten() {
                count += 1;
                assert!(vp.contains(p), "case {k}: {p} outside {vp:?}");
                let _ = taken_back(
                    &four,
                    p,
                    circle,
                    &format!("case {k} (circle plane {circle})"),
                );
            }
            // (The refused vertices were in the circle plane.)
            assert!(!circle || count >= 2, "case {k}: {count} vertices");
        }
    }
}

/// Issue 24 (curv37, class B, `fuzz/regressions/curves/...-4279ce91`): poses 2, 3
/// and 4 within `0.3` of one position in a task of `6e4`, poses 2 and 3
/// `3.9e-6` rad apart. The plain expansion of the curves' determinant
/// cancelled most of its terms' digits there, and the rows' entries had
/// already lost them (each rotation `R_k` rounded on its own, so `R_3 - R_2`
/// kept 10 digits): the center-point cubic was `2.4e-8` of its largest
/// coefficient off the exact one, and its point near the fuzz check's chord
/// `0.0357` off the exact curve, where one ulp of every number of the task
/// moves the exact curve `1e-11` (so a point of the float curve had a
/// circle point of the other class). The reference: the local coefficients
/// (the library's origin and scale, below) of the exact curves of this
/// float task, expanded in rational arithmetic (`fuzz/reference/
/// coefficients.py`: the cosines and sines of the exact angle differences
/// to 100 digits), normalised by the largest. One ulp of every coordinate
/// and angle (8 random sign patterns) moves them by `1.2e-15` (center) and
/// `3.2e-15` (circle) of the largest; the library's are now within `1e-14`.
#[test]
fn issue24_curve_coefficients_keep_their_digits_on_poses_at_one_position() {
    let poses = [
        Pose::new(80996.09375, -9.6875e-10, 8.99609375),
        Pose::new(-0.09438671875, 0.28515625, 0.0),
        Pose::new(0.0, -3.8671875e-10, -3.90625e-6),
        Pose::new(0.0, 0.0, -0.005),
    ];
    let four = FourPositions::new(&poses).unwrap();
    #[rustfmt::skip]
    let exact: [[f64; 10]; 2] = [
        [-0.01430679091658008, 0.0300509227995131, 0.1639426460282141, 0.10810223254835977,
         -0.571751781082427, -0.39835017687437024, -0.3324518534951987, 1.0,
         -0.3324518534951987, 1.0],
        [0.015485980889794883, -0.09206220870167434, -0.16343702370916238, 0.18743151019594478,
         0.6980578855243231, 0.3984323150295958, -0.11085582852471805, -1.0,
         -0.11085582852471805, -1.0],
    ];
    for (curve, exact, what) in [
        (four.center_point_curve(), exact[0], "center"),
        (four.circle_point_curve(), exact[1], "circle"),
    ] {
        let (c, origin, scale) = curve.local_coefficients();
        // The reference's frame.
        assert_eq!(
            (origin.x, origin.y, scale),
            (20248.999840820314, 0.0712890621611328, 60747.09390922152)
        );
        let err = c
            .iter()
            .zip(exact)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        eprintln!("{what}: coefficients {err:e} of the largest off the exact ones");
        assert!(err <= 1e-14, "{what}: {c:?} is {err:e} off");
    }
    // The exact curve's point nearest the fuzz check's point (mpmath at 100
    // digits) is on the library's curve (it was 0.0357 off).
    let p = Point2::new(40497.97540367286, 8816.811801789368);
    let d = four.center_point_curve().distance_estimate(p);
    assert!(d <= 1e-9, "{d}");
}

/// Issue 24 (trace38, class A: `fuzz/regressions/curves/traced-vertex-far-
/// outside-the-view-off-the-curve-110094bf`, poses at one position): the
/// circle-point trace in the fuzz check's view left a vertex at
/// `(-2843.7, -3412.3)`, a million view sizes out of a view `0.003` wide,
/// which `center_point` refused as off the curve (`1.17e-5` against a
/// tolerance of `6.1e-6`). Each curve's trace in the view has every vertex
/// in it, and `center_point` takes every traced circle point.
#[test]
fn trace38_traced_vertices_stay_in_their_view() {
    let poses = [
        Pose::new(
            -98.04650351119562,
            0.002342918359609375,
            -1.2412198464102069,
        ),
        Pose::new(-98.04701331549798, 0.002342918359609375, 3.136592610257762),
        Pose::new(-98.0470107762724, 0.002342918359609375, 3.2565926535897933),
        Pose::new(-98.047013317374, 0.002342918359609375, 3.145498903589793),
    ];
    let four = FourPositions::new(&poses).unwrap();
    let view = Viewport::new(
        -98.04832293919648,
        -98.0454481188109,
        0.0009055082560539885,
        0.003780328641636832,
    )
    .unwrap();
    let mut count = 0;
    for curve in [four.center_point_curve(), four.circle_point_curve()] {
        for p in curve.polylines(&view).into_iter().flatten() {
            assert!(view.contains(p), "{p} outside the view");
            count += 1;
        }
    }
    assert!(count > 0);
    for p in four
        .circle_point_curve()
        .polylines(&view)
        .into_iter()
        .flatten()
    {
        let r = four.center_point(p);
        assert!(
            !matches!(r, Err(Error::InvalidInput(InvalidInput::OffCurve { .. }))),
            "traced circle point {p} refused: {r:?}"
        );
    }
}

/// For each task line of `cases` (its name, the circle plane?, the refused
/// vertex, the exact curve's point that replaces it, the on-curve tolerance
/// reported there, the view `xmin xmax ymin ymax` and the four poses `x y
/// angle`): every traced vertex of both curves in the view taken back, the
/// refused vertex not traced, and the exact point within `1e-3` of the
/// tolerance of a traced vertex.
fn assert_refused_vertex_replaced_by_the_exact_point(cases: &str) {
    for line in cases.lines().filter(|l| !l.is_empty()) {
        let mut words = line.split_whitespace();
        let name = words.next().unwrap();
        let circle: bool = words.next().unwrap().parse().unwrap();
        let n: Vec<f64> = words.map(|v| v.parse().unwrap()).collect();
        assert_eq!(n.len(), 21, "{name}");
        let (refused, exact, tol) = (Point2::new(n[0], n[1]), Point2::new(n[2], n[3]), n[4]);
        let vp = Viewport::new(n[5], n[6], n[7], n[8]).unwrap();
        let poses: Vec<Pose> = n[9..]
            .chunks(3)
            .map(|p| Pose::new(p[0], p[1], p[2]))
            .collect();
        let four = FourPositions::new(&poses).unwrap();
        for plane in [false, true] {
            let curve = if plane {
                four.circle_point_curve()
            } else {
                four.center_point_curve()
            };
            for p in curve.polylines(&vp).into_iter().flatten() {
                let _ = taken_back(&four, p, plane, &format!("{name} (circle plane {plane})"));
            }
        }
        let curve = if circle {
            four.circle_point_curve()
        } else {
            four.center_point_curve()
        };
        let vertices: Vec<Point2<f64>> = curve.polylines(&vp).into_iter().flatten().collect();
        assert!(
            !vertices.contains(&refused),
            "{name}: the refused vertex {refused} is traced"
        );
        let nearest = vertices
            .iter()
            .map(|p| (p - exact).norm())
            .fold(f64::INFINITY, f64::min);
        assert!(
            nearest <= 1e-3 * tol,
            "{name}: the exact point {exact} is {nearest} from the nearest vertex (tolerance {tol})"
        );
    }
}

/// curv39 (issue 24, class A, the eight traced-vertex inputs of
/// `fuzz/open/curves/`): each task's curve in the fuzz check's view, every
/// traced vertex of both curves taken back by `circle_point` /
/// `center_point`, and the refused vertex (an edge crossing in every case)
/// replaced by the exact curve's crossing of that edge
/// (`fuzz/reference/open_curves.py`: the exact curve of the float task,
/// Newton along the edge in mpmath at 60 digits), to a thousandth of the
/// on-curve tolerance there.
///
/// Two causes. Six crossings (`462b0310`, `0b584ef8`, `1adec857`,
/// `23b0b972`, `32450c8c`, `e295bc14`: 1.01 to 1.78 tolerances off) were
/// refined along the edge onto the curve, but the refined point was refused
/// as not zero within `64 eps` of its terms, which ignores the rounding of
/// its plane coordinates (a task hundreds of its sizes from the view), and
/// the unrefined crossing was kept; the exact curve moves there by less
/// than the distance when the task moves by one ulp in three of them
/// (`2.1e-12` against `2.1e-11`, `4.4e-9` against `4.4e-7`, `2.4e-4`
/// against `0.40`). Two (`32bb3f83`, `a0c838da`: `165` and `1.0e6` off,
/// against tolerances of `1.1e-6` and `380`) were a line drawn where the
/// curve is not: the curve traced as a line times a quotient conic whose
/// quadratic terms are `2e-11` and `3e-16` of its linear ones, which the
/// conic sampler took for a line pair.
#[test]
fn curv39_traced_edge_crossings_are_the_exact_curve_s() {
    // One task a line: its name, the circle plane?, the refused vertex, the
    // exact crossing of its edge, the on-curve tolerance reported there,
    // the view (`xmin xmax ymin ymax`) and the four poses (`x y angle`).
    const CASES: &str = "
462b0310 false 0.48130940421703694 -0.00021997469210108082 0.48130940421667221687 -0.00021997469210108082 2.84125270964964e-13 0.48091238309851003 0.4813552323913186 -0.00021997469210108082 0.00022287460070751088 0.4811328144407864 2.9339650901794435e-7 0.3 0.48113347558341263 1.06454076802063e-6 0.3 0.48113413622760665 1.8351036651763917e-6 0.3 0.4811347978232121 2.6067762706451417e-6 -0.09371093750000001
32bb3f83 true 888.1983602397233 12933.801499400006 888.1983602397233 12760.108962420428501 1.0583473246238032e-6 -186.43121354060804 888.1983602397233 12396.60196940095 13471.23154318128 350.7375049901827 12412.904608977884 0.0 350.8348838964327 12760.259609075263 -2.6139396203106458e-11 350.9322628026827 13107.614609172642 3.141592653589793 351.0296417089327 13454.969609270021 3.141592653589793
a0c838da true 7117.250695282906 -3257710.9797775005 -1134915.3653677869075 -3257710.9797775005 380.12351452738915 -3205394.846031315 3350910.03821295 -3257710.9797775005 3298593.9044667645 65980.46875 -3.125e-11 0.0 65980.46875000073 2.923515628304813e-7 0.0 51807.298986901114 40870.330931820965 0.66796875 51807.298986901405 40870.330638813444 0.66796875
0b584ef8 true -448.42378872024807 7.346694153160071 -448.42378872024807 7.3466941531816286531 1.4210468072011154e-11 -448.45088892618463 -448.42378872024807 7.33272831409582 7.359828520032374 -448.4375000000008 7.345703125 0.99609375 -448.4368571484375 7.34625 0.02734375 -448.4375 7.345703124999191 100.0 -448.4375 7.345703124999181 41.0
1adec857 true -0.23740489217118688 -0.001693510899327509 -0.23740489216882194526 -0.001693510899327509 1.7696957319655987e-12 -0.23903744497718263 -0.2358110044130959 -0.001693510899327509 0.001532929664759189 -0.23734876171875 -0.00010509374999999999 0.00099609375 -0.2373488666699115 -0.00010516652559744242 0.0 -0.23754917297355035 1.3712038398777763e-5 73.1132813419961 -0.23744995257071805 -0.0001249079846856963 62.00390625
23b0b972 true -5719.830467605168 -399.9136084517557 -5719.8304676056997371 -399.9136084517557 4.983835988614355e-10 -5720.392850792295 -5719.439028365287 -400.86743087876226 -399.9136084517557 -5719.914563671875 -400.4011343769531 47.99609375 -5719.914728009607 -400.4012468196019 73.11328124999609 -5719.921541005625 -400.3778269189091 0.23828125 -5719.9129256280585 -400.381870545572 30.90625
32450c8c false -4803116.001904903 270.46504067808485 -4803116.0019044585033 270.46504067808485 2.494434409837551e-7 -4803282.634442278 -4802828.716791305 270.46504067808485 724.3826916507588 -4803059.73828125 499.99999834882817 0.28515625 -4803061.4241018435 485.3352358788436 0.058484375 -4803059.767863187 502.0391289619362 0.31640625 -4803041.77176926 502.0391223212631 0.3164061599960937
e295bc14 false -42002067405.50264 -354200972.20397985 -42002067405.902481548 -354200972.20397985 0.3827029756854659 -42375557067.115005 -41630216223.47444 -354200972.20397985 391139871.4365896 -41993473828.125 15042886.328125 73.03515625 -42004646249.84896 19625902.49269017 -8.3984375e-10 -42004647968.12623 19624159.82289651 0.000375 -42008781796.727806 19625898.372381777 0.0
";
    assert_refused_vertex_replaced_by_the_exact_point(CASES);
}

#[test]
fn curv40_a_nearly_straight_piece_through_the_pencil_point_is_traced_across_the_view() {
    // The tracer's pencil point on a piece of the curve that is a line
    // within the chord tolerance across the view (issue 24, class B of
    // curv39: the trace folded back along the piece, which left it partly
    // untraced). One task a line: its name, the circle plane?, the view
    // (`xmin xmax ymin ymax`), the four poses (`x y angle`), the exact
    // crossings of the piece with the view's edges (2 points) and the exact
    // curve's points next to the chord between them at 0.1, 0.3, 0.5, 0.7
    // and 0.9 of it (5 points): `python fuzz/reference/open_curves.py
    // curv40` (mpmath, 60 digits).
    const CASES: &str = "
e067e5da true -798.3274965931357 779.8362538419599 -683.3446684106343 894.8190820244613 -0.00200390625 107.5 31.25 -17.631854817288307 106.02446735641578 -0.001 -17.737756948394164 106.00667311471496 0.0 -29.205900296226382 103.41768675652295 0.10955078125 779.83625384195988772 270.71128609431932135 -798.3274965931357201 -276.96287195114768133 622.01987881510575956 215.94387023117463618 306.38712880428751052 106.40903840788631229 -9.245625058968969297 -3.1257823142763106363 -324.87837154992517657 -112.66062428034715949 -640.51112156559856615 -222.19545608964555515
719363d5 false -41.447670459778394 1.0803654727651093 -41.42202070338598 1.1060152291575172 -0.06526562500000001 -0.00082421875 0.28515625 2.6e-8 -8.3984375e-10 0.058160156250000004 2.6e-8 -8.3984375e-10 0.31640625 0.0 0.0 -3.90625e-12 -0.046605511608247516926 1.1060152291575171546 0.49046644167890068978 -41.422020703385982188 0.0071017004906220629677 -3.1467883638850488142 0.11451608543666970727 -11.652395550465875546 0.22193047269822071092 -20.158002737017462234 0.32934486023218262359 -28.663609923565605174 0.43675924785273136263 -37.169217110112665296
5a77a1d1 true 35484.80055236068 38282.7663499924 -1397.7099957011076 1400.255801930611 35836.490347108884 -0.10002734375 2.145498903589793 35840.234375 -0.10002734375 3.141592653589793 35840.23430756839 -0.10002734375 3.145647341089793 35840.229306159425 -0.10002734375 3.106436446445262 35484.800552360677102 186.38558794412586307 38282.766349992401956 -1279.1542721118724219 35764.597132122361765 39.831601935691027911 36324.190291650657023 -253.27637007178814051 36883.783451176798299 -546.38434208337962647 37443.376610703027702 -839.49231409480280543 38002.969770229277228 -1132.6002861061877944
5855fc72 true -789093.6007922697 786364.2714849757 -1534229.613022059 41228.25925518642 -2417.96875 0.00025 -0.8515625 0.00025002675 -9.648437500000001e-10 0.058484375 0.0 0.0005 0.31640625 0.00025002675 -9.648437500000001e-10 0.000500045 -1209.038713549145986 41228.259255186421797 -1206.7094062735023497 -1534229.6130220589694 -1208.8057810019563477 -116317.52797253813791 -1208.3399178005350898 -431409.10242798714371 -1207.8740571984714552 -746500.67688343626977 -1207.4081967914680329 -1061592.2513388851633 -1206.9423364397411612 -1376683.8257943345225
3633626e true -4137669216922467.0 114539408766058.5 -4149784452624695.0 102424173063830.25 6526171874999.915 -82422.0004921875 0.28515625 -82419.3603359375 -83984.5004921875 0.0 1171874.9146640624 -0.1254921875 81.00390625 -0.0853359375 599999.8745078126 -0.04266796875 3267196043912.9861138 -4149784452624695.0 3263011393493.4905125 102424173063830.25 3266777679903.7310879 -3724563590055842.4006 3265940954183.590092 -2874121864918137.1995 3265104234740.3759504 -2023680139780431.992 3264267535171.4050256 -1173238414642726.7646 3263431010343.1154673 -322796689505021.35955
";
    for line in CASES.lines().filter(|l| !l.is_empty()) {
        let mut words = line.split_whitespace();
        let name = words.next().unwrap();
        let circle: bool = words.next().unwrap().parse().unwrap();
        let n: Vec<f64> = words.map(|v| v.parse().unwrap()).collect();
        assert_eq!(n.len(), 4 + 12 + 14, "{name}");
        let vp = Viewport::new(n[0], n[1], n[2], n[3]).unwrap();
        let poses: Vec<Pose> = n[4..16]
            .chunks(3)
            .map(|p| Pose::new(p[0], p[1], p[2]))
            .collect();
        let exact: Vec<Point2<f64>> = n[16..].chunks(2).map(|p| Point2::new(p[0], p[1])).collect();
        let four = FourPositions::new(&poses).unwrap();
        let curve = if circle {
            four.circle_point_curve()
        } else {
            four.center_point_curve()
        };
        let trace = curve.trace(&vp, None).unwrap();
        let tol = trace.tolerance;
        let lines = trace.polylines();
        for p in lines.iter().flatten() {
            let _ = taken_back(&four, *p, circle, name);
        }
        // Both exact edge crossings are ends of polylines.
        for x in &exact[..2] {
            let nearest = lines
                .iter()
                .flat_map(|l| [l[0], l[l.len() - 1]])
                .map(|p| (p - x).norm())
                .fold(f64::INFINITY, f64::min);
            assert!(
                nearest <= 1e-3 * tol,
                "{name}: the exact crossing {x} is {nearest} from the nearest end (tolerance {tol})"
            );
        }
        // The exact piece between them is traced, within the tolerance.
        for x in &exact[2..] {
            let nearest = lines
                .iter()
                .flat_map(|l| l.windows(2))
                .map(|w| {
                    let ab = w[1] - w[0];
                    let u = ((x - w[0]).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
                    (w[0] + ab * u - x).norm()
                })
                .fold(f64::INFINITY, f64::min);
            assert!(
                nearest <= tol,
                "{name}: the exact curve's point {x} is {nearest} from the trace (tolerance {tol})"
            );
        }
    }
}

/// curv42 (issue 24, the two traced center points of curv41's round that
/// `circle_point` refused): poses at angles `0` and `pi`, `1e19` to `1e23`
/// from the origin, whose center-point curve is a conic within `1e-13` of a
/// line pair (`trace_factored`: the tangent line and the quotient, drawn as
/// its line). The pair's node is on the view's edge (the quotient's line is
/// the edge within rounding), and the line's end there, which did not
/// settle along the edge (the edge runs along a branch), was kept: off the
/// curve by `5.3e14` and `9.4e9` against on-curve tolerances of `1.3e14` and
/// `1.5e10` (the float curve; `fuzz/reference/open_curves.py curv41-a`:
/// `3.2e15` and `1.9e10` from the exact curve). Each task in the fuzz
/// check's view: every traced vertex of both curves taken back, the refused
/// vertex not traced, and the exact curve's point next to the line's new end
/// (`open_curves.py curv42`: the new end projected onto the exact curve of
/// the float task, mpmath at 60 digits) within `1e-3` of the on-curve
/// tolerance of a traced vertex.
#[test]
fn curv42_a_line_pair_s_node_on_the_view_s_edge_is_settled_onto_the_curve() {
    // One task a line: its name, the circle plane?, the refused vertex,
    // the exact curve's point, the on-curve tolerance reported there, the
    // view (`xmin xmax ymin ymax`) and the four poses (`x y angle`).
    const CASES: &str = "
11e1f642 false 52999887614849670000000.0 2919304000000000000000.0 5.2999887322202693634e22 2.9193035620228552496e21 132061133760150.3 5.167927627724836e22 5.432049895245136e22 2.7808132479699753e20 2.919304e21 2.676510399999996e22 2.919304e21 0.0 5.78085420887002e19 2.919304e21 0.0 1.8506102137499996e23 2.919304e21 3.141592653589793 1.1561654231082068e20 2.919304e21 3.141592653589793
aefd216a false 17982707313448956000.0 32.0 17982707308237831610.0 7798999457.5333681681 15111407313.448957 1.7831593240314466e19 1.8133821386583446e19 32.0 3.022281462689792e17 2.8713e18 3.1415926455116683 0.0 6.644645503795821e18 7.270145734513581 0.0 3.2158560000000004e19 35.18583763176272 3.141592653589793 3.0256323750000005e19 33.10453250397926 3.141592653589793
";
    assert_refused_vertex_replaced_by_the_exact_point(CASES);
}
