//! A linear actuator as the input: where to put a cylinder, an electric
//! actuator or a gas strut that drives a synthesized four-bar.
//!
//! The actuator is **added** between a ground pivot `G` and a point `Q` of
//! a moving link (the coupler, the crank or the rocker) of a
//! [`SynthesizedFourBar`]: 6 links, 7 joints, one degree of freedom, driven
//! by the actuator's length `s = |Q - G|` ([`LinkPoint`] gives `Q` and its
//! velocity). The four-bar's own branch, order and circuit verdicts stand:
//! the context takes a feasible linkage and its travel (first pose to
//! last, one assembly mode) and refuses any other
//! ([`DriveError::NoTravel`]). For a placement it adds:
//!
//! * **monotone**: `s` grows (or shrinks) all the way from the first pose
//!   to the last: `ds/dtheta2 = <Q - G, dQ/dtheta2> / s` has no root inside
//!   the travel. Such a root is where the actuator's line is normal to the
//!   velocity of `Q`, or where `Q` stops (a rocker at a limit position of
//!   its own inside the travel, a coupler point through the instantaneous
//!   center): the actuator is at a dead point, its force does no work on
//!   the linkage, and the linkage cannot be pushed on through the poses in
//!   order (the length turns back).
//! * the **stroke** `s_max - s_min` and the **stroke ratio** `s_max / s_min`
//!   over the travel: a cylinder's closed length is more than half its open
//!   length (its body holds the retracted rod), so the ratio is below 2; the
//!   designer's limit is [`ActuatorOptions::max_stroke_ratio`] (default
//!   1.8).
//! * the **force transmission angle** over the travel: with `beta` the
//!   angle between the actuator's line `Q - G` and the velocity of `Q` (the
//!   pressure angle), the transmission angle is `mu = 90° - beta`,
//!   `sin mu = |<Q - G, dQ/dtheta2>| / (s |dQ/dtheta2|)`: 90° when the
//!   actuator pushes `Q` along its path, 0 at a dead point, the four-bar's
//!   convention (its transmission angle is 90° minus the angle between the
//!   coupler's force and the rocker tip's velocity). Its minimum over the
//!   travel is checked against [`DesignLimits::min_transmission`].
//! * the size: the linkage's members and the open actuator over the task's
//!   span, and the longest over the shortest member (the closed actuator
//!   among them).
//!
//! # What is exact and what is sampled
//!
//! `Q` and `dQ/dtheta2` are exact (closed form) at every input angle. The
//! lengths at the poses are exact. The travel is sampled at
//! [`ActuatorOptions::travel_samples`] input angles, evenly, both ends
//! (the first and the last pose) included; a root of `ds/dtheta2` is
//! **bracketed** where its sign changes between samples (zeros at a sample
//! count on the sign after them), so a root of even multiplicity (a
//! stationary `s` that goes on in the same direction: still monotone) is
//! not a turning point, and two roots closer together than the sample step
//! can be missed. The map's figures are those of the samples (but its
//! `clearance` and `acceptable`: "The map and its placements" below); a
//! [placement](ActuatorContext::placement) refines each bracketed root by
//! bisection to rounding (the turning points and, for a non-monotone
//! placement, `s_min`/`s_max` there), and the minimum transmission angle by
//! golden section about its smallest sample. A monotone placement's
//! `s_min` and `s_max` are its lengths at the first and the last pose,
//! exact.
//!
//! # Clearance
//!
//! A [placement](ActuatorContext::placement) also says whether the strut,
//! its line from `G` to `Q` a capsule of the strut's diameter
//! ([`ActuatorOptions::actuator_width`]: one diameter for the whole strut,
//! give the body's), stays clear over the travel
//! ([`Actuator::min_clearance`], [`Actuator::clear`]) of
//!
//! * the linkage's links, each the capsule of its center line, as wide as
//!   [`Constraints::link_width`] (the crank `A0 A`, the coupler's bar
//!   `A B`, the rocker `C0 B`), except a link that carries `Q` (the one it
//!   acts on, or one joined to it at `Q`): such a link may not cross the
//!   strut away from `Q` (a strut through its own link's bar, a bracket on
//!   the wrong side);
//! * the constraints' obstacles (the ground pivot included: a pivot on an
//!   obstacle is a hit) and the envelope's boundary (the ground pivot
//!   inside it).
//!
//! The gap is the least distance between the center lines less the two
//! capsules' half widths (the strut's and the link's; the strut's alone
//! against an obstacle or the envelope): negative where they overlap, and
//! the two half widths below zero at a crossing. A placement is **clear**
//! when its gap is above 0 and at least [`ActuatorOptions::min_gap`]; an
//! acceptable placement is clear. The gap is taken at every travel sample
//! and its smallest sample is refined by golden section, as the
//! transmission angle is: two contacts closer together than a sample step
//! could be missed, as could a contact of a shape thinner than the links
//! move in a step.
//!
//! # The map and its placements
//!
//! A map sample whose sampled figures meet the limits is judged as its
//! [placement](ActuatorContext::placement) is, on the refined transmission
//! angle and gap (each at most its smallest sample): its `clearance` column
//! is the placement's [`min_clearance`](Actuator::min_clearance), and it is
//! `acceptable` only where the placement is. So every placement the
//! rankings over `acceptable` return ([`ActuatorContext::best_placements`])
//! is acceptable and clear by its own figures, its gap at least `min_gap`.

