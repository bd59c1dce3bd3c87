//! Ranking candidate pivots of a solution map, and the margin of a sample
//! to the nearest branch-defect boundary.

use core::cmp::Ordering;
use core::str::FromStr;
use std::collections::{BinaryHeap, HashMap};

use nalgebra::Point2;

use crate::design::{Columns, MapContext, SolutionMap, Varying};
use crate::engine::Control;
use crate::error::{InvalidInput, Result, in_range, named, out_of_memory, try_push, try_vec};
use crate::geom::{Grid, Viewport};
use crate::synthesis::three::Filemon;
use crate::synthesis::{SynthesizedFourBar, SynthesizedSliderCrank};
use crate::tolerance;

/// What a ranking of pivots orders by.
///
/// Every ranking but [`RankBy::Margin`] takes the *acceptable* samples of
/// the map (branch-free, in order on one circuit, meeting the limits and
/// constraints) and orders them by a score, the larger the better; scores
/// that tie (within [`tolerance::RANK_TIE`]) go to the smaller size ratio,
/// then to the larger margin to the nearest branch-defect boundary. With `mu` the minimum transmission angle
/// over the travel, `s` the size ratio (the linkage's size over the task's,
/// [`SynthesizedFourBar::size`](crate::SynthesizedFourBar::size) over
/// [`Task::span`](crate::Task::span)) and `r` the link ratio (longest over
/// shortest link):
///
/// | ranking | score | what it favours |
/// |---|---|---|
/// | [`Balanced`](Self::Balanced) | `sin(mu) / sqrt(s r)` | force transmission, a small linkage and even links, together |
/// | [`Transmission`](Self::Transmission) | `mu` | force transmission alone |
/// | [`Compact`](Self::Compact) | `-s` | the smallest linkage alone |
/// | [`Pareto`](Self::Pareto) | none: the front | every trade-off between `mu` and `s` |
/// | [`Margin`](Self::Margin) | the margin | robustness to moving the pivot (branch-free samples, acceptable or not) |
///
/// Why the balanced score: `sin(mu)` is the share of the coupler's force
/// that turns the output (the reason behind the classical 40 degree rule:
/// 0.64 there, 1 at 90 degrees); the size and link ratios are both scale
/// free and at least about 1, and their geometric mean weighs them alike on
/// a logarithmic scale, so halving the linkage's size is worth what halving
/// its link ratio is, and either is worth going from `mu` = 45 to 90
/// degrees. It never prefers a linkage that is worse on all three.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum RankBy {
    /// Acceptable candidates by `sin(mu) / sqrt(size_ratio * link_ratio)`.
    #[default]
    Balanced,
    /// Acceptable candidates by the minimum transmission angle over the
    /// travel.
    Transmission,
    /// Acceptable candidates by the size ratio, smallest first.
    Compact,
    /// The acceptable candidates on the Pareto front of the minimum
    /// transmission angle (larger is better) and the size ratio (smaller is
    /// better): no other acceptable candidate is as good in both and better
    /// in one. Listed from the most compact to the best transmission.
    Pareto,
    /// Branch-free candidates (acceptable or not) by their margin to the
    /// nearest branch-defect boundary: the fallback when nothing is
    /// acceptable.
    Margin,
}

impl RankBy {
    /// Every ranking, the default first.
    pub const ALL: [RankBy; 5] = [
        RankBy::Balanced,
        RankBy::Transmission,
        RankBy::Compact,
        RankBy::Pareto,
        RankBy::Margin,
    ];

    /// `"balanced"`, `"transmission"`, `"compact"`, `"pareto"` or `"margin"`.
    pub fn as_str(self) -> &'static str {
        match self {
            RankBy::Balanced => "balanced",
            RankBy::Transmission => "transmission",
            RankBy::Compact => "compact",
            RankBy::Pareto => "pareto",
            RankBy::Margin => "margin",
        }
    }

    /// The score of an acceptable candidate with minimum transmission angle
    /// `mu` (radians), size ratio `size_ratio` and link ratio `link_ratio`,
    /// larger is better (see the table above); `None` for
    /// [`RankBy::Pareto`] and [`RankBy::Margin`], which have no such score,
    /// and where a figure is NaN.
    pub fn score(self, mu: f64, size_ratio: f64, link_ratio: f64) -> Option<f64> {
        let v = match self {
            RankBy::Balanced => mu.sin() / (size_ratio * link_ratio).sqrt(),
            RankBy::Transmission => mu,
            RankBy::Compact => -size_ratio,
            RankBy::Pareto | RankBy::Margin => return None,
        };
        (!v.is_nan()).then_some(v)
    }
}

impl FromStr for RankBy {
    type Err = InvalidInput;

    fn from_str(s: &str) -> Result<Self, InvalidInput> {
        let expected = "\"balanced\", \"transmission\", \"compact\", \"pareto\" or \"margin\"";
        let is = |r: &RankBy| r.as_str().eq_ignore_ascii_case(s);
        named(RankBy::ALL, is, "ranking", expected, s)
    }
}

/// How a map's samples are ranked, checked once: how many to keep (`k`),
/// the least distance between two of them (`min_separation`) and what
/// orders them ([`RankBy`]). Every `best_*` ranking of a map takes one
/// ([`MapContext::best_pivots`], [`SolutionMap::best_pivots`],
/// [`PairMap::best_pairs`](crate::PairMap::best_pairs),
/// [`DriveMap::best_drives`](crate::design::DriveMap::best_drives),
/// [`ActuatorMap::best_placements`](crate::design::ActuatorMap::best_placements),
/// ...), so none of them checks it again.
///
/// A candidate closer than the separation to a better one is skipped, so
/// that the list offers distinct options. The separation is measured on
/// the map's grid (in the task's units for a pivot map, in radians of crank
/// rotation for a pair map); by default ([`Ranking::new`],
/// `min_separation() == None`) it is [`Ranking::DEFAULT_SEPARATION`] of the
/// diagonal of the map's viewport:
///
/// ```text
/// separation = min_separation              (given, >= 0 and finite)
///            = 0.02 * hypot(width, height)  (default: the viewport's)
/// ```
///
/// # Example
///
/// ```
/// use burmester::{Error, InvalidInput, RankBy, Ranking};
/// let ranking = Ranking::new(3, RankBy::Transmission);
/// assert_eq!((ranking.k(), ranking.min_separation()), (3, None));
/// let apart = ranking.with_separation(0.5)?;
/// assert_eq!(apart.min_separation(), Some(0.5));
/// assert_eq!(apart.rank_by(), RankBy::Transmission);
/// // A negative or non-finite separation is refused once, here.
/// assert!(matches!(
///     ranking.with_separation(-1.0),
///     Err(Error::InvalidInput(InvalidInput::OutsideRange { name: "min_separation", .. }))
/// ));
/// // An optional separation (None: the default), as a binding gets it.
/// assert_eq!(Ranking::try_new(3, Some(0.5), RankBy::Transmission)?, apart);
/// # Ok::<(), burmester::Error>(())
/// ```
///
/// # See also
///
/// [`MapOptions`](crate::MapOptions), the limits and constraints a map is
/// computed under, checked once in the same way.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ranking {
    k: usize,
    min_separation: Option<f64>,
    rank_by: RankBy,
}

impl Ranking {
    /// The default minimum separation, as a share of the diagonal of the
    /// map's viewport.
    pub const DEFAULT_SEPARATION: f64 = 0.02;

    /// The `k` best samples by `rank_by`, at least the default separation
    /// apart ([`Ranking::DEFAULT_SEPARATION`] of the viewport's diagonal).
    pub const fn new(k: usize, rank_by: RankBy) -> Self {
        Ranking {
            k,
            min_separation: None,
            rank_by,
        }
    }

    /// The whole Pareto front of the acceptable samples over the minimum
    /// transmission angle and the size ratio ([`RankBy::Pareto`]), none
    /// left out: every one of them (`k = usize::MAX`) with no separation
    /// (`Some(0.0)`).
    pub const fn pareto_front() -> Self {
        Ranking {
            k: usize::MAX,
            min_separation: Some(0.0),
            rank_by: RankBy::Pareto,
        }
    }

