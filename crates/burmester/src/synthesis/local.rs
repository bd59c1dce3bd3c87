//! The motion of `n` poses relative to pose 1 in a local frame, and the
//! linear form of the dyad condition, for the four- and five-pose synthesis
//! ([`crate::synthesis::four`], [`crate::synthesis::five`]).
//!
//! Everything works from the poses alone: with
//! `D_1k(z) = R_k z + t_k`, `R_k = e^{i theta_1k}`, `t_k = p_k - R_k p_1`, a
//! dyad (center point `G`, circle point `z` at pose 1) passes pose `k` when
//! `|D_1k(z) - G| = |z - G|`, which expands (the `|z|^2` and `|G|^2` terms
//! cancel) to one equation linear in `z` for fixed `G`, and linear in `G`
//! for fixed `z`:
//!
//! ```text
//! a_k(G) . z = b_k(G),   a_k(G) = conj(R_k) t_k + (1 - conj(R_k)) G,   b_k(G) = t_k . G - |t_k|^2 / 2
//! ```
//!
//! No pole appears, so a pure translation between two poses needs no
//! special case. Three poses give one circle point per center point (the
//! maps of [`crate::Task`]); four give the cubic curves of
//! [`FourPositions`](crate::synthesis::FourPositions); five give the
//! finitely many Burmester points of
//! [`FivePositions`](crate::synthesis::FivePositions).
//!
//! All the arithmetic runs in a local frame (origin the centroid of the
//! pose points, unit their largest distance from it), so results move,
//! turn and scale with the task.

// Comparisons are written `!(a > b)` on purpose: a NaN takes the failing
// branch.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::geom::dd::{Cdd, Dd, cmul, conj, csub, norm2};
use core::ops::{Add, Mul};

use nalgebra::{Point2, Vector2};

use super::errors;
use crate::error::Result;
use crate::geom::{LocalFrame, PerPose, Pose, cross, perp, rotate_cs, wrap_angle};
use crate::synthesis::Task;
use crate::tolerance;

/// The six orders of three rows, the even ones first (a 3x3 determinant's
/// terms).
#[rustfmt::skip]
const PERMS: [[usize; 3]; 6] = [[0, 1, 2], [1, 2, 0], [2, 0, 1], [0, 2, 1], [2, 1, 0], [1, 0, 2]];

/// Why a row solve has no unique answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Failure {
    /// The rows are parallel but inconsistent: the answer is at infinity,
    /// along this unit direction (up to sign).
    AtInfinity(Vector2<f64>),
    /// The rows are parallel and consistent (or all zero): a whole line
    /// of answers.
    Undefined,
}

/// The displacements `D_1k(z) = R_k z + t_k` of a motion (local frame),
/// index 0 the identity, and the linear form of the dyad condition:
///
/// ```text
/// |D_1k(z) - g| = |z - g|   <=>   a_k(g) . z = b_k(g)
/// a_k(g) = conj(R_k) t_k + (1 - conj(R_k)) g,    b_k(g) = t_k . g - |t_k|^2 / 2
/// ```
///
/// (complex products, read as 2-vectors). It is linear in `z` for fixed
/// `g` and linear in `g` for fixed `z`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LinearForm {
    /// `(cos, sin)` of the rotation of each displacement.
    rot: PerPose<(f64, f64)>,
    /// The translation `t_k` of each displacement.
    trans: PerPose<Vector2<f64>>,
}

/// An affine polynomial `[c, x, y]` of the plane.
type Affine = [f64; 3];

impl LinearForm {
    /// `D_1k(z) = R_k z + t_k` (0-based `k`).
    pub(crate) fn displace(&self, k: usize, z: Vector2<f64>) -> Vector2<f64> {
        let (c, s) = self.rot[k];
        rotate_cs(z, c, s) + self.trans[k]
    }

