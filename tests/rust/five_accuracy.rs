//! The Burmester points of near-degenerate five-pose tasks against the
//! exact points of the float task (issue 24, five38): poses at nearly one
//! position, angles `1e-9` to `1e-6` apart or half a turn, coordinates to
//! `1e22`. The exact points were computed once by
//! `tests/python/burmester_reference.py` (exact elimination, mpmath at 60
//! digits) for these very floats and are written here; the cases are
//! inputs of the `burmester_points` fuzz target
//! (`fuzz/regressions/burmester_points/inaccurate-point-rows-lost-digits-*`).
//! Before the double-double correction (`five::refine`) the library's
//! points were `3.6e-6` to `3.5e-3` of `size + d` off these, thirty to a
//! thousand times what the rounding of the inputs moves them.

use std::f64::consts::PI;

use burmester::synthesis::FivePositions;
use burmester::{Point2, Pose, Vector2};

/// Every exact point within `1e4` task sizes has a listed point within
/// `tol (size + d)` (`d` its distance from the poses' centroid), and every
/// listed point within `1e4` task sizes an exact point.
fn assert_at_exact(name: &str, poses: &[(f64, f64, f64)], exact: &[(f64, f64)], tol: f64) {
    let poses: Vec<Pose> = poses.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
    let five = FivePositions::new(&poses).unwrap_or_else(|e| panic!("{name}: {e}"));
    let size = five.size();
    let c = Point2::from(
        poses
            .iter()
            .fold(Vector2::zeros(), |a, p| a + p.position.coords / 5.0),
    );
    let listed: Vec<Point2<f64>> = five.burmester_points().iter().map(|d| d.center).collect();
    let exact: Vec<Point2<f64>> = exact.iter().map(|&(x, y)| Point2::new(x, y)).collect();
    let off = |p: &Point2<f64>, among: &[Point2<f64>]| {
        let d = (p - c).norm();
        let near = among
            .iter()
            .map(|q| (q - p).norm())
            .fold(f64::INFINITY, f64::min);
        (d, near / (size + d))
    };
    for e in &exact {
        let (d, o) = off(e, &listed);
        if d <= 1e4 * size {
            assert!(
                o <= tol,
                "{name}: exact point {e} ({} task sizes out) listed {o:e} of size + d off \
                 (listed {listed:?})",
                d / size
            );
        }
    }
    for p in &listed {
        let (d, o) = off(p, &exact);
        if d <= 1e4 * size {
            assert!(
                o <= tol,
                "{name}: listed point {p} {o:e} of size + d off every exact point"
            );
        }
    }
}

/// The task is refused as not resolved within rounding: the points
/// computed with another pose as the reference pose disagree
/// (`FivePositions::new`'s check). `_exact`: the float task's exact points
/// (mpmath), for the record.
fn assert_refused(name: &str, poses: &[(f64, f64, f64)], _exact: &[(f64, f64)]) {
    use burmester::{DegenerateError, Error};
    let poses: Vec<Pose> = poses.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
    match FivePositions::new(&poses) {
        Err(e @ Error::Degenerate(DegenerateError::UnresolvedBurmesterPoints { .. })) => {
            assert!(
                e.to_string()
                    .contains("another pose as the reference pose disagree"),
                "{name}: {e}"
            );
        }
        other => panic!("{name}: refused expected, got {other:?}"),
    }
}

