//! The options of a map checked once: the limits validated and the
//! constraints prepared, the value every map takes.

use crate::design::constraints::Prepared;
use crate::design::{Constraints, DesignLimits};
use crate::error::Result;

/// The limits and constraints of a map, checked once ([`CheckedOptions::new`]):
/// what the solution maps, the pair map, the atlas and the design search's
/// maps judge their samples by, so that none of them validates the same
/// options again.
pub(crate) struct CheckedOptions {
    limits: DesignLimits,
    constraints: Constraints,
    prepared: Prepared,
}

impl CheckedOptions {
    /// The options, validated: the limits ([`DesignLimits::validate`]) and
    /// the constraints (their polygons as shapes).
    ///
    /// # Errors
    ///
    /// [`InvalidInput`](crate::InvalidInput) for invalid limits or
    /// constraints.
    pub(crate) fn new(limits: &DesignLimits, constraints: &Constraints) -> Result<Self> {
        limits.validate()?;
        Ok(CheckedOptions {
            limits: *limits,
            constraints: constraints.clone(),
            prepared: constraints.prepare()?,
        })
    }

    /// The limits.
    pub(crate) fn limits(&self) -> &DesignLimits {
        &self.limits
    }

    /// The constraints.
    pub(crate) fn constraints(&self) -> &Constraints {
        &self.constraints
    }

    /// The constraints as shapes.
    pub(crate) fn prepared(&self) -> &Prepared {
        &self.prepared
    }
}
