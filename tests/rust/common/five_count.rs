//! What a five-pose answer must be whatever the task: its count with
//! multiplicity, and where each slider's circle point goes. `burmester`
//! only: the integration tests use it through `common`, the fuzz checks
//! (`fuzz/src/lib.rs`) by path.

use burmester::synthesis::{BurmesterSlider, FivePositions};
use burmester::{Point2, Pose};

/// The count with multiplicity of five poses' Burmester points: the finite
/// points and the sliders (points at infinity).
pub(crate) fn total(five: &FivePositions) -> usize {
    five.burmester_points().len() + five.sliders().len()
}

/// The count, where it is 0, 2 or 4 (complex points come in pairs, and
/// the resultant has at most four real roots); otherwise a message with
/// the points, the sliders and the poses.
pub(crate) fn sound_count(five: &FivePositions) -> Result<usize, String> {
    let n = total(five);
    if n % 2 == 0 && n <= 4 {
        return Ok(n);
    }
    let poses: Vec<(f64, f64, f64)> = five
        .poses()
        .iter()
        .map(|p: &Pose| (p.position.x, p.position.y, p.angle))
        .collect();
    Err(format!(
        "count {n}: {:?} and sliders {:?} (poses {poses:?})",
        five.burmester_points(),
        five.sliders()
    ))
}

/// A slider's circle point at poses 1 to 5 (the first is the point itself),
/// whose positions must lie on one line along the slider's direction.
pub(crate) fn slider_positions(five: &FivePositions, s: &BurmesterSlider) -> Vec<Point2<f64>> {
    (1..=5)
        .map(|k| five.displace(s.circle, 1, k).expect("pose index"))
        .collect()
}
