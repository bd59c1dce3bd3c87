//! The one toggle criterion (`tolerance::heron_tolerance`, issue 28) and
//! the modes of a built linkage at its design poses (issue 24, item 5).
//!
//! The exact checks of the band (against mpmath at 300 bits, link ratios
//! from 1 to 1e9) are in `tests/python/test_toggle.py`; here are the
//! reported cases and the property that ties the figures to the position
//! analysis: every pose a linkage reports a mode at assembles in that mode.

use burmester::{AssemblyMode, Branch, Method, Point2, Task, tolerance};
mod common;

use common::config;
use proptest::prelude::*;

fn p(x: f64, y: f64) -> Point2<f64> {
    Point2::new(x, y)
}

/// Issue 28: 1.8e-7 task sizes from the pole circle, a linkage whose crank
/// and coupler are 4.6e7 times its rocker. The earlier band (growing like
/// `L3 / L4`) called its transmission angles of 49 to 57 degrees toggles,
/// so the modes were `[None, None, None]` and `simulate` said boundary.
#[test]
fn issue_28_long_links_at_the_pole_circle_have_their_modes() {
    let task = Task::from_xya(&[
        [-1.8622594211157373, -2.700165078206026, -2.5318845477482217],
        [-1.242879680464385, -1.390640844394518, -3.035693045691944],
        [2.538761869305141, -1.4705020035742344, -2.8394644775952194],
    ])
    .unwrap();
    let f = task
        .filemon(p(0.9270498928708832, -2.456011695005893))
        .unwrap();
    let a0 = p(79.35079574269099, 74.89249517819286);
    let sfb = f.four_bar(a0).unwrap();
    let [l1, l2, l3, l4] = sfb.fourbar.lengths();
    assert!(
        l2 / l4 > 4e7 && l3 / l4 > 4e7,
        "{:?}",
        sfb.fourbar.lengths()
    );
    assert_eq!(sfb.modes().as_slice(), &[Some(AssemblyMode::Crossed); 3]);
    assert!(sfb.is_branch_free());
    for m in [Method::Conic, Method::Direct, Method::Simulate] {
        assert_eq!(f.classify(a0, m).unwrap(), Branch::Free, "{m:?}");
    }
    for (k, &t) in sfb.input_angles.iter().enumerate() {
        let c = sfb.fourbar.solve(t, AssemblyMode::Crossed).unwrap();
        assert!(!c.toggle, "pose {}", k + 1);
        let mu = c.transmission_angle();
        assert!(mu > 49f64.to_radians(), "{}", mu.to_degrees());
        // The documented band at this pose is far below sin(mu).
        let j = sfb.fourbar.joints(&c);
        let r = (j.output_pivot - j.crank_joint).norm();
        let band = tolerance::toggle_band(l3, l4, r, l1 + l2);
        assert!(band < 1e-3 && band > 1e-5, "{band}");
        let pose = sfb.pose_at(t, AssemblyMode::Crossed).unwrap();
        let want = task.poses()[k];
        assert!((pose.position - want.position).norm() < 1e-6 * task.span());
    }
}

/// The poses of issue 24, item 5.
fn item_5_task() -> Task {
    Task::from_xya(&[
        [
            1.0836704496288299,
            0.9215060063700449,
            -0.012354348740407861,
        ],
        [
            -0.4024354514586044,
            -3.2758056629101837,
            -0.008921185907585283,
        ],
        [-3.857809083095093, -4.861235596788566, 2.220945338924377],
    ])
    .unwrap()
}

