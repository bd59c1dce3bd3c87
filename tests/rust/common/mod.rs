//! Helpers shared by the integration tests (each test crate uses some).
#![allow(dead_code)]

use std::f64::consts::PI;

use burmester::{
    AngleInterval, Constraints, Control, DesignLimits, Filemon, Grid, InputRange, MapOptions,
    Point2, Pose, SolutionMap, Task, Vector2,
};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;

pub(crate) mod curve_dyads;
pub(crate) mod five_count;
pub(crate) mod splitmix;

/// The notes' worked example (positions-4-5.md, section 6): five poses of
/// the coupler of the crank-rocker `A0 = (0, 0)`, `B0 = (4, 0)`.
pub(crate) fn notes_poses() -> [Pose; 5] {
    let d = |x: f64, y: f64, a: f64| Pose::new(x, y, a.to_radians());
    [
        d(1.049199280691, 2.279426358634, 45.220037141544),
        d(0.734502065472, 3.198658887874, 26.633426990744),
        d(-0.378159188147, 3.063048993013, 21.786789298262),
        d(-1.268710439724, 2.051150142014, 27.048624103934),
        d(-1.411118156972, 0.597429126400, 48.044287536536),
    ]
}

/// The solution map of `f` on `g` under `limits`, with no constraints.
pub(crate) fn solution_map(f: &Filemon, g: &Grid, limits: &DesignLimits) -> SolutionMap {
    f.solution_map(
        g,
        &MapOptions::new(limits, &Constraints::none()).unwrap(),
        &Control::new(),
    )
    .unwrap()
}

/// The centroid of the poses' positions.
pub(crate) fn centroid(poses: &[Pose]) -> Point2<f64> {
    let n = poses.len() as f64;
    Point2::from(
        poses
            .iter()
            .fold(Vector2::zeros(), |a, p| a + p.position.coords / n),
    )
}

/// Distance from `p` to the segment `a b` (to `a` when the segment is a
/// point).
pub(crate) fn seg_dist(p: Point2<f64>, a: Point2<f64>, b: Point2<f64>) -> f64 {
    let (ab, ap) = (b - a, p - a);
    // The parameter of the foot of the perpendicular: NaN for a point.
    let t = ap.dot(&ab) / ab.norm_squared();
    if t.is_nan() || t <= 0.0 {
        ap.norm()
    } else if t >= 1.0 {
        (p - b).norm()
    } else {
        (ap - ab * t).norm()
    }
}

/// Proptest settings: `cases` cases, no regression files (the tests live
/// outside the crate's source tree).
pub(crate) fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases,
        failure_persistence: None,
        rng_seed: seed(),
        ..ProptestConfig::default()
    }
}

/// The same draw on every run (a run's verdict depends on the code, not
/// on the draw: the README's test command, CI), fresh draws with
/// `BURMESTER_EXPLORE=1` (a search for new cases, pinned as tests when
/// found).
pub(crate) fn seed() -> proptest::test_runner::RngSeed {
    if std::env::var_os("BURMESTER_EXPLORE").is_some() {
        proptest::test_runner::RngSeed::Random
    } else {
        proptest::test_runner::RngSeed::Fixed(0x6275_726d_6573_7465)
    }
}

/// The fixed seed `fixed` for a test pinned to its own draw, or fresh draws
/// with `BURMESTER_EXPLORE=1` (as [`seed`]).
#[allow(dead_code)]
pub(crate) fn seed_or(fixed: u64) -> proptest::test_runner::RngSeed {
    if std::env::var_os("BURMESTER_EXPLORE").is_some() {
        proptest::test_runner::RngSeed::Random
    } else {
        proptest::test_runner::RngSeed::Fixed(fixed)
    }
}

/// `a` wrapped into `(-pi, pi]`.
#[allow(unused_imports)]
pub(crate) use burmester::geom::wrap_angle as wrap;

/// Well-conditioned random tasks: poses within 5 of the origin, rotations
/// between poses at least 0.1 rad (mod 2 pi), poles within 300 of the
/// origin and a pole triangle at least 0.05 across.
pub(crate) fn task() -> impl Strategy<Value = Task> {
    prop::array::uniform3((-5.0f64..5.0, -5.0f64..5.0, -PI..PI)).prop_filter_map(
        "ill-conditioned task",
        |p| {
            let t = Task::from_xya(&p.map(|(x, y, a)| [x, y, a])).ok()?;
            if t.rotations().iter().any(|r| r.abs() < 0.1) {
                return None;
            }
            let far = t
                .cremona()
                .ok()?
                .poles()
                .iter()
                .map(|p| p.coords.norm())
                .fold(0.0, f64::max);
            (far < 300.0 && t.scale() > 0.05).then_some(t)
        },
    )
}

