//! The four-position pair map: every linkage of a four-pose task on one
//! picture.
//!
//! Four poses leave one degree of freedom per dyad: its center point runs
//! along the center-point curve. A linkage is a pair of dyads, so the
//! linkages of a task form a plane, spanned by the curve parameter of the
//! driving dyad and that of the driven dyad. The pair map samples that
//! plane and gives, for each pair, the columns of the three-pose
//! [`SolutionMap`](crate::SolutionMap) ([`Columns`]): branch-free,
//! Grashof class, direction, circuit, minimum transmission angle over the
//! travel, link ratio, size ratio, and `acceptable` under the limits and
//! constraints.
//!
//! # The parameter
//!
//! The curve parameter `s` is the crank rotation: the arcs of `beta_2` (the
//! driving crank's rotation from pose 1 to pose 2) over which the four
//! poses have dyads, laid end to end, first on one solution branch, then on
//! the other ([`FourPositions::dyad_at_parameter`]); it runs over
//! `[0, 2L)` in radians. Each axis of the map takes `n` samples at the
//! middles of `n` equal steps ([`FourPositions::parameter_samples`]), so
//! the map's [`Grid`] is the parameter plane: column `i` is the driving
//! sample `s_i = grid.x(i)`, row `j` the driven sample `s_j = grid.y(j)`.
//!
//! # Each pair
//!
//! The moving pivots at the four poses are computed once per sample of
//! each axis (`D_1k` of the circle point); each pair's figures come from
//! them alone ([`LinkageFigures`](crate::LinkageFigures), no trigonometry):
//! the branch flag is the assembly mode at the four poses, as in
//! [`Task::four_bar`]. A pair of a dyad with itself (the same parameter on
//! both axes) is not a linkage (its ground has no length): invalid.

use crate::design::columns::{Columns, ColumnsOut, Sample, debug_map};
use crate::design::judge::{Judge, fill_rows};
use crate::design::options::MapOptions;
use crate::design::rank::{
    Offer, RankColumns, RankedContext, best, best_with, signed_distances_with,
};
use crate::design::{Constraints, DesignLimits, RankBy, Ranking};
use crate::engine::Control;
use crate::error::{InvalidInput, Result, try_collect};
use crate::geom::Grid;
use crate::linkage::figures::figures;
use crate::synthesis::{CurveDyad, FourPositions};
use crate::synthesis::{SynthesizedFourBar, Task};

/// What a pair map was computed for: the task, the samples of both axes,
/// and the limits and constraints. Holds the per-pair logic (the linkage
/// of a pair, the margins, the best pairs), so that the columns can live
/// elsewhere (for example in NumPy).
#[derive(Clone, PartialEq)]
pub struct PairContext {
    /// The parameter plane: `x` the driving dyad's curve parameter (one
    /// column per sample), `y` the driven dyad's (one row per sample), both
    /// over `[0, FourPositions::parameter_length)`.
    pub grid: Grid,
    /// The task (four poses).
    pub task: Task,
    /// The driving dyad of each column; `None` where it is at infinity
    /// (or where [`Task::four_bar`] would refuse it: a sample of an
    /// ill-conditioned task that misses the poses by more than the dyad
    /// tolerance).
    pub driving: Vec<Option<CurveDyad>>,
    /// The driven dyad of each row; `None` as for [`PairContext::driving`].
    pub driven: Vec<Option<CurveDyad>>,
    /// The limits and constraints behind `acceptable`, checked.
    map_options: MapOptions,
}

/// The parameter plane, the task, how many dyads each axis has, the
/// limits and the constraints, not every dyad.
impl core::fmt::Debug for PairContext {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("PairContext")
            .field("grid", &self.grid)
            .field("task", &self.task)
            .field("driving_dyads", &self.driving.len())
            .field("driven_dyads", &self.driven.len())
            .field("limits", self.limits())
            .field("constraints", self.constraints())
            .finish()
    }
}

/// The pair map: what it was computed for, and its columns (row-major,
/// `n_driven` rows of `n_driving` pairs).
#[derive(Clone, PartialEq)]
pub struct PairMap {
    /// What the map was computed for.
    pub context: PairContext,
    /// One value per pair of every figure, as in the three-pose map.
    pub columns: Columns,
}

debug_map!(PairMap, "pairs");

