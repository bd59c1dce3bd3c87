//! The last correction of a Burmester point: Newton's method on the four
//! circle equations evaluated in double-double from the poses themselves.
//!
//! The elimination and [`super::polish`] work on the linear form's rows,
//! whose entries are rounded from the poses once (`t_k = p_k - R_k p_1`,
//! `1 - conj(R_k)`), and near a degenerate task (poses at nearly one
//! position, angles nearly equal or half a turn apart) those entries have
//! lost most of their digits by cancellation: the point that zeroes the
//! rounded rows lay `1e-6` to `3e-3` of `size + d` from the exact point of
//! the float task, where the rounding of the inputs moves it by thirty to
//! a thousand times less (fuzz/README.md, five38). The residual here is
//! formed from the local positions and rotations in double-double, so
//! that it is the float task's own to far below that rounding; the step
//! (a 4x4 solve in `f64`) only needs to point the right way.

// Comparisons are written `!(a > b)` on purpose: a NaN takes the failing
// branch.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use nalgebra::{Matrix5, Vector2, Vector3, Vector4, Vector5};

use crate::geom::dd::{Cdd, Dd, cmul, conj, csub, norm2};
use crate::synthesis::local::LocalMotion;

/// The rows of the four circle equations of a motion, in double-double
/// from its poses: in the local frame each position `q_k = (p_k - origin)
/// / scale`, each rotation `R_k = e^{i theta_1k}` with `1 - R_k`'s real
/// part `2 sin^2(theta_1k / 2)` (so that it keeps its digits for a small
/// angle), `t_k = q_k - R_k q_1`; row `k` is `a_k(g) . z - b_k(g)` with
/// `a_k(g) = conj(R_k) t_k + (1 - conj(R_k)) g` and `b_k(g) = t_k . g -
/// |t_k|^2 / 2` (`LinearForm`'s, half of `|D_k(z) - g|^2 - |z - g|^2` with
/// the `|z|^2` terms cancelled exactly: a circle point far out, `1e14` task
/// sizes, would otherwise bring `eps |z|^2` from `|R_k| != 1`).
pub(super) struct Accurate {
    /// Per row `k = 2..5`: `conj(R_k) t_k`, `1 - conj(R_k)` as `(1 - cos,
    /// sin)`, `t_k` and `|t_k|^2 / 2`.
    rows: [(Cdd, Cdd, Cdd, Dd); 4],
}

impl Accurate {
    pub(super) fn new(m: &LocalMotion) -> Self {
        let q1 = m.position_dd(0);
        let rows = core::array::from_fn(|r| {
            let k = r + 1;
            let t = m.theta[k];
            let h = (0.5 * t).sin();
            let one_less = Dd::prod(h, h).add(Dd::prod(h, h));
            let rot = (Dd::of(1.0).sub(one_less), Dd::of(t.sin()));
            let tk = csub(m.position_dd(k), cmul(rot, q1));
            let ct = cmul(conj(rot), tk);
            let half = norm2(tk).mul(Dd::of(0.5));
            (ct, (one_less, rot.1), tk, half)
        });
        Accurate { rows }
    }

