//! Every degenerate case of the kinematics notes (section 5, "where the
//! numbers get hard") with its deliberate, documented behaviour:
//!
//! | case | behaviour |
//! |---|---|
//! | pure translation between two of three poses | accepted, its pole `Pole::AtInfinity`: the maps, Filemon's construction and the solution maps run by the linear form (`tests/rust/translation.rs`); what needs three finite poles (`Task::cremona`: pole triangle, pole circles, image poles) is `DegenerateError::PureTranslation`; with four or five poses accepted too |
//! | all three poses with one angle | rejected: `DegenerateError::AllTranslations` (every crank the same vector: parallelograms at their change point) |
//! | a rotation just above `tolerance::MIN_ROTATION` | accepted; its pole is finite (the pole triangle exists) but far, so the maps run by the linear form (`tolerance::POLE_DISTANCE`) and keep the input's accuracy (`tests/python/test_conditioning.py`) |
//! | coincident poses | rejected: `DegenerateError::CoincidentPoses` |
//! | rotations about one point (coincident poles) | rejected: `DegenerateError::CoincidentPoles` |
//! | collinear poles | only in the translation limit (a pole at infinity: the linear form); `CircleOrLine::Line` for collinear points given directly |
//! | driven center point on the pole circle (`C1` at infinity) | `Task::filemon` fails with `DegenerateError::AtInfinity` (with the direction); just off it, everything works |
//! | a Filemon line tangent to the image-pole circle | the conic is a `Parabola` (no center, no asymptotes, one branch), for `line_to_conic` and in an actual construction |
//! | a driving center point at a pole or at `C0` | `conic`: `Boundary`; `direct`: `Undefined` at a pole, `Boundary` at `C0`; `simulate`: an error; maps `false`, margin `-0.0` |
//! | points on the curves | `Boundary` only where a value is exactly zero; either side within the band, the right side beyond it |
//! | tasks at scale 1e-6 and 1e6 | the same answers, scaled |

use std::f64::consts::PI;

use burmester::tolerance::MIN_ROTATION;
use burmester::{
    Branch, CircleOrLine, ConicKind, Cremona, DegenerateError, Error, Filemon, Grid, InvalidInput,
    Line, Method, Point2, Pole, Pose, Task, Vector2, Viewport,
};

fn example() -> Task {
    burmester::example::task()
}

/// The conic and the direct classifier agree at every point of `ys` off
/// the band about the curves (the margin more than `1e-7` task sizes) and
/// off the pole circle; a failure names the point after `label`.
fn classifiers_agree_off_the_band(t: &Task, f: &Filemon, ys: &[Point2<f64>], label: &str) {
    for &y in ys {
        if f.margin(y).unwrap().abs() > 1e-7 * t.scale()
            && cremona(t).pole_circle().side(y).abs() > 1e-6
        {
            assert_eq!(
                f.classify(y, Method::Conic).unwrap(),
                f.classify(y, Method::Direct).unwrap(),
                "{label}at {y}"
            );
        }
    }
}

/// The three-position maps of a three-pose task.
fn cremona(t: &Task) -> &Cremona {
    t.cremona().unwrap()
}

const C0: Point2<f64> = Point2::new(4.0, -1.0);

/// A deterministic spread of points over `[-r, r]^2` around `c`.
fn points(c: Point2<f64>, r: f64, n: usize) -> Vec<Point2<f64>> {
    (0..n)
        .map(|k| {
            let a = k as f64 * 2.399_963_229_728_653; // golden angle
            let s = r * ((k as f64 + 0.5) / n as f64).sqrt();
            c + Vector2::new(a.cos(), a.sin()) * s
        })
        .collect()
}

