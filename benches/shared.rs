//! The measured calls that more than one bench makes, written once.
#![allow(dead_code)]

use std::hint::black_box;

use burmester::design::{Columns, MapContext};
use burmester::{AssemblyMode, Control, Filemon, FourBar, Grid, MapOptions};

/// The solution map of `f` on `grid` into the columns of an earlier map
/// (no fresh pages).
pub(crate) fn solution_map_into(
    f: &Filemon,
    grid: &Grid,
    options: &MapOptions,
    columns: &mut Columns,
    control: &Control<'_>,
) -> MapContext {
    f.solution_map_into(black_box(grid), options, columns.as_out(), control)
        .unwrap()
}

/// The position analysis of `fb` in the open mode at `angles`, into the
/// buffers `t3`, `t4` and `ok`.
pub(crate) fn solve_into(
    fb: &FourBar,
    angles: &[f64],
    t3: &mut [f64],
    t4: &mut [f64],
    ok: &mut [bool],
) -> usize {
    fb.solve_into(black_box(angles), AssemblyMode::Open, t3, t4, ok)
        .unwrap()
}
