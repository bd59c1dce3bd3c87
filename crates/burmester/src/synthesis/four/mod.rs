//! Four poses: the center-point and circle-point curves, the maps between
//! them, the crank-rotation parametrisation, the points where two crank
//! positions coincide, and the four-bar of two dyads.

// Comparisons are written `!(a > b)` on purpose: a NaN takes the failing
// branch.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod arcs;
mod split;

use core::f64::consts::PI;

use nalgebra::{Complex, Matrix3x4, Point2, Vector2, Vector3};

use crate::engine::Control;
use crate::error::{Result, out_of_memory, try_push};
use crate::geom::{Cubic, LocalFrame, Pose, Viewport, wrap_angle};
use crate::linkage::{AngleInterval, AssemblyMode, FourBar, InputRange};
use crate::synthesis::errors;
use crate::synthesis::local::{Failure, LocalMotion, cross3};
use crate::synthesis::order::{CrankOrder, Drive, check_dyad, crank_angles, drive};
use crate::synthesis::task::of_poses;
use crate::synthesis::{Dyad, DyadKind, SliderDyad};
use crate::tolerance;
pub use arcs::{ArcEnd, FilemonArcs};
use split::split_by;

/// The six pairs of four poses (0-based), in the order `12, 13, 14, 23, 24, 34`.
const PAIRS: [(usize, usize); 6] = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];

/// A pole `P_jk` of two poses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairPole {
    /// The two poses (1-based, `j < k`).
    pub poses: [usize; 2],
    /// The pole; `None` when it is at infinity (the two poses differ by a
    /// pure translation).
    pub point: Option<Point2<f64>>,
}

/// A point `Q_jk` of the center-point curve where the crank positions at
/// poses `j` and `k` coincide:
///
/// ```text
/// Q_jk = (P_lj P_lk) x (P_mj P_mk)      ({l, m} the other two poses)
/// ```
///
/// the meet of the line through `P_lj, P_lk` with the line through
/// `P_mj, P_mk`. Its circle point is `D_j1(P_jk)`: the moving pivot sits on
/// the pole `P_jk` at both poses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoincidencePoint {
    /// The two poses (1-based, `j < k`).
    pub poses: [usize; 2],
    /// `Q_jk`; `None` when it is at infinity or undefined (coincident
    /// poles).
    pub center: Option<Point2<f64>>,
    /// Its circle point `D_j1(P_jk)`; `None` when `P_jk` is at infinity.
    pub circle: Option<Point2<f64>>,
}

/// A piece of the center-point curve (in view) on which the cyclic order
/// of the four crank positions is constant, cut at the points `Q_jk`.
#[derive(Debug, Clone, PartialEq)]
pub struct OrderArc {
    /// The crank order of every dyad on the piece.
    pub order: CrankOrder,
    /// The piece, a polyline on the center-point curve; an end inside the
    /// viewport is a point `Q_jk` (or a place where the circle point is
    /// undefined or at infinity).
    pub points: Vec<Point2<f64>>,
}

/// A dyad of four poses, with its place on the crank-rotation
/// parametrisation of the curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveDyad {
    /// The center point (fixed pivot), on the center-point curve.
    pub center: Point2<f64>,
    /// The circle point (moving pivot at pose 1), on the circle-point curve.
    pub circle: Point2<f64>,
    /// The crank rotation from pose 1 to pose 2, `beta_2`, in `(-pi, pi]`.
    pub beta2: f64,
    /// The solution branch at this `beta_2`: the assembly mode of the
    /// compatibility linkage; `None` at one of its toggles (where the two
    /// branches meet) or when the poses have no compatibility linkage.
    pub branch: Option<AssemblyMode>,
    /// The cyclic order of the crank's positions at the four poses.
    pub order: CrankOrder,
}

impl CurveDyad {
    /// The dyad `(center, circle)`.
    pub fn dyad(&self) -> Dyad {
        Dyad::new(self.center, self.circle)
    }
}

/// A dyad of the crank-rotation parametrisation whose three conditions,
/// after the corrections, are off by more than this relative to their terms
/// is not given ([`FourPositions::dyad_at`]): the formulas lost every digit.
const POLISHED: f64 = 1e-8;

/// The most distance from a curve (relative to the task size plus the
/// point's distance from the task) at which a point whose dyad solves the
/// three conditions within their rounding is on the curve
/// ([`FourPositions::on_curve`]).
const ON_CURVE_LOOSE: f64 = 1e-6;

/// The crank-rotation parametrisation counts a dyad as at infinity when
/// the best pair of its equations in `(W, Z)` is this close to singular
/// (relative to the magnitude of the determinant's terms): its center point
/// would be more than about `1 / FAR_DYAD` task sizes away, where the
/// equations no longer fix it to better than `1e-8` relative.
const FAR_DYAD: f64 = 1e-8;

/// The compatibility linkage (Sandor & Erdman) of four poses: with
/// `E_j = e^{i alpha_j} - 1`, `delta_j = p_j - p_1` and the dyad vectors
/// `W = z - G`, `Z = p_1 - z`,
///
/// ```text
/// W (e^{i beta_j} - 1) + Z E_j = delta_j      (j = 2, 3, 4)
/// ```
///
/// is consistent exactly when
/// `Delta_1 + Delta_2 e^{i beta_2} + Delta_3 e^{i beta_3} + Delta_4 e^{i beta_4} = 0`
/// (the 3x3 complex determinant), the loop of a four-bar with ground
/// `-Delta_1` and links `|Delta_2|, |Delta_3|, |Delta_4|`, driven by
/// `beta_2`; its two assembly modes are the two solution branches.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Compat {
    fourbar: FourBar,
    /// `arg Delta_2, arg Delta_3, arg Delta_4`.
    arg: [f64; 3],
    /// `E_2, E_3, E_4`.
    e: [Complex<f64>; 3],
    /// `delta_2, delta_3, delta_4` (local).
    delta: [Complex<f64>; 3],
}

