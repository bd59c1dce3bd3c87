//! The branch problem in the circle-point plane, for any number of poses:
//! Filemon's construction with one line per pose.
//!
//! For the driven dyad `(C0, C1)`, `C'_k = D_k1(C0)` is the driven crank's
//! fixed pivot seen from the coupler frame of pose 1 while at pose `k`
//! (`C'_1 = C0`). The lines through `C1` and `C'_k` split the circle-point
//! plane into sectors, and the branch sign of a driving circle point `A1`
//! at pose `k` is
//!
//! ```text
//! s_k = sign cross(C'_k - C1, A1 - C1)
//! ```
//!
//! The branch-free circle points are the double wedge where every sign
//! agrees, bounded by the two **extreme** lines: the **Filemon lines**.
//! (Which poses give the extreme lines varies with the task.) If the
//! directions `C'_k - C1` do not lie in an open half-plane, every driving
//! circle point has a branch defect ([`FilemonLines::all_defective`]).
//!
//! # A slider as the driven dyad
//!
//! With the driven dyad a slider (a pin `C1` on a ground guide of unit
//! direction `u`, [`SliderDyad`]), its center is at infinity along the
//! normal `n = i·u`, and the line of pose `k` runs through `C1` in the
//! direction `n_k = e^{-i(θ_k - θ_1)} n`: the guide's normal seen from the
//! coupler frame of pose 1 while at pose `k`. The branch sign is then
//!
//! ```text
//! s_k = sign cross(n_k, A1 - C1) = sign <C1 - A1, u_k>,   u_k = e^{-i(θ_k - θ_1)} u
//! ```
//!
//! the side of the perpendicular to the guide through `A` on which the pin
//! lies (the slider-crank's assembly mode), and the limit of the revolute
//! construction with `C0 = C1 + R n`, `R -> ∞` (`C'_k - C1` turns to
//! `R n_k`). Everything else (the extreme lines, the double wedge, the
//! classes) is as for a revolute driven dyad: the only place the kind
//! enters is `DyadKind::filemon_lines`, one match on the kind.

use nalgebra::{Point2, Vector2};

use crate::error::{DegenerateError, InvalidInput, Result};
use crate::geom::{Line, PerPose, cross, normalized, rotate_cs};
use crate::synthesis::motion::Motion;
use crate::synthesis::{DyadKind, SliderDyad, Task, errors};
use crate::tolerance;

/// The branch class of a driving center point (or circle point).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Branch {
    /// The linkage passes every pose in one assembly mode.
    Free,
    /// The linkage passes the poses on different branches (a branch defect).
    Defective,
    /// On a boundary: a branch sign is zero (a toggle at a design pose), or
    /// the point lies on a transformed Filemon conic. Never counted as free.
    Boundary,
}

impl Branch {
    /// Whether the class is [`Branch::Free`].
    pub fn is_free(self) -> bool {
        self == Branch::Free
    }

    /// `"free"`, `"defective"` or `"boundary"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Branch::Free => "free",
            Branch::Defective => "defective",
            Branch::Boundary => "boundary",
        }
    }

    /// The class from the branch signs at the poses: boundary where one is
    /// zero (or NaN), free where all agree.
    pub fn from_signs(s: &[f64]) -> Self {
        if s.iter().any(|&v| v == 0.0 || v.is_nan()) {
            Branch::Boundary
        } else if s.iter().all(|&v| (v > 0.0) == (s[0] > 0.0)) {
            Branch::Free
        } else {
            Branch::Defective
        }
    }
}

/// Filemon's construction in the circle-point plane for a driven dyad: one
/// line per pose through `C1`, the extreme ones, and the branch signs.
#[derive(Clone, Copy, PartialEq)]
pub struct FilemonLines {
    driven: DyadKind,
    /// The direction of each pose's line: `C'_k - C1` for a revolute
    /// driven dyad, `n_k` for a slider.
    dirs: PerPose<Vector2<f64>>,
    /// `C'_k = D_k1(C0)` for a revolute driven dyad; `None` for a slider
    /// (its center is at infinity).
    c_prime: Option<PerPose<Point2<f64>>>,
    /// Pose indices (0-based) sorted by the angle of `C'_k - C1` within
    /// their half-plane: first and last are the extremes. `None` when they
    /// do not lie in an open half-plane.
    order: Option<PerPose<usize>>,
}

crate::geom::debug_shows!(
    /// The driven dyad, the fixed pivot's images `C'k` (none for a slider)
    /// and the lines' directions, not the sort order kept.
    FilemonLines,
    s => driven: s.driven, fixed_pivot_images: s.c_prime, directions: s.dirs,
        all_defective: s.all_defective(),
);

