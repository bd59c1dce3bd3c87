//! The designs of a search with a linear actuator
//! ([`DesignOptions::actuator`]): each ranked, distinct design with the
//! best clear placement of its actuator, lazily in rank order (the module
//! docs of [`search`](super), "With a linear actuator").

use nalgebra::Point2;

use super::{Design, DesignOptions, grid_over};
use crate::design::actuator::{Actuator, ActuatorContext, ActuatorOptions};
use crate::design::{DesignLimits, MapOptions, Ranking};
use crate::engine::Control;
use crate::error::{Error, Result, count_in, finite_point, in_range};
use crate::geom::Viewport;
use crate::linkage::actuator::ActuatorLink;
use crate::synthesis::SynthesizedFourBar;

/// How [`Task::design`](crate::Task::design) places a linear actuator on
/// every design.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ActuatorSearch {
    /// The link it acts on, its stroke ratio limit, the travel's samples.
    pub options: ActuatorOptions,
    /// Its moving point `Q` where it is at pose 1; `None` (default): each
    /// of [`points`](Self::points) is tried.
    pub point: Option<Point2<f64>>,
    /// Candidate ground pivots along the longer side of their box (2 to
    /// [`MAX_SAMPLES`](Self::MAX_SAMPLES), default 64): the pivot region's
    /// box, or with pivots anywhere the linkage's box over its poses
    /// widened by its size on each side.
    pub samples: usize,
    /// The largest size ratio of the linkage with the open actuator (its
    /// size with the actuator's longest length over the task's span,
    /// [`Actuator::size_ratio`]) a placement may have: at least 1,
    /// infinity for no limit; `None` (default): the design's
    /// [`DesignLimits::max_size_ratio`], the one the linkage alone meets
    /// ([`limits`](Self::limits)). A strut reaching beyond the linkage can
    /// be given more room than the linkage (a task file's `[actuator]`
    /// `max_size_ratio`).
    pub max_size_ratio: Option<f64>,
}

impl Default for ActuatorSearch {
    fn default() -> Self {
        ActuatorSearch {
            options: ActuatorOptions::default(),
            point: None,
            samples: 64,
            max_size_ratio: None,
        }
    }
}

/// How many placements of one map are asked for, best first: a ranking
/// over the acceptable samples gives only acceptable, clear placements (the
/// map judges a sample as its placement), the margin's the monotone ones,
/// of which the first acceptable and clear is taken.
const CANDIDATES: usize = 12;

impl ActuatorSearch {
    /// The most ground pivots along the longer side of their box.
    pub const MAX_SAMPLES: usize = 512;

    /// Checks the options.
    ///
    /// # Errors
    ///
    /// As [`ActuatorOptions::validate`]; [`InvalidInput`](crate::InvalidInput)
    /// for a sample count out of range, a non-finite point or a
    /// [`max_size_ratio`](Self::max_size_ratio) below 1 or NaN
    /// ([`OutsideRange`](crate::InvalidInput::OutsideRange) naming
    /// `actuator max_size_ratio`).
    pub fn validate(&self) -> Result<()> {
        self.options.validate()?;
        count_in("actuator samples", self.samples, 2, Self::MAX_SAMPLES)?;
        if let Some(p) = self.point {
            finite_point(["actuator point x", "actuator point y"], p)?;
        }
        if let Some(r) = self.max_size_ratio {
            in_range(
                "actuator max_size_ratio",
                r,
                1.0,
                f64::INFINITY,
                " (the linkage with the open actuator over the task's span)",
            )?;
        }
        Ok(())
    }

    /// The limits a placement meets on a design searched under `limits`:
    /// those, with [`max_size_ratio`](Self::max_size_ratio) in place of
    /// theirs where given.
    pub fn limits(&self, limits: &DesignLimits) -> DesignLimits {
        DesignLimits {
            max_size_ratio: self.max_size_ratio.unwrap_or(limits.max_size_ratio),
            ..*limits
        }
    }

