//! `burmester_points`: four- and five-pose synthesis on the worked example
//! of the notes (`positions-4-5.md`, section 6), against the grid search of
//! candidate circle points that other tools use.
//!
//! * `trace/center_point_curve`: trace the center-point curve of poses
//!   1-4 over a square view of half-width three task sizes about the
//!   centroid of the poses (default polyline tolerance);
//! * `curves/new`: `FourPositions::new` of poses 1-4 (the local frame, the
//!   center- and circle-point cubics, formed in double-double since stop 38);
//! * `curves/free_center_arcs`, `curves/free_circle_arcs`: the branch-free
//!   arcs of both curves in that view for the driven dyad of the example's
//!   crank-rocker (`C0 = (4, 0)`): the trace, each vertex classified, the
//!   class changes bisected;
//! * `points/exact`: the Burmester points of the five poses
//!   (`FivePositions::new`: the curves, the candidates, Newton, the checks);
//! * `points/certificate`, `points/certificate_mixed`: the exact count
//!   certificate of the five poses (`certified_count`, a hidden hook:
//!   the cubics, the resultant, Sturm, isolation; issue 24), and of a
//!   task whose positions mix magnitudes `1e300` and `1e-300`;
//! * `points/grid_search`: the baseline. Candidate circle points on 12 radii
//!   x 48 angles about each pose's position (radii `size/6 .. 2 size`, equal
//!   steps: 5 x 576 = 2880 candidates); for each candidate its five
//!   positions under the poses' displacements, the circle through the
//!   positions at poses 1, 3 and 5, accepted when the positions at poses 2
//!   and 4 lie within 1 % of its radius of it. It counts the accepted
//!   candidates.
//!
//! Before timing, the bench checks completeness: how many of the example's
//! four Burmester points the grid search finds (an accepted candidate within
//! `1e-3` task sizes of the point's circle point, compared at pose 1) and how
//! many the exact method finds; it prints both and writes them to
//! `<target>/criterion/burmester_points/completeness.json` for
//! `benches/report.py`.
//!
//! The pair map has its own bench (`pair_map`).

use std::f64::consts::TAU;
use std::hint::black_box;
use std::path::PathBuf;

use burmester::synthesis::five::certified_count;
use burmester::synthesis::{FivePositions, FourPositions};
use burmester::{Dyad, Point2, Pose, Vector2, Viewport};
use criterion::{Criterion, criterion_group, criterion_main};

#[path = "../tests/rust/common/mod.rs"]
mod common;

// The worked example of the notes: five poses of a known crank-rocker.
use common::notes_poses as example_poses;

use common::centroid;

/// The size of a task as the library measures it: the largest distance of a
/// pose point from their centroid.
fn task_size(poses: &[Pose]) -> f64 {
    let c = centroid(poses);
    poses
        .iter()
        .map(|p| (p.position - c).norm())
        .fold(0.0, f64::max)
}

// ---------------------------------------------------------------------------
// The baseline: a grid search of candidate circle points.
// ---------------------------------------------------------------------------

const RADII: usize = 12;
const ANGLES: usize = 48;
/// Accept when the two check positions lie within this fraction of the
/// fitted radius of the circle.
const ACCEPT: f64 = 0.01;

/// An accepted candidate: the pose it was placed about, its circle point at
/// that pose, its center (the fitted circle's) and its worst relative
/// deviation from the circle.
#[derive(Debug, Clone, Copy)]
struct Hit {
    pose: usize,
    circle: Point2<f64>,
    center: Point2<f64>,
    deviation: f64,
}

/// The grid search: precomputed candidate offsets (radius and angle) and
/// pose rotations.
struct GridSearch {
    poses: [Pose; 5],
    /// `(cos, sin)` of every pose angle.
    rot: [(f64, f64); 5],
    /// Offsets of the candidates from a pose's position.
    offsets: Vec<Vector2<f64>>,
}

impl GridSearch {
    fn new(poses: [Pose; 5]) -> Self {
        let size = task_size(&poses);
        let mut offsets = Vec::with_capacity(RADII * ANGLES);
        for i in 0..RADII {
            let r = size * (i + 1) as f64 / 6.0;
            for k in 0..ANGLES {
                let (s, c) = (TAU * k as f64 / ANGLES as f64).sin_cos();
                offsets.push(Vector2::new(r * c, r * s));
            }
        }
        let rot = poses.map(|p| (p.angle.cos(), p.angle.sin()));
        GridSearch {
            poses,
            rot,
            offsets,
        }
    }

