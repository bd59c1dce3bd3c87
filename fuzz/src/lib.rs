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
//!   margin's sign is the branch map, and a solved configuration carries the
//!   assembly mode that was asked for.
//!
//! The same functions run over the committed corpus in the main workspace's
//! tests (`tests/rust/fuzz_corpus.rs`), so every finding stays a regression
//! test without libFuzzer.

use burmester::{
    AssemblyMode, CircleOrLine, Conic, Constraints, DegenerateError, DesignLimits, Error, FourBar,
    Grid, InputRequirement, Line, Method, Point2, Pose, SolutionMap, Task, Vector2, Viewport,
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

/// Asserts that the message of `e` is not empty (formatting does not panic).
pub fn message(e: &Error) {
    assert!(!e.to_string().is_empty());
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
                3 => {
                    let k = 10f64.powi(i32::from(inp.byte() % 25) - 12);
                    for q in &mut p {
                        q.position = Point2::from(q.position.coords * k);
                    }
                }
                _ => {}
            }
            p
        }
    };
    match Task::new(poses) {
        Ok(t) => Some(t),
        Err(e) => {
            message(&e);
            None
        }
    }
}

fn check_task(t: &Task) {
    for p in t.poles().iter().chain(&t.image_poles()) {
        finite_pt("pole", *p);
    }
    let s = t.scale();
    assert!(s.is_finite() && s > 0.0, "scale {s}");
    for r in t.rotations() {
        finite("rotation", r);
    }
    for a in t.pole_triangle_angles() {
        finite("pole triangle angle", a);
    }
    for k in 0..=4 {
        match t.image_poles_in(k) {
            Ok(ps) => ps.iter().for_each(|p| finite_pt("image pole", *p)),
            Err(e) => {
                assert!(!(1..=3).contains(&k));
                message(&e);
            }
        }
    }
    circle_or_line("pole circle", t.pole_circle());
    circle_or_line("image-pole circle", t.image_pole_circle());
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
    let mut pts: Vec<Point2<f64>> = t.poles().to_vec();
    pts.extend(t.image_poles());
    pts.extend_from_slice(extra);
    let s = t.scale();
    for c in [t.pole_circle(), t.image_pole_circle()] {
        if let CircleOrLine::Circle { center, radius } = c {
            let a = inp.nice();
            pts.push(center + Vector2::new(a.cos(), a.sin()) * radius);
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
                let base = t.poles()[0];
                base + Vector2::new(inp.nice(), inp.nice()) * s
            }
        };
        pts.push(p);
    }
    pts
}