    /// The moving points tried for `linkage` where it is at pose 1: the
    /// given point; or, on the coupler, its moving pivots `A` and `C`,
    /// the points a quarter, half and three quarters of the way from `A`
    /// to `C`, and the task's coupler point and the middles of `A` and `C`
    /// with it; on the crank (the rocker), its moving pivot and the middle
    /// of the link.
    pub fn points(&self, linkage: &SynthesizedFourBar) -> Vec<Point2<f64>> {
        if let Some(p) = self.point {
            return vec![p];
        }
        let (a, c) = (linkage.driving.circle, linkage.driven.circle);
        let mid = |p: Point2<f64>, q: Point2<f64>, t: f64| p + (q - p) * t;
        match self.options.link {
            ActuatorLink::Crank => vec![a, mid(linkage.driving.center, a, 0.5)],
            ActuatorLink::Rocker => vec![c, mid(linkage.driven.center, c, 0.5)],
            ActuatorLink::Coupler => {
                let p = coupler_point(linkage);
                vec![
                    mid(a, c, 0.5),
                    mid(a, c, 0.25),
                    mid(a, c, 0.75),
                    a,
                    c,
                    p,
                    mid(a, p, 0.5),
                    mid(c, p, 0.5),
                ]
            }
        }
    }

    /// The box of candidate ground pivots for `linkage` under `options`.
    fn view(&self, linkage: &SynthesizedFourBar, options: &DesignOptions) -> Viewport {
        if let Some(b) = options.space.pivots.bounds() {
            return b;
        }
        let mut pts = vec![linkage.driving.center, linkage.driven.center];
        pts.extend(self.points(linkage));
        pts.push(coupler_point(linkage));
        let (mut xmin, mut xmax, mut ymin, mut ymax) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for p in pts {
            (xmin, xmax) = (xmin.min(p.x), xmax.max(p.x));
            (ymin, ymax) = (ymin.min(p.y), ymax.max(p.y));
        }
        let h = linkage.size().max(xmax - xmin).max(ymax - ymin);
        Viewport {
            xmin: xmin - h,
            xmax: xmax + h,
            ymin: ymin - h,
            ymax: ymax + h,
        }
    }

    /// The best clear placement for `d`'s linkage under `options` (its
    /// limits, space and ranking), if any, following `control`'s cancel
    /// flag.
    pub(super) fn place(
        &self,
        d: &Design,
        options: &DesignOptions,
        control: &Control<'_>,
    ) -> Result<Option<Actuator>> {
        // A slider design is refused with an actuator (DesignOptions::validate).
        let Some(linkage) = d.linkage.four_bar() else {
            return Ok(None);
        };
        let grid = grid_over(&self.view(linkage, options), self.samples)?;
        let map_options =
            MapOptions::new(&self.limits(&options.limits), &options.space.constraints())?;
        let mut best: Option<Actuator> = None;
        for q in self.points(linkage) {
            let ctx = match ActuatorContext::new(linkage, q, &grid, &map_options, &self.options) {
                Ok(ctx) => ctx,
                // A point on a fixed pivot, or a linkage without a travel.
                Err(Error::Degenerate(_) | Error::Drive(_)) => continue,
                Err(e) => return Err(e),
            };
            let map = ctx.map(control)?;
            let found = map.best_placements(Ranking::new(CANDIDATES, options.rank_by))?;
            let clear = found
                .into_iter()
                .find(|a| a.acceptable && a.monotone && a.clear);
            if let Some(a) = clear
                && best.as_ref().is_none_or(|b| a.score > b.score)
            {
                best = Some(a);
            }
        }
        Ok(best)
    }
}

/// The task's coupler point where it is at pose 1.
fn coupler_point(linkage: &SynthesizedFourBar) -> Point2<f64> {
    let (a, c) = (linkage.driving.circle, linkage.driven.circle);
    let u = (c - a).normalize();
    let n = nalgebra::Vector2::new(-u.y, u.x);
    a + u * linkage.coupler_point.x + n * linkage.coupler_point.y
}
