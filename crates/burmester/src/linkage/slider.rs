//! The slider-crank (RRRP): position analysis in closed form with both
//! assembly modes named, the toggle band, the crank's input range and dead
//! positions, the slider's limit positions and stroke, the transmission
//! angle and coupler-point paths.
//!
//! # Conventions
//!
//! The crank `A0 A` (length `r`) turns about the fixed pivot `A0`; the
//! coupler `A B` (length `l`) joins the crank tip `A` to the slider pin `B`,
//! which runs on a straight guide fixed to the ground: the line through a
//! point `P` in the unit direction `u`, with normal `n = i·u` (`u` turned a
//! quarter turn counter-clockwise). `F` is the foot of the perpendicular
//! from `A0` to the guide and `e = <A0 - P, n>` the signed distance of `A0`
//! from the guide (the offset). The slider's position `s` is `B`'s signed
//! distance from `F` along `u`: `B = F + s u`. Angles are absolute (from
//! the fixed +x axis, counter-clockwise, radians); `theta2` is the crank's,
//! `theta3` the coupler's (the direction from `A` to `B`).
//!
//! # The closed form
//!
//! With `d = e^{i theta2}`, the crank tip is `A = F + a_u u + h n` with
//! `a_u = r <d, u>` and `h = e + r <d, n>` (its height over the guide). The
//! pin is on the guide at distance `l` from `A`, so
//!
//! ```text
//! H = l^2 - h^2 = (l - h) (l + h),      s = a_u + sigma sqrt(H),      B - A = sigma sqrt(H) u - h n
//! ```
//!
//! `sigma = sign <B - A, u>` says whether `B` is ahead of (`+1`) or behind
//! (`-1`) the foot of the perpendicular from `A` to the guide. `H < 0` is
//! a crank angle where the loop does not close (the crank tip is farther
//! than `l` from the guide); `H = 0` is a toggle, where the coupler is
//! perpendicular to the guide and the two modes meet.
//!
//! This is the textbook solution (Norton, *Design of Machinery*, §4.6, the
//! offset slider-crank, eqs. 4.16–4.17): in Norton's symbols (crank `a`,
//! coupler `b`, offset `c` of the guide above the crank pivot, guide along
//! +x, slider position `d`),
//!
//! ```text
//! theta3_1 = asin((a sin theta2 - c) / b),   theta3_2 = pi - theta3_1,   d = a cos theta2 - b cos theta3
//! ```
//!
//! with Norton's `theta3` the direction from `B` to `A`; here `e = -c` and
//! `sigma = -sign cos theta3`: Norton's first solution `theta3_1`
//! (eq. 4.16a) is `sigma = -1`, his second `sigma = +1`.
//!
//! # The assembly modes' names
//!
//! A slider is the limit of a rocker whose fixed pivot goes to infinity
//! along the guide's normal, `C0 = B + R n`, `R -> +inf` (where
//! [`SliderDyad::normal`](crate::SliderDyad::normal) puts the center point).
//! The four-bar's mode is the sign of `cross(B - A, B - C0)`, which tends
//! to `-R <B - A, u>`: so the slider-crank's modes carry the four-bar's
//! names in that limit,
//!
//! ```text
//! AssemblyMode::Open     <=>  sigma = -1   (B behind the foot of the perpendicular from A: Norton's theta3_1)
//! AssemblyMode::Crossed  <=>  sigma = +1   (B ahead of it)
//! ```
//!
//! checked against a four-bar with its rocker pivot `1e6` lengths away
//! (`tests/rust/slider.rs`). Turning the guide's direction round swaps
//! the names, as moving the rocker pivot to the other side of the guide
//! does.
//!
//! # Toggles, dead positions, transmission
//!
//! A toggle is reported where `|H|` is within its rounding,
//! [`tolerance::slider_tolerance`] (the same `LOOP_EPS` as the four-bar's
//! one criterion); inside the band the answer keeps the asked mode's sign.
//!
//! - **Crank input.** The loop closes where `|h| <= l`, that is
//!   `(-l - e) / r <= cos(theta2 - phi) <= (l - e) / r`, `phi` the angle of
//!   `n`: the crank turns fully exactly when `r + |e| <= l`
//!   ([`SliderCrank::input_range`]); otherwise it rocks between dead
//!   positions where the coupler is perpendicular to the guide
//!   ([`InputRange::dead_positions`]).
//! - **Slider input.** The slider cannot drive the crank where crank and
//!   coupler are collinear (the slider's velocity is zero there): those are
//!   the slider's limit positions, `|B - A0| = l + r` and `|B - A0| =
//!   |l - r|`, that is `s = +-sqrt((l +- r)^2 - e^2)`
//!   ([`SliderCrank::limits`]); for a full-turn crank the stroke is
//!   `sqrt((l + r)^2 - e^2) - sqrt((l - r)^2 - e^2)` in either mode
//!   ([`SliderCrank::stroke`]).
//! - **Transmission angle.** The angle between the coupler and the normal
//!   to the slider's line of motion, in `[0, pi/2]` (`pi/2` ideal: the
//!   coupler pushes along the guide; `0` at a dead position of the crank
//!   input): `cos mu = |h| / l` (in Norton's symbols `|a sin theta2 - c| /
//!   b`), the definition of Söylemez, *Mechanisms* (METU), for the
//!   slider-crank, and the limit of the four-bar's coupler-rocker angle as
//!   its rocker pivot goes to infinity along the normal (checked in the
//!   tests).

