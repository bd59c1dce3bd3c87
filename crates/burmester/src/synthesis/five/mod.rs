//! Five poses: the Burmester points (every real one) and the four-bars of
//! their pairs.

// Comparisons are written `!(a > b)` on purpose: a NaN takes the failing
// branch.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use nalgebra::{Complex, Matrix4, Point2, Vector2, Vector4};

use crate::error::{DegenerateError, Error, Result};
use crate::geom::cubic::roots::{
    form_eval, form_mul, form_roots_mult, form_sub, quadratic_roots, roots_in_mult,
};
use crate::geom::cubic::{gradient as grad, hessian as hess};
use crate::geom::{Cubic, LocalFrame, PerPose, Pose, cross, perp, wrap_angle};
use crate::synthesis::Dyad;
use crate::synthesis::errors;
use crate::synthesis::local::{Failure, LocalMotion, close_pair};
use crate::synthesis::order::{Drive, drive};
use crate::synthesis::task::of_poses;
use crate::tolerance;

mod certificate;
mod refine;

#[doc(hidden)]
pub use certificate::certified_count;

/// A four-bar made of two Burmester dyads, classified for either dyad
/// driving.
#[derive(Debug, Clone, PartialEq)]
pub struct BurmesterFourBar {
    /// The indices of the two dyads in [`FivePositions::burmester_points`].
    pub indices: [usize; 2],
    /// `drives[0]`: the first dyad drives, the second is driven;
    /// `drives[1]`: the other way round.
    pub drives: [Drive; 2],
}

/// Five poses of the coupler and their Burmester points: the dyads whose
/// circle point lies on a circle at all five poses.
///
/// # The method (no sampling, no random restarts)
///
/// The Burmester centers are the common points of the center-point curves
/// of two four-pose subsets that share three poses `i, j, k` (the cubics
/// `f` of `i, j, k, l` and `h` of `i, j, k, m`), less the poles
/// `P_ij, P_ik, P_jk` (on both) and the circular points. Both cubics pass
/// through `Q = P_ij` (the pair with the best conditioned pole is taken),
/// so along the line `Q + t w`
///
/// ```text
/// f(Q + t w) = t (a t^2 + b t + c),   h(Q + t w) = t (d t^2 + e t + g)
/// ```
///
/// with `a, d` cubic, `b, e` quadratic and `c, g` linear forms in `w`. The
/// two quadratics have a common root exactly where their resultant
///
/// ```text
/// R(w) = (a g - c d)^2 - (a e - b d)(b g - c e)
/// ```
///
/// vanishes: a binary form of degree 8, whose real roots are the
/// directions from `Q` to `P_ik`, `P_jk` and the (at most four) real
/// Burmester points (the other two roots are the circular points'). Along
/// each the two quadratics share one root (both when they are
/// proportional: two points on one line), or the root is at infinity where
/// both curves have it as their asymptotic direction (a slider).
///
/// # Within rounding: double points, points at infinity, degenerate tasks
///
/// Every form carries a first-order bound on its rounding (the curves'
/// coefficients from the poses, `Q`, each product), so `R` is evaluated
/// with its rounding band ([`crate::tolerance::BURMESTER_EPS`]): its roots
/// are found between its critical points, and a critical point where `R`
/// is zero within the band is a **double root**: two Burmester points that
/// merge, or a pair of complex ones, within rounding. It gives a double
/// point, listed twice (unless Newton's method, from the root and from its
/// reflection, converges to two distinct real points on either side of it:
/// two points closer than the band resolves, each listed once), so that the count with multiplicity (finite points
/// and [`sliders`](FivePositions::sliders)) is 0, 2 or 4 in every frame.
/// The curves share a point at infinity (a slider) when their asymptotic
/// directions agree within the rounding of the computation and of the poses
/// themselves (in the frame they are given in), and the slider's circle
/// point, solved from two of the conditions at infinity, has its five
/// positions on a line (within [`tolerance::BURMESTER_RESIDUAL`] of their span: a root
/// near a common asymptotic direction by rounding can give one far off any
/// line, and gives no point then). An elimination whose count with
/// multiplicity is above four (two cubics meet in nine points, five of them
/// known: more is its rounding band holding several critical points of the
/// resultant, each a double root) is not taken. A resultant that vanishes
/// identically within that rounding for every choice of the shared poses
/// means the points are not isolated (a typed error), as do three poses
/// that are rotations about one point, or of one angle on a line. The
/// elimination is taken from the best conditioned pole and the other
/// choices in turn until every root gives a point: a Burmester point next
/// to a shared pole merges with it in one elimination and not in another.
///
/// Each point is finished by Newton's method on the four circle equations
/// `a_k(G) . z = b_k(G)` in the unknowns `(G, z)`, and kept when the five
/// positions of its circle point are concyclic within
/// [`tolerance::BURMESTER_RESIDUAL`] (scaled by `(L / D)^2` for a center
/// `D` away from positions spanning `L`, where a stretch of a line is as
/// concyclic).
#[derive(Clone, Copy, PartialEq)]
pub struct FivePositions {
    motion: LocalMotion,
    // At most four in all (`MAX_POINTS`), inline: a task keeps them and
    // stays `Copy`.
    points: PerPose<Dyad>,
    sliders: PerPose<BurmesterSlider>,
    curves: [Cubic; 2],
}

crate::geom::debug_shows!(
    /// The poses and the Burmester points, not the motion's internals.
    FivePositions,
    s => poses: s.poses(), burmester_points: s.points, sliders: s.sliders,
);

/// A Burmester point at infinity: a circle point whose five positions lie
/// on a line (a slider: its crank's center point is at infinity in
/// `direction`, and the moving pivot runs along the normal of
/// `direction`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BurmesterSlider {
    /// The circle point (the moving pivot at pose 1).
    pub circle: Point2<f64>,
    /// The unit direction in which the center point is at infinity (the
    /// slider's line is normal to it); defined up to sign.
    pub direction: Vector2<f64>,
}

impl FivePositions {
    /// The Burmester points of five poses.
    ///
    /// # Errors
    ///
    /// [`crate::InvalidInput::NeedsPoses`] unless there are exactly five
    /// poses; the errors of [`super::FourPositions::new`] for the poses
    /// (four of them rotations about one point give
    /// [`crate::DegenerateError::CoincidentPoles`]: a continuum of dyads);
    /// [`crate::DegenerateError::AllTranslations`] when all poses have one
    /// angle (a pure translation);
    /// [`crate::DegenerateError::RotationsAboutOnePoint`] when three poses
    /// are rotations about one point;
    /// [`crate::DegenerateError::CollinearTranslations`] when three poses
    /// have one angle and collinear positions;
    /// [`crate::DegenerateError::InfinitelyManyBurmesterPoints`] when the
    /// Burmester points are not isolated (the elimination vanishes
    /// identically within its rounding, a line of common center points, or
    /// a center with a line of circle points);
    /// [`crate::DegenerateError::UnresolvedBurmesterPoints`] when no choice
    /// of the shared poses gives a point (or a slider whose five positions
    /// are on its line) for every root and an even count of at most four
    /// (a task within rounding of a degenerate one, such as pairs of poses
    /// of one angle or half a turn apart, where the resultant's rounding
    /// band holds several of its critical points), when a choice finds a
    /// line of common points where an earlier one found isolated points
    /// (the line within rounding), when the answer lacks a
    /// Burmester point at coincident poles (`P_ab = P_cd`, verified on the
    /// circle equations) that no choice lists, when the points
    /// computed with another pose as the reference disagree, or when the
    /// exact count disagrees (see below).
    ///
    /// # The answer is checked
    ///
    /// The points are computed five times, with each pose in turn as the
    /// reference pose (the frame the elimination works in: angles relative
    /// to it, its poles and choices of the shared poses rounded anew), and
    /// the answer is given only where the five agree: every point within
    /// [`BURMESTER_NEAR`](crate::tolerance::BURMESTER_NEAR) task sizes that
    /// is apart from the others (farther than `1e-2` of `size + d`) listed
    /// by each within
    /// [`BURMESTER_AGREEMENT`](crate::tolerance::BURMESTER_AGREEMENT) of
    /// `size + d` (`d` its distance from the poses' centroid), and no point
    /// listed twice (a double point) where another lists one point within
    /// `1e-2` of `size + d` of it. A computation that fails is not
    /// counted. The exact points do not
    /// depend on the reference pose; where the computations disagree, the
    /// rounding decides the answer (a task within rounding of a degenerate
    /// one) and the task is refused rather than answered wrongly (issue
    /// 24). On ordinary tasks they agree (100,000 random tasks, none
    /// refused); the check costs four more computations.
    ///
    /// Then the answer is checked against an exact count: the float task
    /// (each rotation from pose 1 moved onto the unit circle by its
    /// half-angle tangent rounded to a double, the positions the exact
    /// values of the floats) is solved in exact integer arithmetic (the
    /// two center-point cubics, their resultant with the poles divided out,
    /// a Sturm count of its real roots, each root's point from the first
    /// subresultant), and the answer's points within `BURMESTER_NEAR` task
    /// sizes must pair one to one with the exact ones there, each within
    /// `1e-3` of `size + d` (a double point may stand for a complex pair of
    /// the exact task within `1e-5` of `size + d` of it, found by Pellet's
    /// test on the exact polynomial: a pair that merges within the
    /// rounding); otherwise the task is refused
    /// ([`crate::DegenerateError::UnresolvedBurmesterPoints`]). Farther
    /// points and sliders are not compared (a far point is known only
    /// within rounding of a slider). Where the exact task is degenerate (a
    /// Burmester point at a pole, a multiple point, a common component)
    /// the checks above answer alone. The exact check costs about 0.7 ms on
    /// an ordinary task (0.3 ms the count, the rest each point's place; its
    /// integers about 550 bits; `FivePositions::new` about 0.83 ms in all on
    /// the notes' worked example) and some tens of milliseconds at the most
    /// on any f64 task (coordinates of `1e100` beside subnormal ones and
    /// subnormal rotations: about 10,000 bits).
    pub fn new(poses: &[Pose]) -> Result<Self> {
        of_poses(poses, 5, "FivePositions::new", Self::of)
    }

    /// The Burmester points of five poses that passed the one check of the
    /// poses ([`check_poses`](crate::synthesis::task::check_poses): a
    /// task's).
    pub(crate) fn of(poses: &[Pose]) -> Result<Self> {
        let (answer, lacking) = Self::solve(poses)?;
        if lacking {
            return Err(errors::unresolved(
                "a Burmester point at coincident poles (verified on the circle equations) is \
                 listed by no choice of the shared poses, and the answer lacks it",
            ));
        }
        for r in 1..5 {
            let turned: [Pose; 5] = core::array::from_fn(|k| poses[(k + r) % 5]);
            // Another reference pose's answer is compared even where it
            // lacks such a point: refused in its own right, it would leave
            // a wrong answer unchecked (five42: refusing it inside `solve`
            // answered two frames wrongly that this comparison refuses).
            if let Ok((other, _)) = Self::solve(&turned) {
                if !answer.agrees(&other, true) || !other.agrees(&answer, false) {
                    return Err(errors::unresolved(
                        "the points computed with another pose as the reference pose disagree \
                         (the exact points do not depend on it: the rounding decides them)",
                    ));
                }
            }
        }
        // The exact count (issue 24): the float task's Burmester points
        // within `BURMESTER_NEAR` task sizes, counted and placed in exact
        // arithmetic, must be the answer's.
        let listed: Vec<(f64, f64)> = answer
            .points
            .iter()
            .map(|d| (d.center.x, d.center.y))
            .collect();
        let o = answer.motion.origin;
        if let Some(why) = certificate::refuses(poses, &listed, (o.x, o.y), answer.motion.scale) {
            return Err(errors::unresolved(why));
        }
        Ok(answer)
    }

    /// Whether every Burmester point of `self` within
    /// [`tolerance::BURMESTER_NEAR`] task sizes that is apart from its
    /// others (farther than `1e-2` of `size + d`) has a point of `other`
    /// within [`tolerance::BURMESTER_AGREEMENT`] of `size + d` (`d` its
    /// distance from the poses' centroid), and, with `doubles` (the answer
    /// checked), no such point listed twice has exactly one point of
    /// `other` within `1e-2` of `size + d`: the check of [`Self::new`].
    fn agrees(&self, other: &Self, doubles: bool) -> bool {
        let (o, size) = (self.motion.origin, self.motion.scale);
        let own = self.burmester_points();
        own.iter().enumerate().all(|(i, p)| {
            let reach = size + (p.center - o).norm();
            let near = is_near(&self.motion, p.center);
            let close = |q: &Dyad| (q.center - p.center).norm() <= 1e-2 * reach;
            let apart = own.iter().enumerate().all(|(j, q)| j == i || !close(q));
            // A double point (two listed at one place) where the other
            // lists one simple point there: one of them has the count
            // wrong (fuzz finding `0368e501` moved, five41: a complex pair
            // read as a double point and moved onto the simple point by
            // `refined`; the other reference poses list it once). Two
            // there or none (a complex pair) is a near pair within rounding.
            let double = own
                .iter()
                .enumerate()
                .any(|(j, q)| j != i && q.center == p.center);
            if doubles
                && near
                && double
                && other.burmester_points().iter().filter(|q| close(q)).count() == 1
            {
                return false;
            }
            !(near && apart)
                || other
                    .burmester_points()
                    .iter()
                    .any(|q| (q.center - p.center).norm() <= tolerance::BURMESTER_AGREEMENT * reach)
        })
    }

