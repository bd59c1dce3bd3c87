//! Five poses: the Burmester points (every real one) and the four-bars of
//! their pairs.

use nalgebra::{Matrix4, Point2, Vector2, Vector4};

use super::errors;
use super::motion::Motion;
use super::order::{Drive, drive};
use super::{BURMESTER_RESIDUAL, COINCIDENT_POSES, DEGENERATE_CURVE};
use crate::error::Result;
use crate::geom::cubic::roots::{form_eval, form_mul, form_roots, form_sub, quadratic_roots};
use crate::geom::{Cubic, LocalFrame, Pose, wrap_angle};
use crate::synthesis::Dyad;

/// A four-bar made of two Burmester dyads, classified for either dyad
/// driving.
#[derive(Debug, Clone, PartialEq)]
pub struct BurmesterFourBar {
    /// The indices of the two dyads in [`FivePositions::burmester_points`].
    pub indices: [usize; 2],
    /// `drives[0]`: the first dyad drives, the second is driven;
    /// `drives[1]`: the other way round.
    pub drives: [Drive; 2],
}

/// Five poses of the coupler and their Burmester points: the dyads whose
/// circle point lies on a circle at all five poses.
///
/// # The method (no sampling, no random restarts)
///
/// The Burmester centers are the common points of the center-point curves
/// of two four-pose subsets that share three poses `i, j, k` (the cubics
/// `f` of `i, j, k, l` and `h` of `i, j, k, m`), less the poles
/// `P_ij, P_ik, P_jk` (on both) and the circular points. Both cubics pass
/// through `Q = P_ij` (the pair with the best conditioned pole is taken),
/// so along the line `Q + t w`
///
/// ```text
/// f(Q + t w) = t (a t^2 + b t + c),   h(Q + t w) = t (d t^2 + e t + g)
/// ```
///
/// with `a, d` cubic, `b, e` quadratic and `c, g` linear forms in `w`. The
/// two quadratics have a common root exactly where their resultant
///
/// ```text
/// R(w) = (a g - c d)^2 - (a e - b d)(b g - c e)
/// ```
///
/// vanishes: a binary form of degree 8, whose real roots (found exactly,
/// as roots of a polynomial on bounded intervals) are the directions from
/// `Q` to `P_ik`, `P_jk` and the (at most four) real Burmester points. Each
/// candidate is finished by Newton's method on the four circle equations
/// `a_k(G) . z = b_k(G)` in the unknowns `(G, z)`, and kept when the five
/// positions of its circle point are concyclic within
/// [`BURMESTER_RESIDUAL`].
#[derive(Clone, PartialEq)]
pub struct FivePositions {
    motion: Motion,
    points: Vec<Dyad>,
    curves: [Cubic; 2],
}

/// The poses and the Burmester points, not the motion's internals.
impl core::fmt::Debug for FivePositions {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("FivePositions")
            .field("poses", &self.poses())
            .field("burmester_points", &self.points)
            .finish()
    }
}

impl FivePositions {
    /// The Burmester points of five poses.
    ///
    /// # Errors
    ///
    /// [`crate::InvalidInput::NeedsPoses`] unless there are exactly five
    /// poses; the errors of [`super::FourPositions::new`] for the poses
    /// (four of them rotations about one point give
    /// [`crate::DegenerateError::CoincidentPoles`]: a continuum of dyads);
    /// [`crate::DegenerateError::AllTranslations`] when all poses have one angle (a
    /// pure translation).
    pub fn new(poses: &[Pose]) -> Result<Self> {
        if poses.len() != 5 {
            return Err(errors::pose_count("FivePositions::new", 5, poses.len()));
        }
        let motion = Motion::new(poses)?;
        // The pair with the best conditioned pole.
        let mut best = (0.0, 0, 1);
        for i in 0..5 {
            for j in i + 1..5 {
                let s = (0.5 * wrap_angle(motion.theta[j] - motion.theta[i]))
                    .sin()
                    .abs();
                if s > best.0 {
                    best = (s, i, j);
                }
            }
        }
        let (s, i, j) = best;
        if !(s > COINCIDENT_POSES) {
            return Err(errors::all_translations());
        }
        let rest: Vec<usize> = (0..5).filter(|&k| k != i && k != j).collect();
        let order = [i, j, rest[0], rest[1], rest[2]];
        let sub = Motion::new(&order.map(|k| poses[k]))?;
        // Every four-pose curve must be proper: four poses that are all
        // rotations about one point leave a continuum of Burmester dyads.
        let rest = Motion::new(&poses[1..])?;
        let subsets = [
            (&motion, [1, 2, 3]),
            (&motion, [1, 2, 4]),
            (&motion, [1, 3, 4]),
            (&motion, [2, 3, 4]),
            (&rest, [1, 2, 3]),
        ];
        for (m, rows) in subsets {
            let (f, mag) = m.form.cubic(rows);
            let max = f.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            if !(max > DEGENERATE_CURVE * mag) {
                let p = m.dehomogenize(m.pole(0, rows[0])).unwrap_or(m.origin);
                return Err(errors::common_pole(p));
            }
        }
        let mut candidates = candidates(&sub);
        candidates
            .iter_mut()
            .for_each(|p| *p = motion.local_of(sub.global_of(*p)));
        // Excluded: the three poles shared by the two cubics.
        let excluded: Vec<Point2<f64>> = [(0, 1), (0, 2), (1, 2)]
            .iter()
            .filter_map(|&(a, b)| sub.dehomogenize(sub.pole(a, b)))
            .collect();
        let mut points: Vec<Dyad> = Vec::new();
        for g0 in candidates {
            let Some((g, z)) = newton(&motion, g0) else {
                continue;
            };
            let dyad = Dyad::new(motion.global_of(g), motion.global_of(z));
            let size = motion.scale + (dyad.center - motion.origin).norm();
            if excluded
                .iter()
                .any(|p| (p - dyad.center).norm() <= 1e-9 * size)
            {
                continue;
            }
            if residual(&motion, &dyad) > BURMESTER_RESIDUAL {
                continue;
            }
            if points
                .iter()
                .any(|q| (q.center - dyad.center).norm() <= 1e-7 * size)
            {
                continue;
            }
            points.push(dyad);
        }
        points.sort_by(|a, b| {
            (a.center - motion.origin)
                .norm()
                .total_cmp(&(b.center - motion.origin).norm())
        });
        let curve = |rows: [usize; 3]| {
            let (f, _) = motion.form.cubic(rows);
            Cubic::from_local(f, motion.origin, motion.scale)
        };
        let curves = [curve([1, 2, 3]), curve([1, 2, 4])];
        Ok(FivePositions {
            motion,
            points,
            curves,
        })
    }