#[test]
fn a_pure_translation_has_no_pole_triangle() {
    for (a2, i, j) in [(0.3, 1, 2), (0.3 + 2.0 * PI, 1, 2), (0.3 + 0.9e-6, 1, 2)] {
        let t = Task::from_xya(&[[0.0, 0.0, 0.3], [1.0, 0.0, a2], [3.0, 2.0, 1.1]]).unwrap();
        let e = t.cremona().unwrap_err();
        assert!(
            matches!(e, Error::Degenerate(DegenerateError::PureTranslation { i: ii, j: jj }) if (ii, jj) == (i, j)),
            "{e:?}"
        );
        let msg = e.to_string();
        for word in [
            "translation",
            "infinity",
            "pole triangle",
            "rotate one of the poses",
            "1e-6",
        ] {
            assert!(msg.contains(word), "{msg}");
        }
        // The maps work without it.
        let y = Point2::new(1.0, -2.0);
        assert!((t.center_point(t.circle_point(y).unwrap()).unwrap() - y).norm() < 1e-12);
    }
    // Poses 2 and 3.
    let t = Task::from_xya(&[[0.0, 0.0, 0.3], [1.0, 0.0, 1.1], [3.0, 2.0, 1.1]]).unwrap();
    assert!(matches!(
        t.cremona().unwrap_err(),
        Error::Degenerate(DegenerateError::PureTranslation { i: 2, j: 3 })
    ));
    // Four poses need no pole of every pair: the translation's pole is at
    // infinity, perpendicular to the translation, and the three-position
    // maps are refused (they need three poses).
    let t = Task::from_xya(&[
        [0.0, 0.0, 0.3],
        [1.0, 0.0, 1.1],
        [3.0, 2.0, 1.1],
        [-1.0, 2.0, 0.2],
    ])
    .unwrap();
    let Pole::AtInfinity { direction } = t.poles()[3] else {
        panic!("{:?}", t.poles())
    };
    assert!((direction.dot(&Vector2::new(2.0, 2.0))).abs() < 1e-15);
    assert!((direction.norm() - 1.0).abs() < 1e-15);
    assert!(
        t.poles()
            .iter()
            .enumerate()
            .all(|(k, p)| (k == 3) != p.finite().is_some())
    );
    assert!(matches!(
        t.cremona().unwrap_err(),
        Error::InvalidInput(InvalidInput::NeedsPoses {
            required: 3,
            found: 4,
            ..
        })
    ));
}

/// Just above `tolerance::MIN_ROTATION` the task is accepted, its pole is far
/// away, and the maps keep a few `eps / theta` of relative accuracy.
#[test]
fn a_near_translation_is_accepted_and_accurate() {
    let theta = 2.0 * MIN_ROTATION;
    let t = Task::from_xya(&[[0.0, 0.0, 0.0], [2.0, 0.5, theta], [3.0, 2.0, 1.1]]).unwrap();
    let spread = 3.7;
    assert!(t.scale() > 1e5, "P12 is far away: {}", t.scale());
    assert!(matches!(
        cremona(&t).pole_circle(),
        CircleOrLine::Circle { .. }
    ));
    let f = t.filemon(C0).unwrap();
    let mut checked = 0;
    for y in points(Point2::new(1.5, 1.0), 6.0, 200) {
        let Ok(x) = t.circle_point(y) else { continue };
        let size = spread + (x - y).norm();
        let back = t.center_point(x).unwrap();
        assert!((back - y).norm() < 1e-7 * size, "{y} -> {x} -> {back}");
        let r = [1, 2, 3].map(|k| (t.displace(x, 1, k).unwrap() - y).norm());
        assert!((r[0] - r[1]).abs() < 1e-7 * size && (r[0] - r[2]).abs() < 1e-7 * size);
        // The two classifiers agree off a band of 1e-6 of the spread.
        if f.margin(y).unwrap().abs() > 1e-6 * spread {
            assert_eq!(
                f.classify(y, Method::Conic).unwrap(),
                f.classify(y, Method::Direct).unwrap(),
                "at {y}"
            );
            checked += 1;
        }
    }
    assert!(checked > 150, "{checked}");
}

#[test]
fn coincident_poses_and_poles_are_rejected() {
    let e = Task::from_xya(&[[1.0, 2.0, 0.3], [1.0, 2.0, 0.3], [3.0, 2.0, 1.1]]).unwrap_err();
    assert!(matches!(
        e,
        Error::Degenerate(DegenerateError::CoincidentPoses { i: 1, j: 2 })
    ));
    assert!(e.to_string().contains("move or rotate one of them"), "{e}");
    // Equal positions with different angles: a rotation about that point.
    let t = Task::from_xya(&[[1.0, 2.0, 0.3], [1.0, 2.0, 0.9], [3.0, 2.0, 1.1]]).unwrap();
    assert!((cremona(&t).poles()[0] - Point2::new(1.0, 2.0)).norm() < 1e-15);
    // Rotations about one point, up to rounding: all poles coincide.
    let c = Point2::new(-3.0, 5.0);
    let poses = [0.2, 1.0, 2.1].map(|a: f64| {
        let p = c + Vector2::new(a.cos(), a.sin()) * 4.0;
        Pose::new(p.x, p.y + 1e-14, a)
    });
    let e = Task::new(&poses).unwrap_err();
    assert!(
        matches!(
            e,
            Error::Degenerate(DegenerateError::CoincidentPoles { .. })
        ),
        "{e:?}"
    );
    assert!(e.to_string().contains("move one pose"), "{e}");
}

