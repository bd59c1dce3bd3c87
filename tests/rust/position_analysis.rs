//! Position analysis checked against published numbers, against two
//! independent formulations (the half-angle form of the seed text and a
//! textbook circle intersection), and against invariants.

use std::f64::consts::{PI, TAU};

mod common;

use burmester::{
    AssemblyError, AssemblyMode, Error, FourBar, Grashof, InputRange, InvalidInput, Point2, Vector2,
};
use proptest::prelude::*;

const CASES: u32 = 4000;

fn unit(a: f64) -> Vector2<f64> {
    Vector2::new(a.cos(), a.sin())
}

/// Loop-closure residual relative to the linkage's size.
fn residual(fb: &FourBar, t2: f64, t3: f64, t4: f64) -> f64 {
    let [l1, l2, l3, l4] = fb.lengths();
    let v = unit(t2) * l2 + unit(t3) * l3 - unit(fb.ground_angle()) * l1 - unit(t4) * l4;
    v.norm() / (l1 + l2 + l3 + l4)
}

/// Independent: the seed's half-angle (tan(theta/2)) solution, ground along
/// +x. Returns the two (theta3, theta4) pairs, same root sign for both.
fn half_angle(l1: f64, l2: f64, l3: f64, l4: f64, t2: f64) -> Option<[(f64, f64); 2]> {
    let (a_, b_, c_) = (
        (l4 * l4 - l2 * l2 - l3 * l3 - l1 * l1) / (2.0 * l2 * l3),
        l1 / l3,
        l1 / l2,
    );
    let a = a_ + b_ * t2.cos() + t2.cos() - c_;
    let b = -2.0 * t2.sin();
    let c = a_ + b_ * t2.cos() - t2.cos() + c_;
    let (e_, f_, g_) = (
        (l3 * l3 - l2 * l2 - l4 * l4 - l1 * l1) / (-2.0 * l2 * l4),
        l1 / l4,
        l1 / l2,
    );
    let e = e_ - f_ * t2.cos() + t2.cos() - g_;
    let f = -2.0 * t2.sin();
    let g = e_ - f_ * t2.cos() - t2.cos() + g_;
    let d3 = b * b - 4.0 * a * c;
    let d4 = f * f - 4.0 * e * g;
    if d3 < 0.0 || d4 < 0.0 || a.abs() < 1e-6 || e.abs() < 1e-6 {
        return None;
    }
    let r = |s: f64| {
        (
            2.0 * ((-b + s * d3.sqrt()) / (2.0 * a)).atan(),
            2.0 * ((-f + s * d4.sqrt()) / (2.0 * e)).atan(),
        )
    };
    Some([r(1.0), r(-1.0)])
}

/// Independent: textbook intersection of the circle about the crank tip
/// (radius L3) and the circle about the output pivot (radius L4).
fn circle_intersection(fb: &FourBar, t2: f64, mode: AssemblyMode) -> Option<(f64, f64)> {
    let [_, l2, l3, l4] = fb.lengths();
    let a = fb.input_pivot() + unit(t2) * l2;
    let o4 = fb.output_pivot();
    let d = o4 - a;
    let r = d.norm();
    let along = (l3 * l3 - l4 * l4 + r * r) / (2.0 * r);
    let h2 = l3 * l3 - along * along;
    if h2 < 0.0 {
        return None;
    }
    let dh = d / r;
    let n = Vector2::new(-dh.y, dh.x);
    for s in [1.0, -1.0] {
        let b = a + dh * along + n * (s * h2.sqrt());
        let t3 = (b - a).y.atan2((b - a).x);
        let t4 = (b - o4).y.atan2((b - o4).x);
        if (t4 - t3).sin() * mode.sign() > 0.0 {
            return Some((t3, t4));
        }
    }
    None
}

fn linkage() -> impl Strategy<Value = FourBar> {
    (
        0.1f64..10.0,
        0.1f64..10.0,
        0.1f64..10.0,
        0.1f64..10.0,
        -100.0f64..100.0,
        -100.0f64..100.0,
        -PI..PI,
    )
        .prop_filter_map("never closes", |(l1, l2, l3, l4, x, y, a)| {
            FourBar::placed(l1, l2, l3, l4, Point2::new(x, y), a).ok()
        })
}

