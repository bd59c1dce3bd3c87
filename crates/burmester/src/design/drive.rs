//! Drive synthesis: a motor for a linkage whose input only swings.
//!
//! A synthesized four-bar ([`SynthesizedFourBar`], three to five poses)
//! whose input link must turn through an arc, not full turns, is driven by
//! an added dyad: a crank `D0 D` turned by the motor and a coupler `D E`
//! to a point `E` rigid with the input link `A0 A` (the **attachment**),
//! making the Watt II six-bar [`SixBar`] (Borm & Kim's conclusion; Norton,
//! *Design of Machinery*, Example 3-4, adds a driver dyad the same way).
//!
//! # The drive at a candidate pivot
//!
//! The input link must turn from the first pose to the last ([the
//! travel](SynthesizedFourBar::travel)), extended at each end by the
//! designer's `swing_margin`: its angle runs over `[theta_a, theta_b]`,
//! and `E = A0 + rho e^{i psi}` over the arc from `psi_a = theta_a + delta`
//! to `psi_b = theta_b + delta` (`rho = |E - A0|`, `delta` the fixed angle
//! of `E` from the input link). A crank-rocker's rocker reaches its ends
//! where crank and coupler are collinear, `|E - D0| = c + r` and `c - r`,
//! so for a candidate crank pivot `D0` with `d_a = |E_a - D0|`,
//! `d_b = |E_b - D0|`:
//!
//! ```text
//! r = |d_a - d_b| / 2,   c = (d_a + d_b) / 2,   g = |A0 - D0|
//! ```
//!
//! is the one drive whose swing is exactly `[psi_a, psi_b]`, provided the
//! distance from `D0` is monotone along the arc: the arc does not contain
//! the direction of `D0 - A0` or its opposite, which (the arc being
//! shorter than `pi`) is
//!
//! ```text
//! cross(D0 - A0, e_a) * cross(D0 - A0, e_b) > 0     (valid)
//! ```
//!
//! Then the loop closes at every crank angle (`|E - D0|` takes only the
//! values of points of the arc), the crank turns fully, the drive's mode is
//! `-sign cross(D0 - A0, e_a)` over the whole turn, and on each stroke `E`
//! moves monotonically from one end to the other: the motion loop's input
//! passes the poses in order once per stroke. It never toggles because the
//! swing lies strictly inside its input range on its branch (checked once,
//! [`DriveError::OutsideInputRange`]).
//!
//! # The figures of each sample (exact, closed form)
//!
//! * the drive loop's minimum transmission angle over a full turn,
//!   `acos max(|k - (g + r)^2|, |k - (g - r)^2|) / (2 c rho)`,
//!   `k = c^2 + rho^2` ([`SixBar`]'s module docs);
//! * the motion loop's over the swing (the same for every `D0`), and the
//!   smaller of the two, `min_transmission_rad`;
//! * the time ratio `(pi + alpha) / (pi - alpha)`, `alpha` the angle at
//!   `D0` between `E_a` and `E_b` (the crank's two collinear positions are
//!   `alpha` off opposite), the slower stroke over the faster: the motor
//!   turns so that the working stroke, first pose to last, is the slower;
//! * the six-bar's link ratio, its size over the task's span, and
//!   `acceptable`: valid, the limits ([`DesignLimits`]: transmission, link
//!   ratio, and the six-bar's size ratio and longest link against
//!   `max_size_ratio` and `max_link_length`), the time ratio at most `max_time_ratio`, `D0` on the base
//!   plate and the moving links clear of the obstacles over the whole
//!   crank turn (the clearance bound of [`Constraints`] with the speed of
//!   the six-bar's fastest joint per unit crank angle).
//!
//! # Time ratio 1 in closed form
//!
//! The classic construction (Norton, Example 3-1): `D0` on the line
//! through `E_a` and `E_b`, beyond the chord, at distance `t` from its
//! midpoint `M`. Then `r = h = rho sin(s / 2)` (`s` the swing), `c = t`,
//! `g^2 = t^2 + m^2` (`m = rho cos(s / 2)`), and the drive's worst
//! `|cos gamma| = g h / (t rho)`: the smaller `t`, the smaller the drive
//! and the worse its transmission, which for the angle `mu` asked for gives
//!
//! ```text
//! t = m / sqrt((rho cos(mu) / h)^2 - 1),   mu < pi/2 - s/2
//! ```
//!
//! (Brodell and Soni's design equations with the ground as unit,
//! [`CrankRockerDesign::unit_time_ratio`]). [`DriveContext::classic`]
//! places it; the map's own sample function evaluates it.

use core::f64::consts::{FRAC_PI_2, PI, TAU};

use core::sync::atomic::{AtomicBool, Ordering};

use nalgebra::{Point2, Vector2};
use pulp::{Arch, Simd, WithSimd};

use crate::design::columns::map_columns;
use crate::design::constraints::Prepared;
use crate::design::rank::{best, flagged_rank_columns, tie_order};
use crate::design::{Constraints, DesignLimits, MapOptions, RankBy, Ranking};
use crate::engine::{Control, Rows, run_blocks_polled, run_blocks_with};
use crate::error::{
    DegenerateError, DriveError, InvalidInput, Result, count_in, finite_point, in_range, outside,
};
use crate::geom::{Grid, PerPose, cross, unit, wrap_angle};
use crate::linkage::grashof::{fmax, fmin};
use crate::linkage::sixbar::arc_worst_cos;
use crate::linkage::{AssemblyMode, Direction, FourBar, InputRange, SixBar};
use crate::simd::{M, Ops, V, acos, acos1, atan2};
use crate::synthesis::SynthesizedFourBar;
use crate::tolerance;

map_columns! {
    $ drive_map_columns, "drive map",
    (
        DriveColumns,
        DriveColumnsOut,
        DriveSample,
        "a drive map",
        "The columns of a drive map: one value per grid sample, row-major.",
        "A drive map's columns to write: one slice per column, one value per grid \
         sample, row-major."
    );
    /// A drive exists: a crank-rocker whose rocker swings exactly over
    /// the travel with its margins, the six-bar turning fully with
    /// neither loop toggling. Where false, the other columns hold
    /// false or NaN.
    valid: bool = false,
    /// The smaller minimum transmission angle of the two loops over a
    /// full crank turn, radians.
    min_transmission_rad: f32 = f32::NAN,
    /// The drive loop's minimum transmission angle over a full crank
    /// turn, radians.
    drive_transmission_rad: f32 = f32::NAN,
    /// The time ratio of the strokes, the slower over the faster (at
    /// least 1).
    time_ratio: f32 = f32::NAN,
    /// The six-bar's longest over its shortest link.
    link_ratio: f32 = f32::NAN,
    /// The six-bar's size (`SixBar::size`) over the task's span.
    size_ratio: f32 = f32::NAN,
    /// Meets the limits, the time ratio and the constraints.
    acceptable: bool = false,
}

macro_rules! define_drive_rows {
    ($($(#[$doc:meta])* $name:ident: $ty:ty = $invalid:expr,)*) => {
        impl<'a> Rows for DriveColumnsOut<'a> {
            fn split_rows(self, rows: usize) -> (Self, Self) {
                // `rows` is in units of `nx` samples: the caller passes
                // `rows * nx` through `RowsOfDrive`.
                let at = rows.min(self.valid.len());
                $(let $name = self.$name.split_at_mut(at);)*
                (
                    DriveColumnsOut { $($name: $name.0,)* },
                    DriveColumnsOut { $($name: $name.1,)* },
                )
            }
        }
    };
}

drive_map_columns!(define_drive_rows);

/// Rows of `nx` samples of a drive map's columns.
struct RowsOfDrive<'a> {
    out: DriveColumnsOut<'a>,
    nx: usize,
}

impl Rows for RowsOfDrive<'_> {
    fn split_rows(self, rows: usize) -> (Self, Self) {
        let (a, b) = self.out.split_rows(rows * self.nx);
        (
            RowsOfDrive {
                out: a,
                nx: self.nx,
            },
            RowsOfDrive {
                out: b,
                nx: self.nx,
            },
        )
    }
}

/// The designer's options of a drive beyond [`DesignLimits`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DriveOptions {
    /// How far the input link swings beyond the first and the last pose,
    /// radians, at each end (default 0: the strokes end at the poses, where
    /// the coupler comes to rest).
    pub swing_margin: f64,
    /// The largest acceptable time ratio (slower stroke over faster), at
    /// least 1 (default infinity: no limit).
    pub max_time_ratio: f64,
}

impl Default for DriveOptions {
    fn default() -> Self {
        DriveOptions {
            swing_margin: 0.0,
            max_time_ratio: f64::INFINITY,
        }
    }
}

