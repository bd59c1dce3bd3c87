//! The columns of the solution map, the pivot map's and the pair map's:
//! defined once, by [`solution_map_columns!`](crate::solution_map_columns):
//! the core's [`Columns`] and per-sample record are generated from that
//! list, and so is the Python binding's class.

use crate::engine::Rows;

/// Calls `$callback! { ... }` with the solution map's columns, each as
/// `/// docs  name: type = value where the linkage does not exist`, in
/// order. The one list of the columns: the core's [`Columns`] and the
/// Python binding's `SolutionMap` class are generated from it.
#[macro_export]
macro_rules! solution_map_columns {
    ($callback:ident) => {
        $callback! {
            /// The linkage exists: the candidate has a circle point and every
            /// link a nonzero length. Where false, the other columns hold
            /// false, 0, NaN or `GRASHOF_NONE`.
            valid: bool = false,
            /// Free of the branch defect (for candidate driving pivots,
            /// exactly the `conic` branch map).
            branch_free: bool = false,
            /// Grashof class as the index of its class in `Grashof::ALL`;
            /// `SolutionMap::GRASHOF_NONE` (255) where invalid.
            grashof: u8 = $crate::SolutionMap::GRASHOF_NONE,
            /// The driving link turns fully.
            input_full: bool = false,
            /// The input rotation that carries the coupler through the poses
            /// in order: `1` counter-clockwise, `-1` clockwise, `0` none
            /// (`Direction::code`).
            direction: i8 = 0,
            /// The input angles at the poses lie on one circuit.
            one_circuit: bool = false,
            /// Minimum transmission angle over the travel, radians; NaN where
            /// there is no travel or no linkage.
            min_transmission_rad: f32 = f32::NAN,
            /// Longest over shortest link; NaN where there is no linkage.
            link_ratio: f32 = f32::NAN,
            /// The linkage's size relative to the task's: the total length of
            /// its members (`SynthesizedFourBar::size`) over the largest
            /// distance between two pose positions (`Task::span`); NaN where
            /// there is no linkage.
            size_ratio: f32 = f32::NAN,
            /// Meets the limits and the constraints, with a feasible,
            /// branch-free motion.
            acceptable: bool = false,
        }
    };
}