    /// `(conj(R_k) t_k, (1 - cos, sin))`: the constant of `a_k` and the
    /// complex factor `1 - conj(R_k)` of `g`.
    fn parts(&self, k: usize) -> (Vector2<f64>, (f64, f64)) {
        let (c, s) = self.rot[k];
        let t = self.trans[k];
        (rotate_cs(t, c, -s), (1.0 - c, s))
    }

    /// Row `k` (0-based, `k >= 1`) at `g`: `(a_k(g), b_k(g))`.
    pub(crate) fn row(&self, k: usize, g: Vector2<f64>) -> (Vector2<f64>, f64) {
        let (ck, (mr, mi)) = self.parts(k);
        let t = self.trans[k];
        let a = ck + Vector2::new(mr * g.x - mi * g.y, mi * g.x + mr * g.y);
        (a, t.dot(&g) - 0.5 * t.norm_squared())
    }

    /// The derivative of `a_k(g) . z - b_k(g)` with respect to `g`:
    /// `conj(1 - conj(R_k)) z - t_k`.
    pub(crate) fn row_dg(&self, k: usize, z: Vector2<f64>) -> Vector2<f64> {
        let (_, (mr, mi)) = self.parts(k);
        Vector2::new(mr * z.x + mi * z.y, mr * z.y - mi * z.x) - self.trans[k]
    }

    /// Row `k` as affine polynomials in `g`: `[a_x, a_y, b]`.
    fn row_poly(&self, k: usize) -> [Affine; 3] {
        let (ck, (mr, mi)) = self.parts(k);
        let t = self.trans[k];
        [
            [ck.x, mr, -mi],
            [ck.y, mi, mr],
            [-0.5 * t.norm_squared(), t.x, t.y],
        ]
    }

    /// The exact expansion of `det [a_i b_i; a_j b_j; a_k b_k]` as a cubic in
    /// `g` (ascending coefficients, as [`crate::geom::Cubic::new`]), and the
    /// largest coefficient of the same expansion with every number replaced
    /// by its magnitude (the scale of its rounding and of a vanishing
    /// determinant).
    pub(crate) fn cubic(&self, rows: [usize; 3]) -> ([f64; 10], f64) {
        let (out, mag) = self.cubic_bounds(rows);
        (out, mag.iter().fold(0.0, |m: f64, v| m.max(*v)))
    }

    /// The exact expansion of [`cubic`](Self::cubic) and, per coefficient,
    /// the same expansion with every number replaced by its magnitude: the
    /// scale of that coefficient's rounding (of the rows from the poses
    /// and of the expansion), in the same units.
    pub(crate) fn cubic_bounds(&self, rows: [usize; 3]) -> ([f64; 10], [f64; 10]) {
        let r = rows.map(|k| self.row_poly(k));
        let ra = r.map(|row| row.map(|p| p.map(f64::abs)));
        let mut out = [0.0; 10];
        let mut mag = [0.0; 10];
        const PERMS: [([usize; 3], f64); 6] = [
            ([0, 1, 2], 1.0),
            ([1, 2, 0], 1.0),
            ([2, 0, 1], 1.0),
            ([0, 2, 1], -1.0),
            ([2, 1, 0], -1.0),
            ([1, 0, 2], -1.0),
        ];
        for (p, sign) in PERMS {
            let term = mul3(&mul2(&r[0][p[0]], &r[1][p[1]]), &r[2][p[2]]);
            let bound = mul3(&mul2(&ra[0][p[0]], &ra[1][p[1]]), &ra[2][p[2]]);
            for i in 0..10 {
                out[i] += sign * term[i];
                mag[i] += bound[i];
            }
        }
        (out, mag)
    }

