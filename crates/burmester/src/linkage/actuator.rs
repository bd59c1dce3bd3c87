//! A point of a moving link of a four-bar, its position and velocity: where
//! a linear actuator is attached (see [`design::actuator`](crate::design::actuator)).
//!
//! An actuator is **added** between a ground pivot `G` and a point `Q` of a
//! moving link (the crank, the coupler or the rocker): the coupler stays
//! held by its two dyads, and the actuator of set length `s = |Q - G|`
//! removes the one degree of freedom left (6 links, 7 joints). Driving the
//! four-bar by its input angle `theta2`, the point moves with
//!
//! ```text
//! crank:   Q = A0 + e^{i theta2} q,   dQ/dtheta2 = i (Q - A0)
//! coupler: Q = A  + e^{i theta3} q,   dQ/dtheta2 = i (A - A0) + omega3 i (Q - A)
//! rocker:  Q = C0 + e^{i theta4} q,   dQ/dtheta2 = omega4 i (Q - C0)
//! ```
//!
//! with the loop's velocity ratios (differentiating
//! `r2 e^{i theta2} + r3 e^{i theta3} = g + r4 e^{i theta4}`):
//!
//! ```text
//! omega3 = r2 sin(theta4 - theta2) / (r3 sin(theta3 - theta4))
//! omega4 = r2 sin(theta3 - theta2) / (r4 sin(theta3 - theta4))
//! ```
//!
//! (infinite at a toggle, where the input cannot drive the loop: a
//! feasible linkage has none over its travel). The actuator's length
//! changes as `ds/dtheta2 = <Q - G, dQ/dtheta2> / s`.

use core::str::FromStr;

use nalgebra::{Point2, Vector2};

use crate::error::{DegenerateError, InvalidInput, Result, named};
use crate::geom::rotate;
use crate::linkage::{AssemblyMode, FourBar};

/// The moving link an actuator acts on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum ActuatorLink {
    /// The input link `A0 A`.
    Crank,
    /// The coupler `A C` (the default: a hood's strut acts on the hood).
    #[default]
    Coupler,
    /// The output link `C0 C`.
    Rocker,
}

impl ActuatorLink {
    /// Every link, the default first.
    pub const ALL: [ActuatorLink; 3] = [
        ActuatorLink::Coupler,
        ActuatorLink::Crank,
        ActuatorLink::Rocker,
    ];

    /// `"crank"`, `"coupler"` or `"rocker"`.
    pub fn as_str(self) -> &'static str {
        match self {
            ActuatorLink::Crank => "crank",
            ActuatorLink::Coupler => "coupler",
            ActuatorLink::Rocker => "rocker",
        }
    }
}

impl FromStr for ActuatorLink {
    type Err = InvalidInput;

    fn from_str(s: &str) -> core::result::Result<Self, InvalidInput> {
        let expected = "\"coupler\", \"crank\" or \"rocker\"";
        named(
            ActuatorLink::ALL,
            |l| l.as_str() == s,
            "actuator link",
            expected,
            s,
        )
    }
}

/// A point rigid with one moving link of a four-bar in one assembly mode:
/// its position and velocity per unit input angle (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkPoint {
    fourbar: FourBar,
    mode: AssemblyMode,
    link: ActuatorLink,
    /// The point in the link's frame: from the link's first joint (`A0`,
    /// `A`, `C0`), turned back by the link's angle.
    local: Vector2<f64>,
}

impl LinkPoint {
    /// The point of `link` that is at `at` when the four-bar is at input
    /// angle `theta2` in `mode`.
    ///
    /// # Errors
    ///
    /// As [`FourBar::solve`] at `theta2`; [`InvalidInput::NotFinite`] for a
    /// non-finite point; [`DegenerateError::ZeroLengthLink`] for a point on
    /// the crank's or the rocker's fixed pivot (it does not move).
    pub fn new(
        fourbar: &FourBar,
        mode: AssemblyMode,
        link: ActuatorLink,
        at: Point2<f64>,
        theta2: f64,
    ) -> Result<Self> {
        crate::error::finite_point(["actuator point x", "actuator point y"], at)?;
        let c = fourbar.solve(theta2, mode)?;
        let j = fourbar.joints(&c);
        let (origin, angle) = match link {
            ActuatorLink::Crank => (j.input_pivot, c.theta2),
            ActuatorLink::Coupler => (j.crank_joint, c.theta3),
            ActuatorLink::Rocker => (j.output_pivot, c.theta4),
        };
        let local = rotate(at - origin, -angle);
        let tiny = 1e-12 * fourbar.lengths().iter().copied().fold(0.0, f64::max);
        if link != ActuatorLink::Coupler && local.norm() <= tiny {
            return Err(DegenerateError::ZeroLengthLink {
                what: "actuator point (on the link's fixed pivot, it does not move)",
                x: at.x,
                y: at.y,
            }
            .into());
        }
        Ok(LinkPoint {
            fourbar: *fourbar,
            mode,
            link,
            local,
        })
    }

