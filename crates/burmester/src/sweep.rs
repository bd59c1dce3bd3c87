//! The dense grid branch sweep: classify every candidate driving fixed
//! pivot on a grid over the center-point plane.
//!
//! # The grid
//!
//! Over a [`Viewport`] `(xmin, xmax, ymin, ymax)` with `nx` by `ny` samples
//! at cell centers,
//!
//! ```text
//! x_i = xmin + (i + 0.5) dx,   dx = (xmax - xmin) / nx
//! y_j = ymin + (j + 0.5) dy,   dy = (ymax - ymin) / ny
//! ```
//!
//! stored row-major, row `j` for `y_j` (so `imshow(map, origin="lower")`
//! shows it the right way up).
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
//! Work is split over blocks of rows with rayon; nothing is allocated inside
//! the loops.
//!
//! # Defined answers
//!
//! A sample is `true` only when it is strictly branch-free:
//!
//! * `conic`: both conic values nonzero and of one sign, and the point not
//!   within [`Task::POINT_TOLERANCE`](crate::Task::POINT_TOLERANCE) of a
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
use rayon::prelude::*;

use crate::conic::{Conic, FAR, Viewport};
use crate::error::{InvalidInput, Result};
use crate::filemon::{Filemon, Method};

/// A grid of sample points at cell centers over a viewport.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    viewport: Viewport,
    nx: usize,
    ny: usize,
    dx: f64,
    dy: f64,
}

impl Grid {
    /// The largest number of samples a grid may have (`2^32`).
    pub const MAX_POINTS: usize = 1 << 32;

    /// A grid of `nx` by `ny` samples over `viewport`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::OutOfRange`] when `nx` or `ny` is zero or the grid
    /// has more than [`Grid::MAX_POINTS`] samples.
    pub fn new(viewport: Viewport, nx: usize, ny: usize) -> Result<Self> {
        for (name, n) in [("nx", nx), ("ny", ny)] {
            if n == 0 {
                return Err(InvalidInput::OutOfRange {
                    name,
                    expected: "must be at least 1",
                    found: n.to_string(),
                }
                .into());
            }
        }
        if nx.checked_mul(ny).is_none_or(|n| n > Self::MAX_POINTS) {
            return Err(InvalidInput::OutOfRange {
                name: "nx * ny",
                expected: "must be at most 2^32 samples",
                found: format!("{nx} * {ny}"),
            }
            .into());
        }
        let (w, h) = viewport.size();
        Ok(Grid {
            viewport,
            nx,
            ny,
            dx: w / nx as f64,
            dy: h / ny as f64,
        })
    }

    /// A grid from the viewport bounds and the sample counts.
    ///
    /// # Errors
    ///
    /// As [`Viewport::new`] and [`Grid::new`].
    pub fn from_bounds(
        xmin: f64,
        xmax: f64,
        ymin: f64,
        ymax: f64,
        nx: usize,
        ny: usize,
    ) -> Result<Self> {
        Self::new(Viewport::new(xmin, xmax, ymin, ymax)?, nx, ny)
    }

    /// The viewport.
    pub fn viewport(&self) -> Viewport {
        self.viewport
    }

    /// Samples per row.
    pub fn nx(&self) -> usize {
        self.nx
    }

    /// Rows.
    pub fn ny(&self) -> usize {
        self.ny
    }

    /// `nx * ny`.
    pub fn len(&self) -> usize {
        self.nx * self.ny
    }

    /// Always false (a grid has at least one sample).
    pub fn is_empty(&self) -> bool {
        false
    }

    /// `x_i = xmin + (i + 0.5) dx`.
    #[inline]
    pub fn x(&self, i: usize) -> f64 {
        self.viewport.xmin + (i as f64 + 0.5) * self.dx
    }

    /// `y_j = ymin + (j + 0.5) dy`.
    #[inline]
    pub fn y(&self, j: usize) -> f64 {
        self.viewport.ymin + (j as f64 + 0.5) * self.dy
    }

