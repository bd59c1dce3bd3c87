//! `burmester.SliderFilemon`, `slider_branch_free_arcs` and
//! `slider_curve_branch`: the branch problem with a slider as the driven
//! dyad (the core's `Filemon` and `FilemonArcs` for a `SliderDyad`). Thin:
//! converts and delegates.

use burmester::SliderDyad;
use burmester::synthesis::FilemonArcs;
use burmester::synthesis::three::Filemon;
use numpy::PyArray2;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::classes::PyTask;
use crate::conv::{PyPoint, Real, pt};
use crate::curves;
use crate::errors::IntoPy;
use crate::geom::{grid_alone, vec2};
use crate::synthesis::filemon_methods;

type Xy = (f64, f64);

/// Filemon's construction for a slider driven dyad of a three-pose task:
/// the pin `C1` on a ground guide of direction `u`, its lines through `C1`
/// in the directions `n_k`, and their exact transforms into the driving
/// crank's center-point plane.
#[pyclass(frozen, eq, name = "SliderFilemon", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PySliderFilemon {
    pub(crate) inner: Filemon,
    /// The slider as the construction keeps it (the guide normalized).
    slider: SliderDyad,
}

#[pymethods]
impl PySliderFilemon {
    #[new]
    fn new(task: PyRef<'_, PyTask>, circle: PyPoint, guide: PyPoint) -> PyResult<Self> {
        let slider = SliderDyad::new(circle.0, guide.0.coords).py()?;
        let inner = Filemon::new(&task.inner, slider).py()?;
        Ok(PySliderFilemon { inner, slider })
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (PyTask, Xy, Xy))> {
        let s = self.slider;
        let cls = py.get_type::<Self>().into_any();
        Ok((cls, (self.task(), pt(s.circle), vec2(s.guide))))
    }

    #[getter]
    fn circle(&self) -> Xy {
        pt(self.slider.circle)
    }

    #[getter]
    fn guide(&self) -> Xy {
        vec2(self.slider.guide)
    }

    #[getter]
    fn normal(&self) -> Xy {
        vec2(self.slider.normal())
    }

    #[getter]
    fn directions(&self) -> Vec<Xy> {
        self.inner
            .construction()
            .directions()
            .iter()
            .map(|d| vec2(*d))
            .collect()
    }

    fn circle_signs(&self, circle: PyPoint) -> PyResult<Vec<f64>> {
        Ok(self.inner.circle_signs(circle.0).py()?.to_vec())
    }

    #[pyo3(signature = (*grid, method = "conic", out = None, progress = None))]
    fn branch_map<'py>(
        &self,
        py: Python<'py>,
        grid: &Bound<'py, PyTuple>,
        method: &str,
        out: Option<Bound<'py, PyAny>>,
        progress: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let g = grid_alone(
            grid,
            "SliderFilemon.branch_map takes a grid (or its six numbers); pass the method by name",
        )?;
        crate::sweep::branch_map(self.inner, py, g, method, out, progress.as_ref())
    }

    fn __repr__(&self) -> String {
        let s = self.slider;
        format!(
            "<SliderFilemon circle=({:?}, {:?}) guide=({:?}, {:?}) all_defective={}>",
            s.circle.x,
            s.circle.y,
            s.guide.x,
            s.guide.y,
            if self.inner.all_defective() {
                "True"
            } else {
                "False"
            }
        )
    }
}

filemon_methods!(PySliderFilemon);

/// The four-pose construction of a slider driven dyad of `task`.
fn four_arcs(
    task: &PyTask,
    circle: PyPoint,
    guide: PyPoint,
    method: &'static str,
) -> PyResult<FilemonArcs> {
    let slider = SliderDyad::new(circle.0, guide.0.coords).py()?;
    task.inner
        .four_positions(method)
        .py()?
        .slider_filemon(&slider)
        .py()
}

/// Four poses: the branch-free arcs of the center-point (or circle-point)
/// curve in view for a slider driven dyad, as `Task.branch_free_arcs`.
#[allow(clippy::too_many_arguments)]
#[pyfunction]
#[pyo3(signature = (task, circle, guide, xmin, xmax, ymin, ymax, *, plane = "center"))]
pub(crate) fn slider_branch_free_arcs<'py>(
    py: Python<'py>,
    task: PyRef<'_, PyTask>,
    circle: PyPoint,
    guide: PyPoint,
    xmin: Real,
    xmax: Real,
    ymin: Real,
    ymax: Real,
    plane: &str,
) -> PyResult<Vec<Bound<'py, PyArray2<f64>>>> {
    let arcs = four_arcs(&task, circle, guide, "slider_branch_free_arcs")?;
    let vp = curves::viewport(xmin, xmax, ymin, ymax)?;
    curves::free_arcs(py, &arcs, &vp, curves::circle_plane(plane)?)
}

/// Four poses: the branch class of a driving center point on the curve for
/// a slider driven dyad, as `Task.curve_branch`.
#[pyfunction]
pub(crate) fn slider_curve_branch(
    task: PyRef<'_, PyTask>,
    circle: PyPoint,
    guide: PyPoint,
    center: PyPoint,
) -> PyResult<&'static str> {
    let arcs = four_arcs(&task, circle, guide, "slider_curve_branch")?;
    Ok(arcs.classify_center_point(center.0).py()?.as_str())
}
