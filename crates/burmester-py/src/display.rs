//! Pictures in Jupyter: the `_repr_png_` of `Task`, `Filemon`, `FourBar`,
//! `SynthesizedFourBar`, `SolutionMap`, `PairMap` and `Cubic` (and, by
//! `repr_png_for!`, `SliderCrank`, `SynthesizedSliderCrank`, `SliderDyad`,
//! `Actuator`, `ActuatorMap`, `InvertedSliderCrank` and
//! `SynthesizedInvertedSliderCrank`).
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

/// `_repr_png_` for each class named: the picture `burmester._display`
/// draws for it (one method, [`repr_png`], for every class; issue 27's
/// slider and actuator classes use it through this macro, each in its own
/// file, so this module depends on none of them).
macro_rules! repr_png_for {
    ($($ty:ty),* $(,)?) => {
        $(
            #[pyo3::pymethods]
            impl $ty {
                /// A picture for Jupyter: PNG bytes drawn by
                /// `burmester._display`, or None without matplotlib.
                fn _repr_png_(
                    slf: &pyo3::Bound<'_, Self>,
                ) -> pyo3::PyResult<pyo3::Py<pyo3::PyAny>> {
                    $crate::display::repr_png(slf.as_any())
                }
            }
        )*
    };
}

pub(crate) use repr_png_for;
