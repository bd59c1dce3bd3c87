//! From poses to the best buildable linkage in one call: [`Task::design`].
//!
//! A designer brings poses, the space in the machine and the limits a
//! linkage must meet; the search answers with the best linkages, ranked by
//! one [`RankBy`] score, each branch-free, carrying the coupler through
//! the poses in order on one circuit, meeting the [`DesignLimits`] and
//! fitting the [`Space`]. Every answer is judged on the exact linkage
//! ([`Task::four_bar`]: the assembly modes at the poses, the minimum
//! transmission angle over the whole travel, the clearance and the
//! envelope over the whole travel), not on a grid sample.
//!
//! # How
//!
//! * **Three poses**: both fixed pivots are free. A coarse pass over pivot
//!   pairs, the [pivot-pair atlas](crate::design::atlas) over the search
//!   box ([`Space::search_box`]: a `coarse_driven` grid of driven pivots
//!   `C0`, each with its best driving pivot `A0` by the ranking's score on
//!   a `coarse_driving` grid), gives the starts: the cells by score, best
//!   first, at least the separation apart. Each start is then **refined
//!   continuously**: both pivots move together, `(A0, C0)` in the plane,
//!   by Nelder–Mead (the steps of the `argmin` crate's, without its
//!   per-step allocations, its parameters adapted to the dimension) on
//!   the exact score. A linkage that misses a limit costs its
//!   score plus a penalty for its shortfall (so the simplex can slide along
//!   a limit's boundary, where the best linkages usually are), one without
//!   a feasible motion a barrier, and only acceptable linkages are kept: the
//!   refined linkage is branch-free, in order, inside the limits and the
//!   space, and not bounded by the grid. The refinement restarts a few times from its
//!   best point with a fresh simplex (the usual cure for a simplex that
//!   collapsed early along a constraint's boundary).
//! * **Four poses**: the [pair map](crate::design::pairs) with
//!   `coarse_pairs` samples along each axis, under the same limits and
//!   space, gives the starts; each is refined along the two curve
//!   parameters (the crank rotations of both dyads,
//!   [`FourPositions::dyad_at_parameter`]).
//! * **Five poses**: every ordered pair of Burmester points, judged the
//!   same way (there is nothing to refine).
//!
//! The answers are **distinct**: a design whose fixed pivots are both
//! within the minimum separation ([`DesignOptions::min_separation`],
//! default [`DesignOptions::DEFAULT_SEPARATION`] task sizes) of a better
//! one's is dropped, so the list offers different linkages, not
//! neighbours of one. Scores within
//! [`tolerance::RANK_TIE`] tie and go to the
//! smaller linkage.
//!
//! # With a motor
//!
//! With [`DesignOptions::motor`] every design returned can be turned by a
//! motor. A design whose input turns fully
//! ([`LinkageFigures::input_full`](crate::LinkageFigures::input_full)) is
//! driven at its input directly ([`Design::drive`] `None`); one whose input
//! swings gets the best drive of [`best_drive`](crate::design::best_drive)
//! ([`Design::drive`]): a crank-rocker added to its input link (the Watt II
//! six-bar), under the same limits (their input requirement aside: the
//! drive's crank always turns fully; the transmission angle for both loops
//! over a full crank turn, the link ratio, the size ratio and the longest
//! link for the whole six-bar), the motor's [`DriveOptions`] (swing margin,
//! time ratio), the same ranking and the space's constraints without the
//! envelope: the drive dyad is checked against the obstacles and the base
//! plate (the pivot region) over the whole crank turn, while the envelope
//! applies to the four-bar over its travel, as without a motor. A design
//! for which no drive is acceptable is passed over
//! ([`DesignReport::undriven`] counts them) and the next distinct
//! candidate is taken, so up to `top` designs are still returned; the
//! drives are searched lazily, in rank order, only for candidates that
//! pass the separation test. The limits' input requirement still filters
//! the four-bars: with [`InputRequirement::Crank`] no drive is ever
//! needed, with [`InputRequirement::Rocker`] every design gets one.
//!
//! # With a linear actuator
//!
//! With [`DesignOptions::actuator`] every design returned is driven by a
//! linear actuator (a cylinder, a gas strut) between a ground pivot on the
//! space's pivot region and a point of one of its moving links
//! ([`ActuatorSearch`]; the [actuator](crate::design::actuator) module).
//! For each candidate, in rank order and only once it passes the
//! separation test, the actuator's placement map over the pivot region's
//! box (or, with pivots anywhere, the linkage's box widened by its size)
//! is computed for the given moving point or for each of a few points of
//! the link ([`ActuatorSearch::points`]), and the best placement by the
//! design's ranking that is monotone, within the limits (the actuator's
//! stroke ratio, its transmission angle, the link and size ratios with
//! the open actuator, the size ratio's bound
//! [`ActuatorSearch::max_size_ratio`], by default the limits') and
//! **clear** over the travel (its capsule,
//! [`ActuatorOptions::actuator_width`](crate::design::ActuatorOptions::actuator_width)
//! across, at least
//! [`min_gap`](crate::design::ActuatorOptions::min_gap) off the links'
//! capsules that do not carry its point, the obstacles and the envelope,
//! [`Actuator::clear`]) is attached ([`Design::actuator`]). A candidate
//! with no such placement is passed over ([`DesignReport::unplaced`]).
//!
//! # A driven slider
//!
//! With [`DesignOptions::driven`] [`DrivenKind::Slider`] the designs are
//! slider-cranks ([`DesignedLinkage::SliderCrank`]): a driving crank of the
//! task driving a slider dyad of the task (its pin on a straight guide
//! fixed to the ground, [`Task::slider_dyads`]), built and judged exactly
//! by [`Task::slider_crank`] (branch: one assembly mode at every pose, no
//! toggle between; order; the transmission angle between the coupler and
//! the guide's normal over the travel; the link ratio of crank and
//! coupler; the size with the stroke; `A0` in the pivot region, the guide
//! needing no pivot). The limits read as for the slider solution map
//! (the `map_slider` module of `design`): the links
//! [`DesignLimits::max_link_length`] bounds are the crank, the coupler and
//! the offset, and [`DesignLimits::min_grashof_margin`] bounds the
//! distance from the crank's change points
//! ([`SliderCrank::rotatability_margin`](crate::SliderCrank::rotatability_margin)).
//!
//! * **Three poses**: `A0` free in the plane, the slider's pin free on the
//!   slider circle ([`Task::slider_circle`]): a coarse pass over
//!   `coarse_driving` pivots along the search box's longer side times
//!   `coarse_driven` pins along the circle (at its parameter, an angle on
//!   a circle or the stereographic parameter on a line), each start
//!   refined over `(A0, t)` by the same Nelder–Mead
//!   ([`SearchPoint::SliderCircle`]).
//! * **Four poses**: `coarse_pairs` dyads along the center-point curve
//!   times the finitely many slider points, each start refined along the
//!   curve parameter ([`SearchPoint::SliderPoint`]).
//! * **Five poses**: every Burmester point times every slider Burmester
//!   point. Four or five poses without a slider point are refused
//!   ([`InvalidInput::NoSliderPoint`], saying why).
//!
//! The separation is measured between crank pivots and between the
//! slider pins at pose 1 ([`DesignedLinkage::driven_point`]). The space's
//! obstacles and envelope are checked over the slider-crank's travel as
//! a slider solution map checks them (the crank and the coupler, capsules
//! of the links' width, against the obstacles; the crank and the coupler
//! triangle inside the envelope; the block is the pin at the coupler's
//! end, its path along the guide checked with the coupler). A motor and a
//! linear actuator are refused with a slider
//! ([`InvalidInput::DrivenKind`]): they are searched on a four-bar.
//!
//! # When nothing fits
//!
//! The report has no designs, never an error and never a silent
//! relaxation of a limit: it says which limit rejected the most candidates
//! of a census (every candidate of a coarse grid judged against every
//! limit, [`DesignReport::rejections`]) and lists the nearest misses: the
//! candidates whose motion is feasible (branch-free, in order on one
//! circuit) that miss the limits by the least ([`NearMiss::shortfall`]).

use core::cell::{Cell, RefCell};
use core::sync::atomic::{AtomicUsize, Ordering};

