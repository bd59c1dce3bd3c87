//! The search with a driven slider ([`DrivenKind::Slider`]): slider-cranks
//! ([`Task::slider_crank`]), a driving crank of the task with a slider
//! dyad of the task, judged on the exact linkage by the same judge, refined
//! by the same simplex, ranked, separated and reported (census, near
//! misses) as the four-bars are (module docs of the search, "A driven
//! slider").
//!
//! * three poses: `A0` free in the plane, the slider's pin free on the
//!   slider circle (one parameter, [`SliderLocus::point_at`]): a coarse
//!   pass over `coarse_driving` crank pivots along the search box's longer
//!   side times `coarse_driven` pins along the circle, then each start
//!   refined over `(A0, t)`;
//! * four poses: the center-point curve (`coarse_pairs` samples of its
//!   parameter) times the finitely many slider points, each start refined
//!   along the curve parameter;
//! * five poses: every Burmester point times every slider Burmester point.
//!
//! The slider-crank's figures are read as the slider solution map reads
//! them (`design::map_slider`): the link ratio of crank and coupler, the
//! links [`DesignLimits::max_link_length`](crate::DesignLimits::max_link_length)
//! bounds the crank, the coupler and the offset, the change-point margin
//! the [`SliderCrank::rotatability_margin`](crate::SliderCrank::rotatability_margin).
//!
//! [`SliderLocus::point_at`]: crate::synthesis::three::SliderLocus

use core::f64::consts::PI;
use core::sync::atomic::{AtomicUsize, Ordering};

use rayon::prelude::*;

use super::{
    CENSUS_DRIVING, COARSE_SHARE, DesignOptions, DesignReport, DrivenKind, Exact, Figures,
    PROGRESS, SearchPoint, Start, Verdict, dyad_at, grid_over, pick_starts,
};
use crate::engine::Control;
use crate::error::{Error, InvalidInput, Result};
use crate::linkage::Direction;
use crate::synthesis::three::SliderLocus;
use crate::synthesis::{Dyad, DyadKind, SliderDyad, SynthesizedSliderCrank, Task};

/// What the judge reads of a slider-crank.
#[derive(Debug, Clone, Copy)]
pub(super) struct SliderFigures {
    pub(super) branch_free: bool,
    pub(super) direction: Direction,
    pub(super) one_circuit: bool,
    pub(super) min_transmission: f64,
    pub(super) link_ratio: f64,
    pub(super) input_full: bool,
    pub(super) margin: f64,
    /// Crank, coupler, offset (and a zero).
    pub(super) lengths: [f64; 4],
}

impl SliderFigures {
    fn of(sc: &SynthesizedSliderCrank) -> Self {
        let l = &sc.linkage;
        SliderFigures {
            branch_free: sc.is_branch_free(),
            direction: sc.direction,
            one_circuit: sc.one_circuit,
            min_transmission: sc.min_transmission,
            link_ratio: l.link_ratio(),
            input_full: l.turns_fully(),
            margin: l.rotatability_margin(),
            lengths: [l.crank(), l.coupler(), l.offset().abs(), 0.0],
        }
    }
}

/// Refuses what a slider design does not take: a motor or an actuator
/// (the drive and the strut are searched on a four-bar). Obstacles and an
/// envelope are checked over the slider-crank's travel
/// (`Prepared::slider_checked`).
pub(super) fn check_options(options: &DesignOptions) -> Result<()> {
    if options.driven != DrivenKind::Slider {
        return Ok(());
    }
    let what = if options.motor.is_some() {
        "a design with a motor (the drive is searched on a four-bar's input; design without \
         the motor, or with driven=\"revolute\")"
    } else if options.actuator.is_some() {
        "a design with a linear actuator (placed on a four-bar; design without the actuator, \
         or with driven=\"revolute\")"
    } else {
        return Ok(());
    };
    Err(InvalidInput::DrivenKind {
        what,
        found: "slider",
    }
    .into())
}

