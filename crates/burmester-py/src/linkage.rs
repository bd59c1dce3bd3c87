//! `burmester.FourBar`, `burmester.Configuration` and
//! `burmester.LinkageFigures` (the core's `linkage`).
//!
//! The naming rule of the whole package: a **property** is a value the
//! object holds or derives without arguments and without failing; anything
//! that takes an argument, can fail, or does real work is a **method**.

use burmester::{
    AssemblyMode, Configuration, Direction, FourBar, Grashof, InputRange, InvertedSliderCrank,
    LinkageFigures, PerPose, Point2, SliderCrank, Vector2,
};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::conv::{Arrays, FloatArray, PyPoint, Real, fill_arrays, pt, py_bool, write_points};
use crate::errors::{IntoPy, invalid};
use crate::getters::getters;
use crate::pickle::{Reduced, new_by_name, reduce_to};

/// Parses `"open"` / `"crossed"`.
pub(crate) fn mode(s: &str) -> PyResult<AssemblyMode> {
    s.parse::<AssemblyMode>().py()
}

/// A linkage driven by a crank angle whose coupler carries a point: the
/// four-bar, the slider-crank and the inverted slider-crank (the core's
/// `coupler_path` of each).
pub(crate) trait CouplerPath: Copy + Sync {
    /// The coupler point `local` (coupler frame) at the crank angles
    /// `theta2s` in `mode`.
    fn path<'a>(
        &'a self,
        local: Vector2<f64>,
        theta2s: &'a [f64],
        mode: AssemblyMode,
    ) -> impl Iterator<Item = burmester::Result<Point2<f64>>> + 'a;
}

/// [`CouplerPath`] for core linkage types by their `coupler_path`.
macro_rules! coupler_path_of {
    ($($linkage:ty),*) => {$(
        impl CouplerPath for $linkage {
            fn path<'a>(
                &'a self,
                local: Vector2<f64>,
                theta2s: &'a [f64],
                mode: AssemblyMode,
            ) -> impl Iterator<Item = burmester::Result<Point2<f64>>> + 'a {
                self.coupler_path(local, theta2s.iter().copied(), mode)
            }
        }
    )*};
}

coupler_path_of!(FourBar, SliderCrank, InvertedSliderCrank);

/// `coupler_point(theta2, point, mode)` of a linkage's class.
pub(crate) fn coupler_point(
    linkage: &impl CouplerPath,
    theta2: Real,
    point: PyPoint,
    mode: &str,
) -> PyResult<(f64, f64)> {
    let (m, angle) = (self::mode(mode)?, [theta2.0]);
    let mut it = linkage.path(point.0.coords, &angle, m);
    it.next().expect("one angle in, one point out").map(pt).py()
}

/// `coupler_path(point, theta2s, mode)` of a linkage's class: `(xs, ys,
/// ok)` over the crank angles (NaN and False where the loop does not
/// close); a bad point is an exception, not a path of NaN.
pub(crate) fn coupler_path<'py>(
    linkage: &impl CouplerPath,
    py: Python<'py>,
    point: PyPoint,
    theta2s: FloatArray<'py>,
    mode: &str,
) -> PyResult<Arrays<'py>> {
    let m = self::mode(mode)?;
    let local = point.0.coords;
    if let Some(Err(e @ burmester::Error::InvalidInput(_))) = linkage.path(local, &[0.0], m).next()
    {
        return Err(e).py();
    }
    let (flat, shape) = (theta2s.values(), theta2s.shape());
    fill_arrays(py, shape, |xs, ys, ok| {
        write_points(linkage.path(local, flat, m), xs, ys, ok);
    })
}