use nalgebra::Point2;
use rayon::prelude::*;

use crate::design::actuator::Actuator;
use crate::design::atlas::check_scored;
use crate::design::constraints::{Checks, Prepared};
use crate::design::drive::{Drive, DriveOptions};
use crate::design::rank::tie_order;
use crate::design::space::{PivotRegion, Space};
use crate::design::{AtlasCell, DesignLimits, InputRequirement, MapOptions, RankBy};
use crate::engine::Control;
use crate::error::{Error, InvalidInput, Result, count_in, in_range};
use crate::geom::{Grid, Viewport};
use crate::linkage::{Direction, LinkageFigures};
use crate::synthesis::{Dyad, DyadKind, Task};
use crate::synthesis::{FivePositions, FourPositions};
use crate::tolerance;

mod linkage;
mod motor;
mod simplex;
mod slider;
mod strut;

pub use linkage::{DesignedLinkage, DrivenKind};
pub use strut::ActuatorSearch;

#[cfg(test)]
mod judge_equal;

use simplex::{End, MAX_DIM, Point};

/// What to search for and how finely (see the [module docs](self)).
#[derive(Debug, Clone, PartialEq)]
pub struct DesignOptions {
    /// The limits every design meets.
    pub limits: DesignLimits,
    /// The space every design fits.
    pub space: Space,
    /// The score the designs are ranked by: [`RankBy::Balanced`]
    /// (default), [`RankBy::Transmission`] or [`RankBy::Compact`].
    pub rank_by: RankBy,
    /// How many designs to return, at most (1 to
    /// [`DesignOptions::MAX_TOP`], default 5).
    pub top: usize,
    /// The least distance, in the task's units, by which a design's fixed
    /// pivots (one of them at least) differ from a better design's;
    /// `None`: [`DesignOptions::DEFAULT_SEPARATION`] task sizes
    /// ([`Task::span`]).
    pub min_separation: Option<f64>,
    /// Three poses: driven pivots along the longer side of the coarse
    /// pass's box (2 to [`DesignOptions::MAX_COARSE_DRIVEN`], default 12).
    pub coarse_driven: usize,
    /// Three poses: driving pivots along the longer side of the coarse
    /// pass's box, for each driven pivot (2 to
    /// [`DesignOptions::MAX_COARSE_DRIVING`], default 48).
    pub coarse_driving: usize,
    /// Four poses: samples along each axis of the coarse pair map (2 to
    /// [`DesignOptions::MAX_COARSE_PAIRS`], default 120).
    pub coarse_pairs: usize,
    /// How many coarse starts are refined, at most (1 to
    /// [`DesignOptions::MAX_STARTS`], default 48).
    pub starts: usize,
    /// Nelder–Mead iterations per refinement, all rounds together (1 to
    /// [`DesignOptions::MAX_ITERATIONS`], default 3000).
    pub max_iterations: usize,
    /// With `Some`, every design can be turned by a motor: one whose input
    /// swings gets the best drive under these options ([`Design::drive`];
    /// module docs, "With a motor"); default `None`: the four-bars alone.
    pub motor: Option<DriveOptions>,
    /// With `Some`, every design is driven by a linear actuator placed
    /// with it ([`Design::actuator`]; module docs, "With a linear
    /// actuator"); default `None`. Not with a motor.
    pub actuator: Option<ActuatorSearch>,
    /// The driven dyad's kind: [`DrivenKind::Revolute`] (default) designs
    /// four-bars, [`DrivenKind::Slider`] slider-cranks (module docs, "A
    /// driven slider"; not with a motor or an actuator).
    pub driven: DrivenKind,
}

impl Default for DesignOptions {
    fn default() -> Self {
        DesignOptions {
            limits: DesignLimits::default(),
            space: Space::default(),
            rank_by: RankBy::Balanced,
            top: 5,
            min_separation: None,
            coarse_driven: Self::DEFAULT_COARSE_DRIVEN,
            coarse_driving: Self::DEFAULT_COARSE_DRIVING,
            coarse_pairs: Self::DEFAULT_COARSE_PAIRS,
            starts: 48,
            max_iterations: 3000,
            motor: None,
            actuator: None,
            driven: DrivenKind::Revolute,
        }
    }
}

impl DesignOptions {
    /// The most designs one search returns.
    pub const MAX_TOP: usize = 100;
    /// The default coarse driven pivots along the box's longer side.
    pub const DEFAULT_COARSE_DRIVEN: usize = 12;
    /// The most coarse driven pivots along the box's longer side.
    pub const MAX_COARSE_DRIVEN: usize = 64;
    /// The default coarse driving pivots along the box's longer side.
    pub const DEFAULT_COARSE_DRIVING: usize = 48;
    /// The most coarse driving pivots along the box's longer side.
    pub const MAX_COARSE_DRIVING: usize = 256;
    /// The default samples per axis of the four-pose coarse pair map.
    pub const DEFAULT_COARSE_PAIRS: usize = 120;
    /// The most samples per axis of the four-pose coarse pair map.
    pub const MAX_COARSE_PAIRS: usize = 2000;
    /// The most refined starts.
    pub const MAX_STARTS: usize = 1000;
    /// The most Nelder–Mead iterations per refinement.
    pub const MAX_ITERATIONS: usize = 20_000;
    /// The default minimum separation of two designs, in task sizes.
    pub const DEFAULT_SEPARATION: f64 = 0.2;

    /// Checks the options (the space and limits against `task` too).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::CountOutOfRange`] naming the count out of range;
    /// [`InvalidInput::OutsideRange`] for a negative or non-finite
    /// separation; [`InvalidInput::UnknownName`] for a ranking without a
    /// score; as [`Space::validate`]; as [`DriveOptions::validate`] for the
    /// motor's options.
    pub fn validate(&self, task: &Task) -> Result<()> {
        count_in("top", self.top, 1, Self::MAX_TOP)?;
        count_in(
            "coarse_driven",
            self.coarse_driven,
            2,
            Self::MAX_COARSE_DRIVEN,
        )?;
        count_in(
            "coarse_driving",
            self.coarse_driving,
            2,
            Self::MAX_COARSE_DRIVING,
        )?;
        count_in("coarse_pairs", self.coarse_pairs, 2, Self::MAX_COARSE_PAIRS)?;
        count_in("starts", self.starts, 1, Self::MAX_STARTS)?;
        count_in(
            "max_iterations",
            self.max_iterations,
            1,
            Self::MAX_ITERATIONS,
        )?;
        if let Some(s) = self.min_separation {
            in_range("min_separation", s, 0.0, f64::MAX, "")?;
        }
        check_scored(self.rank_by, "design ranking")?;
        if let Some(motor) = &self.motor {
            motor.validate()?;
        }
        if let Some(actuator) = &self.actuator {
            let input = if self.motor.is_some() { "both" } else { "" };
            in_set(
                "design input",
                input,
                "a motor or a linear actuator, not both",
            )?;
            actuator.validate()?;
        }
        self.space.validate(task, &self.limits)?;
        slider::check_options(self)
    }

    /// The separation in the task's units.
    fn separation(&self, task: &Task) -> f64 {
        self.min_separation
            .unwrap_or(Self::DEFAULT_SEPARATION * task.span())
    }
}

/// Refuses `found` for `what` unless it is empty (`expected` says what
/// may be given).
fn in_set(what: &'static str, found: &str, expected: &'static str) -> Result<()> {
    if found.is_empty() {
        return Ok(());
    }
    let found = found.to_owned();
    Err(InvalidInput::UnknownName {
        what,
        expected,
        found,
    }
    .into())
}

