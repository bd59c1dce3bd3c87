//! The four-bar linkage: position analysis, its Grashof type and input
//! range, and the figures a designer checks.

pub(crate) mod figures;
mod fourbar;
pub(crate) mod grashof;

pub use figures::{Direction, LinkageFigures};
pub use fourbar::{AssemblyMode, Configuration, FourBar, Joints};
pub(crate) use grashof::input_bounds;
pub use grashof::{AngleInterval, Grashof, InputRange};
