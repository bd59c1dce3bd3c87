//! The branch problem with a slider as the driven dyad (issue 27, part 2):
//! Filemon's lines through `C1` in the directions `n_k`, their exact
//! transforms into the driving crank's center-point plane, the branch map,
//! and the four-pose arcs, checked against
//!
//! * tasks made from known slider-cranks (the generating crank is free);
//! * an independent slider-crank solver written here (crank `A0 A`,
//!   coupler `A B`, `B` on the guide), driven densely by crank angle from
//!   pose to pose: which assembly mode reaches each pose, and whether the
//!   crank can turn there without a dead position;
//! * the revolute construction with `C0 = C1 + R n`, `R -> ∞` (a second
//!   method that must agree in the limit);
//! * the circle-point-plane classification (thousands of random samples);
//! * moving, rotating and scaling the task.

use std::f64::consts::{PI, TAU};

use burmester::Ranking;
use burmester::{
    Branch, Control, Dyad, DyadKind, Error, Filemon, FilemonLines, Grid, InvalidInput, MapOptions,
    Method, Point2, Pose, SliderDyad, Task, Vector2, Viewport,
};

mod common;
use common::splitmix::Rng;

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// A slider-crank: crank `A0 A` of length `r`, coupler `A B` of length `l`,
/// the pin `B` on the guide through `g` along the unit `u`.
#[derive(Clone, Copy, Debug)]
struct SliderCrank {
    a0: Point2<f64>,
    r: f64,
    l: f64,
    g: Point2<f64>,
    u: Vector2<f64>,
}

impl SliderCrank {
    fn pin(&self, phi: f64) -> Point2<f64> {
        self.a0 + self.r * Vector2::new(phi.cos(), phi.sin())
    }

    /// `(p, q, disc)` at crank angle `phi`: the pin's positions are
    /// `g + (p ± sqrt(disc)) u`, `q` is the crank pin's signed distance from
    /// the guide, `disc = l^2 - q^2` (negative: the loop does not close).
    fn parts(&self, phi: f64) -> (f64, f64, f64) {
        let a = self.pin(phi) - self.g;
        let q = cross(self.u, a);
        (self.u.dot(&a), q, self.l * self.l - q * q)
    }

    /// The slider pin at crank angle `phi` in assembly mode `mode` (`±1`,
    /// the sign of `<B - A, u>`), or `None` where the loop does not close.
    fn slider(&self, phi: f64, mode: f64) -> Option<Point2<f64>> {
        let (p, _, disc) = self.parts(phi);
        (disc >= 0.0).then(|| self.g + (p + mode * disc.sqrt()) * self.u)
    }

    /// Whether the crank turns from `from` to `to` (either way round)
    /// without the loop opening or reaching a dead position, checked every
    /// 1e-3 rad.
    fn can_turn(&self, from: f64, to: f64) -> bool {
        let d = (to - from).rem_euclid(TAU);
        [d, d - TAU].iter().any(|&delta| {
            let n = (delta.abs() / 1e-3).ceil().max(1.0) as usize;
            (0..=n).all(|s| self.parts(from + delta * s as f64 / n as f64).2 > 0.0)
        })
    }
}

/// `D_1k(z)` of a list of poses, written here from the definition.
fn displace(poses: &[Pose], k: usize, z: Point2<f64>) -> Point2<f64> {
    let (p1, pk) = (poses[0], poses[k]);
    let t = pk.angle - p1.angle;
    let v = z - p1.position;
    pk.position + Vector2::new(t.cos() * v.x - t.sin() * v.y, t.sin() * v.x + t.cos() * v.y)
}

/// The coupler pose (the crank pin, the coupler's angle) of a slider-crank
/// at crank angle `phi` in mode `mode`.
fn pose_of(sc: &SliderCrank, phi: f64, mode: f64) -> Option<Pose> {
    let a = sc.pin(phi);
    let b = sc.slider(phi, mode)?;
    let d = b - a;
    Some(Pose::new(a.x, a.y, d.y.atan2(d.x)))
}

/// A random slider-crank and `n` crank angles it passes in one mode
/// without a dead position between them: its task (the coupler's poses),
/// the slider dyad `(B1, u)` and the generating crank.
fn random_slider_crank(rng: &mut Rng, n: usize) -> (Task, SliderDyad, SliderCrank) {
    loop {
        let ang = rng.range(-PI, PI);
        let sc = SliderCrank {
            a0: Point2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)),
            r: rng.range(0.4, 1.2),
            l: rng.range(1.5, 3.5),
            g: Point2::new(rng.range(-1.5, 1.5), rng.range(-1.5, 1.5)),
            u: Vector2::new(ang.cos(), ang.sin()),
        };
        let mode = if rng.next() < 0.5 { 1.0 } else { -1.0 };
        let mut phis = vec![rng.range(-PI, PI)];
        for _ in 1..n {
            let last = phis[phis.len() - 1];
            phis.push(last + rng.range(0.35, 1.0));
        }
        let ok = phis.windows(2).all(|w| sc.can_turn(w[0], w[1]))
            && phis.iter().all(|&p| sc.parts(p).2 > 0.05 * sc.l * sc.l);
        if !ok {
            continue;
        }
        let poses: Vec<Pose> = phis
            .iter()
            .map(|&p| pose_of(&sc, p, mode).unwrap())
            .collect();
        let Ok(task) = Task::new(&poses) else {
            continue;
        };
        let b1 = sc.slider(phis[0], mode).unwrap();
        let slider = SliderDyad::new(b1, sc.u).unwrap();
        return (task, slider, sc);
    }
}

/// `n` random slider-cranks of three poses ([`random_slider_crank`]), the
/// same for the same `seed` on every run.
fn random_slider_cranks(
    seed: u64,
    n: usize,
) -> impl Iterator<Item = (Task, SliderDyad, SliderCrank)> {
    let mut rng = Rng(seed);
    (0..n).map(move |_| random_slider_crank(&mut rng, 3))
}

/// The `n` by `n` grid over the square `[-h, h]` by `[-h, h]`.
fn square(h: f64, n: usize) -> Grid {
    Grid::from_bounds(-h, h, -h, h, n, n).unwrap()
}

/// What driving the slider-crank of a driving center point densely says.
#[derive(Debug, PartialEq)]
enum Driven {
    /// Every pose reached in one mode, the crank turning between them.
    Free,
    /// The poses need different assembly modes.
    Defective,
    /// One mode throughout, but the crank cannot turn between two poses
    /// (they lie on separate arcs of a rocking crank: a circuit defect,
    /// which no sign test sees).
    Circuit,
    /// A pose within rounding of a dead position: not compared.
    Near,
}

/// The slider-crank of the driving dyad `(a0, a1)` and the slider.
fn built(a0: Point2<f64>, a1: Point2<f64>, slider: &SliderDyad) -> SliderCrank {
    SliderCrank {
        a0,
        r: (a1 - a0).norm(),
        l: (slider.circle - a1).norm(),
        g: slider.circle,
        u: slider.guide,
    }
}

