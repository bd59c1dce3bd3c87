//! Synthesis: the task and what it holds for each pose count.
//!
//! - [`Task`] (`task.rs`): the poses, validated once, with their motion and
//!   the part for their count, built once: three poses the maps between
//!   the planes ([`three`]), four the Burmester curves ([`four`]), five the
//!   Burmester points ([`five`]). The methods that mean one thing for any
//!   count ([`Task::dyad`], [`Task::circle_point`], [`Task::four_bar`])
//!   dispatch there.
//! - `motion.rs`: the displacements and poles in the fixed frame
//!   ([`Motion`], [`Pole`]); `local.rs`: the same motion in a local frame
//!   with the linear form of the dyad condition (the four- and five-pose
//!   arithmetic).
//! - `dyad.rs`: dyads and the four-bar of two; `branch.rs`: the branch
//!   class and Filemon's construction with one line per pose; `order.rs`:
//!   the order in which a crank meets the poses and the drives of a
//!   four-bar of two dyads; `slider.rs`: the slider dyad (a pin on a
//!   straight guide, the center at infinity) and [`DyadKind`], the one
//!   place a new kind of dyad is added; `task_slider.rs`: the slider dyads
//!   and inverted sliders of a task ([`Task::slider_dyads`],
//!   [`InvertedSlider`]).

mod branch;
mod crank_travel;
mod dyad;
pub(crate) mod errors;
pub mod five;
pub mod four;
mod inverted_crank;
mod local;
pub mod motion;
mod order;
mod slider;
mod slider_crank;
mod task;
mod task_slider;
pub mod three;

pub use branch::{Branch, FilemonLines};
pub(crate) use dyad::members_length;
pub use dyad::{Dyad, SynthesizedFourBar};
pub use five::{BurmesterFourBar, BurmesterSlider, FivePositions};
pub use four::{
    ArcEnd, CoincidencePoint, CurveDyad, FilemonArcs, FourPositions, OrderArc, PairPole,
};
pub use inverted_crank::SynthesizedInvertedSliderCrank;
pub use motion::{Motion, Pole};
pub use order::{CrankOrder, Drive, Turn};
pub use slider::{DyadKind, SliderDyad};
pub use slider_crank::SynthesizedSliderCrank;
pub use task::Task;
pub use task_slider::InvertedSlider;
