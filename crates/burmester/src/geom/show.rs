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
    (@as_str $(#[$m:meta])* $ty:ident { $($variant:ident => $name:literal),+ }) => {
        impl $ty {
            $(#[$m])*
            pub fn as_str(self) -> &'static str {
                match self {
                    $($ty::$variant => $name),+
                }
            }
        }
    };
    ($(#[$m:meta])* $ty:ident { $($variant:ident => $name:literal),+ $(,)? }) => {
        $crate::geom::str_names!(@as_str $(#[$m])* $ty { $($variant => $name),+ });

        impl core::fmt::Display for $ty {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                f.write_str(self.as_str())
            }
        }
    };
}
pub(crate) use str_names;

/// A fieldless enum defined with the name of each variant beside it, its
/// `as_str` (documented by the attributes before `pub fn as_str;`) and
/// its `FromStr`, ASCII case-insensitive, where another name is
/// [`InvalidInput::UnknownName`](crate::InvalidInput::UnknownName) with
/// the `what` and `expected` given after the type's name:
/// `parsed_enum! { /// doc, #[derive(..)] pub enum Type("what",
/// "expected") { /// doc, Variant => "name", ... } /// doc, pub fn as_str; }`.
macro_rules! parsed_enum {
    (
        $(#[$m:meta])*
        $vis:vis enum $ty:ident($what:literal, $expected:literal) {
            $($(#[$vm:meta])* $variant:ident => $name:literal,)+
        }
        $(#[$am:meta])*
        pub fn as_str;
    ) => {
        $(#[$m])*
        $vis enum $ty {
            $($(#[$vm])* $variant,)+
        }

        $crate::geom::str_names!(@as_str $(#[$am])* $ty { $($variant => $name),+ });

        impl core::str::FromStr for $ty {
            type Err = $crate::InvalidInput;

            fn from_str(s: &str) -> Result<Self, $crate::InvalidInput> {
                match s.to_ascii_lowercase().as_str() {
                    $($name => Ok($ty::$variant),)+
                    _ => Err($crate::InvalidInput::UnknownName {
                        what: $what,
                        expected: $expected,
                        found: s.to_owned(),
                    }),
                }
            }
        }
    };
}
pub(crate) use parsed_enum;

#[cfg(test)]
mod tests {
    use crate::{Error, InputRequirement, InvalidInput, Method};

    /// The enums of [`parsed_enum!`]: each name, in any ASCII case, parses
    /// back to its variant, and another name is refused with the message
    /// their hand-written `FromStr` gave (the literal text).
    #[test]
    fn parsed_enums_take_their_names_and_refuse_others() {
        let inputs = [
            InputRequirement::Any,
            InputRequirement::Crank,
            InputRequirement::Rocker,
        ];
        let names: Vec<&str> = inputs.iter().map(|v| v.as_str()).collect();
        assert_eq!(names, ["any", "crank", "rocker"]);
        for v in inputs {
            assert_eq!(v.as_str().parse::<InputRequirement>(), Ok(v));
            assert_eq!(v.as_str().to_uppercase().parse::<InputRequirement>(), Ok(v));
        }
        let methods = [Method::Conic, Method::Direct, Method::Simulate];
        let names: Vec<&str> = methods.iter().map(|v| v.as_str()).collect();
        assert_eq!(names, ["conic", "direct", "simulate"]);
        for v in methods {
            assert_eq!(v.as_str().parse::<Method>(), Ok(v));
            assert_eq!(v.as_str().to_uppercase().parse::<Method>(), Ok(v));
        }
        assert_eq!("SiMuLaTe".parse::<Method>(), Ok(Method::Simulate));
        let e = "crank ".parse::<InputRequirement>().unwrap_err();
        assert!(matches!(e, InvalidInput::UnknownName { .. }));
        assert_eq!(
            Error::from(e).to_string(),
            "unknown input requirement \"crank \"; use one of \"any\", \"crank\" or \"rocker\""
        );
        let e = "Konic".parse::<Method>().unwrap_err();
        assert_eq!(
            e.to_string(),
            "unknown classification method \"Konic\"; use one of \"conic\", \"direct\" or \
             \"simulate\""
        );
        // Not ASCII: no case folding beyond ASCII ("İ" is not "i").
        assert!("dİrect".parse::<Method>().is_err());
    }
}
