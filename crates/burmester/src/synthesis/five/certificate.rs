//! An exact count certificate for the five-pose Burmester points (issue 24;
//! the algorithm of `fuzz/reference/certificate_five.py`, cert43): the
//! number of real finite Burmester points and of real points at infinity of
//! the float task, in exact integer and rational arithmetic.
//!
//! The task within rounding: each pose's rotation from pose 1 is the f64
//! `(a_k - a_1).sin_cos()`, moved onto the unit circle exactly by its
//! half-angle tangent (rounded to a double); positions are the floats'
//! exact dyadic values. Steps: the two center-point cubics `f1`, `f2`
//! (integer, primitive); a shear `x = X + u Y`; the resultant
//! `R(X) = res_Y(f1, f2)` as minus the determinant of the two cubics'
//! 3x3 Bezout matrix, expanded in integer polynomials in `X` (no
//! evaluation, no division); the poles' linear factors divided out
//! exactly (`Q`); `Q` squarefree; its real roots counted by a Sturm
//! sequence (of `Q`'s primitive part; subresultant divisions) and isolated
//! by bisection; the Burmester points at infinity from `4 - deg Q`. Every
//! sign of a polynomial at a dyadic point is taken from a wide-exponent
//! `f64` Horner where a rigorous error bound decides it, exactly
//! otherwise ([`Approx::sign_at`]); gcds by Lehmer's algorithm.
//!
//! Sizes (bounded by the f64 exponent range; the degrees are fixed, so
//! no allocation grows with anything but these bit lengths): a position is
//! an integer over one common `2^e`, `e <= 1074`, of at most
//! `1024 + 1074` bits; a rotation's `C, S, D` at most about `2 (1074 + 53)`
//! bits (a half-angle tangent down to the least double); the rows' entries
//! a few such products, the cubics' coefficients (3x3 determinants of them)
//! at most about 25,000 bits, the resultant (a 6x6 Sylvester determinant
//! in the sheared coefficients) at most about six times that, `Q` and its Sturm
//! sequence (subresultant-sized) at most about seven times `Q`'s. The
//! bisection halves a power-of-two Cauchy bound down to the roots'
//! separation, itself bounded by the same sizes. Measured (release, one
//! core; bench `points/certificate`, `points/certificate_mixed`):
//! ordinary tasks 530-bit cubics, 3,200-bit resultants, about 0.3 ms a
//! task (2.5 ms before fast45; `certificate_five.py`: 20 ms); positions
//! mixing `1e300` and `1e-300`: a 42,000-bit resultant, about 9 ms (95
//! ms before). Before fast45 the 186 frames of the open findings took a
//! median 2.5 ms, max 4 ms, and angles of `1e-300` 39 ms.
//!
//! Step 6 (for judging an answer, [`refuses`]): each isolated root refined
//! by exact bisection and its point's `y` from the first subresultant of
//! the two sheared cubics; the answer's points within `BURMESTER_NEAR`
//! task sizes must pair one to one with the exact ones there
//! ([`disagreement`]; a listed double point may stand for a complex pair
//! of the exact task within [`PAIR_REACH`], [`complex_pair_at`]).
//! `FivePositions::of` refuses an answer that does not (stop 42); where
//! the exact task cannot be certified (degenerate or ambiguous) the
//! library's own checks answer. The heaviest f64 tasks give cubics of
//! about 10,600 bits (test `the_check_at_its_heaviest`: some tens of ms).

use std::cmp::Ordering;

use num_bigint::{BigInt, BigUint, Sign};
use num_traits::{One, Signed, Zero};

use crate::geom::Pose;

/// Why a task could not be certified (a degenerate or ambiguous exact
/// task, a non-finite input, or an internal check that failed).
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct CannotCertify(pub(crate) String);

fn cannot<T>(why: &str) -> Result<T, CannotCertify> {
    Err(CannotCertify(why.to_string()))
}

// ------------------------------------------------------------ rationals

/// An exact rational, reduced, with a positive denominator.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Rat {
    n: BigInt,
    d: BigInt,
}

impl Rat {
    fn new(n: BigInt, d: BigInt) -> Rat {
        debug_assert!(!d.is_zero());
        let g = num_integer_gcd(&n, &d);
        let (mut n, mut d) = if g.is_one() { (n, d) } else { (n / &g, d / &g) };
        if d.is_negative() {
            n = -n;
            d = -d;
        }
        Rat { n, d }
    }
    fn int(n: BigInt) -> Rat {
        Rat {
            n,
            d: BigInt::one(),
        }
    }
    fn small(n: i64) -> Rat {
        Rat::int(BigInt::from(n))
    }
    fn zero() -> Rat {
        Rat::small(0)
    }
    fn is_zero(&self) -> bool {
        self.n.is_zero()
    }
    #[cfg_attr(not(test), allow(dead_code))]
    fn sign(&self) -> Sign {
        self.n.sign()
    }
    fn add(&self, o: &Rat) -> Rat {
        if self.d == o.d {
            return Rat::new(&self.n + &o.n, self.d.clone());
        }
        Rat::new(&self.n * &o.d + &o.n * &self.d, &self.d * &o.d)
    }
    fn neg(&self) -> Rat {
        Rat {
            n: -&self.n,
            d: self.d.clone(),
        }
    }
    fn sub(&self, o: &Rat) -> Rat {
        self.add(&o.neg())
    }
    fn mul(&self, o: &Rat) -> Rat {
        Rat::new(&self.n * &o.n, &self.d * &o.d)
    }
    /// `self / o`; `o` nonzero (checked by every caller).
    fn div(&self, o: &Rat) -> Rat {
        Rat::new(&self.n * &o.d, &self.d * &o.n)
    }
    fn cmp(&self, o: &Rat) -> Ordering {
        (&self.n * &o.d).cmp(&(&o.n * &self.d))
    }
    /// The exact value of a finite f64.
    fn of_f64(v: f64) -> Result<Rat, CannotCertify> {
        if !v.is_finite() {
            return cannot("a non-finite pose");
        }
        if v == 0.0 {
            return Ok(Rat::zero());
        }
        let bits = v.to_bits();
        let exp = ((bits >> 52) & 0x7ff) as i64;
        let frac = bits & ((1u64 << 52) - 1);
        let (m, e) = if exp == 0 {
            (frac, -1074)
        } else {
            (frac | (1u64 << 52), exp - 1075)
        };
        let m = if v < 0.0 {
            -BigInt::from(m)
        } else {
            BigInt::from(m)
        };
        Ok(if e >= 0 {
            Rat::int(m << e as usize)
        } else {
            Rat::new(m, BigInt::one() << (-e) as usize)
        })
    }
    /// The nearest f64 (ties to even), for values within the f64 range.
    fn to_f64(&self) -> f64 {
        if self.is_zero() {
            return 0.0;
        }
        let neg = self.n.is_negative();
        let n = self.n.abs();
        let d = &self.d;
        let k = n.bits() as i64 - d.bits() as i64;
        // q = floor(n 2^-e / d) with 54..56 bits, or e at the subnormal floor
        let e = (k - 55).max(-1074);
        let (num, den) = if e >= 0 {
            (n, d << e as usize)
        } else {
            (n << (-e) as usize, d.clone())
        };
        let q = &num / &den;
        let r = &num - &q * &den;
        let extra = q.bits() as i64 - 53;
        let (mut m, exp) = if extra > 0 {
            let low = &q & ((BigInt::one() << extra as usize) - 1);
            let half = BigInt::one() << (extra - 1) as usize;
            let m = &q >> extra as usize;
            let up = low > half || (low == half && (!r.is_zero() || m.bit(0)));
            (if up { m + 1 } else { m }, e + extra)
        } else {
            let twice = &r << 1;
            let up = twice > den || (twice == den && q.bit(0));
            (if up { q + 1 } else { q }, e)
        };
        if m.bits() > 53 {
            m >>= 1;
            return signed(libm::ldexp(to_u64(&m) as f64, (exp + 1) as i32), neg);
        }
        signed(libm::ldexp(to_u64(&m) as f64, exp as i32), neg)
    }
}

fn signed(v: f64, neg: bool) -> f64 {
    if neg { -v } else { v }
}

fn to_u64(m: &BigInt) -> u64 {
    m.iter_u64_digits().next().unwrap_or(0)
}

/// The non-negative gcd (`gcd(0, 0) = 0`): Lehmer's algorithm (Knuth,
/// TAOCP 2, 4.5.2, Algorithm L) on the leading 63 bits, each round's
/// cofactors applied to the full numbers (or one division step where the
/// leading bits decide no quotient), Euclid in `u64` once both fit a word.
fn num_integer_gcd(a: &BigInt, b: &BigInt) -> BigInt {
    let (mut a, mut b) = (a.magnitude().clone(), b.magnitude().clone());
    if a < b {
        std::mem::swap(&mut a, &mut b);
    }
    while b.bits() > 64 {
        // a >= b > 2^64: the leading 63 bits of a, b at a's position
        let shift = a.bits() - 63;
        let top = |v: &BigUint| (v >> shift).iter_u64_digits().next().unwrap_or(0) as i128;
        let (mut x, mut y) = (top(&a), top(&b));
        let (mut ca, mut cb, mut cc, mut cd) = (1i128, 0i128, 0i128, 1i128);
        while y + cc != 0 && y + cd != 0 {
            let q = (x + ca) / (y + cc);
            if q != (x + cb) / (y + cd) {
                break;
            }
            (ca, cc) = (cc, ca - q * cc);
            (cb, cd) = (cd, cb - q * cd);
            (x, y) = (y, x - q * y);
        }
        // |ca|, |cb|, |cc|, |cd| < 2^63; the combinations are the
        // remainders of the Euclidean steps taken (non-negative, checked)
        let combine = |p: i128, q: i128| -> Option<BigUint> {
            // p a + q b, p and q of opposite signs (or one zero)
            let (x, y) = (&a * p.unsigned_abs(), &b * q.unsigned_abs());
            if p >= 0 && q <= 0 && x >= y {
                Some(x - y)
            } else if p <= 0 && q >= 0 && y >= x {
                Some(y - x)
            } else {
                None
            }
        };
        match (cb != 0).then(|| (combine(ca, cb), combine(cc, cd))) {
            Some((Some(na), Some(nb))) if na >= nb => {
                a = na;
                b = nb;
            }
            _ => {
                let r = &a % &b;
                a = b;
                b = r;
            }
        }
    }
    if b.is_zero() {
        return BigInt::from(a);
    }
    let mut y = b.iter_u64_digits().next().unwrap_or(0);
    let mut x = (&a % y).iter_u64_digits().next().unwrap_or(0);
    while x != 0 {
        (x, y) = (y % x, x);
    }
    BigInt::from(y)
}

fn lcm(a: &BigInt, b: &BigInt) -> BigInt {
    a / num_integer_gcd(a, b) * b
}

// ------------------------------------------------ step 1: the exact task

/// The half-angle tangent of the f64 rotation `(cos d, sin d)`
/// (`d.sin_cos()`).
enum HalfAngle {
    /// `sin d = 0`, `cos d > 0`.
    Identity,
    /// `sin d = 0`, `cos d < 0`.
    HalfTurn,
    /// `s / (1 + c)`, or `(1 - c) / s` for `c < 0`, rounded to a double.
    Tangent(f64),
}

fn half_angle(d: f64) -> Result<HalfAngle, CannotCertify> {
    if !d.is_finite() {
        return cannot("a non-finite pose");
    }
    let (s, c) = d.sin_cos();
    if s == 0.0 {
        return Ok(if c > 0.0 {
            HalfAngle::Identity
        } else {
            HalfAngle::HalfTurn
        });
    }
    let (cr, sr) = (Rat::of_f64(c)?, Rat::of_f64(s)?);
    let one = Rat::small(1);
    let tau = if c >= 0.0 {
        sr.div(&one.add(&cr))
    } else {
        one.sub(&cr).div(&sr)
    };
    Ok(HalfAngle::Tangent(tau.to_f64()))
}

/// The f64 rotation `(cos d, sin d)` (`d.sin_cos()`) moved onto the unit
/// circle exactly by its half-angle tangent rounded to a double: `(c, s)`.
#[cfg(test)]
pub(crate) fn unit_rotation(d: f64) -> Result<(Rat, Rat), CannotCertify> {
    let (c, s, d) = unit_rotation_int(d)?;
    Ok((Rat::new(c, d.clone()), Rat::new(s, d)))
}

/// A displacement from pose 1: `G -> R G + t`, `R = (c, s)` exactly on the
/// unit circle.
#[derive(Debug, Clone)]
struct Disp {
    c: Rat,
    s: Rat,
    tx: Rat,
    ty: Rat,
}

/// The exact displacements of poses 2..5 from pose 1, reduced once from
/// the integer task (`c = C / D`, `s = S / D`, `t = (TX, TY) / (D 2^e)`).
fn displacements(poses: &[[f64; 3]; 5]) -> Result<Vec<Disp>, CannotCertify> {
    let t = int_task(poses)?;
    Ok(t.rot
        .iter()
        .zip(int_translations(&t))
        .map(|((c, s, d), (tx, ty))| {
            let de = d << t.e;
            Disp {
                c: Rat::new(c.clone(), d.clone()),
                s: Rat::new(s.clone(), d.clone()),
                tx: Rat::new(tx, de.clone()),
                ty: Rat::new(ty, de),
            }
        })
        .collect())
}

/// The reference of [`displacements`] (the present one up to fast45: in
/// reduced rationals throughout).
#[cfg(test)]
fn displacements_reference(poses: &[[f64; 3]; 5]) -> Result<Vec<Disp>, CannotCertify> {
    let p1x = Rat::of_f64(poses[0][0])?;
    let p1y = Rat::of_f64(poses[0][1])?;
    let mut out = Vec::with_capacity(4);
    for p in &poses[1..] {
        let (c, s) = unit_rotation(p[2] - poses[0][2])?;
        let tx = Rat::of_f64(p[0])?.sub(&c.mul(&p1x).sub(&s.mul(&p1y)));
        let ty = Rat::of_f64(p[1])?.sub(&s.mul(&p1x).add(&c.mul(&p1y)));
        out.push(Disp { c, s, tx, ty });
    }
    Ok(out)
}

// ------------------------------------------ step 2: the center-point cubics

/// A polynomial of total degree at most 3 in `(x, y)`: `c[i][j]` the
/// coefficient of `x^i y^j`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Poly2<T> {
    c: [[T; 4]; 4],
}

/// The task scaled to integers: per pose 2..5 the rotation `(C, S, D)`
/// (`c = C / D`, `s = S / D`, exactly on the unit circle), and the
/// positions `P / 2^e` (one exponent for all).
struct IntTask {
    rot: Vec<(BigInt, BigInt, BigInt)>,
    pos: Vec<(BigInt, BigInt)>,
    e: u64,
}

fn int_task(poses: &[[f64; 3]; 5]) -> Result<IntTask, CannotCertify> {
    let mut rot = Vec::with_capacity(4);
    for p in &poses[1..] {
        rot.push(unit_rotation_int(p[2] - poses[0][2])?);
    }
    let mut exact = Vec::with_capacity(10);
    for p in poses {
        exact.push((Rat::of_f64(p[0])?, Rat::of_f64(p[1])?));
    }
    // every denominator is a power of two: the largest divides the others
    let e = exact
        .iter()
        .flat_map(|(x, y)| [x.d.bits(), y.d.bits()])
        .max()
        .unwrap_or(1)
        - 1;
    let int = |r: &Rat| &r.n * ((BigInt::one() << e) / &r.d);
    let pos = exact.iter().map(|(x, y)| (int(x), int(y))).collect();
    Ok(IntTask { rot, pos, e })
}

/// `(C, S, D)` with `(C / D, S / D)` the rotation of `unit_rotation`:
/// `tau = T / 2^k`, `D = 4^k + T^2`, `C = 4^k - T^2`, `S = 2^(k+1) T`.
fn unit_rotation_int(d: f64) -> Result<(BigInt, BigInt, BigInt), CannotCertify> {
    let tau = match half_angle(d)? {
        HalfAngle::Identity => return Ok((BigInt::one(), BigInt::zero(), BigInt::one())),
        HalfAngle::HalfTurn => return Ok((-BigInt::one(), BigInt::zero(), BigInt::one())),
        HalfAngle::Tangent(t) => Rat::of_f64(t)?,
    };
    let k = tau.d.bits() - 1;
    let four_k = BigInt::one() << (2 * k);
    let t2 = &tau.n * &tau.n;
    Ok((&four_k - &t2, &tau.n << (k + 1), &four_k + &t2))
}

fn p2_zero() -> Poly2<BigInt> {
    Poly2 {
        c: std::array::from_fn(|_| std::array::from_fn(|_| BigInt::zero())),
    }
}

fn p2_lin(c0: BigInt, cx: BigInt, cy: BigInt) -> Poly2<BigInt> {
    let mut p = p2_zero();
    p.c[0][0] = c0;
    p.c[1][0] = cx;
    p.c[0][1] = cy;
    p
}

/// `p + q` (`sign` 1) or `p - q` (`sign` -1).
fn p2_add(p: &Poly2<BigInt>, q: &Poly2<BigInt>, sign: i64) -> Poly2<BigInt> {
    let mut r = p.clone();
    for i in 0..4 {
        for j in 0..4 {
            if !q.c[i][j].is_zero() {
                if sign < 0 {
                    r.c[i][j] -= &q.c[i][j];
                } else {
                    r.c[i][j] += &q.c[i][j];
                }
            }
        }
    }
    r
}

/// The product; the factors' degrees sum to at most 3 here (entries of
/// degree 1, 3x3 determinants).
fn p2_mul(p: &Poly2<BigInt>, q: &Poly2<BigInt>) -> Poly2<BigInt> {
    let mut r = p2_zero();
    for i in 0..4 {
        for j in 0..4 - i {
            if p.c[i][j].is_zero() {
                continue;
            }
            for k in 0..4 - i - j {
                for l in 0..4 - i - j - k {
                    if !q.c[k][l].is_zero() {
                        r.c[i + k][j + l] += &p.c[i][j] * &q.c[k][l];
                    }
                }
            }
        }
    }
    r
}

/// The 3x3 determinants of rows `r0, r1, r` for each `r` of `last`, by
/// cofactors along the last row (the 2x2 minors of `r0, r1` formed once,
/// shared).
fn det3_last_rows(
    r0: &[Poly2<BigInt>; 3],
    r1: &[Poly2<BigInt>; 3],
    last: [&[Poly2<BigInt>; 3]; 2],
) -> [Poly2<BigInt>; 2] {
    let m2 = |i: usize, j: usize| p2_add(&p2_mul(&r0[i], &r1[j]), &p2_mul(&r0[j], &r1[i]), -1);
    let (m0, m1, m2) = (m2(1, 2), m2(0, 2), m2(0, 1));
    last.map(|r| {
        let t = p2_add(&p2_mul(&r[0], &m0), &p2_mul(&r[1], &m1), -1);
        p2_add(&t, &p2_mul(&r[2], &m2), 1)
    })
}

/// `f` divided by the gcd of its coefficients.
fn ip2_primitive(f: Poly2<BigInt>) -> Poly2<BigInt> {
    let mut g = BigInt::zero();
    for v in f.c.iter().flatten() {
        g = num_integer_gcd(&g, v);
        if g.is_one() {
            return f;
        }
    }
    if g.is_zero() {
        return f;
    }
    Poly2 {
        c: f.c.map(|row| row.map(|v| v / &g)),
    }
}

/// The two center-point cubics `f1 = det(rows 2,3,4)`, `f2 = det(rows
/// 2,3,5)` of the dyad condition's rows `a_k(G) . z = b_k(G)`, integer and
/// primitive: row `k` scaled by `D_k^2 2^e`, the column `b` by `2^(e+1)`
/// (positive factors; the Python's rational cubics made primitive).
fn int_cubics(t: &IntTask) -> [Poly2<BigInt>; 2] {
    let rows: Vec<[Poly2<BigInt>; 3]> = t
        .rot
        .iter()
        .zip(int_translations(t))
        .map(|((c, s, d), (tx, ty))| {
            let de = d << t.e;
            let mr = &de * (d - c);
            let mi = &de * s;
            let ax = p2_lin(c * &tx + s * &ty, mr.clone(), -&mi);
            let ay = p2_lin(c * &ty - s * &tx, mi, mr);
            let b = p2_lin(-(&tx * &tx + &ty * &ty), (&de * &tx) << 1, (&de * &ty) << 1);
            [ax, ay, b]
        })
        .collect();
    det3_last_rows(&rows[0], &rows[1], [&rows[2], &rows[3]]).map(ip2_primitive)
}

/// The translations of poses 2..5 from pose 1 as `(TX, TY)`: `t = (TX,
/// TY) / (D 2^e)`, `TX = D px - (C p1x - S p1y)`, `TY = D py - (S p1x +
/// C p1y)`.
fn int_translations(t: &IntTask) -> Vec<(BigInt, BigInt)> {
    let (p1x, p1y) = &t.pos[0];
    t.rot
        .iter()
        .zip(&t.pos[1..])
        .map(|((c, s, d), (px, py))| (d * px - (c * p1x - s * p1y), d * py - (s * p1x + c * p1y)))
        .collect()
}

/// `f(x, y) = 0` exactly at a rational point (homogenized over the common
/// denominator).
fn ip2_vanishes(f: &Poly2<BigInt>, x: &Rat, y: &Rat) -> bool {
    let d = lcm(&x.d, &y.d);
    let (a, b) = (&x.n * (&d / &x.d), &y.n * (&d / &y.d));
    let powers = |v: &BigInt| -> [BigInt; 4] {
        let v2 = v * v;
        let v3 = &v2 * v;
        [BigInt::one(), v.clone(), v2, v3]
    };
    let (pa, pb, pd) = (powers(&a), powers(&b), powers(&d));
    let mut sum = BigInt::zero();
    for i in 0..4 {
        for j in 0..4 - i {
            if !f.c[i][j].is_zero() {
                sum += &f.c[i][j] * &pa[i] * &pb[j] * &pd[3 - i - j];
            }
        }
    }
    sum.is_zero()
}

