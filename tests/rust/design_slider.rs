//! `Task::design` with a driven slider (`DrivenKind::Slider`, issue 27)
//! against independent things: tasks made from a known slider-crank (its
//! coupler poses by the textbook closed form, written here), every design
//! driven through its travel by a slider-crank solver written here (the
//! pin where the circle of the coupler about the crank pin meets the
//! guide) and by the library's `SliderCrank` position analysis, reaching
//! the poses to 1e-9 with its transmission angle inside the limits over
//! the travel; brute forces over a finer grid (three poses) or finer curve
//! samples (four poses); the known linkage found among the five-pose
//! designs; moved, rotated and scaled tasks giving the moved answers;
//! refusals; the documented maxima with a cancel.
//!
//! Test builds are unoptimised: the coarse resolutions here are reduced.

use core::sync::atomic::{AtomicBool, Ordering};
use std::f64::consts::PI;
use std::time::Duration;

mod common;

use burmester::{
    Control, Design, DesignLimits, DesignOptions, DrivenKind, Grid, Point2, Pose, Similarity,
    SynthesizedSliderCrank, Task, Vector2,
};

/// The known slider-crank: crank pivot `A0`, crank `R`, coupler `L`, the
/// guide at offset `E` from `A0`, turned by `PHI`; the coupler point in
/// the coupler frame.
const A0: [f64; 2] = [0.3, -0.2];
const R: f64 = 1.0;
const L: f64 = 3.2;
const E: f64 = 0.5;
const PHI: f64 = 0.4;
const LOCAL: [f64; 2] = [1.2, 0.9];

/// The textbook closed form of the offset slider-crank (Norton, *Design of
/// Machinery*, section 4.6: with the guide along `x` at height `c` and
/// crank `a`, coupler `b`: `theta3 = asin((a sin theta2 - c) / b)`, the
/// slider at `d = a cos theta2 - b cos theta3`), in the frame of `A0`
/// with the guide along `x` at `y = E`, the pin ahead of the crank pin
/// along the guide: the crank pin, the pin, the coupler angle.
fn textbook(theta: f64) -> (Vector2<f64>, Vector2<f64>, f64) {
    let a = Vector2::new(R * theta.cos(), R * theta.sin());
    let s = (E - a.y) / L;
    let theta3 = s.asin();
    let c = Vector2::new(a.x + L * theta3.cos(), E);
    (a, c, theta3)
}

/// The world frame: turned by `PHI` about `A0`'s frame, moved to `A0`.
fn world(v: Vector2<f64>) -> Point2<f64> {
    let (s, c) = PHI.sin_cos();
    Point2::new(A0[0] + c * v.x - s * v.y, A0[1] + s * v.x + c * v.y)
}

/// The known linkage's task at crank angles `thetas`, with its crank
/// pivot and its slider pin at pose 1 (world).
fn known_task(thetas: &[f64]) -> (Task, Point2<f64>, Point2<f64>) {
    let poses: Vec<Pose> = thetas
        .iter()
        .map(|&t| {
            let (a, _, th3) = textbook(t);
            let (s, c) = th3.sin_cos();
            let p = a + Vector2::new(c * LOCAL[0] - s * LOCAL[1], s * LOCAL[0] + c * LOCAL[1]);
            let w = world(p);
            Pose::new(w.x, w.y, th3 + PHI + 0.25)
        })
        .collect();
    let (_, c, _) = textbook(thetas[0]);
    (
        Task::new(&poses).unwrap(),
        world(Vector2::zeros()),
        world(c),
    )
}

fn wrap(a: f64) -> f64 {
    (a + PI).rem_euclid(2.0 * PI) - PI
}

