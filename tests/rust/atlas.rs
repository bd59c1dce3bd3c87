//! The pivot-pair atlas against the solution maps it reduces: at random
//! driven centers of random tasks, the count, the branch-free count and
//! the best driving pivot equal those of `task.filemon(C0).solution_map`
//! over the same driving grid (`best_pivots(1, _, rank_by)`, for every
//! ranking with a score, with and without size limits); any tiling of the
//! driven grid gives the same cells, bit for bit.

use burmester::{
    AtlasCell, Constraints, Control, DesignLimits, Grid, InputRequirement, MapOptions, Point2,
    RankBy, Ranking, Task, example,
};
mod common;

use common::task;
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;

/// The cells of the first row of driven centers of `t`'s atlas, without
/// constraints.
fn first_row(
    t: &Task,
    driven: &Grid,
    driving: &Grid,
    limits: &DesignLimits,
    rank_by: RankBy,
) -> Vec<AtlasCell> {
    t.pivot_atlas_rows(
        driven,
        0..1,
        driving,
        &MapOptions::new(limits, &Constraints::default()).unwrap(),
        rank_by,
        &Control::new(),
    )
    .unwrap()
}

fn lenient() -> DesignLimits {
    DesignLimits::from_degrees(20.0, 20.0, InputRequirement::Any).unwrap()
}

/// The rankings with a score.
const SCORED: [RankBy; 3] = [RankBy::Balanced, RankBy::Transmission, RankBy::Compact];

/// The cell from the full solution map at `c0`.
fn reference(
    t: &Task,
    c0: Point2<f64>,
    driving: &Grid,
    limits: &DesignLimits,
    rank_by: RankBy,
) -> AtlasCell {
    let Ok(f) = t.filemon(c0) else {
        return AtlasCell::INVALID;
    };
    let map = f
        .solution_map(
            driving,
            &MapOptions::new(limits, &Constraints::default()).unwrap(),
            &Control::new(),
        )
        .unwrap();
    let c = &map.columns;
    let count = c.acceptable.iter().filter(|&&a| a).count() as u64;
    let branch_free = c.branch_free.iter().filter(|&&a| a).count() as u64;
    let best = map
        .best_pivots(Ranking::new(1, rank_by))
        .unwrap()
        .first()
        .map(|p| {
            let k = p.index.0 * driving.nx() + p.index.1;
            burmester::AtlasBest {
                driving: p.center,
                index: p.index,
                min_transmission_rad: c.min_transmission_rad[k],
                link_ratio: c.link_ratio[k],
                margin: p.margin,
                size_ratio: c.size_ratio[k],
                score: p.score,
            }
        });
    AtlasCell {
        valid: true,
        count,
        branch_free,
        best,
    }
}

fn same(a: &AtlasCell, b: &AtlasCell) -> bool {
    let bits = |c: &AtlasCell| {
        (
            c.valid,
            c.count,
            c.branch_free,
            c.best.map(|b| {
                (
                    b.driving.x.to_bits(),
                    b.driving.y.to_bits(),
                    b.index,
                    b.min_transmission_rad.to_bits(),
                    b.link_ratio.to_bits(),
                    b.margin.to_bits(),
                    b.size_ratio.to_bits(),
                    b.score.to_bits(),
                )
            }),
        )
    };
    bits(a) == bits(b)
}

#[test]
fn cells_equal_the_reduced_solution_maps() {
    let mut runner = TestRunner::deterministic();
    let mut with_best = 0;
    let mut checked = 0;
    while checked < 24 {
        let t = task().new_tree(&mut runner).unwrap().current();
        let rank_by = SCORED[checked % 3];
        // Every other task also bounds the linkage's size.
        let limits = if checked % 2 == 0 {
            lenient()
        } else {
            lenient().with_size(25.0, 12.0).unwrap()
        };
        let driven = Grid::from_bounds(-6.0, 6.0, -6.0, 6.0, 3, 2).unwrap();
        let driving = Grid::from_bounds(-8.0, 8.0, -8.0, 8.0, 41, 37).unwrap();
        let atlas = t
            .pivot_atlas(
                &driven,
                &driving,
                &MapOptions::new(&limits, &Constraints::default()).unwrap(),
                rank_by,
                &Control::new(),
            )
            .unwrap();
        assert_eq!(atlas.rank_by, rank_by);
        for k in 0..driven.len() {
            let c0 = driven.point(k % driven.nx(), k / driven.nx());
            let want = reference(&t, c0, &driving, &limits, rank_by);
            assert!(
                same(&atlas.cells[k], &want),
                "{t:?} C0 {c0:?}: {:?} vs {want:?}",
                atlas.cells[k]
            );
            with_best += usize::from(want.best.is_some());
        }
        checked += 1;
    }
    // The check is not vacuous.
    assert!(with_best > 20, "only {with_best} cells with a best pivot");
}

