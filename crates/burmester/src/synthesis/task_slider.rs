//! Slider dyads and inverted sliders of a task, for three, four and five
//! poses (issue 27).
//!
//! A **slider dyad** ([`SliderDyad`]) is a revolute dyad whose center point
//! is at infinity: its pin (the circle point) runs on a straight guide fixed
//! to the ground, so the pin's positions at the poses are collinear. Its
//! circle point is a **slider point** of the task:
//!
//! - three poses: every point of the **slider circle** through `P12`,
//!   `P13` and the image pole `P'23` ([`Task::slider_circle`]; a line when
//!   two poses differ by a pure translation), sampled by
//!   [`Task::slider_dyads`];
//! - four poses: the points of the circle-point curve whose center is at
//!   infinity ([`FourPositions::slider_circle_points`]), finitely many;
//! - five poses: the Burmester points at infinity
//!   ([`FivePositions::sliders`]), 0, 2 or 4 with the finite ones.
//!
//! An **inverted slider** ([`InvertedSlider`]) is the same found by
//! kinematic inversion: a line fixed in the moving body that passes through
//! one fixed pivot (a swivel) at every pose, as a slotted coupler on a
//! ground pin or a rod through a swivelling sleeve. Seen from the body at
//! pose 1 the ground moves by `D_k1`, so the swivel is a slider point of
//! the inverted task ([`Task::inverted`]) and the body line is its guide.
//!
//! Every pose of a task made only of pure translations has one angle,
//! which [`Task::new`] refuses for three poses and [`FourPositions`] /
//! [`FivePositions`] refuse for four or five
//! ([`DegenerateError::AllTranslations`](crate::DegenerateError::AllTranslations)):
//! then every point moves along the same polygon, so every point is a
//! slider point when the pose positions are collinear and none is
//! otherwise; there is nothing to choose between.
//!
//! [`FourPositions`]: crate::synthesis::FourPositions
//! [`FivePositions`]: crate::synthesis::FivePositions
//! [`FourPositions::slider_circle_points`]: crate::synthesis::FourPositions::slider_circle_points
//! [`FivePositions::sliders`]: crate::synthesis::FivePositions::sliders

// Comparisons are written `!(a > b)` on purpose: a NaN takes the failing
// branch.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use nalgebra::{Point2, Vector2};

use crate::error::{InvalidInput, Result, finite_point, out_of_memory};
use crate::geom::{CircleOrLine, Line, Pose, cross, rotate};
use crate::synthesis::three::SliderLocus;
use crate::synthesis::{BurmesterSlider, SliderDyad, Task, errors};
use crate::tolerance;

/// A line fixed in the moving body (the coupler) that passes through one
/// fixed pivot, the **swivel**, at every pose: an inverted slider (a slot
/// in the coupler riding on a ground pin, or a rod through a swivelling
/// sleeve).
///
/// The body line at pose 1 is the line through [`swivel`](Self::swivel)
/// along [`direction`](Self::direction); at pose `k` it is that line moved
/// by `D_1k` ([`body_line_at`](Self::body_line_at)), and it passes through
/// the swivel again.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InvertedSlider {
    /// The swivel: the fixed pivot, in the ground.
    pub swivel: Point2<f64>,
    /// The unit direction of the body line where it is at pose 1.
    pub direction: Vector2<f64>,
}

impl InvertedSlider {
    /// The body line where it is at pose 1 (through the swivel).
    pub fn body_line(&self) -> Line {
        Line {
            point: self.swivel,
            direction: self.direction,
        }
    }

    /// The body line where it is at pose `k` (1-based) of `task`: the line
    /// at pose 1 moved by `D_1k`. It passes through the swivel.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::PoseIndex`] for an index out of range.
    pub fn body_line_at(&self, task: &Task, k: usize) -> Result<Line> {
        let point = task.displace(self.swivel, 1, k)?;
        Ok(Line {
            point,
            direction: rotate(self.direction, task.rotation(1, k)?),
        })
    }

    /// The swivel plus the slot's unit direction where the body is at pose
    /// `k` (1-based) of `task`: the point that stands for the moving pivot
    /// in [`DyadKind::assembly_mode`](crate::DyadKind::assembly_mode).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::PoseIndex`] for an index out of range.
    pub fn slot_point_at(&self, task: &Task, k: usize) -> Result<Point2<f64>> {
        Ok(self.swivel + rotate(self.direction, task.rotation(1, k)?))
    }
}

