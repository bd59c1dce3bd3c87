//! Ranking candidate pivots of a solution map, and the margin of a sample
//! to the nearest branch-defect boundary.

use core::str::FromStr;

use nalgebra::Point2;

use crate::design::{MapContext, SolutionMap, Varying};
use crate::error::{InvalidInput, Result, in_range};
use crate::geom::Grid;
use crate::synthesis::SynthesizedFourBar;
use crate::synthesis::three::Filemon;
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
        let s_lower = s.to_ascii_lowercase();
        RankBy::ALL
            .into_iter()
            .find(|r| r.as_str() == s_lower)
            .ok_or_else(|| InvalidInput::UnknownName {
                what: "ranking",
                expected: "\"balanced\", \"transmission\", \"compact\", \"pareto\" or \"margin\"",
                found: s.to_owned(),
            })
    }
}

/// A candidate pivot of a solution map with its linkage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pivot {
    /// The candidate center point.
    pub center: Point2<f64>,
    /// Its sample `(j, i)`: row `j` (for `y_j`), column `i` (for `x_i`).
    pub index: (usize, usize),
    /// The complete linkage, with its figures.
    pub linkage: SynthesizedFourBar,
    /// Its signed margin (see [`MapContext::margin`]).
    pub margin: f64,
    /// The linkage's size relative to the task's
    /// ([`SynthesizedFourBar::size`] over [`Task::span`](crate::Task::span)).
    pub size_ratio: f64,
    /// Its score by the ranking (see [`RankBy::score`]; the margin for
    /// [`RankBy::Margin`], the minimum transmission angle for
    /// [`RankBy::Pareto`]).
    pub score: f64,
    /// What ranked it.
    pub ranked_by: RankBy,
}

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

impl SolutionMap {
    /// The columns a ranking reads.
    pub fn rank_columns(&self) -> RankColumns<'_> {
        let c = &self.columns;
        RankColumns {
            valid: &c.valid,
            branch_free: &c.branch_free,
            min_transmission_rad: &c.min_transmission_rad,
            link_ratio: &c.link_ratio,
            size_ratio: &c.size_ratio,
            acceptable: &c.acceptable,
        }
    }

    /// The signed margin of sample `k` (see [`MapContext::margin`]).
    pub fn margin(&self, k: usize) -> f64 {
        self.context.margin(k, &self.columns.branch_free)
    }

    /// The `k` best candidates, best first (see [`MapContext::best_pivots`]).
    ///
    /// # Errors
    ///
    /// As [`MapContext::best_pivots`].
    pub fn best_pivots(
        &self,
        k: usize,
        min_separation: Option<f64>,
        rank_by: RankBy,
    ) -> Result<Vec<Pivot>> {
        self.context
            .best_pivots(k, min_separation, rank_by, self.rank_columns())
    }

    /// The whole Pareto front of the acceptable candidates over the minimum
    /// transmission angle and the size ratio, from the most compact to the
    /// best transmission: `best_pivots(usize::MAX, Some(0.0),
    /// RankBy::Pareto)`.
    ///
    /// # Errors
    ///
    /// As [`MapContext::best_pivots`].
    pub fn pareto_front(&self) -> Result<Vec<Pivot>> {
        self.best_pivots(usize::MAX, Some(0.0), RankBy::Pareto)
    }
}

impl MapContext {
    /// The signed margin of sample `k`: positive where branch-free,
    /// negative elsewhere. For candidate driving pivots, the first-order
    /// distance to the nearest transformed Filemon curve
    /// ([`Filemon::margin`]); for candidate driven pivots, the distance to
    /// the nearest sample of the other class in `branch_free` (exact
    /// Euclidean, over the whole grid: infinite when there is none).
    pub fn margin(&self, k: usize, branch_free: &[bool]) -> f64 {
        Margins::new(self, branch_free).get(k)
    }

