//! Filemon's construction and its exact transform into the driving crank's
//! center-point plane (Borm & Kim): the branch problem solved for the
//! driving crank's fixed pivot.
//!
//! # Filemon's construction (circle-point plane)
//!
//! For the driven dyad `(C0, C1)`, `C'_k = D_k1(C0)` is the driven crank's
//! fixed pivot seen from the coupler frame of pose 1 while at pose `k`
//! (`C'_1 = C0`). The three lines through `C1` and `C'_k` split the
//! circle-point plane into six sectors, and the branch sign of a driving
//! circle point `A1` at pose `k` is
//!
//! ```text
//! s_k = sign cross(C'_k - C1, A1 - C1)
//! ```
//!
//! The branch-free circle points are the two opposite sectors where the three
//! signs agree, bounded by the two **extreme** lines: the **Filemon lines**.
//! (Which pose gives the middle line varies with the task.) If the
//! directions `C'_k - C1` do not lie in an open half-plane, every driving
//! circle point has a branch defect ([`Filemon::all_defective`]).
//!
//! # The transformed curves (center-point plane)
//!
//! For the line through `C1` with direction `d`, `f(X) = cross(d, X - C1)`;
//! substituting the circle point `X(Y)` of a center point `Y` (see
//! [`crate::task`]) and multiplying by `den` gives an exact quadratic:
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

use core::str::FromStr;

use nalgebra::{Matrix2, Point2, Vector2};

use crate::conic::{Conic, Line};
use crate::dyad::{Dyad, SynthesizedFourBar};
use crate::error::{InvalidInput, Result};
use crate::geom::{cross, normalized};
use crate::task::Task;

/// How to decide whether a driving center point is free of the branch defect.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Method {
    /// The signs of the two transformed Filemon conics at the point: two
    /// quadratic forms, no division. Defined everywhere, the pole circle
    /// included.
    Conic,
    /// The circle point of the point, then the branch sign at the three
    /// poses.
    Direct,
    /// Build the four-bar, run the position analysis at the three input
    /// angles in pose 1's assembly mode, and check that it lands on poses 2
    /// and 3.
    Simulate,
}

impl Method {
    /// `"conic"`, `"direct"` or `"simulate"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Method::Conic => "conic",
            Method::Direct => "direct",
            Method::Simulate => "simulate",
        }
    }
}

impl FromStr for Method {
    type Err = InvalidInput;

    fn from_str(s: &str) -> Result<Self, InvalidInput> {
        match s.to_ascii_lowercase().as_str() {
            "conic" => Ok(Method::Conic),
            "direct" => Ok(Method::Direct),
            "simulate" => Ok(Method::Simulate),
            _ => Err(InvalidInput::UnknownName {
                what: "classification method",
                expected: "\"conic\", \"direct\" or \"simulate\"",
                found: s.to_owned(),
            }),
        }
    }
}

/// The branch class of a driving center point (or circle point).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Branch {
    /// The linkage passes the three poses in one assembly mode.
    Free,
    /// The linkage passes the poses on different branches (a branch defect).
    Defective,
    /// On a boundary: a branch sign is zero (a toggle at a design pose), or
    /// the point lies on a transformed Filemon conic. Never counted as free.
    Boundary,
}

impl Branch {
    /// Whether the class is [`Branch::Free`].
    pub fn is_free(self) -> bool {
        self == Branch::Free
    }

    /// `"free"`, `"defective"` or `"boundary"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Branch::Free => "free",
            Branch::Defective => "defective",
            Branch::Boundary => "boundary",
        }
    }

    /// The class from three branch signs.
    fn from_signs(s: [f64; 3]) -> Self {
        if s.iter().any(|&v| v == 0.0 || v.is_nan()) {
            Branch::Boundary
        } else if (s[0] > 0.0) == (s[1] > 0.0) && (s[1] > 0.0) == (s[2] > 0.0) {
            Branch::Free
        } else {
            Branch::Defective
        }
    }
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

