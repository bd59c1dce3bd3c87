//! The solution map with a slider driven dyad: `SliderFilemon.solution_map`,
//! `SolutionMap.slider_crank` and `SolutionMap.fixed_kind` (how a map's
//! fixed dyad of either kind crosses to Python and back, its pickle, is
//! `map_state`'s).

use burmester::{Ranking, SliderPivot};
use pyo3::prelude::*;
use pyo3::types::PyList;

use crate::conv::{Count, PyPoint, Real, pt};
use crate::design::PySolutionMap;
use crate::errors::IntoPy;
use crate::map_state::Xy;
use crate::slider::PySynthesizedSliderCrank;
use crate::slider_branch::PySliderFilemon;

#[pymethods]
impl PySolutionMap {
    /// `"revolute"` or `"slider"`: the kind of the fixed dyad.
    #[getter]
    fn fixed_kind(&self) -> &'static str {
        self.context.varying.fixed().as_str()
    }

    /// The slider-crank of sample `(j, i)` of a map with a driven slider.
    fn slider_crank(&self, j: Count, i: Count) -> PyResult<PySynthesizedSliderCrank> {
        let grid = crate::geom::PyGrid {
            inner: self.context.grid,
        };
        grid.point(j, i)?;
        let nx = self.context.grid.nx();
        let k = j.0 * nx + i.0;
        let s = self.context.slider_crank(k).py()?;
        Ok(PySynthesizedSliderCrank::new(s, self.context.task))
    }
}

crate::design::filemon_solution_map_method!(PySliderFilemon, "SliderFilemon.solution_map");

crate::design::ranking_method!(PySolutionMap, best_slider_pivots, slider_ranked);

#[pymethods]
impl PySolutionMap {
    /// The Pareto front of a map with a driven slider, as `SliderPivot`s.
    fn slider_pareto_front<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        self.slider_ranked(py, Ranking::pareto_front())
    }
}

impl PySolutionMap {
    /// The ranking of a map with a driven slider, Ctrl-C polled on a long
    /// one.
    fn slider_ranked<'py>(
        &self,
        py: Python<'py>,
        ranking: Ranking,
    ) -> PyResult<Bound<'py, PyList>> {
        let ctx = &self.context;
        let watch = crate::design::ranking_is_long(ctx.grid.len(), ranking.k());
        let best = self.with_rank_columns(py, |cols| {
            crate::run::run_in(py, watch, None, None, "samples", |control| {
                ctx.best_pivots_with::<burmester::SynthesizedSliderCrank>(ranking, cols, control)
            })
        })?;
        crate::run::list_polled(py, &best, |b| {
            Ok(Bound::new(py, PySliderPivot::of(ctx.task, b))?.into_any())
        })
    }
}

/// A candidate driving pivot of a solution map with a driven slider, with
/// its slider-crank (`SolutionMap.best_pivots` of such a map).
#[pyclass(frozen, name = "SliderPivot", module = "burmester")]
#[derive(Clone)]
pub struct PySliderPivot {
    center: Xy,
    ranked: crate::design::Ranked<PySynthesizedSliderCrank>,
}

impl PySliderPivot {
    fn of(task: burmester::Task, p: &SliderPivot) -> Self {
        PySliderPivot {
            center: pt(p.center),
            ranked: crate::design::ranked_of!(p, PySynthesizedSliderCrank::new(p.linkage, task)),
        }
    }
}

#[pymethods]
impl PySliderPivot {
    #[new]
    fn new(
        center: PyPoint,
        index: (Count, Count),
        linkage: &Bound<'_, PySynthesizedSliderCrank>,
        margin: Real,
        score: Real,
        ranked_by: &str,
    ) -> PyResult<Self> {
        let linkage = linkage.get().clone();
        // The pivot is its slider-crank's crank pivot.
        let a0 = linkage.core().driving.center;
        if center.0 != a0 {
            return Err(crate::errors::invalid(
                "inconsistent_state",
                format!(
                    "a SliderPivot at ({}, {}) with a slider-crank whose crank pivot is {:?}: \
                     the pivot must be the crank pivot",
                    center.0.x,
                    center.0.y,
                    pt(a0)
                ),
            ));
        }
        let ranked = crate::design::Ranked::new(index, linkage, (margin, score), ranked_by)?;
        Ok(PySliderPivot {
            center: pt(center.0),
            ranked,
        })
    }
    fn __repr__(&self) -> String {
        let (x, y) = self.center;
        let l = self.ranked.linkage.core();
        let mu = if l.min_transmission.is_nan() {
            "None".to_owned()
        } else {
            format!("{:.3}", l.min_transmission.to_degrees())
        };
        format!(
            "<SliderPivot center=({x:.6}, {y:.6}) index={:?} crank={:.6} coupler={:.6} \
             offset={:.6} min_transmission_deg={mu} size_ratio={:.3} by {}>",
            self.ranked.index,
            l.linkage.crank(),
            l.linkage.coupler(),
            l.linkage.offset(),
            self.size_ratio(),
            self.ranked.ranked_by.as_str()
        )
    }
    #[getter]
    fn size_ratio(&self) -> f64 {
        self.ranked.linkage.size_ratio_of()
    }
}

crate::design::ranked_getters!(PySliderPivot, PySynthesizedSliderCrank);

crate::design::pivot_methods!(
    PySliderPivot,
    PySynthesizedSliderCrank,
    |l: &PySynthesizedSliderCrank| *l.core()
);

crate::getters::getters!(PySliderPivot {
    Xy: center;
});
