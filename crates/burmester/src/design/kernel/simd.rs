//! The SIMD backend of the per-pivot kernel ([`DrivingRows`]) of the
//! three-pose driving solution map and of the pivot atlas, vectorised
//! across a row of candidate driving centers.
//!
//! [`Sampler::driving_sample`] computes one sample at a time: the circle
//! point by the closed form, the moving pivot at the three poses, the
//! lengths, the input bounds, order and circuit by pseudo-angles, and the
//! worst `|cos mu|` over the travel (see
//! [`LinkageFigures`](crate::LinkageFigures) for the method). Here the same
//! arithmetic runs on SIMD lanes, one candidate per lane, every branch of
//! the scalar code turned into a select, the Grashof class, the minimum
//! transmission angle (the crate's own [`acos`]) and the limits included;
//! [`DrivingKernel::write_row`] then writes a map's row column by column
//! from the lanes' results (the constraints, where there are any, per
//! sample). Where the scalar code's quotients can be had with fewer
//! divisions and the same bits, the lanes take them so: `l1 / m` and
//! `l2 / m` with one (the other is `m / m = 1`), the pseudo-angles of `g`
//! and `-g` from one quotient, the candidates' abscissae in the closed
//! form's frame once per map.
//!
//! The atlas asks less of a row ([`DrivingKernel::row_where`]): only the
//! groups of lanes that hold a branch-free sample, without the Grashof
//! class and the size, and with a flag for the samples that may meet the
//! limits; it decides the transmission limit by a band on the worst
//! `|cos mu|` ([`CosBand`]), taking the `acos` only near the limit. What
//! depends on the driving candidate alone (the circle point, the crank at
//! the three poses, its length and pseudo-angles: [`RowPre`]) it computes
//! once per row for a chunk of driven centers
//! ([`DrivingKernel::pre_row`]), and each center's row reads it.
//!
//! The lanes come from [`pulp`], which picks at run time the widest
//! instruction set the CPU has (AVX2 on x86-64-v3, scalar lanes
//! elsewhere), with no `unsafe` in this crate: a portable wheel built for
//! SSE2 still runs the AVX2 code where the CPU has it. Every lane
//! operation is the scalar path's IEEE operation on the same operands in
//! the same order (no fused multiply-add, no reassociation, a select where
//! the scalar code branches), so a map is the scalar path's bit for bit;
//! the tests below check it for lane widths 1, 2, 4 and 8 and for what
//! the CPU dispatches to.

use nalgebra::Point2;
use pulp::{Arch, Simd, WithSimd};

use crate::simd::{M, Ops, V, acos, acos1};

use crate::design::InputRequirement;
use crate::design::RankBy;
use crate::design::columns::{ColumnsMut, ColumnsOut, ColumnsRow};
use crate::design::judge::Sampler;
use crate::design::kernel::{AtlasAsk, DrivingRows, Seen};
use crate::engine::{Control, run_blocks_with};
use crate::error::{Result, try_collect, try_vec};
use crate::geom::Grid;
use crate::linkage::{Direction, Grashof};
use crate::synthesis::Dyad;
use crate::synthesis::three::Maps;
use crate::tolerance;

/// Rows are padded to a multiple of the widest lane count (8, AVX-512).
const PAD: usize = 8;

/// The flags of a lane, packed as small integers in one `f64`.
const VALID: u8 = 1;
const FULL: u8 = 2;
const ONE_CIRCUIT: u8 = 4;
const CCW: u8 = 8;
const CW: u8 = 16;
/// May meet the limits (atlas rows only): one circuit, a direction, the
/// link ratio, the Grashof margin, the input kind, and a worst `|cos mu|` not surely past the
/// transmission limit; without it the sample is surely not acceptable.
const MAY_MEET: u8 = 32;
/// Meets the limits (map rows only): one circuit, a direction, the link
/// ratio, the Grashof margin, the input kind and the minimum transmission
/// angle, as
/// [`DesignLimits::meets`](crate::DesignLimits::meets) tests them.
const MEETS: u8 = 64;

/// `acos(w) >= angle` for a worst `|cos mu|` `w` in `[0, 1]`, by
/// thresholds on `w` away from the angle and the `acos` near it: the answer
/// is the comparison of the `acos` itself (as [`DesignLimits::meets`]
/// takes it) wherever the crate's [`crate::simd::acos`] and libm's
/// `cos` are within a tenth of [`CosBand::SLACK`] of the true values, which
/// they are by many orders of magnitude (2 ulp and 1 ulp, about `4e-16`
/// rad here).
///
/// [`DesignLimits::meets`]: crate::DesignLimits::meets
#[derive(Debug, Clone, Copy)]
pub(crate) struct CosBand {
    angle: f64,
    /// Below `yes` the angle is surely reached; above `no` surely not.
    yes: f64,
    pub(crate) no: f64,
}

impl CosBand {
    /// Radians either side of the angle where the `acos` is taken.
    pub(crate) const SLACK: f64 = crate::tolerance::COS_SLACK;

    /// The band about `angle` (radians). Outside `[1e-3, 2]` rad (where a
    /// rounding of `cos` could move the thresholds by more than a small
    /// part of the slack) every test takes the `acos`.
    pub(crate) fn new(angle: f64) -> Self {
        if !(1e-3..=2.0).contains(&angle) {
            return CosBand {
                angle,
                yes: f64::NEG_INFINITY,
                no: f64::INFINITY,
            };
        }
        CosBand {
            angle,
            yes: (angle + Self::SLACK).cos(),
            no: (angle - Self::SLACK).cos(),
        }
    }

    /// Whether `acos(w) >= angle`.
    #[inline(always)]
    pub(crate) fn at_least(&self, w: f64) -> bool {
        if w < self.yes {
            true
        } else if w > self.no {
            false
        } else {
            acos1(w) >= self.angle
        }
    }

    /// Whether `acos(w)` may reach the angle (false only where it surely
    /// does not).
    #[inline(always)]
    pub(crate) fn may_reach(&self, w: f64) -> bool {
        w <= self.no
    }
}

/// A Grashof class's code as a lane value.
fn code(g: Grashof) -> f64 {
    f64::from(g.code())
}

/// The lanes' results for one row, one value per candidate (structure of
/// arrays, padded to a multiple of [`PAD`]).
pub(crate) struct RowOut {
    qx: Vec<f64>,
    qy: Vec<f64>,
    /// The largest `|cos mu|` over the travel (meaningless without a
    /// direction).
    worst: Vec<f64>,
    /// `acos(worst)`, the minimum transmission angle ([`acos`]; whole rows
    /// only).
    mu: Vec<f64>,
    ratio: Vec<f64>,
    /// The Grashof margin (`grashof_margin_of`).
    margin: Vec<f64>,
    members: Vec<f64>,
    flags: Vec<f64>,
    /// The Grashof class's code.
    grashof: Vec<f64>,
    /// The flags as bytes ([`DrivingKernel::write_row`]'s scratch).
    codes: Vec<u8>,
}

