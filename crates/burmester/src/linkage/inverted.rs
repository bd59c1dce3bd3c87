//! The inverted slider-crank (RRPR): a crank whose coupler carries a
//! straight slot that slides through a block pivoted on the ground (the
//! slotted coupler of a quick-return mechanism, the rod of an oscillating
//! cylinder, a tilting lid guided through a swivelling sleeve). Position
//! analysis in closed form with both assembly modes named, the crank's
//! input range and dead positions, the position along the slot and its
//! stroke, the swing of the slotted link and the transmission angle.
//!
//! # Conventions
//!
//! The crank `A0 A` (length `r`) turns about the fixed pivot `A0`; the
//! coupler is pinned to the crank at `A` and carries a straight slot that
//! slides through a block pivoted on the ground at the **swivel** `S`
//! (`g = |S - A0|` the ground). In the coupler frame (origin `A`, x-axis
//! the slot's direction `u3 = e^{i theta3}`, y-axis `n3 = i u3`) the slot
//! is the line `y = e`: `e` is the slot's signed **offset** from the crank
//! pin (zero when the slot's line passes through `A`, the oscillating
//! cylinder). The **slot position** `t` is the swivel's x in the coupler
//! frame, `t = <S - A, u3>`: the distance from the crank pin (its foot on
//! the slot) to the ground pivot along the slot. Angles are absolute
//! (from +x, counter-clockwise, radians).
//!
//! # The closed form
//!
//! With `w = S - A` (`A = A0 + r e^{i theta2}`) and `rho = |w|`, the swivel
//! in the coupler frame is `(t, e)`, so `w = (t + i e) u3`:
//!
//! ```text
//! t = sigma sqrt(rho^2 - e^2),    u3 = w (t - i e) / rho^2,    theta3 = arg w - atan2(e, t)
//! ```
//!
//! `sigma = sign t` says whether the swivel is ahead of (`+1`) or behind
//! (`-1`) the crank pin along the slot. `rho < |e|` is a crank angle
//! where the loop does not close; `rho = |e|` (`t = 0`) is a toggle,
//! where the modes meet.
//!
//! This is the textbook solution (Norton, *Design of Machinery*, §4.7,
//! the inverted slider-crank, eqs. 4.18–4.20): with Norton's crank `a`,
//! ground `d` along +x, rocker `c` at the angle `gamma` to the slider
//! axis (`theta3 = theta4 + gamma`), `P sin theta4 + Q cos theta4 + R = 0`,
//!
//! ```text
//! P = a sin theta2 sin gamma + (a cos theta2 - d) cos gamma,
//! Q = -a sin theta2 cos gamma + (a cos theta2 - d) sin gamma,   R = -c sin gamma,
//! theta4 = 2 atan((-2P +- sqrt(4P^2 - 4(R - Q)(R + Q))) / (2 (R - Q))),
//! b = (a sin theta2 - c sin theta4) / sin theta3
//! ```
//!
//! the tangent half-angle quadratic, whose two roots are the two modes;
//! the same chain (crank, block, slotted link, ground), so Norton's
//! `theta3` is this `theta3` for `e = c sin gamma`, and his slider
//! length `b` is `-t - c cos gamma` (checked in the tests, both modes).
//!
//! # The assembly modes' names
//!
//! The slot is the limit of a revolute joint of the coupler at infinity
//! along the slot's normal, `B = A + (x0, e + R)` in the coupler frame,
//! `R -> +inf`, with the swivel `S` its ground pivot (where
//! [`SliderDyad::normal`](crate::SliderDyad::normal) puts a center at
//! infinity, the inverted task's). The four-bar's mode is the sign of
//! `cross(B - A, B - S) = R t + e (t - x0)`, so in that limit
//!
//! ```text
//! AssemblyMode::Open     <=>  sigma = +1   (the swivel ahead of the crank pin along the slot)
//! AssemblyMode::Crossed  <=>  sigma = -1   (behind it)
//! ```
//!
//! checked against a four-bar with its coupler pin `1e6` lengths away
//! (`tests/rust/inverted.rs`). Turning the slot's direction round swaps
//! the names (and `e`'s sign).
//!
//! # Dead positions, stroke, swing, transmission
//!
//! - **Crank input.** The loop closes where `rho >= |e|`, that is
//!   `cos(theta2 - psi0) <= (g^2 + r^2 - e^2) / (2 g r)` (`psi0` the
//!   angle of `S - A0`): the crank turns fully exactly when
//!   `|g - r| >= |e|` ([`InvertedSliderCrank::input_range`]); otherwise it
//!   rocks in one arc, away from the swivel, between the dead positions
//!   where the crank pin is `|e|` from the swivel (`t = 0`).
//! - **Stroke along the slot.** `|t| = sqrt(rho^2 - e^2)` grows with
//!   `rho`, which is largest (`g + r`) with the crank pointing away from
//!   the swivel and smallest (`|g - r|`, or `|e|` at a dead position)
//!   pointing at it: the stroke is `sqrt((g + r)^2 - e^2) -
//!   sqrt(max((g - r)^2, e^2) - e^2)` in either mode
//!   ([`InvertedSliderCrank::slot_limits`]).
//! - **Swing of the slotted link.** The coupler's angular velocity is zero
//!   where its instant center (on the crank's line and on the slot's
//!   normal through `S`) is at infinity: the crank perpendicular to the
//!   slot, `A = A0 +- r n3`, so `g sin(psi0 - theta3) = e +- r`. With
//!   `g > r + |e|` the slotted link swings between two such positions per
//!   mode (the quick-return's working and return strokes); with
//!   `r > g + |e|` it turns fully (Whitworth) and there is no swing
//!   ([`InvertedSliderCrank::swing`]).
//! - **Transmission angle.** The angle between the force the block and the
//!   slot carry (normal to the slot, friction neglected) and the line from
//!   the swivel to the crank pin, in `[0, pi/2]`: `cos mu = |e| / rho`,
//!   `sin mu = |t| / rho` (`pi/2` ideal, always so for `e = 0`; `0` at a
//!   dead position of the crank). It is Norton's angle between the slider
//!   axis and the line `O4 A` turned by a quarter (his `gamma = 90 deg`
//!   layout: `sin mu = |b| / |O4 A|`), the inverted slider-crank's
//!   counterpart of the slider-crank's `cos mu = |h| / l`.

