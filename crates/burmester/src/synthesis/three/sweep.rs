//! The dense grid branch sweep: classify every candidate driving fixed
//! pivot on a grid over the center-point plane.
//!
//! # The `conic` method, fast
//!
//! Along a row the two transformed Filemon curves are quadratics in `x`,
//! `g(x) = x (A x + l) + k`, so each changes sign at most twice. The sweep
//! finds those roots in closed form, bounds how far rounding can move them
//! (and the sign of a point evaluation near them), evaluates only the
//! samples within that band point by point, and fills the runs between them
//! with one value each, at the speed of `memset`. Every sample gets exactly
//! the bits [`Filemon::classify`] with [`Method::Conic`] gives at the same
//! point (the point evaluation uses the same row terms); there is no
//! incremental evaluation, so nothing drifts along a row. Rows where the
//! roots are ill-conditioned (a near double root) are evaluated point by
//! point. [`Filemon::branch_map_pointwise_into`] is the straightforward
//! point-by-point kernel, kept for checking and benchmarking.
//!
//! Work is split over blocks of rows by the [`engine`](crate::engine),
//! which follows progress and cancellation; nothing is allocated inside the
//! loops.
//!
//! # Defined answers
//!
//! A sample is `true` only when it is strictly branch-free:
//!
//! * `conic`: both conic values nonzero and of one sign, and the point not
//!   within [`tolerance::POINT`] of a
//!   pole or `C0` (where all the curves meet). A point on a curve is `false`. On the pole circle the
//!   conic signs are defined and used as they are (the pole circle splits no
//!   region).
//! * `direct` and `simulate`: `false` where the circle point does not exist
//!   (at a pole, exactly on the pole circle), where a branch sign is zero
//!   (a toggle at a design pose), and, for `simulate`, where a link of the
//!   linkage would have zero length.
//! * When every driving circle point is defective
//!   ([`Filemon::all_defective`]) the whole map is `false`.

use nalgebra::Point2;

use crate::engine::{Control, for_rows};
use crate::error::finite_point;
use crate::tolerance;

use crate::error::{Result, try_collect};
use crate::geom::FAR;
use crate::geom::{Conic, Grid};
use crate::synthesis::three::{Filemon, Method};

/// The two conics' shared local frame, with the local coordinates of the
/// grid's columns.
struct Local {
    oy: f64,
    s: f64,
    xs: Vec<f64>,
}

impl Local {
    fn new(c: &Conic, grid: &Grid) -> Result<Self> {
        let (o, s) = c.frame();
        let xs = (0..grid.nx()).map(|i| (grid.x(i) - o.x) / s);
        Ok(Local {
            oy: o.y,
            s,
            xs: try_collect("a row's abscissae", grid.nx(), xs)?,
        })
    }

    #[inline]
    fn y(&self, grid: &Grid, j: usize) -> f64 {
        (grid.y(j) - self.oy) / self.s
    }

    /// Whether row `j` has a sample beyond [`FAR`] (local units): such rows
    /// are classified point by point, as [`Filemon::classify`] scales them.
    fn far_row(&self, grid: &Grid, j: usize) -> bool {
        let near = |v: f64| v.abs() <= FAR;
        let (first, last) = (self.xs[0], self.xs[self.xs.len() - 1]);
        !(near(self.y(grid, j)) && near(first) && near(last))
    }
}

/// The local x of a row's columns, with where to look for a value among
/// them: the columns are evenly spaced, so the index of a value is known
/// to within rounding without a binary search.
struct Columns<'a> {
    xs: &'a [f64],
    x0: f64,
    /// Columns per local unit (zero for fewer than two columns).
    per_unit: f64,
}

impl<'a> Columns<'a> {
    fn new(xs: &'a [f64]) -> Self {
        let n = xs.len();
        let per_unit = if n < 2 {
            0.0
        } else {
            (n - 1) as f64 / (xs[n - 1] - xs[0])
        };
        Columns {
            xs,
            x0: xs.first().copied().unwrap_or(0.0),
            per_unit: if per_unit.is_finite() { per_unit } else { 0.0 },
        }
    }

