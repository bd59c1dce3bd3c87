//! `burmester.SixBar`, `burmester.DriveMap` and `burmester.Drive`, and the
//! drive methods of `SynthesizedFourBar` (the core's `linkage::sixbar` and
//! `design::drive`): a motor for a linkage whose input swings.

use burmester::design::{
    AttachmentSearch, Drive, DriveColumnsOut, DriveContext, DriveOptions, search_drives,
};
use burmester::{
    Constraints, DesignLimits, Grid, MapOptions, Point2, RankBy, Ranking, SixBar, SixBarJoints,
    Task,
};
use numpy::{PyArray2, PyArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use crate::classes::{PyDesignLimits, PySynthesizedFourBar, PyTask};
use crate::conv::{
    Arrays, Count, FloatArray, PyPoint, Real, empty, fill_arrays, pt, py_bool, write_points,
};
use crate::design::{ranking_method, readonly, same_column, set_readonly};
use crate::errors::IntoPy;
use crate::geom::{PyGrid, vec2};
use crate::geom::{grid_alone, grid_map_getters};
use crate::getters::getters;
use crate::linkage::{PyFourBar, mode};
use crate::options::{
    ConstraintState, Keys, Keywords, constraint_state, constraints_of, text_signature,
};
use crate::pickle::{Reduced, reduce_to};
use crate::run::{WATCH_MIN_SAMPLES, run};

type Xy = (f64, f64);

/// The drive options of the Python keywords: the limits (a `DesignLimits`
/// or its keywords), the swing margin and time ratio, the constraints.
struct DriveArgs {
    map_options: MapOptions,
    options: DriveOptions,
}

impl DriveArgs {
    /// The drive options of the keywords `options` of drive method
    /// `method`, which accepts `keys`.
    fn new(method: &str, options: Option<&Bound<'_, PyDict>>, keys: Keys) -> PyResult<Self> {
        let k = Keywords::from_kwargs(method, options, keys)?;
        let options = DriveOptions::from_degrees(k.swing_margin_deg, k.max_time_ratio).py()?;
        Ok(DriveArgs {
            map_options: k.checked()?,
            options,
        })
    }

    /// The context of `linkage` on `grid` with the attachment (default: the
    /// input joint `A` at pose 1).
    fn context(
        &self,
        linkage: &PySynthesizedFourBar,
        attachment: Option<PyPoint>,
        grid: &Grid,
    ) -> PyResult<DriveContext> {
        let l = &linkage.inner;
        let e = attachment.map_or(l.driving.circle, |p| p.0);
        DriveContext::new(l, e, grid, &self.map_options, &self.options).py()
    }
}

/// A one-sample grid about `p` (the context of a single drive).
fn point_grid(p: Point2<f64>) -> PyResult<Grid> {
    let h = 1.0 + p.x.abs().max(p.y.abs());
    Grid::from_bounds(p.x - h, p.x + h, p.y - h, p.y + h, 1, 1).py()
}

fn rank(s: &str) -> PyResult<RankBy> {
    s.parse::<RankBy>().py()
}

/// A Watt II six-bar: a drive four-bar `D0 D E A0` turning the input link
/// `A0 A E` of a motion four-bar `A0 A C C0`.
#[pyclass(frozen, name = "SixBar", module = "burmester")]
#[derive(Clone)]
pub struct PySixBar {
    pub(crate) inner: SixBar,
}

#[pymethods]
impl PySixBar {
    #[new]
    #[pyo3(signature = (*, d0, d, e, a0, a, c, c0, p = None),
        text_signature = "(*, d0, d, e, a0, a, c, c0, p=None)")]
    #[allow(clippy::too_many_arguments)]
    fn new(
        d0: PyPoint,
        d: PyPoint,
        e: PyPoint,
        a0: PyPoint,
        a: PyPoint,
        c: PyPoint,
        c0: PyPoint,
        p: Option<PyPoint>,
    ) -> PyResult<Self> {
        let j = SixBarJoints {
            drive_pivot: d0.0,
            crank_joint: d.0,
            attachment: e.0,
            input_pivot: a0.0,
            input_joint: a.0,
            rocker_joint: c.0,
            output_pivot: c0.0,
            coupler_point: p.map_or(c.0, |q| q.0),
        };
        SixBar::from_joints(&j).map(|inner| PySixBar { inner }).py()
    }

    /// Rebuilds a six-bar from its parts (for pickling).
    #[staticmethod]
    fn _from_parts(
        drive: &Bound<'_, PyFourBar>,
        motion: &Bound<'_, PyFourBar>,
        attachment_angle: f64,
        drive_mode: &str,
        motion_mode: &str,
        coupler_point: PyPoint,
        coupler_angle_offset: f64,
    ) -> PyResult<Self> {
        SixBar::new(
            drive.get().inner,
            motion.get().inner,
            attachment_angle,
            mode(drive_mode)?,
            mode(motion_mode)?,
        )
        .and_then(|s| s.with_coupler_point(coupler_point.0.coords, coupler_angle_offset))
        .map(|inner| PySixBar { inner })
        .py()
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> Reduced<'py> {
        let s = &self.inner;
        let args = (
            PyFourBar::from(*s.drive()),
            PyFourBar::from(*s.motion()),
            s.attachment_angle(),
            s.drive_mode().as_str(),
            s.motion_mode().as_str(),
            vec2(s.coupler_point()),
            s.coupler_angle_offset(),
        );
        reduce_to::<PySixBar>(py, "_from_parts", args)
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PySixBar>()
            .is_ok_and(|o| o.get().inner == self.inner)
    }

    #[getter]
    fn drive(&self) -> PyFourBar {
        (*self.inner.drive()).into()
    }
    #[getter]
    fn motion(&self) -> PyFourBar {
        (*self.inner.motion()).into()
    }
    #[getter]
    fn lengths(&self) -> [f64; 8] {
        self.inner.lengths().links()
    }
    #[getter]
    fn attachment_side(&self) -> f64 {
        self.inner.lengths().attachment_side
    }
    #[getter]
    fn limit_positions(&self) -> Option<Vec<(f64, f64, f64, bool)>> {
        self.inner.limit_positions().map(|l| {
            l.iter()
                .map(|p| (p.crank_angle, p.rocker_angle, p.input_angle, p.extended))
                .collect()
        })
    }
    #[getter]
    fn swing(&self) -> Option<Xy> {
        self.inner.swing().map(|s| (s.start, s.end))
    }
    #[getter]
    fn min_transmission_deg(&self) -> Option<Xy> {
        self.inner
            .min_transmission_angles()
            .map(|[a, b]| (a.to_degrees(), b.to_degrees()))
    }

    /// `(psi, theta2, theta3, theta4)` at crank angle `phi`.
    fn solve(&self, phi: Real) -> PyResult<(f64, f64, f64, f64)> {
        let c = self.inner.solve(phi.0).py()?;
        Ok((
            c.rocker_angle(),
            c.input_angle(),
            c.motion.theta3,
            c.motion.theta4,
        ))
    }
    fn transmission_angles(&self, phi: Real) -> PyResult<Xy> {
        let [a, b] = self.inner.solve(phi.0).py()?.transmission_angles();
        Ok((a, b))
    }
    fn toggle(&self, phi: Real) -> PyResult<bool> {
        Ok(self.inner.solve(phi.0).py()?.toggle())
    }
    #[allow(clippy::type_complexity)]
    fn joints(&self, phi: Real) -> PyResult<[Xy; 8]> {
        let j = self.inner.joints_at(phi.0).py()?;
        Ok(j.to_array().map(pt))
    }
    fn pose_at(&self, phi: Real) -> PyResult<(f64, f64, f64)> {
        let p = self.inner.pose_at(phi.0).py()?;
        Ok((p.position.x, p.position.y, p.angle))
    }
    /// The coupler point over crank angles: `(xs, ys, valid)` arrays of
    /// their shape (NaN and False where a loop does not close).
    fn coupler_path<'py>(&self, py: Python<'py>, phis: FloatArray<'py>) -> PyResult<Arrays<'py>> {
        let (flat, shape) = (phis.values(), phis.shape());
        let six = self.inner;
        fill_arrays(py, shape, |xs, ys, ok| {
            write_points(six.coupler_path(flat.iter().copied()), xs, ys, ok);
        })
    }
    #[pyo3(signature = (start = Real(0.0), samples = Count(360)),
        text_signature = "($self, start=0.0, samples=360)")]
    fn crank_angles(&self, start: Real, samples: Count) -> PyResult<Vec<f64>> {
        self.inner.crank_angles(start.0, samples.0).py()
    }
    fn crank_angles_for_input(&self, theta2: Real) -> Vec<f64> {
        self.inner.crank_angles_for_input(theta2.0)
    }
    fn _repr_png_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        crate::display::repr_png(slf.as_any())
    }
    fn __repr__(&self) -> String {
        let l = self.inner.lengths();
        format!(
            "<SixBar drive {} (crank={:.6} coupler={:.6} rocker={:.6} ground={:.6}) turns_fully={}>",
            self.inner.drive_grashof(),
            l.crank,
            l.drive_coupler,
            l.rocker,
            l.drive_ground,
            py_bool(self.inner.crank_turns_fully())
        )
    }
}