/// The swivel is the pin of the inverted task's slider dyad, and the body
/// line its guide.
impl From<SliderDyad> for InvertedSlider {
    fn from(s: SliderDyad) -> Self {
        InvertedSlider {
            swivel: s.circle,
            direction: s.guide,
        }
    }
}

/// A Burmester point at infinity is a slider dyad: its center is at
/// infinity along `direction`, so the guide is normal to it
/// (`u = -i n`, and [`SliderDyad::normal`] gives `direction` back).
impl From<BurmesterSlider> for SliderDyad {
    fn from(s: BurmesterSlider) -> Self {
        SliderDyad {
            circle: s.circle,
            guide: Vector2::new(s.direction.y, -s.direction.x),
        }
    }
}

/// Which kind of point the checked look-ups are for (for the errors).
#[derive(Clone, Copy)]
struct Asked {
    what: &'static str,
    inverted: bool,
}

const SLIDER: Asked = Asked {
    what: "slider point",
    inverted: false,
};

const SWIVEL: Asked = Asked {
    what: "swivel point",
    inverted: true,
};

/// Slider dyads and inverted sliders.
impl Task {
    /// The most samples [`Task::slider_dyads`] and
    /// [`Task::inverted_sliders`] take: a list of this many is built, and
    /// handed to Python, in well under a tenth of a second, so the call
    /// needs no cancellation (a designer looks at tens or hundreds).
    pub const MAX_SLIDER_SAMPLES: usize = 10_000;

    /// The slider circle of three poses: the points of the moving plane
    /// (written where they are at pose 1) whose three positions are
    /// collinear, the circle through `P12`, `P13` and the image pole
    /// `P'23` (the circumcircle of the image pole triangle; the circle
    /// points whose center point is at infinity). A line when two of the
    /// poses differ by a pure translation (the circle through a pole at
    /// infinity), or when its center is more than `1e12` spans from pose 1.
    ///
    /// Computed from the collinearity condition itself in a frame at pose
    /// 1 (see the `three::slider` module), so that it keeps the poses'
    /// accuracy when the poles are far (small rotations) or at infinity.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NeedsPoses`] for four or five poses, whose slider
    /// points are finitely many ([`Task::slider_dyads`]).
    pub fn slider_circle(&self) -> Result<CircleOrLine> {
        let locus = self.slider_locus("Task::slider_circle")?;
        locus
            .circle()
            .ok_or_else(|| crate::DegenerateError::AllTranslations.into())
    }

    /// The slider dyads of the task: for three poses `samples` of them
    /// along the slider circle ([`Task::slider_circle`]; on a circle at
    /// equal angles from its point nearest pose 1, counterclockwise; on a
    /// line crowded near pose 1 as the stereographic image of equal angles,
    /// none at infinity); for four poses the slider points of the
    /// circle-point curve ([`FourPositions::slider_circle_points`], with
    /// their guides normal to the curve's asymptotic directions); for five
    /// the slider Burmester points ([`FivePositions::sliders`], a double
    /// one listed twice; none when every real Burmester point is finite).
    /// `samples` is checked for every count and used only for three poses.
    ///
    /// Each guide runs through the pin at pose 1, pointed toward the pin's
    /// position farthest from it. For four and five poses a point whose
    /// positions are off its guide by more than
    /// [`tolerance::ON_CURVE_TOLERANCE`] times the task's scale plus the
    /// point's distance from pose 1 (the rounding of a nearly degenerate
    /// task) is left out.
    ///
    /// [`FourPositions::slider_circle_points`]: crate::synthesis::FourPositions::slider_circle_points
    /// [`FivePositions::sliders`]: crate::synthesis::FivePositions::sliders
    ///
    /// # Errors
    ///
    /// [`InvalidInput::CountOutOfRange`] for `samples` outside `1 ..=`
    /// [`Task::MAX_SLIDER_SAMPLES`]; the errors of
    /// [`Task::four_positions`] and [`Task::five_positions`];
    /// [`crate::Error::OutOfMemory`] when the list cannot be allocated.
    pub fn slider_dyads(&self, samples: usize) -> Result<Vec<SliderDyad>> {
        if !(1..=Self::MAX_SLIDER_SAMPLES).contains(&samples) {
            return Err(errors::count(
                "samples",
                samples,
                1,
                Self::MAX_SLIDER_SAMPLES,
            ));
        }
        if self.len() != 3 {
            return Ok(self
                .exact_sliders("Task::slider_dyads")?
                .into_iter()
                .map(|(s, _)| s)
                .collect());
        }
        let locus = self.slider_locus("Task::slider_dyads")?;
        let mut points = Vec::new();
        points
            .try_reserve_exact(samples)
            .map_err(|_| out_of_memory::<Point2<f64>>("slider samples", samples))?;
        locus.samples(samples, &mut points);
        let mut out = Vec::new();
        out.try_reserve_exact(points.len())
            .map_err(|_| out_of_memory::<SliderDyad>("slider dyads", samples))?;
        out.extend(points.into_iter().filter_map(|z| self.guided(z, None)));
        Ok(out)
    }