/// A pair of dyads of a pair map with its linkage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pair {
    /// The driving dyad, with its place on the curve.
    pub driving: CurveDyad,
    /// The driven dyad, with its place on the curve.
    pub driven: CurveDyad,
    /// Its sample `(j, i)`: row `j` (the driven sample), column `i` (the
    /// driving sample).
    pub index: (usize, usize),
    /// The complete linkage, `task.four_bar(&driving.dyad(), &driven.dyad())`.
    pub linkage: SynthesizedFourBar,
    /// Its signed margin (see [`PairContext::margins`]).
    pub margin: f64,
    /// The linkage's size relative to the task's
    /// ([`SynthesizedFourBar::size`] over [`Task::span`]).
    pub size_ratio: f64,
    /// Its score by the ranking (see [`RankBy::score`]; the margin for
    /// [`RankBy::Margin`], the minimum transmission angle for
    /// [`RankBy::Pareto`]).
    pub score: f64,
    /// What ranked it.
    pub ranked_by: RankBy,
}

impl Task {
    /// The most samples on one axis of a pair map.
    pub const MAX_PAIR_SAMPLES: usize = 10_000_000;

    /// The smallest parameter length of a pair map
    /// ([`FourPositions::parameter_length`], radians): a shorter range of
    /// crank rotations (poses 1 and 2 closer than about `2e-7` task sizes)
    /// is within the rounding of its own ends.
    pub const MIN_PAIR_PARAMETER: f64 = 2e-6;

    /// The pair map of a four-pose task: every pair of `n_driving` driving
    /// dyads and `n_driven` driven dyads sampled along the center-point
    /// curve by its parameter (see the [module docs](crate::design::pairs)),
    /// with the columns of the solution map, following `control`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NeedsPoses`] unless the task has four poses; the
    /// errors of [`FourPositions::new`] and
    /// [`FourPositions::beta2_range`] (poses without a crank-rotation
    /// parametrisation); [`InvalidInput::TooSmall`] when the parameter
    /// length is below [`Task::MIN_PAIR_PARAMETER`] (poses 1 and 2 nearly
    /// coincide); [`InvalidInput::GridSize`] when a count is 0,
    /// above [`Task::MAX_PAIR_SAMPLES`], or the map has more than
    /// [`Grid::MAX_POINTS`] pairs; [`InvalidInput`] for an envelope that
    /// leaves out a pose; [`Error::OutOfMemory`](crate::Error::OutOfMemory) when
    /// the columns cannot be allocated;
    /// [`Error::Cancelled`](crate::Error::Cancelled).
    ///
    /// # Example
    ///
    /// ```
    /// use burmester::{Constraints, Control, DesignLimits, MapOptions, RankBy, Ranking, Task};
    /// // Four poses of the coupler of a crank-rocker (A0 = (0, 0), B0 = (4, 0)).
    /// let task = Task::from_xya(&[
    ///     [1.049199280691, 2.279426358634, 45.220037141544_f64.to_radians()],
    ///     [0.734502065472, 3.198658887874, 26.633426990744_f64.to_radians()],
    ///     [-0.378159188147, 3.063048993013, 21.786789298262_f64.to_radians()],
    ///     [-1.268710439724, 2.051150142014, 27.048624103934_f64.to_radians()],
    /// ])?;
    /// let options = MapOptions::new(&DesignLimits::default(), &Constraints::default())?;
    /// let map = task.pair_map(64, 64, &options, &Control::new())?;
    /// let best = map.best_pairs(Ranking::new(3, RankBy::Balanced))?;
    /// assert!(!best.is_empty());
    /// for p in &best {
    ///     // The pair's linkage passes the four poses, branch-free, in order.
    ///     assert!(p.linkage.figures.feasible());
    ///     let again = task.four_bar(&p.driving.dyad(), &p.driven.dyad())?;
    ///     assert_eq!(again, p.linkage);
    /// }
    /// # Ok::<(), burmester::Error>(())
    /// ```
    pub fn pair_map(
        &self,
        n_driving: usize,
        n_driven: usize,
        options: &MapOptions,
        control: &Control<'_>,
    ) -> Result<PairMap> {
        // The dyads follow the cancel flag; the progress is the map's rows.
        let context =
            self.pair_context_with(n_driving, n_driven, options, &control.cancel_only())?;
        let mut columns = Columns::for_overwrite(context.grid.len())?;
        context.fill(options, columns.as_out(), control)?;
        Ok(PairMap { context, columns })
    }

