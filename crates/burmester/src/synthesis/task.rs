//! The task: three to five poses of the coupler, validated once, with their
//! motion (displacements and poles) and the part for their count, built
//! once: for three poses the maps between circle points and center points,
//! for four the Burmester curves, for five the Burmester points. The
//! methods that mean one thing for any count dispatch on that part.
//!
//! The **circle-point plane** holds coupler points written where they are at
//! pose 1; the **center-point plane** is the fixed frame. A dyad's center
//! point (fixed pivot) `Y` and circle point (moving pivot at pose 1) `X`
//! satisfy `|X - Y| = |D_1k(X) - Y|` for every pose `k` (see
//! [`motion`](crate::synthesis::motion) for `D_ij` and the poles).

use nalgebra::{Point2, Vector2};

use crate::error::{DegenerateError, InvalidInput, Result, bounded};
use crate::geom::{PerPose, Pose, Similarity, length};
use crate::synthesis::motion::{Motion, Pole};
use crate::synthesis::three::{Cremona, Linear, Maps};
use crate::synthesis::{Dyad, FivePositions, FourPositions, SynthesizedFourBar};
use crate::tolerance;

/// A method of [`Task`] named `$name` that maps each of `$points` by the
/// method `$each`, lazily: the iterator form of a map of one point.
macro_rules! lazily {
    ($(#[$doc:meta])* $name:ident = $each:ident($points:ident)) => {
        $(#[$doc])*
        pub fn $name<'a, I>(
            &'a self,
            $points: I,
        ) -> impl Iterator<Item = Result<Point2<f64>>> + 'a
        where
            I: IntoIterator<Item = Point2<f64>>,
            I::IntoIter: 'a,
        {
            $points.into_iter().map(move |p| self.$each(p))
        }
    };
}

/// Three to five poses of the coupler, validated, with their motion.
///
/// Everything that holds for any number of poses (the displacements, the
/// poles, dyads and the four-bar built from two) is here; what holds for
/// three poses only is on [`Cremona`] (the pole triangle and circles,
/// which need three finite poles), from [`Task::cremona`], and on
/// [`Filemon`](crate::Filemon) (Filemon's construction and its conics).
///
/// Two of three poses may differ by a pure translation (the same angle
/// modulo `2 pi`, within [`tolerance::MIN_ROTATION`]): the maps, Filemon's
/// construction and the solution maps then run by the linear form, which
/// needs no pole, while [`Task::cremona`] reports
/// [`DegenerateError::PureTranslation`].
///
/// # Example
///
/// ```
/// use burmester::{Pose, Task};
/// let task = Task::new(&[
///     Pose::new(0.0, 0.0, 0.0),
///     Pose::new(2.0, 0.5, 0.4),
///     Pose::new(3.0, 2.0, 1.1),
/// ])?;
/// let [p12, p13, p23] = task.cremona()?.poles();
/// // A circle point and its center point are a round trip.
/// let y = burmester::Point2::new(1.0, -2.0);
/// let x = task.circle_point(y)?;
/// assert!((task.center_point(x)? - y).norm() < 1e-12);
/// # Ok::<(), burmester::Error>(())
/// ```
#[derive(Clone, Copy)]
pub struct Task {
    motion: Motion,
    /// The unit of the relative tolerances (see [`Task::scale`]).
    scale: f64,
    /// What the task holds for its pose count.
    part: Part,
}

/// What a task holds for its number of poses, built once with it: a new
/// pose count is a new arm here (and a folder beside `three/`, `four/`,
/// `five/`).
// One per task, copied with it (a task is `Copy`): no box for the larger.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy)]
enum Part {
    /// Three poses: the maps between the planes, and the maps through the
    /// poles of a task whose maps run by the linear form (a pole far from
    /// the poses): its pole triangle and circles ([`Task::cremona`]).
    Three {
        maps: Maps,
        far_poles: Option<Cremona>,
    },
    /// Four poses: the Burmester curves; `None` when the poses have none
    /// (the error is made again where they are asked for).
    Four(Option<FourPositions>),
    /// Five poses: the Burmester points; `None` when they are refused.
    Five(Option<FivePositions>),
}

/// Equal poses: the motion, the scale and the three-pose maps compared, not
/// the curves or points of four or five poses (which the poses determine).
impl PartialEq for Task {
    fn eq(&self, other: &Self) -> bool {
        let parts = match (&self.part, &other.part) {
            (
                Part::Three { maps, far_poles },
                Part::Three {
                    maps: m,
                    far_poles: f,
                },
            ) => maps == m && far_poles == f,
            (Part::Four(_), Part::Four(_)) | (Part::Five(_), Part::Five(_)) => true,
            _ => false,
        };
        parts && self.motion == other.motion && self.scale == other.scale
    }
}

crate::geom::debug_shows!(
    /// The poses and their poles, not the part kept for their count.
    Task,
    s => poses: s.poses(), poles: s.poles(),
);

impl Task {
    /// The fewest poses of a task.
    pub const MIN_POSES: usize = 3;

    /// The most poses of a task.
    pub const MAX_POSES: usize = crate::geom::MAX_POSES;

    /// Largest magnitude of a pose coordinate. With it and
    /// [`tolerance::MIN_ROTATION`] the poles stay below about `1e107`, so
    /// no square of a distance overflows.
    pub const MAX_COORDINATE: f64 = 1e100;

    /// Largest magnitude of a pose angle, in radians: past it a double no
    /// longer holds the angle to `1e-7` rad.
    pub const MAX_ANGLE: f64 = crate::FourBar::MAX_ANGLE;

    /// Smallest [`Task::scale`]: smaller tasks are rejected (rescale them),
    /// so that no square of a distance underflows.
    pub const MIN_SCALE: f64 = 1e-100;

    /// A task from three to five poses.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::PoseCount`] for fewer than three or more than five
    /// poses; [`InvalidInput::NotFinite`] for a NaN or infinite number;
    /// [`InvalidInput::TooLarge`] when a coordinate exceeds
    /// [`Task::MAX_COORDINATE`] or an angle [`Task::MAX_ANGLE`] in
    /// magnitude; [`DegenerateError::CoincidentPoses`] when two poses are
    /// equal; [`DegenerateError::CoincidentPoles`] when every pose is a
    /// rotation about one point; [`InvalidInput::TooSmall`] when the task
    /// is smaller than [`Task::MIN_SCALE`]. For three poses also
    /// [`DegenerateError::AllTranslations`] when all three have one angle
    /// (every dyad's crank is then one and the same vector).
    ///
    /// Two poses whose angles agree within [`tolerance::MIN_ROTATION`]
    /// (modulo `2 pi`) differ by a pure translation: their pole is
    /// [`Pole::AtInfinity`]. That is the one rule, for any number of poses;
    /// a three-pose task with such a pair runs its maps by the linear form
    /// with the poses' own angles (a rotation below the bound is not
    /// rounded to zero, so the maps stay those of the given poses and vary
    /// continuously across the bound). So does a three-pose task whose pole
    /// `P12` or `P13` lies farther than [`tolerance::POLE_DISTANCE`] spans
    /// from pose 1 (a small rotation), where the closed form through the
    /// poles would lose about `0.5 / theta` times the accuracy the input
    /// allows; its [`Task::cremona`] (the pole triangle and circles) is
    /// still there. The form is chosen by that conditioning, so the maps
    /// keep the input's accuracy at every rotation.
    pub fn new(poses: &[Pose]) -> Result<Self> {
        let n = poses.len();
        if !(Self::MIN_POSES..=Self::MAX_POSES).contains(&n) {
            return Err(InvalidInput::PoseCount {
                found: n,
                min: Self::MIN_POSES,
                max: Self::MAX_POSES,
            }
            .into());
        }
        check_poses(poses)?;
        let motion = Motion::new(PerPose::from_slice(poses));
        for (i, j) in motion.pairs() {
            let (a, b) = (&poses[i - 1], &poses[j - 1]);
            if motion.rotation0(i - 1, j - 1).abs() <= tolerance::MIN_ROTATION
                && a.position == b.position
            {
                return Err(DegenerateError::CoincidentPoses { i, j }.into());
            }
        }
        if n == 3 {
            let poles = motion.poles();
            if poles.iter().all(|p| p.finite().is_some()) {
                Self::three(motion)
            } else {
                Self::translated(motion)
            }
        } else {
            Self::more(motion)
        }
    }

    /// Three poses: the scale is the size of the pole triangle.
    fn three(motion: Motion) -> Result<Self> {
        let poles: Vec<Point2<f64>> = motion.poles().iter().filter_map(Pole::finite).collect();
        let poles = [poles[0], poles[1], poles[2]];
        let size = [(0, 1), (0, 2), (1, 2)]
            .iter()
            .map(|&(a, b)| length(poles[b] - poles[a]))
            .fold(0.0, f64::max);
        if !size.is_finite() {
            return Err(InvalidInput::Overflow {
                what: "the pole triangle",
                hint: "pass poses whose poles are representable (coordinates far below 1e300)",
            }
            .into());
        }
        let extent = motion
            .poses()
            .iter()
            .map(|p| length(p.position - poles[0]))
            .fold(0.0, f64::max);
        if size <= tolerance::POINT * extent || size == 0.0 {
            return Err(DegenerateError::CoincidentPoles {
                x: poles[0].x,
                y: poles[0].y,
            }
            .into());
        }
        Self::check_scale(size)?;
        let cremona = Cremona::new(motion, poles, size);
        // Through the poles where they lie near the poses; else by the
        // linear form, which cancels nothing (tolerance::POLE_DISTANCE).
        let p1 = motion.poses()[0].position;
        let span = span_of(&motion);
        let far = length(poles[0] - p1).max(length(poles[1] - p1));
        if far > tolerance::POLE_DISTANCE * span {
            let linear = Linear::new(motion, size, span);
            return Ok(Task {
                motion,
                scale: size,
                part: Part::Three {
                    maps: Maps::Linear(linear),
                    far_poles: Some(cremona.with_linear(linear)),
                },
            });
        }
        Ok(Task {
            motion,
            scale: size,
            part: Part::Three {
                maps: Maps::Poles(cremona),
                far_poles: None,
            },
        })
    }

    /// Three poses, two of which differ by a pure translation: the scale is
    /// the largest distance between two of the pose positions and the
    /// finite poles (the pole triangle's size has no meaning with a pole at
    /// infinity).
    fn translated(motion: Motion) -> Result<Self> {
        let mut points: Vec<Point2<f64>> = motion.poses().iter().map(|p| p.position).collect();
        points.extend(motion.poles().iter().filter_map(Pole::finite));
        if points.len() == 3 {
            return Err(DegenerateError::AllTranslations.into());
        }
        let mut size: f64 = 0.0;
        for (k, p) in points.iter().enumerate() {
            for q in &points[k + 1..] {
                size = size.max(length(q - p));
            }
        }
        if !size.is_finite() {
            return Err(InvalidInput::Overflow {
                what: "the task's poles",
                hint: "pass poses whose poles are representable (coordinates far below 1e300)",
            }
            .into());
        }
        Self::check_scale(size)?;
        Ok(Task {
            motion,
            scale: size,
            part: Part::Three {
                maps: Maps::Linear(Linear::new(motion, size, span_of(&motion))),
                far_poles: None,
            },
        })
    }

    /// Four or five poses: the scale is the largest distance between two
    /// pose positions.
    fn more(motion: Motion) -> Result<Self> {
        let p = motion.poses();
        let mut size: f64 = 0.0;
        for (i, j) in motion.pairs() {
            size = size.max(length(p[j - 1].position - p[i - 1].position));
        }
        // Every pose a rotation about one point: all poles coincide there.
        let poles = motion.poles();
        if let Some(first) = poles[0].finite() {
            let all_there = poles.iter().all(|q| {
                q.finite().is_some_and(|q| {
                    length(q - first) <= tolerance::POINT * (size + length(p[0].position - first))
                })
            });
            if all_there {
                return Err(DegenerateError::CoincidentPoles {
                    x: first.x,
                    y: first.y,
                }
                .into());
            }
        }
        Self::check_scale(size)?;
        Ok(Task {
            motion,
            scale: size,
            part: if p.len() == 4 {
                Part::Four(FourPositions::of(p).ok())
            } else {
                Part::Five(FivePositions::of(p).ok())
            },
        })
    }

    fn check_scale(size: f64) -> Result<()> {
        if size < Self::MIN_SCALE {
            return Err(InvalidInput::TooSmall {
                name: "the task's size",
                value: size,
                limit: Self::MIN_SCALE,
                hint: "rescale the task (the maps are invariant under scaling)",
            }
            .into());
        }
        Ok(())
    }

    /// A task from `[x, y, angle]` triples (angles in radians).
    ///
    /// # Errors
    ///
    /// As [`Task::new`].
    pub fn from_xya(poses: &[[f64; 3]]) -> Result<Self> {
        let p: Vec<Pose> = poses.iter().map(|&[x, y, a]| Pose::new(x, y, a)).collect();
        Self::new(&p)
    }

    /// The poses.
    pub fn poses(&self) -> &[Pose] {
        self.motion.poses()
    }

    /// The number of poses (3, 4 or 5).
    pub fn len(&self) -> usize {
        self.motion.len()
    }

    /// Always false: a task has at least three poses.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The motion through the poses: displacements and poles.
    pub fn motion(&self) -> &Motion {
        &self.motion
    }

    /// The unit of the relative tolerances: for three poses the size of the
    /// pole triangle (its longest side), or, when two poses differ by a pure
    /// translation, the largest distance between two of the pose positions
    /// and the finite poles; for four or five poses the largest distance
    /// between two pose positions.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// The task's size: the largest distance between two pose positions
    /// (the coupler point's travel, what a designer calls "a task about this
    /// large"). Positive for every task (poses at one position turn about
    /// it, which [`Task::new`] rejects). The unit of
    /// [`SynthesizedFourBar::size`](crate::SynthesizedFourBar::size) ratios.
    pub fn span(&self) -> f64 {
        span_of(&self.motion)
    }

    /// The three-position maps through the poles (pole triangle and
    /// circles, closed-form maps, image poles).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NeedsPoses`] for a task of four or five poses;
    /// [`DegenerateError::PureTranslation`] when two of the three poses
    /// differ by a pure translation (a pole at infinity: there is no pole
    /// triangle). The maps themselves ([`Task::circle_point`],
    /// [`Task::center_point`]), Filemon's construction and the solution maps
    /// work for such a task.
    pub fn cremona(&self) -> Result<&Cremona> {
        match &self.part {
            Part::Three {
                maps: Maps::Poles(c),
                ..
            }
            | Part::Three {
                far_poles: Some(c), ..
            } => Ok(c),
            Part::Three {
                maps: Maps::Linear(l),
                ..
            } => {
                let (i, j) = l.translation().unwrap_or((1, 2));
                Err(DegenerateError::PureTranslation { i, j }.into())
            }
            _ => Err(self.needs(3, "Task::cremona")),
        }
    }

    /// The three-position maps, whichever form the task uses.
    pub(crate) fn maps(&self) -> Option<&Maps> {
        match &self.part {
            Part::Three { maps, .. } => Some(maps),
            _ => None,
        }
    }

    /// The error of a method that needs `required` poses.
    pub(crate) fn needs(&self, required: usize, method: &'static str) -> crate::Error {
        InvalidInput::NeedsPoses {
            method,
            required,
            found: self.len(),
        }
        .into()
    }

    /// The rotations `theta_ij` of the pairs `(1,2), (1,3), ..., (2,3), ...`,
    /// each wrapped into `(-pi, pi]`.
    pub fn rotations(&self) -> Vec<f64> {
        self.motion
            .pairs()
            .map(|(i, j)| self.motion.rotation0(i - 1, j - 1))
            .collect()
    }

    /// The angle from pose `i` to pose `j` (1-based), wrapped into `(-pi, pi]`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::PoseIndex`] for an index out of range.
    pub fn rotation(&self, i: usize, j: usize) -> Result<f64> {
        self.motion.rotation(i, j)
    }

    /// `D_ij(z) = p_j + e^{i theta_ij} (z - p_i)`: where the coupler point
    /// that is at `z` in pose `i` is in pose `j` (1-based).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::PoseIndex`] for an index out of range.
    pub fn displace(&self, z: Point2<f64>, i: usize, j: usize) -> Result<Point2<f64>> {
        self.motion.displace(z, i, j)
    }

    /// Every pole, pairs in the order `(1,2), (1,3), ..., (2,3), ...`; a
    /// pure translation's pole is [`Pole::AtInfinity`].
    pub fn poles(&self) -> Vec<Pole> {
        self.motion.poles()
    }

    /// The circle point (moving pivot at pose 1) whose center point (fixed
    /// pivot) is `center`: for three poses by [`Cremona::circle_point`], or
    /// by the linear form when two poses differ by a pure translation.
    ///
    /// # Errors
    ///
    /// As [`Cremona::circle_point`] (the pole circle is a line through the
    /// two finite poles when the third is at infinity);
    /// [`InvalidInput::NeedsPoses`] for a task of another number of poses.
    pub fn circle_point(&self, center: Point2<f64>) -> Result<Point2<f64>> {
        self.maps()
            .ok_or_else(|| self.needs(3, "Task::circle_point"))?
            .circle_point(center)
    }

    /// The center point (fixed pivot) of the circle point (moving pivot at
    /// pose 1) `circle`: for three poses by [`Cremona::center_point`], or
    /// by the linear form when two poses differ by a pure translation.
    ///
    /// # Errors
    ///
    /// As [`Cremona::center_point`]; [`InvalidInput::NeedsPoses`] for a
    /// task of another number of poses.
    pub fn center_point(&self, circle: Point2<f64>) -> Result<Point2<f64>> {
        self.maps()
            .ok_or_else(|| self.needs(3, "Task::center_point"))?
            .center_point(circle)
    }

    lazily! {
        /// [`circle_point`](Self::circle_point) for each of `centers`, lazily.
        circle_points = circle_point(centers)
    }

    lazily! {
        /// [`center_point`](Self::center_point) for each of `circles`, lazily.
        center_points = center_point(circles)
    }

    /// The same task transformed by a similarity (scale about the origin,
    /// rotate about the origin, translate; optionally mirrored). Used to
    /// check invariance.
    ///
    /// # Errors
    ///
    /// As [`Task::new`].
    pub fn transformed_by(&self, t: &Similarity) -> Result<Self> {
        let p: Vec<Pose> = self.poses().iter().map(|p| t.pose(p)).collect();
        Self::new(&p)
    }

    /// The same task scaled by `factor` about the origin, rotated by
    /// `angle` about the origin, then translated by `offset`.
    ///
    /// # Errors
    ///
    /// As [`Task::new`] and [`Similarity::new`] (for example when `factor`
    /// is zero).
    pub fn transformed(&self, factor: f64, angle: f64, offset: Vector2<f64>) -> Result<Self> {
        self.transformed_by(&Similarity::new(factor, angle, offset)?)
    }
}

/// The part for the pose count, and what dispatches on it.
impl Task {
    /// The Burmester curves of a task of four poses (built with the task).
    /// `method` names the caller in the error.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NeedsPoses`] naming `method` for a task of three or
    /// five poses; the errors of [`FourPositions::new`].
    pub fn four_positions(&self, method: &'static str) -> Result<&FourPositions> {
        match &self.part {
            Part::Four(four) => self.kept(four.as_ref(), FourPositions::of, method),
            _ => Err(self.needs(4, method)),
        }
    }

    /// The Burmester points of a task of five poses (built with the task).
    /// `method` names the caller in the error.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NeedsPoses`] naming `method` for a task of three or
    /// four poses; the errors of [`FivePositions::new`].
    pub fn five_positions(&self, method: &'static str) -> Result<&FivePositions> {
        let Part::Five(five) = &self.part else {
            return Err(self.needs(5, method));
        };
        self.kept(five.as_ref(), FivePositions::of, method)
    }

    /// The part kept when the task was made or, refused then, the same
    /// error again (the part is a function of the poses).
    fn kept<'a, T>(
        &self,
        part: Option<&'a T>,
        build: fn(&[Pose]) -> Result<T>,
        method: &'static str,
    ) -> Result<&'a T> {
        part.ok_or_else(|| {
            build(self.poses())
                .err()
                .unwrap_or_else(|| self.needs(self.len(), method))
        })
    }

    /// Checks that the task maps points between the planes
    /// ([`Task::circle_point_of`], [`Task::center_point_of`]): three poses
    /// (the closed-form maps) or four whose curves exist.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NeedsPoses`] naming `method` for five poses (whose
    /// dyads are finitely many: [`Task::dyad`]); for four, the errors of
    /// [`FourPositions::new`].
    pub fn check_point_maps(&self, method: &'static str) -> Result<()> {
        match &self.part {
            Part::Three { .. } => Ok(()),
            Part::Four(_) => self.four_positions(method).map(|_| ()),
            Part::Five(_) => Err(self.needs(3, method)),
        }
    }

    /// The circle point of a center point for three poses (the closed-form
    /// map, [`Task::circle_point`]) or four (on the center-point curve,
    /// [`FourPositions::circle_point`]).
    ///
    /// # Errors
    ///
    /// As those; [`InvalidInput::NeedsPoses`] for five poses.
    pub fn circle_point_of(&self, center: Point2<f64>) -> Result<Point2<f64>> {
        match &self.part {
            Part::Four(_) => self
                .four_positions("Task::circle_point_of")?
                .circle_point(center),
            _ => self.circle_point(center),
        }
    }

    /// The center point of a circle point for three poses (the closed-form
    /// map, [`Task::center_point`]) or four (on the circle-point curve,
    /// [`FourPositions::center_point`]).
    ///
    /// # Errors
    ///
    /// As those; [`InvalidInput::NeedsPoses`] for five poses.
    pub fn center_point_of(&self, circle: Point2<f64>) -> Result<Point2<f64>> {
        match &self.part {
            Part::Four(_) => self
                .four_positions("Task::center_point_of")?
                .center_point(circle),
            _ => self.center_point(circle),
        }
    }

    /// The dyad of a center point, for any pose count: three poses by the
    /// closed-form map; four by the center-point curve (an error with the
    /// distance when it is off the curve); five by the Burmester point it
    /// is (within [`tolerance::NEAR_BURMESTER_POINT`] relative), else by
    /// the curve of poses 1 to 4, refused unless the dyad passes all five
    /// poses (within [`tolerance::DYAD`]).
    ///
    /// # Errors
    ///
    /// As [`Task::dyad_from_center`], [`FourPositions::dyad_from_center`];
    /// for five poses the errors of [`FivePositions::new`] and
    /// [`InvalidInput::NotADyad`] for a center point that is not a
    /// Burmester point.
    pub fn dyad(&self, center: Point2<f64>) -> Result<Dyad> {
        match &self.part {
            Part::Three { .. } => self.dyad_from_center(center),
            Part::Four(_) => self.four_positions("Task::dyad")?.dyad_from_center(center),
            Part::Five(_) => {
                let five = self.five_positions("Task::dyad")?;
                let p1 = self.poses()[0].position;
                let near = |a: Point2<f64>| {
                    (a - center).norm()
                        <= tolerance::NEAR_BURMESTER_POINT * (self.scale() + (a - p1).norm())
                };
                if let Some(d) = five.burmester_points().iter().find(|d| near(d.center)) {
                    return Ok(*d);
                }
                let d = FourPositions::of(&self.poses()[..4])?.dyad_from_center(center)?;
                let spread = five.residual(&d);
                // A NaN spread (a dyad at infinity) fails too.
                if spread.is_nan() || spread > tolerance::DYAD {
                    let which = "dyad of this center point (not a Burmester point)";
                    return Err(crate::synthesis::errors::not_a_dyad(which, spread));
                }
                Ok(d)
            }
        }
    }

    /// The four-bar of the dyads of two center points ([`Task::dyad`] of
    /// each, then [`Task::four_bar`]), for any pose count.
    ///
    /// # Errors
    ///
    /// As [`Task::dyad`] and [`Task::four_bar`].
    pub fn four_bar_of(
        &self,
        driving_center: Point2<f64>,
        driven_center: Point2<f64>,
    ) -> Result<SynthesizedFourBar> {
        let driving = self.dyad(driving_center)?;
        let driven = self.dyad(driven_center)?;
        self.four_bar(&driving, &driven)
    }

    /// The four-bars of every ordered pair of Burmester points of a task of
    /// five poses, `(driving index, driven index, four-bar)` with the
    /// indices into [`FivePositions::burmester_points`]; a pair whose
    /// four-bar cannot be built (a link of zero length) is left out.
    ///
    /// # Errors
    ///
    /// As [`Task::five_positions`].
    pub fn burmester_four_bars(
        &self,
        method: &'static str,
    ) -> Result<Vec<(usize, usize, SynthesizedFourBar)>> {
        let five = self.five_positions(method)?;
        let points = five.burmester_points();
        let mut out = Vec::new();
        for (i, a) in points.iter().enumerate() {
            for (j, c) in points.iter().enumerate() {
                if i == j {
                    continue;
                }
                if let Ok(fb) = self.four_bar(a, c) {
                    out.push((i, j, fb));
                }
            }
        }
        Ok(out)
    }
}