/// Builds the slider-crank of the driving dyad `(a0, a1)` and the slider
/// `(b1, u)` of `poses` and drives it: the mode that reaches each pose at
/// its crank angle (independent of the library: the solver above, the
/// displacements from the poses).
fn drive(poses: &[Pose], a0: Point2<f64>, a1: Point2<f64>, slider: &SliderDyad) -> Driven {
    let (b1, sc) = (slider.circle, built(a0, a1, slider));
    let mut modes = Vec::new();
    let mut phis = Vec::new();
    for k in 0..poses.len() {
        let (a, b) = (displace(poses, k, a1), displace(poses, k, b1));
        let phi = (a.y - a0.y).atan2(a.x - a0.x);
        // Which of the two solutions at this crank angle is the pose's pin.
        let (p, _, disc) = sc.parts(phi);
        let t = sc.u.dot(&(b - sc.g));
        if disc <= 1e-6 * sc.l * sc.l || (t - p).abs() <= 1e-6 * sc.l {
            return Driven::Near;
        }
        let mode = (t - p).signum();
        let b_mode = sc.slider(phi, mode).unwrap();
        assert!(
            (b_mode - b).norm() <= 1e-7 * (1.0 + sc.l + b.coords.norm()),
            "the pose's pin is a solution at its crank angle: {b_mode} vs {b}"
        );
        modes.push(mode);
        phis.push(phi);
    }
    if modes.iter().any(|&m| m != modes[0]) {
        return Driven::Defective;
    }
    if phis.windows(2).all(|w| sc.can_turn(w[0], w[1])) {
        Driven::Free
    } else {
        Driven::Circuit
    }
}

/// Whether `e` is `InvalidInput` with this cause.
fn cause_of(e: &Error) -> &'static str {
    match e {
        Error::InvalidInput(i) => i.cause(),
        other => panic!("expected invalid input, got {other:?}"),
    }
}

#[test]
fn the_generating_crank_of_a_known_slider_crank_is_free() {
    for (task, slider, sc) in random_slider_cranks(1, 200) {
        let f = Filemon::new(&task, slider).unwrap();
        assert!(f.fixed_pivot_images().is_none());
        assert_eq!(f.driven(), DyadKind::Slider(slider));
        // The crank's circle point is its pin at pose 1.
        let a1 = task.circle_point(sc.a0).unwrap();
        assert!((a1 - task.poses()[0].position).norm() < 1e-8 * (1.0 + a1.coords.norm()));
        for m in [Method::Conic, Method::Direct] {
            assert_eq!(f.classify(sc.a0, m).unwrap(), Branch::Free, "{m:?}");
        }
    }
}

#[test]
fn verdicts_agree_with_driving_the_built_slider_crank() {
    let mut rng = Rng(2);
    let (mut compared, mut free, mut defective, mut circuit, mut near) = (0, 0, 0, 0, 0);
    for _ in 0..60 {
        let (task, slider, _) = random_slider_crank(&mut rng, 3);
        let f = Filemon::new(&task, slider).unwrap();
        for _ in 0..100 {
            let a0 = Point2::new(rng.range(-4.0, 4.0), rng.range(-4.0, 4.0));
            let Ok(a1) = task.circle_point(a0) else {
                continue;
            };
            if (a1 - a0).norm() > 1e4 {
                continue;
            }
            let conic = f.classify(a0, Method::Conic).unwrap();
            let direct = f.classify(a0, Method::Direct).unwrap();
            match drive(task.poses(), a0, a1, &slider) {
                Driven::Near => near += 1,
                Driven::Free => {
                    assert_eq!((conic, direct), (Branch::Free, Branch::Free), "{a0}");
                    free += 1;
                }
                Driven::Defective => {
                    assert_eq!(
                        (conic, direct),
                        (Branch::Defective, Branch::Defective),
                        "{a0}"
                    );
                    defective += 1;
                }
                Driven::Circuit => {
                    // One mode at every pose: the sign tests say free.
                    assert_eq!((conic, direct), (Branch::Free, Branch::Free), "{a0}");
                    circuit += 1;
                }
            }
            compared += 1;
        }
    }
    eprintln!(
        "slider-crank drive: {compared} compared: {free} free, {defective} defective, \
         {circuit} circuit, {near} near a dead position or toggle"
    );
    assert!(free > 500 && defective > 500 && near * 50 < compared);
}

#[test]
fn slider_lines_are_the_limit_of_the_revolute_construction() {
    let mut rng = Rng(3);
    for _ in 0..100 {
        let (task, slider, _) = random_slider_crank(&mut rng, 3);
        let lines = FilemonLines::new(&task, slider).unwrap();
        let n = slider.normal();
        for r in [1e3, 1e5, 1e7] {
            let c0 = slider.circle + r * n;
            let rev = FilemonLines::new(&task, Dyad::new(c0, slider.circle)).unwrap();
            for (d, e) in lines.directions().iter().zip(rev.directions().iter()) {
                let angle = cross(*d, *e).atan2(d.dot(e)).abs();
                assert!(angle < 20.0 / r, "direction off by {angle} at R = {r}");
            }
            // The extreme lines and the classes agree away from the lines.
            if rng.next() < 0.5 || r < 1e7 {
                continue;
            }
            assert_eq!(lines.extreme_poses(), rev.extreme_poses());
            for _ in 0..200 {
                let a1 = Point2::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
                let s = lines.circle_signs(a1);
                let dist = s.iter().fold(f64::INFINITY, |m, v| m.min(v.abs()));
                if dist < 1e-4 {
                    continue;
                }
                assert_eq!(
                    lines.classify_circle_point(a1),
                    rev.classify_circle_point(a1)
                );
                let t = rev.circle_signs(a1);
                for (a, b) in s.iter().zip(t.iter()) {
                    assert_eq!(a.signum(), b.signum());
                }
            }
        }
    }
}

#[test]
fn slider_conics_are_the_limit_of_the_revolute_conics() {
    // The real dyads of the task whose centers run off along n: their
    // circle points approach the slider point and their conic
    // classification the slider's (the center-point plane's limit).
    let mut rng = Rng(4);
    let (mut compared, mut skipped, mut worst) = (0, 0, 0.0f64);
    for _ in 0..40 {
        let (task, slider, _) = random_slider_crank(&mut rng, 3);
        let f = Filemon::new(&task, slider).unwrap();
        // The circle point of C0 = C1 + R n approaches C1 as 1/R.
        let gap = |r: f64| {
            let c0 = slider.circle + r * slider.normal();
            task.filemon(c0)
                .map(|rev| ((rev.driven_circle() - slider.circle).norm(), rev))
        };
        // (Farther out, the rounding of a far center's circle point, about
        // 1e-16 R, overtakes the 1/R.)
        let (Ok((gap5, _)), Ok((gap6, _)), Ok((gap7, rev))) = (gap(1e5), gap(1e6), gap(1e7)) else {
            continue;
        };
        worst = worst.max(gap7);
        assert!(gap7 < 1e-3, "{gap7}");
        assert!(
            gap6 * 5.0 < gap5 || gap5 < 1e-9,
            "{gap6} at 1e6, {gap5} at 1e5"
        );
        for _ in 0..100 {
            let a0 = Point2::new(rng.range(-4.0, 4.0), rng.range(-4.0, 4.0));
            if f.margin(a0).unwrap().abs() < 1e-3 {
                skipped += 1;
                continue;
            }
            assert_eq!(
                f.classify(a0, Method::Conic).unwrap(),
                rev.classify(a0, Method::Conic).unwrap(),
                "{a0}"
            );
            compared += 1;
        }
    }
    eprintln!(
        "conic limit (R = 1e7): circle points within {worst:e} of C1; {compared} compared, \
         {skipped} within 1e-3 of a curve"
    );
    assert!(compared > 3000);
}