use nalgebra::{Point2, Vector2};

use crate::design::columns::map_columns;
use crate::design::constraints::Prepared;
use crate::design::rank::{best, flagged_rank_columns};
use crate::design::{Constraints, DesignLimits, MapOptions, RankBy};
use crate::engine::{Control, for_rows};
use crate::error::{
    DegenerateError, DriveError, InvalidInput, Result, count_in, finite_point, in_range, try_vec,
};
use crate::geom::{Grid, PerPose};
use crate::linkage::actuator::{ActuatorLink, LinkPoint};
use crate::linkage::{AssemblyMode, Joints};
use crate::synthesis::SynthesizedFourBar;

mod clearance;

use clearance::StrutCheck;

map_columns! {
    $ actuator_map_columns, "actuator map",
    (
        ActuatorColumns,
        ActuatorColumnsOut,
        ActuatorSample,
        "an actuator map",
        "The columns of an actuator map: one value per grid sample, row-major.",
        "An actuator map's columns to write: one slice per column, one value per grid \
         sample, row-major."
    );
    /// The actuator has a length over the whole travel (the ground
    /// pivot is off the point's path). Where false, the other columns
    /// hold false or NaN.
    valid: bool = false,
    /// Its length is monotone from the first pose to the last (no
    /// sampled sign change of `ds/dtheta2`).
    monotone: bool = false,
    /// Its length grows from the first pose to the last.
    extends: bool = false,
    /// The actuator's minimum force transmission angle over the
    /// sampled travel, radians (90 degrees minus the angle between its
    /// line and the velocity of its moving point).
    min_transmission_rad: f32 = f32::NAN,
    /// The longest over the shortest length over the travel.
    stroke_ratio: f32 = f32::NAN,
    /// The longest minus the shortest length over the travel.
    stroke: f32 = f32::NAN,
    /// The shortest length over the travel (the closed actuator).
    closed_length: f32 = f32::NAN,
    /// The longest over the shortest member: the linkage's links and
    /// the actuator, closed and open.
    link_ratio: f32 = f32::NAN,
    /// The linkage's size and the open actuator over the task's span.
    size_ratio: f32 = f32::NAN,
    /// The strut's least gap over the travel, task units, refined as the
    /// sample's placement's (its `min_clearance`): its capsule
    /// (`actuator_width`) to the links' capsules (`link_width`), the
    /// obstacles and the envelope (module docs, "Clearance"); negative
    /// where they overlap. Computed where the rest of `acceptable` holds
    /// (monotone, within the limits, on the base plate); NaN elsewhere.
    clearance: f32 = f32::NAN,
    /// Monotone and within the limits: the stroke ratio, the
    /// transmission angle, the link and size ratios, the longest link,
    /// the ground pivot on the base plate, and clear: the clearance
    /// above 0 and at least `min_gap`; judged as the sample's placement is
    /// (module docs, "The map and its placements"): where true, the
    /// placement is acceptable.
    acceptable: bool = false,
}

/// The designer's options of an actuator beyond [`DesignLimits`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ActuatorOptions {
    /// The link the actuator acts on (default the coupler).
    pub link: ActuatorLink,
    /// The largest acceptable stroke ratio, longest over shortest length
    /// (default 1.8; a cylinder's is below 2), at least 1.
    pub max_stroke_ratio: f64,
    /// How many input angles sample the travel, both ends included
    /// (default 256, from [`MIN_TRAVEL_SAMPLES`](Self::MIN_TRAVEL_SAMPLES)
    /// to [`MAX_TRAVEL_SAMPLES`](Self::MAX_TRAVEL_SAMPLES)).
    pub travel_samples: usize,
    /// The strut's diameter, task units (default 0: its center line): its
    /// capsule in the clearance (module docs, "Clearance"). One diameter for
    /// the whole strut: give the thicker part's (a gas spring's or a
    /// cylinder's body, not its rod). At least 0.
    pub actuator_width: f64,
    /// The least gap, task units, a placement must keep over its travel
    /// (default 0: clear by any margin): a placement whose
    /// [`min_clearance`](Actuator::min_clearance) is below it is not
    /// [`clear`](Actuator::clear) nor acceptable. At least 0.
    pub min_gap: f64,
}