/// Where the search found a design, or started from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SearchPoint {
    /// Three poses: the fixed pivots.
    Pivots {
        /// The driving pivot `A0`.
        driving: Point2<f64>,
        /// The driven pivot `C0`.
        driven: Point2<f64>,
    },
    /// Four poses: the curve parameters of both dyads
    /// ([`FourPositions::dyad_at_parameter`]).
    Parameters {
        /// The driving dyad's.
        driving: f64,
        /// The driven dyad's.
        driven: f64,
    },
    /// Five poses: the indices of the Burmester points
    /// ([`FivePositions::burmester_points`]).
    Burmester {
        /// The driving dyad's.
        driving: usize,
        /// The driven dyad's.
        driven: usize,
    },
    /// Three poses with a driven slider: the crank pivot and the slider
    /// circle's parameter of the slider's pin (an angle on a circle, or
    /// `t` of `q + 2 s tan(t) u` on a line; [`Task::slider_circle`]).
    SliderCircle {
        /// The driving pivot `A0`.
        driving: Point2<f64>,
        /// The slider circle's parameter of the pin.
        slider: f64,
    },
    /// Four or five poses with a driven slider: the driving dyad's curve
    /// parameter (four poses, [`FourPositions::dyad_at_parameter`]) or
    /// Burmester point index (five poses, as a number), and the index of
    /// the slider dyad ([`Task::slider_dyads`]).
    SliderPoint {
        /// The driving dyad's parameter or index.
        driving: f64,
        /// The slider dyad's index.
        slider: usize,
    },
}

impl SearchPoint {
    /// The coordinates a refinement moves, the indices staying: both
    /// pivots, both curve parameters, the crank pivot and the pin's
    /// parameter, or the driving dyad's parameter; `None` for the
    /// Burmester points (not refined).
    fn coordinates(&self) -> Option<Vec<f64>> {
        match *self {
            SearchPoint::Pivots { driving, driven } => {
                Some(vec![driving.x, driving.y, driven.x, driven.y])
            }
            SearchPoint::Parameters { driving, driven } => Some(vec![driving, driven]),
            SearchPoint::SliderCircle { driving, slider } => {
                Some(vec![driving.x, driving.y, slider])
            }
            SearchPoint::SliderPoint { driving, .. } => Some(vec![driving]),
            SearchPoint::Burmester { .. } => None,
        }
    }

    /// The point of the same kind (and indices) at the coordinates `x`, as
    /// [`coordinates`](Self::coordinates) gives them.
    fn moved_to(&self, x: &[f64]) -> SearchPoint {
        match *self {
            SearchPoint::Pivots { .. } => SearchPoint::Pivots {
                driving: Point2::new(x[0], x[1]),
                driven: Point2::new(x[2], x[3]),
            },
            SearchPoint::Parameters { .. } => SearchPoint::Parameters {
                driving: x[0],
                driven: x[1],
            },
            SearchPoint::SliderCircle { .. } => SearchPoint::SliderCircle {
                driving: Point2::new(x[0], x[1]),
                slider: x[2],
            },
            SearchPoint::SliderPoint { slider, .. } => SearchPoint::SliderPoint {
                driving: x[0],
                slider,
            },
            SearchPoint::Burmester { .. } => *self,
        }
    }
}

/// One answer of the search.
#[derive(Debug, Clone, PartialEq)]
pub struct Design {
    /// The linkage, of the kind searched for ([`DesignOptions::driven`]):
    /// its driving dyad drives ([`DesignedLinkage::driving`]).
    pub linkage: DesignedLinkage,
    /// Its score by the ranking ([`RankBy::score`] of its exact figures).
    pub score: f64,
    /// Its size over the task's ([`DesignedLinkage::size`] over
    /// [`Task::span`]).
    pub size_ratio: f64,
    /// What ranked it.
    pub ranked_by: RankBy,
    /// Where the coarse pass found it.
    pub coarse: SearchPoint,
    /// Where the refinement took it (the linkage's own place).
    pub refined: SearchPoint,
    /// The coarse sample's score (the grid's `f32` columns).
    pub coarse_score: f64,
    /// How many linkages its refinement judged.
    pub evaluations: usize,
    /// With a motor ([`DesignOptions::motor`]): the drive added to a
    /// linkage whose input swings (the six-bar a motor turns through the
    /// poses, [`best_drive`](crate::design::best_drive)); `None` without a
    /// motor, or when the input turns fully (the motor turns it directly).
    pub drive: Option<Drive>,
    /// With a linear actuator ([`DesignOptions::actuator`]): the best
    /// placement found with the linkage, monotone, within the limits and
    /// clear of the links, the obstacles and the envelope; `None` without.
    pub actuator: Option<Actuator>,
}

/// A limit or a check a candidate can fail.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Limit {
    /// The poses are in different assembly modes (or one is a toggle).
    BranchDefect,
    /// No input direction carries the coupler through the poses in order
    /// on one circuit.
    Order,
    /// The minimum transmission angle over the travel is below the limit.
    Transmission,
    /// The link ratio is above the limit.
    LinkRatio,
    /// The input is not of the required kind (crank or rocker).
    Input,
    /// The linkage is nearer the Grashof change point than allowed
    /// ([`DesignLimits::min_grashof_margin`]).
    GrashofMargin,
    /// The linkage is larger, relative to the task, than allowed.
    SizeRatio,
    /// A link is longer than allowed.
    LinkLength,
    /// A fixed pivot is outside the pivot region.
    PivotRegion,
    /// A moving link hits an obstacle over the travel.
    Obstacles,
    /// A moving part leaves the envelope over the travel.
    Envelope,
}

impl Limit {
    /// Every limit, in the order they are checked.
    pub const ALL: [Limit; 11] = [
        Limit::BranchDefect,
        Limit::Order,
        Limit::Transmission,
        Limit::LinkRatio,
        Limit::Input,
        Limit::GrashofMargin,
        Limit::SizeRatio,
        Limit::LinkLength,
        Limit::PivotRegion,
        Limit::Obstacles,
        Limit::Envelope,
    ];

    /// A short name: `"branch_defect"`, `"order"`, `"transmission"`,
    /// `"link_ratio"`, `"input"`, `"grashof_margin"`, `"size_ratio"`, `"link_length"`,
    /// `"pivot_region"`, `"obstacles"` or `"envelope"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Limit::BranchDefect => "branch_defect",
            Limit::Order => "order",
            Limit::Transmission => "transmission",
            Limit::LinkRatio => "link_ratio",
            Limit::Input => "input",
            Limit::GrashofMargin => "grashof_margin",
            Limit::SizeRatio => "size_ratio",
            Limit::LinkLength => "link_length",
            Limit::PivotRegion => "pivot_region",
            Limit::Obstacles => "obstacles",
            Limit::Envelope => "envelope",
        }
    }

    fn bit(self) -> u16 {
        1 << (self as u16)
    }
}

/// A candidate whose motion is feasible but that misses limits.
#[derive(Debug, Clone, PartialEq)]
pub struct NearMiss {
    /// The linkage.
    pub linkage: DesignedLinkage,
    /// Its size over the task's.
    pub size_ratio: f64,
    /// The limits it misses.
    pub misses: Vec<Limit>,
    /// By how much, the worst of its relative shortfalls: the transmission
    /// angle's `(limit - mu) / limit`, the Grashof margin's
    /// `(limit - margin) / limit`, the link ratio's, size ratio's and
    /// link length's `value / limit - 1`, a pivot's distance outside the
    /// region over the task's size, and 1 for the wrong input kind, an
    /// obstacle hit or the envelope left. Smaller is nearer.
    pub shortfall: f64,
}

/// What [`Task::design`] found, and what it searched under.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignReport {
    /// The designs, best first, distinct (module docs); empty when nothing
    /// fits.
    pub designs: Vec<Design>,
    /// The limits used.
    pub limits: DesignLimits,
    /// The space used.
    pub space: Space,
    /// What ranked the designs.
    pub rank_by: RankBy,
    /// The least distance between two designs' pivots (task units).
    pub min_separation: f64,
    /// Three poses: the box of the coarse pass ([`Space::search_box`]).
    pub search_box: Option<Viewport>,
    /// Candidates the coarse pass judged (pivot pairs, pairs of dyads, or
    /// ordered pairs of Burmester points).
    pub coarse_candidates: usize,
    /// Of them acceptable.
    pub coarse_acceptable: usize,
    /// Linkages the refinements judged.
    pub evaluations: usize,
    /// When there are no designs: how many census candidates failed each
    /// limit, the most first (a candidate may fail several); empty
    /// otherwise.
    pub rejections: Vec<(Limit, usize)>,
    /// When there are no designs: how many candidates the census judged.
    pub census: usize,
    /// When there are no designs: the nearest misses, nearest first, at
    /// most `top`, distinct as the designs are.
    pub near_misses: Vec<NearMiss>,
    /// The motor's options, where the designs were searched with one
    /// ([`DesignOptions::motor`]).
    pub motor: Option<DriveOptions>,
    /// With a motor: the candidates passed over because no drive for them
    /// was acceptable (each would have been a design: acceptable and
    /// distinct from the better designs); 0 without a motor.
    pub undriven: usize,
    /// How a linear actuator was placed, where the designs were searched
    /// with one ([`DesignOptions::actuator`]).
    pub actuator: Option<ActuatorSearch>,
    /// With a linear actuator: the candidates passed over because no
    /// placement for them was acceptable and clear; 0 without.
    pub unplaced: usize,
}

