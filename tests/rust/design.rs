//! The solution-space map, each criterion against an independent
//! computation: the minimum transmission angle against dense stepping of
//! the built linkage, the Grashof class against the textbook inequality,
//! order and circuit against driving the linkage through its travel with
//! the position analysis, and the constraints against direct geometry.

use std::f64::consts::TAU;

use burmester::linkage::Direction;
use burmester::{
    Constraints, Control, DesignLimits, Dyad, Error, Grashof, Grid, InputRequirement, InvalidInput,
    MapOptions, Method, Point2, RankBy, Ranking, SynthesizedFourBar, Task,
};
mod common;

use common::{bits, filemon, solution_map, task, wrap};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;

/// Random linkages of random tasks, with their figures.
fn linkages(n: usize, seed_cases: &mut TestRunner) -> Vec<(Task, SynthesizedFourBar)> {
    let mut out = Vec::new();
    while out.len() < n {
        let t = task().new_tree(seed_cases).unwrap().current();
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
    let mode = fb.modes()[0]?;
    let (t1, t2, t3) = (fb.input_angles[0], fb.input_angles[1], fb.input_angles[2]);
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
                && wrap(p.angle - t.poses()[k].angle).abs() < 1e-7
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
    let mode = fb.modes()[0].unwrap();
    let (t1, t3) = (fb.input_angles[0], fb.input_angles[2]);
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
        if fig.direction == Direction::None || fb.modes()[0].is_none() {
            assert!(fig.min_transmission.is_nan() || fig.direction != Direction::None);
            continue;
        }
        let dense = dense_min_transmission(&fb, fig.direction.sign(), 20_000);
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
        let Some(_) = fb.modes()[0] else { continue };
        // Skip linkages within reach of a dead position at a pose: there
        // the stepping itself is ill-conditioned.
        let near_dead = fb
            .input_angles
            .iter()
            .zip(fb.modes().iter())
            .any(|(&th, &m)| {
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
            let dir = if ok_ccw {
                Direction::Ccw
            } else {
                Direction::Cw
            };
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
        let f = filemon(&mut runner, 6.0);
        let g = Grid::from_bounds(-9.0, 9.0, -8.0, 8.0, 41, 37).unwrap();
        let limits = DesignLimits::default();
        let map = solution_map(&f, &g, &limits);
        let m = &map.columns;
        let branch = f.branch_map(&g, Method::Conic);
        assert_eq!(m.branch_free, branch);
        for k in 0..g.len() {
            let p = map.context.point(k);
            let Ok(fb) = map.context.linkage(k) else {
                assert!(!m.valid[k] || !m.acceptable[k]);
                continue;
            };
            if !m.valid[k] {
                continue;
            }
            let fig = f
                .task()
                .linkage_figures(&fb.driving, &f.driven_crank("the test").unwrap())
                .unwrap();
            assert_eq!(Grashof::from_code(m.grashof[k]), Some(fig.grashof), "{p}");
            assert_eq!(m.direction[k], fig.direction.code(), "{p}");
            assert_eq!(m.one_circuit[k], fig.one_circuit);
            assert_eq!(m.input_full[k], fig.input_full);
            if fig.direction != Direction::None {
                assert!((f64::from(m.min_transmission_rad[k]) - fig.min_transmission).abs() < 1e-6);
            } else {
                assert!(m.min_transmission_rad[k].is_nan());
            }
            assert!((f64::from(m.link_ratio[k]) - fig.link_ratio).abs() < 1e-5 * fig.link_ratio);
            // The map takes its branch flag from the conic sweep, everything
            // else from the linkage's figures.
            let want = m.branch_free[k] && limits.meets(&fig);
            assert_eq!(m.acceptable[k], want, "{p}");
            // `accepts` uses the modes instead of the conic flag: they agree
            // off the curves.
            if fig.branch_free() == m.branch_free[k] {
                assert_eq!(m.acceptable[k], limits.accepts(&fig), "{p}");
            }
        }
    }
}

#[test]
fn limits_and_input_requirements_filter_the_mask() {
    let mut runner = TestRunner::deterministic();
    let f = filemon(&mut runner, 6.0);
    let g = Grid::from_bounds(-9.0, 9.0, -9.0, 9.0, 60, 60).unwrap();
    let loose = DesignLimits {
        min_transmission: 0.0,
        max_link_ratio: f64::INFINITY,
        input: InputRequirement::Any,
        // No margin in either (the map has no margin column to filter by
        // here; the margin's own tests are in design_search.rs).
        min_grashof_margin: 0.0,
        ..DesignLimits::default()
    };
    let base = solution_map(&f, &g, &loose).columns;
    for k in 0..g.len() {
        let feasible =
            base.valid[k] && base.branch_free[k] && base.direction[k] != 0 && base.one_circuit[k];
        assert_eq!(base.acceptable[k], feasible);
    }
    let strict = DesignLimits {
        min_transmission: 40f64.to_radians(),
        max_link_ratio: 5.0,
        input: InputRequirement::Crank,
        min_grashof_margin: 0.0,
        ..DesignLimits::default()
    };
    let m = solution_map(&f, &g, &strict).columns;
    for k in 0..g.len() {
        let want = base.acceptable[k]
            && f64::from(base.min_transmission_rad[k]) >= 40f64.to_radians()
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

/// A point as plain numbers (the clearance reference steps densely, and
/// plain arithmetic keeps it quick in unoptimized test builds).
type Xy = (f64, f64);

fn xy(p: Point2<f64>) -> Xy {
    (p.x, p.y)
}

/// `cross(p - o, q - o)`.
fn orient(o: Xy, p: Xy, q: Xy) -> f64 {
    (p.0 - o.0) * (q.1 - o.1) - (p.1 - o.1) * (q.0 - o.0)
}

/// Distance from `p` to the segment `ab`.
fn point_segment(p: Xy, a: Xy, b: Xy) -> f64 {
    let (abx, aby) = (b.0 - a.0, b.1 - a.1);
    let len2 = (abx * abx + aby * aby).max(1e-300);
    let t = (((p.0 - a.0) * abx + (p.1 - a.1) * aby) / len2).clamp(0.0, 1.0);
    (a.0 + abx * t - p.0).hypot(a.1 + aby * t - p.1)
}

/// Distance between the segments `ab` and `cd` (zero when they cross).
fn seg_seg_dist(a: Xy, b: Xy, c: Xy, d: Xy) -> f64 {
    let crosses =
        orient(a, b, c) * orient(a, b, d) < 0.0 && orient(c, d, a) * orient(c, d, b) < 0.0;
    if crosses {
        return 0.0;
    }
    point_segment(a, c, d)
        .min(point_segment(b, c, d))
        .min(point_segment(c, a, b))
        .min(point_segment(d, a, b))
}

/// Whether `p` is inside the convex, counter-clockwise polygon.
fn inside_convex(poly: &[Xy], p: Xy) -> bool {
    (0..poly.len()).all(|i| orient(poly[i], poly[(i + 1) % poly.len()], p) > 0.0)
}

/// The links at input angle `th`: the distance from the nearest moving link
/// (a segment) to the obstacle (zero when one reaches into it), and the
/// moving joints; `None` where the loop does not close.
fn links_at(
    fb: &SynthesizedFourBar,
    mode: burmester::AssemblyMode,
    th: f64,
    obstacle: &[Xy],
) -> Option<(f64, [Xy; 2])> {
    let j = fb.fourbar.joints_at(th, mode).ok()?;
    let (a0, a, c, c0) = (
        xy(j.input_pivot),
        xy(j.crank_joint),
        xy(j.rocker_joint),
        xy(j.output_pivot),
    );
    let mut closest = f64::INFINITY;
    for (p, q) in [(a0, a), (a, c), (c0, c)] {
        if inside_convex(obstacle, p) || inside_convex(obstacle, q) {
            return Some((0.0, [a, c]));
        }
        for i in 0..obstacle.len() {
            let (u, v) = (obstacle[i], obstacle[(i + 1) % obstacle.len()]);
            closest = closest.min(seg_seg_dist(p, q, u, v));
        }
    }
    Some((closest, [a, c]))
}

/// Independent clearance of the moving links (segments, the obstacle
/// convex and counter-clockwise) over the travel in direction `dir`, by
/// stepping the position analysis: `Some(false)` when some link comes
/// closer than `r` to the obstacle at a step (a collision), `Some(true)`
/// when between every two steps the links stay farther than `r` plus twice
/// the joints' step (so also between the steps), `None` when some stretch
/// stays too close to call even at a fine step. Stretches that come close
/// at the coarse step are stepped again finely.
fn clear(fb: &SynthesizedFourBar, dir: i8, obstacle: &[Point2<f64>], r: f64) -> Option<bool> {
    const COARSE: usize = 200;
    const FINE: usize = 40;
    let obstacle: Vec<Xy> = obstacle.iter().map(|&p| xy(p)).collect();
    let mode = fb.modes()[0].unwrap();
    let (t1, t3) = (fb.input_angles[0], fb.input_angles[2]);
    let mut span = (t3 - t1).rem_euclid(TAU);
    if dir < 0 {
        span -= TAU;
    }
    // The steps of `[from, to]` in `n` intervals; `Err(())` on a collision
    // (or where the loop fails to close, which a feasible travel does not).
    let steps = |from: f64, to: f64, n: usize| -> Result<Vec<(f64, f64, [Xy; 2])>, ()> {
        (0..=n)
            .map(|s| {
                let th = from + (to - from) * (s as f64 / n as f64);
                match links_at(fb, mode, th, &obstacle) {
                    Some((d, joints)) if d >= r * (1.0 - 1e-9) => Ok((th, d, joints)),
                    _ => Err(()),
                }
            })
            .collect()
    };
    // Whether the stretch between two steps is certainly clear.
    let safe = |a: &(f64, f64, [Xy; 2]), b: &(f64, f64, [Xy; 2])| {
        let stride = (0..2)
            .map(|k| (b.2[k].0 - a.2[k].0).hypot(b.2[k].1 - a.2[k].1))
            .fold(0.0, f64::max);
        a.1.min(b.1) > r + 2.0 * stride
    };
    let Ok(coarse) = steps(t1, t1 + span, COARSE) else {
        return Some(false);
    };
    let mut undecided = false;
    for w in coarse.windows(2) {
        if safe(&w[0], &w[1]) {
            continue;
        }
        let Ok(fine) = steps(w[0].0, w[1].0, FINE) else {
            return Some(false);
        };
        undecided |= !fine.windows(2).all(|v| safe(&v[0], &v[1]));
    }
    (!undecided).then_some(true)
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
        ..DesignLimits::default()
    };
    let free = solution_map(&f, &g, &loose);
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
        envelope: None,
    };
    let options = MapOptions::new(&loose, &cons).unwrap();
    let m = f
        .solution_map(&g, &options, &Control::new())
        .unwrap()
        .columns;
    let (mut kept, mut cut_plate, mut cut_obstacle, mut too_close) = (0, 0, 0, 0);
    for k in 0..g.len() {
        if !free.columns.acceptable[k] {
            assert!(!m.acceptable[k]);
            continue;
        }
        let p = free.context.point(k);
        let on_plate = inside(&plate, p);
        if !on_plate {
            assert!(!m.acceptable[k], "{p}: off the plate");
            cut_plate += 1;
            continue;
        }
        let fb = free.context.linkage(k).unwrap();
        let Some(ok) = clear(&fb, free.columns.direction[k], &obstacle, 0.15) else {
            too_close += 1;
            continue;
        };
        assert_eq!(m.acceptable[k], ok, "{p}: on the plate");
        if ok {
            kept += 1;
        } else {
            cut_obstacle += 1;
        }
    }
    assert!(
        kept > 0 && cut_plate > 0 && cut_obstacle > 0 && too_close * 20 < kept + cut_obstacle,
        "{kept} kept, {cut_plate} off the plate, {cut_obstacle} hit, {too_close} too close to call"
    );
}

#[test]
fn best_pivots_are_acceptable_ordered_separated_and_pass_the_poses() {
    let t = burmester::example::task();
    let f = t.filemon(burmester::example::driven_center()).unwrap();
    let g = Grid::from_bounds(-8.0, 8.0, -8.0, 8.0, 200, 200).unwrap();
    let map = solution_map(&f, &g, &DesignLimits::default());
    let best = map
        .best_pivots(Ranking::new(5, RankBy::Transmission))
        .unwrap();
    assert!(!best.is_empty());
    let sep = 0.02 * g.viewport().diagonal();
    for (i, p) in best.iter().enumerate() {
        let (row, col) = p.index;
        let k = row * g.nx() + col;
        assert_eq!(map.context.point(k), p.center);
        assert!(map.columns.acceptable[k]);
        assert_eq!(p.ranked_by, RankBy::Transmission);
        assert!(map.context.limits.accepts(&p.linkage.figures));
        if i > 0 {
            assert!(
                best[i - 1].linkage.figures.min_transmission
                    >= p.linkage.figures.min_transmission - 1e-6
            );
        }
        for q in &best[..i] {
            assert!((q.center - p.center).norm() >= sep);
        }
        assert!(p.margin > 0.0);
        let mode = p.linkage.modes()[0].unwrap();
        for k in 0..3 {
            let pose = p.linkage.pose_at(p.linkage.input_angles[k], mode).unwrap();
            assert!((pose.position - t.poses()[k].position).norm() < 1e-8);
        }
    }
    // Nothing acceptable scores higher than the best.
    let top = map
        .columns
        .min_transmission_rad
        .iter()
        .zip(&map.columns.acceptable)
        .filter(|(_, a)| **a)
        .map(|(v, _)| *v)
        .fold(f32::NEG_INFINITY, f32::max);
    assert!((f64::from(top) - best[0].linkage.figures.min_transmission).abs() < 1e-6);
    // The fallback ranking: branch-free candidates by their margin to the
    // nearest curve, which is the Filemon margin at the pivot.
    let by_margin = map.best_pivots(Ranking::new(5, RankBy::Margin)).unwrap();
    assert!(!by_margin.is_empty());
    for (i, p) in by_margin.iter().enumerate() {
        let k = p.index.0 * g.nx() + p.index.1;
        assert!(map.columns.valid[k] && map.columns.branch_free[k]);
        assert_eq!(p.ranked_by, RankBy::Margin);
        assert_eq!(p.margin, f.margin(p.center).unwrap());
        assert!(p.margin > 0.0);
        if i > 0 {
            assert!(by_margin[i - 1].margin >= p.margin);
        }
        for q in &by_margin[..i] {
            assert!((q.center - p.center).norm() >= sep);
        }
    }
    let widest = (0..g.len())
        .filter(|&k| map.columns.valid[k] && map.columns.branch_free[k])
        .map(|k| f.margin(map.context.point(k)).unwrap())
        .fold(f64::NEG_INFINITY, f64::max);
    assert_eq!(widest, by_margin[0].margin);
}

#[test]
fn the_other_direction_maps_driven_pivots() {
    let t = burmester::example::task();
    let driving = t.dyad_from_center(Point2::new(-3.0, 4.0)).unwrap();
    let g = Grid::from_bounds(-8.0, 8.0, -8.0, 8.0, 40, 40).unwrap();
    let limits = DesignLimits::default();
    let none = Constraints::none();
    let control = Control::new();
    let options = MapOptions::new(&limits, &none).unwrap();
    let map = t
        .driven_solution_map(&driving, &g, &options, &control)
        .unwrap();
    let m = &map.columns;
    let mut free = 0;
    for k in 0..g.len() {
        let c0 = map.context.point(k);
        let Ok(c) = t.dyad_from_center(c0) else {
            continue;
        };
        let Ok(fb) = t.four_bar(&driving, &c) else {
            continue;
        };
        assert!(m.valid[k]);
        assert_eq!(m.branch_free[k], fb.is_branch_free(), "{c0}");
        let fig = t.linkage_figures(&driving, &c).unwrap();
        assert_eq!(m.direction[k], fig.direction.code());
        free += usize::from(m.branch_free[k]);
    }
    assert!(free > 0 && free < g.len());
    let best = map
        .best_pivots(Ranking::new(3, RankBy::Transmission))
        .unwrap();
    assert!(
        best.iter()
            .all(|p| m.acceptable[p.index.0 * g.nx() + p.index.1])
    );
    // A dyad that is not a dyad of the task is refused.
    let bad = Dyad::new(Point2::new(-3.0, 4.0), Point2::new(0.0, 0.0));
    assert!(t.driven_solution_map(&bad, &g, &options, &control).is_err());
}

#[test]
fn bad_limits_and_constraints_are_typed_errors() {
    let t = burmester::example::task();
    let f = t.filemon(burmester::example::driven_center()).unwrap();
    let g = Grid::from_bounds(-8.0, 8.0, -8.0, 8.0, 8, 8).unwrap();
    let control = Control::new();
    let map = |limits: &DesignLimits, cons: &Constraints| {
        MapOptions::new(limits, cons).and_then(|o| f.solution_map(&g, &o, &control))
    };
    let bad = DesignLimits {
        min_transmission: f64::NAN,
        ..DesignLimits::default()
    };
    assert!(map(&bad, &Constraints::none()).is_err());
    let cons = Constraints {
        obstacles: vec![vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0)]],
        link_width: 0.1,
        ..Constraints::none()
    };
    assert!(map(&DesignLimits::default(), &cons).is_err());
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
        let e = map(&DesignLimits::default(), &cons).unwrap_err();
        assert!(e.to_string().contains("obstacle"), "{e}");
    }
    let cons = Constraints {
        base_plate: Some(vec![Point2::new(0.0, 0.0)]),
        ..Constraints::none()
    };
    assert!(map(&DesignLimits::default(), &cons).is_err());
    let cons = Constraints {
        obstacles: vec![vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(0.0, 1.0),
        ]],
        link_width: f64::NAN,
        ..Constraints::none()
    };
    assert!(map(&DesignLimits::default(), &cons).is_err());
}