use core::f64::consts::TAU;

use nalgebra::{Point2, Vector2};

use crate::error::{AssemblyError, InvalidInput, Result, finite, positive};
use crate::geom::{cross, length, normalized, perp, rotate, unit};
use crate::linkage::{AngleInterval, AssemblyMode, FourBar, InputRange};
use crate::tolerance;

/// The sign `sigma = sign <B - A, u>` of a mode (module docs): `-1` for
/// [`AssemblyMode::Open`], `+1` for [`AssemblyMode::Crossed`].
#[inline]
pub(crate) fn side(mode: AssemblyMode) -> f64 {
    -mode.sign()
}

impl AssemblyMode {
    /// The mode of a slider's loop from its coupler vector `B - A` and the
    /// guide's unit direction `u`: [`Open`](AssemblyMode::Open) where
    /// `<B - A, u> < 0`, [`Crossed`](AssemblyMode::Crossed) where it is
    /// positive (the names of the four-bar whose rocker pivot goes to
    /// infinity along `i·u`; module [`crate::linkage`]'s `slider` docs),
    /// `None` (a toggle) where the coupler is perpendicular to the guide
    /// within the slider's toggle band ([`tolerance::slider_tolerance`]),
    /// `reach` being the size of the vectors `B - A` was formed from (the
    /// crank plus the offset in a slider-crank).
    ///
    /// ```
    /// use burmester::{AssemblyMode, Vector2};
    /// let u = Vector2::x();
    /// assert_eq!(AssemblyMode::of_slider(Vector2::new(-3.0, 1.0), u, 2.0), Some(AssemblyMode::Open));
    /// assert_eq!(AssemblyMode::of_slider(Vector2::new(0.0, 1.0), u, 2.0), None);
    /// ```
    pub fn of_slider(coupler: Vector2<f64>, guide: Vector2<f64>, reach: f64) -> Option<Self> {
        let m = length(coupler).max(reach);
        if !(m > 0.0 && m.is_finite()) {
            return None;
        }
        let (v, reach) = (coupler / m, reach / m);
        let u = normalized(guide)?;
        let (x, h) = (v.dot(&u), cross(u, v));
        let l = v.norm();
        let tol = tolerance::slider_tolerance(l, -h, reach);
        if x * x > tol {
            AssemblyMode::from_sign(-x)
        } else {
            None
        }
    }
}

/// One solved position of a slider-crank.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliderConfiguration {
    /// The crank angle, as given.
    pub theta2: f64,
    /// The coupler angle, the direction from the crank tip `A` to the
    /// slider pin `B`, in `(-pi, pi]`.
    pub theta3: f64,
    /// The slider's position: `B`'s signed distance along the guide's
    /// direction `u` from the foot of the perpendicular from the crank pivot.
    pub slider: f64,
    /// The assembly mode that was asked for.
    pub mode: AssemblyMode,
    /// True at a toggle (a dead position of the crank input): the coupler
    /// is perpendicular to the guide within rounding, and both modes give
    /// this answer.
    pub toggle: bool,
    /// The transmission angle, in `[0, pi/2]`: the angle between the
    /// coupler and the normal to the guide (module docs).
    pub transmission_angle: f64,
}