getters!(PySixBar, inner {
    fn str: drive_mode, motion_mode, drive_grashof;
    fn f64: attachment_angle, coupler_angle_offset, link_ratio, size;
    fn Xy = vec2: coupler_point;
    fn Xy = pt: drive_pivot;
    fn bool: crank_turns_fully;
    fn Option<f64>: stroke_angle, time_ratio;
    fn Vec<f64>: dead_positions;
});

/// A drive for a linkage (from a drive map, a pivot or the closed form).
#[pyclass(frozen, name = "Drive", module = "burmester")]
#[derive(Clone)]
pub struct PyDrive {
    pub(crate) inner: Drive,
    task: Task,
    limits: DesignLimits,
    options: DriveOptions,
    constraints: Constraints,
}

impl PyDrive {
    /// A drive found for `task`'s linkage under these limits, options and
    /// constraints (a design's, `burmester.design(..., input="motor")`).
    pub(crate) fn found(
        d: Drive,
        task: Task,
        limits: DesignLimits,
        options: DriveOptions,
        constraints: Constraints,
    ) -> Self {
        PyDrive {
            inner: d,
            task,
            limits,
            options,
            constraints,
        }
    }

    fn of(d: Drive, task: Task, ctx: &DriveContext) -> Self {
        PyDrive {
            inner: d,
            task,
            limits: *ctx.limits(),
            options: *ctx.options(),
            constraints: ctx.constraints().clone(),
        }
    }
}

