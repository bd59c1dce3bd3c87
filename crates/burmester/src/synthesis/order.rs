//! The order in which a crank meets the poses, and the four-bar built from
//! two dyads of `n` poses with its branch and order classification.

// Comparisons are written `!(a > b)` on purpose: a NaN takes the failing
// branch.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use core::f64::consts::TAU;

use nalgebra::Point2;

use super::errors;
use crate::error::Result;
use crate::geom::cross;
use crate::linkage::{AssemblyMode, FourBar, Grashof, InputRange};
use crate::synthesis::Dyad;
use crate::synthesis::local::LocalMotion;
use crate::tolerance;

/// A direction of turning.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Turn {
    /// Counter-clockwise (positive angles).
    Counterclockwise,
    /// Clockwise.
    Clockwise,
}

crate::geom::str_names!(
    /// `"counterclockwise"` or `"clockwise"`.
    Turn {
        Counterclockwise => "counterclockwise",
        Clockwise => "clockwise",
    }
);

/// The cyclic order of a crank's positions at the poses: the pose numbers
/// (1-based) met going counter-clockwise round the fixed pivot from the
/// crank's position at pose 1.
///
/// A crank that turns fully passes the poses in the order of the task
/// exactly when this is `1, 2, ..., n` (counter-clockwise) or
/// `1, n, ..., 2` (clockwise); see [`CrankOrder::direction`]. Along a
/// center-point curve the order changes only where two crank positions
/// coincide (the points `Q_jk` of four poses).
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct CrankOrder {
    seq: [u8; 5],
    len: u8,
}

impl CrankOrder {
    /// The order of the crank angles `angles[k]` (pose `k + 1`, at most
    /// five): sorted counter-clockwise from `angles[0]`; ties keep the
    /// pose order.
    pub(crate) fn from_angles(angles: &[f64]) -> Self {
        let n = angles.len().min(5);
        let mut idx: Vec<usize> = (0..n).collect();
        let off = |k: usize| (angles[k] - angles[0]).rem_euclid(TAU);
        idx.sort_by(|&a, &b| off(a).total_cmp(&off(b)).then(a.cmp(&b)));
        // Pose 1 first, even if rounding put another at offset 0 before it.
        if let Some(p) = idx.iter().position(|&k| k == 0) {
            idx.rotate_left(p);
        }
        let mut seq = [0u8; 5];
        for (s, k) in seq.iter_mut().zip(&idx) {
            *s = *k as u8 + 1;
        }
        CrankOrder { seq, len: n as u8 }
    }

    /// The pose numbers (1-based), pose 1 first, counter-clockwise.
    pub fn sequence(&self) -> &[u8] {
        &self.seq[..self.len as usize]
    }

    /// The number of poses.
    pub fn len(&self) -> usize {
        self.len as usize
    }

    /// Whether there are no poses (never for an order of a task).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The direction in which the crank meets the poses in their order
    /// `1, 2, ..., n`, if it does: counter-clockwise for the sequence
    /// `1, 2, ..., n`, clockwise for `1, n, ..., 2`, else `None`.
    pub fn direction(&self) -> Option<Turn> {
        let s = self.sequence();
        let n = s.len();
        if n < 2 {
            return None;
        }
        if s.iter().enumerate().all(|(i, &k)| k as usize == i + 1) {
            Some(Turn::Counterclockwise)
        } else if s[0] == 1 && s[1..].iter().enumerate().all(|(i, &k)| k as usize == n - i) {
            Some(Turn::Clockwise)
        } else {
            None
        }
    }
}

/// The pose numbers as the designer reads them, `CrankOrder(1-2-3-4)`.
impl core::fmt::Debug for CrankOrder {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "CrankOrder({self})")
    }
}

impl core::fmt::Display for CrankOrder {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        for (i, k) in self.sequence().iter().enumerate() {
            if i > 0 {
                f.write_str("-")?;
            }
            write!(f, "{k}")?;
        }
        Ok(())
    }
}

/// A four-bar built from a driving and a driven dyad of `n` poses, with
/// what it takes to drive it through them.
///
/// At pose `k` the moving pivots are `A_k = D_1k(A1)` and `C_k = D_1k(C1)`;
/// the input angle is `arg(A_k - A0)` and the assembly mode the sign of
/// `cross(C_k - A_k, C_k - C0)` (the sign of `sin(theta4 - theta3)`).
#[derive(Debug, Clone, PartialEq)]
pub struct Drive {
    /// The linkage: input pivot `A0`, output pivot `C0`.
    pub fourbar: FourBar,
    /// The driving dyad `(A0, A1)`.
    pub driving: Dyad,
    /// The driven dyad `(C0, C1)`.
    pub driven: Dyad,
    /// The input angle at each pose (absolute, radians).
    pub input_angles: Vec<f64>,
    /// The assembly mode at each pose; `None` where the pose is a toggle.
    pub modes: Vec<Option<AssemblyMode>>,
    /// The cyclic order of the input crank's positions.
    pub order: CrankOrder,
}

impl Drive {
    /// The Grashof type, the input being the driving crank.
    pub fn grashof(&self) -> Grashof {
        self.fourbar.grashof()
    }