/// `fb` at the input angle `t2_deg` degrees, in the open and the crossed
/// mode: `[theta3, theta4]` in degrees rounded to `1 / per_degree`, to the
/// printed digits.
fn assert_printed(fb: FourBar, t2_deg: f64, per_degree: f64, open: [f64; 2], crossed: [f64; 2]) {
    let t2 = t2_deg.to_radians();
    let round = |x: f64| (x.to_degrees() * per_degree).round() / per_degree;
    let o = fb.solve(t2, AssemblyMode::Open).unwrap();
    assert_eq!(round(o.theta3), open[0]);
    assert_eq!(round(o.theta4), open[1]);
    let c = fb.solve(t2, AssemblyMode::Crossed).unwrap();
    assert_eq!(round(c.theta3), crossed[0]);
    assert_eq!(round(c.theta4), crossed[1]);
}

#[test]
fn norton_example_4_1_to_printed_digits() {
    let fb = FourBar::new(100.0, 40.0, 120.0, 80.0).unwrap();
    assert_printed(fb, 40.0, 1e3, [20.298, 57.325], [-60.978, -98.005]);
}

#[test]
fn second_cross_check_to_printed_digits() {
    let fb = FourBar::new(4.0, 1.0, 3.0, 3.0).unwrap();
    assert_printed(
        fb,
        60.0,
        1e9,
        [39.165923859, 113.038303645],
        [-66.961696355, -140.834076141],
    );
}

#[test]
fn every_bad_input_gives_its_error() {
    let ok = FourBar::new(4.0, 1.0, 3.0, 3.0).unwrap();
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -0.0] {
        for k in 0..4 {
            let mut l = [4.0, 1.0, 3.0, 3.0];
            l[k] = bad;
            let e = FourBar::new(l[0], l[1], l[2], l[3]).unwrap_err();
            assert!(matches!(e, Error::InvalidInput(_)), "{l:?}: {e}");
        }
        if !bad.is_finite() {
            let e = FourBar::placed(4.0, 1.0, 3.0, 3.0, Point2::new(bad, 0.0), 0.0).unwrap_err();
            assert!(matches!(
                e,
                Error::InvalidInput(InvalidInput::NotFinite { .. })
            ));
            let e = FourBar::placed(4.0, 1.0, 3.0, 3.0, Point2::origin(), bad).unwrap_err();
            assert!(matches!(
                e,
                Error::InvalidInput(InvalidInput::NotFinite { .. })
            ));
            let e = ok.solve(bad, AssemblyMode::Open).unwrap_err();
            assert!(matches!(
                e,
                Error::InvalidInput(InvalidInput::NotFinite { .. })
            ));
            let e =
                FourBar::from_pivots(Point2::new(0.0, bad), Point2::new(1.0, 0.0), 1.0, 1.0, 1.0)
                    .unwrap_err();
            assert!(matches!(
                e,
                Error::InvalidInput(InvalidInput::NotFinite { .. })
            ));
        }
    }
    // Coincident pivots: zero ground length.
    let e = FourBar::from_pivots(Point2::new(1.0, 1.0), Point2::new(1.0, 1.0), 1.0, 1.0, 1.0)
        .unwrap_err();
    assert!(matches!(
        e,
        Error::InvalidInput(InvalidInput::NotPositive { .. })
    ));
    // Never closes.
    let e = FourBar::new(10.0, 1.0, 2.0, 3.0).unwrap_err();
    assert!(
        matches!(e, Error::Assembly(AssemblyError::NeverCloses { .. })),
        "{e}"
    );
    assert!(e.to_string().contains("shorten"), "{e}");
    // Out of reach at one angle: a crank-rocker never fails, a triple-rocker does.
    let tr = FourBar::new(3.0, 2.0, 1.5, 1.0).unwrap();
    assert_eq!(tr.grashof(), Grashof::TripleRocker);
    let e = tr.solve(PI, AssemblyMode::Open).unwrap_err();
    assert!(
        matches!(e, Error::Assembly(AssemblyError::OutOfReach { .. })),
        "{e}"
    );
    // Kite with the crank tip on the output pivot: indeterminate, never NaN.
    let kite = FourBar::new(1.0, 1.0, 2.0, 2.0).unwrap();
    let e = kite.solve(0.0, AssemblyMode::Open).unwrap_err();
    assert!(
        matches!(e, Error::Assembly(AssemblyError::Indeterminate { .. })),
        "{e}"
    );
    // Slices of different lengths.
    let (mut a, mut b, mut v) = (vec![0.0; 3], vec![0.0; 2], vec![false; 3]);
    let e = ok
        .solve_into(&[0.0, 1.0, 2.0], AssemblyMode::Open, &mut a, &mut b, &mut v)
        .unwrap_err();
    assert!(matches!(
        e,
        Error::InvalidInput(InvalidInput::LengthMismatch { .. })
    ));
    // Unknown mode names.
    assert!("sideways".parse::<AssemblyMode>().is_err());
    assert_eq!(
        "Crossed".parse::<AssemblyMode>().unwrap(),
        AssemblyMode::Crossed
    );
    // A coupler point that is not finite.
    let path: Vec<_> = ok
        .coupler_path(Vector2::new(f64::NAN, 0.0), [0.0, 1.0], AssemblyMode::Open)
        .collect();
    assert!(
        path.iter()
            .all(|p| matches!(p, Err(Error::InvalidInput(_))))
    );
}

