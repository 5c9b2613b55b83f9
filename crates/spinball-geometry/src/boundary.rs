//! The one trait every table implements.
//!
//! A billiard only ever asks its table one question: *from here, moving like
//! this, which wall do I hit next?* That is [`Boundary::cast`], the single
//! required method (the pattern of parry's `RayCast`). Everything else a caller
//! wants from a table (is a point inside, a uniform point inside, the
//! perimeter, the size used for tolerances) is a provided method built on it,
//! which the built-in tables override with exact closed forms.

use glam::DVec2;
use rand::Rng;

pub use crate::aabb::Aabb;
use crate::hit::{Hit, WallId};
use crate::shape::Shape;
use crate::wall_kind::WallKind;

/// How many candidates [`Boundary::try_sample_interior`] draws from the
/// bounding box before it gives up: 2²², a fraction of a second. A table
/// filling 10⁻⁵ of its box then fails to find room with probability
/// `e^-42`.
pub const MAX_INTERIOR_DRAWS: u64 = 1 << 22;

/// Fixed direction for the default chord test, chosen to avoid passing exactly
/// through the vertices of tables with rational coordinates.
const PROBE: DVec2 = DVec2::new(0.754_877_666_246_692_7, 0.569_840_290_998_053_2);

/// A billiard table: a bounded region of the plane with walls.
///
/// Implementors provide [`cast`](Boundary::cast); the rest is provided.
///
/// # Contract of `cast`
/// For a ball at `origin` (inside the table or on its wall) moving with
/// `velocity`, return the first wall it meets, considering only walls it moves
/// **into** from the table side (`velocity · normal < 0` at the contact). This
/// rule is what keeps a ball that has just reflected from finding the same
/// flat wall again. Ties (a corner or a junction of two walls, hit within
/// rounding) go to the **lower wall id**, so results are deterministic.
/// Return `None` only if no wall lies ahead (the callers turn this into an
/// error; it never happens for a ball inside a bounded table).
pub trait Boundary {
    /// The next wall hit from `origin` along `velocity`. See the trait docs.
    fn cast(&self, origin: DVec2, velocity: DVec2) -> Option<Hit>;

    /// Whether `p` lies in the table (walls included, to rounding).
    ///
    /// Default: `p` is inside if the chord through `p` along a fixed direction
    /// is a real chord of the table: casting backwards and then forwards from
    /// the back wall reaches the same front wall point, passing `p`.
    fn contains(&self, p: DVec2) -> bool {
        chord_contains(self, p)
    }

    /// Whether `p` lies in the table shrunk towards the box centre by
    /// `shrink` (in `(0, 1]`): the region the paper's initial conditions are
    /// drawn from ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#paper-convention), "Paper convention"). Default: `p` lies in the table
    /// and so does `p` scaled back up by `1/shrink` about the box centre (for
    /// a convex table the first follows from the second; with a hole about
    /// the centre it does not). Tables whose
    /// reference code uses another rule (the Sinai obstacle) override it.
    fn contains_shrunk(&self, p: DVec2, shrink: f64) -> bool {
        let c = self.aabb().center();
        // `p` itself must be in the table too: in a table with a hole about
        // the centre, scaling up can carry a point in the hole out of it.
        self.contains(c + (p - c) / shrink) && self.contains(p)
    }

    /// A bounding box of the table.
    ///
    /// Default: a fan of rays from [`reference_point`](Boundary::reference_point);
    /// tight for tables star-shaped about that point (enlarged by 1% to cover
    /// the fan's gaps). Every built-in table overrides it with the exact box.
    fn aabb(&self) -> Aabb {
        let hits = fan(self);
        let mut min = DVec2::splat(f64::INFINITY);
        let mut max = DVec2::splat(f64::NEG_INFINITY);
        for h in hits {
            min = min.min(h.point);
            max = max.max(h.point);
        }
        let pad = 0.01 * (max - min);
        Aabb::new(min - pad, max + pad)
    }

    /// A point inside the table, used by the default methods. Default: the origin.
    fn reference_point(&self) -> DVec2 {
        DVec2::ZERO
    }

    /// Total length of the walls, the range of the Birkhoff coordinate `s`.
    ///
    /// Default: the length of the polygon through a fan of hits (accurate to
    /// about `1e-6` relative for smooth tables star-shaped about the reference
    /// point). Built-in tables override it with the exact value.
    fn perimeter(&self) -> f64 {
        let hits = fan(self);
        let n = hits.len();
        (0..n)
            .map(|i| (hits[(i + 1) % n].point - hits[i].point).length())
            .sum()
    }

