//! Dyads and the four-bar built from a driving and a driven dyad.
//!
//! A dyad is a crank: its center point (fixed pivot) and its circle point
//! (moving pivot at pose 1). The driving dyad is `(A0, A1)`, the driven dyad
//! `(C0, C1)`. At pose `k` the moving pivots are `A_k = D_1k(A1)` and
//! `C_k = D_1k(C1)`; the four-bar has ground `A0 C0`, crank `|A1 - A0|`,
//! coupler `|C1 - A1|` and rocker `|C1 - C0|`.
//!
//! With the position analysis' naming, the assembly mode at pose `k` is
//! the sign of `sin(theta4 - theta3) = cross(C_k - A_k, C_k - C0) / (L3 L4)`,
//! which is minus the branch sign `s_k = sign cross(C0 - C_k, A_k - C_k)` of
//! the paper: the design is free of the branch defect exactly when the mode
//! is the same at the three poses.

use nalgebra::{Point2, Vector2};

use crate::error::{DegenerateError, InvalidInput, Result};
use crate::fourbar::{AssemblyMode, FourBar};
use crate::geom::{cross, rotate};
use crate::task::{Pose, Task};

/// A crank of a synthesized linkage: its fixed pivot and its moving pivot
/// at pose 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dyad {
    /// The center point: the fixed pivot.
    pub center: Point2<f64>,
    /// The circle point: the moving pivot, where it is at pose 1.
    pub circle: Point2<f64>,
}

impl Dyad {
    /// A dyad from its center point and circle point.
    pub const fn new(center: Point2<f64>, circle: Point2<f64>) -> Self {
        Dyad { center, circle }
    }

    /// The crank length `|circle - center|`.
    pub fn length(&self) -> f64 {
        (self.circle - self.center).norm()
    }
}

/// A four-bar built from a driving and a driven dyad of a task, with what it
/// takes to drive it through the task's poses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SynthesizedFourBar {
    /// The linkage: input pivot `A0`, output pivot `C0`.
    pub fourbar: FourBar,
    /// The driving dyad `(A0, A1)`.
    pub driving: Dyad,
    /// The driven dyad `(C0, C1)`.
    pub driven: Dyad,
    /// The input angle `theta2` at each pose (absolute, radians).
    pub input_angles: [f64; 3],
    /// The assembly mode at each pose; `None` where the pose is a toggle
    /// (coupler and rocker collinear).
    pub modes: [Option<AssemblyMode>; 3],
    /// The task's coupler point in the linkage's coupler frame (origin at
    /// the crank joint `A`, x-axis toward the rocker joint `C`).
    pub coupler_point: Vector2<f64>,
    /// The task's coupler angle minus the linkage's coupler angle `theta3`
    /// (constant over the motion).
    pub coupler_angle_offset: f64,
}

impl SynthesizedFourBar {
    /// Whether the linkage passes the three poses in one assembly mode (no
    /// branch defect and no toggle at a pose).
    pub fn is_branch_free(&self) -> bool {
        matches!(self.modes, [Some(a), Some(b), Some(c)] if a == b && b == c)
    }

    /// The coupler pose (the task's coupler point and angle) when the
    /// linkage is driven to `theta2` in `mode`.
    ///
    /// # Errors
    ///
    /// As [`FourBar::solve`].
    pub fn pose_at(&self, theta2: f64, mode: AssemblyMode) -> Result<Pose> {
        let c = self.fourbar.solve(theta2, mode)?;
        let p = self.fourbar.coupler_point(&c, self.coupler_point);
        Ok(Pose {
            position: p,
            angle: c.theta3 + self.coupler_angle_offset,
        })
    }
}

impl Task {
    /// The dyad whose center point is `center` (its circle point from
    /// [`Task::circle_point`]).
    ///
    /// # Errors
    ///
    /// As [`Task::circle_point`].
    pub fn dyad_from_center(&self, center: Point2<f64>) -> Result<Dyad> {
        Ok(Dyad::new(center, self.circle_point(center)?))
    }

    /// The dyad whose circle point is `circle` (its center point from
    /// [`Task::center_point`]).
    ///
    /// # Errors
    ///
    /// As [`Task::center_point`].
    pub fn dyad_from_circle(&self, circle: Point2<f64>) -> Result<Dyad> {
        Ok(Dyad::new(self.center_point(circle)?, circle))
    }