    /// The Burmester points of five poses with the first as the reference
    /// pose, unchecked, and whether they lack a Burmester point at
    /// coincident poles that no choice of the shared poses lists (see
    /// below: [`Self::of`] refuses such an answer, and compares it with its
    /// own where another reference pose gives it).
    fn solve(poses: &[Pose]) -> Result<(Self, bool)> {
        let motion = LocalMotion::new(poses)?;
        // The pair with the best conditioned pole.
        let mut best = (0.0, 0, 1);
        for i in 0..5 {
            for j in i + 1..5 {
                let s = (0.5 * wrap_angle(motion.theta[j] - motion.theta[i]))
                    .sin()
                    .abs();
                if s > best.0 {
                    best = (s, i, j);
                }
            }
        }
        let (s, _, _) = best;
        if !(s > tolerance::COINCIDENT_POSES) {
            return Err(errors::all_translations());
        }
        // Every four-pose curve must be proper: four poses that are all
        // rotations about one point leave a continuum of Burmester dyads.
        let rest = LocalMotion::new(&poses[1..])?;
        let subsets = [
            (&motion, [1, 2, 3]),
            (&motion, [1, 2, 4]),
            (&motion, [1, 3, 4]),
            (&motion, [2, 3, 4]),
            (&rest, [1, 2, 3]),
        ];
        for (m, rows) in subsets {
            let (f, mag) = m.form.cubic(rows);
            let max = f.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            if !(max > tolerance::DEGENERATE_CURVE * mag) {
                let p = m.dehomogenize(m.pole(0, rows[0])).unwrap_or(m.origin);
                return Err(errors::common_pole(p));
            }
        }
        degenerate_triples(&motion)?;
        // The elimination from a pole `P_ij` shared by the curves of poses
        // `i, j, k, l` and `i, j, k, m`: the best conditioned pole first,
        // with each of the other three poses as `k`, then the other poles.
        // A choice whose resultant vanishes identically is skipped (every
        // choice does exactly when the points are not isolated); the first
        // whose every root gives a Burmester point (or a slider) and whose
        // count is even is taken: a Burmester point near one of the shared
        // poles, in the direction of one, merges with it in that
        // elimination and not in another. Failing every choice, the points
        // are not resolved within rounding (a typed error).
        let mut pairs: Vec<(f64, usize, usize)> = Vec::new();
        for a in 0..5 {
            for b in a + 1..5 {
                let s = (0.5 * wrap_angle(motion.theta[b] - motion.theta[a]))
                    .sin()
                    .abs();
                if s > tolerance::COINCIDENT_POSES {
                    pairs.push((s, a, b));
                }
            }
        }
        pairs.sort_by(|x, y| y.0.total_cmp(&x.0));
        // The answer: the first clean choice (every root a point, an even
        // count of at most four) that lists at least as many points as an
        // earlier (better conditioned) choice verified as distinct points
        // within `BURMESTER_NEAR` task sizes while losing others:
        // those points exist (each passed `polish`), so a later choice that
        // finds fewer, none at all for a badly conditioned one, lost them
        // too, within its rounding, and is not clean. And it lists every
        // Burmester point at coincident poles (`P_ab = P_cd`, verified by
        // `polish`) where one can: the choices whose `Q` or shared pole is
        // there cannot see it.
        let mut choices: Vec<[usize; 5]> = Vec::with_capacity(3 * pairs.len());
        for &(_, i, j) in &pairs {
            let mut others = [0; 3];
            for (slot, k) in others.iter_mut().zip((0..5).filter(|&k| k != i && k != j)) {
                *slot = k;
            }
            for r in 0..3 {
                let [a, b] = [(r + 1) % 3, (r + 2) % 3].map(|x| others[x]);
                choices.push([i, j, others[r], a.min(b), a.max(b)]);
            }
        }
        // The Burmester points at coincident poles, verified: a choice must
        // list them (see [`coincident_poles`]).
        let mut required: Vec<Dyad> = Vec::new();
        for g in coincident_poles(&motion) {
            if let Ok(Polished::One(d)) = polish(&motion, g, 1) {
                if concyclic_to_rounding(&motion, &d)
                    && !required.iter().any(|r| same_point(&motion, r, &d))
                {
                    required.push(d);
                }
            }
        }
        let mut any = false;
        // Whether a choice gave its points (without a line of them).
        let mut solved = false;
        // The choices in `order`, the first clean one taken. With
        // `required` points it must list them, and every point within
        // `BURMESTER_NEAR` task sizes that an earlier choice verified (each
        // passed `polish`: it exists, so a choice without it lost it).
        let mut first_clean = |order: &[[usize; 5]], required: &[Dyad]| -> Result<Option<Taken>> {
            let mut verified = 0;
            let mut seen: Vec<Dyad> = required.to_vec();
            for &order in order {
                let sub = LocalMotion::new(&order.map(|x| poses[x]))?;
                let Some(elim) = Elimination::new(&sub) else {
                    continue;
                };
                any = true;
                // A line of common points of the two curves (every point of
                // it a Burmester center) from a later choice, where an
                // earlier one found isolated common points: the line is
                // this choice's rounding, and the task is refused as not
                // resolved (five42: nine frames of the fuzz findings, each
                // with four isolated exact points, were refused as having
                // infinitely many; going on to the next choice instead
                // answered one of them wrongly and refused two right ones).
                // Where the points are not isolated, every choice that is
                // not skipped finds the line.
                let (points, mut sliders, lost, distinct) = match elim.points(&sub, &motion) {
                    Ok(found) => {
                        solved = true;
                        found
                    }
                    Err(Error::Degenerate(DegenerateError::InfinitelyManyBurmesterPoints {
                        ..
                    })) if solved => {
                        return Err(errors::unresolved(
                            "a choice of the shared poses finds a line of common points of the \
                             center-point curves where an earlier one finds isolated points: \
                             the line is its rounding",
                        ));
                    }
                    Err(e) => return Err(e),
                };
                // With three distinct near points verified (each passed
                // `polish`), at most one more Burmester point exists: a far
                // root read both as a finite point and as a slider (the far
                // point's center along the slider's direction, its circle
                // point the slider's) is that one point, and the slider its
                // rounding (issue 24, five40). With fewer near points the
                // slider stands (a far point and a point at infinity in
                // nearly one direction: fuzz findings `08aa7d92`,
                // `47fa849a`).
                if distinct + 1 == MAX_POINTS && points.len() + sliders.len() > MAX_POINTS {
                    sliders.retain(|s| !points.iter().any(|d| far_point_of_slider(&motion, d, s)));
                }
                // Two cubics meet in nine points: `Q`, `P13`, `P23`, the
                // two circular points and at most four Burmester points.
                // More (double roots of the resultant declared within a
                // band wide enough to hold several critical points, or one
                // root read as a finite point and a slider) is this
                // elimination's rounding, not an answer.
                let total = points.len() + sliders.len();
                if total > MAX_POINTS {
                    continue;
                }
                let near = near_count(&motion, &points);
                if lost == 0
                    && total % 2 == 0
                    && near >= verified
                    && seen
                        .iter()
                        .all(|r| points.iter().any(|d| same_point(&motion, r, d)))
                {
                    return Ok(Some((order, points, sliders)));
                }
                verified = verified.max(distinct);
                if !required.is_empty() {
                    for d in &points {
                        if is_near(&motion, d.center)
                            && !seen.iter().any(|r| same_point(&motion, r, d))
                        {
                            seen.push(*d);
                        }
                    }
                }
            }
            Ok(None)
        };
        // Every choice as before; where the answer lacks a point at
        // coincident poles, the choices again with those blind to such a
        // point last (its `Q` or a shared pole there: the point is `Q`, a
        // double common point, or taken out as the pole), the one taken
        // listing them all and every near point an earlier one verified
        // (else the answer as before). Only where the answer lacks one: a
        // choice whose `Q` or shared pole is at the point and which lists
        // it anyway stands (the choices after it read a complex pair near
        // the real plane as two points, or a far point as a slider, on fuzz
        // findings `c268f9be`, `70ea2d4f`, `6e2bbf64`).
        let at: Vec<Vector2<f64>> = required.iter().map(|d| motion.local_of(d.center)).collect();
        let blind = |o: &[usize; 5]| {
            [(o[0], o[1]), (o[0], o[2]), (o[1], o[2])]
                .iter()
                .filter_map(|&(a, b)| finite(motion.pole(a, b)))
                .any(|x| {
                    at.iter()
                        .any(|p| (x - p).norm() <= POLE_MATCH * (1.0 + x.norm()))
                })
        };
        let mut taken = first_clean(&choices, &[])?;
        let mut lacking = false;
        let redo = !required.is_empty()
            && taken.as_ref().is_none_or(|(_, p, _)| {
                required
                    .iter()
                    .any(|r| !p.iter().any(|d| same_point(&motion, r, d)))
            });
        // A blind choice that lists the points at coincident poles may
        // have lost a pair of others with them (its count even): the
        // choices again with the blind ones last, taken only where that
        // answer lists more points within `BURMESTER_NEAR` task sizes (each
        // verified by `polish`), so that no point is lost.
        let blind_taken =
            !required.is_empty() && !redo && taken.as_ref().is_some_and(|(o, _, _)| blind(o));
        if redo || blind_taken {
            let mut seeing = choices.clone();
            seeing.sort_by_key(blind);
            if let Some(t) = first_clean(&seeing, &required)? {
                let more = taken
                    .as_ref()
                    .is_none_or(|(_, p, _)| near_count(&motion, &t.1) > near_count(&motion, p));
                if redo || more {
                    taken = Some(t);
                }
            } else if redo {
                // No choice lists them: the first answer lacks a point that
                // exists (it passed `polish` and the concyclic test), and it
                // was given anyway. Fuzz findings `1491101c` moved (the
                // point at `Q` of the only choice left, two poses at one
                // position: a double point listed in place of the two) and
                // `76e9fa53` moved (a near point and the far one at
                // coincident poles lost together), both answered by a
                // choice admitted by five41's measurement of the angles'
                // rounding, and refused before it. Loosely: a point within
                // `1e-2` of `size + d` of it (the closeness of `agrees`),
                // or a slider it is the far reading of, lists it. The
                // points at coincident poles are polished from the poles,
                // and at `DOUBLE_REACH` four right answers were refused
                // (a far point listed `7e-6` of `size + d` off it,
                // `2e0c2d74` moved; a near one `1.3e-3` off, where `polish`
                // stayed at the pole, `24fd0b38`).
                lacking = taken.as_ref().is_some_and(|(_, p, s)| {
                    required.iter().any(|r| {
                        let reach = motion.scale + (r.center - motion.origin).norm();
                        !p.iter()
                            .any(|d| (d.center - r.center).norm() <= 1e-2 * reach)
                            && !s.iter().any(|s| far_point_of_slider(&motion, r, s))
                    })
                });
            }
        }
        let taken = taken.map(|(_, p, s)| (p, s));
        if !any {
            // Every choice vanished within its rounding. Two poses that
            // nearly coincide make the two curves of every choice nearly
            // one curve (the choice sharing the other three poses) or
            // leave one of them only the digits of their difference: the
            // points may well be isolated (a crank-rocker's poses at crank
            // angles `1e-7` rad apart have two), and the rounding decides.
            if close_pair(
                &motion.poses,
                motion.scale,
                tolerance::NEARLY_COINCIDENT_POSES,
            )
            .is_some()
            {
                return Err(errors::unresolved(
                    "two poses nearly coincide (their points within 1e-4 of the task's size and \
                     their angles within 1e-4 rad), and every elimination vanishes within its \
                     rounding: the rounding decides whether the Burmester points are isolated; \
                     move those poses apart",
                ));
            }
            return Err(errors::infinitely_many(
                "the center-point curves of every two four-pose subsets that share three poses \
                 have a common component (a curve of Burmester centers, or the line at \
                 infinity: a family of sliders)",
            ));
        }
        let Some((mut points, sliders)) = taken else {
            // Poses given far from the origin for their size carry the
            // rounding of their coordinates (`eps` of them), which can
            // decide two nearly merging points (real, or a complex pair):
            // say so, and what to change.
            return Err(errors::unresolved(
                if motion.data_rounding.0 > tolerance::BURMESTER_FAR_FRAME {
                    "from every choice of the shared poses a root of the elimination gives no \
                     Burmester point, or the count with multiplicity is odd or above four, or \
                     below what a better conditioned choice verified; the poses lie far from \
                     the origin for their size, and the rounding of their coordinates decides \
                     these points: give them relative to a point near the task (such as its \
                     centroid)"
                } else {
                    "from every choice of the shared poses a root of the elimination gives no \
                     Burmester point, or the count with multiplicity is odd or above four, or \
                     below what a better conditioned choice verified"
                },
            ));
        };
        refined(&motion, &mut points);
        points.sort_by(|a, b| {
            (a.center - motion.origin)
                .norm()
                .total_cmp(&(b.center - motion.origin).norm())
        });
        let curve = |rows: [usize; 3]| {
            let (f, _) = motion.form.cubic(rows);
            Cubic::from_local(f, motion.origin, motion.scale)
        };
        let curves = [curve([1, 2, 3]), curve([1, 2, 4])];
        let none = Point2::origin();
        Ok((
            FivePositions {
                motion,
                points: PerPose::up_to(&points, Dyad::new(none, none)),
                sliders: PerPose::up_to(
                    &sliders,
                    BurmesterSlider {
                        circle: none,
                        direction: Vector2::zeros(),
                    },
                ),
                curves,
            },
            lacking,
        ))
    }

    /// The five poses.
    pub fn poses(&self) -> &[Pose] {
        &self.motion.poses
    }

    /// The size of the task (the largest distance of a pose point from
    /// their centroid), the unit of the relative tolerances.
    pub fn size(&self) -> f64 {
        self.motion.scale
    }

    /// The real Burmester points with a finite center, as dyads (center
    /// point, circle point at pose 1), nearest the task first.
    ///
    /// With the [`sliders`](Self::sliders) (the Burmester points at
    /// infinity) they number 0, 2 or 4: a double point (two points that
    /// merge, or a pair of complex points, within the rounding of the
    /// elimination: see the type's docs) is listed twice, as two equal
    /// dyads. So five poses with collinear positions (whose reference point
    /// is a slider) have 1 or 3 finite points and one slider. The count
    /// does not depend on the frame the poses are given in.
    pub fn burmester_points(&self) -> &[Dyad] {
        &self.points
    }

    /// The real Burmester points at infinity (a double one listed twice):
    /// the circle points whose five positions are collinear (see
    /// [`burmester_points`](Self::burmester_points) for the count).
    pub fn sliders(&self) -> &[BurmesterSlider] {
        &self.sliders
    }