impl DriveOptions {
    /// Options with the margin in degrees, validated.
    ///
    /// # Errors
    ///
    /// As [`DriveOptions::validate`], the margin named `swing_margin_deg`.
    pub fn from_degrees(swing_margin_deg: f64, max_time_ratio: f64) -> Result<Self> {
        in_range("swing_margin_deg", swing_margin_deg, 0.0, 90.0, " degrees")?;
        let o = DriveOptions {
            swing_margin: swing_margin_deg.to_radians(),
            max_time_ratio,
        };
        o.validate()?;
        Ok(o)
    }

    /// Checks the options: a margin in `[0, pi/2]`, a time ratio limit of
    /// at least 1 (infinity allowed).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::OutsideRange`] for a value out of its range or NaN.
    pub fn validate(&self) -> Result<()> {
        in_range(
            "swing_margin",
            self.swing_margin,
            0.0,
            FRAC_PI_2,
            " radians",
        )?;
        in_range(
            "max_time_ratio",
            self.max_time_ratio,
            1.0,
            f64::INFINITY,
            "",
        )?;
        Ok(())
    }
}

/// What a drive is synthesized for, derived once: the travel and its swing,
/// the attachment, the motion loop's figures over the swing.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Swing {
    /// `A0`.
    a0: Point2<f64>,
    /// `rho = |E - A0|`.
    rho: f64,
    /// `delta = arg(E - A0) - arg(A - A0)`.
    delta: f64,
    /// `theta_a`, `theta_b`: the input angle at the swing's ends, first
    /// pose's end first (unwrapped, `theta_b - theta_a` the signed swing).
    theta: [f64; 2],
    /// `rho e^{i psi_a}`, `rho e^{i psi_b}`: `E - A0` at the ends.
    arm: [Vector2<f64>; 2],
    /// The motion loop's assembly mode.
    motion_mode: AssemblyMode,
    /// The motion loop's minimum transmission angle over the swing.
    motion_mu: f64,
    /// The members that do not depend on `D0`: the motion linkage's and the
    /// arm that carries `E` off the input link ([`SixBar::size`]).
    members: f64,
    /// The shortest and longest of the links that do not depend on `D0`.
    link_min: f64,
    link_max: f64,
    /// `1 / span`, the task's span from the poses the linkage reaches.
    inv_span: f64,
    /// Links shorter than this make no drive.
    tiny: f64,
}

/// The figures of one candidate drive pivot (the map's sample, in `f64`).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Eval {
    valid: bool,
    drive_mu: f64,
    mu: f64,
    time_ratio: f64,
    link_ratio: f64,
    size_ratio: f64,
    /// The six-bar's longest link.
    lmax: f64,
    /// `[g, r, c]`.
    lengths: [f64; 3],
    /// The drive loop's mode.
    mode: AssemblyMode,
}

impl Swing {
    /// The figures of the drives with crank pivots `(x, y)` on the lanes of
    /// `o` (module docs), with no check of the limits: the one arithmetic
    /// of the map's SIMD rows and of the scalar path ([`eval`](Self::eval),
    /// on [`pulp::Scalar`]), every lane operation the scalar one in the
    /// same order (no fused multiply-add), so both give the same bits.
    #[inline(always)]
    fn lanes<S: Simd>(&self, o: Ops<S>, x: V<S>, y: V<S>) -> EvalLanes<S> {
        let [pa, pb] = self.arm;
        let (pax, pay, pbx, pby) = (o.sp(pa.x), o.sp(pa.y), o.sp(pb.x), o.sp(pb.y));
        let wx = o.sub(x, o.sp(self.a0.x));
        let wy = o.sub(y, o.sp(self.a0.y));
        let ca = o.cross(wx, wy, pax, pay);
        let cb = o.cross(wx, wy, pbx, pby);
        let (vax, vay) = (o.sub(pax, wx), o.sub(pay, wy));
        let (vbx, vby) = (o.sub(pbx, wx), o.sub(pby, wy));
        let da = o.norm(vax, vay);
        let db = o.norm(vbx, vby);
        let g = o.norm(wx, wy);
        let half = o.sp(0.5);
        let r = o.mul(half, o.abs(o.sub(da, db)));
        let c = o.mul(half, o.add(da, db));
        let rho = o.sp(self.rho);
        // drive_worst_cos(g, r, c, rho), lane by lane.
        let k = o.add(o.mul(c, c), o.mul(rho, rho));
        let far = o.add(g, r);
        let near = o.sub(g, r);
        let worst = o.div(
            o.fmax(
                o.abs(o.sub(k, o.mul(far, far))),
                o.abs(o.sub(k, o.mul(near, near))),
            ),
            o.mul(o.mul(o.sp(2.0), c), rho),
        );
        let drive_mu = acos(o, o.fmin(worst, o.sp(1.0)));
        let (zero, tiny) = (o.sp(0.0), o.sp(self.tiny));
        let valid = o.and(
            o.and(o.gt(o.mul(ca, cb), zero), o.gt(r, tiny)),
            o.and(
                o.and(o.gt(g, tiny), o.gt(o.fmin(da, db), tiny)),
                o.gt(drive_mu, o.sp(tolerance::TOGGLE_BAND)),
            ),
        );
        // The angle at D0 between E_a and E_b, in [0, pi].
        let alpha = atan2(
            o,
            o.abs(o.cross(vax, vay, vbx, vby)),
            o.dot(vax, vay, vbx, vby),
        );
        let pi = o.sp(PI);
        let time_ratio = o.div(o.add(pi, alpha), o.sub(pi, alpha));
        let lmax = o.fmax(o.fmax(o.sp(self.link_max), g), o.fmax(r, c));
        let lmin = o.fmin(o.fmin(o.sp(self.link_min), g), o.fmin(r, c));
        EvalLanes {
            valid,
            drive_mu,
            mu: o.fmin(drive_mu, o.sp(self.motion_mu)),
            time_ratio,
            link_ratio: o.div(lmax, lmin),
            lmax,
            size_ratio: o.mul(
                o.add(o.add(o.add(o.sp(self.members), g), r), c),
                o.sp(self.inv_span),
            ),
            g,
            r,
            c,
            ca,
        }
    }

    /// The figures of the drive with crank pivot `d0` ([`lanes`](Self::lanes)
    /// on one scalar lane).
    #[inline]
    fn eval(&self, d0: Point2<f64>) -> Eval {
        let e = self.lanes(Ops(pulp::Scalar), d0.x, d0.y);
        Eval {
            valid: e.valid,
            drive_mu: e.drive_mu,
            mu: e.mu,
            time_ratio: e.time_ratio,
            link_ratio: e.link_ratio,
            size_ratio: e.size_ratio,
            lmax: e.lmax,
            lengths: [e.g, e.r, e.c],
            mode: if e.ca > 0.0 {
                AssemblyMode::Crossed
            } else {
                AssemblyMode::Open
            },
        }
    }
}

/// [`Swing::lanes`]'s figures on the lanes of `S`.
#[derive(Clone, Copy)]
struct EvalLanes<S: Simd> {
    valid: M<S>,
    drive_mu: V<S>,
    mu: V<S>,
    time_ratio: V<S>,
    link_ratio: V<S>,
    lmax: V<S>,
    size_ratio: V<S>,
    g: V<S>,
    r: V<S>,
    c: V<S>,
    ca: V<S>,
}

/// Rows are padded to a multiple of the widest lane count (8, AVX-512).
const PAD: usize = 8;

/// One row's lanes, written by [`DriveRow`]: the figures and a flag per
/// sample (`1` valid, `2` meets the limits and the time ratio).
struct RowScratch {
    xs: Vec<f64>,
    flags: Vec<f64>,
    mu: Vec<f64>,
    drive_mu: Vec<f64>,
    time_ratio: Vec<f64>,
    link_ratio: Vec<f64>,
    size_ratio: Vec<f64>,
}

impl RowScratch {
    fn new(grid: &Grid) -> Self {
        let nx = grid.nx();
        let padded = nx.next_multiple_of(PAD);
        let v = || vec![0.0; padded];
        RowScratch {
            xs: (0..padded).map(|i| grid.x(i.min(nx - 1))).collect(),
            flags: v(),
            mu: v(),
            drive_mu: v(),
            time_ratio: v(),
            link_ratio: v(),
            size_ratio: v(),
        }
    }
}

/// The lanes of one row at ordinate `y` (pulp's entry point).
struct DriveRow<'a> {
    swing: &'a Swing,
    /// `[min transmission, max link ratio, max time ratio, max size ratio,
    /// max link length]`.
    limits: [f64; 5],
    y: f64,
    out: &'a mut RowScratch,
}

