//! The Watt II six-bar: a motion four-bar whose input link is driven by a
//! second four-bar, so that a motor turning a crank drives a linkage whose
//! own input only swings (the added dyad of Borm & Kim's conclusion).
//!
//! # The chain
//!
//! ```text
//!            D ─────────── E                 drive loop   D0 - D - E - A0
//!           /               \    A ──── C    motion loop  A0 - A - C - C0
//!         D0                 A0 ─┘       \
//!                                         C0
//! ```
//!
//! The **drive loop** is a four-bar with input pivot `D0`, crank `D0 D`
//! (the motor's crank, angle `phi`), coupler `D E` and rocker `A0 E`
//! (angle `psi`). The **motion loop** is a four-bar with input pivot `A0`,
//! input link `A0 A` (angle `theta2`), coupler `A C` carrying the coupler
//! point, and rocker `C0 C`. `A0`, `A` and `E` are one rigid (ternary)
//! link, so
//!
//! ```text
//! theta2 = psi - delta,    delta = arg(E - A0) - arg(A - A0)   (constant)
//! ```
//!
//! Each loop closes in its own assembly mode ([`AssemblyMode`], the sign
//! of `sin(theta4 - theta3)` of that loop). The position at a crank angle
//! is the drive loop solved at `phi`, then the motion loop at
//! `theta2 = psi - delta`: both by [`FourBar::solve`], so every figure is
//! the four-bar's own, toggle criterion included.
//!
//! # Turning fully
//!
//! The crank turns fully and `A0 E` swings exactly when the drive loop is a
//! Grashof crank-rocker, crank shortest (the drive's
//! [`Grashof::CrankRocker`]). The swing's ends are the two **limit
//! positions**, crank and coupler collinear: `|E - D0| = c + r` (extended)
//! and `|E - D0| = c - r` (folded). With `g = |A0 - D0|` and `rho =
//! |E - A0|`, the triangle `D0 A0 E` has
//!
//! ```text
//! cos(alpha) = (g^2 + s^2 - rho^2) / (2 g s),   s = c + r or c - r,
//! arg(E - D0) = arg(A0 - D0) + m alpha          (m = +1 open, -1 crossed)
//! ```
//!
//! (at a limit position `E - D` is parallel to `E - D0`, so the drive's
//! mode is the sign of `cross(A0 - D0, E - D0)`). The six-bar turns fully
//! when, in addition, the motion loop's input `theta2` stays strictly
//! inside its input range over the swing (neither loop toggles). The
//! **time ratio** of the two strokes is `max(beta, 2 pi - beta) /
//! min(beta, 2 pi - beta)`, `beta` the crank's turn from one limit
//! position to the other.
//!
//! # Transmission over the whole turn
//!
//! The drive's transmission angle depends on `phi` only through
//! `t = |D - A0|`, which runs over `[|g - r|, g + r]` in a full turn:
//!
//! ```text
//! cos(gamma) = (c^2 + rho^2 - t^2) / (2 c rho)
//! ```
//!
//! is linear in `t^2`, so its largest magnitude is at `t = g + r` or
//! `t = |g - r|`. The motion loop's transmission over the swing is the
//! four-bar's closed form over an arc of its input
//! ([`LinkageFigures`](crate::LinkageFigures)): the arc's ends, and the
//! ground direction or its opposite where the arc passes them. Both minima
//! are exact.
//!
//! Norton (*Design of Machinery*, Example 3-4 and §3.4) adds a driver dyad
//! the same way to a non-Grashof linkage; the conclusion of Borm & Kim's
//! paper names it as the way to give any synthesized linkage a fully
//! rotating crank.

use core::f64::consts::{PI, TAU};

use nalgebra::{Point2, Vector2};

use crate::error::{DriveError, InvalidInput, Result, finite};
use crate::geom::{Pose, point_is_finite, rotate, unit, wrap_angle};
use crate::linkage::grashof::{fmax, fmin};
use crate::linkage::{AngleInterval, AssemblyMode, Configuration, FourBar, Grashof, InputRange};
use crate::simd::acos1;
use crate::tolerance;