    /// The center-point curves of poses `1, 2, 3, 4` and `1, 2, 3, 5`: the
    /// Burmester centers are their common points other than `P12, P13,
    /// P23`.
    pub fn center_point_curves(&self) -> [Cubic; 2] {
        self.curves
    }

    /// `D_ij(z)` (1-based `i`, `j`).
    ///
    /// # Errors
    ///
    /// [`crate::InvalidInput::PoseIndex`] when `i` or `j` is not 1 to 5.
    pub fn displace(&self, z: Point2<f64>, i: usize, j: usize) -> Result<Point2<f64>> {
        for k in [i, j] {
            if !(1..=5).contains(&k) {
                return Err(errors::pose_index(k, 5));
            }
        }
        Ok(self.motion.displace(z, i - 1, j - 1))
    }

    /// The relative spread of the crank length of `dyad` over the five
    /// poses: `(max - min) / max` of `|D_1k(circle) - center|`. Zero (to
    /// rounding) for a Burmester point.
    pub fn residual(&self, dyad: &Dyad) -> f64 {
        residual(&self.motion, dyad)
    }

    /// The four-bars of every pair of Burmester points (up to six), each
    /// classified for both choices of the driving dyad. A pair whose
    /// linkage cannot be built (a link of zero length) is left out.
    pub fn four_bars(&self) -> Vec<BurmesterFourBar> {
        let mut out = Vec::new();
        for a in 0..self.points.len() {
            for b in a + 1..self.points.len() {
                let (p, q) = (&self.points[a], &self.points[b]);
                if let (Ok(d1), Ok(d2)) = (drive(&self.motion, p, q), drive(&self.motion, q, p)) {
                    out.push(BurmesterFourBar {
                        indices: [a, b],
                        drives: [d1, d2],
                    });
                }
            }
        }
        out
    }

    /// The four-bar of two dyads of the five poses.
    ///
    /// # Errors
    ///
    /// As [`super::FourPositions::drive`].
    pub fn drive(&self, driving: &Dyad, driven: &Dyad) -> Result<Drive> {
        drive(&self.motion, driving, driven)
    }
}

/// `(max - min) / max` of the crank lengths over the poses.
fn residual(m: &LocalMotion, dyad: &Dyad) -> f64 {
    spread((0..m.poses.len()).map(|k| (m.displace(dyad.circle, 0, k) - dyad.center).norm()))
}

/// `(max - min) / max` of the crank lengths `d` (infinite when all vanish).
fn spread(d: impl Iterator<Item = f64>) -> f64 {
    let (min, max) = d.fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if max > 0.0 {
        (max - min) / max
    } else {
        f64::INFINITY
    }
}

/// A choice of the shared poses taken (the order of the poses) and its
/// Burmester points and sliders.
type Taken = ([usize; 5], Vec<Dyad>, Vec<BurmesterSlider>);

/// The points where two poles of disjoint pairs of poses coincide (within
/// [`POLE_MATCH`], local): `P_ab = P_cd` is a Burmester center (the
/// rotations `a -> b` and `c -> d` about it leave two conditions on the
/// circle point, which meet), found by no elimination from `Q = P_ab` or
/// with `P_ab` for a shared pole: there it is `Q` itself, or taken out as
/// the pole. (Two pairs of poses at one position each, half a turn apart:
/// `P13 = P24`, a Burmester point that the first choices, each blind to it,
/// left out with an even count; five37, `a3403902`, `beafcbe6`,
/// `ce022d68`.)
fn coincident_poles(m: &LocalMotion) -> Vec<Vector2<f64>> {
    let mut poles = [([0usize; 2], None::<Vector2<f64>>); 10];
    let mut n = 0;
    for a in 0..5 {
        for b in a + 1..5 {
            poles[n] = ([a, b], finite(m.pole(a, b)));
            n += 1;
        }
    }
    let mut out = Vec::new();
    for (n, (p, x)) in poles.iter().enumerate() {
        for (q, y) in &poles[n + 1..] {
            let disjoint = p.iter().all(|i| !q.contains(i));
            if let (true, Some(x), Some(y)) = (disjoint, x, y) {
                if (x - y).norm() <= POLE_MATCH * (1.0 + x.norm()) {
                    out.push((x + y) * 0.5);
                }
            }
        }
    }
    out
}

/// Whether the dyad (global) is concyclic to the rounding of its local
/// coordinates ([`tolerance::BURMESTER_ROUNDING`] `eps` over the crank),
/// not merely within [`polish`]'s looser far-point allowance: a point at
/// nearly coincident poles that is not a Burmester point (the two lines of
/// its circle point nearly parallel) passed that allowance and was required
/// of every choice (fuzz findings `78b52e02`, `6e2bbf64`, `499481c1`).
fn concyclic_to_rounding(m: &LocalMotion, d: &Dyad) -> bool {
    let (g, z) = (m.local_of(d.center), m.local_of(d.circle));
    let positions: Vec<Vector2<f64>> = (0..m.poses.len()).map(|k| m.form.displace(k, z)).collect();
    let radius = positions.iter().map(|p| (p - g).norm()).fold(0.0, f64::max);
    let coords = positions.iter().map(|p| p.norm()).fold(g.norm(), f64::max);
    radius > 0.0
        && local_residual(m, g, z)
            <= tolerance::BURMESTER_ROUNDING * f64::EPSILON * (1.0 + coords / radius)
}

/// A homogeneous local point (such as [`LocalMotion::pole`]) as a local
/// point; `None` at infinity.
fn finite(h: [f64; 3]) -> Option<Vector2<f64>> {
    (h[2] != 0.0).then(|| Vector2::new(h[0] / h[2], h[1] / h[2]))
}

/// Whether a center (global) lies within [`tolerance::BURMESTER_NEAR`]
/// task sizes of the poses' centroid.
fn is_near(m: &LocalMotion, center: Point2<f64>) -> bool {
    (center - m.origin).norm() <= tolerance::BURMESTER_NEAR * m.scale
}

/// How many of `points` have their centers [`is_near`].
fn near_count(m: &LocalMotion, points: &[Dyad]) -> usize {
    points.iter().filter(|d| is_near(m, d.center)).count()
}

/// Whether two Burmester points (global) are one: their centers within
/// [`DOUBLE_REACH`] of `size + distance` (each polished by Newton's
/// method to rounding; two points that close are one for [`polish`] too).
fn same_point(m: &LocalMotion, a: &Dyad, b: &Dyad) -> bool {
    let d = (a.center - m.origin).norm();
    (a.center - b.center).norm() <= DOUBLE_REACH * (m.scale + d)
}

/// Three poses that make the Burmester points of five degenerate: three
/// rotations about one point (their three poles coincide), or three poses
/// of one angle with collinear positions
/// ([`LocalMotion::collinear_translations`]).
fn degenerate_triples(m: &LocalMotion) -> Result<()> {
    for i in 0..5 {
        for j in i + 1..5 {
            for k in j + 1..5 {
                let poles = [m.pole(i, j), m.pole(i, k), m.pole(j, k)].map(finite);
                if let [Some(a), Some(b), Some(c)] = poles {
                    let size = 1.0 + a.norm().max(b.norm()).max(c.norm());
                    let spread = (a - b).norm().max((a - c).norm()).max((b - c).norm());
                    if spread <= tolerance::BURMESTER_COMMON_POLE * size {
                        return Err(errors::rotations_about_one_point(
                            [i + 1, j + 1, k + 1],
                            m.global_of((a + b + c) / 3.0),
                        ));
                    }
                }
            }
        }
    }
    if let Some(t) = m.collinear_translations() {
        return Err(errors::collinear_translations(t.map(|k| k + 1)));
    }
    Ok(())
}

/// A binary form with a first-order bound on its rounding error, in units
/// of `eps`: per coefficient, a nonnegative form `e` such that the value at
/// `w` is off by at most about `eps e(|w|)` (the inputs' own rounding scales
/// carried through the products and differences, and the rounding of each
/// operation).
#[derive(Debug, Clone)]
struct Bounded {
    v: Vec<f64>,
    e: Vec<f64>,
}

impl Bounded {
    fn abs(&self) -> Vec<f64> {
        self.v.iter().map(|x| x.abs()).collect()
    }

    fn mul(&self, o: &Bounded) -> Bounded {
        let (a, b) = (self.abs(), o.abs());
        let first = form_mul(&a, &o.e);
        let second = form_mul(&self.e, &b);
        let terms = form_mul(&a, &b);
        Bounded {
            v: form_mul(&self.v, &o.v),
            e: (0..first.len())
                .map(|i| first[i] + second[i] + terms[i])
                .collect(),
        }
    }

    fn sub(&self, o: &Bounded) -> Bounded {
        Bounded {
            v: form_sub(&self.v, &o.v),
            e: (0..self.v.len())
                .map(|i| self.e[i] + o.e[i] + self.v[i].abs() + o.v[i].abs())
                .collect(),
        }
    }

    /// The form in coordinates turned by the angle whose cosine and sine
    /// are `(c, s)`: `f'(w') = f(rot w')`, with its bound carried through
    /// (the magnitudes, and the rounding of the turn: `eps` of each term
    /// per factor).
    fn rotated(&self, c: f64, s: f64) -> Bounded {
        let n = self.v.len();
        let turn = |f: &[f64], x: [f64; 2], y: [f64; 2]| {
            let mut out = vec![0.0; n];
            for (i, &coef) in f.iter().enumerate() {
                let mut term = vec![coef];
                for _ in 0..n - 1 - i {
                    term = form_mul(&term, &x);
                }
                for _ in 0..i {
                    term = form_mul(&term, &y);
                }
                for (o, t) in out.iter_mut().zip(&term) {
                    *o += t;
                }
            }
            out
        };
        let (ac, as_) = (c.abs(), s.abs());
        let grown: Vec<f64> = self
            .e
            .iter()
            .zip(&self.v)
            .map(|(e, v)| e + n as f64 * v.abs())
            .collect();
        Bounded {
            v: turn(&self.v, [c, -s], [s, c]),
            e: turn(&grown, [ac, as_], [as_, ac]),
        }
    }

    /// The value at `w` and its error bound (in units of `eps`, with the
    /// rounding of the evaluation).
    fn at(&self, w: Vector2<f64>) -> (f64, f64) {
        self.at_powers(&Powers::of(w))
    }

    /// [`Bounded::at`] from the powers of `w`: the same arithmetic as
    /// [`form_eval`] on the values, the bound and the magnitudes, without
    /// allocating (as [`Elimination::resultant_at`] evaluates the six forms
    /// from [`Fixed`], some 440 times per elimination on the notes' worked
    /// example: the bisection on the accurate value).
    fn at_powers(&self, p: &Powers) -> (f64, f64) {
        match (self.v.as_slice(), self.e.as_slice()) {
            ([v0, v1], [e0, e1]) => p.at([*v0, *v1], [*e0, *e1]),
            ([v0, v1, v2], [e0, e1, e2]) => p.at([*v0, *v1, *v2], [*e0, *e1, *e2]),
            ([v0, v1, v2, v3], [e0, e1, e2, e3]) => {
                p.at([*v0, *v1, *v2, *v3], [*e0, *e1, *e2, *e3])
            }
            // Not one of the six forms (of degree 1 to 3).
            _ => {
                let (x, y, ax, ay) = (p.x[1], p.y, p.ax[1], p.ay);
                (
                    form_eval(&self.v, x, y),
                    form_eval(&self.e, ax, ay) + form_eval(&self.abs(), ax, ay),
                )
            }
        }
    }
}

/// The six forms of an [`Elimination`] as arrays of their lengths
/// (`(values, bounds)`): `a, d`, `b, e` and `c, g`.
struct Fixed {
    cubic: [([f64; 4], [f64; 4]); 2],
    quadratic: [([f64; 3], [f64; 3]); 2],
    linear: [([f64; 2], [f64; 2]); 2],
}

impl Fixed {
    fn of([a, b, c, d, e, g]: [&Bounded; 6]) -> Self {
        fn arr<const N: usize>(f: &Bounded) -> ([f64; N], [f64; N]) {
            let take = |x: &[f64]| core::array::from_fn(|i| x.get(i).copied().unwrap_or(0.0));
            (take(&f.v), take(&f.e))
        }
        Fixed {
            cubic: [arr(a), arr(d)],
            quadratic: [arr(b), arr(e)],
            linear: [arr(c), arr(g)],
        }
    }
}

/// The powers `1, x, x^2, x^3` of a direction's first coordinate and of its
/// magnitude, as `powi` forms them (so that [`Bounded::at_powers`] agrees
/// with [`form_eval`] to the bit), and the second coordinate and its
/// magnitude.
struct Powers {
    x: [f64; 4],
    y: f64,
    ax: [f64; 4],
    ay: f64,
}

impl Powers {
    /// A form of `N` coefficients `v` with bound `e` at the direction:
    /// [`form_eval`]'s sums, term by term in its order.
    #[inline]
    fn at<const N: usize>(&self, v: [f64; N], e: [f64; N]) -> (f64, f64) {
        let eval = |f: [f64; N], x: &[f64; 4], y: f64| {
            let mut acc = 0.0;
            let mut py = 1.0;
            for (i, c) in f.into_iter().enumerate() {
                acc += c * x[N - 1 - i] * py;
                py *= y;
            }
            acc
        };
        (
            eval(v, &self.x, self.y),
            eval(e, &self.ax, self.ay) + eval(v.map(f64::abs), &self.ax, self.ay),
        )
    }

    fn of(w: Vector2<f64>) -> Self {
        let pw = |x: f64| {
            let x2 = x * x;
            [1.0, x, x2, x * x2]
        };
        Powers {
            x: pw(w.x),
            y: w.y,
            ax: pw(w.x.abs()),
            ay: w.y.abs(),
        }
    }
}

/// The resultant `R(w) = (a g - c d)^2 - (a e - b d)(b g - c e)` of the
/// forms `a, b, c, d, e, g`, with its rounding bound.
fn resultant([a, b, c, d, e, g]: [&Bounded; 6]) -> Bounded {
    let agcd = a.mul(g).sub(&c.mul(d));
    let aebd = a.mul(e).sub(&b.mul(d));
    let bgce = b.mul(g).sub(&c.mul(e));
    agcd.mul(&agcd).sub(&aebd.mul(&bgce))
}