    /// This ranking with the minimum separation `min_separation`, in the
    /// units of the map's grid.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::OutsideRange`] for a negative or non-finite
    /// `min_separation`.
    pub fn with_separation(self, min_separation: f64) -> Result<Self> {
        in_range("min_separation", min_separation, 0.0, f64::MAX, "")?;
        Ok(Ranking {
            min_separation: Some(min_separation),
            ..self
        })
    }

    /// [`Ranking::new`], then [`with_separation`](Self::with_separation)
    /// where `min_separation` is given (`None`: the default): the form for a
    /// caller whose separation is optional (a binding's keyword).
    ///
    /// # Errors
    ///
    /// As [`with_separation`](Self::with_separation).
    pub fn try_new(k: usize, min_separation: Option<f64>, rank_by: RankBy) -> Result<Self> {
        let ranking = Ranking::new(k, rank_by);
        match min_separation {
            Some(s) => ranking.with_separation(s),
            None => Ok(ranking),
        }
    }

    /// How many samples to keep, at most.
    pub const fn k(&self) -> usize {
        self.k
    }

    /// The minimum separation as given; `None`: the default.
    pub const fn min_separation(&self) -> Option<f64> {
        self.min_separation
    }

    /// What orders the samples.
    pub const fn rank_by(&self) -> RankBy {
        self.rank_by
    }

    /// The separation on a map whose viewport is `viewport`: the given one,
    /// or [`Ranking::DEFAULT_SEPARATION`] of its diagonal.
    pub fn separation(&self, viewport: &Viewport) -> f64 {
        self.min_separation
            .unwrap_or(Self::DEFAULT_SEPARATION * viewport.diagonal())
    }
}

impl Default for Ranking {
    /// The five best by the default ranking ([`RankBy::Balanced`]), at the
    /// default separation: the binding's defaults.
    fn default() -> Self {
        Ranking::new(5, RankBy::default())
    }
}

/// A candidate pivot of a solution map with its linkage: a
/// [`SynthesizedFourBar`] (the default), or for a map whose driven dyad is
/// a slider a [`SynthesizedSliderCrank`] ([`SliderPivot`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pivot<L = SynthesizedFourBar> {
    /// The candidate center point.
    pub center: Point2<f64>,
    /// Its sample `(j, i)`: row `j` (for `y_j`), column `i` (for `x_i`).
    pub index: (usize, usize),
    /// The complete linkage, with its figures.
    pub linkage: L,
    /// Its signed margin (see [`MapContext::margin`]).
    pub margin: f64,
    /// The linkage's size relative to the task's
    /// ([`SynthesizedFourBar::size`] or [`SynthesizedSliderCrank::size`]
    /// over [`Task::span`](crate::Task::span)).
    pub size_ratio: f64,
    /// Its score by the ranking (see [`RankBy::score`]; the margin for
    /// [`RankBy::Margin`], the minimum transmission angle for
    /// [`RankBy::Pareto`]).
    pub score: f64,
    /// What ranked it.
    pub ranked_by: RankBy,
}

/// A candidate driving pivot of a solution map whose driven dyad is a
/// slider, with its slider-crank
/// ([`MapContext::best_pivots_with`]).
pub type SliderPivot = Pivot<SynthesizedSliderCrank>;

/// The columns a ranking reads (they may live outside the core, for
/// example in NumPy arrays).
#[derive(Debug, Clone, Copy)]
pub struct RankColumns<'a> {
    /// The `valid` column.
    pub valid: &'a [bool],
    /// The `branch_free` column.
    pub branch_free: &'a [bool],
    /// The `min_transmission_rad` column.
    pub min_transmission_rad: &'a [f32],
    /// The `link_ratio` column.
    pub link_ratio: &'a [f32],
    /// The `size_ratio` column.
    pub size_ratio: &'a [f32],
    /// The `acceptable` column.
    pub acceptable: &'a [bool],
}

/// Defines the ranking of a map `$map` whose one flag column, `$ok`,
/// stands for both `valid` and `branch_free` (a drive map's, an actuator
/// map's): `$name`, the columns it reads, with `$map::rank_columns` and the
/// columns as a solution map's ([`RankColumns`]) for [`best_flagged`], and
/// its results `$item` (with public `margin`, `score` and `ranked_by`) as
/// a [`FlaggedItem`] called `$what`.
macro_rules! flagged_rank_columns {
    ($(#[$doc:meta])* $name:ident, $map:ident, $ok:ident; $item:ident, $what:literal) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy)]
        pub struct $name<'a> {
            #[doc = concat!("The `", stringify!($ok), "` column.")]
            pub $ok: &'a [bool],
            /// The `min_transmission_rad` column.
            pub min_transmission_rad: &'a [f32],
            /// The `link_ratio` column.
            pub link_ratio: &'a [f32],
            /// The `size_ratio` column.
            pub size_ratio: &'a [f32],
            /// The `acceptable` column.
            pub acceptable: &'a [bool],
        }

        impl<'a> $name<'a> {
            /// The columns as a solution map's: the flag column is both
            /// `valid` and `branch_free`.
            fn ranked(self) -> $crate::design::RankColumns<'a> {
                $crate::design::RankColumns {
                    valid: self.$ok,
                    branch_free: self.$ok,
                    min_transmission_rad: self.min_transmission_rad,
                    link_ratio: self.link_ratio,
                    size_ratio: self.size_ratio,
                    acceptable: self.acceptable,
                }
            }
        }

        impl $map {
            /// The columns a ranking reads.
            pub fn rank_columns(&self) -> $name<'_> {
                let c = &self.columns;
                $name {
                    $ok: &c.$ok,
                    min_transmission_rad: &c.min_transmission_rad,
                    link_ratio: &c.link_ratio,
                    size_ratio: &c.size_ratio,
                    acceptable: &c.acceptable,
                }
            }
        }

        impl $crate::design::rank::FlaggedItem for $item {
            const WHAT: &'static str = $what;

            fn ranked(&mut self, margin: f64, score: f64, rank_by: RankBy) {
                (self.margin, self.score, self.ranked_by) = (margin, score, Some(rank_by));
            }
        }
    };
}
pub(crate) use flagged_rank_columns;

