//! `burmester.Cubic` and the records of the four-pose methods of
//! `burmester.Task` (the core's `geom::Cubic` and `synthesis::four`).
//!
//! The `Task` methods themselves are in `synthesis` (one `#[pymethods]`
//! block per class); they take the curves and points from the core's
//! `Task`, which keeps them. Here are the conversions of the core's records
//! to Python values.

use burmester::geom::Cubic;
use burmester::synthesis::{CoincidencePoint, CurveDyad, FilemonArcs};
use burmester::{InvalidInput, Point2, Viewport};
use numpy::PyArray2;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::conv::{PyPoint, Real, pt};
use crate::errors::{IntoPy, to_py};
use crate::getters::getters;
use crate::pickle::{Reduced, reduce_to};

type Xy = (f64, f64);

/// The names of an optional assembly mode, checked (for `_from_fields`).
fn check_name(what: &str, value: Option<&str>, allowed: [&str; 2]) -> PyResult<()> {
    match value {
        Some(v) if !allowed.contains(&v) => Err(crate::errors::invalid(
            "unknown_name",
            format!("unknown {what} {v:?}; expected one of {allowed:?} or None"),
        )),
        _ => Ok(()),
    }
}

/// The error of a pickled record that no record holds.
fn bad_state(what: &str, detail: String) -> PyErr {
    crate::errors::invalid(
        "inconsistent_state",
        format!(
            "unpickling a {what}: {detail}; the pickle was damaged or not made by burmester: \
             compute it again"
        ),
    )
}

/// Refuses the fields of a pickled `CurveDyad` that no dyad has: a point
/// or a rotation that is not finite, a rotation outside `(-pi, pi]`, an
/// order that is not the poses `1` to `4` from pose 1, or a direction that
/// is not the order's.
fn check_curve_dyad_state(
    center: Point2<f64>,
    circle: Point2<f64>,
    beta2: f64,
    order: &str,
    direction: Option<&str>,
) -> PyResult<()> {
    let finite = [center.x, center.y, circle.x, circle.y, beta2]
        .iter()
        .all(|v| v.is_finite());
    if !finite {
        return Err(bad_state(
            "CurveDyad",
            "a point or beta2 that is not finite".into(),
        ));
    }
    if !(beta2 > -core::f64::consts::PI && beta2 <= core::f64::consts::PI) {
        return Err(bad_state(
            "CurveDyad",
            format!("beta2 = {beta2} outside (-pi, pi]"),
        ));
    }
    let seq: Option<Vec<usize>> = order.split('-').map(|k| k.parse().ok()).collect();
    let n = 4;
    let valid = seq.as_ref().is_some_and(|seq| {
        let mut sorted = seq.clone();
        sorted.sort_unstable();
        seq.len() == n && seq[0] == 1 && sorted == (1..=n).collect::<Vec<_>>()
    });
    let Some(seq) = seq.filter(|_| valid) else {
        return Err(bad_state(
            "CurveDyad",
            format!("the order {order:?} (the poses 1 to 4, pose 1 first, as \"1-3-2-4\")"),
        ));
    };
    let want = if seq.iter().enumerate().all(|(i, &k)| k == i + 1) {
        Some("counterclockwise")
    } else if seq[1..].iter().enumerate().all(|(i, &k)| k == n - i) {
        Some("clockwise")
    } else {
        None
    };
    if direction != want {
        return Err(bad_state(
            "CurveDyad",
            format!(
                "the direction {direction:?} with the order {order:?} (its direction is {want:?})"
            ),
        ));
    }
    Ok(())
}

/// A dyad of four poses with its place on the curves: its crank rotation
/// from pose 1 to pose 2, its solution branch and its crank order.
#[pyclass(frozen, eq, from_py_object, name = "CurveDyad", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PyCurveDyad {
    pub(crate) center: Xy,
    pub(crate) circle: Xy,
    beta2: f64,
    branch: Option<String>,
    order: String,
    direction: Option<String>,
}

impl From<&CurveDyad> for PyCurveDyad {
    fn from(d: &CurveDyad) -> Self {
        PyCurveDyad {
            center: pt(d.center),
            circle: pt(d.circle),
            beta2: d.beta2,
            branch: d.branch.map(|b| b.as_str().to_owned()),
            order: d.order.to_string(),
            direction: d.order.direction().map(|t| t.as_str().to_owned()),
        }
    }
}