    /// The slider dyad whose pin is at `circle` at pose 1, checked: for
    /// three poses `circle` must lie on the slider circle within
    /// [`tolerance::ON_CURVE_TOLERANCE`] times the task's scale plus its
    /// distance from pose 1 (a first-order distance); for four or five
    /// poses it must be one of the [`Task::slider_dyads`] within
    /// [`tolerance::NEAR_BURMESTER_POINT`] times the same (a point typed
    /// back in), whose dyad is returned. The guide is the line through the
    /// pin's positions (three poses) or the one found with the point.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a point that is not finite;
    /// [`InvalidInput::NotASliderPoint`] when it is not a slider point
    /// (with its distance and what to take instead);
    /// [`InvalidInput::NoSliderPoint`] for four or five poses that have
    /// none (saying why); the errors of [`Task::four_positions`] and
    /// [`Task::five_positions`].
    pub fn slider_dyad(&self, circle: Point2<f64>) -> Result<SliderDyad> {
        self.slider_checked(circle, SLIDER)
    }

    /// The inverted task: the ground's motion seen from the body, each pose
    /// `k` replaced by `D_k1` (the inverse of `D_1k`), so that pose 1 is
    /// the identity and the inverted task's moving plane at pose 1 is the
    /// ground. Its displacements are `D'_1k = D_k1`; its poles are the
    /// task's (`D_k1` fixes `P_1k`), and its image poles the task's
    /// poles. Pose `k` is `(p_1 - e^{i (phi_1 - phi_k)} p_k, phi_1 - phi_k)`.
    ///
    /// # Errors
    ///
    /// As [`Task::new`] for the inverted poses (a coordinate of
    /// `p_1 - e^{i (phi_1 - phi_k)} p_k` beyond [`Task::MAX_COORDINATE`]:
    /// move the task nearer the origin).
    pub fn inverted(&self) -> Result<Task> {
        let p = self.poses();
        let p1 = p[0];
        let inv: Vec<Pose> = p
            .iter()
            .map(|pk| {
                let angle = p1.angle - pk.angle;
                let at = p1.position - rotate(pk.position.coords, angle);
                Pose::new(at.x, at.y, angle)
            })
            .collect();
        Task::new(&inv)
    }

    /// The inverted sliders of the task: the slider dyads of the inverted
    /// task ([`Task::inverted`], [`Task::slider_dyads`]), each pin a swivel
    /// in the ground and each guide the body line at pose 1. For three
    /// poses `samples` of them along the inverted task's slider circle,
    /// which passes through `P12`, `P13` and `P23` (the pole circle: the
    /// center points whose circle point is at infinity).
    ///
    /// # Errors
    ///
    /// As [`Task::inverted`] and [`Task::slider_dyads`].
    pub fn inverted_sliders(&self, samples: usize) -> Result<Vec<InvertedSlider>> {
        let inv = self.inverted()?;
        Ok(inv
            .slider_dyads(samples)?
            .into_iter()
            .map(InvertedSlider::from)
            .collect())
    }

    /// The inverted slider whose swivel is `swivel`, checked as
    /// [`Task::slider_dyad`] checks a pin, in the inverted task: for three
    /// poses the swivel must lie on the pole circle (through `P12`, `P13`,
    /// `P23`), for four or five it must be one of the
    /// [`Task::inverted_sliders`].
    ///
    /// # Errors
    ///
    /// As [`Task::inverted`] and [`Task::slider_dyad`] (the errors name
    /// the swivel point).
    pub fn inverted_slider(&self, swivel: Point2<f64>) -> Result<InvertedSlider> {
        let inv = self.inverted()?;
        inv.slider_checked(swivel, SWIVEL).map(InvertedSlider::from)
    }

