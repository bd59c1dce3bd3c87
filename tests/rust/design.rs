//! The solution-space map, each criterion against an independent
//! computation: the minimum transmission angle against dense stepping of
//! the built linkage, the Grashof class against the textbook inequality,
//! order and circuit against driving the linkage through its travel with
//! the position analysis, and the constraints against direct geometry.

use std::f64::consts::TAU;

mod common;

use burmester::{
    AssemblyMode, Constraints, DesignLimits, Dyad, Grashof, Grid, InputRequirement, Method, Point2,
    SolutionMap, SynthesizedFourBar, Task, Vector2,
};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;

/// Random linkages of random tasks, with their figures.
fn linkages(n: usize, seed_cases: &mut TestRunner) -> Vec<(Task, SynthesizedFourBar)> {
    let mut out = Vec::new();
    while out.len() < n {
        let t = common::task().new_tree(seed_cases).unwrap().current();
        let pts = (-8.0f64..8.0, -8.0f64..8.0, -8.0f64..8.0, -8.0f64..8.0)
            .new_tree(seed_cases)
            .unwrap()
            .current();
        let (Ok(a), Ok(c)) = (
            t.dyad_from_center(Point2::new(pts.0, pts.1)),
            t.dyad_from_center(Point2::new(pts.2, pts.3)),
        ) else {
            continue;
        };
        let Ok(fb) = t.four_bar(&a, &c) else { continue };
        if fb
            .fourbar
            .lengths()
            .iter()
            .any(|l| !(1e-3..=200.0).contains(l))
        {
            continue;
        }
        out.push((t, fb));
    }
    out
}

/// Drives the linkage from pose 1 in `dir` with the position analysis in
/// pose 1's mode; true when it passes pose 2 and then lands on pose 3
/// without the loop failing to close.
fn drive(t: &Task, fb: &SynthesizedFourBar, dir: f64, steps: usize) -> Option<bool> {
    let mode = fb.modes[0]?;
    let [t1, t2, t3] = fb.input_angles;
    let ccw = |x: f64| {
        if dir > 0.0 {
            (x - t1).rem_euclid(TAU)
        } else {
            (t1 - x).rem_euclid(TAU)
        }
    };
    let (d2, d3) = (ccw(t2), ccw(t3));
    let size = fb.fourbar.lengths().iter().sum::<f64>() + fb.coupler_point.norm();
    let lands = |theta: f64, k: usize| {
        fb.pose_at(theta, mode).is_ok_and(|p| {
            (p.position - t.poses()[k].position).norm() < 1e-7 * size
                && common::wrap(p.angle - t.poses()[k].angle).abs() < 1e-7
        })
    };
    if d3 < d2 {
        // Pose 3 comes first in this direction: the loop must still close
        // up to it, but the order is wrong.
        return Some(false);
    }
    // The loop must close all the way from pose 1 to pose 3.
    for s in 0..=steps {
        let theta = t1 + dir * d3 * (s as f64 / steps as f64);
        if fb.fourbar.solve(theta, mode).is_err() {
            return Some(false);
        }
    }
    Some(lands(t2, 1) && lands(t3, 2))
}

/// The transmission angle's minimum by dense stepping over the travel.
fn dense_min_transmission(fb: &SynthesizedFourBar, dir: f64, steps: usize) -> f64 {
    let mode = fb.modes[0].unwrap();
    let [t1, _, t3] = fb.input_angles;
    let span = if dir > 0.0 {
        (t3 - t1).rem_euclid(TAU)
    } else {
        (t1 - t3).rem_euclid(TAU)
    };
    let mut min = f64::INFINITY;
    for s in 0..=steps {
        let theta = t1 + dir * span * (s as f64 / steps as f64);
        if let Ok(c) = fb.fourbar.solve(theta, mode) {
            min = min.min(c.transmission_angle());
        }
    }
    min
}