/// `coupler_point` and `coupler_path` of the class `$cls` of a linkage
/// driven by a crank angle whose coupler carries a point (a
/// [`CouplerPath`] held in `inner`), by [`coupler_point`] and
/// [`coupler_path`].
macro_rules! coupler_methods {
    ($cls:ty) => {
        #[::pyo3::pymethods]
        impl $cls {
            #[pyo3(signature = (theta2, point, mode = "open"))]
            fn coupler_point(
                &self,
                theta2: $crate::conv::Real,
                point: $crate::conv::PyPoint,
                mode: &str,
            ) -> ::pyo3::PyResult<(f64, f64)> {
                $crate::linkage::coupler_point(&self.inner, theta2, point, mode)
            }

            /// `(xs, ys, ok)` over the crank angles (NaN and False where the loop
            /// does not close).
            #[pyo3(signature = (point, theta2s, mode = "open"))]
            fn coupler_path<'py>(
                &self,
                py: ::pyo3::Python<'py>,
                point: $crate::conv::PyPoint,
                theta2s: $crate::conv::FloatArray<'py>,
                mode: &str,
            ) -> ::pyo3::PyResult<$crate::conv::Arrays<'py>> {
                $crate::linkage::coupler_path(&self.inner, py, point, theta2s, mode)
            }
        }
    };
}

pub(crate) use coupler_methods;

