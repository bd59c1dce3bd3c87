//! `burmester.DesignLimits`, `burmester.SolutionMap` and `burmester.Pivot`
//! (the core's `design`).

use burmester::design::ColumnsOut;
use burmester::{
    Control, DesignLimits, Filemon, Grid, InputRequirement, MapContext, MapOptions, Pivot, RankBy,
    Task, Varying,
};
use numpy::ndarray::Array2;
use numpy::{Element, IntoPyArray, PyArray2, PyArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use crate::classes::{PyDesignLimits, PyFilemon, PySynthesizedFourBar, PyTask};
use crate::conv::{Count, PyPoint, Real, pt};
use crate::errors::IntoPy;
use crate::geom::PyGrid;
use crate::geom::grid_alone;
use crate::getters::getters;
use crate::options::{constraint_state, constraints_of, map_options, text_signature};
use crate::run::{WATCH_MIN_SAMPLES, run};

type Xy = (f64, f64);

#[pymethods]
impl PyDesignLimits {
    #[new]
    #[pyo3(signature = (min_transmission_deg = Real(30.0), max_link_ratio = Real(10.0), input = "any",
        max_size_ratio = Real(f64::INFINITY), max_link_length = Real(f64::INFINITY),
        min_grashof_margin = Real(DesignLimits::DEFAULT_GRASHOF_MARGIN)),
        text_signature = "(min_transmission_deg=30.0, max_link_ratio=10.0, input='any', \
        max_size_ratio=inf, max_link_length=inf, min_grashof_margin=0.01)")]
    fn new(
        min_transmission_deg: Real,
        max_link_ratio: Real,
        input: &str,
        max_size_ratio: Real,
        max_link_length: Real,
        min_grashof_margin: Real,
    ) -> PyResult<Self> {
        let input = input.parse::<InputRequirement>().py()?;
        DesignLimits::from_degrees(min_transmission_deg.0, max_link_ratio.0, input)
            .and_then(|l| l.with_size(max_size_ratio.0, max_link_length.0))
            .and_then(|l| l.with_grashof_margin(min_grashof_margin.0))
            .map(|inner| PyDesignLimits { inner })
            .py()
    }
    /// The shortest decimal number of degrees that gives the limit in
    /// radians exactly (so `DesignLimits(30).min_transmission_deg == 30`,
    /// not `29.999999999999996`, and pickling gives back an equal object).
    #[getter]
    fn min_transmission_deg(&self) -> f64 {
        shortest_degrees(self.inner.min_transmission)
    }
    fn __getnewargs__(&self) -> (f64, f64, &'static str, f64, f64, f64) {
        (
            self.min_transmission_deg(),
            self.inner.max_link_ratio,
            self.inner.input.as_str(),
            self.inner.max_size_ratio,
            self.inner.max_link_length,
            self.inner.min_grashof_margin,
        )
    }
    fn __repr__(&self) -> String {
        let mut extra = String::new();
        if self.inner.max_size_ratio.is_finite() {
            extra += &format!(", max_size_ratio={:?}", self.inner.max_size_ratio);
        }
        if self.inner.max_link_length.is_finite() {
            extra += &format!(", max_link_length={:?}", self.inner.max_link_length);
        }
        if self.inner.min_grashof_margin != DesignLimits::DEFAULT_GRASHOF_MARGIN {
            extra += &format!(", min_grashof_margin={:?}", self.inner.min_grashof_margin);
        }
        format!(
            "DesignLimits(min_transmission_deg={:?}, max_link_ratio={:?}, input='{}'{extra})",
            self.min_transmission_deg(),
            self.inner.max_link_ratio,
            self.inner.input.as_str()
        )
    }
}

getters!(PyDesignLimits, inner {
    f64: max_link_ratio, max_size_ratio, max_link_length, min_grashof_margin;
    str: input;
});

/// The shortest decimal (at most 17 significant digits) whose conversion to
/// radians is `rad`; `rad` in degrees when none is.
fn shortest_degrees(rad: f64) -> f64 {
    let deg = rad.to_degrees();
    (0..17)
        .filter_map(|digits| format!("{deg:.digits$e}").parse::<f64>().ok())
        .find(|d| d.to_radians() == rad)
        .unwrap_or(deg)
}

/// The values of a column (a pickled map's), copied into memory reserved
/// fallibly (a `MemoryError` rather than an abort).
pub(crate) fn collect_column<T: Copy>(v: &numpy::ndarray::ArrayView2<'_, T>) -> PyResult<Vec<T>> {
    let mut out = Vec::new();
    out.try_reserve_exact(v.len()).map_err(|_| {
        pyo3::exceptions::PyMemoryError::new_err(format!(
            "a map column of {} values cannot be allocated",
            v.len()
        ))
    })?;
    out.extend(v.iter().copied());
    Ok(out)
}

