//! The Sinai table in lanes: the square box and the convex disk.
//!
//! Both candidates are cast for every lane (the box by
//! [`cast_box`](super::rectangle::cast_box), the disk by the shared
//! convex-circle arithmetic) and the disk is kept only where it is strictly
//! earlier, the scalar's tie rule (a box wall has the lower id).

use super::rectangle::cast_box;
use super::round::{Ray, Round, convex};
use super::{Geom, LaneHit};
use crate::lanes::Lanes;

/// [`Sinai`](spinball_geometry::Sinai) in lanes: the box and the disk; the
/// disk only if strictly earlier (ties go to the lower wall id, a box wall).
#[derive(Clone, Copy, Debug)]
pub(crate) struct LaneSinai {
    l: f64,
    disk: Round,
    k: f64,
}

impl LaneSinai {
    pub fn new(l: f64, r: f64) -> Self {
        LaneSinai {
            l,
            disk: Round::new(r),
            k: 1.0 / r,
        }
    }
}

impl Geom for LaneSinai {
    const CURVED: bool = true;
    #[inline(always)]
    fn cast<L: Lanes>(&self, x: L, y: L, vx: L, vy: L) -> LaneHit<L> {
        let zero = L::splat(0.0);
        let all = zero.eq(zero);
        let wall = cast_box(self.l, self.l, x, y, vx, vy);
        let ray = Ray::new(x, y, vx, vy);
        let disk = convex::<L, false>(zero, zero, &self.disk, &ray, all);
        // Lanes that miss the disk: an infinite flight time, never earlier.
        let disk_time = L::select(disk.ok, disk.time, L::splat(f64::INFINITY));
        let d = disk_time.lt(wall.time);
        LaneHit {
            time: L::select(d, disk_time, wall.time),
            px: L::select(d, disk.px, wall.px),
            py: L::select(d, disk.py, wall.py),
            nx: L::select(d, disk.nx, wall.nx),
            ny: L::select(d, disk.ny, wall.ny),
            curvature: L::select(d, L::splat(self.k), wall.curvature),
            wall: L::select(d, L::splat(4.0), wall.wall),
        }
    }
}

#[cfg(test)]
mod tests {
    use spinball_geometry::Sinai;

    use super::super::agree::{check, d};
    use super::*;

    #[test]
    fn sinai_casts_agree_including_grazing_the_disk() {
        for (l, r) in [(2.0, 1.0), (1.0, 0.3)] {
            let t = Sinai::new(l, r).unwrap();
            check(
                &t,
                &LaneSinai::new(t.l(), t.r()),
                &[
                    (d(-l * 0.75, r), d(1.0, 0.0)),
                    (d(-l * 0.75, r * (1.0 - 1e-12)), d(1.0, 0.0)),
                    (d(-l * 0.75, r * (1.0 + 1e-12)), d(1.0, 0.0)),
                    (d(0.0, r), d(0.0, 1.0)),
                    (d(0.0, (l + r) / 2.0), d(0.0, -1.0)),
                    (d(l * 0.75, l * 0.75), d(1.0, 1.0)),
                    (d(-l * 0.75, l * 0.75), d(-1.0, 1.0)),
                    (d(0.0, 0.0), d(0.0, 0.0)),
                ],
            );
        }
    }
}