impl Exact<'_> {
    /// The verdict on the linkage of a driving dyad and a driven dyad of
    /// either kind, as [`judge`](Self::judge).
    pub(super) fn judge_kind(
        &self,
        driving: &Dyad,
        driven: &DyadKind,
        all: bool,
    ) -> Option<Verdict> {
        match driven {
            DyadKind::Revolute(d) => self.judge(driving, d, all),
            DyadKind::Slider(s) => {
                self.judge_slider(driving, s, all, self.limits.min_grashof_margin)
            }
            DyadKind::Inverted(_) => None,
        }
    }

    /// The verdict on the slider-crank of `driving` and `driven`, with the
    /// change-point margin `min_margin` (as [`judge_with`](Self::judge_with)).
    fn judge_slider(
        &self,
        driving: &Dyad,
        driven: &SliderDyad,
        all: bool,
        min_margin: f64,
    ) -> Option<Verdict> {
        let sc = self.task.slider_crank(driving, driven).ok()?;
        self.verdict_of(
            driving,
            DyadKind::Slider(*driven),
            Figures::Slider(SliderFigures::of(&sc)),
            sc.size(),
            all,
            min_margin,
        )
    }
}

/// A coarse candidate: the driving dyad, the slider, where.
type Candidate = (Dyad, SliderDyad, SearchPoint);

/// One row of the coarse pass: judged, acceptable, the starts kept.
type RowOut = (usize, usize, Vec<(Start, Verdict)>);

/// The coarse pass polls the cancel flag every this many candidates.
const POLL: usize = 256;

impl Task {
    /// [`Task::design`] with a driven slider (module docs).
    pub(super) fn design_slider(
        &self,
        options: &DesignOptions,
        control: &Control<'_>,
    ) -> Result<DesignReport> {
        let exact = Exact::new(self, options, control)?;
        match self.len() {
            3 => {
                let locus = self.slider_locus("Task::design")?;
                self.design_slider_three(&exact, &locus, options, control)
            }
            _ => {
                let sliders = self.finite_sliders()?;
                self.design_slider_exact(&exact, &sliders, options, control)
            }
        }
    }

    /// The slider dyads of four or five poses; a typed error saying why
    /// when there is none.
    fn finite_sliders(&self) -> Result<Vec<SliderDyad>> {
        let sliders = self.slider_dyads(1)?;
        if sliders.is_empty() {
            // Task::slider_dyad names the reason there is none.
            self.slider_dyad(self.poses()[0].position)?;
        }
        Ok(sliders)
    }

    /// Judges every candidate, row by row (a row: one slider with every
    /// driving dyad, `cand(row, i)` the `i`-th of `row_len`), in parallel,
    /// polling the cancel flag every [`POLL`] candidates, progress over the
    /// coarse share; the counts into `report`. Keeps the acceptable ones
    /// of each row as starts: all with `keep` `None`, else the best `keep`
    /// at least the separation apart ([`pick_starts`]), so that memory does
    /// not grow with the grid.
    #[allow(clippy::too_many_arguments)]
    fn slider_coarse(
        &self,
        exact: &Exact<'_>,
        rows: usize,
        row_len: usize,
        cand: &(dyn Fn(usize, usize) -> Option<Candidate> + Sync),
        keep: Option<(f64, usize)>,
        report: &mut DesignReport,
        control: &Control<'_>,
    ) -> Result<Vec<(Start, Verdict)>> {
        let done = AtomicUsize::new(0);
        let total = (rows * row_len).max(1);
        let out: Vec<RowOut> = (0..rows)
            .into_par_iter()
            .map(|row| {
                let (mut judged, mut acceptable) = (0, 0);
                let mut ok = Vec::new();
                for i in 0..row_len {
                    if i % POLL == 0 && control.is_cancelled() {
                        break;
                    }
                    let Some((a, s, at)) = cand(row, i) else {
                        continue;
                    };
                    let margin = exact.limits.min_grashof_margin;
                    let Some(v) = exact.judge_slider(&a, &s, false, margin) else {
                        continue;
                    };
                    judged += 1;
                    if let (true, Some(score)) = (v.acceptable(), v.score) {
                        acceptable += 1;
                        let start = Start {
                            point: at,
                            driving: a.center,
                            driven: s.circle,
                            score,
                            size: v.size_ratio,
                        };
                        ok.push((start, v));
                    }
                }
                if let Some((sep, n)) = keep {
                    let starts = pick_starts(ok.iter().map(|(s, _)| *s).collect(), sep, n);
                    ok.retain(|(s, _)| {
                        starts
                            .iter()
                            .any(|k| k.point == s.point && k.score == s.score)
                    });
                }
                let d = done.fetch_add(row_len, Ordering::Relaxed) + row_len;
                control.report(COARSE_SHARE * d / total, PROGRESS);
                (judged, acceptable, ok)
            })
            .collect();
        if control.is_cancelled() {
            return Err(Error::Cancelled {
                done: done.into_inner(),
                total,
            });
        }
        let mut all = Vec::new();
        for (judged, acceptable, ok) in out {
            report.coarse_candidates += judged;
            report.coarse_acceptable += acceptable;
            all.extend(ok);
        }
        Ok(all)
    }

