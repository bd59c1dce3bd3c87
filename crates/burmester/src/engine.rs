//! The tiled parallel engine of every long computation (the branch and
//! margin sweeps, the solution maps), and the [`Control`] a caller passes to
//! follow its progress and to cancel it.
//!
//! A grid's rows are split into blocks of about [`BLOCK_SAMPLES`] samples
//! (at least [`BLOCKS_PER_THREAD`] blocks per worker thread when the grid
//! allows), which rayon runs in parallel. Before each row the engine checks the cancel flag (a block of
//! costly samples can take seconds, a row a fraction of that); after each
//! block it reports the rows done. Every sample is computed from its grid
//! indices alone, so the result does not depend on the blocks, on the
//! threads, or on whether progress is followed: a map computed with a
//! progress hook equals one computed without, bit for bit.

use core::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use rayon::prelude::*;

use crate::error::{Error, Result};

/// Samples per block of rows (the unit of parallel work and of progress;
/// cancellation is checked per row).
pub const BLOCK_SAMPLES: usize = 16_384;

/// How a caller follows and stops a long computation: an optional cancel
/// flag, checked before each row, and an optional progress hook,
/// called after each block with `(rows done, rows in all)` from whichever
/// worker thread finished it.
///
/// # Example
///
/// ```
/// use core::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
/// use burmester::{Control, Grid, Method, example};
/// let filemon = example::task().filemon(example::driven_center())?;
/// let grid = Grid::new(example::viewport(), 256, 256)?;
/// let (stop, rows) = (AtomicBool::new(false), AtomicUsize::new(0));
/// let progress = |done: usize, _total: usize| {
///     rows.fetch_max(done, Ordering::Relaxed);
/// };
/// let control = Control::new().with_cancel(&stop).with_progress(&progress);
/// let mut map = vec![false; grid.len()];
/// filemon.branch_map_into(&grid, Method::Conic, &mut map, &control)?;
/// assert_eq!(rows.load(Ordering::Relaxed), 256);
/// assert_eq!(map, filemon.branch_map(&grid, Method::Conic));
/// # Ok::<(), burmester::Error>(())
/// ```
#[derive(Clone, Copy, Default)]
pub struct Control<'a> {
    cancel: Option<&'a AtomicBool>,
    progress: Option<&'a (dyn Fn(usize, usize) + Sync)>,
}

impl core::fmt::Debug for Control<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Control")
            .field("cancel", &self.cancel)
            .field("progress", &self.progress.is_some())
            .finish()
    }
}

impl<'a> Control<'a> {
    /// No cancel flag, no progress hook.
    pub const fn new() -> Self {
        Control {
            cancel: None,
            progress: None,
        }
    }

    /// The computation stops (with [`Error::Cancelled`]) at the next row
    /// once `flag` is true.
    #[must_use]
    pub fn with_cancel(mut self, flag: &'a AtomicBool) -> Self {
        self.cancel = Some(flag);
        self
    }

    /// `hook(done, total)` is called after each block of rows.
    #[must_use]
    pub fn with_progress(mut self, hook: &'a (dyn Fn(usize, usize) + Sync)) -> Self {
        self.progress = Some(hook);
        self
    }

    /// Whether the cancel flag is set.
    pub fn is_cancelled(&self) -> bool {
        self.cancel.is_some_and(|c| c.load(Ordering::Relaxed))
    }

    /// The same cancel flag with another progress hook (for a stage of a
    /// longer computation that reports its own progress in its units).
    pub(crate) fn with_hook<'b>(&self, hook: &'b (dyn Fn(usize, usize) + Sync)) -> Control<'b>
    where
        'a: 'b,
    {
        Control {
            cancel: self.cancel,
            progress: Some(hook),
        }
    }

    /// The same cancel flag without the progress hook (for a stage of a
    /// longer computation whose progress is not reported).
    pub(crate) fn cancel_only(&self) -> Control<'a> {
        Control {
            cancel: self.cancel,
            progress: None,
        }
    }

    /// The cancel flag, if any (a computation made of parts passes it on to
    /// each part's own control).
    pub(crate) fn cancel_flag(&self) -> Option<&'a AtomicBool> {
        self.cancel
    }

    /// [`Error::Cancelled`] after `done` of `total` units when the cancel
    /// flag is set.
    ///
    /// # Errors
    ///
    /// [`Error::Cancelled`] when the flag is set.
    pub(crate) fn check(&self, done: usize, total: usize) -> Result<()> {
        if self.is_cancelled() {
            Err(Error::Cancelled { done, total })
        } else {
            Ok(())
        }
    }

    pub(crate) fn report(&self, done: usize, total: usize) {
        if let Some(p) = self.progress {
            p(done, total);
        }
    }
}