    /// Whether every pose is reached in one assembly mode (no branch
    /// defect, no toggle at a pose): Filemon's test with `n` lines.
    pub fn is_branch_free(&self) -> bool {
        let first = self.modes.first().copied().flatten();
        first.is_some() && self.modes.iter().all(|m| *m == first)
    }

    /// The direction in which the input meets the poses in their order
    /// (no order defect), or `None`: an input that turns fully must meet
    /// them in cyclic order `1, 2, ..., n` one way round; a rocking input
    /// must also hold them all inside one arc of its range, in monotone
    /// order.
    pub fn in_order(&self) -> Option<Turn> {
        let dir = self.order.direction()?;
        let range = self.fourbar.input_range();
        if let InputRange::Full = range {
            return Some(dir);
        }
        let (arcs, count) = range.arcs_array();
        for arc in &arcs[..count] {
            if !self.input_angles.iter().all(|&t| arc.contains(t)) {
                continue;
            }
            let off: Vec<f64> = self
                .input_angles
                .iter()
                .map(|&t| (t - arc.start).rem_euclid(TAU))
                .collect();
            if off.windows(2).all(|w| w[1] > w[0]) {
                return Some(Turn::Counterclockwise);
            }
            if off.windows(2).all(|w| w[1] < w[0]) {
                return Some(Turn::Clockwise);
            }
        }
        None
    }

    /// Whether the linkage passes the poses in one assembly mode and in
    /// order ([`Drive::is_branch_free`] and [`Drive::in_order`]).
    pub fn is_defect_free(&self) -> bool {
        self.is_branch_free() && self.in_order().is_some()
    }
}

/// The crank angles `arg(D_1k(circle) - center)` of a dyad at every pose.
pub(crate) fn crank_angles(m: &LocalMotion, dyad: &Dyad) -> Vec<f64> {
    (0..m.poses.len())
        .map(|k| {
            let v = m.displace(dyad.circle, 0, k) - dyad.center;
            v.y.atan2(v.x)
        })
        .collect()
}

/// Checks that `dyad` passes every pose: its crank length is the same at
/// every pose within [`tolerance::DYAD`] of the crank plus the task size.
pub(crate) fn check_dyad(m: &LocalMotion, dyad: &Dyad, what: &'static str) -> Result<()> {
    for v in [dyad.center.x, dyad.center.y, dyad.circle.x, dyad.circle.y] {
        if !v.is_finite() {
            return Err(errors::not_finite(what, v));
        }
    }
    let d: Vec<f64> = (0..m.poses.len())
        .map(|k| (m.displace(dyad.circle, 0, k) - dyad.center).norm())
        .collect();
    let max = d.iter().copied().fold(0.0, f64::max);
    let min = d.iter().copied().fold(f64::INFINITY, f64::min);
    if !max.is_finite() {
        return Err(errors::not_finite(what, max));
    }
    if max <= tolerance::COINCIDENT_POSES * m.scale {
        return Err(errors::zero_length(what, dyad.center));
    }
    if max - min > tolerance::DYAD * (max + m.scale) {
        return Err(errors::not_a_dyad(what, (max - min) / max));
    }
    Ok(())
}

/// The four-bar of a driving and a driven dyad of the motion's poses.
pub(crate) fn drive(m: &LocalMotion, driving: &Dyad, driven: &Dyad) -> Result<Drive> {
    check_dyad(m, driving, "driving dyad")?;
    check_dyad(m, driven, "driven dyad")?;
    let fourbar =
        crate::synthesis::dyad::linkage_of(driving, driven, tolerance::COINCIDENT_POSES * m.scale)?;
    let n = m.poses.len();
    let a: Vec<Point2<f64>> = (0..n).map(|k| m.displace(driving.circle, 0, k)).collect();
    let c: Vec<Point2<f64>> = (0..n).map(|k| m.displace(driven.circle, 0, k)).collect();
    let input_angles = crank_angles(m, driving);
    let modes = (0..n)
        .map(|k| {
            let (u, v) = (c[k] - a[k], c[k] - driven.center);
            let s = cross(u, v);
            if s.abs() <= 16.0 * f64::EPSILON * u.norm() * v.norm() {
                None
            } else {
                AssemblyMode::from_sign(s)
            }
        })
        .collect();
    Ok(Drive {
        fourbar,
        driving: *driving,
        driven: *driven,
        order: CrankOrder::from_angles(&input_angles),
        input_angles,
        modes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orders_and_directions() {
        let o = CrankOrder::from_angles(&[0.1, 0.5, 1.0, 2.0]);
        assert_eq!(o.sequence(), &[1, 2, 3, 4]);
        assert_eq!(o.direction(), Some(Turn::Counterclockwise));
        let o = CrankOrder::from_angles(&[0.1, -0.5, -1.0, -2.0]);
        assert_eq!(o.sequence(), &[1, 4, 3, 2]);
        assert_eq!(o.direction(), Some(Turn::Clockwise));
        let o = CrankOrder::from_angles(&[0.1, 1.0, 0.5, 2.0, 3.0]);
        assert_eq!(o.sequence(), &[1, 3, 2, 4, 5]);
        assert_eq!(o.direction(), None);
        assert_eq!(o.to_string(), "1-3-2-4-5");
    }
}
