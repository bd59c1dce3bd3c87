//! The designs of a search with a motor ([`DesignOptions::motor`]) or a
//! linear actuator ([`DesignOptions::actuator`]): the ranked, distinct
//! designs, each whose input swings given its best drive (each given its
//! actuator's placement), lazily in rank order (the module docs of
//! [`search`](super), "With a motor", "With a linear actuator").

use super::{Design, DesignOptions, DesignReport, apart, rank_designs, sort_designs};
use crate::design::drive::{DriveOptions, best_drive};
use crate::design::{Constraints, MapOptions};
use crate::engine::Control;
use crate::error::{Error, Result};
use crate::synthesis::Task;

impl Task {
    /// The designs of `all` the report keeps: ranked and distinct, at most
    /// `top`; with a motor each whose input swings carries its drive, and
    /// one without an acceptable drive is passed over (counted in
    /// [`DesignReport::undriven`]).
    pub(super) fn finish_designs(
        &self,
        all: Vec<Design>,
        options: &DesignOptions,
        report: &mut DesignReport,
        control: &Control<'_>,
    ) -> Result<Vec<Design>> {
        let sep = options.separation(self);
        if let Some(search) = &options.actuator {
            // Each with the best clear placement of its actuator.
            let (designs, unplaced) =
                attached_designs(all, sep, options.top, control, |d, part| {
                    d.actuator = search.place(d, options, part)?;
                    Ok(d.actuator.is_some())
                })?;
            report.unplaced = unplaced;
            return Ok(designs);
        }
        match &options.motor {
            None => Ok(rank_designs(all, sep, options.top)),
            Some(motor) => {
                let (designs, undriven) = driven_designs(all, sep, options, motor, control)?;
                report.undriven = undriven;
                Ok(designs)
            }
        }
    }
}

/// The constraints a drive is checked against: the space's without the
/// envelope (the envelope applies to the four-bar over its travel; the
/// drive dyad is checked against the obstacles and the base plate over a
/// full crank turn).
fn drive_constraints(options: &DesignOptions) -> Constraints {
    Constraints {
        envelope: None,
        ..options.space.constraints()
    }
}

/// The designs of `all` best first, at least `sep` apart, at most `top`,
/// each whose input swings with its best drive under `motor`; and how many
/// were passed over for want of a drive. A drive is searched only for a
/// candidate that passes the separation test against the designs kept.
fn driven_designs(
    all: Vec<Design>,
    sep: f64,
    options: &DesignOptions,
    motor: &DriveOptions,
    control: &Control<'_>,
) -> Result<(Vec<Design>, usize)> {
    let map_options = MapOptions::new(&options.limits, &drive_constraints(options))?;
    attached_designs(all, sep, options.top, control, |d, part| {
        // A slider design is refused with a motor (DesignOptions::validate).
        let Some(linkage) = d.linkage.four_bar() else {
            return Ok(false);
        };
        if linkage.figures.input_full {
            return Ok(true);
        }
        match best_drive(linkage, &map_options, motor, options.rank_by, part) {
            Ok(drive) => {
                d.drive = Some(drive);
                Ok(true)
            }
            Err(Error::Drive(_)) => Ok(false),
            Err(e) => Err(e),
        }
    })
}

/// The designs of `all` best first, at least `sep` apart, at most `top`,
/// each that `attach` gives its drive (true); and how many `attach`
/// passed over (false). `attach` runs only for a candidate that passes
/// the separation test against the designs kept, with a control that
/// follows `control`'s cancel flag.
fn attached_designs(
    mut all: Vec<Design>,
    sep: f64,
    top: usize,
    control: &Control<'_>,
    mut attach: impl FnMut(&mut Design, &Control<'_>) -> Result<bool>,
) -> Result<(Vec<Design>, usize)> {
    sort_designs(&mut all);
    // The attached search follows the cancel flag, not the design's progress.
    let mut part = Control::new();
    if let Some(flag) = control.cancel_flag() {
        part = part.with_cancel(flag);
    }
    let mut out: Vec<Design> = Vec::new();
    let mut passed = 0;
    for mut d in all {
        if out.len() >= top {
            break;
        }
        if !out.iter().all(|o| apart(&o.linkage, &d.linkage) >= sep) {
            continue;
        }
        if control.is_cancelled() {
            return Err(Error::Cancelled {
                done: out.len(),
                total: top,
            });
        }
        if attach(&mut d, &part)? {
            out.push(d);
        } else {
            passed += 1;
        }
    }
    Ok((out, passed))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::{InputRequirement, RankBy, Space};
    use core::sync::atomic::AtomicBool;

    /// The refined designs of the example under `rank_by` (few starts).
    fn refined(options: &DesignOptions) -> Vec<Design> {
        let task = crate::example::task();
        let report = task.design(options, &Control::new()).unwrap();
        report.designs
    }

    #[test]
    fn cancelled_before_a_drive_search() {
        let options = DesignOptions {
            rank_by: RankBy::Transmission,
            starts: 4,
            limits: crate::DesignLimits {
                input: InputRequirement::Rocker,
                ..crate::DesignLimits::default()
            },
            ..DesignOptions::default()
        };
        let all = refined(&options);
        assert!(!all.is_empty() && all.iter().all(|d| !d.linkage.input_full()));
        let stop = AtomicBool::new(true);
        let control = Control::new().with_cancel(&stop);
        let r = driven_designs(all, 0.0, &options, &DriveOptions::default(), &control);
        assert!(matches!(r, Err(Error::Cancelled { done: 0, .. })), "{r:?}");
    }

    #[test]
    fn the_envelope_is_left_to_the_four_bar() {
        let space = Space {
            envelope: Some(vec![
                crate::Point2::new(-100.0, -100.0),
                crate::Point2::new(100.0, -100.0),
                crate::Point2::new(100.0, 100.0),
                crate::Point2::new(-100.0, 100.0),
            ]),
            obstacles: vec![vec![
                crate::Point2::new(50.0, 50.0),
                crate::Point2::new(60.0, 50.0),
                crate::Point2::new(55.0, 60.0),
            ]],
            ..Space::default()
        };
        let options = DesignOptions {
            space,
            ..DesignOptions::default()
        };
        let c = drive_constraints(&options);
        assert!(c.envelope.is_none());
        assert_eq!(c.obstacles, options.space.obstacles);
        assert_eq!(c.base_plate, options.space.pivots.polygon());
    }
}
