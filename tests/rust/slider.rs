//! The slider-crank: position analysis against the textbook closed form
//! (Norton, *Design of Machinery*, §4.6, eqs. 4.16–4.17, both circuits),
//! against a dense independent solver (bisection on the guide, no square
//! root formula), against the four-bar whose rocker pivot is far along the
//! guide's normal (the modes' names and the transmission angle); and the
//! slider-crank of a task made from known slider-cranks, its branch and
//! order verdicts against driving the built mechanism densely by crank
//! angle.

use std::f64::consts::{PI, TAU};

use burmester::{
    AssemblyError, AssemblyMode, Direction, Dyad, Error, FourBar, InvalidInput, Point2, Pose,
    SliderCrank, SliderDyad, SynthesizedSliderCrank, Task, Vector2,
};
use proptest::prelude::*;

fn unit(a: f64) -> Vector2<f64> {
    Vector2::new(a.cos(), a.sin())
}

fn wrap(a: f64) -> f64 {
    let t = a.rem_euclid(TAU);
    if t > PI { t - TAU } else { t }
}

/// Norton's offset slider-crank (§4.6, eqs. 4.16a/b and 4.17): crank `a`,
/// coupler `b`, the guide at height `c` above the crank pivot along +x.
/// Returns `(theta3, d)` of his solutions 1 (eq. 4.16a) and 2 (4.16b),
/// his `theta3` the direction from the slider pin to the crank pin.
fn norton(a: f64, b: f64, c: f64, t2: f64) -> Option<[(f64, f64); 2]> {
    let q = (a * t2.sin() - c) / b;
    if q.abs() > 1.0 {
        return None;
    }
    let t31 = q.asin();
    let t32 = (-q).asin() + PI;
    Some([t31, t32].map(|t3| (t3, a * t2.cos() - b * t3.cos())))
}

#[test]
fn norton_closed_form_both_modes() {
    // Norton's example numbers (a = 40, b = 120, c = -20) and a spread of others.
    let cases = [
        (40.0, 120.0, -20.0),
        (40.0, 120.0, 20.0),
        (1.0, 3.0, 0.0),
        (2.0, 2.5, 0.4),
        (5.0, 3.0, 1.0),
        (3.0, 1.0, -0.5),
    ];
    let mut checked = 0;
    for (a, b, c) in cases {
        let sc =
            SliderCrank::new(Point2::origin(), a, b, Point2::new(-7.0, c), Vector2::x()).unwrap();
        assert_eq!(sc.offset(), -c);
        for k in 0..720 {
            let t2 = (k as f64) * TAU / 720.0 - PI;
            let Some(book) = norton(a, b, c, t2) else {
                assert!(sc.solve(t2, AssemblyMode::Open).is_err());
                continue;
            };
            for (mode, (t3, d)) in [AssemblyMode::Open, AssemblyMode::Crossed]
                .into_iter()
                .zip(book)
            {
                let Ok(s) = sc.solve(t2, mode) else {
                    // Only where the book's asin argument is 1 within rounding.
                    let q = (a * t2.sin() - c) / b;
                    assert!((q.abs() - 1.0).abs() < 1e-12, "{a} {b} {c} {t2}");
                    continue;
                };
                let size = a + b + c.abs();
                // Near a toggle the position moves like the square root of
                // the crank angle, so both forms keep only half the digits
                // there (the book's asin of an argument near 1, our root of
                // H near 0).
                let near = s.transmission_angle < 1e-3;
                let (tol_s, tol) = if near { (1e-7, 1e-6) } else { (1e-12, 1e-11) };
                assert!(
                    (s.slider - d).abs() < tol_s * size,
                    "{mode:?} {t2}: {} vs {d}",
                    s.slider
                );
                // Ours runs from A to B, the book's from B to A.
                assert!(wrap(s.theta3 - (t3 + PI)).abs() < tol, "{mode:?} {t2}");
                // The transmission angle: cos mu = |a sin theta2 - c| / b.
                let mu = ((a * t2.sin() - c).abs() / b).min(1.0).acos();
                assert!((s.transmission_angle - mu).abs() < tol, "{mode:?} {t2}");
                checked += 1;
            }
        }
    }
    assert!(checked > 5000, "{checked}");
}