/// The solution map of the built-in example over a square view.
fn example_map(t: &Task, c0: Point2<f64>, g: &Grid) -> burmester::SolutionMap {
    solution_map(&t.filemon(c0).unwrap(), g, &DesignLimits::default())
}

/// The built-in example's task and driven center, and an `n` by `n` grid
/// over `[-8, 8]^2`.
fn example_square(n: usize) -> (Task, Point2<f64>, Grid) {
    let t = burmester::example::task();
    let c0 = burmester::example::driven_center();
    (
        t,
        c0,
        Grid::from_bounds(-8.0, 8.0, -8.0, 8.0, n, n).unwrap(),
    )
}

/// The total length of a linkage's members from its joints at pose 1: the
/// ground, crank, rocker and the coupler triangle (moving pivots and the
/// task's coupler point), computed here from the points themselves.
fn members(t: &Task, l: &SynthesizedFourBar) -> f64 {
    let (a0, a, c0, c) = (
        l.driving.center,
        l.driving.circle,
        l.driven.center,
        l.driven.circle,
    );
    let p = t.poses()[0].position;
    [(a0, c0), (a0, a), (c0, c), (a, c), (a, p), (c, p)]
        .iter()
        .map(|(u, v)| (u - v).norm())
        .sum()
}

#[test]
fn size_ratio_is_the_members_over_the_span_and_scale_free() {
    let (t, c0, g) = example_square(60);
    let map = example_map(&t, c0, &g);
    // The span: the largest distance between two pose positions.
    let p = t.poses();
    let span = (0..3)
        .flat_map(|i| (0..3).map(move |j| (p[i].position - p[j].position).norm()))
        .fold(0.0, f64::max);
    assert_eq!(t.span(), span);
    let mut checked = 0;
    for k in 0..g.len() {
        let Ok(l) = map.context.linkage(k) else {
            assert!(map.columns.size_ratio[k].is_nan() || !map.columns.valid[k]);
            continue;
        };
        let want = members(&t, &l) / span;
        assert!((l.size() / span - want).abs() <= 1e-12 * want, "{k}");
        let got = f64::from(map.columns.size_ratio[k]);
        assert!((got - want).abs() <= 1e-6 * want, "{k}: {got} vs {want}");
        checked += 1;
    }
    assert!(checked > g.len() / 2);
    // Scaled and moved, the same linkages have the same size ratios.
    let f = 2.5;
    let off = burmester::Vector2::new(3.0, -1.0);
    let t2 = t.transformed(f, 0.0, off).unwrap();
    let g2 = Grid::from_bounds(
        -8.0 * f + off.x,
        8.0 * f + off.x,
        -8.0 * f + off.y,
        8.0 * f + off.y,
        60,
        60,
    )
    .unwrap();
    let map2 = example_map(&t2, Point2::new(c0.x * f + off.x, c0.y * f + off.y), &g2);
    for k in 0..g.len() {
        let (a, b) = (map.columns.size_ratio[k], map2.columns.size_ratio[k]);
        assert!(
            (a.is_nan() && b.is_nan()) || (a - b).abs() <= 1e-4 * a,
            "{k}: {a} vs {b}"
        );
    }
}