/// Poses at nearly one position or angle leave the linear form's rows few
/// digits; the points are now at the float task's exact points to `1e-9`
/// of `size + d` (measured after: `1e-12` or better; one case to `1e-6`,
/// where the rounding of the inputs moves the points by `1e-4`). Before:
/// the worst point off by the figure in each case's comment.
#[test]
fn issue24_near_degenerate_five_pose_points_are_the_exact_ones() {
    // Two pairs of poses of one angle, the far point 6.9e3 task sizes out
    // (before: 3.6e-6 off, rounding moves it 4.6e-8).
    assert_at_exact(
        "01fea128 moved",
        &[
            (-0.17895815644286256, 1.1743540492963611, -102.5322176535898),
            (-0.1628858178191565, 1.0583740553666923, -99.390625),
            (-0.09418768743308656, 0.5626398046333166, -99.390625),
            (
                -0.07761983797434135,
                0.44308414290660647,
                -102.5322176535898,
            ),
            (0.016825797724724964, -0.23844730758840862, -99.290625),
        ],
        &[
            (-0.13205197597809312, 0.8091087117264277),
            (0.01682579772472587, -0.23844730758841579),
            (5819.264793138027, 807.2526470440084),
            (22451828154677.457, 3111341642612.5425),
        ],
        1e-9,
    );
    // Angles 4e-13 to 1e-6 apart, two poses 1e-12 apart (before: 3.3e-4
    // off, rounding moves them 7.2e-6).
    assert_at_exact(
        "1300009f",
        &[
            (0.09999999999999913, 2.166e-05, -4.2e-13),
            (-8.632812277955395e-16, 9.999999999999999e-14, 1.0083e-05),
            (9.913671875e-14, -9.999999999999999e-06, 1e-06),
            (-2.40086330625e-12, 1e-07, -6.16945639022682e-45),
            (9.913671875e-14, 9.999999999999999e-14, 1e-09),
        ],
        &[
            (-5.364716359190801, -0.0032258667399695557),
            (2.9350557053729465, -0.0007525312313490338),
        ],
        1e-9,
    );
    // Every pair of angles within 3e-7, three positions within 5e-9 task
    // sizes (before: 2.5e-3 off, rounding moves them 3.6e-7), both frames.
    assert_at_exact(
        "18bd80a0",
        &[
            (0.04671026484375, -6.026562500000001e-07, -1.1523828125e-07),
            (0.0467116151171875, -602.3828125, 7.558593750000004e-09),
            (0.046711012734375, -602.3828125, 7.523437500000006e-09),
            (
                0.046711007734375004,
                -4.7476562499999997e-07,
                1.3552343750000001e-07,
            ),
            (
                0.0467116903515625,
                7.507031250000001e-07,
                7.528515625000001e-08,
            ),
        ],
        &[
            (-0.4753568671702513, 256623.02679723187),
            (-12016.694201389932, 8267.33602477852),
            (-0.5095774802242872, -256928.08808006774),
            (5288430.009934729, 8267.703759246928),
        ],
        1e-9,
    );
    assert_at_exact(
        "18bd80a0 moved",
        &[
            (
                4.6710264843750004e-05,
                6.026562500000001e-10,
                1.1523828125e-07,
            ),
            (4.67116151171875e-05, 0.6023828125, -7.558593750000004e-09),
            (4.6711012734375004e-05, 0.6023828125, -7.523437500000006e-09),
            (
                4.6711007734375003e-05,
                4.74765625e-10,
                -1.3552343750000001e-07,
            ),
            (
                4.67116903515625e-05,
                -7.507031250000001e-10,
                -7.528515625000001e-08,
            ),
        ],
        &[
            (-0.000509577480224172, 256.92808808006777),
            (-12.01669420128064, -8.267336024719919),
            (-0.0004753568671703828, -256.62302679723183),
            (5288.43000998159, -8.26770375918833),
        ],
        1e-9,
    );
    // Coordinates to 1e22, poses half a turn apart at one position
    // (before five38: 3.5e-3 off; rounding moves them 9.8e-5 of `size +
    // d`, so that the rotations' own rounding in `f64` leaves `1.6e-7`).
    // Since stop 39 the answer is checked with each pose as the reference
    // pose (`FivePositions::new`): points that the rounding moves by `1e-4`
    // of `size + d` differ by more than `BURMESTER_AGREEMENT` between those
    // computations, and the task is refused as not resolved within
    // rounding (the exact points below, for the record).
    assert_refused(
        "47915008",
        &[
            (-9984765.625, 9.99999999999999e+21, PI),
            (-9984765.625, 9.99999999999999e+21, 0.0),
            (-9984765.625, -1010397656.25, -2.5345e-05),
            (-255639984765.625, 31405528879.64793, PI),
            (-9984765.62499778, 2349989602343.75, -0.1),
        ],
        // exact:
        &[
            (-9.555049580013288e+22, 5.000000001228723e+21),
            (1.7472107159331796e+18, 5.000000000007422e+21),
            (-127795103087.19376, 2356982818460.467),
            (9.669500983209674e+22, 4.999999998771537e+21),
        ],
    );
    // Four poses within 8e-9 task sizes, angles 1e-8 to 4e-6 apart (before:
    // 2.4e-4 off, rounding moves them 1.6e-5).
    assert_at_exact(
        "c25ed04a",
        &[
            (-3.90625e-06, -3.90625390625e-06, -6.400390625e-08),
            (-6.20078125e-08, -3.90625e-12, -3.906257812499999e-06),
            (-1e-09, -3.906257812499999e-06, -3.896011718749999e-06),
            (-3.90625e-06, -3.90625390625e-06, 0.0),
            (0.09938671875, 839.84375, -1.953125e-05),
        ],
        &[
            (-92831.73662582487, -1944.750177479803),
            (112396.54106542455, 2350.136468498708),
        ],
        1e-9,
    );
    // Angles 1e-12 apart and equal, the far point 6.2e3 task sizes out
    // (before: 1.7e-3 off, rounding moves it 9e-6).
    assert_at_exact(
        "43b1a852 moved",
        &[
            (
                8.200174312302017e-06,
                5.723631169776542e-06,
                -2.532217653589793,
            ),
            (
                1.1531332967431943e-10,
                8.048743146865681e-11,
                0.6093749999999998,
            ),
            (1.7981180089425583e-05, -2.5761164622748646e-05, -0.390625),
            (5.722730676560489, -8.200631353960087, -2.532217653589793),
            (
                8.990647701375424e-06,
                -1.2880542067660126e-05,
                0.6093750000013974,
            ),
        ],
        &[
            (-40594.33276998471, -28334.396265315743),
            (2.364460459836762e-05, -2.513924559558056e-05),
        ],
        1e-9,
    );
}

/// A Burmester point on a double root of the elimination at the curves'
/// common asymptote (the line from `Q` along it holds the point and a
/// point at infinity, within rounding): its direction is within the root's
/// rounding of the asymptote (`7.5e-9` rad in `b56c8054`), the linear
/// parts' roots there agree only to `5e-7` of themselves, and the point
/// was listed as a second slider (2 points and 2 sliders for 4 real points
/// within `1e4` task sizes: the missing one 16, 1.6e3, 0.95 and 0.37 task
/// sizes out, well conditioned: rounding moves it `6e-12`, `1.4e-5`,
/// `2e-12`, `3e-10` of `size + d`). Now 3 points and one slider, the
/// points at the exact reference's to `1e-9` of `size + d`.
#[test]
fn issue24_a_point_on_the_asymptote_s_double_root_is_not_a_slider() {
    type Case = (&'static str, [(f64, f64, f64); 5], &'static [(f64, f64)]);
    let cases: [Case; 4] = [
        (
            "b56c8054 moved",
            [
                (-1.1116372028367825, 0.22236801222759395, -100.000000255),
                (-0.99265625, -2.0146029634113193e-47, -100.0),
                (-0.9875925935889024, -0.008623188722876839, -101.0),
                (-0.9875925935889024, -0.008623188722876839, -100.0),
                (-0.99265625, 0.0, -101.0),
            ],
            &[
                (-4.054176990902723, 5.213637929687902),
                (1.8608742337628514, 1.6698344882755198),
                (19859.415019926408, -33821.41867477491),
                (6.629856127174378e+49, 3.8931437733652523e+49),
            ],
        ),
        (
            "3559e72f moved",
            [
                (-14.20792090489338, 99.302897906735, 11.137686403589793),
                (-14.163425291041294, 98.99190564901976, 7.99609375),
                (-13.852432948497562, 99.03640137602717, 7.99609375),
                (-14.518913148445206, 99.25840219389102, 11.137686403589793),
                (-855.5946232087505, -21.397209310634622, 15.99609375),
            ],
            &[
                (-3947414889261.8066, 27589521196025.254),
                (-855.7969077842962, -21.2674722304996),
                (-14.185673073223212, 99.14740178140845),
                (152609.77998016667, -1066629.9027586754),
            ],
        ),
        (
            "0be74192 moved",
            [
                (
                    0.0004172855990027693,
                    -0.09848184965262084,
                    -99.390625000001,
                ),
                (-2.2796875000000007e-11, -0.09939062504282421, -99.390625),
                (
                    -2.2796875000000007e-11,
                    -0.09939062504282421,
                    -102.5322176535898,
                ),
                (-0.00013260612399717628, -0.09943977401966458, -99.290625),
                (
                    0.0004172855990027693,
                    -0.09848184965262084,
                    -102.5322176535898,
                ),
            ],
            &[
                (-0.0003366224460190667, -0.09868586597464274),
                (-0.0004576223265180563, -0.10038724669932308),
                (0.00020864278810279536, -0.09893623734772256),
                (1827125227.091419, -838967576.3676437),
            ],
        ),
        (
            "90719df8 moved",
            [
                (9.990491761965344e-09, 0.0031250004359742807, 0.043609375),
                (-3.9042391305950844e-17, 0.003124999999999999, 0.043609375),
                (
                    -3.9042391305950844e-17,
                    0.003124999999999999,
                    -3.097983278589793,
                ),
                (
                    9.990492579905123e-09,
                    0.0031250004359555366,
                    -3.097983278589793,
                ),
                (4.365222758844172e-09, 0.0031248999651974055, 0.043599344),
            ],
            &[
                (-0.009972564898432923, 0.0026898174018923147),
                (4.995292987150462e-09, 0.0031250002179845013),
                (7.177904795774451e-09, 0.0031249502005738328),
                (463.8988996771687, -10630.61929282818),
            ],
        ),
    ];
    for (name, poses, exact) in cases {
        assert_at_exact(name, &poses, exact, 1e-9);
        let q: Vec<Pose> = poses.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
        let five = FivePositions::new(&q).unwrap();
        assert_eq!(five.sliders().len(), 1, "{name}: {five:?}");
    }
}

