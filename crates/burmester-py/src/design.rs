//! `burmester.SolutionMap`: the designer's solution-space map.

use burmester::{
    Constraints, DesignLimits, Filemon, Grid, InputRequirement, MapContext, Pivot, Point2,
    SolutionMap, Task,
};
use numpy::ndarray::Array2;
use numpy::{Element, IntoPyArray, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::conv::{Count, PyPoint, Real, pt};
use crate::errors::{IntoPy, InvalidInputError};
use crate::synthesis::PySynthesizedFourBar;

/// The keyword arguments shared by both map constructors.
pub(crate) struct MapOptions {
    pub(crate) limits: DesignLimits,
    pub(crate) constraints: Constraints,
}

impl MapOptions {
    /// The grid and the options of a solution map, from the Python arguments.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn with_grid(
        bounds: [Real; 4],
        size: [Count; 2],
        min_transmission_deg: Real,
        max_link_ratio: Real,
        input: &str,
        base_plate: Option<Vec<PyPoint>>,
        obstacles: Option<Vec<Vec<PyPoint>>>,
        link_width: Real,
        travel_samples: Count,
    ) -> PyResult<(Grid, Self)> {
        let [xmin, xmax, ymin, ymax] = bounds.map(|r| r.0);
        let grid = Grid::from_bounds(xmin, xmax, ymin, ymax, size[0].0, size[1].0).py()?;
        let opts = Self::new(
            min_transmission_deg.0,
            max_link_ratio.0,
            input,
            base_plate,
            obstacles,
            link_width.0,
            travel_samples.0,
        )?;
        Ok((grid, opts))
    }

    #[allow(clippy::too_many_arguments)]
    fn new(
        min_transmission_deg: f64,
        max_link_ratio: f64,
        input: &str,
        base_plate: Option<Vec<PyPoint>>,
        obstacles: Option<Vec<Vec<PyPoint>>>,
        link_width: f64,
        travel_samples: usize,
    ) -> PyResult<Self> {
        let limits = DesignLimits {
            min_transmission: min_transmission_deg.to_radians(),
            max_link_ratio,
            input: input.parse::<InputRequirement>().py()?,
        };
        if !(0.0..=90.0).contains(&min_transmission_deg) {
            return Err(InvalidInputError::new_err(format!(
                "min_transmission_deg must be between 0 and 90 degrees, got {min_transmission_deg}; \
                 pass an angle in that range"
            )));
        }
        let pts = |v: Vec<PyPoint>| v.into_iter().map(|p| p.0).collect::<Vec<Point2<f64>>>();
        let constraints = Constraints {
            base_plate: base_plate.map(pts),
            obstacles: obstacles.unwrap_or_default().into_iter().map(pts).collect(),
            link_width,
            travel_samples,
        };
        Ok(MapOptions {
            limits,
            constraints,
        })
    }
}

fn readonly<'py, T: Element>(py: Python<'py>, grid: &Grid, v: Vec<T>) -> PyResult<Py<PyArray2<T>>> {
    let a = Array2::from_shape_vec((grid.ny(), grid.nx()), v)
        .expect("one value per sample")
        .into_pyarray(py);
    let kw = PyDict::new(py);
    kw.set_item("write", false)?;
    a.call_method("setflags", (), Some(&kw))?;
    Ok(a.unbind())
}

/// The solution-space map over candidate pivots (see the stub for the docs).
#[pyclass(frozen, name = "SolutionMap", module = "burmester")]
pub struct PySolutionMap {
    context: MapContext,
    valid: Py<PyArray2<bool>>,
    branch_free: Py<PyArray2<bool>>,
    grashof: Py<PyArray2<u8>>,
    input_full: Py<PyArray2<bool>>,
    direction: Py<PyArray2<i8>>,
    one_circuit: Py<PyArray2<bool>>,
    min_transmission: Py<PyArray2<f32>>,
    link_ratio: Py<PyArray2<f32>>,
    acceptable: Py<PyArray2<bool>>,
}

impl PySolutionMap {
    /// Moves the map's arrays into read-only NumPy arrays (no copy).
    pub(crate) fn new(py: Python<'_>, map: SolutionMap) -> PyResult<Self> {
        let g = map.context.grid;
        Ok(PySolutionMap {
            valid: readonly(py, &g, map.valid)?,
            branch_free: readonly(py, &g, map.branch_free)?,
            grashof: readonly(py, &g, map.grashof)?,
            input_full: readonly(py, &g, map.input_full)?,
            direction: readonly(py, &g, map.direction)?,
            one_circuit: readonly(py, &g, map.one_circuit)?,
            min_transmission: readonly(py, &g, map.min_transmission)?,
            link_ratio: readonly(py, &g, map.link_ratio)?,
            acceptable: readonly(py, &g, map.acceptable)?,
            context: map.context,
        })
    }
}

fn pivot_dict<'py>(py: Python<'py>, p: &Pivot) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let f = &p.figures;
    let l = &p.linkage;
    d.set_item("center", pt(p.center))?;
    d.set_item("driving", (pt(l.driving.center), pt(l.driving.circle)))?;
    d.set_item("driven", (pt(l.driven.center), pt(l.driven.circle)))?;
    let [l1, l2, l3, l4] = f.lengths;
    d.set_item("lengths", (l1, l2, l3, l4))?;
    d.set_item("grashof", f.grashof.as_str())?;
    d.set_item("input_full", f.input_full)?;
    d.set_item(
        "direction",
        match f.direction {
            1 => "ccw",
            -1 => "cw",
            _ => "none",
        },
    )?;
    d.set_item("min_transmission_deg", f.min_transmission.to_degrees())?;
    d.set_item("link_ratio", f.link_ratio)?;
    d.set_item("margin", p.margin)?;
    let [a, b, c] = l.input_angles;
    d.set_item("input_angles", (a, b, c))?;
    d.set_item("mode", l.modes[0].map(|m| m.as_str()))?;
    d.set_item("index", p.index)?;
    Ok(d)
}

