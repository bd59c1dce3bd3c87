//! `design`: the one-call design search (`Task::design`, default options)
//! on the built-in example against the brute force it must match or beat:
//! for every driven pivot of a grid four times finer than the search's
//! coarse pass (48 x 48 over the same box), the solution map over driving
//! pivots four times finer too (192 x 192) and its best pivot by the same
//! (balanced) score. Before timing, the bench checks that the design's
//! best score is at least the brute force's (same run, same machine) and
//! prints both.

use std::hint::black_box;

use burmester::{
    Control, DesignOptions, Grid, MapOptions, RankBy, Ranking, Task, Viewport, example,
};
use criterion::{Criterion, criterion_group, criterion_main};

/// A grid over `v` with `n` samples along its longer side (as the search's).
fn grid_over(v: &Viewport, n: usize) -> Grid {
    let (w, h) = v.size();
    let (nx, ny) = if w >= h {
        (n, ((n as f64 * h / w).round() as usize).max(2))
    } else {
        (((n as f64 * w / h).round() as usize).max(2), n)
    };
    Grid::new(*v, nx, ny).expect("a grid")
}

/// The brute force's best score over both pivots.
fn brute_force(task: &Task, options: &DesignOptions, bx: &Viewport) -> f64 {
    let driven = grid_over(bx, 4 * options.coarse_driven);
    let driving = grid_over(bx, 4 * options.coarse_driving);
    let map_options =
        MapOptions::new(&options.limits, &options.space.constraints()).expect("the options");
    let mut best = f64::NEG_INFINITY;
    for k in 0..driven.len() {
        let c0 = driven.point(k % driven.nx(), k / driven.nx());
        let Ok(f) = task.filemon(c0) else { continue };
        let map = f
            .solution_map(&driving, &map_options, &Control::new())
            .expect("a map");
        if let Some(p) = map
            .best_pivots(Ranking::new(1, options.rank_by))
            .expect("a ranking")
            .first()
        {
            best = best.max(p.score);
        }
    }
    best
}

fn design(c: &mut Criterion) {
    let task = example::task();
    let options = DesignOptions {
        rank_by: RankBy::Balanced,
        ..DesignOptions::default()
    };
    let control = Control::new();
    let report = task.design(&options, &control).expect("a design");
    let bx = report.search_box.expect("three poses have a search box");
    let brute = brute_force(&task, &options, &bx);
    let got = report.designs[0].score;
    println!("design best score {got:.6}, brute force (4x) best score {brute:.6}");
    assert!(
        got >= brute,
        "the design ({got}) must match or beat the brute force ({brute})"
    );
    let mut g = c.benchmark_group("design");
    g.sample_size(10);
    g.bench_function("example/design", |b| {
        b.iter(|| {
            task.design(black_box(&options), &control)
                .expect("a design")
        })
    });
    g.bench_function("example/brute_force_4x", |b| {
        b.iter(|| brute_force(black_box(&task), &options, &bx))
    });
    g.finish();
}

criterion_group!(benches, design);
criterion_main!(benches);
