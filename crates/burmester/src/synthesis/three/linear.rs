//! The three-position maps from the linear form, for tasks with a pure
//! translation between two poses (a pole at infinity) or a pole far from
//! the poses (a small rotation).
//!
//! # Why a second path
//!
//! [`Cremona`](super::Cremona) writes the maps through the poles (Borm &
//! Kim's closed form). That form is fast, its results are what the tests
//! and the reference pictures of tasks with finite poles are made of, bit
//! for bit, and the dense solution maps depend on its speed; but it needs
//! all three poles finite, and it is well conditioned only where `P12` and
//! `P13` lie near the poses: a pole `D` away (a rotation of about
//! `span / D`) costs it a factor of about `D / span` in relative accuracy,
//! which it cancels away. When two poses differ by a pure translation (one
//! pole at infinity), or `P12` or `P13` lies farther than
//! [`tolerance::POLE_DISTANCE`] spans from pose 1, the task uses this form
//! instead, which keeps the accuracy the input allows at every rotation.
//! The two give the same points up to rounding where both apply (the
//! crate's tests compare them across the switch).
//!
//! # The linear form (Sandor & Erdman, *Advanced Mechanism Design*)
//!
//! With `D_1k(z) = R_k z + t_k`, a dyad with center point `G` and circle
//! point `z` passes pose `k` when `|D_1k(z) - G| = |z - G|`. The `|z|^2`
//! and `|G|^2` terms cancel, leaving a condition linear in each point:
//!
//! ```text
//! w_k(G) . z = t_k . G - |t_k|^2 / 2,     w_k(G) = G - D_k1(G)   (k = 2, 3)
//! ```
//!
//! For a point the two rows say that the circle point is the circumcenter
//! of `G, D_21(G), D_31(G)` and the center point the circumcenter of
//! `z, D_12(z), D_13(z)`; written relative to the given point `P`, with
//! `a = E_2(P) - P`, `b = E_3(P) - P`,
//!
//! ```text
//! answer = P + (|b|^2 perp(a) - |a|^2 perp(b)) / (2 cross(a, b))
//! ```
//!
//! No pole appears: a pure translation has `D_k1(G) - G = -t_k`, a
//! constant. The answer is at infinity where `cross(a, b) = 0` (the pole
//! circle, a line through the two finite poles when the third is at
//! infinity) and undefined at a finite pole (a whole line of answers).
//!
//! For Filemon's line through `C1` with direction `d`, the rows
//! `M(G) z = c(G)` (`M` with rows `w_2, w_3`, affine in `G`; `c` affine)
//! give `z = adj(M) c / det M` with `adj(M) c = c_3 perp(w_2) - c_2
//! perp(w_3)` and `det M = cross(w_2, w_3)` both quadratic, so
//!
//! ```text
//! g_d(G) = cross(d, adj(M) c - C1 det M) = c_3 (d . w_2) - c_2 (d . w_3) - cross(d, C1) det M
//! ```
//!
//! is an exact quadratic with `cross(d, z(G) - C1) = g_d(G) / det M`: the
//! transformed curve, written without a pole. The branch test "the two
//! `g` have one sign" divides by nothing.
//!
//! # Numerics
//!
//! Everything runs in a local frame whose origin is a finite pole near the
//! poses (`P12`, or else `P13`, within [`tolerance::POLE_DISTANCE`] spans
//! of pose 1), where `t_k` is exactly zero for that pose, so every
//! transformed curve passes exactly through the origin; when neither is
//! near, pose 1's position (no curve point is known exactly then, but no
//! far origin cancels the digits of the points near the poses). The unit
//! is the task's [`scale`](crate::Task::scale). The rotations are the
//! poses' own (a rotation within [`tolerance::MIN_ROTATION`] is not rounded
//! to zero), so the maps are those of the given poses.

use nalgebra::{Matrix2, Point2, Vector2};

use crate::error::Result;
use crate::geom::{Conic, LocalFrame, cross, normalized, perp, rotate_cs};
use crate::synthesis::motion::{Motion, Pole};
use crate::synthesis::three::cremona::MapDir;
use crate::tolerance;

/// Components beyond this (local units) are scaled down before squaring.
const BIG: f64 = 1e100;

/// The three-position maps of a task of three poses with a pole at
/// infinity, by the linear form (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Linear {
    /// Local frame: origin a finite pole, unit `scale`.
    origin: Point2<f64>,
    scale: f64,
    /// `(cos, sin)` of `theta_12`, `theta_13`.
    rot: [(f64, f64); 2],
    /// `t_2`, `t_3` in the local frame (`D_1k(z) = R_k z + t_k`).
    shift: [Vector2<f64>; 2],
    /// `[P12, P13, P23]`, `None` at infinity (fixed frame).
    poles: [Option<Point2<f64>>; 3],
    /// `[P12, P13, P'23]`, `P'23 = D_21(P23)`, `None` at infinity.
    image_poles: [Option<Point2<f64>>; 3],
    /// The first pair (1-based) whose pole is at infinity; `None` when
    /// the three poles are finite (the form was chosen for a far pole).
    translation: Option<(usize, usize)>,
    /// Whether the origin is a pole (`P12` or `P13`), which every
    /// transformed curve passes through exactly.
    origin_is_pole: bool,
}

