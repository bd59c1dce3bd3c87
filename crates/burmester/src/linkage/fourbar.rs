//! Four-bar position analysis: both assembly modes in closed form, toggle
//! positions, Grashof type, input range, transmission angle, joints and
//! coupler-point paths.
//!
//! # Conventions
//!
//! The ground link runs from the input pivot `O2` to the output pivot `O4`
//! at the angle `theta1`; the crank `L2` turns about `O2`, the rocker `L4`
//! about `O4`, and the coupler `L3` joins the crank tip `A` to the rocker tip
//! `B`. All angles are absolute (measured from the fixed +x axis,
//! counter-clockwise, in radians), so that the loop reads
//!
//! ```text
//! L2 e^{i theta2} + L3 e^{i theta3} - L1 e^{i theta1} - L4 e^{i theta4} = 0
//! ```
//!
//! With the default placement (`O2` at the origin, ground along +x) this is
//! the textbook form with `theta1 = 0` (Norton, *Design of Machinery*, §4.5).
//!
//! # The closed form
//!
//! The textbook solution substitutes `t = tan(theta/2)` and solves a
//! quadratic `a t^2 + b t + c = 0`; it divides by `2a`, which is zero exactly
//! when the answer is `theta = pi`, and its choice of root does not always
//! match the assembly mode. This module intersects the two circles instead.
//! With `d = O4 - A` and `r = |d|`, Heron's product
//!
//! ```text
//! H = ((L3 + L4)^2 - r^2) (r^2 - (L3 - L4)^2)   (= 16 area^2 of triangle A B O4)
//! ```
//!
//! is negative where the loop does not close and zero at a toggle. Then
//!
//! ```text
//! v3 = d (L3^2 - L4^2 + r^2) + s sqrt(H) i d      theta3 = atan2(v3)
//! v4 = d (L3^2 - L4^2 - r^2) + s sqrt(H) i d      theta4 = atan2(v4)
//! ```
//!
//! with `s = +1` for [`AssemblyMode::Open`] and `-1` for
//! [`AssemblyMode::Crossed`]; `cross(v3, v4) = 2 s r^4 sqrt(H)`, so the mode
//! is the sign of `sin(theta4 - theta3)` by construction, for every linkage
//! including parallelograms and kites. No division occurs, and every angle,
//! `pi` included, comes out of `atan2`. The lengths are scaled by the longest
//! link first, so no product overflows or underflows at any size.
//!
//! The `atan2` is the crate's lane `atan2` (module `simd`: Cephes'
//! rational approximation as Agner Fog's vector class library and `wide`
//! write it, unfused, within 2 ulp of `libm`'s), here on plain `f64`;
//! `sin` and `cos` of the input come from `libm`. [`FourBar::solve_into`]
//! runs the same arithmetic on SIMD lanes picked at run time ([`pulp`]:
//! four angles at a time with AVX2), and in parallel on large inputs, so
//! that it gives the bits of [`FourBar::solve`] on every CPU.
//!
//! A toggle is reported where `|H|` is within its rounding of zero, the
//! crate's one toggle criterion [`tolerance::heron_tolerance`] (derived
//! there): `|H| <= tol`, with the rounding of `r` taken from the ground and
//! the crank it is formed from (`rho = L1 + L2`). Since
//! `sqrt(H) = 2 L3 L4 |sin mu|` (`mu` the transmission angle), in angle
//! terms (see [`AssemblyMode::of_loop`], which decides the mode of a built
//! linkage at a pose by the same bound):
//!
//! ```text
//! |sin mu| <= sqrt(tol) / (2 L3 L4)       (tolerance::toggle_band)
//! ```
//!
//! about `1e-7` rad for links of one size, growing like the square root of
//! the link ratio (`2e-3` at `1e9`): the width of the rounding, not more. A
//! loop that misses closing by less than `tol` (`H >= -tol`) closes at the
//! toggle. Inside the band the answer keeps the asked mode's sign (the loop
//! is not snapped to the toggle), so a pose reached there is still reached
//! to rounding.

use core::f64::consts::{PI, TAU};

use nalgebra::{Point2, Vector2};
use pulp::{Arch, Simd, WithSimd};
use rayon::prelude::*;

use crate::error::{AssemblyError, Error, InvalidInput, Result, finite, positive};
use crate::geom::{cross, normalized, point_is_finite, rotate, unit, wrap_angle};
use crate::linkage::grashof::{InputBounds, grashof_of, input_bounds};
use crate::linkage::{AngleInterval, Grashof, InputRange};
use crate::simd::{M, Ops, Pair, V, atan2};
use crate::tolerance;

/// The two ways to close the loop at one input angle.
///
/// Named by the sign of `sin(theta4 - theta3)`, the angle from the coupler
/// to the rocker: positive is [`Open`](AssemblyMode::Open) (Norton's "open"
/// circuit for the usual layout), negative is
/// [`Crossed`](AssemblyMode::Crossed).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AssemblyMode {
    /// `sin(theta4 - theta3) > 0`.
    Open,
    /// `sin(theta4 - theta3) < 0`.
    Crossed,
}

impl AssemblyMode {
    /// Both modes, open first.
    pub const BOTH: [AssemblyMode; 2] = [AssemblyMode::Open, AssemblyMode::Crossed];

    /// `+1.0` for open, `-1.0` for crossed.
    #[inline]
    pub fn sign(self) -> f64 {
        match self {
            AssemblyMode::Open => 1.0,
            AssemblyMode::Crossed => -1.0,
        }
    }

    /// The other mode.
    #[inline]
    #[must_use]
    pub fn other(self) -> Self {
        match self {
            AssemblyMode::Open => AssemblyMode::Crossed,
            AssemblyMode::Crossed => AssemblyMode::Open,
        }
    }

    /// The mode whose sign is the sign of `value`, or `None` for zero or NaN.
    pub fn from_sign(value: f64) -> Option<Self> {
        if value > 0.0 {
            Some(AssemblyMode::Open)
        } else if value < 0.0 {
            Some(AssemblyMode::Crossed)
        } else {
            None
        }
    }

    /// The mode of a closed loop from its coupler vector (crank joint to
    /// rocker joint) and its rocker vector (output pivot to rocker joint):
    /// the sign of `cross(coupler, rocker)`, the sign of
    /// `sin(theta4 - theta3)`; `None` (a toggle) where the transmission
    /// angle is within the crate's one toggle band (module docs,
    /// [`tolerance::heron_tolerance`]): `4 cross(u, w)^2 <= tol`, the bound
    /// under which [`FourBar::solve`] reports `toggle`, with the vectors'
    /// own size `|u| + |w|` as the size they were formed from
    /// ([`of_loop_within`](Self::of_loop_within) takes it). The one
    /// assembly-mode test of the crate: the synthesized linkages and the
    /// solution maps use it at every pose.
    ///
    /// ```
    /// use burmester::{AssemblyMode, Vector2};
    /// let m = AssemblyMode::of_loop(Vector2::new(1.0, 0.0), Vector2::new(0.0, 2.0));
    /// assert_eq!(m, Some(AssemblyMode::Open));
    /// assert_eq!(AssemblyMode::of_loop(Vector2::new(1.0, 0.0), Vector2::new(3.0, 0.0)), None);
    /// ```
    #[inline(always)]
    pub fn of_loop(coupler: Vector2<f64>, rocker: Vector2<f64>) -> Option<Self> {
        Self::of_loop_scaled(coupler, rocker, None, 1.0)
    }

