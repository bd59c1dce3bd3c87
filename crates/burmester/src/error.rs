//! Errors: one enum per concern, one variant per cause, typed fields.
//!
//! Every fallible function in the crate returns [`Error`](enum@Error), which wraps one of
//! four kinds:
//!
//! * [`InvalidInput`]: a number, a name, a count or a shape the caller passed
//!   is not acceptable (NaN, infinite, zero or negative length, unknown
//!   name, a pose index out of range, a polygon that is not simple). Change
//!   the input.
//! * [`AssemblyError`]: the input is well formed, but the linkage cannot be
//!   put together where it was asked to be (the loop does not close).
//! * [`DegenerateError`]: the geometry is degenerate: an answer lies at
//!   infinity, or the task has no unique answer.
//! * [`Error::Cancelled`]: a long computation was stopped by its
//!   [`Control`](crate::Control) (for example Ctrl-C in Python).
//! * [`Error::OutOfMemory`]: a buffer sized by the input could not be
//!   allocated (Python: `MemoryError`).
//!
//! The messages say what was wrong and what to change; every variant's
//! fields are also available as data ([`Error::cause`], [`Error::fields`]),
//! which the Python binding turns into attributes of its exceptions. Nothing
//! in the crate panics on user input, and no NaN is handed back without a
//! flag saying so.

use core::fmt;

use thiserror::Error;

/// Result type of the crate.
pub type Result<T, E = Error> = core::result::Result<T, E>;

/// A number in a message: short (at most 17 significant digits, in
/// scientific notation when very large or very small), so that a huge value
/// never fills a message with hundreds of digits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        let a = v.abs();
        if v.is_finite() && a != 0.0 && !(1e-5..1e16).contains(&a) {
            write!(f, "{v:e}")
        } else {
            write!(f, "{v}")
        }
    }
}

/// Why a polygon is not acceptable.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PolygonProblem {
    /// Fewer than three vertices.
    TooFewVertices,
    /// Its vertices lie on one line (within a relative `1e-12`): no area.
    NoArea,
    /// Two of its edges cross: it is not a simple polygon.
    SelfIntersecting,
    /// An envelope that leaves out a pose's coupler point (the coupler
    /// must be inside it at every pose).
    ExcludesPoses,
    /// More vertices than
    /// [`Constraints::MAX_POLYGON_VERTICES`](crate::Constraints::MAX_POLYGON_VERTICES).
    TooManyVertices,
}

impl PolygonProblem {
    /// A short name: `"too few vertices"`, `"no area"`, `"self-intersecting"`,
    /// `"too many vertices"`.
    pub fn as_str(self) -> &'static str {
        match self {
            PolygonProblem::TooFewVertices => "too few vertices",
            PolygonProblem::NoArea => "no area",
            PolygonProblem::SelfIntersecting => "self-intersecting",
            PolygonProblem::ExcludesPoses => "excludes poses",
            PolygonProblem::TooManyVertices => "too many vertices",
        }
    }
}

impl fmt::Display for PolygonProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const AREA: &str = "pass a simple polygon with an area";
        match self {
            PolygonProblem::TooFewVertices => write!(f, "it has fewer than 3 vertices; {AREA}"),
            PolygonProblem::NoArea => {
                write!(f, "its vertices lie on one line, so it has no area; {AREA}")
            }
            PolygonProblem::SelfIntersecting => {
                write!(f, "two of its edges cross (it is not simple); {AREA}")
            }
            PolygonProblem::ExcludesPoses => f.write_str(
                "a pose's coupler point lies outside it, so no linkage can stay inside it \
                 (draw it around every pose)",
            ),
            PolygonProblem::TooManyVertices => write!(
                f,
                "it has more than {} vertices; approximate it with fewer (a circle of a few \
                 hundred vertices is within 1e-4 of its radius)",
                crate::Constraints::MAX_POLYGON_VERTICES
            ),
        }
    }
}

/// The value of a field of an error, for bindings ([`Error::fields`]).
#[derive(Debug, Clone, PartialEq)]
pub enum Field {
    /// A number.
    Float(f64),
    /// A count or an index.
    Int(usize),
    /// A name or a description.
    Str(String),
}

impl From<&f64> for Field {
    fn from(v: &f64) -> Self {
        Field::Float(*v)
    }
}

impl From<&usize> for Field {
    fn from(v: &usize) -> Self {
        Field::Int(*v)
    }
}

impl From<&str> for Field {
    fn from(v: &str) -> Self {
        Field::Str(v.to_owned())
    }
}

impl From<&&str> for Field {
    fn from(v: &&str) -> Self {
        Field::Str((*v).to_owned())
    }
}

impl From<&String> for Field {
    fn from(v: &String) -> Self {
        Field::Str(v.clone())
    }
}

/// `name` in snake case: an underscore before every capital but the first,
/// every capital lowered (`"NotADyad"` gives `"not_a_dyad"`); `N` is its
/// length ([`snake_case_len`]).
const fn snake_case<const N: usize>(name: &str) -> [u8; N] {
    let name = name.as_bytes();
    let mut out = [0u8; N];
    let (mut i, mut o) = (0, 0);
    while i < name.len() {
        let c = name[i];
        if c.is_ascii_uppercase() && i > 0 {
            out[o] = b'_';
            o += 1;
        }
        out[o] = c.to_ascii_lowercase();
        o += 1;
        i += 1;
    }
    out
}

/// The length of `name` in snake case ([`snake_case`]).
const fn snake_case_len(name: &str) -> usize {
    let name = name.as_bytes();
    let mut n = name.len();
    let mut i = 1;
    while i < name.len() {
        if name[i].is_ascii_uppercase() {
            n += 1;
        }
        i += 1;
    }
    n
}

