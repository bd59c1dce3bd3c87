//! The checks behind the cargo-fuzz targets of `burmester`.
//!
//! Each target turns the fuzzer's bytes into numbers with [`Input`] (a mix of
//! raw bit patterns, small integers, decimal-looking values, special values
//! and near-repeats of earlier numbers, so that degenerate geometry such as
//! equal angles or a point on a pole comes up often), calls the public API,
//! and asserts:
//!
//! * nothing panics;
//! * every value inside an `Ok` is finite (a fallible function must return an
//!   error rather than hand back a NaN or an infinity);
//! * the infallible accessors (evaluations, displacements, signs, margins) are
//!   finite whenever the inputs are *moderate*: every coordinate, length and
//!   coefficient is zero or of magnitude within `[1e-50, 1e50]` (so no product
//!   of a few of them can overflow); the margin map's documented `-inf` when
//!   every circle point is defective is allowed;
//! * documented consistencies: the branch map equals `classify` at the grid
//!   points bit for bit, its point-by-point kernel equals its run kernel, the
//!   margin's sign is the branch map, a map followed through a progress hook
//!   equals one computed without and a cancelled one is
//!   [`Error::Cancelled`], a three-pose task's poles are its
//!   [`Cremona`]'s, a solved configuration carries the assembly mode that was
//!   asked for, and the ranked pivots of a solution map are what their
//!   ranking admits;
//! * the work parameters of the polylines (the chord tolerance and the point
//!   budget): a tolerance outside its documented range is
//!   [`InvalidInput::OutsideRange`], a curve over the budget
//!   [`InvalidInput::TooLarge`], and nothing else fails.
//!
//! The same functions run over the committed corpus in the main workspace's
//! tests (`tests/rust/fuzz_corpus.rs`), so every finding stays a regression
//! test without libFuzzer.

use core::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use burmester::{
    AssemblyMode, CircleOrLine, Conic, Constraints, Control, DegenerateError, DesignLimits,
    Direction, Dyad, Error, FourBar, Grashof, Grid, InputRequirement, InvalidInput, Line,
    MapOptions, Method, Point2, Pole, Pose, RankBy, Ranking, SolutionMap, Task, Vector2, Viewport,
};

/// Reads numbers from the fuzzer's bytes; past the end everything is zero.
pub struct Input<'a> {
    data: &'a [u8],
    pos: usize,
    history: [f64; 8],
    count: usize,
    /// Whether every number read so far is moderate (see the crate docs).
    pub moderate: bool,
}

const SPECIAL: [f64; 22] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::MAX,
    f64::MIN_POSITIVE,
    5e-324,
    1e-300,
    1e300,
    core::f64::consts::PI,
    core::f64::consts::TAU,
    core::f64::consts::FRAC_PI_2,
    1e-12,
    1e-6,
    1e6,
    1e12,
    f64::EPSILON,
    -core::f64::consts::PI,
    0.5,
];

impl<'a> Input<'a> {
    /// A reader over `data`.
    pub fn new(data: &'a [u8]) -> Self {
        Input {
            data,
            pos: 0,
            history: [0.0; 8],
            count: 0,
            moderate: true,
        }
    }

    /// The next byte (zero past the end).
    pub fn byte(&mut self) -> u8 {
        let b = self.data.get(self.pos).copied().unwrap_or(0);
        self.pos += 1;
        b
    }

    fn bytes<const N: usize>(&mut self) -> [u8; N] {
        core::array::from_fn(|_| self.byte())
    }

    /// A small count in `lo..=hi`.
    pub fn count(&mut self, lo: usize, hi: usize) -> usize {
        lo + usize::from(self.byte()) % (hi - lo + 1)
    }

    /// A number (see the crate docs for the mix).
    pub fn num(&mut self) -> f64 {
        let sel = self.byte();
        let v = match sel % 8 {
            0 => f64::from_le_bytes(self.bytes()),
            1 => f64::from(self.byte() as i8),
            2 => f64::from(i16::from_le_bytes(self.bytes())) / 64.0,
            3 => {
                let m = f64::from(i16::from_le_bytes(self.bytes()));
                let e = i32::from(self.byte() as i8) % 16;
                m * 10f64.powi(e)
            }
            4 => SPECIAL[usize::from(self.byte()) % SPECIAL.len()],
            5 => {
                // A near-repeat of an earlier number.
                let k = usize::from(self.byte()) % 8;
                let base = self.history[k];
                let d = f64::from(self.byte() as i8);
                let e = -(i32::from(self.byte()) % 17);
                base * (1.0 + d * 10f64.powi(e)) + d * 1e-14
            }
            6 => self.history[usize::from(self.byte()) % 8],
            _ => {
                let m = f64::from(i16::from_le_bytes(self.bytes())) / 1000.0;
                m * 10f64.powi(i32::from(self.byte() % 13) - 6)
            }
        };
        self.history[self.count % 8] = v;
        self.count += 1;
        self.note(v);
        v
    }

    /// A number drawn from the "nice" part of the mix only (moderate values).
    pub fn nice(&mut self) -> f64 {
        let m = f64::from(i16::from_le_bytes(self.bytes())) / 256.0;
        let v = match self.byte() % 4 {
            0 => m,
            1 => m * 1e-3,
            2 => m * 1e3,
            _ => self.history[usize::from(self.byte()) % 8] + m * 1e-9,
        };
        self.history[self.count % 8] = v;
        self.count += 1;
        self.note(v);
        v
    }

    /// A point from two numbers.
    pub fn point(&mut self) -> Point2<f64> {
        Point2::new(self.num(), self.num())
    }

    /// Records whether `v` is moderate.
    pub fn note(&mut self, v: f64) {
        let a = v.abs();
        if !(a == 0.0 || (1e-50..=1e50).contains(&a)) {
            self.moderate = false;
        }
    }

    /// Records whether every coordinate of `p` is moderate.
    pub fn note_point(&mut self, p: Point2<f64>) {
        self.note(p.x);
        self.note(p.y);
    }
}

/// Asserts that `v` is finite.
#[track_caller]
pub fn finite(what: &str, v: f64) {
    assert!(v.is_finite(), "{what} is {v}");
}

/// Asserts that both coordinates of `p` are finite.
#[track_caller]
pub fn finite_pt(what: &str, p: Point2<f64>) {
    assert!(p.x.is_finite() && p.y.is_finite(), "{what} is {p:?}");
}

/// Asserts that `a` and `b` are the same, bit for bit (through their
/// debug forms, so that a NaN carried by an error equals itself).
#[track_caller]
pub fn same<T: core::fmt::Debug>(what: &str, a: &T, b: &T) {
    assert_eq!(format!("{a:?}"), format!("{b:?}"), "{what}");
}

/// Asserts that the message of `e` is not empty (formatting does not panic).
pub fn message(e: &Error) {
    assert!(!e.to_string().is_empty());
}

/// The map options of `limits` and `constraints`, checked; `None` (the
/// error's message checked) where they are invalid.
fn map_options(limits: &DesignLimits, constraints: &Constraints) -> Option<MapOptions> {
    MapOptions::new(limits, constraints)
        .map_err(|e| message(&e))
        .ok()
}

fn circle_or_line(what: &str, c: CircleOrLine) {
    match c {
        CircleOrLine::Circle { center, radius } => {
            finite_pt(what, center);
            finite(what, radius);
        }
        CircleOrLine::Line { point, direction } => {
            finite_pt(what, point);
            finite(what, direction.x);
            finite(what, direction.y);
        }
    }
}

/// Position analysis: construction, solve, joints, paths, range, Grashof.
pub fn fourbar(data: &[u8]) {
    let mut inp = Input::new(data);
    let how = inp.byte();
    let built = if how % 2 == 0 {
        let l = [inp.num(), inp.num(), inp.num(), inp.num()];
        let origin = inp.point();
        let angle = inp.num();
        FourBar::placed(l[0], l[1], l[2], l[3], origin, angle)
    } else {
        let (a, b) = (inp.point(), inp.point());
        FourBar::from_pivots(a, b, inp.num(), inp.num(), inp.num())
    };
    let fb = match built {
        Ok(fb) => fb,
        Err(e) => return message(&e),
    };
    for l in fb.lengths() {
        finite("length", l);
        assert!(l > 0.0);
    }
    finite_pt("input pivot", fb.input_pivot());
    finite_pt("output pivot", fb.output_pivot());
    finite("ground angle", fb.ground_angle());
    let ratio = fb.link_ratio();
    assert!(ratio >= 1.0, "link ratio {ratio}");
    let _ = fb.grashof();
    let range = fb.input_range();
    for d in range.dead_positions() {
        assert!(d.is_finite(), "dead position {d}: {fb:?} {range:?}");
    }
    let longest = fb.lengths().iter().copied().fold(0.0, f64::max);
    let n = inp.count(1, 4);
    let mut angles = Vec::new();
    for _ in 0..n {
        let t = match inp.byte() % 3 {
            0 => inp.num(),
            1 => range.dead_positions().first().copied().unwrap_or(0.0) + inp.nice() * 1e-9,
            _ => inp.nice(),
        };
        angles.push(t);
    }
    let local = Vector2::new(inp.num(), inp.num());
    for t in &angles {
        for mode in AssemblyMode::BOTH {
            let solved = fb.solve(*t, mode);
            let joints = fb.joints_at(*t, mode);
            assert_eq!(solved.is_ok(), joints.is_ok(), "solve and joints_at at {t}");
            match solved {
                Ok(c) => {
                    finite("theta3", c.theta3);
                    finite("theta4", c.theta4);
                    let mu = c.transmission_angle();
                    assert!((0.0..=core::f64::consts::FRAC_PI_2).contains(&mu), "{mu}");
                    // The mode asked for is the mode returned (no silent
                    // branch switch), except at a flagged toggle.
                    if !c.toggle {
                        let s = c.coupler_rocker_angle() * mode.sign();
                        assert!(
                            s > -1e-9,
                            "mode {mode} gave angle {}",
                            c.coupler_rocker_angle()
                        );
                    }
                    let j = fb.joints(&c);
                    for p in [j.input_pivot, j.crank_joint, j.rocker_joint, j.output_pivot] {
                        finite_pt("joint", p);
                    }
                    // The loop closes.
                    let ab = (j.rocker_joint - j.crank_joint) / longest;
                    let gap = (ab.norm() - fb.coupler() / longest) * longest;
                    let o = fb.input_pivot();
                    let room = 1e-6 * longest + 1e-14 * (o.x.abs() + o.y.abs());
                    assert!(
                        gap.abs() <= room,
                        "coupler length off by {gap}: {fb:?} at {t} {mode}: {c:?}"
                    );
                    let jj = joints.expect("joints_at agrees with solve");
                    for p in [jj.crank_joint, jj.rocker_joint] {
                        finite_pt("joints_at", p);
                    }
                }
                Err(e) => message(&e),
            }
        }
        for r in fb.coupler_path(local, [*t], AssemblyMode::Open) {
            match r {
                Ok(p) => finite_pt("coupler path", p),
                Err(e) => message(&e),
            }
        }
    }
    let (mut t3, mut t4, mut ok) = (vec![0.0; n], vec![0.0; n], vec![false; n]);
    let closed = fb
        .solve_into(&angles, AssemblyMode::Crossed, &mut t3, &mut t4, &mut ok)
        .expect("equal lengths");
    assert_eq!(closed, ok.iter().filter(|&&v| v).count());
    for k in 0..n {
        assert_eq!(
            ok[k],
            t3[k].is_finite() && t4[k].is_finite(),
            "solve_into at {k}"
        );
    }
}

