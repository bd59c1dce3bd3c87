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
use pyo3::types::{PyDict, PyTuple};

use crate::classes::PyTask;
use crate::conv::{Arrays, FloatArray, PyPoint, Real, pt};
use crate::crank_synth::{configuration_methods, synthesized_crank};
use crate::errors::IntoPy;
use crate::linkage::{self, mode};

type Xy = (f64, f64);

/// `(theta2, slot, theta3)` of a limit, lowest and highest.
type Limits = ((f64, f64, f64), (f64, f64, f64));

/// `(theta2, slot, theta3)` of a limit.
fn limit(l: InvertedLimit) -> (f64, f64, f64) {
    (l.theta2, l.slot, l.theta3)
}

/// An inverted slider-crank (RRPR): a crank whose coupler's slot slides
/// through a block pivoted on the ground at the swivel. What it derives
/// without arguments is computed once and read as fields.
#[pyclass(frozen, name = "InvertedSliderCrank", module = "burmester")]
#[derive(Clone)]
pub struct PyInvertedSliderCrank {
    inner: InvertedSliderCrank,
    #[pyo3(get)]
    crank: f64,
    #[pyo3(get)]
    pivot: Xy,
    #[pyo3(get)]
    swivel: Xy,
    #[pyo3(get)]
    offset: f64,
    #[pyo3(get)]
    ground: f64,
    #[pyo3(get)]
    turns_fully: bool,
    /// `None` when the crank turns fully, else its `(start, end)` arc.
    #[pyo3(get)]
    input_range: Option<Vec<Xy>>,
    #[pyo3(get)]
    dead_positions: Vec<f64>,
    #[pyo3(get)]
    stroke: f64,
}

impl From<InvertedSliderCrank> for PyInvertedSliderCrank {
    fn from(s: InvertedSliderCrank) -> Self {
        let range = s.input_range();
        let (arcs, n) = range.arcs_array();
        PyInvertedSliderCrank {
            inner: s,
            crank: s.crank(),
            pivot: pt(s.crank_pivot()),
            swivel: pt(s.swivel()),
            offset: s.offset(),
            ground: s.ground(),
            turns_fully: range.is_full(),
            input_range: (!range.is_full())
                .then(|| arcs[..n].iter().map(|a| (a.start, a.end)).collect()),
            dead_positions: range.dead_positions(),
            stroke: s.stroke(),
        }
    }
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

    fn __getnewargs_ex__<'py>(&self, py: Python<'py>) -> PyResult<((), Bound<'py, PyDict>)> {
        let s = &self.inner;
        let kw = PyDict::new(py);
        kw.set_item("crank", s.crank())?;
        kw.set_item("swivel", pt(s.swivel()))?;
        kw.set_item("offset", s.offset())?;
        kw.set_item("pivot", pt(s.crank_pivot()))?;
        Ok(((), kw))
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

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PyInvertedSliderCrank>()
            .is_ok_and(|o| o.get().inner == self.inner)
    }
}

/// One solved position of an inverted slider-crank: its fields.
#[pyclass(frozen, name = "InvertedConfiguration", module = "burmester")]
#[derive(Clone)]
pub struct PyInvertedConfiguration {
    inner: InvertedConfiguration,
    /// The linkage it is a position of (for pickling).
    linkage: InvertedSliderCrank,
    #[pyo3(get)]
    theta2: f64,
    #[pyo3(get)]
    theta3: f64,
    #[pyo3(get)]
    slot: f64,
    #[pyo3(get)]
    mode: &'static str,
    #[pyo3(get)]
    toggle: bool,
    #[pyo3(get)]
    transmission_angle: f64,
}

impl PyInvertedConfiguration {
    fn new(c: InvertedConfiguration, linkage: InvertedSliderCrank) -> Self {
        PyInvertedConfiguration {
            inner: c,
            linkage,
            theta2: c.theta2,
            theta3: c.theta3,
            slot: c.slot,
            mode: c.mode.as_str(),
            toggle: c.toggle,
            transmission_angle: c.transmission_angle,
        }
    }
}

configuration_methods!(
    PyInvertedConfiguration,
    PyInvertedSliderCrank,
    "InvertedConfiguration",
    slot
);

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
    reduce "inverted_slider_crank" with key(this) = this.given;
}

#[pymethods]
impl PySynthesizedInvertedSliderCrank {
    fn __repr__(&self) -> String {
        let l = &self.inner.linkage;
        format!(
            "<SynthesizedInvertedSliderCrank crank={:.6} ground={:.6} offset={:.6} \
             branch_free={} direction={}>",
            l.crank(),
            l.ground(),
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
    /// The inverted slider-crank of the driving crank `(A0, A1)` and the
    /// inverted slider `(S, d)` (its swivel and the slot's direction at
    /// pose 1, as `InvertedSlider.swivel` and `.direction`).
    fn inverted_slider_crank(
        &self,
        driving: (PyPoint, PyPoint),
        driven: (PyPoint, PyPoint),
    ) -> PyResult<PySynthesizedInvertedSliderCrank> {
        let d = Dyad::new(driving.0.0, driving.1.0);
        let v = InvertedSlider {
            swivel: driven.0.0,
            direction: driven.1.0.coords,
        };
        let inner = self.inner.inverted_slider_crank(&d, &v).py()?;
        let given = (
            (pt(driving.0.0), pt(driving.1.0)),
            (pt(driven.0.0), pt(driven.1.0)),
        );
        Ok(PySynthesizedInvertedSliderCrank::new(
            inner, self.inner, given,
        ))
    }
}