#[pymethods]
impl PyCurveDyad {
    /// Rebuilds a record from its fields (for pickling).
    #[staticmethod]
    fn _from_fields(
        center: PyPoint,
        circle: PyPoint,
        beta2: Real,
        branch: Option<String>,
        order: String,
        direction: Option<String>,
    ) -> PyResult<Self> {
        check_name("assembly mode", branch.as_deref(), ["open", "crossed"])?;
        check_name(
            "direction",
            direction.as_deref(),
            ["counterclockwise", "clockwise"],
        )?;
        check_curve_dyad_state(center.0, circle.0, beta2.0, &order, direction.as_deref())?;
        Ok(PyCurveDyad {
            center: pt(center.0),
            circle: pt(circle.0),
            beta2: beta2.0,
            branch,
            order,
            direction,
        })
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> Reduced<'py> {
        let args = (
            self.center,
            self.circle,
            self.beta2,
            self.branch.clone(),
            self.order.clone(),
            self.direction.clone(),
        );
        reduce_to::<PyCurveDyad>(py, "_from_fields", args)
    }

    /// The center point (fixed pivot), on the center-point curve.
    #[getter]
    fn center(&self) -> Xy {
        self.center
    }
    /// The circle point (moving pivot at pose 1), on the circle-point curve.
    #[getter]
    fn circle(&self) -> Xy {
        self.circle
    }
    /// `(center, circle)`.
    #[getter]
    fn dyad(&self) -> (Xy, Xy) {
        (self.center, self.circle)
    }
    #[getter]
    fn branch(&self) -> Option<&str> {
        self.branch.as_deref()
    }
    #[getter]
    fn order(&self) -> &str {
        &self.order
    }
    #[getter]
    fn direction(&self) -> Option<&str> {
        self.direction.as_deref()
    }

    fn __repr__(&self) -> String {
        let (c, z) = (self.center, self.circle);
        format!(
            "<CurveDyad center=({:?}, {:?}) circle=({:?}, {:?}) beta2={:?} branch={} order={}>",
            c.0,
            c.1,
            z.0,
            z.1,
            self.beta2,
            self.branch.as_deref().unwrap_or("None"),
            self.order
        )
    }
}

getters!(PyCurveDyad {
    f64: beta2;
});

/// A point `Q_jk` of the center-point curve of four poses where the crank
/// positions at poses `j` and `k` coincide, with its circle point.
#[pyclass(frozen, eq, name = "CoincidencePoint", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PyCoincidencePoint {
    pair: (usize, usize),
    center: Option<Xy>,
    circle: Option<Xy>,
}

impl From<&CoincidencePoint> for PyCoincidencePoint {
    fn from(q: &CoincidencePoint) -> Self {
        PyCoincidencePoint {
            pair: (q.poses[0], q.poses[1]),
            center: q.center.map(pt),
            circle: q.circle.map(pt),
        }
    }
}

#[pymethods]
impl PyCoincidencePoint {
    /// Rebuilds a record from its fields (for pickling).
    #[staticmethod]
    fn _from_fields(
        pair: (usize, usize),
        center: Option<PyPoint>,
        circle: Option<PyPoint>,
    ) -> PyResult<Self> {
        // Q_jk of four poses: 1 <= j < k <= 4, finite points (None: at
        // infinity).
        if !(1 <= pair.0 && pair.0 < pair.1 && pair.1 <= 4) {
            return Err(bad_state(
                "CoincidencePoint",
                format!("the pair {pair:?} (1 <= j < k <= 4)"),
            ));
        }
        let finite = |p: &Option<PyPoint>| {
            p.as_ref()
                .is_none_or(|p| p.0.x.is_finite() && p.0.y.is_finite())
        };
        if !(finite(&center) && finite(&circle)) {
            return Err(bad_state(
                "CoincidencePoint",
                "a point that is not finite".into(),
            ));
        }
        Ok(PyCoincidencePoint {
            pair,
            center: center.map(|p| pt(p.0)),
            circle: circle.map(|p| pt(p.0)),
        })
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> Reduced<'py> {
        let args = (self.pair, self.center, self.circle);
        reduce_to::<PyCoincidencePoint>(py, "_from_fields", args)
    }

    /// `(j, k)`, 1-based.
    #[getter]
    fn pair(&self) -> (usize, usize) {
        self.pair
    }

    fn __repr__(&self) -> String {
        let show = |p: Option<Xy>| p.map_or("None".to_owned(), |(x, y)| format!("({x:?}, {y:?})"));
        format!(
            "<CoincidencePoint Q{}{} center={} circle={}>",
            self.pair.0,
            self.pair.1,
            show(self.center),
            show(self.circle)
        )
    }
}