#[test]
fn rankings_order_by_their_documented_scores() {
    let (t, c0, g) = example_square(120);
    let map = example_map(&t, c0, &g);
    let c = &map.columns;
    let acceptable: Vec<usize> = (0..g.len()).filter(|&k| c.acceptable[k]).collect();
    assert!(acceptable.len() > 100);
    // Each score recomputed here from the linkage's own figures.
    let score = |rank: RankBy, k: usize| -> f64 {
        let l = map.context.linkage(k).unwrap();
        let mu = l.figures.min_transmission;
        let s = members(&t, &l) / t.span();
        let r = l.figures.link_ratio;
        match rank {
            RankBy::Balanced => mu.sin() / (s * r).sqrt(),
            RankBy::Transmission => mu,
            RankBy::Compact => -s,
            _ => unreachable!(),
        }
    };
    for rank in [RankBy::Balanced, RankBy::Transmission, RankBy::Compact] {
        let best = map
            .best_pivots(Ranking::new(4, rank).with_separation(0.0).unwrap())
            .unwrap();
        assert_eq!(best.len(), 4);
        let k0 = best[0].index.0 * g.nx() + best[0].index.1;
        let top = acceptable
            .iter()
            .map(|&k| score(rank, k))
            .fold(f64::NEG_INFINITY, f64::max);
        // The columns are f32: the best by them is the best to f32 rounding.
        assert!(
            (score(rank, k0) - top).abs() <= 1e-5 * top.abs().max(1.0),
            "{rank:?}: {} vs {top}",
            score(rank, k0)
        );
        for p in &best {
            assert_eq!(p.ranked_by, rank);
            let k = p.index.0 * g.nx() + p.index.1;
            assert!(c.acceptable[k]);
            assert!((p.score - score(rank, k)).abs() <= 1e-5 * p.score.abs().max(1.0));
            assert_eq!(p.size_ratio, p.linkage.size() / t.span());
        }
    }
    // The designer's complaint: the best transmission on this example is a
    // large linkage; the balanced ranking offers a much smaller one that
    // still transmits well.
    let by_mu = &map
        .best_pivots(Ranking::new(1, RankBy::Transmission))
        .unwrap()[0];
    let balanced = &map.best_pivots(Ranking::new(1, RankBy::Balanced)).unwrap()[0];
    assert!(
        balanced.size_ratio < 0.5 * by_mu.size_ratio,
        "{} vs {}",
        balanced.size_ratio,
        by_mu.size_ratio
    );
    assert!(balanced.linkage.figures.min_transmission > DesignLimits::default().min_transmission);
    // The balanced best is worse on all three figures than no acceptable
    // sample.
    let fig = |k: usize| (c.min_transmission_rad[k], c.size_ratio[k], c.link_ratio[k]);
    let b = fig(balanced.index.0 * g.nx() + balanced.index.1);
    assert!(
        !acceptable
            .iter()
            .map(|&k| fig(k))
            .any(|o| o.0 > b.0 && o.1 < b.1 && o.2 < b.2)
    );
}

