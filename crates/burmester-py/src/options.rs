//! The one extractor of the map option keywords (`limits`, its three
//! keywords, and the constraints), for every method that takes them: the
//! solution maps, the pair map, the atlas tile and the drives. A method
//! takes them as `**options` and names which of them it accepts
//! ([`Keys`]); the names, types and defaults are written here only.

use burmester::{Constraints, DesignLimits, InputRequirement, Point2};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::classes::PyDesignLimits;
use crate::conv::{Count, PyPoint, Real, pt};
use crate::errors::IntoPy;

/// Calls `$callback! { ... }` with the map option keywords and the drive's
/// two, each as `name: type, whether None is accepted (as not given)`, in
/// order (every one may be left out; the defaults are those of
/// [`DesignLimits`], [`Constraints`] and the drive's: no swing margin, no
/// time ratio limit).
macro_rules! map_option_keywords {
    ($callback:ident) => {
        $callback! {
            limits: PyDesignLimits, true;
            min_transmission_deg: Real, true;
            max_link_ratio: Real, true;
            input: String, true;
            base_plate: Vec<PyPoint>, true;
            obstacles: Vec<Vec<PyPoint>>, true;
            link_width: Real, false;
            travel_samples: Count, false;
            swing_margin_deg: Real, false;
            max_time_ratio: Real, true;
        }
    };
}

macro_rules! define_keywords {
    ($($name:ident: $ty:ty, $none:literal;)*) => {
        /// The keywords as given (`None`: not given, or given as `None`).
        #[derive(Default)]
        struct Given {
            $($name: Option<$ty>,)*
        }

        /// Which of the keywords a method accepts.
        #[derive(Clone, Copy)]
        pub(crate) struct Keys {
            $($name: bool,)*
        }

        impl Keys {
            /// Every keyword.
            const EVERY: Keys = Keys { $($name: true,)* };

            fn accepts(&self, name: &str) -> bool {
                match name {
                    $(stringify!($name) => self.$name,)*
                    _ => false,
                }
            }
        }

        impl Given {
            /// The keyword `name` (accepted) from `value`.
            fn set(&mut self, name: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
                match name {
                    $(stringify!($name) => {
                        self.$name = extract(stringify!($name), value, $none)?;
                    })*
                    _ => unreachable!("checked by Keys::accepts"),
                }
                Ok(())
            }
        }
    };
}

map_option_keywords!(define_keywords);

impl Keys {
    /// The map option keywords (the solution maps, the pair map, the
    /// atlas): every one but the drive's.
    pub(crate) const MAP: Keys = Keys {
        swing_margin_deg: false,
        max_time_ratio: false,
        ..Keys::EVERY
    };
    /// The drives' keywords: every one but `input` (a drive's input is the
    /// motor's crank).
    pub(crate) const DRIVE: Keys = Keys {
        input: false,
        ..Keys::EVERY
    };
    /// The classic drive's: the limits but `input`, and the drive's, no
    /// constraints.
    pub(crate) const CLASSIC: Keys = Keys {
        base_plate: false,
        obstacles: false,
        link_width: false,
        travel_samples: false,
        ..Keys::DRIVE
    };
    /// An actuator's: the limits but `input` (the actuator drives), and
    /// the base plate (its ground pivot's only constraint).
    pub(crate) const ACTUATOR: Keys = Keys {
        base_plate: true,
        obstacles: false,
        link_width: false,
        travel_samples: false,
        swing_margin_deg: false,
        max_time_ratio: false,
        ..Keys::CLASSIC
    };
}

/// `value` as a `T` (`None` as no value where `none` says it may be), a
/// `TypeError` naming the keyword as Python's own arguments do.
fn extract<'py, T>(name: &str, value: &Bound<'py, PyAny>, none: bool) -> PyResult<Option<T>>
where
    T: for<'a> FromPyObject<'a, 'py>,
    for<'a> <T as FromPyObject<'a, 'py>>::Error: Into<PyErr>,
{
    if none && value.is_none() {
        return Ok(None);
    }
    value.extract::<T>().map(Some).map_err(|e| {
        let e: PyErr = e.into();
        let py = value.py();
        if e.get_type(py).is(py.get_type::<PyTypeError>()) {
            let err = PyTypeError::new_err(format!("argument '{name}': {}", e.value(py)));
            err.set_cause(py, Some(e));
            err
        } else {
            e
        }
    })
}

