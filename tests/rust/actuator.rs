//! A linear actuator added to a synthesized four-bar, against dense driving.
//!
//! Each linkage is made from a known four-bar (the task is its coupler at
//! three to five input angles), so the travel is known. The test drives the
//! built four-bar densely by its input angle (8 000 steps), places the
//! moving point on the link by its own frame (from the joints, not the
//! crate's `LinkPoint`), and computes `s = |Q - G|` and the velocity of `Q`
//! by central differences: the sign changes of the differences of `s` are
//! the turning points, the extreme lengths the stroke, and the smallest
//! angle between the actuator's line and the normal to the velocity the
//! transmission angle. The placement's figures must agree.

use std::f64::consts::{FRAC_PI_2, PI};
use std::sync::atomic::AtomicBool;

use burmester::design::{ActuatorContext, ActuatorOptions};
use burmester::{
    ActuatorLink, AssemblyMode, Constraints, Control, DegenerateError, DesignLimits, DriveError,
    Dyad, Error, FourBar, Grid, InputRange, InvalidInput, MapOptions, Point2, RankBy, Ranking,
    SynthesizedFourBar, Task, Vector2,
};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;

mod common;

type P = Point2<f64>;

fn rot(v: Vector2<f64>, a: f64) -> Vector2<f64> {
    let (s, c) = a.sin_cos();
    Vector2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// A task made from a known four-bar at `n` input angles over part of its
/// input range, and its linkage; `None` where it is not feasible.
fn known(
    fb: &FourBar,
    mode: AssemblyMode,
    from: f64,
    width: f64,
    n: usize,
) -> Option<(Task, SynthesizedFourBar)> {
    let arc = match fb.input_range() {
        InputRange::Full => (0.0, 2.0 * PI),
        InputRange::Arc(a) | InputRange::TwoArcs(a, _) => (a.start, a.span()),
    };
    let travel = (width * arc.1).min(2.0);
    let t0 = arc.0 + from * (arc.1 - travel);
    let mut poses = Vec::new();
    let mut thetas = Vec::new();
    for k in 0..n {
        let t = t0 + travel * (k as f64 / (n - 1) as f64);
        let c = fb.solve(t, mode).ok()?;
        if c.transmission_angle() < 0.15 {
            return None;
        }
        let p = fb.joints(&c).coupler_point(Vector2::new(0.6, 0.9));
        poses.push([p.x, p.y, c.theta3]);
        thetas.push(t);
    }
    let task = Task::from_xya(&poses).ok()?;
    let a1 = fb.input_pivot() + rot(Vector2::x(), thetas[0]) * fb.crank();
    let c1 = fb.joints_at(thetas[0], mode).ok()?.rocker_joint;
    let sfb = task
        .four_bar(
            &Dyad::new(fb.input_pivot(), a1),
            &Dyad::new(fb.output_pivot(), c1),
        )
        .ok()?;
    sfb.figures.feasible().then_some((task, sfb))
}

/// A random feasible linkage from a known four-bar.
fn random_linkage(runner: &mut TestRunner) -> (Task, SynthesizedFourBar) {
    loop {
        let ((l1, l2, l3, l4), (ox, oy, ga), (from, width), crossed, n) = (
            (1.0f64..4.0, 0.5f64..3.0, 0.5f64..3.5, 0.5f64..3.0),
            (-2.0f64..2.0, -2.0f64..2.0, -PI..PI),
            (0.0f64..1.0, 0.2f64..0.8),
            any::<bool>(),
            3usize..=5,
        )
            .new_tree(runner)
            .unwrap()
            .current();
        let Ok(fb) = FourBar::placed(l1, l2, l3, l4, Point2::new(ox, oy), ga) else {
            continue;
        };
        let mode = if crossed {
            AssemblyMode::Crossed
        } else {
            AssemblyMode::Open
        };
        if let Some(found) = known(&fb, mode, from, width, n) {
            return found;
        }
    }
}

/// The test's own point of `link` at input angle `t`: fixed in the link's
/// frame taken from the joints at `t0`.
struct Own {
    fb: FourBar,
    mode: AssemblyMode,
    link: ActuatorLink,
    local: Vector2<f64>,
}

impl Own {
    fn frame(&self, t: f64) -> (P, f64) {
        let c = self.fb.solve(t, self.mode).unwrap();
        let j = self.fb.joints(&c);
        match self.link {
            ActuatorLink::Crank => (
                j.input_pivot,
                (j.crank_joint - j.input_pivot)
                    .y
                    .atan2((j.crank_joint - j.input_pivot).x),
            ),
            ActuatorLink::Coupler => {
                let d = j.rocker_joint - j.crank_joint;
                (j.crank_joint, d.y.atan2(d.x))
            }
            ActuatorLink::Rocker => {
                let d = j.rocker_joint - j.output_pivot;
                (j.output_pivot, d.y.atan2(d.x))
            }
        }
    }
    fn new(sfb: &SynthesizedFourBar, link: ActuatorLink, q: P) -> Self {
        let mode = sfb.modes()[0].unwrap();
        let mut o = Own {
            fb: sfb.fourbar,
            mode,
            link,
            local: Vector2::zeros(),
        };
        let (origin, a) = o.frame(sfb.travel_stops().unwrap()[0]);
        o.local = rot(q - origin, -a);
        o
    }
    fn at(&self, t: f64) -> P {
        let (origin, a) = self.frame(t);
        origin + rot(self.local, a)
    }
}

/// What dense driving finds for the ground pivot `g`.
struct Dense {
    turning: Vec<f64>,
    s_min: f64,
    s_max: f64,
    mu_min: f64,
    step: f64,
}

fn dense(sfb: &SynthesizedFourBar, own: &Own, g: P, steps: usize) -> Dense {
    let (start, span) = sfb.travel().unwrap();
    let h = 1e-6 * span.signum();
    let mut s = Vec::with_capacity(steps + 1);
    let mut mu_min = f64::INFINITY;
    for k in 0..=steps {
        let t = start + span * k as f64 / steps as f64;
        let q = own.at(t);
        let d = q - g;
        s.push(d.norm());
        let v = (own.at(t + h) - own.at(t - h)) / (2.0 * h);
        let beta = (d.x * v.y - d.y * v.x).abs().atan2(d.dot(&v).abs());
        mu_min = mu_min.min(FRAC_PI_2 - beta);
    }
    let mut turning = Vec::new();
    for k in 1..steps {
        let (a, b) = (s[k] - s[k - 1], s[k + 1] - s[k]);
        if a * b < 0.0 {
            turning.push(start + span * k as f64 / steps as f64);
        }
    }
    // The extreme lengths refined by ternary search about the extreme
    // samples (the samples alone are off by the square of the step).
    let angle = |k: usize| start + span * k.min(steps) as f64 / steps as f64;
    let refine = |sign: f64| {
        let k = (0..=steps)
            .max_by(|&a, &b| (sign * s[a]).total_cmp(&(sign * s[b])))
            .unwrap();
        let f = |t: f64| sign * (own.at(t) - g).norm();
        let (mut lo, mut hi) = (angle(k.saturating_sub(1)), angle(k + 1));
        for _ in 0..100 {
            let (a, b) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
            if f(a) < f(b) {
                lo = a;
            } else {
                hi = b;
            }
        }
        (own.at(0.5 * (lo + hi)) - g).norm()
    };
    let s_max = refine(1.0).max(s.iter().copied().fold(0.0, f64::max));
    let s_min = refine(-1.0).min(s.iter().copied().fold(f64::INFINITY, f64::min));
    Dense {
        turning,
        s_min,
        s_max,
        mu_min,
        step: (span / steps as f64).abs(),
    }
}

fn context(sfb: &SynthesizedFourBar, link: ActuatorLink, q: P, grid: &Grid) -> ActuatorContext {
    let options = ActuatorOptions {
        link,
        ..ActuatorOptions::default()
    };
    ActuatorContext::new(
        sfb,
        q,
        grid,
        &MapOptions::new(&DesignLimits::default(), &Constraints::none()).unwrap(),
        &options,
    )
    .unwrap()
}

/// A random moving point about the crank joint `A` (within `r` along
/// each axis) and ground pivot about `c` (within `2 r`).
fn point_and_pivot(runner: &mut TestRunner, sfb: &SynthesizedFourBar, c: P, r: f64) -> (P, P) {
    let (qx, qy, gx, gy) = (-1.0f64..1.0, -1.0f64..1.0, -2.0f64..2.0, -2.0f64..2.0)
        .new_tree(runner)
        .unwrap()
        .current();
    let q = sfb.driving.circle + Vector2::new(qx, qy) * r;
    (q, c + Vector2::new(gx, gy) * r)
}

/// The context of the one ground pivot `g` under `constraints`.
fn single(
    sfb: &SynthesizedFourBar,
    link: ActuatorLink,
    q: P,
    g: P,
    constraints: &Constraints,
) -> ActuatorContext {
    single_strut(sfb, link, (q, g), (0.0, 0.0), constraints)
}

/// [`single`] with a strut `width` wide that must keep `min_gap`.
fn single_strut(
    sfb: &SynthesizedFourBar,
    link: ActuatorLink,
    (q, g): (P, P),
    (width, min_gap): (f64, f64),
    constraints: &Constraints,
) -> ActuatorContext {
    let options = ActuatorOptions {
        link,
        actuator_width: width,
        min_gap,
        ..ActuatorOptions::default()
    };
    let limits = DesignLimits::default();
    ActuatorContext::new(
        sfb,
        q,
        &one_grid(g),
        &MapOptions::new(&limits, constraints).unwrap(),
        &options,
    )
    .unwrap()
}

fn one_grid(p: P) -> Grid {
    Grid::from_bounds(p.x - 1.0, p.x + 1.0, p.y - 1.0, p.y + 1.0, 1, 1).unwrap()
}

/// Placements at random ground pivots agree with dense driving: the
/// monotone verdict and the turning points, the stroke, the transmission
/// angle.
#[test]
fn placements_agree_with_dense_driving() {
    let mut runner = TestRunner::new(common::config(1));
    let (mut checked, mut turning, mut monotone) = (0, 0, 0);
    for case in 0..40 {
        let (task, sfb) = random_linkage(&mut runner);
        let link = ActuatorLink::ALL[case % 3];
        let c = common::centroid(task.poses());
        let r = task.span();
        for _ in 0..5 {
            let (q, g) = point_and_pivot(&mut runner, &sfb, c, r);
            let ctx = context(&sfb, link, q, &one_grid(g));
            let Ok(a) = ctx.placement(g) else { continue };
            let own = Own::new(&sfb, link, q);
            let d = dense(&sfb, &own, g, 8_000);
            // Pairs of turning points closer than the placement's sampling
            // are documented as possibly missed.
            let sampled = ctx.travel_angles()[1] - ctx.travel_angles()[0];
            let close = d
                .turning
                .windows(2)
                .any(|w| (w[1] - w[0]).abs() < 2.0 * sampled.abs());
            if close {
                continue;
            }
            checked += 1;
            assert_eq!(
                a.monotone,
                d.turning.is_empty(),
                "case {case}: {:?} vs {:?}",
                a.turning_points,
                d.turning
            );
            assert_eq!(a.turning_points.len(), d.turning.len());
            for (x, y) in a.turning_points.iter().zip(&d.turning) {
                assert!((x - y).abs() <= 2.0 * d.step, "turning point {x} vs {y}");
            }
            if a.monotone {
                monotone += 1;
            } else {
                turning += 1;
                assert_eq!(a.min_transmission, 0.0);
            }
            let tol = 1e-7 * d.s_max;
            assert!(
                (a.min_length - d.s_min).abs() < tol,
                "{} {}",
                a.min_length,
                d.s_min
            );
            assert!((a.max_length - d.s_max).abs() < tol);
            assert!((a.stroke_ratio - d.s_max / d.s_min).abs() < 1e-6 * a.stroke_ratio);
            if a.monotone {
                assert!(
                    (a.min_transmission - d.mu_min).abs() < 1e-5,
                    "mu {} vs dense {}",
                    a.min_transmission,
                    d.mu_min
                );
            }
            // Not monotone: the length turns back where the line is normal
            // to the velocity, or where the point stops (a rocker at its
            // limit position); the placement's minimum is 0 by definition.
            // The lengths at the poses are exact.
            for (k, &t) in sfb.travel_stops().unwrap().iter().enumerate() {
                assert!(((own.at(t) - g).norm() - a.pose_lengths[k]).abs() < 1e-9 * d.s_max);
            }
            // Extending: the last pose's length is the longer.
            if a.monotone {
                let l = a.pose_lengths;
                assert_eq!(a.extends, l[l.len() - 1] > l[0]);
            }
        }
    }
    assert!(
        checked >= 150 && turning >= 20 && monotone >= 20,
        "{checked} {turning} {monotone}"
    );
}

/// A ground pivot on the line through `Q` normal to its velocity at an
/// interior pose makes `ds/dtheta2` vanish there: not monotone, with the
/// turning point at that pose.
#[test]
fn a_pivot_on_the_normal_at_an_interior_pose_is_not_monotone() {
    let mut runner = TestRunner::new(common::config(1));
    let mut n = 0;
    while n < 30 {
        let (task, sfb) = random_linkage(&mut runner);
        let stops = sfb.travel_stops().unwrap();
        let link = ActuatorLink::ALL[n % 3];
        let q = sfb.driving.circle
            + (sfb.driven.circle - sfb.driving.circle) * 0.4
            + Vector2::new(0.0, 0.3 * task.span());
        let probe = context(&sfb, link, q, &one_grid(q));
        let lp = probe
            .placement(q + Vector2::new(10.0, 10.0) * task.span())
            .unwrap();
        let tm = stops[1];
        let (qm, _) = lp.at(tm).unwrap();
        let (_, v) = lp.link_point().at(tm).unwrap();
        if v.norm() < 1e-3 * task.span() {
            continue;
        }
        let normal = Vector2::new(-v.y, v.x) / v.norm();
        for t in [0.8, -0.8] {
            let g = qm + normal * t * task.span();
            let a = probe.placement(g).unwrap();
            assert!(!a.monotone);
            assert_eq!(a.min_transmission, 0.0);
            let near = a.turning_points.iter().any(|x| (x - tm).abs() < 1e-9);
            assert!(near, "{:?} vs {tm}", a.turning_points);
        }
        n += 1;
    }
}

/// The map's samples are the placements' sampled figures; the best
/// placements are acceptable, monotone, in order and apart.
#[test]
fn map_and_ranking_agree_with_placements() {
    let mut runner = TestRunner::new(common::config(1));
    let mut ranked = 0;
    for case in 0..8 {
        let (task, sfb) = random_linkage(&mut runner);
        let link = ActuatorLink::ALL[case % 3];
        let q = sfb.driving.circle + (sfb.driven.circle - sfb.driving.circle) * 0.5;
        let c = common::centroid(task.poses());
        let r = 2.0 * task.span();
        let grid = Grid::from_bounds(c.x - r, c.x + r, c.y - r, c.y + r, 40, 30).unwrap();
        let limits = DesignLimits {
            min_transmission: 20f64.to_radians(),
            ..DesignLimits::default()
        };
        let options = ActuatorOptions {
            link,
            max_stroke_ratio: 2.5,
            ..ActuatorOptions::default()
        };
        let ctx = ActuatorContext::new(
            &sfb,
            q,
            &grid,
            &MapOptions::new(&limits, &Constraints::none()).unwrap(),
            &options,
        )
        .unwrap();
        let map = ctx.map(&Control::new()).unwrap();
        let cols = &map.columns;
        for k in (0..grid.len()).step_by(29) {
            let Ok(a) = ctx.placement_at(k) else {
                assert!(!cols.valid[k]);
                continue;
            };
            assert!(cols.valid[k]);
            assert_eq!(cols.monotone[k], a.monotone);
            assert_eq!(cols.extends[k], a.extends);
            // Refined: never above the sampled minimum.
            assert!(a.min_transmission <= f64::from(cols.min_transmission_rad[k]) + 1e-6);
            if a.monotone {
                assert!(
                    (f64::from(cols.stroke_ratio[k]) - a.stroke_ratio).abs()
                        < 1e-5 * a.stroke_ratio
                );
                assert!(
                    (f64::from(cols.closed_length[k]) - a.min_length).abs() < 1e-5 * a.max_length
                );
            }
        }
        for rank_by in [RankBy::Balanced, RankBy::Transmission, RankBy::Compact] {
            let best = map.best_placements(Ranking::new(5, rank_by)).unwrap();
            for w in best.windows(2) {
                assert!(w[0].score >= w[1].score);
                assert!((w[0].ground - w[1].ground).norm() >= 0.02 * grid.viewport().diagonal());
            }
            for a in &best {
                ranked += 1;
                assert!(a.monotone && a.acceptable, "{a:?}");
                assert!(a.stroke_ratio <= 2.5 + 1e-9);
                let (j, i) = a.index.unwrap();
                assert!(map.columns.acceptable[j * grid.nx() + i]);
            }
        }
        let margin = map
            .best_placements(Ranking::new(3, RankBy::Margin))
            .unwrap();
        assert!(margin.iter().all(|a| a.monotone && a.margin > 0.0));
    }
    assert!(ranked > 0);
}

/// Moving, rotating and scaling the linkage, the point, the pivot and the
/// obstacle keeps every figure (lengths, the clearance among them, scale).
#[test]
fn figures_are_invariant_under_similarities() {
    let mut runner = TestRunner::new(common::config(1));
    for case in 0..20 {
        let (task, sfb) = random_linkage(&mut runner);
        let link = ActuatorLink::ALL[case % 3];
        let (sx, sy, sa, ss, gx, gy) = (
            -5.0f64..5.0,
            -5.0f64..5.0,
            -PI..PI,
            0.1f64..10.0,
            -1.5f64..1.5,
            -1.5f64..1.5,
        )
            .new_tree(&mut runner)
            .unwrap()
            .current();
        let map = |p: P| Point2::from(rot(p.coords, sa) * ss + Vector2::new(sx, sy));
        let q = sfb.driving.circle + (sfb.driven.circle - sfb.driving.circle) * 0.3;
        let g = common::centroid(task.poses()) + Vector2::new(gx, gy) * task.span();
        let (_, sfb2) = common::moved_linkage(&task, &sfb, map, sa);
        // An obstacle and a link width, moved and scaled with the rest:
        // the strut's clearance scales, its verdict stays.
        let c = common::centroid(task.poses());
        let h = 0.2 * task.span();
        let obstacle = [(-h, 0.0), (h, 0.0), (0.0, h)].map(|(x, y)| c + Vector2::new(x, y));
        let place = |s: &SynthesizedFourBar, q: P, g: P, o: Vec<P>, w: f64| {
            let c = Constraints {
                obstacles: vec![o],
                link_width: w,
                ..Constraints::none()
            };
            // The strut twice as wide as the links.
            single_strut(s, link, (q, g), (2.0 * w, 0.0), &c)
                .placement(g)
                .unwrap()
        };
        let w = 0.01 * task.span();
        let a = place(&sfb, q, g, obstacle.to_vec(), w);
        let b = place(&sfb2, map(q), map(g), obstacle.map(map).to_vec(), w * ss);
        assert_eq!(
            a.clear, b.clear,
            "{} vs {}",
            a.min_clearance, b.min_clearance
        );
        let gap = a.min_clearance * ss - b.min_clearance;
        assert!(gap.abs() < 1e-6 * ss * task.span(), "{gap}");
        assert_eq!(a.monotone, b.monotone);
        assert_eq!(a.turning_points.len(), b.turning_points.len());
        assert!((a.stroke_ratio - b.stroke_ratio).abs() < 1e-9 * a.stroke_ratio);
        assert!((a.stroke * ss - b.stroke).abs() < 1e-8 * b.max_length);
        assert!((a.min_transmission - b.min_transmission).abs() < 1e-7);
        assert!((a.size_ratio - b.size_ratio).abs() < 1e-9 * a.size_ratio);
        assert!((a.link_ratio - b.link_ratio).abs() < 1e-9 * a.link_ratio);
    }
}

/// Bad input: typed errors saying what to change.
#[test]
fn bad_input_gives_typed_errors() {
    let mut runner = TestRunner::new(common::config(1));
    let (task, sfb) = random_linkage(&mut runner);
    let q = sfb.driven.circle;
    let g = one_grid(common::centroid(task.poses()));
    let limits = DesignLimits::default();
    let none = Constraints::none();
    let new = |o: &ActuatorOptions, c: &Constraints| {
        MapOptions::new(&limits, c).and_then(|m| ActuatorContext::new(&sfb, q, &g, &m, o))
    };
    // The default options and no constraints, for another linkage or point.
    let map_options = MapOptions::new(&limits, &none).unwrap();
    let plain = |s: &SynthesizedFourBar, p: P| {
        ActuatorContext::new(s, p, &g, &map_options, &ActuatorOptions::default())
    };
    let bad = ActuatorOptions {
        max_stroke_ratio: 0.5,
        ..ActuatorOptions::default()
    };
    assert!(matches!(
        new(&bad, &none),
        Err(Error::InvalidInput(InvalidInput::OutsideRange {
            name: "max_stroke_ratio",
            ..
        }))
    ));
    let bad = ActuatorOptions {
        max_stroke_ratio: f64::NAN,
        ..ActuatorOptions::default()
    };
    assert!(new(&bad, &none).is_err());
    // A negative or non-finite strut width or least gap: refused by name,
    // the message saying what to pass.
    for v in [-1.0, f64::NAN, f64::INFINITY] {
        for (bad, name) in [
            (
                ActuatorOptions {
                    actuator_width: v,
                    ..ActuatorOptions::default()
                },
                "actuator_width",
            ),
            (
                ActuatorOptions {
                    min_gap: v,
                    ..ActuatorOptions::default()
                },
                "min_gap",
            ),
        ] {
            let e = new(&bad, &none).unwrap_err();
            assert!(
                matches!(&e, Error::InvalidInput(InvalidInput::OutsideRange { name: n, .. }) if *n == name),
                "{e:?}"
            );
            let m = e.to_string();
            assert!(
                m.contains(name) && m.contains("pass a value in that range"),
                "{m}"
            );
        }
    }
    for n in [2, ActuatorOptions::MAX_TRAVEL_SAMPLES + 1] {
        let bad = ActuatorOptions {
            travel_samples: n,
            ..ActuatorOptions::default()
        };
        assert!(matches!(
            new(&bad, &none),
            Err(Error::InvalidInput(InvalidInput::CountOutOfRange { .. }))
        ));
    }
    // Obstacles are taken (the strut's clearance); one without an area
    // is refused by name.
    let obstacles = Constraints {
        obstacles: vec![vec![P::new(0.0, 0.0), P::new(1.0, 0.0), P::new(0.0, 1.0)]],
        ..Constraints::none()
    };
    assert!(new(&ActuatorOptions::default(), &obstacles).is_ok());
    let flat = Constraints {
        obstacles: vec![vec![P::new(0.0, 0.0), P::new(1.0, 0.0), P::new(2.0, 0.0)]],
        ..Constraints::none()
    };
    let e = new(&ActuatorOptions::default(), &flat).unwrap_err();
    assert!(
        matches!(e, Error::InvalidInput(InvalidInput::Polygon { .. })),
        "{e}"
    );
    assert!(e.to_string().contains("obstacle 1"), "{e}");
    // A point on the crank's fixed pivot does not move.
    let crank = ActuatorOptions {
        link: ActuatorLink::Crank,
        ..ActuatorOptions::default()
    };
    let e = ActuatorContext::new(&sfb, sfb.driving.center, &g, &map_options, &crank).unwrap_err();
    assert!(
        matches!(e, Error::Degenerate(DegenerateError::ZeroLengthLink { .. })),
        "{e}"
    );
    let nan = plain(&sfb, P::new(f64::NAN, 0.0));
    assert!(matches!(
        nan,
        Err(Error::InvalidInput(InvalidInput::NotFinite { .. }))
    ));
    // The ground pivot on the point's path: no actuator.
    let ctx = new(&ActuatorOptions::default(), &none).unwrap();
    let e = ctx.placement(q).unwrap_err();
    assert!(
        matches!(e, Error::Degenerate(DegenerateError::ZeroLengthLink { .. })),
        "{e}"
    );
    assert!(ctx.placement(P::new(f64::INFINITY, 0.0)).is_err());
    // An infeasible linkage: the four-bar's own verdict stands.
    let mut infeasible = sfb;
    infeasible.figures.one_circuit = false;
    let e = plain(&infeasible, q).unwrap_err();
    assert_eq!(e, Error::Drive(DriveError::NoTravel));
    // A negative separation is refused where the ranking is made, before
    // any map is ranked.
    assert!(matches!(
        Ranking::new(1, RankBy::Balanced).with_separation(-1.0),
        Err(Error::InvalidInput(InvalidInput::OutsideRange { .. }))
    ));
}

/// The documented maximum grid is mapped; one more row is refused; a
/// cancelled map stops.
#[test]
fn documented_maximum_grid_and_cancelling() {
    let mut runner = TestRunner::new(common::config(1));
    let (task, sfb) = random_linkage(&mut runner);
    let c = common::centroid(task.poses());
    let r = 2.0 * task.span();
    let options = ActuatorOptions {
        travel_samples: ActuatorOptions::MIN_TRAVEL_SAMPLES,
        ..ActuatorOptions::default()
    };
    let side = 1024;
    assert_eq!(side * side, ActuatorContext::MAX_GRID_SAMPLES);
    let grid = Grid::from_bounds(c.x - r, c.x + r, c.y - r, c.y + r, side, side).unwrap();
    // The middle of the coupler's A C: it does not stop over the travel
    // (C does where the rocker reverses).
    let q = sfb.driving.circle + (sfb.driven.circle - sfb.driving.circle) * 0.5;
    let limits = DesignLimits::default();
    let none = Constraints::none();
    let map_options = MapOptions::new(&limits, &none).unwrap();
    let ctx = ActuatorContext::new(&sfb, q, &grid, &map_options, &options).unwrap();
    let map = ctx.map(&Control::new()).unwrap();
    assert_eq!(map.columns.valid.len(), side * side);
    let valid = map.columns.valid.iter().filter(|&&m| m).count();
    let mono = map.columns.monotone.iter().filter(|&&m| m).count();
    assert!(
        mono > 0,
        "{valid} valid, {mono} monotone of {}",
        side * side
    );
    assert!(map.columns.monotone.iter().any(|&m| !m));
    // The clearance is there only where the actuator is monotone, and
    // wherever it is acceptable.
    let cols = &map.columns;
    for k in 0..side * side {
        assert!(!cols.clearance[k].is_finite() || cols.monotone[k], "{k}");
        assert!(!cols.acceptable[k] || cols.clearance[k] > 0.0, "{k}");
    }
    let big = Grid::from_bounds(c.x - r, c.x + r, c.y - r, c.y + r, side, side + 1).unwrap();
    assert!(matches!(
        ActuatorContext::new(&sfb, q, &big, &map_options, &options),
        Err(Error::InvalidInput(InvalidInput::GridSize { .. }))
    ));
    let stop = AtomicBool::new(true);
    let e = ctx.map(&Control::new().with_cancel(&stop)).unwrap_err();
    assert!(matches!(e, Error::Cancelled { .. }));
    // The most travel samples.
    let most = ActuatorOptions {
        travel_samples: ActuatorOptions::MAX_TRAVEL_SAMPLES,
        ..ActuatorOptions::default()
    };
    let one = one_grid(c);
    let a = ActuatorContext::new(&sfb, q, &one, &map_options, &most)
        .unwrap()
        .placement(c + Vector2::new(0.0, -r))
        .unwrap();
    assert!(a.max_length > 0.0);
}

// The strut's clearance and the one-call design with an actuator.

/// The test's own gap of the strut `G Q(t)` at input angle `t`: the links
/// from the test's own joints, the distances by parry's segment query (the
/// crate measures with its own closed form), a crossing of the link that
/// carries `Q` by solving the two lines' intersection, an obstacle's
/// distance from its edges and a containment test by winding; the
/// strut's and the links' half widths taken off (`width`: the links', the
/// strut's).
fn own_gap(
    sfb: &SynthesizedFourBar,
    own: &Own,
    g: P,
    t: f64,
    width: (f64, f64),
    obstacles: &[Vec<P>],
) -> f64 {
    use parry2d_f64::math::{Pose, Vector as V};
    use parry2d_f64::query::distance;
    use parry2d_f64::shape::Segment;
    let seg = |a: P, b: P| Segment::new(V::new(a.x, a.y), V::new(b.x, b.y));
    let dist = |a: (P, P), b: (P, P)| {
        distance(
            &Pose::identity(),
            &seg(a.0, a.1),
            &Pose::identity(),
            &seg(b.0, b.1),
        )
        .unwrap()
        .distance
    };
    let c = sfb.fourbar.solve(t, own.mode).unwrap();
    let j = sfb.fourbar.joints(&c);
    let q = own.at(t);
    let (r, rs) = (0.5 * width.0, 0.5 * width.1);
    let mut gap = f64::INFINITY;
    for (link, a, b) in [
        (ActuatorLink::Crank, j.input_pivot, j.crank_joint),
        (ActuatorLink::Coupler, j.crank_joint, j.rocker_joint),
        (ActuatorLink::Rocker, j.output_pivot, j.rocker_joint),
    ] {
        // Q on the link (its own, or one joined to it at Q): a crossing
        // away from Q only.
        let ab = b - a;
        let along = ((q - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
        let on = (q - (a + ab * along)).norm() <= 1e-9 * sfb.fourbar.lengths()[0].max(ab.norm());
        if link == own.link || on {
            // G + u (Q - G) = A + v (B - A), u in [0, 1) away from Q.
            let (d, e) = (q - g, b - a);
            let det = d.x * -e.y - d.y * -e.x;
            if det.abs() > 1e-15 {
                let w = a - g;
                let u = (w.x * -e.y - w.y * -e.x) / det;
                let v = (d.x * w.y - d.y * w.x) / det;
                if (0.0..1.0 - 1e-6).contains(&u) && (0.0..=1.0).contains(&v) {
                    gap = gap.min(-(r + rs));
                }
            }
        } else {
            gap = gap.min(dist((g, q), (a, b)) - r - rs);
        }
    }
    for o in obstacles {
        let inside = |p: P| {
            let mut wind = 0.0;
            for k in 0..o.len() {
                let (a, b) = (o[k] - p, o[(k + 1) % o.len()] - p);
                wind += (a.x * b.y - a.y * b.x).atan2(a.dot(&b));
            }
            wind.abs() > PI
        };
        let mut d = (0..o.len())
            .map(|k| dist((g, q), (o[k], o[(k + 1) % o.len()])))
            .fold(f64::INFINITY, f64::min);
        if inside(g) || inside(q) {
            d = 0.0;
        }
        gap = gap.min(d - rs);
    }
    gap
}

/// The smallest of `f(t)` over `steps` of the travel of `sfb` (both ends
/// included): dense driving, for [`own_gap`].
fn least_over_travel(sfb: &SynthesizedFourBar, steps: usize, f: impl Fn(f64) -> f64) -> f64 {
    let (start, span) = sfb.travel().unwrap();
    (0..=steps)
        .map(|k| f(start + span * k as f64 / steps as f64))
        .fold(f64::INFINITY, f64::min)
}

/// A placement's clearance agrees with dense driving (8 000 steps, the
/// test's own frame and distances), with and without an obstacle, a link
/// width and a strut width (each drawn on its own): the smallest gap to a
/// part of the sample step's motion, the verdict wherever the gap is not
/// within that of zero.
#[test]
fn clearance_agrees_with_dense_driving() {
    let mut runner = TestRunner::new(common::config(1));
    let (mut checked, mut verdicts, mut crossing) = (0, [0usize; 2], 0);
    for case in 0..30 {
        let (task, sfb) = random_linkage(&mut runner);
        let link = ActuatorLink::ALL[case % 3];
        let c = common::centroid(task.poses());
        let r = task.span();
        let (ox, oy, w, ws) = (-1.5f64..1.5, -1.5f64..1.5, 0.0f64..0.05, 0.0f64..0.08)
            .new_tree(&mut runner)
            .unwrap()
            .current();
        let o = c + Vector2::new(ox, oy) * r;
        let h = 0.15 * r;
        let obstacles = if case % 2 == 0 {
            vec![vec![
                o + Vector2::new(-h, -h),
                o + Vector2::new(h, -h),
                o + Vector2::new(0.0, h),
            ]]
        } else {
            Vec::new()
        };
        let width = if case % 3 == 0 { w * r } else { 0.0 };
        let strut = if case % 5 < 3 { ws * r } else { 0.0 };
        let constraints = Constraints {
            obstacles: obstacles.clone(),
            link_width: width,
            ..Constraints::none()
        };
        for _ in 0..5 {
            let (q, g) = point_and_pivot(&mut runner, &sfb, c, r);
            let ctx = single_strut(&sfb, link, (q, g), (strut, 0.0), &constraints);
            let Ok(a) = ctx.placement(g) else { continue };
            let own = Own::new(&sfb, link, q);
            let gap = |t| own_gap(&sfb, &own, g, t, (width, strut), &obstacles);
            let d = least_over_travel(&sfb, 8_000, gap);
            // How far a point of the strut or a link moves in a step of
            // the placement's sampling, bounded from dense samples.
            let step = (ctx.travel_angles()[1] - ctx.travel_angles()[0]).abs();
            let moves = 4.0 * step * r * (1.0 + 1.0 / sfb.figures.min_transmission.sin().max(0.1));
            checked += 1;
            assert_eq!(a.clear, a.min_clearance > 0.0);
            // The refined gap is a gap at some angle: never below the
            // true minimum, which dense driving approaches from above.
            if d.abs() > moves {
                assert_eq!(
                    a.clear,
                    d > 0.0,
                    "case {case}: {} vs dense {d}",
                    a.min_clearance
                );
            }
            if d > -0.5 * (width + strut) + 1e-12 {
                assert!(
                    a.min_clearance <= d + 1e-9 * r && a.min_clearance >= d - moves,
                    "case {case}: {} vs dense {d} (moves {moves})",
                    a.min_clearance
                );
            } else {
                crossing += 1;
                assert!(a.min_clearance <= -0.5 * (width + strut) + 1e-12 || !a.clear);
            }
            verdicts[usize::from(a.clear)] += 1;
        }
    }
    // Both verdicts are met often: [blocked, clear].
    let enough = checked >= 100 && verdicts.iter().all(|&n| n >= 10);
    assert!(enough, "{checked} {verdicts:?} {crossing}");
}

/// A strut through its own link: the rocker's pin at the rocker's middle
/// and the ground pivot beyond the rocker's tip on its line crosses the
/// rocker's bar.
#[test]
fn a_strut_through_its_own_link_is_not_clear() {
    let mut runner = TestRunner::new(common::config(1));
    let linkages: Vec<_> = (0..10).map(|_| random_linkage(&mut runner).1).collect();
    for sfb in linkages {
        let (c0, c1) = (sfb.driven.center, sfb.driven.circle);
        let q = c0 + (c1 - c0) * 0.5;
        // G on the far side of C0, on the rocker's line at pose 1: the
        // strut runs along the bar through C0 there.
        let g = c0 - (c1 - c0) * 0.7;
        let ctx = single(&sfb, ActuatorLink::Rocker, q, g, &Constraints::none());
        let a = ctx.placement(g).unwrap();
        assert!(!a.clear && a.min_clearance <= 0.0, "{}", a.min_clearance);
    }
}

/// The hood of `examples/hood.toml` in millimetres, and its design
/// options.
fn hood() -> (Task, burmester::DesignOptions) {
    let task = Task::from_xya(&[
        [0.0, 0.0, 0.0],
        [-25.0, 45.0, 30f64.to_radians()],
        [-40.0, 80.0, 60f64.to_radians()],
    ])
    .unwrap();
    let limits = DesignLimits {
        min_transmission: 40f64.to_radians(),
        max_link_ratio: 10.0,
        input: burmester::InputRequirement::Any,
        min_grashof_margin: 0.01,
        max_size_ratio: 8.0,
        ..DesignLimits::default()
    };
    let options = burmester::DesignOptions {
        limits,
        space: burmester::Space {
            pivots: burmester::PivotRegion::boxed(-150.0, 50.0, -100.0, 0.0).unwrap(),
            ..burmester::Space::default()
        },
        top: 3,
        starts: 12,
        actuator: Some(burmester::ActuatorSearch::default()),
        ..burmester::DesignOptions::default()
    };
    (task, options)
}

/// The one-call design with an actuator, on the hood: every design
/// carries an actuator whose verdicts dense driving of the built linkage
/// and strut confirms (monotone, stroke ratio, transmission, clearance,
/// the ground pivot on the pivot region), and the linkage is the
/// design's.
#[test]
fn the_design_places_a_clear_actuator_on_every_design() {
    let (task, options) = hood();
    let report = task.design(&options, &Control::new()).unwrap();
    assert!(!report.designs.is_empty(), "{:?}", report.rejections);
    assert_eq!(report.actuator, options.actuator);
    for d in &report.designs {
        let a = d.actuator.as_ref().expect("every design has its actuator");
        assert_eq!(&a.linkage, d.linkage.four_bar().unwrap());
        assert!(a.monotone && a.acceptable && a.clear, "{a:?}");
        assert!(options.space.pivots.contains(a.ground));
        let fb = d.linkage.four_bar().unwrap();
        let own = Own::new(fb, a.link, a.point);
        let dense = dense(fb, &own, a.ground, 8_000);
        assert!(dense.turning.is_empty());
        assert!(
            dense.s_max / dense.s_min <= 1.8 + 1e-6,
            "{}",
            dense.s_max / dense.s_min
        );
        assert!((a.stroke_ratio - dense.s_max / dense.s_min).abs() < 1e-6);
        assert!(dense.mu_min >= options.limits.min_transmission - 1e-5);
        let gap = least_over_travel(fb, 8_000, |t| {
            own_gap(fb, &own, a.ground, t, (0.0, 0.0), &[])
        });
        assert!(
            gap > 0.0 && (gap - a.min_clearance).abs() < 1e-3 * task.span(),
            "dense {gap} vs {} at Q {:?}",
            a.min_clearance,
            a.point
        );
    }
    // The same design without the actuator ranks the same linkages first
    // where they have an actuator (the actuator only filters).
    let plain = burmester::DesignOptions {
        actuator: None,
        ..options.clone()
    };
    let bare = task.design(&plain, &Control::new()).unwrap();
    assert!(bare.designs[0].actuator.is_none());
    assert_eq!(bare.unplaced, 0);
    if report.unplaced == 0 {
        assert_eq!(bare.designs[0].linkage, report.designs[0].linkage);
    }
}

/// The design's actuator options: the documented maximum of ground-pivot
/// samples is searched, one more refused; a motor and an actuator together
/// are refused; a cancelled placement search stops.
#[test]
fn design_actuator_options_at_their_limits() {
    let (task, mut options) = hood();
    options.top = 1;
    options.starts = 2;
    options.actuator = Some(burmester::ActuatorSearch {
        samples: burmester::ActuatorSearch::MAX_SAMPLES,
        point: Some(P::new(-40.0, -20.0)),
        options: ActuatorOptions {
            travel_samples: ActuatorOptions::MIN_TRAVEL_SAMPLES,
            ..ActuatorOptions::default()
        },
        max_size_ratio: None,
    });
    let report = task.design(&options, &Control::new()).unwrap();
    for d in &report.designs {
        assert!(
            d.actuator
                .as_ref()
                .is_some_and(|a| a.clear && a.point == P::new(-40.0, -20.0))
        );
    }
    let mut over = options.clone();
    over.actuator.as_mut().unwrap().samples = burmester::ActuatorSearch::MAX_SAMPLES + 1;
    assert!(matches!(
        task.design(&over, &Control::new()),
        Err(Error::InvalidInput(InvalidInput::CountOutOfRange { .. }))
    ));
    let mut both = options.clone();
    both.motor = Some(burmester::design::DriveOptions::default());
    let e = task.design(&both, &Control::new()).unwrap_err();
    assert!(e.to_string().contains("not both"), "{e}");
    let stop = AtomicBool::new(true);
    let r = task.design(&options, &Control::new().with_cancel(&stop));
    assert!(matches!(r, Err(Error::Cancelled { .. })), "{r:?}");
}

/// The hood as `examples/hood.toml` gives it to `burmester design
/// --input actuator`: its file's size limit 5, its 10 mm links, its 20 mm
/// strut keeping 3 mm on the bracket point `(-40, -20)`, one design asked.
fn hood_on_its_bracket() -> (Task, burmester::DesignOptions) {
    let (task, mut options) = hood();
    options.limits.max_size_ratio = 5.0;
    options.space.link_width = 10.0;
    options.top = 1;
    options.actuator = Some(burmester::ActuatorSearch {
        point: Some(P::new(-40.0, -20.0)),
        options: ActuatorOptions {
            actuator_width: 20.0,
            min_gap: 3.0,
            ..ActuatorOptions::default()
        },
        ..burmester::ActuatorSearch::default()
    });
    (task, options)
}

/// The strut stage's own size bound (`ActuatorSearch::max_size_ratio`,
/// the task file's `[actuator] max_size_ratio`): on the hood's bracket no
/// hinge takes a strut under the limits' 5 (`None`, the default: each is
/// passed over), while 8 places one. Its size with the open strut,
/// recomputed from the linkage and the strut's longest length, is above 5
/// and at most 8, the hinge alone at most 5; the placement at its ground
/// pivot judged afresh is acceptable and clear under the limits with 8 and
/// not acceptable under 5. Infinity, the documented most (no limit), is
/// searched and ranks a hinge at least as good first; below 1, NaN and
/// minus infinity are refused naming the field.
#[test]
fn the_strut_stage_applies_its_own_size_bound() {
    let (task, options) = hood_on_its_bracket();
    let bracket = P::new(-40.0, -20.0);
    assert_eq!(burmester::ActuatorSearch::default().max_size_ratio, None);
    let five = task.design(&options, &Control::new()).unwrap();
    assert!(five.designs.is_empty() && five.unplaced > 0, "{five:?}");

    let mut eight = options.clone();
    eight.actuator.as_mut().unwrap().max_size_ratio = Some(8.0);
    let search = eight.actuator.unwrap();
    assert_eq!(search.limits(&eight.limits).max_size_ratio, 8.0);
    assert_eq!(
        options.actuator.unwrap().limits(&eight.limits),
        eight.limits
    );
    let report = task.design(&eight, &Control::new()).unwrap();
    assert_eq!(report.actuator, Some(search));
    let d = report
        .designs
        .first()
        .expect("a hinge with its strut under 8");
    let a = d.actuator.as_ref().unwrap();
    let fb = d.linkage.four_bar().unwrap();
    assert_eq!(a.point, bracket);
    assert!(a.acceptable && a.clear && a.min_clearance >= 3.0, "{a:?}");
    let size = (fb.size() + a.max_length) / task.span();
    assert!(
        (size - a.size_ratio).abs() < 1e-9,
        "{size} vs {}",
        a.size_ratio
    );
    assert!(size > 5.0 && size <= 8.0, "{size}");
    assert!(d.size_ratio <= 5.0 && (d.size_ratio - fb.size() / task.span()).abs() < 1e-9);
    let judged = |max_size_ratio: f64| {
        let limits = DesignLimits {
            max_size_ratio,
            ..eight.limits
        };
        let map_options = MapOptions::new(&limits, &eight.space.constraints()).unwrap();
        let ctx = ActuatorContext::new(
            fb,
            bracket,
            &one_grid(a.ground),
            &map_options,
            &search.options,
        )
        .unwrap();
        ctx.placement(a.ground).unwrap()
    };
    let again = judged(8.0);
    assert!(again.acceptable && again.clear);
    assert!((again.size_ratio - a.size_ratio).abs() < 1e-12);
    assert!(!judged(5.0).acceptable);

    let mut open = eight.clone();
    open.actuator.as_mut().unwrap().max_size_ratio = Some(f64::INFINITY);
    let unbounded = task.design(&open, &Control::new()).unwrap();
    let best = unbounded
        .designs
        .first()
        .expect("no bound places at least as much");
    assert!(best.score >= d.score, "{} < {}", best.score, d.score);
    assert!(
        best.actuator
            .as_ref()
            .is_some_and(|a| a.acceptable && a.clear)
    );

    for bad in [0.5, f64::NAN, f64::NEG_INFINITY, 1.0 - 1e-12] {
        let mut o = eight.clone();
        o.actuator.as_mut().unwrap().max_size_ratio = Some(bad);
        let e = task.design(&o, &Control::new()).unwrap_err();
        assert!(
            matches!(
                e,
                Error::InvalidInput(InvalidInput::OutsideRange {
                    name: "actuator max_size_ratio",
                    ..
                })
            ),
            "{bad}: {e:?}"
        );
        assert!(e.to_string().contains("actuator max_size_ratio"), "{e}");
    }
    let one = burmester::ActuatorSearch {
        max_size_ratio: Some(1.0),
        ..search
    };
    assert!(one.validate().is_ok());
}

/// The rocker's middle `Q` (at pose 1) and a ground pivot `G` a distance
/// `d` behind the crank's fixed pivot `A0`, against the crank's middle
/// direction `u`, where the construction holds over the travel (checked by
/// driving the linkage densely): the crank in front of `A0`, `Q` behind
/// `G`, `G` off the rocker's bar by `2 d` (the strut does not lie along
/// its own link), and the test's own gap at least `d` everywhere, so that
/// the strut's nearest link is the crank at `A0`, `d` away.
fn passing_the_crank_pivot(sfb: &SynthesizedFourBar, d: f64) -> Option<(P, P)> {
    let (start, span) = sfb.travel()?;
    let mode = sfb.modes()[0]?;
    if span.abs() > 0.8 * PI {
        return None;
    }
    let joints = |t: f64| sfb.fourbar.joints(&sfb.fourbar.solve(t, mode).unwrap());
    let mid = joints(start + 0.5 * span);
    let u = (mid.crank_joint - mid.input_pivot).normalize();
    let g = mid.input_pivot - u * d;
    let q = sfb.driven.center + (sfb.driven.circle - sfb.driven.center) * 0.5;
    let own = Own::new(sfb, ActuatorLink::Rocker, q);
    let off_bar = |p: P, a: P, b: P| {
        let ab = b - a;
        let t = ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
        (p - (a + ab * t)).norm()
    };
    let steps = 2_000;
    let holds = (0..=steps).all(|k| {
        let t = start + span * k as f64 / steps as f64;
        let j = joints(t);
        (j.crank_joint - j.input_pivot).dot(&u) > 0.0
            && (own.at(t) - g).dot(&u) < 0.0
            && off_bar(g, j.output_pivot, j.rocker_joint) > 2.0 * d
            && own_gap(sfb, &own, g, t, (0.0, 0.0), &[]) >= d - 1e-9 * d
    });
    holds.then_some((q, g))
}

/// Limits every monotone placement meets.
fn open_limits() -> DesignLimits {
    DesignLimits {
        min_transmission: 0.0,
        max_link_ratio: f64::INFINITY,
        max_size_ratio: f64::INFINITY,
        max_link_length: f64::INFINITY,
        ..DesignLimits::default()
    }
}

/// A strut that passes the crank's fixed pivot at a known distance `d`
/// ([`passing_the_crank_pivot`]): the placement's and the map's gap are
/// `d` less the two half widths; the least gap `min_gap` rejects it
/// exactly above that.
#[test]
fn a_strut_passing_a_link_at_a_known_distance() {
    let mut runner = TestRunner::new(common::config(1));
    let found = (0..400)
        .filter(|_| {
            let (task, sfb) = random_linkage(&mut runner);
            let d = 0.05 * task.span();
            let Some((q, g)) = passing_the_crank_pivot(&sfb, d) else {
                return false;
            };
            let (wl, ws) = (0.3 * d, 0.5 * d);
            let want = d - 0.5 * wl - 0.5 * ws;
            let c = Constraints {
                link_width: wl,
                ..Constraints::none()
            };
            let at = |min_gap: f64| {
                let options = ActuatorOptions {
                    link: ActuatorLink::Rocker,
                    actuator_width: ws,
                    min_gap,
                    max_stroke_ratio: f64::INFINITY,
                    ..ActuatorOptions::default()
                };
                let ctx = ActuatorContext::new(
                    &sfb,
                    q,
                    &one_grid(g),
                    &MapOptions::new(&open_limits(), &c).unwrap(),
                    &options,
                )
                .unwrap();
                (ctx.placement(g).unwrap(), ctx.map(&Control::new()).unwrap())
            };
            let (a, map) = at(0.0);
            assert!(
                (a.min_clearance - want).abs() < 1e-9 * task.span(),
                "{} vs {want}",
                a.min_clearance
            );
            assert!(a.clear);
            // The map computes it where the actuator is monotone (the other
            // limits are open here).
            let sampled = f64::from(map.columns.clearance[0]);
            assert_eq!(sampled.is_finite(), a.monotone);
            assert!(
                !a.monotone || (sampled - want).abs() < 1e-6 * want,
                "{sampled} vs {want}"
            );
            // min_gap just below the gap keeps it, just above rejects it
            // (the placement and the map sample alike).
            let (below, map_below) = at(want * (1.0 - 1e-6));
            assert!(below.clear && below.acceptable == a.acceptable);
            assert_eq!(map_below.columns.acceptable[0], map.columns.acceptable[0]);
            let (above, map_above) = at(want * (1.0 + 1e-6));
            assert!(!above.clear && !above.acceptable);
            assert!(!map_above.columns.acceptable[0]);
            assert_eq!(above.min_clearance, a.min_clearance);
            true
        })
        .count();
    assert!(found >= 5, "{found} linkages met the construction");
}

/// The map's `clearance` column and its `min_gap`: the column does not
/// depend on `min_gap`; `acceptable` under a least gap is exactly the
/// acceptable samples at gap 0 whose clearance reaches it; a sample's
/// placement refines its clearance down from the sampled one, by at most
/// what the links move in a sample step.
#[test]
fn the_min_gap_filters_the_map_exactly() {
    let mut runner = TestRunner::new(common::config(1));
    let (mut kept, mut dropped) = (0, 0);
    for case in 0..6 {
        let (task, sfb) = random_linkage(&mut runner);
        let r = task.span();
        let c = common::centroid(task.poses());
        let (lo, hi) = (
            c - Vector2::new(2.0, 2.0) * r,
            c + Vector2::new(2.0, 2.0) * r,
        );
        let grid = Grid::from_bounds(lo.x, hi.x, lo.y, hi.y, 48, 40).unwrap();
        let q = sfb.driving.circle + (sfb.driven.circle - sfb.driving.circle) * 0.4;
        let link = ActuatorLink::ALL[case % 3];
        let cons = Constraints {
            link_width: 0.02 * r,
            ..Constraints::none()
        };
        let limits = open_limits();
        let map_at = |min_gap: f64| {
            let options = ActuatorOptions {
                link,
                actuator_width: 0.03 * r,
                min_gap,
                max_stroke_ratio: f64::INFINITY,
                ..ActuatorOptions::default()
            };
            let ctx = ActuatorContext::new(
                &sfb,
                q,
                &grid,
                &MapOptions::new(&limits, &cons).unwrap(),
                &options,
            )
            .unwrap();
            ctx.map(&Control::new()).unwrap()
        };
        let zero = map_at(0.0);
        let m = 0.1 * r;
        let gapped = map_at(m);
        let (z, g) = (&zero.columns, &gapped.columns);
        let bits = |x: &[f32]| x.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&z.clearance), bits(&g.clearance));
        for k in 0..grid.len() {
            let gap = f64::from(z.clearance[k]);
            if z.acceptable[k] {
                assert!(gap > 0.0);
            }
            if (gap - m).abs() <= 1e-6 * r {
                continue; // the column is f32: a tie is not decided by it
            }
            assert_eq!(g.acceptable[k], z.acceptable[k] && gap >= m, "sample {k}");
            if z.acceptable[k] {
                if gap >= m {
                    kept += 1;
                } else {
                    dropped += 1;
                }
            }
        }
        // Placements refine the sampled gap downward, a little.
        let step = (zero.context.travel_angles()[1] - zero.context.travel_angles()[0]).abs();
        let moves = 4.0 * step * r * (1.0 + 1.0 / sfb.figures.min_transmission.sin().max(0.1));
        for k in (0..grid.len()).step_by(29) {
            if !z.clearance[k].is_finite() {
                continue;
            }
            let a = zero.context.placement_at(k).unwrap();
            let sampled = f64::from(z.clearance[k]);
            assert!(
                a.min_clearance <= sampled + 1e-6 * r && a.min_clearance >= sampled - moves,
                "{} vs sampled {sampled}",
                a.min_clearance
            );
        }
    }
    assert!(kept > 0 && dropped > 0, "{kept} kept, {dropped} dropped");
}

/// The context of an actuator map on `grid` for `link` at `q`, a strut
/// `width` wide keeping `min_gap`, links `link_width` wide, under `limits`
/// (no stroke ratio limit), the travel in `samples` samples.
fn strut_context(
    sfb: &SynthesizedFourBar,
    (link, q, samples): (ActuatorLink, P, usize),
    grid: &Grid,
    (width, link_width, min_gap): (f64, f64, f64),
    limits: &DesignLimits,
) -> ActuatorContext {
    let options = ActuatorOptions {
        link,
        actuator_width: width,
        min_gap,
        max_stroke_ratio: f64::INFINITY,
        travel_samples: samples,
    };
    let c = Constraints {
        link_width,
        ..Constraints::none()
    };
    let checked = MapOptions::new(limits, &c).unwrap();
    ActuatorContext::new(sfb, q, grid, &checked, &options).unwrap()
}

/// An `nx` by `ny` grid within two spans of the task's centroid.
fn about(task: &Task, nx: usize, ny: usize) -> Grid {
    let (c, r) = (common::centroid(task.poses()), 2.0 * task.span());
    Grid::from_bounds(c.x - r, c.x + r, c.y - r, c.y + r, nx, ny).unwrap()
}

/// The rankings over the acceptable samples (all but the margin's).
const ACCEPTABLE_RANKINGS: [RankBy; 4] = [
    RankBy::Balanced,
    RankBy::Transmission,
    RankBy::Compact,
    RankBy::Pareto,
];

/// A least gap just above a placement's own (refined) gap: the map of that
/// one ground pivot does not accept it, and no ranking returns it. (The
/// map judged the gap at its travel samples, at least the placement's
/// refined one, so it accepted pivots whose placement's gap was below
/// `min_gap` and the ranking returned them.)
#[test]
fn a_placement_just_below_min_gap_is_not_ranked() {
    // The placements whose gap was tried.
    let mut tried = 0;
    let mut runner = TestRunner::new(common::config(1));
    for case in 0..6 {
        let (task, sfb) = random_linkage(&mut runner);
        let (r, grid) = (task.span(), about(&task, 24, 20));
        let q = sfb.driving.circle + (sfb.driven.circle - sfb.driving.circle) * 0.4;
        let at = (ActuatorLink::ALL[case % 3], q, 256);
        let widths = |min_gap: f64| (0.03 * r, 0.02 * r, min_gap);
        let zero = strut_context(&sfb, at, &grid, widths(0.0), &open_limits());
        let map = zero.map(&Control::new()).unwrap();
        for k in (0..grid.len()).step_by(2) {
            if !map.columns.acceptable[k] {
                continue;
            }
            let own = zero.placement_at(k).unwrap();
            assert!(own.acceptable && own.clear, "{own:?}");
            let min_gap = own.min_clearance + 1e-9 * r;
            let one = strut_context(
                &sfb,
                at,
                &one_grid(own.ground),
                widths(min_gap),
                &open_limits(),
            );
            let single = one.map(&Control::new()).unwrap();
            let again = one.placement_at(0).unwrap();
            assert!((again.min_clearance - own.min_clearance).abs() < 1e-12 * r);
            assert!(!again.clear && !again.acceptable);
            assert!(!single.columns.acceptable[0], "sample {k}: {own:?}");
            for rank_by in ACCEPTABLE_RANKINGS {
                let best = single.best_placements(Ranking::new(1, rank_by)).unwrap();
                assert!(best.is_empty(), "{rank_by:?}: {best:?}");
            }
            tried += 1;
        }
    }
    assert!(tried >= 10, "{tried} placements tried");
}

/// Property: over random linkages, links, moving points, widths, least
/// gaps, transmission limits and travel samples, every placement a ranking
/// over the acceptable samples returns is acceptable and clear by its own
/// figures: its gap above 0 and at least `min_gap`; and the map's
/// `acceptable` column holds only where the sample's placement is
/// acceptable.
#[test]
fn every_ranked_placement_keeps_min_gap() {
    let mut runner = TestRunner::new(common::config(1));
    // The placements ranked, the samples accepted.
    let mut seen = [0usize; 2];
    for case in 0..10 {
        let (task, sfb) = random_linkage(&mut runner);
        let (link, t, (ws, wl, gap), mu, (nx, ny), (near, pick, above), samples) = (
            0usize..3,
            0.2f64..0.8,
            (0.0f64..0.06, 0.0f64..0.04, 0.0f64..0.15),
            0.0f64..30.0,
            (12usize..40, 12usize..40),
            (any::<bool>(), 0.0f64..1.0, 0.0f64..1e-6),
            prop_oneof![Just(256usize), 8usize..64],
        )
            .new_tree(&mut runner)
            .unwrap()
            .current();
        let r = task.span();
        let grid = about(&task, nx, ny);
        // On the link: along the coupler's bar, or along the crank's
        // (rocker's) past the middle.
        let (a, b) = match ActuatorLink::ALL[link] {
            ActuatorLink::Coupler => (sfb.driving.circle, sfb.driven.circle),
            ActuatorLink::Crank => (sfb.driving.center, sfb.driving.circle),
            ActuatorLink::Rocker => (sfb.driven.center, sfb.driven.circle),
        };
        let q = a + (b - a) * t;
        let limits = DesignLimits {
            min_transmission: mu.to_radians(),
            ..open_limits()
        };
        let at = (ActuatorLink::ALL[link], q, samples);
        let widths = |min_gap: f64| (ws * r, wl * r, min_gap);
        // Half the cases try, besides, least gaps just above the gaps of
        // placements acceptable without one (where a judgement on fewer
        // samples than the placement's errs), from the smallest to the
        // largest.
        let mut min_gaps = vec![gap * r];
        if near {
            let zero = strut_context(&sfb, at, &grid, widths(0.0), &limits);
            let map = zero.map(&Control::new()).unwrap();
            let mut gaps: Vec<f64> = (0..grid.len())
                .filter(|&k| map.columns.acceptable[k])
                .map(|k| zero.placement_at(k).unwrap().min_clearance)
                .collect();
            gaps.sort_by(f64::total_cmp);
            let n = gaps.len();
            let picks = n.min(6);
            for m in 0..picks {
                let k = ((m as f64 + pick) * n as f64 / picks as f64) as usize;
                min_gaps.push(gaps[k.min(n - 1)] + above * r);
            }
        }
        for min_gap in min_gaps {
            let ctx = strut_context(&sfb, at, &grid, widths(min_gap), &limits);
            let map = ctx.map(&Control::new()).unwrap();
            for k in 0..grid.len() {
                if map.columns.acceptable[k] {
                    let a = ctx.placement_at(k).unwrap();
                    assert!(a.acceptable && a.clear, "case {case}, sample {k}: {a:?}");
                    assert!(a.min_clearance > 0.0 && a.min_clearance >= min_gap);
                    seen[1] += 1;
                }
            }
            for rank_by in ACCEPTABLE_RANKINGS {
                for a in map.best_placements(Ranking::new(6, rank_by)).unwrap() {
                    assert!(
                        a.min_clearance > 0.0 && a.min_clearance >= min_gap,
                        "case {case}, {rank_by:?}: gap {} below {min_gap}",
                        a.min_clearance
                    );
                    assert!(a.acceptable && a.clear, "case {case}, {rank_by:?}: {a:?}");
                    seen[0] += 1;
                }
            }
        }
    }
    assert!(seen[0] > 0 && seen[1] > 0, "{seen:?} ranked, accepted");
}
