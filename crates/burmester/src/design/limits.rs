//! The designer's limits behind the `acceptable` mask.

use crate::error::{InvalidInput, Result, in_range};
use crate::linkage::{Direction, LinkageFigures};

crate::geom::parsed_enum! {
    /// Which kind of input link a design requires.
    #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
    pub enum InputRequirement("input requirement", "\"any\", \"crank\" or \"rocker\"") {
        /// Any input that carries the coupler through the poses.
        #[default]
        Any => "any",
        /// The input must turn fully (a crank: motor-driven without reversing).
        Crank => "crank",
        /// The input must rock (not turn fully).
        Rocker => "rocker",
    }
    /// `"any"`, `"crank"` or `"rocker"`.
    pub fn as_str;
}

/// The designer's limits behind the `acceptable` mask.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DesignLimits {
    /// The smallest acceptable transmission angle over the travel, radians
    /// (default 30 degrees, a common rule of thumb).
    pub min_transmission: f64,
    /// The largest acceptable ratio of the longest to the shortest link
    /// (default 10).
    pub max_link_ratio: f64,
    /// Which input is required (default: any).
    pub input: InputRequirement,
    /// The largest acceptable size ratio: the linkage's size (the total
    /// length of its members, [`SynthesizedFourBar::size`](crate::SynthesizedFourBar::size))
    /// over the task's ([`Task::span`](crate::Task::span)); scale-free
    /// (default: infinity, no limit).
    pub max_size_ratio: f64,
    /// The longest acceptable link (ground, crank, coupler or rocker), in
    /// the task's units (default: infinity, no limit).
    pub max_link_length: f64,
    /// The smallest acceptable distance from the Grashof change point,
    /// [`LinkageFigures::grashof_margin`]: `|s + l - p - q|` over the links'
    /// total length (default [`DesignLimits::DEFAULT_GRASHOF_MARGIN`], 1%;
    /// 0: no limit). A change-point linkage (every kite) is one no designer
    /// builds: its type flips with the smallest error of a link, and a
    /// fully turning input passes the flat position where it can switch
    /// circuits. The margin keeps the type for every set of link errors
    /// adding up to less than it times the links' total length.
    pub min_grashof_margin: f64,
}

impl Default for DesignLimits {
    fn default() -> Self {
        DesignLimits {
            min_transmission: 30f64.to_radians(),
            max_link_ratio: 10.0,
            input: InputRequirement::Any,
            max_size_ratio: f64::INFINITY,
            max_link_length: f64::INFINITY,
            min_grashof_margin: Self::DEFAULT_GRASHOF_MARGIN,
        }
    }
}

impl DesignLimits {
    /// The default [`min_grashof_margin`](Self::min_grashof_margin): 0.01,
    /// a tolerance of 1% of each link's length (1 mm on a 100 mm link)
    /// that cannot reach the change point. A laser-cut or stamped link
    /// holds its hole distance to about 0.2 mm and a machined one to
    /// 0.05 mm; the rest is for clearance in the joints and deflection.
    /// Four links each off by 1% of its length in the worst directions
    /// move `s + l - p - q` by at most 1% of the links' total length.
    pub const DEFAULT_GRASHOF_MARGIN: f64 = 0.01;

    /// Limits with the transmission angle in degrees (as designers give
    /// it), validated.
    ///
    /// # Errors
    ///
    /// As [`DesignLimits::validate`], with the angle named
    /// `min_transmission_deg` and its range in degrees.
    pub fn from_degrees(
        min_transmission_deg: f64,
        max_link_ratio: f64,
        input: InputRequirement,
    ) -> Result<Self> {
        in_range(
            "min_transmission_deg",
            min_transmission_deg,
            0.0,
            90.0,
            " degrees",
        )?;
        let limits = DesignLimits {
            min_transmission: min_transmission_deg.to_radians(),
            max_link_ratio,
            input,
            ..DesignLimits::default()
        };
        limits.validate()?;
        Ok(limits)
    }

    /// The same limits with the largest size ratio and the longest link
    /// (task units) given (infinity: no limit), validated.
    ///
    /// # Errors
    ///
    /// As [`DesignLimits::validate`].
    pub fn with_size(self, max_size_ratio: f64, max_link_length: f64) -> Result<Self> {
        let limits = DesignLimits {
            max_size_ratio,
            max_link_length,
            ..self
        };
        limits.validate()?;
        Ok(limits)
    }

    /// The same limits with the smallest distance from the Grashof change
    /// point given ([`min_grashof_margin`](Self::min_grashof_margin); 0: no
    /// limit), validated.
    ///
    /// # Errors
    ///
    /// As [`DesignLimits::validate`].
    pub fn with_grashof_margin(self, min_grashof_margin: f64) -> Result<Self> {
        let limits = DesignLimits {
            min_grashof_margin,
            ..self
        };
        limits.validate()?;
        Ok(limits)
    }

    /// Whether the limits bound the linkage's size (a finite
    /// [`max_size_ratio`](Self::max_size_ratio) or
    /// [`max_link_length`](Self::max_link_length)).
    pub fn limits_size(&self) -> bool {
        self.max_size_ratio.is_finite() || self.max_link_length.is_finite()
    }

