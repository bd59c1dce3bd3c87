//! `burmester.Space`, `burmester.Design`, `burmester.NearMiss`,
//! `burmester.DesignReport` and the native half of `burmester.design`
//! (the core's `design::search`): `_design` (the whole search in process),
//! `_design_plan` (the three-pose coarse pass a Dask client computes) and
//! `_design_from_atlas` (the refinement of those cells). With
//! `input="motor"` the designs whose input swings carry their drive
//! (`burmester.Drive`).

use burmester::design::{ActuatorOptions, DriveOptions};
use burmester::{
    ActuatorLink, ActuatorSearch, AtlasBest, AtlasCell, Constraints, Design, DesignLimits,
    DesignOptions, DesignReport, DesignedLinkage, DrivenKind, Dyad, InputRequirement, InvalidInput,
    Limit, NearMiss, PivotRegion, Point2, RankBy, SearchPoint, SliderDyad, Space, Task, Viewport,
};
use numpy::{PyArrayDyn, PyArrayMethods};
use pyo3::exceptions::{PyIndexError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::actuator::PyActuator;
use crate::classes::{PyDesignLimits, PySynthesizedFourBar, PyTask, dyad_tuple};
use crate::conv::{Count, PyPoint, Real, pt};
use crate::drive::PyDrive;
use crate::errors::IntoPy;
use crate::geom::PyGrid;
use crate::getters::getters;
use crate::pickle::{Reduced, reduce_to};
use crate::run::run;
use crate::slider::PySynthesizedSliderCrank;

type Xy = (f64, f64);
type Box4 = (f64, f64, f64, f64);

fn pts(v: Vec<PyPoint>) -> Vec<Point2<f64>> {
    v.into_iter().map(|p| p.0).collect()
}

fn xys(v: &[Point2<f64>]) -> Vec<Xy> {
    v.iter().map(|p| pt(*p)).collect()
}

/// The space a design must fit in.
#[pyclass(frozen, eq, from_py_object, name = "Space", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PySpace {
    pub(crate) inner: Space,
}

#[pymethods]
impl PySpace {
    #[new]
    #[pyo3(signature = (pivot_box = None, pivot_polygon = None, obstacles = None,
        link_width = Real(0.0), envelope = None, travel_samples = Count(64)),
        text_signature = "(pivot_box=None, pivot_polygon=None, obstacles=None, link_width=0.0, \
        envelope=None, travel_samples=64)")]
    fn new(
        pivot_box: Option<(Real, Real, Real, Real)>,
        pivot_polygon: Option<Vec<PyPoint>>,
        obstacles: Option<Vec<Vec<PyPoint>>>,
        link_width: Real,
        envelope: Option<Vec<PyPoint>>,
        travel_samples: Count,
    ) -> PyResult<Self> {
        let pivots = match (pivot_box, pivot_polygon) {
            (Some(_), Some(_)) => {
                return Err(PyTypeError::new_err(
                    "pass either pivot_box=(xmin, xmax, ymin, ymax) or pivot_polygon=[(x, y), ...], \
                     not both",
                ));
            }
            (Some((a, b, c, d)), None) => PivotRegion::boxed(a.0, b.0, c.0, d.0).py()?,
            (None, Some(p)) => PivotRegion::Polygon(pts(p)),
            (None, None) => PivotRegion::Anywhere,
        };
        let inner = Space {
            pivots,
            obstacles: obstacles.unwrap_or_default().into_iter().map(pts).collect(),
            link_width: link_width.0,
            envelope: envelope.map(pts),
            travel_samples: travel_samples.0,
        };
        inner.check().py()?;
        Ok(PySpace { inner })
    }
    /// `"anywhere"`, `"box"` or `"polygon"`.
    #[getter]
    fn region(&self) -> &'static str {
        self.inner.pivots.as_str()
    }
    #[getter]
    fn pivot_box(&self) -> Option<Box4> {
        match &self.inner.pivots {
            PivotRegion::Box(v) => Some((v.xmin, v.xmax, v.ymin, v.ymax)),
            _ => None,
        }
    }
    #[getter]
    fn pivot_polygon(&self) -> Option<Vec<Xy>> {
        match &self.inner.pivots {
            PivotRegion::Polygon(p) => Some(xys(p)),
            _ => None,
        }
    }
    #[getter]
    fn obstacles(&self) -> Vec<Vec<Xy>> {
        self.inner.obstacles.iter().map(|o| xys(o)).collect()
    }
    #[getter]
    fn envelope(&self) -> Option<Vec<Xy>> {
        self.inner.envelope.as_deref().map(xys)
    }
    fn contains_pivot(&self, p: PyPoint) -> bool {
        self.inner.pivots.contains(p.0)
    }
    fn search_box(&self, task: &PyTask, limits: Option<PyDesignLimits>) -> Box4 {
        let l = limits.map(|l| l.inner).unwrap_or_default();
        let v = self.inner.search_box(&task.inner, &l);
        (v.xmin, v.xmax, v.ymin, v.ymax)
    }
    #[allow(clippy::type_complexity)]
    fn __getnewargs__(
        &self,
    ) -> (
        Option<Box4>,
        Option<Vec<Xy>>,
        Vec<Vec<Xy>>,
        f64,
        Option<Vec<Xy>>,
        usize,
    ) {
        (
            self.pivot_box(),
            self.pivot_polygon(),
            self.obstacles(),
            self.inner.link_width,
            self.envelope(),
            self.inner.travel_samples,
        )
    }
    fn __repr__(&self) -> String {
        let mut parts = Vec::new();
        if let Some(b) = self.pivot_box() {
            parts.push(format!("pivot_box={b:?}"));
        }
        if let Some(p) = self.pivot_polygon() {
            parts.push(format!("pivot_polygon=<{} vertices>", p.len()));
        }
        if !self.inner.obstacles.is_empty() {
            parts.push(format!("obstacles=<{}>", self.inner.obstacles.len()));
        }
        if self.inner.link_width != 0.0 {
            parts.push(format!("link_width={:?}", self.inner.link_width));
        }
        if let Some(e) = &self.inner.envelope {
            parts.push(format!("envelope=<{} vertices>", e.len()));
        }
        format!("Space({})", parts.join(", "))
    }
}

