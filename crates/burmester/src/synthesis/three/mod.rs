//! Three-position synthesis: the Cremona map between the planes, Filemon's
//! construction and its exact transform into the driving crank's
//! center-point plane, and the dense branch sweep.
//!
//! A task whose three poles are finite runs the maps through its poles
//! ([`Cremona`]); a task with a pure translation between two poses (a pole
//! at infinity) runs them by the linear form, which needs no pole (see the
//! `linear` module). Everything above the maps (Filemon's construction,
//! the branch maps, the solution maps) goes through `Maps` and works for
//! both.

mod cremona;
mod filemon;
mod linear;
mod slider;
mod sweep;

use nalgebra::{Point2, Vector2};

pub use cremona::Cremona;
pub use filemon::{Filemon, Method};
pub(crate) use linear::Linear;
pub(crate) use slider::SliderLocus;
pub(crate) use sweep::BranchRows;

use crate::Result;
use crate::error::{InvalidInput, finite_point};
use crate::geom::{Conic, LocalFrame};

/// A point passed to a map, in the map's local frame: finite (its
/// coordinates named by `names`) and representable there (else
/// [`InvalidInput::Overflow`] with `hint`).
fn local_input(
    frame: &impl LocalFrame,
    names: [&'static str; 2],
    p: Point2<f64>,
    hint: &'static str,
) -> Result<Vector2<f64>> {
    finite_point(names, p)?;
    let y = frame.local_of(p);
    if !(y.x.is_finite() && y.y.is_finite()) {
        return Err(InvalidInput::Overflow {
            what: "the point in the task's frame",
            hint,
        }
        .into());
    }
    Ok(y)
}

/// The three-position maps of a task: through the poles, or by the linear
/// form when a pole is at infinity.
// One per task, copied with it (a task is `Copy`): no box for the larger.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Maps {
    /// Three finite poles: Borm & Kim's closed form.
    Poles(Cremona),
    /// A pole at infinity: the linear form.
    Linear(Linear),
}

impl Maps {
    /// The circle point of a center point.
    pub(crate) fn circle_point(&self, center: Point2<f64>) -> Result<Point2<f64>> {
        match self {
            Maps::Poles(c) => c.circle_point(center),
            Maps::Linear(l) => l.circle_point(center),
        }
    }

    /// The center point of a circle point.
    pub(crate) fn center_point(&self, circle: Point2<f64>) -> Result<Point2<f64>> {
        match self {
            Maps::Poles(c) => c.center_point(circle),
            Maps::Linear(l) => l.center_point(circle),
        }
    }

    /// The circle point of a center point, unchecked (the hot path).
    #[inline(always)]
    pub(crate) fn circle_point_fast(&self, center: Point2<f64>) -> Option<Point2<f64>> {
        match self {
            Maps::Poles(c) => c.circle_point_fast(center),
            Maps::Linear(l) => l.circle_point_fast(center),
        }
    }

    /// The exact transform of the line through `c1` with the finite,
    /// non-zero direction `d`.
    pub(crate) fn line_conic(&self, c1: Point2<f64>, d: Vector2<f64>) -> Conic {
        match self {
            Maps::Poles(c) => filemon::line_conic(c, c1, d),
            Maps::Linear(l) => l.line_conic(c1, d),
        }
    }

    /// `[P12, P13, P23]`, `None` for a pole at infinity.
    pub(crate) fn poles(&self) -> [Option<Point2<f64>>; 3] {
        match self {
            Maps::Poles(c) => c.poles().map(Some),
            Maps::Linear(l) => l.poles(),
        }
    }
}
