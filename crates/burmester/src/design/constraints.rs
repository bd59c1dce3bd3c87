//! Where the linkage may be: a base plate for the fixed pivot, and obstacles
//! the moving links must clear over the whole travel (parry shapes).
//!
//! # Clearance over the whole travel, not only at samples
//!
//! The links are capsules `link_width` wide around their center lines. The
//! travel is checked at `travel_samples` input angles, and between them by a
//! bound on how far any point of a link can move: a rigid link's velocity
//! field is affine, so along a link no point moves faster than its faster
//! end. The crank tip moves `L2 dtheta`; the rocker tip moves
//! `L4 dtheta4 = L2 dtheta |sin(theta2 - theta3)| / |sin mu|`, at most
//! `L2 dtheta / sin mu_min` with `mu_min` the minimum transmission angle
//! over the travel (exact, [`LinkageFigures::min_transmission`](crate::LinkageFigures::min_transmission)). So within
//! `h` of an input angle every point of every moving link stays within
//!
//! ```text
//! r(h) = L2 h / sin mu_min
//! ```
//!
//! of where it is at that angle. An interval of the travel is clear when
//! the capsules at its middle, inflated by `r(half width)`, miss every
//! obstacle; when they do not, the plain capsules are tested (a hit there
//! is a real collision) and otherwise the interval is halved, down to
//! [`Constraints::MIN_STEP`]. Below that the linkage counts as colliding:
//! "acceptable" never admits a linkage that is not certified clear.
//!
//! # An envelope the moving links stay inside
//!
//! An optional [`Constraints::envelope`] (a simple polygon: the machine's
//! inside) must hold the moving parts over the whole travel: the crank,
//! the rocker and the coupler as its triangle of the two moving pivots and
//! the task's coupler point, each a capsule `link_width` wide. Its
//! boundary has no holes, so the linkage (one connected chain from `A0` to
//! `C0`) is inside exactly when the input pivot `A0` is inside and no
//! capsule touches the boundary. The same halving over the travel decides
//! it, with the coupler point's speed in the bound: the coupler turns at
//! most `L2 / (L3 sin mu_min)` per radian of input, so a point at distance
//! `d` from the crank joint moves at most `L2 (1 + d / L3) / sin mu_min`
//! per radian, and so does every point of the triangle.

use core::sync::atomic::{AtomicBool, Ordering};

use nalgebra::Point2;
use parry2d_f64::math::Vector as PVector;
use parry2d_f64::query::intersection_test;
use parry2d_f64::shape::{Capsule, ConvexPolygon, Segment};
use parry2d_f64::utils::point_in_poly2d;

use crate::error::{InvalidInput, PolygonProblem, Result, bounded, count_in, in_range};
use crate::geom::cross;
use crate::linkage::AssemblyMode;
use crate::synthesis::{SynthesizedFourBar, SynthesizedSliderCrank};
use crate::tolerance;

/// Where the linkage may be: a base plate for the fixed pivot being placed,
/// obstacles the moving links must clear.
#[derive(Debug, Clone, PartialEq)]
pub struct Constraints {
    /// The fixed pivot being placed must lie inside this simple polygon
    /// (vertices in order); `None`: anywhere.
    pub base_plate: Option<Vec<Point2<f64>>>,
    /// Convex obstacles (vertices in any order: their convex hull is used;
    /// give a non-convex obstacle as several convex pieces).
    pub obstacles: Vec<Vec<Point2<f64>>>,
    /// The width of the moving links (crank, coupler, rocker), modelled as
    /// capsules of this diameter around their center lines (at least 0).
    pub link_width: f64,
    /// At how many evenly spaced input angles of the travel the clearance
    /// check starts (2 to [`Constraints::MAX_TRAVEL_SAMPLES`], default 64);
    /// between them it refines where needed (module docs).
    pub travel_samples: usize,
    /// A simple polygon the moving links (crank, rocker and the coupler
    /// triangle with the coupler point) must stay inside over the whole
    /// travel, `link_width` wide (module docs); `None`: no envelope. It
    /// must contain every pose's coupler point.
    pub envelope: Option<Vec<Point2<f64>>>,
}