#[test]
fn the_pareto_front_is_exactly_the_nondominated_acceptable_samples() {
    let (t, c0, g) = example_square(100);
    let map = example_map(&t, c0, &g);
    let c = &map.columns;
    let front = map.pareto_front().unwrap();
    assert!(front.len() >= 3, "{}", front.len());
    let at = |p: &burmester::Pivot| p.index.0 * g.nx() + p.index.1;
    // From the most compact to the best transmission, strictly.
    for w in front.windows(2) {
        let (a, b) = (at(&w[0]), at(&w[1]));
        assert!(c.size_ratio[a] <= c.size_ratio[b]);
        assert!(c.min_transmission_rad[a] < c.min_transmission_rad[b]);
        assert_eq!(w[0].ranked_by, RankBy::Pareto);
    }
    let acceptable: Vec<usize> = (0..g.len())
        .filter(|&k| c.acceptable[k] && !c.min_transmission_rad[k].is_nan())
        .collect();
    let dominates = |a: usize, b: usize| {
        let (ma, sa, mb, sb) = (
            c.min_transmission_rad[a],
            c.size_ratio[a],
            c.min_transmission_rad[b],
            c.size_ratio[b],
        );
        ma >= mb && sa <= sb && (ma > mb || sa < sb)
    };
    // Nothing beats a member of the front on both; everything else is
    // matched or beaten by a member.
    for p in &front {
        let f = at(p);
        assert!(!acceptable.iter().any(|&k| dominates(k, f)), "{f}");
    }
    for &k in &acceptable {
        if front.iter().any(|p| at(p) == k) {
            continue;
        }
        assert!(
            front.iter().any(|p| {
                let f = at(p);
                c.min_transmission_rad[f] >= c.min_transmission_rad[k]
                    && c.size_ratio[f] <= c.size_ratio[k]
            }),
            "{k} is on no side of the front"
        );
    }
    // Its ends are the best of the compact and transmission rankings.
    let first = |r| {
        let ranking = Ranking::new(1, r).with_separation(0.0).unwrap();
        map.best_pivots(ranking).unwrap()[0]
    };
    let (compact, mu) = (&first(RankBy::Compact), &first(RankBy::Transmission));
    assert_eq!(c.size_ratio[at(&front[0])], c.size_ratio[at(compact)]);
    assert_eq!(
        c.min_transmission_rad[at(front.last().unwrap())],
        c.min_transmission_rad[at(mu)]
    );
}