use core::f64::consts::{PI, TAU};

use nalgebra::{Point2, Vector2};

use crate::error::{AssemblyError, InvalidInput, Result, finite, positive};
use crate::geom::{cross, length, perp, rotate, unit, wrap_angle};
use crate::linkage::{AngleInterval, AssemblyMode, FourBar, InputRange};
use crate::tolerance;

impl AssemblyMode {
    /// The mode of an inverted slider-crank's loop from the vector
    /// `w = S - A` (crank pin to swivel) and the slot's direction `u3`
    /// where it is: [`Open`](AssemblyMode::Open) where `t = <w, u3>` is
    /// positive (the swivel ahead of the crank pin along the slot),
    /// [`Crossed`](AssemblyMode::Crossed) where negative (module docs of
    /// [`InvertedSliderCrank`]), `None` (a toggle) where `t^2 = rho^2 -
    /// e^2` is within the slider's toggle band
    /// ([`tolerance::slider_tolerance`]), `reach` the size of the vectors
    /// `w` was formed from (ground plus crank).
    ///
    /// ```
    /// use burmester::{AssemblyMode, Vector2};
    /// let u = Vector2::x();
    /// assert_eq!(AssemblyMode::of_inverted(Vector2::new(3.0, 1.0), u, 4.0), Some(AssemblyMode::Open));
    /// assert_eq!(AssemblyMode::of_inverted(Vector2::new(0.0, 1.0), u, 4.0), None);
    /// ```
    pub fn of_inverted(swivel: Vector2<f64>, slot: Vector2<f64>, reach: f64) -> Option<Self> {
        let m = length(swivel).max(reach);
        let n = length(slot);
        if !(m > 0.0 && m.is_finite() && n > 0.0 && n.is_finite()) {
            return None;
        }
        let (w, reach, u) = (swivel / m, reach / m, slot / n);
        let (t, e) = (w.dot(&u), cross(u, w));
        let tol = tolerance::slider_tolerance(w.norm(), e, reach);
        if t * t > tol {
            AssemblyMode::from_sign(t)
        } else {
            None
        }
    }
}

