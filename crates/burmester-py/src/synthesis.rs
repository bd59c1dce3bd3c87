//! `burmester.Task`, `Filemon`, `Conic` and `SynthesizedFourBar`.

use burmester::{
    CircleOrLine, Conic, Dyad, Filemon, Line, Method, Point2, Pose, SynthesizedFourBar, Task,
    Viewport,
};
use numpy::{IntoPyArray, PyArray2, PyArrayDyn};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::conv::{Count, FloatArray, PyPoint, Real, points, pt, to_numpy, vec2};
use crate::errors::{IntoPy, InvalidInputError};
use crate::fourbar::PyFourBar;

type Xy = (f64, f64);

/// Mapped points (NaN where undefined) and their validity mask.
type MappedPoints<'py> = (Bound<'py, PyArrayDyn<f64>>, Bound<'py, PyArrayDyn<bool>>);

fn method(s: &str) -> PyResult<Method> {
    s.parse::<Method>().py()
}

fn pose_index(k: Count) -> PyResult<usize> {
    let k = k.0;
    if (1..=3).contains(&k) {
        Ok(k)
    } else {
        Err(InvalidInputError::new_err(format!(
            "pose index must be 1, 2 or 3, got {k}; pass one of those"
        )))
    }
}

fn circle_dict<'py>(py: Python<'py>, c: CircleOrLine) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    match c {
        CircleOrLine::Circle { center, radius } => {
            d.set_item("kind", "circle")?;
            d.set_item("center", pt(center))?;
            d.set_item("radius", radius)?;
        }
        CircleOrLine::Line { point, direction } => {
            d.set_item("kind", "line")?;
            d.set_item("point", pt(point))?;
            d.set_item("direction", vec2(direction))?;
        }
    }
    Ok(d)
}

fn line_tuple(l: &Line) -> (Xy, Xy) {
    (pt(l.point), vec2(l.direction))
}

/// Maps an array of points with `f`, returning the mapped points (NaN where
/// it fails) and a validity mask.
fn map_points<'py>(
    py: Python<'py>,
    input: FloatArray,
    f: impl Fn(Point2<f64>) -> burmester::Result<Point2<f64>> + Send + Sync,
) -> PyResult<MappedPoints<'py>> {
    let (pts, lead) = points(&input)?;
    let (out, ok) = py.detach(|| {
        let mut out = Vec::with_capacity(pts.len() * 2);
        let mut ok = Vec::with_capacity(pts.len());
        for p in &pts {
            match f(*p) {
                Ok(q) => {
                    out.extend([q.x, q.y]);
                    ok.push(true);
                }
                Err(_) => {
                    out.extend([f64::NAN, f64::NAN]);
                    ok.push(false);
                }
            }
        }
        (out, ok)
    });
    let mut shape = lead.clone();
    shape.push(2);
    Ok((to_numpy(py, &shape, out), to_numpy(py, &lead, ok)))
}

/// Three poses of the coupler.
#[pyclass(frozen, name = "Task", module = "burmester")]
#[derive(Clone)]
pub struct PyTask {
    pub(crate) inner: Task,
}

#[pymethods]
impl PyTask {
    #[new]
    fn new(poses: Vec<Vec<Real>>) -> PyResult<Self> {
        if poses.len() != 3 {
            return Err(InvalidInputError::new_err(format!(
                "a task needs exactly three poses (x, y, angle), got {}; pass three",
                poses.len()
            )));
        }
        let mut p = [Pose::new(0.0, 0.0, 0.0); 3];
        for (k, (q, v)) in p.iter_mut().zip(&poses).enumerate() {
            let [x, y, a] = v[..] else {
                return Err(InvalidInputError::new_err(format!(
                    "pose {} must be (x, y, angle): three numbers, got {}; pass three",
                    k + 1,
                    v.len()
                )));
            };
            *q = Pose::new(x.0, y.0, a.0);
        }
        Task::new(p).map(|inner| PyTask { inner }).py()
    }

    #[getter]
    fn poses(&self) -> Vec<(f64, f64, f64)> {
        self.inner
            .poses()
            .iter()
            .map(|p| (p.position.x, p.position.y, p.angle))
            .collect()
    }

    #[getter]
    fn rotations(&self) -> (f64, f64, f64) {
        let [a, b, c] = self.inner.rotations();
        (a, b, c)
    }

    #[getter]
    fn scale(&self) -> f64 {
        self.inner.scale()
    }

