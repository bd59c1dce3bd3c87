//! The lane operations shared by the SIMD kernels: the per-pivot kernel
//! of the solution map ([`crate::design`]) and the batch position
//! analysis ([`crate::linkage::FourBar::solve_into`]).
//!
//! Each is one IEEE operation of [`pulp`]'s lanes (or a select where the
//! scalar code branches), inlined into the function `pulp` dispatches so
//! that it compiles with the CPU's target features. On [`pulp::Scalar`]
//! they are plain `f64` operations: the scalar paths call the same code,
//! which is how a lane gives the scalar path's bits.

use pulp::Simd;

/// The lane operations, each inlined into the dispatched function so that
/// it compiles with the CPU's target features.
#[derive(Clone, Copy)]
pub(crate) struct Ops<S>(pub(crate) S);

/// A mask of lanes.
pub(crate) type M<S> = <S as Simd>::m64s;
/// A vector of lanes.
pub(crate) type V<S> = <S as Simd>::f64s;

/// The methods of [`Ops`] that are one `pulp` operation:
/// `name(args) -> V or M = pulp_method;` (types `V`, `M` or `f64`).
macro_rules! lane_ops {
    (@ty V) => { V<S> };
    (@ty M) => { M<S> };
    (@ty f64) => { f64 };
    ($($(#[$doc:meta])* $name:ident($($arg:ident: $t:ident),*) -> $r:ident = $op:ident;)*) => {
        $(
            $(#[$doc])*
            #[inline(always)]
            pub(crate) fn $name(self, $($arg: lane_ops!(@ty $t)),*) -> lane_ops!(@ty $r) {
                self.0.$op($($arg),*)
            }
        )*
    };
}

impl<S: Simd> Ops<S> {
    lane_ops! {
        sp(v: f64) -> V = splat_f64s;
        add(a: V, b: V) -> V = add_f64s;
        sub(a: V, b: V) -> V = sub_f64s;
        mul(a: V, b: V) -> V = mul_f64s;
        div(a: V, b: V) -> V = div_f64s;
        neg(a: V) -> V = neg_f64s;
        abs(a: V) -> V = abs_f64s;
        sqrt(a: V) -> V = sqrt_f64s;
        lt(a: V, b: V) -> M = less_than_f64s;
        gt(a: V, b: V) -> M = greater_than_f64s;
        le(a: V, b: V) -> M = less_than_or_equal_f64s;
        ge(a: V, b: V) -> M = greater_than_or_equal_f64s;
        eq(a: V, b: V) -> M = equal_f64s;
        and(a: M, b: M) -> M = and_m64s;
        or(a: M, b: M) -> M = or_m64s;
        xor(a: M, b: M) -> M = xor_m64s;
        not(a: M) -> M = not_m64s;
        /// `m ? a : b` per lane.
        sel(m: M, a: V, b: V) -> V = select_f64s;
    }
    /// The scalar path's `fmax` (`if a > b { a } else { b }`).
    #[inline(always)]
    pub(crate) fn fmax(self, a: V<S>, b: V<S>) -> V<S> {
        self.sel(self.gt(a, b), a, b)
    }
    /// The scalar path's `fmin` (`if a < b { a } else { b }`).
    #[inline(always)]
    pub(crate) fn fmin(self, a: V<S>, b: V<S>) -> V<S> {
        self.sel(self.lt(a, b), a, b)
    }
    #[inline(always)]
    pub(crate) fn finite(self, a: V<S>) -> M<S> {
        self.lt(self.abs(a), self.sp(f64::INFINITY))
    }
    /// `sqrt(x^2 + y^2)`, as nalgebra's `norm`.
    #[inline(always)]
    pub(crate) fn norm(self, x: V<S>, y: V<S>) -> V<S> {
        self.sqrt(self.add(self.mul(x, x), self.mul(y, y)))
    }
    /// `r . v`.
    #[inline(always)]
    pub(crate) fn dot(self, rx: V<S>, ry: V<S>, vx: V<S>, vy: V<S>) -> V<S> {
        self.add(self.mul(rx, vx), self.mul(ry, vy))
    }
    /// `r x v`.
    #[inline(always)]
    pub(crate) fn cross(self, rx: V<S>, ry: V<S>, vx: V<S>, vy: V<S>) -> V<S> {
        self.sub(self.mul(rx, vy), self.mul(ry, vx))
    }
}

/// The lane operations [`atan2`] is written against: those of [`Ops`] (on
/// every lane width `pulp` dispatches to) and those of `wide::f64x2` (two
/// lanes on the compiled target, for a single
/// [`FourBar::solve`](crate::linkage::FourBar::solve) without a dispatch). Every one is an
/// IEEE operation or a select, so both give the same bits.
pub(crate) trait Lanes: Copy {
    /// A vector of lanes.
    type F: Copy;
    /// A mask of lanes.
    type M: Copy;
    fn sp(self, v: f64) -> Self::F;
    fn add(self, a: Self::F, b: Self::F) -> Self::F;
    fn sub(self, a: Self::F, b: Self::F) -> Self::F;
    fn mul(self, a: Self::F, b: Self::F) -> Self::F;
    fn div(self, a: Self::F, b: Self::F) -> Self::F;
    fn neg(self, a: Self::F) -> Self::F;
    fn abs(self, a: Self::F) -> Self::F;
    fn sqrt(self, a: Self::F) -> Self::F;
    fn lt(self, a: Self::F, b: Self::F) -> Self::M;
    fn gt(self, a: Self::F, b: Self::F) -> Self::M;
    fn ge(self, a: Self::F, b: Self::F) -> Self::M;
    fn eq(self, a: Self::F, b: Self::F) -> Self::M;
    fn and(self, a: Self::M, b: Self::M) -> Self::M;
    /// `m ? a : b` per lane.
    fn sel(self, m: Self::M, a: Self::F, b: Self::F) -> Self::F;
    /// Whether the sign bit is set (`-0.0` included).
    fn sign_negative(self, a: Self::F) -> Self::M;
}

macro_rules! forward {
    ($($name:ident($($arg:ident: $t:ident),*) -> $r:ident;)*) => {
        $(
            #[inline(always)]
            fn $name(self, $($arg: Self::$t),*) -> Self::$r {
                Ops::$name(self, $($arg),*)
            }
        )*
    };
}

impl<S: Simd> Lanes for Ops<S> {
    type F = V<S>;
    type M = M<S>;
    #[inline(always)]
    fn sp(self, v: f64) -> V<S> {
        Ops::sp(self, v)
    }
    forward! {
        add(a: F, b: F) -> F;
        sub(a: F, b: F) -> F;
        mul(a: F, b: F) -> F;
        div(a: F, b: F) -> F;
        neg(a: F) -> F;
        abs(a: F) -> F;
        sqrt(a: F) -> F;
        lt(a: F, b: F) -> M;
        gt(a: F, b: F) -> M;
        ge(a: F, b: F) -> M;
        eq(a: F, b: F) -> M;
        and(a: M, b: M) -> M;
        sel(m: M, a: F, b: F) -> F;
    }
    /// Whether the sign bit is set (`-0.0` included).
    #[inline(always)]
    fn sign_negative(self, a: V<S>) -> M<S> {
        let s = self.0;
        let bits = s.transmute_i64s_u64s(s.transmute_u64s_f64s(a));
        s.less_than_i64s(bits, s.splat_i64s(0))
    }
}

/// `Lanes` methods given as a table: `name(args) -> F or M = body;`, the
/// body an expression of the arguments (the two-lane [`Pair`]'s methods,
/// each one operation of `wide`).
macro_rules! lane_fns {
    ($($name:ident($($arg:ident: $t:ident),*) -> $r:ident = $body:expr;)*) => {
        $(
            #[inline(always)]
            fn $name(self, $($arg: Self::$t),*) -> Self::$r {
                $body
            }
        )*
    };
}

/// Two lanes of `wide` on the compiled target (SSE2 on x86-64, NEON on
/// aarch64): the single [`FourBar::solve`](crate::linkage::FourBar::solve).
#[derive(Clone, Copy)]
pub(crate) struct Pair;

impl Lanes for Pair {
    type F = wide::f64x2;
    type M = wide::f64x2;
    #[inline(always)]
    fn sp(self, v: f64) -> wide::f64x2 {
        wide::f64x2::splat(v)
    }
    lane_fns! {
        add(a: F, b: F) -> F = a + b;
        sub(a: F, b: F) -> F = a - b;
        mul(a: F, b: F) -> F = a * b;
        div(a: F, b: F) -> F = a / b;
        neg(a: F) -> F = -a;
        abs(a: F) -> F = a.abs();
        sqrt(a: F) -> F = a.sqrt();
        lt(a: F, b: F) -> M = a.simd_lt(b);
        gt(a: F, b: F) -> M = a.simd_gt(b);
        ge(a: F, b: F) -> M = a.simd_ge(b);
        eq(a: F, b: F) -> M = a.simd_eq(b);
        and(a: M, b: M) -> M = a & b;
        sel(m: M, a: F, b: F) -> F = m.select(a, b);
        sign_negative(a: F) -> M = a.is_sign_negative();
    }
}

/// `atan2(y, x)` on each lane of `o`: Cephes' rational approximation of
/// `atan` (as `wide` and Agner Fog's vector class library use it) on the
/// first octant, `atan(y/x)` below `y/x = 0.66` and `pi/4 + atan((y - x) /
/// (y + x))` above, with the quotient of each range taken directly (two
/// dependent divisions per angle, not three), every `mul_add` an unfused
/// multiply and add, so that it gives the same bits on every lane width
/// and every CPU. Within 2 ulp of the exact angle.
#[inline(always)]
pub(crate) fn atan2<L: Lanes>(o: L, y: L::F, x: L::F) -> L::F {
    use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
    const MORE_BITS: f64 = 6.123233995736766E-17;
    const P: [f64; 5] = [
        -64.85021904942025,
        -122.88666844901361,
        -75.00855792314705,
        -16.157537187333652,
        -0.8750608600031904,
    ];
    const Q: [f64; 5] = [
        194.5506571482614,
        485.3903996359137,
        432.88106049129027,
        165.02700983169885,
        24.858464901423062,
    ];
    /// Above this the sum `y + x` of the upper range could overflow: both
    /// are scaled by `2^-8` first (exactly: they are normal numbers there).
    const HUGE: f64 = 8.98846567431158e307; // 2^1023
    let zero = o.sp(0.0);
    // Into the first octant: 0 <= y2 <= x2.
    let (x1, y1) = (o.abs(x), o.abs(y));
    let swap = o.gt(y1, x1);
    let mut x2 = o.sel(swap, y1, x1);
    let mut y2 = o.sel(swap, x1, y1);
    // Both infinite: the octant's diagonal.
    let inf = o.sp(f64::INFINITY);
    let both = o.and(o.eq(x1, inf), o.eq(y1, inf));
    x2 = o.sel(both, o.sp(1.0), x2);
    y2 = o.sel(both, o.sp(1.0), y2);
    // The upper range, y2 / x2 >= 0.66 (a rounding of the product moves
    // the border by an ulp, where both ranges are accurate): z = (y2 - x2)
    // / (y2 + x2), the difference exact (Sterbenz); else z = y2 / x2. For
    // x = y = 0 this is NaN, replaced below.
    let upper = o.ge(y2, o.mul(o.sp(0.66), x2));
    let k = o.sel(o.gt(x2, o.sp(HUGE)), o.sp(1.0 / 256.0), o.sp(1.0));
    let (xs, ys) = (o.mul(x2, k), o.mul(y2, k));
    let num = o.sel(upper, o.sub(ys, xs), y2);
    let den = o.sel(upper, o.add(ys, xs), x2);
    let z = o.div(num, den);
    let s = o.sel(upper, o.sp(FRAC_PI_4), zero);
    let fac = o.sel(upper, o.sp(MORE_BITS * 0.5), zero);
    let zz = o.mul(z, z);
    let [p0, p1, p2, p3, p4] = P.map(|c| o.sp(c));
    let [q0, q1, q2, q3, q4] = Q.map(|c| o.sp(c));
    let (z2, z4) = {
        let z2 = o.mul(zz, zz);
        (z2, o.mul(z2, z2))
    };
    let px = o.add(
        mul_add(o, mul_add(o, p3, zz, p2), z2, mul_add(o, p1, zz, p0)),
        o.mul(p4, z4),
    );
    let qx = mul_add(
        o,
        z2,
        mul_add(o, zz, q3, q2),
        mul_add(o, z4, o.add(q4, zz), mul_add(o, zz, q1, q0)),
    );
    let re = mul_add(o, o.div(px, qx), o.mul(z, zz), z);
    let re = o.add(re, o.add(s, fac));
    // Back into place.
    let re = o.sel(swap, o.sub(o.sp(FRAC_PI_2), re), re);
    let re = o.sel(o.and(o.eq(x, zero), o.eq(y, zero)), zero, re);
    let re = o.sel(o.sign_negative(x), o.sub(o.sp(PI), re), re);
    o.sel(o.sign_negative(y), o.neg(re), re)
}

/// `acos(x)` on each lane of `o`: Cephes' method (`asin` of an argument
/// at most 1/2 by `a + a^3 P(a^2) / Q(a^2)`, through `acos(x) =
/// 2 asin(sqrt((1 - x) / 2))` above 1/2, `pi - 2 asin(sqrt((1 + x) / 2))`
/// below -1/2 and `pi/2 - asin(x)` between), one rational function for
/// every lane and the ranges picked by selects, so that it gives the same
/// bits on every lane width and every CPU (libm's `acos` differs between
/// platforms). Within 2 ulp of the exact angle; NaN outside `[-1, 1]`.
#[inline(always)]
pub(crate) fn acos<L: Lanes>(o: L, x: L::F) -> L::F {
    use core::f64::consts::{FRAC_PI_2, FRAC_PI_4};
    /// `pi/2` less its double: the bits `FRAC_PI_2` leaves out.
    const MORE_BITS: f64 = 6.123233995736766e-17;
    const P: [f64; 6] = [
        0.004253011369004428,
        -0.6019598008014124,
        5.444622390564711,
        -16.262479672107002,
        19.562619833175948,
        -8.198089802484825,
    ];
    const Q: [f64; 6] = [
        1.0,
        -14.740913729888538,
        70.49610280856842,
        -147.1791292232726,
        139.51056146574857,
        -49.18853881490881,
    ];
    let half = o.sp(0.5);
    let hi = o.gt(x, half);
    let lo = o.lt(x, o.neg(half));
    // The argument of asin, in [-1/2, 1/2]: sqrt((1 -+ x) / 2) outside
    // [-1/2, 1/2] (exact differences by Sterbenz' lemma), x inside.
    let hx = o.mul(half, x);
    let a = o.sel(
        hi,
        o.sqrt(o.sub(half, hx)),
        o.sel(lo, o.sqrt(o.add(half, hx)), x),
    );
    let zz = o.mul(a, a);
    let z = o.div(o.mul(zz, horner(o, zz, &P)), horner(o, zz, &Q));
    let asin = o.add(o.mul(a, z), a);
    let twice = o.add(asin, asin);
    // Between: (pi/4 - asin) + the lost bits + pi/4, as Cephes.
    let mid = o.add(
        o.add(o.sub(o.sp(FRAC_PI_4), asin), o.sp(MORE_BITS)),
        o.sp(FRAC_PI_4),
    );
    // Below: (pi/2 - 2 asin) + twice the lost bits + pi/2.
    let below = o.add(
        o.add(o.sub(o.sp(FRAC_PI_2), twice), o.sp(2.0 * MORE_BITS)),
        o.sp(FRAC_PI_2),
    );
    o.sel(hi, twice, o.sel(lo, below, mid))
}

/// `a * b + c`, unfused (the same bits on every lane width and CPU).
#[inline(always)]
fn mul_add<L: Lanes>(o: L, a: L::F, b: L::F, c: L::F) -> L::F {
    o.add(o.mul(a, b), c)
}

/// `c[0] z^5 + c[1] z^4 + ... + c[5]` by Horner's rule. A function, not a
/// closure, and always inlined: an outlined call here leaves the caller's
/// SIMD context (the solution map ran at half speed that way).
#[inline(always)]
fn horner<L: Lanes>(o: L, z: L::F, c: &[f64; 6]) -> L::F {
    let mut r = o.sp(c[0]);
    for &k in &c[1..] {
        r = o.add(o.mul(r, z), o.sp(k));
    }
    r
}

/// [`acos`] of one `f64`: the crate's `acos` wherever a result must be the
/// lanes' bits (the minimum transmission angle).
#[inline]
pub(crate) fn acos1(x: f64) -> f64 {
    acos(Ops(pulp::Scalar), x)
}

/// A lane width a kernel's tests run it on.
#[cfg(test)]
#[derive(Debug, Clone, Copy)]
pub(crate) enum Width {
    /// One lane: the scalar path.
    One,
    /// 128 bits, emulated.
    B128,
    /// 256 bits, emulated.
    B256,
    /// 512 bits, emulated.
    B512,
    /// The machine's own, as dispatched.
    Dispatched,
}

#[cfg(test)]
impl Width {
    /// Every width, the scalar path first.
    pub(crate) const ALL: [Width; 5] = [
        Width::One,
        Width::B128,
        Width::B256,
        Width::B512,
        Width::Dispatched,
    ];

    /// Runs `kernel` on this width.
    pub(crate) fn run<K: pulp::WithSimd>(self, kernel: K) -> K::Output {
        match self {
            Width::One => kernel.with_simd(pulp::Scalar),
            Width::B128 => kernel.with_simd(pulp::Scalar128b),
            Width::B256 => kernel.with_simd(pulp::Scalar256b),
            Width::B512 => kernel.with_simd(pulp::Scalar512b),
            Width::Dispatched => pulp::Arch::new().dispatch(kernel),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Ops, Pair, V, acos, atan2};
    use pulp::Simd;

    /// Units in the last place between two finite doubles of one sign.
    fn ulps(a: f64, b: f64) -> u64 {
        (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs()
    }

    fn inputs() -> Vec<(f64, f64)> {
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut v = Vec::new();
        for _ in 0..200_000 {
            let u = |r: u64| (r >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            v.push((10.0 * u(next()), 10.0 * u(next())));
            // Any finite magnitudes, both signs.
            let e = |r: u64| f64::from_bits(r & 0x7fef_ffff_ffff_ffff);
            v.push((e(next()), e(next())));
        }
        // Each range of the reduction and its edges, on both sides of the
        // swap (t = 0.66, 1 + sqrt 2, 1).
        for t in [
            0.66,
            0.66f64.next_down(),
            2.414213562373095,
            2.4142135623730954,
            1.0,
        ] {
            for s in [1.0, -1.0] {
                v.push((s * t, 1.0));
                v.push((1.0, s * t));
            }
        }
        v
    }

    #[test]
    fn atan2_is_within_two_ulp_of_libm() {
        let o = Ops(pulp::Scalar);
        for (y, x) in inputs() {
            let (got, want) = (atan2(o, y, x), libm::atan2(y, x));
            if want.abs() < 1e-300 {
                // Underflowing quotients: both at the smallest scales.
                assert!(
                    (got - want).abs() <= 1e-300,
                    "atan2({y}, {x}) = {got}, not {want}"
                );
                continue;
            }
            assert_eq!(got.is_sign_negative(), want.is_sign_negative(), "{y} {x}");
            assert!(ulps(got, want) <= 2, "atan2({y}, {x}) = {got}, not {want}");
        }
    }

    #[test]
    fn atan2_has_ieee_special_values() {
        use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
        let o = Ops(pulp::Scalar);
        let inf = f64::INFINITY;
        let cases = [
            (0.0, 0.0, 0.0),
            (-0.0, 0.0, -0.0),
            (0.0, -0.0, PI),
            (-0.0, -0.0, -PI),
            (1.0, 0.0, FRAC_PI_2),
            (-1.0, 0.0, -FRAC_PI_2),
            (0.0, -1.0, PI),
            (-0.0, -1.0, -PI),
            (inf, inf, FRAC_PI_4),
            (-inf, inf, -FRAC_PI_4),
            (inf, -inf, 3.0 * FRAC_PI_4),
            (1.0, inf, 0.0),
            (1.0, -inf, PI),
            (inf, 1.0, FRAC_PI_2),
        ];
        for (y, x, want) in cases {
            let got = atan2(o, y, x);
            assert!(ulps(got, want) <= 2, "atan2({y}, {x}) = {got}, not {want}");
        }
        assert!(atan2(o, f64::NAN, 1.0).is_nan() && atan2(o, 1.0, f64::NAN).is_nan());
    }

    /// `wide`'s two lanes (the single solve) give the scalar bits.
    #[test]
    fn atan2_on_wide_pairs_is_the_scalar_bits() {
        let o = Ops(pulp::Scalar);
        let mut v = inputs();
        for a in [
            0.0,
            -0.0,
            1.0,
            -1.0,
            f64::INFINITY,
            -f64::INFINITY,
            f64::NAN,
        ] {
            for b in [0.0, -0.0, 2.0, -2.0, f64::INFINITY, -f64::INFINITY] {
                v.push((a, b));
            }
        }
        for w in v.chunks_exact(2) {
            let [(y0, x0), (y1, x1)] = [w[0], w[1]];
            let pair = atan2(Pair, wide::f64x2::new([y0, y1]), wide::f64x2::new([x0, x1]));
            for (got, (y, x)) in pair.to_array().into_iter().zip([(y0, x0), (y1, x1)]) {
                let want = atan2(o, y, x);
                assert!(
                    got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                    "atan2({y}, {x}): {got} on a pair, {want} on a scalar"
                );
            }
        }
    }

    /// Every lane width gives the scalar bits.
    #[test]
    fn atan2_lanes_are_the_scalar_bits() {
        fn run<S: Simd>(s: S, ys: &[f64], xs: &[f64]) -> Vec<f64> {
            let o = Ops(s);
            let (yv, _) = S::as_simd_f64s(ys);
            let (xv, _) = S::as_simd_f64s(xs);
            let mut out = vec![0.0; ys.len()];
            let (ov, _) = S::as_mut_simd_f64s(&mut out);
            for ((r, &y), &x) in ov.iter_mut().zip(yv).zip(xv) {
                let v: V<S> = atan2(o, y, x);
                *r = v;
            }
            out
        }
        let (ys, xs): (Vec<f64>, Vec<f64>) = inputs().into_iter().take(4096).unzip();
        let scalar = run(pulp::Scalar, &ys, &xs);
        for lanes in [
            run(pulp::Scalar128b, &ys, &xs),
            run(pulp::Scalar256b, &ys, &xs),
            run(pulp::Scalar512b, &ys, &xs),
        ] {
            for (a, b) in scalar.iter().zip(&lanes) {
                assert_eq!(a.to_bits(), b.to_bits());
            }
        }
    }

    fn acos_inputs() -> Vec<f64> {
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut v = Vec::new();
        for _ in 0..200_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let u = (state >> 11) as f64 / (1u64 << 53) as f64;
            v.push(2.0 * u - 1.0);
            // Near +-1, where the angle is small or near pi.
            v.push(1.0 - u * u * u * 1e-6);
            v.push(-1.0 + u * u * u * 1e-6);
            // Tiny magnitudes.
            v.push(f64::from_bits(state & 0x3e7f_ffff_ffff_ffff));
        }
        for t in [0.5f64, 1.0, 0.0, 1e-300, 5e-324] {
            for s in [1.0, -1.0] {
                v.extend([s * t, s * t.next_up(), s * t.next_down()]);
            }
        }
        v.retain(|x| x.abs() <= 1.0);
        v
    }

    #[test]
    fn acos_is_within_two_ulp_of_libm() {
        let o = Ops(pulp::Scalar);
        let mut worst = 0;
        for x in acos_inputs() {
            let (got, want) = (acos(o, x), libm::acos(x));
            let d = ulps(got, want);
            worst = worst.max(d);
            assert!(d <= 1, "acos({x}) = {got}, not {want}");
        }
        assert!(worst >= 1, "the inputs reach no rounding difference at all");
        assert_eq!(acos(o, 1.0), 0.0);
        assert_eq!(acos(o, -1.0), core::f64::consts::PI);
        assert_eq!(acos(o, 0.0), core::f64::consts::FRAC_PI_2);
        for x in [1.0f64.next_up(), (-1.0f64).next_down(), 2.0, -7.0, f64::NAN] {
            assert!(acos(o, x).is_nan(), "acos({x}) is not NaN");
        }
        for x in [f64::INFINITY, -f64::INFINITY] {
            assert!(acos(o, x).is_nan(), "acos({x}) is not NaN");
        }
    }

    /// The solution map stores the minimum transmission angle as `f32`:
    /// rounded there, the crate's `acos` is libm's on every input tried.
    #[test]
    fn acos_as_f32_is_libms() {
        let o = Ops(pulp::Scalar);
        let mut differ = 0;
        for x in acos_inputs().into_iter().filter(|x| *x >= 0.0) {
            if acos(o, x) as f32 != libm::acos(x) as f32 {
                differ += 1;
            }
        }
        assert_eq!(differ, 0);
    }

    /// Every lane width and `wide`'s pairs give the scalar bits.
    #[test]
    fn acos_lanes_are_the_scalar_bits() {
        fn run<S: Simd>(s: S, xs: &[f64]) -> Vec<f64> {
            let o = Ops(s);
            let (xv, _) = S::as_simd_f64s(xs);
            let mut out = vec![0.0; xs.len()];
            let (ov, _) = S::as_mut_simd_f64s(&mut out);
            for (r, &x) in ov.iter_mut().zip(xv) {
                let v: V<S> = acos(o, x);
                *r = v;
            }
            out
        }
        let mut xs = acos_inputs();
        xs.extend([2.0, -2.0, f64::NAN, f64::INFINITY]);
        xs.truncate(xs.len() / 8 * 8);
        let scalar = run(pulp::Scalar, &xs);
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
        for lanes in [
            run(pulp::Scalar128b, &xs),
            run(pulp::Scalar256b, &xs),
            run(pulp::Scalar512b, &xs),
        ] {
            for (&a, &b) in scalar.iter().zip(&lanes) {
                assert!(same(a, b), "{a} {b}");
            }
        }
        #[cfg(target_arch = "x86_64")]
        if let Some(v3) = pulp::x86::V3::try_new() {
            for (&a, &b) in scalar.iter().zip(&run(v3, &xs)) {
                assert!(same(a, b), "{a} {b} (AVX2)");
            }
        }
        for (w, want) in xs.chunks_exact(2).zip(scalar.chunks_exact(2)) {
            let pair = acos(Pair, wide::f64x2::new([w[0], w[1]])).to_array();
            assert!(same(pair[0], want[0]) && same(pair[1], want[1]));
        }
    }
}
