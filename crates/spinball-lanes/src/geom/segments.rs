//! Tables built from segments in lanes: any [`SegmentTable`] (polygons,
//! mushrooms, annuli, tables with holes) runs in the kernels.
//!
//! The scalar `SegmentTable::cast` picks the earliest wall with one
//! division: the flat walls are compared by their undivided flight times
//! (`LineSegment::approach`, cross-multiplied), in the order of
//! `SegmentTable::flat_visits`; the arcs by the numerators of theirs
//! (`ArcSegment::approach`: every arc divides by `|v|²`) in id order; then
//! the earliest arc against the earliest flat wall, cross-multiplied, and
//! only the winner's fraction is divided and only the winner is landed
//! (a flat wall's contact, or an arc's contact snapped onto its circle).
//! Here every wall is cast for every lane with the same arithmetic and
//! the same comparisons, and the earliest kept by compare-and-select, so a
//! lane finds bitwise the scalar hit. The walls' constants are computed
//! once, when the table is compiled into a [`LaneSegments`].
//!
//! The search keeps only the nearest wall's flight time and id per lane;
//! the winner's constants (start, direction, length of a flat wall; centre,
//! radius, curvature of an arc) are fetched together by that id, as one
//! row of [`Records`], once, for the landing, rather than carried through
//! every comparison (which would keep a dozen more registers live per lane
//! group).
//! A finite-difference shadow, which meets its reference's wall in all but
//! the rarest steps, reuses the reference's fetch when every lane's ids
//! agree ([`Geom::land_both`]).
//!
//! An arc whose chord lies along an axis (`ArcSegment::chord`, exact for
//! the stadium's and the mushroom's caps) tests its contact with one
//! product instead of a cross product ([`Cover`]).
//!
//! The flat walls' forms (alone, paired with their opposite, along an axis)
//! and the search for the earliest of them are in
//! [`flat_walls`](super::flat_walls); the arcs, the choice between the two
//! kinds and the landing are here.
//!
//! [`SegmentTable`]: spinball_geometry::SegmentTable

use spinball_geometry::{ArcSegment, Segment, SegmentTable};

use super::flat_walls::{Step, earliest, steps};
use super::round::{Ray, Round, concave_root, contact, convex_root};
use super::{Geom, LaneHit};
use crate::lanes::{ArcCast, BulkyCast, Footprint, Lanes, MaskOps, Records, cmp};

/// An arc's constants, as `ArcSegment::approach` and `land` use them.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Curve {
    /// Wall id.
    id: f64,
    /// The ball meets it from inside its circle (else from outside).
    concave: bool,
    cx: f64,
    cy: f64,
    round: Round,
    /// How a contact is tested against the chord.
    cover: Cover,
    /// `−slack · |chord| − lift`: how far behind the chord's line moved
    /// through the centre a contact still counts (times `|v|²` in the test).
    floor: f64,
}

/// The test of `ArcSegment::approach` that a contact lies on the arc: on
/// its side of the chord, `side · chord × q ≥ floor · |v|²`, with `q` the
/// contact's offset from the centre times `|v|²`.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Cover {
    /// A full circle covers every contact: no test.
    Full,
    /// A chord along an axis (one of `side · chord`'s components exactly
    /// zero, as the stadium's caps and the mushroom's cap have): the cross
    /// product `q_y c_x − q_x c_y` is one product, `q_x · (−c_y)` if
    /// `upright` (`c_x` zero), else `q_y · c_x`, and `q`'s other component
    /// is not computed. The product left out is a signed zero wherever the
    /// test counts (where the root is found, `q` is finite: positions and
    /// speeds within `1e60`, the crate's ranges, keep `|q|` below `1e182`);
    /// it can change only the sign of a zero cross product, which the
    /// comparison does not see.
    Axis { upright: bool, k: f64 },
    /// Any other chord, `side · chord`: the whole cross product.
    Oblique { chx: f64, chy: f64 },
}

