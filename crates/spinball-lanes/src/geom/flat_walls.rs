//! The flat walls of a table built from segments, in lanes: the forms a
//! flat wall is cast in and the search for the earliest.
//!
//! A flat wall is cast as `LineSegment::approach` casts it, operation for
//! operation, in one of four forms chosen when the table is compiled:
//! - alone, any direction ([`Step::One`]), reusing `−(v·n)` and `v·dir` of
//!   the wall before it when the two normals are bitwise the same;
//! - two walls with exactly opposite normals as one, whose constants are
//!   selected lane by lane (the wall facing the ball; [`Step::Pair`]);
//! - along an axis, alone or paired ([`Step::AxisOne`], [`Step::AxisPair`]):
//!   the direction and the normal each have one component exactly zero, so
//!   each of the cast's dot products is one product, in the ball's
//!   coordinates across and along the wall ([`AxisRay`]; one form for both
//!   orientations, so the kernels hold one more copy of the cast, not two);
//! - two walls along an axis on one line, cast in one step that computes
//!   what depends on the line alone once ([`Step::AxisLine`]).
//!
//! What one step shares with the next (`−(v·n)` and `v·dir`) is carried
//! through the loop over the steps; anything more carried that way costs
//! registers in every step of every table (measured: a shared line carried
//! so made the mushroom's kernels about a fifth slower), so two walls on one
//! line are one step instead.
//!
//! The earliest wall is kept as an undivided fraction (`dist / speed`) and
//! compared cross-multiplied, as the scalar `SegmentTable::cast` compares
//! its flat walls, in the same order and with the same tie rule.

use spinball_geometry::{FlatVisit, LineSegment, Segment, SegmentTable};

use super::round::Ray;
use crate::lanes::{Lanes, MaskOps, cmp};

/// A flat wall's constants, as `LineSegment::approach` and `land` use them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Flat {
    /// Wall id.
    pub(super) id: f64,
    /// Start point.
    sx: f64,
    sy: f64,
    /// Unit direction.
    dx: f64,
    dy: f64,
    /// Unit inward normal.
    nx: f64,
    ny: f64,
    /// Minus the normal: `v·(−n)` is `−(v·n)` exactly.
    mnx: f64,
    mny: f64,
    /// `length + slack`: the reach of the wall along itself.
    hi: f64,
}

impl Flat {
    fn new(id: usize, l: &LineSegment, slack: f64) -> Self {
        let (start, dir, normal) = (l.start(), l.direction(), l.normal());
        Flat {
            id: id as f64,
            sx: start.x,
            sy: start.y,
            dx: dir.x,
            dy: dir.y,
            nx: normal.x,
            ny: normal.y,
            mnx: -normal.x,
            mny: -normal.y,
            hi: l.length() + slack,
        }
    }

    #[inline(always)]
    fn lanes<L: Lanes>(&self, cpu: L::Needs) -> FlatLanes<L> {
        FlatLanes {
            id: L::splat(cpu, self.id),
            sx: L::splat(cpu, self.sx),
            sy: L::splat(cpu, self.sy),
            dx: L::splat(cpu, self.dx),
            dy: L::splat(cpu, self.dy),
            nx: L::splat(cpu, self.nx),
            ny: L::splat(cpu, self.ny),
            hi: L::splat(cpu, self.hi),
        }
    }
}

/// A flat wall's constants per lane (the two walls of a pair differ by lane).
#[derive(Clone, Copy, Debug)]
struct FlatLanes<L: Lanes> {
    id: L,
    sx: L,
    sy: L,
    dx: L,
    dy: L,
    nx: L,
    ny: L,
    hi: L,
}