fn bits(v: f64) -> u64 {
    v.to_bits()
}

#[pymethods]
impl PyDrive {
    /// Rebuilds a drive from its state (for pickling).
    #[staticmethod]
    fn _from_state(
        linkage: PySynthesizedFourBar,
        drive_pivot: PyPoint,
        attachment: PyPoint,
        state: DriveState,
        ranked: (Option<(usize, usize)>, f64, f64, Option<String>),
    ) -> PyResult<Self> {
        let (map_options, options) = state.options()?;
        let grid = point_grid(drive_pivot.0)?;
        let ctx =
            DriveContext::new(&linkage.inner, attachment.0, &grid, &map_options, &options).py()?;
        let mut d = ctx.drive(drive_pivot.0).py()?;
        (d.index, d.margin, d.score) = (ranked.0, ranked.1, ranked.2);
        d.ranked_by = ranked.3.as_deref().map(rank).transpose()?;
        Ok(PyDrive::of(d, linkage.task(), &ctx))
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> Reduced<'py> {
        let d = &self.inner;
        let args = (
            PySynthesizedFourBar::new(self.task, d.linkage),
            pt(d.drive_pivot),
            pt(d.attachment),
            drive_state(&self.limits, &self.options, &self.constraints),
            (d.index, d.margin, d.score, d.ranked_by.map(|r| r.as_str())),
        );
        reduce_to::<PyDrive>(py, "_from_state", args)
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<PyDrive>().is_ok_and(|o| {
            let (a, b) = (&o.get().inner, &self.inner);
            PySynthesizedFourBar::new(o.get().task, a.linkage)
                == PySynthesizedFourBar::new(self.task, b.linkage)
                && a.sixbar == b.sixbar
                && a.drive_pivot == b.drive_pivot
                && a.attachment == b.attachment
                && a.index == b.index
                && bits(a.margin) == bits(b.margin)
                && bits(a.score) == bits(b.score)
                && a.ranked_by == b.ranked_by
                && a.acceptable == b.acceptable
                && o.get().limits == self.limits
                && o.get().options == self.options
                && o.get().constraints == self.constraints
        })
    }