/// A double root of the elimination that is one simple real point: Newton's
/// method converges to the same point to rounding from both sides, and
/// the root's other multiplicity is a complex pair whose directions from
/// the elimination's pole lie within rounding of the point's. Each real
/// point was listed twice (4 points where the exact reference has 2 real
/// ones and a complex pair; `708d41e1`: 2 of 4 near ones a ghost double).
/// Now each once, at the reference's points to `1e-9` of `size + d`.
#[test]
fn issue24_a_simple_point_on_a_double_root_is_listed_once() {
    type Case = (&'static str, [(f64, f64, f64); 5], &'static [(f64, f64)]);
    let cases: [Case; 2] = [
        (
            "68561dbd moved",
            [
                (-5.641550092355349, 8.257294505795791, 0.609375),
                (-2.843567552564649e-15, 4.112738334986467e-15, 0.609400444),
                (82000.5899897234, 57235.50682345072, 0.609374999999),
                (-2.843567552564649e-15, 4.112738334986467e-15, 0.60937525444),
                (0.17981062689681115, -0.25761246566474616, 0.709375),
            ],
            &[
                (4.672880654977232, 3.193379813450958),
                (41284.12446942171, 28212.202143504615),
            ],
        ),
        (
            "09c359d8 moved",
            [
                (-7.43931599e-11, -7.34375e-10, 0.0),
                (-7.43931599e-11, -7.34375e-10, -1.0),
                (-7.438434181469281e-11, -7.318405e-10, -PI),
                (-7.439062499999999e-11, -7.34303e-10, 0.0),
                (0.000999999925609375, -7.34375e-10, -6.283185307176395),
            ],
            &[
                (-7.443254470974931e-11, -7.343516482218371e-10),
                (0.000499999925567178, -1.760420658183394e-05),
            ],
        ),
    ];
    for (name, poses, exact) in cases {
        assert_at_exact(name, &poses, exact, 1e-9);
        let q: Vec<Pose> = poses.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
        let five = FivePositions::new(&q).unwrap();
        let pts = five.burmester_points();
        for (i, p) in pts.iter().enumerate() {
            assert!(
                pts[..i].iter().all(|q| q.center != p.center),
                "{name}: {} listed twice ({pts:?})",
                p.center
            );
        }
    }
    // `708d41e1`'s moved frame (two points `1e12` task sizes out, two near
    // ones `0.068` apart): listed once since five38. With the check of
    // `FivePositions::new` alone (xcheck39) another reference pose disagreed
    // and the task was refused; with five39's fixes every reference pose
    // finds the same points, and they are the exact ones.
    let (name, poses, exact): Case = (
        "708d41e1 moved",
        [
            (1.0398711198593622, 0.04068798379594484, 0.04069921874509375),
            (0.04069921874609375, -3.90625e-12, 0.04069921874609375),
            (0.04069921874609375, -3.90625e-12, -3.1008934348436994),
            (1.0398711198593622, 0.04068798379594484, -3.1008934348436994),
            (0.035165652949314, 0.1358873785474983, 0.04069921874609375),
        ],
        &[
            (-958485168172.8483, -1039861241971.677),
            (0.5375183864043381, 0.08828768117172157),
            (0.5402851693027059, 0.020343991896143502),
            (1039861241972.5303, -958485168173.5725),
        ],
    );
    assert_at_exact(name, &poses, exact, 1e-9);
    let q: Vec<Pose> = poses.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
    let pts = FivePositions::new(&q).unwrap().burmester_points().to_vec();
    for (i, p) in pts.iter().enumerate() {
        assert!(
            pts[..i].iter().all(|q| q.center != p.center),
            "{name}: {} listed twice",
            p.center
        );
    }
}

/// A badly conditioned choice of the shared poses read a complex pair
/// (`1.2` task sizes off the real plane) as a real double point: its
/// estimate passed the crank-length check (the circle point far out makes
/// the spread small relative to the crank) though Newton's method from it
/// converged to another point, `4e-3` of `size + d` away. Such an estimate
/// is no point now (`polish`), that choice is not clean, and a better one
/// is taken. Before: `2b069ec9`'s moved frame listed a ghost double point
/// `0.87` of `size + d` off every exact point beside its two real points.
#[test]
fn issue24_a_ghost_double_point_whose_newton_iteration_leaves_is_not_listed() {
    let poses = [
        (1e-15, 0.0, -4.5e-13),
        (1e-15, -0.001, -2.0 * PI),
        (-1.7172e-14, 3e-24, 2.5444e-5),
        (1e-15, -0.001, 25.399),
        (-1.7172e-14, 1.7172e-14, -1e-6),
    ];
    assert_at_exact(
        "2b069ec9 moved",
        &poses,
        &[
            (-0.0004546175368759968, -0.0005000004057574524),
            (0.007499767702094085, -0.0004004133887599345),
        ],
        1e-9,
    );
    let five = FivePositions::new(
        &poses
            .iter()
            .map(|&(x, y, a)| Pose::new(x, y, a))
            .collect::<Vec<_>>(),
    )
    .unwrap();
    assert_eq!(five.burmester_points().len(), 2, "no point listed twice");
}

