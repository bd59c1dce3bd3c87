//! Filemon's construction for three poses and its exact transform into the
//! driving crank's center-point plane (Borm & Kim): the branch problem
//! solved for the driving crank's fixed pivot.
//!
//! The construction itself (one line per pose through `C1`, the extreme
//! lines, the branch signs) holds for any number of poses and lives in
//! [`FilemonLines`]; this module adds what three poses allow.
//!
//! # The transformed curves (center-point plane)
//!
//! For the line through `C1` with direction `d`, `f(X) = cross(d, X - C1)`;
//! substituting the circle point `X(Y)` of a center point `Y` (see
//! [`Cremona`]) and multiplying by `den` gives an exact quadratic:
//!
//! ```text
//! g(Y) = cross(d, P12 - C1) den(Y) + cross(d, u(Y)) kappa(Y)
//! ```
//!
//! Its zero set is a conic through `P12, P13, P23` and `C0`. Since
//! `f(X(Y)) = g(Y) / den(Y)`, the classification needs no division: the
//! driving center point `A0` is branch-free exactly when `g_a(A0) g_b(A0) > 0`
//! for the two Filemon lines (directions oriented as `C'_k - C1`). The pole
//! circle, where the circle point is at infinity, splits nothing: `den`
//! cancels. The coefficients come from this closed form, not from samples.
//!
//! A task with a pure translation between two poses has a pole at infinity;
//! its curves are written from the linear form instead (see the `linear`
//! module): the same curves up to a constant factor, through the finite
//! poles and `C0`, exact conics, and the same sign test.

use core::f64::consts::{FRAC_PI_8, TAU};

use nalgebra::{Matrix2, Point2, Vector2};

use crate::error::{InvalidInput, Result, finite_point};
use crate::geom::{Conic, Line, LocalFrame, Pose, cross, normalized, wrap_angle};
use crate::linkage::{AngleInterval, AssemblyMode, InputRange};
use crate::synthesis::branch::{Branch, FilemonLines};
use crate::synthesis::three::{Cremona, Maps};
use crate::synthesis::{Dyad, DyadKind, SynthesizedFourBar, Task};
use crate::tolerance;

crate::geom::parsed_enum! {
    /// How to decide whether a driving center point is free of the branch defect.
    #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
    pub enum Method("classification method", "\"conic\", \"direct\" or \"simulate\"") {
        /// The signs of the two transformed Filemon conics at the point: two
        /// quadratic forms, no division. Defined everywhere, the pole circle
        /// included.
        Conic => "conic",
        /// The circle point of the point, then the branch sign at the three
        /// poses.
        Direct => "direct",
        /// Build the linkage and drive it (the four-bar of a driven crank, the
        /// slider-crank, [`Task::slider_crank`], of a driven slider): from
        /// each pose to the next, the
        /// input turns (either way, reversing between poses as needed) inside
        /// its input range in pose 1's assembly mode, in steps of at most
        /// `pi/8`, every step solved by the position analysis, and the coupler
        /// must land on the pose. Free when every pose is reached without a
        /// dead position. Besides the branch defect this also sees the circuit
        /// defect of an input that rocks in two separate arcs (poses on both),
        /// which the sign tests cannot.
        Simulate => "simulate",
    }
    /// `"conic"`, `"direct"` or `"simulate"`.
    pub fn as_str;
}

/// A quadratic `y^T K y + L . y + F` in the task's local frame.
#[derive(Debug, Clone, Copy)]
struct Quadratic {
    k: Matrix2<f64>,
    l: Vector2<f64>,
    f: f64,
}

impl Quadratic {
    fn coefficients(&self) -> [f64; 6] {
        let k = &self.k;
        [
            k[(0, 0)],
            k[(0, 1)] + k[(1, 0)],
            k[(1, 1)],
            self.l.x,
            self.l.y,
            self.f,
        ]
    }
}

/// `J` with `cross(a, b) = a^T J b`.
fn j() -> Matrix2<f64> {
    Matrix2::new(0.0, 1.0, -1.0, 0.0)
}

/// Rotation matrix by `-alpha`, given `(cos alpha, sin alpha)`.
fn rot_neg((c, s): (f64, f64)) -> Matrix2<f64> {
    Matrix2::new(c, s, -s, c)
}