impl DesignReport {
    /// The limit that rejected the most census candidates, if any.
    pub fn main_rejection(&self) -> Option<Limit> {
        self.rejections.first().map(|r| r.0)
    }
}

/// What the three-pose coarse pass computes: the atlas of `driven` ×
/// `driving` over the search box under the limits and `constraints` (the
/// space's), ranked by the options' ranking. A distributed caller computes
/// it ([`Task::pivot_atlas_rows`] in tiles) and hands the cells to
/// [`Task::design_from_atlas`].
#[derive(Debug, Clone, PartialEq)]
pub struct DesignPlan {
    /// The box of the coarse pass.
    pub search_box: Viewport,
    /// The coarse driven pivots.
    pub driven: Grid,
    /// The coarse driving pivots of each.
    pub driving: Grid,
    /// The constraints of the atlas (the space's).
    pub constraints: crate::design::Constraints,
}

/// The cost of a linkage that is not acceptable (a barrier; finite, so the
/// simplex's statistics stay numbers).
const BARRIER: f64 = 1e300;

/// Driving pivots along the longer side of the census grid, for each
/// coarse driven pivot.
const CENSUS_DRIVING: usize = 20;

/// Dyads along the curve of a four-pose census.
const CENSUS_PAIRS: usize = 100;

/// A grid over `v` with `n` samples along the longer side (at least 2
/// along the shorter).
fn grid_over(v: &Viewport, n: usize) -> Result<Grid> {
    let (w, h) = v.size();
    let (nx, ny) = if w >= h {
        (n, ((n as f64 * h / w).round() as usize).max(2))
    } else {
        (((n as f64 * w / h).round() as usize).max(2), n)
    };
    Grid::new(*v, nx, ny)
}

/// The figures the exact judge reads: a four-bar's, or a slider-crank's
/// (as the slider solution map reads them, `design::map_slider`).
#[derive(Debug, Clone, Copy)]
enum Figures {
    FourBar(LinkageFigures),
    Slider(slider::SliderFigures),
}

/// A field both kinds of figures have.
macro_rules! either {
    ($f:expr, $field:ident) => {
        match $f {
            Figures::FourBar(f) => f.$field,
            Figures::Slider(f) => f.$field,
        }
    };
}

impl Figures {
    fn branch_free(&self) -> bool {
        match self {
            Figures::FourBar(f) => f.branch_free(),
            Figures::Slider(f) => f.branch_free,
        }
    }

    /// A driving direction and one circuit.
    fn ordered(&self) -> bool {
        either!(self, direction) != Direction::None && either!(self, one_circuit)
    }

    fn min_transmission(&self) -> f64 {
        either!(self, min_transmission)
    }

    fn link_ratio(&self) -> f64 {
        either!(self, link_ratio)
    }

    fn input_full(&self) -> bool {
        either!(self, input_full)
    }

    /// The distance from the change point: the four-bar's Grashof
    /// margin, the slider-crank's rotatability margin.
    fn margin(&self) -> f64 {
        match self {
            Figures::FourBar(f) => f.grashof_margin(),
            Figures::Slider(f) => f.margin,
        }
    }

    /// The longest link [`DesignLimits::max_link_length`] bounds.
    fn longest(&self) -> f64 {
        either!(self, lengths).iter().copied().fold(0.0, f64::max)
    }
}

/// The verdict of the exact judge on one linkage: its dyads and figures
/// (the linkage itself is built, by [`Task::four_bar`] or
/// [`Task::slider_crank`], only for the verdicts kept).
#[derive(Clone)]
struct Verdict {
    driving: Dyad,
    driven: DyadKind,
    figures: Figures,
    size_ratio: f64,
    fails: u16,
    shortfall: f64,
    /// The score, where acceptable.
    score: Option<f64>,
    /// The score's formula on the figures, acceptable or not (where the
    /// motion has a travel).
    raw: Option<f64>,
}

impl Verdict {
    fn acceptable(&self) -> bool {
        self.fails == 0 && self.score.is_some()
    }

    fn motion_feasible(&self) -> bool {
        self.fails & (Limit::BranchDefect.bit() | Limit::Order.bit()) == 0
    }

    /// The linkage judged (`None` never, in fact: the judge gave no
    /// verdict where [`Task::four_bar`] or [`Task::slider_crank`] fails).
    fn linkage(&self, task: &Task) -> Option<DesignedLinkage> {
        match &self.driven {
            DyadKind::Revolute(d) => task
                .four_bar(&self.driving, d)
                .ok()
                .map(DesignedLinkage::FourBar),
            DyadKind::Slider(s) => task
                .slider_crank(&self.driving, s)
                .ok()
                .map(DesignedLinkage::SliderCrank),
            DyadKind::Inverted(_) => None,
        }
    }
}

/// The exact judge: the limits and the space on the exact linkage.
struct Exact<'a> {
    task: &'a Task,
    limits: DesignLimits,
    rank_by: RankBy,
    region: &'a PivotRegion,
    prepared: Prepared,
    span: f64,
    /// The search's cancel flag: a clearance test over the travel checks
    /// it between intervals (one test can take long).
    cancel: Option<&'a std::sync::atomic::AtomicBool>,
}

impl<'a> Exact<'a> {
    fn new(task: &'a Task, options: &'a DesignOptions, control: &Control<'a>) -> Result<Self> {
        Ok(Exact {
            cancel: control.cancel_flag(),
            task,
            limits: options.limits,
            rank_by: options.rank_by,
            region: &options.space.pivots,
            prepared: options.space.constraints().prepare()?,
            span: task.span(),
        })
    }

    /// The verdict on the linkage of two dyads (`None`: no linkage). With
    /// `all` every limit is checked (a census), else it stops at the first
    /// failure.
    fn judge(&self, driving: &Dyad, driven: &Dyad, all: bool) -> Option<Verdict> {
        self.judge_with(driving, driven, all, self.limits.min_grashof_margin)
    }

    /// [`judge`](Self::judge) with the Grashof margin `min_margin` in
    /// place of the limits' own (a refinement's relaxed phase passes 0).
    fn judge_with(
        &self,
        driving: &Dyad,
        driven: &Dyad,
        all: bool,
        min_margin: f64,
    ) -> Option<Verdict> {
        let (figures, size) = self.task.four_bar_figures(driving, driven)?;
        self.verdict(driving, driven, figures, size, all, min_margin)
    }

    /// [`verdict_of`](Self::verdict_of) for a four-bar.
    fn verdict(
        &self,
        driving: &Dyad,
        driven: &Dyad,
        f: LinkageFigures,
        size: f64,
        all: bool,
        min_margin: f64,
    ) -> Option<Verdict> {
        self.verdict_of(
            driving,
            DyadKind::Revolute(*driven),
            Figures::FourBar(f),
            size,
            all,
            min_margin,
        )
    }

