//! `branch_sweep`: classify every candidate driving center point on an
//! `n x n` grid over the center-point plane of the built-in example.
//!
//! * `conic`: the run-based sweep of the two transformed conics;
//! * `conic_pointwise`: the same, evaluated point by point;
//! * `direct`: the circle point, then the sign test at the three poses;
//! * `simulate`: build the four-bar and drive it (up to 1024^2);
//! * `margin`: the signed margin map (f32);
//! * `solution_map`: the designer's full map (branch, Grashof, order and
//!   circuit, minimum transmission angle over the travel, link ratio,
//!   acceptable mask), up to 1024^2, into fresh columns;
//! * `solution_map_into`: the same into an earlier map's columns;
//! * `memset`: filling a byte buffer of the same size, the physical floor
//!   for writing the map.
//!
//! Throughput is in grid points.

use std::hint::black_box;

use burmester::{Control, Grid, MapOptions, Method, example};
use criterion::{
    BenchmarkId, Criterion, SamplingMode, Throughput, criterion_group, criterion_main,
};

mod shared;

const SIZES: [usize; 3] = [256, 1024, 4096];

fn sweep(c: &mut Criterion) {
    let f = example::task().filemon(example::driven_center()).unwrap();
    let vp = example::viewport();
    let control = Control::new();
    let mut g = c.benchmark_group("branch_sweep");
    g.sampling_mode(SamplingMode::Flat);
    for n in SIZES {
        let grid = Grid::new(vp, n, n).unwrap();
        let mut out = vec![false; grid.len()];
        let mut margin = vec![0.0f32; grid.len()];
        g.throughput(Throughput::Elements(grid.len() as u64));
        g.sample_size(if n >= 4096 { 10 } else { 30 });
        g.bench_with_input(BenchmarkId::new("memset", n), &n, |b, _| {
            b.iter(|| black_box(&mut out[..]).fill(black_box(true)))
        });
        g.bench_with_input(BenchmarkId::new("conic", n), &n, |b, _| {
            b.iter(|| {
                f.branch_map_into(&grid, Method::Conic, black_box(&mut out), &control)
                    .unwrap()
            })
        });
        g.bench_with_input(BenchmarkId::new("conic_alloc", n), &n, |b, _| {
            b.iter(|| f.branch_map(black_box(&grid), Method::Conic))
        });
        g.bench_with_input(BenchmarkId::new("conic_pointwise", n), &n, |b, _| {
            b.iter(|| {
                f.branch_map_pointwise_into(&grid, black_box(&mut out))
                    .unwrap()
            })
        });
        g.bench_with_input(BenchmarkId::new("margin", n), &n, |b, _| {
            b.iter(|| {
                f.margin_map_into(&grid, black_box(&mut margin), &control)
                    .unwrap()
            })
        });
        g.bench_with_input(BenchmarkId::new("direct", n), &n, |b, _| {
            b.iter(|| {
                f.branch_map_into(&grid, Method::Direct, black_box(&mut out), &control)
                    .unwrap()
            })
        });
        if n <= 1024 {
            let options = MapOptions::default();
            g.bench_with_input(BenchmarkId::new("solution_map", n), &n, |b, _| {
                b.iter(|| {
                    f.solution_map(black_box(&grid), &options, &control)
                        .unwrap()
                })
            });
            // The same map into the columns of an earlier one: no fresh
            // pages, like `direct` into its existing buffer.
            let mut columns = f.solution_map(&grid, &options, &control).unwrap().columns;
            g.bench_with_input(BenchmarkId::new("solution_map_into", n), &n, |b, _| {
                b.iter(|| shared::solution_map_into(&f, &grid, &options, &mut columns, &control))
            });
            g.bench_with_input(BenchmarkId::new("simulate", n), &n, |b, _| {
                b.iter(|| {
                    f.branch_map_into(&grid, Method::Simulate, black_box(&mut out), &control)
                        .unwrap()
                })
            });
        }
    }
    g.finish();
}

criterion_group!(benches, sweep);
criterion_main!(benches);