/// The normal `(alpha, beta)` of a circular cubic's real asymptotic
/// direction from the coefficients of its cubic part
/// `(x^2 + y^2)(alpha x + beta y)` (`x^3, x^2 y, x y^2, y^3`).
fn cubic_normal(v: &[f64]) -> Vector2<f64> {
    Vector2::new(0.5 * (v[0] + v[2]), 0.5 * (v[1] + v[3]))
}

/// Whether a value is zero within the rounding band of its bound.
fn negligible(v: f64, bound: f64) -> bool {
    v.abs() <= tolerance::BURMESTER_EPS * f64::EPSILON * bound
}

/// A shared pole of the two cubics other than `Q`: a point (local) or a
/// direction at infinity.
#[derive(Debug, Clone, Copy)]
enum SharedPole {
    At(Vector2<f64>),
    Infinite(Vector2<f64>),
}

/// A common point of the two cubics found along a line from `Q`: a point
/// (local) with the rounding of its distance from `Q` (local units; zero
/// where not bounded), or a direction at infinity.
#[derive(Debug, Clone, Copy)]
enum Common {
    At(Vector2<f64>, f64),
    Infinite(Vector2<f64>),
}

/// The elimination of the Burmester centers of five poses from the
/// center-point curves `f` of poses `1, 2, 3, 4` and `h` of poses
/// `1, 2, 3, 5` (of the ordered `sub`), along the lines through their
/// common point `Q = P12` (see [`FivePositions`]), with the rounding bound
/// of every form.
struct Elimination {
    q: Vector2<f64>,
    /// `a, b, c` of `f` and `d, e, g` of `h` along the line `Q + t w`.
    forms: [Bounded; 6],
    /// The same forms' values and bounds in arrays of their lengths (`a, d`
    /// cubic, `b, e` quadratic, `c, g` linear), for
    /// [`Elimination::resultant_at`].
    fixed: Fixed,
    /// The resultant `R(w)`.
    r: Bounded,
    /// `P13` and `P23`.
    poles: [SharedPole; 2],
    /// The real asymptotic direction the two curves share (within
    /// rounding), if any: a common point at infinity.
    asymptote: Option<Vector2<f64>>,
}

impl Elimination {
    /// The elimination for `sub`; `None` when the resultant vanishes
    /// identically within its rounding (the curves share a component not
    /// through `Q`, or a conic through it), or the cubic part of a curve
    /// does (the line at infinity is a component of it).
    fn new(sub: &LocalMotion) -> Option<Self> {
        Self::build(sub, true)
    }

    /// [`Self::new`] where `checked`; unchecked, a resultant that vanishes
    /// within the inputs' rounding is kept (the tasks that
    /// [`Self::angles_move`] builds to measure it).
    fn build(sub: &LocalMotion, checked: bool) -> Option<Self> {
        let th = wrap_angle(sub.theta[1] - sub.theta[0]);
        let (sn, cs) = (0.5 * th).sin_cos();
        if sn == 0.0 {
            return None;
        }
        let mid = (sub.pos[0] + sub.pos[1]) * 0.5;
        let half = (sub.pos[1] - sub.pos[0]) * 0.5;
        let cot = cs / sn;
        let q = mid + perp(half) * cot;
        // The rounding scale of `Q` (in units of eps): the midpoint, and the
        // cotangent of the half angle times the half chord.
        let dq = 4.0 * (mid.norm() + half.norm() * (cot.abs() + th.abs() / (2.0 * sn * sn)));
        // The inputs' own rounding in this frame (a point's coordinates are
        // known to half an ulp, an angle too): carried with the rounding of
        // the coefficients, so that what is decided within rounding (a
        // double root, a common point at infinity, a resultant that
        // vanishes) is decided alike for the task moved, turned or scaled.
        let (dp, da) = sub.data_rounding;
        let at_q = |rows: [usize; 3], with_data: bool, angles: bool| -> [Bounded; 3] {
            let (c, m) = sub.form.cubic_bounds(rows);
            let da = if angles { da } else { 0.0 };
            let data = sub.form.cubic_data_bounds(rows, sub.pos[0], dp, da);
            let top = c.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            let top = if top > 0.0 && top.is_finite() {
                top
            } else {
                1.0
            };
            let w = if with_data { 1.0 } else { 0.0 };
            let m: [f64; 10] = core::array::from_fn(|i| (m[i] + w * data[i]) / top);
            let c = c.map(|v| v / top);
            let (x, y) = (q.x, q.y);
            let (ax, ay) = (x.abs(), y.abs());
            let g = grad(&c, x, y);
            let h = hess(&c, x, y);
            // The error scale of each coefficient: its own rounding (the
            // expansion in magnitudes) and that of the evaluation.
            let ca = c.map(f64::abs);
            let cm: [f64; 10] = core::array::from_fn(|i| m[i] + ca[i]);
            let gm0 = grad(&cm, ax, ay);
            let hm0 = hess(&cm, ax, ay);
            // And `Q`'s rounding, through the next derivative.
            let third = [
                6.0 * cm[6] + 2.0 * cm[7],
                2.0 * cm[7] + 2.0 * cm[8],
                2.0 * cm[8] + 6.0 * cm[9],
            ];
            let hm = [0, 1, 2].map(|i| hm0[i] + third[i] * dq);
            let gm = [
                gm0[0] + (hm0[0] + hm0[1]) * dq,
                gm0[1] + (hm0[1] + hm0[2]) * dq,
            ];
            [
                Bounded {
                    v: vec![c[6], c[7], c[8], c[9]],
                    e: vec![m[6], m[7], m[8], m[9]],
                },
                Bounded {
                    v: vec![0.5 * h[0], h[1], 0.5 * h[2]],
                    e: vec![0.5 * hm[0], hm[1], 0.5 * hm[2]],
                },
                Bounded {
                    v: g.to_vec(),
                    e: gm.to_vec(),
                },
            ]
        };
        // The forms with the rounding of the computation, which decides the
        // roots (a double root where the resultant touches zero within it),
        // and with the inputs' rounding too, which decides what must not
        // depend on the frame: a resultant that vanishes, a common point at
        // infinity.
        let [a, b, c] = at_q([1, 2, 3], false, false);
        let [d, e, g] = at_q([1, 2, 4], false, false);
        let [ad, bd, cd] = at_q([1, 2, 3], true, true);
        let [dd, ed, gd] = at_q([1, 2, 4], true, true);
        let r = resultant([&a, &b, &c, &d, &e, &g]);
        let rd = resultant([&ad, &bd, &cd, &dd, &ed, &gd]);
        let within = |b: &Bounded| {
            b.v.iter()
                .zip(&b.e)
                .all(|(v, e)| negligible(*v, *e + v.abs()))
        };
        // The bound of the inputs' rounding above is first order in each
        // coefficient from the magnitudes of its terms. For the angles
        // (known to `eps` of the largest: `100` rad given, `1.4e-14`) it
        // exceeds by far what their rounding moves the resultant where a
        // curve's terms cancel (its cubic `5e-6` of them: two pairs of
        // poses of nearly one angle, three poses nearly rotations about
        // one point): fuzz finding `33fcbf9c` moved, the bound `1e-5`, the
        // resultant `3e-8`, and the task with every input moved at random
        // within its rounding moved it by at most `1.4e-15`. Every well
        // conditioned choice was skipped and the answer lost both points
        // (five41). So where the bound of the positions' rounding alone
        // leaves the resultant standing, the angles' rounding is measured:
        // each angle moved alone by it, the changes added up. `measured`:
        // the cubic parts with the positions' rounding, and how far the
        // angles' rounding moves the two curves' asymptotic normals.
        let measured = if checked && within(&rd) {
            // The positions' rounding as before, the angles' measured.
            let [[ap, bp, cp], [dp, ep, gp]] =
                [[1, 2, 3], [1, 2, 4]].map(|rows| at_q(rows, true, false));
            let rp = resultant([&ap, &bp, &cp, &dp, &ep, &gp]);
            if within(&rp) {
                return None;
            }
            let (moved, normals) = Self::angles_move(sub, &r.v, [&a, &d])?;
            let vanishes = rp.v.iter().zip(&rp.e).zip(&moved).all(|((v, e), m)| {
                v.abs() <= tolerance::BURMESTER_EPS * (f64::EPSILON * (e + v.abs()) + m)
            });
            if vanishes {
                return None;
            }
            Some((ap, dp, normals))
        } else {
            None
        };
        if r.v.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let shared = |j: usize, k: usize| {
            let h = sub.pole(j, k);
            match finite(h) {
                Some(p) => SharedPole::At(p),
                None => {
                    let d = Vector2::new(h[0], h[1]);
                    SharedPole::Infinite(d / d.norm())
                }
            }
        };
        // The cubic part of a circular cubic is `(x^2 + y^2)(alpha x + beta y)`:
        // its real asymptotic direction is normal to `(alpha, beta)`.
        let normal = |k: &Bounded| {
            let v = cubic_normal(&k.v);
            let e = Vector2::new(
                0.5 * (k.e[0] + k.e[2] + k.v[0].abs() + k.v[2].abs()),
                0.5 * (k.e[1] + k.e[3] + k.v[1].abs() + k.v[3].abs()),
            );
            (v, e)
        };
        // Where the angles' rounding was measured, the common asymptotic
        // direction is decided with it too: the magnitude bound that called
        // the resultant zero also called the two curves' normals parallel,
        // and a far point was read as a slider (fuzz findings `1c3f2c56`,
        // `5112b39f` moved, `4.3e3` and `770` task sizes out: a point and a
        // slider where the exact task has two points; `1b251dfd` moved,
        // five42).
        let ((nf, ef), (nh, eh)) = match &measured {
            Some((ap, dp, [mf, mh])) => {
                let ((nf, ef), (nh, eh)) = (normal(ap), normal(dp));
                ((nf, ef + mf / f64::EPSILON), (nh, eh + mh / f64::EPSILON))
            }
            None => (normal(&ad), normal(&dd)),
        };
        // A curve whose cubic part is zero within rounding has the line at
        // infinity for a component (every direction a slider's): this
        // choice is degenerate.
        if [(nf, ef), (nh, eh)]
            .iter()
            .any(|(n, e)| negligible(n.x, e.x) && negligible(n.y, e.y))
        {
            return None;
        }
        let common = negligible(
            cross(nf, nh),
            nf.x.abs() * eh.y + ef.x * nh.y.abs() + nf.y.abs() * eh.x + ef.y * nh.x.abs(),
        );
        let n = if nf.norm() >= nh.norm() { nf } else { nh };
        let asymptote = (common && n.norm() > 0.0).then(|| perp(n) / n.norm());
        Some(Elimination {
            q,
            fixed: Fixed::of([&a, &b, &c, &d, &e, &g]),
            forms: [a, b, c, d, e, g],
            r,
            poles: [shared(0, 2), shared(1, 2)],
            asymptote,
        })
    }

    /// How far the rounding of `sub`'s angles moves the coefficients of
    /// its resultant (`base`, as [`Self::build`] forms it) and the
    /// asymptotic normals of its two curves (of their cubic parts `cubic`,
    /// [`cubic_normal`]), to first order: each pose's angle moved alone by
    /// the angles' rounding (`data_rounding`: twice `eps` of the largest
    /// angle), the elimination built again and the changes added up (per
    /// coordinate for the normals). `None` where a moved task has no
    /// elimination.
    #[allow(clippy::type_complexity)]
    fn angles_move(
        sub: &LocalMotion,
        base: &[f64],
        cubic: [&Bounded; 2],
    ) -> Option<(Vec<f64>, [Vector2<f64>; 2])> {
        let poses = sub.poses.as_slice();
        let da = sub.data_rounding.1 * f64::EPSILON;
        let mut moved = vec![0.0; base.len()];
        let mut normals = [Vector2::zeros(); 2];
        for k in 0..poses.len() {
            let q = PerPose::from_fn(poses.len(), |j| {
                let mut p = poses[j];
                if j == k {
                    p.angle += da;
                }
                p
            });
            let m = LocalMotion::new(q.as_slice()).ok()?;
            let other = Self::build(&m, false)?;
            if other.r.v.len() != moved.len() {
                return None;
            }
            for (s, (a, b)) in moved.iter_mut().zip(other.r.v.iter().zip(base)) {
                *s += (a - b).abs();
            }
            for (n, (o, b)) in normals
                .iter_mut()
                .zip([&other.forms[0], &other.forms[3]].into_iter().zip(cubic))
            {
                *n += (cubic_normal(&o.v) - cubic_normal(&b.v)).abs();
            }
        }
        Some((moved, normals))
    }

    /// The Burmester points and sliders of this elimination (`motion` the
    /// task's own), each finished on the four circle equations and checked
    /// ([`polish`]), with the count with multiplicity of the roots that gave
    /// none (lost) and the count of distinct finite points found within
    /// [`tolerance::BURMESTER_NEAR`] task sizes (a double point listed twice
    /// counts once: only its place is verified; a far point or a slider may
    /// be the rounding of a complex pair or of each other).
    fn points(
        &self,
        sub: &LocalMotion,
        motion: &LocalMotion,
    ) -> Result<(Vec<Dyad>, Vec<BurmesterSlider>, usize, usize)> {
        let (finite, infinite) = self.solve()?;
        let mut points = Vec::new();
        let mut lost = 0;
        let mut distinct = 0;
        // Two roots of the resultant are two directions from `Q`: they
        // cannot be one Burmester point. A point that another root already
        // gave (closer than a split pair may be) is that root's, and this
        // root gave none.
        let known = |points: &[Dyad], d: &Dyad| {
            let near = 0.5 * DOUBLE_REACH * (motion.scale + (d.center - motion.origin).norm());
            points.iter().any(|p| (p.center - d.center).norm() <= near)
        };
        let near = |d: &Dyad| is_near(motion, d.center);
        for (g0, mult) in finite {
            let g0 = motion.local_of(sub.global_of(g0));
            match polish(motion, g0, mult)? {
                Polished::One(dyad) if !known(&points, &dyad) => {
                    distinct += usize::from(near(&dyad));
                    points.extend(core::iter::repeat_n(dyad, mult));
                }
                Polished::Pair(a, b) if !known(&points, &a) && !known(&points, &b) => {
                    distinct += usize::from(near(&a)) + usize::from(near(&b));
                    points.extend([a, b]);
                }
                // A pair of complex points: no real point, none lost.
                Polished::Complex => {}
                // One simple point: once, its other multiplicity not real.
                Polished::Simple(dyad) if !known(&points, &dyad) => {
                    distinct += usize::from(near(&dyad));
                    points.push(dyad);
                }
                _ => lost += mult,
            }
        }
        let mut sliders = Vec::new();
        for (u, mult) in infinite {
            let slider = motion
                .form
                .solve_at_infinity(u, &[1, 2, 3, 4])
                .ok()
                .and_then(|z| check_slider(motion, z, u));
            match slider {
                Some(s) => sliders.extend(core::iter::repeat_n(s, mult)),
                None => lost += mult,
            }
        }
        Ok((points, sliders, lost, distinct))
    }

