//! `burmester.FourBar` and `burmester.Configuration`.

use burmester::{AssemblyMode, Configuration, FourBar, InputRange, Point2};
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::conv::{FloatArray, PyPoint, Real, pt, to_numpy};
use crate::errors::IntoPy;

/// Parses `"open"` / `"crossed"`.
pub(crate) fn mode(s: &str) -> PyResult<AssemblyMode> {
    s.parse::<AssemblyMode>().py()
}

/// A planar four-bar linkage.
#[pyclass(frozen, name = "FourBar", module = "burmester")]
#[derive(Clone)]
pub struct PyFourBar {
    pub(crate) inner: FourBar,
}

impl From<FourBar> for PyFourBar {
    fn from(inner: FourBar) -> Self {
        PyFourBar { inner }
    }
}

type Arrays<'py> = (
    Bound<'py, PyArrayDyn<f64>>,
    Bound<'py, PyArrayDyn<f64>>,
    Bound<'py, PyArrayDyn<bool>>,
);

#[pymethods]
impl PyFourBar {
    #[new]
    #[pyo3(signature = (ground, crank, coupler, rocker, *, origin = PyPoint(Point2::origin()), ground_angle = Real(0.0)),
        text_signature = "(ground, crank, coupler, rocker, *, origin=(0.0, 0.0), ground_angle=0.0)")]
    fn new(
        ground: Real,
        crank: Real,
        coupler: Real,
        rocker: Real,
        origin: PyPoint,
        ground_angle: Real,
    ) -> PyResult<Self> {
        FourBar::placed(
            ground.0,
            crank.0,
            coupler.0,
            rocker.0,
            origin.0,
            ground_angle.0,
        )
        .map(Self::from)
        .py()
    }

    #[staticmethod]
    fn from_pivots(
        input_pivot: PyPoint,
        output_pivot: PyPoint,
        crank: Real,
        coupler: Real,
        rocker: Real,
    ) -> PyResult<Self> {
        FourBar::from_pivots(input_pivot.0, output_pivot.0, crank.0, coupler.0, rocker.0)
            .map(Self::from)
            .py()
    }

    #[getter]
    fn ground(&self) -> f64 {
        self.inner.ground()
    }
    #[getter]
    fn crank(&self) -> f64 {
        self.inner.crank()
    }
    #[getter]
    fn coupler(&self) -> f64 {
        self.inner.coupler()
    }
    #[getter]
    fn rocker(&self) -> f64 {
        self.inner.rocker()
    }
    #[getter]
    fn lengths(&self) -> (f64, f64, f64, f64) {
        let [a, b, c, d] = self.inner.lengths();
        (a, b, c, d)
    }
    #[getter]
    fn input_pivot(&self) -> (f64, f64) {
        pt(self.inner.input_pivot())
    }
    #[getter]
    fn output_pivot(&self) -> (f64, f64) {
        pt(self.inner.output_pivot())
    }
    #[getter]
    fn ground_angle(&self) -> f64 {
        self.inner.ground_angle()
    }

    fn link_ratio(&self) -> f64 {
        self.inner.link_ratio()
    }

    #[pyo3(signature = (theta2, mode = "open"))]
    fn solve(&self, theta2: Real, mode: &str) -> PyResult<(f64, f64)> {
        let c = self.inner.solve(theta2.0, self::mode(mode)?).py()?;
        Ok((c.theta3, c.theta4))
    }

    #[pyo3(signature = (theta2, mode = "open"))]
    fn configuration(&self, theta2: Real, mode: &str) -> PyResult<PyConfiguration> {
        let c = self.inner.solve(theta2.0, self::mode(mode)?).py()?;
        Ok(PyConfiguration { inner: c })
    }

    #[pyo3(signature = (theta2s, mode = "open"))]
    fn solve_many<'py>(
        &self,
        py: Python<'py>,
        theta2s: FloatArray,
        mode: &str,
    ) -> PyResult<Arrays<'py>> {
        let mode = self::mode(mode)?;
        let FloatArray {
            values: flat,
            shape,
        } = theta2s;
        let n = flat.len();
        let fb = self.inner;
        let (t3, t4, ok) = py.detach(move || {
            let (mut t3, mut t4, mut ok) = (vec![0.0; n], vec![0.0; n], vec![false; n]);
            // Lengths agree by construction, so this cannot fail.
            let _ = fb.solve_into(&flat, mode, &mut t3, &mut t4, &mut ok);
            (t3, t4, ok)
        });
        Ok((
            to_numpy(py, &shape, t3),
            to_numpy(py, &shape, t4),
            to_numpy(py, &shape, ok),
        ))
    }

    fn grashof(&self) -> &'static str {
        self.inner.grashof().as_str()
    }

    fn input_turns_fully(&self) -> bool {
        self.inner.input_turns_fully()
    }

    /// `None` when the input turns fully, else a list of `(start, end)` arcs.
    fn input_range(&self) -> Option<Vec<(f64, f64)>> {
        match self.inner.input_range() {
            InputRange::Full => None,
            r => {
                let (arcs, n) = r.arcs_array();
                Some(arcs[..n].iter().map(|a| (a.start, a.end)).collect())
            }
        }
    }

    fn dead_positions(&self) -> Vec<f64> {
        self.inner.input_range().dead_positions()
    }

    #[pyo3(signature = (theta2, mode = "open"))]
    fn transmission_angle(&self, theta2: Real, mode: &str) -> PyResult<f64> {
        Ok(self
            .inner
            .solve(theta2.0, self::mode(mode)?)
            .py()?
            .transmission_angle())
    }

    #[pyo3(signature = (theta2, mode = "open"))]
    #[allow(clippy::type_complexity)]
    fn joints(
        &self,
        theta2: Real,
        mode: &str,
    ) -> PyResult<((f64, f64), (f64, f64), (f64, f64), (f64, f64))> {
        let j = self.inner.joints_at(theta2.0, self::mode(mode)?).py()?;
        Ok((
            pt(j.input_pivot),
            pt(j.crank_joint),
            pt(j.rocker_joint),
            pt(j.output_pivot),
        ))
    }

    #[pyo3(signature = (theta2, point, mode = "open"))]
    fn coupler_point(&self, theta2: Real, point: PyPoint, mode: &str) -> PyResult<(f64, f64)> {
        let mode = self::mode(mode)?;
        let local = point.0.coords;
        let mut it = self.inner.coupler_path(local, [theta2.0], mode);
        it.next().expect("one angle in, one point out").map(pt).py()
    }

    #[pyo3(signature = (point, theta2s, mode = "open"))]
    fn coupler_path<'py>(
        &self,
        py: Python<'py>,
        point: PyPoint,
        theta2s: FloatArray,
        mode: &str,
    ) -> PyResult<Arrays<'py>> {
        let mode = self::mode(mode)?;
        let local = point.0.coords;
        if !(local.x.is_finite() && local.y.is_finite()) {
            // Report the bad point once, as an exception.
            self.inner
                .coupler_path(local, [0.0], mode)
                .next()
                .expect("one item")
                .py()?;
        }
        let FloatArray {
            values: flat,
            shape,
        } = theta2s;
        let fb = self.inner;
        let (xs, ys, ok) = py.detach(move || {
            let n = flat.len();
            let (mut xs, mut ys, mut ok) = (vec![f64::NAN; n], vec![f64::NAN; n], vec![false; n]);
            for (i, p) in fb.coupler_path(local, flat, mode).enumerate() {
                if let Ok(p) = p {
                    xs[i] = p.x;
                    ys[i] = p.y;
                    ok[i] = true;
                }
            }
            (xs, ys, ok)
        });
        Ok((
            to_numpy(py, &shape, xs),
            to_numpy(py, &shape, ys),
            to_numpy(py, &shape, ok),
        ))
    }

    fn __repr__(&self) -> String {
        let [l1, l2, l3, l4] = self.inner.lengths();
        let o = self.inner.input_pivot();
        let a = self.inner.ground_angle();
        if o == Point2::origin() && a == 0.0 {
            format!("FourBar({l1:?}, {l2:?}, {l3:?}, {l4:?})")
        } else {
            format!(
                "FourBar({l1:?}, {l2:?}, {l3:?}, {l4:?}, origin=({:?}, {:?}), ground_angle={a:?})",
                o.x, o.y
            )
        }
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PyFourBar>()
            .map(|o| o.get().inner == self.inner)
            .unwrap_or(false)
    }
}