/// The sign `sigma = sign t` of a mode: `+1` for
/// [`AssemblyMode::Open`], `-1` for [`AssemblyMode::Crossed`].
#[inline]
fn sigma(mode: AssemblyMode) -> f64 {
    mode.sign()
}

/// One solved position of an inverted slider-crank.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InvertedConfiguration {
    /// The crank angle, as given.
    pub theta2: f64,
    /// The coupler angle: the slot's direction `u3`, in `(-pi, pi]`.
    pub theta3: f64,
    /// The slot position `t = <S - A, u3>`: the swivel's signed distance
    /// along the slot from the foot of the perpendicular from the crank
    /// pin (positive in [`AssemblyMode::Open`]).
    pub slot: f64,
    /// The assembly mode that was asked for.
    pub mode: AssemblyMode,
    /// True at a toggle (a dead position of the crank input): the crank
    /// pin is `|e|` from the swivel within rounding, and both modes give
    /// this answer.
    pub toggle: bool,
    /// The transmission angle, in `[0, pi/2]`: `cos mu = |e| / |S - A|`
    /// (module docs).
    pub transmission_angle: f64,
}

/// Where the joints of an inverted slider-crank are in one configuration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InvertedJoints {
    /// The crank pivot `A0`, fixed.
    pub crank_pivot: Point2<f64>,
    /// The crank pin `A`, joining crank and coupler.
    pub crank_joint: Point2<f64>,
    /// The swivel `S`, the block's ground pivot, fixed.
    pub swivel: Point2<f64>,
    /// The foot of the perpendicular from the crank pin to the slot's line:
    /// `A + e n3`, the slot position's origin.
    pub slot_foot: Point2<f64>,
}

impl InvertedJoints {
    /// The slot's unit direction `u3` here (from the foot toward the
    /// swivel in [`AssemblyMode::Open`]).
    pub fn slot_direction(&self) -> Vector2<f64> {
        let w = self.swivel - self.crank_joint;
        let f = self.slot_foot - self.crank_joint;
        let e = length(f);
        if e == 0.0 {
            return w.normalize();
        }
        // f = e n3 with n3 = i u3: u3 = -i f / e, signed by the side.
        let n3 = f / e;
        Vector2::new(n3.y, -n3.x)
    }
}

/// A limit of the slot position or of the slotted link's angle, with the
/// crank angle where it is reached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InvertedLimit {
    /// The crank angle there, radians.
    pub theta2: f64,
    /// The slot position there ([`InvertedConfiguration::slot`]).
    pub slot: f64,
    /// The coupler angle there ([`InvertedConfiguration::theta3`]; for a
    /// swing, unwrapped so that the two ends differ by the swing).
    pub theta3: f64,
}

/// An inverted slider-crank (RRPR): a crank about a fixed pivot and a
/// coupler whose slot slides through a block pivoted on the ground at the
/// swivel (module docs).
///
/// # Example
///
/// ```
/// use burmester::{AssemblyMode, InvertedSliderCrank, Point2};
/// // A shaper's quick return: crank 100 mm, swivel 300 mm below the crank
/// // pivot, the slot through the crank pin.
/// let q = InvertedSliderCrank::new(Point2::origin(), 100.0, Point2::new(0.0, -300.0), 0.0)?;
/// let c = q.solve(0.0, AssemblyMode::Crossed)?;
/// // Swivel (0, -300), pin (100, 0): the slot runs from the pin away from the swivel.
/// assert!((c.slot + (100f64.powi(2) + 300f64.powi(2)).sqrt()).abs() < 1e-9);
/// assert!((q.stroke() - 200.0).abs() < 1e-9);
/// // It swings by 2 asin(100 / 300) about the swivel.
/// let [lo, hi] = q.swing(AssemblyMode::Crossed).unwrap();
/// assert!(((hi.theta3 - lo.theta3) - 2.0 * (1.0f64 / 3.0).asin()).abs() < 1e-12);
/// # Ok::<(), burmester::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InvertedSliderCrank {
    pivot: Point2<f64>,
    crank: f64,
    swivel: Point2<f64>,
    offset: f64,
    /// `|S - A0|`.
    ground: f64,
    /// `max(r, g, |e|)`: the arithmetic runs at unit size.
    scale: f64,
}