    fn poles(&self) -> (Xy, Xy, Xy) {
        let [a, b, c] = self.inner.poles();
        (pt(a), pt(b), pt(c))
    }

    fn image_poles(&self) -> (Xy, Xy, Xy) {
        let [a, b, c] = self.inner.image_poles();
        (pt(a), pt(b), pt(c))
    }

    fn image_poles_in(&self, frame: Count) -> PyResult<(Xy, Xy, Xy)> {
        let [a, b, c] = self.inner.image_poles_in(pose_index(frame)?).py()?;
        Ok((pt(a), pt(b), pt(c)))
    }

    fn pole_circle<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        circle_dict(py, self.inner.pole_circle())
    }

    fn image_pole_circle<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        circle_dict(py, self.inner.image_pole_circle())
    }

    fn pole_triangle_angles(&self) -> (f64, f64, f64) {
        let [a, b, c] = self.inner.pole_triangle_angles();
        (a, b, c)
    }

    fn displace(&self, point: PyPoint, i: Count, j: Count) -> PyResult<Xy> {
        Ok(pt(self.inner.displace(
            point.0,
            pose_index(i)?,
            pose_index(j)?,
        )))
    }

    fn circle_point(&self, center: PyPoint) -> PyResult<Xy> {
        self.inner.circle_point(center.0).map(pt).py()
    }

    fn center_point(&self, circle: PyPoint) -> PyResult<Xy> {
        self.inner.center_point(circle.0).map(pt).py()
    }

    fn circle_points<'py>(
        &self,
        py: Python<'py>,
        centers: FloatArray,
    ) -> PyResult<MappedPoints<'py>> {
        let t = self.inner;
        map_points(py, centers, move |p| t.circle_point(p))
    }

    fn center_points<'py>(
        &self,
        py: Python<'py>,
        circles: FloatArray,
    ) -> PyResult<MappedPoints<'py>> {
        let t = self.inner;
        map_points(py, circles, move |p| t.center_point(p))
    }

    fn dyad(&self, center: PyPoint) -> PyResult<(Xy, Xy)> {
        let d = self.inner.dyad_from_center(center.0).py()?;
        Ok((pt(d.center), pt(d.circle)))
    }

    fn crank_angles(&self, center: PyPoint) -> PyResult<(f64, f64, f64)> {
        let d = self.inner.dyad_from_center(center.0).py()?;
        let [a, b, c] = self.inner.crank_angles(&d);
        Ok((a, b, c))
    }

    fn filemon(&self, driven_center: PyPoint) -> PyResult<PyFilemon> {
        self.inner
            .filemon(driven_center.0)
            .map(|inner| PyFilemon { inner })
            .py()
    }

    fn four_bar(
        &self,
        driving_center: PyPoint,
        driven_center: PyPoint,
    ) -> PyResult<PySynthesizedFourBar> {
        let a = self.inner.dyad_from_center(driving_center.0).py()?;
        let c = self.inner.dyad_from_center(driven_center.0).py()?;
        self.inner
            .four_bar(&a, &c)
            .map(|inner| PySynthesizedFourBar { inner })
            .py()
    }

    #[pyo3(signature = (driving_center, xmin, xmax, ymin, ymax, nx, ny, *,
        min_transmission_deg = Real(30.0), max_link_ratio = Real(10.0), input = "any",
        base_plate = None, obstacles = None, link_width = Real(0.0), travel_samples = Count(64)),
        text_signature = "($self, /, driving_center, xmin, xmax, ymin, ymax, nx, ny, *, \
        min_transmission_deg=30.0, max_link_ratio=10.0, input='any', base_plate=None, \
        obstacles=None, link_width=0.0, travel_samples=64)")]
    #[allow(clippy::too_many_arguments)]
    fn driven_solution_map(
        &self,
        py: Python<'_>,
        driving_center: PyPoint,
        xmin: Real,
        xmax: Real,
        ymin: Real,
        ymax: Real,
        nx: Count,
        ny: Count,
        min_transmission_deg: Real,
        max_link_ratio: Real,
        input: &str,
        base_plate: Option<Vec<PyPoint>>,
        obstacles: Option<Vec<Vec<PyPoint>>>,
        link_width: Real,
        travel_samples: Count,
    ) -> PyResult<crate::design::PySolutionMap> {
        let (grid, opts) = crate::design::MapOptions::with_grid(
            [xmin, xmax, ymin, ymax],
            [nx, ny],
            min_transmission_deg,
            max_link_ratio,
            input,
            base_plate,
            obstacles,
            link_width,
            travel_samples,
        )?;
        crate::design::driven_solution_map(py, self.inner, driving_center.0, grid, opts)
    }

    fn line_to_conic(&self, point: PyPoint, direction: PyPoint) -> PyResult<PyConic> {
        self.inner
            .line_to_conic(&Line {
                point: point.0,
                direction: direction.0.coords,
            })
            .map(|inner| PyConic { inner })
            .py()
    }

    fn __repr__(&self) -> String {
        let p: Vec<String> = self
            .poses()
            .iter()
            .map(|(x, y, a)| format!("({x:?}, {y:?}, {a:?})"))
            .collect();
        format!("Task([{}])", p.join(", "))
    }
}

