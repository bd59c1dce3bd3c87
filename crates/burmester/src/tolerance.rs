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
/// differ by a pure translation: their pole is at infinity (what needs
/// three finite poles, the pole triangle, is refused). The three-position
/// maps do not switch here: they run by the linear form with the poses' own
/// angles (no pole, no division by `theta`) wherever a pole lies farther
/// than [`POLE_DISTANCE`] spans from the poses, which includes every pole
/// at infinity, so they are the same maps on both sides of this bound.
pub const MIN_ROTATION: f64 = 1e-6;

/// The farthest the poles `P12` and `P13` may lie from pose 1's position,
/// in units of the task's span (the largest distance between two pose
/// positions), for a task of three poses to run its maps through the poles
/// (Borm & Kim's closed form, [`Cremona`](crate::Cremona)); farther, a
/// small rotation puts a pole far away and the closed form loses what it
/// cancels (its relative error grows like `eps / theta`, a factor of about
/// `0.5 / theta` over what rounding the input causes: `1e6` at `1e-6`
/// rad), so the maps run by the linear form, which needs no pole and keeps
/// the input's accuracy at every rotation (measured against mpmath from
/// `1e-9` to 1 rad). A pole `8` spans away is a rotation of about `0.12`
/// rad; the closed form is then within a factor of about `5` of the
/// input's rounding. The choice is by this conditioning, not by the
/// rotation alone; [`MIN_ROTATION`] still says where a pole is at infinity.
pub const POLE_DISTANCE: f64 = 8.0;

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

/// `sqrt(ROUNDING_EPS eps)`, the earlier toggle band's factor: Heron's
/// product within [`ROUNDING_EPS`] of `((L3 + L4)^2 + r^2)^2`, in angle
/// terms `|sin mu| <= TOGGLE_BAND ((L3 + L4)^2 + r^2) / (2 L3 L4)`. That
/// band grows like `L3 / L4` and called a 49 degree transmission angle a
/// toggle at a link ratio of `5e7`; the crate's one toggle criterion is now
/// [`heron_tolerance`] (whose band is about `1e-7` rad, like this one, when
/// `L3` and `L4` are alike). Kept as the scale of a toggle band for links
/// of one size.
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

/// The Burmester points of five poses computed with each pose in turn as
/// the reference pose must agree within this many times `size + d` (`d`
/// the point's distance from the poses' centroid), or the task is refused
/// as not resolved within rounding
/// ([`crate::synthesis::FivePositions::new`]). On ordinary tasks they
/// agree to `1e-12` or better; where the rounding decides the answer (a
/// task within rounding of a degenerate one) they differ by `1e-2` to `1`
/// (stop 39: fuzz inputs of `burmester_points`). Points whose rounding
/// moves them by more than this (ill-conditioned, near a double point) are
/// refused too.
pub const BURMESTER_AGREEMENT: f64 = 1e-4;

/// Factor of `f64::EPSILON` of the loop closure's rounding, in the crate's
/// one toggle criterion [`heron_tolerance`] (derived there). The measured
/// rounding of Heron's product stays below `0.6 eps` times the bound's
/// terms (2,000 positions near the dead positions of linkages with link
/// ratios from 1 to `1e9`, against mpmath at 300 bits), so this factor
/// leaves a margin of about 8: the computed toggle decision is the exact
/// one wherever `|sin mu|` lies outside `[band / 2, 2 band]`.
pub const LOOP_EPS: f64 = 4.0;