impl Cover {
    fn new(full: bool, chx: f64, chy: f64) -> Self {
        if full {
            Cover::Full
        } else if chy == 0.0 {
            Cover::Axis {
                upright: false,
                k: chx,
            }
        } else if chx == 0.0 {
            Cover::Axis {
                upright: true,
                k: -chy,
            }
        } else {
            Cover::Oblique { chx, chy }
        }
    }
}

impl Curve {
    fn new(id: usize, a: &ArcSegment, slack: f64) -> Self {
        let (r, chord, side) = (a.radius(), a.chord(), a.chord_side());
        let (c, start) = (a.center(), a.start());
        let lift = side * chord.perp_dot(c - start);
        Curve {
            id: id as f64,
            concave: a.is_concave(),
            cx: c.x,
            cy: c.y,
            round: Round::new(r),
            // `side` is ±1: scaling the chord by it negates the cross
            // product exactly.
            cover: Cover::new(a.is_full(), side * chord.x, side * chord.y),
            floor: -slack * chord.length() - lift,
        }
    }
}

/// What landing on a wall needs, by wall id, as the columns of one
/// [`Records`]: its origin (a flat wall's start, an arc's centre: the
/// ball's offset from it after the flight is computed once for both kinds),
/// a flat wall's direction and length, an arc's curvature, radius and the
/// radius's reciprocal. A wall's entries in the other kind's columns are 0.
#[derive(Clone, Debug, PartialEq)]
struct Landing(Records);

impl Landing {
    fn new(walls: &[Segment]) -> Self {
        Landing(Records::new(
            walls
                .iter()
                .map(|w| match w {
                    Segment::Line(l) => {
                        let (o, d) = (l.start(), l.direction());
                        [o.x, o.y, d.x, d.y, l.length(), 0.0, 0.0, 0.0]
                    }
                    Segment::Arc(a) => {
                        let (c, r) = (a.center(), a.radius());
                        let inv_r = Round::new(r).inv_r;
                        [c.x, c.y, 0.0, 0.0, 0.0, a.curvature(), r, inv_r]
                    }
                })
                .collect(),
        ))
    }
}

/// A [`SegmentTable`] compiled for the kernels: every wall's constants,
/// in the order the cast visits them. Build it once per table; the kernels
/// cast against a [`view`](Self::view) of it.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct LaneSegments {
    /// The flat walls, in `SegmentTable::flat_visits` order.
    steps: Vec<Step>,
    /// The arcs, in id order.
    arcs: Vec<Curve>,
    /// The walls' constants for the landing, by id.
    landing: Landing,
    /// `−slack`: how far behind a flat wall, or past its ends, a ball or a
    /// contact still counts.
    lo: f64,
    /// Every arc has radius 1 (the contact's scalings by `r` and `1/r` are
    /// then exact and skipped).
    unit: bool,
}

impl LaneSegments {
    pub fn new(table: &SegmentTable) -> Self {
        let slack = table.slack();
        let walls = table.walls();
        let arcs = walls
            .iter()
            .enumerate()
            .filter_map(|(i, w)| match w {
                Segment::Arc(a) => Some(Curve::new(i, a, slack)),
                Segment::Line(_) => None,
            })
            .collect::<Vec<Curve>>();
        LaneSegments {
            unit: arcs.iter().all(|a| a.round.r == 1.0),
            steps: steps(table),
            arcs,
            landing: Landing::new(walls),
            lo: -slack,
        }
    }

    /// Whether the table has an arc.
    pub fn is_curved(&self) -> bool {
        !self.arcs.is_empty()
    }

    /// The table as the kernels cast against it. `CURVED` must be true if
    /// the table has an arc (false skips the tangent map's curvature term
    /// and the circle arithmetic).
    pub fn view<const CURVED: bool>(&self) -> Segments<'_, CURVED> {
        assert!(
            CURVED || !self.is_curved(),
            "a table with arcs needs the curved view"
        );
        Segments {
            steps: &self.steps,
            arcs: &self.arcs,
            landing: &self.landing,
            lo: self.lo,
            unit: self.unit,
        }
    }
}

/// A borrowed [`LaneSegments`], the form the kernels take (`Copy`).
/// `CURVED`: whether it may hold arcs.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Segments<'a, const CURVED: bool> {
    steps: &'a [Step],
    arcs: &'a [Curve],
    landing: &'a Landing,
    lo: f64,
    unit: bool,
}

