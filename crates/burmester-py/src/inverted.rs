//! `burmester.InvertedSliderCrank`, `burmester.InvertedConfiguration` and
//! `burmester.SynthesizedInvertedSliderCrank` (the core's
//! `linkage::inverted` and `synthesis::inverted_crank`), with
//! `Task.inverted_slider_crank`: convert and delegate.

use burmester::{
    AssemblyMode, Dyad, InvertedConfiguration, InvertedLimit, InvertedSlider, InvertedSliderCrank,
    Point2, SynthesizedInvertedSliderCrank, Task,
};
use numpy::PyArrayDyn;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use crate::classes::PyTask;
use crate::conv::{
    Arrays, Count, FloatArray, PyPoint, Real, fill_arrays, pt, to_numpy, write_points,
};
use crate::errors::IntoPy;
use crate::linkage::mode;

type Xy = (f64, f64);

/// `(theta2, slot, theta3)` of a limit, lowest and highest.
type Limits = ((f64, f64, f64), (f64, f64, f64));

/// `None` for NaN.
fn finite_or_none(v: f64) -> Option<f64> {
    (!v.is_nan()).then_some(v)
}

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
        let m = self::mode(mode)?;
        let mut it = self.inner.coupler_path(point.0.coords, [theta2.0], m);
        it.next().expect("one angle in, one point out").map(pt).py()
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
        let m = self::mode(mode)?;
        let local = point.0.coords;
        let first = self.inner.coupler_path(local, [0.0], m).next();
        if let Some(Err(e @ burmester::Error::InvalidInput(_))) = first {
            return Err(e).py();
        }
        let (flat, shape) = (theta2s.values(), theta2s.shape());
        let sc = self.inner;
        fill_arrays(py, shape, |xs, ys, ok| {
            write_points(sc.coupler_path(local, flat.iter().copied(), m), xs, ys, ok);
        })
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

#[pymethods]
impl PyInvertedConfiguration {
    fn __repr__(&self) -> String {
        let c = &self.inner;
        format!(
            "InvertedConfiguration(theta2={:?}, theta3={:?}, slot={:?}, mode='{}', toggle={})",
            c.theta2,
            c.theta3,
            c.slot,
            c.mode.as_str(),
            if c.toggle { "True" } else { "False" }
        )
    }
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<PyInvertedConfiguration>().is_ok_and(|o| {
            let o = o.get();
            o.inner == self.inner && o.linkage == self.linkage
        })
    }
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, (f64, &'static str))> {
        let sc = Bound::new(py, PyInvertedSliderCrank::from(self.linkage))?;
        Ok((
            sc.getattr("solve")?,
            (self.inner.theta2, self.inner.mode.as_str()),
        ))
    }
}

/// An inverted slider-crank built from a driving crank and an inverted
/// slider of a task; what it derives without arguments is computed once
/// and read as fields.
#[pyclass(frozen, name = "SynthesizedInvertedSliderCrank", module = "burmester")]
#[derive(Clone)]
pub struct PySynthesizedInvertedSliderCrank {
    inner: SynthesizedInvertedSliderCrank,
    /// The task it was built for (for pickling).
    task: Task,
    /// The arguments as given (for pickling and equality).
    given: ((Xy, Xy), (Xy, Xy)),
    #[pyo3(get)]
    linkage: PyInvertedSliderCrank,
    /// `(A0, A1)`.
    #[pyo3(get)]
    driving: (Xy, Xy),
    /// `(S, d)`: the swivel and the slot's unit direction at pose 1.
    #[pyo3(get)]
    driven: (Xy, Xy),
    #[pyo3(get)]
    input_angles: Vec<f64>,
    #[pyo3(get)]
    modes: Vec<Option<&'static str>>,
    #[pyo3(get)]
    slot_positions: Vec<f64>,
    #[pyo3(get)]
    coupler_point: Xy,
    #[pyo3(get)]
    coupler_angle_offset: f64,
    #[pyo3(get)]
    direction: &'static str,
    #[pyo3(get)]
    one_circuit: bool,
    #[pyo3(get)]
    min_transmission_deg: Option<f64>,
    #[pyo3(get)]
    stroke_used: Option<f64>,
    #[pyo3(get)]
    swing_used_deg: Option<f64>,
    #[pyo3(get)]
    size: f64,
    #[pyo3(get)]
    size_ratio: f64,
    #[pyo3(get)]
    branch_free: bool,
    #[pyo3(get)]
    feasible: bool,
    /// The cyclic order of the crank's positions, `"1-2-3"`.
    #[pyo3(get)]
    order: String,
    #[pyo3(get)]
    travel: Option<Xy>,
    #[pyo3(get)]
    travel_stops: Option<Vec<f64>>,
}