/// A ranking `$best(ranking)`, documented by `$doc`: the
/// [`Ranking::k`] best `$item`s by its [`RankBy`], candidates closer than
/// its separation to a better one skipped. A map's (`$best -> $item`) is
/// its context's `$best` over its own
/// [`rank_columns`](SolutionMap::rank_columns). A context's takes the
/// `columns` (`$best($columns) -> $item`) and, following a control
/// (`with $with`), asks `$with` with a control that is never cancelled, or,
/// for a map with one flag column (`flagged $at`), asks [`best_flagged`],
/// each result built by `$at`.
macro_rules! best {
    ($(#[$doc:meta])* $best:ident -> $item:ty) => {
        $crate::design::rank::best! {
            @fn [$(#[$doc])*] $best(self, ranking) -> $item {
                self.context.$best(ranking, self.rank_columns())
            }
        }
    };
    ($(#[$doc:meta])* $best:ident($columns:ty) -> $item:ty, with $with:ident) => {
        $crate::design::rank::best! {
            @fn [$(#[$doc])*] $best(self, ranking, columns: $columns) -> $item {
                self.$with(ranking, columns, &$crate::engine::Control::new())
            }
        }
    };
    ($(#[$doc:meta])* $best:ident($columns:ty) -> $item:ty, flagged $at:ident) => {
        $crate::design::rank::best! {
            @fn [$(#[$doc])*] $best(self, ranking, columns: $columns) -> $item {
                let ranked = columns.ranked();
                $crate::design::rank::best_flagged(&self.grid, ranking, ranked, |s| self.$at(s))
            }
        }
    };
    (@fn [$($doc:tt)*] $best:ident($s:ident, $r:ident $(, $c:ident: $columns:ty)?) -> $item:ty
        $body:block) => {
        $($doc)*
        pub fn $best(
            &$s,
            $r: $crate::design::Ranking,
            $($c: $columns)?
        ) -> $crate::error::Result<Vec<$item>> $body
    };
}
pub(crate) use best;

impl RankColumns<'_> {
    /// The score of sample `s` by `rank_by` (see [`RankBy::score`]).
    fn score(&self, s: usize, rank_by: RankBy) -> Option<f64> {
        rank_by.score(
            f64::from(self.min_transmission_rad[s]),
            f64::from(self.size_ratio[s]),
            f64::from(self.link_ratio[s]),
        )
    }
}

impl Columns {
    /// The columns a ranking reads.
    pub fn rank_columns(&self) -> RankColumns<'_> {
        RankColumns {
            valid: &self.valid,
            branch_free: &self.branch_free,
            min_transmission_rad: &self.min_transmission_rad,
            link_ratio: &self.link_ratio,
            size_ratio: &self.size_ratio,
            acceptable: &self.acceptable,
        }
    }
}

impl SolutionMap {
    /// The columns a ranking reads.
    pub fn rank_columns(&self) -> RankColumns<'_> {
        self.columns.rank_columns()
    }

    /// The signed margin of sample `k` (see [`MapContext::margin`]).
    pub fn margin(&self, k: usize) -> f64 {
        self.context.margin(k, &self.columns.branch_free)
    }

    best! {
        /// The best candidates by `ranking`, best first (see
        /// [`MapContext::best_pivots`]).
        ///
        /// # Errors
        ///
        /// As [`MapContext::best_pivots`].
        best_pivots -> Pivot
    }

    /// [`best_pivots`](Self::best_pivots) following `control` (see
    /// [`MapContext::best_pivots_with`]).
    ///
    /// # Errors
    ///
    /// As [`MapContext::best_pivots_with`].
    pub fn best_pivots_with(&self, ranking: Ranking, control: &Control<'_>) -> Result<Vec<Pivot>> {
        (self.context).best_pivots_with(ranking, self.rank_columns(), control)
    }

    /// The whole Pareto front of the acceptable candidates over the minimum
    /// transmission angle and the size ratio, from the most compact to the
    /// best transmission: `best_pivots(Ranking::pareto_front())`.
    ///
    /// # Errors
    ///
    /// As [`MapContext::best_pivots`].
    pub fn pareto_front(&self) -> Result<Vec<Pivot>> {
        self.best_pivots(Ranking::pareto_front())
    }

    /// The best candidates by `ranking` of a map with a driven slider, best first,
    /// each with its slider-crank (see
    /// [`MapContext::best_pivots_with`]).
    ///
    /// # Errors
    ///
    /// As [`MapContext::best_pivots_with`].
    pub fn best_slider_pivots(&self, ranking: Ranking) -> Result<Vec<SliderPivot>> {
        let columns = self.rank_columns();
        (self.context).best_pivots_with(ranking, columns, &Control::new())
    }

    /// The whole Pareto front of a map with a driven slider (as
    /// [`pareto_front`](Self::pareto_front)), each with its slider-crank.
    ///
    /// # Errors
    ///
    /// As [`MapContext::best_pivots_with`].
    pub fn slider_pareto_front(&self) -> Result<Vec<SliderPivot>> {
        self.best_slider_pivots(Ranking::pareto_front())
    }
}

impl MapContext {
    /// The signed margin of sample `k`: positive where branch-free,
    /// negative elsewhere. For candidate driving pivots, the first-order
    /// distance to the nearest transformed Filemon curve
    /// ([`Filemon::margin`]); for candidate driven pivots, the distance to
    /// the nearest sample of the other class in `branch_free` (exact
    /// Euclidean, over the whole grid: infinite when there is none), found
    /// by a search outwards from the sample (no memory sized by the grid).
    pub fn margin(&self, k: usize, branch_free: &[bool]) -> f64 {
        match self.varying {
            Varying::Driving { .. } | Varying::DrivingSlider { .. } => {
                Filemon::new(&self.task, self.varying.fixed())
                    .ok()
                    .map_or(f64::NEG_INFINITY, |f| f.margin_at(self.point(k)))
            }
            Varying::Driven { .. } => Nearest::new(&self.grid, branch_free).get(k),
        }
    }

    best! {
        /// The [`Ranking::k`] best candidates, best first, from the map's
        /// columns, by the ranking's [`RankBy`] (see [`RankBy`] for the
        /// candidates and scores of each ranking; runs of scores within
        /// [`tolerance::RANK_TIE`] go to the smaller size ratio, then the
        /// larger margin). Candidates closer than the ranking's separation
        /// to a better one are skipped, so the list offers distinct options
        /// (default: [`Ranking::DEFAULT_SEPARATION`] of the viewport's
        /// diagonal); candidates without a linkage are skipped.
        ///
        /// The candidates are selected, not sorted: `O(n log k)` for `n`
        /// samples (the Pareto front sorts its candidates, `O(n log n)`).
        ///
        /// # Errors
        ///
        /// [`InvalidInput::LengthMismatch`] for columns of another length
        /// than the grid; [`Error::OutOfMemory`](crate::Error::OutOfMemory);
        /// [`InvalidInput::DrivenKind`] for a map with a driven slider (a
        /// [`Pivot`] carries a four-bar; rank its samples from the columns and
        /// build each with [`MapContext::slider_crank`]).
        best_pivots(RankColumns<'_>) -> Pivot, with best_pivots_with
    }

    /// [`best_pivots`](Self::best_pivots) following `control`: the cancel
    /// flag is checked every few thousand samples and candidates; progress
    /// is not reported. Its pivots carry the linkage `L` of the map's
    /// driven kind: a [`SynthesizedFourBar`] ([`Pivot`]) for a driven
    /// crank, a [`SynthesizedSliderCrank`] ([`SliderPivot`]) for a driven
    /// slider, ranked the same way on the slider-crank's columns (module
    /// `map_slider`: the transmission angle between the coupler and the
    /// guide's normal over the travel, the size ratio of
    /// [`SynthesizedSliderCrank::size`], the link ratio of crank and
    /// coupler; every [`RankBy`] reads columns a slider-crank has, and the
    /// margin is the distance to the slider's transformed Filemon conic).
    ///
    /// # Errors
    ///
    /// As [`best_pivots`](Self::best_pivots);
    /// [`Error::Cancelled`](crate::Error::Cancelled);
    /// [`InvalidInput::DrivenKind`] for pivots of the other kind than the
    /// map's driven dyad (naming the ranking to use instead).
    pub fn best_pivots_with<L: PivotLinkage>(
        &self,
        ranking: Ranking,
        columns: RankColumns<'_>,
        control: &Control<'_>,
    ) -> Result<Vec<Pivot<L>>> {
        let is_slider = matches!(self.varying, Varying::DrivingSlider { .. });
        if is_slider != L::SLIDER {
            return Err(InvalidInput::DrivenKind {
                what: if L::SLIDER {
                    "best_slider_pivots (a map with a driven crank: rank it by best_pivots)"
                } else {
                    "best_pivots (its Pivot carries a four-bar; rank a map with a driven slider \
                     by best_slider_pivots)"
                },
                found: if is_slider { "slider" } else { "revolute" },
            }
            .into());
        }
        let ranked = Ranked(self, core::marker::PhantomData::<L>);
        best_with(&ranked, ranking, columns, control)
    }
}

/// The linkage a ranked [`Pivot`] of a solution map carries: a
/// [`SynthesizedFourBar`] (a driven crank) or a [`SynthesizedSliderCrank`]
/// (a driven slider). Sealed: implemented for those two only.
pub trait PivotLinkage: Sized + sealed::Sealed {
    /// Whether it is the linkage of a map with a driven slider.
    const SLIDER: bool;
    /// The linkage of sample `s` of the map `ctx`; `None` for an invalid
    /// sample.
    #[doc(hidden)]
    fn of_sample(ctx: &MapContext, s: usize) -> Option<Self>;
    /// Its size (over [`Task::span`](crate::Task::span): the size ratio).
    #[doc(hidden)]
    fn linkage_size(&self) -> f64;
}

mod sealed {
    /// Seals [`PivotLinkage`](super::PivotLinkage).
    pub trait Sealed {}
    impl Sealed for crate::synthesis::SynthesizedFourBar {}
    impl Sealed for crate::synthesis::SynthesizedSliderCrank {}
}

/// Implements [`PivotLinkage`] for `$linkage`, the linkage of a map whose
/// driven dyad is a slider when `$slider`, built by `MapContext::$of`.
macro_rules! pivot_linkage {
    ($($linkage:ty: $slider:literal, $of:ident;)*) => {$(
        impl PivotLinkage for $linkage {
            const SLIDER: bool = $slider;
            fn of_sample(ctx: &MapContext, s: usize) -> Option<Self> {
                ctx.$of(s).ok()
            }
            fn linkage_size(&self) -> f64 {
                self.size()
            }
        }
    )*};
}

pivot_linkage! {
    SynthesizedFourBar: false, linkage;
    SynthesizedSliderCrank: true, slider_crank;
}

/// A map ranked into pivots carrying the linkage `L`.
struct Ranked<'a, L>(&'a MapContext, core::marker::PhantomData<L>);

/// What the rankings of a map need of its context: the pivot map's
/// ([`MapContext`]) and the pair map's
/// ([`PairContext`](crate::design::PairContext)). Every ranking of a map
/// is [`best_with`] over it.
pub(crate) trait RankedContext {
    /// A ranked sample with its linkage ([`Pivot`], [`Pair`](crate::design::Pair)).
    type Item;
    /// What the results are called (for an allocation that fails).
    const WHAT: &'static str;
    /// Whether every margin is computed at once (the distance transform,
    /// for a map without a Filemon construction) whatever the ranking.
    const ALL_MARGINS: bool = false;
    /// The grid of the samples (separations are measured on it).
    fn grid(&self) -> &Grid;
    /// The driving map's Filemon construction, for the margins: `Some`
    /// (the construction, or `None` when it fails) for a map over
    /// candidate driving pivots, `None` for the others (their margins are
    /// distances to the other class on the grid).
    fn filemon(&self) -> Option<Option<Filemon>>;
    /// The result of the sample `offer` offers, with its linkage; `None`
    /// where it has none.
    fn item(&self, offer: &Offer<'_>) -> Option<Self::Item>;
}

/// A sample a ranking offers a map's context ([`RankedContext::item`]).
pub(crate) struct Offer<'a> {
    /// The sample, row-major.
    pub(crate) s: usize,
    /// Its score (see [`Pivot::score`]).
    pub(crate) score: f64,
    /// The ranking.
    pub(crate) rank_by: RankBy,
    /// Its margin, computed when asked.
    margin: &'a dyn Fn() -> f64,
}

impl Offer<'_> {
    /// The sample's margin.
    pub(crate) fn margin(&self) -> f64 {
        (self.margin)()
    }

    /// The sample's `(row, column)` on a grid of `nx` columns, its margin
    /// and the size ratio of its linkage `l` on a task of span `span`.
    pub(crate) fn placed(&self, nx: usize, l: &SynthesizedFourBar, span: f64) -> Placed {
        self.placed_size(nx, l.size(), span)
    }

    /// As [`placed`](Self::placed) for a linkage of size `size`.
    pub(crate) fn placed_size(&self, nx: usize, size: f64, span: f64) -> Placed {
        ((self.s / nx, self.s % nx), (self.margin)(), size / span)
    }
}

/// What [`Offer::placed`] gives: the index, the margin, the size ratio.
pub(crate) type Placed = ((usize, usize), f64, f64);

impl<L: PivotLinkage> RankedContext for Ranked<'_, L> {
    type Item = Pivot<L>;
    const WHAT: &'static str = "the best pivots";

    fn grid(&self) -> &Grid {
        &self.0.grid
    }

    fn filemon(&self) -> Option<Option<Filemon>> {
        let ctx = self.0;
        match ctx.varying {
            Varying::Driving { .. } | Varying::DrivingSlider { .. } => {
                Some(Filemon::new(&ctx.task, ctx.varying.fixed()).ok())
            }
            Varying::Driven { .. } => None,
        }
    }

    fn item(&self, o: &Offer<'_>) -> Option<Pivot<L>> {
        let ctx = self.0;
        let linkage = L::of_sample(ctx, o.s)?;
        let (index, margin, size_ratio) =
            o.placed_size(ctx.grid.nx(), linkage.linkage_size(), ctx.task.span());
        Some(Pivot {
            center: ctx.point(o.s),
            index,
            linkage,
            margin,
            size_ratio,
            score: o.score,
            ranked_by: o.rank_by,
        })
    }
}

/// A result of a map whose one flag column stands for `valid` and
/// `branch_free` ([`flagged_rank_columns!`]): a drive, a placement of an
/// actuator.
pub(crate) trait FlaggedItem {
    /// What the results are called (for an allocation that fails).
    const WHAT: &'static str;
    /// Records the ranking that chose it: its margin, its score, the
    /// ranking.
    fn ranked(&mut self, margin: f64, score: f64, rank_by: RankBy);
}

/// A map with one flag column ranked: its grid and the result of each
/// sample, `at`.
struct Flagged<'a, F> {
    grid: &'a Grid,
    at: F,
}

