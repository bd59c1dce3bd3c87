//! Three-position synthesis: poses, the task, poles and image poles, the pole
//! circles, and the exact maps between circle points and center points.
//!
//! # Conventions
//!
//! A [`Pose`] `k` of the coupler is `(p_k, phi_k)`: where a chosen coupler
//! point is, and the coupler's angle. With `theta_ij = phi_j - phi_i`, the
//! displacement from pose `i` to pose `j` carries a coupler-fixed point:
//!
//! ```text
//! D_ij(z) = p_j + e^{i theta_ij} (z - p_i)
//! ```
//!
//! The **circle-point plane** holds coupler points written where they are at
//! pose 1; the **center-point plane** is the fixed frame. A dyad's center
//! point (fixed pivot) `Y` and circle point (moving pivot at pose 1) `X`
//! satisfy `|X - Y| = |D_12(X) - Y| = |D_13(X) - Y|`.
//!
//! # The maps (Borm & Kim; Hall, *Kinematics and Linkage Design*)
//!
//! The **pole** of poses `i, j` is the fixed point of `D_ij`:
//!
//! ```text
//! P_ij = (p_j - e^{i theta_ij} p_i) / (1 - e^{i theta_ij})
//!      = (p_i + p_j)/2 + i (p_j - p_i)/2 * cot(theta_ij / 2)
//! ```
//!
//! The circle point of a center point `Y` (the circumcenter of `Y`,
//! `D_21(Y)`, `D_31(Y)`) in closed form:
//!
//! ```text
//! u = e^{-i theta12/2} (Y - P12)      v = e^{-i theta13/2} (Y - P13)
//! den = cross(u, v)                   kappa = cross(P13 - P12, v)
//! X = P12 + u kappa / den
//! ```
//!
//! and the center point of a circle point `X` is the same with the angles
//! negated (`Y` is where the line through `P12` along
//! `e^{i theta12/2} (X - P12)` meets the line through `P13` along
//! `e^{i theta13/2} (X - P13)`). `den = 0` on the **pole circle** (through
//! `P12, P13, P23`): those center points have their circle point at infinity.
//! Circle points on the **image-pole circle** (through `P12, P13, P'23`) have
//! their center point at infinity. At a pole the map is undefined (a whole
//! line of answers). The map is a quadratic (Cremona) transformation: a line
//! of one plane becomes a conic through the three poles in the other.
//!
//! # Numerics
//!
//! All maps run in a local frame with its origin at `P12` and its unit the
//! size of the pole triangle, so results do not depend on where the task is
//! or how large it is. A point within [`Task::POINT_TOLERANCE`] (relative to
//! that size) of a pole is "at the pole"; a map whose denominator is within
//! a few machine epsilons of zero, relative to its factors, is "at infinity".

use core::f64::consts::PI;

use nalgebra::{Point2, Vector2};

use crate::error::{DegenerateError, InvalidInput, Result, finite};
use crate::geom::{cross, length, perp, rotate_cs, wrap_angle};

/// A pose of the coupler: where a chosen coupler point is, and the coupler's
/// angle (radians, counter-clockwise from +x).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// Position of the coupler point.
    pub position: Point2<f64>,
    /// Angle of the coupler, radians.
    pub angle: f64,
}

impl Pose {
    /// A pose from coordinates and an angle in radians.
    pub const fn new(x: f64, y: f64, angle: f64) -> Self {
        Pose {
            position: Point2::new(x, y),
            angle,
        }
    }

    /// Whether every number is finite.
    pub fn is_finite(&self) -> bool {
        self.position.x.is_finite() && self.position.y.is_finite() && self.angle.is_finite()
    }

    /// Where the coupler point that is at `local` in the coupler frame
    /// (origin at the pose's point, x-axis along the coupler angle) is.
    pub fn to_world(&self, local: Vector2<f64>) -> Point2<f64> {
        let (s, c) = self.angle.sin_cos();
        self.position + rotate_cs(local, c, s)
    }

    /// The coupler-frame coordinates of the fixed point `p` (inverse of
    /// [`to_world`](Self::to_world)).
    pub fn to_local(&self, p: Point2<f64>) -> Vector2<f64> {
        let (s, c) = self.angle.sin_cos();
        rotate_cs(p - self.position, c, -s)
    }
}

