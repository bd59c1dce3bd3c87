//! `Filemon.branch_map` and `Filemon.margin_map`: the dense grid sweep.

use burmester::{Filemon, Grid, Method};
use numpy::ndarray::Array2;
use numpy::{Element, IntoPyArray, PyArray2, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::PyMemoryError;
use pyo3::prelude::*;

use crate::conv::{Count, Real};
use crate::errors::{IntoPy, InvalidInputError};

/// The grid of the arguments `(xmin, xmax, ymin, ymax, nx, ny)`.
pub(crate) type GridArgs = (Real, Real, Real, Real, Count, Count);

fn grid((xmin, xmax, ymin, ymax, nx, ny): GridArgs) -> PyResult<Grid> {
    Grid::from_bounds(xmin.0, xmax.0, ymin.0, ymax.0, nx.0, ny.0).py()
}

/// Runs `fill` into a fresh `(ny, nx)` array (handed to NumPy without a
/// copy) or into `out`, with the GIL released.
fn run<'py, T: Element + Copy + Send>(
    py: Python<'py>,
    grid: Grid,
    zero: T,
    out: Option<Bound<'py, PyArray2<T>>>,
    fill: impl Fn(&mut [T]) + Send + Sync,
) -> PyResult<Bound<'py, PyArray2<T>>> {
    let (ny, nx) = (grid.ny(), grid.nx());
    match out {
        None => {
            // A refused allocation is a MemoryError, not an abort.
            let mut v = Vec::new();
            v.try_reserve_exact(grid.len()).map_err(|_| {
                PyMemoryError::new_err(format!(
                    "a ({ny}, {nx}) map needs {} bytes, more than can be allocated; pass a \
                     smaller nx and ny, or an out= array",
                    grid.len().saturating_mul(core::mem::size_of::<T>())
                ))
            })?;
            let v = py.detach(move || {
                v.resize(grid.len(), zero);
                fill(&mut v);
                v
            });
            Ok(Array2::from_shape_vec((ny, nx), v)
                .expect("one value per sample")
                .into_pyarray(py))
        }
        Some(arr) => {
            if arr.shape() != [ny, nx] {
                return Err(InvalidInputError::new_err(format!(
                    "out has shape {:?}, but the grid needs ({ny}, {nx}); pass an array of shape (ny, nx)",
                    arr.shape()
                )));
            }
            if !arr.is_c_contiguous() {
                return Err(InvalidInputError::new_err(
                    "out must be C-contiguous; pass numpy.empty((ny, nx), dtype=...)",
                ));
            }
            {
                let mut rw = arr.try_readwrite().map_err(|e| {
                    InvalidInputError::new_err(format!(
                        "out cannot be written: {e}; pass a writeable array"
                    ))
                })?;
                let slice = rw.as_slice_mut().map_err(|_| {
                    InvalidInputError::new_err(
                        "out must be C-contiguous; pass numpy.empty((ny, nx), dtype=...)",
                    )
                })?;
                py.detach(|| fill(slice));
            }
            Ok(arr)
        }
    }
}

/// `Filemon.branch_map` (see the stub for the docs).
pub(crate) fn branch_map<'py>(
    f: Filemon,
    py: Python<'py>,
    args: GridArgs,
    method: &str,
    out: Option<Bound<'py, PyArray2<bool>>>,
) -> PyResult<Bound<'py, PyArray2<bool>>> {
    let grid = grid(args)?;
    let method = method.parse::<Method>().py()?;
    run(py, grid, false, out, move |buf| {
        // The buffer has grid.len() flags by construction.
        let _ = f.branch_map_into(&grid, method, buf);
    })
}

/// `Filemon.margin_map`.
pub(crate) fn margin_map<'py>(
    f: Filemon,
    py: Python<'py>,
    args: GridArgs,
    out: Option<Bound<'py, PyArray2<f32>>>,
) -> PyResult<Bound<'py, PyArray2<f32>>> {
    let grid = grid(args)?;
    run(py, grid, 0.0f32, out, move |buf| {
        let _ = f.margin_map_into(&grid, buf);
    })
}
