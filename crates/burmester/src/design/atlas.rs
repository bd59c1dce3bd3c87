//! The pivot-pair atlas: both fixed pivots at once.
//!
//! For every candidate driven center point `C0` on a grid (the *driven
//! grid*), the three-position solution map over candidate driving center
//! points `A0` on another grid (the *driving grid*),
//! [`Filemon::solution_map`], reduced to what a designer compares across
//! `C0`:
//!
//! * the number of acceptable driving pivots;
//! * the best of them by a [`RankBy`] with a score
//!   ([`Balanced`](RankBy::Balanced), the default of the Python binding,
//!   [`Transmission`](RankBy::Transmission) or [`Compact`](RankBy::Compact);
//!   scores within [`tolerance::RANK_TIE`] tie and go to the more compact
//!   linkage, the smaller size ratio, then to the larger margin to the
//!   nearest branch-defect boundary, as in the maps), exactly the first
//!   pivot of [`SolutionMap::best_pivots`](crate::SolutionMap::best_pivots)`(`[`Ranking::new`](crate::Ranking::new)`(1,
//!   rank_by))`, with its figures and score;
//! * the number of branch-free driving samples (the map's `branch_free`
//!   column).
//!
//! The per-`C0` map is never materialised: the branch flags come one row at
//! a time from the same sweep kernel as the branch map, the figures are
//! computed only where a sample is branch-free (elsewhere it can be neither
//! branch-free nor acceptable), and the best is kept as it streams by. Each
//! driven center is computed from its grid indices alone, so any tiling of
//! the driven grid ([`Task::pivot_atlas_rows`]) gives the same cells, bit
//! for bit, as one call ([`Task::pivot_atlas`]).
//!
//! Driven centers where Filemon's construction fails (on the pole circle,
//! at a pole) are flagged `valid = false`, with count 0 and no best.

use core::ops::Range;
use core::sync::atomic::{AtomicUsize, Ordering};

use nalgebra::Point2;
use rayon::prelude::*;

use crate::design::judge::Sampler;
use crate::design::kernel::{self, AtlasAsk, CosBand, DrivingRows, RowOut, RowPre, sample_score};
use crate::design::options::MapOptions;
use crate::design::rank::tie_order;
use crate::design::{Constraints, DesignLimits, RankBy};
use crate::engine::Control;
use crate::error::{Error, InvalidInput, Result, try_push, try_vec};
use crate::geom::Grid;
use crate::synthesis::Task;
use crate::synthesis::three::{BranchRows, Filemon};
use crate::tolerance;

/// The best driving pivot of one driven center (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AtlasBest {
    /// The driving center point `A0`.
    pub driving: Point2<f64>,
    /// Its sample `(j, i)` on the driving grid.
    pub index: (usize, usize),
    /// Minimum transmission angle over the travel, radians (the solution
    /// map's `min_transmission_rad`).
    pub min_transmission_rad: f32,
    /// Longest over shortest link.
    pub link_ratio: f32,
    /// Its margin to the nearest branch-defect boundary
    /// ([`Filemon::margin`]).
    pub margin: f64,
    /// The linkage's size relative to the task's (the solution map's
    /// `size_ratio`).
    pub size_ratio: f32,
    /// Its score by the atlas's ranking ([`RankBy::score`] of the three
    /// columns above, as the map's ranking reads them).
    pub score: f64,
}

/// One driven center's reduced solution map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AtlasCell {
    /// Filemon's construction exists for this driven center.
    pub valid: bool,
    /// Acceptable driving samples (the map's `acceptable` column).
    pub count: u64,
    /// Branch-free driving samples (the map's `branch_free` column).
    pub branch_free: u64,
    /// The best acceptable driving pivot, if any.
    pub best: Option<AtlasBest>,
}

impl AtlasCell {
    /// A driven center without Filemon's construction.
    pub const INVALID: AtlasCell = AtlasCell {
        valid: false,
        count: 0,
        branch_free: 0,
        best: None,
    };
}

/// The pivot-pair atlas: what it was computed for, and one
/// [`AtlasCell`] per driven center, row-major.
#[derive(Clone, PartialEq)]
pub struct PivotAtlas {
    /// The task.
    pub task: Task,
    /// The candidate driven center points `C0`.
    pub driven: Grid,
    /// The candidate driving center points `A0` of each map.
    pub driving: Grid,
    /// The limits behind `acceptable`.
    pub limits: DesignLimits,
    /// The constraints behind `acceptable`.
    pub constraints: Constraints,
    /// What chose each cell's best driving pivot.
    pub rank_by: RankBy,
    /// One cell per driven sample, row-major.
    pub cells: Vec<AtlasCell>,
}