    /// The `k` best candidates, best first, from the map's columns, by
    /// `rank_by` (see [`RankBy`] for the candidates and scores of each
    /// ranking; runs of scores within [`tolerance::RANK_TIE`] go to the
    /// smaller size ratio, then the larger margin). Candidates closer than `min_separation` to a better
    /// one are skipped, so the list offers distinct options (default,
    /// `None`: 2% of the viewport's diagonal); candidates without a
    /// linkage are skipped.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::OutsideRange`] for a negative or non-finite
    /// `min_separation`; [`InvalidInput::LengthMismatch`] for columns of
    /// another length than the grid.
    pub fn best_pivots(
        &self,
        k: usize,
        min_separation: Option<f64>,
        rank_by: RankBy,
        columns: RankColumns<'_>,
    ) -> Result<Vec<Pivot>> {
        let sep = match min_separation {
            Some(s) => in_range("min_separation", s, 0.0, f64::MAX, "")?,
            None => 0.02 * self.grid.viewport().diagonal(),
        };
        let n = self.grid.len();
        columns.check_len(n)?;
        let margins = Margins::new(self, columns.branch_free);
        let span = self.task.span();
        let mut out: Vec<Pivot> = Vec::new();
        rank_samples(
            n,
            rank_by,
            &columns,
            &|s| margins.get(s),
            |s, margin, score| {
                if out.len() >= k {
                    return false;
                }
                let p = self.point(s);
                if out.iter().any(|q| (q.center - p).norm() < sep) {
                    return true;
                }
                if let Ok(linkage) = self.linkage(s) {
                    let nx = self.grid.nx();
                    out.push(Pivot {
                        center: p,
                        index: (s / nx, s % nx),
                        linkage,
                        margin,
                        size_ratio: linkage.size() / span,
                        score,
                        ranked_by: rank_by,
                    });
                }
                out.len() < k
            },
        );
        Ok(out)
    }
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
/// to `take(sample, margin, score)`, which returns whether it wants more.
/// Runs of scores within [`tolerance::RANK_TIE`] are offered by
/// [`tie_order`] (the smaller size ratio, then the larger `margin`).
pub(crate) fn rank_samples(
    n: usize,
    rank_by: RankBy,
    columns: &RankColumns<'_>,
    margin: &dyn Fn(usize) -> f64,
    mut take: impl FnMut(usize, f64, f64) -> bool,
) {
    match rank_by {
        RankBy::Margin => {
            let mut cand: Vec<(usize, f64)> = (0..n)
                .filter(|&s| columns.valid[s] && columns.branch_free[s])
                .map(|s| (s, margin(s)))
                .collect();
            cand.sort_by(|a, b| b.1.total_cmp(&a.1));
            for (s, m) in cand {
                if !take(s, m, m) {
                    return;
                }
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
            // By size, ties by the better transmission: a candidate is
            // on the front when it transmits better than every smaller
            // (or as small and listed before) one.
            cand.sort_by(|a, b| a.1.total_cmp(&b.1).then(b.2.total_cmp(&a.2)));
            let mut best = f32::NEG_INFINITY;
            for (s, _, mu) in cand {
                if mu > best {
                    best = mu;
                    if !take(s, margin(s), f64::from(mu)) {
                        return;
                    }
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
                // A run of equal scores: the smaller, then the wider
                // margin first.
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
                    if !take(s, m, score) {
                        return;
                    }
                }
                i = j;
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

/// The margins of a map's samples, computing what they share once.
struct Margins<'a> {
    context: &'a MapContext,
    branch_free: &'a [bool],
    filemon: Option<Filemon>,
    distances: core::cell::OnceCell<Vec<f64>>,
}

impl<'a> Margins<'a> {
    fn new(context: &'a MapContext, branch_free: &'a [bool]) -> Self {
        let filemon = match context.varying {
            Varying::Driving { driven } => Filemon::new(&context.task, driven).ok(),
            Varying::Driven { .. } => None,
        };
        Margins {
            context,
            branch_free,
            filemon,
            distances: core::cell::OnceCell::new(),
        }
    }

    fn get(&self, k: usize) -> f64 {
        match self.context.varying {
            Varying::Driving { .. } => self
                .filemon
                .as_ref()
                .map_or(f64::NEG_INFINITY, |f| f.margin_at(self.context.point(k))),
            Varying::Driven { .. } => self
                .distances
                .get_or_init(|| signed_distances(&self.context.grid, self.branch_free))[k],
        }
    }
}

/// For every sample, the Euclidean distance to the nearest sample of the
/// other class in `flags` (positive where `flags` is true, negative where
/// false, infinite when the other class is empty): the exact distance
/// transform of Felzenszwalb and Huttenlocher, separable over columns and
/// rows, in the grid's units.
pub(crate) fn signed_distances(grid: &Grid, flags: &[bool]) -> Vec<f64> {
    let (nx, ny) = (grid.nx(), grid.ny());
    let mut out = vec![0.0; nx * ny];
    for class in [true, false] {
        // Squared distance from the samples of `class` to the nearest of
        // the other class.
        let mut d: Vec<f64> = flags
            .iter()
            .map(|&f| if f == class { f64::INFINITY } else { 0.0 })
            .collect();
        let mut col = vec![0.0; ny];
        let mut tmp = vec![0.0; ny.max(nx)];
        for i in 0..nx {
            for j in 0..ny {
                col[j] = d[j * nx + i];
            }
            transform_1d(&col, grid.dy(), &mut tmp[..ny]);
            for j in 0..ny {
                d[j * nx + i] = tmp[j];
            }
        }
        for j in 0..ny {
            let row = &mut d[j * nx..(j + 1) * nx];
            transform_1d(row, grid.dx(), &mut tmp[..nx]);
            row.copy_from_slice(&tmp[..nx]);
        }
        for (k, &f) in flags.iter().enumerate() {
            if f == class {
                let r = d[k].sqrt();
                out[k] = if class { r } else { -r };
            }
        }
    }
    out
}

/// `out[p] = min_q (h^2 (p - q)^2 + f[q])`: the lower envelope of
/// parabolas (Felzenszwalb and Huttenlocher), `O(n)`.
fn transform_1d(f: &[f64], h: f64, out: &mut [f64]) {
    let n = f.len();
    let h2 = h * h;
    // Vertices of the envelope's parabolas and the boundaries between them.
    let mut v: Vec<usize> = Vec::with_capacity(n);
    let mut z: Vec<f64> = Vec::with_capacity(n + 1);
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

    #[test]
    fn distance_transform_is_exact() {
        let grid = Grid::from_bounds(0.0, 7.0, 0.0, 3.5, 14, 5).unwrap();
        let mut flags = vec![true; grid.len()];
        for k in [3, 30, 47, 69] {
            flags[k] = false;
        }
        let d = signed_distances(&grid, &flags);
        for k in 0..grid.len() {
            let p = grid.point(k % 14, k / 14);
            let brute = (0..grid.len())
                .filter(|&q| flags[q] != flags[k])
                .map(|q| (grid.point(q % 14, q / 14) - p).norm())
                .fold(f64::INFINITY, f64::min);
            let want = if flags[k] { brute } else { -brute };
            assert!((d[k] - want).abs() < 1e-12, "{k}: {} vs {want}", d[k]);
        }
        let all = signed_distances(&grid, &vec![true; grid.len()]);
        assert!(all.iter().all(|v| *v == f64::INFINITY));
    }
}
