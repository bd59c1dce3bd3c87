//! The three-position maps between circle points and center points (the
//! Cremona transformation), the poles and image poles, and the pole circles.
//!
//! # The maps (Borm & Kim; Hall, *Kinematics and Linkage Design*)
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
//! or how large it is. A point within [`tolerance::POINT`] (relative to
//! that size) of a pole is "at the pole"; a map whose denominator is within
//! [`tolerance::CROSS_EPS`] machine epsilons of zero, relative to its
//! factors, is "at infinity".

use core::f64::consts::PI;

use nalgebra::{Point2, Vector2};

use crate::error::Result;
use crate::geom::{CircleOrLine, LocalFrame, cross, rotate_cs};
use crate::synthesis::motion::Motion;
use crate::synthesis::three::Linear;
use crate::tolerance;

/// Which way a point is mapped, for error messages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum MapDir {
    CenterToCircle,
    CircleToCenter,
}

/// The three-position maps of a task of three poses: its poles, image
/// poles, pole circles, and the exact maps between circle points and center
/// points. Get it from [`Task::cremona`](crate::Task::cremona).
#[derive(Clone, Copy, PartialEq)]
pub struct Cremona {
    motion: Motion,
    /// `P12, P13, P23`.
    poles: [Point2<f64>; 3],
    /// `P'23 = D_21(P23)`.
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
    /// The linear form, for a task whose pole `P12` or `P13` lies farther
    /// than [`tolerance::POLE_DISTANCE`] spans from the poses: the maps
    /// run by it (the task's own maps), not through the far pole.
    linear: Option<Linear>,
}

crate::geom::debug_shows!(
    /// The poles `P12, P13, P23` and the image poles, not the local frame.
    Cremona,
    s => poles: s.poles(), image_poles: s.image_poles(),
);

crate::geom::local_frame!(Cremona);

impl Cremona {
    /// The maps of a validated three-pose motion whose poles are finite,
    /// with `scale` the size of the pole triangle.
    pub(crate) fn new(motion: Motion, poles: [Point2<f64>; 3], scale: f64) -> Self {
        let origin = poles[0];
        let half = |t: f64| {
            let (s, c) = (0.5 * t).sin_cos();
            (c, s)
        };
        Cremona {
            motion,
            poles,
            // P'23 = D_21(P23): the reflection of P23 across the line P12 P13.
            image_p23: motion.displace0(poles[2], 1, 0),
            origin,
            scale,
            q13: (poles[1] - origin) / scale,
            q23: (poles[2] - origin) / scale,
            half12: half(motion.rotation0(0, 1)),
            half13: half(motion.rotation0(0, 2)),
            linear: None,
        }
    }

    /// The same, its maps run by `linear` (a pole far from the poses).
    pub(crate) fn with_linear(self, linear: Linear) -> Self {
        Cremona {
            linear: Some(linear),
            ..self
        }
    }

    /// The poles `[P12, P13, P23]`.
    pub fn poles(&self) -> [Point2<f64>; 3] {
        self.poles
    }

    /// The size of the pole triangle (its longest side).
    pub fn scale(&self) -> f64 {
        self.scale
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
    /// [`crate::InvalidInput::PoseIndex`] when `k` is not 1, 2 or 3.
    pub fn image_poles_in(&self, k: usize) -> Result<[Point2<f64>; 3]> {
        let k = self.motion.index(k)?;
        let pairs = [(0, 1), (0, 2), (1, 2)];
        Ok([0, 1, 2].map(|n| {
            let (i, j) = pairs[n];
            if i == k || j == k {
                self.poles[n]
            } else {
                self.motion.displace0(self.poles[n], i, k)
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

    /// The circle point (moving pivot at pose 1) whose center point (fixed
    /// pivot) is `center`: by the closed form through the poles, or, for a
    /// task whose pole `P12` or `P13` lies farther than
    /// [`tolerance::POLE_DISTANCE`] spans from the poses (a small rotation),
    /// by the linear form, which does not cancel the digits a far pole
    /// would (the task's own maps, [`Task::circle_point`](crate::Task::circle_point),
    /// bit for bit).
    ///
    /// # Errors
    ///
    /// [`crate::DegenerateError::AtInfinity`] when `center` is on the pole circle
    /// (the answer lies at infinity; the error carries its direction);
    /// [`crate::DegenerateError::Undefined`] when `center` is at a pole (a whole
    /// line of circle points has it as center); [`crate::InvalidInput::NotFinite`]
    /// for a non-finite point, [`crate::InvalidInput::Overflow`] for a point
    /// more than about `1e300` task sizes away.
    pub fn circle_point(&self, center: Point2<f64>) -> Result<Point2<f64>> {
        match &self.linear {
            Some(l) => l.circle_point(center),
            None => self.map(center, MapDir::CenterToCircle),
        }
    }

    /// The center point (fixed pivot) of the circle point (moving pivot at
    /// pose 1) `circle` (through the poles or by the linear form, as
    /// [`Cremona::circle_point`]).
    ///
    /// # Errors
    ///
    /// [`crate::DegenerateError::AtInfinity`] when `circle` is on the image-pole
    /// circle (the center point is at infinity: a slider);
    /// [`crate::DegenerateError::Undefined`] at an image pole;
    /// [`crate::InvalidInput::NotFinite`] for a non-finite point,
    /// [`crate::InvalidInput::Overflow`] for a point more than about `1e300`
    /// task sizes away.
    pub fn center_point(&self, circle: Point2<f64>) -> Result<Point2<f64>> {
        match &self.linear {
            Some(l) => l.center_point(circle),
            None => self.map(circle, MapDir::CircleToCenter),
        }
    }

    /// The map of a local point of ordinary size (see
    /// [`Cremona::map_parts_scaled`]): `(u, kappa, den, v)` with the answer
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

    /// The map in the local frame: returns `(u, kappa, den, v)` with the
    /// answer `u * kappa / den` (local).
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

    /// The circle point of a center point by the closed form, in the fixed
    /// frame, or `None` where it does not exist (on the pole circle) or
    /// overflows. The hot path of the solution maps: no checks beyond that.
    #[inline(always)]
    pub(crate) fn circle_point_fast(&self, center: Point2<f64>) -> Option<Point2<f64>> {
        let (u, kappa, den, _) = self.map_parts(self.local_of(center), -1.0);
        let q = self.origin + u * (kappa / den * self.scale);
        (q.x.is_finite() && q.y.is_finite() && den != 0.0).then_some(q)
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
        let y = super::local_input(
            self,
            names,
            p,
            "pass a point within about 1e300 task sizes (Task::scale) of the poles",
        )?;
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
        let tol = tolerance::POINT / m;
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
                return Err(crate::synthesis::errors::undefined(what, at, p));
            }
        }
        let un = u.norm();
        let at_infinity = |d| crate::synthesis::errors::at_infinity(what, curve, p, d);
        if den.abs() <= tolerance::CROSS_EPS * f64::EPSILON * un * v.norm() {
            let d = if kappa * den < 0.0 { -u / un } else { u / un };
            return Err(at_infinity(d));
        }
        let out = self.global_of(u * (kappa / den) * m);
        if out.x.is_finite() && out.y.is_finite() {
            Ok(out)
        } else {
            Err(at_infinity(u / un))
        }
    }
}

/// `a` reduced modulo `pi` into `(-pi/2, pi/2]`.
fn reduce_half_turn(a: f64) -> f64 {
    let mut r = a % PI;
    if r > PI / 2.0 {
        r -= PI;
    } else if r <= -PI / 2.0 {
        r += PI;
    }
    r
}
