//! Filemon's construction with four lines, and the exact ends of the
//! branch-free arcs of the circle-point curve.

use nalgebra::Point2;

use super::split::split_by;
use super::{FourPositions, POLL_SAMPLES};
use crate::engine::Control;
use crate::error::{Result, try_push};
use crate::geom::cubic::roots::quadratic_roots;
use crate::geom::{Cubic, Line, LocalFrame, PerPose, Viewport, cross, normalized};
use crate::synthesis::branch::FilemonLines;
use crate::synthesis::errors;
use crate::synthesis::motion::Motion;
use crate::synthesis::{Branch, DyadKind};

/// An end of a branch-free arc: where an extreme Filemon line meets the
/// circle-point curve (besides `C1`), and the center point of that dyad.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcEnd {
    /// The pose (1-based) whose line it is on.
    pub pose: usize,
    /// The circle point, on the circle-point curve and on the line.
    pub circle: Point2<f64>,
    /// Its center point, on the center-point curve; `None` where it is at
    /// infinity (a slider) or undefined.
    pub center: Option<Point2<f64>>,
}

/// Filemon's construction for a driven dyad of four poses: a crank
/// `(C0, C1)` or a slider `(C1, u)` (its lines run through `C1` in the
/// directions `n_k`, see [`FilemonLines`]; everything below holds with
/// `n_k` for `C'_k - C1`).
///
/// # The lines and the double wedge
///
/// `C'_k = D_k1(C0)` is the driven crank's fixed pivot seen from the
/// coupler frame of pose 1 while at pose `k`. The branch sign of a driving
/// circle point `A1` at pose `k` is
///
/// ```text
/// s_k = sign cross(C'_k - C1, A1 - C1)
/// ```
///
/// and the driving dyad passes the four poses in one assembly mode when
/// the four signs agree: in the double wedge between the two **extreme**
/// lines (the directions `C'_k - C1` sorted by angle inside their
/// half-plane), or nowhere when the directions do not lie in an open
/// half-plane ([`FilemonArcs::all_defective`]).
///
/// # The exact arc ends
///
/// The driving circle point must lie on the circle-point curve, which
/// passes through `C1`; the line through `C1` along `d` meets the cubic
/// where
///
/// ```text
/// f(C1 + t d) = t (a3 t^2 + a2 t + a1) = 0
/// ```
///
/// so each line meets it in at most two more points, the roots of one
/// quadratic. Those on the two extreme lines are the ends of the
/// branch-free arcs ([`FilemonArcs::arc_ends`]); their center points (the
/// circle-to-center map) end the arcs of the center-point curve. No
/// sampling.
#[derive(Debug, Clone, PartialEq)]
pub struct FilemonArcs {
    four: FourPositions,
    /// The lines, their directions and order (any kind of driven dyad).
    lines: FilemonLines,
    /// The poses (0-based) sorted by the angle of the directions within
    /// their half-plane; `None` when they do not lie in an open half-plane.
    order: Option<[usize; 4]>,
    /// The other points of each line on the circle-point curve.
    meets: [Vec<Point2<f64>>; 4],
    ends: Vec<ArcEnd>,
}

impl FilemonArcs {
    /// The construction for a driven dyad of `four` (checked to pass the
    /// poses by the caller).
    ///
    /// # Errors
    ///
    /// As [`FilemonLines::new`] (for a crank, an image `C'_k` that is not
    /// finite or coincides with `C1` is [`crate::InvalidInput::Overflow`]).
    pub(crate) fn new(four: &FourPositions, driven: DyadKind) -> Result<Self> {
        let motion = Motion::new(PerPose::from_slice(four.poses()));
        let lines = FilemonLines::of_motion(&motion, four.size(), driven)?;
        let c1 = driven.circle();
        let mut dirs = [nalgebra::Vector2::zeros(); 4];
        for (d, v) in dirs.iter_mut().zip(lines.directions().iter()) {
            *d = normalized(*v).ok_or_else(errors::bad_driven)?;
        }
        let order = lines
            .pose_order()
            .map(|o| [o[0] - 1, o[1] - 1, o[2] - 1, o[3] - 1]);
        let curve = four.circle_point_curve();
        let p = curve.local_of(c1);
        let meets = dirs.map(|d| {
            let r = curve.restriction_local(p, d);
            // f(C1 + t d) / t: C1 is on the curve, so the constant term is
            // rounding; a root within rounding of 0 is C1 again (a tangent).
            quadratic_roots(r[3], r[2], r[1])
                .into_iter()
                .filter(|t| t.abs() > 1e-12 * (1.0 + p.norm()))
                .map(|t| curve.global_of(p + d * curve.refine_on_line(p, d, t)))
                .filter(|q| q.x.is_finite() && q.y.is_finite())
                .collect::<Vec<_>>()
        });
        let ends = match order {
            None => Vec::new(),
            Some(o) => [o[0], o[3]]
                .iter()
                .flat_map(|&k| {
                    meets[k].iter().map(move |&x| ArcEnd {
                        pose: k + 1,
                        circle: x,
                        center: None,
                    })
                })
                .map(|mut e| {
                    e.center = four.center_point(e.circle).ok();
                    e
                })
                .collect(),
        };
        Ok(FilemonArcs {
            four: *four,
            lines,
            order,
            meets,
            ends,
        })
    }

    /// The driven dyad: `(C0, C1)` for a crank, `(C1, u)` for a slider.
    pub fn driven(&self) -> DyadKind {
        self.lines.driven()
    }

