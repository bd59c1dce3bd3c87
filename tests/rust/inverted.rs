//! The inverted slider-crank (issue 27): position analysis against Norton's
//! closed form (*Design of Machinery*, §4.7, the inverted slider-crank:
//! the tangent half-angle quadratic in `theta4`, eq. 4.18, and the slider
//! length `b`, eq. 4.20) and against a dense independent solver (both
//! modes); the modes named as a four-bar's whose coupler pin goes to
//! infinity along the slot's normal; dead positions, stroke along the slot,
//! swing of the slotted link and transmission angle against dense sampling.
//! The inverted slider-crank of a task: tasks made from known inverted
//! slider-cranks, the swivel and slot found among the library's inverted
//! sliders, the built linkage reaching the poses, its branch/order verdict
//! against dense driving, and invariance under moves, rotations, scaling.

mod common;

use std::f64::consts::PI;

use burmester::{
    AssemblyMode, Direction, Error, FourBar, InvertedSlider, InvertedSliderCrank, Point2, Pose,
    Task, Vector2,
};
use common::wrap;
use proptest::prelude::*;

fn cross(u: Vector2<f64>, v: Vector2<f64>) -> f64 {
    u.x * v.y - u.y * v.x
}

fn unit(a: f64) -> Vector2<f64> {
    Vector2::new(a.cos(), a.sin())
}

/// Norton's inverted slider-crank, eq. 4.18 (crank `a`, ground `d` along
/// +x from `O2` at the origin, rocker `c` at `gamma` to the slider axis):
/// both `(theta3, theta4, b)`, from the tangent half-angle quadratic
/// `S t^2 + T t + U = 0`, `S = R - Q`, `T = 2P`, `U = Q + R`.
fn norton(a: f64, c: f64, d: f64, gamma: f64, theta2: f64) -> Vec<(f64, f64, f64)> {
    let (s2, c2) = theta2.sin_cos();
    let p = a * s2 * gamma.sin() + (a * c2 - d) * gamma.cos();
    let q = -a * s2 * gamma.cos() + (a * c2 - d) * gamma.sin();
    let r = -c * gamma.sin();
    let (s, t, u) = (r - q, 2.0 * p, q + r);
    let disc = t * t - 4.0 * s * u;
    if disc < 0.0 {
        return vec![];
    }
    [1.0, -1.0]
        .iter()
        .map(|sg| {
            let theta4 = 2.0 * ((-t + sg * disc.sqrt()) / (2.0 * s)).atan();
            let theta3 = theta4 + gamma;
            // eq. 4.20: b = (a sin theta2 - c sin theta4) / sin theta3.
            let b = (a * s2 - c * theta4.sin()) / theta3.sin();
            (theta3, theta4, b)
        })
        .collect()
}

#[test]
fn agrees_with_nortons_closed_form_in_both_modes() {
    let mut checked = 0;
    for &(a, c, d, gamma) in &[
        (40.0, 0.0, 100.0, PI / 2.0),
        (40.0, 15.0, 100.0, PI / 2.0),
        (40.0, -12.0, 90.0, 1.2),
        (130.0, 20.0, 60.0, 2.0),
        (75.0, 5.0, 80.0, 0.7),
    ] {
        // Norton's ground O4 = (d, 0) is the swivel; his slider axis runs
        // through A at `c sin gamma` from O4: our slot through S at the
        // offset e = c sin gamma from A (module docs).
        let e = c * f64::sin(gamma);
        let inv = InvertedSliderCrank::new(Point2::origin(), a, Point2::new(d, 0.0), e).unwrap();
        for i in 0..72 {
            let t2 = -PI + (i as f64 + 0.37) * PI / 36.0;
            let book = norton(a, c, d, gamma, t2);
            let ours: Vec<_> = AssemblyMode::BOTH
                .iter()
                .filter_map(|&m| inv.solve(t2, m).ok())
                .collect();
            assert_eq!(book.len(), ours.len(), "{a} {c} {d} {gamma} at {t2}");
            for c3 in &ours {
                // Norton's b runs from B to A: b = -t - c cos gamma.
                let b = -c3.slot - c * gamma.cos();
                let hit = book.iter().any(|&(t3, _, bb)| {
                    wrap(t3 - c3.theta3).abs() < 1e-9 && (bb - b).abs() < 1e-9 * (a + d)
                });
                assert!(hit, "{a} {c} {d} {gamma} at {t2}: {c3:?} not in {book:?}");
                checked += 1;
            }
            // The two roots are the two modes, not one twice.
            if ours.len() == 2 && !ours[0].toggle {
                assert!(wrap(ours[0].theta3 - ours[1].theta3).abs() > 1e-6);
            }
        }
    }
    assert!(checked > 600, "{checked}");
}