    /// The five positions of the moving point that is at `z` at pose `j`.
    fn positions(&self, z: Point2<f64>, j: usize) -> [Point2<f64>; 5] {
        let (cj, sj) = self.rot[j];
        let d = z - self.poses[j].position;
        // In the coupler frame.
        let local = Vector2::new(cj * d.x + sj * d.y, -sj * d.x + cj * d.y);
        std::array::from_fn(|k| {
            let (c, s) = self.rot[k];
            self.poses[k].position
                + Vector2::new(c * local.x - s * local.y, s * local.x + c * local.y)
        })
    }

    /// The candidate at `z` (pose `j`), if accepted.
    fn test(&self, z: Point2<f64>, j: usize) -> Option<Hit> {
        let q = self.positions(z, j);
        let center = circumcenter(q[0], q[2], q[4])?;
        let r = (q[0] - center).norm();
        let deviation = ((q[1] - center).norm() - r)
            .abs()
            .max(((q[3] - center).norm() - r).abs())
            / r;
        (deviation <= ACCEPT).then_some(Hit {
            pose: j,
            circle: z,
            center,
            deviation,
        })
    }

    /// Calls `f` for every accepted candidate.
    fn search(&self, mut f: impl FnMut(Hit)) {
        for (j, p) in self.poses.iter().enumerate() {
            for o in &self.offsets {
                if let Some(h) = self.test(p.position + o, j) {
                    f(h);
                }
            }
        }
    }

    /// The number of accepted candidates.
    fn count(&self) -> usize {
        let mut n = 0;
        self.search(|_| n += 1);
        n
    }

    /// The circle point at pose 1 of the moving point that is at `z` at
    /// pose `j`.
    fn at_pose_1(&self, z: Point2<f64>, j: usize) -> Point2<f64> {
        self.positions(z, j)[0]
    }
}

/// The center of the circle through `a`, `b`, `c`; `None` when they are
/// (nearly) collinear.
fn circumcenter(a: Point2<f64>, b: Point2<f64>, c: Point2<f64>) -> Option<Point2<f64>> {
    let (u, v) = (b - a, c - a);
    let d = 2.0 * (u.x * v.y - u.y * v.x);
    if d.abs() <= 1e-12 * u.norm_squared().max(v.norm_squared()) {
        return None;
    }
    let (uu, vv) = (u.norm_squared(), v.norm_squared());
    Some(a + Vector2::new(v.y * uu - u.y * vv, u.x * vv - v.x * uu) / d)
}

// ---------------------------------------------------------------------------
// Completeness.
// ---------------------------------------------------------------------------

/// Where criterion writes: `$CARGO_TARGET_DIR/criterion`, else the
/// workspace's `target/criterion`.
fn criterion_dir() -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../target"));
    target.join("criterion")
}

