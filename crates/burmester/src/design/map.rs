//! The solution-space map: one value per grid sample of every figure.
//!
//! The columns are defined once, by [`solution_map_columns!`](crate::solution_map_columns):
//! the core's [`Columns`] and per-sample record are generated from that
//! list, and so is the Python binding's class.

use core::sync::atomic::AtomicBool;

use nalgebra::Point2;

use crate::design::constraints::Prepared;
use crate::design::kernel::DrivingKernel;
use crate::design::{Constraints, DesignLimits};
use crate::engine::{Control, Rows, run_blocks};
use crate::error::{InvalidInput, Result, try_vec, try_zeroed_vec};
use crate::geom::Grid;
use crate::linkage::LinkageFigures;
use crate::linkage::figures::figures;
use crate::synthesis::three::{Filemon, Maps, Method};
use crate::synthesis::{Dyad, Motion, SynthesizedFourBar, Task, members_length};
use crate::tolerance;

/// Calls `$callback! { ... }` with the solution map's columns, each as
/// `/// docs  name: type = value where the linkage does not exist`, in
/// order. The one list of the columns: the core's [`Columns`] and the
/// Python binding's `SolutionMap` class are generated from it.
#[macro_export]
macro_rules! solution_map_columns {
    ($callback:ident) => {
        $callback! {
            /// The linkage exists: the candidate has a circle point and every
            /// link a nonzero length. Where false, the other columns hold
            /// false, 0, NaN or `GRASHOF_NONE`.
            valid: bool = false,
            /// Free of the branch defect (for candidate driving pivots,
            /// exactly the `conic` branch map).
            branch_free: bool = false,
            /// Grashof class as the index of its class in `Grashof::ALL`;
            /// `SolutionMap::GRASHOF_NONE` (255) where invalid.
            grashof: u8 = $crate::SolutionMap::GRASHOF_NONE,
            /// The driving link turns fully.
            input_full: bool = false,
            /// The input rotation that carries the coupler through the poses
            /// in order: `1` counter-clockwise, `-1` clockwise, `0` none
            /// (`Direction::code`).
            direction: i8 = 0,
            /// The input angles at the poses lie on one circuit.
            one_circuit: bool = false,
            /// Minimum transmission angle over the travel, radians; NaN where
            /// there is no travel or no linkage.
            min_transmission_rad: f32 = f32::NAN,
            /// Longest over shortest link; NaN where there is no linkage.
            link_ratio: f32 = f32::NAN,
            /// The linkage's size relative to the task's: the total length of
            /// its members (`SynthesizedFourBar::size`) over the largest
            /// distance between two pose positions (`Task::span`); NaN where
            /// there is no linkage.
            size_ratio: f32 = f32::NAN,
            /// Meets the limits and the constraints, with a feasible,
            /// branch-free motion.
            acceptable: bool = false,
        }
    };
}

