//! Three-pose tasks with a pure translation between two poses (a pole at
//! infinity): the maps, Filemon's construction, the branch maps and the
//! solution map, checked against things computed here independently
//! (circumcenters, linkages driven through their poses) and across the
//! threshold `tolerance::MIN_ROTATION`.

use std::f64::consts::PI;

use burmester::{
    AssemblyMode, DegenerateError, DesignLimits, Error, Filemon, FourBar, Grid, Method, Point2,
    Pole, Pose, Similarity, Task, Vector2,
};
mod common;

/// `D_1k(z) = p_k + e^{i (phi_k - phi_1)} (z - p_1)`, written here from the
/// poses (not through the crate's motion).
fn carry(poses: &[Pose], k: usize, z: Point2<f64>) -> Point2<f64> {
    let (s, c) = (poses[k].angle - poses[0].angle).sin_cos();
    let d = z - poses[0].position;
    poses[k].position + Vector2::new(c * d.x - s * d.y, s * d.x + c * d.y)
}

/// The circumcenter of three points, by the perpendicular bisectors.
fn circumcenter(a: Point2<f64>, b: Point2<f64>, c: Point2<f64>) -> Point2<f64> {
    let (u, v) = (b - a, c - a);
    let d = 2.0 * (u.x * v.y - u.y * v.x);
    let (uu, vv) = (u.norm_squared(), v.norm_squared());
    a + Vector2::new(v.y * uu - u.y * vv, u.x * vv - v.x * uu) / d
}

fn poses(xya: &[[f64; 3]]) -> Vec<Pose> {
    xya.iter().map(|&[x, y, a]| Pose::new(x, y, a)).collect()
}

/// Two poses, 1-based.
type Pair = (usize, usize);

/// A task of [`translation_tasks`]: as given, as a task, its driven
/// center and its Filemon construction.
type Translated = (Vec<[f64; 3]>, Task, Point2<f64>, Filemon);

/// Each of [`translation_tasks`] as given, as a task, and its Filemon
/// construction for the driven center `(4, -1)` (with that center).
fn translated_filemons() -> Vec<Translated> {
    translation_tasks()
        .into_iter()
        .map(|(xya, _)| {
            let t = Task::from_xya(&xya).unwrap();
            let c0 = Point2::new(4.0, -1.0);
            let f = t.filemon(c0).unwrap();
            (xya, t, c0, f)
        })
        .collect()
}

/// Tasks with a pure translation between poses (1,2), (1,3), (2,3), one
/// with a turn of a whole revolution, and one with two pairs within the
/// rotation bound (their third pole far away, but finite).
fn translation_tasks() -> Vec<(Vec<[f64; 3]>, Pair)> {
    vec![
        (
            vec![[0.0, 0.0, 0.3], [2.0, 0.5, 0.3], [3.0, 2.0, 1.1]],
            (1, 2),
        ),
        (
            vec![[1.0, -1.0, -0.4], [2.5, 1.0, 0.6], [4.0, 0.0, -0.4]],
            (1, 3),
        ),
        (
            vec![[0.0, 1.0, 0.2], [-1.0, 3.0, 1.0], [2.0, 4.0, 1.0]],
            (2, 3),
        ),
        (
            vec![
                [0.0, 0.0, 0.3],
                [2.0, 0.5, 0.3 + 2.0 * PI],
                [3.0, 2.0, -0.8],
            ],
            (1, 2),
        ),
        (
            vec![[0.0, 0.0, 0.0], [2.0, 0.5, 0.9e-6], [3.0, 2.0, -0.9e-6]],
            (1, 2),
        ),
    ]
}

/// A spread of points (golden angle) in a disc of radius `r` around `c`.
fn spread(c: Point2<f64>, r: f64, n: usize) -> Vec<Point2<f64>> {
    (0..n)
        .map(|k| {
            let a = k as f64 * 2.399_963_229_728_653;
            let s = r * ((k as f64 + 0.5) / n as f64).sqrt();
            c + Vector2::new(a.cos(), a.sin()) * s
        })
        .collect()
}

