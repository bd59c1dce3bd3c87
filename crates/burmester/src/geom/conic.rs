//! General plane conics `A x^2 + B x y + C y^2 + D x + E y + F = 0`: kind,
//! center, axes, asymptotes, evaluation, and sampling into polylines clipped
//! to a viewport.
//!
//! # Sampling
//!
//! A conic through a known point `Q` is parametrized exactly by the pencil
//! of lines through `Q`: the line along `w = (cos s, sin s)` meets the conic
//! again at
//!
//! ```text
//! Y(s) = Q + t(s) w,    t(s) = -(grad q(Q) . w) / (w^T M w)
//! ```
//!
//! where `M` is the matrix of the quadratic part. As `s` runs over half a
//! turn this traces the whole conic once. The denominator vanishes exactly
//! at the asymptote directions, so the parameter intervals between its roots
//! are the branches: a hyperbola gives two, a parabola one, an ellipse one
//! closed loop. Each branch is followed out to beyond the viewport (the
//! parts near the asymptotes are included), sampled adaptively, and clipped
//! to the viewport (parry's AABB line clipping); no segment ever joins two
//! branches across infinity.

use core::f64::consts::{FRAC_PI_2, PI};

use nalgebra::{Matrix3, Point2, Vector2};
use parry2d_f64::bounding_volume::Aabb;

use crate::error::{InvalidInput, Result, finite};
use crate::geom::{Line, LocalFrame, Viewport, cross, segment_distance};

/// Relative tolerance of the kind tests (parabola, degenerate).
const KIND_TOLERANCE: f64 = crate::tolerance::CONIC_KIND;

/// The kind of a conic.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ConicKind {
    /// `B^2 - 4AC < 0`, non-degenerate (possibly with no real points).
    Ellipse,
    /// `B^2 - 4AC > 0`, non-degenerate.
    Hyperbola,
    /// `B^2 - 4AC = 0`, non-degenerate.
    Parabola,
    /// The 3x3 determinant vanishes: a pair of lines, a double line, a
    /// point, or nothing.
    Degenerate,
}

impl ConicKind {
    /// `"ellipse"`, `"hyperbola"`, `"parabola"` or `"degenerate"`.
    pub fn as_str(self) -> &'static str {
        match self {
            ConicKind::Ellipse => "ellipse",
            ConicKind::Hyperbola => "hyperbola",
            ConicKind::Parabola => "parabola",
            ConicKind::Degenerate => "degenerate",
        }
    }
}

impl core::fmt::Display for ConicKind {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A conic `A x^2 + B x y + C y^2 + D x + E y + F = 0`.
///
/// Stored in a local frame (an origin and a unit length) with its
/// coefficients scaled so that the largest is 1 in magnitude: the value
/// `q(p)` is defined up to a positive factor, which keeps every sign test
/// meaningful while no evaluation overflows.
///
/// # Example
///
/// ```
/// use burmester::{Conic, ConicKind, Point2};
/// // x^2 - y^2 = 1
/// let h = Conic::new(1.0, 0.0, -1.0, 0.0, 0.0, -1.0)?;
/// assert_eq!(h.kind(), ConicKind::Hyperbola);
/// assert!(h.evaluate(Point2::new(1.0, 0.0)).abs() < 1e-15);
/// # Ok::<(), burmester::Error>(())
/// ```
#[derive(Clone, Copy, PartialEq)]
pub struct Conic {
    /// Local coefficients `[A, B, C, D, E, F]`, max magnitude 1.
    q: [f64; 6],
    origin: Point2<f64>,
    scale: f64,
    /// A point on the conic, local, if one is known exactly.
    known: Option<Vector2<f64>>,
}

crate::geom::debug_shows!(
    /// The kind and the coefficients `[A, B, C, D, E, F]` of
    /// `A x^2 + B x y + C y^2 + D x + E y + F = 0` in world coordinates, not
    /// the local frame the conic is kept in.
    Conic,
    s => kind: s.kind(), coefficients: s.coefficients(),
);

crate::geom::local_frame!(Conic);

impl Conic {
    /// A conic from its coefficients in the fixed frame.
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] when a coefficient is not finite, or when `A, B, C,
    /// D, E` are all zero (no curve).
    pub fn new(a: f64, b: f64, c: f64, d: f64, e: f64, f: f64) -> Result<Self> {
        let names = ["A", "B", "C", "D", "E", "F"];
        let q = [a, b, c, d, e, f];
        for (n, v) in names.iter().zip(q) {
            finite(n, v)?;
        }
        // After scaling to a largest coefficient of 1, so that a quadratic
        // part that underflows against `F` (say `1e-300` beside `1e300`)
        // is refused as it would be by `from_parts`.
        let c = Self::local(q, Point2::origin(), 1.0, None);
        if c.q[..5].iter().all(|&v| v == 0.0) {
            return Err(InvalidInput::ConicCoefficients.into());
        }
        Ok(c)
    }

    /// The conic's exact stored form: its local coefficients (largest 1 in
    /// magnitude), the local frame's origin and unit, and a local point
    /// known to lie on it. [`Conic::from_parts`] rebuilds the same conic,
    /// bit for bit (for serialization).
    pub fn to_parts(&self) -> ([f64; 6], Point2<f64>, f64, Option<Vector2<f64>>) {
        (self.q, self.origin, self.scale, self.known)
    }

    /// The conic of [`Conic::to_parts`].
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for a non-finite number, a unit that is not
    /// positive, or `A, B, C, D, E` all zero.
    pub fn from_parts(
        q: [f64; 6],
        origin: Point2<f64>,
        scale: f64,
        known: Option<Vector2<f64>>,
    ) -> Result<Self> {
        for v in q {
            finite("conic coefficient", v)?;
        }
        crate::error::finite_point(["conic origin x", "conic origin y"], origin)?;
        crate::error::positive("conic unit length", scale)?;
        if let Some(k) = known {
            crate::error::finite_point(["known point x", "known point y"], Point2::from(k))?;
        }
        if q[..5].iter().all(|&v| v == 0.0) {
            return Err(InvalidInput::ConicCoefficients.into());
        }
        Ok(Self::local(q, origin, scale, known))
    }