/// The one toggle criterion of the crate: the rounding band of Heron's
/// product of a loop closure. [`FourBar::solve`](crate::FourBar::solve)
/// reports a toggle (and accepts a loop that just fails to close) within
/// it, [`AssemblyMode::of_loop`](crate::AssemblyMode::of_loop) gives no
/// mode within it, and so the figures at a design pose, the three-pose
/// `simulate` classifier and the solution maps, which take their modes from
/// those two.
///
/// Arguments, in any one unit (the band is homogeneous of degree 4):
/// `sum2 = (L3 + L4)^2` and `diffsum = |L3^2 - L4^2| = |L3 - L4| (L3 + L4)`
/// of the coupler `L3` and the rocker `L4`, `r2 = r^2` with `r` the
/// distance from the crank tip `A` to the output pivot `O4`, `rho` the size
/// of the vectors `r` was formed from (`L1 + L2`, ground and crank, in the
/// position analysis), and Heron's two factors
/// `a = (L3 + L4)^2 - r^2` and `b = r^2 - (L3 - L4)^2` as the caller
/// computed them.
///
/// # Derivation
///
/// ```text
/// The loop closes where the crank tip A and the output pivot O4, at
/// distance r, can be joined by the coupler L3 and the rocker L4 meeting at
/// the rocker tip B: where Heron's product
///
///     H = A B,    A = (L3 + L4)^2 - r^2,    B = r^2 - (L3 - L4)^2
///
/// is not negative. With phi = theta4 - theta3 the angle from the coupler
/// to the rocker (the transmission angle mu has |sin mu| = |sin phi|),
///
///     A = 2 L3 L4 (1 + cos phi),   B = 2 L3 L4 (1 - cos phi),
///     H = 16 area(A B O4)^2 = (2 L3 L4 sin mu)^2,
///
/// so A = 0 at the extended toggle (r = L3 + L4) and B = 0 at the folded
/// one (r = |L3 - L4|). The position analysis forms d = O4 - A =
/// L1 e^{i theta1} - L2 e^{i theta2} from two vectors of lengths L1 and L2:
/// each component of d is off by up to about eps rho, rho = L1 + L2, so
/// r^2 = |d|^2 by up to about eps (2 sqrt(2) r rho + r^2). The lengths are
/// rounded to eps relative (scaled by the longest link), and A and B are
/// differences of squares:
///
///     err(A) <~ eps E_A,    E_A = (L3 + L4)^2 + r^2 + 2 r rho
///     err(B) <~ eps E_B,    E_B = |L3 - L4| (L3 + L4) + r^2 + 2 r rho
///     err(H) <~ |B| err(A) + |A| err(B) + err(A) err(B)
///
/// up to factors of a few, which LOOP_EPS covers (measured: below 0.6).
/// Where H is within that of zero, the rounding cannot tell the loop's two
/// modes apart, nor a loop that just closes from one that just does not.
/// The criterion: the loop is at a toggle where
///
///     |H| <= tol = k (|B| E_A + |A| E_B) + k^2 E_A E_B,    k = LOOP_EPS eps,
///
/// in angle terms, since sqrt(H) = 2 L3 L4 |sin mu|,
///
///     |sin mu| <= band = sqrt(tol) / (2 L3 L4).
///
/// At the extended and the folded toggle (A = 0, B = 4 L3 L4; B = 0,
/// A = 4 L3 L4) the band is
///
///     band = sqrt(LOOP_EPS eps E_A / (L3 L4)),   sqrt(LOOP_EPS eps E_B / (L3 L4)),
///
/// and between them it lies below the larger of the two. For four links
/// of one size that is about 1e-7 (the width of the earlier band
/// TOGGLE_BAND ((L3 + L4)^2 + r^2) / (2 L3 L4), which grew like L3 / L4);
/// it grows like the square root of the link ratio: for a long crank and
/// coupler (L2 ~ L3) on a short rocker, sqrt(4 LOOP_EPS eps L3 / L4) to
/// sqrt(6 LOOP_EPS eps L3 / L4) (short to long ground), the square root of
/// the rocker angle's rounding eps (L2 + L3) / L4 away from a toggle, about
/// 2e-3 at a link ratio of 1e9. A transmission angle of 3 degrees is a
/// toggle only beyond link ratios of about 5e11.
///
/// The mode of a built loop from its coupler and rocker vectors
/// (AssemblyMode::of_loop) tests 4 cross(u, w)^2 = H against the same tol,
/// with A = 2 (|u| |w| + u . w), B = 2 (|u| |w| - u . w), r = |u - w| and
/// rho the size of the vectors u and w came from.
/// ```
///
/// Returns `tol`; NaN input gives NaN (every comparison with it fails, so
/// a NaN loop is neither closed nor clear of a toggle).
#[inline(always)]
pub fn heron_tolerance(sum2: f64, diffsum: f64, r2: f64, rho: f64, a: f64, b: f64) -> f64 {
    let k = LOOP_EPS * f64::EPSILON;
    let r = r2.sqrt();
    let shared = r2 + 2.0 * r * rho;
    let ea = sum2 + shared;
    let eb = diffsum + shared;
    k * (b.abs() * ea + a.abs() * eb) + k * k * ea * eb
}