/// A flat wall along an axis: its direction and normal each have one
/// component exactly zero, so of `LineSegment::approach`'s four dot products
/// each is one product (the other adds a signed zero, which can only change
/// the sign of a zero sum: no comparison sees it, and the distance is
/// clamped to its positive part, `+0.0` for either zero). Horizontal and
/// vertical walls share one form, in a frame that names the ball's
/// coordinates across and along the wall ([`AxisRay`]), so the kernels hold
/// one more copy of a flat wall's cast, not two.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Axis {
    /// Wall id.
    pub(super) id: f64,
    /// The wall runs along y (its normal along x); else along x.
    pub(super) upright: bool,
    /// The start's coordinates across the wall and along it.
    sn: f64,
    st: f64,
    /// The direction's component along the wall, the normal's across it,
    /// and minus that.
    d: f64,
    n: f64,
    mn: f64,
    /// `length + slack`.
    hi: f64,
}

impl Axis {
    /// The wall in axis form, if it lies along an axis.
    fn new(f: &Flat) -> Option<Self> {
        let (upright, sn, st, d, n) = if f.ny == 0.0 && f.dx == 0.0 {
            (true, f.sx, f.sy, f.dy, f.nx)
        } else if f.nx == 0.0 && f.dy == 0.0 {
            (false, f.sy, f.sx, f.dx, f.ny)
        } else {
            return None;
        };
        Some(Axis {
            id: f.id,
            upright,
            sn,
            st,
            d,
            n,
            mn: -n,
            hi: f.hi,
        })
    }

    #[inline(always)]
    fn lanes<L: Lanes>(&self, cpu: L::Needs) -> AxisLanes<L> {
        AxisLanes {
            id: L::splat(cpu, self.id),
            sn: L::splat(cpu, self.sn),
            st: L::splat(cpu, self.st),
            d: L::splat(cpu, self.d),
            n: L::splat(cpu, self.n),
            hi: L::splat(cpu, self.hi),
        }
    }
}

/// An axis wall's constants per lane (the two walls of a pair differ by
/// lane).
#[derive(Clone, Copy, Debug)]
struct AxisLanes<L: Lanes> {
    id: L,
    sn: L,
    st: L,
    d: L,
    n: L,
    hi: L,
}

/// The ball's position and velocity across an axis wall (`n`) and along
/// it (`t`): `(x, y)` for a vertical wall, `(y, x)` for a horizontal one.
#[derive(Clone, Copy, Debug)]
struct AxisRay<L: Lanes> {
    pn: L,
    pt: L,
    vn: L,
    vt: L,
}

impl<L: Lanes> AxisRay<L> {
    #[inline(always)]
    fn new(ray: &Ray<L>, upright: bool) -> Self {
        if upright {
            AxisRay {
                pn: ray.x,
                pt: ray.y,
                vn: ray.vx,
                vt: ray.vy,
            }
        } else {
            AxisRay {
                pn: ray.y,
                pt: ray.x,
                vn: ray.vy,
                vt: ray.vx,
            }
        }
    }
}

/// One step of the flat walls' visit order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Step {
    /// A flat wall; `true` if the step before is a flat wall with bitwise
    /// the same normal (its `−(v·n)` and `v·dir` are then reused).
    One(Flat, bool),
    /// Two flat walls with opposite normals (lower id first).
    Pair(Flat, Flat),
    /// A flat wall along an axis; `true` if the step before is one along
    /// the same axis with bitwise the same normal (as for `One`).
    AxisOne(Axis, bool),
    /// Two walls along an axis that lie on one line (bitwise the same
    /// normal and coordinate across), visited one after the other, as the
    /// mushroom's two halves of the cap's floor: what the cast computes
    /// from the line alone ([`Across`]) is computed once for both, then
    /// each wall's tests along it, and the two are compared with the
    /// earliest so far as one candidate. `true` as for `AxisOne`.
    AxisLine(Axis, Axis, bool),
    /// Two walls along the same axis with opposite normals (lower id first).
    AxisPair(Axis, Axis),
}

