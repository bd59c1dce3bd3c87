//! The four-bar linkage: position analysis, its Grashof type and input
//! range, and the figures a designer checks; the Watt II six-bar that
//! drives a four-bar's swinging input from a motor ([`SixBar`]).

pub(crate) mod figures;
mod fourbar;
pub(crate) mod grashof;
pub mod sixbar;

pub use figures::{Direction, LinkageFigures};
pub use fourbar::{AssemblyMode, Configuration, FourBar, Joints};
pub(crate) use grashof::input_bounds;
pub use grashof::{AngleInterval, Grashof, InputRange};
pub use sixbar::{LimitPosition, SixBar, SixBarConfiguration, SixBarJoints, SixBarLengths};