impl Default for Constraints {
    fn default() -> Self {
        Constraints {
            base_plate: None,
            obstacles: Vec::new(),
            link_width: 0.0,
            travel_samples: Self::DEFAULT_TRAVEL_SAMPLES,
            envelope: None,
        }
    }
}

impl Constraints {
    /// The default number of travel samples.
    pub const DEFAULT_TRAVEL_SAMPLES: usize = 64;

    /// The most travel samples (the work per linkage grows with them).
    pub const MAX_TRAVEL_SAMPLES: usize = 4096;

    /// The largest magnitude of a vertex coordinate.
    pub const MAX_COORDINATE: f64 = 1e100;

    /// The most vertices of one polygon (the base plate, an obstacle): each
    /// candidate pivot is tested against every edge of the base plate and
    /// each clearance test walks an obstacle's vertices, so the work grows
    /// with them. A circle of a few hundred vertices is within `1e-4` of
    /// its radius; approximate finer outlines.
    pub const MAX_POLYGON_VERTICES: usize = 4096;

    /// The smallest input step (radians) of the clearance refinement: an
    /// interval that cannot be certified clear at this width counts as a
    /// collision.
    pub const MIN_STEP: f64 = 1e-9;

    /// No constraints.
    pub fn none() -> Self {
        Constraints::default()
    }

    /// Validates the constraints and builds parry shapes.
    ///
    /// # Errors
    ///
    /// [`InvalidInput`] for a non-finite or too large vertex, a negative or
    /// non-finite `link_width`, a travel sample count out of range, a base
    /// plate that is not a simple polygon with an area, an obstacle
    /// without an area, or a polygon of more than
    /// [`Constraints::MAX_POLYGON_VERTICES`] vertices.
    pub(crate) fn prepare(&self) -> Result<Prepared> {
        const RESCALE: &str = "rescale the constraints with the task";
        for p in self
            .base_plate
            .iter()
            .flatten()
            .chain(self.obstacles.iter().flatten())
            .chain(self.envelope.iter().flatten())
        {
            bounded("constraint vertex x", p.x, Self::MAX_COORDINATE, RESCALE)?;
            bounded("constraint vertex y", p.y, Self::MAX_COORDINATE, RESCALE)?;
        }
        let width = in_range("link_width", self.link_width, 0.0, Self::MAX_COORDINATE, "")?;
        let samples = count_in(
            "travel_samples",
            self.travel_samples,
            2,
            Self::MAX_TRAVEL_SAMPLES,
        )?;
        if let Some(plate) = &self.base_plate {
            check_polygon("base_plate", plate, true)?;
        }
        if let Some(env) = &self.envelope {
            check_polygon("envelope", env, true)?;
        }
        let mut obstacles = Vec::with_capacity(self.obstacles.len());
        for (k, o) in self.obstacles.iter().enumerate() {
            // parry's hull asserts on fewer than two distinct points: check
            // that the vertices span an area first.
            let name = || format!("obstacle {}", k + 1);
            check_polygon(&name(), o, false)?;
            let pts: Vec<PVector> = o.iter().map(|p| PVector::new(p.x, p.y)).collect();
            let hull = ConvexPolygon::from_convex_hull(&pts).ok_or(InvalidInput::Polygon {
                name: name(),
                vertices: o.len(),
                problem: PolygonProblem::NoArea,
            })?;
            obstacles.push(hull);
        }
        Ok(Prepared {
            plate: self
                .base_plate
                .as_ref()
                .map(|p| p.iter().map(|q| PVector::new(q.x, q.y)).collect()),
            obstacles,
            envelope: self.envelope.as_ref().map(|e| {
                let pts: Vec<PVector> = e.iter().map(|q| PVector::new(q.x, q.y)).collect();
                let edges = (0..pts.len())
                    .map(|k| Segment::new(pts[k], pts[(k + 1) % pts.len()]))
                    .collect();
                (pts, edges)
            }),
            radius: 0.5 * width,
            samples,
        })
    }
}

