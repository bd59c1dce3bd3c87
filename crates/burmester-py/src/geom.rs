//! `burmester.Grid` and `burmester.Conic` (the core's `geom`).

use burmester::{Conic, Grid, Vector2, Viewport};
use numpy::{PyArray1, PyArrayDyn};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyList, PySequence, PyTuple};

use crate::conv::{Count, FloatArray, PyPoint, Real, pt, slice_mut, writer, zeros};
use crate::errors::{IntoPy, invalid};
use crate::getters::getters;
use crate::pickle::{Reduced, reduce_to};

type Xy = (f64, f64);

/// A grid of sample points at cell centers over a viewport.
#[pyclass(frozen, eq, from_py_object, name = "Grid", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PyGrid {
    pub(crate) inner: Grid,
}

/// The sample coordinates of a grid's columns and rows.
type Axes<'py> = (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>);

#[pymethods]
impl PyGrid {
    #[new]
    fn new(xmin: Real, xmax: Real, ymin: Real, ymax: Real, nx: Count, ny: Count) -> PyResult<Self> {
        Grid::from_bounds(xmin.0, xmax.0, ymin.0, ymax.0, nx.0, ny.0)
            .map(|inner| PyGrid { inner })
            .py()
    }

    #[getter]
    fn extent(&self) -> (f64, f64, f64, f64) {
        extent(&self.inner)
    }
    #[getter]
    fn shape(&self) -> (usize, usize) {
        (self.inner.ny(), self.inner.nx())
    }
    #[getter]
    fn size(&self) -> usize {
        self.inner.len()
    }

    /// `(xs, ys)`: the sample coordinates of the columns and of the rows.
    fn cell_centers<'py>(&self, py: Python<'py>) -> PyResult<Axes<'py>> {
        let g = &self.inner;
        // NumPy allocates them (a failed allocation is a MemoryError).
        let axis = |n: usize, at: &dyn Fn(usize) -> f64| -> PyResult<Bound<'py, PyArray1<f64>>> {
            let a = crate::conv::empty::<f64>(py, &[n])?;
            {
                let mut w = crate::conv::writer(&a)?;
                for (k, o) in crate::conv::slice_mut(&mut w).iter_mut().enumerate() {
                    *o = at(k);
                }
            }
            a.cast_into::<PyArray1<f64>>().map_err(PyErr::from)
        };
        Ok((axis(g.nx(), &|i| g.x(i))?, axis(g.ny(), &|j| g.y(j))?))
    }

    /// The sample `[j, i]`: `(x_i, y_j)`.
    pub(crate) fn point(&self, j: Count, i: Count) -> PyResult<Xy> {
        let (j, i) = (j.0, i.0);
        let g = &self.inner;
        if i >= g.nx() || j >= g.ny() {
            return Err(invalid(
                "grid_index",
                format!(
                    "sample ({j}, {i}) is outside the grid of shape ({}, {}); pass indices within it",
                    g.ny(),
                    g.nx()
                ),
            ));
        }
        Ok(pt(g.point(i, j)))
    }

    /// The sample `[j, i]` nearest to a point (clamped to the grid).
    fn nearest(&self, point: PyPoint) -> PyResult<(usize, usize)> {
        self.inner.nearest(point.0).py()
    }

    fn __getnewargs__(&self) -> (f64, f64, f64, f64, usize, usize) {
        let (a, b, c, d) = extent(&self.inner);
        (a, b, c, d, self.inner.nx(), self.inner.ny())
    }

    fn __repr__(&self) -> String {
        let (a, b, c, d) = extent(&self.inner);
        format!(
            "Grid({a:?}, {b:?}, {c:?}, {d:?}, {}, {})",
            self.inner.nx(),
            self.inner.ny()
        )
    }
}

getters!(PyGrid, [inner.viewport()] {
    f64: xmin, xmax, ymin, ymax;
});

getters!(PyGrid, inner {
    fn usize: nx, ny;
    fn f64: dx, dy;
});

/// `(xmin, xmax, ymin, ymax)` of a grid's view.
pub(crate) fn extent(g: &Grid) -> (f64, f64, f64, f64) {
    let v = g.viewport();
    (v.xmin, v.xmax, v.ymin, v.ymax)
}

