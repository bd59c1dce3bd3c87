//! Slider dyads and the dyad-kind seam.
//!
//! A slider is a revolute joint with its center at infinity: a pin (the
//! moving pivot) that runs on a straight guide fixed to the ground. As the
//! limit of a crank whose fixed pivot goes to infinity along the guide's
//! normal `n = i·u`, it is a [`SliderDyad`]: its circle point (the pin at
//! pose 1, which lies on the guide) and the guide's unit direction `u`.
//!
//! [`DyadKind`] is the one place a new kind of dyad is added: every
//! operation that depends on the kind (the Filemon direction of a driven
//! dyad at a pose, the assembly mode of a linkage of two dyads, how the
//! pin moves) matches on it, so a new kind is a new variant and the
//! compiler lists each place that must learn it.

use nalgebra::{Point2, Vector2};

use crate::error::{InvalidInput, Result};
use crate::geom::{Line, normalized, perp};
use crate::synthesis::{Dyad, InvertedSlider};

/// A slider dyad: a pin on a straight guide fixed to the ground.
///
/// The guide is the line through [`circle`](Self::circle) in the direction
/// [`guide`](Self::guide). The direction is defined up to sign; it is kept
/// as given (normalized) so that a stroke has a sign.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliderDyad {
    /// The circle point: the pin (moving pivot) where it is at pose 1, a
    /// point of the guide.
    pub circle: Point2<f64>,
    /// The guide's unit direction `u` in the ground.
    pub guide: Vector2<f64>,
}

impl SliderDyad {
    /// A slider dyad from its circle point and the guide's direction (any
    /// length; normalized).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::NotFinite`] when the circle point is not finite;
    /// [`InvalidInput::ZeroDirection`] when the direction is zero or not
    /// finite.
    pub fn new(circle: Point2<f64>, guide: Vector2<f64>) -> Result<Self> {
        for (name, value) in [
            ("slider circle point x", circle.x),
            ("slider circle point y", circle.y),
        ] {
            if !value.is_finite() {
                return Err(InvalidInput::NotFinite { name, value }.into());
            }
        }
        let guide = normalized(guide).ok_or(InvalidInput::ZeroDirection {
            name: "slider guide direction",
            x: guide.x,
            y: guide.y,
        })?;
        Ok(SliderDyad { circle, guide })
    }

    /// The guide's normal `n = i·u`: the direction in which the dyad's
    /// center point is at infinity.
    pub fn normal(&self) -> Vector2<f64> {
        perp(self.guide)
    }

    /// The guide: the line through the circle point along `u`.
    pub fn guide_line(&self) -> Line {
        Line {
            point: self.circle,
            direction: self.guide,
        }
    }
}

/// A dyad of any kind: the seam where a new kind of dyad is added.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum DyadKind {
    /// A crank: a revolute fixed pivot and a revolute moving pivot.
    Revolute(Dyad),
    /// A pin on a straight guide fixed to the ground (center at infinity).
    Slider(SliderDyad),
    /// A straight slot of the moving body through a block pivoted on the
    /// ground at the swivel (the circle point at infinity, normal to the
    /// slot; the kinematic inverse of a slider).
    Inverted(InvertedSlider),
}

impl DyadKind {
    /// The circle point: the moving pivot where it is at pose 1. An
    /// inverted slider's moving pivot is at infinity (normal to its slot):
    /// its one finite joint, the swivel, is returned (every operation that
    /// needs a finite circle point refuses an inverted slider first:
    /// [`InvalidInput::InvertedDriven`]).
    pub fn circle(&self) -> Point2<f64> {
        match self {
            DyadKind::Revolute(d) => d.circle,
            DyadKind::Slider(s) => s.circle,
            DyadKind::Inverted(v) => v.swivel,
        }
    }

    /// `"revolute"`, `"slider"` or `"inverted"`.
    pub fn as_str(&self) -> &'static str {
        match self {
            DyadKind::Revolute(_) => "revolute",
            DyadKind::Slider(_) => "slider",
            DyadKind::Inverted(_) => "inverted",
        }
    }
}

impl From<Dyad> for DyadKind {
    fn from(d: Dyad) -> Self {
        DyadKind::Revolute(d)
    }
}

impl From<SliderDyad> for DyadKind {
    fn from(s: SliderDyad) -> Self {
        DyadKind::Slider(s)
    }
}

impl From<InvertedSlider> for DyadKind {
    fn from(v: InvertedSlider) -> Self {
        DyadKind::Inverted(v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn new_normalizes_and_refuses_bad_input() {
        let s = SliderDyad::new(Point2::new(1.0, 2.0), Vector2::new(3.0, 4.0)).unwrap();
        assert!((s.guide - Vector2::new(0.6, 0.8)).norm() < 1e-15);
        assert!((s.normal() - Vector2::new(-0.8, 0.6)).norm() < 1e-15);
        assert!(SliderDyad::new(Point2::new(1.0, 2.0), Vector2::zeros()).is_err());
        assert!(SliderDyad::new(Point2::new(f64::NAN, 2.0), Vector2::x()).is_err());
        assert!(SliderDyad::new(Point2::origin(), Vector2::new(f64::INFINITY, 0.0)).is_err());
        let line = s.guide_line();
        assert_eq!(line.point, s.circle);
        assert_eq!(DyadKind::from(s).as_str(), "slider");
        assert_eq!(DyadKind::from(s).circle(), s.circle);
    }
}
