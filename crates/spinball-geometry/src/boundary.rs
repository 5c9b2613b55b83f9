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

use crate::hit::Hit;

/// An axis-aligned bounding box.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Aabb {
    /// Lower-left corner.
    pub min: DVec2,
    /// Upper-right corner.
    pub max: DVec2,
}

impl Aabb {
    /// The box spanned by two corners.
    pub fn new(min: DVec2, max: DVec2) -> Self {
        Aabb { min, max }
    }
    /// Centre of the box.
    pub fn center(&self) -> DVec2 {
        0.5 * (self.min + self.max)
    }
    /// Full extents (width, height).
    pub fn size(&self) -> DVec2 {
        self.max - self.min
    }
    /// The smallest box holding both.
    pub fn union(&self, other: &Aabb) -> Aabb {
        Aabb::new(self.min.min(other.min), self.max.max(other.max))
    }
}

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
        let (Some(front), Some(back)) = (self.cast(p, PROBE), self.cast(p, -PROBE)) else {
            return false;
        };
        let tol = 1e-9 * self.length_scale();
        // Both hits must lie on the line through `p`: from a point outside, a
        // cast may return a contact snapped onto a wall somewhere else.
        let on_line = |hit: &Hit, dir: DVec2| (p + dir * hit.time - hit.point).length() <= tol;
        if !on_line(&front, PROBE) || !on_line(&back, -PROBE) {
            return false;
        }
        let Some(again) = self.cast(back.point, PROBE) else {
            return false;
        };
        (again.point - front.point).length() <= tol
    }

    /// Whether `p` lies in the table shrunk towards the box centre by
    /// `shrink` (in `(0, 1]`): the region the paper's initial conditions are
    /// drawn from ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#paper-convention), "Paper convention"). Default: `p` scaled back up
    /// by `1/shrink` about the box centre lies in the table. Tables whose
    /// reference code uses another rule (the Sinai obstacle) override it.
    fn contains_shrunk(&self, p: DVec2, shrink: f64) -> bool {
        let c = self.aabb().center();
        self.contains(c + (p - c) / shrink)
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
        for p in hits {
            min = min.min(p);
            max = max.max(p);
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
        (0..n).map(|i| (hits[(i + 1) % n] - hits[i]).length()).sum()
    }

    /// Characteristic size of the table (half the diagonal of its bounding box).
    /// Geometric tolerances are this times a small multiple of machine epsilon.
    fn length_scale(&self) -> f64 {
        0.5 * self.aabb().size().length()
    }

    /// A point drawn uniformly from the table shrunk by `shrink` (`1.0` for the
    /// whole table), by rejection from the bounding box.
    fn sample_interior<R: Rng + ?Sized>(&self, rng: &mut R, shrink: f64) -> DVec2
    where
        Self: Sized,
    {
        let bx = self.aabb();
        let c = bx.center();
        let half = 0.5 * bx.size() * shrink;
        loop {
            let p = c + DVec2::new(
                half.x * (2.0 * rng.random::<f64>() - 1.0),
                half.y * (2.0 * rng.random::<f64>() - 1.0),
            );
            let inside = if shrink == 1.0 {
                self.contains(p)
            } else {
                self.contains_shrunk(p, shrink)
            };
            if inside {
                return p;
            }
        }
    }

    /// The Birkhoff coordinates `(s, v∥)` of a hit for a ball arriving with
    /// `velocity` (paper §II.B): arc length and tangential velocity.
    fn birkhoff(&self, hit: &Hit, velocity: DVec2) -> (f64, f64) {
        (hit.s(), velocity.dot(hit.tangent()))
    }
}

/// Hit points of a fan of rays from the reference point.
fn fan<B: Boundary + ?Sized>(table: &B) -> Vec<DVec2> {
    const N: usize = 4096;
    let o = table.reference_point();
    (0..N)
        .filter_map(|i| {
            let dir = DVec2::from_angle(std::f64::consts::TAU * (i as f64 + 0.5) / N as f64);
            table.cast(o, dir).map(|h| h.point)
        })
        .collect()
}

/// Pick the earlier of two candidate hits; on a tie the first (lower wall id)
/// wins. Built-in tables list candidates in wall-id order.
#[inline]
pub(crate) fn earlier(a: Option<Hit>, b: Option<Hit>) -> Option<Hit> {
    match (a, b) {
        (Some(x), Some(y)) => Some(if y.time < x.time { y } else { x }),
        (x, None) => x,
        (None, y) => y,
    }
}
