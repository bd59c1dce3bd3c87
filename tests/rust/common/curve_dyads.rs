//! The dyads the library itself puts on the Burmester curves of four poses,
//! which it must accept back. `burmester` only: the integration tests use it
//! through `common`, the fuzz checks (`fuzz/src/lib.rs`) by path.

use burmester::synthesis::{CurveDyad, FourPositions};

/// The crank-rotation runs and the parameter samples of `n` samples each
/// (as the pair map samples the curve), those that succeed, in that order.
pub(crate) fn own_curve_dyads(four: &FourPositions, n: usize) -> Vec<CurveDyad> {
    let mut dyads = Vec::new();
    if let Ok(runs) = four.dyad_runs(n) {
        dyads.extend(runs.into_iter().flatten());
    }
    if let Ok(samples) = four.parameter_samples(n) {
        dyads.extend(samples.into_iter().flatten());
    }
    dyads
}
