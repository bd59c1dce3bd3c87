//! What a designer checks of one linkage that must pass a task's poses in
//! order: the assembly mode at each pose, Grashof type, order and circuit,
//! the minimum transmission angle over the whole travel, the link ratio.
//!
//! # How the figures are computed (no trigonometry per linkage)
//!
//! With the lengths `L1..L4`, the input angles `theta_k` at the poses, and
//! `theta1` the ground direction, the loop closes where
//! `c = cos(theta - theta1)` lies in `[c_min, c_max]`
//! ([`FourBar::input_range`](crate::FourBar::input_range)). Angles are
//! compared through a monotone pseudo-angle measured from a direction known
//! to lie outside the travel: the first input angle for a crank, a
//! direction in the input's dead zone for a rocker (`theta1 + pi` when the
//! input rocks about `theta1`, `theta1` otherwise, which both arcs of a
//! Grashof double-rocker avoid).
//!
//! * **Modes.** The assembly mode at a pose is the sign of
//!   `sin(theta4 - theta3)` of the pose's loop, where the position
//!   analysis' loop at the pose's input direction closes clear of a toggle
//!   (the one criterion, [`crate::tolerance::heron_tolerance`], with the
//!   ground and crank as the loop's reach), and `None` (a toggle) otherwise:
//!   a pose with a mode assembles in it.
//! * **Order.** A crank that turns fully must meet the poses in the cyclic
//!   order `1, 2, ..., n` in one direction: their pseudo-angles from pose 1
//!   strictly increase (counter-clockwise) or strictly decrease
//!   (clockwise). A rocker must reach them monotonically inside one arc of
//!   its input range.
//! * **Circuit.** A Grashof double-rocker's input rocks in one of two arcs,
//!   mirror images across the ground line: the poses must all lie on one.
//! * **Transmission.** The transmission angle depends on the input only
//!   through `r^2 = L1^2 + L2^2 - 2 L1 L2 c`:
//!
//! ```text
//! cos mu = (L3^2 + L4^2 - r^2) / (2 L3 L4),   quality = acos |cos mu|   (in [0, pi/2])
//! ```
//!
//! `|cos mu|` is convex in `c`, so its largest value over the travel is at
//! an extreme of `c`: an end of the travel, or `c = +1` / `c = -1` where
//! the travel passes the ground direction or its opposite. The minimum
//! transmission angle over the travel is exact, from at most four
//! candidates.

use nalgebra::{Point2, Vector2};

use crate::geom::{PerPose, cross};
use crate::linkage::grashof::{fmax, fmin, grashof_of};
use crate::linkage::{AssemblyMode, FourBar, Grashof, input_bounds};

/// The input rotation that carries the coupler through the poses in order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Direction {
    /// Counter-clockwise.
    Ccw,
    /// Clockwise.
    Cw,
    /// No direction does: an order defect, or poses on different circuits.
    None,
}

impl Direction {
    /// Every direction, in the order of their [`code`](Self::code)s `1, -1, 0`.
    pub const ALL: [Direction; 3] = [Direction::Ccw, Direction::Cw, Direction::None];

    /// `1` counter-clockwise, `-1` clockwise, `0` none (the solution map's
    /// `direction` column).
    pub fn code(self) -> i8 {
        match self {
            Direction::Ccw => 1,
            Direction::Cw => -1,
            Direction::None => 0,
        }
    }

    /// The direction of a code (`0` and anything else: none).
    pub fn from_code(code: i8) -> Self {
        match code {
            1 => Direction::Ccw,
            -1 => Direction::Cw,
            _ => Direction::None,
        }
    }

    /// `"ccw"`, `"cw"` or `"none"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Direction::Ccw => "ccw",
            Direction::Cw => "cw",
            Direction::None => "none",
        }
    }

    /// `1.0`, `-1.0` or `0.0`.
    pub fn sign(self) -> f64 {
        f64::from(self.code())
    }
}