getters!(PySpace, inner {
    f64: link_width;
    usize: travel_samples;
});

/// A search point as `(kind, values)` (for pickling).
fn point_state(p: &SearchPoint) -> (&'static str, [f64; 4]) {
    match *p {
        SearchPoint::Pivots { driving, driven } => {
            ("pivots", [driving.x, driving.y, driven.x, driven.y])
        }
        SearchPoint::Parameters { driving, driven } => ("parameters", [driving, driven, 0.0, 0.0]),
        SearchPoint::Burmester { driving, driven } => {
            ("burmester", [driving as f64, driven as f64, 0.0, 0.0])
        }
        SearchPoint::SliderCircle { driving, slider } => {
            ("slider_circle", [driving.x, driving.y, slider, 0.0])
        }
        SearchPoint::SliderPoint { driving, slider } => {
            ("slider_point", [driving, slider as f64, 0.0, 0.0])
        }
    }
}

fn point_of(kind: &str, v: [f64; 4]) -> PyResult<SearchPoint> {
    Ok(match kind {
        "pivots" => SearchPoint::Pivots {
            driving: Point2::new(v[0], v[1]),
            driven: Point2::new(v[2], v[3]),
        },
        "parameters" => SearchPoint::Parameters {
            driving: v[0],
            driven: v[1],
        },
        "burmester" => SearchPoint::Burmester {
            driving: v[0] as usize,
            driven: v[1] as usize,
        },
        "slider_circle" => SearchPoint::SliderCircle {
            driving: Point2::new(v[0], v[1]),
            slider: v[2],
        },
        "slider_point" => SearchPoint::SliderPoint {
            driving: v[0],
            slider: v[1] as usize,
        },
        other => {
            return Err(PyTypeError::new_err(format!(
                "unknown search point kind {other:?}"
            )));
        }
    })
}

/// A search point for Python: `((ax, ay), (cx, cy))` for pivots,
/// `(s_driving, s_driven)` for curve parameters, `(i, j)` for Burmester
/// points; with a driven slider `((ax, ay), t)` (three poses: the slider
/// circle's parameter) or `(s_or_i, j)` (the slider dyad's index).
fn point_py<'py>(py: Python<'py>, p: &SearchPoint) -> PyResult<Bound<'py, PyAny>> {
    Ok(match *p {
        SearchPoint::Pivots { driving, driven } => {
            (pt(driving), pt(driven)).into_pyobject(py)?.into_any()
        }
        SearchPoint::Parameters { driving, driven } => {
            (driving, driven).into_pyobject(py)?.into_any()
        }
        SearchPoint::Burmester { driving, driven } => {
            (driving, driven).into_pyobject(py)?.into_any()
        }
        SearchPoint::SliderCircle { driving, slider } => {
            (pt(driving), slider).into_pyobject(py)?.into_any()
        }
        SearchPoint::SliderPoint { driving, slider } => {
            (driving, slider).into_pyobject(py)?.into_any()
        }
    })
}

/// The linkage of two dyads of `task` (as built by the search): a
/// four-bar of the driven `(C0, C1)`, or with `kind` slider a slider-crank
/// of the driven `(C1, u)`.
fn linkage_of(
    task: &Task,
    driving: (PyPoint, PyPoint),
    driven: (PyPoint, PyPoint),
    kind: DrivenKind,
) -> PyResult<DesignedLinkage> {
    let a = Dyad::new(driving.0.0, driving.1.0);
    match kind {
        DrivenKind::Revolute => task
            .four_bar(&a, &Dyad::new(driven.0.0, driven.1.0))
            .map(DesignedLinkage::FourBar),
        DrivenKind::Slider => SliderDyad::new(driven.0.0, driven.1.0.coords)
            .and_then(|mut s| {
                // A unit guide kept bit for bit (normalizing a unit vector
                // again may move its last bit): the pickled design equals.
                let u = driven.1.0.coords;
                if (u.norm() - 1.0).abs() <= 4.0 * f64::EPSILON {
                    s.guide = u;
                }
                task.slider_crank(&a, &s)
            })
            .map(DesignedLinkage::SliderCrank),
    }
    .py()
}

/// The driven dyad of a designed linkage as two points (for pickling):
/// `(C0, C1)`, or a slider's `(C1, u)`.
fn driven_tuple(l: &DesignedLinkage) -> ((f64, f64), (f64, f64)) {
    match l {
        DesignedLinkage::FourBar(f) => dyad_tuple(&f.driven),
        DesignedLinkage::SliderCrank(s) => {
            (pt(s.driven.circle), (s.driven.guide.x, s.driven.guide.y))
        }
    }
}

