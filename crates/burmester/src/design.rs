//! The designer's solution-space map: from branch-free to buildable and
//! good.
//!
//! The paper stops at branch-free and names Grashof type and order as
//! future work. For every candidate driving center point `A0` on a grid
//! (the same grid as the branch map), [`Filemon::solution_map`] gives:
//!
//! * whether the linkage exists (a circle point, links of nonzero length);
//! * the branch-free flag (exactly the branch map's);
//! * the Grashof class, and whether the driving link turns fully;
//! * order and circuit: the input rotation direction that carries the
//!   coupler from pose 1 through pose 2 to pose 3, or none; for a rocker
//!   input, whether the three input angles lie on one circuit (one arc of
//!   the input range) with pose 2 between poses 1 and 3;
//! * the minimum transmission angle over the whole travel from pose 1
//!   through pose 2 to pose 3 (not only at the poses);
//! * the ratio of the longest to the shortest link;
//! * an `acceptable` mask from [`DesignLimits`] and [`Constraints`].
//!
//! [`Task::driven_solution_map`] does the same the other way round: a
//! fixed driving dyad, candidate driven center points.
//!
//! # How the figures are computed (no trigonometry per point)
//!
//! With the lengths `L1..L4`, the input angles `theta_k` at the poses, and
//! `theta1` the ground direction, the loop closes where
//! `c = cos(theta - theta1)` lies in `[c_min, c_max]`
//! ([`FourBar::input_range`](crate::FourBar::input_range)). Angles are compared through a monotone
//! pseudo-angle measured from a direction known to lie outside the travel:
//! the first input angle for a crank, a direction in the input's dead zone
//! for a rocker (`theta1 + pi` when the input rocks about `theta1`,
//! `theta1` otherwise, which both arcs of a Grashof double-rocker avoid).
//!
//! The transmission angle depends on the input only through
//! `r^2 = L1^2 + L2^2 - 2 L1 L2 c`:
//!
//! ```text
//! cos mu = (L3^2 + L4^2 - r^2) / (2 L3 L4),   quality = acos |cos mu|   (in [0, pi/2])
//! ```
//!
//! `|cos mu|` is convex in `c`, so its largest value over the travel is at
//! an extreme of `c`: an end of the travel, or `c = +1` / `c = -1` where
//! the travel passes the ground direction or its opposite. The minimum
//! transmission angle over the travel is exact, from at most four
//! candidates.

use nalgebra::{Point2, Vector2};
use parry2d_f64::math::Vector as PVector;
use parry2d_f64::query::intersection_test;
use parry2d_f64::shape::{Capsule, ConvexPolygon};
use parry2d_f64::utils::point_in_poly2d;
use rayon::prelude::*;

use crate::dyad::{Dyad, SynthesizedFourBar};
use crate::error::{InvalidInput, Result, finite, positive};
use crate::filemon::{Filemon, Method};
use crate::fourbar::{AssemblyMode, Grashof, input_bounds};
use crate::geom::{cross, rotate_cs};
use crate::sweep::Grid;
use crate::task::Task;

/// Which kind of input link a design requires.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum InputRequirement {
    /// Any input that carries the coupler through the poses.
    #[default]
    Any,
    /// The input must turn fully (a crank: motor-driven without reversing).
    Crank,
    /// The input must rock (not turn fully).
    Rocker,
}

impl InputRequirement {
    /// `"any"`, `"crank"` or `"rocker"`.
    pub fn as_str(self) -> &'static str {
        match self {
            InputRequirement::Any => "any",
            InputRequirement::Crank => "crank",
            InputRequirement::Rocker => "rocker",
        }
    }
}

impl core::str::FromStr for InputRequirement {
    type Err = InvalidInput;

    fn from_str(s: &str) -> Result<Self, InvalidInput> {
        match s.to_ascii_lowercase().as_str() {
            "any" => Ok(InputRequirement::Any),
            "crank" => Ok(InputRequirement::Crank),
            "rocker" => Ok(InputRequirement::Rocker),
            _ => Err(InvalidInput::UnknownName {
                what: "input requirement",
                expected: "\"any\", \"crank\" or \"rocker\"",
                found: s.to_owned(),
            }),
        }
    }
}

/// The designer's limits behind the `acceptable` mask.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DesignLimits {
    /// The smallest acceptable transmission angle over the travel, radians
    /// (default 30 degrees, a common rule of thumb).
    pub min_transmission: f64,
    /// The largest acceptable ratio of the longest to the shortest link
    /// (default 10).
    pub max_link_ratio: f64,
    /// Which input is required (default: any).
    pub input: InputRequirement,
}

impl Default for DesignLimits {
    fn default() -> Self {
        DesignLimits {
            min_transmission: 30f64.to_radians(),
            max_link_ratio: 10.0,
            input: InputRequirement::Any,
        }
    }
}

