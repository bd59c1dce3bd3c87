//! Plane cubic curves
//! `f(x, y) = c00 + c10 x + c01 y + c20 x^2 + c11 x y + c02 y^2 + c30 x^3 + c21 x^2 y + c12 x y^2 + c03 y^3 = 0`:
//! evaluation, gradient, distance, line intersections, and tracing of every
//! component that crosses a viewport into polylines.
//!
//! # Frame and scaling
//!
//! Like [`Conic`](crate::Conic), a cubic is stored in a local frame (an
//! origin and a unit length) with its coefficients divided by the largest in
//! magnitude: `f` is defined up to a positive factor, every sign test keeps
//! its meaning, and no evaluation overflows (points more than `1e100` units
//! of the frame away are evaluated as `f(p) / m^3`, `m` their distance in
//! those units, which has the sign of `f(p)`).
//!
//! # Tracing (the pencil through a point of the curve)
//!
//! Let `Q` be a point of the curve. The line through `Q` along
//! `w = (cos s, sin s)` meets it where
//!
//! ```text
//! f(Q + t w) = t (alpha(w) t^2 + beta(w) t + gamma(w)) = 0
//! alpha(w) = cubic part of f at w,  beta(w) = w^T H(Q) w / 2,  gamma(w) = grad f(Q) . w
//! ```
//!
//! so the two other points are the roots `t+-(s)` of one quadratic, whose
//! discriminant `Delta(w) = beta^2 - 4 alpha gamma` is a binary quartic
//! form. As `s` runs over half a turn, the two roots trace the **whole** real
//! curve (every oval and every unbounded branch, not only the component of
//! `Q`): over each interval of directions where `Delta >= 0` the two roots
//! join at both ends (where the line from `Q` is tangent to the curve) into
//! one closed loop of the projective curve; with `Delta > 0` everywhere each
//! root is a loop by itself. A loop is unbounded where `alpha` vanishes (an
//! asymptotic direction) and one root passes through infinity. The roots of
//! `Delta` and `alpha` are found exactly (roots of binary forms, no
//! sampling), so no component is missed however small or far it is.
//!
//! Where the curve crosses the viewport's edges is found exactly too (one
//! cubic in one variable per edge). Each crossing is placed on its loop, and
//! the stretches of a loop between consecutive crossings that lie inside
//! the viewport are sampled adaptively, from crossing to crossing: the ends
//! of every polyline are exact points of the curve on the edges (or, where
//! no point of the curve on the edge is near an end, the curve's nearest
//! point within a tenth of the chord tolerance inside), and a loop
//! with no crossing is either wholly inside (one closed polyline) or wholly
//! outside. `Q` is taken near the viewport and away from singular points of
//! the curve; everything is in units of the viewport and of the curve's
//! frame, so the result does not depend on where the curve is or how large.
//!
//! **Chord tolerance.** Between two consecutive vertices of a polyline, the
//! curve's point at the middle parameter lies within `tolerance` of the chord
//! (default [`Cubic::DEFAULT_TOLERANCE`] times the viewport's diagonal; a
//! tolerance below `1e-10` of the diagonal is raised to it), and no chord is
//! longer than a twentieth of the diagonal. Every vertex lies on the curve
//! to rounding (one Newton step onto the curve). A trace places at most
//! about a million vertices, whatever the tolerance.
//!
//! Near a singular point (a node, where two branches cross) the two loops
//! that meet there are traced separately and meet at the node; an isolated
//! real point (an acnode) is not drawn. When every point found near the
//! viewport lies on a line component of the curve (a cubic made of lines),
//! the curve is divided by that line and the quotient conic is traced by
//! [`crate::Conic::polylines`].

// Comparisons are written `!(a > b)` on purpose: a NaN takes the failing
// branch.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub(crate) mod roots;
mod trace;

use nalgebra::{Point2, Vector2};

use crate::error::{InvalidInput, Result, finite};
use crate::geom::{Line, LocalFrame, Viewport};

pub use trace::{CubicComponent, CubicTrace};