impl Default for ActuatorOptions {
    fn default() -> Self {
        ActuatorOptions {
            link: ActuatorLink::Coupler,
            max_stroke_ratio: 1.8,
            travel_samples: 256,
            actuator_width: 0.0,
            min_gap: 0.0,
        }
    }
}

impl ActuatorOptions {
    /// The fewest travel samples.
    pub const MIN_TRAVEL_SAMPLES: usize = 8;
    /// The most travel samples.
    pub const MAX_TRAVEL_SAMPLES: usize = 1 << 14;

    /// Checks the options.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::OutsideRange`] for a stroke ratio limit below 1 or
    /// NaN (infinity: no limit), a negative or non-finite `actuator_width`
    /// or `min_gap` (or one past [`Constraints::MAX_COORDINATE`]);
    /// [`InvalidInput::CountOutOfRange`] for a travel sample count out of
    /// its range.
    pub fn validate(&self) -> Result<()> {
        let most = Constraints::MAX_COORDINATE;
        in_range("actuator_width", self.actuator_width, 0.0, most, "")?;
        in_range("min_gap", self.min_gap, 0.0, most, "")?;
        in_range(
            "max_stroke_ratio",
            self.max_stroke_ratio,
            1.0,
            f64::INFINITY,
            "",
        )?;
        count_in(
            "actuator travel_samples",
            self.travel_samples,
            Self::MIN_TRAVEL_SAMPLES,
            Self::MAX_TRAVEL_SAMPLES,
        )?;
        Ok(())
    }
}

/// What the context derives once: the travel sampled, `Q` and its velocity
/// at every sample and at the poses, the linkage's fixed figures.
#[derive(Debug, Clone, PartialEq)]
struct Travel {
    point: LinkPoint,
    /// The travel's assembly mode.
    mode: AssemblyMode,
    /// The linkage's joints at each sample.
    joints: Vec<Joints>,
    /// The sampled input angles, first pose to last.
    theta: Vec<f64>,
    /// `Q` at each sample.
    q: Vec<Point2<f64>>,
    /// `dQ/dtheta2` at each sample, times the travel's direction (the
    /// velocity per unit of travel from the first pose toward the last).
    v: Vec<Vector2<f64>>,
    /// `Q` at each pose.
    at_poses: PerPose<Point2<f64>>,
    /// The linkage's size.
    members: f64,
    /// Its shortest and longest link.
    link_min: f64,
    link_max: f64,
    /// `1 / span`.
    inv_span: f64,
    /// Lengths below this make no actuator.
    tiny: f64,
}

/// The sampled figures of one ground pivot (the map's sample, in `f64`).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Eval {
    valid: bool,
    monotone: bool,
    extends: bool,
    /// `min sin(mu)` over the samples, and the sample where it is.
    min_sin: f64,
    worst: usize,
    s_min: f64,
    s_max: f64,
    link_ratio: f64,
    size_ratio: f64,
    /// The sample intervals `(k, k + 1)` where `ds/dtheta2` changes sign
    /// (bracketed roots), their count.
    turns: usize,
}

/// The refined figures of one ground pivot and the verdict on them
/// ([`ActuatorContext::judge`]).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Verdict {
    /// The minimum transmission angle (0 when not monotone) and where.
    min_transmission: f64,
    worst_angle: f64,
    /// The strut's least gap and where.
    gap: f64,
    gap_angle: f64,
    /// The gap above 0 and at least `min_gap`.
    clear: bool,
    /// Within the limits and clear.
    acceptable: bool,
}

impl Travel {
    /// The sampled figures of the ground pivot `g` (module docs). Calls
    /// `root(k0, k1)` for each bracket: `ds/dtheta2` of opposite signs at
    /// samples `k0 < k1`, zero (or of either sign) between.
    #[inline]
    fn eval(&self, g: Point2<f64>, mut root: impl FnMut(usize, usize)) -> Eval {
        let (mut s_min, mut s_max) = (f64::INFINITY, 0.0f64);
        let (mut min_sin, mut worst) = (f64::INFINITY, 0);
        let mut last: Option<(usize, bool)> = None;
        let mut turns = 0;
        let mut first_sign = None;
        for (k, (q, v)) in self.q.iter().zip(&self.v).enumerate() {
            let d = q - g;
            let s = d.norm();
            s_min = s_min.min(s);
            s_max = s_max.max(s);
            let f = d.dot(v);
            let vn = v.norm();
            let sin = (f.abs() / (s * vn)).min(1.0);
            // NaN (zero speed or length) counts as a dead point.
            let sin = if sin.is_nan() { 0.0 } else { sin };
            if sin < min_sin {
                min_sin = sin;
                worst = k;
            }
            if f != 0.0 {
                let up = f > 0.0;
                first_sign.get_or_insert(up);
                if let Some((k0, was)) = last
                    && was != up
                {
                    turns += 1;
                    root(k0, k);
                }
                last = Some((k, up));
            }
        }
        let valid = s_min > self.tiny && s_max.is_finite();
        let lmax = self.link_max.max(s_max);
        let lmin = self.link_min.min(s_min);
        Eval {
            valid,
            monotone: valid && turns == 0 && first_sign.is_some(),
            extends: first_sign.unwrap_or(false),
            min_sin,
            worst,
            s_min,
            s_max,
            link_ratio: lmax / lmin,
            size_ratio: (self.members + s_max) * self.inv_span,
            turns,
        }
    }

