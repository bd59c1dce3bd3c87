//! The slider points of three poses: the circle points whose three
//! positions are collinear, the pins of the slider dyads (a revolute dyad
//! whose center point is at infinity).
//!
//! # The slider circle
//!
//! With `D_1k(z) = p_k + R_k (z - p_1)` and `R_k = e^{i theta_1k}`, the
//! point `z` moves by `w_k = D_1k(z) - z = d_k + a_k (z - p_1)` from pose 1
//! to pose `k`, where `d_k = p_k - p_1` and
//! `a_k = R_k - 1 = 2 sin(theta_1k / 2) i e^{i theta_1k / 2}`. Its three
//! positions are collinear exactly when `cross(w_2, w_3) = 0`, which in
//! `x = z - p_1` reads
//!
//! ```text
//! A |x|^2 + g . x + C = 0,
//! A = Im(conj(a_2) a_3) = 4 sin(theta_12/2) sin(theta_13/2) sin(theta_23/2)
//! g = (Im b, Re b),  b = conj(d_2) a_3 - a_2 conj(d_3)
//! C = cross(d_2, d_3)
//! ```
//!
//! a circle (`A != 0`), or a line when two of the poses differ by a pure
//! translation (`A = 0`: a pole at infinity, the circle through it). It
//! passes through `P12` and `P13` (where `w_2` or `w_3` vanishes) and is
//! the circumcircle of the image pole triangle `P12, P13, P'23` (the notes'
//! fact, checked in the tests against [`Cremona::image_pole_circle`]): the
//! circle points of the centers at infinity. It is written in a frame with
//! its origin at `p_1` and its unit the task's span, with `A` in its closed
//! form of the half angles, so that it keeps the accuracy of the poses at
//! small rotations (where the poles go far away and a circle through them
//! would cancel).
//!
//! [`Cremona::image_pole_circle`]: crate::Cremona::image_pole_circle

// Comparisons are written `!(a > b)` on purpose: a NaN takes the failing
// branch.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use core::f64::consts::PI;

use nalgebra::{Point2, Vector2};

use crate::geom::{CircleOrLine, cross, perp};
use crate::synthesis::motion::Motion;

/// The slider circle of a three-pose motion in its local frame (origin
/// `p_1`, unit the span): `a |x|^2 + g . x + c = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct SliderLocus {
    origin: Point2<f64>,
    unit: f64,
    a: f64,
    g: Vector2<f64>,
    c: f64,
}

/// A circle whose center is farther than this many spans from pose 1 is
/// a line for [`SliderLocus::circle`] (as for [`CircleOrLine::through`],
/// within `1e-12` relative: a double no longer tells them apart near the
/// task).
const LINE_BEYOND: f64 = 1e12;

/// `conj(u) v` as complex numbers.
fn conj_mul(u: Vector2<f64>, v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(u.x * v.x + u.y * v.y, u.x * v.y - u.y * v.x)
}

impl SliderLocus {
    /// The slider circle of the first three poses of `motion`, in units of
    /// `unit` (positive: the task's span).
    pub(crate) fn new(motion: &Motion, unit: f64) -> Self {
        let p = motion.poses();
        let (p1, p2, p3) = (p[0], p[1], p[2]);
        let d2 = (p2.position - p1.position) / unit;
        let d3 = (p3.position - p1.position) / unit;
        let (h2, h3) = (0.5 * (p2.angle - p1.angle), 0.5 * (p3.angle - p1.angle));
        let (s2, c2) = h2.sin_cos();
        let (s3, c3) = h3.sin_cos();
        // a_k = 2 sin(h_k) i e^{i h_k}, written without 1 - cos.
        let a2 = Vector2::new(-2.0 * s2 * s2, 2.0 * s2 * c2);
        let a3 = Vector2::new(-2.0 * s3 * s3, 2.0 * s3 * c3);
        let a = 4.0 * s2 * s3 * (0.5 * (p3.angle - p2.angle)).sin();
        // b = conj(d2) a3 - a2 conj(d3) = conj(d2) a3 - conj(d3 conj(a2)).
        let m1 = conj_mul(d2, a3);
        let m2 = conj_mul(a2, d3);
        let b = Vector2::new(m1.x - m2.x, m1.y + m2.y);
        SliderLocus {
            origin: p1.position,
            unit,
            a,
            g: Vector2::new(b.y, b.x),
            c: cross(d2, d3),
        }
    }

    /// The local radius `sqrt(|g|^2 - 4 a c) / (2 |a|)` (infinite for a
    /// line).
    fn local_radius(&self) -> f64 {
        let disc = (self.g.norm_squared() - 4.0 * self.a * self.c).max(0.0);
        disc.sqrt() / (2.0 * self.a.abs())
    }

    /// Whether the locus is taken as a line: `a = 0`, or its center is
    /// farther than [`LINE_BEYOND`] spans.
    fn is_line(&self) -> bool {
        !(2.0 * self.a.abs() * LINE_BEYOND > self.g.norm())
    }

    /// The locus as a circle (center, radius) or a line (a point, a unit
    /// direction); `None` when it is neither (`a = 0` and `g = 0`: every
    /// pose one angle, which a task refuses).
    pub(crate) fn circle(&self) -> Option<CircleOrLine> {
        let gn = self.g.norm();
        if self.is_line() {
            if !(gn > 0.0) {
                return None;
            }
            return Some(CircleOrLine::Line {
                point: self.origin + self.g * (-self.c / (gn * gn)) * self.unit,
                direction: perp(self.g) / gn,
            });
        }
        let center = self.g * (-0.5 / self.a);
        Some(CircleOrLine::Circle {
            center: self.origin + center * self.unit,
            radius: self.local_radius() * self.unit,
        })
    }

