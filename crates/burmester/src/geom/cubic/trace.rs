//! Tracing a cubic through the pencil of lines at one of its points (see
//! the docs of [`crate::geom::cubic`]).

use core::f64::consts::PI;
use core::sync::atomic::{AtomicBool, Ordering};

use nalgebra::{Point2, Vector2};

use super::Cubic;
use super::roots::{form_eval, form_mul, form_roots, form_sub, real_roots, roots_in};
use crate::geom::{Conic, LocalFrame, Viewport};

/// The traced curve: every real component of the cubic, with its
/// polylines inside the viewport.
#[derive(Debug, Clone, PartialEq)]
pub struct CubicTrace {
    /// The real components of the curve (in view or not; a component out of
    /// view has no polylines). A non-singular cubic has one or two.
    pub components: Vec<CubicComponent>,
    /// The chord tolerance that was used, in the units of the plane.
    pub tolerance: f64,
}

impl CubicTrace {
    /// How many components have a part in view.
    pub fn in_view(&self) -> usize {
        self.components
            .iter()
            .filter(|c| !c.polylines.is_empty())
            .count()
    }

    /// Every polyline of every component.
    pub fn polylines(&self) -> Vec<Vec<Point2<f64>>> {
        self.components
            .iter()
            .flat_map(|c| c.polylines.iter().cloned())
            .collect()
    }
}

/// One real component of a cubic (a closed loop of the projective curve).
#[derive(Debug, Clone, PartialEq)]
pub struct CubicComponent {
    /// Its pieces inside the viewport, each from edge to edge (or one
    /// closed polyline, last point equal to the first, when the whole
    /// component is in view).
    pub polylines: Vec<Vec<Point2<f64>>>,
    /// Whether it stays finite (an oval); `false` for a branch that runs to
    /// infinity.
    pub bounded: bool,
    /// Whether it lies wholly inside the viewport (then it is bounded and
    /// has one closed polyline).
    pub closed: bool,
}

/// Which root of the pencil's quadratic.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Sheet {
    Plus,
    Minus,
}

/// The pencil of lines through a point `q` of the curve (local frame).
struct Pencil<'a> {
    cubic: &'a Cubic,
    q: Vector2<f64>,
    alpha: [f64; 4],
    beta: [f64; 3],
    gamma: [f64; 2],
    /// The direction (angle) of the tangent at `q`.
    tangent: f64,
}

impl Pencil<'_> {
    fn coefficients(&self, s: f64) -> (Vector2<f64>, f64, f64, f64) {
        let (sn, cs) = s.sin_cos();
        let a = form_eval(&self.alpha, cs, sn);
        let b = form_eval(&self.beta, cs, sn);
        let g = form_eval(&self.gamma, cs, sn);
        (Vector2::new(cs, sn), a, b, g)
    }

    fn delta(&self, s: f64) -> f64 {
        let (_, a, b, g) = self.coefficients(s);
        b * b - 4.0 * a * g
    }

    /// `(t+, t-)` along the direction `s`; `tangent` forces the double root
    /// (a loop's turning point, where `Delta = 0`).
    fn roots(&self, s: f64, tangent: bool) -> (Vector2<f64>, f64, f64) {
        let (w, a, b, g) = self.coefficients(s);
        if tangent {
            let t0 = if 2.0 * a.abs() >= b.abs() {
                -b / (2.0 * a)
            } else {
                -2.0 * g / b
            };
            return (w, t0, t0);
        }
        let sq = (b * b - 4.0 * a * g).max(0.0).sqrt();
        if b >= 0.0 {
            let q = -0.5 * (b + sq);
            if q == 0.0 {
                let t = if g == 0.0 { 0.0 } else { f64::INFINITY };
                return (w, t, t);
            }
            (w, g / q, q / a)
        } else {
            let q = 0.5 * (sq - b);
            (w, q / a, g / q)
        }
    }

    /// The point of the curve on `sheet` along `s` (local), after one
    /// Newton step onto the curve; `None` at infinity.
    fn point(&self, s: f64, sheet: Sheet, tangent: bool, tol: f64) -> Option<Vector2<f64>> {
        let (w, tp, tm) = self.roots(s, tangent);
        let t = match sheet {
            Sheet::Plus => tp,
            Sheet::Minus => tm,
        };
        let p = self.q + w * t;
        if !(p.x.is_finite() && p.y.is_finite()) {
            return None;
        }
        Some(polish(self.cubic, p, tol))
    }
}

/// One Newton step of `p` onto the curve along the gradient, kept only when
/// it is a small correction (a thousandth of the chord tolerance) that
/// lowers `|f|`: next to a singular point the gradient is at rounding level
/// too, and a step from a point already on the curve to rounding could
/// throw it off (a proptest found one thrown 4e-6 off a near tacnode).
fn polish(cubic: &Cubic, p: Vector2<f64>, tol: f64) -> Vector2<f64> {
    let f = cubic.eval_local(p);
    let g = cubic.grad_local(p);
    let g2 = g.norm_squared();
    if f == 0.0 || !(g2 > 0.0) {
        return p;
    }
    let step = g * (f / g2);
    if !(step.norm() <= 1e-3 * tol && step.iter().all(|v| v.is_finite())) {
        return p;
    }
    let q = p - step;
    if cubic.eval_local(q).abs() < f.abs() {
        q
    } else {
        p
    }
}

/// A loop of the projective curve, by the pencil's parameter.
#[derive(Debug, Clone, Copy)]
enum Kind {
    /// `Delta > 0` for every direction: one root, `s` over half a turn
    /// (`lambda` in `[0, 1)`, `s = pi lambda`).
    Full(Sheet),
    /// `Delta >= 0` on `[a, b]`: the `+` root from `a` to `b`
    /// (`lambda` in `[0, 1]`), then the `-` root back (`lambda` in `[1, 2]`),
    /// with `s = a + (b - a) (1 - cos(pi u)) / 2` so that the turning points
    /// are smooth in `lambda`.
    Interval { a: f64, b: f64 },
}

#[derive(Debug, Clone, Copy)]
struct Loop {
    kind: Kind,
    bounded: bool,
}

impl Loop {
    fn period(&self) -> f64 {
        match self.kind {
            Kind::Full(_) => 1.0,
            Kind::Interval { .. } => 2.0,
        }
    }

    /// `(s, sheet, tangent)` at `lambda`.
    fn at(&self, lambda: f64) -> (f64, Sheet, bool) {
        match self.kind {
            Kind::Full(sheet) => (PI * lambda.rem_euclid(1.0), sheet, false),
            Kind::Interval { a, b } => {
                let l = lambda.rem_euclid(2.0);
                let (u, sheet) = if l <= 1.0 {
                    (l, Sheet::Plus)
                } else {
                    (2.0 - l, Sheet::Minus)
                };
                let s = a + (b - a) * 0.5 * (1.0 - (PI * u).cos());
                (s, sheet, u == 0.0 || u == 1.0)
            }
        }
    }

    /// `lambda` of the direction `s` (any angle) on `sheet`, if this loop
    /// covers it.
    fn lambda_of(&self, s: f64, sheet: Sheet) -> Option<f64> {
        match self.kind {
            Kind::Full(k) => (k == sheet).then(|| s.rem_euclid(PI) / PI),
            Kind::Interval { a, b } => {
                let lifted = a + (s - a).rem_euclid(PI);
                if lifted > b {
                    return None;
                }
                let u = (1.0 - 2.0 * (lifted - a) / (b - a)).clamp(-1.0, 1.0).acos() / PI;
                Some(match sheet {
                    Sheet::Plus => u,
                    Sheet::Minus => 2.0 - u,
                })
            }
        }
    }
}

/// The most vertices one trace places by refinement (beyond the initial
/// samples): a bound on the work for any input.
const MAX_VERTICES: usize = 1 << 20;

/// A trace with a cancel flag reads it every this many vertices placed or
/// settled (a power of two; a few milliseconds of work at most).
const CANCEL_POLL: usize = 4096;

/// Whether `cancel` is set.
fn cancelled(cancel: Option<&AtomicBool>) -> bool {
    cancel.is_some_and(|c| c.load(Ordering::Relaxed))
}

/// The local viewport and the sampling parameters.
struct View<'c> {
    lo: Vector2<f64>,
    hi: Vector2<f64>,
    radius: f64,
    tol: f64,
    /// How far a point may lie beyond the viewport and count as in it: the
    /// chord tolerance, or 16 ulps of the viewport's coordinates if more
    /// (a view far from the curve's frame).
    margin: f64,
    max_chord: f64,
    /// Vertices left to place (a bound on the work, whatever the input).
    budget: core::cell::Cell<usize>,
    /// A cancel flag, read every [`CANCEL_POLL`] vertices placed: once it
    /// is set the budget is spent (the trace ends at once, unrefined).
    cancel: Option<&'c AtomicBool>,
}

