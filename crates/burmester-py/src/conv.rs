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

/// A point `(x, y)` from Python: any sequence of two numbers (tuple, list,
/// NumPy array).
#[derive(Debug, Clone, Copy)]
pub(crate) struct PyPoint(pub(crate) burmester::Point2<f64>);

impl<'a, 'py> FromPyObject<'a, 'py> for PyPoint {
    type Error = PyErr;

    fn extract(ob: pyo3::Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        let v: Vec<f64> = ob.extract().map_err(|_| {
            pyo3::exceptions::PyTypeError::new_err(format!(
                "expected a point (x, y): a sequence of two numbers, got {}",
                ob.get_type()
                    .name()
                    .map(|n| n.to_string())
                    .unwrap_or_else(|_| "an object".into())
            ))
        })?;
        if v.len() != 2 {
            return Err(pyo3::exceptions::PyTypeError::new_err(format!(
                "expected a point (x, y): a sequence of two numbers, got {} numbers",
                v.len()
            )));
        }
        Ok(PyPoint(burmester::Point2::new(v[0], v[1])))
    }
}

/// `(x, y)` for Python.
pub(crate) fn pt(p: burmester::Point2<f64>) -> (f64, f64) {
    (p.x, p.y)
}

/// `(x, y)` of a vector for Python.
pub(crate) fn vec2(v: burmester::Vector2<f64>) -> (f64, f64) {
    (v.x, v.y)
}

/// Points from an array-like of shape `(..., 2)`: the flat points and the
/// leading shape.
pub(crate) fn points(
    a: &PyArrayLikeDyn<'_, f64, AllowTypeChange>,
) -> PyResult<(Vec<burmester::Point2<f64>>, Vec<usize>)> {
    let view = a.as_array();
    let shape = view.shape();
    if shape.last() != Some(&2) {
        return Err(crate::errors::InvalidInputError::new_err(format!(
            "points must be an array of shape (..., 2), got shape {shape:?}; pass (x, y) pairs"
        )));
    }
    let lead = shape[..shape.len() - 1].to_vec();
    let flat: Vec<f64> = view.iter().copied().collect();
    Ok((
        flat.chunks_exact(2)
            .map(|c| burmester::Point2::new(c[0], c[1]))
            .collect(),
        lead,
    ))
}