/// The flat walls of `table` in the order its cast visits them
/// (`SegmentTable::flat_visits`), each in the form it is cast in.
pub(super) fn steps(table: &SegmentTable) -> Vec<Step> {
    let (slack, walls) = (table.slack(), table.walls());
    let flat = |i: usize| match &walls[i] {
        Segment::Line(l) => Flat::new(i, l, slack),
        Segment::Arc(_) => unreachable!("flat visits are lines"),
    };
    let mut steps: Vec<Step> = Vec::new();
    for v in table.flat_visits() {
        // A wall cast alone reuses `−(v·n)` and `v·dir` of the step before
        // if that is a wall of the same form with bitwise the same normal.
        let last = steps.last().copied();
        let step = match *v {
            FlatVisit::One(i) => {
                let f = flat(i);
                match Axis::new(&f) {
                    Some(a) => {
                        let normal =
                            |p: &Axis| p.upright == a.upright && p.n.to_bits() == a.n.to_bits();
                        match last {
                            // On the line of the wall before: cast with it.
                            Some(Step::AxisOne(p, shares))
                                if normal(&p) && p.sn.to_bits() == a.sn.to_bits() =>
                            {
                                Step::AxisLine(p, a, shares)
                            }
                            Some(Step::AxisOne(p, _) | Step::AxisLine(_, p, _)) if normal(&p) => {
                                Step::AxisOne(a, true)
                            }
                            _ => Step::AxisOne(a, false),
                        }
                    }
                    None => {
                        let bits = |w: &Flat| (w.nx.to_bits(), w.ny.to_bits());
                        let shares = matches!(last, Some(Step::One(p, _)) if bits(&p) == bits(&f));
                        Step::One(f, shares)
                    }
                }
            }
            FlatVisit::Pair(i, j) => {
                let (f, g) = (flat(i), flat(j));
                match (Axis::new(&f), Axis::new(&g)) {
                    (Some(a), Some(b)) => {
                        debug_assert_eq!(a.upright, b.upright, "opposite normals");
                        Step::AxisPair(a, b)
                    }
                    _ => Step::Pair(f, g),
                }
            }
        };
        // A wall on the line of the one before replaces it, the two cast
        // as one step.
        if matches!(step, Step::AxisLine(..)) {
            steps.pop();
        }
        steps.push(step);
    }
    steps
}

/// `LineSegment::approach`, lane by lane, given `w = −(v·n)` and
/// `vd = v·dir`: the lanes where it returns `Some`, and the undivided
/// flight time's numerator.
#[inline(always)]
fn approach<L: Lanes>(f: &FlatLanes<L>, w: L, vd: L, lo: f64, ray: &Ray<L>) -> (L::Mask, L) {
    let relx = ray.x - f.sx;
    let rely = ray.y - f.sy;
    let dist = relx * f.nx + rely * f.ny;
    let along = relx * f.dx + rely * f.dy;
    let line = Across::new(dist, w, vd, lo);
    (line.span(along, f.hi, w), line.dist)
}

/// [`approach`] for a wall along an axis, in the ray's frame across and
/// along it (`w = −(v·n)`, `vd = v·dir` in that frame too).
#[inline(always)]
fn approach_axis<L: Lanes>(f: &AxisLanes<L>, w: L, vd: L, lo: f64, r: &AxisRay<L>) -> (L::Mask, L) {
    let line = Across::axis(f, w, vd, lo, r);
    (line.span(along_axis(f, r), f.hi, w), line.dist)
}

/// The ball's offset along a wall along an axis from its start, in the
/// ray's frame across and along it.
#[inline(always)]
fn along_axis<L: Lanes>(f: &AxisLanes<L>, r: &AxisRay<L>) -> L {
    (r.pt - f.st) * f.d
}

/// What `LineSegment::approach` computes from a wall's line alone, given
/// `w = −(v·n)` and `vd = v·dir`: walls on one line share it.
#[derive(Clone, Copy, Debug)]
struct Across<L: Lanes> {
    /// Moving into the line, not behind it.
    ok: L::Mask,
    /// The ball's distance from the line, its positive part.
    dist: L,
    /// `vd · dist` and `lo · w`, the terms of the tests along the wall
    /// that do not depend on where on the line it lies.
    vd_dist: L,
    lo_w: L,
}