/// Task construction, poles, circles and the maps.
pub fn task_maps(data: &[u8]) {
    let mut inp = Input::new(data);
    let Some(t) = task(&mut inp) else { return };
    check_task(&t);
    let pts = probe_points(&mut inp, &t, &[]);
    let moderate = inp.moderate;
    for p in pts {
        check_map(&t, "circle point", p, t.circle_point(p));
        check_map(&t, "center point", p, t.center_point(p));
        if let Ok(d) = t.dyad_from_center(p) {
            for a in t.crank_angles(&d) {
                if moderate {
                    finite("crank angle", a);
                }
            }
        }
        if moderate && p.x.is_finite() && p.y.is_finite() {
            for (i, j) in [(1, 2), (2, 3), (3, 1)] {
                finite_pt("displaced", t.displace(p, i, j));
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
}

/// Filemon's construction, the classifiers, the maps and the conic curves.
pub fn filemon_classify(data: &[u8]) {
    let mut inp = Input::new(data);
    let Some(t) = task(&mut inp) else { return };
    let c0 = match inp.byte() % 3 {
        0 => inp.point(),
        1 => t.poles()[0] + Vector2::new(inp.nice(), inp.nice()) * t.scale(),
        _ => t.poles()[usize::from(inp.byte()) % 3] + Vector2::new(inp.nice(), inp.nice()) * 1e-9,
    };
    inp.note_point(c0);
    let f = match t.filemon(c0) {
        Ok(f) => f,
        Err(e) => return message(&e),
    };
    finite_pt("C1", f.circle_point());
    for p in f.fixed_pivot_images() {
        if inp.moderate {
            finite_pt("C'", p);
        }
    }
    let mut pts = probe_points(&mut inp, &t, &[c0, f.circle_point()]);
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
            assert!(f.classify(p, Method::Conic).is_err());
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
        let margin = f.margin(p);
        assert!(
            !margin.is_nan(),
            "margin at {p:?}: {:?} {:?} {:?}",
            f.driven(),
            f.fixed_pivot_images(),
            f.conic_values(p)
        );
        if let Some(v) = f.conic_values(p)
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
                for v in fb.input_angles {
                    finite("input angle", v);
                }
                finite("coupler point", fb.coupler_point.x);
                finite("coupler point", fb.coupler_point.y);
                for (k, m) in fb.modes.iter().enumerate() {
                    if let Some(m) = m
                        && let Ok(q) = fb.pose_at(fb.input_angles[k], *m)
                    {
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
    let margins = f.margin_map(&grid);
    let direct = f.branch_map(&grid, Method::Direct);
    for j in 0..ny {
        for i in 0..nx {
            let k = j * nx + i;
            let p = grid.point(i, j);
            let c = f.classify(p, Method::Conic).expect("finite point");
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

fn grid_viewport(g: &Grid) -> burmester::Result<Viewport> {
    let v = g.viewport();
    Viewport::new(v.xmin, v.xmax, v.ymin, v.ymax)
}

fn polylines(c: &Conic, vp: &Viewport) {
    let (w, h) = vp.size();
    // Rounding of the conic's local frame (origin and unit) comes on top.
    let (_, origin, unit) = c.local_coefficients();
    let slack = 1e-14 * (origin.x.abs() + origin.y.abs() + unit)
        + 1e-6 * (w + h)
        + 1e-9 * (vp.xmax.abs().max(vp.xmin.abs()) + vp.ymax.abs().max(vp.ymin.abs()));
    for l in c.polylines(vp, None) {
        assert!(l.len() >= 2);
        for p in l {
            finite_pt("polyline point", p);
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

/// Checks the arrays of a solution map: lengths, and the documented
/// relations between them (no unflagged NaN).
fn check_solution_map(map: &SolutionMap) {
    let n = map.context.grid.len();
    for len in [
        map.valid.len(),
        map.branch_free.len(),
        map.grashof.len(),
        map.input_full.len(),
        map.direction.len(),
        map.one_circuit.len(),
        map.min_transmission.len(),
        map.link_ratio.len(),
        map.acceptable.len(),
    ] {
        assert_eq!(len, n);
    }
    for k in 0..n {
        if map.acceptable[k] {
            assert!(
                map.valid[k] && map.branch_free[k] && map.direction[k] != 0 && map.one_circuit[k]
            );
        }
        if !map.valid[k] {
            assert!(!map.acceptable[k] && map.direction[k] == 0);
            assert_eq!(map.grashof[k], SolutionMap::GRASHOF_NONE);
            assert!(map.min_transmission[k].is_nan() && map.link_ratio[k].is_nan());
            continue;
        }
        assert!(SolutionMap::grashof_of_code(map.grashof[k]).is_some());
        let r = map.link_ratio[k];
        assert!(r >= 1.0, "link ratio {r}");
        let t = map.min_transmission[k];
        if map.direction[k] == 0 {
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
    let near =
        |inp: &mut Input<'_>, t: &Task| t.poles()[0] + Vector2::new(inp.nice(), inp.nice()) * s;
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
    let limits = DesignLimits {
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
    };
    let polygon = |inp: &mut Input<'_>| -> Vec<Point2<f64>> {
        let n = inp.count(0, 5);
        (0..n)
            .map(|_| {
                if inp.byte() % 4 == 0 {
                    inp.point()
                } else {
                    near(inp, &t)
                }
            })
            .collect()
    };
    let constraints = Constraints {
        base_plate: if inp.byte() % 2 == 0 {
            Some(polygon(&mut inp))
        } else {
            None
        },
        obstacles: (0..inp.count(0, 2)).map(|_| polygon(&mut inp)).collect(),
        link_width: if inp.byte() % 3 == 0 {
            inp.num()
        } else {
            inp.nice().abs() * s * 0.1
        },
        travel_samples: inp.count(0, 16),
    };
    match f.solution_map(&grid, &limits, &constraints) {
        Err(e) => message(&e),
        Ok(map) => {
            check_solution_map(&map);
            for p in map.best_pivots(inp.count(0, 4), None) {
                assert!(map.acceptable[p.index]);
                finite_pt("pivot", p.center);
                assert!(p.figures.link_ratio >= 1.0);
            }
        }
    }
    // The other direction, with the driving dyad at a probe point.
    let a0 = near(&mut inp, &t);
    if let Ok(driving) = t.dyad_from_center(a0) {
        match t.driven_solution_map(&driving, &grid, &limits, &constraints) {
            Err(e) => message(&e),
            Ok(map) => {
                check_solution_map(&map);
                for p in map.best_pivots(2, Some(0.0)) {
                    assert!(map.acceptable[p.index]);
                }
            }
        }
    }
}