/// Every pose with a mode assembles in it and reaches the pose (to `1e-9`
/// task sizes, `1e-6` near a toggle, where the loop is as ill-conditioned
/// as a square root, as in `tests/python/test_robustness.py`); a pose
/// without one is a toggle of the position analysis or out of its reach by
/// rounding (`1e-13` of the reach).
fn assert_modes_assemble(task: &Task, sfb: &burmester::SynthesizedFourBar) {
    for (k, (&t, mode)) in sfb.input_angles.iter().zip(sfb.modes().iter()).enumerate() {
        match mode {
            Some(m) => {
                let c = sfb.fourbar.solve(t, *m).unwrap();
                let pose = sfb.pose_at(t, *m).unwrap();
                let want = task.poses()[k];
                let tol = if c.transmission_angle() < 1e-3 {
                    1e-6
                } else {
                    1e-9
                };
                assert!(
                    (pose.position - want.position).norm() < tol * task.scale(),
                    "pose {}: {c:?}",
                    k + 1
                );
            }
            None => {
                for m in AssemblyMode::BOTH {
                    match sfb.fourbar.solve(t, m) {
                        Ok(c) => assert!(c.toggle, "pose {}: {c:?}", k + 1),
                        Err(burmester::Error::Assembly(burmester::AssemblyError::OutOfReach {
                            distance,
                            max_reach,
                            ..
                        })) => assert!(distance - max_reach < 1e-13 * max_reach),
                        Err(e) => panic!("{e}"),
                    }
                }
            }
        }
    }
}

/// Issue 24, item 5: a linkage reported feasible with modes open, open,
/// open whose third design pose did not assemble (`configuration` raised
/// `AssemblyError`, a distance of 8.860675295579062 against a reach of
/// 8.860675295578911): the figures took the mode from the pose's own
/// triangle with one band, the position analysis the loop at the input
/// angle with another, and the two loops differed by the synthesis'
/// rounding (the rocker 2.1e-13 longer at pose 3 than at pose 1: the task
/// has a rotation of 0.0034 rad and its maps ran through a pole 300 spans
/// away). Here with those very dyads (passed as they were): the figures
/// now take the position analysis' loop at each pose with its band, so
/// pose 3, out of reach by 1.5e-13, has no mode, and the linkage is
/// neither branch-free nor feasible.
#[test]
fn issue_24_item_5_every_reported_mode_assembles() {
    let task = item_5_task();
    let (a0, c0) = (
        p(-6.610038700798108, 5.074014566959427),
        p(-3.6415281503788215, 3.0351314430766507),
    );
    let driving = burmester::Dyad::new(a0, p(3.34168308519952, 3.881799329399769));
    let driven = burmester::Dyad::new(c0, p(3.9066207505716193, 2.7050713121968784));
    let sfb = task.four_bar(&driving, &driven).unwrap();
    assert_eq!(
        sfb.modes().as_slice(),
        &[Some(AssemblyMode::Open), Some(AssemblyMode::Open), None]
    );
    assert!(!sfb.is_branch_free() && !sfb.figures.feasible());
    assert_modes_assemble(&task, &sfb);
    // The task's own dyads now come from the linear form (its pole P12 is
    // 300 spans away: tolerance::POLE_DISTANCE), accurate to 1e-15: pose 3
    // is then 8e-14 inside the reach, a transmission angle of 3.9e-7 rad,
    // beyond the band: feasible, and it assembles.
    let f = task.filemon(c0).unwrap();
    let sfb = f.four_bar(a0).unwrap();
    assert_eq!(sfb.modes().as_slice(), &[Some(AssemblyMode::Open); 3]);
    assert!(sfb.figures.feasible());
    assert_modes_assemble(&task, &sfb);
    let c = sfb
        .fourbar
        .solve(sfb.input_angles[2], AssemblyMode::Open)
        .unwrap();
    let j = sfb.fourbar.joints(&c);
    let [l1, l2, l3, l4] = sfb.fourbar.lengths();
    let band = tolerance::toggle_band(l3, l4, (j.output_pivot - j.crank_joint).norm(), l1 + l2);
    let mu = c.transmission_angle();
    assert!(mu > band && mu < 1e-6 && !c.toggle, "{mu} {band}");
    for m in [Method::Conic, Method::Direct, Method::Simulate] {
        assert_eq!(f.classify(a0, m).unwrap(), Branch::Free, "{m:?}");
    }
}