/// Whether ranking `n` samples for `k` results can take long enough to
/// watch for Ctrl-C (a few milliseconds and more).
pub(crate) fn ranking_is_long(n: usize, k: usize) -> bool {
    n >= 1 << 16 || k >= 1 << 12
}

/// A column of a map as a read-only NumPy array of shape `(ny, nx)`,
/// taking the buffer (no copy).
pub(crate) fn readonly<T: Element>(
    py: Python<'_>,
    (ny, nx): (usize, usize),
    v: Vec<T>,
) -> PyResult<Py<PyArray2<T>>> {
    let a = Array2::from_shape_vec((ny, nx), v)
        .expect("one value per sample")
        .into_pyarray(py);
    set_readonly(a.as_any())?;
    Ok(a.unbind())
}

/// A column of a pickled map, read without trusting its values: its dtype
/// and shape checked (a `TypeError` otherwise), and a bool column read as
/// its bytes, since NumPy keeps any byte in a bool array and only 0 and 1
/// are bools (a `bool` of another byte is undefined behaviour in Rust).
pub(crate) trait StateColumn: Sized {
    /// The column `name`, of shape `shape`, from `item`.
    fn read(
        item: Bound<'_, PyAny>,
        name: &'static str,
        shape: (usize, usize),
    ) -> PyResult<Vec<Self>>;
}

/// `item` as a 2-d array of `T`; a `TypeError` naming the column `name` of
/// a pickled map otherwise.
fn column_array<'py, T: Element>(
    item: Bound<'py, PyAny>,
    name: &str,
) -> PyResult<Bound<'py, PyArray2<T>>> {
    item.cast_into::<PyArray2<T>>().map_err(|e| {
        PyTypeError::new_err(format!(
            "column {name} of a pickled map: {}",
            PyErr::from(e)
        ))
    })
}

/// The values of a 2-d array of `T` of shape `shape`, in row-major order.
fn read_plain<T: Element + Copy>(
    item: Bound<'_, PyAny>,
    name: &'static str,
    shape: (usize, usize),
) -> PyResult<Vec<T>> {
    let a = column_array::<T>(item, name)?;
    let ro = a.readonly();
    let v = ro.as_array();
    if v.shape() != [shape.0, shape.1] {
        return Err(PyTypeError::new_err(format!(
            "column {name} of a pickled map has shape {:?}, not the map's {:?}",
            v.shape(),
            [shape.0, shape.1]
        )));
    }
    collect_column(&v)
}

macro_rules! plain_state_column {
    ($($t:ty),*) => {$(
        impl StateColumn for $t {
            fn read(
                item: Bound<'_, PyAny>,
                name: &'static str,
                shape: (usize, usize),
            ) -> PyResult<Vec<Self>> {
                read_plain::<$t>(item, name, shape)
            }
        }
    )*};
}
plain_state_column!(u8, i8, f32);

impl StateColumn for bool {
    fn read(
        item: Bound<'_, PyAny>,
        name: &'static str,
        shape: (usize, usize),
    ) -> PyResult<Vec<Self>> {
        // The dtype first (no element is read), then the bytes.
        let a = column_array::<bool>(item, name)?;
        let bytes = a.as_any().call_method1("view", ("u1",))?;
        let v = read_plain::<u8>(bytes, name, shape)?;
        if let Some(k) = v.iter().position(|&b| b > 1) {
            return Err(bad_state(
                name,
                k,
                shape.1,
                format!("the byte {} (a bool is 0 or 1)", v[k]),
            ));
        }
        Ok(v.into_iter().map(|b| b == 1).collect())
    }
}

/// The error of a pickled map whose column `name` holds, at sample `k` of
/// rows of `nx`, what `what` says.
fn bad_state(name: &str, k: usize, nx: usize, what: String) -> PyErr {
    crate::errors::invalid(
        "inconsistent_state",
        format!(
            "unpickling a map: column {name} holds {what} at row {}, column {}, which no map \
             holds; the pickle was damaged or not made by burmester: compute the map again",
            k / nx,
            k % nx
        ),
    )
}