    /// The verdict on the linkage of two dyads with figures `f` and size
    /// `size` ([`DesignedLinkage::size`]), as
    /// [`judge_with`](Self::judge_with).
    fn verdict_of(
        &self,
        driving: &Dyad,
        driven: DyadKind,
        f: Figures,
        size: f64,
        all: bool,
        min_margin: f64,
    ) -> Option<Verdict> {
        let size_ratio = size / self.span;
        let mut v = Verdict {
            driving: *driving,
            driven,
            figures: f,
            size_ratio,
            fails: 0,
            shortfall: 0.0,
            score: None,
            raw: None,
        };
        let fail = |v: &mut Verdict, limit: Limit, by: f64| {
            v.fails |= limit.bit();
            v.shortfall = v.shortfall.max(by);
        };
        if !f.branch_free() {
            fail(&mut v, Limit::BranchDefect, f64::INFINITY);
        }
        if !f.ordered() {
            fail(&mut v, Limit::Order, f64::INFINITY);
        }
        if v.fails != 0 && !all {
            return Some(v);
        }
        let lim = &self.limits;
        let mu = f.min_transmission();
        if !mu.is_nan() && mu < lim.min_transmission {
            fail(
                &mut v,
                Limit::Transmission,
                (lim.min_transmission - mu) / lim.min_transmission,
            );
        }
        if f.link_ratio() > lim.max_link_ratio {
            fail(
                &mut v,
                Limit::LinkRatio,
                f.link_ratio() / lim.max_link_ratio - 1.0,
            );
        }
        let input_ok = match lim.input {
            InputRequirement::Any => true,
            InputRequirement::Crank => f.input_full(),
            InputRequirement::Rocker => !f.input_full(),
        };
        if !input_ok {
            fail(&mut v, Limit::Input, 1.0);
        }
        let margin = f.margin();
        if margin < min_margin {
            fail(
                &mut v,
                Limit::GrashofMargin,
                (min_margin - margin) / min_margin,
            );
        }
        if size_ratio > lim.max_size_ratio {
            fail(
                &mut v,
                Limit::SizeRatio,
                size_ratio / lim.max_size_ratio - 1.0,
            );
        }
        let longest = f.longest();
        if longest > lim.max_link_length {
            fail(
                &mut v,
                Limit::LinkLength,
                longest / lim.max_link_length - 1.0,
            );
        }
        // A slider's guide is a fixed line: no pivot to place.
        let driven_pivot = match &v.driven {
            DyadKind::Revolute(d) => d.center,
            _ => driving.center,
        };
        let outside = self
            .region
            .distance_outside(driving.center)
            .max(self.region.distance_outside(driven_pivot));
        if !self.region.contains(driving.center) || !self.region.contains(driven_pivot) {
            fail(&mut v, Limit::PivotRegion, outside / self.span);
        }
        // A linkage missing only the Grashof margin goes on to its raw
        // score: the refinement's penalty then slopes off the change
        // point instead of walling it off.
        if v.fails & !Limit::GrashofMargin.bit() != 0 && !all {
            return Some(v);
        }
        // The motion's checks need a feasible motion (and the linkage).
        if v.motion_feasible() && self.prepared.checks_motion() {
            let linkage = v.linkage(self.task)?;
            let (p, cancel) = (&self.prepared, self.cancel);
            let clear = match &linkage {
                DesignedLinkage::FourBar(fb) => p.clearance_ok(fb, cancel),
                DesignedLinkage::SliderCrank(sc) => p.slider_checked(sc, Checks::Obstacles, cancel),
            };
            if !clear {
                fail(&mut v, Limit::Obstacles, 1.0);
            }
            if v.fails == 0 || all {
                let inside = match &linkage {
                    DesignedLinkage::FourBar(fb) => p.envelope_ok(fb, cancel),
                    DesignedLinkage::SliderCrank(sc) => {
                        p.slider_checked(sc, Checks::Envelope, cancel)
                    }
                };
                if !inside {
                    fail(&mut v, Limit::Envelope, 1.0);
                }
            }
        }
        v.raw = self
            .rank_by
            .score(f.min_transmission(), size_ratio, f.link_ratio());
        if v.fails == 0 {
            v.score = v.raw;
        }
        Some(v)
    }
}

/// The refinement's objective: the negated score of an acceptable
/// linkage; for one whose motion is feasible but that misses limits, the
/// negated score's formula plus a penalty of [`PENALTY`] times its
/// shortfall (relative to the score's size), so the simplex slides along a
/// limit's boundary instead of stalling at it; [`BARRIER`] for one without
/// a feasible motion (or no linkage). Points are judged with the Grashof
/// margin `judged_margin` (the limits' own, or 0 in a relaxed phase of
/// [`refine`]). Keeps the best verdict seen that meets every limit with
/// the limits' own margin `strict_margin`: the answer is always
/// acceptable.
struct Objective<'a, F: Fn(&[f64], f64) -> Option<Verdict>> {
    eval: F,
    control: &'a Control<'a>,
    /// The points' coordinates ([`MAX_DIM`] at most).
    dim: usize,
    evaluations: Cell<usize>,
    judged_margin: f64,
    strict_margin: f64,
    best: RefCell<Option<(f64, Point, Verdict)>>,
    /// The best point of the current phase (acceptable as judged) and its
    /// cost: where its rounds restart.
    phase_best: RefCell<Option<(f64, Point, f64)>>,
    /// Whether a point judged so far missed the Grashof margin: the band
    /// around the change point was met (else the relaxed phases cannot
    /// find what the first missed, and are skipped).
    met_margin: Cell<bool>,
}

impl<F: Fn(&[f64], f64) -> Option<Verdict>> Objective<'_, F> {
    /// The cost of the point `p` (its first `dim` coordinates).
    fn cost(&self, p: &Point) -> f64 {
        let x = &p[..self.dim];
        if self.control.is_cancelled() || !x.iter().all(|v| v.is_finite()) {
            return BARRIER;
        }
        self.evaluations.set(self.evaluations.get() + 1);
        let Some(v) = (self.eval)(x, self.judged_margin) else {
            return BARRIER;
        };
        if !v.acceptable() {
            if v.fails & Limit::GrashofMargin.bit() != 0 {
                self.met_margin.set(true);
            }
            return match v.raw {
                Some(raw) if v.motion_feasible() && v.shortfall.is_finite() => {
                    -raw + PENALTY * (1.0 + raw.abs()) * v.shortfall
                }
                _ => BARRIER,
            };
        }
        let cost = -v.score.unwrap_or(f64::NAN);
        {
            // The same rule as the best's below: a relaxed phase refines
            // as a search without the margin would.
            let mut phase = self.phase_best.borrow_mut();
            let better = match &*phase {
                None => true,
                Some((c, _, size)) => {
                    cost < *c - tolerance::RANK_TIE
                        || (cost <= *c + tolerance::RANK_TIE && v.size_ratio < *size)
                }
            };
            if better {
                *phase = Some((cost, *p, v.size_ratio));
            }
        }
        // Judged with a relaxed margin, acceptable only at the limits' own.
        if v.figures.margin() < self.strict_margin {
            return cost;
        }
        let mut best = self.best.borrow_mut();
        let better = match &*best {
            None => true,
            Some((c, _, b)) => {
                cost < *c - tolerance::RANK_TIE
                    || (cost <= *c + tolerance::RANK_TIE && v.size_ratio < b.size_ratio)
            }
        };
        if better {
            *best = Some((cost, *p, v));
        }
        cost
    }
}

/// The weight of a limit's relative shortfall in the refinement's cost
/// (per unit of the score's size).
const PENALTY: f64 = 4.0;

/// Nelder–Mead rounds of a refinement: each restarts from the best point
/// so far with the initial simplex scaled by its factor (a simplex that
/// collapsed early, flat along a constraint's boundary, starts afresh),
/// sharing the iterations.
const ROUNDS: [f64; 6] = [1.0, 0.5, 0.25, 1.0, 0.125, 0.03125];