#[test]
fn conic_classification_agrees_with_the_circle_point_plane() {
    let mut rng = Rng(5);
    let (mut compared, mut band) = (0, 0);
    for _ in 0..50 {
        let (task, slider, _) = random_slider_crank(&mut rng, 3);
        let f = Filemon::new(&task, slider).unwrap();
        let lines = f.construction();
        for _ in 0..100 {
            let a0 = Point2::new(rng.range(-6.0, 6.0), rng.range(-6.0, 6.0));
            let Ok(a1) = task.circle_point(a0) else {
                continue;
            };
            let conic = f.classify(a0, Method::Conic).unwrap();
            let circle = lines.classify_circle_point(a1);
            // Within rounding of a line in the circle-point plane the two
            // may differ.
            let s = lines.circle_signs(a1);
            let dist = s.iter().fold(f64::INFINITY, |m, v| m.min(v.abs()));
            if dist <= 1e-9 * (1.0 + (a1 - slider.circle).norm()) {
                band += 1;
                continue;
            }
            assert_eq!(conic, circle, "{a0} (circle point {a1})");
            compared += 1;
        }
    }
    eprintln!("conic vs circle plane: {compared} compared, {band} in the band");
    assert!(compared > 4900);
}

#[test]
fn branch_map_is_the_pointwise_classification() {
    for (task, slider, _) in random_slider_cranks(6, 10) {
        let f = Filemon::new(&task, slider).unwrap();
        let grid = Grid::from_bounds(-4.0, 4.0, -3.0, 3.5, 97, 83).unwrap();
        for method in [Method::Conic, Method::Direct] {
            let map = f.branch_map(&grid, method);
            for j in 0..grid.ny() {
                for i in 0..grid.nx() {
                    let p = grid.point(i, j);
                    let want = f.classify(p, method).is_ok_and(|b| b.is_free());
                    assert_eq!(map[j * grid.nx() + i], want, "{method:?} at {p}");
                }
            }
        }
        let free = f
            .branch_map(&grid, Method::Conic)
            .iter()
            .filter(|&&b| b)
            .count();
        assert!(free > 0 || f.all_defective());
    }
}

#[test]
fn invariant_under_moving_rotating_and_scaling() {
    let mut rng = Rng(7);
    let mut compared = 0;
    for _ in 0..30 {
        let (task, slider, _) = random_slider_crank(&mut rng, 3);
        let f = Filemon::new(&task, slider).unwrap();
        let (s, rot, t) = (
            10f64.powf(rng.range(-3.0, 3.0)),
            rng.range(-PI, PI),
            Vector2::new(rng.range(-1e3, 1e3), rng.range(-1e3, 1e3)),
        );
        let (c, sn) = (rot.cos(), rot.sin());
        let turn = |v: Vector2<f64>| Vector2::new(c * v.x - sn * v.y, sn * v.x + c * v.y);
        let map = |p: Point2<f64>| Point2::from(turn(p.coords) * s + t);
        let poses: Vec<Pose> = task
            .poses()
            .iter()
            .map(|p| {
                let q = map(p.position);
                Pose::new(q.x, q.y, p.angle + rot)
            })
            .collect();
        let moved = Task::new(&poses).unwrap();
        let ms = SliderDyad::new(map(slider.circle), turn(slider.guide)).unwrap();
        let g = Filemon::new(&moved, ms).unwrap();
        assert_eq!(f.all_defective(), g.all_defective());
        assert_eq!(f.extreme_poses(), g.extreme_poses());
        for _ in 0..100 {
            let a0 = Point2::new(rng.range(-4.0, 4.0), rng.range(-4.0, 4.0));
            if f.margin(a0).unwrap().abs() < 1e-6 {
                continue;
            }
            assert_eq!(
                f.classify(a0, Method::Conic).unwrap(),
                g.classify(map(a0), Method::Conic).unwrap()
            );
            compared += 1;
        }
    }
    assert!(compared > 2500);
}

#[test]
fn slider_errors_are_typed() {
    let mut rng = Rng(8);
    let (task, slider, sc) = random_slider_crank(&mut rng, 3);
    let zero = SliderDyad {
        circle: slider.circle,
        guide: Vector2::zeros(),
    };
    let e = Filemon::new(&task, zero).unwrap_err();
    assert_eq!(cause_of(&e), "zero_direction");
    let nan = SliderDyad {
        circle: Point2::new(f64::NAN, 0.0),
        guide: slider.guide,
    };
    assert_eq!(
        cause_of(&Filemon::new(&task, nan).unwrap_err()),
        "not_finite"
    );
    // A guide that is not the line of the pin's positions.
    let off = SliderDyad::new(slider.circle, slider.normal()).unwrap();
    let e = Filemon::new(&task, off).unwrap_err();
    assert_eq!(cause_of(&e), "not_a_dyad");
    assert!(e.to_string().contains("slider"), "{e}");
    // What needs a four-bar refuses a slider, saying why (the simulate
    // method and the solution map drive the slider-crank instead).
    let f = Filemon::new(&task, slider).unwrap();
    let grid = square(1.0, 4);
    let map = f
        .solution_map(
            &grid,
            &MapOptions::new(&Default::default(), &burmester::Constraints::none()).unwrap(),
            &Control::new(),
        )
        .unwrap();
    let obstacles = burmester::Constraints {
        obstacles: vec![vec![
            Point2::new(50.0, 50.0),
            Point2::new(51.0, 50.0),
            Point2::new(51.0, 51.0),
        ]],
        ..burmester::Constraints::none()
    };
    // Obstacles are checked over the slider-crank's travel (once refused).
    assert!(
        f.solution_map(
            &grid,
            &MapOptions::new(&Default::default(), &obstacles).unwrap(),
            &Control::new()
        )
        .is_ok()
    );
    for e in [
        f.four_bar(sc.a0).unwrap_err(),
        map.context.linkage(0).unwrap_err(),
    ] {
        assert_eq!(cause_of(&e), "driven_kind");
        assert!(e.to_string().contains("slider"), "{e}");
    }
    assert!(f.classify(sc.a0, Method::Simulate).is_ok());
    let mut out = vec![false; grid.len()];
    f.branch_map_into(&grid, Method::Simulate, &mut out, &Control::new())
        .unwrap();
    // Four poses: the three-pose construction is refused, the four-pose
    // one takes the slider.
    let (four, slider4, _) = random_slider_crank(&mut rng, 4);
    assert_eq!(
        cause_of(&Filemon::new(&four, slider4).unwrap_err()),
        "needs_poses"
    );
    assert!(matches!(
        InvalidInput::ZeroDirection {
            name: "",
            x: 0.0,
            y: 0.0
        }
        .cause(),
        "zero_direction"
    ));
}

