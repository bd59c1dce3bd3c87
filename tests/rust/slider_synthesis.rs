//! Slider dyads and inverted sliders of a task (issue 27): tasks made from
//! known slider-cranks and inverted slider-cranks, driven by an independent
//! closed-form solve, must have the known pin and guide (or swivel and body
//! line) among the library's; every slider dyad's positions, computed from
//! the poses directly, lie on its guide; the slider circle is the circle
//! through `P12`, `P13`, `P'23`; everything moves, turns and scales with
//! the task; the errors are typed.

mod common;

use std::f64::consts::PI;

use burmester::{
    CircleOrLine, DegenerateError, Error, InvalidInput, InvertedSlider, Point2, Pose, SliderDyad,
    Task, Vector2,
};
use proptest::prelude::*;

/// `cross(u, v)`.
fn cross(u: Vector2<f64>, v: Vector2<f64>) -> f64 {
    u.x * v.y - u.y * v.x
}

/// `v` turned by `a`.
fn turn(v: Vector2<f64>, a: f64) -> Vector2<f64> {
    let (s, c) = a.sin_cos();
    Vector2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// Where the coupler point that is at `z` at pose 1 is at pose `k`,
/// computed from the poses themselves (not the task's displacement):
/// `p_k + R(phi_k - phi_1) (z - p_1)`.
fn at_pose(poses: &[Pose], z: Point2<f64>, k: usize) -> Point2<f64> {
    let (p1, pk) = (poses[0], poses[k]);
    pk.position + turn(z - p1.position, pk.angle - p1.angle)
}

/// The largest distance of `z`'s positions from the line through its
/// position at pose 1 along `u` (unit), over the poses.
fn off_guide(poses: &[Pose], z: Point2<f64>, u: Vector2<f64>) -> f64 {
    (0..poses.len())
        .map(|k| cross(u, at_pose(poses, z, k) - z).abs())
        .fold(0.0, f64::max)
}

/// Whether two unit directions are parallel (either sign) within `tol`.
fn parallel(u: Vector2<f64>, v: Vector2<f64>, tol: f64) -> bool {
    cross(u, v).abs() <= tol
}

/// A slider-crank built by hand: crank `A0 A` (length `r`), coupler `A B`
/// (length `l`), the pin `B` on the guide through `g0` along the unit `u`,
/// and a coupler point at `(px, py)` in the coupler's frame (origin `A`,
/// x along `B - A`).
#[derive(Debug, Clone, Copy)]
struct SliderCrank {
    a0: Point2<f64>,
    r: f64,
    l: f64,
    g0: Point2<f64>,
    u: Vector2<f64>,
    point: Vector2<f64>,
}

impl SliderCrank {
    /// `(A, B)` at crank angle `t`, `B` ahead of the foot of the
    /// perpendicular from `A` to the guide (one assembly mode), by the
    /// textbook closed form: `B = g0 + s u` with `|B - A| = l`, the larger
    /// root of `s^2 + 2 s u.(g0 - A) + |g0 - A|^2 - l^2 = 0`. `None` where
    /// the coupler cannot reach the guide.
    fn solve(&self, t: f64) -> Option<(Point2<f64>, Point2<f64>)> {
        let a = self.a0 + Vector2::new(t.cos(), t.sin()) * self.r;
        let w = self.g0 - a;
        let h = self.u.dot(&w);
        let disc = h * h - w.norm_squared() + self.l * self.l;
        (disc > 0.0).then(|| (a, self.g0 + self.u * (-h + disc.sqrt())))
    }

    /// The coupler pose at crank angle `t`.
    fn pose(&self, t: f64) -> Option<Pose> {
        let (a, b) = self.solve(t)?;
        let phi = (b.y - a.y).atan2(b.x - a.x);
        let p = a + turn(self.point, phi);
        Some(Pose::new(p.x, p.y, phi))
    }

    fn poses(&self, angles: &[f64]) -> Option<Vec<Pose>> {
        angles.iter().map(|&t| self.pose(t)).collect()
    }

    /// The pin at the first crank angle.
    fn pin(&self, t: f64) -> Point2<f64> {
        self.solve(t).unwrap().1
    }
}

fn slider_crank() -> SliderCrank {
    SliderCrank {
        a0: Point2::new(0.0, 0.0),
        r: 1.0,
        l: 3.2,
        g0: Point2::new(0.5, -0.4),
        u: Vector2::new(0.2f64.cos(), 0.2f64.sin()),
        point: Vector2::new(1.0, 0.8),
    }
}

const ANGLES: [f64; 5] = [0.3, 0.9, 1.6, 2.2, 2.9];

/// An inverted slider-crank: crank `A0 A` (length `r`), the coupler a rod
/// through `A` that slides through a sleeve swivelling on the ground pin
/// `s`, and a coupler point at `point` in the rod's frame (origin `A`, x
/// toward the swivel).
fn inverted_poses(
    a0: Point2<f64>,
    r: f64,
    s: Point2<f64>,
    point: Vector2<f64>,
    angles: &[f64],
) -> Vec<Pose> {
    angles
        .iter()
        .map(|&t| {
            let a = a0 + Vector2::new(t.cos(), t.sin()) * r;
            let phi = (s.y - a.y).atan2(s.x - a.x);
            let p = a + turn(point, phi);
            Pose::new(p.x, p.y, phi)
        })
        .collect()
}

/// Checks that every slider dyad of `task` has its positions on its guide
/// (computed from the poses), through its pin, with a unit guide.
fn check_on_guides(task: &Task, sliders: &[SliderDyad], tol: f64) {
    for s in sliders {
        assert!((s.guide.norm() - 1.0).abs() < 1e-12);
        let off = off_guide(task.poses(), s.circle, s.guide);
        let reach = (s.circle - task.poses()[0].position).norm();
        assert!(off <= tol * (task.span() + reach), "{s:?}: off {off}");
    }
}

/// The slider dyad of `task` (four or five poses) whose pin is the
/// slider-crank's pin at the first crank angle, with the known guide;
/// every slider dyad's positions on its guide within `tol`.
fn known_slider(task: &Task, sc: &SliderCrank, tol: f64) -> SliderDyad {
    let b1 = sc.pin(ANGLES[0]);
    let sliders = task.slider_dyads(1).unwrap();
    check_on_guides(task, &sliders, tol);
    let found = *sliders
        .iter()
        .find(|s| (s.circle - b1).norm() < 10.0 * tol * task.span())
        .unwrap_or_else(|| panic!("{b1} not among {sliders:?}"));
    assert!(parallel(found.guide, sc.u, 10.0 * tol));
    found
}

#[test]
fn slider_crank_pin_is_on_the_slider_circle_of_three_poses() {
    let sc = slider_crank();
    let poses = sc.poses(&ANGLES[..3]).unwrap();
    let task = Task::new(&poses).unwrap();
    let b1 = sc.pin(ANGLES[0]);
    // The pin is on the circle through P12, P13, P'23 ...
    let Ok(CircleOrLine::Circle { center, radius }) = task.slider_circle() else {
        panic!("{:?}", task.slider_circle());
    };
    assert!(((b1 - center).norm() - radius).abs() < 1e-12 * task.span());
    // ... its slider dyad has the known guide ...
    let s = task.slider_dyad(b1).unwrap();
    assert_eq!(s.circle, b1);
    assert!(parallel(s.guide, sc.u, 1e-12), "{:?} {:?}", s.guide, sc.u);
    // ... and the crank's own dyad is the task's dyad of A0 (the poses are
    // those of the slider-crank).
    let d = task.dyad(sc.a0).unwrap();
    assert!((d.circle - sc.solve(ANGLES[0]).unwrap().0).norm() < 1e-12);
    // The circle is the image pole circle (a second construction).
    let Some(CircleOrLine::Circle {
        center: c2,
        radius: r2,
    }) = task.cremona().ok().map(|c| c.image_pole_circle())
    else {
        panic!("no image pole circle");
    };
    assert!((c2 - center).norm() < 1e-11 * radius && (r2 - radius).abs() < 1e-11 * radius);
    check_on_guides(&task, &task.slider_dyads(64).unwrap(), 1e-12);
}

#[test]
fn slider_crank_pin_is_a_slider_point_of_four_poses() {
    let sc = slider_crank();
    let task = Task::new(&sc.poses(&ANGLES[..4]).unwrap()).unwrap();
    let b1 = sc.pin(ANGLES[0]);
    let found = known_slider(&task, &sc, 1e-10);
    // The same through the curve's own list, and checked back.
    let four = task.four_positions("test").unwrap();
    assert!(
        four.slider_circle_points()
            .iter()
            .any(|p| (p - b1).norm() < 1e-9 * task.span())
    );
    assert_eq!(
        task.slider_dyad(b1 + Vector2::new(1e-12, 0.0)).unwrap(),
        found
    );
    let e = task.slider_dyad(b1 + Vector2::new(0.1, 0.0)).unwrap_err();
    assert_eq!(e.cause(), "not_a_slider_point", "{e}");
    assert!(e.to_string().contains("Task::slider_dyads"), "{e}");
}

#[test]
fn slider_crank_pin_is_a_slider_burmester_point_of_five_poses() {
    let sc = slider_crank();
    let task = Task::new(&sc.poses(&ANGLES).unwrap()).unwrap();
    let b1 = sc.pin(ANGLES[0]);
    known_slider(&task, &sc, 1e-9);
    // The conversion from the five-pose type keeps the normal.
    let five = task.five_positions("test").unwrap();
    for bs in five.sliders() {
        let s = SliderDyad::from(*bs);
        assert!((s.normal() - bs.direction).norm() < 1e-15);
    }
    // The crank is a Burmester point too (a check of the poses).
    assert!(
        five.burmester_points()
            .iter()
            .any(|d| (d.center - sc.a0).norm() < 1e-7)
    );
    assert!(task.slider_dyad(b1).is_ok());
}

#[test]
fn five_poses_without_a_slider_say_why() {
    // The notes' crank-rocker poses: four finite Burmester points.
    let task = Task::new(&common::notes_poses()).unwrap();
    let five = task.five_positions("test").unwrap();
    assert!(five.sliders().is_empty(), "{:?}", five.sliders());
    assert!(task.slider_dyads(1).unwrap().is_empty());
    let e = task.slider_dyad(Point2::new(0.0, 0.0)).unwrap_err();
    assert!(
        matches!(e, Error::InvalidInput(InvalidInput::NoSliderPoint { .. })),
        "{e}"
    );
    assert!(e.to_string().contains("finite center"), "{e}");
}

#[test]
fn inverted_slider_crank_swivel_is_found() {
    let (a0, r, s) = (Point2::new(0.0, 0.0), 1.0, Point2::new(3.5, 0.6));
    let point = Vector2::new(1.2, 0.7);
    for n in 3..=5 {
        let poses = inverted_poses(a0, r, s, point, &ANGLES[..n]);
        let task = Task::new(&poses).unwrap();
        let a1 = a0 + Vector2::new(ANGLES[0].cos(), ANGLES[0].sin()) * r;
        let line = (s - a1).normalize();
        let inv: InvertedSlider = match n {
            3 => task.inverted_slider(s).unwrap(),
            _ => *task
                .inverted_sliders(1)
                .unwrap()
                .iter()
                .find(|i| (i.swivel - s).norm() < 1e-8)
                .unwrap_or_else(|| panic!("{n} poses: {s} not among the swivels")),
        };
        assert!(parallel(inv.direction, line, 1e-8), "{n}: {inv:?}");
        // The body line passes the swivel at every pose (from the poses).
        for k in 0..n {
            let q = at_pose(&poses, a1, k);
            let d = turn(inv.direction, poses[k].angle - poses[0].angle);
            assert!(cross(d, s - q).abs() < 1e-8, "{n} poses, pose {}", k + 1);
        }
        // Every swivel's body line passes it at every pose.
        for i in task.inverted_sliders(16).unwrap() {
            for k in 1..=n {
                let l = i.body_line_at(&task, k).unwrap();
                assert!(
                    cross(l.direction, i.swivel - l.point).abs()
                        < 1e-8 * (1.0 + (i.swivel - a1).norm())
                );
            }
        }
    }
}

#[test]
fn swivels_of_three_poses_are_on_the_pole_circle() {
    let task = Task::from_xya(&[[0.0, 0.0, 0.0], [2.0, 0.5, 0.4], [3.0, 2.0, 1.1]]).unwrap();
    let inv = task.inverted().unwrap();
    let CircleOrLine::Circle { center, radius } = task.cremona().unwrap().pole_circle() else {
        panic!();
    };
    for i in task.inverted_sliders(40).unwrap() {
        assert!(((i.swivel - center).norm() - radius).abs() < 1e-12 * radius);
    }
    // Off the pole circle: typed, naming the swivel.
    let e = task.inverted_slider(center).unwrap_err();
    assert_eq!(e.cause(), "not_a_slider_point");
    assert!(e.to_string().contains("swivel point"), "{e}");
    assert!(e.to_string().contains("pole circle"), "{e}");
    // The inverted task's displacements are the inverse ones.
    let z = Point2::new(-0.4, 1.9);
    for k in 1..=3 {
        let back = task.displace(inv.displace(z, 1, k).unwrap(), 1, k).unwrap();
        assert!((back - z).norm() < 1e-13);
    }
}

#[test]
fn a_pure_translation_gives_a_line_and_all_translations_are_refused() {
    // Poses 2 and 3 share an angle: P23 is at infinity, the circle through
    // it a line.
    let task = Task::from_xya(&[[0.0, 0.0, 0.0], [2.0, 0.5, 0.4], [3.0, 2.0, 0.4]]).unwrap();
    let Ok(CircleOrLine::Line { point, direction }) = task.slider_circle() else {
        panic!("{:?}", task.slider_circle());
    };
    for t in [-50.0, -1.0, 0.0, 2.5, 1e3] {
        let z = point + direction * t;
        assert!(task.slider_dyad(z).is_ok(), "{t}");
    }
    let sliders = task.slider_dyads(33).unwrap();
    assert_eq!(sliders.len(), 33);
    check_on_guides(&task, &sliders, 1e-12);
    // All three poses one angle: no task (every point moves along the same
    // polygon: all slider points or none).
    let e = Task::from_xya(&[[0.0, 0.0, 0.4], [2.0, 0.5, 0.4], [3.0, 2.0, 0.4]]).unwrap_err();
    assert!(matches!(
        e,
        Error::Degenerate(DegenerateError::AllTranslations)
    ));
    // Four poses of one angle: a task, whose curves (and sliders) are
    // refused with the same error.
    let t4 = Task::from_xya(&[
        [0.0, 0.0, 0.4],
        [2.0, 0.5, 0.4],
        [3.0, 2.0, 0.4],
        [1.0, 3.0, 0.4],
    ])
    .unwrap();
    let e = t4.slider_dyads(1).unwrap_err();
    assert!(
        matches!(e, Error::Degenerate(DegenerateError::AllTranslations)),
        "{e}"
    );
}

#[test]
fn errors_are_typed() {
    let task = Task::from_xya(&[[0.0, 0.0, 0.0], [2.0, 0.5, 0.4], [3.0, 2.0, 1.1]]).unwrap();
    let e = task.slider_dyad(Point2::new(f64::NAN, 0.0)).unwrap_err();
    assert_eq!(e.cause(), "not_finite");
    let e = task.slider_dyad(Point2::new(10.0, 10.0)).unwrap_err();
    let Error::InvalidInput(InvalidInput::NotASliderPoint {
        distance,
        tolerance,
        ..
    }) = e
    else {
        panic!("{e}");
    };
    assert!(distance > tolerance && distance > 1.0);
    for n in [0, Task::MAX_SLIDER_SAMPLES + 1] {
        assert_eq!(
            task.slider_dyads(n).unwrap_err().cause(),
            "count_out_of_range"
        );
    }
    let five = Task::new(&common::notes_poses()).unwrap();
    assert_eq!(five.slider_circle().unwrap_err().cause(), "needs_poses");
}

#[test]
fn slider_dyads_at_the_documented_maximum() {
    let task = Task::from_xya(&[[0.0, 0.0, 0.0], [2.0, 0.5, 0.4], [3.0, 2.0, 1.1]]).unwrap();
    let sliders = task.slider_dyads(Task::MAX_SLIDER_SAMPLES).unwrap();
    assert_eq!(sliders.len(), Task::MAX_SLIDER_SAMPLES);
    let every: Vec<SliderDyad> = sliders.iter().step_by(97).copied().collect();
    check_on_guides(&task, &every, 1e-12);
    let inv = task.inverted_sliders(Task::MAX_SLIDER_SAMPLES).unwrap();
    assert_eq!(inv.len(), Task::MAX_SLIDER_SAMPLES);
}

proptest! {
    #![proptest_config(common::config(64))]

    /// Random points of the slider circle of random tasks: collinear
    /// positions, and the circle is the image pole circle.
    #[test]
    fn random_points_of_the_slider_circle_are_slider_points(
        task in common::task(),
        angles in prop::collection::vec(-PI..PI, 8),
    ) {
        let circle = task.slider_circle().unwrap();
        let CircleOrLine::Circle { center, radius } = circle else {
            return Err(TestCaseError::fail(format!("{circle:?}")));
        };
        if let CircleOrLine::Circle { center: c, radius: r } = task.cremona().unwrap().image_pole_circle() {
            prop_assert!((c - center).norm() <= 1e-9 * (radius + task.scale()));
            prop_assert!((r - radius).abs() <= 1e-9 * (radius + task.scale()));
        }
        for a in angles {
            let z = center + Vector2::new(a.cos(), a.sin()) * radius;
            let s = task.slider_dyad(z).unwrap();
            let p: Vec<Point2<f64>> = (0..3).map(|k| at_pose(task.poses(), z, k)).collect();
            let longest = (p[1] - p[0]).norm().max((p[2] - p[0]).norm()).max((p[2] - p[1]).norm());
            prop_assert!(cross(p[1] - p[0], p[2] - p[0]).abs() <= 1e-9 * longest * longest);
            prop_assert!(off_guide(task.poses(), z, s.guide) <= 1e-9 * (longest + task.span()));
        }
    }

    /// The slider points move, turn and scale with the task: the samples
    /// of three poses one by one, and the exact ones of four and five
    /// poses of random slider-cranks (whose pin is among them).
    #[test]
    fn slider_points_move_with_the_frame(
        r in 0.5f64..1.5,
        l in 2.5f64..4.0,
        gx in -0.5f64..0.5,
        gy in -0.8f64..0.0,
        gamma in -0.6f64..0.6,
        px in -1.0f64..1.0,
        py in 0.3f64..1.5,
        factor in 0.01f64..100.0,
        angle in -PI..PI,
        ox in -50.0f64..50.0,
        oy in -50.0f64..50.0,
    ) {
        let sc = SliderCrank {
            a0: Point2::new(0.0, 0.0),
            r,
            l,
            g0: Point2::new(gx, gy),
            u: Vector2::new(gamma.cos(), gamma.sin()),
            point: Vector2::new(px, py),
        };
        let Some(poses) = sc.poses(&ANGLES) else {
            return Ok(());
        };
        let map = |p: Point2<f64>| Point2::from(turn(p.coords * factor, angle) + Vector2::new(ox, oy));
        for n in 3..=5 {
            let Ok(task) = Task::new(&poses[..n]) else {
                continue;
            };
            let moved = task.transformed(factor, angle, Vector2::new(ox, oy)).unwrap();
            let (a, b) = match (task.slider_dyads(12), moved.slider_dyads(12)) {
                (Ok(a), Ok(b)) => (a, b),
                // A task refused (five poses whose points cannot be
                // resolved) must be refused when moved too.
                (Err(_), Err(_)) => continue,
                (a, b) => return Err(TestCaseError::fail(format!("{n}: {a:?} vs {b:?}"))),
            };
            prop_assert_eq!(a.len(), b.len(), "{} poses", n);
            let unit = task.span() + 1.0;
            for s in &a {
                let want = map(s.circle);
                let Some(m) = b.iter().min_by(|x, y| {
                    (x.circle - want).norm().total_cmp(&(y.circle - want).norm())
                }) else {
                    return Err(TestCaseError::fail("none"));
                };
                let reach = (s.circle - task.poses()[0].position).norm();
                prop_assert!(
                    (m.circle - want).norm() <= 1e-7 * factor * (unit + reach),
                    "{} poses: {} vs {}", n, m.circle, want
                );
                prop_assert!(parallel(m.guide, turn(s.guide, angle), 1e-7));
            }
            check_on_guides(&task, &a, 1e-8);
            let b1 = sc.pin(ANGLES[0]);
            if n > 3 {
                prop_assert!(
                    a.iter().any(|s| (s.circle - b1).norm() <= 1e-7 * unit),
                    "{} poses: {} not among {:?}", n, b1, a
                );
            } else {
                prop_assert!(task.slider_dyad(b1).is_ok());
            }
        }
    }
}