    /// The resultant at `w` from the forms' values there (more accurate
    /// than its expanded coefficients, whose terms cancel), and its
    /// rounding band: [`tolerance::BURMESTER_EPS`] `eps` times a
    /// first-order bound on its error (the forms' own errors through the
    /// products, and the rounding of each).
    fn resultant_at(&self, w: Vector2<f64>) -> (f64, f64) {
        let p = Powers::of(w);
        let f = &self.fixed;
        let [a, d] = [0, 1].map(|i| p.at(f.cubic[i].0, f.cubic[i].1));
        let [b, e] = [0, 1].map(|i| p.at(f.quadratic[i].0, f.quadratic[i].1));
        let [c, g] = [0, 1].map(|i| p.at(f.linear[i].0, f.linear[i].1));
        // A product and a difference of `(value, error)` pairs.
        let mul = |x: (f64, f64), y: (f64, f64)| {
            let v = x.0 * y.0;
            (v, x.0.abs() * y.1 + x.1 * y.0.abs() + v.abs())
        };
        let sub = |x: (f64, f64), y: (f64, f64)| {
            let v = x.0 - y.0;
            (v, x.1 + y.1 + v.abs())
        };
        let x = sub(mul(a, g), mul(c, d));
        let y = sub(mul(a, e), mul(b, d));
        let z = sub(mul(b, g), mul(c, e));
        let r = sub(mul(x, x), mul(y, z));
        (r.0, tolerance::BURMESTER_EPS * f64::EPSILON * r.1)
    }

    /// The first part of [`Self::roots_placed`] (tests).
    #[cfg(test)]
    fn roots(&self) -> Vec<(f64, usize)> {
        self.roots_placed().0
    }

    /// First: the real roots of the resultant (angles in `[0, pi)`, with their
    /// multiplicity): those of [`form_roots_mult`] on its expanded
    /// coefficients, and near every root of those coefficients (real, or
    /// complex within [`CLUSTER_WINDOW`] of the real line) again from the
    /// forms turned to put that root at `w = (1, 0)`.
    ///
    /// The expanded coefficients are accurate only relative to their own
    /// size: where several roots crowd within `1e-5` rad of a direction
    /// (Burmester points nearly on one line through `Q`) at `tan` `0.4`
    /// from the chart's axis, the polynomial's terms there cancel to far
    /// below their rounding, its critical points are noise, and two or four
    /// real roots were lost (a task turned by a frame change listed 2 of its
    /// 4 points; given with that line along an axis, all 4). Turned to the
    /// crowd, the low coefficients are the forms' values there, as accurate
    /// as [`Elimination::resultant_at`], so the roots are found alike in
    /// every frame.
    ///
    /// That search again (two eigenvalue problems, six forms turned and a
    /// bisection per window: two thirds of the time of
    /// [`FivePositions::new`] on the notes' worked example, measured with
    /// the forms evaluated without allocating) is done only
    /// where the first answer is in doubt ([`all_found`]): it is skipped
    /// when the first search found six simple roots, each a sign change of
    /// the accurate value, with that value beyond its band between every
    /// two neighbours. Nothing is left then for a crowd to hide.
    ///
    /// Second: the roots among them placed only to their window (angle,
    /// half width: see [`Self::searched_again_keeping`]).
    #[allow(clippy::type_complexity)]
    fn roots_placed(&self) -> (Vec<(f64, usize)>, Vec<(f64, f64)>) {
        let value = |wx: f64, wy: f64| self.resultant_at(Vector2::new(wx, wy));
        let roots = form_roots_mult(&self.r.v, &value);
        if all_found(&roots, &value) {
            return (roots, Vec::new());
        }
        let mut kept = Vec::new();
        let roots = self.searched_again_keeping(roots, &mut kept);
        (roots, kept)
    }

    /// [`Self::searched_again_keeping`] without the kept roots (tests).
    #[cfg(test)]
    fn searched_again(&self, roots: Vec<(f64, usize)>) -> Vec<(f64, usize)> {
        self.searched_again_keeping(roots, &mut Vec::new())
    }

    /// `roots` (of [`form_roots_mult`]) with those in each of [`clusters`]'
    /// windows replaced by the roots found there again from the forms
    /// turned to the window (see [`Elimination::roots_placed`]), the roots
    /// kept only to their window added to `kept` (angle, the window's half
    /// width).
    fn searched_again_keeping(
        &self,
        mut roots: Vec<(f64, usize)>,
        kept: &mut Vec<(f64, f64)>,
    ) -> Vec<(f64, usize)> {
        let value = |wx: f64, wy: f64| self.resultant_at(Vector2::new(wx, wy));
        let gap = angle_gap;
        let all_simple = roots.iter().all(|&(_, m)| m == 1);
        for (center, half) in clusters(&self.r.v) {
            let (s, c) = center.sin_cos();
            let [a, b, cc, d, e, g] = self.forms.each_ref().map(|f| f.rotated(c, s));
            let turned = resultant([&a, &b, &cc, &d, &e, &g]);
            let t = half.tan();
            let found: Vec<(f64, usize)> = roots_in_mult(&turned.v, -1.5 * t, 1.5 * t, &|u| {
                value(c - s * u, s + c * u)
            })
            .into_iter()
            .filter(|(u, _)| u.abs() <= t)
            .map(|(u, m)| ((center + u.atan()).rem_euclid(core::f64::consts::PI), m))
            .collect();
            // A window that finds no root, with both its ends within the
            // rounding band, keeps the one simple root found in it where
            // every root found was simple: a change of sign of the
            // accurate value beyond its band (its place uncertain, not its
            // existence; `polish` finishes it). Fuzz findings `957b29d3`,
            // `b916f313`, `c8458652` (five40): two poses `1e-8` rad or less
            // apart at one position, three of the four real roots dropped
            // so, and both Burmester points with them. Where a double root
            // was found the band holds critical points, and the root stays
            // dropped (the half-turn family of `0c09dd2e` is refused
            // otherwise).
            let inside: Vec<usize> = roots
                .iter()
                .filter(|&&(r, _)| gap(r, center) <= half)
                .map(|&(_, m)| m)
                .collect();
            let blind = [-1.5 * t, 1.5 * t].iter().all(|&u| {
                let (v, band) = value(c - s * u, s + c * u);
                v.abs() <= band
            });
            let keep_simple = found.is_empty() && inside == [1] && blind && all_simple;
            if keep_simple {
                kept.extend(
                    roots
                        .iter()
                        .filter(|&&(r, m)| m == 1 && gap(r, center) <= half)
                        .map(|&(r, _)| (r, half)),
                );
            }
            roots.retain(|&(r, m)| {
                (keep_simple && m == 1)
                    || (gap(r, center) > half
                        && found.iter().all(|&(f, _)| gap(r, f) > CLUSTER_SAME))
            });
            roots.extend(found);
        }
        roots.sort_by(|x, y| x.0.total_cmp(&y.0));
        roots
    }

    /// The common points of the two curves other than `Q`, `P13`, `P23`
    /// and the circular points: `(centers (local), multiplicity)` and
    /// `(directions at infinity, multiplicity)`.
    ///
    /// Each real root of the resultant (with its multiplicity: a double
    /// root where it touches zero within its rounding) is a direction from
    /// `Q` along which the two quadratics share a root: one, `t = (a g - c
    /// d) / (b d - a e)`; both when the quadratics are proportional
    /// (two common points on one line); at infinity when `a` and `d` vanish
    /// (both curves' asymptotic direction). The poles `P13`, `P23` are
    /// among them once each and are taken out.
    #[allow(clippy::type_complexity)]
    fn solve(&self) -> Result<(Vec<(Vector2<f64>, usize)>, Vec<(Vector2<f64>, usize)>)> {
        let (roots, kept) = self.roots_placed();
        let mut used = [false; 2];
        let mut finite = Vec::new();
        let mut infinite = Vec::new();
        let far = 1.0 / (tolerance::BURMESTER_EPS * f64::EPSILON);
        // The root of the common asymptotic direction: the nearest.
        let gap = angle_gap;
        let at_infinity = self.asymptote.and_then(|u| {
            let su = u.y.atan2(u.x);
            roots
                .iter()
                .enumerate()
                .map(|(i, &(s, _))| (i, gap(s, su)))
                .filter(|&(_, g)| g <= ASYMPTOTE_MATCH)
                .min_by(|x, y| x.1.total_cmp(&y.1))
                .map(|(i, _)| i)
        });
        for (index, (s, mult)) in roots.into_iter().enumerate() {
            // A root placed only to its window (`searched_again`): a shared
            // pole whose direction from `Q` is in that window is that root
            // (matched to the window, as the root is known; `ac54dbdb`
            // refused otherwise, five40).
            if let Some(&(_, half)) = kept.iter().find(|k| k.0 == s) {
                let pole = (0..2).find(|&k| {
                    let dir = match self.poles[k] {
                        SharedPole::At(x) => x - self.q,
                        SharedPole::Infinite(u) => u,
                    };
                    !used[k] && gap(dir.y.atan2(dir.x), s) <= half
                });
                if let Some(k) = pole {
                    used[k] = true;
                    continue;
                }
            }
            let w = match (at_infinity == Some(index), self.asymptote) {
                (true, Some(u)) => u,
                _ => Vector2::new(s.cos(), s.sin()),
            };
            let [(av, am), (bv, bm), (cv, cm), (dv, dm), (ev, em), (gv, gm)] =
                self.forms.each_ref().map(|f| f.at(w));
            let line_f = negligible(av, am) && negligible(bv, bm) && negligible(cv, cm);
            let line_h = negligible(dv, dm) && negligible(ev, em) && negligible(gv, gm);
            if line_f && line_h {
                return Err(errors::infinitely_many(
                    "a line through a pole of three of them lies on the center-point curves of \
                     two four-pose subsets (every point of it is a Burmester center)",
                ));
            }
            // First-order error bounds of products (units of eps).
            let pb = |x: (f64, f64), y: (f64, f64)| x.0.abs() * y.1 + x.1 * y.0.abs();
            let (a, b, c) = ((av, am), (bv, bm), (cv, cm));
            let (d, e, g) = ((dv, dm), (ev, em), (gv, gm));
            let mut cands: Vec<Common> = Vec::new();
            if at_infinity == Some(index)
                || (self.asymptote.is_none() && negligible(av, am) && negligible(dv, dm))
            {
                cands.push(Common::Infinite(w));
                // A finite common root on the same line as well: the root
                // of a curve's linear part, of `h`'s where the line lies on
                // `f` within rounding (`f`'s parts are then noise: its root
                // was taken next to `Q`, matched a pole there, and a point
                // was lost).
                let (lb, lc) = if line_f { (ev, gv) } else { (bv, cv) };
                let (ob, oc) = if line_f { (bv, cv) } else { (ev, gv) };
                let t = -lc / lb;
                // The two linear parts' roots agree within rounding, or
                // within `PROPORTIONAL_REL` of their terms (the finite
                // point's own direction is within the root's rounding of
                // the asymptote, `7.5e-9` rad in `b56c8054`'s moved frame,
                // and along lines this close to the asymptote the curves'
                // crossings move `1e3` times faster: the roots `16.11306`
                // task sizes out differed by `4.8e-7` of them, and the
                // point was listed as a second slider). The candidate is
                // then polished and checked like any other.
                let agree = negligible(cv * ev - gv * bv, pb(c, e) + pb(g, b))
                    || (ob * t + oc).abs() <= PROPORTIONAL_REL * ((ob * t).abs() + oc.abs());
                if mult >= 2 && agree && lb != 0.0 && t.is_finite() {
                    cands.push(Common::At(self.q + w * t, 0.0));
                }
            } else {
                let num = av * gv - cv * dv;
                let den = bv * dv - av * ev;
                if negligible(den, pb(b, d) + pb(a, e)) && negligible(num, pb(a, g) + pb(c, d)) {
                    // The quadratics proportional: the roots of `f`'s, or of
                    // `h`'s where the line lies on `f` (`f`'s are noise).
                    let (qa, qb, qc) = if line_f { (dv, ev, gv) } else { (av, bv, cv) };
                    for t in quadratic_roots(qa, qb, qc) {
                        cands.push(Common::At(self.q + w * t, 0.0));
                    }
                } else {
                    // The root of `f`'s quadratic where `h`'s is nearest zero
                    // (relative to its terms): accurate for far points too,
                    // where the formula's numerator and denominator cancel.
                    let rel = |t: f64| {
                        (dv * t * t + ev * t + gv).abs()
                            / (dv.abs() * t * t + ev.abs() * t.abs() + gv.abs())
                    };
                    let roots_f = quadratic_roots(av, bv, cv);
                    let t = roots_f
                        .iter()
                        .copied()
                        .filter(|t| t.is_finite())
                        .min_by(|x, y| rel(*x).total_cmp(&rel(*y)))
                        .unwrap_or(num / den);
                    if t.is_finite() && t.abs() <= far {
                        // The rounding of the root (first order, from the
                        // bounds of `f`'s parts): a far root `-b / a` is
                        // known to the relative rounding of `a`, which
                        // near a curve whose cubic part nearly vanishes
                        // is large (`1e-2` in `803d9c63`).
                        let slope = (2.0 * av * t + bv).abs();
                        let dt = tolerance::BURMESTER_EPS
                            * f64::EPSILON
                            * (am * t * t + bm * t.abs() + cm)
                            / slope;
                        let dt = if dt.is_finite() { dt } else { 0.0 };
                        cands.push(Common::At(self.q + w * t, dt));
                    } else {
                        cands.push(Common::Infinite(w));
                    }
                    // A double root of the resultant whose direction holds
                    // two common points, one on each root of `f`'s quadratic
                    // (the quadratics proportional, beyond the rounding
                    // band's test): both points (a point and a pole, or two
                    // points), not the one listed twice.
                    if mult >= 2 && roots_f.len() == 2 {
                        let other = if roots_f[0] == t {
                            roots_f[1]
                        } else {
                            roots_f[0]
                        };
                        // Proportional quadratics pair their roots one to
                        // one: `h`'s root nearest `other` is not the one
                        // nearest `t`. A near double root of `h` makes
                        // `rel` small at both of `f`'s roots while only one
                        // is common (a complex pair near merging, `7e-5`
                        // task sizes off the real plane, was read as two
                        // real points and the task refused).
                        let roots_h = quadratic_roots(dv, ev, gv);
                        let nearest = |x: f64| {
                            roots_h
                                .iter()
                                .copied()
                                .min_by(|p, q| (p - x).abs().total_cmp(&(q - x).abs()))
                        };
                        if other.is_finite()
                            && other.abs() <= far
                            && rel(other) <= PROPORTIONAL_REL
                            && roots_h.len() == 2
                            && nearest(other) != nearest(t)
                            && (other - t).abs() > DOUBLE_REACH * (1.0 + t.abs())
                        {
                            cands.push(Common::At(self.q + w * other, 0.0));
                        }
                    }
                    // Both quadratics with a root at `Q` within a
                    // simple point's reach, on a double root of the
                    // resultant whose common root taken is another one
                    // beyond [`far_root`]: the line is a common tangent of the
                    // curves at `Q` within rounding, and `Q` a double
                    // common point of them: a Burmester point at `Q`
                    // (which the rounding of `c` and `g` put on either
                    // side of it), a candidate that `polish` decides.
                    // (`803d9c63`, `0c09dd2e`: the point at `Q = P34`,
                    // or at coincident poles next to `Q`, along the
                    // direction of a shared pole `1e12` task sizes out:
                    // the roots of `f`'s and `h`'s quadratics there
                    // `+-2.2e-5` and `+-2e-7`, the far pole taken and
                    // the point lost.)
                    let reach = SINGLE_REACH * (1.0 + self.q.norm());
                    let at_q = |r: &[f64]| {
                        r.iter()
                            .copied()
                            .filter(|x| x.abs() <= reach)
                            .min_by(|x, y| x.abs().total_cmp(&y.abs()))
                    };
                    if mult >= 2 && t.is_finite() && t.abs() > far_root() && cands.len() == 1 {
                        if let (Some(tf), Some(th)) =
                            (at_q(&roots_f), at_q(&quadratic_roots(dv, ev, gv)))
                        {
                            cands.push(Common::At(self.q + w * (0.5 * (tf + th)), 0.0));
                        }
                    }
                }
            }
            let each = if cands.len() == 1 { mult } else { 1 };
            for cand in cands {
                let mut m = each;
                for (k, pole) in self.poles.iter().enumerate() {
                    if used[k] || m == 0 {
                        continue;
                    }
                    let hit = match (cand, pole) {
                        // Within the match, or, for a pole beyond
                        // [`far_root`] from `Q`, within the rounding of
                        // the root's distance from `Q` (a pole `1.6e12`
                        // task sizes out whose root, known to `1.7e-2` of
                        // it, lay `3e-4` off it, was listed as a point:
                        // `803d9c63`). Nearer, a pole and a Burmester point
                        // within a badly conditioned root's rounding of
                        // each other are both kept (`47915008`'s point 16
                        // task sizes out, `1.6e-3` of it from a pole, was
                        // lost to a match at any distance).
                        (Common::At(p, dt), SharedPole::At(x)) => {
                            let r = (x - self.q).norm();
                            let off = (p - x).norm();
                            off <= POLE_MATCH * (1.0 + x.norm())
                                || (r > far_root() && dt <= FAR_ROOT_REL * r && off <= dt)
                        }
                        (Common::Infinite(u), SharedPole::Infinite(x)) => {
                            cross(u, *x).abs() <= POLE_MATCH
                        }
                        // A pole so far out that its direction from `Q` is
                        // within the match of a root to the asymptote is,
                        // for this elimination, at infinity there too: that
                        // root is the pole (a slider listed in its place
                        // made a point near the task vanish, the count
                        // even).
                        (Common::Infinite(u), SharedPole::At(x)) => {
                            let r = x - self.q;
                            r.norm() * ASYMPTOTE_MATCH >= 1.0
                                && cross(u, r / r.norm()).abs() <= ASYMPTOTE_MATCH
                        }
                        _ => false,
                    };
                    if hit {
                        used[k] = true;
                        m -= 1;
                    }
                }
                if m > 0 {
                    match cand {
                        Common::At(p, _) => finite.push((p, m)),
                        Common::Infinite(u) => infinite.push((u, m)),
                    }
                }
            }
        }
        Ok((finite, infinite))
    }
}

