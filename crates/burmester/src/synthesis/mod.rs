//! Synthesis: the motion of the task's poses, dyads and the four-bar built
//! from two, and what is specific to three poses (`three`).

mod branch;
pub mod curves;
mod dyad;
pub mod motion;
mod task;
pub mod three;

pub use branch::{Branch, FilemonLines};
pub(crate) use dyad::members_length;
pub use dyad::{Dyad, SynthesizedFourBar};
pub use motion::{Motion, Pole};
pub use task::Task;
