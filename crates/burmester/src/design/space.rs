//! The space a design must fit in: where the fixed pivots may go (the
//! machine frame), obstacles the moving links must clear, and an envelope
//! they must stay inside, over the whole travel.
//!
//! The largest allowed linkage is a limit, not a place:
//! [`DesignLimits::max_size_ratio`] (relative to the task) and
//! [`DesignLimits::max_link_length`] (in the task's units).

use nalgebra::Point2;

use crate::design::constraints::check_simple_polygon;
use crate::design::judge::Judge;
use crate::design::options::MapOptions;
use crate::design::{Constraints, DesignLimits};
use crate::error::{InvalidInput, Result};
pub(crate) use crate::geom::segment_distance;
use crate::geom::{Viewport, finite_bounds};
use crate::synthesis::Task;

/// Where the fixed pivots of a design may go.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum PivotRegion {
    /// Anywhere: the coarse pass samples [`Space::DEFAULT_REACH`] task
    /// sizes around the poses (or the box the size limit allows, module
    /// docs of [`search`](crate::design::search)); the refinement is not
    /// bounded.
    #[default]
    Anywhere,
    /// Inside a box (its edges included).
    Box(Viewport),
    /// Inside a simple polygon (vertices in order).
    Polygon(Vec<Point2<f64>>),
}

impl PivotRegion {
    /// A box, checked: finite numbers, `xmin < xmax`, `ymin < ymax`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] naming the coordinate (`"pivot_box
    /// xmin"`, ...); [`InvalidInput::OutsideRange`] for an inverted or
    /// empty box (naming `"pivot_box xmax"` or `"pivot_box ymax"`).
    pub fn boxed(xmin: f64, xmax: f64, ymin: f64, ymax: f64) -> Result<Self> {
        let names = [
            "pivot_box xmin",
            "pivot_box xmax",
            "pivot_box ymin",
            "pivot_box ymax",
        ];
        finite_bounds(names, [xmin, xmax, ymin, ymax])?;
        for (name, lo, hi) in [
            ("pivot_box xmax", xmin, xmax),
            ("pivot_box ymax", ymin, ymax),
        ] {
            if hi <= lo {
                return Err(InvalidInput::OutsideRange {
                    name,
                    value: hi,
                    min: lo,
                    max: f64::INFINITY,
                    unit: " (above the minimum: the box is inverted or empty)",
                }
                .into());
            }
        }
        Ok(PivotRegion::Box(Viewport::new(xmin, xmax, ymin, ymax)?))
    }

