//! Drive synthesis (the Watt II six-bar) against independent computations.
//!
//! Every drive a map returns is driven through a full crank turn in small
//! steps by this file's own loop-closure solver (circle intersections,
//! continuity by the nearest solution; nothing of the crate's position
//! analysis): the motion must be continuous and close after a turn,
//! neither loop may toggle, the coupler must reach every pose to `1e-9`
//! task sizes in order on one stroke, and the smallest transmission angle
//! of each loop (dense steps refined by golden sections) must agree with
//! the map's to `1e-6` rad. The tasks are made from known linkages whose
//! input swings (rocker inputs: triple-rockers, double-rockers, rocker-
//! cranks), with three, four or five poses.

use std::f64::consts::{PI, TAU};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use burmester::design::{
    AttachmentSearch, CrankRockerDesign, Drive, DriveContext, DriveOptions, best_drive,
    search_drives,
};
use burmester::{
    AssemblyMode, Constraints, Control, DesignLimits, DesignOptions, DriveError, Dyad, Error,
    FourBar, Grid, InputRange, MapOptions, Point2, RankBy, Ranking, SixBar, SixBarJoints,
    SynthesizedFourBar, Task, Vector2,
};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;

mod common;
use common::wrap;

type P = Point2<f64>;

fn unit(a: f64) -> Vector2<f64> {
    Vector2::new(a.cos(), a.sin())
}

fn cross(u: Vector2<f64>, v: Vector2<f64>) -> f64 {
    u.x * v.y - u.y * v.x
}

/// The two intersections of the circles about `p` (radius `a`) and `q`
/// (radius `b`), and the half-distance between them over the larger radius
/// (how far from a toggle); `None` where they miss.
fn circles(p: P, a: f64, q: P, b: f64) -> Option<([P; 2], f64)> {
    let d = q - p;
    let l2 = d.norm_squared();
    let l = l2.sqrt();
    let x = (a * a - b * b + l2) / (2.0 * l);
    let h2 = a * a - x * x;
    if h2 < 0.0 {
        return None;
    }
    let h = h2.sqrt();
    let u = d / l;
    let n = Vector2::new(-u.y, u.x);
    let m = p + u * x;
    Some(([m + n * h, m - n * h], h / a.max(b)))
}

/// The folded angle between two vectors, in `[0, pi/2]`.
fn folded(u: Vector2<f64>, v: Vector2<f64>) -> f64 {
    let a = cross(u, v).abs().atan2(u.dot(&v));
    a.min(PI - a)
}

/// The six-bar of a drive by its own pieces (nothing of the crate's
/// position analysis): pivots, lengths, the ternary link's angle from the
/// attachment and `A1`, the coupler's frame from pose 1.
struct Own {
    d0: P,
    a0: P,
    c0: P,
    r: f64,
    c: f64,
    rho: f64,
    l2: f64,
    l3: f64,
    l4: f64,
    delta: f64,
    a1: P,
    c1: P,
    pose1: (P, f64),
}

/// One solved position: `E`, `A`, `C` and the two transmission angles.
#[derive(Clone, Copy)]
struct State {
    e: P,
    a: P,
    c: P,
    theta2: f64,
    mu_drive: f64,
    mu_motion: f64,
    /// How far each loop is from a toggle (intersection half-distance over
    /// the radius).
    gap: f64,
}

impl Own {
    fn new(task: &Task, d: &Drive) -> Own {
        let l = &d.linkage;
        let (a0, a1) = (l.driving.center, l.driving.circle);
        let (c0, c1) = (l.driven.center, l.driven.circle);
        let e1 = d.attachment;
        let lens = d.sixbar.lengths();
        let rho = (e1 - a0).norm();
        assert!((rho - lens.rocker).abs() < 1e-12 * (1.0 + rho), "rho");
        let (ea, aa) = (e1 - a0, a1 - a0);
        let p = task.poses()[0];
        Own {
            d0: d.drive_pivot,
            a0,
            c0,
            r: lens.crank,
            c: lens.drive_coupler,
            rho,
            l2: aa.norm(),
            l3: (c1 - a1).norm(),
            l4: (c1 - c0).norm(),
            delta: ea.y.atan2(ea.x) - aa.y.atan2(aa.x),
            a1,
            c1,
            pose1: (p.position, p.angle),
        }
    }

    /// Solves at crank angle `phi`, taking each loop's solution nearest to
    /// `prev`.
    fn solve(&self, phi: f64, prev: &State) -> Option<State> {
        let dpt = self.d0 + unit(phi) * self.r;
        let ([e1, e2], g1) = circles(dpt, self.c, self.a0, self.rho)?;
        let e = if (e1 - prev.e).norm() <= (e2 - prev.e).norm() {
            e1
        } else {
            e2
        };
        let v = e - self.a0;
        let theta2 = v.y.atan2(v.x) - self.delta;
        let a = self.a0 + unit(theta2) * self.l2;
        let ([c1, c2], g2) = circles(a, self.l3, self.c0, self.l4)?;
        let c = if (c1 - prev.c).norm() <= (c2 - prev.c).norm() {
            c1
        } else {
            c2
        };
        Some(State {
            e,
            a,
            c,
            theta2,
            mu_drive: folded(e - dpt, e - self.a0),
            mu_motion: folded(c - a, c - self.c0),
            gap: g1.min(g2),
        })
    }

    /// The coupler pose of a state (the rigid motion of `A1 C1` to `A C`
    /// applied to pose 1).
    fn pose(&self, s: &State) -> (P, f64) {
        let (u1, u) = (self.c1 - self.a1, s.c - s.a);
        let turn = u.y.atan2(u.x) - u1.y.atan2(u1.x);
        let (p1, ang1) = self.pose1;
        let w = p1 - self.a1;
        let (sn, cs) = turn.sin_cos();
        (
            s.a + Vector2::new(cs * w.x - sn * w.y, sn * w.x + cs * w.y),
            ang1 + turn,
        )
    }
}

/// What the independent check measured.
struct Checked {
    drive_min: f64,
    motion_min: f64,
}