fn pose(inp: &mut Input<'_>) -> Pose {
    Pose::new(inp.num(), inp.num(), inp.num())
}

/// A task: raw numbers, or moderate ones with a chosen near-degeneracy.
fn task(inp: &mut Input<'_>) -> Option<Task> {
    let poses = match inp.byte() % 3 {
        0 => [pose(inp), pose(inp), pose(inp)],
        _ => {
            let mut p = [0; 3].map(|_| Pose::new(inp.nice(), inp.nice(), inp.nice()));
            match inp.byte() % 6 {
                // Near a translation between two poses.
                0 => p[1].angle = p[0].angle + inp.nice() * 1e-6,
                // Near a pose repeated.
                1 => {
                    p[2] = Pose::new(
                        p[1].position.x,
                        p[1].position.y + inp.nice() * 1e-9,
                        p[1].angle,
                    )
                }
                // Near rotations about one point.
                2 => {
                    let c = Point2::new(inp.nice(), inp.nice());
                    let (p0, a0) = (p[0].position, p[0].angle);
                    for q in &mut p[1..] {
                        let t = q.angle - a0;
                        let (s, co) = t.sin_cos();
                        let v = p0 - c;
                        q.position = c
                            + Vector2::new(co * v.x - s * v.y, s * v.x + co * v.y)
                            + Vector2::new(inp.nice() * 1e-12, 0.0);
                    }
                }
                // Scaled.
                3 => scale(inp, &mut p),
                _ => {}
            }
            p
        }
    };
    task_of(&poses)
}

/// The poses' positions scaled by a power of ten from `1e-12` to `1e12`.
fn scale(inp: &mut Input<'_>, poses: &mut [Pose]) {
    let k = 10f64.powi(i32::from(inp.byte() % 25) - 12);
    for q in poses {
        q.position = Point2::from(q.position.coords * k);
    }
}

/// The task of `poses`, or none when they are refused (with a message
/// that passes [`message`]'s checks).
fn task_of(poses: &[Pose]) -> Option<Task> {
    match Task::new(poses) {
        Ok(t) => Some(t),
        Err(e) => {
            message(&e);
            None
        }
    }
}

/// The finite poles of a task of three poses: all three, unless two poses
/// differ by a pure translation.
fn finite_poles(t: &Task) -> Vec<Point2<f64>> {
    t.poles().iter().filter_map(Pole::finite).collect()
}

/// A task of three poses with a pure translation: no pole triangle (a typed
/// error naming the pair), the pair's pole at infinity, a positive scale.
fn check_translated(t: &Task) {
    let e = t
        .cremona()
        .expect_err("a task with a pole at infinity has no pole triangle");
    message(&e);
    let Error::Degenerate(DegenerateError::PureTranslation { i, j }) = e else {
        panic!("unexpected error {e:?}");
    };
    let pairs = [(1, 2), (1, 3), (2, 3)];
    let k = pairs.iter().position(|&q| q == (i, j)).expect("a pair");
    assert!(matches!(t.poles()[k], Pole::AtInfinity { .. }));
    let at_hand = finite_poles(t);
    assert!(!at_hand.is_empty() && at_hand.len() < 3);
    for p in &at_hand {
        finite_pt("pole", *p);
    }
    let s = t.scale();
    assert!(s.is_finite() && s > 0.0, "scale {s}");
    for r in t.rotations() {
        finite("rotation", r);
    }
}

fn check_task(t: &Task) {
    assert_eq!(t.len(), 3);
    let Ok(cr) = t.cremona() else {
        return check_translated(t);
    };
    // The general poles of three poses are the Cremona poles, bit for bit
    // (a task with a pure translation has no Cremona: checked above).
    let poles = t.poles();
    assert_eq!(poles.len(), 3);
    for (k, (p, q)) in poles.iter().zip(cr.poles()).enumerate() {
        assert_eq!(*p, Pole::Finite(q), "pole {k}");
    }
    for p in cr.poles().iter().chain(&cr.image_poles()) {
        finite_pt("pole", *p);
    }
    let s = t.scale();
    assert!(s.is_finite() && s > 0.0, "scale {s}");
    assert_eq!(s.to_bits(), cr.scale().to_bits(), "task and Cremona scales");
    let rotations = t.rotations();
    assert_eq!(rotations.len(), 3);
    for r in rotations {
        finite("rotation", r);
    }
    for (i, j) in [(1, 2), (1, 3), (2, 3)] {
        finite("rotation", t.rotation(i, j).expect("valid pose indices"));
    }
    for (i, j) in [(0, 1), (1, 4)] {
        match t.rotation(i, j) {
            Ok(r) => panic!("rotation({i}, {j}) of three poses is {r}"),
            Err(e) => message(&e),
        }
    }
    for a in cr.pole_triangle_angles() {
        finite("pole triangle angle", a);
    }
    for k in 0..=4 {
        match cr.image_poles_in(k) {
            Ok(ps) => ps.iter().for_each(|p| finite_pt("image pole", *p)),
            Err(e) => {
                assert!(!(1..=3).contains(&k));
                message(&e);
            }
        }
    }
    circle_or_line("pole circle", cr.pole_circle());
    circle_or_line("image-pole circle", cr.image_pole_circle());
}

/// A map result: a finite point, or a typed error with a unit direction.
fn check_map(t: &Task, what: &str, p: Point2<f64>, r: burmester::Result<Point2<f64>>) {
    match r {
        Ok(q) => finite_pt(what, q),
        Err(e) => {
            message(&e);
            match e.clone() {
                Error::Degenerate(DegenerateError::AtInfinity { dir_x, dir_y, .. }) => {
                    let n = dir_x.hypot(dir_y);
                    assert!(
                        (n - 1.0).abs() < 1e-9,
                        "{what}: direction of norm {n} at {p:?}: {e:?}"
                    );
                }
                Error::Degenerate(DegenerateError::Undefined { .. }) => {}
                Error::InvalidInput(_) => {
                    let far = (p.x.abs().max(p.y.abs()) / t.scale()) > 1e299;
                    assert!(
                        !(p.x.is_finite() && p.y.is_finite()) || far,
                        "{what} rejected {p:?}"
                    );
                }
                other => panic!("{what}: unexpected error {other:?}"),
            }
        }
    }
}

/// Points that exercise the special places of a task.
fn probe_points(inp: &mut Input<'_>, t: &Task, extra: &[Point2<f64>]) -> Vec<Point2<f64>> {
    let finite = finite_poles(t);
    let mut pts: Vec<Point2<f64>> = finite.clone();
    if let Ok(cr) = t.cremona() {
        pts.extend(cr.image_poles());
    }
    pts.extend_from_slice(extra);
    let s = t.scale();
    if let Ok(cr) = t.cremona() {
        for c in [cr.pole_circle(), cr.image_pole_circle()] {
            if let CircleOrLine::Circle { center, radius } = c {
                let a = inp.nice();
                pts.push(center + Vector2::new(a.cos(), a.sin()) * radius);
            }
        }
    }
    let n = inp.count(1, 6);
    for _ in 0..n {
        let p = match inp.byte() % 3 {
            0 => inp.point(),
            1 => {
                let base = pts[usize::from(inp.byte()) % pts.len()];
                base + Vector2::new(inp.nice(), inp.nice()) * (s * 1e-12)
            }
            _ => {
                let base = finite[0];
                base + Vector2::new(inp.nice(), inp.nice()) * s
            }
        };
        pts.push(p);
    }
    pts
}

/// Task construction, poles, circles and the maps; then (from the bytes
/// the three-pose checks leave) the same task with a fourth and a fifth pose.
pub fn task_maps(data: &[u8]) {
    let mut inp = Input::new(data);
    let Some(t) = task(&mut inp) else { return };
    check_task(&t);
    // With a pure translation the maps run by the linear form (no Cremona).
    let cr = t.cremona().ok();
    let pts = probe_points(&mut inp, &t, &[]);
    let moderate = inp.moderate;
    for (i, j) in [(0, 1), (2, 4)] {
        match t.displace(Point2::origin(), i, j) {
            Ok(q) => panic!("displace by poses {i}, {j} of three gave {q:?}"),
            Err(e) => message(&e),
        }
    }
    for p in pts {
        let circle = t.circle_point(p);
        if let Some(cr) = cr {
            same("Task and Cremona", &circle, &cr.circle_point(p));
        }
        check_map(&t, "circle point", p, circle.clone());
        let center = t.center_point(p);
        if let Some(cr) = cr {
            same("Task and Cremona", &center, &cr.center_point(p));
        }
        check_map(&t, "center point", p, center);
        if let Ok(d) = t.dyad_from_center(p) {
            assert_eq!(d, Dyad::new(p, circle.expect("the dyad's circle point")));
            let angles = t.crank_angles(&d);
            assert_eq!(angles.len(), 3);
            for a in angles.iter() {
                if moderate {
                    finite("crank angle", *a);
                }
            }
        }
        if moderate && p.x.is_finite() && p.y.is_finite() {
            for (i, j) in [(1, 2), (2, 3), (3, 1)] {
                finite_pt(
                    "displaced",
                    t.displace(p, i, j).expect("valid pose indices"),
                );
            }
        }
        let d = Vector2::new(inp.nice(), inp.nice());
        match t.line_to_conic(&Line {
            point: p,
            direction: d,
        }) {
            Ok(c) => {
                for v in c.coefficients() {
                    if moderate {
                        finite("line conic coefficient", v);
                    }
                }
            }
            Err(e) => message(&e),
        }
    }
    more_poses(&mut inp, &t);
}