/// Where the joints of a slider-crank are in one configuration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliderJoints {
    /// The crank pivot `A0`, fixed.
    pub crank_pivot: Point2<f64>,
    /// The crank tip `A`, joining crank and coupler.
    pub crank_joint: Point2<f64>,
    /// The slider pin `B`, on the guide.
    pub slider_joint: Point2<f64>,
}

impl SliderJoints {
    /// Where a point fixed to the coupler is; `local` in the coupler frame
    /// (origin at the crank joint `A`, x-axis toward the slider pin `B`),
    /// as [`Joints::coupler_point`](crate::Joints::coupler_point).
    pub fn coupler_point(&self, local: Vector2<f64>) -> Point2<f64> {
        let e = normalized(self.slider_joint - self.crank_joint).unwrap_or_else(Vector2::x);
        self.crank_joint + rotate(local, e.y.atan2(e.x))
    }
}

/// A limit position of the slider: where crank and coupler are collinear
/// (the slider's velocity is zero; a slider input cannot drive the crank
/// on), or a dead position of the crank where the crank's range ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliderLimit {
    /// The crank angle there, radians.
    pub theta2: f64,
    /// The slider's position there (as [`SliderConfiguration::slider`]).
    pub slider: f64,
}

/// A slider-crank (RRRP): a crank about a fixed pivot, a coupler, and a
/// slider pin on a straight guide fixed to the ground (module docs).
///
/// # Example
///
/// ```
/// use burmester::{AssemblyMode, Point2, SliderCrank, Vector2};
/// // Crank 40, coupler 120, the guide 20 above the crank pivot along +x
/// // (Norton's offset c = 20, so e = -20).
/// let sc = SliderCrank::new(Point2::origin(), 40.0, 120.0, Point2::new(0.0, 20.0), Vector2::x())?;
/// let c = sc.solve(60f64.to_radians(), AssemblyMode::Open)?;
/// let t3 = ((40.0 * 60f64.to_radians().sin() - 20.0) / 120.0).asin(); // Norton's theta3_1
/// assert!((c.slider - (20.0 - 120.0 * t3.cos())).abs() < 1e-12);
/// assert!(sc.turns_fully());
/// # Ok::<(), burmester::Error>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct SliderCrank {
    pivot: Point2<f64>,
    crank: f64,
    coupler: f64,
    /// The foot `F` of the perpendicular from the pivot to the guide.
    foot: Point2<f64>,
    /// The guide's unit direction `u`.
    guide: Vector2<f64>,
    /// `e = <A0 - F, n>`.
    offset: f64,
    /// `max(r, l, |e|)`: the arithmetic runs at unit size.
    scale: f64,
    /// The guide point and direction as passed to [`SliderCrank::new`]
    /// (building from them again gives this linkage, bit for bit).
    given: (Point2<f64>, Vector2<f64>),
}

/// Equal when the linkages are: the same pivot, lengths, guide line (its
/// foot from the pivot) and direction, however the guide was given.
impl PartialEq for SliderCrank {
    fn eq(&self, other: &Self) -> bool {
        (
            self.pivot,
            self.crank,
            self.coupler,
            self.foot,
            self.guide,
            self.offset,
        ) == (
            other.pivot,
            other.crank,
            other.coupler,
            other.foot,
            other.guide,
            other.offset,
        )
    }
}

crate::linkage::crank_coupler_methods!(
    SliderCrank,
    SliderConfiguration,
    SliderJoints,
    "toward the slider pin `B`"
);

impl SliderCrank {
    /// The largest extent of a slider-crank: the crank pivot's distance
    /// from the origin (as `|x| + |y|`) plus the crank, the coupler and
    /// the offset ([`FourBar::MAX_EXTENT`]).
    pub const MAX_EXTENT: f64 = FourBar::MAX_EXTENT;