#[test]
fn a_translation_is_accepted_and_its_pole_is_a_direction() {
    for (xya, (i, j)) in translation_tasks() {
        let t = Task::from_xya(&xya).unwrap();
        let p = poses(&xya);
        let pair = [(1, 2), (1, 3), (2, 3)]
            .iter()
            .position(|&q| q == (i, j))
            .unwrap();
        let Pole::AtInfinity { direction } = t.poles()[pair] else {
            panic!("{:?}", t.poles())
        };
        let travel = p[j - 1].position - p[i - 1].position;
        assert!(direction.dot(&travel).abs() < 1e-12 * travel.norm());
        // The pole triangle does not exist: typed, naming the pair.
        let e = t.cremona().unwrap_err();
        assert!(
            matches!(e, Error::Degenerate(DegenerateError::PureTranslation { i: a, j: b }) if (a, b) == (i, j)),
            "{e:?}"
        );
        assert_eq!(e.cause(), "pure_translation");
        assert!(e.to_string().contains("pole triangle"), "{e}");
        // The scale: the largest distance between the pose positions and
        // the finite poles.
        let mut pts: Vec<Point2<f64>> = p.iter().map(|q| q.position).collect();
        pts.extend(t.poles().iter().filter_map(Pole::finite));
        let mut size: f64 = 0.0;
        for a in &pts {
            for b in &pts {
                size = size.max((a - b).norm());
            }
        }
        assert!(
            (t.scale() - size).abs() <= 1e-15 * size,
            "{} {size}",
            t.scale()
        );
    }
}

#[test]
fn all_translations_are_refused_with_the_reason() {
    for xya in [
        [[0.0, 0.0, 0.3], [2.0, 0.5, 0.3], [3.0, 2.0, 0.3]],
        [
            [0.0, 0.0, 0.3],
            [2.0, 0.5, 0.3 + 0.4e-6],
            [3.0, 2.0, 0.3 - 0.4e-6],
        ],
    ] {
        let e = Task::from_xya(&xya).unwrap_err();
        assert!(
            matches!(e, Error::Degenerate(DegenerateError::AllTranslations)),
            "{e:?}"
        );
        assert!(e.to_string().contains("parallelogram"), "{e}");
    }
    // Which is what the maps would say: with one angle, every dyad's crank
    // is the same vector (the circumcenter offset of 0, -t2, -t3).
    let p = poses(&[[0.0, 0.0, 0.3], [2.0, 0.5, 0.3], [3.0, 2.0, 0.3]]);
    let crank = |g: Point2<f64>| {
        let x = circumcenter(
            g,
            g - (p[1].position - p[0].position),
            g - (p[2].position - p[0].position),
        );
        x - g
    };
    let c = crank(Point2::new(0.0, 0.0));
    for g in spread(Point2::new(1.0, 1.0), 5.0, 20) {
        assert!((crank(g) - c).norm() < 1e-12 * (1.0 + c.norm() + g.coords.norm()));
    }
}

#[test]
fn hand_built_dyads_come_back_from_the_maps() {
    for (xya, _) in translation_tasks() {
        let t = Task::from_xya(&xya).unwrap();
        let p = poses(&xya);
        let s = t.scale();
        let mut checked = 0;
        for z in spread(Point2::new(1.0, 0.5), 8.0, 200) {
            let g = circumcenter(z, carry(&p, 1, z), carry(&p, 2, z));
            if g.coords.norm() >= 1e4 || !g.coords.norm().is_finite() {
                continue; // near the image-pole circle: a slider
            }
            let tol = 1e-9 * (s + z.coords.norm() + g.coords.norm());
            let y = t.center_point(z).unwrap();
            assert!((y - g).norm() < tol, "{xya:?} {z:?}: {y:?} vs {g:?}");
            let x = t.circle_point(g).unwrap();
            assert!((x - z).norm() < tol, "{xya:?} {g:?}: {x:?} vs {z:?}");
            // The dyad's three moving-pivot positions are concyclic about
            // its center point.
            let d = t.dyad_from_center(g).unwrap();
            let r: Vec<f64> = t.moving_pivots(&d).iter().map(|m| (m - g).norm()).collect();
            for rk in &r[1..] {
                assert!((rk - r[0]).abs() < tol, "{r:?}");
            }
            checked += 1;
        }
        assert!(checked > 150, "{checked}");
    }
}

