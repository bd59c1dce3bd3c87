//! `burmester.SliderCrank`, `burmester.SliderConfiguration` and
//! `burmester.SynthesizedSliderCrank` (the core's `linkage::slider` and
//! `synthesis::slider_crank`), with `Task.slider_crank`.

use burmester::{
    Dyad, Point2, SliderConfiguration, SliderCrank, SliderDyad, SynthesizedSliderCrank, Vector2,
};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use crate::classes::PyTask;
use crate::conv::{Arrays, FloatArray, PyPoint, Real, pt};
use crate::crank_synth::{configuration_methods, synthesized_crank};
use crate::errors::IntoPy;
use crate::linkage::{self, mode};

type Xy = (f64, f64);

fn xy(v: Vector2<f64>) -> Xy {
    (v.x, v.y)
}

/// A slider-crank (RRRP): crank about a fixed pivot, coupler, slider pin
/// on a straight guide. What it derives without arguments is computed once
/// and read as fields.
#[pyclass(frozen, name = "SliderCrank", module = "burmester")]
#[derive(Clone)]
pub struct PySliderCrank {
    inner: SliderCrank,
    #[pyo3(get)]
    crank: f64,
    #[pyo3(get)]
    coupler: f64,
    #[pyo3(get)]
    pivot: Xy,
    #[pyo3(get)]
    guide: Xy,
    #[pyo3(get)]
    guide_normal: Xy,
    #[pyo3(get)]
    foot: Xy,
    #[pyo3(get)]
    offset: f64,
    #[pyo3(get)]
    link_ratio: f64,
    #[pyo3(get)]
    turns_fully: bool,
    /// `None` when the crank turns fully, else its `(start, end)` arcs.
    #[pyo3(get)]
    input_range: Option<Vec<Xy>>,
    #[pyo3(get)]
    dead_positions: Vec<f64>,
    /// `[(theta2, slider, mode)]` where crank and coupler are collinear.
    #[pyo3(get)]
    collinear_positions: Vec<(f64, f64, &'static str)>,
}

impl From<SliderCrank> for PySliderCrank {
    fn from(s: SliderCrank) -> Self {
        let range = s.input_range();
        let (arcs, n) = range.arcs_array();
        PySliderCrank {
            inner: s,
            crank: s.crank(),
            coupler: s.coupler(),
            pivot: pt(s.crank_pivot()),
            guide: xy(s.guide()),
            guide_normal: xy(s.guide_normal()),
            foot: pt(s.foot()),
            offset: s.offset(),
            link_ratio: s.link_ratio(),
            turns_fully: range.is_full(),
            input_range: (!range.is_full())
                .then(|| arcs[..n].iter().map(|a| (a.start, a.end)).collect()),
            dead_positions: range.dead_positions(),
            collinear_positions: s
                .collinear_positions()
                .into_iter()
                .map(|(p, m)| (p.theta2, p.slider, m.as_str()))
                .collect(),
        }
    }
}

#[pymethods]
impl PySliderCrank {
    #[new]
    #[pyo3(signature = (*args, crank = None, coupler = None, guide_point = None,
        guide = PyPoint(Point2::new(1.0, 0.0)), pivot = PyPoint(Point2::origin())),
        text_signature = "(*, crank, coupler, guide_point, guide=(1.0, 0.0), pivot=(0.0, 0.0))")]
    fn new(
        args: &Bound<'_, PyTuple>,
        crank: Option<Real>,
        coupler: Option<Real>,
        guide_point: Option<PyPoint>,
        guide: PyPoint,
        pivot: PyPoint,
    ) -> PyResult<Self> {
        let (true, Some(crank), Some(coupler), Some(guide_point)) =
            (args.is_empty(), crank, coupler, guide_point)
        else {
            return Err(PyTypeError::new_err(
                "SliderCrank takes its parts by name: SliderCrank(crank=..., coupler=..., \
                 guide_point=(x, y), guide=(ux, uy), pivot=(x, y))",
            ));
        };
        SliderCrank::new(pivot.0, crank.0, coupler.0, guide_point.0, guide.0.coords)
            .map(Self::from)
            .py()
    }

    fn __getnewargs_ex__<'py>(&self, py: Python<'py>) -> PyResult<((), Bound<'py, PyDict>)> {
        let s = &self.inner;
        let kw = PyDict::new(py);
        kw.set_item("crank", s.crank())?;
        kw.set_item("coupler", s.coupler())?;
        let (point, direction) = s.guide_as_given();
        kw.set_item("guide_point", pt(point))?;
        kw.set_item("guide", xy(direction))?;
        kw.set_item("pivot", pt(s.crank_pivot()))?;
        Ok(((), kw))
    }

    fn guide_point(&self, slider: Real) -> Xy {
        pt(self.inner.guide_point(slider.0))
    }

    #[pyo3(signature = (theta2, mode = "open"))]
    fn solve(&self, theta2: Real, mode: &str) -> PyResult<PySliderConfiguration> {
        let c = self.inner.solve(theta2.0, self::mode(mode)?).py()?;
        Ok(PySliderConfiguration::new(c, self.inner))
    }

    #[pyo3(signature = (theta2, mode = "open"))]
    fn joints(&self, theta2: Real, mode: &str) -> PyResult<(Xy, Xy, Xy)> {
        let j = self.inner.joints_at(theta2.0, self::mode(mode)?).py()?;
        Ok((pt(j.crank_pivot), pt(j.crank_joint), pt(j.slider_joint)))
    }

    #[pyo3(signature = (theta2, point, mode = "open"))]
    fn coupler_point(&self, theta2: Real, point: PyPoint, mode: &str) -> PyResult<Xy> {
        linkage::coupler_point(&self.inner, theta2, point, mode)
    }

    /// `(xs, ys, ok)` over the crank angles (NaN and False where the loop
    /// does not close).
    #[pyo3(signature = (point, theta2s, mode = "open"))]
    fn coupler_path<'py>(
        &self,
        py: Python<'py>,
        point: PyPoint,
        theta2s: FloatArray<'py>,
        mode: &str,
    ) -> PyResult<Arrays<'py>> {
        linkage::coupler_path(&self.inner, py, point, theta2s, mode)
    }

    /// `((theta2, slider), (theta2, slider))`: the lowest and the highest
    /// slider position in `mode`.
    #[pyo3(signature = (mode = "open"))]
    fn limits(&self, mode: &str) -> PyResult<(Xy, Xy)> {
        let [lo, hi] = self.inner.limits(self::mode(mode)?);
        Ok(((lo.theta2, lo.slider), (hi.theta2, hi.slider)))
    }

    #[pyo3(signature = (mode = "open"))]
    fn stroke(&self, mode: &str) -> PyResult<f64> {
        Ok(self.inner.stroke(self::mode(mode)?))
    }

    fn __repr__(&self) -> String {
        let s = &self.inner;
        // The arguments as given: evaluating the repr rebuilds it exactly.
        let (p, (f, u)) = (s.crank_pivot(), s.guide_as_given());
        format!(
            "SliderCrank(crank={:?}, coupler={:?}, guide_point=({:?}, {:?}), guide=({:?}, {:?}), \
             pivot=({:?}, {:?}))",
            s.crank(),
            s.coupler(),
            f.x,
            f.y,
            u.x,
            u.y,
            p.x,
            p.y
        )
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PySliderCrank>()
            .is_ok_and(|o| o.get().inner == self.inner)
    }
}