    /// The slider circle of a task of three poses (`method` names the
    /// caller in the error).
    pub(crate) fn slider_locus(&self, method: &'static str) -> Result<SliderLocus> {
        if self.len() != 3 {
            return Err(self.needs(3, method));
        }
        Ok(SliderLocus::new(self.motion(), self.span()))
    }

    /// The slider dyad of the pin `circle` with its guide through the
    /// pin's positions: normal to `normal` when given, else along the two
    /// positions farthest apart; pointed toward the position farthest from
    /// the first. With the largest distance of a position from the guide.
    /// `None` when the positions all coincide (or are not finite).
    pub(crate) fn guided(
        &self,
        circle: Point2<f64>,
        normal: Option<Vector2<f64>>,
    ) -> Option<SliderDyad> {
        self.guided_off(circle, normal).map(|(s, _)| s)
    }

    /// [`guided`](Self::guided) with the largest distance of a position
    /// from the guide.
    fn guided_off(
        &self,
        circle: Point2<f64>,
        normal: Option<Vector2<f64>>,
    ) -> Option<(SliderDyad, f64)> {
        let p = self.motion().positions(circle);
        let first = p[0];
        let far = p
            .iter()
            .copied()
            .max_by(|a, b| (a - first).norm().total_cmp(&(b - first).norm()))?;
        let u = match normal {
            Some(n) => Vector2::new(n.y, -n.x),
            None => {
                let mut best = (0.0, Vector2::zeros());
                for (i, a) in p.iter().enumerate() {
                    for b in &p[i + 1..] {
                        let d = b - a;
                        if d.norm() > best.0 {
                            best = (d.norm(), d);
                        }
                    }
                }
                best.1
            }
        };
        let u = if u.dot(&(far - first)) < 0.0 { -u } else { u };
        let dyad = SliderDyad::new(circle, u).ok()?;
        let off = p
            .iter()
            .map(|q| cross(dyad.guide, q - first).abs())
            .fold(0.0, f64::max);
        Some((dyad, off))
    }

    /// The exact slider points of four or five poses as slider dyads,
    /// each with its position's distance from pose 1; those whose
    /// positions are off the guide (see [`Task::slider_dyads`]) left out.
    fn exact_sliders(&self, method: &'static str) -> Result<Vec<(SliderDyad, f64)>> {
        let found: Vec<(Point2<f64>, Vector2<f64>)> = if self.len() == 4 {
            self.four_positions(method)?.slider_circles()
        } else {
            self.five_positions(method)?
                .sliders()
                .iter()
                .map(|s| (s.circle, s.direction))
                .collect()
        };
        let p1 = self.poses()[0].position;
        Ok(found
            .into_iter()
            .filter_map(|(z, n)| {
                let (s, off) = self.guided_off(z, Some(n))?;
                let reach = (z - p1).norm();
                let allowed = tolerance::ON_CURVE_TOLERANCE * (self.scale() + reach);
                (off <= allowed).then_some((s, reach))
            })
            .collect())
    }

