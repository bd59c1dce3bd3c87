//! `burmester.ActuatorMap` and `burmester.Actuator`, and the actuator
//! methods of `SynthesizedFourBar` (the core's `design::actuator`): a
//! linear actuator added between a ground pivot and a point of a moving
//! link.

use burmester::design::{Actuator, ActuatorContext, ActuatorMap, ActuatorOptions};
use burmester::{
    ActuatorLink, Constraints, DesignLimits, Grid, MapOptions, Point2, RankBy, Ranking, Task,
};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use crate::classes::{PyDesignLimits, PySynthesizedFourBar};
use crate::conv::{Count, PyPoint, Real, pt};
use crate::design::{ranking_method, set_readonly};
use crate::errors::IntoPy;
use crate::geom::PyGrid;
use crate::geom::{grid_alone, grid_map_getters};
use crate::getters::getters;
use crate::options::{Keys, Keywords, constraint_state, constraints_of, text_signature};
use crate::run::{WATCH_MIN_SAMPLES, run};

type Xy = (f64, f64);

/// What an actuator is placed for: the link, the point, the options, the
/// limits and the base plate.
struct ActuatorArgs {
    point: Option<Point2<f64>>,
    options: ActuatorOptions,
    map_options: MapOptions,
}

impl ActuatorArgs {
    /// `terms`: the link, the point, the stroke ratio limit, the travel's
    /// samples; `strut`: the strut's diameter and least gap.
    fn new(
        method: &str,
        terms: (&str, Option<PyPoint>, Real, Count),
        strut: (Real, Real),
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Self> {
        let (link, point, max_stroke_ratio, samples) = terms;
        let k = Keywords::from_kwargs(method, options, Keys::ACTUATOR)?;
        Ok(ActuatorArgs {
            point: point.map(|p| p.0),
            options: ActuatorOptions {
                link: link.parse::<ActuatorLink>().py()?,
                max_stroke_ratio: max_stroke_ratio.0,
                travel_samples: samples.0,
                actuator_width: strut.0.0,
                min_gap: strut.1.0,
            },
            map_options: k.checked()?,
        })
    }

    /// The context on `grid`; the point by default: the link's moving
    /// joint at pose 1 (the crank's `A`, the rocker's `C`), the middle of
    /// the coupler's `A C`.
    fn context(&self, linkage: &PySynthesizedFourBar, grid: &Grid) -> PyResult<ActuatorContext> {
        let l = &linkage.inner;
        let (a, c) = (l.driving.circle, l.driven.circle);
        let q = self.point.unwrap_or(match self.options.link {
            ActuatorLink::Crank => a,
            ActuatorLink::Rocker => c,
            ActuatorLink::Coupler => a + (c - a) * 0.5,
        });
        ActuatorContext::new(l, q, grid, &self.map_options, &self.options).py()
    }
}

/// A one-sample grid about `p` (the context of a single placement).
fn point_grid(p: Point2<f64>) -> PyResult<Grid> {
    let h = 1.0 + p.x.abs().max(p.y.abs());
    Grid::from_bounds(p.x - h, p.x + h, p.y - h, p.y + h, 1, 1).py()
}

/// An actuator placement and its figures (read-only attributes, see the
/// stub).
#[pyclass(frozen, name = "Actuator", module = "burmester")]
#[derive(Clone)]
pub struct PyActuator {
    inner: Actuator,
    task: Task,
    context: ActuatorContext,
    #[pyo3(get)]
    link: &'static str,
    #[pyo3(get)]
    ground: Xy,
    #[pyo3(get)]
    point: Xy,
    #[pyo3(get)]
    pose_lengths: Vec<f64>,
    #[pyo3(get)]
    turning_points: Vec<f64>,
    /// `(monotone, extends, acceptable)`.
    flags: (bool, bool, bool),
    /// `(min_length, max_length, stroke, stroke_ratio)`.
    lengths: [f64; 4],
    /// `(min_transmission_deg, worst_angle, link_ratio, size_ratio, margin,
    /// score, max_stroke_ratio)`.
    figures: [f64; 7],
}

impl PyActuator {
    fn of(inner: Actuator, task: Task, context: &ActuatorContext) -> Self {
        let a = &inner;
        PyActuator {
            link: a.link.as_str(),
            ground: pt(a.ground),
            point: pt(a.point),
            pose_lengths: a.pose_lengths.to_vec(),
            turning_points: a.turning_points.clone(),
            flags: (a.monotone, a.extends, a.acceptable),
            lengths: [a.min_length, a.max_length, a.stroke, a.stroke_ratio],
            figures: [
                a.min_transmission.to_degrees(),
                a.worst_angle,
                a.link_ratio,
                a.size_ratio,
                a.margin,
                a.score,
                context.options().max_stroke_ratio,
            ],
            task,
            context: context.clone(),
            inner,
        }
    }
}

impl PyActuator {
    /// A placement found elsewhere (by `Task::design`) with the terms it
    /// was found under.
    pub(crate) fn found(
        inner: Actuator,
        task: Task,
        options: &ActuatorOptions,
        limits: &DesignLimits,
        constraints: &Constraints,
    ) -> PyResult<Self> {
        let grid = point_grid(inner.ground)?;
        let map_options = MapOptions::new(limits, constraints).py()?;
        let context =
            ActuatorContext::new(&inner.linkage, inner.point, &grid, &map_options, options).py()?;
        Ok(PyActuator::of(inner, task, &context))
    }

