//! Plain read-only properties written once: `getters!` makes the
//! `#[getter]` methods that only read a value of the wrapped core object.

/// A `#[pymethods]` block of plain getters of `$cls`, each reading
/// `self.$field.<name>` (`self.<name>` without a field, `self.<path>.<name>`
/// with a path in brackets, such as `[inner.viewport()]`), as in
/// `getters!(PyConfiguration, inner { f64: theta2, theta3; str: mode; })`.
/// The groups, each ending in `;`:
///
/// - `T: a, b;` the fields `a`, `b` (of a `Copy` type `T`);
/// - `fn T: a, b;` the results of the methods `a()`, `b()`;
/// - `str: a;` / `fn str: a;` the name (`.as_str()`, a `&'static str`) of
///   an enum field or method result;
/// - `T = f: a;` / `fn T = f: a;` the field or method result converted by
///   the function `f` (such as `pt` for a point).
///
/// A getter with a doc comment or any other logic is written out instead.
macro_rules! getters {
    ($cls:ty { $($groups:tt)* }) => {
        $crate::getters::getters!(@group $cls, [], [] $($groups)*);
    };
    ($cls:ty, $field:ident { $($groups:tt)* }) => {
        $crate::getters::getters!(@group $cls, [$field.], [] $($groups)*);
    };
    ($cls:ty, [$($path:tt)*] { $($groups:tt)* }) => {
        $crate::getters::getters!(@group $cls, [$($path)*.], [] $($groups)*);
    };
    (@group $cls:ty, $path:tt, [$($made:tt)*]) => {
        #[pyo3::pymethods]
        impl $cls {
            $($made)*
        }
    };
    (@group $cls:ty, $path:tt, $made:tt str: $($n:ident),+; $($rest:tt)*) => {
        $crate::getters::getters!(@make $cls, $path, $made, &'static str,
            ::core::convert::identity, [$($n (.as_str()))+] $($rest)*);
    };
    (@group $cls:ty, $path:tt, $made:tt fn str: $($n:ident),+; $($rest:tt)*) => {
        $crate::getters::getters!(@make $cls, $path, $made, &'static str,
            ::core::convert::identity, [$($n (().as_str()))+] $($rest)*);
    };
    (@group $cls:ty, $path:tt, $made:tt fn $t:ty = $f:path: $($n:ident),+; $($rest:tt)*) => {
        $crate::getters::getters!(@make $cls, $path, $made, $t, $f, [$($n (()))+] $($rest)*);
    };
    (@group $cls:ty, $path:tt, $made:tt fn $t:ty: $($n:ident),+; $($rest:tt)*) => {
        $crate::getters::getters!(@make $cls, $path, $made, $t,
            ::core::convert::identity, [$($n (()))+] $($rest)*);
    };
    (@group $cls:ty, $path:tt, $made:tt $t:ty = $f:path: $($n:ident),+; $($rest:tt)*) => {
        $crate::getters::getters!(@make $cls, $path, $made, $t, $f, [$($n ())+] $($rest)*);
    };
    (@group $cls:ty, $path:tt, $made:tt $t:ty: $($n:ident),+; $($rest:tt)*) => {
        $crate::getters::getters!(@make $cls, $path, $made, $t,
            ::core::convert::identity, [$($n ())+] $($rest)*);
    };
    // One getter a step, `f(self.<path>.name<suffix>)` (the path ends in a
    // dot unless empty), until the group's
    // names are made.
    (@make $cls:ty, $path:tt, $made:tt, $t:ty, $f:path, [] $($rest:tt)*) => {
        $crate::getters::getters!(@group $cls, $path, $made $($rest)*);
    };
    (@make $cls:ty, [$($path:tt)*], [$($made:tt)*], $t:ty, $f:path,
        [$n:ident ($($suffix:tt)*) $($more:tt)*] $($rest:tt)*) => {
        $crate::getters::getters!(@make $cls, [$($path)*], [$($made)*
            #[getter]
            fn $n(&self) -> $t {
                $f(self.$($path)*$n $($suffix)*)
            }
        ], $t, $f, [$($more)*] $($rest)*);
    };
}

pub(crate) use getters;