/// The pole triangle's angles are `theta_ij / 2` (mod pi), so the poles are
/// collinear only when some `theta_ij` is a whole turn: a translation,
/// which is rejected. Collinear points given directly make a line.
#[test]
fn collinear_poles_occur_only_in_the_translation_limit() {
    for theta in [1e-1, 1e-3, 1e-5, 2e-6] {
        let t = Task::from_xya(&[[0.0, 0.0, 0.0], [2.0, 0.5, theta], [3.0, 2.0, 1.1]]).unwrap();
        let a = cremona(&t).pole_triangle_angles();
        assert!((a[0].abs() - theta / 2.0).abs() < 1e-9, "{a:?}");
        let CircleOrLine::Circle { center, radius } = cremona(&t).pole_circle() else {
            panic!("a proper circle at theta = {theta}")
        };
        // Its points still have their circle point at infinity.
        let y = center + Vector2::new(0.0, 1.0) * radius;
        let far = (y - cremona(&t).poles()[1]).norm() / t.scale();
        if far > 1e-3 {
            assert!(
                matches!(
                    t.circle_point(y),
                    Err(Error::Degenerate(DegenerateError::AtInfinity { .. }))
                ) || t.circle_point(y).unwrap().coords.norm() > 1e6 * t.scale(),
                "theta = {theta}"
            );
        }
    }
    let line = CircleOrLine::through(
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(3.0, 3.0),
    );
    let CircleOrLine::Line { point, direction } = line else {
        panic!("{line:?}")
    };
    assert!((direction.norm() - 1.0).abs() < 1e-15);
    assert_eq!(point, Point2::new(0.0, 0.0));
    assert_eq!(line.side(Point2::new(2.0, 2.0)), 0.0);
}

#[test]
fn a_driven_center_on_the_pole_circle_has_its_circle_point_at_infinity() {
    let t = example();
    let CircleOrLine::Circle { center, radius } = cremona(&t).pole_circle() else {
        panic!()
    };
    let w = Vector2::new(0.8f64.cos(), 0.8f64.sin());
    let on = center + w * radius;
    let e = t.filemon(on).unwrap_err();
    let Error::Degenerate(DegenerateError::AtInfinity { dir_x, dir_y, .. }) = e else {
        panic!("{e:?}")
    };
    assert!((dir_x.hypot(dir_y) - 1.0).abs() < 1e-12);
    let msg = e.to_string();
    assert!(
        msg.contains("pole circle")
            && msg.contains("infinity")
            && msg.contains("choose a point off it"),
        "{msg}"
    );
    // Just off the circle: C1 is far away, and everything still works.
    for off in [1e-6, -1e-6, 1e-9] {
        let c0 = center + w * (radius * (1.0 + off));
        let f = t.filemon(c0).unwrap();
        let c1 = f.driven_circle();
        assert!((c1 - c0).norm() > 1e3 * t.scale(), "C1 = {c1}");
        let Some(conics) = f.conics() else { continue };
        for g in conics {
            for p in cremona(&t).poles().iter().chain([&c0]) {
                assert!(g.distance_estimate(*p) < 1e-9 * t.scale());
            }
        }
        let near = points(Point2::new(1.0, 0.0), 6.0, 200);
        classifiers_agree_off_the_band(&t, &f, &near, &format!("off = {off}, "));
    }
}

#[test]
fn a_line_tangent_to_the_image_pole_circle_gives_a_parabola() {
    let t = example();
    let CircleOrLine::Circle { center, radius } = cremona(&t).image_pole_circle() else {
        panic!()
    };
    let vp = Viewport::new(-10.0, 10.0, -10.0, 10.0).unwrap();
    for a in [0.3f64, 1.0, 2.5, -2.0] {
        let n = Vector2::new(a.cos(), a.sin());
        let d = Vector2::new(-n.y, n.x);
        let conic = |r: f64| {
            t.line_to_conic(&Line {
                point: center + n * r,
                direction: d,
            })
            .unwrap()
        };
        let g = conic(radius);
        assert_eq!(g.kind(), ConicKind::Parabola, "a = {a}");
        assert_eq!(g.center(), None);
        assert!(g.asymptotes().is_none());
        let lines = g.polylines(&vp, None).unwrap();
        assert_eq!(lines.len(), 1, "one branch");
        for p in &lines[0][1..lines[0].len() - 1] {
            assert!(g.distance_estimate(*p) < 1e-9);
        }
        for p in cremona(&t).poles() {
            assert!(g.distance_estimate(p) < 1e-12);
        }
        // Property 1 on either side of the tangent.
        assert_eq!(conic(radius * (1.0 + 1e-9)).kind(), ConicKind::Ellipse);
        assert_eq!(conic(radius * (1.0 - 1e-9)).kind(), ConicKind::Hyperbola);
    }
}