    /// Area of the table (holes excluded): the `|Q|` of mean-free-path and
    /// collision-rate formulas.
    ///
    /// Default: the area of the polygon through a fan of hits (accurate to
    /// about `1e-6` relative for smooth tables star-shaped about the
    /// reference point). Built-in tables and [`SegmentTable`](crate::SegmentTable)
    /// override it with the exact value.
    fn area(&self) -> f64 {
        let hits = fan(self);
        let n = hits.len();
        0.5 * (0..n)
            .map(|i| hits[i].point.perp_dot(hits[(i + 1) % n].point))
            .sum::<f64>()
            .abs()
    }

    /// Total length of the curved walls: at α = 0 the share of collisions
    /// on curved walls under the invariant measure is
    /// `curved_length / perimeter` (the billiard map's measure `cos θ ds dθ`
    /// gives each wall its share of the perimeter).
    ///
    /// Default: the fan polygon's edges whose two end hits are both on
    /// curved walls (as accurate as [`perimeter`](Boundary::perimeter)).
    /// Built-in tables and [`SegmentTable`](crate::SegmentTable) override it
    /// with the exact value.
    fn curved_length(&self) -> f64 {
        let hits = fan(self);
        let n = hits.len();
        (0..n)
            .filter(|&i| hits[i].is_curved() && hits[(i + 1) % n].is_curved())
            .map(|i| (hits[(i + 1) % n].point - hits[i].point).length())
            .sum()
    }

    /// The table as data, for engines that compile it (the vector-lane
    /// kernels of `spinball-lanes`) and for the provenance of results.
    ///
    /// Default: `None` (the table runs on the scalar path only). Every
    /// built-in table and [`SegmentTable`](crate::SegmentTable) returns its
    /// [`Shape`]; a wrapper around one of them should forward it.
    fn shape(&self) -> Option<Shape> {
        None
    }

    /// The length the table is measured in: `s` for a table scaled by `s`
    /// from its reference shape, and 1 for every table of the paper (unit
    /// circle, unit square, stadium with unit caps, Sinai box of half-side 2).
    /// Finite-difference perturbations scale with it.
    ///
    /// Default: [`length_scale`](Boundary::length_scale). Built-in tables
    /// override it: circle `R`, rectangle `min(l, h)`, stadium 1 (its cap
    /// radius), Sinai `l / 2`.
    fn unit_length(&self) -> f64 {
        self.length_scale()
    }

    /// Characteristic size of the table (half the diagonal of its bounding box).
    /// Geometric tolerances are this times a small multiple of machine epsilon.
    fn length_scale(&self) -> f64 {
        0.5 * self.aabb().size().length()
    }

    /// A point drawn uniformly from the table shrunk by `shrink` (`1.0` for the
    /// whole table), by rejection from the bounding box: at most
    /// [`MAX_INTERIOR_DRAWS`] candidates, `None` if none was inside (a table,
    /// or shrunk table, that fills almost none of its box: a ring or a
    /// corridor narrower than `1 − shrink` of its size, a thin strip across
    /// its box).
    fn try_sample_interior<R: Rng + ?Sized>(&self, rng: &mut R, shrink: f64) -> Option<DVec2>
    where
        Self: Sized,
    {
        let bx = self.aabb();
        let c = bx.center();
        let half = 0.5 * bx.size() * shrink;
        (0..MAX_INTERIOR_DRAWS).find_map(|_| {
            let p = c + DVec2::new(
                half.x * (2.0 * rng.random::<f64>() - 1.0),
                half.y * (2.0 * rng.random::<f64>() - 1.0),
            );
            let inside = if shrink == 1.0 {
                self.contains(p)
            } else {
                self.contains_shrunk(p, shrink)
            };
            inside.then_some(p)
        })
    }

    /// [`try_sample_interior`](Self::try_sample_interior) for a table known
    /// to have room.
    ///
    /// # Panics
    /// If no candidate of [`MAX_INTERIOR_DRAWS`] was inside (fallible
    /// callers use `try_sample_interior`).
    fn sample_interior<R: Rng + ?Sized>(&self, rng: &mut R, shrink: f64) -> DVec2
    where
        Self: Sized,
    {
        self.try_sample_interior(rng, shrink).unwrap_or_else(|| {
            panic!(
                "no point of {MAX_INTERIOR_DRAWS} drawn from the bounding box was inside the table shrunk by {shrink}"
            )
        })
    }

    /// The wall contact at Birkhoff arc length `s` (taken modulo the
    /// perimeter): point, inward normal, curvature, wall id and `s`, with
    /// flight time 0. The inverse of [`Hit::s`]: what a phase-space section
    /// needs to put a ball at given Birkhoff coordinates.
    ///
    /// Default: `None` (the table cannot say). Every built-in table and
    /// [`SegmentTable`](crate::SegmentTable) give it in closed form, and
    /// return `None` only for a non-finite `s`.
    fn hit_at(&self, s: f64) -> Option<Hit> {
        let _ = s;
        None
    }