    /// The figures `e` with the lengths exact: the shortest and the
    /// longest of the lengths at the poses, `pose_lengths`, and at the
    /// refined turning points, `turns` (none when monotone: then the
    /// first and the last pose's), and the ratios of them.
    fn exact(&self, e: &Eval, pose_lengths: &PerPose<f64>, turns: &[f64]) -> Eval {
        let (mut s_min, mut s_max) = (f64::INFINITY, 0.0f64);
        for &s in pose_lengths.iter().chain(turns) {
            s_min = s_min.min(s);
            s_max = s_max.max(s);
        }
        Eval {
            s_min,
            s_max,
            link_ratio: self.link_max.max(s_max) / self.link_min.min(s_min),
            size_ratio: (self.members + s_max) * self.inv_span,
            ..*e
        }
    }

    /// `ds/dtheta2 * s` at input angle `theta`: `<Q - G, dQ/dtheta2>`.
    fn rate(&self, g: Point2<f64>, theta: f64) -> Result<f64> {
        let (q, v) = self.point.at(theta)?;
        Ok((q - g).dot(&v))
    }

    /// `sin mu` at input angle `theta`.
    fn sin_mu(&self, g: Point2<f64>, theta: f64) -> Result<f64> {
        let (q, v) = self.point.at(theta)?;
        let d = q - g;
        let s = (d.dot(&v).abs() / (d.norm() * v.norm())).min(1.0);
        Ok(if s.is_nan() { 0.0 } else { s })
    }
}

/// What an actuator map is computed for: the linkage, the link and the
/// point `Q` the actuator acts on, the grid of candidate ground pivots
/// `G`, the limits, options and constraints; validated when made
/// ([`ActuatorContext::new`]), with the travel sampled once.
#[derive(Debug, Clone, PartialEq)]
pub struct ActuatorContext {
    grid: Grid,
    linkage: SynthesizedFourBar,
    point: Point2<f64>,
    map_options: MapOptions,
    options: ActuatorOptions,
    travel: Travel,
}

/// An actuator map: what it was computed for, and its columns.
#[derive(Debug, Clone, PartialEq)]
pub struct ActuatorMap {
    /// What the map was computed for.
    pub context: ActuatorContext,
    /// One value per grid sample of every figure.
    pub columns: ActuatorColumns,
}

/// One actuator placement and its figures (see the [module docs](self)):
/// from a map ([`ActuatorMap::best_placements`]) or a ground pivot
/// ([`ActuatorContext::placement`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Actuator {
    /// The linkage driven.
    pub linkage: SynthesizedFourBar,
    /// The link the actuator acts on.
    pub link: ActuatorLink,
    /// The ground pivot `G`.
    pub ground: Point2<f64>,
    /// The moving point `Q`, where it is at pose 1.
    pub point: Point2<f64>,
    /// The actuator's length at each pose (exact).
    pub pose_lengths: PerPose<f64>,
    /// Its length is monotone from the first pose to the last.
    pub monotone: bool,
    /// Its length grows from the first pose to the last.
    pub extends: bool,
    /// The input angles inside the travel where `ds/dtheta2 = 0` and
    /// changes sign (the dead points; empty when monotone), refined by
    /// bisection.
    pub turning_points: Vec<f64>,
    /// The shortest length over the travel (the closed actuator).
    pub min_length: f64,
    /// The longest length over the travel (the open actuator).
    pub max_length: f64,
    /// `max_length - min_length`.
    pub stroke: f64,
    /// `max_length / min_length`.
    pub stroke_ratio: f64,
    /// The minimum force transmission angle over the travel, radians
    /// (refined; 0 when not monotone).
    pub min_transmission: f64,
    /// The input angle where it is reached.
    pub worst_angle: f64,
    /// The longest over the shortest member (links and actuator).
    pub link_ratio: f64,
    /// The linkage and the open actuator over the task's span.
    pub size_ratio: f64,
    /// Whether it meets the limits of the context it came from, clear
    /// ([`clear`](Self::clear)) among them.
    pub acceptable: bool,
    /// The smallest gap over the travel between the strut (a capsule of
    /// [`ActuatorOptions::actuator_width`]) and the links (capsules of
    /// [`Constraints::link_width`]) that do not carry its moving point, the
    /// obstacles and the envelope's boundary; negative where they overlap
    /// (module docs, "Clearance").
    pub min_clearance: f64,
    /// The input angle where it is.
    pub clearance_angle: f64,
    /// The strut stays clear over the travel: `min_clearance` above 0 and
    /// at least [`ActuatorOptions::min_gap`].
    pub clear: bool,
    /// Its sample `(j, i)` in a map, if it came from one.
    pub index: Option<(usize, usize)>,
    /// Its signed distance to the nearest non-monotone sample (grid units),
    /// if it came from a map; NaN otherwise.
    pub margin: f64,
    /// Its score by the ranking that chose it (NaN otherwise).
    pub score: f64,
    /// The ranking that chose it.
    pub ranked_by: Option<RankBy>,
    /// The moving point.
    link_point: LinkPoint,
}