    /// The construction in the circle-point plane (lines, directions,
    /// extremes, signs), as for any number of poses.
    pub fn construction(&self) -> &FilemonLines {
        &self.lines
    }

    /// `[C'_1, ..., C'_4]`, `C'_k = D_k1(C0)`; `None` for a slider (its
    /// center is at infinity).
    pub fn fixed_pivot_images(&self) -> Option<[Point2<f64>; 4]> {
        self.lines
            .fixed_pivot_images()
            .map(|c| [c[0], c[1], c[2], c[3]])
    }

    /// The four lines through `C1` (directions `C'_k - C1` for a crank,
    /// `n_k` for a slider).
    pub fn all_lines(&self) -> [Line; 4] {
        let l = self.lines.all_lines();
        [l[0], l[1], l[2], l[3]]
    }

    /// Whether every driving circle point has a branch defect (the
    /// lines' directions do not lie in an open half-plane).
    pub fn all_defective(&self) -> bool {
        self.order.is_none()
    }

    /// The poses (1-based) of the two extreme lines (the Filemon lines),
    /// first and last by angle; `None` when all are defective.
    pub fn extreme_poses(&self) -> Option<[usize; 2]> {
        self.order.map(|o| [o[0] + 1, o[3] + 1])
    }

    /// The two Filemon lines; `None` when all are defective.
    pub fn lines(&self) -> Option<[Line; 2]> {
        let all = self.all_lines();
        self.order.map(|o| [all[o[0]], all[o[3]]])
    }

    /// The points other than `C1` where the line of pose `k` (1-based)
    /// meets the circle-point curve (none, one or two); empty for a `k`
    /// that is not 1 to 4.
    pub fn line_points(&self, k: usize) -> &[Point2<f64>] {
        match k {
            1..=4 => &self.meets[k - 1],
            _ => &[],
        }
    }

    /// The exact ends of the branch-free arcs (on the two Filemon lines);
    /// empty when all are defective.
    pub fn arc_ends(&self) -> &[ArcEnd] {
        &self.ends
    }

    /// The branch signs `cross(d_k, A1 - C1)` of a driving circle point
    /// (`d_k = C'_k - C1` for a crank, `n_k` for a slider).
    pub fn circle_signs(&self, a1: Point2<f64>) -> [f64; 4] {
        let s = self.lines.circle_signs(a1);
        [s[0], s[1], s[2], s[3]]
    }

    /// The branch class of a driving circle point `A1`: free when the four
    /// signs agree, a boundary where one is zero (a toggle at a pose) or
    /// where `A1` is `C1` (within [`crate::tolerance::POINT`] task sizes:
    /// every sign is zero there, and a curve with a line of centers whose
    /// circle point is `C1` would otherwise be labelled by rounding).
    pub fn classify_circle_point(&self, a1: Point2<f64>) -> Branch {
        if (a1 - self.driven().circle()).norm() <= crate::tolerance::POINT * self.four.size() {
            return Branch::Boundary;
        }
        let s = self.circle_signs(a1);
        if s.iter().any(|&v| v == 0.0 || v.is_nan()) {
            Branch::Boundary
        } else if self.order.is_some() && s.iter().all(|&v| (v > 0.0) == (s[0] > 0.0)) {
            Branch::Free
        } else {
            Branch::Defective
        }
    }

    /// The branch class of a driving center point `A0` on the center-point
    /// curve (through its circle point).
    ///
    /// # Errors
    ///
    /// As [`FourPositions::circle_point`].
    pub fn classify_center_point(&self, a0: Point2<f64>) -> Result<Branch> {
        Ok(self.classify_circle_point(self.four.circle_point(a0)?))
    }

    /// The branch-free arcs of the circle-point curve in view.
    ///
    /// The class of a driving circle point changes only where it crosses
    /// an extreme Filemon line (the exact arc ends) and at `C1` (where
    /// every sign is zero; never free). The traced curve
    /// ([`crate::geom::Cubic::trace`], default tolerance) is sampled with
    /// those points as vertices, exactly (placed on the curve by the
    /// tracer's own parameter), so each piece between two of them is a
    /// stretch of the curve of one class, labelled by its vertices; the
    /// free pieces are joined across the arc ends they share and cut at
    /// `C1`. The curve's point at the middle of each chord next to a mark
    /// (or between vertices of different classes, or on a stretch of
    /// centers whose circle points are nearly one point) is classified
    /// too, and a change it shows is found on the curve by bisection and
    /// made a vertex (where the exact arc ends are rounding: a line of
    /// centers whose circle points are nearly one point). A point is free
    /// only where its class holds across the float curve's own resolution
    /// there (near a singular point of a nearly degenerate task it may be
    /// far coarser than the task allows; such stretches are omitted). The arcs are the
    /// same in every view: the arcs of a smaller view are those of a larger
    /// one, clipped.
    ///
    /// # Errors
    ///
    /// [`crate::Error::OutOfMemory`] when the labelled vertices cannot be
    /// allocated.
    pub fn free_circle_arcs(&self, viewport: &Viewport) -> Result<Vec<Vec<Point2<f64>>>> {
        self.free_arcs_with(viewport, true, &Control::new())
    }

    /// The branch-free arcs of the center-point curve in view (the driving
    /// center points whose dyads pass the poses in one assembly mode): as
    /// [`free_circle_arcs`](Self::free_circle_arcs), with the centers of
    /// the exact arc ends and `C0` (never free; a slider has none) as the
    /// vertices where the class may change, each traced point classified by
    /// its circle point.
    ///
    /// # Errors
    ///
    /// As [`free_circle_arcs`](Self::free_circle_arcs).
    pub fn free_center_arcs(&self, viewport: &Viewport) -> Result<Vec<Vec<Point2<f64>>>> {
        self.free_arcs_with(viewport, false, &Control::new())
    }