/// An unreduced fraction (`d > 0`): the poles' arithmetic, reduced once
/// at the end (the same values as in [`Rat`], fewer gcds).
#[derive(Debug, Clone)]
struct Frac {
    n: BigInt,
    d: BigInt,
}

impl Frac {
    fn of(r: &Rat) -> Frac {
        Frac {
            n: r.n.clone(),
            d: r.d.clone(),
        }
    }
    fn add(&self, o: &Frac, sign: i64) -> Frac {
        let (a, b) = if self.d == o.d {
            (self.n.clone(), o.n.clone())
        } else {
            (&self.n * &o.d, &o.n * &self.d)
        };
        let d = if self.d == o.d {
            self.d.clone()
        } else {
            &self.d * &o.d
        };
        Frac {
            n: if sign < 0 { a - b } else { a + b },
            d,
        }
    }
    fn mul(&self, o: &Frac) -> Frac {
        Frac {
            n: &self.n * &o.n,
            d: &self.d * &o.d,
        }
    }
    /// `self / o`, `o` nonzero.
    fn div(&self, o: &Frac) -> Frac {
        let (n, d) = (&self.n * &o.d, &self.d * &o.n);
        if d.is_negative() {
            Frac { n: -n, d: -d }
        } else {
            Frac { n, d }
        }
    }
    fn rat(self) -> Rat {
        Rat::new(self.n, self.d)
    }
}

/// The fixed point of `G -> R G + t` (`None`: a translation), from
/// `(c, s, tx, ty)`.
fn fixed_point(d: [Frac; 4]) -> Option<(Rat, Rat)> {
    let [c, s, tx, ty] = d;
    let one = Frac {
        n: BigInt::one(),
        d: BigInt::one(),
    };
    let mr = one.add(&c, -1);
    let det = mr.mul(&mr).add(&s.mul(&s), 1);
    if det.n.is_zero() {
        return None;
    }
    let x = mr.mul(&tx).add(&s.mul(&ty), -1).div(&det);
    let y = s.mul(&tx).add(&mr.mul(&ty), 1).div(&det);
    Some((x.rat(), y.rat()))
}

/// The poles P12, P13, P23 (unreduced arithmetic, each coordinate reduced
/// once; the reference is `poles_reference`).
fn poles(disp: &[Disp]) -> [Option<(Rat, Rat)>; 3] {
    let f = |d: &Disp| [&d.c, &d.s, &d.tx, &d.ty].map(Frac::of);
    let ([c2, s2, tx2, ty2], d3) = (f(&disp[0]), f(&disp[1]));
    let c = d3[0].mul(&c2).add(&d3[1].mul(&s2), 1);
    let s = d3[1].mul(&c2).add(&d3[0].mul(&s2), -1);
    let tx = d3[2].add(&c.mul(&tx2).add(&s.mul(&ty2), -1), -1);
    let ty = d3[3].add(&s.mul(&tx2).add(&c.mul(&ty2), 1), -1);
    [
        fixed_point(f(&disp[0])),
        fixed_point(d3),
        fixed_point([c, s, tx, ty]),
    ]
}

/// The fixed point of `G -> R G + t` in reduced rationals (the reference
/// of [`fixed_point`]).
#[cfg(test)]
fn fixed_point_reference(d: &Disp) -> Option<(Rat, Rat)> {
    let one = Rat::small(1);
    let mr = one.sub(&d.c);
    let det = mr.mul(&mr).add(&d.s.mul(&d.s));
    if det.is_zero() {
        return None;
    }
    let x = mr.mul(&d.tx).sub(&d.s.mul(&d.ty)).div(&det);
    let y = d.s.mul(&d.tx).add(&mr.mul(&d.ty)).div(&det);
    Some((x, y))
}

/// The poles P12, P13, P23 in reduced rationals (the present [`poles`]
/// up to fast45).
#[cfg(test)]
fn poles_reference(disp: &[Disp]) -> [Option<(Rat, Rat)>; 3] {
    let (d2, d3) = (&disp[0], &disp[1]);
    let c = d3.c.mul(&d2.c).add(&d3.s.mul(&d2.s));
    let s = d3.s.mul(&d2.c).sub(&d3.c.mul(&d2.s));
    let tx = d3.tx.sub(&c.mul(&d2.tx).sub(&s.mul(&d2.ty)));
    let ty = d3.ty.sub(&s.mul(&d2.tx).add(&c.mul(&d2.ty)));
    [
        fixed_point_reference(d2),
        fixed_point_reference(d3),
        fixed_point_reference(&Disp { c, s, tx, ty }),
    ]
}

/// `L` with the cubic part `(x^2 + y^2) L` of `f`: `(Lx, Ly)`, checked.
fn cubic_part_line(f: &Poly2<BigInt>) -> Result<(BigInt, BigInt), CannotCertify> {
    let (lx, ly) = (f.c[3][0].clone(), f.c[0][3].clone());
    if f.c[2][1] != ly || f.c[1][2] != lx {
        return cannot("internal: a cubic part that is not circular");
    }
    Ok((lx, ly))
}

// ------------------------------------------------ step 3: the resultant

fn binom(n: usize, k: usize) -> i64 {
    [[1, 0, 0, 0], [1, 1, 0, 0], [1, 2, 1, 0], [1, 3, 3, 1]][n][k]
}

/// `q^3 p(X + u Y, Y)` (`u = a / q`) as coefficient lists in `Y`, each a
/// list of integers in `X`, trimmed.
// `out[k][e + j]`: the Python's index arithmetic, kept.
#[allow(clippy::needless_range_loop)]
fn shear(p: &Poly2<BigInt>, a: i64, q: i64) -> Vec<Vec<BigInt>> {
    let mut out: [[BigInt; 4]; 4] =
        std::array::from_fn(|_| std::array::from_fn(|_| BigInt::zero()));
    for i in 0..4 {
        for j in 0..4 - i {
            let v = &p.c[i][j];
            if v.is_zero() {
                continue;
            }
            // (X + uY)^i Y^j = sum_k C(i,k) X^k (uY)^(i-k) Y^j
            for k in 0..=i {
                let e = i - k;
                let f = BigInt::from(binom(i, k))
                    * BigInt::from(a).pow(e as u32)
                    * BigInt::from(q).pow((3 - e) as u32);
                out[k][e + j] += v * f;
            }
        }
    }
    let deg_y = (0..4)
        .rev()
        .find(|&b| (0..4).any(|a| !out[a][b].is_zero()))
        .unwrap_or(0);
    (0..=deg_y)
        .map(|b| {
            let mut col: Vec<BigInt> = (0..4).map(|a| out[a][b].clone()).collect();
            while col.last().is_some_and(|v| v.is_zero()) {
                col.pop();
            }
            col
        })
        .collect()
}

#[cfg(test)]
fn ieval(a: &[BigInt], x: i64) -> BigInt {
    let x = BigInt::from(x);
    let mut r = BigInt::zero();
    for v in a.iter().rev() {
        r = r * &x + v;
    }
    r
}

/// The determinant of an integer matrix by Bareiss's fraction-free
/// elimination (exact divisions).
fn det_bareiss(mut m: Vec<Vec<BigInt>>) -> BigInt {
    let n = m.len();
    let mut negate = false;
    let mut prev = BigInt::one();
    for k in 0..n.saturating_sub(1) {
        if m[k][k].is_zero() {
            match (k + 1..n).find(|&r| !m[r][k].is_zero()) {
                Some(r) => {
                    m.swap(k, r);
                    negate = !negate;
                }
                None => return BigInt::zero(),
            }
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let v = (&m[i][j] * &m[k][k] - &m[i][k] * &m[k][j]) / &prev;
                m[i][j] = v;
            }
        }
        prev = m[k][k].clone();
    }
    let d = m[n - 1][n - 1].clone();
    if negate { -d } else { d }
}

/// The product of two integer polynomials (lowest degree first; trimmed
/// when the factors are).
fn imul(a: &[BigInt], b: &[BigInt]) -> IPoly {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut r = vec![BigInt::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        for (j, y) in b.iter().enumerate() {
            if !y.is_zero() {
                r[i + j] += x * y;
            }
        }
    }
    r
}

/// `a + b` (`sign` 1) or `a - b` (`sign` -1), trimmed.
fn iadd(a: &[BigInt], b: &[BigInt], sign: i64) -> IPoly {
    let mut r = a.to_vec();
    if r.len() < b.len() {
        r.resize(b.len(), BigInt::zero());
    }
    for (v, w) in r.iter_mut().zip(b) {
        if sign < 0 {
            *v -= w;
        } else {
            *v += w;
        }
    }
    itrim(r)
}

/// `res_Y` of two cubics in `Y` given as coefficient lists in `Y` (each a
/// list of integers in `X`; both of `Y`-degree exactly 3, as every
/// admissible shear gives): `-det B` of their 3x3 Bezout matrix, its
/// entries integer polynomials in `X`, expanded exactly (no evaluation,
/// no division). `B(y, z) = (f(y) g(z) - f(z) g(y)) / (y - z) =
/// sum b_ij y^i z^j`, so `b_ij` sums `w_kl = f_k g_l - f_l g_k` over the
/// `k > l` with `k + l = i + j + 1`, `l <= i, j < k`; for two cubics
/// `res = (-1)^(3 (3 - 1) / 2) det B = -det B` (the Sylvester determinant
/// of `resultant_y_sylvester`, checked by the tests). Integer
/// coefficients, lowest degree first, trimmed.
fn resultant_y(c1: &[Vec<BigInt>], c2: &[Vec<BigInt>]) -> Result<Vec<BigInt>, CannotCertify> {
    if c1.len() != 4 || c2.len() != 4 {
        return cannot("internal: a sheared cubic of Y-degree other than 3");
    }
    let mut b: [[IPoly; 3]; 3] = Default::default();
    for k in 1..4 {
        for l in 0..k {
            let w = iadd(&imul(&c1[k], &c2[l]), &imul(&c1[l], &c2[k]), -1);
            for (i, row) in b.iter_mut().enumerate().take(k).skip(l) {
                let j = k - 1 - i + l;
                if i <= j {
                    row[j] = iadd(&row[j], &w, 1);
                }
            }
        }
    }
    // symmetric: b_ji = b_ij; cofactors along the first row
    let m = |p: &IPoly, q: &IPoly, r: &IPoly, s: &IPoly| iadd(&imul(p, q), &imul(r, s), -1);
    let c0 = m(&b[1][1], &b[2][2], &b[1][2], &b[1][2]);
    let c1 = m(&b[0][1], &b[2][2], &b[1][2], &b[0][2]);
    let c2 = m(&b[0][1], &b[1][2], &b[1][1], &b[0][2]);
    let det = iadd(
        &iadd(&imul(&b[0][0], &c0), &imul(&b[0][1], &c1), -1),
        &imul(&b[0][2], &c2),
        1,
    );
    Ok(det.into_iter().map(|v| -v).collect())
}

/// `res_Y` of two polynomials given as coefficient lists in `Y` (each a
/// list in `X`): evaluation at `X = 0..9`, Sylvester determinants, Newton
/// interpolation. Integer coefficients, lowest degree first, trimmed. The
/// reference of [`resultant_y`] (the present one up to fast45).
#[cfg(test)]
fn resultant_y_sylvester(
    c1: &[Vec<BigInt>],
    c2: &[Vec<BigInt>],
) -> Result<Vec<BigInt>, CannotCertify> {
    let (n1, n2) = (c1.len() - 1, c2.len() - 1);
    let size = n1 + n2;
    let xs: Vec<i64> = (0..10).collect();
    let mut vals = Vec::with_capacity(xs.len());
    for &x in &xs {
        let a: Vec<BigInt> = c1.iter().map(|c| ieval(c, x)).collect();
        let b: Vec<BigInt> = c2.iter().map(|c| ieval(c, x)).collect();
        let mut rows = Vec::with_capacity(size);
        for i in 0..n2 {
            let mut row = vec![BigInt::zero(); size];
            for k in 0..=n1 {
                row[i + k] = a[n1 - k].clone();
            }
            rows.push(row);
        }
        for i in 0..n1 {
            let mut row = vec![BigInt::zero(); size];
            for k in 0..=n2 {
                row[i + k] = b[n2 - k].clone();
            }
            rows.push(row);
        }
        vals.push(det_bareiss(rows));
    }
    let mut coef: Vec<Rat> = vals.into_iter().map(Rat::int).collect();
    for j in 1..xs.len() {
        for i in (j..xs.len()).rev() {
            coef[i] = coef[i]
                .sub(&coef[i - 1])
                .div(&Rat::small(xs[i] - xs[i - j]));
        }
    }
    let mut poly = vec![Rat::zero()];
    for i in (0..xs.len()).rev() {
        let mut new = vec![Rat::zero(); poly.len() + 1];
        for (k, v) in poly.iter().enumerate() {
            new[k + 1] = new[k + 1].add(v);
            new[k] = new[k].sub(&v.mul(&Rat::small(xs[i])));
        }
        new[0] = new[0].add(&coef[i]);
        poly = new;
    }
    if poly.iter().any(|v| !v.d.is_one()) {
        return cannot("internal: the interpolated resultant is not integer");
    }
    let mut out: Vec<BigInt> = poly.into_iter().map(|v| v.n).collect();
    while out.last().is_some_and(|v| v.is_zero()) {
        out.pop();
    }
    Ok(out)
}

// ------------------------------------------- step 4: squarefree, Sturm

/// An integer polynomial, lowest degree first, trimmed.
type IPoly = Vec<BigInt>;

fn itrim(mut a: IPoly) -> IPoly {
    while a.last().is_some_and(|v| v.is_zero()) {
        a.pop();
    }
    a
}

/// `a` divided by the gcd of its coefficients (a positive factor).
fn content_free(a: IPoly) -> IPoly {
    let mut g = BigInt::zero();
    for v in &a {
        g = num_integer_gcd(&g, v);
        if g.is_one() {
            return a;
        }
    }
    if g.is_zero() {
        return a;
    }
    a.into_iter().map(|v| v / &g).collect()
}

/// A positive multiple of the remainder of `a / b` (`b` nonzero):
/// pseudo-division with `|lc(b)|`, so signs are kept. Each step drops
/// the leading term it cancels instead of computing it.
fn prem(a: &[BigInt], b: &[BigInt]) -> IPoly {
    let lc = &b[b.len() - 1];
    let (lc_abs, negative) = (lc.abs(), lc.is_negative());
    let mut r = itrim(a.to_vec());
    while r.len() >= b.len() {
        let k = r.len() - b.len();
        let c = r.pop().unwrap_or_default();
        for v in r.iter_mut() {
            *v *= &lc_abs;
        }
        for (i, v) in b[..b.len() - 1].iter().enumerate() {
            let t = &c * v;
            if negative {
                r[i + k] += t;
            } else {
                r[i + k] -= t;
            }
        }
        r = itrim(r);
    }
    r
}

fn ideriv(a: &[BigInt]) -> IPoly {
    itrim((1..a.len()).map(|i| &a[i] * BigInt::from(i)).collect())
}

/// The Sturm sequence of `a`, each member scaled by a positive factor;
/// its last member is `gcd(a, a')` up to a factor. `a` is made primitive
/// first (a positive factor: the members shrink by its content's
/// multiples). The factors are kept small without gcds: each
/// pseudo-remainder is divided by the magnitude of the subresultant
/// sequence's `beta_i` (Collins: `|beta_1| = 1`, `|psi_1| = 1`,
/// `|psi_i| = |lc r_(i-1)|^d_(i-1) / |psi_(i-1)|^(d_(i-1) - 1)`,
/// `|beta_i| = |lc r_(i-1)| |psi_i|^d_i`, `d_i = deg r_(i-1) - deg r_i`),
/// an exact divisor (checked: quotient times divisor); its signs do not
/// matter here (a positive divisor keeps the Sturm signs). Where a
/// division were not exact (not expected) the member's content is
/// divided out instead. A constant member (the last) is kept as its sign
/// (`1` or `-1`), all that is read of it.
fn sturm(a: &[BigInt]) -> Vec<IPoly> {
    if a.len() < 2 {
        // a constant (every Burmester point at infinity): no roots
        return vec![itrim(a.to_vec())];
    }
    let a = content_free(itrim(a.to_vec()));
    let da = ideriv(&a);
    let mut seq = vec![a, da];
    let mut psi = BigInt::one();
    let mut beta = BigInt::one();
    let mut d_prev = 0usize;
    loop {
        let (r0, r1) = (&seq[seq.len() - 2], &seq[seq.len() - 1]);
        let d = r0.len() - r1.len();
        if seq.len() > 2 {
            // i >= 2: psi_i from lc(r_(i-1)) = lc(r0), d_(i-1) = d_prev
            let lc = r0[r0.len() - 1].abs();
            psi = if d_prev == 0 {
                psi
            } else {
                lc.pow(d_prev as u32) / psi.pow((d_prev - 1) as u32)
            };
            beta = lc * psi.pow(d as u32);
        }
        if r1.len() == 2 {
            // the last remainder, a constant: its sign only
            match sign_of_prem_linear(r0, r1) {
                Sign::NoSign => break,
                s => {
                    let one = BigInt::one();
                    seq.push(vec![if s == Sign::Minus { one } else { -one }]);
                    break;
                }
            }
        }
        let r = prem(r0, r1);
        if r.is_empty() {
            break;
        }
        if r.len() == 1 {
            // -r / |beta|: its sign is -r's
            seq.push(vec![if r[0].is_negative() {
                BigInt::one()
            } else {
                -BigInt::one()
            }]);
            break;
        }
        let r: IPoly = r.into_iter().map(|v| -v).collect();
        let divided: Option<IPoly> = if beta.is_one() {
            Some(r.clone())
        } else {
            r.iter()
                .map(|v| {
                    let q = v / &beta;
                    (&q * &beta == *v).then_some(q)
                })
                .collect()
        };
        seq.push(divided.unwrap_or_else(|| content_free(r)));
        d_prev = d;
    }
    seq
}

/// The sign of `prem(a, b)` for a linear `b = b1 X + b0`: that of
/// `a(-b0 / b1)` (`prem = |b1|^m a(-b0 / b1)`, `m = deg a`), so of
/// `H = sum a_i (-b0)^i b1^(m - i)` times `sign(b1)^m`. `H` in [`Wide`]
/// where it decides: each term a product of `m + 1` inputs within
/// `2^-52` and `m + 2` roundings, the sum `m` more, so within
/// `(3m + 3) 2^-52 sum |t_i|`, under `2^-46` for `m <= 16`; `|H| > 2^-32
/// sum |t_i|` (the sum computed alike) decides. Else the exact `prem`.
fn sign_of_prem_linear(a: &[BigInt], b: &[BigInt]) -> Sign {
    let m = a.len().saturating_sub(1);
    if a.is_empty() || b.len() != 2 || m > 16 {
        return prem(a, b).first().map_or(Sign::NoSign, BigInt::sign);
    }
    let (x, y) = (Wide::of(&-&b[0]), Wide::of(&b[1]));
    let one = Wide::new(1.0, 0);
    let (mut px, mut py) = (vec![one; m + 1], vec![one; m + 1]);
    for i in 1..=m {
        px[i] = px[i - 1].mul(x);
        py[i] = py[i - 1].mul(y);
    }
    let (mut h, mut t) = (Wide::ZERO, Wide::ZERO);
    for (i, c) in a.iter().enumerate() {
        let term = Wide::of(c).mul(px[i]).mul(py[m - i]);
        h = h.add(term);
        t = t.add(term.abs());
    }
    if h.exceeds(t, 32) {
        let neg = (h.m < 0.0) != (b[1].is_negative() && m % 2 == 1);
        return if neg { Sign::Minus } else { Sign::Plus };
    }
    prem(a, b).first().map_or(Sign::NoSign, BigInt::sign)
}

/// `a` squarefree: `gcd(a, a')` (the Sturm sequence's last member) a
/// constant.
fn squarefree(seq: &[IPoly]) -> bool {
    seq.last().is_some_and(|g| g.len() == 1)
}

fn sign_changes(signs: impl Iterator<Item = Sign>) -> usize {
    let mut last = Sign::NoSign;
    let mut n = 0;
    for s in signs.filter(|&s| s != Sign::NoSign) {
        if last != Sign::NoSign && s != last {
            n += 1;
        }
        last = s;
    }
    n
}

fn at_inf(seq: &[IPoly], negative: bool) -> usize {
    sign_changes(seq.iter().map(|p| {
        let s = p.last().map_or(Sign::NoSign, BigInt::sign);
        if negative && p.len() % 2 == 0 { -s } else { s }
    }))
}

/// `a / (D X - N)` for the root `x = N / D` (reduced): exact over the
/// integers by Gauss's lemma (the divisor is primitive) when `x` is a
/// root; otherwise an internal error.
fn divide_linear(a: &[BigInt], x: &Rat) -> Result<IPoly, CannotCertify> {
    let (n, d) = (&x.n, &x.d);
    let mut r = a.to_vec();
    let mut q = vec![BigInt::zero(); a.len().saturating_sub(1)];
    for k in (0..q.len()).rev() {
        // r's leading term r[k+1] X^(k+1) = c X^k (D X - N); exact
        // checked by the product (cheaper than a second division)
        let c = &r[k + 1] / d;
        if &c * d != r[k + 1] {
            return cannot("internal: a pole's factor does not divide the resultant");
        }
        r[k + 1] = BigInt::zero();
        r[k] += &c * n;
        q[k] = c;
    }
    if !r[0].is_zero() {
        return cannot("internal: a pole's factor does not divide the resultant");
    }
    Ok(itrim(q))
}