#[test]
fn rankings_parse_from_their_names() {
    for r in RankBy::ALL {
        assert_eq!(r.as_str().parse::<RankBy>().unwrap(), r);
    }
    assert_eq!(RankBy::default(), RankBy::Balanced);
    let e = "fastest".parse::<RankBy>().unwrap_err().to_string();
    assert!(e.contains("balanced") && e.contains("pareto"), "{e}");
}

#[test]
fn ties_go_to_the_more_compact_linkage() {
    // Columns from outside the core (as NumPy's): every acceptable sample
    // given the same transmission angle, so all tie and the ranking by
    // transmission orders them by size, smallest first.
    let (t, c0, g) = example_square(60);
    let map = example_map(&t, c0, &g);
    let c = &map.columns;
    let flat: Vec<f32> = c
        .min_transmission_rad
        .iter()
        .map(|v| if v.is_nan() { *v } else { 1.0 })
        .collect();
    let cols = burmester::design::RankColumns {
        min_transmission_rad: &flat,
        ..map.rank_columns()
    };
    let ranking = Ranking::new(10, RankBy::Transmission).with_separation(0.0);
    let best = map.context.best_pivots(ranking.unwrap(), cols).unwrap();
    let at = |p: &burmester::Pivot| p.index.0 * g.nx() + p.index.1;
    let smallest = (0..g.len())
        .filter(|&k| c.acceptable[k] && !flat[k].is_nan())
        .map(|k| c.size_ratio[k])
        .fold(f32::INFINITY, f32::min);
    assert_eq!(c.size_ratio[at(&best[0])], smallest);
    for w in best.windows(2) {
        assert_eq!(w[0].score, w[1].score);
        assert!(c.size_ratio[at(&w[0])] <= c.size_ratio[at(&w[1])]);
    }
}