/// One solved position of a slider-crank: its fields.
#[pyclass(frozen, name = "SliderConfiguration", module = "burmester")]
#[derive(Clone)]
pub struct PySliderConfiguration {
    inner: SliderConfiguration,
    /// The linkage it is a position of (for pickling).
    linkage: SliderCrank,
    #[pyo3(get)]
    theta2: f64,
    #[pyo3(get)]
    theta3: f64,
    #[pyo3(get)]
    slider: f64,
    #[pyo3(get)]
    mode: &'static str,
    #[pyo3(get)]
    toggle: bool,
    #[pyo3(get)]
    transmission_angle: f64,
}

impl PySliderConfiguration {
    fn new(c: SliderConfiguration, linkage: SliderCrank) -> Self {
        PySliderConfiguration {
            inner: c,
            linkage,
            theta2: c.theta2,
            theta3: c.theta3,
            slider: c.slider,
            mode: c.mode.as_str(),
            toggle: c.toggle,
            transmission_angle: c.transmission_angle,
        }
    }
}

configuration_methods!(
    PySliderConfiguration,
    PySliderCrank,
    "SliderConfiguration",
    slider
);

synthesized_crank! {
    /// A slider-crank built from a driving crank and a driven slider of a
    /// task; what it derives without arguments is computed once and read as
    /// fields.
    pub struct PySynthesizedSliderCrank(
        SynthesizedSliderCrank, "SynthesizedSliderCrank", linkage: PySliderCrank
    );
    fn new(s, task) {
        /// `(C1, u)`.
        #[pyo3(get)]
        driven: (Xy, Xy) = (pt(s.driven.circle), xy(s.driven.guide)),
        #[pyo3(get)]
        slider_positions: Vec<f64> = s.slider_positions.to_vec(),
    }
    reduce "slider_crank" with key(this) = (this.driving, this.driven);
}

impl PySynthesizedSliderCrank {
    /// The core's slider-crank.
    pub(crate) fn core(&self) -> &SynthesizedSliderCrank {
        &self.inner
    }

    /// Its size over its task's span.
    pub(crate) fn size_ratio_of(&self) -> f64 {
        self.size_ratio
    }
}

#[pymethods]
impl PySynthesizedSliderCrank {
    fn __repr__(&self) -> String {
        let l = &self.inner.linkage;
        format!(
            "<SynthesizedSliderCrank crank={:.6} coupler={:.6} offset={:.6} branch_free={} \
             direction={}>",
            l.crank(),
            l.coupler(),
            l.offset(),
            if self.inner.is_branch_free() {
                "True"
            } else {
                "False"
            },
            self.inner.direction
        )
    }
}

#[pymethods]
impl PyTask {
    /// The slider-crank of the driving crank `(A0, A1)` and the driven
    /// slider `(C1, u)` (its pin at pose 1 and the guide's direction).
    fn slider_crank(
        &self,
        driving: (PyPoint, PyPoint),
        driven: (PyPoint, PyPoint),
    ) -> PyResult<PySynthesizedSliderCrank> {
        let d = Dyad::new(driving.0.0, driving.1.0);
        let s = SliderDyad::new(driven.0.0, driven.1.0.coords).py()?;
        let inner = self.inner.slider_crank(&d, &s).py()?;
        Ok(PySynthesizedSliderCrank::new(inner, self.inner))
    }
}