impl<T: FlaggedItem, F: Fn(usize) -> Result<T>> RankedContext for Flagged<'_, F> {
    type Item = T;
    const WHAT: &'static str = T::WHAT;
    const ALL_MARGINS: bool = true;

    fn grid(&self) -> &Grid {
        self.grid
    }

    fn filemon(&self) -> Option<Option<Filemon>> {
        None
    }

    fn item(&self, o: &Offer<'_>) -> Option<T> {
        let mut item = (self.at)(o.s).ok()?;
        item.ranked(o.margin(), o.score, o.rank_by);
        Some(item)
    }
}

/// The best results of a map with one flag column on `grid` (a drive
/// map's, an actuator map's) by `ranking`, best first, from its `columns`
/// (as [`RankColumns`]: the flag column both `valid` and `branch_free`),
/// each built by `at` (a sample without one is skipped), as
/// [`best_with`] gives them; every margin is computed at once, by the
/// distance transform (the distance to the nearest sample without the
/// flag).
///
/// # Errors
///
/// As [`best_with`].
pub(crate) fn best_flagged<T: FlaggedItem>(
    grid: &Grid,
    ranking: Ranking,
    columns: RankColumns<'_>,
    at: impl Fn(usize) -> Result<T>,
) -> Result<Vec<T>> {
    best_with(&Flagged { grid, at }, ranking, columns, &Control::new())
}

/// The best results of a map with context `ctx` by `ranking`, best first,
/// from its `columns` (as [`MapContext::best_pivots_with`] says),
/// following `control`.
///
/// # Errors
///
/// As [`MapContext::best_pivots_with`].
pub(crate) fn best_with<C: RankedContext>(
    ctx: &C,
    ranking: Ranking,
    columns: RankColumns<'_>,
    control: &Control<'_>,
) -> Result<Vec<C::Item>> {
    let grid = ctx.grid();
    let (k, rank_by) = (ranking.k(), ranking.rank_by());
    let sep = ranking.separation(&grid.viewport());
    let n = grid.len();
    columns.check_len(n)?;
    // A map that wants every margin asks for them all.
    let want = if C::ALL_MARGINS { usize::MAX } else { k };
    let margins = Margins::new(
        grid,
        ctx.filemon(),
        columns.branch_free,
        rank_by,
        want,
        control,
    )?;
    let nx = grid.nx();
    let mut apart = Separation::new(grid, sep);
    let mut out: Vec<C::Item> = Vec::new();
    let mut failed = None;
    rank_samples(
        n,
        rank_by,
        &columns,
        &|s| margins.get(s),
        k,
        control,
        |s, margin, score| {
            if out.len() >= k {
                return false;
            }
            let p = grid.point(s % nx, s / nx);
            if !apart.is_clear(p) {
                return true;
            }
            let margin = || margin.unwrap_or_else(|| margins.get(s));
            let offer = Offer {
                s,
                score,
                rank_by,
                margin: &margin,
            };
            if let Some(item) = ctx.item(&offer) {
                if let Err(e) = try_push(&mut out, C::WHAT, item).and_then(|()| apart.add(p)) {
                    failed = Some(e);
                    return false;
                }
            }
            out.len() < k
        },
    )?;
    failed.map_or(Ok(out), Err)
}