/// The angle between two directions given as angles (mod `pi`).
fn angle_gap(x: f64, y: f64) -> f64 {
    let d = (x - y).rem_euclid(core::f64::consts::PI);
    d.min(core::f64::consts::PI - d)
}

/// Whether the real roots `roots` (angles in `[0, pi)`, sorted, with their
/// multiplicity) that [`form_roots_mult`] found of the resultant (accurate
/// `value` and its rounding band, as [`Elimination::resultant_at`]) are
/// all it has, each told apart from its neighbours, so that
/// [`Elimination::roots_placed`]' search again near every eigenvalue (in
/// [`clusters`]' windows) would find the same: [`REAL_ROOTS`] roots, each
/// simple, and the accurate value halfway between every two neighbours
/// (the last and the first too) beyond [`APART`] times its band.
///
/// Sound: a simple root of [`form_roots_mult`] is a sign change of the
/// accurate value between two points where it is beyond its band (a zero
/// within the band is a double root there, and the intervals next to it
/// are not searched), so each is a real root of the resultant, and the
/// value beyond its band between two of them makes them two roots, not one
/// double root (which the search again would decide where the value
/// touches its band there). The resultant has at most [`REAL_ROOTS`] real
/// roots (its degree, 8, less the circular points' pair, far off the real
/// line), so these are all: no root is left to a crowd the expanded
/// coefficients blur (the search again's reason: there, roots are lost, or
/// found double, or as roots within the band of each other). Anything
/// else (fewer roots: a complex pair, or roots lost; a double root; two
/// roots not told apart) is searched again as before.
fn all_found(roots: &[(f64, usize)], value: &dyn Fn(f64, f64) -> (f64, f64)) -> bool {
    use core::f64::consts::PI;
    roots.len() == REAL_ROOTS
        && roots.iter().all(|&(_, m)| m == 1)
        && roots
            .iter()
            .zip(roots.iter().cycle().skip(1))
            .all(|(x, y)| {
                // The neighbour after the last is the first, half a turn on.
                let y = if y.0 > x.0 { y.0 } else { y.0 + PI };
                let (s, c) = (0.5 * (x.0 + y)).sin_cos();
                let (v, band) = value(c, s);
                v.abs() > APART * band
            })
}

/// How far beyond its rounding band (times) the resultant must be between
/// two neighbouring roots for them to be told apart ([`all_found`]).
const APART: f64 = 4.0;

/// The most real roots the resultant has: its degree, 8, less the two
/// circular points' (`w = (1, +-i)`, far off the real line).
const REAL_ROOTS: usize = 6;

/// The directions (angles in `[0, pi)`) of the roots of a binary form's
/// expanded coefficients, real or within [`CLUSTER_WINDOW`] rad of the real
/// line (the eigenvalues of the companion matrices of both charts), grouped
/// into windows `(center, half width)` at least [`CLUSTER_WINDOW`] wide
/// (see [`Elimination::roots_placed`]). Empty when the eigenvalues are not found.
fn clusters(f: &[f64]) -> Vec<(f64, f64)> {
    use core::f64::consts::PI;
    let mut angles = Vec::new();
    let chart = |p: &[f64]| -> Vec<nalgebra::Complex<f64>> {
        let mut n = p.len();
        while n > 0 && p[n - 1] == 0.0 {
            n -= 1;
        }
        if n < 2 || !p[..n].iter().all(|c| c.is_finite()) {
            return Vec::new();
        }
        let deg = n - 1;
        let lead = p[deg];
        let comp = nalgebra::DMatrix::from_fn(deg, deg, |i, j| {
            if i == 0 {
                -p[deg - 1 - j] / lead
            } else if i == j + 1 {
                1.0
            } else {
                0.0
            }
        });
        if !comp.iter().all(|v| v.is_finite()) {
            return Vec::new();
        }
        comp.try_schur(f64::EPSILON, 1000)
            .map(|s| s.complex_eigenvalues().iter().copied().collect())
            .unwrap_or_default()
    };
    for u in chart(f) {
        if u.re.abs() <= 1.0 && u.im.abs() / (1.0 + u.re * u.re) <= CLUSTER_WINDOW {
            angles.push(u.re.atan().rem_euclid(PI));
        }
    }
    let rev: Vec<f64> = f.iter().rev().copied().collect();
    for v in chart(&rev) {
        if v.re.abs() < 1.0 && v.im.abs() / (1.0 + v.re * v.re) <= CLUSTER_WINDOW {
            angles.push(1.0f64.atan2(v.re));
        }
    }
    angles.sort_by(f64::total_cmp);
    let mut windows: Vec<(f64, f64)> = Vec::new();
    for a in angles {
        match windows.last_mut() {
            Some((lo, hi)) if a - *hi <= 2.0 * CLUSTER_WINDOW => *hi = a,
            _ => windows.push((a, a)),
        }
    }
    windows
        .into_iter()
        .map(|(lo, hi)| (0.5 * (lo + hi), 0.5 * (hi - lo) + CLUSTER_WINDOW))
        .collect()
}

/// The half width (rad) of a window in which the resultant's roots are
/// found again from the forms turned to its center, and how far from the
/// real line (rad) a complex root of the expanded coefficients may be to
/// mark one: a crowd of `k` roots within `1e-5` rad is spread by the
/// coefficients' rounding (`1e-13` relative and more) over about its
/// `k`-th root (`1e-3` for four), which this holds with room.
const CLUSTER_WINDOW: f64 = 1e-2;

/// A root found in a window and one found outside it within this many
/// rad are one root (found twice at the window's edge).
const CLUSTER_SAME: f64 = 1e-9;

/// The most Burmester points (with multiplicity, sliders included) five
/// poses can have: the nine common points of two cubics less `Q`, `P13`,
/// `P23` and the two circular points.
const MAX_POINTS: usize = 4;

/// A shared pole and a common point found along a line from `Q` are the
/// same when they agree within this (local units, plus the pole's distance;
/// radians for directions at infinity).
const POLE_MATCH: f64 = 1e-6;

/// Along a double root of the resultant, the other root of `f`'s quadratic
/// is a common point too when `h`'s quadratic is zero there within this
/// much of its terms (a root's direction is known to about the square
/// root of the band there; a root of `f` off `h` leaves terms of its own
/// size).
const PROPORTIONAL_REL: f64 = 1e-4;

/// A root of `f`'s quadratic matches a shared pole beyond [`far_root`]
/// from `Q` within the root's own rounding only where that rounding is at
/// most this much of the pole's distance (a root known to its order of
/// magnitude matches nothing).
const FAR_ROOT_REL: f64 = 0.1;

/// How far from `Q` (local) a common root along a line from it is within
/// the square root of the rounding of infinity: `1 / sqrt(BURMESTER_EPS
/// eps)`, about `1.7e7` task sizes. A root that far out lies where the
/// curves' cubic parts, which place it, are within the square root of their
/// rounding of vanishing (a pole of two poses `1e-12` rad apart, `1.6e12`
/// task sizes out, in `803d9c63`): its distance is known only to that
/// rounding, and [`Elimination::solve`] matches it to a shared pole there
/// within it, and looks for a Burmester point at `Q` on the same line.
/// Nearer (poles `1e5` to `1.6e7` task sizes out in fuzz inputs
/// `622ff580`, `9d23e6b4`; a far root `0.8` to `3.5e4` out in `924ba8db`,
/// `77a8a120`, `d01f0022`) those rules changed answers that were right.
fn far_root() -> f64 {
    1.0 / (tolerance::BURMESTER_EPS * f64::EPSILON).sqrt()
}

/// The root of the resultant nearest the curves' common asymptotic
/// direction, within this many radians, is that common point at infinity.
const ASYMPTOTE_MATCH: f64 = 1e-6;