crate::geom::debug_shows!(
    /// The task, both grids, the limits and constraints, and how many driven
    /// centers have an acceptable driving pivot, not every cell.
    PivotAtlas, a =>
    task: a.task,
    driven: a.driven,
    driving: a.driving,
    limits: a.limits,
    constraints: a.constraints,
    cells: a.cells.len(),
    with_acceptable: a.cells.iter().filter(|c| c.count > 0).count(),
);

impl PivotAtlas {
    /// The branch-free fraction of cell `k`: branch-free driving samples
    /// over all driving samples (NaN for an invalid cell).
    pub fn branch_free_fraction(&self, k: usize) -> f64 {
        let c = &self.cells[k];
        if c.valid {
            c.branch_free as f64 / self.driving.len() as f64
        } else {
            f64::NAN
        }
    }
}

impl Task {
    /// The pivot-pair atlas over driven centers on `driven`, each reduced
    /// from its solution map over `driving` (module docs of
    /// [`atlas`](crate::design::atlas)), in parallel, following `control`:
    /// progress counts driving rows over all driven centers
    /// (`driving.ny()` per driven center, so it moves within a center
    /// whose map takes seconds), and the cancel flag is checked before
    /// every driving sample and inside the clearance tests.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NeedsPoses`] for a task of four or five poses;
    /// [`InvalidInput`] for an envelope that leaves out a pose, or a
    /// ranking without a score ([`RankBy::Pareto`], [`RankBy::Margin`]);
    /// [`Error::OutOfMemory`]; [`Error::Cancelled`].
    pub fn pivot_atlas(
        &self,
        driven: &Grid,
        driving: &Grid,
        options: &MapOptions,
        rank_by: RankBy,
        control: &Control<'_>,
    ) -> Result<PivotAtlas> {
        let rows = 0..driven.ny();
        let cells = self.pivot_atlas_rows(driven, rows, driving, options, rank_by, control)?;
        Ok(PivotAtlas {
            task: *self,
            driven: *driven,
            driving: *driving,
            limits: *options.limits(),
            constraints: options.constraints().clone(),
            rank_by,
            cells,
        })
    }

    /// The cells of rows `rows` of the driven grid (a tile of
    /// [`pivot_atlas`](Self::pivot_atlas), equal to its cells there bit for
    /// bit), row-major.
    ///
    /// # Errors
    ///
    /// As [`pivot_atlas`](Self::pivot_atlas);
    /// [`InvalidInput::OutsideRange`] for rows outside the driven grid.
    pub fn pivot_atlas_rows(
        &self,
        driven: &Grid,
        rows: Range<usize>,
        driving: &Grid,
        options: &MapOptions,
        rank_by: RankBy,
        control: &Control<'_>,
    ) -> Result<Vec<AtlasCell>> {
        self.three_poses("the pivot atlas")?;
        check_scored(rank_by, "atlas ranking")?;
        if rows.start > rows.end || rows.end > driven.ny() {
            return Err(InvalidInput::OutsideRange {
                name: "driven rows",
                value: rows.end as f64,
                min: rows.start as f64,
                max: driven.ny() as f64,
                unit: "",
            }
            .into());
        }
        let sampler = Sampler::new(self, options)?.with_control(control);
        let nx = driven.nx();
        let cells_in_all = (rows.end - rows.start) * nx;
        let mut cells = try_vec("a pivot atlas", cells_in_all, AtlasCell::INVALID)?;
        // Progress counts the driving rows over all driven centers: a
        // driven center's map can take seconds (obstacles, thousands of
        // travel samples), a driving row of it a small part of that.
        let per_cell = driving.ny();
        let total = cells_in_all.saturating_mul(per_cell);
        let done = AtomicUsize::new(0);
        // The total at once, so that a follower sees the work begin.
        control.report(0, total);
        let xs = kernel::padded_xs(driving)?;
        let failed: std::sync::Mutex<Option<Error>> = std::sync::Mutex::new(None);
        let fail = |e: Error| {
            if let Ok(mut f) = failed.lock() {
                f.get_or_insert(e);
            }
        };
        cells.par_chunks_mut(CHUNK).enumerate().for_each_init(
            || Scratch::new(&xs, driving.nx()),
            |scratch, (m, chunk)| {
                if control.is_cancelled() {
                    return;
                }
                let scratch = match scratch {
                    Ok(s) => s,
                    Err(e) => return fail(e.clone()),
                };
                let centers: Vec<Point2<f64>> = (m * CHUNK..m * CHUNK + chunk.len())
                    .map(|k| driven.point(k % nx, rows.start + k / nx))
                    .collect();
                let tick = |units: usize| {
                    let d = done.fetch_add(units, Ordering::Relaxed) + units;
                    control.report(d, total);
                };
                if let Err(e) = atlas_chunk(
                    self, &sampler, &centers, driving, rank_by, scratch, chunk, control, &tick,
                ) {
                    fail(e);
                }
            },
        );
        if let Some(e) = failed.into_inner().ok().flatten() {
            return Err(e);
        }
        let done = done.into_inner();
        if done < total || control.is_cancelled() {
            return Err(Error::Cancelled {
                done: done.min(total.saturating_sub(1)),
                total,
            });
        }
        Ok(cells)
    }
}

