//! `burmester.SliderDyad`, `burmester.InvertedSlider` and the slider
//! methods of `burmester.Task` (the core's `synthesis::task_slider`, issue
//! 27): convert and delegate.

use burmester::{InvertedSlider, Point2, SliderDyad, Vector2};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use crate::classes::PyTask;
use crate::conv::{Count, PyPoint, pt};
use crate::errors::IntoPy;
use crate::geom::vec2;

type Xy = (f64, f64);

/// The point and unit direction of a pickled record, kept bit for bit:
/// finite, and the direction of unit length within `1e-12` (what the
/// constructors make), else an `InvalidInputError` saying the pickle is
/// not one of burmester's.
fn check_state(what: &str, p: Point2<f64>, d: Vector2<f64>) -> PyResult<()> {
    let finite = [p.x, p.y, d.x, d.y].iter().all(|v| v.is_finite());
    if !finite || !((d.norm() - 1.0).abs() <= 1e-12) {
        return Err(crate::errors::invalid(
            "inconsistent_state",
            format!(
                "unpickling a {what}: a point that is not finite or a direction that is not a \
                 unit vector; the pickle was damaged or not made by burmester: compute it again"
            ),
        ));
    }
    Ok(())
}

/// A slider dyad: a pin on a straight guide fixed to the ground (a
/// revolute dyad whose center point is at infinity).
#[pyclass(frozen, eq, from_py_object, name = "SliderDyad", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PySliderDyad {
    pub(crate) inner: SliderDyad,
}

#[pymethods]
impl PySliderDyad {
    #[new]
    fn new(circle: PyPoint, guide: PyPoint) -> PyResult<Self> {
        let inner = SliderDyad::new(circle.0, guide.0.coords).py()?;
        Ok(PySliderDyad { inner })
    }

    /// Rebuilds a record from its fields (for pickling), bit for bit.
    #[staticmethod]
    fn _from_fields(circle: PyPoint, guide: PyPoint) -> PyResult<Self> {
        check_state("SliderDyad", circle.0, guide.0.coords)?;
        Ok(PySliderDyad {
            inner: SliderDyad {
                circle: circle.0,
                guide: guide.0.coords,
            },
        })
    }

    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let args = (pt(self.inner.circle), vec2(self.inner.guide)).into_pyobject(py)?;
        Ok((py.get_type::<PySliderDyad>().getattr("_from_fields")?, args))
    }

    /// The pin (moving pivot) at pose 1, a point of the guide.
    #[getter]
    fn circle(&self) -> Xy {
        pt(self.inner.circle)
    }

    /// The guide's unit direction.
    #[getter]
    fn guide(&self) -> Xy {
        vec2(self.inner.guide)
    }

    /// The guide's unit normal, where the center point is at infinity.
    #[getter]
    fn normal(&self) -> Xy {
        vec2(self.inner.normal())
    }

    fn __repr__(&self) -> String {
        let (c, u) = (self.inner.circle, self.inner.guide);
        format!(
            "SliderDyad(circle=({:?}, {:?}), guide=({:?}, {:?}))",
            c.x, c.y, u.x, u.y
        )
    }
}

/// An inverted slider: a line of the moving body that passes through a
/// fixed pivot (the swivel) at every pose.
#[pyclass(
    frozen,
    eq,
    from_py_object,
    name = "InvertedSlider",
    module = "burmester"
)]
#[derive(Clone, PartialEq)]
pub(crate) struct PyInvertedSlider {
    pub(crate) inner: InvertedSlider,
}

#[pymethods]
impl PyInvertedSlider {
    #[new]
    fn new(swivel: PyPoint, direction: PyPoint) -> PyResult<Self> {
        // The same checks as a slider dyad's (its pin and guide).
        let s = SliderDyad::new(swivel.0, direction.0.coords).py()?;
        Ok(PyInvertedSlider {
            inner: InvertedSlider::from(s),
        })
    }

    /// Rebuilds a record from its fields (for pickling), bit for bit.
    #[staticmethod]
    fn _from_fields(swivel: PyPoint, direction: PyPoint) -> PyResult<Self> {
        check_state("InvertedSlider", swivel.0, direction.0.coords)?;
        Ok(PyInvertedSlider {
            inner: InvertedSlider {
                swivel: swivel.0,
                direction: direction.0.coords,
            },
        })
    }

    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let args = (pt(self.inner.swivel), vec2(self.inner.direction)).into_pyobject(py)?;
        Ok((
            py.get_type::<PyInvertedSlider>().getattr("_from_fields")?,
            args,
        ))
    }

    /// The swivel: the fixed pivot the body line passes through.
    #[getter]
    fn swivel(&self) -> Xy {
        pt(self.inner.swivel)
    }

    /// The unit direction of the body line at pose 1.
    #[getter]
    fn direction(&self) -> Xy {
        vec2(self.inner.direction)
    }

    /// `(point, direction)` of the body line at pose `k` of `task`.
    fn body_line_at(&self, task: PyTask, k: Count) -> PyResult<(Xy, Xy)> {
        let l = self.inner.body_line_at(&task.inner, k.0).py()?;
        Ok((pt(l.point), vec2(l.direction)))
    }

    fn __repr__(&self) -> String {
        let (s, d) = (self.inner.swivel, self.inner.direction);
        format!(
            "InvertedSlider(swivel=({:?}, {:?}), direction=({:?}, {:?}))",
            s.x, s.y, d.x, d.y
        )
    }
}

/// The slider methods of `Task`.
#[pymethods]
impl PyTask {
    fn slider_circle<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        crate::synthesis::circle_dict(py, self.inner.slider_circle().py()?)
    }

    #[pyo3(signature = (samples = Count(200)), text_signature = "($self, samples=200)")]
    fn slider_dyads(&self, samples: Count) -> PyResult<Vec<PySliderDyad>> {
        let v = self.inner.slider_dyads(samples.0).py()?;
        Ok(v.into_iter().map(|inner| PySliderDyad { inner }).collect())
    }

    fn slider_dyad(&self, circle: PyPoint) -> PyResult<PySliderDyad> {
        let inner = self.inner.slider_dyad(circle.0).py()?;
        Ok(PySliderDyad { inner })
    }

    fn inverted(&self) -> PyResult<PyTask> {
        Ok(PyTask {
            inner: self.inner.inverted().py()?,
        })
    }

    #[pyo3(signature = (samples = Count(200)), text_signature = "($self, samples=200)")]
    fn inverted_sliders(&self, samples: Count) -> PyResult<Vec<PyInvertedSlider>> {
        let v = self.inner.inverted_sliders(samples.0).py()?;
        Ok(v.into_iter()
            .map(|inner| PyInvertedSlider { inner })
            .collect())
    }

    fn inverted_slider(&self, swivel: PyPoint) -> PyResult<PyInvertedSlider> {
        let inner = self.inner.inverted_slider(swivel.0).py()?;
        Ok(PyInvertedSlider { inner })
    }
}