getters!(PyCoincidencePoint {
    Option<Xy>: center, circle;
});

/// A polyline as an `(n, 2)` array.
/// NumPy allocates it (a failed allocation is a `MemoryError`).
pub(crate) fn polyline<'py>(
    py: Python<'py>,
    l: &[Point2<f64>],
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let a = crate::conv::empty::<f64>(py, &[l.len(), 2])?;
    {
        let mut w = crate::conv::writer(&a)?;
        for (o, p) in crate::conv::slice_mut(&mut w).chunks_exact_mut(2).zip(l) {
            o.copy_from_slice(&[p.x, p.y]);
        }
    }
    a.cast_into::<PyArray2<f64>>().map_err(PyErr::from)
}

/// A viewport from its four numbers.
pub(crate) fn viewport(xmin: Real, xmax: Real, ymin: Real, ymax: Real) -> PyResult<Viewport> {
    Viewport::new(xmin.0, xmax.0, ymin.0, ymax.0).py()
}

/// `polylines(xmin, xmax, ymin, ymax, tolerance=None)` of a curve class
/// `$cls` (`Cubic`, `Conic`) wrapping a curve `inner`: `$lines(&inner,
/// &viewport, tolerance)` computed without the GIL, as `(n, 2)` arrays.
macro_rules! polylines_method {
    ($cls:ident, $lines:expr) => {
        #[pymethods]
        impl $cls {
            #[pyo3(signature = (xmin, xmax, ymin, ymax, tolerance = None))]
            fn polylines<'py>(
                &self,
                py: Python<'py>,
                xmin: $crate::conv::Real,
                xmax: $crate::conv::Real,
                ymin: $crate::conv::Real,
                ymax: $crate::conv::Real,
                tolerance: Option<$crate::conv::Real>,
            ) -> PyResult<Vec<Bound<'py, numpy::PyArray2<f64>>>> {
                use $crate::errors::IntoPy;
                let vp = $crate::curves::viewport(xmin, xmax, ymin, ymax)?;
                let (c, tolerance, lines_of) = (self.inner, tolerance.map(|t| t.0), $lines);
                let lines = py.detach(|| lines_of(&c, &vp, tolerance)).py()?;
                lines
                    .iter()
                    .map(|l| $crate::curves::polyline(py, l))
                    .collect()
            }
        }
    };
}
pub(crate) use polylines_method;

/// The branch-free arcs of a four-pose construction (any driven dyad kind)
/// inside `vp`, of the circle-point curve where `circle` (else the
/// center-point curve), as polylines; computed without the GIL, Ctrl-C
/// watched (a degenerate task traces a million vertices: seconds).
pub(crate) fn free_arcs<'py>(
    py: Python<'py>,
    arcs: &FilemonArcs,
    vp: &Viewport,
    circle: bool,
) -> PyResult<Vec<Bound<'py, PyArray2<f64>>>> {
    let lines = crate::run::run_in(py, true, None, None, "traced vertices", |control| {
        arcs.free_arcs_with(vp, circle, control)
    })?;
    lines.iter().map(|l| polyline(py, l)).collect()
}

/// Whether `plane` names the circle-point plane (`"circle"`) rather than
/// the center-point plane (`"center"`).
pub(crate) fn circle_plane(plane: &str) -> PyResult<bool> {
    match plane {
        "center" => Ok(false),
        "circle" => Ok(true),
        _ => Err(to_py(
            InvalidInput::UnknownName {
                what: "plane",
                expected: "\"center\" or \"circle\"",
                found: plane.to_owned(),
            }
            .into(),
        )),
    }
}

/// Rejects a point with a NaN or infinite coordinate (typed like the
/// core's `NotFinite`).
fn finite_point(p: PyPoint, what: [&'static str; 2]) -> PyResult<Point2<f64>> {
    for (name, value) in what.into_iter().zip([p.0.x, p.0.y]) {
        if !value.is_finite() {
            return Err(to_py(InvalidInput::NotFinite { name, value }.into()));
        }
    }
    Ok(p.0)
}

/// A plane cubic curve `f(x, y) = 0`: the center-point and circle-point
/// curves of four poses.
#[pyclass(frozen, eq, name = "Cubic", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PyCubic {
    pub(crate) inner: Cubic,
}