impl Actuator {
    /// The moving point `Q` and the actuator's length at input angle
    /// `theta2` (for drawing and checking the motion).
    ///
    /// # Errors
    ///
    /// As [`FourBar::solve`](crate::FourBar::solve).
    pub fn at(&self, theta2: f64) -> Result<(Point2<f64>, f64)> {
        let (q, _) = self.link_point.at(theta2)?;
        Ok((q, (q - self.ground).norm()))
    }

    /// The moving point, its velocity per unit input angle.
    pub fn link_point(&self) -> &LinkPoint {
        &self.link_point
    }
}

flagged_rank_columns! {
    /// The columns a ranking of placements reads.
    ActuatorRankColumns, ActuatorMap, monotone;
    Actuator, "the best placements"
}

impl ActuatorContext {
    /// The most samples of an actuator map's grid (`2^20`, 1024 x 1024).
    pub const MAX_GRID_SAMPLES: usize = 1 << 20;

    /// The context of an actuator map for `linkage` with the actuator on
    /// `options.link` at the point `point` (where it is at pose 1), the
    /// candidate ground pivots on `grid`, validated (see the [module
    /// docs](self)).
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for invalid actuator options, a
    /// non-finite point, or a grid of more than
    /// [`MAX_GRID_SAMPLES`](Self::MAX_GRID_SAMPLES) samples;
    /// [`DriveError::NoTravel`] for a linkage that does not carry the
    /// coupler through its poses in order in one mode;
    /// [`DegenerateError::ZeroLengthLink`] for a point on the crank's or the
    /// rocker's fixed pivot; [`Error::OutOfMemory`](crate::Error::OutOfMemory).
    pub fn new(
        linkage: &SynthesizedFourBar,
        point: Point2<f64>,
        grid: &Grid,
        map_options: &MapOptions,
        options: &ActuatorOptions,
    ) -> Result<Self> {
        options.validate()?;
        if grid.len() > Self::MAX_GRID_SAMPLES {
            return Err(InvalidInput::GridSize {
                nx: grid.nx(),
                ny: grid.ny(),
                max: Self::MAX_GRID_SAMPLES,
            }
            .into());
        }
        finite_point(["actuator point x", "actuator point y"], point)?;
        let travel = travel_of(linkage, point, options)?;
        Ok(ActuatorContext {
            grid: *grid,
            linkage: *linkage,
            point,
            map_options: map_options.clone(),
            options: *options,
            travel,
        })
    }

    /// The grid of candidate ground pivots.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }
    /// The linkage driven.
    pub fn linkage(&self) -> &SynthesizedFourBar {
        &self.linkage
    }
    /// The moving point `Q` at pose 1.
    pub fn point(&self) -> Point2<f64> {
        self.point
    }
    /// Where `Q` is at each pose.
    pub fn point_at_poses(&self) -> PerPose<Point2<f64>> {
        self.travel.at_poses
    }
    /// The limits behind `acceptable`.
    pub fn limits(&self) -> &DesignLimits {
        self.map_options.limits()
    }
    /// The options.
    pub fn options(&self) -> &ActuatorOptions {
        &self.options
    }
    /// The constraints: the base plate behind `acceptable`, the obstacles
    /// and envelope behind a placement's clearance.
    pub fn constraints(&self) -> &Constraints {
        self.map_options.constraints()
    }
    /// The limits and the constraints, checked.
    pub fn map_options(&self) -> &MapOptions {
        &self.map_options
    }
    /// The sampled input angles of the travel, first pose to last.
    pub fn travel_angles(&self) -> &[f64] {
        &self.travel.theta
    }
    /// The candidate ground pivot of sample `k` (row-major).
    pub fn ground(&self, k: usize) -> Point2<f64> {
        self.grid.point(k % self.grid.nx(), k / self.grid.nx())
    }