/// Where the joints of a [`SixBar`] are in one position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SixBarJoints {
    /// `D0`: the motor's fixed pivot (the drive crank's).
    pub drive_pivot: Point2<f64>,
    /// `D`: the drive crank's tip, joining crank and drive coupler.
    pub crank_joint: Point2<f64>,
    /// `E`: where the drive coupler joins the motion loop's input link.
    pub attachment: Point2<f64>,
    /// `A0`: the motion loop's input pivot (fixed), the drive's output pivot.
    pub input_pivot: Point2<f64>,
    /// `A`: the motion loop's input joint (input link to coupler).
    pub input_joint: Point2<f64>,
    /// `C`: the motion loop's rocker joint (coupler to rocker).
    pub rocker_joint: Point2<f64>,
    /// `C0`: the motion loop's output pivot (fixed).
    pub output_pivot: Point2<f64>,
    /// `P`: the coupler point (fixed to the coupler `A C`).
    pub coupler_point: Point2<f64>,
}

impl SixBarJoints {
    /// The joints as an array, in the order of the fields (`D0, D, E, A0,
    /// A, C, C0, P`).
    pub fn to_array(&self) -> [Point2<f64>; 8] {
        [
            self.drive_pivot,
            self.crank_joint,
            self.attachment,
            self.input_pivot,
            self.input_joint,
            self.rocker_joint,
            self.output_pivot,
            self.coupler_point,
        ]
    }
}

/// One solved position of a [`SixBar`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SixBarConfiguration {
    /// The crank angle `phi` (absolute), as given.
    pub crank_angle: f64,
    /// The drive loop at `phi`: its `theta4` is the rocker angle `psi` of
    /// `A0 E`.
    pub drive: Configuration,
    /// The motion loop at `theta2 = psi - delta`.
    pub motion: Configuration,
}

impl SixBarConfiguration {
    /// The rocker angle `psi = arg(E - A0)`.
    pub fn rocker_angle(&self) -> f64 {
        self.drive.theta4
    }

    /// The motion loop's input angle `theta2 = arg(A - A0)`.
    pub fn input_angle(&self) -> f64 {
        self.motion.theta2
    }

    /// The transmission angles `[drive, motion]`, each in `[0, pi/2]`
    /// ([`Configuration::transmission_angle`]).
    pub fn transmission_angles(&self) -> [f64; 2] {
        [
            self.drive.transmission_angle(),
            self.motion.transmission_angle(),
        ]
    }

    /// Whether either loop is at a toggle here.
    pub fn toggle(&self) -> bool {
        self.drive.toggle || self.motion.toggle
    }
}

/// A limit position of the drive: crank and drive coupler collinear, where
/// the input link reverses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitPosition {
    /// The crank angle `phi` there, in `(-pi, pi]`.
    pub crank_angle: f64,
    /// The rocker angle `psi = arg(E - A0)` there.
    pub rocker_angle: f64,
    /// The motion loop's input angle `theta2 = psi - delta` there.
    pub input_angle: f64,
    /// `true` for the extended position (`|E - D0| = c + r`), `false` for
    /// the folded one (`|E - D0| = c - r`).
    pub extended: bool,
}

/// The link lengths of a [`SixBar`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SixBarLengths {
    /// `|A0 - D0|`: the drive loop's ground.
    pub drive_ground: f64,
    /// `r = |D - D0|`: the motor's crank.
    pub crank: f64,
    /// `c = |E - D|`: the drive coupler.
    pub drive_coupler: f64,
    /// `rho = |E - A0|`: the input link's arm to `E` (the drive's rocker).
    pub rocker: f64,
    /// `|A - A0|`: the motion loop's input link.
    pub input: f64,
    /// `|C - A|`: the motion loop's coupler.
    pub coupler: f64,
    /// `|C - C0|`: the motion loop's rocker.
    pub output: f64,
    /// `|C0 - A0|`: the motion loop's ground.
    pub ground: f64,
    /// `|E - A|`: the third side of the ternary input link `A0 A E` (zero
    /// when `E` is `A`); a side of the plate, not a link, so not in the link
    /// ratio.
    pub attachment_side: f64,
}

impl SixBarLengths {
    /// The eight links, in the order of the fields (without the plate side).
    pub fn links(&self) -> [f64; 8] {
        [
            self.drive_ground,
            self.crank,
            self.drive_coupler,
            self.rocker,
            self.input,
            self.coupler,
            self.output,
            self.ground,
        ]
    }
}