macro_rules! define_columns {
    ($($(#[$doc:meta])* $name:ident: $ty:ty = $invalid:expr,)*) => {
        /// The columns of a solution map: one value per grid sample,
        /// row-major like the branch map.
        #[derive(Debug, Clone, PartialEq)]
        pub struct Columns {
            $($(#[$doc])* pub $name: Vec<$ty>,)*
        }

        impl Columns {
            /// The names of the columns, in order.
            pub const NAMES: &'static [&'static str] = &[$(stringify!($name)),*];

            /// Room for `n` samples, zeroed, for a fill that writes every
            /// sample (each path does: a sample with no linkage is
            /// [`Sample::INVALID`]); the pages are first touched by the
            /// threads that write them.
            pub(crate) fn for_overwrite(n: usize) -> Result<Self> {
                Ok(Columns {
                    $($name: try_zeroed_vec("a solution map", n)?,)*
                })
            }

            /// Sample `i`, every column.
            #[cfg(test)]
            pub(crate) fn sample(&self, i: usize) -> Sample {
                Sample {
                    $($name: self.$name[i],)*
                }
            }

            /// Every column borrowed for writing: an earlier map's columns
            /// to fill again with [`Filemon::solution_map_into`] or
            /// [`Task::driven_solution_map_into`], without new pages.
            pub fn as_out(&mut self) -> ColumnsOut<'_> {
                ColumnsOut {
                    $($name: &mut self.$name,)*
                }
            }

            #[cfg(test)]
            pub(crate) fn rows(&mut self, nx: usize) -> ColumnsMut<'_> {
                self.as_out().rows(nx)
            }
        }

        /// A solution map's columns to write: one slice per column, each
        /// of one value per grid sample, row-major. From
        /// [`Columns::as_out`] (to reuse a map's memory) or from buffers
        /// the caller allocates (the Python binding's NumPy arrays).
        #[derive(Debug)]
        pub struct ColumnsOut<'a> {
            $($(#[$doc])* pub $name: &'a mut [$ty],)*
        }

        impl<'a> ColumnsOut<'a> {
            /// Every column has `n` values.
            pub(crate) fn check_len(&self, n: usize) -> Result<()> {
                $(
                    if self.$name.len() != n {
                        return Err(InvalidInput::LengthMismatch {
                            name: concat!("column ", stringify!($name)),
                            expected: n,
                            found: self.$name.len(),
                        }
                        .into());
                    }
                )*
                Ok(())
            }

            pub(crate) fn rows(self, nx: usize) -> ColumnsMut<'a> {
                ColumnsMut {
                    $($name: self.$name,)*
                    nx,
                }
            }
        }

        /// One sample's values.
        #[derive(Clone, Copy)]
        pub(crate) struct Sample {
            $(pub(crate) $name: $ty,)*
        }

        impl Sample {
            pub(crate) const INVALID: Sample = Sample {
                $($name: $invalid,)*
            };
        }

        /// A block of rows of every column.
        pub(crate) struct ColumnsMut<'a> {
            $($name: &'a mut [$ty],)*
            nx: usize,
        }

        impl Rows for ColumnsMut<'_> {
            fn split_rows(self, rows: usize) -> (Self, Self) {
                let at = (rows * self.nx).min(self.valid.len());
                $(let $name = self.$name.split_at_mut(at);)*
                (
                    ColumnsMut { $($name: $name.0,)* nx: self.nx },
                    ColumnsMut { $($name: $name.1,)* nx: self.nx },
                )
            }
        }

        impl ColumnsMut<'_> {
            #[inline(always)]
            pub(crate) fn set(&mut self, i: usize, s: Sample) {
                $(self.$name[i] = s.$name;)*
            }

            /// Row `r` of the block, every column.
            #[inline(always)]
            pub(crate) fn row(&mut self, r: usize) -> ColumnsRow<'_> {
                let at = r * self.nx..(r + 1) * self.nx;
                ColumnsRow {
                    $($name: &mut self.$name[at.clone()],)*
                }
            }
        }

        /// One row of every column, for a writer that fills a row column
        /// by column.
        pub(crate) struct ColumnsRow<'a> {
            $(pub(crate) $name: &'a mut [$ty],)*
        }
    };
}

crate::solution_map_columns!(define_columns);

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
}

impl Varying {
    /// `"driving"` or `"driven"`: which center point varies.
    pub fn as_str(&self) -> &'static str {
        match self {
            Varying::Driving { .. } => "driving",
            Varying::Driven { .. } => "driven",
        }
    }

    /// The fixed dyad.
    pub fn fixed(&self) -> Dyad {
        match *self {
            Varying::Driving { driven } => driven,
            Varying::Driven { driving } => driving,
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

/// What the map was computed for and how many samples are acceptable, not
/// every value of every column (those are [`SolutionMap::columns`]).
impl core::fmt::Debug for SolutionMap {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let count = |c: &[bool]| c.iter().filter(|&&b| b).count();
        f.debug_struct("SolutionMap")
            .field("context", &self.context)
            .field("samples", &self.columns.valid.len())
            .field("branch_free", &count(&self.columns.branch_free))
            .field("acceptable", &count(&self.columns.acceptable))
            .finish()
    }
}

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
    /// As [`Task::four_bar`] (for an invalid sample).
    pub fn linkage(&self, k: usize) -> Result<SynthesizedFourBar> {
        let p = self.point(k);
        let d = self.task.dyad_from_center(p)?;
        match self.varying {
            Varying::Driving { driven } => self.task.four_bar(&d, &driven),
            Varying::Driven { driving } => self.task.four_bar(&driving, &d),
        }
    }
}