impl DesignLimits {
    /// Checks the limits: a transmission angle in `[0, pi/2]`, a link ratio
    /// of at least 1 (infinity allowed: no limit).
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] when a limit is NaN or out of its range.
    pub fn validate(&self) -> Result<()> {
        let t = finite("min_transmission", self.min_transmission)?;
        if !(0.0..=core::f64::consts::FRAC_PI_2).contains(&t) {
            return Err(InvalidInput::OutOfRange {
                name: "min_transmission",
                expected: "must be between 0 and pi/2 radians (0 and 90 degrees)",
                found: t.to_string(),
            }
            .into());
        }
        if self.max_link_ratio.is_nan() || self.max_link_ratio < 1.0 {
            return Err(InvalidInput::OutOfRange {
                name: "max_link_ratio",
                expected: "must be at least 1 (infinity for no limit)",
                found: self.max_link_ratio.to_string(),
            }
            .into());
        }
        Ok(())
    }
}

/// Where the linkage may be: a base plate for the fixed pivot, obstacles
/// the moving links must clear.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Constraints {
    /// The fixed pivot being placed must lie inside this simple polygon
    /// (vertices in order); `None`: anywhere.
    pub base_plate: Option<Vec<Point2<f64>>>,
    /// Convex obstacles (vertices in any order: their convex hull is used;
    /// give a non-convex obstacle as several convex pieces).
    pub obstacles: Vec<Vec<Point2<f64>>>,
    /// The width of the moving links (crank, coupler, rocker), modelled as
    /// capsules of this diameter around their center lines.
    pub link_width: f64,
    /// How many input angles of the travel are checked for clearance
    /// (default 64 when zero).
    pub travel_samples: usize,
}

impl Constraints {
    /// No constraints.
    pub fn none() -> Self {
        Constraints::default()
    }

    fn samples(&self) -> usize {
        if self.travel_samples == 0 {
            64
        } else {
            self.travel_samples
        }
    }

    /// Validates the constraints and builds parry shapes.
    fn prepare(&self) -> Result<Prepared> {
        for p in self
            .base_plate
            .iter()
            .flatten()
            .chain(self.obstacles.iter().flatten())
        {
            for (name, v) in [("constraint vertex x", p.x), ("constraint vertex y", p.y)] {
                if finite(name, v)?.abs() > MAX_COORDINATE {
                    return Err(InvalidInput::OutOfRange {
                        name,
                        expected: "must be at most 1e100 in magnitude; rescale the constraints",
                        found: v.to_string(),
                    }
                    .into());
                }
            }
        }
        if let Some(plate) = &self.base_plate {
            if plate.len() < 3 {
                return Err(InvalidInput::OutOfRange {
                    name: "base_plate",
                    expected: "must have at least 3 vertices",
                    found: plate.len().to_string(),
                }
                .into());
            }
        }
        let width = if self.obstacles.is_empty() {
            0.0
        } else {
            finite("link_width", self.link_width)?
        };
        if width < 0.0 {
            return Err(InvalidInput::NotPositive {
                name: "link_width",
                value: width,
            }
            .into());
        }
        let mut obstacles = Vec::with_capacity(self.obstacles.len());
        for o in &self.obstacles {
            let bad = || InvalidInput::OutOfRange {
                name: "obstacle",
                expected: "must have at least 3 vertices that are not all on one line; pass a \
                           polygon",
                found: format!("{} vertices", o.len()),
            };
            // parry's hull asserts on fewer than two distinct points: check
            // that the vertices span an area first.
            if !spans_area(o) {
                return Err(bad().into());
            }
            let pts: Vec<PVector> = o.iter().map(|p| PVector::new(p.x, p.y)).collect();
            obstacles.push(ConvexPolygon::from_convex_hull(&pts).ok_or_else(bad)?);
        }
        Ok(Prepared {
            plate: self
                .base_plate
                .as_ref()
                .map(|p| p.iter().map(|q| PVector::new(q.x, q.y)).collect()),
            obstacles,
            radius: 0.5 * width,
            samples: self.samples(),
        })
    }
}

/// The largest coordinate of a constraint vertex.
const MAX_COORDINATE: f64 = 1e100;

/// Whether the points span an area: three or more, not all on one line
/// (relative to their extent).
fn spans_area(pts: &[Point2<f64>]) -> bool {
    let Some(&p0) = pts.first() else {
        return false;
    };
    let far = pts
        .iter()
        .max_by(|a, b| {
            (*a - p0)
                .norm_squared()
                .total_cmp(&(*b - p0).norm_squared())
        })
        .copied()
        .unwrap_or(p0);
    let d = far - p0;
    let extent = d.norm_squared();
    extent > 0.0 && pts.iter().any(|q| cross(d, q - p0).abs() > 1e-12 * extent)
}

/// Constraints as parry shapes.
struct Prepared {
    plate: Option<Vec<PVector>>,
    obstacles: Vec<ConvexPolygon>,
    radius: f64,
    samples: usize,
}

impl Prepared {
    fn pivot_ok(&self, p: Point2<f64>) -> bool {
        self.plate
            .as_ref()
            .is_none_or(|poly| point_in_poly2d(PVector::new(p.x, p.y), poly))
    }

