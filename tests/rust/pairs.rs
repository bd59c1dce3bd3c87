//! The four-position pair map, checked against independent computations:
//! the notes' worked example (a task made from a known crank-rocker), the
//! linkage built by `Task::four_bar` for each pair, Filemon's construction
//! with four lines for the branch flag, the crank order for the direction,
//! driving the built linkage through the poses, and invariance under the
//! number of threads.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

mod common;

use common::bits;

use burmester::design::PairMap;
use burmester::synthesis::{FourPositions, Turn};
use burmester::{
    Branch, Constraints, Control, DesignLimits, Direction, Error, InvalidInput, MapOptions, Point2,
    Pose, RankBy, Ranking, Task,
};

/// The notes' worked example (positions-4-5.md, section 6): four poses of
/// the coupler of the crank-rocker `A0 = (0, 0)`, `B0 = (4, 0)`.
fn example_poses() -> [Pose; 4] {
    let [p1, p2, p3, p4, _] = common::notes_poses();
    [p1, p2, p3, p4]
}

fn example_task() -> Task {
    Task::new(&example_poses()).unwrap()
}

fn map(task: &Task, n_driving: usize, n_driven: usize) -> PairMap {
    map_with(task, n_driving, n_driven, &Control::new()).unwrap()
}

/// The example task's curves, and its pair map (as [`map`]).
fn four_and_map(n_driving: usize, n_driven: usize) -> (FourPositions, PairMap) {
    let task = example_task();
    let four = FourPositions::new(task.poses()).unwrap();
    (four, map(&task, n_driving, n_driven))
}

/// The pair map of `task` at the default limits, with no constraints,
/// under `control`.
fn map_with(
    task: &Task,
    n_driving: usize,
    n_driven: usize,
    control: &Control<'_>,
) -> Result<PairMap, Error> {
    task.pair_map(n_driving, n_driven, &MapOptions::default(), control)
}

/// The sample of `samples` whose center is nearest `p`, and its distance.
fn nearest(samples: &[Option<burmester::synthesis::CurveDyad>], p: Point2<f64>) -> (usize, f64) {
    samples
        .iter()
        .enumerate()
        .filter_map(|(i, d)| d.map(|d| (i, (d.center - p).norm())))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap()
}

/// A small deterministic generator (`SplitMix64`) for choosing cells.
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: usize) -> usize {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) % n as u64) as usize
    }
}

#[test]
fn the_generating_pair_is_a_branch_free_ccw_cell_and_not_swapped() {
    let task = example_task();
    let m = map(&task, 720, 720);
    let ctx = &m.context;
    let (i_a, da) = nearest(&ctx.driving, Point2::new(0.0, 0.0));
    let (j_b, db) = nearest(&ctx.driven, Point2::new(4.0, 0.0));
    // The sampled dyads pass close to the generating ones.
    assert!(da < 0.05 && db < 0.05, "{da} {db}");
    let nx = ctx.grid.nx();
    let k = j_b * nx + i_a;
    let c = &m.columns;
    assert!(c.valid[k] && c.branch_free[k], "cell {k}");
    assert_eq!(c.direction[k], Direction::Ccw.code());
    assert!(c.one_circuit[k] && c.input_full[k]);
    assert!(c.acceptable[k]);
    // The linkage of the cell is the crank-rocker, to the sampling.
    let l = m.linkage(j_b, i_a).unwrap();
    let lengths = l.figures.lengths;
    for (got, want) in lengths.iter().zip([4.0, 1.5, 3.5, 3.0]) {
        assert!((got - want).abs() < 0.1, "{lengths:?}");
    }
    // With B0 driving (the same two dyads swapped) it is not branch-free.
    let (i_b, _) = nearest(&ctx.driving, Point2::new(4.0, 0.0));
    let (j_a, _) = nearest(&ctx.driven, Point2::new(0.0, 0.0));
    let swapped = j_a * nx + i_b;
    assert!(c.valid[swapped]);
    assert!(!c.branch_free[swapped] && !c.acceptable[swapped]);
}