impl core::fmt::Display for Direction {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// What a designer checks of one linkage built from a driving and a driven
/// dyad of a task (see the module docs for how each is computed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkageFigures {
    /// `[ground, crank, coupler, rocker]`.
    pub lengths: [f64; 4],
    /// Grashof type, the driving link being the input.
    pub grashof: Grashof,
    /// Whether the driving link turns fully.
    pub input_full: bool,
    /// The assembly mode at each pose (`None` at a toggle).
    pub modes: PerPose<Option<AssemblyMode>>,
    /// The input rotation that carries the coupler from pose 1 through the
    /// poses in order to the last.
    pub direction: Direction,
    /// Whether the input angles at the poses lie on one circuit (one arc of
    /// the input range; always true for an input that turns fully).
    pub one_circuit: bool,
    /// The smallest transmission angle over the travel from pose 1 through
    /// the poses to the last, radians in `[0, pi/2]`; NaN when there is no
    /// travel ([`Direction::None`]).
    pub min_transmission: f64,
    /// Longest over shortest link.
    pub link_ratio: f64,
}

impl LinkageFigures {
    /// Whether every pose is in one assembly mode (no branch defect, no
    /// toggle at a pose).
    pub fn branch_free(&self) -> bool {
        match self.modes.first() {
            Some(Some(m)) => self.modes.iter().all(|x| *x == Some(*m)),
            _ => false,
        }
    }

    /// Whether the motion through the poses in order is feasible:
    /// branch-free, one circuit, and a driving direction.
    pub fn feasible(&self) -> bool {
        self.branch_free() && self.one_circuit && self.direction != Direction::None
    }

    /// Whether the input link rocks between two dead positions (it does not
    /// turn fully).
    pub fn input_rocks(&self) -> bool {
        !self.input_full
    }

    /// How far the linkage is from the Grashof change point, as a part of
    /// the links' total length:
    ///
    /// ```text
    /// |s + l - p - q| / (s + l + p + q)     in [0, 1)
    /// ```
    ///
    /// (`s` shortest, `l` longest). Zero at a change point (every kite, two
    /// pairs of equal adjacent links, is one), where the type flips with
    /// the smallest error of a link and a fully turning input passes the
    /// flat position in which the linkage can switch circuits. The type
    /// holds for every set of link errors adding up to less than the margin
    /// times the links' total length (each link off by less than the margin
    /// times its own length); [`DesignLimits::min_grashof_margin`](crate::DesignLimits::min_grashof_margin)
    /// is the limit on it.
    pub fn grashof_margin(&self) -> f64 {
        super::grashof::grashof_margin_of(self.lengths)
    }
}

/// A monotone pseudo-angle of `v` measured counter-clockwise from `r`, in
/// `[0, 4)`.
#[inline(always)]
pub(crate) fn pseudo_angle(r: Vector2<f64>, v: Vector2<f64>) -> f64 {
    let x = r.dot(&v);
    let y = cross(r, v);
    let d = x.abs() + y.abs();
    if d == 0.0 {
        return 0.0;
    }
    let p = y / d;
    if x >= 0.0 {
        if y >= 0.0 { p } else { 4.0 + p }
    } else {
        2.0 - p
    }
}

/// The direction of a strictly monotone sequence (`None` otherwise).
#[inline(always)]
fn monotone(t: &[f64]) -> Direction {
    let up = t.windows(2).all(|w| w[0] < w[1]);
    let down = t.windows(2).all(|w| w[0] > w[1]);
    match (up, down) {
        (true, false) => Direction::Ccw,
        (false, true) => Direction::Cw,
        _ => Direction::None,
    }
}