    /// Whether the moving links clear every obstacle over the travel.
    fn clearance_ok(&self, fb: &SynthesizedFourBar, fig: &LinkageFigures) -> bool {
        if self.obstacles.is_empty() {
            return true;
        }
        let Some(mode) = fb.modes[0] else {
            return false;
        };
        let [t1, _, t3] = fb.input_angles;
        let dir = f64::from(fig.direction);
        if dir == 0.0 {
            return false;
        }
        // Signed sweep from pose 1 to pose 3 in the driving direction.
        let tau = core::f64::consts::TAU;
        let mut span = (t3 - t1).rem_euclid(tau);
        if dir < 0.0 {
            span -= tau;
        }
        let n = self.samples.max(2);
        let identity = parry2d_f64::math::Pose::identity();
        for s in 0..n {
            let theta = t1 + span * (s as f64 / (n - 1) as f64);
            let Ok(j) = fb.fourbar.joints_at(theta, mode) else {
                return false;
            };
            let v = |p: Point2<f64>| PVector::new(p.x, p.y);
            let links = [
                (j.input_pivot, j.crank_joint),
                (j.crank_joint, j.rocker_joint),
                (j.output_pivot, j.rocker_joint),
            ];
            for (a, b) in links {
                let cap = Capsule::new(v(a), v(b), self.radius);
                for o in &self.obstacles {
                    let hit = intersection_test(&identity, &cap, &identity, o)
                        .map_or(true, |r| r.intersecting);
                    if hit {
                        return false;
                    }
                }
            }
        }
        true
    }
}

/// What a designer checks of one linkage built from a driving and a driven
/// dyad of a task.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkageFigures {
    /// `[ground, crank, coupler, rocker]`.
    pub lengths: [f64; 4],
    /// Grashof type, the driving link being the input.
    pub grashof: Grashof,
    /// Whether the driving link turns fully.
    pub input_full: bool,
    /// The assembly mode at each pose (`None` at a toggle).
    pub modes: [Option<AssemblyMode>; 3],
    /// The input rotation direction that carries the coupler from pose 1
    /// through pose 2 to pose 3: `1` counter-clockwise, `-1` clockwise, `0`
    /// none (order defect, or the poses on different circuits).
    pub direction: i8,
    /// Whether the three input angles lie on one circuit (one arc of the
    /// input range; always true for an input that turns fully).
    pub one_circuit: bool,
    /// The smallest transmission angle over the travel from pose 1 through
    /// pose 2 to pose 3, radians in `[0, pi/2]`; NaN when `direction` is 0
    /// (there is no travel).
    pub min_transmission: f64,
    /// Longest over shortest link.
    pub link_ratio: f64,
}

impl LinkageFigures {
    /// Whether the three poses are in one assembly mode (no branch defect).
    pub fn branch_free(&self) -> bool {
        matches!(self.modes, [Some(a), Some(b), Some(c)] if a == b && b == c)
    }

    /// Whether the motion pose 1 -> 2 -> 3 is feasible: branch-free, one
    /// circuit, and a driving direction.
    pub fn feasible(&self) -> bool {
        self.branch_free() && self.one_circuit && self.direction != 0
    }

    /// Whether the figures meet `limits` (and the motion is feasible).
    pub fn meets(&self, limits: &DesignLimits) -> bool {
        self.feasible()
            && self.min_transmission >= limits.min_transmission
            && self.link_ratio <= limits.max_link_ratio
            && match limits.input {
                InputRequirement::Any => true,
                InputRequirement::Crank => self.input_full,
                InputRequirement::Rocker => !self.input_full,
            }
    }
}

/// The displacements `D_1k` of a task as `z -> R_k z + t_k`.
#[derive(Clone, Copy)]
struct Moves {
    rot: [(f64, f64); 3],
    shift: [Vector2<f64>; 3],
}

impl Moves {
    fn new(task: &Task) -> Self {
        let p = task.poses();
        let rot = [0, 1, 2].map(|k| {
            let (s, c) = (p[k].angle - p[0].angle).sin_cos();
            (c, s)
        });
        let shift = [0, 1, 2].map(|k| {
            let (c, s) = rot[k];
            p[k].position.coords - rotate_cs(p[0].position.coords, c, s)
        });
        Moves { rot, shift }
    }

    #[inline(always)]
    fn apply(&self, k: usize, z: Point2<f64>) -> Point2<f64> {
        let (c, s) = self.rot[k];
        Point2::from(rotate_cs(z.coords, c, s) + self.shift[k])
    }
}

/// A monotone pseudo-angle of `v` measured counter-clockwise from `r`, in
/// `[0, 4)`.
#[inline(always)]
fn pseudo_angle(r: Vector2<f64>, v: Vector2<f64>) -> f64 {
    let x = r.dot(&v);
    let y = cross(r, v);
    let d = x.abs() + y.abs();
    if d == 0.0 {
        return 0.0;
    }
    let p = y / d;
    if x >= 0.0 {
        if y >= 0.0 { p } else { 4.0 + p }
    } else {
        2.0 - p
    }
}