    /// [`of_loop`](Self::of_loop) for vectors formed from vectors of size
    /// up to `reach` (the ground plus the crank, `L1 + L2`, for the loop
    /// of a linkage: the `rho` of [`tolerance::heron_tolerance`]), whose
    /// rounding widens the band as it widens [`FourBar::solve`]'s.
    ///
    /// ```
    /// use burmester::{AssemblyMode, Vector2};
    /// // A 49 degree transmission angle on links 1e7 apart has a mode.
    /// let (u, w) = (Vector2::new(1.0, 0.0), Vector2::new(-0.65e-7, 0.76e-7));
    /// assert_eq!(AssemblyMode::of_loop_within(u, w, 2.0), Some(AssemblyMode::Open));
    /// ```
    #[inline(always)]
    pub fn of_loop_within(coupler: Vector2<f64>, rocker: Vector2<f64>, reach: f64) -> Option<Self> {
        Self::of_loop_scaled(coupler, rocker, Some(reach), 1.0)
    }

    /// The mode of [`of_loop_within`](Self::of_loop_within) where the loop
    /// is clear of its toggle band by a factor of 100 in `sin mu` (decided
    /// by a bound without square roots), else `None`: the fast path of the
    /// figures, which check the rest by the position analysis' loop. The
    /// factor covers the difference between a pose's loop and the position
    /// analysis' loop at the pose (the synthesis' rounding: lengths that
    /// differ from pose 1's by up to about `1e4 eps` relative, which moves
    /// `sin mu` near a toggle by the square root of that).
    #[inline(always)]
    pub(crate) fn of_loop_well_clear(
        coupler: Vector2<f64>,
        rocker: Vector2<f64>,
        reach: f64,
    ) -> Option<Self> {
        Self::of_loop_scaled(coupler, rocker, Some(reach), 1e4)
    }

    /// [`of_loop_within`](Self::of_loop_within), the reach `|u| + |w|`
    /// where `None` (taken after scaling, so that it does not overflow);
    /// with `margin > 1`, only the mode of a loop clear of `margin` times
    /// the bound without square roots (`None` otherwise).
    #[inline(always)]
    fn of_loop_scaled(
        coupler: Vector2<f64>,
        rocker: Vector2<f64>,
        reach: Option<f64>,
        margin: f64,
    ) -> Option<Self> {
        // In units of the largest component where a four-fold product could
        // leave the range of doubles (zero, NaN and infinite vectors: NaN).
        let m = (coupler.x.abs().max(coupler.y.abs())).max(rocker.x.abs().max(rocker.y.abs()));
        let k = if (SAFE_MIN..=SAFE_MAX).contains(&m) {
            1.0
        } else {
            1.0 / m
        };
        let (u, w) = (coupler * k, rocker * k);
        let s = cross(u, w);
        let (u2, w2) = (u.norm_squared(), w.norm_squared());
        let r2 = (u - w).norm_squared();
        // A bound of the tolerance without square roots: A, B >= 0 with
        // A + B = 4 |u| |w| <= 2 (u2 + w2), and each E below
        // (|u| + |w|)^2 + r^2 + r^2 + rho^2 <= 2 (u2 + w2) + 2 r2 + rho^2.
        let kk = tolerance::LOOP_EPS * f64::EPSILON;
        let rho2 = reach.map_or(2.0 * (u2 + w2), |r| (r * k) * (r * k));
        let e_up = 2.0 * (u2 + w2) + 2.0 * r2 + rho2;
        let tol_up = kk * 2.0 * (u2 + w2) * e_up + kk * kk * e_up * e_up;
        if 4.0 * s * s > margin * tol_up {
            return AssemblyMode::from_sign(s);
        }
        if margin > 1.0 {
            return None;
        }
        let (p, dot) = ((u2 * w2).sqrt(), u.dot(&w));
        // Heron's factors from the vectors (no cancellation of squares):
        // A = 2 L3 L4 (1 + cos phi), B = 2 L3 L4 (1 - cos phi).
        let (a, b) = (2.0 * (p + dot), 2.0 * (p - dot));
        // (L3 + L4)^2 and |L3^2 - L4^2| from the squares.
        let (sum2, diffsum) = (u2 + w2 + 2.0 * p, (u2 - w2).abs());
        let rho = reach.map_or_else(|| u2.sqrt() + w2.sqrt(), |r| r * k);
        let tol = tolerance::heron_tolerance(sum2, diffsum, r2, rho, a, b);
        // Not `<=`: NaN (zero vectors, `m = 0`) is a toggle too (no mode).
        if 4.0 * s * s > tol {
            AssemblyMode::from_sign(s)
        } else {
            None
        }
    }
}

crate::geom::str_names!(
    /// `"open"` or `"crossed"`.
    AssemblyMode {
        Open => "open",
        Crossed => "crossed",
    }
);

impl core::str::FromStr for AssemblyMode {
    type Err = InvalidInput;

    /// Parses `"open"` or `"crossed"` (ASCII case-insensitive).
    fn from_str(s: &str) -> Result<Self, InvalidInput> {
        if s.eq_ignore_ascii_case("open") {
            Ok(AssemblyMode::Open)
        } else if s.eq_ignore_ascii_case("crossed") {
            Ok(AssemblyMode::Crossed)
        } else {
            Err(InvalidInput::UnknownName {
                what: "assembly mode",
                expected: "\"open\" or \"crossed\"",
                found: s.to_owned(),
            })
        }
    }
}

/// One solved position of a four-bar.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Configuration {
    /// Input (crank) angle, as given.
    pub theta2: f64,
    /// Coupler angle, in `(-pi, pi]`.
    pub theta3: f64,
    /// Output (rocker) angle, in `(-pi, pi]`.
    pub theta4: f64,
    /// The assembly mode that was asked for.
    pub mode: AssemblyMode,
    /// True at a toggle (dead) position, where the two modes meet: coupler
    /// and rocker are collinear and `sin(theta4 - theta3)` is zero within
    /// rounding, so both modes give this same answer.
    pub toggle: bool,
}

impl Configuration {
    /// The angle from the coupler to the rocker, `theta4 - theta3` wrapped
    /// into `(-pi, pi]`; its sign is the assembly mode.
    pub fn coupler_rocker_angle(&self) -> f64 {
        wrap_angle(self.theta4 - self.theta3)
    }