#[test]
fn four_poses_arcs_agree_with_driving_the_slider_crank() {
    let mut rng = Rng(9);
    let (mut compared, mut free, mut defective, mut circuit, mut near) = (0, 0, 0, 0, 0);
    let mut tasks = 0;
    while tasks < 30 {
        let (task, slider, sc) = random_slider_crank(&mut rng, 4);
        let Ok(four) = task.four_positions("test") else {
            continue;
        };
        tasks += 1;
        let arcs = four.slider_filemon(&slider).unwrap();
        assert!(arcs.fixed_pivot_images().is_none());
        // The generating crank is on the center-point curve and free.
        assert_eq!(arcs.classify_center_point(sc.a0).unwrap(), Branch::Free);
        // The arc ends: on the circle-point curve and on their pose's line.
        let curve = four.circle_point_curve();
        for e in arcs.arc_ends() {
            let line = arcs.all_lines()[e.pose - 1];
            let off = cross(line.direction, e.circle - line.point).abs();
            assert!(off < 1e-8 * (1.0 + (e.circle - line.point).norm()), "{off}");
            let g = curve.gradient(e.circle).norm();
            assert!(curve.evaluate(e.circle).abs() <= 1e-8 * g * (1.0 + e.circle.coords.norm()));
        }
        // Points of the center-point curve: the class against the drive.
        let vp = Viewport::new(-5.0, 5.0, -5.0, 5.0).unwrap();
        for line in four.center_point_curve().polylines(&vp) {
            for a0 in line.iter().step_by(3) {
                let Ok(a1) = four.circle_point(*a0) else {
                    continue;
                };
                if (a1 - a0).norm() > 1e4 || (a1 - slider.circle).norm() < 1e-6 {
                    continue;
                }
                let class = arcs.classify_center_point(*a0).unwrap();
                match drive(task.poses(), *a0, a1, &slider) {
                    Driven::Near => near += 1,
                    Driven::Free => {
                        assert_eq!(class, Branch::Free, "{a0}");
                        free += 1;
                    }
                    Driven::Defective => {
                        assert_eq!(class, Branch::Defective, "{a0}");
                        defective += 1;
                    }
                    Driven::Circuit => {
                        assert_eq!(class, Branch::Free, "{a0}");
                        circuit += 1;
                    }
                }
                compared += 1;
            }
        }
        // The free arcs' points are free.
        for arc in arcs.free_center_arcs(&vp).unwrap() {
            for p in arc.iter().skip(1).step_by(5) {
                if let Ok(b) = arcs.classify_center_point(*p) {
                    assert_ne!(b, Branch::Defective, "{p}");
                }
            }
        }
    }
    eprintln!(
        "four poses: {compared} curve points: {free} free, {defective} defective, \
         {circuit} circuit, {near} near"
    );
    assert!(free > 200 && defective > 100);
}

// The solution map with a driven slider (every column) and the simulate
// method, against driving the built slider-crank densely with the solver
// above.

/// What driving the slider-crank of `(a0, a1)` and the slider densely by
/// crank angle says about the map's figures (independent of the library).
#[derive(Debug)]
struct Dense {
    /// The loop closes at every crank angle (`None`: within 1e-6 `l^2` of a
    /// change point, not compared).
    full: Option<bool>,
    /// The crank rotation that meets the poses in order from pose 1 without
    /// the loop opening: `1`, `-1` or `0` (`None`: a dead position within
    /// the walking band, not compared).
    direction: Option<i8>,
    /// Every pose on one arc of the crank's range.
    one_circuit: bool,
    /// The smallest transmission angle over the travel (the angle between
    /// the coupler and the guide's normal, `cos mu = |q| / l`), sampled
    /// every 1e-3 rad; NaN without a travel.
    min_mu: f64,
    /// The span of the slider's positions over the travel in pose 1's mode.
    stroke: f64,
    /// Crank and coupler lengths and the offset.
    r: f64,
    l: f64,
    e: f64,
}

fn dense_figures(poses: &[Pose], a0: Point2<f64>, a1: Point2<f64>, slider: &SliderDyad) -> Dense {
    let (b1, sc) = (slider.circle, built(a0, a1, slider));
    let band = 1e-6 * sc.l * sc.l;
    let n = 4096;
    let discs: Vec<f64> = (0..n)
        .map(|i| sc.parts(i as f64 * TAU / n as f64).2)
        .collect();
    let lowest = discs.iter().copied().fold(f64::INFINITY, f64::min);
    // The lowest disc is at the crank along the normal: check it exactly.
    let n_u = Vector2::new(-sc.u.y, sc.u.x);
    let lowest = [n_u, -n_u]
        .iter()
        .map(|d| sc.parts(d.y.atan2(d.x)).2)
        .fold(lowest, f64::min);
    let full = (lowest.abs() > band).then_some(lowest > 0.0);
    let phis: Vec<f64> = (0..poses.len())
        .map(|k| {
            let a = displace(poses, k, a1);
            (a.y - a0.y).atan2(a.x - a0.x)
        })
        .collect();
    let one_circuit = phis.windows(2).all(|w| sc.can_turn(w[0], w[1]));
    // Walk from pose 1 each way: the poses in order, the loop closed.
    let step = 2e-3;
    let mut direction = Some(0);
    let mut travel = None;
    for dir in [1.0, -1.0] {
        let dist: Vec<f64> = phis
            .iter()
            .map(|p| ((p - phis[0]) * dir).rem_euclid(TAU))
            .collect();
        let in_order = dist.windows(2).all(|w| w[0] < w[1]);
        let end = dist[dist.len() - 1];
        let steps = (end / step).ceil() as usize;
        let low = (0..=steps)
            .map(|s| sc.parts(phis[0] + dir * end * s as f64 / steps as f64).2)
            .fold(f64::INFINITY, f64::min);
        if low.abs() <= band {
            direction = None;
        }
        if in_order && low > 0.0 {
            if let Some(d) = direction.as_mut() {
                *d = dir as i8;
            }
            travel = Some((dir * end, steps));
        }
    }
    let (mut min_mu, mut stroke) = (f64::NAN, f64::NAN);
    if let Some((span, steps)) = travel {
        let (p, _, disc) = sc.parts(phis[0]);
        let t1 = sc.u.dot(&(b1 - sc.g));
        let mode = (t1 - p).signum();
        let _ = disc;
        let at = |s: f64| {
            let (p, _, disc) = sc.parts(phis[0] + span * s / steps as f64);
            p + mode * disc.max(0.0).sqrt()
        };
        let (mut lo, mut hi, mut mu) = ((f64::INFINITY, 0), (f64::NEG_INFINITY, 0), f64::INFINITY);
        for s in 0..=steps {
            let phi = phis[0] + span * s as f64 / steps as f64;
            let (_, q, _) = sc.parts(phi);
            mu = mu.min((q.abs() / sc.l).min(1.0).acos());
            let t = at(s as f64);
            if t < lo.0 {
                lo = (t, s);
            }
            if t > hi.0 {
                hi = (t, s);
            }
        }
        // The extremes refined within a step either side, 1e-3 steps.
        let refine = |s: usize, pick: fn(f64, f64) -> f64| {
            (0..=2000)
                .map(|i| (s as f64 - 1.0 + i as f64 * 1e-3).clamp(0.0, steps as f64))
                .map(at)
                .fold(at(s as f64), pick)
        };
        min_mu = mu;
        stroke = refine(hi.1, f64::max) - refine(lo.1, f64::min);
    }
    Dense {
        full,
        direction,
        one_circuit,
        min_mu,
        stroke,
        r: sc.r,
        l: sc.l,
        e: cross(sc.u, a0 - b1),
    }
}

