//! Viewports and grids of sample points at cell centers.
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

use nalgebra::Point2;

use crate::error::{InvalidInput, Result, finite};

/// A rectangle of the plane, `xmin <= x <= xmax`, `ymin <= y <= ymax`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Viewport {
    /// Left edge.
    pub xmin: f64,
    /// Right edge.
    pub xmax: f64,
    /// Bottom edge.
    pub ymin: f64,
    /// Top edge.
    pub ymax: f64,
}

/// Refuses a bound of a box that is not finite, naming it: `names` and
/// `bounds` in the order `xmin`, `xmax`, `ymin`, `ymax`.
pub(crate) fn finite_bounds(names: [&'static str; 4], bounds: [f64; 4]) -> Result<()> {
    for (name, value) in names.into_iter().zip(bounds) {
        finite(name, value)?;
    }
    Ok(())
}

impl Viewport {
    /// A viewport, validated.
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] when a bound is not finite or `xmin >= xmax` or
    /// `ymin >= ymax`.
    pub fn new(xmin: f64, xmax: f64, ymin: f64, ymax: f64) -> Result<Self> {
        finite_bounds(["xmin", "xmax", "ymin", "ymax"], [xmin, xmax, ymin, ymax])?;
        if xmin >= xmax || ymin >= ymax || !(xmax - xmin).is_finite() || !(ymax - ymin).is_finite()
        {
            return Err(InvalidInput::Viewport {
                xmin,
                xmax,
                ymin,
                ymax,
            }
            .into());
        }
        Ok(Viewport {
            xmin,
            xmax,
            ymin,
            ymax,
        })
    }

    /// Width and height.
    pub fn size(&self) -> (f64, f64) {
        (self.xmax - self.xmin, self.ymax - self.ymin)
    }

    /// The length of the diagonal.
    pub fn diagonal(&self) -> f64 {
        let (w, h) = self.size();
        w.hypot(h)
    }

    /// The center.
    pub fn center(&self) -> Point2<f64> {
        Point2::new(0.5 * (self.xmin + self.xmax), 0.5 * (self.ymin + self.ymax))
    }

    /// Whether `p` lies inside (edges included).
    pub fn contains(&self, p: Point2<f64>) -> bool {
        p.x >= self.xmin && p.x <= self.xmax && p.y >= self.ymin && p.y <= self.ymax
    }
}

/// A grid of sample points at cell centers over a viewport.
#[derive(Clone, Copy, PartialEq)]
pub struct Grid {
    viewport: Viewport,
    nx: usize,
    ny: usize,
    dx: f64,
    dy: f64,
}

crate::geom::debug_shows!(
    /// The viewport and the sample counts, not the derived cell size.
    Grid,
    s => viewport: s.viewport, nx: s.nx, ny: s.ny,
);

impl Grid {
    /// The largest number of samples a grid may have (`2^32`).
    pub const MAX_POINTS: usize = 1 << 32;

    /// A grid of `nx` by `ny` samples over `viewport`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::GridSize`] when `nx` or `ny` is zero or the grid
    /// has more than [`Grid::MAX_POINTS`] samples.
    pub fn new(viewport: Viewport, nx: usize, ny: usize) -> Result<Self> {
        if nx == 0 || ny == 0 || nx.checked_mul(ny).is_none_or(|n| n > Self::MAX_POINTS) {
            return Err(InvalidInput::GridSize {
                nx,
                ny,
                max: Self::MAX_POINTS,
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

    /// The spacing of the columns, `(xmax - xmin) / nx`.
    pub fn dx(&self) -> f64 {
        self.dx
    }

    /// The spacing of the rows, `(ymax - ymin) / ny`.
    pub fn dy(&self) -> f64 {
        self.dy
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

    /// The sample `(j, i)` (row, column) nearest to `p`, clamped to the
    /// grid.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a non-finite point.
    pub fn nearest(&self, p: Point2<f64>) -> Result<(usize, usize)> {
        crate::error::finite_point(["point x", "point y"], p)?;
        let v = self.viewport;
        let cell = |u: f64, lo: f64, d: f64, n: usize| {
            (((u - lo) / d - 0.5).round().max(0.0) as usize).min(n - 1)
        };
        Ok((
            cell(p.y, v.ymin, self.dy, self.ny),
            cell(p.x, v.xmin, self.dx, self.nx),
        ))
    }

    pub(crate) fn check_len(&self, len: usize) -> Result<()> {
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