/// One solved position of a four-bar.
#[pyclass(frozen, name = "Configuration", module = "burmester")]
#[derive(Clone)]
pub struct PyConfiguration {
    pub(crate) inner: Configuration,
}

#[pymethods]
impl PyConfiguration {
    #[getter]
    fn theta2(&self) -> f64 {
        self.inner.theta2
    }
    #[getter]
    fn theta3(&self) -> f64 {
        self.inner.theta3
    }
    #[getter]
    fn theta4(&self) -> f64 {
        self.inner.theta4
    }
    #[getter]
    fn mode(&self) -> &'static str {
        self.inner.mode.as_str()
    }
    #[getter]
    fn toggle(&self) -> bool {
        self.inner.toggle
    }
    #[getter]
    fn transmission_angle(&self) -> f64 {
        self.inner.transmission_angle()
    }
    #[getter]
    fn coupler_rocker_angle(&self) -> f64 {
        self.inner.coupler_rocker_angle()
    }
    fn __repr__(&self) -> String {
        let c = &self.inner;
        format!(
            "Configuration(theta2={:?}, theta3={:?}, theta4={:?}, mode='{}', toggle={})",
            c.theta2,
            c.theta3,
            c.theta4,
            c.mode.as_str(),
            if c.toggle { "True" } else { "False" }
        )
    }
}