/// A task of four or five poses: the three of `t` and one or two more,
/// read after everything else (so that inputs written for three poses keep
/// their meaning). What holds for any number of poses: poles (at infinity
/// for a pure translation, which more than three poses allow),
/// displacements, rotations, crank angles; the three-position maps are
/// typed errors.
fn more_poses(inp: &mut Input<'_>, t: &Task) {
    let n = inp.count(3, 5);
    if n == 3 {
        return;
    }
    let mut poses = t.poses().to_vec();
    for _ in 3..n {
        let p = match inp.byte() % 4 {
            0 => pose(inp),
            // A pure translation of an earlier pose.
            1 => {
                let q = poses[usize::from(inp.byte()) % poses.len()];
                Pose::new(
                    q.position.x + inp.nice(),
                    q.position.y + inp.nice(),
                    q.angle,
                )
            }
            // A rotation about an earlier pole (a finite one: a pure
            // translation between two of the three poses has its pole at
            // infinity, and not all three are).
            2 => {
                let poles: Vec<Point2<f64>> = t.poles().iter().filter_map(Pole::finite).collect();
                assert!(!poles.is_empty(), "three poses of one angle make no task");
                let c = poles[usize::from(inp.byte()) % poles.len()];
                let q = poses[0];
                let a = inp.nice();
                let v = q.position - c;
                let (s, co) = a.sin_cos();
                Pose::new(
                    c.x + co * v.x - s * v.y,
                    c.y + s * v.x + co * v.y,
                    q.angle + a,
                )
            }
            _ => Pose::new(inp.nice(), inp.nice(), inp.nice()),
        };
        poses.push(p);
    }
    let more = match Task::new(&poses) {
        Ok(m) => m,
        Err(e) => return message(&e),
    };
    let moderate = inp.moderate;
    assert_eq!(more.len(), n);
    let s = more.scale();
    assert!(s.is_finite() && s > 0.0, "scale {s}");
    let poles = more.poles();
    assert_eq!(poles.len(), n * (n - 1) / 2);
    let pairs: Vec<(usize, usize)> = more.motion().pairs().collect();
    assert_eq!(pairs.len(), poles.len());
    for (p, &(i, j)) in poles.iter().zip(&pairs) {
        assert_eq!(Ok(*p), more.motion().pole(i, j), "pole {i}{j}");
        match p {
            Pole::Finite(q) => finite_pt("pole", *q),
            Pole::AtInfinity { direction } => {
                let r = direction.norm();
                assert!((r - 1.0).abs() < 1e-9, "pole {i}{j} at infinity along {r}");
            }
        }
    }
    let rotations = more.rotations();
    assert_eq!(rotations.len(), pairs.len());
    for (r, &(i, j)) in rotations.iter().zip(&pairs) {
        finite("rotation", *r);
        assert_eq!(Ok(*r), more.rotation(i, j));
    }
    for (i, j) in [(0, 1), (1, n + 1)] {
        assert!(more.displace(Point2::origin(), i, j).is_err());
        assert!(more.rotation(i, j).is_err());
    }
    assert!(more.motion().pole(2, 2).is_err());
    let z = Point2::new(inp.nice(), inp.nice());
    let moderate = moderate && inp.moderate;
    for (i, j) in pairs {
        match more.displace(z, i, j) {
            Ok(d) => {
                assert!(z.x.is_finite() && z.y.is_finite(), "displaced {z:?}");
                if moderate {
                    finite_pt("displaced", d);
                }
            }
            Err(e) => {
                assert!(!(z.x.is_finite() && z.y.is_finite()), "displace {z:?}: {e}");
                message(&e);
            }
        }
    }
    let dyad = Dyad::new(Point2::new(inp.nice(), inp.nice()), z);
    let angles = more.crank_angles(&dyad);
    assert_eq!(angles.len(), n);
    if moderate && inp.moderate {
        angles.iter().for_each(|a| finite("crank angle", *a));
    }
    // The three-position maps need three poses.
    let needs = |r: burmester::Result<()>| match r {
        Err(Error::InvalidInput(InvalidInput::NeedsPoses {
            required, found, ..
        })) => {
            assert_eq!((required, found), (3, n));
        }
        other => panic!("a task of {n} poses: {other:?}"),
    };
    needs(more.cremona().map(|_| ()));
    needs(more.circle_point(z).map(|_| ()));
    needs(more.center_point(z).map(|_| ()));
    needs(more.filemon(z).map(|_| ()));
    needs(
        more.line_to_conic(&Line {
            point: z,
            direction: Vector2::x(),
        })
        .map(|_| ()),
    );
}

/// Filemon's construction, the classifiers, the maps and the conic curves.
pub fn filemon_classify(data: &[u8]) {
    let mut inp = Input::new(data);
    let Some(t) = task(&mut inp) else { return };
    let poles = finite_poles(&t);
    let c0 = match inp.byte() % 3 {
        0 => inp.point(),
        1 => poles[0] + Vector2::new(inp.nice(), inp.nice()) * t.scale(),
        _ => {
            poles[usize::from(inp.byte()) % poles.len()]
                + Vector2::new(inp.nice(), inp.nice()) * 1e-9
        }
    };
    inp.note_point(c0);
    let f = match t.filemon(c0) {
        Ok(f) => f,
        Err(e) => return message(&e),
    };
    let c1 = f.driven_circle();
    finite_pt("C1", c1);
    assert_eq!(f.driven(), Dyad::new(c0, c1).into());
    for p in f.fixed_pivot_images().into_iter().flatten() {
        if inp.moderate {
            finite_pt("C'", p);
        }
    }
    let mut pts = probe_points(&mut inp, &t, &[c0, c1]);
    // Points on the curves, from lines through the known points.
    if let Some(cs) = f.conics() {
        for c in cs {
            let w = Vector2::new(inp.nice(), inp.nice());
            let base = pts[usize::from(inp.byte()) % pts.len()];
            if w.norm() > 0.0 {
                pts.extend(c.intersect_line(&Line {
                    point: base,
                    direction: w,
                }));
            }
        }
    }
    let moderate = inp.moderate;
    for p in &pts {
        let p = *p;
        if !(p.x.is_finite() && p.y.is_finite()) {
            for m in [Method::Conic, Method::Direct, Method::Simulate] {
                assert!(f.classify(p, m).is_err());
            }
            assert!(f.margin(p).is_err());
            assert!(f.conic_values(p).is_err());
            continue;
        }
        let conic = f
            .classify(p, Method::Conic)
            .expect("conic classifies every finite point");
        for m in [Method::Direct, Method::Simulate] {
            if let Err(e) = f.classify(p, m) {
                message(&e);
            }
        }
        let margin = f.margin(p).expect("a finite point has a margin");
        let values = f.conic_values(p).expect("a finite point has conic values");
        assert!(
            !margin.is_nan(),
            "margin at {p:?}: {:?} {:?} {:?}",
            f.driven(),
            f.fixed_pivot_images(),
            values
        );
        if let Some(v) = values
            && moderate
        {
            finite("conic value", v[0]);
            finite("conic value", v[1]);
            assert!(margin.is_finite(), "margin {margin}");
        }
        assert_eq!(
            margin > 0.0,
            conic.is_free(),
            "margin {margin} vs {conic:?} at {p:?}"
        );
        match f.four_bar(p) {
            Ok(fb) => {
                assert_eq!(fb.input_angles.len(), 3);
                for v in fb.input_angles.iter() {
                    finite("input angle", *v);
                }
                finite("coupler point", fb.coupler_point.x);
                finite("coupler point", fb.coupler_point.y);
                finite("coupler angle offset", fb.coupler_angle_offset);
                for (k, m) in fb.modes().iter().enumerate() {
                    // Not a let chain: the crate's tests build on Rust 1.85.
                    if let Some(Ok(q)) = m.map(|m| fb.pose_at(fb.input_angles[k], m)) {
                        finite_pt("pose", q.position);
                        finite("pose angle", q.angle);
                    }
                }
            }
            Err(e) => message(&e),
        }
    }
    // A small grid around one of the points: the sweep equals classify.
    let center = pts[usize::from(inp.byte()) % pts.len()];
    let half = match inp.byte() % 3 {
        0 => inp.num().abs(),
        1 => t.scale() * 10f64.powi(i32::from(inp.byte() % 16) - 12),
        _ => t.scale(),
    };
    let (nx, ny) = (inp.count(1, 24), inp.count(1, 6));
    let Ok(grid) = Grid::from_bounds(
        center.x - half,
        center.x + half,
        center.y - half * 0.75,
        center.y + half * 0.75,
        nx,
        ny,
    ) else {
        return;
    };
    let map = f.branch_map(&grid, Method::Conic);
    let mut pw = vec![false; grid.len()];
    f.branch_map_pointwise_into(&grid, &mut pw).expect("length");
    assert_eq!(map, pw, "run and point kernels differ");
    check_control(&f, &grid, &map);
    let margins = f.margin_map(&grid);
    let direct = f.branch_map(&grid, Method::Direct);
    for j in 0..ny {
        for i in 0..nx {
            let k = j * nx + i;
            let p = grid.point(i, j);
            let c = f.classify(p, Method::Conic).expect("finite point");
            assert_eq!(
                f.is_branch_free(p, Method::Conic),
                Ok(c.is_free()),
                "is_branch_free at {p:?}"
            );
            assert_eq!(
                map[k],
                c.is_free(),
                "branch map vs classify at {p:?}: {c:?} {:?} {:?} {:?} {:?}",
                f.conic_values(p),
                f.special_points(),
                grid,
                t.scale()
            );
            let m = margins[k];
            assert!(!m.is_nan());
            if !f.all_defective() {
                assert_eq!(m > 0.0, map[k], "margin map sign at {p:?}: {m}");
            }
            let d = f.classify(p, Method::Direct).is_ok_and(|b| b.is_free());
            assert_eq!(
                direct[k],
                d,
                "direct map vs classify at {p:?}: {} {:?} {:?} {:?}",
                f.all_defective(),
                f.classify(p, Method::Direct),
                f.fixed_pivot_images(),
                f.driven()
            );
        }
    }
    // The curves on a small viewport.
    if let (Some(cs), Ok(vp)) = (f.conics(), grid_viewport(&grid)) {
        for c in cs {
            polylines(&c, &vp);
        }
    }
}

/// A map followed through a progress hook is the map computed without, bit
/// for bit, and the hook reaches every row; a cancelled one is
/// [`Error::Cancelled`] before any row; a buffer of another length is
/// refused.
fn check_control(f: &burmester::Filemon, grid: &Grid, map: &[bool]) {
    let rows = AtomicUsize::new(0);
    let hook = |done: usize, total: usize| {
        assert!(
            done <= total && total == grid.ny(),
            "progress {done} of {total}"
        );
        rows.fetch_max(done, Ordering::Relaxed);
    };
    let followed = Control::new().with_progress(&hook);
    let mut out = vec![false; grid.len()];
    f.branch_map_into(grid, Method::Conic, &mut out, &followed)
        .expect("not cancelled");
    assert_eq!(out, map, "a map followed by a progress hook differs");
    assert_eq!(rows.load(Ordering::Relaxed), grid.ny());
    let mut margins = vec![0.0f32; grid.len()];
    f.margin_map_into(grid, &mut margins, &followed)
        .expect("not cancelled");
    let plain = f.margin_map(grid);
    assert!(
        margins
            .iter()
            .zip(&plain)
            .all(|(a, b)| a.to_bits() == b.to_bits()),
        "a margin map followed by a progress hook differs"
    );
    let stop = AtomicBool::new(true);
    let cancelled = Control::new().with_cancel(&stop);
    for m in [Method::Conic, Method::Direct] {
        match f.branch_map_into(grid, m, &mut out, &cancelled) {
            Err(Error::Cancelled { done, total }) => {
                assert_eq!((done, total), (0, grid.ny()));
            }
            other => panic!("a cancelled {m:?} map gave {other:?}"),
        }
    }
    assert!(matches!(
        f.margin_map_into(grid, &mut margins, &cancelled),
        Err(Error::Cancelled { .. })
    ));
    let mut short = vec![false; grid.len() - 1];
    assert!(matches!(
        f.branch_map_into(grid, Method::Conic, &mut short, &Control::new()),
        Err(Error::InvalidInput(InvalidInput::LengthMismatch { .. }))
    ));
    assert!(matches!(
        f.branch_map_pointwise_into(grid, &mut short),
        Err(Error::InvalidInput(InvalidInput::LengthMismatch { .. }))
    ));
}