impl RankColumns<'_> {
    /// Checks that every column has `n` values.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::LengthMismatch`] naming the first that has not.
    pub(crate) fn check_len(&self, n: usize) -> Result<()> {
        for (name, len) in [
            ("valid", self.valid.len()),
            ("branch_free", self.branch_free.len()),
            ("min_transmission_rad", self.min_transmission_rad.len()),
            ("link_ratio", self.link_ratio.len()),
            ("size_ratio", self.size_ratio.len()),
            ("acceptable", self.acceptable.len()),
        ] {
            if len != n {
                return Err(InvalidInput::LengthMismatch {
                    name,
                    expected: n,
                    found: len,
                }
                .into());
            }
        }
        Ok(())
    }
}

/// The ranking of the `n` samples of a map's `columns` by `rank_by` (see
/// [`RankBy`]), shared by every map: offers each candidate, best first,
/// to `take(sample, margin, score)`, which returns whether it wants more
/// (`margin` is `None` where the ranking did not need it: `take` asks for
/// it when it takes the candidate).
/// Runs of scores within [`tolerance::RANK_TIE`] are offered by
/// [`tie_order`] (the smaller size ratio, then the larger `margin`).
///
/// The order is that of sorting every candidate by its key (score or
/// margin, larger first; then the sample, smaller first), but the
/// candidates are *selected*: the best `m` (about `want`, the number the
/// caller expects to take; eight times as many each time more are asked
/// for) by a heap, `O(n log m)`, with the runs of ties at the end of them;
/// the Pareto front sorts its candidates. The cancel flag of `control` is
/// checked every [`POLL`] samples or candidates.
///
/// # Errors
///
/// [`Error::OutOfMemory`](crate::Error::OutOfMemory);
/// [`Error::Cancelled`](crate::Error::Cancelled) (its counts are samples).
pub(crate) fn rank_samples(
    n: usize,
    rank_by: RankBy,
    columns: &RankColumns<'_>,
    margin: &dyn Fn(usize) -> f64,
    want: usize,
    control: &Control<'_>,
    mut take: impl FnMut(usize, Option<f64>, f64) -> bool,
) -> Result<()> {
    if rank_by == RankBy::Pareto {
        let mut cand: Vec<(usize, f32, f32)> = Vec::new();
        for s in 0..n {
            poll(control, s, n)?;
            if columns.acceptable[s]
                && !columns.min_transmission_rad[s].is_nan()
                && !columns.size_ratio[s].is_nan()
            {
                let c = (s, columns.size_ratio[s], columns.min_transmission_rad[s]);
                try_push(&mut cand, "the Pareto candidates", c)?;
            }
        }
        // By size, ties by the better transmission, then by sample: a
        // candidate is on the front when it transmits better than every
        // smaller (or as small and listed before) one.
        sort_polled(
            &mut cand,
            |a, b| {
                a.1.total_cmp(&b.1)
                    .then(b.2.total_cmp(&a.2))
                    .then(a.0.cmp(&b.0))
            },
            control,
        )?;
        let mut best = f32::NEG_INFINITY;
        for (m, (s, _, mu)) in cand.into_iter().enumerate() {
            poll(control, m, n)?;
            if mu > best {
                best = mu;
                if !take(s, None, f64::from(mu)) {
                    return Ok(());
                }
            }
        }
        return Ok(());
    }
    let by_margin = rank_by == RankBy::Margin;
    let key = |s: usize| -> Option<f64> {
        if by_margin {
            (columns.valid[s] && columns.branch_free[s]).then(|| margin(s))
        } else if columns.acceptable[s] {
            columns.score(s, rank_by)
        } else {
            None
        }
    };
    // Ties group only the scores (the margin ranking has no ties).
    let tie = if by_margin {
        None
    } else {
        Some(tolerance::RANK_TIE)
    };
    let mut m = want.saturating_add(want / 4).saturating_add(16).min(n);
    // Candidates already offered (a pass with more of them offers these
    // again first, in the same order).
    let mut offered = 0usize;
    loop {
        let (list, threshold, complete) = select(n, m, &key, tie, control)?;
        let mut count = 0usize;
        let mut i = 0;
        while i < list.len() {
            // Each candidate taken can cost a linkage (microseconds to
            // milliseconds with obstacles): the flag (one atomic load) is
            // checked before every one.
            control.check(i, list.len())?;
            let start = list[i].1;
            // A run starting below the m-th key may miss members.
            if !complete && start.total_cmp(&threshold) == Ordering::Less {
                break;
            }
            let mut j = i + 1;
            if let Some(t) = tie {
                while j < list.len() && (start - list[j].1).abs() <= t {
                    j += 1;
                }
            }
            if count + (j - i) <= offered {
                // Offered by an earlier pass.
                count += j - i;
                i = j;
                continue;
            }
            if j - i == 1 {
                // A candidate alone: its margin only for the margin ranking
                // (its key); the caller asks for it when it takes one.
                let (s, key) = list[i];
                count += 1;
                offered = count;
                if !take(s, by_margin.then_some(key), key) {
                    return Ok(());
                }
                i = j;
                continue;
            }
            // A run of ties (scores only): by size, then margin.
            let mut run: Vec<(usize, f32, f64, f64)> = Vec::new();
            for &(s, key) in &list[i..j] {
                let item = (s, columns.size_ratio[s], margin(s), key);
                try_push(&mut run, "a run of tied candidates", item)?;
            }
            sort_polled(
                &mut run,
                |a, b| tie_order((a.1, a.2), (b.1, b.2)).then(a.0.cmp(&b.0)),
                control,
            )?;
            for (s, _, mg, score) in run {
                control.check(i, list.len())?;
                count += 1;
                if count <= offered {
                    continue;
                }
                offered = count;
                if !take(s, Some(mg), score) {
                    return Ok(());
                }
            }
            i = j;
        }
        if complete || m >= n {
            return Ok(());
        }
        // Eight times as many; past a quarter of the samples, all of them.
        m = m.saturating_mul(8);
        if m >= n / 4 {
            m = n;
        }
    }
}

/// Samples or candidates between two checks of the cancel flag.
const POLL: usize = 1 << 14;

/// Checks the cancel flag every [`POLL`] steps.
#[inline]
fn poll(control: &Control<'_>, i: usize, n: usize) -> Result<()> {
    if i % POLL == 0 {
        control.check(i, n)?;
    }
    Ok(())
}

/// A candidate in a selection heap: the worse is the greater, so that the
/// top of the (max-)heap is the one to drop.
#[derive(Clone, Copy)]
struct Worst(usize, f64);