    /// A first-order bound, per coefficient, on the change of the expansion
    /// of [`cubic`](Self::cubic) when the poses' positions move by up to
    /// `dp` (local units) and their angles by up to `da` (radians), over
    /// `eps`-sized changes: the inputs' own rounding carried through the
    /// determinant (a point's coordinates are known to half an ulp, so a
    /// task far from the origin for its size is known only that well in
    /// its own frame).
    pub(crate) fn cubic_data_bounds(
        &self,
        rows: [usize; 3],
        q1: Vector2<f64>,
        dp: f64,
        da: f64,
    ) -> [f64; 10] {
        let r = rows.map(|k| self.row_poly(k));
        let ra = r.map(|row| row.map(|p| p.map(f64::abs)));
        // The change of each entry: `t_k = q_k - R_k q_1` by `2 dp + da |q_1|`,
        // `conj(R_k) t_k` by that and `da |t_k|`, the rotation parts by `da`.
        let err = rows.map(|k| {
            let t = self.trans[k].norm();
            let et = 2.0 * dp + da * q1.norm();
            let eck = et + da * t;
            [[eck, da, da], [eck, da, da], [t * et, et, et]]
        });
        let mut out = [0.0; 10];
        for p in PERMS {
            let (a, b, c) = (ra[0][p[0]], ra[1][p[1]], ra[2][p[2]]);
            let (ea, eb, ec) = (err[0][p[0]], err[1][p[1]], err[2][p[2]]);
            for term in [
                mul3(&mul2(&ea, &b), &c),
                mul3(&mul2(&a, &eb), &c),
                mul3(&mul2(&a, &b), &ec),
            ] {
                for i in 0..10 {
                    out[i] += term[i];
                }
            }
        }
        out
    }

    /// How well `g` (local) solves the rows `ks` with the circle point of
    /// their best conditioned pair: the largest residual `a_k(g) . z -
    /// b_k(g)` over the bound on its terms in units of `eps` (the rows'
    /// entries, `z`, and `g` itself known to `dg` plus its own rounding,
    /// local units over `eps`, through the rows' derivative). `None` where
    /// the rows have no unique circle point.
    pub(crate) fn consistency(&self, g: Vector2<f64>, ks: &[usize], dg: f64) -> Option<f64> {
        let z = self.solve(g, ks).ok()?;
        let mut worst = 0.0f64;
        for &k in ks {
            let (ck, (mr, mi)) = self.parts(k);
            let t = self.trans[k];
            let (a, b) = self.row(k, g);
            let (gx, gy) = (g.x.abs(), g.y.abs());
            let ax = ck.x.abs() + mr.abs() * gx + mi.abs() * gy;
            let ay = ck.y.abs() + mi.abs() * gx + mr.abs() * gy;
            let bound = ax * z.x.abs()
                + ay * z.y.abs()
                + t.x.abs() * gx
                + t.y.abs() * gy
                + 0.5 * t.norm_squared()
                + self.row_dg(k, z).norm() * (g.norm() + dg);
            let r = (a.dot(&z) - b).abs() / (f64::EPSILON * bound);
            worst = worst.max(if r.is_nan() { f64::INFINITY } else { r });
        }
        Some(worst)
    }

    /// The form of the inverted motion (the ground seen from the coupler
    /// at pose 1): `D_1k^-1(w) = conj(R_k) w - conj(R_k) t_k`.
    pub(crate) fn inverse(&self) -> LinearForm {
        LinearForm {
            rot: self.rot.map(|(c, s)| (c, -s)),
            trans: PerPose::from_fn(self.rot.len(), |k| {
                let (c, s) = self.rot[k];
                -rotate_cs(self.trans[k], c, -s)
            }),
        }
    }

    /// The `z` with `a_k(g) . z = b_k(g)` for the rows `ks`, from the pair
    /// of rows with the largest determinant (the best conditioned).
    pub(crate) fn solve(&self, g: Vector2<f64>, ks: &[usize]) -> Result<Vector2<f64>, Failure> {
        let rows: Vec<(Vector2<f64>, f64)> = ks.iter().map(|&k| self.row(k, g)).collect();
        solve_rows(&rows)
    }