#[test]
fn min_transmission_matches_dense_stepping() {
    let mut runner = TestRunner::deterministic();
    let mut checked = 0;
    for (t, fb) in linkages(400, &mut runner) {
        let fig = t.linkage_figures(&fb.driving, &fb.driven).unwrap();
        if fig.direction == 0 || fb.modes[0].is_none() {
            assert!(fig.min_transmission.is_nan() || fig.direction != 0);
            continue;
        }
        let dense = dense_min_transmission(&fb, f64::from(fig.direction), 20_000);
        // The analytic minimum is exact; dense stepping can only miss the
        // true minimum by a step's worth.
        assert!(
            dense >= fig.min_transmission - 1e-9,
            "{dense} < {}",
            fig.min_transmission
        );
        assert!(
            dense - fig.min_transmission < 2e-3,
            "{dense} vs {}",
            fig.min_transmission
        );
        checked += 1;
    }
    assert!(checked > 50, "only {checked} feasible linkages");
}

#[test]
fn grashof_matches_the_textbook_inequality() {
    let mut runner = TestRunner::deterministic();
    for (t, fb) in linkages(400, &mut runner) {
        let fig = t.linkage_figures(&fb.driving, &fb.driven).unwrap();
        let l = fig.lengths;
        let mut s = l;
        s.sort_by(f64::total_cmp);
        let margin = (s[0] + s[3]) - (s[1] + s[2]);
        if margin.abs() < 1e-9 * s[3] {
            continue;
        }
        let shortest = (0..4).min_by(|&a, &b| l[a].total_cmp(&l[b])).unwrap();
        let want = if margin > 0.0 {
            Grashof::TripleRocker
        } else {
            [
                Grashof::DoubleCrank,
                Grashof::CrankRocker,
                Grashof::DoubleRocker,
                Grashof::RockerCrank,
            ][shortest]
        };
        assert_eq!(fig.grashof, want, "{l:?}");
        assert_eq!(fig.grashof, fb.fourbar.grashof());
        assert_eq!(fig.input_full, fb.fourbar.input_turns_fully());
        let ratio = s[3] / s[0];
        assert!((fig.link_ratio - ratio).abs() < 1e-12 * ratio);
    }
}

#[test]
fn order_and_circuit_match_driving_the_linkage() {
    let mut runner = TestRunner::deterministic();
    let (mut feasible, mut infeasible) = (0, 0);
    for (t, fb) in linkages(600, &mut runner) {
        let fig = t.linkage_figures(&fb.driving, &fb.driven).unwrap();
        let Some(_) = fb.modes[0] else { continue };
        // Skip linkages within reach of a dead position at a pose: there
        // the stepping itself is ill-conditioned.
        let near_dead = fb.input_angles.iter().zip(fb.modes).any(|(&th, m)| {
            m.is_none_or(|m| {
                fb.fourbar
                    .solve(th, m)
                    .is_ok_and(|c| c.transmission_angle() < 1e-3)
            })
        });
        if near_dead {
            continue;
        }
        let ok_ccw = drive(&t, &fb, 1.0, 4000).unwrap();
        let ok_cw = drive(&t, &fb, -1.0, 4000).unwrap();
        let simulated = ok_ccw || ok_cw;
        assert_eq!(
            fig.feasible(),
            simulated,
            "figures {fig:?}, ccw {ok_ccw}, cw {ok_cw}, angles {:?}",
            fb.input_angles
        );
        if simulated {
            let dir = if ok_ccw { 1 } else { -1 };
            assert_eq!(fig.direction, dir);
            feasible += 1;
        } else {
            infeasible += 1;
        }
    }
    assert!(
        feasible > 30 && infeasible > 30,
        "{feasible} feasible, {infeasible} not"
    );
}

