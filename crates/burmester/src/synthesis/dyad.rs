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
//! is the same at every pose ([`AssemblyMode::of_loop`]).

use core::f64::consts::TAU;

use nalgebra::{Point2, Vector2};

use crate::error::{DegenerateError, InvalidInput, Result, count_in};
use crate::geom::{PerPose, Pose, rotate};
use crate::linkage::figures::{figures, figures_of};
use crate::linkage::{AssemblyMode, Direction, FourBar, LinkageFigures};
use crate::synthesis::Task;
use crate::tolerance;

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
/// takes to drive it through the task's poses and its figures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SynthesizedFourBar {
    /// The linkage: input pivot `A0`, output pivot `C0`.
    pub fourbar: FourBar,
    /// The driving dyad `(A0, A1)`.
    pub driving: Dyad,
    /// The driven dyad `(C0, C1)`.
    pub driven: Dyad,
    /// The input angle `theta2` at each pose (absolute, radians, in
    /// `(-pi, pi]`).
    pub input_angles: PerPose<f64>,
    /// The task's coupler point in the linkage's coupler frame (origin at
    /// the crank joint `A`, x-axis toward the rocker joint `C`).
    pub coupler_point: Vector2<f64>,
    /// The task's coupler angle minus the linkage's coupler angle `theta3`
    /// (constant over the motion).
    pub coupler_angle_offset: f64,
    /// What a designer checks of it: the assembly mode at each pose,
    /// Grashof type, order and circuit, the minimum transmission angle over
    /// the travel, the link ratio.
    pub figures: LinkageFigures,
}

impl SynthesizedFourBar {
    /// The most input angles [`travel_angles`](Self::travel_angles) returns.
    pub const MAX_TRAVEL_SAMPLES: usize = 1 << 20;

    /// The assembly mode at each pose; `None` where the pose is a toggle
    /// (coupler and rocker collinear).
    pub fn modes(&self) -> PerPose<Option<AssemblyMode>> {
        self.figures.modes
    }

    /// Whether the linkage passes every pose in one assembly mode (no
    /// branch defect and no toggle at a pose).
    pub fn is_branch_free(&self) -> bool {
        self.figures.branch_free()
    }