/// The toggle band of [`heron_tolerance`] in angle terms: a loop with
/// coupler `l3`, rocker `l4`, crank tip to output pivot `r` and `rho` the
/// size of the vectors `r` was formed from (`L1 + L2` in the position
/// analysis) is at a toggle where `|sin mu| <= toggle_band(l3, l4, r, rho)`
/// (`mu` the transmission angle). For tables, tests and messages; the
/// decisions compare Heron's product with [`heron_tolerance`] directly.
pub fn toggle_band(l3: f64, l4: f64, r: f64, rho: f64) -> f64 {
    let m = l3.max(l4).max(r).max(rho);
    let (l3, l4, r, rho) = (l3 / m, l4 / m, r / m, rho / m);
    let (sum, diff) = (l3 + l4, l3 - l4);
    let r2 = r * r;
    let tol = heron_tolerance(
        sum * sum,
        diff.abs() * sum,
        r2,
        rho,
        sum * sum - r2,
        r2 - diff * diff,
    );
    tol.sqrt() / (2.0 * l3 * l4)
}

// Tolerances of `geom` and `design` (issue 25: moved here from the modules
// that use them, under the names those modules keep as aliases).

/// Relative size (against the largest coefficient, which is 1) below which
/// a cubic's coefficient counts as zero for
/// [`Cubic::degree`](crate::geom::Cubic::degree) and
/// [`Cubic::is_circular`](crate::geom::Cubic::is_circular).
pub const CUBIC_KIND: f64 = 1e-12;

/// A polynomial's value within this many machine epsilons of the magnitude
/// of its terms (`sum |p_i| |x|^i`) counts as zero (the real roots of the
/// cubic's polynomials: a critical point there is a double root).
pub const ROOT_ZERO_EPS: f64 = 32.0;

/// Radians either side of a transmission-angle limit where the design
/// kernel takes the `acos` of the worst `|cos mu|` instead of comparing it
/// with the limit's cosines (its `CosBand`): far larger than the rounding
/// of `acos` and `cos` (about `4e-16` rad), so the comparison is the
/// `acos`'s own.
pub const COS_SLACK: f64 = 1e-9;

/// Radians below the best run's score under which an atlas sample's score
/// (an f32, rounded by at most `1e-7` rad) can neither tie nor lead.
pub const TOP_SLACK: f64 = 1e-6;

// The four- and five-pose synthesis (`synthesis::four`, `synthesis::five`).

/// A point lies on a curve when its first-order distance from it
/// ([`crate::geom::Cubic::distance_estimate`]) is at most this times the task
/// size ([`FourPositions::size`](crate::synthesis::FourPositions::size)) plus
/// the point's distance from the centroid of the pose points, or at most the
/// curve's rounding band there ([`ON_CURVE_EPS`]: the rounding of the curve's
/// coefficients from the poses and of its evaluation, over the gradient,
/// plus the rounding of the point's coordinates), or when the curve's value
/// there is within that band (at a singular point the first-order distance
/// means nothing). The band is what covers the library's own points where
/// the curve is ill-conditioned (poses that are nearly rotations about one
/// point, a nearly singular point of the curve): it moves, turns and
/// scales with the task.
pub const ON_CURVE_TOLERANCE: f64 = 1e-9;

/// Two poses are the same when their points agree within this times the
/// task size and their angles within this many radians (modulo `2 pi`).
pub const COINCIDENT_POSES: f64 = 1e-12;

/// Two poses nearly coincide when their points agree within this times the
/// task size and their angles within this many radians (modulo `2 pi`).
/// Only a message depends on it: where every elimination of five poses
/// vanishes within its rounding (the two curves of each choice nearly
/// share a component), a task with two such poses is refused as not
/// resolved (the rounding decides; move the poses apart), not as having
/// infinitely many Burmester points. A crank-rocker driven to two crank
/// angles `1e-7` rad apart (the poses `2e-7` task sizes apart) has two
/// isolated exact points where every choice vanished (stop 41's
/// designer-range stress, `fuzz/reference/moderate_five.py`).
pub const NEARLY_COINCIDENT_POSES: f64 = 1e-4;

/// A curve vanishes identically (the poses are rotations about one point)
/// when every coefficient of its exact expansion is at most this times the
/// largest coefficient of the same expansion with every term taken in
/// magnitude (the scale of its rounding).
pub const DEGENERATE_CURVE: f64 = 1e-12;

/// A Burmester point is kept when the crank length of its dyad varies over
/// the five poses by at most this relative amount (`(max - min) / max`);
/// the points found are concyclic to about `1e-14`.
pub const BURMESTER_RESIDUAL: f64 = 1e-10;