/// Filemon's construction for a driven dyad, and its transformed conics.
#[pyclass(frozen, name = "Filemon", module = "burmester")]
#[derive(Clone)]
pub struct PyFilemon {
    pub(crate) inner: Filemon,
}

#[pymethods]
impl PyFilemon {
    #[getter]
    fn task(&self) -> PyTask {
        PyTask {
            inner: *self.inner.task(),
        }
    }

    #[getter]
    fn driven_center(&self) -> Xy {
        pt(self.inner.driven().center)
    }

    #[getter]
    fn circle_point(&self) -> Xy {
        pt(self.inner.circle_point())
    }

    #[getter]
    fn fixed_pivot_images(&self) -> (Xy, Xy, Xy) {
        let [a, b, c] = self.inner.fixed_pivot_images();
        (pt(a), pt(b), pt(c))
    }

    #[getter]
    fn all_defective(&self) -> bool {
        self.inner.all_defective()
    }

    #[getter]
    fn lines(&self) -> Vec<(Xy, Xy)> {
        self.inner
            .lines()
            .map(|ls| ls.iter().map(line_tuple).collect())
            .unwrap_or_default()
    }

    #[getter]
    fn all_lines(&self) -> Vec<(Xy, Xy)> {
        self.inner.all_lines().iter().map(line_tuple).collect()
    }

    #[getter]
    fn conics(&self) -> Vec<PyConic> {
        self.inner
            .conics()
            .map(|cs| cs.iter().map(|&inner| PyConic { inner }).collect())
            .unwrap_or_default()
    }

    #[getter]
    fn extreme_poses(&self) -> Option<(usize, usize)> {
        self.inner.extreme_poses().map(|([a, b], _)| (a, b))
    }

    #[getter]
    fn middle_pose(&self) -> Option<usize> {
        self.inner.extreme_poses().map(|(_, m)| m)
    }

    fn line_conic(&self, pose: Count) -> PyResult<PyConic> {
        Ok(PyConic {
            inner: self.inner.line_conic(pose_index(pose)?),
        })
    }

    #[pyo3(signature = (center, method = "conic"))]
    fn is_branch_free(&self, center: PyPoint, method: &str) -> PyResult<bool> {
        self.inner
            .is_branch_free(center.0, self::method(method)?)
            .py()
    }