/// One position of `sc` by the solver here: the coupler point, its angle,
/// the pin and the transmission angle; `None` where the loop does not
/// close.
fn own_solve(
    sc: &SynthesizedSliderCrank,
    theta: f64,
    open: bool,
) -> Option<(Point2<f64>, f64, Point2<f64>, f64)> {
    let l = &sc.linkage;
    let (f, u) = (l.foot(), l.guide());
    let n = Vector2::new(-u.y, u.x);
    let a = l.crank_pivot() + Vector2::new(theta.cos(), theta.sin()) * l.crank();
    let w = a - f;
    let (along, h) = (w.dot(&u), w.dot(&n));
    let disc = l.coupler() * l.coupler() - h * h;
    if disc <= 0.0 {
        return None;
    }
    // Open: the pin behind the crank pin along the guide (`<C - A, u> <
    // 0`, as the library names the modes).
    let sign = if open { -1.0 } else { 1.0 };
    let c = f + u * (along + sign * disc.sqrt());
    let th3 = (c - a).y.atan2((c - a).x);
    let (s, co) = th3.sin_cos();
    let q = sc.coupler_point;
    let p = a + Vector2::new(co * q.x - s * q.y, s * q.x + co * q.y);
    let mu = (h.abs() / l.coupler()).min(1.0).acos();
    Some((p, th3 + sc.coupler_angle_offset, c, mu))
}

/// Every check of one slider design: it is a slider-crank; driven by the
/// solver here and by the library's position analysis it reaches the
/// poses at its travel stops to 1e-9; over the travel the loop closes
/// with no jump and the transmission angle stays within the limit; its
/// link ratio and size ratio are its figures'.
fn check_design(t: &Task, limits: &DesignLimits, d: &Design) {
    let sc = d.linkage.slider_crank().expect("a slider-crank");
    assert!(sc.feasible());
    let span = t.span();
    let mode = sc.modes[0].unwrap();
    let open = mode == burmester::AssemblyMode::Open;
    let stops = sc.travel_stops().unwrap();
    for (k, pose) in t.poses().iter().enumerate() {
        let (p, ang, _, _) = own_solve(sc, stops[k], open).expect("closes at a pose");
        assert!(
            (p - pose.position).norm() < 1e-9 * span,
            "pose {} missed by {}",
            k + 1,
            (p - pose.position).norm()
        );
        assert!(wrap(ang - pose.angle).abs() < 1e-9);
        let q = sc.pose_at(stops[k], mode).unwrap();
        assert!((q.position - pose.position).norm() < 1e-9 * span);
        assert!(wrap(q.angle - pose.angle).abs() < 1e-9);
    }
    let mut prev: Option<Point2<f64>> = None;
    let mut worst = f64::INFINITY;
    for th in sc.travel_angles(4001).unwrap() {
        let (_, _, c, mu) = own_solve(sc, th, open).expect("the loop opens over the travel");
        if let Some(p) = prev {
            assert!(
                (c - p).norm() < 0.05 * sc.linkage.coupler(),
                "a jump at {th}"
            );
        }
        prev = Some(c);
        let lib = sc.linkage.solve(th, mode).unwrap();
        assert!((lib.transmission_angle - mu).abs() < 1e-9);
        worst = worst.min(mu);
    }
    assert!(worst >= limits.min_transmission - 1e-9, "{worst}");
    assert!(worst >= sc.min_transmission - 1e-9);
    assert!(worst <= sc.min_transmission + 1e-3);
    let (r, l) = (sc.linkage.crank(), sc.linkage.coupler());
    assert!(r.max(l) / r.min(l) <= limits.max_link_ratio);
    assert!((sc.size() / span - d.size_ratio).abs() < 1e-12 * d.size_ratio);
    assert!(sc.linkage.rotatability_margin() >= limits.min_grashof_margin);
}

/// The score of a slider-crank under the default limits as checked here,
/// `None` where it is not acceptable.
fn score_of(t: &Task, o: &DesignOptions, sc: &SynthesizedSliderCrank) -> Option<f64> {
    let l = &sc.linkage;
    let lim = &o.limits;
    let link = l.crank().max(l.coupler()) / l.crank().min(l.coupler());
    let ok = sc.feasible()
        && sc.min_transmission >= lim.min_transmission
        && link <= lim.max_link_ratio
        && l.rotatability_margin() >= lim.min_grashof_margin
        && sc.size() / t.span() <= lim.max_size_ratio;
    if !ok {
        return None;
    }
    o.rank_by
        .score(sc.min_transmission, sc.size() / t.span(), link)
}