/// A designed linkage for Python: a `SynthesizedFourBar` or a
/// `SynthesizedSliderCrank`.
fn linkage_py(py: Python<'_>, task: Task, l: &DesignedLinkage) -> PyResult<Py<PyAny>> {
    Ok(match l {
        DesignedLinkage::FourBar(f) => PySynthesizedFourBar::new(task, *f)
            .into_pyobject(py)?
            .into_any()
            .unbind(),
        DesignedLinkage::SliderCrank(s) => PySynthesizedSliderCrank::new(*s, task)
            .into_pyobject(py)?
            .into_any()
            .unbind(),
    })
}

/// The state readers a found linkage shares (`Design`, `NearMiss`): a
/// `#[pymethods]` block for `$cls`, whose `task` and `inner` (with
/// `linkage` and `size_ratio`) they read.
macro_rules! found_linkage_getters {
    ($cls:ident) => {
        #[pymethods]
        impl $cls {
            #[getter]
            fn linkage(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                linkage_py(py, self.task, &self.inner.linkage)
            }
            /// A four-bar's figures (None for a slider-crank: its
            /// figures are the linkage's own fields).
            #[getter]
            fn figures(&self) -> Option<crate::linkage::PyLinkageFigures> {
                let f = self.inner.linkage.four_bar()?;
                Some(PySynthesizedFourBar::new(self.task, *f).figures())
            }
            /// `"revolute"` (a four-bar) or `"slider"` (a slider-crank).
            #[getter]
            fn driven_kind(&self) -> &'static str {
                self.inner.linkage.kind().as_str()
            }
            #[getter]
            fn size_ratio(&self) -> f64 {
                self.inner.size_ratio
            }
        }
    };
}

found_linkage_getters!(PyDesign);
found_linkage_getters!(PyNearMiss);

/// One answer of `burmester.design`.
#[pyclass(frozen, from_py_object, name = "Design", module = "burmester")]
#[derive(Clone)]
pub struct PyDesign {
    task: Task,
    inner: Design,
    /// The drive with what it was found under (`inner.drive` for Python).
    drive: Option<PyDrive>,
    /// The actuator's options and the constraints it was placed under
    /// (with `inner.actuator`, for Python).
    strut: Option<(ActuatorOptions, DesignLimits, Constraints)>,
}

impl PyDesign {
    /// A design of `report` (its drive, if any, with the limits, the motor's
    /// options and the constraints it was found under).
    fn of(task: Task, report: &DesignReport, d: &Design) -> Self {
        let drive = d.drive.map(|drive| {
            PyDrive::found(
                drive,
                task,
                report.limits,
                report.motor.unwrap_or_default(),
                Constraints {
                    envelope: None,
                    ..report.space.constraints()
                },
            )
        });
        PyDesign {
            task,
            inner: d.clone(),
            drive,
            strut: report.actuator.map(|a| {
                (
                    a.options,
                    a.limits(&report.limits),
                    report.space.constraints(),
                )
            }),
        }
    }
}

