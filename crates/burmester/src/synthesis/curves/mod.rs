//! Four- and five-position synthesis: the Burmester curves (center-point
//! and circle-point cubics), the crank-rotation parametrisation, where the
//! order of the crank positions changes, Filemon's construction with four
//! lines and the exact ends of the branch-free arcs, and the Burmester
//! points of five poses with the four-bars of their pairs.
//!
//! Everything works from the poses alone: with
//! `D_1k(z) = R_k z + t_k`, `R_k = e^{i theta_1k}`, `t_k = p_k - R_k p_1`, a
//! dyad (center point `G`, circle point `z` at pose 1) passes pose `k` when
//! `|D_1k(z) - G| = |z - G|`, which expands (the `|z|^2` and `|G|^2` terms
//! cancel) to one equation linear in `z` for fixed `G`, and linear in `G`
//! for fixed `z`:
//!
//! ```text
//! a_k(G) . z = b_k(G),   a_k(G) = conj(R_k) t_k + (1 - conj(R_k)) G,   b_k(G) = t_k . G - |t_k|^2 / 2
//! ```
//!
//! No pole appears, so a pure translation between two poses needs no
//! special case. Three poses give one circle point per center point (the
//! existing [`crate::Task`]); four give the cubic curves of
//! [`FourPositions`]; five give the finitely many Burmester points of
//! [`FivePositions`].
//!
//! All the arithmetic runs in a local frame (origin the centroid of the
//! pose points, unit their largest distance from it), so results move,
//! turn and scale with the task.

// Comparisons are written `!(a > b)` on purpose: a NaN takes the failing
// branch.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod branch;
mod errors;
mod five;
mod four;
mod motion;
mod order;
mod split;

pub use branch::{ArcEnd, FilemonArcs};
pub use five::{BurmesterFourBar, BurmesterSlider, FivePositions};
pub use four::{CoincidencePoint, CurveDyad, FourPositions, OrderArc, Pole};
pub use order::{CrankOrder, Drive, Turn};

/// A point lies on a curve when its first-order distance from it
/// ([`crate::geom::Cubic::distance_estimate`]) is at most this times the task
/// size ([`FourPositions::size`]) plus the point's distance from the
/// centroid of the pose points, or at most the curve's rounding band there
/// ([`crate::tolerance::ON_CURVE_EPS`]: the rounding of the curve's
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

/// A curve vanishes identically (the poses are rotations about one point)
/// when every coefficient of its exact expansion is at most this times the
/// largest coefficient of the same expansion with every term taken in
/// magnitude (the scale of its rounding).
pub const DEGENERATE_CURVE: f64 = 1e-12;

/// A dyad passes the poses when its crank length varies over them by at
/// most this times the crank length plus the task size.
pub const DYAD_TOLERANCE: f64 = 1e-9;

/// A Burmester point is kept when the crank length of its dyad varies over
/// the five poses by at most this relative amount (`(max - min) / max`);
/// the points found are concyclic to about `1e-14`.
pub const BURMESTER_RESIDUAL: f64 = 1e-10;