    /// A conic given in a local frame: `q((Y - origin) / scale)`, with an
    /// optional local point known to lie on it.
    pub(crate) fn local(
        q: [f64; 6],
        origin: Point2<f64>,
        scale: f64,
        known: Option<Vector2<f64>>,
    ) -> Self {
        let m = q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let q = if m > 0.0 && m.is_finite() {
            q.map(|v| v / m)
        } else {
            q
        };
        Conic {
            q,
            origin,
            scale,
            known,
        }
    }

    /// The coefficients `[A, B, C, D, E, F]` in the fixed frame (defined
    /// up to a positive factor).
    pub fn coefficients(&self) -> [f64; 6] {
        let [a, b, c, d, e, f] = self.q;
        let (ox, oy) = (self.origin.x, self.origin.y);
        let s = self.scale;
        let s2 = s * s;
        [
            a / s2,
            b / s2,
            c / s2,
            (-2.0 * a * ox - b * oy) / s2 + d / s,
            (-b * ox - 2.0 * c * oy) / s2 + e / s,
            (a * ox * ox + b * ox * oy + c * oy * oy) / s2 - (d * ox + e * oy) / s + f,
        ]
    }

    /// The local coefficients, origin and unit length.
    pub fn local_coefficients(&self) -> ([f64; 6], Point2<f64>, f64) {
        (self.q, self.origin, self.scale)
    }

    /// `q` in local coordinates, associated as `x (A x + l) + k` with the
    /// row terms `l = B y + D`, `k = y (C y + E) + F` (see [`Conic::row`]),
    /// so that a grid sweep that precomputes the row terms gets the same
    /// bits as a point evaluation.
    #[inline(always)]
    fn eval_local(&self, x: f64, y: f64) -> f64 {
        let (a, l, k) = self.row(y);
        x * (a * x + l) + k
    }

    /// The quadratic along the local row `y`: `(A, l, k)` with
    /// `q(x, y) = x (A x + l) + k`.
    #[inline(always)]
    pub(crate) fn row(&self, y: f64) -> (f64, f64, f64) {
        let [a, b, c, d, e, f] = self.q;
        (a, b * y + d, y * (c * y + e) + f)
    }

    /// A bound on the rounding error of [`Conic::row`] and the evaluation
    /// along the row at local `x`: the sum of the magnitudes of the terms.
    #[inline]
    pub(crate) fn row_magnitude(&self, x: f64, y: f64) -> f64 {
        let [a, b, c, d, e, f] = self.q;
        a.abs() * x * x
            + (b.abs() * y.abs() + d.abs()) * x.abs()
            + y.abs() * (c.abs() * y.abs() + e.abs())
            + f.abs()
    }

    /// The local frame: `(origin, scale)`.
    pub(crate) fn frame(&self) -> (Point2<f64>, f64) {
        (self.origin, self.scale)
    }

    #[inline(always)]
    fn grad_local(&self, p: Vector2<f64>) -> Vector2<f64> {
        let [a, b, c, d, e, _] = self.q;
        Vector2::new(2.0 * a * p.x + b * p.y + d, b * p.x + 2.0 * c * p.y + e)
    }

    #[inline(always)]
    fn quad_local(&self, w: Vector2<f64>) -> f64 {
        let [a, b, c, ..] = self.q;
        a * w.x * w.x + b * w.x * w.y + c * w.y * w.y
    }

    /// `q(v m) / m^2` for `(v, m)` from [`Conic::local_scaled`]: the plain
    /// evaluation when `m = 1`.
    #[inline]
    fn eval_scaled(&self, v: Vector2<f64>, m: f64) -> f64 {
        if m == 1.0 {
            return self.eval_local(v.x, v.y);
        }
        let [.., d, e, f] = self.q;
        self.quad_local(v) + (d * v.x + e * v.y) / m + f / m / m
    }

    /// `grad q(v m) / m` for `(v, m)` from [`Conic::local_scaled`].
    #[inline]
    fn grad_scaled(&self, v: Vector2<f64>, m: f64) -> Vector2<f64> {
        if m == 1.0 {
            return self.grad_local(v);
        }
        let [a, b, c, d, e, _] = self.q;
        Vector2::new(
            2.0 * a * v.x + b * v.y + d / m,
            b * v.x + 2.0 * c * v.y + e / m,
        )
    }

    /// [`evaluate`](Self::evaluate) of a point checked to be finite.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a non-finite point.
    pub fn try_evaluate(&self, p: Point2<f64>) -> Result<f64> {
        crate::error::finite_point(["point x", "point y"], p)?;
        Ok(self.evaluate(p))
    }

    /// The value `q(p)` (up to the conic's positive factor): zero on the
    /// curve, and its sign tells the side.
    ///
    /// Finite for every finite point: a point more than `1e100` units of the
    /// conic's frame away (see [`Conic::local_coefficients`]) is evaluated
    /// as `q(p) / m^2` with `m` its distance in those units, which has the
    /// same sign.
    #[inline]
    pub fn evaluate(&self, p: Point2<f64>) -> f64 {
        let (v, m) = self.local_scaled(p);
        self.eval_scaled(v, m)
    }

    /// The sign of [`evaluate`](Self::evaluate): `1`, `-1`, or `0` on the curve.
    pub fn side(&self, p: Point2<f64>) -> i8 {
        let v = self.evaluate(p);
        if v > 0.0 {
            1
        } else if v < 0.0 {
            -1
        } else {
            0
        }
    }

    /// The gradient of `q` at `p`, in the fixed frame.
    pub fn gradient(&self, p: Point2<f64>) -> Vector2<f64> {
        self.grad_local(self.local_of(p)) / self.scale
    }