#[test]
fn random_driven_centers_of_the_example() {
    let t = example::task();
    let mut runner = TestRunner::deterministic();
    let driving = Grid::new(example::viewport(), 48, 40).unwrap();
    let limits = DesignLimits::default();
    for n in 0..12 {
        let rank_by = SCORED[n % 3];
        let (x, y) = (-6.0f64..6.0, -6.0f64..6.0)
            .new_tree(&mut runner)
            .unwrap()
            .current();
        // A one-sample driven grid at the random center.
        let driven = Grid::from_bounds(x - 0.5, x + 0.5, y - 0.5, y + 0.5, 1, 1).unwrap();
        let c0 = driven.point(0, 0);
        let cells = first_row(&t, &driven, &driving, &limits, rank_by);
        let want = reference(&t, c0, &driving, &limits, rank_by);
        assert!(
            same(&cells[0], &want),
            "C0 {c0:?}: {:?} vs {want:?}",
            cells[0]
        );
    }
}

#[test]
fn any_tiling_gives_the_same_cells() {
    let t = example::task();
    let driven = Grid::new(example::viewport(), 9, 7).unwrap();
    let driving = Grid::new(example::viewport(), 30, 24).unwrap();
    let options = MapOptions::new(&lenient(), &Constraints::default()).unwrap();
    let by = RankBy::Balanced;
    let whole = t
        .pivot_atlas(&driven, &driving, &options, by, &Control::new())
        .unwrap();
    assert!(whole.cells.iter().any(|c| c.best.is_some()));
    for tile in [1, 2, 3, 7] {
        let mut cells = Vec::new();
        let mut j = 0;
        while j < driven.ny() {
            let end = (j + tile).min(driven.ny());
            cells.extend(
                t.pivot_atlas_rows(&driven, j..end, &driving, &options, by, &Control::new())
                    .unwrap(),
            );
            j = end;
        }
        assert_eq!(cells.len(), whole.cells.len());
        for (a, b) in cells.iter().zip(&whole.cells) {
            assert!(same(a, b), "tile {tile}: {a:?} vs {b:?}");
        }
    }
}

#[test]
fn driven_centers_without_filemon_are_invalid() {
    let t = example::task();
    let poles = t
        .filemon(example::driven_center())
        .unwrap()
        .cremona()
        .unwrap()
        .poles();
    // A one-sample grid exactly at a pole.
    let p = poles[0];
    let driven = Grid::from_bounds(p.x - 1.0, p.x + 1.0, p.y - 1.0, p.y + 1.0, 1, 1).unwrap();
    assert_eq!(driven.point(0, 0), p);
    let driving = Grid::new(example::viewport(), 10, 10).unwrap();
    let cells = first_row(
        &t,
        &driven,
        &driving,
        &DesignLimits::default(),
        RankBy::Balanced,
    );
    assert_eq!(cells[0], AtlasCell::INVALID);
}

#[test]
fn bad_input_and_cancel() {
    use core::sync::atomic::AtomicBool;
    let t = example::task();
    let g = Grid::new(example::viewport(), 4, 4).unwrap();
    let (l, c, by) = (
        DesignLimits::default(),
        Constraints::default(),
        RankBy::Balanced,
    );
    let options = MapOptions::new(&l, &c).unwrap();
    assert!(
        t.pivot_atlas_rows(&g, 2..5, &g, &options, by, &Control::new())
            .is_err()
    );
    let stop = AtomicBool::new(true);
    let e = t
        .pivot_atlas(&g, &g, &options, by, &Control::new().with_cancel(&stop))
        .unwrap_err();
    assert!(matches!(e, burmester::Error::Cancelled { done: 0, .. }));
    let bad = Constraints {
        link_width: -1.0,
        ..Constraints::default()
    };
    assert!(
        MapOptions::new(&l, &bad)
            .and_then(|o| t.pivot_atlas(&g, &g, &o, by, &Control::new()))
            .is_err()
    );
    // Rankings without a score are refused.
    for r in [RankBy::Pareto, RankBy::Margin] {
        let e = t
            .pivot_atlas(&g, &g, &options, r, &Control::new())
            .unwrap_err();
        assert_eq!(e.cause(), "unknown_name", "{e}");
    }
}
