//! The reference backend of the per-sample kernel: one sample at a time,
//! [`Sampler::driving_sample`] itself (and the kernel of a task whose
//! poles are at infinity).

use nalgebra::Point2;

use crate::design::RankBy;
use crate::design::columns::{ColumnsOut, Sample};
use crate::design::judge::{Sampler, fill};
use crate::design::kernel::{AtlasAsk, DrivingRows, RowOut, RowPre, Seen};
use crate::engine::Control;
use crate::error::Result;
use crate::geom::Grid;
use crate::synthesis::Dyad;

/// The driving map's samples of one driven dyad (moving pivot `c` at the
/// three poses), each by [`Sampler::driving_sample`].
pub(crate) struct ScalarRows<'s> {
    pub(crate) sampler: &'s Sampler<'s>,
    pub(crate) driven: Dyad,
    pub(crate) c: [Point2<f64>; 3],
}

impl DrivingRows for ScalarRows<'_> {
    fn fill(&self, g: &Grid, b: &[bool], out: ColumnsOut<'_>, c: &Control<'_>) -> Result<()> {
        fill(g, out, c, |k, a0| {
            self.sampler.driving_sample(a0, self.driven, &self.c, b[k])
        })
    }

    fn pre_row(&self, _: f64, _: &[f64], _: &[bool], _: &mut RowPre) {}

    fn row_where(&self, _: f64, _: &[f64], _: &[bool], _: &RowPre, _: &mut RowOut) {}

    fn atlas_sample(&self, _: &RowOut, _: usize, a0: Point2<f64>, ask: &AtlasAsk<'_>) -> Seen {
        let s = self.sampler.driving_sample(a0, self.driven, &self.c, true);
        s.valid
            .then_some(s.acceptable.then_some(sample_score(&s, ask.rank_by)))
    }
}

/// The score of a sample by `rank_by`, from its columns as the map's
/// ranking reads them (`None` where NaN).
pub(crate) fn sample_score(s: &Sample, rank_by: RankBy) -> Option<f64> {
    rank_by.score(
        f64::from(s.min_transmission_rad),
        f64::from(s.size_ratio),
        f64::from(s.link_ratio),
    )
}
