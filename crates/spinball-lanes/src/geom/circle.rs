//! The circle table in lanes: one concave wall about the origin.
//!
//! The integrable reference case; its cast is the shared concave-circle
//! arithmetic of [`round`](super::round) with nothing to choose between.

use super::round::{Ray, Root, Round, concave_root, contact_at};
use super::{Geom, LaneHit};
use crate::lanes::{Lanes, LeanCast};

/// [`Circle`](spinball_geometry::Circle) in lanes.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LaneCircle {
    round: Round,
    k: f64,
}

impl LaneCircle {
    pub fn new(r: f64) -> Self {
        LaneCircle {
            round: Round::new(r),
            k: -1.0 / r,
        }
    }
}

/// What the circle's search leaves for the landing: the ray, the root and
/// the flight time.
#[derive(Clone, Copy, Debug)]
pub(crate) struct CircleFound<L: Lanes> {
    ray: Ray<L>,
    root: Root<L>,
    time: L,
}

impl Geom for LaneCircle {
    const CURVED: bool = true;
    type Footprint = LeanCast;
    type Found<L: Lanes> = CircleFound<L>;

    #[inline(always)]
    fn search<L: Lanes>(&self, x: L, y: L, vx: L, vy: L) -> CircleFound<L> {
        let cpu = x.proof();
        let zero = L::splat(cpu, 0.0);
        let ray = Ray::new(x, y, vx, vy);
        let root = concave_root::<L, true>(zero, zero, &self.round, &ray);
        CircleFound {
            ray,
            root,
            time: (root.num * ray.inv_a).max(zero),
        }
    }

    #[inline(always)]
    fn land<L: Lanes>(&self, f: CircleFound<L>) -> LaneHit<L> {
        let cpu = f.time.proof();
        let zero = L::splat(cpu, 0.0);
        let (px, py, radx, rady) =
            contact_at::<L, false>(zero, zero, &f.root, &f.ray, f.time, &self.round, f.root.ok);
        LaneHit {
            time: L::select(f.root.ok, f.time, L::splat(cpu, f64::NAN)),
            px,
            py,
            nx: -radx,
            ny: -rady,
            curvature: L::splat(cpu, self.k),
            wall: zero,
        }
    }
}

#[cfg(test)]
mod tests {
    use spinball_geometry::Circle;

    use super::super::agree::{check, d};
    use super::*;

    #[test]
    fn circle_casts_agree() {
        for r in [1.0, 0.7] {
            let t = Circle::new(r).unwrap();
            check(
                &t,
                &LaneCircle::new(t.radius()),
                &[
                    (d(0.0, 0.0), d(1.0, 0.0)),
                    (d(r, 0.0), d(0.0, 1.0)),
                    (d(r * 0.999_999_999, 0.0), d(0.0, 1.0)),
                    (d(0.0, 0.0), d(0.0, 0.0)),
                ],
            );
        }
    }
}