#[test]
fn grashof_textbook_cases() {
    let cases = [
        ((4.0, 1.0, 3.0, 3.0), Grashof::CrankRocker),
        ((1.0, 4.0, 3.0, 3.0), Grashof::DoubleCrank),
        ((4.0, 3.0, 1.0, 3.0), Grashof::DoubleRocker),
        ((4.0, 3.0, 3.0, 1.0), Grashof::RockerCrank),
        ((3.0, 2.0, 1.5, 1.0), Grashof::TripleRocker),
        ((2.0, 1.0, 2.0, 1.0), Grashof::ChangePoint), // parallelogram
        ((1.0, 1.0, 2.0, 2.0), Grashof::ChangePoint), // kite
        ((0.3, 0.1, 0.3, 0.1), Grashof::ChangePoint), // decimal lengths
    ];
    for ((l1, l2, l3, l4), want) in cases {
        let fb = FourBar::new(l1, l2, l3, l4).unwrap();
        assert_eq!(fb.grashof(), want, "{l1} {l2} {l3} {l4}");
        assert_eq!(
            fb.grashof().as_str().parse::<String>().unwrap(),
            want.as_str()
        );
    }
    assert!(
        FourBar::new(2.0, 1.0, 2.0, 1.0)
            .unwrap()
            .input_turns_fully()
    );
    assert!(
        FourBar::new(4.0, 1.0, 3.0, 3.0)
            .unwrap()
            .input_turns_fully()
    );
    assert!(
        !FourBar::new(4.0, 3.0, 3.0, 1.0)
            .unwrap()
            .input_turns_fully()
    );
}

#[test]
fn parallelogram_and_kite_give_the_mode_asked_for() {
    for (l1, l2, l3, l4) in [
        (2.0, 1.0, 2.0, 1.0),
        (1.0, 1.0, 1.0, 1.0),
        (1.0, 1.0, 2.0, 2.0),
        (2.0, 2.0, 1.0, 1.0),
        (3.0, 1.0, 1.0, 3.0),
    ] {
        let fb = FourBar::new(l1, l2, l3, l4).unwrap();
        let range = fb.input_range();
        for k in 0..3600 {
            let t2 = (k as f64 + 0.5) * TAU / 3600.0 - PI;
            if !range.contains(t2) {
                assert!(fb.solve(t2, AssemblyMode::Open).is_err());
                continue;
            }
            for mode in AssemblyMode::BOTH {
                match fb.solve(t2, mode) {
                    Ok(c) => {
                        assert!(residual(&fb, t2, c.theta3, c.theta4) < 1e-13);
                        if !c.toggle {
                            assert!(
                                (c.theta4 - c.theta3).sin() * mode.sign() > 0.0,
                                "{l1} {l2} {l3} {l4} at {t2}: asked {mode}, got {c:?}"
                            );
                        }
                    }
                    Err(e) => panic!("{l1} {l2} {l3} {l4} at {t2}: {e}"),
                }
            }
        }
    }
}

