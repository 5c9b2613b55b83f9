//! The circle table in lanes: one concave wall about the origin.
//!
//! The integrable reference case; its cast is the shared concave-circle
//! arithmetic of [`round`](super::round) with nothing to choose between.

use super::round::{Ray, Round, concave};
use super::{Geom, LaneHit};
use crate::lanes::Lanes;

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

impl Geom for LaneCircle {
    const CURVED: bool = true;
    #[inline(always)]
    fn cast<L: Lanes>(&self, x: L, y: L, vx: L, vy: L) -> LaneHit<L> {
        let zero = L::splat(0.0);
        let all = zero.eq(zero);
        let ray = Ray::new(x, y, vx, vy);
        let c = concave::<L, false, true>(zero, zero, &self.round, &ray, all);
        LaneHit {
            time: L::select(c.ok, c.time, L::splat(f64::NAN)),
            px: c.px,
            py: c.py,
            nx: c.nx,
            ny: c.ny,
            curvature: L::splat(self.k),
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
