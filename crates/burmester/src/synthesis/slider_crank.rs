//! The slider-crank of a task: a driving crank `(A0, A1)` and a driven
//! slider `C1` on its guide ([`SliderDyad`]), with what it takes to drive
//! it through the task's poses.
//!
//! At pose `k` the moving pivots are `A_k = D_1k(A1)` and `C_k = D_1k(C1)`
//! (on the guide). The input angle is `arg(A_k - A0)`; the assembly mode is
//! the sign of `<C_k - A_k, u>` named as the position analysis names it
//! ([`SliderCrank`]: [`AssemblyMode::Open`] where it is negative). Seen in
//! the coupler frame at pose 1 that is the notes' formula
//! `mode_k = sign <C1 - A1, u_k>`, `u_k = e^{-i(theta_k - theta_1)} u`
//! (the coupler turned back to pose 1 carries `C_k - A_k` to `C1 - A1`
//! and `u` to `u_k`). The order is the driving crank's: a crank that turns
//! fully must meet the poses in cyclic order one way round, a rocking one
//! monotonically inside one arc of its range (the four-bar's logic,
//! `linkage::figures::travel`, with the guide's normal for the ground
//! line).

use nalgebra::{Point2, Vector2};

use crate::error::Result;
use crate::geom::{perp, rotate};
use crate::linkage::{AssemblyMode, Direction, SliderCrank};
use crate::synthesis::crank_travel::{branch_mode, crank_modes, crank_travel};
use crate::synthesis::{Dyad, DyadKind, SliderDyad, Task};
use crate::tolerance;

impl DyadKind {
    /// The assembly mode of a linkage whose driving crank's joint is at
    /// `crank_joint` and whose driven dyad (this one) has its moving pivot
    /// at `joint`; `reach` the size of the vectors the loop was formed
    /// from (ground plus crank of a four-bar, crank plus offset of a
    /// slider-crank). A crank: the sign of `cross(joint - crank_joint,
    /// joint - center)` ([`AssemblyMode::of_loop_within`]); a slider: the
    /// sign of `<crank_joint - joint, u>` ([`AssemblyMode::of_slider`], the
    /// limit of the crank's as its center goes to infinity along the
    /// guide's normal). An inverted slider, whose moving pivot is at
    /// infinity: `joint` is read as the swivel plus the slot's direction
    /// where the slot is ([`InvertedSlider::slot_point_at`]), and the mode
    /// is the sign of the slot position `<S - crank_joint, u3>`
    /// ([`AssemblyMode::of_inverted`]). `None` at a toggle.
    ///
    /// [`InvertedSlider::slot_point_at`]: crate::InvertedSlider::slot_point_at
    pub fn assembly_mode(
        &self,
        crank_joint: Point2<f64>,
        joint: Point2<f64>,
        reach: f64,
    ) -> Option<AssemblyMode> {
        match self {
            DyadKind::Revolute(d) => {
                AssemblyMode::of_loop_within(joint - crank_joint, joint - d.center, reach)
            }
            DyadKind::Slider(s) => AssemblyMode::of_slider(joint - crank_joint, s.guide, reach),
            DyadKind::Inverted(v) => {
                AssemblyMode::of_inverted(v.swivel - crank_joint, joint - v.swivel, reach)
            }
        }
    }
}

crate::synthesis::crank_travel::crank_synthesized! {
    /// A slider-crank built from a driving crank and a driven slider of a
    /// task, with its input angle and assembly mode at each pose, its order
    /// and what a designer checks (module docs).
    pub struct SynthesizedSliderCrank {
        /// The linkage: crank pivot `A0`, the guide through `C1`.
        linkage: SliderCrank,
        /// The driven slider (`C1` on its guide).
        driven: SliderDyad,
        toggle: "the coupler perpendicular to the guide",
        /// The slider's position at each pose (as
        /// [`SliderConfiguration::slider`](crate::SliderConfiguration::slider)).
        slider_positions,
        axis: "toward the slider pin",
        /// The slider's travel along the guide over the crank's travel from
        /// the first pose to the last (its highest minus its lowest position
        /// there); NaN without a travel or with a branch defect.
        stroke_used,
    }
}

impl SynthesizedSliderCrank {
    /// The linkage's size: crank, coupler, the two other sides of the
    /// coupler triangle (the moving pivots and the task's coupler point),
    /// the offset (the ground from the pivot to the guide) and the length
    /// of guide the slider runs on over the travel (the
    /// [`stroke_used`](Self::stroke_used); the spread of the slider's
    /// positions at the poses where that is NaN).
    pub fn size(&self) -> f64 {
        let (a, c) = (self.driving.circle, self.driven.circle);
        let ac = c - a;
        let p = a + rotate(self.coupler_point, ac.y.atan2(ac.x));
        let guide = self.stroke_or_spread();
        self.linkage.crank()
            + self.linkage.coupler()
            + (p - a).norm()
            + (p - c).norm()
            + self.linkage.offset().abs()
            + guide
    }
}