    /// The placement and the terms it was found under.
    pub(crate) fn parts(&self) -> (Actuator, (ActuatorOptions, DesignLimits, Constraints)) {
        let c = &self.context;
        (
            self.inner.clone(),
            (*c.options(), *c.limits(), c.constraints().clone()),
        )
    }
}

getters!(PyActuator, inner {
    f64: min_clearance, clearance_angle;
    bool: clear;
});
// The strut's terms it was placed under, and the map's.
getters!(PyActuator, [context.options()] { f64: actuator_width, min_gap; });
getters!(PyActuator, [context.constraints()] { f64: link_width; });
getters!(PyActuatorMap, [map.context.options()] { f64: max_stroke_ratio, actuator_width, min_gap; });

/// The figures by name, each a getter of one element of
/// [`PyActuator`]'s arrays.
macro_rules! actuator_getters {
    ($($name:ident: $ty:ty = $field:ident $(. $idx:tt)? $([$at:literal])?;)*) => {
        #[pymethods]
        impl PyActuator {
            $(
                #[getter]
                fn $name(&self) -> $ty {
                    self.$field $(.$idx)? $([$at])?
                }
            )*
        }
    };
}

actuator_getters! {
    monotone: bool = flags.0;
    extends: bool = flags.1;
    acceptable: bool = flags.2;
    min_length: f64 = lengths[0];
    max_length: f64 = lengths[1];
    stroke: f64 = lengths[2];
    stroke_ratio: f64 = lengths[3];
    min_transmission_deg: f64 = figures[0];
    worst_angle: f64 = figures[1];
    link_ratio: f64 = figures[2];
    size_ratio: f64 = figures[3];
    margin: f64 = figures[4];
    score: f64 = figures[5];
    max_stroke_ratio: f64 = figures[6];
}

#[pymethods]
impl PyActuator {
    #[getter]
    fn linkage(&self) -> PySynthesizedFourBar {
        PySynthesizedFourBar::new(self.task, self.inner.linkage)
    }
    #[getter]
    fn index(&self) -> Option<(usize, usize)> {
        self.inner.index
    }
    #[getter]
    fn ranked_by(&self) -> Option<&'static str> {
        self.inner.ranked_by.map(RankBy::as_str)
    }
    #[getter]
    fn limits(&self) -> PyDesignLimits {
        PyDesignLimits {
            inner: *self.context.limits(),
        }
    }

