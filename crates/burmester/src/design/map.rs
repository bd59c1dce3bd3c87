//! The solution-space map over candidate pivots of three poses: one value
//! per grid sample of every figure (the columns, [`Columns`]).

use nalgebra::Point2;

use crate::design::columns::{Columns, ColumnsOut, Sample, debug_map};
use crate::design::judge::{Sampler, fill};
use crate::design::kernel;
use crate::design::options::MapOptions;
use crate::design::{Constraints, DesignLimits};
use crate::engine::Control;
use crate::error::{InvalidInput, Result, try_vec};
use crate::geom::Grid;
use crate::linkage::figures::figures;
use crate::synthesis::errors::not_a_dyad;
use crate::synthesis::three::{Filemon, Method};
use crate::synthesis::{Dyad, DyadKind, SliderDyad, SynthesizedFourBar, Task};
use crate::tolerance;

/// Which pivot a solution map varies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Varying {
    /// Candidate driving center points `A0`, with this driven dyad.
    Driving {
        /// The fixed driven dyad `(C0, C1)`.
        driven: Dyad,
    },
    /// Candidate driven center points `C0`, with this driving dyad.
    Driven {
        /// The fixed driving dyad `(A0, A1)`.
        driving: Dyad,
    },
    /// Candidate driving center points `A0`, with this driven slider: each
    /// sample's linkage is a slider-crank
    /// ([`MapContext::slider_crank`]).
    DrivingSlider {
        /// The fixed driven slider (`C1` on its guide).
        driven: SliderDyad,
    },
}

impl Varying {
    /// `"driving"` or `"driven"`: which center point varies (a driving
    /// map with a slider is `"driving"` too).
    pub fn as_str(&self) -> &'static str {
        match self {
            Varying::Driving { .. } | Varying::DrivingSlider { .. } => "driving",
            Varying::Driven { .. } => "driven",
        }
    }

    /// The fixed dyad: a crank, or the driven slider of
    /// [`Varying::DrivingSlider`].
    pub fn fixed(&self) -> DyadKind {
        match *self {
            Varying::Driving { driven } => driven.into(),
            Varying::Driven { driving } => driving.into(),
            Varying::DrivingSlider { driven } => driven.into(),
        }
    }
}

/// What a solution map was computed for: the grid, the task, which pivot
/// varies, and the limits and constraints. Holds the per-sample logic
/// (the linkage of a sample, its margin, the best pivots), so that the
/// columns can live elsewhere (for example in NumPy).
#[derive(Debug, Clone, PartialEq)]
pub struct MapContext {
    /// The grid.
    pub grid: Grid,
    /// The task.
    pub task: Task,
    /// Which pivot varies, and the fixed dyad.
    pub varying: Varying,
    /// The limits behind `acceptable`.
    pub limits: DesignLimits,
    /// The constraints behind `acceptable`.
    pub constraints: Constraints,
}

/// The solution-space map: what it was computed for, and its columns.
#[derive(Clone, PartialEq)]
pub struct SolutionMap {
    /// What the map was computed for.
    pub context: MapContext,
    /// One value per grid sample of every figure.
    pub columns: Columns,
}

debug_map!(SolutionMap, "samples");

impl SolutionMap {
    /// The Grashof code of an invalid sample.
    pub const GRASHOF_NONE: u8 = 255;
}

impl MapContext {
    /// The candidate center point of sample `k` (row-major index).
    pub fn point(&self, k: usize) -> Point2<f64> {
        self.grid.point(k % self.grid.nx(), k / self.grid.nx())
    }

    /// The linkage of sample `k`.
    ///
    /// # Errors
    ///
    /// As [`Task::four_bar`] (for an invalid sample);
    /// [`InvalidInput::DrivenKind`] for a map with a driven slider (its
    /// linkages are [`slider_crank`](Self::slider_crank)s).
    pub fn linkage(&self, k: usize) -> Result<SynthesizedFourBar> {
        let p = self.point(k);
        match self.varying {
            Varying::Driving { driven } => {
                self.task.four_bar(&self.task.dyad_from_center(p)?, &driven)
            }
            Varying::Driven { driving } => self
                .task
                .four_bar(&driving, &self.task.dyad_from_center(p)?),
            Varying::DrivingSlider { .. } => Err(InvalidInput::DrivenKind {
                what: "a map's four-bar (MapContext::linkage)",
                found: "slider",
            }
            .into()),
        }
    }
}