/// Filemon's construction for a driven dyad, with the transformed lines.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Filemon {
    task: Task,
    driven: Dyad,
    /// `C'_k = D_k1(C0)`.
    c_prime: [Point2<f64>; 3],
    /// Pose indices (0-based) sorted by the angle of `C'_k - C1` within
    /// their half-plane: first and last are the extremes. `None` when they
    /// do not lie in an open half-plane.
    order: Option<[usize; 3]>,
    /// The transformed line of each pose's direction, `g_k`.
    conics: [Conic; 3],
}

impl Task {
    /// The exact image in the center-point plane of a line of the
    /// circle-point plane: the conic `g(Y) = cross(d, P12 - X0) den(Y) +
    /// cross(d, u(Y)) kappa(Y)` through `P12, P13, P23` (module docs), with
    /// `g > 0` where the circle point lies left of the line (times the sign
    /// of `den`).
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for a non-finite point or a zero or non-finite direction.
    pub fn line_to_conic(&self, line: &Line) -> Result<Conic> {
        crate::error::finite("line point x", line.point.x)?;
        crate::error::finite("line point y", line.point.y)?;
        if normalized(line.direction).is_none() {
            return Err(InvalidInput::OutOfRange {
                name: "line direction",
                expected: "must be a finite, non-zero vector",
                found: format!("({}, {})", line.direction.x, line.direction.y),
            }
            .into());
        }
        Ok(line_conic(self, line.point, line.direction))
    }

    /// Filemon's construction for the driven dyad whose center point is
    /// `driven_center`.
    ///
    /// # Errors
    ///
    /// As [`Task::circle_point`] (the driven center point must be off the
    /// pole circle and the poles); [`crate::DegenerateError::ZeroLengthLink`]
    /// when its circle point coincides with it.
    pub fn filemon(&self, driven_center: Point2<f64>) -> Result<Filemon> {
        let driven = self.dyad_from_center(driven_center)?;
        Filemon::new(self, driven)
    }
}

impl Filemon {
    /// Filemon's construction for a driven dyad of `task`.
    ///
    /// # Errors
    ///
    /// [`crate::DegenerateError::ZeroLengthLink`] when the dyad has no
    /// length; [`InvalidInput::OutOfRange`] when an image `C'_k` of its
    /// fixed pivot overflows or coincides with its circle point.
    pub fn new(task: &Task, driven: Dyad) -> Result<Self> {
        if driven.length() <= Task::POINT_TOLERANCE * task.scale() {
            return Err(crate::DegenerateError::ZeroLengthLink {
                what: "driven crank",
                x: driven.center.x,
                y: driven.center.y,
            }
            .into());
        }
        let c1 = driven.circle;
        let c_prime = [1, 2, 3].map(|k| task.displace(driven.center, k, 1));
        let dirs = c_prime.map(|c| c - c1);
        if dirs.iter().any(|d| normalized(*d).is_none()) {
            return Err(InvalidInput::OutOfRange {
                name: "driven dyad",
                expected: "must have its fixed pivot's images C'k = D_k1(C0) finite and apart \
                           from its circle point C1; choose a driven center point nearer the task",
                found: format!(
                    "C0 = ({}, {}), C1 = ({}, {})",
                    driven.center.x, driven.center.y, c1.x, c1.y
                ),
            }
            .into());
        }
        let order = half_plane_order(&dirs);
        let conics = dirs.map(|d| line_conic(task, c1, d));
        Ok(Filemon {
            task: *task,
            driven,
            c_prime,
            order,
            conics,
        })
    }

    /// The task.
    pub fn task(&self) -> &Task {
        &self.task
    }

    /// The driven dyad `(C0, C1)`.
    pub fn driven(&self) -> Dyad {
        self.driven
    }

    /// `C1`, the driven crank's circle point.
    pub fn circle_point(&self) -> Point2<f64> {
        self.driven.circle
    }

    /// `[C'_1, C'_2, C'_3]`, `C'_k = D_k1(C0)`.
    pub fn fixed_pivot_images(&self) -> [Point2<f64>; 3] {
        self.c_prime
    }

    /// The three lines through `C1` and `C'_k`, directions `C'_k - C1`.
    pub fn all_lines(&self) -> [Line; 3] {
        self.c_prime.map(|c| Line {
            point: self.driven.circle,
            direction: c - self.driven.circle,
        })
    }

