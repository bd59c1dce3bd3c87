//! Conversions between NumPy arrays and Rust buffers.

use numpy::ndarray::{Array, IxDyn};
use numpy::{
    Element, IntoPyArray, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyReadwriteArrayDyn,
    PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyOverflowError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::IntoPyDict;

use crate::errors::{InvalidInputError, invalid};

/// An array-like of real numbers (list, tuple, ndarray of a real dtype,
/// nested to any depth), read as float64 in C order: a C-contiguous float64
/// NumPy array in native byte order is read in place (no copy); anything
/// else is converted once by `numpy.asarray`.
///
/// Errors say what to change: a ragged nesting or an int too large for a
/// float is an `InvalidInputError`; strings, complex numbers and other
/// objects that are not real numbers are a `TypeError` (NumPy would
/// silently drop an imaginary part or turn `None` into NaN).
pub(crate) struct FloatArray<'py> {
    /// C-contiguous (checked on extraction), so `as_slice` succeeds.
    array: PyReadonlyArrayDyn<'py, f64>,
}

impl FloatArray<'_> {
    /// The values in C order, read in place.
    pub(crate) fn values(&self) -> &[f64] {
        self.array
            .as_slice()
            .expect("C-contiguous, checked on extraction")
    }

    /// The shape.
    pub(crate) fn shape(&self) -> &[usize] {
        self.array.shape()
    }
}

impl<'a, 'py> FromPyObject<'a, 'py> for FloatArray<'py> {
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
            // A C-contiguous native float64 array comes back as itself.
            "b" | "i" | "u" | "f" => np.call_method(
                "asarray",
                (arr,),
                Some(&[("dtype", "float64"), ("order", "C")].into_py_dict(py)?),
            )?,
            "O" => {
                // Element by element, so that None is a TypeError rather than NaN
                // and a huge int an InvalidInputError.
                let shape: Vec<usize> = arr.getattr("shape")?.extract()?;
                let flat: Vec<Real> = arr
                    .call_method0("ravel")?
                    .call_method0("tolist")?
                    .extract()?;
                let values = flat.into_iter().map(|r| r.0).collect();
                to_numpy(py, &shape, values).into_any()
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
        let mut arr = arr.cast_into::<PyArrayDyn<f64>>().map_err(PyErr::from)?;
        if !arr.is_aligned() {
            // C-contiguous but misaligned (from a byte buffer at an odd
            // offset, say): an aligned copy.
            arr = arr.call_method0("copy")?.cast_into().map_err(PyErr::from)?;
        }
        let array = arr
            .try_readonly()
            .map_err(|e| PyTypeError::new_err(e.to_string()))?;
        if array.as_slice().is_err() {
            return Err(PyTypeError::new_err(
                "expected a C-contiguous array after conversion; pass a NumPy array",
            ));
        }
        Ok(FloatArray { array })
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

/// Outputs up to this many bytes are allocated through NumPy's C API
/// directly (a failure there would be a panic, not a `MemoryError`, but
/// such a small allocation does not fail).
const SMALL_OUTPUT_BYTES: usize = 1 << 20;

/// A fresh zero-filled, C-contiguous NumPy array of `shape` to write
/// results into. A large one is made by `numpy.zeros`, so that a failed
/// allocation is a `MemoryError`; its untouched pages cost no memory.
pub(crate) fn zeros<'py, T: Element>(
    py: Python<'py>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyArrayDyn<T>>> {
    fresh(py, shape, "zeros")
}

/// A fresh C-contiguous NumPy array of `shape` for results that write every
/// element (a map, as `out=` must be, or a batch of solves): a large one is
/// made by `numpy.empty`, so it takes memory where NumPy's allocator would
/// (pages already mapped for an array freed before, as `numpy.ones` does,
/// instead of fresh zeroed pages faulted in one by one, which also contend
/// between threads); a failed allocation is a `MemoryError`.
pub(crate) fn empty<'py, T: Element>(
    py: Python<'py>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyArrayDyn<T>>> {
    fresh(py, shape, "empty")
}