    /// The limit of [`solve`](Self::solve) as `g` goes to infinity in the
    /// direction `u` (a unit vector): the rows divided by `|g|` tend to
    /// `(1 - conj(R_k)) u . z = t_k . u`. Where `u` is an asymptotic
    /// direction of the center-point curve they are consistent, and `z` is
    /// the circle point of the dyad whose center is at infinity (a slider).
    pub(crate) fn solve_at_infinity(
        &self,
        u: Vector2<f64>,
        ks: &[usize],
    ) -> Result<Vector2<f64>, Failure> {
        let rows: Vec<(Vector2<f64>, f64)> = ks
            .iter()
            .map(|&k| {
                let (_, (mr, mi)) = self.parts(k);
                let a = Vector2::new(mr * u.x - mi * u.y, mi * u.x + mr * u.y);
                (a, self.trans[k].dot(&u))
            })
            .collect();
        solve_rows(&rows)
    }
}

/// The `z` with `a . z = b` for the rows `(a, b)`, from the pair of rows
/// with the largest determinant (the best conditioned).
fn solve_rows(rows: &[(Vector2<f64>, f64)]) -> Result<Vector2<f64>, Failure> {
    let (mut best, mut pair) = (-1.0, (0, 0));
    for i in 0..rows.len() {
        for j in i + 1..rows.len() {
            let d = cross(rows[i].0, rows[j].0).abs();
            if d > best {
                best = d;
                pair = (i, j);
            }
        }
    }
    let (r, amax) = rows
        .iter()
        .map(|(a, _)| a.norm())
        .enumerate()
        .fold((0, 0.0), |acc, (i, n)| if n > acc.1 { (i, n) } else { acc });
    if !(amax > 0.0) || !amax.is_finite() {
        return Err(Failure::Undefined);
    }
    if !(best > 64.0 * f64::EPSILON * amax * amax) {
        // Parallel rows: consistent (a line of answers) or not (at infinity).
        let (ar, br) = rows[r];
        let inconsistent = rows.iter().any(|(a, b)| {
            let lam = a.dot(&ar) / (amax * amax);
            (b - lam * br).abs() > 1e-9 * (b.abs() + (lam * br).abs()) + f64::MIN_POSITIVE
        });
        return Err(if inconsistent {
            Failure::AtInfinity(perp(ar / amax))
        } else {
            Failure::Undefined
        });
    }
    let ((ai, bi), (aj, bj)) = (rows[pair.0], rows[pair.1]);
    let det = cross(ai, aj);
    let z = Vector2::new(bi * aj.y - bj * ai.y, ai.x * bj - aj.x * bi) / det;
    if z.iter().all(|v| v.is_finite()) {
        Ok(z)
    } else {
        Err(Failure::AtInfinity(perp(ai / ai.norm())))
    }
}

/// `e^{i phi}` as a double-double, its real part `1 - 2 sin^2(phi / 2)`
/// (so that `e^{i phi} - 1` keeps its digits for a small `phi`).
fn unit_dd(phi: f64) -> Cdd {
    let h = (0.5 * phi).sin();
    (Dd::sum(1.0, -2.0 * h * h), Dd::of(phi.sin()))
}

impl LocalMotion {
    /// The local position of pose `k`, `(p_k - origin) / scale`, in
    /// double-double (the difference exact, the quotient to about 106 bits).
    pub(crate) fn position_dd(&self, k: usize) -> Cdd {
        let p = self.poses[k].position;
        (
            Dd::sum(p.x, -self.origin.x).div(self.scale),
            Dd::sum(p.y, -self.origin.y).div(self.scale),
        )
    }