/// A Burmester center found by the elimination (local, `motion`'s frame),
/// finished by Newton's method on the four circle equations (kept only
/// when it lowers the crank-length spread and stays near: a double point
/// is as well placed as its rounding allows), and checked: `None` when
/// its crank length varies by more than [`tolerance::BURMESTER_RESIDUAL`] (not a
/// Burmester point) or its circle point is at infinity.
///
/// A double root (`mult` 2) may be two real points apart, closer than the
/// resultant's rounding band resolves (two points `6.3e-5` apart in a task
/// of size 3 were one double root whose estimate lay between them, beyond
/// what the check allows: the task was refused as unresolved): Newton's
/// method, converged from the estimate to a point beyond a double point's
/// reach and from the estimate reflected through it to a distinct point on
/// the other side, both within a single point's reach and both checked,
/// gives the two points (`Polished::Pair`). Otherwise the double point is
/// listed twice as before.
///
/// An estimate within [`tolerance::BURMESTER_NEAR`] task sizes from which
/// Newton's method converges beyond [`SINGLE_REACH`] (and the
/// double-double Newton of [`refine`] beyond [`REFINE_REACH`]) is no point
/// (`Polished::None`): no root of the four equations lies near it.
///
/// # Errors
///
/// [`crate::DegenerateError::InfinitelyManyBurmesterPoints`] when the four
/// equations leave a whole line of circle points at the center.
fn polish(m: &LocalMotion, g0: Vector2<f64>, mult: usize) -> Result<Polished> {
    let z0 = match m.form.solve(g0, &[1, 2, 3, 4]) {
        Ok(z) => z,
        Err(Failure::Undefined) => {
            return Err(errors::infinitely_many(
                "a Burmester center has a whole line of circle points (the four conditions at \
                 it are one)",
            ));
        }
        Err(Failure::AtInfinity(_)) => return Ok(Polished::None),
    };
    let scale = 1.0 + g0.norm();
    let first = newton(m, g0);
    if mult == 2 {
        let sides = both_sides(m, g0, first, scale);
        if let Some(pair) = sides.and_then(|s| split(m, g0, s, scale)) {
            return Ok(pair);
        }
        if complex_pair(m, g0, z0, scale) {
            return Ok(Polished::Complex);
        }
        if let Some(one) = sides.and_then(|s| simple(m, s, scale)) {
            return Ok(one);
        }
    }
    // Judged in the task's own frame (local: origin the poses' centroid,
    // unit their span), so that the check and its rounding allowance do not
    // depend on where the task is given: moved far out, the global
    // coordinates' rounding would pass a point between two close roots.
    // Newton's method from the estimate of a point within
    // [`tolerance::BURMESTER_NEAR`] task sizes converged (its steps at the
    // rounding of the coordinates) to a point beyond a simple root's reach:
    // no root of the four equations lies near the estimate, which is not a
    // Burmester point however small its crank-length spread (relative to
    // the crank: `427fbb95`'s ghost had its circle point `4e5` task sizes
    // out). A badly conditioned choice read a complex pair, or a real
    // point's double root, as a real double point `0.01` to `1` of `size +
    // d` off every exact point, and it was the answer where the better
    // choices had lost a root.
    // The rows' entries may have lost most of their digits (poses at
    // nearly one position or angle), and Newton's method on them may leave
    // a genuine point: the estimate is rejected only where the
    // double-double Newton of [`refine`] does not converge within
    // [`REFINE_REACH`] of it either (`18bd80a0`: points 850 task sizes out
    // whose float iterations ended at another point, which [`refined`]
    // puts within `1e-9` of the exact ones). Farther out than
    // `BURMESTER_NEAR` a point is known only to its distance squared times
    // the rounding, and is left as it was.
    let near = is_near(m, m.global_of(g0));
    let far_off = |g: Vector2<f64>| {
        (g - g0).norm() > SINGLE_REACH * scale
            && refine::Accurate::new(m)
                .newton(g0, z0)
                .is_none_or(|(g1, _, _)| (g1 - g0).norm() > REFINE_REACH * scale)
    };
    if let (Some((g, _, true)), true) = (first, near) {
        if far_off(g) {
            return Ok(Polished::None);
        }
    }
    let mut best = (local_residual(m, g0, z0), g0, z0);
    if let Some((g, z, _)) = first {
        let reach = if mult > 1 { DOUBLE_REACH } else { SINGLE_REACH } * scale;
        let r = local_residual(m, g, z);
        if (g - g0).norm() <= reach && r <= best.0 {
            best = (r, g, z);
        }
    }
    let (r, g, z) = best;
    Ok(if accepted(m, g, z, r) {
        Polished::One(Dyad::new(m.global_of(g), m.global_of(z)))
    } else {
        Polished::None
    })
}

/// The answer's points, each corrected by Newton's method on the four
/// circle equations in double-double ([`refine`]): kept where it converges
/// within [`REFINE_REACH`] (times `1 + |G|`, local), within a quarter of
/// the way to any other listed point (a point listed twice stays so), and
/// to a smaller residual of the accurate rows.
fn refined(m: &LocalMotion, points: &mut [Dyad]) {
    let accurate = refine::Accurate::new(m);
    let local: Vec<(Vector2<f64>, Vector2<f64>)> = points
        .iter()
        .map(|d| (m.local_of(d.center), m.local_of(d.circle)))
        .collect();
    for i in 0..points.len() {
        let (g, z) = local[i];
        // A point listed twice: as its first listing.
        if let Some(j) = (0..i).find(|&j| local[j] == local[i]) {
            points[i] = points[j];
            continue;
        }
        let Some((g1, z1, start)) = accurate.newton(g, z) else {
            continue;
        };
        let moved = (g1 - g).norm();
        let apart = local
            .iter()
            .map(|(h, _)| (h - g).norm())
            .filter(|&x| x > 0.0)
            .fold(f64::INFINITY, f64::min);
        // A move at the rounding of the local coordinates needs no check
        // of the residual (most points of a moderate task).
        let tiny = moved <= 1e-12 * (1.0 + g.norm());
        if moved <= REFINE_REACH * (1.0 + g.norm())
            && moved <= 0.25 * apart
            && (tiny || accurate.residual(g1, z1) <= start)
        {
            points[i] = Dyad::new(m.global_of(g1), m.global_of(z1));
        }
    }
}

/// How far (times `1 + |G|`, local) [`refined`] may move a point.
const REFINE_REACH: f64 = 1e-2;

/// A double root that is one simple real point (see [`polish`]): Newton's
/// method from its estimate converged beyond a double point's reach
/// ([`DOUBLE_REACH`], within [`SINGLE_REACH`]) and from the estimate
/// reflected through that point ([`both_sides`]) converged to the same
/// point to
/// [`SIMPLE_SAME`] (times `1 + |G|`): at a simple root Newton's method ends
/// at the rounding of the coordinates from either side, at a double one
/// only at about its square root, apart. The root's other multiplicity is
/// then not a real point: a complex pair whose directions from `Q` lie
/// within the resultant's rounding of the point's (`3ef91cde`: two real
/// points and a pair `0.3` task sizes off the real plane, every direction
/// from `Q` within `1e-5` rad of two; each real point was listed twice).
/// The point is listed once; the count of such a choice stays even only
/// when another root is read the same way.
fn simple(m: &LocalMotion, ((g1, z1), (g2, _)): Sides, scale: f64) -> Option<Polished> {
    ((g2 - g1).norm() <= SIMPLE_SAME * scale && accepted(m, g1, z1, local_residual(m, g1, z1)))
        .then(|| Polished::Simple(Dyad::new(m.global_of(g1), m.global_of(z1))))
}

/// Two converged points of Newton's method, each with its circle point
/// ([`both_sides`]).
type Sides = ((Vector2<f64>, Vector2<f64>), (Vector2<f64>, Vector2<f64>));

/// Newton's method from a double root's estimate `g0` (`first`, converged
/// beyond [`DOUBLE_REACH`] and within [`SINGLE_REACH`], times `scale`) and
/// from `g0` reflected through that point (converged): both points with
/// their circle points, for [`split`] and [`simple`] to judge.
fn both_sides(
    m: &LocalMotion,
    g0: Vector2<f64>,
    first: Option<(Vector2<f64>, Vector2<f64>, bool)>,
    scale: f64,
) -> Option<Sides> {
    let (g1, z1, true) = first? else {
        return None;
    };
    let d = (g1 - g0).norm();
    if !(d > DOUBLE_REACH * scale && d <= SINGLE_REACH * scale) {
        return None;
    }
    let (g2, z2, true) = newton(m, g0 * 2.0 - g1)? else {
        return None;
    };
    Some(((g1, z1), (g2, z2)))
}

/// See [`simple`]: the rounding of the local coordinates, with room.
const SIMPLE_SAME: f64 = 1e-12;

/// What [`polish`] makes of a root of the elimination.
enum Polished {
    /// No Burmester point (not concyclic, or the circle point at infinity).
    None,
    /// One point (listed with the root's multiplicity).
    One(Dyad),
    /// A double root that is two distinct real points, each listed once.
    Pair(Dyad, Dyad),
    /// A double root that is a pair of complex points resolved apart from
    /// the real plane ([`complex_pair`]): no real point.
    Complex,
    /// A double root that is one simple real point ([`simple`]), listed
    /// once: the root's other multiplicity is not a real point.
    Simple(Dyad),
}

/// Whether the double root at `g0` (local, circle point `z0`) is a pair of
/// complex Burmester points told apart from the real plane: Newton's method
/// on the four circle equations in complex `(G, z)`, from `g0` moved off
/// the real plane by [`SINGLE_REACH`] in either coordinate, converges (both
/// starts) to a root within [`SINGLE_REACH`] of `g0` whose imaginary part
/// is beyond [`DOUBLE_REACH`] and beyond the square root of the poses'
/// rounding in their frame (all times `1 + |g0|`). Near a merge the two
/// roots are simple ones `2 delta` apart, found to about `eps / delta`, so
/// such a pair is resolved; a real double point (two real points, or one
/// within rounding) draws the iterates to the real plane instead. Before,
/// such a pair (`7e-5` task sizes off the real plane, its real part's crank
/// lengths equal within the check's tolerance) was listed as a real double
/// point in one frame and not in another.
fn complex_pair(m: &LocalMotion, g0: Vector2<f64>, z0: Vector2<f64>, scale: f64) -> bool {
    type C = Complex<f64>;
    // Each row `a_k(G) . z - b_k(G)` with `a_k` and `b_k` affine in `G`.
    let rows: [([[f64; 3]; 2], [f64; 3]); 4] = core::array::from_fn(|r| {
        let k = r + 1;
        let (a0, b0) = m.form.row(k, Vector2::zeros());
        let (ax, bx) = m.form.row(k, Vector2::x());
        let (ay, by) = m.form.row(k, Vector2::y());
        (
            [
                [a0.x, ax.x - a0.x, ay.x - a0.x],
                [a0.y, ax.y - a0.y, ay.y - a0.y],
            ],
            [b0, bx - b0, by - b0],
        )
    });
    let affine = |p: &[f64; 3], g: [C; 2]| g[0] * p[1] + g[1] * p[2] + p[0];
    let solve = |start: [C; 4]| -> Option<[C; 4]> {
        let mut x = start;
        let mut last = f64::INFINITY;
        for _ in 0..60 {
            let g = [x[0], x[1]];
            let mut jac = Matrix4::<C>::zeros();
            let mut rhs = Vector4::<C>::zeros();
            for (r, (a, b)) in rows.iter().enumerate() {
                let av = [affine(&a[0], g), affine(&a[1], g)];
                rhs[r] = -(av[0] * x[2] + av[1] * x[3] - affine(b, g));
                for i in 0..2 {
                    jac[(r, i)] = x[2] * a[0][i + 1] + x[3] * a[1][i + 1] - b[i + 1];
                    jac[(r, 2 + i)] = av[i];
                }
            }
            let step = jac.lu().solve(&rhs)?;
            if !step.iter().all(|v| v.re.is_finite() && v.im.is_finite()) {
                return None;
            }
            for i in 0..4 {
                x[i] += step[i];
            }
            let size = 1.0 + x.iter().map(|v| v.norm()).fold(0.0, f64::max);
            let n = step.iter().map(|v| v.norm()).fold(0.0, f64::max);
            if n <= 8.0 * f64::EPSILON * size || (n >= last && n <= 1e-10 * size) {
                return Some(x);
            }
            last = n;
        }
        None
    };
    let off = SINGLE_REACH * scale;
    // A change of the task by `rho` (relative) moves a double root's pair
    // by about `sqrt(rho)`: the poses' own rounding in this frame (far out,
    // `eps` of coordinates millions of task sizes out: the same merging task
    // moved by `(-3e6, 2e6)` makes its real pair a complex one `1.7e-5`
    // off) decides such a pair, which is then not told apart.
    let (dp, da) = m.data_rounding;
    let rounding = (tolerance::BURMESTER_EPS * f64::EPSILON * (dp + da)).sqrt();
    let apart = DOUBLE_REACH.max(rounding) * scale;
    [Vector2::<f64>::x(), Vector2::y()].iter().all(|d| {
        let start = [
            C::new(g0.x, off * d.x),
            C::new(g0.y, off * d.y),
            C::new(z0.x, 0.0),
            C::new(z0.y, 0.0),
        ];
        let got = solve(start);
        got.is_some_and(|x| {
            let re = Vector2::new(x[0].re, x[1].re);
            let im = Vector2::new(x[0].im, x[1].im);
            (re - g0).norm() <= SINGLE_REACH * scale && im.norm() > apart
        })
    })
}

/// How far (times `1 + |G|`, local) Newton's method may move a simple root's
/// center, and a double root's (as well placed as its rounding allows).
const SINGLE_REACH: f64 = 1e-3;
/// See [`SINGLE_REACH`].
const DOUBLE_REACH: f64 = 1e-6;

/// A double root at `g0` split into two real points (see [`polish`]):
/// Newton's method from `g0` and from `g0` reflected through it
/// ([`both_sides`]) converged, on opposite sides of `g0`, to distinct points each beyond
/// [`DOUBLE_REACH`] and within [`SINGLE_REACH`], both concyclic.
fn split(
    m: &LocalMotion,
    g0: Vector2<f64>,
    ((g1, z1), (g2, z2)): Sides,
    scale: f64,
) -> Option<Polished> {
    let within = |g: Vector2<f64>| {
        let d = (g - g0).norm();
        d > DOUBLE_REACH * scale && d <= SINGLE_REACH * scale
    };
    if !within(g2)
        || !((g2 - g0).dot(&(g1 - g0)) < 0.0)
        || !((g2 - g1).norm() > DOUBLE_REACH * scale)
    {
        return None;
    }
    (accepted(m, g1, z1, local_residual(m, g1, z1))
        && accepted(m, g2, z2, local_residual(m, g2, z2)))
    .then_some(Polished::Pair(
        Dyad::new(m.global_of(g1), m.global_of(z1)),
        Dyad::new(m.global_of(g2), m.global_of(z2)),
    ))
}