/// Defines a map's column types from its list of columns (as
/// [`solution_map_columns!`](crate::solution_map_columns) gives it):
/// `$columns`, one `Vec` per column, with the names and room for a fill;
/// `$out`, every column borrowed for writing; `$sample`, one sample's
/// values with `INVALID`, the sample without a linkage. `$what` names the
/// map in an allocation error; `$doc` and `$out_doc` document the first two.
/// The one definition of a map's columns, for the solution map and the
/// drive map.
macro_rules! map_column_types {
    ($columns:ident, $out:ident, $sample:ident, $what:literal, $doc:literal, $out_doc:literal;
     $($(#[$cdoc:meta])* $name:ident: $ty:ty = $invalid:expr,)*) => {
        #[doc = $doc]
        #[derive(Debug, Clone, PartialEq)]
        pub struct $columns {
            $($(#[$cdoc])* pub $name: Vec<$ty>,)*
        }

        impl $columns {
            /// The names of the columns, in order.
            pub const NAMES: &'static [&'static str] = &[$(stringify!($name)),*];

            /// Room for `n` samples, zeroed, for a fill that writes every
            /// sample (each path does: a sample with no linkage is the
            /// sample's `INVALID`); the pages are first touched by the
            /// threads that write them.
            pub(crate) fn for_overwrite(n: usize) -> $crate::error::Result<Self> {
                Ok($columns {
                    $($name: $crate::error::try_zeroed_vec($what, n)?,)*
                })
            }

            /// Every column borrowed for writing: an earlier map's columns
            /// to fill again (with the map's `_into` method), without new
            /// pages.
            pub fn as_out(&mut self) -> $out<'_> {
                $out {
                    $($name: &mut self.$name,)*
                }
            }
        }

        #[doc = $out_doc]
        #[derive(Debug)]
        pub struct $out<'a> {
            $($(#[$cdoc])* pub $name: &'a mut [$ty],)*
        }

        impl $out<'_> {
            /// Every column has `n` values.
            pub(crate) fn check_len(&self, n: usize) -> $crate::error::Result<()> {
                $(
                    if self.$name.len() != n {
                        return Err($crate::error::InvalidInput::LengthMismatch {
                            name: concat!("column ", stringify!($name)),
                            expected: n,
                            found: self.$name.len(),
                        }
                        .into());
                    }
                )*
                Ok(())
            }
        }

        /// One sample's values.
        #[derive(Clone, Copy)]
        pub(crate) struct $sample {
            $(pub(crate) $name: $ty,)*
        }

        impl $sample {
            /// The sample without a linkage.
            pub(crate) const INVALID: $sample = $sample {
                $($name: $invalid,)*
            };
        }
    };
}
pub(crate) use map_column_types;

/// Defines a map's columns from its one list: the exported macro `$list`,
/// which calls `$callback! { ... }` with the columns (each as `/// docs
/// name: type = value where there is no sample`, in order; the Python
/// binding generates its class from it), the core's column types
/// ([`map_column_types!`]) and the columns-to-write's `set`, which writes
/// one sample of every column. `$d` is a `$` token (for the macro it
/// defines); `$map` names the map in the docs. The one definition of the
/// drive map's and the actuator map's columns.
macro_rules! map_columns {
    ($d:tt $list:ident, $map:literal,
     ($columns:ident, $out:ident, $sample:ident, $what:literal, $doc:literal, $out_doc:literal);
     $($(#[$cdoc:meta])* $name:ident: $ty:ty = $invalid:expr,)*) => {
        #[doc = concat!(
            "Calls `$callback! { ... }` with the ", $map, "'s columns, each as `/// docs  ",
            "name: type = value where there is none`, in order. The one list of the columns: ",
            "the core's `", stringify!($columns), "` and the Python binding's class are ",
            "generated from it."
        )]
        #[macro_export]
        macro_rules! $list {
            ($d callback:ident) => {
                $d callback! {
                    $($(#[$cdoc])* $name: $ty = $invalid,)*
                }
            };
        }

        $crate::design::columns::map_column_types!(
            $columns, $out, $sample, $what, $doc, $out_doc;
            $($(#[$cdoc])* $name: $ty = $invalid,)*
        );

        impl $out<'_> {
            /// Writes sample `i` of every column.
            #[inline(always)]
            fn set(&mut self, i: usize, s: $sample) {
                $(self.$name[i] = s.$name;)*
            }
        }
    };
}
pub(crate) use map_columns;

/// Implements `Debug` for a map `$map` of a `context` and its `columns`
/// (a [`Columns`]): what it was computed for, how many samples it has
/// (the field `$samples`) and how many of them are branch-free and
/// acceptable, not every value of every column. The solution map's and the
/// pair map's.
macro_rules! debug_map {
    ($map:ident, $samples:literal) => {
        #[doc = concat!(
            "What the map was computed for and how many ", $samples, " are acceptable, not\n",
            "every value of every column (those are [`", stringify!($map), "::columns`])."
        )]
        impl core::fmt::Debug for $map {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                let count = |c: &[bool]| c.iter().filter(|&&b| b).count();
                f.debug_struct(stringify!($map))
                    .field("context", &self.context)
                    .field($samples, &self.columns.valid.len())
                    .field("branch_free", &count(&self.columns.branch_free))
                    .field("acceptable", &count(&self.columns.acceptable))
                    .finish()
            }
        }
    };
}
pub(crate) use debug_map;

macro_rules! define_columns {
    ($($t:tt)*) => {
        map_column_types!(
            Columns,
            ColumnsOut,
            Sample,
            "a solution map",
            "The columns of a solution map: one value per grid sample, row-major like the \
             branch map.",
            "A solution map's columns to write: one slice per column, each of one value per \
             grid sample, row-major. From [`Columns::as_out`] (to reuse a map's memory, with \
             [`Filemon::solution_map_into`](crate::Filemon::solution_map_into) or \
             [`Task::driven_solution_map_into`](crate::Task::driven_solution_map_into)) or \
             from buffers the caller allocates (the Python binding's NumPy arrays).";
            $($t)*
        );
        define_rows! { $($t)* }
    };
}

macro_rules! define_rows {
    ($($(#[$doc:meta])* $name:ident: $ty:ty = $invalid:expr,)*) => {
        #[cfg(test)]
        impl Columns {
            /// Sample `i`, every column.
            pub(crate) fn sample(&self, i: usize) -> Sample {
                Sample {
                    $($name: self.$name[i],)*
                }
            }

            pub(crate) fn rows(&mut self, nx: usize) -> ColumnsMut<'_> {
                self.as_out().rows(nx)
            }
        }

        impl<'a> ColumnsOut<'a> {
            pub(crate) fn rows(self, nx: usize) -> ColumnsMut<'a> {
                ColumnsMut {
                    $($name: self.$name,)*
                    nx,
                }
            }
        }

        /// A block of rows of every column.
        pub(crate) struct ColumnsMut<'a> {
            $($name: &'a mut [$ty],)*
            nx: usize,
        }

        impl Rows for ColumnsMut<'_> {
            fn split_rows(self, rows: usize) -> (Self, Self) {
                let at = (rows * self.nx).min(self.valid.len());
                $(let $name = self.$name.split_at_mut(at);)*
                (
                    ColumnsMut { $($name: $name.0,)* nx: self.nx },
                    ColumnsMut { $($name: $name.1,)* nx: self.nx },
                )
            }
        }

        impl ColumnsMut<'_> {
            #[inline(always)]
            pub(crate) fn set(&mut self, i: usize, s: Sample) {
                $(self.$name[i] = s.$name;)*
            }

            /// Row `r` of the block, every column.
            #[inline(always)]
            pub(crate) fn row(&mut self, r: usize) -> ColumnsRow<'_> {
                let at = r * self.nx..(r + 1) * self.nx;
                ColumnsRow {
                    $($name: &mut self.$name[at.clone()],)*
                }
            }
        }

        /// One row of every column, for a writer that fills a row column
        /// by column.
        pub(crate) struct ColumnsRow<'a> {
            $(pub(crate) $name: &'a mut [$ty],)*
        }
    };
}

crate::solution_map_columns!(define_columns);