    /// `xs.partition_point(pred)` for a `pred` that holds on every column
    /// before `i` (a walk up from `i`).
    #[inline]
    fn walk_from(&self, mut i: usize, pred: impl Fn(f64) -> bool) -> usize {
        while i < self.xs.len() && pred(self.xs[i]) {
            i += 1;
        }
        i
    }

    /// `xs.partition_point(pred)` for a `pred` that holds below `v` and
    /// fails above it (`x < v` or `x <= v`): the same index, found from
    /// the estimate `(v - x0) per_unit` and a walk of the few columns that
    /// rounding puts on the wrong side of it.
    #[inline]
    fn partition_point(&self, v: f64, pred: impl Fn(f64) -> bool) -> usize {
        let n = self.xs.len();
        // The cast saturates (NaN to 0); the walk corrects any estimate.
        let mut i = (((v - self.x0) * self.per_unit) as usize).min(n);
        while i > 0 && !pred(self.xs[i - 1]) {
            i -= 1;
        }
        while i < n && pred(self.xs[i]) {
            i += 1;
        }
        i
    }
}

/// Whether two conic values make a branch-free point.
#[inline(always)]
fn free(g1: f64, g2: f64) -> bool {
    (g1 > 0.0 && g2 > 0.0) | (g1 < 0.0 && g2 < 0.0)
}

/// One row of one conic: `g(x) = x (a x + l) + k`.
#[derive(Clone, Copy)]
struct RowQuad {
    a: f64,
    l: f64,
    k: f64,
}

impl RowQuad {
    #[inline(always)]
    fn eval(&self, x: f64) -> f64 {
        x * (self.a * x + self.l) + self.k
    }
}

/// Local-x intervals around the roots of one row quadratic, outside which
/// a point evaluation has the sign of the exact quadratic; `None` when the
/// row must be evaluated point by point.
fn danger(c: &Conic, q: RowQuad, y: f64, out: &mut [(f64, f64); 2]) -> Option<usize> {
    const K: f64 = tolerance::SWEEP_BAND_EPS * f64::EPSILON;
    let RowQuad { a, l, k } = q;
    let width = |r: f64| {
        let slope = (2.0 * a * r + l).abs();
        let w = K * c.row_magnitude(r, y) / slope;
        (r.is_finite() && w.is_finite()).then_some((r - w, r + w))
    };
    if a == 0.0 {
        if l == 0.0 {
            return Some(0);
        }
        out[0] = width(-k / l)?;
        return Some(1);
    }
    let disc = l * l - 4.0 * a * k;
    let inv_a = 1.0 / a;
    let v = -0.5 * l * inv_a;
    // Below this the sign between the roots (or whether they exist) is
    // within rounding: |g(vertex)| = |disc| / (4 |a|) against K M(vertex).
    let tol = K * (l * l + 4.0 * (a * k).abs()).max(4.0 * a.abs() * c.row_magnitude(v, y));
    if disc < -tol {
        return Some(0);
    }
    if disc <= tol {
        // Near a double root: both roots lie within sqrt(tol)/|a| of the
        // vertex; cover that and the rounding band around it.
        let half = tol.sqrt() / a.abs() + (K * c.row_magnitude(v, y) / a.abs()).sqrt();
        if !(v.is_finite() && half.is_finite()) {
            return None;
        }
        out[0] = (v - half, v + half);
        return Some(1);
    }
    let sq = disc.sqrt();
    let qq = -0.5 * (l + l.signum() * sq);
    // The slope |2 a r + l| at either root is sqrt(disc).
    let per_magnitude = K / sq;
    let band = |r: f64| {
        let w = c.row_magnitude(r, y) * per_magnitude;
        (r.is_finite() && w.is_finite()).then_some((r - w, r + w))
    };
    out[0] = band(qq * inv_a)?;
    out[1] = band(k / qq)?;
    Some(2)
}

/// The `conic` branch map of one Filemon over a grid, one row at a time:
/// row `j` holds exactly the bits of row `j` of
/// [`Filemon::branch_map_into`] with [`Method::Conic`] (the same kernel),
/// without allocating the map (the pivot-pair atlas reduces many maps).
pub(crate) struct BranchRows<'a> {
    filemon: &'a Filemon,
    grid: &'a Grid,
    conics: Option<([Conic; 2], Local)>,
}