fn grid_viewport(g: &Grid) -> burmester::Result<Viewport> {
    let v = g.viewport();
    Viewport::new(v.xmin, v.xmax, v.ymin, v.ymax)
}

/// The default polylines of `c` on `vp` (see [`check_polylines`]).
fn polylines(c: &Conic, vp: &Viewport) {
    let _ = check_polylines(c, vp, None);
}

/// `c.polylines(vp, tolerance)`: an error only for a viewport whose
/// diagonal is beyond [`Conic::MAX_VIEWPORT_DIAGONAL`] (first), a
/// tolerance outside `[Conic::MIN_RELATIVE_TOLERANCE, 1]` times the
/// viewport's diagonal ([`InvalidInput::OutsideRange`]) or a curve that
/// needs more than [`Conic::MAX_POLYLINE_POINTS`] points
/// ([`InvalidInput::TooLarge`]);
/// otherwise at most that many finite points, in the viewport, in polylines
/// of two points or more that do not stay on one point. Returns the result.
fn check_polylines(
    c: &Conic,
    vp: &Viewport,
    tolerance: Option<f64>,
) -> burmester::Result<Vec<Vec<Point2<f64>>>> {
    let diag = vp.diagonal();
    let huge = diag.is_nan() || diag > Conic::MAX_VIEWPORT_DIAGONAL;
    let in_range =
        tolerance.is_none_or(|t| (Conic::MIN_RELATIVE_TOLERANCE * diag..=diag).contains(&t));
    let lines = match c.polylines(vp, tolerance) {
        Ok(lines) => lines,
        Err(e) => {
            message(&e);
            if huge {
                assert!(
                    matches!(
                        &e,
                        Error::InvalidInput(InvalidInput::TooLarge {
                            name: "viewport diagonal",
                            ..
                        })
                    ),
                    "polylines on a huge {vp:?}: {e}"
                );
                return Err(e);
            }
            match &e {
                Error::InvalidInput(InvalidInput::OutsideRange { name, .. }) => {
                    assert_eq!(*name, "tolerance");
                    assert!(!in_range, "tolerance {tolerance:?} refused on {vp:?}: {e}");
                }
                Error::InvalidInput(InvalidInput::TooLarge { .. }) => {
                    assert!(in_range, "tolerance {tolerance:?}: {e}");
                }
                other => panic!("polylines of {c:?} on {vp:?}: {other:?}"),
            }
            return Err(e);
        }
    };
    assert!(!huge, "a viewport of diagonal {diag} accepted");
    assert!(in_range, "tolerance {tolerance:?} accepted on {vp:?}");
    let total: usize = lines.iter().map(Vec::len).sum();
    assert!(total <= Conic::MAX_POLYLINE_POINTS, "{total} points");
    let (w, h) = vp.size();
    // Rounding of the conic's local frame (origin and unit) comes on top.
    let (_, origin, unit) = c.local_coefficients();
    let slack = 1e-14 * (origin.x.abs() + origin.y.abs() + unit)
        + 1e-6 * (w + h)
        + 1e-9 * (vp.xmax.abs().max(vp.xmin.abs()) + vp.ymax.abs().max(vp.ymin.abs()));
    for l in &lines {
        assert!(l.len() >= 2);
        assert!(l.iter().any(|p| *p != l[0]), "a polyline on one point");
        for &p in l {
            assert!(
                p.x.is_finite() && p.y.is_finite(),
                "polyline point {p:?} of {c:?} on {vp:?}, tolerance {tolerance:?}"
            );
            assert!(
                p.x >= vp.xmin - slack
                    && p.x <= vp.xmax + slack
                    && p.y >= vp.ymin - slack
                    && p.y <= vp.ymax + slack,
                "polyline point {p:?} outside {vp:?}: {c:?} {:?}",
                c.kind()
            );
        }
    }
    Ok(lines)
}

/// General conics: kind, center, axes, asymptotes, evaluation, polylines.
pub fn conic(data: &[u8]) {
    let mut inp = Input::new(data);
    let q = [0; 6].map(|_| inp.num());
    let c = match Conic::new(q[0], q[1], q[2], q[3], q[4], q[5]) {
        Ok(c) => c,
        Err(e) => return message(&e),
    };
    let moderate = inp.moderate;
    let kind = c.kind();
    let _ = c.is_degenerate();
    for v in c.coefficients() {
        finite("coefficient", v);
    }
    // The stored form rebuilds the same conic, bit for bit.
    let (q, origin, unit, known) = c.to_parts();
    same(
        "from_parts of to_parts",
        &Conic::from_parts(q, origin, unit, known),
        &Ok(c),
    );
    finite("axis angle", c.axis_angle());
    if let Some(p) = c.center() {
        finite_pt("center", p);
    }
    if let Some(a) = c.asymptotes() {
        assert_eq!(kind, burmester::ConicKind::Hyperbola);
        for l in a {
            finite_pt("asymptote", l.point);
            assert!((l.direction.norm() - 1.0).abs() < 1e-9);
        }
    }
    for _ in 0..inp.count(1, 4) {
        let p = inp.point();
        let moderate = moderate && inp.moderate;
        let v = c.evaluate(p);
        match c.try_evaluate(p) {
            Ok(t) => {
                assert!(p.x.is_finite() && p.y.is_finite());
                assert_eq!(
                    t.to_bits(),
                    v.to_bits(),
                    "try_evaluate and evaluate at {p:?}"
                );
                // Finite for every finite point (far points are scaled).
                finite("value", t);
            }
            Err(e) => {
                assert!(
                    !(p.x.is_finite() && p.y.is_finite()),
                    "try_evaluate at {p:?}"
                );
                message(&e);
            }
        }
        if p.x.is_finite() && p.y.is_finite() && moderate {
            finite("value", v);
            let g = c.gradient(p);
            finite("gradient", g.x);
            finite("gradient", g.y);
            assert!(!c.distance_estimate(p).is_nan());
        }
        let _ = c.side(p);
        let w = Vector2::new(inp.nice(), inp.nice());
        if p.x.is_finite() && p.y.is_finite() && w.norm() > 0.0 {
            for x in c.intersect_line(&Line {
                point: p,
                direction: w,
            }) {
                finite_pt("intersection", x);
            }
        }
    }
    let (x0, y0, w, h) = (inp.num(), inp.num(), inp.num().abs(), inp.num().abs());
    if let Ok(vp) = Viewport::new(x0, x0 + w, y0, y0 + h) {
        polylines(&c, &vp);
    }
}

/// The work parameters of [`Conic::polylines`]: the chord tolerance (none,
/// the default given explicitly, anywhere in its range and at both ends,
/// just outside it, raw numbers) and the point budget, on general, nearly
/// degenerate and closed curves, on viewports at and around the curve.
pub fn conic_polylines(data: &[u8]) {
    let mut inp = Input::new(data);
    let q: [f64; 6] = match inp.byte() % 4 {
        0 => [0; 6].map(|_| inp.num()),
        1 => [0; 6].map(|_| inp.nice()),
        // Nearly a line pair: (a x + b y + c)(d x + e y + f) + eps.
        2 => {
            let l = [0; 6].map(|_| inp.nice());
            let eps = inp.nice() * 10f64.powi(-i32::from(inp.byte() % 17));
            [
                l[0] * l[3],
                l[0] * l[4] + l[1] * l[3],
                l[1] * l[4],
                l[0] * l[5] + l[2] * l[3],
                l[1] * l[5] + l[2] * l[4],
                l[2] * l[5] + eps,
            ]
        }
        // An ellipse (or circle) with center, radii and axis angle.
        _ => {
            let (cx, cy) = (inp.nice(), inp.nice());
            let (ra, rb) = (inp.nice(), inp.nice());
            let t = inp.nice();
            let (s, c) = t.sin_cos();
            let (ia, ib) = (1.0 / (ra * ra), 1.0 / (rb * rb));
            let a = c * c * ia + s * s * ib;
            let b = 2.0 * c * s * (ia - ib);
            let cc = s * s * ia + c * c * ib;
            [
                a,
                b,
                cc,
                -2.0 * a * cx - b * cy,
                -b * cx - 2.0 * cc * cy,
                a * cx * cx + b * cx * cy + cc * cy * cy - 1.0,
            ]
        }
    };
    let c = match Conic::new(q[0], q[1], q[2], q[3], q[4], q[5]) {
        Ok(c) => c,
        Err(e) => return message(&e),
    };
    let vp = match inp.byte() % 3 {
        0 => {
            let (x0, y0, w, h) = (inp.num(), inp.num(), inp.num().abs(), inp.num().abs());
            Viewport::new(x0, x0 + w, y0, y0 + h)
        }
        // Around the curve's center (or the origin), of a chosen size.
        _ => {
            let at = c.center().unwrap_or_else(Point2::origin);
            let half = 10f64.powi(i32::from(inp.byte() % 25) - 12) * (1.0 + inp.nice().abs());
            let aspect = 1.0 + inp.nice().abs();
            let off = Vector2::new(inp.nice(), inp.nice()) * half;
            let m = at + off;
            Viewport::new(
                m.x - half,
                m.x + half,
                m.y - half * aspect,
                m.y + half * aspect,
            )
        }
    };
    let vp = match vp {
        Ok(vp) => vp,
        Err(e) => return message(&e),
    };
    let diag = vp.diagonal();
    let lo = Conic::MIN_RELATIVE_TOLERANCE * diag;
    let tolerance = match inp.byte() % 7 {
        0 => None,
        // The documented default, given explicitly: the same answer.
        1 => {
            let none = check_polylines(&c, &vp, None);
            let given = check_polylines(&c, &vp, Some(diag * 1e-3));
            same("None and the default tolerance", &none, &given);
            return;
        }
        // Across the range: diag * 10^-k, k in 0..=9 (both ends exactly).
        2 => Some(if inp.byte() % 10 == 9 {
            lo
        } else {
            diag * 10f64.powi(-i32::from(inp.byte() % 10))
        }),
        // Just outside the range.
        3 => Some(match inp.byte() % 4 {
            0 => f64::from_bits(lo.to_bits().saturating_sub(1)),
            1 => f64::from_bits(diag.to_bits() + 1),
            2 => 0.0,
            _ => -diag,
        }),
        // Raw numbers: NaN, infinities, signs, anything.
        4 => Some(inp.num()),
        // A fraction of the diagonal.
        _ => Some(diag * (inp.nice().abs() % 1.0)),
    };
    let _ = check_polylines(&c, &vp, tolerance);
}

/// Checks the arrays of a solution map: lengths, and the documented
/// relations between them (no unflagged NaN).
fn check_solution_map(map: &SolutionMap) {
    check_columns(&map.columns, map.context.grid.len(), &map.context.limits);
}