/// A center point given for a dyad of five poses is the Burmester point
/// whose center lies within this times the task's scale plus its distance
/// from pose 1 (a Burmester point typed back in).
pub const NEAR_BURMESTER_POINT: f64 = 1e-7;

// The slider-crank (issue 27, `linkage::slider`).

/// The toggle band of a slider-crank's loop: the rounding of
/// `H = (l - h) (l + h)`, `l` the coupler and `h` the crank tip's height
/// over the guide, `rho` the size of the vectors `h` was formed from (the
/// crank plus the offset), all in one unit. `sqrt(H) = |<B - A, u>| =
/// l sin mu` (`mu` the transmission angle, the angle between the coupler
/// and the guide's normal), so the loop is at a toggle where `|H| <= tol`,
/// in angle terms `sin mu <= sqrt(tol) / l`.
///
/// # Derivation
///
/// ```text
/// h = e + r <d, n> is off by up to about eps rho (the offset, and the
/// crank times its rounded direction), l by eps l, so each factor of H,
/// l - h and l + h, by up to about eps E with E = l + |h| + rho, and
///
///     err(H) <~ eps E (|l - h| + |l + h|) + (eps E)^2.
///
/// With LOOP_EPS (the four-bar's factor, the same margin over the
/// measured rounding):
///
///     tol = k E (|l - h| + |l + h|) + k^2 E^2,    k = LOOP_EPS eps.
///
/// At the toggle (h = +-l) the band is sin mu <= sqrt(2 k E / l), about
/// 2e-7 rad for links of one size (the four-bar's, heron_tolerance).
/// ```
///
/// NaN input gives NaN.
#[inline]
pub fn slider_tolerance(l: f64, h: f64, rho: f64) -> f64 {
    let k = LOOP_EPS * f64::EPSILON;
    let e = l + h.abs() + rho;
    k * e * ((l - h).abs() + (l + h).abs()) + k * k * e * e
}

// Five poses in far-moved frames (issue 24, fuzz32).

/// The rounding allowance, in `eps` of the coordinates over the crank's
/// length, of a Burmester point's concyclicity check and of a slider's
/// collinearity check. The check runs in the task's own frame (origin the
/// poses' centroid, unit their span: `LocalMotion`), so the coordinates are
/// those of the task, not of where it is given: in the frame moved by
/// `(1e6, -1e6)` the global coordinates' `64 eps` allowed a spread of
/// `7e-8` (a crank of `0.2`) and passed points `2e-4` off two roots `5e-5`
/// apart, each listed twice (a wrong count). The local positions, crank and
/// center are each rounded once or twice in forming the spread from the
/// four displacements (a few `eps` of the coordinates each); 64 leaves the
/// margin the check had, and the points found are concyclic to about
/// `1e-14`.
pub const BURMESTER_ROUNDING: f64 = 64.0;

/// Five poses whose coordinates exceed this many task sizes are "far from
/// the origin" in the message of an unresolved task: there the rounding of
/// the coordinates (`eps` of them, over `1e3` of it a `2e-13` task sizes)
/// moves two nearly merging Burmester points by its square root, about
/// `5e-7` task sizes and more, and can make a close real pair complex (the
/// task of `issue24_a_double_root_that_is_two_real_points_gives_both`
/// moved by `(-3e6, 2e6)`: its two real points `6.3e-5` apart are a complex
/// pair `1.7e-5` off the real plane after the move's rounding, by the exact
/// reference). The message then says to give the poses relative to a point
/// near the task. Only the wording depends on it.
pub const BURMESTER_FAR_FRAME: f64 = 1e3;

/// Burmester points within this many task sizes of the poses' centroid are
/// "near": an elimination of five poses is taken only when it lists at
/// least as many near points (with multiplicity) as a better conditioned
/// choice of the shared poses verified as distinct near points while losing
/// other roots (a badly conditioned choice can find fewer roots, or none,
/// and look clean). Farther out a point is known only to its distance
/// squared times the rounding (a complex pair `1.2` task sizes off the real
/// plane `1e6` task sizes out passes the concyclicity check as two real
/// points in some choices), and a far point and a slider are within
/// rounding of each other, so they do not count: `1e4`, the distance beyond
/// which the fuzz target's frame check does not compare points either.
pub const BURMESTER_NEAR: f64 = 1e4;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn toggle_band_is_the_root_of_the_heron_band() {
        assert_eq!(TOGGLE_BAND, (ROUNDING_EPS * f64::EPSILON).sqrt());
    }
}