impl PartialEq for Worst {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Worst {}
impl PartialOrd for Worst {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Worst {
    fn cmp(&self, other: &Self) -> Ordering {
        // Better: the larger key, then the smaller sample.
        other.1.total_cmp(&self.1).then(self.0.cmp(&other.0))
    }
}

/// The best candidates of `key` (`None`: not a candidate), best first
/// (the larger key, then the smaller sample): the best `m` and, when
/// `tie` is given, every candidate within `tie` below the `m`-th (so the
/// runs of ties starting at or above it are whole). Returns them with the
/// `m`-th key and whether they are all the candidates.
fn select(
    n: usize,
    m: usize,
    key: &dyn Fn(usize) -> Option<f64>,
    tie: Option<f64>,
    control: &Control<'_>,
) -> Result<Selected> {
    if m >= n {
        // Every candidate: sorted, with no heap.
        let mut list: Vec<(usize, f64)> = Vec::new();
        for s in 0..n {
            poll(control, s, n)?;
            if let Some(v) = key(s) {
                try_push(&mut list, "the candidates", (s, v))?;
            }
        }
        best_first(&mut list, control)?;
        let threshold = list.last().map_or(f64::NEG_INFINITY, |c| c.1);
        return Ok((list, threshold, true));
    }
    let mut heap: BinaryHeap<Worst> = BinaryHeap::new();
    heap.try_reserve_exact(m.saturating_add(1))
        .map_err(|_| out_of_memory::<Worst>("the best candidates", m))?;
    let mut total = 0usize;
    for s in 0..n {
        poll(control, s, n)?;
        let Some(v) = key(s) else { continue };
        total += 1;
        let c = Worst(s, v);
        if heap.len() < m {
            heap.push(c);
        } else if heap.peek().is_some_and(|w| c < *w) {
            heap.pop();
            heap.push(c);
        }
    }
    let threshold = heap.peek().map_or(f64::NEG_INFINITY, |w| w.1);
    let mut list: Vec<(usize, f64)> = Vec::new();
    if total <= m || tie.is_none() {
        list.try_reserve_exact(heap.len())
            .map_err(|_| out_of_memory::<(usize, f64)>("the best candidates", heap.len()))?;
        // Sorted by pieces that check the flag (a heap's own sort of a
        // million candidates takes a fraction of a second unpolled).
        list.extend(heap.into_vec().into_iter().map(|w| (w.0, w.1)));
        best_first(&mut list, control)?;
        return Ok((list, threshold, total <= m));
    }
    drop(heap);
    let t = tie.unwrap_or(0.0);
    let low = threshold - t;
    for s in 0..n {
        poll(control, s, n)?;
        if let Some(v) = key(s) {
            if v >= low || v.total_cmp(&threshold) != Ordering::Less {
                try_push(&mut list, "the best candidates", (s, v))?;
            }
        }
    }
    best_first(&mut list, control)?;
    let complete = list.len() == total;
    Ok((list, threshold, complete))
}

/// Sorts candidates `(sample, key)` best first: the larger key, then the
/// smaller sample ([`sort_polled`]).
fn best_first(list: &mut Vec<(usize, f64)>, control: &Control<'_>) -> Result<()> {
    sort_polled(
        list,
        |a, b| b.1.total_cmp(&a.1).then(a.0.cmp(&b.0)),
        control,
    )
}

/// Sorts `v` by `cmp` (a total order), checking the cancel flag between
/// pieces of the work: sorted runs of [`POLL`] values, merged pairwise.
fn sort_polled<T: Copy>(
    v: &mut Vec<T>,
    cmp: impl Fn(&T, &T) -> Ordering,
    control: &Control<'_>,
) -> Result<()> {
    let n = v.len();
    if n <= POLL {
        v.sort_unstable_by(&cmp);
        return Ok(());
    }
    for (m, chunk) in v.chunks_mut(POLL).enumerate() {
        control.check(m * POLL, n)?;
        chunk.sort_unstable_by(&cmp);
    }
    let mut buf: Vec<T> = Vec::new();
    buf.try_reserve_exact(n)
        .map_err(|_| out_of_memory::<T>("a sort buffer", n))?;
    let mut src = core::mem::take(v);
    let mut width = POLL;
    while width < n {
        buf.clear();
        let mut start = 0;
        while start < n {
            let mid = (start + width).min(n);
            let end = (start + 2 * width).min(n);
            let (a, b) = (&src[start..mid], &src[mid..end]);
            let (mut i, mut j) = (0, 0);
            while i < a.len() && j < b.len() {
                if (i + j) % POLL == 0 {
                    if let Err(e) = control.check(start + i + j, n) {
                        *v = src;
                        return Err(e);
                    }
                }
                if cmp(&b[j], &a[i]) == Ordering::Less {
                    buf.push(b[j]);
                    j += 1;
                } else {
                    buf.push(a[i]);
                    i += 1;
                }
            }
            buf.extend_from_slice(&a[i..]);
            buf.extend_from_slice(&b[j..]);
            start = end;
        }
        core::mem::swap(&mut src, &mut buf);
        width *= 2;
    }
    *v = src;
    Ok(())
}

/// The points taken, by the cell of [`Separation`] they lie in.
type Cells = HashMap<(i64, i64), Vec<Point2<f64>>>;

/// What [`select`] gives: the candidates `(sample, key)` best first, the
/// `m`-th key, and whether they are all the candidates.
type Selected = (Vec<(usize, f64)>, f64, bool);

/// The points taken so far, to skip candidates closer than the separation
/// to one of them: a hash of cells as wide as the separation, so each
/// test looks at the points of nine cells (a cell holds at most four
/// points that far apart).
pub(crate) struct Separation {
    sep: f64,
    origin: Point2<f64>,
    /// `None`: no two samples can be closer than the separation (it is
    /// below half the grid's spacing), or cells would be too many for an
    /// integer index (a test then looks at every point).
    cells: Option<Cells>,
    all: Vec<Point2<f64>>,
    trivial: bool,
}

impl Separation {
    /// For candidates at the samples of `grid`, kept `sep` apart.
    pub(crate) fn new(grid: &Grid, sep: f64) -> Self {
        let v = grid.viewport();
        let trivial = sep.is_nan() || sep <= 0.5 * grid.dx().min(grid.dy());
        let span = ((v.xmax - v.xmin) / sep).max((v.ymax - v.ymin) / sep);
        Separation {
            sep,
            origin: Point2::new(v.xmin, v.ymin),
            cells: (!trivial && span < 1e15).then(HashMap::new),
            all: Vec::new(),
            trivial,
        }
    }

    fn cell(&self, p: Point2<f64>) -> (i64, i64) {
        (
            ((p.x - self.origin.x) / self.sep).floor() as i64,
            ((p.y - self.origin.y) / self.sep).floor() as i64,
        )
    }

    /// Whether `p` is at least the separation from every point taken.
    pub(crate) fn is_clear(&self, p: Point2<f64>) -> bool {
        if self.trivial {
            return true;
        }
        let far = |q: &Point2<f64>| (q - p).norm() >= self.sep;
        match &self.cells {
            None => self.all.iter().all(far),
            Some(cells) => {
                let (cx, cy) = self.cell(p);
                (-1..=1).all(|dx| {
                    (-1..=1).all(|dy| {
                        cells
                            .get(&(cx.saturating_add(dx), cy.saturating_add(dy)))
                            .is_none_or(|v| v.iter().all(far))
                    })
                })
            }
        }
    }

    /// Takes `p`.
    ///
    /// # Errors
    ///
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory).
    pub(crate) fn add(&mut self, p: Point2<f64>) -> Result<()> {
        if self.trivial {
            return Ok(());
        }
        let key = self.cell(p);
        match &mut self.cells {
            None => try_push(&mut self.all, "the pivots taken", p),
            Some(cells) => {
                cells
                    .try_reserve(1)
                    .map_err(|_| out_of_memory::<Point2<f64>>("the pivots taken", cells.len()))?;
                try_push(cells.entry(key).or_default(), "the pivots taken", p)
            }
        }
    }
}

/// The order of candidates whose scores tie, by `(size_ratio, margin)`:
/// the smaller size ratio first (NaN last), then the larger margin.
pub(crate) fn tie_order(a: (f32, f64), b: (f32, f64)) -> core::cmp::Ordering {
    let size = |v: f32| if v.is_nan() { f32::INFINITY } else { v };
    size(a.0).total_cmp(&size(b.0)).then(b.1.total_cmp(&a.1))
}

/// From this many results on, a ranking of a driven map computes every
/// margin at once (a distance transform, `O(n)`) rather than each by a
/// search around its sample.
pub(crate) const MANY_MARGINS: usize = 1024;

/// The margins of a map's samples, computing what they share once: the
/// driving map's Filemon construction, or the distance transform of the
/// other maps (for the margin ranking, which needs every margin, and for
/// many results) or a search outwards from each sample (for a few).
struct Margins<'a> {
    grid: &'a Grid,
    nearest: Nearest<'a>,
    /// `Some` for a driving map (see [`RankedContext::filemon`]).
    filemon: Option<Option<Filemon>>,
    distances: Option<Vec<f64>>,
}

