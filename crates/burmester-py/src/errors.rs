//! The one place where core errors become Python exceptions.
//!
//! Every exception carries the core error's cause and fields as
//! attributes: `cause` (for example `"at_infinity"`) and one attribute per
//! field (`dir_x`, `dir_y`, `name`, `value`, ...).

use burmester::error::Field;
use pyo3::create_exception;
use pyo3::exceptions::{PyKeyboardInterrupt, PyMemoryError, PyValueError};
use pyo3::prelude::*;

create_exception!(
    burmester,
    BurmesterError,
    PyValueError,
    "Base of every error raised by burmester (a ValueError)."
);
/// The one table of the binding's exceptions: each kind of core error (a
/// variant of `burmester::Error` that wraps an enum of causes) and the
/// `BurmesterError` subclass it raises, with its docstring. Causes and
/// fields come from the core's one list of errors (`burmester::error`).
macro_rules! exceptions {
    ($($Kind:ident => $Class:ident: $doc:literal,)*) => {
        $(create_exception!(burmester, $Class, BurmesterError, $doc);)*

        /// The Python exception of a core error, with its message: the
        /// kind's class, `KeyboardInterrupt` for a cancelled computation,
        /// `MemoryError` for an allocation that failed.
        fn exception(e: &burmester::Error, msg: String) -> PyErr {
            match e {
                $(burmester::Error::$Kind(_) => $Class::new_err(msg),)*
                burmester::Error::Cancelled { .. } => PyKeyboardInterrupt::new_err(msg),
                burmester::Error::OutOfMemory { .. } => PyMemoryError::new_err(msg),
                _ => BurmesterError::new_err(msg),
            }
        }
    };
}

exceptions! {
    InvalidInput => InvalidInputError:
        "A number or name passed in is not acceptable: NaN, infinite, zero or negative length, unknown name.",
    Assembly => AssemblyError:
        "The linkage cannot be assembled as asked (the loop does not close).",
    Degenerate => DegenerateError:
        "The geometry is degenerate: an answer lies at infinity, or the task has no unique answer.",
    Drive => DriveError:
        "A six-bar cannot be built as asked, or a linkage cannot be driven from a motor by an added dyad (its cause says why).",
}

/// Maps a core error to its Python exception, with its cause and fields as
/// attributes.
pub(crate) fn to_py(e: burmester::Error) -> PyErr {
    let err = exception(&e, e.to_string());
    Python::attach(|py| {
        let value = err.value(py);
        // Setting attributes on a fresh exception object cannot fail in
        // practice; an attribute that could not be set is left out.
        let _ = value.setattr("cause", e.cause());
        for (name, field) in e.fields() {
            let _ = match field {
                Field::Float(v) => value.setattr(name, v),
                Field::Int(v) => value.setattr(name, v),
                Field::Str(v) => value.setattr(name, v),
            };
        }
    });
    err
}

/// An `InvalidInputError` raised by the binding itself (an argument that
/// never reaches the core: an array of the wrong shape, an `out=` array
/// that cannot be written), with its `cause` set like the core's.
pub(crate) fn invalid(cause: &'static str, msg: impl Into<String>) -> PyErr {
    let err = InvalidInputError::new_err(msg.into());
    Python::attach(|py| {
        // As in `to_py`: a fresh exception object takes the attribute.
        let _ = err.value(py).setattr("cause", cause);
    });
    err
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