/// A Watt II six-bar: a drive four-bar `D0 D E A0` whose output link `A0 E`
/// is rigid with the input link `A0 A` of a motion four-bar `A0 A C C0`
/// (see the [module docs](self) for the chain and the formulas).
///
/// # Example
///
/// ```
/// use burmester::{AssemblyMode, FourBar, Point2, SixBar};
/// // A triple-rocker (its input only swings) ...
/// let motion = FourBar::from_pivots(Point2::new(0.0, 0.0), Point2::new(3.0, 0.0), 2.0, 1.5, 1.0)?;
/// assert!(!motion.input_turns_fully());
/// // ... driven by a crank-rocker whose rocker is its input link (E = A, delta = 0).
/// let drive = FourBar::from_pivots(Point2::new(-1.0, 3.0), Point2::new(0.0, 0.0), 0.4, 3.0, 2.0)?;
/// let six = SixBar::new(drive, motion, 0.0, AssemblyMode::Open, AssemblyMode::Open)?;
/// assert!(six.crank_turns_fully());
/// let [mu_drive, mu_motion] = six.min_transmission_angles().unwrap();
/// assert!(mu_drive > 0.5 && mu_motion > 0.3);
/// for k in 0..36 {
///     let c = six.solve(k as f64 * 10f64.to_radians())?;
///     assert!(!c.toggle());
/// }
/// # Ok::<(), burmester::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SixBar {
    drive: FourBar,
    motion: FourBar,
    drive_mode: AssemblyMode,
    motion_mode: AssemblyMode,
    attachment_angle: f64,
    coupler_point: Vector2<f64>,
    coupler_angle_offset: f64,
}

impl SixBar {
    /// The most crank angles [`crank_angles`](Self::crank_angles) returns.
    pub const MAX_SAMPLES: usize = 1 << 20;