/// Whether `p` lies inside the simple polygon `poly` (its boundary
/// included, as parry's test takes it).
pub(crate) fn inside_polygon(poly: &[Point2<f64>], p: Point2<f64>) -> bool {
    let pts: Vec<PVector> = poly.iter().map(|q| PVector::new(q.x, q.y)).collect();
    point_in_poly2d(PVector::new(p.x, p.y), &pts)
}

/// Checks a polygon that must be simple (a base plate, a region, an
/// envelope), naming it `name`.
///
/// # Errors
///
/// [`InvalidInput::Polygon`] for fewer than three vertices, no area or
/// crossing edges; [`InvalidInput::NotFinite`] for a non-finite vertex.
pub(crate) fn check_simple_polygon(name: &str, pts: &[Point2<f64>]) -> Result<()> {
    for p in pts {
        bounded(
            "polygon vertex x",
            p.x,
            Constraints::MAX_COORDINATE,
            "rescale the polygon with the task",
        )?;
        bounded(
            "polygon vertex y",
            p.y,
            Constraints::MAX_COORDINATE,
            "rescale the polygon with the task",
        )?;
    }
    check_polygon(name, pts, true)?;
    Ok(())
}

/// Checks that a polygon has three vertices spanning an area and, when
/// `simple` is asked for, that no two of its edges cross.
fn check_polygon(name: &str, pts: &[Point2<f64>], simple: bool) -> Result<(), InvalidInput> {
    let bad = |problem| InvalidInput::Polygon {
        name: name.to_owned(),
        vertices: pts.len(),
        problem,
    };
    if pts.len() < 3 {
        return Err(bad(PolygonProblem::TooFewVertices));
    }
    if pts.len() > Constraints::MAX_POLYGON_VERTICES {
        return Err(bad(PolygonProblem::TooManyVertices));
    }
    if !spans_area(pts) {
        return Err(bad(PolygonProblem::NoArea));
    }
    if simple && self_intersects(pts) {
        return Err(bad(PolygonProblem::SelfIntersecting));
    }
    Ok(())
}

/// Whether the points span an area: not all on one line (relative to their
/// extent, [`tolerance::COLLINEAR`]).
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
    extent > 0.0
        && pts
            .iter()
            .any(|q| cross(d, q - p0).abs() > tolerance::COLLINEAR * extent)
}

/// Whether the segments `a b` and `c d` meet: they cross, or an end of one
/// lies on the other (exact orientation tests).
fn segments_meet((a, b): (Point2<f64>, Point2<f64>), (c, d): (Point2<f64>, Point2<f64>)) -> bool {
    let orient = |a: Point2<f64>, b: Point2<f64>, c: Point2<f64>| cross(b - a, c - a);
    let on = |a: Point2<f64>, b: Point2<f64>, c: Point2<f64>| {
        orient(a, b, c) == 0.0
            && c.x >= a.x.min(b.x)
            && c.x <= a.x.max(b.x)
            && c.y >= a.y.min(b.y)
            && c.y <= a.y.max(b.y)
    };
    let (d1, d2) = (orient(c, d, a), orient(c, d, b));
    let (d3, d4) = (orient(a, b, c), orient(a, b, d));
    ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
        || on(c, d, a)
        || on(c, d, b)
        || on(a, b, c)
        || on(a, b, d)
}

/// Whether two edges of the closed polygon cross or touch (adjacent edges
/// share only their common vertex). The edges are swept by their smallest
/// `x` so that only edges whose `x` extents overlap are compared: `n log n`
/// for the outlines of parts, at most `n^2 / 2` tests (`n` is at most
/// [`Constraints::MAX_POLYGON_VERTICES`]).
fn self_intersects(pts: &[Point2<f64>]) -> bool {
    let n = pts.len();
    let edge = |i: usize| (pts[i], pts[(i + 1) % n]);
    let meet = segments_meet;
    let adjacent = |i: usize, j: usize| {
        let (i, j) = (i.min(j), i.max(j));
        j == i + 1 || (i == 0 && j == n - 1)
    };
    // Adjacent edges share a vertex; they overlap only if they fold back on
    // each other along one line.
    for i in 0..n {
        let (p, shared, q) = (pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n]);
        let (u, v) = (p - shared, q - shared);
        if cross(u, v) == 0.0 && u.dot(&v) > 0.0 {
            return true;
        }
    }
    let x_range = |i: usize| {
        let (a, b) = edge(i);
        (a.x.min(b.x), a.x.max(b.x))
    };
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_unstable_by(|&a, &b| x_range(a).0.total_cmp(&x_range(b).0));
    for (k, &i) in order.iter().enumerate() {
        let right = x_range(i).1;
        for &j in &order[k + 1..] {
            if x_range(j).0 > right {
                break;
            }
            if !adjacent(i, j) && meet(edge(i), edge(j)) {
                return true;
            }
        }
    }
    false
}