/// Counts the Burmester points the two methods find, prints them and writes
/// them to `completeness.json`.
fn completeness() {
    let poses = example_poses();
    let five = FivePositions::new(&poses).expect("the worked example");
    let exact = five.burmester_points();
    let size = five.size();
    let tol = 1e-3 * size;
    let grid = GridSearch::new(poses);
    let mut hits = Vec::new();
    grid.search(|h| hits.push(h));
    // The circle point of every hit at pose 1, nearest Burmester point.
    let nearest = |h: &Hit| {
        let z1 = grid.at_pose_1(h.circle, h.pose);
        exact
            .iter()
            .map(|d| (d.circle - z1).norm())
            .fold(f64::INFINITY, f64::min)
    };
    let grid_found = exact
        .iter()
        .filter(|d| {
            hits.iter()
                .any(|h| (grid.at_pose_1(h.circle, h.pose) - d.circle).norm() <= tol)
        })
        .count();
    let within = |k: f64| hits.iter().filter(|h| nearest(h) <= k * size).count();
    println!(
        "burmester_points/completeness: exact {} of 4 Burmester points; grid search \
         ({RADII} radii x {ANGLES} angles x 5 poses = {} candidates, accept within {} %) \
         accepts {} candidates and finds {grid_found} of 4 (within {tol:.1e} = 1e-3 task sizes)",
        exact.len(),
        5 * RADII * ANGLES,
        100.0 * ACCEPT,
        hits.len(),
    );
    for h in &hits {
        println!(
            "  accepted: pose {} circle ({:.4}, {:.4}) center ({:.4}, {:.4}) deviation {:.2e}; \
             nearest Burmester circle point {:.3} task sizes away",
            h.pose + 1,
            h.circle.x,
            h.circle.y,
            h.center.x,
            h.center.y,
            h.deviation,
            nearest(h) / size,
        );
    }
    // The exact points: all five positions concyclic to rounding.
    let worst = exact
        .iter()
        .map(|d| five.residual(d))
        .fold(0.0f64, f64::max);
    println!(
        "  exact: {} points, worst crank-length spread {worst:.1e}",
        exact.len()
    );
    let json = format!(
        "{{\"task\": \"notes worked example\", \"burmester_points\": 4, \"exact_found\": {}, \
         \"grid_candidates\": {}, \"grid_accepted\": {}, \"grid_found\": {grid_found}, \
         \"grid_accepted_within_0.1_size\": {}, \"tolerance_sizes\": 1e-3, \"exact_worst_residual\": {worst:e}}}\n",
        exact.len(),
        5 * RADII * ANGLES,
        hits.len(),
        within(0.1),
    );
    let dir = criterion_dir().join("burmester_points");
    if std::fs::create_dir_all(&dir).is_ok() {
        let _ = std::fs::write(dir.join("completeness.json"), json);
    }
}

// ---------------------------------------------------------------------------
// The benchmarks.
// ---------------------------------------------------------------------------

fn bench(c: &mut Criterion) {
    completeness();
    let poses = example_poses();

    let four = FourPositions::new(&poses[..4]).expect("the worked example");
    let centre = centroid(four.poses());
    let h = 3.0 * four.size();
    let view = Viewport::new(centre.x - h, centre.x + h, centre.y - h, centre.y + h).unwrap();
    let mut g = c.benchmark_group("burmester_points/trace");
    g.bench_function("center_point_curve", |b| {
        b.iter(|| {
            four.center_point_curve()
                .trace(black_box(&view), None)
                .unwrap()
        })
    });
    g.finish();

    let mut g = c.benchmark_group("burmester_points/curves");
    g.bench_function("new", |b| {
        b.iter(|| FourPositions::new(black_box(&poses[..4])).unwrap())
    });
    // The example's driven dyad: its rocker's fixed pivot, on the curve.
    let driven = four
        .curve_dyad(Point2::new(4.0, 0.0))
        .expect("the example's C0 is a center point");
    let arcs = four
        .filemon(&Dyad::new(driven.center, driven.circle))
        .expect("the example's driven dyad");
    g.bench_function("free_center_arcs", |b| {
        b.iter(|| arcs.free_center_arcs(black_box(&view)).unwrap())
    });
    g.bench_function("free_circle_arcs", |b| {
        b.iter(|| arcs.free_circle_arcs(black_box(&view)).unwrap())
    });
    g.finish();

    let mut g = c.benchmark_group("burmester_points/points");
    g.bench_function("exact", |b| {
        b.iter(|| FivePositions::new(black_box(&poses)).unwrap())
    });
    // Set-up included, as in the exact method.
    g.bench_function("grid_search", |b| {
        b.iter(|| GridSearch::new(black_box(poses)).count())
    });
    // The exact count certificate (issue 24) of the example, and of a task
    // whose positions mix magnitudes 1e300 and 1e-300 (its worst case).
    let example = poses.map(|p| [p.position.x, p.position.y, p.angle]);
    let mixed = [
        [1e300, 2e-299, 0.1],
        [-3e-300, 1.5e300, 0.7],
        [2e300, -1e-300, -0.4],
        [5e-299, 7e299, 1.2],
        [-1e300, -2e-300, 2.0],
    ];
    for (name, task) in [("certificate", example), ("certificate_mixed", mixed)] {
        assert!(certified_count(&task).is_some(), "{name}");
        g.bench_function(name, |b| b.iter(|| certified_count(black_box(&task))));
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