impl WithSimd for DriveRow<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let o = Ops(s);
        let out = self.out;
        let y = o.sp(self.y);
        let [mt, mr, mq, ms, ml] = self.limits.map(|v| o.sp(v));
        let (one, two, zero) = (o.sp(1.0), o.sp(2.0), o.sp(0.0));
        let xs = S::as_simd_f64s(&out.xs).0;
        let flags = S::as_mut_simd_f64s(&mut out.flags).0;
        let mu = S::as_mut_simd_f64s(&mut out.mu).0;
        let drive_mu = S::as_mut_simd_f64s(&mut out.drive_mu).0;
        let time_ratio = S::as_mut_simd_f64s(&mut out.time_ratio).0;
        let link_ratio = S::as_mut_simd_f64s(&mut out.link_ratio).0;
        let size_ratio = S::as_mut_simd_f64s(&mut out.size_ratio).0;
        for (c, &x) in xs.iter().enumerate() {
            let e = self.swing.lanes(o, x, y);
            let meets = o.and(
                o.and(
                    o.and(e.valid, o.ge(e.mu, mt)),
                    o.and(o.le(e.link_ratio, mr), o.le(e.time_ratio, mq)),
                ),
                o.and(o.le(e.size_ratio, ms), o.le(e.lmax, ml)),
            );
            flags[c] = o.add(o.sel(e.valid, one, zero), o.sel(meets, two, zero));
            mu[c] = e.mu;
            drive_mu[c] = e.drive_mu;
            time_ratio[c] = e.time_ratio;
            link_ratio[c] = e.link_ratio;
            size_ratio[c] = e.size_ratio;
        }
    }
}

/// What a drive map is computed for: the linkage, the attachment `E`, the
/// grid of candidate crank pivots `D0`, the limits, options and
/// constraints; validated when made ([`DriveContext::new`]), with the
/// swing derived once. Holds the per-sample logic (the drive of a sample,
/// the best drives), so that the columns can live elsewhere (NumPy).
#[derive(Debug, Clone, PartialEq)]
pub struct DriveContext {
    grid: Grid,
    linkage: SynthesizedFourBar,
    attachment: Point2<f64>,
    map_options: MapOptions,
    options: DriveOptions,
    swing: Swing,
}

/// A drive map: what it was computed for, and its columns.
#[derive(Debug, Clone, PartialEq)]
pub struct DriveMap {
    /// What the map was computed for.
    pub context: DriveContext,
    /// One value per grid sample of every figure.
    pub columns: DriveColumns,
}

/// What a designer checks of a drive (see the [module docs](self)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DriveFigures {
    /// The smaller of the two loops' minimum transmission angles over a
    /// full crank turn, radians.
    pub min_transmission: f64,
    /// The drive loop's minimum transmission angle over a full turn.
    pub drive_transmission: f64,
    /// The motion loop's minimum transmission angle over the swing.
    pub motion_transmission: f64,
    /// The time ratio, slower stroke over faster (at least 1).
    pub time_ratio: f64,
    /// The six-bar's longest over shortest link.
    pub link_ratio: f64,
    /// The six-bar's size over the task's span.
    pub size_ratio: f64,
    /// The motion loop's input angle at the start and the end of the
    /// working stroke (first pose's end first; their difference is the
    /// signed swing, the travel and the margins).
    pub swing: [f64; 2],
    /// The crank's turn over the working stroke, radians (`pi` at time
    /// ratio 1, more than `pi` otherwise).
    pub stroke: f64,
}

/// A drive for a linkage: the six-bar, the crank angles at the poses, and
/// its figures; from a drive map ([`DriveMap::best_drives`]), a pivot
/// ([`DriveContext::drive`]) or the closed form ([`DriveContext::classic`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Drive {
    /// The six-bar: the drive loop and the linkage as its motion loop.
    pub sixbar: SixBar,
    /// The linkage driven.
    pub linkage: SynthesizedFourBar,
    /// The motor's crank pivot `D0`.
    pub drive_pivot: Point2<f64>,
    /// The attachment `E`, where it is at pose 1.
    pub attachment: Point2<f64>,
    /// The figures.
    pub figures: DriveFigures,
    /// The crank angle at each pose on the working stroke, unwrapped from
    /// the start of the stroke in the motor's direction (monotone).
    pub pose_crank_angles: PerPose<f64>,
    /// The crank angle where the working stroke starts (a limit position).
    pub stroke_start: f64,
    /// The motor's direction over the working stroke.
    pub direction: Direction,
    /// Whether it meets the limits, the time ratio and the constraints of
    /// the context it came from.
    pub acceptable: bool,
    /// Its sample `(j, i)` in a drive map, if it came from one.
    pub index: Option<(usize, usize)>,
    /// Its signed distance to the nearest sample without a drive (grid
    /// units), if it came from a map; NaN otherwise.
    pub margin: f64,
    /// Its score by the ranking that chose it (NaN otherwise).
    pub score: f64,
    /// The ranking that chose it.
    pub ranked_by: Option<RankBy>,
}

impl Drive {
    /// The crank angles of one full turn from the working stroke's start,
    /// in the motor's direction: `samples` of them, evenly spaced, the
    /// start included and the start plus a turn not.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::CountOutOfRange`] for fewer than 2 or more than
    /// [`SixBar::MAX_SAMPLES`] samples.
    pub fn turn_angles(&self, samples: usize) -> Result<Vec<f64>> {
        let n = count_in("samples", samples, 2, SixBar::MAX_SAMPLES)?;
        let s = self.direction.sign();
        Ok((0..n)
            .map(|k| self.stroke_start + s * TAU * (k as f64 / n as f64))
            .collect())
    }
}

/// A crank-rocker designed in closed form.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CrankRockerDesign {
    /// The ground `|O4 - O2|`.
    pub ground: f64,
    /// The crank.
    pub crank: f64,
    /// The coupler.
    pub coupler: f64,
    /// The rocker.
    pub rocker: f64,
    /// The minimum transmission angle over a full turn, radians.
    pub min_transmission: f64,
}

/// Checks that the angle `value` is in the open interval `(0, max)` (NaN
/// is not), `unit` saying so in the message.
fn open_angle(name: &'static str, value: f64, max: f64, unit: &'static str) -> Result<f64> {
    let inside = value > 0.0 && value < max;
    inside
        .then_some(value)
        .ok_or_else(|| outside(name, value, [0.0, max], unit).into())
}

impl CrankRockerDesign {
    /// The crank-rocker with time ratio 1 whose rocker of length `rocker`
    /// swings through `swing` radians and whose minimum transmission angle
    /// over a full turn is `min_transmission` (module docs: Norton's
    /// construction, Example 3-1, the crank pivot on the line through the
    /// rocker's two end positions; Brodell and Soni's equations):
    ///
    /// ```text
    /// crank = rocker sin(swing / 2)
    /// coupler = t,  ground = sqrt(t^2 + (rocker cos(swing / 2))^2),
    /// t = rocker cos(swing / 2) / sqrt((cos(mu) / sin(swing / 2))^2 - 1)
    /// ```
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for a rocker that is not positive and finite, a
    /// swing outside `(0, pi)`, or a transmission angle outside
    /// `(0, pi/2 - swing/2)` (no time-ratio-1 crank-rocker reaches it).
    ///
    /// # Example
    ///
    /// ```
    /// use burmester::design::CrankRockerDesign;
    /// let d = CrankRockerDesign::unit_time_ratio(1.0, 45f64.to_radians(), 40f64.to_radians())?;
    /// assert!((d.crank - 22.5f64.to_radians().sin()).abs() < 1e-15);
    /// # Ok::<(), burmester::Error>(())
    /// ```
    pub fn unit_time_ratio(rocker: f64, swing: f64, min_transmission: f64) -> Result<Self> {
        let rocker = crate::error::positive("rocker length", rocker)?;
        let swing = open_angle("swing", swing, PI, " radians (exclusive)")?;
        let best = FRAC_PI_2 - 0.5 * swing;
        let why = " radians (exclusive; pi/2 - swing/2 is reached only at infinite size)";
        let min_transmission = open_angle("min_transmission", min_transmission, best, why)?;
        let (h, m) = (rocker * (0.5 * swing).sin(), rocker * (0.5 * swing).cos());
        let q = rocker * min_transmission.cos() / h;
        let t = m / (q * q - 1.0).sqrt();
        Ok(CrankRockerDesign {
            ground: t.hypot(m),
            crank: h,
            coupler: t,
            rocker,
            min_transmission,
        })
    }
}

impl DriveContext {
    /// The largest number of samples of one side of an attachment search's
    /// drive map.
    pub const MAX_SEARCH_SAMPLES: usize = 1024;