/// Constraints as parry shapes.
#[derive(Clone)]
pub(crate) struct Prepared {
    plate: Option<Vec<PVector>>,
    pub(crate) obstacles: Vec<ConvexPolygon>,
    /// The envelope's vertices and its boundary edges.
    envelope: Option<(Vec<PVector>, Vec<Segment>)>,
    radius: f64,
    samples: usize,
}

impl Prepared {
    /// The default constraints ([`Constraints::default`]) as shapes: what
    /// [`Constraints::prepare`] gives them, without a check that cannot
    /// fail.
    pub(crate) fn unconstrained() -> Self {
        Prepared {
            plate: None,
            obstacles: Vec::new(),
            envelope: None,
            radius: 0.0,
            samples: Constraints::DEFAULT_TRAVEL_SAMPLES,
        }
    }

    /// Whether there is nothing to test: no base plate, no obstacles, no
    /// envelope.
    pub(crate) fn is_empty(&self) -> bool {
        self.plate.is_none() && self.obstacles.is_empty() && self.envelope.is_none()
    }

    /// Whether the motion must be checked (obstacles or an envelope).
    pub(crate) fn checks_motion(&self) -> bool {
        !self.obstacles.is_empty() || self.envelope.is_some()
    }

    /// Whether the linkage clears the obstacles and stays inside the
    /// envelope over the whole travel (module docs).
    pub(crate) fn motion_ok(&self, fb: &SynthesizedFourBar, cancel: Option<&AtomicBool>) -> bool {
        self.clearance_ok(fb, cancel) && self.envelope_ok(fb, cancel)
    }

    /// Whether the envelope (if any) holds the point `p`.
    pub(crate) fn in_envelope(&self, p: Point2<f64>) -> bool {
        self.envelope
            .as_ref()
            .is_none_or(|(poly, _)| point_in_poly2d(PVector::new(p.x, p.y), poly))
    }

    /// Whether the moving parts stay inside the envelope over the whole
    /// travel (module docs); true without an envelope.
    pub(crate) fn envelope_ok(&self, fb: &SynthesizedFourBar, cancel: Option<&AtomicBool>) -> bool {
        let Some((_, edges)) = &self.envelope else {
            return true;
        };
        if !self.in_envelope(fb.driving.center) {
            return false;
        }
        let (l2, l3) = (fb.fourbar.crank(), fb.figures.lengths[2]);
        let d = fb.coupler_point.norm();
        let Some(rate) = self.rate(fb, l2 * (1.0 + d / l3)) else {
            return false;
        };
        let identity = parry2d_f64::math::Pose::identity();
        let v = |p: Point2<f64>| PVector::new(p.x, p.y);
        let radius = self.radius;
        let clear_at = |mode: AssemblyMode, theta: f64, extra: f64| -> Option<bool> {
            let j = fb.fourbar.joints_at(theta, mode).ok()?;
            let c = fb.fourbar.solve(theta, mode).ok()?;
            let p = fb.fourbar.coupler_point(&c, fb.coupler_point);
            let links = [
                (j.input_pivot, j.crank_joint),
                (j.crank_joint, j.rocker_joint),
                (j.crank_joint, p),
                (j.rocker_joint, p),
                (j.output_pivot, j.rocker_joint),
            ];
            for (a, b) in links {
                let cap = Capsule::new(v(a), v(b), radius + extra);
                for e in edges {
                    let hit = intersection_test(&identity, &cap, &identity, e)
                        .map_or(true, |r| r.intersecting);
                    if hit {
                        return Some(false);
                    }
                }
            }
            Some(true)
        };
        self.over_travel(fb, rate, &clear_at, Go(cancel))
    }