#[pymethods]
impl PyDesign {
    /// The driving dyad's fixed pivot `A0` (its crank drives).
    #[getter]
    fn driving_pivot(&self) -> Xy {
        pt(self.inner.linkage.driving().center)
    }
    /// The driven dyad's fixed pivot `C0` (None for a slider-crank,
    /// whose guide needs no pivot).
    #[getter]
    fn driven_pivot(&self) -> Option<Xy> {
        self.inner.linkage.four_bar().map(|f| pt(f.driven.center))
    }
    /// `"pivots"`, `"parameters"` or `"burmester"`: what `coarse` and
    /// `refined` are.
    #[getter]
    fn found_by(&self) -> &'static str {
        point_state(&self.inner.coarse).0
    }
    #[getter]
    fn coarse<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        point_py(py, &self.inner.coarse)
    }
    #[getter]
    fn refined<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        point_py(py, &self.inner.refined)
    }
    /// With a motor: the drive of a linkage whose input swings (None
    /// without a motor, or when the input turns fully).
    #[getter]
    fn drive(&self) -> Option<PyDrive> {
        self.drive.clone()
    }
    /// With `input="actuator"`: the linear actuator placed with the
    /// linkage (None without).
    #[getter]
    fn actuator(&self) -> PyResult<Option<PyActuator>> {
        match (&self.inner.actuator, &self.strut) {
            (Some(a), Some((o, l, c))) => {
                PyActuator::found(a.clone(), self.task, o, l, c).map(Some)
            }
            _ => Ok(None),
        }
    }
    #[staticmethod]
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (task, driving, driven, score, size_ratio, ranked_by, kind, coarse, refined,
        evaluations, attached = (None, None)))]
    fn _from_state(
        task: PyTask,
        driving: (PyPoint, PyPoint),
        driven: (PyPoint, PyPoint),
        score: f64,
        size_ratio: f64,
        ranked_by: &str,
        kind: &str,
        coarse: ([f64; 4], f64),
        refined: [f64; 4],
        evaluations: usize,
        attached: (Option<Bound<'_, PyDrive>>, Option<Bound<'_, PyActuator>>),
    ) -> PyResult<Self> {
        let ((coarse, coarse_score), (drive, actuator)) = (coarse, attached);
        let slider = kind.starts_with("slider");
        let driven_kind = if slider {
            DrivenKind::Slider
        } else {
            DrivenKind::Revolute
        };
        let linkage = linkage_of(&task.inner, driving, driven, driven_kind)?;
        let drive = drive.map(|d| d.get().clone());
        let strut = actuator.as_ref().map(|a| a.get().parts());
        Ok(PyDesign {
            strut: strut.as_ref().map(|s| s.1.clone()),
            drive: drive.clone(),
            task: task.inner,
            inner: Design {
                linkage,
                score,
                size_ratio,
                ranked_by: ranked_by.parse::<RankBy>().py()?,
                coarse: point_of(kind, coarse)?,
                refined: point_of(kind, refined)?,
                coarse_score,
                evaluations,
                drive: drive.map(|d| d.inner),
                actuator: strut.map(|s| s.0),
            },
        })
    }
    fn __reduce__<'py>(&self, py: Python<'py>) -> Reduced<'py> {
        let d = &self.inner;
        let (kind, coarse) = point_state(&d.coarse);
        let (_, refined) = point_state(&d.refined);
        let args = (
            PyTask { inner: self.task },
            dyad_tuple(d.linkage.driving()),
            driven_tuple(&d.linkage),
            d.score,
            d.size_ratio,
            d.ranked_by.as_str(),
            kind,
            (coarse, d.coarse_score),
            refined,
            d.evaluations,
            (self.drive.clone(), self.actuator().ok().flatten()),
        );
        reduce_to::<PyDesign>(py, "_from_state", args)
    }
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PyDesign>()
            .is_ok_and(|o| o.get().task == self.task && o.get().inner == self.inner)
    }
    /// A picture for Jupyter: the linkage at the poses, or None without
    /// matplotlib.
    fn _repr_png_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        crate::display::repr_png(slf.as_any())
    }
    fn __repr__(&self) -> String {
        let l = &self.inner.linkage;
        let a0 = l.driving().center;
        let (what, driven) = match l {
            DesignedLinkage::FourBar(f) => (
                f.figures.grashof.to_string(),
                format!("C0=({:.6}, {:.6})", f.driven.center.x, f.driven.center.y),
            ),
            DesignedLinkage::SliderCrank(s) => (
                "slider-crank".to_owned(),
                format!(
                    "guide=({:.6}, {:.6}) along ({:.6}, {:.6})",
                    s.driven.circle.x, s.driven.circle.y, s.driven.guide.x, s.driven.guide.y
                ),
            ),
        };
        format!(
            "<Design {what} A0=({:.6}, {:.6}) {driven} min_transmission_deg={:.3} \
             size_ratio={:.3} score={:.6} by {}>",
            a0.x,
            a0.y,
            l.min_transmission().to_degrees(),
            self.inner.size_ratio,
            self.inner.score,
            self.inner.ranked_by.as_str()
        )
    }
}

getters!(PyDesign, inner {
    f64: score, coarse_score;
    str: ranked_by;
    usize: evaluations;
});

fn limit_of(name: &str) -> PyResult<Limit> {
    Limit::ALL
        .into_iter()
        .find(|l| l.as_str() == name)
        .ok_or_else(|| PyTypeError::new_err(format!("unknown limit {name:?}")))
}

/// A candidate that misses the limits by little (when nothing fits).
#[pyclass(frozen, eq, from_py_object, name = "NearMiss", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PyNearMiss {
    task: Task,
    inner: NearMiss,
}

#[pymethods]
impl PyNearMiss {
    #[getter]
    fn misses(&self) -> Vec<&'static str> {
        self.inner.misses.iter().map(|l| l.as_str()).collect()
    }
    #[staticmethod]
    #[pyo3(signature = (task, driving, driven, size_ratio, misses, shortfall, driven_kind = "revolute"))]
    fn _from_state(
        task: PyTask,
        driving: (PyPoint, PyPoint),
        driven: (PyPoint, PyPoint),
        size_ratio: f64,
        misses: Vec<String>,
        shortfall: f64,
        driven_kind: &str,
    ) -> PyResult<Self> {
        let kind = DrivenKind::from_name(driven_kind).py()?;
        Ok(PyNearMiss {
            task: task.inner,
            inner: NearMiss {
                linkage: linkage_of(&task.inner, driving, driven, kind)?,
                size_ratio,
                misses: misses
                    .iter()
                    .map(|m| limit_of(m))
                    .collect::<PyResult<_>>()?,
                shortfall,
            },
        })
    }
    fn __reduce__<'py>(&self, py: Python<'py>) -> Reduced<'py> {
        let m = &self.inner;
        let args = (
            PyTask { inner: self.task },
            dyad_tuple(m.linkage.driving()),
            driven_tuple(&m.linkage),
            m.size_ratio,
            self.misses(),
            m.shortfall,
            m.linkage.kind().as_str(),
        );
        reduce_to::<PyNearMiss>(py, "_from_state", args)
    }
    fn __repr__(&self) -> String {
        format!(
            "<NearMiss misses {} by {:.4} size_ratio={:.3}>",
            self.misses().join(", "),
            self.inner.shortfall,
            self.inner.size_ratio
        )
    }
}

getters!(PyNearMiss, inner {
    f64: shortfall;
});

/// What `burmester.design` found: a sequence of `Design`s, best first, and
/// what the search ran under.
#[pyclass(frozen, eq, sequence, name = "DesignReport", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PyDesignReport {
    task: Task,
    inner: DesignReport,
}