    /// [`Task::slider_dyad`], its errors naming `asked`.
    fn slider_checked(&self, circle: Point2<f64>, asked: Asked) -> Result<SliderDyad> {
        let names = if asked.inverted {
            ["swivel point x", "swivel point y"]
        } else {
            ["slider point x", "slider point y"]
        };
        finite_point(names, circle)?;
        let p1 = self.poses()[0].position;
        let reach = (circle - p1).norm();
        let off = |distance: f64, tolerance: f64, hint: &'static str| -> crate::Error {
            InvalidInput::NotASliderPoint {
                what: asked.what,
                x: circle.x,
                y: circle.y,
                distance,
                tolerance,
                hint,
            }
            .into()
        };
        if self.len() == 3 {
            let method = if asked.inverted {
                "Task::inverted_slider"
            } else {
                "Task::slider_dyad"
            };
            let locus = self.slider_locus(method)?;
            let distance = locus.distance(circle);
            let allowed = tolerance::ON_CURVE_TOLERANCE * (self.scale() + reach);
            if !(distance <= allowed) {
                let hint = if asked.inverted {
                    "a swivel of three poses lies on the pole circle through P12, P13 and P23: \
                     take a point of it (Task::inverted_sliders samples it)"
                } else {
                    "a slider point of three poses lies on the slider circle through P12, P13 \
                     and the image pole P'23: take a point of it (Task::slider_circle; \
                     Task::slider_dyads samples it)"
                };
                return Err(off(distance, allowed, hint));
            }
            return self
                .guided(circle, None)
                .ok_or_else(|| off(distance, allowed, "take a point of the circle"));
        }
        let (method, none_why, hint) = match (self.len(), asked.inverted) {
            (4, false) => (
                "Task::slider_dyad",
                "the circle-point curve of these four poses has no finite point whose center \
                 point is at infinity; use a revolute dyad (Task::dyad) or move a pose",
                "the slider points of four poses are finitely many: take one of \
                 Task::slider_dyads",
            ),
            (4, true) => (
                "Task::inverted_slider",
                "the inverted task's circle-point curve has no finite point whose center \
                 point is at infinity; use a revolute dyad (Task::dyad) or move a pose",
                "the swivels of four poses are finitely many: take one of \
                 Task::inverted_sliders",
            ),
            (_, false) => (
                "Task::slider_dyad",
                "every real Burmester point of these five poses has a finite center point \
                 (Task::dyad builds their dyads); move or rotate a pose to bring a Burmester \
                 point to infinity, or synthesize for four poses",
                "the slider Burmester points of five poses are finitely many: take one of \
                 Task::slider_dyads",
            ),
            (_, true) => (
                "Task::inverted_slider",
                "every real Burmester point of the inverted five poses has a finite center \
                 point; move or rotate a pose, or synthesize for four poses",
                "the swivels of five poses are finitely many: take one of \
                 Task::inverted_sliders",
            ),
        };
        let exact = self.exact_sliders(method)?;
        let nearest = exact
            .iter()
            .map(|(s, r)| ((s.circle - circle).norm(), s, r))
            .min_by(|a, b| a.0.total_cmp(&b.0));
        let Some((distance, s, r)) = nearest else {
            return Err(InvalidInput::NoSliderPoint {
                what: asked.what,
                why: none_why,
            }
            .into());
        };
        let allowed = tolerance::NEAR_BURMESTER_POINT * (self.scale() + r);
        if distance <= allowed {
            Ok(*s)
        } else {
            Err(off(distance, allowed, hint))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The three poses of [`Task`]'s example.
    const POSES: [[f64; 3]; 3] = [[0.0, 0.0, 0.0], [2.0, 0.5, 0.4], [3.0, 2.0, 1.1]];

    fn task3() -> Task {
        Task::from_xya(&POSES).unwrap()
    }

    #[test]
    fn three_pose_samples_are_sliders_and_check_back() {
        let t = task3();
        let sliders = t.slider_dyads(24).unwrap();
        assert_eq!(sliders.len(), 24);
        for s in &sliders {
            let p: Vec<Point2<f64>> = (1..=3)
                .map(|k| t.displace(s.circle, 1, k).unwrap())
                .collect();
            for q in &p {
                assert!(cross(s.guide, q - s.circle).abs() < 1e-12 * t.span());
            }
            assert_eq!(t.slider_dyad(s.circle).unwrap(), *s);
        }
        let e = t.slider_dyad(Point2::new(40.0, 40.0)).unwrap_err();
        assert_eq!(e.cause(), "not_a_slider_point", "{e}");
        assert!(e.to_string().contains("slider circle"), "{e}");
        assert!(matches!(e, crate::Error::InvalidInput(_)));
        assert_eq!(t.slider_dyads(0).unwrap_err().cause(), "count_out_of_range");
        assert!(t.slider_dyads(Task::MAX_SLIDER_SAMPLES + 1).is_err());
    }

    #[test]
    fn inverted_task_runs_the_inverse_displacements() {
        let t = task3();
        let inv = t.inverted().unwrap();
        let z = Point2::new(0.7, -1.3);
        for k in 1..=3 {
            let a = inv.displace(z, 1, k).unwrap();
            let b = t.displace(z, k, 1).unwrap();
            assert!((a - b).norm() < 1e-13, "{k}: {a} {b}");
        }
        // The inverted task's slider circle is the task's pole circle.
        let (a, b) = (
            inv.slider_circle().unwrap(),
            t.cremona().unwrap().pole_circle(),
        );
        let (
            CircleOrLine::Circle { center, radius },
            CircleOrLine::Circle {
                center: c,
                radius: r,
            },
        ) = (a, b)
        else {
            panic!("{a:?} {b:?}");
        };
        assert!((center - c).norm() < 1e-12 && (radius - r).abs() < 1e-12);
        for s in t.inverted_sliders(9).unwrap() {
            for k in 1..=3 {
                let line = s.body_line_at(&t, k).unwrap();
                assert!(line.side(s.swivel).abs() < 1e-12 * t.span(), "{k}");
            }
        }
    }
}
