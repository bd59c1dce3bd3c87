//! Conversions between NumPy arrays and Rust buffers.

use numpy::ndarray::{Array, IxDyn};
use numpy::{AllowTypeChange, Element, IntoPyArray, PyArrayDyn, PyArrayLikeDyn};
use pyo3::prelude::*;

/// Any array-like of floats (list, tuple, ndarray of any real dtype), read as
/// float64 in C order: its flat values and its shape.
pub(crate) fn flatten(a: &PyArrayLikeDyn<'_, f64, AllowTypeChange>) -> (Vec<f64>, Vec<usize>) {
    let view = a.as_array();
    (view.iter().copied().collect(), view.shape().to_vec())
}

/// A NumPy array of `shape` that takes ownership of `values` (no copy).
pub(crate) fn to_numpy<'py, T: Element>(
    py: Python<'py>,
    shape: &[usize],
    values: Vec<T>,
) -> Bound<'py, PyArrayDyn<T>> {
    Array::from_shape_vec(IxDyn(shape), values)
        .expect("the buffer has one value per element of the shape")
        .into_pyarray(py)
}
