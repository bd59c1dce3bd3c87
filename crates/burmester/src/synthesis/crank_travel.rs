//! What a linkage of a task driven by a crank derives from its crank angles,
//! modes, direction and circuit at the poses, written once for the kinds
//! that have them as fields (the slider-crank and the inverted
//! slider-crank of a task), with the struct holding those fields, and the
//! crank angles, modes and travel their constructors compute.

use nalgebra::{Point2, Vector2};

use crate::error::{InvalidInput, Result};
use crate::geom::PerPose;
use crate::linkage::AssemblyMode;
use crate::linkage::figures::{Travel, travel};
use crate::synthesis::DyadKind;

/// The struct of a synthesized linkage driven by a crank: the linkage, the
/// driving dyad, the driven one, the crank angle, assembly mode and the
/// driven joint's position (`$positions`) at each pose, the task's coupler
/// point and angle offset, the direction, circuit, smallest transmission
/// angle and stroke used, then the fields of its own kind; with its
/// [`crank_travel_methods`] and `pose_at`.
macro_rules! crank_synthesized {
    (
        $(#[$meta:meta])*
        pub struct $Type:ident {
            $(#[$ld:meta])* linkage: $L:ty,
            $(#[$dd:meta])* driven: $D:ty,
            toggle: $toggle:literal,
            $(#[$pd:meta])* $positions:ident,
            axis: $axis:literal,
            $(#[$sd:meta])* stroke_used,
            $($(#[$xd:meta])* $extra:ident: $xt:ty,)*
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub struct $Type {
            $(#[$ld])*
            pub linkage: $L,
            /// The driving dyad `(A0, A1)`.
            pub driving: $crate::synthesis::Dyad,
            $(#[$dd])*
            pub driven: $D,
            /// The crank angle at each pose (absolute, radians, in `(-pi, pi]`).
            pub input_angles: $crate::geom::PerPose<f64>,
            #[doc = concat!(
                "The assembly mode at each pose; `None` where the pose is at a\n",
                "toggle (", $toggle, ")."
            )]
            pub modes: $crate::geom::PerPose<Option<$crate::linkage::AssemblyMode>>,
            $(#[$pd])*
            pub $positions: $crate::geom::PerPose<f64>,
            #[doc = concat!(
                "The task's coupler point in the coupler frame (origin at the crank\n",
                "pin `A`, x-axis ", $axis, ")."
            )]
            pub coupler_point: nalgebra::Vector2<f64>,
            /// The task's coupler angle minus the coupler angle `theta3`.
            pub coupler_angle_offset: f64,
            /// The crank rotation that carries the coupler from pose 1 through the
            /// poses in order to the last.
            pub direction: $crate::linkage::Direction,
            /// Whether the crank angles at the poses lie on one circuit (one arc
            /// of the input range; always true for a crank that turns fully).
            pub one_circuit: bool,
            /// The smallest transmission angle over the travel, radians in
            /// `[0, pi/2]`; NaN without a travel.
            pub min_transmission: f64,
            $(#[$sd])*
            pub stroke_used: f64,
            $($(#[$xd])* pub $extra: $xt,)*
        }

        $crate::synthesis::crank_travel::crank_travel_methods!($Type);

        impl $Type {
            /// The struct from its parts: the linkage, the dyads, the crank
            /// angles and modes at the poses (`crank_modes`), the crank's
            /// travel (`crank_travel`), the task's coupler point and angle
            /// offset in the coupler frame (`Task::coupler_point_along`),
            /// the driven joint's positions and the figures (the smallest
            /// transmission angle, the stroke used, then the kind's own).
            #[allow(clippy::too_many_arguments)]
            fn from_parts(
                linkage: $L,
                driving: $crate::synthesis::Dyad,
                driven: $D,
                (input_angles, modes): (
                    $crate::geom::PerPose<f64>,
                    $crate::geom::PerPose<Option<$crate::linkage::AssemblyMode>>,
                ),
                travel: $crate::linkage::figures::Travel,
                (coupler_point, coupler_angle_offset): (nalgebra::Vector2<f64>, f64),
                $positions: $crate::geom::PerPose<f64>,
                (min_transmission, stroke_used, $($extra,)*): (f64, f64, $($xt,)*),
            ) -> Self {
                $Type {
                    linkage,
                    driving,
                    driven,
                    input_angles,
                    modes,
                    $positions,
                    coupler_point,
                    coupler_angle_offset,
                    direction: travel.direction,
                    one_circuit: travel.one_circuit,
                    min_transmission,
                    stroke_used,
                    $($extra,)*
                }
            }

            /// The [`stroke_used`](Self::stroke_used), or where that is NaN
            /// the spread of the driven joint's positions at the poses.
            fn stroke_or_spread(&self) -> f64 {
                if self.stroke_used.is_nan() {
                    let s = &self.$positions;
                    let hi = s.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                    let lo = s.iter().copied().fold(f64::INFINITY, f64::min);
                    hi - lo
                } else {
                    self.stroke_used
                }
            }

            /// The coupler pose (the task's coupler point and angle) when the
            /// crank is driven to `theta2` in `mode`.
            ///
            /// # Errors
            ///
            #[doc = concat!("As [`", stringify!($L), "::solve`].")]
            pub fn pose_at(
                &self,
                theta2: f64,
                mode: $crate::linkage::AssemblyMode,
            ) -> $crate::Result<$crate::geom::Pose> {
                let c = self.linkage.solve(theta2, mode)?;
                Ok($crate::geom::Pose {
                    position: self.linkage.coupler_point(&c, self.coupler_point),
                    angle: c.theta3 + self.coupler_angle_offset,
                })
            }
        }
    };
}

pub(crate) use crank_synthesized;

/// The branch, feasibility, order and travel methods of a synthesized
/// linkage with the fields `input_angles`, `modes`, `direction` and
/// `one_circuit`.
macro_rules! crank_travel_methods {
    ($Type:ident) => {
        impl $Type {
            /// The most crank angles [`travel_angles`](Self::travel_angles)
            /// returns.
            pub const MAX_TRAVEL_SAMPLES: usize = 1 << 20;

            /// Whether every pose is in one assembly mode (no branch
            /// defect, no toggle at a pose).
            pub fn is_branch_free(&self) -> bool {
                $crate::synthesis::crank_travel::branch_mode(&self.modes).is_some()
            }

            /// Whether the motion through the poses in order is feasible:
            /// branch-free, one circuit and a driving direction.
            pub fn feasible(&self) -> bool {
                self.is_branch_free()
                    && self.one_circuit
                    && self.direction != $crate::linkage::Direction::None
            }

            /// The cyclic order of the crank's positions at the poses.
            pub fn order(&self) -> $crate::synthesis::CrankOrder {
                $crate::synthesis::CrankOrder::from_angles(&self.input_angles)
            }

            /// The travel: the crank angle at pose 1 and the signed angle
            /// the crank turns through the poses to the last (positive
            /// counter-clockwise); `None` without a driving direction.
            pub fn travel(&self) -> Option<(f64, f64)> {
                $crate::synthesis::dyad::travel_of(&self.input_angles, self.direction)
            }

            /// The crank angle at each pose along the
            /// [`travel`](Self::travel), unwrapped (monotone from the angle
            /// at pose 1); `None` without a travel.
            pub fn travel_stops(&self) -> Option<$crate::geom::PerPose<f64>> {
                $crate::synthesis::dyad::travel_stops_of(&self.input_angles, self.travel()?)
            }

            /// `samples` crank angles evenly spaced over the travel, both
            /// ends included; empty without a travel.
            ///
            /// # Errors
            ///
            /// [`InvalidInput::CountOutOfRange`](crate::InvalidInput::CountOutOfRange)
            /// for fewer than 2 or more than
            /// [`MAX_TRAVEL_SAMPLES`](Self::MAX_TRAVEL_SAMPLES) samples;
            /// [`Error::OutOfMemory`](crate::Error::OutOfMemory) when they
            /// cannot be allocated.
            pub fn travel_angles(&self, samples: usize) -> $crate::Result<Vec<f64>> {
                $crate::synthesis::dyad::travel_angles_of(
                    self.travel(),
                    samples,
                    Self::MAX_TRAVEL_SAMPLES,
                )
            }
        }
    };
}

pub(crate) use crank_travel_methods;

/// The one assembly mode of every pose, `None` with a branch defect or a
/// toggle at a pose.
pub(crate) fn branch_mode(modes: &[Option<AssemblyMode>]) -> Option<AssemblyMode> {
    match modes.first() {
        Some(Some(m)) if modes.iter().all(|x| *x == Some(*m)) => Some(*m),
        _ => None,
    }
}

/// The crank angles `arg(A_k - A0)` of a crank about `a0` whose pin is at
/// `a[k]` at pose `k`, and the assembly mode at each pose of the linkage
/// whose driven dyad is `kind` with its joint at `joint(k)`
/// ([`DyadKind::assembly_mode`], `reach` as there); `None` at a toggle and
/// where the position analysis' loop at the pose's crank angle does not
/// assemble clear of its toggle in that mode (`clear(theta2, mode)`, as the
/// four-bar's figures).
pub(crate) fn crank_modes(
    a: &PerPose<Point2<f64>>,
    a0: Point2<f64>,
    kind: DyadKind,
    joint: impl Fn(usize) -> Point2<f64>,
    reach: f64,
    clear: impl Fn(f64, AssemblyMode) -> bool,
) -> (PerPose<f64>, PerPose<Option<AssemblyMode>>) {
    let input_angles = a.map(|p| {
        let v = p - a0;
        v.y.atan2(v.x)
    });
    let modes = PerPose::from_fn(a.len(), |k| {
        let m = kind.assembly_mode(a[k], joint(k), reach)?;
        clear(input_angles[k], m).then_some(m)
    });
    (input_angles, modes)
}

/// The directions `A_k - A0` of a crank about `a0` whose pin is at `a[k]`
/// at pose `k`, and its travel through the poses ([`travel`] about `axis`,
/// the input range's ends free where `lo`, `hi`).
///
/// # Errors
///
/// [`InvalidInput::PoseCount`] for other than 3 to 5 poses.
pub(crate) fn crank_travel(
    a: &PerPose<Point2<f64>>,
    a0: Point2<f64>,
    axis: Vector2<f64>,
    lo: bool,
    hi: bool,
) -> Result<(Vec<Vector2<f64>>, Travel)> {
    let e: Vec<Vector2<f64>> = a.iter().map(|p| p - a0).collect();
    let trav = match e.len() {
        3 => e.first_chunk().map(|e| travel::<3>(e, axis, lo, hi)),
        4 => e.first_chunk().map(|e| travel::<4>(e, axis, lo, hi)),
        5 => e.first_chunk().map(|e| travel::<5>(e, axis, lo, hi)),
        _ => None,
    };
    let trav = trav.ok_or(InvalidInput::PoseCount {
        found: e.len(),
        min: 3,
        max: 5,
    })?;
    Ok((e, trav))
}

impl crate::Task {
    /// Checks that the points `p[k]` lie on the lines through `base` in the
    /// directions `dir(k)` (unit): the largest distance from them over the
    /// largest distance from `base` plus the task's scale must be within
    /// [`tolerance::DYAD`](crate::tolerance::DYAD). A slider's pin
    /// positions on its guide, an inverted slider's swivel on the body line
    /// at each pose.
    ///
    /// # Errors
    ///
    /// [`crate::InvalidInput::NotASlider`] naming
    /// `which`, with the spread found.
    pub(crate) fn check_on_lines(
        &self,
        which: &'static str,
        p: &[nalgebra::Point2<f64>],
        base: nalgebra::Point2<f64>,
        dir: impl Fn(usize) -> nalgebra::Vector2<f64>,
    ) -> crate::Result<()> {
        let reach = p.iter().map(|q| (q - base).norm()).fold(0.0, f64::max);
        let off = p
            .iter()
            .enumerate()
            .map(|(k, q)| crate::geom::cross(dir(k), q - base).abs())
            .fold(0.0, f64::max);
        let spread = off / (reach + self.scale());
        let tolerance = crate::tolerance::DYAD;
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(spread <= tolerance) {
            return Err(crate::InvalidInput::NotASlider {
                which,
                spread,
                tolerance,
            }
            .into());
        }
        Ok(())
    }
}