/// The same in an actual construction: a driven center point chosen (by
/// bisection along a line) so that a Filemon line is tangent to the
/// image-pole circle.
#[test]
fn a_filemon_line_tangent_to_the_image_pole_circle_gives_a_parabola() {
    let t = example();
    let CircleOrLine::Circle { center, radius } = cremona(&t).image_pole_circle() else {
        panic!()
    };
    let c0_at = |s: f64| C0 + Vector2::new(1.0, 0.7) * s;
    // Line 1's distance from the circle's center, minus the radius.
    let gap = |s: f64| {
        let f = t.filemon(c0_at(s)).unwrap();
        let l = f.all_lines()[0];
        let d = l.direction.normalize();
        (d.x * (center.y - l.point.y) - d.y * (center.x - l.point.x)).abs() - radius
    };
    let (mut a, mut b) = (-0.9, -0.5);
    assert!(gap(a) * gap(b) < 0.0);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if gap(m) * gap(a) <= 0.0 {
            b = m;
        } else {
            a = m;
        }
    }
    let f = t.filemon(c0_at(a)).unwrap();
    let (extremes, _) = f.extreme_poses().unwrap();
    assert!(extremes.contains(&1), "line 1 is a Filemon line");
    let g = f.line_conic(1).unwrap();
    assert_eq!(g.kind(), ConicKind::Parabola);
    assert!(g.center().is_none() && g.asymptotes().is_none());
    let vp = Viewport::new(-10.0, 10.0, -10.0, 10.0).unwrap();
    assert_eq!(g.polylines(&vp, None).unwrap().len(), 1);
    // The classifiers still agree off the band.
    classifiers_agree_off_the_band(&t, &f, &points(Point2::new(0.0, 0.0), 8.0, 300), "");
}

#[test]
fn a_driving_center_at_a_pole_or_at_c0_is_a_boundary() {
    let t = example();
    let f = t.filemon(C0).unwrap();
    let s = t.scale();
    for (k, &p) in f.special_points().iter().enumerate() {
        let is_c0 = k == 3;
        for q in [p, p + Vector2::new(0.5e-12, -0.5e-12) * s] {
            assert_eq!(f.classify(q, Method::Conic).unwrap(), Branch::Boundary);
            assert_eq!(f.margin(q).unwrap(), 0.0);
            assert!(f.margin(q).unwrap().is_sign_negative());
        }
        match f.classify(p, Method::Direct) {
            Ok(b) => {
                assert!(is_c0, "direct at a pole must fail");
                assert_eq!(b, Branch::Boundary);
            }
            Err(e) => {
                assert!(!is_c0);
                assert!(
                    matches!(e, Error::Degenerate(DegenerateError::Undefined { .. })),
                    "{e:?}"
                );
                assert!(e.to_string().contains("not unique"));
            }
        }
        let e = f.classify(p, Method::Simulate).unwrap_err();
        assert!(matches!(e, Error::Degenerate(_)), "{e:?}");
        if is_c0 {
            assert!(
                matches!(e, Error::Degenerate(DegenerateError::ZeroLengthLink { .. })),
                "{e:?}"
            );
        }
        // A one-sample grid on the point, and a fine grid around it.
        let one = Grid::from_bounds(p.x - 1.0, p.x + 1.0, p.y - 1.0, p.y + 1.0, 1, 1).unwrap();
        for m in [Method::Conic, Method::Direct, Method::Simulate] {
            assert_eq!(f.branch_map(&one, m), vec![false]);
        }
        assert!(f.margin_map(&one)[0] <= 0.0);
    }
}