impl<'a> BranchRows<'a> {
    pub(crate) fn new(filemon: &'a Filemon, grid: &'a Grid) -> Result<Self> {
        let conics = match filemon.conics() {
            Some([ca, cb]) => Some(([ca, cb], Local::new(&ca, grid)?)),
            None => None,
        };
        Ok(BranchRows {
            filemon,
            grid,
            conics,
        })
    }

    /// Whether some sample can be branch-free (not every circle point is
    /// defective).
    pub(crate) fn any(&self) -> bool {
        self.conics.is_some()
    }

    /// Row `j` into `row` (`grid.nx()` flags).
    pub(crate) fn row(&self, j: usize, row: &mut [bool]) {
        let Some(([ca, cb], local)) = &self.conics else {
            row.fill(false);
            return;
        };
        if local.far_row(self.grid, j) {
            self.filemon.far_row_map(self.grid, j, row);
            return;
        }
        conic_row(ca, cb, local.y(self.grid, j), &local.xs, row);
        self.filemon.clear_special_points(self.grid, j, row);
    }
}

impl Filemon {
    /// The branch map over `grid` by `method`: one flag per sample,
    /// row-major, `true` where strictly branch-free (module docs).
    pub fn branch_map(&self, grid: &Grid, method: Method) -> Vec<bool> {
        let mut out = vec![false; grid.len()];
        // The buffer fits and nothing cancels: this cannot fail.
        let _ = self.branch_map_into(grid, method, &mut out, &Control::new());
        out
    }

    /// [`branch_map`](Self::branch_map) into a buffer of `grid.len()`
    /// flags, following `control`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::LengthMismatch`](crate::InvalidInput::LengthMismatch)
    /// when the buffer's length is not `grid.len()`;
    /// [`Error::Cancelled`](crate::Error::Cancelled) when `control` stopped
    /// it (the buffer then holds a partial map).
    pub fn branch_map_into(
        &self,
        grid: &Grid,
        method: Method,
        out: &mut [bool],
        control: &Control<'_>,
    ) -> Result<()> {
        grid.check_len(out.len())?;
        let Some([ca, cb]) = self.conics() else {
            return for_rows(grid.nx(), out, control, |_, row| row.fill(false));
        };
        match method {
            Method::Conic => {
                let local = Local::new(&ca, grid)?;
                for_rows(grid.nx(), out, control, |j, row| {
                    if local.far_row(grid, j) {
                        self.far_row_map(grid, j, row);
                        return;
                    }
                    conic_row(&ca, &cb, local.y(grid, j), &local.xs, row);
                    self.clear_special_points(grid, j, row);
                })
            }
            Method::Direct | Method::Simulate => for_rows(grid.nx(), out, control, |j, row| {
                for (i, o) in row.iter_mut().enumerate() {
                    *o = self
                        .classify(grid.point(i, j), method)
                        .is_ok_and(|c| c.is_free());
                }
            }),
        }
    }

    /// The `conic` method evaluated point by point (the straightforward
    /// kernel). Gives exactly the answers of
    /// [`branch_map_into`](Self::branch_map_into) with [`Method::Conic`];
    /// kept for checking and benchmarking.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::LengthMismatch`](crate::InvalidInput::LengthMismatch)
    /// when the buffer's length is not `grid.len()`.
    pub fn branch_map_pointwise_into(&self, grid: &Grid, out: &mut [bool]) -> Result<()> {
        grid.check_len(out.len())?;
        let Some([ca, cb]) = self.conics() else {
            out.fill(false);
            return Ok(());
        };
        let local = Local::new(&ca, grid)?;
        for_rows(grid.nx(), out, &Control::new(), |j, row| {
            if local.far_row(grid, j) {
                self.far_row_map(grid, j, row);
                return;
            }
            pointwise_row(&ca, &cb, local.y(grid, j), &local.xs, row);
            self.clear_special_points(grid, j, row);
        })
    }

    /// Row `j` by [`Filemon::classify`], point by point (far rows).
    fn far_row_map(&self, grid: &Grid, j: usize, row: &mut [bool]) {
        for (i, o) in row.iter_mut().enumerate() {
            *o = self.classify_conic(grid.point(i, j)).is_free();
        }
    }