    /// A slider-crank with its crank pivot at `pivot`, crank length
    /// `crank`, coupler length `coupler`, and the guide through
    /// `guide_point` in the direction `guide_direction` (any length;
    /// normalized, its sign kept: it names the modes and the sign of the
    /// slider's position).
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for a length that is not positive and finite, a
    /// point that is not finite, a zero direction, a linkage larger than
    /// [`SliderCrank::MAX_EXTENT`] or a ratio of the lengths that
    /// overflows; [`AssemblyError::GuideOutOfReach`] when the guide is
    /// farther from the pivot than crank and coupler reach (no crank angle
    /// closes the loop).
    pub fn new(
        pivot: Point2<f64>,
        crank: f64,
        coupler: f64,
        guide_point: Point2<f64>,
        guide_direction: Vector2<f64>,
    ) -> Result<Self> {
        let crank = positive("crank length", crank)?;
        let coupler = positive("coupler length", coupler)?;
        finite("crank pivot x", pivot.x)?;
        finite("crank pivot y", pivot.y)?;
        finite("guide point x", guide_point.x)?;
        finite("guide point y", guide_point.y)?;
        let guide = normalized(guide_direction).ok_or(InvalidInput::ZeroDirection {
            name: "guide direction",
            x: guide_direction.x,
            y: guide_direction.y,
        })?;
        let w = pivot - guide_point;
        let offset = cross(guide, w);
        let extent = pivot.x.abs() + pivot.y.abs() + crank + coupler + offset.abs();
        if extent.is_nan() || extent > Self::MAX_EXTENT || !length(w).is_finite() {
            return Err(InvalidInput::TooLarge {
                name: "slider-crank size (the pivot's distance plus crank, coupler and offset)",
                value: extent.max(length(w)),
                limit: Self::MAX_EXTENT,
                hint: "rescale the linkage, or pass a guide point nearer the crank pivot",
            }
            .into());
        }
        let scale = crank.max(coupler).max(offset.abs());
        if !(scale / crank.min(coupler)).is_finite() {
            return Err(InvalidInput::TooLarge {
                name: "ratio of the longest to the shortest link",
                value: scale / crank.min(coupler),
                limit: f64::MAX,
                hint: "pass lengths of comparable sizes",
            }
            .into());
        }
        let reach = crank + coupler;
        if offset.abs() > reach * (1.0 + tolerance::ROUNDING_EPS * f64::EPSILON) {
            return Err(AssemblyError::GuideOutOfReach {
                offset: offset.abs(),
                reach,
            }
            .into());
        }
        Ok(SliderCrank {
            pivot,
            crank,
            coupler,
            foot: pivot - perp(guide) * offset,
            guide,
            offset,
            scale,
            given: (guide_point, guide_direction),
        })
    }

    /// The guide point and direction as they were passed to
    /// [`SliderCrank::new`]: building from them again gives this linkage,
    /// bit for bit (its pickle).
    pub fn guide_as_given(&self) -> (Point2<f64>, Vector2<f64>) {
        self.given
    }

    /// The coupler length `l`.
    pub fn coupler(&self) -> f64 {
        self.coupler
    }
    /// The guide's unit direction `u`.
    pub fn guide(&self) -> Vector2<f64> {
        self.guide
    }
    /// The guide's unit normal `n = i·u`.
    pub fn guide_normal(&self) -> Vector2<f64> {
        perp(self.guide)
    }
    /// The foot `F` of the perpendicular from the crank pivot to the
    /// guide: the origin of the slider's position.
    pub fn foot(&self) -> Point2<f64> {
        self.foot
    }
    /// The offset `e = <A0 - F, n>`: the crank pivot's signed distance
    /// from the guide.
    pub fn offset(&self) -> f64 {
        self.offset
    }
    /// The point of the guide at slider position `s`: `F + s u`.
    pub fn guide_point(&self, s: f64) -> Point2<f64> {
        self.foot + self.guide * s
    }
    /// Longest over shortest of the crank and the coupler.
    pub fn link_ratio(&self) -> f64 {
        self.crank.max(self.coupler) / self.crank.min(self.coupler)
    }