impl DyadKind {
    /// The center point where it is finite: `C0` for a crank, `None` for a
    /// slider (its center is at infinity along the guide's normal), the
    /// swivel for an inverted slider.
    pub fn finite_center(&self) -> Option<Point2<f64>> {
        match self {
            DyadKind::Revolute(d) => Some(d.center),
            DyadKind::Slider(_) => None,
            DyadKind::Inverted(v) => Some(v.swivel),
        }
    }

    /// The crank, or the error naming `what` (which needs a crank) for a
    /// dyad of another kind.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::DrivenKind`] when the dyad is a slider,
    /// [`InvalidInput::InvertedDriven`] when it is an inverted slider.
    pub fn crank(&self, what: &'static str) -> Result<crate::synthesis::Dyad> {
        match self {
            DyadKind::Revolute(d) => Ok(*d),
            DyadKind::Slider(_) => Err(InvalidInput::DrivenKind {
                what,
                found: self.as_str(),
            }
            .into()),
            DyadKind::Inverted(_) => Err(InvalidInput::InvertedDriven { what }.into()),
        }
    }

    /// Filemon's construction ([`FilemonLines`]) of this driven dyad for
    /// `motion`: the directions of the lines through the circle point `C1`,
    /// one per pose, and the fixed pivot's images `C'_k = D_k1(C0)` where
    /// the center is finite (a slider's guide is kept normalized). The
    /// directions: `C'_k - C1` for a crank, the guide's
    /// normal seen from the coupler frame of pose 1 at pose `k`,
    /// `n_k = e^{-i(θ_k - θ_1)} n`, for a slider (the limit of the crank's
    /// direction as its center goes to infinity along `n`; see
    /// [`FilemonLines`]). `scale` is the task's size. The one place where
    /// Filemon's construction depends on the dyad's kind.
    ///
    /// # Errors
    ///
    /// A crank: [`DegenerateError::ZeroLengthLink`] when it has no length
    /// (within [`tolerance::POINT`]), [`InvalidInput::Overflow`] when an
    /// image `C'_k` overflows or coincides with `C1`. A slider:
    /// [`InvalidInput::NotFinite`] for a circle point that is not finite,
    /// [`InvalidInput::ZeroDirection`] for a zero or non-finite guide,
    /// [`InvalidInput::NotADyad`] when the pin's positions `D_1k(C1)` are
    /// not on the guide (farther than [`tolerance::DYAD`] times the task's
    /// size plus the pin's travel): not a slider dyad of the task. An
    /// inverted slider: [`InvalidInput::InvertedDriven`] (its circle point
    /// is at infinity, so its lines are parallel: the branch-free driving
    /// circle points `A1` are those on one side of every line through
    /// `D_k1(S)` normal to the slot, the sign of the slot position
    /// `<D_k1(S) - A1, u>`, which [`Task::inverted_slider_crank`] reports).
    pub(crate) fn filemon_lines(&self, motion: &Motion, scale: f64) -> Result<FilemonLines> {
        match self {
            DyadKind::Revolute(driven) => {
                if driven.length() <= tolerance::POINT * scale {
                    return Err(DegenerateError::ZeroLengthLink {
                        what: "driven crank",
                        x: driven.center.x,
                        y: driven.center.y,
                    }
                    .into());
                }
                let c1 = driven.circle;
                let c_prime =
                    PerPose::from_fn(motion.len(), |k| motion.displace0(driven.center, k, 0));
                let dirs = c_prime.map(|c| c - c1);
                if dirs.iter().any(|d| normalized(*d).is_none()) {
                    return Err(InvalidInput::Overflow {
                        what: "a direction C'k - C1 of Filemon's construction",
                        hint: "the driven pivot's images C'k = D_k1(C0) must be finite and apart \
                               from its circle point C1: choose a driven center point nearer the \
                               task",
                    }
                    .into());
                }
                Ok(FilemonLines::of(*self, dirs, Some(c_prime)))
            }
            DyadKind::Slider(slider) => {
                let s = SliderDyad::new(slider.circle, slider.guide)?;
                // Kept as given when already unit (normalizing again may move
                // the last bit).
                let s = if (slider.guide.norm() - 1.0).abs() <= 4.0 * f64::EPSILON {
                    *slider
                } else {
                    s
                };
                // The pin's positions D_1k(C1) must lie on the guide.
                let (off, travel) = (0..motion.len())
                    .map(|k| {
                        let p = motion.first_to(k, s.circle) - s.circle;
                        (cross(s.guide, p).abs(), p.norm())
                    })
                    .fold((0.0f64, 0.0f64), |a, b| (a.0.max(b.0), a.1.max(b.1)));
                let spread = off / (scale + travel);
                if spread.is_nan() || spread > tolerance::DYAD {
                    return Err(errors::not_a_dyad(
                        "slider driven dyad (its pin's positions are off its guide)",
                        spread,
                    ));
                }
                let n = s.normal();
                let poses = motion.poses();
                let dirs = PerPose::from_fn(motion.len(), |k| {
                    let (sin, cos) = (poses[0].angle - poses[k].angle).sin_cos();
                    rotate_cs(n, cos, sin)
                });
                Ok(FilemonLines::of(s.into(), dirs, None))
            }
            // Its circle point is at infinity (normal to the slot): the
            // lines "through C1" are parallel, the lines through the
            // swivel's images D_k1(S) normal to the slot at pose 1, which
            // this construction (lines through one finite C1) cannot hold.
            DyadKind::Inverted(_) => Err(InvalidInput::InvertedDriven {
                what: "Filemon's construction",
            }
            .into()),
        }
    }
}