fn cx(v: Vector2<f64>) -> Complex<f64> {
    Complex::new(v.x, v.y)
}

impl Compat {
    fn new(m: &LocalMotion) -> Result<Self> {
        let e = [1, 2, 3].map(|k| Complex::from_polar(1.0, m.theta[k]) - 1.0);
        let delta = [1, 2, 3].map(|k| cx(m.pos[k] - m.pos[0]));
        let d2 = e[1] * delta[2] - e[2] * delta[1];
        let d3 = -(e[0] * delta[2] - e[2] * delta[0]);
        let d4 = e[0] * delta[1] - e[1] * delta[0];
        let d1 = -(d2 + d3 + d4);
        let lengths = [d1, d2, d3, d4].map(|d| d.norm());
        let size = lengths.iter().copied().fold(0.0, f64::max);
        if lengths
            .iter()
            .any(|&l| !(l > tolerance::DEGENERATE_CURVE * size))
        {
            return Err(errors::no_parametrization());
        }
        let g = -d1;
        let fourbar = FourBar::placed(
            lengths[0],
            lengths[1],
            lengths[2],
            lengths[3],
            Point2::origin(),
            g.im.atan2(g.re),
        )?;
        Ok(Compat {
            fourbar,
            arg: [d2.arg(), d3.arg(), d4.arg()],
            e,
            delta,
        })
    }

    /// `(W, Z)` from the crank rotations `beta_2, beta_3, beta_4`, by the
    /// best conditioned pair of equations; `None` at infinity.
    fn dyad(&self, beta: [f64; 3]) -> Option<(Complex<f64>, Complex<f64>)> {
        let b = beta.map(|t| Complex::from_polar(1.0, t) - 1.0);
        // |e^{i beta} - 1| <= 2: every determinant is at most 4 max |E_j|,
        // and the numerator of W is of the order of max |E_j| (in task sizes).
        let scale = 4.0 * self.e.iter().fold(0.0f64, |m, e| m.max(e.norm()));
        let mut best: Option<(f64, usize, usize, Complex<f64>)> = None;
        for (j, k) in [(0, 1), (0, 2), (1, 2)] {
            let det = b[j] * self.e[k] - b[k] * self.e[j];
            if best.is_none_or(|(d, ..)| det.norm() > d) {
                best = Some((det.norm(), j, k, det));
            }
        }
        let (size, j, k, det) = best?;
        if !(size > FAR_DYAD * scale) {
            return None;
        }
        let w = (self.delta[j] * self.e[k] - self.delta[k] * self.e[j]) / det;
        let z = (b[j] * self.delta[k] - b[k] * self.delta[j]) / det;
        (w.re.is_finite() && w.im.is_finite() && z.re.is_finite() && z.im.is_finite())
            .then_some((w, z))
    }

    /// The branch (compatibility mode) of a dyad with crank rotations
    /// `beta_3, beta_4`: the sign of `sin(theta4 - theta3)` of the
    /// compatibility four-bar; `None` at a toggle.
    fn branch(&self, beta3: f64, beta4: f64) -> Option<AssemblyMode> {
        let theta3 = beta3 + self.arg[1];
        let theta4 = beta4 + self.arg[2] + PI;
        let s = (theta4 - theta3).sin();
        if s.abs() <= 1e-12 {
            None
        } else {
            AssemblyMode::from_sign(s)
        }
    }
}

/// Four poses of the coupler: the center-point and circle-point curves
/// (Burmester curves) and what lies on them.
///
/// # The curves (exact cubics)
///
/// With `D_1k(z) = R_k z + t_k`, a dyad (center `G`, circle point `z` at
/// pose 1) passes pose `k` when `a_k(G) . z = b_k(G)`, linear in `z`
/// (module docs). Three such equations in two unknowns are consistent
/// exactly where
///
/// ```text
/// f(G) = det [a_2 b_2; a_3 b_3; a_4 b_4] = 0
/// ```
///
/// a circular cubic through the six poles: the **center-point curve**. Its
/// ten coefficients are expanded exactly from the poses (a product of
/// affine polynomials), never fitted. The **circle-point curve** is the
/// same construction for the inverted motion (`D_1k^-1`, the ground seen
/// from the coupler at pose 1), in the circle-point plane. A pure
/// translation between two poses needs no special case (its pole is at
/// infinity; the curves are unchanged in kind).
///
/// # Example
///
/// ```
/// use burmester::{Pose, Viewport};
/// use burmester::synthesis::FourPositions;
/// let four = FourPositions::new(&[
///     Pose::new(1.0, 2.0, 0.3),
///     Pose::new(2.5, 1.0, 0.9),
///     Pose::new(0.5, -1.0, -0.4),
///     Pose::new(-1.0, 0.2, 1.7),
/// ])?;
/// // The poles lie on the center-point curve; a center point maps to its
/// // circle point and back.
/// let p12 = four.poles()[0].point.unwrap();
/// let dyad = four.dyad_from_center(p12)?;
/// assert!(four.center_point_curve().distance_estimate(p12) < 1e-12);
/// assert!((four.center_point(dyad.circle)? - p12).norm() < 1e-9);
/// // Every traced point is a center point: its circle point stays on one
/// // circle about it at the four poses.
/// let view = Viewport::new(-10.0, 10.0, -10.0, 10.0)?;
/// for g in four.center_point_curve().polylines(&view).into_iter().flatten() {
///     if let Ok(z) = four.circle_point(g) {
///         let r: Vec<f64> = (1..=4).map(|k| (four.displace(z, 1, k).unwrap() - g).norm()).collect();
///         assert!(r.iter().all(|x| (x - r[0]).abs() <= 1e-9 * r[0]));
///     }
/// }
/// # Ok::<(), burmester::Error>(())
/// ```
#[derive(Clone, Copy, PartialEq)]
pub struct FourPositions {
    motion: LocalMotion,
    center_curve: Cubic,
    circle_curve: Cubic,
    /// Per coefficient of each stored curve (center, circle), the scale of
    /// its rounding from the poses, in the units of the stored
    /// coefficients (the expansion with every number in magnitude, over
    /// the largest coefficient).
    bounds: [[f64; 10]; 2],
    compat: Option<Compat>,
}