/// `FivePositions::new` checks its answer with each pose in turn as the
/// reference pose and refuses the task where the five computations
/// disagree. Fuzz finding `73db7229` (three positions within `1e-7` in a
/// task of size `5e4`, two poses at one position): as given, the four
/// exact points (mpmath, `tests/python/burmester_reference.py`) to `1e-6`
/// of `size + d` (the rounding of the near positions moves them by about
/// `2e-7`); moved to another frame, before stop 39, a real double point
/// where the exact task has two simple points (`6.36, -10.0` missing,
/// `2189.38, -4508.27` listed twice): now refused, or the exact points.
#[test]
fn issue24_a_five_pose_answer_that_another_reference_pose_contradicts_is_refused() {
    let given = [
        (3.141592653589793e-7, 1e-7, PI),
        (0.0, 100000.0, 0.0),
        (0.0, -1e-8, -0.00018938),
        (0.0, 100000.0, -1.0),
        (2.35e-5, -2.51e-8, -0.01),
    ];
    assert_at_exact(
        "73db7229",
        &given,
        &[
            (-84275.73975871856, 49999.99822779228),
            (31.503378820671912, 50000.00000005012),
            (-0.000990562957200038, -0.0005410660252134962),
            (29666.30044898902, 49999.99937704335),
        ],
        1e-6,
    );
    let moved = [
        (6.360937532632469, -9.9976562453008, 3.592782346410207),
        (4366.72575243026, -9009.287554943017, 6.734375),
        (6.360937499563964, -9.997656249100071, 6.73456438),
        (4366.72575243026, -9009.287554943017, 7.734375),
        (6.360939613738675, -9.997655223055448, 6.744375),
    ];
    let exact = [
        (-5397.674867449548, -8184.372150064382),
        (6.360824763915346, -9.997650750058508),
        (2189.378424196906, -4508.268943916663),
        (4856.29969741851, -3216.0836228681515),
    ];
    let q: Vec<Pose> = moved.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
    match FivePositions::new(&q) {
        Ok(_) => assert_at_exact("73db7229 moved", &moved, &exact, 1e-6),
        Err(_) => assert_refused("73db7229 moved", &moved, &exact),
    }
}

