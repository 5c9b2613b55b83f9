//! The rectangle in lanes, and the box cast the Sinai table reuses.
//!
//! Four flat walls whose next one is decided by comparing the two candidate
//! crossings (horizontal and vertical) by cross multiplication, so a cast
//! costs one division, as in the scalar `cast_box`.

use super::{Geom, LaneHit};
use crate::lanes::{Lanes, LeanCast, MaskOps};

/// `box_ahead` of `spinball-geometry` per lane: the wall ahead and its
/// flight time as the undivided fraction `dist / speed`.
#[derive(Clone, Copy, Debug)]
pub(super) struct BoxAhead<L: Lanes> {
    /// Whether the horizontal wall (bottom or top) comes first.
    use_y: L::Mask,
    up: L::Mask,
    right: L::Mask,
    /// The lanes where the scalar finds a wall (the ball moves).
    pub ok: L::Mask,
    pub dist: L,
    pub speed: L,
}

impl<L: Lanes> BoxAhead<L> {
    #[inline(always)]
    pub fn new(l: f64, h: f64, x: L, y: L, vx: L, vy: L) -> Self {
        let cpu = x.proof();
        let zero = L::splat(cpu, 0.0);
        let up = vy.gt(zero);
        let right = vx.gt(zero);
        let dy = L::select(up, L::splat(cpu, h) - y, y + h).max(zero);
        let dx = L::select(right, L::splat(cpu, l) - x, x + l).max(zero);
        let avy = vy.abs();
        let avx = vx.abs();
        let ty = dy * avx;
        let tx = dx * avy;
        // Tie: the lower id wins, which is the horizontal wall unless it is
        // the top (2) against the right (1).
        let y_wins_tie = up.and(right).not();
        let use_y = avy
            .gt(zero)
            .and(avx.eq(zero).or(ty.lt(tx)).or(ty.eq(tx).and(y_wins_tie)));
        BoxAhead {
            use_y,
            up,
            right,
            ok: use_y.or(avx.gt(zero)),
            dist: L::select(use_y, dy, dx),
            speed: L::select(use_y, avy, avx),
        }
    }

    /// `land_box`: the hit after flying for `time` (NaN where the scalar
    /// has none).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub fn land(&self, l: f64, h: f64, x: L, y: L, vx: L, vy: L, time: L) -> LaneHit<L> {
        let cpu = x.proof();
        let zero = L::splat(cpu, 0.0);
        let one = L::splat(cpu, 1.0);
        let (use_y, up, right) = (self.use_y, self.up, self.right);
        let ok = self.ok.and(time.is_finite());
        let time = time.max(zero);
        let px = (x + vx * time).clamp(-l, l);
        let py = (y + vy * time).clamp(-h, h);
        LaneHit {
            time: L::select(ok, time, L::splat(cpu, f64::NAN)),
            px: L::select(
                use_y,
                px,
                L::select(right, L::splat(cpu, l), L::splat(cpu, -l)),
            ),
            py: L::select(
                use_y,
                L::select(up, L::splat(cpu, h), L::splat(cpu, -h)),
                py,
            ),
            nx: L::select(use_y, zero, L::select(right, -one, one)),
            ny: L::select(use_y, L::select(up, -one, one), zero),
            curvature: zero,
            wall: L::select(
                use_y,
                L::select(up, L::splat(cpu, 2.0), zero),
                L::select(right, one, L::splat(cpu, 3.0)),
            ),
        }
    }
}

/// [`Rectangle`](spinball_geometry::Rectangle) in lanes.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LaneRectangle {
    l: f64,
    h: f64,
}

impl LaneRectangle {
    pub fn new(l: f64, h: f64) -> Self {
        LaneRectangle { l, h }
    }
}

/// What the rectangle's search leaves for the landing: the ball, the wall
/// ahead and the flight time.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BoxFound<L: Lanes> {
    ball: [L; 4],
    walls: BoxAhead<L>,
    time: L,
}

impl Geom for LaneRectangle {
    const CURVED: bool = false;
    type Footprint = LeanCast;
    type Found<L: Lanes> = BoxFound<L>;

    #[inline(always)]
    fn search<L: Lanes>(&self, x: L, y: L, vx: L, vy: L) -> BoxFound<L> {
        let walls = BoxAhead::new(self.l, self.h, x, y, vx, vy);
        BoxFound {
            ball: [x, y, vx, vy],
            walls,
            time: walls.dist / walls.speed,
        }
    }

    #[inline(always)]
    fn land<L: Lanes>(&self, f: BoxFound<L>) -> LaneHit<L> {
        let [x, y, vx, vy] = f.ball;
        f.walls.land(self.l, self.h, x, y, vx, vy, f.time)
    }
}

#[cfg(test)]
mod tests {
    use spinball_geometry::Rectangle;

    use super::super::agree::{check, d};
    use super::*;

    #[test]
    fn rectangle_casts_agree_including_corners() {
        for (l, h) in [(1.0, 1.0), (1.5, 1.0)] {
            let t = Rectangle::new(l, h).unwrap();
            check(
                &t,
                &LaneRectangle::new(t.l(), t.h()),
                &[
                    (d(0.0, 0.0), d(l, h)),
                    (d(0.0, 0.0), d(-l, -h)),
                    (d(0.0, 0.0), d(l, -h)),
                    (d(0.0, 0.0), d(-l, h)),
                    (d(0.0, h), d(1.0, 0.0)),
                    (d(l, h), d(-1.0, -1.0)),
                    (d(0.0, 0.0), d(0.0, 0.0)),
                ],
            );
        }
    }
}