/// Refuses the columns of a pickled map that no map holds: a Grashof code
/// that names no class, a direction other than -1, 0, 1, an angle outside
/// `[0, pi/2]`, a ratio below 1, an invalid sample with values, a valid one
/// without them, a travel without a direction (or the other way round), an
/// acceptable sample that is not branch-free, feasible and within the
/// limits; a Grashof class where `no_grashof` (a map of slider-cranks,
/// `map_state::NoGrashof`), none elsewhere. (The bool bytes are checked
/// as they are read.)
pub(crate) fn check_state(
    c: &burmester::design::Columns,
    nx: usize,
    limits: &DesignLimits,
    no_grashof: bool,
) -> PyResult<()> {
    use burmester::{Grashof, SolutionMap};
    // f32 columns hold the f64 figures rounded: allow their rounding.
    let slack = 1.0 + 4.0 * f64::from(f32::EPSILON);
    let half_pi = core::f64::consts::FRAC_PI_2 as f32;
    for k in 0..c.valid.len() {
        let bad = |name: &str, what: String| Err(bad_state(name, k, nx, what));
        let (g, d) = (c.grashof[k], c.direction[k]);
        if usize::from(g) >= Grashof::ALL.len() && g != SolutionMap::GRASHOF_NONE {
            return bad(
                "grashof",
                format!(
                    "the code {g} (Grashof codes are 0 to {} and {} for none)",
                    Grashof::ALL.len() - 1,
                    SolutionMap::GRASHOF_NONE
                ),
            );
        }
        if !(-1..=1).contains(&d) {
            return bad(
                "direction",
                format!("the code {d} (directions are -1, 0 and 1)"),
            );
        }
        let (mt, lr, sr) = (c.min_transmission_rad[k], c.link_ratio[k], c.size_ratio[k]);
        if !c.valid[k] {
            // Sample::INVALID, every column.
            let empty = !c.branch_free[k]
                && g == SolutionMap::GRASHOF_NONE
                && !c.input_full[k]
                && d == 0
                && !c.one_circuit[k]
                && mt.is_nan()
                && lr.is_nan()
                && sr.is_nan()
                && !c.acceptable[k];
            if !empty {
                return bad(
                    "valid",
                    "false with other columns set (a sample without a linkage holds false, 0, \
                     NaN and the Grashof code 255)"
                        .to_owned(),
                );
            }
            continue;
        }
        if (g == SolutionMap::GRASHOF_NONE) != no_grashof {
            return bad("grashof", crate::map_state::grashof_problem(no_grashof));
        }
        if lr.is_nan() || lr < 1.0 {
            return bad("link_ratio", format!("{lr} (at least 1 for a linkage)"));
        }
        if sr.is_nan() || sr <= 0.0 {
            return bad("size_ratio", format!("{sr} (positive for a linkage)"));
        }
        if (d == 0) != mt.is_nan() || !(mt.is_nan() || (0.0..=half_pi).contains(&mt)) {
            return bad(
                "min_transmission_rad",
                format!(
                    "{mt} with the direction {d} (an angle in [0, pi/2] with a direction, NaN \
                     without)"
                ),
            );
        }
        if c.input_full[k] && !c.one_circuit[k] {
            return bad(
                "one_circuit",
                "false for an input that turns fully (one circuit)".to_owned(),
            );
        }
        if !c.one_circuit[k] && d != 0 {
            return bad("direction", format!("{d} for poses on two circuits (0)"));
        }
        if c.acceptable[k] {
            let input_ok = match limits.input {
                InputRequirement::Any => true,
                InputRequirement::Crank => c.input_full[k],
                InputRequirement::Rocker => !c.input_full[k],
            };
            let meets = c.branch_free[k]
                && d != 0
                && input_ok
                && f64::from(lr) <= limits.max_link_ratio * slack
                && f64::from(mt) * slack >= limits.min_transmission;
            if !meets {
                return bad(
                    "acceptable",
                    "true for a sample that is not branch-free, feasible and within the map's \
                     limits"
                        .to_owned(),
                );
            }
        }
    }
    Ok(())
}

/// `a.setflags(write=False)`.
pub(crate) fn set_readonly(a: &Bound<'_, PyAny>) -> PyResult<()> {
    let kw = PyDict::new(a.py());
    kw.set_item("write", false)?;
    a.call_method("setflags", (), Some(&kw))?;
    Ok(())
}

/// A column's values, for comparing maps (floats by their bits, so that
/// NaN equals NaN).
pub(crate) trait Bits: Copy {
    fn bits(self) -> u64;
}

impl Bits for bool {
    fn bits(self) -> u64 {
        u64::from(self)
    }
}

impl Bits for u8 {
    fn bits(self) -> u64 {
        u64::from(self)
    }
}

impl Bits for i8 {
    fn bits(self) -> u64 {
        self as u8 as u64
    }
}

impl Bits for f32 {
    fn bits(self) -> u64 {
        u64::from(self.to_bits())
    }
}

pub(crate) fn same_column<T: Element + Bits>(
    py: Python<'_>,
    a: &Py<PyArray2<T>>,
    b: &Py<PyArray2<T>>,
) -> bool {
    let (a, b) = (a.bind(py).readonly(), b.bind(py).readonly());
    match (a.as_slice(), b.as_slice()) {
        (Ok(a), Ok(b)) => a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.bits() == y.bits()),
        _ => false,
    }
}

/// The limits of a map class's context: a field of a solution map's
/// ([`MapContext`]), part of a pair map's checked options
/// ([`burmester::PairContext::map_options`]).
pub(crate) trait ContextLimits {
    /// The limits behind `acceptable`.
    fn context_limits(&self) -> DesignLimits;
}

