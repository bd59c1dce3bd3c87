//! `scaling`: the parallel paths on 1, 2, 4, ... threads, up to the
//! machine's cores (a rayon pool of each size, `install`ed around the
//! measured call), to read thread scaling as the ratio of the 1-thread
//! time to the n-thread time of one run:
//!
//! * `solution_map_into/{1024,2048}`: the designer's solution map of the
//!   built-in example into an earlier map's columns (the tiled engine);
//! * `direct/1024`: the `direct` branch map (a circle point and three sign
//!   tests per sample, the same engine);
//! * `solve_into/1000000`: position analysis of 10^6 input angles (the
//!   batch kernel, parallel over chunks of 4096);
//! * `atlas/32x256`: the pivot-pair atlas, 32^2 driven centers by 256^2
//!   driving samples each, ranked by transmission (as when the logs in
//!   `benches/scaling/` were taken, before the atlas took any ranking).
//!
//! Run it on a machine with many cores; `benches/report.py` lists it when
//! its output is present. Throughput is in samples (angles for
//! `solve_into`).

use std::hint::black_box;

use burmester::{Constraints, Control, DesignLimits, FourBar, Grid, Method, RankBy, example};
use criterion::{
    BenchmarkId, Criterion, SamplingMode, Throughput, criterion_group, criterion_main,
};

mod shared;

/// 1, 2, 4, ... up to the available cores, and the core count itself.
fn thread_counts() -> Vec<usize> {
    let max = std::thread::available_parallelism().map_or(1, usize::from);
    let mut counts: Vec<usize> = (0..)
        .map(|k| 1usize << k)
        .take_while(|&t| t <= max)
        .collect();
    if counts.last() != Some(&max) {
        counts.push(max);
    }
    counts
}

fn pool(threads: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a rayon pool")
}

fn scaling(c: &mut Criterion) {
    let task = example::task();
    let f = task.filemon(example::driven_center()).unwrap();
    let vp = example::viewport();
    let control = Control::new();
    let limits = DesignLimits::default();
    let none = Constraints::none();
    let fb = FourBar::new(100.0, 40.0, 120.0, 80.0).unwrap();
    let n_angles = 1_000_000usize;
    let angles: Vec<f64> = (0..n_angles)
        .map(|k| k as f64 * (std::f64::consts::TAU / n_angles as f64))
        .collect();
    let (mut t3, mut t4, mut ok) = (
        vec![0.0; n_angles],
        vec![0.0; n_angles],
        vec![false; n_angles],
    );
    let mut g = c.benchmark_group("scaling");
    g.sampling_mode(SamplingMode::Flat);
    g.sample_size(10);
    for threads in thread_counts() {
        let pool = pool(threads);
        for n in [1024usize, 2048] {
            let grid = Grid::new(vp, n, n).unwrap();
            let mut columns = f
                .solution_map(&grid, &limits, &none, &control)
                .unwrap()
                .columns;
            g.throughput(Throughput::Elements(grid.len() as u64));
            g.bench_with_input(
                BenchmarkId::new(format!("solution_map_into/{n}"), threads),
                &threads,
                |b, _| {
                    pool.install(|| {
                        b.iter(|| {
                            shared::solution_map_into(
                                &f,
                                &grid,
                                &limits,
                                &none,
                                &mut columns,
                                &control,
                            )
                        })
                    })
                },
            );
        }
        let grid = Grid::new(vp, 1024, 1024).unwrap();
        let mut out = vec![false; grid.len()];
        g.throughput(Throughput::Elements(grid.len() as u64));
        g.bench_with_input(
            BenchmarkId::new("direct/1024", threads),
            &threads,
            |b, _| {
                pool.install(|| {
                    b.iter(|| {
                        f.branch_map_into(&grid, Method::Direct, black_box(&mut out), &control)
                            .unwrap()
                    })
                })
            },
        );
        g.throughput(Throughput::Elements(n_angles as u64));
        g.bench_with_input(
            BenchmarkId::new("solve_into/1000000", threads),
            &threads,
            |b, _| {
                pool.install(|| {
                    b.iter(|| shared::solve_into(&fb, &angles, &mut t3, &mut t4, &mut ok))
                })
            },
        );
        let driven = Grid::new(vp, 32, 32).unwrap();
        let driving = Grid::new(vp, 256, 256).unwrap();
        g.throughput(Throughput::Elements((driven.len() * driving.len()) as u64));
        g.bench_with_input(
            BenchmarkId::new("atlas/32x256", threads),
            &threads,
            |b, _| {
                pool.install(|| {
                    b.iter(|| {
                        task.pivot_atlas(
                            &driven,
                            &driving,
                            &limits,
                            &none,
                            // The ranking of the measured logs.
                            RankBy::Transmission,
                            &control,
                        )
                        .unwrap()
                    })
                })
            },
        );
    }
    g.finish();
}

criterion_group!(benches, scaling);
criterion_main!(benches);