    /// The transmission angle: the acute angle between coupler and rocker,
    /// in `[0, pi/2]` (`pi/2` is ideal, `0` is a toggle).
    ///
    /// ```text
    /// mu = |theta4 - theta3| (wrapped to [0, pi]), folded: min(mu, pi - mu)
    /// ```
    pub fn transmission_angle(&self) -> f64 {
        let mu = self.coupler_rocker_angle().abs();
        mu.min(PI - mu)
    }
}

/// Where the four joints are in one configuration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Joints {
    /// The input (crank) pivot `O2`, fixed.
    pub input_pivot: Point2<f64>,
    /// The crank tip `A`, joining crank and coupler.
    pub crank_joint: Point2<f64>,
    /// The rocker tip `B`, joining coupler and rocker.
    pub rocker_joint: Point2<f64>,
    /// The output (rocker) pivot `O4`, fixed.
    pub output_pivot: Point2<f64>,
}

impl Joints {
    /// Where a point fixed to the coupler is. `local` is given in the
    /// coupler frame: origin at the crank joint `A`, x-axis toward the rocker
    /// joint `B`.
    pub fn coupler_point(&self, local: Vector2<f64>) -> Point2<f64> {
        let ab = self.rocker_joint - self.crank_joint;
        // The coupler has a length, so `ab` is not zero (scaled: no underflow).
        let e = normalized(ab).unwrap_or_else(Vector2::x);
        self.crank_joint
            + Vector2::new(e.x * local.x - e.y * local.y, e.y * local.x + e.x * local.y)
    }
}

/// The loop closed at one input angle, before any angle is computed.
#[derive(Debug, Clone, Copy)]
struct Closed {
    /// `e^{i theta2}`.
    crank_dir: Vector2<f64>,
    /// A vector along the coupler, `A -> B`.
    v3: Vector2<f64>,
    /// A vector along the rocker, `O4 -> B`.
    v4: Vector2<f64>,
    toggle: bool,
}

/// The arithmetic of closing the loop, before any check
/// ([`FourBar::loop_vectors`]), on the lanes of `S` (plain `f64` for
/// [`pulp::Scalar`]).
#[derive(Clone, Copy)]
struct LoopVectors<S: Simd> {
    /// `|O4 - A|^2`, in units of `scale^2`.
    r2: V<S>,
    /// Heron's product `H` (module docs).
    heron: V<S>,
    /// The rounding band of `H`.
    tol: V<S>,
    /// A vector along the coupler, `A -> B`.
    v3: [V<S>; 2],
    /// A vector along the rocker, `O4 -> B`.
    v4: [V<S>; 2],
}

impl<S: Simd> LoopVectors<S> {
    /// Whether `v3` or `v4` vanished (the indeterminate case of
    /// [`FourBar::solve`]).
    #[inline(always)]
    fn degenerate(&self, o: Ops<S>) -> M<S> {
        let zero = o.sp(0.0);
        let [x3, y3] = self.v3;
        let [x4, y4] = self.v4;
        o.or(
            o.and(o.eq(x3, zero), o.eq(y3, zero)),
            o.and(o.eq(x4, zero), o.eq(y4, zero)),
        )
    }
}

/// Angles per parallel task of [`FourBar::solve_into`].
const SOLVE_CHUNK: usize = 1 << 12;
/// From this many angles on, [`FourBar::solve_into`] runs in parallel.
const SOLVE_PARALLEL_MIN: usize = 1 << 14;

/// A planar four-bar linkage.
///
/// Built from its four link lengths, and placed by its input pivot and the
/// direction of its ground link (default: the origin and +x).
///
/// # Example
///
/// ```
/// use burmester::{AssemblyMode, FourBar};
/// // Norton, Design of Machinery, Example 4-1.
/// let fb = FourBar::new(100.0, 40.0, 120.0, 80.0)?;
/// let c = fb.solve(40f64.to_radians(), AssemblyMode::Open)?;
/// assert!((c.theta3.to_degrees() - 20.298).abs() < 5e-4);
/// assert!((c.theta4.to_degrees() - 57.325).abs() < 5e-4);
/// # Ok::<(), burmester::Error>(())
/// ```
#[derive(Clone, Copy, PartialEq)]
pub struct FourBar {
    ground: f64,
    crank: f64,
    coupler: f64,
    rocker: f64,
    origin: Point2<f64>,
    ground_angle: f64,
    /// Lengths divided by `scale`, the longest link: the arithmetic runs at
    /// unit size, so no product of lengths overflows or underflows.
    scale: f64,
    /// `ground / scale` times the ground's unit direction.
    g_vec: Vector2<f64>,
    c_n: f64,
    sum_n: f64,
    diff_n: f64,
    /// `(L3^2 - L4^2) / scale^2`.
    sq_diff_n: f64,
    /// `(L1 + L2) / scale`: the size of the vectors the crank tip's
    /// distance to the output pivot is formed from (the `rho` of
    /// [`tolerance::heron_tolerance`]).
    rho_n: f64,
}

crate::geom::debug_shows!(
    /// The lengths, the fixed pivots and the Grashof type, not the normalized
    /// quantities the solver keeps.
    FourBar, l =>
    ground: l.ground,
    crank: l.crank,
    coupler: l.coupler,
    rocker: l.rocker,
    input_pivot: l.origin,
    output_pivot: l.output_pivot(),
    grashof: l.grashof(),
);

impl FourBar {
    /// The largest extent of a linkage: the input pivot's distance from the
    /// origin (as `|x| + |y|`) plus the four lengths. Larger linkages are
    /// rejected, so that no joint position overflows.
    pub const MAX_EXTENT: f64 = 1e300;