/// The sign of `p(N / D)` (of `D^deg p(N / D)`, an integer).
fn sign_at_rat(p: &[BigInt], x: &Rat) -> Sign {
    homogeneous_at(p, x, p.len().saturating_sub(1)).sign()
}

/// `D^n p(N / D)` at `x = N / D` (an integer for `n >= deg p`; one
/// positive factor `D^n` for every `p` evaluated with the same `n`).
fn homogeneous_at(p: &[BigInt], x: &Rat, n: usize) -> BigInt {
    let Some(last) = p.last() else {
        return BigInt::zero();
    };
    let mut h = last.clone();
    let mut dk = BigInt::one();
    for a in p.iter().rev().skip(1) {
        dk *= &x.d;
        h = h * &x.n + a * &dk;
    }
    h * x.d.pow((n + 1 - p.len()) as u32)
}

/// A dyadic rational `m / 2^k` (the bisection's points).
#[derive(Debug, Clone)]
struct Dyadic {
    m: BigInt,
    k: u64,
}

impl Dyadic {
    fn normal(mut m: BigInt, mut k: u64) -> Dyadic {
        if m.is_zero() {
            return Dyadic { m, k: 0 };
        }
        let z = m.trailing_zeros().unwrap_or(0).min(k);
        m >>= z;
        k -= z;
        Dyadic { m, k }
    }
    /// `(w_a a + w_b b) / (w_a + w_b)`, `w_a + w_b` a power of two `2^e`.
    fn blend(a: &Dyadic, wa: i64, b: &Dyadic, wb: i64, e: u64) -> Dyadic {
        let k = a.k.max(b.k);
        let m = (&a.m << (k - a.k)) * wa + (&b.m << (k - b.k)) * wb;
        Dyadic::normal(m, k + e)
    }
    fn rat(&self) -> Rat {
        Rat::new(self.m.clone(), BigInt::one() << self.k)
    }
    /// A rational whose denominator is a power of two (`None` otherwise).
    fn of_rat(r: &Rat) -> Option<Dyadic> {
        let k = r.d.bits() - 1;
        (r.d == BigInt::one() << k).then(|| Dyadic::normal(r.n.clone(), k))
    }
}

/// The sign of `p(m / 2^k)` (of `2^(k deg p) p(m / 2^k)`, an integer).
fn sign_at(p: &[BigInt], x: &Dyadic) -> Sign {
    let Some(last) = p.last() else {
        return Sign::NoSign;
    };
    let mut h = last.clone();
    for (j, a) in p.iter().rev().skip(1).enumerate() {
        h = h * &x.m + (a << (x.k * (j as u64 + 1)));
    }
    h.sign()
}

/// A float with a wide exponent, `m 2^e` (`m = 0` or `0.5 <= |m| < 1`):
/// the approximate signs of the isolation. Each product and sum is within
/// a relative `2^-53` of the exact one of its operands (an `f64` rounding;
/// a summand below `2^-200` of the other is dropped, within that too).
#[derive(Debug, Clone, Copy)]
struct Wide {
    m: f64,
    e: i64,
}

impl Wide {
    const ZERO: Wide = Wide { m: 0.0, e: 0 };

    fn new(m: f64, e: i64) -> Wide {
        if m == 0.0 {
            return Wide::ZERO;
        }
        let (f, x) = libm::frexp(m);
        Wide {
            m: f,
            e: e + i64::from(x),
        }
    }
    /// Within a relative `2^-52` of `v` (its leading 64 bits, rounded).
    fn of(v: &BigInt) -> Wide {
        let bits = v.bits();
        let mut digits = v.iter_u64_digits();
        let (Some(hi), lo) = (digits.next_back(), digits.next_back()) else {
            return Wide::ZERO;
        };
        let hb = bits - 64 * (bits.div_ceil(64) - 1);
        let top = if hb == 64 {
            hi
        } else {
            (hi << (64 - hb)) | (lo.unwrap_or(0) >> hb)
        };
        let m = top as f64;
        Wide::new(if v.is_negative() { -m } else { m }, bits as i64 - 64)
    }
    fn abs(self) -> Wide {
        Wide {
            m: self.m.abs(),
            e: self.e,
        }
    }
    fn mul(self, o: Wide) -> Wide {
        Wide::new(self.m * o.m, self.e + o.e)
    }
    fn add(self, o: Wide) -> Wide {
        let (a, b) = if self.m == 0.0 || (o.m != 0.0 && o.e > self.e) {
            (o, self)
        } else {
            (self, o)
        };
        let d = a.e - b.e;
        if b.m == 0.0 || d > 200 {
            return a;
        }
        Wide::new(a.m + libm::ldexp(b.m, -(d as i32)), a.e)
    }
    /// `|self| > 2^-s |o|`.
    fn exceeds(self, o: Wide, s: i64) -> bool {
        if self.m == 0.0 || o.m == 0.0 {
            return self.m != 0.0;
        }
        let oe = o.e - s;
        if self.e != oe {
            return self.e > oe;
        }
        self.m.abs() > o.m.abs()
    }
}

/// A polynomial with its coefficients' [`Wide`] approximations.
struct Approx<'a> {
    p: &'a [BigInt],
    w: Vec<Wide>,
}

impl Approx<'_> {
    fn of(p: &[BigInt]) -> Approx<'_> {
        Approx {
            p,
            w: p.iter().map(Wide::of).collect(),
        }
    }
    /// The sign of `p(x)`, `xw` within `2^-52` of `x`: Horner in [`Wide`]
    /// when it decides (below), else exact ([`sign_at`]). With the
    /// coefficients and `x` within a relative `2^-52` and each operation
    /// within `2^-53`, the computed `h` is within `(3n + 2) 2^-52 A` of
    /// `p(x)` for degree `n`, `A = sum |p_i| |x|^i`, itself within that
    /// relative error of the computed `a` (the same Horner on magnitudes):
    /// for `n <= 16` under `2^-45 a`; `|h| > 2^-32 a` decides the sign.
    fn sign_at(&self, x: &Dyadic, xw: Wide) -> Sign {
        self.approx_sign(xw).unwrap_or_else(|| sign_at(self.p, x))
    }
    /// The sign of `p(x)` where the [`Wide`] Horner decides it.
    fn approx_sign(&self, xw: Wide) -> Option<Sign> {
        if self.p.len() > 17 {
            return None;
        }
        let (mut h, mut a) = (Wide::ZERO, Wide::ZERO);
        let xa = xw.abs();
        for c in self.w.iter().rev() {
            h = h.mul(xw).add(*c);
            a = a.mul(xa).add(c.abs());
        }
        h.exceeds(a, 32)
            .then_some(if h.m > 0.0 { Sign::Plus } else { Sign::Minus })
    }
}

/// `x` within a relative `2^-52`.
fn dyadic_wide(x: &Dyadic) -> Wide {
    let w = Wide::of(&x.m);
    Wide {
        m: w.m,
        e: w.e - x.k as i64,
    }
}

/// The sign changes of the Sturm sequence at `x`.
fn changes_at(seq: &[Approx], x: &Dyadic) -> usize {
    let xw = dyadic_wide(x);
    sign_changes(seq.iter().map(|p| p.sign_at(x, xw)))
}

/// Sorted disjoint intervals `(lo, hi)`, one real root of the squarefree
/// `q` each (`seq` its Sturm sequence: counts, bisection of a power-of-two
/// Cauchy bound; the Python's steps, in integers), signs by
/// [`Approx::sign_at`].
fn isolate(q: &[BigInt], seq: &[IPoly]) -> Vec<(Rat, Rat)> {
    let approx: Vec<Approx> = seq.iter().map(|p| Approx::of(p)).collect();
    let qa = Approx::of(q);
    bisect(
        q,
        seq,
        |x| qa.sign_at(x, dyadic_wide(x)) == Sign::NoSign,
        |x| changes_at(&approx, x),
    )
}

/// [`isolate`] with exact signs throughout (its reference).
#[cfg(test)]
fn isolate_reference(q: &[BigInt], seq: &[IPoly]) -> Vec<(Rat, Rat)> {
    bisect(
        q,
        seq,
        |x| sign_at(q, x) == Sign::NoSign,
        |x| sign_changes(seq.iter().map(|p| sign_at(p, x))),
    )
}

/// The bisection of [`isolate`]: `zero(x)` whether `q(x) = 0`,
/// `changes(x)` the Sturm sequence's sign changes at `x`. Each step
/// counts them at its midpoint only (those at its left end come with the
/// interval).
fn bisect(
    q: &[BigInt],
    seq: &[IPoly],
    zero: impl Fn(&Dyadic) -> bool,
    changes: impl Fn(&Dyadic) -> usize,
) -> Vec<(Rat, Rat)> {
    let n = at_inf(seq, true) - at_inf(seq, false);
    if n == 0 {
        return Vec::new();
    }
    // the least 2^e >= 1 + max |q_i / q_n|, doubled
    let lead = q[q.len() - 1].abs();
    let target = &lead
        + q[..q.len() - 1]
            .iter()
            .map(BigInt::abs)
            .max()
            .unwrap_or_default();
    let mut e = 0u64;
    while (&lead << e) < target {
        e += 1;
    }
    let bound = Dyadic {
        m: BigInt::one() << (e + 1),
        k: 0,
    };
    let mut out = Vec::new();
    let lo = Dyadic { m: -&bound.m, k: 0 };
    let v_lo = changes(&lo);
    let mut stack = vec![(lo, bound, n, v_lo)];
    while let Some((lo, hi, k, v_lo)) = stack.pop() {
        match k {
            0 => continue,
            1 => {
                out.push((lo, hi));
                continue;
            }
            _ => {}
        }
        let mut mid = Dyadic::blend(&lo, 1, &hi, 1, 1);
        if zero(&mid) {
            let a = Dyadic::blend(&lo, 1, &hi, 3, 2);
            mid = if !zero(&a) {
                a
            } else {
                Dyadic::blend(&lo, 3, &hi, 1, 2)
            };
        }
        let v_mid = changes(&mid);
        let left = v_lo - v_mid;
        stack.push((lo, mid.clone(), left, v_lo));
        stack.push((mid, hi, k - left, v_mid));
    }
    let mut out: Vec<(Rat, Rat)> = out.iter().map(|(a, b)| (a.rat(), b.rat())).collect();
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// The certified count of five poses `[x, y, angle]`: `(finite points,
/// sliders)`, `None` where the task cannot be certified. The
/// `points/certificate` bench's hook (re-exported hidden), not API.
#[doc(hidden)]
pub fn certified_count(poses: &[[f64; 3]; 5]) -> Option<(usize, usize)> {
    certify(poses).ok().map(|c| (c.finite, c.sliders))
}

// ------------------------------------------------------ the certificate

/// The shears `u = a / q` tried in turn.
const SHEARS: [(i64, i64); 6] = [(3, 7), (-5, 11), (7, 13), (-2, 9), (11, 17), (-13, 19)];

/// A certified count: the real finite Burmester points, the real ones at
/// infinity (sliders), and what they came from.
#[derive(Debug, Clone)]
pub(crate) struct Certified {
    /// The number of real finite Burmester points.
    // read by the tests (the reference's values); the refusal reads the points
    #[cfg_attr(not(test), allow(dead_code))]
    pub(crate) finite: usize,
    /// The number of real Burmester points at infinity.
    // read by the tests (the reference's values); the refusal reads the points
    #[cfg_attr(not(test), allow(dead_code))]
    pub(crate) sliders: usize,
    /// The shear `u = a / q` (`X = x - u y`).
    pub(crate) shear: (i64, i64),
    /// Isolating intervals of the finite points' `X`, sorted.
    pub(crate) intervals: Vec<(Rat, Rat)>,
    /// `Q`, the resultant with the poles' factors divided out (integer, a
    /// positive multiple of the Python's primitive `Q`, lowest degree
    /// first).
    pub(crate) q: IPoly,
    /// `Q`'s Sturm sequence (each member a positive multiple; the one the
    /// count and the intervals came from).
    pub(crate) sturm: Vec<IPoly>,
    /// The resultant `res_Y(f1, f2)` of the sheared integer cubics.
    // read by the tests (the reference's values); the refusal reads the points
    #[cfg_attr(not(test), allow(dead_code))]
    pub(crate) resultant: Vec<BigInt>,
    /// The integer primitive cubics `f1`, `f2`.
    pub(crate) cubics: [Poly2<BigInt>; 2],
    /// The pose order used (pose 1 first, the shared poses next).
    pub(crate) order: [usize; 5],
}

/// The certificate on poses `1, i, j, k, l` for each choice of the shared
/// poses `1, i, j`: the first that certifies, else the reasons of all.
pub(crate) fn certify(poses: &[[f64; 3]; 5]) -> Result<Certified, CannotCertify> {
    let mut reasons: Vec<String> = Vec::new();
    for (i, j) in [(1, 2), (1, 3), (1, 4), (2, 3), (2, 4), (3, 4)] {
        let mut order = [0, i, j, 0, 0];
        let mut n = 3;
        for k in 1..5 {
            if k != i && k != j {
                order[n] = k;
                n += 1;
            }
        }
        let task = order.map(|k| poses[k]);
        match certify_order(&task) {
            Ok(mut c) => {
                c.order = order;
                return Ok(c);
            }
            Err(e) => reasons.push(e.0),
        }
    }
    reasons.sort();
    reasons.dedup();
    Err(CannotCertify(reasons.join("; ")))
}

/// The certificate with the shared poses 1, 2, 3 as given.
pub(crate) fn certify_order(poses: &[[f64; 3]; 5]) -> Result<Certified, CannotCertify> {
    let task = int_task(poses)?;
    let [f1, f2] = int_cubics(&task);
    let disp = displacements(poses)?;
    let all = poles(&disp);
    let pl: Vec<&(Rat, Rat)> = all.iter().flatten().collect();
    let inf_poles = 3 - pl.len();
    if inf_poles > 1 {
        return cannot("poles at infinity (poses 1, 2, 3 all with one rotation)");
    }
    for p in &pl {
        if !ip2_vanishes(&f1, &p.0, &p.1) || !ip2_vanishes(&f2, &p.0, &p.1) {
            return cannot("internal: a pole off a cubic");
        }
    }
    let (l1, l2) = (cubic_part_line(&f1)?, cubic_part_line(&f2)?);
    if (l1.0.is_zero() && l1.1.is_zero()) || (l2.0.is_zero() && l2.1.is_zero()) {
        return cannot("a cubic of degree < 3 (the line at infinity a component)");
    }
    let parallel = (&l1.0 * &l2.1 - &l1.1 * &l2.0).is_zero();
    let mut last = None;
    for (a, q) in SHEARS {
        let on = |l: &(BigInt, BigInt)| (&l.0 * a + &l.1 * q).is_zero();
        if on(&l1) || on(&l2) {
            continue;
        }
        let (c1, c2) = (shear(&f1, a, q), shear(&f2, a, q));
        let r = resultant_y(&c1, &c2)?;
        if r.is_empty() {
            return cannot("a common component (the resultant vanishes)");
        }
        let mut qp = r.clone();
        let u = Rat::new(BigInt::from(a), BigInt::from(q));
        let xs: Vec<Rat> = pl.iter().map(|p| p.0.sub(&u.mul(&p.1))).collect();
        for xp in &xs {
            qp = divide_linear(&qp, xp)?;
        }
        if xs.iter().any(|xp| sign_at_rat(&qp, xp) == Sign::NoSign) {
            return cannot(
                "a Burmester point at a pole (or coincident poles of higher multiplicity)",
            );
        }
        let seq = sturm(&qp);
        if !squarefree(&seq) {
            last = Some("a multiple common point (Q not squarefree for any shear)");
            continue;
        }
        let deg = qp.len() - 1;
        if deg > 4 {
            return cannot("internal: more than four Burmester points");
        }
        let infinite = 4 - deg;
        let sliders = if inf_poles > 0 {
            if infinite > 1 {
                return cannot("a pole at infinity and more than one Burmester point at infinity");
            }
            infinite
        } else if !parallel {
            0
        } else if infinite == 0 {
            return cannot("internal: a common asymptotic direction without a point at infinity");
        } else if infinite <= 2 {
            infinite
        } else {
            return cannot(
                "3 or 4 Burmester points at infinity (at the real direction or the circular points)",
            );
        };
        let intervals = isolate(&qp, &seq);
        return Ok(Certified {
            finite: intervals.len(),
            sliders,
            shear: (a, q),
            intervals,
            q: qp,
            sturm: seq,
            resultant: r,
            cubics: [f1, f2],
            order: [0, 1, 2, 3, 4],
        });
    }
    cannot(last.unwrap_or("no admissible shear"))
}

// ------------------------------------------- step 6: each root's point

/// Bisection steps beyond which a root is refined no further (the widest
/// isolating interval, `2^(e+2)` for `e` up to a few thousand bits, down
/// to `2^-110` of the task's reach: well under this).
const MAX_REFINE: usize = 8_192;

/// The isolated root in `(lo, hi)` of `q` refined by exact bisection (in
/// dyadic rationals: no gcds) until the interval is about `2^-110` of
/// `max(|lo|, |hi|, reach)` wide: its midpoint (exact where a midpoint is
/// the root).
fn refine(q: &[BigInt], lo: &Rat, hi: &Rat, reach: &Rat) -> Result<Rat, CannotCertify> {
    let (Some(mut lo), Some(mut hi)) = (Dyadic::of_rat(lo), Dyadic::of_rat(hi)) else {
        return cannot("internal: an isolating interval's end is not dyadic");
    };
    // log2 of a magnitude, within one
    let log2 = |n: &BigInt, d: &BigInt| n.bits() as i64 - d.bits() as i64;
    let floor = log2(&reach.n, &reach.d);
    let low = sign_at(q, &lo);
    for _ in 0..MAX_REFINE {
        let top = [&lo, &hi]
            .iter()
            .map(|v| v.m.bits() as i64 - v.k as i64)
            .fold(floor, i64::max);
        let width = Dyadic::blend(&hi, 1, &lo, -1, 0); // hi - lo
        if width.m.is_zero() || width.m.bits() as i64 - (width.k as i64) < top - 110 {
            break;
        }
        let mid = Dyadic::blend(&lo, 1, &hi, 1, 1);
        match sign_at(q, &mid) {
            Sign::NoSign => return Ok(mid.rat()),
            s if s == low => lo = mid,
            _ => hi = mid,
        }
    }
    Ok(Dyadic::blend(&lo, 1, &hi, 1, 1).rat())
}

/// The finite Burmester points `(x, y)` of a certificate, one per isolated
/// root of `Q` (in the order of the intervals): `X` refined by exact
/// bisection, `Y` the common root of the two sheared cubics over it, from
/// the first subresultant `S1(Y) = s1 Y + s0` (`Y = -s0 / s1`: at a simple
/// common point alone over its `X`, as `Q` squarefree and the `Y^3`
/// coefficients constant make every root, `s1 != 0`), then
/// `x = X + u Y`. `reach` (the task's size, `> 0`) sets the refinement's
/// absolute floor.
pub(crate) fn points(c: &Certified, reach: f64) -> Result<Vec<(f64, f64)>, CannotCertify> {
    let (a, q) = c.shear;
    let reach = Rat::of_f64(reach)?;
    let [f1, f2] = &c.cubics;
    let (c1, c2) = (shear(f1, a, q), shear(f2, a, q));
    if c1.len() != 4 || c2.len() != 4 {
        return cannot("internal: a sheared cubic without its Y^3 term");
    }
    let mut out = Vec::with_capacity(c.intervals.len());
    for (lo, hi) in &c.intervals {
        let x0 = refine(&c.q, lo, hi, &reach)?;
        // D^3 c(N / D) for each column c (degree at most 3 in X): one
        // positive factor for every entry
        let a: Vec<BigInt> = c1.iter().map(|col| homogeneous_at(col, &x0, 3)).collect();
        let b: Vec<BigInt> = c2.iter().map(|col| homogeneous_at(col, &x0, 3)).collect();
        // Sylvester rows Y f1, f1, Y f2, f2 in the powers Y^4 .. Y^0
        let z = BigInt::zero();
        let rows = [
            [&a[3], &a[2], &a[1], &a[0], &z],
            [&z, &a[3], &a[2], &a[1], &a[0]],
            [&b[3], &b[2], &b[1], &b[0], &z],
            [&z, &b[3], &b[2], &b[1], &b[0]],
        ];
        let minor = |last: usize| {
            det_bareiss(
                rows.iter()
                    .map(|r| vec![r[0].clone(), r[1].clone(), r[2].clone(), r[last].clone()])
                    .collect(),
            )
        };
        let (s1, s0) = (minor(3), minor(4));
        if s1.is_zero() {
            return cannot(
                "internal: two common points over one X (the first subresultant vanishes)",
            );
        }
        // y = -s0 / s1 and x = x0 + (a / q) y = (n0 q s1 - a s0 d0) / (d0 q s1),
        // rounded to f64 unreduced (no gcds: `to_f64` needs only d > 0)
        let (s0, s1) = if s1.is_negative() {
            (-s0, -s1)
        } else {
            (s0, s1)
        };
        let y = Rat {
            n: -&s0,
            d: s1.clone(),
        };
        let qs1 = &s1 * c.shear.1;
        let x = Rat {
            n: &x0.n * &qs1 - &s0 * &x0.d * c.shear.0,
            d: &x0.d * qs1,
        };
        out.push((x.to_f64(), y.to_f64()));
    }
    Ok(out)
}

// ------------------------------------------ the check of a listed answer

/// How far (of `size + d`) a listed Burmester point may lie from its
/// exact point (`d` the listed point's distance from the centroid).
pub(crate) const PAIRING: f64 = 1e-3;

/// Why a listed answer disagrees with the certificate: `None` where it
/// agrees. The points within `near` task sizes (`BURMESTER_NEAR`) must
/// match the exact ones one to one: each listed point there paired with
/// its own exact point within [`PAIRING`] of `size + d`, and every exact
/// point there paired with a listed one (a listed point just beyond
/// `near` sizes may pair with an exact point just within, and the other
/// way). Farther points and sliders (known only within rounding of each
/// other: a far point may be read as a slider) are not compared. Listed
/// near points left unpaired may stand two by two for a complex pair of
/// the exact task where `complex_pair` says so (a double point: the
/// library's answer for a pair that merges within its rounding, which the
/// rotations' rounding onto the unit circle may leave complex).
pub(crate) fn disagreement(
    exact: &[(f64, f64)],
    listed: &[(f64, f64)],
    origin: (f64, f64),
    size: f64,
    near: f64,
    complex_pair: &dyn Fn((f64, f64), (f64, f64)) -> bool,
) -> Option<&'static str> {
    let dist = |p: (f64, f64)| (p.0 - origin.0).hypot(p.1 - origin.1);
    let is_near = |p: (f64, f64)| dist(p) <= near * size;
    let close =
        |l: (f64, f64), e: (f64, f64)| (l.0 - e.0).hypot(l.1 - e.1) <= PAIRING * (size + dist(l));
    // every injective pairing of listed with exact points, as the exact
    // index of each listed point (`None`: unpaired); at most 4 and 4
    fn pairings(
        n: usize,
        m: usize,
        used: &mut Vec<bool>,
        at: &mut Vec<Option<usize>>,
        f: &mut dyn FnMut(&[Option<usize>]) -> bool,
    ) -> bool {
        if at.len() == n {
            return f(at);
        }
        at.push(None);
        if pairings(n, m, used, at, f) {
            return true;
        }
        at.pop();
        for k in 0..m {
            if !used[k] {
                used[k] = true;
                at.push(Some(k));
                let found = pairings(n, m, used, at, f);
                at.pop();
                used[k] = false;
                if found {
                    return true;
                }
            }
        }
        false
    }
    let ok = pairings(
        listed.len(),
        exact.len(),
        &mut vec![false; exact.len()],
        &mut Vec::with_capacity(listed.len()),
        &mut |at: &[Option<usize>]| {
            let listed_ok = at.iter().zip(listed).all(|(k, &l)| match k {
                Some(k) => close(l, exact[*k]),
                None => true,
            });
            let exact_ok = exact
                .iter()
                .enumerate()
                .all(|(k, &e)| !is_near(e) || at.contains(&Some(k)));
            if !(listed_ok && exact_ok) {
                return false;
            }
            // the near listed points left unpaired (each test exact: only
            // where the pairing holds otherwise)
            let left: Vec<(f64, f64)> = at
                .iter()
                .zip(listed)
                .filter(|(k, l)| k.is_none() && is_near(**l))
                .map(|(_, &l)| l)
                .collect();
            match left.len() {
                0 => true,
                2 => complex_pair(left[0], left[1]),
                4 => [[0, 1, 2, 3], [0, 2, 1, 3], [0, 3, 1, 2]]
                    .iter()
                    .any(|[a, b, c, d]| {
                        complex_pair(left[*a], left[*b]) && complex_pair(left[*c], left[*d])
                    }),
                _ => false,
            }
        },
    );
    if ok {
        return None;
    }
    let count = |ps: &[(f64, f64)]| ps.iter().filter(|&&p| is_near(p)).count();
    Some(if count(listed) != count(exact) {
        "the answer's count of Burmester points within 1e4 task sizes is not the float task's \
         (counted in exact arithmetic)"
    } else {
        "a listed Burmester point is not within 1e-3 of size + d of the float task's exact \
         point (found in exact arithmetic)"
    })
}