/// A circle through three points, or the line they lie on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CircleOrLine {
    /// A proper circle.
    Circle {
        /// Its center.
        center: Point2<f64>,
        /// Its radius.
        radius: f64,
    },
    /// The three points are collinear (within rounding).
    Line {
        /// A point of the line.
        point: Point2<f64>,
        /// A unit direction of the line.
        direction: Vector2<f64>,
    },
}

impl CircleOrLine {
    /// The circle (or line) through three points. Collinear within a
    /// relative `1e-12` (the triangle's doubled area against its longest side
    /// squared) gives a line through the two farthest apart.
    pub fn through(a: Point2<f64>, b: Point2<f64>, c: Point2<f64>) -> Self {
        // In units of the longest side, so that no square overflows or
        // underflows.
        let unit = length(b - a).max(length(c - a)).max(length(c - b));
        let unit = if unit > 0.0 && unit.is_finite() {
            unit
        } else {
            1.0
        };
        let (ab, ac) = ((b - a) / unit, (c - a) / unit);
        let det = 2.0 * cross(ab, ac);
        let longest = ab
            .norm_squared()
            .max(ac.norm_squared())
            .max((ac - ab).norm_squared());
        if det.abs() <= 1e-12 * longest || longest == 0.0 {
            let (p, q) = [(a, b), (a, c), (b, c)]
                .into_iter()
                .max_by(|x, y| {
                    (x.1 - x.0)
                        .norm_squared()
                        .total_cmp(&(y.1 - y.0).norm_squared())
                })
                .unwrap_or((a, b));
            let d = q - p;
            let n = d.norm();
            return CircleOrLine::Line {
                point: p,
                direction: if n > 0.0 { d / n } else { Vector2::x() },
            };
        }
        let (b2, c2) = (ab.norm_squared(), ac.norm_squared());
        let off = Vector2::new(ac.y * b2 - ab.y * c2, ab.x * c2 - ac.x * b2) / det;
        CircleOrLine::Circle {
            center: a + off * unit,
            radius: off.norm() * unit,
        }
    }

    /// Signed distance-like value: negative inside the circle (or left of
    /// the line), zero on it, positive outside (or right of it).
    pub fn side(&self, p: Point2<f64>) -> f64 {
        match *self {
            CircleOrLine::Circle { center, radius } => (p - center).norm() - radius,
            CircleOrLine::Line { point, direction } => -cross(direction, p - point),
        }
    }
}

/// Which plane a point is in, for error messages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum MapDir {
    CenterToCircle,
    CircleToCenter,
}

/// Three poses of the coupler, validated, with their poles.
///
/// # Example
///
/// ```
/// use burmester::{Pose, Task};
/// let task = Task::new([
///     Pose::new(0.0, 0.0, 0.0),
///     Pose::new(2.0, 0.5, 0.4),
///     Pose::new(3.0, 2.0, 1.1),
/// ])?;
/// let [p12, p13, p23] = task.poles();
/// // A circle point and its center point are a round trip.
/// let y = burmester::Point2::new(1.0, -2.0);
/// let x = task.circle_point(y)?;
/// assert!((task.center_point(x)? - y).norm() < 1e-12);
/// # Ok::<(), burmester::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Task {
    poses: [Pose; 3],
    /// `theta_12`, `theta_13`, `theta_23` wrapped into `(-pi, pi]`.
    theta: [f64; 3],
    poles: [Point2<f64>; 3],
    image_p23: Point2<f64>,
    /// Local frame: origin `P12`, unit `scale`.
    origin: Point2<f64>,
    scale: f64,
    /// `P13` in the local frame.
    q13: Vector2<f64>,
    /// `P23` in the local frame.
    q23: Vector2<f64>,
    /// `(cos, sin)` of `theta12/2` and `theta13/2`.
    half12: (f64, f64),
    half13: (f64, f64),
}

impl Task {
    /// Relative distance (in units of the pole triangle's size) within
    /// which a point counts as lying on a pole.
    pub const POINT_TOLERANCE: f64 = 1e-12;

    /// Largest magnitude of a pose coordinate. With it and
    /// [`Task::MIN_ROTATION`] the poles stay below about `1e107`, so no
    /// square of a distance overflows.
    pub const MAX_COORDINATE: f64 = 1e100;

    /// Largest magnitude of a pose angle, in radians: past it a double no
    /// longer holds the angle to `1e-7` rad.
    pub const MAX_ANGLE: f64 = 1e9;

