//! `burmester._burmester._atlas_tile`: one tile (rows of driven centers) of
//! the pivot-pair atlas (the core's `design::atlas`). The assembly, the
//! `PivotAtlas` class and the Dask glue are pure Python
//! (`burmester/atlas.py`).

use burmester::{AtlasCell, RankBy};
use numpy::IntoPyArray;
use numpy::ndarray::{Array2, Array3};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::conv::{Count, PyPoint, Real};
use crate::design::{MapOptions, PyDesignLimits};
use crate::errors::IntoPy;
use crate::geom::PyGrid;
use crate::run::{WATCH_MIN_SAMPLES, run};
use crate::synthesis::PyTask;

/// The cells of rows `row_start..row_end` of the driven grid, as a dict of
/// NumPy arrays of shape `(rows, nx)` (`best_driving` and `best_index`:
/// `(rows, nx, 2)`), computed on `threads` rayon threads (default: the
/// global pool).
#[pyfunction]
#[pyo3(signature = (task, driven, row_start, row_end, driving, *, limits = None,
    min_transmission_deg = None, max_link_ratio = None, input = None, base_plate = None,
    obstacles = None, link_width = Real(0.0), travel_samples = Count(64), rank_by = "balanced",
    envelope = None, threads = None, progress = None),
    text_signature = "(task, driven, row_start, row_end, driving, *, limits=None, \
    min_transmission_deg=None, max_link_ratio=None, input=None, base_plate=None, obstacles=None, \
    link_width=0.0, travel_samples=64, rank_by='balanced', envelope=None, threads=None, \
    progress=None)")]
#[allow(clippy::too_many_arguments)]
pub(crate) fn _atlas_tile<'py>(
    py: Python<'py>,
    task: &PyTask,
    driven: &PyGrid,
    row_start: Count,
    row_end: Count,
    driving: &PyGrid,
    limits: Option<PyDesignLimits>,
    min_transmission_deg: Option<Real>,
    max_link_ratio: Option<Real>,
    input: Option<&str>,
    base_plate: Option<Vec<PyPoint>>,
    obstacles: Option<Vec<Vec<PyPoint>>>,
    link_width: Real,
    travel_samples: Count,
    rank_by: &str,
    envelope: Option<Vec<PyPoint>>,
    threads: Option<Count>,
    progress: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let rank_by = rank_by.parse::<RankBy>().py()?;
    let mut opts = MapOptions::new(
        limits,
        min_transmission_deg,
        max_link_ratio,
        input,
        base_plate,
        obstacles,
        link_width,
        travel_samples,
    )?;
    opts.constraints.envelope = envelope.map(|v| v.into_iter().map(|p| p.0).collect());
    let (t, dn, dv) = (task.inner, driven.inner, driving.inner);
    let (r0, r1) = (row_start.0, row_end.0);
    let pool = match threads {
        Some(Count(n)) => Some(
            rayon::ThreadPoolBuilder::new()
                .num_threads(n.max(1))
                .build()
                .map_err(|e| PyValueError::new_err(format!("cannot start {n} threads: {e}")))?,
        ),
        None => None,
    };
    let samples = r1.saturating_sub(r0) * dn.nx() * dv.len();
    let cells = run(
        py,
        samples >= WATCH_MIN_SAMPLES,
        progress,
        None,
        |control| {
            let work = || {
                t.pivot_atlas_rows(
                    &dn,
                    r0..r1,
                    &dv,
                    &opts.limits,
                    &opts.constraints,
                    rank_by,
                    control,
                )
            };
            match &pool {
                Some(p) => p.install(work),
                None => work(),
            }
        },
    )?;
    let (rows, nx) = (r1 - r0, dn.nx());
    let col = |f: &dyn Fn(&AtlasCell) -> f64| -> Array2<f64> {
        Array2::from_shape_vec((rows, nx), cells.iter().map(f).collect()).expect("one per cell")
    };
    let d = PyDict::new(py);
    let valid = Array2::from_shape_vec((rows, nx), cells.iter().map(|c| c.valid).collect())
        .expect("one per cell");
    let ints = |f: &dyn Fn(&AtlasCell) -> i64| -> Array2<i64> {
        Array2::from_shape_vec((rows, nx), cells.iter().map(f).collect()).expect("one per cell")
    };
    d.set_item("valid", valid.into_pyarray(py))?;
    d.set_item("count", ints(&|c| c.count as i64).into_pyarray(py))?;
    d.set_item(
        "branch_free",
        ints(&|c| c.branch_free as i64).into_pyarray(py),
    )?;
    let best = |f: fn(&burmester::AtlasBest) -> f64| {
        col(&|c: &AtlasCell| c.best.as_ref().map_or(f64::NAN, f)).into_pyarray(py)
    };
    d.set_item(
        "best_transmission_rad",
        best(|b| f64::from(b.min_transmission_rad)),
    )?;
    d.set_item("best_link_ratio", best(|b| f64::from(b.link_ratio)))?;
    d.set_item("best_margin", best(|b| b.margin))?;
    d.set_item("best_size_ratio", best(|b| f64::from(b.size_ratio)))?;
    d.set_item("best_score", best(|b| b.score))?;
    let mut driving_xy = Vec::with_capacity(rows * nx * 2);
    let mut index = Vec::with_capacity(rows * nx * 2);
    for c in &cells {
        match &c.best {
            Some(b) => {
                driving_xy.extend([b.driving.x, b.driving.y]);
                index.extend([b.index.0 as i64, b.index.1 as i64]);
            }
            None => {
                driving_xy.extend([f64::NAN, f64::NAN]);
                index.extend([-1, -1]);
            }
        }
    }
    d.set_item(
        "best_driving",
        Array3::from_shape_vec((rows, nx, 2), driving_xy)
            .expect("two per cell")
            .into_pyarray(py),
    )?;
    d.set_item(
        "best_index",
        Array3::from_shape_vec((rows, nx, 2), index)
            .expect("two per cell")
            .into_pyarray(py),
    )?;
    Ok(d)
}
