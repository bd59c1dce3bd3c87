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
//! # Example
//!
//! ```
//! use burmester::{AssemblyMode, FourBar, Grashof};
//! let fb = FourBar::new(4.0, 1.0, 3.0, 3.0)?;
//! assert_eq!(fb.grashof(), Grashof::CrankRocker);
//! let c = fb.solve(60f64.to_radians(), AssemblyMode::Open)?;
//! assert!((c.theta3.to_degrees() - 39.165923859).abs() < 1e-8);
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

pub use design::{
    AtlasBest, AtlasCell, Constraints, DesignLimits, InputRequirement, MapContext, Pair,
    PairContext, PairMap, Pivot, PivotAtlas, RankBy, SolutionMap, Varying,
};
pub use engine::Control;
pub use error::{AssemblyError, DegenerateError, DriveError, Error, InvalidInput, Result};
pub use geom::{CircleOrLine, Conic, ConicKind, Grid, Line, PerPose, Pose, Similarity, Viewport};
pub use linkage::{
    AngleInterval, AssemblyMode, Configuration, Direction, FourBar, Grashof, InputRange, Joints,
    LinkageFigures,
};
pub use linkage::{LimitPosition, SixBar, SixBarConfiguration, SixBarJoints, SixBarLengths};
pub use nalgebra::{Point2, Vector2};
pub use synthesis::three::{Cremona, Filemon, Method};
pub use synthesis::{Branch, Dyad, FilemonLines, Motion, Pole, SynthesizedFourBar, Task};

/// The README's Rust examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
struct ReadmeDoctests;