#[pymethods]
impl PySolutionMap {
    #[getter]
    fn valid(&self, py: Python<'_>) -> Py<PyArray2<bool>> {
        self.valid.clone_ref(py)
    }
    #[getter]
    fn branch_free(&self, py: Python<'_>) -> Py<PyArray2<bool>> {
        self.branch_free.clone_ref(py)
    }
    #[getter]
    fn grashof(&self, py: Python<'_>) -> Py<PyArray2<u8>> {
        self.grashof.clone_ref(py)
    }
    #[getter]
    fn input_full(&self, py: Python<'_>) -> Py<PyArray2<bool>> {
        self.input_full.clone_ref(py)
    }
    #[getter]
    fn direction(&self, py: Python<'_>) -> Py<PyArray2<i8>> {
        self.direction.clone_ref(py)
    }
    #[getter]
    fn one_circuit(&self, py: Python<'_>) -> Py<PyArray2<bool>> {
        self.one_circuit.clone_ref(py)
    }
    #[getter]
    fn min_transmission(&self, py: Python<'_>) -> Py<PyArray2<f32>> {
        self.min_transmission.clone_ref(py)
    }
    #[getter]
    fn link_ratio(&self, py: Python<'_>) -> Py<PyArray2<f32>> {
        self.link_ratio.clone_ref(py)
    }
    #[getter]
    fn acceptable(&self, py: Python<'_>) -> Py<PyArray2<bool>> {
        self.acceptable.clone_ref(py)
    }
    /// The names of the Grashof codes, by code.
    #[classattr]
    fn grashof_names() -> Vec<&'static str> {
        burmester::Grashof::ALL.iter().map(|g| g.as_str()).collect()
    }
    #[getter]
    fn extent(&self) -> (f64, f64, f64, f64) {
        let v = self.context.grid.viewport();
        (v.xmin, v.xmax, v.ymin, v.ymax)
    }
    #[getter]
    fn shape(&self) -> (usize, usize) {
        (self.context.grid.ny(), self.context.grid.nx())
    }
    #[getter]
    fn varying(&self) -> &'static str {
        match self.context.varying {
            burmester::Varying::Driving { .. } => "driving",
            burmester::Varying::Driven { .. } => "driven",
        }
    }
    fn point(&self, j: Count, i: Count) -> PyResult<(f64, f64)> {
        let (j, i) = (j.0, i.0);
        let g = &self.context.grid;
        if i >= g.nx() || j >= g.ny() {
            return Err(InvalidInputError::new_err(format!(
                "sample ({j}, {i}) is outside the map of shape ({}, {}); pass indices within it",
                g.ny(),
                g.nx()
            )));
        }
        Ok(pt(g.point(i, j)))
    }
    fn linkage(&self, j: Count, i: Count) -> PyResult<PySynthesizedFourBar> {
        let nx = self.context.grid.nx();
        self.point(j, i)?;
        let (j, i) = (j.0, i.0);
        self.context
            .linkage(j * nx + i)
            .map(|inner| PySynthesizedFourBar { inner })
            .py()
    }
    #[pyo3(signature = (k = Count(5), min_separation = None),
        text_signature = "($self, /, k=5, min_separation=None)")]
    fn best_pivots<'py>(
        &self,
        py: Python<'py>,
        k: Count,
        min_separation: Option<Real>,
    ) -> PyResult<Bound<'py, PyList>> {
        let (k, min_separation) = (k.0, min_separation.map(|r| r.0));
        if let Some(s) = min_separation {
            if !(s.is_finite() && s >= 0.0) {
                return Err(InvalidInputError::new_err(format!(
                    "min_separation must be a finite distance of at least 0, got {s}; pass one \
                     (or None for the default)"
                )));
            }
        }
        let acc = self.acceptable.bind(py).readonly();
        let mt = self.min_transmission.bind(py).readonly();
        let bf = self.branch_free.bind(py).readonly();
        let (acc, mt, bf) = (acc.as_slice()?, mt.as_slice()?, bf.as_slice()?);
        let ctx = &self.context;
        let pivots = py.detach(|| ctx.best_pivots(k, min_separation, acc, mt, bf));
        let list = PyList::empty(py);
        for p in &pivots {
            list.append(pivot_dict(py, p)?)?;
        }
        Ok(list)
    }
    fn __repr__(&self) -> String {
        let (ny, nx) = self.shape();
        format!("<SolutionMap {} pivots, {ny} x {nx}>", self.varying())
    }
}

/// `Filemon.solution_map`.
pub(crate) fn solution_map(
    py: Python<'_>,
    f: Filemon,
    grid: Grid,
    opts: MapOptions,
) -> PyResult<PySolutionMap> {
    let map = py
        .detach(|| f.solution_map(&grid, &opts.limits, &opts.constraints))
        .py()?;
    PySolutionMap::new(py, map)
}

/// `Task.driven_solution_map`.
pub(crate) fn driven_solution_map(
    py: Python<'_>,
    task: Task,
    driving_center: Point2<f64>,
    grid: Grid,
    opts: MapOptions,
) -> PyResult<PySolutionMap> {
    let driving = task.dyad_from_center(driving_center).py()?;
    let map = py
        .detach(|| task.driven_solution_map(&driving, &grid, &opts.limits, &opts.constraints))
        .py()?;
    PySolutionMap::new(py, map)
}