#[pymethods]
impl PyDesignReport {
    #[getter]
    fn task(&self) -> PyTask {
        PyTask { inner: self.task }
    }
    #[getter]
    fn designs(&self) -> Vec<PyDesign> {
        self.inner
            .designs
            .iter()
            .map(|d| PyDesign::of(self.task, &self.inner, d))
            .collect()
    }
    #[getter]
    fn near_misses(&self) -> Vec<PyNearMiss> {
        self.inner
            .near_misses
            .iter()
            .map(|m| PyNearMiss {
                task: self.task,
                inner: m.clone(),
            })
            .collect()
    }
    #[getter]
    fn rejections(&self) -> Vec<(&'static str, usize)> {
        self.inner
            .rejections
            .iter()
            .map(|(l, n)| (l.as_str(), *n))
            .collect()
    }
    #[getter]
    fn main_rejection(&self) -> Option<&'static str> {
        self.inner.main_rejection().map(|l| l.as_str())
    }
    #[getter]
    fn space(&self) -> PySpace {
        PySpace {
            inner: self.inner.space.clone(),
        }
    }
    #[getter]
    fn search_box(&self) -> Option<Box4> {
        self.inner
            .search_box
            .map(|v| (v.xmin, v.xmax, v.ymin, v.ymax))
    }
    /// With a motor: the candidates passed over for want of a drive.
    #[getter]
    fn undriven(&self) -> usize {
        self.inner.undriven
    }
    /// With a linear actuator: the candidates passed over for want of a
    /// clear, acceptable placement.
    #[getter]
    fn unplaced(&self) -> usize {
        self.inner.unplaced
    }
    /// Whether the designs were searched with a linear actuator
    /// (`input="actuator"`).
    #[getter]
    fn actuator(&self) -> bool {
        self.inner.actuator.is_some()
    }
    /// With a linear actuator: the largest size ratio of a design with its
    /// open actuator (`actuator_max_size_ratio`, else the limits'); None
    /// without an actuator.
    #[getter]
    fn actuator_max_size_ratio(&self) -> Option<f64> {
        let r = &self.inner;
        r.actuator.map(|a| a.limits(&r.limits).max_size_ratio)
    }
    /// Whether the designs were searched with a motor (`input="motor"`).
    #[getter]
    fn motor(&self) -> bool {
        self.inner.motor.is_some()
    }
    /// The motor's swing margin, degrees (None without a motor).
    #[getter]
    fn swing_margin_deg(&self) -> Option<f64> {
        self.inner.motor.map(|m| m.swing_margin.to_degrees())
    }
    /// The motor's largest time ratio (None without a motor).
    #[getter]
    fn max_time_ratio(&self) -> Option<f64> {
        self.inner.motor.map(|m| m.max_time_ratio)
    }
    fn __len__(&self) -> usize {
        self.inner.designs.len()
    }
    fn __iter__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyIterator>> {
        pyo3::types::PyList::new(py, self.designs())?.try_iter()
    }
    fn __getitem__(&self, index: isize) -> PyResult<PyDesign> {
        let n = self.inner.designs.len() as isize;
        let k = if index < 0 { index + n } else { index };
        if !(0..n).contains(&k) {
            return Err(PyIndexError::new_err(format!(
                "design index {index} out of range for {n} designs"
            )));
        }
        Ok(PyDesign::of(
            self.task,
            &self.inner,
            &self.inner.designs[k as usize],
        ))
    }
    #[staticmethod]
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (task, designs, limits, space, rank_by, min_separation, search_box, counts,
        rejections, near_misses, inputs = (None, None), passed = Passed::Counts(0, 0)))]
    fn _from_state(
        task: PyTask,
        designs: Vec<PyDesign>,
        limits: PyDesignLimits,
        space: PySpace,
        rank_by: &str,
        min_separation: f64,
        search_box: Option<Box4>,
        counts: (usize, usize, usize, usize),
        rejections: Vec<(String, usize)>,
        near_misses: Vec<PyNearMiss>,
        inputs: (Option<(f64, f64)>, Option<StrutState>),
        passed: Passed,
    ) -> PyResult<Self> {
        let (motor, actuator) = inputs;
        let (undriven, unplaced, strut) = match passed {
            Passed::Counts(u, p) => (u, p, None),
            Passed::WithStrut(u, p, s) => (u, p, s),
        };
        // A pickle from before the strut's diameter and gap: 0, 0.
        let (actuator_width, min_gap) = strut.unwrap_or((0.0, 0.0));
        let actuator = actuator
            .map(|state| {
                let (link, ratio, travel, point, samples, max_size_ratio) = match state {
                    StrutState::WithSize(l, r, t, p, n, m) => (l, r, t, p, n, m),
                    StrutState::Before(l, r, t, p, n) => (l, r, t, p, n, None),
                };
                Ok::<_, PyErr>(ActuatorSearch {
                    options: ActuatorOptions {
                        link: link.parse::<ActuatorLink>().py()?,
                        max_stroke_ratio: ratio,
                        travel_samples: travel,
                        actuator_width,
                        min_gap,
                    },
                    point: point.map(|p| p.0),
                    samples,
                    max_size_ratio,
                })
            })
            .transpose()?;
        Ok(PyDesignReport {
            task: task.inner,
            inner: DesignReport {
                designs: designs.into_iter().map(|d| d.inner).collect(),
                limits: limits.inner,
                space: space.inner,
                rank_by: rank_by.parse::<RankBy>().py()?,
                min_separation,
                search_box: search_box.map(|(xmin, xmax, ymin, ymax)| Viewport {
                    xmin,
                    xmax,
                    ymin,
                    ymax,
                }),
                coarse_candidates: counts.0,
                coarse_acceptable: counts.1,
                evaluations: counts.2,
                rejections: rejections
                    .iter()
                    .map(|(l, n)| Ok((limit_of(l)?, *n)))
                    .collect::<PyResult<_>>()?,
                census: counts.3,
                near_misses: near_misses.into_iter().map(|m| m.inner).collect(),
                motor: motor.map(|(swing_margin, max_time_ratio)| DriveOptions {
                    swing_margin,
                    max_time_ratio,
                }),
                undriven,
                actuator,
                unplaced,
            },
        })
    }
    fn __reduce__<'py>(&self, py: Python<'py>) -> Reduced<'py> {
        let r = &self.inner;
        let args = (
            self.task(),
            self.designs(),
            self.limits(),
            self.space(),
            self.rank_by(),
            r.min_separation,
            self.search_box(),
            (
                r.coarse_candidates,
                r.coarse_acceptable,
                r.evaluations,
                r.census,
            ),
            self.rejections(),
            self.near_misses(),
            (
                r.motor.map(|m| (m.swing_margin, m.max_time_ratio)),
                r.actuator.map(|a| {
                    let o = a.options;
                    (
                        o.link.as_str(),
                        o.max_stroke_ratio,
                        o.travel_samples,
                        a.point.map(pt),
                        a.samples,
                        a.max_size_ratio,
                    )
                }),
            ),
            (
                r.undriven,
                r.unplaced,
                r.actuator
                    .map(|a| (a.options.actuator_width, a.options.min_gap)),
            ),
        );
        reduce_to::<PyDesignReport>(py, "_from_state", args)
    }
    fn __repr__(&self) -> String {
        match self.inner.designs.first() {
            Some(d) => format!(
                "<DesignReport {} designs by {}, best score {:.6}>",
                self.inner.designs.len(),
                self.inner.rank_by.as_str(),
                d.score
            ),
            None => format!(
                "<DesignReport no design; {} near misses, most rejected by {}>",
                self.inner.near_misses.len(),
                self.main_rejection().unwrap_or("none")
            ),
        }
    }
}

