//! `burmester.Task`, `Pole`, `Filemon` and `SynthesizedFourBar` (the core's
//! `synthesis`).

use burmester::synthesis::{FivePositions, FourPositions};
use burmester::{CircleOrLine, Cremona, Line, Point2, Pole, Pose, Task};
use numpy::{PyArray2, PyArrayDyn};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PySequence, PyTuple};

use crate::classes::{PyFilemon, PySynthesizedFourBar, PyTask, dyad_tuple};
use crate::conv::{
    Count, FloatArray, PyPoint, Real, points, pt, py_bool, slice_mut, to_numpy, writer, zeros,
};
use crate::curves::{self, PyCoincidencePoint, PyCubic, PyCurveDyad};
use crate::errors::IntoPy;
use crate::geom::{PyConic, grid_alone, grid_arg, vec2};
use crate::getters::getters;
use crate::linkage::{PyFourBar, PyLinkageFigures};

type Xy = (f64, f64);

/// Mapped points (NaN where undefined) and their validity mask.
type MappedPoints<'py> = PyResult<(Bound<'py, PyArrayDyn<f64>>, Bound<'py, PyArrayDyn<bool>>)>;

pub(crate) fn circle_dict<'py>(py: Python<'py>, c: CircleOrLine) -> PyResult<Bound<'py, PyDict>> {
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

pub(crate) fn line_tuple(l: &Line) -> (Xy, Xy) {
    (pt(l.point), vec2(l.direction))
}

/// Maps an array of points with the task's map `f` (for the Python method
/// `method`), returning the mapped points (NaN where it fails) and a
/// validity mask. A C-contiguous float64 input is read in place and the
/// results are written straight into the returned arrays.
fn map_points<'py>(
    py: Python<'py>,
    task: &Task,
    method: &'static str,
    input: FloatArray<'py>,
    f: impl Fn(&Task, Point2<f64>) -> burmester::Result<Point2<f64>> + Send + Sync,
) -> MappedPoints<'py> {
    // A task of five poses is a misuse, not a point without an answer:
    // raise instead of a mask of False.
    task.check_point_maps(method).py()?;
    let pts = points(&input)?;
    let mut shape = pts.lead.clone();
    shape.push(2);
    let out = zeros::<f64>(py, &shape)?;
    let ok = zeros::<bool>(py, &pts.lead)?;
    {
        let (mut out_w, mut ok_w) = (writer(&out)?, writer(&ok)?);
        let (out_s, ok_s) = (slice_mut(&mut out_w), slice_mut(&mut ok_w));
        py.detach(|| {
            for ((p, q), valid) in pts.iter().zip(out_s.chunks_exact_mut(2)).zip(ok_s) {
                match f(task, p) {
                    Ok(r) => {
                        q.copy_from_slice(&[r.x, r.y]);
                        *valid = true;
                    }
                    Err(_) => {
                        q.copy_from_slice(&[f64::NAN, f64::NAN]);
                        *valid = false;
                    }
                }
            }
        });
    }
    Ok((out, ok))
}

/// The poses of a task from Python: a sequence of `(x, y, angle)`.
fn poses_arg(ob: &Bound<'_, PyAny>) -> PyResult<Vec<Pose>> {
    let usage = |what: String| {
        PyTypeError::new_err(format!(
            "a task takes a sequence of poses (x, y, angle), each three numbers; {what}"
        ))
    };
    if ob.is_instance_of::<pyo3::types::PyString>() {
        return Err(usage("got a string".into()));
    }
    let seq = ob.cast::<PySequence>().map_err(|_| {
        usage(format!(
            "got {}",
            ob.get_type()
                .name()
                .map_or("an object".into(), |n| n.to_string())
        ))
    })?;
    let mut out = Vec::new();
    for (k, item) in seq.try_iter()?.enumerate() {
        let item = item?;
        let v: Vec<Real> = item.extract().map_err(|e: PyErr| {
            if e.is_instance_of::<crate::errors::InvalidInputError>(ob.py()) {
                e
            } else {
                usage(format!("pose {} is not a sequence of numbers", k + 1))
            }
        })?;
        let [x, y, a] = v[..] else {
            return Err(crate::errors::invalid(
                "pose_shape",
                format!(
                    "pose {} must be (x, y, angle): three numbers, got {}; pass three",
                    k + 1,
                    v.len()
                ),
            ));
        };
        out.push(Pose::new(x.0, y.0, a.0));
    }
    Ok(out)
}