#[inline(always)]
fn fmax(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

#[inline(always)]
fn fmin(a: f64, b: f64) -> f64 {
    if a < b { a } else { b }
}

/// Grashof class and input bounds of `[ground, crank, coupler, rocker]`,
/// branch-light (the same decisions as [`grashof_of`] and
/// [`input_bounds`]).
#[inline(always)]
fn classify_lengths(l: [f64; 4]) -> (Grashof, bool, bool, f64, f64) {
    let [l1, l2, l3, l4] = l;
    // The lengths are finite and positive here: plain comparisons.
    let max = fmax(fmax(l1, l2), fmax(l3, l4));
    let min = fmin(fmin(l1, l2), fmin(l3, l4));
    let sum = l1 + l2 + l3 + l4;
    let lhs = min + max;
    let rhs = sum - lhs;
    // Same relative tolerance as the position analysis (8 eps).
    let tol = 8.0 * f64::EPSILON * sum;
    let grashof = if (lhs - rhs).abs() <= tol {
        Grashof::ChangePoint
    } else if lhs > rhs {
        Grashof::TripleRocker
    } else if l1 == min {
        Grashof::DoubleCrank
    } else if l2 == min {
        Grashof::CrankRocker
    } else if l3 == min {
        Grashof::DoubleRocker
    } else {
        Grashof::RockerCrank
    };
    let b = input_bounds(l);
    (grashof, b.lo_free, b.hi_free, b.c_min, b.c_max)
}

/// The figures of the linkage `A0 A1 C1 C0`, with `A_k`, `C_k` the moving
/// pivots at the poses; `None` when a link has (nearly) zero length.
///
/// Pseudo-angles are scale invariant, so no direction is normalized.
///
/// With `MODES = false` the assembly modes are not computed (all `None`):
/// the map takes its branch flag from the conic sweep instead.
#[inline]
fn figures<const MODES: bool>(
    a0: Point2<f64>,
    a: [Point2<f64>; 3],
    c0: Point2<f64>,
    c: [Point2<f64>; 3],
    tiny: f64,
) -> Option<LinkageFigures> {
    let ground = c0 - a0;
    let l1 = ground.norm();
    let l2 = (a[0] - a0).norm();
    let l3 = (c[0] - a[0]).norm();
    let l4 = (c[0] - c0).norm();
    let lengths = [l1, l2, l3, l4];
    if !(l1 > tiny && l2 > tiny && l3 > tiny && l4 > tiny && (l1 + l2 + l3 + l4).is_finite()) {
        return None;
    }
    let modes = [0, 1, 2].map(|k| {
        if !MODES {
            return None;
        }
        let (u, w) = (c[k] - a[k], c[k] - c0);
        let s = cross(u, w);
        // |s| <= 16 eps |u| |w|, squared: no square roots.
        let t = 16.0 * f64::EPSILON;
        if s * s <= t * t * u.norm_squared() * w.norm_squared() {
            None
        } else {
            AssemblyMode::from_sign(s)
        }
    });
    let (grashof, lo_free, hi_free, _, _) = classify_lengths(lengths);
    let full = lo_free && hi_free;
    let g = ground;
    let e = [0, 1, 2].map(|k| a[k] - a0);
    // The travel as pseudo-angles from a reference outside it: [from, to].
    let (reference, direction, one_circuit, from, to) = if full {
        let t2 = pseudo_angle(e[0], e[1]);
        let t3 = pseudo_angle(e[0], e[2]);
        let dir: i8 = if t2 == 0.0 || t3 == 0.0 || t2 == t3 {
            0
        } else if t2 < t3 {
            1
        } else {
            -1
        };
        let (from, to) = if dir > 0 { (0.0, t3) } else { (t3, 4.0) };
        (e[0], dir, true, from, to)
    } else {
        // The dead zone: around -g when the input rocks about g, around g
        // otherwise (one arc about g + pi, or the two arcs off the ground line).
        let reference = if hi_free { -g } else { g };
        let t = e.map(|ek| pseudo_angle(reference, ek));
        let one_circuit = if !hi_free && !lo_free {
            // Two arcs: one on each side of the ground line.
            let side = e.map(|ek| cross(g, ek) > 0.0);
            side[0] == side[1] && side[1] == side[2]
        } else {
            true
        };
        let between = (t[0] < t[1] && t[1] < t[2]) || (t[2] < t[1] && t[1] < t[0]);
        let dir: i8 = if !one_circuit || !between {
            0
        } else if t[0] < t[2] {
            1
        } else {
            -1
        };
        (reference, dir, one_circuit, t[0].min(t[2]), t[0].max(t[2]))
    };
    let min_transmission = if direction == 0 {
        f64::NAN
    } else {
        let inside = |v: Vector2<f64>| {
            let p = pseudo_angle(reference, v);
            (p >= from && p <= to) || (full && p == 0.0)
        };
        // |cos mu| at c = cos(theta - theta1) (module docs).
        let k0 = l1 * l1 + l2 * l2;
        let k1 = 2.0 * l1 * l2;
        let k2 = l3 * l3 + l4 * l4;
        let inv = 1.0 / (2.0 * l3 * l4);
        let cos_mu = |cc: f64| fmin(((k2 - (k0 - k1 * cc)) * inv).abs(), 1.0);
        let inv12 = 1.0 / (l1 * l2);
        let mut worst = fmax(cos_mu(g.dot(&e[0]) * inv12), cos_mu(g.dot(&e[2]) * inv12));
        if inside(g) {
            worst = fmax(worst, cos_mu(1.0));
        }
        if inside(-g) {
            worst = fmax(worst, cos_mu(-1.0));
        }
        worst.acos()
    };
    let min = fmin(fmin(l1, l2), fmin(l3, l4));
    let max = fmax(fmax(l1, l2), fmax(l3, l4));
    Some(LinkageFigures {
        lengths,
        grashof,
        input_full: full,
        modes,
        direction,
        one_circuit,
        min_transmission,
        link_ratio: max / min,
    })
}

impl Task {
    /// The figures of the linkage built from a driving and a driven dyad of
    /// this task.
    ///
    /// # Errors
    ///
    /// As [`Task::four_bar`].
    pub fn linkage_figures(&self, driving: &Dyad, driven: &Dyad) -> Result<LinkageFigures> {
        // Validates the dyads and the links.
        self.four_bar(driving, driven)?;
        let m = Moves::new(self);
        let a = [0, 1, 2].map(|k| m.apply(k, driving.circle));
        let c = [0, 1, 2].map(|k| m.apply(k, driven.circle));
        figures::<true>(driving.center, a, driven.center, c, 0.0).ok_or_else(|| {
            InvalidInput::OutOfRange {
                name: "linkage",
                expected: "must have links of nonzero, finite length",
                found: format!("{driving:?} and {driven:?}"),
            }
            .into()
        })
    }
}

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

/// What a solution map was computed for: the grid, the task, which pivot
/// varies, and the limits and constraints. Holds the per-sample logic
/// (the linkage of a sample, its margin, the best pivots), so that the
/// arrays can live elsewhere (for example in NumPy).
#[derive(Debug, Clone)]
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

/// The solution-space map: one value per grid sample, row-major like the
/// branch map.
#[derive(Debug, Clone)]
pub struct SolutionMap {
    /// What the map was computed for.
    pub context: MapContext,
    /// The linkage exists: the candidate has a circle point and every link
    /// a nonzero length. Where false, the other arrays hold false, 0, NaN
    /// or [`SolutionMap::GRASHOF_NONE`].
    pub valid: Vec<bool>,
    /// Free of the branch defect (for candidate driving pivots, exactly the
    /// `conic` branch map).
    pub branch_free: Vec<bool>,
    /// Grashof class as [`SolutionMap::grashof_code`]; `GRASHOF_NONE` where
    /// invalid.
    pub grashof: Vec<u8>,
    /// The driving link turns fully.
    pub input_full: Vec<bool>,
    /// `1` counter-clockwise, `-1` clockwise, `0` no feasible order.
    pub direction: Vec<i8>,
    /// The three input angles lie on one circuit.
    pub one_circuit: Vec<bool>,
    /// Minimum transmission angle over the travel, radians; NaN where
    /// `direction` is 0 or the linkage does not exist.
    pub min_transmission: Vec<f32>,
    /// Longest over shortest link; NaN where the linkage does not exist.
    pub link_ratio: Vec<f32>,
    /// Meets the limits and the constraints, with a feasible, branch-free
    /// motion.
    pub acceptable: Vec<bool>,
}

impl SolutionMap {
    /// The Grashof code of an invalid sample.
    pub const GRASHOF_NONE: u8 = 255;

    /// The code of a Grashof class in [`SolutionMap::grashof`]: the order
    /// of [`Grashof::ALL`].
    pub fn grashof_code(g: Grashof) -> u8 {
        Grashof::ALL.iter().position(|&x| x == g).unwrap_or(255) as u8
    }

    /// The Grashof class of a code (`None` for [`SolutionMap::GRASHOF_NONE`]).
    pub fn grashof_of_code(code: u8) -> Option<Grashof> {
        Grashof::ALL.get(usize::from(code)).copied()
    }

    /// The candidate center point of sample `k` (row-major index).
    pub fn point(&self, k: usize) -> Point2<f64> {
        self.context.point(k)
    }

    /// The linkage of sample `k`.
    ///
    /// # Errors
    ///
    /// As [`Task::four_bar`] (for an invalid sample).
    pub fn linkage(&self, k: usize) -> Result<SynthesizedFourBar> {
        self.context.linkage(k)
    }

    /// The signed margin of sample `k` (see [`MapContext::margin`]).
    pub fn margin(&self, k: usize) -> f64 {
        self.context.margin(k, &self.branch_free)
    }

    /// The `k` best acceptable candidates, best first (see
    /// [`MapContext::best_pivots`]).
    pub fn best_pivots(&self, k: usize, min_separation: Option<f64>) -> Vec<Pivot> {
        self.context.best_pivots(
            k,
            min_separation,
            &self.acceptable,
            &self.min_transmission,
            &self.branch_free,
        )
    }
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
        match self.varying {
            Varying::Driving { driven } => {
                let a = self.task.dyad_from_center(p)?;
                self.task.four_bar(&a, &driven)
            }
            Varying::Driven { driving } => {
                let c = self.task.dyad_from_center(p)?;
                self.task.four_bar(&driving, &c)
            }
        }
    }

    /// The signed margin of sample `k`: for candidate driving pivots, the
    /// distance to the nearest branch-defect boundary
    /// ([`Filemon::margin`]); for candidate driven pivots, the distance to
    /// the nearest sample of the other class in `branch_free`, measured on
    /// the grid within 64 samples (infinity beyond).
    pub fn margin(&self, k: usize, branch_free: &[bool]) -> f64 {
        match self.varying {
            Varying::Driving { driven } => Filemon::new(&self.task, driven)
                .map(|f| f.margin(self.point(k)))
                .unwrap_or(f64::NEG_INFINITY),
            Varying::Driven { .. } => self.grid_margin(k, branch_free),
        }
    }

    fn grid_margin(&self, k: usize, branch_free: &[bool]) -> f64 {
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        let (i, j) = ((k % nx) as isize, (k / nx) as isize);
        let me = branch_free[k];
        let p = self.point(k);
        let mut best = f64::INFINITY;
        for dj in -64isize..=64 {
            for di in -64isize..=64 {
                let (ii, jj) = (i + di, j + dj);
                if ii < 0 || jj < 0 || ii >= nx as isize || jj >= ny as isize {
                    continue;
                }
                let kk = jj as usize * nx + ii as usize;
                if branch_free[kk] != me {
                    best = best.min((self.point(kk) - p).norm());
                }
            }
        }
        if me { best } else { -best }
    }

    /// The `k` best acceptable candidates, best first, from the map's
    /// arrays.
    ///
    /// The score is the minimum transmission angle over the travel; ties
    /// (within 1e-9 rad) go to the larger margin to the nearest
    /// branch-defect boundary. Candidates closer than `min_separation` to
    /// a better one are skipped, so the list offers distinct options
    /// (default: 2% of the viewport's diagonal).
    pub fn best_pivots(
        &self,
        k: usize,
        min_separation: Option<f64>,
        acceptable: &[bool],
        min_transmission: &[f32],
        branch_free: &[bool],
    ) -> Vec<Pivot> {
        let sep = min_separation
            .filter(|s| s.is_finite() && *s >= 0.0)
            .unwrap_or(0.02 * self.grid.viewport().diagonal());
        let mut cand: Vec<(usize, f32)> = acceptable
            .iter()
            .zip(min_transmission)
            .enumerate()
            .filter(|(_, (a, t))| **a && !t.is_nan())
            .map(|(i, (_, t))| (i, *t))
            .collect();
        cand.sort_by(|a, b| b.1.total_cmp(&a.1));
        let mut out: Vec<Pivot> = Vec::new();
        let mut i = 0;
        while i < cand.len() && out.len() < k {
            // A run of equal scores: order by margin.
            let mut j = i + 1;
            while j < cand.len() && (cand[i].1 - cand[j].1).abs() <= 1e-9 {
                j += 1;
            }
            let mut run: Vec<(usize, f64)> = cand[i..j]
                .iter()
                .map(|&(s, _)| (s, self.margin(s, branch_free)))
                .collect();
            run.sort_by(|a, b| b.1.total_cmp(&a.1));
            for (s, margin) in run {
                if out.len() >= k {
                    break;
                }
                let p = self.point(s);
                if out.iter().any(|q| (q.center - p).norm() < sep) {
                    continue;
                }
                let Ok(linkage) = self.linkage(s) else {
                    continue;
                };
                let Ok(figures) = self.task.linkage_figures(&linkage.driving, &linkage.driven)
                else {
                    continue;
                };
                out.push(Pivot {
                    center: p,
                    index: s,
                    linkage,
                    figures,
                    margin,
                });
            }
            i = j;
        }
        out
    }
}

