//! The strut's clearance over its travel: the actuator's line, from its
//! ground pivot `G` to its moving point `Q`, against the linkage's links,
//! the obstacles and the envelope (the module docs of
//! [`actuator`](super), "Clearance").

use nalgebra::Point2;
use parry2d_f64::math::Vector as PVector;
use parry2d_f64::query::distance;
use parry2d_f64::shape::Segment;

use crate::design::constraints::Prepared;
use crate::design::space::segment_distance as point_segment;
use crate::error::Result;
use crate::geom::cross;
use crate::linkage::actuator::ActuatorLink;
use crate::linkage::{AssemblyMode, FourBar, Joints};

/// What the gap of a strut is measured against at one input angle.
pub(super) struct StrutCheck<'a> {
    /// The four-bar the strut drives, in its travel's mode.
    pub(super) fourbar: &'a FourBar,
    pub(super) mode: AssemblyMode,
    /// The link the strut acts on (its pin is on it).
    pub(super) link: ActuatorLink,
    /// The obstacles, the envelope and the links' width.
    pub(super) prepared: &'a Prepared,
    /// The strut's ground pivot `G`.
    pub(super) ground: Point2<f64>,
    /// Half the strut's diameter (`ActuatorOptions::actuator_width`).
    pub(super) strut_radius: f64,
    /// Distances at most this are contact (a crossing).
    pub(super) tiny: f64,
}

impl StrutCheck<'_> {
    /// The gap at input angle `theta` with the moving point at `q` (see
    /// [`gap_at`](Self::gap_at)).
    pub(super) fn gap(&self, theta: f64, q: Point2<f64>) -> Result<f64> {
        let j = self.fourbar.joints_at(theta, self.mode)?;
        Ok(self.gap_at(&j, q))
    }

    /// The gap with the linkage's joints at `j` and the moving point at
    /// `q`: the least of the strut's distance to each link it does not
    /// share a pin with less the strut's and the link's half widths, its
    /// distance to each obstacle and to the envelope's boundary less its
    /// own half width (negative by that distance when `G` is outside the
    /// envelope), and minus the two half widths where it crosses a link it
    /// shares `Q` with away from `Q`.
    pub(super) fn gap_at(&self, j: &Joints, q: Point2<f64>) -> f64 {
        let (r, rs) = (self.prepared.radius(), self.strut_radius);
        let g = self.ground;
        let links = [
            (ActuatorLink::Crank, j.input_pivot, j.crank_joint),
            (ActuatorLink::Coupler, j.crank_joint, j.rocker_joint),
            (ActuatorLink::Rocker, j.output_pivot, j.rocker_joint),
        ];
        // The strut without its last `1000 tiny` at `Q`: what may not touch
        // a link that carries `Q` (its own, or one joined to it at `Q`).
        let d = q - g;
        let s = d.norm();
        let back = 1e3 * self.tiny;
        let short = if s > 2.0 * back {
            q - d * (back / s)
        } else {
            g
        };
        let mut gap = f64::INFINITY;
        for (which, a, b) in links {
            if which == self.link || point_segment(q, a, b) <= self.tiny {
                if segment_distance(g, short, a, b) <= self.tiny {
                    gap = gap.min(-(r + rs));
                }
            } else {
                gap = gap.min(segment_distance(g, q, a, b) - r - rs);
            }
        }
        if !self.prepared.obstacles.is_empty() {
            let v = |p: Point2<f64>| PVector::new(p.x, p.y);
            let identity = parry2d_f64::math::Pose::identity();
            let strut = Segment::new(v(g), v(q));
            for o in &self.prepared.obstacles {
                let dist = distance(&identity, &strut, &identity, o).map_or(0.0, |x| x.distance);
                gap = gap.min(dist - rs);
            }
        }
        if let Some(edges) = self.prepared.envelope_edges() {
            let p = |e: PVector| Point2::new(e.x, e.y);
            let dist = edges
                .iter()
                .map(|e| segment_distance(g, q, p(e.a), p(e.b)))
                .fold(f64::INFINITY, f64::min);
            gap = gap.min(if self.prepared.in_envelope(g) {
                dist - rs
            } else {
                -dist - rs
            });
        }
        gap
    }
}

/// The distance between the segments `p1 p2` and `q1 q2` (0 where they
/// cross).
pub(super) fn segment_distance(
    p1: Point2<f64>,
    p2: Point2<f64>,
    q1: Point2<f64>,
    q2: Point2<f64>,
) -> f64 {
    let d1 = cross(q2 - q1, p1 - q1);
    let d2 = cross(q2 - q1, p2 - q1);
    let d3 = cross(p2 - p1, q1 - p1);
    let d4 = cross(p2 - p1, q2 - p1);
    if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
        return 0.0;
    }
    point_segment(p1, q1, q2)
        .min(point_segment(p2, q1, q2))
        .min(point_segment(q1, p1, p2))
        .min(point_segment(q2, p1, p2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segment_distances() {
        let p = |x, y| Point2::new(x, y);
        // Crossing, parallel, touching at an end, apart along a line.
        let cases = [
            ([(0., 0.), (2., 2.), (0., 2.), (2., 0.)], 0.0),
            ([(0., 0.), (2., 0.), (0., 1.), (2., 1.)], 1.0),
            ([(0., 0.), (1., 0.), (1., 0.), (1., 5.)], 0.0),
            ([(0., 0.), (1., 0.), (3., 0.), (4., 0.)], 2.0),
        ];
        for (s, want) in cases {
            let [a, b, c, d] = s.map(|(x, y)| p(x, y));
            assert_eq!(segment_distance(a, b, c, d), want);
            assert_eq!(segment_distance(c, d, a, b), want);
        }
    }
}