/// Relative size (against the largest coefficient, which is 1) below which
/// a coefficient counts as zero for [`Cubic::degree`] and
/// [`Cubic::is_circular`].
const KIND_TOLERANCE: f64 = crate::tolerance::CUBIC_KIND;

/// A plane cubic curve `f(x, y) = 0` (see the module docs for the order of
/// the coefficients).
///
/// # Example
///
/// ```
/// use burmester::{Point2, Viewport};
/// use burmester::geom::Cubic;
/// // The folium-like cubic y^2 = x^3 - x: an oval and an unbounded branch.
/// let c = Cubic::new([0.0, -1.0, 0.0, 0.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0])?;
/// assert!(c.evaluate(Point2::new(1.0, 0.0)).abs() < 1e-15);
/// let trace = c.trace(&Viewport::new(-3.0, 3.0, -3.0, 3.0)?, None)?;
/// assert_eq!(trace.in_view(), 2);
/// assert!(trace.components.iter().any(|k| k.closed));
/// # Ok::<(), burmester::Error>(())
/// ```
#[derive(Clone, Copy, PartialEq)]
pub struct Cubic {
    /// Local coefficients, ascending order, largest magnitude 1.
    c: [f64; 10],
    origin: Point2<f64>,
    scale: f64,
}

crate::geom::debug_shows!(
    /// The degree and the ten coefficients in world coordinates (the order of
    /// [`Cubic::coefficients`]), not the local frame the cubic is kept in.
    Cubic,
    s => degree: s.degree(), coefficients: s.coefficients(),
);

crate::geom::local_frame!(Cubic);

impl Cubic {
    /// The default chord tolerance of [`Cubic::trace`] and
    /// [`Cubic::polylines`], relative to the viewport's diagonal.
    pub const DEFAULT_TOLERANCE: f64 = 1e-3;

