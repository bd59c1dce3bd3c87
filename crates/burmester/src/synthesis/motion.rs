//! The motion of the coupler through its poses, for any number of poses:
//! the displacements `D_ij` and the poles, poles at infinity included.
//!
//! # Conventions
//!
//! A [`Pose`] `k` of the coupler is `(p_k, phi_k)`: where a chosen coupler
//! point is, and the coupler's angle. With `theta_ij = phi_j - phi_i`, the
//! displacement from pose `i` to pose `j` carries a coupler-fixed point:
//!
//! ```text
//! D_ij(z) = p_j + e^{i theta_ij} (z - p_i)
//! D_1k(z) = R_k z + t_k,   R_k = e^{i theta_1k},   t_k = p_k - R_k p_1
//! ```
//!
//! The **pole** of poses `i, j` is the fixed point of `D_ij`:
//!
//! ```text
//! P_ij = (p_j - e^{i theta_ij} p_i) / (1 - e^{i theta_ij})
//!      = (p_i + p_j)/2 + i (p_j - p_i)/2 * cot(theta_ij / 2)
//! ```
//!
//! A pure translation (`theta_ij = 0` modulo `2 pi`, within
//! [`tolerance::MIN_ROTATION`]) has its pole
//! at infinity, in the direction perpendicular to the translation:
//! [`Pole::AtInfinity`].

use nalgebra::{Point2, Vector2};

use crate::error::{InvalidInput, Result};
use crate::geom::{PerPose, Pose, normalized, perp, rotate_cs, wrap_angle};
use crate::tolerance;

/// A pole: the fixed point of the displacement between two poses, or the
/// direction in which it lies at infinity (a pure translation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pole {
    /// A finite pole.
    Finite(Point2<f64>),
    /// The two poses differ by a pure translation: the pole is at infinity
    /// in this unit direction (perpendicular to the translation; a point at
    /// infinity has no sign, so `-direction` is the same pole).
    AtInfinity {
        /// A unit direction.
        direction: Vector2<f64>,
    },
}

impl Pole {
    /// The finite point, if the pole is finite.
    pub fn finite(&self) -> Option<Point2<f64>> {
        match *self {
            Pole::Finite(p) => Some(p),
            Pole::AtInfinity { .. } => None,
        }
    }
}

/// The motion of the coupler through a task's poses: the displacements
/// `D_1k(z) = R_k z + t_k`, which carry any coupler point from pose 1 to
/// pose `k`.
#[derive(Clone, Copy, PartialEq)]
pub struct Motion {
    poses: PerPose<Pose>,
    /// `(cos, sin)` of `theta_1k`.
    rot: PerPose<(f64, f64)>,
    /// `t_k = p_k - R_k p_1`.
    shift: PerPose<Vector2<f64>>,
}

crate::geom::debug_shows!(
    /// The poses and their poles, not the rotations and shifts kept.
    Motion,
    s => poses: s.poses(), poles: s.poles(),
);

impl Motion {
    /// The motion through `poses` (validated by [`Task::new`](crate::Task::new)).
    pub(crate) fn new(poses: PerPose<Pose>) -> Self {
        let p1 = poses[0];
        let rot = poses.map(|p| {
            let (s, c) = (p.angle - p1.angle).sin_cos();
            (c, s)
        });
        let shift = PerPose::from_fn(poses.len(), |k| {
            let (c, s) = rot[k];
            poses[k].position.coords - rotate_cs(p1.position.coords, c, s)
        });
        Motion { poses, rot, shift }
    }

    /// The number of poses.
    pub fn len(&self) -> usize {
        self.poses.len()
    }

    /// Always false: a motion has at least three poses.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The poses.
    pub fn poses(&self) -> &[Pose] {
        &self.poses
    }

    /// Checks a 1-based pose index and returns it 0-based.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::PoseIndex`] when it is not from 1 to the number of
    /// poses.
    pub fn index(&self, k: usize) -> Result<usize, InvalidInput> {
        if (1..=self.len()).contains(&k) {
            Ok(k - 1)
        } else {
            Err(InvalidInput::PoseIndex {
                index: k,
                count: self.len(),
            })
        }
    }

    /// `((cos, sin) of theta_1k, t_k)`: the parts of [`first_to`](Self::first_to)
    /// for a 0-based `k` (no check: internal; the vectorised map kernel).
    #[inline]
    pub(crate) fn first_to_parts(&self, k: usize) -> ((f64, f64), Vector2<f64>) {
        (self.rot[k], self.shift[k])
    }

    /// `D_1k(z) = R_k z + t_k` for a 0-based `k` (no check: internal).
    #[inline(always)]
    pub(crate) fn first_to(&self, k: usize, z: Point2<f64>) -> Point2<f64> {
        let (c, s) = self.rot[k];
        Point2::from(rotate_cs(z.coords, c, s) + self.shift[k])
    }

    /// Where a coupler point that is at `z` in pose 1 is in every pose:
    /// `[z, D_12(z), ..., D_1n(z)]`.
    #[inline]
    pub(crate) fn positions(&self, z: Point2<f64>) -> PerPose<Point2<f64>> {
        PerPose::from_fn(self.len(), |k| self.first_to(k, z))
    }