/// Golden-section minimum of `f` on `[lo, hi]`.
fn golden(mut lo: f64, mut hi: f64, f: impl Fn(f64) -> f64) -> f64 {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut x1, mut x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..200 {
        if f1 < f2 {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = f(x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = f(x2);
        }
        if hi - lo < 1e-13 {
            break;
        }
    }
    f1.min(f2)
}

/// Drives `d` through a full crank turn in `steps` steps from pose 1 in the
/// motor's direction with [`Own`], checking everything the module docs
/// list; returns the refined minimum transmission angles.
fn check_drive(task: &Task, d: &Drive, steps: usize) -> Checked {
    let own = Own::new(task, d);
    let span = task.span();
    let n = task.len();
    let dir = d.direction.sign();
    let phis = &d.pose_crank_angles;
    // Pose 1: the drive coupler spans D(phi_1) to E1.
    let dpt = own.d0 + unit(phis[0]) * own.r;
    assert!(
        ((d.attachment - dpt).norm() - own.c).abs() < 1e-9 * span,
        "the crank at pose 1 does not reach E1"
    );
    let start = State {
        e: d.attachment,
        a: own.a1,
        c: own.c1,
        theta2: d.linkage.input_angles[0],
        mu_drive: f64::NAN,
        mu_motion: f64::NAN,
        gap: 1.0,
    };
    let first = own.solve(phis[0], &start).expect("closes at pose 1");
    // The pose angles are in order in the motor's direction, within one
    // stroke from pose 1.
    for k in 1..n {
        assert!(
            (phis[k] - phis[k - 1]) * dir > 0.0,
            "pose crank angles out of order: {:?}",
            &phis[..]
        );
    }
    let stroke = d.figures.stroke;
    assert!(
        (phis[n - 1] - d.stroke_start) * dir <= stroke + 1e-9,
        "the poses are not on one stroke"
    );
    // The steps: a full turn, the pose angles among them.
    let mut at: Vec<(f64, Option<usize>)> = (0..=steps)
        .map(|k| (phis[0] + dir * TAU * k as f64 / steps as f64, None))
        .collect();
    for (k, &p) in phis.iter().enumerate() {
        at.push((p, Some(k)));
    }
    at.sort_by(|x, y| ((x.0 - phis[0]) * dir).total_cmp(&((y.0 - phis[0]) * dir)));
    let mut prev = first;
    let mut seen = 0;
    let (mut dmin, mut mmin) = (f64::INFINITY, f64::INFINITY);
    let (mut dmin_at, mut mmin_at) = (phis[0], phis[0]);
    let mut thetas = Vec::with_capacity(at.len());
    let scale = own.r.max(own.rho).max(own.l2).max(own.l4);
    for &(phi, pose) in &at {
        let s = own
            .solve(phi, &prev)
            .expect("the loops close over the whole turn");
        // Continuous: no joint jumps more than a step's worth.
        let jump = (s.e - prev.e).norm().max((s.c - prev.c).norm());
        assert!(
            jump < 200.0 * scale * TAU / steps as f64,
            "a jump of {jump} at phi = {phi}"
        );
        assert!(s.gap > 1e-6, "a loop toggles at phi = {phi}");
        if s.mu_drive < dmin {
            dmin = s.mu_drive;
            dmin_at = phi;
        }
        if s.mu_motion < mmin {
            mmin = s.mu_motion;
            mmin_at = phi;
        }
        if let Some(k) = pose {
            assert_eq!(k, seen, "pose {} reached out of order", k + 1);
            seen += 1;
            let (p, ang) = own.pose(&s);
            let want = task.poses()[k];
            let err = (p - want.position).norm();
            assert!(err <= 1e-9 * span, "pose {}: off by {err}", k + 1);
            assert!(wrap(ang - want.angle).abs() <= 1e-9, "pose {} angle", k + 1);
        }
        thetas.push(((phi - phis[0]) * dir, s.theta2));
        prev = s;
    }
    assert_eq!(seen, n, "every pose reached");
    // Back where it started after a full turn.
    let end = own.solve(phis[0] + dir * TAU, &prev).unwrap();
    assert!((end.e - first.e).norm() < 1e-9 * scale && (end.c - first.c).norm() < 1e-9 * scale);
    // The input angle is monotone from pose 1 to the last pose (one stroke).
    let last = (phis[n - 1] - phis[0]) * dir;
    let travel: Vec<f64> = thetas
        .iter()
        .filter(|(o, _)| *o <= last + 1e-12)
        .map(|&(_, t)| t)
        .collect();
    let sgn = (d.linkage.travel().unwrap().1).signum();
    for w in travel.windows(2) {
        assert!(
            wrap(w[1] - w[0]) * sgn >= -1e-12,
            "the input turns back between the poses"
        );
    }
    // Refine each minimum by golden sections about its best step.
    let h = 2.0 * TAU / steps as f64;
    let near = |phi0: f64, pick: fn(&State) -> f64| {
        let seed = own
            .solve(phi0, &prev_at(&own, &at, phi0, &first, dir, phis[0]))
            .unwrap();
        golden(phi0 - h, phi0 + h, |phi| {
            own.solve(phi, &seed).map_or(f64::INFINITY, |s| pick(&s))
        })
    };
    let drive_min = near(dmin_at, |s| s.mu_drive).min(dmin);
    let motion_min = near(mmin_at, |s| s.mu_motion).min(mmin);
    Checked {
        drive_min,
        motion_min,
    }
}

/// A state near crank angle `phi` on the tracked path (re-tracks from pose 1).
fn prev_at(
    own: &Own,
    at: &[(f64, Option<usize>)],
    phi: f64,
    first: &State,
    dir: f64,
    phi0: f64,
) -> State {
    let mut prev = *first;
    for &(p, _) in at {
        if (p - phi0) * dir > (phi - phi0) * dir {
            break;
        }
        prev = own.solve(p, &prev).unwrap();
    }
    prev
}

/// A task of `n` poses made from a known four-bar whose input swings, and
/// its linkage (the generating dyads, so the linkage is the generator).
fn swinging_task(runner: &mut TestRunner, n: usize) -> (Task, SynthesizedFourBar) {
    loop {
        let v = (
            (0.5f64..4.0, 0.5f64..3.0, 0.5f64..3.0, 0.5f64..3.0),
            (-3.0f64..3.0, -3.0f64..3.0, -PI..PI),
            (0.05f64..0.3, 0.3f64..0.9, -1.5f64..2.5, -1.5f64..1.5),
            any::<bool>(),
            any::<bool>(),
        )
            .new_tree(runner)
            .unwrap()
            .current();
        let ((l1, l2, l3, l4), (ox, oy, ga), (from, width, u, w), crossed, cw) = v;
        let Ok(fb) = FourBar::placed(l1, l2, l3, l4, Point2::new(ox, oy), ga) else {
            continue;
        };
        let arc = match fb.input_range() {
            InputRange::Full => continue,
            InputRange::Arc(a) => a,
            InputRange::TwoArcs(a, _) => a,
        };
        let travel = (width * arc.span()).min(PI - 0.3);
        if travel < 0.2 {
            continue;
        }
        let t0 = arc.start + from * (arc.span() - travel);
        let mode = if crossed {
            AssemblyMode::Crossed
        } else {
            AssemblyMode::Open
        };
        let mut poses = Vec::new();
        let mut ok = true;
        let mut thetas = Vec::new();
        for k in 0..n {
            // Uneven spacing, in order.
            let f = (k as f64 / (n - 1) as f64).powf(1.3);
            let t = if cw {
                t0 + travel * (1.0 - f)
            } else {
                t0 + travel * f
            };
            thetas.push(t);
            let Ok(c) = fb.solve(t, mode) else {
                ok = false;
                break;
            };
            if c.transmission_angle() < 0.1 {
                ok = false;
                break;
            }
            let j = fb.joints(&c);
            let p = j.coupler_point(Vector2::new(u, w));
            poses.push([p.x, p.y, c.theta3]);
        }
        if !ok {
            continue;
        }
        let Ok(task) = Task::from_xya(&poses) else {
            continue;
        };
        if task.span() < 0.2 {
            continue;
        }
        let c0 = fb.output_pivot();
        let a1 = fb.input_pivot() + unit(thetas[0]) * l2;
        let c1 = fb.joints_at(thetas[0], mode).unwrap().rocker_joint;
        let Ok(sfb) = task.four_bar(&Dyad::new(fb.input_pivot(), a1), &Dyad::new(c0, c1)) else {
            continue;
        };
        if !sfb.figures.feasible() {
            continue;
        }
        return (task, sfb);
    }
}

/// [`best_drive`] of `sfb` under `limits` by the balanced ranking, with
/// the default options and no constraints.
fn balanced_drive(sfb: &SynthesizedFourBar, limits: &DesignLimits) -> Result<Drive, Error> {
    best_drive(
        sfb,
        &MapOptions::new(limits, &Constraints::none()).unwrap(),
        &DriveOptions::default(),
        RankBy::Balanced,
        &Control::new(),
    )
}

/// The six-bar of `drive` and the motion loop of `six`, both loops open,
/// the drive's input at 0.
fn open_six_bar(drive: FourBar, six: &SixBar) -> Result<SixBar, Error> {
    SixBar::new(
        drive,
        *six.motion(),
        0.0,
        AssemblyMode::Open,
        AssemblyMode::Open,
    )
}

/// The drive context of `sfb` attached at `e` on `grid`, with [`anything`]
/// as its limits and the default options.
fn anything_context(
    sfb: &SynthesizedFourBar,
    e: Point2<f64>,
    grid: &Grid,
    constraints: &Constraints,
) -> Result<DriveContext, Error> {
    MapOptions::new(&anything(), constraints)
        .and_then(|o| DriveContext::new(sfb, e, grid, &o, &DriveOptions::default()))
}

/// [`search_drives`] of `sfb` with [`anything`] as its limits, the default
/// options and no constraints.
fn search_anything(
    sfb: &SynthesizedFourBar,
    search: &AttachmentSearch,
    rank_by: RankBy,
    control: &Control<'_>,
) -> Result<burmester::design::DriveSearch, Error> {
    search_drives(
        sfb,
        search,
        &MapOptions::new(&anything(), &Constraints::none()).unwrap(),
        &DriveOptions::default(),
        rank_by,
        control,
    )
}

/// Limits under which every drive is acceptable.
fn anything() -> DesignLimits {
    DesignLimits {
        min_transmission: 0.0,
        max_link_ratio: f64::INFINITY,
        ..DesignLimits::default()
    }
}

/// The drive map of a random attachment of `sfb`, on a 48 x 48 grid about
/// `A0`.
fn random_context(
    runner: &mut TestRunner,
    sfb: &SynthesizedFourBar,
    margin: f64,
) -> Option<DriveContext> {
    let (ratio, angle) = (0.3f64..2.5, -PI..PI).new_tree(runner).unwrap().current();
    let a0 = sfb.driving.center;
    let e = a0 + rotate(sfb.driving.circle - a0, angle) * ratio;
    let rho = (e - a0).norm();
    let h = 4.0 * rho;
    let grid = Grid::from_bounds(a0.x - h, a0.x + h, a0.y - h, a0.y + h, 48, 48).unwrap();
    let options = DriveOptions {
        swing_margin: margin,
        ..DriveOptions::default()
    };
    DriveContext::new(
        sfb,
        e,
        &grid,
        &MapOptions::new(&anything(), &Constraints::none()).unwrap(),
        &options,
    )
    .ok()
}

fn rotate(v: Vector2<f64>, a: f64) -> Vector2<f64> {
    let (s, c) = a.sin_cos();
    Vector2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// Checks the drive against the independent solver and the map's columns.
fn check_against_map(task: &Task, d: &Drive, map: &burmester::design::DriveMap) -> bool {
    if d.figures.min_transmission < 0.05 {
        return false;
    }
    let got = check_drive(task, d, 6000);
    let f = &d.figures;
    assert!(
        (got.drive_min - f.drive_transmission).abs() < 1e-6,
        "drive loop: stepped {} vs {}",
        got.drive_min,
        f.drive_transmission
    );
    assert!(
        (got.motion_min - f.motion_transmission).abs() < 1e-6,
        "motion loop: stepped {} vs {}",
        got.motion_min,
        f.motion_transmission
    );
    if let Some((j, i)) = d.index {
        let k = j * map.context.grid().nx() + i;
        let c = &map.columns;
        assert!(c.valid[k]);
        assert!((f64::from(c.drive_transmission_rad[k]) - got.drive_min).abs() < 1e-6);
        assert!(
            (f64::from(c.min_transmission_rad[k]) - got.drive_min.min(got.motion_min)).abs() < 1e-6
        );
        assert!((f64::from(c.time_ratio[k]) - f.time_ratio).abs() < 1e-6 * f.time_ratio);
    }
    true
}

#[test]
fn returned_drives_pass_the_independent_check() {
    let mut runner = TestRunner::new(common::config(1));
    let mut checked = 0;
    let mut cases = 0;
    for case in 0..36 {
        let n = 3 + case % 3;
        let (task, sfb) = swinging_task(&mut runner, n);
        let margin = if case % 4 == 1 { 0.05 } else { 0.0 };
        let Some(ctx) = random_context(&mut runner, &sfb, margin) else {
            continue;
        };
        cases += 1;
        let map = ctx.map(&Control::new()).unwrap();
        let mut drives = Vec::new();
        for rank in [RankBy::Balanced, RankBy::Transmission, RankBy::Compact] {
            drives.extend(map.best_drives(Ranking::new(2, rank)).unwrap());
        }
        for d in &drives {
            assert!(d.sixbar.crank_turns_fully());
            if check_against_map(&task, d, &map) {
                checked += 1;
            }
        }
    }
    eprintln!("{checked} drives of {cases} tasks passed the independent check");
    assert!(cases >= 20, "{cases} tasks had a drive context");
    assert!(checked >= 60, "only {checked} drives were checked");
}

proptest! {
    #![proptest_config(common::config(24))]

    /// Random valid samples of random maps: the independent check, and the
    /// figures of `DriveContext::drive` are the map's columns.
    #[test]
    fn map_samples_are_the_drives_they_describe(seed in 0u64..1_000_000, n in 3usize..=5) {
        let mut runner = TestRunner::new_with_rng(
            common::config(1),
            proptest::test_runner::TestRng::from_seed(
                proptest::test_runner::RngAlgorithm::ChaCha,
                &seed.to_le_bytes().repeat(4),
            ),
        );
        let (task, sfb) = swinging_task(&mut runner, n);
        let Some(ctx) = random_context(&mut runner, &sfb, 0.0) else { return Ok(()); };
        let map = ctx.map(&Control::new()).unwrap();
        let valid: Vec<usize> = (0..map.columns.valid.len()).filter(|&k| map.columns.valid[k]).collect();
        for &k in valid.iter().step_by((valid.len() / 3).max(1)).take(3) {
            let d = ctx.drive_at(k).unwrap();
            prop_assert_eq!(d.figures.min_transmission as f32, map.columns.min_transmission_rad[k]);
            prop_assert_eq!(d.figures.size_ratio as f32, map.columns.size_ratio[k]);
            prop_assert_eq!(d.figures.link_ratio as f32, map.columns.link_ratio[k]);
            prop_assert_eq!(d.acceptable, map.columns.acceptable[k]);
            prop_assert!((d.sixbar.link_ratio() - d.figures.link_ratio).abs() < 1e-9 * d.figures.link_ratio);
            prop_assert!((d.sixbar.time_ratio().unwrap() - d.figures.time_ratio).abs() < 1e-9 * d.figures.time_ratio);
            let [md, mm] = d.sixbar.min_transmission_angles().unwrap();
            prop_assert!((md - d.figures.drive_transmission).abs() < 1e-9);
            prop_assert!((mm - d.figures.motion_transmission).abs() < 1e-9);
            check_against_map(&task, &d, &map);
        }
        // Where the map says there is no drive, there is none.
        if let Some(k) = (0..map.columns.valid.len()).find(|&k| !map.columns.valid[k]) {
            let e = ctx.drive_at(k).unwrap_err();
            prop_assert!(matches!(e, Error::Drive(DriveError::NotACrankRocker { .. })), "{}", e);
        }
    }
}

/// A time-ratio-1 crank-rocker against the textbook.
///
/// Norton, *Design of Machinery* (5th ed.), Example 3-1 ("Rocker output,
/// two positions with angular displacement"): "Design a fourbar Grashof
/// crank-rocker to give 45 degrees of rocker rotation with equal time
/// forward and back, from a constant speed motor input." The construction:
/// draw the rocker `O4 B` in its two extreme positions `B1`, `B2`, 45
/// degrees apart; draw the chord `B1 B2` and extend it; pick `O2` on the
/// extension; the crank is half of `B1 B2`, the coupler `O2` to the chord's
/// midpoint; check Grashof. Brodell and Soni ("Design of the crank-rocker
/// mechanism with unit time ratio", J. Mechanisms 5, 1970; Uicker, Pennock
/// and Shigley, *Theory of Machines and Mechanisms*, §10 on crank-rocker
/// design) give the same linkage in closed form for a chosen transmission
/// angle `gamma`, ground as unit: `r3/r1 = sqrt((1 - cos phi) / (2 cos^2
/// gamma))`, `r4/r1 = sqrt((1 - (r3/r1)^2) / (1 - (r3/r1)^2 cos^2 gamma))`,
/// `r2/r1 = r4/r1 sqrt((1 - cos phi) / 2)`.
///
/// The book's own drawing picks `O2` by hand, so its link lengths are not
/// a property of the problem; what the problem fixes (45 degrees, equal
/// times) and both constructions are checked: each linkage is then run
/// through a full turn by the position analysis, whose rocker must swing
/// 45 degrees with the crank turning 180 degrees each way.
#[test]
fn closed_form_crank_rocker_is_the_textbook_one() {
    let swing = 45f64.to_radians();
    for gamma_deg in [30.0f64, 40.0, 50.0, 60.0] {
        let gamma = gamma_deg.to_radians();
        let d = CrankRockerDesign::unit_time_ratio(1.0, swing, gamma).unwrap();
        // Brodell and Soni, ground as unit.
        let r3 = ((1.0 - swing.cos()) / (2.0 * gamma.cos().powi(2))).sqrt();
        let r4 = ((1.0 - r3 * r3) / (1.0 - r3 * r3 * gamma.cos().powi(2))).sqrt();
        let r2 = r4 * ((1.0 - swing.cos()) / 2.0).sqrt();
        let k = d.ground;
        assert!((d.coupler / k - r3).abs() < 1e-12, "{gamma_deg}: coupler");
        assert!((d.rocker / k - r4).abs() < 1e-12, "{gamma_deg}: rocker");
        assert!((d.crank / k - r2).abs() < 1e-12, "{gamma_deg}: crank");
        // Norton's construction: crank is half the chord B1 B2.
        assert!((d.crank - (22.5f64).to_radians().sin()).abs() < 1e-15);
        // Run it: the rocker swings 45 degrees, the crank turns 180 degrees
        // each way, the smallest transmission angle is gamma.
        let fb = FourBar::new(d.ground, d.crank, d.coupler, d.rocker).unwrap();
        assert_eq!(fb.grashof(), burmester::Grashof::CrankRocker);
        let steps = 720_000;
        let (mut lo, mut hi) = ((f64::INFINITY, 0.0), (f64::NEG_INFINITY, 0.0));
        let mut mu = f64::INFINITY;
        for s in 0..steps {
            let t = TAU * s as f64 / steps as f64;
            let c = fb.solve(t, AssemblyMode::Open).unwrap();
            if c.theta4 < lo.0 {
                lo = (c.theta4, t);
            }
            if c.theta4 > hi.0 {
                hi = (c.theta4, t);
            }
            mu = mu.min(c.transmission_angle());
        }
        assert!(
            (hi.0 - lo.0 - swing).abs() < 1e-9,
            "{gamma_deg}: swing {}",
            hi.0 - lo.0
        );
        let stroke = (hi.1 - lo.1).rem_euclid(TAU);
        assert!(
            (stroke - PI).abs() < 2.0 * TAU / steps as f64,
            "{gamma_deg}: stroke {stroke}"
        );
        assert!((mu - gamma).abs() < 1e-9, "{gamma_deg}: mu {mu}");
    }
}

/// The classic drive of a linkage: time ratio 1 and the drive transmission
/// asked for, which the map's own sample confirms.
#[test]
fn the_classic_drive_is_confirmed_by_the_map() {
    let mut runner = TestRunner::new(common::config(1));
    let mut done = 0;
    for case in 0..12 {
        let (task, sfb) = swinging_task(&mut runner, 3 + case % 3);
        let Some(ctx) = random_context(&mut runner, &sfb, 0.02) else {
            continue;
        };
        let [sa, sb] = ctx.swing();
        let best = PI / 2.0 - 0.5 * (sb - sa).abs();
        for beyond_first in [true, false] {
            let mu = 0.6 * best;
            let d = ctx.classic(beyond_first, Some(mu)).unwrap();
            assert!(
                (d.figures.time_ratio - 1.0).abs() < 1e-9,
                "{}",
                d.figures.time_ratio
            );
            assert!((d.figures.drive_transmission - mu).abs() < 1e-9);
            assert!((d.figures.stroke - PI).abs() < 1e-9);
            // The map at that very point (a one-sample grid about it).
            let p = d.drive_pivot;
            let g =
                Grid::from_bounds(p.x - 1e-3, p.x + 1e-3, p.y - 1e-3, p.y + 1e-3, 1, 1).unwrap();
            let m = ctx.with_grid(&g).map(&Control::new()).unwrap();
            assert!(m.columns.valid[0]);
            assert!((f64::from(m.columns.time_ratio[0]) - 1.0).abs() < 1e-6);
            assert!((f64::from(m.columns.drive_transmission_rad[0]) - mu).abs() < 1e-6);
            let got = check_drive(&task, &d, 6000);
            assert!((got.drive_min - mu).abs() < 1e-6);
            done += 1;
        }
        let e = ctx.classic(true, Some(best + 1e-6)).unwrap_err();
        assert!(matches!(e, Error::InvalidInput(_)), "{e}");
    }
    assert!(done >= 16, "{done}");
}

/// The built-in example's best-transmission linkage is a triple-rocker;
/// `best_drive` finds it a motor drive that passes the independent check.
#[test]
fn the_examples_triple_rocker_gets_a_motor() {
    let task = burmester::example::task();
    let f = task.filemon(burmester::example::driven_center()).unwrap();
    let grid = Grid::new(burmester::example::viewport(), 400, 400).unwrap();
    let limits = DesignLimits {
        min_transmission: 30f64.to_radians(),
        ..DesignLimits::default()
    };
    let options = MapOptions::new(&limits, &Constraints::none()).unwrap();
    let map = f.solution_map(&grid, &options, &Control::new()).unwrap();
    let best = map
        .best_pivots(Ranking::new(1, RankBy::Transmission))
        .unwrap();
    let sfb = best[0].linkage;
    assert_eq!(sfb.figures.grashof, burmester::Grashof::TripleRocker);
    let d = balanced_drive(&sfb, &limits).unwrap();
    assert!(d.acceptable && d.sixbar.crank_turns_fully());
    assert!(d.figures.min_transmission >= limits.min_transmission);
    let got = check_drive(&task, &d, 20_000);
    assert!((got.drive_min - d.figures.drive_transmission).abs() < 1e-6);
    assert!((got.motion_min - d.figures.motion_transmission).abs() < 1e-6);
}

/// Why there is no drive: typed errors with what to change.
#[test]
fn no_drive_says_why() {
    let mut runner = TestRunner::new(common::config(1));
    let (_, sfb) = swinging_task(&mut runner, 3);
    let a0 = sfb.driving.center;
    let grid = Grid::from_bounds(a0.x - 1.0, a0.x + 1.0, a0.y - 1.0, a0.y + 1.0, 8, 8).unwrap();
    let none = Constraints::none();
    let limits = DesignLimits::default();
    let map_options = MapOptions::new(&limits, &none).unwrap();
    let ctx = |e: P, margin: f64| {
        let o = DriveOptions {
            swing_margin: margin,
            ..DriveOptions::default()
        };
        DriveContext::new(&sfb, e, &grid, &map_options, &o)
    };
    // The attachment on A0.
    let e = ctx(a0, 0.0).unwrap_err();
    assert_eq!(e.cause(), "zero_length_link");
    // A margin past the dead positions.
    let e = ctx(sfb.driving.circle, 1.5).unwrap_err();
    assert!(
        matches!(
            e,
            Error::Drive(DriveError::OutsideInputRange { .. } | DriveError::TravelTooLarge { .. })
        ),
        "{e}"
    );
    assert!(e.to_string().contains("swing_margin_deg"), "{e}");
    // Bad options.
    for o in [
        DriveOptions {
            swing_margin: -0.1,
            ..DriveOptions::default()
        },
        DriveOptions {
            swing_margin: f64::NAN,
            ..DriveOptions::default()
        },
        DriveOptions {
            max_time_ratio: 0.5,
            ..DriveOptions::default()
        },
    ] {
        let e = DriveContext::new(&sfb, sfb.driving.circle, &grid, &map_options, &o).unwrap_err();
        assert!(matches!(e, Error::InvalidInput(_)), "{e}");
    }
    let e = ctx(Point2::new(f64::NAN, 0.0), 0.0).unwrap_err();
    assert!(matches!(e, Error::InvalidInput(_)), "{e}");
    // A linkage with a branch defect has no travel.
    let t = burmester::example::task();
    let f = t.filemon(burmester::example::driven_center()).unwrap();
    let bad = (0..400)
        .map(|k| Point2::new(-7.5 + 0.04 * k as f64, 3.3))
        .filter_map(|p| f.four_bar(p).ok())
        .find(|l| !l.is_branch_free())
        .unwrap();
    // What a linkage's context at its own driving circle point refuses.
    let refused = |l: &SynthesizedFourBar| {
        let o = DriveOptions::default();
        DriveContext::new(l, l.driving.circle, &grid, &map_options, &o).unwrap_err()
    };
    assert_eq!(refused(&bad), Error::Drive(DriveError::NoTravel));
    // A crank that turns more than half a turn between the poses.
    let crank = FourBar::new(4.0, 1.0, 3.0, 3.0).unwrap();
    let (t1, t2, t3) = (0.0f64, 1.6, 3.3);
    let mut poses = Vec::new();
    for t in [t1, t2, t3] {
        let c = crank.solve(t, AssemblyMode::Open).unwrap();
        let p = crank.joints(&c).coupler_point(Vector2::new(1.0, 0.5));
        poses.push([p.x, p.y, c.theta3]);
    }
    let task = Task::from_xya(&poses).unwrap();
    let j = crank.joints_at(t1, AssemblyMode::Open).unwrap();
    let l = task
        .four_bar(
            &Dyad::new(j.input_pivot, j.crank_joint),
            &Dyad::new(j.output_pivot, j.rocker_joint),
        )
        .unwrap();
    assert!(l.figures.feasible() && l.figures.input_full);
    let e = refused(&l);
    assert!(
        matches!(e, Error::Drive(DriveError::TravelTooLarge { .. })),
        "{e}"
    );
    // Nothing acceptable: the error carries what was found.
    let strict = DesignLimits {
        min_transmission: 89f64.to_radians(),
        ..DesignLimits::default()
    };
    let e = balanced_drive(&sfb, &strict).unwrap_err();
    match e {
        Error::Drive(DriveError::NoAcceptableDrive {
            searched,
            valid,
            best_transmission_deg,
            ..
        }) => {
            assert!(searched > 0 && valid > 0 && best_transmission_deg < 89.0);
        }
        other => panic!("{other}"),
    }
}

/// Base plate and obstacles over the whole crank turn, against direct
/// geometry at dense crank angles.
#[test]
fn constraints_hold_over_the_whole_turn() {
    let mut runner = TestRunner::new(common::config(1));
    let (_, sfb) = swinging_task(&mut runner, 3);
    let a0 = sfb.driving.center;
    let e = sfb.driving.circle;
    let rho = (e - a0).norm();
    let h = 4.0 * rho;
    let grid = Grid::from_bounds(a0.x - h, a0.x + h, a0.y - h, a0.y + h, 40, 40).unwrap();
    // A half-plane base plate (x above A0's) and a square obstacle.
    let plate = vec![
        Point2::new(a0.x, a0.y - 10.0 * h),
        Point2::new(a0.x + 10.0 * h, a0.y - 10.0 * h),
        Point2::new(a0.x + 10.0 * h, a0.y + 10.0 * h),
        Point2::new(a0.x, a0.y + 10.0 * h),
    ];
    // A small square about the valid crank pivot on the plate's side that
    // is farthest from the linkage: drives near it collide (their crank
    // sweeps it), the others may not.
    let far = |q: P| {
        [
            sfb.driving.center,
            sfb.driving.circle,
            sfb.driven.center,
            sfb.driven.circle,
        ]
        .iter()
        .map(|p| (p - q).norm())
        .fold(f64::INFINITY, f64::min)
    };
    let probe = anything_context(&sfb, e, &grid, &Constraints::none())
        .unwrap()
        .map(&Control::new())
        .unwrap();
    let o = (0..grid.len())
        .filter(|&k| probe.columns.valid[k])
        .map(|k| grid_point(&grid, k))
        .filter(|p| p.x > a0.x + 0.5 * rho)
        .max_by(|p, q| far(*p).total_cmp(&far(*q)))
        .expect("a valid pivot on the plate's side");
    let s = 0.3 * rho;
    let obstacle = vec![
        o + Vector2::new(-s, -s),
        o + Vector2::new(s, -s),
        o + Vector2::new(s, s),
        o + Vector2::new(-s, s),
    ];
    let constraints = Constraints {
        base_plate: Some(plate),
        obstacles: vec![obstacle.clone()],
        link_width: 0.0,
        travel_samples: 64,
        envelope: None,
    };
    let ctx = anything_context(&sfb, e, &grid, &constraints).unwrap();
    let free = anything_context(&sfb, e, &grid, &Constraints::none()).unwrap();
    // An envelope would go unchecked over the crank's turn: refused.
    let big = 1e6;
    let with_envelope = Constraints {
        envelope: Some(vec![
            P::new(-big, -big),
            P::new(big, -big),
            P::new(big, big),
            P::new(-big, big),
        ]),
        ..Constraints::none()
    };
    let refused = anything_context(&sfb, e, &grid, &with_envelope);
    assert!(
        matches!(&refused, Err(burmester::Error::InvalidInput(burmester::InvalidInput::UnknownName { found, .. })) if found == "envelope"),
        "{refused:?}"
    );
    let map = ctx.map(&Control::new()).unwrap();
    let base = free.map(&Control::new()).unwrap();
    // Whether the segment a-b meets the open square (Liang-Barsky clipping).
    let seg_hits = |a: P, b: P| {
        let dd = b - a;
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (p, q) in [
            (-dd.x, a.x - (o.x - s)),
            (dd.x, (o.x + s) - a.x),
            (-dd.y, a.y - (o.y - s)),
            (dd.y, (o.y + s) - a.y),
        ] {
            if p == 0.0 {
                if q <= 0.0 {
                    return false;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
            }
        }
        t0 < t1
    };
    let (mut hit, mut clear) = (0, 0);
    let candidates: Vec<usize> = (0..grid.len())
        .filter(|&k| base.columns.acceptable[k])
        .collect();
    for k in 0..grid.len() {
        if !base.columns.acceptable[k] {
            assert!(!map.columns.acceptable[k]);
        }
    }
    // The 60 nearest the obstacle and 60 spread over the rest.
    let mut by_distance = candidates.clone();
    by_distance.sort_by(|&p, &q| {
        (grid_point(&grid, p) - o)
            .norm()
            .total_cmp(&(grid_point(&grid, q) - o).norm())
    });
    let (near, rest) = by_distance.split_at(by_distance.len().min(60));
    let checked: Vec<usize> = near
        .iter()
        .chain(rest.iter().step_by((rest.len() / 60).max(1)))
        .copied()
        .collect();
    for &k in &checked {
        let d = ctx.drive_at(k).unwrap();
        if d.drive_pivot.x <= a0.x {
            assert!(!map.columns.acceptable[k], "off the plate");
            continue;
        }
        // Direct: dense crank angles, exact segment tests of the links
        // found from the motion.
        let links = moving_links(&d.sixbar);
        let collides = (0..2000).any(|s| {
            let j = d.sixbar.joints_at(TAU * s as f64 / 2000.0).unwrap();
            let j = j.to_array();
            links.iter().any(|&(a, b)| seg_hits(j[a], j[b]))
        });
        if collides {
            assert!(
                !map.columns.acceptable[k],
                "a collision was accepted at {k}"
            );
            hit += 1;
        } else if map.columns.acceptable[k] {
            clear += 1;
        }
    }
    assert!(hit > 0 && clear > 0, "hit {hit}, clear {clear}");
}

fn grid_point(g: &Grid, k: usize) -> P {
    g.point(k % g.nx(), k / g.nx())
}

/// The moving links of `six` found from its motion, independently of the
/// library's list of them: the pairs of its joints (`D0 D E A0 A C C0`, in
/// [`SixBarJoints::to_array`]'s order; not the coupler point) whose
/// distance stays the same over a crank turn, but for the pairs of fixed
/// pivots (the ground), each segment once. Seven where no joints
/// coincide: the drive crank, the drive coupler, the input link's three
/// sides, the coupler and the rocker; fewer where they do (an attachment
/// `E` at the input joint `A`: `A0 A` is `A0 E`, `A E` a point, six).
fn moving_links(six: &SixBar) -> Vec<(usize, usize)> {
    const FIXED: [usize; 3] = [0, 3, 6];
    let turn: Vec<[P; 8]> = (0..16)
        .map(|s| six.joints_at(TAU * s as f64 / 16.0).unwrap().to_array())
        .collect();
    let scale = six.size();
    let near = |p: P, q: P| (p - q).norm() <= 1e-9 * scale;
    let mut links: Vec<(usize, usize)> = Vec::new();
    for a in 0..7 {
        for b in a + 1..7 {
            if FIXED.contains(&a) && FIXED.contains(&b) {
                continue;
            }
            let d0 = (turn[0][a] - turn[0][b]).norm();
            let rigid = turn
                .iter()
                .all(|j| ((j[a] - j[b]).norm() - d0).abs() <= 1e-9 * scale);
            let (p, q) = (turn[0][a], turn[0][b]);
            let again = links.iter().any(|&(c, d)| {
                let (r, s) = (turn[0][c], turn[0][d]);
                (near(p, r) && near(q, s)) || (near(p, s) && near(q, r))
            });
            if rigid && !again {
                links.push((a, b));
            }
        }
    }
    // Every moving joint (D, E, A, C) is on a link.
    for j in [1, 2, 4, 5] {
        assert!(
            links.iter().any(|&(a, b)| a == j || b == j),
            "joint {j} on no link: {links:?}"
        );
    }
    links
}

/// The attachment search returns drives best first, each the best of its
/// attachment's map; progress covers every map and Ctrl-C stops it.
#[test]
fn attachment_search_ranks_and_stops() {
    let mut runner = TestRunner::new(common::config(1));
    let (_, sfb) = swinging_task(&mut runner, 4);
    let search = AttachmentSearch {
        ratios: vec![0.5, 1.0, 2.0],
        angles: vec![0.0, 1.0, 2.0, -2.0],
        reach: 4.0,
        samples: 32,
    };
    let last = AtomicUsize::new(0);
    let hook = |d: usize, t: usize| {
        assert!(d <= t && t == 12 * 32);
        last.fetch_max(d, Ordering::Relaxed);
    };
    let found = search_anything(
        &sfb,
        &search,
        RankBy::Balanced,
        &Control::new().with_progress(&hook),
    )
    .unwrap();
    assert_eq!(last.load(Ordering::Relaxed), 12 * 32);
    assert!(!found.drives.is_empty());
    for w in found.drives.windows(2) {
        assert!(w[0].score >= w[1].score);
    }
    assert_eq!(found.searched, 12 * 32 * 32);
    // Cancelled after the first progress report.
    let stop = AtomicBool::new(false);
    let hook = |_: usize, _: usize| stop.store(true, Ordering::Relaxed);
    let e = search_anything(
        &sfb,
        &search,
        RankBy::Balanced,
        &Control::new().with_cancel(&stop).with_progress(&hook),
    )
    .unwrap_err();
    assert!(
        matches!(e, Error::Cancelled { done, total } if done < total),
        "{e}"
    );
    // Rankings without a score are refused.
    let e = search_anything(&sfb, &search, RankBy::Pareto, &Control::new()).unwrap_err();
    assert!(matches!(e, Error::InvalidInput(_)));
    let mut bad = search.clone();
    bad.samples = DriveContext::MAX_SEARCH_SAMPLES + 1;
    assert!(bad.validate().is_err());
    bad.samples = 1;
    bad.ratios = vec![f64::NAN];
    assert!(bad.validate().is_err());
}

/// At the documented maxima: the largest grid (cancelled at once, or out of
/// memory, never an abort), the most search samples, the most crank
/// angles; and a map cancelled midway says how far it got.
#[test]
fn documented_maxima_and_cancelling() {
    let mut runner = TestRunner::new(common::config(1));
    let (_, sfb) = swinging_task(&mut runner, 3);
    let side = (Grid::MAX_POINTS as f64).sqrt() as usize;
    let a0 = sfb.driving.center;
    let big =
        Grid::from_bounds(a0.x - 4.0, a0.x + 4.0, a0.y - 4.0, a0.y + 4.0, side, side).unwrap();
    let ctx = DriveContext::new(
        &sfb,
        sfb.driving.circle,
        &big,
        &MapOptions::new(&DesignLimits::default(), &Constraints::none()).unwrap(),
        &DriveOptions::default(),
    )
    .unwrap();
    let stop = AtomicBool::new(true);
    let r = ctx.map(&Control::new().with_cancel(&stop));
    assert!(
        matches!(
            r,
            Err(Error::Cancelled { done: 0, .. }) | Err(Error::OutOfMemory { .. })
        ),
        "{:?}",
        r.err()
    );
    // A map cancelled after its first block.
    let g = Grid::from_bounds(a0.x - 4.0, a0.x + 4.0, a0.y - 4.0, a0.y + 4.0, 512, 512).unwrap();
    let stop = AtomicBool::new(false);
    let hook = |_: usize, _: usize| stop.store(true, Ordering::Relaxed);
    let e = ctx
        .with_grid(&g)
        .map(&Control::new().with_cancel(&stop).with_progress(&hook))
        .unwrap_err();
    assert!(
        matches!(e, Error::Cancelled { done, total: 512 } if done < 512),
        "{e}"
    );
    // The most samples of a search side, on one attachment.
    let search = AttachmentSearch {
        ratios: vec![1.0],
        angles: vec![0.0],
        reach: 4.0,
        samples: DriveContext::MAX_SEARCH_SAMPLES,
    };
    let found = search_anything(&sfb, &search, RankBy::Compact, &Control::new()).unwrap();
    assert_eq!(found.searched, DriveContext::MAX_SEARCH_SAMPLES.pow(2));
    // The most crank angles of a turn.
    if let Some(d) = found.drives.first() {
        let a = d.turn_angles(SixBar::MAX_SAMPLES).unwrap();
        assert_eq!(a.len(), SixBar::MAX_SAMPLES);
        assert!(d.turn_angles(SixBar::MAX_SAMPLES + 1).is_err());
        assert!(d.sixbar.crank_angles(0.0, SixBar::MAX_SAMPLES).is_ok());
        assert!(d.sixbar.crank_angles(0.0, 1).is_err());
    }
    // The most attachments.
    let n = AttachmentSearch::MAX_ATTACHMENTS;
    let many = AttachmentSearch {
        ratios: vec![1.0; n],
        angles: vec![0.0],
        ..AttachmentSearch::default()
    };
    assert!(many.validate().is_ok());
    let too_many = AttachmentSearch {
        ratios: vec![1.0; n + 1],
        ..many
    };
    assert!(too_many.validate().is_err());
}

/// Moving, rotating and scaling the task moves, rotates and scales the
/// drive map's figures (to rounding).
#[test]
fn figures_are_invariant_under_similarities() {
    let mut runner = TestRunner::new(common::config(1));
    let (task, sfb) = swinging_task(&mut runner, 3);
    let e = sfb.driving.circle;
    let (k, ang, off) = (3.7f64, 0.9f64, Vector2::new(5.0, -2.0));
    let tf = |p: P| Point2::from(rotate(p.coords, ang) * k + off);
    let (_, s2) = common::moved_linkage(&task, &sfb, tf, ang);
    let a0 = sfb.driving.center;
    for d0 in [
        a0 + Vector2::new(1.3, 2.9),
        a0 + Vector2::new(-2.2, 0.7),
        a0 + Vector2::new(0.4, -3.1),
    ] {
        let g = Grid::from_bounds(-1.0, 1.0, -1.0, 1.0, 1, 1).unwrap();
        let c1 = anything_context(&sfb, e, &g, &Constraints::none()).unwrap();
        let c2 = anything_context(&s2, tf(e), &g, &Constraints::none()).unwrap();
        match (c1.drive(d0), c2.drive(tf(d0))) {
            (Ok(x), Ok(y)) => {
                let (f, h) = (x.figures, y.figures);
                assert!((f.min_transmission - h.min_transmission).abs() < 1e-9);
                assert!((f.time_ratio - h.time_ratio).abs() < 1e-9);
                assert!((f.size_ratio - h.size_ratio).abs() < 1e-9 * f.size_ratio);
                assert!((f.link_ratio - h.link_ratio).abs() < 1e-9 * f.link_ratio);
                for (p, q) in x.pose_crank_angles.iter().zip(y.pose_crank_angles.iter()) {
                    assert!(wrap(q - p - ang).abs() < 1e-9);
                }
            }
            (Err(_), Err(_)) => {}
            (a, b) => panic!("{:?} vs {:?}", a.err(), b.err()),
        }
    }
}

/// A six-bar built from joints solves back to them, and refuses bad joints
/// with typed errors.
#[test]
fn sixbar_from_joints_and_bad_input() {
    let j = SixBarJoints {
        drive_pivot: Point2::new(-1.0, 3.0),
        crank_joint: Point2::new(-0.6, 3.0),
        attachment: Point2::new(2.0 * 0.7f64.cos(), 2.0 * 0.7f64.sin()),
        input_pivot: Point2::new(0.0, 0.0),
        input_joint: Point2::new(2.0 * 0.7f64.cos(), 2.0 * 0.7f64.sin()),
        rocker_joint: Point2::new(2.6, 0.9),
        output_pivot: Point2::new(3.0, 0.0),
        coupler_point: Point2::new(2.0, 1.5),
    };
    let six = SixBar::from_joints(&j).unwrap();
    let c = six.solve(0.0).unwrap();
    let back = six.joints(&c);
    for (p, q) in back.to_array().iter().zip(j.to_array().iter()) {
        assert!((p - q).norm() < 1e-12, "{p} vs {q}");
    }
    let mut bad = j;
    bad.crank_joint = bad.drive_pivot;
    assert_eq!(
        SixBar::from_joints(&bad).unwrap_err().cause(),
        "zero_length_link"
    );
    let mut bad = j;
    bad.coupler_point.x = f64::INFINITY;
    assert!(matches!(
        SixBar::from_joints(&bad),
        Err(Error::InvalidInput(_))
    ));
    // A drive loop at a toggle: E on the line A0 D... coupler and rocker collinear.
    let mut bad = j;
    let d = bad.crank_joint;
    bad.attachment = Point2::from(d.coords * (2.0 / d.coords.norm()));
    bad.input_joint = bad.attachment;
    assert_eq!(
        SixBar::from_joints(&bad).unwrap_err().cause(),
        "toggle_joints"
    );
    // A drive whose output pivot is not A0.
    let drive =
        FourBar::from_pivots(Point2::new(-1.0, 3.0), Point2::new(0.5, 0.0), 0.4, 3.0, 2.0).unwrap();
    let e = open_six_bar(drive, &six).unwrap_err();
    assert_eq!(e.cause(), "pivot_mismatch");
    // Beyond the drive's reach: the error of the loop.
    let drive =
        FourBar::from_pivots(Point2::new(-1.0, 3.0), Point2::new(0.0, 0.0), 2.5, 1.0, 2.0).unwrap();
    let six2 = open_six_bar(drive, &six).unwrap();
    assert!(!six2.crank_turns_fully());
    assert!(six2.min_transmission_angles().is_none());
    assert!(!six2.dead_positions().is_empty());
    assert!((0..360).any(|k| six2.solve((k as f64).to_radians()).is_err()));
}

/// The six-bar's size over the task's and its longest link, from its own
/// link lengths (not the map's columns).
fn sixbar_size(task: &Task, d: &Drive) -> (f64, f64) {
    let longest = d.sixbar.lengths().links().into_iter().fold(0.0, f64::max);
    (d.sixbar.size() / task.span(), longest)
}

/// Under finite size limits (the six-bar's size ratio and longest link), a
/// drive map accepts no sample whose six-bar, built as a drive, is larger,
/// and accepts every sample comfortably inside them that it accepts
/// without them.
#[test]
fn size_limits_bound_every_acceptable_drive() {
    let mut runner = TestRunner::new(common::config(1));
    let (mut inside, mut cut, mut cases) = (0usize, 0usize, 0usize);
    for case in 0..8 {
        let (task, sfb) = swinging_task(&mut runner, 3 + case % 3);
        let Some(free) = random_context(&mut runner, &sfb, 0.0) else {
            continue;
        };
        let fmap = free.map(&Control::new()).unwrap();
        // Limits through the middle of the valid drives.
        let (mut sizes, mut longest) = (Vec::new(), Vec::new());
        for k in (0..free.grid().len()).step_by(5) {
            if fmap.columns.valid[k] {
                let (s, l) = sixbar_size(&task, &free.drive_at(k).unwrap());
                sizes.push(s);
                longest.push(l);
            }
        }
        if sizes.len() < 10 {
            continue;
        }
        cases += 1;
        sizes.sort_by(f64::total_cmp);
        longest.sort_by(f64::total_cmp);
        let (max_size, max_link) = (sizes[sizes.len() / 2], longest[longest.len() * 2 / 3]);
        let limits = anything().with_size(max_size, max_link).unwrap();
        let ctx = DriveContext::new(
            &sfb,
            free.attachment(),
            free.grid(),
            &MapOptions::new(&limits, &Constraints::none()).unwrap(),
            &DriveOptions::default(),
        )
        .unwrap();
        let map = ctx.map(&Control::new()).unwrap();
        for k in 0..ctx.grid().len() {
            if !map.columns.valid[k] {
                continue;
            }
            let d = ctx.drive_at(k).unwrap();
            let (s, l) = sixbar_size(&task, &d);
            assert_eq!(d.acceptable, map.columns.acceptable[k]);
            if map.columns.acceptable[k] {
                assert!(s <= max_size * (1.0 + 1e-9), "size {s} over {max_size}");
                assert!(l <= max_link * (1.0 + 1e-12), "link {l} over {max_link}");
                inside += 1;
            } else if fmap.columns.acceptable[k]
                && s < max_size * (1.0 - 1e-9)
                && l < max_link * (1.0 - 1e-12)
            {
                panic!("sample {k} is inside the size limits but not acceptable");
            } else {
                cut += 1;
            }
        }
        // The best drive under the limits keeps them too.
        if let Ok(d) = balanced_drive(&sfb, &limits) {
            let (s, l) = sixbar_size(&task, &d);
            assert!(s <= max_size * (1.0 + 1e-9) && l <= max_link * (1.0 + 1e-12));
        }
    }
    eprintln!("{cases} maps: {inside} samples inside the size limits, {cut} cut");
    assert!(
        cases >= 4 && inside > 100 && cut > 100,
        "{cases} {inside} {cut}"
    );
}

/// A design search with a motor on the example by the balanced score
/// (whose second design on these small coarse grids is a triple-rocker,
/// its input swinging 56 degrees): small coarse grids, few starts.
fn motor_options(motor: DriveOptions, input: burmester::InputRequirement) -> DesignOptions {
    DesignOptions {
        rank_by: RankBy::Balanced,
        coarse_driven: 5,
        coarse_driving: 16,
        starts: 12,
        limits: DesignLimits {
            input,
            ..DesignLimits::default()
        },
        motor: Some(motor),
        ..DesignOptions::default()
    }
}

/// With a motor every design either turns fully or has a drive whose
/// six-bar, driven through a full crank turn by this file's own solver,
/// reaches every pose in order on one stroke with both loops' transmission
/// angles at least the limit; the designs are those of the search without
/// a motor when none is passed over.
#[test]
fn design_with_a_motor_turns_every_design() {
    let task = burmester::example::task();
    let options = motor_options(DriveOptions::default(), burmester::InputRequirement::Any);
    let report = task.design(&options, &Control::new()).unwrap();
    assert!(!report.designs.is_empty());
    assert_eq!(report.motor, Some(DriveOptions::default()));
    let limit = report.limits.min_transmission;
    let mut driven = 0;
    for d in &report.designs {
        let f = &d.linkage.four_bar().unwrap().figures;
        match &d.drive {
            None => assert!(f.input_full, "a swinging design without a drive"),
            Some(drive) => {
                assert!(!f.input_full, "a drive for a crank");
                assert_eq!(&drive.linkage, d.linkage.four_bar().unwrap());
                assert!(drive.acceptable && drive.sixbar.crank_turns_fully());
                let got = check_drive(&task, drive, 20_000);
                assert!(
                    got.drive_min >= limit - 1e-9,
                    "drive loop {}",
                    got.drive_min
                );
                assert!(
                    got.motion_min >= limit - 1e-9,
                    "motion loop {}",
                    got.motion_min
                );
                assert!((got.drive_min - drive.figures.drive_transmission).abs() < 1e-6);
                assert!((got.motion_min - drive.figures.motion_transmission).abs() < 1e-6);
                driven += 1;
            }
        }
    }
    assert!(driven >= 1, "no design needed a drive");
    eprintln!(
        "{} designs, {driven} driven, {} passed over",
        report.designs.len(),
        report.undriven
    );
    if report.undriven == 0 {
        let plain = task
            .design(
                &DesignOptions {
                    motor: None,
                    ..options.clone()
                },
                &Control::new(),
            )
            .unwrap();
        let a: Vec<_> = plain.designs.iter().map(|d| d.linkage).collect();
        let b: Vec<_> = report.designs.iter().map(|d| d.linkage).collect();
        assert_eq!(a, b, "a motor changed the designs without passing any over");
        assert!(plain.designs.iter().all(|d| d.drive.is_none()));
    }
}

/// A time ratio no drive reaches (1 with a swing margin) passes every
/// swinging design over: counted, fewer designs, never an error; with a
/// rocker input required nothing is left.
#[test]
fn impossible_drives_are_passed_over() {
    let task = burmester::example::task();
    let impossible = DriveOptions::from_degrees(5.0, 1.0).unwrap();
    let feasible = task
        .design(
            &motor_options(DriveOptions::default(), burmester::InputRequirement::Any),
            &Control::new(),
        )
        .unwrap();
    let any = task
        .design(
            &motor_options(impossible, burmester::InputRequirement::Any),
            &Control::new(),
        )
        .unwrap();
    assert!(any.undriven >= 1, "nothing passed over");
    assert!(
        any.designs
            .iter()
            .all(|d| d.linkage.input_full() && d.drive.is_none())
    );
    let swinging = feasible
        .designs
        .iter()
        .filter(|d| d.drive.is_some())
        .count();
    assert!(swinging >= 1);
    assert!(any.designs.len() <= feasible.designs.len());
    let rockers = task
        .design(
            &motor_options(impossible, burmester::InputRequirement::Rocker),
            &Control::new(),
        )
        .unwrap();
    assert!(rockers.designs.is_empty() && rockers.undriven >= 1);
    // The input requirement still filters the four-bars: cranks need no
    // drive.
    let cranks = task
        .design(
            &motor_options(impossible, burmester::InputRequirement::Crank),
            &Control::new(),
        )
        .unwrap();
    assert_eq!(cranks.undriven, 0);
    assert!(cranks.designs.iter().all(|d| d.linkage.input_full()));
}

/// The motor's options are checked, the most designs are allowed, and a
/// cancelled search says so.
#[test]
fn motor_design_bounds_and_cancelling() {
    let task = burmester::example::task();
    let bad = DesignOptions {
        motor: Some(DriveOptions {
            swing_margin: -0.1,
            max_time_ratio: 2.0,
        }),
        ..DesignOptions::default()
    };
    let e = task.design(&bad, &Control::new()).unwrap_err();
    assert!(e.to_string().contains("swing_margin"), "{e}");
    let bad = DesignOptions {
        motor: Some(DriveOptions {
            swing_margin: 0.0,
            max_time_ratio: 0.5,
        }),
        ..DesignOptions::default()
    };
    let e = task.design(&bad, &Control::new()).unwrap_err();
    assert!(e.to_string().contains("max_time_ratio"), "{e}");
    // The most designs.
    let most = DesignOptions {
        top: DesignOptions::MAX_TOP,
        ..motor_options(DriveOptions::default(), burmester::InputRequirement::Any)
    };
    let r = task.design(&most, &Control::new()).unwrap();
    assert!(!r.designs.is_empty() && r.designs.len() <= DesignOptions::MAX_TOP);
    assert!(
        r.designs
            .iter()
            .all(|d| d.linkage.input_full() || d.drive.is_some())
    );
    let too_many = DesignOptions {
        top: DesignOptions::MAX_TOP + 1,
        ..most.clone()
    };
    assert!(task.design(&too_many, &Control::new()).is_err());
    let stop = AtomicBool::new(true);
    let e = task
        .design(&most, &Control::new().with_cancel(&stop))
        .unwrap_err();
    assert!(matches!(e, Error::Cancelled { .. }), "{e}");
}
