//! The inverted slider-crank of a task: a driving crank `(A0, A1)` and an
//! inverted slider (a line of the coupler through a ground swivel `S` at
//! every pose, [`InvertedSlider`]), with what it takes to drive it through
//! the task's poses.
//!
//! At pose `k` the crank pin is `A_k = D_1k(A1)` and the slot runs through
//! `S` in the direction `u3_k = e^{i(theta_k - theta_1)} d` (`d` the body
//! line's direction at pose 1). The input angle is `arg(A_k - A0)`; the
//! assembly mode is the sign of the slot position `t_k = <S - A_k, u3_k>`,
//! named as the position analysis names it ([`InvertedSliderCrank`]:
//! [`AssemblyMode::Open`](crate::AssemblyMode::Open) where it is
//! positive). Seen in the coupler frame at pose 1 that is
//! `sign <D_k1(S) - A1, d>`: the side of the line through the swivel's
//! image `D_k1(S)` normal to the slot on which `A1` lies
//! (Filemon's construction with the circle point at infinity, whose lines
//! are parallel: [`InvalidInput::InvertedDriven`] in
//! [`FilemonLines`](crate::FilemonLines)). The order is the driving
//! crank's, as for the four-bar and the slider-crank, with the ground line
//! `S - A0` for the axis of the input range (the loop closes where
//! `cos(theta2 - psi0) <= (g^2 + r^2 - e^2) / (2 g r)`).

use nalgebra::Vector2;

use crate::error::{InvalidInput, Result};
use crate::geom::{PerPose, cross, rotate};
use crate::linkage::{Direction, InvertedSliderCrank};
use crate::synthesis::crank_travel::{branch_mode, crank_modes, crank_travel};
use crate::synthesis::{Dyad, DyadKind, InvertedSlider, Task};

crate::synthesis::crank_travel::crank_synthesized! {
    /// An inverted slider-crank built from a driving crank and an inverted
    /// slider of a task, with its input angle, assembly mode and slot position
    /// at each pose, its order and what a designer checks (module docs).
    pub struct SynthesizedInvertedSliderCrank {
        /// The linkage: crank pivot `A0`, the swivel `S`, the slot's offset.
        linkage: InvertedSliderCrank,
        /// The driven inverted slider (the swivel and the slot at pose 1).
        driven: InvertedSlider,
        toggle: "the crank pin `|e|` from the swivel",
        /// The slot position at each pose (as
        /// [`InvertedConfiguration::slot`](crate::InvertedConfiguration::slot)).
        slot_positions,
        axis: "along the slot",
        /// The block's travel along the slot over the crank's travel from the
        /// first pose to the last (the highest minus the lowest slot
        /// position there); NaN without a travel or with a branch defect.
        stroke_used,
        /// The slotted link's swing over the travel (its largest minus its
        /// smallest angle there, radians, each measured within half a turn of
        /// its angle at pose 1: a slotted link that turns more than half a
        /// turn over the travel is not told apart); NaN without a travel or
        /// with a branch defect.
        swing_used: f64,
    }
}

impl SynthesizedInvertedSliderCrank {
    /// The linkage's size: the crank, the ground, the distances of the
    /// task's coupler point from the crank pin and from the swivel at pose
    /// 1, and the length of slot the block runs on over the travel (the
    /// [`stroke_used`](Self::stroke_used); the spread of the slot positions
    /// at the poses where that is NaN).
    pub fn size(&self) -> f64 {
        let a = self.driving.circle;
        let p = a + rotate(
            self.coupler_point,
            self.driven.direction.y.atan2(self.driven.direction.x),
        );
        let slot = self.stroke_or_spread();
        self.linkage.crank()
            + self.linkage.ground()
            + (p - a).norm()
            + (p - self.driven.swivel).norm()
            + slot
    }
}