impl ContextLimits for MapContext {
    fn context_limits(&self) -> DesignLimits {
        self.limits
    }
}

impl ContextLimits for burmester::PairContext {
    fn context_limits(&self) -> DesignLimits {
        *self.limits()
    }
}

/// Defines a Python map class `$cls` (named `$pyname`) holding a context
/// of type `$ctx` and the solution map's columns as read-only NumPy arrays
/// of shape `(rows, columns)`: the one definition of how a map's columns
/// cross to Python, for every map that has them.
macro_rules! py_map_class {
    ($cls:ident, $pyname:literal, $ctx:ty, $best:ident => $item:ident;
     $($(#[$doc:meta])* $name:ident: $ty:ty = $invalid:expr,)*) => {
        /// A map with the solution map's columns (see the stub for the docs).
        #[pyclass(frozen, name = $pyname, module = "burmester")]
        pub struct $cls {
            pub(crate) context: $ctx,
            $($(#[$doc])* #[pyo3(get)] $name: Py<PyArray2<$ty>>,)*
        }

        impl $cls {
            /// The best samples by `ranking` (`$item` records), reading the
            /// NumPy columns in place.
            fn ranked<'py>(
                &self,
                py: Python<'py>,
                ranking: burmester::Ranking,
            ) -> PyResult<Bound<'py, pyo3::types::PyList>> {
                let ctx = &self.context;
                let watch = $crate::design::ranking_is_long(ctx.grid.len(), ranking.k());
                let best = self.with_rank_columns(py, |cols| {
                    $crate::run::run_in(py, watch, None, None, "samples", |control| {
                        ctx.$best(ranking, cols, control)
                    })
                })?;
                $crate::run::list_polled(py, &best, |b| {
                    Ok(Bound::new(py, $item::of(ctx.task, b))?.into_any())
                })
            }
            /// A map whose columns NumPy allocates (`numpy.empty`: pages
            /// mapped lazily, huge pages asked for on large arrays, as for
            /// a fresh branch map), `fill` writes (the core's `_into` map)
            /// and then are made read-only.
            pub(crate) fn filled(
                py: Python<'_>,
                shape: (usize, usize),
                fill: impl FnOnce(burmester::design::ColumnsOut<'_>) -> PyResult<$ctx>,
            ) -> PyResult<Self> {
                $(
                    let $name = $crate::conv::empty::<$ty>(py, &[shape.0, shape.1])?
                        .cast_into::<PyArray2<$ty>>()
                        .map_err(PyErr::from)?;
                )*
                let context = {
                    $(let mut $name = $name.readwrite();)*
                    fill(burmester::design::ColumnsOut {
                        $($name: $name.as_slice_mut()?,)*
                    })?
                };
                $($crate::design::set_readonly($name.as_any())?;)*
                Ok($cls {
                    $($name: $name.unbind(),)*
                    context,
                })
            }

            /// The columns by name.
            fn column_dict<'py>(
                &self,
                py: Python<'py>,
            ) -> PyResult<Bound<'py, pyo3::types::PyDict>> {
                let d = pyo3::types::PyDict::new(py);
                $(d.set_item(stringify!($name), self.$name.clone_ref(py))?;)*
                Ok(d)
            }

            /// A map from its context and its columns by name (copied), each
            /// of shape `shape`.
            fn from_columns(
                py: Python<'_>,
                context: $ctx,
                shape: (usize, usize),
                columns: &Bound<'_, pyo3::types::PyDict>,
            ) -> PyResult<Self> {
                $(
                    let $name: Vec<$ty> = {
                        let item = columns.get_item(stringify!($name))?.ok_or_else(|| {
                            pyo3::exceptions::PyTypeError::new_err(concat!("missing column ", stringify!($name)))
                        })?;
                        <$ty as $crate::design::StateColumn>::read(item, stringify!($name), shape)?
                    };
                )*
                // Values and rows a map can hold, and nothing else.
                let cols = burmester::design::Columns { $($name,)* };
                let no_grashof = $crate::map_state::NoGrashof::no_grashof(&context);
                let limits = $crate::design::ContextLimits::context_limits(&context);
                $crate::design::check_state(&cols, shape.1, &limits, no_grashof)?;
                let burmester::design::Columns { $($name,)* } = cols;
                Ok($cls {
                    $($name: $crate::design::readonly(py, shape, $name)?,)*
                    context,
                })
            }

            /// Equal to `other` (a Python object): a map of the same class,
            /// context and columns (`__eq__`).
            fn equals(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> bool {
                other.cast::<$cls>().is_ok_and(|o| {
                    let o = o.get();
                    o.context == self.context
                        $(&& $crate::design::same_column(py, &self.$name, &o.$name))*
                })
            }

            /// The columns a ranking reads, borrowed from the arrays, passed
            /// to `f`.
            pub(crate) fn with_rank_columns<R>(
                &self,
                py: Python<'_>,
                f: impl FnOnce(burmester::design::RankColumns<'_>) -> PyResult<R>,
            ) -> PyResult<R> {
                let valid = self.valid.bind(py).readonly();
                let bf = self.branch_free.bind(py).readonly();
                let mt = self.min_transmission_rad.bind(py).readonly();
                let lr = self.link_ratio.bind(py).readonly();
                let sr = self.size_ratio.bind(py).readonly();
                let acc = self.acceptable.bind(py).readonly();
                f(burmester::design::RankColumns {
                    valid: valid.as_slice()?,
                    branch_free: bf.as_slice()?,
                    min_transmission_rad: mt.as_slice()?,
                    link_ratio: lr.as_slice()?,
                    size_ratio: sr.as_slice()?,
                    acceptable: acc.as_slice()?,
                })
            }
        }

        $crate::geom::grid_map_getters!($cls, burmester::design::Columns, [context.grid]);

        /// What every map with the solution map's columns offers Python
        /// (each map's own methods are in its module).
        #[pymethods]
        impl $cls {
            /// The names of the Grashof codes, by code.
            #[classattr]
            fn grashof_names() -> Vec<&'static str> {
                burmester::Grashof::ALL.iter().map(|g| g.as_str()).collect()
            }
            #[getter]
            fn task(&self) -> $crate::classes::PyTask {
                $crate::classes::PyTask {
                    inner: self.context.task,
                }
            }
            #[getter]
            fn limits(&self) -> $crate::classes::PyDesignLimits {
                $crate::classes::PyDesignLimits {
                    inner: $crate::design::ContextLimits::context_limits(&self.context),
                }
            }
            fn __reduce__<'py>(&self, py: Python<'py>) -> $crate::pickle::Reduced<'py> {
                $crate::pickle::reduce_to::<$cls>(py, "_from_state", self.state(py)?)
            }
            fn pareto_front<'py>(
                &self,
                py: Python<'py>,
            ) -> PyResult<Bound<'py, pyo3::types::PyList>> {
                self.ranked(py, burmester::Ranking::pareto_front())
            }
            /// A picture for Jupyter: PNG bytes drawn by `burmester._display`,
            /// or None without matplotlib.
            fn _repr_png_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
                $crate::display::repr_png(slf.as_any())
            }
        }
    };
}
pub(crate) use py_map_class;