    /// A six-bar from its two loops: `drive` (input pivot `D0`, output
    /// pivot `A0`) and `motion` (input pivot `A0`), the angle `delta =
    /// arg(E - A0) - arg(A - A0)` of the ternary input link, and the mode
    /// each loop closes in. The coupler point is the motion coupler's joint
    /// `A` until [`with_coupler_point`](Self::with_coupler_point) sets it.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a non-finite angle;
    /// [`DriveError::PivotMismatch`] when the drive's output pivot is not
    /// the motion loop's input pivot (within `1e-9` of the linkage's size).
    pub fn new(
        drive: FourBar,
        motion: FourBar,
        attachment_angle: f64,
        drive_mode: AssemblyMode,
        motion_mode: AssemblyMode,
    ) -> Result<Self> {
        let attachment_angle = finite("attachment angle", attachment_angle)?;
        let size = drive
            .lengths()
            .iter()
            .chain(motion.lengths().iter())
            .sum::<f64>();
        let distance = (drive.output_pivot() - motion.input_pivot()).norm();
        let tolerance = 1e-9 * size;
        // NaN fails too.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(distance <= tolerance) {
            return Err(DriveError::PivotMismatch {
                distance,
                tolerance,
            }
            .into());
        }
        Ok(SixBar {
            drive,
            motion,
            drive_mode,
            motion_mode,
            attachment_angle,
            coupler_point: Vector2::zeros(),
            coupler_angle_offset: 0.0,
        })
    }

    /// The same six-bar carrying the coupler point `local` (in the motion
    /// coupler's frame: origin at `A`, x-axis toward `C`), its pose angle
    /// being the coupler angle `theta3` plus `angle_offset` (as
    /// [`SynthesizedFourBar`](crate::SynthesizedFourBar) holds them).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a non-finite value.
    pub fn with_coupler_point(mut self, local: Vector2<f64>, angle_offset: f64) -> Result<Self> {
        finite("coupler point u", local.x)?;
        finite("coupler point v", local.y)?;
        self.coupler_angle_offset = finite("coupler angle offset", angle_offset)?;
        self.coupler_point = local;
        Ok(self)
    }

    /// A six-bar from where its joints are in one position (see
    /// [`SixBarJoints`]): the lengths, the modes of both loops and the angle
    /// of the ternary input link are read from them, the coupler point `P`
    /// is fixed to the coupler `A C`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a non-finite coordinate;
    /// [`crate::DegenerateError::ZeroLengthLink`] for two joints of a link (or two
    /// fixed pivots) that coincide; [`DriveError::ToggleJoints`] when a
    /// loop is at a toggle in the given position (its mode is undefined);
    /// the errors of [`FourBar::from_pivots`] (a linkage too large).
    pub fn from_joints(j: &SixBarJoints) -> Result<Self> {
        const NAMES: [&str; 8] = ["D0", "D", "E", "A0", "A", "C", "C0", "P"];
        for (p, name) in j.to_array().iter().zip(NAMES) {
            if !point_is_finite(p) {
                let value = if p.x.is_finite() { p.y } else { p.x };
                return Err(InvalidInput::NotFinite {
                    name: joint_name(name),
                    value,
                }
                .into());
            }
        }
        let extent = j
            .to_array()
            .iter()
            .map(|p| p.x.abs() + p.y.abs())
            .fold(0.0, f64::max);
        let tiny = tolerance::POINT * extent;
        let links = [
            (j.drive_pivot, j.crank_joint, "drive crank D0-D"),
            (j.crank_joint, j.attachment, "drive coupler D-E"),
            (j.input_pivot, j.attachment, "input link arm A0-E"),
            (j.drive_pivot, j.input_pivot, "drive ground D0-A0"),
            (j.input_pivot, j.input_joint, "input link A0-A"),
            (j.input_joint, j.rocker_joint, "coupler A-C"),
            (j.output_pivot, j.rocker_joint, "rocker C0-C"),
            (j.input_pivot, j.output_pivot, "ground A0-C0"),
        ];
        super::nonzero_links(links, tiny)?;
        // A loop through the fixed pivot `p0`, the joints `a` and `b` and
        // the fixed pivot `p1`, and its assembly mode (None at a toggle).
        let four_bar = |p0: Point2<f64>, a: Point2<f64>, b: Point2<f64>, p1: Point2<f64>| {
            FourBar::from_pivots(p0, p1, (a - p0).norm(), (b - a).norm(), (b - p1).norm())
                .map(|f| (f, AssemblyMode::of_loop(b - a, b - p1)))
        };
        let (drive, drive_mode) =
            four_bar(j.drive_pivot, j.crank_joint, j.attachment, j.input_pivot)?;
        let (motion, motion_mode) =
            four_bar(j.input_pivot, j.input_joint, j.rocker_joint, j.output_pivot)?;
        let drive_mode = drive_mode.ok_or(DriveError::ToggleJoints { which: "drive" })?;
        let motion_mode = motion_mode.ok_or(DriveError::ToggleJoints { which: "motion" })?;
        let (e, a) = (j.attachment - j.input_pivot, j.input_joint - j.input_pivot);
        let delta = e.y.atan2(e.x) - a.y.atan2(a.x);
        let ac = j.rocker_joint - j.input_joint;
        let local = rotate(j.coupler_point - j.input_joint, -ac.y.atan2(ac.x));
        // The drive was placed from `D0` toward `A0`, so its output pivot is
        // `A0` to rounding: `new` cannot refuse it.
        SixBar::new(drive, motion, wrap_angle(delta), drive_mode, motion_mode)?
            .with_coupler_point(local, 0.0)
    }

    /// The drive loop `D0 D E A0` (input pivot `D0`, output pivot `A0`).
    pub fn drive(&self) -> &FourBar {
        &self.drive
    }
    /// The motion loop `A0 A C C0`.
    pub fn motion(&self) -> &FourBar {
        &self.motion
    }
    /// The drive loop's assembly mode.
    pub fn drive_mode(&self) -> AssemblyMode {
        self.drive_mode
    }
    /// The motion loop's assembly mode.
    pub fn motion_mode(&self) -> AssemblyMode {
        self.motion_mode
    }
    /// `delta = arg(E - A0) - arg(A - A0)`, the fixed angle of the ternary
    /// input link, radians.
    pub fn attachment_angle(&self) -> f64 {
        self.attachment_angle
    }
    /// The coupler point in the motion coupler's frame (origin `A`, x-axis
    /// toward `C`).
    pub fn coupler_point(&self) -> Vector2<f64> {
        self.coupler_point
    }
    /// The pose angle minus the coupler angle `theta3`.
    pub fn coupler_angle_offset(&self) -> f64 {
        self.coupler_angle_offset
    }
    /// The motor's fixed pivot `D0`.
    pub fn drive_pivot(&self) -> Point2<f64> {
        self.drive.input_pivot()
    }

    /// The link lengths.
    pub fn lengths(&self) -> SixBarLengths {
        let [g, r, c, rho] = self.drive.lengths();
        let [l1, l2, l3, l4] = self.motion.lengths();
        let (s, co) = self.attachment_angle.sin_cos();
        // |rho e^{i delta} - l2|, the third side of the ternary link.
        let side = Vector2::new(rho * co - l2, rho * s).norm();
        SixBarLengths {
            drive_ground: g,
            crank: r,
            drive_coupler: c,
            rocker: rho,
            input: l2,
            coupler: l3,
            output: l4,
            ground: l1,
            attachment_side: side,
        }
    }

    /// Longest over shortest of the eight links ([`SixBarLengths::links`]).
    pub fn link_ratio(&self) -> f64 {
        let l = self.lengths().links();
        let max = l.iter().copied().fold(0.0, f64::max);
        let min = l.iter().copied().fold(f64::INFINITY, f64::min);
        max / min
    }

    /// The six-bar's size: the total length of its members. The motion
    /// loop's as [`SynthesizedFourBar::size`](crate::SynthesizedFourBar::size)
    /// counts a four-bar's (ground, input link, rocker and the coupler
    /// triangle through the coupler point), the drive's ground `|A0 - D0|`,
    /// crank and coupler, and the arm that carries `E` off the input link:
    /// the distance from `E` to the segment `A0 A` (none when `E` is on the
    /// link, so a drive pinned to the link itself adds only its three links).
    pub fn size(&self) -> f64 {
        let l = self.lengths();
        let cp = self.coupler_point;
        l.drive_ground
            + l.crank
            + l.drive_coupler
            + l.input
            + l.coupler
            + l.output
            + l.ground
            + cp.norm()
            + (cp - Vector2::new(l.coupler, 0.0)).norm()
            + attachment_arm(l.rocker, self.attachment_angle, l.input)
    }

    /// The drive loop's Grashof type (a crank-rocker for a motor drive).
    pub fn drive_grashof(&self) -> Grashof {
        self.drive.grashof()
    }

    /// Solves both loops at crank angle `phi` (radians).
    ///
    /// # Errors
    ///
    /// As [`FourBar::solve`], for the drive loop at `phi` and for the motion
    /// loop at the input angle the drive gives (an error names that loop's
    /// own input angle).
    pub fn solve(&self, phi: f64) -> Result<SixBarConfiguration> {
        let drive = self.drive.solve(phi, self.drive_mode)?;
        let theta2 = drive.theta4 - self.attachment_angle;
        let motion = self.motion.solve(theta2, self.motion_mode)?;
        Ok(SixBarConfiguration {
            crank_angle: phi,
            drive,
            motion,
        })
    }

    /// The joints of a configuration of this six-bar.
    pub fn joints(&self, c: &SixBarConfiguration) -> SixBarJoints {
        let d0 = self.drive.input_pivot();
        let a0 = self.motion.input_pivot();
        let c0 = self.motion.output_pivot();
        let a = a0 + unit(c.motion.theta2) * self.motion.crank();
        SixBarJoints {
            drive_pivot: d0,
            crank_joint: d0 + unit(c.crank_angle) * self.drive.crank(),
            attachment: a0 + unit(c.drive.theta4) * self.drive.rocker(),
            input_pivot: a0,
            input_joint: a,
            rocker_joint: c0 + unit(c.motion.theta4) * self.motion.rocker(),
            output_pivot: c0,
            coupler_point: a + rotate(self.coupler_point, c.motion.theta3),
        }
    }

    /// Solves at `phi` and returns the joints.
    ///
    /// # Errors
    ///
    /// As [`SixBar::solve`].
    pub fn joints_at(&self, phi: f64) -> Result<SixBarJoints> {
        Ok(self.joints(&self.solve(phi)?))
    }

    /// The coupler pose at crank angle `phi`: the coupler point and the
    /// coupler angle plus the offset.
    ///
    /// # Errors
    ///
    /// As [`SixBar::solve`].
    pub fn pose_at(&self, phi: f64) -> Result<Pose> {
        let c = self.solve(phi)?;
        let a = self.motion.input_pivot() + unit(c.motion.theta2) * self.motion.crank();
        Ok(Pose {
            position: a + rotate(self.coupler_point, c.motion.theta3),
            angle: c.motion.theta3 + self.coupler_angle_offset,
        })
    }

    /// The coupler point's path over the crank angles `phis`, lazily.
    ///
    /// # Errors
    ///
    /// Each item as [`SixBar::pose_at`].
    pub fn coupler_path<'a, I>(&'a self, phis: I) -> impl Iterator<Item = Result<Point2<f64>>> + 'a
    where
        I: IntoIterator<Item = f64>,
        I::IntoIter: 'a,
    {
        phis.into_iter()
            .map(move |phi| self.pose_at(phi).map(|p| p.position))
    }

    /// `samples` crank angles evenly spaced over one full turn from
    /// `start`, counter-clockwise (`start` included, `start + 2 pi` not).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::CountOutOfRange`] for fewer than 2 or more than
    /// [`SixBar::MAX_SAMPLES`]; [`InvalidInput::NotFinite`] for a
    /// non-finite start.
    pub fn crank_angles(&self, start: f64, samples: usize) -> Result<Vec<f64>> {
        let start = finite("start angle", start)?;
        let n = crate::error::count_in("samples", samples, 2, Self::MAX_SAMPLES)?;
        Ok((0..n)
            .map(|k| start + TAU * (k as f64 / n as f64))
            .collect())
    }

    /// The drive's two limit positions (crank and coupler collinear, where
    /// the input link reverses), extended first; `None` unless the drive
    /// is a crank-rocker (module docs).
    pub fn limit_positions(&self) -> Option<[LimitPosition; 2]> {
        if self.drive.grashof() != Grashof::CrankRocker {
            return None;
        }
        let [g, r, c, rho] = self.drive.lengths();
        let d0 = self.drive.input_pivot();
        let a0 = self.motion.input_pivot();
        let base = self.drive.ground_angle();
        let m = self.drive_mode.sign();
        let at = |s: f64, extended: bool| {
            let cos_a = ((g * g + s * s - rho * rho) / (2.0 * g * s)).clamp(-1.0, 1.0);
            let u = base + m * cos_a.acos();
            let e = d0 + unit(u) * s;
            let v = e - a0;
            let psi = v.y.atan2(v.x);
            LimitPosition {
                crank_angle: wrap_angle(if extended { u } else { u + PI }),
                rocker_angle: psi,
                input_angle: psi - self.attachment_angle,
                extended,
            }
        };
        Some([at(c + r, true), at(c - r, false)])
    }

    /// The swing of the motion loop's input `theta2` between the limit
    /// positions, counter-clockwise from `start` (less than `pi` wide);
    /// `None` unless the drive is a crank-rocker.
    pub fn swing(&self) -> Option<AngleInterval> {
        let [e, f] = self.limit_positions()?;
        let d = wrap_angle(f.input_angle - e.input_angle);
        Some(if d >= 0.0 {
            AngleInterval {
                start: e.input_angle,
                end: e.input_angle + d,
            }
        } else {
            AngleInterval {
                start: f.input_angle,
                end: f.input_angle - d,
            }
        })
    }

    /// The crank's turn from the extended to the folded limit position,
    /// counter-clockwise, in `[0, 2 pi)`; `None` unless the drive is a
    /// crank-rocker.
    pub fn stroke_angle(&self) -> Option<f64> {
        let [e, f] = self.limit_positions()?;
        Some((f.crank_angle - e.crank_angle).rem_euclid(TAU))
    }

    /// The time ratio of the two strokes at a constant crank speed, the
    /// slower over the faster (at least 1; 1 when the crank turns `pi`
    /// each way); `None` unless the drive is a crank-rocker.
    pub fn time_ratio(&self) -> Option<f64> {
        let beta = self.stroke_angle()?;
        let (long, short) = (beta.max(TAU - beta), beta.min(TAU - beta));
        Some(long / short)
    }

    /// Whether the motor's crank turns fully with neither loop toggling:
    /// the drive is a crank-rocker and the motion loop's input stays
    /// strictly inside its input range over the swing.
    pub fn crank_turns_fully(&self) -> bool {
        self.swing().is_some_and(|s| swing_inside(&self.motion, s))
    }

    /// The smallest transmission angles over a full crank turn, `[drive,
    /// motion]`, radians in `[0, pi/2]`, exact (module docs); `None` unless
    /// the crank turns fully ([`crank_turns_fully`](Self::crank_turns_fully)).
    pub fn min_transmission_angles(&self) -> Option<[f64; 2]> {
        let swing = self.swing()?;
        if !swing_inside(&self.motion, swing) {
            return None;
        }
        let [g, r, c, rho] = self.drive.lengths();
        let drive = acos1(drive_worst_cos(g, r, c, rho).min(1.0));
        let motion = acos1(arc_worst_cos(&self.motion, swing.start, swing.span()).min(1.0));
        Some([drive, motion])
    }

    /// The crank angles at which the drive's rocker `A0 E` is at angle
    /// `psi` in the drive's mode: none, one (at a limit position) or two
    /// (one per stroke), in `(-pi, pi]`.
    pub fn crank_angles_for_rocker(&self, psi: f64) -> Vec<f64> {
        let [_, r, c, rho] = self.drive.lengths();
        let d0 = self.drive.input_pivot();
        let a0 = self.motion.input_pivot();
        let e = a0 + unit(psi) * rho;
        let w = e - d0;
        let s = w.norm();
        // NaN fails too.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(s > 0.0) {
            return Vec::new();
        }
        let x = (r * r + s * s - c * c) / (2.0 * r * s);
        // The rounding of `x` grows with `(r^2 + s^2 + c^2) / (r s)`: at a
        // limit position of a drive with a long coupler it is many eps.
        let slack =
            2.0 * tolerance::ROUNDING_EPS * f64::EPSILON * (r * r + s * s + c * c) / (r * s);
        // NaN fails too.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(x.abs() <= 1.0 + slack) {
            return Vec::new();
        }
        let beta = x.clamp(-1.0, 1.0).acos();
        let base = w.y.atan2(w.x);
        let mut out: Vec<f64> = Vec::with_capacity(2);
        for sign in [1.0, -1.0] {
            let phi = wrap_angle(base + sign * beta);
            let dpt = d0 + unit(phi) * r;
            let mode = AssemblyMode::of_loop(e - dpt, e - a0);
            let ok = mode.is_none_or(|m| m == self.drive_mode);
            if ok && !out.iter().any(|&q| wrap_angle(q - phi).abs() < 1e-12) {
                out.push(phi);
            }
        }
        out.sort_by(f64::total_cmp);
        out
    }

    /// The crank angles at which the motion loop's input is `theta2`
    /// ([`crank_angles_for_rocker`](Self::crank_angles_for_rocker) at
    /// `theta2 + delta`).
    pub fn crank_angles_for_input(&self, theta2: f64) -> Vec<f64> {
        self.crank_angles_for_rocker(theta2 + self.attachment_angle)
    }

    /// The crank angles, in `(-pi, pi]` and ascending, at which a loop
    /// reaches a toggle (a dead position, where the six-bar locks): the
    /// drive's own, where `|D - A0|` reaches `c + rho` or `|c - rho|`, and
    /// those where the motion loop's input reaches one of its dead
    /// positions. Empty when the crank turns fully.
    pub fn dead_positions(&self) -> Vec<f64> {
        let [g, r, c, rho] = self.drive.lengths();
        let base = self.drive.ground_angle();
        let mut out = Vec::new();
        for t in [c + rho, (c - rho).abs()] {
            let x = (g * g + r * r - t * t) / (2.0 * g * r);
            if x.abs() <= 1.0 {
                let a = x.acos();
                out.push(wrap_angle(base + a));
                out.push(wrap_angle(base - a));
            }
        }
        for theta in self.motion.input_range().dead_positions() {
            out.extend(self.crank_angles_for_input(theta));
        }
        out.sort_by(f64::total_cmp);
        out.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
        out
    }
}