/// The map options of a call: the limits and the constraints, as the
/// core takes them (it validates them), and the drive's swing margin
/// (degrees) and largest time ratio.
pub(crate) struct MapOptions {
    pub(crate) limits: DesignLimits,
    pub(crate) constraints: Constraints,
    pub(crate) swing_margin_deg: f64,
    pub(crate) max_time_ratio: f64,
}

impl MapOptions {
    /// The options from the keywords `options` of method `method` (its
    /// name, for the error of a keyword it does not take), which accepts
    /// `keys`; the core validates the values.
    pub(crate) fn from_kwargs(
        method: &str,
        options: Option<&Bound<'_, PyDict>>,
        keys: Keys,
    ) -> PyResult<Self> {
        let mut g = Given::default();
        for (k, v) in options.into_iter().flat_map(|d| d.iter()) {
            let name = k.extract::<String>()?;
            if !keys.accepts(&name) {
                return Err(PyTypeError::new_err(format!(
                    "{method}() got an unexpected keyword argument '{name}'"
                )));
            }
            g.set(&name, &v)?;
        }
        let limits = match g.limits {
            Some(l) => {
                if g.min_transmission_deg.is_some()
                    || g.max_link_ratio.is_some()
                    || g.input.is_some()
                {
                    return Err(PyTypeError::new_err(
                        "pass either limits=DesignLimits(...) or the keywords \
                         min_transmission_deg, max_link_ratio and input, not both",
                    ));
                }
                l.inner
            }
            None => {
                let d = DesignLimits::default();
                let input = match g.input {
                    Some(s) => s.parse::<InputRequirement>().py()?,
                    None => d.input,
                };
                DesignLimits::from_degrees(
                    g.min_transmission_deg
                        .map_or(d.min_transmission.to_degrees(), |r| r.0),
                    g.max_link_ratio.map_or(d.max_link_ratio, |r| r.0),
                    input,
                )
                .py()?
            }
        };
        let pts = |v: Vec<PyPoint>| v.into_iter().map(|p| p.0).collect::<Vec<Point2<f64>>>();
        let d = Constraints::default();
        Ok(MapOptions {
            limits,
            constraints: Constraints {
                base_plate: g.base_plate.map(pts),
                obstacles: g
                    .obstacles
                    .unwrap_or_default()
                    .into_iter()
                    .map(pts)
                    .collect(),
                link_width: g.link_width.map_or(d.link_width, |r| r.0),
                travel_samples: g.travel_samples.map_or(d.travel_samples, |c| c.0),
                envelope: None,
            },
            swing_margin_deg: g.swing_margin_deg.map_or(0.0, |r| r.0),
            max_time_ratio: g.max_time_ratio.map_or(f64::INFINITY, |r| r.0),
        })
    }
}

/// The constraints as plain data (for pickling).
pub(crate) type ConstraintState = (Option<Vec<(f64, f64)>>, Vec<Vec<(f64, f64)>>, f64, usize);

/// The constraints of a map or a drive as plain data (for pickling).
pub(crate) fn constraint_state(c: &Constraints) -> ConstraintState {
    let pts = |v: &[Point2<f64>]| v.iter().map(|p| pt(*p)).collect::<Vec<_>>();
    (
        c.base_plate.as_deref().map(pts),
        c.obstacles.iter().map(|o| pts(o)).collect(),
        c.link_width,
        c.travel_samples,
    )
}

/// The constraints of their plain data ([`constraint_state`]).
pub(crate) fn constraints_of(
    s: (Option<Vec<PyPoint>>, Vec<Vec<PyPoint>>, f64, usize),
) -> Constraints {
    let pts = |v: Vec<PyPoint>| v.into_iter().map(|p| p.0).collect::<Vec<_>>();
    Constraints {
        base_plate: s.0.map(pts),
        obstacles: s.1.into_iter().map(pts).collect(),
        link_width: s.2,
        travel_samples: s.3,
        envelope: None,
    }
}