    /// Closes the loop at `theta2` in units of `scale`: the crank
    /// direction, `a_u`, `h`, `H` and its band.
    #[inline]
    fn close(&self, theta2: f64) -> Result<(Vector2<f64>, f64, f64, f64, f64)> {
        super::bounded_theta2(theta2)?;
        let (s2, c2) = libm::sincos(theta2);
        let d = Vector2::new(c2, s2);
        let k = 1.0 / self.scale;
        let (r, l, e) = (self.crank * k, self.coupler * k, self.offset * k);
        let a_u = r * d.dot(&self.guide);
        let h = e + r * cross(self.guide, d);
        let heron = (l - h) * (l + h);
        let tol = tolerance::slider_tolerance(l, h, r + e.abs());
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(heron >= -tol) {
            return Err(AssemblyError::SliderOutOfReach {
                theta2,
                height: h.abs() * self.scale,
                coupler: self.coupler,
            }
            .into());
        }
        Ok((d, a_u, h, heron, tol))
    }

    /// Solves the loop at crank angle `theta2` (radians) in `mode`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a NaN or infinite angle,
    /// [`InvalidInput::TooLarge`] beyond [`SliderCrank::MAX_ANGLE`];
    /// [`AssemblyError::SliderOutOfReach`] where the loop does not close
    /// (the crank tip is farther than the coupler from the guide).
    pub fn solve(&self, theta2: f64, mode: AssemblyMode) -> Result<SliderConfiguration> {
        let (_, a_u, h, heron, tol) = self.close(theta2)?;
        let x = side(mode) * heron.max(0.0).sqrt();
        let (u, n) = (self.guide, perp(self.guide));
        let v = u * x - n * h;
        Ok(SliderConfiguration {
            theta2,
            theta3: v.y.atan2(v.x),
            slider: (a_u + x) * self.scale,
            mode,
            toggle: heron <= tol,
            transmission_angle: x.abs().atan2(h.abs()),
        })
    }

    /// The joints of a configuration of this linkage.
    pub fn joints(&self, c: &SliderConfiguration) -> SliderJoints {
        SliderJoints {
            crank_pivot: self.pivot,
            crank_joint: self.pivot + unit(c.theta2) * self.crank,
            slider_joint: self.guide_point(c.slider),
        }
    }

    /// Where the crank can be: all the way round exactly when
    /// `r + |e| <= l` (within [`tolerance::ROUNDING_EPS`]), else one arc,
    /// or two arcs mirror images across the normal to the guide through
    /// the pivot (a crank longer than the coupler plus the offset), bounded
    /// by the dead positions where the coupler is perpendicular to the
    /// guide (module docs).
    pub fn input_range(&self) -> InputRange {
        let (r, l, e) = (self.crank, self.coupler, self.offset);
        let (lo_free, hi_free) = self.free_ends();
        let n = perp(self.guide);
        let phi = n.y.atan2(n.x);
        let acos = |c: f64| c.clamp(-1.0, 1.0).acos();
        let (c_min, c_max) = ((-l - e) / r, (l - e) / r);
        match (lo_free, hi_free) {
            (true, true) => InputRange::Full,
            (false, true) => {
                let a = acos(c_min);
                InputRange::Arc(AngleInterval {
                    start: phi - a,
                    end: phi + a,
                })
            }
            (true, false) => {
                let a = acos(c_max);
                InputRange::Arc(AngleInterval {
                    start: phi + a,
                    end: phi + TAU - a,
                })
            }
            (false, false) => {
                let (a_lo, a_hi) = (acos(c_max), acos(c_min));
                InputRange::TwoArcs(
                    AngleInterval {
                        start: phi + a_lo,
                        end: phi + a_hi,
                    },
                    AngleInterval {
                        start: phi - a_hi,
                        end: phi - a_lo,
                    },
                )
            }
        }
    }

    /// Whether the crank turns fully (`r + |e| <= l`).
    pub fn turns_fully(&self) -> bool {
        self.input_range().is_full()
    }