/// A candidate pivot with its linkage and figures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pivot {
    /// The candidate center point.
    pub center: Point2<f64>,
    /// Its row-major index in the map.
    pub index: usize,
    /// The complete linkage.
    pub linkage: SynthesizedFourBar,
    /// Its figures.
    pub figures: LinkageFigures,
    /// Its signed margin (see [`SolutionMap::margin`]).
    pub margin: f64,
}

/// One sample's values, for filling the arrays.
#[derive(Clone, Copy)]
struct Sample {
    valid: bool,
    branch_free: bool,
    grashof: u8,
    input_full: bool,
    direction: i8,
    one_circuit: bool,
    min_transmission: f32,
    link_ratio: f32,
    acceptable: bool,
}

impl Sample {
    const INVALID: Sample = Sample {
        valid: false,
        branch_free: false,
        grashof: SolutionMap::GRASHOF_NONE,
        input_full: false,
        direction: 0,
        one_circuit: false,
        min_transmission: f32::NAN,
        link_ratio: f32::NAN,
        acceptable: false,
    };
}

impl SolutionMap {
    fn empty(
        grid: Grid,
        task: Task,
        varying: Varying,
        limits: DesignLimits,
        constraints: Constraints,
    ) -> Self {
        let n = grid.len();
        SolutionMap {
            context: MapContext {
                grid,
                task,
                varying,
                limits,
                constraints,
            },
            valid: vec![false; n],
            branch_free: vec![false; n],
            grashof: vec![Self::GRASHOF_NONE; n],
            input_full: vec![false; n],
            direction: vec![0; n],
            one_circuit: vec![false; n],
            min_transmission: vec![f32::NAN; n],
            link_ratio: vec![f32::NAN; n],
            acceptable: vec![false; n],
        }
    }