#[test]
fn maps_into_reused_columns_are_the_fresh_maps_bit_for_bit() {
    let t = burmester::example::task();
    let g = Grid::from_bounds(-8.0, 8.0, -8.0, 8.0, 61, 47).unwrap();
    let limits = DesignLimits::default();
    let none = Constraints::none();
    let control = Control::new();
    // Another task's map leaves other values in every column: the map
    // written over it must not depend on them.
    let moved = t
        .transformed(1.7, 0.3, burmester::Vector2::new(1.0, -2.0))
        .unwrap();
    let mut reused = example_map(&moved, Point2::new(2.0, -1.0), &g).columns;
    let options = MapOptions::new(&limits, &none).unwrap();
    for c0 in [Point2::new(-1.5, 2.5), Point2::new(3.0, 1.0)] {
        let f = t.filemon(c0).unwrap();
        let fresh = f.solution_map(&g, &options, &control).unwrap();
        assert_ne!(bits(&reused), bits(&fresh.columns));
        let context = f
            .solution_map_into(&g, &options, reused.as_out(), &control)
            .unwrap();
        assert_eq!(context, fresh.context);
        assert_eq!(bits(&reused), bits(&fresh.columns), "driven center {c0}");
    }
    let driving = t.dyad_from_center(Point2::new(-3.0, 4.0)).unwrap();
    let fresh = t
        .driven_solution_map(&driving, &g, &options, &control)
        .unwrap();
    let context = t
        .driven_solution_map_into(&driving, &g, &options, reused.as_out(), &control)
        .unwrap();
    assert_eq!(context, fresh.context);
    assert_eq!(bits(&reused), bits(&fresh.columns));
    // A column of the wrong length is a typed error naming it.
    let mut short = fresh.columns.clone();
    short.link_ratio.pop();
    let f = t.filemon(Point2::new(-1.5, 2.5)).unwrap();
    let err = f
        .solution_map_into(&g, &options, short.as_out(), &control)
        .unwrap_err();
    assert!(
        matches!(
            err,
            burmester::Error::InvalidInput(burmester::InvalidInput::LengthMismatch {
                name: "column link_ratio",
                ..
            })
        ),
        "{err}"
    );
    assert!(
        t.driven_solution_map_into(&driving, &g, &options, short.as_out(), &control)
            .is_err()
    );
}