/// Filemon's construction for a driven dyad of a three-pose task, with the
/// transformed lines.
#[derive(Clone, Copy, PartialEq)]
pub struct Filemon {
    task: Task,
    maps: Maps,
    lines: FilemonLines,
    /// The transformed line of each pose's direction, `g_k`.
    conics: [Conic; 3],
    /// The finite poles, then `C0` (for a revolute driven dyad), in the
    /// first `n_special` entries.
    special: [Point2<f64>; 4],
    n_special: usize,
}

crate::geom::debug_shows!(
    /// The task, the driven dyad (`(C0, C1)`, or a slider's `(C1, u)`), the
    /// fixed pivot's images `C'k` (none for a slider) and the two transformed Filemon lines (when the circle points are not
    /// all defective), not the maps and frames kept to evaluate them.
    Filemon,
    s =>
        task: s.task,
        driven: s.driven(),
        fixed_pivot_images: s.fixed_pivot_images(),
        conics: s.conics(),
);

impl Task {
    /// The exact image in the center-point plane of a line of the
    /// circle-point plane: the conic `g(Y) = cross(d, P12 - X0) den(Y) +
    /// cross(d, u(Y)) kappa(Y)` through `P12, P13, P23` (module docs), with
    /// `g > 0` where the circle point lies left of the line (times the sign
    /// of `den`). With a pole at infinity the conic comes from the linear
    /// form, `g(Y) = cross(d, adj(M) c - X0 det M)`, through the finite
    /// poles, with `g > 0` where the circle point lies left of the line
    /// (times the sign of `det M`).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a non-finite point,
    /// [`InvalidInput::ZeroDirection`] for a zero or non-finite direction,
    /// [`InvalidInput::NeedsPoses`] for a task of four or five poses.
    pub fn line_to_conic(&self, line: &Line) -> Result<Conic> {
        let maps = self.three_poses("Task::line_to_conic")?;
        finite_point(["line point x", "line point y"], line.point)?;
        if normalized(line.direction).is_none() {
            return Err(InvalidInput::ZeroDirection {
                name: "line direction",
                x: line.direction.x,
                y: line.direction.y,
            }
            .into());
        }
        Ok(maps.line_conic(line.point, line.direction))
    }

    /// Filemon's construction for the driven dyad whose center point is
    /// `driven_center`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NeedsPoses`] for a task of four or five poses; as
    /// [`Task::circle_point`] (the driven center point must be off the pole
    /// circle and the finite poles); as [`Filemon::new`].
    pub fn filemon(&self, driven_center: Point2<f64>) -> Result<Filemon> {
        let maps = self.three_poses("Task::filemon")?;
        let driven = Dyad::new(driven_center, maps.circle_point(driven_center)?);
        Filemon::with_maps(self, *maps, driven.into())
    }

    /// The three-position maps, or the error naming `method`.
    pub(crate) fn three_poses(&self, method: &'static str) -> Result<&Maps> {
        self.maps().ok_or_else(|| self.needs(3, method))
    }
}

impl Filemon {
    /// Filemon's construction for a driven dyad of a three-pose `task`: a
    /// crank ([`Dyad`]) or a slider ([`crate::SliderDyad`]; its lines run
    /// through `C1` in the directions `n_k`, see [`FilemonLines`], and
    /// their transforms are conics through the finite poles, with the same
    /// sign test as for a crank).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NeedsPoses`] for a task of four or five poses; as
    /// [`FilemonLines::new`].
    pub fn new(task: &Task, driven: impl Into<DyadKind>) -> Result<Self> {
        Self::with_maps(task, *task.three_poses("Filemon::new")?, driven.into())
    }