fn slider(o: DesignOptions) -> DesignOptions {
    DesignOptions {
        driven: DrivenKind::Slider,
        coarse_driven: 6,
        coarse_driving: 16,
        coarse_pairs: 30,
        starts: 12,
        ..o
    }
}

fn best_score(designs: &[Design]) -> f64 {
    designs[0].score
}

/// The best design scores at least the best acceptable slider-crank of
/// every `driving` dyad with every slider (to 1e-6 relative).
fn beats_the_brute_force(
    t: &Task,
    o: &DesignOptions,
    designs: &[Design],
    driving: impl Iterator<Item = burmester::Dyad>,
    sliders: &[burmester::SliderDyad],
) {
    let mut brute = f64::NEG_INFINITY;
    for a in driving {
        for s in sliders {
            if let Some(x) = t
                .slider_crank(&a, s)
                .ok()
                .and_then(|sc| score_of(t, o, &sc))
            {
                brute = brute.max(x);
            }
        }
    }
    assert!(brute.is_finite());
    let got = best_score(designs);
    assert!(
        got >= brute - 1e-6 * brute.abs().max(1.0),
        "{got} < {brute}"
    );
}

#[test]
fn three_poses_beat_a_finer_brute_force() {
    let (t, a0, c1) = known_task(&[0.3, 1.2, 2.0]);
    let o = slider(DesignOptions::default());
    let r = t.design(&o, &Control::new()).unwrap();
    assert!(!r.designs.is_empty());
    for d in &r.designs {
        check_design(&t, &o.limits, d);
        assert!(matches!(
            d.refined,
            burmester::SearchPoint::SliderCircle { .. }
        ));
    }
    // The known linkage is one candidate.
    let known = t
        .slider_crank(
            &t.dyad_from_center(a0).unwrap(),
            &t.slider_dyad(c1).unwrap(),
        )
        .unwrap();
    let known_score = score_of(&t, &o, &known).expect("the known linkage is acceptable");
    assert!(best_score(&r.designs) >= known_score - 1e-9);
    // A brute force four times finer: A0 over the search box, pins along
    // the slider circle.
    let bx = r.search_box.unwrap();
    let (w, h) = bx.size();
    let n = 4 * o.coarse_driving;
    let (nx, ny) = if w >= h {
        (n, ((n as f64 * h / w).round() as usize).max(2))
    } else {
        (((n as f64 * w / h).round() as usize).max(2), n)
    };
    let g = Grid::new(bx, nx, ny).unwrap();
    let sliders = t.slider_dyads(4 * o.coarse_driven).unwrap();
    let driving = (0..g.len()).filter_map(|k| t.dyad_from_center(g.point(k % nx, k / nx)).ok());
    beats_the_brute_force(&t, &o, &r.designs, driving, &sliders);
    // Distinct: crank pivots or pins apart by the separation.
    for (i, d) in r.designs.iter().enumerate() {
        for e in &r.designs[..i] {
            let apart = (d.linkage.driving().center - e.linkage.driving().center)
                .norm()
                .max((d.linkage.driven_point() - e.linkage.driven_point()).norm());
            assert!(apart >= r.min_separation);
        }
    }
}

#[test]
fn four_poses_beat_finer_curve_samples() {
    let (t, a0, c1) = known_task(&[0.3, 1.0, 1.8, 2.7]);
    let o = slider(DesignOptions::default());
    // The known pin is a slider point of the task, the known pivot on the
    // center-point curve.
    let sliders = t.slider_dyads(1).unwrap();
    assert!(sliders.iter().any(|s| (s.circle - c1).norm() < 1e-7));
    let _ = a0;
    let r = t.design(&o, &Control::new()).unwrap();
    assert!(!r.designs.is_empty());
    for d in &r.designs {
        check_design(&t, &o.limits, d);
    }
    let four = t.four_positions("test").unwrap();
    let samples = four.parameter_samples(4 * o.coarse_pairs).unwrap();
    let driving = samples.into_iter().flatten().map(|a| a.dyad());
    beats_the_brute_force(&t, &o, &r.designs, driving, &sliders);
}