/// The distance from `E = rho e^{i delta}` to the segment from `0` to `l2`
/// (the input link `A0 A` in its own frame): the arm that carries the
/// attachment off the link.
pub(crate) fn attachment_arm(rho: f64, delta: f64, l2: f64) -> f64 {
    let (s, c) = delta.sin_cos();
    let (x, y) = (rho * c, rho * s);
    let t = x.clamp(0.0, l2);
    (x - t).hypot(y)
}

/// A joint's name in messages.
fn joint_name(name: &str) -> &'static str {
    match name {
        "D0" => "joint D0 (drive pivot)",
        "D" => "joint D (crank joint)",
        "E" => "joint E (attachment)",
        "A0" => "joint A0 (input pivot)",
        "A" => "joint A (input joint)",
        "C" => "joint C (rocker joint)",
        "C0" => "joint C0 (output pivot)",
        _ => "joint P (coupler point)",
    }
}

/// The drive loop's largest `|cos gamma|` over a full crank turn, for
/// ground `g`, crank `r`, coupler `c` and rocker `rho` (module docs): at
/// `|D - A0| = g + r` or `|g - r|`. The one formula of the six-bar and the
/// drive map.
#[inline(always)]
pub(crate) fn drive_worst_cos(g: f64, r: f64, c: f64, rho: f64) -> f64 {
    let k = c * c + rho * rho;
    let far = g + r;
    let near = g - r;
    fmax((k - far * far).abs(), (k - near * near).abs()) / (2.0 * c * rho)
}