    /// `((x, y), s)`: the moving point and the actuator's length at input
    /// angle `theta2`.
    fn at(&self, theta2: Real) -> PyResult<(Xy, f64)> {
        let (q, s) = self.inner.at(theta2.0).py()?;
        Ok((pt(q), s))
    }

    /// `(theta2, x, y, s)` arrays over the travel, `samples` input angles
    /// from the first pose to the last.
    #[pyo3(signature = (samples = Count(64)), text_signature = "($self, samples=64)")]
    #[allow(clippy::type_complexity)]
    fn travel<'py>(
        &self,
        py: Python<'py>,
        samples: Count,
    ) -> PyResult<(
        Bound<'py, PyArray1<f64>>,
        Bound<'py, PyArray1<f64>>,
        Bound<'py, PyArray1<f64>>,
        Bound<'py, PyArray1<f64>>,
    )> {
        let thetas = self.inner.linkage.travel_angles(samples.0).py()?;
        let mut xs = Vec::with_capacity(thetas.len());
        let mut ys = Vec::with_capacity(thetas.len());
        let mut ss = Vec::with_capacity(thetas.len());
        for &t in &thetas {
            let (q, s) = self.inner.at(t).py()?;
            xs.push(q.x);
            ys.push(q.y);
            ss.push(s);
        }
        Ok((
            PyArray1::from_vec(py, thetas),
            PyArray1::from_vec(py, xs),
            PyArray1::from_vec(py, ys),
            PyArray1::from_vec(py, ss),
        ))
    }

    /// Rebuilds a placement from its state (for pickling).
    #[staticmethod]
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (linkage, point, ground, limits, options, constraints, extra, envelope = None,
        strut = None))]
    fn _from_state(
        linkage: PySynthesizedFourBar,
        point: PyPoint,
        ground: PyPoint,
        limits: PyDesignLimits,
        options: (String, f64, usize),
        constraints: (Option<Vec<PyPoint>>, Vec<Vec<PyPoint>>, f64, usize),
        extra: (Option<(usize, usize)>, f64, f64, Option<String>),
        envelope: Option<Vec<PyPoint>>,
        strut: Option<(f64, f64)>,
    ) -> PyResult<Self> {
        let context = context_of(
            &linkage,
            point,
            ground.0,
            limits,
            (options, strut),
            constraints,
            envelope,
        )?;
        let mut a = context.placement(ground.0).py()?;
        a.index = extra.0;
        a.margin = extra.1;
        a.score = extra.2;
        a.ranked_by = extra.3.map(|s| s.parse::<RankBy>()).transpose().py()?;
        Ok(PyActuator::of(a, linkage.task(), &context))
    }

    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let a = &self.inner;
        let args = (
            self.linkage(),
            pt(a.point),
            pt(a.ground),
            self.limits(),
            options_state(self.context.options()),
            constraint_state(self.context.constraints()),
            (a.index, a.margin, a.score, self.ranked_by()),
            self.context
                .constraints()
                .envelope
                .as_ref()
                .map(|e| e.iter().map(|p| pt(*p)).collect::<Vec<_>>()),
            strut_state(self.context.options()),
        )
            .into_pyobject(py)?;
        Ok((py.get_type::<PyActuator>().getattr("_from_state")?, args))
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<PyActuator>().is_ok_and(|o| {
            let (a, b) = (&o.get().inner, &self.inner);
            // NaN margins and scores compare equal by their bits.
            let same = |x: f64, y: f64| x.to_bits() == y.to_bits();
            let (mut x, mut y) = (a.clone(), b.clone());
            (x.margin, x.score, y.margin, y.score) = (0.0, 0.0, 0.0, 0.0);
            x == y
                && same(a.margin, b.margin)
                && same(a.score, b.score)
                && o.get().task == self.task
                && same_terms(&o.get().context, &self.context)
        })
    }

    fn __repr__(&self) -> String {
        let a = &self.inner;
        format!(
            "<Actuator {} ground=({:.6}, {:.6}) monotone={} stroke_ratio={:.3} \
             min_transmission_deg={:.3} acceptable={}>",
            a.link.as_str(),
            a.ground.x,
            a.ground.y,
            if a.monotone { "True" } else { "False" },
            a.stroke_ratio,
            a.min_transmission.to_degrees(),
            if a.acceptable { "True" } else { "False" }
        )
    }
}