    /// First-order distance from `p` to the curve, `|q| / |grad q|` (exact
    /// for lines, accurate near the curve). Infinite where the gradient
    /// vanishes off the curve.
    pub fn distance_estimate(&self, p: Point2<f64>) -> f64 {
        let (v, m) = self.local_scaled(p);
        let g = self.grad_scaled(v, m);
        // `hypot`, not `norm`: a gradient of `1e-300` does not underflow.
        let g = g.x.hypot(g.y);
        let val = self.eval_scaled(v, m).abs();
        if val == 0.0 {
            0.0
        } else {
            val / g * m * self.scale
        }
    }

    /// `B^2 - 4AC` of the local coefficients (its sign is the kind's).
    fn discriminant(&self) -> f64 {
        let [a, b, c, ..] = self.q;
        b * b - 4.0 * a * c
    }

    fn matrix3(&self) -> Matrix3<f64> {
        let [a, b, c, d, e, f] = self.q;
        Matrix3::new(
            a,
            0.5 * b,
            0.5 * d,
            0.5 * b,
            c,
            0.5 * e,
            0.5 * d,
            0.5 * e,
            f,
        )
    }

    /// Whether the conic is degenerate (its 3x3 matrix is singular within
    /// a relative `1e-12`).
    pub fn is_degenerate(&self) -> bool {
        let [a, b, c, ..] = self.q;
        if a == 0.0 && b == 0.0 && c == 0.0 {
            return true;
        }
        let m = self.matrix3();
        let n = m.norm();
        m.determinant().abs() <= KIND_TOLERANCE * n * n * n
    }

    /// The kind: ellipse, hyperbola, parabola or degenerate. `B^2 - 4AC`
    /// within a relative `1e-12` of zero counts as a parabola.
    pub fn kind(&self) -> ConicKind {
        if self.is_degenerate() {
            return ConicKind::Degenerate;
        }
        let [a, b, c, ..] = self.q;
        let disc = self.discriminant();
        if disc.abs() <= KIND_TOLERANCE * (a * a + b * b + c * c) {
            ConicKind::Parabola
        } else if disc < 0.0 {
            ConicKind::Ellipse
        } else {
            ConicKind::Hyperbola
        }
    }

    /// The eigen-decomposition of the quadratic part: `(angle, l1, l2)`
    /// with `l1 >= l2` the eigenvalues for the directions `angle` and
    /// `angle + pi/2`; `angle = atan2(B, A - C) / 2` in `(-pi/2, pi/2]`.
    fn eigen(&self) -> (f64, f64, f64) {
        let [a, b, c, ..] = self.q;
        let angle = 0.5 * b.atan2(a - c);
        let mean = 0.5 * (a + c);
        let r = (0.5 * (a - c)).hypot(0.5 * b);
        (angle, mean + r, mean - r)
    }

    /// The direction of a principal axis, as an angle in `(-pi/2, pi/2]`;
    /// the other axis is at right angles (the pair is defined modulo
    /// `pi/2`). Zero for a circle.
    pub fn axis_angle(&self) -> f64 {
        self.eigen().0
    }

    /// The center (where the gradient vanishes), if unique: ellipses,
    /// hyperbolas and crossing line pairs have one; parabolas do not.
    pub fn center(&self) -> Option<Point2<f64>> {
        let [a, b, c, d, e, _] = self.q;
        let det = 4.0 * a * c - b * b;
        if det.abs() <= KIND_TOLERANCE * (a * a + b * b + c * c) {
            return None;
        }
        let x = (b * e - 2.0 * c * d) / det;
        let y = (b * d - 2.0 * a * e) / det;
        let p = self.global_of(Vector2::new(x, y));
        (p.x.is_finite() && p.y.is_finite()).then_some(p)
    }

    /// The directions (unit, as angles in `[0, pi)`) along which the
    /// quadratic part vanishes: two for a hyperbola or crossing lines, one
    /// for a parabola, none for an ellipse.
    fn null_directions(&self) -> Vec<f64> {
        let [a, b, c, ..] = self.q;
        let (angle, l1, l2) = self.eigen();
        let scale = (a * a + b * b + c * c).sqrt();
        if scale == 0.0 {
            return Vec::new();
        }
        let tol = KIND_TOLERANCE * scale;
        let norm = |t: f64| t.rem_euclid(PI);
        if l1.abs() <= tol && l2.abs() <= tol {
            Vec::new()
        } else if l1.abs() <= tol {
            vec![norm(angle)]
        } else if l2.abs() <= tol {
            vec![norm(angle + FRAC_PI_2)]
        } else if l1 * l2 < 0.0 {
            let alpha = (-l1 / l2).sqrt().atan();
            let mut v = vec![norm(angle + alpha), norm(angle - alpha)];
            v.sort_by(f64::total_cmp);
            v
        } else {
            Vec::new()
        }
    }

    /// The asymptotes of a hyperbola (through its center), else `None`.
    /// Directions are unit vectors.
    pub fn asymptotes(&self) -> Option<[Line; 2]> {
        if self.kind() != ConicKind::Hyperbola {
            return None;
        }
        let center = self.center()?;
        let dirs = self.null_directions();
        if dirs.len() != 2 {
            return None;
        }
        Some([dirs[0], dirs[1]].map(|t| Line {
            point: center,
            direction: Vector2::new(t.cos(), t.sin()),
        }))
    }

    /// Points where the line `point + r * direction` meets the conic (zero,
    /// one or two, in order of `r`). An intersection too far away to be
    /// represented (a line nearly along an asymptote) is left out.
    pub fn intersect_line(&self, line: &Line) -> Vec<Point2<f64>> {
        let p = self.local_of(line.point);
        let w = line.direction / self.scale;
        roots_on_line(self, p, w)
            .into_iter()
            .map(|r| self.global_of(p + w * r))
            .filter(|q| q.x.is_finite() && q.y.is_finite())
            .collect()
    }