    /// [`free_circle_arcs`](Self::free_circle_arcs) (where `circle`) or
    /// [`free_center_arcs`](Self::free_center_arcs) following `control`:
    /// the cancel flag is checked before the trace, inside it every 4096
    /// vertices placed or settled (a trace may place a million), then
    /// (with a progress report in traced vertices, each classified once)
    /// every 1024 vertices and before each bisection of a class change.
    ///
    /// # Errors
    ///
    /// As [`free_circle_arcs`](Self::free_circle_arcs);
    /// [`crate::Error::Cancelled`] when the flag is set (`0` of `0` before
    /// the trace or inside it).
    pub fn free_arcs_with(
        &self,
        viewport: &Viewport,
        circle: bool,
        control: &Control<'_>,
    ) -> Result<Vec<Vec<Point2<f64>>>> {
        // The exact arc ends in the curve's plane, and the driven dyad's
        // point there, are the vertices where the class may change.
        let mut marks: Vec<Point2<f64>> = self
            .ends
            .iter()
            .filter_map(|e| if circle { Some(e.circle) } else { e.center })
            .collect();
        let driven = self.driven();
        let (curve, at) = if circle {
            (self.four.circle_point_curve(), Some(driven.circle()))
        } else {
            (self.four.center_point_curve(), driven.finite_center())
        };
        // The driven dyad's point (never free) is the last mark; a slider
        // has no center point, and no mark is `never` then.
        let never = at.map_or(usize::MAX, |_| marks.len());
        marks.extend(at);
        // Free only where the float curve decides it (see `label`).
        let free = |p: Point2<f64>| self.label(p, circle);
        control.check(0, 0)?;
        // The trace itself reads the cancel flag (`Cancelled`, 0 of 0).
        let lines = curve.polylines_marked(viewport, &marks, control.cancel_flag())?;
        // Progress counts the traced vertices, each classified once.
        let mut poll = Poll {
            control,
            done: 0,
            total: lines.iter().map(Vec::len).sum(),
        };
        // The curve's point of a chord lies within the trace's chord
        // tolerance of it; twice that is the reach of the chord's own branch.
        let reach = 2.0 * Cubic::DEFAULT_TOLERANCE * viewport.diagonal();
        let mark_class = |p: Point2<f64>| self.mark_class(p, circle, reach);
        let lines = resolve_changes(curve, &lines, reach, never, &free, &mark_class, &mut poll)?;
        control.report(poll.total, poll.total);
        Ok(free_pieces(&lines, never))
    }
}

impl FilemonArcs {
    /// The label of a point of the curve of its plane (`circle`: the
    /// circle-point curve): free only where the four signs agree and keep
    /// agreeing across the float curve's own resolution there
    /// ([`resolution`]), with the circle point of a center point.
    ///
    /// The curve's coefficients are rounded to doubles, so a traced point,
    /// or the curve's point next to a chord, is known only to within that
    /// band. Near a singular point (or on a nearly degenerate task) it is
    /// far coarser than the task itself allows: on the circle plane of the
    /// fuzz input `b1b9e681` the resolution is `1.5e-2` in a view of 25
    /// (the exact curve `2.7e-3` from a traced point there, where one ulp
    /// of the task moves it by `3e-9`), and the signs are `0.08` with the
    /// lines' directions `42` long. A circle point nearer a Filemon line
    /// than the band's width, or a center whose circle point is nearer one
    /// than twice the way it moves as the center moves across the band
    /// (measured on one side), has its class decided by rounding and is
    /// not called free. On an ordinary curve this omits about `1e-14` task
    /// sizes next to an arc end.
    fn label(&self, p: Point2<f64>, circle: bool) -> Label {
        let (is_free, image) = self.raw_class(p, circle);
        if is_free != Some(true) {
            return Label {
                free: is_free,
                image,
                room: 0.0,
            };
        }
        let room = self.room(image.unwrap_or(p));
        let free = self.decided(p, circle, image, room.abs());
        Label {
            free: Some(free),
            image,
            room: if free { room } else { 0.0 },
        }
    }

    /// The distance of a circle point from the nearest Filemon line (of
    /// the four), signed by the half of the double wedge it is in (the sign
    /// of its first branch sign: the half of a free point).
    fn room(&self, z: Point2<f64>) -> f64 {
        let s = self.circle_signs(z);
        s.iter()
            .zip(self.lines.directions().iter())
            .fold(f64::INFINITY, |m, (s, d)| m.min(s.abs() / d.norm()))
            .copysign(s[0])
    }

    /// The class of the curve's point next to a mark (an exact arc end, in
    /// the plane of the curve; taken back onto the curve along its gradient,
    /// within `reach`) where it holds across the float curve's resolution
    /// there (as [`label`](Self::label) decides a free point): `Some(free)`
    /// for a mark that is decidedly inside a stretch of one class, `None`
    /// for one on its extreme line within rounding, as an arc end is, or
    /// without a class. On a line of centers whose circle points are nearly
    /// one point (three poses at nearly one position) an arc end's center is
    /// rounding along the line and off the curve (curv34): the curve's
    /// point next to it has its circle point well off the extreme line,
    /// inside a stretch of one class, and the class changes somewhere
    /// between it and the next vertex (fuzz inputs `144ad15d`, `aaa7b4d6`,
    /// `910507b9`: the mark `600`, `650` and `1.2e7` from the exact change,
    /// and `3.6e-4` off the exact curve against an on-curve tolerance of
    /// `6.5e-5`, `fuzz/reference/open_curves.py`).
    fn mark_class(&self, p: Point2<f64>, circle: bool, reach: f64) -> Option<bool> {
        let curve = if circle {
            self.four.circle_point_curve()
        } else {
            self.four.center_point_curve()
        };
        let q = curve_point_near(curve, p, reach)?;
        let (is_free, image) = self.raw_class(q, circle);
        is_free.filter(|_| self.decided(q, circle, image, self.room(image.unwrap_or(q)).abs()))
    }