    /// Filemon's construction with the task's three-position maps (checked
    /// once by the caller).
    fn with_maps(task: &Task, maps: Maps, driven: DyadKind) -> Result<Self> {
        let lines = FilemonLines::new(task, driven)?;
        let c1 = driven.circle();
        let conics = [0, 1, 2].map(|k| maps.line_conic(c1, lines.all_lines()[k].direction));
        let mut special = [c1; 4];
        let mut n_special = 0;
        // Every transformed line through C1 passes through the center point
        // of C1: C0 for a crank; at infinity for a slider.
        for p in maps
            .poles()
            .into_iter()
            .flatten()
            .chain(driven.finite_center())
        {
            special[n_special] = p;
            n_special += 1;
        }
        Ok(Filemon {
            task: *task,
            maps,
            lines,
            conics,
            special,
            n_special,
        })
    }

    /// The task.
    pub fn task(&self) -> &Task {
        &self.task
    }

    /// The task's three-position maps through the poles.
    ///
    /// # Errors
    ///
    /// As [`Task::cremona`]: [`crate::DegenerateError::PureTranslation`]
    /// when two poses differ by a pure translation.
    pub fn cremona(&self) -> Result<&Cremona> {
        self.task.cremona()
    }

    /// The construction in the circle-point plane (lines, extremes, signs).
    pub fn construction(&self) -> &FilemonLines {
        &self.lines
    }

    /// The driven dyad: `(C0, C1)` for a crank, `(C1, u)` for a slider.
    pub fn driven(&self) -> DyadKind {
        self.lines.driven()
    }

    /// The driven crank `(C0, C1)`, or the error naming `what` (which needs
    /// a crank) for another kind of driven dyad.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::DrivenKind`] when the driven dyad is not a crank.
    pub fn driven_crank(&self, what: &'static str) -> Result<Dyad> {
        self.lines.driven().crank(what)
    }

    /// `C1`, the driven dyad's circle point (moving pivot at pose 1).
    pub fn driven_circle(&self) -> Point2<f64> {
        self.lines.driven().circle()
    }

    /// `[C'_1, C'_2, C'_3]`, `C'_k = D_k1(C0)`; `None` for a slider (its
    /// center is at infinity).
    pub fn fixed_pivot_images(&self) -> Option<[Point2<f64>; 3]> {
        self.lines.fixed_pivot_images().map(|c| [c[0], c[1], c[2]])
    }

    /// The three lines through `C1` in the directions of the poses (see
    /// [`FilemonLines::directions`]): for a crank through `C'_k`.
    pub fn all_lines(&self) -> [Line; 3] {
        let l = self.lines.all_lines();
        [l[0], l[1], l[2]]
    }

    /// Whether every driving circle point has a branch defect (the
    /// directions `C'_k - C1` do not lie in an open half-plane).
    pub fn all_defective(&self) -> bool {
        self.lines.all_defective()
    }

    /// The poses (1-based) whose lines are the extreme ones (the Filemon
    /// lines), and the middle pose; `None` when all are defective.
    pub fn extreme_poses(&self) -> Option<([usize; 2], usize)> {
        self.lines.pose_order().map(|o| ([o[0], o[2]], o[1]))
    }

    /// The two Filemon lines (through `C1`, directions `C'_k - C1` of the
    /// extreme poses); `None` when all are defective.
    pub fn lines(&self) -> Option<[Line; 2]> {
        self.lines.lines()
    }

    /// The two transformed Filemon conics in the center-point plane;
    /// `None` when all are defective.
    pub fn conics(&self) -> Option<[Conic; 2]> {
        self.lines
            .extreme_poses()
            .map(|[a, b]| [self.conics[a - 1], self.conics[b - 1]])
    }

    /// The transformed line of pose `k`'s direction (1-based), for any of
    /// the three lines.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::PoseIndex`] when `k` is not 1, 2 or 3.
    pub fn line_conic(&self, k: usize) -> Result<Conic> {
        Ok(self.conics[self.task.motion().index(k)?])
    }

    /// The branch signs `cross(C'_k - C1, A1 - C1)` of a driving circle point.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a non-finite point.
    pub fn circle_signs(&self, a1: Point2<f64>) -> Result<[f64; 3]> {
        finite_point(["circle point x", "circle point y"], a1)?;
        let s = self.lines.circle_signs(a1);
        Ok([s[0], s[1], s[2]])
    }

    /// The branch class of a driving circle point `A1` (Filemon's test in
    /// the circle-point plane).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a non-finite point.
    pub fn classify_circle_point(&self, a1: Point2<f64>) -> Result<Branch> {
        finite_point(["circle point x", "circle point y"], a1)?;
        Ok(self.lines.classify_circle_point(a1))
    }