getters!(PyDesignReport, inner {
    PyDesignLimits = PyDesignLimits::from: limits;
    usize: census, coarse_candidates, coarse_acceptable, evaluations;
    str: rank_by;
    f64: min_separation;
});

/// The options of `burmester.design` from its keywords.
#[allow(clippy::too_many_arguments)]
fn options(
    space: Option<PySpace>,
    limits: Option<PyDesignLimits>,
    rank_by: &str,
    top: Count,
    min_separation: Option<Real>,
    coarse_driven: Count,
    coarse_driving: Count,
    coarse_pairs: Count,
    starts: Count,
    max_iterations: Count,
    input: Option<&str>,
    swing_margin_deg: Real,
    max_time_ratio: Option<Real>,
    actuator_link: &str,
    actuator_point: Option<PyPoint>,
    max_stroke_ratio: Real,
    actuator_samples: Count,
    actuator_width: Real,
    min_gap: Real,
    actuator_max_size_ratio: Option<Real>,
    driven: &str,
) -> PyResult<DesignOptions> {
    let mut limits = limits.map(|l| l.inner).unwrap_or_default();
    let strut = StrutArgs {
        link: actuator_link,
        point: actuator_point.map(|p| p.0),
        max_stroke_ratio: max_stroke_ratio.0,
        samples: actuator_samples.0,
        actuator_width: actuator_width.0,
        min_gap: min_gap.0,
        max_size_ratio: actuator_max_size_ratio.map(|r| r.0),
    };
    let actuator = strut.search(&mut limits, input)?;
    let motor = motor_of(
        &mut limits,
        input.filter(|_| actuator.is_none()),
        swing_margin_deg,
        max_time_ratio,
    )?;
    Ok(DesignOptions {
        limits,
        motor,
        actuator,
        space: space.map(|s| s.inner).unwrap_or_default(),
        rank_by: rank_by.parse::<RankBy>().py()?,
        top: top.0,
        min_separation: min_separation.map(|r| r.0),
        coarse_driven: coarse_driven.0,
        coarse_driving: coarse_driving.0,
        coarse_pairs: coarse_pairs.0,
        starts: starts.0,
        max_iterations: max_iterations.0,
        driven: DrivenKind::from_name(driven).py()?,
    })
}

/// A report's counts of candidates passed over (undriven, unplaced) as
/// pickled, with the actuator's diameter and least gap where it has them (a
/// pickle from before they were options reads as 0, 0).
#[derive(FromPyObject)]
enum Passed {
    WithStrut(usize, usize, Option<(f64, f64)>),
    Counts(usize, usize),
}

/// A report's actuator search as plain data (for pickling): the link, the
/// stroke ratio limit, the travel samples, the point, the ground samples
/// and the size ratio limit with the open actuator (a pickle from before it
/// was an option has none: the limits').
#[derive(FromPyObject)]
enum StrutState {
    WithSize(String, f64, usize, Option<PyPoint>, usize, Option<f64>),
    Before(String, f64, usize, Option<PyPoint>, usize),
}