    /// The context of a drive map for `linkage` with the attachment `E` at
    /// `attachment` (where it is at pose 1, rigid with the input link), the
    /// candidate crank pivots on `grid`, validated (see the [module
    /// docs](self)).
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for invalid drive options, an envelope among the
    /// constraints (it is not checked over the crank's turn), or a
    /// non-finite attachment; [`DriveError::NoTravel`] for a linkage
    /// that does not carry the coupler through its poses in order in one
    /// mode; [`DriveError::TravelTooLarge`] when the travel with its margins
    /// is not less than `pi`; [`DriveError::OutsideInputRange`] when the
    /// margins take the input beyond its dead positions;
    /// [`DegenerateError::ZeroLengthLink`] for an attachment on `A0`.
    pub fn new(
        linkage: &SynthesizedFourBar,
        attachment: Point2<f64>,
        grid: &Grid,
        map_options: &MapOptions,
        options: &DriveOptions,
    ) -> Result<Self> {
        options.validate()?;
        if map_options.constraints().envelope.is_some() {
            // The whole-turn checks cover the base plate and the obstacles;
            // an envelope would go unchecked, so it is refused.
            return Err(InvalidInput::UnknownName {
                what: "drive constraint",
                expected: "base_plate, obstacles, link_width and travel_samples (a drive map does not check an envelope)",
                found: "envelope".to_owned(),
            }
            .into());
        }
        finite_point(["attachment x", "attachment y"], attachment)?;
        let swing = swing_of(linkage, attachment, options)?;
        Ok(DriveContext {
            grid: *grid,
            linkage: *linkage,
            attachment,
            map_options: map_options.clone(),
            options: *options,
            swing,
        })
    }

    /// The grid of candidate crank pivots.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }
    /// The linkage driven.
    pub fn linkage(&self) -> &SynthesizedFourBar {
        &self.linkage
    }
    /// The attachment `E` at pose 1.
    pub fn attachment(&self) -> Point2<f64> {
        self.attachment
    }
    /// The limits behind `acceptable`.
    pub fn limits(&self) -> &DesignLimits {
        self.map_options.limits()
    }
    /// The options.
    pub fn options(&self) -> &DriveOptions {
        &self.options
    }
    /// The constraints behind `acceptable`.
    pub fn constraints(&self) -> &Constraints {
        self.map_options.constraints()
    }
    /// The limits and the constraints, checked.
    pub fn map_options(&self) -> &MapOptions {
        &self.map_options
    }
    /// The motion loop's input angle at the start and the end of the
    /// working stroke (the travel extended by the margins).
    pub fn swing(&self) -> [f64; 2] {
        self.swing.theta
    }
    /// Where `E` is at the two ends of the swing, start first.
    pub fn attachment_ends(&self) -> [Point2<f64>; 2] {
        self.swing.arm.map(|v| self.swing.a0 + v)
    }
    /// The motion loop's minimum transmission angle over the swing, radians
    /// (the same for every drive of this context).
    pub fn motion_transmission(&self) -> f64 {
        self.swing.motion_mu
    }
    /// The same context on another grid (nothing to validate again).
    #[must_use]
    pub fn with_grid(&self, grid: &Grid) -> Self {
        DriveContext {
            grid: *grid,
            ..self.clone()
        }
    }

    /// The candidate crank pivot of sample `k` (row-major).
    pub fn point(&self, k: usize) -> Point2<f64> {
        self.grid.point(k % self.grid.nx(), k / self.grid.nx())
    }

    /// The drive map over the grid, following `control`.
    ///
    /// # Errors
    ///
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory) when the columns
    /// cannot be allocated; [`Error::Cancelled`](crate::Error::Cancelled).
    pub fn map(&self, control: &Control<'_>) -> Result<DriveMap> {
        let mut columns = DriveColumns::for_overwrite(self.grid.len())?;
        self.map_into(columns.as_out(), control)?;
        Ok(DriveMap {
            context: self.clone(),
            columns,
        })
    }

    /// [`map`](Self::map) into columns the caller owns (an earlier map's,
    /// [`DriveColumns::as_out`], or NumPy arrays): every value written,
    /// the bits of `map`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::LengthMismatch`] when a column does not have
    /// `grid.len()` values; [`Error::Cancelled`](crate::Error::Cancelled)
    /// (the columns then hold a partial map).
    pub fn map_into(&self, out: DriveColumnsOut<'_>, control: &Control<'_>) -> Result<()> {
        out.check_len(self.grid.len())?;
        let mut judge = self.judge();
        // A sample's clearance over the turn can take tens of milliseconds
        // (refined by halves where a link grazes an obstacle): it polls the
        // cancel flag between its intervals too.
        judge.cancel = control.cancel_flag();
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        let grid = &self.grid;
        let rows = RowsOfDrive { out, nx };
        if judge.prepared.obstacles.is_empty() {
            // The rows on SIMD lanes (the scalar path's bits), then the
            // columns from them; the base plate per sample where given.
            let limits = self.lane_limits();
            let plate = !judge.prepared.is_empty();
            // Made on a block's first row: a cancelled map allocates none.
            let init = || Ok(None::<RowScratch>);
            return run_blocks_with(nx, ny, rows, control, init, |scratch, j0, mut block, n| {
                let scratch = scratch.get_or_insert_with(|| RowScratch::new(grid));
                for r in 0..n {
                    let y = grid.y(j0 + r);
                    Arch::new().dispatch(DriveRow {
                        swing: &self.swing,
                        limits,
                        y,
                        out: scratch,
                    });
                    judge.write_row(scratch, y, plate, &mut block.out, r * nx, nx);
                }
            });
        }
        // With obstacles a sample checks a full crank turn: the cancel flag
        // is polled per sample, not only per row.
        run_blocks_polled(nx, ny, rows, control, |j, mut row, control| {
            let y = grid.y(j);
            for i in 0..nx {
                if control.is_cancelled() {
                    return false;
                }
                row.out.set(i, judge.sample(Point2::new(grid.x(i), y)));
            }
            true
        })
    }

    /// The limits of [`DriveRow`]'s lanes.
    fn lane_limits(&self) -> [f64; 5] {
        let limits = self.limits();
        [
            limits.min_transmission,
            limits.max_link_ratio,
            self.options.max_time_ratio,
            limits.max_size_ratio,
            limits.max_link_length,
        ]
    }

    /// The limits and the prepared constraints.
    fn judge(&self) -> DriveJudge<'_> {
        DriveJudge {
            context: self,
            prepared: self.map_options.prepared(),
            cancel: None,
        }
    }

    /// The drive with its crank pivot at `d0`.
    ///
    /// # Errors
    ///
    /// [`DriveError::NotACrankRocker`] where `d0` gives no valid drive (the
    /// map's `valid` is false there); [`InvalidInput::NotFinite`] for a
    /// non-finite point.
    pub fn drive(&self, d0: Point2<f64>) -> Result<Drive> {
        finite_point(["drive pivot x", "drive pivot y"], d0)?;
        let judge = self.judge();
        judge.drive(d0)
    }

    /// The drive of sample `k`, with its index.
    ///
    /// # Errors
    ///
    /// As [`drive`](Self::drive).
    pub fn drive_at(&self, k: usize) -> Result<Drive> {
        let mut d = self.drive(self.point(k))?;
        d.index = Some((k / self.grid.nx(), k % self.grid.nx()));
        Ok(d)
    }

    /// The classic drive with time ratio 1 (module docs): the crank pivot
    /// on the line through `E`'s two end positions, beyond the end of the
    /// first pose (`beyond_first`) or of the last, at the distance that
    /// gives the drive loop the minimum transmission angle
    /// `drive_transmission` (radians) over a full turn; `None`: halfway
    /// between the limits' transmission angle and the best a time-ratio-1
    /// drive reaches, `pi/2 - swing/2` (the smaller the angle, the smaller
    /// the drive). The map's sample function evaluates it, so its figures
    /// are those of the map there.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::OutsideRange`] for a transmission angle outside
    /// `(0, pi/2 - swing/2)` (with `None`: a limit at or beyond it); as
    /// [`drive`](Self::drive).
    pub fn classic(&self, beyond_first: bool, drive_transmission: Option<f64>) -> Result<Drive> {
        let [pa, pb] = self.swing.arm;
        let rho = self.swing.rho;
        let swing = cross(pa, pb).abs().atan2(pa.dot(&pb));
        let mu = drive_transmission
            .unwrap_or(0.5 * (self.limits().min_transmission + FRAC_PI_2 - 0.5 * swing));
        let design = CrankRockerDesign::unit_time_ratio(rho, swing, mu)?;
        let mid = self.swing.a0 + 0.5 * (pa + pb);
        let chord = pb - pa;
        let u = chord / chord.norm();
        let d0 = if beyond_first {
            mid - u * design.coupler
        } else {
            mid + u * design.coupler
        };
        self.drive(d0)
    }

    best! {
        /// The [`Ranking::k`](crate::Ranking::k) best drives of a map's
        /// columns by `ranking` (the rankings of [`RankBy`] over the acceptable
        /// samples; [`RankBy::Margin`] orders the valid samples by their
        /// distance to the nearest sample without a drive). Candidates closer
        /// than the ranking's separation to a better one are skipped (default:
        /// 2% of the viewport's diagonal).
        ///
        /// # Errors
        ///
        /// [`InvalidInput::LengthMismatch`] for columns of another length than
        /// the grid; [`Error::OutOfMemory`](crate::Error::OutOfMemory).
        best_drives(DriveRankColumns<'_>) -> Drive, flagged drive_at
    }
}

