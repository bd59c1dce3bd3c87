//! The seam between the search and the kinds of linkage it designs: the
//! driven dyad's kind ([`DrivenKind`]) and the linkage a design holds
//! ([`DesignedLinkage`]). A new kind is a new variant of both, with its
//! arm in each method here and its judge and candidates in the search.

use nalgebra::Point2;

use crate::geom::PerPose;
use crate::linkage::AssemblyMode;
use crate::synthesis::{Dyad, SynthesizedFourBar, SynthesizedSliderCrank};

/// The kind of the driven dyad a design searches for
/// ([`DesignOptions::driven`](super::DesignOptions::driven)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum DrivenKind {
    /// A crank (revolute dyad): the designs are four-bars.
    #[default]
    Revolute,
    /// A slider (its pin on a straight guide fixed to the ground): the
    /// designs are slider-cranks ([`Task::slider_crank`](crate::Task::slider_crank)).
    Slider,
}

impl DrivenKind {
    /// Every kind.
    pub const ALL: [DrivenKind; 2] = [DrivenKind::Revolute, DrivenKind::Slider];

    /// Its name: `"revolute"` or `"slider"`.
    pub fn as_str(self) -> &'static str {
        match self {
            DrivenKind::Revolute => "revolute",
            DrivenKind::Slider => "slider",
        }
    }

    /// The kind named `name` (as [`as_str`](Self::as_str) gives it).
    ///
    /// # Errors
    ///
    /// [`InvalidInput::UnknownName`](crate::InvalidInput::UnknownName) for
    /// another name.
    pub fn from_name(name: &str) -> crate::Result<Self> {
        Self::ALL
            .into_iter()
            .find(|k| k.as_str() == name)
            .ok_or_else(|| {
                crate::InvalidInput::UnknownName {
                    what: "driven dyad kind",
                    expected: "\"revolute\" or \"slider\"",
                    found: name.to_owned(),
                }
                .into()
            })
    }
}

/// The linkage of a design ([`Design::linkage`](super::Design::linkage)):
/// of the kind the search was asked for ([`DrivenKind`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DesignedLinkage {
    /// A four-bar (a driven crank).
    FourBar(SynthesizedFourBar),
    /// A slider-crank (a driven slider).
    SliderCrank(SynthesizedSliderCrank),
}

impl DesignedLinkage {
    /// Its driven dyad's kind.
    pub fn kind(&self) -> DrivenKind {
        match self {
            DesignedLinkage::FourBar(_) => DrivenKind::Revolute,
            DesignedLinkage::SliderCrank(_) => DrivenKind::Slider,
        }
    }

    /// The four-bar, if it is one.
    pub fn four_bar(&self) -> Option<&SynthesizedFourBar> {
        match self {
            DesignedLinkage::FourBar(l) => Some(l),
            DesignedLinkage::SliderCrank(_) => None,
        }
    }

    /// The slider-crank, if it is one.
    pub fn slider_crank(&self) -> Option<&SynthesizedSliderCrank> {
        match self {
            DesignedLinkage::SliderCrank(l) => Some(l),
            DesignedLinkage::FourBar(_) => None,
        }
    }

    /// The driving dyad `(A0, A1)`.
    pub fn driving(&self) -> &Dyad {
        match self {
            DesignedLinkage::FourBar(l) => &l.driving,
            DesignedLinkage::SliderCrank(l) => &l.driving,
        }
    }

    /// Where the driven dyad is placed: the driven pivot `C0` of a
    /// four-bar; the slider's pin `C1` at pose 1 (on its guide) of a
    /// slider-crank. The separation of two designs is measured on it and
    /// on the driving pivot.
    pub fn driven_point(&self) -> Point2<f64> {
        match self {
            DesignedLinkage::FourBar(l) => l.driven.center,
            DesignedLinkage::SliderCrank(l) => l.driven.circle,
        }
    }

    /// The crank angle at each pose.
    pub fn input_angles(&self) -> &PerPose<f64> {
        match self {
            DesignedLinkage::FourBar(l) => &l.input_angles,
            DesignedLinkage::SliderCrank(l) => &l.input_angles,
        }
    }

    /// The assembly mode at each pose (`None` at a toggle).
    pub fn modes(&self) -> PerPose<Option<AssemblyMode>> {
        match self {
            DesignedLinkage::FourBar(l) => l.modes(),
            DesignedLinkage::SliderCrank(l) => l.modes,
        }
    }

    /// Whether the motion through the poses is feasible: branch-free, on
    /// one circuit, with a driving direction.
    pub fn feasible(&self) -> bool {
        match self {
            DesignedLinkage::FourBar(l) => l.figures.feasible(),
            DesignedLinkage::SliderCrank(l) => l.feasible(),
        }
    }

    /// The smallest transmission angle over the travel (radians; NaN
    /// without a travel): the four-bar's between coupler and rocker, the
    /// slider-crank's between the coupler and the guide's normal.
    pub fn min_transmission(&self) -> f64 {
        match self {
            DesignedLinkage::FourBar(l) => l.figures.min_transmission,
            DesignedLinkage::SliderCrank(l) => l.min_transmission,
        }
    }

    /// Whether the crank turns fully.
    pub fn input_full(&self) -> bool {
        match self {
            DesignedLinkage::FourBar(l) => l.figures.input_full,
            DesignedLinkage::SliderCrank(l) => l.linkage.turns_fully(),
        }
    }

    /// Longest over shortest link (the slider-crank's: of the crank and
    /// the coupler).
    pub fn link_ratio(&self) -> f64 {
        match self {
            DesignedLinkage::FourBar(l) => l.figures.link_ratio,
            DesignedLinkage::SliderCrank(l) => l.linkage.link_ratio(),
        }
    }

    /// Its size (task units): [`SynthesizedFourBar::size`] or
    /// [`SynthesizedSliderCrank::size`].
    pub fn size(&self) -> f64 {
        match self {
            DesignedLinkage::FourBar(l) => l.size(),
            DesignedLinkage::SliderCrank(l) => l.size(),
        }
    }

    /// The travel: the crank angle at pose 1 and the signed angle through
    /// the poses to the last; `None` without a driving direction.
    pub fn travel(&self) -> Option<(f64, f64)> {
        match self {
            DesignedLinkage::FourBar(l) => l.travel(),
            DesignedLinkage::SliderCrank(l) => l.travel(),
        }
    }
}