crate::linkage::crank_coupler_methods!(
    InvertedSliderCrank,
    InvertedConfiguration,
    InvertedJoints,
    "along the slot"
);

impl InvertedSliderCrank {
    /// The largest extent: the crank pivot's and the swivel's distances
    /// from the origin (as `|x| + |y|`) plus the crank and the offset
    /// ([`FourBar::MAX_EXTENT`]).
    pub const MAX_EXTENT: f64 = FourBar::MAX_EXTENT;

    /// An inverted slider-crank with its crank pivot at `pivot`, crank
    /// length `crank`, the block's ground pivot at `swivel` and the slot's
    /// signed `offset` from the crank pin (the line `y = offset` of the
    /// coupler frame: origin the crank pin, x along the slot; zero when the
    /// slot's line passes through the pin).
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for a crank that is not positive and finite, a
    /// point or offset that is not finite, a linkage larger than
    /// [`InvertedSliderCrank::MAX_EXTENT`] or lengths whose ratio
    /// overflows; [`AssemblyError::SwivelOutOfReach`] when the offset is
    /// larger than ground plus crank (no crank angle closes the loop).
    pub fn new(pivot: Point2<f64>, crank: f64, swivel: Point2<f64>, offset: f64) -> Result<Self> {
        let crank = positive("crank length", crank)?;
        finite("crank pivot x", pivot.x)?;
        finite("crank pivot y", pivot.y)?;
        finite("swivel x", swivel.x)?;
        finite("swivel y", swivel.y)?;
        let offset = finite("slot offset", offset)?;
        let extent =
            pivot.x.abs() + pivot.y.abs() + swivel.x.abs() + swivel.y.abs() + crank + offset.abs();
        if extent.is_nan() || extent > Self::MAX_EXTENT {
            return Err(InvalidInput::TooLarge {
                name: "inverted slider-crank size (the pivots' distances plus crank and offset)",
                value: extent,
                limit: Self::MAX_EXTENT,
                hint: "rescale the linkage or move it nearer the origin",
            }
            .into());
        }
        let ground = length(swivel - pivot);
        let scale = crank.max(ground).max(offset.abs());
        if !(scale / crank).is_finite() {
            return Err(InvalidInput::TooLarge {
                name: "ratio of the ground or offset to the crank",
                value: scale / crank,
                limit: f64::MAX,
                hint: "pass lengths of comparable sizes",
            }
            .into());
        }
        let reach = ground + crank;
        if offset.abs() > reach * (1.0 + tolerance::ROUNDING_EPS * f64::EPSILON) {
            return Err(AssemblyError::SwivelOutOfReach {
                offset: offset.abs(),
                reach,
            }
            .into());
        }
        Ok(InvertedSliderCrank {
            pivot,
            crank,
            swivel,
            offset,
            ground,
            scale,
        })
    }

    /// The swivel `S`: the block's ground pivot.
    pub fn swivel(&self) -> Point2<f64> {
        self.swivel
    }
    /// The slot's signed offset `e` from the crank pin (module docs).
    pub fn offset(&self) -> f64 {
        self.offset
    }
    /// The ground `g = |S - A0|`.
    pub fn ground(&self) -> f64 {
        self.ground
    }

    /// Closes the loop at `theta2` in units of `scale`: `w = S - A`, `t^2`
    /// and its band.
    #[inline]
    fn close(&self, theta2: f64) -> Result<(Vector2<f64>, f64, f64)> {
        super::bounded_theta2(theta2)?;
        let k = 1.0 / self.scale;
        let (r, e) = (self.crank * k, self.offset * k);
        let w = (self.swivel - self.pivot) * k - unit(theta2) * r;
        let rho = w.norm();
        let heron = (rho - e.abs()) * (rho + e.abs());
        let tol = tolerance::slider_tolerance(rho, e, r + self.ground * k);
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(heron >= -tol) {
            return Err(AssemblyError::SlotOutOfReach {
                theta2,
                distance: rho * self.scale,
                offset: self.offset.abs(),
            }
            .into());
        }
        Ok((w, heron, tol))
    }