macro_rules! py_solution_map {
    ($($t:tt)*) => {
        py_map_class!(PySolutionMap, "SolutionMap", MapContext, best_pivots_with => PyPivot; $($t)*);
    };
}

burmester::solution_map_columns!(py_solution_map);

/// What a ranked sample of a map holds besides its place (`Pivot`,
/// `Pair`, `SliderPivot`): its sample `(j, i)`, its linkage (of the class
/// `L`), its margin, its score and the ranking that scored it.
#[derive(Clone)]
pub(crate) struct Ranked<L> {
    pub(crate) index: (usize, usize),
    pub(crate) linkage: L,
    pub(crate) margin: f64,
    pub(crate) score: f64,
    pub(crate) ranked_by: RankBy,
}

impl<L> Ranked<L> {
    /// The ranked part of `__new__`'s arguments (the ranking by its name).
    pub(crate) fn new(
        index: (Count, Count),
        linkage: L,
        (margin, score): (Real, Real),
        ranked_by: &str,
    ) -> PyResult<Self> {
        Ok(Ranked {
            index: (index.0.0, index.1.0),
            linkage,
            margin: margin.0,
            score: score.0,
            ranked_by: ranked_by.parse::<RankBy>().py()?,
        })
    }

    /// The same ranking of the same linkage as `o` (the linkages compared
    /// by `key`, floats by their bits), for `__eq__`.
    pub(crate) fn same<K: PartialEq>(&self, o: &Self, key: impl Fn(&L) -> K) -> bool {
        o.index == self.index
            && key(&o.linkage) == key(&self.linkage)
            && o.margin.to_bits() == self.margin.to_bits()
            && o.score.to_bits() == self.score.to_bits()
            && o.ranked_by == self.ranked_by
    }
}

impl Ranked<PySynthesizedFourBar> {
    /// The end of the repr: the Grashof class, the transmission, the size
    /// ratio and the ranking.
    pub(crate) fn repr(&self) -> String {
        let f = &self.linkage.inner.figures;
        let mu = if f.min_transmission.is_nan() {
            "None".to_owned()
        } else {
            format!("{:.3}", f.min_transmission.to_degrees())
        };
        let size = self.linkage.size_ratio();
        let by = self.ranked_by.as_str();
        format!(
            "{} min_transmission_deg={mu} size_ratio={size:.3} by {by}",
            f.grashof
        )
    }
}

