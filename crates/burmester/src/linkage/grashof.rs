//! The Grashof type of a four-bar and where its input link can be: all the
//! way round, or one or two arcs bounded by dead (toggle) positions.

use core::f64::consts::TAU;

use crate::tolerance;

/// Grashof type of a four-bar, the input being the crank link.
///
/// With `s` the shortest, `l` the longest and `p`, `q` the other two links,
/// the linkage is Grashof when `s + l < p + q` (some link turns fully), a
/// change point when `s + l = p + q` (within rounding), and non-Grashof
/// otherwise. A Grashof linkage is named after its shortest link.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Grashof {
    /// Grashof, crank shortest: the input turns fully, the output rocks.
    CrankRocker,
    /// Grashof, ground shortest: both the input and the output turn fully (drag link).
    DoubleCrank,
    /// Grashof, rocker shortest: the output turns fully, the input rocks.
    RockerCrank,
    /// Grashof, coupler shortest: both the input and the output rock; the coupler turns fully.
    DoubleRocker,
    /// Non-Grashof (`s + l > p + q`): no link turns fully relative to another.
    TripleRocker,
    /// `s + l = p + q`: the linkage passes through a flat (change point)
    /// position where it can switch assembly modes.
    ChangePoint,
}

impl Grashof {
    /// Every class, in the order of their codes in a solution map.
    pub const ALL: [Grashof; 6] = [
        Grashof::CrankRocker,
        Grashof::DoubleCrank,
        Grashof::RockerCrank,
        Grashof::DoubleRocker,
        Grashof::TripleRocker,
        Grashof::ChangePoint,
    ];

    /// The code of the class in a solution map's `grashof` column: its
    /// index in [`Grashof::ALL`].
    pub fn code(self) -> u8 {
        match self {
            Grashof::CrankRocker => 0,
            Grashof::DoubleCrank => 1,
            Grashof::RockerCrank => 2,
            Grashof::DoubleRocker => 3,
            Grashof::TripleRocker => 4,
            Grashof::ChangePoint => 5,
        }
    }

    /// The class of a code (`None` for a code of no class, such as
    /// `SolutionMap::GRASHOF_NONE`).
    pub fn from_code(code: u8) -> Option<Self> {
        Grashof::ALL.get(usize::from(code)).copied()
    }

    /// The name used in the Python API: `"crank-rocker"`, `"double-crank"`,
    /// `"rocker-crank"`, `"double-rocker"`, `"triple-rocker"` or `"change-point"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Grashof::CrankRocker => "crank-rocker",
            Grashof::DoubleCrank => "double-crank",
            Grashof::RockerCrank => "rocker-crank",
            Grashof::DoubleRocker => "double-rocker",
            Grashof::TripleRocker => "triple-rocker",
            Grashof::ChangePoint => "change-point",
        }
    }

    /// Whether `s + l < p + q` strictly (some link turns fully and the
    /// linkage never reaches a change point).
    pub fn is_grashof(self) -> bool {
        !matches!(self, Grashof::TripleRocker | Grashof::ChangePoint)
    }
}

impl core::fmt::Display for Grashof {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A closed interval of angles, counter-clockwise from `start` to `end`
/// (`start <= end < start + 2 pi`), in radians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleInterval {
    /// Where the interval starts.
    pub start: f64,
    /// Where it ends, counter-clockwise from `start`.
    pub end: f64,
}

impl AngleInterval {
    /// The angular width `end - start`.
    pub fn span(&self) -> f64 {
        self.end - self.start
    }

    /// The middle angle.
    pub fn mid(&self) -> f64 {
        0.5 * (self.start + self.end)
    }

    /// Whether `angle` (any multiple of `2 pi` added) lies in the interval.
    pub fn contains(&self, angle: f64) -> bool {
        let t = (angle - self.start).rem_euclid(TAU);
        t <= self.span()
    }
}

/// Where the input link can be: all the way round, or one or two arcs
/// bounded by dead (toggle) positions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum InputRange {
    /// The input turns fully.
    Full,
    /// The input rocks within one arc.
    Arc(AngleInterval),
    /// The input rocks within one of two arcs, mirror images across the
    /// ground line (a Grashof double-rocker's two circuits).
    TwoArcs(AngleInterval, AngleInterval),
}

impl InputRange {
    /// Whether the input can reach `theta2`.
    pub fn contains(&self, theta2: f64) -> bool {
        match self {
            InputRange::Full => true,
            InputRange::Arc(a) => a.contains(theta2),
            InputRange::TwoArcs(a, b) => a.contains(theta2) || b.contains(theta2),
        }
    }

    /// Whether the input turns fully.
    pub fn is_full(&self) -> bool {
        matches!(self, InputRange::Full)
    }

    /// The arcs as an array of up to two, with their count.
    pub fn arcs_array(&self) -> ([AngleInterval; 2], usize) {
        let zero = AngleInterval {
            start: 0.0,
            end: 0.0,
        };
        match *self {
            InputRange::Full => ([zero; 2], 0),
            InputRange::Arc(a) => ([a, zero], 1),
            InputRange::TwoArcs(a, b) => ([a, b], 2),
        }
    }

    /// The dead positions: the input angles that bound the arcs (empty when
    /// the input turns fully).
    pub fn dead_positions(&self) -> Vec<f64> {
        let (arcs, n) = self.arcs_array();
        arcs[..n].iter().flat_map(|a| [a.start, a.end]).collect()
    }
}