    /// What wall `wall` does to a ball that reaches it: reflect it, let it
    /// out (a hole) or pass it to its periodic partner.
    ///
    /// Default: [`WallKind::Reflecting`] for every wall (a closed table).
    /// [`SegmentTable`](crate::SegmentTable) returns the kinds it was
    /// given; a wrapper around a table must forward it, or its holes and
    /// periodic walls turn into mirrors.
    #[inline]
    fn wall_kind(&self, wall: WallId) -> WallKind {
        let _ = wall;
        WallKind::Reflecting
    }

    /// The lattice basis `[b₁, b₂]` of a periodic table: a ball's
    /// [`Cell`](crate::Cell) `(i, j)` sits at `i·b₁ + j·b₂`. `None` for a
    /// table without periodic walls (the default); forward it in wrappers.
    fn lattice(&self) -> Option<[DVec2; 2]> {
        None
    }

    /// Whether any wall is a hole (a ball can leave the table). Default:
    /// `false`; forward it in wrappers.
    fn has_holes(&self) -> bool {
        false
    }

    /// The Birkhoff coordinates `(s, v∥)` of a hit for a ball arriving with
    /// `velocity` (paper §II.B): arc length and tangential velocity.
    fn birkhoff(&self, hit: &Hit, velocity: DVec2) -> (f64, f64) {
        (hit.s(), velocity.dot(hit.tangent()))
    }
}

/// A borrowed table is a table: `Billiard::new(&table, law)` runs without
/// cloning it. Every method forwards, so exact overrides are kept.
impl<B: Boundary> Boundary for &B {
    #[inline]
    fn cast(&self, origin: DVec2, velocity: DVec2) -> Option<Hit> {
        (**self).cast(origin, velocity)
    }
    fn contains(&self, p: DVec2) -> bool {
        (**self).contains(p)
    }
    fn contains_shrunk(&self, p: DVec2, shrink: f64) -> bool {
        (**self).contains_shrunk(p, shrink)
    }
    fn aabb(&self) -> Aabb {
        (**self).aabb()
    }
    fn reference_point(&self) -> DVec2 {
        (**self).reference_point()
    }
    fn perimeter(&self) -> f64 {
        (**self).perimeter()
    }
    fn area(&self) -> f64 {
        (**self).area()
    }
    fn curved_length(&self) -> f64 {
        (**self).curved_length()
    }
    fn shape(&self) -> Option<Shape> {
        (**self).shape()
    }
    fn length_scale(&self) -> f64 {
        (**self).length_scale()
    }
    fn unit_length(&self) -> f64 {
        (**self).unit_length()
    }
    fn sample_interior<R: Rng + ?Sized>(&self, rng: &mut R, shrink: f64) -> DVec2 {
        (**self).sample_interior(rng, shrink)
    }
    fn try_sample_interior<R: Rng + ?Sized>(&self, rng: &mut R, shrink: f64) -> Option<DVec2> {
        (**self).try_sample_interior(rng, shrink)
    }
    fn birkhoff(&self, hit: &Hit, velocity: DVec2) -> (f64, f64) {
        (**self).birkhoff(hit, velocity)
    }
    fn hit_at(&self, s: f64) -> Option<Hit> {
        (**self).hit_at(s)
    }
    #[inline]
    fn wall_kind(&self, wall: WallId) -> WallKind {
        (**self).wall_kind(wall)
    }
    fn lattice(&self) -> Option<[DVec2; 2]> {
        (**self).lattice()
    }
    fn has_holes(&self) -> bool {
        (**self).has_holes()
    }
}

/// The default [`Boundary::contains`]: whether the chord through `p` along
/// a fixed direction is a real chord of the table.
pub(crate) fn chord_contains<B: Boundary + ?Sized>(table: &B, p: DVec2) -> bool {
    let (Some(front), Some(back)) = (table.cast(p, PROBE), table.cast(p, -PROBE)) else {
        return false;
    };
    let tol = 1e-9 * table.length_scale();
    // Both hits must lie on the line through `p`: from a point outside, a
    // cast may return a contact snapped onto a wall somewhere else.
    let on_line = |hit: &Hit, dir: DVec2| (p + dir * hit.time - hit.point).length() <= tol;
    if !on_line(&front, PROBE) || !on_line(&back, -PROBE) {
        return false;
    }
    let Some(again) = table.cast(back.point, PROBE) else {
        return false;
    };
    (again.point - front.point).length() <= tol
}

/// Hits of a fan of rays from the reference point.
fn fan<B: Boundary + ?Sized>(table: &B) -> Vec<Hit> {
    const N: usize = 4096;
    let o = table.reference_point();
    (0..N)
        .filter_map(|i| {
            let dir = DVec2::from_angle(std::f64::consts::TAU * (i as f64 + 0.5) / N as f64);
            table.cast(o, dir)
        })
        .collect()
}