/// A pole: the fixed point of the displacement between two poses, or the
/// direction in which it lies at infinity.
#[pyclass(frozen, eq, name = "Pole", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PyPole {
    pair: (usize, usize),
    point: Option<Xy>,
    direction: Option<Xy>,
}

#[pymethods]
impl PyPole {
    #[new]
    #[pyo3(signature = (pair, point = None, direction = None))]
    fn new(
        pair: (Count, Count),
        point: Option<PyPoint>,
        direction: Option<PyPoint>,
    ) -> PyResult<Self> {
        let pair = (pair.0.0, pair.1.0);
        if !(1 <= pair.0 && pair.0 < pair.1 && pair.1 <= burmester::geom::MAX_POSES) {
            return Err(crate::errors::invalid(
                "pose_index",
                format!(
                    "a pole's pair must be two pose indices 1 <= i < j <= {}, got {pair:?}; \
                     pass 1-based indices",
                    burmester::geom::MAX_POSES
                ),
            ));
        }
        if point.is_some() == direction.is_some() {
            return Err(PyTypeError::new_err(
                "a pole has either a point or a direction (at infinity)",
            ));
        }
        let bad = |e: burmester::InvalidInput| Err(crate::errors::to_py(e.into()));
        if let Some(p) = point {
            for (name, value) in [("pole x", p.0.x), ("pole y", p.0.y)] {
                if !value.is_finite() {
                    return bad(burmester::InvalidInput::NotFinite { name, value });
                }
            }
        }
        if let Some(d) = direction {
            let (x, y) = (d.0.x, d.0.y);
            if !(x.is_finite() && y.is_finite()) || (x == 0.0 && y == 0.0) {
                return bad(burmester::InvalidInput::ZeroDirection {
                    name: "the pole's direction",
                    x,
                    y,
                });
            }
        }
        Ok(PyPole {
            pair,
            point: point.map(|p| pt(p.0)),
            direction: direction.map(|d| pt(d.0)),
        })
    }
    /// `(i, j)`, 1-based.
    #[getter]
    fn pair(&self) -> (usize, usize) {
        self.pair
    }
    #[getter]
    fn at_infinity(&self) -> bool {
        self.point.is_none()
    }
    fn __getnewargs__(&self) -> ((usize, usize), Option<Xy>, Option<Xy>) {
        (self.pair, self.point, self.direction)
    }
    fn __repr__(&self) -> String {
        let (i, j) = self.pair;
        match (self.point, self.direction) {
            (Some((x, y)), _) => format!("Pole(({i}, {j}), point=({x:?}, {y:?}))"),
            (_, Some((x, y))) => format!("Pole(({i}, {j}), direction=({x:?}, {y:?}))"),
            _ => format!("Pole(({i}, {j}))"),
        }
    }
}

getters!(PyPole {
    Option<Xy>: point, direction;
});

impl PyTask {
    fn cremona(&self) -> PyResult<&Cremona> {
        self.inner.cremona().py()
    }

    fn four(&self, method: &'static str) -> PyResult<&FourPositions> {
        self.inner.four_positions(method).py()
    }

    fn five(&self, method: &'static str) -> PyResult<&FivePositions> {
        self.inner.five_positions(method).py()
    }
}

