//! The four built-in tables, cast in lanes.
//!
//! A kernel needs each table's answer to [`Boundary::cast`] for `N` balls at
//! once, without a branch per ball. Each table here computes every candidate
//! wall for every lane (the flat crossing *and* the cap, the box *and* the
//! disk) and keeps the right one with compare-and-select. The arithmetic is
//! the scalar cast's, operation for operation (same divisions, same square
//! roots, same clamps, same tie rules), so a lane finds bitwise the hit that
//! [`Boundary::cast`] finds. Where the scalar cast returns `None` (no wall
//! ahead), the lane's flight time becomes NaN, which then sticks to that
//! lane's state and is reported as an error at the end of the run.
//!
//! [`Boundary::cast`]: spinball_geometry::Boundary::cast

use crate::lanes::{Lanes, MaskOps};

/// The next wall hit of `N` balls.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LaneHit<L: Lanes> {
    /// Flight time (NaN where the scalar cast has no hit).
    pub time: L,
    /// Contact point.
    pub px: L,
    /// Contact point.
    pub py: L,
    /// Unit inward normal.
    pub nx: L,
    /// Unit inward normal.
    pub ny: L,
    /// Signed curvature (`-1/R` concave, `+1/R` convex, 0 flat).
    pub curvature: L,
    /// Wall id, as in the scalar table (as `f64`; for diagnostics and tests).
    pub wall: L,
}

/// A table the kernels can cast against in lanes.
pub(crate) trait Geom: Copy + Send + Sync {
    /// Whether the table has curved walls (the tangent map then needs its
    /// curvature term; flat-only tables skip it).
    const CURVED: bool;
    /// The next wall hit from `(x, y)` along `(vx, vy)`, lane by lane.
    fn cast<L: Lanes>(&self, x: L, y: L, vx: L, vy: L) -> LaneHit<L>;
}

/// A wall contact without curvature and id.
struct Contact<L: Lanes> {
    time: L,
    px: L,
    py: L,
    nx: L,
    ny: L,
}

/// `contact` of `spinball-geometry`: contact point and unit radial
/// direction for a root `r` (relative to the centre `(cx, cy)`) that lies on
/// the circle up to rounding, by one Newton step for `1/|r|`. In the lanes of
/// `care` where `r` is not that close to the circle (a ball found off the
/// wall, never in a sound run) the scalar normalises exactly instead; that
/// is computed only if such a lane exists.
///
/// `UNIT`: the radius is 1, so the scalar's multiplications by `1/r²`, `1/r`
/// and `r` are multiplications by 1.0, exact, and left out.
#[inline(always)]
fn contact<L: Lanes, const UNIT: bool>(
    cx: L,
    cy: L,
    rx: L,
    ry: L,
    k: &Round,
    care: L::Mask,
) -> (L, L, L, L) {
    let times = |x: L, f: f64| if UNIT { x } else { x * f };
    let rr = times(rx * rx + ry * ry, k.inv_r * k.inv_r);
    let near = (rr - 1.0).abs().lt(L::splat(1e-8));
    let s = times(L::splat(1.5) - rr * 0.5, k.inv_r);
    let (mut nx, mut ny) = (rx * s, ry * s);
    if care.and(near.not()).any() {
        let inv = L::splat(1.0) / (rx * rx + ry * ry).sqrt();
        nx = L::select(near, nx, rx * inv);
        ny = L::select(near, ny, ry * inv);
    }
    (cx + times(nx, k.r), cy + times(ny, k.r), nx, ny)
}

/// Constants of a circle of radius `r` as the scalar casts use them.
#[derive(Clone, Copy, Debug)]
struct Round {
    r: f64,
    /// `r * r`.
    r2: f64,
    /// `1 / r`.
    inv_r: f64,
    /// `128 ε r²`: below this `c` a concave cast clamps `disc` at 0.
    touch: f64,
}

impl Round {
    fn new(r: f64) -> Self {
        Round {
            r,
            r2: r * r,
            inv_r: 1.0 / r,
            touch: 128.0 * f64::EPSILON * r * r,
        }
    }
}

