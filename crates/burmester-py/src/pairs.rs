//! `burmester.PairMap` and `burmester.Pair` (the core's `design::pairs`).

use burmester::{Constraints, Control, Pair, PairContext, Point2, RankBy, Task};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

use crate::conv::{Count, PyPoint, Real, pt};
use crate::curves::PyCurveDyad;
use crate::design::ranking_is_long;
use crate::design::{MapOptions, PyDesignLimits, py_map_class};
use crate::errors::IntoPy;
use crate::geom::PyGrid;
use crate::run::{WATCH_MIN_SAMPLES, list_polled, run, run_in};
use crate::synthesis::{PySynthesizedFourBar, PyTask};

macro_rules! py_pair_map {
    ($($t:tt)*) => {
        py_map_class!(PyPairMap, "PairMap", PairContext; $($t)*);
    };
}

burmester::solution_map_columns!(py_pair_map);

/// A pair of dyads of a pair map with its linkage.
#[pyclass(frozen, name = "Pair", module = "burmester")]
#[derive(Clone)]
pub struct PyPair {
    driving: PyCurveDyad,
    driven: PyCurveDyad,
    index: (usize, usize),
    linkage: PySynthesizedFourBar,
    margin: f64,
    score: f64,
    ranked_by: RankBy,
}

impl PyPair {
    fn of(task: Task, p: &Pair) -> Self {
        PyPair {
            driving: (&p.driving).into(),
            driven: (&p.driven).into(),
            index: p.index,
            linkage: PySynthesizedFourBar::new(task, p.linkage),
            margin: p.margin,
            score: p.score,
            ranked_by: p.ranked_by,
        }
    }
}

#[pymethods]
impl PyPair {
    #[new]
    fn new(
        driving: PyCurveDyad,
        driven: PyCurveDyad,
        index: (Count, Count),
        linkage: PySynthesizedFourBar,
        margin: Real,
        score: Real,
        ranked_by: &str,
    ) -> PyResult<Self> {
        Ok(PyPair {
            driving,
            driven,
            index: (index.0.0, index.1.0),
            linkage,
            margin: margin.0,
            score: score.0,
            ranked_by: ranked_by.parse::<RankBy>().py()?,
        })
    }
    #[getter]
    fn driving(&self) -> PyCurveDyad {
        self.driving.clone()
    }
    #[getter]
    fn driven(&self) -> PyCurveDyad {
        self.driven.clone()
    }
    #[getter]
    fn index(&self) -> (usize, usize) {
        self.index
    }
    #[getter]
    fn linkage(&self) -> PySynthesizedFourBar {
        self.linkage.clone()
    }
    #[getter]
    fn figures(&self) -> crate::linkage::PyLinkageFigures {
        self.linkage.figures()
    }
    #[getter]
    fn margin(&self) -> f64 {
        self.margin
    }
    #[getter]
    fn size_ratio(&self) -> f64 {
        self.linkage.size_ratio()
    }
    #[getter]
    fn score(&self) -> f64 {
        self.score
    }
    #[getter]
    fn ranked_by(&self) -> &'static str {
        self.ranked_by.as_str()
    }
    /// Rebuilds a pair from its task and fields (for pickling): the
    /// linkage from the two dyads exactly as they were (not from their
    /// centers alone, which would round the circle points again).
    #[staticmethod]
    #[allow(clippy::too_many_arguments)]
    fn _from_state(
        task: PyTask,
        driving: PyCurveDyad,
        driven: PyCurveDyad,
        index: (Count, Count),
        margin: Real,
        score: Real,
        ranked_by: &str,
    ) -> PyResult<Self> {
        let dyad = |d: &PyCurveDyad| {
            burmester::Dyad::new(
                Point2::new(d.center.0, d.center.1),
                Point2::new(d.circle.0, d.circle.1),
            )
        };
        let linkage = task
            .inner
            .four_bar(&dyad(&driving), &dyad(&driven))
            .map(|l| PySynthesizedFourBar::new(task.inner, l))
            .py()?;
        Self::new(driving, driven, index, linkage, margin, score, ranked_by)
    }
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let args = (
            PyTask {
                inner: self.linkage.task(),
            },
            self.driving.clone(),
            self.driven.clone(),
            self.index,
            self.margin,
            self.score,
            self.ranked_by.as_str(),
        )
            .into_pyobject(py)?;
        Ok((py.get_type::<PyPair>().getattr("_from_state")?, args))
    }
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<PyPair>().is_ok_and(|o| {
            let o = o.get();
            o.driving == self.driving
                && o.driven == self.driven
                && o.index == self.index
                && o.linkage == self.linkage
                && o.margin.to_bits() == self.margin.to_bits()
                && o.score.to_bits() == self.score.to_bits()
                && o.ranked_by == self.ranked_by
        })
    }
    fn __repr__(&self) -> String {
        let f = &self.linkage.inner.figures;
        let (a, c) = (self.driving.center, self.driven.center);
        format!(
            "<Pair driving=({:.6}, {:.6}) driven=({:.6}, {:.6}) index={:?} {} \
             min_transmission_deg={} size_ratio={:.3} by {}>",
            a.0,
            a.1,
            c.0,
            c.1,
            self.index,
            f.grashof,
            if f.min_transmission.is_nan() {
                "None".to_owned()
            } else {
                format!("{:.3}", f.min_transmission.to_degrees())
            },
            self.linkage.size_ratio(),
            self.ranked_by.as_str()
        )
    }
}

