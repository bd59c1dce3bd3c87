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
    // A NaN norm is not finite: refused by the first test.
    if !finite || (d.norm() - 1.0).abs() > 1e-12 {
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

/// A Python record of a core value that is a point and a unit direction
/// (its two fields): the class, its constructor (checked as a
/// [`SliderDyad`]'s pin and guide, the direction normalized), its pickling
/// (bit for bit, through `_from_fields`), its two getters and its repr.
macro_rules! point_direction_record {
    (
        $(#[$doc:meta])*
        $Py:ident($Core:ident, $name:literal) {
            $(#[$pdoc:meta])* $point:ident,
            $(#[$ddoc:meta])* $direction:ident $(,)?
        }
    ) => {
        $(#[$doc])*
        #[pyclass(frozen, eq, from_py_object, name = $name, module = "burmester")]
        #[derive(Clone, PartialEq)]
        pub(crate) struct $Py {
            pub(crate) inner: $Core,
        }

        #[pymethods]
        impl $Py {
            #[new]
            fn new($point: PyPoint, $direction: PyPoint) -> PyResult<Self> {
                let s = SliderDyad::new($point.0, $direction.0.coords).py()?;
                Ok($Py { inner: $Core::from(s) })
            }

            /// Rebuilds a record from its fields (for pickling), bit for bit.
            #[staticmethod]
            fn _from_fields($point: PyPoint, $direction: PyPoint) -> PyResult<Self> {
                check_state($name, $point.0, $direction.0.coords)?;
                let inner = $Core { $point: $point.0, $direction: $direction.0.coords };
                Ok($Py { inner })
            }

            fn __reduce__<'py>(
                &self,
                py: Python<'py>,
            ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
                let args = (pt(self.inner.$point), vec2(self.inner.$direction)).into_pyobject(py)?;
                Ok((py.get_type::<$Py>().getattr("_from_fields")?, args))
            }

            $(#[$pdoc])*
            #[getter]
            fn $point(&self) -> Xy {
                pt(self.inner.$point)
            }

            $(#[$ddoc])*
            #[getter]
            fn $direction(&self) -> Xy {
                vec2(self.inner.$direction)
            }

            fn __repr__(&self) -> String {
                let (p, d) = (self.inner.$point, self.inner.$direction);
                format!(
                    concat!($name, "(", stringify!($point), "=({:?}, {:?}), ",
                        stringify!($direction), "=({:?}, {:?}))"),
                    p.x, p.y, d.x, d.y
                )
            }
        }
    };
}

point_direction_record! {
    /// A slider dyad: a pin on a straight guide fixed to the ground (a
    /// revolute dyad whose center point is at infinity).
    PySliderDyad(SliderDyad, "SliderDyad") {
        /// The pin (moving pivot) at pose 1, a point of the guide.
        circle,
        /// The guide's unit direction.
        guide,
    }
}

point_direction_record! {
    /// An inverted slider: a line of the moving body that passes through a
    /// fixed pivot (the swivel) at every pose.
    PyInvertedSlider(InvertedSlider, "InvertedSlider") {
        /// The swivel: the fixed pivot the body line passes through.
        swivel,
        /// The unit direction of the body line at pose 1.
        direction,
    }
}

#[pymethods]
impl PySliderDyad {
    /// The guide's unit normal, where the center point is at infinity.
    #[getter]
    fn normal(&self) -> Xy {
        vec2(self.inner.normal())
    }
}

#[pymethods]
impl PyInvertedSlider {
    /// `(point, direction)` of the body line at pose `k` of `task`.
    fn body_line_at(&self, task: PyTask, k: Count) -> PyResult<(Xy, Xy)> {
        let l = self.inner.body_line_at(&task.inner, k.0).py()?;
        Ok((pt(l.point), vec2(l.direction)))
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

// Pictures in Jupyter (`_repr_png_`).
crate::display::repr_png_for!(PySliderDyad);