#[test]
fn bad_arguments_are_reported_before_the_columns_are_allocated() {
    // The largest grid: its columns would take gigabytes; invalid limits and
    // a dyad that is not the task's are refused without allocating them.
    let side = (Grid::MAX_POINTS as f64).sqrt() as usize;
    let g = Grid::from_bounds(-8.0, 8.0, -8.0, 8.0, side, side).unwrap();
    let t = burmester::example::task();
    let f = t.filemon(Point2::new(4.0, -1.0)).unwrap();
    let bad = DesignLimits {
        max_link_ratio: 0.5,
        ..DesignLimits::default()
    };
    let (none, control) = (Constraints::none(), Control::new());
    let invalid = |r: burmester::Result<burmester::SolutionMap>| {
        matches!(r, Err(burmester::Error::InvalidInput(_)))
    };
    assert!(invalid(
        MapOptions::new(&bad, &none).and_then(|o| f.solution_map(&g, &o, &control))
    ));
    let driving = t.dyad_from_center(Point2::new(-3.0, 4.0)).unwrap();
    assert!(invalid(MapOptions::new(&bad, &none).and_then(|o| {
        t.driven_solution_map(&driving, &g, &o, &control)
    })));
    let not_a_dyad = Dyad::new(Point2::new(-3.0, 4.0), Point2::new(0.0, 0.0));
    let limits = DesignLimits::default();
    assert!(invalid(t.driven_solution_map(
        &not_a_dyad,
        &g,
        &MapOptions::new(&limits, &none).unwrap(),
        &control
    )));
}