#[pymethods]
impl PyTask {
    #[new]
    fn new(poses: &Bound<'_, PyAny>) -> PyResult<Self> {
        Task::new(&poses_arg(poses)?)
            .map(|inner| PyTask { inner })
            .py()
    }

    fn __getnewargs__(&self) -> (Vec<(f64, f64, f64)>,) {
        (self.poses(),)
    }

    fn __len__(&self) -> usize {
        self.inner.len()
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
    fn poles(&self) -> Vec<PyPole> {
        self.inner
            .motion()
            .pairs()
            .zip(self.inner.poles())
            .map(|(pair, p)| match p {
                Pole::Finite(q) => PyPole {
                    pair,
                    point: Some(pt(q)),
                    direction: None,
                },
                Pole::AtInfinity { direction } => PyPole {
                    pair,
                    point: None,
                    direction: Some(vec2(direction)),
                },
            })
            .collect()
    }

    fn rotation(&self, i: Count, j: Count) -> PyResult<f64> {
        self.inner.rotation(i.0, j.0).py()
    }

    fn image_poles(&self) -> PyResult<(Xy, Xy, Xy)> {
        let [a, b, c] = self.cremona()?.image_poles();
        Ok((pt(a), pt(b), pt(c)))
    }

    fn image_poles_in(&self, frame: Count) -> PyResult<(Xy, Xy, Xy)> {
        let [a, b, c] = self.cremona()?.image_poles_in(frame.0).py()?;
        Ok((pt(a), pt(b), pt(c)))
    }

    fn pole_circle<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        circle_dict(py, self.cremona()?.pole_circle())
    }