    /// The class of a point by its four signs (free, or `None` where a
    /// center point has no circle point), and the circle point of a center.
    fn raw_class(&self, p: Point2<f64>, circle: bool) -> (Option<bool>, Option<Point2<f64>>) {
        if circle {
            (Some(self.classify_circle_point(p) == Branch::Free), None)
        } else {
            match self.four.circle_point(p) {
                Ok(z) => (Some(self.classify_circle_point(z) == Branch::Free), Some(z)),
                Err(_) => (None, None),
            }
        }
    }

    /// Whether the class of the curve's point `p` (with its circle point
    /// `image` in the center plane) holds across the float curve's
    /// resolution there: its circle point is farther from every Filemon
    /// line than the band's width (the circle plane) or than twice the way
    /// it moves as the center moves across the band, by each pair of the
    /// conditions where they are nearly parallel ([`NEARLY_PARALLEL`]), and
    /// than [`ULPS`] ulps of its coordinates (the center plane);
    /// `apart` is that circle point's distance from the nearest line
    /// ([`room`](Self::room)).
    fn decided(
        &self,
        p: Point2<f64>,
        circle: bool,
        image: Option<Point2<f64>>,
        apart: f64,
    ) -> bool {
        let curve = if circle {
            self.four.circle_point_curve()
        } else {
            self.four.center_point_curve()
        };
        resolution(curve, p).is_some_and(|r| {
            match image {
                None => apart > r,
                // How far the circle point moves as the center moves
                // across the band (one side: twice that, for the other),
                // and at least a few ulps of the circle point's coordinates
                // (the lines through `C1` are known no better; fuzz input
                // `1e3714ac`). Where the conditions are nearly parallel,
                // by each pair of them ([`NEARLY_PARALLEL`]). (Solved as
                // `circle_point` solves them, without its on-curve test:
                // the moved center is on the band's edge by construction.)
                Some(z) => normalized(curve.gradient(p)).is_some_and(|g| {
                    let motion = &self.four.motion;
                    let moved = motion.local_of(p + g * r);
                    let moves = |ks: &[usize]| {
                        motion
                            .form
                            .solve(moved, ks)
                            .map(|w| (motion.global_of(w) - z).norm())
                    };
                    let far = if nearly_parallel(&motion.form, moved) {
                        // A pair without a unique solution there is not
                        // one the classifier takes.
                        PAIRS
                            .iter()
                            .filter_map(|ks| moves(ks).ok())
                            .reduce(f64::max)
                    } else {
                        moves(&[1, 2, 3]).ok()
                    };
                    apart > ULPS * f64::EPSILON * z.coords.norm()
                        && far.is_some_and(|d| apart > 2.0 * d)
                }),
            }
        })
    }
}

/// A point's label ([`FilemonArcs::label`]): free (`None` where a center
/// point has no class) and, in the center plane, its circle point.
#[derive(Debug, Clone, Copy)]
struct Label {
    free: Option<bool>,
    image: Option<Point2<f64>>,
    /// For a free point, its circle point's distance from the nearest
    /// Filemon line, signed by the half of the double wedge it is in (the
    /// sign of its branch signs); `0` otherwise.
    room: f64,
}

/// The band about the float curve, in units of the first-order move of
/// the rounding of its coefficients ([`resolution`]), within
/// which a free point's class must hold: the band within which the tracer
/// settles a vertex and the curve's point next to a chord is found
/// ([`Cubic::is_on`]'s rule, `|f|` within `64 eps` of its terms).
const RESOLUTION: f64 = 64.0;

/// The float curve's resolution at `p`: how far the rounding of its
/// coefficients (half an ulp of each, `eps` of the terms' magnitude at
/// `p`) moves the curve there, to first order, [`RESOLUTION`] times that,
/// and at least a few ulps of the point's own coordinates (a task of
/// `5e-11` at `2.9e-5` from the origin, fuzz input `4960ca6f`, has its
/// curve resolved to `7e-27` by its coefficients, but its points are placed
/// only to `3.4e-21`, and the class there changes from one ulp to the next);
/// `None` where the gradient is zero or the point is not finite in the
/// curve's frame.
fn resolution(curve: &Cubic, p: Point2<f64>) -> Option<f64> {
    // `f` and its terms over `m^3`, the gradient over `m^2` (local units).
    let (_, bound, g, m) = curve.value_and_bound(p, &[0.0; 10])?;
    let d = RESOLUTION * f64::EPSILON * bound / g * m * curve.frame().1;
    let d = d.max(ULPS * f64::EPSILON * p.coords.norm());
    d.is_finite().then_some(d)
}

/// How many ulps of a point's coordinates its class must hold across, at
/// least.
const ULPS: f64 = 4.0;