/// The largest bit length of the integer cubics' coefficients of the task
/// (poses 1, 2, 3 shared).
#[cfg(test)]
fn cubic_bits(task: &[[f64; 3]; 5]) -> Result<u64, CannotCertify> {
    let t = int_task(task)?;
    Ok(int_cubics(&t)
        .iter()
        .flat_map(|f| f.c.iter().flatten())
        .map(BigInt::bits)
        .max()
        .unwrap_or(0))
}

/// The certificate's verdict on a five-pose answer listing the finite
/// Burmester points `listed` (centers) of `poses`, with the poses'
/// centroid `origin` and size: `Some(why)` refuses the answer (see
/// [`disagreement`], with `near` the
/// [`BURMESTER_NEAR`](crate::tolerance::BURMESTER_NEAR) sizes); `None` where
/// it agrees or where the exact task cannot be certified (a degenerate or
/// ambiguous exact task: the library's own checks answer those).
pub(crate) fn refuses(
    poses: &[Pose],
    listed: &[(f64, f64)],
    origin: (f64, f64),
    size: f64,
) -> Option<&'static str> {
    let task: [[f64; 3]; 5] = poses
        .get(..5)?
        .iter()
        .map(|p| [p.position.x, p.position.y, p.angle])
        .collect::<Vec<_>>()
        .try_into()
        .ok()?;
    let c = certify(&task).ok()?;
    let exact = points(&c, size).ok()?;
    let pair = |a: (f64, f64), b: (f64, f64)| complex_pair_at(&c, a, b, origin, size);
    disagreement(
        &exact,
        listed,
        origin,
        size,
        crate::tolerance::BURMESTER_NEAR,
        &pair,
    )
}

/// How close (of `size + d`) two listed points standing for a complex pair
/// of the exact task lie to each other and to the pair.
pub(crate) const PAIR_REACH: f64 = 1e-5;