/// The five-pose task of the known linkage: its crank is a Burmester
/// point, its pin a slider Burmester point, and with no separation every
/// acceptable pair is a design: the known one among them.
#[test]
fn five_poses_find_the_known_slider_crank() {
    let (t, a0, c1) = known_task(&[0.1, 0.8, 1.5, 2.3, 3.0]);
    let o = DesignOptions {
        top: DesignOptions::MAX_TOP,
        min_separation: Some(0.0),
        ..slider(DesignOptions::default())
    };
    let r = t.design(&o, &Control::new()).unwrap();
    for d in &r.designs {
        check_design(&t, &o.limits, d);
    }
    let span = t.span();
    assert!(
        r.designs.iter().any(|d| {
            (d.linkage.driving().center - a0).norm() < 1e-6 * span
                && (d.linkage.driven_point() - c1).norm() < 1e-6 * span
        }),
        "{:?}",
        r.designs
            .iter()
            .map(|d| (d.linkage.driving().center, d.linkage.driven_point()))
            .collect::<Vec<_>>()
    );
    // Moved, turned and scaled: the moved designs, in the same order.
    let sim = Similarity::new(3.7, 1.1, Vector2::new(12.0, -40.0)).unwrap();
    let t2 = t.transformed_by(&sim).unwrap();
    let r2 = t2.design(&o, &Control::new()).unwrap();
    assert_eq!(r2.designs.len(), r.designs.len());
    for (d, d2) in r.designs.iter().zip(&r2.designs) {
        assert!(
            (d2.score - d.score).abs() < 1e-7,
            "{} {}",
            d.score,
            d2.score
        );
        assert!((d2.size_ratio - d.size_ratio).abs() < 1e-7 * d.size_ratio);
        let a = sim.point(d.linkage.driving().center);
        let c = sim.point(d.linkage.driven_point());
        assert!((d2.linkage.driving().center - a).norm() < 1e-6 * t2.span());
        assert!((d2.linkage.driven_point() - c).norm() < 1e-6 * t2.span());
    }
}

/// Three poses moved, turned and scaled: the search box and the circle's
/// samples move with the task, so the best design moves with it (the
/// simplex's path differs by rounding only).
#[test]
fn three_poses_moved_give_the_moved_answer() {
    let (t, _, _) = known_task(&[0.3, 1.2, 2.0]);
    let o = slider(DesignOptions::default());
    let r = t.design(&o, &Control::new()).unwrap();
    let sim = Similarity::new(0.25, -2.0, Vector2::new(-7.0, 3.0)).unwrap();
    let t2 = t.transformed_by(&sim).unwrap();
    let r2 = t2.design(&o, &Control::new()).unwrap();
    let (d, d2) = (&r.designs[0], &r2.designs[0]);
    check_design(&t2, &o.limits, d2);
    assert!(
        (d2.score - d.score).abs() < 1e-4 * d.score.abs(),
        "{} {}",
        d.score,
        d2.score
    );
    let a = sim.point(d.linkage.driving().center);
    assert!((d2.linkage.driving().center - a).norm() < 1e-2 * t2.span());
}

#[test]
fn refusals_are_typed() {
    let (t, _, _) = known_task(&[0.3, 1.2, 2.0]);
    let with_motor = DesignOptions {
        motor: Some(burmester::design::DriveOptions::default()),
        ..slider(DesignOptions::default())
    };
    let e = t.design(&with_motor, &Control::new()).unwrap_err();
    assert_eq!(e.cause(), "driven_kind", "{e}");
    assert!(e.to_string().contains("motor"));
    let e = t
        .design_plan(&slider(DesignOptions::default()))
        .unwrap_err();
    assert_eq!(e.cause(), "driven_kind", "{e}");
    // Five poses without a slider Burmester point: the reason, typed.
    let poses = [
        Pose::new(
            1.049199280691,
            2.279426358634,
            45.220037141544f64.to_radians(),
        ),
        Pose::new(
            0.734502065472,
            3.198658887874,
            26.633426990744f64.to_radians(),
        ),
        Pose::new(
            -0.378159188147,
            3.063048993013,
            21.786789298262f64.to_radians(),
        ),
        Pose::new(
            -1.268710439724,
            2.051150142014,
            27.048624103934f64.to_radians(),
        ),
        Pose::new(
            -1.411118156972,
            0.597429126400,
            48.044287536536f64.to_radians(),
        ),
    ];
    let five = Task::new(&poses).unwrap();
    assert!(five.slider_dyads(1).unwrap().is_empty());
    let e = five
        .design(&slider(DesignOptions::default()), &Control::new())
        .unwrap_err();
    assert_eq!(e.cause(), "no_slider_point", "{e}");
}