/// Checks every number of `poses` (at most [`Task::MAX_POSES`]): finite,
/// coordinates within [`Task::MAX_COORDINATE`] and angles within
/// [`Task::MAX_ANGLE`] in magnitude. The one check of the poses, for a task
/// and for the curves and points built from poses alone.
///
/// # Errors
///
/// [`InvalidInput::NotFinite`] or [`InvalidInput::TooLarge`] naming the
/// pose and the number.
pub(crate) fn check_poses(poses: &[Pose]) -> Result<()> {
    const NAMES: [[&str; 3]; 5] = [
        ["pose 1 x", "pose 1 y", "pose 1 angle"],
        ["pose 2 x", "pose 2 y", "pose 2 angle"],
        ["pose 3 x", "pose 3 y", "pose 3 angle"],
        ["pose 4 x", "pose 4 y", "pose 4 angle"],
        ["pose 5 x", "pose 5 y", "pose 5 angle"],
    ];
    const RESCALE: &str = "rescale the task (the maps are invariant under scaling)";
    for (p, names) in poses.iter().zip(NAMES) {
        bounded(names[0], p.position.x, Task::MAX_COORDINATE, RESCALE)?;
        bounded(names[1], p.position.y, Task::MAX_COORDINATE, RESCALE)?;
        bounded(
            names[2],
            p.angle,
            Task::MAX_ANGLE,
            crate::linkage::ANGLE_HINT,
        )?;
    }
    Ok(())
}