    /// A cubic from its coefficients in the fixed frame, in the order
    /// `[c00, c10, c01, c20, c11, c02, c30, c21, c12, c03]`:
    ///
    /// ```text
    /// f(x, y) = c00 + c10 x + c01 y + c20 x^2 + c11 x y + c02 y^2
    ///         + c30 x^3 + c21 x^2 y + c12 x y^2 + c03 y^3
    /// ```
    ///
    /// Lower degrees (a conic, a line) are accepted.
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] when a coefficient is not finite, or when every
    /// coefficient but `c00` is zero (no curve).
    pub fn new(coefficients: [f64; 10]) -> Result<Self> {
        const NAMES: [&str; 10] = [
            "c00", "c10", "c01", "c20", "c11", "c02", "c30", "c21", "c12", "c03",
        ];
        for (n, v) in NAMES.iter().zip(coefficients) {
            finite(n, v)?;
        }
        if coefficients[1..].iter().all(|&v| v == 0.0) {
            return Err(InvalidInput::CubicCoefficients.into());
        }
        Ok(Self::from_local(coefficients, Point2::origin(), 1.0))
    }

    /// A cubic given in a local frame, `f((p - origin) / scale)`; the
    /// coefficients are divided by the largest in magnitude.
    pub(crate) fn from_local(c: [f64; 10], origin: Point2<f64>, scale: f64) -> Self {
        let m = c.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let c = if m > 0.0 && m.is_finite() {
            c.map(|v| v / m)
        } else {
            c
        };
        Cubic { c, origin, scale }
    }

    /// The coefficients in the fixed frame, in the order of [`Cubic::new`]
    /// (defined up to a positive factor). For a curve whose frame is far
    /// from the fixed origin or very large or small they may overflow; the
    /// local ones ([`Cubic::local_coefficients`]) never do.
    pub fn coefficients(&self) -> [f64; 10] {
        let b = -self.origin.coords / self.scale;
        let s = self.scale;
        let (s2, s3) = (s * s, s * s * s);
        let g = self.grad_local(b);
        let h = self.hessian_local(b);
        let c = &self.c;
        [
            self.eval_local(b),
            g.x / s,
            g.y / s,
            0.5 * h[0] / s2,
            h[1] / s2,
            0.5 * h[2] / s2,
            c[6] / s3,
            c[7] / s3,
            c[8] / s3,
            c[9] / s3,
        ]
    }

    /// The local coefficients (largest magnitude 1), the frame's origin and
    /// its unit length: `f(p) = sum c_ij u^i v^j` with `(u, v) = (p - origin) / scale`.
    pub fn local_coefficients(&self) -> ([f64; 10], Point2<f64>, f64) {
        (self.c, self.origin, self.scale)
    }

    /// The cubic of [`Cubic::local_coefficients`]: the same curve, bit for
    /// bit (for serialization, for example pickling in Python).
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for a non-finite number, a unit length that is not
    /// positive, or every coefficient but `c00` zero.
    pub fn from_local_coefficients(
        coefficients: [f64; 10],
        origin: Point2<f64>,
        scale: f64,
    ) -> Result<Self> {
        for v in coefficients {
            finite("cubic coefficient", v)?;
        }
        crate::error::finite_point(["cubic origin x", "cubic origin y"], origin)?;
        crate::error::positive("cubic unit length", scale)?;
        if coefficients[1..].iter().all(|&v| v == 0.0) {
            return Err(InvalidInput::CubicCoefficients.into());
        }
        Ok(Self::from_local(coefficients, origin, scale))
    }

    /// `f` at a local point.
    #[inline]
    pub(crate) fn eval_local(&self, v: Vector2<f64>) -> f64 {
        let c = &self.c;
        let (x, y) = (v.x, v.y);
        c[0] + y * (c[2] + y * (c[5] + y * c[9]))
            + x * (c[1] + y * (c[4] + y * c[8]) + x * (c[3] + y * c[7] + x * c[6]))
    }

    /// `sum |c_ij| |x|^i |y|^j`: the scale of the rounding error of
    /// [`Cubic::eval_local`].
    pub(crate) fn magnitude_local(&self, v: Vector2<f64>) -> f64 {
        magnitude(&self.c, v.x, v.y)
    }

    /// The value and the rounding scale of the curve at `p` when its local
    /// coefficients are each known to within `err` (in the units of the
    /// stored coefficients, whose largest is 1): `(f, B, |grad f|, m)` with
    /// `f` as [`Cubic::evaluate`] (`f(u m) / m^3`, `m` of
    /// [`LocalFrame::local_scaled`], 1 for points within `1e100` frame
    /// units), `B = sum (|c_ij| + err_ij) |u|^i |v|^j` the bound on the
    /// terms of that evaluation in the same scaling, and the gradient's
    /// length (local units) in the same scaling (`grad f(u m) / m^2`).
    /// `None` for a point whose local coordinates are not finite.
    pub(crate) fn value_and_bound(
        &self,
        p: Point2<f64>,
        err: &[f64; 10],
    ) -> Option<(f64, f64, f64, f64)> {
        let (u, m) = self.local_scaled(p);
        if !(u.iter().all(|v| v.is_finite()) && m.is_finite()) {
            return None;
        }
        let f = self.eval_scaled(u, m);
        let g = self.grad_scaled(u, m).norm();
        let a: [f64; 10] = core::array::from_fn(|i| self.c[i].abs() + err[i]);
        let (x, y) = (u.x.abs(), u.y.abs());
        let cubic = a[6] * x * x * x + a[7] * x * x * y + a[8] * x * y * y + a[9] * y * y * y;
        let quad = a[3] * x * x + a[4] * x * y + a[5] * y * y;
        let lin = a[1] * x + a[2] * y;
        let bound = if m == 1.0 {
            cubic + quad + lin + a[0]
        } else {
            cubic + (quad + (lin + a[0] / m) / m) / m
        };
        Some((f, bound, g, m))
    }

    /// Whether `p` is on the curve within the distance `tol`, and its
    /// first-order distance: on when the distance is at most `tol`, or when
    /// `f(p)` is zero within rounding (at a singular point the first-order
    /// distance means nothing). The four-pose curves use this rule with a
    /// band derived from their coefficients' rounding
    /// ([`ON_CURVE_TOLERANCE`](crate::tolerance::ON_CURVE_TOLERANCE)).
    ///
    /// ```
    /// use burmester::Point2;
    /// use burmester::geom::Cubic;
    ///
    /// // The nodal cubic y^2 = x^2 (x + 1): singular at the origin.
    /// let c = Cubic::new([0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0])?;
    /// assert!(c.is_on(Point2::new(0.0, 0.0), 1e-9).0);
    /// assert!(c.is_on(Point2::new(3.0, 6.0), 1e-9).0);
    /// assert!(!c.is_on(Point2::new(3.0, 6.1), 1e-9).0);
    /// # Ok::<(), burmester::Error>(())
    /// ```
    pub fn is_on(&self, p: Point2<f64>, tol: f64) -> (bool, f64) {
        let d = self.distance_estimate(p);
        if d <= tol {
            return (true, d);
        }
        (self.is_zero_local(self.local_of(p)), d)
    }

    /// Whether the curve's value at the local point `v` is zero within the
    /// rounding of its evaluation: the test [`Cubic::is_on`] falls back to
    /// at a singular point, where the distance estimate says nothing.
    pub(crate) fn is_zero_local(&self, v: Vector2<f64>) -> bool {
        v.iter().all(|x| x.is_finite())
            && self.eval_local(v).abs() <= 64.0 * f64::EPSILON * self.magnitude_local(v)
    }

    /// The gradient at a local point (local units).
    #[inline]
    pub(crate) fn grad_local(&self, v: Vector2<f64>) -> Vector2<f64> {
        Vector2::from(gradient(&self.c, v.x, v.y))
    }

    /// A bound on the terms of the gradient at a local point.
    pub(crate) fn grad_magnitude_local(&self, v: Vector2<f64>) -> f64 {
        let [gx, gy] = gradient(&self.c.map(f64::abs), v.x.abs(), v.y.abs());
        gx.hypot(gy)
    }

    /// The Hessian `[fxx, fxy, fyy]` at a local point.
    #[inline]
    pub(crate) fn hessian_local(&self, v: Vector2<f64>) -> [f64; 3] {
        hessian(&self.c, v.x, v.y)
    }

    /// The cubic part as a binary form `[c30, c21, c12, c03]`.
    #[inline]
    pub(crate) fn cubic_form(&self) -> [f64; 4] {
        [self.c[6], self.c[7], self.c[8], self.c[9]]
    }

    /// The most Newton steps of [`refine_on_line`](Self::refine_on_line).
    const REFINE_STEPS: usize = 64;

    /// A root `t` of `f(p + d t)` (local) refined by Newton steps on the
    /// curve's own value: the restriction's coefficients lose the digits
    /// that `p` far from the curve's frame cancels, the point's value does
    /// not. A step is kept only while it lowers `|f|`; from a root the
    /// cancellation put units of the plane away (a line from a point
    /// millions of task sizes out) Newton gains a factor of a few per step
    /// before it turns quadratic, so it may take up to
    /// [`REFINE_STEPS`](Self::REFINE_STEPS).
    pub(crate) fn refine_on_line(&self, p: Vector2<f64>, d: Vector2<f64>, mut t: f64) -> f64 {
        let mut f = self.eval_local(p + d * t);
        for _ in 0..Self::REFINE_STEPS {
            if f == 0.0 {
                break;
            }
            let slope = self.grad_local(p + d * t).dot(&d);
            let next = t - f / slope;
            if !next.is_finite() {
                break;
            }
            let fn_ = self.eval_local(p + d * next);
            if !(fn_.abs() < f.abs()) {
                break;
            }
            (t, f) = (next, fn_);
        }
        t
    }

    /// The restriction to the local line `p + t d`: `[a0, a1, a2, a3]` with
    /// `f(p + t d) = a0 + a1 t + a2 t^2 + a3 t^3` (exact for a cubic).
    pub(crate) fn restriction_local(&self, p: Vector2<f64>, d: Vector2<f64>) -> [f64; 4] {
        let g = self.grad_local(p);
        let h = self.hessian_local(p);
        let k = self.cubic_form();
        [
            self.eval_local(p),
            g.dot(&d),
            0.5 * (h[0] * d.x * d.x + 2.0 * h[1] * d.x * d.y + h[2] * d.y * d.y),
            roots::form_eval(&k, d.x, d.y),
        ]
    }

    /// `f(u m) / m^3` for `(u, m)` from [`Cubic::local_scaled`].
    fn eval_scaled(&self, u: Vector2<f64>, m: f64) -> f64 {
        if m == 1.0 {
            return self.eval_local(u);
        }
        let c = &self.c;
        let (x, y) = (u.x, u.y);
        let cubic = roots::form_eval(&self.cubic_form(), x, y);
        let quad = c[3] * x * x + c[4] * x * y + c[5] * y * y;
        let lin = c[1] * x + c[2] * y;
        cubic + (quad + (lin + c[0] / m) / m) / m
    }

    /// `grad f(u m) / m^2` for `(u, m)` from [`Cubic::local_scaled`].
    fn grad_scaled(&self, u: Vector2<f64>, m: f64) -> Vector2<f64> {
        if m == 1.0 {
            return self.grad_local(u);
        }
        let c = &self.c;
        let (x, y) = (u.x, u.y);
        Vector2::new(
            3.0 * c[6] * x * x
                + 2.0 * c[7] * x * y
                + c[8] * y * y
                + (2.0 * c[3] * x + c[4] * y + c[1] / m) / m,
            c[7] * x * x
                + 2.0 * c[8] * x * y
                + 3.0 * c[9] * y * y
                + (c[4] * x + 2.0 * c[5] * y + c[2] / m) / m,
        )
    }

    /// The value `f(p)` (up to the curve's positive factor): zero on the
    /// curve, its sign tells the side. Finite for every finite point (far
    /// points are evaluated scaled; see the module docs).
    pub fn evaluate(&self, p: Point2<f64>) -> f64 {
        let (u, m) = self.local_scaled(p);
        self.eval_scaled(u, m)
    }

    /// The gradient of `f` at `p`, in the fixed frame (with the factor of
    /// [`Cubic::evaluate`]: a point more than `1e100` units of the frame
    /// away, where the value is `f(p) / m^3`, has the gradient
    /// `grad f(p) / m^3`, so that `|f| / |grad f|` keeps its meaning).
    /// Finite for every finite point.
    pub fn gradient(&self, p: Point2<f64>) -> Vector2<f64> {
        let (u, m) = self.local_scaled(p);
        if m == 1.0 {
            return self.grad_local(u) / self.scale;
        }
        // grad f(u m) = m^2 grad_scaled, in fixed units over `scale`; over
        // `m^3`: grad_scaled / (m scale), with `m scale` the point's
        // distance from the frame's origin (finite).
        self.grad_scaled(u, m) / (m * self.scale)
    }

    /// First-order distance from `p` to the curve, `|f| / |grad f|`:
    /// accurate near the curve away from singular points. Zero on the
    /// curve; infinite where the gradient vanishes off the curve.
    pub fn distance_estimate(&self, p: Point2<f64>) -> f64 {
        let (u, m) = self.local_scaled(p);
        let val = self.eval_scaled(u, m).abs();
        if val == 0.0 {
            return 0.0;
        }
        let g = self.grad_scaled(u, m).norm();
        val / g * m * self.scale
    }

    /// The degree: 3, or less when the higher coefficients vanish (within a
    /// relative `1e-12`).
    pub fn degree(&self) -> usize {
        let c = &self.c;
        if c[6..].iter().any(|v| v.abs() > KIND_TOLERANCE) {
            3
        } else if c[3..6].iter().any(|v| v.abs() > KIND_TOLERANCE) {
            2
        } else {
            1
        }
    }

    /// Whether the cubic is **circular**: it passes through the circular
    /// points at infinity, i.e. its cubic part is `(x^2 + y^2) (a x + b y)`
    /// (`c30 = c12`, `c21 = c03`, within a relative `1e-12`). Center-point
    /// and circle-point curves are circular.
    pub fn is_circular(&self) -> bool {
        let c = &self.c;
        self.degree() == 3
            && (c[6] - c[8]).abs() <= KIND_TOLERANCE
            && (c[7] - c[9]).abs() <= KIND_TOLERANCE
    }

    /// The real asymptotic directions (unit vectors, angles in `[0, pi)`):
    /// where the cubic part vanishes. One for a circular cubic, up to three
    /// in general, none for a curve of lower degree.
    pub fn asymptotic_directions(&self) -> Vec<Vector2<f64>> {
        if self.degree() < 3 {
            return Vec::new();
        }
        roots::form_roots(&self.cubic_form())
            .into_iter()
            .map(|s| Vector2::new(s.cos(), s.sin()))
            .collect()
    }

    /// The points where the line `point + r direction` meets the curve
    /// (up to three, in the order of `r`). A line that lies on the curve
    /// (a line component) gives none.
    pub fn intersect_line(&self, line: &Line) -> Vec<Point2<f64>> {
        let p = self.local_of(line.point);
        let d = line.direction / self.scale;
        if !(p.iter().all(|v| v.is_finite()) && d.iter().all(|v| v.is_finite())) {
            return Vec::new();
        }
        let coeffs = self.restriction_local(p, d);
        roots::real_roots(&coeffs)
            .into_iter()
            .map(|r| self.global_of(p + d * self.refine_on_line(p, d, r)))
            .filter(|q| q.x.is_finite() && q.y.is_finite())
            .collect()
    }

    /// Every component of the curve that crosses `viewport`, traced into
    /// polylines (module docs). `tolerance` is the chord tolerance in the
    /// units of the plane (below `1e-10` of the viewport's diagonal it is
    /// raised to that); `None` gives [`Cubic::DEFAULT_TOLERANCE`] times the
    /// viewport's diagonal.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a tolerance that is NaN or infinite,
    /// [`InvalidInput::NotPositive`] for one that is zero or negative.
    pub fn trace(&self, viewport: &Viewport, tolerance: Option<f64>) -> Result<CubicTrace> {
        let tol = match tolerance {
            None => Self::default_tolerance(viewport),
            Some(t) => crate::error::positive("tolerance", t)?,
        };
        Ok(trace::trace(self, viewport, tol))
    }

    /// [`Cubic::DEFAULT_TOLERANCE`] times the viewport's diagonal.
    fn default_tolerance(viewport: &Viewport) -> f64 {
        viewport.diagonal() * Self::DEFAULT_TOLERANCE
    }

    /// The polylines of [`Cubic::polylines`] with the given points of the
    /// curve as vertices (see `trace::trace_marked`), each vertex with the
    /// index of the mark it is: the pieces between two marks are the
    /// curve's own, whatever the viewport. With a `cancel` flag the trace
    /// reads it every few thousand vertices (a trace may place up to a
    /// million).
    ///
    /// # Errors
    ///
    /// [`crate::Error::Cancelled`] (`0` of `0`) once `cancel` is set.
    pub(crate) fn polylines_marked(
        &self,
        viewport: &Viewport,
        marks: &[Point2<f64>],
        cancel: Option<&core::sync::atomic::AtomicBool>,
    ) -> Result<Vec<MarkedPolyline>> {
        trace::trace_marked(
            self,
            viewport,
            Self::default_tolerance(viewport),
            marks,
            cancel,
        )
    }

    /// The polylines of [`Cubic::trace`] with the default tolerance, every
    /// component together. A closed component in view is one polyline whose
    /// last point equals its first.
    pub fn polylines(&self, viewport: &Viewport) -> Vec<Vec<Point2<f64>>> {
        trace::trace(self, viewport, Self::default_tolerance(viewport)).polylines()
    }
}