    /// A point on the conic near the viewport, in local coordinates.
    fn find_point(&self, near: Vector2<f64>) -> Option<Vector2<f64>> {
        if let Some(k) = self.known {
            return Some(k);
        }
        let center = self.center().map(|c| self.local_of(c));
        let (angle, ..) = self.eigen();
        let mut dirs = vec![
            Vector2::new(1.0, 0.0),
            Vector2::new(0.0, 1.0),
            Vector2::new(angle.cos(), angle.sin()),
            Vector2::new(-angle.sin(), angle.cos()),
        ];
        dirs.extend(
            self.null_directions()
                .iter()
                .map(|t| Vector2::new(t.cos(), t.sin())),
        );
        for base in center.into_iter().chain([near, Vector2::zeros()]) {
            for w in &dirs {
                if let Some(r) = roots_on_line(self, base, *w).first() {
                    return Some(base + w * *r);
                }
            }
        }
        None
    }

    /// The smallest chord tolerance of [`Conic::polylines`], relative to
    /// the viewport's diagonal.
    pub const MIN_RELATIVE_TOLERANCE: f64 = 1e-9;

    /// The most points [`Conic::polylines`] returns.
    pub const MAX_POLYLINE_POINTS: usize = 10_000_000;

    /// The largest viewport diagonal of [`Conic::polylines`] (beyond, the
    /// sampler's differences of coordinates could overflow).
    pub const MAX_VIEWPORT_DIAGONAL: f64 = 1e300;

    /// The curve sampled into polylines clipped to `viewport`, each
    /// branch separately and never joined across infinity.
    ///
    /// `tolerance` is the largest distance between the curve and a chord, in
    /// the units of the plane, from [`Conic::MIN_RELATIVE_TOLERANCE`] times
    /// the viewport's diagonal to the diagonal; pass `None` for a
    /// thousandth of the diagonal.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::OutsideRange`] for a tolerance outside that range
    /// (or not finite); [`InvalidInput::TooLarge`] when the curve would
    /// need more than [`Conic::MAX_POLYLINE_POINTS`] points (a nearly
    /// degenerate conic at a fine tolerance), or for a viewport whose
    /// diagonal is beyond [`Conic::MAX_VIEWPORT_DIAGONAL`].
    pub fn polylines(
        &self,
        viewport: &Viewport,
        tolerance: Option<f64>,
    ) -> Result<Vec<Vec<Point2<f64>>>> {
        let diag = viewport.diagonal();
        // Not `>`: an overflowed (infinite) diagonal fails too.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(diag <= Self::MAX_VIEWPORT_DIAGONAL) {
            return Err(InvalidInput::TooLarge {
                name: "viewport diagonal",
                value: diag,
                limit: Self::MAX_VIEWPORT_DIAGONAL,
                hint: "pass a smaller viewport",
            }
            .into());
        }
        let tol = match tolerance {
            None => diag * 1e-3,
            Some(t) => crate::error::in_range(
                "tolerance",
                t,
                Self::MIN_RELATIVE_TOLERANCE * diag,
                diag,
                " (plane units: 1e-9 to 1 times the viewport's diagonal)",
            )?,
        } / self.scale;
        let lo = self.local_of(Point2::new(viewport.xmin, viewport.ymin));
        let hi = self.local_of(Point2::new(viewport.xmax, viewport.ymax));
        if self.misses_box(lo, hi) {
            return Ok(Vec::new());
        }
        let aabb = Aabb::new(
            parry2d_f64::math::Vector::new(lo.x, lo.y),
            parry2d_f64::math::Vector::new(hi.x, hi.y),
        );
        let mut sampler = Sampler {
            conic: self,
            lo,
            hi,
            aabb,
            tol,
            center: (lo + hi) * 0.5,
            radius: 0.5 * (hi - lo).norm(),
            out: Vec::new(),
            current: Vec::new(),
            points: 0,
        };
        if let Some((p, w)) = self.line_in_box(lo, hi, tol) {
            sampler.line(p, w);
        } else if self.kind() == ConicKind::Degenerate {
            for line in self.degenerate_lines(sampler.center) {
                sampler.line(line.0, line.1);
            }
        } else if let Some(q) = self.find_point(sampler.center) {
            self.sample_branches(q, &mut sampler);
        }
        if sampler.points > Self::MAX_POLYLINE_POINTS {
            return Err(InvalidInput::TooLarge {
                name: "the number of polyline points",
                value: sampler.points as f64,
                limit: Self::MAX_POLYLINE_POINTS as f64,
                hint: "pass a larger tolerance",
            }
            .into());
        }
        Ok(sampler
            .out
            .into_iter()
            .map(|pl| pl.into_iter().map(|v| self.global_of(v)).collect())
            .collect())
    }

    /// Whether the conic has no point in the local box `[lo, hi]`: its
    /// constant term outweighs a bound of the rest over the box (taken
    /// about the local origin, so over a larger box). The kind's relative
    /// test cannot say this: a constant term that dominates the rest (a
    /// quotient conic of a cubic whose other terms are rounding) makes the
    /// matrix singular within `1e-12` of its norm, and its "line pair" would
    /// be drawn where the curve is not.
    fn misses_box(&self, lo: Vector2<f64>, hi: Vector2<f64>) -> bool {
        let [_, _, _, d, e, f] = self.q;
        let (quadratic, rx, ry) = self.quadratic_in_box(lo, hi);
        let rest = quadratic + d.abs() * rx + e.abs() * ry;
        // Well beyond the rounding of either side; false for NaN or infinity.
        f.abs() > rest * (1.0 + 1e-9)
    }

    /// A bound of the quadratic terms over the local box `lo..hi`,
    /// `|A| rx^2 + |B| rx ry + |C| ry^2`, with the box's reach `rx`, `ry`
    /// (the largest `|x|`, `|y|` in it).
    fn quadratic_in_box(&self, lo: Vector2<f64>, hi: Vector2<f64>) -> (f64, f64, f64) {
        let [a, b, c, ..] = self.q;
        let rx = lo.x.abs().max(hi.x.abs());
        let ry = lo.y.abs().max(hi.y.abs());
        (
            a.abs() * rx * rx + b.abs() * rx * ry + c.abs() * ry * ry,
            rx,
            ry,
        )
    }

    /// The line `D x + E y + F = 0` (local point and direction) where the
    /// quadratic terms, bounded over the local box `lo..hi`, move the curve
    /// from it by at most a thousandth of the chord tolerance `tol` (local
    /// units) there: every point of the conic in the box is then within
    /// that of the line and the line within it of the conic (its other
    /// points lie beyond `|(D, E)| / |(A, B, C)|`, far out). Such a conic's
    /// matrix is singular within rounding of its norm: taken for a line
    /// pair (through a far center, or none for an isolated point), it drew
    /// lines where the curve is not, or nothing where it crosses the view
    /// (issue 24; the four-pose tracer met it in its quotient conics).
    fn line_in_box(
        &self,
        lo: Vector2<f64>,
        hi: Vector2<f64>,
        tol: f64,
    ) -> Option<(Vector2<f64>, Vector2<f64>)> {
        let [_, _, _, d, e, f] = self.q;
        let (quadratic, _, _) = self.quadratic_in_box(lo, hi);
        let n = Vector2::new(d, e);
        let g = n.norm();
        // False for NaN or infinity.
        if !(g > 0.0 && quadratic <= 1e-3 * tol * g) {
            return None;
        }
        Some((-n * (f / (g * g)), Vector2::new(-e, d)))
    }

    /// The lines of a degenerate conic (local point and direction).
    fn degenerate_lines(&self, near: Vector2<f64>) -> Vec<(Vector2<f64>, Vector2<f64>)> {
        let [a, b, c, d, e, f] = self.q;
        if a == 0.0 && b == 0.0 && c == 0.0 {
            // A single line D x + E y + F = 0.
            let n = Vector2::new(d, e);
            let n2 = n.norm_squared();
            if n2 == 0.0 {
                return Vec::new();
            }
            return vec![(-n * (f / n2), Vector2::new(-e, d))];
        }
        let dirs = self.null_directions();
        if let Some(center) = self.center() {
            let c0 = self.local_of(center);
            // Crossing lines through the center (none if it is an isolated point).
            return dirs
                .iter()
                .map(|t| (c0, Vector2::new(t.cos(), t.sin())))
                .collect();
        }
        // Parallel or double lines along the null direction.
        let Some(&t) = dirs.first() else {
            return Vec::new();
        };
        let w = Vector2::new(t.cos(), t.sin());
        let n = Vector2::new(-w.y, w.x);
        roots_on_line(self, near, n)
            .into_iter()
            .map(|r| (near + n * r, w))
            .collect()
    }

    /// Samples every branch through the pencil of lines at `q`.
    fn sample_branches(&self, q: Vector2<f64>, sampler: &mut Sampler) {
        let g = self.grad_local(q);
        let t_of = |s: f64| {
            let w = Vector2::new(s.cos(), s.sin());
            -g.dot(&w) / self.quad_local(w)
        };
        let point = |s: f64| {
            let w = Vector2::new(s.cos(), s.sin());
            q + w * t_of(s)
        };
        let breaks = self.null_directions();
        // Far enough that the curve is off the viewport.
        let far = 4.0 * ((q - sampler.center).norm() + sampler.radius);
        if breaks.is_empty() {
            // Ellipse: a closed loop starting and ending at q (tangent direction).
            let s0 = g.y.atan2(g.x) + FRAC_PI_2;
            sampler.sample(&point, s0, s0 + PI);
            sampler.finish();
            return;
        }
        let mut intervals = Vec::new();
        for (k, &b) in breaks.iter().enumerate() {
            let next = if k + 1 < breaks.len() {
                breaks[k + 1]
            } else {
                breaks[0] + PI
            };
            intervals.push((b, next));
        }
        for (a, b) in intervals {
            let Some(s_lo) = trim(&t_of, a, 0.5 * (a + b), far) else {
                continue;
            };
            let Some(s_hi) = trim(&t_of, b, 0.5 * (a + b), far) else {
                continue;
            };
            sampler.sample(&point, s_lo, s_hi);
            sampler.finish();
        }
    }
}

