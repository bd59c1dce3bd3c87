//! Plane geometry: poses and similarity transforms, lines and circles,
//! conics, viewports and grids; and the small planar helpers shared by the
//! modules (points are read as complex numbers `z = x + iy`, see the
//! conventions in the crate docs).

pub mod conic;
pub mod cubic;
pub(crate) mod dd;
mod frame;
mod grid;
mod line;
mod pose;
mod show;

pub use conic::{Conic, ConicKind};
pub use cubic::Cubic;
pub(crate) use frame::{FAR, LocalFrame, local_frame};
pub(crate) use grid::finite_bounds;
pub use grid::{Grid, Viewport};
pub use line::{CircleOrLine, Line};
pub use pose::{MAX_POSES, PerPose, Pose, Similarity};
pub(crate) use show::{debug_shows, parsed_enum, str_names};

use nalgebra::{Point2, Vector2};

/// `cross(u, v) = u.x * v.y - u.y * v.x = Im(conj(u) * v)`.
#[inline(always)]
#[allow(dead_code)]
pub(crate) fn cross(u: Vector2<f64>, v: Vector2<f64>) -> f64 {
    u.x * v.y - u.y * v.x
}

/// `u` turned a quarter turn counter-clockwise (`i * u`).
#[inline(always)]
pub(crate) fn perp(u: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-u.y, u.x)
}

/// `u` rotated counter-clockwise by the angle whose cosine and sine are `(c, s)`.
#[inline(always)]
pub(crate) fn rotate_cs(u: Vector2<f64>, c: f64, s: f64) -> Vector2<f64> {
    Vector2::new(c * u.x - s * u.y, s * u.x + c * u.y)
}

/// `u` rotated counter-clockwise by `angle` radians.
#[inline]
pub(crate) fn rotate(u: Vector2<f64>, angle: f64) -> Vector2<f64> {
    let (s, c) = angle.sin_cos();
    rotate_cs(u, c, s)
}

/// The unit vector at `angle`.
#[inline]
pub(crate) fn unit(angle: f64) -> Vector2<f64> {
    let (s, c) = angle.sin_cos();
    Vector2::new(c, s)
}

/// `angle` wrapped into `(-pi, pi]`.
#[inline]
pub fn wrap_angle(angle: f64) -> f64 {
    use core::f64::consts::{PI, TAU};
    let mut a = angle % TAU;
    if a > PI {
        a -= TAU;
    } else if a <= -PI {
        a += TAU;
    }
    a
}

/// `|u|` without overflow or underflow in the squares (`hypot`).
#[inline]
pub(crate) fn length(u: Vector2<f64>) -> f64 {
    u.x.hypot(u.y)
}

/// `u / |u|`, computed without overflow or underflow; `None` for a zero or
/// non-finite vector.
#[inline]
pub(crate) fn normalized(u: Vector2<f64>) -> Option<Vector2<f64>> {
    let m = u.x.abs().max(u.y.abs());
    if !(m > 0.0 && m.is_finite()) {
        return None;
    }
    let w = u / m;
    Some(w / w.norm())
}

/// Whether every coordinate of `p` is finite.
#[inline]
pub(crate) fn point_is_finite(p: &Point2<f64>) -> bool {
    p.x.is_finite() && p.y.is_finite()
}

/// The distance from `p` to the segment `ab`.
pub(crate) fn segment_distance(p: Point2<f64>, a: Point2<f64>, b: Point2<f64>) -> f64 {
    let ab = b - a;
    let len2 = ab.norm_squared();
    let t = if len2 > 0.0 {
        ((p - a).dot(&ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p - (a + ab * t)).norm()
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::PI;
    #[test]
    fn wrap_is_half_open() {
        assert_eq!(wrap_angle(PI), PI);
        assert!((wrap_angle(-PI) - PI).abs() < 1e-15);
        assert!((wrap_angle(3.0 * PI) - PI).abs() < 1e-12);
        assert!((wrap_angle(0.5 + 4.0 * PI) - 0.5).abs() < 1e-12);
        assert!((wrap_angle(-0.5 - 4.0 * PI) + 0.5).abs() < 1e-12);
    }

    #[test]
    fn rotate_and_cross() {
        let u = Vector2::new(1.0, 0.0);
        let v = rotate(u, PI / 2.0);
        assert!((v - Vector2::new(0.0, 1.0)).norm() < 1e-15);
        assert_eq!(cross(u, perp(u)), 1.0);
        assert!((unit(PI).x + 1.0).abs() < 1e-15);
    }
}
