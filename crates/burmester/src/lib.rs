//! # burmester
//!
//! Planar four-bar linkages for mechanism designers: position analysis,
//! three-position Burmester synthesis, and the exact elimination of the
//! branch problem in the driving crank's center-point plane (Borm & Kim).
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

pub mod conic;
pub mod design;
pub mod dyad;
pub mod error;
pub mod example;
pub mod filemon;
pub mod fourbar;
mod geom;
pub mod sweep;
pub mod task;

pub use conic::{Conic, ConicKind, Line, Viewport};
pub use design::{
    Constraints, DesignLimits, InputRequirement, LinkageFigures, MapContext, Pivot, SolutionMap,
    Varying,
};
pub use dyad::{Dyad, SynthesizedFourBar};
pub use error::{AssemblyError, DegenerateError, Error, InvalidInput, Result};
pub use filemon::{Branch, Filemon, Method};
pub use fourbar::{
    AngleInterval, AssemblyMode, Configuration, FourBar, Grashof, InputRange, Joints,
};
pub use nalgebra::{Point2, Vector2};
pub use sweep::Grid;
pub use task::{CircleOrLine, Pose, Similarity, Task};

/// The README's Rust examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
struct ReadmeDoctests;