#[test]
fn toggle_positions_are_reported_at_the_dead_positions() {
    // Triple-rocker: the input rocks between two dead positions.
    let fb = FourBar::new(3.0, 2.0, 1.5, 1.0).unwrap();
    let InputRange::Arc(arc) = fb.input_range() else {
        panic!("{:?}", fb.input_range());
    };
    for t in [arc.start, arc.end] {
        let o = fb.solve(t, AssemblyMode::Open).unwrap();
        let c = fb.solve(t, AssemblyMode::Crossed).unwrap();
        assert!(o.toggle && c.toggle, "{o:?} {c:?}");
        assert!((o.theta3 - c.theta3).abs() < 1e-6 && (o.theta4 - c.theta4).abs() < 1e-6);
        assert!(o.transmission_angle() < 1e-6);
    }
    // Just inside: closes, not a toggle; just outside: out of reach.
    let inside = fb.solve(arc.start + 1e-6, AssemblyMode::Open).unwrap();
    assert!(!inside.toggle);
    assert!(fb.solve(arc.start - 1e-6, AssemblyMode::Open).is_err());
    assert_eq!(fb.input_range().dead_positions(), vec![arc.start, arc.end]);
}

#[test]
fn grashof_double_rocker_has_two_arcs() {
    let fb = FourBar::new(4.0, 3.0, 1.0, 3.0).unwrap();
    let r = fb.input_range();
    let InputRange::TwoArcs(a, b) = r else {
        panic!("{r:?}");
    };
    assert!((a.start + b.end).abs() < 1e-12 && (a.end + b.start).abs() < 1e-12);
    assert!(fb.solve(a.mid(), AssemblyMode::Open).is_ok());
    assert!(fb.solve(b.mid(), AssemblyMode::Open).is_ok());
    assert!(fb.solve(0.0, AssemblyMode::Open).is_err());
    assert!(fb.solve(PI, AssemblyMode::Open).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: CASES, failure_persistence: None, rng_seed: common::seed(), ..ProptestConfig::default() })]

    #[test]
    fn both_modes_close_and_carry_their_sign(fb in linkage(), t2 in -10.0f64..10.0) {
        let o = fb.solve(t2, AssemblyMode::Open);
        let c = fb.solve(t2, AssemblyMode::Crossed);
        prop_assert_eq!(o.is_ok(), c.is_ok());
        if let (Ok(o), Ok(c)) = (o, c) {
            prop_assert!(residual(&fb, t2, o.theta3, o.theta4) < 1e-13);
            prop_assert!(residual(&fb, t2, c.theta3, c.theta4) < 1e-13);
            prop_assert_eq!(o.toggle, c.toggle);
            if !o.toggle {
                prop_assert!(o.coupler_rocker_angle() > 0.0);
                prop_assert!(c.coupler_rocker_angle() < 0.0);
            }
            for x in [o.theta3, o.theta4, c.theta3, c.theta4] {
                prop_assert!(x.is_finite() && x > -PI - 1e-15 && x <= PI);
            }
        }
    }

    #[test]
    fn closes_exactly_where_the_circles_meet(fb in linkage(), t2 in -PI..PI) {
        let [_, l2, l3, l4] = fb.lengths();
        let r = (fb.output_pivot() - (fb.input_pivot() + unit(t2) * l2)).norm();
        let size = fb.lengths().iter().sum::<f64>();
        let gap = (r - (l3 + l4)).max((l3 - l4).abs() - r);
        let res = fb.solve(t2, AssemblyMode::Open);
        if gap > 1e-9 * size {
            let is_out_of_reach =
                matches!(res, Err(Error::Assembly(AssemblyError::OutOfReach { .. })));
            prop_assert!(is_out_of_reach);
        } else if gap < -1e-9 * size {
            prop_assert!(res.is_ok());
            prop_assert!(fb.input_range().contains(t2));
        }
    }

    #[test]
    fn agrees_with_circle_intersection(fb in linkage(), t2 in -PI..PI) {
        for mode in AssemblyMode::BOTH {
            if let (Ok(c), Some((t3, t4))) = (fb.solve(t2, mode), circle_intersection(&fb, t2, mode)) {
                if c.transmission_angle() > 1e-3 {
                    prop_assert!(common::wrap(c.theta3 - t3).abs() < 1e-9, "{:?} vs {} {}", c, t3, t4);
                    prop_assert!(common::wrap(c.theta4 - t4).abs() < 1e-9, "{:?} vs {} {}", c, t3, t4);
                }
            }
        }
    }

    #[test]
    fn agrees_with_the_seed_half_angle_form(
        l1 in 0.1f64..10.0, l2 in 0.1f64..10.0, l3 in 0.1f64..10.0, l4 in 0.1f64..10.0,
        t2 in -PI..PI,
    ) {
        let Ok(fb) = FourBar::new(l1, l2, l3, l4) else { return Ok(()); };
        let (Ok(o), Ok(c)) = (fb.solve(t2, AssemblyMode::Open), fb.solve(t2, AssemblyMode::Crossed))
        else { return Ok(()); };
        if o.transmission_angle() < 1e-3 { return Ok(()); }
        if let Some(pairs) = half_angle(l1, l2, l3, l4, t2) {
            let close = |p: (f64, f64), q: &burmester::Configuration| {
                common::wrap(p.0 - q.theta3).abs() < 1e-7 && common::wrap(p.1 - q.theta4).abs() < 1e-7
            };
            // The same root sign gives one mode, the other sign the other.
            prop_assert!(
                (close(pairs[0], &o) && close(pairs[1], &c)) || (close(pairs[0], &c) && close(pairs[1], &o)),
                "{:?} {:?} {:?}", pairs, o, c
            );
        }
    }

    #[test]
    fn mirroring_swaps_the_modes(fb in linkage(), t2 in -PI..PI) {
        // Reflection across the ground line: theta -> 2 theta1 - theta.
        let t1 = fb.ground_angle();
        for mode in AssemblyMode::BOTH {
            if let Ok(c) = fb.solve(t2, mode) {
                let m = fb.solve(2.0 * t1 - t2, mode.other()).unwrap();
                if !c.toggle {
                    prop_assert!(common::wrap(m.theta3 - (2.0 * t1 - c.theta3)).abs() < 1e-9);
                    prop_assert!(common::wrap(m.theta4 - (2.0 * t1 - c.theta4)).abs() < 1e-9);
                }
            }
        }
    }

    #[test]
    fn scaling_and_moving_keep_the_angles(fb in linkage(), t2 in -PI..PI, k in 1e-6f64..1e6) {
        let [l1, l2, l3, l4] = fb.lengths();
        let scaled = FourBar::placed(l1 * k, l2 * k, l3 * k, l4 * k, Point2::new(1e3, -7.0), fb.ground_angle()).unwrap();
        for mode in AssemblyMode::BOTH {
            match (fb.solve(t2, mode), scaled.solve(t2, mode)) {
                (Ok(a), Ok(b)) => {
                    if a.transmission_angle() > 1e-4 {
                        prop_assert!(common::wrap(a.theta3 - b.theta3).abs() < 1e-9);
                        prop_assert!(common::wrap(a.theta4 - b.theta4).abs() < 1e-9);
                    }
                }
                (Err(_), Err(_)) => {}
                (a, b) => {
                    // Only within rounding of a dead position.
                    let t = a.as_ref().map(|c| c.transmission_angle()).or(b.as_ref().map(|c| c.transmission_angle())).unwrap();
                    prop_assert!(t < 1e-6, "{:?} {:?}", a, b);
                }
            }
        }
    }

    #[test]
    fn transmission_angle_matches_the_law_of_cosines(fb in linkage(), t2 in -PI..PI) {
        if let Ok(c) = fb.solve(t2, AssemblyMode::Open) {
            let j = fb.joints(&c);
            let [_, _, l3, l4] = fb.lengths();
            let r2 = (j.output_pivot - j.crank_joint).norm_squared();
            let cos_mu = ((l3 * l3 + l4 * l4 - r2) / (2.0 * l3 * l4)).clamp(-1.0, 1.0);
            let mu = cos_mu.acos();
            let want = mu.min(PI - mu);
            if c.transmission_angle() > 1e-4 {
                prop_assert!((c.transmission_angle() - want).abs() < 1e-7);
            }
            // Joints are where the lengths say.
            prop_assert!(((j.crank_joint - j.input_pivot).norm() - fb.crank()).abs() < 1e-12 * fb.crank().max(1.0) * 10.0);
            prop_assert!(((j.rocker_joint - j.crank_joint).norm() - l3).abs() < 1e-12 * 100.0);
            prop_assert!(((j.rocker_joint - j.output_pivot).norm() - l4).abs() < 1e-12 * 100.0);
        }
    }

    #[test]
    fn coupler_point_rides_on_the_coupler(fb in linkage(), u in -5.0f64..5.0, v in -5.0f64..5.0) {
        let local = Vector2::new(u, v);
        let angles: Vec<f64> = (0..64).map(|k| k as f64 * TAU / 64.0).collect();
        for (t2, p) in angles.iter().zip(fb.coupler_path(local, angles.iter().copied(), AssemblyMode::Open)) {
            if let Ok(p) = p {
                let j = fb.joints_at(*t2, AssemblyMode::Open).unwrap();
                prop_assert!(((p - j.crank_joint).norm() - local.norm()).abs() < 1e-9);
                let to_b = Vector2::new(fb.coupler() - u, -v).norm();
                prop_assert!(((p - j.rocker_joint).norm() - to_b).abs() < 1e-9);
            }
        }
    }

    #[test]
    fn solve_into_matches_solve(fb in linkage(), ts in prop::collection::vec(-10.0f64..10.0, 0..64)) {
        let n = ts.len();
        let (mut t3, mut t4, mut ok) = (vec![0.0; n], vec![0.0; n], vec![false; n]);
        let count = fb.solve_into(&ts, AssemblyMode::Crossed, &mut t3, &mut t4, &mut ok).unwrap();
        prop_assert_eq!(count, ok.iter().filter(|&&b| b).count());
        for (i, r) in fb.solve_iter(ts.iter().copied(), AssemblyMode::Crossed).enumerate() {
            match r {
                Ok(c) => { prop_assert!(ok[i]); prop_assert_eq!(c.theta3, t3[i]); prop_assert_eq!(c.theta4, t4[i]); }
                Err(_) => { prop_assert!(!ok[i]); prop_assert!(t3[i].is_nan() && t4[i].is_nan()); }
            }
        }
    }

    #[test]
    fn grashof_class_matches_the_input_range(fb in linkage()) {
        let g = fb.grashof();
        let [l1, l2, l3, l4] = fb.lengths();
        let mut l = [l1, l2, l3, l4];
        l.sort_by(f64::total_cmp);
        let margin = (l[0] + l[3]) - (l[1] + l[2]);
        if margin.abs() < 1e-9 { return Ok(()); }
        // Textbook inequality.
        prop_assert_eq!(g.is_grashof(), margin < 0.0);
        let full = fb.input_turns_fully();
        match g {
            Grashof::CrankRocker | Grashof::DoubleCrank => prop_assert!(full),
            // The input rocks; a rocker-crank or a Grashof double-rocker may
            // have two circuits, mirror images across the ground line.
            Grashof::RockerCrank | Grashof::DoubleRocker => prop_assert!(!full),
            Grashof::TripleRocker => prop_assert!(matches!(fb.input_range(), InputRange::Arc(_))),
            Grashof::ChangePoint => {}
        }
        // Dense stepping: the loop closes exactly inside the range.
        let range = fb.input_range();
        for k in 0..720 {
            let t = -PI + (k as f64 + 0.5) * TAU / 720.0;
            let near_dead = range.dead_positions().iter().any(|&d| common::wrap(t - d).abs() < 1e-7);
            if !near_dead {
                prop_assert_eq!(fb.solve(t, AssemblyMode::Open).is_ok(), range.contains(t), "at {}", t);
            }
        }
    }
}

