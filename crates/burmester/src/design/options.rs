//! The options of a map checked once: the limits validated and the
//! constraints prepared, the value every map takes.

use std::fmt;

use crate::design::constraints::Prepared;
use crate::design::{Constraints, DesignLimits};
use crate::error::Result;

/// The limits and constraints of a map, checked once ([`MapOptions::new`]):
/// what the solution maps, the pair map, the atlas, the drive and actuator
/// maps and the drive search judge their samples by, so that none of them
/// validates the same options again.
///
/// # Example
///
/// ```
/// use burmester::{Constraints, DesignLimits, MapOptions};
/// let options = MapOptions::new(&DesignLimits::default(), &Constraints::default())?;
/// assert_eq!(options.limits(), &DesignLimits::default());
/// let bad = DesignLimits { max_link_ratio: 0.5, ..DesignLimits::default() };
/// assert!(MapOptions::new(&bad, &Constraints::default()).is_err());
/// assert_eq!(MapOptions::default(), options);
/// # Ok::<(), burmester::Error>(())
/// ```
#[derive(Clone)]
pub struct MapOptions {
    limits: DesignLimits,
    constraints: Constraints,
    prepared: Prepared,
}

impl MapOptions {
    /// The options, validated: the limits ([`DesignLimits::validate`]) and
    /// the constraints (their polygons as shapes).
    ///
    /// # Errors
    ///
    /// [`InvalidInput`](crate::InvalidInput) for invalid limits or
    /// constraints.
    pub fn new(limits: &DesignLimits, constraints: &Constraints) -> Result<Self> {
        limits.validate()?;
        Ok(MapOptions {
            limits: *limits,
            constraints: constraints.clone(),
            prepared: constraints.prepare()?,
        })
    }

    /// The limits.
    pub fn limits(&self) -> &DesignLimits {
        &self.limits
    }

    /// The constraints.
    pub fn constraints(&self) -> &Constraints {
        &self.constraints
    }

    /// The constraints as shapes.
    pub(crate) fn prepared(&self) -> &Prepared {
        &self.prepared
    }
}

impl Default for MapOptions {
    /// The default limits ([`DesignLimits::default`]) and no constraints
    /// ([`Constraints::default`]), both valid.
    fn default() -> Self {
        MapOptions {
            limits: DesignLimits::default(),
            constraints: Constraints::default(),
            prepared: Prepared::unconstrained(),
        }
    }
}

/// The limits and the constraints (the shapes follow from them).
impl fmt::Debug for MapOptions {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("MapOptions")
            .field("limits", &self.limits)
            .field("constraints", &self.constraints)
            .finish()
    }
}

/// Equal when the limits and the constraints are (the shapes follow from
/// them).
impl PartialEq for MapOptions {
    fn eq(&self, other: &Self) -> bool {
        self.limits == other.limits && self.constraints == other.constraints
    }
}