/// Whether each pose's reported mode is one the position analysis
/// assembles clear of a toggle at the pose's input angle, and no mode
/// exactly where it assembles none: `None` when they agree, else the
/// first pose (1-based) where they do not.
fn modes_disagree_with_solve(sfb: &burmester::SynthesizedFourBar) -> Option<usize> {
    for (k, (&t, mode)) in sfb.input_angles.iter().zip(sfb.modes().iter()).enumerate() {
        let clear: Vec<AssemblyMode> = AssemblyMode::BOTH
            .into_iter()
            .filter(|&m| sfb.fourbar.solve(t, m).is_ok_and(|c| !c.toggle))
            .collect();
        let agree = match mode {
            Some(m) => clear.contains(m),
            None => clear.is_empty(),
        };
        if !agree {
            return Some(k + 1);
        }
    }
    None
}

/// The open case of fuzz/README.md ("a pose the figures call a toggle
/// that the position analysis assembles", issue 24 item 5): near a
/// transformed Filemon line the figures' toggle test (the pose's loop, and
/// the position analysis' loop rebuilt from the crank's direction) and
/// `FourBar::solve` (the loop from the input angle) fell on different
/// sides of the band. Found again by this search: of 200,000 draws, 151
/// poses disagreed, both ways (104 poses called toggles that `solve`
/// assembles clear in both modes; 47 given a mode where `solve` reports a
/// toggle). Now the figures ask the position analysis itself near the
/// band. Two of the found cases, then the search (fixed seed) over 20,000
/// draws: driving centers 1e-16 to 1e-4 task sizes off a transformed line.
#[test]
fn a_pose_has_a_mode_exactly_when_the_position_analysis_assembles_it_clear() {
    let found = [
        (
            [
                [
                    -2.124299675653311,
                    -1.4806734021171044,
                    -0.13457607385047143,
                ],
                [-4.1330316779369225, 2.952495527595916, 0.5004374031182246],
                [-4.486500307204791, 1.4902786966836619, 1.447137396319802],
            ],
            p(-4.186348644237693, -0.43075869202920813),
            p(-5.1844578613853685, -0.2084744759912314),
        ),
        (
            [
                [0.34538160821415964, 2.932841832262687, 1.9612682460243298],
                [4.711335410509559, -1.5356452398033813, 0.2862779501625494],
                [
                    2.7505623740869156,
                    -0.47938997286428986,
                    -1.4818537261822629,
                ],
            ],
            p(-3.2372746182730356, -3.88093653837288),
            p(32.73425703703483, -4.396946409619198),
        ),
    ];
    for (poses, c0, a0) in found {
        let task = Task::from_xya(&poses).unwrap();
        let sfb = task.filemon(c0).unwrap().four_bar(a0).unwrap();
        assert_eq!(modes_disagree_with_solve(&sfb), None, "{:?}", sfb.modes());
        assert_modes_assemble(&task, &sfb);
    }
    let mut state: u64 = 0x1234_5678;
    let mut rnd = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 11) as f64) / ((1u64 << 53) as f64)
    };
    let mut built = 0;
    for _ in 0..20_000 {
        let poses: Vec<[f64; 3]> = (0..3)
            .map(|_| {
                [
                    rnd() * 10.0 - 5.0,
                    rnd() * 10.0 - 5.0,
                    (rnd() - 0.5) * core::f64::consts::TAU,
                ]
            })
            .collect();
        let Ok(task) = Task::from_xya(&poses) else {
            continue;
        };
        let Ok(f) = task.filemon(p(rnd() * 12.0 - 6.0, rnd() * 12.0 - 6.0)) else {
            continue;
        };
        let Ok(conic) = f.line_conic(1 + (rnd() * 3.0) as usize) else {
            continue;
        };
        let angle = rnd() * core::f64::consts::TAU;
        let q = p(rnd() * 20.0 - 10.0, rnd() * 20.0 - 10.0) * task.scale();
        let dir = burmester::Vector2::new(angle.cos(), angle.sin());
        let line = burmester::Line {
            point: q,
            direction: dir,
        };
        let Some(&on) = conic.intersect_line(&line).first() else {
            continue;
        };
        let n = conic.gradient(on);
        if n.norm().is_nan() || n.norm() == 0.0 {
            continue;
        }
        let side = if rnd() < 0.5 { -1.0 } else { 1.0 };
        let off = 10f64.powf(-16.0 + rnd() * 12.0);
        let a0 = on + n.normalize() * (side * off * task.scale());
        let Ok(sfb) = f.four_bar(a0) else { continue };
        assert_eq!(
            modes_disagree_with_solve(&sfb),
            None,
            "{poses:?} {a0:?} {:?}",
            sfb.modes()
        );
        built += 1;
    }
    assert!(built > 5_000, "{built}");
}

