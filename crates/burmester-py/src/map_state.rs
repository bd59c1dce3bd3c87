//! How a solution map's or pair map's state crosses to Python and back
//! (its pickle): the fixed dyad of either kind (a crank, a driven slider),
//! what varies, and the Grashof check of a pickled map's samples. Below
//! the map classes (`design`, `slider_map`, `pairs`), which all read it.

use burmester::{Dyad, MapContext, PairContext, SliderDyad, Varying};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;

use crate::classes::dyad_tuple;
use crate::conv::{PyPoint, pt};
use crate::errors::IntoPy;

pub(crate) type Xy = (f64, f64);

/// Whether a map's valid samples have no Grashof class (a map of
/// slider-cranks: Grashof's law is a four-bar's), for checking a pickle.
pub(crate) trait NoGrashof {
    /// True for a map with a driven slider.
    fn no_grashof(&self) -> bool;
}

impl NoGrashof for MapContext {
    fn no_grashof(&self) -> bool {
        matches!(self.varying, Varying::DrivingSlider { .. })
    }
}

impl NoGrashof for PairContext {
    fn no_grashof(&self) -> bool {
        false
    }
}

/// What is wrong with a valid sample's Grashof code in a pickle.
pub(crate) fn grashof_problem(no_grashof: bool) -> String {
    if no_grashof {
        "a class for a slider-crank (Grashof's law is a four-bar's: 255)".to_owned()
    } else {
        "no class for a valid sample".to_owned()
    }
}

/// The fixed dyad of a map: `(C0, C1)` of a crank (`(A0, A1)` of a
/// driven map's driving crank), `(C1, u)` of a driven slider.
pub(crate) fn fixed_tuple(v: &Varying) -> (Xy, Xy) {
    match v {
        Varying::Driving { driven: d } | Varying::Driven { driving: d } => dyad_tuple(d),
        Varying::DrivingSlider { driven } => (pt(driven.circle), (driven.guide.x, driven.guide.y)),
    }
}

/// How a map's pickle names what varies: `"driving"`, `"driven"` or
/// `"driving_slider"`.
pub(crate) fn varying_state(v: &Varying) -> &'static str {
    match v {
        Varying::DrivingSlider { .. } => "driving_slider",
        other => other.as_str(),
    }
}

/// What varies, from a pickle's name ([`varying_state`]) and fixed dyad.
pub(crate) fn varying_of(name: &str, fixed: (PyPoint, PyPoint)) -> PyResult<Varying> {
    let dyad = Dyad::new(fixed.0.0, fixed.1.0);
    Ok(match name {
        "driving" => Varying::Driving { driven: dyad },
        "driven" => Varying::Driven { driving: dyad },
        "driving_slider" => Varying::DrivingSlider {
            driven: SliderDyad::new(fixed.0.0, fixed.1.0.coords).py()?,
        },
        other => {
            return Err(PyTypeError::new_err(format!(
                "varying must be 'driving', 'driven' or 'driving_slider', got {other:?}"
            )));
        }
    })
}
