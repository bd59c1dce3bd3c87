//! The one place where core errors become Python exceptions.

use pyo3::PyErr;
use pyo3::create_exception;
use pyo3::exceptions::PyValueError;

create_exception!(
    burmester,
    BurmesterError,
    PyValueError,
    "Base of every error raised by burmester (a ValueError)."
);
create_exception!(
    burmester,
    InvalidInputError,
    BurmesterError,
    "A number or name passed in is not acceptable: NaN, infinite, zero or negative length, unknown name."
);
create_exception!(
    burmester,
    AssemblyError,
    BurmesterError,
    "The linkage cannot be assembled as asked (the loop does not close)."
);
create_exception!(
    burmester,
    DegenerateError,
    BurmesterError,
    "The geometry is degenerate: an answer lies at infinity, or the task has no unique answer."
);

/// Maps a core error to its Python exception.
pub(crate) fn to_py(e: burmester::Error) -> PyErr {
    let msg = e.to_string();
    match e {
        burmester::Error::InvalidInput(_) => InvalidInputError::new_err(msg),
        burmester::Error::Assembly(_) => AssemblyError::new_err(msg),
        burmester::Error::Degenerate(_) => DegenerateError::new_err(msg),
        _ => BurmesterError::new_err(msg),
    }
}

/// `result.py()` turns a core result into a Python result.
pub(crate) trait IntoPy<T> {
    /// Maps the error with [`to_py`].
    fn py(self) -> Result<T, PyErr>;
}

impl<T, E: Into<burmester::Error>> IntoPy<T> for Result<T, E> {
    fn py(self) -> Result<T, PyErr> {
        self.map_err(|e| to_py(e.into()))
    }
}