crate::geom::local_frame!(Linear);

impl Linear {
    /// The maps of a validated three-pose motion with at least one finite
    /// pole (and a pole at infinity, or one farther than
    /// [`tolerance::POLE_DISTANCE`] spans from pose 1); `scale` is the
    /// task's scale, `span` the largest distance between two pose
    /// positions.
    pub(crate) fn new(motion: Motion, scale: f64, span: f64) -> Self {
        let all = motion.poles();
        let poles = [0, 1, 2].map(|k| all[k].finite());
        let translation = motion
            .pairs()
            .zip(&all)
            .find(|(_, p)| matches!(p, Pole::AtInfinity { .. }))
            .map(|(pair, _)| pair);
        // The origin: P12, else P13, where near the poses (then that row is
        // exactly zero); else pose 1's position (no row is exactly zero
        // there, and no far origin costs the near points their digits).
        let p1 = motion.poses()[0].position;
        let near = |p: Option<Point2<f64>>| {
            p.filter(|q| (q - p1).norm() <= tolerance::POLE_DISTANCE * span)
        };
        let (origin, exact) = match (near(poles[0]), near(poles[1])) {
            (Some(p), _) => (p, 0),
            (None, Some(p)) => (p, 1),
            (None, None) => (p1, 2),
        };
        let rot = [1, 2].map(|k| {
            let (s, c) = motion.rotation0(0, k).sin_cos();
            (c, s)
        });
        let shift = [0, 1].map(|n| {
            if n == exact {
                Vector2::zeros()
            } else {
                (motion.first_to(n + 1, origin) - origin) / scale
            }
        });
        let image_poles = [
            poles[0],
            poles[1],
            poles[2].map(|p| motion.displace0(p, 1, 0)),
        ];
        Linear {
            origin,
            scale,
            rot,
            shift,
            poles,
            image_poles,
            translation,
            origin_is_pole: exact < 2,
        }
    }

    /// `[P12, P13, P23]`, `None` for a pole at infinity.
    pub(crate) fn poles(&self) -> [Option<Point2<f64>>; 3] {
        self.poles
    }

    /// The first pair of poses (1-based) that differ by a pure
    /// translation; `None` when the three poles are finite.
    pub(crate) fn translation(&self) -> Option<(usize, usize)> {
        self.translation
    }

    /// `D_1k(z)` in the local frame (`n = 0, 1` for poses 2, 3).
    #[inline(always)]
    fn forward(&self, n: usize, z: Vector2<f64>) -> Vector2<f64> {
        let (c, s) = self.rot[n];
        rotate_cs(z, c, s) + self.shift[n]
    }

    /// `D_k1(g)` in the local frame (`n = 0, 1` for poses 2, 3).
    #[inline(always)]
    fn backward(&self, n: usize, g: Vector2<f64>) -> Vector2<f64> {
        let (c, s) = self.rot[n];
        rotate_cs(g - self.shift[n], c, -s)
    }

    /// The chords `(a, b)` from a local point to its two images: to
    /// `D_21, D_31` for the circle point of a center point, to `D_12, D_13`
    /// for the center point of a circle point.
    #[inline(always)]
    fn chords(&self, p: Vector2<f64>, dir: MapDir) -> (Vector2<f64>, Vector2<f64>) {
        match dir {
            MapDir::CenterToCircle => (self.backward(0, p) - p, self.backward(1, p) - p),
            MapDir::CircleToCenter => (self.forward(0, p) - p, self.forward(1, p) - p),
        }
    }

    /// The circle point of a center point in the fixed frame, or `None`
    /// where it does not exist or overflows (the solution map's hot path).
    #[inline(always)]
    pub(crate) fn circle_point_fast(&self, center: Point2<f64>) -> Option<Point2<f64>> {
        let g = self.local_of(center);
        let (a, b) = self.chords(g, MapDir::CenterToCircle);
        let den = cross(a, b);
        let n = perp(a) * b.norm_squared() - perp(b) * a.norm_squared();
        let q = self.global_of(g + n / (2.0 * den));
        (q.x.is_finite() && q.y.is_finite() && den != 0.0).then_some(q)
    }

    /// The circle point of a center point (as
    /// [`Cremona::circle_point`](super::Cremona::circle_point)).
    pub(crate) fn circle_point(&self, center: Point2<f64>) -> Result<Point2<f64>> {
        self.map(center, MapDir::CenterToCircle)
    }