    /// A four-bar from its ground, crank (input), coupler and rocker
    /// (output) lengths, with the input pivot at the origin and the ground
    /// along +x.
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] when a length is zero, negative, NaN or infinite,
    /// or the linkage is larger than [`FourBar::MAX_EXTENT`] or its link ratio
    /// overflows; [`AssemblyError::NeverCloses`] when the longest link is longer than
    /// the other three together (no input angle closes the loop).
    pub fn new(ground: f64, crank: f64, coupler: f64, rocker: f64) -> Result<Self> {
        Self::placed(ground, crank, coupler, rocker, Point2::origin(), 0.0)
    }

    /// A four-bar with its input pivot at `origin` and its ground link at
    /// `ground_angle` radians from +x.
    ///
    /// # Errors
    ///
    /// As [`FourBar::new`], and [`InvalidInput::NotFinite`] for a
    /// non-finite origin or angle.
    pub fn placed(
        ground: f64,
        crank: f64,
        coupler: f64,
        rocker: f64,
        origin: Point2<f64>,
        ground_angle: f64,
    ) -> Result<Self> {
        let ([ground, crank, coupler, rocker], scale) =
            Self::checked([ground, crank, coupler, rocker], origin, ground_angle)?;
        let [g, c, l3, l4] = [ground, crank, coupler, rocker].map(|l| l / scale);
        Ok(FourBar {
            ground,
            crank,
            coupler,
            rocker,
            origin,
            ground_angle,
            scale,
            g_vec: unit(ground_angle) * g,
            c_n: c,
            sum_n: l3 + l4,
            diff_n: l3 - l4,
            sq_diff_n: (l3 - l4) * (l3 + l4),
            rho_n: g + c,
        })
    }

    /// The checks of [`FourBar::placed`], in its order: its lengths and
    /// their largest (`scale`), or its error.
    fn checked(
        [ground, crank, coupler, rocker]: [f64; 4],
        origin: Point2<f64>,
        ground_angle: f64,
    ) -> Result<([f64; 4], f64)> {
        let ground = positive("ground length", ground)?;
        let crank = positive("crank length", crank)?;
        let coupler = positive("coupler length", coupler)?;
        let rocker = positive("rocker length", rocker)?;
        finite("origin x", origin.x)?;
        finite("origin y", origin.y)?;
        finite("ground angle", ground_angle)?;
        let links = [ground, crank, coupler, rocker];
        let scale = links.iter().copied().fold(0.0, f64::max);
        // Every joint lies within `extent` of the fixed frame's origin; past
        // `MAX_EXTENT` a joint or a length of two joints could overflow.
        let extent = origin.x.abs() + origin.y.abs() + links.iter().sum::<f64>();
        let shortest = links.iter().copied().fold(f64::INFINITY, f64::min);
        if extent.is_nan() || extent > Self::MAX_EXTENT {
            return Err(InvalidInput::TooLarge {
                name: "linkage size (the origin's distance plus the four lengths)",
                value: extent,
                limit: Self::MAX_EXTENT,
                hint: "rescale the linkage",
            }
            .into());
        }
        if !(scale / shortest).is_finite() {
            return Err(InvalidInput::TooLarge {
                name: "ratio of the longest to the shortest link",
                value: scale / shortest,
                limit: f64::MAX,
                hint: "pass lengths of comparable sizes",
            }
            .into());
        }
        let [g, c, l3, l4] = links.map(|l| l / scale);
        let sum_n = g + c + l3 + l4;
        // The longest link is 1 in units of `scale`.
        let others = sum_n - 1.0;
        if 1.0 > others * (1.0 + tolerance::ROUNDING_EPS * f64::EPSILON) {
            return Err(AssemblyError::NeverCloses {
                longest: scale,
                others: others * scale,
            }
            .into());
        }
        Ok((links, scale))
    }

    /// A four-bar between two given fixed pivots: the ground length and
    /// angle come from `input_pivot` and `output_pivot`.
    ///
    /// # Errors
    ///
    /// As [`FourBar::placed`]; the pivots must be finite and distinct.
    pub fn from_pivots(
        input_pivot: Point2<f64>,
        output_pivot: Point2<f64>,
        crank: f64,
        coupler: f64,
        rocker: f64,
    ) -> Result<Self> {
        if !point_is_finite(&input_pivot) || !point_is_finite(&output_pivot) {
            let bad = [input_pivot.x, input_pivot.y, output_pivot.x, output_pivot.y]
                .into_iter()
                .find(|v| !v.is_finite())
                .unwrap_or(f64::NAN);
            return Err(InvalidInput::NotFinite {
                name: "fixed pivot coordinate",
                value: bad,
            }
            .into());
        }
        let d = output_pivot - input_pivot;
        let ground = d.norm();
        Self::placed(ground, crank, coupler, rocker, input_pivot, d.y.atan2(d.x))
    }

    /// Whether [`FourBar::placed`] builds a linkage of these lengths at
    /// `origin`: its checks, at a finite ground angle.
    pub(crate) fn lengths_ok(
        ground: f64,
        crank: f64,
        coupler: f64,
        rocker: f64,
        origin: Point2<f64>,
    ) -> bool {
        Self::checked([ground, crank, coupler, rocker], origin, 0.0).is_ok()
    }

    /// Ground length `L1` (input pivot to output pivot).
    pub fn ground(&self) -> f64 {
        self.ground
    }
    /// Crank (input) length `L2`.
    pub fn crank(&self) -> f64 {
        self.crank
    }
    /// Coupler length `L3`.
    pub fn coupler(&self) -> f64 {
        self.coupler
    }
    /// Rocker (output) length `L4`.
    pub fn rocker(&self) -> f64 {
        self.rocker
    }
    /// The four lengths `[ground, crank, coupler, rocker]`.
    pub fn lengths(&self) -> [f64; 4] {
        [self.ground, self.crank, self.coupler, self.rocker]
    }
    /// The input pivot `O2`.
    pub fn input_pivot(&self) -> Point2<f64> {
        self.origin
    }
    /// The output pivot `O4`.
    pub fn output_pivot(&self) -> Point2<f64> {
        self.origin + unit(self.ground_angle) * self.ground
    }
    /// The angle of the ground link, `theta1`, in radians.
    pub fn ground_angle(&self) -> f64 {
        self.ground_angle
    }
    /// Ratio of the longest to the shortest link.
    pub fn link_ratio(&self) -> f64 {
        let l = self.lengths();
        let min = l.iter().copied().fold(f64::INFINITY, f64::min);
        self.scale / min
    }

    /// Closes the loop at `theta2`: the crank direction and the two vectors
    /// whose arguments are `theta3` and `theta4` (module docs), no
    /// trigonometry beyond `sin` and `cos` of the input.
    #[inline(always)]
    fn close(&self, theta2: f64, mode: AssemblyMode) -> Result<Closed> {
        // NaN fails here too.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(theta2.abs() <= Self::MAX_ANGLE) {
            return Err(angle_error(theta2));
        }
        let (s2, c2) = libm::sincos(theta2);
        let o = Ops(pulp::Scalar);
        let l = self.loop_vectors(o, c2, s2, mode.sign());
        // One comparison catches both a loop that does not close and NaN
        // (from a non-finite angle). A crank tip on the output pivot
        // (`r2 == 0`) makes `v3` and `v4` zero, caught below.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(l.heron >= -l.tol) {
            return Err(self.close_error(theta2, l.r2));
        }
        // Both vanish only when the crank tip is within rounding of the
        // output pivot of a linkage whose coupler equals its rocker (or the
        // products underflow there): every coupler angle closes the loop.
        if l.degenerate(o) {
            return Err(indeterminate(theta2));
        }
        Ok(Closed {
            crank_dir: Vector2::new(c2, s2),
            v3: Vector2::new(l.v3[0], l.v3[1]),
            v4: Vector2::new(l.v4[0], l.v4[1]),
            // The one toggle criterion (module docs); the loop keeps the
            // asked mode's sign inside the band instead of snapping to the
            // toggle.
            toggle: l.heron <= l.tol,
        })
    }

    /// The arithmetic of [`close`](Self::close) for the crank directions
    /// `(c2, s2)` and the mode's sign, without its checks, on the lanes of
    /// `o`: shared by `close` (on [`pulp::Scalar`]) and the batch kernel
    /// of [`solve_into`](Self::solve_into), so that both give the same
    /// bits.
    #[inline(always)]
    fn loop_vectors<S: Simd>(&self, o: Ops<S>, c2: V<S>, s2: V<S>, sign: f64) -> LoopVectors<S> {
        // d = O4 - A, in units of `scale`.
        let c_n = o.sp(self.c_n);
        let dx = o.sub(o.sp(self.g_vec.x), o.mul(c_n, c2));
        let dy = o.sub(o.sp(self.g_vec.y), o.mul(c_n, s2));
        let r2 = o.add(o.mul(dx, dx), o.mul(dy, dy));
        let (sum, diff) = (o.sp(self.sum_n), o.sp(self.diff_n));
        let sum2 = o.mul(sum, sum);
        let (a, b) = (o.sub(sum2, r2), o.sub(r2, o.mul(diff, diff)));
        let heron = o.mul(a, b);
        let diffsum = o.sp(self.sq_diff_n.abs());
        let tol = heron_tolerance(o, sum2, diffsum, r2, o.sp(self.rho_n), a, b);
        // A select, not `max` (which may return either zero for `-0.0`).
        let zero = o.sp(0.0);
        let root = o.0.sqrt_f64s(o.sel(o.gt(heron, zero), heron, zero));
        let h = o.mul(o.sp(sign), root);
        // n = perp(d) h.
        let (nx, ny) = (o.mul(o.neg(dy), h), o.mul(dx, h));
        let (k3, k4) = (
            o.add(o.sp(self.sq_diff_n), r2),
            o.sub(o.sp(self.sq_diff_n), r2),
        );
        LoopVectors {
            r2,
            heron,
            tol,
            v3: [o.add(o.mul(dx, k3), nx), o.add(o.mul(dy, k3), ny)],
            v4: [o.add(o.mul(dx, k4), nx), o.add(o.mul(dy, k4), ny)],
        }
    }

    /// The largest input angle magnitude, in radians: beyond, a double
    /// cannot hold the angle to `1e-7` rad (the same bound as a task's
    /// angles).
    pub const MAX_ANGLE: f64 = 1e9;

    #[cold]
    #[inline(never)]
    fn close_error(&self, theta2: f64, r2: f64) -> Error {
        if !theta2.is_finite() {
            return InvalidInput::NotFinite {
                name: "theta2",
                value: theta2,
            }
            .into();
        }
        AssemblyError::OutOfReach {
            theta2,
            distance: r2.sqrt() * self.scale,
            min_reach: self.diff_n.abs() * self.scale,
            max_reach: self.sum_n * self.scale,
        }
        .into()
    }

    /// Solves the loop at input angle `theta2` (radians) in `mode`.
    ///
    /// Returns the coupler and rocker angles; at a toggle position the
    /// result carries `toggle = true` (both modes coincide there).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a NaN or infinite angle;
    /// [`AssemblyError::OutOfReach`] where the loop does not close;
    /// [`AssemblyError::Indeterminate`] where the crank tip lies on the
    /// output pivot of a linkage whose coupler equals its rocker.
    #[inline]
    pub fn solve(&self, theta2: f64, mode: AssemblyMode) -> Result<Configuration> {
        let c = self.close(theta2, mode)?;
        // The lanes' `atan2` on two `wide` lanes: `solve_into`'s bits.
        let [theta3, theta4] = atan2(
            Pair,
            wide::f64x2::new([c.v3.y, c.v4.y]),
            wide::f64x2::new([c.v3.x, c.v4.x]),
        )
        .to_array();
        Ok(Configuration {
            theta2,
            theta3,
            theta4,
            mode,
            toggle: c.toggle,
        })
    }

    /// Solves the loop at every angle of `theta2s`, lazily: one result per
    /// angle, no allocation.
    pub fn solve_iter<'a, I>(
        &'a self,
        theta2s: I,
        mode: AssemblyMode,
    ) -> impl Iterator<Item = Result<Configuration>> + 'a
    where
        I: IntoIterator<Item = f64>,
        I::IntoIter: 'a,
    {
        theta2s.into_iter().map(move |t| self.solve(t, mode))
    }

    /// Solves the loop at every angle of `theta2s`, writing `theta3`,
    /// `theta4` and whether the loop closed into the three output slices.
    /// Where it does not close (or the angle is not finite, or beyond
    /// [`MAX_ANGLE`](Self::MAX_ANGLE)) the angles are NaN and `valid` is
    /// false; elsewhere they are the bits of [`solve`](Self::solve). Runs a
    /// batch kernel four angles at a time, and from 2^14 angles on in
    /// parallel (rayon) over chunks of 4096. Returns how many closed.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::LengthMismatch`] when the slices differ in length.
    pub fn solve_into(
        &self,
        theta2s: &[f64],
        mode: AssemblyMode,
        theta3: &mut [f64],
        theta4: &mut [f64],
        valid: &mut [bool],
    ) -> Result<usize> {
        for (name, len) in [
            ("theta3", theta3.len()),
            ("theta4", theta4.len()),
            ("valid", valid.len()),
        ] {
            if len != theta2s.len() {
                return Err(InvalidInput::LengthMismatch {
                    name,
                    expected: theta2s.len(),
                    found: len,
                }
                .into());
            }
        }
        if theta2s.len() < SOLVE_PARALLEL_MIN {
            return Ok(self.solve_chunk(theta2s, mode, theta3, theta4, valid));
        }
        Ok(theta2s
            .par_chunks(SOLVE_CHUNK)
            .zip(theta3.par_chunks_mut(SOLVE_CHUNK))
            .zip(theta4.par_chunks_mut(SOLVE_CHUNK))
            .zip(valid.par_chunks_mut(SOLVE_CHUNK))
            .map(|(((t, a), b), v)| self.solve_chunk(t, mode, a, b, v))
            .sum())
    }

    /// The batch kernel of [`solve_into`](Self::solve_into) on slices of
    /// one length: the loop closure and both `atan2` on SIMD lanes picked
    /// at run time ([`pulp`]; `sin` and `cos` from `libm` lane by lane),
    /// without branches, giving the bits of [`solve`](Self::solve) (every
    /// lane operation is the scalar operation; module [`crate::simd`]).
    /// Returns how many closed.
    fn solve_chunk(
        &self,
        theta2s: &[f64],
        mode: AssemblyMode,
        theta3: &mut [f64],
        theta4: &mut [f64],
        valid: &mut [bool],
    ) -> usize {
        Arch::new().dispatch(SolveLanes {
            fb: self,
            theta2s,
            mode,
            theta3,
            theta4,
            valid,
        })
    }

    /// The joint positions of a configuration of this linkage.
    pub fn joints(&self, c: &Configuration) -> Joints {
        let a = self.origin + unit(c.theta2) * self.crank;
        let o4 = self.output_pivot();
        Joints {
            input_pivot: self.origin,
            crank_joint: a,
            rocker_joint: o4 + unit(c.theta4) * self.rocker,
            output_pivot: o4,
        }
    }

    /// Solves at `theta2` in `mode` and returns the joint positions,
    /// without computing any angle (no trigonometry beyond `sin` and `cos` of
    /// the input).
    ///
    /// # Errors
    ///
    /// As [`FourBar::solve`].
    pub fn joints_at(&self, theta2: f64, mode: AssemblyMode) -> Result<Joints> {
        let c = self.close(theta2, mode)?;
        let a = self.origin + c.crank_dir * self.crank;
        let o4 = self.output_pivot();
        Ok(Joints {
            input_pivot: self.origin,
            crank_joint: a,
            rocker_joint: o4 + normalized(c.v4).unwrap_or(c.v4) * self.rocker,
            output_pivot: o4,
        })
    }

    /// Where a point fixed to the coupler is, in a configuration.
    ///
    /// `local` is given in the coupler frame: origin at the crank joint `A`,
    /// x-axis from `A` toward the rocker joint `B`.
    ///
    /// ```text
    /// P = A + e^{i theta3} (u + i v)
    /// ```
    pub fn coupler_point(&self, c: &Configuration, local: Vector2<f64>) -> Point2<f64> {
        let a = self.origin + unit(c.theta2) * self.crank;
        a + rotate(local, c.theta3)
    }

    /// Grashof type, the input being the crank link.
    ///
    /// The equality `s + l = p + q` is decided within a relative rounding
    /// tolerance of a few machine epsilons, so that change-point linkages
    /// given with decimal lengths are recognised.
    pub fn grashof(&self) -> Grashof {
        grashof_of(self.lengths())
    }

    /// How far the linkage is from the Grashof change point:
    /// `|s + l - p - q| / (s + l + p + q)` (see
    /// [`LinkageFigures::grashof_margin`](crate::LinkageFigures::grashof_margin)).
    pub fn grashof_margin(&self) -> f64 {
        crate::linkage::grashof::grashof_margin_of(self.lengths())
    }

    /// Where the input link can be: all the way round, or the arcs between
    /// its dead positions.
    ///
    /// With `c = cos(theta2 - theta1)` the crank tip is at distance
    /// `r^2 = L1^2 + L2^2 - 2 L1 L2 c` from the output pivot, and the loop
    /// closes where `|L3 - L4| <= r <= L3 + L4`:
    ///
    /// ```text
    /// (L1^2 + L2^2 - (L3 + L4)^2) / (2 L1 L2) <= c <= (L1^2 + L2^2 - (L3 - L4)^2) / (2 L1 L2)
    /// ```
    ///
    /// A bound within rounding of `+-1` counts as reached, so that change-point
    /// linkages turn fully.
    pub fn input_range(&self) -> InputRange {
        let InputBounds {
            c_min,
            c_max,
            lo_free,
            hi_free,
        } = input_bounds(self.lengths());
        let t1 = self.ground_angle;
        match (lo_free, hi_free) {
            (true, true) => InputRange::Full,
            (false, true) => {
                let a = c_min.clamp(-1.0, 1.0).acos();
                InputRange::Arc(AngleInterval {
                    start: t1 - a,
                    end: t1 + a,
                })
            }
            (true, false) => {
                let a = c_max.clamp(-1.0, 1.0).acos();
                InputRange::Arc(AngleInterval {
                    start: t1 + a,
                    end: t1 + TAU - a,
                })
            }
            (false, false) => {
                let a_lo = c_max.clamp(-1.0, 1.0).acos();
                let a_hi = c_min.clamp(-1.0, 1.0).acos();
                InputRange::TwoArcs(
                    AngleInterval {
                        start: t1 + a_lo,
                        end: t1 + a_hi,
                    },
                    AngleInterval {
                        start: t1 - a_hi,
                        end: t1 - a_lo,
                    },
                )
            }
        }
    }

    /// Whether the input link turns fully (its [`input_range`](Self::input_range) is full).
    pub fn input_turns_fully(&self) -> bool {
        self.input_range().is_full()
    }
}