/// The documented relations between the columns of a map of `n` samples
/// under `limits` (the solution map's, the pair map's).
fn check_columns(c: &burmester::design::Columns, n: usize, limits: &DesignLimits) {
    for len in [
        c.valid.len(),
        c.branch_free.len(),
        c.grashof.len(),
        c.input_full.len(),
        c.direction.len(),
        c.one_circuit.len(),
        c.min_transmission_rad.len(),
        c.link_ratio.len(),
        c.acceptable.len(),
    ] {
        assert_eq!(len, n);
    }
    for k in 0..n {
        let direction = Direction::from_code(c.direction[k]);
        assert_eq!(direction.code(), c.direction[k], "direction code");
        if c.acceptable[k] {
            assert!(
                c.valid[k] && c.branch_free[k] && direction != Direction::None && c.one_circuit[k]
            );
            let t = f64::from(c.min_transmission_rad[k]);
            // The limits hold in f64; the column is rounded to f32.
            assert!(
                t >= limits.min_transmission * (1.0 - 1e-6) - 1e-7,
                "acceptable with transmission {t} below {}",
                limits.min_transmission
            );
            let r = f64::from(c.link_ratio[k]);
            // (A ratio beyond f32::MAX is infinite in the column.)
            assert!(
                r <= limits.max_link_ratio * (1.0 + 1e-6) || r.is_infinite(),
                "acceptable with link ratio {r} above {}",
                limits.max_link_ratio
            );
            match limits.input {
                InputRequirement::Any => {}
                InputRequirement::Crank => assert!(c.input_full[k]),
                InputRequirement::Rocker => assert!(!c.input_full[k]),
            }
        }
        if !c.valid[k] {
            assert!(!c.acceptable[k] && !c.branch_free[k] && c.direction[k] == 0);
            assert!(!c.input_full[k] && !c.one_circuit[k]);
            assert_eq!(c.grashof[k], SolutionMap::GRASHOF_NONE);
            assert!(c.min_transmission_rad[k].is_nan() && c.link_ratio[k].is_nan());
            continue;
        }
        assert!(Grashof::from_code(c.grashof[k]).is_some());
        let r = c.link_ratio[k];
        assert!(r >= 1.0, "link ratio {r}");
        let t = c.min_transmission_rad[k];
        if direction == Direction::None {
            assert!(t.is_nan(), "transmission {t} without a travel");
        } else {
            assert!(
                (0.0..=core::f32::consts::FRAC_PI_2 + 1e-6).contains(&t),
                "transmission {t}"
            );
        }
    }
}

/// The solution-space map in both directions, on small grids anywhere, with
/// arbitrary limits and constraints; the best pivots of each.
pub fn solution_map(data: &[u8]) {
    let mut inp = Input::new(data);
    let Some(t) = task(&mut inp) else { return };
    let s = t.scale();
    let p12 = finite_poles(&t)[0];
    let near = |inp: &mut Input<'_>, _: &Task| p12 + Vector2::new(inp.nice(), inp.nice()) * s;
    let c0 = if inp.byte() % 2 == 0 {
        inp.point()
    } else {
        near(&mut inp, &t)
    };
    let f = match t.filemon(c0) {
        Ok(f) => f,
        Err(e) => return message(&e),
    };
    let (a, b) = if inp.byte() % 2 == 0 {
        (inp.point(), inp.point())
    } else {
        (near(&mut inp, &t), near(&mut inp, &t))
    };
    let vp = match Viewport::new(a.x.min(b.x), a.x.max(b.x), a.y.min(b.y), a.y.max(b.y)) {
        Ok(v) => v,
        Err(e) => return message(&e),
    };
    let grid = match Grid::new(vp, inp.count(1, 12), inp.count(1, 12)) {
        Ok(g) => g,
        Err(e) => return message(&e),
    };
    let limits = limits_of(&mut inp);
    let constraints = constraints_of(&mut inp, &|inp| near(inp, &t), s);
    let Some(options) = map_options(&limits, &constraints) else {
        return;
    };
    let control = Control::new();
    match f.solution_map(&grid, &options, &control) {
        Err(e) => message(&e),
        Ok(map) => {
            check_solution_map(&map);
            check_cancelled(f.solution_map(&grid, &options, &cancelled()));
            check_pivots(&map, inp.count(0, 4), None);
        }
    }
    // The other direction, with the driving dyad at a probe point.
    let a0 = near(&mut inp, &t);
    if let Ok(driving) = t.dyad_from_center(a0) {
        match t.driven_solution_map(&driving, &grid, &options, &control) {
            Err(e) => message(&e),
            Ok(map) => {
                check_solution_map(&map);
                check_cancelled(t.driven_solution_map(&driving, &grid, &options, &cancelled()));
                check_pivots(&map, 2, Some(0.0));
            }
        }
    }
}

/// A control whose cancel flag is set.
fn cancelled() -> Control<'static> {
    static STOP: AtomicBool = AtomicBool::new(true);
    Control::new().with_cancel(&STOP)
}

/// A map that succeeds uncancelled is [`Error::Cancelled`] when cancelled
/// before it starts.
fn check_cancelled(r: burmester::Result<SolutionMap>) {
    match r {
        Err(Error::Cancelled { done, .. }) => assert_eq!(done, 0),
        other => panic!("a cancelled solution map gave {other:?}"),
    }
}

/// The `k` best pivots of `map` by each ranking: at most `k`, each a sample
/// its ranking admits (acceptable by transmission, valid and branch-free by
/// margin) with its linkage and a positive margin, farther than the
/// separation from every better one, best first.
fn check_pivots(map: &SolutionMap, k: usize, min_separation: Option<f64>) {
    let c = &map.columns;
    let nx = map.context.grid.nx();
    let sep = min_separation.unwrap_or(0.02 * map.context.grid.viewport().diagonal());
    for rank in RankBy::ALL {
        let pivots = map
            .best_pivots(Ranking::try_new(k, min_separation, rank).expect("a valid separation"))
            .expect("a valid ranking");
        assert!(pivots.len() <= k);
        for (n, p) in pivots.iter().enumerate() {
            let (j, i) = p.index;
            let s = j * nx + i;
            assert!(i < nx && s < map.context.grid.len(), "index {:?}", p.index);
            assert_eq!(p.center, map.context.point(s));
            assert_eq!(p.ranked_by, rank);
            finite_pt("pivot", p.center);
            assert!(p.linkage.figures.link_ratio >= 1.0);
            assert!(
                p.margin > 0.0,
                "pivot {:?} by {rank:?} with margin {}",
                p.index,
                p.margin
            );
            assert!(p.size_ratio.is_finite() && p.size_ratio > 0.0);
            match rank {
                RankBy::Margin => assert!(c.valid[s] && c.branch_free[s]),
                _ => assert!(c.acceptable[s]),
            }
            for q in &pivots[..n] {
                assert!(
                    (q.center - p.center).norm() >= sep,
                    "pivots closer than {sep}"
                );
                match rank {
                    // The front from compact to transmitting.
                    RankBy::Pareto => assert!(q.score < p.score, "front out of order"),
                    _ => assert!(q.score >= p.score - 2e-9, "scores out of order"),
                }
            }
        }
    }
    for bad in [-1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            Ranking::try_new(k, Some(bad), RankBy::Transmission),
            Err(Error::InvalidInput(InvalidInput::OutsideRange { .. }))
        ));
    }
}

/// Limits from the input: raw numbers now and then, else in range.
fn limits_of(inp: &mut Input<'_>) -> DesignLimits {
    DesignLimits {
        min_transmission: if inp.byte() % 4 == 0 {
            inp.num()
        } else {
            inp.nice().abs() % 1.5
        },
        max_link_ratio: if inp.byte() % 4 == 0 {
            inp.num()
        } else {
            1.0 + inp.nice().abs()
        },
        input: [
            InputRequirement::Any,
            InputRequirement::Crank,
            InputRequirement::Rocker,
        ][usize::from(inp.byte()) % 3],
        ..DesignLimits::default()
    }
}

/// Constraints from the input around `near` (a point of the task scaled
/// by `s`): polygons of up to five vertices (raw or near), a link width,
/// up to 16 travel samples (0 and 1 are refused).
fn constraints_of(
    inp: &mut Input<'_>,
    near: &dyn Fn(&mut Input<'_>) -> Point2<f64>,
    s: f64,
) -> Constraints {
    let polygon = |inp: &mut Input<'_>| -> Vec<Point2<f64>> {
        let n = inp.count(0, 5);
        (0..n)
            .map(|_| {
                if inp.byte() % 4 == 0 {
                    inp.point()
                } else {
                    near(inp)
                }
            })
            .collect()
    };
    Constraints {
        base_plate: if inp.byte() % 2 == 0 {
            Some(polygon(inp))
        } else {
            None
        },
        obstacles: (0..inp.count(0, 2)).map(|_| polygon(inp)).collect(),
        link_width: if inp.byte() % 3 == 0 {
            inp.num()
        } else {
            inp.nice().abs() * s * 0.1
        },
        travel_samples: inp.count(0, 16),
        // The envelope (design's `Space`) is exercised by the design
        // search's tests, not here.
        envelope: None,
    }
}

/// The limits, with a transmission limit of at least 0.05 rad where
/// there are obstacles: below it the clearance refinement takes `1 /
/// sin(mu_min)` times the work (the open class of `fuzz/README.md`, slow
/// by design), which would make every input a timeout.
fn away_from_the_slow_class(mut limits: DesignLimits, c: &Constraints) -> DesignLimits {
    if !c.obstacles.is_empty() && (0.0..0.05).contains(&limits.min_transmission) {
        limits.min_transmission = 0.05;
    }
    limits
}

/// Four poses: raw, or moderate with a chosen near-degeneracy (poses 1 and
/// 2 nearly alike, one angle, a repeated angle, scaled).
fn four_poses(inp: &mut Input<'_>) -> Option<Task> {
    let mut p: Vec<Pose> = if inp.byte() % 4 == 0 {
        (0..4).map(|_| pose(inp)).collect()
    } else {
        (0..4)
            .map(|_| Pose::new(inp.nice(), inp.nice(), inp.nice()))
            .collect()
    };
    match inp.byte() % 8 {
        0 => {
            // Poses 1 and 2 a hair apart.
            let e = 10f64.powi(-i32::from(inp.byte() % 16));
            p[1] = Pose::new(
                p[0].position.x + inp.nice() * e,
                p[0].position.y + inp.nice() * e,
                p[0].angle + inp.nice() * e,
            );
        }
        1 => {
            // One angle.
            for k in 1..4 {
                p[k].angle = p[0].angle;
            }
        }
        2 => {
            // Two poses of one angle.
            let (i, j) = (usize::from(inp.byte()) % 4, usize::from(inp.byte()) % 4);
            p[j].angle = p[i].angle;
        }
        3 => scale(inp, &mut p),
        _ => {}
    }
    task_of(&p)
}