/// A [`Ranking`] refuses a negative or non-finite separation where it is
/// made (the variant and message the rankings gave for it before), and
/// ranks a map as a brute-force reference does: the acceptable samples by
/// transmission (ties by size ratio, then margin, then sample), each kept
/// unless closer than the separation to one kept before, the first `k`.
#[test]
fn a_ranking_is_checked_once_and_ranks_as_the_reference() {
    for bad in [-1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let e = Ranking::new(3, RankBy::Balanced)
            .with_separation(bad)
            .unwrap_err();
        let Error::InvalidInput(InvalidInput::OutsideRange {
            name,
            value,
            min,
            max,
            unit,
        }) = e
        else {
            panic!("{e:?}");
        };
        assert_eq!(
            (name, min, max, unit),
            ("min_separation", 0.0, f64::MAX, "")
        );
        assert_eq!(value.to_bits(), bad.to_bits());
        assert!(
            e.to_string()
                .starts_with("min_separation must be between 0 and "),
            "{e}"
        );
        assert!(
            e.to_string().ends_with("; pass a value in that range"),
            "{e}"
        );
        // (The same error from the optional form: compared as text, NaN
        // being unequal to itself.)
        let again = Ranking::try_new(3, Some(bad), RankBy::Balanced).unwrap_err();
        assert_eq!(again.to_string(), e.to_string());
    }
    // Zero and None are valid; the accessors give back what was given.
    let r = Ranking::try_new(7, None, RankBy::Compact).unwrap();
    assert_eq!(
        (r.k(), r.min_separation(), r.rank_by()),
        (7, None, RankBy::Compact)
    );
    assert_eq!(r, Ranking::new(7, RankBy::Compact));
    let r0 = r.with_separation(0.0).unwrap();
    assert_eq!(r0.min_separation(), Some(0.0));
    assert_eq!(Ranking::default(), Ranking::new(5, RankBy::Balanced));
    let front = Ranking::pareto_front();
    assert_eq!(
        (front.k(), front.min_separation(), front.rank_by()),
        (usize::MAX, Some(0.0), RankBy::Pareto)
    );

    // One map: the default separation is 2% of the viewport's diagonal,
    // here 0.02 * hypot(16, 12) = 0.4.
    let t = burmester::example::task();
    let f = t.filemon(burmester::example::driven_center()).unwrap();
    let g = Grid::from_bounds(-8.0, 8.0, -6.0, 6.0, 161, 121).unwrap();
    let map = solution_map(&f, &g, &DesignLimits::default());
    let c = &map.columns;
    assert_eq!(
        Ranking::new(1, RankBy::Balanced).separation(&g.viewport()),
        0.4
    );
    let mut cand: Vec<usize> = (0..g.len()).filter(|&s| c.acceptable[s]).collect();
    assert!(cand.len() > 100, "{} acceptable", cand.len());
    cand.sort_by(|&a, &b| {
        let mu = |s: usize| c.min_transmission_rad[s];
        mu(b)
            .total_cmp(&mu(a))
            .then(c.size_ratio[a].total_cmp(&c.size_ratio[b]))
            .then(map.margin(b).total_cmp(&map.margin(a)))
            .then(a.cmp(&b))
    });
    let reference = |k: usize, sep: f64| {
        let mut kept: Vec<usize> = Vec::new();
        for &s in &cand {
            if kept.len() == k {
                break;
            }
            let p = map.context.point(s);
            if kept
                .iter()
                .all(|&q| (map.context.point(q) - p).norm() >= sep)
                && map.context.linkage(s).is_ok()
            {
                kept.push(s);
            }
        }
        kept
    };
    let ranked = |r: Ranking| -> Vec<usize> {
        let best = map.best_pivots(r).unwrap();
        best.iter()
            .map(|p| p.index.0 * g.nx() + p.index.1)
            .collect()
    };
    // The separation matters on this map: the six best differ without it.
    assert_ne!(reference(6, 0.4), reference(6, 0.0));
    for (ranking, sep) in [
        (Ranking::new(6, RankBy::Transmission), 0.4),
        (
            Ranking::new(6, RankBy::Transmission)
                .with_separation(0.0)
                .unwrap(),
            0.0,
        ),
        (
            Ranking::new(4, RankBy::Transmission)
                .with_separation(2.5)
                .unwrap(),
            2.5,
        ),
    ] {
        let expected = reference(ranking.k(), sep);
        assert_eq!(expected.len(), ranking.k());
        assert_eq!(ranked(ranking), expected, "{ranking:?}");
    }
}