impl<L: Lanes> Across<L> {
    /// From the ball's distance `dist` from the line (`lo`: minus the
    /// table's slack).
    #[inline(always)]
    fn new(dist: L, w: L, vd: L, lo: f64) -> Self {
        let cpu = dist.proof();
        let zero = L::splat(cpu, 0.0);
        let lo = L::splat(cpu, lo);
        // Moving into the wall, not behind it (a NaN distance is not
        // "behind").
        let ok = dist.test::<{ cmp::NLT }>(lo, w.gt(zero));
        // The positive part (`+0.0` for either zero, as the scalar's).
        let dist = dist.max(zero);
        Across {
            ok,
            dist,
            vd_dist: vd * dist,
            lo_w: lo * w,
        }
    }

    /// From the ball's distance from a wall's line along an axis.
    #[inline(always)]
    fn axis(f: &AxisLanes<L>, w: L, vd: L, lo: f64, r: &AxisRay<L>) -> Self {
        Self::new((r.pn - f.sn) * f.n, w, vd, lo)
    }

    /// `LineSegment::approach`'s tests along the wall, whose start the
    /// ball is `along` from and whose reach is `hi`: the lanes where it
    /// returns `Some`.
    #[inline(always)]
    fn span(&self, along: L, hi: L, w: L) -> L::Mask {
        let along_w = along * w + self.vd_dist;
        along_w.test::<{ cmp::LE }>(hi * w, along_w.test::<{ cmp::GE }>(self.lo_w, self.ok))
    }
}

/// The earliest flat wall so far, lane by lane: its undivided flight time
/// (`dist / speed`; `dist` NaN while there is none) and its id.
#[derive(Clone, Copy, Debug)]
pub(super) struct Earliest<L: Lanes> {
    pub(super) dist: L,
    pub(super) speed: L,
    pub(super) id: L,
}

impl<L: Lanes> Earliest<L> {
    /// The lanes of `ok` where the candidate `(dist, w)` of wall `id` comes
    /// first: strictly earlier (`dist·speed' < dist'·w`, any candidate while
    /// there is none), or, if `TIES`, as early with a lower id.
    ///
    /// The first wall cast comes first wherever it is found (the NaN
    /// `dist` of none fails every `<=`), so its lanes are `ok` as they are.
    #[inline(always)]
    fn beaten<const TIES: bool>(&self, first: bool, ok: L::Mask, dist: L, w: L, id: L) -> L::Mask {
        if first {
            return ok;
        }
        let (x, y) = (dist * self.speed, self.dist * w);
        if TIES {
            ok.and(
                y.compare::<{ cmp::NLE }>(x)
                    .or(id.test::<{ cmp::LT }>(self.id, x.eq(y))),
            )
        } else {
            y.test::<{ cmp::NLE }>(x, ok)
        }
    }

    #[inline(always)]
    fn keep(&mut self, take: L::Mask, dist: L, w: L, id: L) {
        self.dist = L::select(take, dist, self.dist);
        self.speed = L::select(take, w, self.speed);
        self.id = L::select(take, id, self.id);
    }
}