    /// Solves the loop at crank angle `theta2` (radians) in `mode`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a NaN or infinite angle,
    /// [`InvalidInput::TooLarge`] beyond [`InvertedSliderCrank::MAX_ANGLE`];
    /// [`AssemblyError::SlotOutOfReach`] where the loop does not close
    /// (the crank pin nearer the swivel than the slot's offset).
    pub fn solve(&self, theta2: f64, mode: AssemblyMode) -> Result<InvertedConfiguration> {
        let (w, heron, tol) = self.close(theta2)?;
        let e = self.offset / self.scale;
        let t = sigma(mode) * heron.max(0.0).sqrt();
        // theta3 = arg w - atan2(e, t).
        let theta3 = wrap_angle(w.y.atan2(w.x) - e.atan2(t));
        Ok(InvertedConfiguration {
            theta2,
            theta3,
            slot: t * self.scale,
            mode,
            toggle: heron <= tol,
            transmission_angle: t.abs().atan2(e.abs()),
        })
    }

    /// The joints of a configuration of this linkage.
    pub fn joints(&self, c: &InvertedConfiguration) -> InvertedJoints {
        let a = self.pivot + unit(c.theta2) * self.crank;
        InvertedJoints {
            crank_pivot: self.pivot,
            crank_joint: a,
            swivel: self.swivel,
            slot_foot: a + perp(unit(c.theta3)) * self.offset,
        }
    }

    /// The angle `psi0` of the ground line, from the crank pivot to the
    /// swivel (`0` when they coincide).
    pub fn ground_angle(&self) -> f64 {
        let g = self.swivel - self.pivot;
        g.y.atan2(g.x)
    }

    /// Whether the crank turns fully: `|g - r| >= |e|`, within
    /// [`tolerance::ROUNDING_EPS`].
    pub fn turns_fully(&self) -> bool {
        let (r, g, e) = (self.crank, self.ground, self.offset.abs());
        let slack = tolerance::ROUNDING_EPS * f64::EPSILON * (r + g + e);
        (g - r).abs() + slack >= e
    }

    /// Where the crank can be: all the way round exactly when
    /// [`turns_fully`](Self::turns_fully), else one arc pointing away from
    /// the swivel, `cos(theta2 - psi0) <= (g^2 + r^2 - e^2) / (2 g r)`,
    /// bounded by the dead positions where the crank pin is `|e|` from the
    /// swivel (module docs).
    pub fn input_range(&self) -> InputRange {
        if self.turns_fully() {
            return InputRange::Full;
        }
        let (r, g, e) = (
            self.crank / self.scale,
            self.ground / self.scale,
            self.offset / self.scale,
        );
        let c = ((g * g + r * r - e * e) / (2.0 * g * r)).clamp(-1.0, 1.0);
        let a = c.acos();
        let psi0 = self.ground_angle();
        InputRange::Arc(AngleInterval {
            start: psi0 + a,
            end: psi0 + TAU - a,
        })
    }

    /// The dead positions of the crank input (empty when it turns fully).
    pub fn dead_positions(&self) -> Vec<f64> {
        self.input_range().dead_positions()
    }

    /// The slot position's limits in `mode`: `[lowest, highest]` slot
    /// position, each with its crank angle and coupler angle. `|t|` is
    /// largest with the crank pointing away from the swivel and smallest
    /// pointing at it, or at a dead position (`t = 0`) for a crank that
    /// does not turn fully.
    pub fn slot_limits(&self, mode: AssemblyMode) -> [InvertedLimit; 2] {
        let psi0 = self.ground_angle();
        let near = if self.turns_fully() {
            psi0
        } else {
            self.dead_positions()[0]
        };
        let at = |theta2: f64| {
            let c = self.solve(theta2, mode).ok();
            InvertedLimit {
                theta2,
                slot: c.map_or(f64::NAN, |c| c.slot),
                theta3: c.map_or(f64::NAN, |c| c.theta3),
            }
        };
        let (far, near) = (at(wrap_angle(psi0 + PI)), at(near));
        if far.slot <= near.slot {
            [far, near]
        } else {
            [near, far]
        }
    }

