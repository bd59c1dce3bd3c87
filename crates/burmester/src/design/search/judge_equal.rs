//! The exact judge's fast path against the reference, bit for bit: the
//! figures and size of [`Task::four_bar_figures`] are those of
//! [`Task::four_bar`]'s linkage ([`SynthesizedFourBar::size`]), and it
//! fails exactly where `four_bar` does; the search's verdicts from it are
//! those from the linkage, obstacles and envelope included.

use nalgebra::{Point2, Vector2};

use super::{DesignOptions, Exact, Verdict};
use crate::design::{DesignLimits, Space};
use crate::engine::Control;
use crate::linkage::LinkageFigures;
use crate::synthesis::{Dyad, Pole, SynthesizedFourBar, Task};

/// The integration tests' generator (splitmix64), uniform in `[0, 1)`.
#[path = "../../../../../tests/rust/common/splitmix.rs"]
mod splitmix;
use splitmix::Rng;

impl Rng {
    /// A point uniform in the square of half side `r` about `c`.
    fn point(&mut self, c: Point2<f64>, r: f64) -> Point2<f64> {
        c + Vector2::new(self.range(-r, r), self.range(-r, r))
    }
}

/// The figures as bits (a NaN transmission angle equals itself).
fn figure_bits(f: &LinkageFigures) -> (Vec<u64>, String) {
    let mut v: Vec<u64> = f.lengths.iter().map(|x| x.to_bits()).collect();
    v.push(f.min_transmission.to_bits());
    v.push(f.link_ratio.to_bits());
    let rest = format!(
        "{:?} {} {:?} {:?} {}",
        f.grashof,
        f.input_full,
        &f.modes[..],
        f.direction,
        f.one_circuit
    );
    (v, rest)
}

/// A four-bar verdict's figures.
fn four_bar_figures(v: &Verdict) -> &LinkageFigures {
    match &v.figures {
        super::Figures::FourBar(f) => f,
        super::Figures::Slider(_) => panic!("a four-bar's verdict"),
    }
}

/// A verdict as bits.
fn verdict_bits(v: &Verdict) -> (Vec<u64>, String, u16) {
    let (mut bits, rest) = figure_bits(four_bar_figures(v));
    for x in [
        v.size_ratio,
        v.shortfall,
        v.score.unwrap_or(f64::NAN),
        v.raw.unwrap_or(f64::NAN),
    ] {
        bits.push(x.to_bits());
    }
    let rest = format!(
        "{rest} {:?} {:?} {} {}",
        v.driving,
        v.driven,
        v.score.is_some(),
        v.raw.is_some()
    );
    (bits, rest, v.fails)
}

/// Tasks of three, four and five poses: a crank-rocker's coupler (so the
/// four- and five-pose curves and Burmester points exist) and random ones.
fn tasks(rng: &mut Rng) -> Vec<Task> {
    let fb =
        crate::FourBar::from_pivots(Point2::new(0.0, 0.0), Point2::new(4.0, 0.0), 1.5, 3.5, 3.0)
            .expect("the notes' crank-rocker");
    let pose = |th: f64| {
        let c = fb.solve(th, crate::AssemblyMode::Open).expect("it closes");
        let j = fb
            .joints_at(th, crate::AssemblyMode::Open)
            .expect("it closes");
        let p = j.crank_joint + crate::geom::rotate(Vector2::new(1.0, 1.5), c.theta3);
        [p.x, p.y, c.theta3]
    };
    let mut out = vec![crate::example::task()];
    for n in [3usize, 4, 5] {
        for _ in 0..3 {
            let start = rng.range(0.0, 6.0);
            let step = rng.range(0.4, 1.0);
            let poses: Vec<[f64; 3]> = (0..n).map(|k| pose(start + step * k as f64)).collect();
            out.extend(Task::from_xya(&poses));
        }
        for _ in 0..2 {
            let poses: Vec<[f64; 3]> = (0..n)
                .map(|_| {
                    [
                        rng.range(-3.0, 3.0),
                        rng.range(-3.0, 3.0),
                        rng.range(-1.5, 1.5),
                    ]
                })
                .collect();
            out.extend(Task::from_xya(&poses));
        }
    }
    out
}