/// Whether two listed points `a`, `b` within [`PAIR_REACH`] of `size + d`
/// of each other stand for a complex pair of the certificate's task: in
/// `X` (the shear's coordinate), the disk about their midpoint of radius
/// `r` (`PAIR_REACH (size + d) (1 + |u|)` plus their distance) holds no
/// real root of `Q` (a Sturm count) and exactly two roots (Pellet's test
/// on `Q`'s Taylor coefficients there, in exact rationals:
/// `|q_2| r^2 > sum_(k != 2) |q_k| r^k`).
fn complex_pair_at(
    c: &Certified,
    a: (f64, f64),
    b: (f64, f64),
    origin: (f64, f64),
    size: f64,
) -> bool {
    let d = (a.0 - origin.0).hypot(a.1 - origin.1);
    let gap = (a.0 - b.0).hypot(a.1 - b.1);
    let reach = PAIR_REACH * (size + d);
    if !(gap <= reach) {
        return false;
    }
    let u = c.shear.0 as f64 / c.shear.1 as f64;
    let r = (reach + gap) * (1.0 + u.abs());
    let (mx, my) = ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
    let (Ok(mx), Ok(my), Ok(r)) = (Rat::of_f64(mx), Rat::of_f64(my), Rat::of_f64(r)) else {
        return false;
    };
    if r.is_zero() {
        return false;
    }
    let ur = Rat::new(BigInt::from(c.shear.0), BigInt::from(c.shear.1));
    let xm = mx.sub(&ur.mul(&my));
    // no real root within r
    let (lo, hi) = (xm.sub(&r), xm.add(&r));
    let changes = |x: &Rat| sign_changes(c.sturm.iter().map(|p| sign_at_rat(p, x)));
    if sign_at_rat(&c.q, &lo) == Sign::NoSign
        || sign_at_rat(&c.q, &hi) == Sign::NoSign
        || changes(&lo) != changes(&hi)
    {
        return false;
    }
    // Taylor coefficients at xm: repeated synthetic division
    let mut t: Vec<Rat> = c.q.iter().cloned().map(Rat::int).collect();
    let n = t.len();
    for i in 0..n {
        for j in (i..n - 1).rev() {
            let v = t[j + 1].mul(&xm);
            t[j] = t[j].add(&v);
        }
    }
    if n < 3 {
        return false;
    }
    let abs = |v: &Rat| {
        if v.n.is_negative() {
            v.neg()
        } else {
            v.clone()
        }
    };
    let mut rk = Rat::small(1);
    let (mut two, mut rest) = (Rat::zero(), Rat::zero());
    for (k, q) in t.iter().enumerate() {
        let term = abs(q).mul(&rk);
        if k == 2 {
            two = term;
        } else {
            rest = rest.add(&term);
        }
        rk = rk.mul(&r);
    }
    two.cmp(&rest) == Ordering::Greater
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `2^61 - 1`: the expected big integers are written as residues.
    const P: u64 = (1 << 61) - 1;

    fn residue(v: &BigInt) -> u64 {
        let p = BigInt::from(P);
        let r = ((v % &p) + &p) % &p;
        to_u64(&r)
    }

    /// The dyad condition's 3x3 determinant for poses 1 and `k`, `l`, `m`
    /// (indices into `disp`) at a rational point, in rationals from the
    /// exact displacements (the reference of `int_cubics`).
    fn det_at(disp: &[Disp], ks: [usize; 3], x: &Rat, y: &Rat) -> Rat {
        let one = Rat::small(1);
        let rows: Vec<[Rat; 3]> = ks
            .iter()
            .map(|&k| {
                let d = &disp[k];
                let ckx = d.c.mul(&d.tx).add(&d.s.mul(&d.ty));
                let cky = d.s.neg().mul(&d.tx).add(&d.c.mul(&d.ty));
                let mr = one.sub(&d.c);
                let ax = ckx.add(&mr.mul(x)).sub(&d.s.mul(y));
                let ay = cky.add(&d.s.mul(x)).add(&mr.mul(y));
                let sq = d.tx.mul(&d.tx).add(&d.ty.mul(&d.ty));
                let b = d.tx.mul(x).add(&d.ty.mul(y)).sub(&sq.div(&Rat::small(2)));
                [ax, ay, b]
            })
            .collect();
        let m = |a: &Rat, b: &Rat, c: &Rat, d: &Rat| a.mul(d).sub(&b.mul(c));
        let (r0, r1, r2) = (&rows[0], &rows[1], &rows[2]);
        r0[0]
            .mul(&m(&r1[1], &r1[2], &r2[1], &r2[2]))
            .sub(&r0[1].mul(&m(&r1[0], &r1[2], &r2[0], &r2[2])))
            .add(&r0[2].mul(&m(&r1[0], &r1[1], &r2[0], &r2[1])))
    }

    fn int_eval(f: &Poly2<BigInt>, x: &Rat, y: &Rat) -> Rat {
        let mut sum = Rat::zero();
        for i in 0..4 {
            for j in 0..4 - i {
                let mut t = Rat::int(f.c[i][j].clone());
                for _ in 0..i {
                    t = t.mul(x);
                }
                for _ in 0..j {
                    t = t.mul(y);
                }
                sum = sum.add(&t);
            }
        }
        sum
    }

    /// The rational Euclidean gcd (the reference of `squarefree`).
    fn uderiv(a: &[Rat]) -> UPoly {
        trim(
            (1..a.len())
                .map(|i| a[i].mul(&Rat::small(i as i64)))
                .collect(),
        )
    }

    fn ugcd(a: &[Rat], b: &[Rat]) -> UPoly {
        let (mut a, mut b) = (trim(a.to_vec()), trim(b.to_vec()));
        while !b.is_empty() {
            let r = udiv(&a, &b).1;
            a = b;
            b = r;
        }
        a
    }

    // Rational univariate polynomials (the references of the integer
    // steps).

    /// Univariate polynomials, lowest degree first, trimmed (no zero leading
    /// coefficient; the zero polynomial is empty).
    type UPoly = Vec<Rat>;
    fn trim(mut a: UPoly) -> UPoly {
        while a.last().is_some_and(|v| v.is_zero()) {
            a.pop();
        }
        a
    }

    /// Quotient and remainder of `a / b` (`b` nonzero).
    fn udiv(a: &[Rat], b: &[Rat]) -> (UPoly, UPoly) {
        let b = trim(b.to_vec());
        let mut a = trim(a.to_vec());
        let mut q = vec![Rat::zero(); (a.len() + 1).saturating_sub(b.len())];
        while !b.is_empty() && a.len() >= b.len() {
            let k = a.len() - b.len();
            let c = a[a.len() - 1].div(&b[b.len() - 1]);
            for (i, v) in b.iter().enumerate() {
                a[i + k] = a[i + k].sub(&c.mul(v));
            }
            q[k] = c;
            a = trim(a);
        }
        (trim(q), a)
    }

    /// The primitive integer polynomial with the roots and the signs of the
    /// rational `q` (a positive multiple).
    fn primitive_of(q: &[Rat]) -> IPoly {
        let mut den = BigInt::one();
        for v in q {
            den = lcm(&den, &v.d);
        }
        content_free(q.iter().map(|v| &v.n * (&den / &v.d)).collect())
    }

    fn rat_str(r: &Rat) -> String {
        if r.d.is_one() {
            r.n.to_string()
        } else {
            format!("{}/{}", r.n, r.d)
        }
    }

    struct Exact {
        finite: usize,
        sliders: usize,
        shear: (i64, i64),
        resultant: Vec<u64>,
        resultant_bits: u64,
        q: Vec<u64>,
        q_bits: u64,
        intervals: Vec<(String, String)>,
    }

    struct Case {
        label: String,
        poses: [[f64; 3]; 5],
        /// Per pose 2..5: the bit length of `c`'s denominator, and `c`'s
        /// numerator, `s`'s numerator, the denominator as residues.
        rotations: Vec<[u64; 4]>,
        /// `((i, j), residue)` of the nonzero coefficients.
        f1: Vec<((usize, usize), u64)>,
        f2: Vec<((usize, usize), u64)>,
        cubic_bits: u64,
        /// `certify_order` on the poses as given.
        order: Result<Exact, String>,
        /// `certify`: finite, sliders, the pose order that certified.
        certify: (usize, usize, [usize; 5]),
    }

    /// Expected values from `fuzz/reference/certificate_five.py` (run on
    /// the same f64 poses; big integers as residues mod `2^61 - 1`), one
    /// case a line, fields split by `|`: label, the poses, rotations, f1,
    /// f2 (`i j residue` each), the cubics' largest bit length,
    /// `certify_order` (`finite sliders a q resultant-bits Q-bits`, or its
    /// reason), the resultant, `Q` (primitive), the isolating intervals,
    /// `certify` (`finite sliders order`). The cases: `examples/five.toml`
    /// (its angles in radians as f64), four random ordinary tasks
    /// (`random.Random(44)`, positions in [-5, 5], angles in [-1.5, 1.5]),
    /// two frames of `fuzz/open/burmester_points` whose listed count is
    /// wrong (1 point + 1 slider listed, 4 exact; none listed, 4 exact,
    /// certified with the shared poses 1, 2, 4), three designer tasks
    /// (`--designer`'s crank-rocker draws, `random.Random(44)`, two crank
    /// angles `1e-2`, `1e-5`, `1e-8` apart), two more open frames whose
    /// exact answer has a slider (3 points + 1 slider, certified with the
    /// shared poses 1, 2, 5; a conic with the poses as given).
    const DATA: &str = "\
five.toml | 1.049199280691 2.279426358634 0.7892385359940679 0.734502065472 3.198658887874 0.4648409920780081 -0.378159188147 3.063048993013 0.3802512066929368 -1.268710439724 2.051150142014 0.47208754874794917 -1.411118156972 0.5974291264 0.8385310042874287 | 111 732493103823302715 1513025236701015545 1574475805297233860 111 729621583901942816 1657091159509385467 1577347325218593759 111 840706305636809599 648338294465671547 1466262603483726976 117 1229912756600075153 1731158564924527547 1147987846651546734 | 0 0 1442202657367849792 0 1 1204819298024021320 0 2 2252790165956311024 0 3 2603650098487648 1 0 2212003927023722399 1 1 1516797260112232807 1 2 1138270008697169838 2 0 1120724178656429578 2 1 2603650098487648 3 0 1138270008697169838 | 0 0 1697616435612024605 0 1 1772661975860656648 0 2 2112736637118461464 0 3 87437475853901133 1 0 1755623223561202899 1 1 824549921383718630 1 2 1466279118420009653 2 0 97641484848531457 2 1 87437475853901133 3 0 1466279118420009653 | 549 | 4 0 3 7 3296 1800 | 566176984401181199 134700407615406492 1001893539670636960 587035592426447548 77988506456367629 1046145729959260799 1766341361820302833 223510748847931145 | 1726179049200136465 602372380456128592 1414962992992789158 1483431050496021321 396753582288264765 | 0 4 4 6 6 8 32 64 | 4 0 0 1 2 3 4
random0 | -0.9146412074550625 0.41972009104596175 1.0861098494378196 -3.2333435580455614 -2.748404794218533 -1.4127082401956668 -3.833494665571362 -4.911943741129331 -1.0299289947499086 0.13713208502675656 4.89492910377551 0.5805307842943144 -1.215734288767191 -0.9495226468074396 0.5739288852371378 | 106 381102809693521076 1607771856837412241 1924744597566683979 103 1934597951036459668 1393862131754979139 371246157688862059 109 2031392050773555619 684474434023458436 274732433416848988 109 64156962286485349 684473442041059926 2241967521903919258 | 0 0 1954671050284692768 0 1 156148492465358218 0 2 435814387639068733 0 3 2204922304639091374 1 0 1500315597069479840 1 1 1756441743968371558 1 2 2119090011177072579 2 0 1609076752725774895 2 1 2204922304639091374 3 0 2119090011177072579 | 0 0 1389861492127589352 0 1 702415696646387538 0 2 571189300619206361 0 3 33157834658666440 1 0 2037855396607378994 1 1 2115185049492694508 1 2 86284270552806587 2 0 1497542056585192956 2 1 33157834658666440 3 0 86284270552806587 | 524 | 2 0 3 7 3182 1734 | 258671280838261798 168042392711966371 1558319137747751759 530040016680454885 1257803947061424365 245892387313263940 225351611977953187 1764352743406340264 | 1113696363442837449 1720082125899652746 1655679318654563316 59162059687730854 273078072045664558 | -32 -16 -16 0 | 2 0 0 1 2 3 4
random1 | -1.7388012738314007 -4.264465694217318 1.024568690718627 1.1721995591408323 -3.8799017287035245 -1.289799937860248 -4.0537245370446495 4.589232453363275 -1.176849403758692 1.253169687228409 4.695674798615805 -1.3949900117989393 -1.1412115323682928 -0.2271902951518845 1.2506683809439987 | 103 1848348294741781628 173386080685239579 457495813983540099 99 2082272042533904549 703124356568813821 223571035399266138 106 348624911322831161 193643135508433722 1957222495937373894 109 852048382212715139 540463912242605378 1454076101977689468 | 0 0 196279974568447045 0 1 268726639642482802 0 2 2064529001801825920 0 3 2051217986099999417 1 0 1314953271706599960 1 1 71512809077921266 1 2 555233877716947933 2 0 517195120612903624 2 1 2051217986099999417 3 0 555233877716947933 | 0 0 2279554807763411957 0 1 1790348535336241356 0 2 1007370607050583890 0 3 660673739375595924 1 0 1770063831030311041 1 1 1669654512936574169 1 2 2031035470979508944 2 0 921583737374602041 2 1 660673739375595924 3 0 2031035470979508944 | 514 | 4 0 3 7 3103 1709 | 2199654558513108816 29787277297035706 263158319823177979 1249405523977430146 1062538446327012484 1817356005457940388 2187569967928431111 390871795289604098 | 2216961058055230630 1887088542096846982 699276517839117633 853162136380051551 1738150055495863659 | -16 -8 -8 -4 -4 0 0 256 | 4 0 0 1 2 3 4
random2 | -3.1140683494476518 -2.416531313425583 -0.7561060761684054 -4.507952627282976 1.737168204826979 0.9501163217394302 -0.6363494910402778 -4.621664752170085 0.6407399407338459 2.3704601708394026 1.5344604709370468 -0.5140414825935492 3.3048168920634797 1.3055820356033463 0.2699208364329264 | 104 506714459317541676 770120574246229025 1799132947942663379 107 2283066808849312624 1783484533766569022 22846569108558991 109 1699411365795654207 2197790853050096863 606713118394750400 107 2277505770456921056 18054038751539155 28407607500950559 | 0 0 1896831895169902434 0 1 398977736027733718 0 2 434303301338914734 0 3 514764327381328033 1 0 439549893012599335 1 1 573738630835174800 1 2 582687769966151135 2 0 1732925646004301962 2 1 514764327381328033 3 0 582687769966151135 | 0 0 884304466342030719 0 1 980974576445426636 0 2 1990452026560525492 0 3 186626364587735962 1 0 556085398171552621 1 1 1522967917813043864 1 2 1127579144283763103 2 0 1441148029020061896 2 1 186626364587735962 3 0 1127579144283763103 | 526 | 4 0 3 7 3189 1733 | 1767670525325635054 9690726543985006 1453651049934987306 64404425548049573 1675732839032401188 130195833913548929 1904800757610836148 408760763200476109 | 10563522684725157 1359958538869304093 261969515227951072 66966550069678323 2018460785778178245 | -4 -2 -2 0 0 32 32 64 | 4 0 0 1 2 3 4
random3 | 0.4052938633104306 -2.6673850801996335 -0.13328249767027023 2.9405966949926965 1.8375533070430228 -0.46227790527971946 3.1961395571639493 3.39416196477519 -1.3691304338432202 -3.427307456039644 -2.7685349521672578 -1.4562346954635212 2.5345523360244613 1.4679038938878524 0.12960506115268045 | 111 1936007408874999023 71870697262165439 370961500245537552 103 434503072401763441 544932428870418073 1871344334858441614 107 1544373533754095554 2251745033529271099 761539844203776061 107 539591905943483377 1243002800328186378 1766321472014388238 | 0 0 794927828401388198 0 1 732853168458487012 0 2 404694214278024411 0 3 978805224109410042 1 0 1493790768307339615 1 1 1402372476307435980 1 2 23688568708785207 2 0 744693027749847399 2 1 978805224109410042 3 0 23688568708785207 | 0 0 242036868883906078 0 1 611373429299452749 0 2 93843723704016560 0 3 1503563319461316160 1 0 288664311555750770 1 1 2157890853818969136 1 2 517374837881488490 2 0 377498147149446535 2 1 1503563319461316160 3 0 517374837881488490 | 528 | 2 0 3 7 3191 1723 | 2087052916888692448 783759553536652427 2119267437998596977 888860049260894020 493908053047357370 908944401290992882 1006062950724334317 1528612988856808625 | 1351442423326699030 1845971497105203225 673601907222138778 553696113276632559 133544629025062855 | -256 0 0 256 | 2 0 0 1 2 3 4
far-ghost-from-an-angle-measured-choice-3783e8a2 task | -8.86718650390625 819960937500.0 -3.90625e-12 -8.86718650390625 819960937500.0 0.0 9.960937499999999e-07 386093750000.0 2.7648437500000003e-08 -70.03906150390627 386093750000.0 -3.90625e-06 -723.5156240039064 386093749999.96094 0.00390625 | 183 1529973893286962213 1446617873039800367 775869115926731739 159 1349023921746453237 587051544585176940 956819224906194186 141 355362355885104191 2250505138172804094 1950480653329114048 123 75391311971152402 9007210717011826 2230451697242541551 | 0 0 1130177872125585474 0 1 1994922622035948982 0 2 1211556619323746703 0 3 391805561542723549 1 0 892106287252230360 1 1 1903008811047298020 1 2 254271091933003492 2 0 1240715266781493859 2 1 391805561542723549 3 0 254271091933003492 | 0 0 1764300763540759763 0 1 641672321638914249 0 2 2012695830028515297 0 3 1160108101537215181 1 0 1673669971037719661 1 1 1509961418254602378 1 2 1927086417623373685 2 0 2207776739981152572 2 1 1160108101537215181 3 0 1927086417623373685 | 708 | 4 0 3 7 3962 2269 | 735503170222186696 368944073767175939 1518777192810177117 2092151343722778187 2209049111546860571 1165304565356366229 379113920519763850 852643655898961473 | 1830471791337571016 1677326528379055120 603636595749557535 89867286278644621 1249848417297634934 | -258771779584 -258503344128 -258503344128 -258234908672 -206158430208 -137438953472 0 5846006549323611672814739330865132078623730171904 | 4 0 0 1 2 3 4
no-points-from-an-angle-measured-choice-2683252a moved | 1222350383.195415 -305711581.83519876 -101577.36034265358 4850610.9421027675 -1213134.280645759 -101574.218751 9701193405603.488 -2426282445907.3125 -101574.218751 21.514809289400656 -5.182804670138333 -101574.21875 4850610.9421027675 -1213134.280645759 -101577.36034265358 | 104 1757259635326225442 1120395292080476686 548583373887468513 104 1757259635326225442 1120395292080476686 548583373887468513 104 2014662912017077653 1631854922723246102 291180097330834026 1 1 0 1 | 0 0 1736171862901847424 0 1 223857104371739688 0 2 2100217169505311561 0 3 1372086191988953824 1 0 1490302629982624352 1 1 1734682278083900925 1 2 486933807192812977 2 0 1612042890489604953 2 1 1372086191988953824 3 0 486933807192812977 | 0 0 1933477120198789318 0 1 637813486428755341 0 2 19895983726782475 1 0 867503048927976673 1 1 302476200775567586 2 0 2285947025486911476 | 477 | cannot: a cubic of degree < 3 (the line at infinity a component) |  |  |  | 4 0 0 1 3 2 4
designer k=2 | -192.17384391933138 -168.06084947746524 -0.2726948699241527 -179.68317230347535 -138.2834666880529 -0.5584023869070822 -179.78671223083123 -138.2678340770443 -0.558619336016774 -205.24372956186 -157.18884742591652 -0.3630086897979289 -205.35916578706014 -157.41449770363613 -0.36071560233050803 | 111 1187210355631288118 1945393096894114461 1119758553489248457 107 1837787495269045041 54033066354068315 468125882688826574 113 200648757786202237 720372433390850739 2109697851054862210 113 2246190508863182598 1296838359546032275 64156099977881849 | 0 0 735314770050025249 0 1 462486560803318762 0 2 2123239177685842630 0 3 715844290032952305 1 0 1377999667926100575 1 1 337459489612724123 1 2 1720906702760429601 2 0 692850293619294457 2 1 715844290032952305 3 0 1720906702760429601 | 0 0 1118082825144741938 0 1 1237571588140915399 0 2 715735663951230161 0 3 687195391596896425 1 0 2168199697804634401 1 1 1377841691362032928 1 2 1625597300755687404 2 0 838043938660881942 2 1 687195391596896425 3 0 1625597300755687404 | 515 | 4 0 3 7 3047 1695 | 974086688903275562 508681336263755727 1526953659613984132 2199452493710594954 59791509840140125 121699586478252102 2254999950379383988 1519487643658398277 | 809583957620392042 35628272199183833 1895956588365329084 1558214052177602775 1663852598200588995 | -128 -64 -64 0 32 48 48 64 | 4 0 0 1 2 3 4
designer k=5 | -209.35891785129817 -162.30937501211866 -0.9459831854329868 -184.39524602870296 -193.5109328178659 -1.1352732330464579 -184.3957823180736 -193.51042601530017 -1.1352689772541633 -122.30515594657057 -231.78670510883575 -1.557259853151308 -113.79585673626622 -211.66262727756762 -1.5407871426237596 | 107 1265589644846699752 234180500614080395 1040323733111171863 113 2066430886397618311 1873069934067809703 243915722443446136 107 687252212312083610 1206942497039460572 1618661165645788005 109 1093234751782869919 1260921625861678627 1212889732407534688 | 0 0 2052829231836560052 0 1 41599501704857058 0 2 1009944203835490688 0 3 1488790556503035291 1 0 1751994092353964123 1 1 1951545871515402753 1 2 2266741625334350839 2 0 1467535212122527250 2 1 1488790556503035291 3 0 2266741625334350839 | 0 0 611315606238123957 0 1 779774726770168636 0 2 1997961532485518183 0 3 1399512965853058033 1 0 2573999014946556 1 1 1267936014438407129 1 2 590293487696860202 2 0 2049176108220599125 2 1 1399512965853058033 3 0 590293487696860202 | 509 | 4 0 3 7 3018 1660 | 1992078864951859526 1773755988865677051 666481142501834127 1026833437166235146 1231209639526873386 2070754687093898680 2258049393618800870 91408294753067577 | 1918111940672853863 2010696126652506726 620714088541758759 1400456146367755294 740912376464083691 | -256 -192 -136 -132 -132 -128 -128 0 | 4 0 0 1 2 3 4
designer k=8 | -94.8391650730893 400.8611681693843 -0.610989706021356 9.237441704734131 368.7815449578821 -1.3152714097164362 9.237441306115173 368.78154496009375 -1.3152714077969931 3.9518356820973395 410.77534100715917 -1.1719599220487487 -45.023816484370215 422.84587039467374 -0.9103468785892442 | 105 1415015043583662728 945749457384563936 890845557816075639 109 1528657121094471627 684443713548778427 777467363095932980 109 700342183129022151 108005303852720108 1605782301061382456 111 1073183560502963107 936578929492839441 1233785348617573468 | 0 0 503425600009546777 0 1 1402365995954380183 0 2 44651993796774368 0 3 1533021185514889175 1 0 702791554073448731 1 1 837148097962891339 1 2 184944402156575016 2 0 179388859652576790 2 1 1533021185514889175 3 0 184944402156575016 | 0 0 898250806107654916 0 1 2029753694054086708 0 2 1272348221633242877 0 3 720240916178399532 1 0 1263886582564162086 1 1 232066338212281726 1 2 1422379437576420816 2 0 1889759744371131828 2 1 720240916178399532 3 0 1422379437576420816 | 506 | 4 0 3 7 2996 1664 | 296310824534788927 1681588018594801141 355445892504625464 375837439199285286 1215956845087731894 700808784162329164 1470206958654949788 1169531432692978830 | 301981558657355539 1297213884231930174 415490989064694917 822806978613673724 998942294740469599 | -256 -192 -192 -160 -160 -144 -144 -128 | 4 0 0 1 2 3 4
point-not-found-in-another-frame-ac2bde46 task | -1.1561532346410208 4.04765625 3.141592653589793 -1.4703125000000001 3.94765635 0.0 -1.4703125000000001 4.04765625 0.0 -1.1561532346410208 3.94765625 3.141592653589793 -1.4703125000000001 3.94755125 -1.6e-07 | 108 2064586511228060215 2273180530507303211 241256497985633738 108 2064586511228060215 2273180530507303211 241256497985633738 1 1 0 1 104 474654380369214560 2327024556043202 1975303816920335263 | 0 0 237835758760246698 0 1 162844703407612594 1 0 1810980805191706528 1 1 869038901069284204 | 0 0 2246435976162716261 0 1 338336953517428102 0 2 720417642323151516 0 3 1279783802005981870 1 0 102996777832192812 1 1 1497000044232554580 2 0 1996473702719928042 2 1 1279783802005981870 | 349 | cannot: a cubic of degree < 3 (the line at infinity a component) |  |  |  | 3 1 0 1 4 2 3
point-not-found-in-another-frame-cbc8befa moved | 0.00046387496619138647 0.0009893582466233817 7.999999999999 0.000609375 0.0 7.999999999999 0.000609375 0.0 4.858407346410207 0.00046387496619138647 0.0009893582466233817 4.858407346410207 0.0006093749010641753 -1.4550003380861357e-11 8.0 | 1 1 0 1 106 1739903059205353253 2080607761576533986 565939950041895130 106 1739903059205353253 2080607761576533986 565939950041895130 101 549755496919 1267763295104794624 549756130857 | 0 0 2294226369745233443 0 1 1229185864006070605 0 2 1193549018128546663 1 0 535928746824971664 1 1 1986270353534961668 2 0 1112293991085147288 | 0 0 489128418943752552 0 1 751544948934511462 0 2 17435370551084553 0 3 2277049713890002012 1 0 2079567356394845389 1 1 1953294223910627031 1 2 600407941266988846 2 0 1083818587651726375 2 1 2277049713890002012 3 0 600407941266988846 | 412 | cannot: a cubic of degree < 3 (the line at infinity a component) |  |  |  | 3 1 0 1 4 2 3";

    fn cases() -> Vec<Case> {
        fn nums<T: std::str::FromStr>(field: &str) -> Vec<T>
        where
            T::Err: std::fmt::Debug,
        {
            field
                .split_whitespace()
                .map(|v| v.parse().unwrap())
                .collect()
        }
        fn coefficients(field: &str) -> Vec<((usize, usize), u64)> {
            nums::<u64>(field)
                .chunks(3)
                .map(|c| ((c[0] as usize, c[1] as usize), c[2]))
                .collect()
        }
        DATA.lines()
            .map(|line| {
                let f: Vec<&str> = line.split(" | ").collect();
                let p: Vec<f64> = nums(f[1]);
                let order = if f[6].starts_with("cannot: ") {
                    Err(f[6]["cannot: ".len()..].to_string())
                } else {
                    let o: Vec<i64> = nums(f[6]);
                    let iv: Vec<String> = f[9].split_whitespace().map(str::to_string).collect();
                    Ok(Exact {
                        finite: o[0] as usize,
                        sliders: o[1] as usize,
                        shear: (o[2], o[3]),
                        resultant: nums(f[7]),
                        resultant_bits: o[4] as u64,
                        q: nums(f[8]),
                        q_bits: o[5] as u64,
                        intervals: iv.chunks(2).map(|c| (c[0].clone(), c[1].clone())).collect(),
                    })
                };
                let c: Vec<usize> = nums(f[10]);
                Case {
                    label: f[0].to_string(),
                    poses: std::array::from_fn(|k| [p[3 * k], p[3 * k + 1], p[3 * k + 2]]),
                    rotations: nums::<u64>(f[2])
                        .chunks(4)
                        .map(|r| [r[0], r[1], r[2], r[3]])
                        .collect(),
                    f1: coefficients(f[3]),
                    f2: coefficients(f[4]),
                    cubic_bits: f[5].trim().parse().unwrap(),
                    order,
                    certify: (c[0], c[1], [c[2], c[3], c[4], c[5], c[6]]),
                }
            })
            .collect()
    }

    /// Each case's finite points by `certificate_five.py`'s `points_of` (mpmath,
    /// 50 digits, rounded to f64): label, then `x y` per point in its order.
    const POINTS: &str = "\
five.toml | 1.8096286353591149e-12 -1.2698100992181122e-12 4.000000000000685 -1.5589419303707116e-12 9.141553542891431 5.477137731301525 28.569489334786752 -40.15778659754287
random0 | -27.51402252991264 8.251050072848727 -3.6885331284552194 -1.1453549620434236
random1 | -20.457175525532254 -27.198003962774322 -15.73871806194064 -25.33499516563052 -2.880069766189269 -1.5184408948096777 1.2426259379914597 -0.06461070916933928
random2 | -9.082776410139736 -12.966222068395394 -0.2812621597266689 2.3462947803388046 -1.0824646881358937 -2.5437532125302265 51.210759674215986 -17.79565002708756
random3 | -1.5784066401958408 0.6971015516175997 7.817423751988794 -3.243388663948926
far-ghost-from-an-angle-measured-choice-3783e8a2 task | -209788418.0367162 603036236825.022 85.89602915905671 603027338629.8086 -70.1852268748019 386093420615.0845 224451663054364.4 603036241152.5342
no-points-from-an-angle-measured-choice-2683252a moved | 2.4933041821393077e+21 9.969171594440423e+21 14551308.163940558 -3639297.787762919 2263053485748.055 -1256576200894.5476 161564525060.26395 -9659140452192.357
designer k=2 | -161.17909668741459 -217.2703846006155 -84.39877584893257 -79.13921839514192 -94.31412734101976 -299.8937136031696 -35.790208131340925 -218.38382042818174
designer k=5 | -371.6048397335646 -308.7472129021805 -241.65313134433723 -252.03535871856457 -275.4331897198544 -335.1987079883187 -301.99313053797204 -407.32685076257036
designer k=8 | -122.86252368210977 251.95483048359597 -44.427497911755864 294.05967050027186 -50.967710268957475 232.10272362857114 -70.60549532108062 161.647926380063
point-not-found-in-another-frame-ac2bde46 task | -875413461.5915049 3.997656275 -1.313232867318606 3.99765627499996 -1.3132328673205105 3.94755123743367
point-not-found-in-another-frame-cbc8befa moved | 0.0005366249336563596 0.0004946791160408921 0.0005366249830956933 0.0004946791233116909 14.54931937278598 -98.92703003062458";

    /// The size and centroid of `certificate_five.py`'s `size_c`.
    fn size_c(poses: &[[f64; 3]; 5]) -> (f64, (f64, f64)) {
        let cx = poses.iter().map(|p| p[0]).sum::<f64>() / 5.0;
        let cy = poses.iter().map(|p| p[1]).sum::<f64>() / 5.0;
        let s = poses
            .iter()
            .map(|p| (p[0] - cx).hypot(p[1] - cy))
            .fold(0.0, f64::max);
        (s, (cx, cy))
    }

    // ---------------------------------------------------- step 6

    #[test]
    fn points_match_the_reference() {
        let reference: Vec<(String, Vec<(f64, f64)>)> = POINTS
            .lines()
            .map(|l| {
                let (label, rest) = l.split_once(" | ").unwrap();
                let v: Vec<f64> = rest
                    .split_whitespace()
                    .map(|v| v.parse().unwrap())
                    .collect();
                (
                    label.to_string(),
                    v.chunks(2).map(|c| (c[0], c[1])).collect(),
                )
            })
            .collect();
        let cases = cases();
        assert_eq!(cases.len(), reference.len());
        for (case, (label, expected)) in cases.iter().zip(&reference) {
            assert_eq!(&case.label, label);
            let c = certify(&case.poses).unwrap();
            let (size, o) = size_c(&case.poses);
            let got = points(&c, size).unwrap();
            assert_eq!(got.len(), expected.len(), "{label}");
            assert_eq!(got.len(), c.finite, "{label}");
            for (g, e) in got.iter().zip(expected) {
                let d = (e.0 - o.0).hypot(e.1 - o.1);
                let off = (g.0 - e.0).hypot(g.1 - e.1) / (size + d);
                assert!(off <= 1e-12, "{label}: {g:?} against {e:?} ({off:e})");
            }
            // the points are common points of the float cubics, in exact
            // arithmetic: each within rounding of both (their values at the
            // point against the terms' magnitude)
            for &(x, y) in &got {
                let (xr, yr) = (Rat::of_f64(x).unwrap(), Rat::of_f64(y).unwrap());
                for f in &c.cubics {
                    let mut mag = 0.0;
                    for i in 0..4 {
                        for j in 0..4 - i {
                            let t = f.c[i][j]
                                .to_string()
                                .parse::<f64>()
                                .unwrap_or(f64::INFINITY);
                            mag += t.abs() * x.abs().powi(i as i32) * y.abs().powi(j as i32);
                        }
                    }
                    let v = int_eval(f, &xr, &yr).to_f64().abs();
                    assert!(
                        v <= 1e-9 * mag,
                        "{label}: ({x}, {y}) off a cubic: {v:e} of {mag:e}"
                    );
                }
            }
        }
    }

    /// A task bisected to where two Burmester points merge (the proptest
    /// `issue24_burmester_points_near_merging_in_any_frame`'s draw): the
    /// library lists a double point at `(-10.1544, -0.6154)` where the
    /// certificate's task has a complex pair (mpmath on `certificate_five.py`'s
    /// `Q`: `X = -9.89059897527 +- 7.18e-5 i`, `3.4e-6` of `(size + d)(1 + |u|)`).
    #[test]
    fn a_double_point_stands_for_a_complex_pair_only_within_reach() {
        let t = [
            [3.0653607684151782, 3.404510322410228, -1.8656328355815006],
            [0.6720586959400408, 4.3336256718586785, -1.21374477807433],
            [0.48196293416697733, 3.573544204279525, -1.1586064861140164],
            [2.2385573593654735, 1.880116991393753, -1.6214637585185665],
            [3.2134645568473554, 1.1691282560365681, -1.91927971680065],
        ];
        let c = certify(&t).unwrap();
        assert_eq!((c.finite, c.sliders), (2, 0));
        let (size, o) = size_c(&t);
        let double = (-10.154351762279195, -0.6154231671715791);
        assert!(complex_pair_at(&c, double, double, o, size));
        // a near pair (not one point) there also
        let other = (double.0 + 1e-7, double.1 - 1e-7);
        assert!(complex_pair_at(&c, double, other, o, size));
        // not two points too far apart, not at a real point, not away
        let far = (double.0 + 1e-3, double.1);
        assert!(!complex_pair_at(&c, double, far, o, size));
        let real = (-0.013427726864169598, 1.5320186783702125);
        assert!(!complex_pair_at(&c, real, real, o, size));
        let away = (-10.0, -0.6);
        assert!(!complex_pair_at(&c, away, away, o, size));
        // the whole answer: accepted, and refused without the pair
        let listed = [
            real,
            (-0.2697285685092796, -3.208431104658629),
            double,
            double,
        ];
        let exact = points(&c, size).unwrap();
        let pair = |a, b| complex_pair_at(&c, a, b, o, size);
        assert_eq!(disagreement(&exact, &listed, o, size, 1e4, &pair), None);
        assert!(disagreement(&exact, &listed[..3], o, size, 1e4, &pair).is_some());
    }

    #[test]
    fn a_listed_answer_is_judged_by_the_exact_near_points() {
        let o = (0.0, 0.0);
        let exact = [(1.0, 0.0), (1.0, 1e-9), (5.0, 5.0), (3e4, 0.0)];
        let near = 1e4;
        let no = |_: (f64, f64), _: (f64, f64)| false;
        // all four listed; the far one may be left out or read elsewhere
        assert_eq!(disagreement(&exact, &exact, o, 1.0, near, &no), None);
        assert_eq!(disagreement(&exact, &exact[..3], o, 1.0, near, &no), None);
        // a double point for two nearly merging exact points
        let double = [(1.0, 5e-10), (1.0, 5e-10), (5.0, 5.0)];
        assert_eq!(disagreement(&exact, &double, o, 1.0, near, &no), None);
        // one of the merging pair lost: a near count that differs
        let lost = [(1.0, 0.0), (5.0, 5.0)];
        assert!(
            disagreement(&exact, &lost, o, 1.0, near, &no)
                .unwrap()
                .contains("count")
        );
        // a simple point listed twice, a point off its own, a ghost
        let twice = [(5.0, 5.0), (5.0, 5.0), (1.0, 0.0)];
        assert!(disagreement(&exact[1..], &twice, o, 1.0, near, &no).is_some());
        let off = [(1.0, 0.0), (1.0, 1e-9), (5.0, 5.02)];
        let why = disagreement(&exact, &off, o, 1.0, near, &no).unwrap();
        assert!(why.contains("not within"), "{why}");
        let ghost = [(1.0, 0.0), (1.0, 1e-9), (5.0, 5.0), (-3.0, 2.0)];
        assert!(disagreement(&exact, &ghost, o, 1.0, near, &no).is_some());
        // within 1e-3 of size + d: a far-out near point with its own reach
        let within = [(1.0, 0.0), (1.0, 1e-9), (5.0 + 4e-3, 5.0)];
        assert_eq!(disagreement(&exact, &within, o, 1.0, near, &no), None);
        // across the near boundary: a listed point just beyond pairs with an
        // exact point just within
        let edge_exact = [(1e4 - 1e-3, 0.0)];
        let edge_listed = [(1e4 + 1e-3, 0.0)];
        assert_eq!(
            disagreement(&edge_exact, &edge_listed, o, 1.0, near, &no),
            None
        );
        assert_eq!(
            disagreement(&edge_listed, &edge_exact, o, 1.0, near, &no),
            None
        );
        // no exact near point, none listed near
        assert_eq!(disagreement(&[], &[(2e4, 0.0)], o, 1.0, near, &no), None);
        assert!(disagreement(&[], &[(2.0, 0.0)], o, 1.0, near, &no).is_some());
        // a double point where the exact task has a complex pair: accepted
        // only as `complex_pair` says
        let yes = |_: (f64, f64), _: (f64, f64)| true;
        let pair = [
            (1.0, 0.0),
            (1.0, 1e-9),
            (5.0, 5.0),
            (-3.0, 2.0),
            (-3.0, 2.0),
        ];
        assert!(disagreement(&exact, &pair, o, 1.0, near, &no).is_some());
        assert_eq!(disagreement(&exact, &pair, o, 1.0, near, &yes), None);
        // never one point alone, nor for a missing exact point
        assert!(disagreement(&exact, &ghost, o, 1.0, near, &yes).is_some());
        assert!(disagreement(&exact, &lost, o, 1.0, near, &yes).is_some());
    }

    fn max_bits(vs: impl IntoIterator<Item = BigInt>) -> u64 {
        vs.into_iter().map(|v| v.bits()).max().unwrap_or(0)
    }

    // ------------------------------------ the fast paths and references

    /// A xorshift stream for the random agreements below.
    struct Stream(u64);

    impl Stream {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
        /// A random integer of up to `bits` bits, either sign, often with
        /// long runs of zero or one bits.
        fn int(&mut self, bits: u64) -> BigInt {
            let n = self.next() % (bits + 1);
            let mut v = BigInt::zero();
            while v.bits() < n {
                let w = match self.next() % 4 {
                    0 => 0,
                    1 => u64::MAX,
                    _ => self.next(),
                };
                v = (v << 64) + w;
            }
            v >>= v.bits().saturating_sub(n);
            if self.next() % 2 == 0 { -v } else { v }
        }
    }

    #[test]
    fn lehmer_gcd_matches_euclid() {
        fn euclid(a: &BigInt, b: &BigInt) -> BigInt {
            let (mut a, mut b) = (a.abs(), b.abs());
            while !b.is_zero() {
                let r = &a % &b;
                a = b;
                b = r;
            }
            a
        }
        let mut r = Stream(0x5851_f42d_4c95_7f2d);
        for bits in [1, 40, 64, 65, 128, 300, 1000, 4000] {
            for _ in 0..60 {
                let g = r.int(bits / 2 + 1);
                let (a, b) = (r.int(bits), r.int(bits));
                // a common factor often, equal and zero operands sometimes
                let (a, b) = match r.next() % 5 {
                    0 => (&a * &g, &b * &g),
                    1 => (a.clone(), a.clone()),
                    2 => (a, BigInt::zero()),
                    _ => (a, b),
                };
                assert_eq!(num_integer_gcd(&a, &b), euclid(&a, &b), "{a} {b}");
                assert_eq!(num_integer_gcd(&b, &a), euclid(&a, &b), "{a} {b}");
            }
        }
    }

    /// The Sturm sequence by rational remainders (`udiv`), each member
    /// made primitive (the reference of `sturm`, up to positive factors).
    fn primitive_sturm(q: &[BigInt]) -> Vec<IPoly> {
        let rat = |p: &IPoly| -> UPoly { p.iter().cloned().map(Rat::int).collect() };
        let mut reference = vec![content_free(q.to_vec()), content_free(ideriv(q))];
        loop {
            let (a, b) = (
                &reference[reference.len() - 2],
                &reference[reference.len() - 1],
            );
            let r = udiv(&rat(a), &rat(b)).1;
            if r.is_empty() {
                break;
            }
            reference.push(primitive_of(&r.iter().map(Rat::neg).collect::<UPoly>()));
        }
        reference
    }

    /// The fast steps against their references (the present path up to
    /// fast45) on one task: displacements, poles, and for the shears in
    /// turn up to the first squarefree `Q` (the one `certify_order`
    /// takes) the resultant, the Sturm sequence (up to positive factors)
    /// and the isolating intervals; `certify_order`'s fields equal to
    /// them. Returns the number of shears compared and whether a
    /// certificate was compared.
    fn agree_with_the_references(label: &str, poses: &[[f64; 3]; 5]) -> (usize, bool) {
        let (disp, reference) = match (displacements(poses), displacements_reference(poses)) {
            (Ok(a), Ok(b)) => (a, b),
            (Err(a), Err(b)) => {
                assert_eq!(a, b, "{label}");
                return (0, false);
            }
            (a, b) => panic!("{label}: {:?} against {:?}", a.err(), b.err()),
        };
        for (a, b) in disp.iter().zip(&reference) {
            assert_eq!(
                (&a.c, &a.s, &a.tx, &a.ty),
                (&b.c, &b.s, &b.tx, &b.ty),
                "{label}"
            );
        }
        let all = poles(&disp);
        assert_eq!(all, poles_reference(&reference), "{label}");
        let pl: Vec<&(Rat, Rat)> = all.iter().flatten().collect();
        let [f1, f2] = int_cubics(&int_task(poses).unwrap());
        let cert = certify_order(poses);
        let mut compared = 0;
        for (a, q) in SHEARS {
            let (c1, c2) = (shear(&f1, a, q), shear(&f2, a, q));
            if c1.len() != 4 || c2.len() != 4 {
                assert!(resultant_y(&c1, &c2).is_err());
                continue;
            }
            let r = resultant_y(&c1, &c2).unwrap();
            assert_eq!(r, resultant_y_sylvester(&c1, &c2).unwrap(), "{label}");
            compared += 1;
            let u = Rat::new(BigInt::from(a), BigInt::from(q));
            let mut qp = r.clone();
            for p in &pl {
                match divide_linear(&qp, &p.0.sub(&u.mul(&p.1))) {
                    Ok(v) => qp = v,
                    Err(_) => return (compared, false),
                }
            }
            if r.is_empty() || qp.is_empty() {
                return (compared, false);
            }
            let (seq, seq_ref) = (sturm(&qp), primitive_sturm(&qp));
            let primitive: Vec<IPoly> = seq.iter().cloned().map(content_free).collect();
            assert_eq!(primitive, seq_ref, "{label}");
            if !squarefree(&seq) {
                continue;
            }
            let iv = isolate(&qp, &seq);
            assert_eq!(iv, isolate_reference(&qp, &seq_ref), "{label}");
            let certified = match &cert {
                Ok(c) if c.shear == (a, q) => {
                    assert_eq!(
                        (&c.resultant, &c.q, &c.intervals),
                        (&r, &qp, &iv),
                        "{label}"
                    );
                    assert_eq!(c.finite, iv.len(), "{label}");
                    true
                }
                _ => false,
            };
            return (compared, certified);
        }
        (compared, false)
    }

    #[test]
    fn fast_steps_agree_with_the_present_ones() {
        let (mut compared, mut certified) = (0, [0; 3]);
        let mut tally = |kind: usize, (n, c): (usize, bool)| {
            compared += n;
            certified[kind] += usize::from(c);
        };
        for case in &cases() {
            tally(0, agree_with_the_references(&case.label, &case.poses));
        }
        let far = [
            [1e300, 2e299, 0.1],
            [-3e300, 1.5e300, 0.7],
            [2e300, -1e300, -0.4],
            [5e299, 7e299, 1.2],
            [-1e300, -2e300, 2.0],
        ];
        for (label, f) in [("far", 1.0), ("near", 1e-600)] {
            let poses = far.map(|p| [p[0] * f, p[1] * f, p[2]]);
            tally(0, agree_with_the_references(label, &poses));
        }
        // random tasks: ordinary ones (positions in [-5, 5], angles in
        // [-1.5, 1.5]), equal angles (poles at infinity), and ones whose
        // coordinates mix magnitudes 1e-300..1e300
        let mut r = Stream(0x6a09_e667_f3bc_c909);
        let mut unit = move || (r.next() >> 11) as f64 / (1u64 << 53) as f64;
        for trial in 0..360 {
            let mut poses: [[f64; 3]; 5] = std::array::from_fn(|_| {
                [10.0 * unit() - 5.0, 10.0 * unit() - 5.0, 3.0 * unit() - 1.5]
            });
            if trial % 12 == 1 {
                poses[1][2] = poses[0][2];
            }
            if trial >= 300 {
                for p in poses.iter_mut() {
                    for v in p.iter_mut().take(2) {
                        *v *= 10f64.powi((600.0 * unit()) as i32 - 300);
                    }
                }
            }
            let kind = if trial >= 300 { 2 } else { 1 };
            tally(
                kind,
                agree_with_the_references(&format!("random {trial}"), &poses),
            );
        }
        // nearly all certify with the poses as given (the module's cases
        // certified in another order aside)
        assert!(compared >= 370, "{compared}");
        assert!(
            certified[0] >= 10 && certified[1] >= 290 && certified[2] >= 55,
            "{certified:?}"
        );
    }

    #[test]
    fn approximate_signs_match_the_exact_ones() {
        // random polynomials of degree 0..=6 with 1..40000-bit
        // coefficients, some with a dyadic root, at dyadic points of
        // numerators up to 4000 bits over 2^0..2^3000, the roots among
        // them: where the Wide Horner decides, its sign is exact
        let mut r = Stream(0x1405_7b7e_f767_814f);
        let (mut decided, mut total) = (0, 0);
        for trial in 0..400 {
            let bits = [1, 64, 700, 5000, 40000][trial % 5];
            let deg = (r.next() % 7) as usize;
            let mut p: IPoly = (0..=deg).map(|_| r.int(bits)).collect();
            let root = Dyadic::normal(r.int(80), r.next() % 100);
            if trial % 3 == 0 {
                // times (2^k X - m): a root at m / 2^k
                let lin = vec![-root.m.clone(), BigInt::one() << root.k];
                p = imul(&p, &lin);
            }
            let p = itrim(p);
            let a = Approx::of(&p);
            for t in 0..20 {
                let x = match t {
                    0 => root.clone(),
                    1 => Dyadic::normal(BigInt::zero(), 0),
                    _ => Dyadic::normal(r.int([3, 60, 4000][t % 3]), r.next() % 3000),
                };
                let exact = sign_at(&p, &x);
                assert_eq!(a.sign_at(&x, dyadic_wide(&x)), exact, "trial {trial}");
                if let Some(s) = a.approx_sign(dyadic_wide(&x)) {
                    assert_eq!(s, exact, "trial {trial} t {t}");
                    decided += 1;
                }
                total += 1;
            }
        }
        // the approximation decides nearly everywhere (not at roots)
        assert!(decided * 10 > total * 8, "{decided} of {total}");
        // Wide's leading bits: exact below 2^53, rounded above
        for v in [1i64, -3, 1 << 52, (1 << 53) + 1, i64::MAX, i64::MIN + 1] {
            let w = Wide::of(&BigInt::from(v));
            assert_eq!(libm::ldexp(w.m, w.e as i32), v as f64, "{v}");
        }
        let w = Wide::of(&(BigInt::from(3) << 5000));
        assert_eq!((w.m, w.e), (0.75, 5002));
    }

    #[test]
    fn approximate_remainder_signs_match_the_exact_ones() {
        // a of degree 0..=6, b linear, 1..40000-bit coefficients; b's
        // root a root of a (a zero remainder) or near one sometimes
        let mut r = Stream(0x3c6e_f372_fe94_f82b);
        let mut zeros = 0;
        for trial in 0..600 {
            let bits = [1, 64, 700, 5000, 40000][trial % 5];
            let deg = (r.next() % 7) as usize;
            let mut a: IPoly = (0..=deg).map(|_| r.int(bits)).collect();
            let mut b = vec![r.int(bits), r.int(bits)];
            if b[1].is_zero() {
                b[1] = BigInt::one();
            }
            match trial % 3 {
                0 => a = imul(&a, &b),
                1 => {
                    a = imul(&a, &b);
                    a[0] += r.int(8);
                }
                _ => {}
            }
            let a = itrim(a);
            let exact = prem(&a, &b).first().map_or(Sign::NoSign, BigInt::sign);
            zeros += usize::from(exact == Sign::NoSign);
            assert_eq!(sign_of_prem_linear(&a, &b), exact, "trial {trial}");
        }
        assert!(zeros > 150, "{zeros}");
    }

    #[test]
    fn linear_division_is_exact_or_refused() {
        // (3X - 2)(X + 5)(7X^2 + 1) times 6: divided by its roots 2/3 and
        // -5, refused at 1/3, 2 and 2/9 (not roots; 9X - 2 not a factor)
        let big = BigInt::one() << 3000;
        let mut p: IPoly = vec![BigInt::from(6) * &big];
        for f in [
            vec![BigInt::from(-2), BigInt::from(3)],
            vec![BigInt::from(5), BigInt::one()],
            vec![BigInt::one(), BigInt::zero(), BigInt::from(7)],
        ] {
            p = imul(&p, &f);
        }
        let r = |n: i64, d: i64| Rat::new(BigInt::from(n), BigInt::from(d));
        let q = divide_linear(&divide_linear(&p, &r(2, 3)).unwrap(), &r(-5, 1)).unwrap();
        assert_eq!(
            q,
            vec![
                BigInt::from(6) * &big,
                BigInt::zero(),
                BigInt::from(42) * &big
            ]
        );
        for x in [r(1, 3), r(2, 1), r(2, 9)] {
            assert!(divide_linear(&p, &x).is_err(), "{x:?}");
        }
    }

    #[test]
    fn bezout_resultant_matches_sylvester() {
        // random cubics of total degree 3 in (X, Y) (the reference
        // interpolates a resultant of degree at most 9), with a constant
        // nonzero Y^3 coefficient as the shears give; zero coefficients,
        // small and big ones; then the module's tasks under every shear
        let mut r = Stream(0x2545_f491_4f6c_dd1d);
        for trial in 0..200 {
            let bits = [3, 60, 500, 3000][trial % 4];
            let cubic = |r: &mut Stream| -> Vec<Vec<BigInt>> {
                (0..4)
                    .map(|k| {
                        let mut c: IPoly = (0..=3 - k).map(|_| r.int(bits)).collect();
                        if r.next() % 4 == 0 {
                            c[0] = BigInt::zero();
                        }
                        if k == 3 && c[0].is_zero() {
                            c[0] = BigInt::one();
                        }
                        itrim(c)
                    })
                    .collect()
            };
            let (c1, c2) = (cubic(&mut r), cubic(&mut r));
            assert_eq!(
                resultant_y(&c1, &c2).unwrap(),
                resultant_y_sylvester(&c1, &c2).unwrap(),
                "trial {trial}"
            );
        }
        for case in &cases() {
            let [f1, f2] = int_cubics(&int_task(&case.poses).unwrap());
            for (a, q) in SHEARS {
                let (c1, c2) = (shear(&f1, a, q), shear(&f2, a, q));
                if c1.len() == 4 && c2.len() == 4 {
                    assert_eq!(
                        resultant_y(&c1, &c2).unwrap(),
                        resultant_y_sylvester(&c1, &c2).unwrap(),
                        "{} ({a}, {q})",
                        case.label
                    );
                } else {
                    assert!(resultant_y(&c1, &c2).is_err());
                }
            }
        }
    }

    // ---------------------------------------------------- step 1

    #[test]
    fn exact_f64_round_trips_and_rounds_to_nearest() {
        let mut x = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        for _ in 0..2000 {
            let v = f64::from_bits(next());
            if v.is_finite() {
                assert_eq!(
                    Rat::of_f64(v).unwrap().to_f64().to_bits(),
                    v.to_bits(),
                    "{v:e}"
                );
            }
            // a / b of integers below 2^53: IEEE division rounds correctly
            let a = (next() >> 11) as f64;
            let b = ((next() >> 11) | 1) as f64;
            let r = Rat::new(BigInt::from(a as u64), BigInt::from(b as u64));
            assert_eq!(r.to_f64(), a / b, "{a} / {b}");
            assert_eq!(r.neg().to_f64(), -(a / b));
        }
        // subnormal, tie to even, the smallest subnormal
        for v in [
            f64::MIN_POSITIVE / 3.0,
            5e-324,
            1.0 + f64::EPSILON,
            f64::MAX,
        ] {
            assert_eq!(Rat::of_f64(v).unwrap().to_f64(), v);
        }
        let tie = Rat::of_f64(1.0)
            .unwrap()
            .add(&Rat::new(BigInt::one(), BigInt::one() << 53));
        assert_eq!(tie.to_f64(), 1.0);
        let tie = Rat::of_f64(1.0 + f64::EPSILON)
            .unwrap()
            .add(&Rat::new(BigInt::one(), BigInt::one() << 53));
        assert_eq!(tie.to_f64(), 1.0 + 2.0 * f64::EPSILON);
        assert!(Rat::of_f64(f64::NAN).is_err() && Rat::of_f64(f64::INFINITY).is_err());
    }

    #[test]
    fn rotations_are_exactly_on_the_unit_circle_and_match_the_reference() {
        for case in &cases() {
            for (k, &[bits, cn, sn, cd]) in case.rotations.iter().enumerate() {
                let d = case.poses[k + 1][2] - case.poses[0][2];
                let (c, s) = unit_rotation(d).unwrap();
                assert_eq!(c.add(&Rat::zero()).mul(&c).add(&s.mul(&s)), Rat::small(1));
                assert!(
                    (c.to_f64() - d.cos()).abs() < 1e-15 && (s.to_f64() - d.sin()).abs() < 1e-15
                );
                assert_eq!(
                    (c.d.bits(), residue(&c.n), residue(&s.n), residue(&c.d)),
                    (bits, cn, sn, cd),
                    "{} pose {}",
                    case.label,
                    k + 2
                );
            }
        }
        assert_eq!(unit_rotation(0.0).unwrap(), (Rat::small(1), Rat::zero()));
        assert!(unit_rotation(f64::NAN).is_err());
        let poses = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.1],
            [f64::INFINITY, 0.0, 0.2],
            [0.0, 1.0, 0.3],
            [1.0, 1.0, 0.4],
        ];
        assert!(certify(&poses).is_err());
    }

    // ---------------------------------------------------- step 2

    #[test]
    fn cubics_match_the_reference() {
        for case in &cases() {
            let disp = displacements(&case.poses).unwrap();
            let [f1, f2] = int_cubics(&int_task(&case.poses).unwrap());
            // the poles lie exactly on both cubics (rotations on the unit circle)
            for p in poles(&disp).iter().flatten() {
                assert!(ip2_vanishes(&f1, &p.0, &p.1) && ip2_vanishes(&f2, &p.0, &p.1));
            }
            // a positive multiple of the rational determinants: one ratio
            // at ten points
            for (f, ks) in [(&f1, [0, 1, 2]), (&f2, [0, 1, 3])] {
                let mut ratio: Option<Rat> = None;
                for t in 0..10i64 {
                    let (x, y) = (
                        Rat::new(BigInt::from(3 * t - 7), BigInt::from(5)),
                        Rat::small(t * t - 11),
                    );
                    let (a, b) = (int_eval(f, &x, &y), det_at(&disp, ks, &x, &y));
                    assert!(!b.is_zero());
                    let r = a.div(&b);
                    assert_eq!(r.sign(), Sign::Plus);
                    assert_eq!(*ratio.get_or_insert(r.clone()), r, "{}", case.label);
                }
            }
            for (f, want) in [(&f1, &case.f1), (&f2, &case.f2)] {
                cubic_part_line(f).unwrap();
                for i in 0..4 {
                    for j in 0..4 {
                        let expected = want.iter().find(|w| w.0 == (i, j)).map_or(0, |w| w.1);
                        assert_eq!(residue(&f.c[i][j]), expected, "{} ({i}, {j})", case.label);
                    }
                }
            }
            let all = f1.c.iter().chain(f2.c.iter()).flatten().cloned();
            assert_eq!(max_bits(all), case.cubic_bits, "{}", case.label);
        }
    }

    // ---------------------------------------------------- step 3

    #[test]
    fn bareiss_matches_cofactor_expansion() {
        fn cofactor(m: &[Vec<BigInt>]) -> BigInt {
            if m.len() == 1 {
                return m[0][0].clone();
            }
            let mut sum = BigInt::zero();
            for c in 0..m.len() {
                let minor: Vec<Vec<BigInt>> = m[1..]
                    .iter()
                    .map(|r| {
                        r.iter()
                            .enumerate()
                            .filter(|&(j, _)| j != c)
                            .map(|(_, v)| v.clone())
                            .collect()
                    })
                    .collect();
                let t = &m[0][c] * cofactor(&minor);
                sum = if c % 2 == 0 { sum + t } else { sum - t };
            }
            sum
        }
        let mut x = 12345_u64;
        for n in 1..=6 {
            for trial in 0..20 {
                let m: Vec<Vec<BigInt>> = (0..n)
                    .map(|_| {
                        (0..n)
                            .map(|_| {
                                x = x
                                    .wrapping_mul(6364136223846793005)
                                    .wrapping_add(1442695040888963407);
                                // zeros often (pivoting), big values sometimes
                                let v = ((x >> 33) % 7) as i64 - 3;
                                if trial % 3 == 0 {
                                    BigInt::from(v) << 100
                                } else {
                                    BigInt::from(v)
                                }
                            })
                            .collect()
                    })
                    .collect();
                assert_eq!(det_bareiss(m.clone()), cofactor(&m), "n = {n}");
            }
        }
    }

    #[test]
    fn resultant_and_quotient_match_the_reference() {
        for case in &cases() {
            let Ok(exact) = &case.order else { continue };
            let c = certify_order(&case.poses).unwrap();
            assert_eq!(c.shear, exact.shear, "{}", case.label);
            let r: Vec<u64> = c.resultant.iter().map(residue).collect();
            assert_eq!(r, exact.resultant, "{}", case.label);
            assert_eq!(max_bits(c.resultant.iter().cloned()), exact.resultant_bits);
            let q = content_free(c.q.clone());
            assert_eq!(
                q.iter().map(residue).collect::<Vec<_>>(),
                exact.q,
                "{}",
                case.label
            );
            assert_eq!(max_bits(q), exact.q_bits);
            // a second method at X = 11 (no interpolation node): the
            // Sylvester determinant there equals the interpolated R(11)
            let (a, qd) = c.shear;
            let (c1, c2) = (shear(&c.cubics[0], a, qd), shear(&c.cubics[1], a, qd));
            let (ca, cb): (Vec<BigInt>, Vec<BigInt>) = (
                c1.iter().map(|p| ieval(p, 11)).collect(),
                c2.iter().map(|p| ieval(p, 11)).collect(),
            );
            let mut rows = Vec::new();
            for i in 0..3 {
                let mut row = vec![BigInt::zero(); 6];
                for k in 0..4 {
                    row[i + k] = ca[3 - k].clone();
                }
                rows.push(row);
            }
            for i in 0..3 {
                let mut row = vec![BigInt::zero(); 6];
                for k in 0..4 {
                    row[i + k] = cb[3 - k].clone();
                }
                rows.push(row);
            }
            assert_eq!(det_bareiss(rows), ieval(&c.resultant, 11), "{}", case.label);
        }
    }

    // ---------------------------------------------------- step 4

    #[test]
    fn sturm_isolates_known_roots() {
        // (X - 1)(X - 2)(X + 1/3)(X^2 + 1): three real roots
        let lin = |r: Rat| vec![r.neg(), Rat::small(1)];
        let mut p = vec![Rat::small(1), Rat::zero(), Rat::small(1)];
        for r in [
            Rat::small(1),
            Rat::small(2),
            Rat::new(BigInt::from(-1), BigInt::from(3)),
        ] {
            let l = lin(r);
            let mut out = vec![Rat::zero(); p.len() + 1];
            for (i, a) in p.iter().enumerate() {
                for (j, b) in l.iter().enumerate() {
                    out[i + j] = out[i + j].add(&a.mul(b));
                }
            }
            p = out;
        }
        let pi = primitive_of(&p);
        let iv = isolate(&pi, &sturm(&pi));
        assert_eq!(iv.len(), 3);
        for ((lo, hi), root) in iv.iter().zip([-1.0 / 3.0, 1.0, 2.0]) {
            assert!(lo.to_f64() < root && root <= hi.to_f64(), "{root}");
        }
        assert!(ugcd(&p, &uderiv(&p)).len() == 1 && squarefree(&sturm(&primitive_of(&p))));
        // a double root is seen by the squarefree test
        let mut sq = p.clone();
        sq.insert(0, Rat::zero());
        sq.insert(0, Rat::zero());
        assert!(ugcd(&sq, &uderiv(&sq)).len() > 1 && !squarefree(&sturm(&primitive_of(&sq))));
        let none = primitive_of(&[Rat::small(1), Rat::zero(), Rat::small(1)]);
        assert!(isolate(&none, &sturm(&none)).is_empty());
    }

    #[test]
    fn sturm_sequence_matches_the_primitive_one() {
        // the reference: each pseudo-remainder made primitive by gcds
        for case in &cases() {
            let q = certify(&case.poses).unwrap().q;
            let seq = sturm(&q);
            let reference = primitive_sturm(&q);
            let primitive: Vec<IPoly> = seq.iter().cloned().map(content_free).collect();
            assert_eq!(primitive, reference, "{}", case.label);
            // the divided members stay within the subresultants' size (a
            // determinant of order at most 7 in the coefficients)
            let bits = |p: &IPoly| p.iter().map(BigInt::bits).max().unwrap_or(0);
            assert!(
                seq.iter().all(|p| bits(p) <= 7 * bits(&q) + 64),
                "{}",
                case.label
            );
        }
    }

    #[test]
    fn counts_match_the_reference() {
        for case in &cases() {
            match (&case.order, certify_order(&case.poses)) {
                (Ok(exact), Ok(c)) => {
                    assert_eq!(
                        (c.finite, c.sliders),
                        (exact.finite, exact.sliders),
                        "{}",
                        case.label
                    );
                    let iv: Vec<(String, String)> = c
                        .intervals
                        .iter()
                        .map(|(a, b)| (rat_str(a), rat_str(b)))
                        .collect();
                    assert_eq!(iv, exact.intervals, "{}", case.label);
                    // each interval holds a sign change of Q
                    for (lo, hi) in &c.intervals {
                        assert_ne!(sign_at_rat(&c.q, lo), sign_at_rat(&c.q, hi));
                    }
                }
                (Err(why), Err(e)) => assert_eq!(e.0, *why, "{}", case.label),
                (want, got) => panic!(
                    "{}: want {:?}, got {:?}",
                    case.label,
                    want.as_ref().err(),
                    got.err()
                ),
            }
            let c = certify(&case.poses).unwrap();
            assert_eq!(
                (c.finite, c.sliders, c.order),
                case.certify,
                "{}",
                case.label
            );
        }
    }

    #[test]
    fn far_exponents_and_a_translation_match_the_reference() {
        // (poses, finite, sliders, intervals) from certificate_five.py;
        // poses 1 and 2 of the last with one angle (the pole P12 at
        // infinity)
        type Expected = (
            [[f64; 3]; 5],
            usize,
            usize,
            &'static [(&'static str, &'static str)],
        );
        let tasks: [Expected; 3] = [
            (
                [
                    [1e300, 2e299, 0.1],
                    [-3e300, 1.5e300, 0.7],
                    [2e300, -1e300, -0.4],
                    [5e299, 7e299, 1.2],
                    [-1e300, -2e300, 2.0],
                ],
                0,
                0,
                &[],
            ),
            (
                [
                    [1e-300, 2e-299, 0.1],
                    [-3e-300, 1.5e-300, 0.7],
                    [2e-300, -1e-300, -0.4],
                    [5e-299, 7e-299, 1.2],
                    [-1e-300, -2e-300, 2.0],
                ],
                2,
                0,
                &[],
            ),
            (
                [
                    [1.0, 2.0, 0.3],
                    [-3.0, 1.5, 0.3],
                    [2.0, -1.0, -0.4],
                    [5.0, 7.0, 1.2],
                    [-1.0, -2.0, 2.0],
                ],
                2,
                0,
                &[("-16", "-8"), ("-8", "0")],
            ),
        ];
        for (poses, finite, sliders, intervals) in tasks {
            let c = certify(&poses).unwrap();
            assert_eq!(
                (c.finite, c.sliders, c.order),
                (finite, sliders, [0, 1, 2, 3, 4])
            );
            if !intervals.is_empty() {
                let iv: Vec<(String, String)> = c
                    .intervals
                    .iter()
                    .map(|(a, b)| (rat_str(a), rat_str(b)))
                    .collect();
                let want: Vec<(String, String)> = intervals
                    .iter()
                    .map(|&(a, b)| (a.into(), b.into()))
                    .collect();
                assert_eq!(iv, want);
            }
        }
    }

    #[test]
    fn counts_are_invariant_under_exact_scaling_and_mirroring() {
        // positions times 2^k and the mirror (x, -y, -a) are exact in f64
        // and keep the Burmester points' count and kind
        for case in &cases() {
            let want = certify(&case.poses).unwrap();
            let mut variants: Vec<(String, [[f64; 3]; 5])> = [-600, 600]
                .iter()
                .map(|&k| {
                    let f = 2f64.powi(k);
                    (
                        format!("2^{k}"),
                        case.poses.map(|p| [p[0] * f, p[1] * f, p[2]]),
                    )
                })
                .collect();
            variants.push(("mirrored".into(), case.poses.map(|p| [p[0], -p[1], -p[2]])));
            for (what, poses) in variants {
                let c = certify(&poses).unwrap();
                assert_eq!(
                    (c.finite, c.sliders),
                    (want.finite, want.sliders),
                    "{} {what}",
                    case.label
                );
            }
        }
    }

    #[test]
    fn time_per_task() {
        let runs = 1;
        let cases = cases();
        let start = std::time::Instant::now();
        for _ in 0..runs {
            for case in &cases {
                certify(&case.poses).unwrap();
            }
        }
        let per = start.elapsed().as_secs_f64() / (runs * cases.len()) as f64;
        println!(
            "certificate: {:.3} ms per task ({} tasks x {runs})",
            per * 1e3,
            cases.len()
        );
    }

    /// The check at its heaviest: tasks mixing coordinates of `1e100`
    /// (the library's input limit) or `1e308` with subnormal ones, and
    /// subnormal rotations, give about the largest integers an f64 task can
    /// (cubics of about 7,900 and 10,600 bits; ordinary tasks about 550,
    /// the fuzz corpora's frames at most about 1,030, the heaviest of 300
    /// random such tasks 10,017): certified, the times printed (tens of
    /// milliseconds in release), so no five-pose call needs to poll Ctrl-C.
    #[test]
    fn the_check_at_its_heaviest() {
        let pose = |p: &[f64; 3]| Pose::new(p[0], p[1], p[2]);
        let tasks = [
            [
                [1e100, 5e-324, 0.0],
                [-5e-324, 0.5e100, 5e-324],
                [3e-323, -1e100, 1.3],
                [1e100, 1e100, 1e-323],
                [-0.9e100, 5e-324, -0.4],
            ],
            [
                [1e308, 5e-324, 0.0],
                [-5e-324, 0.5e308, 5e-324],
                [3e-323, -1e308, 0.7],
                [1e308, -0.7e308, 1.5e-323],
                [-0.9e308, 1e-323, 2.1],
            ],
        ];
        for (task, least) in tasks.iter().zip([7_000, 10_000]) {
            let bits = cubic_bits(task).unwrap();
            assert!(bits >= least, "{bits}");
            let start = std::time::Instant::now();
            let c = certify(task).unwrap();
            let size = task[0][0].abs();
            let exact = points(&c, size).unwrap();
            let poses: Vec<Pose> = task.iter().map(pose).collect();
            // the exact answer agrees with itself
            assert_eq!(refuses(&poses, &exact, (0.0, 0.0), size), None);
            println!(
                "{bits} bits, {} points, {:.1} ms (certified twice)",
                exact.len(),
                start.elapsed().as_secs_f64() * 1e3
            );
        }
    }

    // ------------------------------ certify_order's branches, designed tasks
    //
    // One task per branch of `certify_order` / `certify`, each run through
    // `fuzz/reference/certificate_five.py` (`certify_order`, `certify`,
    // `points_of`); the expected values are its output. The tasks are
    // exact by design: integer positions, and angles whose half-angle
    // tangent (`unit_rotation`) comes out an exact small dyadic (1/2, 1/4,
    // 3/4, ...: rotations `(3/5, 4/5)`, `(15/17, 8/17)`, ...), so the
    // degenerate coincidences hold exactly; the small-integer ones were
    // found by classifying random tasks of that grid by the reference's
    // branch. Where a task certifies, one independent fact is checked too:
    // a point found by construction is a Burmester center exactly (its
    // circle point's five positions equidistant from it, solved directly
    // from the exact task, no elimination) and lies in an isolating
    // interval, or a slider's circle point has five collinear positions.

    /// `certify_order`'s expected result: `(finite, sliders, shear,
    /// intervals)`, or the reason.
    type OrderWant = Result<
        (
            usize,
            usize,
            (i64, i64),
            &'static [(&'static str, &'static str)],
        ),
        &'static str,
    >;
    /// `certify`'s certificate: `(finite, sliders, shear, order,
    /// intervals)`.
    type CertifyOk = (
        usize,
        usize,
        (i64, i64),
        [usize; 5],
        &'static [(&'static str, &'static str)],
    );
    /// `certify`'s expected result, or the reasons joined.
    type CertifyWant = Result<CertifyOk, &'static str>;

    fn interval_strs(c: &Certified) -> Vec<(String, String)> {
        c.intervals
            .iter()
            .map(|(a, b)| (rat_str(a), rat_str(b)))
            .collect()
    }

    fn want_strs(iv: &[(&str, &str)]) -> Vec<(String, String)> {
        iv.iter().map(|&(a, b)| (a.into(), b.into())).collect()
    }

    /// `certify_order` and `certify` on `poses` equal the reference's
    /// (counts, shear, intervals, pose order, reasons); `certify`'s
    /// certificate where it certifies.
    fn matches_reference(
        label: &str,
        poses: &[[f64; 3]; 5],
        order: OrderWant,
        want: CertifyWant,
    ) -> Option<Certified> {
        match (certify_order(poses), order) {
            (Ok(c), Ok((finite, sliders, shear, iv))) => {
                assert_eq!(
                    (c.finite, c.sliders, c.shear),
                    (finite, sliders, shear),
                    "{label}"
                );
                assert_eq!(interval_strs(&c), want_strs(iv), "{label}");
                for (lo, hi) in &c.intervals {
                    assert_ne!(sign_at_rat(&c.q, lo), sign_at_rat(&c.q, hi), "{label}");
                }
            }
            (Err(e), Err(why)) => assert_eq!(e.0, why, "{label}"),
            (got, want) => panic!(
                "{label}: certify_order gave {:?}, the reference {:?}",
                got.map(|c| (c.finite, c.sliders, c.shear)),
                want.map(|w| (w.0, w.1, w.2))
            ),
        }
        match (certify(poses), want) {
            (Ok(c), Ok((finite, sliders, shear, order, iv))) => {
                assert_eq!(
                    (c.finite, c.sliders, c.shear, c.order),
                    (finite, sliders, shear, order),
                    "{label}"
                );
                assert_eq!(interval_strs(&c), want_strs(iv), "{label}");
                Some(c)
            }
            (Err(e), Err(why)) => {
                assert_eq!(e.0, why, "{label}");
                None
            }
            (got, want) => panic!(
                "{label}: certify gave {:?}, the reference {:?}",
                got.map(|c| (c.finite, c.sliders, c.order)),
                want.map(|w| (w.0, w.1, w.3))
            ),
        }
    }

    /// `matches_reference` where the shared poses 1, 2, 3 certify:
    /// `(finite, sliders, shear)` and the intervals.
    fn certified_as_given(
        label: &str,
        poses: &[[f64; 3]; 5],
        (finite, sliders, shear): (usize, usize, (i64, i64)),
        iv: &'static [(&'static str, &'static str)],
    ) -> Certified {
        let want = Ok((finite, sliders, shear, [0, 1, 2, 3, 4], iv));
        matches_reference(label, poses, Ok((finite, sliders, shear, iv)), want).unwrap()
    }

    /// `matches_reference` where the shared poses 1, 2, 3 fail (`why`) and
    /// a later choice certifies (`want`, step 6's `points`).
    fn falls_through(
        label: &str,
        poses: &[[f64; 3]; 5],
        why: &'static str,
        want: CertifyOk,
        points: &[(f64, f64)],
    ) -> Certified {
        let c = matches_reference(label, poses, Err(why), Ok(want)).unwrap();
        points_match(&c, poses, points);
        c
    }

    /// `g` is exactly a Burmester center and its `X` lies in `c`'s
    /// interval `k`.
    fn center_in_interval(c: &Certified, poses: &[[f64; 3]; 5], g: &(Rat, Rat), k: usize) {
        assert!(exact_center(poses, g));
        assert_eq!(interval_of(c, g), Some(k));
    }

    /// Step 6's points of `c` equal `certificate_five.py`'s `points_of`
    /// (to `1e-12` of `size + d`).
    fn points_match(c: &Certified, poses: &[[f64; 3]; 5], expected: &[(f64, f64)]) {
        let (size, o) = size_c(poses);
        let got = points(c, size).unwrap();
        assert_eq!(got.len(), expected.len());
        for (g, e) in got.iter().zip(expected) {
            let d = (e.0 - o.0).hypot(e.1 - o.1);
            assert!(
                (g.0 - e.0).hypot(g.1 - e.1) <= 1e-12 * (size + d),
                "{g:?} {e:?}"
            );
        }
    }

    /// Whether `g` is exactly a Burmester center of the exact task (the
    /// certificate's rotations, exactly on the unit circle, and the floats'
    /// positions): a pose-1 point `z` with `|R_k z + t_k - g| = |z - g|`
    /// for the four displacements, each linear in `z`:
    /// `z . 2 (R_k^T (t_k - g) + g) = |g|^2 - |t_k - g|^2`; `z` from two
    /// independent rows, all four checked (a pole's row is `0 = 0`).
    fn exact_center(poses: &[[f64; 3]; 5], g: &(Rat, Rat)) -> bool {
        let rows: Vec<(Rat, Rat, Rat)> = displacements(poses)
            .unwrap()
            .iter()
            .map(|d| {
                let (ex, ey) = (d.tx.sub(&g.0), d.ty.sub(&g.1));
                let vx = d.c.mul(&ex).add(&d.s.mul(&ey)).add(&g.0);
                let vy = d.c.mul(&ey).sub(&d.s.mul(&ex)).add(&g.1);
                let w = g.0.mul(&g.0).add(&g.1.mul(&g.1));
                let w = w.sub(&ex.mul(&ex)).sub(&ey.mul(&ey));
                (vx.add(&vx), vy.add(&vy), w)
            })
            .collect();
        for i in 0..4 {
            for j in i + 1..4 {
                let (a, b) = (&rows[i], &rows[j]);
                let det = a.0.mul(&b.1).sub(&a.1.mul(&b.0));
                if det.is_zero() {
                    continue;
                }
                let zx = a.2.mul(&b.1).sub(&a.1.mul(&b.2)).div(&det);
                let zy = a.0.mul(&b.2).sub(&a.2.mul(&b.0)).div(&det);
                return rows.iter().all(|r| r.0.mul(&zx).add(&r.1.mul(&zy)) == r.2);
            }
        }
        false
    }

    /// The isolating interval of `c` (its shear) that holds the point `g`'s
    /// `X = x - u y`: `(lo, hi]`, as the bisection counts roots.
    fn interval_of(c: &Certified, g: &(Rat, Rat)) -> Option<usize> {
        let u = Rat::new(BigInt::from(c.shear.0), BigInt::from(c.shear.1));
        let x = g.0.sub(&u.mul(&g.1));
        c.intervals
            .iter()
            .position(|(lo, hi)| lo.cmp(&x) == Ordering::Less && x.cmp(hi) != Ordering::Greater)
    }

    /// The library's answer: the listed centers and the sliders'
    /// directions.
    type LibraryAnswer = (Vec<[f64; 2]>, Vec<[f64; 2]>);

    /// The library's answer (`FivePositions::new`), or its error.
    fn library(poses: &[[f64; 3]; 5]) -> Result<LibraryAnswer, String> {
        let p: Vec<crate::geom::Pose> = poses
            .iter()
            .map(|q| crate::geom::Pose::new(q[0], q[1], q[2]))
            .collect();
        super::super::FivePositions::new(&p)
            .map(|f| {
                let centers = f
                    .burmester_points()
                    .iter()
                    .map(|d| [d.center.x, d.center.y]);
                let sliders = f.sliders().iter().map(|s| [s.direction.x, s.direction.y]);
                (centers.collect(), sliders.collect())
            })
            .map_err(|e| e.to_string())
    }

    /// The angles used below: `unit_rotation` of each has its half-angle
    /// tangent exactly the dyadic `tau` (1/2, 1/4, 3/4, ...), so the
    /// rotation is `((1 - tau^2), 2 tau) / (1 + tau^2)`.
    #[test]
    fn designed_angles_have_exact_dyadic_half_angle_tangents() {
        for (angle, tau) in [
            (0.9272952180016123, 0.5),
            (0.4899573262537283, 0.25),
            (1.2870022175865687, 0.75),
            (0.24870998909352288, 0.125),
            (2.498091544796509, 3.0),
            (0.7175413405411444, 0.375),
            (2.1616780010823367, 1.875),
            (2.413634740570505, 2.625),
            (2.4440506464219793, 2.75),
            (2.5445947904174346, 3.25),
        ] {
            for (a, t) in [(angle, tau), (-angle, -tau)] {
                let t = Rat::of_f64(t).unwrap();
                let one = Rat::small(1);
                let d = one.add(&t.mul(&t));
                let want = (one.sub(&t.mul(&t)).div(&d), t.add(&t).div(&d));
                assert_eq!(unit_rotation(a).unwrap(), want, "{a}");
            }
        }
    }

    /// Each of `c`'s intervals holds the `X` of exactly one of `centers`
    /// (the library's points, f64), and each center lies in one.
    fn one_center_per_interval(c: &Certified, centers: &[[f64; 2]]) {
        let u = c.shear.0 as f64 / c.shear.1 as f64;
        let mut count = vec![0; c.intervals.len()];
        for p in centers {
            let x = p[0] - u * p[1];
            let k = c
                .intervals
                .iter()
                .position(|(lo, hi)| lo.to_f64() < x && x <= hi.to_f64());
            count[k.unwrap_or_else(|| panic!("{p:?} in no interval"))] += 1;
        }
        assert!(count.iter().all(|&n| n == 1), "{count:?}");
    }

    /// Both cubics' real point at infinity is the direction (0, 1)
    /// (`L = (Lx, 0)`), and the library agrees with `c`: one listed center
    /// in each interval, and `sliders` sliders in the direction (0, 1).
    fn vertical_sliders(c: &Certified, poses: &[[f64; 3]; 5], sliders: usize) {
        for f in &c.cubics {
            let (lx, ly) = cubic_part_line(f).unwrap();
            assert!(ly.is_zero() && !lx.is_zero());
        }
        let (centers, directions) = library(poses).unwrap();
        one_center_per_interval(c, &centers);
        assert_eq!(directions.len(), sliders);
        assert!(
            directions.iter().all(|d| d[0].abs() < 1e-9),
            "{directions:?}"
        );
    }

    const TAU_HALF: f64 = 0.9272952180016123;

    #[test]
    fn a_pole_at_infinity_with_one_slider() {
        // poses 1 and 2 with one angle (a translation along x: P12 at
        // infinity in the direction (0, 1)), and all five positions on the
        // x axis: the moving origin is a slider whose center is at infinity
        // in the pole's direction (the branch's "at most one Burmester
        // point at infinity"); the pole alone (no slider) is
        // `far_exponents_and_a_translation_match_the_reference`'s last task
        let poses = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [3.0, 0.0, TAU_HALF],
            [-2.0, 0.0, -0.4899573262537283],
            [5.0, 0.0, 1.2870022175865687],
        ];
        let iv: &[(&str, &str)] = &[("-16", "0"), ("0", "1"), ("1", "2")];
        let c = certified_as_given(
            "a pole at infinity and a slider",
            &poses,
            (3, 1, (3, 7)),
            iv,
        );
        points_match(
            &c,
            &poses,
            &[
                (-0.5880398106564148, 5.700185404914164),
                (1.572970050198376, 2.9539661333913383),
                (1.7985559989901487, 0.8102118728352874),
            ],
        );
        assert!(poles(&displacements(&poses).unwrap())[0].is_none());
        // the library: three points, one in each interval, and one slider
        // in the direction (0, 1)
        vertical_sliders(&c, &poses, 1);
        // pose 5 moved off the line by (2^-20, 2^-21): the slider becomes
        // one far finite point (y about 6.6e6; the reference: 4 points, the
        // new interval (-4194304, -2097152]), the three near ones stay
        let mut moved = poses;
        moved[4][0] += 2f64.powi(-20);
        moved[4][1] += 2f64.powi(-21);
        let m = certify_order(&moved).unwrap();
        assert_eq!((m.finite, m.sliders, m.shear), (4, 0, (3, 7)));
        let iv = want_strs(&[
            ("-4194304", "-2097152"),
            ("-2097152", "0"),
            ("0", "1"),
            ("1", "2"),
        ]);
        assert_eq!(interval_strs(&m), iv);
    }

    #[test]
    fn a_pole_at_infinity_with_more_points_at_infinity_cannot_certify() {
        // poses 1 and 3 with one angle (P13 at infinity), poses 2, 4, 5
        // rotations about (2, 1): the shared poses 1, 2, 3 leave
        // `4 - deg Q = 2` (a double slider in the pole's direction or a
        // pair at the circular points: ambiguous)
        let poses = [
            [-2.0, -1.0, 0.0],
            [2.0, 1.0, 2.1616780010823367],
            [0.0, 1.0, 0.0],
            [2.0, 1.0, -2.413634740570505],
            [2.0, 1.0, 2.4440506464219793],
        ];
        assert!(poles(&displacements(&poses).unwrap())[1].is_none());
        matches_reference(
            "a pole at infinity and two points at infinity",
            &poses,
            Err("a pole at infinity and more than one Burmester point at infinity"),
            Err(
                "a Burmester point at a pole (or coincident poles of higher multiplicity); \
                 a pole at infinity and more than one Burmester point at infinity",
            ),
        );
    }

    #[test]
    fn poles_at_infinity_fall_through_to_the_last_choice_of_shared_poses() {
        // poses 1, 2, 3 with one angle (three poles at infinity); with the
        // shared poses 1, 2, 4 / 1, 2, 5 / 1, 3, 4 / 1, 3, 5 a cubic holds
        // two poles at infinity in different directions (its cubic part
        // vanishes: the line at infinity a component); 1, 4, 5 certifies
        let poses = [
            [-1.0, -1.0, 0.0],
            [-2.0, 0.0, 0.0],
            [-1.0, 0.0, 0.0],
            [2.0, 2.0, -2.4440506464219793],
            [0.0, -2.0, -2.1616780010823367],
        ];
        let c = falls_through(
            "poles at infinity",
            &poses,
            "poles at infinity (poses 1, 2, 3 all with one rotation)",
            (0, 0, (3, 7), [0, 3, 4, 1, 2], &[]),
            &[],
        );
        // the four other earlier choices, each as the reference says
        for (order, why) in [
            (
                [0, 1, 3, 2, 4],
                "a cubic of degree < 3 (the line at infinity a component)",
            ),
            (
                [0, 1, 4, 2, 3],
                "a cubic of degree < 3 (the line at infinity a component)",
            ),
            (
                [0, 2, 3, 1, 4],
                "a cubic of degree < 3 (the line at infinity a component)",
            ),
            (
                [0, 2, 4, 1, 3],
                "a cubic of degree < 3 (the line at infinity a component)",
            ),
        ] {
            assert_eq!(certify_order(&order.map(|k| poses[k])).unwrap_err().0, why);
        }
        // `4 - deg Q = 2`, not parallel: the pair at the circular points
        assert_eq!(c.q.len() - 1, 2);
        // the library: no point, no slider
        assert_eq!(library(&poses).unwrap(), (vec![], vec![]));
    }

    #[test]
    fn a_double_slider() {
        // poses 2 and 4 with one angle, 3 and 5 with the opposite one, each
        // pair a translation by (1, 0): the moving point (-5/8, -5/4) (with
        // the rotation (3/5, 4/5)) has its five positions on y = -5/4, a
        // slider whose center is at infinity in the direction (0, 1), where
        // both poles P24 and P35 lie too; `4 - deg Q = 2` with `L1 || L2`:
        // a double slider (the same count with the shared poses 1, 2, 5 /
        // 1, 3, 4 / 1, 4, 5; with 1, 2, 4 and 1, 3, 5 the pole at infinity
        // P24 or P35 leaves it ambiguous)
        let poses = [
            [1.0, 0.0, 0.0],
            [2.0, -1.0, -TAU_HALF],
            [0.0, 0.0, TAU_HALF],
            [1.0, -1.0, -TAU_HALF],
            [-1.0, 0.0, TAU_HALF],
        ];
        let c = certified_as_given("a double slider", &poses, (0, 2, (3, 7)), &[]);
        for order in [[0, 1, 4, 2, 3], [0, 2, 3, 1, 4], [0, 3, 4, 1, 2]] {
            let o = certify_order(&order.map(|k| poses[k])).unwrap();
            assert_eq!((o.finite, o.sliders), (0, 2), "{order:?}");
        }
        vertical_sliders(&c, &poses, 2);
        // the slider's circle point: five positions with one y, exactly
        let (bx, by) = (
            Rat::new(BigInt::from(-5), BigInt::from(8)),
            Rat::new(BigInt::from(-5), BigInt::from(4)),
        );
        let ys: Vec<Rat> = poses
            .iter()
            .map(|p| {
                let (c, s) = unit_rotation(p[2]).unwrap();
                Rat::of_f64(p[1]).unwrap().add(&s.mul(&bx)).add(&c.mul(&by))
            })
            .collect();
        assert!(ys.iter().all(|y| *y == by), "{ys:?}");
        // pose 5 moved by (-2^-20, -2^-21): the double slider becomes two
        // far real points (y about +-886, as the reference finds), both
        // outside |X| <= 100; moved the other way, a complex pair
        for (sign, finite) in [(-1.0, 2), (1.0, 0)] {
            let mut moved = poses;
            moved[4][0] += sign * 2f64.powi(-20);
            moved[4][1] += sign * 2f64.powi(-21);
            let m = certify_order(&moved).unwrap();
            assert_eq!((m.finite, m.sliders, m.q.len() - 1), (finite, 0, 4));
            let seq = sturm(&m.q);
            let seq: Vec<Approx> = seq.iter().map(|p| Approx::of(p)).collect();
            let at = |v: i64| {
                changes_at(
                    &seq,
                    &Dyadic {
                        m: BigInt::from(v),
                        k: 0,
                    },
                )
            };
            assert_eq!(at(-100) - at(100), 0);
        }
    }

    #[test]
    fn a_double_slider_with_two_finite_points() {
        // all positions on the x axis (the moving origin a slider), poses 1
        // and 4 with one angle, 3 and 5 with one angle: the poles P14, P35
        // at infinity in the slider's direction (0, 1), as in
        // `a_double_slider`; two real finite points besides
        let poses = [
            [2.0, 0.0, 0.0],
            [-3.0, 0.0, 2.679411319197999],
            [1.0, 0.0, -2.498091544796509],
            [1.0, 0.0, 0.0],
            [2.0, 0.0, -2.498091544796509],
        ];
        let iv: &[(&str, &str)] = &[("-8", "0"), ("0", "8")];
        let c = certified_as_given("a double slider and two points", &poses, (2, 2, (3, 7)), iv);
        points_match(
            &c,
            &poses,
            &[
                (-2.153279627147614, -1.8166912377080495e-41),
                (0.6532796271476137, -1.9806415413326574e-42),
            ],
        );
        vertical_sliders(&c, &poses, 2);
    }

    #[test]
    fn three_or_four_points_at_infinity_cannot_certify() {
        // poses 3, 4, 5 with one angle (their positions on one line: every
        // dyad through them a slider)
        let poses = [
            [1.0, 0.0, 0.0],
            [2.0, 0.0, -2.413634740570505],
            [0.0, -2.0, 0.7175413405411444],
            [2.0, 2.0, 0.7175413405411444],
            [1.0, 0.0, 0.7175413405411444],
        ];
        matches_reference(
            "3 or 4 points at infinity",
            &poses,
            Err(
                "3 or 4 Burmester points at infinity (at the real direction or the circular points)",
            ),
            Err(
                "3 or 4 Burmester points at infinity (at the real direction or the circular points); \
                 a cubic of degree < 3 (the line at infinity a component)",
            ),
        );
    }

    #[test]
    fn a_burmester_point_at_a_pole_falls_through_to_another_choice() {
        // the pole P13 = (1/2, -1/2) is a Burmester center: `Q(X_p) = 0`
        // with the shared poses 1, 2, 3; with 1, 2, 4 it is no pole and an
        // isolated root
        let poses = [
            [1.0, -2.0, 0.0],
            [2.0, -1.0, 0.7175413405411444],
            [1.0, 1.0, 2.498091544796509],
            [2.0, -1.0, 2.498091544796509],
            [1.0, 1.0, 1.2870022175865687],
        ];
        let c = falls_through(
            "a Burmester point at a pole",
            &poses,
            "a Burmester point at a pole (or coincident poles of higher multiplicity)",
            (2, 0, (3, 7), [0, 1, 3, 2, 4], &[("-32", "0"), ("0", "32")]),
            &[(-4.413244109980611, -4.808190581405396), (0.5, -0.5)],
        );
        let p13 = poles(&displacements(&poses).unwrap())[1].clone().unwrap();
        assert_eq!(
            p13,
            (
                Rat::new(BigInt::from(1), BigInt::from(2)),
                Rat::new(BigInt::from(-1), BigInt::from(2))
            )
        );
        center_in_interval(&c, &poses, &p13, 1);
        // (the check tells: the pole P12 = (1/6, -1/6) is no center)
        let p12 = poles(&displacements(&poses).unwrap())[0].clone().unwrap();
        assert_eq!(p12.0, Rat::new(BigInt::from(1), BigInt::from(6)));
        assert!(!exact_center(&poses, &p12));
        let (centers, sliders) = library(&poses).unwrap();
        one_center_per_interval(&c, &centers);
        assert!(sliders.is_empty());
    }

    #[test]
    fn coincident_poles_give_a_common_component() {
        // poses 2 and 3 rotations of pose 1 about (85, 0) (rotations
        // (3/5, 4/5) and (15/17, 8/17)): P12 = P13 = P23. Coincident poles
        // are always all three (two displacements from pose 1 that fix a
        // point fix it in the third), and then both cubics are
        // `((x - 85)^2 + y^2)` times a line: the resultant vanishes, so the
        // reason "coincident poles of higher multiplicity" of `Q(X_p) = 0`
        // is not reached by coincident poles (only by a Burmester point at
        // a pole). The shared poses 1, 4, 5 certify: (85, 0) itself is a
        // Burmester center (any circle point fits poses 1, 2, 3).
        let poses = [
            [0.0, 0.0, 0.0],
            [34.0, -68.0, TAU_HALF],
            [10.0, -40.0, 0.4899573262537283],
            [3.0, 7.0, 1.2870022175865687],
            [-5.0, 2.0, -0.24870998909352288],
        ];
        let c = falls_through(
            "coincident poles",
            &poses,
            "a common component (the resultant vanishes)",
            (2, 0, (3, 7), [0, 3, 4, 1, 2], &[("0", "64"), ("64", "128")]),
            &[(14.757789558483408, 17.27430420207375), (85.0, 0.0)],
        );
        let p = (Rat::small(85), Rat::zero());
        for q in poles(&displacements(&poses).unwrap()) {
            assert_eq!(q, Some(p.clone()));
        }
        let circle = p2_add(
            &p2_mul(
                &p2_lin(BigInt::from(-85), BigInt::one(), BigInt::zero()),
                &p2_lin(BigInt::from(-85), BigInt::one(), BigInt::zero()),
            ),
            &p2_mul(
                &p2_lin(BigInt::zero(), BigInt::zero(), BigInt::one()),
                &p2_lin(BigInt::zero(), BigInt::zero(), BigInt::one()),
            ),
            1,
        );
        for f in int_cubics(&int_task(&poses).unwrap()) {
            // f = circle * (a x + b y + e): a, b from the cubic part, e
            // from the x^2 coefficient (circle's x^2 - 170 x ...)
            let (a, b) = (f.c[3][0].clone(), f.c[0][3].clone());
            let e = &f.c[2][0] + &a * 170;
            assert_eq!(p2_mul(&circle, &p2_lin(e, a, b)), f);
        }
        center_in_interval(&c, &poses, &p, 1);
        // (the library refuses this task: "rotations about one point")
    }

    /// `Q` of the shared poses 1, 2, 3 at the shear `a / q` (the steps of
    /// `certify_order`, for the tests of its shear loop).
    fn q_at_shear(poses: &[[f64; 3]; 5], a: i64, q: i64) -> IPoly {
        let [f1, f2] = int_cubics(&int_task(poses).unwrap());
        let r = resultant_y(&shear(&f1, a, q), &shear(&f2, a, q)).unwrap();
        let u = Rat::new(BigInt::from(a), BigInt::from(q));
        let mut qp = r;
        for p in poles(&displacements(poses).unwrap()).iter().flatten() {
            qp = divide_linear(&qp, &p.0.sub(&u.mul(&p.1))).unwrap();
        }
        qp
    }

    #[test]
    fn a_mirror_symmetric_task_takes_the_second_shear() {
        // mirror symmetric about the line through the origin along (7, -3)
        // (the reflection S = [[20, -21], [-21, -20]] / 29; pose 1 on the
        // axis, poses 2 <-> 3 and 4 <-> 5 mirror images with opposite
        // angles): S maps Burmester points to Burmester points and
        // `p - S p` is normal to the axis, along (3, 7), so a point and its
        // image have one `X = x - (3/7) y`. Here the two real points lie on
        // the axis and the complex pair are each other's images: `Q` has a
        // double root at the first shear 3/7, and the second, -5/11, is
        // squarefree.
        let t = 2.4440506464219793; // tau 11/4
        let poses = [
            [7.0, -3.0, 0.0],
            [-58.0, 0.0, t],
            [-40.0, 42.0, -t],
            [-58.0, 29.0, t],
            [-61.0, 22.0, -t],
        ];
        // the exact task is symmetric: positions S p, rotations conjugate
        let mirror = |p: &[f64; 3]| {
            [
                (20.0 * p[0] - 21.0 * p[1]) / 29.0,
                (-21.0 * p[0] - 20.0 * p[1]) / 29.0,
            ]
        };
        assert_eq!(mirror(&poses[0]), [poses[0][0], poses[0][1]]);
        for (i, j) in [(1, 2), (3, 4)] {
            assert_eq!(mirror(&poses[i]), [poses[j][0], poses[j][1]]);
            let (c, s) = unit_rotation(poses[i][2]).unwrap();
            assert_eq!(unit_rotation(poses[j][2]).unwrap(), (c, s.neg()));
        }
        let iv: &[(&str, &str)] = &[("-8388608", "0"), ("0", "8388608")];
        let c = certified_as_given("mirror symmetric", &poses, (2, 0, (-5, 11)), iv);
        points_match(
            &c,
            &poses,
            &[
                (-26.63844849910239, 11.416477928186739),
                (54.95663031728421, -23.552841564550377),
            ],
        );
        // at 3/7: one double root (the complex pair's common X); at -5/11
        // the certificate's Q
        let q37 = q_at_shear(&poses, 3, 7);
        let seq = sturm(&q37);
        assert_eq!((q37.len() - 1, seq.last().unwrap().len() - 1), (4, 1));
        assert_eq!(
            content_free(q_at_shear(&poses, -5, 11)),
            content_free(c.q.clone())
        );
        // the library: the two points on the axis (3 x + 7 y = 0), one in
        // each interval
        let (centers, sliders) = library(&poses).unwrap();
        one_center_per_interval(&c, &centers);
        for p in &centers {
            assert!(
                (3.0 * p[0] + 7.0 * p[1]).abs() < 1e-9 * (p[0].abs() + 1.0),
                "{p:?}"
            );
        }
        assert!(sliders.is_empty());
    }

    #[test]
    fn a_multiple_common_point_cannot_certify_and_all_six_choices_fail() {
        // poses 1 and 3 with one angle, 4 and 5 with one angle, poses 2 and
        // 3 at one position: (-1, 1/2) is a double Burmester center (the
        // library lists it twice); with the shared poses 1, 2, 3 `Q` has
        // its double root at every shear, and every other choice fails too
        let poses = [
            [0.0, 1.0, 0.0],
            [-2.0, 0.0, -0.7175413405411444],
            [-2.0, 0.0, 0.0],
            [0.0, 0.0, 2.5445947904174346],
            [-2.0, 1.0, 2.5445947904174346],
        ];
        matches_reference(
            "a multiple common point",
            &poses,
            Err("a multiple common point (Q not squarefree for any shear)"),
            Err(
                "a Burmester point at a pole (or coincident poles of higher multiplicity); \
                 a cubic of degree < 3 (the line at infinity a component); \
                 a multiple common point (Q not squarefree for any shear)",
            ),
        );
        let g = (Rat::small(-1), Rat::new(BigInt::one(), BigInt::from(2)));
        assert!(exact_center(&poses, &g));
        for (a, q) in SHEARS {
            // gcd(Q, Q') (the Sturm sequence's last member) is linear, its
            // root the center's X
            let seq = sturm(&q_at_shear(&poses, a, q));
            let gcd = seq.last().unwrap();
            let x =
                g.0.sub(&Rat::new(BigInt::from(a), BigInt::from(q)).mul(&g.1));
            assert_eq!(gcd.len(), 2, "{a}/{q}");
            assert_eq!(sign_at_rat(gcd, &x), Sign::NoSign, "{a}/{q}");
        }
    }

    #[test]
    fn a_repeated_pose_gives_a_common_component_and_all_six_choices_fail() {
        // poses 4 and 5 equal: f1 = f2 (R = 0) with the shared poses
        // 1, 2, 3; every other choice shares pose 4 or 5 with a third
        // row equal to another (a zero cubic)
        let poses = [
            [-2.0, -1.0, 0.0],
            [2.0, 1.0, 2.1616780010823367],
            [-2.0, -2.0, 2.1616780010823367],
            [-1.0, 0.0, -2.413634740570505],
            [-1.0, 0.0, -2.413634740570505],
        ];
        let [f1, f2] = int_cubics(&int_task(&poses).unwrap());
        assert_eq!(f1, f2);
        matches_reference(
            "a repeated pose",
            &poses,
            Err("a common component (the resultant vanishes)"),
            Err("a common component (the resultant vanishes); \
                 a cubic of degree < 3 (the line at infinity a component)"),
        );
    }

    #[test]
    fn equal_poses_1_and_2_give_zero_cubics() {
        // poses 1 and 2 equal: row 2 is zero, both cubics vanish
        // identically (the reference raised on an empty `max` here before
        // its fix)
        let poses = [
            [1.0, 2.0, 0.0],
            [1.0, 2.0, 0.0],
            [1.0, -1.0, 2.4440506464219793],
            [1.0, -1.0, 0.7175413405411444],
            [2.0, 0.0, 0.0],
        ];
        for f in int_cubics(&int_task(&poses).unwrap()) {
            assert_eq!(f, p2_zero());
        }
        matches_reference(
            "equal poses 1 and 2",
            &poses,
            Err("a cubic of degree < 3 (the line at infinity a component)"),
            Err("a cubic of degree < 3 (the line at infinity a component); \
                 poles at infinity (poses 1, 2, 3 all with one rotation)"),
        );
    }
}