    /// Where the dyad's moving pivot is at pose `k` (1-based): `D_1k(circle)`.
    ///
    /// # Panics
    ///
    /// If `k` is not 1, 2 or 3.
    pub fn moving_pivot(&self, dyad: &Dyad, k: usize) -> Point2<f64> {
        self.displace(dyad.circle, 1, k)
    }

    /// The dyad's crank angle at each pose: `arg(D_1k(circle) - center)`.
    pub fn crank_angles(&self, dyad: &Dyad) -> [f64; 3] {
        [1, 2, 3].map(|k| {
            let v = self.moving_pivot(dyad, k) - dyad.center;
            v.y.atan2(v.x)
        })
    }

    /// Checks that `dyad` is a dyad of this task: its moving pivot stays at
    /// one distance from its fixed pivot over the three poses (within a
    /// relative `1e-9`), and it has a length.
    fn check_dyad(&self, dyad: &Dyad, what: &'static str) -> Result<()> {
        let d = [1, 2, 3].map(|k| (self.moving_pivot(dyad, k) - dyad.center).norm());
        let size = d[0].max(d[1]).max(d[2]);
        if !size.is_finite() {
            return Err(InvalidInput::NotFinite {
                name: what,
                value: size,
            }
            .into());
        }
        if size <= Task::POINT_TOLERANCE * self.scale() {
            return Err(DegenerateError::ZeroLengthLink {
                what,
                x: dyad.center.x,
                y: dyad.center.y,
            }
            .into());
        }
        if (d[0] - d[1]).abs().max((d[0] - d[2]).abs()) > 1e-9 * (size + self.scale()) {
            return Err(InvalidInput::OutOfRange {
                name: what,
                expected: "must be a dyad of the task (its moving pivot at one distance from its \
                           fixed pivot in all three poses); build it with Task::dyad_from_center",
                found: format!("distances {:?}", d),
            }
            .into());
        }
        Ok(())
    }

    /// The four-bar built from a driving dyad `(A0, A1)` and a driven dyad
    /// `(C0, C1)`, with its input angle and assembly mode at each pose.
    ///
    /// Driving the returned linkage to `input_angles[k]` in `modes[k]`
    /// places the task's coupler point and angle at pose `k + 1`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::OutOfRange`] when a dyad is not a dyad of this task;
    /// [`DegenerateError::ZeroLengthLink`] when a link has zero length
    /// (coincident pivots, a crank of zero length, or coincident moving
    /// pivots); errors of [`FourBar::from_pivots`].
    pub fn four_bar(&self, driving: &Dyad, driven: &Dyad) -> Result<SynthesizedFourBar> {
        self.check_dyad(driving, "driving dyad")?;
        self.check_dyad(driven, "driven dyad")?;
        let tiny = Task::POINT_TOLERANCE * self.scale();
        for (a, b, what) in [
            (driving.center, driven.center, "ground link"),
            (driving.circle, driven.circle, "coupler link"),
        ] {
            if (a - b).norm() <= tiny {
                return Err(DegenerateError::ZeroLengthLink {
                    what,
                    x: a.x,
                    y: a.y,
                }
                .into());
            }
        }
        let fourbar = FourBar::from_pivots(
            driving.center,
            driven.center,
            driving.length(),
            (driven.circle - driving.circle).norm(),
            driven.length(),
        )?;
        let a = [1, 2, 3].map(|k| self.moving_pivot(driving, k));
        let c = [1, 2, 3].map(|k| self.moving_pivot(driven, k));
        let input_angles = [0, 1, 2].map(|k| {
            let v = a[k] - driving.center;
            v.y.atan2(v.x)
        });
        let modes = [0, 1, 2].map(|k| {
            let s = cross(c[k] - a[k], c[k] - driven.center);
            let size = (c[k] - a[k]).norm() * (c[k] - driven.center).norm();
            if s.abs() <= 16.0 * f64::EPSILON * size {
                None
            } else {
                AssemblyMode::from_sign(s)
            }
        });
        let ac = c[0] - a[0];
        let theta3 = ac.y.atan2(ac.x);
        let pose1 = self.poses()[0];
        Ok(SynthesizedFourBar {
            fourbar,
            driving: *driving,
            driven: *driven,
            input_angles,
            modes,
            coupler_point: rotate(pose1.position - a[0], -theta3),
            coupler_angle_offset: pose1.angle - theta3,
        })
    }
}