    /// The stroke along the slot: `sqrt((g + r)^2 - e^2) - sqrt(max((g -
    /// r)^2, e^2) - e^2)`, the same in either mode (module docs).
    pub fn stroke(&self) -> f64 {
        let (r, g, e) = (self.crank, self.ground, self.offset.abs());
        let far = ((g + r - e) * (g + r + e)).max(0.0).sqrt();
        let lo = (g - r).abs().max(e);
        let near = ((lo - e) * (lo + e)).max(0.0).sqrt();
        far - near
    }

    /// The positions in `mode` where the slotted link's angle is
    /// stationary: the crank perpendicular to the slot (`A = A0 +- r n3`,
    /// `g sin(psi0 - theta3) = e +- r`), each with its crank angle, slot
    /// position and coupler angle (module docs). Empty where the slotted
    /// link turns fully or the ground is zero.
    pub fn stationary_positions(&self, mode: AssemblyMode) -> Vec<InvertedLimit> {
        let (r, g, e) = (self.crank, self.ground, self.offset);
        let mut out = Vec::with_capacity(4);
        if g == 0.0 {
            return out;
        }
        let psi0 = self.ground_angle();
        for side in [1.0, -1.0] {
            let q = (e + side * r) / g;
            if !(-1.0..=1.0).contains(&q) {
                continue;
            }
            for d in [q.asin(), PI - q.asin()] {
                let theta3 = psi0 - d;
                let crank = perp(unit(theta3)) * side;
                let theta2 = crank.y.atan2(crank.x);
                if let Ok(c) = self.solve(theta2, mode)
                    && wrap_angle(c.theta3 - theta3).abs() < 1e-6
                {
                    out.push(InvertedLimit {
                        theta2,
                        slot: c.slot,
                        theta3: c.theta3,
                    });
                }
            }
        }
        out
    }

    /// The swing of the slotted link (the coupler's angle) in `mode`: its
    /// two ends, `[lowest, highest]` `theta3` (unwrapped so that their
    /// difference is the swing), where the crank is perpendicular to the
    /// slot ([`stationary_positions`](Self::stationary_positions)) or, for
    /// a crank that does not turn fully, possibly at a dead position.
    /// `None` where the slotted link turns fully (`r > g + |e|`, the
    /// Whitworth quick return) or the ground is zero.
    pub fn swing(&self, mode: AssemblyMode) -> Option<[InvertedLimit; 2]> {
        let mut cands = self.stationary_positions(mode);
        if cands.is_empty() {
            return None;
        }
        for t in self.dead_positions() {
            if let Ok(c) = self.solve(t, mode) {
                cands.push(InvertedLimit {
                    theta2: t,
                    slot: c.slot,
                    theta3: c.theta3,
                });
            }
        }
        // Unwrapped about the coupler angle with the crank pointing away
        // from the swivel (always closed, inside the swing).
        let psi0 = self.ground_angle();
        let reference = self.solve(wrap_angle(psi0 + PI), mode).ok()?.theta3;
        let unwrap = |c: &InvertedLimit| InvertedLimit {
            theta3: reference + wrap_angle(c.theta3 - reference),
            ..*c
        };
        let first = unwrap(&cands[0]);
        Some(
            cands
                .iter()
                .map(unwrap)
                .fold([first, first], |[lo, hi], p| {
                    [
                        if p.theta3 < lo.theta3 { p } else { lo },
                        if p.theta3 > hi.theta3 { p } else { hi },
                    ]
                }),
        )
    }

    /// The time ratio of a crank turning at constant speed through the
    /// slotted link's two strokes (the longer over the shorter crank angle
    /// between the swing's ends; the quick-return ratio), `None` where
    /// there is no swing or the crank does not turn fully.
    pub fn time_ratio(&self, mode: AssemblyMode) -> Option<f64> {
        if !self.turns_fully() {
            return None;
        }
        let [lo, hi] = self.swing(mode)?;
        let a = (hi.theta2 - lo.theta2).rem_euclid(TAU);
        let b = TAU - a;
        Some(a.max(b) / a.min(b))
    }
}
