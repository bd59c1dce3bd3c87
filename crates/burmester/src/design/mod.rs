//! The designer's solution-space map: from branch-free to buildable and
//! good.
//!
//! The paper stops at branch-free and names Grashof type and order as
//! future work. For every candidate driving center point `A0` on a grid
//! (the same grid as the branch map), [`Filemon::solution_map`](crate::Filemon::solution_map) gives:
//!
//! * whether the linkage exists (a circle point, links of nonzero length);
//! * the branch-free flag (exactly the branch map's);
//! * the Grashof class, and whether the driving link turns fully;
//! * order and circuit: the input rotation direction that carries the
//!   coupler from pose 1 through pose 2 to pose 3, or none; for a rocker
//!   input, whether the three input angles lie on one circuit (one arc of
//!   the input range) with pose 2 between poses 1 and 3;
//! * the minimum transmission angle over the whole travel from pose 1
//!   through pose 2 to pose 3 (not only at the poses);
//! * the ratio of the longest to the shortest link;
//! * an `acceptable` mask from [`DesignLimits`] and [`Constraints`].
//!
//! [`Task::driven_solution_map`](crate::Task::driven_solution_map) does the same the other way round: a
//! fixed driving dyad, candidate driven center points.
//!
//! With a slider as the driven dyad (a [`Filemon`](crate::Filemon) of a
//! [`SliderDyad`](crate::SliderDyad)), each sample's linkage is a
//! slider-crank and the columns are its figures (`map_slider`:
//! the crank's rotatability `r + |e| <= l` in place of Grashof's law, the
//! transmission angle between coupler and guide normal;
//! [`MapContext::slider_crank`]).
//!
//! For four poses, [`Task::pair_map`](crate::Task::pair_map) gives the same
//! columns over pairs of dyads along the center-point curve: every linkage
//! of the task on one picture ([`pairs`]).
//!
//! [`Task::design`](crate::Task::design) puts it together: from the poses,
//! the [`Space`] in the machine and the [`DesignLimits`] to the best
//! linkages, searched over both fixed pivots (three poses), both curve
//! parameters (four) or every pair of Burmester points (five), refined
//! continuously on the exact figures ([`search`]).
//!
//! The three-pose driving map and the [`atlas`] compute their samples on
//! SIMD lanes (AVX2 where the CPU has it, chosen at run time by `pulp`),
//! bit for bit what the per-sample scalar code gives.
//!
//! How each figure is computed is in [`linkage::figures`](crate::linkage::LinkageFigures);
//! the constraints, the clearance check and its bound are in
//! [`Constraints`]; the maps run on the tiled [`engine`](crate::engine).
//!
//! A linkage whose input only swings is driven from a motor by an added
//! dyad: [`drive`] maps the candidate crank pivots of that dyad (the Watt
//! II six-bar, [`SixBar`](crate::SixBar)) and ranks them the same way.

pub mod actuator;
pub mod atlas;
mod columns;
mod constraints;
pub mod drive;
mod judge;
mod kernel;
mod limits;
mod map;
mod map_slider;
mod options;
pub mod pairs;
mod rank;
pub mod search;
mod space;

pub use actuator::{
    Actuator, ActuatorColumns, ActuatorColumnsOut, ActuatorContext, ActuatorMap, ActuatorOptions,
    ActuatorRankColumns,
};
pub use atlas::{AtlasBest, AtlasCell, PivotAtlas};
pub use columns::{Columns, ColumnsOut};
pub use constraints::Constraints;
pub use drive::{
    AttachmentSearch, CrankRockerDesign, Drive, DriveColumns, DriveColumnsOut, DriveContext,
    DriveFigures, DriveMap, DriveOptions, DriveRankColumns, DriveSearch, best_drive, search_drives,
};
pub use limits::{DesignLimits, InputRequirement};
pub use map::{MapContext, SolutionMap, Varying};
pub use options::MapOptions;
pub use pairs::{Pair, PairContext, PairMap};
pub use rank::{Pivot, PivotLinkage, RankBy, RankColumns, Ranking, SliderPivot};
pub use search::ActuatorSearch;
pub use search::{
    Design, DesignOptions, DesignPlan, DesignReport, DesignedLinkage, DrivenKind, Limit, NearMiss,
    SearchPoint,
};
pub use space::{PivotRegion, Space};