/// The actuator's keywords of `burmester.design`.
struct StrutArgs<'a> {
    link: &'a str,
    point: Option<Point2<f64>>,
    max_stroke_ratio: f64,
    samples: usize,
    /// The strut's diameter and the least gap.
    actuator_width: f64,
    min_gap: f64,
    /// The size ratio limit with the open actuator (None: the limits').
    max_size_ratio: Option<f64>,
}

impl StrutArgs<'_> {
    /// With `input="actuator"`: the actuator's search (any input); its
    /// keywords refused otherwise.
    fn search(
        &self,
        limits: &mut DesignLimits,
        input: Option<&str>,
    ) -> PyResult<Option<ActuatorSearch>> {
        let wanted = input.is_some_and(|i| i.eq_ignore_ascii_case("actuator"));
        if !wanted {
            let set = self.link != "coupler"
                || self.point.is_some()
                || self.max_stroke_ratio != 1.8
                || self.samples != 64
                || self.actuator_width != 0.0
                || self.min_gap != 0.0
                || self.max_size_ratio.is_some();
            if set {
                return Err(crate::errors::invalid(
                    "needs_actuator",
                    format!(
                        "actuator_link, actuator_point, max_stroke_ratio, actuator_samples, \
                         actuator_width, min_gap and actuator_max_size_ratio set the linear \
                         actuator; pass input=\"actuator\" with them (got input={:?})",
                        input.unwrap_or("None")
                    ),
                ));
            }
            return Ok(None);
        }
        limits.input = InputRequirement::Any;
        let search = ActuatorSearch {
            options: ActuatorOptions {
                link: self.link.parse::<ActuatorLink>().py()?,
                max_stroke_ratio: self.max_stroke_ratio,
                actuator_width: self.actuator_width,
                min_gap: self.min_gap,
                ..ActuatorOptions::default()
            },
            point: self.point,
            samples: self.samples,
            max_size_ratio: self.max_size_ratio,
        };
        search.validate().py()?;
        Ok(Some(search))
    }
}

/// The motor's options of `input` (`"motor"`: any input, drives attached)
/// and `limits.input` as `input` asks (`None`: the limits' own).
fn motor_of(
    limits: &mut DesignLimits,
    input: Option<&str>,
    swing_margin_deg: Real,
    max_time_ratio: Option<Real>,
) -> PyResult<Option<DriveOptions>> {
    let Some(input) = input else {
        return no_motor(swing_margin_deg, max_time_ratio, "None").map(|_| None);
    };
    if input.eq_ignore_ascii_case("motor") {
        limits.input = InputRequirement::Any;
        let q = max_time_ratio.map_or(f64::INFINITY, |r| r.0);
        return DriveOptions::from_degrees(swing_margin_deg.0, q)
            .py()
            .map(Some);
    }
    limits.input = input.parse::<InputRequirement>().map_err(|_| {
        crate::errors::to_py(
            InvalidInput::UnknownName {
                what: "input",
                expected: "\"any\", \"crank\", \"rocker\", \"motor\" or \"actuator\" (or None: the \
                           limits' own)",
                found: input.to_owned(),
            }
            .into(),
        )
    })?;
    no_motor(swing_margin_deg, max_time_ratio, input).map(|_| None)
}

/// Refuses the motor's options without a motor.
fn no_motor(swing_margin_deg: Real, max_time_ratio: Option<Real>, input: &str) -> PyResult<()> {
    let q = max_time_ratio.map_or(f64::INFINITY, |r| r.0);
    if swing_margin_deg.0 != 0.0 || q != f64::INFINITY {
        return Err(crate::errors::invalid(
            "needs_motor",
            format!(
                "swing_margin_deg and max_time_ratio set the motor's drive; pass input=\"motor\" \
                 with them (got input={input:?}, swing_margin_deg={}, max_time_ratio={q})",
                swing_margin_deg.0
            ),
        ));
    }
    Ok(())
}

/// Calls `$callback! { $header ... }` with the keywords of
/// `burmester.design` after its positional arguments, each as
/// `name: [type] = [default],`, in [`options`]' order: the one list of
/// their types and defaults.
macro_rules! design_keywords {
    ($callback:ident! $header:tt) => {
        $callback! { $header
            space: [Option<PySpace>] = [None],
            limits: [Option<PyDesignLimits>] = [None],
            rank_by: [&str] = ["balanced"],
            top: [Count] = [Count(5)],
            min_separation: [Option<Real>] = [None],
            coarse_driven: [Count] = [Count(12)],
            coarse_driving: [Count] = [Count(48)],
            coarse_pairs: [Count] = [Count(120)],
            starts: [Count] = [Count(48)],
            max_iterations: [Count] = [Count(3000)],
            input: [Option<&str>] = [None],
            swing_margin_deg: [Real] = [Real(0.0)],
            max_time_ratio: [Option<Real>] = [None],
            actuator_link: [&str] = ["coupler"],
            actuator_point: [Option<PyPoint>] = [None],
            max_stroke_ratio: [Real] = [Real(1.8)],
            actuator_samples: [Count] = [Count(64)],
            actuator_width: [Real] = [Real(0.0)],
            min_gap: [Real] = [Real(0.0)],
            actuator_max_size_ratio: [Option<Real>] = [None],
            driven: [&str] = ["revolute"],
        }
    };
}

/// Defines a native design function: the keywords of `burmester.design`
/// (after `task` and the function's own positional arguments) parsed into
/// `opts`, then `$body`.
macro_rules! design_fn {
    ($($header:tt)*) => {
        design_keywords!(design_fn_with! { $($header)* });
    };
}