impl View<'_> {
    fn inside(&self, p: Vector2<f64>) -> bool {
        p.x >= self.lo.x && p.x <= self.hi.x && p.y >= self.lo.y && p.y <= self.hi.y
    }

    /// The sides of the viewport that `p` lies beyond by more than the
    /// margin, one bit each (left, right, below, above); `0` for
    /// a point in view or within the tolerance of it.
    fn beyond(&self, p: Vector2<f64>) -> u8 {
        let m = self.margin;
        u8::from(p.x < self.lo.x - m)
            | u8::from(p.x > self.hi.x + m) << 1
            | u8::from(p.y < self.lo.y - m) << 2
            | u8::from(p.y > self.hi.y + m) << 3
    }
}

/// A vertex of a marked trace (local): the point, and the index of the
/// mark it is (`None` for a vertex of the sampling or an edge crossing).
type Marked = (Vector2<f64>, Option<usize>);

pub(super) fn trace(cubic: &Cubic, viewport: &Viewport, tol: f64) -> CubicTrace {
    let (mut trace, _) = trace_impl(cubic, viewport, tol, &[], None);
    let reach = SETTLE_REACH * trace.tolerance;
    for c in &mut trace.components {
        for l in &mut c.polylines {
            let points = l.iter().map(|p| (*p, None));
            let settled = settle_polyline(cubic, points, viewport, reach, true, None);
            *l = settled.into_iter().map(|(p, _)| p).collect();
        }
        c.polylines.retain(|l| l.len() >= 2);
    }
    trace
}

/// The most a traced vertex moves when it is settled onto the curve, in
/// chord tolerances: the drawing stays within the tolerance of the curve.
const SETTLE_REACH: f64 = 0.1;

/// A polyline's vertices settled onto the curve ([`settle`]); marks stay
/// as given. An inner vertex that no Newton correction within `reach`
/// brings onto the curve (along the gradient, or across the polyline) is
/// left out: its neighbours' chord stands for the curve there. That happens
/// where the curve is traced as a line and a conic that its coefficients
/// give only to `1e-9`: at their crossing the cubic's two branches pass
/// each other a little apart and the conic's vertex lies in the gap (the
/// exact curve `1.6e-3` away in a task of `7.7`, within the chord
/// tolerance but beyond the curve's rounding there: `open_curves.py`).
/// An edge end that does not settle along its edge is kept, or with `near`
/// moved to the curve's nearest point within `reach` where there is one
/// (off the edge, inside the view). The relaxed factored trace's test
/// (`trace_impl`) asks its ends to settle along their edges (`near`
/// false): its line's end that does not is not the curve's crossing there.
fn settle_polyline(
    cubic: &Cubic,
    line: impl Iterator<Item = (Point2<f64>, Option<usize>)>,
    viewport: &Viewport,
    reach: f64,
    near: bool,
    cancel: Option<&AtomicBool>,
) -> Vec<(Point2<f64>, Option<usize>)> {
    let mut line: Vec<(Point2<f64>, Option<usize>)> = line.collect();
    // A closed polyline (last point the first) is a cycle: every vertex is
    // an inner one, and it is closed again after.
    let closed = line.len() > 3 && line[0] == line[line.len() - 1];
    if closed {
        line.pop();
    }
    let n = line.len();
    let mut out = Vec::with_capacity(n + 1);
    for (i, &(p, mark)) in line.iter().enumerate() {
        // Cancelled: the rest unsettled (the caller answers `Cancelled`).
        if i % CANCEL_POLL == CANCEL_POLL - 1 && cancelled(cancel) {
            out.extend_from_slice(&line[i..]);
            return out;
        }
        if mark.is_some() {
            out.push((p, mark));
            continue;
        }
        let inner = closed || (i > 0 && i + 1 < n);
        // A crossing found in the local frame comes back to the plane an
        // ulp or two off the view's edge (outside it, or inside but no
        // longer on the edge for the settling): an end that close is put
        // on the edge.
        let p = if inner { p } else { onto_edge(p, viewport) };
        // An end off the viewport's edges (where a vertex beyond the view
        // was left out, `sample`) is settled as an inner vertex is, across
        // its one chord.
        let (on_x_edge, on_y_edge) = on_edges(p, viewport);
        let free_end = !inner && !on_x_edge && !on_y_edge && n >= 2;
        let across = if inner {
            let chord = line[(i + 1) % n].0 - line[(i + n - 1) % n].0;
            Some(Vector2::new(-chord.y, chord.x))
        } else if free_end {
            let chord = line[if i == 0 { 1 } else { n - 2 }].0 - p;
            Some(Vector2::new(-chord.y, chord.x))
        } else {
            None
        };
        match settle(cubic, p, viewport, reach, across) {
            Some(q) => out.push((q, None)),
            // An edge end that does not settle along its edge: with `near`,
            // the nearest point of the curve within `reach` in the viewport
            // ([`settle_near`]); else (or if there is none) the end as it is.
            None if !inner && !free_end => {
                let q = near.then(|| settle_near(cubic, p, viewport, reach));
                out.push((q.flatten().unwrap_or(p), None));
            }
            None => {}
        }
    }
    if closed && !out.is_empty() {
        out.push(out[0]);
    }
    out
}

/// Whether `p` lies exactly on a horizontal edge of the viewport (`y` an
/// edge's) and on a vertical one (`x` an edge's).
fn on_edges(p: Point2<f64>, viewport: &Viewport) -> (bool, bool) {
    (
        p.y == viewport.ymin || p.y == viewport.ymax,
        p.x == viewport.xmin || p.x == viewport.xmax,
    )
}

/// `p` with a coordinate within 16 ulps (of the view's extent and place)
/// of an edge of the viewport put on that edge.
fn onto_edge(p: Point2<f64>, viewport: &Viewport) -> Point2<f64> {
    let snap = |v: f64, lo: f64, hi: f64| {
        let near = 16.0 * f64::EPSILON * lo.abs().max(hi.abs()).max(hi - lo);
        if (v - lo).abs() <= near {
            lo
        } else if (v - hi).abs() <= near {
            hi
        } else {
            v
        }
    };
    Point2::new(
        snap(p.x, viewport.xmin, viewport.xmax),
        snap(p.y, viewport.ymin, viewport.ymax),
    )
}

/// A traced vertex settled onto the curve: Newton steps on the curve's own
/// value (in its local frame), each kept only while it lowers `|f|` and
/// the vertex stays within `reach` (plane units) of where it was and
/// inside the viewport, as in [`Cubic::refine_on_line`]. A vertex on an
/// edge of the viewport moves along that edge (a crossing stays one);
/// elsewhere along the gradient, or else along `across` (the normal of the
/// polyline there). `None` when the vertex ends off the curve (beyond the
/// rounding of its value). The sampler's points are roots of the pencil's
/// quadratic through a point that may lie far from them (a view thousands
/// of task sizes wide), and a curve traced as a line and a conic is that
/// product only to `1e-9` of its coefficients: both leave vertices well
/// within the chord tolerance but farther from the curve than its
/// rounding, which the four-pose maps refuse as off the curve (issue 24,
/// class A; `fuzz/reference/open_curves.py` measures them against the exact
/// curves).
fn settle(
    cubic: &Cubic,
    p: Point2<f64>,
    viewport: &Viewport,
    reach: f64,
    across: Option<Vector2<f64>>,
) -> Option<Point2<f64>> {
    let v = cubic.local_of(p);
    // Far points (evaluated scaled) and degenerate reaches are left as
    // they are: no claim either way.
    if !(v.iter().all(|c| c.is_finite())
        && cubic.eval_local(v).is_finite()
        && reach.is_finite()
        && reach > 0.0)
    {
        return Some(p);
    }
    if cubic.is_zero_local(v) {
        return Some(p);
    }
    let (on_x_edge, on_y_edge) = on_edges(p, viewport);
    if on_x_edge || on_y_edge {
        if on_x_edge && on_y_edge {
            return Some(p);
        }
        // Along the edge: the other coordinate stays the edge's, exactly.
        let d = if on_x_edge {
            Vector2::new(1.0, 0.0)
        } else {
            Vector2::new(0.0, 1.0)
        };
        let t = cubic.refine_on_line(v, d, 0.0);
        let mut q = cubic.global_of(v + d * t);
        if on_x_edge {
            q.y = p.y;
        } else {
            q.x = p.x;
        }
        let closer = cubic.evaluate(q).abs() < cubic.evaluate(p).abs();
        let q = if closer && viewport.contains(q) && (q - p).norm() <= reach {
            q
        } else {
            p
        };
        // On the edge the vertex is a point of the plane (one coordinate
        // fixed, the other rounded to a double): its value is zero only
        // within what that rounding moves it, which in a task hundreds of
        // its sizes from the view can be far more than the rounding of
        // the evaluation (issue 24, class A: `open_curves.py` puts such
        // crossings 1.0 to 1.8 on-curve tolerances off the exact curve,
        // where the curve moves by less than that when the task moves by
        // an ulp; the crossing refined along the edge is on it to its
        // coordinates' rounding, but was refused here and the crossing
        // kept unsettled).
        return on_curve_in_plane(cubic, q).then_some(q);
    }
    let reach_local = reach / cubic.scale;
    let mut x = v;
    let mut f = cubic.eval_local(v);
    for _ in 0..Cubic::REFINE_STEPS {
        if f == 0.0 {
            break;
        }
        let g = cubic.grad_local(x);
        let g2 = g.norm_squared();
        if !(g2 > 0.0) {
            break;
        }
        let y = x - g * (f / g2);
        if !(y.iter().all(|c| c.is_finite()) && (y - v).norm() <= reach_local) {
            break;
        }
        let fy = cubic.eval_local(y);
        if !(fy.abs() < f.abs() && viewport.contains(cubic.global_of(y))) {
            break;
        }
        (x, f) = (y, fy);
    }
    if cubic.is_zero_local(x) {
        return Some(cubic.global_of(x));
    }
    let d = across.filter(|d| d.norm() > 0.0)?;
    let d = d / d.norm();
    let t = cubic.refine_on_line(v, d, 0.0);
    let y = v + d * t;
    let q = cubic.global_of(y);
    (t.abs() <= reach_local && viewport.contains(q) && cubic.is_zero_local(y)).then_some(q)
}