    /// What [`Task::pair_map`] computes its map for, without the map: the
    /// parameter plane, the dyads of both axes, the limits and constraints
    /// (validated).
    ///
    /// # Errors
    ///
    /// As [`Task::pair_map`] (but for the allocation of the columns and
    /// cancelling).
    pub fn pair_context(
        &self,
        n_driving: usize,
        n_driven: usize,
        options: &MapOptions,
    ) -> Result<PairContext> {
        self.pair_context_with(n_driving, n_driven, options, &Control::new())
    }

    /// [`pair_context`](Self::pair_context) following `control` (the
    /// dyads of both axes are computed with
    /// [`FourPositions::parameter_samples_with`]: ten million of them take
    /// seconds).
    ///
    /// # Errors
    ///
    /// As [`pair_context`](Self::pair_context);
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory) when the dyads
    /// cannot be allocated; [`Error::Cancelled`](crate::Error::Cancelled).
    pub fn pair_context_with(
        &self,
        n_driving: usize,
        n_driven: usize,
        options: &MapOptions,
        control: &Control<'_>,
    ) -> Result<PairContext> {
        if self.len() != 4 {
            return Err(self.needs(4, "Task::pair_map"));
        }
        if n_driving == 0
            || n_driven == 0
            || n_driving > Self::MAX_PAIR_SAMPLES
            || n_driven > Self::MAX_PAIR_SAMPLES
            || n_driving
                .checked_mul(n_driven)
                .is_none_or(|n| n > Grid::MAX_POINTS)
        {
            return Err(InvalidInput::GridSize {
                nx: n_driving,
                ny: n_driven,
                max: Grid::MAX_POINTS,
            }
            .into());
        }
        Judge::new(self, options)?;
        let four: &FourPositions = self.four_positions("Task::pair_map")?;
        let length = four.parameter_length()?;
        // Poses 1 and 2 nearly alike leave the crank almost no rotation
        // between them: a parameter plane too small to sample (its size is
        // below the rounding of the range's ends).
        if length.is_nan() || length < Self::MIN_PAIR_PARAMETER {
            return Err(InvalidInput::TooSmall {
                name: "the range of crank rotations from pose 1 to pose 2 (the pair map's \
                       parameter, radians over both branches)",
                value: length,
                limit: Self::MIN_PAIR_PARAMETER,
                hint: "poses 1 and 2 (nearly) coincide: move pose 2 away from pose 1, or list \
                       the poses with two distinct ones first",
            }
            .into());
        }
        Ok(PairContext {
            grid: Grid::from_bounds(0.0, length, 0.0, length, n_driving, n_driven)?,
            task: *self,
            driving: self.buildable(four.parameter_samples_with(n_driving, control)?, control)?,
            driven: self.buildable(four.parameter_samples_with(n_driven, control)?, control)?,
            map_options: options.clone(),
        })
    }
}

impl Task {
    /// The dyads of `samples` that [`Task::four_bar`] accepts (they pass
    /// the poses within [`tolerance::DYAD`](crate::tolerance::DYAD), their
    /// crank has a length); `None` for the others. A sample of an
    /// ill-conditioned task (poses 1 and 2 a hair apart) can miss by more
    /// than rounding: a pair of it would be a linkage the library refuses.
    fn buildable(
        &self,
        mut samples: Vec<Option<CurveDyad>>,
        control: &Control<'_>,
    ) -> Result<Vec<Option<CurveDyad>>> {
        let n = samples.len();
        for (i, d) in samples.iter_mut().enumerate() {
            if i % (1 << 14) == 0 {
                control.check(i, n)?;
            }
            if d.is_some_and(|d| self.check_dyad(&d.dyad(), "dyad").is_err()) {
                *d = None;
            }
        }
        Ok(samples)
    }
}