/// `numpy.<make>(shape, dtype)` for a large array, zeros for a small one.
fn fresh<'py, T: Element>(
    py: Python<'py>,
    shape: &[usize],
    make: &str,
) -> PyResult<Bound<'py, PyArrayDyn<T>>> {
    let bytes = shape
        .iter()
        .try_fold(size_of::<T>(), |acc, &d| acc.checked_mul(d));
    if bytes.is_some_and(|b| b <= SMALL_OUTPUT_BYTES) {
        return Ok(PyArrayDyn::<T>::zeros(py, IxDyn(shape), false));
    }
    let np = py.import("numpy")?;
    let kwargs = [("dtype", T::get_dtype(py))].into_py_dict(py)?;
    np.call_method(make, (shape.to_vec(),), Some(&kwargs))?
        .cast_into::<PyArrayDyn<T>>()
        .map_err(PyErr::from)
}

/// Write access to an array made by [`zeros`] or [`empty`].
pub(crate) fn writer<'py, T: Element>(
    a: &Bound<'py, PyArrayDyn<T>>,
) -> PyResult<PyReadwriteArrayDyn<'py, T>> {
    a.try_readwrite()
        .map_err(|e| PyTypeError::new_err(e.to_string()))
}

/// The values of an array made by [`zeros`], to fill (with the GIL
/// released: a `&mut [T]` is `Send`).
pub(crate) fn slice_mut<'a, T: Element>(w: &'a mut PyReadwriteArrayDyn<'_, T>) -> &'a mut [T] {
    w.as_slice_mut()
        .expect("numpy.zeros makes a C-contiguous array")
}

/// A bool as Python writes it (`True`, `False`), for reprs.
pub(crate) fn py_bool(b: bool) -> &'static str {
    if b { "True" } else { "False" }
}

/// Two float arrays and a mask, as NumPy arrays of one shape.
pub(crate) type Arrays<'py> = (
    Bound<'py, PyArrayDyn<f64>>,
    Bound<'py, PyArrayDyn<f64>>,
    Bound<'py, PyArrayDyn<bool>>,
);

/// Two float arrays and a mask of `shape` (made by [`empty`]), filled by
/// `fill` with the GIL released; `fill` must write every element.
pub(crate) fn fill_arrays<'py>(
    py: Python<'py>,
    shape: &[usize],
    fill: impl FnOnce(&mut [f64], &mut [f64], &mut [bool]) + Send,
) -> PyResult<Arrays<'py>> {
    let (a, b, ok) = (empty(py, shape)?, empty(py, shape)?, empty(py, shape)?);
    {
        let (mut aw, mut bw, mut ow) = (writer(&a)?, writer(&b)?, writer(&ok)?);
        let (a_s, b_s, ok_s) = (slice_mut(&mut aw), slice_mut(&mut bw), slice_mut(&mut ow));
        py.detach(|| fill(a_s, b_s, ok_s));
    }
    Ok((a, b, ok))
}

/// The points of `path` into `xs`, `ys` and `ok` (NaN, NaN and false where
/// a point is an error, such as a loop that does not close).
pub(crate) fn write_points<E>(
    path: impl Iterator<Item = Result<burmester::Point2<f64>, E>>,
    xs: &mut [f64],
    ys: &mut [f64],
    ok: &mut [bool],
) {
    for (((p, x), y), valid) in path.zip(xs).zip(ys).zip(ok) {
        (*x, *y, *valid) = match p {
            Ok(p) => (p.x, p.y, true),
            Err(_) => (f64::NAN, f64::NAN, false),
        };
    }
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

/// Points read in place from an array-like of shape `(..., 2)`.
pub(crate) struct Points<'a> {
    /// `x0, y0, x1, y1, ...`.
    flat: &'a [f64],
    /// The shape without its last axis (of length 2).
    pub(crate) lead: Vec<usize>,
}

impl<'a> Points<'a> {
    /// The points, in C order.
    pub(crate) fn iter(&self) -> impl Iterator<Item = burmester::Point2<f64>> + Send + 'a {
        self.flat
            .chunks_exact(2)
            .map(|c| burmester::Point2::new(c[0], c[1]))
    }
}

/// Points from an array-like of shape `(..., 2)`, read in place, and their
/// leading shape.
pub(crate) fn points<'a>(a: &'a FloatArray<'_>) -> PyResult<Points<'a>> {
    let shape = a.shape();
    if shape.last() != Some(&2) {
        return Err(invalid(
            "shape",
            format!(
                "points must be an array of shape (..., 2), got shape {shape:?}; pass (x, y) pairs"
            ),
        ));
    }
    Ok(Points {
        flat: a.values(),
        lead: shape[..shape.len() - 1].to_vec(),
    })
}