/// Limits nothing meets: no design, the census names the limit and the
/// near misses are feasible slider-cranks.
#[test]
fn nothing_fits_reports_a_census() {
    let (t, _, _) = known_task(&[0.3, 1.2, 2.0]);
    let o = DesignOptions {
        limits: DesignLimits {
            min_transmission: 89f64.to_radians(),
            ..DesignLimits::default()
        },
        ..slider(DesignOptions::default())
    };
    let r = t.design(&o, &Control::new()).unwrap();
    assert!(r.designs.is_empty());
    assert!(r.census > 0);
    assert_eq!(r.main_rejection(), Some(burmester::Limit::Transmission));
    assert!(!r.near_misses.is_empty());
    for m in &r.near_misses {
        let sc = m.linkage.slider_crank().unwrap();
        assert!(sc.feasible());
        assert!(sc.min_transmission < o.limits.min_transmission);
    }
}

/// At the documented maxima of the coarse pass and the refinement the
/// search starts (nothing sized by the grid is held whole) and answers a
/// cancel within a second, in this unoptimised build.
#[test]
fn maxima_answer_a_cancel() {
    let (t, _, _) = known_task(&[0.3, 1.2, 2.0]);
    let o = DesignOptions {
        coarse_driven: DesignOptions::MAX_COARSE_DRIVEN,
        coarse_driving: DesignOptions::MAX_COARSE_DRIVING,
        starts: DesignOptions::MAX_STARTS,
        max_iterations: DesignOptions::MAX_ITERATIONS,
        top: DesignOptions::MAX_TOP,
        ..slider(DesignOptions::default())
    };
    let (e, latency) = common::cancelled_after(Duration::from_millis(300), |stop| {
        t.design(&o, &Control::new().with_cancel(stop)).unwrap_err()
    });
    assert_eq!(e.cause(), "cancelled");
    assert!(latency < Duration::from_secs(1), "{latency:?}");
    // Four poses at the most curve samples, cancelled in the refinement.
    let (t4, _, _) = known_task(&[0.3, 1.0, 1.8, 2.7]);
    let o4 = DesignOptions {
        coarse_pairs: DesignOptions::MAX_COARSE_PAIRS,
        ..slider(DesignOptions::default())
    };
    let stop = AtomicBool::new(false);
    let hook = |d: usize, n: usize| {
        if 10 * d > 8 * n {
            stop.store(true, Ordering::Relaxed);
        }
    };
    let e = t4
        .design(&o4, &Control::new().with_cancel(&stop).with_progress(&hook))
        .unwrap_err();
    assert_eq!(e.cause(), "cancelled");
}

/// The distance from the segment `p q` to the convex polygon `poly`
/// (0 where they meet), by another computation than the library's (which
/// tests the edges for crossings): the distance of a point to the polygon
/// (0 inside, else the least distance to an edge) is convex along the
/// segment (the distance to a convex set), so a golden-section search over
/// the segment's parameter finds its least value; the least value it
/// evaluates is returned (exactly 0 once a point inside is found).
fn segment_polygon_distance(p: Point2<f64>, q: Point2<f64>, poly: &[Point2<f64>]) -> f64 {
    let cross = |a: Vector2<f64>, b: Vector2<f64>| a.x * b.y - a.y * b.x;
    let point_seg = |x: Point2<f64>, a: Point2<f64>, b: Point2<f64>| {
        let d = b - a;
        let t = ((x - a).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
        (x - (a + d * t)).norm()
    };
    let n = poly.len();
    let inside = |x: Point2<f64>| {
        let s: Vec<f64> = (0..n)
            .map(|i| cross(poly[(i + 1) % n] - poly[i], x - poly[i]))
            .collect();
        s.iter().all(|&v| v >= 0.0) || s.iter().all(|&v| v <= 0.0)
    };
    let at = |t: f64| {
        let x = p + (q - p) * t;
        if inside(x) {
            return 0.0;
        }
        (0..n)
            .map(|i| point_seg(x, poly[i], poly[(i + 1) % n]))
            .fold(f64::INFINITY, f64::min)
    };
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut lo, mut hi) = (0.0, 1.0);
    let (mut t1, mut t2) = (1.0 - g, g);
    let (mut f1, mut f2) = (at(t1), at(t2));
    let mut least = at(0.0).min(at(1.0)).min(f1).min(f2);
    // 0.618^100 of the segment: below rounding.
    for _ in 0..100 {
        if f1 <= f2 {
            (hi, t2, f2) = (t2, t1, f1);
            t1 = hi - g * (hi - lo);
            f1 = at(t1);
        } else {
            (lo, t1, f1) = (t1, t2, f2);
            t2 = lo + g * (hi - lo);
            f2 = at(t2);
        }
        least = least.min(f1).min(f2);
    }
    least
}