crate::linkage::coupler_path_method!(FourBar, |l, t, mode, local| {
    Ok(l.joints_at(t, mode)?.coupler_point(local))
});

/// The error of a position where every coupler angle closes the loop.
#[cold]
#[inline(never)]
fn indeterminate(theta2: f64) -> Error {
    AssemblyError::Indeterminate { theta2 }.into()
}

/// The error of an input angle that is not finite or beyond
/// [`FourBar::MAX_ANGLE`].
#[cold]
#[inline(never)]
fn angle_error(theta2: f64) -> Error {
    match crate::linkage::bounded_theta2(theta2) {
        Err(e) => e.into(),
        Ok(_) => unreachable!("angle_error of a bounded angle"),
    }
}

/// [`tolerance::heron_tolerance`] on the lanes of `o`: the same
/// operations in the same order (no fused multiply-add), so the same bits
/// (checked by `heron_tolerance_lanes_are_the_criterion`).
#[inline(always)]
fn heron_tolerance<S: Simd>(
    o: Ops<S>,
    sum2: V<S>,
    diffsum: V<S>,
    r2: V<S>,
    rho: V<S>,
    a: V<S>,
    b: V<S>,
) -> V<S> {
    let k = o.sp(tolerance::LOOP_EPS * f64::EPSILON);
    let r = o.0.sqrt_f64s(r2);
    let shared = o.add(r2, o.mul(o.mul(o.sp(2.0), r), rho));
    let ea = o.add(sum2, shared);
    let eb = o.add(diffsum, shared);
    let first = o.mul(k, o.add(o.mul(o.abs(b), ea), o.mul(o.abs(a), eb)));
    o.add(first, o.mul(o.mul(o.mul(k, k), ea), eb))
}