/// The largest distance between two pose positions (`Task::span`, written
/// here from its definition).
fn span_of(poses: &[Pose]) -> f64 {
    let mut s: f64 = 0.0;
    for p in poses {
        for q in poses {
            s = s.max((p.position - q.position).norm());
        }
    }
    s
}

fn slider_map(f: &Filemon, grid: &Grid) -> burmester::SolutionMap {
    f.solution_map(
        grid,
        &MapOptions::new(&Default::default(), &burmester::Constraints::none()).unwrap(),
        &Control::new(),
    )
    .unwrap()
}

#[test]
fn slider_map_columns_agree_with_driving_the_built_slider_crank() {
    let grid = square(4.0, 14);
    let mut seen = [0usize; 9];
    for (task, slider, _) in random_slider_cranks(31, 16) {
        let f = Filemon::new(&task, slider).unwrap();
        let map = slider_map(&f, &grid);
        let c = &map.columns;
        let span = span_of(task.poses());
        for k in 0..grid.len() {
            let a0 = map.context.point(k);
            let Ok(a1) = task.circle_point(a0) else {
                assert!(!c.valid[k]);
                continue;
            };
            if (a1 - a0).norm() > 1e3 || (slider.circle - a1).norm() < 1e-9 {
                continue;
            }
            assert!(c.valid[k], "{a0}");
            seen[0] += 1;
            assert_eq!(c.grashof[k], burmester::SolutionMap::GRASHOF_NONE);
            let d = dense_figures(task.poses(), a0, a1, &slider);
            // Branch: the map's flag is the conic branch map; driving says
            // which mode reaches each pose.
            match drive(task.poses(), a0, a1, &slider) {
                Driven::Near => {}
                Driven::Free | Driven::Circuit => {
                    assert!(c.branch_free[k], "{a0}");
                    seen[1] += 1;
                }
                Driven::Defective => {
                    assert!(!c.branch_free[k], "{a0}");
                    seen[1] += 1;
                }
            }
            if let Some(full) = d.full {
                assert_eq!(c.input_full[k], full, "{a0}: {d:?}");
                seen[2] += 1;
            }
            if let Some(dir) = d.direction {
                assert_eq!(c.direction[k], dir, "{a0}: {d:?}");
                seen[3] += 1;
                if dir != 0 {
                    let mu = c.min_transmission_rad[k] as f64;
                    // The dense minimum is at most 1e-3 rad of crank off.
                    assert!(
                        mu <= d.min_mu + 1e-6 && mu >= d.min_mu - 2e-2,
                        "{a0}: {mu} vs {}",
                        d.min_mu
                    );
                    seen[4] += 1;
                } else {
                    assert!(c.min_transmission_rad[k].is_nan());
                }
            }
            if d.direction.is_some() && d.full.is_some() {
                assert_eq!(c.one_circuit[k], d.one_circuit, "{a0}: {d:?}");
                seen[5] += 1;
            }
            let ratio = d.r.max(d.l) / d.r.min(d.l);
            assert!((c.link_ratio[k] as f64 - ratio).abs() <= 1e-5 * ratio);
            // The size: crank, coupler, the coupler triangle's other sides
            // (the coupler point is pose 1's position), the offset and the
            // guide the slider runs on over the travel.
            let p = task.poses()[0].position;
            let sc = map.context.slider_crank(k).unwrap();
            let guide = if c.branch_free[k] && d.direction.is_some_and(|x| x != 0) {
                seen[6] += 1;
                assert!(
                    (sc.stroke_used - d.stroke).abs() <= 1e-5 * (1.0 + d.stroke),
                    "{a0}: {} vs {}",
                    sc.stroke_used,
                    d.stroke
                );
                d.stroke
            } else {
                sc.size() - (d.r + d.l + (p - a1).norm() + (p - slider.circle).norm() + d.e.abs())
            };
            let size = d.r + d.l + (p - a1).norm() + (p - slider.circle).norm() + d.e.abs() + guide;
            assert!(
                (c.size_ratio[k] as f64 - size / span).abs() <= 1e-5 * size / span,
                "{a0}"
            );
            // The map's linkage is the slider-crank of the sample.
            assert!((sc.linkage.crank() - d.r).abs() <= 1e-9 * (1.0 + d.r));
            assert!((sc.linkage.coupler() - d.l).abs() <= 1e-9 * (1.0 + d.l));
            // acceptable: branch-free and the default limits, read from the
            // columns and the offset (the rotatability margin).
            let margin =
                ((d.l - d.r - d.e).abs()).min((d.l - d.r + d.e).abs()) / (d.r + d.l + d.e.abs());
            let want = c.branch_free[k]
                && c.one_circuit[k]
                && c.direction[k] != 0
                && (c.link_ratio[k] as f64) <= 10.0
                && margin >= 0.01
                && sc.min_transmission >= 30f64.to_radians();
            if (margin - 0.01).abs() > 1e-9 {
                assert_eq!(c.acceptable[k], want, "{a0}");
                seen[7] += u8::from(want) as usize;
            }
        }
    }
    eprintln!(
        "samples {}, branch {}, input_full {}, direction {}, transmission {}, one_circuit {}, \
         stroke {}, acceptable {}",
        seen[0], seen[1], seen[2], seen[3], seen[4], seen[5], seen[6], seen[7]
    );
    assert!(
        seen[0] > 3000 && seen[1] > 3000 && seen[3] > 3000,
        "{seen:?}"
    );
    assert!(seen[4] > 500 && seen[7] > 100, "{seen:?}");
}

#[test]
fn simulate_agrees_with_driving_and_with_the_exact_map() {
    let grid = square(4.0, 20);
    let (mut agree, mut circuit) = (0, 0);
    for (task, slider, _) in random_slider_cranks(32, 12) {
        let f = Filemon::new(&task, slider).unwrap();
        let map = slider_map(&f, &grid);
        let sim = f.branch_map(&grid, Method::Simulate);
        for (k, &sim_k) in sim.iter().enumerate() {
            let a0 = map.context.point(k);
            let Ok(a1) = task.circle_point(a0) else {
                continue;
            };
            if (a1 - a0).norm() > 1e3 {
                continue;
            }
            let want = match drive(task.poses(), a0, a1, &slider) {
                Driven::Near => continue,
                Driven::Free => Branch::Free,
                Driven::Defective => Branch::Defective,
                Driven::Circuit => {
                    circuit += 1;
                    Branch::Defective
                }
            };
            let got = f.classify(a0, Method::Simulate).unwrap();
            assert_eq!(got, want, "{a0}");
            assert_eq!(sim_k, got == Branch::Free);
            // Simulate is the exact map's branch flag and circuit flag.
            let c = &map.columns;
            assert_eq!(
                got == Branch::Free,
                c.branch_free[k] && c.one_circuit[k],
                "{a0}"
            );
            agree += 1;
        }
    }
    eprintln!("simulate agrees with driving at {agree} samples ({circuit} circuit defects)");
    assert!(agree > 3000 && circuit > 0, "{agree} {circuit}");
}