/// Blocks per worker thread the engine aims for: the cost of a sample
/// varies across a map (branch-free regions cost the whole kernel, others
/// little), so a few blocks per thread leave the threads idle at the end;
/// with 32 per thread the last block to finish is a small share of a map's
/// time on 16 threads (measured: `benches/scaling.rs`, BENCHMARKS.md).
pub const BLOCKS_PER_THREAD: usize = 32;

/// Rows per block for rows of `nx` samples: about [`BLOCK_SAMPLES`]
/// samples, fewer where that would give fewer than [`BLOCKS_PER_THREAD`]
/// blocks per thread of the current rayon pool (at least one row).
pub(crate) fn rows_per_block(nx: usize, ny: usize) -> usize {
    let blocks = BLOCKS_PER_THREAD * rayon::current_num_threads().max(1);
    (BLOCK_SAMPLES / nx.max(1)).clamp(1, ny.div_ceil(blocks).max(1))
}

/// Data laid out in rows that can be split into blocks (one output array,
/// or the columns of a solution map).
pub(crate) trait Rows: Send + Sized {
    /// The first `rows` rows, and the rest.
    fn split_rows(self, rows: usize) -> (Self, Self);
}

/// One row-major array of rows of `nx` values.
pub(crate) struct RowsOf<'a, T> {
    pub(crate) data: &'a mut [T],
    pub(crate) nx: usize,
}

impl<T: Send> Rows for RowsOf<'_, T> {
    fn split_rows(self, rows: usize) -> (Self, Self) {
        let nx = self.nx;
        let (a, b) = self.data.split_at_mut((rows * nx).min(self.data.len()));
        (RowsOf { data: a, nx }, RowsOf { data: b, nx })
    }
}

/// Runs `f(first_row, rows_data, rows)` over the `ny` rows of `data` (rows
/// of `nx` samples), in parallel over blocks of rows, honouring `control`
/// (it is called one row at a time, so that cancelling takes effect at the
/// next row).
///
/// # Errors
///
/// [`Error::Cancelled`] when the cancel flag stopped it before every row
/// was done; [`Error::OutOfMemory`] when the list of blocks cannot be
/// allocated.
pub(crate) fn run_blocks<R: Rows>(
    nx: usize,
    ny: usize,
    data: R,
    control: &Control<'_>,
    f: impl Fn(usize, R, usize) + Sync,
) -> Result<()> {
    run_blocks_with(
        nx,
        ny,
        data,
        control,
        || Ok(()),
        |(), j, rows, n| f(j, rows, n),
    )
}

/// The blocks of rows of `data`: `(first_row, rows_data, rows)`, sized by
/// [`rows_per_block`].
fn blocks_of<R: Rows>(nx: usize, ny: usize, data: R) -> Result<Vec<(usize, R, usize)>> {
    let per = rows_per_block(nx, ny);
    let mut blocks = Vec::new();
    blocks
        .try_reserve_exact(ny.div_ceil(per))
        .map_err(|_| crate::error::out_of_memory::<(usize, R, usize)>("blocks", ny / per))?;
    let mut rest = data;
    let mut j = 0;
    while j < ny {
        let n = per.min(ny - j);
        let (block, tail) = rest.split_rows(n);
        blocks.push((j, block, n));
        rest = tail;
        j += n;
    }
    Ok(blocks)
}

/// The end of a run over blocks: [`Error::Cancelled`] unless every row was
/// done and the flag stayed clear (work inside a row that checks the flag
/// itself, a linkage's clearance, may have cut its last row short: a run
/// during which the flag was set is cancelled even when every row was
/// reached).
fn finish(done: usize, ny: usize, control: &Control<'_>) -> Result<()> {
    if done < ny || control.is_cancelled() {
        return Err(Error::Cancelled { done, total: ny });
    }
    Ok(())
}