/// The four-position pair map on small grids of both axes, with arbitrary
/// limits and constraints: the column relations; a progress hook changes
/// nothing and a cancelled map is `Cancelled`; each acceptable pair's
/// linkage exists and is `Task::four_bar` of its dyads; the margins' sign
/// is the branch flag; the best pairs of every ranking are what their
/// ranking admits, in order, apart.
pub fn pair_map(data: &[u8]) {
    let mut inp = Input::new(data);
    let Some(t) = four_poses(&mut inp) else {
        return;
    };
    let s = t.scale();
    let o = t.poses()[0].position;
    let near = |inp: &mut Input<'_>| o + Vector2::new(inp.nice(), inp.nice()) * s;
    let (nd, nv) = (inp.count(0, 12), inp.count(0, 12));
    let limits = limits_of(&mut inp);
    let constraints = constraints_of(&mut inp, &near, s);
    let limits = away_from_the_slow_class(limits, &constraints);
    if std::env::var_os("FUZZ_DEBUG").is_some() {
        eprintln!("{:?}\n{nd} x {nv}\n{limits:?}\n{constraints:?}", t.poses());
    }
    let Some(options) = map_options(&limits, &constraints) else {
        return;
    };
    let map = match t.pair_map(nd, nv, &options, &Control::new()) {
        Ok(m) => m,
        Err(e) => return message(&e),
    };
    let n = nd * nv;
    assert_eq!(map.context.shape(), (nv, nd));
    assert_eq!(
        (map.context.driving.len(), map.context.driven.len()),
        (nd, nv)
    );
    check_columns(&map.columns, n, &limits);
    // Progress and cancelling.
    let last = AtomicUsize::new(0);
    let hook = |d: usize, _t: usize| {
        last.fetch_max(d, Ordering::Relaxed);
    };
    let again = t
        .pair_map(nd, nv, &options, &Control::new().with_progress(&hook))
        .expect("the same map with a progress hook");
    same("pair map with progress", &again, &map);
    assert!(matches!(
        t.pair_map(nd, nv, &options, &cancelled()),
        Err(Error::Cancelled { .. })
    ));
    let c = &map.columns;
    for k in 0..n {
        if c.acceptable[k] {
            let l = map
                .context
                .linkage(k)
                .expect("an acceptable pair has a linkage");
            let (a, b) = map.context.dyads(k).expect("both dyads finite");
            same(
                "the pair's linkage",
                &t.four_bar(&a.dyad(), &b.dyad())
                    .expect("four_bar of the dyads"),
                &l,
            );
            finite("size", l.size());
        }
    }
    let margins = map.margins().expect("margins of a small map");
    for (k, m) in margins.iter().enumerate() {
        assert_eq!(*m > 0.0, c.branch_free[k], "margin sign at {k}");
    }
    let diag = map.context.grid.viewport().diagonal();
    for sep in [None, Some(0.0), Some(inp.nice().abs() * diag * 0.1)] {
        let k = inp.count(0, 4);
        if sep.is_some_and(|s| !s.is_finite()) {
            assert!(matches!(
                Ranking::try_new(k, sep, RankBy::Balanced),
                Err(Error::InvalidInput(InvalidInput::OutsideRange { .. }))
            ));
            continue;
        }
        for rank in RankBy::ALL {
            let ranking = Ranking::try_new(k, sep, rank).expect("a valid separation");
            let pairs = map.best_pairs(ranking).expect("a valid ranking");
            assert!(pairs.len() <= k);
            let sep = sep.unwrap_or(0.02 * diag);
            let at = |p: &burmester::Pair| {
                Point2::new(map.context.grid.x(p.index.1), map.context.grid.y(p.index.0))
            };
            for (m, p) in pairs.iter().enumerate() {
                let s_ = p.index.0 * nd + p.index.1;
                assert!(s_ < n);
                assert_eq!(p.ranked_by, rank);
                match rank {
                    RankBy::Margin => assert!(c.valid[s_] && c.branch_free[s_]),
                    _ => assert!(c.acceptable[s_]),
                }
                assert!(
                    p.margin > 0.0,
                    "pair {:?} by {rank:?}: margin {}",
                    p.index,
                    p.margin
                );
                assert_eq!(p.margin, margins[s_], "margin of {:?}", p.index);
                for q in &pairs[..m] {
                    assert!((at(q) - at(p)).norm() >= sep, "pairs closer than {sep}");
                    match rank {
                        RankBy::Pareto => assert!(q.score < p.score, "front out of order"),
                        _ => assert!(q.score >= p.score - 2e-9, "scores out of order"),
                    }
                }
            }
        }
    }
}

/// The pivot-pair atlas with constraints on small grids anywhere: each
/// valid cell is its driven center's solution map reduced (the count of
/// acceptable samples, of branch-free ones, and the first pivot of
/// `best_pivots(1, 0, Transmission)`), an invalid cell has no Filemon
/// construction; any split of the driven rows gives the same cells; a
/// cancelled atlas is `Cancelled`; progress reaches its total.
pub fn atlas(data: &[u8]) {
    let mut inp = Input::new(data);
    let Some(t) = task(&mut inp) else { return };
    let s = t.scale();
    let p12 = finite_poles(&t)[0];
    let near = |inp: &mut Input<'_>| p12 + Vector2::new(inp.nice(), inp.nice()) * s;
    let grid = |inp: &mut Input<'_>, most: usize| -> Option<Grid> {
        let (a, b) = if inp.byte() % 4 == 0 {
            (inp.point(), inp.point())
        } else {
            (near(inp), near(inp))
        };
        let vp = match Viewport::new(a.x.min(b.x), a.x.max(b.x), a.y.min(b.y), a.y.max(b.y)) {
            Ok(v) => v,
            Err(e) => {
                message(&e);
                return None;
            }
        };
        match Grid::new(vp, inp.count(1, most), inp.count(1, most)) {
            Ok(g) => Some(g),
            Err(e) => {
                message(&e);
                None
            }
        }
    };
    let Some(driven) = grid(&mut inp, 3) else {
        return;
    };
    let Some(driving) = grid(&mut inp, 8) else {
        return;
    };
    let limits = limits_of(&mut inp);
    let constraints = constraints_of(&mut inp, &near, s);
    let limits = away_from_the_slow_class(limits, &constraints);
    if std::env::var_os("FUZZ_DEBUG").is_some() {
        eprintln!(
            "{:?}\n{driven:?}\n{driving:?}\n{limits:?}\n{constraints:?}",
            t.poses()
        );
    }
    let Some(options) = map_options(&limits, &constraints) else {
        return;
    };
    let last = AtomicUsize::new(0);
    let hook = |d: usize, total: usize| {
        assert!(d <= total);
        last.fetch_max(d, Ordering::Relaxed);
    };
    let atlas = match t.pivot_atlas(
        &driven,
        &driving,
        &options,
        RankBy::Transmission,
        &Control::new().with_progress(&hook),
    ) {
        Ok(a) => a,
        Err(e) => return message(&e),
    };
    assert_eq!(
        last.into_inner(),
        driven.len() * driving.ny(),
        "progress total"
    );
    assert_eq!(atlas.cells.len(), driven.len());
    for (k, cell) in atlas.cells.iter().enumerate() {
        let c0 = driven.point(k % driven.nx(), k / driven.nx());
        let Ok(f) = t.filemon(c0) else {
            assert_eq!(*cell, burmester::AtlasCell::INVALID, "cell {k}");
            continue;
        };
        assert!(cell.valid, "cell {k} at {c0}");
        let map = f
            .solution_map(&driving, &options, &Control::new())
            .expect("the atlas's own map");
        let col = &map.columns;
        let count = col.acceptable.iter().filter(|&&a| a).count() as u64;
        let free = col.branch_free.iter().filter(|&&a| a).count() as u64;
        assert_eq!(
            (cell.count, cell.branch_free),
            (count, free),
            "cell {k} at {c0}"
        );
        let first = Ranking::new(1, RankBy::Transmission).with_separation(0.0);
        let best = map
            .best_pivots(first.expect("a valid separation"))
            .expect("best pivots");
        match (&cell.best, best.first()) {
            (None, None) => {}
            (Some(b), Some(p)) => {
                assert_eq!(b.index, p.index, "cell {k}: best pivot");
                assert_eq!(b.driving, p.center);
                assert_eq!(f64::from(b.min_transmission_rad), p.score);
                assert_eq!(b.margin, p.margin);
            }
            (a, b) => panic!("cell {k}: atlas best {a:?}, map best {b:?}"),
        }
    }
    // Tiles: any split of the driven rows.
    let cut = inp.count(0, driven.ny());
    let mut tiled = t
        .pivot_atlas_rows(
            &driven,
            0..cut,
            &driving,
            &options,
            RankBy::Transmission,
            &Control::new(),
        )
        .expect("the first tile");
    tiled.extend(
        t.pivot_atlas_rows(
            &driven,
            cut..driven.ny(),
            &driving,
            &options,
            RankBy::Transmission,
            &Control::new(),
        )
        .expect("the second tile"),
    );
    same("tiled atlas", &tiled, &atlas.cells);
    assert!(matches!(
        t.pivot_atlas(
            &driven,
            &driving,
            &options,
            RankBy::Transmission,
            &cancelled()
        ),
        Err(Error::Cancelled { .. })
    ));
}

// ---------------------------------------------------------------------------
// Four and five poses (issue 24): the Burmester curves, the branch-free
// arcs in any view, the library's own points on its curves, and the
// Burmester points (counts, sliders, degenerate tasks, frames).
// ---------------------------------------------------------------------------

use burmester::Similarity;
use burmester::synthesis::{FilemonArcs, FivePositions, FourPositions};

#[path = "../../tests/rust/common/curve_dyads.rs"]
mod curve_dyads;
#[path = "../../tests/rust/common/five_count.rs"]
mod five_count;

/// `n` poses: raw numbers, or moderate ones with a chosen structure: nearly
/// rotations about one point (curves whose coefficients cancel), three
/// rotations about one point, pure translations, poses at one position,
/// collinear positions, three of one angle on a line, Cardan motion;
/// moved and scaled anywhere.
fn structured_poses(inp: &mut Input<'_>, n: usize) -> Vec<Pose> {
    let mut p: Vec<Pose> = match inp.byte() % 4 {
        0 => (0..n).map(|_| pose(inp)).collect(),
        _ => (0..n)
            .map(|_| Pose::new(inp.nice(), inp.nice(), inp.nice()))
            .collect(),
    };
    let c = Point2::new(inp.nice(), inp.nice());
    match inp.byte() % 9 {
        // Nearly rotations about c (or exactly, for the first three).
        0 | 1 => {
            let exact = inp.byte() % 2 == 0;
            let jitter = 10f64.powi(-i32::from(inp.byte() % 13));
            let (p0, a0) = (p[0].position, p[0].angle);
            for (k, q) in p.iter_mut().enumerate().skip(1) {
                let t = q.angle - a0;
                let (s, co) = t.sin_cos();
                let v = p0 - c;
                let off = if exact && k < 3 { 0.0 } else { jitter };
                q.position = c
                    + Vector2::new(co * v.x - s * v.y, s * v.x + co * v.y)
                    + Vector2::new(off * inp.nice(), off * inp.nice());
            }
        }
        // Pure translations: pairs of one angle.
        2 => {
            let k = usize::from(inp.byte()) % n;
            let j = usize::from(inp.byte()) % n;
            p[k].angle = p[j].angle;
            let k = usize::from(inp.byte()) % n;
            let j = usize::from(inp.byte()) % n;
            p[k].angle = p[j].angle;
        }
        // Two poses at one position.
        3 => {
            let k = usize::from(inp.byte()) % n;
            let j = usize::from(inp.byte()) % n;
            p[k].position = p[j].position;
        }
        // Collinear positions (or three of them of one angle).
        4 | 5 => {
            let d = Vector2::new(inp.nice(), inp.nice());
            let same = inp.byte() % 2 == 0;
            for (k, q) in p.iter_mut().enumerate() {
                q.position = c + d * (k as f64 + 0.1 * inp.nice());
                if same && k < 3 {
                    q.angle = 0.3;
                }
            }
        }
        // Cardan motion.
        6 => {
            let r = inp.nice();
            for q in &mut p {
                let f = q.angle;
                q.position = Point2::new(c.x + r * f.cos(), c.y);
                q.angle = core::f64::consts::PI - f;
            }
        }
        _ => {}
    }
    // Moved and scaled.
    if inp.byte() % 2 == 0 {
        let k = 10f64.powi(i32::from(inp.byte() % 25) - 12);
        let off = Vector2::new(inp.nice(), inp.nice()) * 10f64.powi(i32::from(inp.byte() % 13) - 6);
        for q in &mut p {
            q.position = Point2::from(q.position.coords * k + off);
        }
    }
    p
}

