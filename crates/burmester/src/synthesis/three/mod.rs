//! Three-position synthesis: the Cremona map between the planes, Filemon's
//! construction and its exact transform into the driving crank's
//! center-point plane, and the dense branch sweep.

mod cremona;
mod filemon;
mod sweep;

pub use cremona::Cremona;
pub use filemon::{Filemon, Method};
pub(crate) use sweep::BranchRows;
