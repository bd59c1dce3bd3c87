//! Lines, and the circle (or line) through three points.

use nalgebra::{Point2, Vector2};

use crate::geom::{Viewport, cross, length};

/// A line: a point and a direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    /// A point of the line.
    pub point: Point2<f64>,
    /// Its direction (not necessarily unit; see the producer's docs).
    pub direction: Vector2<f64>,
}

impl Line {
    /// `cross(direction, p - point)`: positive left of the line, negative right.
    pub fn side(&self, p: Point2<f64>) -> f64 {
        cross(self.direction, p - self.point)
    }

    /// The part of the infinite line inside `viewport`, as its two ends
    /// (parry's AABB clipping), or `None` when it misses the viewport or
    /// its point or direction is zero or not finite.
    pub fn clip(&self, viewport: &Viewport) -> Option<(Point2<f64>, Point2<f64>)> {
        use parry2d_f64::bounding_volume::Aabb;
        use parry2d_f64::math::Vector as V;
        let finite = |v: Vector2<f64>| v.x.is_finite() && v.y.is_finite();
        if self.direction == Vector2::zeros()
            || !finite(self.direction)
            || !finite(self.point.coords)
        {
            return None;
        }
        let aabb = Aabb::new(
            V::new(viewport.xmin, viewport.ymin),
            V::new(viewport.xmax, viewport.ymax),
        );
        let (p, d) = (self.point, self.direction);
        let (t0, t1) = aabb.clip_line_parameters(V::new(p.x, p.y), V::new(d.x, d.y))?;
        Some((p + d * t0, p + d * t1))
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