/// `cast_concave_circle` of `spinball-geometry`, lane by lane (centre per
/// lane). `care`: the lanes whose result is used. `UNIT`: radius 1 (see
/// [`contact`]); `ON_AXIS`: `cy = 0`, so `y − cy = y` exactly.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn concave<L: Lanes, const UNIT: bool, const ON_AXIS: bool>(
    cx: L,
    cy: L,
    k: &Round,
    x: L,
    y: L,
    vx: L,
    vy: L,
    care: L::Mask,
) -> Contact<L> {
    let zero = L::splat(0.0);
    let dx = x - cx;
    let dy = if ON_AXIS { y } else { y - cy };
    let a = vx * vx + vy * vy;
    let b = dx * vx + dy * vy;
    let c = (dx * dx + dy * dy) - k.r2;
    let disc = b * b - a * c;
    // On the circle to rounding: touch at once rather than miss.
    let disc = L::select(c.le(L::splat(k.touch)), disc.max(zero), disc);
    let ok = disc.ge(zero).and(a.gt(zero));
    let inv_a = L::splat(1.0) / a;
    let time = ((disc.sqrt() - b) * inv_a).max(zero);
    let (px, py, radx, rady) =
        contact::<L, UNIT>(cx, cy, dx + vx * time, dy + vy * time, k, care.and(ok));
    Contact {
        time: L::select(ok, time, L::splat(f64::NAN)),
        px,
        py,
        nx: -radx,
        ny: -rady,
    }
}

/// `cast_convex_circle` about the origin, lane by lane. Lanes that miss the
/// disk get an infinite flight time.
#[inline(always)]
fn convex<L: Lanes>(k: &Round, x: L, y: L, vx: L, vy: L) -> Contact<L> {
    let zero = L::splat(0.0);
    let dx = x - 0.0;
    let dy = y - 0.0;
    let b = dx * vx + dy * vy;
    let a = vx * vx + vy * vy;
    let c = (dx * dx + dy * dy) - k.r2;
    let disc = b * b - a * c;
    let ok = b.lt(zero).and(disc.gt(zero));
    let inv_a = L::splat(1.0) / a;
    let time = ((-b - disc.sqrt()) * inv_a).max(zero);
    let (px, py, radx, rady) =
        contact::<L, false>(zero, zero, dx + vx * time, dy + vy * time, k, ok);
    Contact {
        time: L::select(ok, time, L::splat(f64::INFINITY)),
        px,
        py,
        nx: radx,
        ny: rady,
    }
}

/// `cast_box` of `spinball-geometry` (walls 0 bottom, 1 right, 2 top,
/// 3 left; ties to the lower id): the two candidate times compared by cross
/// multiplication, one division.
#[inline(always)]
fn cast_box<L: Lanes>(l: f64, h: f64, x: L, y: L, vx: L, vy: L) -> LaneHit<L> {
    let zero = L::splat(0.0);
    let one = L::splat(1.0);
    let up = vy.gt(zero);
    let right = vx.gt(zero);
    let dy = L::select(up, L::splat(h) - y, y + h).max(zero);
    let dx = L::select(right, L::splat(l) - x, x + l).max(zero);
    let avy = vy.abs();
    let avx = vx.abs();
    let ty = dy * avx;
    let tx = dx * avy;
    // Tie: the lower id wins, which is the horizontal wall unless it is the
    // top (2) against the right (1).
    let y_wins_tie = up.and(right).not();
    let use_y = avy
        .gt(zero)
        .and(avx.eq(zero).or(ty.lt(tx)).or(ty.eq(tx).and(y_wins_tie)));
    let time = L::select(use_y, dy, dx) / L::select(use_y, avy, avx);
    let ok = use_y.or(avx.gt(zero)).and(time.is_finite());
    let time = time.max(zero);
    let px = (x + vx * time).clamp(-l, l);
    let py = (y + vy * time).clamp(-h, h);
    LaneHit {
        time: L::select(ok, time, L::splat(f64::NAN)),
        px: L::select(use_y, px, L::select(right, L::splat(l), L::splat(-l))),
        py: L::select(use_y, L::select(up, L::splat(h), L::splat(-h)), py),
        nx: L::select(use_y, zero, L::select(right, -one, one)),
        ny: L::select(use_y, L::select(up, -one, one), zero),
        curvature: zero,
        wall: L::select(
            use_y,
            L::select(up, L::splat(2.0), zero),
            L::select(right, one, L::splat(3.0)),
        ),
    }
}

/// [`Circle`] in lanes.
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
        let c = concave::<L, false, true>(zero, zero, &self.round, x, y, vx, vy, all);
        LaneHit {
            time: c.time,
            px: c.px,
            py: c.py,
            nx: c.nx,
            ny: c.ny,
            curvature: L::splat(self.k),
            wall: zero,
        }
    }
}

/// [`Rectangle`] in lanes.
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

impl Geom for LaneRectangle {
    const CURVED: bool = false;
    #[inline(always)]
    fn cast<L: Lanes>(&self, x: L, y: L, vx: L, vy: L) -> LaneHit<L> {
        cast_box(self.l, self.h, x, y, vx, vy)
    }
}

/// [`Stadium`] in lanes: the flat crossing first, then the cap on the side
/// of the crossing.
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