impl Task {
    /// The inverted slider-crank built from a driving crank `(A0, A1)` and
    /// an inverted slider (the swivel `S` and the slot's direction at pose
    /// 1; [`Task::inverted_sliders`], [`Task::inverted_slider`]), with its
    /// crank angle, assembly mode and slot position at each pose, its order
    /// and figures. The slot's offset is `e = cross(d, S - A1)`.
    ///
    /// Driving the returned linkage to `input_angles[k]` in `modes[k]`
    /// places the task's coupler point and angle at pose `k + 1`
    /// ([`SynthesizedInvertedSliderCrank::pose_at`]).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotADyad`] when the driving dyad's circle point is
    /// not a circle point of its center (build it with
    /// [`Task::dyad_from_center`]); [`InvalidInput::ZeroDirection`] for a
    /// slot direction that is zero or not finite;
    /// [`InvalidInput::NotASlider`] when the body line leaves the swivel at
    /// a pose (take one of the task's inverted sliders); errors of
    /// [`InvertedSliderCrank::new`].
    pub fn inverted_slider_crank(
        &self,
        driving: &Dyad,
        driven: &InvertedSlider,
    ) -> Result<SynthesizedInvertedSliderCrank> {
        self.check_dyad(driving, "driving dyad")?;
        crate::error::finite_point(["swivel point x", "swivel point y"], driven.swivel)?;
        let d = crate::geom::normalized(driven.direction).ok_or(InvalidInput::ZeroDirection {
            name: "inverted slider's slot direction",
            x: driven.direction.x,
            y: driven.direction.y,
        })?;
        let driven = InvertedSlider {
            swivel: driven.swivel,
            direction: d,
        };
        let s = driven.swivel;
        let n = self.len();
        // The slot's direction at each pose and the body line's distance
        // from the swivel there.
        let motion = self.motion();
        let swivel_images = motion.positions(s);
        let slot = PerPose::from_fn(n, |k| rotate(d, motion.rotation0(0, k)));
        self.check_on_lines(
            "driven inverted slider (its body line leaves the swivel)",
            &swivel_images,
            s,
            |k| slot[k],
        )?;
        let a = motion.positions(driving.circle);
        let a0 = driving.center;
        let offset = cross(d, s - a[0]);
        let linkage = InvertedSliderCrank::new(a0, driving.length(), s, offset)?;
        let reach = linkage.crank() + linkage.ground();
        let kind = DyadKind::Inverted(driven);
        let (input_angles, modes) = crank_modes(
            &a,
            a0,
            kind,
            |k| s + slot[k],
            reach,
            |t, m| linkage.solve(t, m).is_ok_and(|sol| !sol.toggle),
        );
        let slot_positions = PerPose::from_fn(n, |k| (s - a[k]).dot(&slot[k]));
        let g = s - a0;
        let axis = if g.norm() > 0.0 { g } else { Vector2::x() };
        let (e, trav) = crank_travel(&a, a0, axis, true, linkage.turns_fully())?;
        let last = n - 1;
        let figures = if trav.direction == Direction::None {
            (f64::NAN, f64::NAN, f64::NAN)
        } else {
            // cos mu = |e| / rho is largest where rho = |S - A| is
            // smallest: at an end of the travel or with the crank pointing
            // at the swivel.
            let r = linkage.crank();
            let cos_mu =
                |dir: Vector2<f64>| (offset.abs() / (g - dir.normalize() * r).norm()).min(1.0);
            let mut worst = cos_mu(e[0]).max(cos_mu(e[last]));
            if trav.contains(axis) {
                worst = worst.max(cos_mu(axis));
            }
            let (stroke, swing) = match branch_mode(&modes) {
                Some(mode) => {
                    let at = |v: Vector2<f64>| linkage.solve(v.y.atan2(v.x), mode).ok();
                    let mut ends: Vec<(f64, f64)> = [e[0], e[last], axis, -axis]
                        .iter()
                        .enumerate()
                        .filter(|(i, v)| *i < 2 || trav.contains(**v))
                        .filter_map(|(_, v)| at(*v).map(|c| (c.slot, c.theta3)))
                        .collect();
                    for p in linkage.stationary_positions(mode) {
                        let v = Vector2::new(p.theta2.cos(), p.theta2.sin());
                        if trav.contains(v) {
                            ends.push((p.slot, p.theta3));
                        }
                    }
                    let t3_ref = ends.first().map_or(0.0, |x| x.1);
                    let (mut lo_t, mut hi_t, mut lo_a, mut hi_a) = (
                        f64::INFINITY,
                        f64::NEG_INFINITY,
                        f64::INFINITY,
                        f64::NEG_INFINITY,
                    );
                    for (t, a3) in ends {
                        let a3 = crate::geom::wrap_angle(a3 - t3_ref);
                        (lo_t, hi_t) = (lo_t.min(t), hi_t.max(t));
                        (lo_a, hi_a) = (lo_a.min(a3), hi_a.max(a3));
                    }
                    (hi_t - lo_t, hi_a - lo_a)
                }
                _ => (f64::NAN, f64::NAN),
            };
            (worst.acos(), stroke, swing)
        };
        Ok(SynthesizedInvertedSliderCrank::from_parts(
            linkage,
            *driving,
            driven,
            (input_angles, modes),
            trav,
            self.coupler_point_along(a[0], d),
            slot_positions,
            figures,
        ))
    }
}