crate::geom::debug_shows!(
    /// The poses and the two curves, not the motion's internals.
    FourPositions,
    s => poses: s.poses(), center_point_curve: s.center_curve, circle_point_curve: s.circle_curve,
);

impl FourPositions {
    /// The curves of four poses.
    ///
    /// # Errors
    ///
    /// [`crate::InvalidInput::NeedsPoses`] unless there are exactly four
    /// poses; [`crate::InvalidInput`] for non-finite numbers, coordinates
    /// beyond [`crate::Task::MAX_COORDINATE`], angles beyond
    /// [`crate::Task::MAX_ANGLE`], a task smaller than
    /// [`crate::Task::MIN_SCALE`]; [`crate::DegenerateError::CoincidentPoses`]
    /// for two equal poses (within [`crate::tolerance::COINCIDENT_POSES`]);
    /// [`crate::DegenerateError::CoincidentPoles`] when the poses are all
    /// rotations about one point (the curve vanishes identically, within
    /// [`crate::tolerance::DEGENERATE_CURVE`]);
    /// [`crate::DegenerateError::CollinearTranslations`] when three poses
    /// have one angle and collinear positions (every dyad through them is a
    /// slider: no finite center point);
    /// [`crate::DegenerateError::AllTranslations`] when all four have one
    /// angle (every dyad's crank is one vector: the curve degenerates).
    pub fn new(poses: &[Pose]) -> Result<Self> {
        of_poses(poses, 4, "FourPositions::new", Self::of)
    }

    /// The curves of four poses that passed the one check of the poses
    /// ([`check_poses`](crate::synthesis::task::check_poses): a task's, or
    /// four of a task's five).
    pub(crate) fn of(poses: &[Pose]) -> Result<Self> {
        let motion = LocalMotion::new(poses)?;
        // Four poses of one angle are translations: every pole is at
        // infinity and no dyad passes them (the curve's equation is a
        // nonzero constant, or vanishes).
        if motion
            .theta
            .iter()
            .all(|t| wrap_angle(*t).abs() <= tolerance::COINCIDENT_POSES)
        {
            return Err(errors::all_translations());
        }
        if let Some(t) = motion.collinear_translations() {
            return Err(errors::collinear_translations(t.map(|k| k + 1)));
        }
        // The coefficients from the accurate expansion (poses at nearly one
        // position cancel most of the plain one's digits); the scale of
        // their rounding from the plain one's terms in magnitude.
        let curve = |inverse: bool| -> Result<(Cubic, [f64; 10])> {
            let form = if inverse {
                motion.form.inverse()
            } else {
                motion.form
            };
            let (_, mags) = form.cubic_bounds([1, 2, 3]);
            let f = motion.curve_cubic(inverse);
            let mag = mags.iter().fold(0.0f64, |m, v| m.max(*v));
            let max = f.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            if !(max > tolerance::DEGENERATE_CURVE * mag) {
                // Rotations about one point: their common pole (never the
                // poses' centroid, which is no pole).
                return match motion.dehomogenize(motion.pole(0, 1)) {
                    Some(p) => Err(errors::common_pole(p)),
                    None => Err(errors::all_translations()),
                };
            }
            Ok((
                Cubic::from_local(f, motion.origin, motion.scale),
                mags.map(|m| m / max),
            ))
        };
        let (center_curve, center_bounds) = curve(false)?;
        let (circle_curve, circle_bounds) = curve(true)?;
        let compat = Compat::new(&motion).ok();
        Ok(FourPositions {
            motion,
            center_curve,
            circle_curve,
            bounds: [center_bounds, circle_bounds],
            compat,
        })
    }

    /// The four poses.
    pub fn poses(&self) -> &[Pose] {
        &self.motion.poses
    }

    /// The size of the task: the largest distance of a pose point from
    /// their centroid. The unit of the relative tolerances.
    pub fn size(&self) -> f64 {
        self.motion.scale
    }

    /// The center-point curve (fixed frame).
    pub fn center_point_curve(&self) -> &Cubic {
        &self.center_curve
    }

    /// The circle-point curve (the coupler frame at pose 1).
    pub fn circle_point_curve(&self) -> &Cubic {
        &self.circle_curve
    }

    /// `D_ij(z) = p_j + e^{i theta_ij} (z - p_i)` (1-based `i`, `j`).
    ///
    /// # Errors
    ///
    /// [`crate::InvalidInput::CountOutOfRange`] when `i` or `j` is not 1 to 4.
    pub fn displace(&self, z: Point2<f64>, i: usize, j: usize) -> Result<Point2<f64>> {
        for k in [i, j] {
            if !(1..=4).contains(&k) {
                return Err(errors::pose_index(k, 4));
            }
        }
        Ok(self.motion.displace(z, i - 1, j - 1))
    }