impl Geom for LaneStadium {
    const CURVED: bool = true;
    #[inline(always)]
    fn cast<L: Lanes>(&self, x: L, y: L, vx: L, vy: L) -> LaneHit<L> {
        let zero = L::splat(0.0);
        let one = L::splat(1.0);
        let a = self.a;
        // Crossing of y = +1 (moving up) or y = -1 ahead, tested without
        // dividing: |x_cross| <= a  <=>  |x |v_y| + v_x dist| <= a |v_y|.
        let up = vy.gt(zero);
        let dist = L::select(up, L::splat(1.0) - y, y + 1.0).max(zero);
        let avy = vy.abs();
        let x_scaled = x * avy + vx * dist;
        let moving_y = vy.ne(zero);
        let flat = moving_y.and(x_scaled.abs().le(avy * self.reach));
        let flat_time = dist / avy;
        let flat_x = (x + vx * flat_time).clamp(-a, a);
        // Otherwise the cap on the side of the crossing (of v_x if v_y = 0).
        let side = L::select(moving_y, x_scaled, vx);
        let right = side.gt(zero);
        let cx = L::select(right, L::splat(a), L::splat(-a));
        let cap = concave::<L, true, true>(cx, zero, &self.cap, x, y, vx, vy, flat.not());
        LaneHit {
            time: L::select(flat, flat_time, cap.time),
            px: L::select(flat, flat_x, cap.px),
            py: L::select(flat, L::select(up, one, -one), cap.py),
            nx: L::select(flat, zero, cap.nx),
            ny: L::select(flat, L::select(up, -one, one), cap.ny),
            curvature: L::select(flat, zero, -one),
            wall: L::select(
                flat,
                L::select(up, L::splat(2.0), zero),
                L::select(right, one, L::splat(3.0)),
            ),
        }
    }
}

/// [`Sinai`] in lanes: the box and the disk; the disk only if strictly
/// earlier (ties go to the lower wall id, a box wall).
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
        let wall = cast_box(self.l, self.l, x, y, vx, vy);
        let disk = convex(&self.disk, x, y, vx, vy);
        let d = disk.time.lt(wall.time);
        LaneHit {
            time: L::select(d, disk.time, wall.time),
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
    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64;
    use spinball_geometry::{Boundary, Circle, DVec2, Hit, Rectangle, Sinai, Stadium};

    use super::*;

    /// The lane cast (one `f64` lane) against the scalar cast: same wall,
    /// bitwise the same time, point and normal (`==`, so up to the sign of
    /// a zero); NaN time exactly where the scalar has no hit.
    fn agree<T: Boundary, G: Geom>(table: &T, g: &G, o: DVec2, v: DVec2) {
        let h = g.cast::<f64>(o.x, o.y, v.x, v.y);
        match table.cast(o, v) {
            Some(Hit {
                time,
                point,
                normal,
                curvature,
                wall,
                ..
            }) => {
                let what = format!("from {o:?} along {v:?}");
                assert_eq!(h.wall, f64::from(wall), "wall {what}");
                assert_eq!(h.time, time, "time {what}");
                assert_eq!((h.px, h.py), (point.x, point.y), "point {what}");
                assert_eq!((h.nx, h.ny), (normal.x, normal.y), "normal {what}");
                assert_eq!(h.curvature, curvature, "curvature {what}");
            }
            None => assert!(h.time.is_nan(), "no scalar hit from {o:?} along {v:?}"),
        }
    }

    /// Random rays from inside and from the walls, plus the given special ones.
    fn check<T: Boundary, G: Geom>(table: &T, g: &G, special: &[(DVec2, DVec2)]) {
        for &(o, v) in special {
            agree(table, g, o, v);
        }
        let mut rng = Pcg64::seed_from_u64(11);
        for _ in 0..20_000 {
            let o = table.sample_interior(&mut rng, 1.0);
            let v = DVec2::from_angle(rng.random::<f64>() * std::f64::consts::TAU)
                * (0.1 + rng.random::<f64>());
            agree(table, g, o, v);
            // From the wall just hit, in a random inward direction.
            if let Some(hit) = table.cast(o, v) {
                let w = DVec2::from_angle(rng.random::<f64>() * std::f64::consts::PI)
                    .rotate(hit.tangent());
                agree(table, g, hit.point, w);
                // Grazing: almost along the wall.
                let eps = 10f64.powi(-rng.random_range(3..16));
                agree(table, g, hit.point, hit.tangent() + hit.normal * eps);
                agree(table, g, hit.point, -hit.tangent() + hit.normal * eps);
            }
        }
    }

    fn d(x: f64, y: f64) -> DVec2 {
        DVec2::new(x, y)
    }

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
