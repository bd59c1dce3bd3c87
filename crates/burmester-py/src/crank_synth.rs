//! What `burmester.SynthesizedSliderCrank` and
//! `burmester.SynthesizedInvertedSliderCrank` share, written once: the
//! fields read from the core's crank-driven synthesized linkages (whose
//! branch, order and travel methods come from the core's
//! `synthesis::crank_travel`), pickling through the task, equality, the
//! travel's angles and the pose at a crank angle; and the equality and
//! pickling of their solved positions. Also what the linkages themselves
//! (`burmester.SliderCrank`, `burmester.InvertedSliderCrank`) and their
//! solved positions share: the fields derived once and equality.

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
/// `travel_angles`, `pose_at` and `__repr__` (the linkage's lengths named
/// after `repr`, the branch and the direction); and the constructor
/// `Task.$ctor(driving, driven)` (two point pairs), whose body makes the
/// class from the core task `$tk` and the two pairs.
macro_rules! synthesized_crank {
    (
        $(#[$meta:meta])*
        pub struct $Py:ident($Core:ty, $name:literal, linkage: $PyLinkage:ty);
        fn new($s:ident, $task:ident $(, $arg:ident: $argty:ty)*) {
            $($(#[$fmeta:meta])* $field:ident: $fty:ty = $init:expr,)*
        }
        reduce with key($this:ident) = $key:expr;
        repr $($part:ident),+;
        $(#[$cmeta:meta])*
        fn $ctor:ident($tk:ident, $driving:ident, $driven:ident) $body:block
    ) => {
        $crate::crank_synth::frozen_class! {
            $(#[$meta])*
            $Py($Core, $name) {
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
        }}

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
                Ok((task.getattr(stringify!($ctor))?, args))
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
            fn __repr__(&self) -> String {
                let l = &self.inner.linkage;
                format!(
                    concat!("<", $name, $(" ", stringify!($part), "={:.6}",)+
                        " branch_free={} direction={}>"),
                    $(l.$part(),)+
                    $crate::conv::py_bool(self.inner.is_branch_free()),
                    self.inner.direction
                )
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

        #[::pyo3::pymethods]
        impl $crate::classes::PyTask {
            $(#[$cmeta])*
            fn $ctor(
                &self,
                $driving: ($crate::conv::PyPoint, $crate::conv::PyPoint),
                $driven: ($crate::conv::PyPoint, $crate::conv::PyPoint),
            ) -> ::pyo3::PyResult<$Py> {
                let $tk = self.inner;
                $body
            }
        }
    };
}

pub(crate) use synthesized_crank;

/// `$(#[$meta])* pub struct $Py { inner: $Core, fields }` as a frozen,
/// cloneable class named `$name` of the module `burmester`.
macro_rules! frozen_class {
    ($(#[$meta:meta])* $Py:ident($Core:ty, $name:literal) { $($fields:tt)* }) => {
        $(#[$meta])*
        #[::pyo3::pyclass(frozen, name = $name, module = "burmester")]
        #[derive(Clone)]
        pub struct $Py {
            inner: $Core,
            $($fields)*
        }
    };
}

pub(crate) use frozen_class;

/// The class `$Py` (Python name `$name`) of a core linkage `$Core` driven
/// by a crank (the slider-crank and the inverted slider-crank), and the
/// class `$Conf` (Python name `$conf_name`) of its solved positions
/// `$ConfCore`.
///
/// `$Py`: what it derives without arguments, computed once in
/// `From<$Core>` and read as fields (`crank`, `pivot`, `offset`,
/// `turns_fully`, `input_range`, `dead_positions`, then the fields given,
/// each with its expression of the core linkage `$s`); `__eq__` (the same
/// core linkage); `__getnewargs_ex__` (`crank`, `pivot` and the keywords
/// given after `by name`, expressions of `$s`); `coupler_point` and
/// `coupler_path`.
///
/// `$Conf`: its fields (`theta2`, `theta3`, `$along`, `mode`, `toggle`,
/// `transmission_angle`) read once in `$Conf::new(c, linkage)`, `__repr__`
/// (`$conf_name(theta2=.., theta3=.., $along=.., mode=.., toggle=..)`),
/// `__eq__` (the same position of the same linkage) and `__reduce__`
/// (through `$Py.solve(theta2, mode)`).
macro_rules! crank_linkage {
    (
        $(#[$meta:meta])*
        pub struct $Py:ident($Core:ty, $name:literal);
        fn from($s:ident) {
            $($(#[$fmeta:meta])* $field:ident: $fty:ty = $init:expr,)*
        }
        by name { $($kw:literal: $kwvalue:expr,)* }
        $(#[$cmeta:meta])*
        pub struct $Conf:ident($ConfCore:ty, $conf_name:literal, $along:ident);
    ) => {
        $crate::crank_synth::frozen_class! {
            $(#[$meta])*
            $Py($Core, $name) {
            #[pyo3(get)]
            crank: f64,
            #[pyo3(get)]
            pivot: (f64, f64),
            #[pyo3(get)]
            offset: f64,
            #[pyo3(get)]
            turns_fully: bool,
            /// `None` when the crank turns fully, else its `(start, end)` arcs.
            #[pyo3(get)]
            input_range: Option<Vec<(f64, f64)>>,
            #[pyo3(get)]
            dead_positions: Vec<f64>,
            $($(#[$fmeta])* $field: $fty,)*
        }}

        impl From<$Core> for $Py {
            fn from($s: $Core) -> Self {
                let range = $s.input_range();
                let (arcs, n) = range.arcs_array();
                $Py {
                    inner: $s,
                    crank: $s.crank(),
                    pivot: $crate::conv::pt($s.crank_pivot()),
                    offset: $s.offset(),
                    turns_fully: range.is_full(),
                    input_range: (!range.is_full())
                        .then(|| arcs[..n].iter().map(|a| (a.start, a.end)).collect()),
                    dead_positions: range.dead_positions(),
                    $($field: $init,)*
                }
            }
        }

        #[::pyo3::pymethods]
        impl $Py {
            fn __eq__(&self, other: &::pyo3::Bound<'_, ::pyo3::PyAny>) -> bool {
                other
                    .cast::<$Py>()
                    .is_ok_and(|o| o.get().inner == self.inner)
            }
        }

        $crate::pickle::new_by_name!($Py, $s => {
            "crank": $s.crank(),
            "pivot": $crate::conv::pt($s.crank_pivot()),
            $($kw: $kwvalue,)*
        });

        $crate::linkage::coupler_methods!($Py);

        $crate::crank_synth::frozen_class! {
            $(#[$cmeta])*
            $Conf($ConfCore, $conf_name) {
            /// The linkage it is a position of (for pickling).
            linkage: $Core,
            #[pyo3(get)]
            theta2: f64,
            #[pyo3(get)]
            theta3: f64,
            #[pyo3(get)]
            $along: f64,
            #[pyo3(get)]
            mode: &'static str,
            #[pyo3(get)]
            toggle: bool,
            #[pyo3(get)]
            transmission_angle: f64,
        }}

        impl $Conf {
            fn new(c: $ConfCore, linkage: $Core) -> Self {
                $Conf {
                    inner: c,
                    linkage,
                    theta2: c.theta2,
                    theta3: c.theta3,
                    $along: c.$along,
                    mode: c.mode.as_str(),
                    toggle: c.toggle,
                    transmission_angle: c.transmission_angle,
                }
            }
        }

        #[::pyo3::pymethods]
        impl $Conf {
            fn __repr__(&self) -> String {
                let c = &self.inner;
                let along = (stringify!($along), c.$along);
                let (angles, mode) = ([c.theta2, c.theta3], c.mode);
                $crate::linkage::configuration_repr($conf_name, angles, along, mode, c.toggle)
            }
            fn __eq__(&self, other: &::pyo3::Bound<'_, ::pyo3::PyAny>) -> bool {
                other.cast::<$Conf>().is_ok_and(|o| {
                    let o = o.get();
                    o.inner == self.inner && o.linkage == self.linkage
                })
            }
            fn __reduce__<'py>(
                &self,
                py: ::pyo3::Python<'py>,
            ) -> ::pyo3::PyResult<(::pyo3::Bound<'py, ::pyo3::PyAny>, (f64, &'static str))> {
                use ::pyo3::types::PyAnyMethods;
                let sc = ::pyo3::Bound::new(py, $Py::from(self.linkage))?;
                Ok((
                    sc.getattr("solve")?,
                    (self.inner.theta2, self.inner.mode.as_str()),
                ))
            }
        }
    };
}

pub(crate) use crank_linkage;