/// A press in mm: crank 40 about the origin, coupler 160, the ram's pin on
/// a horizontal guide 10 above the crank pivot, at crank angles 30, 90 and
/// 150 degrees (the coupler's pose: the crank pin and the coupler's angle);
/// its task, the ram's slider dyad and their Filemon lines.
fn press() -> (Task, SliderDyad, Filemon) {
    let sc = SliderCrank {
        a0: Point2::origin(),
        r: 40.0,
        l: 160.0,
        g: Point2::new(0.0, 10.0),
        u: Vector2::x(),
    };
    let poses: Vec<Pose> = [30f64, 90.0, 150.0]
        .iter()
        .map(|d| pose_of(&sc, d.to_radians(), 1.0).unwrap())
        .collect();
    let b1 = sc.slider(30f64.to_radians(), 1.0).unwrap();
    let task = Task::new(&poses).unwrap();
    let slider = SliderDyad::new(b1, sc.u).unwrap();
    let f = Filemon::new(&task, slider).unwrap();
    (task, slider, f)
}

#[test]
fn the_generating_crank_of_a_press_is_acceptable() {
    let (task, slider, f) = press();
    let grid = square(105.0, 21);
    let map = slider_map(&f, &grid);
    let k = 10 * 21 + 10;
    assert_eq!(map.context.point(k), Point2::origin());
    let c = &map.columns;
    assert!(c.valid[k] && c.branch_free[k] && c.acceptable[k] && c.one_circuit[k]);
    let sc = map.context.slider_crank(k).unwrap();
    assert!((sc.linkage.crank() - 40.0).abs() < 1e-9);
    assert!((sc.linkage.coupler() - 160.0).abs() < 1e-9);
    assert!((sc.linkage.offset().abs() - 10.0).abs() < 1e-9);
    // cos mu = |e + r sin theta| / l is largest at 90 degrees: 30 / 160.
    let mu = (30.0f64 / 160.0).acos();
    assert!((map.columns.min_transmission_rad[k] as f64 - mu).abs() < 1e-6);
    assert_eq!(map.columns.direction[k], 1);
    assert!(map.columns.input_full[k]);
    assert_eq!(
        f.classify(Point2::origin(), Method::Simulate).unwrap(),
        Branch::Free
    );
    // Its margin is positive (branch-free), and a Pivot carries a four-bar.
    assert!(map.margin(k) > 0.0);
    let e = map
        .best_pivots(Ranking::new(3, burmester::RankBy::Balanced))
        .unwrap_err();
    assert_eq!(cause_of(&e), "driven_kind");
    assert_eq!(map.context.varying.as_str(), "driving");
    assert_eq!(map.context.varying.fixed(), DyadKind::Slider(slider));
    // A crank's map has no slider-crank.
    let revolute = task.filemon(Point2::new(300.0, -200.0)).unwrap();
    let rmap = slider_map(&revolute, &grid);
    assert_eq!(
        cause_of(&rmap.context.slider_crank(0).unwrap_err()),
        "driven_kind"
    );
}

#[test]
fn slider_map_is_invariant_under_moves_rotations_and_scaling() {
    let mut rng = Rng(33);
    let (n, h) = (24, 4.0);
    let mut compared = 0;
    let mut flips = 0;
    for _ in 0..10 {
        let (task, slider, _) = random_slider_crank(&mut rng, 3);
        let (s, t) = (
            rng.range(0.01, 100.0),
            Vector2::new(rng.range(-50.0, 50.0), rng.range(-50.0, 50.0)),
        );
        // A quarter turn keeps the grid's samples on a grid: (x, y) ->
        // s (-y, x) + t.
        let map_pt = |p: Point2<f64>| Point2::new(-p.y, p.x) * s + t;
        let map_dir = |v: Vector2<f64>| Vector2::new(-v.y, v.x);
        let poses: Vec<Pose> = task
            .poses()
            .iter()
            .map(|p| {
                let q = map_pt(p.position);
                Pose::new(q.x, q.y, p.angle + PI / 2.0)
            })
            .collect();
        let task2 = Task::new(&poses).unwrap();
        let slider2 = SliderDyad::new(map_pt(slider.circle), map_dir(slider.guide)).unwrap();
        let g1 = square(h, n);
        let g2 =
            Grid::from_bounds(-h * s + t.x, h * s + t.x, -h * s + t.y, h * s + t.y, n, n).unwrap();
        let m1 = slider_map(&Filemon::new(&task, slider).unwrap(), &g1);
        let m2 = slider_map(&Filemon::new(&task2, slider2).unwrap(), &g2);
        let (c1, c2) = (&m1.columns, &m2.columns);
        for j in 0..n {
            for i in 0..n {
                let k1 = j * n + i;
                let k2 = i * n + (n - 1 - j);
                let p1 = m1.context.point(k1);
                assert!(
                    (map_pt(p1) - m2.context.point(k2)).norm()
                        < 1e-9 * s * (1.0 + h) + 1e-9 * t.norm()
                );
                if !c1.valid[k1] || !c2.valid[k2] {
                    assert_eq!(c1.valid[k1], c2.valid[k2]);
                    continue;
                }
                // Exact flags may flip only within rounding of a curve.
                let margin = m1.context.margin(k1, &c1.branch_free).abs();
                let near = margin < 1e-6;
                let same = c1.branch_free[k1] == c2.branch_free[k2]
                    && c1.direction[k1] == c2.direction[k2]
                    && c1.one_circuit[k1] == c2.one_circuit[k2]
                    && c1.input_full[k1] == c2.input_full[k2]
                    && c1.acceptable[k1] == c2.acceptable[k2];
                if !same {
                    assert!(near, "{p1}: margin {margin}");
                    flips += 1;
                    continue;
                }
                let close = |a: f32, b: f32| {
                    (a.is_nan() && b.is_nan()) || (a - b).abs() <= 1e-4 * (1.0 + a.abs())
                };
                assert!(
                    close(c1.min_transmission_rad[k1], c2.min_transmission_rad[k2]),
                    "{p1}"
                );
                assert!(close(c1.link_ratio[k1], c2.link_ratio[k2]), "{p1}");
                assert!(close(c1.size_ratio[k1], c2.size_ratio[k2]), "{p1}");
                compared += 1;
            }
        }
    }
    eprintln!("invariance: {compared} samples equal, {flips} within rounding of a curve");
    assert!(compared > 4000, "{compared}");
}

/// The exact slider-crank of every valid sample of a slider map, built
/// from the task (`Task::slider_crank`), with the sample: the second
/// method the ranking is checked against.
fn exact_cells(
    task: &Task,
    slider: &SliderDyad,
    map: &burmester::SolutionMap,
) -> Vec<(usize, burmester::SynthesizedSliderCrank)> {
    (0..map.context.grid.len())
        .filter_map(|k| {
            let d = task.dyad_from_center(map.context.point(k)).ok()?;
            Some((k, task.slider_crank(&d, slider).ok()?))
        })
        .collect()
}

