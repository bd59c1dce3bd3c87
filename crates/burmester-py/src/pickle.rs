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

/// `__getnewargs_ex__` of `$cls`, a class built from its parts by name
/// only: `((), {name: value})`, each value an expression of `$s` (the
/// wrapped core value, `self.inner`).
macro_rules! new_by_name {
    ($cls:ty, $s:ident => { $($name:literal: $value:expr),* $(,)? }) => {
        #[::pyo3::pymethods]
        impl $cls {
            fn __getnewargs_ex__<'py>(
                &self,
                py: ::pyo3::Python<'py>,
            ) -> ::pyo3::PyResult<((), ::pyo3::Bound<'py, ::pyo3::types::PyDict>)> {
                use ::pyo3::types::PyDictMethods;
                let $s = &self.inner;
                let kw = ::pyo3::types::PyDict::new(py);
                $(kw.set_item($name, $value)?;)*
                Ok(((), kw))
            }
        }
    };
}

pub(crate) use new_by_name;