    /// The actuator map over the grid, following `control`.
    ///
    /// # Errors
    ///
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory);
    /// [`Error::Cancelled`](crate::Error::Cancelled).
    pub fn map(&self, control: &Control<'_>) -> Result<ActuatorMap> {
        let mut columns = ActuatorColumns::for_overwrite(self.grid.len())?;
        self.map_into(columns.as_out(), control)?;
        Ok(ActuatorMap {
            context: self.clone(),
            columns,
        })
    }

    /// [`map`](Self::map) into columns the caller owns (NumPy arrays).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::LengthMismatch`] when a column does not have
    /// `grid.len()` values; as [`map`](Self::map).
    pub fn map_into(&self, mut out: ActuatorColumnsOut<'_>, control: &Control<'_>) -> Result<()> {
        out.check_len(self.grid.len())?;
        let prepared = self.map_options.prepared();
        let nx = self.grid.nx();
        let mut samples = try_vec("an actuator map", self.grid.len(), ActuatorSample::INVALID)?;
        for_rows(nx, &mut samples, control, |j, row| {
            let y = self.grid.y(j);
            for (i, s) in row.iter_mut().enumerate() {
                *s = self.sample(prepared, Point2::new(self.grid.x(i), y));
            }
        })?;
        for (i, s) in samples.iter().enumerate() {
            out.set(i, *s);
        }
        Ok(())
    }

    /// Whether a least gap `gap` is clear: above 0 and at least the
    /// options' `min_gap`.
    fn clear(&self, gap: f64) -> bool {
        gap > 0.0 && gap >= self.options.min_gap
    }

    /// Whether sampled figures meet the limits (the clearance apart).
    fn meets(&self, prepared: &Prepared, g: Point2<f64>, e: &Eval, mu: f64) -> bool {
        let l = self.limits();
        e.monotone
            && e.s_max / e.s_min <= self.options.max_stroke_ratio
            && mu >= l.min_transmission
            && e.link_ratio <= l.max_link_ratio
            && e.size_ratio <= l.max_size_ratio
            && e.s_max.max(self.travel.link_max) <= l.max_link_length
            && prepared.pivot_ok(g)
    }

    /// One sample of the map.
    fn sample(&self, prepared: &Prepared, g: Point2<f64>) -> ActuatorSample {
        let e = self.travel.eval(g, |_, _| {});
        if !e.valid {
            return ActuatorSample::INVALID;
        }
        let mu = e.min_sin.asin();
        // Where the sampled figures meet the limits, the verdict is the
        // placement's own: its refined transmission angle and gap are
        // never above the sampled ones, so a sample judged on those could
        // be acceptable while its placement is not (a gap just below
        // `min_gap`). Elsewhere the gap is not computed (NaN): the refined
        // figures would not make the sample acceptable.
        let (gap, acceptable) = if self.meets(prepared, g, &e, mu) {
            // Monotone (`meets`): the lengths are the poses'.
            let t = &self.travel;
            let exact = t.exact(&e, &t.at_poses.map(|q| (q - g).norm()), &[]);
            match self.judge(prepared, g, &exact, None) {
                Ok(v) => (v.gap, v.acceptable),
                // The placement fails too (the ranking skips it).
                Err(_) => (f64::NAN, false),
            }
        } else {
            (f64::NAN, false)
        };
        ActuatorSample {
            valid: true,
            monotone: e.monotone,
            extends: e.extends,
            min_transmission_rad: mu as f32,
            stroke_ratio: (e.s_max / e.s_min) as f32,
            stroke: (e.s_max - e.s_min) as f32,
            closed_length: e.s_min as f32,
            link_ratio: e.link_ratio as f32,
            size_ratio: e.size_ratio as f32,
            clearance: gap as f32,
            acceptable,
        }
    }

    /// The refined figures of the ground pivot `g` and the verdict on them,
    /// from its sampled figures `e` and its first refined turning point
    /// (`None` when monotone): shared by [`placement`](Self::placement)
    /// and the map's `clearance` and `acceptable` columns, so that an
    /// acceptable sample's placement is acceptable.
    fn judge(
        &self,
        prepared: &Prepared,
        g: Point2<f64>,
        e: &Eval,
        turning: Option<f64>,
    ) -> Result<Verdict> {
        let t = &self.travel;
        let (min_transmission, worst_angle) = if let Some(th) = turning {
            (0.0, th)
        } else {
            let k = e.worst;
            let a = t.theta[k.saturating_sub(1)];
            let b = t.theta[(k + 1).min(t.theta.len() - 1)];
            let (th, sin) = golden_min(|x| t.sin_mu(g, x), a, b, e.min_sin, t.theta[k])?;
            (sin.asin(), th)
        };
        let (gap, gap_angle) = self.clearance(prepared, g)?;
        let clear = self.clear(gap);
        let acceptable = clear && self.meets(prepared, g, e, min_transmission);
        Ok(Verdict {
            min_transmission,
            worst_angle,
            gap,
            gap_angle,
            clear,
            acceptable,
        })
    }

    /// The placement with its ground pivot at `g`, its turning points and
    /// minimum transmission angle refined (module docs).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a non-finite point;
    /// [`DegenerateError::ZeroLengthLink`] where `g` is on the moving
    /// point's path (the map's `valid` is false there).
    pub fn placement(&self, g: Point2<f64>) -> Result<Actuator> {
        finite_point(["actuator ground x", "actuator ground y"], g)?;
        let t = &self.travel;
        let mut brackets = Vec::new();
        let e = t.eval(g, |k0, k1| brackets.push((k0, k1)));
        if !e.valid {
            return Err(DegenerateError::ZeroLengthLink {
                what: "actuator (its ground pivot is on the moving point's path)",
                x: g.x,
                y: g.y,
            }
            .into());
        }
        let mut turning = Vec::with_capacity(brackets.len());
        let mut turn_lengths = Vec::with_capacity(brackets.len());
        let pose_lengths = t.at_poses.map(|q| (q - g).norm());
        for (k0, k1) in brackets {
            let th = bisect(|x| t.rate(g, x), t.theta[k0], t.theta[k1])?;
            let (q, _) = t.point.at(th)?;
            turn_lengths.push((q - g).norm());
            turning.push(th);
        }
        let exact = t.exact(&e, &pose_lengths, &turn_lengths);
        let (s_min, s_max) = (exact.s_min, exact.s_max);
        let v = self.judge(
            self.map_options.prepared(),
            g,
            &exact,
            turning.first().copied(),
        )?;
        Ok(Actuator {
            linkage: self.linkage,
            link: self.options.link,
            ground: g,
            point: self.point,
            pose_lengths,
            monotone: e.monotone,
            extends: e.extends,
            turning_points: turning,
            min_length: s_min,
            max_length: s_max,
            stroke: s_max - s_min,
            stroke_ratio: s_max / s_min,
            min_transmission: v.min_transmission,
            worst_angle: v.worst_angle,
            link_ratio: exact.link_ratio,
            size_ratio: exact.size_ratio,
            acceptable: v.acceptable,
            min_clearance: v.gap,
            clearance_angle: v.gap_angle,
            clear: v.clear,
            index: None,
            margin: f64::NAN,
            score: f64::NAN,
            ranked_by: None,
            link_point: t.point,
        })
    }

    /// The strut's smallest gap over the travel with its ground pivot at
    /// `g` and the input angle where it is (module docs, "Clearance").
    fn clearance(&self, prepared: &Prepared, g: Point2<f64>) -> Result<(f64, f64)> {
        let t = &self.travel;
        let check = self.strut_check(prepared, g);
        let (mut worst, mut least) = (0, f64::INFINITY);
        for (k, (j, &q)) in t.joints.iter().zip(&t.q).enumerate() {
            let gap = check.gap_at(j, q);
            if gap < least {
                (worst, least) = (k, gap);
            }
        }
        let a = t.theta[worst.saturating_sub(1)];
        let b = t.theta[(worst + 1).min(t.theta.len() - 1)];
        let gap_at = |x: f64| check.gap(x, t.point.at(x)?.0);
        let (th, gap) = golden_min(gap_at, a, b, least, t.theta[worst])?;
        Ok((gap, th))
    }

    /// What the strut's gap with its ground pivot at `g` is measured
    /// against.
    fn strut_check<'a>(&'a self, prepared: &'a Prepared, g: Point2<f64>) -> StrutCheck<'a> {
        StrutCheck {
            fourbar: &self.linkage.fourbar,
            mode: self.travel.mode,
            link: self.options.link,
            prepared,
            ground: g,
            strut_radius: 0.5 * self.options.actuator_width,
            tiny: self.travel.tiny,
        }
    }

    /// The placement of sample `k`, with its index.
    ///
    /// # Errors
    ///
    /// As [`placement`](Self::placement).
    pub fn placement_at(&self, k: usize) -> Result<Actuator> {
        let mut a = self.placement(self.ground(k))?;
        a.index = Some((k / self.grid.nx(), k % self.grid.nx()));
        Ok(a)
    }

    best! {
        /// The [`Ranking::k`](crate::Ranking::k) best placements of a map's
        /// columns by `ranking` (the rankings of [`RankBy`] over the acceptable
        /// samples, the link ratio that of the members with the actuator;
        /// [`RankBy::Margin`] orders the monotone samples by their distance to
        /// the nearest non-monotone one). Candidates closer than the ranking's
        /// separation to a better one are skipped (default: 2% of the
        /// viewport's diagonal).
        ///
        /// # Errors
        ///
        /// [`InvalidInput::LengthMismatch`] for columns of another length than
        /// the grid; [`Error::OutOfMemory`](crate::Error::OutOfMemory).
        best_placements(ActuatorRankColumns<'_>) -> Actuator, flagged placement_at
    }
}