    /// The center-point cubic (`inverse == false`) or the circle-point
    /// cubic of the first four poses: the expansion of
    /// [`LinearForm::cubic`] (rows 2, 3, 4), accurate to what the poses
    /// allow. The rows' entries are formed in double-double arithmetic from
    /// the poses themselves (the local positions `(p_k - origin) / scale`,
    /// each rotation `R_k` a product along a chain of the poses, nearest
    /// angles first, of `e^{i (a_k - a_j)}`, so that two nearly equal
    /// angles give rotations whose difference keeps its digits), and the
    /// determinant is expanded in double-double: near a degenerate task
    /// (poses at nearly one position and angle) the expansion cancels
    /// most of its terms' digits, which the plain one
    /// ([`LinearForm::cubic_bounds`]) then loses (`2e-8` of the largest
    /// coefficient where the poses allow `1e-15`).
    pub(crate) fn curve_cubic(&self, inverse: bool) -> [f64; 10] {
        const N: usize = 4;
        debug_assert!(self.poses.len() >= N);
        let pos: [Cdd; N] = core::array::from_fn(|k| self.position_dd(k));
        // The rotations from pose 1, along the chain of nearest angles.
        let angle = |k: usize| self.poses[k].angle;
        let mut rot: [Option<Cdd>; N] = [None; N];
        rot[0] = Some((Dd::of(1.0), Dd::ZERO));
        for _ in 1..N {
            let mut best: Option<(f64, usize, usize)> = None;
            for k in (0..N).filter(|&k| rot[k].is_none()) {
                for j in (0..N).filter(|&j| rot[j].is_some()) {
                    let d = wrap_angle(angle(k) - angle(j)).abs();
                    if best.is_none_or(|(b, ..)| d < b) {
                        best = Some((d, j, k));
                    }
                }
            }
            let Some((_, j, k)) = best else { break };
            rot[k] = rot[j].map(|r| cmul(r, unit_dd(angle(k) - angle(j))));
        }
        let rot = rot.map(|r| r.unwrap_or((Dd::of(f64::NAN), Dd::of(f64::NAN))));
        // `t_k = q_k - R_k q_1`; the inverted motion's rotation is
        // `conj(R_k)` and its translation `-conj(R_k) t_k`.
        let disp: [(Cdd, Cdd); N] = core::array::from_fn(|k| {
            let t = csub(pos[k], cmul(rot[k], pos[0]));
            if inverse {
                let ct = cmul(conj(rot[k]), t);
                (conj(rot[k]), (ct.0.neg(), ct.1.neg()))
            } else {
                (rot[k], t)
            }
        });
        // Row k as affine polynomials in `g` (as `LinearForm::row_poly`).
        let row = |k: usize| -> [[Dd; 3]; 3] {
            let (r, t) = disp[k];
            let ck = cmul(conj(r), t);
            let (mr, mi) = (Dd::of(1.0).sub(r.0), r.1);
            let half = norm2(t).mul(Dd::of(-0.5));
            [[ck.0, mr, mi.neg()], [ck.1, mi, mr], [half, t.0, t.1]]
        };
        let r = [row(1), row(2), row(3)];
        let mut out = [Dd::ZERO; 10];
        for (p, sign) in PERMS.iter().zip([1.0, 1.0, 1.0, -1.0, -1.0, -1.0]) {
            let term = mul3(&mul2(&r[0][p[0]], &r[1][p[1]]), &r[2][p[2]]);
            for i in 0..10 {
                out[i] = out[i].add(Dd {
                    hi: sign * term[i].hi,
                    lo: sign * term[i].lo,
                });
            }
        }
        out.map(|v| v.hi + v.lo)
    }
}

/// `p q` for affine `p`, `q`: a quadratic `[1, x, y, x^2, xy, y^2]` (in
/// doubles, or double-doubles for [`LocalMotion::curve_cubic`]).
fn mul2<T: Copy + Add<Output = T> + Mul<Output = T>>(p: &[T; 3], q: &[T; 3]) -> [T; 6] {
    [
        p[0] * q[0],
        p[0] * q[1] + p[1] * q[0],
        p[0] * q[2] + p[2] * q[0],
        p[1] * q[1],
        p[1] * q[2] + p[2] * q[1],
        p[2] * q[2],
    ]
}