/// What `build` makes of exactly `count` poses given alone (not by a
/// task): the count checked (the error naming `method`), then the one check
/// of the poses ([`check_poses`]).
pub(crate) fn of_poses<T>(
    poses: &[Pose],
    count: usize,
    method: &'static str,
    build: fn(&[Pose]) -> Result<T>,
) -> Result<T> {
    if poses.len() != count {
        return Err(crate::synthesis::errors::pose_count(
            method,
            count,
            poses.len(),
        ));
    }
    check_poses(poses)?;
    build(poses)
}

/// The largest distance between two pose positions ([`Task::span`]).
fn span_of(motion: &Motion) -> f64 {
    let p = motion.poses();
    motion
        .pairs()
        .map(|(i, j)| length(p[j - 1].position - p[i - 1].position))
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Error;

    fn task() -> Task {
        Task::from_xya(&[[0.0, 0.0, 0.0], [2.0, 0.5, 0.4], [3.0, 2.0, 1.1]]).unwrap()
    }

    #[test]
    fn poles_are_fixed_points() {
        let t = task();
        let [p12, p13, p23] = t.cremona().unwrap().poles();
        assert!((t.displace(p12, 1, 2).unwrap() - p12).norm() < 1e-12);
        assert!((t.displace(p13, 1, 3).unwrap() - p13).norm() < 1e-12);
        assert!((t.displace(p23, 2, 3).unwrap() - p23).norm() < 1e-12);
        let generic: Vec<Point2<f64>> = t.poles().iter().filter_map(Pole::finite).collect();
        assert_eq!(generic, vec![p12, p13, p23]);
    }

    #[test]
    fn pure_translation_and_coincident_poses_are_typed() {
        // A translation between two of three poses is a task; only what
        // needs three finite poles is refused.
        let t = Task::from_xya(&[[0.0, 0.0, 0.3], [1.0, 0.0, 0.3], [3.0, 2.0, 1.1]]).unwrap();
        let e = t.cremona().unwrap_err();
        assert!(matches!(
            e,
            Error::Degenerate(DegenerateError::PureTranslation { i: 1, j: 2 })
        ));
        assert!(e.to_string().contains("translation"), "{e}");
        let x = t.circle_point(Point2::new(1.0, -2.0)).unwrap();
        assert!((t.center_point(x).unwrap() - Point2::new(1.0, -2.0)).norm() < 1e-12);
        let e = Task::from_xya(&[[0.0, 0.0, 0.3], [1.0, 0.0, 0.3], [3.0, 2.0, 0.3]]).unwrap_err();
        assert!(matches!(
            e,
            Error::Degenerate(DegenerateError::AllTranslations)
        ));
        let e = Task::from_xya(&[[0.0, 0.0, 0.3], [3.0, 2.0, 1.1], [3.0, 2.0, 1.1]]).unwrap_err();
        assert!(matches!(
            e,
            Error::Degenerate(DegenerateError::CoincidentPoses { i: 2, j: 3 })
        ));
        let e =
            Task::from_xya(&[[0.0, 0.0, f64::NAN], [3.0, 2.0, 1.1], [1.0, 2.0, 1.3]]).unwrap_err();
        assert!(matches!(e, Error::InvalidInput(_)));
    }

    #[test]
    fn pose_counts() {
        let five = [
            [0.0, 0.0, 0.0],
            [2.0, 0.5, 0.4],
            [3.0, 2.0, 1.1],
            [1.0, 3.0, 1.1],
            [-1.0, 2.0, 0.2],
        ];
        for n in 3..=5 {
            let t = Task::from_xya(&five[..n]).unwrap();
            assert_eq!(t.len(), n);
            assert_eq!(t.poles().len(), n * (n - 1) / 2);
            assert_eq!(t.cremona().is_ok(), n == 3);
        }
        // A pure translation (poses 3 and 4) is fine with four poses.
        let t = Task::from_xya(&five[..4]).unwrap();
        assert!(matches!(t.poles()[5], Pole::AtInfinity { .. }));
        let e = t.circle_point(Point2::new(0.0, 1.0)).unwrap_err();
        assert_eq!(e.cause(), "needs_poses");
        for bad in [&five[..2], &[[0.0; 3]; 6][..]] {
            let e = Task::from_xya(bad).unwrap_err();
            assert!(
                matches!(e, Error::InvalidInput(InvalidInput::PoseCount { .. })),
                "{e}"
            );
        }
    }
}