    /// The five poses.
    pub fn poses(&self) -> &[Pose] {
        &self.motion.poses
    }

    /// The size of the task (the largest distance of a pose point from
    /// their centroid), the unit of the relative tolerances.
    pub fn size(&self) -> f64 {
        self.motion.scale
    }

    /// The real Burmester points as dyads (center point, circle point at
    /// pose 1): none, two or four in practice (at most four), nearest the
    /// task first.
    pub fn burmester_points(&self) -> &[Dyad] {
        &self.points
    }

    /// The center-point curves of poses `1, 2, 3, 4` and `1, 2, 3, 5`: the
    /// Burmester centers are their common points other than `P12, P13,
    /// P23`.
    pub fn center_point_curves(&self) -> [Cubic; 2] {
        self.curves
    }

    /// `D_ij(z)` (1-based `i`, `j`).
    ///
    /// # Errors
    ///
    /// [`crate::InvalidInput::PoseIndex`] when `i` or `j` is not 1 to 5.
    pub fn displace(&self, z: Point2<f64>, i: usize, j: usize) -> Result<Point2<f64>> {
        for k in [i, j] {
            if !(1..=5).contains(&k) {
                return Err(errors::pose_index(k, 5));
            }
        }
        Ok(self.motion.displace(z, i - 1, j - 1))
    }

    /// The relative spread of the crank length of `dyad` over the five
    /// poses: `(max - min) / max` of `|D_1k(circle) - center|`. Zero (to
    /// rounding) for a Burmester point.
    pub fn residual(&self, dyad: &Dyad) -> f64 {
        residual(&self.motion, dyad)
    }

    /// The four-bars of every pair of Burmester points (up to six), each
    /// classified for both choices of the driving dyad. A pair whose
    /// linkage cannot be built (a link of zero length) is left out.
    pub fn four_bars(&self) -> Vec<BurmesterFourBar> {
        let mut out = Vec::new();
        for a in 0..self.points.len() {
            for b in a + 1..self.points.len() {
                let (p, q) = (&self.points[a], &self.points[b]);
                if let (Ok(d1), Ok(d2)) = (drive(&self.motion, p, q), drive(&self.motion, q, p)) {
                    out.push(BurmesterFourBar {
                        indices: [a, b],
                        drives: [d1, d2],
                    });
                }
            }
        }
        out
    }

    /// The four-bar of two dyads of the five poses.
    ///
    /// # Errors
    ///
    /// As [`super::FourPositions::drive`].
    pub fn drive(&self, driving: &Dyad, driven: &Dyad) -> Result<Drive> {
        drive(&self.motion, driving, driven)
    }
}

/// `(max - min) / max` of the crank lengths over the poses.
fn residual(m: &Motion, dyad: &Dyad) -> f64 {
    let d: Vec<f64> = (0..m.poses.len())
        .map(|k| (m.displace(dyad.circle, 0, k) - dyad.center).norm())
        .collect();
    let max = d.iter().copied().fold(0.0, f64::max);
    let min = d.iter().copied().fold(f64::INFINITY, f64::min);
    if max > 0.0 {
        (max - min) / max
    } else {
        f64::INFINITY
    }
}