#[test]
fn each_cell_is_the_linkage_of_its_two_dyads() {
    let task = example_task();
    let m = map(&task, 97, 61);
    let ctx = &m.context;
    let (ny, nx) = ctx.shape();
    assert_eq!((ny, nx), (61, 97));
    assert_eq!(m.columns.valid.len(), nx * ny);
    let mut rng = Rng(7);
    let mut checked = 0;
    for _ in 0..600 {
        let (j, i) = (rng.below(ny), rng.below(nx));
        let k = j * nx + i;
        let (Some(a), Some(c)) = (ctx.driving[i], ctx.driven[j]) else {
            assert!(!m.columns.valid[k]);
            continue;
        };
        // The parameter of the sample is the grid's.
        let four = FourPositions::new(task.poses()).unwrap();
        assert_eq!(four.dyad_at_parameter(ctx.grid.x(i)).unwrap(), a);
        assert_eq!(four.dyad_at_parameter(ctx.grid.y(j)).unwrap(), c);
        match task.four_bar(&a.dyad(), &c.dyad()) {
            Ok(fb) => {
                let f = fb.figures;
                let col = &m.columns;
                assert!(col.valid[k]);
                assert_eq!(col.branch_free[k], f.branch_free());
                assert_eq!(col.grashof[k], f.grashof.code());
                assert_eq!(col.input_full[k], f.input_full);
                assert_eq!(col.direction[k], f.direction.code());
                assert_eq!(col.one_circuit[k], f.one_circuit);
                assert_eq!(
                    col.min_transmission_rad[k].to_bits(),
                    (f.min_transmission as f32).to_bits()
                );
                assert_eq!(col.link_ratio[k], f.link_ratio as f32);
                let size = (fb.size() / task.span()) as f32;
                assert!((col.size_ratio[k] - size).abs() <= 1e-6 * size);
                // The same linkage (NaN figures compare by their text).
                assert_eq!(format!("{:?}", m.linkage(j, i).unwrap()), format!("{fb:?}"));
                checked += 1;
            }
            Err(_) => assert!(!m.columns.valid[k]),
        }
    }
    assert!(checked > 400, "{checked}");
}

#[test]
fn a_dyad_with_itself_is_no_linkage() {
    let task = example_task();
    let m = map(&task, 50, 50);
    for i in 0..50 {
        assert!(!m.columns.valid[i * 50 + i]);
        assert!(m.linkage(i, i).is_err());
    }
}

#[test]
fn branch_free_cells_agree_with_filemons_four_lines() {
    let (four, m) = four_and_map(400, 40);
    let ctx = &m.context;
    let nx = ctx.grid.nx();
    let (mut free, mut defective) = (0, 0);
    for (j, driven) in ctx.driven.iter().enumerate() {
        let Some(driven) = driven else { continue };
        let Ok(arcs) = four.filemon(&driven.dyad()) else {
            continue;
        };
        for (i, driving) in ctx.driving.iter().enumerate() {
            let Some(driving) = driving else { continue };
            let k = j * nx + i;
            if !m.columns.valid[k] {
                continue;
            }
            match arcs.classify_circle_point(driving.circle) {
                Branch::Free => {
                    assert!(m.columns.branch_free[k], "({j}, {i})");
                    free += 1;
                }
                Branch::Defective => {
                    assert!(!m.columns.branch_free[k], "({j}, {i})");
                    defective += 1;
                }
                Branch::Boundary => {}
            }
        }
    }
    assert!(free > 1000 && defective > 1000, "{free} {defective}");
}

#[test]
fn the_direction_of_a_turning_crank_is_its_crank_order() {
    let (four, m) = four_and_map(300, 30);
    let ctx = &m.context;
    let nx = ctx.grid.nx();
    let mut seen = [0usize; 3];
    for (k, &full) in m.columns.input_full.iter().enumerate() {
        if !(m.columns.valid[k] && full) {
            continue;
        }
        let driving = ctx.driving[k % nx].unwrap();
        let order = four.crank_order(&driving.dyad());
        assert_eq!(order, driving.order);
        let want = match order.direction() {
            Some(Turn::Counterclockwise) => Direction::Ccw,
            Some(Turn::Clockwise) => Direction::Cw,
            None => Direction::None,
        };
        assert_eq!(Direction::from_code(m.columns.direction[k]), want, "{k}");
        seen[(want.code() + 1) as usize] += 1;
    }
    // The example has turning cranks of every kind.
    assert!(seen.iter().all(|&n| n > 0), "{seen:?}");
}