/// Whether the exact slider-crank `sc` meets the default limits (written
/// here from their definitions: feasible, a transmission angle of 30
/// degrees, a link ratio of 10, 1% from the change points), with the map's
/// branch flag of its sample.
fn acceptable_by_default(sc: &burmester::SynthesizedSliderCrank, branch_free: bool) -> bool {
    branch_free
        && sc.one_circuit
        && sc.direction != burmester::Direction::None
        && sc.linkage.link_ratio() <= 10.0
        && sc.linkage.rotatability_margin() >= 0.01
        && sc.min_transmission >= 30f64.to_radians()
}

#[test]
fn ranking_a_slider_map_agrees_with_rescoring_every_cell() {
    use burmester::RankBy;
    let (task, slider, f) = press();
    let grid = square(150.0, 41);
    let map = slider_map(&f, &grid);
    let cells = exact_cells(&task, &slider, &map);
    let span = task.span();
    let mut acceptable = 0;
    for (k, sc) in &cells {
        let want = acceptable_by_default(sc, map.columns.branch_free[*k]);
        // The columns are f32: skip a sample whose transmission is within
        // their rounding of the limit.
        if (sc.min_transmission - 30f64.to_radians()).abs() > 1e-6 {
            assert_eq!(map.columns.acceptable[*k], want, "sample {k}");
        }
        acceptable += usize::from(map.columns.acceptable[*k]);
    }
    assert!(acceptable > 50, "{acceptable} acceptable samples");
    for rank_by in [RankBy::Balanced, RankBy::Transmission, RankBy::Compact] {
        let best = map.best_slider_pivots(Ranking::new(5, rank_by)).unwrap();
        assert!(!best.is_empty(), "{rank_by:?}");
        let b = &best[0];
        // Its linkage is the exact slider-crank of its center.
        let d = task.dyad_from_center(b.center).unwrap();
        let exact = task.slider_crank(&d, &slider).unwrap();
        assert_eq!(b.linkage, exact);
        assert_eq!(b.center, map.context.point(b.index.0 * 41 + b.index.1));
        assert!((b.size_ratio - exact.size() / span).abs() <= 1e-12 * b.size_ratio);
        // It reaches the poses, branch-free and in order: the library's
        // verdict, the pose at each crank angle, and the independent solver.
        assert!(exact.feasible(), "{rank_by:?}");
        for (k, p) in task.poses().iter().enumerate() {
            let at = exact
                .pose_at(exact.input_angles[k], exact.modes[k].unwrap())
                .unwrap();
            assert!(
                (at.position - p.position).norm() < 1e-9 * span,
                "{rank_by:?} pose {k}"
            );
        }
        assert_eq!(
            drive(task.poses(), d.center, d.circle, &slider),
            Driven::Free
        );
        let dense = dense_figures(task.poses(), d.center, d.circle, &slider);
        assert!(
            (dense.min_mu - exact.min_transmission).abs() < 1e-5,
            "{} vs {}",
            dense.min_mu,
            exact.min_transmission
        );
        // Its score is the best of every acceptable cell rescored from the
        // exact linkage, within the columns' f32 rounding.
        let brute = cells
            .iter()
            .filter(|(k, _)| map.columns.acceptable[*k])
            .filter_map(|(_, sc)| {
                rank_by.score(
                    sc.min_transmission,
                    sc.size() / span,
                    sc.linkage.link_ratio(),
                )
            })
            .fold(f64::NEG_INFINITY, f64::max);
        let exact_score = rank_by
            .score(
                exact.min_transmission,
                exact.size() / span,
                exact.linkage.link_ratio(),
            )
            .unwrap();
        let tol = 4.0 * f64::from(f32::EPSILON) * brute.abs().max(1.0);
        assert!(
            (exact_score - brute).abs() <= tol && (b.score - brute).abs() <= tol,
            "{rank_by:?}: best {} (exact {exact_score}) vs brute force {brute}",
            b.score
        );
        eprintln!(
            "{rank_by:?}: best A0 ({:.1}, {:.1}) crank {:.1} coupler {:.1} offset {:.1} mu {:.1} deg size ratio {:.2} score {:.4} (brute force {brute:.4})",
            b.center.x,
            b.center.y,
            exact.linkage.crank(),
            exact.linkage.coupler(),
            exact.linkage.offset(),
            exact.min_transmission.to_degrees(),
            b.size_ratio,
            b.score
        );
        // Best first, and apart by the default separation.
        for w in best.windows(2) {
            assert!(w[0].score >= w[1].score - 1e-9, "{rank_by:?}");
        }
    }
    // The margin ranking: branch-free samples by their margin to the conic.
    let by_margin = map
        .best_slider_pivots(Ranking::new(3, RankBy::Margin))
        .unwrap();
    assert!(by_margin[0].margin > 0.0 && by_margin[0].linkage.is_branch_free());
    assert_eq!(
        by_margin[0].margin,
        map.margin(by_margin[0].index.0 * 41 + by_margin[0].index.1)
    );
    // The Pareto front: acceptable, sizes rising with the transmission, and
    // no acceptable cell (rescored exactly) better in both beyond the f32
    // rounding.
    let front = map.slider_pareto_front().unwrap();
    assert!(front.len() >= 2, "{}", front.len());
    for w in front.windows(2) {
        assert!(w[0].size_ratio <= w[1].size_ratio);
        assert!(w[0].linkage.min_transmission < w[1].linkage.min_transmission);
    }
    let eps = 1e-6;
    for p in &front {
        assert!(p.linkage.feasible());
        let (mu, s) = (p.linkage.min_transmission, p.size_ratio);
        for (k, sc) in &cells {
            if map.columns.acceptable[*k] {
                let (m2, s2) = (sc.min_transmission, sc.size() / span);
                assert!(
                    !(m2 > mu * (1.0 + eps) && s2 < s * (1.0 - eps)),
                    "front member ({mu}, {s}) dominated by sample {k} ({m2}, {s2})"
                );
            }
        }
    }
    // Every pivot asked for (the documented maximum: usize::MAX), apart by
    // nothing: every acceptable sample once.
    let every = Ranking::new(usize::MAX, RankBy::Balanced).with_separation(0.0);
    let all = map.best_slider_pivots(every.unwrap()).unwrap();
    assert_eq!(all.len(), acceptable);
    // The four-bar's ranking refuses a slider map, naming what to use, and
    // the slider's a crank's map.
    let e = map
        .best_pivots(Ranking::new(3, RankBy::Balanced))
        .unwrap_err();
    assert_eq!(cause_of(&e), "driven_kind");
    assert!(e.to_string().contains("best_slider_pivots"), "{e}");
    let revolute = task.filemon(Point2::new(300.0, -200.0)).unwrap();
    let rmap = slider_map(&revolute, &grid);
    let e = rmap
        .best_slider_pivots(Ranking::new(3, RankBy::Balanced))
        .unwrap_err();
    assert_eq!(cause_of(&e), "driven_kind");
    assert!(e.to_string().contains("best_pivots"), "{e}");
    // A cancelled ranking stops with Cancelled.
    let stop = std::sync::atomic::AtomicBool::new(true);
    let control = Control::new().with_cancel(&stop);
    let e = map
        .context
        .best_pivots_with::<burmester::SynthesizedSliderCrank>(
            Ranking::new(3, RankBy::Pareto),
            map.rank_columns(),
            &control,
        )
        .unwrap_err();
    assert!(matches!(e, Error::Cancelled { .. }), "{e:?}");
}