/// The pairs of the circle-point conditions (poses 2, 3, 4; rows 1 to 3)
/// whose solutions [`FilemonArcs::decided`] asks to agree on a center's
/// class where the conditions are nearly parallel ([`NEARLY_PARALLEL`]).
const PAIRS: [[usize; 2]; 3] = [[1, 2], [1, 3], [2, 3]];

/// The sine of the angle between two of the three circle-point conditions
/// (their vectors `a_k(g)`) below which, for every pair, they are nearly
/// parallel (they nearly leave a line of circle points: a stretch of
/// centers whose circle points are nearly one point, three poses at nearly
/// one position). There the best conditioned pair, which `circle_point`
/// solves, changes along the curve within a chord, and off the curve the
/// pairs disagree: on fuzz input `9df66c48` (sines `0.004` to `0.03`) the
/// determinant of poses 3 and 4 is `0.53`, `1.33` and `0.57` of that of
/// poses 2 and 3 at a chord's start, the curve's point at its middle and
/// its end (`5e-10` apart in a view `6e-6` wide), and the two pairs' circle
/// points for that middle point (`5e-20` off the exact curve) are
/// `1.4e-16` apart, against a distance of `1.8e-16` from the Filemon
/// lines. Elsewhere the pairs are well apart (`0.46` to `0.97` on the line
/// of centers of `f1c7cc58`, whose best pair does not change along it).
const NEARLY_PARALLEL: f64 = 0.1;

/// Whether the three circle-point conditions at the center `g` (local) are
/// nearly parallel ([`NEARLY_PARALLEL`]).
fn nearly_parallel(form: &crate::synthesis::local::LinearForm, g: nalgebra::Vector2<f64>) -> bool {
    let a = [1, 2, 3].map(|k| form.row(k, g).0);
    PAIRS.iter().all(|&[i, j]| {
        let (u, v) = (a[i - 1], a[j - 1]);
        cross(u, v).abs() < NEARLY_PARALLEL * u.norm() * v.norm()
    })
}

/// A traced vertex: where it is, the index of the mark it is (if any) and,
/// for a vertex that is not a mark, whether it is free (`None` where it
/// has no class) and its circle point (the center plane).
#[derive(Debug, Clone, Copy)]
struct Vertex {
    at: Point2<f64>,
    mark: Option<usize>,
    free: Option<bool>,
    /// The circle point of a center point (the center plane, not a mark).
    image: Option<Point2<f64>>,
    /// Its label's room ([`Label::room`]).
    room: f64,
}

/// The progress of [`FilemonArcs::free_arcs_with`] in traced vertices, with its
/// control.
struct Poll<'a, 'c> {
    control: &'a Control<'c>,
    done: usize,
    total: usize,
}

impl Poll<'_, '_> {
    /// One more unit done: every [`POLL_SAMPLES`] units the progress is
    /// reported and the cancel flag checked.
    fn step(&mut self) -> Result<()> {
        if self.done % POLL_SAMPLES == 0 {
            self.check()?;
        }
        self.done += 1;
        Ok(())
    }

    /// Reports the progress and checks the cancel flag now.
    fn check(&self) -> Result<()> {
        self.control.report(self.done, self.total);
        self.control.check(self.done, self.total)
    }
}

/// Where [`resolve_changes`] takes a chord of the center plane for a
/// stretch of centers whose circle points are nearly one point: its ends'
/// circle points closer than this fraction of its length. On such a
/// stretch (a line of centers of a task with three poses at nearly one
/// position) the exact arc ends' centers are rounding along it or lost
/// (the two meets of an extreme line with the circle-point curve a double
/// root within rounding), while each center's class is well decided and
/// can change and change back within one chord: the chord's middle is
/// classified. Measured `2e-13` to `3e-11` on such lines; an ordinary
/// curve's ratio is of order 1, and falls to this only `1e3` task sizes
/// out (as the square of the distance), where the check only costs time.
/// Only chords of free ends (a free stretch hidden in a defective chord
/// is omitted, not called free) longer than the reach of the chord's own
/// branch (twice the trace's chord tolerance): a trace refined to its
/// budget along such a line (a million vertices on the center plane of
/// `traced-vertex-1.5-tolerances-off-ordinary-task`) would otherwise
/// classify most middles too.
const CONTRACTED: f64 = 1e-6;

/// The mark index of a class change found by [`resolve_changes`]: a
/// vertex where the class may change, never the driven dyad's point.
const CHANGE: usize = usize::MAX - 1;

/// The curve's point nearest `m` on the line through `m` along the
/// gradient there, if it lies within `reach` of `m` and between `a` and
/// `b` (within the chord's length of both).
fn curve_point_between(
    curve: &Cubic,
    m: Point2<f64>,
    reach: f64,
    a: Point2<f64>,
    b: Point2<f64>,
) -> Option<Point2<f64>> {
    let len = (b - a).norm();
    curve_point_near(curve, m, reach).filter(|q| (q - a).norm() <= len && (q - b).norm() <= len)
}

/// The curve's point nearest `m` on the line through `m` along the
/// gradient there, if it lies within `reach` of `m`.
fn curve_point_near(curve: &Cubic, m: Point2<f64>, reach: f64) -> Option<Point2<f64>> {
    let g = curve.gradient(m);
    if !(g.x.is_finite() && g.y.is_finite()) || g.norm() == 0.0 {
        return None;
    }
    curve
        .intersect_line(&Line {
            point: m,
            direction: g,
        })
        .into_iter()
        .filter(|q| q.x.is_finite() && q.y.is_finite())
        .min_by(|p, q| (p - m).norm().total_cmp(&(q - m).norm()))
        .filter(|q| (q - m).norm() <= reach)
}

