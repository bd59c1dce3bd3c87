//! Errors, one enum per concern.
//!
//! Every fallible function in the crate returns [`Error`](enum@Error), which wraps one of
//! three kinds:
//!
//! * [`InvalidInput`]: a number or a string the caller passed is not
//!   acceptable (NaN, infinite, zero or negative length, unknown name, wrong
//!   length of a batch). Change the input.
//! * [`AssemblyError`]: the input is well formed, but the linkage cannot be
//!   put together where it was asked to be (the loop does not close).
//! * [`DegenerateError`]: the geometry is degenerate: an answer lies at
//!   infinity, or the task has no unique answer.
//!
//! The messages say what was wrong and what to change. Nothing in the crate
//! panics on user input, and no NaN is handed back without a flag saying so.

use thiserror::Error;

/// Result type of the crate.
pub type Result<T, E = Error> = core::result::Result<T, E>;

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
}

/// An argument is not acceptable: change it.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum InvalidInput {
    /// A number is NaN or infinite.
    #[error("{name} must be a finite number, got {value}; pass a finite value")]
    NotFinite {
        /// What the number is (for example `"crank length"`).
        name: &'static str,
        /// The value that was passed.
        value: f64,
    },
    /// A length is zero or negative.
    #[error("{name} must be greater than zero, got {value}; pass a positive length")]
    NotPositive {
        /// What the length is.
        name: &'static str,
        /// The value that was passed.
        value: f64,
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
    /// A grid or a sampling parameter is out of its range.
    #[error("{name} is {found}, but {expected}")]
    OutOfRange {
        /// Which argument.
        name: &'static str,
        /// What is expected, in words (for example `"must be at least 1"`).
        expected: &'static str,
        /// What was found, formatted.
        found: String,
    },
}

/// The linkage cannot be assembled as asked.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum AssemblyError {
    /// The longest link is longer than the other three together: no input
    /// angle closes the loop.
    #[error(
        "the linkage can never be assembled: its longest link ({longest}) is longer than the \
         other three together ({others}); shorten it or lengthen the others"
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
        "the loop does not close at theta2 = {theta2} rad: the crank tip is {distance} from the \
         output pivot, but coupler and rocker reach only from {min_reach} to {max_reach}; choose \
         an input angle inside the input range (FourBar::input_range)"
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
        "the position at theta2 = {theta2} rad is indeterminate: the crank tip lies on the output \
         pivot and the coupler is as long as the rocker, so any coupler angle closes the loop; \
         step the input angle away from it"
    )]
    Indeterminate {
        /// The input angle, in radians.
        theta2: f64,
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
    /// `Task::MIN_ROTATION`), so their pole is at infinity.
    #[error(
        "poses {i} and {j} have the same angle (within 1e-6 rad), so the motion between them is \
         a pure translation and their pole is at infinity; this is not supported: rotate one of \
         the poses by at least 1e-6 rad (a few thousandths of a degree)"
    )]
    PureTranslation {
        /// First pose index (1-based).
        i: usize,
        /// Second pose index (1-based).
        j: usize,
    },
    /// The three poses are rotations about one point: all three poles
    /// coincide, and every dyad has its center point there.
    #[error(
        "the three poses are rotations about one point ({x}, {y}): all poles coincide there, so \
         the synthesis is degenerate (every dyad is centered there); move one pose off that \
         rotation"
    )]
    CoincidentPoles {
        /// x of the common pole.
        x: f64,
        /// y of the common pole.
        y: f64,
    },
    /// The answer of a map lies at infinity.
    #[error(
        "the {what} of ({x}, {y}) is at infinity (direction {dir_x}, {dir_y}): the point lies on \
         the {curve}; choose a point off it"
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
        "the {what} of ({x}, {y}) is not unique: the point is at {at}, where the map is \
         undefined; choose a point off it"
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
    /// A dyad's center point and circle point coincide (a link of zero length).
    #[error(
        "the {what} has zero length: its center point and circle point coincide at ({x}, {y}); \
         choose another point"
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

impl Error {
    /// A short name of the kind: `"invalid input"`, `"assembly"` or `"degenerate"`.
    pub fn kind(&self) -> &'static str {
        match self {
            Error::InvalidInput(_) => "invalid input",
            Error::Assembly(_) => "assembly",
            Error::Degenerate(_) => "degenerate",
        }
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
}