    fn image_pole_circle<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        circle_dict(py, self.cremona()?.image_pole_circle())
    }

    fn pole_triangle_angles(&self) -> PyResult<(f64, f64, f64)> {
        let [a, b, c] = self.cremona()?.pole_triangle_angles();
        Ok((a, b, c))
    }

    fn displace(&self, point: PyPoint, i: Count, j: Count) -> PyResult<Xy> {
        self.inner.displace(point.0, i.0, j.0).map(pt).py()
    }

    fn circle_point(&self, center: PyPoint) -> PyResult<Xy> {
        self.inner.circle_point_of(center.0).map(pt).py()
    }

    fn center_point(&self, circle: PyPoint) -> PyResult<Xy> {
        self.inner.center_point_of(circle.0).map(pt).py()
    }

    fn circle_points<'py>(&self, py: Python<'py>, centers: FloatArray<'py>) -> MappedPoints<'py> {
        map_points(
            py,
            &self.inner,
            "Task.circle_points",
            centers,
            Task::circle_point_of,
        )
    }

    fn center_points<'py>(&self, py: Python<'py>, circles: FloatArray<'py>) -> MappedPoints<'py> {
        map_points(
            py,
            &self.inner,
            "Task.center_points",
            circles,
            Task::center_point_of,
        )
    }

    fn dyad(&self, center: PyPoint) -> PyResult<(Xy, Xy)> {
        let d = self.inner.dyad(center.0).py()?;
        Ok(dyad_tuple(&d))
    }

    fn crank_angles(&self, center: PyPoint) -> PyResult<Vec<f64>> {
        let d = self.inner.dyad(center.0).py()?;
        Ok(self.inner.crank_angles(&d).to_vec())
    }

    // Four poses: the Burmester curves.

    fn center_point_curve(&self) -> PyResult<PyCubic> {
        let four = self.four("Task.center_point_curve")?;
        Ok(PyCubic {
            inner: *four.center_point_curve(),
        })
    }

    fn circle_point_curve(&self) -> PyResult<PyCubic> {
        let four = self.four("Task.circle_point_curve")?;
        Ok(PyCubic {
            inner: *four.circle_point_curve(),
        })
    }

    /// The six points `Q_jk` (pairs `12, 13, 14, 23, 24, 34`).
    fn coincidence_points(&self) -> PyResult<Vec<PyCoincidencePoint>> {
        let four = self.four("Task.coincidence_points")?;
        Ok(four.coincidence_points().iter().map(Into::into).collect())
    }

    fn curve_dyad(&self, center: PyPoint) -> PyResult<PyCurveDyad> {
        let four = self.four("Task.curve_dyad")?;
        Ok((&four.curve_dyad(center.0).py()?).into())
    }

    #[pyo3(signature = (samples = Count(200)), text_signature = "($self, samples=200)")]
    fn curve_dyads<'py>(
        &self,
        py: Python<'py>,
        samples: Count,
    ) -> PyResult<Bound<'py, pyo3::types::PyList>> {
        let four = self.four("Task.curve_dyads")?;
        // Ten million samples take seconds: Ctrl-C is watched.
        let long = samples.0 >= 1 << 14;
        let runs = crate::run::run_in(py, long, None, None, "dyads", |control| {
            four.dyad_runs_with(samples.0, control)
        })?;
        crate::run::list_polled(py, &runs, |run| {
            Ok(crate::run::list_polled(py, run, |d| {
                Ok(Bound::new(py, PyCurveDyad::from(d))?.into_any())
            })?
            .into_any())
        })
    }

    /// Four poses: the branch-free arcs of the center-point curve in view
    /// for the driven dyad with this center point (Filemon's construction
    /// with four lines, exact arc ends).
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (driven_center, xmin, xmax, ymin, ymax, *, plane = "center"))]
    fn branch_free_arcs<'py>(
        &self,
        py: Python<'py>,
        driven_center: PyPoint,
        xmin: Real,
        xmax: Real,
        ymin: Real,
        ymax: Real,
        plane: &str,
    ) -> PyResult<Vec<Bound<'py, PyArray2<f64>>>> {
        let four = self.four("Task.branch_free_arcs")?;
        let vp = curves::viewport(xmin, xmax, ymin, ymax)?;
        let circle = curves::circle_plane(plane)?;
        let driven = four.dyad_from_center(driven_center.0).py()?;
        let arcs = four.filemon(&driven).py()?;
        curves::free_arcs(py, &arcs, &vp, circle)
    }

    /// Four poses: the branch class (`"free"`, `"defective"`, `"boundary"`)
    /// of a driving center point on the curve for the driven dyad with
    /// `driven_center`.
    fn curve_branch(&self, driven_center: PyPoint, center: PyPoint) -> PyResult<&'static str> {
        let four = self.four("Task.curve_branch")?;
        let driven = four.dyad_from_center(driven_center.0).py()?;
        let arcs = four.filemon(&driven).py()?;
        Ok(arcs.classify_center_point(center.0).py()?.as_str())
    }

    #[allow(clippy::type_complexity)]
    #[pyo3(signature = (xmin, xmax, ymin, ymax, *, plane = "center"))]
    fn order_arcs<'py>(
        &self,
        py: Python<'py>,
        xmin: Real,
        xmax: Real,
        ymin: Real,
        ymax: Real,
        plane: &str,
    ) -> PyResult<Vec<(String, Option<&'static str>, Bound<'py, PyArray2<f64>>)>> {
        let four = self.four("Task.order_arcs")?;
        let vp = curves::viewport(xmin, xmax, ymin, ymax)?;
        let circle = curves::circle_plane(plane)?;
        let arcs = py.detach(|| {
            if circle {
                four.circle_order_arcs(&vp)
            } else {
                four.order_arcs(&vp)
            }
        });
        arcs.iter()
            .map(|a| {
                Ok((
                    a.order.to_string(),
                    a.order.direction().map(|d| d.as_str()),
                    curves::polyline(py, &a.points)?,
                ))
            })
            .collect()
    }

    // Five poses: the Burmester points.

    fn burmester_points(&self) -> PyResult<Vec<(Xy, Xy)>> {
        let five = self.five("Task.burmester_points")?;
        Ok(five.burmester_points().iter().map(dyad_tuple).collect())
    }

    fn burmester_curves(&self) -> PyResult<(PyCubic, PyCubic)> {
        let five = self.five("Task.burmester_curves")?;
        let [a, b] = five.center_point_curves();
        Ok((PyCubic { inner: a }, PyCubic { inner: b }))
    }

    fn burmester_four_bars(&self) -> PyResult<Vec<(usize, usize, PySynthesizedFourBar)>> {
        let bars = self.inner.burmester_four_bars("Task.burmester_four_bars");
        Ok(bars
            .py()?
            .into_iter()
            .map(|(i, j, fb)| (i, j, PySynthesizedFourBar::new(self.inner, fb)))
            .collect())
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
        self.inner
            .four_bar_of(driving_center.0, driven_center.0)
            .map(|inner| PySynthesizedFourBar::new(self.inner, inner))
            .py()
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

    /// A picture for Jupyter: PNG bytes drawn by `burmester._display`, or
    /// None without matplotlib.
    fn _repr_png_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        crate::display::repr_png(slf.as_any())
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

getters!(PyTask, inner {
    fn Vec<f64>: rotations;
    fn f64: scale, span;
});

#[pymethods]
impl PyFilemon {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (Xy,))> {
        let task = Bound::new(py, self.task())?;
        let c0 = self.inner.driven_crank("Filemon").py()?.center;
        Ok((task.getattr("filemon")?, (pt(c0),)))
    }

    #[getter]
    fn driven_center(&self) -> PyResult<Xy> {
        // A Filemon is made from a driven center point (Task.filemon): a
        // crank; a slider's construction is a SliderFilemon.
        Ok(pt(self
            .inner
            .driven_crank("Filemon.driven_center")
            .py()?
            .center))
    }

    #[getter]
    fn fixed_pivot_images(&self) -> Option<(Xy, Xy, Xy)> {
        // Always there for a crank (every Filemon is one).
        let [a, b, c] = self.inner.fixed_pivot_images()?;
        Some((pt(a), pt(b), pt(c)))
    }

    #[pyo3(signature = (center, method = "conic"))]
    fn is_branch_free(&self, center: PyPoint, method: &str) -> PyResult<bool> {
        self.inner
            .is_branch_free(center.0, self::method(method)?)
            .py()
    }

    fn circle_signs(&self, circle: PyPoint) -> PyResult<(f64, f64, f64)> {
        let [a, b, c] = self.inner.circle_signs(circle.0).py()?;
        Ok((a, b, c))
    }

    #[pyo3(signature = (*grid, method = None, out = None, progress = None),
        text_signature = "($self, *grid, method='conic', out=None, progress=None)")]
    fn branch_map<'py>(
        &self,
        py: Python<'py>,
        grid: &Bound<'py, PyTuple>,
        method: Option<&str>,
        out: Option<Bound<'py, PyAny>>,
        progress: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (g, used) = grid_arg(grid)?;
        let method = match (grid.len() - used, method) {
            (0, m) => m.unwrap_or("conic").to_owned(),
            (1, None) => grid.get_item(used)?.extract::<String>()?,
            _ => {
                return Err(PyTypeError::new_err(
                    "branch_map takes a grid (or its six numbers) and a method, once",
                ));
            }
        };
        crate::sweep::branch_map(self.inner, py, g, &method, out, progress.as_ref())
    }

    #[pyo3(signature = (*grid, out = None, progress = None),
        text_signature = "($self, *grid, out=None, progress=None)")]
    fn margin_map<'py>(
        &self,
        py: Python<'py>,
        grid: &Bound<'py, PyTuple>,
        out: Option<Bound<'py, PyAny>>,
        progress: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let g = grid_alone(grid, "margin_map takes a grid (or its six numbers)")?;
        crate::sweep::margin_map(self.inner, py, g, out, progress.as_ref())
    }

    fn margin(&self, center: PyPoint) -> PyResult<f64> {
        self.inner.margin(center.0).py()
    }

    fn four_bar(&self, driving_center: PyPoint) -> PyResult<PySynthesizedFourBar> {
        self.inner
            .four_bar(driving_center.0)
            .map(|inner| PySynthesizedFourBar::new(*self.inner.task(), inner))
            .py()
    }

    /// A picture for Jupyter: PNG bytes drawn by `burmester._display`, or
    /// None without matplotlib.
    fn _repr_png_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        crate::display::repr_png(slf.as_any())
    }

    fn __repr__(&self) -> String {
        let c0 = self
            .inner
            .driven()
            .finite_center()
            .unwrap_or(Point2::new(f64::NAN, f64::NAN));
        format!(
            "<Filemon driven_center=({:?}, {:?}) all_defective={}>",
            c0.x,
            c0.y,
            py_bool(self.inner.all_defective())
        )
    }
}