    /// Sets the samples of row `j` that lie at a pole or at `C0` to
    /// `false` (they are on every curve), as [`Filemon::classify`] does.
    fn clear_special_points(&self, grid: &Grid, j: usize, row: &mut [bool]) {
        self.for_special_columns(grid, j, |i| row[i] = false);
    }

    /// Calls `f(i)` for each column `i` of row `j` whose sample lies within
    /// [`tolerance::POINT`] of a pole or `C0`.
    fn for_special_columns(&self, grid: &Grid, j: usize, mut f: impl FnMut(usize)) {
        let tol = tolerance::POINT * self.task().scale();
        let y = grid.y(j);
        let xmin = grid.viewport().xmin;
        for p in self.special_points() {
            if (p.y - y).abs() > tol {
                continue;
            }
            // Candidate columns around p.x (x_i is monotone in i), widened
            // by how far rounding can move x_i (many columns when the grid
            // is finer than the spacing of doubles there).
            let slack = (4.0 * f64::EPSILON * (xmin.abs() + p.x.abs() + tol) / grid.dx()).ceil();
            let lo = ((p.x - tol - xmin) / grid.dx() - 0.5).floor() - 1.0 - slack;
            let hi = ((p.x + tol - xmin) / grid.dx() - 0.5).ceil() + 2.0 + slack;
            let (lo, hi) = (
                lo.max(0.0) as usize,
                hi.clamp(0.0, grid.nx() as f64) as usize,
            );
            for i in lo..hi {
                if (grid.x(i) - p.x).abs() <= tol {
                    f(i);
                }
            }
        }
    }

    /// The signed margin map over `grid`: at each sample, the first-order
    /// distance to the nearer of the two transformed Filemon curves,
    ///
    /// ```text
    /// m = +- min(|g_a| / |grad g_a|, |g_b| / |grad g_b|)
    /// ```
    ///
    /// positive where branch-free, negative (or `-0.0` on a curve)
    /// elsewhere, in the plane's units, as `f32`. Its sign is the branch map
    /// even where the distance underflows (a free sample is then the
    /// smallest positive `f32`). For contour plots and for
    /// ranking pivots by their distance to a defect. When every circle
    /// point is defective the map is `-inf` everywhere (there is no
    /// boundary).
    pub fn margin_map(&self, grid: &Grid) -> Vec<f32> {
        let mut out = vec![0.0; grid.len()];
        // The buffer fits and nothing cancels: this cannot fail.
        let _ = self.fill_margin_map(grid, &mut out, &Control::new());
        out
    }

    /// [`margin_map`](Self::margin_map) into a buffer of `grid.len()`
    /// values, following `control`.
    ///
    /// # Errors
    ///
    /// As [`branch_map_into`](Self::branch_map_into).
    pub fn margin_map_into(
        &self,
        grid: &Grid,
        out: &mut [f32],
        control: &Control<'_>,
    ) -> Result<()> {
        grid.check_len(out.len())?;
        self.fill_margin_map(grid, out, control)
    }

    fn fill_margin_map(&self, grid: &Grid, out: &mut [f32], control: &Control<'_>) -> Result<()> {
        let Some([ca, cb]) = self.conics() else {
            return for_rows(grid.nx(), out, control, |_, row| {
                row.fill(f32::NEG_INFINITY)
            });
        };
        let local = Local::new(&ca, grid)?;
        for_rows(grid.nx(), out, control, |j, row| {
            if local.far_row(grid, j) {
                for (i, o) in row.iter_mut().enumerate() {
                    *o = margin_f32(self.margin_at(grid.point(i, j)));
                }
                return;
            }
            margin_row(&ca, &cb, local.y(grid, j), local.s, &local.xs, row);
            self.for_special_columns(grid, j, |i| row[i] = -0.0);
        })
    }

    /// The signed margin at one point (see [`margin_map`](Self::margin_map)).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`](crate::InvalidInput::NotFinite) for a
    /// non-finite point.
    pub fn margin(&self, p: Point2<f64>) -> Result<f64> {
        finite_point(["driving center x", "driving center y"], p)?;
        Ok(self.margin_at(p))
    }

