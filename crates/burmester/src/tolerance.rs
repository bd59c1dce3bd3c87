//! Tolerances: every decision the crate takes within rounding, named,
//! documented, and used from here only.
//!
//! Lengths are relative: "in task sizes" means in units of
//! [`Task::scale`](crate::Task::scale), "relative" means in units of the
//! size of the quantities compared. Factors named `*_EPS` multiply
//! `f64::EPSILON`. The README's table of tolerance bands lists them with
//! what each decides. Where a user may want another value the function
//! takes it as a parameter, with its default documented there.

/// A point within this distance (in task sizes) of a pole, an image pole or
/// the driven pivot `C0` lies "at" it: maps are undefined there and every
/// transformed Filemon curve passes through it, so it is never branch-free.
pub const POINT: f64 = 1e-12;

/// Two poses whose angles agree within this many radians (modulo `2 pi`)
/// differ by a pure translation: their pole is at infinity. Above the
/// bound the three-position maps run through the poles and keep a relative
/// accuracy of a few `eps / theta` near the poses, about `1e-9` at this
/// bound; at or below it they run by the linear form with the poses' own
/// angles (no pole, no division by `theta`), so the maps change by `O(theta)`
/// across the bound.
pub const MIN_ROTATION: f64 = 1e-6;

/// Factor of `f64::EPSILON` for the position analysis' rounding decisions,
/// relative to the size of the quantities compared: a toggle (Heron's
/// product `H` within `8 eps` of zero), the Grashof equality
/// `s + l = p + q`, a loop that just closes, and an input range that just
/// turns fully.
pub const ROUNDING_EPS: f64 = 8.0;

/// Factor of `f64::EPSILON` within which a cross product of two vectors,
/// relative to the product of their lengths, is zero: an answer of a
/// three-position map at infinity (its denominator).
pub const CROSS_EPS: f64 = 16.0;

/// The one toggle criterion, `sqrt(ROUNDING_EPS eps)`: a loop with coupler
/// `L3`, rocker `L4` and crank tip to output pivot `r` is at a toggle where
/// its transmission angle `mu` has
/// `|sin mu| <= TOGGLE_BAND ((L3 + L4)^2 + r^2) / (2 L3 L4)` (about `1e-7`
/// rad when `L3` and `L4` are alike). It is Heron's product within
/// [`ROUNDING_EPS`] of zero, restated in angle terms; both
/// [`FourBar::solve`](crate::FourBar::solve) and the mode of a built linkage
/// at a pose ([`AssemblyMode::of_loop`](crate::AssemblyMode::of_loop)) use it.
pub const TOGGLE_BAND: f64 = 4.214_684_851_089_403_5e-8;

/// Relative tolerance of "collinear": three points whose doubled triangle
/// area is within this fraction of the longest side squared lie on a line
/// (a pole circle becomes a line, an obstacle has no area).
pub const COLLINEAR: f64 = 1e-12;

/// Relative tolerance of the conic kind tests: a discriminant `B^2 - 4AC`
/// or a determinant within this fraction of its terms is zero (parabola,
/// degenerate conic).
pub const CONIC_KIND: f64 = 1e-12;

/// A dyad passed to a task is its dyad when its moving pivot's distances to
/// its fixed pivot over the poses agree within this fraction of the dyad's
/// length plus the task's size.
pub const DYAD: f64 = 1e-9;

/// The `simulate` classifier reaches a pose when the driven coupler lands
/// within this many task sizes of its position and this many radians of
/// its angle.
pub const REACH: f64 = 1e-7;

/// Two candidates of a ranking whose scores (radians of transmission angle)
/// agree within this are tied, and go by their margin.
pub const RANK_TIE: f64 = 1e-9;

/// Factor of `f64::EPSILON` of the rounding band of the branch sweep: along
/// a row, a sample farther than this times the row's magnitude (over the
/// slope) from a root of a conic has the root-free sign.
pub const SWEEP_BAND_EPS: f64 = 64.0;

// Four and five poses: the Burmester curves and points (issue 24).

/// Factor of `f64::EPSILON` of the rounding band of a Burmester curve (the
/// center-point or circle-point cubic of four poses) at a point: a point
/// is on the curve when the curve's value there is within this many `eps`
/// of the bound on its terms, `sum (|c_ij| + m_ij) |x|^i |y|^j`, where
/// `m_ij` is the coefficient's own rounding scale (the exact expansion of
/// the determinant from the poses with every number in magnitude). Over the
/// gradient this is a distance: the curve's position is known only to
/// within it, which near a nearly singular point of a curve of nearly equal
/// rotations is thousands of times the rounding of the coefficients'
/// largest. The points the library computes on the curves (the traced
/// vertices, the crank-rotation dyads, the arc ends, the Burmester points)
/// are within about a fifth of this band.
pub const ON_CURVE_EPS: f64 = 64.0;

/// Factor of `f64::EPSILON` of the rounding band of the elimination of the
/// Burmester points of five poses: a value of the resultant (or of one of
/// the forms it is made of) within this many `eps` of the bound on its
/// terms (the same computation in magnitudes, with the rounding scales of
/// the curves' coefficients and of the pole they are taken from) is zero.
/// A critical point of the resultant where it is zero so is a double root:
/// two Burmester points that merge, or a pair of complex ones, within
/// rounding (a double point, listed twice). Where the whole resultant is
/// zero so for every choice of the shared poses, the points are not
/// isolated. A center farther than `1 / (BURMESTER_EPS eps)` task sizes
/// (about `3e14`), where its rounding is of its own size, is at infinity
/// (a slider).
pub const BURMESTER_EPS: f64 = 16.0;

/// Three poses whose three poles agree within this many task sizes (plus
/// the poles' distance from the task) are rotations about one point: the
/// Burmester points of five poses with them are not isolated.
pub const BURMESTER_COMMON_POLE: f64 = 1e-9;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn toggle_band_is_the_root_of_the_heron_band() {
        assert_eq!(TOGGLE_BAND, (ROUNDING_EPS * f64::EPSILON).sqrt());
    }
}