/// `q a` for a quadratic `q` and an affine `a`: a cubic, ascending (the
/// terms of each degree on one line).
#[rustfmt::skip]
fn mul3<T: Copy + Add<Output = T> + Mul<Output = T>>(q: &[T; 6], a: &[T; 3]) -> [T; 10] {
    [
        q[0] * a[0],
        q[0] * a[1] + q[1] * a[0], q[0] * a[2] + q[2] * a[0],
        q[1] * a[1] + q[3] * a[0], q[1] * a[2] + q[2] * a[1] + q[4] * a[0], q[2] * a[2] + q[5] * a[0],
        q[3] * a[1], q[3] * a[2] + q[4] * a[1], q[4] * a[2] + q[5] * a[1], q[5] * a[2],
    ]
}

/// `n` poses, validated, in a local frame (origin the centroid of the pose
/// points, unit their largest distance from it), with the linear form.
// Inline, not on the heap: a task keeps its curves or points (and so this)
// and stays `Copy`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LocalMotion {
    pub(crate) poses: PerPose<Pose>,
    pub(crate) origin: Point2<f64>,
    pub(crate) scale: f64,
    /// The pose points in the local frame.
    pub(crate) pos: PerPose<Vector2<f64>>,
    /// `theta_1k`, wrapped into `(-pi, pi]`.
    pub(crate) theta: PerPose<f64>,
    pub(crate) form: LinearForm,
    /// How far the poses' own rounding may move them in this frame, over
    /// `eps`: their positions (local units) and their angles (radians).
    pub(crate) data_rounding: (f64, f64),
}

crate::geom::local_frame!(LocalMotion);

/// The first two poses (0-based) whose points agree within `tol` times
/// `scale` and whose angles within `tol` radians (modulo `2 pi`), if any.
pub(crate) fn close_pair(poses: &[Pose], scale: f64, tol: f64) -> Option<(usize, usize)> {
    let n = poses.len();
    (0..n)
        .flat_map(|i| (i + 1..n).map(move |j| (i, j)))
        .find(|&(i, j)| {
            let d = (poses[j].position - poses[i].position).norm();
            let a = wrap_angle(poses[j].angle - poses[i].angle).abs();
            d <= tol * scale && a <= tol
        })
}

impl LocalMotion {
    /// The motion of two to five `poses` that passed the one check of the
    /// poses ([`check_poses`](crate::synthesis::task::check_poses): finite,
    /// within the task's bounds).
    ///
    /// # Errors
    ///
    /// What the local frame itself needs: two poses that coincide within
    /// [`tolerance::COINCIDENT_POSES`], poses all at one point, or a frame
    /// smaller than [`Task::MIN_SCALE`].
    pub(crate) fn new(poses: &[Pose]) -> Result<Self> {
        debug_assert!((2..=crate::geom::MAX_POSES).contains(&poses.len()));
        let n = poses.len() as f64;
        let origin = Point2::from(
            poses
                .iter()
                .fold(Vector2::zeros(), |acc, p| acc + p.position.coords / n),
        );
        let scale = poses
            .iter()
            .map(|p| (p.position - origin).norm())
            .fold(0.0, f64::max);
        if let Some((i, j)) = close_pair(poses, scale, tolerance::COINCIDENT_POSES) {
            return Err(errors::coincident_poses(i + 1, j + 1));
        }
        if scale == 0.0 {
            return Err(errors::common_pole(origin));
        }
        if scale < Task::MIN_SCALE {
            return Err(errors::too_small(scale, Task::MIN_SCALE));
        }
        let poses = PerPose::from_slice(poses);
        let pos = poses.map(|p| (p.position - origin) / scale);
        let theta = poses.map(|p| wrap_angle(p.angle - poses[0].angle));
        let rot = theta.map(|t| {
            let (s, c) = t.sin_cos();
            (c, s)
        });
        let trans = PerPose::from_fn(poses.len(), |k| {
            let (c, s) = rot[k];
            pos[k] - rotate_cs(pos[0], c, s)
        });
        let far = poses
            .iter()
            .map(|p| p.position.x.abs().max(p.position.y.abs()))
            .fold(0.0, f64::max);
        let turn = poses.iter().map(|p| p.angle.abs()).fold(0.0, f64::max);
        Ok(LocalMotion {
            poses,
            origin,
            scale,
            pos,
            theta,
            form: LinearForm { rot, trans },
            data_rounding: (far / scale, 2.0 * turn),
        })
    }