/// Whether every coordinate of the poses is moderate and their size is
/// not far below their distance from the origin (a task whose own rounding
/// is not of its size).
fn moderate_task(poses: &[Pose], size: f64) -> bool {
    poses.iter().all(|p| {
        let a = [p.position.x.abs(), p.position.y.abs(), p.angle.abs()];
        a.iter().all(|&v| v == 0.0 || (1e-50..=1e50).contains(&v))
            && p.position.coords.norm() <= 1e6 * size
            && p.angle.abs() <= 100.0
    })
}

/// Four poses: the curves, the crank-rotation dyads and parameter samples
/// accepted back by the on-curve test (never `OffCurve`), the traced
/// vertices of both curves accepted back, and the branch-free arcs of a
/// driven dyad in two views against `classify` at every arc vertex and at
/// the curve's point at the middle of every chord (free, away from the arc
/// ends and `C0`).
pub fn curves(data: &[u8]) {
    let mut inp = Input::new(data);
    let poses = structured_poses(&mut inp, 4);
    let four = match FourPositions::new(&poses) {
        Ok(f) => f,
        Err(e) => return message(&e),
    };
    let size = four.size();
    assert!(size.is_finite() && size > 0.0);
    let moderate = moderate_task(&poses, size);
    let off_curve = |r: &burmester::Result<Point2<f64>>| {
        matches!(r, Err(Error::InvalidInput(InvalidInput::OffCurve { .. })))
    };
    let n = inp.count(1, 24);
    let dyads = curve_dyads::own_curve_dyads(&four, n);
    for d in &dyads {
        finite_pt("curve dyad center", d.center);
        finite_pt("curve dyad circle", d.circle);
        let z = four.circle_point(d.center);
        assert!(
            !off_curve(&z),
            "own center {} refused: {z:?} (poses {poses:?})",
            d.center
        );
        let g = four.center_point(d.circle);
        assert!(
            !off_curve(&g),
            "own circle point {} refused: {g:?}",
            d.circle
        );
        if let Ok(z) = z {
            finite_pt("circle point", z);
        }
    }
    if !moderate {
        return;
    }
    let o = poses
        .iter()
        .fold(Vector2::zeros(), |a, p| a + p.position.coords / 4.0);
    let view = |inp: &mut Input<'_>, at: Point2<f64>| {
        let h = size * 10f64.powi(i32::from(inp.byte() % 5) - 2) * (1.0 + inp.byte() as f64 / 64.0);
        let c = at + Vector2::new(inp.nice(), inp.nice()) * (size * 1e-2);
        Viewport::new(c.x - h, c.x + h, c.y - h, c.y + h).ok()
    };
    if let Some(vp) = view(&mut inp, Point2::from(o)) {
        // Every traced point of each curve is taken by its map.
        type Map = fn(&FourPositions, Point2<f64>) -> burmester::Result<Point2<f64>>;
        for (curve, map, what) in [
            (
                four.center_point_curve(),
                FourPositions::circle_point as Map,
                "",
            ),
            (
                four.circle_point_curve(),
                FourPositions::center_point,
                "circle point ",
            ),
        ] {
            for p in curve.polylines(&vp).into_iter().flatten() {
                let r = map(&four, p);
                assert!(
                    !off_curve(&r),
                    "traced {what}{p} refused: {r:?} (poses {poses:?}, view {vp:?})"
                );
            }
        }
    }
    if dyads.is_empty() {
        return;
    }
    let driven = dyads[usize::from(inp.byte()) % dyads.len()].dyad();
    if !(driven.length() > 1e-2 * size && driven.length() < 1e3 * size) {
        return;
    }
    let arcs = match four.filemon(&driven) {
        Ok(a) => a,
        Err(e) => return message(&e),
    };
    // The arcs against the classifier where the classes are decided well:
    // rotations of at least `tolerance::MIN_ROTATION` between every two poses
    // (below it the maps are within rounding of a pure translation's), and
    // no arc end within a millionth of the task of C1 (an extreme line all
    // but tangent to the curve there: its second meet is known only to
    // rounding over the angle).
    let turned = (0..4).all(|i| {
        (i + 1..4).all(|j| {
            let d = (poses[j].angle - poses[i].angle).rem_euclid(core::f64::consts::TAU);
            d.min(core::f64::consts::TAU - d) >= burmester::tolerance::MIN_ROTATION
        })
    });
    let apart = arcs
        .arc_ends()
        .iter()
        .all(|e| (e.circle - driven.circle).norm() > 1e-6 * size);
    if !(turned && apart) {
        return;
    }
    for at in [Point2::from(o), driven.center] {
        if let Some(vp) = view(&mut inp, at) {
            check_free_arcs(&four, &arcs, &vp);
        }
    }
}

/// The free arcs of both planes in `vp`: vertices free, and the curve's
/// point at the middle of each chord free unless it is within a millionth
/// of the view of an arc end or `C0`/`C1` (where the class is rounding) or
/// the curve there is not the chord's (another branch nearer).
fn check_free_arcs(four: &FourPositions, arcs: &FilemonArcs, vp: &Viewport) {
    let diag = vp.diagonal();
    for circle in [false, true] {
        let (lines, curve) = if circle {
            (
                arcs.free_circle_arcs(vp)
                    .expect("free arcs (no cancel flag: out of memory only)"),
                four.circle_point_curve(),
            )
        } else {
            (
                arcs.free_center_arcs(vp)
                    .expect("free arcs (no cancel flag: out of memory only)"),
                four.center_point_curve(),
            )
        };
        let mut marks: Vec<Point2<f64>> = arcs
            .arc_ends()
            .iter()
            .filter_map(|e| if circle { Some(e.circle) } else { e.center })
            .collect();
        marks.extend(if circle {
            Some(arcs.driven().circle())
        } else {
            arcs.driven().finite_center()
        });
        let near_mark = |p: Point2<f64>| marks.iter().any(|m| (m - p).norm() <= 1e-6 * diag);
        let class = |p: Point2<f64>| {
            if circle {
                Ok(arcs.classify_circle_point(p))
            } else {
                arcs.classify_center_point(p)
            }
        };
        for l in &lines {
            assert!(l.len() >= 2);
            for p in l {
                finite_pt("arc vertex", *p);
            }
            for p in &l[1..l.len() - 1] {
                if near_mark(*p) {
                    continue;
                }
                if let Ok(b) = class(*p) {
                    assert!(b == burmester::Branch::Free, "arc vertex {p} is {b:?}");
                }
            }
            for w in l.windows(2) {
                let m = Point2::from((w[0].coords + w[1].coords) * 0.5);
                let len = (w[1] - w[0]).norm();
                if len <= 1e-9 * diag {
                    continue;
                }
                let g = curve.gradient(m);
                let Some(q) = curve
                    .intersect_line(&Line {
                        point: m,
                        direction: g,
                    })
                    .into_iter()
                    .min_by(|a, b| (a - m).norm().total_cmp(&(b - m).norm()))
                else {
                    continue;
                };
                // The curve's own point: within the chord tolerance and
                // between the chord's ends.
                if (q - m).norm() > 2e-3 * diag || near_mark(q) {
                    continue;
                }
                if (q - w[0]).norm() > len || (q - w[1]).norm() > len {
                    continue;
                }
                if let Ok(b) = class(q) {
                    assert!(
                        b == burmester::Branch::Free,
                        "the chord {} - {} of an arc passes {q} ({b:?}) in {vp:?}, {} plane; \
                         poses {:?}, driven {:?}, arc ends {:?}",
                        w[0],
                        w[1],
                        if circle { "circle" } else { "center" },
                        four.poses(),
                        arcs.driven(),
                        arcs.arc_ends()
                    );
                }
            }
        }
    }
}

/// The five poses of a `burmester_points` input and the frame it moves
/// them to (the same bytes as [`burmester_points`] reads).
pub fn burmester_points_task(data: &[u8]) -> (Vec<Pose>, burmester::Result<Similarity>) {
    let mut inp = Input::new(data);
    let poses = structured_poses(&mut inp, 5);
    let k = 10f64.powi(i32::from(inp.byte() % 7) - 3);
    let t = Similarity::new(k, inp.nice(), Vector2::new(inp.nice(), inp.nice()) * k);
    let t = t.map(|t| if inp.byte() % 2 == 0 { t.mirrored() } else { t });
    (poses, t)
}