    #[pyo3(signature = (center, method = "conic"))]
    fn classify(&self, center: PyPoint, method: &str) -> PyResult<&'static str> {
        Ok(self
            .inner
            .classify(center.0, self::method(method)?)
            .py()?
            .as_str())
    }

    fn classify_circle_point(&self, circle: PyPoint) -> &'static str {
        self.inner.classify_circle_point(circle.0).as_str()
    }

    fn circle_signs(&self, circle: PyPoint) -> (f64, f64, f64) {
        let [a, b, c] = self.inner.circle_signs(circle.0);
        (a, b, c)
    }

    fn conic_values(&self, center: PyPoint) -> Option<(f64, f64)> {
        self.inner.conic_values(center.0).map(|[a, b]| (a, b))
    }

    #[pyo3(signature = (xmin, xmax, ymin, ymax, nx, ny, method = "conic", *, out = None))]
    #[allow(clippy::too_many_arguments)]
    fn branch_map<'py>(
        &self,
        py: Python<'py>,
        xmin: Real,
        xmax: Real,
        ymin: Real,
        ymax: Real,
        nx: Count,
        ny: Count,
        method: &str,
        out: Option<Bound<'py, PyArray2<bool>>>,
    ) -> PyResult<Bound<'py, PyArray2<bool>>> {
        let grid = (xmin, xmax, ymin, ymax, nx, ny);
        crate::sweep::branch_map(self.inner, py, grid, method, out)
    }

    #[pyo3(signature = (xmin, xmax, ymin, ymax, nx, ny, *, out = None))]
    #[allow(clippy::too_many_arguments)]
    fn margin_map<'py>(
        &self,
        py: Python<'py>,
        xmin: Real,
        xmax: Real,
        ymin: Real,
        ymax: Real,
        nx: Count,
        ny: Count,
        out: Option<Bound<'py, PyArray2<f32>>>,
    ) -> PyResult<Bound<'py, PyArray2<f32>>> {
        let grid = (xmin, xmax, ymin, ymax, nx, ny);
        crate::sweep::margin_map(self.inner, py, grid, out)
    }

    fn margin(&self, center: PyPoint) -> f64 {
        self.inner.margin(center.0)
    }

    #[pyo3(signature = (xmin, xmax, ymin, ymax, nx, ny, *, min_transmission_deg = Real(30.0),
        max_link_ratio = Real(10.0), input = "any", base_plate = None, obstacles = None,
        link_width = Real(0.0), travel_samples = Count(64)),
        text_signature = "($self, /, xmin, xmax, ymin, ymax, nx, ny, *, \
        min_transmission_deg=30.0, max_link_ratio=10.0, input='any', base_plate=None, \
        obstacles=None, link_width=0.0, travel_samples=64)")]
    #[allow(clippy::too_many_arguments)]
    fn solution_map(
        &self,
        py: Python<'_>,
        xmin: Real,
        xmax: Real,
        ymin: Real,
        ymax: Real,
        nx: Count,
        ny: Count,
        min_transmission_deg: Real,
        max_link_ratio: Real,
        input: &str,
        base_plate: Option<Vec<PyPoint>>,
        obstacles: Option<Vec<Vec<PyPoint>>>,
        link_width: Real,
        travel_samples: Count,
    ) -> PyResult<crate::design::PySolutionMap> {
        let (grid, opts) = crate::design::MapOptions::with_grid(
            [xmin, xmax, ymin, ymax],
            [nx, ny],
            min_transmission_deg,
            max_link_ratio,
            input,
            base_plate,
            obstacles,
            link_width,
            travel_samples,
        )?;
        crate::design::solution_map(py, self.inner, grid, opts)
    }

    fn four_bar(&self, driving_center: PyPoint) -> PyResult<PySynthesizedFourBar> {
        self.inner
            .four_bar(driving_center.0)
            .map(|inner| PySynthesizedFourBar { inner })
            .py()
    }

    fn __repr__(&self) -> String {
        let c0 = self.inner.driven().center;
        format!(
            "<Filemon driven_center=({:?}, {:?}) all_defective={}>",
            c0.x,
            c0.y,
            if self.inner.all_defective() {
                "True"
            } else {
                "False"
            }
        )
    }
}

/// A conic `A x^2 + B x y + C y^2 + D x + E y + F = 0`.
#[pyclass(frozen, name = "Conic", module = "burmester")]
#[derive(Clone)]
pub struct PyConic {
    pub(crate) inner: Conic,
}

#[pymethods]
impl PyConic {
    #[new]
    #[allow(clippy::many_single_char_names)]
    fn new(a: Real, b: Real, c: Real, d: Real, e: Real, f: Real) -> PyResult<Self> {
        Conic::new(a.0, b.0, c.0, d.0, e.0, f.0)
            .map(|inner| PyConic { inner })
            .py()
    }

    #[getter]
    fn coefficients(&self) -> (f64, f64, f64, f64, f64, f64) {
        let [a, b, c, d, e, f] = self.inner.coefficients();
        (a, b, c, d, e, f)
    }