/// The one list of the crate's errors. Each enum is written once, as
/// `thiserror` reads it (its messages in `#[error]`), and from that list
/// come the enum, its `cause()` (the variant's name in snake case) and its
/// `fields()` (the variant's fields by name, in order, each as a [`Field`];
/// `field: type => expression` gives the field as that expression
/// instead). A variant that wraps another error (`Kind(#[from] Inner)`)
/// takes its cause and fields from it. A new error is one variant here.
macro_rules! error_enums {
    ($(
        $(#[$attr:meta])*
        pub enum $Enum:ident {
            $(
                $(#[$vattr:meta])*
                $Variant:ident
                $(( $(#[$iattr:meta])* $Inner:ty ))?
                $({
                    $( $(#[$fattr:meta])* $field:ident: $fty:ty $(=> $conv:expr)? ),* $(,)?
                })?
            ),* $(,)?
        }
    )*) => {$(
        $(#[$attr])*
        pub enum $Enum {
            $(
                $(#[$vattr])*
                $Variant
                $(( $(#[$iattr])* $Inner ))?
                $({ $( $(#[$fattr])* $field: $fty, )* })?,
            )*
        }

        impl $Enum {
            /// The cause: the variant's name in snake case (for example
            /// `"not_finite"`, `"out_of_reach"`, `"at_infinity"`); the
            /// Python exception's `cause`.
            pub fn cause(&self) -> &'static str {
                match self {
                    $(error_enums!(@pattern $Enum $Variant inner $(($Inner))?) => {
                        error_enums!(@cause $Variant inner $(($Inner))?)
                    })*
                }
            }

            /// The variant's fields by name, as data (the Python binding
            /// sets them as attributes of its exceptions).
            pub fn fields(&self) -> Vec<(&'static str, Field)> {
                match self {
                    $(error_enums!(
                        @pattern $Enum $Variant inner $(($Inner))? $({ $($field)* })?
                    ) => error_enums!(
                        @fields inner $(($Inner))? $({ $($field $(=> $conv)?;)* })?
                    ),)*
                }
            }
        }
    )*};
    (@pattern $Enum:ident $Variant:ident $inner:ident ($Inner:ty)) => {
        $Enum::$Variant($inner)
    };
    (@pattern $Enum:ident $Variant:ident $inner:ident $({ $($field:ident)* })?) => {
        $Enum::$Variant { $($($field,)*)? .. }
    };
    (@cause $Variant:ident $inner:ident ($Inner:ty)) => {
        $inner.cause()
    };
    (@cause $Variant:ident $inner:ident) => {{
        const NAME: &str = stringify!($Variant);
        const BYTES: [u8; snake_case_len(NAME)] = snake_case(NAME);
        const CAUSE: &str = match core::str::from_utf8(&BYTES) {
            Ok(cause) => cause,
            Err(_) => panic!("a variant's name is ASCII"),
        };
        CAUSE
    }};
    (@fields $inner:ident ($Inner:ty)) => {
        $inner.fields()
    };
    (@fields $inner:ident $({ $($field:ident $(=> $conv:expr)?;)* })?) => {
        vec![$($((stringify!($field), error_enums!(@field $field $(=> $conv)?)),)*)?]
    };
    (@field $field:ident => $conv:expr) => {
        Field::from($conv)
    };
    (@field $field:ident) => {
        Field::from($field)
    };
}
error_enums! {
/// Any error of the crate.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum Error {
    /// An argument is not acceptable.
    #[error(transparent)]
    InvalidInput(#[from] InvalidInput),
    /// The linkage cannot be assembled as asked.
    #[error(transparent)]
    Assembly(#[from] AssemblyError),
    /// The geometry is degenerate (an answer at infinity, or no unique answer).
    #[error(transparent)]
    Degenerate(#[from] DegenerateError),
    /// The computation was cancelled through its [`Control`](crate::Control)
    /// before it finished; nothing it was filling holds a complete answer.
    #[error(
        "the computation was cancelled after {done} of {total} rows; run it again to get a \
         complete result"
    )]
    Cancelled {
        /// Rows (or other units of work) finished when it stopped.
        done: usize,
        /// Rows in all.
        total: usize,
    },
    /// A buffer sized by the input could not be allocated.
    #[error(
        "{what} needs {bytes} bytes, more than can be allocated; ask for fewer samples (a smaller \
         grid) or split the work"
    )]
    OutOfMemory {
        /// What was being allocated.
        what: &'static str,
        /// How many bytes it needs.
        bytes: usize,
    },
    /// A six-bar cannot be built as asked, or a linkage cannot be driven
    /// from a motor by an added dyad.
    #[error(transparent)]
    Drive(#[from] DriveError),
}

/// An argument is not acceptable: change it.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum InvalidInput {
    /// A number is NaN or infinite.
    #[error("{name} must be a finite number, got {}; pass a finite value", Num(*.value))]
    NotFinite {
        /// What the number is (for example `"crank length"`).
        name: &'static str,
        /// The value that was passed.
        value: f64,
    },
    /// A length is zero or negative.
    #[error("{name} must be greater than zero, got {}; pass a positive length", Num(*.value))]
    NotPositive {
        /// What the length is.
        name: &'static str,
        /// The value that was passed.
        value: f64,
    },
    /// A number is outside the closed range `[min, max]`.
    #[error(
        "{name} must be between {} and {}{}, got {}; pass a value in that range",
        Num(*.min), Num(*.max), .unit, Num(*.value)
    )]
    OutsideRange {
        /// What the number is.
        name: &'static str,
        /// The value that was passed.
        value: f64,
        /// The smallest accepted value.
        min: f64,
        /// The largest accepted value (infinity: no upper limit).
        max: f64,
        /// The unit of the range, with a leading space (for example
        /// `" degrees"`), or empty (as a field: without the space).
        unit: &'static str => unit.trim(),
    },
    /// A magnitude exceeds the documented limit past which the arithmetic
    /// could overflow or lose its precision.
    #[error("{name} is {}, beyond the limit of {} in magnitude; {hint}", Num(*.value), Num(*.limit))]
    TooLarge {
        /// What the number is (for example `"pose 2 angle"`).
        name: &'static str,
        /// The value that was passed (or derived from the input).
        value: f64,
        /// The documented limit.
        limit: f64,
        /// What to do about it.
        hint: &'static str,
    },
    /// A size is below the documented limit past which the arithmetic could
    /// underflow.
    #[error("{name} is {}, below the limit of {}; {hint}", Num(*.value), Num(*.limit))]
    TooSmall {
        /// What the size is.
        name: &'static str,
        /// The size found.
        value: f64,
        /// The documented limit.
        limit: f64,
        /// What to do about it.
        hint: &'static str,
    },
    /// A count (of samples, of results) is outside its documented range.
    #[error("{name} must be from {min} to {max}, got {value}; pass a count in that range")]
    CountOutOfRange {
        /// What is counted.
        name: &'static str,
        /// The count that was passed.
        value: usize,
        /// The smallest accepted count.
        min: usize,
        /// The largest accepted count.
        max: usize,
    },
    /// A name (an assembly mode, a method) is not one of those accepted.
    #[error("unknown {what} {found:?}; use one of {expected}")]
    UnknownName {
        /// What kind of name it is (for example `"assembly mode"`).
        what: &'static str,
        /// The accepted names, for the message.
        expected: &'static str,
        /// The name that was passed.
        found: String,
    },
    /// Two slices that must have the same length do not.
    #[error("{name} has {found} entries but {expected} were expected; pass slices of equal length")]
    LengthMismatch {
        /// Which argument has the wrong length.
        name: &'static str,
        /// The length that was expected.
        expected: usize,
        /// The length that was found.
        found: usize,
    },
    /// A task was given a number of poses it does not support.
    #[error(
        "a task takes {min} to {max} poses, got {found}; pass {min} poses for the branch maps, \
         {} for the Burmester curves or {max} for the Burmester points",
        .min + 1
    )]
    PoseCount {
        /// The number of poses passed.
        found: usize,
        /// The smallest supported number.
        min: usize,
        /// The largest supported number.
        max: usize,
    },
    /// A method that needs a specific number of poses was called on a task
    /// with another number.
    #[error("{method} needs a task of {required} poses, but this task has {found}")]
    NeedsPoses {
        /// The method (for example `"Task::filemon"`).
        method: &'static str,
        /// The number of poses it needs.
        required: usize,
        /// The number of poses of the task.
        found: usize,
    },
    /// A pose index (1-based) is out of range.
    #[error("pose index must be from 1 to {count}, got {index}; pass a 1-based index of a pose")]
    PoseIndex {
        /// The index that was passed.
        index: usize,
        /// The number of poses.
        count: usize,
    },
    /// A grid has no samples in one direction, or more than
    /// [`Grid::MAX_POINTS`](crate::Grid::MAX_POINTS) in all.
    #[error(
        "a grid of {nx} by {ny} samples is not supported: nx and ny must be at least 1 and \
         nx * ny at most {max}; pass other sample counts"
    )]
    GridSize {
        /// Samples per row.
        nx: usize,
        /// Rows.
        ny: usize,
        /// The largest number of samples.
        max: usize,
    },
    /// A viewport is empty or inverted (or its size overflows).
    #[error(
        "the viewport x from {} to {}, y from {} to {} is empty or inverted; pass xmin < xmax \
         and ymin < ymax (with a finite size)",
        Num(*.xmin), Num(*.xmax), Num(*.ymin), Num(*.ymax)
    )]
    Viewport {
        /// Left edge.
        xmin: f64,
        /// Right edge.
        xmax: f64,
        /// Bottom edge.
        ymin: f64,
        /// Top edge.
        ymax: f64,
    },
    /// A direction vector is zero (or not finite).
    #[error("{name} must be a finite, non-zero vector, got ({}, {}); pass a direction", Num(*.x), Num(*.y))]
    ZeroDirection {
        /// Which direction.
        name: &'static str,
        /// Its x.
        x: f64,
        /// Its y.
        y: f64,
    },
    /// An operation was given a driven dyad of a kind it does not take: a
    /// slider where a four-bar is built, a crank where a slider-crank is.
    #[error(
        "{what} does not take a {found} driven dyad: a four-bar needs a revolute driven dyad \
         (a crank), a slider-crank a slider; build the linkage of the dyad's kind (linkage for \
         a crank, slider_crank for a slider)"
    )]
    DrivenKind {
        /// What does not take the kind.
        what: &'static str,
        /// The kind given (`"slider"` or `"revolute"`).
        found: &'static str,
    },
    /// An operation on the driven dyad that is not defined for an inverted
    /// slider (its circle point is at infinity, normal to the slot).
    #[error(
        "{what} is not defined for an inverted slider as the driven dyad: its circle point is at \
         infinity, so Filemon's lines through it are parallel (through the swivel's images \
         D_k1(S), normal to the slot at pose 1) and no finite crank drives it; pass a revolute or \
         slider driven dyad, or build the linkage with Task::inverted_slider_crank, whose modes at \
         the poses give the branch verdict"
    )]
    InvertedDriven {
        /// What is not defined.
        what: &'static str,
    },
    /// The quadratic and linear coefficients of a conic are all zero.
    #[error(
        "a conic needs A, B, C, D or E nonzero (all are zero); pass the coefficients of a curve"
    )]
    ConicCoefficients,
    /// Every coefficient of a cubic but the constant is zero.
    #[error(
        "a cubic needs a coefficient other than the constant nonzero; pass the coefficients of a \
         curve"
    )]
    CubicCoefficients,
    /// A point that must lie on a curve (a center point on the center-point
    /// curve, a circle point on the circle-point curve) is off it.
    #[error(
        "the {what} is {} from its curve, more than the tolerance of {}; take a point of the \
         traced curve (or a Burmester point)",
        Num(*.distance), Num(*.tolerance)
    )]
    OffCurve {
        /// Which point (for example `"center point"`).
        what: &'static str,
        /// Its first-order distance from the curve.
        distance: f64,
        /// The largest distance accepted.
        tolerance: f64,
    },
    /// A dyad passed to a task is not a dyad of it: its moving pivot is not
    /// at one distance from its fixed pivot in every pose.
    #[error(
        "the {which} is not a dyad of the task: its moving pivot's distances from its fixed pivot \
         over the poses differ by {} (relative), more than {}; build it with Task::dyad_from_center",
        Num(*.spread), Num(*.tolerance)
    )]
    NotADyad {
        /// Which dyad (`"driving dyad"` or `"driven dyad"`).
        which: &'static str,
        /// The spread of the distances, relative to the dyad's and the
        /// task's size.
        spread: f64,
        /// The tolerance ([`tolerance::DYAD`](crate::tolerance::DYAD)).
        tolerance: f64,
    },
    /// A polygon (a base plate, an obstacle) is not acceptable.
    #[error("{name} is not a usable polygon ({vertices} vertices): {problem}")]
    Polygon {
        /// Which polygon (for example `"base_plate"` or `"obstacle 2"`).
        name: String,
        /// How many vertices it has.
        vertices: usize,
        /// What is wrong (as a field: [`PolygonProblem::as_str`]).
        problem: PolygonProblem => problem.as_str(),
    },
    /// A result would not be representable (it overflows), although every
    /// input is finite: the input is too far from the task or the linkage.
    #[error("{what} overflows: {hint}")]
    Overflow {
        /// What overflows (for example `"the coupler point's position"`).
        what: &'static str,
        /// What to do about it.
        hint: &'static str,
    },
    /// A slider dyad passed to a task is not a slider of it: its pin's
    /// positions over the poses leave its guide.
    #[error(
        "the {which} is not a slider of the task: its pin's positions over the poses leave the \
         guide by {} (relative to the task's size), more than {}; take a slider point of the task \
         (a point whose positions are collinear) with the guide through its positions",
        Num(*.spread), Num(*.tolerance)
    )]
    NotASlider {
        /// Which dyad (`"driven slider"`).
        which: &'static str,
        /// The largest distance of a position from the guide, relative to
        /// the task's size.
        spread: f64,
        /// The tolerance ([`tolerance::DYAD`](crate::tolerance::DYAD)).
        tolerance: f64,
    },
    /// A point asked for as a slider point (a circle point whose positions
    /// at the poses are collinear: the pin of a slider dyad, or the swivel
    /// of an inverted slider) is not one: for three poses it is off the
    /// slider circle, for four or five poses it is none of the finitely
    /// many slider points (issue 27).
    #[error(
        "({}, {}) is not a {what} of the task: it is {} from the nearest one, more than the \
         tolerance of {}; {hint}",
        Num(*.x), Num(*.y), Num(*.distance), Num(*.tolerance)
    )]
    NotASliderPoint {
        /// What was asked for (`"slider point"` or `"swivel point"`).
        what: &'static str,
        /// x of the point given.
        x: f64,
        /// y of the point given.
        y: f64,
        /// Its distance from the slider circle (three poses) or from the
        /// nearest slider point (four or five poses; infinite when there
        /// is none).
        distance: f64,
        /// The largest distance accepted.
        tolerance: f64,
        /// What to change (which points are slider points).
        hint: &'static str,
    },
    /// A slider point (or an inverted slider's swivel point) was asked for
    /// where the task has none (issue 27).
    #[error("the task has no {what}: {why}")]
    NoSliderPoint {
        /// What was asked for (`"slider point"` or `"swivel point"`).
        what: &'static str,
        /// Why there is none, and what to change.
        why: &'static str,
    },
}