/// Nelder–Mead from `x0` with initial steps `h` (one per coordinate), in
/// the [`ROUNDS`]; the best acceptable verdict and where, and the
/// evaluations.
///
/// With a Grashof margin in the limits (`strict_margin > 0`) the
/// refinement is continued: after those rounds, the [`ROUNDS`] from `x0`
/// judged without the margin (`iterations` more: as a search without it
/// would refine), then the [`ROUNDS`] judged with it from where that phase
/// ended (half of `iterations` more). The best linkages of a task often
/// lie along the change point's ridge `s + l = p + q` (kites, whose even
/// links the balanced score favours), which the margin cuts out of the
/// acceptable set: refined with the margin alone, the simplex stops short
/// of the band around the ridge (the hood of `examples/hood.toml` gave
/// 0.338 against 0.419 continued). The relaxed phase walks the ridge (and
/// passes linkages meeting the margin that a search without it finds);
/// the strict phase, whose cost slopes off the ridge (a linkage missing
/// only the margin gets [`PENALTY`], not [`BARRIER`]), steps off to the
/// nearest linkage meeting the margin. Only linkages meeting every limit,
/// the margin included, are kept (the start is one), so the answer is
/// never worse than the start nor than the first rounds alone. The two
/// continued phases run only where the first rounds met the band (judged
/// a point missing the margin): elsewhere the band did not hold the
/// simplex, and they would cost 2.5 times the evaluations for nothing.
fn refine<F: Fn(&[f64], f64) -> Option<Verdict>>(
    eval: F,
    x0: &[f64],
    h: &[f64],
    iterations: usize,
    strict_margin: f64,
    control: &Control<'_>,
) -> (Option<(Vec<f64>, Verdict)>, usize) {
    // Two (four poses) or four (three poses) coordinates, a step each.
    let dim = x0.len().min(MAX_DIM);
    debug_assert!(x0.len() == dim && h.len() == dim);
    let mut start: Point = [0.0; MAX_DIM];
    start[..dim].copy_from_slice(&x0[..dim]);
    let mut objective = Objective {
        eval,
        control,
        dim,
        evaluations: Cell::new(0),
        judged_margin: strict_margin,
        strict_margin,
        best: RefCell::new(None),
        phase_best: RefCell::new(None),
        met_margin: Cell::new(false),
    };
    // The start must be acceptable.
    if objective.cost(&start) >= BARRIER {
        return (None, objective.evaluations.get());
    }
    let Some(o) = rounds(objective, &start, h, iterations, false, control) else {
        return (None, 0);
    };
    objective = o;
    // Across the margin's band only where the first phase met it: a
    // simplex that never touched the band was not held by it.
    if strict_margin > 0.0 && objective.met_margin.get() {
        objective.judged_margin = 0.0;
        *objective.phase_best.get_mut() = None;
        let Some(o) = rounds(objective, &start, h, iterations, true, control) else {
            return (None, 0);
        };
        objective = o;
        let ridge = objective.phase_best.get_mut().take().map(|(_, x, _)| x);
        objective.judged_margin = strict_margin;
        let from = ridge.unwrap_or(start);
        let Some(o) = rounds(objective, &from, h, iterations.div_ceil(2), true, control) else {
            return (None, 0);
        };
        objective = o;
    }
    let evaluations = objective.evaluations.get();
    let best = objective
        .best
        .into_inner()
        .map(|(_, x, v)| (x[..dim].to_vec(), v));
    (best, evaluations)
}

/// The [`ROUNDS`] of Nelder–Mead from `x0` (after the first round, from
/// the best acceptable point, or with `from_phase` the phase's best),
/// `iterations` shared between them; the objective back (`None` where the
/// solver failed).
fn rounds<'a, F: Fn(&[f64], f64) -> Option<Verdict>>(
    objective: Objective<'a, F>,
    x0: &Point,
    h: &[f64],
    iterations: usize,
    from_phase: bool,
    control: &Control<'_>,
) -> Option<Objective<'a, F>> {
    let dim = objective.dim;
    let per_round = iterations.div_ceil(ROUNDS.len());
    let mut left = iterations;
    for scale in ROUNDS {
        let budget = per_round.min(left);
        if budget == 0 || control.is_cancelled() {
            break;
        }
        left -= budget;
        let at = if from_phase {
            objective.phase_best.borrow().as_ref().map(|(_, x, _)| *x)
        } else {
            objective.best.borrow().as_ref().map(|(_, x, _)| *x)
        };
        let from = at.unwrap_or(*x0);
        let mut simplex = [from; MAX_DIM + 1];
        for (k, hk) in h.iter().take(dim).enumerate() {
            simplex[k + 1][k] += hk * scale;
        }
        let end = simplex::minimize(
            &simplex[..=dim],
            dim,
            1e-13,
            budget,
            |p| objective.cost(p),
            || control.is_cancelled(),
        );
        if end == End::Failed {
            return None;
        }
    }
    Some(objective)
}

/// The distance between two designs: the larger of their driving pivots'
/// and driven pivots' distances.
fn apart(a: &DesignedLinkage, b: &DesignedLinkage) -> f64 {
    (a.driving().center - b.driving().center)
        .norm()
        .max((a.driven_point() - b.driven_point()).norm())
}

/// The dyad of `task` whose center is `(x[0], x[1])` (a refinement's
/// coordinates), if any.
fn dyad_at(task: &Task, x: &[f64]) -> Option<Dyad> {
    task.dyad_from_center(Point2::new(x[0], x[1])).ok()
}

/// A coarse start: where, its pivots, its coarse score and size ratio.
#[derive(Debug, Clone, Copy)]
struct Start {
    point: SearchPoint,
    driving: Point2<f64>,
    driven: Point2<f64>,
    score: f64,
    size: f64,
}

/// The starts by score (ties to the smaller size ratio, then in the given
/// order), at least `sep` apart, at most `n`.
fn pick_starts(mut cand: Vec<Start>, sep: f64, n: usize) -> Vec<Start> {
    cand.sort_by(|a, b| {
        if (a.score - b.score).abs() <= tolerance::RANK_TIE {
            tie_order((a.size as f32, 0.0), (b.size as f32, 0.0))
        } else {
            b.score.total_cmp(&a.score)
        }
    });
    let mut out: Vec<Start> = Vec::new();
    for c in cand {
        if out.len() >= n {
            break;
        }
        let far = out.iter().all(|o| {
            (o.driving - c.driving)
                .norm()
                .max((o.driven - c.driven).norm())
                >= sep
        });
        if far {
            out.push(c);
        }
    }
    out
}

/// The designs, best first (ties to the smaller size), at least `sep`
/// apart, at most `top`.
fn rank_designs(mut all: Vec<Design>, sep: f64, top: usize) -> Vec<Design> {
    sort_designs(&mut all);
    let mut out: Vec<Design> = Vec::new();
    for d in all {
        if out.len() >= top {
            break;
        }
        if out.iter().all(|o| apart(&o.linkage, &d.linkage) >= sep) {
            out.push(d);
        }
    }
    out
}

/// The designs best first (ties to the smaller size).
fn sort_designs(all: &mut [Design]) {
    all.sort_by(|a, b| {
        if (a.score - b.score).abs() <= tolerance::RANK_TIE {
            a.size_ratio.total_cmp(&b.size_ratio)
        } else {
            b.score.total_cmp(&a.score)
        }
    });
}

/// Progress of the whole search in thousandths: the coarse pass the first
/// 800, the refinements the rest.
const PROGRESS: usize = 1000;
const COARSE_SHARE: usize = 800;

impl Task {
    /// The best linkages for this task inside the options' space under its
    /// limits, ranked by its score (see the [module
    /// docs](crate::design::search)), following `control` (progress in
    /// thousandths of the whole search; cancelling stops the coarse pass
    /// at its next row and a refinement at its next step).
    ///
    /// # Errors
    ///
    /// As [`DesignOptions::validate`]; [`Error::Cancelled`];
    /// [`Error::OutOfMemory`]; for four or five poses the errors of
    /// [`FourPositions::new`] and [`FivePositions::new`] (poses without a
    /// crank-rotation parametrisation or Burmester points). An empty answer
    /// is not an error: see [`DesignReport::rejections`].
    ///
    /// # Example
    ///
    /// ```
    /// use burmester::{Control, DesignOptions, RankBy, example};
    /// let task = example::task();
    /// // Fewer starts than the default, for a quick example.
    /// let options = DesignOptions { starts: 4, ..DesignOptions::default() };
    /// let report = task.design(&options, &Control::new())?;
    /// let best = &report.designs[0];
    /// // A four-bar: the driven dyad is a crank by default (DesignOptions::driven).
    /// let four_bar = best.linkage.four_bar().expect("a four-bar");
    /// assert!(four_bar.figures.feasible());
    /// assert!(four_bar.figures.min_transmission >= report.limits.min_transmission);
    /// assert_eq!(best.ranked_by, RankBy::Balanced);
    /// # Ok::<(), burmester::Error>(())
    /// ```
    pub fn design(&self, options: &DesignOptions, control: &Control<'_>) -> Result<DesignReport> {
        options.validate(self)?;
        if options.driven == DrivenKind::Slider {
            return self.design_slider(options, control);
        }
        match self.len() {
            3 => {
                let plan = self.plan(options)?;
                let hook = |d: usize, t: usize| {
                    control.report(COARSE_SHARE * d / t.max(1), PROGRESS);
                };
                let atlas = self.pivot_atlas(
                    &plan.driven,
                    &plan.driving,
                    &MapOptions::new(&options.limits, &plan.constraints)?,
                    options.rank_by,
                    &control.with_hook(&hook),
                )?;
                self.refine_three(options, &plan, &atlas.cells, control)
            }
            4 => self.design_four(options, control),
            _ => self.design_five(options, control),
        }
    }

