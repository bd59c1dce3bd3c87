//! # burmester
//!
//! Planar four-bar linkages for mechanism designers: position analysis,
//! Burmester synthesis, and the exact elimination of the branch problem in
//! the driving crank's center-point plane (Borm & Kim).
//!
//! # Layout
//!
//! Each module imports only from those above it:
//!
//! * [`geom`]: plane geometry (poses, lines and circles, conics, viewports
//!   and grids, per-pose values).
//! * [`linkage`]: the four-bar: position analysis, Grashof type and input
//!   range, the one assembly-mode test, and the figures a designer checks.
//! * [`synthesis`]: the task (three to five poses), its motion
//!   (displacements, poles), dyads and the four-bar built from two,
//!   Filemon's construction in the circle-point plane, and
//!   [`synthesis::three`]: the three-position maps, Filemon's conics and the
//!   branch sweep.
//! * [`design`]: limits, constraints, the solution-space map and ranking.
//! * [`engine`]: the tiled parallel engine with progress and cancellation;
//!   [`tolerance`]: every rounding decision, named; [`error`]: the errors.
//!
//! # Conventions
//!
//! Points are [`Point2<f64>`](nalgebra::Point2), directions
//! [`Vector2<f64>`](nalgebra::Vector2); in formulas a point is read as the
//! complex number `z = x + iy`. Angles are counter-clockwise positive, in
//! radians, and absolute (measured from the fixed +x axis).
//!
//! ```text
//! cross(u, v) = u.x v.y - u.y v.x = Im(conj(u) v)
//! ```
//!
//! # Errors
//!
//! Every fallible function returns [`Error`](enum@Error); bad input never panics and no
//! NaN is handed back without a flag saying so. See [`error`].
//!
//! # Example: position analysis
//!
//! ```
//! use burmester::{AssemblyMode, FourBar, Grashof};
//! let fb = FourBar::new(4.0, 1.0, 3.0, 3.0)?;
//! assert_eq!(fb.grashof(), Grashof::CrankRocker);
//! let c = fb.solve(60f64.to_radians(), AssemblyMode::Open)?;
//! assert!((c.theta3.to_degrees() - 39.165923859).abs() < 1e-8);
//! # Ok::<(), burmester::Error>(())
//! ```
//!
//! # Example: three poses, from the task to the linkage
//!
//! The designer's path: three poses of the coupler (here a lid's front
//! edge, in millimetres), the driven crank's fixed pivot `C0`, the
//! solution map over every candidate driving pivot `A0` (branch-free,
//! Grashof type, order and circuit, transmission over the whole travel,
//! size, judged against the limits), the best pivot, and its linkage,
//! checked by driving it through the poses. `examples/three_pose.rs` is
//! the same with printing (`cargo run -p burmester --example three_pose`).
//!
//! ```
//! use burmester::{
//!     AssemblyMode, Constraints, Control, DesignLimits, Grid, InputRequirement, MapOptions,
//!     Point2, RankBy, Ranking, Task, Viewport,
//! };
//! // x, y (mm) and the coupler's angle (radians) at each pose.
//! let task = Task::from_xya(&[
//!     [0.0, 0.0, 0f64.to_radians()],
//!     [60.0, 55.0, 40f64.to_radians()],
//!     [90.0, 140.0, 85f64.to_radians()],
//! ])?;
//! let filemon = task.filemon(Point2::new(-60.0, -40.0))?; // the driven crank's C0
//! let grid = Grid::new(Viewport::new(-250.0, 250.0, -250.0, 250.0)?, 200, 200)?;
//! let limits = DesignLimits::from_degrees(40.0, 10.0, InputRequirement::Any)?;
//! // The limits and constraints checked once, for any number of maps.
//! let options = MapOptions::new(&limits, &Constraints::default())?;
//! let map = filemon.solution_map(&grid, &options, &Control::new())?;
//! let best = map.best_pivots(Ranking::new(3, RankBy::Balanced))?;
//! let linkage = best[0].linkage; // a SynthesizedFourBar: lengths, pivots, figures
//! assert!(linkage.figures.min_transmission.to_degrees() >= 40.0);
//! assert!(linkage.is_branch_free());
//! println!("A0 = {:?}: {:?}", best[0].center, linkage.fourbar); // lengths, pivots, Grashof type
//! for (k, &theta2) in linkage.input_angles.iter().enumerate() {
//!     let mode = linkage.modes()[k].unwrap_or(AssemblyMode::Open);
//!     let pose = linkage.pose_at(theta2, mode)?;
//!     assert!((pose.position - task.poses()[k].position).norm() < 1e-9);
//! }
//! # Ok::<(), burmester::Error>(())
//! ```
//!
//! # Example: four and five poses
//!
//! Four poses leave a curve of center points (a circular cubic) and a
//! plane of linkages (the pair map); five leave finitely many Burmester
//! points. The poses here come from a known crank-rocker with fixed
//! pivots `(0, 0)` and `(4, 0)`, so both come back
//! (`examples/four_five_pose.rs` prints the whole of it).
//!
//! ```
//! use burmester::synthesis::{FivePositions, FourPositions};
//! use burmester::{AssemblyMode, FourBar, Point2, Pose, Task};
//! let fb = FourBar::from_pivots(Point2::origin(), Point2::new(4.0, 0.0), 1.5, 3.5, 3.0)?;
//! let pose = |deg: f64| -> burmester::Result<Pose> {
//!     // The coupler point (1, 1.5) in the frame at the crank joint, x toward the rocker joint.
//!     let j = fb.joints_at(deg.to_radians(), AssemblyMode::Open)?;
//!     let phi = (j.rocker_joint.y - j.crank_joint.y).atan2(j.rocker_joint.x - j.crank_joint.x);
//!     let (s, c) = phi.sin_cos();
//!     Ok(Pose::new(j.crank_joint.x + c - 1.5 * s, j.crank_joint.y + s + 1.5 * c, phi))
//! };
//! let four: Vec<Pose> = [20.0, 70.0, 120.0, 170.0].map(pose).into_iter().collect::<Result<_, _>>()?;
//! let curves = FourPositions::new(&four)?;
//! assert!(curves.center_point_curve().is_circular());
//! let (a, b) = (curves.dyad_from_center(Point2::origin())?, curves.dyad_from_center(Point2::new(4.0, 0.0))?);
//! let linkage = Task::new(&four)?.four_bar(&a, &b)?;
//! assert!((linkage.fourbar.coupler() - 3.5).abs() < 1e-9 && linkage.is_branch_free());
//!
//! let five: Vec<Pose> = [20.0, 70.0, 120.0, 170.0, 230.0].map(pose).into_iter().collect::<Result<_, _>>()?;
//! let points = FivePositions::new(&five)?;
//! let near = |x: f64, y: f64| points.burmester_points().iter().any(|d| (d.center - Point2::new(x, y)).norm() < 1e-6);
//! assert!(near(0.0, 0.0) && near(4.0, 0.0));
//! # Ok::<(), burmester::Error>(())
//! ```

