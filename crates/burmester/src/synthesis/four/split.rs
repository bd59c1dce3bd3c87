//! Cutting traced polylines where a label of their points changes, at
//! exactly known points.

use nalgebra::Point2;

/// The runs of `polylines` on which `label` is constant: a change between
/// two vertices cuts there, at the point of `cuts` nearest the segment
/// (within the segment's length of it), else at the segment's middle; the
/// cut point ends one run and starts the next. A vertex without a label
/// (`None`) ends the run before it.
pub(crate) fn split_by<L: PartialEq + Copy>(
    polylines: &[Vec<Point2<f64>>],
    cuts: &[Point2<f64>],
    label: impl Fn(Point2<f64>) -> Option<L>,
) -> Vec<(L, Vec<Point2<f64>>)> {
    let cut_at = |a: Point2<f64>, b: Point2<f64>| {
        let ab = b - a;
        let len = ab.norm();
        cuts.iter()
            .map(|&c| {
                let u = ((c - a).dot(&ab) / (len * len).max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
                ((a + ab * u - c).norm(), c)
            })
            .filter(|(d, _)| *d <= len)
            .min_by(|x, y| x.0.total_cmp(&y.0))
            .map_or(Point2::from((a.coords + b.coords) * 0.5), |(_, c)| c)
    };
    let mut out = Vec::new();
    for line in polylines {
        let mut run: Option<(L, Vec<Point2<f64>>)> = None;
        let mut prev: Option<Point2<f64>> = None;
        for &p in line {
            let l = label(p);
            match (&mut run, l) {
                (Some((cur, pts)), Some(l)) if *cur == l => pts.push(p),
                (Some((_, pts)), Some(l)) => {
                    let c = cut_at(prev.unwrap_or(p), p);
                    pts.push(c);
                    if let Some(done) = run.take() {
                        out.push(done);
                    }
                    run = Some((l, vec![c, p]));
                }
                (None, Some(l)) => run = Some((l, vec![p])),
                (_, None) => {
                    if let Some(done) = run.take() {
                        out.push(done);
                    }
                }
            }
            prev = Some(p);
        }
        if let Some(done) = run {
            out.push(done);
        }
    }
    out.retain(|(_, pts)| pts.len() >= 2);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cuts_at_the_given_points() {
        let line: Vec<Point2<f64>> = (0..=10).map(|i| Point2::new(i as f64, 0.0)).collect();
        let runs = split_by(&[line], &[Point2::new(4.3, 0.0)], |p| Some(p.x > 4.3));
        assert_eq!(runs.len(), 2);
        assert!(!runs[0].0);
        assert_eq!(*runs[0].1.last().unwrap(), Point2::new(4.3, 0.0));
        assert_eq!(runs[1].1[0], Point2::new(4.3, 0.0));
        assert_eq!(runs[1].1.len(), 7);
    }
}