impl RowOut {
    /// Room for the padded row `xs` of [`DrivingKernel::padded_xs`].
    ///
    /// # Errors
    ///
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory).
    pub(crate) fn new(xs: &[f64]) -> Result<Self> {
        let v = || try_vec("a row's lanes", xs.len(), 0.0);
        Ok(RowOut {
            qx: v()?,
            qy: v()?,
            worst: v()?,
            mu: v()?,
            ratio: v()?,
            margin: v()?,
            members: v()?,
            flags: v()?,
            grashof: v()?,
            codes: try_vec("a row's lanes", xs.len(), 0)?,
        })
    }
}

/// The candidates of one driving map (or atlas cell): the task's closed
/// form for the circle point, its motion to poses 2 and 3, and the fixed
/// driven dyad, as the constants of the lanes.
pub(crate) struct DrivingKernel<'s> {
    sampler: &'s Sampler<'s>,
    driven: Dyad,
    origin: [f64; 2],
    scale: f64,
    q13: [f64; 2],
    /// `(cos, -sin)` of `theta12 / 2` and `theta13 / 2` (the center to
    /// circle direction of the map).
    half12: (f64, f64),
    half13: (f64, f64),
    /// `(cos, sin)` and shift of the motion from pose 1 to poses 2 and 3.
    rot: [(f64, f64); 2],
    shift: [[f64; 2]; 2],
    /// The driven center and its moving pivot at pose 1.
    c0: [f64; 2],
    c1: [f64; 2],
    /// The rocker's length, and `|P - C1|` for the members' length.
    l4: f64,
    to_driven: f64,
    point: [f64; 2],
    tiny: f64,
    /// The limits as the atlas rows test them: the largest link ratio,
    /// the input kind, the smallest Grashof margin, and the worst
    /// `|cos mu|` above which the transmission limit is surely missed.
    max_ratio: f64,
    input: InputRequirement,
    min_margin: f64,
    cos_no: f64,
    /// The transmission limit (radians) and `1 / Task::span`, for a map.
    min_transmission: f64,
    inv_span: f64,
}

impl<'s> DrivingKernel<'s> {
    /// The kernel of the driving map with driven dyad `driven` (moving
    /// pivot `c` at the three poses); `None` for a task with a pole at
    /// infinity (the linear form, which keeps the scalar path).
    pub(crate) fn new(
        sampler: &'s Sampler<'s>,
        driven: Dyad,
        c: &[Point2<f64>; 3],
    ) -> Option<Self> {
        let Maps::Poles(cremona) = sampler.maps else {
            return None;
        };
        let (origin, scale) = cremona.frame();
        let q13 = cremona.local_p13();
        let ((c12, s12), (c13, s13)) = cremona.half_angles();
        let rot_shift = |k: usize| sampler.motion.first_to_parts(k);
        let ((r1, t1), (r2, t2)) = (rot_shift(1), rot_shift(2));
        let point = sampler.judge.point();
        let limits = sampler.judge.limits();
        Some(DrivingKernel {
            sampler,
            driven,
            origin: [origin.x, origin.y],
            scale,
            q13: [q13.x, q13.y],
            half12: (c12, -s12),
            half13: (c13, -s13),
            rot: [r1, r2],
            shift: [[t1.x, t1.y], [t2.x, t2.y]],
            c0: [driven.center.x, driven.center.y],
            c1: [c[0].x, c[0].y],
            l4: (c[0] - driven.center).norm(),
            to_driven: (point - driven.circle).norm(),
            point: [point.x, point.y],
            tiny: sampler.judge.tiny,
            max_ratio: limits.max_link_ratio,
            input: limits.input,
            min_margin: limits.min_grashof_margin,
            cos_no: CosBand::new(limits.min_transmission).no,
            min_transmission: limits.min_transmission,
            inv_span: sampler.judge.inv_span(),
        })
    }