impl PairContext {
    /// The map of this context into columns the caller owns (each of
    /// `grid.len()` values, row-major with a row per driven sample): what
    /// [`Task::pair_map`] computes into fresh columns, the same bits, as
    /// [`Filemon::solution_map_into`](crate::Filemon::solution_map_into)
    /// for the three-pose map.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::LengthMismatch`]
    /// when a column has another length (or the context's dyads do not
    /// match its grid), [`InvalidInput::NeedsPoses`]
    /// when its task does not have four poses, as [`Task::pair_map`] for
    /// its limits and constraints; [`Error::Cancelled`](crate::Error::Cancelled).
    pub fn map_into(&self, out: ColumnsOut<'_>, control: &Control<'_>) -> Result<()> {
        // The task and the dyads are public: a context changed by hand must
        // still be one `pair_context` could give (its options were checked
        // when it was made).
        if self.task.len() != 4 {
            return Err(self.task.needs(4, "PairContext::map_into"));
        }
        for (name, expected, found) in [
            ("context driving dyads", self.grid.nx(), self.driving.len()),
            ("context driven dyads", self.grid.ny(), self.driven.len()),
        ] {
            if found != expected {
                return Err(InvalidInput::LengthMismatch {
                    name,
                    expected,
                    found,
                }
                .into());
            }
        }
        out.check_len(self.grid.len())?;
        self.fill(&self.map_options, out, control)
    }

    /// The columns of the map, this context checked to be one
    /// [`Task::pair_context`] could give and `options` its limits and
    /// constraints, checked.
    fn fill(&self, options: &MapOptions, out: ColumnsOut<'_>, control: &Control<'_>) -> Result<()> {
        let (n_driving, n_driven) = (self.driving.len(), self.driven.len());
        let judge = Judge::new(&self.task, options)?.with_control(control);
        // The moving pivots at the four poses, once per sample of each axis.
        let motion = self.task.motion();
        let pivots = |d: &Option<CurveDyad>| {
            d.map(|d| (d.dyad(), [0, 1, 2, 3].map(|k| motion.first_to(k, d.circle))))
        };
        let a = try_collect(
            "the driving pivots",
            n_driving,
            self.driving.iter().map(pivots),
        )?;
        let c = try_collect(
            "the driven pivots",
            n_driven,
            self.driven.iter().map(pivots),
        )?;
        fill_rows(n_driving, n_driven, out, control, |j, i| {
            let (Some((da, pa)), Some((dc, pc))) = (&a[i], &c[j]) else {
                return Sample::INVALID;
            };
            let fig = figures::<true, 4>(da.center, pa, dc.center, pc, judge.tiny);
            let free = fig.is_some_and(|f| f.branch_free());
            judge.sample(fig, free, &[da.center, dc.center], *da, *dc)
        })
    }

    /// The limits behind `acceptable`.
    pub fn limits(&self) -> &DesignLimits {
        self.map_options.limits()
    }

    /// The constraints behind `acceptable`.
    pub fn constraints(&self) -> &Constraints {
        self.map_options.constraints()
    }

    /// The limits and the constraints, checked (as the context was made).
    pub fn map_options(&self) -> &MapOptions {
        &self.map_options
    }

    /// `(n_driven, n_driving)`: the rows and the columns of the map.
    pub fn shape(&self) -> (usize, usize) {
        (self.grid.ny(), self.grid.nx())
    }

    /// The driving and driven dyads of pair `k` (row-major index), `None`
    /// where either is at infinity.
    pub fn dyads(&self, k: usize) -> Option<(CurveDyad, CurveDyad)> {
        let nx = self.grid.nx();
        Some((self.driving[k % nx]?, self.driven[k / nx]?))
    }

    /// The linkage of pair `k` (row-major index).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::OutsideRange`] for an index outside the map or a
    /// dyad at infinity; as [`Task::four_bar`] (for an invalid pair).
    pub fn linkage(&self, k: usize) -> Result<SynthesizedFourBar> {
        let n = self.grid.len();
        let (a, c) =
            (k < n)
                .then(|| self.dyads(k))
                .flatten()
                .ok_or(InvalidInput::OutsideRange {
                    name: "pair (a dyad at infinity or an index outside the map)",
                    value: k as f64,
                    min: 0.0,
                    max: n as f64 - 1.0,
                    unit: "",
                })?;
        self.task.four_bar(&a.dyad(), &c.dyad())
    }