/// `of_loop` and `of_loop_within` at the band: the issue's angle (49
/// degrees on links 4.6e7 apart) has a mode; a loop within the band of its
/// toggle has none; both modes by sign.
#[test]
fn of_loop_follows_the_band() {
    let (l3, l4) = (1.0, 1.0 / 4.6e7);
    let mu = 49f64.to_radians();
    let u = burmester::Vector2::new(l3, 0.0);
    for s in [1.0, -1.0] {
        let w = burmester::Vector2::new(-l4 * mu.cos(), s * l4 * mu.sin());
        let want = if s > 0.0 {
            AssemblyMode::Open
        } else {
            AssemblyMode::Crossed
        };
        assert_eq!(AssemblyMode::of_loop(u, w), Some(want));
        assert_eq!(AssemblyMode::of_loop_within(u, w, 2.0), Some(want));
        // At an angle of a tenth of the band: a toggle.
        let r = (u - w).norm();
        let band = tolerance::toggle_band(l3, l4, r, 2.0);
        let a = 0.1 * band;
        let w = burmester::Vector2::new(-l4 * a.cos(), s * l4 * a.sin());
        assert_eq!(AssemblyMode::of_loop_within(u, w, 2.0), None, "{band}");
    }
    // Zero, NaN and huge vectors.
    let z = burmester::Vector2::zeros();
    assert_eq!(AssemblyMode::of_loop(z, z), None);
    assert_eq!(
        AssemblyMode::of_loop(burmester::Vector2::new(f64::NAN, 1.0), u),
        None
    );
    let big = burmester::Vector2::new(1e300, 0.0);
    assert_eq!(
        AssemblyMode::of_loop(big, burmester::Vector2::new(0.0, 1e300)),
        Some(AssemblyMode::Open)
    );
}

/// A driving center near the pole circle of a random task: the circle
/// point runs far away, and the crank and coupler grow (link ratios up
/// to about 1e9 at the distances drawn).
fn near_pole_circle(task: &Task, angle: f64, log_dist: f64, side: f64) -> Option<Point2<f64>> {
    let c = task.cremona().ok()?.pole_circle();
    let burmester::CircleOrLine::Circle { center, radius } = c else {
        return None;
    };
    let d = side * 10f64.powf(log_dist) * task.scale();
    Some(center + burmester::Vector2::new(angle.cos(), angle.sin()) * (radius + d))
}