#[test]
fn map_samples_match_the_linkage_at_each_point() {
    let mut runner = TestRunner::deterministic();
    for _ in 0..6 {
        let f = common::filemon(&mut runner, 6.0);
        let g = Grid::from_bounds(-9.0, 9.0, -8.0, 8.0, 41, 37).unwrap();
        let limits = DesignLimits::default();
        let map = f.solution_map(&g, &limits, &Constraints::none()).unwrap();
        let branch = f.branch_map(&g, Method::Conic);
        assert_eq!(map.branch_free, branch);
        for k in 0..g.len() {
            let p = map.point(k);
            let Ok(fb) = map.linkage(k) else {
                assert!(!map.valid[k] || !map.acceptable[k]);
                continue;
            };
            if !map.valid[k] {
                continue;
            }
            let fig = f.task().linkage_figures(&fb.driving, &f.driven()).unwrap();
            assert_eq!(
                SolutionMap::grashof_of_code(map.grashof[k]),
                Some(fig.grashof),
                "{p}"
            );
            assert_eq!(map.direction[k], fig.direction, "{p}");
            assert_eq!(map.one_circuit[k], fig.one_circuit);
            assert_eq!(map.input_full[k], fig.input_full);
            if fig.direction != 0 {
                assert!((f64::from(map.min_transmission[k]) - fig.min_transmission).abs() < 1e-6);
            } else {
                assert!(map.min_transmission[k].is_nan());
            }
            assert!((f64::from(map.link_ratio[k]) - fig.link_ratio).abs() < 1e-5 * fig.link_ratio);
            let want = map.branch_free[k] && fig.meets(&limits);
            // `meets` uses the modes; the map the conic flag: they agree off the curves.
            if fig.branch_free() == map.branch_free[k] {
                assert_eq!(map.acceptable[k], want, "{p}");
            }
        }
    }
}

#[test]
fn limits_and_input_requirements_filter_the_mask() {
    let mut runner = TestRunner::deterministic();
    let f = common::filemon(&mut runner, 6.0);
    let g = Grid::from_bounds(-9.0, 9.0, -9.0, 9.0, 60, 60).unwrap();
    let loose = DesignLimits {
        min_transmission: 0.0,
        max_link_ratio: f64::INFINITY,
        input: InputRequirement::Any,
    };
    let base = f.solution_map(&g, &loose, &Constraints::none()).unwrap();
    for k in 0..g.len() {
        let feasible =
            base.valid[k] && base.branch_free[k] && base.direction[k] != 0 && base.one_circuit[k];
        assert_eq!(base.acceptable[k], feasible);
    }
    let strict = DesignLimits {
        min_transmission: 40f64.to_radians(),
        max_link_ratio: 5.0,
        input: InputRequirement::Crank,
    };
    let m = f.solution_map(&g, &strict, &Constraints::none()).unwrap();
    for k in 0..g.len() {
        let want = base.acceptable[k]
            && f64::from(base.min_transmission[k]) >= 40f64.to_radians()
            && base.link_ratio[k] <= 5.0
            && base.input_full[k];
        assert_eq!(m.acceptable[k], want, "{k}");
    }
}

/// Independent geometry: is `p` inside the simple polygon (winding number)?
fn inside(poly: &[Point2<f64>], p: Point2<f64>) -> bool {
    let mut wn = 0i32;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        let c = (b - a).x * (p - a).y - (b - a).y * (p - a).x;
        if a.y <= p.y {
            if b.y > p.y && c > 0.0 {
                wn += 1;
            }
        } else if b.y <= p.y && c < 0.0 {
            wn -= 1;
        }
    }
    wn != 0
}

fn seg_seg_dist(a: Point2<f64>, b: Point2<f64>, c: Point2<f64>, d: Point2<f64>) -> f64 {
    let pt_seg = |p: Point2<f64>, a: Point2<f64>, b: Point2<f64>| {
        let ab = b - a;
        let t = ((p - a).dot(&ab) / ab.norm_squared().max(1e-300)).clamp(0.0, 1.0);
        (a + ab * t - p).norm()
    };
    let cr = |o: Point2<f64>, p: Point2<f64>, q: Point2<f64>| {
        (p - o).x * (q - o).y - (p - o).y * (q - o).x
    };
    let crosses = cr(a, b, c) * cr(a, b, d) < 0.0 && cr(c, d, a) * cr(c, d, b) < 0.0;
    if crosses {
        return 0.0;
    }
    pt_seg(a, c, d)
        .min(pt_seg(b, c, d))
        .min(pt_seg(c, a, b))
        .min(pt_seg(d, a, b))
}