impl Task {
    /// The slider-crank built from a driving crank `(A0, A1)` and a driven
    /// slider (`C1` on its guide), with its crank angle, assembly mode and
    /// slider position at each pose, its order and figures.
    ///
    /// Driving the returned linkage to `input_angles[k]` in `modes[k]`
    /// places the task's coupler point and angle at pose `k + 1`
    /// ([`SynthesizedSliderCrank::pose_at`]).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotADyad`] when the driving dyad's circle point is
    /// not a circle point of its center (build it with
    /// [`Task::dyad_from_center`]); [`InvalidInput::NotASlider`] when the
    /// slider's positions over the poses leave its guide (take a slider
    /// point of the task and the line through its positions);
    /// [`DegenerateError::ZeroLengthLink`](crate::DegenerateError::ZeroLengthLink)
    /// for a crank or coupler of no length; errors of [`SliderCrank::new`].
    ///
    /// [`InvalidInput::NotADyad`]: crate::InvalidInput::NotADyad
    /// [`InvalidInput::NotASlider`]: crate::InvalidInput::NotASlider
    pub fn slider_crank(
        &self,
        driving: &Dyad,
        driven: &SliderDyad,
    ) -> Result<SynthesizedSliderCrank> {
        self.check_dyad(driving, "driving dyad")?;
        let c = self.motion().positions(driven.circle);
        let u = driven.guide;
        self.check_on_lines("driven slider", &c, c[0], |_| u)?;
        crate::linkage::nonzero_links(
            [(driving.circle, driven.circle, "coupler link")],
            tolerance::POINT * self.scale(),
        )?;
        let a0 = driving.center;
        let linkage = SliderCrank::new(
            a0,
            driving.length(),
            (driven.circle - driving.circle).norm(),
            driven.circle,
            u,
        )?;
        let a = self.motion().positions(driving.circle);
        let reach = linkage.crank() + linkage.offset().abs();
        let (input_angles, modes) = crank_modes(
            &a,
            a0,
            DyadKind::Slider(*driven),
            |k| c[k],
            reach,
            |t, m| linkage.solve(t, m).is_ok_and(|sol| !sol.toggle),
        );
        let foot = linkage.foot();
        let slider_positions = c.map(|p| (p - foot).dot(&u));
        let (lo, hi) = linkage.free_ends();
        let n = perp(u);
        let (e, trav) = crank_travel(&a, a0, n, lo, hi)?;
        let last = e.len() - 1;
        let figures = if trav.direction == Direction::None {
            (f64::NAN, f64::NAN)
        } else {
            // cos mu = |h| / l with h = e + r <d, n>, convex in <d, n>: its
            // largest value on the travel is at an end or where the crank
            // passes +-n (as the four-bar's figures).
            let (r, l, off) = (linkage.crank(), linkage.coupler(), linkage.offset());
            let cos_mu = |dn: f64| ((off + r * dn).abs() / l).min(1.0);
            let unit_dn = |v: Vector2<f64>| v.dot(&n) / v.norm();
            let mut worst = cos_mu(unit_dn(e[0])).max(cos_mu(unit_dn(e[last])));
            for (dir, dn) in [(n, 1.0), (-n, -1.0)] {
                if trav.contains(dir) {
                    worst = worst.max(cos_mu(dn));
                }
            }
            let stroke = match branch_mode(&modes) {
                Some(mode) => {
                    let (mut lo_s, mut hi_s) = (
                        slider_positions[0].min(slider_positions[last]),
                        slider_positions[0].max(slider_positions[last]),
                    );
                    for (p, m) in linkage.collinear_positions() {
                        let d = Vector2::new(p.theta2.cos(), p.theta2.sin());
                        if m == mode && trav.contains(d) {
                            lo_s = lo_s.min(p.slider);
                            hi_s = hi_s.max(p.slider);
                        }
                    }
                    hi_s - lo_s
                }
                _ => f64::NAN,
            };
            (worst.acos(), stroke)
        };
        Ok(SynthesizedSliderCrank::from_parts(
            linkage,
            *driving,
            *driven,
            (input_angles, modes),
            trav,
            self.coupler_point_along(a[0], c[0] - a[0]),
            slider_positions,
            figures,
        ))
    }
}