proptest! {
    // A fixed seed: random draws find, about once in ten runs of 400 cases,
    // a driving center 1e-8 task sizes off a transformed Filemon line where
    // the figures call the pose a toggle (no mode) and the position
    // analysis, at a transmission angle of 1.3e-7 rad, does not (an open
    // case of issue 24, recorded in fuzz/README.md with its input; the
    // same on the code before the issue 25 restructuring). CI must not
    // depend on the draw; make it `RngSeed::Random` to search further.
    #![proptest_config(ProptestConfig {
        rng_seed: proptest::test_runner::RngSeed::Fixed(0x7066_0024),
        ..config(400)
    })]

    /// Issue 24, item 5 (and the target that would have found it): every
    /// pose at which a synthesized linkage reports a mode assembles in that
    /// mode (`solve` closes the loop at the pose's input angle), the
    /// configuration there is the pose's (its rocker tip is the driven
    /// moving pivot at the pose, nearer than the other mode's), and a pose
    /// the figures call a toggle is one of the position analysis. Tasks
    /// with driving centers from 1e-9 to 1 task sizes off the pole circle,
    /// where the links grow long; from 1e-16 to 1e-4 task sizes off a
    /// transformed Filemon line, where a pose is at a dead position (item
    /// 5's case); and anywhere within 10 task sizes.
    #[test]
    fn every_reported_mode_assembles(
        task in common::task(),
        c0 in (-6.0f64..6.0, -6.0f64..6.0),
        angle in 0.0f64..core::f64::consts::TAU,
        log_dist in -9.0f64..0.0,
        side in prop::sample::select(vec![-1.0, 1.0]),
        free in (-10.0f64..10.0, -10.0f64..10.0),
        kind in 0u8..3,
        pose in 1usize..=3,
        log_off in -16.0f64..-4.0,
    ) {
        let Ok(f) = task.filemon(p(c0.0, c0.1)) else { return Ok(()) };
        let a0 = match kind {
            0 => match near_pole_circle(&task, angle, log_dist, side) {
                Some(a0) => a0,
                None => return Ok(()),
            },
            1 => {
                // A line through `free` meets pose `pose`'s transformed
                // line: there pose `pose` is at a toggle.
                let conic = f.line_conic(pose).unwrap();
                let q = p(free.0, free.1) * task.scale();
                let dir = burmester::Vector2::new(angle.cos(), angle.sin());
                let Some(&on) = conic.intersect_line(&burmester::Line { point: q, direction: dir }).first() else {
                    return Ok(());
                };
                let n = conic.gradient(on);
                let Some(n) = (n.norm() > 0.0).then(|| n.normalize()) else { return Ok(()) };
                on + n * (side * 10f64.powf(log_off) * task.scale())
            }
            _ => p(free.0, free.1) * task.scale(),
        };
        let Ok(sfb) = f.four_bar(a0) else { return Ok(()) };
        let c = task.moving_pivots(&sfb.driven);
        for (k, (&t, mode)) in sfb.input_angles.iter().zip(sfb.modes().iter().copied()).enumerate() {
            match mode {
                Some(m) => {
                    let got = sfb.fourbar.joints_at(t, m);
                    prop_assert!(got.is_ok(), "pose {}: {:?}", k + 1, got);
                    let other = sfb.fourbar.joints_at(t, m.other()).unwrap();
                    let (near_m, near_o) = (
                        (got.unwrap().rocker_joint - c[k]).norm(),
                        (other.rocker_joint - c[k]).norm(),
                    );
                    prop_assert!(near_m <= near_o, "pose {}: {near_m} vs {near_o}", k + 1);
                }
                None => {
                    for m in AssemblyMode::BOTH {
                        if let Ok(c) = sfb.fourbar.solve(t, m) {
                            prop_assert!(c.toggle, "pose {}: {c:?}", k + 1);
                        }
                    }
                }
            }
        }
        // A branch-free linkage assembles at every pose; `simulate` agrees
        // with the figures on a toggle at a pose.
        if sfb.is_branch_free() {
            for (&t, m) in sfb.input_angles.iter().zip(sfb.modes().iter().copied()) {
                prop_assert!(sfb.fourbar.solve(t, m.unwrap()).is_ok());
            }
        } else if sfb.modes().iter().any(Option::is_none) {
            prop_assert_eq!(f.classify(a0, Method::Simulate).unwrap(), Branch::Boundary);
        }
    }
}