    /// Smallest size of the pole triangle ([`Task::scale`]): smaller tasks
    /// are rejected (rescale them), so that no square of a distance
    /// underflows.
    pub const MIN_SCALE: f64 = 1e-100;

    /// Smallest angle between two poses (radians) that is not treated as a
    /// pure translation. The pole of two poses rotated by `theta` lies about
    /// `1 / theta` times their separation away, and the maps, which run
    /// through the poles, lose that factor in relative accuracy near the
    /// poses: at this bound, a few `1e6 * f64::EPSILON` (`1e-9` was measured).
    pub const MIN_ROTATION: f64 = 1e-6;

    /// A task from three poses.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a NaN or infinite number;
    /// [`DegenerateError::CoincidentPoses`] when two poses are equal;
    /// [`DegenerateError::PureTranslation`] when two poses have the same
    /// angle (modulo `2 pi`, within [`Task::MIN_ROTATION`]): their pole is
    /// at infinity; [`DegenerateError::CoincidentPoles`] when the three
    /// poses are rotations about one point; [`InvalidInput::OutOfRange`]
    /// when a coordinate exceeds [`Task::MAX_COORDINATE`] or an angle
    /// [`Task::MAX_ANGLE`] in magnitude, or
    /// the pole triangle is smaller than [`Task::MIN_SCALE`].
    pub fn new(poses: [Pose; 3]) -> Result<Self> {
        const NAMES: [[&str; 3]; 3] = [
            ["pose 1 x", "pose 1 y", "pose 1 angle"],
            ["pose 2 x", "pose 2 y", "pose 2 angle"],
            ["pose 3 x", "pose 3 y", "pose 3 angle"],
        ];
        for (p, n) in poses.iter().zip(NAMES) {
            finite(n[0], p.position.x)?;
            finite(n[1], p.position.y)?;
            finite(n[2], p.angle)?;
            if p.angle.abs() > Self::MAX_ANGLE {
                return Err(InvalidInput::OutOfRange {
                    name: n[2],
                    expected: "must be at most 1e9 radians in magnitude (beyond, a double cannot \
                               hold the angle to 1e-7 rad); reduce it modulo 2 pi",
                    found: p.angle.to_string(),
                }
                .into());
            }
            for (name, v) in [(n[0], p.position.x), (n[1], p.position.y)] {
                if v.abs() > Self::MAX_COORDINATE {
                    return Err(InvalidInput::OutOfRange {
                        name,
                        expected: "must be at most 1e100 in magnitude; rescale the task (the \
                                   maps are invariant under scaling)",
                        found: v.to_string(),
                    }
                    .into());
                }
            }
        }
        let pairs = [(0, 1), (0, 2), (1, 2)];
        let theta = pairs.map(|(i, j)| wrap_angle(poses[j].angle - poses[i].angle));
        for (&(i, j), &t) in pairs.iter().zip(&theta) {
            if t.abs() <= Self::MIN_ROTATION {
                return Err(if poses[i].position == poses[j].position {
                    DegenerateError::CoincidentPoses { i: i + 1, j: j + 1 }
                } else {
                    DegenerateError::PureTranslation { i: i + 1, j: j + 1 }
                }
                .into());
            }
        }
        let poles = [0, 1, 2].map(|k| {
            let (i, j) = pairs[k];
            pole(&poses[i], &poses[j], theta[k])
        });
        let size = [(0, 1), (0, 2), (1, 2)]
            .iter()
            .map(|&(a, b)| length(poles[b] - poles[a]))
            .fold(0.0, f64::max);
        if !size.is_finite() {
            return Err(InvalidInput::OutOfRange {
                name: "task",
                expected: "poses whose poles are representable (coordinates far below 1e300)",
                found: format!("a pole triangle of size {size}"),
            }
            .into());
        }
        let extent = poses
            .iter()
            .map(|p| length(p.position - poles[0]))
            .fold(0.0, f64::max);
        if size <= Self::POINT_TOLERANCE * extent || size == 0.0 {
            return Err(DegenerateError::CoincidentPoles {
                x: poles[0].x,
                y: poles[0].y,
            }
            .into());
        }
        if size < Self::MIN_SCALE {
            return Err(InvalidInput::OutOfRange {
                name: "task",
                expected: "must have a pole triangle of size at least 1e-100; rescale the task \
                           (the maps are invariant under scaling)",
                found: format!("a pole triangle of size {size}"),
            }
            .into());
        }
        let origin = poles[0];
        let scale = size;
        let q13 = (poles[1] - origin) / scale;
        let q23 = (poles[2] - origin) / scale;
        let half = |t: f64| {
            let (s, c) = (0.5 * t).sin_cos();
            (c, s)
        };
        let mut task = Task {
            poses,
            theta,
            poles,
            image_p23: poles[2],
            origin,
            scale,
            q13,
            q23,
            half12: half(theta[0]),
            half13: half(theta[1]),
        };
        // P'23 = D_21(P23): the reflection of P23 across the line P12 P13.
        task.image_p23 = task.displace(poles[2], 2, 1);
        Ok(task)
    }