/// The curve's nearest point to `p` within `reach` (plane units) and in
/// the viewport, on the curve as [`on_curve_in_plane`] asks, along eight
/// lines through `p` (none of them parallel to an axis); `None` if there is
/// none. For an edge end of the trace that does not settle along its edge:
/// the crossing of a line and a quotient conic (`trace_factored`) drawn on
/// the edge, where the curve is that product only to `1e-9` of its
/// coefficients. There the product's node is a saddle of the curve's
/// value (its gradient nearly zero) between two branches a little apart,
/// the edge may be one of the product's lines (no crossing of the curve
/// along it), and the node is off the curve by far more than its rounding
/// (issue 24, curv42: a center-point curve of poses at angles `0` and `pi`
/// `1e19` to `1e23` from the origin, the node `3.2e15` from the exact
/// curve against an on-curve tolerance of `1.3e14`, `open_curves.py`). Every
/// line through the node that is not along a branch meets the branches
/// within a few times their distance from it.
fn settle_near(
    cubic: &Cubic,
    p: Point2<f64>,
    viewport: &Viewport,
    reach: f64,
) -> Option<Point2<f64>> {
    let v = cubic.local_of(p);
    let reach_local = reach / cubic.scale;
    if !(v.iter().all(|c| c.is_finite()) && reach_local.is_finite() && reach_local > 0.0) {
        return None;
    }
    let mut best: Option<(f64, Point2<f64>)> = None;
    for k in 0..8 {
        let ang = (f64::from(k) + 0.5) * PI / 8.0;
        let w = Vector2::new(ang.cos(), ang.sin()) * reach_local;
        for u in real_roots(&cubic.restriction_local(v, w)) {
            if !(u.abs() <= 1.0) {
                continue;
            }
            let u = cubic.refine_on_line(v, w, u);
            if !(u.abs() <= 1.0) {
                continue;
            }
            let q = cubic.global_of(v + w * u);
            if !(viewport.contains(q) && on_curve_in_plane(cubic, q)) {
                continue;
            }
            let d = (q - p).norm();
            if best.is_none_or(|(b, _)| d < b) {
                best = Some((d, q));
            }
        }
    }
    best.map(|(_, q)| q)
}

/// Whether the plane point `p` is on the curve as well as a point of the
/// plane can be: its value (local) within the rounding of its evaluation
/// (`64 eps` of its terms, as [`Cubic::is_zero_local`]) plus what the
/// rounding of its coordinates and of the frame's origin moves it (`64 eps`
/// of their sizes, the rule of the four-pose curves' on-curve test).
fn on_curve_in_plane(cubic: &Cubic, p: Point2<f64>) -> bool {
    let v = cubic.local_of(p);
    if !v.iter().all(|x| x.is_finite()) {
        return false;
    }
    let shift = (p.coords.norm() + cubic.origin.coords.norm()) / cubic.scale;
    let bound = cubic.magnitude_local(v) + cubic.grad_local(v).norm() * shift;
    cubic.eval_local(v).abs() <= 64.0 * f64::EPSILON * bound
}