/// On a curve the value is zero up to rounding: `Boundary` where it is
/// exactly zero, either side within the band, and the right side (both
/// methods) a little beyond it.
#[test]
fn points_on_the_curves() {
    let t = example();
    let f = t.filemon(C0).unwrap();
    let [ga, gb] = f.conics().unwrap();
    let s = t.scale();
    let mut crossings = 0;
    for (k, base) in points(Point2::new(0.0, 0.0), 7.0, 60)
        .into_iter()
        .enumerate()
    {
        let a = k as f64 * 0.7;
        let line = Line {
            point: base,
            direction: Vector2::new(a.cos(), a.sin()),
        };
        for (g, other) in [(ga, gb), (gb, ga)] {
            for p in g.intersect_line(&line) {
                assert!(g.distance_estimate(p) < 1e-12 * s, "{p}");
                let c = f.classify(p, Method::Conic).unwrap();
                if g.evaluate(p) == 0.0 {
                    assert_eq!(c, Branch::Boundary);
                }
                // Step off the curve along its normal, both ways.
                let n = g.gradient(p).normalize();
                let step = 1e-7 * s;
                if other.distance_estimate(p) < 1e3 * step
                    || cremona(&t).pole_circle().side(p).abs() < 1e3 * step
                    || f.special_points()
                        .iter()
                        .any(|q| (q - p).norm() < 1e3 * step)
                {
                    continue;
                }
                let sides = [1.0, -1.0].map(|sg| {
                    let q = p + n * (sg * step);
                    let c = f.classify(q, Method::Conic).unwrap();
                    assert_eq!(c, f.classify(q, Method::Direct).unwrap(), "at {q}");
                    c
                });
                assert_ne!(
                    sides[0], sides[1],
                    "the curve separates free from defective at {p}"
                );
                assert!(sides.contains(&Branch::Free) && sides.contains(&Branch::Defective));
                crossings += 1;
            }
        }
    }
    assert!(crossings > 50, "{crossings}");
}

/// Tasks scaled to 1e-6 and 1e6 (and moved): the poles, the circle points
/// and the branch maps scale with them.
#[test]
fn tasks_at_scale_1e_minus_6_and_1e6() {
    let t = example();
    let f = t.filemon(C0).unwrap();
    let vp = (-8.0, 8.0, -8.0, 8.0);
    let n = 128;
    let g1 = Grid::from_bounds(vp.0, vp.1, vp.2, vp.3, n, n).unwrap();
    let m1 = f.branch_map(&g1, Method::Conic);
    for k in [1e-6, 1e6] {
        let off = Vector2::new(3.0, -2.0) * k;
        let map = |p: Point2<f64>| Point2::from(p.coords * k + off);
        let poses: Vec<Pose> = t
            .poses()
            .iter()
            .map(|p| Pose {
                position: map(p.position),
                angle: p.angle,
            })
            .collect();
        let tk = Task::new(&poses).unwrap();
        assert!((tk.scale() - k * t.scale()).abs() < 1e-12 * k * t.scale());
        for (p, q) in cremona(&t).poles().iter().zip(cremona(&tk).poles()) {
            assert!((map(*p) - q).norm() < 1e-12 * k * t.scale());
        }
        let fk = tk.filemon(map(C0)).unwrap();
        assert!((map(f.driven_circle()) - fk.driven_circle()).norm() < 1e-11 * k * t.scale());
        for (a, b) in f.conics().unwrap().iter().zip(fk.conics().unwrap()) {
            assert_eq!(a.kind(), b.kind());
        }
        let gk = Grid::from_bounds(
            vp.0 * k + off.x,
            vp.1 * k + off.x,
            vp.2 * k + off.y,
            vp.3 * k + off.y,
            n,
            n,
        )
        .unwrap();
        let mk = fk.branch_map(&gk, Method::Conic);
        for j in 0..n {
            for i in 0..n {
                let idx = j * n + i;
                if m1[idx] != mk[idx] {
                    // Only within rounding of a curve.
                    let p = g1.point(i, j);
                    assert!(
                        f.margin(p).unwrap().abs() < 1e-9 * t.scale(),
                        "k = {k} at {p}"
                    );
                }
            }
        }
        assert!(mk.iter().any(|&b| b) && !mk.iter().all(|&b| b));
        for y in points(Point2::new(0.0, 0.0), 6.0, 50) {
            if let (Ok(x), Ok(xk)) = (t.circle_point(y), tk.circle_point(map(y))) {
                let size = t.scale() + (x - y).norm();
                assert!((map(x) - xk).norm() < 1e-9 * k * size);
            }
        }
    }
}