/// Whether two contexts place under the same terms (the linkage, the
/// point, the limits, options and constraints; not the grid).
fn same_terms(a: &ActuatorContext, b: &ActuatorContext) -> bool {
    a.linkage() == b.linkage()
        && a.point() == b.point()
        && a.limits() == b.limits()
        && a.options() == b.options()
        && a.constraints() == b.constraints()
}

/// The options as plain data (for pickling).
fn options_state(o: &ActuatorOptions) -> (&'static str, f64, usize) {
    (o.link.as_str(), o.max_stroke_ratio, o.travel_samples)
}

/// The strut's diameter and least gap as plain data (for pickling; a
/// pickle without them, from before they were options, reads as 0, 0).
fn strut_state(o: &ActuatorOptions) -> (f64, f64) {
    (o.actuator_width, o.min_gap)
}

/// The context of a pickled map or placement.
fn context_of(
    linkage: &PySynthesizedFourBar,
    point: PyPoint,
    at: Point2<f64>,
    limits: PyDesignLimits,
    (options, strut): ((String, f64, usize), Option<(f64, f64)>),
    constraints: (Option<Vec<PyPoint>>, Vec<Vec<PyPoint>>, f64, usize),
    envelope: Option<Vec<PyPoint>>,
) -> PyResult<ActuatorContext> {
    let (actuator_width, min_gap) = strut.unwrap_or((0.0, 0.0));
    let options = ActuatorOptions {
        link: options.0.parse::<ActuatorLink>().py()?,
        max_stroke_ratio: options.1,
        travel_samples: options.2,
        actuator_width,
        min_gap,
    };
    let grid = point_grid(at)?;
    let constraints = Constraints {
        envelope: envelope.map(|e| e.into_iter().map(|p| p.0).collect()),
        ..constraints_of(constraints)
    };
    let map_options = MapOptions::new(&limits.inner, &constraints).py()?;
    ActuatorContext::new(&linkage.inner, point.0, &grid, &map_options, &options).py()
}

/// A NumPy 2-D array of a column (read-only).
fn column<'py, T: numpy::Element + Copy>(
    py: Python<'py>,
    shape: (usize, usize),
    v: &[T],
) -> PyResult<Py<PyAny>> {
    let a = PyArray1::from_slice(py, v).reshape([shape.0, shape.1])?;
    set_readonly(a.as_any())?;
    Ok(a.into_any().unbind())
}