    /// A task from `[x, y, angle]` triples (angles in radians).
    ///
    /// # Errors
    ///
    /// As [`Task::new`].
    pub fn from_xya(poses: [[f64; 3]; 3]) -> Result<Self> {
        Self::new(poses.map(|[x, y, a]| Pose::new(x, y, a)))
    }

    /// The three poses.
    pub fn poses(&self) -> &[Pose; 3] {
        &self.poses
    }

    /// `[theta_12, theta_13, theta_23]`, each wrapped into `(-pi, pi]`.
    pub fn rotations(&self) -> [f64; 3] {
        self.theta
    }

    /// The angle from pose `i` to pose `j` (1-based), wrapped into `(-pi, pi]`.
    ///
    /// # Panics
    ///
    /// If `i` or `j` is not 1, 2 or 3 (a programming error, not user input).
    pub fn rotation(&self, i: usize, j: usize) -> f64 {
        wrap_angle(self.poses[j - 1].angle - self.poses[i - 1].angle)
    }

    /// The size of the pole triangle (its longest side): the unit of the
    /// relative tolerances.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// `D_ij(z) = p_j + e^{i theta_ij} (z - p_i)`: where the coupler point
    /// that is at `z` in pose `i` is in pose `j` (1-based).
    ///
    /// # Panics
    ///
    /// If `i` or `j` is not 1, 2 or 3.
    pub fn displace(&self, z: Point2<f64>, i: usize, j: usize) -> Point2<f64> {
        let (pi, pj) = (&self.poses[i - 1], &self.poses[j - 1]);
        let t = pj.angle - pi.angle;
        let (s, c) = t.sin_cos();
        pj.position + rotate_cs(z - pi.position, c, s)
    }

    /// The poles `[P12, P13, P23]`.
    pub fn poles(&self) -> [Point2<f64>; 3] {
        self.poles
    }

    /// The image poles in the pose-1 frame: `[P12, P13, P'23]`, with
    /// `P'23 = D_21(P23)`, the reflection of `P23` across the line `P12 P13`.
    /// They are the poles of the inverted motion (the ground seen from the
    /// coupler at pose 1).
    pub fn image_poles(&self) -> [Point2<f64>; 3] {
        [self.poles[0], self.poles[1], self.image_p23]
    }

    /// The image poles `[P12^k, P13^k, P23^k]` in the frame of pose `k`
    /// (1-based): `P_ij^k = D_ik(P_ij)` (a pole whose indices contain `k`
    /// is its own image).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::OutOfRange`] when `k` is not 1, 2 or 3.
    pub fn image_poles_in(&self, k: usize) -> Result<[Point2<f64>; 3]> {
        if !(1..=3).contains(&k) {
            return Err(InvalidInput::OutOfRange {
                name: "pose index",
                expected: "must be 1, 2 or 3",
                found: k.to_string(),
            }
            .into());
        }
        let pairs = [(1, 2), (1, 3), (2, 3)];
        Ok([0, 1, 2].map(|n| {
            let (i, j) = pairs[n];
            if i == k || j == k {
                self.poles[n]
            } else {
                self.displace(self.poles[n], i, k)
            }
        }))
    }

    /// The pole circle, through `P12, P13, P23`: center points on it have
    /// their circle point at infinity.
    pub fn pole_circle(&self) -> CircleOrLine {
        let [a, b, c] = self.poles;
        CircleOrLine::through(a, b, c)
    }

    /// The image-pole circle, through `P12, P13, P'23`: circle points on it
    /// have their center point at infinity.
    pub fn image_pole_circle(&self) -> CircleOrLine {
        let [a, b, c] = self.image_poles();
        CircleOrLine::through(a, b, c)
    }