    /// The abscissae of `grid`'s columns, padded with the last to a
    /// multiple of the widest lane count.
    ///
    /// # Errors
    ///
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory).
    pub(crate) fn padded_xs(grid: &Grid) -> Result<Vec<f64>> {
        let nx = grid.nx();
        let n = nx.next_multiple_of(PAD);
        try_collect(
            "a row's abscissae",
            n,
            (0..n).map(|i| grid.x(i.min(nx - 1))),
        )
    }

    /// The lanes of the row at ordinate `y` with abscissae `xs` (padded)
    /// into `out`, on the widest SIMD the CPU has.
    #[inline]
    pub(crate) fn row(&self, y: f64, xs: &[f64], local: &[f64], out: &mut RowOut) {
        Arch::new().dispatch(Lanes {
            k: self,
            y,
            xs,
            local: Some(local),
            needed: None,
            pre: None,
            out,
        });
    }

    /// [`row`](Self::row) but only for the lanes of groups that hold a
    /// sample where `needed` (one flag per column) is true (the others keep
    /// what they held), only what
    /// [`judge_for_atlas`](Self::judge_for_atlas) reads, and with the
    /// driving candidates' lanes taken from `pre` ([`pre_row`](Self::pre_row)
    /// of the same row, for at least the groups `needed` asks for): the
    /// same bits as computing them here.
    #[inline]
    pub(crate) fn row_where(
        &self,
        y: f64,
        xs: &[f64],
        needed: &[bool],
        pre: &RowPre,
        out: &mut RowOut,
    ) {
        Arch::new().dispatch(Lanes {
            k: self,
            y,
            xs,
            local: None,
            needed: Some(needed),
            pre: Some(pre),
            out,
        });
    }

    /// The lanes of the row at ordinate `y` that depend on the driving
    /// candidate only, for the groups with a sample where `needed` is
    /// true, into `pre`. They use only the task's constants, so the
    /// kernel of any driven dyad of one [`Sampler`] gives the same `pre`.
    #[inline]
    pub(crate) fn pre_row(&self, y: f64, xs: &[f64], needed: &[bool], pre: &mut RowPre) {
        Arch::new().dispatch(PreLanes {
            k: self,
            y,
            xs,
            needed,
            pre,
        });
    }

    /// The abscissae `x` in the frame of the closed form for the circle
    /// point.
    #[inline(always)]
    fn local_x<S: Simd>(&self, o: Ops<S>, x: V<S>) -> V<S> {
        o.div(o.sub(x, o.sp(self.origin[0])), o.sp(self.scale))
    }

    /// [`local_x`](Self::local_x) of every abscissa of the padded row
    /// `xs`, computed once for the rows of a map: the lanes' bits.
    ///
    /// # Errors
    ///
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory).
    pub(crate) fn local_xs(&self, xs: &[f64]) -> Result<Vec<f64>> {
        let o = Ops(pulp::Scalar);
        try_collect(
            "a row's abscissae",
            xs.len(),
            xs.iter().map(|&x| self.local_x(o, x)),
        )
    }

    /// The driving candidates' lanes at abscissae `x`, ordinate `y`: the
    /// circle point by the closed form (`circle_point_fast`), the crank at
    /// the three poses (`Motion::first_to`), its length and pseudo-angles.
    #[inline(always)]
    fn driving_lanes<S: Simd>(&self, o: Ops<S>, x: V<S>, yx: V<S>, y: f64) -> Pre<S> {
        let zero = o.sp(0.0);
        let (ox, oy) = (o.sp(self.origin[0]), o.sp(self.origin[1]));
        let scale = o.sp(self.scale);
        let (q13x, q13y) = (o.sp(self.q13[0]), o.sp(self.q13[1]));
        let (c12, s12) = (o.sp(self.half12.0), o.sp(self.half12.1));
        let (c13, s13) = (o.sp(self.half13.0), o.sp(self.half13.1));
        let [(r1c, r1s), (r2c, r2s)] = self.rot.map(|(c, s)| (o.sp(c), o.sp(s)));
        let [t1, t2] = self.shift.map(|t| t.map(|v| o.sp(v)));
        let yy = o.sp((y - self.origin[1]) / self.scale);
        let y = o.sp(y);
        let ux = o.sub(o.mul(c12, yx), o.mul(s12, yy));
        let uy = o.add(o.mul(s12, yx), o.mul(c12, yy));
        let (wx, wy) = (o.sub(yx, q13x), o.sub(yy, q13y));
        let vx = o.sub(o.mul(c13, wx), o.mul(s13, wy));
        let vy = o.add(o.mul(s13, wx), o.mul(c13, wy));
        let den = o.cross(ux, uy, vx, vy);
        let kappa = o.cross(q13x, q13y, vx, vy);
        let t = o.mul(o.div(kappa, den), scale);
        let qx = o.add(ox, o.mul(ux, t));
        let qy = o.add(oy, o.mul(uy, t));
        let has_q = o.and(o.and(o.finite(qx), o.finite(qy)), o.not(o.eq(den, zero)));
        // The moving pivot at poses 2 and 3, and the crank at the three
        // poses.
        let a1x = o.add(o.sub(o.mul(r1c, qx), o.mul(r1s, qy)), t1[0]);
        let a1y = o.add(o.add(o.mul(r1s, qx), o.mul(r1c, qy)), t1[1]);
        let a2x = o.add(o.sub(o.mul(r2c, qx), o.mul(r2s, qy)), t2[0]);
        let a2y = o.add(o.add(o.mul(r2s, qx), o.mul(r2c, qy)), t2[1]);
        let (e0x, e0y) = (o.sub(qx, x), o.sub(qy, y));
        let (e1x, e1y) = (o.sub(a1x, x), o.sub(a1y, y));
        let (e2x, e2y) = (o.sub(a2x, x), o.sub(a2y, y));
        Pre {
            qx,
            qy,
            has_q,
            e: [e0x, e0y, e1x, e1y, e2x, e2y],
            l2: o.norm(e0x, e0y),
            tf1: o.pseudo(e0x, e0y, e1x, e1y),
            tf2: o.pseudo(e0x, e0y, e2x, e2y),
        }
    }

    /// The flags and the driving direction of column `i` of `out`, or
    /// `None` where the linkage does not exist.
    #[inline(always)]
    fn decode(out: &RowOut, i: usize) -> Option<(u8, Direction)> {
        let flags = out.flags[i] as u8;
        if flags & VALID == 0 {
            return None;
        }
        let direction = if flags & CCW != 0 {
            Direction::Ccw
        } else if flags & CW != 0 {
            Direction::Cw
        } else {
            Direction::None
        };
        Some((flags, direction))
    }

    /// What the atlas reads of a branch-free sample (column `i` of `out`,
    /// candidate `a0`): `None` where the linkage does not exist, else
    /// `Some(Some(w))` where the sample is acceptable, `w` its worst
    /// `|cos mu|` (its minimum transmission angle is `w.acos()`), and
    /// `Some(None)` where it is not. The transmission limit is decided by
    /// `band` without an `acos` away from it.
    #[inline]
    pub(crate) fn judge_for_atlas(
        &self,
        out: &RowOut,
        i: usize,
        a0: Point2<f64>,
        band: &CosBand,
    ) -> Option<Option<f64>> {
        let (flags, direction) = Self::decode(out, i)?;
        if flags & MAY_MEET == 0 {
            return Some(None);
        }
        let judge = &self.sampler.judge;
        let worst = out.worst[i];
        let meets = || {
            judge.limits().meets_when(
                flags & ONE_CIRCUIT != 0,
                direction,
                out.ratio[i],
                flags & FULL != 0,
                out.margin[i],
                || band.at_least(worst),
            )
        };
        let driving = Dyad::new(a0, Point2::new(out.qx[i], out.qy[i]));
        let sized = || meets() && self.meets_size(&out.qx, &out.qy, i, a0);
        let acceptable = judge.acceptable(true, sized, &[a0], driving, self.driven);
        Some(acceptable.then_some(worst))
    }

    /// The minimum transmission angle, the link ratio and the size ratio
    /// of column `i` of `out` (candidate `a0`, worst `|cos mu|` `w`) as
    /// the solution map's `f32` columns hold them.
    #[inline]
    pub(crate) fn ranked_at(
        &self,
        out: &RowOut,
        i: usize,
        a0: Point2<f64>,
        w: f64,
    ) -> (f32, f32, f32) {
        let (_, members) = self.lengths_at(out, i, a0);
        (
            acos1(w) as f32,
            out.ratio[i] as f32,
            (members * self.inv_span) as f32,
        )
    }

    /// The link lengths `[ground, crank, coupler, rocker]` and the members'
    /// total length ([`members_length`](crate::synthesis::members_length))
    /// of column `i` of `out` (candidate `a0`), as the scalar path
    /// ([`Sampler::driving_sample`]) computes them.
    #[inline]
    pub(crate) fn lengths_at(&self, out: &RowOut, i: usize, a0: Point2<f64>) -> ([f64; 4], f64) {
        self.lengths_of(&out.qx, &out.qy, i, a0)
    }

    /// [`lengths_at`](Self::lengths_at) from the circle points' columns.
    #[inline]
    fn lengths_of(&self, qx: &[f64], qy: &[f64], i: usize, a0: Point2<f64>) -> ([f64; 4], f64) {
        let a1 = Point2::new(qx[i], qy[i]);
        let c0 = self.driven.center;
        let c1 = Point2::new(self.c1[0], self.c1[1]);
        let lengths = [
            (c0 - a0).norm(),
            (a1 - a0).norm(),
            (c1 - a1).norm(),
            (c1 - c0).norm(),
        ];
        let point = Point2::new(self.point[0], self.point[1]);
        let members = crate::synthesis::members_length(lengths, a1, self.driven.circle, point);
        (lengths, members)
    }

    /// Whether column `i` (candidate `a0`, circle points `qx`, `qy`) is
    /// within the limits' size bounds
    /// ([`DesignLimits::meets_size`](crate::DesignLimits::meets_size)).
    #[inline]
    fn meets_size(&self, qx: &[f64], qy: &[f64], i: usize, a0: Point2<f64>) -> bool {
        let limits = self.sampler.judge.limits();
        if !limits.limits_size() {
            return true;
        }
        let (lengths, members) = self.lengths_of(qx, qy, i, a0);
        limits.meets_size(lengths, members * self.inv_span)
    }

    /// Writes the row at ordinate `y` (abscissae `xs`, branch flags
    /// `branch`) from the lanes in `out` ([`row`](Self::row)) into `row`,
    /// column by column: [`Sampler::driving_sample`] bit for bit at every
    /// sample.
    #[inline]
    pub(crate) fn write_row(
        &self,
        out: &mut RowOut,
        y: f64,
        xs: &[f64],
        branch: &[bool],
        row: ColumnsRow<'_>,
    ) {
        let nx = branch.len();
        // The flags, small integers (zero where the linkage does not
        // exist), as bytes: the low bits of `f + 2^52` (in loops the
        // compiler vectorises, unlike `as u8`'s saturating conversion).
        let small = |f: f64| (f + 4_503_599_627_370_496.0).to_bits() as u8;
        let codes = &mut out.codes[..nx];
        for (c, &f) in codes.iter_mut().zip(&out.flags) {
            *c = small(f);
        }
        let codes = &*codes;
        let nan = f32::NAN;
        for (d, &c) in row.valid.iter_mut().zip(codes) {
            *d = c & VALID != 0;
        }
        for ((d, &c), &b) in row.branch_free.iter_mut().zip(codes).zip(branch) {
            *d = b & (c & VALID != 0);
        }
        for ((d, &c), &g) in row.grashof.iter_mut().zip(codes).zip(&out.grashof) {
            *d = if c & VALID != 0 {
                small(g)
            } else {
                crate::SolutionMap::GRASHOF_NONE
            };
        }
        for (d, &c) in row.input_full.iter_mut().zip(codes) {
            *d = c & FULL != 0;
        }
        for (d, &c) in row.direction.iter_mut().zip(codes) {
            *d = i8::from(c & CCW != 0) - i8::from(c & CW != 0);
        }
        for (d, &c) in row.one_circuit.iter_mut().zip(codes) {
            *d = c & ONE_CIRCUIT != 0;
        }
        for ((d, &c), &mu) in row.min_transmission_rad.iter_mut().zip(codes).zip(&out.mu) {
            *d = if c & (CCW | CW) != 0 { mu as f32 } else { nan };
        }
        for ((d, &c), &r) in row.link_ratio.iter_mut().zip(codes).zip(&out.ratio) {
            *d = if c & VALID != 0 { r as f32 } else { nan };
        }
        for ((d, &c), &m) in row.size_ratio.iter_mut().zip(codes).zip(&out.members) {
            *d = if c & VALID != 0 {
                (m * self.inv_span) as f32
            } else {
                nan
            };
        }
        let judge = &self.sampler.judge;
        let acceptable = row.acceptable.iter_mut().zip(codes).zip(branch);
        if judge.unconstrained() {
            for ((d, &c), &b) in acceptable {
                *d = b & (c & MEETS != 0);
            }
        } else {
            for (i, ((d, &c), &b)) in acceptable.enumerate() {
                let a0 = Point2::new(xs[i], y);
                let driving = Dyad::new(a0, Point2::new(out.qx[i], out.qy[i]));
                let meets = || c & MEETS != 0 && self.meets_size(&out.qx, &out.qy, i, a0);
                *d = judge.acceptable(b, meets, &[a0], driving, self.driven);
            }
        }
    }

    /// Fills the columns of a driving solution map over `grid` (`xs` its
    /// [`padded_xs`](Self::padded_xs)) with branch flags `branch`, over
    /// blocks of rows on the engine.
    pub(crate) fn fill(
        &self,
        grid: &Grid,
        xs: &[f64],
        branch: &[bool],
        columns: ColumnsMut<'_>,
        control: &Control<'_>,
    ) -> Result<()> {
        let nx = grid.nx();
        let local = self.local_xs(xs)?;
        let init = || RowOut::new(xs);
        run_blocks_with(
            nx,
            grid.ny(),
            columns,
            control,
            init,
            |out, j0, mut block, rows| {
                for r in 0..rows {
                    let j = j0 + r;
                    let y = grid.y(j);
                    self.row(y, xs, &local, out);
                    let branch = &branch[j * nx..(j + 1) * nx];
                    self.write_row(out, y, xs, branch, block.row(r));
                }
            },
        )
    }
}