    /// `D_ij(z) = p_j + e^{i theta_ij} (z - p_i)`: where the coupler point
    /// that is at `z` in pose `i` is in pose `j` (1-based).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::PoseIndex`] for an index out of range,
    /// [`InvalidInput::NotFinite`] for a point that is not finite.
    pub fn displace(&self, z: Point2<f64>, i: usize, j: usize) -> Result<Point2<f64>> {
        crate::error::finite_point(["point x", "point y"], z)?;
        let (i, j) = (self.index(i)?, self.index(j)?);
        Ok(self.displace0(z, i, j))
    }

    /// [`displace`](Self::displace) with 0-based, valid indices.
    pub(crate) fn displace0(&self, z: Point2<f64>, i: usize, j: usize) -> Point2<f64> {
        let (pi, pj) = (&self.poses[i], &self.poses[j]);
        let (s, c) = (pj.angle - pi.angle).sin_cos();
        pj.position + rotate_cs(z - pi.position, c, s)
    }

    /// The rotation from pose `i` to pose `j` (1-based), wrapped into
    /// `(-pi, pi]`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::PoseIndex`] for an index out of range.
    pub fn rotation(&self, i: usize, j: usize) -> Result<f64> {
        let (i, j) = (self.index(i)?, self.index(j)?);
        Ok(self.rotation0(i, j))
    }

    pub(crate) fn rotation0(&self, i: usize, j: usize) -> f64 {
        wrap_angle(self.poses[j].angle - self.poses[i].angle)
    }

    /// The pole of poses `i` and `j` (1-based).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::PoseIndex`] for an index out of range or `i == j`
    /// (a pose has no pole with itself: every point is fixed).
    pub fn pole(&self, i: usize, j: usize) -> Result<Pole> {
        let (i0, j0) = (self.index(i)?, self.index(j)?);
        if i0 == j0 {
            return Err(InvalidInput::PoseIndex {
                index: j,
                count: self.len(),
            }
            .into());
        }
        Ok(self.pole0(i0, j0))
    }

    pub(crate) fn pole0(&self, i: usize, j: usize) -> Pole {
        let (a, b) = (&self.poses[i], &self.poses[j]);
        let theta = self.rotation0(i, j);
        if theta.abs() <= tolerance::MIN_ROTATION {
            let d = perp(b.position - a.position);
            return Pole::AtInfinity {
                direction: normalized(d).unwrap_or_else(Vector2::x),
            };
        }
        let mid = Point2::from((a.position.coords + b.position.coords) * 0.5);
        let half = 0.5 * theta;
        let cot = half.cos() / half.sin();
        Pole::Finite(mid + perp(b.position - a.position) * (0.5 * cot))
    }

    /// The pairs `(i, j)`, 1-based, `i < j`, in the order `(1,2), (1,3),
    /// ..., (1,n), (2,3), ...`.
    pub fn pairs(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        let n = self.len();
        (1..=n).flat_map(move |i| (i + 1..=n).map(move |j| (i, j)))
    }

    /// Every pole, in the order of [`pairs`](Self::pairs).
    pub fn poles(&self) -> Vec<Pole> {
        self.pairs()
            .map(|(i, j)| self.pole0(i - 1, j - 1))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn motion(poses: &[[f64; 3]]) -> Motion {
        let p: Vec<Pose> = poses.iter().map(|&[x, y, a]| Pose::new(x, y, a)).collect();
        Motion::new(PerPose::from_slice(&p))
    }

    #[test]
    fn displacements_compose_and_invert() {
        let m = motion(&[
            [0.0, 0.0, 0.0],
            [2.0, 0.5, 0.4],
            [3.0, 2.0, 1.1],
            [1.0, 3.0, -0.7],
        ]);
        let z = Point2::new(0.3, -1.2);
        for k in 0..4 {
            let w = m.first_to(k, z);
            assert!((m.displace0(w, k, 0) - z).norm() < 1e-14);
            assert!((m.displace0(z, 0, k) - w).norm() < 1e-14);
        }
        let d23 = m.displace(m.displace(z, 1, 2).unwrap(), 2, 3).unwrap();
        assert!((d23 - m.displace(z, 1, 3).unwrap()).norm() < 1e-14);
        assert!(m.displace(z, 0, 2).is_err());
        assert!(m.displace(z, 1, 5).is_err());
    }

    #[test]
    fn poles_are_fixed_points_and_translations_at_infinity() {
        let m = motion(&[[0.0, 0.0, 0.3], [1.0, 0.0, 0.3], [3.0, 2.0, 1.1]]);
        let poles = m.poles();
        assert_eq!(poles.len(), 3);
        match poles[0] {
            Pole::AtInfinity { direction } => {
                assert!((direction.x.abs()) < 1e-15 && (direction.y.abs() - 1.0).abs() < 1e-15)
            }
            p => panic!("expected a pole at infinity, got {p:?}"),
        }
        let p13 = poles[1].finite().unwrap();
        assert!((m.displace(p13, 1, 3).unwrap() - p13).norm() < 1e-12);
        let p23 = m.pole(2, 3).unwrap().finite().unwrap();
        assert!((m.displace(p23, 2, 3).unwrap() - p23).norm() < 1e-12);
        assert!(m.pole(2, 2).is_err());
        assert_eq!(m.pairs().collect::<Vec<_>>(), vec![(1, 2), (1, 3), (2, 3)]);
    }
}