    /// Fills every sample from `eval(point, branch_flag_hint) -> Sample`, in
    /// parallel over blocks of rows.
    fn fill(&mut self, eval: impl Fn(usize, Point2<f64>) -> Sample + Sync) {
        let nx = self.context.grid.nx();
        let grid = self.context.grid;
        let rows = (16_384 / nx).clamp(1, grid.ny().div_ceil(8).max(1));
        let chunk = nx * rows;
        let SolutionMap {
            valid,
            branch_free,
            grashof,
            input_full,
            direction,
            one_circuit,
            min_transmission,
            link_ratio,
            acceptable,
            ..
        } = self;
        valid
            .par_chunks_mut(chunk)
            .zip(branch_free.par_chunks_mut(chunk))
            .zip(grashof.par_chunks_mut(chunk))
            .zip(input_full.par_chunks_mut(chunk))
            .zip(direction.par_chunks_mut(chunk))
            .zip(one_circuit.par_chunks_mut(chunk))
            .zip(min_transmission.par_chunks_mut(chunk))
            .zip(link_ratio.par_chunks_mut(chunk))
            .zip(acceptable.par_chunks_mut(chunk))
            .enumerate()
            .for_each(|(b, ((((((((va, bf), gr), inf), di), oc), mt), lr), ac))| {
                let base = b * chunk;
                for r in (0..va.len()).step_by(nx) {
                    let j = (base + r) / nx;
                    let y = grid.y(j);
                    let row = r..r + nx;
                    let out = va[row.clone()]
                        .iter_mut()
                        .zip(&mut bf[row.clone()])
                        .zip(&mut gr[row.clone()])
                        .zip(&mut inf[row.clone()])
                        .zip(&mut di[row.clone()])
                        .zip(&mut oc[row.clone()])
                        .zip(&mut mt[row.clone()])
                        .zip(&mut lr[row.clone()])
                        .zip(&mut ac[row]);
                    for (i, ((((((((va, bf), gr), inf), di), oc), mt), lr), ac)) in out.enumerate()
                    {
                        let s = eval(base + r + i, Point2::new(grid.x(i), y));
                        *va = s.valid;
                        *bf = s.branch_free;
                        *gr = s.grashof;
                        *inf = s.input_full;
                        *di = s.direction;
                        *oc = s.one_circuit;
                        *mt = s.min_transmission;
                        *lr = s.link_ratio;
                        *ac = s.acceptable;
                    }
                }
            });
    }
}

