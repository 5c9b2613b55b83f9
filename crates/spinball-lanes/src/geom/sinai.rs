//! The Sinai table in lanes: the square box and the convex disk.
//!
//! Both candidates are cast for every lane as undivided fractions (the box
//! wall ahead by [`BoxAhead`], the disk by the shared convex-circle root),
//! compared cross-multiplied, the disk kept only where it is strictly
//! earlier (the scalar's tie rule: a box wall has the lower id), and the
//! winner's fraction divided once, as in the scalar cast.

use super::rectangle::BoxAhead;
use super::round::{Ray, Root, Round, contact_at, convex_root};
use super::{Geom, LaneHit};
use crate::lanes::{Lanes, LeanCast, MaskOps};

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

/// What the Sinai table's search leaves for the landing.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SinaiFound<L: Lanes> {
    ray: Ray<L>,
    walls: BoxAhead<L>,
    root: Root<L>,
    disk_wins: L::Mask,
    time: L,
}

impl Geom for LaneSinai {
    const CURVED: bool = true;
    type Footprint = LeanCast;
    type Found<L: Lanes> = SinaiFound<L>;

    #[inline(always)]
    fn search<L: Lanes>(&self, x: L, y: L, vx: L, vy: L) -> SinaiFound<L> {
        let cpu = x.proof();
        let zero = L::splat(cpu, 0.0);
        let walls = BoxAhead::new(self.l, self.l, x, y, vx, vy);
        let ray = Ray::new_undivided(x, y, vx, vy);
        let root = convex_root(zero, zero, &self.disk, &ray);
        let num = root.num.max(zero);
        // The disk if strictly earlier (`num·speed < dist·|v|²`) or if the
        // ball meets no box wall; ties go to the box (lower ids).
        let disk_wins = root.ok.and(
            walls
                .ok
                .not()
                .or((num * walls.speed).lt(walls.dist * ray.a)),
        );
        // One division, of the winner's fraction.
        let time = L::select(disk_wins, num, walls.dist) / L::select(disk_wins, ray.a, walls.speed);
        SinaiFound {
            ray,
            walls,
            root,
            disk_wins,
            time,
        }
    }

    #[inline(always)]
    fn land<L: Lanes>(&self, f: SinaiFound<L>) -> LaneHit<L> {
        let cpu = f.time.proof();
        let zero = L::splat(cpu, 0.0);
        let (r, time, disk_wins) = (&f.ray, f.time, f.disk_wins);
        let wall = f.walls.land(self.l, self.l, r.x, r.y, r.vx, r.vy, time);
        let (px, py, nx, ny) =
            contact_at::<L, false>(zero, zero, &f.root, r, time, &self.disk, disk_wins);
        LaneHit {
            time: L::select(disk_wins, time, wall.time),
            px: L::select(disk_wins, px, wall.px),
            py: L::select(disk_wins, py, wall.py),
            nx: L::select(disk_wins, nx, wall.nx),
            ny: L::select(disk_wins, ny, wall.ny),
            curvature: L::select(disk_wins, L::splat(cpu, self.k), wall.curvature),
            wall: L::select(disk_wins, L::splat(cpu, 4.0), wall.wall),
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