/// The figures of the linkage `A0 A1 C1 C0`, with `A_k`, `C_k` the moving
/// pivots at the `N` poses; `None` when a link is not longer than `tiny`
/// or the lengths overflow.
///
/// Pseudo-angles are scale invariant, so no direction is normalized.
///
/// With `MODES = false` the assembly modes are not computed (all `None`):
/// the three-pose map takes its branch flag from the conic sweep instead.
#[inline]
pub(crate) fn figures<const MODES: bool, const N: usize>(
    a0: Point2<f64>,
    a: &[Point2<f64>; N],
    c0: Point2<f64>,
    c: &[Point2<f64>; N],
    tiny: f64,
) -> Option<LinkageFigures> {
    let ground = c0 - a0;
    let l1 = ground.norm();
    let l2 = (a[0] - a0).norm();
    let l3 = (c[0] - a[0]).norm();
    let l4 = (c[0] - c0).norm();
    let lengths = [l1, l2, l3, l4];
    if !(l1 > tiny && l2 > tiny && l3 > tiny && l4 > tiny && (l1 + l2 + l3 + l4).is_finite()) {
        return None;
    }
    // The mode at a pose: a pose's own loop clear of the toggle band by a
    // factor of 100 in sin(mu) (most of them) is clear in the position
    // analysis' loop too, which differs from it by the synthesis' rounding,
    // far inside that margin: its sign is the mode, decided without square
    // roots. Otherwise the position analysis itself decides: the linkage
    // `FourBar::from_pivots(a0, c0, l2, l3, l4)` (what `Task::four_bar`
    // builds) at the pose's input angle has a mode exactly when
    // `FourBar::solve` closes its loop clear of a toggle there, and the mode
    // is the one whose rocker joint is the pose's (the nearer of the two),
    // so that a reported mode always assembles and reaches the pose, and a
    // toggle is reported exactly where the position analysis reports one.
    let modes = PerPose::from_fn(N, |k| {
        if !MODES {
            return None;
        }
        let (u, w) = (c[k] - a[k], c[k] - c0);
        AssemblyMode::of_loop_well_clear(u, w, l1 + l2)
            .or_else(|| mode_by_position_analysis(a0, c0, [l2, l3, l4], a[k], c[k]))
    });
    let grashof = grashof_of(lengths);
    let bounds = input_bounds(lengths);
    let (lo_free, hi_free) = (bounds.lo_free, bounds.hi_free);
    let full = lo_free && hi_free;
    let g = ground;
    let e: [Vector2<f64>; N] = core::array::from_fn(|k| a[k] - a0);
    let last = N - 1;
    let trav = travel(&e, g, lo_free, hi_free);
    let (direction, one_circuit) = (trav.direction, trav.one_circuit);
    let min_transmission = if direction == Direction::None {
        f64::NAN
    } else {
        let inside = |v: Vector2<f64>| trav.contains(v);
        // |cos mu| at c = cos(theta - theta1) (module docs).
        let k0 = l1 * l1 + l2 * l2;
        let k1 = 2.0 * l1 * l2;
        let k2 = l3 * l3 + l4 * l4;
        let inv = 1.0 / (2.0 * l3 * l4);
        let cos_mu = |cc: f64| fmin(((k2 - (k0 - k1 * cc)) * inv).abs(), 1.0);
        let inv12 = 1.0 / (l1 * l2);
        let mut worst = fmax(
            cos_mu(g.dot(&e[0]) * inv12),
            cos_mu(g.dot(&e[last]) * inv12),
        );
        if inside(g) {
            worst = fmax(worst, cos_mu(1.0));
        }
        if inside(-g) {
            worst = fmax(worst, cos_mu(-1.0));
        }
        crate::simd::acos1(worst)
    };
    let min = fmin(fmin(l1, l2), fmin(l3, l4));
    let max = fmax(fmax(l1, l2), fmax(l3, l4));
    Some(LinkageFigures {
        lengths,
        grashof,
        input_full: full,
        modes,
        direction,
        one_circuit,
        min_transmission,
        link_ratio: max / min,
    })
}

/// The assembly mode at a pose near a toggle, by the position analysis:
/// the linkage with input pivot `a0`, output pivot `c0` and lengths
/// `[crank, coupler, rocker]` driven to the direction of `a - a0`; `None`
/// where [`FourBar::solve`] finds no position clear of a toggle there (out
/// of reach, indeterminate, or within the band), else the mode whose
/// rocker joint is nearer `c`, the pose's moving pivot.
#[cold]
fn mode_by_position_analysis(
    a0: Point2<f64>,
    c0: Point2<f64>,
    [crank, coupler, rocker]: [f64; 3],
    a: Point2<f64>,
    c: Point2<f64>,
) -> Option<AssemblyMode> {
    let fb = FourBar::from_pivots(a0, c0, crank, coupler, rocker).ok()?;
    let v = a - a0;
    let theta2 = v.y.atan2(v.x);
    let [open, crossed] = AssemblyMode::BOTH.map(|m| fb.solve(theta2, m).ok());
    let (open, crossed) = (open?, crossed?);
    // The toggle flag is the loop's, the same in both modes.
    if open.toggle || crossed.toggle {
        return None;
    }
    let d = |q: &crate::linkage::Configuration| (fb.joints(q).rocker_joint - c).norm_squared();
    Some(if d(&open) <= d(&crossed) {
        AssemblyMode::Open
    } else {
        AssemblyMode::Crossed
    })
}