    /// Whether `p` lies on the center-point curve (`circle == false`) or
    /// the circle-point curve, with its first-order distance from it and
    /// the largest accepted distance (see [`tolerance::ON_CURVE_TOLERANCE`]): the
    /// larger of [`tolerance::ON_CURVE_TOLERANCE`] times the task size plus the
    /// distance of `p` from the task's centroid, and the rounding band of
    /// the curve at `p` ([`tolerance::ON_CURVE_EPS`]): the curve's value
    /// within that many `eps` of the bound on its terms (the rounding of
    /// its coefficients from the poses and of the evaluation) over its
    /// gradient, plus the rounding of the point's coordinates. A point
    /// whose value is within the band is on the curve wherever the
    /// gradient vanishes (a singular point).
    pub(crate) fn on_curve(&self, p: Point2<f64>, circle: bool) -> (bool, f64, f64) {
        let (curve, bounds) = if circle {
            (&self.circle_curve, &self.bounds[1])
        } else {
            (&self.center_curve, &self.bounds[0])
        };
        let (origin, scale) = (self.motion.origin, self.motion.scale);
        let dist = curve.distance_estimate(p);
        let relative = tolerance::ON_CURVE_TOLERANCE * (scale + (p - origin).norm());
        let Some((f, bound, grad, m)) = curve.value_and_bound(p, bounds) else {
            return (dist <= relative, dist, relative);
        };
        let band = tolerance::ON_CURVE_EPS * f64::EPSILON * bound;
        // The point's own rounding: its coordinates and the frame's origin
        // are known to half an ulp each.
        let point =
            tolerance::ON_CURVE_EPS * f64::EPSILON * (p.coords.norm() + origin.coords.norm());
        let rounding = band / grad * m * scale + point;
        let tol = if rounding.is_finite() {
            relative.max(rounding)
        } else {
            relative
        };
        if dist <= tol || f.abs() <= band {
            return (true, dist, tol);
        }
        // Where the task is ill-conditioned (nearly equal angles, a point
        // millions of task sizes out) a point of the curve is known only as
        // well as its dyad solves the three conditions: within the rounding
        // of their terms (with the circle point), and within a millionth.
        let form = if circle {
            self.motion.form.inverse()
        } else {
            self.motion.form
        };
        let v = self.motion.local_of(p);
        let dg = (p.coords.norm() + origin.coords.norm()) / scale;
        let solved = dist <= ON_CURVE_LOOSE * (scale + (p - origin).norm())
            && form
                .consistency(v, &[1, 2, 3], dg)
                .is_some_and(|r| r <= tolerance::ON_CURVE_EPS);
        (solved, dist, tol)
    }