    /// How fast (per radian of input) no point of the checked parts moves
    /// faster than, from `speed`, the speed bound before the division by
    /// the sine of the minimum transmission angle; `None` when that angle
    /// is not positive (no bound).
    fn rate(&self, fb: &SynthesizedFourBar, speed: f64) -> Option<f64> {
        let sin_mu = fb.figures.min_transmission.sin();
        (sin_mu > 0.0 && speed.is_finite()).then(|| speed / sin_mu)
    }

    /// Whether `clear_at(mode, theta, extra)` holds over the whole travel
    /// (`rate`: the bound on how fast a checked point moves), checked at
    /// the middles of `samples` intervals and refined by halves; false
    /// once `go` says the computation was cancelled.
    fn over_travel(
        &self,
        fb: &SynthesizedFourBar,
        rate: f64,
        clear_at: &dyn Fn(AssemblyMode, f64, f64) -> Option<bool>,
        go: Go<'_>,
    ) -> bool {
        self.over_crank_travel(fb.modes().first().copied(), fb.travel(), rate, clear_at, go)
    }

    /// [`over_travel`](Self::over_travel) of a crank in assembly mode
    /// `mode` (pose 1's) over the travel `(start, span)`; false without
    /// them.
    fn over_crank_travel(
        &self,
        mode: Option<Option<AssemblyMode>>,
        travel: Option<(f64, f64)>,
        rate: f64,
        clear_at: &dyn Fn(AssemblyMode, f64, f64) -> Option<bool>,
        go: Go<'_>,
    ) -> bool {
        let (Some(Some(mode)), Some((start, span))) = (mode, travel) else {
            return false;
        };
        let n = self.samples;
        let step = span / n as f64;
        (0..n).all(|k| {
            let mid = start + step * (k as f64 + 0.5);
            go.on() && interval_clear(clear_at, mode, mid, 0.5 * step.abs(), rate, go)
        })
    }

    /// Whether the fixed pivot `p` is on the base plate.
    pub(crate) fn pivot_ok(&self, p: Point2<f64>) -> bool {
        self.plate
            .as_ref()
            .is_none_or(|poly| point_in_poly2d(PVector::new(p.x, p.y), poly))
    }

    /// Whether the moving links, inflated by `extra`, clear every obstacle
    /// at input angle `theta` (`None`: the loop does not close there).
    fn clear_at(
        &self,
        fb: &SynthesizedFourBar,
        mode: AssemblyMode,
        theta: f64,
        extra: f64,
    ) -> Option<bool> {
        let j = fb.fourbar.joints_at(theta, mode).ok()?;
        let v = |p: Point2<f64>| PVector::new(p.x, p.y);
        let identity = parry2d_f64::math::Pose::identity();
        let links = [
            (j.input_pivot, j.crank_joint),
            (j.crank_joint, j.rocker_joint),
            (j.output_pivot, j.rocker_joint),
        ];
        for (a, b) in links {
            let cap = Capsule::new(v(a), v(b), self.radius + extra);
            for o in &self.obstacles {
                let hit = intersection_test(&identity, &cap, &identity, o)
                    .map_or(true, |r| r.intersecting);
                if hit {
                    return Some(false);
                }
            }
        }
        Some(true)
    }

    /// The envelope's boundary edges, if any (the actuator's clearance,
    /// `design::actuator`).
    pub(crate) fn envelope_edges(&self) -> Option<&[Segment]> {
        self.envelope.as_ref().map(|(_, e)| e.as_slice())
    }

    /// Half the links' width: the radius of their capsules.
    pub(crate) fn radius(&self) -> f64 {
        self.radius
    }

    /// How many intervals the clearance check starts from.
    pub(crate) fn samples(&self) -> usize {
        self.samples
    }

