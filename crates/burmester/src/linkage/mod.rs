//! The four-bar linkage: position analysis, its Grashof type and input
//! range, and the figures a designer checks; the Watt II six-bar that
//! drives a four-bar's swinging input from a motor ([`SixBar`]).

pub mod actuator;
pub(crate) mod figures;
mod fourbar;
pub(crate) mod grashof;
mod inverted;
pub mod sixbar;
mod slider;

pub use actuator::{ActuatorLink, LinkPoint};
pub use figures::{Direction, LinkageFigures};
pub use fourbar::{AssemblyMode, Configuration, FourBar, Joints};
pub(crate) use grashof::input_bounds;
pub use grashof::{AngleInterval, Grashof, InputRange};
pub use inverted::{InvertedConfiguration, InvertedJoints, InvertedLimit, InvertedSliderCrank};
pub use sixbar::{LimitPosition, SixBar, SixBarConfiguration, SixBarJoints, SixBarLengths};
pub use slider::{SliderConfiguration, SliderCrank, SliderJoints, SliderLimit};

/// Refuses a link of no length: the first pair of joints `(a, b, name)`
/// within `tiny` of each other.
///
/// # Errors
///
/// [`crate::DegenerateError::ZeroLengthLink`] naming the link, at `a`.
pub(crate) fn nonzero_links<const N: usize>(
    links: [(nalgebra::Point2<f64>, nalgebra::Point2<f64>, &'static str); N],
    tiny: f64,
) -> crate::Result<()> {
    for (a, b, what) in links {
        if (a - b).norm() <= tiny {
            return Err(crate::DegenerateError::ZeroLengthLink {
                what,
                x: a.x,
                y: a.y,
            }
            .into());
        }
    }
    Ok(())
}

/// `joints_at(theta2, mode)` (as `$Joints`), `coupler_point(c, local)` and
/// `coupler_path(local, theta2s, mode)` of a crank-driven linkage
/// `$Linkage` (fields `pivot` and `crank`, a method `joints`) whose
/// configuration `$Config` carries the crank angle `theta2` and the coupler
/// angle `theta3`, the coupler frame's origin at the crank pin and its
/// x-axis as `$axis` says: the slider-crank and the inverted slider-crank.
macro_rules! crank_coupler_methods {
    ($Linkage:ident, $Config:ident, $Joints:ident, $axis:literal) => {
        impl $Linkage {
            /// The joints at `theta2` in `mode`.
            ///
            /// # Errors
            ///
            #[doc = concat!("As [`", stringify!($Linkage), "::solve`].")]
            pub fn joints_at(&self, theta2: f64, mode: AssemblyMode) -> Result<$Joints> {
                let c = self.solve(theta2, mode)?;
                Ok(self.joints(&c))
            }

            #[doc = concat!(
                "Where a point fixed to the coupler is in a configuration (`local`\n",
                "in the coupler frame: origin at the crank pin `A`, x-axis ",
                $axis,
                ")."
            )]
            pub fn coupler_point(&self, c: &$Config, local: Vector2<f64>) -> Point2<f64> {
                self.pivot + unit(c.theta2) * self.crank + rotate(local, c.theta3)
            }

            /// The path of a coupler point over the crank angles `theta2s`,
            /// lazily: one result per angle (an error where the loop does
            /// not close).
            ///
            /// # Errors
            ///
            #[doc = concat!(
                "Each item is an error where [`", stringify!($Linkage), "::solve`] fails; a\n",
                "non-finite `local` gives [`InvalidInput::NotFinite`] for every\n",
                "item, a point whose position overflows [`InvalidInput::Overflow`]."
            )]
            pub fn coupler_path<'a, I>(
                &'a self,
                local: Vector2<f64>,
                theta2s: I,
                mode: AssemblyMode,
            ) -> impl Iterator<Item = Result<Point2<f64>>> + 'a
            where
                I: IntoIterator<Item = f64>,
                I::IntoIter: 'a,
            {
                $crate::linkage::coupler_path_of(local, theta2s, move |t| {
                    Ok(self.coupler_point(&self.solve(t, mode)?, local))
                })
            }
        }
    };
}

pub(crate) use crank_coupler_methods;

/// The path of a coupler point `local` over the input angles `theta2s`,
/// lazily, `at(t)` placing it at the angle `t` (a linkage's
/// `coupler_path`): an error where `at` fails, [`InvalidInput::NotFinite`]
/// for every item where `local` is not finite, and
/// [`InvalidInput::Overflow`] where the position overflows.
///
/// [`InvalidInput::NotFinite`]: crate::InvalidInput::NotFinite
/// [`InvalidInput::Overflow`]: crate::InvalidInput::Overflow
pub(crate) fn coupler_path_of<'a, I>(
    local: nalgebra::Vector2<f64>,
    theta2s: I,
    at: impl Fn(f64) -> crate::Result<nalgebra::Point2<f64>> + 'a,
) -> impl Iterator<Item = crate::Result<nalgebra::Point2<f64>>> + 'a
where
    I: IntoIterator<Item = f64>,
    I::IntoIter: 'a,
{
    let local_ok = crate::error::finite("coupler point u", local.x)
        .and_then(|_| crate::error::finite("coupler point v", local.y))
        .map_err(crate::Error::from);
    theta2s.into_iter().map(move |t| {
        local_ok.clone()?;
        let p = at(t)?;
        if crate::geom::point_is_finite(&p) {
            Ok(p)
        } else {
            Err(crate::InvalidInput::Overflow {
                what: "the coupler point's position",
                hint: "pass a coupler point nearer the coupler",
            }
            .into())
        }
    })
}