impl PySynthesizedInvertedSliderCrank {
    fn new(s: SynthesizedInvertedSliderCrank, task: Task, given: ((Xy, Xy), (Xy, Xy))) -> Self {
        let (d, g) = (&s.driving, &s.driven);
        PySynthesizedInvertedSliderCrank {
            inner: s,
            task,
            given,
            linkage: s.linkage.into(),
            driving: (pt(d.center), pt(d.circle)),
            driven: (pt(g.swivel), (g.direction.x, g.direction.y)),
            input_angles: s.input_angles.to_vec(),
            modes: s
                .modes
                .iter()
                .map(|m| m.map(AssemblyMode::as_str))
                .collect(),
            slot_positions: s.slot_positions.to_vec(),
            coupler_point: (s.coupler_point.x, s.coupler_point.y),
            coupler_angle_offset: s.coupler_angle_offset,
            direction: s.direction.as_str(),
            one_circuit: s.one_circuit,
            min_transmission_deg: finite_or_none(s.min_transmission).map(f64::to_degrees),
            stroke_used: finite_or_none(s.stroke_used),
            swing_used_deg: finite_or_none(s.swing_used).map(f64::to_degrees),
            size: s.size(),
            size_ratio: s.size() / task.span(),
            branch_free: s.is_branch_free(),
            feasible: s.feasible(),
            order: s.order().to_string(),
            travel: s.travel(),
            travel_stops: s.travel_stops().map(|t| t.to_vec()),
        }
    }
}

#[pymethods]
impl PySynthesizedInvertedSliderCrank {
    fn __reduce__<'py>(&self, py: Python<'py>) -> crate::pickle::Reduced<'py> {
        let task = Bound::new(py, PyTask { inner: self.task })?;
        let args = self.given.into_pyobject(py)?;
        Ok((task.getattr("inverted_slider_crank")?, args))
    }
    /// Equal when built from the same task and arguments, bit for bit (the
    /// rest is a function of them; NaN figures would make a field-wise
    /// comparison unequal to itself).
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        let bits = |(a, b): ((Xy, Xy), (Xy, Xy))| {
            [a.0.0, a.0.1, a.1.0, a.1.1, b.0.0, b.0.1, b.1.0, b.1.1].map(f64::to_bits)
        };
        other
            .cast::<PySynthesizedInvertedSliderCrank>()
            .is_ok_and(|o| {
                let o = o.get();
                o.task == self.task && bits(o.given) == bits(self.given)
            })
    }
    fn travel_angles<'py>(
        &self,
        py: Python<'py>,
        samples: Count,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let s = self.inner;
        let v = py.detach(|| s.travel_angles(samples.0)).py()?;
        Ok(to_numpy(py, &[v.len()], v))
    }
    #[pyo3(signature = (theta2, mode = "open"))]
    fn pose_at(&self, theta2: Real, mode: &str) -> PyResult<(f64, f64, f64)> {
        let p = self.inner.pose_at(theta2.0, self::mode(mode)?).py()?;
        Ok((p.position.x, p.position.y, p.angle))
    }

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