    /// Whether the segments, as capsules of the links' width inflated by
    /// `extra`, clear every obstacle (the six-bar's check over a crank
    /// turn, `design::drive`).
    pub(crate) fn segments_clear(
        &self,
        segments: &[(Point2<f64>, Point2<f64>)],
        extra: f64,
    ) -> bool {
        let v = |p: Point2<f64>| PVector::new(p.x, p.y);
        let identity = parry2d_f64::math::Pose::identity();
        segments.iter().all(|&(a, b)| {
            let cap = Capsule::new(v(a), v(b), self.radius + extra);
            self.obstacles.iter().all(|o| {
                !intersection_test(&identity, &cap, &identity, o).map_or(true, |r| r.intersecting)
            })
        })
    }

    /// Whether the moving links clear every obstacle over the whole travel
    /// (module docs). One test can take milliseconds to seconds (thousands
    /// of travel samples, refined), so it checks `cancel` between
    /// intervals and fails once it is set (the computation it serves is
    /// then cancelled and its answer dropped).
    pub(crate) fn clearance_ok(
        &self,
        fb: &SynthesizedFourBar,
        cancel: Option<&AtomicBool>,
    ) -> bool {
        if self.obstacles.is_empty() {
            return true;
        }
        // Within `h` of a checked angle no point of a link moves farther
        // than `rate * h`.
        let Some(rate) = self.rate(fb, fb.fourbar.crank()) else {
            return false;
        };
        let clear_at = |mode, theta, extra| self.clear_at(fb, mode, theta, extra);
        self.over_travel(fb, rate, &clear_at, Go(cancel))
    }
}

/// # A slider-crank over its travel
///
/// A slider-crank's moving parts (a map with a driven slider,
/// [`Filemon::solution_map`](crate::Filemon::solution_map) of a [`Filemon`](crate::Filemon)
/// built with a driven slider; `SliderFilemon.solution_map` in Python)
/// are checked as a four-bar's, capsules `link_width` wide: against the
/// obstacles the crank `A0 A` and the coupler `A B`; inside the envelope
/// the crank and the coupler triangle `A B P` (`P` the task's coupler
/// point). The slider's block is its pin `B` with the links' width: the
/// coupler's capsule ends at `B`, so checking it over the whole travel
/// checks the block's path, the length of guide the slider runs on (the
/// [`stroke_used`](SynthesizedSliderCrank::stroke_used)). The block's own
/// length and the rail beyond the stroke are the designer's (leave half
/// the block's length free along the guide past the stroke).
///
/// The bound on how fast a point moves per radian of crank: the crank pin
/// `A` moves `r`; the pin `B` moves along the guide with the component of
/// `A`'s velocity along the coupler, `|v_B| sin mu <= r` (`mu` the
/// transmission angle, between the coupler and the guide's normal), so
/// `|v_B| <= r / sin mu`; the coupler turns at most `(|v_A| + |v_B|) / l`,
/// and a point of the coupler at distance `d` from `A` moves at most
/// `r + d r (1 + 1 / sin mu) / l`. The coupler's points are convex
/// combinations of `A`, `B` and `P` (velocities affine), so
/// `r (1 + 1 / sin mu) (1 + d / l)` with `d` the larger of `l` and `|P - A|`
/// bounds every moving point.
impl Prepared {
    /// Whether the slider-crank `sc` clears the obstacles and stays inside
    /// the envelope over the whole travel (see above); false once `cancel`
    /// is set.
    pub(crate) fn slider_motion_ok(
        &self,
        sc: &SynthesizedSliderCrank,
        cancel: Option<&AtomicBool>,
    ) -> bool {
        self.slider_checked(sc, Checks::Both, cancel)
    }