/// What the per-sample evaluation of every map shares, for any number of
/// poses: the prepared limits and constraints, and the scales of the
/// figures. The one place a sample's columns are computed from a
/// linkage's figures.
pub(crate) struct Judge<'a> {
    task: &'a Task,
    /// Links shorter than this make no linkage.
    pub(crate) tiny: f64,
    /// The task's coupler point at pose 1 and `1 / Task::span`.
    point: Point2<f64>,
    inv_span: f64,
    limits: &'a DesignLimits,
    prepared: Prepared,
    /// The cancel flag of the computation (a clearance test checks it).
    cancel: Option<&'a AtomicBool>,
}

impl Judge<'_> {
    /// The task's coupler point at pose 1 (for the members' length).
    pub(crate) fn point(&self) -> Point2<f64> {
        self.point
    }
}

impl<'a> Judge<'a> {
    pub(crate) fn new(
        task: &'a Task,
        limits: &'a DesignLimits,
        constraints: &Constraints,
    ) -> Result<Self> {
        limits.validate()?;
        let prepared = constraints.prepare()?;
        if let Some(env) = &constraints.envelope {
            if !task
                .poses()
                .iter()
                .all(|p| prepared.in_envelope(p.position))
            {
                return Err(InvalidInput::Polygon {
                    name: "envelope".to_owned(),
                    vertices: env.len(),
                    problem: crate::error::PolygonProblem::ExcludesPoses,
                }
                .into());
            }
        }
        Ok(Judge {
            task,
            tiny: tolerance::POINT * task.scale(),
            point: task.poses()[0].position,
            inv_span: 1.0 / task.span(),
            limits,
            prepared,
            cancel: None,
        })
    }

    /// The judge, its clearance tests stopping once `control` is cancelled.
    pub(crate) fn with_control(mut self, control: &Control<'a>) -> Self {
        self.cancel = control.cancel_flag();
        self
    }

    /// The sample for figures `fig` with branch flag `branch_free`, where
    /// `candidates` are the varying center points (each must lie on the
    /// base plate) and `driving`, `driven` the linkage's dyads (for the
    /// constraints).
    #[inline]
    pub(crate) fn sample(
        &self,
        fig: Option<LinkageFigures>,
        branch_free: bool,
        candidates: &[Point2<f64>],
        driving: Dyad,
        driven: Dyad,
    ) -> Sample {
        let Some(f) = fig else {
            return Sample::INVALID;
        };
        let members = members_length(f.lengths, driving.circle, driven.circle, self.point);
        self.sample_sized(f, branch_free, candidates, driving, driven, members)
    }

    /// The `acceptable` column: branch-free, the limits met (`meets`, asked
    /// only for a branch-free sample), every candidate on the base plate,
    /// and the linkage clear of the obstacles.
    #[inline(always)]
    pub(crate) fn acceptable(
        &self,
        branch_free: bool,
        meets: impl FnOnce() -> bool,
        candidates: &[Point2<f64>],
        driving: Dyad,
        driven: Dyad,
    ) -> bool {
        branch_free
            && meets()
            && candidates.iter().all(|&c| self.prepared.pivot_ok(c))
            && (!self.prepared.checks_motion()
                || self
                    .task
                    .four_bar(&driving, &driven)
                    .is_ok_and(|fb| self.prepared.motion_ok(&fb, self.cancel)))
    }

    /// `1 / Task::span`: the size ratio per length.
    pub(crate) fn inv_span(&self) -> f64 {
        self.inv_span
    }

    /// Whether `acceptable` is branch-free and the limits alone (no base
    /// plate, no obstacles, no envelope, no size limits).
    pub(crate) fn unconstrained(&self) -> bool {
        self.prepared.is_empty() && !self.limits.limits_size()
    }

    /// The limits behind `acceptable`.
    pub(crate) fn limits(&self) -> &DesignLimits {
        self.limits
    }

    /// [`sample`](Self::sample) of a linkage whose members' total length
    /// ([`members_length`]) is `members`.
    #[inline(always)]
    pub(crate) fn sample_sized(
        &self,
        f: LinkageFigures,
        branch_free: bool,
        candidates: &[Point2<f64>],
        driving: Dyad,
        driven: Dyad,
        members: f64,
    ) -> Sample {
        let acceptable = self.acceptable(
            branch_free,
            || self.limits.meets(&f) && self.limits.meets_size(f.lengths, members * self.inv_span),
            candidates,
            driving,
            driven,
        );
        Sample {
            valid: true,
            branch_free,
            grashof: f.grashof.code(),
            input_full: f.input_full,
            direction: f.direction.code(),
            one_circuit: f.one_circuit,
            min_transmission_rad: f.min_transmission as f32,
            link_ratio: f.link_ratio as f32,
            size_ratio: (members * self.inv_span) as f32,
            acceptable,
        }
    }
}