#[test]
fn acceptable_cells_drive_through_the_four_poses() {
    let task = example_task();
    let m = map(&task, 200, 200);
    let nx = m.context.grid.nx();
    let cells: Vec<usize> = (0..m.columns.acceptable.len())
        .filter(|&k| m.columns.acceptable[k])
        .collect();
    assert!(cells.len() > 100, "{}", cells.len());
    for &k in cells.iter().step_by(cells.len() / 100) {
        let fb = m.linkage(k / nx, k % nx).unwrap();
        let mode = fb.modes()[0].unwrap();
        assert!(fb.modes().iter().all(|&x| x == Some(mode)));
        assert!(fb.figures.min_transmission >= DesignLimits::default().min_transmission);
        for (t, want) in fb.input_angles.iter().zip(task.poses()) {
            let got = fb.pose_at(*t, mode).unwrap();
            let scale = 1.0 + fb.size();
            assert!((got.position - want.position).norm() < 1e-8 * scale, "{k}");
            let da = (got.angle - want.angle).rem_euclid(std::f64::consts::TAU);
            assert!(da.min(std::f64::consts::TAU - da) < 1e-8, "{k}");
        }
    }
}

#[test]
fn the_map_does_not_depend_on_the_threads_or_the_progress_hook() {
    let task = example_task();
    let many = map(&task, 300, 257);
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(|| map(&task, 300, 257));
    assert_eq!(bits(&one.columns), bits(&many.columns));
    assert_eq!(one.context, many.context);
    let rows = AtomicUsize::new(0);
    let hook = |done: usize, total: usize| {
        assert_eq!(total, 257);
        rows.fetch_max(done, Ordering::Relaxed);
    };
    let followed = map_with(&task, 300, 257, &Control::new().with_progress(&hook)).unwrap();
    assert_eq!(rows.into_inner(), 257);
    assert_eq!(bits(&followed.columns), bits(&many.columns));
}

#[test]
fn best_pairs_rebuild_their_linkages_and_rank_by_score() {
    let task = example_task();
    let m = map(&task, 256, 256);
    for rank_by in [RankBy::Balanced, RankBy::Transmission, RankBy::Compact] {
        let best = m.best_pairs(Ranking::new(8, rank_by)).unwrap();
        assert_eq!(best.len(), 8, "{rank_by:?}");
        for w in best.windows(2) {
            assert!(w[0].score >= w[1].score - 1e-12, "{rank_by:?}");
        }
        for p in &best {
            let k = p.index.0 * 256 + p.index.1;
            assert!(m.columns.acceptable[k]);
            assert!(p.margin > 0.0);
            assert_eq!(
                task.four_bar(&p.driving.dyad(), &p.driven.dyad()).unwrap(),
                p.linkage
            );
            let f = p.linkage.figures;
            let want = rank_by
                .score(f.min_transmission, p.size_ratio, f.link_ratio)
                .unwrap();
            // The map's columns are single precision.
            assert!(
                (p.score - want).abs() < 1e-5 * (1.0 + want.abs()),
                "{rank_by:?}"
            );
        }
    }
    // The best transmission is the largest acceptable value of the column.
    let top = m.best_pairs(Ranking::new(1, RankBy::Transmission)).unwrap()[0];
    let max = (0..m.columns.acceptable.len())
        .filter(|&k| m.columns.acceptable[k])
        .map(|k| m.columns.min_transmission_rad[k])
        .fold(f32::NEG_INFINITY, f32::max);
    assert_eq!(top.score, f64::from(max));
    // The Pareto front: sizes grow, transmissions grow.
    let front = m.pareto_front().unwrap();
    assert!(front.len() >= 2);
    for w in front.windows(2) {
        assert!(w[0].size_ratio <= w[1].size_ratio + 1e-6);
        assert!(w[0].score < w[1].score);
    }
    // Nothing acceptable ranks above a front member in both figures.
    for p in &front {
        let k = p.index.0 * 256 + p.index.1;
        let (s, mu) = (m.columns.size_ratio[k], m.columns.min_transmission_rad[k]);
        assert!(
            !(0..m.columns.acceptable.len()).any(|q| m.columns.acceptable[q]
                && m.columns.size_ratio[q] < s
                && m.columns.min_transmission_rad[q] > mu)
        );
    }
    // Margins: positive exactly on the branch-free cells.
    let margins = m.margins().unwrap();
    for (k, &free) in m.columns.branch_free.iter().enumerate() {
        assert_eq!(margins[k] > 0.0, free);
    }
}