macro_rules! py_actuator_map {
    ($($(#[$doc:meta])* $name:ident: $ty:ty = $invalid:expr,)*) => {
        /// An actuator map: over a grid of candidate ground pivots, each
        /// sample's figures as NumPy columns (the map is computed again when
        /// unpickled: it is a function of what it was computed for).
        #[pyclass(frozen, name = "ActuatorMap", module = "burmester")]
        pub struct PyActuatorMap {
            map: ActuatorMap,
            task: Task,
            $($(#[$doc])* #[pyo3(get)] $name: Py<PyAny>,)*
        }

        impl PyActuatorMap {
            fn new(py: Python<'_>, map: ActuatorMap, task: Task) -> PyResult<Self> {
                let g = map.context.grid();
                let shape = (g.ny(), g.nx());
                $(let $name = column(py, shape, &map.columns.$name)?;)*
                Ok(PyActuatorMap {
                    map,
                    task,
                    $($name,)*
                })
            }
        }

        /// Whether two maps' columns hold the same bits (NaN equal to NaN).
        fn same_columns(a: &ActuatorMap, b: &ActuatorMap) -> bool {
            let (a, b) = (&a.columns, &b.columns);
            true $(&& SameBits::same_bits(&a.$name, &b.$name))*
        }
    };
}

/// Equality of a column's values by their bits (NaN equal to NaN).
trait SameBits {
    fn same_bits(a: &Self, b: &Self) -> bool;
}

impl SameBits for Vec<bool> {
    fn same_bits(a: &Self, b: &Self) -> bool {
        a == b
    }
}

impl SameBits for Vec<f32> {
    fn same_bits(a: &Self, b: &Self) -> bool {
        a.len() == b.len() && a.iter().zip(b).all(|(p, q)| p.to_bits() == q.to_bits())
    }
}

burmester::actuator_map_columns!(py_actuator_map);

ranking_method!(PyActuatorMap, best_placements, ranked -> Vec<PyActuator>);

impl PyActuatorMap {
    /// The best placements by `ranking`.
    fn ranked(&self, py: Python<'_>, ranking: Ranking) -> PyResult<Vec<PyActuator>> {
        let map = &self.map;
        let found = py.detach(|| map.best_placements(ranking)).py()?;
        Ok(found
            .into_iter()
            .map(|a| PyActuator::of(a, self.task, &map.context))
            .collect())
    }

    fn sample(&self, j: Count, i: Count) -> PyResult<usize> {
        self.grid().point(j, i)?;
        Ok(j.0 * self.map.context.grid().nx() + i.0)
    }
}

grid_map_getters!(
    PyActuatorMap,
    burmester::design::ActuatorColumns,
    [map.context.grid()]
);

#[pymethods]
impl PyActuatorMap {
    #[getter]
    fn linkage(&self) -> PySynthesizedFourBar {
        PySynthesizedFourBar::new(self.task, *self.map.context.linkage())
    }
    #[getter]
    fn link(&self) -> &'static str {
        self.map.context.options().link.as_str()
    }
    #[getter]
    fn point(&self) -> Xy {
        pt(self.map.context.point())
    }
    #[getter]
    fn point_at_poses(&self) -> Vec<Xy> {
        self.map
            .context
            .point_at_poses()
            .iter()
            .map(|p| pt(*p))
            .collect()
    }
    #[getter]
    fn limits(&self) -> PyDesignLimits {
        PyDesignLimits {
            inner: *self.map.context.limits(),
        }
    }
    #[getter]
    fn samples(&self) -> usize {
        self.map.context.options().travel_samples
    }
    /// The candidate ground pivot of sample `(j, i)`.
    fn ground(&self, j: Count, i: Count) -> PyResult<Xy> {
        self.grid().point(j, i)
    }
    /// The placement of sample `(j, i)`.
    fn placement(&self, j: Count, i: Count) -> PyResult<PyActuator> {
        let k = self.sample(j, i)?;
        let a = self.map.context.placement_at(k).py()?;
        Ok(PyActuator::of(a, self.task, &self.map.context))
    }
    fn pareto_front(&self, py: Python<'_>) -> PyResult<Vec<PyActuator>> {
        self.ranked(py, Ranking::pareto_front())
    }

    /// Rebuilds a map from its state (for pickling): computed again.
    #[staticmethod]
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (linkage, point, grid, limits, options, constraints, strut = None))]
    fn _from_state(
        py: Python<'_>,
        linkage: PySynthesizedFourBar,
        point: PyPoint,
        grid: PyGrid,
        limits: PyDesignLimits,
        options: (String, f64, usize),
        constraints: (Option<Vec<PyPoint>>, Vec<Vec<PyPoint>>, f64, usize),
        strut: Option<(f64, f64)>,
    ) -> PyResult<Self> {
        let ctx = context_of(
            &linkage,
            point,
            Point2::origin(),
            limits,
            (options, strut),
            constraints,
            None,
        )?;
        let ctx = ActuatorContext::new(
            &linkage.inner,
            ctx.point(),
            &grid.inner,
            ctx.map_options(),
            ctx.options(),
        )
        .py()?;
        let map = run(py, false, None, None, |control| ctx.map(control))?;
        Self::new(py, map, linkage.task())
    }

    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let c = &self.map.context;
        let args = (
            self.linkage(),
            pt(c.point()),
            self.grid(),
            self.limits(),
            options_state(c.options()),
            constraint_state(c.constraints()),
            strut_state(c.options()),
        )
            .into_pyobject(py)?;
        Ok((py.get_type::<PyActuatorMap>().getattr("_from_state")?, args))
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<PyActuatorMap>().is_ok_and(|o| {
            let (a, b) = (&o.get().map, &self.map);
            a.context == b.context && o.get().task == self.task && same_columns(a, b)
        })
    }

    fn __repr__(&self) -> String {
        let (ny, nx) = self.shape();
        format!(
            "<ActuatorMap {} ground pivots, {ny} x {nx}>",
            self.map.context.options().link.as_str()
        )
    }
}

