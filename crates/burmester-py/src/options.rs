//! The one extractor of the map option keywords (`limits`, its three
//! keywords, and the constraints), for every method that takes them: the
//! solution maps, the pair map, the atlas tile and the drives. A method
//! takes them as `**options` and names which of them it accepts
//! ([`Keys`]); the names, types and defaults are written here only.

use burmester::{Constraints, DesignLimits, InputRequirement, MapOptions, Point2};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::classes::PyDesignLimits;
use crate::conv::{Count, PyPoint, Real, pt};
use crate::errors::IntoPy;

/// Calls `$callback! { $args ... }` (the callback given as the tokens of
/// its path in brackets, then its own arguments) with the map option
/// keywords and the drive's two, each as `name: type, whether None is
/// accepted (as not given), its default as the signatures show it, [taken
/// by the maps, the drives, the classic drive, an actuator]`, in the order
/// the signatures list them (every one may be left out; the defaults are
/// those of [`DesignLimits`], [`Constraints`] and the drive's: no swing
/// margin, no time ratio limit). The one list of the names: the extractor
/// ([`Keys`], [`Keywords`]) and the methods' text signatures
/// ([`text_signature!`]) are made from it.
macro_rules! map_option_keywords {
    ([$($callback:tt)*] $($args:tt)*) => {
        $($callback)*! { $($args)*
            limits: PyDesignLimits, true, "None", [true true true true];
            min_transmission_deg: Real, true, "None", [true true true true];
            max_link_ratio: Real, true, "None", [true true true true];
            input: String, true, "None", [true false false false];
            swing_margin_deg: Real, false, "0.0", [false true true false];
            max_time_ratio: Real, true, "None", [false true true false];
            base_plate: Vec<PyPoint>, true, "None", [true true false true];
            obstacles: Vec<Vec<PyPoint>>, true, "None", [true true false false];
            link_width: Real, false, "0.0", [true true false true];
            travel_samples: Count, false, "64", [true true false false];
        }
    };
}

macro_rules! define_keywords {
    ($($name:ident: $ty:ty, $none:literal, $default:literal, [$m:tt $d:tt $c:tt $a:tt];)*) => {
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
            /// The map option keywords (the solution maps, the pair map, the
            /// atlas): every one but the drive's.
            pub(crate) const MAP: Keys = Keys { $($name: $m,)* };
            /// The drives' keywords: every one but `input` (a drive's input
            /// is the motor's crank).
            pub(crate) const DRIVE: Keys = Keys { $($name: $d,)* };
            /// The classic drive's: the limits but `input`, and the drive's,
            /// no constraints.
            pub(crate) const CLASSIC: Keys = Keys { $($name: $c,)* };
            /// An actuator's: the limits but `input` (the actuator drives),
            /// and the base plate (its ground pivot's only constraint).
            pub(crate) const ACTUATOR: Keys = Keys { $($name: $a,)* };

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

map_option_keywords!([define_keywords]);

/// The option keywords of the set `$keys` (`MAP`, `DRIVE`, `CLASSIC` or
/// `ACTUATOR`, as [`Keys`]) as a signature lists them: `, name=default`
/// each, in order (a string literal, for `concat!`).
macro_rules! keywords_signature {
    ($keys:ident; $($name:ident: $ty:ty, $none:literal, $default:literal, [$($f:tt)*];)*) => {
        concat!($($crate::options::keywords_signature!(@one $keys [$($f)*] $name $default)),*)
    };
    (@one MAP [true $d:tt $c:tt $a:tt] $name:ident $default:literal) => {
        concat!(", ", stringify!($name), "=", $default)
    };
    (@one DRIVE [$m:tt true $c:tt $a:tt] $name:ident $default:literal) => {
        concat!(", ", stringify!($name), "=", $default)
    };
    (@one CLASSIC [$m:tt $d:tt true $a:tt] $name:ident $default:literal) => {
        concat!(", ", stringify!($name), "=", $default)
    };
    (@one ACTUATOR [$m:tt $d:tt $c:tt true] $name:ident $default:literal) => {
        concat!(", ", stringify!($name), "=", $default)
    };
    (@one $keys:ident [$($f:tt)*] $name:ident $default:literal) => {
        ""
    };
}

/// The Python text signature of a method taking the option keywords of
/// `$keys` (see [`Keys`]) as `**options`, for `#[doc = ...]` above a method
/// marked `text_signature = None` (pyo3 takes only a literal there):
/// `$head` (`"name($self, ..."`, up to the keywords), the keywords, then
/// `$tail` (`", progress=None"`, up to the closing parenthesis), then the
/// line that ends a signature;
/// `doc` where doc comments follow (pyo3 joins them with a newline).
macro_rules! text_signature {
    ($keys:ident, $head:literal, $tail:literal) => {
        concat!($crate::options::text_signature!($keys, $head, $tail, doc), "\n")
    };
    ($keys:ident, $head:literal, $tail:literal, doc) => {
        concat!(
            $head,
            $crate::options::map_option_keywords!([$crate::options::keywords_signature] $keys;),
            $tail,
            ")\n--\n"
        )
    };
}

pub(crate) use {keywords_signature, map_option_keywords, text_signature};

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

/// The option keywords of a call: the limits and the constraints, not yet
/// checked ([`Keywords::checked`] gives the core's [`MapOptions`]), and
/// the drive's swing margin (degrees) and largest time ratio.
pub(crate) struct Keywords {
    pub(crate) limits: DesignLimits,
    pub(crate) constraints: Constraints,
    pub(crate) swing_margin_deg: f64,
    pub(crate) max_time_ratio: f64,
}

impl Keywords {
    /// The limits and the constraints, checked by the core.
    pub(crate) fn checked(&self) -> PyResult<MapOptions> {
        MapOptions::new(&self.limits, &self.constraints).py()
    }

    /// The options from the keywords `options` of method `method` (its
    /// name, for the error of a keyword it does not take), which accepts
    /// `keys`; [`checked`](Self::checked) validates the values.
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
        Ok(Keywords {
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

/// The checked map options ([`Keys::MAP`]) of the keywords `options` of
/// method `method`: what every map method takes.
pub(crate) fn map_options(
    method: &str,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<MapOptions> {
    Keywords::from_kwargs(method, options, Keys::MAP)?.checked()
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