/// Driven centers per parallel task: the driving candidates' lanes of a
/// row ([`RowPre`]) are computed once for them all.
const CHUNK: usize = 16;

/// A worker's buffers for [`atlas_chunk`].
struct Scratch<'a> {
    /// The driving grid's padded abscissae (`kernel::padded_xs`).
    xs: &'a [f64],
    /// The groups of a row some center of the chunk needs.
    union: Vec<bool>,
    /// The driving candidates' lanes of a row.
    pre: RowPre,
    /// The kernel's lanes of a row for one center.
    out: RowOut,
}

impl<'a> Scratch<'a> {
    fn new(xs: &'a [f64], nx: usize) -> Result<Self> {
        Ok(Scratch {
            xs,
            union: try_vec("a driving row", nx, false)?,
            pre: RowPre::new(xs)?,
            out: RowOut::new(xs)?,
        })
    }
}

/// The reduction of one driven center as the driving rows go by.
struct Cell<'a> {
    filemon: &'a Filemon,
    branch: BranchRows<'a>,
    kernel: Box<dyn DrivingRows + 'a>,
    /// The branch flags of the current row.
    row: Vec<bool>,
    /// Whether the current row has a branch-free sample.
    active: bool,
    /// The acceptable samples within `RANK_TIE` of the best score so far:
    /// exactly the first run of `best_pivots`' ranking once all are seen.
    top: f64,
    run: Vec<(usize, f64)>,
    /// The scores that may reach the best run (below it by more than
    /// `TOP_SLACK`, a score cannot tie after its rounding to f32).
    reach: CosBand,
    cell: AtlasCell,
}