/// The motion loop's largest `|cos mu|` over the arc of its input from
/// `start`, `span >= 0` counter-clockwise: at the arc's ends, and at the
/// ground direction `theta1` or its opposite where the arc passes them
/// ([`LinkageFigures`](crate::LinkageFigures)).
pub(crate) fn arc_worst_cos(fb: &FourBar, start: f64, span: f64) -> f64 {
    let l = fb.lengths();
    let m = l.iter().copied().fold(0.0, f64::max);
    let [l1, l2, l3, l4] = l.map(|x| x / m);
    let k = l3 * l3 + l4 * l4 - l1 * l1 - l2 * l2;
    let k1 = 2.0 * l1 * l2;
    let inv = 1.0 / (2.0 * l3 * l4);
    let at = |cc: f64| ((k + k1 * cc) * inv).abs();
    let t1 = fb.ground_angle();
    let arc = AngleInterval {
        start,
        end: start + span,
    };
    let mut worst = fmax(at((start - t1).cos()), at((start + span - t1).cos()));
    if arc.contains(t1) {
        worst = fmax(worst, at(1.0));
    }
    if arc.contains(t1 + PI) {
        worst = fmax(worst, at(-1.0));
    }
    fmin(worst, f64::INFINITY)
}

/// Whether the arc `swing` of a four-bar's input lies strictly inside one
/// arc of its input range (no dead position on it or at its ends).
pub(crate) fn swing_inside(fb: &FourBar, swing: AngleInterval) -> bool {
    let inside = |a: &AngleInterval| {
        let from = (swing.start - a.start).rem_euclid(TAU);
        from > 0.0 && from + swing.span() < a.span()
    };
    match fb.input_range() {
        InputRange::Full => true,
        InputRange::Arc(a) => inside(&a),
        InputRange::TwoArcs(a, b) => inside(&a) || inside(&b),
    }
}