flagged_rank_columns! {
    /// The columns a ranking of drives reads.
    DriveRankColumns, DriveMap, valid;
    Drive, "the best drives"
}

impl DriveMap {
    best! {
        /// The best drives by `ranking` (see [`DriveContext::best_drives`]).
        ///
        /// # Errors
        ///
        /// As [`DriveContext::best_drives`].
        best_drives -> Drive
    }
}

/// The limits and prepared constraints of a context: the one place a
/// sample's columns and a drive's figures are computed.
struct DriveJudge<'a> {
    context: &'a DriveContext,
    prepared: &'a Prepared,
    /// The map's cancel flag: a clearance test stops (not clear) once it is
    /// set, and the map is then [`Error::Cancelled`](crate::Error::Cancelled).
    cancel: Option<&'a AtomicBool>,
}

impl DriveJudge<'_> {
    /// Whether the figures meet the limits (transmission, link ratio, the
    /// six-bar's size ratio and longest link) and the time ratio (not the
    /// constraints): [`DriveRow`]'s `meets`, comparison for comparison.
    #[inline(always)]
    fn meets(&self, e: &Eval) -> bool {
        let (c, l) = (self.context, self.context.limits());
        e.valid
            && e.mu >= l.min_transmission
            && e.link_ratio <= l.max_link_ratio
            && e.time_ratio <= c.options.max_time_ratio
            && e.size_ratio <= l.max_size_ratio
            && e.lmax <= l.max_link_length
    }

    /// Whether `d0` is on the base plate and the six-bar of the drive clear
    /// of the obstacles over the whole turn.
    fn constraints_ok(&self, d0: Point2<f64>, e: &Eval) -> bool {
        if !self.prepared.pivot_ok(d0) {
            return false;
        }
        if self.prepared.obstacles.is_empty() {
            return true;
        }
        self.context
            .sixbar(d0, e)
            .is_ok_and(|six| self.clear_over_turn(&six, e))
    }

    /// Writes the row at ordinate `y` from its lanes (`scratch`, filled by
    /// [`DriveRow`]) into `out` from `base`: the samples [`sample`](Self::sample)
    /// gives, bit for bit (the base plate tested per sample when `plate`).
    #[inline]
    fn write_row(
        &self,
        scratch: &RowScratch,
        y: f64,
        plate: bool,
        out: &mut DriveColumnsOut<'_>,
        base: usize,
        nx: usize,
    ) {
        let nan = f32::NAN;
        let code = |f: f64| f as u8;
        let flags = &scratch.flags[..nx];
        let pick = |v: &[f64], i: usize| {
            if code(flags[i]) & 1 != 0 {
                v[i] as f32
            } else {
                nan
            }
        };
        for (i, d) in out.valid[base..base + nx].iter_mut().enumerate() {
            *d = code(flags[i]) & 1 != 0;
        }
        for (i, d) in out.min_transmission_rad[base..base + nx]
            .iter_mut()
            .enumerate()
        {
            *d = pick(&scratch.mu, i);
        }
        for (i, d) in out.drive_transmission_rad[base..base + nx]
            .iter_mut()
            .enumerate()
        {
            *d = pick(&scratch.drive_mu, i);
        }
        for (i, d) in out.time_ratio[base..base + nx].iter_mut().enumerate() {
            *d = pick(&scratch.time_ratio, i);
        }
        for (i, d) in out.link_ratio[base..base + nx].iter_mut().enumerate() {
            *d = pick(&scratch.link_ratio, i);
        }
        for (i, d) in out.size_ratio[base..base + nx].iter_mut().enumerate() {
            *d = pick(&scratch.size_ratio, i);
        }
        for (i, d) in out.acceptable[base..base + nx].iter_mut().enumerate() {
            *d = code(flags[i]) & 2 != 0
                && (!plate || self.prepared.pivot_ok(Point2::new(scratch.xs[i], y)));
        }
    }

    /// One sample of the map.
    #[inline(always)]
    fn sample(&self, d0: Point2<f64>) -> DriveSample {
        let e = self.context.swing.eval(d0);
        if !e.valid {
            return DriveSample::INVALID;
        }
        let acceptable = self.meets(&e) && self.constraints_ok(d0, &e);
        DriveSample {
            valid: true,
            min_transmission_rad: e.mu as f32,
            drive_transmission_rad: e.drive_mu as f32,
            time_ratio: e.time_ratio as f32,
            link_ratio: e.link_ratio as f32,
            size_ratio: e.size_ratio as f32,
            acceptable,
        }
    }

    /// The drive with crank pivot `d0`.
    fn drive(&self, d0: Point2<f64>) -> Result<Drive> {
        let c = self.context;
        let e = c.swing.eval(d0);
        let not = || DriveError::NotACrankRocker { x: d0.x, y: d0.y };
        if !e.valid {
            return Err(not().into());
        }
        let six = c.sixbar(d0, &e)?;
        let limits = six.limit_positions().ok_or_else(not)?;
        // The limit where the working stroke starts: E at the first pose's
        // end of the swing.
        let [ta, _] = c.swing.theta;
        let (start, end) = if wrap_angle(limits[0].input_angle - ta).abs()
            <= wrap_angle(limits[1].input_angle - ta).abs()
        {
            (limits[0], limits[1])
        } else {
            (limits[1], limits[0])
        };
        let beta = (end.crank_angle - start.crank_angle).rem_euclid(TAU);
        let (direction, stroke) = if beta >= PI {
            (Direction::Ccw, beta)
        } else {
            (Direction::Cw, TAU - beta)
        };
        let s = direction.sign();
        let stops = c.linkage.travel_stops().ok_or(DriveError::NoTravel)?;
        // Near a limit position the crank angle of an input angle is ill
        // conditioned (the input is stationary there): a few 1e-7 rad from
        // a rounding of 1e-13; the pose itself is reached to second order.
        let slack = 1e-6;
        let last = stops.len() - 1;
        let mut angles = [0.0; crate::geom::MAX_POSES];
        for (k, &theta) in stops.iter().enumerate() {
            if c.options.swing_margin == 0.0 && (k == 0 || k == last) {
                // The stroke ends at the first and the last pose exactly.
                angles[k] = start.crank_angle + if k == 0 { 0.0 } else { s * stroke };
                continue;
            }
            let best = six
                .crank_angles_for_input(theta)
                .into_iter()
                .map(|phi| {
                    let o = ((phi - start.crank_angle) * s).rem_euclid(TAU);
                    if o > TAU - slack { 0.0 } else { o }
                })
                .filter(|&o| o <= stroke + slack)
                .fold(f64::NAN, |m, o| if m.is_nan() || o < m { o } else { m });
            if best.is_nan() {
                return Err(not().into());
            }
            angles[k] = start.crank_angle + s * best.min(stroke);
        }
        let pose_crank_angles = PerPose::from_slice(&angles[..stops.len()]);
        let acceptable = self.meets(&e) && self.constraints_ok(d0, &e);
        Ok(Drive {
            sixbar: six,
            linkage: c.linkage,
            drive_pivot: d0,
            attachment: c.attachment,
            figures: DriveFigures {
                min_transmission: e.mu,
                drive_transmission: e.drive_mu,
                motion_transmission: c.swing.motion_mu,
                time_ratio: e.time_ratio,
                link_ratio: e.link_ratio,
                size_ratio: e.size_ratio,
                swing: c.swing.theta,
                stroke,
            },
            pose_crank_angles,
            stroke_start: start.crank_angle,
            direction,
            acceptable,
            index: None,
            margin: f64::NAN,
            score: f64::NAN,
            ranked_by: None,
        })
    }

    /// Whether the six-bar's moving links, as capsules, clear every
    /// obstacle over a full crank turn: the constraints' interval test
    /// ([`Constraints`]) with the speed bound of the six-bar's joints per
    /// unit crank angle: `D` moves `r`, `E` at most `r / sin(gamma_min)`,
    /// `A` at most `L2 r / (rho sin(gamma_min))` and `C` at most that over
    /// `sin(mu_min)`.
    fn clear_over_turn(&self, six: &SixBar, e: &Eval) -> bool {
        let l = six.lengths();
        let (sd, sm) = (e.drive_mu.sin(), self.context.swing.motion_mu.sin());
        if !(sd > 0.0 && sm > 0.0) {
            return false;
        }
        let r = l.crank;
        let turn = r / (l.rocker * sd);
        let rate = fmax(fmax(r, r / sd), fmax(l.input * turn, l.input * turn / sm));
        let n = self.prepared.samples();
        let step = TAU / n as f64;
        (0..n).all(|k| {
            self.going() && self.interval_clear(six, step * (k as f64 + 0.5), 0.5 * step, rate)
        })
    }

    /// Whether the map goes on (its cancel flag, if any, is clear).
    #[inline]
    fn going(&self) -> bool {
        self.cancel.is_none_or(|c| !c.load(Ordering::Relaxed))
    }

    fn interval_clear(&self, six: &SixBar, mid: f64, half: f64, rate: f64) -> bool {
        match self.clear_at(six, mid, rate * half) {
            Some(true) => return true,
            None => return false,
            Some(false) => {}
        }
        if self.clear_at(six, mid, 0.0) != Some(true)
            || half < Constraints::MIN_STEP
            || !self.going()
        {
            return false;
        }
        let q = 0.5 * half;
        self.interval_clear(six, mid - q, q, rate) && self.interval_clear(six, mid + q, q, rate)
    }

    fn clear_at(&self, six: &SixBar, phi: f64, extra: f64) -> Option<bool> {
        let j = six.joints_at(phi).ok()?;
        let segs = [
            (j.drive_pivot, j.crank_joint),
            (j.crank_joint, j.attachment),
            (j.input_pivot, j.attachment),
            (j.input_pivot, j.input_joint),
            (j.input_joint, j.attachment),
            (j.input_joint, j.rocker_joint),
            (j.output_pivot, j.rocker_joint),
        ];
        Some(self.prepared.segments_clear(&segs, extra))
    }
}