/// A polyline whose vertices each come with the index of the mark they
/// are, if any ([`Cubic::polylines_marked`]).
pub(crate) type MarkedPolyline = Vec<(Point2<f64>, Option<usize>)>;

/// The gradient `[fx, fy]` at `(x, y)` of the cubic with the ascending
/// coefficients `c` (`c00, c10, c01, c20, c11, c02, c30, c21, c12, c03`).
#[inline]
pub(crate) fn gradient(c: &[f64; 10], x: f64, y: f64) -> [f64; 2] {
    [
        c[1] + 2.0 * c[3] * x + c[4] * y + 3.0 * c[6] * x * x + 2.0 * c[7] * x * y + c[8] * y * y,
        c[2] + c[4] * x + 2.0 * c[5] * y + c[7] * x * x + 2.0 * c[8] * x * y + 3.0 * c[9] * y * y,
    ]
}

/// `sum |c_ij| |x|^i |y|^j` for the cubic with the ascending coefficients
/// `c` (as [`gradient`]): the bound on the terms of its value at `(x, y)`,
/// and on its value anywhere in the box `|u| <= |x|`, `|v| <= |y|`.
#[inline]
pub(crate) fn magnitude(c: &[f64; 10], x: f64, y: f64) -> f64 {
    let c = c.map(f64::abs);
    let (x, y) = (x.abs(), y.abs());
    c[0] + y * (c[2] + y * (c[5] + y * c[9]))
        + x * (c[1] + y * (c[4] + y * c[8]) + x * (c[3] + y * c[7] + x * c[6]))
}