/// The polylines of [`trace`] with given points of the curve made
/// vertices: each mark inside the viewport is placed on its loop by the
/// pencil's parameter (as an edge crossing is) and the loop is sampled from
/// knot to knot, so the mark is a vertex, exactly, between the curve's own
/// points on either side of it. Every vertex comes with the index of the
/// mark it is. A mark that cannot be placed on a loop (a singular point,
/// a curve traced as a line and a conic) is inserted into the nearest
/// chord within the chord tolerance, if any.
///
/// # Errors
///
/// [`crate::Error::Cancelled`] (`0` of `0`: no vertex is given) when
/// `cancel` is set during the trace, read every [`CANCEL_POLL`] vertices.
pub(super) fn trace_marked(
    cubic: &Cubic,
    viewport: &Viewport,
    tol: f64,
    marks: &[Point2<f64>],
    cancel: Option<&AtomicBool>,
) -> crate::error::Result<Vec<super::MarkedPolyline>> {
    let stop = || crate::Error::Cancelled { done: 0, total: 0 };
    let local: Vec<Vector2<f64>> = marks.iter().map(|m| cubic.local_of(*m)).collect();
    let (trace, marked) = trace_impl(cubic, viewport, tol, &local, cancel);
    if cancelled(cancel) {
        return Err(stop());
    }
    let reach = SETTLE_REACH * trace.tolerance;
    let mut out: Vec<Vec<(Point2<f64>, Option<usize>)>> = match marked {
        Some(lines) => lines
            .into_iter()
            .map(|l| {
                l.into_iter()
                    .map(|(v, m)| match m {
                        Some(k) => (marks[k], Some(k)),
                        None => (cubic.global_of(v), None),
                    })
                    .collect()
            })
            .collect(),
        None => trace
            .polylines()
            .into_iter()
            .map(|l| l.into_iter().map(|p| (p, None)).collect())
            .collect(),
    };
    // Marks not placed on a loop: into the nearest chord.
    let placed: Vec<bool> = (0..marks.len())
        .map(|k| out.iter().flatten().any(|(_, m)| *m == Some(k)))
        .collect();
    let inside = |p: &Point2<f64>| {
        p.x >= viewport.xmin && p.x <= viewport.xmax && p.y >= viewport.ymin && p.y <= viewport.ymax
    };
    for (k, m) in marks.iter().enumerate() {
        if placed[k] || !inside(m) || !(m.x.is_finite() && m.y.is_finite()) {
            continue;
        }
        let mut best: Option<(f64, usize, usize)> = None;
        for (li, l) in out.iter().enumerate() {
            for (i, w) in l.windows(2).enumerate() {
                let (a, b) = (w[0].0, w[1].0);
                let ab = b - a;
                let u =
                    ((m - a).dot(&ab) / ab.norm_squared().max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
                let d = (a + ab * u - m).norm();
                if best.is_none_or(|(bd, ..)| d < bd) {
                    best = Some((d, li, i));
                }
            }
        }
        if let Some((d, li, i)) = best {
            if d <= trace.tolerance {
                out[li].insert(i + 1, (*m, Some(k)));
            }
        }
    }
    let out: Vec<_> = out
        .into_iter()
        .map(|l| settle_polyline(cubic, l.into_iter(), viewport, reach, true, cancel))
        .filter(|l| l.len() >= 2)
        .collect();
    if cancelled(cancel) {
        return Err(stop());
    }
    Ok(out)
}

/// [`trace`], and with marks the polylines with the marks as vertices
/// (`None` when the curve was traced as a line and a conic).
#[allow(clippy::type_complexity)]
fn trace_impl(
    cubic: &Cubic,
    viewport: &Viewport,
    tol: f64,
    marks: &[Vector2<f64>],
    cancel: Option<&AtomicBool>,
) -> (CubicTrace, Option<Vec<Vec<Marked>>>) {
    let empty = CubicTrace {
        components: Vec::new(),
        tolerance: tol,
    };
    let empty = (empty, None);
    let lo = cubic.local_of(Point2::new(viewport.xmin, viewport.ymin));
    let hi = cubic.local_of(Point2::new(viewport.xmax, viewport.ymax));
    let finite = lo.iter().chain(hi.iter()).all(|v| v.is_finite());
    if !(finite && hi.x > lo.x && hi.y > lo.y) {
        return empty;
    }
    let center = (lo + hi) * 0.5;
    let radius = 0.5 * (hi - lo).norm();
    if !(radius > 0.0 && radius.is_finite()) {
        return empty;
    }
    // Never below a ten-billionth of the diagonal (rounding).
    let tol = (tol / cubic.scale).max(2e-10 * radius);
    let far = lo.amax().max(hi.amax());
    let view = View {
        lo,
        hi,
        radius,
        tol,
        margin: tol.max(16.0 * f64::EPSILON * far),
        max_chord: 0.1 * radius,
        budget: core::cell::Cell::new(MAX_VERTICES),
        cancel,
    };
    let Some(q) = choose_point(cubic, center, radius) else {
        return empty;
    };
    if tangent_is_component(cubic, q, radius) {
        if let Some(t) = trace_factored(cubic, q, viewport, &view, false) {
            return (t, None);
        }
    }
    let pencil_at = |q: Vector2<f64>| {
        let g = cubic.grad_local(q);
        let h = cubic.hessian_local(q);
        Pencil {
            cubic,
            q,
            alpha: cubic.cubic_form(),
            beta: [0.5 * h[0], h[1], 0.5 * h[2]],
            gamma: [g.x, g.y],
            tangent: (g.x.atan2(-g.y)).rem_euclid(PI),
        }
    };
    let crossings = edge_crossings(cubic, &view);
    // Each crossing on its loop, and whether one is on no loop.
    let place_all = |pencil: &Pencil<'_>, loops: &[Loop]| {
        let mut on_loop: Vec<Vec<(f64, Vector2<f64>)>> = vec![Vec::new(); loops.len()];
        let mut unplaced = false;
        for &x in &crossings {
            if let Some((k, lambda)) = place(pencil, loops, x, &view) {
                on_loop[k].push((lambda, x));
            } else {
                unplaced = true;
            }
        }
        (on_loop, unplaced)
    };
    let mut pencil = pencil_at(q);
    let mut loops = loops(&pencil);
    let (mut on_loop, unplaced) = place_all(&pencil, &loops);
    // A crossing on no loop: the pencil's point may lie on a piece of the
    // curve that is a line within the chord tolerance across the view.
    // Every direction from it that holds that piece is then within
    // rounding of its tangent, where `Delta` is rounding and its loops are
    // noise, and the trace would fold back along the piece (issue 24, class
    // B: loops `2e-7` to `5e-3` rad wide, `Delta` `1e-19` over coefficients
    // of `1e-4`). Such a curve is traced as its tangent line and the
    // quotient conic where that product is the curve within the settling's
    // reach across the view, and only where every vertex of it settles onto
    // the curve (a fuzz round found pure-translation tasks whose line or
    // conic left vertices the maps refuse).
    if unplaced {
        if let Some(t) = trace_factored(cubic, q, viewport, &view, true) {
            let reach = SETTLE_REACH * t.tolerance;
            let settles = t.components.iter().flat_map(|c| &c.polylines).all(|l| {
                let points = l.iter().map(|p| (*p, None));
                let s = settle_polyline(cubic, points, viewport, reach, false, None);
                s.len() == l.len() && s.iter().all(|(p, _)| on_curve_in_plane(cubic, *p))
            });
            if settles {
                return (t, None);
            }
        }
        // Else the crossing would be dropped and the trace would run from
        // the last placed one around its loop and back across the view
        // (fuzz input `401a552c`: a nearly straight branch `5.8e7` long, its
        // left edge crossing dropped, the trace's last chord `1.3e6` long
        // back across a loop `1.5e4` across with defective stretches): the
        // pencil is taken about another regular point of the curve (off
        // that piece: about the frame's origin too), the first on which
        // every crossing is placed; where there is none, as before.
        let others = [center, Vector2::zeros()]
            .into_iter()
            .flat_map(|base| line_points(cubic, base, radius))
            .filter(|x| *x != q && regular(cubic, *x, radius));
        for x in others {
            let p = pencil_at(x);
            let l = self::loops(&p);
            if let (on, false) = place_all(&p, &l) {
                (pencil, loops, on_loop) = (p, l, on);
                break;
            }
        }
    }
    // Each mark inside the viewport on its loop.
    let mut marks_on: Vec<Vec<(f64, Vector2<f64>, usize)>> = vec![Vec::new(); loops.len()];
    for (k, &x) in marks.iter().enumerate() {
        if x.iter().all(|v| v.is_finite()) && view.inside(x) {
            if let Some((lp, lambda)) = place(&pencil, &loops, x, &view) {
                marks_on[lp].push((lambda, x, k));
            }
        }
    }
    let mut marked_lines: Vec<Vec<Marked>> = Vec::new();
    let mut components = Vec::with_capacity(loops.len() + 1);
    for ((lp, mut cs), mut ms) in loops.iter().zip(on_loop).zip(marks_on) {
        cs.sort_by(|a, b| a.0.total_cmp(&b.0));
        ms.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut polylines = Vec::new();
        let mut closed = false;
        if cs.is_empty() {
            if lp.bounded {
                let (s, sheet, tangent) = lp.at(0.0);
                let (sm, sheet_m, tangent_m) = lp.at(0.5 * lp.period());
                if let (Some(p0), Some(pm)) = (
                    pencil.point(s, sheet, tangent, view.tol),
                    pencil.point(sm, sheet_m, tangent_m, view.tol),
                ) {
                    if view.inside(pm) {
                        if ms.is_empty() {
                            let lines = sample(&pencil, lp, 0.0, lp.period(), p0, p0, &view);
                            marked_lines.extend(untagged(&lines));
                            polylines.extend(lines);
                        } else {
                            // From the first mark around to it again.
                            let mut knots: Vec<(f64, Vector2<f64>, Option<usize>)> =
                                ms.iter().map(|&(l, x, k)| (l, x, Some(k))).collect();
                            let (l0, x0, k0) = ms[0];
                            knots.push((l0 + lp.period(), x0, Some(k0)));
                            let lines = sample_knots(&pencil, lp, &knots, &view);
                            polylines.extend(lines.iter().map(|l| l.iter().map(|v| v.0).collect()));
                            marked_lines.extend(lines);
                        }
                        closed = true;
                    }
                }
            }
        } else {
            let n = cs.len();
            for i in 0..n {
                let (la, xa) = cs[i];
                let (lb, xb) = if i + 1 < n {
                    cs[i + 1]
                } else {
                    (cs[0].0 + lp.period(), cs[0].1)
                };
                if !(lb > la) {
                    continue;
                }
                let (sm, sheet, tangent) = lp.at(0.5 * (la + lb));
                match pencil.point(sm, sheet, tangent, view.tol) {
                    Some(pm) if view.inside(pm) => {
                        // The marks on the way (their parameter lifted into
                        // `(la, lb)`).
                        let mut knots = vec![(la, xa, None)];
                        let mut inner: Vec<(f64, Vector2<f64>, Option<usize>)> = ms
                            .iter()
                            .flat_map(|&(l, x, k)| {
                                [l, l + lp.period()]
                                    .into_iter()
                                    .filter(move |&l| l > la && l < lb)
                                    .map(move |l| (l, x, Some(k)))
                            })
                            .collect();
                        inner.sort_by(|a, b| a.0.total_cmp(&b.0));
                        let plain = inner.is_empty();
                        knots.extend(inner);
                        knots.push((lb, xb, None));
                        if plain {
                            let lines = sample(&pencil, lp, la, lb, xa, xb, &view);
                            marked_lines.extend(untagged(&lines));
                            polylines.extend(lines);
                        } else {
                            let lines = sample_knots(&pencil, lp, &knots, &view);
                            polylines.extend(lines.iter().map(|l| l.iter().map(|v| v.0).collect()));
                            marked_lines.extend(lines);
                        }
                    }
                    _ => {}
                }
            }
        }
        polylines.retain(|l: &Vec<Vector2<f64>>| l.len() >= 2 && l.iter().any(|p| *p != l[0]));
        let closed = closed && polylines.len() == 1;
        components.push(CubicComponent {
            polylines: polylines
                .into_iter()
                .map(|l| l.into_iter().map(|v| cubic.global_of(v)).collect())
                .collect(),
            bounded: lp.bounded,
            closed,
        });
    }
    marked_lines.retain(|l| l.len() >= 2 && l.iter().any(|p| p.0 != l[0].0));
    (
        CubicTrace {
            components,
            tolerance: view.tol * cubic.scale,
        },
        Some(marked_lines),
    )
}