    /// The sample `(x_i, y_j)`.
    #[inline]
    pub fn point(&self, i: usize, j: usize) -> Point2<f64> {
        Point2::new(self.x(i), self.y(j))
    }

    /// Rows per rayon task: about 16 K samples, at least 8 tasks when the
    /// grid allows.
    fn rows_per_block(&self) -> usize {
        (16_384 / self.nx).clamp(1, self.ny.div_ceil(8).max(1))
    }

    /// Calls `f(j, row)` for every row `j` of `out` (`nx` values each), in
    /// parallel over blocks of rows.
    pub(crate) fn par_rows<T: Send>(&self, out: &mut [T], f: impl Fn(usize, &mut [T]) + Sync) {
        let rows = self.rows_per_block();
        let nx = self.nx;
        out.par_chunks_mut(nx * rows)
            .enumerate()
            .for_each(|(b, block)| {
                for (r, row) in block.chunks_mut(nx).enumerate() {
                    f(b * rows + r, row);
                }
            });
    }

    fn check_len(&self, len: usize) -> Result<()> {
        if len == self.len() {
            Ok(())
        } else {
            Err(InvalidInput::LengthMismatch {
                name: "output buffer",
                expected: self.len(),
                found: len,
            }
            .into())
        }
    }
}

/// The two conics' shared local frame, with the local coordinates of the
/// grid's columns.
struct Local {
    oy: f64,
    s: f64,
    xs: Vec<f64>,
}

impl Local {
    fn new(c: &Conic, grid: &Grid) -> Self {
        let (o, s) = c.frame();
        Local {
            oy: o.y,
            s,
            xs: (0..grid.nx).map(|i| (grid.x(i) - o.x) / s).collect(),
        }
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
    const K: f64 = 64.0 * f64::EPSILON;
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
    let v = -l / (2.0 * a);
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
    out[0] = width(qq / a)?;
    out[1] = width(k / qq)?;
    Some(2)
}

impl Filemon {
    /// The branch map over `grid` by `method`: one flag per sample,
    /// row-major, `true` where strictly branch-free (module docs).
    pub fn branch_map(&self, grid: &Grid, method: Method) -> Vec<bool> {
        let mut out = vec![false; grid.len()];
        self.fill_branch_map(grid, method, &mut out);
        out
    }

    /// [`branch_map`](Self::branch_map) into a buffer of `grid.len()` flags.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::LengthMismatch`] when the buffer's length is not
    /// `grid.len()`.
    pub fn branch_map_into(&self, grid: &Grid, method: Method, out: &mut [bool]) -> Result<()> {
        grid.check_len(out.len())?;
        self.fill_branch_map(grid, method, out);
        Ok(())
    }

    fn fill_branch_map(&self, grid: &Grid, method: Method, out: &mut [bool]) {
        let Some([ca, cb]) = self.conics() else {
            out.par_chunks_mut(1 << 16).for_each(|c| c.fill(false));
            return;
        };
        match method {
            Method::Conic => {
                let local = Local::new(&ca, grid);
                grid.par_rows(out, |j, row| {
                    if local.far_row(grid, j) {
                        self.far_row_map(grid, j, row);
                        return;
                    }
                    conic_row(&ca, &cb, local.y(grid, j), &local.xs, row);
                    self.clear_special_points(grid, j, row);
                });
            }
            Method::Direct | Method::Simulate => {
                grid.par_rows(out, |j, row| {
                    for (i, o) in row.iter_mut().enumerate() {
                        *o = self
                            .classify(grid.point(i, j), method)
                            .is_ok_and(|c| c.is_free());
                    }
                });
            }
        }
    }