impl DriveContext {
    /// The six-bar of the drive `e` at `d0`.
    fn sixbar(&self, d0: Point2<f64>, e: &Eval) -> Result<SixBar> {
        let l = &self.linkage;
        let [_, r, c] = e.lengths;
        let drive = FourBar::from_pivots(d0, self.swing.a0, r, c, self.swing.rho)?;
        SixBar::new(
            drive,
            l.fourbar,
            self.swing.delta,
            e.mode,
            self.swing.motion_mode,
        )?
        .with_coupler_point(l.coupler_point, l.coupler_angle_offset)
    }
}

/// The swing of `linkage` with the attachment at `attachment` (module docs).
fn swing_of(
    linkage: &SynthesizedFourBar,
    attachment: Point2<f64>,
    options: &DriveOptions,
) -> Result<Swing> {
    let f = &linkage.figures;
    let motion_mode = match linkage.modes().first() {
        Some(Some(m)) if f.feasible() => *m,
        _ => return Err(DriveError::NoTravel.into()),
    };
    let (start, span) = linkage.travel().ok_or(DriveError::NoTravel)?;
    let margin = options.swing_margin;
    let sign = span.signum();
    let swing = span.abs() + 2.0 * margin;
    // NaN fails too.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    if !(swing < PI * (1.0 - 1e-9)) {
        return Err(DriveError::TravelTooLarge {
            travel_deg: span.abs().to_degrees(),
            swing_deg: swing.to_degrees(),
            margin_deg: margin.to_degrees(),
        }
        .into());
    }
    let (before, after) = room(&linkage.fourbar, start, span);
    if !(margin < before && margin < after) {
        return Err(DriveError::OutsideInputRange {
            margin_deg: margin.to_degrees(),
            before_deg: before.to_degrees(),
            after_deg: after.to_degrees(),
        }
        .into());
    }
    let theta = [start - sign * margin, start + span + sign * margin];
    let a0 = linkage.driving.center;
    let arm = attachment - a0;
    let rho = arm.norm();
    let span_task = pose_span(linkage);
    let tiny = tolerance::POINT * span_task.max(linkage.fourbar.lengths()[0]);
    // NaN fails too.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    if !(rho > tiny) {
        return Err(DegenerateError::ZeroLengthLink {
            what: "input link arm A0-E (the attachment is on A0)",
            x: attachment.x,
            y: attachment.y,
        }
        .into());
    }
    let theta1 = linkage.input_angles[0];
    let delta = wrap_angle(arm.y.atan2(arm.x) - theta1);
    let arm_at = |t: f64| unit(t + delta) * rho;
    let (lo, width) = if sign >= 0.0 {
        (theta[0], theta[1] - theta[0])
    } else {
        (theta[1], theta[0] - theta[1])
    };
    let motion_mu = acos1(fmin(arc_worst_cos(&linkage.fourbar, lo, width), 1.0));
    let ls = linkage.fourbar.lengths();
    let arm_off =
        crate::linkage::sixbar::attachment_arm(rho, delta, (linkage.driving.circle - a0).norm());
    Ok(Swing {
        a0,
        rho,
        delta,
        theta,
        arm: [arm_at(theta[0]), arm_at(theta[1])],
        motion_mode,
        motion_mu,
        members: linkage.size() + arm_off,
        link_min: ls.iter().copied().fold(rho, f64::min),
        link_max: ls.iter().copied().fold(rho, f64::max),
        inv_span: 1.0 / span_task,
        tiny,
    })
}

/// How far the input of `fb` can turn before `start` and past
/// `start + span` (the travel, signed) before a dead position: infinite
/// when it turns fully.
fn room(fb: &FourBar, start: f64, span: f64) -> (f64, f64) {
    let arcs = match fb.input_range() {
        InputRange::Full => return (f64::INFINITY, f64::INFINITY),
        InputRange::Arc(a) => vec![a],
        InputRange::TwoArcs(a, b) => vec![a, b],
    };
    for a in arcs {
        if a.contains(start) {
            let from = (start - a.start).rem_euclid(TAU);
            // Counter-clockwise room below the travel and above it.
            let (lo, hi) = if span >= 0.0 {
                (from, a.span() - from - span)
            } else {
                (from + span, a.span() - from)
            };
            return if span >= 0.0 { (lo, hi) } else { (hi, lo) };
        }
    }
    (0.0, 0.0)
}

/// The task's span from the poses the linkage reaches: the largest
/// distance between two of them.
pub(crate) fn pose_span(linkage: &SynthesizedFourBar) -> f64 {
    let mode = linkage.modes()[0].unwrap_or(AssemblyMode::Open);
    let pts: Vec<Point2<f64>> = linkage
        .input_angles
        .iter()
        .filter_map(|&t| linkage.pose_at(t, mode).ok().map(|p| p.position))
        .collect();
    let mut span: f64 = 0.0;
    for (i, p) in pts.iter().enumerate() {
        for q in &pts[i + 1..] {
            span = span.max((p - q).norm());
        }
    }
    span
}

/// Where to look for attachments and drive pivots
/// ([`search_drives`]): the attachment `E` at `ratio |A - A0|` from `A0`,
/// turned `angle` from the input link (`0`: on the link through `A`,
/// `pi`: behind `A0`), for every ratio and angle; for each, a drive map of
/// `samples x samples` candidate pivots over the square of half-width
/// `reach |E - A0|` about `A0`.
#[derive(Debug, Clone, PartialEq)]
pub struct AttachmentSearch {
    /// `|E - A0| / |A - A0|` of each candidate (default 0.5, 1, 1.5, 2).
    pub ratios: Vec<f64>,
    /// The angle of each candidate from the input link, radians (default
    /// every 30 degrees).
    pub angles: Vec<f64>,
    /// The half-width of each drive map, in units of `|E - A0|` (default 4).
    pub reach: f64,
    /// Samples per side of each drive map (default 96).
    pub samples: usize,
}

impl Default for AttachmentSearch {
    fn default() -> Self {
        AttachmentSearch {
            ratios: vec![0.5, 1.0, 1.5, 2.0],
            angles: (0..12).map(|k| (30.0 * k as f64).to_radians()).collect(),
            reach: 4.0,
            samples: 96,
        }
    }
}

impl AttachmentSearch {
    /// The most candidate attachments.
    pub const MAX_ATTACHMENTS: usize = 4096;

