//! Four- and five-position synthesis from Rust. The poses are made by
//! driving a known crank-rocker (fixed pivots A0 = (0, 0) and B0 = (4, 0)),
//! so its two dyads must come back: on the center-point curve of four
//! poses, and among the Burmester points of five.
//!
//! Four poses: the center-point curve (a circular cubic), the linkage of
//! two of its dyads, and the pair map of every linkage of the four poses
//! with its best pairs. Five poses: the Burmester points and the four-bars
//! of every two of them, for either one driving.
//!
//! ```sh
//! cargo run --release -p burmester --example four_five_pose
//! ```

use burmester::synthesis::{FivePositions, FourPositions};
use burmester::{AssemblyMode, Control, FourBar, MapOptions, Point2, Pose, RankBy, Ranking, Task};

/// The pose of the coupler of `fb` at crank angle `deg`: the coupler point
/// at (1, 1.5) in the frame at the crank joint, x toward the rocker joint.
fn pose(fb: &FourBar, deg: f64) -> Result<Pose, burmester::Error> {
    let j = fb.joints_at(deg.to_radians(), AssemblyMode::Open)?;
    let x = j.rocker_joint - j.crank_joint;
    let phi = x.y.atan2(x.x);
    Ok(Pose::new(
        j.crank_joint.x + phi.cos() - 1.5 * phi.sin(),
        j.crank_joint.y + phi.sin() + 1.5 * phi.cos(),
        phi,
    ))
}

/// `x` rounded to six decimals, without the sign of a rounded zero.
fn tidy(x: f64) -> f64 {
    (x * 1e6).round() / 1e6 + 0.0
}

fn near(p: Point2<f64>, q: [f64; 2]) -> bool {
    (p - Point2::new(q[0], q[1])).norm() < 1e-6
}

fn main() -> Result<(), burmester::Error> {
    // The generating linkage: crank 1.5, coupler 3.5, rocker 3.0.
    let fb = FourBar::from_pivots(Point2::origin(), Point2::new(4.0, 0.0), 1.5, 3.5, 3.0)?;
    println!("generating linkage: {fb:?}");

    // ---- Four poses ----------------------------------------------------
    let poses4: Vec<Pose> = [20.0, 70.0, 120.0, 170.0]
        .iter()
        .map(|&d| pose(&fb, d))
        .collect::<Result<_, _>>()?;
    let task4 = Task::new(&poses4)?;
    let four = FourPositions::new(&poses4)?;
    let curve = four.center_point_curve();
    println!(
        "four poses: center-point curve of degree {}, circular: {}",
        curve.degree(),
        curve.is_circular()
    );
    // Both fixed pivots of the generating linkage lie on the curve ...
    let driving = four.dyad_from_center(Point2::new(0.0, 0.0))?;
    let driven = four.dyad_from_center(Point2::new(4.0, 0.0))?;
    println!("dyads: driving {driving:?}, driven {driven:?}");
    // ... and the linkage built from them is the generating one.
    let linkage = task4.four_bar(&driving, &driven)?;
    let [g, c, cp, r] = linkage.fourbar.lengths();
    println!("their linkage: ground {g:.6}, crank {c:.6}, coupler {cp:.6}, rocker {r:.6}");
    assert!((g - 4.0).abs() < 1e-9 && (c - 1.5).abs() < 1e-9);
    assert!((cp - 3.5).abs() < 1e-9 && (r - 3.0).abs() < 1e-9);
    assert!(linkage.figures.branch_free());

    // The pair map: every (driving, driven) pair of dyads along the curve,
    // with the three-pose solution map's figures, and its best pairs.
    let pairs = task4.pair_map(200, 200, &MapOptions::default(), &Control::new())?;
    let n_ok = pairs.columns.acceptable.iter().filter(|&&b| b).count();
    println!("pair map 200 x 200: {n_ok} acceptable pairs");
    for (k, p) in pairs
        .best_pairs(Ranking::new(3, RankBy::Balanced))?
        .iter()
        .enumerate()
    {
        let f = &p.linkage.figures;
        println!(
            "#{}: A0 = ({:.3}, {:.3}), C0 = ({:.3}, {:.3}), {:?}, min transmission {:.1} deg",
            k + 1,
            p.driving.center.x,
            p.driving.center.y,
            p.driven.center.x,
            p.driven.center.y,
            f.grashof,
            f.min_transmission.to_degrees()
        );
        assert!(f.feasible() && f.branch_free());
    }

    // ---- Five poses ----------------------------------------------------
    let poses5: Vec<Pose> = [20.0, 70.0, 120.0, 170.0, 230.0]
        .iter()
        .map(|&d| pose(&fb, d))
        .collect::<Result<_, _>>()?;
    let five = FivePositions::new(&poses5)?;
    println!(
        "five poses: {} Burmester points",
        five.burmester_points().len()
    );
    for (k, d) in five.burmester_points().iter().enumerate() {
        println!(
            "  B{}: center ({:.6}, {:.6}), crank length {:.6}",
            k + 1,
            tidy(d.center.x),
            tidy(d.center.y),
            d.length()
        );
    }
    let centers: Vec<Point2<f64>> = five.burmester_points().iter().map(|d| d.center).collect();
    assert!(centers.iter().any(|&p| near(p, [0.0, 0.0])));
    assert!(centers.iter().any(|&p| near(p, [4.0, 0.0])));
    for b in five.four_bars() {
        for (which, drive) in b.drives.iter().enumerate() {
            let [i, j] = if which == 0 {
                b.indices
            } else {
                [b.indices[1], b.indices[0]]
            };
            println!(
                "  B{} drives B{}: {:?}, branch-free: {}, crank order {}",
                i + 1,
                j + 1,
                drive.grashof(),
                drive.is_branch_free(),
                drive.order
            );
        }
    }
    Ok(())
}