/// A random Filemon construction with a driven center point in
/// `[-half, half]^2`, not all defective, and a driven crank of some length.
pub(crate) fn filemon(runner: &mut TestRunner, half: f64) -> Filemon {
    loop {
        let t = task().new_tree(runner).unwrap().current();
        let c = (-half..half, -half..half)
            .new_tree(runner)
            .unwrap()
            .current();
        if let Ok(f) = t.filemon(Point2::new(c.0, c.1)) {
            if !f.all_defective()
                && (f.driven_circle() - f.driven_crank("the test").unwrap().center).norm() > 1e-3
            {
                return f;
            }
        }
    }
}

/// Whether the linkage of `f` with the driving center point `a0` has the
/// circuit defect of a Grashof double-rocker input: its input rocks on two
/// arcs and the poses' input angles do not all lie on one of them (which
/// `Method::Simulate` reports and the sign tests cannot see).
pub(crate) fn poses_on_both_arcs(f: &Filemon, a0: Point2<f64>) -> bool {
    let Ok(fb) = f.four_bar(a0) else {
        return false;
    };
    match fb.fourbar.input_range() {
        InputRange::TwoArcs(p, q) => {
            let on = |arc: &AngleInterval| fb.input_angles.iter().all(|&a| arc.contains(a));
            !on(&p) && !on(&q)
        }
        _ => false,
    }
}

/// Every column's values as bits (NaN equals NaN).
pub(crate) fn bits(c: &burmester::design::Columns) -> Vec<Vec<u64>> {
    vec![
        c.valid.iter().map(|&v| u64::from(v)).collect(),
        c.branch_free.iter().map(|&v| u64::from(v)).collect(),
        c.grashof.iter().map(|&v| u64::from(v)).collect(),
        c.input_full.iter().map(|&v| u64::from(v)).collect(),
        c.direction.iter().map(|&v| v as u8 as u64).collect(),
        c.one_circuit.iter().map(|&v| u64::from(v)).collect(),
        c.min_transmission_rad
            .iter()
            .map(|v| u64::from(v.to_bits()))
            .collect(),
        c.link_ratio
            .iter()
            .map(|v| u64::from(v.to_bits()))
            .collect(),
        c.size_ratio
            .iter()
            .map(|v| u64::from(v.to_bits()))
            .collect(),
        c.acceptable.iter().map(|&v| u64::from(v)).collect(),
    ]
}

/// `task` and its linkage `sfb` moved by `tf` (a similarity that turns by
/// `turn` radians): the moved task and the linkage rebuilt on it from the
/// moved dyads.
pub(crate) fn moved_linkage(
    task: &Task,
    sfb: &burmester::SynthesizedFourBar,
    tf: impl Fn(Point2<f64>) -> Point2<f64>,
    turn: f64,
) -> (Task, burmester::SynthesizedFourBar) {
    use burmester::Dyad;
    let poses: Vec<[f64; 3]> = task
        .poses()
        .iter()
        .map(|p| {
            let q = tf(p.position);
            [q.x, q.y, p.angle + turn]
        })
        .collect();
    let moved = Task::from_xya(&poses).unwrap();
    let linkage = moved
        .four_bar(
            &Dyad::new(tf(sfb.driving.center), tf(sfb.driving.circle)),
            &Dyad::new(tf(sfb.driven.center), tf(sfb.driven.circle)),
        )
        .unwrap();
    (moved, linkage)
}

/// Runs `f` with a cancel flag that a second thread sets `after` it
/// starts, on a pool of two threads of its own (the global pool is shared
/// with the other tests of a binary, whose long tasks would delay the
/// answer): `f`'s answer and how long after the flag it came.
pub(crate) fn cancelled_after<T: Send>(
    after: std::time::Duration,
    f: impl FnOnce(&core::sync::atomic::AtomicBool) -> T + Send,
) -> (T, std::time::Duration) {
    let stop = core::sync::atomic::AtomicBool::new(false);
    std::thread::scope(|s| {
        let flagged = s.spawn(|| {
            std::thread::sleep(after);
            stop.store(true, core::sync::atomic::Ordering::Relaxed);
            std::time::Instant::now()
        });
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        let out = pool.install(|| f(&stop));
        let done = std::time::Instant::now();
        (out, done - flagged.join().unwrap())
    })
}