    /// The center point of a circle point (as
    /// [`Cremona::center_point`](super::Cremona::center_point)).
    pub(crate) fn center_point(&self, circle: Point2<f64>) -> Result<Point2<f64>> {
        self.map(circle, MapDir::CircleToCenter)
    }

    fn map(&self, p: Point2<f64>, dir: MapDir) -> Result<Point2<f64>> {
        let (what, curve, names, special, labels) = match dir {
            MapDir::CenterToCircle => (
                "circle point",
                "pole circle",
                ["center point x", "center point y"],
                self.poles,
                ["the pole P12", "the pole P13", "the pole P23"],
            ),
            MapDir::CircleToCenter => (
                "center point",
                "image-pole circle",
                ["circle point x", "circle point y"],
                self.image_poles,
                [
                    "the image pole P'12",
                    "the image pole P'13",
                    "the image pole P'23",
                ],
            ),
        };
        let y = super::local_input(
            self,
            names,
            p,
            "pass a point within about 1e300 task sizes (Task::scale) of the poses",
        )?;
        let m = y.x.abs().max(y.y.abs()).max(1.0);
        for (pole, at) in special.iter().zip(labels) {
            if let Some(q) = pole {
                let d = self.local_of(*q) - y;
                if d.x.abs().max(d.y.abs()) <= tolerance::POINT * m {
                    return Err(crate::synthesis::errors::undefined(what, at, p));
                }
            }
        }
        let (mut a, mut b) = self.chords(y, dir);
        // The offset is homogeneous of degree 1 in (a, b): scale far chords.
        let k = a.x.abs().max(a.y.abs()).max(b.x.abs()).max(b.y.abs());
        let k = if k > BIG { k } else { 1.0 };
        a /= k;
        b /= k;
        let den = cross(a, b);
        let n = perp(a) * b.norm_squared() - perp(b) * a.norm_squared();
        let at_infinity = || {
            let d = normalized(if den < 0.0 { -n } else { n }).unwrap_or_else(|| {
                // Both chords along one line: the answer runs off
                // perpendicular to them.
                normalized(perp(a)).unwrap_or_else(Vector2::x)
            });
            crate::synthesis::errors::at_infinity(what, curve, p, d)
        };
        if den.abs() <= tolerance::CROSS_EPS * f64::EPSILON * a.norm() * b.norm() {
            return Err(at_infinity());
        }
        let out = self.global_of(y + n * (k / (2.0 * den)));
        if out.x.is_finite() && out.y.is_finite() {
            Ok(out)
        } else {
            Err(at_infinity())
        }
    }

    /// The exact transform of the line through `c1` with (non-zero)
    /// direction `d` into the center-point plane (module docs), as a conic
    /// in the local frame; it passes exactly through the origin.
    pub(crate) fn line_conic(&self, c1: Point2<f64>, d: Vector2<f64>) -> Conic {
        let dn = normalized(d).unwrap_or_else(Vector2::x);
        // w_k(g) = g - D_k1(g) = W_k g + w0_k with W_k = I - R_k^T,
        // w0_k = R_k^T t_k; c_k(g) = t_k . g + e_k, e_k = -|t_k|^2 / 2.
        let rows = [0, 1].map(|n| {
            let (c, s) = self.rot[n];
            let rt = Matrix2::new(c, s, -s, c);
            let t = self.shift[n];
            (Matrix2::identity() - rt, rt * t, t, -0.5 * t.norm_squared())
        });
        let [(w2, w02, t2, e2), (w3, w03, t3, e3)] = rows;
        // d . w_k = h_k . g + h0_k.
        let (h2, h02) = (w2.transpose() * dn, dn.dot(&w02));
        let (h3, h03) = (w3.transpose() * dn, dn.dot(&w03));
        // cross(a, b) = a^T J b.
        let j = Matrix2::new(0.0, 1.0, -1.0, 0.0);
        let det_k = w2.transpose() * j * w3;
        let det_l = w2.transpose() * j * w03 + w3.transpose() * j.transpose() * w02;
        let det_f = w02.dot(&(j * w03));
        let cdc = cross(dn, self.local_of(c1));
        // g = c_3 (d . w_2) - c_2 (d . w_3) - cross(d, C1) det.
        let k = t3 * h2.transpose() - t2 * h3.transpose() - det_k * cdc;
        let l = h2 * e3 + t3 * h02 - (h3 * e2 + t2 * h03) - det_l * cdc;
        let f = e3 * h02 - e2 * h03 - det_f * cdc;
        let q = [k[(0, 0)], k[(0, 1)] + k[(1, 0)], k[(1, 1)], l.x, l.y, f];
        // The origin is a finite pole when it is P12 or P13 (then f is
        // exactly zero); else no point is known exactly.
        let known = self.origin_is_pole.then(Vector2::zeros);
        Conic::local(q, self.origin, self.scale, known)
    }
}