/// What the per-sample evaluation of either three-pose map shares: the
/// task's motion and maps, and the [`Judge`].
pub(crate) struct Sampler<'a> {
    pub(super) judge: Judge<'a>,
    pub(super) maps: &'a Maps,
    pub(super) motion: &'a Motion,
}

impl<'a> Sampler<'a> {
    pub(crate) fn new(
        task: &'a Task,
        limits: &'a DesignLimits,
        constraints: &Constraints,
    ) -> Result<Self> {
        limits.validate()?;
        let maps = task.three_poses("the solution map")?;
        Ok(Sampler {
            judge: Judge::new(task, limits, constraints)?,
            maps,
            motion: task.motion(),
        })
    }

    /// The sampler, its clearance tests stopping once `control` is
    /// cancelled.
    pub(crate) fn with_control(mut self, control: &Control<'a>) -> Self {
        self.judge = self.judge.with_control(control);
        self
    }

    /// The moving pivot at the three poses of the dyad centered at `p` (its
    /// circle point by the closed form), or `None` where it does not exist.
    #[inline(always)]
    fn moving_pivots(&self, p: Point2<f64>) -> Option<[Point2<f64>; 3]> {
        let q = self.maps.circle_point_fast(p)?;
        Some([q, self.motion.first_to(1, q), self.motion.first_to(2, q)])
    }

    /// The moving pivot of a fixed dyad at the three poses.
    pub(crate) fn fixed_pivots(&self, d: &Dyad) -> [Point2<f64>; 3] {
        [0, 1, 2].map(|k| self.motion.first_to(k, d.circle))
    }

    /// The sample of candidate driving center `a0` of a driving map with
    /// the driven dyad `driven` (moving pivot `c` at the three poses) and
    /// the branch flag `branch_free`: one sample of
    /// [`Filemon::solution_map`].
    #[inline]
    pub(crate) fn driving_sample(
        &self,
        a0: Point2<f64>,
        driven: Dyad,
        c: &[Point2<f64>; 3],
        branch_free: bool,
    ) -> Sample {
        let Some(a) = self.moving_pivots(a0) else {
            return Sample::INVALID;
        };
        let fig = figures::<false, 3>(a0, &a, driven.center, c, self.judge.tiny);
        self.judge
            .sample(fig, branch_free, &[a0], Dyad::new(a0, a[0]), driven)
    }
}

/// Fills a map's columns, `nx` samples a row and `ny` rows, from
/// `eval(j, i)` (row `j`, column `i`), over blocks of rows on the
/// [`engine`](crate::engine).
pub(crate) fn fill_rows(
    nx: usize,
    ny: usize,
    columns: ColumnsOut<'_>,
    control: &Control<'_>,
    eval: impl Fn(usize, usize) -> Sample + Sync,
) -> Result<()> {
    run_blocks(nx, ny, columns.rows(nx), control, |j0, mut block, rows| {
        for r in 0..rows {
            let j = j0 + r;
            for i in 0..nx {
                block.set(r * nx + i, eval(j, i));
            }
        }
    })
}

/// Fills a map's columns from `eval(k, point)`, over blocks of rows.
fn fill(
    grid: &Grid,
    columns: ColumnsOut<'_>,
    control: &Control<'_>,
    eval: impl Fn(usize, Point2<f64>) -> Sample + Sync,
) -> Result<()> {
    let nx = grid.nx();
    fill_rows(nx, grid.ny(), columns, control, |j, i| {
        eval(j * nx + i, Point2::new(grid.x(i), grid.y(j)))
    })
}

impl MapContext {
    fn new(
        grid: &Grid,
        task: &Task,
        varying: Varying,
        limits: &DesignLimits,
        constraints: &Constraints,
    ) -> Self {
        MapContext {
            grid: *grid,
            task: *task,
            varying,
            limits: *limits,
            constraints: constraints.clone(),
        }
    }
}

