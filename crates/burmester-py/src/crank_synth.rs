//! What `burmester.SynthesizedSliderCrank` and
//! `burmester.SynthesizedInvertedSliderCrank` share, written once: the
//! fields read from the core's crank-driven synthesized linkages (whose
//! branch, order and travel methods come from the core's
//! `synthesis::crank_travel`), pickling through the task, equality, the
//! travel's angles and the pose at a crank angle; and the equality and
//! pickling of their solved positions.

/// What a synthesized crank-driven linkage is built from besides the task:
/// its two dyads as `((x, y), (x, y))` each.
pub(crate) type Key = (((f64, f64), (f64, f64)), ((f64, f64), (f64, f64)));

/// `None` for NaN.
pub(crate) fn finite_or_none(v: f64) -> Option<f64> {
    (!v.is_nan()).then_some(v)
}

/// The class `$Py` (Python name `$name`) of a core synthesized linkage
/// `$Core` driven by a crank: the shared fields, `$Py::new(s, task,
/// args...)` filling them with the fields given after them (each with its
/// expression of `s`, `task` and the arguments), and `__reduce__` (through
/// `Task.$ctor` with `key(self)`), `__eq__` (task and `key`, bit for bit),
/// `travel_angles` and `pose_at`.
macro_rules! synthesized_crank {
    (
        $(#[$meta:meta])*
        pub struct $Py:ident($Core:ty, $name:literal, linkage: $PyLinkage:ty);
        fn new($s:ident, $task:ident $(, $arg:ident: $argty:ty)*) {
            $($(#[$fmeta:meta])* $field:ident: $fty:ty = $init:expr,)*
        }
        reduce $ctor:literal with key($this:ident) = $key:expr;
    ) => {
        $(#[$meta])*
        #[::pyo3::pyclass(frozen, name = $name, module = "burmester")]
        #[derive(Clone)]
        pub struct $Py {
            inner: $Core,
            /// The task it was built for (for pickling).
            task: ::burmester::Task,
            #[pyo3(get)]
            linkage: $PyLinkage,
            /// `(A0, A1)`.
            #[pyo3(get)]
            driving: ((f64, f64), (f64, f64)),
            #[pyo3(get)]
            input_angles: Vec<f64>,
            #[pyo3(get)]
            modes: Vec<Option<&'static str>>,
            #[pyo3(get)]
            coupler_point: (f64, f64),
            #[pyo3(get)]
            coupler_angle_offset: f64,
            #[pyo3(get)]
            direction: &'static str,
            #[pyo3(get)]
            one_circuit: bool,
            #[pyo3(get)]
            min_transmission_deg: Option<f64>,
            #[pyo3(get)]
            stroke_used: Option<f64>,
            #[pyo3(get)]
            size: f64,
            #[pyo3(get)]
            size_ratio: f64,
            #[pyo3(get)]
            branch_free: bool,
            #[pyo3(get)]
            feasible: bool,
            /// The cyclic order of the crank's positions, `"1-2-3"`.
            #[pyo3(get)]
            order: String,
            #[pyo3(get)]
            travel: Option<(f64, f64)>,
            #[pyo3(get)]
            travel_stops: Option<Vec<f64>>,
            $($(#[$fmeta])* $field: $fty,)*
        }

        impl $Py {
            pub(crate) fn new($s: $Core, $task: ::burmester::Task $(, $arg: $argty)*) -> Self {
                use $crate::crank_synth::finite_or_none;
                let d = &$s.driving;
                $Py {
                    inner: $s,
                    task: $task,
                    linkage: $s.linkage.into(),
                    driving: ($crate::conv::pt(d.center), $crate::conv::pt(d.circle)),
                    input_angles: $s.input_angles.to_vec(),
                    modes: $s
                        .modes
                        .iter()
                        .map(|m| m.map(::burmester::AssemblyMode::as_str))
                        .collect(),
                    coupler_point: ($s.coupler_point.x, $s.coupler_point.y),
                    coupler_angle_offset: $s.coupler_angle_offset,
                    direction: $s.direction.as_str(),
                    one_circuit: $s.one_circuit,
                    min_transmission_deg: finite_or_none($s.min_transmission).map(f64::to_degrees),
                    stroke_used: finite_or_none($s.stroke_used),
                    size: $s.size(),
                    size_ratio: $s.size() / $task.span(),
                    branch_free: $s.is_branch_free(),
                    feasible: $s.feasible(),
                    order: $s.order().to_string(),
                    travel: $s.travel(),
                    travel_stops: $s.travel_stops().map(|t| t.to_vec()),
                    $($field: $init,)*
                }
            }

            /// What it was built from besides the task: the arguments of
            /// `Task.$ctor`.
            fn key(&self) -> $crate::crank_synth::Key {
                let $this = self;
                $key
            }
        }

        #[::pyo3::pymethods]
        impl $Py {
            fn __reduce__<'py>(&self, py: ::pyo3::Python<'py>) -> $crate::pickle::Reduced<'py> {
                use ::pyo3::IntoPyObject;
                use ::pyo3::types::PyAnyMethods;
                let task = ::pyo3::Bound::new(py, $crate::classes::PyTask { inner: self.task })?;
                let args = self.key().into_pyobject(py)?;
                Ok((task.getattr($ctor)?, args))
            }
            /// Equal when built from the same task and arguments, bit for
            /// bit (the rest is a function of them; NaN figures would make
            /// a field-wise comparison unequal to itself).
            fn __eq__(&self, other: &::pyo3::Bound<'_, ::pyo3::PyAny>) -> bool {
                                let bits = |(a, b): $crate::crank_synth::Key| {
                    [a.0.0, a.0.1, a.1.0, a.1.1, b.0.0, b.0.1, b.1.0, b.1.1].map(f64::to_bits)
                };
                other.cast::<$Py>().is_ok_and(|o| {
                    let o = o.get();
                    o.task == self.task && bits(o.key()) == bits(self.key())
                })
            }
            fn travel_angles<'py>(
                &self,
                py: ::pyo3::Python<'py>,
                samples: $crate::conv::Count,
            ) -> ::pyo3::PyResult<::pyo3::Bound<'py, ::numpy::PyArrayDyn<f64>>> {
                use $crate::errors::IntoPy;
                let s = self.inner;
                let v = py.detach(|| s.travel_angles(samples.0)).py()?;
                Ok($crate::conv::to_numpy(py, &[v.len()], v))
            }
            #[pyo3(signature = (theta2, mode = "open"))]
            fn pose_at(
                &self,
                theta2: $crate::conv::Real,
                mode: &str,
            ) -> ::pyo3::PyResult<(f64, f64, f64)> {
                use $crate::errors::IntoPy;
                let m = $crate::linkage::mode(mode)?;
                let p = self.inner.pose_at(theta2.0, m).py()?;
                Ok((p.position.x, p.position.y, p.angle))
            }
        }
    };
}

pub(crate) use synthesized_crank;

/// `__repr__` (`$name(theta2=.., theta3=.., $along=.., mode=.., toggle=..)`),
/// `__eq__` (the same position of the same linkage) and `__reduce__`
/// (through `$PyLinkage.solve(theta2, mode)`) of a solved position `$Py`
/// of a crank-driven linkage, with the fields `inner` (the core's
/// configuration) and `linkage` (the core's linkage).
macro_rules! configuration_methods {
    ($Py:ident, $PyLinkage:ident, $name:literal, $along:ident) => {
        #[::pyo3::pymethods]
        impl $Py {
            fn __repr__(&self) -> String {
                let c = &self.inner;
                format!(
                    concat!(
                        $name,
                        "(theta2={:?}, theta3={:?}, ",
                        stringify!($along),
                        "={:?}, mode='{}', toggle={})"
                    ),
                    c.theta2,
                    c.theta3,
                    c.$along,
                    c.mode.as_str(),
                    if c.toggle { "True" } else { "False" }
                )
            }
            fn __eq__(&self, other: &::pyo3::Bound<'_, ::pyo3::PyAny>) -> bool {
                other.cast::<$Py>().is_ok_and(|o| {
                    let o = o.get();
                    o.inner == self.inner && o.linkage == self.linkage
                })
            }
            fn __reduce__<'py>(
                &self,
                py: ::pyo3::Python<'py>,
            ) -> ::pyo3::PyResult<(::pyo3::Bound<'py, ::pyo3::PyAny>, (f64, &'static str))> {
                use ::pyo3::types::PyAnyMethods;
                let sc = ::pyo3::Bound::new(py, $PyLinkage::from(self.linkage))?;
                Ok((
                    sc.getattr("solve")?,
                    (self.inner.theta2, self.inner.mode.as_str()),
                ))
            }
        }
    };
}

pub(crate) use configuration_methods;