    /// Checks the search.
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for no candidates or more than
    /// [`MAX_ATTACHMENTS`](Self::MAX_ATTACHMENTS), a ratio that is not
    /// positive and finite (at most `1e6`), a non-finite angle, a reach
    /// outside `(0, 1e6]`, or samples outside `1..=`[`DriveContext::MAX_SEARCH_SAMPLES`].
    pub fn validate(&self) -> Result<()> {
        let n = self.ratios.len().saturating_mul(self.angles.len());
        count_in("attachment candidates", n, 1, Self::MAX_ATTACHMENTS)?;
        for &r in &self.ratios {
            if !(r > 0.0 && r <= 1e6) {
                return Err(InvalidInput::OutsideRange {
                    name: "attachment ratio",
                    value: r,
                    min: 0.0,
                    max: 1e6,
                    unit: " (above 0)",
                }
                .into());
            }
        }
        for &a in &self.angles {
            crate::error::bounded("attachment angle", a, 1e9, "reduce it modulo 2 pi")?;
        }
        if !(self.reach > 0.0 && self.reach <= 1e6) {
            return Err(InvalidInput::OutsideRange {
                name: "reach",
                value: self.reach,
                min: 0.0,
                max: 1e6,
                unit: " (above 0)",
            }
            .into());
        }
        count_in("samples", self.samples, 1, DriveContext::MAX_SEARCH_SAMPLES)?;
        Ok(())
    }

    /// The candidate attachments of `linkage`, at pose 1.
    pub fn attachments(&self, linkage: &SynthesizedFourBar) -> Vec<Point2<f64>> {
        let a0 = linkage.driving.center;
        let arm = linkage.driving.circle - a0;
        let mut out = Vec::with_capacity(self.ratios.len() * self.angles.len());
        for &r in &self.ratios {
            for &a in &self.angles {
                out.push(a0 + crate::geom::rotate(arm * r, a));
            }
        }
        out
    }
}

/// What [`search_drives`] found: the best drive of each attachment that
/// has an acceptable one, best first, and what was searched.
#[derive(Debug, Clone, PartialEq)]
pub struct DriveSearch {
    /// The best drive of each attachment with an acceptable drive, best
    /// first by the ranking (ties to the smaller size ratio).
    pub drives: Vec<Drive>,
    /// Candidate drive pivots examined, over every attachment.
    pub searched: usize,
    /// Of them, pivots with a drive (the maps' `valid`).
    pub valid: usize,
    /// The best minimum transmission angle of those, radians (NaN when
    /// there were none).
    pub best_transmission: f64,
}

/// Searches attachments and drive pivots for `linkage` (see
/// [`AttachmentSearch`]): for each attachment the drive map and its best
/// acceptable drive by `rank_by` (balanced, transmission or compact),
/// following `control` (the progress counts the rows of every map).
///
/// # Errors
///
/// [`InvalidInput`] for an invalid search or drive options, an envelope
/// among the constraints, or a ranking other than balanced, transmission or
/// compact; the errors of
/// [`DriveContext::new`] that do not depend on the attachment (no travel,
/// a travel too large, margins outside the input range);
/// [`Error::Cancelled`](crate::Error::Cancelled).
pub fn search_drives(
    linkage: &SynthesizedFourBar,
    search: &AttachmentSearch,
    map_options: &MapOptions,
    options: &DriveOptions,
    rank_by: RankBy,
    control: &Control<'_>,
) -> Result<DriveSearch> {
    search.validate()?;
    if !matches!(
        rank_by,
        RankBy::Balanced | RankBy::Transmission | RankBy::Compact
    ) {
        return Err(InvalidInput::UnknownName {
            what: "ranking of a drive search",
            expected: "\"balanced\", \"transmission\" or \"compact\"",
            found: rank_by.as_str().to_owned(),
        }
        .into());
    }
    let attachments = search.attachments(linkage);
    let n = search.samples;
    let parts = attachments.len();
    let mut drives = Vec::new();
    let (mut searched, mut valid, mut best_mu) = (0usize, 0usize, f64::NAN);
    for (k, &e) in attachments.iter().enumerate() {
        let rho = (e - linkage.driving.center).norm();
        let a0 = linkage.driving.center;
        let h = search.reach * rho;
        let grid = Grid::from_bounds(a0.x - h, a0.x + h, a0.y - h, a0.y + h, n, n)?;
        let context = match DriveContext::new(linkage, e, &grid, map_options, options) {
            Ok(c) => c,
            // An attachment too close to A0 for this linkage: skip it.
            Err(crate::Error::Degenerate(DegenerateError::ZeroLengthLink { .. })) => continue,
            Err(err) => return Err(err),
        };
        let hook = |d: usize, _t: usize| control.report(k * n + d, parts * n);
        let mut part = Control::new().with_progress(&hook);
        if let Some(flag) = control.cancel_flag() {
            part = part.with_cancel(flag);
        }
        let map = context.map(&part).map_err(|err| match err {
            crate::Error::Cancelled { done, .. } => crate::Error::Cancelled {
                done: k * n + done,
                total: parts * n,
            },
            other => other,
        })?;
        searched += grid.len();
        for (s, &v) in map.columns.valid.iter().enumerate() {
            if v {
                valid += 1;
                let mu = f64::from(map.columns.min_transmission_rad[s]);
                if best_mu.is_nan() || mu > best_mu {
                    best_mu = mu;
                }
            }
        }
        if let Some(d) = map
            .best_drives(Ranking::new(1, rank_by))?
            .into_iter()
            .next()
        {
            drives.push(d);
        }
    }
    drives.sort_by(|a, b| {
        b.score.total_cmp(&a.score).then(tie_order(
            (a.figures.size_ratio as f32, 0.0),
            (b.figures.size_ratio as f32, 0.0),
        ))
    });
    Ok(DriveSearch {
        drives,
        searched,
        valid,
        best_transmission: best_mu,
    })
}

