//! `Debug` of the public types shows what a designer knows (lengths,
//! pivots, poses, poles, modes, counts), not the normalized or cached
//! quantities kept inside, and never every value of a map.

use burmester::synthesis::{FivePositions, FourPositions};
use burmester::{
    AssemblyMode, DesignLimits, FourBar, Grid, Point2, Pose, RankBy, Ranking, Task, Viewport,
};
mod common;

/// `value`'s debug text contains `want` and no internals.
fn shows(value: &impl std::fmt::Debug, want: &str) {
    let text = format!("{value:?}");
    assert!(text.contains(want), "{text}");
    no_internals(&text);
}

fn no_internals(text: &str) {
    for inner in [
        "c_n",
        "sum_n",
        "diff_n",
        "sq_diff_n",
        "g_vec",
        "scale",
        "origin",
        "three:",
        "maps",
        "special",
        "n_special",
        "known",
        "half12",
        "q13",
        "rot:",
        "shift",
        "compat",
        "seq:",
    ] {
        assert!(!text.contains(inner), "`{inner}` in {text}");
    }
}

#[test]
fn fourbar_shows_lengths_pivots_and_grashof() {
    let fb =
        FourBar::from_pivots(Point2::new(1.0, 2.0), Point2::new(5.0, 2.0), 1.5, 3.5, 3.0).unwrap();
    let text = format!("{fb:?}");
    assert_eq!(
        text,
        "FourBar { ground: 4.0, crank: 1.5, coupler: 3.5, rocker: 3.0, input_pivot: [1.0, 2.0], \
         output_pivot: [5.0, 2.0], grashof: CrankRocker }"
    );
    no_internals(&format!("{fb:#?}"));
}

#[test]
fn task_filemon_and_maps_show_what_they_are_for() {
    let task = Task::from_xya(&[[0.0, 0.0, 0.0], [2.0, 0.5, 0.4], [3.0, 2.0, 1.1]]).unwrap();
    let text = format!("{task:?}");
    assert!(
        text.starts_with("Task { poses: [Pose { position: [0.0, 0.0], angle: 0.0 }"),
        "{text}"
    );
    assert!(text.contains("poles: [Finite("), "{text}");
    no_internals(&text);

    let filemon = task.filemon(Point2::new(4.0, -1.0)).unwrap();
    let text = format!("{filemon:?}");
    assert!(
        text.contains("driven: Revolute(Dyad { center: [4.0, -1.0]"),
        "{text}"
    );
    assert!(
        text.contains("kind: Hyperbola") && text.contains("kind: Ellipse"),
        "{text}"
    );
    no_internals(&text);

    let grid = Grid::new(Viewport::new(-8.0, 8.0, -8.0, 8.0).unwrap(), 64, 48).unwrap();
    assert_eq!(
        format!("{grid:?}"),
        "Grid { viewport: Viewport { xmin: -8.0, xmax: 8.0, ymin: -8.0, ymax: 8.0 }, nx: 64, ny: 48 }"
    );
    let map = common::solution_map(&filemon, &grid, &DesignLimits::default());
    let text = format!("{map:?}");
    let acceptable = map.columns.acceptable.iter().filter(|&&b| b).count();
    assert!(text.contains(&format!("samples: {}", 64 * 48)), "{text}");
    assert!(
        text.contains(&format!("acceptable: {acceptable}")),
        "{text}"
    );
    // A summary, not the 3072 values of each column.
    assert!(text.len() < 2000, "{} characters", text.len());
    no_internals(&text);

    let best = map.best_pivots(Ranking::new(1, RankBy::Balanced)).unwrap();
    let text = format!("{:?}", best[0].linkage);
    assert!(text.contains("fourbar: FourBar { ground: "), "{text}");
    assert!(text.contains("modes: ["), "{text}");
    no_internals(&text);
}

#[test]
fn curves_show_poses_curves_and_points() {
    let fb = FourBar::from_pivots(Point2::origin(), Point2::new(4.0, 0.0), 1.5, 3.5, 3.0).unwrap();
    let pose = |deg: f64| {
        let j = fb
            .joints_at(f64::to_radians(deg), AssemblyMode::Open)
            .unwrap();
        let phi = (j.rocker_joint.y - j.crank_joint.y).atan2(j.rocker_joint.x - j.crank_joint.x);
        Pose::new(j.crank_joint.x, j.crank_joint.y, phi)
    };
    let four: Vec<Pose> = [20.0, 70.0, 120.0, 170.0].map(pose).to_vec();
    let curves = FourPositions::new(&four).unwrap();
    shows(
        &curves,
        "center_point_curve: Cubic { degree: 3, coefficients: [",
    );
    let dyad = curves.curve_dyad(Point2::origin()).unwrap();
    let text = format!("{dyad:?}");
    assert!(text.contains("CrankOrder(1-2-3-4)"), "{text}");

    let five: Vec<Pose> = [20.0, 70.0, 120.0, 170.0, 230.0].map(pose).to_vec();
    let points = FivePositions::new(&five).unwrap();
    shows(&points, "burmester_points: [Dyad { center: ");
}