    /// [`slider_motion_ok`](Self::slider_motion_ok) for the obstacles
    /// alone, the envelope alone, or both (the one-call design counts a
    /// candidate's failures by limit).
    pub(crate) fn slider_checked(
        &self,
        sc: &SynthesizedSliderCrank,
        checks: Checks,
        cancel: Option<&AtomicBool>,
    ) -> bool {
        let obstacles = checks != Checks::Envelope && !self.obstacles.is_empty();
        let envelope = checks != Checks::Obstacles && self.envelope.is_some();
        if !(obstacles || envelope) {
            return true;
        }
        if envelope && !self.in_envelope(sc.driving.center) {
            return false;
        }
        let l = &sc.linkage;
        let sin_mu = sc.min_transmission.sin();
        let d = sc.coupler_point.norm().max(l.coupler());
        let rate = l.crank() * (1.0 + 1.0 / sin_mu) * (1.0 + d / l.coupler());
        if !(sin_mu > 0.0 && rate.is_finite()) {
            return false;
        }
        let identity = parry2d_f64::math::Pose::identity();
        let v = |p: Point2<f64>| PVector::new(p.x, p.y);
        let clear_at = |mode: AssemblyMode, theta: f64, extra: f64| -> Option<bool> {
            let j = l.joints_at(theta, mode).ok()?;
            let p = j.coupler_point(sc.coupler_point);
            let (a0, a, b) = (j.crank_pivot, j.crank_joint, j.slider_joint);
            let hits = |(x, y): (Point2<f64>, Point2<f64>),
                        shape: &dyn parry2d_f64::shape::Shape| {
                let cap = Capsule::new(v(x), v(y), self.radius + extra);
                intersection_test(&identity, &cap, &identity, shape)
                    .map_or(true, |r| r.intersecting)
            };
            let struck = obstacles
                && [(a0, a), (a, b)]
                    .into_iter()
                    .any(|seg| self.obstacles.iter().any(|o| hits(seg, o)));
            let escapes = envelope
                && self.envelope.as_ref().is_some_and(|(_, edges)| {
                    [(a0, a), (a, b), (a, p), (b, p)]
                        .into_iter()
                        .any(|seg| edges.iter().any(|e| hits(seg, e)))
                });
            Some(!struck && !escapes)
        };
        self.over_crank_travel(
            sc.modes.first().copied(),
            sc.travel(),
            rate,
            &clear_at,
            Go(cancel),
        )
    }
}

/// What a slider-crank's motion is checked against
/// ([`Prepared::slider_checked`]).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Checks {
    /// The obstacles only.
    Obstacles,
    /// The envelope only.
    Envelope,
    /// Both.
    Both,
}

/// Whether a clearance test may go on: its computation's cancel flag is
/// not set.
#[derive(Clone, Copy)]
struct Go<'a>(Option<&'a AtomicBool>);

impl Go<'_> {
    #[inline]
    fn on(self) -> bool {
        self.0.is_none_or(|c| !c.load(Ordering::Relaxed))
    }
}