    /// The signed angles of the pole triangle, measured from the geometry,
    /// each reduced modulo `pi` into `(-pi/2, pi/2]`: at `P12` from `P13` to
    /// `P23`, at `P13` from `P12` to `P23`, and at `P23` from `P12` to `P13`.
    /// They equal `theta12/2`, `theta13/2` and `theta23/2` modulo `pi`.
    pub fn pole_triangle_angles(&self) -> [f64; 3] {
        let [p12, p13, p23] = self.poles;
        let ang = |at: Point2<f64>, from: Point2<f64>, to: Point2<f64>| {
            let (a, b) = (from - at, to - at);
            reduce_half_turn(cross(a, b).atan2(a.dot(&b)))
        };
        [ang(p12, p13, p23), ang(p13, p12, p23), ang(p23, p12, p13)]
    }

    /// `(cos, sin)` of `theta12/2` and `theta13/2`.
    pub(crate) fn half_angles(&self) -> ((f64, f64), (f64, f64)) {
        (self.half12, self.half13)
    }

    /// The local frame: origin `P12`, unit [`scale`](Self::scale).
    pub(crate) fn frame(&self) -> (Point2<f64>, f64) {
        (self.origin, self.scale)
    }

    /// `P13` in the local frame.
    pub(crate) fn local_p13(&self) -> Vector2<f64> {
        self.q13
    }

    /// A fixed point in the local frame.
    #[inline]
    pub(crate) fn local_of(&self, p: Point2<f64>) -> Vector2<f64> {
        (p - self.origin) / self.scale
    }

    /// A local-frame vector back in the fixed frame.
    #[inline]
    pub(crate) fn global_of(&self, v: Vector2<f64>) -> Point2<f64> {
        self.origin + v * self.scale
    }

    /// The circle point (moving pivot at pose 1) whose center point (fixed
    /// pivot) is `center`.
    ///
    /// # Errors
    ///
    /// [`DegenerateError::AtInfinity`] when `center` is on the pole circle
    /// (the answer lies at infinity; the error carries its direction);
    /// [`DegenerateError::Undefined`] when `center` is at a pole (a whole
    /// line of circle points has it as center); [`InvalidInput::NotFinite`]
    /// for a non-finite point, [`InvalidInput::OutOfRange`] for a point
    /// more than about `1e300` task sizes away.
    pub fn circle_point(&self, center: Point2<f64>) -> Result<Point2<f64>> {
        self.map(center, MapDir::CenterToCircle)
    }

    /// The center point (fixed pivot) of the circle point (moving pivot at
    /// pose 1) `circle`.
    ///
    /// # Errors
    ///
    /// [`DegenerateError::AtInfinity`] when `circle` is on the image-pole
    /// circle (the center point is at infinity: a slider);
    /// [`DegenerateError::Undefined`] at an image pole;
    /// [`InvalidInput::NotFinite`] for a non-finite point,
    /// [`InvalidInput::OutOfRange`] for a point more than about `1e300`
    /// task sizes away.
    pub fn center_point(&self, circle: Point2<f64>) -> Result<Point2<f64>> {
        self.map(circle, MapDir::CircleToCenter)
    }