    /// Whether every driving circle point has a branch defect (the
    /// directions `C'_k - C1` do not lie in an open half-plane).
    pub fn all_defective(&self) -> bool {
        self.order.is_none()
    }

    /// The poses (1-based) whose lines are the extreme ones (the Filemon
    /// lines), and the middle pose; `None` when all are defective.
    pub fn extreme_poses(&self) -> Option<([usize; 2], usize)> {
        self.order.map(|o| ([o[0] + 1, o[2] + 1], o[1] + 1))
    }

    /// The two Filemon lines (through `C1`, directions `C'_k - C1` of the
    /// extreme poses); `None` when all are defective.
    pub fn lines(&self) -> Option<[Line; 2]> {
        let all = self.all_lines();
        self.order.map(|o| [all[o[0]], all[o[2]]])
    }

    /// The two transformed Filemon conics in the center-point plane;
    /// `None` when all are defective.
    pub fn conics(&self) -> Option<[Conic; 2]> {
        self.order.map(|o| [self.conics[o[0]], self.conics[o[2]]])
    }

    /// The transformed line of pose `k`'s direction (1-based), for any of
    /// the three lines.
    ///
    /// # Panics
    ///
    /// If `k` is not 1, 2 or 3.
    pub fn line_conic(&self, k: usize) -> Conic {
        self.conics[k - 1]
    }

    /// The branch signs `cross(C'_k - C1, A1 - C1)` of a driving circle point.
    pub fn circle_signs(&self, a1: Point2<f64>) -> [f64; 3] {
        let c1 = self.driven.circle;
        self.c_prime.map(|c| cross(c - c1, a1 - c1))
    }

    /// The branch class of a driving circle point `A1` (Filemon's test in
    /// the circle-point plane).
    pub fn classify_circle_point(&self, a1: Point2<f64>) -> Branch {
        Branch::from_signs(self.circle_signs(a1))
    }

    /// The values of the two transformed Filemon conics at a driving center
    /// point (`None` when all are defective). Their product is positive
    /// exactly where the point is branch-free.
    pub fn conic_values(&self, a0: Point2<f64>) -> Option<[f64; 2]> {
        self.conics().map(|[a, b]| [a.evaluate(a0), b.evaluate(a0)])
    }