/// The cells of driven centers `centers`, into `cells`: each as one solution
/// map of the driving grid reduced (module docs), the rows of the driving
/// grid taken in order for every center, the lanes of the driving
/// candidates computed once per row for all of them. `tick(units)` counts
/// the driving rows done, one unit per row of one center (a center's row
/// with obstacles can take seconds); it stops, leaving `cells` partly
/// written and not counting the row it was in, once `control` is
/// cancelled.
///
/// # Errors
///
/// [`Error::OutOfMemory`] for the buffers of a driving row.
#[allow(clippy::too_many_arguments)]
fn atlas_chunk(
    task: &Task,
    sampler: &Sampler<'_>,
    centers: &[Point2<f64>],
    driving: &Grid,
    rank_by: RankBy,
    scratch: &mut Scratch<'_>,
    cells: &mut [AtlasCell],
    control: &Control<'_>,
    tick: &dyn Fn(usize),
) -> Result<()> {
    let filemons: Vec<Option<Filemon>> = centers.iter().map(|&c0| task.filemon(c0).ok()).collect();
    // The transmission limit.
    let limit = CosBand::new(sampler.judge.limits().min_transmission);
    let mut live: Vec<(usize, Cell<'_>)> = Vec::new();
    for (m, f) in filemons.iter().enumerate() {
        let Some(filemon) = f else {
            cells[m] = AtlasCell::INVALID;
            continue;
        };
        // The atlas's Filemons are made from driven center points: cranks.
        let Ok(driven) = filemon.driven_crank("the atlas") else {
            cells[m] = AtlasCell::INVALID;
            continue;
        };
        let c = sampler.fixed_pivots(&driven);
        let branch = BranchRows::new(filemon, driving)?;
        let cell = AtlasCell {
            valid: true,
            ..AtlasCell::INVALID
        };
        if !branch.any() {
            cells[m] = cell;
            continue;
        }
        live.push((
            m,
            Cell {
                filemon,
                branch,
                kernel: kernel::for_driven(sampler, driven, &c),
                row: try_vec("a driving row", driving.nx(), false)?,
                active: false,
                top: f64::NEG_INFINITY,
                run: Vec::new(),
                reach: CosBand::new(f64::NEG_INFINITY),
                cell,
            },
        ));
    }
    let Scratch {
        xs,
        union,
        pre,
        out,
    } = scratch;
    let nx = driving.nx();
    // The centers without a row to reduce are done.
    tick((centers.len() - live.len()) * driving.ny());
    if live.is_empty() {
        return Ok(());
    }
    for j in 0..driving.ny() {
        if control.is_cancelled() {
            return Ok(());
        }
        union.fill(false);
        let mut any = false;
        for (_, cell) in &mut live {
            cell.branch.row(j, &mut cell.row);
            cell.active = cell.row.contains(&true);
            if cell.active {
                any = true;
                for (u, &f) in union.iter_mut().zip(&cell.row) {
                    *u |= f;
                }
            }
        }
        if !any {
            tick(live.len());
            continue;
        }
        let y = driving.y(j);
        // Every center's kernel has the task's constants: any one fills
        // the driving candidates' lanes.
        if let Some((_, c)) = live.first() {
            c.kernel.pre_row(y, xs, union, pre);
        }
        tick(live.iter().filter(|(_, c)| !c.active).count());
        for (_, cell) in live.iter_mut().filter(|(_, c)| c.active) {
            cell.kernel.row_where(y, xs, &cell.row, pre, out);
            cell.take_row(driving, j, nx, out, &limit, rank_by, control)?;
            if control.is_cancelled() {
                // A row cut short: not counted.
                return Ok(());
            }
            tick(1);
        }
    }
    for (m, cell) in live {
        cells[m] = cell.finish(task, sampler, driving, rank_by, control)?;
    }
    Ok(())
}

impl Cell<'_> {
    /// The branch-free samples of row `j` (the kernel's lanes in `out`).
    #[allow(clippy::too_many_arguments)]
    fn take_row(
        &mut self,
        driving: &Grid,
        j: usize,
        nx: usize,
        out: &RowOut,
        limit: &CosBand,
        rank_by: RankBy,
        control: &Control<'_>,
    ) -> Result<()> {
        let by_transmission = rank_by == RankBy::Transmission;
        for (i, _) in self.row.iter().enumerate().filter(|(_, f)| **f) {
            // A sample with obstacles can take milliseconds (its clearance
            // over the travel), a row of them seconds.
            if control.is_cancelled() {
                return Ok(());
            }
            let p = driving.point(i, j);
            // Acceptable samples with their score where it may reach the
            // run of the best (by transmission: elsewhere no `acos` is
            // taken).
            let ask = AtlasAsk {
                limit,
                rank_by,
                reach: &self.reach,
            };
            let seen = self.kernel.atlas_sample(out, i, p, &ask);
            let Some(acceptable) = seen else {
                continue;
            };
            self.cell.branch_free += 1;
            let Some(score) = acceptable else {
                continue;
            };
            self.cell.count += 1;
            let Some(score) = score.filter(|s| !s.is_nan()) else {
                continue;
            };
            if score > self.top {
                self.top = score;
                let top = self.top;
                self.run.retain(|&(_, v)| tied(top, v));
                if by_transmission {
                    self.reach = CosBand::new(top - tolerance::RANK_TIE - TOP_SLACK);
                }
            }
            if tied(self.top, score) {
                try_push(
                    &mut self.run,
                    "the best driving pivots",
                    (j * nx + i, score),
                )?;
            }
        }
        Ok(())
    }

    /// The cell once every row is seen.
    fn finish(
        self,
        task: &Task,
        sampler: &Sampler<'_>,
        driving: &Grid,
        rank_by: RankBy,
        control: &Control<'_>,
    ) -> Result<AtlasCell> {
        let mut cell = self.cell;
        cell.best = best(task, self.filemon, sampler, driving, self.run);
        if cell.best.is_none() && cell.count > 0 {
            // No candidate of the first run has a linkage (not seen in
            // practice): rank every acceptable sample, as `best_pivots` does.
            let all = all_acceptable(self.filemon, sampler, driving, rank_by, control)?;
            cell.best = best(task, self.filemon, sampler, driving, all);
        }
        Ok(cell)
    }
}