/// The poses of a crank-rocker at three input angles, two of them where the
/// coupler angle repeats (on either side of its maximum): a task with a
/// pure translation between poses 1 and 3, made from a known linkage.
fn linkage_task() -> (FourBar, Task, [f64; 3]) {
    let fb =
        FourBar::from_pivots(Point2::new(0.0, 0.0), Point2::new(4.0, 0.5), 1.0, 3.5, 3.0).unwrap();
    let mode = AssemblyMode::Open;
    let theta3 = |a: f64| fb.solve(a, mode).unwrap().theta3;
    // The maximum of theta3 over a dense scan, then the two inputs where
    // theta3 equals a level below it, by bisection on either side.
    let n = 3600;
    let (mut best, mut at) = (f64::NEG_INFINITY, 0.0);
    for k in 0..n {
        let a = 2.0 * PI * k as f64 / n as f64;
        if theta3(a) > best {
            (best, at) = (theta3(a), a);
        }
    }
    let level = best - 0.05;
    let root = |mut lo: f64, mut hi: f64| {
        // theta3(lo) < level < theta3(hi) or the reverse.
        let up = theta3(hi) > theta3(lo);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if (theta3(mid) > level) == up {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let step = 0.01;
    let mut a = at;
    while theta3(a) > level {
        a -= step;
    }
    let first = root(a, a + step);
    let mut b = at;
    while theta3(b) > level {
        b += step;
    }
    let third = root(b, b - step);
    let inputs = [first, 0.5 * (first + third) + PI, third];
    let point = Vector2::new(1.2, 0.8);
    let xya: Vec<Pose> = inputs
        .iter()
        .map(|&a| {
            let c = fb.solve(a, mode).unwrap();
            let j = fb.joints(&c);
            {
                let q = j.coupler_point(point);
                Pose::new(q.x, q.y, c.theta3)
            }
        })
        .collect();
    assert!((xya[2].angle - xya[0].angle).abs() < 1e-12);
    (fb, Task::new(&xya).unwrap(), inputs)
}

#[test]
fn a_linkage_with_a_repeated_coupler_angle_is_recovered() {
    let (fb, t, inputs) = linkage_task();
    assert!(matches!(t.poles()[1], Pole::AtInfinity { .. }));
    let c = fb.solve(inputs[0], AssemblyMode::Open).unwrap();
    let j = fb.joints(&c);
    let tol = 1e-9 * t.scale();
    let a1 = t.circle_point(j.input_pivot).unwrap();
    assert!(
        (a1 - j.crank_joint).norm() < tol,
        "{a1:?} {:?}",
        j.crank_joint
    );
    let c1 = t.circle_point(j.output_pivot).unwrap();
    assert!((c1 - j.rocker_joint).norm() < tol);
    assert!((t.center_point(j.rocker_joint).unwrap() - j.output_pivot).norm() < tol);
    // The linkage built back from its dyads reaches the poses in one mode
    // (a crank-rocker driven by its crank has no branch defect), and
    // Filemon's test says so by every method.
    let driving = t.dyad_from_center(j.input_pivot).unwrap();
    let driven = t.dyad_from_center(j.output_pivot).unwrap();
    let built = t.four_bar(&driving, &driven).unwrap();
    assert!(built.is_branch_free());
    let f = t.filemon(j.output_pivot).unwrap();
    for m in [Method::Conic, Method::Direct, Method::Simulate] {
        assert!(f.is_branch_free(j.input_pivot, m).unwrap(), "{m:?}");
    }
}

/// Whether `p` is within `band` of either Filemon conic (first-order
/// distance) or of a special point.
fn near_curves(f: &burmester::Filemon, p: Point2<f64>, band: f64) -> bool {
    let Some([a, b]) = f.conics() else {
        return false;
    };
    a.distance_estimate(p) < band
        || b.distance_estimate(p) < band
        || f.special_points().iter().any(|q| (q - p).norm() < band)
}

#[test]
fn branch_maps_agree_with_the_built_linkages() {
    let mut tasks: Vec<Task> = translation_tasks()
        .into_iter()
        .map(|(xya, _)| Task::from_xya(&xya).unwrap())
        .collect();
    tasks.push(linkage_task().1);
    let (mut free, mut defective) = (0, 0);
    for t in &tasks {
        for c0 in [Point2::new(4.0, -1.0), Point2::new(-2.0, 3.0)] {
            let Ok(f) = t.filemon(c0) else { continue };
            if f.all_defective() {
                continue;
            }
            let n = 48;
            let g = Grid::from_bounds(-8.0, 10.0, -8.0, 10.0, n, n).unwrap();
            let conic = f.branch_map(&g, Method::Conic);
            let direct = f.branch_map(&g, Method::Direct);
            let sim = f.branch_map(&g, Method::Simulate);
            let band = 1e-7 * 18.0;
            for jj in 0..n {
                for ii in 0..n {
                    let k = jj * n + ii;
                    let p = g.point(ii, jj);
                    let Ok(fb) = f.four_bar(p) else { continue };
                    if near_curves(&f, p, band) {
                        continue;
                    }
                    // The sign test on the built four-bar: its assembly
                    // mode at the three poses.
                    let built = fb.is_branch_free();
                    assert_eq!(conic[k], built, "{:?} C0 {c0:?} at {p:?}", t.poses());
                    assert_eq!(direct[k], built, "{p:?}");
                    if sim[k] != built {
                        // Simulation also sees the circuit defect (an input
                        // rocking in two arcs): only ever stricter.
                        assert!(built && !sim[k], "{p:?}");
                    }
                    if built {
                        free += 1;
                    } else {
                        defective += 1;
                    }
                }
            }
        }
    }
    assert!(free > 1000 && defective > 1000, "{free} {defective}");
}

#[test]
fn the_conics_are_exact_on_the_transformed_lines() {
    for (xya, t, _, f) in translated_filemons() {
        for (k, line) in f.all_lines().iter().enumerate() {
            let conic = f.line_conic(k + 1).unwrap();
            // The curve passes through the finite poles and C0.
            for &q in f.special_points() {
                let gr = conic.gradient(q).norm();
                assert!(conic.evaluate(q).abs() <= 1e-12 * gr * t.scale(), "{q:?}");
            }
            // The center point of every point of the line lies on it.
            let d = line.direction.normalize();
            let mut on = 0;
            for s in (-40..=40).map(|s| s as f64 * 0.37) {
                let x = line.point + d * s;
                let Ok(y) = t.center_point(x) else { continue };
                if y.coords.norm() > 1e3 {
                    continue;
                }
                let r = conic.distance_estimate(y);
                assert!(
                    r < 1e-9 * (t.scale() + y.coords.norm()),
                    "{xya:?} {y:?}: {r}"
                );
                on += 1;
            }
            assert!(on > 60);
        }
        // The products conic * side share the sign of det M, the same for
        // the three lines at one point.
        for y in spread(Point2::new(1.0, 1.0), 6.0, 60) {
            let Ok(x) = t.circle_point(y) else { continue };
            let prods: Vec<f64> = (0..3)
                .map(|k| {
                    let l = f.all_lines()[k];
                    let c = f.line_conic(k + 1).unwrap();
                    c.evaluate(y) * l.direction.normalize().perp(&(x - l.point))
                })
                .collect();
            if prods.iter().any(|v| v.abs() < 1e-9) {
                continue;
            }
            assert!(
                prods.iter().all(|v| v.signum() == prods[0].signum()),
                "{prods:?}"
            );
        }
    }
}

#[test]
fn a_rotation_below_and_above_the_bound_gives_nearby_maps() {
    let base = [[0.0, 0.0, 0.3], [2.0, 0.5, 0.3], [3.0, 2.0, 1.1]];
    let exact = Task::from_xya(&base).unwrap();
    let c0 = Point2::new(4.0, -1.0);
    let fe = exact.filemon(c0).unwrap();
    let g = Grid::from_bounds(-8.0, 10.0, -8.0, 10.0, 64, 64).unwrap();
    let me = fe.branch_map(&g, Method::Conic);
    for eps in [1e-6, -1e-6, 2e-6, 1e-5] {
        let mut xya = base;
        xya[1][2] += eps;
        let t = Task::from_xya(&xya).unwrap();
        // Within the bound the pole is at infinity; beyond it, finite.
        assert_eq!(t.cremona().is_ok(), eps.abs() > 1e-6);
        for y in spread(Point2::new(1.0, 1.0), 6.0, 50) {
            let (Ok(a), Ok(b)) = (exact.circle_point(y), t.circle_point(y)) else {
                continue;
            };
            if a.coords.norm() > 100.0 {
                continue;
            }
            // The circle point moves by O(eps) times the distances involved.
            assert!(
                (a - b).norm() < 1e3 * eps.abs() * (1.0 + a.coords.norm()),
                "{eps}: {a:?} {b:?}"
            );
        }
        let f = t.filemon(c0).unwrap();
        let m = f.branch_map(&g, Method::Conic);
        let differ = m.iter().zip(&me).filter(|(a, b)| a != b).count();
        assert!(differ <= g.len() / 100, "{eps}: {differ} of {}", g.len());
    }
}

#[test]
fn translated_tasks_are_invariant_under_similarities() {
    for (_, t, c0, f) in translated_filemons() {
        for sim in [
            Similarity::new(2.5, 0.7, Vector2::new(-3.0, 11.0)).unwrap(),
            Similarity::new(1e-3, -2.0, Vector2::new(5.0, 0.0)).unwrap(),
            Similarity::new(40.0, 0.0, Vector2::new(0.0, -7.0))
                .unwrap()
                .mirrored(),
        ] {
            let u = t.transformed_by(&sim).unwrap();
            let fu = u.filemon(sim.point(c0)).unwrap();
            let k = sim.point(Point2::new(1.0, 0.0)) - sim.point(Point2::origin());
            for y in spread(Point2::new(1.0, 1.0), 7.0, 80) {
                if let (Ok(a), Ok(b)) = (t.circle_point(y), u.circle_point(sim.point(y))) {
                    let tol = 1e-9 * k.norm() * (t.scale() + a.coords.norm() + y.coords.norm());
                    assert!((sim.point(a) - b).norm() < tol, "{a:?} {b:?}");
                }
                if near_curves(&f, y, 1e-7) {
                    continue;
                }
                assert_eq!(
                    f.is_branch_free(y, Method::Conic).unwrap(),
                    fu.is_branch_free(sim.point(y), Method::Conic).unwrap(),
                    "{y:?}"
                );
            }
        }
    }
}

#[test]
fn the_solution_map_runs_on_a_translated_task() {
    let t = Task::from_xya(&translation_tasks()[0].0).unwrap();
    let f = t.filemon(Point2::new(4.0, -1.0)).unwrap();
    let g = Grid::from_bounds(-8.0, 10.0, -8.0, 10.0, 40, 40).unwrap();
    let limits = DesignLimits::default();
    let map = common::solution_map(&f, &g, &limits);
    let m = &map.columns;
    assert_eq!(m.branch_free, f.branch_map(&g, Method::Conic));
    let (mut valid, mut acceptable) = (0, 0);
    for k in 0..g.len() {
        if !m.valid[k] {
            continue;
        }
        valid += 1;
        // Each valid sample's linkage is the one built from its dyads, with
        // the same figures.
        let fb = map.context.linkage(k).unwrap();
        let fig = t
            .linkage_figures(&fb.driving, &f.driven_crank("the test").unwrap())
            .unwrap();
        assert_eq!(m.link_ratio[k], fig.link_ratio as f32);
        assert_eq!(m.acceptable[k], m.branch_free[k] && limits.meets(&fig));
        if m.acceptable[k] {
            acceptable += 1;
            assert!(m.branch_free[k] && fb.is_branch_free());
        }
    }
    assert!(valid > 1000 && acceptable > 0, "{valid} {acceptable}");
}
