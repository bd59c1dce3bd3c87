//! `pair_map`: the four-position pair map (`Task::pair_map`) on four poses
//! of the notes' worked example (`positions-4-5.md`, section 6, poses 1-4),
//! `n x n` pairs of dyads sampled along the center-point curve, with the
//! default limits and no constraints; throughput in pairs. The fill runs on
//! every core (the engine's tiled parallel fill).

use std::hint::black_box;

use burmester::{Control, MapOptions, Task};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

/// Poses 1-4 of the worked example: the coupler of the crank-rocker
/// `A0 = (0, 0)`, `B0 = (4, 0)`.
fn task() -> Task {
    Task::new(&common::notes_poses()[..4]).expect("the example's poses")
}

#[path = "../tests/rust/common/mod.rs"]
mod common;

fn pair_map(c: &mut Criterion) {
    let task = task();
    let (options, control) = (MapOptions::default(), Control::new());
    let mut g = c.benchmark_group("pair_map");
    g.sample_size(10);
    for n in [256usize, 1024] {
        g.throughput(Throughput::Elements((n * n) as u64));
        g.bench_with_input(BenchmarkId::new("example", n), &n, |b, &n| {
            b.iter(|| {
                task.pair_map(black_box(n), n, &options, &control)
                    .expect("the map")
            })
        });
    }
    g.finish();
}

criterion_group!(benches, pair_map);
criterion_main!(benches);