/// The linkage cannot be assembled as asked.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum AssemblyError {
    /// The longest link is longer than the other three together: no input
    /// angle closes the loop.
    #[error(
        "the linkage can never be assembled: its longest link ({}) is longer than the other three \
         together ({}); shorten it or lengthen the others",
        Num(*.longest), Num(*.others)
    )]
    NeverCloses {
        /// The longest link length.
        longest: f64,
        /// The sum of the other three.
        others: f64,
    },
    /// At this input angle the coupler and the rocker cannot reach from the
    /// crank tip to the output pivot.
    #[error(
        "the loop does not close at theta2 = {} rad: the crank tip is {} from the output pivot, \
         but coupler and rocker reach only from {} to {}; choose an input angle inside the input \
         range (FourBar::input_range)",
        Num(*.theta2), Num(*.distance), Num(*.min_reach), Num(*.max_reach)
    )]
    OutOfReach {
        /// The input angle, in radians.
        theta2: f64,
        /// Distance from the crank tip to the output pivot.
        distance: f64,
        /// `|coupler - rocker|`.
        min_reach: f64,
        /// `coupler + rocker`.
        max_reach: f64,
    },
    /// The crank tip lies on the output pivot and the coupler equals the
    /// rocker: every coupler angle closes the loop.
    #[error(
        "the position at theta2 = {} rad is indeterminate: the crank tip lies on the output pivot \
         and the coupler is as long as the rocker, so any coupler angle closes the loop; step the \
         input angle away from it",
        Num(*.theta2)
    )]
    Indeterminate {
        /// The input angle, in radians.
        theta2: f64,
    },
    /// A slider-crank's guide is farther from its crank pivot than crank
    /// and coupler reach: no crank angle closes the loop.
    #[error(
        "the slider-crank can never be assembled: its guide is {} from the crank pivot, farther \
         than crank and coupler reach together ({}); move the guide nearer the pivot or lengthen \
         the crank or the coupler",
        Num(*.offset), Num(*.reach)
    )]
    GuideOutOfReach {
        /// The pivot's distance from the guide.
        offset: f64,
        /// Crank plus coupler.
        reach: f64,
    },
    /// At this crank angle the crank tip of a slider-crank is farther from
    /// the guide than the coupler is long.
    #[error(
        "the slider-crank's loop does not close at theta2 = {} rad: the crank tip is {} from the \
         guide, farther than the coupler's length {}; choose a crank angle inside the input range \
         (SliderCrank::input_range)",
        Num(*.theta2), Num(*.height), Num(*.coupler)
    )]
    SliderOutOfReach {
        /// The crank angle, in radians.
        theta2: f64,
        /// The crank tip's distance from the guide.
        height: f64,
        /// The coupler's length.
        coupler: f64,
    },
    /// An inverted slider-crank's slot is offset from the crank pin by
    /// more than ground and crank reach: no crank angle closes the loop.
    #[error(
        "the inverted slider-crank can never be assembled: its slot is {} from the crank pin, \
         farther than ground and crank reach together ({}); reduce the slot's offset, move the \
         swivel away from the crank pivot or lengthen the crank",
        Num(*.offset), Num(*.reach)
    )]
    SwivelOutOfReach {
        /// The slot's offset from the crank pin.
        offset: f64,
        /// Ground plus crank.
        reach: f64,
    },
    /// At this crank angle the crank pin of an inverted slider-crank is
    /// nearer the swivel than the slot's offset.
    #[error(
        "the inverted slider-crank's loop does not close at theta2 = {} rad: the crank pin is {} \
         from the swivel, nearer than the slot's offset {}; choose a crank angle inside the input \
         range (InvertedSliderCrank::input_range)",
        Num(*.theta2), Num(*.distance), Num(*.offset)
    )]
    SlotOutOfReach {
        /// The crank angle, in radians.
        theta2: f64,
        /// The crank pin's distance from the swivel.
        distance: f64,
        /// The slot's offset from the crank pin.
        offset: f64,
    },
}

