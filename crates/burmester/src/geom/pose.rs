//! Poses of the coupler and similarity transforms of the plane.

use nalgebra::{Point2, Vector2};

use crate::error::{Result, finite};
use crate::geom::rotate_cs;

/// A pose of the coupler: where a chosen coupler point is, and the coupler's
/// angle (radians, counter-clockwise from +x).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// Position of the coupler point.
    pub position: Point2<f64>,
    /// Angle of the coupler, radians.
    pub angle: f64,
}

impl Pose {
    /// A pose from coordinates and an angle in radians.
    pub const fn new(x: f64, y: f64, angle: f64) -> Self {
        Pose {
            position: Point2::new(x, y),
            angle,
        }
    }

    /// Whether every number is finite.
    pub fn is_finite(&self) -> bool {
        self.position.x.is_finite() && self.position.y.is_finite() && self.angle.is_finite()
    }

    /// Where the coupler point that is at `local` in the coupler frame
    /// (origin at the pose's point, x-axis along the coupler angle) is.
    pub fn to_world(&self, local: Vector2<f64>) -> Point2<f64> {
        let (s, c) = self.angle.sin_cos();
        self.position + rotate_cs(local, c, s)
    }

    /// The coupler-frame coordinates of the fixed point `p` (inverse of
    /// [`to_world`](Self::to_world)).
    pub fn to_local(&self, p: Point2<f64>) -> Vector2<f64> {
        let (s, c) = self.angle.sin_cos();
        rotate_cs(p - self.position, c, -s)
    }
}

/// A similarity transform of the plane: scale about the origin, rotate about
/// the origin, then translate. Optionally a mirror (reflection across the
/// x-axis) first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Similarity {
    /// Scale factor (positive).
    pub factor: f64,
    /// Rotation angle, radians.
    pub angle: f64,
    /// Translation.
    pub offset: Vector2<f64>,
    /// Reflect across the x-axis before everything else.
    pub mirror: bool,
}

impl Similarity {
    /// A similarity without mirror.
    ///
    /// # Errors
    ///
    /// [`InvalidInput`](crate::InvalidInput) for a non-finite number or a factor that is not positive.
    pub fn new(factor: f64, angle: f64, offset: Vector2<f64>) -> Result<Self> {
        crate::error::positive("scale factor", factor)?;
        finite("rotation angle", angle)?;
        finite("offset x", offset.x)?;
        finite("offset y", offset.y)?;
        Ok(Similarity {
            factor,
            angle,
            offset,
            mirror: false,
        })
    }

    /// The same transform with a reflection across the x-axis first.
    #[must_use]
    pub fn mirrored(mut self) -> Self {
        self.mirror = !self.mirror;
        self
    }

    /// Transforms a point.
    pub fn point(&self, p: Point2<f64>) -> Point2<f64> {
        let v = if self.mirror {
            Vector2::new(p.x, -p.y)
        } else {
            p.coords
        };
        let (s, c) = self.angle.sin_cos();
        Point2::from(rotate_cs(v * self.factor, c, s) + self.offset)
    }

    /// Transforms a direction (no translation, no scaling).
    pub fn direction(&self, d: Vector2<f64>) -> Vector2<f64> {
        let v = if self.mirror {
            Vector2::new(d.x, -d.y)
        } else {
            d
        };
        let (s, c) = self.angle.sin_cos();
        rotate_cs(v, c, s)
    }

    /// Transforms an angle (a direction given as an angle).
    pub fn angle_of(&self, a: f64) -> f64 {
        if self.mirror {
            self.angle - a
        } else {
            self.angle + a
        }
    }

    /// Transforms a pose.
    pub fn pose(&self, p: &Pose) -> Pose {
        Pose {
            position: self.point(p.position),
            angle: self.angle_of(p.angle),
        }
    }
}

/// The most poses a task can have (five: the Burmester points).
pub const MAX_POSES: usize = 5;

/// One value per pose of a task (at most [`MAX_POSES`]): a small `Copy`
/// array that reads as a slice, so that per-pose results need no
/// allocation.
///
/// # Example
///
/// ```
/// use burmester::geom::PerPose;
/// let angles = PerPose::from_fn(3, |k| k as f64 * 0.5);
/// assert_eq!(&angles[..], &[0.0, 0.5, 1.0]);
/// assert_eq!(angles.len(), 3);
/// ```
#[derive(Clone, Copy)]
pub struct PerPose<T> {
    items: [T; MAX_POSES],
    len: u8,
}

impl<T: Copy> PerPose<T> {
    /// `f(0), f(1), ..., f(n - 1)`.
    ///
    /// # Panics
    ///
    /// If `n` is 0 or more than [`MAX_POSES`] (callers pass a task's pose
    /// count, which is validated).
    pub fn from_fn(n: usize, mut f: impl FnMut(usize) -> T) -> Self {
        assert!(
            (1..=MAX_POSES).contains(&n),
            "a per-pose array holds 1 to {MAX_POSES} values, not {n}"
        );
        let first = f(0);
        let mut items = [first; MAX_POSES];
        for (k, item) in items.iter_mut().enumerate().take(n).skip(1) {
            *item = f(k);
        }
        PerPose {
            items,
            len: n as u8,
        }
    }

    /// The values of a slice of 1 to [`MAX_POSES`] values.
    ///
    /// # Panics
    ///
    /// If the slice is empty or longer than [`MAX_POSES`].
    pub fn from_slice(values: &[T]) -> Self {
        Self::from_fn(values.len(), |k| values[k])
    }

    /// At most [`MAX_POSES`] values, possibly none (a few results per task,
    /// kept inline), with `fill` in the rest of the room.
    ///
    /// # Panics
    ///
    /// If the slice is longer than [`MAX_POSES`].
    pub(crate) fn up_to(values: &[T], fill: T) -> Self {
        let mut items = [fill; MAX_POSES];
        items[..values.len()].copy_from_slice(values);
        PerPose {
            items,
            len: values.len() as u8,
        }
    }

    /// `g` applied to every value.
    pub fn map<U: Copy>(&self, mut g: impl FnMut(T) -> U) -> PerPose<U> {
        PerPose::from_fn(self.len(), |k| g(self.items[k]))
    }

    /// The values as a slice.
    pub fn as_slice(&self) -> &[T] {
        &self.items[..usize::from(self.len)]
    }
}

impl<T> core::ops::Deref for PerPose<T> {
    type Target = [T];

    fn deref(&self) -> &[T] {
        &self.items[..usize::from(self.len)]
    }
}

impl<T: PartialEq> PartialEq for PerPose<T> {
    fn eq(&self, other: &Self) -> bool {
        self[..] == other[..]
    }
}

impl<T: core::fmt::Debug> core::fmt::Debug for PerPose<T> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}