    /// The coarse pass of a three-pose [`design`](Self::design): the
    /// atlas's grids and constraints, for a caller that computes it
    /// elsewhere (in tiles, on a cluster) and finishes with
    /// [`design_from_atlas`](Self::design_from_atlas).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NeedsPoses`] unless the task has three poses; as
    /// [`DesignOptions::validate`].
    pub fn design_plan(&self, options: &DesignOptions) -> Result<DesignPlan> {
        if self.len() != 3 {
            return Err(self.needs(3, "Task::design_plan"));
        }
        options.validate(self)?;
        if options.driven == DrivenKind::Slider {
            return Err(InvalidInput::DrivenKind {
                what: "the pivot-pair atlas of Task::design_plan (a four-bar's coarse pass; \
                       design with a driven slider in one call, Task::design)",
                found: "slider",
            }
            .into());
        }
        self.plan(options)
    }

    fn plan(&self, options: &DesignOptions) -> Result<DesignPlan> {
        let search_box = options.space.search_box(self, &options.limits);
        Ok(DesignPlan {
            search_box,
            driven: grid_over(&search_box, options.coarse_driven)?,
            driving: grid_over(&search_box, options.coarse_driving)?,
            constraints: options.space.constraints(),
        })
    }

    /// A three-pose [`design`](Self::design) from its coarse pass computed
    /// elsewhere: `cells` are the atlas cells of
    /// [`design_plan`](Self::design_plan)'s grids (row-major over its
    /// driven grid), as [`Task::pivot_atlas`] gives them with the plan's
    /// constraints, the options' limits and ranking. The same cells give
    /// the same report, bit for bit.
    ///
    /// # Errors
    ///
    /// As [`design_plan`](Self::design_plan);
    /// [`InvalidInput::LengthMismatch`] for cells of another count than the
    /// plan's driven grid; [`Error::Cancelled`].
    pub fn design_from_atlas(
        &self,
        options: &DesignOptions,
        cells: &[AtlasCell],
        control: &Control<'_>,
    ) -> Result<DesignReport> {
        let plan = self.design_plan(options)?;
        if cells.len() != plan.driven.len() {
            return Err(InvalidInput::LengthMismatch {
                name: "atlas cells",
                expected: plan.driven.len(),
                found: cells.len(),
            }
            .into());
        }
        self.refine_three(options, &plan, cells, control)
    }

    /// The empty report of `options`, to fill.
    fn report(&self, options: &DesignOptions, search_box: Option<Viewport>) -> DesignReport {
        DesignReport {
            designs: Vec::new(),
            limits: options.limits,
            space: options.space.clone(),
            rank_by: options.rank_by,
            min_separation: options.separation(self),
            search_box,
            coarse_candidates: 0,
            coarse_acceptable: 0,
            evaluations: 0,
            rejections: Vec::new(),
            census: 0,
            near_misses: Vec::new(),
            motor: options.motor,
            undriven: 0,
            actuator: options.actuator,
            unplaced: 0,
        }
    }

    /// Refines the starts of three poses' coarse cells.
    fn refine_three(
        &self,
        options: &DesignOptions,
        plan: &DesignPlan,
        cells: &[AtlasCell],
        control: &Control<'_>,
    ) -> Result<DesignReport> {
        let exact = Exact::new(self, options, control)?;
        let sep = options.separation(self);
        let region = &options.space.pivots;
        let mut report = self.report(options, Some(plan.search_box));
        report.coarse_candidates = plan.driven.len() * plan.driving.len();
        report.coarse_acceptable = cells.iter().map(|c| c.count as usize).sum();
        let nx = plan.driven.nx();
        let cand: Vec<Start> = cells
            .iter()
            .enumerate()
            .filter_map(|(k, c)| {
                let b = c.best?;
                let driven = plan.driven.point(k % nx, k / nx);
                region.contains(driven).then_some(Start {
                    point: SearchPoint::Pivots {
                        driving: b.driving,
                        driven,
                    },
                    driving: b.driving,
                    driven,
                    score: b.score,
                    size: f64::from(b.size_ratio),
                })
            })
            .collect();
        let starts = pick_starts(cand, sep, options.starts);
        let h = [
            plan.driving.dx(),
            plan.driving.dy(),
            plan.driven.dx(),
            plan.driven.dy(),
        ];
        let eval = |x: &[f64], margin: f64| {
            let (a, c) = (dyad_at(self, &x[..2])?, dyad_at(self, &x[2..])?);
            exact.judge_with(&a, &c, false, margin)
        };
        let refined = self.refine_starts(&starts, &h, options, control, &eval)?;
        report.evaluations = refined.iter().map(|d| d.evaluations).sum();
        report.designs = self.finish_designs(refined, options, &mut report, control)?;
        if report.designs.is_empty() {
            self.census_three(&exact, options, plan, &mut report, control)?;
        }
        control.report(PROGRESS, PROGRESS);
        Ok(report)
    }

    /// Refines every start (in parallel), each from its point's
    /// [`coordinates`](SearchPoint::coordinates) with steps `h`, judging
    /// points by `eval`.
    fn refine_starts(
        &self,
        starts: &[Start],
        h: &[f64],
        options: &DesignOptions,
        control: &Control<'_>,
        eval: &(dyn Fn(&[f64], f64) -> Option<Verdict> + Sync),
    ) -> Result<Vec<Design>> {
        let done = AtomicUsize::new(0);
        let n = starts.len().max(1);
        let out: Vec<Option<Design>> = starts
            .par_iter()
            .map(|s| {
                let x = s.point.coordinates()?;
                let (best, evaluations) = refine(
                    eval,
                    &x,
                    h,
                    options.max_iterations,
                    options.limits.min_grashof_margin,
                    control,
                );
                let d = done.fetch_add(1, Ordering::Relaxed) + 1;
                control.report(COARSE_SHARE + (PROGRESS - COARSE_SHARE) * d / n, PROGRESS);
                let (xb, v) = best?;
                Some(Design {
                    linkage: v.linkage(self)?,
                    score: v.score?,
                    size_ratio: v.size_ratio,
                    ranked_by: options.rank_by,
                    coarse: s.point,
                    refined: s.point.moved_to(&xb),
                    coarse_score: s.score,
                    evaluations,
                    drive: None,
                    actuator: None,
                })
            })
            .collect();
        if control.is_cancelled() {
            return Err(Error::Cancelled {
                done: done.into_inner(),
                total: starts.len(),
            });
        }
        Ok(out.into_iter().flatten().collect())
    }

    /// The census of a three-pose search that found nothing: every coarse
    /// driven pivot with a grid of driving pivots, judged on every limit.
    fn census_three(
        &self,
        exact: &Exact<'_>,
        options: &DesignOptions,
        plan: &DesignPlan,
        report: &mut DesignReport,
        control: &Control<'_>,
    ) -> Result<()> {
        let driving = grid_over(&plan.search_box, CENSUS_DRIVING)?;
        let dyads: Vec<Option<Dyad>> = (0..driving.len())
            .map(|k| {
                self.dyad_from_center(driving.point(k % driving.nx(), k / driving.nx()))
                    .ok()
            })
            .collect();
        let driven: Vec<Option<Dyad>> = (0..plan.driven.len())
            .map(|k| {
                let nx = plan.driven.nx();
                self.dyad_from_center(plan.driven.point(k % nx, k / nx))
                    .ok()
            })
            .collect();
        let pairs: Vec<(Dyad, DyadKind)> = driven
            .iter()
            .flatten()
            .flat_map(|c| {
                dyads
                    .iter()
                    .flatten()
                    .map(move |a| (*a, DyadKind::Revolute(*c)))
            })
            .collect();
        self.census(exact, options, &pairs, report, control)
    }

