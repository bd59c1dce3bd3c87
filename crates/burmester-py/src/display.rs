//! Pictures in Jupyter: the `_repr_png_` of `Task`, `Filemon`, `FourBar`,
//! `SynthesizedFourBar`, `SolutionMap`, `PairMap` and `Cubic`.
//!
//! The binding draws nothing itself: each method hands the object to the
//! pure-Python `burmester._display.repr_png`, which imports matplotlib only
//! when it is called (so `import burmester` does not) and returns the PNG
//! bytes, or None when matplotlib is not installed (Jupyter then shows the
//! `repr`).

use pyo3::prelude::*;

/// `burmester._display.repr_png(obj)`: PNG bytes, or None.
pub(crate) fn repr_png(obj: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let display = obj.py().import("burmester._display")?;
    Ok(display.call_method1("repr_png", (obj,))?.unbind())
}