/// The smallest gap over the travel between the moving parts of the
/// slider-crank of `(a0, a1)` and the slider, driven densely by this
/// file's solver: from the obstacles (crank `A0 A` and coupler `A B`) and
/// from the envelope's edges (crank, coupler and the coupler triangle
/// with the task's point), parry distances between segments and polygons
/// (minus nothing: compare with the links' half width). `None` without a
/// travel (no crank rotation meets the poses in order with the loop
/// closed).
fn dense_gaps(
    poses: &[Pose],
    a0: Point2<f64>,
    a1: Point2<f64>,
    slider: &SliderDyad,
    obstacles: &[Vec<Point2<f64>>],
    envelope: &[Point2<f64>],
) -> Option<(f64, f64)> {
    use parry2d_f64::math::{Pose as PPose, Vector as V};
    use parry2d_f64::query::distance;
    use parry2d_f64::shape::{ConvexPolygon, Segment};
    let (b1, sc) = (slider.circle, built(a0, a1, slider));
    let p1 = poses[0].position;
    let phis: Vec<f64> = (0..poses.len())
        .map(|k| {
            let a = displace(poses, k, a1);
            (a.y - a0.y).atan2(a.x - a0.x)
        })
        .collect();
    let (p, _, _) = sc.parts(phis[0]);
    let mode = (sc.u.dot(&(b1 - sc.g)) - p).signum();
    let steps = 1000;
    let travel = [1.0, -1.0].into_iter().find_map(|dir: f64| {
        let dist: Vec<f64> = phis
            .iter()
            .map(|p| ((p - phis[0]) * dir).rem_euclid(TAU))
            .collect();
        let end = dist[dist.len() - 1];
        let closed =
            (0..=steps).all(|s| sc.parts(phis[0] + dir * end * s as f64 / steps as f64).2 > 0.0);
        (dist.windows(2).all(|w| w[0] < w[1]) && closed).then_some(dir * end)
    })?;
    let v = |q: Point2<f64>| V::new(q.x, q.y);
    let seg = |a: Point2<f64>, b: Point2<f64>| Segment::new(v(a), v(b));
    let id = PPose::identity();
    let hulls: Vec<ConvexPolygon> = obstacles
        .iter()
        .map(|o| {
            ConvexPolygon::from_convex_hull(&o.iter().map(|q| v(*q)).collect::<Vec<_>>()).unwrap()
        })
        .collect();
    let n = envelope.len();
    let edges: Vec<Segment> = (0..n)
        .map(|k| seg(envelope[k], envelope[(k + 1) % n]))
        .collect();
    let local = p1 - a1;
    let angle1 = (b1 - a1).y.atan2((b1 - a1).x);
    let (mut to_obstacles, mut to_envelope) = (f64::INFINITY, f64::INFINITY);
    for s in 0..=steps {
        let phi = phis[0] + travel * s as f64 / steps as f64;
        let a = sc.pin(phi);
        let b = sc.slider(phi, mode)?;
        let t = (b - a).y.atan2((b - a).x) - angle1;
        let pt = a + Vector2::new(
            t.cos() * local.x - t.sin() * local.y,
            t.sin() * local.x + t.cos() * local.y,
        );
        for (x, y) in [(a0, a), (a, b)] {
            for h in &hulls {
                to_obstacles =
                    to_obstacles.min(distance(&id, &seg(x, y), &id, h).unwrap().distance);
            }
        }
        for (x, y) in [(a0, a), (a, b), (a, pt), (b, pt)] {
            for e in &edges {
                to_envelope = to_envelope.min(distance(&id, &seg(x, y), &id, e).unwrap().distance);
            }
        }
    }
    Some((to_obstacles, to_envelope))
}

#[test]
fn slider_map_obstacles_and_envelope_agree_with_driving_the_built_slider_crank() {
    let (task, slider, f) = press();
    let grid = square(150.0, 25);
    let free = slider_map(&f, &grid);
    let rect = |x0: f64, x1: f64, y0: f64, y1: f64| {
        vec![
            Point2::new(x0, y0),
            Point2::new(x1, y0),
            Point2::new(x1, y1),
            Point2::new(x0, y1),
        ]
    };
    // A block above the ram's path, a floor plate below the guide and a
    // housing (mm); links 8 mm wide.
    let obstacles = vec![
        rect(70.0, 110.0, 40.0, 70.0),
        rect(120.0, 220.0, -40.0, -12.0),
    ];
    let envelope = rect(-140.0, 260.0, -110.0, 110.0);
    let width = 8.0;
    let constraints = burmester::Constraints {
        obstacles: obstacles.clone(),
        envelope: Some(envelope.clone()),
        link_width: width,
        ..burmester::Constraints::none()
    };
    let map = f
        .solution_map(
            &grid,
            &MapOptions::new(&Default::default(), &constraints).unwrap(),
            &Control::new(),
        )
        .unwrap();
    let inside = |q: Point2<f64>| q.x > -140.0 && q.x < 260.0 && q.y > -110.0 && q.y < 110.0;
    let (mut clear, mut struck, mut escapes, mut borderline) = (0, 0, 0, 0);
    for k in 0..grid.len() {
        if !free.columns.acceptable[k] {
            // Constraints only take samples away.
            assert!(!map.columns.acceptable[k], "sample {k}");
            continue;
        }
        let a0 = map.context.point(k);
        let d = task.dyad_from_center(a0).unwrap();
        let (to_obstacles, to_envelope) =
            dense_gaps(task.poses(), a0, d.circle, &slider, &obstacles, &envelope)
                .expect("an acceptable sample has a travel");
        let r = 0.5 * width;
        // The dense samples are 1/1000 of the travel apart (a point moves
        // at most about 1 mm between two): within 2 mm of the half width
        // the verdict is not compared.
        let gap = (to_obstacles - r).min(if inside(a0) { to_envelope - r } else { -1.0 });
        if gap.abs() < 2.0 {
            borderline += 1;
            continue;
        }
        assert_eq!(
            map.columns.acceptable[k],
            gap > 0.0,
            "sample {k} at {a0}: gaps {to_obstacles} (obstacles), {to_envelope} (envelope)"
        );
        if gap > 0.0 {
            clear += 1;
        } else if to_obstacles < r {
            struck += 1;
        } else {
            escapes += 1;
        }
    }
    eprintln!(
        "obstacles: {clear} clear, {struck} struck, {escapes} leave the envelope, {borderline} within 2 mm"
    );
    assert!(
        clear > 20 && struck > 20 && escapes > 5,
        "{clear} {struck} {escapes}"
    );
    // The best pivot under the constraints is clear by the dense check.
    let best = map
        .best_slider_pivots(Ranking::new(1, burmester::RankBy::Balanced))
        .unwrap();
    let d = task.dyad_from_center(best[0].center).unwrap();
    let (o, e) = dense_gaps(
        task.poses(),
        d.center,
        d.circle,
        &slider,
        &obstacles,
        &envelope,
    )
    .unwrap();
    assert!(o > 0.5 * width && e > 0.5 * width, "{o} {e}");
}