fn sample(
    fig: Option<LinkageFigures>,
    branch_free: bool,
    limits: &DesignLimits,
    accept_extra: impl FnOnce(&LinkageFigures) -> bool,
) -> Sample {
    let Some(f) = fig else {
        return Sample::INVALID;
    };
    let ok = branch_free
        && f.one_circuit
        && f.direction != 0
        && f.min_transmission >= limits.min_transmission
        && f.link_ratio <= limits.max_link_ratio
        && match limits.input {
            InputRequirement::Any => true,
            InputRequirement::Crank => f.input_full,
            InputRequirement::Rocker => !f.input_full,
        };
    Sample {
        valid: true,
        branch_free,
        grashof: SolutionMap::grashof_code(f.grashof),
        input_full: f.input_full,
        direction: f.direction,
        one_circuit: f.one_circuit,
        min_transmission: f.min_transmission as f32,
        link_ratio: f.link_ratio as f32,
        acceptable: ok && accept_extra(&f),
    }
}

/// What the per-sample evaluation of either map shares: the task's
/// displacements, its frame, and the prepared constraints.
struct Sampler<'a> {
    task: Task,
    moves: Moves,
    origin: Point2<f64>,
    scale: f64,
    tiny: f64,
    limits: &'a DesignLimits,
    prepared: Prepared,
}

impl<'a> Sampler<'a> {
    fn new(task: &Task, limits: &'a DesignLimits, constraints: &Constraints) -> Result<Self> {
        limits.validate()?;
        let (origin, scale) = task.frame();
        Ok(Sampler {
            task: *task,
            moves: Moves::new(task),
            origin,
            scale,
            tiny: Task::POINT_TOLERANCE * task.scale(),
            limits,
            prepared: constraints.prepare()?,
        })
    }

    /// The moving pivot at the three poses of the dyad centered at `p` (its
    /// circle point by the closed form), or `None` where it does not exist.
    #[inline(always)]
    fn moving_pivots(&self, p: Point2<f64>) -> Option<[Point2<f64>; 3]> {
        let (u, kappa, den, _) = self.task.map_parts((p - self.origin) / self.scale, -1.0);
        let q = self.origin + u * (kappa / den * self.scale);
        if !(q.x.is_finite() && q.y.is_finite()) || den == 0.0 {
            return None;
        }
        Some([q, self.moves.apply(1, q), self.moves.apply(2, q)])
    }