    #[getter]
    fn sixbar(&self) -> PySixBar {
        PySixBar {
            inner: self.inner.sixbar,
        }
    }
    #[getter]
    fn linkage(&self) -> PySynthesizedFourBar {
        PySynthesizedFourBar::new(self.task, self.inner.linkage)
    }
    #[getter]
    fn task(&self) -> PyTask {
        PyTask { inner: self.task }
    }
    #[getter]
    fn pose_crank_angles(&self) -> Vec<f64> {
        self.inner.pose_crank_angles.to_vec()
    }
    #[getter]
    fn ranked_by(&self) -> Option<&'static str> {
        self.inner.ranked_by.map(|r| r.as_str())
    }
    #[getter]
    fn limits(&self) -> PyDesignLimits {
        PyDesignLimits { inner: self.limits }
    }
    #[getter]
    fn swing_margin_deg(&self) -> f64 {
        self.options.swing_margin.to_degrees()
    }
    #[getter]
    fn min_transmission_deg(&self) -> f64 {
        self.inner.figures.min_transmission.to_degrees()
    }
    #[getter]
    fn drive_transmission_deg(&self) -> f64 {
        self.inner.figures.drive_transmission.to_degrees()
    }
    #[getter]
    fn motion_transmission_deg(&self) -> f64 {
        self.inner.figures.motion_transmission.to_degrees()
    }
    #[getter]
    fn time_ratio(&self) -> f64 {
        self.inner.figures.time_ratio
    }
    #[getter]
    fn link_ratio(&self) -> f64 {
        self.inner.figures.link_ratio
    }
    #[getter]
    fn size_ratio(&self) -> f64 {
        self.inner.figures.size_ratio
    }
    #[getter]
    fn swing(&self) -> Xy {
        let [a, b] = self.inner.figures.swing;
        (a, b)
    }
    #[getter]
    fn stroke(&self) -> f64 {
        self.inner.figures.stroke
    }
    #[pyo3(signature = (samples = Count(120)), text_signature = "($self, samples=120)")]
    fn turn_angles(&self, samples: Count) -> PyResult<Vec<f64>> {
        self.inner.turn_angles(samples.0).py()
    }
    fn pose_at(&self, phi: Real) -> PyResult<(f64, f64, f64)> {
        self.sixbar().pose_at(phi)
    }
    fn _repr_png_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        crate::display::repr_png(slf.as_any())
    }
    fn __repr__(&self) -> String {
        let d = &self.inner;
        let f = &d.figures;
        format!(
            "<Drive drive_pivot=({:.6}, {:.6}) min_transmission_deg={:.3} time_ratio={:.3} \
             size_ratio={:.3} acceptable={}>",
            d.drive_pivot.x,
            d.drive_pivot.y,
            f.min_transmission.to_degrees(),
            f.time_ratio,
            f.size_ratio,
            py_bool(d.acceptable)
        )
    }
}

getters!(PyDrive, inner {
    Xy = pt: drive_pivot, attachment;
    f64: stroke_start, margin, score;
    str: direction;
    bool: acceptable;
    Option<(usize, usize)>: index;
});