/// [`run_blocks`] with a scratch value made by `init` (once per worker's
/// share of the blocks, not per block) and lent to `f` for each row (buffers
/// a row's work reuses: `f` must not depend on what an earlier row left in
/// them); `init` fails with [`Error::OutOfMemory`] when they cannot be
/// allocated.
///
/// # Errors
///
/// As [`run_blocks`]; the first error of `init`.
pub(crate) fn run_blocks_with<R: Rows, S>(
    nx: usize,
    ny: usize,
    data: R,
    control: &Control<'_>,
    init: impl Fn() -> Result<S> + Sync,
    f: impl Fn(&mut S, usize, R, usize) + Sync,
) -> Result<()> {
    let blocks = blocks_of(nx, ny, data)?;
    // The total from the start: an interrupt before the first block ends
    // can say how far the work got.
    control.report(0, ny);
    let done = AtomicUsize::new(0);
    let failed: std::sync::Mutex<Option<Error>> = std::sync::Mutex::new(None);
    blocks.into_par_iter().for_each_init(
        || init().map_err(Some),
        |scratch, (j0, block, n)| {
            let scratch = match scratch {
                Ok(s) => s,
                Err(e) => {
                    if let (Some(e), Ok(mut f)) = (e.take(), failed.lock()) {
                        f.get_or_insert(e);
                    }
                    return;
                }
            };
            // Row by row, checking the cancel flag before each: a block of
            // costly samples (a solution map with obstacles) can take seconds,
            // a row a small fraction of that.
            let mut rest = block;
            let mut finished = 0;
            while finished < n && !control.is_cancelled() {
                let (row, tail) = rest.split_rows(1);
                f(scratch, j0 + finished, row, 1);
                rest = tail;
                finished += 1;
            }
            if finished > 0 {
                let d = done.fetch_add(finished, Ordering::Relaxed) + finished;
                control.report(d, ny);
            }
        },
    );
    if let Some(e) = failed.into_inner().ok().flatten() {
        return Err(e);
    }
    finish(done.into_inner(), ny, control)
}

/// [`run_blocks`] for rows whose samples can each take long (a drive map
/// with obstacles checks a full crank turn per sample): `f(first_row, rows_data,
/// rows)` returns whether it finished its row, and may stop early once the
/// cancel flag is set (it gets `control` to poll); a row it did not finish
/// is not counted as done.
///
/// # Errors
///
/// As [`run_blocks`].
pub(crate) fn run_blocks_polled<R: Rows>(
    nx: usize,
    ny: usize,
    data: R,
    control: &Control<'_>,
    f: impl Fn(usize, R, &Control<'_>) -> bool + Sync,
) -> Result<()> {
    let blocks = blocks_of(nx, ny, data)?;
    // The total from the start: an interrupt before the first block ends
    // can say how far the work got.
    control.report(0, ny);
    let done = AtomicUsize::new(0);
    blocks.into_par_iter().for_each(|(j0, block, n)| {
        let mut rest = block;
        let mut finished = 0;
        while finished < n && !control.is_cancelled() {
            let (row, tail) = rest.split_rows(1);
            if !f(j0 + finished, row, control) {
                break;
            }
            rest = tail;
            finished += 1;
        }
        if finished > 0 {
            let d = done.fetch_add(finished, Ordering::Relaxed) + finished;
            control.report(d, ny);
        }
    });
    finish(done.into_inner(), ny, control)
}

/// Calls `f(j, row)` for every row `j` of `out` (`nx` values each), in
/// parallel over blocks of rows, honouring `control`.
///
/// # Errors
///
/// As [`run_blocks`].
pub(crate) fn for_rows<T: Send>(
    nx: usize,
    out: &mut [T],
    control: &Control<'_>,
    f: impl Fn(usize, &mut [T]) + Sync,
) -> Result<()> {
    let ny = out.len() / nx.max(1);
    run_blocks(nx, ny, RowsOf { data: out, nx }, control, |j0, block, _| {
        for (r, row) in block.data.chunks_mut(nx).enumerate() {
            f(j0 + r, row);
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_cover_every_row_once() {
        for (nx, ny) in [(1, 1), (3, 17), (100_000, 3), (7, 10_000)] {
            let mut out = vec![0u32; nx * ny];
            for_rows(nx, &mut out, &Control::new(), |j, row| {
                for v in row.iter_mut() {
                    *v += j as u32 + 1;
                }
            })
            .unwrap();
            for (k, v) in out.iter().enumerate() {
                assert_eq!(*v as usize, k / nx + 1);
            }
        }
    }

    #[test]
    fn cancelled_before_start_does_nothing() {
        let stop = AtomicBool::new(true);
        let mut out = vec![0u8; 64 * 64];
        let e = for_rows(
            64,
            &mut out,
            &Control::new().with_cancel(&stop),
            |_, row| row.fill(1),
        )
        .unwrap_err();
        assert_eq!(e, Error::Cancelled { done: 0, total: 64 });
        assert!(out.iter().all(|&v| v == 0));
    }

    #[test]
    fn progress_reaches_the_total() {
        let last = AtomicUsize::new(0);
        let hook = |d: usize, t: usize| {
            assert!(d <= t);
            last.fetch_max(d, Ordering::Relaxed);
        };
        let mut out = vec![0u8; 50 * 300];
        for_rows(
            50,
            &mut out,
            &Control::new().with_progress(&hook),
            |_, _| {},
        )
        .unwrap();
        assert_eq!(last.into_inner(), 300);
    }
}