impl DrivingRows for DrivingKernel<'_> {
    fn fill(&self, g: &Grid, b: &[bool], out: ColumnsOut<'_>, c: &Control<'_>) -> Result<()> {
        let xs = DrivingKernel::padded_xs(g)?;
        DrivingKernel::fill(self, g, &xs, b, out.rows(g.nx()), c)
    }

    fn pre_row(&self, y: f64, xs: &[f64], needed: &[bool], pre: &mut RowPre) {
        DrivingKernel::pre_row(self, y, xs, needed, pre);
    }

    fn row_where(&self, y: f64, xs: &[f64], needed: &[bool], pre: &RowPre, out: &mut RowOut) {
        DrivingKernel::row_where(self, y, xs, needed, pre, out);
    }

    #[inline]
    fn atlas_sample(&self, out: &RowOut, i: usize, a0: Point2<f64>, ask: &AtlasAsk<'_>) -> Seen {
        let rank_by = ask.rank_by;
        self.judge_for_atlas(out, i, a0, ask.limit).map(|a| {
            a.map(|w| {
                if rank_by == RankBy::Transmission {
                    ask.reach
                        .may_reach(w)
                        .then(|| f64::from(crate::simd::acos1(w) as f32))
                } else {
                    let (mu, ratio, size) = self.ranked_at(out, i, a0, w);
                    rank_by.score(f64::from(mu), f64::from(size), f64::from(ratio))
                }
            })
        })
    }
}

/// One row of lanes (pulp's entry point).
struct Lanes<'k, 'o> {
    k: &'k DrivingKernel<'k>,
    y: f64,
    xs: &'o [f64],
    /// [`DrivingKernel::local_xs`] of `xs`, or computed here.
    local: Option<&'o [f64]>,
    /// Compute only the groups of lanes with a needed sample.
    needed: Option<&'o [bool]>,
    /// The lanes of the driving candidates alone, computed beforehand
    /// ([`DrivingKernel::pre_row`]) for at least the needed groups.
    pre: Option<&'o RowPre>,
    out: &'o mut RowOut,
}