/// Polylines with no marks.
fn untagged(lines: &[Vec<Vector2<f64>>]) -> Vec<Vec<Marked>> {
    lines
        .iter()
        .map(|l| l.iter().map(|&v| (v, None)).collect())
        .collect()
}

/// Samples a loop from knot to knot (parameters increasing; the points
/// given exactly, each with its mark), joined into polylines through the
/// knots: each knot is a vertex, with its mark.
fn sample_knots(
    pencil: &Pencil<'_>,
    lp: &Loop,
    knots: &[(f64, Vector2<f64>, Option<usize>)],
    view: &View,
) -> Vec<Vec<Marked>> {
    let mut out: Vec<Vec<Marked>> = Vec::new();
    let mut current: Vec<Marked> = Vec::new();
    for w in knots.windows(2) {
        let ((la, xa, ta), (lb, xb, tb)) = (w[0], w[1]);
        if !(lb > la) {
            continue;
        }
        let pieces = sample(pencil, lp, la, lb, xa, xb, view);
        let last = pieces.len().saturating_sub(1);
        for (i, piece) in pieces.into_iter().enumerate() {
            let n = piece.len();
            let tagged: Vec<Marked> = piece
                .into_iter()
                .enumerate()
                .map(|(j, v)| {
                    let tag = if i == 0 && j == 0 && v == xa {
                        ta
                    } else if i == last && j + 1 == n && v == xb {
                        tb
                    } else {
                        None
                    };
                    (v, tag)
                })
                .collect();
            let joins = current
                .last()
                .zip(tagged.first())
                .is_some_and(|(a, b)| a.0 == b.0 && a.1.is_some() && a.1 == b.1);
            if joins {
                current.extend(tagged.into_iter().skip(1));
            } else {
                if current.len() >= 2 {
                    out.push(core::mem::take(&mut current));
                }
                current = tagged;
            }
        }
    }
    if current.len() >= 2 {
        out.push(current);
    }
    out
}

/// The curve's crossings of eight lines through `base`, each refined on
/// the curve's own value (the base, the view's center, may be far from the
/// curve, and the pencil's point is a vertex of the trace).
fn line_points(cubic: &Cubic, base: Vector2<f64>, radius: f64) -> Vec<Vector2<f64>> {
    let mut out = Vec::new();
    for k in 0..8 {
        let ang = (k as f64 + 0.3) * PI / 8.0;
        let w = Vector2::new(ang.cos(), ang.sin()) * radius.max(f64::MIN_POSITIVE);
        let coeffs = cubic.restriction_local(base, w);
        for u in real_roots(&coeffs) {
            let u = cubic.refine_on_line(base, w, u);
            let x = base + w * u;
            if x.iter().all(|v| v.is_finite()) {
                out.push(x);
            }
        }
    }
    out
}

/// How regular the curve's point `x` is: its gradient against the scale
/// of the gradient's terms ([`REGULAR`] and above: regular).
fn regularity(cubic: &Cubic, x: Vector2<f64>) -> f64 {
    cubic.grad_local(x).norm() / cubic.grad_magnitude_local(x).max(f64::MIN_POSITIVE)
}

/// The [`regularity`] from which [`choose_point`] takes a point for a
/// regular one.
const REGULAR: f64 = 1e-4;

/// Whether [`choose_point`] takes the curve's point `x` for a regular one
/// off line components (its first choice).
fn regular(cubic: &Cubic, x: Vector2<f64>, radius: f64) -> bool {
    regularity(cubic, x) >= REGULAR && !tangent_is_component(cubic, x, radius)
}

/// A point of the curve near the viewport and away from singular points:
/// the curve's crossings of eight lines through the viewport's center,
/// the nearest among the well-conditioned ones (gradient not small against
/// its terms), avoiding points whose tangent line is a component.
fn choose_point(cubic: &Cubic, center: Vector2<f64>, radius: f64) -> Option<Vector2<f64>> {
    let mut cands = Vec::new();
    for base in [center, Vector2::zeros()] {
        cands.extend(line_points(cubic, base, radius));
        if !cands.is_empty() {
            break;
        }
    }
    let score = |x: &Vector2<f64>| {
        let line = tangent_is_component(cubic, *x, radius);
        (regularity(cubic, *x), line, (x - center).norm())
    };
    let scored: Vec<_> = cands.iter().map(|x| (*x, score(x))).collect();
    let pick = |good: &dyn Fn(&(f64, bool, f64)) -> bool| {
        scored
            .iter()
            .filter(|(_, s)| good(s))
            .min_by(|a, b| a.1.2.total_cmp(&b.1.2))
            .map(|(x, _)| *x)
    };
    // Regular points off line components first, then regular points on a
    // line component (the curve is then divided by it), then the most
    // regular point.
    pick(&|s| s.0 >= REGULAR && !s.1)
        .or_else(|| pick(&|s| s.0 >= REGULAR))
        .or_else(|| {
            scored
                .iter()
                .max_by(|a, b| a.1.0.total_cmp(&b.1.0))
                .map(|(x, _)| *x)
        })
}

/// Whether the tangent line of the curve at its point `x` lies on the curve
/// (a line component): the restriction along it vanishes within rounding.
fn tangent_is_component(cubic: &Cubic, x: Vector2<f64>, radius: f64) -> bool {
    let g = cubic.grad_local(x);
    let n = g.norm();
    if !(n > 0.0) {
        return false;
    }
    let radius = radius.max(f64::MIN_POSITIVE);
    let tau = Vector2::new(-g.y, g.x) / n * radius;
    let r = cubic.restriction_local(x, tau);
    // The scale of the curve's terms over the disc of the viewport's radius
    // around `x`.
    let reach = x.map(|v| v.abs() + radius);
    r[2].abs() + r[3].abs() <= 1e-9 * cubic.magnitude_local(reach)
}