/// The geometry is degenerate: an answer lies at infinity, or the task has no
/// unique answer.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum DegenerateError {
    /// Two poses of a task are equal.
    #[error(
        "poses {i} and {j} are equal (same position and angle), so they give no information; \
         move or rotate one of them"
    )]
    CoincidentPoses {
        /// First pose index (1-based).
        i: usize,
        /// Second pose index (1-based).
        j: usize,
    },
    /// Two poses differ by a pure translation (their angles agree within
    /// [`tolerance::MIN_ROTATION`](crate::tolerance::MIN_ROTATION)), so their
    /// pole is at infinity, where a computation needs three finite poles:
    /// the pole triangle, its angles, the pole circles and the image poles
    /// ([`Task::cremona`](crate::Task::cremona)).
    #[error(
        "poses {i} and {j} have the same angle (within 1e-6 rad), so the motion between them is \
         a pure translation and their pole is at infinity: the task has no pole triangle, pole \
         circles or image poles (the circle and center points, Filemon's construction and the \
         solution maps work without them); rotate one of the poses by more than 1e-6 rad if you \
         need them"
    )]
    PureTranslation {
        /// First pose index (1-based).
        i: usize,
        /// Second pose index (1-based).
        j: usize,
    },
    /// The poses are rotations about one point: all their poles coincide,
    /// and every dyad has its center point there.
    #[error(
        "the poses are rotations about one point ({}, {}): all poles coincide there, so \
         the synthesis is degenerate (every dyad is centered there); move one pose off that \
         rotation",
        Num(*.x), Num(*.y)
    )]
    CoincidentPoles {
        /// x of the common pole.
        x: f64,
        /// y of the common pole.
        y: f64,
    },
    /// The answer of a map lies at infinity.
    #[error(
        "the {what} of ({}, {}) is at infinity (direction {}, {}): the point lies on the \
         {curve}; choose a point off it",
        Num(*.x), Num(*.y), Num(*.dir_x), Num(*.dir_y)
    )]
    AtInfinity {
        /// What was asked for (for example `"circle point"`).
        what: &'static str,
        /// The curve the point lies on (for example `"pole circle"`).
        curve: &'static str,
        /// x of the point that was mapped.
        x: f64,
        /// y of the point that was mapped.
        y: f64,
        /// x of the unit direction of the answer at infinity.
        dir_x: f64,
        /// y of the unit direction of the answer at infinity.
        dir_y: f64,
    },
    /// The map has no unique answer at this point (a pole, where every
    /// image coincides).
    #[error(
        "the {what} of ({}, {}) is not unique: the point is at {at}, where the map is undefined; \
         choose a point off it",
        Num(*.x), Num(*.y)
    )]
    Undefined {
        /// What was asked for.
        what: &'static str,
        /// Where the point lies (for example `"the pole P12"`).
        at: &'static str,
        /// x of the point.
        x: f64,
        /// y of the point.
        y: f64,
    },
    /// Every pose has the same angle: the motion is a pure translation. With
    /// three poses every dyad's crank is one and the same vector (each
    /// center point's circle point is it moved by a fixed offset), so every
    /// four-bar is a parallelogram at its change point (or, with the poses
    /// on a line, no dyad exists); with four or five the Burmester points
    /// are not defined (none or infinitely many).
    #[error(
        "every pose has the same angle: the motion is a pure translation, for which the synthesis \
         is degenerate (with three poses every dyad's crank is the same vector, so every four-bar \
         is a parallelogram at its change point; with more there are no Burmester points, or \
         infinitely many); rotate a pose"
    )]
    AllTranslations,
    /// The crank rotation does not parametrize the center-point curve (the
    /// compatibility linkage of the poses has a link of zero length).
    #[error(
        "the crank rotation does not parametrize this task's center-point curve (its \
         compatibility linkage has a link of zero length); trace the curve instead"
    )]
    NotParametrizable,
    /// The dyad at this crank rotation has its center point at infinity (a
    /// slider).
    #[error(
        "the dyad at the crank rotation beta2 = {} rad has its center point at infinity (a \
         slider); step beta2 off it",
        Num(*.beta2)
    )]
    SliderDyad {
        /// The crank rotation from pose 1 to pose 2, radians.
        beta2: f64,
    },
    /// Three of five poses are rotations about one point (their three poles
    /// coincide): every dyad through them has its center point there or
    /// its moving pivot there, so the two center-point curves that the
    /// Burmester points are the meets of share the zero circle about it
    /// and the points are not isolated (issue 24).
    #[error(
        "poses {i}, {j} and {k} are rotations about one point ({}, {}): every dyad through them \
         has its center point or its moving pivot there, so the Burmester points of the five \
         poses are not isolated (the curves whose meets they are share a component); move or \
         rotate one of these poses off that rotation",
        Num(*.x), Num(*.y)
    )]
    RotationsAboutOnePoint {
        /// First pose (1-based).
        i: usize,
        /// Second pose (1-based).
        j: usize,
        /// Third pose (1-based).
        k: usize,
        /// x of the common pole.
        x: f64,
        /// y of the common pole.
        y: f64,
    },
    /// Three of four or five poses have one angle and collinear positions:
    /// every dyad through them is a slider (its moving pivot's three
    /// positions lie on a line), so no finite center point passes them and
    /// the center-point curves degenerate to the line at infinity (issue
    /// 24).
    #[error(
        "poses {i}, {j} and {k} have the same angle and positions on one line: every dyad \
         through them is a slider (its moving pivot's positions lie on a line), so no finite \
         center point passes them and the center-point curves degenerate; rotate one of these \
         poses or move it off the line"
    )]
    CollinearTranslations {
        /// First pose (1-based).
        i: usize,
        /// Second pose (1-based).
        j: usize,
        /// Third pose (1-based).
        k: usize,
    },
    /// Five poses with infinitely many Burmester points: the center-point
    /// curves of two four-pose subsets share a component (a line, a conic
    /// or the whole curve), every point of which is the center of a dyad
    /// through all five poses, or a center has a whole line of circle
    /// points (issue 24).
    #[error(
        "the five poses have infinitely many Burmester points: {what}, so the dyads through all \
         five poses are not isolated; move or rotate a pose"
    )]
    InfinitelyManyBurmesterPoints {
        /// What is shared (for example `"the center-point curves of every two four-pose
        /// subsets that share three poses have a common component"`).
        what: &'static str,
    },
    /// Five poses whose Burmester points the elimination does not resolve
    /// within rounding: from every choice of the shared poses a root of
    /// the resultant gives no point, or the count is odd (the task is
    /// within rounding of a degenerate one: nearly coincident poses or
    /// poles, nearly equal angles) (issue 24).
    #[error(
        "the Burmester points of the five poses are not resolved within rounding: {what}; the \
         task is within rounding of a degenerate one (nearly coincident poses or poles, nearly \
         equal angles): move or rotate a pose"
    )]
    UnresolvedBurmesterPoints {
        /// What failed.
        what: &'static str,
    },
    /// A dyad's center point and circle point coincide (a link of zero length).
    #[error(
        "the {what} has zero length: its ends coincide at ({}, {}); choose another point",
        Num(*.x), Num(*.y)
    )]
    ZeroLengthLink {
        /// Which link.
        what: &'static str,
        /// x of the point.
        x: f64,
        /// y of the point.
        y: f64,
    },
}