    /// The moving pivot of a fixed dyad at the three poses.
    fn fixed_pivots(&self, d: &Dyad) -> [Point2<f64>; 3] {
        [0, 1, 2].map(|k| self.moves.apply(k, d.circle))
    }

    /// The sample for figures `fig` with branch flag `branch_free`, where
    /// `candidate` is the varying center point and `driving`, `driven` the
    /// linkage's dyads (for the constraints).
    fn sample(
        &self,
        fig: Option<LinkageFigures>,
        branch_free: bool,
        candidate: Point2<f64>,
        driving: Dyad,
        driven: Dyad,
    ) -> Sample {
        sample(fig, branch_free, self.limits, |f| {
            self.prepared.pivot_ok(candidate)
                && (self.prepared.obstacles.is_empty()
                    || self
                        .task
                        .four_bar(&driving, &driven)
                        .is_ok_and(|fb| self.prepared.clearance_ok(&fb, f)))
        })
    }
}

impl Filemon {
    /// The solution-space map over candidate driving center points `A0`
    /// (module docs). The branch-free flag is exactly the `conic` branch
    /// map; the other figures come from the linkage at each sample.
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for invalid limits or constraints.
    pub fn solution_map(
        &self,
        grid: &Grid,
        limits: &DesignLimits,
        constraints: &Constraints,
    ) -> Result<SolutionMap> {
        let sampler = Sampler::new(self.task(), limits, constraints)?;
        let driven = self.driven();
        let mut map = SolutionMap::empty(
            *grid,
            *self.task(),
            Varying::Driving { driven },
            *limits,
            constraints.clone(),
        );
        let branch = self.branch_map(grid, Method::Conic);
        let c = sampler.fixed_pivots(&driven);
        map.fill(|k, a0| {
            let Some(a) = sampler.moving_pivots(a0) else {
                return Sample::INVALID;
            };
            let fig = figures::<false>(a0, a, driven.center, c, sampler.tiny);
            sampler.sample(fig, branch[k], a0, Dyad::new(a0, a[0]), driven)
        });
        Ok(map)
    }
}

impl Task {
    /// The solution-space map over candidate driven center points `C0`,
    /// with a fixed driving dyad: the other direction of
    /// [`Filemon::solution_map`], so a designer can iterate either way. The
    /// branch-free flag is the sign test at the three poses.
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for invalid limits or constraints, or a driving
    /// dyad that is not a dyad of this task.
    pub fn driven_solution_map(
        &self,
        driving: &Dyad,
        grid: &Grid,
        limits: &DesignLimits,
        constraints: &Constraints,
    ) -> Result<SolutionMap> {
        let sampler = Sampler::new(self, limits, constraints)?;
        positive("driving crank length", driving.length())?;
        let d = self.dyad_from_center(driving.center)?;
        if (d.circle - driving.circle).norm() > 1e-9 * (self.scale() + driving.length()) {
            return Err(InvalidInput::OutOfRange {
                name: "driving dyad",
                expected: "must be a dyad of the task (its circle point the circle point of its \
                           center point)",
                found: format!("{driving:?}"),
            }
            .into());
        }
        let mut map = SolutionMap::empty(
            *grid,
            *self,
            Varying::Driven { driving: *driving },
            *limits,
            constraints.clone(),
        );
        let a = sampler.fixed_pivots(driving);
        map.fill(|_, c0| {
            let Some(c) = sampler.moving_pivots(c0) else {
                return Sample::INVALID;
            };
            let fig = figures::<true>(driving.center, a, c0, c, sampler.tiny);
            let free = fig.is_some_and(|f| f.branch_free());
            sampler.sample(fig, free, c0, *driving, Dyad::new(c0, c[0]))
        });
        Ok(map)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pseudo_angle_is_monotone() {
        let r = Vector2::new(1.0, 0.0);
        let mut last = -1.0;
        for k in 0..360 {
            let a = (k as f64).to_radians();
            let p = pseudo_angle(r, Vector2::new(a.cos(), a.sin()));
            assert!(p > last, "{k}: {p} <= {last}");
            assert!((0.0..4.0).contains(&p));
            last = p;
        }
    }

    #[test]
    fn limits_validate() {
        assert!(DesignLimits::default().validate().is_ok());
        let l = |t: f64, r: f64| DesignLimits {
            min_transmission: t,
            max_link_ratio: r,
            input: InputRequirement::Any,
        };
        assert!(l(2.0, 10.0).validate().is_err());
        assert!(l(0.1, 0.5).validate().is_err());
        assert!(l(0.1, f64::NAN).validate().is_err());
        assert!(l(0.1, f64::INFINITY).validate().is_ok());
        assert_eq!(
            "Crank".parse::<InputRequirement>().unwrap(),
            InputRequirement::Crank
        );
    }
}