macro_rules! py_drive_map {
    ($($(#[$doc:meta])* $name:ident: $ty:ty = $invalid:expr,)*) => {
        /// A drive map (see the stub for the docs).
        #[pyclass(frozen, name = "DriveMap", module = "burmester")]
        pub struct PyDriveMap {
            context: DriveContext,
            task: Task,
            $($(#[$doc])* #[pyo3(get)] $name: Py<PyArray2<$ty>>,)*
        }

        impl PyDriveMap {
            /// A map whose columns NumPy allocates and `fill` writes.
            fn filled(
                py: Python<'_>,
                context: DriveContext,
                task: Task,
                fill: impl FnOnce(&DriveContext, DriveColumnsOut<'_>) -> PyResult<()>,
            ) -> PyResult<Self> {
                let shape = [context.grid().ny(), context.grid().nx()];
                $(
                    let $name = empty::<$ty>(py, &shape)?
                        .cast_into::<PyArray2<$ty>>()
                        .map_err(PyErr::from)?;
                )*
                {
                    $(let mut $name = $name.readwrite();)*
                    fill(&context, DriveColumnsOut {
                        $($name: $name.as_slice_mut()?,)*
                    })?;
                }
                $(set_readonly($name.as_any())?;)*
                Ok(PyDriveMap {
                    context,
                    task,
                    $($name: $name.unbind(),)*
                })
            }

            fn column_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
                let d = PyDict::new(py);
                $(d.set_item(stringify!($name), self.$name.clone_ref(py))?;)*
                Ok(d)
            }

            fn from_columns(
                py: Python<'_>,
                context: DriveContext,
                task: Task,
                columns: &Bound<'_, PyDict>,
            ) -> PyResult<Self> {
                let shape = (context.grid().ny(), context.grid().nx());
                $(
                    let $name: Vec<$ty> = {
                        let item = columns.get_item(stringify!($name))?.ok_or_else(|| {
                            PyTypeError::new_err(concat!("missing column ", stringify!($name)))
                        })?;
                        let a = item.cast_into::<PyArray2<$ty>>().map_err(PyErr::from)?;
                        let ro = a.readonly();
                        let v = ro.as_array();
                        if v.shape() != [shape.0, shape.1] {
                            return Err(PyTypeError::new_err(concat!(
                                "column ", stringify!($name), " does not have the map's shape"
                            )));
                        }
                        v.iter().copied().collect()
                    };
                )*
                Ok(PyDriveMap {
                    context,
                    task,
                    $($name: readonly(py, shape, $name)?,)*
                })
            }

            fn same_columns(&self, py: Python<'_>, other: &Self) -> bool {
                true $(&& same_column(py, &self.$name, &other.$name))*
            }
        }
    };
}

burmester::drive_map_columns!(py_drive_map);

ranking_method!(PyDriveMap, best_drives, ranked -> Vec<PyDrive>);

impl PyDriveMap {
    /// The best drives by `ranking`, reading the NumPy columns in place.
    fn ranked(&self, py: Python<'_>, ranking: Ranking) -> PyResult<Vec<PyDrive>> {
        let valid = self.valid.bind(py).readonly();
        let mt = self.min_transmission_rad.bind(py).readonly();
        let lr = self.link_ratio.bind(py).readonly();
        let sr = self.size_ratio.bind(py).readonly();
        let acc = self.acceptable.bind(py).readonly();
        let cols = burmester::design::DriveRankColumns {
            valid: valid.as_slice()?,
            min_transmission_rad: mt.as_slice()?,
            link_ratio: lr.as_slice()?,
            size_ratio: sr.as_slice()?,
            acceptable: acc.as_slice()?,
        };
        let ctx = &self.context;
        let drives = py.detach(|| ctx.best_drives(ranking, cols)).py()?;
        Ok(drives
            .into_iter()
            .map(|d| PyDrive::of(d, self.task, ctx))
            .collect())
    }

    fn sample(&self, j: Count, i: Count) -> PyResult<usize> {
        PyGrid {
            inner: *self.context.grid(),
        }
        .point(j, i)?;
        Ok(j.0 * self.context.grid().nx() + i.0)
    }
}

grid_map_getters!(
    PyDriveMap,
    burmester::design::DriveColumns,
    [context.grid()]
);

#[pymethods]
impl PyDriveMap {
    #[getter]
    fn linkage(&self) -> PySynthesizedFourBar {
        PySynthesizedFourBar::new(self.task, *self.context.linkage())
    }
    #[getter]
    fn attachment_ends(&self) -> (Xy, Xy) {
        let [a, b] = self.context.attachment_ends();
        (pt(a), pt(b))
    }
    #[getter]
    fn swing(&self) -> Xy {
        let [a, b] = self.context.swing();
        (a, b)
    }
    #[getter]
    fn motion_transmission_deg(&self) -> f64 {
        self.context.motion_transmission().to_degrees()
    }
    #[getter]
    fn limits(&self) -> PyDesignLimits {
        PyDesignLimits {
            inner: *self.context.limits(),
        }
    }
    #[getter]
    fn swing_margin_deg(&self) -> f64 {
        self.context.options().swing_margin.to_degrees()
    }
    #[getter]
    fn max_time_ratio(&self) -> f64 {
        self.context.options().max_time_ratio
    }
    fn point(&self, j: Count, i: Count) -> PyResult<Xy> {
        self.grid().point(j, i)
    }
    fn drive(&self, j: Count, i: Count) -> PyResult<PyDrive> {
        let k = self.sample(j, i)?;
        let d = self.context.drive_at(k).py()?;
        Ok(PyDrive::of(d, self.task, &self.context))
    }
    fn pareto_front(&self, py: Python<'_>) -> PyResult<Vec<PyDrive>> {
        self.ranked(py, Ranking::pareto_front())
    }
    /// The closed-form drive of time ratio 1 in this map's context.
    #[pyo3(signature = (beyond_first = true, drive_transmission_deg = None))]
    fn classic_drive(
        &self,
        beyond_first: bool,
        drive_transmission_deg: Option<Real>,
    ) -> PyResult<PyDrive> {
        let d = self
            .context
            .classic(
                beyond_first,
                drive_transmission_deg.map(|r| r.0.to_radians()),
            )
            .py()?;
        Ok(PyDrive::of(d, self.task, &self.context))
    }

    /// Rebuilds a map from its state (for pickling).
    #[staticmethod]
    fn _from_state(
        py: Python<'_>,
        linkage: PySynthesizedFourBar,
        attachment: PyPoint,
        grid: PyGrid,
        state: DriveState,
        columns: &Bound<'_, PyDict>,
    ) -> PyResult<Self> {
        let (map_options, options) = state.options()?;
        let context = DriveContext::new(
            &linkage.inner,
            attachment.0,
            &grid.inner,
            &map_options,
            &options,
        )
        .py()?;
        Self::from_columns(py, context, linkage.task(), columns)
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> Reduced<'py> {
        let c = &self.context;
        let args = (
            self.linkage(),
            pt(c.attachment()),
            self.grid(),
            drive_state(c.limits(), c.options(), c.constraints()),
            self.column_dict(py)?,
        );
        reduce_to::<PyDriveMap>(py, "_from_state", args)
    }

    fn __eq__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<PyDriveMap>().is_ok_and(|o| {
            o.get().context == self.context
                && o.get().task == self.task
                && self.same_columns(py, o.get())
        })
    }

    fn _repr_png_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        crate::display::repr_png(slf.as_any())
    }

    fn __repr__(&self) -> String {
        let (ny, nx) = self.shape();
        format!("<DriveMap drive pivots, {ny} x {nx}>")
    }
}

getters!(PyDriveMap, context {
    fn Xy = pt: attachment;
});

/// The drive methods of `SynthesizedFourBar`: driving it from a motor by
/// an added dyad (the Watt II six-bar).
#[pymethods]
impl PySynthesizedFourBar {
    #[doc = text_signature!(DRIVE, "drive_map($self, *grid, attachment=None", ", progress=None")]
    #[pyo3(signature = (*grid, attachment = None, progress = None,
        **options),
        text_signature = None)]
    fn drive_map(
        &self,
        py: Python<'_>,
        grid: &Bound<'_, PyTuple>,
        attachment: Option<PyPoint>,
        progress: Option<&Bound<'_, PyAny>>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PyDriveMap> {
        let args = DriveArgs::new("SynthesizedFourBar.drive_map", options, Keys::DRIVE)?;
        drive_map(self, py, grid, attachment, args, progress)
    }

    #[doc = text_signature!(DRIVE, "drive($self, drive_pivot, attachment=None, *", "")]
    #[pyo3(signature = (drive_pivot, attachment = None, **options),
        text_signature = None)]
    fn drive(
        &self,
        drive_pivot: PyPoint,
        attachment: Option<PyPoint>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PyDrive> {
        let args = DriveArgs::new("SynthesizedFourBar.drive", options, Keys::DRIVE)?;
        drive(self, drive_pivot, attachment, args)
    }

    #[doc = text_signature!(
        CLASSIC,
        "classic_drive($self, attachment=None, *, beyond_first=True, drive_transmission_deg=None",
        ""
    )]
    #[pyo3(signature = (attachment = None, *, beyond_first = true, drive_transmission_deg = None,
        **options),
        text_signature = None)]
    fn classic_drive(
        &self,
        attachment: Option<PyPoint>,
        beyond_first: bool,
        drive_transmission_deg: Option<Real>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PyDrive> {
        let args = DriveArgs::new("SynthesizedFourBar.classic_drive", options, Keys::CLASSIC)?;
        classic_drive(self, attachment, beyond_first, drive_transmission_deg, args)
    }

    #[doc = text_signature!(
        DRIVE,
        "drive_search($self, *, ratios=None, angles_deg=None, reach=4.0, samples=96",
        ", rank_by='balanced', progress=None"
    )]
    #[pyo3(signature = (*, ratios = None, angles_deg = None, reach = Real(4.0),
        samples = Count(96), rank_by = "balanced", progress = None, **options),
        text_signature = None)]
    #[allow(clippy::too_many_arguments)]
    fn drive_search(
        &self,
        py: Python<'_>,
        ratios: Option<Vec<Real>>,
        angles_deg: Option<Vec<Real>>,
        reach: Real,
        samples: Count,
        rank_by: &str,
        progress: Option<&Bound<'_, PyAny>>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Vec<PyDrive>> {
        let args = DriveArgs::new("SynthesizedFourBar.drive_search", options, Keys::DRIVE)?;
        let search = search_of(ratios, angles_deg, reach, samples);
        drive_search(self, py, search, args, rank_by, progress)
    }

    #[doc = text_signature!(DRIVE, "best_drive($self, *", ", rank_by='balanced', progress=None")]
    #[pyo3(signature = (*, rank_by = "balanced", progress = None, **options),
        text_signature = None)]
    fn best_drive(
        &self,
        py: Python<'_>,
        rank_by: &str,
        progress: Option<&Bound<'_, PyAny>>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PyDrive> {
        let args = DriveArgs::new("SynthesizedFourBar.best_drive", options, Keys::DRIVE)?;
        best_drive(self, py, args, rank_by, progress)
    }
}

