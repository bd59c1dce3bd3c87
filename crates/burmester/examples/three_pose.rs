//! Three-position synthesis from Rust, the way a designer works: the task
//! (three poses of a lid's front edge, in millimetres), the driven crank's
//! fixed pivot, the solution map over every candidate driving pivot, the
//! best pivot, and the linkage's figures, checked by driving it through the
//! poses.
//!
//! ```sh
//! cargo run --release -p burmester --example three_pose
//! ```

use burmester::{
    AssemblyMode, Constraints, Control, DesignLimits, Grid, InputRequirement, MapOptions, Point2,
    RankBy, Ranking, Task, Viewport,
};

fn main() -> Result<(), burmester::Error> {
    // 1. The task: where the coupler point is (x, y in mm) and the coupler's
    //    angle at each pose (radians in the API; degrees are easier to read).
    let task = Task::from_xya(&[
        [0.0, 0.0, 0f64.to_radians()],
        [60.0, 55.0, 40f64.to_radians()],
        [90.0, 140.0, 85f64.to_radians()],
    ])?;
    println!("{task:?}");
    println!(
        "task size (largest distance between two poses): {:.1} mm",
        task.span()
    );

    // 2. The driven crank's fixed pivot C0 (a hinge on the frame), and
    //    Filemon's construction for it: the driving pivots A0 that would
    //    pass the poses in two assembly modes (the branch problem) lie on
    //    the other side of two conics.
    let filemon = task.filemon(Point2::new(-60.0, -40.0))?;
    let kinds: Vec<_> = filemon
        .conics()
        .into_iter()
        .flatten()
        .map(|c| c.kind())
        .collect();
    println!("Filemon's lines in the center-point plane: {kinds:?}");

    // 3. The solution map: every candidate A0 on a 400 x 400 grid over a
    //    500 mm square, with its Grashof type, order and circuit, minimum
    //    transmission angle over the whole travel, link ratio and size,
    //    judged against the limits. `Control` takes a progress hook and a
    //    cancel flag (`with_progress`, `with_cancel`).
    let grid = Grid::new(Viewport::new(-250.0, 250.0, -250.0, 250.0)?, 400, 400)?;
    let limits = DesignLimits::from_degrees(40.0, 10.0, InputRequirement::Any)?;
    let map = filemon.solution_map(
        &grid,
        &MapOptions::new(&limits, &Constraints::default())?,
        &Control::new(),
    )?;
    let share =
        |column: &[bool]| 100.0 * column.iter().filter(|&&b| b).count() as f64 / grid.len() as f64;
    println!(
        "solution map {} x {}: {:.1}% branch-free, {:.2}% acceptable",
        grid.nx(),
        grid.ny(),
        share(&map.columns.branch_free),
        share(&map.columns.acceptable)
    );

    // 4. The best pivots by the balanced score (force transmission, a small
    //    linkage and even links together), kept apart from each other.
    let best = map.best_pivots(Ranking::new(3, RankBy::Balanced))?;
    for (k, p) in best.iter().enumerate() {
        let f = &p.linkage.figures;
        println!(
            "#{}: A0 = ({:.1}, {:.1}) mm, {:?}, min transmission {:.1} deg, size {:.1} x the task",
            k + 1,
            p.center.x,
            p.center.y,
            f.grashof,
            f.min_transmission.to_degrees(),
            p.size_ratio
        );
    }
    let Some(pivot) = best.first() else {
        eprintln!("no acceptable driving pivot in the view: widen it or relax the limits");
        std::process::exit(1);
    };

    // 5. The linkage of the best pivot: what a designer builds.
    let linkage = pivot.linkage;
    println!("{:#?}", linkage.fourbar);
    println!("{:?}", linkage.figures);

    // 6. Check it: driven to its input angle at each pose, in the pose's
    //    assembly mode, the coupler carries the coupler point to the pose.
    for (k, (&theta2, mode)) in linkage
        .input_angles
        .iter()
        .zip(linkage.modes().iter())
        .enumerate()
    {
        let mode = mode.unwrap_or(AssemblyMode::Open);
        let at = linkage.pose_at(theta2, mode)?;
        let want = task.poses()[k];
        let miss = (at.position - want.position).norm();
        let turn = (at.angle - want.angle).sin().abs();
        println!(
            "pose {}: input {:7.2} deg, {:?}, coupler point {:.2e} mm from the pose",
            k + 1,
            theta2.to_degrees(),
            mode,
            miss
        );
        assert!(
            miss < 1e-9 * task.span(),
            "pose {} missed by {miss} mm",
            k + 1
        );
        assert!(turn < 1e-9, "pose {} turned {turn} rad off", k + 1);
    }
    Ok(())
}