    /// The values of the two transformed Filemon conics at a driving center
    /// point (`None` when all are defective). Their product is positive
    /// exactly where the point is branch-free.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] for a non-finite point.
    pub fn conic_values(&self, a0: Point2<f64>) -> Result<Option<[f64; 2]>> {
        finite_point(["driving center x", "driving center y"], a0)?;
        Ok(self.values(a0))
    }

    fn values(&self, a0: Point2<f64>) -> Option<[f64; 2]> {
        self.conics().map(|[a, b]| [a.evaluate(a0), b.evaluate(a0)])
    }

    /// The branch class of a driving center point `A0`, by `method`.
    ///
    /// When [`Filemon::all_defective`] holds, no method returns
    /// [`Branch::Free`] (the branch map is `false` everywhere then).
    ///
    /// With [`Method::Conic`], a point where a conic value is zero, or
    /// within [`tolerance::POINT`] of a pole or of `C0` (where all the
    /// curves meet), is [`Branch::Boundary`]; the pole circle needs no
    /// special case.
    ///
    /// # Tolerance bands
    ///
    /// Lengths in task sizes ([`Task::scale`]); `R` is the point's distance
    /// from `P12`.
    ///
    /// ```text
    /// conic     each conic's sign is the exact sign of the closed form (from the
    ///           task's double parameters) at points farther than
    ///           1e-13 (1 + R)^2 from the curve; Boundary only where a value is
    ///           exactly zero or within 1e-12 of P12, P13, P23, C0
    /// direct    agrees with conic farther than 1e-9 from the curves and the
    ///           pole circle (the circle point's rounding grows near both)
    /// simulate  agrees with direct farther than 1e-9 from the curves and the
    ///           pole circle, except that it also reports the circuit defect of
    ///           an input rocking in two arcs; a pose counts as reached within 1e-7
    ///           task sizes and 1e-7 rad (tolerance::REACH); a toggle at a design
    ///           pose or on the way (tolerance::heron_tolerance) is Boundary
    /// ```
    ///
    /// Inside a band a point may be classified either way. The conic band
    /// is checked against an exact rational evaluation of the closed form
    /// (the signs were exact beyond `5e-16 (1 + R)^2` in those runs), the
    /// others against each other and against driving the linkage densely,
    /// in the crate's tests.
    ///
    /// # Errors
    ///
    /// [`Method::Direct`] and [`Method::Simulate`] fail where the circle
    /// point does not exist (on the pole circle, at a pole:
    /// [`crate::DegenerateError`]); [`Method::Simulate`] also where a link
    /// has zero length. A non-finite point is [`InvalidInput::NotFinite`].
    pub fn classify(&self, a0: Point2<f64>, method: Method) -> Result<Branch> {
        finite_point(["driving center x", "driving center y"], a0)?;
        let b = match method {
            Method::Conic => self.classify_conic(a0),
            Method::Direct => {
                let a1 = self.maps.circle_point(a0)?;
                self.lines.classify_circle_point(a1)
            }
            Method::Simulate => self.classify_simulate(a0)?,
        };
        // When the directions C'_k - C1 span no open half-plane, no point is
        // free; a sign test that says otherwise is rounding at that border.
        Ok(if b == Branch::Free && self.all_defective() {
            Branch::Defective
        } else {
            b
        })
    }

    /// Whether the driving center point `a0` is branch-free, by `method`
    /// ([`Branch::Boundary`] counts as not free).
    ///
    /// # Errors
    ///
    /// As [`Filemon::classify`].
    pub fn is_branch_free(&self, a0: Point2<f64>, method: Method) -> Result<bool> {
        Ok(self.classify(a0, method)?.is_free())
    }

    /// The points every transformed curve passes through: the finite
    /// poles among `P12, P13, P23` (all three unless two poses differ by a
    /// pure translation), then `C0` (for a crank; a slider's is at
    /// infinity).
    pub fn special_points(&self) -> &[Point2<f64>] {
        &self.special[..self.n_special]
    }