/// [`design_fn`] with the keywords.
macro_rules! design_fn_with {
    ({ $(#[$m:meta])* fn $name:ident<$lt:lifetime>($py:ident, $task:ident $(, $arg:ident: $ty:ty)*;
        $opts:ident, $progress:ident) -> $ret:ty $body:block }
     $($k:ident: [$($t:tt)*] = [$($d:tt)*],)*) => {
        $(#[$m])*
        #[pyfunction]
        #[pyo3(signature = ($task $(, $arg)*, *, $($k = $($d)*,)* progress = None))]
        #[allow(clippy::too_many_arguments)]
        pub(crate) fn $name<$lt>(
            $py: Python<$lt>,
            $task: &PyTask,
            $($arg: $ty,)*
            $($k: $($t)*,)*
            $progress: Option<&Bound<$lt, PyAny>>,
        ) -> PyResult<$ret> {
            let $opts = options($($k,)*)?;
            $body
        }
    };
}

design_fn! {
    /// The whole search in this process (the GIL released, progress in
    /// thousandths, Ctrl-C).
    fn _design<'py>(py, task; opts, progress) -> PyDesignReport {
        let t = task.inner;
        let report = run(py, true, progress, None, |c| t.design(&opts, c))?;
        Ok(PyDesignReport { task: t, inner: report })
    }
}

design_fn! {
    /// The three-pose coarse pass: the driven and driving grids and the
    /// keywords of `_atlas_tile`.
    fn _design_plan<'py>(py, task; opts, progress) -> Bound<'py, PyDict> {
        let _ = progress;
        let plan = task.inner.design_plan(&opts).py()?;
        let d = PyDict::new(py);
        d.set_item("driven", PyGrid { inner: plan.driven })?;
        d.set_item("driving", PyGrid { inner: plan.driving })?;
        let kw = PyDict::new(py);
        kw.set_item("limits", PyDesignLimits { inner: opts.limits })?;
        let c = &plan.constraints;
        kw.set_item("base_plate", c.base_plate.as_deref().map(xys))?;
        kw.set_item("obstacles", c.obstacles.iter().map(|o| xys(o)).collect::<Vec<_>>())?;
        kw.set_item("link_width", c.link_width)?;
        kw.set_item("travel_samples", c.travel_samples)?;
        kw.set_item("envelope", c.envelope.as_deref().map(xys))?;
        kw.set_item("rank_by", opts.rank_by.as_str())?;
        d.set_item("atlas", kw)?;
        Ok(d)
    }
}

/// A column of `arrays` as f64 values.
fn column(arrays: &Bound<'_, PyDict>, name: &str) -> PyResult<Vec<f64>> {
    let item = arrays
        .get_item(name)?
        .ok_or_else(|| PyTypeError::new_err(format!("missing atlas array {name}")))?;
    let a = item
        .call_method1("astype", ("float64",))?
        .cast_into::<PyArrayDyn<f64>>()
        .map_err(PyErr::from)?;
    let ro = a.readonly();
    Ok(ro.as_array().iter().copied().collect())
}

/// Atlas cells from the arrays `_atlas_tile` returns (concatenated).
fn cells_of(arrays: &Bound<'_, PyDict>) -> PyResult<Vec<AtlasCell>> {
    let valid = column(arrays, "valid")?;
    let count = column(arrays, "count")?;
    let branch_free = column(arrays, "branch_free")?;
    let mu = column(arrays, "best_transmission_rad")?;
    let ratio = column(arrays, "best_link_ratio")?;
    let margin = column(arrays, "best_margin")?;
    let size = column(arrays, "best_size_ratio")?;
    let score = column(arrays, "best_score")?;
    let xy = column(arrays, "best_driving")?;
    let index = column(arrays, "best_index")?;
    let n = valid.len();
    for (name, len, want) in [
        ("count", count.len(), n),
        ("branch_free", branch_free.len(), n),
        ("best_score", score.len(), n),
        ("best_driving", xy.len(), 2 * n),
        ("best_index", index.len(), 2 * n),
    ] {
        if len != want {
            return Err(PyTypeError::new_err(format!(
                "atlas array {name} has {len} values, expected {want}"
            )));
        }
    }
    Ok((0..n)
        .map(|k| AtlasCell {
            valid: valid[k] != 0.0,
            count: count[k] as u64,
            branch_free: branch_free[k] as u64,
            best: (!score[k].is_nan()).then(|| AtlasBest {
                driving: Point2::new(xy[2 * k], xy[2 * k + 1]),
                index: (index[2 * k] as usize, index[2 * k + 1] as usize),
                min_transmission_rad: mu[k] as f32,
                link_ratio: ratio[k] as f32,
                margin: margin[k],
                size_ratio: size[k] as f32,
                score: score[k],
            }),
        })
        .collect())
}

design_fn! {
    /// The refinement of a three-pose coarse pass computed elsewhere:
    /// `arrays` are `_atlas_tile`'s arrays over the plan's driven grid.
    fn _design_from_atlas<'py>(py, task, arrays: &Bound<'py, PyDict>; opts, progress) -> PyDesignReport {
        let cells = cells_of(arrays)?;
        let t = task.inner;
        let report = run(py, true, progress, None, |c| t.design_from_atlas(&opts, &cells, c))?;
        Ok(PyDesignReport { task: t, inner: report })
    }
}