/// Where the class changes between two points of the curve with different
/// classes, `a` (`la`) and `b`: bisection on the curve (the chord's
/// middle taken back onto the curve along the gradient) until the two
/// points are within rounding of each other or the curve between them
/// is no longer found. Returns the point on the free side of the bracket
/// (a free arc ends at a free point).
fn change_between(
    curve: &Cubic,
    reach: f64,
    mut a: Point2<f64>,
    la: bool,
    mut b: Point2<f64>,
    free: &impl Fn(Point2<f64>) -> Label,
) -> Point2<f64> {
    for _ in 0..200 {
        let scale = a.coords.norm().max(b.coords.norm());
        if (b - a).norm() <= 8.0 * f64::EPSILON * scale {
            break;
        }
        let m = Point2::from((a.coords + b.coords) * 0.5);
        let Some(q) = curve_point_between(curve, m, reach, a, b) else {
            break;
        };
        if q == a || q == b {
            break;
        }
        match free(q).free {
            Some(l) if l == la => a = q,
            Some(_) => b = q,
            None => break,
        }
    }
    if la { a } else { b }
}

/// What the free arcs' vertices are called where they cannot be allocated.
const VERTICES: &str = "free arcs' vertices";

/// The traced polylines, each vertex that is not a mark classified by
/// `free` (once: the labels go on with the vertices), with the class
/// changes that a chord next to a mark (or between vertices of different
/// classes) hides made vertices: the curve's point at the middle of such a chord (taken back onto
/// the curve along the gradient, within `reach` of the middle and between
/// the chord's ends) is classified, and where its class differs from that
/// of an end that is not a mark, the change is found by bisection on the
/// curve ([`change_between`]) and inserted as a mark, the middle point as
/// an ordinary vertex after it. The driven dyad's point (the mark `never`,
/// a boundary) is never free: where the middle of its chord is free, the
/// change between them is found the same way (on a line of centers whose
/// circle points are nearly that of the driven dyad, the classifier's
/// boundary about it covers a long stretch of the line). The middle of a
/// chord whose ends' circle points are nearly one point ([`CONTRACTED`])
/// is classified too, and so is that of a chord of two free ends that may
/// hide a crossing of an extreme line and back ([`Chords::hides`]: an
/// end's circle point near a Filemon line, or the ends in different halves
/// of the double wedge). Where a free middle is inserted next to a mark of
/// unknown class, the half next to the mark is examined again
/// ([`Chords::fill`]). A mark (other than the driven dyad's point and the
/// changes found here) whose own point is decidedly of one class
/// (`mark_class`: an arc end's center that is rounding along a line of
/// centers, [`FilemonArcs::mark_class`]) counts as of that class, so a
/// change between it and a middle of the other class is found the same way.
///
/// The exact arc ends are the meets of the extreme lines with the
/// circle-point curve; on a curve with a line of centers whose circle
/// points are nearly one point (three poses at nearly one position), those
/// meets lie within rounding of that point, and their centers (the
/// circle-to-center map of a point where a whole line of centers meets)
/// are known only to rounding along the line, while the class of each
/// center on it is well decided (its circle point moves smoothly along a
/// tiny arc across the extreme lines). There a class change is found where
/// it happens, in the plane of the curve.
fn resolve_changes(
    curve: &Cubic,
    lines: &[Vec<(Point2<f64>, Option<usize>)>],
    reach: f64,
    never: usize,
    free: &impl Fn(Point2<f64>) -> Label,
    mark_class: &impl Fn(Point2<f64>) -> Option<bool>,
    poll: &mut Poll<'_, '_>,
) -> Result<Vec<Vec<Vertex>>> {
    // A mark's own class where it is decided (not the driven dyad's point,
    // never free, nor a change found here, on the free side of one), each
    // mark's found once (it ends two chords).
    let known = core::cell::RefCell::new(Vec::<(usize, Option<bool>)>::new());
    let of_mark = |w: &Vertex| {
        let k = w.mark.filter(|&k| k != never && k != CHANGE)?;
        if let Some(&(_, c)) = known.borrow().iter().find(|(j, _)| *j == k) {
            return c;
        }
        let c = mark_class(w.at);
        known.borrow_mut().push((k, c));
        c
    };
    let ctx = Chords {
        curve,
        reach,
        never,
        free,
        of_mark: &of_mark,
    };
    lines
        .iter()
        .map(|line| {
            let mut out = super::try_vec_of::<Vertex>(VERTICES, line.len())?;
            let mut prev: Option<Vertex> = None;
            for &(at, mark) in line {
                poll.step()?;
                let label = match mark {
                    Some(_) => Label {
                        free: None,
                        image: None,
                        room: 0.0,
                    },
                    None => free(at),
                };
                let v = Vertex {
                    at,
                    mark,
                    free: label.free,
                    image: label.image,
                    room: label.room,
                };
                if let Some(u) = prev {
                    ctx.fill(&u, &v, 0, &mut out, poll)?;
                }
                try_push(&mut out, VERTICES, v)?;
                prev = Some(v);
            }
            Ok(out)
        })
        .collect()
}

/// What [`resolve_changes`] examines each chord with.
struct Chords<'a, F, M> {
    curve: &'a Cubic,
    reach: f64,
    never: usize,
    free: &'a F,
    of_mark: &'a M,
}

/// How many times [`Chords::fill`] takes the half of a chord next to a
/// mark of unknown class again.
const REEXAMINE: usize = 64;