/// `(max - min) / max` of the crank lengths over the poses of the dyad
/// with center `g` and circle point `z` in the task's local frame (the
/// rounding of the check is then that of the task's own size, wherever the
/// task is given).
fn local_residual(m: &LocalMotion, g: Vector2<f64>, z: Vector2<f64>) -> f64 {
    spread((0..m.poses.len()).map(|k| (m.form.displace(k, z) - g).norm()))
}

/// Whether the dyad of center `g` and circle point `z` (local, crank-length
/// spread `r` from [`local_residual`]) passes [`polish`]'s check.
fn accepted(m: &LocalMotion, g: Vector2<f64>, z: Vector2<f64>, r: f64) -> bool {
    // The crank-length spread of a point `D` task sizes out along the
    // normal of a line through the positions is about `(L / D)^2` (`L` the
    // span of the positions): far out, a Burmester point is told from a
    // stretch of line only that well, and rounding allows
    // [`tolerance::BURMESTER_ROUNDING`] `eps` of the local coordinates (the
    // task's own scale, not where it is given) over the crank's length.
    let positions: Vec<Vector2<f64>> = (0..m.poses.len()).map(|k| m.form.displace(k, z)).collect();
    let span = positions
        .iter()
        .flat_map(|a| positions.iter().map(move |b| (a - b).norm()))
        .fold(0.0, f64::max);
    let radius = (g - z).norm().max(span);
    let coords = positions.iter().map(|p| p.norm()).fold(g.norm(), f64::max);
    let allowed = (tolerance::BURMESTER_RESIDUAL * (span / radius).powi(2))
        .max(tolerance::BURMESTER_ROUNDING * f64::EPSILON * (1.0 + coords / radius));
    r <= allowed
}

/// A slider found by the elimination (circle point `z` local, direction
/// `u`), checked as [`polish`] checks a finite point: the circle point's
/// five positions must lie on a line normal to `u` within
/// [`tolerance::BURMESTER_RESIDUAL`] of their span (or the rounding of their
/// local coordinates, [`tolerance::BURMESTER_ROUNDING`] `eps`). The circle point is solved from two of the four
/// conditions at infinity; those two alone do not make its positions
/// collinear, and a root of the resultant within rounding of a common
/// asymptotic direction (a near-degenerate task) can give a circle point
/// whose positions are far off any line. `None` then (the root gives no
/// Burmester point), and for a circle point not finite.
fn check_slider(m: &LocalMotion, z: Vector2<f64>, u: Vector2<f64>) -> Option<BurmesterSlider> {
    let circle = m.global_of(z);
    if !(circle.x.is_finite() && circle.y.is_finite() && u.x.is_finite() && u.y.is_finite()) {
        return None;
    }
    // In the task's own frame (local), as `accepted`: the allowance is the
    // rounding of the task's coordinates, not of where it is given.
    let p: Vec<Vector2<f64>> = (0..m.poses.len()).map(|k| m.form.displace(k, z)).collect();
    let span = p
        .iter()
        .flat_map(|a| p.iter().map(move |b| (a - b).norm()))
        .fold(0.0, f64::max);
    let coords = p.iter().map(|q| q.norm()).fold(0.0, f64::max);
    // The line's normal from the positions themselves (the root's direction
    // is known only to the resultant's conditioning): from the first
    // position to the farthest, which must be `u`'s within the loose
    // match of a root to the asymptote.
    let far = p
        .iter()
        .max_by(|a, b| (*a - p[0]).norm().total_cmp(&(*b - p[0]).norm()))
        .map_or(Vector2::zeros(), |q| q - p[0]);
    if !(far.norm() > 0.0) {
        return None;
    }
    let n = perp(far) / far.norm();
    let n = if n.dot(&u) < 0.0 { -n } else { n };
    if !(cross(n, u).abs() <= 1e-3) {
        return None;
    }
    let off = p[1..]
        .iter()
        .map(|q| (q - p[0]).dot(&n).abs())
        .fold(0.0, f64::max);
    let allowed = (tolerance::BURMESTER_RESIDUAL * span)
        .max(tolerance::BURMESTER_ROUNDING * f64::EPSILON * coords);
    (off <= allowed).then_some(BurmesterSlider {
        circle,
        direction: n,
    })
}

/// Whether the finite Burmester point `d`, beyond
/// [`tolerance::BURMESTER_NEAR`] task sizes, is the slider `s` read a
/// second time: its center along the slider's direction (within `1e-3`
/// rad, the loose match of a root to the asymptote) and its circle point
/// the slider's (within `1e-3` of `size + d`, `d` the circle point's
/// distance from the centroid).
fn far_point_of_slider(m: &LocalMotion, d: &Dyad, s: &BurmesterSlider) -> bool {
    if is_near(m, d.center) {
        return false;
    }
    let g = d.center - m.origin;
    let reach = m.scale + (s.circle - m.origin).norm();
    cross(g / g.norm(), s.direction).abs() <= 1e-3 && (d.circle - s.circle).norm() <= 1e-3 * reach
}

/// Newton's method on the four circle equations `a_k(G) . z = b_k(G)`
/// (k = 2..5) in `(G, z)` (local), from the center `g0` and the circle point
/// of its best pair of rows. When the steps never pass the step test
/// (a center tens of thousands of task sizes away, nearly a slider, whose
/// position rounding leaves loose along one direction: the steps wander at
/// rounding level) the iterate with the smallest equation residual is
/// returned, and the caller keeps it only if its crank lengths agree to
/// [`tolerance::BURMESTER_RESIDUAL`]; the flag says whether the steps
/// converged (false for that best iterate). `None` when a step is not
/// finite.
fn newton(m: &LocalMotion, g0: Vector2<f64>) -> Option<(Vector2<f64>, Vector2<f64>, bool)> {
    let mut g = g0;
    let mut z = m.form.solve(g, &[1, 2, 3, 4]).ok()?;
    let mut last = f64::INFINITY;
    let mut best = (f64::INFINITY, g, z);
    for _ in 0..60 {
        let mut jac = Matrix4::zeros();
        let mut rhs = Vector4::zeros();
        for (r, k) in (1..5).enumerate() {
            let (a, b) = m.form.row(k, g);
            let dg = m.form.row_dg(k, z);
            rhs[r] = -(a.dot(&z) - b);
            jac[(r, 0)] = dg.x;
            jac[(r, 1)] = dg.y;
            jac[(r, 2)] = a.x;
            jac[(r, 3)] = a.y;
        }
        let r = rhs.norm();
        if r < best.0 {
            best = (r, g, z);
        }
        let step = jac.full_piv_lu().solve(&rhs)?;
        if !step.iter().all(|v| v.is_finite()) {
            return None;
        }
        g += Vector2::new(step[0], step[1]);
        z += Vector2::new(step[2], step[3]);
        let size = 1.0 + g.norm() + z.norm();
        let n = step.norm();
        if n <= 8.0 * f64::EPSILON * size || (n >= last && n <= 1e-10 * size) {
            return Some((g, z, true));
        }
        last = n;
    }
    Some((best.1, best.2, false))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synthesis::local::cross3;

    /// The worked example of `positions-4-5.md` section 6 (the bench's).
    fn worked_example() -> Vec<Pose> {
        [
            (1.049199280691, 2.279426358634, 45.220037141544),
            (0.734502065472, 3.198658887874, 26.633426990744),
            (-0.378159188147, 3.063048993013, 21.786789298262),
            (-1.268710439724, 2.051150142014, 27.048624103934),
            (-1.411118156972, 0.597429126400, 48.044287536536),
        ]
        .iter()
        .map(|&(x, y, a): &(f64, f64, f64)| Pose::new(x, y, a.to_radians()))
        .collect()
    }

    #[test]
    fn forms_at_a_direction_agree_with_form_eval_to_the_bit() {
        // `at_powers` replaced `form_eval` on the values, the bounds and the
        // magnitudes (allocating) in the resultant's bisection: the same
        // arithmetic, so the same bits, at every kind of direction.
        let forms = [
            vec![1.25, -3.5e-3, 7.0, -0.1],
            vec![-2.0, 1.0e5, 3.3],
            vec![0.7, -1.9],
            vec![0.0, 4.5, -1.0e-12, 2.0],
            vec![1.0, 2.0, 3.0, 4.0, 5.0],
        ];
        let dirs = [
            (1.0, 0.0),
            (0.0, 1.0),
            (0.6, -0.8),
            (-0.31, 0.95),
            (-1.0, -1.0e-9),
            (1.0, 0.4142135623730951),
            (-0.9999999, 1.3e-3),
        ];
        for (k, v) in forms.iter().enumerate() {
            let e: Vec<f64> = v.iter().map(|x: &f64| 0.37 * x.abs() + k as f64).collect();
            let f = Bounded { v: v.clone(), e };
            for &(x, y) in &dirs {
                let (ax, ay) = (f64::abs(x), f64::abs(y));
                let want = (
                    form_eval(&f.v, x, y),
                    form_eval(&f.e, ax, ay) + form_eval(&f.abs(), ax, ay),
                );
                let got = f.at(Vector2::new(x, y));
                assert_eq!(
                    (got.0.to_bits(), got.1.to_bits()),
                    (want.0.to_bits(), want.1.to_bits()),
                    "form {k} at ({x}, {y}): {got:?} against {want:?}"
                );
            }
        }
    }

    #[test]
    fn the_worked_example_needs_no_search_again_and_it_would_find_the_same() {
        // The worked example's elimination (as `FivePositions::of` takes
        // it: the first choice) has six simple, separated roots: `roots`
        // skips the search again near every eigenvalue, which finds the
        // same roots (within rounding) and multiplicities.
        let poses = worked_example();
        let motion = LocalMotion::new(&poses).unwrap();
        let mut checked = 0;
        for i in 0..5 {
            for j in i + 1..5 {
                let others: Vec<usize> = (0..5).filter(|&k| k != i && k != j).collect();
                let order = [i, j, others[0], others[1], others[2]];
                let sub = LocalMotion::new(&order.map(|x| poses[x])).unwrap();
                let Some(elim) = Elimination::new(&sub) else {
                    continue;
                };
                let value = |wx: f64, wy: f64| elim.resultant_at(Vector2::new(wx, wy));
                let first = form_roots_mult(&elim.r.v, &value);
                if !all_found(&first, &value) {
                    continue;
                }
                checked += 1;
                let again = elim.searched_again(first.clone());
                assert_eq!(first.len(), again.len(), "{first:?} against {again:?}");
                for (x, y) in first.iter().zip(&again) {
                    assert_eq!(x.1, y.1);
                    assert!(angle_gap(x.0, y.0) <= 1e-12, "{first:?} against {again:?}");
                }
                assert_eq!(elim.roots(), first);
                // And the points it gives are the task's four (the notes'
                // centers, from the linkage the task was made of and the
                // notes' exact elimination, to their ten digits).
                let (points, sliders, lost, _) = elim.points(&sub, &motion).unwrap();
                assert_eq!((points.len(), sliders.len(), lost), (4, 0, 0));
                for want in [
                    (0.0, 0.0),
                    (4.0, 0.0),
                    (9.1415535429, 5.4771377313),
                    (28.5694893347, -40.1577865973),
                ] {
                    let want = Point2::new(want.0, want.1);
                    assert!(
                        points.iter().any(|d| (d.center - want).norm() <= 1e-9),
                        "{want} not among {points:?}"
                    );
                }
            }
        }
        // Every choice of the pair has four real points and two poles.
        assert_eq!(checked, 10);
    }

    /// `clusters`' windows do not merge across the wrap at `0 = pi`: a crowd
    /// of roots there (eigenvalues at small positive angles and just below
    /// `pi`) gets a window on each side. Not a miss: each window holds its
    /// eigenvalues with `CLUSTER_WINDOW` to spare on both sides (measured
    /// with `angle_gap`, which wraps), so the crowd lies inside both, and the
    /// search again of the later one replaces the roots the earlier found
    /// within it (`searched_again` keeps a root only outside the window).
    /// Every root of the expanded form, crowded at the wrap over `1e-6` to
    /// `5e-3` rad (two, three or four of them, a quadratic or quartic whose
    /// other roots are away), lies inside a window.
    #[test]
    fn a_crowd_at_the_wrap_lies_inside_the_windows() {
        use core::f64::consts::PI;
        for spread in [1e-6, 1e-4, 1e-3, 5e-3] {
            // Roots (as `tan`) at `-spread`, `spread / 2`, and for the
            // quartic `spread` and `3` (away).
            let crowds: [&[f64]; 3] = [
                &[-spread, 0.5 * spread],
                &[-spread, 0.5 * spread, spread],
                &[-spread, 0.5 * spread, spread, 3.0],
            ];
            for roots in crowds {
                // Coefficients of `prod (u - r)`, lowest first.
                let mut f = vec![1.0];
                for &r in roots {
                    let mut g = vec![0.0; f.len() + 1];
                    for (i, c) in f.iter().enumerate() {
                        g[i + 1] += c;
                        g[i] -= r * c;
                    }
                    f = g;
                }
                let windows = clusters(&f);
                // Two windows, one on each side of the wrap, both holding 0.
                let holding = windows.iter().filter(|&&(c, h)| angle_gap(0.0, c) <= h);
                assert_eq!(holding.count(), 2, "{windows:?}");
                for &r in roots.iter().filter(|r| r.abs() < 1.0) {
                    let a = r.atan().rem_euclid(PI);
                    assert!(
                        windows.iter().any(|&(c, h)| angle_gap(a, c) <= h),
                        "root at {a} outside {windows:?} (spread {spread})"
                    );
                }
            }
        }
    }

    #[test]
    fn homogeneous_cross_is_the_meet() {
        // The lines x = 1 and y = 2 meet at (1, 2).
        let l1 = [1.0, 0.0, -1.0];
        let l2 = [0.0, 1.0, -2.0];
        let p = cross3(l1, l2);
        assert!((p[0] / p[2] - 1.0).abs() < 1e-15 && (p[1] / p[2] - 2.0).abs() < 1e-15);
    }
}
