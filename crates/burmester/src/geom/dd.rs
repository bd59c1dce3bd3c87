//! Double-double numbers: about 106 bits from error-free transformations
//! of `f64`s, for the few sums that cancel most of their terms' digits (the
//! four-pose curves' coefficients, the five-pose points' last correction).

use core::ops::{Add, Mul};

/// A double-double number `hi + lo` (`|lo|` at most half an ulp of `hi`):
/// about 106 bits, from error-free transformations (Dekker's product, no
/// fused multiply-add needed), for the curves' coefficients, whose
/// expansion may cancel most of its terms' digits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Dd {
    pub(crate) hi: f64,
    pub(crate) lo: f64,
}

impl Dd {
    pub(crate) const ZERO: Dd = Dd { hi: 0.0, lo: 0.0 };

    pub(crate) fn of(v: f64) -> Dd {
        Dd { hi: v, lo: 0.0 }
    }

    /// `a + b` exactly as a double-double.
    pub(crate) fn sum(a: f64, b: f64) -> Dd {
        let s = a + b;
        let bb = s - a;
        let e = (a - (s - bb)) + (b - bb);
        Dd::fast(s, e)
    }

    /// `a + b` renormalised, for `|a| >= |b|` (or `a` zero).
    pub(crate) fn fast(a: f64, b: f64) -> Dd {
        let s = a + b;
        Dd {
            hi: s,
            lo: b - (s - a),
        }
    }

    /// `a b` exactly as a double-double (Dekker's split; exact unless a
    /// partial product overflows or underflows).
    pub(crate) fn prod(a: f64, b: f64) -> Dd {
        fn split(a: f64) -> (f64, f64) {
            let t = 134_217_729.0 * a; // 2^27 + 1
            let hi = t - (t - a);
            (hi, a - hi)
        }
        let p = a * b;
        let (ah, al) = split(a);
        let (bh, bl) = split(b);
        let e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
        // A split that overflows gives a NaN error term: the product alone.
        Dd {
            hi: p,
            lo: if e.is_finite() { e } else { 0.0 },
        }
    }

    pub(crate) fn add(self, o: Dd) -> Dd {
        let s = Dd::sum(self.hi, o.hi);
        let t = Dd::sum(self.lo, o.lo);
        let u = Dd::fast(s.hi, s.lo + t.hi);
        Dd::fast(u.hi, u.lo + t.lo)
    }

    pub(crate) fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    pub(crate) fn sub(self, o: Dd) -> Dd {
        self.add(o.neg())
    }

    pub(crate) fn mul(self, o: Dd) -> Dd {
        let p = Dd::prod(self.hi, o.hi);
        Dd::fast(p.hi, p.lo + (self.hi * o.lo + self.lo * o.hi))
    }

    /// `self b` for a double `b` (one product of doubles fewer than
    /// [`mul`](Self::mul) of `Dd::of(b)` would spend on the zero `lo`).
    pub(crate) fn mul_f64(self, b: f64) -> Dd {
        let p = Dd::prod(self.hi, b);
        Dd::fast(p.hi, p.lo + self.lo * b)
    }

    /// `self / d` for a double `d`.
    pub(crate) fn div(self, d: f64) -> Dd {
        let q1 = self.hi / d;
        let r = self.sub(Dd::prod(q1, d));
        Dd::fast(q1, r.hi / d)
    }
}

// The operators, for code written once for `f64` and `Dd` (the polynomial
// products of `synthesis::local`): the same operations as the methods.
impl Add for Dd {
    type Output = Dd;
    fn add(self, o: Dd) -> Dd {
        Dd::add(self, o)
    }
}

impl Mul for Dd {
    type Output = Dd;
    fn mul(self, o: Dd) -> Dd {
        Dd::mul(self, o)
    }
}

/// A complex (or plane) double-double `(re, im)`.
pub(crate) type Cdd = (Dd, Dd);

/// `a b` of complex double-doubles.
pub(crate) fn cmul(a: Cdd, b: Cdd) -> Cdd {
    (
        a.0.mul(b.0).sub(a.1.mul(b.1)),
        a.0.mul(b.1).add(a.1.mul(b.0)),
    )
}

/// `a - b` of complex double-doubles.
pub(crate) fn csub(a: Cdd, b: Cdd) -> Cdd {
    (a.0.sub(b.0), a.1.sub(b.1))
}

/// The conjugate of `a`.
pub(crate) fn conj(a: Cdd) -> Cdd {
    (a.0, a.1.neg())
}

/// `|a|^2`.
pub(crate) fn norm2(a: Cdd) -> Dd {
    a.0.mul(a.0).add(a.1.mul(a.1))
}