/// The least distance of the crank `A0 A` and the coupler `A B` of `sc`
/// from `poly` over its travel, driven densely by the solver here.
fn dense_obstacle_distance(sc: &SynthesizedSliderCrank, poly: &[Point2<f64>]) -> f64 {
    let mode = sc.modes[0].unwrap();
    let open = mode == burmester::AssemblyMode::Open;
    let l = &sc.linkage;
    let a0 = l.crank_pivot();
    let mut least = f64::INFINITY;
    for th in sc.travel_angles(4001).unwrap() {
        let (_, _, b, _) = own_solve(sc, th, open).expect("closes over the travel");
        let a = a0 + Vector2::new(th.cos(), th.sin()) * l.crank();
        least = least
            .min(segment_polygon_distance(a0, a, poly))
            .min(segment_polygon_distance(a, b, poly));
    }
    least
}

#[test]
fn obstacles_are_checked_over_the_slider_cranks_travel() {
    // The best slider-crank without obstacles; then a square across its
    // coupler at pose 1: every design then clears the square by the links'
    // half width over its whole travel (driven densely here), and the
    // first answer, which the square strikes, is not among them.
    let (t, _, _) = known_task(&[0.3, 1.2, 2.0]);
    // Fewer, shorter refinements: each point of one checks the travel
    // against the square (slow in an unoptimised test build).
    let o = DesignOptions {
        top: 2,
        starts: 3,
        max_iterations: 200,
        ..slider(DesignOptions::default())
    };
    let free = t.design(&o, &Control::new()).unwrap();
    let first = *free.designs[0].linkage.slider_crank().unwrap();
    let mode = first.modes[0].unwrap();
    let stops = first.travel_stops().unwrap();
    let j = first.linkage.joints_at(stops[0], mode).unwrap();
    let mid = Point2::from((j.crank_joint.coords + j.slider_joint.coords) * 0.5);
    let h = 0.04 * t.span();
    let square = vec![
        mid + Vector2::new(-h, -h),
        mid + Vector2::new(h, -h),
        mid + Vector2::new(h, h),
        mid + Vector2::new(-h, h),
    ];
    assert_eq!(dense_obstacle_distance(&first, &square), 0.0, "the premise");
    let width = 0.02 * t.span();
    let o2 = DesignOptions {
        space: burmester::Space {
            obstacles: vec![square.clone()],
            link_width: width,
            ..Default::default()
        },
        ..o
    };
    let r = t.design(&o2, &Control::new()).unwrap();
    assert!(!r.designs.is_empty(), "{:?}", r.rejections);
    for d in &r.designs {
        check_design(&t, &o2.limits, d);
        let sc = d.linkage.slider_crank().unwrap();
        let gap = dense_obstacle_distance(sc, &square);
        // The library's test is exact over the travel (a bound on the
        // links' speed); the dense check here may miss the closest
        // approach between its samples by a sliver.
        assert!(gap >= 0.5 * width - 1e-6 * t.span(), "gap {gap}");
        assert!(
            (sc.driving.center - first.driving.center).norm() > 1e-6 * t.span()
                || (sc.linkage.foot() - first.linkage.foot()).norm() > 1e-6 * t.span(),
            "the struck slider-crank came back"
        );
    }
}