/// The actuator methods of `SynthesizedFourBar`: a linear actuator added
/// between a ground pivot and a point of a moving link.
#[pymethods]
impl PySynthesizedFourBar {
    #[doc = text_signature!(
        ACTUATOR,
        "actuator_map($self, *grid, link='coupler', point=None, max_stroke_ratio=1.8, samples=256, \
         actuator_width=0.0, min_gap=0.0",
        ", progress=None"
    )]
    #[pyo3(signature = (*grid, link = "coupler", point = None, max_stroke_ratio = Real(1.8),
        samples = Count(256), actuator_width = Real(0.0), min_gap = Real(0.0), progress = None,
        **options),
        text_signature = None)]
    #[allow(clippy::too_many_arguments)]
    fn actuator_map(
        &self,
        py: Python<'_>,
        grid: &Bound<'_, PyTuple>,
        link: &str,
        point: Option<PyPoint>,
        max_stroke_ratio: Real,
        samples: Count,
        actuator_width: Real,
        min_gap: Real,
        progress: Option<&Bound<'_, PyAny>>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PyActuatorMap> {
        let m = "SynthesizedFourBar.actuator_map";
        let terms = (link, point, max_stroke_ratio, samples);
        let args = ActuatorArgs::new(m, terms, (actuator_width, min_gap), options)?;
        let what = "actuator_map takes a grid (or its six numbers); the rest goes by keyword";
        let g = grid_alone(grid, what)?;
        let ctx = args.context(self, &g)?;
        let watch = g.len() >= WATCH_MIN_SAMPLES / 64;
        let map = run(py, watch, progress, None, |control| ctx.map(control))?;
        PyActuatorMap::new(py, map, self.task())
    }

    #[doc = text_signature!(
        ACTUATOR,
        "actuator($self, ground, link='coupler', point=None, max_stroke_ratio=1.8, samples=256, \
         actuator_width=0.0, min_gap=0.0, *",
        ""
    )]
    #[pyo3(signature = (ground, link = "coupler", point = None, max_stroke_ratio = Real(1.8),
        samples = Count(256), actuator_width = Real(0.0), min_gap = Real(0.0), **options),
        text_signature = None)]
    #[allow(clippy::too_many_arguments)]
    fn actuator(
        &self,
        ground: PyPoint,
        link: &str,
        point: Option<PyPoint>,
        max_stroke_ratio: Real,
        samples: Count,
        actuator_width: Real,
        min_gap: Real,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PyActuator> {
        let m = "SynthesizedFourBar.actuator";
        let terms = (link, point, max_stroke_ratio, samples);
        let args = ActuatorArgs::new(m, terms, (actuator_width, min_gap), options)?;
        let ctx = args.context(self, &point_grid(ground.0)?)?;
        let a = ctx.placement(ground.0).py()?;
        Ok(PyActuator::of(a, self.task(), &ctx))
    }
}

// Pictures in Jupyter (`_repr_png_`).
crate::display::repr_png_for!(PyActuator, PyActuatorMap);