impl Filemon {
    /// The solution-space map over candidate driving center points `A0`
    /// on `grid` (see [`design`](crate::design)), following `control`. The
    /// branch-free flag is exactly the `conic` branch map; the other
    /// figures come from the linkage at each sample.
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for invalid limits or constraints;
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory) when the columns
    /// cannot be allocated; [`Error::Cancelled`](crate::Error::Cancelled).
    pub fn solution_map(
        &self,
        grid: &Grid,
        limits: &DesignLimits,
        constraints: &Constraints,
        control: &Control<'_>,
    ) -> Result<SolutionMap> {
        // The arguments are checked before the columns are allocated.
        let sampler = Sampler::new(self.task(), limits, constraints)?.with_control(control);
        let mut columns = Columns::for_overwrite(grid.len())?;
        self.fill_solution_map(&sampler, grid, columns.as_out(), control)?;
        Ok(SolutionMap {
            context: self.map_context(grid, limits, constraints),
            columns,
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
        limits: &DesignLimits,
        constraints: &Constraints,
        out: ColumnsOut<'_>,
        control: &Control<'_>,
    ) -> Result<MapContext> {
        let sampler = Sampler::new(self.task(), limits, constraints)?.with_control(control);
        out.check_len(grid.len())?;
        self.fill_solution_map(&sampler, grid, out, control)?;
        Ok(self.map_context(grid, limits, constraints))
    }

    fn map_context(
        &self,
        grid: &Grid,
        limits: &DesignLimits,
        constraints: &Constraints,
    ) -> MapContext {
        let varying = Varying::Driving {
            driven: self.driven(),
        };
        MapContext::new(grid, self.task(), varying, limits, constraints)
    }

    /// The columns of the map, the arguments checked.
    fn fill_solution_map(
        &self,
        sampler: &Sampler<'_>,
        grid: &Grid,
        out: ColumnsOut<'_>,
        control: &Control<'_>,
    ) -> Result<()> {
        let driven = self.driven();
        let mut branch = try_vec("a branch map", grid.len(), false)?;
        self.branch_map_into(grid, Method::Conic, &mut branch, control)?;
        let c = sampler.fixed_pivots(&driven);
        match DrivingKernel::new(sampler, driven, &c) {
            Some(kernel) => {
                let xs = DrivingKernel::padded_xs(grid)?;
                kernel.fill(grid, &xs, &branch, out.rows(grid.nx()), control)
            }
            None => fill(grid, out, control, |k, a0| {
                sampler.driving_sample(a0, driven, &c, branch[k])
            }),
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
    /// [`InvalidInput`] for invalid limits or constraints, or a driving
    /// dyad that is not a dyad of this task; as [`Filemon::solution_map`].
    pub fn driven_solution_map(
        &self,
        driving: &Dyad,
        grid: &Grid,
        limits: &DesignLimits,
        constraints: &Constraints,
        control: &Control<'_>,
    ) -> Result<SolutionMap> {
        // The arguments are checked before the columns are allocated.
        let sampler = self
            .driven_sampler(driving, limits, constraints)?
            .with_control(control);
        let mut columns = Columns::for_overwrite(grid.len())?;
        self.fill_driven_map(&sampler, driving, grid, columns.as_out(), control)?;
        let varying = Varying::Driven { driving: *driving };
        Ok(SolutionMap {
            context: MapContext::new(grid, self, varying, limits, constraints),
            columns,
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
        limits: &DesignLimits,
        constraints: &Constraints,
        out: ColumnsOut<'_>,
        control: &Control<'_>,
    ) -> Result<MapContext> {
        let sampler = self
            .driven_sampler(driving, limits, constraints)?
            .with_control(control);
        out.check_len(grid.len())?;
        self.fill_driven_map(&sampler, driving, grid, out, control)?;
        let varying = Varying::Driven { driving: *driving };
        Ok(MapContext::new(grid, self, varying, limits, constraints))
    }

    /// The sampler of the driven map, once the driving dyad is checked to
    /// be one of this task.
    fn driven_sampler<'a>(
        &'a self,
        driving: &Dyad,
        limits: &'a DesignLimits,
        constraints: &Constraints,
    ) -> Result<Sampler<'a>> {
        let sampler = Sampler::new(self, limits, constraints)?;
        let d = self.dyad_from_center(driving.center)?;
        let spread = (d.circle - driving.circle).norm() / (self.scale() + driving.length());
        if spread.is_nan() || spread > tolerance::DYAD {
            return Err(InvalidInput::NotADyad {
                which: "driving dyad",
                spread,
                tolerance: tolerance::DYAD,
            }
            .into());
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