/// Independent clearance: every link segment stays farther than `r` from
/// the (convex, counter-clockwise) obstacle, over the sampled travel.
fn clear(fb: &SynthesizedFourBar, dir: i8, obstacle: &[Point2<f64>], r: f64, n: usize) -> bool {
    let mode = fb.modes[0].unwrap();
    let [t1, _, t3] = fb.input_angles;
    let mut span = (t3 - t1).rem_euclid(TAU);
    if dir < 0 {
        span -= TAU;
    }
    for s in 0..n {
        let th = t1 + span * (s as f64 / (n - 1) as f64);
        let j = fb.fourbar.joints_at(th, mode).unwrap();
        for (a, b) in [
            (j.input_pivot, j.crank_joint),
            (j.crank_joint, j.rocker_joint),
            (j.output_pivot, j.rocker_joint),
        ] {
            if inside(obstacle, a) || inside(obstacle, b) {
                return false;
            }
            for i in 0..obstacle.len() {
                let (c, d) = (obstacle[i], obstacle[(i + 1) % obstacle.len()]);
                if seg_seg_dist(a, b, c, d) <= r {
                    return false;
                }
            }
        }
    }
    true
}

#[test]
fn constraints_match_direct_geometry() {
    let t = burmester::example::task();
    let f = t.filemon(burmester::example::driven_center()).unwrap();
    let g = Grid::from_bounds(-8.0, 8.0, -8.0, 8.0, 48, 48).unwrap();
    let loose = DesignLimits {
        min_transmission: 0.0,
        max_link_ratio: f64::INFINITY,
        input: InputRequirement::Any,
    };
    let free = f.solution_map(&g, &loose, &Constraints::none()).unwrap();
    // An L-shaped (non-convex) base plate.
    let plate: Vec<Point2<f64>> = [
        (-8.0, -8.0),
        (2.0, -8.0),
        (2.0, 0.0),
        (-2.0, 0.0),
        (-2.0, 8.0),
        (-8.0, 8.0),
    ]
    .iter()
    .map(|&(x, y)| Point2::new(x, y))
    .collect();
    let obstacle: Vec<Point2<f64>> = [(-1.0, -3.0), (0.5, -3.0), (0.5, -2.0), (-1.0, -2.0)]
        .iter()
        .map(|&(x, y)| Point2::new(x, y))
        .collect();
    let cons = Constraints {
        base_plate: Some(plate.clone()),
        obstacles: vec![obstacle.clone()],
        link_width: 0.3,
        travel_samples: 48,
    };
    let m = f.solution_map(&g, &loose, &cons).unwrap();
    let (mut kept, mut cut_plate, mut cut_obstacle) = (0, 0, 0);
    for k in 0..g.len() {
        if !free.acceptable[k] {
            assert!(!m.acceptable[k]);
            continue;
        }
        let p = free.point(k);
        let on_plate = inside(&plate, p);
        let fb = free.linkage(k).unwrap();
        let ok = on_plate && clear(&fb, free.direction[k], &obstacle, 0.15, 48);
        assert_eq!(m.acceptable[k], ok, "{p}: plate {on_plate}");
        if ok {
            kept += 1;
        } else if !on_plate {
            cut_plate += 1;
        } else {
            cut_obstacle += 1;
        }
    }
    assert!(
        kept > 0 && cut_plate > 0 && cut_obstacle > 0,
        "{kept} {cut_plate} {cut_obstacle}"
    );
}

#[test]
fn best_pivots_are_acceptable_ordered_separated_and_pass_the_poses() {
    let t = burmester::example::task();
    let f = t.filemon(burmester::example::driven_center()).unwrap();
    let g = Grid::from_bounds(-8.0, 8.0, -8.0, 8.0, 200, 200).unwrap();
    let map = f
        .solution_map(&g, &DesignLimits::default(), &Constraints::none())
        .unwrap();
    let best = map.best_pivots(5, None);
    assert!(!best.is_empty());
    let sep = 0.02 * g.viewport().diagonal();
    for (i, p) in best.iter().enumerate() {
        assert!(map.acceptable[p.index]);
        assert!(p.figures.meets(&map.context.limits));
        if i > 0 {
            assert!(best[i - 1].figures.min_transmission >= p.figures.min_transmission - 1e-6);
        }
        for q in &best[..i] {
            assert!((q.center - p.center).norm() >= sep);
        }
        assert!(p.margin > 0.0);
        let mode = p.linkage.modes[0].unwrap();
        for k in 0..3 {
            let pose = p.linkage.pose_at(p.linkage.input_angles[k], mode).unwrap();
            assert!((pose.position - t.poses()[k].position).norm() < 1e-8);
        }
    }
    // Nothing acceptable scores higher than the best.
    let top = map
        .min_transmission
        .iter()
        .zip(&map.acceptable)
        .filter(|(_, a)| **a)
        .map(|(v, _)| *v)
        .fold(f32::NEG_INFINITY, f32::max);
    assert!((f64::from(top) - best[0].figures.min_transmission).abs() < 1e-6);
}

