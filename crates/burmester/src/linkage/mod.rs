//! The four-bar linkage: position analysis, its Grashof type and input
//! range, and the figures a designer checks; the Watt II six-bar that
//! drives a four-bar's swinging input from a motor ([`SixBar`]).

pub mod actuator;
pub(crate) mod figures;
mod fourbar;
pub(crate) mod grashof;
pub mod sixbar;

pub use actuator::{ActuatorLink, LinkPoint};
pub use figures::{Direction, LinkageFigures};
pub use fourbar::{AssemblyMode, Configuration, FourBar, Joints};
pub(crate) use grashof::input_bounds;
pub use grashof::{AngleInterval, Grashof, InputRange};
pub use sixbar::{LimitPosition, SixBar, SixBarConfiguration, SixBarJoints, SixBarLengths};

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