#[pymethods]
impl PyCubic {
    /// A cubic from its ten coefficients
    /// `c00, c10, c01, c20, c11, c02, c30, c21, c12, c03`.
    #[new]
    fn new(coefficients: Vec<Real>) -> PyResult<Self> {
        let c: Vec<f64> = coefficients.into_iter().map(|r| r.0).collect();
        let Ok(c) = <[f64; 10]>::try_from(c.as_slice()) else {
            return Err(PyTypeError::new_err(format!(
                "a cubic takes its ten coefficients c00, c10, c01, c20, c11, c02, c30, c21, c12, \
                 c03 as one sequence, got {} numbers",
                c.len()
            )));
        };
        Cubic::new(c).map(|inner| PyCubic { inner }).py()
    }

    /// Rebuilds a cubic from its exact stored form (for pickling).
    #[staticmethod]
    fn _from_parts(coefficients: [f64; 10], origin: PyPoint, scale: Real) -> PyResult<Self> {
        Cubic::from_local_coefficients(coefficients, origin.0, scale.0)
            .map(|inner| PyCubic { inner })
            .py()
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> Reduced<'py> {
        let (c, o, s) = self.inner.local_coefficients();
        reduce_to::<PyCubic>(py, "_from_parts", (c.to_vec(), pt(o), s))
    }

    /// The ten coefficients in the fixed frame (defined up to a positive
    /// factor), in the order of the constructor.
    #[getter]
    fn coefficients<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(py, self.inner.coefficients())
    }

    #[getter]
    fn asymptotic_directions(&self) -> Vec<Xy> {
        self.inner
            .asymptotic_directions()
            .into_iter()
            .map(|d| (d.x, d.y))
            .collect()
    }

    fn evaluate(&self, point: PyPoint) -> PyResult<f64> {
        Ok(self
            .inner
            .evaluate(finite_point(point, ["point x", "point y"])?))
    }

    fn __call__(&self, point: PyPoint) -> PyResult<f64> {
        self.evaluate(point)
    }

    /// A picture for Jupyter: PNG bytes drawn by `burmester._display`, or
    /// None without matplotlib.
    fn _repr_png_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        crate::display::repr_png(slf.as_any())
    }

    fn gradient(&self, point: PyPoint) -> PyResult<Xy> {
        let g = self
            .inner
            .gradient(finite_point(point, ["point x", "point y"])?);
        Ok((g.x, g.y))
    }

    fn distance(&self, point: PyPoint) -> PyResult<f64> {
        Ok(self
            .inner
            .distance_estimate(finite_point(point, ["point x", "point y"])?))
    }

    fn intersect_line(&self, point: PyPoint, direction: PyPoint) -> PyResult<Vec<Xy>> {
        let p = finite_point(point, ["line point x", "line point y"])?;
        let d = finite_point(direction, ["line direction x", "line direction y"])?;
        if d.x == 0.0 && d.y == 0.0 {
            return Err(to_py(
                InvalidInput::ZeroDirection {
                    name: "the line's direction",
                    x: d.x,
                    y: d.y,
                }
                .into(),
            ));
        }
        let line = burmester::Line {
            point: p,
            direction: d.coords,
        };
        Ok(self
            .inner
            .intersect_line(&line)
            .into_iter()
            .map(pt)
            .collect())
    }

    fn __repr__(&self) -> String {
        let c: Vec<String> = self
            .inner
            .coefficients()
            .iter()
            .map(|v| format!("{v:?}"))
            .collect();
        format!("Cubic([{}])", c.join(", "))
    }
}

/// `Cubic.polylines`'s `tolerance` (by default the core's), checked: from
/// 1e-9 to 1 times the viewport's diagonal, the range `Conic::polylines`
/// takes.
fn cubic_tolerance(vp: &Viewport, tolerance: Option<f64>) -> burmester::Result<Option<f64>> {
    let diag = vp.diagonal();
    match tolerance {
        Some(value) if !(1e-9 * diag..=diag).contains(&value) => Err(InvalidInput::OutsideRange {
            name: "tolerance",
            value,
            min: 1e-9 * diag,
            max: diag,
            unit: " (plane units: 1e-9 to 1 times the viewport's diagonal)",
        }
        .into()),
        t => Ok(t),
    }
}

polylines_method!(PyCubic, |c: &Cubic, vp, tolerance| {
    cubic_tolerance(vp, tolerance)
        .and_then(|t| c.trace(vp, t))
        .map(|t| t.polylines())
});

getters!(PyCubic, inner {
    fn usize: degree;
    fn bool: is_circular;
});