impl MapContext {
    fn new(grid: &Grid, task: &Task, varying: Varying, options: &MapOptions) -> Self {
        MapContext {
            grid: *grid,
            task: *task,
            varying,
            limits: *options.limits(),
            constraints: options.constraints().clone(),
        }
    }
}

/// What fills a map's columns.
type Fill<'a> = dyn Fn(ColumnsOut<'_>) -> Result<()> + 'a;

/// What a solution map is computed from: the Filemon construction of a
/// map over candidate driving pivots, or the task and the driving dyad of
/// a map over candidate driven pivots.
#[derive(Clone, Copy)]
enum Source<'a> {
    Driving(&'a Filemon),
    Driven(&'a Task, &'a Dyad),
}

impl Source<'_> {
    /// The map's arguments checked, then `finish(context, fill)`: what the
    /// map is computed for and the fill of its columns, for [`fresh`] (the
    /// map's own columns, allocated once the arguments are checked) or
    /// [`into`] (the caller's).
    fn map<T>(
        self,
        grid: &Grid,
        options: &MapOptions,
        control: &Control<'_>,
        finish: impl FnOnce(MapContext, &Fill<'_>) -> Result<T>,
    ) -> Result<T> {
        match self {
            Source::Driving(filemon) => {
                let sampler = Sampler::new(filemon.task(), options)?.with_control(control);
                let context = filemon.map_context(grid, options)?;
                finish(context, &|out| {
                    filemon.fill_solution_map(&sampler, grid, out, control)
                })
            }
            Source::Driven(task, driving) => {
                let sampler = task.driven_sampler(driving, options)?.with_control(control);
                let varying = Varying::Driven { driving: *driving };
                let context = MapContext::new(grid, task, varying, options);
                finish(context, &|out| {
                    task.fill_driven_map(&sampler, driving, grid, out, control)
                })
            }
        }
    }
}