    /// The branch class of a driving center point `A0`, by `method`.
    ///
    /// When [`Filemon::all_defective`] holds, no method returns
    /// [`Branch::Free`] (the branch map is `false` everywhere then).
    ///
    /// With [`Method::Conic`], a point where a conic value is zero, or
    /// within [`Task::POINT_TOLERANCE`] of a pole or of `C0` (where all the
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
    /// simulate  agrees with direct where it is not Boundary; a pose counts as
    ///           reached within 1e-7 of the linkage's size and 1e-7 rad
    /// ```
    ///
    /// Inside a band a point may be classified either way. The conic band
    /// is checked against an exact rational evaluation of the closed form
    /// (the signs were exact beyond `5e-16 (1 + R)^2` in those runs), the
    /// others against each other, in the crate's tests.
    ///
    /// # Errors
    ///
    /// [`Method::Direct`] and [`Method::Simulate`] fail where the circle
    /// point does not exist (on the pole circle, at a pole:
    /// [`crate::DegenerateError`]); [`Method::Simulate`] also where a link
    /// has zero length. A non-finite point is [`InvalidInput::NotFinite`].
    pub fn classify(&self, a0: Point2<f64>, method: Method) -> Result<Branch> {
        crate::error::finite("driving center x", a0.x)?;
        crate::error::finite("driving center y", a0.y)?;
        let b = match method {
            Method::Conic => self.classify_conic(a0),
            Method::Direct => {
                let a1 = self.task.circle_point(a0)?;
                self.classify_circle_point(a1)
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

    /// The points every transformed curve passes through: `P12, P13, P23`
    /// and `C0`.
    pub fn special_points(&self) -> [Point2<f64>; 4] {
        let [a, b, c] = self.task.poles();
        [a, b, c, self.driven.center]
    }

    /// Whether `p` is within [`Task::POINT_TOLERANCE`] (relative to the
    /// task's size) of a pole or of `C0`, where all the conics meet.
    pub(crate) fn at_special_point(&self, p: Point2<f64>) -> bool {
        let tol = Task::POINT_TOLERANCE * self.task.scale();
        self.special_points()
            .iter()
            .any(|q| (q.x - p.x).abs() <= tol && (q.y - p.y).abs() <= tol)
    }

    pub(crate) fn classify_conic(&self, a0: Point2<f64>) -> Branch {
        if self.at_special_point(a0) {
            return Branch::Boundary;
        }
        match self.conic_values(a0) {
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

    fn classify_simulate(&self, a0: Point2<f64>) -> Result<Branch> {
        let fb = self.four_bar(a0)?;
        let Some(mode) = fb.modes[0] else {
            return Ok(Branch::Boundary);
        };
        let poses = self.task.poses();
        let size = fb.fourbar.lengths().iter().sum::<f64>()
            + (poses[0].position - fb.driving.circle).norm();
        for (k, want) in poses.iter().enumerate().skip(1) {
            let theta2 = fb.input_angles[k];
            let c = match fb.fourbar.solve(theta2, mode) {
                Ok(c) => c,
                Err(_) => return Ok(Branch::Defective),
            };
            if c.toggle {
                return Ok(Branch::Boundary);
            }
            let pose = fb.pose_at(theta2, mode)?;
            let dp = (pose.position - want.position).norm();
            let da = crate::geom::wrap_angle(pose.angle - want.angle).abs();
            if dp > 1e-7 * size || da > 1e-7 {
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
    /// As [`Task::circle_point`] and [`Task::four_bar`].
    pub fn four_bar(&self, driving_center: Point2<f64>) -> Result<SynthesizedFourBar> {
        let driving = self.task.dyad_from_center(driving_center)?;
        self.task.four_bar(&driving, &self.driven)
    }
}

/// The order of three directions by angle when they lie in an open
/// half-plane (extremes first and last), else `None`.
fn half_plane_order(d: &[Vector2<f64>; 3]) -> Option<[usize; 3]> {
    use core::f64::consts::{PI, TAU};
    let ang = d.map(|v| v.y.atan2(v.x));
    let mut idx = [0usize, 1, 2];
    idx.sort_by(|&a, &b| ang[a].total_cmp(&ang[b]));
    // Circular gaps between consecutive angles; the directions lie in an
    // open half-plane iff the largest gap exceeds pi. The extremes are the
    // two angles bounding that gap.
    let gaps = [
        ang[idx[1]] - ang[idx[0]],
        ang[idx[2]] - ang[idx[1]],
        ang[idx[0]] + TAU - ang[idx[2]],
    ];
    let (k, &gap) = gaps
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))
        .unwrap_or((0, &0.0));
    if gap <= PI {
        return None;
    }
    // The gap runs from idx[k] to idx[k+1]; the run of directions starts
    // after it.
    let start = (k + 1) % 3;
    Some([idx[start], idx[(start + 1) % 3], idx[(start + 2) % 3]])
}

/// The exact transform of the line through `c1` with direction `d` into the
/// center-point plane, as a conic in the task's local frame.
fn line_conic(task: &Task, c1: Point2<f64>, d: Vector2<f64>) -> Conic {
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
    fn half_plane_order_finds_the_extremes() {
        let v = |a: f64| Vector2::new(a.cos(), a.sin());
        assert_eq!(half_plane_order(&[v(0.1), v(0.5), v(0.3)]), Some([0, 2, 1]));
        assert_eq!(
            half_plane_order(&[v(3.0), v(-3.0), v(2.5)]),
            Some([2, 0, 1])
        );
        assert_eq!(half_plane_order(&[v(0.0), v(2.2), v(-2.2)]), None);
    }

    #[test]
    fn methods_parse() {
        assert_eq!("Direct".parse::<Method>().unwrap(), Method::Direct);
        assert!("exact".parse::<Method>().is_err());
    }
}