    /// `"anywhere"`, `"box"` or `"polygon"`.
    pub fn as_str(&self) -> &'static str {
        match self {
            PivotRegion::Anywhere => "anywhere",
            PivotRegion::Box(_) => "box",
            PivotRegion::Polygon(_) => "polygon",
        }
    }

    /// Checks the region.
    ///
    /// # Errors
    ///
    /// As [`PivotRegion::boxed`] for a box given as a value; for a polygon
    /// [`InvalidInput::Polygon`] named `"pivot_polygon"` (fewer than three
    /// vertices, no area, crossing edges) or [`InvalidInput::NotFinite`].
    pub fn validate(&self) -> Result<()> {
        match self {
            PivotRegion::Anywhere => Ok(()),
            PivotRegion::Box(v) => Self::boxed(v.xmin, v.xmax, v.ymin, v.ymax).map(|_| ()),
            PivotRegion::Polygon(p) => check_simple_polygon("pivot_polygon", p),
        }
    }

    /// Whether the fixed pivot `p` may go there.
    pub fn contains(&self, p: Point2<f64>) -> bool {
        match self {
            PivotRegion::Anywhere => true,
            PivotRegion::Box(v) => p.x >= v.xmin && p.x <= v.xmax && p.y >= v.ymin && p.y <= v.ymax,
            PivotRegion::Polygon(poly) => crate::design::constraints::inside_polygon(poly, p),
        }
    }

    /// How far `p` lies outside the region (0 inside).
    pub fn distance_outside(&self, p: Point2<f64>) -> f64 {
        if self.contains(p) {
            return 0.0;
        }
        match self {
            PivotRegion::Anywhere => 0.0,
            PivotRegion::Box(v) => {
                let dx = (v.xmin - p.x).max(p.x - v.xmax).max(0.0);
                let dy = (v.ymin - p.y).max(p.y - v.ymax).max(0.0);
                dx.hypot(dy)
            }
            PivotRegion::Polygon(poly) => (0..poly.len())
                .map(|k| segment_distance(p, poly[k], poly[(k + 1) % poly.len()]))
                .fold(f64::INFINITY, f64::min),
        }
    }

    /// The region as a polygon (a box's four corners), `None` for
    /// anywhere.
    pub fn polygon(&self) -> Option<Vec<Point2<f64>>> {
        match self {
            PivotRegion::Anywhere => None,
            PivotRegion::Box(v) => Some(vec![
                Point2::new(v.xmin, v.ymin),
                Point2::new(v.xmax, v.ymin),
                Point2::new(v.xmax, v.ymax),
                Point2::new(v.xmin, v.ymax),
            ]),
            PivotRegion::Polygon(p) => Some(p.clone()),
        }
    }

    /// The smallest box around the region, `None` for anywhere.
    pub fn bounds(&self) -> Option<Viewport> {
        let poly = self.polygon()?;
        let (mut xmin, mut xmax, mut ymin, mut ymax) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for p in &poly {
            xmin = xmin.min(p.x);
            xmax = xmax.max(p.x);
            ymin = ymin.min(p.y);
            ymax = ymax.max(p.y);
        }
        Viewport::new(xmin, xmax, ymin, ymax).ok()
    }
}

/// The space a design must fit in (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Space {
    /// Where both fixed pivots may go.
    pub pivots: PivotRegion,
    /// Convex obstacles the moving links must clear over the whole travel
    /// (as [`Constraints::obstacles`]).
    pub obstacles: Vec<Vec<Point2<f64>>>,
    /// The width of the moving links (capsules around their center lines).
    pub link_width: f64,
    /// A simple polygon the moving links (and the coupler triangle with the
    /// coupler point) must stay inside over the whole travel
    /// ([`Constraints::envelope`]); it must contain every pose.
    pub envelope: Option<Vec<Point2<f64>>>,
    /// Where the clearance and envelope checks start along the travel
    /// ([`Constraints::travel_samples`]).
    pub travel_samples: usize,
}

impl Default for Space {
    fn default() -> Self {
        Space {
            pivots: PivotRegion::Anywhere,
            obstacles: Vec::new(),
            link_width: 0.0,
            envelope: None,
            travel_samples: Constraints::DEFAULT_TRAVEL_SAMPLES,
        }
    }
}

impl Space {
    /// How far around the poses (in task sizes, [`Task::span`], from the
    /// centroid of the pose positions) the coarse pass looks for pivots
    /// when neither the region nor the size limit bounds them.
    pub const DEFAULT_REACH: f64 = 3.0;

    /// No bounds: pivots anywhere, no obstacles, no envelope.
    pub fn anywhere() -> Self {
        Space::default()
    }

    /// The constraints every map and the exact judge apply: the region as
    /// the base plate (of every pivot a map places), the obstacles, the
    /// link width, the envelope.
    pub fn constraints(&self) -> Constraints {
        Constraints {
            base_plate: self.pivots.polygon(),
            obstacles: self.obstacles.clone(),
            link_width: self.link_width,
            travel_samples: self.travel_samples,
            envelope: self.envelope.clone(),
        }
    }

    /// Checks the space alone (without a task): the region, the
    /// obstacles, the envelope and the numbers.
    ///
    /// # Errors
    ///
    /// As [`Space::validate`] but for the poses.
    pub fn check(&self) -> Result<()> {
        self.pivots.validate()?;
        self.constraints().prepare()?;
        Ok(())
    }

