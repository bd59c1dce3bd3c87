//! Conversions between NumPy arrays and Rust buffers.

use numpy::ndarray::{Array, IxDyn};
use numpy::{Element, IntoPyArray, PyArrayDyn, PyArrayMethods};
use pyo3::exceptions::{PyOverflowError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::IntoPyDict;

use crate::errors::{InvalidInputError, invalid};

/// An array-like of real numbers (list, tuple, ndarray of a real dtype,
/// nested to any depth), read as float64 in C order: its flat values and
/// its shape.
///
/// Errors say what to change: a ragged nesting or an int too large for a
/// float is an `InvalidInputError`; strings, complex numbers and other
/// objects that are not real numbers are a `TypeError` (NumPy would
/// silently drop an imaginary part or turn `None` into NaN).
pub(crate) struct FloatArray {
    pub(crate) values: Vec<f64>,
    pub(crate) shape: Vec<usize>,
}

impl<'a, 'py> FromPyObject<'a, 'py> for FloatArray {
    type Error = PyErr;

    fn extract(ob: pyo3::Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        let py = ob.py();
        let np = py.import("numpy")?;
        let arr = np.call_method1("asarray", (ob,)).map_err(|e| {
            if e.is_instance_of::<PyValueError>(py) {
                invalid(
                    "not_rectangular",
                    format!(
                        "expected an array of numbers of one shape ({e}); pass a rectangular array"
                    ),
                )
            } else {
                e
            }
        })?;
        let kind: String = arr.getattr("dtype")?.getattr("kind")?.extract()?;
        let arr = match kind.as_str() {
            "b" | "i" | "u" | "f" => arr,
            "O" => {
                // Element by element, so that None is a TypeError rather than NaN
                // and a huge int an InvalidInputError.
                let shape: Vec<usize> = arr.getattr("shape")?.extract()?;
                let flat: Vec<Real> = arr
                    .call_method0("ravel")?
                    .call_method0("tolist")?
                    .extract()?;
                return Ok(FloatArray {
                    values: flat.into_iter().map(|r| r.0).collect(),
                    shape,
                });
            }
            "c" => {
                return Err(PyTypeError::new_err(
                    "complex numbers are not accepted; pass real numbers",
                ));
            }
            _ => {
                return Err(PyTypeError::new_err(format!(
                    "expected real numbers, got an array of dtype {}; pass floats",
                    arr.getattr("dtype")?.str()?
                )));
            }
        };
        let arr = np.call_method(
            "asarray",
            (arr,),
            Some(&[("dtype", "float64"), ("order", "C")].into_py_dict(py)?),
        )?;
        let arr = arr.cast_into::<PyArrayDyn<f64>>().map_err(PyErr::from)?;
        let ro = arr
            .try_readonly()
            .map_err(|e| PyTypeError::new_err(e.to_string()))?;
        let view = ro.as_array();
        Ok(FloatArray {
            values: view.iter().copied().collect(),
            shape: view.shape().to_vec(),
        })
    }
}

/// A real number from Python (anything `float()` accepts as a number); an
/// int too large for a float is an `InvalidInputError` instead of
/// Python's `OverflowError`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Real(pub(crate) f64);

impl<'a, 'py> FromPyObject<'a, 'py> for Real {
    type Error = PyErr;

    fn extract(ob: pyo3::Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        // NumPy's complex scalars convert to float by dropping the imaginary
        // part (with a warning): refuse them, as Python's complex is.
        let complex = ob
            .get_type()
            .name()
            .is_ok_and(|n| n.to_string().contains("complex"));
        if complex {
            return Err(PyTypeError::new_err(
                "complex numbers are not accepted; pass real numbers",
            ));
        }
        match ob.extract::<f64>() {
            Ok(v) => Ok(Real(v)),
            Err(e) if e.is_instance_of::<PyOverflowError>(ob.py()) => Err(invalid(
                "too_large",
                format!(
                    "{} is too large to be a float; pass a finite number",
                    short_repr(&ob)
                ),
            )),
            Err(e) => Err(e),
        }
    }
}

/// A count or an index from Python: a negative int or one beyond 64 bits is
/// an `InvalidInputError` instead of Python's `OverflowError`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Count(pub(crate) usize);

impl<'a, 'py> FromPyObject<'a, 'py> for Count {
    type Error = PyErr;

    fn extract(ob: pyo3::Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        match ob.extract::<usize>() {
            Ok(v) => Ok(Count(v)),
            Err(e) if e.is_instance_of::<PyOverflowError>(ob.py()) => Err(invalid(
                "count_out_of_range",
                format!(
                    "{} is out of range: a count or an index must be a non-negative integer \
                     (at most 2^64 - 1); pass one",
                    short_repr(&ob)
                ),
            )),
            Err(e) => Err(e),
        }
    }
}

/// `repr(ob)`, cut to 40 characters.
fn short_repr(ob: &pyo3::Borrowed<'_, '_, PyAny>) -> String {
    let r = ob
        .repr()
        .map(|r| r.to_string())
        .unwrap_or_else(|_| "the value".into());
    if r.chars().count() > 40 {
        let head: String = r.chars().take(20).collect();
        format!("{head}... ({} characters)", r.chars().count())
    } else {
        r
    }
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
        let v: Vec<Real> = ob.extract().map_err(|e: PyErr| {
            if e.is_instance_of::<InvalidInputError>(ob.py()) {
                return e;
            }
            PyTypeError::new_err(format!(
                "expected a point (x, y): a sequence of two numbers, got {}",
                ob.get_type()
                    .name()
                    .map(|n| n.to_string())
                    .unwrap_or_else(|_| "an object".into())
            ))
        })?;
        let v: Vec<f64> = v.into_iter().map(|r| r.0).collect();
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

/// Points from an array-like of shape `(..., 2)`: the flat points and the
/// leading shape.
pub(crate) fn points(a: &FloatArray) -> PyResult<(Vec<burmester::Point2<f64>>, Vec<usize>)> {
    let shape = &a.shape;
    if shape.last() != Some(&2) {
        return Err(invalid(
            "shape",
            format!(
                "points must be an array of shape (..., 2), got shape {shape:?}; pass (x, y) pairs"
            ),
        ));
    }
    let lead = shape[..shape.len() - 1].to_vec();
    Ok((
        a.values
            .chunks_exact(2)
            .map(|c| burmester::Point2::new(c[0], c[1]))
            .collect(),
        lead,
    ))
}
