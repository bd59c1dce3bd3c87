//! Every error of the four- and five-position modules, built here and only
//! here, so that the variants can be swapped for dedicated ones in one
//! place.

// Comparisons are written `!(a > b)` on purpose: a NaN takes the failing
// branch.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use nalgebra::{Point2, Vector2};

use crate::error::{DegenerateError, Error, InvalidInput};
use crate::tolerance;

/// A slice of poses of the wrong length for a method that needs `required`.
pub(crate) fn pose_count(method: &'static str, required: usize, found: usize) -> Error {
    InvalidInput::NeedsPoses {
        method,
        required,
        found,
    }
    .into()
}

/// A number that is NaN or infinite.
pub(crate) fn not_finite(name: &'static str, value: f64) -> Error {
    InvalidInput::NotFinite { name, value }.into()
}

/// A 1-based pose index out of range.
pub(crate) fn pose_index(index: usize, count: usize) -> Error {
    InvalidInput::PoseIndex { index, count }.into()
}

/// A task smaller than [`Task::MIN_SCALE`](crate::Task::MIN_SCALE).
pub(crate) fn too_small(value: f64, limit: f64) -> Error {
    InvalidInput::TooSmall {
        name: "the task's size",
        value,
        limit,
        hint: "rescale the task (the curves are invariant under scaling)",
    }
    .into()
}

/// A point so far from the task that its coordinates in the task's frame
/// overflow.
pub(crate) fn far_point() -> Error {
    InvalidInput::Overflow {
        what: "the point in the task's frame",
        hint: "pass a point within about 1e300 task sizes of the poses",
    }
    .into()
}

/// A count out of its range.
pub(crate) fn count(name: &'static str, value: usize, min: usize, max: usize) -> Error {
    InvalidInput::CountOutOfRange {
        name,
        value,
        min,
        max,
    }
    .into()
}

/// A point that is not on the curve it must lie on: `distance` is its
/// first-order distance from the curve, `tolerance` the largest accepted.
pub(crate) fn off_curve(what: &'static str, distance: f64, tolerance: f64) -> Error {
    InvalidInput::OffCurve {
        what,
        distance,
        tolerance,
    }
    .into()
}

/// A dyad that does not pass every pose.
pub(crate) fn not_a_dyad(which: &'static str, spread: f64) -> Error {
    InvalidInput::NotADyad {
        which,
        spread,
        tolerance: tolerance::DYAD,
    }
    .into()
}

/// Two equal poses.
pub(crate) fn coincident_poses(i: usize, j: usize) -> Error {
    DegenerateError::CoincidentPoses { i, j }.into()
}

/// Poses that are rotations about one point: every dyad is centered there.
pub(crate) fn common_pole(p: Point2<f64>) -> Error {
    DegenerateError::CoincidentPoles { x: p.x, y: p.y }.into()
}

/// A map whose answer lies at infinity, in the direction `dir`.
pub(crate) fn at_infinity(
    what: &'static str,
    curve: &'static str,
    p: Point2<f64>,
    dir: Vector2<f64>,
) -> Error {
    DegenerateError::AtInfinity {
        what,
        curve,
        x: p.x,
        y: p.y,
        dir_x: dir.x,
        dir_y: dir.y,
    }
    .into()
}

/// A map with a whole line of answers at `p`.
pub(crate) fn undefined(what: &'static str, at: &'static str, p: Point2<f64>) -> Error {
    DegenerateError::Undefined {
        what,
        at,
        x: p.x,
        y: p.y,
    }
    .into()
}

/// A link of zero length.
pub(crate) fn zero_length(what: &'static str, p: Point2<f64>) -> Error {
    DegenerateError::ZeroLengthLink {
        what,
        x: p.x,
        y: p.y,
    }
    .into()
}

/// The compatibility linkage of the poses has a link of zero length, so
/// the crank rotation does not parametrize the curve.
pub(crate) fn no_parametrization() -> Error {
    DegenerateError::NotParametrizable.into()
}

/// A crank rotation whose dyad has its center point at infinity.
pub(crate) fn dyad_at_infinity(beta2: f64) -> Error {
    DegenerateError::SliderDyad { beta2 }.into()
}

/// Poses that all have one angle: the motion is a pure translation.
pub(crate) fn all_translations() -> Error {
    DegenerateError::AllTranslations.into()
}

/// A driven dyad whose fixed pivot's images coincide with its circle point.
pub(crate) fn bad_driven() -> Error {
    InvalidInput::Overflow {
        what: "a direction C'k - C1 of Filemon's construction",
        hint: "the driven pivot's images C'k = D_k1(C0) must be finite and apart from its \
               circle point C1: choose a driven center point nearer the task",
    }
    .into()
}

/// Three of five poses are rotations about one point `p` (1-based poses).
pub(crate) fn rotations_about_one_point(poses: [usize; 3], p: Point2<f64>) -> Error {
    let [i, j, k] = poses;
    DegenerateError::RotationsAboutOnePoint {
        i,
        j,
        k,
        x: p.x,
        y: p.y,
    }
    .into()
}

/// Three of five poses with one angle and collinear positions (1-based).
pub(crate) fn collinear_translations(poses: [usize; 3]) -> Error {
    let [i, j, k] = poses;
    DegenerateError::CollinearTranslations { i, j, k }.into()
}

/// Five poses whose Burmester points are not isolated.
pub(crate) fn infinitely_many(what: &'static str) -> Error {
    DegenerateError::InfinitelyManyBurmesterPoints { what }.into()
}

/// Five poses whose Burmester points the elimination does not resolve.
pub(crate) fn unresolved(what: &'static str) -> Error {
    DegenerateError::UnresolvedBurmesterPoints { what }.into()
}