impl<'a> Margins<'a> {
    fn new(
        grid: &'a Grid,
        filemon: Option<Option<Filemon>>,
        branch_free: &'a [bool],
        rank_by: RankBy,
        want: usize,
        control: &Control<'_>,
    ) -> Result<Self> {
        let distances = if filemon.is_none() && (rank_by == RankBy::Margin || want > MANY_MARGINS) {
            Some(signed_distances_with(grid, branch_free, control)?)
        } else {
            None
        };
        Ok(Margins {
            grid,
            nearest: Nearest::new(grid, branch_free),
            filemon,
            distances,
        })
    }

    fn get(&self, k: usize) -> f64 {
        let nx = self.grid.nx();
        match (&self.filemon, &self.distances) {
            (Some(f), _) => f.as_ref().map_or(f64::NEG_INFINITY, |f| {
                f.margin_at(self.grid.point(k % nx, k / nx))
            }),
            (None, Some(d)) => d[k],
            (None, None) => self.nearest.get(k),
        }
    }
}

/// The signed distance from a sample to the nearest sample of the other
/// class in `flags` (as [`signed_distances_with`] gives it, without its
/// memory): the samples are searched in square rings around the sample,
/// nearest first, until the ring is farther than the nearest found.
pub(crate) struct Nearest<'a> {
    grid: &'a Grid,
    flags: &'a [bool],
    /// Whether some sample is `false`, `true` (else the distance is
    /// infinite).
    has: [bool; 2],
}

impl<'a> Nearest<'a> {
    /// For the samples of `grid` flagged `flags` (one pass over them).
    pub(crate) fn new(grid: &'a Grid, flags: &'a [bool]) -> Self {
        let any_false = flags.contains(&false);
        let any_true = flags.contains(&true);
        Nearest {
            grid,
            flags,
            has: [any_false, any_true],
        }
    }

    /// The signed distance of sample `k`.
    pub(crate) fn get(&self, k: usize) -> f64 {
        let (grid, flags) = (self.grid, self.flags);
        let (nx, ny) = (grid.nx(), grid.ny());
        let class = flags[k];
        let sign = if class { 1.0 } else { -1.0 };
        if !self.has[usize::from(!class)] {
            return sign * f64::INFINITY;
        }
        let (i0, j0) = ((k % nx) as i64, (k / nx) as i64);
        let (h2x, h2y) = (grid.dx() * grid.dx(), grid.dy() * grid.dy());
        let step = grid.dx().min(grid.dy());
        let mut best = f64::INFINITY;
        let visit = |i: i64, j: i64, best: &mut f64| {
            if i < 0 || j < 0 || i >= nx as i64 || j >= ny as i64 {
                return;
            }
            if flags[j as usize * nx + i as usize] != class {
                let (di, dj) = ((i - i0) as f64, (j - j0) as f64);
                // The transform's arithmetic: the column pass, then the row's.
                let d2 = h2x * di * di + (h2y * dj * dj + 0.0);
                *best = best.min(d2);
            }
        };
        let reach = (nx.max(ny)) as i64;
        for r in 1..=reach {
            // Every sample of ring r is at least r steps away.
            let near = r as f64 * step;
            if near * near > best {
                break;
            }
            for i in (i0 - r)..=(i0 + r) {
                visit(i, j0 - r, &mut best);
                visit(i, j0 + r, &mut best);
            }
            for j in (j0 - r + 1)..(j0 + r) {
                visit(i0 - r, j, &mut best);
                visit(i0 + r, j, &mut best);
            }
        }
        sign * best.sqrt()
    }
}

/// For every sample, the Euclidean distance to the nearest sample of the
/// other class in `flags` (positive where `flags` is true, negative where
/// false, infinite when the other class is empty): the exact distance
/// transform of Felzenszwalb and Huttenlocher, separable over columns and
/// rows, in the grid's units.
///
/// # Errors
///
/// [`Error::OutOfMemory`](crate::Error::OutOfMemory);
/// [`Error::Cancelled`](crate::Error::Cancelled) (checked every few
/// columns and rows; its counts are the passes' lines).
pub(crate) fn signed_distances_with(
    grid: &Grid,
    flags: &[bool],
    control: &Control<'_>,
) -> Result<Vec<f64>> {
    const WHAT: &str = "a distance transform";
    let (nx, ny) = (grid.nx(), grid.ny());
    let lines = 2 * (nx + ny);
    let mut done = 0;
    let mut out = try_vec(WHAT, nx * ny, 0.0)?;
    let mut d = try_vec(WHAT, nx * ny, 0.0)?;
    let mut col = try_vec(WHAT, ny, 0.0)?;
    let mut tmp = try_vec(WHAT, ny.max(nx), 0.0)?;
    let mut scratch = Envelope::new(ny.max(nx))?;
    // The flag is checked about every POLL samples of work.
    let check = |done: usize, len: usize| -> Result<()> {
        if done % (POLL / len.max(1)).max(1) == 0 {
            control.check(done, lines)?;
        }
        Ok(())
    };
    for class in [true, false] {
        // Squared distance from the samples of `class` to the nearest of
        // the other class.
        for (v, &f) in d.iter_mut().zip(flags) {
            *v = if f == class { f64::INFINITY } else { 0.0 };
        }
        for i in 0..nx {
            check(done, ny)?;
            done += 1;
            for j in 0..ny {
                col[j] = d[j * nx + i];
            }
            transform_1d(&col, grid.dy(), &mut tmp[..ny], &mut scratch);
            for j in 0..ny {
                d[j * nx + i] = tmp[j];
            }
        }
        for j in 0..ny {
            check(done, nx)?;
            done += 1;
            let row = &mut d[j * nx..(j + 1) * nx];
            transform_1d(row, grid.dx(), &mut tmp[..nx], &mut scratch);
            row.copy_from_slice(&tmp[..nx]);
        }
        for (k, &f) in flags.iter().enumerate() {
            if f == class {
                let r = d[k].sqrt();
                out[k] = if class { r } else { -r };
            }
        }
    }
    Ok(out)
}

/// The buffers of [`transform_1d`], allocated once.
struct Envelope {
    v: Vec<usize>,
    z: Vec<f64>,
}

impl Envelope {
    fn new(n: usize) -> Result<Self> {
        const WHAT: &str = "a distance transform";
        let mut v = Vec::new();
        v.try_reserve_exact(n)
            .map_err(|_| out_of_memory::<usize>(WHAT, n))?;
        let mut z = Vec::new();
        z.try_reserve_exact(n + 1)
            .map_err(|_| out_of_memory::<f64>(WHAT, n + 1))?;
        Ok(Envelope { v, z })
    }
}

