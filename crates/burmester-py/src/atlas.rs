//! `burmester._burmester._atlas_tile`: one tile (rows of driven centers) of
//! the pivot-pair atlas (the core's `design::atlas`). The assembly, the
//! `PivotAtlas` class and the Dask glue are pure Python
//! (`burmester/atlas.py`).

use burmester::{AtlasCell, RankBy};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::classes::PyTask;
use crate::conv::{Count, PyPoint};
use crate::conv::{empty, slice_mut, writer};
use crate::errors::IntoPy;
use crate::geom::PyGrid;
use crate::options::{Keys, Keywords, text_signature};
use crate::run::{WATCH_MIN_SAMPLES, run_in};

#[doc = text_signature!(
    MAP,
    "_atlas_tile(task, driven, row_start, row_end, driving, *",
    ", rank_by='balanced', envelope=None, threads=None, progress=None",
    doc
)]
/// The cells of rows `row_start..row_end` of the driven grid, as a dict of
/// NumPy arrays of shape `(rows, nx)` (`best_driving` and `best_index`:
/// `(rows, nx, 2)`), computed on `threads` rayon threads (default: the
/// global pool).
#[pyfunction]
#[pyo3(signature = (task, driven, row_start, row_end, driving, *, rank_by = "balanced",
    envelope = None, threads = None, progress = None, **options),
    text_signature = None)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn _atlas_tile<'py>(
    py: Python<'py>,
    task: &PyTask,
    driven: &PyGrid,
    row_start: Count,
    row_end: Count,
    driving: &PyGrid,
    rank_by: &str,
    envelope: Option<Vec<PyPoint>>,
    threads: Option<Count>,
    progress: Option<&Bound<'py, PyAny>>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let rank_by = rank_by.parse::<RankBy>().py()?;
    let mut keywords = Keywords::from_kwargs("_atlas_tile", options, Keys::MAP)?;
    keywords.constraints.envelope = envelope.map(|v| v.into_iter().map(|p| p.0).collect());
    let opts = keywords.checked()?;
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
    // Progress counts the driving rows over all driven centers (a center's
    // map can take seconds); the interrupt message says so.
    let cells = run_in(
        py,
        samples >= WATCH_MIN_SAMPLES,
        progress,
        None,
        "driving rows (over all driven centers)",
        |control| {
            let work = || t.pivot_atlas_rows(&dn, r0..r1, &dv, &opts, rank_by, control);
            match &pool {
                Some(p) => p.install(work),
                None => work(),
            }
        },
    )?;
    let (rows, nx) = (r1 - r0, dn.nx());
    let d = PyDict::new(py);
    // Each column a NumPy array (a failed allocation is a MemoryError),
    // filled from the cells.
    fn column<'py, T: numpy::Element + Copy>(
        py: Python<'py>,
        shape: &[usize],
        cells: &[AtlasCell],
        f: impl Fn(&AtlasCell) -> [T; 2],
        per_cell: usize,
    ) -> PyResult<Bound<'py, PyAny>> {
        let a = empty::<T>(py, shape)?;
        {
            let mut w = writer(&a)?;
            let out = slice_mut(&mut w);
            for (o, c) in out.chunks_exact_mut(per_cell).zip(cells) {
                o.copy_from_slice(&f(c)[..per_cell]);
            }
        }
        Ok(a.into_any())
    }
    let flat = [rows, nx];
    d.set_item("valid", column(py, &flat, &cells, |c| [c.valid; 2], 1)?)?;
    d.set_item(
        "count",
        column(py, &flat, &cells, |c| [c.count as i64; 2], 1)?,
    )?;
    d.set_item(
        "branch_free",
        column(py, &flat, &cells, |c| [c.branch_free as i64; 2], 1)?,
    )?;
    let best = |f: fn(&burmester::AtlasBest) -> f64| {
        column(
            py,
            &flat,
            &cells,
            move |c| [c.best.as_ref().map_or(f64::NAN, f); 2],
            1,
        )
    };
    d.set_item(
        "best_transmission_rad",
        best(|b| f64::from(b.min_transmission_rad))?,
    )?;
    d.set_item("best_link_ratio", best(|b| f64::from(b.link_ratio))?)?;
    d.set_item("best_margin", best(|b| b.margin)?)?;
    d.set_item("best_size_ratio", best(|b| f64::from(b.size_ratio))?)?;
    d.set_item("best_score", best(|b| b.score)?)?;
    // The two-value columns of each cell's best driving pivot (`none`
    // where the cell has none).
    fn best_pair<'py, T: numpy::Element + Copy>(
        py: Python<'py>,
        shape: &[usize],
        cells: &[AtlasCell],
        none: [T; 2],
        f: impl Fn(&burmester::AtlasBest) -> [T; 2],
    ) -> PyResult<Bound<'py, PyAny>> {
        column(py, shape, cells, |c| c.best.as_ref().map_or(none, &f), 2)
    }
    let pairs = [rows, nx, 2];
    let driving = |b: &burmester::AtlasBest| [b.driving.x, b.driving.y];
    let driving = best_pair(py, &pairs, &cells, [f64::NAN; 2], driving)?;
    d.set_item("best_driving", driving)?;
    let index = |b: &burmester::AtlasBest| [b.index.0 as i64, b.index.1 as i64];
    d.set_item("best_index", best_pair(py, &pairs, &cells, [-1; 2], index)?)?;
    Ok(d)
}