/// Candidate Burmester centers (local frame of `sub`): the points of the
/// first cubic along the real roots of the resultant form from `P12`.
fn candidates(sub: &Motion) -> Vec<Vector2<f64>> {
    let h12 = sub.pole(0, 1);
    if h12[2] == 0.0 {
        return Vec::new();
    }
    let q = Vector2::new(h12[0] / h12[2], h12[1] / h12[2]);
    let (f, _) = sub.form.cubic([1, 2, 3]);
    let (h, _) = sub.form.cubic([1, 2, 4]);
    let origin = Point2::origin();
    let (f, h) = (
        Cubic::from_local(f, origin, 1.0),
        Cubic::from_local(h, origin, 1.0),
    );
    let forms = |k: &Cubic| {
        let g = k.grad_local(q);
        let hh = k.hessian_local(q);
        (
            k.cubic_form().to_vec(),
            vec![0.5 * hh[0], hh[1], 0.5 * hh[2]],
            vec![g.x, g.y],
        )
    };
    let (a, b, c) = forms(&f);
    let (d, e, g) = forms(&h);
    let agcd = form_sub(&form_mul(&a, &g), &form_mul(&c, &d));
    let aebd = form_sub(&form_mul(&a, &e), &form_mul(&b, &d));
    let bgce = form_sub(&form_mul(&b, &g), &form_mul(&c, &e));
    let res = form_sub(&form_mul(&agcd, &agcd), &form_mul(&aebd, &bgce));
    let mut out = Vec::new();
    for s in form_roots(&res) {
        let (sn, cs) = s.sin_cos();
        let (fa, fb, fc) = (
            form_eval(&a, cs, sn),
            form_eval(&b, cs, sn),
            form_eval(&c, cs, sn),
        );
        let mut ts = quadratic_roots(fa, fb, fc);
        if ts.is_empty() && fa != 0.0 {
            // A double root lost to rounding.
            ts.push(-fb / (2.0 * fa));
        }
        for t in ts {
            let p = q + Vector2::new(cs, sn) * t;
            if p.iter().all(|v| v.is_finite()) {
                out.push(p);
            }
        }
    }
    out
}

/// Newton's method on the four circle equations `a_k(G) . z = b_k(G)`
/// (k = 2..5) in `(G, z)` (local), from the center `g0` and the circle point
/// of its best pair of rows. When the steps never pass the step test
/// (a center tens of thousands of task sizes away, nearly a slider, whose
/// position rounding leaves loose along one direction: the steps wander at
/// rounding level) the iterate with the smallest equation residual is
/// returned, and the caller keeps it only if its crank lengths agree to
/// [`BURMESTER_RESIDUAL`]. `None` when a step is not finite.
fn newton(m: &Motion, g0: Vector2<f64>) -> Option<(Vector2<f64>, Vector2<f64>)> {
    let mut g = g0;
    let mut z = m.form.solve(g, &[1, 2, 3, 4]).ok()?;
    let mut last = f64::INFINITY;
    let mut best = (f64::INFINITY, g, z);
    for _ in 0..60 {
        let mut jac = Matrix4::zeros();
        let mut rhs = Vector4::zeros();
        for (r, k) in (1..5).enumerate() {
            let (a, b) = m.form.row(k, g);
            let dg = m.form.row_dg(k, z);
            rhs[r] = -(a.dot(&z) - b);
            jac[(r, 0)] = dg.x;
            jac[(r, 1)] = dg.y;
            jac[(r, 2)] = a.x;
            jac[(r, 3)] = a.y;
        }
        let r = rhs.norm();
        if r < best.0 {
            best = (r, g, z);
        }
        let step = jac.full_piv_lu().solve(&rhs)?;
        if !step.iter().all(|v| v.is_finite()) {
            return None;
        }
        g += Vector2::new(step[0], step[1]);
        z += Vector2::new(step[2], step[3]);
        let size = 1.0 + g.norm() + z.norm();
        let n = step.norm();
        if n <= 8.0 * f64::EPSILON * size || (n >= last && n <= 1e-10 * size) {
            return Some((g, z));
        }
        last = n;
    }
    Some((best.1, best.2))
}

#[cfg(test)]
mod tests {
    use super::super::motion::cross3;

    #[test]
    fn homogeneous_cross_is_the_meet() {
        // The lines x = 1 and y = 2 meet at (1, 2).
        let l1 = [1.0, 0.0, -1.0];
        let l2 = [0.0, 1.0, -2.0];
        let p = cross3(l1, l2);
        assert!((p[0] / p[2] - 1.0).abs() < 1e-15 && (p[1] / p[2] - 2.0).abs() < 1e-15);
    }
}