    /// Checks the space for `task` under `limits`.
    ///
    /// # Errors
    ///
    /// As [`PivotRegion::validate`]; [`InvalidInput::Polygon`] for an
    /// obstacle without an area or an envelope that is not simple or
    /// leaves out a pose (`problem` "excludes poses"); the errors of
    /// [`DesignLimits::validate`] and of the constraints' numbers.
    pub fn validate(&self, task: &Task, limits: &DesignLimits) -> Result<()> {
        self.pivots.validate()?;
        Judge::new(task, &MapOptions::new(limits, &self.constraints())?)?;
        Ok(())
    }

    /// The box the coarse pass samples pivots in: the region's bounds; for
    /// pivots anywhere, [`Space::DEFAULT_REACH`] task sizes around the
    /// centroid of the poses. A size limit `S` bounds every pivot of an
    /// acceptable linkage to `S` task sizes around pose 1's coupler point
    /// `P` (the crank and the coupler side from its joint to `P` reach it,
    /// and both count in the size): a region's bounds are cut to that
    /// square (unless that leaves nothing), and pivots anywhere take that
    /// square where it is the smaller box.
    pub fn search_box(&self, task: &Task, limits: &DesignLimits) -> Viewport {
        let span = task.span();
        let square = |c: Point2<f64>, half: f64| Viewport {
            xmin: c.x - half,
            xmax: c.x + half,
            ymin: c.y - half,
            ymax: c.y + half,
        };
        let poses = task.poses();
        let n = poses.len() as f64;
        let centroid = Point2::new(
            poses.iter().map(|p| p.position.x).sum::<f64>() / n,
            poses.iter().map(|p| p.position.y).sum::<f64>() / n,
        );
        let s = limits.max_size_ratio;
        let p1 = poses[0].position;
        match self.pivots.bounds() {
            None => {
                let reach = Self::DEFAULT_REACH * span;
                if s.is_finite() && s * span <= reach {
                    square(p1, s * span)
                } else {
                    square(centroid, reach)
                }
            }
            Some(bounds) if s.is_finite() => {
                let r = square(p1, s * span);
                let cut = Viewport {
                    xmin: bounds.xmin.max(r.xmin),
                    xmax: bounds.xmax.min(r.xmax),
                    ymin: bounds.ymin.max(r.ymin),
                    ymax: bounds.ymax.min(r.ymax),
                };
                if cut.xmin < cut.xmax && cut.ymin < cut.ymax {
                    cut
                } else {
                    bounds
                }
            }
            Some(bounds) => bounds,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regions() {
        assert!(PivotRegion::boxed(0.0, 1.0, 0.0, 1.0).is_ok());
        let e = PivotRegion::boxed(1.0, 0.0, 0.0, 1.0).unwrap_err();
        assert!(e.to_string().contains("pivot_box xmax"), "{e}");
        let e = PivotRegion::boxed(0.0, 1.0, 0.0, 0.0).unwrap_err();
        assert!(e.to_string().contains("pivot_box ymax"), "{e}");
        let e = PivotRegion::boxed(f64::NAN, 1.0, 0.0, 1.0).unwrap_err();
        assert!(e.to_string().contains("pivot_box xmin"), "{e}");
        let b = PivotRegion::boxed(0.0, 2.0, 0.0, 1.0).unwrap();
        assert!(b.contains(Point2::new(1.0, 0.5)) && !b.contains(Point2::new(3.0, 0.5)));
        assert_eq!(b.distance_outside(Point2::new(5.0, 5.0)), 5.0);
        let tri = PivotRegion::Polygon(vec![
            Point2::new(0.0, 0.0),
            Point2::new(4.0, 0.0),
            Point2::new(0.0, 4.0),
        ]);
        assert!(tri.validate().is_ok());
        assert!(tri.contains(Point2::new(1.0, 1.0)) && !tri.contains(Point2::new(3.0, 3.0)));
        assert!((tri.distance_outside(Point2::new(3.0, 3.0)) - 2f64.sqrt()).abs() < 1e-12);
        let bow = PivotRegion::Polygon(vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(1.0, 0.0),
            Point2::new(0.0, 1.0),
        ]);
        let e = bow.validate().unwrap_err();
        assert!(e.to_string().contains("pivot_polygon"), "{e}");
    }
}