/// Why a six-bar cannot be built as asked, or a synthesized linkage
/// cannot be driven from a motor by an added dyad (the drive dyad of the
/// Watt II six-bar, [`SixBar`](crate::SixBar)).
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum DriveError {
    /// The drive loop's output pivot is not the motion loop's input pivot.
    #[error(
        "the drive loop's output pivot is {} from the motion loop's input pivot A0, more than {}; \
         build the drive from D0 to A0 (FourBar::from_pivots)",
        Num(*.distance), Num(*.tolerance)
    )]
    PivotMismatch {
        /// How far apart they are.
        distance: f64,
        /// The tolerance (`1e-9` of the sum of the links).
        tolerance: f64,
    },
    /// A loop is at a toggle in the joints given, so its mode is undefined.
    #[error(
        "the {which} loop is at a toggle in the joints given (its coupler and rocker are \
         collinear), so its assembly mode is undefined; give the joints of a position off the \
         toggle"
    )]
    ToggleJoints {
        /// `"drive"` or `"motion"`.
        which: &'static str,
    },
    /// The linkage does not carry the coupler through its poses in order.
    #[error(
        "the linkage does not carry the coupler through its poses in order in one assembly mode \
         (a branch, order or circuit defect), so no drive can; pick a feasible linkage \
         (figures.feasible)"
    )]
    NoTravel,
    /// The input link's travel with the margins is too wide for the
    /// rocker of a crank-rocker.
    #[error(
        "the input link turns {} degrees from the first pose to the last, {} degrees with the \
         swing margin of {} degrees at each end; the rocker of a crank-rocker swings less than 180 \
         degrees: reduce swing_margin_deg, or pick a linkage with a shorter travel",
        Num(*.travel_deg), Num(*.swing_deg), Num(*.margin_deg)
    )]
    TravelTooLarge {
        /// The travel from the first pose to the last, degrees.
        travel_deg: f64,
        /// The swing, travel and margins, degrees.
        swing_deg: f64,
        /// The margin at each end, degrees.
        margin_deg: f64,
    },
    /// The swing with its margins leaves the motion loop's input range.
    #[error(
        "the swing margin of {} degrees leaves the motion loop's input range: its input link can \
         turn only {} degrees before the first pose and {} degrees past the last before the loop \
         toggles; give a swing_margin_deg below both",
        Num(*.margin_deg), Num(*.before_deg), Num(*.after_deg)
    )]
    OutsideInputRange {
        /// The margin asked for, degrees.
        margin_deg: f64,
        /// The room before the first pose, degrees.
        before_deg: f64,
        /// The room past the last pose, degrees.
        after_deg: f64,
    },
    /// The drive pivot gives no crank-rocker with the swing asked for.
    #[error(
        "a drive pivot at ({}, {}) gives no crank-rocker with this swing: the line through it and \
         A0 meets the arc that E swings on (or the drive has a link of no length); move it (the \
         drive map's valid column shows where a drive exists)",
        Num(*.x), Num(*.y)
    )]
    NotACrankRocker {
        /// The drive pivot's x.
        x: f64,
        /// The drive pivot's y.
        y: f64,
    },
    /// No drive searched meets the limits and constraints.
    #[error(
        "no acceptable drive among {searched} candidates ({valid} of them crank-rocker drives); the \
         best minimum transmission angle over a crank turn is {:.1} degrees, the limit {:.1} \
         degrees; relax the limits (min_transmission_deg, max_link_ratio, max_time_ratio, \
         max_size_ratio, max_link_length), the constraints or the swing margin, or search more \
         attachments",
        .best_transmission_deg, .min_transmission_deg
    )]
    NoAcceptableDrive {
        /// Candidate drives examined.
        searched: usize,
        /// Of them, crank-rocker drives that turn the six-bar fully.
        valid: usize,
        /// The best minimum transmission angle among those, degrees (NaN
        /// when there were none).
        best_transmission_deg: f64,
        /// The limit, degrees.
        min_transmission_deg: f64,
    },
}
}