    /// Checks a point and returns it in the local frame.
    fn local_point(&self, p: Point2<f64>, names: [&'static str; 2]) -> Result<Vector2<f64>> {
        for (n, v) in names.iter().zip([p.x, p.y]) {
            if !v.is_finite() {
                return Err(errors::not_finite(n, v));
            }
        }
        let g = self.motion.local_of(p);
        if !g.iter().all(|v| v.is_finite()) {
            return Err(errors::far_point());
        }
        Ok(g)
    }

    /// The circle point (moving pivot at pose 1) of a center point on the
    /// center-point curve: the solution of the best conditioned pair of
    /// the three linear equations.
    ///
    /// # Errors
    ///
    /// [`crate::InvalidInput::OffCurve`] when `center` is not on the curve
    /// by the rule of [`tolerance::ON_CURVE_TOLERANCE`] (relative to the task size
    /// plus its distance from the task, or the curve's rounding band
    /// there), with its distance and the tolerance;
    /// [`crate::DegenerateError::AtInfinity`] where the circle point is at
    /// infinity; [`crate::DegenerateError::Undefined`] where a whole line of
    /// circle points passes the four poses; [`crate::InvalidInput`] for a
    /// non-finite point.
    pub fn circle_point(&self, center: Point2<f64>) -> Result<Point2<f64>> {
        self.other_point(center, false)
    }

    /// The center point (fixed pivot) of a circle point on the circle-point
    /// curve (the inverted motion's equations, linear in the center).
    ///
    /// # Errors
    ///
    /// As [`FourPositions::circle_point`], for the circle-point curve (a
    /// center at infinity is a slider).
    pub fn center_point(&self, circle: Point2<f64>) -> Result<Point2<f64>> {
        self.other_point(circle, true)
    }

    /// The point of the other plane of `p`, on the center-point curve or
    /// (`from_circle`) on the circle-point curve.
    fn other_point(&self, p: Point2<f64>, from_circle: bool) -> Result<Point2<f64>> {
        let (given, what, curve, undefined, form) = if from_circle {
            (
                "circle point",
                "center point",
                "circle-point curve where its center point is at infinity (a slider)",
                "a point where the four conditions leave a line of center points",
                self.motion.form.inverse(),
            )
        } else {
            (
                "center point",
                "circle point",
                "center-point curve where its circle point is at infinity",
                "a point where the four conditions leave a line of circle points",
                self.motion.form,
            )
        };
        let names = if from_circle {
            ["circle point x", "circle point y"]
        } else {
            ["center point x", "center point y"]
        };
        let v = self.local_point(p, names)?;
        let (on, dist, tol) = self.on_curve(p, from_circle);
        if !on {
            return Err(errors::off_curve(given, dist, tol));
        }
        match form.solve(v, &[1, 2, 3]) {
            Ok(q) => Ok(self.motion.global_of(q)),
            Err(Failure::AtInfinity(d)) => Err(errors::at_infinity(what, curve, p, d)),
            Err(Failure::Undefined) => Err(errors::undefined(what, undefined, p)),
        }
    }

    /// The dyad whose center point is `center`.
    ///
    /// # Errors
    ///
    /// As [`FourPositions::circle_point`].
    pub fn dyad_from_center(&self, center: Point2<f64>) -> Result<Dyad> {
        Ok(Dyad::new(center, self.circle_point(center)?))
    }

    /// The dyad whose circle point is `circle`.
    ///
    /// # Errors
    ///
    /// As [`FourPositions::center_point`].
    pub fn dyad_from_circle(&self, circle: Point2<f64>) -> Result<Dyad> {
        Ok(Dyad::new(self.center_point(circle)?, circle))
    }

    /// The crank angles `arg(D_1k(circle) - center)` at the four poses.
    pub fn crank_angles(&self, dyad: &Dyad) -> [f64; 4] {
        let a = crank_angles(&self.motion, dyad);
        [a[0], a[1], a[2], a[3]]
    }

    /// The cyclic order of the crank's positions at the four poses.
    pub fn crank_order(&self, dyad: &Dyad) -> CrankOrder {
        CrankOrder::from_angles(&self.crank_angles(dyad))
    }

    /// The center-point curve in view ([`Cubic::polylines`]) cut into the
    /// pieces where the crank order is constant: the order is that of each
    /// vertex's dyad, and a change is cut at the exact point `Q_jk` where the
    /// two crank positions swap. [`CrankOrder::direction`] tells the pieces
    /// whose crank meets the poses in order.
    pub fn order_arcs(&self, viewport: &Viewport) -> Vec<OrderArc> {
        let cuts: Vec<Point2<f64>> = self
            .coincidence_points()
            .iter()
            .filter_map(|q| q.center)
            .collect();
        let polylines = self.center_curve.polylines(viewport);
        order_runs(&polylines, &cuts, |p| {
            self.dyad_from_center(p).ok().map(|d| self.crank_order(&d))
        })
    }

    /// The circle-point curve in `viewport` cut into pieces of constant
    /// crank order, as [`order_arcs`](Self::order_arcs) in the circle-point
    /// plane: each traced point's dyad is that of its center point
    /// ([`center_point`](Self::center_point)), and the cuts are the circle
    /// points `D_j1(P_jk)` of the points `Q_jk`, where the moving pivot
    /// sits on the pole `P_jk` at poses `j` and `k`, and at the
    /// [`slider_circle_points`](Self::slider_circle_points), where the
    /// center point passes through infinity.
    pub fn circle_order_arcs(&self, viewport: &Viewport) -> Vec<OrderArc> {
        let mut cuts: Vec<Point2<f64>> = self
            .coincidence_points()
            .iter()
            .filter_map(|q| q.circle)
            .collect();
        cuts.extend(self.slider_circle_points());
        let polylines = self.circle_curve.polylines(viewport);
        order_runs(&polylines, &cuts, |z| {
            self.dyad_from_circle(z).ok().map(|d| self.crank_order(&d))
        })
    }

    /// The circle points whose center point is at infinity, one per real
    /// asymptotic direction `u` of the center-point curve: the limits of
    /// the circle points as the center goes to infinity along `u` (the
    /// crank becomes a slider moving along `u`'s normal). Found from the
    /// linear form's rows divided by `|G|`, which tend to
    /// `(1 - conj(R_k)) u . z = t_k . u`, exact.
    pub fn slider_circle_points(&self) -> Vec<Point2<f64>> {
        self.slider_circles().into_iter().map(|(p, _)| p).collect()
    }

    /// [`slider_circle_points`](Self::slider_circle_points), each with the
    /// unit asymptotic direction `u` of the center-point curve it belongs
    /// to (where its center point is at infinity; its guide is normal to
    /// `u`).
    pub(crate) fn slider_circles(&self) -> Vec<(Point2<f64>, Vector2<f64>)> {
        self.center_curve
            .asymptotic_directions()
            .into_iter()
            .filter_map(|u| {
                let z = self.motion.form.solve_at_infinity(u, &[1, 2, 3]).ok()?;
                Some((self.motion.global_of(z), u))
            })
            .filter(|(p, _)| p.x.is_finite() && p.y.is_finite())
            .collect()
    }

    /// The six poles `P_jk`, in the order `12, 13, 14, 23, 24, 34`. They lie
    /// on the center-point curve.
    pub fn poles(&self) -> [PairPole; 6] {
        PAIRS.map(|(j, k)| PairPole {
            poses: [j + 1, k + 1],
            point: self.motion.dehomogenize(self.motion.pole(j, k)),
        })
    }

    /// The six points `Q_jk` where the crank positions at poses `j` and `k`
    /// coincide, in the order `12, 13, 14, 23, 24, 34`: the only places
    /// along the center-point curve (besides infinity) where the cyclic
    /// order of the four crank angles can change.
    pub fn coincidence_points(&self) -> [CoincidencePoint; 6] {
        let m = &self.motion;
        PAIRS.map(|(j, k)| {
            let others: Vec<usize> = (0..4).filter(|&i| i != j && i != k).collect();
            let (l, n) = (others[0], others[1]);
            let line1 = cross3(m.pole(l, j), m.pole(l, k));
            let line2 = cross3(m.pole(n, j), m.pole(n, k));
            let degenerate = |h: [f64; 3]| h.iter().all(|v| v.abs() <= 1e-14);
            let center = if degenerate(line1) || degenerate(line2) {
                None
            } else {
                m.dehomogenize(cross3(line1, line2))
            };
            let circle = m
                .dehomogenize(m.pole(j, k))
                .map(|p| m.displace(p, j, 0))
                .filter(|p| p.x.is_finite() && p.y.is_finite());
            CoincidencePoint {
                poses: [j + 1, k + 1],
                center,
                circle,
            }
        })
    }

    fn compat(&self) -> Result<&Compat> {
        self.compat.as_ref().ok_or_else(|| {
            // Rebuild for the error message.
            match Compat::new(&self.motion) {
                Err(e) => e,
                Ok(_) => errors::no_parametrization(),
            }
        })
    }

    /// The crank rotations `beta_2` (radians, absolute) where the
    /// compatibility linkage closes: all of them, or one or two arcs whose
    /// ends are its toggles, where the two solution branches meet.
    ///
    /// # Errors
    ///
    /// [`crate::InvalidInput::CountOutOfRange`] when the poses have no
    /// compatibility linkage (a link of zero length: for example two poses
    /// that are pure translations of pose 1).
    pub fn beta2_range(&self) -> Result<InputRange> {
        let c = self.compat()?;
        let shift = |a: AngleInterval| AngleInterval {
            start: a.start - c.arg[0],
            end: a.end - c.arg[0],
        };
        Ok(match c.fourbar.input_range() {
            InputRange::Full => InputRange::Full,
            InputRange::Arc(a) => InputRange::Arc(shift(a)),
            InputRange::TwoArcs(a, b) => InputRange::TwoArcs(shift(a), shift(b)),
        })
    }

    /// The dyad on solution branch `branch` whose crank turns by `beta2`
    /// from pose 1 to pose 2 (the compatibility-linkage parametrisation of
    /// the curves).
    ///
    /// # Errors
    ///
    /// As [`FourPositions::beta2_range`]; [`crate::AssemblyError::OutOfReach`]
    /// when `beta2` is outside that range; [`crate::DegenerateError::AtInfinity`]
    /// where the dyad's center point is at infinity;
    /// [`crate::DegenerateError::NotParametrizable`] where the formulas lose
    /// every digit (rotations between the poses of about `1e-7` rad: the
    /// dyad's conditions are off by more than `1e-8` of their terms after
    /// the corrections, or its center or circle point is not on its curve
    /// by [`FourPositions::circle_point`]'s test: a dyad given here is
    /// always taken back); [`crate::InvalidInput`] for a non-finite angle.
    pub fn dyad_at(&self, beta2: f64, branch: AssemblyMode) -> Result<CurveDyad> {
        let c = self.compat()?;
        let conf = c.fourbar.solve(beta2 + c.arg[0], branch)?;
        let beta = [beta2, conf.theta3 - c.arg[1], conf.theta4 - c.arg[2] - PI];
        let Some((w, z)) = c.dyad(beta) else {
            return Err(errors::dyad_at_infinity(beta2));
        };
        let q1 = cx(self.motion.pos[0]);
        let zl = q1 - z;
        let gl = zl - w;
        let (gl, zl, residual) =
            self.polish(Vector2::new(gl.re, gl.im), Vector2::new(zl.re, zl.im));
        // Where the crank-rotation formulas lose every digit (rotations of
        // 1e-7 rad: they divide by the square of the angle) and the
        // corrections cannot mend it, there is no dyad to give.
        if !(residual <= POLISHED) {
            return Err(errors::no_parametrization());
        }
        let center = self.motion.global_of(gl);
        let circle = self.motion.global_of(zl);
        // What the library gives it takes back: a dyad whose center or
        // circle point the on-curve test refuses is not given.
        if !(self.on_curve(center, false).0 && self.on_curve(circle, true).0) {
            return Err(errors::no_parametrization());
        }
        let dyad = Dyad::new(center, circle);
        Ok(CurveDyad {
            center,
            circle,
            beta2: wrap_angle(beta2),
            branch: if conf.toggle { None } else { Some(branch) },
            order: self.crank_order(&dyad),
        })
    }

    /// Gauss-Newton steps of a dyad `(g, z)` (local) onto the solutions of
    /// the three equations `a_k(g) . z = b_k(g)` (the smallest change,
    /// `-J^T (J J^T)^-1 F`), at most eight, each kept only when it is a
    /// small correction (below `1e-4` of the dyad's size) that lowers the
    /// residuals relative to their terms, until a step is at the level of
    /// rounding. Where the task is ill-conditioned (nearly equal angles:
    /// the crank-rotation formulas lose digits as the square of the angle)
    /// the steps are what puts the dyad on the curve to rounding. Returns
    /// the dyad and its largest residual relative to its terms.
    fn polish(
        &self,
        mut g: Vector2<f64>,
        mut z: Vector2<f64>,
    ) -> (Vector2<f64>, Vector2<f64>, f64) {
        let form = &self.motion.form;
        let system = |g: Vector2<f64>, z: Vector2<f64>| {
            let mut jac = Matrix3x4::zeros();
            let mut res = Vector3::zeros();
            let mut worst = 0.0f64;
            for (r, k) in (1..4).enumerate() {
                let (a, b) = form.row(k, g);
                let dg = form.row_dg(k, z);
                res[r] = a.dot(&z) - b;
                let terms = a.x.abs() * z.x.abs() + a.y.abs() * z.y.abs() + b.abs();
                worst = worst.max(res[r].abs() / terms.max(f64::MIN_POSITIVE));
                jac[(r, 0)] = dg.x;
                jac[(r, 1)] = dg.y;
                jac[(r, 2)] = a.x;
                jac[(r, 3)] = a.y;
            }
            (jac, res, worst)
        };
        let (mut jac, mut res, mut worst) = system(g, z);
        for _ in 0..8 {
            let Some(y) = (jac * jac.transpose()).lu().solve(&res) else {
                break;
            };
            let step = jac.transpose() * y;
            let size = 1.0 + g.norm() + z.norm();
            if !(step.norm() <= 1e-4 * size) {
                break;
            }
            let (g2, z2) = (
                g - Vector2::new(step[0], step[1]),
                z - Vector2::new(step[2], step[3]),
            );
            let (jac2, res2, worst2) = system(g2, z2);
            if !(worst2 < worst) {
                break;
            }
            (g, z, jac, res, worst) = (g2, z2, jac2, res2, worst2);
            if step.norm() <= 4.0 * f64::EPSILON * size {
                break;
            }
        }
        (g, z, worst)
    }

    /// The dyad of a center point on the curve, with its crank rotation
    /// `beta_2` and its solution branch.
    ///
    /// # Errors
    ///
    /// As [`FourPositions::circle_point`].
    pub fn curve_dyad(&self, center: Point2<f64>) -> Result<CurveDyad> {
        let dyad = self.dyad_from_center(center)?;
        let a = self.crank_angles(&dyad);
        let branch = self
            .compat
            .as_ref()
            .and_then(|c| c.branch(a[2] - a[0], a[3] - a[0]));
        Ok(CurveDyad {
            center,
            circle: dyad.circle,
            beta2: wrap_angle(a[1] - a[0]),
            branch,
            order: CrankOrder::from_angles(&a),
        })
    }

    /// Samples of the dyads along the curves by the crank rotation: about
    /// `samples` values of `beta_2` spread over [`FourPositions::beta2_range`]
    /// (its ends, the toggles, included), for each solution branch. Each
    /// run is one branch over one arc of `beta_2`, in order; a dyad at
    /// infinity splits a run. Consecutive centers of a run may still be far
    /// apart where the curve runs to infinity between them (plot the traced
    /// [`Cubic`] for a faithful picture).
    ///
    /// # Errors
    ///
    /// As [`FourPositions::beta2_range`]; [`crate::InvalidInput::CountOutOfRange`]
    /// when `samples` is 0 or more than ten million.
    pub fn dyad_runs(&self, samples: usize) -> Result<Vec<Vec<CurveDyad>>> {
        self.dyad_runs_with(samples, &Control::new())
    }

    /// [`dyad_runs`](Self::dyad_runs) following `control`: the cancel flag
    /// is checked every 1024 dyads (about a millisecond), progress counts them
    /// (about twice `samples` in all, one pass per solution branch).
    ///
    /// # Errors
    ///
    /// As [`dyad_runs`](Self::dyad_runs); [`crate::Error::OutOfMemory`]
    /// when the dyads cannot be allocated; [`crate::Error::Cancelled`].
    pub fn dyad_runs_with(
        &self,
        samples: usize,
        control: &Control<'_>,
    ) -> Result<Vec<Vec<CurveDyad>>> {
        const WHAT: &str = "the dyads along the curve";
        if samples == 0 || samples > Self::MAX_SAMPLES {
            return Err(errors::count("samples", samples, 1, Self::MAX_SAMPLES));
        }
        let intervals = self.beta2_arcs()?;
        let total_len: f64 = intervals.iter().map(|(a, b)| b - a).sum();
        let counts: Vec<usize> = intervals
            .iter()
            .map(|&(lo, hi)| ((samples as f64 * (hi - lo) / total_len).round() as usize).max(2))
            .collect();
        let total = 2 * counts.iter().map(|n| n + 1).sum::<usize>();
        let mut done = 0;
        let mut runs = Vec::new();
        for branch in AssemblyMode::BOTH {
            for (&(lo, hi), &n) in intervals.iter().zip(&counts) {
                let mut run = try_vec_of(WHAT, n + 1)?;
                for i in 0..=n {
                    if done % POLL_SAMPLES == 0 {
                        control.check(done, total)?;
                        control.report(done, total);
                    }
                    done += 1;
                    let beta = lo + (hi - lo) * (i as f64 / n as f64);
                    match self.dyad_at(beta, branch) {
                        Ok(d) => run.push(d),
                        Err(_) => {
                            if !run.is_empty() {
                                try_push(&mut runs, WHAT, core::mem::take(&mut run))?;
                                run = try_vec_of(WHAT, n - i)?;
                            }
                        }
                    }
                }
                if !run.is_empty() {
                    try_push(&mut runs, WHAT, run)?;
                }
            }
        }
        control.report(total, total);
        Ok(runs)
    }

    /// The most samples of [`dyad_runs`](Self::dyad_runs) and
    /// [`parameter_samples`](Self::parameter_samples): ten million.
    pub const MAX_SAMPLES: usize = 10_000_000;

    /// The arcs of `beta_2` over which the compatibility linkage closes
    /// ([`FourPositions::beta2_range`]) as `(start, end)`, in order.
    fn beta2_arcs(&self) -> Result<Vec<(f64, f64)>> {
        Ok(match self.beta2_range()? {
            InputRange::Full => vec![(-PI, PI)],
            InputRange::Arc(a) => vec![(a.start, a.end)],
            InputRange::TwoArcs(a, b) => vec![(a.start, a.end), (b.start, b.end)],
        })
    }

    /// The length of the curve parameter `s` of
    /// [`FourPositions::dyad_at_parameter`]: twice the total length, in
    /// radians, of [`FourPositions::beta2_range`] (`4 pi` when the crank
    /// rotation is unrestricted).
    ///
    /// # Errors
    ///
    /// As [`FourPositions::beta2_range`].
    pub fn parameter_length(&self) -> Result<f64> {
        Ok(2.0 * self.beta2_arcs()?.iter().map(|(a, b)| b - a).sum::<f64>())
    }

    /// The dyad at the curve parameter `s`: one scalar for the whole
    /// center-point curve, built from the crank rotation. The arcs of
    /// [`FourPositions::beta2_range`] are laid end to end, first on the
    /// [`AssemblyMode::Open`] solution branch, then on the
    /// [`AssemblyMode::Crossed`] one:
    ///
    /// ```text
    /// s in [0, L):   Open branch,    beta_2 = the point s along the arcs
    /// s in [L, 2L):  Crossed branch, beta_2 = the point s - L along the arcs
    /// ```
    ///
    /// with `L` half the [`FourPositions::parameter_length`]. So `s` is
    /// measured in radians of crank rotation, and a step in `s` within one
    /// arc is a step of the crank's rotation from pose 1 to pose 2. The
    /// branches meet at the toggles that end the arcs (where the curve
    /// goes on), and the center point runs to infinity where the dyad does.
    ///
    /// # Errors
    ///
    /// As [`FourPositions::dyad_at`]; [`crate::InvalidInput::OutsideRange`]
    /// when `s` is outside `[0, 2L]`.
    pub fn dyad_at_parameter(&self, s: f64) -> Result<CurveDyad> {
        let arcs = self.beta2_arcs()?;
        let half: f64 = arcs.iter().map(|(a, b)| b - a).sum();
        let s = crate::error::in_range("curve parameter", s, 0.0, 2.0 * half, "")?;
        let (branch, mut t) = if s < half {
            (AssemblyMode::Open, s)
        } else {
            (AssemblyMode::Crossed, s - half)
        };
        let mut beta = arcs[arcs.len() - 1].1;
        for &(a, b) in &arcs {
            if t <= b - a {
                beta = a + t;
                break;
            }
            t -= b - a;
        }
        self.dyad_at(beta, branch)
    }

    /// [`parameter_samples`](Self::parameter_samples) following `control`
    /// (the cancel flag checked every 1024 samples, progress
    /// counting them).
    ///
    /// # Errors
    ///
    /// As [`parameter_samples`](Self::parameter_samples);
    /// [`crate::Error::OutOfMemory`] when the samples cannot be allocated;
    /// [`crate::Error::Cancelled`].
    pub fn parameter_samples_with(
        &self,
        n: usize,
        control: &Control<'_>,
    ) -> Result<Vec<Option<CurveDyad>>> {
        if n == 0 || n > Self::MAX_SAMPLES {
            return Err(errors::count("samples", n, 1, Self::MAX_SAMPLES));
        }
        let length = self.parameter_length()?;
        let step = length / n as f64;
        let mut out = try_vec_of("the dyads of the curve parameter", n)?;
        for i in 0..n {
            if i % POLL_SAMPLES == 0 {
                control.check(i, n)?;
                control.report(i, n);
            }
            out.push(self.dyad_at_parameter((i as f64 + 0.5) * step).ok());
        }
        control.report(n, n);
        Ok(out)
    }

    /// `n` samples of the curve parameter, at the middles of `n` equal
    /// steps of `[0, parameter_length)` (so never at a toggle):
    /// `s_i = (i + 1/2) parameter_length / n`, with each one's dyad
    /// ([`FourPositions::dyad_at_parameter`]), `None` where it is at
    /// infinity.
    ///
    /// # Errors
    ///
    /// As [`FourPositions::beta2_range`]; [`crate::InvalidInput::CountOutOfRange`]
    /// when `n` is 0 or more than ten million.
    pub fn parameter_samples(&self, n: usize) -> Result<Vec<Option<CurveDyad>>> {
        self.parameter_samples_with(n, &Control::new())
    }

    /// The four-bar of a driving and a driven dyad of the four poses, with
    /// its input angles, assembly modes and crank order at each pose.
    ///
    /// # Errors
    ///
    /// [`crate::InvalidInput::CountOutOfRange`] when a dyad does not pass the four
    /// poses (its crank length varies by more than [`crate::tolerance::DYAD`]);
    /// [`crate::DegenerateError::ZeroLengthLink`] for a link of zero length;
    /// errors of [`FourBar::from_pivots`].
    pub fn drive(&self, driving: &Dyad, driven: &Dyad) -> Result<Drive> {
        drive(&self.motion, driving, driven)
    }

    /// Filemon's construction with four lines for a driven dyad, with the
    /// exact ends of the branch-free arcs of the circle-point curve.
    ///
    /// # Errors
    ///
    /// [`crate::InvalidInput::CountOutOfRange`] when `driven` does not pass the
    /// four poses (as [`FourPositions::drive`]) or an image `C'_k = D_k1(C0)`
    /// of its fixed pivot is not finite or coincides with its circle point;
    /// [`crate::DegenerateError::ZeroLengthLink`] for a crank of zero length.
    pub fn filemon(&self, driven: &Dyad) -> Result<FilemonArcs> {
        check_dyad(&self.motion, driven, "driven dyad")?;
        FilemonArcs::new(self, DyadKind::Revolute(*driven))
    }

    /// [`filemon`](Self::filemon) for a slider driven dyad: the pin `C1`
    /// on a ground guide of direction `u`; the lines run through `C1` in
    /// the directions `n_k` (see [`crate::FilemonLines`]).
    ///
    /// # Errors
    ///
    /// [`crate::InvalidInput::NotFinite`] or
    /// [`crate::InvalidInput::ZeroDirection`] for a circle point or guide
    /// that is not finite or zero; [`crate::InvalidInput::NotADyad`] when
    /// the pin's four positions `D_1k(C1)` are not on the guide (within
    /// [`crate::tolerance::DYAD`] of the task's size and the pin's travel):
    /// pass a slider point of the task and its guide.
    pub fn slider_filemon(&self, driven: &SliderDyad) -> Result<FilemonArcs> {
        FilemonArcs::new(self, DyadKind::Slider(*driven))
    }
}

/// Dyads computed between two checks of the cancel flag (and progress
/// reports) by [`FourPositions::dyad_runs_with`] and
/// [`FourPositions::parameter_samples_with`]: about a millisecond of work.
pub(crate) const POLL_SAMPLES: usize = 1024;

/// An empty vector with room for `n` values, reserved fallibly.
fn try_vec_of<T>(what: &'static str, n: usize) -> Result<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(n)
        .map_err(|_| out_of_memory::<T>(what, n))?;
    Ok(v)
}

/// The runs of `polylines` of one crank order (`order` of a point, `None`
/// where it has no dyad), cut at the nearest of `cuts`.
fn order_runs(
    polylines: &[Vec<Point2<f64>>],
    cuts: &[Point2<f64>],
    order: impl Fn(Point2<f64>) -> Option<CrankOrder>,
) -> Vec<OrderArc> {
    split_by(polylines, cuts, order)
        .into_iter()
        .map(|(order, points)| OrderArc { order, points })
        .collect()
}