/// `SynthesizedFourBar.drive_map` (the binding's method delegates here).
fn drive_map(
    this: &PySynthesizedFourBar,
    py: Python<'_>,
    grid: &Bound<'_, PyTuple>,
    attachment: Option<PyPoint>,
    args: DriveArgs,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<PyDriveMap> {
    let what = "drive_map takes a grid (or its six numbers); the rest goes by keyword";
    let g = grid_alone(grid, what)?;
    let context = args.context(this, attachment, &g)?;
    let watch = g.len() >= WATCH_MIN_SAMPLES / 16;
    PyDriveMap::filled(py, context, this.task(), |ctx, out| {
        run(py, watch, progress, None, |control| {
            ctx.map_into(out, control)
        })
    })
}

/// `SynthesizedFourBar.drive` (the binding's method delegates here).
fn drive(
    this: &PySynthesizedFourBar,
    drive_pivot: PyPoint,
    attachment: Option<PyPoint>,
    args: DriveArgs,
) -> PyResult<PyDrive> {
    let ctx = args.context(this, attachment, &point_grid(drive_pivot.0)?)?;
    let d = ctx.drive(drive_pivot.0).py()?;
    Ok(PyDrive::of(d, this.task(), &ctx))
}

/// `SynthesizedFourBar.classic_drive` (the binding's method delegates here).
fn classic_drive(
    this: &PySynthesizedFourBar,
    attachment: Option<PyPoint>,
    beyond_first: bool,
    drive_transmission_deg: Option<Real>,
    args: DriveArgs,
) -> PyResult<PyDrive> {
    let a0 = this.inner.driving.center;
    let ctx = args.context(this, attachment, &point_grid(a0)?)?;
    let d = ctx
        .classic(
            beyond_first,
            drive_transmission_deg.map(|r| r.0.to_radians()),
        )
        .py()?;
    Ok(PyDrive::of(d, this.task(), &ctx))
}

/// `SynthesizedFourBar.drive_search` (the binding's method delegates here).
fn drive_search(
    this: &PySynthesizedFourBar,
    py: Python<'_>,
    search: AttachmentSearch,
    args: DriveArgs,
    rank_by: &str,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<Vec<PyDrive>> {
    let (l, rank_by) = (this.inner, rank(rank_by)?);
    let found = run(py, true, progress, None, |control| {
        search_drives(
            &l,
            &search,
            &args.map_options,
            &args.options,
            rank_by,
            control,
        )
    })?;
    let ctx = args.context(this, None, &point_grid(l.driving.center)?)?;
    Ok(found
        .drives
        .into_iter()
        .map(|d| PyDrive::of(d, this.task(), &ctx))
        .collect())
}

/// `SynthesizedFourBar.best_drive` (the binding's method delegates here).
fn best_drive(
    this: &PySynthesizedFourBar,
    py: Python<'_>,
    args: DriveArgs,
    rank_by: &str,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<PyDrive> {
    let (l, rank_by) = (this.inner, rank(rank_by)?);
    let d = run(py, true, progress, None, |control| {
        burmester::design::best_drive(&l, &args.map_options, &args.options, rank_by, control)
    })?;
    let ctx = args.context(
        this,
        Some(PyPoint(d.attachment)),
        &point_grid(d.drive_pivot)?,
    )?;
    Ok(PyDrive::of(d, this.task(), &ctx))
}

/// The attachment search of the Python keywords (the core checks it).
fn search_of(
    ratios: Option<Vec<Real>>,
    angles_deg: Option<Vec<Real>>,
    reach: Real,
    samples: Count,
) -> AttachmentSearch {
    let d = AttachmentSearch::default();
    AttachmentSearch {
        ratios: ratios.map_or(d.ratios, |v| v.into_iter().map(|r| r.0).collect()),
        angles: angles_deg.map_or(d.angles, |v| {
            v.into_iter().map(|r| r.0.to_radians()).collect()
        }),
        reach: reach.0,
        samples: samples.0,
    }
}

/// `burmester.unit_time_ratio_crank_rocker`: the closed form.
#[pyfunction]
pub(crate) fn unit_time_ratio_crank_rocker(
    rocker: Real,
    swing_deg: Real,
    min_transmission_deg: Real,
) -> PyResult<(f64, f64, f64, f64)> {
    let d = burmester::design::CrankRockerDesign::unit_time_ratio(
        rocker.0,
        swing_deg.0.to_radians(),
        min_transmission_deg.0.to_radians(),
    )
    .py()?;
    Ok((d.ground, d.crank, d.coupler, d.rocker))
}

/// A drive context's options as plain data (for pickling a drive or a drive
/// map): the limits, the drive's options (swing margin, time ratio) and the
/// constraints, written by [`drive_state`].
#[derive(FromPyObject)]
struct DriveState(
    PyDesignLimits,
    (f64, f64),
    (Option<Vec<PyPoint>>, Vec<Vec<PyPoint>>, f64, usize),
);

impl DriveState {
    /// The checked map options and the drive's options.
    fn options(self) -> PyResult<(MapOptions, DriveOptions)> {
        let DriveState(limits, (swing_margin, max_time_ratio), constraints) = self;
        let map_options = MapOptions::new(&limits.inner, &constraints_of(constraints)).py()?;
        let options = DriveOptions {
            swing_margin,
            max_time_ratio,
        };
        Ok((map_options, options))
    }
}

/// What [`DriveState`] reads back.
fn drive_state(
    limits: &DesignLimits,
    options: &DriveOptions,
    constraints: &Constraints,
) -> (PyDesignLimits, (f64, f64), ConstraintState) {
    (
        PyDesignLimits { inner: *limits },
        (options.swing_margin, options.max_time_ratio),
        constraint_state(constraints),
    )
}