impl ActuatorMap {
    best! {
        /// The best placements by `ranking` (see
        /// [`ActuatorContext::best_placements`]).
        ///
        /// # Errors
        ///
        /// As [`ActuatorContext::best_placements`].
        best_placements -> Actuator
    }
}

/// The travel of `linkage` sampled for the point `point` of `options.link`.
fn travel_of(
    linkage: &SynthesizedFourBar,
    point: Point2<f64>,
    options: &ActuatorOptions,
) -> Result<Travel> {
    let mode = match linkage.modes().first() {
        Some(Some(m)) if linkage.figures.feasible() => *m,
        _ => return Err(DriveError::NoTravel.into()),
    };
    let stops = linkage.travel_stops().ok_or(DriveError::NoTravel)?;
    let lp = LinkPoint::new(&linkage.fourbar, mode, options.link, point, stops[0])?;
    let n = options.travel_samples;
    let theta = linkage.travel_angles(n)?;
    let mut q = try_vec("an actuator's travel", n, Point2::origin())?;
    let mut v = try_vec("an actuator's travel", n, Vector2::zeros())?;
    let o = Point2::origin();
    let mut joints = try_vec(
        "an actuator's travel",
        n,
        Joints {
            input_pivot: o,
            crank_joint: o,
            rocker_joint: o,
            output_pivot: o,
        },
    )?;
    // The velocity per unit of travel, first pose toward the last: along
    // a clockwise travel the input angle decreases.
    let (_, span) = linkage.travel().ok_or(DriveError::NoTravel)?;
    let forward = span.signum();
    for (k, &th) in theta.iter().enumerate() {
        let (qk, vk) = lp.at(th)?;
        (q[k], v[k]) = (qk, vk * forward);
        joints[k] = linkage.fourbar.joints_at(th, mode)?;
    }
    let mut at = [Point2::origin(); crate::geom::MAX_POSES];
    for (k, &th) in stops.iter().enumerate() {
        at[k] = lp.at(th)?.0;
    }
    let lengths = linkage.fourbar.lengths();
    let span = crate::design::drive::pose_span(linkage);
    let link_max = lengths.iter().copied().fold(0.0, f64::max);
    Ok(Travel {
        point: lp,
        mode,
        joints,
        theta,
        q,
        v,
        at_poses: PerPose::from_slice(&at[..stops.len()]),
        members: linkage.size(),
        link_min: lengths.iter().copied().fold(f64::INFINITY, f64::min),
        link_max,
        inv_span: 1.0 / span,
        tiny: 1e-9 * link_max,
    })
}