    /// The signed margin of every pair: the distance in the parameter
    /// plane (radians of crank rotation, the context's `grid`) to the
    /// nearest pair of the other class in `branch_free`, positive where
    /// branch-free, negative elsewhere, infinite where the other class is
    /// empty (the exact Euclidean distance transform over the whole map,
    /// as for the driven three-pose map).
    ///
    /// # Errors
    ///
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory) when the
    /// transform's buffers cannot be allocated.
    pub fn margins(&self, branch_free: &[bool]) -> Result<Vec<f64>> {
        self.margins_with(branch_free, &Control::new())
    }

    /// [`margins`](Self::margins) following `control` (the cancel flag is
    /// checked every few thousand samples of work).
    ///
    /// # Errors
    ///
    /// As [`margins`](Self::margins); [`Error::Cancelled`](crate::Error::Cancelled).
    pub fn margins_with(&self, branch_free: &[bool], control: &Control<'_>) -> Result<Vec<f64>> {
        signed_distances_with(&self.grid, branch_free, control)
    }

    best! {
        /// The [`Ranking::k`] best pairs, best first, from the map's columns,
        /// by `ranking` (the rankings of the three-pose map, [`RankBy`]: runs
        /// of scores within [`tolerance::RANK_TIE`](crate::tolerance::RANK_TIE)
        /// go to the smaller size ratio, then the larger margin). A pair closer
        /// than the ranking's separation in the parameter plane to a better one
        /// is skipped, so the list offers distinct options (default:
        /// [`Ranking::DEFAULT_SEPARATION`] of the plane's diagonal).
        ///
        /// # Errors
        ///
        /// [`InvalidInput::LengthMismatch`] for columns of another length than
        /// the map.
        best_pairs(RankColumns<'_>) -> Pair, with best_pairs_with
    }

    /// [`best_pairs`](Self::best_pairs) following `control` (the cancel
    /// flag checked every few thousand samples and candidates; the
    /// candidates selected, `O(n log k)`, as
    /// [`MapContext::best_pivots_with`](crate::MapContext::best_pivots_with)).
    ///
    /// # Errors
    ///
    /// As [`best_pairs`](Self::best_pairs);
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory);
    /// [`Error::Cancelled`](crate::Error::Cancelled).
    pub fn best_pairs_with(
        &self,
        ranking: Ranking,
        columns: RankColumns<'_>,
        control: &Control<'_>,
    ) -> Result<Vec<Pair>> {
        best_with(self, ranking, columns, control)
    }
}

impl RankedContext for PairContext {
    type Item = Pair;
    const WHAT: &'static str = "the best pairs";

    fn grid(&self) -> &Grid {
        &self.grid
    }

    fn filemon(&self) -> Option<Option<crate::synthesis::three::Filemon>> {
        None
    }

    fn item(&self, o: &Offer<'_>) -> Option<Pair> {
        let ((driving, driven), linkage) = (self.dyads(o.s)?, self.linkage(o.s).ok()?);
        let (index, margin, size_ratio) = o.placed(self.grid.nx(), &linkage, self.task.span());
        Some(Pair {
            driving,
            driven,
            index,
            linkage,
            margin,
            size_ratio,
            score: o.score,
            ranked_by: o.rank_by,
        })
    }
}

impl PairMap {
    /// The columns a ranking reads.
    pub fn rank_columns(&self) -> RankColumns<'_> {
        self.columns.rank_columns()
    }

    /// The linkage of pair `(j, i)`: driven sample `j`, driving sample `i`.
    ///
    /// # Errors
    ///
    /// As [`PairContext::linkage`].
    pub fn linkage(&self, j: usize, i: usize) -> Result<SynthesizedFourBar> {
        let (ny, nx) = self.context.shape();
        if j >= ny || i >= nx {
            return Err(InvalidInput::OutsideRange {
                name: "pair index",
                value: (if j >= ny { j } else { i }) as f64,
                min: 0.0,
                max: (if j >= ny { ny } else { nx }) as f64 - 1.0,
                unit: "",
            }
            .into());
        }
        self.context.linkage(j * nx + i)
    }

    /// The signed margin of every pair (see [`PairContext::margins`]).
    ///
    /// # Errors
    ///
    /// As [`PairContext::margins`].
    pub fn margins(&self) -> Result<Vec<f64>> {
        self.context.margins(&self.columns.branch_free)
    }

    best! {
        /// The best pairs by `ranking`, best first (see
        /// [`PairContext::best_pairs`]).
        ///
        /// # Errors
        ///
        /// As [`PairContext::best_pairs`].
        best_pairs -> Pair
    }

    /// The whole Pareto front of the acceptable pairs over the minimum
    /// transmission angle and the size ratio, from the most compact to the
    /// best transmission: `best_pairs(Ranking::pareto_front())`.
    ///
    /// # Errors
    ///
    /// As [`PairContext::best_pairs`].
    pub fn pareto_front(&self) -> Result<Vec<Pair>> {
        self.best_pairs(Ranking::pareto_front())
    }
}