/// The batch kernel of `solve_into` (structure of arrays, rayon above its
/// threshold) gives exactly the bits of `solve`, and NaN rows where `solve`
/// fails: 10^5 angles on each of many linkages, including angles at and
/// next to the toggle positions (where the closure is most sensitive to
/// rounding), angles beyond `MAX_ANGLE`, NaN and infinities.
#[test]
fn solve_into_batch_is_bitwise_solve() {
    // xorshift64*: deterministic, no dependency.
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut next = move || {
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        (state.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    };
    let n = 100_000;
    let mut linkages = vec![
        FourBar::new(3.0, 2.0, 1.5, 1.0).unwrap(),
        FourBar::new(4.0, 1.0, 3.0, 3.0).unwrap(),
        FourBar::new(2.0, 1.0, 2.0, 1.0).unwrap(),
        FourBar::new(1.0, 1.0, 2.0, 2.0).unwrap(),
    ];
    while linkages.len() < 24 {
        let l = [0; 4].map(|_| 0.1 + 9.9 * next());
        let (x, y, a) = (
            200.0 * next() - 100.0,
            200.0 * next() - 100.0,
            TAU * next() - PI,
        );
        if let Ok(fb) = FourBar::placed(l[0], l[1], l[2], l[3], Point2::new(x, y), a) {
            linkages.push(fb);
        }
    }
    for fb in &linkages {
        let mut ts: Vec<f64> = (0..n).map(|_| 20.0 * next() - 10.0).collect();
        // Near the toggles: the arc ends, nudged by a few ulps to 1e-6.
        if let InputRange::Arc(arc) = fb.input_range() {
            for (k, t) in ts.iter_mut().enumerate().take(2000) {
                let end = if k % 2 == 0 { arc.start } else { arc.end };
                let nudge = [0.0, 1e-16, -1e-16, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6][k / 2 % 8];
                *t = end * (1.0 + nudge) + nudge;
            }
        }
        ts[2001] = f64::NAN;
        ts[2002] = f64::INFINITY;
        ts[2003] = -f64::INFINITY;
        ts[2004] = FourBar::MAX_ANGLE;
        ts[2005] = FourBar::MAX_ANGLE * (1.0 + f64::EPSILON);
        ts[2006] = -1e12;
        ts[2007] = 1e6 + 0.25;
        for mode in [AssemblyMode::Open, AssemblyMode::Crossed] {
            // The whole slice (parallel path) and an odd-length prefix
            // (serial path with a tail shorter than the lane count).
            for len in [n, 4099] {
                let (mut t3, mut t4, mut ok) = (vec![0.0; len], vec![0.0; len], vec![false; len]);
                let count = fb
                    .solve_into(&ts[..len], mode, &mut t3, &mut t4, &mut ok)
                    .unwrap();
                assert_eq!(count, ok.iter().filter(|&&b| b).count());
                for (i, &t) in ts[..len].iter().enumerate() {
                    match fb.solve(t, mode) {
                        Ok(c) => {
                            assert!(ok[i], "{fb:?} {t}");
                            assert_eq!(c.theta3.to_bits(), t3[i].to_bits(), "{fb:?} {t}");
                            assert_eq!(c.theta4.to_bits(), t4[i].to_bits(), "{fb:?} {t}");
                        }
                        Err(_) => {
                            assert!(!ok[i], "{fb:?} {t}");
                            assert!(t3[i].is_nan() && t4[i].is_nan());
                        }
                    }
                }
            }
        }
    }
}