/// The Hessian `[fxx, fxy, fyy]` at `(x, y)` of the cubic with the
/// ascending coefficients `c`.
#[inline]
pub(crate) fn hessian(c: &[f64; 10], x: f64, y: f64) -> [f64; 3] {
    [
        2.0 * c[3] + 6.0 * c[6] * x + 2.0 * c[7] * y,
        c[4] + 2.0 * c[7] * x + 2.0 * c[8] * y,
        2.0 * c[5] + 2.0 * c[8] * x + 6.0 * c[9] * y,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn folium() -> Cubic {
        // y^2 = x^3 - x
        Cubic::new([0.0, -1.0, 0.0, 0.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0]).unwrap()
    }

    /// Issue 24, item 7: the gradient at a far point was `inf - inf`
    /// (NaN) where the value was scaled; now it has the value's factor:
    /// finite for every finite point, along the gradient's direction, and
    /// the same where both forms apply.
    #[test]
    fn far_gradients_are_scaled_like_the_value() {
        let c = Cubic::new(core::array::from_fn(|k| k as f64)).unwrap();
        for p in [
            Point2::new(-1e308, 1e308),
            Point2::new(f64::MAX, -f64::MAX),
            Point2::new(1e200, 3e150),
            Point2::new(-1e101, 2e101),
        ] {
            let g = c.gradient(p);
            assert!(
                g.x.is_finite() && g.y.is_finite() && g != Vector2::zeros(),
                "{p}: {g}"
            );
            // Far out the cubic part decides the direction.
            let (u, _) = c.local_scaled(p);
            let k = c.c;
            let cubic = Vector2::new(
                3.0 * k[6] * u.x * u.x + 2.0 * k[7] * u.x * u.y + k[8] * u.y * u.y,
                k[7] * u.x * u.x + 2.0 * k[8] * u.x * u.y + 3.0 * k[9] * u.y * u.y,
            );
            // Directions by a scale-safe norm: the gradient with the
            // value's factor is tiny out there (subnormal at 1e308).
            let unit = |v: Vector2<f64>| {
                let w = v / v.x.abs().max(v.y.abs());
                w / w.norm()
            };
            assert!((unit(g) - unit(cubic)).norm() < 1e-9, "{p}: {g} vs {cubic}");
            // |f| / |grad f| is the distance estimate's value.
            let d = c.evaluate(p).abs() / g.x.hypot(g.y);
            let e = c.distance_estimate(p);
            assert!((d - e).abs() <= 1e-12 * e, "{p}: {d} vs {e}");
        }
        // Near points: the plain gradient, bit for bit.
        let p = Point2::new(0.3, -2.0);
        assert_eq!(c.gradient(p), c.grad_local(c.local_of(p)) / c.scale);
    }

    #[test]
    fn local_coefficients_round_trip() {
        let c = Cubic::from_local(
            [0.3, -1.0, 0.2, 0.1, 0.7, -0.4, 0.9, 0.1, 0.9, 0.1],
            Point2::new(1.5, -2.0),
            3.0,
        );
        let (k, o, s) = c.local_coefficients();
        assert_eq!(Cubic::from_local_coefficients(k, o, s).unwrap(), c);
        assert!(Cubic::from_local_coefficients(k, o, 0.0).is_err());
        assert!(Cubic::from_local_coefficients(k, Point2::new(f64::NAN, 0.0), s).is_err());
        let mut bad = k;
        bad[3] = f64::INFINITY;
        assert!(Cubic::from_local_coefficients(bad, o, s).is_err());
        let mut constant = [0.0; 10];
        constant[0] = 1.0;
        assert!(Cubic::from_local_coefficients(constant, o, s).is_err());
    }

    #[test]
    fn evaluation_and_frames() {
        let c = folium();
        for x in [-0.5f64, 1.5, 3.0] {
            let y2 = x * x * x - x;
            if y2 >= 0.0 {
                assert!(c.evaluate(Point2::new(x, y2.sqrt())).abs() < 1e-14);
            }
        }
        // The same curve in a shifted, scaled frame.
        let (o, s) = (Point2::new(3.0, -2.0), 0.25);
        let k = c.coefficients();
        let shifted = {
            let ev = |p: Point2<f64>| c.evaluate(p);
            // Local coefficients by finite differences are not exact; use the
            // Taylor form instead.
            let b = o.coords;
            let g = c.grad_local(b);
            let h = c.hessian_local(b);
            let _ = ev;
            Cubic::from_local(
                [
                    c.eval_local(b),
                    g.x * s,
                    g.y * s,
                    0.5 * h[0] * s * s,
                    h[1] * s * s,
                    0.5 * h[2] * s * s,
                    k[6] * s * s * s,
                    k[7] * s * s * s,
                    k[8] * s * s * s,
                    k[9] * s * s * s,
                ],
                o,
                s,
            )
        };
        let k2 = shifted.coefficients();
        let f = k[6] / k2[6];
        for i in 0..10 {
            assert!((k[i] - f * k2[i]).abs() < 1e-12, "{k:?} {k2:?}");
        }
        let p = Point2::new(0.3, 0.7);
        assert!((c.evaluate(p) - f * shifted.evaluate(p)).abs() < 1e-12);
        // Far points keep their sign and stay finite.
        let far = Point2::new(1e200, 1e199);
        assert!(c.evaluate(far) > 0.0 && c.evaluate(far).is_finite());
        assert!(c.distance_estimate(far).is_finite());
        assert_eq!(c.degree(), 3);
        assert!(!c.is_circular());
        assert_eq!(c.asymptotic_directions().len(), 1);
    }

    #[test]
    fn lines_meet_in_up_to_three_points() {
        let c = folium();
        let pts = c.intersect_line(&Line {
            point: Point2::new(0.0, 0.0),
            direction: Vector2::new(1.0, 0.0),
        });
        assert_eq!(pts.len(), 3);
        for (p, x) in pts.iter().zip([-1.0, 0.0, 1.0]) {
            assert!((p.x - x).abs() < 1e-14 && p.y.abs() < 1e-14, "{pts:?}");
        }
    }

    #[test]
    fn bad_coefficients_are_rejected() {
        assert!(Cubic::new([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]).is_err());
        assert!(Cubic::new([0.0, f64::NAN, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]).is_err());
    }
}