    /// The link.
    pub fn link(&self) -> ActuatorLink {
        self.link
    }

    /// The point in the link's frame (from `A0`, `A` or `C0`, turned back
    /// by the link's angle).
    pub fn local(&self) -> Vector2<f64> {
        self.local
    }

    /// Where the point is at input angle `theta2`, and its velocity per
    /// unit input angle `dQ/dtheta2` (module docs).
    ///
    /// # Errors
    ///
    /// As [`FourBar::solve`].
    pub fn at(&self, theta2: f64) -> Result<(Point2<f64>, Vector2<f64>)> {
        let fb = &self.fourbar;
        let c = fb.solve(theta2, self.mode)?;
        let j = fb.joints(&c);
        let perp = |v: Vector2<f64>| Vector2::new(-v.y, v.x);
        let [_, r2, r3, r4] = fb.lengths();
        let den = (c.theta3 - c.theta4).sin();
        Ok(match self.link {
            ActuatorLink::Crank => {
                let q = j.input_pivot + rotate(self.local, c.theta2);
                (q, perp(q - j.input_pivot))
            }
            ActuatorLink::Coupler => {
                let q = j.crank_joint + rotate(self.local, c.theta3);
                let w3 = r2 * (c.theta4 - c.theta2).sin() / (r3 * den);
                (
                    q,
                    perp(j.crank_joint - j.input_pivot) + perp(q - j.crank_joint) * w3,
                )
            }
            ActuatorLink::Rocker => {
                let q = j.output_pivot + rotate(self.local, c.theta4);
                let w4 = r2 * (c.theta3 - c.theta2).sin() / (r4 * den);
                (q, perp(q - j.output_pivot) * w4)
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The velocity agrees with a central difference of the position, on
    /// every link and both modes.
    #[test]
    fn velocity_is_the_derivative_of_the_position() {
        let fb = FourBar::new(4.0, 1.5, 3.5, 3.0).unwrap();
        for mode in AssemblyMode::BOTH {
            for link in ActuatorLink::ALL {
                let p = LinkPoint::new(&fb, mode, link, Point2::new(1.2, 2.3), 0.7).unwrap();
                for k in 0..20 {
                    let t = -1.0 + 0.1 * k as f64;
                    let h = 1e-6;
                    let (_, v) = p.at(t).unwrap();
                    let (a, _) = p.at(t - h).unwrap();
                    let (b, _) = p.at(t + h).unwrap();
                    let fd = (b - a) / (2.0 * h);
                    assert!((fd - v).norm() < 1e-7 * (1.0 + v.norm()), "{link:?} {t}");
                }
            }
        }
    }

    #[test]
    fn the_point_is_where_it_was_given() {
        let fb = FourBar::new(4.0, 1.5, 3.5, 3.0).unwrap();
        for link in ActuatorLink::ALL {
            let at = Point2::new(-0.4, 1.9);
            let p = LinkPoint::new(&fb, AssemblyMode::Open, link, at, 0.3).unwrap();
            assert!((p.at(0.3).unwrap().0 - at).norm() < 1e-14);
        }
        let e = LinkPoint::new(
            &fb,
            AssemblyMode::Open,
            ActuatorLink::Crank,
            Point2::origin(),
            0.3,
        );
        assert!(matches!(
            e,
            Err(crate::Error::Degenerate(
                DegenerateError::ZeroLengthLink { .. }
            ))
        ));
        assert!("slider".parse::<ActuatorLink>().is_err());
        for l in ActuatorLink::ALL {
            assert_eq!(l.as_str().parse::<ActuatorLink>().unwrap(), l);
        }
    }
}