    /// The four rows at the center `g` and the circle point `z = Z / w`
    /// (local, homogeneous: `|Z|^2 + w^2 = 1`), `a_k(g) . Z - b_k(g) w`,
    /// with the normalisation as a fifth equation, and their Jacobian in
    /// `(g, Z, w)`: `conj(1 - conj(R_k)) Z - t_k w`, `a_k(g)`, `-b_k(g)`.
    fn equations(&self, g: Vector2<f64>, h: Vector3<f64>) -> (Vector5<f64>, Matrix5<f64>) {
        let mut e = Vector5::zeros();
        let mut jac = Matrix5::zeros();
        for (r, (ct, m, t, half)) in self.rows.iter().enumerate() {
            let ax = ct.0.add(m.0.mul_f64(g.x)).sub(m.1.mul_f64(g.y));
            let ay = ct.1.add(m.1.mul_f64(g.x)).add(m.0.mul_f64(g.y));
            let b = t.0.mul_f64(g.x).add(t.1.mul_f64(g.y)).sub(*half);
            let v = ax.mul_f64(h.x).add(ay.mul_f64(h.y)).sub(b.mul_f64(h.z));
            e[r] = v.hi + v.lo;
            // The Jacobian only steers the steps: in doubles, from the
            // accurate entries rounded once.
            let (mr, mi) = (m.0.hi + m.0.lo, m.1.hi + m.1.lo);
            let (tx, ty) = (t.0.hi + t.0.lo, t.1.hi + t.1.lo);
            jac[(r, 0)] = mr * h.x + mi * h.y - tx * h.z;
            jac[(r, 1)] = mr * h.y - mi * h.x - ty * h.z;
            jac[(r, 2)] = ax.hi + ax.lo;
            jac[(r, 3)] = ay.hi + ay.lo;
            jac[(r, 4)] = -(b.hi + b.lo);
        }
        let n = Dd::prod(h.x, h.x)
            .add(Dd::prod(h.y, h.y))
            .add(Dd::prod(h.z, h.z))
            .sub(Dd::of(1.0));
        e[4] = n.hi + n.lo;
        jac[(4, 2)] = 2.0 * h.x;
        jac[(4, 3)] = 2.0 * h.y;
        jac[(4, 4)] = 2.0 * h.z;
        (e, jac)
    }

    /// The norm of the four rows at `(g, z)` (local), `z` normalised as in
    /// [`equations`](Self::equations).
    pub(super) fn residual(&self, g: Vector2<f64>, z: Vector2<f64>) -> f64 {
        let e = self.equations(g, homogeneous(z)).0;
        Vector4::new(e[0], e[1], e[2], e[3]).norm()
    }

    /// Newton's method from `(g, z)` (local) on [`equations`](Self::equations):
    /// the converged point and the residual ([`residual`](Self::residual))
    /// at the start, or `None` when a step is not finite or the steps do
    /// not shrink within a few iterations. It ends after a step below
    /// [`CONVERGED`] (relative): the point then carries that step, and
    /// what is left is of its square. The circle point is homogeneous: one
    /// far out (a center at a pose's position, its circle point `1e9` task
    /// sizes out) is known only in its direction, and in `(g, z)` the steps
    /// diverged there.
    pub(super) fn newton(
        &self,
        g: Vector2<f64>,
        z: Vector2<f64>,
    ) -> Option<(Vector2<f64>, Vector2<f64>, f64)> {
        let (mut g, mut h) = (g, homogeneous(z));
        let mut last = f64::INFINITY;
        let mut start = f64::NAN;
        for _ in 0..ITERATIONS {
            let (e, jac) = self.equations(g, h);
            if start.is_nan() {
                start = Vector4::new(e[0], e[1], e[2], e[3]).norm();
            }
            let step = jac.lu().solve(&(-e))?;
            if !step.iter().all(|v| v.is_finite()) {
                return None;
            }
            let dg = Vector2::new(step[0], step[1]);
            let dh = Vector3::new(step[2], step[3], step[4]);
            g += dg;
            h += dh;
            let n = (dg.norm() / (1.0 + g.norm())).max(dh.norm());
            if n <= CONVERGED {
                let z = Vector2::new(h.x, h.y) / h.z;
                return z.iter().all(|v| v.is_finite()).then_some((g, z, start));
            }
            if !(n < last) {
                return None;
            }
            last = n;
        }
        None
    }
}

/// The circle point `z` as `(Z, w)` with `z = Z / w` and `|Z|^2 + w^2 = 1`.
fn homogeneous(z: Vector2<f64>) -> Vector3<f64> {
    let n = (1.0 + z.norm_squared()).sqrt();
    Vector3::new(z.x / n, z.y / n, 1.0 / n)
}

/// A step this small (relative to the center's `1 + |g|`, and to the
/// normalised circle point) ends [`Accurate::newton`].
const CONVERGED: f64 = 1e-12;

/// At most this many steps: from the elimination's polished point (`3e-3`
/// of `size + d` off at worst, in the inputs examined) Newton's method
/// converges quadratically in a handful.
const ITERATIONS: usize = 8;
