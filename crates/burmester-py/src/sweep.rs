//! `Filemon.branch_map` and `Filemon.margin_map`: the dense grid sweep.

use burmester::{Filemon, Grid, Method};
use numpy::ndarray::Array2;
use numpy::{Element, IntoPyArray, PyArray2, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;

use crate::errors::{IntoPy, InvalidInputError};

fn grid(xmin: f64, xmax: f64, ymin: f64, ymax: f64, nx: usize, ny: usize) -> PyResult<Grid> {
    Grid::from_bounds(xmin, xmax, ymin, ymax, nx, ny).py()
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
            let v = py.detach(|| {
                let mut v = vec![zero; grid.len()];
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
                    InvalidInputError::new_err(format!("out cannot be written: {e}"))
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
#[allow(clippy::too_many_arguments)]
pub(crate) fn branch_map<'py>(
    f: Filemon,
    py: Python<'py>,
    xmin: f64,
    xmax: f64,
    ymin: f64,
    ymax: f64,
    nx: usize,
    ny: usize,
    method: &str,
    out: Option<Bound<'py, PyArray2<bool>>>,
) -> PyResult<Bound<'py, PyArray2<bool>>> {
    let grid = grid(xmin, xmax, ymin, ymax, nx, ny)?;
    let method = method.parse::<Method>().py()?;
    run(py, grid, false, out, move |buf| {
        // The buffer has grid.len() flags by construction.
        let _ = f.branch_map_into(&grid, method, buf);
    })
}

/// `Filemon.margin_map`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn margin_map<'py>(
    f: Filemon,
    py: Python<'py>,
    xmin: f64,
    xmax: f64,
    ymin: f64,
    ymax: f64,
    nx: usize,
    ny: usize,
    out: Option<Bound<'py, PyArray2<f32>>>,
) -> PyResult<Bound<'py, PyArray2<f32>>> {
    let grid = grid(xmin, xmax, ymin, ymax, nx, ny)?;
    run(py, grid, 0.0f32, out, move |buf| {
        let _ = f.margin_map_into(&grid, buf);
    })
}
