//! Python bindings of `burmester`: the `burmester._burmester` extension module.
//!
//! Thin wrappers only: each class holds a core value, converts arguments,
//! and maps core errors to Python exceptions in one place (the `errors` module).

use pyo3::prelude::*;

mod conv;
mod design;
mod errors;
mod fourbar;
mod sweep;
mod synthesis;

/// The native core of the `burmester` package.
#[pymodule]
mod _burmester {
    #[pymodule_export]
    use crate::design::PySolutionMap;
    #[pymodule_export]
    use crate::errors::{AssemblyError, BurmesterError, DegenerateError, InvalidInputError};
    #[pymodule_export]
    use crate::fourbar::{PyConfiguration, PyFourBar};
    #[pymodule_export]
    use crate::synthesis::{PyConic, PyFilemon, PySynthesizedFourBar, PyTask};

    #[pymodule_init]
    fn init(m: &pyo3::Bound<'_, pyo3::types::PyModule>) -> pyo3::PyResult<()> {
        use pyo3::types::PyModuleMethods;
        m.add("__version__", env!("CARGO_PKG_VERSION"))
    }
}