/// Grashof type of the positive, finite lengths `[ground, crank, coupler,
/// rocker]` (see [`FourBar::grashof`](crate::FourBar::grashof)): the one
/// Grashof test of the crate, branch-light because the solution maps call it
/// per sample. The equality `s + l = p + q` is decided within
/// [`tolerance::ROUNDING_EPS`] of the sum; equal shortest links name the
/// class in the order ground, crank, coupler, rocker.
#[inline(always)]
pub(crate) fn grashof_of(lengths: [f64; 4]) -> Grashof {
    let [l1, l2, l3, _] = lengths;
    let Sides { min, lhs, rhs, sum } = sides(lengths);
    let tol = tolerance::ROUNDING_EPS * f64::EPSILON * sum;
    if (lhs - rhs).abs() <= tol {
        Grashof::ChangePoint
    } else if lhs > rhs {
        Grashof::TripleRocker
    } else if l1 == min {
        Grashof::DoubleCrank
    } else if l2 == min {
        Grashof::CrankRocker
    } else if l3 == min {
        Grashof::DoubleRocker
    } else {
        Grashof::RockerCrank
    }
}

/// The Grashof margin of the positive, finite lengths `[ground, crank,
/// coupler, rocker]`: how far the linkage is from the change point, as a
/// part of the links' total length,
///
/// ```text
/// margin = |s + l - p - q| / (s + l + p + q)     in [0, 1)
/// ```
///
/// with `s` the shortest, `l` the longest and `p`, `q` the other two links
/// (zero at a change point, such as every kite: two pairs of equal
/// adjacent links). The sum is the tolerance it stands for: along any
/// change of the lengths, `s + l - p - q` (continuous, and on each piece
/// of the order of the links a sum of the four lengths with signs `+ + - -`)
/// moves by at most the sum of the links' errors, so the type (and the
/// linkage's distance from a change point) survives every error of the
/// links that adds up to less than `margin` times their total length: in
/// particular every link off by less than `margin` times its own length.
/// Computed as [`grashof_of`] sums (the same bits in the solution maps'
/// lanes).
#[inline(always)]
pub(crate) fn grashof_margin_of(lengths: [f64; 4]) -> f64 {
    let Sides { lhs, rhs, sum, .. } = sides(lengths);
    (lhs - rhs).abs() / sum
}

/// The two sides of Grashof's inequality of `[ground, crank, coupler,
/// rocker]`: `s + l` and `p + q`, with the shortest link and the sum (one
/// arithmetic for [`grashof_of`] and [`grashof_margin_of`], the same
/// operations in the same order as the solution maps' lanes).
struct Sides {
    min: f64,
    lhs: f64,
    rhs: f64,
    sum: f64,
}

#[inline(always)]
fn sides(lengths: [f64; 4]) -> Sides {
    let [l1, l2, l3, l4] = lengths;
    let max = fmax(fmax(l1, l2), fmax(l3, l4));
    let min = fmin(fmin(l1, l2), fmin(l3, l4));
    let sum = l1 + l2 + l3 + l4;
    let lhs = min + max;
    Sides {
        min,
        lhs,
        rhs: sum - lhs,
        sum,
    }
}

/// `max(a, b)` for numbers known not to be NaN (no branch on NaN).
#[inline(always)]
pub(crate) fn fmax(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

/// `min(a, b)` for numbers known not to be NaN.
#[inline(always)]
pub(crate) fn fmin(a: f64, b: f64) -> f64 {
    if a < b { a } else { b }
}

/// Where the loop closes, as bounds on `c = cos(theta2 - theta1)`, and
/// whether each bound is beyond `-1` / `1` (within rounding).
#[derive(Debug, Clone, Copy)]
pub(crate) struct InputBounds {
    pub(crate) c_min: f64,
    pub(crate) c_max: f64,
    /// `c_min <= -1`: the input passes `theta1 + pi`.
    pub(crate) lo_free: bool,
    /// `c_max >= 1`: the input passes `theta1`.
    pub(crate) hi_free: bool,
}

/// The input bounds of the lengths `[ground, crank, coupler, rocker]` (see
/// [`FourBar::input_range`](crate::FourBar::input_range)); any positive scale.
pub(crate) fn input_bounds(lengths: [f64; 4]) -> InputBounds {
    // In units of the longer of ground and crank, so that neither the
    // squares nor `2 L1 L2` underflow (the link ratio is finite). A square
    // of `L3 + L4` may overflow to infinity: then `c_min` is `-inf` and the
    // bound is reached, as it should be.
    let [l1, l2, l3, l4] = lengths;
    let m = l1.max(l2);
    let (g, c) = (l1 / m, l2 / m);
    let (sum, diff) = (l3 / m + l4 / m, l3 / m - l4 / m);
    let base = g * g + c * c;
    let two = 2.0 * g * c;
    let rounding = tolerance::ROUNDING_EPS * f64::EPSILON / two;
    let c_min = (base - sum * sum) / two;
    let c_max = (base - diff * diff) / two;
    InputBounds {
        c_min,
        c_max,
        lo_free: c_min <= -1.0 + rounding * (base + sum * sum),
        hi_free: c_max >= 1.0 - rounding * (base + diff * diff),
    }
}