/// The root of `f` between `a` and `b` (where its signs differ, or one is
/// zero), by bisection to rounding.
fn bisect(f: impl Fn(f64) -> Result<f64>, mut a: f64, mut b: f64) -> Result<f64> {
    let fa = f(a)?;
    if fa == 0.0 {
        return Ok(a);
    }
    let up = fa > 0.0;
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if m == a || m == b {
            break;
        }
        let fm = f(m)?;
        if fm == 0.0 {
            return Ok(m);
        }
        if (fm > 0.0) == up {
            a = m;
        } else {
            b = m;
        }
    }
    Ok(0.5 * (a + b))
}

/// The smallest value of `f` on `[a, b]` by golden section, starting from
/// the sampled smallest `(x0, f0)` (kept if the search finds nothing
/// smaller): `(x, f(x))`.
fn golden_min(
    f: impl Fn(f64) -> Result<f64>,
    a: f64,
    b: f64,
    f0: f64,
    x0: f64,
) -> Result<(f64, f64)> {
    const R: f64 = 0.618_033_988_749_894_9;
    let (mut lo, mut hi) = (a.min(b), a.max(b));
    let mut best = (x0, f0);
    let mut c = hi - R * (hi - lo);
    let mut d = lo + R * (hi - lo);
    let (mut fc, mut fd) = (f(c)?, f(d)?);
    for _ in 0..80 {
        if fc < best.1 {
            best = (c, fc);
        }
        if fd < best.1 {
            best = (d, fd);
        }
        if fc < fd {
            hi = d;
            d = c;
            fd = fc;
            c = hi - R * (hi - lo);
            fc = f(c)?;
        } else {
            lo = c;
            c = d;
            fc = fd;
            d = lo + R * (hi - lo);
            fd = f(d)?;
        }
        if hi - lo <= 1e-15 * (1.0 + hi.abs()) {
            break;
        }
    }
    Ok(best)
}