    /// Whether `p` is within [`tolerance::POINT`] (relative to the task's
    /// size) of a finite pole or of `C0`, where all the conics meet.
    pub(crate) fn at_special_point(&self, p: Point2<f64>) -> bool {
        let tol = tolerance::POINT * self.task.scale();
        self.special_points()
            .iter()
            .any(|q| (q.x - p.x).abs() <= tol && (q.y - p.y).abs() <= tol)
    }

    pub(crate) fn classify_conic(&self, a0: Point2<f64>) -> Branch {
        if self.at_special_point(a0) {
            return Branch::Boundary;
        }
        match self.values(a0) {
            None => Branch::Defective,
            // Signs, not the product `a * b`, which underflows to zero for
            // two tiny values (the sweep tests signs too).
            Some([a, b]) => {
                if a == 0.0 || b == 0.0 || a.is_nan() || b.is_nan() {
                    Branch::Boundary
                } else if (a > 0.0) == (b > 0.0) {
                    Branch::Free
                } else {
                    Branch::Defective
                }
            }
        }
    }

    /// Drives the linkage from pose to pose ([`Method::Simulate`]): the
    /// four-bar of a driven crank, the slider-crank of a driven slider.
    fn classify_simulate(&self, a0: Point2<f64>) -> Result<Branch> {
        match self.driven() {
            DyadKind::Revolute(_) => {
                let fb = self.four_bar(a0)?;
                let range = fb.fourbar.input_range();
                let toggle = |t, m| fb.fourbar.solve(t, m).map(|c| c.toggle);
                let pose = |t, m| fb.pose_at(t, m);
                self.drive_through(&fb.input_angles, &fb.modes(), &range, toggle, pose)
            }
            DyadKind::Slider(driven) => {
                let sc = self
                    .task
                    .slider_crank(&self.task.dyad_from_center(a0)?, &driven)?;
                let range = sc.linkage.input_range();
                let toggle = |t, m| sc.linkage.solve(t, m).map(|c| c.toggle);
                let pose = |t, m| sc.pose_at(t, m);
                self.drive_through(&sc.input_angles, &sc.modes, &range, toggle, pose)
            }
            // Never built with an inverted driven dyad (`FilemonLines::new`
            // refuses it); say so rather than assume.
            DyadKind::Inverted(_) => Err(InvalidInput::InvertedDriven {
                what: "the simulate branch method",
            }
            .into()),
        }
    }

    /// Drives a linkage whose crank is at `input_angles` in `modes` at the
    /// poses and whose crank can be in `range` from each pose to the next
    /// in pose 1's mode, in steps of at most `pi/8`; `toggle(theta, mode)`
    /// solves the loop (whether it is at a toggle), `pose(theta, mode)`
    /// gives the coupler's pose ([`Method::Simulate`]).
    fn drive_through(
        &self,
        input_angles: &[f64],
        modes: &[Option<AssemblyMode>],
        range: &InputRange,
        toggle: impl Fn(f64, AssemblyMode) -> Result<bool>,
        pose: impl Fn(f64, AssemblyMode) -> Result<Pose>,
    ) -> Result<Branch> {
        // A toggle at a design pose (the figures' one band, which the
        // position analysis shares) is the boundary, wherever it is.
        let Some(Some(mode)) = modes.first().copied() else {
            return Ok(Branch::Boundary);
        };
        if modes.iter().any(Option::is_none) {
            return Ok(Branch::Boundary);
        }
        let poses = self.task.poses();
        let reach = tolerance::REACH * self.task.scale();
        for (k, want) in poses.iter().enumerate().skip(1) {
            let (from, to) = (input_angles[k - 1], input_angles[k]);
            let Some(path) = input_path(range, from, to) else {
                // Not on the arc the input is on: a circuit defect (or a
                // pose within rounding of a dead position).
                return Ok(Branch::Defective);
            };
            let steps = (path.abs() / FRAC_PI_8).ceil().max(1.0) as usize;
            for s in 1..=steps {
                let theta = from + path * (s as f64 / steps as f64);
                match toggle(theta, mode) {
                    Err(_) => return Ok(Branch::Defective),
                    // A dead position on the way, or a toggle at the pose.
                    Ok(true) => return Ok(Branch::Boundary),
                    Ok(false) => {}
                }
            }
            let got = pose(to, mode)?;
            let dp = (got.position - want.position).norm();
            let da = wrap_angle(got.angle - want.angle).abs();
            if !(dp <= reach && da <= tolerance::REACH) {
                return Ok(Branch::Defective);
            }
        }
        Ok(Branch::Free)
    }

