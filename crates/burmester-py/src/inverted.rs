//! `burmester.InvertedSliderCrank`, `burmester.InvertedConfiguration` and
//! `burmester.SynthesizedInvertedSliderCrank` (the core's
//! `linkage::inverted` and `synthesis::inverted_crank`), with
//! `Task.inverted_slider_crank`: convert and delegate.

use burmester::{
    Dyad, InvertedConfiguration, InvertedLimit, InvertedSlider, InvertedSliderCrank, Point2,
    SynthesizedInvertedSliderCrank,
};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::conv::{PyPoint, Real, pt};
use crate::crank_synth::{crank_linkage, synthesized_crank};
use crate::errors::IntoPy;
use crate::linkage::mode;

type Xy = (f64, f64);

/// `(theta2, slot, theta3)` of a limit, lowest and highest.
type Limits = ((f64, f64, f64), (f64, f64, f64));

/// `(theta2, slot, theta3)` of a limit.
fn limit(l: InvertedLimit) -> (f64, f64, f64) {
    (l.theta2, l.slot, l.theta3)
}

crank_linkage! {
    /// An inverted slider-crank (RRPR): a crank whose coupler's slot slides
    /// through a block pivoted on the ground at the swivel. What it derives
    /// without arguments is computed once and read as fields.
    pub struct PyInvertedSliderCrank(InvertedSliderCrank, "InvertedSliderCrank");
    fn from(s) {
        #[pyo3(get)]
        swivel: Xy = pt(s.swivel()),
        #[pyo3(get)]
        ground: f64 = s.ground(),
        #[pyo3(get)]
        stroke: f64 = s.stroke(),
    }
    by name {
        "swivel": pt(s.swivel()),
        "offset": s.offset(),
    }
    /// One solved position of an inverted slider-crank: its fields.
    pub struct PyInvertedConfiguration(InvertedConfiguration, "InvertedConfiguration", slot);
}

#[pymethods]
impl PyInvertedSliderCrank {
    #[new]
    #[pyo3(signature = (*args, crank = None, swivel = None, offset = Real(0.0),
        pivot = PyPoint(Point2::origin())),
        text_signature = "(*, crank, swivel, offset=0.0, pivot=(0.0, 0.0))")]
    fn new(
        args: &Bound<'_, PyTuple>,
        crank: Option<Real>,
        swivel: Option<PyPoint>,
        offset: Real,
        pivot: PyPoint,
    ) -> PyResult<Self> {
        let (true, Some(crank), Some(swivel)) = (args.is_empty(), crank, swivel) else {
            return Err(PyTypeError::new_err(
                "InvertedSliderCrank takes its parts by name: InvertedSliderCrank(crank=..., \
                 swivel=(x, y), offset=..., pivot=(x, y))",
            ));
        };
        InvertedSliderCrank::new(pivot.0, crank.0, swivel.0, offset.0)
            .map(Self::from)
            .py()
    }

    #[pyo3(signature = (theta2, mode = "open"))]
    fn solve(&self, theta2: Real, mode: &str) -> PyResult<PyInvertedConfiguration> {
        let c = self.inner.solve(theta2.0, self::mode(mode)?).py()?;
        Ok(PyInvertedConfiguration::new(c, self.inner))
    }

    /// `(A0, A, S, F)`: crank pivot, crank pin, swivel, and the foot of the
    /// perpendicular from the pin to the slot.
    #[pyo3(signature = (theta2, mode = "open"))]
    fn joints(&self, theta2: Real, mode: &str) -> PyResult<(Xy, Xy, Xy, Xy)> {
        let j = self.inner.joints_at(theta2.0, self::mode(mode)?).py()?;
        Ok((
            pt(j.crank_pivot),
            pt(j.crank_joint),
            pt(j.swivel),
            pt(j.slot_foot),
        ))
    }

    /// `((theta2, slot, theta3), (theta2, slot, theta3))`: the lowest and
    /// the highest slot position in `mode`.
    #[pyo3(signature = (mode = "open"))]
    fn slot_limits(&self, mode: &str) -> PyResult<Limits> {
        let [lo, hi] = self.inner.slot_limits(self::mode(mode)?);
        Ok((limit(lo), limit(hi)))
    }

    /// The slotted link's swing's ends in `mode`, `((theta2, slot,
    /// theta3), (theta2, slot, theta3))`, or `None` where it turns fully.
    #[pyo3(signature = (mode = "open"))]
    fn swing(&self, mode: &str) -> PyResult<Option<Limits>> {
        Ok(self
            .inner
            .swing(self::mode(mode)?)
            .map(|[lo, hi]| (limit(lo), limit(hi))))
    }

    #[pyo3(signature = (mode = "open"))]
    fn time_ratio(&self, mode: &str) -> PyResult<Option<f64>> {
        Ok(self.inner.time_ratio(self::mode(mode)?))
    }

    fn __repr__(&self) -> String {
        let s = &self.inner;
        let (p, w) = (s.crank_pivot(), s.swivel());
        format!(
            "InvertedSliderCrank(crank={:?}, swivel=({:?}, {:?}), offset={:?}, pivot=({:?}, {:?}))",
            s.crank(),
            w.x,
            w.y,
            s.offset(),
            p.x,
            p.y
        )
    }
}

synthesized_crank! {
    /// An inverted slider-crank built from a driving crank and an inverted
    /// slider of a task; what it derives without arguments is computed once
    /// and read as fields.
    pub struct PySynthesizedInvertedSliderCrank(
        SynthesizedInvertedSliderCrank,
        "SynthesizedInvertedSliderCrank",
        linkage: PyInvertedSliderCrank
    );
    fn new(s, task, given: ((Xy, Xy), (Xy, Xy))) {
        /// The arguments as given (for pickling and equality).
        given: ((Xy, Xy), (Xy, Xy)) = given,
        /// `(S, d)`: the swivel and the slot's unit direction at pose 1.
        #[pyo3(get)]
        driven: (Xy, Xy) = (pt(s.driven.swivel), (s.driven.direction.x, s.driven.direction.y)),
        #[pyo3(get)]
        slot_positions: Vec<f64> = s.slot_positions.to_vec(),
        #[pyo3(get)]
        swing_used_deg: Option<f64> = finite_or_none(s.swing_used).map(f64::to_degrees),
    }
    reduce with key(this) = this.given;
    repr crank, ground, offset;
    /// The inverted slider-crank of the driving crank `(A0, A1)` and the
    /// inverted slider `(S, d)` (its swivel and the slot's direction at
    /// pose 1, as `InvertedSlider.swivel` and `.direction`).
    fn inverted_slider_crank(task, driving, driven) {
        let d = Dyad::new(driving.0.0, driving.1.0);
        let v = InvertedSlider {
            swivel: driven.0.0,
            direction: driven.1.0.coords,
        };
        let inner = task.inverted_slider_crank(&d, &v).py()?;
        let given = (
            (pt(driving.0.0), pt(driving.1.0)),
            (pt(driven.0.0), pt(driven.1.0)),
        );
        Ok(PySynthesizedInvertedSliderCrank::new(inner, task, given))
    }
}

// Pictures in Jupyter (`_repr_png_`).
crate::display::repr_png_for!(PyInvertedSliderCrank, PySynthesizedInvertedSliderCrank);