/// What every map over a grid of samples offers Python: `columns` (the
/// names of `$columns`, in order), `grid`, `extent` and `shape`, of the
/// map `$cls` whose grid is `self.<path>` (a `Grid` or a `&Grid`, such as
/// `[context.grid()]`).
macro_rules! grid_map_getters {
    ($cls:ty, $columns:ty, [$($path:tt)*]) => {
        impl $cls {
            /// The grid of its samples.
            fn samples_grid(&self) -> ::burmester::Grid {
                ::burmester::Grid::clone(&self.$($path)*)
            }
        }

        #[::pyo3::pymethods]
        impl $cls {
            /// The names of the columns, in order.
            #[classattr]
            fn columns() -> Vec<&'static str> {
                <$columns>::NAMES.to_vec()
            }
            #[getter]
            fn grid(&self) -> $crate::geom::PyGrid {
                $crate::geom::PyGrid {
                    inner: self.samples_grid(),
                }
            }
            #[getter]
            fn extent(&self) -> (f64, f64, f64, f64) {
                $crate::geom::extent(&self.samples_grid())
            }
            #[getter]
            fn shape(&self) -> (usize, usize) {
                let g = self.samples_grid();
                (g.ny(), g.nx())
            }
        }
    };
}

pub(crate) use grid_map_getters;

/// A grid from the leading positional arguments of a call: a `Grid`, its
/// six numbers `xmin, xmax, ymin, ymax, nx, ny` as one tuple or list (as
/// `pivot_atlas` takes them), or the six numbers one by one. Returns the
/// grid and how many arguments it took.
pub(crate) fn grid_arg(args: &Bound<'_, PyTuple>) -> PyResult<(Grid, usize)> {
    let usage = || {
        PyTypeError::new_err(
            "expected a grid: a burmester.Grid, or its six numbers xmin, xmax, ymin, ymax, nx, ny \
             (as a tuple or one by one)",
        )
    };
    let first = args.get_item(0).map_err(|_| usage())?;
    if let Ok(g) = first.cast::<PyGrid>() {
        return Ok((g.get().inner, 1));
    }
    if first.is_instance_of::<PyTuple>() || first.is_instance_of::<PyList>() {
        let six = first.cast::<PySequence>()?;
        if six.len()? != 6 {
            return Err(usage());
        }
        return Ok((six_numbers(|k| six.get_item(k))?, 1));
    }
    if args.len() < 6 {
        return Err(usage());
    }
    Ok((six_numbers(|k| args.get_item(k))?, 6))
}

/// The grid of a map's positional arguments `grid` (a `Grid`, its tuple
/// or its six numbers) and nothing else; a `TypeError` saying `what` the
/// method takes otherwise.
pub(crate) fn grid_alone(grid: &Bound<'_, PyTuple>, what: &'static str) -> PyResult<Grid> {
    let (g, used) = grid_arg(grid)?;
    if used != grid.len() {
        return Err(PyTypeError::new_err(what));
    }
    Ok(g)
}

/// The grid of six numbers `xmin, xmax, ymin, ymax, nx, ny`, the `k`-th
/// from `item(k)`.
fn six_numbers<'py>(item: impl Fn(usize) -> PyResult<Bound<'py, PyAny>>) -> PyResult<Grid> {
    let num = |k: usize| -> PyResult<f64> { Ok(item(k)?.extract::<Real>()?.0) };
    let count = |k: usize| -> PyResult<usize> { Ok(item(k)?.extract::<Count>()?.0) };
    Grid::from_bounds(num(0)?, num(1)?, num(2)?, num(3)?, count(4)?, count(5)?).py()
}