/// [`figures`] (with the modes) for a slice of 3 to 5 poses.
pub(crate) fn figures_of(
    a0: Point2<f64>,
    a: &[Point2<f64>],
    c0: Point2<f64>,
    c: &[Point2<f64>],
    tiny: f64,
) -> Option<LinkageFigures> {
    match a.len() {
        3 => figures::<true, 3>(a0, a.try_into().ok()?, c0, c.try_into().ok()?, tiny),
        4 => figures::<true, 4>(a0, a.try_into().ok()?, c0, c.try_into().ok()?, tiny),
        5 => figures::<true, 5>(a0, a.try_into().ok()?, c0, c.try_into().ok()?, tiny),
        _ => None,
    }
}

/// The travel of an input link through the poses, as pseudo-angles from a
/// reference direction outside it (module docs: order and circuit).
pub(crate) struct Travel {
    /// The direction the pseudo-angles are measured from.
    pub(crate) reference: Vector2<f64>,
    /// The direction that carries the input through the poses in order.
    pub(crate) direction: Direction,
    /// Whether the poses lie on one circuit.
    pub(crate) one_circuit: bool,
    /// The travel's ends, `from <= to`, as pseudo-angles from `reference`.
    pub(crate) from: f64,
    /// See `from`.
    pub(crate) to: f64,
    /// Whether the input turns fully.
    pub(crate) full: bool,
}

impl Travel {
    /// Whether the direction `v` lies on the travel.
    #[inline(always)]
    pub(crate) fn contains(&self, v: Vector2<f64>) -> bool {
        let p = pseudo_angle(self.reference, v);
        (p >= self.from && p <= self.to) || (self.full && p == 0.0)
    }
}

/// The [`Travel`] of an input whose directions at the poses are `e` (any
/// lengths), whose range is symmetric about the axis `g` (the ground line
/// of a four-bar, the guide's normal of a slider-crank: the input closes
/// where `c = cos(theta - arg g)` lies in `[c_min, c_max]`), with
/// `lo_free` (`c_min <= -1`) and `hi_free` (`c_max >= 1`).
#[inline(always)]
pub(crate) fn travel<const N: usize>(
    e: &[Vector2<f64>; N],
    g: Vector2<f64>,
    lo_free: bool,
    hi_free: bool,
) -> Travel {
    let full = lo_free && hi_free;
    let last = N - 1;
    // The travel as pseudo-angles from a reference outside it: [from, to].
    let (reference, direction, one_circuit, from, to) = if full {
        let t: [f64; N] = core::array::from_fn(|k| pseudo_angle(e[0], e[k]));
        // Pose 1 at 0, the others strictly after it one way round.
        let dir = if t[1..].contains(&0.0) {
            Direction::None
        } else {
            monotone(&t[1..])
        };
        let (from, to) = if dir == Direction::Ccw {
            (0.0, t[last])
        } else {
            (t[last], 4.0)
        };
        (e[0], dir, true, from, to)
    } else {
        // The dead zone: around -g when the input rocks about g, around g
        // otherwise (one arc about g + pi, or the two arcs off the ground line).
        let reference = if hi_free { -g } else { g };
        let t: [f64; N] = core::array::from_fn(|k| pseudo_angle(reference, e[k]));
        let one_circuit = if !hi_free && !lo_free {
            // Two arcs: one on each side of the ground line.
            let side = cross(g, e[0]) > 0.0;
            e.iter().all(|ek| (cross(g, *ek) > 0.0) == side)
        } else {
            true
        };
        let dir = if one_circuit {
            monotone(&t)
        } else {
            Direction::None
        };
        (
            reference,
            dir,
            one_circuit,
            t[0].min(t[last]),
            t[0].max(t[last]),
        )
    };
    Travel {
        reference,
        direction,
        one_circuit,
        from,
        to,
        full,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pseudo_angle_is_monotone() {
        let r = Vector2::new(1.0, 0.0);
        let mut last = -1.0;
        for k in 0..360 {
            let a = (k as f64).to_radians();
            let p = pseudo_angle(r, Vector2::new(a.cos(), a.sin()));
            assert!(p > last, "{k}: {p} <= {last}");
            assert!((0.0..4.0).contains(&p));
            last = p;
        }
    }

    #[test]
    fn monotone_sequences() {
        assert_eq!(monotone(&[0.1, 0.5, 2.0]), Direction::Ccw);
        assert_eq!(monotone(&[3.0, 0.5]), Direction::Cw);
        assert_eq!(monotone(&[0.1, 0.5, 0.3]), Direction::None);
        assert_eq!(monotone(&[0.5, 0.5]), Direction::None);
        for d in Direction::ALL {
            assert_eq!(Direction::from_code(d.code()), d);
        }
    }
}