impl PyPairMap {
    /// The `k` best pairs by `rank_by`, reading the NumPy columns in place.
    fn ranked<'py>(
        &self,
        py: Python<'py>,
        k: usize,
        min_separation: Option<f64>,
        rank_by: RankBy,
    ) -> PyResult<Bound<'py, PyList>> {
        let ctx = &self.context;
        let watch = ranking_is_long(ctx.grid.len(), k);
        let pairs = self.with_rank_columns(py, |cols| {
            run_in(py, watch, None, None, "samples", |control| {
                ctx.best_pairs_with(k, min_separation, rank_by, cols, control)
            })
        })?;
        list_polled(py, &pairs, |p| {
            Ok(Bound::new(py, PyPair::of(ctx.task, p))?.into_any())
        })
    }

    /// The row-major index of pair `[j, i]`, or `InvalidInputError` naming
    /// the index out of range.
    fn index(&self, j: Count, i: Count) -> PyResult<usize> {
        let (ny, nx) = self.context.shape();
        for (name, v, n, what) in [("j", j.0, ny, "driven"), ("i", i.0, nx, "driving")] {
            if v >= n {
                return Err(crate::errors::invalid(
                    "grid_index",
                    format!(
                        "pair ({}, {}) is outside the map of shape ({ny}, {nx}): {name} (the \
                         {what} sample) must be from 0 to {}; pass indices within it",
                        j.0,
                        i.0,
                        n - 1
                    ),
                ));
            }
        }
        Ok(j.0 * nx + i.0)
    }
}

/// The dyads of an axis as a Python list (`None` at infinity), built
/// with Ctrl-C honoured (ten million of them take seconds).
fn dyads<'py>(
    py: Python<'py>,
    v: &[Option<burmester::synthesis::CurveDyad>],
) -> PyResult<Bound<'py, PyList>> {
    list_polled(py, v, |d| match d {
        Some(d) => Ok(Bound::new(py, PyCurveDyad::from(d))?.into_any()),
        None => Ok(py.None().into_bound(py)),
    })
}