/// The lanes of a row that depend on the driving candidate only, not on
/// the driven dyad: the circle point, the crank at the three poses, its
/// length, its pseudo-angles at poses 2 and 3. The atlas computes them once
/// per row for a chunk of driven centers ([`DrivingKernel::pre_row`]).
pub(crate) struct RowPre {
    /// `qx, qy, has_q, e0x, e0y, e1x, e1y, e2x, e2y, l2, tf1, tf2`.
    v: [Vec<f64>; 12],
}

impl RowPre {
    /// Room for the padded row `xs` of [`DrivingKernel::padded_xs`].
    ///
    /// # Errors
    ///
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory).
    pub(crate) fn new(xs: &[f64]) -> Result<Self> {
        let mut v: [Vec<f64>; 12] = Default::default();
        for lane in &mut v {
            *lane = try_vec("a row's lanes", xs.len(), 0.0)?;
        }
        Ok(RowPre { v })
    }
}

/// [`RowPre`]'s values on one group of lanes.
#[derive(Clone, Copy)]
struct Pre<S: Simd> {
    qx: V<S>,
    qy: V<S>,
    has_q: M<S>,
    e: [V<S>; 6],
    l2: V<S>,
    tf1: V<S>,
    tf2: V<S>,
}

/// The driving candidate's lanes into [`RowPre`] (pulp's entry point).
struct PreLanes<'k, 'o> {
    k: &'k DrivingKernel<'k>,
    y: f64,
    xs: &'o [f64],
    needed: &'o [bool],
    pre: &'o mut RowPre,
}

impl WithSimd for PreLanes<'_, '_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let o = Ops(s);
        let n = S::F64_LANES;
        let (xs, _) = S::as_simd_f64s(self.xs);
        let [qx, qy, has_q, e0x, e0y, e1x, e1y, e2x, e2y, l2, tf1, tf2] =
            self.pre.v.each_mut().map(|v| lanes::<S>(v));
        for (c, &x) in xs.iter().enumerate() {
            if !group_needed(self.needed, c, n) {
                continue;
            }
            let p = self.k.driving_lanes(o, x, self.k.local_x(o, x), self.y);
            qx[c] = p.qx;
            qy[c] = p.qy;
            has_q[c] = o.sel(p.has_q, o.sp(1.0), o.sp(0.0));
            [e0x[c], e0y[c], e1x[c], e1y[c], e2x[c], e2y[c]] = p.e;
            l2[c] = p.l2;
            tf1[c] = p.tf1;
            tf2[c] = p.tf2;
        }
    }
}

/// Whether group `c` of `n` lanes holds a needed sample.
#[inline(always)]
fn group_needed(needed: &[bool], c: usize, n: usize) -> bool {
    needed
        .get(c * n..((c + 1) * n).min(needed.len()))
        .is_some_and(|l| l.contains(&true))
}

impl<S: Simd> Ops<S> {
    /// `pseudo_angle(r, v)`: the monotone pseudo-angle of `v` from `r`.
    #[inline(always)]
    fn pseudo(self, rx: V<S>, ry: V<S>, vx: V<S>, vy: V<S>) -> V<S> {
        let x = self.dot(rx, ry, vx, vy);
        let y = self.cross(rx, ry, vx, vy);
        let d = self.add(self.abs(x), self.abs(y));
        self.pseudo_of(x, y, self.div(y, d), self.eq(d, self.sp(0.0)))
    }
    /// `(pseudo(r, v), pseudo(r, -v))` with one division: negating `v`
    /// negates the dot and cross products and the quotient exactly (a zero
    /// may change sign, which no comparison of a pseudo-angle sees).
    #[inline(always)]
    fn pseudo_pm(self, rx: V<S>, ry: V<S>, vx: V<S>, vy: V<S>) -> (V<S>, V<S>) {
        let x = self.dot(rx, ry, vx, vy);
        let y = self.cross(rx, ry, vx, vy);
        let d = self.add(self.abs(x), self.abs(y));
        let flat = self.eq(d, self.sp(0.0));
        let p = self.div(y, d);
        (
            self.pseudo_of(x, y, p, flat),
            self.pseudo_of(self.neg(x), self.neg(y), self.neg(p), flat),
        )
    }
    /// The pseudo-angle from the dot product `x`, the cross product `y`,
    /// their quotient `p = y / (|x| + |y|)`, and whether both are zero
    /// (`flat`, the angle 0). A method, not a closure: always inlined into
    /// the dispatched lanes.
    #[inline(always)]
    fn pseudo_of(self, x: V<S>, y: V<S>, p: V<S>, flat: M<S>) -> V<S> {
        let (zero, two, four) = (self.sp(0.0), self.sp(2.0), self.sp(4.0));
        let upper = self.sel(self.ge(y, zero), p, self.add(four, p));
        let t = self.sel(self.ge(x, zero), upper, self.sub(two, p));
        self.sel(flat, zero, t)
    }
    /// `|cos mu|` at `c = cc` from `[k0, k1, k2, 1 / (2 L3 L4)]` (`figures`).
    #[inline(always)]
    fn cos_mu(self, cc: V<S>, [k0, k1, k2, inv]: [V<S>; 4]) -> V<S> {
        let c = self.mul(self.sub(k2, self.sub(k0, self.mul(k1, cc))), inv);
        self.fmin(self.abs(c), self.sp(1.0))
    }
    /// Whether pseudo-angle `p` lies in the travel `[from, to]` (or is the
    /// crank's start, for a crank).
    #[inline(always)]
    fn inside(self, p: V<S>, from: V<S>, to: V<S>, full: M<S>) -> M<S> {
        let between = self.and(self.ge(p, from), self.le(p, to));
        self.or(between, self.and(full, self.eq(p, self.sp(0.0))))
    }
    /// `v` where `m`, else 0.
    #[inline(always)]
    fn flag(self, m: M<S>, v: u8) -> V<S> {
        self.sel(m, self.sp(f64::from(v)), self.sp(0.0))
    }
}

/// A padded row of values as whole SIMD vectors (no tail: [`PAD`]).
#[inline(always)]
fn lanes<S: Simd>(v: &mut [f64]) -> &mut [V<S>] {
    S::as_mut_simd_f64s(v).0
}