    /// Three poses (0-based) of one angle (within
    /// [`tolerance::COINCIDENT_POSES`]) whose positions lie on a line (within
    /// [`crate::tolerance::COLLINEAR`]), if any: every dyad through them is
    /// a slider (its moving pivot's three positions are collinear), so no
    /// finite center point passes them and the center-point curve is the
    /// line at infinity, twice, and a line of centers at infinity.
    pub(crate) fn collinear_translations(&self) -> Option<[usize; 3]> {
        let n = self.poses.len();
        let same = |a: usize, b: usize| {
            wrap_angle(self.theta[a] - self.theta[b]).abs() <= tolerance::COINCIDENT_POSES
        };
        for i in 0..n {
            for j in i + 1..n {
                for k in j + 1..n {
                    if same(i, j) && same(i, k) {
                        let (u, v) = (self.pos[j] - self.pos[i], self.pos[k] - self.pos[i]);
                        let longest = u.norm_squared().max(v.norm_squared());
                        if cross(u, v).abs() <= crate::tolerance::COLLINEAR * longest {
                            return Some([i, j, k]);
                        }
                    }
                }
            }
        }
        None
    }

    /// `D_ij(z) = p_j + e^{i theta_ij} (z - p_i)` in the fixed frame
    /// (0-based `i`, `j`).
    pub(crate) fn displace(&self, z: Point2<f64>, i: usize, j: usize) -> Point2<f64> {
        let (pi, pj) = (&self.poses[i], &self.poses[j]);
        let (s, c) = wrap_angle(pj.angle - pi.angle).sin_cos();
        pj.position + rotate_cs(z - pi.position, c, s)
    }

    /// The pole `P_jk` (0-based) in homogeneous local coordinates
    /// `[X, Y, W]` (unit length):
    ///
    /// ```text
    /// P_jk = [ sin(theta/2) (q_j + q_k)/2 + cos(theta/2) i (q_k - q_j)/2 ,  sin(theta/2) ]
    /// ```
    ///
    /// `W = 0` for a pure translation (a pole at infinity, perpendicular to
    /// the translation).
    pub(crate) fn pole(&self, j: usize, k: usize) -> [f64; 3] {
        let th = wrap_angle(self.theta[k] - self.theta[j]);
        let (s, c) = (0.5 * th).sin_cos();
        let mid = (self.pos[j] + self.pos[k]) * 0.5;
        let d = (self.pos[k] - self.pos[j]) * 0.5;
        let xy = mid * s + perp(d) * c;
        unit3([xy.x, xy.y, s])
    }

    /// A homogeneous local point in the fixed frame, `None` at infinity
    /// (or when it is not representable).
    pub(crate) fn dehomogenize(&self, h: [f64; 3]) -> Option<Point2<f64>> {
        if h[2] == 0.0 {
            return None;
        }
        let p = self.global_of(Vector2::new(h[0] / h[2], h[1] / h[2]));
        (p.x.is_finite() && p.y.is_finite()).then_some(p)
    }
}

/// `a x b` for homogeneous points or lines.
pub(crate) fn cross3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    unit3([
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ])
}

