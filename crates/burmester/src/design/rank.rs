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
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum RankBy {
    /// Acceptable candidates by the minimum transmission angle over the
    /// travel, ties (within [`tolerance::RANK_TIE`]) by the margin.
    #[default]
    Transmission,
    /// Branch-free candidates (acceptable or not) by their margin to the
    /// nearest branch-defect boundary: the fallback when nothing is
    /// acceptable.
    Margin,
}

impl RankBy {
    /// `"transmission"` or `"margin"`.
    pub fn as_str(self) -> &'static str {
        match self {
            RankBy::Transmission => "transmission",
            RankBy::Margin => "margin",
        }
    }
}

impl FromStr for RankBy {
    type Err = InvalidInput;

    fn from_str(s: &str) -> Result<Self, InvalidInput> {
        match s.to_ascii_lowercase().as_str() {
            "transmission" => Ok(RankBy::Transmission),
            "margin" => Ok(RankBy::Margin),
            _ => Err(InvalidInput::UnknownName {
                what: "ranking",
                expected: "\"transmission\" or \"margin\"",
                found: s.to_owned(),
            }),
        }
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
    /// The `acceptable` column.
    pub acceptable: &'a [bool],
}

impl SolutionMap {
    /// The columns a ranking reads.
    pub fn rank_columns(&self) -> RankColumns<'_> {
        let c = &self.columns;
        RankColumns {
            valid: &c.valid,
            branch_free: &c.branch_free,
            min_transmission_rad: &c.min_transmission_rad,
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

    /// The `k` best candidates, best first, from the map's columns.
    ///
    /// With [`RankBy::Transmission`] the candidates are the acceptable
    /// samples, scored by the minimum transmission angle over the travel;
    /// ties (within [`tolerance::RANK_TIE`]) go to the larger margin to the
    /// nearest branch-defect boundary. With [`RankBy::Margin`] they are the
    /// valid, branch-free samples, scored by their margin. Candidates
    /// closer than `min_separation` to a better one are skipped, so the
    /// list offers distinct options (default, `None`: 2% of the viewport's
    /// diagonal).
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
        for (name, len) in [
            ("valid", columns.valid.len()),
            ("branch_free", columns.branch_free.len()),
            ("min_transmission_rad", columns.min_transmission_rad.len()),
            ("acceptable", columns.acceptable.len()),
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
        let margins = Margins::new(self, columns.branch_free);
        let mut out: Vec<Pivot> = Vec::new();
        let take = |s: usize, margin: f64, out: &mut Vec<Pivot>| {
            let p = self.point(s);
            if out.iter().any(|q| (q.center - p).norm() < sep) {
                return;
            }
            if let Ok(linkage) = self.linkage(s) {
                let nx = self.grid.nx();
                out.push(Pivot {
                    center: p,
                    index: (s / nx, s % nx),
                    linkage,
                    margin,
                    ranked_by: rank_by,
                });
            }
        };
        match rank_by {
            RankBy::Transmission => {
                let mut cand: Vec<(usize, f32)> = (0..n)
                    .filter(|&s| columns.acceptable[s] && !columns.min_transmission_rad[s].is_nan())
                    .map(|s| (s, columns.min_transmission_rad[s]))
                    .collect();
                cand.sort_by(|a, b| b.1.total_cmp(&a.1));
                let mut i = 0;
                while i < cand.len() && out.len() < k {
                    // A run of equal scores: order by margin.
                    let mut j = i + 1;
                    while j < cand.len()
                        && f64::from(cand[i].1 - cand[j].1).abs() <= tolerance::RANK_TIE
                    {
                        j += 1;
                    }
                    let mut run: Vec<(usize, f64)> = cand[i..j]
                        .iter()
                        .map(|&(s, _)| (s, margins.get(s)))
                        .collect();
                    run.sort_by(|a, b| b.1.total_cmp(&a.1));
                    for (s, margin) in run {
                        if out.len() >= k {
                            break;
                        }
                        take(s, margin, &mut out);
                    }
                    i = j;
                }
            }
            RankBy::Margin => {
                let mut cand: Vec<(usize, f64)> = (0..n)
                    .filter(|&s| columns.valid[s] && columns.branch_free[s])
                    .map(|s| (s, margins.get(s)))
                    .collect();
                cand.sort_by(|a, b| b.1.total_cmp(&a.1));
                for (s, margin) in cand {
                    if out.len() >= k {
                        break;
                    }
                    take(s, margin, &mut out);
                }
            }
        }
        Ok(out)
    }
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