    /// The linkage's size: the total length of its members, the ground
    /// `A0 C0`, the crank, the rocker and the three sides of the coupler
    /// triangle (the moving pivots and the task's coupler point, which the
    /// coupler plate must carry). Compare it with the task's size,
    /// [`Task::span`]: the solution map's `size_ratio` column is this over
    /// that.
    pub fn size(&self) -> f64 {
        let (a, c) = (self.driving.circle, self.driven.circle);
        let ac = c - a;
        let p = a + rotate(self.coupler_point, ac.y.atan2(ac.x));
        members_length(self.figures.lengths, a, c, p)
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

    /// The travel: the input angle at pose 1 and the signed angle the input
    /// turns, in the feasible direction, through the poses to the last
    /// (positive counter-clockwise); `None` when no direction carries the
    /// coupler through the poses in order ([`Direction::None`]).
    pub fn travel(&self) -> Option<(f64, f64)> {
        travel_of(&self.input_angles, self.figures.direction)
    }

    /// The input angle at each pose along the [`travel`](Self::travel),
    /// unwrapped: starting at the angle of pose 1 and moving monotonically
    /// in the travel's direction (so the poses' angles are exact stops of a
    /// drive); `None` when there is no travel.
    pub fn travel_stops(&self) -> Option<PerPose<f64>> {
        travel_stops_of(&self.input_angles, self.travel()?)
    }

    /// `samples` input angles evenly spaced over the [`travel`](Self::travel),
    /// both ends included (for drawing and animating the motion).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::CountOutOfRange`] for fewer than 2 or more than
    /// [`SynthesizedFourBar::MAX_TRAVEL_SAMPLES`] samples;
    /// [`InvalidInput::NeedsPoses`]-free: a linkage without a feasible
    /// direction gives an empty list.
    pub fn travel_angles(&self, samples: usize) -> Result<Vec<f64>> {
        travel_angles_of(self.travel(), samples, Self::MAX_TRAVEL_SAMPLES)
    }
}

/// The travel of an input whose angles at the poses are `t` and whose
/// feasible direction is `direction` ([`SynthesizedFourBar::travel`]).
pub(crate) fn travel_of(t: &PerPose<f64>, direction: Direction) -> Option<(f64, f64)> {
    let span = (t[t.len() - 1] - t[0]).rem_euclid(TAU);
    match direction {
        Direction::Ccw => Some((t[0], span)),
        Direction::Cw => Some((t[0], span - TAU)),
        Direction::None => None,
    }
}

/// The input angles `t` unwrapped along the travel `(start, span)`
/// ([`SynthesizedFourBar::travel_stops`]).
pub(crate) fn travel_stops_of(t: &PerPose<f64>, (start, span): (f64, f64)) -> Option<PerPose<f64>> {
    Some(PerPose::from_fn(t.len(), |k| {
        let d = (t[k] - t[0]).rem_euclid(TAU);
        let d = if span < 0.0 && d > 0.0 { d - TAU } else { d };
        start + d
    }))
}

/// `samples` angles evenly spaced over a travel, both ends included, at
/// most `max` ([`SynthesizedFourBar::travel_angles`]); empty without a
/// travel.
pub(crate) fn travel_angles_of(
    travel: Option<(f64, f64)>,
    samples: usize,
    max: usize,
) -> Result<Vec<f64>> {
    let n = count_in("travel samples", samples, 2, max)?;
    Ok(match travel {
        Some((start, span)) => crate::error::try_collect(
            "travel angles",
            n,
            (0..n).map(|k| start + span * (k as f64 / (n - 1) as f64)),
        )?,
        None => Vec::new(),
    })
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

    /// Where the dyad's moving pivot is at each pose: `D_1k(circle)`.
    pub fn moving_pivots(&self, dyad: &Dyad) -> PerPose<Point2<f64>> {
        self.motion().positions(dyad.circle)
    }

    /// The dyad's crank angle at each pose: `arg(D_1k(circle) - center)`.
    pub fn crank_angles(&self, dyad: &Dyad) -> PerPose<f64> {
        self.moving_pivots(dyad).map(|p| {
            let v = p - dyad.center;
            v.y.atan2(v.x)
        })
    }

    /// Checks that `dyad` is a dyad of this task: its moving pivot stays at
    /// one distance from its fixed pivot over the poses (within
    /// [`tolerance::DYAD`]), and it has a length.
    pub(crate) fn check_dyad(&self, dyad: &Dyad, which: &'static str) -> Result<()> {
        self.check_dyad_at(dyad, &self.moving_pivots(dyad), which)
    }

    /// [`check_dyad`](Self::check_dyad) of a dyad whose moving pivot is at
    /// `at` at the poses.
    fn check_dyad_at(&self, dyad: &Dyad, at: &[Point2<f64>], which: &'static str) -> Result<()> {
        let d = PerPose::from_fn(at.len(), |k| (at[k] - dyad.center).norm());
        let size = d.iter().copied().fold(0.0, f64::max);
        if !size.is_finite() {
            return Err(InvalidInput::Overflow {
                what: "the dyad's length",
                hint: "pass a dyad nearer the task",
            }
            .into());
        }
        if size <= tolerance::POINT * self.scale() {
            return Err(DegenerateError::ZeroLengthLink {
                what: which,
                x: dyad.center.x,
                y: dyad.center.y,
            }
            .into());
        }
        let spread =
            d.iter().map(|&x| (x - d[0]).abs()).fold(0.0, f64::max) / (size + self.scale());
        if spread > tolerance::DYAD {
            return Err(InvalidInput::NotADyad {
                which,
                spread,
                tolerance: tolerance::DYAD,
            }
            .into());
        }
        Ok(())
    }

    /// The four-bar built from a driving dyad `(A0, A1)` and a driven dyad
    /// `(C0, C1)`, with its input angle and assembly mode at each pose and
    /// its figures.
    ///
    /// Driving the returned linkage to `input_angles[k]` in `modes()[k]`
    /// places the task's coupler point and angle at pose `k + 1`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotADyad`] when a dyad is not a dyad of this task;
    /// [`DegenerateError::ZeroLengthLink`] when a link has zero length
    /// (coincident pivots, a crank of zero length, or coincident moving
    /// pivots); errors of [`FourBar::from_pivots`].
    pub fn four_bar(&self, driving: &Dyad, driven: &Dyad) -> Result<SynthesizedFourBar> {
        let a = self.moving_pivots(driving);
        let c = self.moving_pivots(driven);
        self.check_dyad_at(driving, &a, "driving dyad")?;
        self.check_dyad_at(driven, &c, "driven dyad")?;
        let fourbar = linkage_of(driving, driven, tolerance::POINT * self.scale())?;
        let input_angles = a.map(|p| {
            let v = p - driving.center;
            v.y.atan2(v.x)
        });
        let figures = figures_of(driving.center, &a, driven.center, &c, 0.0).ok_or(
            InvalidInput::Overflow {
                what: "the linkage's lengths",
                hint: "pass dyads nearer the task",
            },
        )?;
        let (coupler_point, coupler_angle_offset) = self.coupler_point_along(a[0], c[0] - a[0]);
        Ok(SynthesizedFourBar {
            fourbar,
            driving: *driving,
            driven: *driven,
            input_angles,
            coupler_point,
            coupler_angle_offset,
            figures,
        })
    }

    /// The coupler's angle `theta3` at pose 1 of a linkage whose coupler
    /// frame has its origin at `a1` and its x-axis along `axis` there (a
    /// four-bar's: from its crank pin toward its rocker pin), and the task's
    /// coupler point in that frame ([`SynthesizedFourBar::coupler_point`]).
    fn coupler_frame_along(&self, a1: Point2<f64>, axis: Vector2<f64>) -> (f64, Vector2<f64>) {
        let theta3 = axis.y.atan2(axis.x);
        (theta3, rotate(self.poses()[0].position - a1, -theta3))
    }

    /// The task's coupler point in the coupler frame of
    /// [`coupler_frame_along`](Self::coupler_frame_along) and its coupler
    /// angle at pose 1 minus `theta3` there.
    pub(crate) fn coupler_point_along(
        &self,
        a1: Point2<f64>,
        axis: Vector2<f64>,
    ) -> (Vector2<f64>, f64) {
        let (theta3, point) = self.coupler_frame_along(a1, axis);
        (point, self.poses()[0].angle - theta3)
    }

    /// The figures of [`four_bar`](Self::four_bar)'s linkage and its
    /// [`SynthesizedFourBar::size`], bit for bit, or `None` exactly where
    /// `four_bar` fails: the same checks and arithmetic without what the
    /// figures and the size do not need (the ground angle, the input
    /// angles, the moving pivots a second time). The design search's exact
    /// judge, which builds the linkage only for the few it keeps.
    pub(crate) fn four_bar_figures(
        &self,
        driving: &Dyad,
        driven: &Dyad,
    ) -> Option<(LinkageFigures, f64)> {
        match self.len() {
            3 => self.four_bar_figures_n::<3>(driving, driven),
            4 => self.four_bar_figures_n::<4>(driving, driven),
            5 => self.four_bar_figures_n::<5>(driving, driven),
            _ => None,
        }
    }

    /// [`four_bar_figures`](Self::four_bar_figures) of a task of `N` poses.
    #[inline]
    fn four_bar_figures_n<const N: usize>(
        &self,
        driving: &Dyad,
        driven: &Dyad,
    ) -> Option<(LinkageFigures, f64)> {
        let m = self.motion();
        let a: [Point2<f64>; N] = core::array::from_fn(|k| m.first_to(k, driving.circle));
        let c: [Point2<f64>; N] = core::array::from_fn(|k| m.first_to(k, driven.circle));
        self.check_dyad_at(driving, &a, "driving dyad").ok()?;
        self.check_dyad_at(driven, &c, "driven dyad").ok()?;
        let figures = figures::<true, N>(driving.center, &a, driven.center, &c, 0.0)?;
        // The checks of `linkage_of` on the figures' lengths, which are its
        // lengths: with both dyads checked their points are finite, and the
        // moving pivots at pose 1 are the circle points (up to a zero's
        // sign); its ground angle is finite with its ground's length.
        let [ground, crank, coupler, rocker] = figures.lengths;
        let tiny = tolerance::POINT * self.scale();
        if ground <= tiny
            || coupler <= tiny
            || !FourBar::lengths_ok(ground, crank, coupler, rocker, driving.center)
        {
            return None;
        }
        // `SynthesizedFourBar::size`: the coupler point placed back from
        // the coupler's frame along the circle points' direction, which is
        // `theta3`'s own unless a zero's sign differs.
        let ac1 = c[0] - a[0];
        let (theta3, coupler_point) = self.coupler_frame_along(a[0], ac1);
        let (pa, pc) = (driving.circle, driven.circle);
        let ac = pc - pa;
        let same = ac.x.to_bits() == ac1.x.to_bits() && ac.y.to_bits() == ac1.y.to_bits();
        let angle = if same { theta3 } else { ac.y.atan2(ac.x) };
        let p = pa + rotate(coupler_point, angle);
        Some((figures, members_length(figures.lengths, pa, pc, p)))
    }

    /// The figures of the linkage built from a driving and a driven dyad of
    /// this task (its [`SynthesizedFourBar::figures`]).
    ///
    /// # Errors
    ///
    /// As [`Task::four_bar`].
    pub fn linkage_figures(&self, driving: &Dyad, driven: &Dyad) -> Result<LinkageFigures> {
        Ok(self.four_bar(driving, driven)?.figures)
    }
}

/// The total length of a linkage's members (see
/// [`SynthesizedFourBar::size`]) from its four link lengths (ground,
/// crank, coupler, rocker), its moving pivots `a`, `c` and the coupler
/// point `p`, all at pose 1.
#[inline]
pub(crate) fn members_length(
    lengths: [f64; 4],
    a: Point2<f64>,
    c: Point2<f64>,
    p: Point2<f64>,
) -> f64 {
    let [l1, l2, l3, l4] = lengths;
    l1 + l2 + l3 + l4 + (p - a).norm() + (p - c).norm()
}

/// The four-bar of two dyads (for any number of poses): ground from the
/// driving to the driven center, crank and rocker their lengths, coupler
/// between the circle points.
///
/// # Errors
///
/// [`DegenerateError::ZeroLengthLink`] when the ground or the coupler is
/// within `tiny` of zero; errors of [`FourBar::from_pivots`].
pub(crate) fn linkage_of(driving: &Dyad, driven: &Dyad, tiny: f64) -> Result<FourBar> {
    crate::linkage::nonzero_links(
        [
            (driving.center, driven.center, "ground link"),
            (driving.circle, driven.circle, "coupler link"),
        ],
        tiny,
    )?;
    FourBar::from_pivots(
        driving.center,
        driven.center,
        driving.length(),
        (driven.circle - driving.circle).norm(),
        driven.length(),
    )
}