    /// [`circle_point`](Self::circle_point) for each of `centers`, lazily.
    pub fn circle_points<'a, I>(
        &'a self,
        centers: I,
    ) -> impl Iterator<Item = Result<Point2<f64>>> + 'a
    where
        I: IntoIterator<Item = Point2<f64>>,
        I::IntoIter: 'a,
    {
        centers.into_iter().map(move |p| self.circle_point(p))
    }

    /// [`center_point`](Self::center_point) for each of `circles`, lazily.
    pub fn center_points<'a, I>(
        &'a self,
        circles: I,
    ) -> impl Iterator<Item = Result<Point2<f64>>> + 'a
    where
        I: IntoIterator<Item = Point2<f64>>,
        I::IntoIter: 'a,
    {
        circles.into_iter().map(move |p| self.center_point(p))
    }

    /// The Cremona map of a local point of ordinary size (see
    /// [`Task::map_parts_scaled`]): `(u, kappa, den, v)` with the answer
    /// `u * kappa / den` (local); `dir_sign` is `-1` for the circle point of
    /// a center point, `+1` for the center point of a circle point.
    #[inline(always)]
    pub(crate) fn map_parts(
        &self,
        y: Vector2<f64>,
        dir_sign: f64,
    ) -> (Vector2<f64>, f64, f64, Vector2<f64>) {
        self.map_parts_scaled(y, self.q13, dir_sign)
    }

    /// The Cremona map in the local frame: returns `(u, kappa, den)` with
    /// the answer `u * kappa / den` (local), for the direction `dir`.
    #[inline(always)]
    fn map_parts_scaled(
        &self,
        y: Vector2<f64>,
        q13: Vector2<f64>,
        dir_sign: f64,
    ) -> (Vector2<f64>, f64, f64, Vector2<f64>) {
        let (c12, s12) = self.half12;
        let (c13, s13) = self.half13;
        let u = rotate_cs(y, c12, dir_sign * s12);
        let v = rotate_cs(y - q13, c13, dir_sign * s13);
        let den = cross(u, v);
        let kappa = cross(q13, v);
        (u, kappa, den, v)
    }

    fn map(&self, p: Point2<f64>, dir: MapDir) -> Result<Point2<f64>> {
        let (what, curve, names) = match dir {
            MapDir::CenterToCircle => (
                "circle point",
                "pole circle",
                ["center point x", "center point y"],
            ),
            MapDir::CircleToCenter => (
                "center point",
                "image-pole circle",
                ["circle point x", "circle point y"],
            ),
        };
        finite(names[0], p.x)?;
        finite(names[1], p.y)?;
        let y = self.local_of(p);
        if !(y.x.is_finite() && y.y.is_finite()) {
            return Err(InvalidInput::OutOfRange {
                name: names[0],
                expected: "must lie within about 1e300 task sizes (Task::scale) of the poles; \
                           pass a nearer point",
                found: format!("({}, {})", p.x, p.y),
            }
            .into());
        }
        let sign = match dir {
            MapDir::CenterToCircle => -1.0,
            MapDir::CircleToCenter => 1.0,
        };
        let third = match dir {
            MapDir::CenterToCircle => self.q23,
            MapDir::CircleToCenter => self.local_of(self.image_p23),
        };
        // Far points (beyond one task size) run in units of `m`: the answer
        // `u kappa / den` is homogeneous of degree 1 in (y, q13), so the
        // scaled parts give it, times `m`, without overflow for any finite
        // point (at `m = 1` this is the plain formula, bit for bit).
        let m = y.x.abs().max(y.y.abs()).max(1.0);
        let (u, kappa, den, v) = self.map_parts_scaled(y / m, self.q13 / m, sign);
        let tol = Self::POINT_TOLERANCE / m;
        let at = [
            (u.norm(), "the pole P12"),
            (v.norm(), "the pole P13"),
            ((y - third).norm() / m, "the pole P23"),
        ];
        for (dist, name) in at {
            if dist <= tol {
                let at = match (dir, name) {
                    (MapDir::CircleToCenter, "the pole P12") => "the image pole P'12",
                    (MapDir::CircleToCenter, "the pole P13") => "the image pole P'13",
                    (MapDir::CircleToCenter, _) => "the image pole P'23",
                    (_, n) => n,
                };
                return Err(DegenerateError::Undefined {
                    what,
                    at,
                    x: p.x,
                    y: p.y,
                }
                .into());
            }
        }
        let un = u.norm();
        if den.abs() <= 16.0 * f64::EPSILON * un * v.norm() {
            let d = if kappa * den < 0.0 { -u / un } else { u / un };
            return Err(DegenerateError::AtInfinity {
                what,
                curve,
                x: p.x,
                y: p.y,
                dir_x: d.x,
                dir_y: d.y,
            }
            .into());
        }
        let out = self.global_of(u * (kappa / den) * m);
        if out.x.is_finite() && out.y.is_finite() {
            Ok(out)
        } else {
            let d = u / un;
            Err(DegenerateError::AtInfinity {
                what,
                curve,
                x: p.x,
                y: p.y,
                dir_x: d.x,
                dir_y: d.y,
            }
            .into())
        }
    }

    /// The same task moved by the rigid motion "rotate by `angle` about the
    /// origin, then translate by `offset`", and scaled by `factor` about the
    /// origin first. Used to check invariance.
    ///
    /// # Errors
    ///
    /// As [`Task::new`] (for example when `factor` is zero).
    pub fn transformed(&self, factor: f64, angle: f64, offset: Vector2<f64>) -> Result<Self> {
        let t = Similarity::new(factor, angle, offset)?;
        Self::new(self.poses.map(|p| t.pose(&p)))
    }
}

