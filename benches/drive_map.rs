//! `drive_map`: the drive map (`DriveContext::map`) against the solution
//! map, in the same run and on grids of the same size, so their ratio is
//! the cost per sample of one over the other.
//!
//! The linkage is the built-in example's best by transmission (a
//! triple-rocker, its input swinging), the attachment its input joint `A`,
//! the candidate crank pivots a square of half-width 4 `|A - A0|` about
//! `A0`; the solution map is the example's over its view, the one of the
//! `branch_sweep` bench. Both fill columns they were given
//! (`solution_map_into`, `map_into`: no fresh pages), and the drive map
//! also fresh (`map`). Default limits, no constraints, every core.

use std::hint::black_box;

use burmester::design::{DriveContext, DriveOptions};
use burmester::{Control, Grid, MapOptions, RankBy, Ranking, example};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

fn drive_map(c: &mut Criterion) {
    let (options, control) = (MapOptions::default(), Control::new());
    let f = example::task()
        .filemon(example::driven_center())
        .expect("the example");
    let view = Grid::new(example::viewport(), 400, 400).expect("the view");
    let smap = f.solution_map(&view, &options, &control).expect("the map");
    let linkage = smap
        .best_pivots(Ranking::new(1, RankBy::Transmission))
        .expect("ranked")[0]
        .linkage;
    let a0 = linkage.driving.center;
    let e = linkage.driving.circle;
    let h = 4.0 * (e - a0).norm();
    let mut g = c.benchmark_group("drive_map");
    g.sample_size(20);
    for n in [256usize, 1024] {
        g.throughput(Throughput::Elements((n * n) as u64));
        let grid = Grid::from_bounds(a0.x - h, a0.x + h, a0.y - h, a0.y + h, n, n).expect("grid");
        let ctx = DriveContext::new(&linkage, e, &grid, &options, &DriveOptions::default())
            .expect("a drive context");
        g.bench_with_input(BenchmarkId::new("drive_map", n), &n, |b, _| {
            b.iter(|| black_box(&ctx).map(&control).expect("the drive map"))
        });
        let mut dcols = ctx.map(&control).expect("the drive map").columns;
        g.bench_with_input(BenchmarkId::new("drive_map_into", n), &n, |b, _| {
            b.iter(|| {
                black_box(&ctx)
                    .map_into(dcols.as_out(), &control)
                    .expect("the drive map")
            })
        });
        let sgrid = Grid::new(example::viewport(), n, n).expect("grid");
        let mut scols = f
            .solution_map(&sgrid, &options, &control)
            .expect("the map")
            .columns;
        g.bench_with_input(BenchmarkId::new("solution_map_into", n), &n, |b, _| {
            b.iter(|| {
                f.solution_map_into(black_box(&sgrid), &options, scols.as_out(), &control)
                    .expect("the map")
            })
        });
    }
    g.finish();
}

criterion_group!(benches, drive_map);
criterion_main!(benches);
