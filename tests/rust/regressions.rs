//! Regression tests named after fuzz findings whose input in
//! `fuzz/regressions/` does not fail on the code before the fix by itself
//! (the input was found against an intermediate state, or the check was
//! refined after it): each test here states the bug directly and fails on
//! the code before its fix. The other findings' inputs fail on the old code
//! as they are (`tests/rust/fuzz_corpus.rs` replays them all).

use burmester::{Error, FourBar, Grid, Method, Point2, Pose, Task, Vector2};

fn example() -> Task {
    burmester::example::task()
}

/// fourbar/lengths-near-f64-max-overflow-joints: a linkage whose extent
/// overflows had its output pivot at infinity.
#[test]
fn lengths_near_f64_max_are_rejected_not_overflowed() {
    let big = 1e308;
    match FourBar::placed(big, big, big, big, Point2::new(big, 0.0), 0.0) {
        Err(Error::InvalidInput(e)) => assert!(e.to_string().contains("rescale"), "{e}"),
        Ok(fb) => panic!("accepted, output pivot {}", fb.output_pivot()),
        Err(e) => panic!("{e:?}"),
    }
    // At the limit everything is finite.
    let l = FourBar::MAX_EXTENT / 5.0;
    let fb = FourBar::placed(l, l, l, l, Point2::new(l, 0.0), 0.3).unwrap();
    let o = fb.output_pivot();
    assert!(o.x.is_finite() && o.y.is_finite());
    let j = fb.joints_at(1.0, burmester::AssemblyMode::Open).unwrap();
    assert!(j.rocker_joint.x.is_finite() && j.rocker_joint.y.is_finite());
}

/// filemon_classify/grid-finer-than-ulp-misses-special-point: where the
/// grid is finer than the spacing of doubles, the sweep missed the sample
/// on `C0` (classify says boundary, the map said free).
#[test]
fn a_grid_finer_than_the_spacing_of_doubles_still_clears_c0() {
    let off = Vector2::new(9.3e7, -8.3e6);
    let t = example();
    let poses: Vec<Pose> = t
        .poses()
        .iter()
        .map(|p| Pose {
            position: p.position + off,
            angle: p.angle,
        })
        .collect();
    let t = Task::new(&poses).unwrap();
    let c0 = Point2::new(4.0, -1.0) + off;
    let f = t.filemon(c0).unwrap();
    let mut checked = 0;
    for (h, n) in [(3e-8, 15), (1e-8, 31), (1e-7, 9)] {
        let g = Grid::from_bounds(c0.x - h, c0.x + h, c0.y - h, c0.y + h, n, 5).unwrap();
        let map = f.branch_map(&g, Method::Conic);
        let mut pw = vec![false; g.len()];
        f.branch_map_pointwise_into(&g, &mut pw).unwrap();
        for j in 0..5 {
            for i in 0..n {
                let p = g.point(i, j);
                let want = f.is_branch_free(p, Method::Conic).unwrap();
                assert_eq!(map[j * n + i], want, "run kernel at {p}");
                assert_eq!(pw[j * n + i], want, "point kernel at {p}");
                checked += usize::from(!want);
            }
        }
    }
    assert!(checked > 0);
}

/// filemon_classify/margin-underflow-loses-sign: the margin map's sign is
/// the branch map, even where the distance underflows `f32` (a task of size
/// 1e-50) or `f64`.
#[test]
fn the_margin_map_keeps_its_sign_where_the_distance_underflows() {
    let k = 1e-50;
    let t = example();
    let poses: Vec<Pose> = t
        .poses()
        .iter()
        .map(|p| Pose {
            position: Point2::from(p.position.coords * k),
            angle: p.angle,
        })
        .collect();
    let t = Task::new(&poses).unwrap();
    let f = t.filemon(Point2::new(4.0 * k, -k)).unwrap();
    let g = Grid::from_bounds(-8.0 * k, 8.0 * k, -8.0 * k, 8.0 * k, 64, 48).unwrap();
    let map = f.branch_map(&g, Method::Conic);
    let margins = f.margin_map(&g);
    assert!(map.iter().any(|&b| b));
    for (m, b) in margins.iter().zip(&map) {
        assert_eq!(*m > 0.0, *b, "margin {m} vs free {b}");
    }
    for j in 0..48 {
        for i in 0..64 {
            let p = g.point(i, j);
            assert_eq!(
                f.margin(p).unwrap() > 0.0,
                f.is_branch_free(p, Method::Conic).unwrap()
            );
        }
    }
}