/// The two points of the guide at distance `l` from `a`, by bisection of
/// `g(s) = |F + s u - a|^2 - l^2` on each side of the foot of `a` (no
/// square-root formula): `[behind, ahead]` along `u`.
fn bisect_roots(f: Point2<f64>, u: Vector2<f64>, a: Point2<f64>, l: f64) -> Option<[f64; 2]> {
    let g = |s: f64| (f + u * s - a).norm_squared() - l * l;
    let mid = (a - f).dot(&u);
    if g(mid) > 0.0 {
        return None;
    }
    let solve = |mut lo: f64, mut hi: f64| {
        // g(lo) and g(hi) of opposite signs.
        let up = g(hi) > g(lo);
        for _ in 0..200 {
            let m = 0.5 * (lo + hi);
            if (g(m) > 0.0) == up {
                hi = m;
            } else {
                lo = m;
            }
        }
        0.5 * (lo + hi)
    };
    Some([solve(mid - 2.0 * l, mid), solve(mid, mid + 2.0 * l)])
}

fn arb_slider() -> impl Strategy<Value = (SliderCrank, f64)> {
    (
        -5.0..5.0f64,
        -5.0..5.0f64,
        0.2..4.0f64,
        0.2..6.0f64,
        -3.0..3.0f64,
        -PI..PI,
        0.01..100.0f64,
    )
        .prop_filter_map("assembles", |(x, y, r, l, e, g, k)| {
            let pivot = Point2::new(x, y) * k;
            let u = unit(g);
            let n = Vector2::new(-u.y, u.x);
            // The guide through a point at offset e from the pivot.
            let p = pivot - n * (e * k) + u * 1.7;
            SliderCrank::new(pivot, r * k, l * k, p, u)
                .ok()
                .map(|s| (s, k))
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// 400 crank angles per linkage against the bisection solver: the
    /// slider's position, the coupler angle and which root is which mode.
    #[test]
    fn dense_independent_solver((sc, _k) in arb_slider()) {
        let size = sc.crank() + sc.coupler() + sc.offset().abs();
        let mut solved = 0;
        for i in 0..400 {
            let t2 = (i as f64 + 0.5) * TAU / 400.0 - PI;
            let a = sc.crank_pivot() + unit(t2) * sc.crank();
            let roots = bisect_roots(sc.foot(), sc.guide(), a, sc.coupler());
            let open = sc.solve(t2, AssemblyMode::Open);
            let Some([behind, ahead]) = roots else {
                // Beyond the guide's reach; the library agrees except within
                // rounding of the toggle.
                if let Ok(c) = open { prop_assert!(c.transmission_angle < 1e-6); }
                continue;
            };
            let (o, x) = (open.unwrap(), sc.solve(t2, AssemblyMode::Crossed).unwrap());
            prop_assert!((o.slider - behind).abs() <= 1e-9 * size, "{} {}", o.slider, behind);
            prop_assert!((x.slider - ahead).abs() <= 1e-9 * size, "{} {}", x.slider, ahead);
            for c in [o, x] {
                let j = sc.joints(&c);
                let v = j.slider_joint - j.crank_joint;
                prop_assert!((v.norm() - sc.coupler()).abs() <= 1e-9 * size);
                prop_assert!(wrap(v.y.atan2(v.x) - c.theta3).abs() <= 1e-9);
                // The mode's sign is <B - A, u> (Open behind).
                let side = v.dot(&sc.guide());
                if !c.toggle {
                    prop_assert_eq!(side < 0.0, c.mode == AssemblyMode::Open);
                    prop_assert_eq!(AssemblyMode::of_slider(v, sc.guide(), sc.crank() + sc.offset().abs()), Some(c.mode));
                }
            }
            solved += 1;
        }
        // Every linkage assembles somewhere; a sample grid of 400 finds it
        // unless its range is a sliver.
        prop_assert!(solved > 0 || sc.input_range().dead_positions().len() == 2);
    }

    /// The input range is where the loop closes, the dead positions are
    /// toggles with a zero transmission angle, and a crank turns fully
    /// exactly when r + |e| <= l.
    #[test]
    fn input_range_and_dead_positions((sc, _k) in arb_slider()) {
        let range = sc.input_range();
        let (r, l, e) = (sc.crank(), sc.coupler(), sc.offset());
        prop_assert_eq!(range.is_full(), r + e.abs() <= l);
        for i in 0..720 {
            let t2 = (i as f64 + 0.5) * TAU / 720.0;
            let h = e + r * (Vector2::new(t2.cos(), t2.sin()).dot(&sc.guide_normal()));
            if (h.abs() - l).abs() < 1e-9 * (r + l) { continue; }
            prop_assert_eq!(range.contains(t2), sc.solve(t2, AssemblyMode::Open).is_ok(), "{}", t2);
        }
        for t in range.dead_positions() {
            for m in AssemblyMode::BOTH {
                let c = sc.solve(t, m).unwrap();
                prop_assert!(c.toggle);
                prop_assert!(c.transmission_angle < 1e-6);
            }
        }
    }

    /// The slider's limits and stroke against dense driving in each mode,
    /// and the textbook stroke of a full-turn crank.
    #[test]
    fn limits_and_stroke((sc, _k) in arb_slider()) {
        let size = sc.crank() + sc.coupler() + sc.offset().abs();
        let (r, l, e) = (sc.crank(), sc.coupler(), sc.offset());
        for m in AssemblyMode::BOTH {
            let [lo, hi] = sc.limits(m);
            let (mut dlo, mut dhi) = (f64::INFINITY, f64::NEG_INFINITY);
            // The dead positions too: near one the slider moves like the
            // square root of the crank angle, which a grid would miss.
            let grid = (0..20000).map(|i| i as f64 * TAU / 20000.0);
            for t2 in grid.chain(sc.input_range().dead_positions()) {
                if let Ok(c) = sc.solve(t2, m) {
                    dlo = dlo.min(c.slider);
                    dhi = dhi.max(c.slider);
                }
            }
            // Sampled extremes are inside the exact ones and close to them.
            prop_assert!(dlo >= lo.slider - 1e-9 * size && dhi <= hi.slider + 1e-9 * size);
            prop_assert!(dlo - lo.slider <= 1e-3 * size && hi.slider - dhi <= 1e-3 * size,
                "{m:?}: {} {} vs {} {}", lo.slider, hi.slider, dlo, dhi);
            // The angles given are where the slider is there.
            for p in [lo, hi] {
                let c = sc.solve(p.theta2, m).unwrap();
                prop_assert!((c.slider - p.slider).abs() <= 1e-7 * size);
            }
            if sc.turns_fully() {
                let book = ((l + r).powi(2) - e * e).sqrt() - ((l - r).powi(2) - e * e).sqrt();
                prop_assert!((sc.stroke(m) - book).abs() <= 1e-12 * size * size / (l - r).abs().max(1e-3 * size));
            }
        }
    }

    /// The modes carry the four-bar's names in the limit of a rocker pivot
    /// far along the guide's normal (`C0 = B + R n`), and the transmission
    /// angles agree.
    #[test]
    fn four_bar_limit_names_the_modes((sc, _k) in arb_slider(), t2 in -PI..PI) {
        for m in AssemblyMode::BOTH {
            let Ok(c) = sc.solve(t2, m) else { continue };
            // Away from the toggle, where the four-bar's rounding at a link
            // ratio of 1e6 (about 1e-10 / sin mu) stays small.
            if c.transmission_angle < 0.02 { continue; }
            let j = sc.joints(&c);
            let big = 1e6 * (sc.crank() + sc.coupler());
            let c0 = j.slider_joint + sc.guide_normal() * big;
            let fb = FourBar::from_pivots(sc.crank_pivot(), c0, sc.crank(), sc.coupler(), big).unwrap();
            let f = fb.solve(t2, m).unwrap();
            prop_assert!(wrap(f.theta3 - c.theta3).abs() < 1e-6, "{m:?}: {} vs {}", f.theta3, c.theta3);
            prop_assert!((f.transmission_angle() - c.transmission_angle).abs() < 1e-6);
            let fj = fb.joints(&f);
            prop_assert!((fj.rocker_joint - j.slider_joint).norm() < 1e-6 * (sc.crank() + sc.coupler()));
        }
    }
}

// The slider-crank of a task.

/// A task made from a known slider-crank: the coupler point `local` (in the
/// coupler frame) and the coupler angle at crank angles `angles`, each in
/// its mode; with the known driving dyad and slider.
fn task_of(
    sc: &SliderCrank,
    local: Vector2<f64>,
    angles: &[(f64, AssemblyMode)],
) -> Option<(Task, Dyad, SliderDyad)> {
    let mut poses = Vec::new();
    let mut first = None;
    for &(t, m) in angles {
        let c = sc.solve(t, m).ok()?;
        let j = sc.joints(&c);
        first.get_or_insert(j);
        poses.push(Pose {
            position: sc.coupler_point(&c, local),
            angle: c.theta3 + 0.3,
        });
    }
    let task = Task::new(&poses).ok()?;
    let j = first?;
    Some((
        task,
        Dyad::new(sc.crank_pivot(), j.crank_joint),
        SliderDyad::new(j.slider_joint, sc.guide()).ok()?,
    ))
}

/// Drives the built linkage densely by crank angle from pose 1 in the mode
/// of pose 1, each way round, for one turn or until the loop fails: the
/// direction in which it reaches the poses 2..n in order (a pose reached:
/// the coupler within `1e-7` of it when the crank passes its angle).
fn dense_verdict(s: &SynthesizedSliderCrank, task: &Task) -> Direction {
    let Some(mode) = s.modes[0] else {
        return Direction::None;
    };
    let n = task.len();
    let scale = task.scale();
    let steps = 20000;
    for (dir, name) in [(1.0, Direction::Ccw), (-1.0, Direction::Cw)] {
        let t0 = s.input_angles[0];
        let mut next = 1;
        let mut prev = t0;
        for i in 1..=steps {
            let t = t0 + dir * TAU * i as f64 / steps as f64;
            if s.linkage.solve(t, mode).is_err() {
                break;
            }
            // The poses whose crank angle lies between prev and t.
            for k in 1..n {
                let off = |x: f64| ((x - t0) * dir).rem_euclid(TAU);
                let (a, b) = (off(prev), if i == steps { TAU } else { off(t) });
                let ok = off(s.input_angles[k]);
                if ok > a && ok <= b {
                    let p = s.pose_at(s.input_angles[k], mode).unwrap();
                    let q = task.poses()[k];
                    let hit = (p.position - q.position).norm() < 1e-7 * scale
                        && wrap(p.angle - q.angle).abs() < 1e-7;
                    if hit && k == next {
                        next += 1;
                    } else if hit {
                        next = usize::MAX; // out of order
                    }
                }
            }
            prev = t;
        }
        if next == n {
            return name;
        }
    }
    Direction::None
}

/// Poses clear of toggles and of each other (the verdicts are then robust
/// to the dense step).
fn clear_poses(sc: &SliderCrank, angles: &[(f64, AssemblyMode)]) -> bool {
    let clear_of_toggle =
        |&(t, m): &(f64, AssemblyMode)| sc.solve(t, m).is_ok_and(|c| c.transmission_angle > 1e-3);
    let apart = |i: usize| {
        angles[..i]
            .iter()
            .all(|b| wrap(angles[i].0 - b.0).abs() > 1e-2)
    };
    angles.iter().all(clear_of_toggle) && (0..angles.len()).all(apart)
}

fn arb_task() -> impl Strategy<Value = (SliderCrank, Vector2<f64>, Vec<(f64, AssemblyMode)>)> {
    (
        arb_slider(),
        (-2.0..2.0f64, -2.0..2.0f64),
        prop::collection::vec((-PI..PI, prop::bool::weighted(0.85)), 3..=5),
        prop::bool::ANY,
    )
        .prop_map(|((sc, k), (x, y), raw, crossed)| {
            let m0 = if crossed {
                AssemblyMode::Crossed
            } else {
                AssemblyMode::Open
            };
            let angles = raw
                .into_iter()
                .map(|(t, same)| (t, if same { m0 } else { m0.other() }))
                .collect();
            (sc, Vector2::new(x, y) * k, angles)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// Tasks made from known slider-cranks: the library's slider-crank of
    /// the known dyads reaches the poses, gives the modes they were made in
    /// (and the notes' coupler-frame formula), and its branch and order
    /// verdicts agree with driving it densely.
    #[test]
    fn tasks_from_known_slider_cranks((sc, local, angles) in arb_task()) {
        let Some((task, driving, driven)) = task_of(&sc, local, &angles) else {
            return Ok(());
        };
        prop_assume!(clear_poses(&sc, &angles));
        let s = task.slider_crank(&driving, &driven).unwrap();
        let size = sc.crank() + sc.coupler() + sc.offset().abs() + local.norm();
        prop_assert!((s.linkage.crank() - sc.crank()).abs() < 1e-9 * size);
        prop_assert!((s.linkage.coupler() - sc.coupler()).abs() < 1e-9 * size);
        prop_assert!((s.linkage.offset() - sc.offset()).abs() < 1e-9 * size);
        for (k, &(t, m)) in angles.iter().enumerate() {
            prop_assert!(wrap(s.input_angles[k] - t).abs() < 1e-9);
            prop_assert_eq!(s.modes[k], Some(m));
            // The notes' formula in the coupler frame at pose 1.
            let dth = task.poses()[k].angle - task.poses()[0].angle;
            let uk = Vector2::new(
                sc.guide().x * dth.cos() + sc.guide().y * dth.sin(),
                -sc.guide().x * dth.sin() + sc.guide().y * dth.cos(),
            );
            let sign = (driven.circle - driving.circle).dot(&uk);
            prop_assert_eq!(sign < 0.0, m == AssemblyMode::Open);
            // Driving the built linkage reaches the pose.
            let p = s.pose_at(s.input_angles[k], m).unwrap();
            let q = task.poses()[k];
            prop_assert!((p.position - q.position).norm() < 1e-9 * size);
            prop_assert!(wrap(p.angle - q.angle).abs() < 1e-9);
            prop_assert!((s.slider_positions[k] - sc.solve(t, m).unwrap().slider).abs() < 1e-9 * size);
        }
        let same = angles.iter().all(|a| a.1 == angles[0].1);
        prop_assert_eq!(s.is_branch_free(), same);
        let dense = dense_verdict(&s, &task);
        let lib = if s.feasible() { s.direction } else { Direction::None };
        prop_assert_eq!(lib, dense, "order {}, modes {:?}", s.order(), angles);
        if s.feasible() {
            // The stroke used and the smallest transmission angle against
            // dense driving over the travel.
            let ts = s.travel_angles(4001).unwrap();
            let m = s.modes[0].unwrap();
            let (mut lo, mut hi, mut mu) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY);
            for t in ts {
                let c = s.linkage.solve(t, m).unwrap();
                lo = lo.min(c.slider);
                hi = hi.max(c.slider);
                mu = mu.min(c.transmission_angle);
            }
            prop_assert!(hi - lo <= s.stroke_used + 1e-9 * size);
            prop_assert!(hi - lo >= s.stroke_used - 1e-3 * size);
            prop_assert!(mu >= s.min_transmission - 1e-9);
            prop_assert!(mu <= s.min_transmission + 2e-3);
            let stops = s.travel_stops().unwrap();
            for k in 1..stops.len() {
                prop_assert!((stops[k] - stops[k - 1]) * s.direction.sign() > 0.0);
            }
        } else {
            prop_assert!(s.stroke_used.is_nan() || !s.is_branch_free() || s.direction != Direction::None);
        }
        prop_assert!(s.size() >= sc.crank() + sc.coupler());
    }

    /// Moving, rotating and scaling a task moves, rotates and scales its
    /// slider-crank: the same modes, direction and transmission, the
    /// stroke and the size scaled, the crank angles turned.
    #[test]
    fn moves_rotations_scaling((sc, local, angles) in arb_task(),
                               f in 0.01..100.0f64, rot in -PI..PI, dx in -50.0..50.0f64, dy in -50.0..50.0f64) {
        let Some((task, driving, driven)) = task_of(&sc, local, &angles) else {
            return Ok(());
        };
        prop_assume!(clear_poses(&sc, &angles));
        let s = task.slider_crank(&driving, &driven).unwrap();
        let sim = burmester::Similarity::new(f, rot, Vector2::new(dx, dy)).unwrap();
        let t2 = task.transformed_by(&sim).unwrap();
        let d2 = Dyad::new(sim.point(driving.center), sim.point(driving.circle));
        let g2 = SliderDyad::new(sim.point(driven.circle), sim.direction(driven.guide)).unwrap();
        let s2 = t2.slider_crank(&d2, &g2).unwrap();
        prop_assert_eq!(s2.modes, s.modes);
        prop_assert_eq!(s2.direction, s.direction);
        prop_assert_eq!(s2.one_circuit, s.one_circuit);
        for k in 0..angles.len() {
            prop_assert!(wrap(s2.input_angles[k] - s.input_angles[k] - rot).abs() < 1e-9);
        }
        if s.min_transmission.is_nan() {
            prop_assert!(s2.min_transmission.is_nan());
        } else {
            prop_assert!((s2.min_transmission - s.min_transmission).abs() < 1e-7);
        }
        if s.stroke_used.is_nan() {
            prop_assert!(s2.stroke_used.is_nan());
        } else {
            prop_assert!((s2.stroke_used - f * s.stroke_used).abs() < 1e-8 * f * s.size());
        }
        prop_assert!((s2.size() - f * s.size()).abs() < 1e-8 * f * s.size());
    }
}

#[test]
fn bad_input_is_refused_with_typed_errors() {
    let o = Point2::origin();
    let x = Vector2::x();
    let is = |r: burmester::Result<SliderCrank>, want: &str| {
        let e = r.unwrap_err();
        let cause = match &e {
            Error::InvalidInput(i) => i.cause(),
            Error::Assembly(a) => a.cause(),
            _ => "other",
        };
        assert_eq!(cause, want, "{e}");
    };
    is(SliderCrank::new(o, -1.0, 2.0, o, x), "not_positive");
    is(SliderCrank::new(o, 1.0, f64::NAN, o, x), "not_finite");
    is(
        SliderCrank::new(o, 1.0, 2.0, Point2::new(0.0, f64::INFINITY), x),
        "not_finite",
    );
    is(
        SliderCrank::new(o, 1.0, 2.0, o, Vector2::zeros()),
        "zero_direction",
    );
    is(
        SliderCrank::new(o, 1.0, 2.0, Point2::new(0.0, 3.5), x),
        "guide_out_of_reach",
    );
    is(
        SliderCrank::new(Point2::new(2e300, 0.0), 1.0, 2.0, o, x),
        "too_large",
    );
    // At the documented maxima: the extent and the angle.
    let sc = SliderCrank::new(Point2::new(0.0, 0.0), 1.0, 2.0, Point2::new(0.0, 0.5), x).unwrap();
    if let Err(e) = SliderCrank::new(o, 1e299, 2e299, Point2::new(0.0, 1e299), x) {
        panic!("at the maximum extent: {e}");
    }
    assert!(sc.solve(SliderCrank::MAX_ANGLE, AssemblyMode::Open).is_ok());
    match sc.solve(SliderCrank::MAX_ANGLE * 1.5, AssemblyMode::Open) {
        Err(Error::InvalidInput(InvalidInput::TooLarge { .. })) => {}
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        sc.solve(f64::NAN, AssemblyMode::Open),
        Err(Error::InvalidInput(InvalidInput::NotFinite { .. }))
    ));
    // Out of reach at a crank angle: a rocking crank (r + |e| > l).
    let rock = SliderCrank::new(o, 2.0, 1.5, Point2::new(0.0, 1.0), x).unwrap();
    assert!(!rock.turns_fully());
    let e = rock.solve(-PI / 2.0, AssemblyMode::Open).unwrap_err();
    assert!(
        matches!(e, Error::Assembly(AssemblyError::SliderOutOfReach { .. })),
        "{e}"
    );
    assert!(e.to_string().contains("input range"), "{e}");
    let path: Vec<_> = sc
        .coupler_path(Vector2::new(f64::NAN, 0.0), [0.0, 1.0], AssemblyMode::Open)
        .collect();
    assert!(path.iter().all(|p| p.is_err()));
}

#[test]
fn task_refuses_what_is_not_a_slider_crank() {
    let sc =
        SliderCrank::new(Point2::origin(), 1.0, 3.0, Point2::new(0.0, 0.4), unit(0.2)).unwrap();
    let angles = [
        (0.2, AssemblyMode::Open),
        (1.0, AssemblyMode::Open),
        (2.1, AssemblyMode::Open),
        (3.0, AssemblyMode::Open),
    ];
    let (task, driving, driven) = task_of(&sc, Vector2::new(0.5, 0.7), &angles).unwrap();
    let s = task.slider_crank(&driving, &driven).unwrap();
    assert!(s.feasible(), "{s:?}");
    assert_eq!(s.direction, Direction::Ccw);
    assert!(sc.turns_fully());
    // A guide in another direction: the slider's positions leave it.
    let bad = SliderDyad::new(driven.circle, unit(0.5)).unwrap();
    let e = task.slider_crank(&driving, &bad).unwrap_err();
    assert!(
        matches!(e, Error::InvalidInput(InvalidInput::NotASlider { .. })),
        "{e}"
    );
    assert!(e.to_string().contains("slider point"), "{e}");
    // A driving circle point that is not one of its center.
    let wrong = Dyad::new(driving.center, driving.circle + Vector2::new(0.1, 0.0));
    let e = task.slider_crank(&wrong, &driven).unwrap_err();
    assert!(
        matches!(e, Error::InvalidInput(InvalidInput::NotADyad { .. })),
        "{e}"
    );
    // A coupler of no length.
    let same = SliderDyad::new(driving.circle, unit(0.2)).unwrap();
    assert!(task.slider_crank(&driving, &same).is_err());
    // travel_angles at its documented maximum, and one past it.
    let t = s
        .travel_angles(SynthesizedSliderCrank::MAX_TRAVEL_SAMPLES)
        .unwrap();
    assert_eq!(t.len(), SynthesizedSliderCrank::MAX_TRAVEL_SAMPLES);
    assert!((t[0] - s.input_angles[0]).abs() < 1e-15);
    assert!(
        s.travel_angles(SynthesizedSliderCrank::MAX_TRAVEL_SAMPLES + 1)
            .is_err()
    );
    assert!(s.travel_angles(1).is_err());
}

/// A designer's task: a press ram (the slider) driven by a 40 mm crank
/// through a 150 mm connecting rod with a 10 mm offset: the stroke, the
/// quick return and the worst transmission angle are what the books give.
#[test]
fn press_in_millimetres() {
    let sc = SliderCrank::new(
        Point2::new(100.0, 50.0),
        40.0,
        150.0,
        Point2::new(0.0, 40.0),
        Vector2::x(),
    )
    .unwrap();
    assert!(sc.turns_fully());
    let e: f64 = 10.0;
    let book = (190f64.powi(2) - e * e).sqrt() - (110f64.powi(2) - e * e).sqrt();
    for m in AssemblyMode::BOTH {
        assert!((sc.stroke(m) - book).abs() < 1e-10, "{}", sc.stroke(m));
    }
    // The worst transmission angle over a turn: cos mu = (r + |e|) / l.
    let worst = (0..3600)
        .map(|i| {
            sc.solve(i as f64 * TAU / 3600.0, AssemblyMode::Crossed)
                .unwrap()
                .transmission_angle
        })
        .fold(f64::INFINITY, f64::min);
    assert!(
        (worst - (50.0f64 / 150.0).acos()).abs() < 1e-5,
        "{}",
        worst.to_degrees()
    );
    // The limit positions are where crank and coupler are collinear.
    let [lo, hi] = sc.limits(AssemblyMode::Crossed);
    for p in [lo, hi] {
        let j = sc.joints_at(p.theta2, AssemblyMode::Crossed).unwrap();
        let (a, b) = (
            j.crank_joint - j.crank_pivot,
            j.slider_joint - j.crank_joint,
        );
        assert!((a.x * b.y - a.y * b.x).abs() < 1e-9 * 40.0 * 150.0);
    }
}