/// Magnitudes between which four-fold products (Heron's product of a loop
/// and its tolerance) need no scaling.
const SAFE_MIN: f64 = 1e-60;
/// See [`SAFE_MIN`].
const SAFE_MAX: f64 = 1e60;

/// [`FourBar::solve_chunk`] on the lanes of one instruction set.
struct SolveLanes<'a> {
    fb: &'a FourBar,
    theta2s: &'a [f64],
    mode: AssemblyMode,
    theta3: &'a mut [f64],
    theta4: &'a mut [f64],
    valid: &'a mut [bool],
}

impl WithSimd for SolveLanes<'_> {
    type Output = usize;

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) -> usize {
        let (fb, o) = (self.fb, Ops(s));
        let n = S::F64_LANES;
        let (zero, one, nan) = (o.sp(0.0), o.sp(1.0), o.sp(f64::NAN));
        let max_angle = o.sp(FourBar::MAX_ANGLE);
        let sign = self.mode.sign();
        let (t_in, _) = S::as_simd_f64s(self.theta2s);
        let (t3_out, _) = S::as_mut_simd_f64s(self.theta3);
        let (t4_out, _) = S::as_mut_simd_f64s(self.theta4);
        // One vector of scratch (at most 8 lanes of f64 on any CPU pulp
        // knows; `as_simd` takes whole vectors only).
        let mut buf = [[0.0f64; 8]; 2];
        let mut count = 0;
        for (c, (&t, (a, b))) in t_in
            .iter()
            .zip(t3_out.iter_mut().zip(t4_out.iter_mut()))
            .enumerate()
        {
            let angles = &self.theta2s[c * n..(c + 1) * n];
            for (k, &x) in angles.iter().enumerate() {
                (buf[0][k], buf[1][k]) = libm::sincos(x);
            }
            let s2 = S::as_simd_f64s(&buf[0][..n]).0[0];
            let c2 = S::as_simd_f64s(&buf[1][..n]).0[0];
            let l = fb.loop_vectors(o, c2, s2, sign);
            let ([x3, y3], [x4, y4]) = (l.v3, l.v4);
            // The checks of `close`, as one mask (NaN fails them).
            let ok = o.and(
                o.and(o.le(o.abs(t), max_angle), o.ge(l.heron, o.neg(l.tol))),
                o.not(l.degenerate(o)),
            );
            *a = o.sel(ok, atan2(o, y3, x3), nan);
            *b = o.sel(ok, atan2(o, y4, x4), nan);
            let (flags, _) = S::as_mut_simd_f64s(&mut buf[0][..n]);
            flags[0] = o.sel(ok, one, zero);
            let lanes = &mut self.valid[c * n..(c + 1) * n];
            for (v, &f) in lanes.iter_mut().zip(&buf[0][..n]) {
                *v = f != 0.0;
                count += usize::from(*v);
            }
        }
        let done = t_in.len() * n;
        for (i, &t) in self.theta2s.iter().enumerate().skip(done) {
            match fb.solve(t, self.mode) {
                Ok(c) => {
                    self.theta3[i] = c.theta3;
                    self.theta4[i] = c.theta4;
                    self.valid[i] = true;
                    count += 1;
                }
                Err(_) => {
                    self.theta3[i] = f64::NAN;
                    self.theta4[i] = f64::NAN;
                    self.valid[i] = false;
                }
            }
        }
        count
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simd::Width;

    fn deg(x: f64) -> f64 {
        x.to_radians()
    }

    /// The batch kernel on every lane width (1, 2, 4, 8 and as dispatched)
    /// gives `solve`'s bits, NaN where it fails, and the same count:
    /// angles across several turns, at the input's limits and beyond
    /// `MAX_ANGLE`, and lengths that leave a tail.
    #[test]
    fn solve_lanes_are_solve_on_every_width() {
        let linkages = [
            FourBar::new(3.0, 2.0, 1.5, 1.0).unwrap(),
            FourBar::placed(4.0, 1.0, 3.0, 3.0, Point2::new(-2.0, 5.0), 2.5).unwrap(),
            FourBar::new(1.0, 1.0, 2.0, 2.0).unwrap(),
        ];
        for fb in &linkages {
            let mut ts: Vec<f64> = (0..1003).map(|k| -20.0 + 0.04 * k as f64).collect();
            if let InputRange::Arc(arc) = fb.input_range() {
                ts.extend([arc.start, arc.end, arc.start.next_up(), arc.end.next_down()]);
            }
            ts.extend([f64::NAN, f64::INFINITY, 2e9, -0.0, 0.0]);
            for mode in AssemblyMode::BOTH {
                let n = ts.len();
                let run = |width: Width| {
                    let (mut t3, mut t4, mut ok) = (vec![0.0; n], vec![0.0; n], vec![false; n]);
                    let count = width.run(SolveLanes {
                        fb,
                        theta2s: &ts,
                        mode,
                        theta3: &mut t3,
                        theta4: &mut t4,
                        valid: &mut ok,
                    });
                    (count, t3, t4, ok)
                };
                for width in Width::ALL {
                    let (count, t3, t4, ok) = run(width);
                    assert_eq!(count, ok.iter().filter(|&&b| b).count());
                    for (i, &t) in ts.iter().enumerate() {
                        match fb.solve(t, mode) {
                            Ok(c) => {
                                assert!(ok[i], "{t}");
                                assert_eq!(c.theta3.to_bits(), t3[i].to_bits(), "{t}");
                                assert_eq!(c.theta4.to_bits(), t4[i].to_bits(), "{t}");
                            }
                            Err(_) => assert!(!ok[i] && t3[i].is_nan() && t4[i].is_nan(), "{t}"),
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn norton_example_4_1() {
        let fb = FourBar::new(100.0, 40.0, 120.0, 80.0).unwrap();
        let o = fb.solve(deg(40.0), AssemblyMode::Open).unwrap();
        let c = fb.solve(deg(40.0), AssemblyMode::Crossed).unwrap();
        let r = |x: f64| (x.to_degrees() * 1000.0).round() / 1000.0;
        assert_eq!((r(o.theta3), r(o.theta4)), (20.298, 57.325));
        assert_eq!((r(c.theta3), r(c.theta4)), (-60.978, -98.005));
        assert!(!o.toggle && !c.toggle);
    }

    #[test]
    fn angle_pi_is_exact() {
        // Rhombus at theta2 = pi/2: A = (0, 1), O4 = (1, 0). Open is the
        // parallelogram (B = (1, 1)); crossed folds B onto O2, theta4 = pi,
        // where the half-angle form divides by zero.
        let fb = FourBar::new(1.0, 1.0, 1.0, 1.0).unwrap();
        let c = fb.solve(PI / 2.0, AssemblyMode::Open).unwrap();
        assert!(c.theta3.abs() < 1e-15, "{c:?}");
        assert!((c.theta4 - PI / 2.0).abs() < 1e-15);
        let x = fb.solve(PI / 2.0, AssemblyMode::Crossed).unwrap();
        assert!(wrap_angle(x.theta4 - PI).abs() < 1e-15, "{x:?}");
        assert!((x.theta3 + PI / 2.0).abs() < 1e-15, "{x:?}");
        assert!(x.coupler_rocker_angle() < 0.0);
    }

    #[test]
    fn bad_lengths_are_typed_errors() {
        for (args, what) in [
            ((0.0, 1.0, 1.0, 1.0), "ground"),
            ((1.0, -1.0, 1.0, 1.0), "crank"),
            ((1.0, 1.0, f64::NAN, 1.0), "coupler"),
            ((1.0, 1.0, 1.0, f64::INFINITY), "rocker"),
        ] {
            let e = FourBar::new(args.0, args.1, args.2, args.3).unwrap_err();
            assert!(matches!(e, Error::InvalidInput(_)), "{e}");
            assert!(e.to_string().contains(what), "{e}");
        }
        let e = FourBar::new(10.0, 1.0, 2.0, 3.0).unwrap_err();
        assert!(matches!(
            e,
            Error::Assembly(AssemblyError::NeverCloses { .. })
        ));
    }

    /// Near every dead position, at distances from `1e-20` to `1e-2` rad:
    /// [`FourBar::solve`]'s `toggle` and the mode of the loop it builds
    /// ([`AssemblyMode::of_loop`]) give the same answer outside the band's
    /// own rounding (a factor of 2 either side of the bound), and the loop
    /// keeps the asked mode's sign: it is not snapped to the toggle.
    #[test]
    fn one_toggle_criterion_in_angle_terms() {
        let linkages = [
            [3.0, 2.0, 1.5, 1.0],
            [4.0, 3.0, 2.0, 2.5],
            [1.0, 0.9, 0.3, 0.5],
            [2.0, 1.9, 0.05, 0.2],
            [1e-3, 0.9e-3, 0.3e-3, 0.5e-3],
        ];
        let mut toggles = 0;
        for l in linkages {
            let fb = FourBar::new(l[0], l[1], l[2], l[3]).unwrap();
            let dead = fb.input_range().dead_positions();
            assert!(!dead.is_empty(), "{l:?} has dead positions");
            for &t0 in &dead {
                for e in -80..=8 {
                    for side in [-1.0, 1.0] {
                        let t = t0 + side * 10f64.powf(e as f64 / 4.0);
                        for mode in [AssemblyMode::Open, AssemblyMode::Crossed] {
                            let Ok(c) = fb.solve(t, mode) else { continue };
                            let j = fb.joints_at(t, mode).unwrap();
                            let u = j.rocker_joint - j.crank_joint;
                            let w = j.rocker_joint - j.output_pivot;
                            let (u2, w2) = (u.norm_squared(), w.norm_squared());
                            let big = u2 + w2 + 2.0 * (u2 * w2).sqrt() + (u - w).norm_squared();
                            let bound = 0.5 * tolerance::TOGGLE_BAND * big;
                            let s = cross(u, w);
                            let m = AssemblyMode::of_loop(u, w);
                            if s.abs() < 0.5 * bound {
                                assert!(c.toggle && m.is_none(), "{l:?} at {t}: {s} vs {bound}");
                                toggles += 1;
                            } else if s.abs() > 2.0 * bound {
                                assert!(!c.toggle && m == Some(mode), "{l:?} at {t}: {s}");
                            }
                            // Not snapped: the asked mode's sign, or zero to
                            // rounding.
                            assert!(s * mode.sign() >= -1e-3 * bound, "{l:?} at {t}: {s}");
                        }
                    }
                }
            }
        }
        assert!(toggles > 50, "the band was reached ({toggles} times)");
    }

    /// The lanes' Heron tolerance is `tolerance::heron_tolerance`, bit for
    /// bit, on every lane width (the one criterion, written twice).
    #[test]
    fn heron_tolerance_lanes_are_the_criterion() {
        let mut x = 0.123_456_789_f64;
        let mut next = || {
            // A small LCG-free sequence: fractional parts of multiples.
            x = (x * 997.0 + 0.271_828_18).fract();
            x
        };
        for _ in 0..2000 {
            let sum = 2.0 * next();
            let diff = sum * (2.0 * next() - 1.0) * next();
            let r2 = (sum * 1.5 * next()).powi(2) * 10f64.powi(-(next() * 8.0) as i32);
            let rho = 2.0 * next() + 1e-9;
            let (a, b) = (sum * sum - r2, r2 - diff * diff);
            let (sum, diff) = (sum * sum, (diff * sum).abs());
            let want = tolerance::heron_tolerance(sum, diff, r2, rho, a, b);
            let o = Ops(pulp::Scalar);
            let got = heron_tolerance(o, sum, diff, r2, rho, a, b);
            assert_eq!(got.to_bits(), want.to_bits(), "{sum} {diff} {r2} {rho}");
            struct Lanes([f64; 6], f64);
            impl WithSimd for Lanes {
                type Output = ();
                #[inline(always)]
                fn with_simd<S: Simd>(self, s: S) {
                    let o = Ops(s);
                    let [sum, diff, r2, rho, a, b] = self.0.map(|v| o.sp(v));
                    let t = heron_tolerance(o, sum, diff, r2, rho, a, b);
                    let mut out = [0.0f64; 8];
                    let n = S::F64_LANES;
                    S::as_mut_simd_f64s(&mut out[..n]).0[0] = t;
                    for v in &out[..n] {
                        assert_eq!(v.to_bits(), self.1.to_bits());
                    }
                }
            }
            Arch::new().dispatch(Lanes([sum, diff, r2, rho, a, b], want));
        }
    }

    /// Issue 28's linkage (crank and coupler 4.6e7 times the rocker): the
    /// earlier band grew like `L3 / L4` and called every position a
    /// toggle; the loop's rounding allows a band of about `5e-4` in
    /// `sin mu`, so the transmission angles of 49 to 57 degrees at its
    /// poses are not toggles, while positions within the band of its dead
    /// positions are.
    #[test]
    fn long_links_on_a_short_rocker_keep_their_modes() {
        let fb = FourBar::from_pivots(
            Point2::new(79.35079574269099, 74.89249517819286),
            Point2::new(0.9270498928708832, -2.456011695005893),
            1502669804.6436944,
            1502669676.747299,
            32.832706862152556,
        )
        .unwrap();
        let mut reached = 0;
        for t in (0..2000).map(|k| -PI + TAU * k as f64 / 2000.0) {
            for mode in AssemblyMode::BOTH {
                let Ok(c) = fb.solve(t, mode) else { continue };
                let mu = c.transmission_angle();
                // The band is about 4e-4 here (`tolerance::toggle_band`).
                if mu > 2e-3 {
                    assert!(!c.toggle, "{t}: {}", mu.to_degrees());
                } else if mu < 1e-4 {
                    assert!(c.toggle, "{t}: {}", mu.to_degrees());
                }
                reached += 1;
            }
        }
        assert!(reached > 100, "{reached}");
        for &t0 in &fb.input_range().dead_positions() {
            let c = fb.solve(t0, AssemblyMode::Open).unwrap();
            assert!(c.toggle, "{t0}");
        }
    }

    #[test]
    fn input_angles_beyond_the_bound_are_refused() {
        let fb = FourBar::new(4.0, 1.0, 3.0, 3.0).unwrap();
        assert!(fb.solve(1e9, AssemblyMode::Open).is_ok());
        for t in [1e300, -2e9, f64::INFINITY, f64::NAN] {
            let e = fb.solve(t, AssemblyMode::Open).unwrap_err();
            assert!(
                matches!(
                    e,
                    Error::InvalidInput(
                        InvalidInput::TooLarge { .. } | InvalidInput::NotFinite { .. }
                    )
                ),
                "{t}: {e}"
            );
            assert!(fb.joints_at(t, AssemblyMode::Crossed).is_err());
        }
    }
}
