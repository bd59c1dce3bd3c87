//! Local frames: the curves and maps work in coordinates centred on their
//! task and measured in its size, so that no formula loses digits to where
//! the task sits or overflows at its size.

use nalgebra::{Point2, Vector2};

/// Local coordinates beyond which a point is evaluated scaled: a curve's
/// value at `v` is computed as `f(v) / m^d` with `m = max(|x|, |y|)`, which
/// keeps its sign and cannot overflow. Nearer points are evaluated by the
/// plain formula, bit for bit as a grid sweep does.
pub(crate) const FAR: f64 = 1e100;

/// A frame in which a point `p` of the plane is `origin + scale v`: the one
/// home of the conversions of the curves and maps that work locally.
pub(crate) trait LocalFrame {
    /// The frame's origin and unit, in the fixed frame.
    fn frame(&self) -> (Point2<f64>, f64);

    /// The local coordinates of a fixed point.
    #[inline]
    fn local_of(&self, p: Point2<f64>) -> Vector2<f64> {
        let (origin, scale) = self.frame();
        (p - origin) / scale
    }

    /// A local vector back in the fixed frame.
    #[inline]
    fn global_of(&self, v: Vector2<f64>) -> Point2<f64> {
        let (origin, scale) = self.frame();
        origin + v * scale
    }

    /// The local coordinates `v` of `p` as `(v / m, m)`: `m = 1` (and `v`
    /// bit for bit) when `max(|x|, |y|) <= FAR`, else `m = max(|x|, |y|)`,
    /// computed without overflow in `v / m` (`m` itself may be infinite).
    #[inline]
    fn local_scaled(&self, p: Point2<f64>) -> (Vector2<f64>, f64) {
        let v = self.local_of(p);
        if v.x.abs().max(v.y.abs()) <= FAR {
            return (v, 1.0);
        }
        let (origin, scale) = self.frame();
        let w = p - origin;
        let mw = w.x.abs().max(w.y.abs());
        (w / mw, mw / scale)
    }
}

/// [`LocalFrame`] for a type that keeps its frame in the fields `origin`
/// and `scale`.
macro_rules! local_frame {
    ($ty:ident) => {
        impl $crate::geom::LocalFrame for $ty {
            #[inline]
            fn frame(&self) -> (nalgebra::Point2<f64>, f64) {
                (self.origin, self.scale)
            }
        }
    };
}
pub(crate) use local_frame;