pub mod design;
pub mod engine;
pub mod error;
pub mod example;
pub mod geom;
pub mod linkage;
pub(crate) mod simd;
pub mod synthesis;
pub mod tolerance;

pub use design::ActuatorSearch;
pub use design::{
    AtlasBest, AtlasCell, Constraints, DesignLimits, InputRequirement, MapContext, MapOptions,
    Pair, PairContext, PairMap, Pivot, PivotAtlas, RankBy, Ranking, SolutionMap, Varying,
};
pub use design::{
    Design, DesignOptions, DesignPlan, DesignReport, Limit, NearMiss, PivotRegion, SearchPoint,
    Space,
};
pub use design::{DesignedLinkage, DrivenKind};
pub use design::{PivotLinkage, SliderPivot};
pub use engine::Control;
pub use error::{AssemblyError, DegenerateError, DriveError, Error, InvalidInput, Result};
pub use geom::{CircleOrLine, Conic, ConicKind, Grid, Line, PerPose, Pose, Similarity, Viewport};
pub use linkage::{ActuatorLink, LinkPoint};
pub use linkage::{
    AngleInterval, AssemblyMode, Configuration, Direction, FourBar, Grashof, InputRange, Joints,
    LinkageFigures,
};
pub use linkage::{InvertedConfiguration, InvertedJoints, InvertedLimit, InvertedSliderCrank};
pub use linkage::{LimitPosition, SixBar, SixBarConfiguration, SixBarJoints, SixBarLengths};
pub use linkage::{SliderConfiguration, SliderCrank, SliderJoints, SliderLimit};
pub use nalgebra::{Point2, Vector2};
pub use synthesis::InvertedSlider;
pub use synthesis::SynthesizedInvertedSliderCrank;
pub use synthesis::SynthesizedSliderCrank;
pub use synthesis::three::{Cremona, Filemon, Method};
pub use synthesis::{
    Branch, Dyad, DyadKind, FilemonLines, Motion, Pole, SliderDyad, SynthesizedFourBar, Task,
};

/// The README's Rust examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
struct ReadmeDoctests;