/// `out[p] = min_q (h^2 (p - q)^2 + f[q])`: the lower envelope of
/// parabolas (Felzenszwalb and Huttenlocher), `O(n)`.
fn transform_1d(f: &[f64], h: f64, out: &mut [f64], scratch: &mut Envelope) {
    let n = f.len();
    let h2 = h * h;
    // Vertices of the envelope's parabolas and the boundaries between them
    // (`n` and `n + 1` at most: reserved).
    let Envelope { v, z } = scratch;
    v.clear();
    z.clear();
    for q in 0..n {
        if f[q].is_infinite() {
            continue;
        }
        loop {
            let Some(&p) = v.last() else {
                v.push(q);
                z.clear();
                z.push(f64::NEG_INFINITY);
                break;
            };
            // Where the parabolas of p and q meet.
            let (qf, pf) = (q as f64, p as f64);
            let s = ((f[q] + h2 * qf * qf) - (f[p] + h2 * pf * pf)) / (2.0 * h2 * (qf - pf));
            if s <= z[z.len() - 1] {
                v.pop();
                z.pop();
                continue;
            }
            v.push(q);
            z.push(s);
            break;
        }
    }
    if v.is_empty() {
        out.fill(f64::INFINITY);
        return;
    }
    z.push(f64::INFINITY);
    let mut k = 0;
    for (p, o) in out.iter_mut().enumerate() {
        let x = p as f64;
        while z[k + 1] < x {
            k += 1;
        }
        let q = v[k] as f64;
        *o = h2 * (x - q) * (x - q) + f[v[k]];
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The ranking as it was before the selection (every candidate sorted):
    /// the reference the selection must reproduce, offer for offer.
    fn reference(
        n: usize,
        rank_by: RankBy,
        columns: &RankColumns<'_>,
        margin: &dyn Fn(usize) -> f64,
    ) -> Vec<(usize, f64, f64)> {
        let mut offered = Vec::new();
        match rank_by {
            RankBy::Margin => {
                let mut cand: Vec<(usize, f64)> = (0..n)
                    .filter(|&s| columns.valid[s] && columns.branch_free[s])
                    .map(|s| (s, margin(s)))
                    .collect();
                cand.sort_by(|a, b| b.1.total_cmp(&a.1));
                for (s, m) in cand {
                    offered.push((s, m, m));
                }
            }
            RankBy::Pareto => {
                let mut cand: Vec<(usize, f32, f32)> = (0..n)
                    .filter(|&s| {
                        columns.acceptable[s]
                            && !columns.min_transmission_rad[s].is_nan()
                            && !columns.size_ratio[s].is_nan()
                    })
                    .map(|s| (s, columns.size_ratio[s], columns.min_transmission_rad[s]))
                    .collect();
                cand.sort_by(|a, b| a.1.total_cmp(&b.1).then(b.2.total_cmp(&a.2)));
                let mut best = f32::NEG_INFINITY;
                for (s, _, mu) in cand {
                    if mu > best {
                        best = mu;
                        offered.push((s, margin(s), f64::from(mu)));
                    }
                }
            }
            _ => {
                let mut cand: Vec<(usize, f64)> = (0..n)
                    .filter(|&s| columns.acceptable[s])
                    .filter_map(|s| Some((s, columns.score(s, rank_by)?)))
                    .collect();
                cand.sort_by(|a, b| b.1.total_cmp(&a.1));
                let mut i = 0;
                while i < cand.len() {
                    let mut j = i + 1;
                    while j < cand.len() && (cand[i].1 - cand[j].1).abs() <= tolerance::RANK_TIE {
                        j += 1;
                    }
                    let mut run: Vec<(usize, f32, f64, f64)> = cand[i..j]
                        .iter()
                        .map(|&(s, score)| (s, columns.size_ratio[s], margin(s), score))
                        .collect();
                    run.sort_by(|a, b| tie_order((a.1, a.2), (b.1, b.2)));
                    for (s, _, m, score) in run {
                        offered.push((s, m, score));
                    }
                    i = j;
                }
            }
        }
        offered
    }

    /// Columns of `n` samples from `seed`: few distinct values, so that
    /// scores tie (exactly and within `RANK_TIE`) often.
    fn columns_of(n: usize, seed: u64) -> Columns {
        let mut x = seed | 1;
        let mut next = move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let mut c = Columns::for_overwrite(0).unwrap();
        for _ in 0..n {
            let r = next();
            c.valid.push(r % 7 != 0);
            c.branch_free.push(r % 5 != 0);
            let mu = match (r >> 8) % 9 {
                0 => f32::NAN,
                k => 0.1 * k as f32 + if (r >> 16) % 3 == 0 { 1e-10 } else { 0.0 },
            };
            c.min_transmission_rad.push(mu);
            c.link_ratio.push(1.0 + ((r >> 20) % 4) as f32);
            c.size_ratio.push(if (r >> 24) % 11 == 0 {
                f32::NAN
            } else {
                1.0 + ((r >> 28) % 5) as f32
            });
            c.acceptable
                .push(c.valid.last() == Some(&true) && (r >> 32) % 3 != 0);
        }
        c
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        /// The selection offers what sorting every candidate offered, in
        /// the same order, whatever the number wanted (each pass of a
        /// larger selection repeats none).
        #[test]
        fn selection_offers_what_sorting_offered(
            n in 0usize..3000, seed in any::<u64>(), want in 0usize..40, stop in 0usize..200,
        ) {
            let columns = columns_of(n, seed);
            let cols = columns.rank_columns();
            let margin = |s: usize| ((s * 7919) % 13) as f64 - 3.0;
            for rank_by in RankBy::ALL {
                let want_all = reference(n, rank_by, &cols, &margin);
                let mut got = Vec::new();
                rank_samples(n, rank_by, &cols, &margin, want, &Control::new(), |s, m, score| {
                    // A margin the ranking computed is the margin.
                    assert!(m.is_none_or(|m| m == margin(s)));
                    got.push((s, margin(s), score));
                    got.len() < stop
                })
                .unwrap();
                let k = want_all.len().min(stop.max(1));
                prop_assert_eq!(&got[..], &want_all[..k], "{:?}", rank_by);
            }
        }
    }

    #[test]
    fn separation_is_the_brute_force_test() {
        let grid = Grid::from_bounds(-3.0, 5.0, -1.0, 2.0, 40, 17).unwrap();
        for sep in [0.0, 0.01, 0.1, 0.35, 1.0, 7.0, 1e6] {
            let mut apart = Separation::new(&grid, sep);
            let mut taken: Vec<Point2<f64>> = Vec::new();
            for k in 0..grid.len() {
                let s = (k * 389) % grid.len();
                let p = grid.point(s % 40, s / 40);
                let brute = taken.iter().all(|q| (q - p).norm() >= sep);
                assert_eq!(apart.is_clear(p), brute, "sep {sep} at {p}");
                if brute {
                    apart.add(p).unwrap();
                    taken.push(p);
                }
            }
        }
    }

    #[test]
    fn a_cancelled_selection_stops() {
        static STOP: core::sync::atomic::AtomicBool = core::sync::atomic::AtomicBool::new(true);
        let columns = columns_of(100_000, 3);
        let cols = columns.rank_columns();
        let control = Control::new().with_cancel(&STOP);
        for rank_by in RankBy::ALL {
            let r = rank_samples(100_000, rank_by, &cols, &|_| 1.0, 5, &control, |_, _, _| {
                true
            });
            assert!(
                matches!(r, Err(crate::Error::Cancelled { .. })),
                "{rank_by:?}"
            );
        }
        let mut v: Vec<u32> = (0..100_000).rev().collect();
        assert!(sort_polled(&mut v, |a, b| a.cmp(b), &control).is_err());
        let mut v: Vec<u32> = (0..100_000).map(|k| (k * 7919) % 100_003).collect();
        sort_polled(&mut v, |a, b| a.cmp(b), &Control::new()).unwrap();
        assert!(v.windows(2).all(|w| w[0] <= w[1]));
    }

    #[test]
    fn the_nearest_other_sample_is_the_transform() {
        let grid = Grid::from_bounds(0.0, 7.0, 0.0, 1.5, 14, 9).unwrap();
        let flags = columns_of(grid.len(), 11).branch_free;
        let d = signed_distances_with(&grid, &flags, &Control::new()).unwrap();
        for (k, &want) in d.iter().enumerate() {
            let got = Nearest::new(&grid, &flags).get(k);
            assert!(
                (got - want).abs() <= 1e-12 * want.abs(),
                "{k}: {got} vs {}",
                d[k]
            );
        }
        let all = vec![false; grid.len()];
        assert_eq!(Nearest::new(&grid, &all).get(3), f64::NEG_INFINITY);
    }

    #[test]
    fn distance_transform_is_exact() {
        let grid = Grid::from_bounds(0.0, 7.0, 0.0, 3.5, 14, 5).unwrap();
        let mut flags = vec![true; grid.len()];
        for k in [3, 30, 47, 69] {
            flags[k] = false;
        }
        let d = signed_distances_with(&grid, &flags, &Control::new()).unwrap();
        for k in 0..grid.len() {
            let p = grid.point(k % 14, k / 14);
            let brute = (0..grid.len())
                .filter(|&q| flags[q] != flags[k])
                .map(|q| (grid.point(q % 14, q / 14) - p).norm())
                .fold(f64::INFINITY, f64::min);
            let want = if flags[k] { brute } else { -brute };
            assert!((d[k] - want).abs() < 1e-12, "{k}: {} vs {want}", d[k]);
        }
        let all = signed_distances_with(&grid, &vec![true; grid.len()], &Control::new()).unwrap();
        assert!(all.iter().all(|v| *v == f64::INFINITY));
    }
}
