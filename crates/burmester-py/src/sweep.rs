//! `Filemon.branch_map` and `Filemon.margin_map`: the dense grid sweeps.

use burmester::{Filemon, Grid, Method};
use numpy::ndarray::Array2;
use numpy::{Element, IntoPyArray, PyArray2, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;

use crate::errors::{IntoPy, invalid};
use crate::run::{WATCH_MIN_SAMPLES, run};

/// Checks an `out=` argument: a C-contiguous, writeable NumPy array of
/// `dtype` in native byte order and of the grid's shape.
fn out_array<'py, T: Element>(
    out: &Bound<'py, PyAny>,
    grid: &Grid,
    dtype: &str,
) -> PyResult<Bound<'py, PyArray2<T>>> {
    let (ny, nx) = (grid.ny(), grid.nx());
    let np_dtype = out.getattr("dtype").ok();
    let Some(found) = np_dtype else {
        return Err(PyTypeError::new_err(format!(
            "out must be a NumPy array, got {}; pass numpy.empty(({ny}, {nx}), dtype={dtype})",
            out.get_type()
                .name()
                .map_or("an object".into(), |n| n.to_string())
        )));
    };
    let shape: Vec<usize> = out.getattr("shape")?.extract()?;
    if shape != [ny, nx] {
        return Err(invalid(
            "out_array",
            format!(
                "out has shape {shape:?}, but the grid needs ({ny}, {nx}); pass an array of shape (ny, nx)"
            ),
        ));
    }
    let name: String = found.getattr("name")?.extract()?;
    let native: bool = found.getattr("isnative")?.extract()?;
    if name != dtype || !native {
        return Err(invalid(
            "out_array",
            format!(
                "out has dtype {} ({}), but this map is written as {dtype} in native byte order; pass \
             numpy.empty(({ny}, {nx}), dtype={dtype})",
                found.str()?,
                if native {
                    "native"
                } else {
                    "swapped byte order"
                },
            ),
        ));
    }
    let arr = out.cast::<PyArray2<T>>().map_err(|_| {
        invalid("out_array", format!(
            "out must be a 2-D NumPy array of {dtype}; pass numpy.empty(({ny}, {nx}), dtype={dtype})"
        ))
    })?;
    if !arr.is_c_contiguous() {
        return Err(invalid(
            "out_array",
            format!(
                "out must be C-contiguous (not a strided view); pass numpy.empty(({ny}, {nx}), \
             dtype={dtype})"
            ),
        ));
    }
    if !out
        .getattr("flags")?
        .getattr("writeable")?
        .extract::<bool>()?
    {
        return Err(invalid(
            "out_array",
            "out is read-only; pass a writeable array",
        ));
    }
    Ok(arr.clone())
}

/// Runs `fill` into a fresh `(ny, nx)` array (handed to NumPy without a
/// copy) or into `out`, with the GIL released, Ctrl-C and progress.
fn run_map<'py, T: Element + Copy + Send>(
    py: Python<'py>,
    grid: Grid,
    zero: T,
    dtype: &str,
    out: Option<Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
    fill: impl Fn(&mut [T], &burmester::Control<'_>) -> burmester::Result<()> + Send + Sync,
) -> PyResult<Bound<'py, PyAny>> {
    let (ny, nx) = (grid.ny(), grid.nx());
    let watch = grid.len() >= WATCH_MIN_SAMPLES;
    match out {
        None => {
            let v = run(py, watch, progress, None, |control| {
                let mut v = burmester::error::try_vec("a map", grid.len(), zero)?;
                fill(&mut v, control)?;
                Ok(v)
            })?;
            Ok(Array2::from_shape_vec((ny, nx), v)
                .expect("one value per sample")
                .into_pyarray(py)
                .into_any())
        }
        Some(out) => {
            let arr = out_array::<T>(&out, &grid, dtype)?;
            {
                let mut rw = arr.try_readwrite().map_err(|_| {
                    invalid(
                        "out_array",
                        "out is being written by another call (NumPy arrays lent to Rust are \
                         borrow-checked); pass a separate array to each concurrent call",
                    )
                })?;
                let slice = rw.as_slice_mut().map_err(|_| {
                    invalid(
                        "out_array",
                        "out must be C-contiguous; pass numpy.empty((ny, nx))",
                    )
                })?;
                run(py, watch, progress, Some("out"), |control| {
                    fill(slice, control)
                })?;
            }
            Ok(out)
        }
    }
}

/// `Filemon.branch_map` (see the stub for the docs).
pub(crate) fn branch_map<'py>(
    f: Filemon,
    py: Python<'py>,
    grid: Grid,
    method: &str,
    out: Option<Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let method = method.parse::<Method>().py()?;
    run_map(
        py,
        grid,
        false,
        "bool",
        out,
        progress,
        move |buf, control| f.branch_map_into(&grid, method, buf, control),
    )
}

/// `Filemon.margin_map`.
pub(crate) fn margin_map<'py>(
    f: Filemon,
    py: Python<'py>,
    grid: Grid,
    out: Option<Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    run_map(
        py,
        grid,
        0.0f32,
        "float32",
        out,
        progress,
        move |buf, control| f.margin_map_into(&grid, buf, control),
    )
}