    /// The first-order distance of `p` from the locus, `|f| / |grad f|`
    /// (in the task's units): exact to first order near it, and without
    /// the cancellation of `| |p - center| - radius |` on a large circle.
    pub(crate) fn distance(&self, p: Point2<f64>) -> f64 {
        let x = (p - self.origin) / self.unit;
        let f = self.a * x.norm_squared() + self.g.dot(&x) + self.c;
        let grad = (x * (2.0 * self.a) + self.g).norm();
        if grad > 0.0 {
            (f / grad).abs() * self.unit
        } else {
            // The center of a circle: its radius away.
            self.local_radius() * self.unit
        }
    }

    /// `n` points of the locus: for a circle at equal angles `2 pi j / n`
    /// from the point of it nearest pose 1 (counterclockwise); for a line
    /// at `q + 2 s tan(pi (j + 1/2) / n - pi/2) u` (`q` the foot of pose 1
    /// on it, `s` the span, `u` its direction): the stereographic image of
    /// `n` equally spaced points of a circle of diameter `2 s` tangent to
    /// the line at `q`, so that the samples crowd near the task and none is
    /// at infinity.
    pub(crate) fn samples(&self, n: usize, out: &mut Vec<Point2<f64>>) {
        let line = self.is_line();
        out.extend((0..n).filter_map(|j| {
            let t = if line {
                PI * (j as f64 + 0.5) / n as f64 - 0.5 * PI
            } else {
                2.0 * PI * j as f64 / n as f64
            };
            self.point_at(t)
        }));
    }

    /// The point of the locus at parameter `t`, continuous in `t`: for a
    /// circle the point at angle `t` counterclockwise from the point
    /// nearest pose 1; for a line `q + 2 s tan(t) u` (`t` in `(-pi/2,
    /// pi/2)`; module docs of [`samples`](Self::samples)). `None` for a
    /// locus that is neither.
    pub(crate) fn point_at(&self, t: f64) -> Option<Point2<f64>> {
        let gn = self.g.norm();
        if !(gn > 0.0) {
            return None;
        }
        let ghat = self.g / gn;
        if self.is_line() {
            let q = ghat * (-self.c / gn);
            let u = perp(ghat);
            return Some(self.origin + (q + u * (2.0 * t.tan())) * self.unit);
        }
        // The nearest point q0 = -s e0, e0 = sign(a) g/|g| the direction
        // from the center to pose 1, s = 2 c sign(a) / (|g| + 2 |a| r) its
        // signed distance (no cancellation: |m|^2 - r^2 = c / a).
        let r = self.local_radius();
        let q0 = ghat * (-2.0 * self.c / (gn + 2.0 * self.a.abs() * r));
        let e0 = ghat * self.a.signum();
        let t0 = perp(e0);
        let (s, c) = (0.5 * t).sin_cos();
        // cos(t) - 1 = -2 sin^2(t/2), sin(t) = 2 sin cos.
        let x = q0 + (e0 * (-2.0 * s * s) + t0 * (2.0 * s * c)) * r;
        Some(self.origin + x * self.unit)
    }

    /// Whether the locus is a line (its parameter then runs over
    /// `(-pi/2, pi/2)`, else over a full turn).
    pub(crate) fn line(&self) -> bool {
        self.is_line()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Task;

    fn locus(poses: &[[f64; 3]]) -> (Task, SliderLocus) {
        let t = Task::from_xya(poses).unwrap();
        let l = SliderLocus::new(t.motion(), t.span());
        (t, l)
    }

    /// The doubled area of the triangle of `z`'s three positions over the
    /// longest side squared.
    fn collinearity(t: &Task, z: Point2<f64>) -> f64 {
        let p: Vec<Point2<f64>> = (1..=3).map(|k| t.displace(z, 1, k).unwrap()).collect();
        let longest = [(0, 1), (0, 2), (1, 2)]
            .iter()
            .map(|&(i, j)| (p[j] - p[i]).norm())
            .fold(0.0, f64::max);
        cross(p[1] - p[0], p[2] - p[0]).abs() / (longest * longest)
    }

    #[test]
    fn circle_passes_the_poles_and_the_image_pole() {
        let (t, l) = locus(&[[0.0, 0.0, 0.0], [2.0, 0.5, 0.4], [3.0, 2.0, 1.1]]);
        for p in t.cremona().unwrap().image_poles() {
            assert!(l.distance(p) < 1e-13 * t.span(), "{}", l.distance(p));
        }
        let mut pts = Vec::new();
        l.samples(12, &mut pts);
        assert_eq!(pts.len(), 12);
        for z in pts {
            assert!(collinearity(&t, z) < 1e-13, "{z}");
            assert!(l.distance(z) < 1e-13 * t.span());
        }
    }

    #[test]
    fn a_translation_gives_a_line() {
        // Poses 1 and 2 differ by a translation: the circle through P12
        // (at infinity) is a line.
        let (t, l) = locus(&[[0.0, 0.0, 0.3], [1.0, 0.0, 0.3], [3.0, 2.0, 1.1]]);
        let Some(CircleOrLine::Line { point, direction }) = l.circle() else {
            panic!("{:?}", l.circle());
        };
        let mut pts = Vec::new();
        l.samples(7, &mut pts);
        for z in pts.iter().copied().chain([point, point + direction * 3.0]) {
            assert!(collinearity(&t, z) < 1e-13, "{z}");
        }
        // The middle sample (n odd) is the foot of pose 1.
        let foot = pts[3];
        assert!(cross(direction, foot - point).abs() < 1e-14);
        assert!(direction.dot(&(t.poses()[0].position - foot)).abs() < 1e-14);
    }
}