impl FilemonLines {
    /// Filemon's construction for a driven dyad of `task`: a crank
    /// ([`Dyad`](crate::synthesis::Dyad)) or a slider ([`SliderDyad`]).
    ///
    /// # Errors
    ///
    /// A crank with no length
    /// ([`DegenerateError::ZeroLengthLink`]) or whose fixed pivot's image
    /// `C'_k` overflows or coincides with its circle point
    /// ([`InvalidInput::Overflow`]); a slider whose circle point is not
    /// finite ([`InvalidInput::NotFinite`]) or whose guide is zero
    /// ([`InvalidInput::ZeroDirection`]), or whose pin's positions are not
    /// on its guide ([`InvalidInput::NotADyad`]).
    pub fn new(task: &Task, driven: impl Into<DyadKind>) -> Result<Self> {
        Self::of_motion(task.motion(), task.scale(), driven.into())
    }

    /// [`new`](Self::new) for a motion of any number of poses and its
    /// size `scale`.
    pub(crate) fn of_motion(motion: &Motion, scale: f64, driven: DyadKind) -> Result<Self> {
        driven.filemon_lines(motion, scale)
    }

    /// The construction from its checked directions (and the fixed pivot's
    /// images of a crank).
    fn of(
        driven: DyadKind,
        dirs: PerPose<Vector2<f64>>,
        c_prime: Option<PerPose<Point2<f64>>>,
    ) -> Self {
        FilemonLines {
            driven,
            dirs,
            c_prime,
            order: half_plane_order(&dirs),
        }
    }

    /// The driven dyad: `(C0, C1)` for a crank, `(C1, u)` for a slider.
    pub fn driven(&self) -> DyadKind {
        self.driven
    }

    /// `C'_k = D_k1(C0)`, one per pose; `None` for a slider (its center is
    /// at infinity).
    pub fn fixed_pivot_images(&self) -> Option<PerPose<Point2<f64>>> {
        self.c_prime
    }

    /// The directions of the lines, one per pose: `C'_k - C1` for a crank,
    /// the unit `n_k = e^{-i(θ_k - θ_1)} n` for a slider.
    pub fn directions(&self) -> PerPose<Vector2<f64>> {
        self.dirs
    }

    /// The lines through `C1`, one per pose, directions
    /// [`directions`](Self::directions).
    pub fn all_lines(&self) -> PerPose<Line> {
        let c1 = self.driven.circle();
        self.dirs.map(|d| Line {
            point: c1,
            direction: d,
        })
    }

    /// Whether every driving circle point has a branch defect (the
    /// directions `C'_k - C1` do not lie in an open half-plane).
    pub fn all_defective(&self) -> bool {
        self.order.is_none()
    }

    /// The poses (1-based) in the order of their lines' directions within
    /// the half-plane: the first and the last give the Filemon lines;
    /// `None` when all are defective.
    pub fn pose_order(&self) -> Option<PerPose<usize>> {
        self.order.map(|o| o.map(|k| k + 1))
    }

    /// The poses (1-based) whose lines are the extreme ones (the Filemon
    /// lines); `None` when all are defective.
    pub fn extreme_poses(&self) -> Option<[usize; 2]> {
        self.order.map(|o| [o[0] + 1, o[o.len() - 1] + 1])
    }

    /// The two Filemon lines (through `C1`, directions `C'_k - C1` of the
    /// extreme poses); `None` when all are defective.
    pub fn lines(&self) -> Option<[Line; 2]> {
        let all = self.all_lines();
        self.order.map(|o| [all[o[0]], all[o[o.len() - 1]]])
    }