/// Whether the travel within `half` of `mid` is clear by `clear_at`,
/// refining by halves where the inflated test cannot decide.
fn interval_clear(
    clear_at: &dyn Fn(AssemblyMode, f64, f64) -> Option<bool>,
    mode: AssemblyMode,
    mid: f64,
    half: f64,
    rate: f64,
    go: Go<'_>,
) -> bool {
    match clear_at(mode, mid, rate * half) {
        Some(true) => return true,
        None => return false,
        Some(false) => {}
    }
    // A hit of the plain capsules is a collision.
    if clear_at(mode, mid, 0.0) != Some(true) || half < Constraints::MIN_STEP || !go.on() {
        return false;
    }
    let q = 0.5 * half;
    interval_clear(clear_at, mode, mid - q, q, rate, go)
        && interval_clear(clear_at, mode, mid + q, q, rate, go)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(v: &[[f64; 2]]) -> Vec<Point2<f64>> {
        v.iter().map(|&[x, y]| Point2::new(x, y)).collect()
    }

    #[test]
    fn polygons_are_checked() {
        let square = pts(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
        assert!(check_polygon("p", &square, true).is_ok());
        let bow = pts(&[[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]]);
        let e = check_polygon("p", &bow, true).unwrap_err();
        assert!(matches!(
            e,
            InvalidInput::Polygon {
                problem: PolygonProblem::SelfIntersecting,
                ..
            }
        ));
        // A convex obstacle's vertices may come in any order.
        assert!(check_polygon("o", &bow, false).is_ok());
        let line = pts(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]);
        assert!(check_polygon("p", &line, true).is_err());
        assert!(check_polygon("p", &line[..2], true).is_err());
        let spike = pts(&[[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 1.0]]);
        assert!(check_polygon("p", &spike, true).is_err());
    }

    /// The check before the sweep: every pair of edges.
    fn self_intersects_brute(pts: &[Point2<f64>]) -> bool {
        let n = pts.len();
        let meet = segments_meet;
        let edge = |i: usize| (pts[i], pts[(i + 1) % n]);
        for i in 0..n {
            for j in i + 1..n {
                if j == i + 1 || (i == 0 && j == n - 1) {
                    let (shared, p, q) = if j == i + 1 {
                        (pts[j], pts[i], pts[(j + 1) % n])
                    } else {
                        (pts[0], pts[1], pts[n - 1])
                    };
                    let (u, v) = (p - shared, q - shared);
                    if cross(u, v) == 0.0 && u.dot(&v) > 0.0 {
                        return true;
                    }
                } else if meet(edge(i), edge(j)) {
                    return true;
                }
            }
        }
        false
    }

    #[test]
    fn the_sweep_finds_what_every_pair_finds() {
        // Polygons on a small integer lattice: crossings, touchings,
        // collinear overlaps and folds come up often.
        let mut x = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = move |m: u64| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x % m) as f64
        };
        let mut found = [0usize; 2];
        for case in 0..20_000 {
            let n = 3 + (case % 9);
            let p: Vec<Point2<f64>> = (0..n).map(|_| Point2::new(next(5), next(5))).collect();
            let want = self_intersects_brute(&p);
            assert_eq!(self_intersects(&p), want, "{p:?}");
            found[usize::from(want)] += 1;
        }
        assert!(found[0] > 1000 && found[1] > 1000, "{found:?}");
    }

    /// The shapes of no constraints, made without a check, are what the
    /// check gives the default constraints.
    #[test]
    fn unconstrained_is_the_default_prepared() {
        let (a, b) = (
            Prepared::unconstrained(),
            Constraints::default().prepare().unwrap(),
        );
        assert!(a.plate.is_none() && b.plate.is_none());
        assert!(a.obstacles.is_empty() && b.obstacles.is_empty());
        assert!(a.envelope.is_none() && b.envelope.is_none());
        assert_eq!(a.radius.to_bits(), b.radius.to_bits());
        assert_eq!(a.samples, b.samples);
        assert!(a.is_empty() && !a.checks_motion());
    }

    #[test]
    fn a_large_polygon_is_checked_quickly_or_refused() {
        // A circle of the most vertices allowed: checked (the sweep looks
        // at edges whose x ranges overlap, not at every pair).
        let n = Constraints::MAX_POLYGON_VERTICES;
        let circle = |n: usize| -> Vec<Point2<f64>> {
            (0..n)
                .map(|k| {
                    let t = core::f64::consts::TAU * k as f64 / n as f64;
                    Point2::new(t.cos(), t.sin())
                })
                .collect()
        };
        let c = Constraints {
            base_plate: Some(circle(n)),
            obstacles: vec![circle(n)],
            ..Constraints::default()
        };
        assert!(c.prepare().is_ok());
        // One more vertex: refused, naming the bound.
        let c = Constraints {
            obstacles: vec![circle(n + 1)],
            ..Constraints::default()
        };
        let e = c.prepare().err().expect("too many vertices");
        assert!(matches!(
            e,
            crate::Error::InvalidInput(InvalidInput::Polygon {
                problem: PolygonProblem::TooManyVertices,
                ..
            })
        ));
        let msg = e.to_string();
        assert!(
            msg.contains("obstacle 1") && msg.contains("more than 4096 vertices"),
            "{msg}"
        );
    }

    #[test]
    fn bad_numbers_are_refused() {
        let c = |w: f64, n: usize| Constraints {
            link_width: w,
            travel_samples: n,
            ..Constraints::default()
        };
        assert!(c(0.0, 64).prepare().is_ok());
        assert!(c(-1.0, 64).prepare().is_err());
        assert!(c(f64::NAN, 64).prepare().is_err());
        assert!(c(f64::INFINITY, 64).prepare().is_err());
        assert!(c(0.1, 1).prepare().is_err());
        assert!(c(0.1, 10_000_000).prepare().is_err());
    }
}