    /// [`margin`](Self::margin) of a finite point.
    pub(crate) fn margin_at(&self, p: Point2<f64>) -> f64 {
        let Some([ca, cb]) = self.conics() else {
            return f64::NEG_INFINITY;
        };
        if self.at_special_point(p) {
            return -0.0;
        }
        let (o, s) = ca.frame();
        let v = (p - o) / s;
        let m = v.x.abs().max(v.y.abs());
        if m > FAR || m.is_nan() {
            // Far away: the scaled evaluations (see `Conic::evaluate`).
            let d = ca.distance_estimate(p).min(cb.distance_estimate(p));
            return signed_margin(d, free(ca.evaluate(p), cb.evaluate(p)));
        }
        margin_at(&ca, &cb, v.x, v.y, s)
    }
}

fn quads(ca: &Conic, cb: &Conic, y: f64) -> (RowQuad, RowQuad) {
    let (a, l, k) = ca.row(y);
    let (a2, l2, k2) = cb.row(y);
    (
        RowQuad { a, l, k },
        RowQuad {
            a: a2,
            l: l2,
            k: k2,
        },
    )
}

#[inline]
fn pointwise_row(ca: &Conic, cb: &Conic, y: f64, xs: &[f64], out: &mut [bool]) {
    let (qa, qb) = quads(ca, cb, y);
    for (o, &x) in out.iter_mut().zip(xs) {
        *o = free(qa.eval(x), qb.eval(x));
    }
}

/// One row by runs (module docs).
fn conic_row(ca: &Conic, cb: &Conic, y: f64, xs: &[f64], out: &mut [bool]) {
    let (qa, qb) = quads(ca, cb, y);
    let (mut ra, mut rb) = ([(0.0, 0.0); 2], [(0.0, 0.0); 2]);
    let (Some(na), Some(nb)) = (danger(ca, qa, y, &mut ra), danger(cb, qb, y, &mut rb)) else {
        pointwise_row(ca, cb, y, xs, out);
        return;
    };
    // The samples inside each band, `[first >= lo, first > hi)` (exact
    // partition points of the columns; empty where no sample falls inside,
    // and a run still ends there). A sample outside every band has the
    // exact sign of both quadratics, which does not change between two
    // bands, so a run between them takes the value of its first sample.
    let cols = Columns::new(xs);
    let mut zones = [(0usize, 0usize); 4];
    let mut n = 0;
    for &(lo, hi) in ra[..na].iter().chain(&rb[..nb]) {
        let i0 = cols.partition_point(lo, |x| x < lo);
        zones[n] = (i0, cols.walk_from(i0, |x| x <= hi));
        n += 1;
    }
    let zones = &mut zones[..n];
    zones.sort_unstable_by_key(|z| z.0);
    let mut pos = 0;
    let mut k = 0;
    while k < zones.len() {
        let (start, mut end) = zones[k];
        k += 1;
        while k < zones.len() && zones[k].0 <= end {
            end = end.max(zones[k].1);
            k += 1;
        }
        if start > pos {
            let x = xs[pos];
            out[pos..start].fill(free(qa.eval(x), qb.eval(x)));
        }
        let from = start.max(pos);
        if end > from {
            for (o, &x) in out[from..end].iter_mut().zip(&xs[from..end]) {
                *o = free(qa.eval(x), qb.eval(x));
            }
        }
        pos = pos.max(end);
    }
    if pos < xs.len() {
        let x = xs[pos];
        out[pos..].fill(free(qa.eval(x), qb.eval(x)));
    }
}

/// One conic along a row, for the margin: value and gradient.
#[derive(Clone, Copy)]
struct RowGrad {
    q: RowQuad,
    /// `dq/dy = b x + gy0`.
    b: f64,
    gy0: f64,
}

impl RowGrad {
    fn new(c: &Conic, y: f64) -> Self {
        let [_, b, cc, _, e, _] = c.local_coefficients().0;
        let (a, l, k) = c.row(y);
        RowGrad {
            q: RowQuad { a, l, k },
            b,
            gy0: 2.0 * cc * y + e,
        }
    }

    /// `(|q| / |grad q|, q)`; the distance is 0 on the curve.
    #[inline(always)]
    fn dist(&self, x: f64) -> (f64, f64) {
        let g = self.q.eval(x);
        let gx = 2.0 * self.q.a * x + self.q.l;
        let gy = self.b * x + self.gy0;
        // Local coordinates are of order one: no overflow in the squares.
        let d = g.abs() / (gx * gx + gy * gy).sqrt();
        (if g == 0.0 { 0.0 } else { d }, g)
    }
}