/// Checks that a ranking has a score (not the Pareto front or the margin).
pub(crate) fn check_scored(rank_by: RankBy, what: &'static str) -> Result<()> {
    if rank_by.score(1.0, 1.0, 1.0).is_none() {
        return Err(InvalidInput::UnknownName {
            what,
            expected: "\"balanced\", \"transmission\" or \"compact\" (a ranking with a score)",
            found: rank_by.as_str().to_owned(),
        }
        .into());
    }
    Ok(())
}

/// Radians below the best run's score under which a sample's score (an
/// f32, rounded by at most 1e-7 rad) can neither tie nor lead.
const TOP_SLACK: f64 = tolerance::TOP_SLACK;

/// Whether `score` ties with the best score `top` (as `best_pivots` groups
/// runs: the difference in `f64`).
#[inline]
fn tied(top: f64, score: f64) -> bool {
    (top - score).abs() <= tolerance::RANK_TIE
}

/// Every acceptable sample with a score, `(k, score)`.
/// Empty once `control` is cancelled (the atlas is then cancelled too).
///
/// # Errors
///
/// [`Error::OutOfMemory`].
fn all_acceptable(
    filemon: &Filemon,
    sampler: &Sampler<'_>,
    driving: &Grid,
    rank_by: RankBy,
    control: &Control<'_>,
) -> Result<Vec<(usize, f64)>> {
    let driven = filemon.driven_crank("the atlas")?;
    let c = sampler.fixed_pivots(&driven);
    let branch = BranchRows::new(filemon, driving)?;
    let mut row = try_vec("a driving row", driving.nx(), false)?;
    let mut out = Vec::new();
    for j in 0..driving.ny() {
        if control.is_cancelled() {
            return Ok(Vec::new());
        }
        branch.row(j, &mut row);
        for (i, _) in row.iter().enumerate().filter(|(_, f)| **f) {
            let s = sampler.driving_sample(driving.point(i, j), driven, &c, true);
            if let (true, Some(score)) = (s.acceptable, sample_score(&s, rank_by)) {
                try_push(
                    &mut out,
                    "the acceptable driving pivots",
                    (j * driving.nx() + i, score),
                )?;
            }
        }
    }
    Ok(out)
}

/// The first pivot `best_pivots(Ranking::new(1, rank_by))` takes from
/// the candidates `cand` (`(k, score)`, in sample order): sorted by score,
/// runs of ties by size ratio then margin, the first with a linkage.
fn best(
    task: &Task,
    filemon: &Filemon,
    sampler: &Sampler<'_>,
    driving: &Grid,
    mut cand: Vec<(usize, f64)>,
) -> Option<AtlasBest> {
    let driven = filemon.driven_crank("the atlas").ok()?;
    let c = sampler.fixed_pivots(&driven);
    let nx = driving.nx();
    cand.sort_by(|a, b| b.1.total_cmp(&a.1));
    let mut i = 0;
    while i < cand.len() {
        let mut j = i + 1;
        while j < cand.len() && tied(cand[i].1, cand[j].1) {
            j += 1;
        }
        let mut run: Vec<(usize, f32, f64, f64)> = cand[i..j]
            .iter()
            .map(|&(k, score)| {
                let p = driving.point(k % nx, k / nx);
                let size = sampler.driving_sample(p, driven, &c, true).size_ratio;
                (k, size, filemon.margin_at(p), score)
            })
            .collect();
        run.sort_by(|a, b| tie_order((a.1, a.2), (b.1, b.2)));
        for (k, _, margin, score) in run {
            let p = driving.point(k % nx, k / nx);
            let linkage = task
                .dyad_from_center(p)
                .and_then(|d| task.four_bar(&d, &driven));
            if linkage.is_ok() {
                let s = sampler.driving_sample(p, driven, &c, true);
                return Some(AtlasBest {
                    driving: p,
                    index: (k / nx, k % nx),
                    min_transmission_rad: s.min_transmission_rad,
                    link_ratio: s.link_ratio,
                    margin,
                    size_ratio: s.size_ratio,
                    score,
                });
            }
        }
        i = j;
    }
    None
}