getters!(PyFilemon, inner {
    fn Xy = pt: driven_circle;
});

/// The methods of the three-pose construction (the core's `Filemon`, in
/// the field `inner`) that do not depend on the driven dyad's kind, for
/// `$class`: `Filemon` (a crank) and `SliderFilemon` (a slider) both.
macro_rules! filemon_methods {
    ($class:ty) => {
        #[pymethods]
        impl $class {
            #[getter]
            fn task(&self) -> $crate::classes::PyTask {
                $crate::classes::PyTask {
                    inner: *self.inner.task(),
                }
            }

            #[getter]
            fn all_defective(&self) -> bool {
                self.inner.all_defective()
            }

            #[getter]
            fn lines(&self) -> Vec<((f64, f64), (f64, f64))> {
                let lines = self.inner.lines();
                let lines = lines.iter().flatten();
                lines.map($crate::synthesis::line_tuple).collect()
            }

            #[getter]
            fn all_lines(&self) -> Vec<((f64, f64), (f64, f64))> {
                let lines = self.inner.all_lines();
                lines.iter().map($crate::synthesis::line_tuple).collect()
            }

            #[getter]
            fn sectors(&self) -> Vec<(f64, f64, bool)> {
                self.inner.construction().sectors()
            }

            #[getter]
            fn conics(&self) -> Vec<$crate::geom::PyConic> {
                let conics = self.inner.conics();
                let conics = conics.iter().flatten();
                conics
                    .map(|&inner| $crate::geom::PyConic { inner })
                    .collect()
            }

            #[getter]
            fn extreme_poses(&self) -> Option<(usize, usize)> {
                self.inner.extreme_poses().map(|([a, b], _)| (a, b))
            }

            #[getter]
            fn middle_pose(&self) -> Option<usize> {
                self.inner.extreme_poses().map(|(_, m)| m)
            }

            fn line_conic(&self, pose: $crate::conv::Count) -> PyResult<$crate::geom::PyConic> {
                let inner = self.inner.line_conic(pose.0).py()?;
                Ok($crate::geom::PyConic { inner })
            }

            #[pyo3(signature = (center, method = "conic"))]
            fn classify(
                &self,
                center: $crate::conv::PyPoint,
                method: &str,
            ) -> PyResult<&'static str> {
                let method = method.parse::<burmester::Method>().py()?;
                Ok(self.inner.classify(center.0, method).py()?.as_str())
            }

            fn classify_circle_point(
                &self,
                circle: $crate::conv::PyPoint,
            ) -> PyResult<&'static str> {
                Ok(self.inner.classify_circle_point(circle.0).py()?.as_str())
            }

            fn conic_values(&self, center: $crate::conv::PyPoint) -> PyResult<Option<(f64, f64)>> {
                Ok(self.inner.conic_values(center.0).py()?.map(|[a, b]| (a, b)))
            }
        }
    };
}