    /// Judges every pair on every limit into the report's rejections and
    /// near misses.
    fn census(
        &self,
        exact: &Exact<'_>,
        options: &DesignOptions,
        pairs: &[(Dyad, DyadKind)],
        report: &mut DesignReport,
        control: &Control<'_>,
    ) -> Result<()> {
        const CHUNK: usize = 256;
        let results: Vec<(Vec<usize>, usize, Vec<Verdict>)> = pairs
            .par_chunks(CHUNK)
            .map(|chunk| {
                let mut counts = vec![0usize; Limit::ALL.len()];
                let mut judged = 0;
                let mut misses = Vec::new();
                if control.is_cancelled() {
                    return (counts, judged, misses);
                }
                for (a, c) in chunk {
                    let Some(v) = exact.judge_kind(a, c, true) else {
                        continue;
                    };
                    judged += 1;
                    for (k, l) in Limit::ALL.iter().enumerate() {
                        if v.fails & l.bit() != 0 {
                            counts[k] += 1;
                        }
                    }
                    if v.motion_feasible() && v.fails != 0 {
                        misses.push(v);
                    }
                }
                // Keep the chunk's nearest few.
                misses.sort_by(|a, b| a.shortfall.total_cmp(&b.shortfall));
                misses.truncate(4 * options.top);
                (counts, judged, misses)
            })
            .collect();
        if control.is_cancelled() {
            return Err(Error::Cancelled {
                done: 0,
                total: pairs.len(),
            });
        }
        let mut counts = vec![0usize; Limit::ALL.len()];
        let mut misses = Vec::new();
        for (c, j, m) in results {
            for (t, v) in counts.iter_mut().zip(c) {
                *t += v;
            }
            report.census += j;
            misses.extend(m);
        }
        let mut rejections: Vec<(Limit, usize)> = Limit::ALL
            .iter()
            .copied()
            .zip(counts)
            .filter(|(_, n)| *n > 0)
            .collect();
        rejections.sort_by_key(|r| core::cmp::Reverse(r.1));
        report.rejections = rejections;
        misses.sort_by(|a, b| {
            a.shortfall
                .total_cmp(&b.shortfall)
                .then(a.size_ratio.total_cmp(&b.size_ratio))
        });
        let sep = report.min_separation;
        let mut near: Vec<NearMiss> = Vec::new();
        for v in misses {
            if near.len() >= options.top {
                break;
            }
            let Some(linkage) = v.linkage(self) else {
                continue;
            };
            if near.iter().all(|o| apart(&o.linkage, &linkage) >= sep) {
                near.push(NearMiss {
                    linkage,
                    size_ratio: v.size_ratio,
                    misses: Limit::ALL
                        .iter()
                        .copied()
                        .filter(|l| v.fails & l.bit() != 0)
                        .collect(),
                    shortfall: v.shortfall,
                });
            }
        }
        report.near_misses = near;
        Ok(())
    }

    /// Four poses: the coarse pair map, refined along the curve parameters.
    fn design_four(&self, options: &DesignOptions, control: &Control<'_>) -> Result<DesignReport> {
        let exact = Exact::new(self, options, control)?;
        let sep = options.separation(self);
        let four: &FourPositions = self.four_positions("Task::design")?;
        let length = four.parameter_length()?;
        let n = options.coarse_pairs;
        let hook = |d: usize, t: usize| control.report(COARSE_SHARE * d / t.max(1), PROGRESS);
        let map_options = MapOptions::new(&options.limits, &options.space.constraints())?;
        let map = self.pair_map(n, n, &map_options, &control.with_hook(&hook))?;
        let mut report = self.report(options, None);
        let c = &map.columns;
        report.coarse_candidates = c.valid.iter().filter(|v| **v).count();
        report.coarse_acceptable = c.acceptable.iter().filter(|v| **v).count();
        let grid = map.context.grid;
        let cand: Vec<Start> = (0..grid.len())
            .filter(|&k| c.acceptable[k])
            .filter_map(|k| {
                let (a, d) = map.context.dyads(k)?;
                let score = options.rank_by.score(
                    f64::from(c.min_transmission_rad[k]),
                    f64::from(c.size_ratio[k]),
                    f64::from(c.link_ratio[k]),
                )?;
                Some(Start {
                    point: SearchPoint::Parameters {
                        driving: grid.x(k % n),
                        driven: grid.y(k / n),
                    },
                    driving: a.center,
                    driven: d.center,
                    score,
                    size: f64::from(c.size_ratio[k]),
                })
            })
            .collect();
        let starts = pick_starts(cand, sep, options.starts);
        let step = length / n as f64;
        let eval = |x: &[f64], margin: f64| {
            if !(0.0..=length).contains(&x[0]) || !(0.0..=length).contains(&x[1]) {
                return None;
            }
            let a = four.dyad_at_parameter(x[0]).ok()?;
            let d = four.dyad_at_parameter(x[1]).ok()?;
            exact.judge_with(&a.dyad(), &d.dyad(), false, margin)
        };
        let refined = self.refine_starts(&starts, &[step, step], options, control, &eval)?;
        report.evaluations = refined.iter().map(|d| d.evaluations).sum();
        report.designs = self.finish_designs(refined, options, &mut report, control)?;
        if report.designs.is_empty() {
            let m = CENSUS_PAIRS.min(n);
            let dyads: Vec<Dyad> = four
                .parameter_samples(m)?
                .into_iter()
                .flatten()
                .map(|d| d.dyad())
                .collect();
            let pairs: Vec<(Dyad, DyadKind)> = dyads
                .iter()
                .enumerate()
                .flat_map(|(i, a)| {
                    dyads
                        .iter()
                        .enumerate()
                        .filter(move |(j, _)| *j != i)
                        .map(move |(_, c)| (*a, DyadKind::Revolute(*c)))
                })
                .collect();
            self.census(&exact, options, &pairs, &mut report, control)?;
        }
        control.report(PROGRESS, PROGRESS);
        Ok(report)
    }

    /// Five poses: every ordered pair of Burmester points.
    fn design_five(&self, options: &DesignOptions, control: &Control<'_>) -> Result<DesignReport> {
        let exact = Exact::new(self, options, control)?;
        let five: &FivePositions = self.five_positions("Task::design")?;
        let points = five.burmester_points();
        let mut report = self.report(options, None);
        let mut all = Vec::new();
        let mut pairs = Vec::new();
        for (i, a) in points.iter().enumerate() {
            for (j, c) in points.iter().enumerate() {
                if i == j {
                    continue;
                }
                if control.is_cancelled() {
                    return Err(Error::Cancelled {
                        done: pairs.len(),
                        total: points.len() * points.len().saturating_sub(1),
                    });
                }
                pairs.push((*a, DyadKind::Revolute(*c)));
                let Some(v) = exact.judge(a, c, false) else {
                    continue;
                };
                report.coarse_candidates += 1;
                if let (true, Some(score)) = (v.acceptable(), v.score) {
                    let Some(linkage) = v.linkage(self) else {
                        continue;
                    };
                    report.coarse_acceptable += 1;
                    let at = SearchPoint::Burmester {
                        driving: i,
                        driven: j,
                    };
                    all.push(Design {
                        linkage,
                        score,
                        size_ratio: v.size_ratio,
                        ranked_by: options.rank_by,
                        coarse: at,
                        refined: at,
                        coarse_score: score,
                        evaluations: 1,
                        drive: None,
                        actuator: None,
                    });
                }
            }
        }
        report.evaluations = report.coarse_candidates;
        report.designs = self.finish_designs(all, options, &mut report, control)?;
        if report.designs.is_empty() {
            self.census(&exact, options, &pairs, &mut report, control)?;
        }
        control.report(PROGRESS, PROGRESS);
        Ok(report)
    }
}