/// A similarity transform of the plane: scale about the origin, rotate about
/// the origin, then translate. Optionally a mirror (reflection across the
/// x-axis) first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Similarity {
    /// Scale factor (positive).
    pub factor: f64,
    /// Rotation angle, radians.
    pub angle: f64,
    /// Translation.
    pub offset: Vector2<f64>,
    /// Reflect across the x-axis before everything else.
    pub mirror: bool,
}

impl Similarity {
    /// A similarity without mirror.
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for a non-finite number or a factor that is not positive.
    pub fn new(factor: f64, angle: f64, offset: Vector2<f64>) -> Result<Self> {
        crate::error::positive("scale factor", factor)?;
        finite("rotation angle", angle)?;
        finite("offset x", offset.x)?;
        finite("offset y", offset.y)?;
        Ok(Similarity {
            factor,
            angle,
            offset,
            mirror: false,
        })
    }

    /// The same transform with a reflection across the x-axis first.
    #[must_use]
    pub fn mirrored(mut self) -> Self {
        self.mirror = !self.mirror;
        self
    }

    /// Transforms a point.
    pub fn point(&self, p: Point2<f64>) -> Point2<f64> {
        let v = if self.mirror {
            Vector2::new(p.x, -p.y)
        } else {
            p.coords
        };
        let (s, c) = self.angle.sin_cos();
        Point2::from(rotate_cs(v * self.factor, c, s) + self.offset)
    }

    /// Transforms a direction (no translation, no scaling).
    pub fn direction(&self, d: Vector2<f64>) -> Vector2<f64> {
        let v = if self.mirror {
            Vector2::new(d.x, -d.y)
        } else {
            d
        };
        let (s, c) = self.angle.sin_cos();
        rotate_cs(v, c, s)
    }

    /// Transforms an angle (a direction given as an angle).
    pub fn angle_of(&self, a: f64) -> f64 {
        if self.mirror {
            self.angle - a
        } else {
            self.angle + a
        }
    }

    /// Transforms a pose.
    pub fn pose(&self, p: &Pose) -> Pose {
        Pose {
            position: self.point(p.position),
            angle: self.angle_of(p.angle),
        }
    }
}

/// `a` reduced modulo `pi` into `(-pi/2, pi/2]`.
pub(crate) fn reduce_half_turn(a: f64) -> f64 {
    let mut r = a % PI;
    if r > PI / 2.0 {
        r -= PI;
    } else if r <= -PI / 2.0 {
        r += PI;
    }
    r
}

/// The pole of two poses, `theta` their rotation (not zero).
fn pole(a: &Pose, b: &Pose, theta: f64) -> Point2<f64> {
    let mid = Point2::from((a.position.coords + b.position.coords) * 0.5);
    let half = 0.5 * theta;
    let cot = half.cos() / half.sin();
    mid + perp(b.position - a.position) * (0.5 * cot)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Error;

    fn task() -> Task {
        Task::from_xya([[0.0, 0.0, 0.0], [2.0, 0.5, 0.4], [3.0, 2.0, 1.1]]).unwrap()
    }

    #[test]
    fn poles_are_fixed_points() {
        let t = task();
        let [p12, p13, p23] = t.poles();
        assert!((t.displace(p12, 1, 2) - p12).norm() < 1e-12);
        assert!((t.displace(p13, 1, 3) - p13).norm() < 1e-12);
        assert!((t.displace(p23, 2, 3) - p23).norm() < 1e-12);
    }

    #[test]
    fn pure_translation_and_coincident_poses_are_typed() {
        let e = Task::from_xya([[0.0, 0.0, 0.3], [1.0, 0.0, 0.3], [3.0, 2.0, 1.1]]).unwrap_err();
        assert!(matches!(
            e,
            Error::Degenerate(DegenerateError::PureTranslation { i: 1, j: 2 })
        ));
        assert!(e.to_string().contains("translation"), "{e}");
        let e = Task::from_xya([[0.0, 0.0, 0.3], [3.0, 2.0, 1.1], [3.0, 2.0, 1.1]]).unwrap_err();
        assert!(matches!(
            e,
            Error::Degenerate(DegenerateError::CoincidentPoses { i: 2, j: 3 })
        ));
        let e =
            Task::from_xya([[0.0, 0.0, f64::NAN], [3.0, 2.0, 1.1], [1.0, 2.0, 1.3]]).unwrap_err();
        assert!(matches!(e, Error::InvalidInput(_)));
    }
}