/// The parameter nearest to the pole `at` (toward `mid`) where `|t|`
/// exceeds `far`: steps geometrically toward the pole.
fn trim(t_of: &impl Fn(f64) -> f64, at: f64, mid: f64, far: f64) -> Option<f64> {
    let mut step = mid - at;
    for _ in 0..1100 {
        step *= 0.5;
        let s = at + step;
        if s == at {
            return Some(at + step * 2.0);
        }
        let t = t_of(s);
        if t.abs() > far && t_of(at + 0.5 * step).abs() > t.abs() {
            return Some(s);
        }
    }
    None
}

/// Real roots `r` of `q(p + r w) = 0`, sorted.
fn roots_on_line(c: &Conic, p: Vector2<f64>, w: Vector2<f64>) -> Vec<f64> {
    let alpha = c.quad_local(w);
    let beta = c.grad_local(p).dot(&w);
    let gamma = c.eval_local(p.x, p.y);
    let size = alpha.abs() + beta.abs() + gamma.abs();
    if size == 0.0 || !size.is_finite() {
        return Vec::new();
    }
    if alpha.abs() <= 1e-14 * size {
        if beta == 0.0 {
            return Vec::new();
        }
        return vec![-gamma / beta];
    }
    let disc = beta * beta - 4.0 * alpha * gamma;
    if disc < 0.0 {
        return Vec::new();
    }
    let sq = disc.sqrt();
    let qq = -0.5 * (beta + beta.signum() * sq);
    let mut r = if qq == 0.0 {
        vec![0.0]
    } else {
        vec![qq / alpha, gamma / qq]
    };
    r.retain(|v| v.is_finite());
    r.sort_by(f64::total_cmp);
    r
}

/// Adaptive sampling and viewport clipping, in local coordinates.
struct Sampler<'a> {
    conic: &'a Conic,
    /// The viewport's corners (local).
    lo: Vector2<f64>,
    hi: Vector2<f64>,
    aabb: Aabb,
    tol: f64,
    center: Vector2<f64>,
    radius: f64,
    out: Vec<Vec<Vector2<f64>>>,
    current: Vec<Vector2<f64>>,
    /// Points emitted so far; past [`Conic::MAX_POLYLINE_POINTS`] sampling
    /// stops.
    points: usize,
}