/// A cubic with a line component through `q` (its tangent there):
/// `f = L q2` with `L` the tangent line, traced as the line and the
/// quotient conic (the existing [`crate::Conic`] sampler). `None` when the
/// division leaves a remainder beyond rounding (`1e-9` of the
/// coefficients), or with `in_view`, beyond what moves the curve by
/// [`SETTLE_REACH`] chord tolerances anywhere in the view (the remainder's
/// bound over the view against the gradient at `q`).
fn trace_factored(
    cubic: &Cubic,
    q: Vector2<f64>,
    viewport: &Viewport,
    view: &View,
    in_view: bool,
) -> Option<CubicTrace> {
    let g = cubic.grad_local(q);
    let n = g.norm();
    if !(n > 0.0) {
        return None;
    }
    // L(v) = n . (v - q), unit normal n.
    let nn = g / n;
    let l = [-nn.dot(&q), nn.x, nn.y];
    // The product L q2 as a linear map of q2's coefficients
    // [1, x, y, x^2, xy, y^2] onto the cubic's [1, x, y, x^2, xy, y^2, x^3, x^2y, xy^2, y^3].
    let mut m = nalgebra::DMatrix::<f64>::zeros(10, 6);
    // (monomial of q2, monomial of L) -> monomial of the product.
    const PRODUCT: [[usize; 3]; 6] = [
        [0, 1, 2],
        [1, 3, 4],
        [2, 4, 5],
        [3, 6, 7],
        [4, 7, 8],
        [5, 8, 9],
    ];
    for (col, targets) in PRODUCT.iter().enumerate() {
        for (li, &row) in targets.iter().enumerate() {
            m[(row, col)] += l[li];
        }
    }
    let f = nalgebra::DVector::from_column_slice(&cubic.c);
    let svd = m.clone().svd(true, true);
    let q2 = svd.solve(&f, 1e-14).ok()?;
    let remainder = &m * &q2 - &f;
    let exact = remainder.norm() <= 1e-9 * f.norm();
    if !exact {
        // The remainder's bound over the view (each monomial at the view's
        // largest coordinates) and how far it moves the curve there.
        let xm = view.lo.x.abs().max(view.hi.x.abs());
        let ym = view.lo.y.abs().max(view.hi.y.abs());
        let r: [f64; 10] = core::array::from_fn(|k| remainder[k]);
        let bound = super::magnitude(&r, xm, ym);
        if !(in_view && bound <= SETTLE_REACH * view.tol * n) {
            return None;
        }
    }
    // In the conic's order [A, B, C, D, E, F] (x^2, xy, y^2, x, y, 1).
    // A quotient whose quadratic terms are too small to move it in the
    // view is drawn by the conic sampler as its line `D x + E y + F = 0`
    // (`Conic::polylines`; issue 24, class A: quadratic terms `2e-11` and
    // `3e-16` of the linear ones, taken for a line pair by the conic's
    // matrix, drew a line across the view `165` and `1e6` from the exact
    // curve, `open_curves.py`).
    let qc = [q2[3], q2[4], q2[5], q2[1], q2[2], q2[0]];
    let conic = crate::geom::Conic::local(qc, cubic.origin, cubic.scale, None);
    let tol = view.tol * cubic.scale;
    let mut components = Vec::new();
    // The line, clipped to the viewport.
    let d = Vector2::new(-nn.y, nn.x);
    let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
    let mut inside = true;
    for i in 0..2 {
        if d[i].abs() > 0.0 {
            let a = (view.lo[i] - q[i]) / d[i];
            let b = (view.hi[i] - q[i]) / d[i];
            t0 = t0.max(a.min(b));
            t1 = t1.min(a.max(b));
        } else if q[i] < view.lo[i] || q[i] > view.hi[i] {
            inside = false;
        }
    }
    let line = if inside && t1 > t0 {
        vec![vec![
            cubic.global_of(q + d * t0),
            cubic.global_of(q + d * t1),
        ]]
    } else {
        Vec::new()
    };
    components.push(CubicComponent {
        polylines: line,
        bounded: false,
        closed: false,
    });
    let bounded = conic.kind() == crate::geom::ConicKind::Ellipse;
    // The tolerance is within the conic's accepted range (a fraction of
    // the viewport's diagonal): an error is not expected; draw nothing then.
    let tol = tol.clamp(
        Conic::MIN_RELATIVE_TOLERANCE * viewport.diagonal(),
        viewport.diagonal(),
    );
    for pl in conic.polylines(viewport, Some(tol)).unwrap_or_default() {
        let closed = bounded && pl.len() > 2 && pl[0] == pl[pl.len() - 1];
        components.push(CubicComponent {
            polylines: vec![pl],
            bounded,
            closed,
        });
    }
    Some(CubicTrace {
        components,
        tolerance: tol,
    })
}

/// The loops of the pencil: the intervals of directions where `Delta >= 0`.
fn loops(pencil: &Pencil<'_>) -> Vec<Loop> {
    let delta = form_sub(
        &form_mul(&pencil.beta, &pencil.beta),
        &form_mul(&pencil.alpha, &pencil.gamma.map(|v| 4.0 * v)),
    );
    let droots = form_roots(&delta);
    let aroots = form_roots(&pencil.alpha);
    // Which sheet runs to infinity at each asymptotic direction: at
    // alpha = 0 the finite root is -gamma/beta, the other is infinite.
    let diverging: Vec<(f64, Option<Sheet>)> = aroots
        .iter()
        .map(|&s| {
            let (_, _, b, _) = pencil.coefficients(s);
            let sheet = if b > 0.0 {
                Some(Sheet::Minus)
            } else if b < 0.0 {
                Some(Sheet::Plus)
            } else {
                None
            };
            (s, sheet)
        })
        .collect();
    let mut out = Vec::new();
    if droots.is_empty() {
        if pencil.delta(0.37) > 0.0 {
            for sheet in [Sheet::Plus, Sheet::Minus] {
                let bounded = !diverging.iter().any(|(_, d)| d.is_none_or(|d| d == sheet));
                out.push(Loop {
                    kind: Kind::Full(sheet),
                    bounded,
                });
            }
        }
        return out;
    }
    let m = droots.len();
    for i in 0..m {
        let a = droots[i];
        let b = if i + 1 < m {
            droots[i + 1]
        } else {
            droots[0] + PI
        };
        if !(b > a) {
            continue;
        }
        if pencil.delta(0.5 * (a + b)) > 0.0 {
            let bounded = !aroots.iter().any(|&s| {
                let lifted = a + (s - a).rem_euclid(PI);
                lifted > a && lifted < b
            });
            out.push(Loop {
                kind: Kind::Interval { a, b },
                bounded,
            });
        }
    }
    out
}

/// Where the curve crosses the viewport's edges (local), each edge a cubic
/// in one variable; corners found twice are kept once.
fn edge_crossings(cubic: &Cubic, view: &View) -> Vec<Vector2<f64>> {
    let (lo, hi) = (view.lo, view.hi);
    let mid = (lo + hi) * 0.5;
    let half = (hi - lo) * 0.5;
    let edges = [
        (Vector2::new(mid.x, lo.y), Vector2::new(half.x, 0.0)),
        (Vector2::new(mid.x, hi.y), Vector2::new(half.x, 0.0)),
        (Vector2::new(lo.x, mid.y), Vector2::new(0.0, half.y)),
        (Vector2::new(hi.x, mid.y), Vector2::new(0.0, half.y)),
    ];
    let mut out: Vec<Vector2<f64>> = Vec::new();
    for (m, h) in edges {
        let coeffs = cubic.restriction_local(m, h);
        for u in roots_in(&coeffs, -1.0, 1.0) {
            // Refined on the curve's own value: the restriction's
            // coefficients lose the digits that the edge's place cancels.
            let u = cubic.refine_on_line(m, h, u).clamp(-1.0, 1.0);
            let mut x = m + h * u;
            // Exactly on the edge and inside the viewport.
            x.x = x.x.clamp(lo.x, hi.x);
            x.y = x.y.clamp(lo.y, hi.y);
            if !out.iter().any(|y| (y - x).norm() <= 1e-12 * view.radius) {
                out.push(x);
            }
        }
    }
    out
}

/// The loop and the parameter of a crossing `x`, checked: the loop's point
/// there must be `x` (within a loose relative `1e-6`).
fn place(
    pencil: &Pencil<'_>,
    loops: &[Loop],
    x: Vector2<f64>,
    view: &View,
) -> Option<(usize, f64)> {
    let d = x - pencil.q;
    let r = d.norm();
    let (s, t) = if r <= 1e-12 * view.radius {
        (pencil.tangent, 0.0)
    } else {
        let s = d.y.atan2(d.x).rem_euclid(PI);
        (s, d.dot(&Vector2::new(s.cos(), s.sin())))
    };
    let (_, tp, tm) = pencil.roots(s, false);
    let sheet = if (t - tp).abs() <= (t - tm).abs() {
        Sheet::Plus
    } else {
        Sheet::Minus
    };
    let mut best: Option<(usize, f64)> = None;
    for (k, lp) in loops.iter().enumerate() {
        if let Some(l) = lp.lambda_of(s, sheet) {
            best = Some((k, l));
            break;
        }
    }
    if best.is_none() {
        // A crossing at a turning point can land just outside its interval
        // by rounding: take the nearest end.
        let mut nearest = f64::INFINITY;
        for (k, lp) in loops.iter().enumerate() {
            if let Kind::Interval { a, b } = lp.kind {
                for (end, l) in [(a, 0.0), (b, 1.0)] {
                    let gap = (s - end).rem_euclid(PI).min((end - s).rem_euclid(PI));
                    if gap < nearest {
                        nearest = gap;
                        best = Some((k, l));
                    }
                }
            }
        }
    }
    let (k, l) = best?;
    let (s2, sheet2, tangent) = loops[k].at(l);
    let p = pencil.point(s2, sheet2, tangent, view.tol)?;
    ((p - x).norm() <= 1e-6 * (view.radius + r)).then_some((k, l))
}