    /// The four-bar with this driven dyad and the driving dyad whose center
    /// point is `driving_center`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::DrivenKind`] for a slider driven dyad (a
    /// slider-crank, not a four-bar); as [`Task::circle_point`] and
    /// [`Task::four_bar`].
    pub fn four_bar(&self, driving_center: Point2<f64>) -> Result<SynthesizedFourBar> {
        let driven = self.driven_crank("Filemon::four_bar")?;
        let driving = self.task.dyad_from_center(driving_center)?;
        self.task.four_bar(&driving, &driven)
    }
}

/// The signed angle the input turns from `from` to `to` without leaving its
/// input range (either way round for an input that turns fully: the
/// shorter), or `None` when `to` is not on the arc `from` is on.
fn input_path(range: &InputRange, from: f64, to: f64) -> Option<f64> {
    let within = |a: &AngleInterval| {
        let (of, ot) = (
            (from - a.start).rem_euclid(TAU),
            (to - a.start).rem_euclid(TAU),
        );
        (of <= a.span() && ot <= a.span()).then_some(ot - of)
    };
    match range {
        InputRange::Full => Some(wrap_angle(to - from)),
        InputRange::Arc(a) => within(a),
        InputRange::TwoArcs(a, b) => within(a).or_else(|| within(b)),
    }
}

/// The exact transform of the line through `c1` with direction `d` into the
/// center-point plane, as a conic in the task's local frame.
pub(super) fn line_conic(task: &Cremona, c1: Point2<f64>, d: Vector2<f64>) -> Conic {
    let (origin, scale) = task.frame();
    let q13 = task.local_p13();
    let (h12, h13) = task.half_angles();
    let r1 = rot_neg(h12);
    let r2 = rot_neg(h13);
    let j = j();
    // u = R1 y; v = R2 y + v0.
    let v0 = -(r2 * q13);
    // den = cross(u, v) = y^T (R1^T J R2) y + y^T R1^T J v0.
    let den = Quadratic {
        k: r1.transpose() * j * r2,
        l: r1.transpose() * j * v0,
        f: 0.0,
    };
    // kappa = cross(q13, v) = (R2^T J^T q13) . y + cross(q13, v0).
    let k1 = r2.transpose() * j.transpose() * q13;
    let k0 = cross(q13, v0);
    // cross(d, u) = (R1^T J^T d) . y.
    // The callers pass a finite, non-zero direction.
    let dn = normalized(d).unwrap_or_else(Vector2::x);
    let m1 = r1.transpose() * j.transpose() * dn;
    let c1l = task.local_of(c1);
    let cdc = cross(dn, c1l);
    // g = cross(d, u) kappa - cross(d, c1) den.
    let g = Quadratic {
        k: m1 * k1.transpose() - den.k * cdc,
        l: m1 * k0 - den.l * cdc,
        f: 0.0,
    };
    Conic::local(g.coefficients(), origin, scale, Some(Vector2::zeros()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn methods_parse() {
        assert_eq!("Direct".parse::<Method>().unwrap(), Method::Direct);
        assert!("exact".parse::<Method>().is_err());
    }

    #[test]
    fn paths_stay_in_the_input_range() {
        let arc = AngleInterval {
            start: 3.0,
            end: 5.0,
        };
        let r = InputRange::Arc(arc);
        assert!((input_path(&r, 3.5, 4.5).unwrap() - 1.0).abs() < 1e-15);
        assert!((input_path(&r, 4.5 - TAU, 3.5).unwrap() + 1.0).abs() < 1e-12);
        assert_eq!(input_path(&r, 3.5, 0.0), None);
        let full = input_path(&InputRange::Full, 3.0, -3.0).unwrap();
        assert!((full - (TAU - 6.0)).abs() < 1e-12);
    }
}
