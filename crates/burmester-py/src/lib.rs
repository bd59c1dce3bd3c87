//! Python bindings of `burmester`: the `burmester._burmester` extension module.
//!
//! Thin wrappers only, one module per core module (`geom`, `linkage`,
//! `synthesis`, `design`; `sweep` holds the three-pose sweeps of
//! `synthesis::three`), each importing only from those before it. Each class
//! holds a core value, converts arguments, and maps core errors to Python
//! exceptions in one place (`errors`); long calls release the GIL and
//! honour Ctrl-C and progress callbacks through one runner (`run`). The
//! pictures Jupyter shows (`_repr_png_`) are drawn in Python (`display`).

use pyo3::prelude::*;

mod actuator;
mod atlas;
mod classes;
mod conv;
mod crank_synth;
mod curves;
mod design;
mod display;
mod drive;
mod errors;
mod geom;
mod getters;
mod inverted;
mod linkage;
mod map_state;
mod options;
mod pairs;
mod pickle;
mod run;
mod search;
mod slider;
mod slider_branch;
mod slider_dyads;
mod slider_map;
mod sweep;
mod synthesis;

/// The native core of the `burmester` package.
#[pymodule]
mod _burmester {
    #[pymodule_export]
    use crate::actuator::{PyActuator, PyActuatorMap};
    #[pymodule_export]
    use crate::atlas::_atlas_tile;
    #[pymodule_export]
    use crate::classes::{PyDesignLimits, PyFilemon, PySynthesizedFourBar, PyTask};
    #[pymodule_export]
    use crate::curves::{PyCoincidencePoint, PyCubic, PyCurveDyad};
    #[pymodule_export]
    use crate::design::{PyPivot, PySolutionMap};
    #[pymodule_export]
    use crate::drive::{PyDrive, PyDriveMap, PySixBar, unit_time_ratio_crank_rocker};
    #[pymodule_export]
    use crate::errors::DriveError;
    #[pymodule_export]
    use crate::errors::{AssemblyError, BurmesterError, DegenerateError, InvalidInputError};
    #[pymodule_export]
    use crate::geom::{PyConic, PyGrid, clip_line};
    #[pymodule_export]
    use crate::inverted::{
        PyInvertedConfiguration, PyInvertedSliderCrank, PySynthesizedInvertedSliderCrank,
    };
    #[pymodule_export]
    use crate::linkage::{PyConfiguration, PyFourBar, PyLinkageFigures};
    #[pymodule_export]
    use crate::pairs::{PyPair, PyPairMap};
    #[pymodule_export]
    use crate::search::{
        _design, _design_from_atlas, _design_plan, PyDesign, PyDesignReport, PyNearMiss, PySpace,
    };
    #[pymodule_export]
    use crate::slider::{PySliderConfiguration, PySliderCrank, PySynthesizedSliderCrank};
    #[pymodule_export]
    use crate::slider_branch::{PySliderFilemon, slider_branch_free_arcs, slider_curve_branch};
    #[pymodule_export]
    use crate::slider_dyads::{PyInvertedSlider, PySliderDyad};
    #[pymodule_export]
    use crate::slider_map::PySliderPivot;
    #[pymodule_export]
    use crate::synthesis::PyPole;

    #[pymodule_init]
    fn init(m: &pyo3::Bound<'_, pyo3::types::PyModule>) -> pyo3::PyResult<()> {
        use pyo3::types::PyModuleMethods;
        // Load NumPy's C API now, while no signal can be pending: loading it
        // lazily in the first array-returning call would import NumPy there,
        // and a Ctrl-C at that moment would fail the import inside Rust.
        let _ = numpy::PyArray1::<f64>::zeros(m.py(), 0, false);
        m.add("__version__", env!("CARGO_PKG_VERSION"))
    }
}