pub(crate) use filemon_methods;

filemon_methods!(PyFilemon);

fn method(s: &str) -> PyResult<burmester::Method> {
    s.parse::<burmester::Method>().py()
}

#[pymethods]
impl PySynthesizedFourBar {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (Xy, Xy))> {
        let task = Bound::new(py, PyTask { inner: self.task })?;
        Ok((
            task.getattr("four_bar")?,
            (pt(self.inner.driving.center), pt(self.inner.driven.center)),
        ))
    }
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PySynthesizedFourBar>()
            .is_ok_and(|o| *o.get() == *self)
    }
    #[getter]
    fn fourbar(&self) -> PyFourBar {
        self.inner.fourbar.into()
    }
    #[getter]
    pub(crate) fn size_ratio(&self) -> f64 {
        self.inner.size() / self.task.span()
    }
    /// The linkage's score by a ranking (`RankBy::score`); None without a
    /// feasible travel.
    #[pyo3(signature = (rank_by = "balanced"))]
    fn score(&self, rank_by: &str) -> PyResult<Option<f64>> {
        let rank = rank_by.parse::<burmester::RankBy>().py()?;
        if matches!(rank, burmester::RankBy::Pareto | burmester::RankBy::Margin) {
            return Err(crate::errors::invalid(
                "unknown_name",
                format!(
                    "a linkage alone has no {rank_by:?} score; use \"balanced\", \"transmission\" \
                     or \"compact\""
                ),
            ));
        }
        let f = &self.inner.figures;
        Ok(rank.score(f.min_transmission, self.size_ratio(), f.link_ratio))
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
    fn input_angles(&self) -> Vec<f64> {
        self.inner.input_angles.to_vec()
    }
    #[getter]
    fn modes(&self) -> Vec<Option<&'static str>> {
        self.inner
            .modes()
            .iter()
            .map(|m| m.map(|m| m.as_str()))
            .collect()
    }
    #[getter]
    pub(crate) fn figures(&self) -> PyLinkageFigures {
        PyLinkageFigures {
            inner: self.inner.figures,
        }
    }
    #[getter]
    fn branch_free(&self) -> bool {
        self.inner.is_branch_free()
    }
    /// `(start, span)` of the travel, or None.
    #[getter]
    fn travel(&self) -> Option<(f64, f64)> {
        self.inner.travel()
    }
    /// The input angle at each pose along the travel, unwrapped, or None.
    #[getter]
    fn travel_stops(&self) -> Option<Vec<f64>> {
        self.inner.travel_stops().map(|s| s.to_vec())
    }
    fn travel_angles<'py>(
        &self,
        py: Python<'py>,
        samples: Count,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let sfb = self.inner;
        let v = py.detach(|| sfb.travel_angles(samples.0)).py()?;
        let n = v.len();
        Ok(to_numpy(py, &[n], v))
    }
    #[pyo3(signature = (theta2, mode = "open"))]
    fn pose_at(&self, theta2: Real, mode: &str) -> PyResult<(f64, f64, f64)> {
        let p = self
            .inner
            .pose_at(theta2.0, crate::linkage::mode(mode)?)
            .py()?;
        Ok((p.position.x, p.position.y, p.angle))
    }

    /// A picture for Jupyter: PNG bytes drawn by `burmester._display`, or
    /// None without matplotlib.
    fn _repr_png_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        crate::display::repr_png(slf.as_any())
    }

    fn __repr__(&self) -> String {
        let [l1, l2, l3, l4] = self.inner.fourbar.lengths();
        format!(
            "<SynthesizedFourBar ground={l1:.6} crank={l2:.6} coupler={l3:.6} rocker={l4:.6} \
             branch_free={}>",
            py_bool(self.inner.is_branch_free())
        )
    }
}

getters!(PySynthesizedFourBar, inner {
    fn f64: size;
    Xy = vec2: coupler_point;
    f64: coupler_angle_offset;
});