impl<F, M> Chords<'_, F, M>
where
    F: Fn(Point2<f64>) -> Label,
    M: Fn(&Vertex) -> Option<bool>,
{
    /// Whether a mark's own class is unknown (an arc end's point on its
    /// extreme line within rounding, or one off the curve): not the driven
    /// dyad's point (never free) nor a change found here.
    fn unknown_mark(&self, w: &Vertex) -> bool {
        w.mark.is_some_and(|k| k != self.never && k != CHANGE) && (self.of_mark)(w).is_none()
    }

    /// Whether a chord of two free ends may hide a stretch of the other
    /// class ([`HIDDEN`]): its ends in different halves of the double wedge,
    /// or either end's circle point nearer a Filemon line than the curve
    /// may stray from the chord (the circle plane: `reach`) or than the
    /// ends' circle points are apart (the center plane).
    fn hides(&self, u: &Vertex, v: &Vertex) -> bool {
        let span = match (u.image, v.image) {
            (Some(za), Some(zb)) => (zb - za).norm(),
            _ => self.reach,
        };
        u.room.is_sign_negative() != v.room.is_sign_negative()
            || u.room.abs().min(v.room.abs()) <= HIDDEN * span
    }

    /// The vertices that the chord `u`-`v` hides, pushed onto `out` in
    /// order (see [`resolve_changes`]): where the curve's point at its
    /// middle has a class that differs from an end's, the change between
    /// them (bisected) and the middle point. Where the middle is free and
    /// inserted, and the other end is a mark of unknown class, the half
    /// next to that mark is examined again (up to [`REEXAMINE`] times): a
    /// chord from a mark across a free stretch to a defective vertex says
    /// nothing of the stretch between the mark and the middle (fuzz input
    /// `eb1a5faa`: an arc end's center that is rounding along a line of
    /// centers, the exact class defective from it to `0.62` of the chord).
    fn fill(
        &self,
        u: &Vertex,
        v: &Vertex,
        depth: usize,
        out: &mut Vec<Vertex>,
        poll: &mut Poll<'_, '_>,
    ) -> Result<()> {
        let (curve, reach, never, free) = (self.curve, self.reach, self.never, self.free);
        let (a, b) = (u.at, v.at);
        let (la, lb) = (u.free, v.free);
        // A chord next to a mark (an arc end that may be rounding along a
        // line of centers) or whose ends differ; between two vertices of
        // one class away from the marks a change is a pair of them, which
        // the exact arc ends resolve, except on a stretch of centers whose
        // circle points are nearly one point (`contracted`) or where the
        // chord may hide the pair (`hidden`).
        let marked = u.mark.is_some() || v.mark.is_some();
        // (Only a chord of free ends: a free stretch hidden in a defective
        // chord is omitted, not wrong.)
        let both_free = la == Some(true) && lb == Some(true);
        let len = (b - a).norm();
        let contracted = match (u.image, v.image) {
            (Some(za), Some(zb)) => both_free && len > reach && (zb - za).norm() < CONTRACTED * len,
            _ => false,
        };
        let hidden = both_free && self.hides(u, v);
        if !((la.is_some() || lb.is_some()) && (marked || la != lb || contracted || hidden)) {
            return Ok(());
        }
        let m = Point2::from((a.coords + b.coords) * 0.5);
        let Some(q) = curve_point_between(curve, m, reach, a, b).filter(|q| *q != a && *q != b)
        else {
            return Ok(());
        };
        let lq = free(q);
        let Some(lm) = lq.free else {
            return Ok(());
        };
        // The driven dyad's point is never free.
        let differs_a = la.is_some_and(|l| l != lm)
            || (lm && u.mark == Some(never))
            || (self.of_mark)(u).is_some_and(|l| l != lm);
        let differs_b = lb.is_some_and(|l| l != lm)
            || (lm && v.mark == Some(never))
            || (self.of_mark)(v).is_some_and(|l| l != lm);
        if !(differs_a || differs_b) {
            return Ok(());
        }
        poll.check()?;
        let w = Vertex {
            at: q,
            mark: None,
            free: Some(lm),
            image: lq.image,
            room: lq.room,
        };
        let again = lm && depth < REEXAMINE;
        if differs_a {
            try_push(
                out,
                VERTICES,
                change(change_between(curve, reach, a, !lm, q, free)),
            )?;
        } else if again && self.unknown_mark(u) {
            self.fill(u, &w, depth + 1, out, poll)?;
        }
        try_push(out, VERTICES, w)?;
        if differs_b {
            try_push(
                out,
                VERTICES,
                change(change_between(curve, reach, q, lm, b, free)),
            )?;
        } else if again && self.unknown_mark(v) {
            self.fill(&w, v, depth + 1, out, poll)?;
        }
        Ok(())
    }
}

/// A class change found by [`resolve_changes`], as a vertex.
fn change(at: Point2<f64>) -> Vertex {
    Vertex {
        at,
        mark: Some(CHANGE),
        free: None,
        image: None,
        room: 0.0,
    }
}

/// Where [`Chords::hides`] takes a chord of two free ends for one that may
/// hide a stretch of the other class: an end's circle point within this
/// many times the chord's span (the circle plane: the reach of the chord's
/// own branch; the center plane: the distance of its ends' circle points)
/// of a Filemon line. In the circle plane this is sure: each half of the
/// double wedge is convex, so a curve within `reach` of a chord whose ends
/// are farther than `reach` inside one half stays inside it. In the center
/// plane the circle points of the chord's stretch are only known at its
/// ends. Measured on the fuzz inputs `free-chord-of-two-free-ends-hides-*`:
/// the curve crosses an extreme line and back within one chord of two free
/// ends, next to `C1`, an arc end or a pair of meets lost to rounding.
const HIDDEN: f64 = 1.0;

