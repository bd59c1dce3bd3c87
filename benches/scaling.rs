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
//!   `benches/scaling/` were taken, before the atlas took any ranking);
//! * `design/example`: the one-call design (`Task::design`, balanced
//!   ranking, default options) of the built-in example;
//! * `pair_map/512`: the four-position pair map, 512^2 pairs of dyads of
//!   poses 1-4 of the notes' worked example;
//! * `drive_map/1024`: the drive map of the example's best linkage by
//!   transmission, 1024^2 crank pivots (as in the `drive_map` bench);
//! * `actuator_map/256`: the actuator map of that linkage, the actuator on
//!   the coupler at the middle of `A C`, 256^2 ground pivots, 256 travel
//!   samples each.
//!
//! Run it on a machine with many cores; `benches/report.py` lists it when
//! its output is present. Throughput is in samples (angles for
//! `solve_into`).

use std::hint::black_box;

use burmester::design::{
    ActuatorContext, ActuatorOptions, DesignOptions, DriveContext, DriveOptions,
};
use burmester::{Control, FourBar, Grid, MapOptions, Method, RankBy, Ranking, Task, example};
use criterion::{
    BenchmarkId, Criterion, SamplingMode, Throughput, criterion_group, criterion_main,
};

mod shared;

#[path = "../tests/rust/common/mod.rs"]
mod common;

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
    let options = MapOptions::default();
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
    let task4 = Task::new(&common::notes_poses()[..4]).expect("the notes' poses 1-4");
    let design_options = DesignOptions {
        rank_by: RankBy::Balanced,
        ..DesignOptions::default()
    };
    // The drive map's and the actuator map's linkage: the example's best by
    // transmission on a 400^2 view (the `drive_map` bench's).
    let view = Grid::new(vp, 400, 400).unwrap();
    let linkage = f
        .solution_map(&view, &options, &control)
        .unwrap()
        .best_pivots(Ranking::new(1, RankBy::Transmission))
        .unwrap()[0]
        .linkage;
    let (a0, e) = (linkage.driving.center, linkage.driving.circle);
    let h = 4.0 * (e - a0).norm();
    let drive_grid = Grid::from_bounds(a0.x - h, a0.x + h, a0.y - h, a0.y + h, 1024, 1024).unwrap();
    let drive =
        DriveContext::new(&linkage, e, &drive_grid, &options, &DriveOptions::default()).unwrap();
    let q = nalgebra::center(&linkage.driving.circle, &linkage.driven.circle);
    let act_grid = Grid::from_bounds(a0.x - h, a0.x + h, a0.y - h, a0.y + h, 256, 256).unwrap();
    let actuator = ActuatorContext::new(
        &linkage,
        q,
        &act_grid,
        &options,
        &ActuatorOptions::default(),
    )
    .unwrap();
    let mut g = c.benchmark_group("scaling");
    g.sampling_mode(SamplingMode::Flat);
    g.sample_size(10);
    for threads in thread_counts() {
        let pool = pool(threads);
        for n in [1024usize, 2048] {
            let grid = Grid::new(vp, n, n).unwrap();
            let mut columns = f.solution_map(&grid, &options, &control).unwrap().columns;
            g.throughput(Throughput::Elements(grid.len() as u64));
            g.bench_with_input(
                BenchmarkId::new(format!("solution_map_into/{n}"), threads),
                &threads,
                |b, _| {
                    pool.install(|| {
                        b.iter(|| {
                            shared::solution_map_into(&f, &grid, &options, &mut columns, &control)
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
                            &options,
                            // The ranking of the measured logs.
                            RankBy::Transmission,
                            &control,
                        )
                        .unwrap()
                    })
                })
            },
        );
        g.throughput(Throughput::Elements(1));
        g.bench_with_input(
            BenchmarkId::new("design/example", threads),
            &threads,
            |b, _| {
                pool.install(|| {
                    b.iter(|| task.design(black_box(&design_options), &control).unwrap())
                })
            },
        );
        g.throughput(Throughput::Elements(512 * 512));
        g.bench_with_input(
            BenchmarkId::new("pair_map/512", threads),
            &threads,
            |b, _| {
                pool.install(|| {
                    b.iter(|| {
                        task4
                            .pair_map(black_box(512), 512, &options, &control)
                            .unwrap()
                    })
                })
            },
        );
        g.throughput(Throughput::Elements(drive_grid.len() as u64));
        g.bench_with_input(
            BenchmarkId::new("drive_map/1024", threads),
            &threads,
            |b, _| pool.install(|| b.iter(|| black_box(&drive).map(&control).unwrap())),
        );
        g.throughput(Throughput::Elements(act_grid.len() as u64));
        g.bench_with_input(
            BenchmarkId::new("actuator_map/256", threads),
            &threads,
            |b, _| pool.install(|| b.iter(|| black_box(&actuator).map(&control).unwrap())),
        );
    }
    g.finish();
}

criterion_group!(benches, scaling);
criterion_main!(benches);