/// A map of `grid` computed for `context`: its columns allocated, then
/// filled by `fill`.
fn fresh(
    grid: &Grid,
    context: MapContext,
    fill: impl FnOnce(ColumnsOut<'_>) -> Result<()>,
) -> Result<SolutionMap> {
    let mut columns = Columns::for_overwrite(grid.len())?;
    fill(columns.as_out())?;
    Ok(SolutionMap { context, columns })
}

/// What a map of `grid` into the caller's columns `out` gives: `out`
/// checked to hold the grid, filled by `fill`, and `context`.
fn into(
    grid: &Grid,
    context: MapContext,
    out: ColumnsOut<'_>,
    fill: impl FnOnce(ColumnsOut<'_>) -> Result<()>,
) -> Result<MapContext> {
    out.check_len(grid.len())?;
    fill(out)?;
    Ok(context)
}

impl Filemon {
    /// The solution-space map over candidate driving center points `A0`
    /// on `grid` (see [`design`](crate::design)), following `control`. The
    /// branch-free flag is exactly the `conic` branch map; the other
    /// figures come from the linkage at each sample: the four-bar of a
    /// driven crank, the slider-crank ([`MapContext::slider_crank`]) of a
    /// driven slider (no Grashof class; the crank's rotatability
    /// `r + |e| <= l` is `input_full`).
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for an envelope that leaves out a pose (obstacles
    /// and an envelope are checked over a slider-crank's travel too: module
    /// `map_slider`);
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory) when the columns
    /// cannot be allocated; [`Error::Cancelled`](crate::Error::Cancelled).
    pub fn solution_map(
        &self,
        grid: &Grid,
        options: &MapOptions,
        control: &Control<'_>,
    ) -> Result<SolutionMap> {
        // The arguments are checked before the columns are allocated.
        Source::Driving(self).map(grid, options, control, |context, fill| {
            fresh(grid, context, fill)
        })
    }

    /// [`solution_map`](Self::solution_map) into columns the caller owns:
    /// an earlier map's ([`Columns::as_out`]), so that a map recomputed as
    /// a designer moves a pose or a pivot costs no fresh pages, or buffers
    /// from another allocator. Every value of every column is written, the
    /// same bits as `solution_map`'s; returns what the map was computed
    /// for.
    ///
    /// # Errors
    ///
    /// As [`solution_map`](Self::solution_map), and
    /// [`InvalidInput::LengthMismatch`] when a column does not have
    /// `grid.len()` values. When cancelled the columns hold a partial map.
    pub fn solution_map_into(
        &self,
        grid: &Grid,
        options: &MapOptions,
        out: ColumnsOut<'_>,
        control: &Control<'_>,
    ) -> Result<MapContext> {
        Source::Driving(self).map(grid, options, control, |context, fill| {
            into(grid, context, out, fill)
        })
    }

    /// What the map is computed for.
    fn map_context(&self, grid: &Grid, options: &MapOptions) -> Result<MapContext> {
        let varying = match self.driven() {
            DyadKind::Revolute(driven) => Varying::Driving { driven },
            DyadKind::Slider(driven) => Varying::DrivingSlider { driven },
            // A Filemon is never built with an inverted driven dyad
            // (`FilemonLines::new` refuses it); say so rather than assume.
            DyadKind::Inverted(_) => {
                return Err(InvalidInput::InvertedDriven {
                    what: "a solution map",
                }
                .into());
            }
        };
        Ok(MapContext::new(grid, self.task(), varying, options))
    }

    /// The columns of the map, the arguments checked.
    fn fill_solution_map(
        &self,
        sampler: &Sampler<'_>,
        grid: &Grid,
        out: ColumnsOut<'_>,
        control: &Control<'_>,
    ) -> Result<()> {
        let mut branch = try_vec("a branch map", grid.len(), false)?;
        self.branch_map_into(grid, Method::Conic, &mut branch, control)?;
        match self.driven() {
            DyadKind::Revolute(driven) => {
                let c = sampler.fixed_pivots(&driven);
                kernel::for_driven(sampler, driven, &c).fill(grid, &branch, out, control)
            }
            DyadKind::Slider(driven) => sampler.fill_slider(driven, grid, &branch, out, control),
            DyadKind::Inverted(_) => Err(InvalidInput::InvertedDriven {
                what: "a solution map",
            }
            .into()),
        }
    }
}

impl Task {
    /// The solution-space map over candidate driven center points `C0`,
    /// with a fixed driving dyad: the other direction of
    /// [`Filemon::solution_map`], so a designer can iterate either way. The
    /// branch-free flag is the assembly-mode test at the three poses.
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for a driving dyad that is not a dyad of this task;
    /// as [`Filemon::solution_map`].
    pub fn driven_solution_map(
        &self,
        driving: &Dyad,
        grid: &Grid,
        options: &MapOptions,
        control: &Control<'_>,
    ) -> Result<SolutionMap> {
        // The arguments are checked before the columns are allocated.
        let source = Source::Driven(self, driving);
        source.map(grid, options, control, |context, fill| {
            fresh(grid, context, fill)
        })
    }

    /// [`driven_solution_map`](Self::driven_solution_map) into columns the
    /// caller owns, as [`Filemon::solution_map_into`].
    ///
    /// # Errors
    ///
    /// As [`driven_solution_map`](Self::driven_solution_map), and
    /// [`InvalidInput::LengthMismatch`] when a column does not have
    /// `grid.len()` values.
    pub fn driven_solution_map_into(
        &self,
        driving: &Dyad,
        grid: &Grid,
        options: &MapOptions,
        out: ColumnsOut<'_>,
        control: &Control<'_>,
    ) -> Result<MapContext> {
        let source = Source::Driven(self, driving);
        source.map(grid, options, control, |context, fill| {
            into(grid, context, out, fill)
        })
    }

    /// The sampler of the driven map, once the driving dyad is checked to
    /// be one of this task.
    fn driven_sampler<'a>(
        &'a self,
        driving: &Dyad,
        options: &'a MapOptions,
    ) -> Result<Sampler<'a>> {
        let sampler = Sampler::new(self, options)?;
        let d = self.dyad_from_center(driving.center)?;
        let spread = (d.circle - driving.circle).norm() / (self.scale() + driving.length());
        if spread.is_nan() || spread > tolerance::DYAD {
            return Err(not_a_dyad("driving dyad", spread));
        }
        Ok(sampler)
    }

    /// The columns of the driven map, the arguments checked.
    fn fill_driven_map(
        &self,
        sampler: &Sampler<'_>,
        driving: &Dyad,
        grid: &Grid,
        out: ColumnsOut<'_>,
        control: &Control<'_>,
    ) -> Result<()> {
        let a = sampler.fixed_pivots(driving);
        fill(grid, out, control, |_, c0| {
            let Some(c) = sampler.moving_pivots(c0) else {
                return Sample::INVALID;
            };
            let fig = figures::<true, 3>(driving.center, &a, c0, &c, sampler.judge.tiny);
            let free = fig.is_some_and(|f| f.branch_free());
            sampler
                .judge
                .sample(fig, free, &[c0], *driving, Dyad::new(c0, c[0]))
        })
    }
}