/// Dyads of `t` as the search judges them (from centers, curve parameters
/// or Burmester points), near and at its poles, and things that are not
/// dyads of it or have no length.
fn candidates(t: &Task, rng: &mut Rng, n: usize) -> Vec<Dyad> {
    let c = t.poses()[0].position;
    let span = t.span();
    let mut out = Vec::new();
    let poles: Vec<Point2<f64>> = t
        .poles()
        .into_iter()
        .filter_map(|p| match p {
            Pole::Finite(q) => Some(q),
            Pole::AtInfinity { .. } => None,
        })
        .collect();
    match t.len() {
        3 => {
            for k in 0..n {
                let p = match k % 8 {
                    0 if !poles.is_empty() => poles[k / 8 % poles.len()],
                    1 if !poles.is_empty() => rng.point(poles[k / 8 % poles.len()], 1e-9 * span),
                    2 => rng.point(c, 1e3 * span),
                    _ => rng.point(c, 3.0 * span),
                };
                out.extend(t.dyad_from_center(p));
            }
        }
        4 => {
            if let Ok(four) = t.four_positions("test") {
                if let Ok(len) = four.parameter_length() {
                    for _ in 0..n {
                        out.extend(
                            four.dyad_at_parameter(rng.range(0.0, len))
                                .map(|d| d.dyad()),
                        );
                    }
                }
            }
        }
        _ => {
            if let Ok(five) = t.five_positions("test") {
                out.extend(five.burmester_points());
            }
        }
    }
    let dyads = out.len();
    for k in 0..dyads / 4 + 8 {
        let d = if dyads > 0 {
            out[k % dyads]
        } else {
            Dyad::new(c, c)
        };
        out.push(match k % 4 {
            // Not a dyad of the task.
            0 => Dyad::new(d.center, rng.point(d.circle, 0.5 * span)),
            // Nearly one (the check's tolerance).
            1 => Dyad::new(d.center, rng.point(d.circle, 1e-9 * span)),
            // No crank.
            2 => Dyad::new(d.center, d.center),
            // Far off, or not finite.
            _ => Dyad::new(
                Point2::new(f64::NAN, d.center.y),
                Point2::new(1e305, d.circle.y),
            ),
        });
    }
    out
}

#[test]
fn fast_figures_equal_the_linkages_bit_for_bit() {
    let mut rng = Rng(22);
    let (mut some, mut none, mut feasible) = (0, 0, 0);
    for t in tasks(&mut rng) {
        let dyads = candidates(&t, &mut rng, 80);
        for (i, a) in dyads.iter().enumerate() {
            // Every pair of a sample of them, the same dyad twice included.
            for c in dyads.iter().skip(i % 7).step_by(7) {
                let fast = t.four_bar_figures(a, c);
                let reference = t.four_bar(a, c).map(|l| (l.figures, l.size()));
                match (&fast, &reference) {
                    (None, Err(_)) => none += 1,
                    (Some((f, s)), Ok((g, r))) => {
                        assert_eq!(figure_bits(f), figure_bits(g), "{t:?} {a:?} {c:?}");
                        assert_eq!(s.to_bits(), r.to_bits(), "{t:?} {a:?} {c:?}");
                        some += 1;
                        feasible += usize::from(f.feasible());
                    }
                    _ => panic!(
                        "{t:?} {a:?} {c:?}: fast {:?}, reference {:?}",
                        fast.is_some(),
                        reference.map(|_| ())
                    ),
                }
            }
        }
    }
    assert!(
        some > 5000 && none > 2000 && feasible > 1000,
        "{some} linkages ({feasible} feasible), {none} refused"
    );
}

#[test]
fn verdicts_equal_the_linkages_bit_for_bit() {
    let mut rng = Rng(27);
    let obstacle = vec![
        Point2::new(1.5, 2.5),
        Point2::new(3.0, 2.5),
        Point2::new(3.0, 4.0),
        Point2::new(1.5, 4.0),
    ];
    let (mut judged, mut acceptable) = (0, 0);
    for t in tasks(&mut rng) {
        let c = t.poses()[0].position;
        let span = t.span();
        let envelope: Vec<Point2<f64>> = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
            .iter()
            .map(|&(x, y)| c + Vector2::new(x, y) * 4.0 * span)
            .collect();
        let spaces = [
            Space::default(),
            Space {
                obstacles: vec![obstacle.clone()],
                link_width: 0.05,
                envelope: Some(envelope),
                travel_samples: 16,
                ..Space::default()
            },
        ];
        let dyads = candidates(&t, &mut rng, 40);
        for space in spaces {
            let options = DesignOptions {
                space,
                limits: DesignLimits::default()
                    .with_size(20.0, 10.0 * span)
                    .expect("limits"),
                ..DesignOptions::default()
            };
            let control = Control::new();
            let exact = Exact::new(&t, &options, &control).expect("a judge");
            for (i, a) in dyads.iter().enumerate() {
                for d in dyads.iter().skip(i % 5).step_by(5) {
                    for (all, margin) in [(false, 0.01), (false, 0.0), (true, 0.01)] {
                        let fast = exact.judge_with(a, d, all, margin);
                        let reference = t.four_bar(a, d).ok().and_then(|l: SynthesizedFourBar| {
                            exact.verdict(a, d, l.figures, l.size(), all, margin)
                        });
                        assert_eq!(
                            fast.as_ref().map(verdict_bits),
                            reference.as_ref().map(verdict_bits),
                            "{t:?} {a:?} {d:?}"
                        );
                        if let Some(v) = &fast {
                            judged += 1;
                            acceptable += usize::from(v.acceptable());
                            // The linkage kept is the one judged.
                            let l = v.linkage(&t).expect("a linkage");
                            let l = l.four_bar().expect("a four-bar");
                            assert_eq!(figure_bits(&l.figures), figure_bits(four_bar_figures(v)));
                        }
                    }
                }
            }
        }
    }
    assert!(
        judged > 3000 && acceptable > 100,
        "{judged} judged, {acceptable} acceptable"
    );
}
