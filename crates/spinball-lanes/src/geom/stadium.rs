//! The stadium in lanes: two flat walls and two unit half-circle caps.
//!
//! Bunimovich's stadium is the paper's main table, so it has a kernel of its
//! own rather than going through the general segment table: one flat
//! crossing test decides between the flat wall and the cap on that side,
//! and only that cap is cast against (one square root per cast); the flat
//! wall's flight time and the cap's are then one division of the chosen
//! fraction (`dist / |v_y|` or `num / |v|²`), as in the scalar cast.

use super::round::{Ray, Root, Round, concave_root, contact_at};
use super::{Geom, LaneHit};
use crate::lanes::{Lanes, LeanCast, MaskOps};

/// [`Stadium`](spinball_geometry::Stadium) in lanes: the flat crossing
/// first, then the cap on the side of the crossing.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LaneStadium {
    a: f64,
    /// `a + slack`, the reach of a flat wall (the scalar's tolerance).
    reach: f64,
    /// The caps' unit circle.
    cap: Round,
}

impl LaneStadium {
    pub fn new(a: f64) -> Self {
        // The scalar table's tolerance, recomputed from the public `a` with
        // the same expression (the agreement tests check the hits match).
        let slack = 64.0 * f64::EPSILON * (a + 1.0);
        LaneStadium {
            a,
            reach: a + slack,
            cap: Round::new(1.0),
        }
    }
}

/// What the stadium's search leaves for the landing: what the landing
/// needs of the choice between flat wall and cap, folded into as few masks
/// as it can be (a kernel holds this across another search).
#[derive(Clone, Copy, Debug)]
pub(crate) struct StadiumFound<L: Lanes> {
    ray: Ray<L>,
    root: Root<L>,
    /// The flight time, and the hit's (NaN where the scalar has none).
    time: L,
    hit_time: L,
    /// The flat wall (else the cap); the cap, where the cast finds it.
    flat: L::Mask,
    cap: L::Mask,
    /// `+1` for the top wall, `-1` for the bottom.
    side_y: L,
    /// The cap's centre.
    cx: L,
    wall: L,
}

impl Geom for LaneStadium {
    const CURVED: bool = true;
    type Footprint = LeanCast;
    type Found<L: Lanes> = StadiumFound<L>;

    #[inline(always)]
    fn search<L: Lanes>(&self, x: L, y: L, vx: L, vy: L) -> StadiumFound<L> {
        let cpu = x.proof();
        let zero = L::splat(cpu, 0.0);
        let one = L::splat(cpu, 1.0);
        let a = self.a;
        // Crossing of y = +1 (moving up) or y = -1 ahead, tested without
        // dividing: |x_cross| <= a  <=>  |x |v_y| + v_x dist| <= a |v_y|.
        let up = vy.gt(zero);
        let dist = L::select(up, L::splat(cpu, 1.0) - y, y + 1.0).max(zero);
        let avy = vy.abs();
        let x_scaled = x * avy + vx * dist;
        let moving_y = vy.ne(zero);
        let flat = moving_y.and(x_scaled.abs().le(avy * self.reach));
        // Otherwise the cap on the side of the crossing (of v_x if v_y = 0).
        let side = L::select(moving_y, x_scaled, vx);
        let right = side.gt(zero);
        let cx = L::select(right, L::splat(cpu, a), L::splat(cpu, -a));
        let ray = Ray::new_undivided(x, y, vx, vy);
        let root = concave_root::<L, true>(cx, zero, &self.cap, &ray);
        // One division: the flat wall's fraction or the cap's.
        let time = L::select(flat, dist, root.num.max(zero)) / L::select(flat, avy, ray.a);
        StadiumFound {
            ray,
            root,
            time,
            hit_time: L::select(flat.or(root.ok), time, L::splat(cpu, f64::NAN)),
            flat,
            cap: flat.not().and(root.ok),
            side_y: L::select(up, one, -one),
            cx,
            wall: L::select(
                flat,
                L::select(up, L::splat(cpu, 2.0), zero),
                L::select(right, one, L::splat(cpu, 3.0)),
            ),
        }
    }

    #[inline(always)]
    fn land<L: Lanes>(&self, f: StadiumFound<L>) -> LaneHit<L> {
        let cpu = f.time.proof();
        let zero = L::splat(cpu, 0.0);
        let flat = f.flat;
        let flat_x = (f.ray.x + f.ray.vx * f.time).clamp(-self.a, self.a);
        let (cap_px, cap_py, radx, rady) =
            contact_at::<L, true>(f.cx, zero, &f.root, &f.ray, f.time, &self.cap, f.cap);
        LaneHit {
            time: f.hit_time,
            px: L::select(flat, flat_x, cap_px),
            py: L::select(flat, f.side_y, cap_py),
            nx: L::select(flat, zero, -radx),
            // The inward normal of the wall at y = ±1 is ∓1 (negation is exact).
            ny: L::select(flat, -f.side_y, -rady),
            curvature: L::select(flat, zero, L::splat(cpu, -1.0)),
            wall: f.wall,
        }
    }
}

#[cfg(test)]
mod tests {
    use spinball_geometry::Stadium;

    use super::super::agree::{check, d};
    use super::*;

    #[test]
    fn stadium_casts_agree_including_junctions() {
        for a in [1.0, 0.2, 4.0] {
            let t = Stadium::new(a).unwrap();
            check(
                &t,
                &LaneStadium::new(t.a()),
                &[
                    (d(0.0, 0.0), d(a, 1.0)),
                    (d(0.0, 0.0), d(-a, -1.0)),
                    (d(0.0, 0.0), d(a, -1.0)),
                    (d(0.0, 1.0), d(1.0, 0.0)),
                    (d(0.0, 1.0 - 1e-12), d(1.0, 1e-13)),
                    (d(a + 1.0, 0.0), d(0.0, 1.0)),
                    (d(0.0, 0.0), d(1.0, 0.0)),
                    (d(0.0, 0.0), d(0.0, 0.0)),
                ],
            );
        }
    }
}
