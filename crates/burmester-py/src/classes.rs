//! The pyclass types other modules pass around, at the bottom of the
//! binding: each holds a core value. Their methods live in the module of
//! their concept (`synthesis`, `design`), which imports from here and never
//! the other way round.

use burmester::{DesignLimits, Dyad, Filemon, SynthesizedFourBar, Task};
use pyo3::prelude::*;

use crate::conv::pt;

type Xy = (f64, f64);

/// `(center, circle)` of a dyad for Python.
pub(crate) fn dyad_tuple(d: &Dyad) -> (Xy, Xy) {
    (pt(d.center), pt(d.circle))
}

/// Three to five poses of the coupler.
#[pyclass(frozen, eq, from_py_object, name = "Task", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PyTask {
    pub(crate) inner: Task,
}

/// Filemon's construction for a driven dyad, and its transformed conics.
#[pyclass(frozen, eq, name = "Filemon", module = "burmester")]
#[derive(Clone, PartialEq)]
pub(crate) struct PyFilemon {
    pub(crate) inner: Filemon,
}

/// A four-bar built from a driving and a driven dyad of a task.
#[pyclass(
    frozen,
    from_py_object,
    name = "SynthesizedFourBar",
    module = "burmester"
)]
#[derive(Clone)]
pub struct PySynthesizedFourBar {
    pub(crate) inner: SynthesizedFourBar,
    /// The task it was built for (for pickling).
    pub(crate) task: Task,
}

impl PySynthesizedFourBar {
    pub(crate) fn new(task: Task, inner: SynthesizedFourBar) -> Self {
        PySynthesizedFourBar { inner, task }
    }

    /// The task it was built for.
    pub(crate) fn task(&self) -> Task {
        self.task
    }
}

/// Equal when built from the same task and dyads, bit for bit: the linkage
/// and its figures are a function of them (figures that are NaN, as the
/// transmission of a linkage without a travel, would make a field-wise
/// comparison say a linkage differs from itself).
impl PartialEq for PySynthesizedFourBar {
    fn eq(&self, other: &Self) -> bool {
        let bits = |d: &Dyad| [d.center.x, d.center.y, d.circle.x, d.circle.y].map(f64::to_bits);
        self.task == other.task
            && bits(&self.inner.driving) == bits(&other.inner.driving)
            && bits(&self.inner.driven) == bits(&other.inner.driven)
    }
}

/// The designer's limits behind the `acceptable` mask.
#[pyclass(
    frozen,
    eq,
    from_py_object,
    name = "DesignLimits",
    module = "burmester"
)]
#[derive(Clone, PartialEq)]
pub(crate) struct PyDesignLimits {
    pub(crate) inner: DesignLimits,
}

impl From<DesignLimits> for PyDesignLimits {
    fn from(inner: DesignLimits) -> Self {
        PyDesignLimits { inner }
    }
}