#[pymethods]
impl PyPairMap {
    /// A picture for Jupyter: PNG bytes drawn by `burmester._display`, or
    /// None without matplotlib.
    fn _repr_png_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        crate::display::repr_png(slf.as_any())
    }

    /// The names of the Grashof codes, by code.
    #[classattr]
    fn grashof_names() -> Vec<&'static str> {
        burmester::Grashof::ALL.iter().map(|g| g.as_str()).collect()
    }
    /// The names of the columns, in order.
    #[classattr]
    fn columns() -> Vec<&'static str> {
        burmester::design::Columns::NAMES.to_vec()
    }
    #[getter]
    fn grid(&self) -> PyGrid {
        PyGrid {
            inner: self.context.grid,
        }
    }
    #[getter]
    fn extent(&self) -> (f64, f64, f64, f64) {
        let v = self.context.grid.viewport();
        (v.xmin, v.xmax, v.ymin, v.ymax)
    }
    #[getter]
    fn shape(&self) -> (usize, usize) {
        self.context.shape()
    }
    #[getter]
    fn driving_dyads<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        dyads(py, &self.context.driving)
    }
    #[getter]
    fn driven_dyads<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        dyads(py, &self.context.driven)
    }
    #[getter]
    fn task(&self) -> PyTask {
        PyTask {
            inner: self.context.task,
        }
    }
    #[getter]
    fn limits(&self) -> PyDesignLimits {
        PyDesignLimits {
            inner: self.context.limits,
        }
    }
    fn linkage(&self, j: Count, i: Count) -> PyResult<PySynthesizedFourBar> {
        let k = self.index(j, i)?;
        self.context
            .linkage(k)
            .map(|l| PySynthesizedFourBar::new(self.context.task, l))
            .py()
    }
    fn margins<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let bf = self.branch_free.bind(py).readonly();
        let bf = bf.as_slice()?;
        let ctx = &self.context;
        let watch = ctx.grid.len() >= 1 << 16;
        let m = run_in(py, watch, None, None, "lines", |control| {
            ctx.margins_with(bf, control)
        })?;
        Ok(Array2::from_shape_vec(ctx.shape(), m)
            .expect("one value per pair")
            .into_pyarray(py))
    }
    #[pyo3(signature = (k = Count(5), min_separation = None, rank_by = "balanced"),
        text_signature = "($self, /, k=5, min_separation=None, rank_by='balanced')")]
    fn best_pairs<'py>(
        &self,
        py: Python<'py>,
        k: Count,
        min_separation: Option<Real>,
        rank_by: &str,
    ) -> PyResult<Bound<'py, PyList>> {
        let rank_by = rank_by.parse::<RankBy>().py()?;
        self.ranked(py, k.0, min_separation.map(|r| r.0), rank_by)
    }
    fn pareto_front<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        self.ranked(py, usize::MAX, Some(0.0), RankBy::Pareto)
    }

    /// Rebuilds a map from its state (for pickling): the samples are
    /// recomputed from the task (the same bits), the columns copied.
    #[staticmethod]
    fn _from_state(
        py: Python<'_>,
        task: PyTask,
        shape: (Count, Count),
        limits: PyDesignLimits,
        constraints: (Option<Vec<PyPoint>>, Vec<Vec<PyPoint>>, f64, usize),
        columns: &Bound<'_, PyDict>,
    ) -> PyResult<Self> {
        let pts = |v: Vec<PyPoint>| v.into_iter().map(|p| p.0).collect::<Vec<_>>();
        let constraints = Constraints {
            base_plate: constraints.0.map(pts),
            obstacles: constraints.1.into_iter().map(pts).collect(),
            link_width: constraints.2,
            travel_samples: constraints.3,
            envelope: None,
        };
        let (ny, nx) = (shape.0.0, shape.1.0);
        let context = py
            .detach(|| task.inner.pair_context(nx, ny, &limits.inner, &constraints))
            .py()?;
        Self::from_columns(py, context, (ny, nx), columns)
    }

    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let c = &self.context;
        let pts = |v: &[Point2<f64>]| v.iter().map(|p| pt(*p)).collect::<Vec<_>>();
        let constraints = (
            c.constraints.base_plate.as_deref().map(pts),
            c.constraints
                .obstacles
                .iter()
                .map(|o| pts(o))
                .collect::<Vec<_>>(),
            c.constraints.link_width,
            c.constraints.travel_samples,
        );
        let args = (
            self.task(),
            self.shape(),
            self.limits(),
            constraints,
            self.column_dict(py)?,
        )
            .into_pyobject(py)?;
        Ok((py.get_type::<PyPairMap>().getattr("_from_state")?, args))
    }

    fn __eq__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PyPairMap>()
            .is_ok_and(|o| o.get().context == self.context && self.same_columns(py, o.get()))
    }

    fn __repr__(&self) -> String {
        let (ny, nx) = self.shape();
        format!("<PairMap {ny} driven x {nx} driving dyads>")
    }
}

/// `Task.pair_map`.
pub(crate) fn pair_map(
    py: Python<'_>,
    task: Task,
    n_driving: usize,
    n_driven: usize,
    opts: MapOptions,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<PyPairMap> {
    let watch = n_driving.saturating_mul(n_driven) >= WATCH_MIN_SAMPLES / 16;
    // The context first: the arguments are checked before NumPy allocates.
    // Its dyads take seconds for millions of samples: Ctrl-C is watched,
    // progress is the map's alone.
    let long = n_driving.saturating_add(n_driven) >= 1 << 14;
    let context = run_in(py, long, None, None, "dyads", |control| {
        task.pair_context_with(
            n_driving,
            n_driven,
            &opts.limits,
            &opts.constraints,
            control,
        )
    })?;
    let shape = context.shape();
    PyPairMap::filled(py, shape, |out| {
        run(py, watch, progress, None, |control: &Control<'_>| {
            context.map_into(out, control)?;
            Ok(context)
        })
    })
}