impl Error {
    /// A short name of the kind: `"invalid input"`, `"assembly"`,
    /// `"degenerate"`, `"cancelled"` or `"memory"`.
    pub fn kind(&self) -> &'static str {
        match self {
            Error::InvalidInput(_) => "invalid input",
            Error::Assembly(_) => "assembly",
            Error::Degenerate(_) => "degenerate",
            Error::Cancelled { .. } => "cancelled",
            Error::OutOfMemory { .. } => "memory",
            Error::Drive(_) => "drive",
        }
    }
}

/// A vector of `n` copies of `value`, or [`Error::OutOfMemory`] when it
/// cannot be allocated (instead of aborting the process).
pub fn try_vec<T: Clone + Send>(what: &'static str, n: usize, value: T) -> Result<Vec<T>> {
    /// From this many bytes on the vector is filled on every core, so that
    /// the first touch of its pages (the kernel zeroing them) is spread
    /// over the threads instead of run before the parallel work starts.
    const PARALLEL_FILL_BYTES: usize = 1 << 20;
    let mut v = Vec::new();
    v.try_reserve_exact(n)
        .map_err(|_| out_of_memory::<T>(what, n))?;
    if n.saturating_mul(core::mem::size_of::<T>()) >= PARALLEL_FILL_BYTES {
        use rayon::iter::ParallelExtend;
        v.par_extend(rayon::iter::repeat_n(value, n));
    } else {
        v.resize(n, value);
    }
    Ok(v)
}