    #[getter]
    fn kind(&self) -> &'static str {
        self.inner.kind().as_str()
    }

    #[getter]
    fn center(&self) -> Option<Xy> {
        self.inner.center().map(pt)
    }

    #[getter]
    fn axis_angle(&self) -> f64 {
        self.inner.axis_angle()
    }

    #[getter]
    fn asymptotes(&self) -> Option<(Xy, Xy, Xy)> {
        self.inner
            .asymptotes()
            .map(|[a, b]| (pt(a.point), vec2(a.direction), vec2(b.direction)))
    }

    fn evaluate(&self, point: PyPoint) -> f64 {
        self.inner.evaluate(point.0)
    }

    fn __call__(&self, point: PyPoint) -> f64 {
        self.inner.evaluate(point.0)
    }

    fn evaluate_many<'py>(
        &self,
        py: Python<'py>,
        points: FloatArray,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (pts, lead) = crate::conv::points(&points)?;
        let c = self.inner;
        let v: Vec<f64> = py.detach(|| pts.iter().map(|p| c.evaluate(*p)).collect());
        Ok(to_numpy(py, &lead, v))
    }

    fn side(&self, point: PyPoint) -> i8 {
        self.inner.side(point.0)
    }

    fn distance(&self, point: PyPoint) -> f64 {
        self.inner.distance_estimate(point.0)
    }

    #[pyo3(signature = (xmin, xmax, ymin, ymax, tolerance = None))]
    fn polylines<'py>(
        &self,
        py: Python<'py>,
        xmin: Real,
        xmax: Real,
        ymin: Real,
        ymax: Real,
        tolerance: Option<Real>,
    ) -> PyResult<Vec<Bound<'py, PyArray2<f64>>>> {
        let vp = Viewport::new(xmin.0, xmax.0, ymin.0, ymax.0).py()?;
        let tolerance = tolerance.map(|t| t.0);
        if let Some(t) = tolerance {
            if !(t.is_finite() && t > 0.0) {
                return Err(InvalidInputError::new_err(format!(
                    "tolerance must be a positive finite number, got {t}; pass one, or None for the default"
                )));
            }
        }
        let c = self.inner;
        let lines = py.detach(|| c.polylines(&vp, tolerance));
        Ok(lines
            .into_iter()
            .map(|l| {
                let flat: Vec<f64> = l.iter().flat_map(|p| [p.x, p.y]).collect();
                numpy::ndarray::Array2::from_shape_vec((l.len(), 2), flat)
                    .expect("two coordinates per point")
                    .into_pyarray(py)
            })
            .collect())
    }

    fn __repr__(&self) -> String {
        let [a, b, c, d, e, f] = self.inner.coefficients();
        format!(
            "Conic({a:?}, {b:?}, {c:?}, {d:?}, {e:?}, {f:?})  # {}",
            self.inner.kind()
        )
    }
}

/// A four-bar built from a driving and a driven dyad of a task.
#[pyclass(frozen, name = "SynthesizedFourBar", module = "burmester")]
#[derive(Clone)]
pub struct PySynthesizedFourBar {
    pub(crate) inner: SynthesizedFourBar,
}

fn dyad_tuple(d: &Dyad) -> (Xy, Xy) {
    (pt(d.center), pt(d.circle))
}

#[pymethods]
impl PySynthesizedFourBar {
    #[getter]
    fn fourbar(&self) -> PyFourBar {
        self.inner.fourbar.into()
    }
    #[getter]
    fn driving(&self) -> (Xy, Xy) {
        dyad_tuple(&self.inner.driving)
    }
    #[getter]
    fn driven(&self) -> (Xy, Xy) {
        dyad_tuple(&self.inner.driven)
    }
    #[getter]
    fn input_angles(&self) -> (f64, f64, f64) {
        let [a, b, c] = self.inner.input_angles;
        (a, b, c)
    }
    #[getter]
    fn modes(
        &self,
    ) -> (
        Option<&'static str>,
        Option<&'static str>,
        Option<&'static str>,
    ) {
        let [a, b, c] = self.inner.modes.map(|m| m.map(|m| m.as_str()));
        (a, b, c)
    }
    #[getter]
    fn coupler_point(&self) -> Xy {
        vec2(self.inner.coupler_point)
    }
    #[getter]
    fn coupler_angle_offset(&self) -> f64 {
        self.inner.coupler_angle_offset
    }
    fn is_branch_free(&self) -> bool {
        self.inner.is_branch_free()
    }
    #[pyo3(signature = (theta2, mode = "open"))]
    fn pose_at(&self, theta2: Real, mode: &str) -> PyResult<(f64, f64, f64)> {
        let p = self
            .inner
            .pose_at(theta2.0, crate::fourbar::mode(mode)?)
            .py()?;
        Ok((p.position.x, p.position.y, p.angle))
    }
    fn __repr__(&self) -> String {
        let [l1, l2, l3, l4] = self.inner.fourbar.lengths();
        format!(
            "<SynthesizedFourBar ground={l1:.6} crank={l2:.6} coupler={l3:.6} rocker={l4:.6} \
             branch_free={}>",
            if self.inner.is_branch_free() {
                "True"
            } else {
                "False"
            }
        )
    }
}