/// `h` scaled to unit length (unchanged when zero).
fn unit3(h: [f64; 3]) -> [f64; 3] {
    let m = h.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if !(m > 0.0) || !m.is_finite() {
        return h;
    }
    let h = h.map(|v| v / m);
    let n = (h[0] * h[0] + h[1] * h[1] + h[2] * h[2]).sqrt();
    h.map(|v| v / n)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn motion() -> LocalMotion {
        LocalMotion::new(&[
            Pose::new(1.0, 2.0, 0.3),
            Pose::new(2.5, 1.0, 0.9),
            Pose::new(0.5, -1.0, -0.4),
            Pose::new(-1.0, 0.2, 1.7),
        ])
        .unwrap()
    }

    #[test]
    fn rows_state_the_dyad_condition() {
        let m = motion();
        let g = Vector2::new(0.3, -0.7);
        for z in [Vector2::new(0.1, 0.2), Vector2::new(-2.0, 1.5)] {
            for k in 1..4 {
                let (a, b) = m.form.row(k, g);
                let lhs = (m.form.displace(k, z) - g).norm_squared() - (z - g).norm_squared();
                assert!((lhs - 2.0 * (a.dot(&z) - b)).abs() < 1e-13, "{lhs}");
                // The g-derivative.
                let e = |g: Vector2<f64>| {
                    let (a, b) = m.form.row(k, g);
                    a.dot(&z) - b
                };
                let h = 1e-6;
                let num = Vector2::new(
                    (e(g + Vector2::x() * h) - e(g - Vector2::x() * h)) / (2.0 * h),
                    (e(g + Vector2::y() * h) - e(g - Vector2::y() * h)) / (2.0 * h),
                );
                assert!((num - m.form.row_dg(k, z)).norm() < 1e-8);
            }
        }
    }

    #[test]
    fn the_cubic_is_the_determinant() {
        let m = motion();
        let (c, mag) = m.form.cubic([1, 2, 3]);
        assert!(mag > 0.0);
        for g in [Vector2::new(0.3, -0.7), Vector2::new(2.0, 1.0)] {
            let r: Vec<_> = (1..4).map(|k| m.form.row(k, g)).collect();
            let det = r[0].0.x * (r[1].0.y * r[2].1 - r[2].0.y * r[1].1)
                - r[0].0.y * (r[1].0.x * r[2].1 - r[2].0.x * r[1].1)
                + r[0].1 * (r[1].0.x * r[2].0.y - r[2].0.x * r[1].0.y);
            let cubic = crate::geom::Cubic::new(c).unwrap();
            let k = c.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            assert!((cubic.evaluate(Point2::from(g)) * k - det).abs() < 1e-13);
        }
    }

    #[test]
    fn the_accurate_cubic_is_the_plain_one_on_a_moderate_task() {
        let m = motion();
        for inverse in [false, true] {
            let form = if inverse { m.form.inverse() } else { m.form };
            let (plain, mag) = form.cubic([1, 2, 3]);
            let accurate = m.curve_cubic(inverse);
            for (a, b) in accurate.iter().zip(plain) {
                assert!((a - b).abs() <= 1e-14 * mag, "{accurate:?} {plain:?}");
            }
        }
        // The double-double parts: a product and a sum kept exactly.
        let p = Dd::prod(1.0 + f64::EPSILON, 1.0 - f64::EPSILON);
        assert_eq!((p.hi, p.lo), (1.0, -f64::EPSILON * f64::EPSILON));
        let s = Dd::sum(1.0, 1e-30);
        assert_eq!((s.hi, s.lo), (1.0, 1e-30));
        assert!(
            Dd::of(1.0)
                .div(3.0)
                .mul(Dd::of(3.0))
                .sub(Dd::of(1.0))
                .hi
                .abs()
                < 1e-31
        );
    }

    #[test]
    fn poles_are_fixed_points() {
        let m = motion();
        for j in 0..4 {
            for k in j + 1..4 {
                let p = m.dehomogenize(m.pole(j, k)).unwrap();
                assert!((m.displace(p, j, k) - p).norm() < 1e-12);
            }
        }
        // The inverse form undoes the motion.
        let inv = m.form.inverse();
        let z = Vector2::new(0.4, -1.1);
        for k in 0..4 {
            assert!((inv.displace(k, m.form.displace(k, z)) - z).norm() < 1e-14);
        }
    }
}