impl Sampler<'_> {
    const INITIAL: usize = 256;
    const MAX_DEPTH: u32 = 24;

    /// A whole line, clipped.
    fn line(&mut self, p: Vector2<f64>, w: Vector2<f64>) {
        let v = |v: Vector2<f64>| parry2d_f64::math::Vector::new(v.x, v.y);
        if let Some((t0, t1)) = self.aabb.clip_line_parameters(v(p), v(w)) {
            // Clamped: from a far `p` the ends are on the edges only up to
            // the rounding of `p`.
            let clamp = |q: Vector2<f64>| {
                Vector2::new(
                    q.x.clamp(self.lo.x, self.hi.x),
                    q.y.clamp(self.lo.y, self.hi.y),
                )
            };
            let (a, b) = (clamp(p + w * t0), clamp(p + w * t1));
            if a != b {
                self.out.push(vec![a, b]);
            }
        }
    }

    fn sample(&mut self, point: &impl Fn(f64) -> Vector2<f64>, s0: f64, s1: f64) {
        let n = Self::INITIAL;
        let mut prev_s = s0;
        let mut prev = point(s0);
        for k in 1..=n {
            let s = s0 + (s1 - s0) * (k as f64 / n as f64);
            let p = point(s);
            self.refine(point, prev_s, prev, s, p, 0);
            prev_s = s;
            prev = p;
        }
    }

    fn refine(
        &mut self,
        point: &impl Fn(f64) -> Vector2<f64>,
        s0: f64,
        p0: Vector2<f64>,
        s1: f64,
        p1: Vector2<f64>,
        depth: u32,
    ) {
        if self.points > Conic::MAX_POLYLINE_POINTS {
            return;
        }
        let sm = 0.5 * (s0 + s1);
        let pm = point(sm);
        // Refine where the chord or the midpoint passes near the viewport.
        let reach = 2.0 * self.radius;
        let relevant = (pm - self.center).norm() <= reach
            || segment_distance(
                Point2::from(self.center),
                Point2::from(p0),
                Point2::from(p1),
            ) <= reach;
        if depth < Self::MAX_DEPTH && relevant && pm.iter().all(|v| v.is_finite()) {
            let chord = p1 - p0;
            let len = chord.norm();
            let dev = if len > 0.0 {
                cross(chord, pm - p0).abs() / len
            } else {
                (pm - p0).norm()
            };
            if dev > self.tol || len > 0.05 * self.radius {
                self.refine(point, s0, p0, sm, pm, depth + 1);
                self.refine(point, sm, pm, s1, p1, depth + 1);
                return;
            }
        }
        self.segment(p0, p1);
    }

    /// Clips one segment and appends it to the current polyline.
    fn segment(&mut self, a: Vector2<f64>, b: Vector2<f64>) {
        self.points += 1;
        if !(a.iter().all(|v| v.is_finite()) && b.iter().all(|v| v.is_finite())) {
            self.finish();
            return;
        }
        let v = |v: Vector2<f64>| parry2d_f64::math::Vector::new(v.x, v.y);
        let ab = b - a;
        let clip = if ab == Vector2::zeros() {
            None
        } else {
            self.aabb.clip_line_parameters(v(a), v(ab))
        };
        let Some((t0, t1)) = clip else {
            self.finish();
            return;
        };
        let (t0, t1) = (t0.max(0.0), t1.min(1.0));
        if t0 > t1 {
            self.finish();
            return;
        }
        // Unclipped ends stay exactly the samples, so consecutive segments
        // join; clipped ends move onto the curve where it crosses the edge.
        // (A parameter rounded to 0 or 1 on a long chord does not make its
        // end inside: check.)
        let inside = |q: Vector2<f64>| {
            q.x >= self.lo.x && q.x <= self.hi.x && q.y >= self.lo.y && q.y <= self.hi.y
        };
        let ca = if t0 == 0.0 && inside(a) {
            a
        } else {
            self.on_edge(a + ab * t0)
        };
        let cb = if t1 == 1.0 && inside(b) {
            b
        } else {
            self.on_edge(a + ab * t1)
        };
        match self.current.last() {
            Some(last) if t0 == 0.0 && *last == ca => self.current.push(cb),
            _ => {
                self.finish();
                self.current.push(ca);
                self.current.push(cb);
            }
        }
        if t1 < 1.0 {
            self.finish();
        }
    }

    /// The point where the curve crosses the viewport edge nearest to `p`
    /// (a point of a chord on that edge), or `p` if none is within the
    /// sampling tolerance.
    fn on_edge(&self, p: Vector2<f64>) -> Vector2<f64> {
        let edges = [
            (
                (p.x - self.lo.x).abs(),
                Vector2::new(self.lo.x, p.y),
                Vector2::y(),
            ),
            (
                (p.x - self.hi.x).abs(),
                Vector2::new(self.hi.x, p.y),
                Vector2::y(),
            ),
            (
                (p.y - self.lo.y).abs(),
                Vector2::new(p.x, self.lo.y),
                Vector2::x(),
            ),
            (
                (p.y - self.hi.y).abs(),
                Vector2::new(p.x, self.hi.y),
                Vector2::x(),
            ),
        ];
        let (_, base, w) = edges
            .into_iter()
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .expect("four edges");
        // Clamped in both cases: a chord from a far sample puts its edge
        // point there only up to the rounding of that far point.
        let q = roots_on_line(self.conic, base, w)
            .into_iter()
            .filter(|r| r.abs() <= 2.0 * self.tol)
            .min_by(|a, b| a.abs().total_cmp(&b.abs()))
            .map_or(p, |r| base + w * r);
        Vector2::new(
            q.x.clamp(self.lo.x, self.hi.x),
            q.y.clamp(self.lo.y, self.hi.y),
        )
    }

    fn finish(&mut self) {
        // A polyline of one repeated point is a chord from far samples that
        // only grazes the viewport's edge, not a piece of the curve.
        let first = self.current.first().copied();
        if self.current.len() >= 2 && self.current.iter().any(|p| Some(*p) != first) {
            self.out.push(core::mem::take(&mut self.current));
        } else {
            self.current.clear();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Error;

    fn vp() -> Viewport {
        Viewport::new(-5.0, 5.0, -5.0, 5.0).unwrap()
    }

    #[test]
    fn kinds() {
        let c = |q: [f64; 6]| Conic::new(q[0], q[1], q[2], q[3], q[4], q[5]).unwrap();
        assert_eq!(
            c([1.0, 0.0, 1.0, 0.0, 0.0, -1.0]).kind(),
            ConicKind::Ellipse
        );
        assert_eq!(
            c([1.0, 0.0, -1.0, 0.0, 0.0, -1.0]).kind(),
            ConicKind::Hyperbola
        );
        assert_eq!(
            c([1.0, 0.0, 0.0, 0.0, -1.0, 0.0]).kind(),
            ConicKind::Parabola
        );
        assert_eq!(
            c([1.0, 0.0, -1.0, 0.0, 0.0, 0.0]).kind(),
            ConicKind::Degenerate
        );
        assert_eq!(
            c([0.0, 0.0, 0.0, 1.0, 1.0, 0.0]).kind(),
            ConicKind::Degenerate
        );
        assert!(Conic::new(0.0, 0.0, 0.0, 0.0, 0.0, 1.0).is_err());
        assert!(Conic::new(f64::NAN, 0.0, 0.0, 0.0, 0.0, 1.0).is_err());
    }

    /// Found through the `curves` fuzz target (issue 24): a constant term
    /// that dominates terms of rounding size. The matrix is singular within
    /// `1e-12` of its norm, so the kind is "degenerate", and a line pair
    /// was drawn across a view where the conic has no point (its value is
    /// near 1 all over it). A conic that passes the view is still drawn.
    #[test]
    fn a_dominant_constant_term_draws_nothing() {
        let c = Conic::new(
            0.0,
            -4.235164736271502e-21,
            -2.4397873920804114e-20,
            0.0,
            1.6940658945086007e-21,
            1.000000000000001,
        )
        .unwrap();
        assert_eq!(c.kind(), ConicKind::Degenerate);
        for h in [0.01, 1.0, 1e6] {
            let vp = Viewport::new(-h, h, -h, h).unwrap();
            for i in 0..=20 {
                for j in 0..=20 {
                    let p = Point2::new(-h + 0.1 * h * i as f64, -h + 0.1 * h * j as f64);
                    assert!(c.evaluate(p) > 0.99, "{p}");
                }
            }
            assert!(c.polylines(&vp, None).unwrap().is_empty());
        }
        // The same terms about a conic that passes the view: drawn, on it.
        let pair = Conic::new(1.0, 0.0, -1.0, 0.0, 0.0, 1e-30).unwrap();
        let lines = pair.polylines(&vp(), None).unwrap();
        assert!(!lines.is_empty());
        let circle = Conic::new(1.0, 0.0, 1.0, 0.0, 0.0, -1e-6).unwrap();
        let lines = circle.polylines(&vp(), None).unwrap();
        assert!(!lines.is_empty());
        for p in lines.iter().flatten() {
            assert!((p.coords.norm() - 1e-3).abs() <= 1e-5, "{p}");
        }
    }

    #[test]
    fn circle_samples_close_within_tolerance() {
        let circle = Conic::new(1.0, 0.0, 1.0, -2.0, 0.0, -3.0).unwrap(); // (x-1)^2 + y^2 = 4
        let pl = circle.polylines(&vp(), Some(1e-4)).unwrap();
        assert_eq!(pl.len(), 1);
        let l = &pl[0];
        assert!((l[0] - l[l.len() - 1]).norm() < 1e-12, "closed loop");
        for p in l {
            assert!(((p - Point2::new(1.0, 0.0)).norm() - 2.0).abs() < 1e-12);
        }
        assert_eq!(circle.center(), Some(Point2::new(1.0, 0.0)));
    }

    #[test]
    fn hyperbola_gives_two_branches_reaching_the_edges() {
        let h = Conic::new(1.0, 0.0, -1.0, 0.0, 0.0, -1.0).unwrap();
        let pl = h.polylines(&vp(), None).unwrap();
        assert_eq!(pl.len(), 2, "{pl:?}");
        for l in &pl {
            // Every branch leaves through the edges at both ends.
            for p in [l[0], l[l.len() - 1]] {
                assert!(
                    (p.x.abs() - 5.0).abs() < 1e-9 || (p.y.abs() - 5.0).abs() < 1e-9,
                    "{p}"
                );
            }
            // Never crosses x = 0 (no segment across infinity).
            let sign = l[0].x.signum();
            assert!(l.iter().all(|p| p.x.signum() == sign));
            for p in l {
                assert!((p.x * p.x - p.y * p.y - 1.0).abs() < 1e-9);
            }
        }
        let [a1, a2] = h.asymptotes().unwrap();
        let slopes = [
            a1.direction.y / a1.direction.x,
            a2.direction.y / a2.direction.x,
        ];
        assert!(slopes.iter().any(|s| (s - 1.0).abs() < 1e-12));
        assert!(slopes.iter().any(|s| (s + 1.0).abs() < 1e-12));
    }

    #[test]
    fn parabola_and_line_pairs() {
        let p = Conic::new(1.0, 0.0, 0.0, 0.0, -1.0, 0.0).unwrap(); // y = x^2
        let pl = p.polylines(&vp(), None).unwrap();
        assert_eq!(pl.len(), 1);
        assert!(pl[0].iter().all(|q| (q.y - q.x * q.x).abs() < 1e-9));
        let pair = Conic::new(1.0, 0.0, -1.0, 0.0, 0.0, 0.0).unwrap(); // y = +-x
        let pl = pair.polylines(&vp(), None).unwrap();
        assert_eq!(pl.len(), 2);
        let parallel = Conic::new(0.0, 0.0, 1.0, 0.0, 0.0, -1.0).unwrap(); // y = +-1
        let pl = parallel.polylines(&vp(), None).unwrap();
        assert_eq!(pl.len(), 2);
        for l in &pl {
            assert!(l.iter().all(|q| (q.y.abs() - 1.0).abs() < 1e-12));
        }
        let empty = Conic::new(1.0, 0.0, 1.0, 0.0, 0.0, 1.0).unwrap();
        assert!(empty.polylines(&vp(), None).unwrap().is_empty());
    }

    #[test]
    fn global_coefficients_round_trip_through_a_local_frame() {
        let g = Conic::new(0.3, -1.2, 0.7, 2.0, -0.5, -4.0).unwrap();
        let (q, ..) = g.local_coefficients();
        let local = Conic::local(
            {
                // Re-express in a frame at (10, -3), unit 7.
                let (ox, oy, s) = (10.0, -3.0, 7.0);
                let [a, b, c, d, e, f] = q;
                let ev = |x: f64, y: f64| a * x * x + b * x * y + c * y * y + d * x + e * y + f;
                [
                    a * s * s,
                    b * s * s,
                    c * s * s,
                    (2.0 * a * ox + b * oy + d) * s,
                    (b * ox + 2.0 * c * oy + e) * s,
                    ev(ox, oy),
                ]
            },
            Point2::new(10.0, -3.0),
            7.0,
            None,
        );
        let (a, b) = (g.coefficients(), local.coefficients());
        let k = a[0] / b[0];
        for i in 0..6 {
            assert!((a[i] - k * b[i]).abs() < 1e-12, "{a:?} {b:?}");
        }
        for p in [Point2::new(1.0, 2.0), Point2::new(-3.0, 0.5)] {
            assert!((g.evaluate(p) - k * local.evaluate(p)).abs() < 1e-12);
        }
    }

    /// Fuzz finding (`conic`): a quadratic part that underflows against a
    /// huge `F` once gave a conic without a curve, which `from_parts` then
    /// refused (the round trip broke).
    #[test]
    fn coefficients_that_underflow_to_no_curve_are_refused() {
        let e = Conic::new(1e-300, 0.0, 0.0, 0.0, 0.0, 1e300).unwrap_err();
        assert!(matches!(
            e,
            Error::InvalidInput(InvalidInput::ConicCoefficients)
        ));
        let c = Conic::new(1e-300, 0.0, 0.0, 0.0, 0.0, 1e-290).unwrap();
        let (q, o, s, k) = c.to_parts();
        assert_eq!(Conic::from_parts(q, o, s, k).unwrap(), c);
    }

    /// Fuzz findings (`conic_polylines`): viewports of the size of
    /// `f64::MAX` once gave NaN points inside an `Ok`.
    #[test]
    fn polylines_refuse_viewports_too_large_to_sample() {
        let c = Conic::new(
            1.0,
            -0.05235987755982988,
            3.7084564308453e-310,
            0.0,
            0.0,
            -0.05235987755982988,
        )
        .unwrap();
        let v = Viewport::new(4e-323, f64::MAX, 4e-323, f64::MAX).unwrap();
        assert!(matches!(
            c.polylines(&v, None).unwrap_err(),
            Error::InvalidInput(InvalidInput::TooLarge { .. })
        ));
        let c = Conic::new(
            6.966104075427817e-21,
            -0.0014543504901960785,
            0.0,
            0.0005732843137254902,
            0.0,
            1.0,
        )
        .unwrap();
        let v = Viewport::new(2.33e-321, 1.036e-6, 0.0, f64::MAX).unwrap();
        assert!(c.polylines(&v, Some(1e308)).is_err());
        // At the largest viewport allowed, every point is finite.
        let v = Viewport::new(-3e299, 3e299, -3e299, 3e299).unwrap();
        for t in [None, Some(3e299)] {
            for line in c.polylines(&v, t).unwrap() {
                assert!(line.iter().all(|p| p.x.is_finite() && p.y.is_finite()));
            }
        }
    }

    /// A conic whose quadratic terms are `1e-14` of its linear ones is its
    /// line `x + y = 1` across the view (its other points lie `1e14` out),
    /// though its matrix is singular within `1e-12` of its norm (kind
    /// `Degenerate`): it was taken for a line pair through its far center
    /// (an ellipse: an isolated point) and nothing was drawn (issue 24).
    /// Every vertex is on the conic within the tolerance, and the ends are
    /// the line's exact crossings of the view's edges.
    #[test]
    fn a_conic_that_is_its_line_in_the_view_is_drawn_as_that_line() {
        for (qa, qc) in [(1e-14, 1e-14), (1e-14, -1e-14), (3e-13, 0.0)] {
            let c = Conic::new(qa, 0.0, qc, 1.0, 1.0, -1.0).unwrap();
            assert_eq!(c.kind(), ConicKind::Degenerate);
            let lines = c.polylines(&vp(), Some(1e-6)).unwrap();
            assert_eq!(lines.len(), 1, "{lines:?}");
            for p in &lines[0] {
                let g = c.gradient(*p).norm();
                assert!(c.evaluate(*p).abs() / g <= 1e-6, "{p}");
            }
            // x + y = 1 crosses the square [-5, 5]^2 at (-4, 5) and (5, -4).
            let ends = [lines[0][0], *lines[0].last().unwrap()];
            for want in [Point2::new(-4.0, 5.0), Point2::new(5.0, -4.0)] {
                assert!(ends.iter().any(|p| (p - want).norm() <= 1e-9), "{ends:?}");
            }
        }
        // A conic whose quadratic terms do move it in the view is sampled
        // as before: the parabola y = x^2 / 10 is not its tangent line.
        let parabola = Conic::new(0.1, 0.0, 0.0, 0.0, -1.0, 0.0).unwrap();
        let lines = parabola.polylines(&vp(), None).unwrap();
        assert!(lines.iter().flatten().count() > 10);
        for p in lines.iter().flatten() {
            assert!((p.y - 0.1 * p.x * p.x).abs() <= 1e-2, "{p}");
        }
    }
}