/// The [`Ranked`] part of the core's ranked sample `$p` (a `Pivot`, a
/// `SliderPivot` or a `Pair`, whose fields have the same names), its
/// linkage wrapped as `$linkage`.
macro_rules! ranked_of {
    ($p:expr, $linkage:expr) => {
        $crate::design::Ranked {
            index: $p.index,
            linkage: $linkage,
            margin: $p.margin,
            score: $p.score,
            ranked_by: $p.ranked_by,
        }
    };
}
pub(crate) use ranked_of;

/// The getters a ranked sample of a map shares (`Pivot`, `Pair`,
/// `SliderPivot`): `#[pymethods]` blocks for `$cls`, which reads them from
/// its field `ranked` (a [`Ranked`] of the linkage class `$L`). Without
/// `$L`: a four-bar's, with the figures and the size ratio.
macro_rules! ranked_getters {
    ($cls:ident) => {
        $crate::design::ranked_getters!($cls, $crate::classes::PySynthesizedFourBar);

        #[pymethods]
        impl $cls {
            #[getter]
            fn figures(&self) -> $crate::linkage::PyLinkageFigures {
                self.ranked.linkage.figures()
            }
            #[getter]
            fn size_ratio(&self) -> f64 {
                self.ranked.linkage.size_ratio()
            }
        }
    };
    ($cls:ident, $L:ty) => {
        #[pymethods]
        impl $cls {
            #[getter]
            fn linkage(&self) -> $L {
                self.ranked.linkage.clone()
            }
        }

        $crate::getters::getters!($cls, ranked {
            (usize, usize): index;
            f64: margin, score;
            str: ranked_by;
        });
    };
}
pub(crate) use ranked_getters;

/// The `#[pymethods]` block of a ranking method `$name` of the map class
/// `$cls` (`k=5, min_separation=None, rank_by='balanced'`), delegating to
/// its `$ranked(py, ranking)` with the keywords checked once into a
/// [`burmester::Ranking`], which returns a list (`-> $ret` where that is
/// not a `PyList`).
macro_rules! ranking_method {
    ($cls:ident, $name:ident, $ranked:ident) => {
        $crate::design::ranking_method!(
            $cls, $name, $ranked -> Bound<'py, pyo3::types::PyList>
        );
    };
    ($cls:ident, $name:ident, $ranked:ident -> $ret:ty) => {
        #[pymethods]
        impl $cls {
            #[pyo3(signature = (k = $crate::conv::Count(5), min_separation = None, rank_by = "balanced"),
                text_signature = "($self, /, k=5, min_separation=None, rank_by='balanced')")]
            fn $name<'py>(
                &self,
                py: Python<'py>,
                k: $crate::conv::Count,
                min_separation: Option<$crate::conv::Real>,
                rank_by: &str,
            ) -> PyResult<$ret> {
                use $crate::errors::IntoPy;
                let rank_by = rank_by.parse::<burmester::RankBy>().py()?;
                let separation = min_separation.map(|r| r.0);
                let ranking = burmester::Ranking::try_new(k.0, separation, rank_by).py()?;
                self.$ranked(py, ranking)
            }
        }
    };
}
pub(crate) use ranking_method;

/// `__getnewargs__` (the arguments of `__new__`) and `__eq__` (the same
/// center and ranking, floats by their bits, the linkages by `$key`) of a
/// ranked pivot `$cls` (`Pivot`, `SliderPivot`) whose linkage is a `$L`.
macro_rules! pivot_methods {
    ($cls:ident, $L:ty, $key:expr) => {
        #[pymethods]
        impl $cls {
            #[allow(clippy::type_complexity)]
            fn __getnewargs__(&self) -> ((f64, f64), (usize, usize), $L, f64, f64, &'static str) {
                let r = &self.ranked;
                (
                    self.center,
                    r.index,
                    r.linkage.clone(),
                    r.margin,
                    r.score,
                    r.ranked_by.as_str(),
                )
            }
            fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
                other.cast::<$cls>().is_ok_and(|o| {
                    let o = o.get();
                    o.center == self.center && self.ranked.same(&o.ranked, $key)
                })
            }
        }
    };
}
pub(crate) use pivot_methods;

ranked_getters!(PyPivot);

/// A candidate pivot of a solution map with its linkage.
#[pyclass(frozen, name = "Pivot", module = "burmester")]
#[derive(Clone)]
pub struct PyPivot {
    center: Xy,
    ranked: Ranked<PySynthesizedFourBar>,
}

impl PyPivot {
    fn of(task: Task, p: &Pivot) -> Self {
        PyPivot {
            center: pt(p.center),
            ranked: ranked_of!(p, PySynthesizedFourBar::new(task, p.linkage)),
        }
    }
}