    /// The positions where crank and coupler are collinear, each with the
    /// mode it is in: `|B - A0| = l + r` (extended) and `|B - A0| = |l - r|`
    /// (folded) with `B` on the guide, `s = +-sqrt((l +- r)^2 - e^2)`
    /// (the folded ones only where `|l - r| >= |e|`). The dead positions of
    /// a slider input.
    pub fn collinear_positions(&self) -> Vec<(SliderLimit, AssemblyMode)> {
        let (r, l, e) = (self.crank, self.coupler, self.offset);
        let mut out = Vec::with_capacity(4);
        // (|B - A0|, the crank's direction along B - A0: +1 or -1).
        let folded = if l >= r { -1.0 } else { 1.0 };
        for (dist, along) in [(l + r, 1.0), ((l - r).abs(), folded)] {
            let q = dist * dist - e * e;
            if q.is_nan() || q < 0.0 || dist == 0.0 {
                continue;
            }
            for sign in [1.0, -1.0] {
                let s = sign * q.sqrt();
                let b = self.guide_point(s);
                let dir = (b - self.pivot) / dist;
                let crank = dir * (along * r);
                let theta2 = crank.y.atan2(crank.x);
                // <B - A, u> = <(B - A0) - crank, u>.
                let x = (b - self.pivot - crank).dot(&self.guide);
                let mode = if x < 0.0 {
                    AssemblyMode::Open
                } else {
                    AssemblyMode::Crossed
                };
                out.push((SliderLimit { theta2, slider: s }, mode));
            }
        }
        out
    }

    /// The slider's limit positions in `mode` over the crank's input range
    /// (both arcs where there are two): `[lowest, highest]` slider
    /// position, each with its crank angle. They are where crank and
    /// coupler are collinear ([`collinear_positions`](Self::collinear_positions))
    /// or, for a crank that does not turn fully, possibly a dead position
    /// of the crank, where the modes meet.
    pub fn limits(&self, mode: AssemblyMode) -> [SliderLimit; 2] {
        let mut cands: Vec<SliderLimit> = self
            .collinear_positions()
            .into_iter()
            .filter(|(_, m)| *m == mode)
            .map(|(p, _)| p)
            .collect();
        for t in self.input_range().dead_positions() {
            if let Ok(c) = self.solve(t, mode) {
                cands.push(SliderLimit {
                    theta2: t,
                    slider: c.slider,
                });
            }
        }
        let Some(&first) = cands.first() else {
            let none = SliderLimit {
                theta2: f64::NAN,
                slider: f64::NAN,
            };
            return [none; 2];
        };
        cands.iter().fold([first, first], |[lo, hi], &p| {
            [
                if p.slider < lo.slider { p } else { lo },
                if p.slider > hi.slider { p } else { hi },
            ]
        })
    }

    /// The slider's stroke in `mode`: the distance between its
    /// [`limits`](Self::limits). For a crank that turns fully it is
    /// `sqrt((l + r)^2 - e^2) - sqrt((l - r)^2 - e^2)` in either mode.
    pub fn stroke(&self, mode: AssemblyMode) -> f64 {
        let [lo, hi] = self.limits(mode);
        hi.slider - lo.slider
    }

    /// Whether the crank tip's height over the guide,
    /// `h = e + r cos(theta - phi)` (`phi` the angle of the normal), stays within the coupler's
    /// reach at `cos = -1` and at `cos = +1`: `(r - e <= l, r + e <= l)`,
    /// within [`tolerance::ROUNDING_EPS`] (both: the crank turns fully).
    pub(crate) fn free_ends(&self) -> (bool, bool) {
        let (r, l, e) = (self.crank, self.coupler, self.offset);
        let slack = tolerance::ROUNDING_EPS * f64::EPSILON * (r + l + e.abs());
        (r - e <= l + slack, r + e <= l + slack)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::PI;

    #[test]
    fn norton_offset_slider_crank() {
        // a = 40, b = 120, c = 20 (guide above the pivot), theta2 = 60 deg.
        let sc = SliderCrank::new(
            Point2::origin(),
            40.0,
            120.0,
            Point2::new(5.0, 20.0),
            Vector2::x(),
        )
        .unwrap();
        assert_eq!(sc.offset(), -20.0);
        let t2 = 60f64.to_radians();
        let t31 = ((40.0 * t2.sin() - 20.0) / 120.0).asin();
        let t32 = PI - t31;
        for (mode, t3) in [(AssemblyMode::Open, t31), (AssemblyMode::Crossed, t32)] {
            let c = sc.solve(t2, mode).unwrap();
            let d = 40.0 * t2.cos() - 120.0 * t3.cos();
            assert!(
                (c.slider - d).abs() < 1e-12,
                "{mode:?}: {} vs {d}",
                c.slider
            );
            // Norton's theta3 runs from B to A; ours from A to B.
            let ours = crate::geom::wrap_angle(t3 + PI);
            assert!((crate::geom::wrap_angle(c.theta3 - ours)).abs() < 1e-13);
        }
    }
}