/// `f64::clamp` with per-lane bounds (`lo <= hi`, neither NaN).
#[inline(always)]
fn clamp<L: Lanes>(x: L, lo: L, hi: L) -> L {
    let x = L::select(x.lt(lo), lo, x);
    L::select(x.gt(hi), hi, x)
}

/// A wall's constants for its landing, fetched by its id for every lane:
/// its origin, a flat wall's direction and length, an arc's radius, its
/// reciprocal, its normal's sign and its curvature (the other kind's read
/// 0).
#[derive(Clone, Copy, Debug)]
struct Fetched<L: Lanes> {
    ox: L,
    oy: L,
    dx: L,
    dy: L,
    length: L,
    r: L,
    inv_r: L,
    sign: L,
    curvature: L,
}

impl Landing {
    /// The constants of wall `wall`, lane by lane (each kind's columns hold
    /// zeros at the other kind's ids; those lanes are discarded). The
    /// normal's sign against the radial direction is that of the curvature
    /// (an arc's is never 0).
    #[inline(always)]
    fn fetch<L: Lanes>(&self, wall: L) -> Fetched<L> {
        let cpu = wall.proof();
        let [ox, oy, dx, dy, length, curvature, r, inv_r] = L::fetch(&self.0, wall);
        Fetched {
            ox,
            oy,
            dx,
            dy,
            length,
            r,
            inv_r,
            sign: L::select(
                curvature.lt(L::splat(cpu, 0.0)),
                L::splat(cpu, -1.0),
                L::splat(cpu, 1.0),
            ),
            curvature,
        }
    }
}

/// The ball's offset from wall `k`'s origin (a flat wall's start, an arc's
/// centre) after flying for `time`, `(origin − o) + v·time`, as
/// `LineSegment::land` and `ArcSegment::land` compute it.
#[inline(always)]
fn offset<L: Lanes>(k: &Fetched<L>, ray: &Ray<L>, time: L) -> (L, L) {
    (
        (ray.x - k.ox) + ray.vx * time,
        (ray.y - k.oy) + ray.vy * time,
    )
}

/// `LineSegment::land` of flat wall `k` from the ball's offset `q` from
/// its start: the contact and the normal.
#[inline(always)]
fn flat_contact<L: Lanes>(k: &Fetched<L>, q: (L, L)) -> (L, L, L, L) {
    let cpu = q.0.proof();
    let along = clamp(q.0 * k.dx + q.1 * k.dy, L::splat(cpu, 0.0), k.length);
    // The normal is the direction's left perpendicular, exactly.
    (k.ox + k.dx * along, k.oy + k.dy * along, -k.dy, k.dx)
}

/// `LineSegment::land` of flat wall `k` (id `wall`) after flying for
/// `time` (the one division), as a hit: the landing of a table without
/// arcs.
#[inline(always)]
fn land_flat<L: Lanes>(k: &Fetched<L>, ray: &Ray<L>, time: L, wall: L) -> LaneHit<L> {
    let cpu = time.proof();
    let (px, py, nx, ny) = flat_contact(k, offset(k, ray, time));
    LaneHit {
        time,
        px,
        py,
        nx,
        ny,
        curvature: L::splat(cpu, 0.0),
        wall,
    }
}

/// The earliest arc so far, lane by lane: its root's numerator (the
/// flight time times `|v|²`; NaN while there is none) and its id.
#[derive(Clone, Copy, Debug)]
struct Nearest<L: Lanes> {
    num: L,
    id: L,
}

