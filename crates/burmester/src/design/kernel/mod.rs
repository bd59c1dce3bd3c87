//! The per-sample kernel of the three-pose driving solution map and of the
//! pivot atlas, behind one trait ([`DrivingRows`]): the scalar path
//! ([`scalar`], one sample at a time through [`Sampler::driving_sample`])
//! is the reference, the SIMD lanes ([`simd`]) give its bits faster. A new
//! backend is one new file here implementing [`DrivingRows`], chosen in
//! [`for_driven`], the one place a kernel is chosen.

use nalgebra::Point2;

use crate::design::RankBy;
use crate::design::columns::ColumnsOut;
use crate::design::judge::Sampler;
use crate::engine::Control;
use crate::error::Result;
use crate::geom::Grid;
use crate::synthesis::Dyad;

mod scalar;
mod simd;

pub(crate) use scalar::sample_score;
pub(crate) use simd::{CosBand, RowOut, RowPre};

/// The samples of a driving map (or an atlas cell) with one driven dyad:
/// candidate driving centers on a grid, a row at a time.
pub(crate) trait DrivingRows {
    /// Fills the columns `out` of the driving map over grid `g` with branch
    /// flags `b` (one per sample), over blocks of rows on the engine,
    /// following `c`: [`Sampler::driving_sample`] bit for bit at every
    /// sample.
    ///
    /// # Errors
    ///
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory) for a row's
    /// buffers; [`Error::Cancelled`](crate::Error::Cancelled).
    fn fill(&self, g: &Grid, b: &[bool], out: ColumnsOut<'_>, c: &Control<'_>) -> Result<()>;

    /// For the atlas: what depends on the driving candidates alone of the
    /// row at ordinate `y` (abscissae `xs`, the grid's
    /// [`padded_xs`](simd::DrivingKernel::padded_xs)) where `needed`, into
    /// `pre` (the same for every kernel of one sampler; a backend that
    /// needs none leaves it).
    fn pre_row(&self, y: f64, xs: &[f64], needed: &[bool], pre: &mut RowPre);

    /// For the atlas: the row at ordinate `y` where `needed`, from `pre`
    /// ([`pre_row`](Self::pre_row) of the row), into `out`.
    fn row_where(&self, y: f64, xs: &[f64], needed: &[bool], pre: &RowPre, out: &mut RowOut);

    /// For the atlas: the branch-free sample `i` of the row in `out`
    /// (candidate `a0`), as `ask` asks.
    fn atlas_sample(&self, out: &RowOut, i: usize, a0: Point2<f64>, ask: &AtlasAsk<'_>) -> Seen;
}

/// What the atlas asks of a sample ([`DrivingRows::atlas_sample`]).
pub(crate) struct AtlasAsk<'a> {
    /// The transmission limit.
    pub(crate) limit: &'a CosBand,
    /// The ranking whose score is asked.
    pub(crate) rank_by: RankBy,
    /// Ranking by transmission: the band a score must reach to matter.
    pub(crate) reach: &'a CosBand,
}

/// What the atlas sees of a sample: `None` without a linkage, `Some(None)`
/// where it is not acceptable, else its score (`None` where NaN, or
/// below [`AtlasAsk::reach`] when ranking by transmission).
pub(crate) type Seen = Option<Option<Option<f64>>>;

/// The kernel of the driving map of `sampler` with the driven dyad
/// `driven` (moving pivot `c` at the three poses): the SIMD lanes where
/// the task has them (poles at finite points), the scalar path elsewhere.
pub(crate) fn for_driven<'s>(
    sampler: &'s Sampler<'s>,
    driven: Dyad,
    c: &[Point2<f64>; 3],
) -> Box<dyn DrivingRows + 's> {
    match simd::DrivingKernel::new(sampler, driven, c) {
        Some(k) => Box::new(k),
        None => Box::new(scalar::ScalarRows {
            sampler,
            driven,
            c: *c,
        }),
    }
}

/// The driving grid's abscissae as the kernels read a row: padded to a
/// whole number of lanes.
///
/// # Errors
///
/// [`Error::OutOfMemory`](crate::Error::OutOfMemory).
pub(crate) fn padded_xs(grid: &Grid) -> Result<Vec<f64>> {
    simd::DrivingKernel::padded_xs(grid)
}
