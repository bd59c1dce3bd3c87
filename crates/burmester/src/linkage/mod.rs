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

/// What an error says to do with an angle beyond the largest (a crank
/// angle, a pose's angle).
pub(crate) const ANGLE_HINT: &str =
    "reduce it modulo 2 pi (beyond, a double cannot hold the angle to 1e-7 rad)";

/// Refuses a crank angle `theta2` that is not finite or beyond
/// [`FourBar::MAX_ANGLE`] (the largest of every crank-driven linkage).
pub(crate) fn bounded_theta2(theta2: f64) -> core::result::Result<f64, crate::InvalidInput> {
    crate::error::bounded("theta2", theta2, FourBar::MAX_ANGLE, ANGLE_HINT)
}

/// `MAX_ANGLE`, `crank_pivot()`, `crank()`, `joints_at(theta2, mode)` (as
/// `$Joints`), `coupler_point(c, local)` and `coupler_path(local, theta2s,
/// mode)` of a crank-driven linkage `$Linkage` (fields `pivot` and
/// `crank`, a method `joints`) whose configuration `$Config` carries the
/// crank angle `theta2` and the coupler angle `theta3`, the coupler
/// frame's origin at the crank pin and its x-axis as `$axis` says: the
/// slider-crank and the inverted slider-crank.
macro_rules! crank_coupler_methods {
    ($Linkage:ident, $Config:ident, $Joints:ident, $axis:literal) => {
        impl $Linkage {
            /// The largest crank angle magnitude, radians ([`FourBar::MAX_ANGLE`]).
            pub const MAX_ANGLE: f64 = $crate::FourBar::MAX_ANGLE;

            /// The crank pivot `A0`.
            pub fn crank_pivot(&self) -> Point2<f64> {
                self.pivot
            }
            /// The crank length `r`.
            pub fn crank(&self) -> f64 {
                self.crank
            }

            /// The joints at `theta2` in `mode`.
            ///
            /// # Errors
            ///
            #[doc = concat!("As [`", stringify!($Linkage), "::solve`].")]
            pub fn joints_at(&self, theta2: f64, mode: AssemblyMode) -> Result<$Joints> {
                let c = self.solve(theta2, mode)?;
                Ok(self.joints(&c))
            }

            /// Where a point fixed to the coupler is in a configuration (`local`
            #[doc = concat!("in the coupler frame: origin at the crank pin `A`, x-axis ", $axis, ").")]
            pub fn coupler_point(&self, c: &$Config, local: Vector2<f64>) -> Point2<f64> {
                self.pivot + unit(c.theta2) * self.crank + rotate(local, c.theta3)
            }
        }

        $crate::linkage::coupler_path_method!($Linkage, |l, t, mode, local| {
            Ok(l.coupler_point(&l.solve(t, mode)?, local))
        });
    };
}

pub(crate) use crank_coupler_methods;

/// `coupler_path(local, theta2s, mode)` of a linkage `$Linkage` with a
/// method `solve`, `|l, t, mode, local| body` placing the coupler point
/// `local` of the linkage `l` at the input angle `t` in `mode`: the
/// four-bar, the slider-crank and the inverted slider-crank.
macro_rules! coupler_path_method {
    ($Linkage:ident, |$l:ident, $t:ident, $mode:ident, $local:ident| $body:expr) => {
        impl $Linkage {
            /// The path of a coupler point over the input angles `theta2s`,
            /// lazily: one result per angle (an error where the loop does
            /// not close).
            ///
            /// # Errors
            ///
            #[doc = concat!(
                "Each item is an error where [`", stringify!($Linkage), "::solve`] fails; a\n",
                "non-finite `local` gives [`InvalidInput::NotFinite`] for every\n",
                "item, and a point so far from the coupler that its position\n",
                "overflows gives [`InvalidInput::Overflow`]."
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
                let at = |$l: &Self,
                          $t: f64,
                          $mode: AssemblyMode,
                          $local: Vector2<f64>|
                 -> Result<Point2<f64>> { $body };
                $crate::linkage::coupler_path_of(local, theta2s, move |t| at(self, t, mode, local))
            }
        }
    };
}

pub(crate) use coupler_path_method;

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
