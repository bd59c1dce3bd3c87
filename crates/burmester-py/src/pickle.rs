//! Pickling: what every class's `__reduce__` returns, written once.

use pyo3::prelude::*;
use pyo3::types::PyTuple;
use pyo3::{BoundObject, PyTypeInfo};

/// What `__reduce__` returns: a callable and the arguments it is called
/// with on unpickling.
pub(crate) type Reduced<'py> = PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)>;

/// `(T.<rebuild>, args)`: the class's static method `rebuild` (such as
/// `_from_state` or `_from_parts`) called with `args`.
pub(crate) fn reduce_to<'py, T: PyTypeInfo>(
    py: Python<'py>,
    rebuild: &str,
    args: impl IntoPyObject<'py, Target = PyTuple>,
) -> Reduced<'py> {
    let f = py.get_type::<T>().getattr(rebuild)?;
    let args = args.into_pyobject(py).map_err(Into::into)?;
    Ok((f, args.into_bound()))
}