/// The repr of a solved position of a crank-driven linkage,
/// `name(theta2=.., theta3=.., <along>=.., mode='..', toggle=..)`, with
/// `along` the name and value of its output (`theta4`, `slider`, `slot`).
pub(crate) fn configuration_repr(
    name: &str,
    [theta2, theta3]: [f64; 2],
    (along, value): (&str, f64),
    mode: AssemblyMode,
    toggle: bool,
) -> String {
    format!(
        "{name}(theta2={theta2:?}, theta3={theta3:?}, {along}={value:?}, mode='{}', toggle={})",
        mode.as_str(),
        py_bool(toggle)
    )
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

#[pymethods]
impl PyFourBar {
    #[new]
    #[pyo3(signature = (*args, ground = None, crank = None, coupler = None, rocker = None,
        origin = PyPoint(Point2::origin()), ground_angle = Real(0.0)),
        text_signature = "(*, ground, crank, coupler, rocker, origin=(0.0, 0.0), ground_angle=0.0)")]
    #[allow(clippy::too_many_arguments)]
    fn new(
        args: &Bound<'_, PyTuple>,
        ground: Option<Real>,
        crank: Option<Real>,
        coupler: Option<Real>,
        rocker: Option<Real>,
        origin: PyPoint,
        ground_angle: Real,
    ) -> PyResult<Self> {
        if !args.is_empty() {
            return Err(PyTypeError::new_err(format!(
                "FourBar takes its lengths by name, got {} positional arguments: pass \
                 FourBar(ground=..., crank=..., coupler=..., rocker=...) (books order the four \
                 links differently)",
                args.len()
            )));
        }
        let (Some(ground), Some(crank), Some(coupler), Some(rocker)) =
            (ground, crank, coupler, rocker)
        else {
            return Err(PyTypeError::new_err(
                "FourBar needs all four lengths: FourBar(ground=..., crank=..., coupler=..., \
                 rocker=...)",
            ));
        };
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
    fn lengths(&self) -> (f64, f64, f64, f64) {
        let [a, b, c, d] = self.inner.lengths();
        (a, b, c, d)
    }

    #[pyo3(signature = (theta2, mode = "open"))]
    fn solve(&self, theta2: Real, mode: &str) -> PyResult<(f64, f64)> {
        let c = self.inner.solve(theta2.0, self::mode(mode)?).py()?;
        Ok((c.theta3, c.theta4))
    }

    #[pyo3(signature = (theta2, mode = "open"))]
    fn configuration(&self, theta2: Real, mode: &str) -> PyResult<PyConfiguration> {
        let c = self.inner.solve(theta2.0, self::mode(mode)?).py()?;
        Ok(PyConfiguration {
            inner: c,
            fourbar: self.inner,
        })
    }

    #[pyo3(signature = (theta2s, mode = "open"))]
    fn solve_many<'py>(
        &self,
        py: Python<'py>,
        theta2s: FloatArray<'py>,
        mode: &str,
    ) -> PyResult<Arrays<'py>> {
        let mode = self::mode(mode)?;
        let (flat, shape) = (theta2s.values(), theta2s.shape());
        let fb = self.inner;
        // Every element is written (NaN and false where the loop does not
        // close); the lengths agree by construction, so this cannot fail.
        fill_arrays(py, shape, |t3, t4, ok| {
            let _ = fb.solve_into(flat, mode, t3, t4, ok);
        })
    }

    /// `None` when the input turns fully, else a list of `(start, end)` arcs.
    #[getter]
    fn input_range(&self) -> Option<Vec<(f64, f64)>> {
        match self.inner.input_range() {
            InputRange::Full => None,
            r => {
                let (arcs, n) = r.arcs_array();
                Some(arcs[..n].iter().map(|a| (a.start, a.end)).collect())
            }
        }
    }

    #[getter]
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

    /// A picture for Jupyter: PNG bytes drawn by `burmester._display`, or
    /// None without matplotlib.
    fn _repr_png_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        crate::display::repr_png(slf.as_any())
    }

    fn __repr__(&self) -> String {
        let [l1, l2, l3, l4] = self.inner.lengths();
        let o = self.inner.input_pivot();
        let a = self.inner.ground_angle();
        let lengths = format!("ground={l1:?}, crank={l2:?}, coupler={l3:?}, rocker={l4:?}");
        if o == Point2::origin() && a == 0.0 {
            format!("FourBar({lengths})")
        } else {
            format!(
                "FourBar({lengths}, origin=({:?}, {:?}), ground_angle={a:?})",
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

new_by_name!(PyFourBar, f => {
    "ground": f.ground(),
    "crank": f.crank(),
    "coupler": f.coupler(),
    "rocker": f.rocker(),
    "origin": pt(f.input_pivot()),
    "ground_angle": f.ground_angle(),
});

coupler_methods!(PyFourBar);

getters!(PyFourBar, inner {
    fn f64: ground, crank, coupler, rocker, ground_angle, link_ratio, grashof_margin;
    fn (f64, f64) = pt: input_pivot, output_pivot;
    fn str: grashof;
    fn bool: input_turns_fully;
});

/// One solved position of a four-bar.
#[pyclass(frozen, name = "Configuration", module = "burmester")]
#[derive(Clone)]
pub struct PyConfiguration {
    pub(crate) inner: Configuration,
    /// The linkage it is a position of (for pickling).
    fourbar: FourBar,
}

#[pymethods]
impl PyConfiguration {
    fn __repr__(&self) -> String {
        let c = &self.inner;
        configuration_repr(
            "Configuration",
            [c.theta2, c.theta3],
            ("theta4", c.theta4),
            c.mode,
            c.toggle,
        )
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PyConfiguration>()
            .map(|o| o.get().inner == self.inner && o.get().fourbar == self.fourbar)
            .unwrap_or(false)
    }

    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, (f64, &'static str))> {
        let fb = Bound::new(py, PyFourBar::from(self.fourbar))?;
        Ok((
            fb.getattr("configuration")?,
            (self.inner.theta2, self.inner.mode.as_str()),
        ))
    }
}

getters!(PyConfiguration, inner {
    f64: theta2, theta3, theta4;
    str: mode;
    bool: toggle;
    fn f64: transmission_angle, coupler_rocker_angle;
});

/// What a designer checks of one linkage that must pass a task's poses.
#[pyclass(frozen, eq, name = "LinkageFigures", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PyLinkageFigures {
    pub(crate) inner: LinkageFigures,
}

type Modes = Vec<Option<&'static str>>;

#[pymethods]
impl PyLinkageFigures {
    /// Rebuilds figures from their fields (for pickling).
    #[staticmethod]
    #[allow(clippy::too_many_arguments)]
    fn _from_fields(
        lengths: [f64; 4],
        grashof: &str,
        input_full: bool,
        modes: Vec<Option<String>>,
        direction: &str,
        one_circuit: bool,
        min_transmission: f64,
        link_ratio: f64,
    ) -> PyResult<Self> {
        let grashof = Grashof::ALL
            .into_iter()
            .find(|g| g.as_str() == grashof)
            .ok_or_else(|| invalid("unknown_name", format!("unknown Grashof type {grashof:?}")))?;
        let direction = Direction::ALL
            .into_iter()
            .find(|d| d.as_str() == direction)
            .ok_or_else(|| invalid("unknown_name", format!("unknown direction {direction:?}")))?;
        let modes = modes
            .iter()
            .map(|m| m.as_deref().map(mode).transpose())
            .collect::<PyResult<Vec<_>>>()?;
        if !(1..=burmester::geom::MAX_POSES).contains(&modes.len()) {
            return Err(invalid("count_out_of_range", "figures need 1 to 5 modes"));
        }
        // What the lengths decide must be what they decide, and the rest
        // must hang together (figures no linkage has are refused).
        let fb = FourBar::new(lengths[0], lengths[1], lengths[2], lengths[3]).py()?;
        let bad = |what: String| {
            Err(invalid(
                "inconsistent_state",
                format!(
                    "unpickling linkage figures: {what}; the pickle was damaged or not made by \
                     burmester: compute the figures again"
                ),
            ))
        };
        if fb.grashof() != grashof {
            return bad(format!(
                "the Grashof type {:?} is not the lengths' ({:?})",
                grashof.as_str(),
                fb.grashof().as_str()
            ));
        }
        if fb.input_turns_fully() != input_full {
            return bad(format!("input_full {input_full} is not the lengths'"));
        }
        if link_ratio.to_bits() != fb.link_ratio().to_bits() {
            return bad(format!(
                "the link ratio {link_ratio} is not the lengths' ({})",
                fb.link_ratio()
            ));
        }
        if input_full && !one_circuit {
            return bad("an input that turns fully on two circuits".to_owned());
        }
        if !one_circuit && direction != Direction::None {
            return bad(format!(
                "a direction {:?} on two circuits",
                direction.as_str()
            ));
        }
        let angle_ok = (0.0..=core::f64::consts::FRAC_PI_2).contains(&min_transmission);
        if (direction == Direction::None) != min_transmission.is_nan()
            || !(min_transmission.is_nan() || angle_ok)
        {
            return bad(format!(
                "the minimum transmission angle {min_transmission} with the direction {:?} (an \
                 angle in [0, pi/2] with a direction, NaN without)",
                direction.as_str()
            ));
        }
        Ok(PyLinkageFigures {
            inner: LinkageFigures {
                lengths,
                grashof,
                input_full,
                modes: PerPose::from_slice(&modes),
                direction,
                one_circuit,
                min_transmission,
                link_ratio,
            },
        })
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> Reduced<'py> {
        let f = &self.inner;
        let args = (
            f.lengths,
            f.grashof.as_str(),
            f.input_full,
            self.modes(),
            f.direction.as_str(),
            f.one_circuit,
            f.min_transmission,
            f.link_ratio,
        );
        reduce_to::<PyLinkageFigures>(py, "_from_fields", args)
    }

    /// `(ground, crank, coupler, rocker)`.
    #[getter]
    fn lengths(&self) -> (f64, f64, f64, f64) {
        let [a, b, c, d] = self.inner.lengths;
        (a, b, c, d)
    }
    #[getter]
    fn modes(&self) -> Modes {
        self.inner
            .modes
            .iter()
            .map(|m| m.map(|m| m.as_str()))
            .collect()
    }
    #[getter]
    fn min_transmission_deg(&self) -> Option<f64> {
        let t = self.inner.min_transmission;
        (!t.is_nan()).then(|| t.to_degrees())
    }
    fn __repr__(&self) -> String {
        let f = &self.inner;
        format!(
            "<LinkageFigures {} direction={} branch_free={} min_transmission_deg={} link_ratio={:.3}>",
            f.grashof,
            f.direction,
            py_bool(f.branch_free()),
            self.min_transmission_deg()
                .map_or("None".to_owned(), |t| format!("{t:.3}")),
            f.link_ratio
        )
    }
}

getters!(PyLinkageFigures, inner {
    str: grashof, direction;
    bool: input_full, one_circuit;
    f64: link_ratio;
    fn f64: grashof_margin;
    fn bool: branch_free, feasible;
});
