//! How the crate's types show themselves: `Debug` by what a value means,
//! and the names of the variants of a fieldless enum.

/// `Debug` for a type shown by what it means rather than by what it keeps:
/// `debug_shows!(Type, s => name: value, ...)` shows each `value` (an
/// expression of `s`, the value shown) under `name`. Doc attributes before
/// the type go on the `impl`.
macro_rules! debug_shows {
    ($(#[$m:meta])* $ty:ident, $s:ident => $($name:ident: $value:expr),+ $(,)?) => {
        $(#[$m])*
        impl core::fmt::Debug for $ty {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                let $s = self;
                f.debug_struct(stringify!($ty))
                    $(.field(stringify!($name), &$value))+
                    .finish()
            }
        }
    };
}
pub(crate) use debug_shows;

/// `as_str` (documented by the attributes given) and `Display` for a
/// fieldless enum, from the name of each variant:
/// `str_names!(/// doc, Type { Variant => "name", ... })`.
macro_rules! str_names {
    ($(#[$m:meta])* $ty:ident { $($variant:ident => $name:literal),+ $(,)? }) => {
        impl $ty {
            $(#[$m])*
            pub fn as_str(self) -> &'static str {
                match self {
                    $($ty::$variant => $name),+
                }
            }
        }

        impl core::fmt::Display for $ty {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                f.write_str(self.as_str())
            }
        }
    };
}
pub(crate) use str_names;