/// The landing on wall `k` (id `wall`) after flying for `time`, as a hit:
/// `ArcSegment::land` in the lanes of `arc_wins`, `LineSegment::land` in
/// the others, sharing the origin and the offset from it. The exact
/// normalisation of an arc contact off the circle is computed only if a
/// lane of `arc_wins` has one.
#[inline(always)]
fn land<L: Lanes, const UNIT: bool>(
    k: &Fetched<L>,
    ray: &Ray<L>,
    time: L,
    wall: L,
    arc_wins: L::Mask,
) -> LaneHit<L> {
    let (qx, qy) = offset(k, ray, time);
    let (fx, fy, fnx, fny) = flat_contact(k, (qx, qy));
    let (px, py, radx, rady) = contact::<L, UNIT>(k.ox, k.oy, qx, qy, k.r, k.inv_r, arc_wins);
    LaneHit {
        time,
        px: L::select(arc_wins, px, fx),
        py: L::select(arc_wins, py, fy),
        nx: L::select(arc_wins, radx * k.sign, fnx),
        ny: L::select(arc_wins, rady * k.sign, fny),
        // 0 at a flat wall's id.
        curvature: k.curvature,
        wall,
    }
}

impl<const CURVED: bool> Segments<'_, CURVED> {
    /// `ArcSegment::approach`, lane by lane: the lanes where it returns
    /// `Some`, and the root's numerator (clamped at 0).
    #[inline(always)]
    fn approach_arc<L: Lanes>(&self, a: &Curve, ray: &Ray<L>) -> (L::Mask, L) {
        let cpu = ray.x.proof();
        let zero = L::splat(cpu, 0.0);
        let (cx, cy) = (L::splat(cpu, a.cx), L::splat(cpu, a.cy));
        // A root behind a ball clear of the circle is no hit.
        let (root, on) = if a.concave {
            let root = concave_root::<L, false>(cx, cy, &a.round, ray);
            (root, root.inside)
        } else {
            let root = convex_root(cx, cy, &a.round, ray);
            (root, root.c.ge(L::splat(cpu, -a.round.touch)))
        };
        let ok = root.ok.and(root.num.ge(zero).or(on));
        let num = root.num.max(zero);
        // The contact's offset from the centre, times `|v|²`, one
        // coordinate at a time.
        let qx = || root.dx * ray.a + ray.vx * num;
        let qy = || root.dy * ray.a + ray.vy * num;
        let cross = match a.cover {
            Cover::Full => return (ok, num),
            Cover::Axis { upright: true, k } => qx() * L::splat(cpu, k),
            Cover::Axis { upright: false, k } => qy() * L::splat(cpu, k),
            Cover::Oblique { chx, chy } => qy() * L::splat(cpu, chx) - qx() * L::splat(cpu, chy),
        };
        (
            cross.test::<{ cmp::GE }>(L::splat(cpu, a.floor) * ray.a, ok),
            num,
        )
    }

    /// The earliest arc of every lane, in id order: only a strictly
    /// earlier root replaces the best (and any root replaces none).
    #[inline(always)]
    fn arcs<L: Lanes>(&self, ray: &Ray<L>) -> Nearest<L> {
        let cpu = ray.x.proof();
        let none = L::splat(cpu, f64::NAN);
        let Some((first, rest)) = self.arcs.split_first() else {
            return Nearest {
                num: none,
                id: L::splat(cpu, 0.0),
            };
        };
        // Any root replaces none: the first arc's comparison with the NaN
        // best would be true in every lane, so it is left out.
        let (ok, num) = self.approach_arc(first, ray);
        let mut best = Nearest {
            num: L::select(ok, num, none),
            id: L::select(ok, L::splat(cpu, first.id), L::splat(cpu, 0.0)),
        };
        for a in rest {
            let (ok, num) = self.approach_arc(a, ray);
            let take = best.num.test::<{ cmp::NLE }>(num, ok);
            best.num = L::select(take, num, best.num);
            best.id = L::select(take, L::splat(cpu, a.id), best.id);
        }
        best
    }
}