    /// The `conic` method evaluated point by point (the straightforward
    /// kernel). Gives exactly the answers of
    /// [`branch_map_into`](Self::branch_map_into) with [`Method::Conic`];
    /// kept for checking and benchmarking.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::LengthMismatch`] when the buffer's length is not
    /// `grid.len()`.
    pub fn branch_map_pointwise_into(&self, grid: &Grid, out: &mut [bool]) -> Result<()> {
        grid.check_len(out.len())?;
        let Some([ca, cb]) = self.conics() else {
            out.fill(false);
            return Ok(());
        };
        let local = Local::new(&ca, grid);
        grid.par_rows(out, |j, row| {
            if local.far_row(grid, j) {
                self.far_row_map(grid, j, row);
                return;
            }
            pointwise_row(&ca, &cb, local.y(grid, j), &local.xs, row);
            self.clear_special_points(grid, j, row);
        });
        Ok(())
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
    /// [`Task::POINT_TOLERANCE`](crate::Task::POINT_TOLERANCE) of a pole or `C0`.
    fn for_special_columns(&self, grid: &Grid, j: usize, mut f: impl FnMut(usize)) {
        let tol = crate::task::Task::POINT_TOLERANCE * self.task().scale();
        let y = grid.y(j);
        let xmin = grid.viewport().xmin;
        for p in self.special_points() {
            if (p.y - y).abs() > tol {
                continue;
            }
            // Candidate columns around p.x (x_i is monotone in i), widened
            // by how far rounding can move x_i (many columns when the grid
            // is finer than the spacing of doubles there).
            let slack = (4.0 * f64::EPSILON * (xmin.abs() + p.x.abs() + tol) / grid.dx).ceil();
            let lo = ((p.x - tol - xmin) / grid.dx - 0.5).floor() - 1.0 - slack;
            let hi = ((p.x + tol - xmin) / grid.dx - 0.5).ceil() + 2.0 + slack;
            let (lo, hi) = (lo.max(0.0) as usize, hi.clamp(0.0, grid.nx as f64) as usize);
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
        self.fill_margin_map(grid, &mut out);
        out
    }

    /// [`margin_map`](Self::margin_map) into a buffer of `grid.len()` values.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::LengthMismatch`] when the buffer's length is not
    /// `grid.len()`.
    pub fn margin_map_into(&self, grid: &Grid, out: &mut [f32]) -> Result<()> {
        grid.check_len(out.len())?;
        self.fill_margin_map(grid, out);
        Ok(())
    }

    fn fill_margin_map(&self, grid: &Grid, out: &mut [f32]) {
        let Some([ca, cb]) = self.conics() else {
            out.par_chunks_mut(1 << 16)
                .for_each(|c| c.fill(f32::NEG_INFINITY));
            return;
        };
        let local = Local::new(&ca, grid);
        grid.par_rows(out, |j, row| {
            if local.far_row(grid, j) {
                for (i, o) in row.iter_mut().enumerate() {
                    *o = margin_f32(self.margin(grid.point(i, j)));
                }
                return;
            }
            margin_row(&ca, &cb, local.y(grid, j), local.s, &local.xs, row);
            self.for_special_columns(grid, j, |i| row[i] = -0.0);
        });
    }

    /// The signed margin at one point (see [`margin_map`](Self::margin_map)).
    pub fn margin(&self, p: Point2<f64>) -> f64 {
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
    let mut bands = [(0.0, 0.0); 4];
    let (mut ra, mut rb) = ([(0.0, 0.0); 2], [(0.0, 0.0); 2]);
    let (Some(na), Some(nb)) = (danger(ca, qa, y, &mut ra), danger(cb, qb, y, &mut rb)) else {
        pointwise_row(ca, cb, y, xs, out);
        return;
    };
    let mut n = 0;
    for &b in ra[..na].iter().chain(&rb[..nb]) {
        bands[n] = b;
        n += 1;
    }
    // Sample index ranges [lo, hi) of the bands, one sample of margin on
    // each side, merged.
    let mut zones = [(0usize, 0usize); 4];
    for (z, &(lo, hi)) in zones.iter_mut().zip(&bands[..n]) {
        let i0 = xs.partition_point(|&x| x < lo).saturating_sub(1);
        let i1 = (xs.partition_point(|&x| x <= hi) + 1).min(xs.len());
        *z = (i0, i1.max(i0));
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
