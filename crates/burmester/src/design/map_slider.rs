//! The solution map with a driven slider: every candidate driving center
//! point `A0` of a three-pose task with a fixed driven slider (`C1` on its
//! guide, [`SliderDyad`]) makes a slider-crank
//! ([`Task::slider_crank`]), and the map's columns are that linkage's
//! figures.
//!
//! What a slider-crank has in place of a four-bar's figures:
//!
//! * `branch_free`: exactly the `conic` branch map of the slider's Filemon
//!   construction, as for a crank;
//! * `grashof`: Grashof's law is a four-bar's; the column holds
//!   [`SolutionMap::GRASHOF_NONE`](crate::SolutionMap::GRASHOF_NONE) for
//!   every sample. The crank's own rotatability condition is
//!   `input_full`: the crank turns fully exactly when `r + |e| <= l`
//!   ([`SliderCrank::turns_fully`]);
//! * `direction`, `one_circuit`, `min_transmission_rad`: the
//!   [`SynthesizedSliderCrank`]'s (the transmission angle between the
//!   coupler and the guide's normal, over the travel);
//! * `link_ratio`: longest over shortest of the crank and the coupler
//!   ([`SliderCrank::link_ratio`]; the guide has no length and the offset
//!   may be zero);
//! * `size_ratio`: [`SynthesizedSliderCrank::size`] (crank, coupler, the
//!   coupler triangle's other sides, the offset and the guide the slider
//!   runs on) over [`Task::span`].
//!
//! `acceptable` applies [`DesignLimits`](crate::DesignLimits) as to a
//! four-bar, with two readings: the links a
//! [`max_link_length`](crate::DesignLimits::max_link_length) bounds are
//! the crank, the coupler and the offset, and
//! [`min_grashof_margin`](crate::DesignLimits::min_grashof_margin) bounds
//! the distance from the slider-crank's change points
//! ([`SliderCrank::rotatability_margin`]). A base plate holds `A0`;
//! obstacles and an envelope are checked over the slider-crank's travel:
//! the crank, the coupler (and its triangle with the coupler point, for the
//! envelope) and the slider's block on its guide, capsules of the links'
//! width (`design::constraints`, "A slider-crank over its travel").

use nalgebra::Point2;

use crate::design::MapContext;
use crate::design::columns::{ColumnsOut, Sample};
use crate::design::judge::{Sampler, fill};
use crate::design::map::Varying;
use crate::engine::Control;
use crate::error::{InvalidInput, Result};
use crate::geom::Grid;
use crate::linkage::SliderCrank;
use crate::synthesis::{SliderDyad, SynthesizedSliderCrank, Task};

impl SliderCrank {
    /// The distance from the change points of the crank's input range,
    /// over the links' total: `min(|l - r - e|, |l - r + e|) / (r + l +
    /// |e|)`. The crank's range changes kind (full turn, one arc, two
    /// arcs) where `r + e = l` or `r - e = l`
    /// ([`input_range`](Self::input_range)); there the coupler reaches
    /// perpendicular to the guide with the crank along the guide's normal,
    /// a toggle the crank can pass into either circuit. The slider-crank's
    /// reading of [`LinkageFigures::grashof_margin`](crate::LinkageFigures::grashof_margin):
    /// crank, coupler and offset each off by less than this fraction of
    /// their total cannot change the range's kind.
    pub fn rotatability_margin(&self) -> f64 {
        let (r, l, e) = (self.crank(), self.coupler(), self.offset());
        (l - r - e).abs().min((l - r + e).abs()) / (r + l + e.abs())
    }
}

/// The slider-crank of candidate driving center `a0` with the driven
/// slider `driven`: one sample's linkage.
fn slider_crank_at(
    task: &Task,
    a0: Point2<f64>,
    driven: &SliderDyad,
) -> Result<SynthesizedSliderCrank> {
    task.slider_crank(&task.dyad_from_center(a0)?, driven)
}

impl Sampler<'_> {
    /// The columns of a driving map with the driven slider `driven` and
    /// the branch map `branch` (module docs).
    pub(crate) fn fill_slider(
        &self,
        driven: SliderDyad,
        grid: &Grid,
        branch: &[bool],
        out: ColumnsOut<'_>,
        control: &Control<'_>,
    ) -> Result<()> {
        let task = self.judge.task();
        fill(grid, out, control, |k, a0| {
            match slider_crank_at(task, a0, &driven) {
                Ok(sc) => self.judge.slider_sample(&sc, branch[k]),
                Err(_) => Sample::INVALID,
            }
        })
    }
}

impl MapContext {
    /// The slider-crank of sample `k` of a map with a driven slider: the
    /// linkage its columns describe.
    ///
    /// # Errors
    ///
    /// As [`Task::slider_crank`] (for an invalid sample);
    /// [`InvalidInput::DrivenKind`] for a map with a driven crank (its
    /// linkages are [`linkage`](Self::linkage)s).
    pub fn slider_crank(&self, k: usize) -> Result<SynthesizedSliderCrank> {
        match self.varying {
            Varying::DrivingSlider { driven } => {
                slider_crank_at(&self.task, self.point(k), &driven)
            }
            Varying::Driving { .. } | Varying::Driven { .. } => Err(InvalidInput::DrivenKind {
                what: "a map's slider-crank (MapContext::slider_crank)",
                found: "revolute",
            }
            .into()),
        }
    }
}