#[test]
fn bad_input_gives_typed_errors() {
    let task = example_task();
    let (l, c) = (DesignLimits::default(), Constraints::default());
    let ctl = Control::new();
    let three = Task::new(&example_poses()[..3]).unwrap();
    assert!(matches!(
        three.pair_map(8, 8, &MapOptions::new(&l, &c).unwrap(), &ctl),
        Err(Error::InvalidInput(InvalidInput::NeedsPoses {
            required: 4,
            found: 3,
            ..
        }))
    ));
    for (a, b) in [(0, 8), (8, 0), (1 << 20, 1 << 20), (usize::MAX, 2)] {
        assert!(
            matches!(
                task.pair_map(a, b, &MapOptions::new(&l, &c).unwrap(), &ctl),
                Err(Error::InvalidInput(InvalidInput::GridSize { .. }))
            ),
            "{a} {b}"
        );
    }
    let bad = DesignLimits {
        max_link_ratio: 0.5,
        ..l
    };
    assert!(matches!(
        MapOptions::new(&bad, &c).and_then(|o| task.pair_map(8, 8, &o, &ctl)),
        Err(Error::InvalidInput(_))
    ));
    let m = map(&task, 8, 8);
    assert!(m.linkage(8, 0).is_err() && m.linkage(0, 8).is_err());
    assert!(
        Ranking::new(3, RankBy::Balanced)
            .with_separation(-1.0)
            .is_err()
    );
}

#[test]
fn a_cancelled_map_stops_with_cancelled() {
    let task = example_task();
    let stop = AtomicBool::new(true);
    let e = map_with(&task, 64, 64, &Control::new().with_cancel(&stop)).unwrap_err();
    assert_eq!(e, Error::Cancelled { done: 0, total: 64 });
}

#[test]
fn a_cancelled_map_stops_while_it_samples_the_curves() {
    // The driving axis at its documented maximum: ten million dyads take
    // seconds. A cancelled map stops before them, in the curve's samples
    // (it computed them all and stopped at the first row of the map before).
    let task = example_task();
    let stop = AtomicBool::new(true);
    let n = Task::MAX_PAIR_SAMPLES;
    let e = map_with(&task, n, 2, &Control::new().with_cancel(&stop)).unwrap_err();
    assert_eq!(e, Error::Cancelled { done: 0, total: n });
}

#[test]
fn a_context_maps_into_reused_columns_bit_for_bit() {
    let task = example_task();
    let fresh = map(&task, 37, 23);
    // Another map's columns (another size of the same length) hold other
    // values: every one must be written.
    let mut reused = map(&task, 23, 37).columns;
    assert_ne!(bits(&reused), bits(&fresh.columns));
    fresh
        .context
        .map_into(reused.as_out(), &Control::new())
        .unwrap();
    assert_eq!(bits(&reused), bits(&fresh.columns));
    // A context put together by hand that no task gives is refused, not
    // indexed out of bounds.
    let mut bad = fresh.context.clone();
    bad.driven.pop();
    assert!(matches!(
        bad.map_into(reused.as_out(), &Control::new()),
        Err(Error::InvalidInput(InvalidInput::LengthMismatch {
            name: "context driven dyads",
            ..
        }))
    ));
    let mut three = fresh.context.clone();
    three.task = burmester::example::task();
    assert!(matches!(
        three.map_into(reused.as_out(), &Control::new()),
        Err(Error::InvalidInput(InvalidInput::NeedsPoses { .. }))
    ));
    reused.valid.pop();
    assert!(matches!(
        fresh.context.map_into(reused.as_out(), &Control::new()),
        Err(Error::InvalidInput(InvalidInput::LengthMismatch {
            name: "column valid",
            ..
        }))
    ));
}