/// Samples the loop between `la` and `lb` (the ends given exactly as
/// `xa`, `xb`) adaptively to the chord tolerance: one polyline, or several
/// if a point on the way is not finite.
fn sample(
    pencil: &Pencil<'_>,
    lp: &Loop,
    la: f64,
    lb: f64,
    xa: Vector2<f64>,
    xb: Vector2<f64>,
    view: &View,
) -> Vec<Vec<Vector2<f64>>> {
    const INITIAL: usize = 32;
    let point = |l: f64| {
        let (s, sheet, tangent) = lp.at(l);
        pencil.point(s, sheet, tangent, view.tol)
    };
    let mut out = Vec::new();
    let mut current = vec![xa];
    let mut prev = (la, Some(xa));
    for i in 1..=INITIAL {
        let l = la + (lb - la) * (i as f64 / INITIAL as f64);
        let p = if i == INITIAL { Some(xb) } else { point(l) };
        refine(&point, prev, (l, p), 0, view, &mut current, &mut out);
        prev = (l, p);
    }
    if current.len() >= 2 {
        out.push(current);
    }
    // The piece sampled lies between two edge crossings with its middle in
    // view, so in view: a vertex beyond the viewport (by more than the
    // margin) is not the piece's (a sheet's root taken far out, where
    // the pencil's quadratic is ill-conditioned, or a crossing missed) and
    // is left out, the polyline split there (issue 24, class A: such a
    // vertex millions of view sizes out, not on the curve to its rounding).
    if out.iter().flatten().any(|&p| view.beyond(p) != 0) {
        out = out
            .into_iter()
            .flat_map(|l| {
                l.split(|&p| view.beyond(p) != 0)
                    .filter(|l| l.len() >= 2)
                    .map(<[_]>::to_vec)
                    .collect::<Vec<_>>()
            })
            .collect();
    }
    out
}