/// The free arcs of polylines whose marked vertices (`Some(index)`) are
/// the only places where the label can change: each polyline is cut at its
/// marks into pieces, a piece is labelled by the majority of its vertices
/// between the marks (a piece whose labels disagree, where a change was not
/// marked, is cut where they change, as [`split_by`] does), and
/// consecutive free pieces are joined except at the mark `never` (never
/// free), also around a closed polyline. The vertices' labels are those
/// they carry (classified once, by [`resolve_changes`]).
fn free_pieces(lines: &[Vec<Vertex>], never: usize) -> Vec<Vec<Point2<f64>>> {
    let mut out = Vec::new();
    for line in lines {
        if line.len() < 2 {
            continue;
        }
        // Cut at the marks.
        let mut pieces: Vec<&[Vertex]> = Vec::new();
        let mut start = 0;
        for i in 1..line.len() {
            if line[i].mark.is_some() || i + 1 == line.len() {
                pieces.push(&line[start..=i]);
                start = i;
            }
        }
        // Each piece's runs of one label; `joins` tells whether a run may
        // be joined to the run before it (they meet at a mark other than
        // `never`).
        let mut runs: Vec<(bool, Vec<Point2<f64>>, bool)> = Vec::new();
        for piece in pieces {
            let labels: Vec<Option<bool>> = piece
                .iter()
                .enumerate()
                .filter(|(j, v)| v.mark.is_none() || (*j != 0 && *j + 1 != piece.len()))
                .map(|(_, v)| v.free)
                .collect();
            let joinable = piece[0].mark.is_some_and(|k| k != never);
            let (yes, no) = labels.iter().fold((0, 0), |(y, n), l| match l {
                Some(true) => (y + 1, n),
                Some(false) => (y, n + 1),
                None => (y, n),
            });
            let points: Vec<Point2<f64>> = piece.iter().map(|v| v.at).collect();
            if yes + no == labels.len() && (yes == 0 || no == 0) && !labels.is_empty() {
                runs.push((yes > 0, points, joinable));
            } else {
                // Labels disagree or are missing: cut where they change.
                let cuts: Vec<Point2<f64>> = piece
                    .iter()
                    .filter(|v| v.mark.is_some())
                    .map(|v| v.at)
                    .collect();
                // A mark at an end takes the label of its neighbour.
                let n = piece.len();
                let label_at = |j: usize| -> Option<bool> {
                    let j = if piece[j].mark.is_some() && n > 2 {
                        if j == 0 { 1 } else { n - 2 }
                    } else {
                        j
                    };
                    piece[j].free
                };
                // The labels by the points' bits (a lookup, not a search: a
                // piece may have a million vertices).
                let all: std::collections::HashMap<(u64, u64), Option<bool>> = (0..n)
                    .map(|j| {
                        let p = piece[j].at;
                        ((p.x.to_bits(), p.y.to_bits()), label_at(j))
                    })
                    .collect();
                let split = split_by(&[points], &cuts, |p| {
                    all.get(&(p.x.to_bits(), p.y.to_bits())).copied().flatten()
                });
                // A free run ends at a vertex or a mark, never at the middle
                // of a chord where an unmarked change was cut: the change is
                // somewhere on that chord, so half of it may be defective (a
                // tiny oval of a nearly singular curve that crosses an
                // extreme line where the arc ends do not resolve it).
                let exact = |p: &Point2<f64>| {
                    all.contains_key(&(p.x.to_bits(), p.y.to_bits())) || cuts.contains(p)
                };
                for (i, (l, mut pts)) in split.into_iter().enumerate() {
                    if l {
                        if pts.last().is_some_and(|p| !exact(p)) {
                            pts.pop();
                        }
                        if pts.first().is_some_and(|p| !exact(p)) {
                            pts.remove(0);
                        }
                        if pts.len() < 2 {
                            continue;
                        }
                    }
                    runs.push((l, pts, i == 0 && joinable));
                }
            }
        }
        // Join free runs that meet at a mark other than `never`.
        let mut joined: Vec<Vec<Point2<f64>>> = Vec::new();
        let mut open: Option<Vec<Point2<f64>>> = None;
        for (is_free, pts, joins) in runs {
            match (&mut open, is_free) {
                (Some(cur), true) if joins && cur.last() == pts.first() => {
                    cur.extend(pts.into_iter().skip(1));
                }
                (_, true) => {
                    if let Some(done) = open.take() {
                        joined.push(done);
                    }
                    open = Some(pts);
                }
                (_, false) => {
                    if let Some(done) = open.take() {
                        joined.push(done);
                    }
                }
            }
        }
        if let Some(done) = open {
            joined.push(done);
        }
        // Around a closed polyline: the last free run goes on into the
        // first when they meet at the polyline's start (not a mark, or a
        // mark other than `never`).
        let closed = line[0].at == line[line.len() - 1].at;
        let start_ok = line[0].mark.is_none_or(|k| k != never);
        if closed && start_ok && joined.len() >= 2 {
            let first_at_start = joined[0].first() == Some(&line[0].at);
            let last_at_end = joined[joined.len() - 1].last() == Some(&line[0].at);
            if first_at_start && last_at_end {
                let first = joined.remove(0);
                if let Some(last) = joined.last_mut() {
                    last.extend(first.into_iter().skip(1));
                }
            }
        }
        out.extend(joined);
    }
    out.retain(|l| l.len() >= 2);
    out
}