/// A vector of `n` zeros (`false`, `0`, `0.0`), or [`Error::OutOfMemory`]
/// when it cannot be allocated: fresh pages from the allocator, which the
/// first write touches (on the thread that writes it), with no pass that
/// fills them first.
pub(crate) fn try_zeroed_vec<T: bytemuck::Zeroable>(
    what: &'static str,
    n: usize,
) -> Result<Vec<T>> {
    bytemuck::allocation::try_zeroed_vec(n).map_err(|()| out_of_memory::<T>(what, n))
}

/// The items of `items` (about `n` of them) in a vector whose memory is
/// reserved fallibly: [`Error::OutOfMemory`] instead of an abort when it
/// cannot be allocated. The collecting `collect()` of an iterator sized by
/// the input.
pub(crate) fn try_collect<T>(
    what: &'static str,
    n: usize,
    items: impl IntoIterator<Item = T>,
) -> Result<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(n)
        .map_err(|_| out_of_memory::<T>(what, n))?;
    for x in items {
        try_push(&mut v, what, x)?;
    }
    Ok(v)
}

/// Pushes `x` onto `v`, growing it fallibly: [`Error::OutOfMemory`]
/// instead of an abort when it cannot grow (a vector whose length the
/// input decides).
#[inline]
pub(crate) fn try_push<T>(v: &mut Vec<T>, what: &'static str, x: T) -> Result<()> {
    if v.len() == v.capacity() {
        v.try_reserve(1)
            .map_err(|_| out_of_memory::<T>(what, v.len().saturating_add(1)))?;
    }
    v.push(x);
    Ok(())
}

/// [`Error::OutOfMemory`] for `n` values of `T`.
pub(crate) fn out_of_memory<T>(what: &'static str, n: usize) -> Error {
    Error::OutOfMemory {
        what,
        bytes: n.saturating_mul(core::mem::size_of::<T>()),
    }
}

/// Checks that `value` is finite.
pub(crate) fn finite(name: &'static str, value: f64) -> Result<f64, InvalidInput> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(InvalidInput::NotFinite { name, value })
    }
}

/// Checks that `value` is finite and greater than zero.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, InvalidInput> {
    let value = finite(name, value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(InvalidInput::NotPositive { name, value })
    }
}

/// Checks that `value` is finite and at most `limit` in magnitude.
pub(crate) fn bounded(
    name: &'static str,
    value: f64,
    limit: f64,
    hint: &'static str,
) -> Result<f64, InvalidInput> {
    let value = finite(name, value)?;
    if value.abs() <= limit {
        Ok(value)
    } else {
        Err(InvalidInput::TooLarge {
            name,
            value,
            limit,
            hint,
        })
    }
}

/// Checks that `value` is in `[min, max]` (NaN is not).
pub(crate) fn in_range(
    name: &'static str,
    value: f64,
    min: f64,
    max: f64,
    unit: &'static str,
) -> Result<f64, InvalidInput> {
    let inside = (min..=max).contains(&value);
    inside
        .then_some(value)
        .ok_or_else(|| outside(name, value, [min, max], unit))
}

/// The error of a `value` outside `[min, max]` (or the open interval, as
/// `unit` says).
pub(crate) fn outside(
    name: &'static str,
    value: f64,
    range: [f64; 2],
    unit: &'static str,
) -> InvalidInput {
    let [min, max] = range;
    InvalidInput::OutsideRange {
        name,
        value,
        min,
        max,
        unit,
    }
}

