//! `Filemon.branch_map` and `Filemon.margin_map`: the dense grid sweeps.

use burmester::{Filemon, Grid, Method};
use numpy::{Element, PyArray2, PyArrayMethods, PyUntypedArrayMethods};
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

/// Runs `fill` into a fresh `(ny, nx)` array or into `out`, with the GIL
/// released, Ctrl-C and progress.
///
/// A fresh map is allocated by NumPy (`numpy.zeros`: its pages are mapped
/// lazily, and NumPy asks for huge pages on large arrays) and then swept
/// exactly as `out=` is, so that its first-touch page faults happen inside
/// the parallel sweep instead of in a single-threaded fill beforehand.
fn run_map<'py, T: Element + Copy + Send>(
    py: Python<'py>,
    grid: Grid,
    dtype: &str,
    out: Option<Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
    fill: impl Fn(&mut [T], &burmester::Control<'_>) -> burmester::Result<()> + Send + Sync,
) -> PyResult<Bound<'py, PyAny>> {
    let watch = grid.len() >= WATCH_MIN_SAMPLES;
    let (out, partial) = match out {
        Some(out) => (out, Some("out")),
        None => (
            crate::conv::empty::<T>(py, &[grid.ny(), grid.nx()])?.into_any(),
            None,
        ),
    };
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
        run(py, watch, progress, partial, |control| fill(slice, control))?;
    }
    Ok(out)
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
    run_map(py, grid, "bool", out, progress, move |buf, control| {
        f.branch_map_into(&grid, method, buf, control)
    })
}

/// `Filemon.margin_map`.
pub(crate) fn margin_map<'py>(
    f: Filemon,
    py: Python<'py>,
    grid: Grid,
    out: Option<Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    run_map(py, grid, "float32", out, progress, move |buf, control| {
        f.margin_map_into(&grid, buf, control)
    })
}