/// A conic `A x^2 + B x y + C y^2 + D x + E y + F = 0`.
#[pyclass(frozen, eq, name = "Conic", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PyConic {
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

    /// Rebuilds a conic from its exact stored form (for pickling).
    #[staticmethod]
    fn _from_parts(
        q: [f64; 6],
        origin: PyPoint,
        scale: Real,
        known: Option<PyPoint>,
    ) -> PyResult<Self> {
        Conic::from_parts(q, origin.0, scale.0, known.map(|k| k.0.coords))
            .map(|inner| PyConic { inner })
            .py()
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> Reduced<'py> {
        let (q, o, s, k) = self.inner.to_parts();
        let args = (q, pt(o), s, k.map(|k| (k.x, k.y)));
        reduce_to::<PyConic>(py, "_from_parts", args)
    }

    #[getter]
    fn coefficients(&self) -> (f64, f64, f64, f64, f64, f64) {
        let [a, b, c, d, e, f] = self.inner.coefficients();
        (a, b, c, d, e, f)
    }

    #[getter]
    fn center(&self) -> Option<Xy> {
        self.inner.center().map(pt)
    }

    #[getter]
    fn asymptotes(&self) -> Option<(Xy, Xy, Xy)> {
        self.inner
            .asymptotes()
            .map(|[a, b]| (pt(a.point), vec2(a.direction), vec2(b.direction)))
    }

    fn evaluate(&self, point: PyPoint) -> PyResult<f64> {
        self.inner.try_evaluate(point.0).py()
    }

    fn __call__(&self, point: PyPoint) -> PyResult<f64> {
        self.evaluate(point)
    }

    fn evaluate_many<'py>(
        &self,
        py: Python<'py>,
        points: FloatArray<'py>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let pts = crate::conv::points(&points)?;
        let out = zeros::<f64>(py, &pts.lead)?;
        {
            let mut w = writer(&out)?;
            let out_s = slice_mut(&mut w);
            let c = self.inner;
            py.detach(|| -> burmester::Result<()> {
                for (p, v) in pts.iter().zip(out_s) {
                    *v = c.try_evaluate(p)?;
                }
                Ok(())
            })
            .py()?;
        }
        Ok(out)
    }

    fn side(&self, point: PyPoint) -> PyResult<i8> {
        self.inner.try_evaluate(point.0).py()?;
        Ok(self.inner.side(point.0))
    }

    fn distance(&self, point: PyPoint) -> PyResult<f64> {
        self.inner.try_evaluate(point.0).py()?;
        Ok(self.inner.distance_estimate(point.0))
    }

    fn __repr__(&self) -> String {
        let [a, b, c, d, e, f] = self.inner.coefficients();
        format!(
            "Conic({a:?}, {b:?}, {c:?}, {d:?}, {e:?}, {f:?})  # {}",
            self.inner.kind()
        )
    }
}

crate::curves::polylines_method!(PyConic, Conic::polylines);

getters!(PyConic, inner {
    fn str: kind;
    fn f64: axis_angle;
});

/// `(x, y)` of a vector for Python.
pub(crate) fn vec2(v: Vector2<f64>) -> Xy {
    (v.x, v.y)
}

/// The part of the line `point + t direction` inside the rectangle
/// `extent = (xmin, xmax, ymin, ymax)`, as its two ends, or None.
#[pyfunction]
pub(crate) fn clip_line(
    point: PyPoint,
    direction: PyPoint,
    extent: &Bound<'_, PyAny>,
) -> PyResult<Option<(Xy, Xy)>> {
    let usage = |what: String| {
        PyTypeError::new_err(format!(
            "expected an extent (xmin, xmax, ymin, ymax): a sequence of four numbers, got {what}"
        ))
    };
    let e: Vec<Real> = extent.extract().map_err(|e: PyErr| {
        if e.is_instance_of::<crate::errors::InvalidInputError>(extent.py()) {
            return e;
        }
        usage(
            extent
                .get_type()
                .name()
                .map_or("an object".into(), |n| n.to_string()),
        )
    })?;
    let [xmin, xmax, ymin, ymax] = e[..] else {
        return Err(usage(format!("{} numbers", e.len())));
    };
    let vp = Viewport::new(xmin.0, xmax.0, ymin.0, ymax.0).py()?;
    let line = burmester::Line {
        point: point.0,
        direction: direction.0.coords,
    };
    Ok(line.clip(&vp).map(|(a, b)| (pt(a), pt(b))))
}