/// All coupler angles `theta3` that close the loop at `theta2`, by a dense
/// scan of `f(theta3) = cross(u3, S - A) - e` over a full turn and
/// bisection: the independent solver.
fn dense_roots(inv: &InvertedSliderCrank, t2: f64) -> Vec<f64> {
    let a = inv.crank_pivot() + unit(t2) * inv.crank();
    let w = inv.swivel() - a;
    let f = |t3: f64| cross(unit(t3), w) - inv.offset();
    let n = 20_000;
    let mut out = Vec::new();
    for i in 0..n {
        let (mut lo, mut hi) = (
            -PI + 2.0 * PI * i as f64 / n as f64,
            -PI + 2.0 * PI * (i + 1) as f64 / n as f64,
        );
        if f(lo).signum() == f(hi).signum() {
            continue;
        }
        for _ in 0..80 {
            let mid = 0.5 * (lo + hi);
            if f(mid).signum() == f(lo).signum() {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        out.push(0.5 * (lo + hi));
    }
    out
}

#[test]
fn agrees_with_a_dense_independent_solver() {
    let cases = [
        (Point2::new(0.0, 0.0), 100.0, Point2::new(0.0, -300.0), 0.0),
        (Point2::new(10.0, 5.0), 60.0, Point2::new(150.0, 40.0), 25.0),
        (Point2::new(-3.0, 2.0), 2.0, Point2::new(1.0, 0.5), -0.4),
        (Point2::new(0.0, 0.0), 50.0, Point2::new(30.0, 0.0), 10.0),
        (Point2::new(0.0, 0.0), 50.0, Point2::new(45.0, 0.0), 20.0),
    ];
    for (a0, r, s, e) in cases {
        let inv = InvertedSliderCrank::new(a0, r, s, e).unwrap();
        for i in 0..90 {
            let t2 = -PI + (i as f64 + 0.21) * PI / 45.0;
            let roots = dense_roots(&inv, t2);
            let a = a0 + unit(t2) * r;
            let sols: Vec<_> = AssemblyMode::BOTH
                .iter()
                .filter_map(|&m| inv.solve(t2, m).ok())
                .collect();
            if roots.is_empty() {
                assert!(sols.is_empty(), "{t2}");
                let err = inv.solve(t2, AssemblyMode::Open).unwrap_err();
                assert_eq!(err.cause(), "slot_out_of_reach");
                assert!(!inv.input_range().contains(t2));
                continue;
            }
            assert!(inv.input_range().contains(t2));
            assert_eq!(roots.len(), 2, "{t2}");
            for c in &sols {
                assert!(
                    roots.iter().any(|&x| wrap(x - c.theta3).abs() < 1e-9),
                    "{t2} {c:?}"
                );
                // The mode is the sign of the slot position t = <S - A, u3>.
                let t = (s - a).dot(&unit(c.theta3));
                assert!((t - c.slot).abs() < 1e-9 * (r + (s - a0).norm()));
                assert_eq!(AssemblyMode::from_sign(t), Some(c.mode));
                // The joints: the swivel on the slot's line.
                let j = inv.joints(c);
                assert!(cross(unit(c.theta3), j.swivel - j.slot_foot).abs() < 1e-9 * (r + 300.0));
                assert!((j.slot_foot - j.crank_joint).norm() - e.abs() < 1e-9 * (r + 300.0));
                // Transmission: cos mu = |e| / |S - A|.
                let mu = (e.abs() / (s - a).norm()).acos();
                assert!((mu - c.transmission_angle).abs() < 1e-9);
            }
        }
    }
}

/// The modes carry the four-bar's names in the limit of a coupler pin far
/// along the slot's normal (`B = A + (t, e + R)` in the coupler frame,
/// rocker `S B`).
#[test]
fn four_bar_limit_names_the_modes() {
    let inv =
        InvertedSliderCrank::new(Point2::new(1.0, 2.0), 40.0, Point2::new(120.0, -30.0), 15.0)
            .unwrap();
    let mut checked = 0;
    for i in 0..36 {
        let t2 = -PI + (i as f64 + 0.5) * PI / 18.0;
        for m in AssemblyMode::BOTH {
            let c = inv.solve(t2, m).unwrap();
            let big = 1e6 * 160.0;
            let local = Vector2::new(c.slot, inv.offset() + big);
            let fb = FourBar::from_pivots(
                inv.crank_pivot(),
                inv.swivel(),
                inv.crank(),
                local.norm(),
                big,
            )
            .unwrap();
            let f = fb.solve(t2, m).unwrap();
            let ours = c.theta3 + local.y.atan2(local.x);
            assert!(
                wrap(f.theta3 - ours).abs() < 1e-6,
                "{m:?} {t2}: {} vs {ours}",
                f.theta3
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 72);
}

#[test]
fn dead_positions_stroke_swing_and_time_ratio_against_dense_sampling() {
    let cases = [
        // Quick return (slotted link swings), with and without offset.
        (Point2::new(0.0, 0.0), 100.0, Point2::new(0.0, -300.0), 0.0),
        (
            Point2::new(0.0, 0.0),
            100.0,
            Point2::new(40.0, -280.0),
            35.0,
        ),
        // Whitworth (slotted link turns fully).
        (Point2::new(0.0, 0.0), 100.0, Point2::new(0.0, -40.0), 20.0),
        // A crank that rocks between dead positions.
        (Point2::new(0.0, 0.0), 50.0, Point2::new(45.0, 0.0), 20.0),
    ];
    for (a0, r, s, e) in cases {
        let inv = InvertedSliderCrank::new(a0, r, s, e).unwrap();
        let g = (s - a0).norm();
        assert_eq!(inv.turns_fully(), (g - r).abs() >= e.abs());
        for d in inv.dead_positions() {
            for m in AssemblyMode::BOTH {
                let c = inv.solve(d, m).unwrap();
                assert!(c.toggle && c.slot.abs() < 1e-6 * g, "{c:?}");
                assert!(c.transmission_angle < 1e-6);
            }
            // Between the dead positions the loop closes; pointing at the
            // swivel it does not.
            let range = inv.input_range();
            let mid = 0.5 * (inv.dead_positions()[0] + inv.dead_positions()[1]);
            assert!(range.contains(mid) && !range.contains(mid + PI));
            assert_eq!(
                inv.solve(mid + PI, AssemblyMode::Open).unwrap_err().cause(),
                "slot_out_of_reach"
            );
        }
        for m in AssemblyMode::BOTH {
            let n = 200_000;
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            let mut angles = Vec::new();
            for i in 0..n {
                let t2 = -PI + 2.0 * PI * i as f64 / n as f64;
                if let Ok(c) = inv.solve(t2, m) {
                    lo = lo.min(c.slot);
                    hi = hi.max(c.slot);
                    angles.push(c.theta3);
                }
            }
            // The dead positions themselves (theta3 moves as the square
            // root of the distance from them, faster than samples resolve).
            for d in inv.dead_positions() {
                let c = inv.solve(d, m).unwrap();
                lo = lo.min(c.slot);
                hi = hi.max(c.slot);
                angles.push(c.theta3);
            }
            let [l, h] = inv.slot_limits(m);
            assert!(
                (l.slot - lo).abs() < 1e-6 * g && (h.slot - hi).abs() < 1e-6 * g,
                "{m:?}"
            );
            assert!((inv.stroke() - (hi - lo)).abs() < 1e-6 * g);
            match inv.swing(m) {
                Some([s_lo, s_hi]) => {
                    let reference = angles[0];
                    let un: Vec<f64> = angles
                        .iter()
                        .map(|a| reference + wrap(a - reference))
                        .collect();
                    let (dlo, dhi) = un
                        .iter()
                        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                            (a.min(x), b.max(x))
                        });
                    let swing = s_hi.theta3 - s_lo.theta3;
                    assert!(
                        (swing - (dhi - dlo)).abs() < 1e-4,
                        "{m:?}: {swing} vs {}",
                        dhi - dlo
                    );
                }
                None => {
                    // The slotted link turns fully: every direction is met.
                    assert!(r > g + e.abs());
                    let mut bins = [false; 36];
                    for a in &angles {
                        bins[(((a + PI) / (2.0 * PI) * 36.0) as usize).min(35)] = true;
                    }
                    assert!(bins.iter().all(|b| *b));
                }
            }
        }
    }
    // The shaper: crank 100 mm, swivel 300 mm below, no offset. The ends of
    // the swing are where the crank is perpendicular to the slot, at crank
    // angles 2 acos(r / g) apart: time ratio (pi + 2 asin(r/g)) / (pi - 2 asin(r/g)).
    let q =
        InvertedSliderCrank::new(Point2::origin(), 100.0, Point2::new(0.0, -300.0), 0.0).unwrap();
    let b = (1.0f64 / 3.0).asin();
    let ratio = q.time_ratio(AssemblyMode::Crossed).unwrap();
    assert!(
        (ratio - (PI + 2.0 * b) / (PI - 2.0 * b)).abs() < 1e-9,
        "{ratio}"
    );
}

#[test]
fn errors_are_typed() {
    let o = Point2::origin();
    let e = InvertedSliderCrank::new(o, 1.0, Point2::new(2.0, 0.0), 3.5).unwrap_err();
    assert_eq!(e.cause(), "swivel_out_of_reach");
    assert!(matches!(e, Error::Assembly(_)));
    assert!(e.to_string().contains("offset"), "{e}");
    assert_eq!(
        InvertedSliderCrank::new(o, 0.0, Point2::new(2.0, 0.0), 0.0)
            .unwrap_err()
            .cause(),
        "not_positive"
    );
    assert!(InvertedSliderCrank::new(o, 1.0, Point2::new(f64::NAN, 0.0), 0.0).is_err());
    assert!(InvertedSliderCrank::new(o, 1.0, Point2::new(2.0, 0.0), f64::INFINITY).is_err());
    let max = InvertedSliderCrank::MAX_EXTENT;
    assert!(InvertedSliderCrank::new(o, 2.0 * max, Point2::new(1.0, 0.0), 0.0).is_err());
    // At the documented maxima it still solves.
    let big = InvertedSliderCrank::new(o, max / 4.0, Point2::new(max / 2.0, 0.0), 0.0).unwrap();
    let c = big
        .solve(InvertedSliderCrank::MAX_ANGLE, AssemblyMode::Open)
        .unwrap();
    assert!(c.slot.is_finite() && c.slot > 0.0);
    assert!(
        big.solve(InvertedSliderCrank::MAX_ANGLE * 1.01, AssemblyMode::Open)
            .is_err()
    );
    assert!(big.solve(f64::NAN, AssemblyMode::Open).is_err());
}

// The inverted slider-crank of a task.

/// A task made from a known inverted slider-crank: the coupler point
/// `local` (coupler frame) and the coupler angle plus 0.4 at each crank
/// angle, each in its mode.
fn task_of(
    inv: &InvertedSliderCrank,
    local: Vector2<f64>,
    angles: &[(f64, AssemblyMode)],
) -> Option<Task> {
    let poses: Option<Vec<Pose>> = angles
        .iter()
        .map(|&(t, m)| {
            let c = inv.solve(t, m).ok()?;
            (!c.toggle).then_some(())?;
            Some(Pose {
                position: inv.coupler_point(&c, local),
                angle: c.theta3 + 0.4,
            })
        })
        .collect();
    Task::new(&poses?).ok()
}

fn shaper() -> InvertedSliderCrank {
    InvertedSliderCrank::new(
        Point2::new(0.0, 0.0),
        100.0,
        Point2::new(30.0, -300.0),
        12.0,
    )
    .unwrap()
}

const ANGLES: [f64; 5] = [-0.4, 0.3, 1.1, 1.9, 2.6];

/// The known swivel among the task's inverted sliders, its slot parallel to
/// the known one at pose 1.
fn known_inverted(task: &Task, inv: &InvertedSliderCrank, theta3: f64) -> InvertedSlider {
    let found = if task.len() == 3 {
        task.inverted_slider(inv.swivel()).unwrap()
    } else {
        *task
            .inverted_sliders(1)
            .unwrap()
            .iter()
            .find(|i| (i.swivel - inv.swivel()).norm() < 1e-6 * 300.0)
            .unwrap_or_else(|| panic!("{} poses: swivel not found", task.len()))
    };
    assert!(
        cross(found.direction, unit(theta3)).abs() < 1e-7,
        "{found:?}"
    );
    found
}

#[test]
fn tasks_from_known_inverted_slider_cranks_are_rebuilt() {
    let inv = shaper();
    let local = Vector2::new(180.0, 40.0);
    for n in 3..=5 {
        for m in AssemblyMode::BOTH {
            let angles: Vec<_> = ANGLES[..n].iter().map(|&t| (t, m)).collect();
            let task = task_of(&inv, local, &angles).unwrap();
            let c1 = inv.solve(ANGLES[0], m).unwrap();
            let found = known_inverted(&task, &inv, c1.theta3);
            let pin = inv.crank_pivot() + unit(ANGLES[0]) * inv.crank();
            let driving = burmester::Dyad::new(inv.crank_pivot(), pin);
            let built = task.inverted_slider_crank(&driving, &found).unwrap();
            assert!((built.linkage.crank() - 100.0).abs() < 1e-8);
            assert!((built.linkage.offset().abs() - 12.0).abs() < 1e-7);
            assert!((built.linkage.swivel() - inv.swivel()).norm() < 1e-6);
            // The found slot direction may be the known one turned round:
            // then the modes' names swap.
            let same = found.direction.dot(&unit(c1.theta3)) > 0.0;
            let want = if same { m } else { m.other() };
            assert!(built.is_branch_free(), "{n} {m:?}: {:?}", built.modes);
            assert_eq!(built.modes[0], Some(want));
            assert_eq!(built.direction, Direction::Ccw);
            #[allow(clippy::needless_range_loop)]
            for k in 0..n {
                let p = built
                    .pose_at(built.input_angles[k], built.modes[k].unwrap())
                    .unwrap();
                let q = task.poses()[k];
                assert!(
                    (p.position - q.position).norm() < 1e-7,
                    "{n} {m:?} pose {k}"
                );
                assert!(wrap(p.angle - q.angle).abs() < 1e-9);
                assert!(
                    (built.slot_positions[k].abs() - inv.solve(ANGLES[k], m).unwrap().slot.abs())
                        .abs()
                        < 1e-7
                );
            }
            // Dense driving over the travel passes the poses in order, with
            // no toggle on the way, and the figures agree with it.
            let ts = built.travel_angles(20_001).unwrap();
            let mode = built.modes[0].unwrap();
            let (mut worst_mu, mut lo, mut hi) = (f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY);
            let mut nearest = vec![(f64::INFINITY, 0usize); n];
            for (i, t) in ts.iter().enumerate() {
                let c = built.linkage.solve(*t, mode).unwrap();
                assert!(!c.toggle);
                worst_mu = worst_mu.min(c.transmission_angle);
                lo = lo.min(c.slot);
                hi = hi.max(c.slot);
                let p = built.pose_at(*t, mode).unwrap();
                for (k, q) in task.poses().iter().enumerate() {
                    let d =
                        (p.position - q.position).norm() + 300.0 * wrap(p.angle - q.angle).abs();
                    if d < nearest[k].0 {
                        nearest[k] = (d, i);
                    }
                }
            }
            // Each pose is passed (within the samples' spacing), in order.
            let spacing = (ts[1] - ts[0]).abs() * 600.0;
            for k in 0..n {
                assert!(
                    nearest[k].0 < spacing,
                    "{n} {m:?} pose {k}: {:?}",
                    nearest[k]
                );
                if k > 0 {
                    assert!(nearest[k].1 > nearest[k - 1].1, "{n} {m:?}: order");
                }
            }
            assert!((worst_mu - built.min_transmission).abs() < 1e-6);
            assert!((built.stroke_used - (hi - lo)).abs() < 1e-3);
            assert!(built.feasible());
        }
    }
}

#[test]
fn branch_verdict_agrees_with_dense_driving() {
    let inv = shaper();
    let local = Vector2::new(180.0, 40.0);
    // Pose 2 from the other mode: a branch defect that no driving in one
    // mode passes.
    let angles = [
        (ANGLES[0], AssemblyMode::Open),
        (ANGLES[1], AssemblyMode::Crossed),
        (ANGLES[2], AssemblyMode::Open),
    ];
    let task = task_of(&inv, local, &angles).unwrap();
    let c1 = inv.solve(ANGLES[0], AssemblyMode::Open).unwrap();
    let found = known_inverted(&task, &inv, c1.theta3);
    let driving = task.dyad_from_center(inv.crank_pivot()).unwrap();
    let built = task.inverted_slider_crank(&driving, &found).unwrap();
    assert!(!built.is_branch_free() && !built.feasible());
    assert!(built.stroke_used.is_nan());
    for m in AssemblyMode::BOTH {
        let mut met = [false; 3];
        for i in 0..40_000 {
            let t = -PI + 2.0 * PI * i as f64 / 40_000.0;
            let Ok(p) = built.pose_at(t, m) else { continue };
            for (k, q) in task.poses().iter().enumerate() {
                if (p.position - q.position).norm() < 1e-2 && wrap(p.angle - q.angle).abs() < 1e-4 {
                    met[k] = true;
                }
            }
        }
        assert!(!met.iter().all(|x| *x), "{m:?} passes all poses");
    }
    // Filemon's construction is refused with a typed error that says why.
    let e = burmester::FilemonLines::new(&task, found).unwrap_err();
    assert_eq!(e.cause(), "inverted_driven");
    assert!(e.to_string().contains("parallel"), "{e}");
    // A line that does not pass the swivel at every pose is refused.
    let bad = InvertedSlider {
        swivel: found.swivel + Vector2::new(5.0, 0.0),
        direction: found.direction,
    };
    let e = task.inverted_slider_crank(&driving, &bad).unwrap_err();
    assert_eq!(e.cause(), "not_a_slider");
    let zero = InvertedSlider {
        swivel: found.swivel,
        direction: Vector2::zeros(),
    };
    assert_eq!(
        task.inverted_slider_crank(&driving, &zero)
            .unwrap_err()
            .cause(),
        "zero_direction"
    );
    assert!(built.travel_angles(1).is_err());
}

proptest! {
    #![proptest_config(common::config(48))]

    /// Moving, rotating and scaling the task moves, rotates and scales the
    /// built linkage: the same modes, order, transmission, swing; lengths
    /// and stroke scaled.
    #[test]
    fn invariant_under_moves_rotations_and_scaling(
        dx in -200.0f64..200.0, dy in -200.0f64..200.0, rot in -PI..PI, k in 0.05f64..20.0,
        t0 in -PI..PI, step in 0.2f64..0.6,
    ) {
        let inv = shaper();
        let local = Vector2::new(180.0, 40.0);
        let m = AssemblyMode::Open;
        let angles: Vec<_> = (0..3).map(|i| (t0 + step * i as f64, m)).collect();
        let Some(task) = task_of(&inv, local, &angles) else { return Ok(()) };
        let c1 = inv.solve(t0, m).unwrap();
        let found = known_inverted(&task, &inv, c1.theta3);
        let driving = task.dyad_from_center(inv.crank_pivot()).unwrap();
        let base = task.inverted_slider_crank(&driving, &found).unwrap();
        let (sn, cs) = rot.sin_cos();
        let map = |p: Point2<f64>| {
            Point2::new(k * (cs * p.x - sn * p.y) + dx, k * (sn * p.x + cs * p.y) + dy)
        };
        let moved: Vec<Pose> = task
            .poses()
            .iter()
            .map(|p| Pose { position: map(p.position), angle: p.angle + rot })
            .collect();
        let t2 = Task::new(&moved).unwrap();
        let f2 = t2.inverted_slider(map(found.swivel)).unwrap();
        let d2 = t2.dyad_from_center(map(inv.crank_pivot())).unwrap();
        let b2 = t2.inverted_slider_crank(&d2, &f2).unwrap();
        let flip = f2.direction.dot(&Vector2::new(cs * found.direction.x - sn * found.direction.y, sn * found.direction.x + cs * found.direction.y)) < 0.0;
        for i in 0..3 {
            let want = base.modes[i].map(|x| if flip { x.other() } else { x });
            prop_assert_eq!(b2.modes[i], want);
            let s = if flip { -1.0 } else { 1.0 };
            prop_assert!((b2.slot_positions[i] - s * k * base.slot_positions[i]).abs() < 1e-7 * k * 300.0);
        }
        prop_assert_eq!(b2.direction, base.direction);
        prop_assert_eq!(b2.feasible(), base.feasible());
        prop_assert!((b2.linkage.crank() - k * base.linkage.crank()).abs() < 1e-8 * k * 100.0);
        prop_assert!((b2.linkage.offset().abs() - k * base.linkage.offset().abs()).abs() < 1e-7 * k * 100.0);
        prop_assert!((b2.min_transmission - base.min_transmission).abs() < 1e-7);
        if base.is_branch_free() {
            prop_assert!((b2.stroke_used - k * base.stroke_used).abs() < 1e-6 * k * 300.0);
            prop_assert!((b2.swing_used - base.swing_used).abs() < 1e-7);
        }
    }
}