    /// Three poses: `A0` on a grid of the search box times pins along the
    /// slider circle, refined over `(A0, t)`.
    fn design_slider_three(
        &self,
        exact: &Exact<'_>,
        locus: &SliderLocus,
        options: &DesignOptions,
        control: &Control<'_>,
    ) -> Result<DesignReport> {
        let line = locus.line();
        // The circle's parameter over a turn; the line's over (-pi/2, pi/2)
        // (the stereographic samples of `Task::slider_dyads`).
        let param = |j: usize, n: usize| {
            if line {
                PI * (j as f64 + 0.5) / n as f64 - 0.5 * PI
            } else {
                2.0 * PI * j as f64 / n as f64
            }
        };
        let slider_at = |t: f64| -> Option<SliderDyad> {
            if line && (t.is_nan() || t.abs() >= 0.5 * PI) {
                return None;
            }
            self.guided(locus.point_at(t)?, None)
        };
        let search_box = options.space.search_box(self, &options.limits);
        let driving = grid_over(&search_box, options.coarse_driving)?;
        // The driving dyads of a grid, in parallel, following the cancel
        // flag (a grid at the most is 65536 centers).
        let dyads = |g: &crate::geom::Grid| -> Result<Vec<Dyad>> {
            let out: Vec<Option<Dyad>> = (0..g.len())
                .into_par_iter()
                .map(|k| {
                    if control.is_cancelled() {
                        return None;
                    }
                    self.dyad_from_center(g.point(k % g.nx(), k / g.nx())).ok()
                })
                .collect();
            if control.is_cancelled() {
                return Err(Error::Cancelled {
                    done: 0,
                    total: g.len(),
                });
            }
            Ok(out.into_iter().flatten().collect())
        };
        let sliders = |n: usize| -> Vec<(f64, SliderDyad)> {
            (0..n)
                .filter_map(|j| {
                    let t = param(j, n);
                    Some((t, slider_at(t)?))
                })
                .collect()
        };
        let pair = |a: &Dyad, (t, s): &(f64, SliderDyad)| -> Candidate {
            let at = SearchPoint::SliderCircle {
                driving: a.center,
                slider: *t,
            };
            (*a, *s, at)
        };
        let sl = sliders(options.coarse_driven);
        let a = dyads(&driving)?;
        let sep = options.separation(self);
        let mut report = self.report(options, Some(search_box));
        let coarse = self.slider_coarse(
            exact,
            sl.len(),
            a.len(),
            &|j, i| Some(pair(&a[i], &sl[j])),
            Some((sep, options.starts)),
            &mut report,
            control,
        )?;
        let starts = pick_starts(
            coarse.into_iter().map(|(s, _)| s).collect(),
            sep,
            options.starts,
        );
        let n = options.coarse_driven as f64;
        let dt = if line { PI / n } else { 2.0 * PI / n };
        let h = [driving.dx(), driving.dy(), dt];
        let eval = |x: &[f64], margin: f64| {
            let (a, s) = (dyad_at(self, x)?, slider_at(x[2])?);
            exact.judge_slider(&a, &s, false, margin)
        };
        let refined = self.refine_starts(&starts, &h, options, control, &eval)?;
        report.evaluations = refined.iter().map(|d| d.evaluations).sum();
        report.designs = self.finish_designs(refined, options, &mut report, control)?;
        if report.designs.is_empty() {
            let census_box = grid_over(&search_box, CENSUS_DRIVING)?;
            let a = dyads(&census_box)?;
            let census: Vec<(Dyad, DyadKind)> = sl
                .iter()
                .flat_map(|(_, s)| a.iter().map(|a| (*a, DyadKind::Slider(*s))))
                .collect();
            self.census(exact, options, &census, &mut report, control)?;
        }
        control.report(PROGRESS, PROGRESS);
        Ok(report)
    }

