//! `position`: a single solve and a sweep of 3600 input angles, against the
//! `pos()` of the Rust crate `four-bar` 7.0.5 on the same linkage (the
//! baseline named in the foundation issue), measured in the same run.
//!
//! `four-bar`'s `pos()` returns five points (both pivots, both moving
//! joints and a coupler point), so `joints_coupler` does the same
//! work here for a like-for-like figure; `solve` returns the angles only.

use std::f64::consts::TAU;
use std::hint::black_box;

use burmester::{AssemblyMode, FourBar, Vector2};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use four_bar::NormFourBar;
use four_bar::mech::{CurveGen, Stat, fb::UnNorm};

mod shared;

const SWEEP: usize = 3600;

/// Norton's Example 4-1 with a coupler point (mm).
const L: [f64; 4] = [100.0, 40.0, 120.0, 80.0];
const COUPLER_POINT: (f64, f64) = (60.0, 30.0);

fn baseline() -> four_bar::FourBar {
    let (u, v) = COUPLER_POINT;
    let norm = NormFourBar {
        l1: L[0],
        l3: L[2],
        l4: L[3],
        l5: u.hypot(v),
        g: v.atan2(u),
        stat: Stat::C1B1,
    };
    four_bar::FourBar::new(UnNorm::from_driver(L[1]), norm)
}

fn single(c: &mut Criterion) {
    let fb = FourBar::new(L[0], L[1], L[2], L[3]).unwrap();
    let base = baseline();
    let local = Vector2::new(COUPLER_POINT.0, COUPLER_POINT.1);
    let t2 = 0.7f64;
    let mut g = c.benchmark_group("position/single");
    g.throughput(Throughput::Elements(1));
    g.bench_function("solve", |b| {
        b.iter(|| fb.solve(black_box(t2), black_box(AssemblyMode::Open)))
    });
    g.bench_function("joints_coupler", |b| {
        b.iter(|| {
            let j = fb
                .joints_at(black_box(t2), black_box(AssemblyMode::Open))
                .unwrap();
            (j, j.coupler_point(local))
        })
    });
    g.bench_function("four_bar_pos", |b| b.iter(|| base.pos(black_box(t2))));
    g.finish();
}

fn sweep(c: &mut Criterion) {
    let fb = FourBar::new(L[0], L[1], L[2], L[3]).unwrap();
    let base = baseline();
    let angles: Vec<f64> = (0..SWEEP).map(|k| k as f64 * TAU / SWEEP as f64).collect();
    let (mut t3, mut t4, mut ok) = (vec![0.0; SWEEP], vec![0.0; SWEEP], vec![false; SWEEP]);
    let mut g = c.benchmark_group("position/sweep");
    g.throughput(Throughput::Elements(SWEEP as u64));
    g.bench_function(BenchmarkId::new("solve_into", SWEEP), |b| {
        b.iter(|| shared::solve_into(&fb, &angles, &mut t3, &mut t4, &mut ok))
    });
    g.bench_function(BenchmarkId::new("four_bar_pos", SWEEP), |b| {
        b.iter(|| {
            black_box(&angles)
                .iter()
                .filter_map(|&t| base.pos(t))
                .map(|p| p[3][0])
                .sum::<f64>()
        })
    });
    g.finish();
}

criterion_group!(benches, single, sweep);
criterion_main!(benches);
