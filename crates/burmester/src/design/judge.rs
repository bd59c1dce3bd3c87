//! The per-sample evaluation every map shares: the options checked once
//! ([`MapOptions`]), the figures of a linkage judged into a sample's
//! columns ([`Judge`]), the three-pose maps' candidates ([`Sampler`]), and
//! the fill of a map's rows on the [`engine`](crate::engine).

use core::sync::atomic::AtomicBool;

use nalgebra::Point2;

use crate::design::DesignLimits;
use crate::design::columns::{ColumnsOut, Sample};
use crate::design::constraints::Prepared;
use crate::design::options::MapOptions;
use crate::engine::{Control, run_blocks};
use crate::error::{InvalidInput, Result};
use crate::geom::Grid;
use crate::linkage::LinkageFigures;
use crate::linkage::figures::figures;
use crate::synthesis::three::Maps;
use crate::synthesis::{Dyad, Motion, SynthesizedSliderCrank, Task, members_length};
use crate::tolerance;

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
    prepared: &'a Prepared,
    /// The cancel flag of the computation (a clearance test checks it).
    cancel: Option<&'a AtomicBool>,
}

impl Judge<'_> {
    /// The task's coupler point at pose 1 (for the members' length).
    pub(crate) fn point(&self) -> Point2<f64> {
        self.point
    }

    /// The task.
    pub(crate) fn task(&self) -> &Task {
        self.task
    }

    /// The sample of a slider-crank `sc` with branch flag `branch_free`
    /// (module `map_slider`): its driving center must lie on the base
    /// plate, its moving parts clear the obstacles and stay inside the
    /// envelope over the travel (`Prepared::slider_motion_ok`).
    pub(crate) fn slider_sample(&self, sc: &SynthesizedSliderCrank, branch_free: bool) -> Sample {
        let l = &sc.linkage;
        let size_ratio = sc.size() * self.inv_span;
        let (input_full, link_ratio) = (l.turns_fully(), l.link_ratio());
        let lengths = [l.crank(), l.coupler(), l.offset().abs(), 0.0];
        let acceptable = branch_free
            && self.limits.meets_when(
                sc.one_circuit,
                sc.direction,
                link_ratio,
                input_full,
                l.rotatability_margin(),
                || sc.min_transmission >= self.limits.min_transmission,
            )
            && self.limits.meets_size(lengths, size_ratio)
            && self.prepared.pivot_ok(sc.driving.center)
            && self.prepared.slider_motion_ok(sc, self.cancel);
        Sample {
            valid: true,
            branch_free,
            grashof: crate::SolutionMap::GRASHOF_NONE,
            input_full,
            direction: sc.direction.code(),
            one_circuit: sc.one_circuit,
            min_transmission_rad: sc.min_transmission as f32,
            link_ratio: link_ratio as f32,
            size_ratio: size_ratio as f32,
            acceptable,
        }
    }
}

impl<'a> Judge<'a> {
    /// The judge of `task`'s samples by the options `options`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::Polygon`] for an envelope that leaves out a pose.
    pub(crate) fn new(task: &'a Task, options: &'a MapOptions) -> Result<Self> {
        let (limits, prepared) = (options.limits(), options.prepared());
        if let Some(env) = &options.constraints().envelope {
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
    pub(crate) judge: Judge<'a>,
    pub(crate) maps: &'a Maps,
    pub(crate) motion: &'a Motion,
}

impl<'a> Sampler<'a> {
    /// The sampler of three-pose `task`'s maps by the options `options`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NeedsPoses`] unless the task has three poses; as
    /// [`Judge::new`].
    pub(crate) fn new(task: &'a Task, options: &'a MapOptions) -> Result<Self> {
        let maps = task.three_poses("the solution map")?;
        Ok(Sampler {
            judge: Judge::new(task, options)?,
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
    pub(crate) fn moving_pivots(&self, p: Point2<f64>) -> Option<[Point2<f64>; 3]> {
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
    /// [`Filemon::solution_map`](crate::Filemon::solution_map).
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
pub(crate) fn fill(
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