/// The best drive for `linkage` under the limits, the options and the
/// constraints, by `rank_by` over the default [`AttachmentSearch`]: the
/// function the one-call design calls for a linkage whose input swings.
/// The limits' input requirement does not apply (a drive's crank always
/// turns fully); their transmission angle and link ratio do, for both
/// loops and the six-bar's links, and their size ratio and longest link
/// for the whole six-bar (its size over the task's span, and every link of
/// both loops).
///
/// # Errors
///
/// [`DriveError::NoAcceptableDrive`] (with what was searched and the best
/// transmission angle found) when no drive is acceptable; the other
/// [`DriveError`]s say why a drive cannot exist at all (no travel, a travel
/// too large for a crank-rocker, margins beyond the input's dead
/// positions); as [`search_drives`].
///
/// # Example
///
/// ```
/// use burmester::design::{best_drive, DriveOptions};
/// use burmester::{Control, MapOptions, RankBy, example};
/// let filemon = example::task().filemon(example::driven_center())?;
/// let linkage = filemon.four_bar(burmester::Point2::new(-2.0, 6.0))?;
/// match best_drive(&linkage, &MapOptions::default(), &DriveOptions::default(),
///                  RankBy::Balanced, &Control::new()) {
///     Ok(drive) => assert!(drive.sixbar.crank_turns_fully() && drive.acceptable),
///     Err(burmester::Error::Drive(why)) => println!("no drive: {why}"),
///     Err(e) => return Err(e),
/// }
/// # Ok::<(), burmester::Error>(())
/// ```
pub fn best_drive(
    linkage: &SynthesizedFourBar,
    map_options: &MapOptions,
    options: &DriveOptions,
    rank_by: RankBy,
    control: &Control<'_>,
) -> Result<Drive> {
    let search = AttachmentSearch::default();
    let found = search_drives(linkage, &search, map_options, options, rank_by, control)?;
    found.drives.into_iter().next().ok_or_else(|| {
        DriveError::NoAcceptableDrive {
            searched: found.searched,
            valid: found.valid,
            best_transmission_deg: found.best_transmission.to_degrees(),
            min_transmission_deg: map_options.limits().min_transmission.to_degrees(),
        }
        .into()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linkage::sixbar::drive_worst_cos;
    use crate::simd::Width;

    /// The drive map's rows on every lane width (1, 2, 4, 8 and as
    /// dispatched) give the scalar path's bits, sample by sample, with and
    /// without finite size limits (the six-bar's size ratio and longest
    /// link).
    #[test]
    fn drive_lanes_are_the_scalar_path_on_every_width() {
        let linkage = example_linkage(60, &DesignLimits::default());
        let a0 = linkage.driving.center;
        let g =
            Grid::from_bounds(a0.x - 40.0, a0.x + 40.0, a0.y - 40.0, a0.y + 40.0, 37, 29).unwrap();
        let opts = DriveOptions {
            swing_margin: 0.02,
            max_time_ratio: 1.3,
        };
        let context = |limits: &DesignLimits| {
            let map_options = MapOptions::new(limits, &Constraints::default()).unwrap();
            DriveContext::new(&linkage, linkage.driving.circle, &g, &map_options, &opts).unwrap()
        };
        // Size limits that cut through the valid samples: the medians of
        // their size ratios and longest links.
        let free = context(&DesignLimits::default());
        let (mut sizes, mut longest) = (Vec::new(), Vec::new());
        for k in 0..g.len() {
            let e = free.swing.eval(free.point(k));
            if e.valid {
                sizes.push(e.size_ratio);
                longest.push(e.lmax);
            }
        }
        sizes.sort_by(f64::total_cmp);
        longest.sort_by(f64::total_cmp);
        let (size, length) = (sizes[sizes.len() / 2], longest[longest.len() / 2]);
        let d = DesignLimits::default();
        for limits in [
            d,
            d.with_size(size, f64::INFINITY).unwrap(),
            d.with_size(f64::INFINITY, length).unwrap(),
            d.with_size(size, length).unwrap(),
        ] {
            let counts = lanes_against_scalar(&context(&limits), &g);
            assert!(counts[0] > 0 && counts[1] > 0, "{counts:?} {limits:?}");
        }
    }

    /// The best-transmission linkage of the example's solution map on an
    /// `n` x `n` grid under `limits`.
    fn example_linkage(n: usize, limits: &DesignLimits) -> SynthesizedFourBar {
        let task = crate::example::task();
        let f = task.filemon(crate::example::driven_center()).unwrap();
        let grid = Grid::new(crate::example::viewport(), n, n).unwrap();
        let map = f
            .solution_map(
                &grid,
                &MapOptions::new(limits, &Constraints::default()).unwrap(),
                &Control::new(),
            )
            .unwrap();
        map.best_pivots(Ranking::new(1, RankBy::Transmission))
            .unwrap()[0]
            .linkage
    }

    /// A drive map with an obstacle polls its cancel flag inside a sample's
    /// clearance test, not only between samples: one sample's test over the
    /// turn took up to 40 ms (refined by halves where a link grazes the
    /// obstacle; measured from Python on the map of
    /// `test_drive.py::test_ctrl_c_stops_a_drive_map`, whose Ctrl-C latency
    /// that made 0.56 s under load), and the map waited for it. With the
    /// flag set, every sample that was clear is no longer taken as clear
    /// (the test stopped at once), and the map is `Cancelled`.
    #[test]
    fn a_clearance_test_over_the_turn_stops_when_cancelled() {
        use core::sync::atomic::AtomicBool;
        let limits = DesignLimits {
            min_transmission: 30f64.to_radians(),
            ..DesignLimits::default()
        };
        let linkage = example_linkage(100, &limits);
        let a0 = linkage.driving.center;
        let wall = [(0.5, -9.0), (0.8, -9.0), (0.8, 9.0), (0.5, 9.0)]
            .map(|(x, y)| Point2::new(a0.x + x, a0.y + y))
            .to_vec();
        let constraints = Constraints {
            obstacles: vec![wall],
            link_width: 0.05,
            travel_samples: 128,
            ..Constraints::default()
        };
        let free = DesignLimits {
            min_transmission: 0.0,
            max_link_ratio: f64::INFINITY,
            ..DesignLimits::default()
        };
        let g = Grid::from_bounds(a0.x - 9.0, a0.x + 9.0, a0.y - 9.0, a0.y + 9.0, 12, 12).unwrap();
        let ctx = DriveContext::new(
            &linkage,
            linkage.driving.circle,
            &g,
            &MapOptions::new(&free, &constraints).unwrap(),
            &DriveOptions::default(),
        )
        .unwrap();
        let stop = AtomicBool::new(true);
        let mut stopped = ctx.judge();
        stopped.cancel = Some(&stop);
        let judge = ctx.judge();
        let mut clear = 0;
        for k in 0..g.len() {
            let d0 = ctx.point(k);
            let e = ctx.swing.eval(d0);
            if !(e.valid && judge.meets(&e)) {
                continue;
            }
            let six = ctx.sixbar(d0, &e).unwrap();
            if judge.clear_over_turn(&six, &e) {
                clear += 1;
                assert!(!stopped.clear_over_turn(&six, &e), "{d0}");
            }
        }
        assert!(clear > 0, "no sample clears the wall");
        let cancelled = Control::new().with_cancel(&stop);
        assert!(matches!(
            ctx.map(&cancelled),
            Err(crate::Error::Cancelled { .. })
        ));
    }

    /// Checks every row of `ctx`'s grid on every lane width against the
    /// scalar path and the map; counts the valid samples, not acceptable
    /// and acceptable.
    fn lanes_against_scalar(ctx: &DriveContext, g: &Grid) -> [usize; 2] {
        let judge = ctx.judge();
        let lim = ctx.lane_limits();
        let mut counts = [0usize; 2];
        for j in 0..g.ny() {
            let y = g.y(j);
            let run = |width: Width| {
                let mut scratch = RowScratch::new(g);
                width.run(DriveRow {
                    swing: &ctx.swing,
                    limits: lim,
                    y,
                    out: &mut scratch,
                });
                scratch
            };
            for width in Width::ALL {
                let sc = run(width);
                for i in 0..g.nx() {
                    let d0 = Point2::new(g.x(i), y);
                    let e = ctx.swing.eval(d0);
                    let s = judge.sample(d0);
                    let flag = sc.flags[i] as u8;
                    assert_eq!(flag & 1 != 0, e.valid && s.valid, "{d0}");
                    assert_eq!(flag & 2 != 0, s.acceptable, "{d0}");
                    if e.valid {
                        for (lane, scalar) in [
                            (sc.mu[i], e.mu),
                            (sc.drive_mu[i], e.drive_mu),
                            (sc.time_ratio[i], e.time_ratio),
                            (sc.link_ratio[i], e.link_ratio),
                            (sc.size_ratio[i], e.size_ratio),
                        ] {
                            assert_eq!(lane.to_bits(), scalar.to_bits(), "{d0}");
                        }
                        counts[usize::from(s.acceptable)] += 1;
                    }
                }
            }
        }
        // And the map itself is the samples.
        let m = ctx.map(&Control::new()).unwrap();
        for k in 0..g.len() {
            let s = judge.sample(ctx.point(k));
            assert_eq!(m.columns.valid[k], s.valid);
            assert_eq!(m.columns.acceptable[k], s.acceptable);
            assert_eq!(
                m.columns.min_transmission_rad[k].to_bits(),
                s.min_transmission_rad.to_bits()
            );
            assert_eq!(m.columns.time_ratio[k].to_bits(), s.time_ratio.to_bits());
            assert_eq!(m.columns.size_ratio[k].to_bits(), s.size_ratio.to_bits());
        }
        counts
    }

    #[test]
    fn unit_time_ratio_matches_the_construction() {
        // Norton's construction for a 45 degree swing: the crank is half
        // the chord B1 B2; O2 on the chord's line.
        let (rho, swing) = (2.0, 45f64.to_radians());
        for mu in [20.0f64, 40.0, 60.0] {
            let d = CrankRockerDesign::unit_time_ratio(rho, swing, mu.to_radians()).unwrap();
            let (b1, b2) = (unit(0.0) * rho, unit(swing) * rho);
            assert!((d.crank - 0.5 * (b2 - b1).norm()).abs() < 1e-14);
            // O2 beyond B2 on the chord's line at distance `coupler` from
            // the midpoint: the crank and coupler are collinear at both ends.
            let mid = 0.5 * (b1 + b2);
            let u = (b2 - b1) / (b2 - b1).norm();
            let o2 = mid + u * d.coupler;
            assert!((o2.norm() - d.ground).abs() < 1e-12);
            assert!(((o2 - b1).norm() - (d.coupler + d.crank)).abs() < 1e-12);
            assert!(((o2 - b2).norm() - (d.coupler - d.crank)).abs() < 1e-12);
            // The transmission angle at the crank along the ground line.
            let worst = drive_worst_cos(d.ground, d.crank, d.coupler, d.rocker);
            assert!((worst.acos() - mu.to_radians()).abs() < 1e-12, "{mu}");
        }
        assert!(CrankRockerDesign::unit_time_ratio(1.0, 1.0, 1.2).is_err());
        assert!(CrankRockerDesign::unit_time_ratio(1.0, PI, 0.1).is_err());
        assert!(CrankRockerDesign::unit_time_ratio(-1.0, 1.0, 0.1).is_err());
    }
}