/// Appends the polyline from `a` to `b` (parameters and points), refined
/// until the middle point is within the tolerance of the chord and the
/// chord is short; a point at infinity splits the polyline.
#[allow(clippy::type_complexity)]
fn refine(
    point: &impl Fn(f64) -> Option<Vector2<f64>>,
    a: (f64, Option<Vector2<f64>>),
    b: (f64, Option<Vector2<f64>>),
    depth: u32,
    view: &View,
    current: &mut Vec<Vector2<f64>>,
    out: &mut Vec<Vec<Vector2<f64>>>,
) {
    const MAX_DEPTH: u32 = 48;
    let (la, pa) = a;
    let (lb, pb) = b;
    let lm = 0.5 * (la + lb);
    let pm = point(lm);
    let split = match (pa, pm, pb) {
        (Some(pa), Some(pm), Some(pb)) => {
            let chord = pb - pa;
            let len = chord.norm();
            let dev = if len > 0.0 {
                ((pm - pa).x * chord.y - (pm - pa).y * chord.x).abs() / len
            } else {
                (pm - pa).norm()
            };
            // A chord whose ends and middle all lie beyond one side of the
            // viewport is not refined: its vertices are left out (`sample`),
            // and refining it could spend the whole budget far out, where
            // the coordinates' rounding exceeds the tolerance (issue 24: a
            // conic with a cubic term `1.5e-15` of its largest coefficient
            // closes into an oval `1e15` view sizes across, which took all
            // 1,048,576 vertices, none in view).
            (dev > view.tol || len > view.max_chord)
                && view.beyond(pa) & view.beyond(pm) & view.beyond(pb) == 0
        }
        _ => true,
    };
    let mut budget = view.budget.get();
    if budget % CANCEL_POLL == 0 && budget > 0 && cancelled(view.cancel) {
        budget = 0;
        view.budget.set(0);
    }
    if split && depth < MAX_DEPTH && lm > la && lm < lb && budget > 0 {
        view.budget.set(budget - 1);
        refine(point, a, (lm, pm), depth + 1, view, current, out);
        refine(point, (lm, pm), b, depth + 1, view, current, out);
        return;
    }
    match (pa, pb) {
        (Some(_), Some(pb)) if !(split && depth >= MAX_DEPTH && pm.is_none()) => {
            current.push(pb);
        }
        (_, Some(pb)) => {
            if current.len() >= 2 {
                out.push(core::mem::take(current));
            }
            current.clear();
            current.push(pb);
        }
        (_, None) => {
            if current.len() >= 2 {
                out.push(core::mem::take(current));
            }
            current.clear();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A long trace for a legitimate reason: `x (x^2 + y^2 - 1)` (a line
    /// and a circle) in a view just around the circle, at the finest
    /// tolerance a trace takes (`2e-10` of the view's half-diagonal): about
    /// 170,000 vertices, most of a second in a debug build. (The input
    /// before, a conic with cubic terms of rounding, `4e-16`, reached the
    /// whole budget only through the tracer's defect of
    /// [`a_conic_with_a_tiny_cubic_term_is_traced_in_its_view`]: 33
    /// vertices since.)
    fn slow_cubic() -> (Cubic, Viewport) {
        let cubic = Cubic::new([0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0]).unwrap();
        (cubic, vp(1.1))
    }

    /// A long trace stops on its cancel flag: set before the call, at
    /// once; set 20 ms into it (1 ms in release), within a fraction of a
    /// second, `Cancelled` with no vertex given. The whole trace is
    /// measured too: over 100,000 vertices, so that the flag lands inside
    /// it.
    #[test]
    fn a_long_trace_stops_when_cancelled() {
        use std::time::{Duration, Instant};
        let (cubic, view) = slow_cubic();
        let tol = 1e-300;
        let set = AtomicBool::new(true);
        let t0 = Instant::now();
        let r = trace_marked(&cubic, &view, tol, &[], Some(&set));
        assert!(
            matches!(r, Err(crate::Error::Cancelled { done: 0, total: 0 })),
            "{r:?}"
        );
        assert!(
            t0.elapsed() < Duration::from_millis(500),
            "{:?}",
            t0.elapsed()
        );
        let after = Duration::from_millis(if cfg!(debug_assertions) { 20 } else { 1 });
        let stop = AtomicBool::new(false);
        let (r, at, back) = std::thread::scope(|s| {
            let setter = s.spawn(|| {
                std::thread::sleep(after);
                stop.store(true, Ordering::Relaxed);
                Instant::now()
            });
            let r = trace_marked(&cubic, &view, tol, &[], Some(&stop));
            (r, setter.join().unwrap(), Instant::now())
        });
        assert!(
            matches!(r, Err(crate::Error::Cancelled { done: 0, total: 0 })),
            "{r:?}"
        );
        let latency = back.saturating_duration_since(at);
        assert!(latency < Duration::from_millis(500), "{latency:?}");
        let n: usize = trace_marked(&cubic, &view, tol, &[], None)
            .unwrap()
            .iter()
            .map(Vec::len)
            .sum();
        assert!(n > 100_000, "{n} vertices: not a long trace");
    }

    /// Issue 24 (trace38): the center-point cubic of `fuzz/regressions/
    /// curves/trace-spent-its-budget-far-outside-the-view-30957a36` (its
    /// local coefficients, origin and scale), a rectangular hyperbola plus
    /// a circular cubic term `3.1e-16` (the exact curve's; `1.5e-15` of the
    /// largest coefficient), and the fuzz check's view. The cubic term
    /// closes one branch of the hyperbola into an oval about `1e15` across,
    /// wholly outside the view, whose turning point the pencil computed in
    /// view (ill-conditioned there): the oval was sampled, every chord far
    /// out refined until the whole budget was spent (1,048,640 vertices,
    /// 1,048,603 outside the view, in steps of length zero where the
    /// coordinates' rounding exceeds the tolerance). Now: the other branch
    /// alone, every vertex in view and on the curve, and a few vertices.
    #[test]
    fn a_conic_with_a_tiny_cubic_term_is_traced_in_its_view() {
        let c = [
            0.0745667719493974,
            -0.026364956120593815,
            0.019096015553886916,
            -0.3621476832076146,
            -1.0,
            0.3621476832076146,
            3.0734782212576794e-16,
            9.353948322509667e-32,
            3.0734782212576764e-16,
            -2.9231088507842707e-32,
        ];
        let cubic = Cubic::from_local(
            c,
            Point2::new(-0.0019969776214826184, -0.04285546875),
            0.0475220808370063,
        );
        // `xmin, xmax, ymin, ymax`.
        let v = [
            -0.029242633635673303,
            0.0658015280383393,
            -0.0365912110441461,
            0.058452950629866496,
        ];
        let view = Viewport::new(v[0], v[1], v[2], v[3]).unwrap();
        let t = cubic.trace(&view, None).unwrap();
        let lines = t.polylines();
        let n: usize = lines.iter().map(Vec::len).sum();
        assert!(n < 1000, "{n} vertices");
        assert_eq!(lines.len(), 1, "{lines:?}");
        let l = &lines[0];
        assert!(l.len() >= 10, "{l:?}");
        for p in l {
            assert!(view.contains(*p), "{p} outside the view");
            assert!(cubic.is_zero_local(cubic.local_of(*p)), "{p} off the curve");
        }
        // From edge to edge.
        let on_edge = |p: Point2<f64>| {
            p.x == view.xmin || p.x == view.xmax || p.y == view.ymin || p.y == view.ymax
        };
        assert!(on_edge(l[0]) && on_edge(l[l.len() - 1]), "{l:?}");
        // The marked trace too.
        let m = trace_marked(&cubic, &view, t.tolerance, &[], None).unwrap();
        assert_eq!(m.iter().map(Vec::len).sum::<usize>(), n);
        assert!(m.iter().flatten().all(|(p, _)| view.contains(*p)));
    }

    fn vp(h: f64) -> Viewport {
        Viewport::new(-h, h, -h, h).unwrap()
    }

    /// Distance from `p` to the nearest chord of the polylines.
    fn distance(t: &CubicTrace, p: Point2<f64>) -> f64 {
        let mut best = f64::INFINITY;
        for l in t.polylines() {
            for w in l.windows(2) {
                let (a, b) = (w[0], w[1]);
                let ab = b - a;
                let u =
                    ((p - a).dot(&ab) / ab.norm_squared().max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
                best = best.min((a + ab * u - p).norm());
            }
        }
        best
    }

    #[test]
    fn an_oval_and_a_branch() {
        // y^2 = x^3 - x: an oval on [-1, 0] and a branch from x = 1.
        let c = Cubic::new([0.0, -1.0, 0.0, 0.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0]).unwrap();
        let t = c.trace(&vp(3.0), None).unwrap();
        assert_eq!(t.components.len(), 2, "{t:?}");
        assert_eq!(t.in_view(), 2);
        let oval = t.components.iter().find(|k| k.bounded).unwrap();
        assert!(oval.closed);
        assert_eq!(oval.polylines.len(), 1);
        let l = &oval.polylines[0];
        assert_eq!(l[0], l[l.len() - 1]);
        let branch = t.components.iter().find(|k| !k.bounded).unwrap();
        assert_eq!(branch.polylines.len(), 1);
        for l in t.polylines() {
            for p in l {
                assert!(c.distance_estimate(p) < 1e-12, "{p}");
            }
        }
        // Zoomed onto the oval only.
        let t = c
            .trace(&Viewport::new(-1.2, 0.2, -1.0, 1.0).unwrap(), None)
            .unwrap();
        assert_eq!(t.in_view(), 1);
        assert!(t.components.iter().any(|k| k.closed));
    }

    #[test]
    fn a_node_and_a_line_pair() {
        // The nodal cubic y^2 = x^2 (x + 1).
        let c = Cubic::new([0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0]).unwrap();
        let t = c.trace(&vp(2.0), None).unwrap();
        assert!(t.in_view() >= 1);
        // The loop passes near the node and through (-1, 0).
        assert!(distance(&t, Point2::new(-1.0, 0.0)) < t.tolerance);
        assert!(distance(&t, Point2::new(0.0, 0.0)) < t.tolerance);
        for p in t.polylines().iter().flatten() {
            assert!(c.evaluate(*p).abs() < 1e-12, "{p}");
        }
        // A line times a circle: x (x^2 + y^2 - 1).
        let c = Cubic::new([0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0]).unwrap();
        let t = c.trace(&vp(2.0), None).unwrap();
        for p in [
            (0.0, 1.9),
            (0.0, -0.3),
            (-1.0, 0.0),
            (0.6, 0.8),
            (0.6, -0.8),
        ] {
            assert!(distance(&t, Point2::new(p.0, p.1)) < t.tolerance, "{p:?}");
        }
        assert!(t.components.iter().any(|k| k.closed));
    }

    #[test]
    fn a_cusp_and_an_isolated_point() {
        // y^2 = x^3: a cusp at the origin.
        let c = Cubic::new([0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0]).unwrap();
        let t = c.trace(&vp(2.0), None).unwrap();
        assert!(distance(&t, Point2::new(0.0, 0.0)) < t.tolerance);
        assert!(distance(&t, Point2::new(1.0, 1.0)) < t.tolerance);
        assert!(distance(&t, Point2::new(1.0, -1.0)) < t.tolerance);
        for p in t.polylines().iter().flatten() {
            assert!(c.evaluate(*p).abs() < 1e-12, "{p}");
        }
        // y^2 = x^2 (x - 1): an isolated point at the origin (not drawn) and
        // a branch from x = 1.
        let c = Cubic::new([0.0, 0.0, 0.0, -1.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0]).unwrap();
        let t = c.trace(&vp(2.0), None).unwrap();
        assert!(distance(&t, Point2::new(1.0, 0.0)) < t.tolerance);
        assert!(distance(&t, Point2::new(1.5, 1.5 * 0.5f64.sqrt())) < t.tolerance);
        for p in t.polylines().iter().flatten() {
            assert!(c.evaluate(*p).abs() < 1e-12, "{p}");
        }
    }

    #[test]
    fn extreme_viewports_and_tolerances_finish() {
        let c = Cubic::new([0.0, -1.0, 0.0, 0.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0]).unwrap();
        for h in [1e-300, 1e-12, 1e12, 1e300] {
            let t = c.trace(&vp(h), None).unwrap();
            for p in t.polylines().iter().flatten() {
                assert!(p.x.is_finite() && p.y.is_finite());
            }
        }
        let t = c
            .trace(&Viewport::new(-6e307, 6e307, -6e307, 6e307).unwrap(), None)
            .unwrap();
        for p in t.polylines().iter().flatten() {
            assert!(p.x.is_finite() && p.y.is_finite());
        }
        // A tolerance far below rounding is raised; the work stays bounded.
        let t = c.trace(&vp(3.0), Some(1e-300)).unwrap();
        assert!(t.tolerance >= 1e-10 * 6.0 * 2f64.sqrt() * 0.99);
        assert!(t.polylines().iter().map(Vec::len).sum::<usize>() < 2_000_000);
        // A viewport far from the curve.
        let t = c
            .trace(&Viewport::new(100.0, 101.0, -1.0, 0.0).unwrap(), None)
            .unwrap();
        assert_eq!(t.in_view(), 0);
    }

    #[test]
    fn three_lines() {
        // (x + 1.3 y) x (x + 1.1): every point near the view is on a line.
        let c = Cubic::new([0.0, 0.0, 0.0, 1.1, 1.43, 0.0, 1.0, 1.3, 0.0, 0.0]).unwrap();
        let t = c.trace(&vp(4.0), None).unwrap();
        for p in [(0.0, 3.0), (-1.1, -2.0), (2.6, -2.0), (0.0, 0.0)] {
            assert!(distance(&t, Point2::new(p.0, p.1)) < t.tolerance, "{p:?}");
        }
        for p in t.polylines().iter().flatten() {
            assert!(c.evaluate(*p).abs() < 1e-12, "{p}");
        }
    }

    #[test]
    fn an_invalid_tolerance_is_a_typed_error() {
        use crate::error::{Error, InvalidInput};
        let c = Cubic::new([0.0, -1.0, 0.0, 0.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0]).unwrap();
        let view = vp(3.0);
        // NaN and infinities are not finite; zero and below not positive.
        let bad = [
            (f64::NAN, "a finite number"),
            (f64::INFINITY, "a finite number"),
            (f64::NEG_INFINITY, "a finite number"),
            (0.0, "greater than zero"),
            (-0.0, "greater than zero"),
            (-1e-3, "greater than zero"),
            (-f64::MAX, "greater than zero"),
        ];
        for (t, want) in bad {
            let e = c.trace(&view, Some(t)).unwrap_err();
            let typed = match &e {
                Error::InvalidInput(InvalidInput::NotFinite {
                    name: "tolerance",
                    value,
                }) => !t.is_finite() && value.to_bits() == t.to_bits(),
                Error::InvalidInput(InvalidInput::NotPositive {
                    name: "tolerance",
                    value,
                }) => t.is_finite() && value.to_bits() == t.to_bits(),
                _ => false,
            };
            assert!(typed, "{t}: {e:?}");
            let message = e.to_string();
            assert!(
                message.starts_with(&format!("tolerance must be {want}")),
                "{message}"
            );
        }
        // The default, given or not, is one trace, and the one of `polylines`.
        let default = c.trace(&view, None).unwrap();
        let given = c
            .trace(&view, Some(view.diagonal() * Cubic::DEFAULT_TOLERANCE))
            .unwrap();
        assert_eq!(
            default.tolerance,
            view.diagonal() * Cubic::DEFAULT_TOLERANCE
        );
        assert_eq!(default.polylines(), given.polylines());
        assert_eq!(default.polylines(), c.polylines(&view));
        assert_eq!(default.in_view(), 2);
    }
}
