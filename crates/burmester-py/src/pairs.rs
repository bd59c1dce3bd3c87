//! `burmester.PairMap` and `burmester.Pair` (the core's `design::pairs`).

use burmester::{Control, MapOptions, Pair, PairContext, Point2, Task};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

use crate::classes::{PyDesignLimits, PySynthesizedFourBar, PyTask};
use crate::conv::{Count, PyPoint, Real};
use crate::curves::PyCurveDyad;
use crate::design::{Ranked, py_map_class, ranked_getters, ranked_of};
use crate::errors::IntoPy;
use crate::options::{constraint_state, constraints_of, map_options, text_signature};
use crate::pickle::{Reduced, reduce_to};
use crate::run::{WATCH_MIN_SAMPLES, list_polled, run, run_in};

macro_rules! py_pair_map {
    ($($t:tt)*) => {
        py_map_class!(PyPairMap, "PairMap", PairContext, best_pairs_with => PyPair; $($t)*);
    };
}

burmester::solution_map_columns!(py_pair_map);

ranked_getters!(PyPair);
crate::design::ranking_method!(PyPairMap, best_pairs, ranked);

/// A pair of dyads of a pair map with its linkage.
#[pyclass(frozen, name = "Pair", module = "burmester")]
#[derive(Clone)]
pub struct PyPair {
    driving: PyCurveDyad,
    driven: PyCurveDyad,
    ranked: Ranked<PySynthesizedFourBar>,
}

impl PyPair {
    fn of(task: Task, p: &Pair) -> Self {
        PyPair {
            driving: (&p.driving).into(),
            driven: (&p.driven).into(),
            ranked: ranked_of!(p, PySynthesizedFourBar::new(task, p.linkage)),
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
            ranked: Ranked::new(index, linkage, (margin, score), ranked_by)?,
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
    fn __reduce__<'py>(&self, py: Python<'py>) -> Reduced<'py> {
        let r = &self.ranked;
        let args = (
            PyTask {
                inner: r.linkage.task(),
            },
            self.driving.clone(),
            self.driven.clone(),
            r.index,
            r.margin,
            r.score,
            r.ranked_by.as_str(),
        );
        reduce_to::<PyPair>(py, "_from_state", args)
    }
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<PyPair>().is_ok_and(|o| {
            let o = o.get();
            o.driving == self.driving
                && o.driven == self.driven
                && self.ranked.same(&o.ranked, PySynthesizedFourBar::clone)
        })
    }
    fn __repr__(&self) -> String {
        let (a, c) = (self.driving.center, self.driven.center);
        let index = self.ranked.index;
        format!(
            "<Pair driving=({:.6}, {:.6}) driven=({:.6}, {:.6}) index={index:?} {}>",
            a.0,
            a.1,
            c.0,
            c.1,
            self.ranked.repr()
        )
    }
}

impl PyPairMap {
    /// The arguments of `_from_state` (for pickling).
    fn state<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let constraints = constraint_state(self.context.constraints());
        let columns = self.column_dict(py)?;
        (
            self.task(),
            self.shape(),
            self.limits(),
            constraints,
            columns,
        )
            .into_pyobject(py)
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
    #[getter]
    fn driving_dyads<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        dyads(py, &self.context.driving)
    }
    #[getter]
    fn driven_dyads<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        dyads(py, &self.context.driven)
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
        let opts = MapOptions::new(&limits.inner, &constraints_of(constraints)).py()?;
        let (ny, nx) = (shape.0.0, shape.1.0);
        let context = py.detach(|| task.inner.pair_context(nx, ny, &opts)).py()?;
        Self::from_columns(py, context, (ny, nx), columns)
    }

    fn __eq__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> bool {
        self.equals(py, other)
    }

    fn __repr__(&self) -> String {
        let (ny, nx) = self.shape();
        format!("<PairMap {ny} driven x {nx} driving dyads>")
    }
}

/// The pair map of `Task` (four poses).
#[pymethods]
impl PyTask {
    #[doc = text_signature!(
        MAP,
        "pair_map($self, n_driving=256, n_driven=None, *",
        ", progress=None",
        doc
    )]
    /// Four poses: the pair map (see the stub).
    #[pyo3(signature = (n_driving = Count(256), n_driven = None, *, progress = None, **options),
        text_signature = None)]
    fn pair_map(
        &self,
        py: Python<'_>,
        n_driving: Count,
        n_driven: Option<Count>,
        progress: Option<&Bound<'_, PyAny>>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PyPairMap> {
        let opts = map_options("Task.pair_map", options)?;
        let n_driven = n_driven.map_or(n_driving.0, |n| n.0);
        pair_map(py, self.inner, n_driving.0, n_driven, opts, progress)
    }
}

/// `Task.pair_map`.
fn pair_map(
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
        task.pair_context_with(n_driving, n_driven, &opts, control)
    })?;
    let shape = context.shape();
    PyPairMap::filled(py, shape, |out| {
        run(py, watch, progress, None, |control: &Control<'_>| {
            context.map_into(out, control)?;
            Ok(context)
        })
    })
}