    /// Four poses (the center-point curve times the slider points, refined
    /// along the curve) and five (Burmester points times slider Burmester
    /// points).
    fn design_slider_exact(
        &self,
        exact: &Exact<'_>,
        sliders: &[SliderDyad],
        options: &DesignOptions,
        control: &Control<'_>,
    ) -> Result<DesignReport> {
        let four = self.len() == 4;
        // The driving dyads with their curve parameter (four poses) or
        // Burmester index (five).
        let driving: Vec<(f64, Dyad)> = if four {
            let f = self.four_positions("Task::design")?;
            let n = options.coarse_pairs;
            let length = f.parameter_length()?;
            f.parameter_samples(n)?
                .into_iter()
                .enumerate()
                .filter_map(|(i, d)| Some(((i as f64 + 0.5) * length / n as f64, d?.dyad())))
                .collect()
        } else {
            let f = self.five_positions("Task::design")?;
            f.burmester_points()
                .iter()
                .enumerate()
                .map(|(i, d)| (i as f64, *d))
                .collect()
        };
        let cand = |j: usize, i: usize| -> Candidate {
            let (t, a) = driving[i];
            let at = SearchPoint::SliderPoint {
                driving: t,
                slider: j,
            };
            (a, sliders[j], at)
        };
        let sep = options.separation(self);
        // Five poses keep every acceptable pair (they are the designs).
        let keep = four.then_some((sep, options.starts));
        let mut report = self.report(options, None);
        let coarse = self.slider_coarse(
            exact,
            sliders.len(),
            driving.len(),
            &|j, i| Some(cand(j, i)),
            keep,
            &mut report,
            control,
        )?;
        let found = if four {
            let f = self.four_positions("Task::design")?;
            let length = f.parameter_length()?;
            let starts = pick_starts(
                coarse.into_iter().map(|(s, _)| s).collect(),
                sep,
                options.starts,
            );
            let step = length / options.coarse_pairs as f64;
            // Refined along the curve, each start with its own slider.
            let mut refined = Vec::new();
            for (j, s) in sliders.iter().enumerate() {
                let mine: Vec<Start> = starts
                    .iter()
                    .filter(|st| {
                        matches!(st.point, SearchPoint::SliderPoint { slider, .. } if slider == j)
                    })
                    .copied()
                    .collect();
                if mine.is_empty() {
                    continue;
                }
                let eval = |x: &[f64], margin: f64| {
                    if !(0.0..=length).contains(&x[0]) {
                        return None;
                    }
                    let a = f.dyad_at_parameter(x[0]).ok()?.dyad();
                    exact.judge_slider(&a, s, false, margin)
                };
                refined.extend(self.refine_starts(&mine, &[step], options, control, &eval)?);
            }
            report.evaluations = refined.iter().map(|d| d.evaluations).sum();
            refined
        } else {
            report.evaluations = report.coarse_candidates;
            coarse
                .into_iter()
                .filter_map(|(s, v)| {
                    Some(super::Design {
                        linkage: v.linkage(self)?,
                        score: s.score,
                        size_ratio: v.size_ratio,
                        ranked_by: options.rank_by,
                        coarse: s.point,
                        refined: s.point,
                        coarse_score: s.score,
                        evaluations: 1,
                        drive: None,
                        actuator: None,
                    })
                })
                .collect()
        };
        report.designs = self.finish_designs(found, options, &mut report, control)?;
        if report.designs.is_empty() {
            let census: Vec<(Dyad, DyadKind)> = sliders
                .iter()
                .flat_map(|s| driving.iter().map(|(_, a)| (*a, DyadKind::Slider(*s))))
                .collect();
            self.census(exact, options, &census, &mut report, control)?;
        }
        control.report(PROGRESS, PROGRESS);
        Ok(report)
    }
}