/// Whether `v` lies strictly between `from` and `to` turning the short way
/// (for the unit tests).
#[cfg(test)]
fn between(from: Vector2<f64>, v: Vector2<f64>, to: Vector2<f64>) -> bool {
    use crate::geom::cross;
    let s = cross(from, to).signum();
    cross(from, v) * s > 0.0 && cross(v, to) * s > 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A triple-rocker driven at its input joint by a crank-rocker.
    fn example() -> SixBar {
        let motion =
            FourBar::from_pivots(Point2::new(0.0, 0.0), Point2::new(3.0, 0.0), 2.0, 1.5, 1.0)
                .unwrap();
        let drive =
            FourBar::from_pivots(Point2::new(-1.0, 3.0), Point2::new(0.0, 0.0), 0.4, 3.0, 2.0)
                .unwrap();
        SixBar::new(drive, motion, 0.0, AssemblyMode::Open, AssemblyMode::Open).unwrap()
    }

    #[test]
    fn limit_positions_are_the_extremes_of_a_dense_turn() {
        let six = example();
        assert_eq!(six.drive_grashof(), Grashof::CrankRocker);
        let [e, f] = six.limit_positions().unwrap();
        for l in [e, f] {
            let c = six.solve(l.crank_angle).unwrap();
            assert!(
                wrap_angle(c.rocker_angle() - l.rocker_angle).abs() < 1e-9,
                "{l:?}"
            );
        }
        let n = 200_000;
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        let swing = six.swing().unwrap();
        for k in 0..n {
            let c = six.solve(TAU * k as f64 / n as f64).unwrap();
            let t = swing.start + wrap_angle(c.input_angle() - swing.start);
            lo = lo.min(t);
            hi = hi.max(t);
        }
        assert!((lo - swing.start).abs() < 1e-8, "{lo} {swing:?}");
        assert!((hi - swing.end).abs() < 1e-8, "{hi} {swing:?}");
    }

    #[test]
    fn from_joints_round_trips() {
        let six = example()
            .with_coupler_point(Vector2::new(0.3, 0.7), 0.0)
            .unwrap();
        for phi in [-2.0, 0.3, 1.7] {
            let j = six.joints_at(phi).unwrap();
            let again = SixBar::from_joints(&j).unwrap();
            assert_eq!(again.drive_mode(), six.drive_mode());
            assert_eq!(again.motion_mode(), six.motion_mode());
            for psi in [-1.0, 0.5, 2.5] {
                let (p, q) = (six.pose_at(psi).unwrap(), again.pose_at(psi).unwrap());
                assert!((p.position - q.position).norm() < 1e-12, "{phi} {psi}");
                assert!(wrap_angle(p.angle - q.angle).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn crank_angles_for_an_input_reach_it() {
        let six = example();
        let s = six.swing().unwrap();
        let theta = s.start + 0.3 * s.span();
        let phis = six.crank_angles_for_input(theta);
        assert_eq!(phis.len(), 2);
        for phi in phis {
            let c = six.solve(phi).unwrap();
            assert!(wrap_angle(c.input_angle() - theta).abs() < 1e-12);
        }
        assert!(six.crank_angles_for_input(s.end + 0.1).is_empty());
        assert!(six.dead_positions().is_empty());
        assert!(between(
            unit(s.start),
            unit(s.start + 0.5 * s.span()),
            unit(s.end)
        ));
    }
}