/// Checks that a count is in `[min, max]`.
pub(crate) fn count_in(
    name: &'static str,
    value: usize,
    min: usize,
    max: usize,
) -> Result<usize, InvalidInput> {
    let error = InvalidInput::CountOutOfRange {
        name,
        value,
        min,
        max,
    };
    (min..=max).contains(&value).then_some(value).ok_or(error)
}

/// The one of `all` that `is` picks: the value of a name `found` that
/// was parsed; [`InvalidInput::UnknownName`] for `found` as a `what` where
/// none is, listing the names `expected`.
pub(crate) fn named<T>(
    all: impl IntoIterator<Item = T>,
    is: impl FnMut(&T) -> bool,
    what: &'static str,
    expected: &'static str,
    found: &str,
) -> Result<T, InvalidInput> {
    let unknown = || InvalidInput::UnknownName {
        what,
        expected,
        found: found.to_owned(),
    };
    all.into_iter().find(is).ok_or_else(unknown)
}

/// Checks that a point is finite, naming its coordinates `"{what} x"` and
/// `"{what} y"`.
pub(crate) fn finite_point(
    names: [&'static str; 2],
    p: nalgebra::Point2<f64>,
) -> Result<nalgebra::Point2<f64>, InvalidInput> {
    finite(names[0], p.x)?;
    finite(names[1], p.y)?;
    Ok(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_say_what_to_change() {
        let e: Error = positive("crank length", -1.0).unwrap_err().into();
        let msg = e.to_string();
        assert!(msg.contains("crank length"), "{msg}");
        assert!(msg.contains("-1"), "{msg}");
        assert!(msg.contains("positive"), "{msg}");
        assert_eq!(e.kind(), "invalid input");
        assert_eq!(e.cause(), "not_positive");
        assert_eq!(
            e.fields(),
            vec![
                ("name", Field::Str("crank length".into())),
                ("value", Field::Float(-1.0))
            ]
        );
        let e = finite("theta2", f64::NAN).unwrap_err();
        assert!(e.to_string().contains("finite"));
        assert_eq!(finite("x", 1.5), Ok(1.5));
        assert!(matches!(
            positive("x", 0.0),
            Err(InvalidInput::NotPositive { .. })
        ));
        assert!(matches!(
            positive("x", f64::INFINITY),
            Err(InvalidInput::NotFinite { .. })
        ));
    }

    #[test]
    fn numbers_in_messages_are_short() {
        let e = bounded("x", 1e300, 1e100, "rescale").unwrap_err();
        let msg = e.to_string();
        assert!(msg.contains("1e300") && msg.contains("1e100"), "{msg}");
        assert!(msg.len() < 120, "{msg}");
        assert_eq!(Num(0.25).to_string(), "0.25");
        assert_eq!(Num(-3.0).to_string(), "-3");
        assert_eq!(Num(1e-300).to_string(), "1e-300");
        assert_eq!(Num(f64::NAN).to_string(), "NaN");
    }

    #[test]
    fn every_cause_has_its_fields() {
        let e: Error = DegenerateError::AtInfinity {
            what: "circle point",
            curve: "pole circle",
            x: 1.0,
            y: 2.0,
            dir_x: 0.6,
            dir_y: 0.8,
        }
        .into();
        assert_eq!(e.cause(), "at_infinity");
        let f = e.fields();
        assert!(f.contains(&("dir_x", Field::Float(0.6))));
        assert!(f.contains(&("curve", Field::Str("pole circle".into()))));
        let e = Error::Cancelled { done: 3, total: 9 };
        assert_eq!(
            e.fields(),
            vec![("done", Field::Int(3)), ("total", Field::Int(9))]
        );
    }

    #[test]
    fn causes_and_fields_come_from_the_one_list() {
        // The causes are the variants' names in snake case, also where a
        // name has one-letter words or the variant has no fields.
        let cases: [(Error, &str); 7] = [
            (
                InvalidInput::NotADyad {
                    which: "driving dyad",
                    spread: 0.1,
                    tolerance: 1e-9,
                }
                .into(),
                "not_a_dyad",
            ),
            (InvalidInput::ConicCoefficients.into(), "conic_coefficients"),
            (
                DriveError::NotACrankRocker { x: 1.0, y: 2.0 }.into(),
                "not_a_crank_rocker",
            ),
            (DriveError::NoTravel.into(), "no_travel"),
            (
                DegenerateError::InfinitelyManyBurmesterPoints { what: "w" }.into(),
                "infinitely_many_burmester_points",
            ),
            (
                AssemblyError::Indeterminate { theta2: 0.5 }.into(),
                "indeterminate",
            ),
            (
                Error::OutOfMemory {
                    what: "a grid",
                    bytes: 8,
                },
                "out_of_memory",
            ),
        ];
        for (e, cause) in cases {
            assert_eq!(e.cause(), cause, "{e:?}");
        }
        assert_eq!(InvalidInput::CubicCoefficients.fields(), vec![]);
        assert_eq!(DriveError::NoTravel.fields(), vec![]);
        // A field given as an expression of the list: the unit without its
        // leading space, the polygon's problem by its short name.
        let e: Error = in_range("angle", 400.0, 0.0, 360.0, " degrees")
            .unwrap_err()
            .into();
        assert_eq!(
            e.fields(),
            vec![
                ("name", Field::Str("angle".into())),
                ("value", Field::Float(400.0)),
                ("min", Field::Float(0.0)),
                ("max", Field::Float(360.0)),
                ("unit", Field::Str("degrees".into())),
            ]
        );
        assert!(e.to_string().contains("360 degrees"), "{e}");
        let e: Error = InvalidInput::Polygon {
            name: "obstacle 2".into(),
            vertices: 2,
            problem: PolygonProblem::TooFewVertices,
        }
        .into();
        assert_eq!(e.cause(), "polygon");
        assert_eq!(
            e.fields(),
            vec![
                ("name", Field::Str("obstacle 2".into())),
                ("vertices", Field::Int(2)),
                ("problem", Field::Str("too few vertices".into())),
            ]
        );
    }
}