#[inline(always)]
fn margin_at(ca: &Conic, cb: &Conic, x: f64, y: f64, s: f64) -> f64 {
    margin_of(&RowGrad::new(ca, y), &RowGrad::new(cb, y), x, s)
}

#[inline(always)]
fn margin_of(ra: &RowGrad, rb: &RowGrad, x: f64, s: f64) -> f64 {
    let (da, ga) = ra.dist(x);
    let (db, gb) = rb.dist(x);
    signed_margin(da.min(db) * s, free(ga, gb))
}

/// `+d` where free, `-d` elsewhere; a free point's margin stays positive
/// when `d` underflows to zero (its sign is the branch map).
#[inline(always)]
fn signed_margin(d: f64, is_free: bool) -> f64 {
    if is_free {
        d.max(f64::from_bits(1))
    } else {
        -d
    }
}

/// A margin as `f32`, keeping its sign: a positive margin below the
/// smallest `f32` becomes the smallest positive `f32`, a negative one `-0.0`.
#[inline(always)]
fn margin_f32(m: f64) -> f32 {
    let v = m as f32;
    if m > 0.0 { v.max(f32::from_bits(1)) } else { v }
}

fn margin_row(ca: &Conic, cb: &Conic, y: f64, s: f64, xs: &[f64], out: &mut [f32]) {
    let (ra, rb) = (RowGrad::new(ca, y), RowGrad::new(cb, y));
    for (o, &x) in out.iter_mut().zip(xs) {
        *o = margin_f32(margin_of(&ra, &rb, x, s));
    }
}

#[cfg(test)]
mod tests {
    use super::Columns;
    use proptest::prelude::*;

    /// Columns as `Local` makes them: `(x_i - o) / s` on a grid.
    fn columns(x0: f64, dx: f64, n: usize, o: f64, s: f64) -> Vec<f64> {
        (0..n)
            .map(|i| (x0 + (i as f64 + 0.5) * dx - o) / s)
            .collect()
    }

    fn check(xs: &[f64], v: f64) {
        let c = Columns::new(xs);
        assert_eq!(
            c.partition_point(v, |x| x < v),
            xs.partition_point(|&x| x < v),
            "x < {v}"
        );
        assert_eq!(
            c.partition_point(v, |x| x <= v),
            xs.partition_point(|&x| x <= v),
            "x <= {v}"
        );
    }

    #[test]
    fn the_index_of_a_value_is_the_binary_search_s() {
        // Values on, between and beyond the columns, and grids finer than
        // the spacing of doubles (runs of equal columns).
        for xs in [
            columns(-8.0, 16.0 / 4096.0, 4096, 0.3, 1.7),
            columns(1e8, 1e-9, 300, 0.0, 1.0),
            columns(-1.0, 0.5, 1, 0.0, 1.0),
            columns(-1.0, 0.5, 2, 0.0, 1.0),
            Vec::new(),
        ] {
            let mut vs = vec![0.0, f64::INFINITY, f64::NEG_INFINITY, 1e300, -1e300];
            for (i, &x) in xs.iter().enumerate().step_by(7) {
                vs.extend([x, x.next_up(), x.next_down(), x + 1e-3 * (i as f64)]);
            }
            for v in vs {
                check(&xs, v);
            }
        }
    }

    proptest! {
        #[test]
        fn the_index_matches_on_random_grids(
            x0 in -1e3f64..1e3,
            dx in 1e-6f64..10.0,
            n in 0usize..5000,
            o in -1e3f64..1e3,
            s in 1e-3f64..1e3,
            t in -0.2f64..1.2,
        ) {
            let xs = columns(x0, dx, n, o, s);
            let (lo, hi) = ((x0 - o) / s, (x0 + n as f64 * dx - o) / s);
            let v = lo + t * (hi - lo);
            check(&xs, v);
            if let Some(&x) = xs.get((t.clamp(0.0, 1.0) * n as f64) as usize) {
                check(&xs, x);
            }
        }
    }
}