/// The earliest flat wall of every lane: the walls of `steps` cast in
/// order (`lo`: minus the table's slack).
#[inline(always)]
pub(super) fn earliest<L: Lanes>(steps: &[Step], lo: f64, ray: &Ray<L>) -> Earliest<L> {
    let cpu = ray.x.proof();
    let zero = L::splat(cpu, 0.0);
    let (vx, vy) = (ray.vx, ray.vy);
    let mut best = Earliest {
        dist: L::splat(cpu, f64::NAN),
        speed: L::splat(cpu, 1.0),
        id: zero,
    };
    // `−(v·n)` and `v·dir` of the last flat wall cast alone.
    let (mut w, mut vd) = (zero, zero);
    for (i, step) in steps.iter().enumerate() {
        let first = i == 0;
        match step {
            Step::One(f, shares) => {
                let c = f.lanes::<L>(cpu);
                if !shares {
                    w = vx * f.mnx + vy * f.mny;
                    vd = vx * c.dx + vy * c.dy;
                }
                let (ok, dist) = approach(&c, w, vd, lo, ray);
                // Every wall visited before this one has a lower id, so
                // a tie never goes to it: strictly earlier suffices.
                let take = best.beaten::<false>(first, ok, dist, w, c.id);
                best.keep(take, dist, w, c.id);
            }
            Step::Pair(a, b) => {
                // `−(v·n)` of `a`; that of `b` is its negation, so the
                // wall facing the ball (if any) has divisor `|w|`.
                let wa = vx * a.mnx + vy * a.mny;
                let faces_a = wa.gt(zero);
                let (ca, cb) = (a.lanes::<L>(cpu), b.lanes::<L>(cpu));
                let sel = |p: L, q: L| L::select(faces_a, p, q);
                let c = FlatLanes {
                    id: sel(ca.id, cb.id),
                    sx: sel(ca.sx, cb.sx),
                    sy: sel(ca.sy, cb.sy),
                    dx: sel(ca.dx, cb.dx),
                    dy: sel(ca.dy, cb.dy),
                    nx: sel(ca.nx, cb.nx),
                    ny: sel(ca.ny, cb.ny),
                    hi: sel(ca.hi, cb.hi),
                };
                let w = wa.abs();
                let vd = vx * c.dx + vy * c.dy;
                let (ok, dist) = approach(&c, w, vd, lo, ray);
                let take = best.beaten::<true>(first, ok, dist, w, c.id);
                best.keep(take, dist, w, c.id);
            }
            Step::AxisOne(a, shares) => {
                let r = AxisRay::new(ray, a.upright);
                let c = a.lanes::<L>(cpu);
                if !shares {
                    w = r.vn * L::splat(cpu, a.mn);
                    vd = r.vt * c.d;
                }
                let (ok, dist) = approach_axis(&c, w, vd, lo, &r);
                // Visited in the same order as `Step::One`: strictly
                // earlier suffices.
                let take = best.beaten::<false>(first, ok, dist, w, c.id);
                best.keep(take, dist, w, c.id);
            }
            Step::AxisLine(a, b, shares) => {
                let r = AxisRay::new(ray, a.upright);
                let (ca, cb) = (a.lanes::<L>(cpu), b.lanes::<L>(cpu));
                if !shares {
                    w = r.vn * L::splat(cpu, a.mn);
                    vd = r.vt * ca.d;
                }
                // The second wall's `−(v·n)`, `v·dir` (its direction is
                // the first's: the normals are the same) and everything
                // from the line are the first's, bitwise.
                let line = Across::axis(&ca, w, vd, lo, &r);
                let on_a = line.span(along_axis(&ca, &r), ca.hi, w);
                let on_b = line.span(along_axis(&cb, &r), cb.hi, w);
                // The two walls are one candidate, `(line.dist, w)`, with
                // the first's id where it is found. Visited one after the
                // other, the second could not replace the first: against a
                // best of the same fraction, its `line.dist · w` is the
                // same finite product on both sides (within the crate's
                // ranges), and only a strictly earlier candidate replaces.
                // So one comparison with the best before them picks what
                // the two in turn pick, bitwise.
                let id = L::select(on_a, ca.id, cb.id);
                let take = best.beaten::<false>(first, on_a.or(on_b), line.dist, w, id);
                best.keep(take, line.dist, w, id);
            }
            Step::AxisPair(a, b) => {
                // As `Step::Pair`, in the frame of the pair's axis (both
                // walls lie along it: their normals are opposite).
                let r = AxisRay::new(ray, a.upright);
                let wa = r.vn * L::splat(cpu, a.mn);
                let faces_a = wa.gt(zero);
                let (ca, cb) = (a.lanes::<L>(cpu), b.lanes::<L>(cpu));
                let sel = |p: L, q: L| L::select(faces_a, p, q);
                let c = AxisLanes {
                    id: sel(ca.id, cb.id),
                    sn: sel(ca.sn, cb.sn),
                    st: sel(ca.st, cb.st),
                    d: sel(ca.d, cb.d),
                    n: sel(ca.n, cb.n),
                    hi: sel(ca.hi, cb.hi),
                };
                let w = wa.abs();
                let vd = r.vt * c.d;
                let (ok, dist) = approach_axis(&c, w, vd, lo, &r);
                let take = best.beaten::<true>(first, ok, dist, w, c.id);
                best.keep(take, dist, w, c.id);
            }
        }
    }
    best
}