    /// The sectors around `C1` cut by the lines (each line gives two rays),
    /// counter-clockwise: `(start angle, end angle, branch-free)` in
    /// radians, the angles increasing, the last sector ending a full turn
    /// after the first begins. A sector is branch-free where every line
    /// sees its points on one side (and not every circle point is
    /// defective): the double wedge between the Filemon lines.
    pub fn sectors(&self) -> Vec<(f64, f64, bool)> {
        use core::f64::consts::{PI, TAU};
        let dirs = self.dirs;
        let mut angles: Vec<f64> = dirs
            .iter()
            .flat_map(|d| {
                let a = d.y.atan2(d.x);
                [a.rem_euclid(TAU), (a + PI).rem_euclid(TAU)]
            })
            .collect();
        angles.sort_by(f64::total_cmp);
        angles.dedup();
        let n = angles.len();
        (0..n)
            .map(|k| {
                let a0 = angles[k];
                let a1 = if k + 1 < n {
                    angles[k + 1]
                } else {
                    angles[0] + TAU
                };
                let mid = 0.5 * (a0 + a1);
                let m = Vector2::new(mid.cos(), mid.sin());
                let s = dirs.iter().map(|d| cross(*d, m)).collect::<Vec<_>>();
                let free = !self.all_defective() && Branch::from_signs(&s) == Branch::Free;
                (a0, a1, free)
            })
            .collect()
    }

    /// The branch signs `cross(d_k, A1 - C1)` of a driving circle point,
    /// one per pose (`d_k` the [`directions`](Self::directions): for a
    /// slider `cross(n_k, A1 - C1) = <C1 - A1, u_k>`).
    pub fn circle_signs(&self, a1: Point2<f64>) -> PerPose<f64> {
        let c1 = self.driven.circle();
        self.dirs.map(|d| cross(d, a1 - c1))
    }

    /// The branch class of a driving circle point `A1` (Filemon's test in
    /// the circle-point plane). When every circle point is defective, none
    /// is free: a sign test that says otherwise is rounding at that border.
    pub fn classify_circle_point(&self, a1: Point2<f64>) -> Branch {
        match Branch::from_signs(&self.circle_signs(a1)) {
            Branch::Free if self.all_defective() => Branch::Defective,
            b => b,
        }
    }
}

/// The order of directions by angle when they lie in an open half-plane
/// (extremes first and last), else `None`.
pub(crate) fn half_plane_order(d: &[Vector2<f64>]) -> Option<PerPose<usize>> {
    use core::f64::consts::{PI, TAU};
    let n = d.len();
    let ang: Vec<f64> = d.iter().map(|v| v.y.atan2(v.x)).collect();
    let mut idx: Vec<usize> = (0..n).collect();
    idx.sort_by(|&a, &b| ang[a].total_cmp(&ang[b]));
    // Circular gaps between consecutive angles; the directions lie in an
    // open half-plane iff the largest gap exceeds pi. The extremes are the
    // two angles bounding that gap.
    let gap = |k: usize| {
        if k + 1 < n {
            ang[idx[k + 1]] - ang[idx[k]]
        } else {
            ang[idx[0]] + TAU - ang[idx[n - 1]]
        }
    };
    let (k, widest) = (0..n)
        .map(|k| (k, gap(k)))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap_or((0, 0.0));
    if widest <= PI {
        return None;
    }
    // The gap runs from idx[k] to idx[k+1]; the run of directions starts
    // after it.
    let start = (k + 1) % n;
    Some(PerPose::from_fn(n, |m| idx[(start + m) % n]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_plane_order_finds_the_extremes() {
        let v = |a: f64| Vector2::new(a.cos(), a.sin());
        let order = |d: &[Vector2<f64>]| half_plane_order(d).map(|o| o.to_vec());
        assert_eq!(order(&[v(0.1), v(0.5), v(0.3)]), Some(vec![0, 2, 1]));
        assert_eq!(order(&[v(3.0), v(-3.0), v(2.5)]), Some(vec![2, 0, 1]));
        assert_eq!(order(&[v(0.0), v(2.2), v(-2.2)]), None);
        assert_eq!(
            order(&[v(0.1), v(0.5), v(0.3), v(1.4)]),
            Some(vec![0, 2, 1, 3])
        );
        assert_eq!(order(&[v(0.0), v(1.0), v(2.0), v(3.5)]), None);
    }

    #[test]
    fn signs() {
        assert_eq!(Branch::from_signs(&[1.0, 2.0, 0.5, 3.0]), Branch::Free);
        assert_eq!(Branch::from_signs(&[-1.0, -2.0, -0.5]), Branch::Free);
        assert_eq!(Branch::from_signs(&[1.0, -2.0, 0.5]), Branch::Defective);
        assert_eq!(Branch::from_signs(&[1.0, 0.0, 0.5]), Branch::Boundary);
    }
}