impl<const CURVED: bool> Segments<'_, CURVED> {
    /// The search of a table with arcs: the earliest arc against the
    /// earliest flat wall, and the winner's flight time.
    #[inline(always)]
    fn curved<L: Lanes>(&self, ray: Ray<L>) -> Found<L> {
        // The arcs first: their square roots are the longest latencies of
        // the search, and the flat walls (independent of them) then fill the
        // wait in program order, within the processor's scheduling window.
        // The order of evaluation changes no result (the two searches share
        // nothing until they are compared below).
        let round = self.arcs(&ray);
        let flat = earliest(self.steps, self.lo, &ray);
        // The earliest arc against the earliest flat wall, cross-multiplied:
        // `t|v|²·speed < dist·|v|²` (any arc if there is no flat wall, a NaN
        // `dist`), ties to the lower id.
        let (x, y) = (round.num * flat.speed, flat.dist * ray.a);
        let arc_wins = round.num.test::<{ cmp::EQ }>(
            round.num,
            y.compare::<{ cmp::NLE }>(x)
                .or(round.id.test::<{ cmp::LT }>(flat.id, x.eq(y))),
        );
        // The one division: the winner's fraction.
        let time =
            L::select(arc_wins, round.num, flat.dist) / L::select(arc_wins, ray.a, flat.speed);
        Found {
            ray,
            time,
            wall: L::select(arc_wins, round.id, flat.id),
            arc_wins,
        }
    }
}

/// What a segment table's search leaves for the landing: the ray, the
/// flight time, the wall and the lanes whose wall is an arc.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Found<L: Lanes> {
    ray: Ray<L>,
    time: L,
    wall: L,
    arc_wins: L::Mask,
}

/// Whether a segment table may hold arcs, as a type: `Arcs<true>` or
/// `Arcs<false>`, which name the table's footprint.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Arcs<const CURVED: bool>;

/// The register footprint of a segment table's cast.
pub(crate) trait SegmentFootprint {
    /// [`ArcCast`] with arcs, [`BulkyCast`] without.
    type Of: Footprint;
}

impl SegmentFootprint for Arcs<true> {
    type Of = ArcCast;
}

impl SegmentFootprint for Arcs<false> {
    type Of = BulkyCast;
}

impl<const CURVED: bool> Geom for Segments<'_, CURVED>
where
    Arcs<CURVED>: SegmentFootprint,
{
    const CURVED: bool = CURVED;
    type Footprint = <Arcs<CURVED> as SegmentFootprint>::Of;
    type Found<L: Lanes> = Found<L>;

    #[inline(always)]
    fn search<L: Lanes>(&self, x: L, y: L, vx: L, vy: L) -> Found<L> {
        if !CURVED {
            let ray = Ray::flat(x, y, vx, vy);
            let flat = earliest(self.steps, self.lo, &ray);
            let none = flat.id.ne(flat.id);
            return Found {
                ray,
                time: flat.dist / flat.speed,
                wall: flat.id,
                arc_wins: none,
            };
        }
        // `|v|²` serves every arc.
        self.curved(Ray::new_undivided(x, y, vx, vy))
    }

    #[inline(always)]
    fn land<L: Lanes>(&self, f: Found<L>) -> LaneHit<L> {
        self.land_fetched(&self.landing.fetch(f.wall), f)
    }

    #[inline(always)]
    fn land_both<L: Lanes>(&self, a: Found<L>, b: Found<L>) -> (LaneHit<L>, LaneHit<L>) {
        let ka = self.landing.fetch(a.wall);
        // A finite-difference shadow meets its reference's wall in all but
        // the rarest steps (at a corner, a junction): the same ids read the
        // same constants, bitwise, so they are fetched once. A NaN id (no
        // wall) compares unequal and is fetched on its own.
        let kb = if b.wall.ne(a.wall).any() {
            self.landing.fetch(b.wall)
        } else {
            ka
        };
        (self.land_fetched(&ka, a), self.land_fetched(&kb, b))
    }
}

impl<const CURVED: bool> Segments<'_, CURVED> {
    /// The landing of `f` on the wall whose constants are `k`.
    #[inline(always)]
    fn land_fetched<L: Lanes>(&self, k: &Fetched<L>, f: Found<L>) -> LaneHit<L> {
        if !CURVED {
            land_flat(k, &f.ray, f.time, f.wall)
        } else if self.unit {
            land::<L, true>(k, &f.ray, f.time, f.wall, f.arc_wins)
        } else {
            land::<L, false>(k, &f.ray, f.time, f.wall, f.arc_wins)
        }
    }
}

/// Tables built from segments for the tests here and in the kernels.
#[cfg(test)]
pub(crate) mod tests;
