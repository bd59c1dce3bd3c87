//! `burmester.SliderCrank`, `burmester.SliderConfiguration` and
//! `burmester.SynthesizedSliderCrank` (the core's `linkage::slider` and
//! `synthesis::slider_crank`), with `Task.slider_crank`.

use burmester::{
    Dyad, Point2, SliderConfiguration, SliderCrank, SliderDyad, SynthesizedSliderCrank, Vector2,
};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::conv::{PyPoint, Real, pt};
use crate::crank_synth::{crank_linkage, synthesized_crank};
use crate::errors::IntoPy;
use crate::linkage::mode;

type Xy = (f64, f64);

fn xy(v: Vector2<f64>) -> Xy {
    (v.x, v.y)
}

crank_linkage! {
    /// A slider-crank (RRRP): crank about a fixed pivot, coupler, slider pin
    /// on a straight guide. What it derives without arguments is computed once
    /// and read as fields.
    pub struct PySliderCrank(SliderCrank, "SliderCrank");
    fn from(s) {
        #[pyo3(get)]
        coupler: f64 = s.coupler(),
        #[pyo3(get)]
        guide: Xy = xy(s.guide()),
        #[pyo3(get)]
        guide_normal: Xy = xy(s.guide_normal()),
        #[pyo3(get)]
        foot: Xy = pt(s.foot()),
        #[pyo3(get)]
        link_ratio: f64 = s.link_ratio(),
        /// `[(theta2, slider, mode)]` where crank and coupler are collinear.
        #[pyo3(get)]
        collinear_positions: Vec<(f64, f64, &'static str)> = s
            .collinear_positions()
            .into_iter()
            .map(|(p, m)| (p.theta2, p.slider, m.as_str()))
            .collect(),
    }
    by name {
        "coupler": s.coupler(),
        "guide_point": pt(s.guide_as_given().0),
        "guide": xy(s.guide_as_given().1),
    }
    /// One solved position of a slider-crank: its fields.
    pub struct PySliderConfiguration(SliderConfiguration, "SliderConfiguration", slider);
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
}

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
    reduce with key(this) = (this.driving, this.driven);
    repr crank, coupler, offset;
    /// The slider-crank of the driving crank `(A0, A1)` and the driven
    /// slider `(C1, u)` (its pin at pose 1 and the guide's direction).
    fn slider_crank(task, driving, driven) {
        let d = Dyad::new(driving.0.0, driving.1.0);
        let s = SliderDyad::new(driven.0.0, driven.1.0.coords).py()?;
        let inner = task.slider_crank(&d, &s).py()?;
        Ok(PySynthesizedSliderCrank::new(inner, task))
    }
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

// Pictures in Jupyter (`_repr_png_`).
crate::display::repr_png_for!(PySliderCrank, PySynthesizedSliderCrank);