    /// Whether a linkage with link lengths `lengths` and size ratio
    /// `size_ratio` (its size over the task's) is within the size limits:
    /// `size_ratio <= max_size_ratio` and every link at most
    /// `max_link_length`.
    #[inline]
    pub fn meets_size(&self, lengths: [f64; 4], size_ratio: f64) -> bool {
        size_ratio <= self.max_size_ratio && lengths.iter().all(|&l| l <= self.max_link_length)
    }

    /// Checks the limits: a transmission angle in `[0, pi/2]`, a link ratio
    /// of at least 1 (infinity allowed: no limit), a size ratio of at least
    /// 1, a link length above 0 (infinity allowed for both) and a Grashof
    /// margin in `[0, 1]`.
    ///
    /// # Errors
    ///
    /// [`InvalidInput::OutsideRange`] when a limit is NaN or out of its range.
    pub fn validate(&self) -> Result<()> {
        in_range(
            "min_transmission",
            self.min_transmission,
            0.0,
            core::f64::consts::FRAC_PI_2,
            " radians",
        )?;
        in_range(
            "max_link_ratio",
            self.max_link_ratio,
            1.0,
            f64::INFINITY,
            "",
        )?;
        in_range(
            "max_size_ratio",
            self.max_size_ratio,
            1.0,
            f64::INFINITY,
            " (the linkage's size over the task's)",
        )?;
        if self.max_link_length.is_nan() || self.max_link_length <= 0.0 {
            return Err(InvalidInput::NotPositive {
                name: "max_link_length",
                value: self.max_link_length,
            }
            .into());
        }
        in_range(
            "min_grashof_margin",
            self.min_grashof_margin,
            0.0,
            1.0,
            " (|s + l - p - q| over the links' total length)",
        )?;
        Ok(())
    }

    /// Whether a linkage's figures meet the limits, its motion being
    /// feasible (branch-free, one circuit, a driving direction).
    pub fn accepts(&self, f: &LinkageFigures) -> bool {
        f.branch_free() && self.meets(f)
    }

    /// [`accepts`](Self::accepts) but for the branch flag, which a
    /// three-pose driving map takes from its exact conic sweep instead of
    /// the modes: one circuit, a driving direction, the transmission angle,
    /// the link ratio, the input kind and the Grashof margin. The one
    /// acceptance test of the solution maps and the rankings.
    pub fn meets(&self, f: &LinkageFigures) -> bool {
        self.meets_when(
            f.one_circuit,
            f.direction,
            f.link_ratio,
            f.input_full,
            f.grashof_margin(),
            || f.min_transmission >= self.min_transmission,
        )
    }

    /// [`meets`](Self::meets) from the figures it reads, the transmission
    /// test given (`transmission_ok`: the minimum transmission angle is at
    /// least the limit) and asked last: the atlas decides it mostly without
    /// an `acos`.
    #[inline(always)]
    pub(crate) fn meets_when(
        &self,
        one_circuit: bool,
        direction: Direction,
        link_ratio: f64,
        input_full: bool,
        grashof_margin: f64,
        transmission_ok: impl FnOnce() -> bool,
    ) -> bool {
        one_circuit
            && direction != Direction::None
            && link_ratio <= self.max_link_ratio
            && grashof_margin >= self.min_grashof_margin
            && match self.input {
                InputRequirement::Any => true,
                InputRequirement::Crank => input_full,
                InputRequirement::Rocker => !input_full,
            }
            && transmission_ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limits_validate() {
        assert!(DesignLimits::default().validate().is_ok());
        let l = |t: f64, r: f64| DesignLimits {
            min_transmission: t,
            max_link_ratio: r,
            ..DesignLimits::default()
        };
        assert!(l(2.0, 10.0).validate().is_err());
        assert!(l(0.1, 0.5).validate().is_err());
        assert!(l(0.1, f64::NAN).validate().is_err());
        assert!(l(0.1, f64::INFINITY).validate().is_ok());
        assert!(DesignLimits::from_degrees(95.0, 10.0, InputRequirement::Any).is_err());
        let e = DesignLimits::from_degrees(f64::NAN, 10.0, InputRequirement::Any).unwrap_err();
        assert!(e.to_string().contains("min_transmission_deg"), "{e}");
        let d = DesignLimits::default();
        assert!(d.with_size(0.5, 1.0).is_err());
        assert!(d.with_size(f64::NAN, 1.0).is_err());
        assert!(d.with_size(2.0, 0.0).is_err());
        assert!(d.with_size(2.0, f64::NAN).is_err());
        let s = d.with_size(5.0, 3.0).unwrap();
        assert!(s.limits_size() && !d.limits_size());
        assert!(s.meets_size([1.0, 2.0, 3.0, 1.0], 5.0));
        assert!(!s.meets_size([1.0, 2.0, 3.1, 1.0], 4.0));
        assert!(!s.meets_size([1.0, 2.0, 3.0, 1.0], 5.1));
        assert_eq!(d.min_grashof_margin, DesignLimits::DEFAULT_GRASHOF_MARGIN);
        assert!(d.with_grashof_margin(-0.1).is_err());
        assert!(d.with_grashof_margin(f64::NAN).is_err());
        assert!(d.with_grashof_margin(1.5).is_err());
        let e = d.with_grashof_margin(2.0).unwrap_err();
        assert!(e.to_string().contains("min_grashof_margin"), "{e}");
        assert_eq!(d.with_grashof_margin(0.0).unwrap().min_grashof_margin, 0.0);
        assert_eq!(
            "Crank".parse::<InputRequirement>().unwrap(),
            InputRequirement::Crank
        );
    }
}