#[pymethods]
impl PyPivot {
    #[new]
    fn new(
        center: PyPoint,
        index: (Count, Count),
        linkage: PySynthesizedFourBar,
        margin: Real,
        score: Real,
        ranked_by: &str,
    ) -> PyResult<Self> {
        // A pivot is one of its linkage's fixed pivots.
        let l = &linkage.inner;
        if center.0 != l.driving.center && center.0 != l.driven.center {
            return Err(crate::errors::invalid(
                "inconsistent_state",
                format!(
                    "a Pivot at ({}, {}) with a linkage whose fixed pivots are {:?} and {:?}: \
                     the pivot must be one of them",
                    center.0.x,
                    center.0.y,
                    pt(l.driving.center),
                    pt(l.driven.center)
                ),
            ));
        }
        let ranked = Ranked::new(index, linkage, (margin, score), ranked_by)?;
        Ok(PyPivot {
            center: pt(center.0),
            ranked,
        })
    }
    fn __repr__(&self) -> String {
        let (x, y) = self.center;
        let index = self.ranked.index;
        format!(
            "<Pivot center=({x:.6}, {y:.6}) index={index:?} {}>",
            self.ranked.repr()
        )
    }
}

getters!(PyPivot {
    Xy: center;
});

pivot_methods!(PyPivot, PySynthesizedFourBar, PySynthesizedFourBar::clone);

ranking_method!(PySolutionMap, best_pivots, ranked);

impl PySolutionMap {
    /// The arguments of `_from_state` (for pickling).
    fn state<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let c = &self.context;
        let fixed = crate::map_state::fixed_tuple(&c.varying);
        let grid = PyGrid { inner: c.grid };
        let (task, limits) = (self.task(), self.limits());
        let columns = self.column_dict(py)?;
        let constraints = constraint_state(&c.constraints);
        (
            grid,
            task,
            crate::map_state::varying_state(&c.varying),
            fixed,
            limits,
            constraints,
            columns,
        )
            .into_pyobject(py)
    }
}

#[pymethods]
impl PySolutionMap {
    #[getter]
    fn fixed_dyad(&self) -> (Xy, Xy) {
        crate::map_state::fixed_tuple(&self.context.varying)
    }
    fn point(&self, j: Count, i: Count) -> PyResult<Xy> {
        self.grid().point(j, i)
    }
    fn linkage(&self, j: Count, i: Count) -> PyResult<PySynthesizedFourBar> {
        self.point(j, i)?;
        let k = j.0 * self.context.grid.nx() + i.0;
        self.context
            .linkage(k)
            .map(|l| PySynthesizedFourBar::new(self.context.task, l))
            .py()
    }
    fn margin(&self, py: Python<'_>, j: Count, i: Count) -> PyResult<f64> {
        self.point(j, i)?;
        let k = j.0 * self.context.grid.nx() + i.0;
        let bf = self.branch_free.bind(py).readonly();
        let bf = bf.as_slice()?;
        let ctx = &self.context;
        Ok(py.detach(|| ctx.margin(k, bf)))
    }

    /// Rebuilds a map from its state (for pickling).
    #[staticmethod]
    #[allow(clippy::too_many_arguments)]
    fn _from_state(
        py: Python<'_>,
        grid: PyGrid,
        task: PyTask,
        varying: &str,
        fixed: (PyPoint, PyPoint),
        limits: PyDesignLimits,
        constraints: (Option<Vec<PyPoint>>, Vec<Vec<PyPoint>>, f64, usize),
        columns: &Bound<'_, PyDict>,
    ) -> PyResult<Self> {
        let varying = crate::map_state::varying_of(varying, fixed)?;
        let context = MapContext {
            grid: grid.inner,
            task: task.inner,
            varying,
            limits: limits.inner,
            constraints: constraints_of(constraints),
        };
        check_context(py, &context)?;
        let shape = (context.grid.ny(), context.grid.nx());
        Self::from_columns(py, context, shape, columns)
    }

    fn __eq__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> bool {
        self.equals(py, other)
    }

    fn __repr__(&self) -> String {
        let (ny, nx) = self.shape();
        format!("<SolutionMap {} pivots, {ny} x {nx}>", self.varying())
    }
}

getters!(PySolutionMap, context {
    str: varying;
});