/// The check refuses no ordinary task: 400 random five-pose tasks (positions
/// in a square of side 10, angles within 3 rad; a fixed seed) are all
/// answered, each point's five positions on a circle about its center
/// (100,000 such tasks measured in release, none refused:
/// `FIVE_RANDOM_TASKS=100000 cargo test --release --test five_accuracy
/// refuses_no_ordinary_task`). The exact count certificate of
/// `FivePositions::new` is in the check since stop 42.
#[test]
fn issue24_the_reference_pose_check_refuses_no_ordinary_task() {
    let n: usize = std::env::var("FIVE_RANDOM_TASKS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(400);
    let mut s: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut rnd = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..n {
        let poses: Vec<Pose> = (0..5)
            .map(|_| Pose::new(rnd() * 10.0 - 5.0, rnd() * 10.0 - 5.0, rnd() * 6.0 - 3.0))
            .collect();
        let five = FivePositions::new(&poses).unwrap_or_else(|e| panic!("{poses:?}: {e}"));
        for d in five.burmester_points() {
            let r: Vec<f64> = poses
                .iter()
                .map(|p| {
                    let (sn, c) = (p.angle - poses[0].angle).sin_cos();
                    let v = d.circle - poses[0].position;
                    let at = p.position + Vector2::new(c * v.x - sn * v.y, sn * v.x + c * v.y);
                    (at - d.center).norm()
                })
                .collect();
            let spread = r.iter().fold(0.0f64, |m, x| m.max((x - r[0]).abs()));
            assert!(
                spread <= 1e-8 * (1.0 + r[0]),
                "{poses:?}: {d:?} radii {r:?}"
            );
        }
    }
}

/// [`assert_at_exact`] to `1e-9` for the tasks of the family below (poses
/// and exact points as arrays), and the task's answer.
fn assert_family(name: &str, poses: [[f64; 3]; 5], exact: [[f64; 2]; 4]) -> FivePositions {
    let tuples = poses.map(|[x, y, a]| (x, y, a));
    assert_at_exact(name, &tuples, &exact.map(|[x, y]| (x, y)), 1e-9);
    FivePositions::new(&tuples.map(|(x, y, a)| Pose::new(x, y, a))).unwrap()
}

/// Poses `(1, 0, 1e-12)`, `(0, 0, 0)`, `(0, 0, pi)`, `(1, 0, pi)` and a
/// fifth of angle 0 (two half-turn pairs at two positions, poses of nearly
/// one angle with their poles `1e12` task sizes out, `P13 = P24`): a choice
/// of the shared poses whose `Q` is a Burmester point (`Q = P34 = (0.5,
/// 0.25)` in `803d9c63`, or at the coincident poles next to `Q = P13` in
/// `0c09dd2e`'s moved frame) sees it along a double root of the resultant
/// that is also the direction of a shared pole `1e12` task sizes out. The
/// far root matched the pole only to `1e-4` of its distance (its rounding:
/// the curves' cubic parts are `1e-13`), so the pole was listed as a point
/// (a ghost double, or a single ghost beside the point missing), and the
/// point at `Q` (a root of each quadratic within `2e-5` of `Q`, on either
/// side) was lost. Now the far root matches the pole within its rounding,
/// and the point at `Q` is a candidate that `polish` finishes. Exact points
/// from `tests/python/burmester_reference.py`; both frames of each (the
/// far points, `1.8e12` task sizes out, are not compared). Before:
/// `803d9c63` as given missed `(0.5, 0.25)`, `0c09dd2e` moved the point
/// at the coincident poles.
#[test]
fn issue24_a_point_at_q_along_a_far_pole_s_direction_is_found() {
    type Case = (&'static str, [[f64; 3]; 5], [[f64; 2]; 4]);
    let cases: [Case; 4] = [
        (
            "803d9c63",
            [
                [1.0, 0.0, 1e-12],
                [0.0, 0.0, 0.0],
                [0.0, 0.0, PI],
                [1.0, 0.0, PI],
                [0.0, 0.5, 0.0],
            ],
            [
                [-999999999999.5, 999999999999.875],
                [0.5, 0.25],
                [0.5000000000000625, -1.25e-13],
                [1000000000000.5, 1000000000000.375],
            ],
        ),
        (
            "803d9c63 moved",
            [
                [0.7422497254585013, 0.5707327554692566, 0.734374999999],
                [0.0, -0.09939062500390625, 0.734375],
                [0.0, -0.09939062500390625, -2.407217653589793],
                [0.7422497254585013, 0.5707327554692566, -2.407217653589793],
                [0.33506169023658144, -0.4705154877331569, 0.734375],
            ],
            [
                [0.3711248627292133, 0.23567106523280987],
                [0.5386557078475414, 0.05010863386804988],
                [-72127940579.1655, -1412404350745.0813],
                [1412404350746.0322, -72127940579.49553],
            ],
        ),
        (
            "0c09dd2e",
            [
                [1.0, 0.0, 1e-12],
                [0.0, 0.0, 0.0],
                [0.0, 0.0, PI],
                [1.0, 0.0, PI],
                [0.0, -0.136, 0.0],
            ],
            [
                [-999999999999.5, 999999999999.7161],
                [0.499999999999983, -1.25e-13],
                [0.5, -0.068],
                [1000000000000.5, 1000000000000.2161],
            ],
        ),
        (
            "0c09dd2e moved",
            [
                [51.33120315111327, 54.04068798379985, 0.04069921874509375],
                [50.33203125, 54.0, 0.04069921874609375],
                [50.33203125, 54.0, -3.1008934348436994],
                [51.33120315111327, 54.04068798379985, -3.1008934348436994],
                [50.32649768420322, 54.1358873785514, 0.04069921874609375],
            ],
            [
                [-958485168122.5616, -1039861241917.6951],
                [50.828850417658245, 54.088287681175636],
                [50.831617200556614, 54.02034399190005],
                [1039861242022.8218, -958485168119.5608],
            ],
        ),
    ];
    for (name, poses, exact) in cases {
        let five = assert_family(name, poses, exact);
        // Four real points, none at infinity (the two far ones listed too).
        assert_eq!(
            (five.burmester_points().len(), five.sliders().len()),
            (4, 0),
            "{name}"
        );
    }
}

/// The same family with a fifth pose turned (`(0, -0.1, -0.1)` in
/// `b91364fa`, `(0, -0.02561, -0.02561)` in `d03cbd5e`): the first clean
/// choice of the shared poses had its `Q` at the coincident poles
/// (`P13 = P24`), listed that point, and had lost a pair of others (an
/// even count: 2 of the 3 near points). Where the answer is such a blind
/// choice, the choices are now tried again with the blind ones last, and
/// the answer taken where it lists more near points. Exact points from
/// `tests/python/burmester_reference.py` (the far point, `3.3e12` task
/// sizes out, is listed as a slider or a point: not compared). Before:
/// `(0.4981936335433019, 2.06169179491692)` missing in `b91364fa`'s moved
/// frame, `(0.5, -0.012805)` in `d03cbd5e` as given.
#[test]
fn issue24_a_blind_choice_that_lost_a_pair_is_not_the_answer() {
    type Case = (&'static str, [[f64; 3]; 5], [[f64; 2]; 4]);
    let cases: [Case; 2] = [
        (
            "b91364fa moved",
            [
                [0.9995117584851364, 2.027338663985326, 0.031249999999],
                [0.0, 1.99609375, 0.03125],
                [0.0, 1.99609375, -3.110342653589793],
                [0.9995117584851364, 2.027338663985326, -3.110342653589793],
                [-0.003124491398532608, 2.0960449258485134, 0.13125],
            ],
            [
                [-0.9961778293686254, 1.9649530552263033],
                [0.4981936335433019, 2.06169179491692],
                [0.49975587924255593, 2.0117162069927876],
                [62489909523.88537, -1999026125774.1062],
            ],
        ),
        (
            "d03cbd5e",
            [
                [1.0, 0.0, 1e-12],
                [1e-12, 0.0, 0.0],
                [0.0, 0.0, PI],
                [1.0, 0.0, PI],
                [0.0, -0.02561, -0.02561],
            ],
            [
                [1.5001093203816207, 1999999999997.5],
                [-0.9997813664067418, 9.99672073512103e-13],
                [0.5000000000002479, -1.476398308376112e-11],
                [0.50000000000025, -0.012805000004878239],
            ],
        ),
    ];
    for (name, poses, exact) in cases {
        assert_family(name, poses, exact);
    }
}

/// A far root read both as a finite Burmester point and as a slider
/// (five40, fuzz finding `4de1b986`: poses 2 to 4 within `2e-12` task sizes
/// of one position, poses 1 and 5 at another `9e4` out, angles in two
/// groups `1e-7` apart). As given, the choices that see all three near
/// points listed the far fourth twice (a point `8.8e5` task sizes out and
/// a slider along its direction: five in all) and were skipped; the answer
/// was a choice that lost the near point `(-45040.68, 45113.28)` with the
/// far one (2 points). Now refused (the reference poses disagree) or the
/// exact points; moved, the exact points (three near ones to `1e-6` of
/// `size + d`, as before).
#[test]
fn issue24_a_far_point_read_also_as_a_slider_does_not_lose_a_pair() {
    let given = [
        (-3.2003906250000004e-8, 90226.5625, 3.90625e-6),
        (4.63671875e-9, -8.800000000000001e-8, -8.78515625e-8),
        (
            -8.77265625e-8,
            -1.8021484375000002e-7,
            -3.2367187500000006e-8,
        ),
        (
            -1.8021875000000003e-7,
            5.4273437500000004e-8,
            -0.09246484375,
        ),
        (-3.2003906250000004e-8, 90226.5625, -0.09246493611328124),
    ];
    let exact = [
        (-47604270188.52355, 45115.10528246511),
        (-45040.68374890675, 45113.28125178833),
        (0.04497046905326175, 45077.33080565351),
        (6.831210875664416e-05, 34.28581250138755),
    ];
    let q: Vec<Pose> = given.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
    match FivePositions::new(&q) {
        Ok(_) => assert_at_exact("4de1b986", &given, &exact, 1e-6),
        Err(_) => assert_refused("4de1b986", &given, &exact),
    }
    let moved = [
        (75.63966415745165, -49.04591390347451, 0.99608984375),
        (
            -0.0923632813213427,
            -9.246479105781268e-5,
            0.9960938378515625,
        ),
        (
            -0.09236328144895091,
            -9.246481845668193e-5,
            0.9960937823671875,
        ),
        (-0.09236328130240962, -9.246502355472336e-5, 1.08855859375),
        (75.63966415745165, -49.04591390347451, 1.0885586861132812),
    ];
    let exact = [
        (-25876937.5914632, -39956859.80609808),
        (-0.0635853080657807, -0.018729667864098565),
        (13.29020214697899, -62.32808267008591),
        (37.74349973186493, -24.503423308421628),
    ];
    assert_at_exact("4de1b986 moved", &moved, &exact, 1e-6);
}

/// A real root of the resultant that the search of its window drops
/// (five40): where the resultant's roots are all simple, a window whose
/// ends lie within the resultant's rounding band and that finds no root
/// keeps the root found there first (a change of sign of the accurate
/// value beyond its band). `957b29d3` moved (poses 1 and 2 `6e-12` rad
/// apart at one position) and `b916f313` as given (poses 1 and 2 `1e-8` rad
/// apart at one position; both points `89` task sizes out): the best
/// conditioned choice listed no point, three of its four real roots
/// dropped so, where the exact task has two real points (and a complex
/// pair `0.6` and `620` task sizes off the real plane). Fails before: no
/// points.
#[test]
fn issue24_a_root_that_its_window_cannot_place_is_kept() {
    assert_at_exact(
        "957b29d3 moved",
        &[
            (-2.0641580041210355, -3.276603432641337, 0.9960938409960938),
            (-2.0641580041210355, -3.276603432641337, 0.996093841),
            (
                0.8985753370371314,
                -0.5414617157171036,
                9.099609377116735e-8,
            ),
            (-2.674765096206945, 2.959454614345093, 0.9960938420000001),
            (
                1.4400370527476776,
                0.2946136213242747,
                5.1999999972629496e-8,
            ),
        ],
        &[
            (0.47927865508804735, 2.1605282432750896),
            (-1.0289467892756383, -7.162923543047891),
        ],
        1e-6,
    );
    assert_at_exact(
        "b916f313",
        &[
            (-3.90625e-6, -3.90625e-12, -3.90625e-12),
            (-3.90625e-6, -3.90625e-12, 1.024609375e-8),
            (-3.90625e-12, 0.00099609374609375, -3.84225390625e-6),
            (1996.09375, -0.99609375, -3.8422578125e-6),
            (90.0, 13000.0, 0.0009960937421874998),
        ],
        &[
            (141803.45364794217, 939877.1955395764),
            (-142600.50285724518, -913318.0147288884),
        ],
        1e-6,
    );
}

/// Fuzz findings `33fcbf9c` and `2461959a`, each in its moved frame
/// (angles `100` and `65656` rad, known to `1.4e-14` and `1.5e-11`): the
/// bound of the angles' rounding, from the magnitudes of the terms,
/// called the resultant of every well conditioned choice of the shared
/// poses zero within rounding (`1e-5` against `3e-8` in `33fcbf9c`, where
/// the angles' rounding moves it by `1.4e-15`), and the answer came from a
/// badly conditioned choice: no points where the exact task has two
/// (`33fcbf9c`: four poses nearly rotations about one point, a complex pair
/// `2e-3` off the real plane), two of four (`2461959a`). The angles'
/// rounding is now measured (each angle moved alone). Exact points:
/// `tests/python/burmester_reference.py` (mpmath). Fails before: no points;
/// the point `(-8.6e16, -9.6e15)` missing.
#[test]
fn issue24_angles_known_to_their_rounding_do_not_skip_every_good_choice() {
    assert_at_exact(
        "33fcbf9c moved",
        &[
            (2.688393327041083, 1.9084406514770993, -102.7470614035898),
            (-1.2101307279109845, -3.2701504594429127, -99.60546975),
            (-2.4928766289830095, -0.4396138834149905, -100.60546875),
            (2.6943628476454182, 1.916386853216854, -102.7470614035898),
            (-1.2100898071492252, -3.2701941934657177, -99.605451498),
        ],
        &[
            (0.4996073932088858, -0.4946992382217919),
            (0.7391314461864061, -0.6808573556362969),
        ],
        1e-6,
    );
    assert_at_exact(
        "2461959a moved",
        &[
            (330457.4099037527, -66962971.01374104, 65656.250001),
            (2462350.512538664, -66736979.696875334, 65656.221999),
            (316380.5643384256, -66963426.06423548, 65656.225327),
            (104939064316461.33, -994478720754866.8, 65656.226959),
            (104939064316461.33, -994478720754866.8, 65656.225327),
        ],
        &[
            (-8.635743591294869e16, -9615358589019186.0),
            (22250444.514649183, -253663633.98339164),
            (52476485085244.37, -497238663825545.94),
            (55292115152042.266, -496941817716133.2),
        ],
        1e-6,
    );
}

/// A five-pose answer that lists a point twice where another reference
/// pose lists it once is refused (`FivePositions::new`'s check; five41).
/// Fuzz findings `3ef91cde` and `d984b3d2`, each in its moved frame: both
/// points listed twice (a complex pair `0.25` task sizes off the real
/// plane, and two points at infinity, read as double points and moved
/// onto the simple ones by the refinement) where the exact task has each
/// once (mpmath, `tests/python/burmester_reference.py`); the other
/// reference poses list each once. The check compared only points apart
/// from the others, so a double point passed it. Fails before: four points,
/// each exact one twice.
#[test]
fn issue24_a_double_point_that_another_reference_pose_lists_once_is_refused() {
    type Case = (&'static str, [(f64, f64, f64); 5], [(f64, f64); 2]);
    let cases: [Case; 2] = [
        (
            "3ef91cde moved",
            [
                (-3.3907279326441238, -0.09944792341978526, -0.0997646929375),
                (-2.39570352897566, -0.19904788792168798, -0.0997656929375),
                (-3.390731058615301, -0.09944761051628546, 3.041826960652293),
                (-3.390730959015024, -0.09944661548875583, 3.041826960652293),
                (-3.3907309590140287, -0.09944661548885543, 0.9002343070625),
            ],
            [
                (-3.3907296824220903, -0.09944963298278792),
                (-2.893216957590906, -0.14924439066009987),
            ],
        ),
        (
            "d984b3d2 moved",
            [
                (
                    1.5068567133818246e-5,
                    -0.0006332161533354372,
                    -64.39162109375,
                ),
                (
                    1.5171517817306995e-5,
                    -0.0006332731578474464,
                    -64.39062487228125,
                ),
                (-3.893928431355109, -1.047530166343804, -64.390625),
                (-923.2326123968348, 73283.2586258713, -64.390625),
                (1.506836820337093e-5, -0.0006332834262157036, -64.390625),
            ],
            [
                (-9752.13698791159, 36265.96943053909),
                (-69.19089523121255, 257.8095375703168),
            ],
        ),
    ];
    for (name, poses, exact) in cases {
        let q: Vec<Pose> = poses.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
        match FivePositions::new(&q) {
            Ok(f) => {
                // Each exact point once: no point listed twice.
                let pts = f.burmester_points();
                for (i, p) in pts.iter().enumerate() {
                    assert!(
                        pts[i + 1..].iter().all(|d| d.center != p.center),
                        "{name}: {} listed twice ({:?})",
                        p.center,
                        pts.iter().map(|d| d.center).collect::<Vec<_>>()
                    );
                }
                assert_at_exact(name, &poses, &exact, 1e-6);
            }
            Err(_) => assert_refused(name, &poses, &exact),
        }
    }
}

/// An answer that lacks a Burmester point at coincident poles which no
/// choice of the shared poses lists is refused (five42). Fuzz findings
/// `76e9fa53` and `1491101c`, each in its moved frame: the only choices
/// left were admitted by five41's measurement of the angles' rounding,
/// and each answer lacked a point verified at coincident poles
/// (`76e9fa53`: two of four points, the near `(3.41, -1.41)` and the far
/// one at coincident poles lost together; `1491101c`: the point at `Q` of
/// the only choice, `(0.00079, 9.91)`, lost and the other listed twice).
/// The choices again with those points required found none, and the first
/// answer was given anyway. Exact points: `tests/python/burmester_reference.py`
/// (mpmath; `1491101c` has two more at infinity). Refused now, or (should a
/// later change answer) the exact points. Fails before: a point missing.
#[test]
fn issue24_an_answer_that_lacks_a_point_at_coincident_poles_is_refused() {
    use burmester::{DegenerateError, Error};
    type Case = (&'static str, [(f64, f64, f64); 5], &'static [(f64, f64)]);
    let cases: [Case; 2] = [
        (
            "76e9fa53 moved",
            [
                (1.9297502855082698, -0.7803129409784815, 74.99609381325),
                (
                    0.09249609734464646,
                    -1.5288250016163258e-9,
                    74.99609381324609,
                ),
                (0.09249609374999794, 5.1234714622481425e-15, 78.90234374925),
                (1.9297502855082698, -0.7803129409784815, 78.9023437492539),
                (-4.912612857176176, -11.998207549019924, 74.9960938132539),
            ],
            &[
                (199671422719.9088, 470128255495.53546),
                (-1.5274633484919529, -6.3672824611617305),
                (3.414617423454858, -1.4109611376528737),
                (312750445777.497, 376094725558.20874),
            ],
        ),
        (
            "1491101c moved",
            [
                (
                    0.0007412696787929557,
                    -990.0901718749986,
                    -3.1415927057978243,
                ),
                (
                    0.0007866777098207951,
                    9.909828122779897,
                    -3.1415927057978243,
                ),
                (
                    0.0007934799302669603,
                    9.909828124999988,
                    -0.00010005220803102796,
                ),
                (
                    0.000793477709820911,
                    9.909828124999988,
                    -5.2207031250000006e-8,
                ),
                (
                    0.0007934799302668444,
                    9.909828122779542,
                    -3.1415927057978243,
                ),
            ],
            &[
                (0.0007934799315221613, 9.909828123889765),
                (0.000763964451266543, -490.09017187499916),
            ],
        ),
    ];
    for (name, poses, exact) in cases {
        let q: Vec<Pose> = poses.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
        match FivePositions::new(&q) {
            Ok(_) => assert_at_exact(name, &poses, exact, 1e-6),
            Err(Error::Degenerate(DegenerateError::UnresolvedBurmesterPoints { .. })) => {}
            Err(e) => panic!("{name}: {e}"),
        }
    }
}

/// A line of common points of the two center-point curves that a later
/// choice of the shared poses finds, where an earlier choice found
/// isolated points, is that choice's rounding: the task is refused as not
/// resolved, not as having infinitely many Burmester points (five42).
/// Fuzz findings `9da3b0ea` moved and `cada740b` as given: four isolated
/// exact points each (`tests/python/burmester_reference.py`, mpmath; the
/// curves share no component). Fails before: `InfinitelyManyBurmesterPoints`.
#[test]
fn issue24_a_line_within_a_later_choice_s_rounding_is_not_infinitely_many_points() {
    use burmester::{DegenerateError, Error};
    type Case = (&'static str, [(f64, f64, f64); 5]);
    let cases: [Case; 2] = [
        (
            "9da3b0ea moved",
            [
                (43723718355.99744, 999043660934.4398, -97.43310992320511),
                (43723718355.99744, 999043660934.4398, -99.00390625),
                (5.855549643737797, -0.17489487341568397, -99.00390625),
                (-4.417801451614124, 0.2747242247391977, -99.003909579),
                (-2.413092469320362, -99.9087384652794, -102.1454989035898),
            ],
        ),
        (
            "cada740b",
            [
                (
                    -9.84375776953125e-10,
                    6.054687499999999e-7,
                    1.9921875000000004e-9,
                ),
                (-9.84375976953125e-10, 9.960937499999999e-7, -1e-9),
                (
                    -3.9160937597656245e-7,
                    6.054687499933592e-7,
                    -3.906250000003906,
                ),
                (
                    7.498624999023438e-6,
                    9.960937499999999e-7,
                    -3.906250004003906,
                ),
                (-3.9160937597656245e-7, 6.054687499933592e-7, -3.906250001),
            ],
        ),
    ];
    for (name, poses) in cases {
        let q: Vec<Pose> = poses.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
        match FivePositions::new(&q) {
            Err(Error::Degenerate(DegenerateError::UnresolvedBurmesterPoints { .. })) => {}
            other => panic!("{name}: refused as not resolved expected, got {other:?}"),
        }
    }
}

/// Where the angles' rounding of a choice's resultant is measured (five41),
/// the common asymptotic direction of its two curves is decided with the
/// measured rounding too (five42): the magnitude bound that called the
/// resultant zero also called the curves' asymptotic normals parallel, and
/// a far point was read as a slider. Fuzz findings `5112b39f` moved (angles
/// near `34132` rad; its point `770` task sizes out) and `1b251dfd` moved
/// (angles near `100` rad; `310` task sizes out), each listed as one point
/// and a slider where the exact task has two points and a complex pair
/// (`tests/python/burmester_reference.py`, mpmath). Fails before: the far
/// point missing.
#[test]
fn issue24_a_far_point_is_not_read_as_a_slider_where_the_angles_are_measured() {
    assert_at_exact(
        "5112b39f moved",
        &[
            (34132.81356346431, 34132.807079057115, 34132.81640625),
            (34132.8125, 34132.8125, 34132.812499907),
            (34132.81467874012, 34132.81574220304, 34132.8125),
            (-21624.031478641824, -48701.44860150799, 34115.8125),
            (34185.23950346967, 34210.82964521469, 34111.81640625),
        ],
        &[
            (-51048397.172473684, 34359510.546512544),
            (34175.25826364923, 34105.60954787749),
        ],
        1e-6,
    );
    assert_at_exact(
        "1b251dfd moved",
        &[
            (0.0013260610120030126, 0.000491489768403724, -100.390625),
            (-2.0527205034100092e-7, -4.49443205921284e-7, -99.390625),
            (417.28562180055303, 908.775390202951, -99.390626),
            (
                4.172856217996443e-10,
                9.087753902033683e-10,
                -105.6738103071796,
            ),
            (
                -2.0527205034100092e-7,
                -4.49443205921284e-7,
                -102.5322176535898,
            ),
        ],
        &[
            (0.0001473141378245786, 0.00032254084676396587),
            (225175.98845560447, -102844.6682814264),
        ],
        1e-6,
    );
}

/// A crank-rocker in millimetres (ground about 100) driven to five crank
/// angles, two of them `1e-7` rad apart (stop 41's designer-range stress,
/// `fuzz/reference/moderate_five.py`, family `known-near`): poses 2 and 3
/// are `8.4e-6` mm apart in a task of size about 40 mm. Every choice of the
/// shared poses vanishes within its rounding (the two curves of each
/// nearly one curve), and the task was refused, with every pose as the
/// reference pose, as having infinitely many Burmester points; the exact
/// float task (`burmester_reference.py`) has two isolated real points,
/// `(412.9879979506825, 276.06221975137896)` and
/// `(403.51129160717744, 174.4180587269174)`, and no slider. The refusal
/// stands (the rounding of every elimination decides it) but says that
/// the points are not resolved and to move the near poses apart. A task whose
/// points are truly not isolated with no poses near each other (Cardan
/// motion, `curves.rs`) keeps `InfinitelyManyBurmesterPoints`.
#[test]
fn issue24_nearly_coincident_poses_whose_every_elimination_vanishes_are_not_infinitely_many() {
    use burmester::{DegenerateError, Error};
    let poses = [
        (367.9841706374187, 431.5876429720099, -0.8127201859561507),
        (334.2172582590474, 420.93818917293066, -0.671687837024974),
        (334.2172658572368, 420.938192891125, -0.6716878712875773),
        (394.53493494900073, 431.97763619403185, -0.9128145772057858),
        (384.04430266030647, 432.7087531478958, -0.874031963831141),
    ];
    for r in 0..5 {
        let turned: Vec<Pose> = (0..5)
            .map(|k| {
                let (x, y, a) = poses[(k + r) % 5];
                Pose::new(x, y, a)
            })
            .collect();
        match FivePositions::new(&turned) {
            Err(e @ Error::Degenerate(DegenerateError::UnresolvedBurmesterPoints { .. })) => {
                assert!(
                    e.to_string().contains("nearly coincide"),
                    "reference pose {r}: {e}"
                );
            }
            other => panic!("reference pose {r}: not resolved expected, got {other:?}"),
        }
    }
}

/// An answer that the exact count contradicts is refused (stop 42): the
/// float task solved in exact integer arithmetic (`FivePositions::new`'s
/// last check). Three frames of `fuzz/open/burmester_points` whose answer
/// passed every earlier check and was wrong against the exact points
/// (`certificate_five.py`'s `points_of`, mpmath; `balance_five.py`'s
/// judge agrees): a point missing from a pair (`eae1e20a` moved: listed
/// `(127.015, 42.074)` alone, the exact pair's `(169.089, 15.058)` lost),
/// no points where two exist (`0157aa6a` moved), and a simple point read
/// as a near pair and a slider (`c49a3126`: two ghosts listed, the exact
/// `(-3.456, -1.119)` missing). Each is now refused, or answered at the
/// exact points (each within `1e-6` of `size + d`).
#[test]
fn issue24_an_answer_that_the_exact_count_contradicts_is_refused() {
    use burmester::{DegenerateError, Error};
    type Frame = (&'static str, [(f64, f64, f64); 5], &'static [(f64, f64)]);
    let frames: [Frame; 3] = [
        (
            "eae1e20a moved",
            [
                (154.03023058681399, 84.14709848078965, 0.99999999999947),
                (100.00000000006321, 9.84521052225239e-11, 1.0),
                (100.0, 0.0, -2.141592653589793),
                (154.03023058681399, 84.14709848078965, -2.141592653589793),
                (184.14709848078968, -54.03023058681396, 1.0),
            ],
            &[
                (127.01511529344542, 42.073549240412795),
                (169.0886645338422, 15.058433946996649),
                (56822084216412.45, -260701871679429.0),
                (260701871679945.1, 56822084216366.95),
            ],
        ),
        (
            "0157aa6a moved",
            [
                (-3.2927775606855376, 101.48102067026616, -106.5322176535937),
                (2.9333090118539644, 103.28439020876431, -103.3906260000039),
                (2.2609942607602367, 100.25035539841507, -104.39062500000391),
                (-3.3023210716129356, 101.47824601758283, -106.5322176535937),
                (2.9333025193775355, 103.28444974884508, -103.3906077480039),
            ],
            &[
                (-0.1797329205928153, 102.38270748872615),
                (-0.09982683286199098, 102.09006156107938),
            ],
        ),
        (
            "c49a3126 task",
            [
                (-2.00390625e-9, 2.8515625e-10, 0.99609375),
                (0.0, 9.9609375e-10, 0.996093694015625),
                (2.20703125, 2.207031250996094, 2.2070312489921875),
                (1996.09375, 0.00056640625, -3.90625e-6),
                (2.2070312516015624, 0.0, 0.0),
            ],
            &[
                (-3.4560759833558166, -1.1191045804104822),
                (1002.7000894195206, 381.53143239738137),
            ],
        ),
    ];
    for (name, poses, exact) in frames {
        let task: Vec<Pose> = poses.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
        match FivePositions::new(&task) {
            Err(Error::Degenerate(DegenerateError::UnresolvedBurmesterPoints { .. })) => {}
            Err(e) => panic!("{name}: {e}"),
            Ok(_) => assert_at_exact(name, &poses, exact, 1e-6),
        }
    }
}