#[test]
fn the_other_direction_maps_driven_pivots() {
    let t = burmester::example::task();
    let driving = t.dyad_from_center(Point2::new(-3.0, 4.0)).unwrap();
    let g = Grid::from_bounds(-8.0, 8.0, -8.0, 8.0, 40, 40).unwrap();
    let map = t
        .driven_solution_map(&driving, &g, &DesignLimits::default(), &Constraints::none())
        .unwrap();
    let mut free = 0;
    for k in 0..g.len() {
        let c0 = map.point(k);
        let Ok(c) = t.dyad_from_center(c0) else {
            continue;
        };
        let Ok(fb) = t.four_bar(&driving, &c) else {
            continue;
        };
        assert!(map.valid[k]);
        assert_eq!(map.branch_free[k], fb.is_branch_free(), "{c0}");
        let fig = t.linkage_figures(&driving, &c).unwrap();
        assert_eq!(map.direction[k], fig.direction);
        free += usize::from(map.branch_free[k]);
    }
    assert!(free > 0 && free < g.len());
    assert!(
        map.best_pivots(3, None)
            .iter()
            .all(|p| map.acceptable[p.index])
    );
    // A dyad that is not a dyad of the task is refused.
    let bad = Dyad::new(Point2::new(-3.0, 4.0), Point2::new(0.0, 0.0));
    assert!(
        t.driven_solution_map(&bad, &g, &DesignLimits::default(), &Constraints::none())
            .is_err()
    );
}

#[test]
fn bad_limits_and_constraints_are_typed_errors() {
    let t = burmester::example::task();
    let f = t.filemon(burmester::example::driven_center()).unwrap();
    let g = Grid::from_bounds(-8.0, 8.0, -8.0, 8.0, 8, 8).unwrap();
    let bad = DesignLimits {
        min_transmission: f64::NAN,
        ..DesignLimits::default()
    };
    assert!(f.solution_map(&g, &bad, &Constraints::none()).is_err());
    let cons = Constraints {
        obstacles: vec![vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0)]],
        link_width: 0.1,
        ..Constraints::none()
    };
    assert!(f.solution_map(&g, &DesignLimits::default(), &cons).is_err());
    // fuzz/regressions/solution_map/obstacle-of-coincident-points-panics-in-hull:
    // parry's hull asserted on an obstacle without area.
    for obstacle in [
        vec![Point2::new(1.0, 1.0)],
        vec![Point2::new(1.0, 1.0); 4],
        vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(2.0, 2.0),
        ],
    ] {
        let cons = Constraints {
            obstacles: vec![obstacle],
            link_width: 0.1,
            ..Constraints::none()
        };
        let e = f
            .solution_map(&g, &DesignLimits::default(), &cons)
            .unwrap_err();
        assert!(e.to_string().contains("obstacle"), "{e}");
    }
    let cons = Constraints {
        base_plate: Some(vec![Point2::new(0.0, 0.0)]),
        ..Constraints::none()
    };
    assert!(f.solution_map(&g, &DesignLimits::default(), &cons).is_err());
    let cons = Constraints {
        obstacles: vec![vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(0.0, 1.0),
        ]],
        link_width: f64::NAN,
        ..Constraints::none()
    };
    assert!(f.solution_map(&g, &DesignLimits::default(), &cons).is_err());
    let _ = (AssemblyMode::Open, Vector2::<f64>::zeros());
}