impl WithSimd for Lanes<'_, '_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let (k, o) = (self.k, Ops(s));
        let (zero, one, two, four) = (o.sp(0.0), o.sp(1.0), o.sp(2.0), o.sp(4.0));
        let (c0x, c0y) = (o.sp(k.c0[0]), o.sp(k.c0[1]));
        let (c1x, c1y) = (o.sp(k.c1[0]), o.sp(k.c1[1]));
        let (px, py) = (o.sp(k.point[0]), o.sp(k.point[1]));
        let (l4, tiny, to_driven) = (o.sp(k.l4), o.sp(k.tiny), o.sp(k.to_driven));
        let rounding_eps = o.sp(tolerance::ROUNDING_EPS * f64::EPSILON);
        let (max_ratio, cos_no) = (o.sp(k.max_ratio), o.sp(k.cos_no));
        let min_margin = o.sp(k.min_margin);
        let min_transmission = o.sp(k.min_transmission);
        let y = o.sp(self.y);

        let n = S::F64_LANES;
        // The whole sample for a map; for the atlas (`needed`) only what
        // `judge_for_atlas` reads.
        let whole = self.needed.is_none();
        let (xs, _) = S::as_simd_f64s(self.xs);
        let out = self.out;
        let (o_qx, o_qy) = (lanes::<S>(&mut out.qx), lanes::<S>(&mut out.qy));
        let (o_worst, o_ratio) = (lanes::<S>(&mut out.worst), lanes::<S>(&mut out.ratio));
        let o_margin = lanes::<S>(&mut out.margin);
        let (o_members, o_flags) = (lanes::<S>(&mut out.members), lanes::<S>(&mut out.flags));
        let (o_grashof, o_mu) = (lanes::<S>(&mut out.grashof), lanes::<S>(&mut out.mu));
        for (c, &x) in xs.iter().enumerate() {
            if self
                .needed
                .is_some_and(|needed| !group_needed(needed, c, n))
            {
                continue;
            }
            let Pre {
                qx,
                qy,
                has_q,
                e: [e0x, e0y, e1x, e1y, e2x, e2y],
                l2,
                tf1,
                tf2,
            } = match self.pre {
                None => {
                    let yx = match self.local {
                        Some(local) => S::as_simd_f64s(local).0[c],
                        None => k.local_x(o, x),
                    };
                    k.driving_lanes(o, x, yx, self.y)
                }
                Some(pre) => {
                    let col = |i: usize| S::as_simd_f64s(&pre.v[i]).0[c];
                    Pre {
                        qx: col(0),
                        qy: col(1),
                        has_q: o.eq(col(2), one),
                        e: [col(3), col(4), col(5), col(6), col(7), col(8)],
                        l2: col(9),
                        tf1: col(10),
                        tf2: col(11),
                    }
                }
            };
            // The lengths and whether the linkage exists (`figures`).
            let (gx, gy) = (o.sub(c0x, x), o.sub(c0y, y));
            let l1 = o.norm(gx, gy);
            let l3 = o.norm(o.sub(c1x, qx), o.sub(c1y, qy));
            let total = o.add(o.add(o.add(l1, l2), l3), l4);
            let valid = o.and(
                o.and(
                    o.and(has_q, o.gt(l1, tiny)),
                    o.and(o.gt(l2, tiny), o.gt(l3, tiny)),
                ),
                o.and(o.gt(l4, tiny), o.finite(total)),
            );
            // The input bounds (`input_bounds`).
            // `l1 / m` and `l2 / m` with `m` the larger: one of them is
            // `m / m`, exactly 1 for every linkage that exists.
            let l1_max = o.gt(l1, l2);
            let m = o.sel(l1_max, l1, l2);
            let r = o.div(o.sel(l1_max, l2, l1), m);
            let (g, cr) = (o.sel(l1_max, one, r), o.sel(l1_max, r, one));
            let (l3m, l4m) = (o.div(l3, m), o.div(l4, m));
            let (sum, diff) = (o.add(l3m, l4m), o.sub(l3m, l4m));
            let base = o.add(o.mul(g, g), o.mul(cr, cr));
            let twice = o.mul(o.mul(two, g), cr);
            let rounding = o.div(rounding_eps, twice);
            let (sum2, diff2) = (o.mul(sum, sum), o.mul(diff, diff));
            let c_min = o.div(o.sub(base, sum2), twice);
            let c_max = o.div(o.sub(base, diff2), twice);
            let lo_free = o.le(c_min, o.add(o.sp(-1.0), o.mul(rounding, o.add(base, sum2))));
            let hi_free = o.ge(c_max, o.sub(one, o.mul(rounding, o.add(base, diff2))));
            let full = o.and(lo_free, hi_free);
            // A crank: pseudo-angles `tf1`, `tf2` from the crank at pose 1.
            let no_zero = o.not(o.or(o.eq(tf1, zero), o.eq(tf2, zero)));
            let ccw_f = o.and(no_zero, o.lt(tf1, tf2));
            let cw_f = o.and(no_zero, o.gt(tf1, tf2));
            let from_f = o.sel(ccw_f, zero, tf2);
            let to_f = o.sel(ccw_f, tf2, four);
            // A rocker: pseudo-angles from a direction in the dead zone.
            let rx = o.sel(hi_free, o.neg(gx), gx);
            let ry = o.sel(hi_free, o.neg(gy), gy);
            let tr0 = o.pseudo(rx, ry, e0x, e0y);
            let tr1 = o.pseudo(rx, ry, e1x, e1y);
            let tr2 = o.pseudo(rx, ry, e2x, e2y);
            let side0 = o.gt(o.cross(gx, gy, e0x, e0y), zero);
            let side1 = o.gt(o.cross(gx, gy, e1x, e1y), zero);
            let side2 = o.gt(o.cross(gx, gy, e2x, e2y), zero);
            let same = o.not(o.or(o.xor(side0, side1), o.xor(side0, side2)));
            let one_c = o.or(o.or(hi_free, lo_free), same);
            let ccw_r = o.and(one_c, o.and(o.lt(tr0, tr1), o.lt(tr1, tr2)));
            let cw_r = o.and(one_c, o.and(o.gt(tr0, tr1), o.gt(tr1, tr2)));
            // Where the direction is defined no pseudo-angle is NaN, and
            // `from`, `to` are only compared: a select is `f64::min`/`max`.
            let from_r = o.sel(o.lt(tr2, tr0), tr2, tr0);
            let to_r = o.sel(o.gt(tr2, tr0), tr2, tr0);
            // Either case.
            let rock = o.not(full);
            let ccw = o.or(o.and(full, ccw_f), o.and(rock, ccw_r));
            let cw = o.or(o.and(full, cw_f), o.and(rock, cw_r));
            let one_circuit = o.or(full, one_c);
            let (rx, ry) = (o.sel(full, e0x, rx), o.sel(full, e0y, ry));
            let (from, to) = (o.sel(full, from_f, from_r), o.sel(full, to_f, to_r));
            // The worst |cos mu| over the travel.
            let k0 = o.add(o.mul(l1, l1), o.mul(l2, l2));
            let k1 = o.mul(o.mul(two, l1), l2);
            let k2 = o.add(o.mul(l3, l3), o.mul(l4, l4));
            let inv = o.div(one, o.mul(o.mul(two, l3), l4));
            let kk = [k0, k1, k2, inv];
            let inv12 = o.div(one, o.mul(l1, l2));
            let mut worst = o.fmax(
                o.cos_mu(o.mul(o.dot(gx, gy, e0x, e0y), inv12), kk),
                o.cos_mu(o.mul(o.dot(gx, gy, e2x, e2y), inv12), kk),
            );
            let (p_g, p_minus_g) = o.pseudo_pm(rx, ry, gx, gy);
            let at_g = o.inside(p_g, from, to, full);
            worst = o.sel(at_g, o.fmax(worst, o.cos_mu(one, kk)), worst);
            let at_minus_g = o.inside(p_minus_g, from, to, full);
            worst = o.sel(at_minus_g, o.fmax(worst, o.cos_mu(o.sp(-1.0), kk)), worst);
            // Link ratio, Grashof margin (`grashof_margin_of`); the Grashof
            // class and the members' length (`members_length`) below, for
            // a map.
            let longest = o.fmax(o.fmax(l1, l2), o.fmax(l3, l4));
            let shortest = o.fmin(o.fmin(l1, l2), o.fmin(l3, l4));
            let lhs = o.add(shortest, longest);
            let rhs = o.sub(total, lhs);
            let margin = o.div(o.abs(o.sub(lhs, rhs)), total);
            // Zero where the linkage does not exist.
            let flags = o.sel(
                valid,
                o.add(
                    o.add(o.flag(valid, VALID), o.flag(full, FULL)),
                    o.add(
                        o.flag(one_circuit, ONE_CIRCUIT),
                        o.add(o.flag(ccw, CCW), o.flag(cw, CW)),
                    ),
                ),
                zero,
            );

            let ratio = o.div(longest, shortest);
            o_qx[c] = qx;
            o_qy[c] = qy;
            o_worst[c] = worst;
            o_ratio[c] = ratio;
            o_margin[c] = margin;
            // The limits' tests but the transmission angle's, as
            // `meets_when` makes them.
            let input = match k.input {
                InputRequirement::Any => o.eq(zero, zero),
                InputRequirement::Crank => full,
                InputRequirement::Rocker => o.not(full),
            };
            let limits = o.and(
                o.and(o.and(valid, one_circuit), o.or(ccw, cw)),
                o.and(
                    o.and(o.le(ratio, max_ratio), o.ge(margin, min_margin)),
                    input,
                ),
            );
            if whole {
                let mu = acos(o, worst);
                o_mu[c] = mu;
                let meets = o.and(limits, o.ge(mu, min_transmission));
                o_flags[c] = o.add(flags, o.flag(meets, MEETS));
            } else {
                let may = o.and(limits, o.le(worst, cos_no));
                o_flags[c] = o.add(flags, o.flag(may, MAY_MEET));
            }
            if whole {
                // The Grashof class (`grashof_of`), as its code.
                let change = o.le(o.abs(o.sub(lhs, rhs)), o.mul(rounding_eps, total));
                let by_shortest = o.sel(
                    o.eq(l1, shortest),
                    o.sp(code(Grashof::DoubleCrank)),
                    o.sel(
                        o.eq(l2, shortest),
                        o.sp(code(Grashof::CrankRocker)),
                        o.sel(
                            o.eq(l3, shortest),
                            o.sp(code(Grashof::DoubleRocker)),
                            o.sp(code(Grashof::RockerCrank)),
                        ),
                    ),
                );
                let grashof = o.sel(
                    change,
                    o.sp(code(Grashof::ChangePoint)),
                    o.sel(
                        o.gt(lhs, rhs),
                        o.sp(code(Grashof::TripleRocker)),
                        by_shortest,
                    ),
                );
                let members = o.add(
                    o.add(total, o.norm(o.sub(px, qx), o.sub(py, qy))),
                    to_driven,
                );
                o_members[c] = members;
                o_grashof[c] = grashof;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Pose;
    use crate::design::columns::{Columns, Sample};
    use crate::design::judge::Sampler;
    use crate::design::options::MapOptions;
    use crate::design::{Constraints, DesignLimits, InputRequirement};
    use crate::geom::{Grid, Viewport};
    use crate::simd::Width;
    use crate::synthesis::Task;
    use proptest::prelude::*;

    /// Fills the lanes of the row at an ordinate.
    type RowFn<'a> = dyn Fn(f64, &mut RowOut) + 'a;

    /// Every lane of a row, on the lanes of the caller's choice.
    fn lanes<'k, 'o>(
        k: &'k DrivingKernel<'k>,
        y: f64,
        xs: &'o [f64],
        out: &'o mut RowOut,
    ) -> Lanes<'k, 'o> {
        Lanes {
            k,
            y,
            xs,
            local: None,
            needed: None,
            pre: None,
            out,
        }
    }

    /// Every field of two samples, bit for bit.
    fn same(a: &Sample, b: &Sample) -> bool {
        a.valid == b.valid
            && a.branch_free == b.branch_free
            && a.grashof == b.grashof
            && a.input_full == b.input_full
            && a.direction == b.direction
            && a.one_circuit == b.one_circuit
            && a.min_transmission_rad.to_bits() == b.min_transmission_rad.to_bits()
            && a.link_ratio.to_bits() == b.link_ratio.to_bits()
            && a.size_ratio.to_bits() == b.size_ratio.to_bits()
            && a.acceptable == b.acceptable
    }

    /// The kernel on each lane width, and as dispatched, against the
    /// scalar path at every sample of `grid`; returns the samples checked.
    fn check(task: &Task, c0: Point2<f64>, grid: &Grid) -> usize {
        [
            DesignLimits::default(),
            DesignLimits {
                min_transmission: 0.0,
                max_link_ratio: 4.0,
                input: InputRequirement::Crank,
                ..DesignLimits::default()
            },
            DesignLimits {
                min_transmission: 50f64.to_radians(),
                max_link_ratio: 1e300,
                input: InputRequirement::Rocker,
                ..DesignLimits::default()
            },
            DesignLimits {
                max_size_ratio: 12.0,
                max_link_length: 6.0,
                ..DesignLimits::default()
            },
            DesignLimits {
                min_grashof_margin: 0.0,
                ..DesignLimits::default()
            },
            DesignLimits {
                min_transmission: 0.0,
                max_link_ratio: f64::INFINITY,
                min_grashof_margin: 0.15,
                ..DesignLimits::default()
            },
        ]
        .iter()
        .map(|limits| check_with(task, c0, grid, limits))
        .sum()
    }

    fn check_with(task: &Task, c0: Point2<f64>, grid: &Grid, limits: &DesignLimits) -> usize {
        let options = MapOptions::new(limits, &Constraints::default()).unwrap();
        let sampler = Sampler::new(task, &options).unwrap();
        let Ok(driven) = task.dyad_from_center(c0) else {
            return 0;
        };
        let c = sampler.fixed_pivots(&driven);
        let Some(k) = DrivingKernel::new(&sampler, driven, &c) else {
            return 0;
        };
        let xs = DrivingKernel::padded_xs(grid).unwrap();
        let mut out = RowOut::new(&xs).unwrap();
        let all = vec![true; grid.nx()];
        // The driving candidates' lanes computed beforehand (as the atlas
        // does, dispatched) and read on other lane widths.
        let with_pre = |y: f64, out: &mut RowOut, width: Width| {
            let mut pre = RowPre::new(&xs).unwrap();
            k.pre_row(y, &xs, &all, &mut pre);
            width.run(Lanes {
                pre: Some(&pre),
                ..lanes(&k, y, &xs, out)
            });
        };
        let (kr, xr) = (&k, &xs);
        let on = |width: Width| move |y: f64, out: &mut RowOut| width.run(lanes(kr, y, xr, out));
        let [one, b128, b256, b512] = [Width::One, Width::B128, Width::B256, Width::B512].map(on);
        let widths: [&RowFn<'_>; 7] = [
            &one,
            &b128,
            &b256,
            &b512,
            &|y, out| k.row(y, &xs, &k.local_xs(&xs).unwrap(), out),
            &|y, out| with_pre(y, out, Width::One),
            &|y, out| with_pre(y, out, Width::B512),
        ];
        let mut n = 0;
        let nx = grid.nx();
        let mut row = Columns::for_overwrite(nx).unwrap();
        for j in 0..grid.ny() {
            let y = grid.y(j);
            let branch: Vec<bool> = (0..nx).map(|i| (i + j) % 3 != 0).collect();
            for lanes in widths {
                lanes(y, &mut out);
                k.write_row(&mut out, y, &xs, &branch, row.rows(nx).row(0));
                for (i, &free) in branch.iter().enumerate() {
                    let a0 = Point2::new(grid.x(i), y);
                    let want = sampler.driving_sample(a0, driven, &c, free);
                    let got = row.sample(i);
                    assert!(same(&want, &got), "sample ({i}, {j}) at {a0}");
                    n += 1;
                }
            }
            // The atlas's path: only the needed groups of lanes, the
            // transmission angle only where the rest is acceptable.
            let needed: Vec<bool> = (0..grid.nx()).map(|i| (i * 7 + j) % 5 != 0).collect();
            let mut out = RowOut::new(&xs).unwrap();
            // The candidates' lanes for more groups than needed, as the
            // atlas's union over a chunk of centers.
            let mut pre = RowPre::new(&xs).unwrap();
            let more: Vec<bool> = needed
                .iter()
                .enumerate()
                .map(|(i, &f)| f || i % 3 == 0)
                .collect();
            k.pre_row(y, &xs, &more, &mut pre);
            k.row_where(y, &xs, &needed, &pre, &mut out);
            for (i, _) in needed.iter().enumerate().filter(|(_, f)| **f) {
                let a0 = Point2::new(grid.x(i), y);
                let want = sampler.driving_sample(a0, driven, &c, true);
                let band = CosBand::new(limits.min_transmission);
                let got = k.judge_for_atlas(&out, i, a0, &band);
                let want = want.valid.then_some(
                    want.acceptable
                        .then_some(want.min_transmission_rad.to_bits()),
                );
                let got = got.map(|a| a.map(|w| (acos1(w) as f32).to_bits()));
                assert_eq!(got, want, "({i}, {j}) at {a0}");
                n += 1;
            }
        }
        n
    }

    fn grid(x: (f64, f64), y: (f64, f64), nx: usize, ny: usize) -> Grid {
        Grid::new(Viewport::new(x.0, x.1, y.0, y.1).unwrap(), nx, ny).unwrap()
    }

    /// A 3 x 3 grid whose middle sample is exactly `p`, if one is found.
    fn through(p: Point2<f64>) -> Option<Grid> {
        (0..40).map(|e| 0.5f64.powi(e)).find_map(|h| {
            let g = grid(
                (p.x - 3.0 * h, p.x + 3.0 * h),
                (p.y - 3.0 * h, p.y + 3.0 * h),
                3,
                3,
            );
            (g.x(1) == p.x && g.y(1) == p.y).then_some(g)
        })
    }

    #[test]
    fn example_task_bit_for_bit() {
        let task = crate::example::task();
        let c0 = crate::example::driven_center();
        let g = grid((-8.0, 8.0), (-8.0, 8.0), 67, 53);
        assert!(check(&task, c0, &g) > 5 * 67 * 53);
        // Samples exactly on the driven center (no ground link) and, where
        // a grid can hit them, on the poles (no circle point).
        let poles = task.filemon(c0).unwrap().cremona().unwrap().poles();
        let mut hit = 0;
        for p in [c0].into_iter().chain(poles) {
            if let Some(g) = through(p) {
                hit += 1;
                assert!(check(&task, c0, &g) >= 5 * 9);
            }
        }
        assert!(hit >= 1);
        // Far and huge candidates.
        assert!(check(&task, c0, &grid((-1e12, 1e12), (-1e300, 1e300), 17, 13)) > 0);
    }

    #[test]
    fn cos_band_is_the_acos_comparison() {
        let mut checked = 0;
        for angle in [
            0.0,
            1e-12,
            5e-4,
            1e-3,
            0.1,
            30f64.to_radians(),
            1.0,
            89f64.to_radians(),
            2.0,
            3.0,
        ] {
            let band = CosBand::new(angle);
            let c = angle.cos();
            // Dense about the threshold (ulps and slacks away) and across [0, 1].
            let near = (-3000..=3000).map(|k| c + f64::from(k) * 1e-13);
            let ulps = (-50..=50).map(|k| c + f64::from(k) * f64::EPSILON * c.abs().max(1e-300));
            let spread = (0..=2000).map(|k| f64::from(k) / 2000.0);
            for w in near
                .chain(ulps)
                .chain(spread)
                .filter(|w| (0.0..=1.0).contains(w))
            {
                assert_eq!(band.at_least(w), acos1(w) >= angle, "angle {angle}, w {w}");
                if !band.may_reach(w) {
                    assert!(
                        acos1(w) < angle - 0.5 * CosBand::SLACK,
                        "angle {angle}, w {w}"
                    );
                }
                checked += 1;
            }
        }
        assert!(checked > 50_000);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        #[test]
        fn random_tasks_bit_for_bit(
            poses in proptest::collection::vec((-5.0..5.0f64, -5.0..5.0f64, -3.0..3.0f64), 3),
            c0 in (-6.0..6.0f64, -6.0..6.0f64),
            half in 0.5..40.0f64,
            n in 1usize..23,
        ) {
            let poses: Vec<Pose> = poses.iter().map(|&(x, y, a)| Pose::new(x, y, a)).collect();
            let Ok(task) = Task::new(&poses) else { return Ok(()); };
            let grid = grid((-half, half), (-half * 0.7, half * 1.3), n, 9);
            check(&task, Point2::new(c0.0, c0.1), &grid);
        }
    }
}