/// Five poses: the Burmester points are a typed error or a sound answer
/// (finite, 0, 2 or 4 with the sliders, concyclic, sliders on a line), and
/// in another frame (moved, turned, scaled, mirrored) the same points, each
/// frame's among the other's, apart from any that nearly merge, lie beyond
/// `1e4` task sizes, or are ill-conditioned at the rounding of the inputs
/// (within `1e-6` of the other frame's size plus distance and ten times
/// what that rounding moves the point: [`rounding_moves`]).
pub fn burmester_points(data: &[u8]) {
    let (poses, t) = burmester_points_task(data);
    let five = match FivePositions::new(&poses) {
        Ok(f) => f,
        Err(e) => return message(&e),
    };
    let size = five.size();
    let moderate = moderate_task(&poses, size);
    check_five(&five);
    if !moderate {
        return;
    }
    let t = match t {
        Ok(t) => t,
        Err(e) => return message(&e),
    };
    let moved: Vec<Pose> = poses.iter().map(|q| t.pose(q)).collect();
    let Ok(other) = FivePositions::new(&moved) else {
        return;
    };
    check_five(&other);
    // The points apart from the others (a near pair decides within
    // rounding, which the frame changes) and within 1e4 task sizes move.
    let c = |f: &FivePositions| {
        Point2::from(
            f.poses()
                .iter()
                .fold(Vector2::zeros(), |a, p| a + p.position.coords / 5.0),
        )
    };
    let (ca, cb) = (c(&five), c(&other));
    // How far the rounding of the frame change, and of the frame the
    // library computes in, moves each exact point: first order, from the
    // point's own equations ([`rounding_moves`]), each of the fifteen
    // inputs moved alone by its rounding and the moves added up (the most
    // that all of them together move it, whatever their signs). Each
    // input's rounding: `4 eps` of its value in the other frame (brought
    // back: the position's distance from the origin plus the frame's
    // offset, the angle plus the frame's turn), and of what the library's
    // own frame rounds, wherever the task is given (`LocalMotion`:
    // positions relative to the poses' centroid in units of the task's
    // size, angles as differences from pose 1's: `eps` of the size, and of
    // the largest angle). Each frame's answer is then the exact point of
    // its task moved by that rounding, to first order; the frames may
    // differ by the check's tolerance (`1e-6` of the other frame's size
    // plus distance) and ten times that move. A point that it moves beyond
    // `1e-3` of `size + d` is not compared (ill-conditioned: a double point
    // within rounding, a task within rounding of a degenerate one).
    //
    // The estimate is the exact point's, not the library's answers for
    // perturbed tasks (the check before five37, which perturbed by the
    // frame change's rounding alone and skipped any point the perturbed
    // answers moved by `1e-8`): a library that loses a point in a
    // perturbed task lost it, and that must not make a well-conditioned
    // point look ill-conditioned (`ce022d68`: a point 5 task sizes out that
    // the rounding moves by `1e-13` of `size + d`, missing in the other
    // frame, mpmath); and tasks perturbed below the library's own rounding
    // gave the same point, called stable, where the rounding of its frame
    // moves the exact point by `5e-5` of `size + d` (`7aa89d36`: poses
    // `1e-12` from the given origin in a task of size 1; each frame's
    // answer within `4.9e-6` of its exact point, the frames `1e-5` apart).
    //
    // Both ways: each frame's points among the other's (a point in the
    // other frame alone, off any of this frame's, is wrong in one of them).
    let e = 4.0 * f64::EPSILON;
    let rounding = |q: &[Pose], offset: f64, angle: f64, size: f64| -> Vec<(f64, f64)> {
        let turn = q.iter().map(|p| p.angle.abs()).fold(0.0, f64::max);
        q.iter()
            .map(|p| {
                (
                    e * (p.position.coords.norm() + offset + size),
                    e * (p.angle.abs() + turn + angle),
                )
            })
            .collect()
    };
    // The frame change undone (for the points of the other frame).
    let back = |w: Point2<f64>| {
        let (s, c) = (-t.angle).sin_cos();
        let v = w - t.offset;
        let v = Vector2::new(c * v.x - s * v.y, s * v.x + c * v.y) / t.factor;
        Point2::from(if t.mirror { Vector2::new(v.x, -v.y) } else { v })
    };
    let ways: [Frame<'_>; 2] = [
        (
            &five,
            &poses,
            ca,
            &other,
            cb,
            rounding(&poses, t.offset.norm() / t.factor, t.angle.abs(), size),
            &|p| t.point(p),
        ),
        (
            &other,
            &moved,
            cb,
            &five,
            ca,
            rounding(&moved, t.offset.norm(), t.angle.abs(), other.size()),
            &back,
        ),
    ];
    for (from, from_poses, ca, to, cb, rounding, map) in ways {
        let size = from.size();
        let pts = from.burmester_points();
        for (i, p) in pts.iter().enumerate() {
            // A center or a circle point beyond 1e4 task sizes: a point at
            // infinity in the fixed or the moving plane within rounding
            // (the library reports a far center as a slider from `3e14`
            // task sizes out; a far circle point it reports as it finds
            // it: open, see fuzz/README.md).
            let d = (p.center - ca).norm();
            if d > 1e4 * size || (p.circle - ca).norm() > 1e4 * size {
                continue;
            }
            let alone = pts
                .iter()
                .enumerate()
                .all(|(j, q)| j == i || (q.center - p.center).norm() > 1e-2 * (size + d));
            if !alone {
                continue;
            }
            let moved_by = rounding_moves(from_poses, ca, size, p, &rounding) / (size + d);
            if moved_by.is_nan() || moved_by > 1e-3 {
                continue;
            }
            let w = map(p.center);
            let sb = to.size() + (w - cb).norm();
            let allowed = (1e-6 + 10.0 * moved_by) * sb;
            let nearest = to
                .burmester_points()
                .iter()
                .map(|q| (q.center - w).norm())
                .fold(f64::INFINITY, f64::min);
            assert!(
                nearest <= allowed,
                "{} ({} task sizes away, circle point {} task sizes; rounding moves it {} of \
                 size + d; in the other frame {w}, the nearest point {} of size + d off) not \
                 among {:?} (poses {from_poses:?}; the task: {poses:?}, moved {moved:?})",
                p.center,
                d / size,
                (p.circle - ca).norm() / size,
                moved_by,
                nearest / sb,
                to.burmester_points()
            );
        }
    }
}

/// One way of [`burmester_points`]' comparison of two frames: the answer
/// compared, its poses and centroid, the answer compared with and its
/// centroid, the rounding of each input ([`rounding_moves`]), and the map
/// of a point to the other frame.
type Frame<'a> = (
    &'a FivePositions,
    &'a [Pose],
    Point2<f64>,
    &'a FivePositions,
    Point2<f64>,
    Vec<(f64, f64)>,
    &'a dyn Fn(Point2<f64>) -> Point2<f64>,
);

/// How far the rounding of the inputs moves the Burmester point `p` of
/// `poses` (centroid `origin`, size `size`), to first order: each input
/// moved alone by its rounding (`rounding[k]`: pose `k`'s position,
/// either coordinate, and angle), the moves of the center added up.
/// Infinite where the point's equations are singular (a double point, or
/// one not isolated).
///
/// The point's equations: with `D_k = P_k + R(a_k - a_1) (z - P_1)` the
/// circle point `z`'s position at pose `k` and `G` the center, `E_k =
/// |D_k - G|^2 - |z - G|^2 = 0` for `k = 2..5`. Their Jacobian in `(G,
/// z)` has rows `2 (z - D_k)`, `2 R_k^T (D_k - G) - 2 (z - G)`; in the
/// inputs, `dE_k / dP_k = 2 (D_k - G)`, `dE_k / dP_1 = -2 R_k^T (D_k -
/// G)`, `dE_k / da_k = -dE_k / da_1 = 2 (D_k - G) . perp(D_k - P_k)`. A
/// change `dq` of an input moves `(G, z)` by `-J^-1 (dE / dq) dq`. Worked
/// in units of the task's size about its centroid (the quadratic terms
/// neither overflow nor lose the task to the frame's offset). Checked
/// against mpmath's Newton on the same equations with each input moved
/// (five37: `7aa89d36`, `ce022d68`).
fn rounding_moves(
    poses: &[Pose],
    origin: Point2<f64>,
    size: f64,
    p: &Dyad,
    rounding: &[(f64, f64)],
) -> f64 {
    let local = |q: Point2<f64>| (q - origin) / size;
    let perp = |v: Vector2<f64>| Vector2::new(-v.y, v.x);
    let rot = |a: f64, v: Vector2<f64>| {
        let (s, c) = a.sin_cos();
        Vector2::new(c * v.x - s * v.y, s * v.x + c * v.y)
    };
    let (g, z) = (local(p.center), local(p.circle));
    let p1 = local(poses[0].position);
    // Rows `k = 2..5`: the Jacobian in `(G, z)`, and each input's column.
    let mut jac = [[0.0f64; 4]; 4];
    let mut cols = [[0.0f64; 4]; 15];
    for r in 0..4 {
        let k = r + 1;
        let pk = local(poses[k].position);
        let a = poses[k].angle - poses[0].angle;
        let d = pk + rot(a, z - p1);
        let dg = d - g;
        let rt = rot(-a, dg);
        let jz = rt * 2.0 - (z - g) * 2.0;
        jac[r] = [2.0 * (z.x - d.x), 2.0 * (z.y - d.y), jz.x, jz.y];
        let turn = 2.0 * dg.dot(&perp(d - pk));
        // Inputs: pose `j`'s x, y, angle at `3 j`, `3 j + 1`, `3 j + 2`.
        cols[3 * k][r] += 2.0 * dg.x;
        cols[3 * k + 1][r] += 2.0 * dg.y;
        cols[3 * k + 2][r] += turn;
        cols[0][r] -= 2.0 * rt.x;
        cols[1][r] -= 2.0 * rt.y;
        cols[2][r] -= turn;
    }
    let mut total = 0.0;
    for (n, col) in cols.iter().enumerate() {
        let (dp, da) = rounding[n / 3];
        let dq = if n % 3 == 2 { da } else { dp / size };
        let Some(x) = solve4(jac, *col) else {
            return f64::INFINITY;
        };
        total += (x[0] * x[0] + x[1] * x[1]).sqrt() * dq;
    }
    // Back from units of the size.
    if total.is_finite() {
        total * size
    } else {
        f64::INFINITY
    }
}

/// `a x = b` by Gaussian elimination with partial pivoting; `None` when
/// `a` is singular to rounding (a pivot below `1e-13` of the largest
/// entry) or the answer not finite.
fn solve4(mut a: [[f64; 4]; 4], mut b: [f64; 4]) -> Option<[f64; 4]> {
    let top = a.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    if !(top > 0.0 && top.is_finite()) {
        return None;
    }
    for c in 0..4 {
        let piv = (c..4).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))?;
        if a[piv][c].is_nan() || a[piv][c].abs() <= 1e-13 * top {
            return None;
        }
        a.swap(c, piv);
        b.swap(c, piv);
        for i in c + 1..4 {
            let f = a[i][c] / a[c][c];
            let row = a[c];
            for (v, r) in a[i].iter_mut().zip(row).skip(c) {
                *v -= f * r;
            }
            b[i] -= f * b[c];
        }
    }
    let mut x = [0.0; 4];
    for c in (0..4).rev() {
        let s: f64 = (c + 1..4).map(|j| a[c][j] * x[j]).sum();
        x[c] = (b[c] - s) / a[c][c];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// One five-pose answer on its own: the count always; each point's
/// concyclicity and each slider's collinearity where the task is moderate
/// (within `1e-8`, or the rounding of the coordinates over the crank).
fn check_five(f: &FivePositions) {
    if let Err(m) = five_count::sound_count(f) {
        panic!("{m}");
    }
    let size = f.size();
    let moderate = moderate_task(f.poses(), size);
    let coords = f
        .poses()
        .iter()
        .map(|p| p.position.coords.norm())
        .fold(0.0, f64::max);
    for d in f.burmester_points() {
        finite_pt("Burmester center", d.center);
        finite_pt("Burmester circle point", d.circle);
        let r = f.residual(d);
        let radius = (d.center - d.circle).norm().max(size);
        let c = coords.max(d.center.coords.norm());
        let allowed = 1e-8f64.max(1e3 * f64::EPSILON * (1.0 + c / radius));
        assert!(
            !moderate || r <= allowed,
            "{d:?}: spread {r} (poses {:?})",
            f.poses()
        );
    }
    for s in f.sliders() {
        finite_pt("slider circle point", s.circle);
        let p = five_count::slider_positions(f, s);
        let span = p.iter().map(|q| (q - p[0]).norm()).fold(size, f64::max);
        let c = coords.max(s.circle.coords.norm());
        for q in &p[1..] {
            let off = (q - p[0]).dot(&s.direction).abs();
            assert!(
                !moderate || off <= 1e-7 * span + 1e3 * f64::EPSILON * c,
                "{s:?}: off its line by {off} (poses {:?})",
                f.poses()
            );
        }
    }
    let _ = f.four_bars();
}