/// Refuses the context of a pickled map that no map has: a fixed dyad that
/// is not the task's (a driving map's driven dyad is the task's dyad of its
/// center, bit for bit; a driven map's driving dyad must be a dyad of the
/// task), or limits and constraints a map refuses. The core decides, on a
/// map of one sample of the grid's view (its checks come before any work).
fn check_context(py: Python<'_>, c: &MapContext) -> PyResult<()> {
    let v = c.grid.viewport();
    let probe = Grid::from_bounds(v.xmin, v.xmax, v.ymin, v.ymax, 1, 1).py()?;
    let control = burmester::Control::new();
    let opts = MapOptions::new(&c.limits, &c.constraints).py()?;
    py.detach(|| match c.varying {
        Varying::Driving { driven } => {
            let f = c.task.filemon(driven.center)?;
            if f.driven() != driven.into() {
                return Ok(Err(()));
            }
            f.solution_map(&probe, &opts, &control).map(|_| Ok(()))
        }
        Varying::Driven { driving } => c
            .task
            .driven_solution_map(&driving, &probe, &opts, &control)
            .map(|_| Ok(())),
        Varying::DrivingSlider { driven } => Filemon::new(&c.task, driven)?
            .solution_map(&probe, &opts, &control)
            .map(|_| Ok(())),
    })
    .py()?
    .map_err(|()| {
        crate::errors::invalid(
            "inconsistent_state",
            "unpickling a map: its driven dyad is not the task's dyad of its center; the \
             pickle was damaged or not made by burmester: compute the map again",
        )
    })
}

/// `solution_map` of a Python class `$cls` whose `inner` is a `Filemon`
/// (`Filemon`, `SliderFilemon`), named `$name` in errors.
macro_rules! filemon_solution_map_method {
    ($cls:ty, $name:literal) => {
        /// The solution map over candidate driving pivots.
        #[pymethods]
        impl $cls {
            #[doc = $crate::options::text_signature!(MAP, "solution_map($self, *grid", ", progress=None")]
            #[pyo3(signature = (*grid, progress = None, **options), text_signature = None)]
            fn solution_map(
                &self,
                py: Python<'_>,
                grid: &Bound<'_, pyo3::types::PyTuple>,
                progress: Option<&Bound<'_, PyAny>>,
                options: Option<&Bound<'_, pyo3::types::PyDict>>,
            ) -> PyResult<$crate::design::PySolutionMap> {
                let f = self.inner;
                $crate::design::filemon_solution_map(py, f, $name, grid, progress, options)
            }
        }
    };
}
pub(crate) use filemon_solution_map_method;

filemon_solution_map_method!(PyFilemon, "Filemon.solution_map");

/// `Filemon.solution_map` and `SliderFilemon.solution_map` (named `name`)
/// from their Python arguments.
pub(crate) fn filemon_solution_map(
    py: Python<'_>,
    f: Filemon,
    name: &'static str,
    grid: &Bound<'_, PyTuple>,
    progress: Option<&Bound<'_, PyAny>>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<PySolutionMap> {
    let what = "solution_map takes a grid (or its six numbers); the limits go by keyword";
    let (g, opts) = map_arguments(name, what, grid, options)?;
    grid_map(py, &g, progress, |out, control| {
        f.solution_map_into(&g, &opts, out, control)
    })
}

/// The driven solution map of `Task` (candidate driven pivots).
#[pymethods]
impl PyTask {
    #[doc = text_signature!(
        MAP,
        "driven_solution_map($self, driving_center, *grid",
        ", progress=None"
    )]
    #[pyo3(signature = (driving_center, *grid, progress = None, **options),
        text_signature = None)]
    fn driven_solution_map(
        &self,
        py: Python<'_>,
        driving_center: PyPoint,
        grid: &Bound<'_, PyTuple>,
        progress: Option<&Bound<'_, PyAny>>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PySolutionMap> {
        let what = "driven_solution_map takes the driving center and a grid (or its six numbers)";
        let (g, opts) = map_arguments("Task.driven_solution_map", what, grid, options)?;
        let task = self.inner;
        let driving = task.dyad_from_center(driving_center.0).py()?;
        grid_map(py, &g, progress, |out, control| {
            task.driven_solution_map_into(&driving, &g, &opts, out, control)
        })
    }
}

/// The grid (a `Grid` or its six numbers; `what` says so in the error)
/// and the checked map options of the arguments of map method `method`.
fn map_arguments(
    method: &str,
    what: &'static str,
    grid: &Bound<'_, PyTuple>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<(Grid, MapOptions)> {
    Ok((grid_alone(grid, what)?, map_options(method, options)?))
}

/// A solution map over `grid`: fresh NumPy columns filled by `map_into`
/// (the core's `_into` map), Ctrl-C watched and `progress` followed on a
/// large grid.
fn grid_map(
    py: Python<'_>,
    grid: &Grid,
    progress: Option<&Bound<'_, PyAny>>,
    map_into: impl FnOnce(ColumnsOut<'_>, &Control<'_>) -> burmester::Result<MapContext> + Send,
) -> PyResult<PySolutionMap> {
    let watch = grid.len() >= WATCH_MIN_SAMPLES / 16;
    PySolutionMap::filled(py, (grid.ny(), grid.nx()), |out| {
        run(py, watch, progress, None, |control| map_into(out, control))
    })
}
