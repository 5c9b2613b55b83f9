//! The circle arithmetic every table with a round wall shares.
//!
//! The circle table, the stadium's caps, the Sinai disk and the arcs of a
//! table built from segments all meet a ball the way `spinball-geometry`'s
//! `cast_concave_circle` and `cast_convex_circle` do, and snap the contact
//! onto the circle with its private `contact`. Those three are written here
//! once, over [`Lanes`], operation for operation as the scalar functions,
//! so that every table's lane cast finds bitwise the scalar hit.

use crate::lanes::{Lanes, MaskOps, cmp};

/// A ball's position and velocity, with `|v|²` and `1/|v|²`, which do not
/// depend on the circle: a table with several round walls computes them
/// once per cast.
#[derive(Clone, Copy, Debug)]
pub(super) struct Ray<L: Lanes> {
    pub x: L,
    pub y: L,
    pub vx: L,
    pub vy: L,
    /// `|v|²`, as the scalar `velocity.length_squared()`.
    pub a: L,
    /// `1 / |v|²`.
    pub inv_a: L,
}

impl<L: Lanes> Ray<L> {
    #[inline(always)]
    pub fn new(x: L, y: L, vx: L, vy: L) -> Self {
        let cpu = x.proof();
        let a = vx * vx + vy * vy;
        Ray {
            x,
            y,
            vx,
            vy,
            a,
            inv_a: L::splat(cpu, 1.0) / a,
        }
    }

    /// `|v|²` without its reciprocal, for a cast that divides once by a
    /// chosen fraction's denominator instead.
    #[inline(always)]
    pub fn new_undivided(x: L, y: L, vx: L, vy: L) -> Self {
        let cpu = x.proof();
        Ray {
            x,
            y,
            vx,
            vy,
            a: vx * vx + vy * vy,
            inv_a: L::splat(cpu, 0.0),
        }
    }

    /// A ray for tables without round walls: `|v|²` and `1/|v|²` are left
    /// at 0, unused.
    #[inline(always)]
    pub fn flat(x: L, y: L, vx: L, vy: L) -> Self {
        let cpu = x.proof();
        let zero = L::splat(cpu, 0.0);
        Ray {
            x,
            y,
            vx,
            vy,
            a: zero,
            inv_a: zero,
        }
    }
}

/// Constants of a circle of radius `r` as the scalar casts use them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Round {
    pub r: f64,
    /// `r * r`.
    pub r2: f64,
    /// `1 / r`.
    pub inv_r: f64,
    /// `128 ε r²`: below this `c` a concave cast clamps `disc` at 0.
    pub touch: f64,
}

impl Round {
    pub fn new(r: f64) -> Self {
        Round {
            r,
            r2: r * r,
            inv_r: 1.0 / r,
            touch: 128.0 * f64::EPSILON * r * r,
        }
    }
}

/// `contact` of `spinball-geometry`: contact point and unit radial
/// direction for a root `r` (relative to the centre `(cx, cy)`) that lies on
/// the circle up to rounding, by one Newton step for `1/|r|`. In the lanes of
/// `care` where `r` is not that close to the circle (a ball found off the
/// wall: a flight time clamped at 0) the scalar normalises exactly instead;
/// that is computed only if such a lane exists.
///
/// The radius `r` and its reciprocal `inv_r` (the scalar's `1.0 / radius`)
/// come per lane: the arcs of a table built from segments differ by lane.
/// `UNIT`: the radius is 1, so the scalar's multiplications by `1/r²`, `1/r`
/// and `r` are multiplications by 1.0, exact, and left out.
#[inline(always)]
pub(super) fn contact<L: Lanes, const UNIT: bool>(
    cx: L,
    cy: L,
    rx: L,
    ry: L,
    r: L,
    inv_r: L,
    care: L::Mask,
) -> (L, L, L, L) {
    let cpu = rx.proof();
    let times = |x: L, f: L| if UNIT { x } else { x * f };
    let rr = if UNIT {
        rx * rx + ry * ry
    } else {
        (rx * rx + ry * ry) * (inv_r * inv_r)
    };
    let near = (rr - 1.0).abs().lt(L::splat(cpu, 1e-8));
    let s = times(L::splat(cpu, 1.5) - rr * 0.5, inv_r);
    let (mut nx, mut ny) = (rx * s, ry * s);
    if care.and(near.not()).any() {
        let inv = L::splat(cpu, 1.0) / (rx * rx + ry * ry).sqrt();
        nx = L::select(near, nx, rx * inv);
        ny = L::select(near, ny, ry * inv);
    }
    (cx + times(nx, r), cy + times(ny, r), nx, ny)
}

/// A circle root per lane as an undivided fraction: the flight time is
/// `num / a` (`a = |v|²` of the ray), before clamping; `dx, dy` is the
/// ball's offset from the centre. `ok`: the lanes where the scalar finds the
/// root.
#[derive(Clone, Copy, Debug)]
pub(super) struct Root<L: Lanes> {
    pub ok: L::Mask,
    pub num: L,
    pub dx: L,
    pub dy: L,
    /// `|d|² − r²`: how far off the circle the ball is.
    pub c: L,
    /// `c <= 128 ε r²` (a concave root computes it; a convex one leaves it
    /// unset, all false).
    pub inside: L::Mask,
}

/// `concave_root` of `spinball-geometry`: the larger root for a ball inside
/// the circle. `ON_AXIS`: the centre is on the x axis (skip `y − 0`).
#[inline(always)]
pub(super) fn concave_root<L: Lanes, const ON_AXIS: bool>(
    cx: L,
    cy: L,
    k: &Round,
    ray: &Ray<L>,
) -> Root<L> {
    let cpu = cx.proof();
    let zero = L::splat(cpu, 0.0);
    let (vx, vy) = (ray.vx, ray.vy);
    let dx = ray.x - cx;
    let dy = if ON_AXIS { ray.y } else { ray.y - cy };
    let a = ray.a;
    let b = dx * vx + dy * vy;
    let c = (dx * dx + dy * dy) - k.r2;
    let disc = b * b - a * c;
    // On the circle to rounding: touch at once rather than miss.
    let inside = c.le(L::splat(cpu, k.touch));
    let disc = L::select(inside, disc.max(zero), disc);
    let ok = disc.test::<{ cmp::GE }>(zero, a.gt(zero));
    Root {
        ok,
        num: disc.sqrt() - b,
        dx,
        dy,
        c,
        inside,
    }
}

/// `convex_root` of `spinball-geometry`: the smaller root for a ball
/// outside the circle moving towards it.
#[inline(always)]
pub(super) fn convex_root<L: Lanes>(cx: L, cy: L, k: &Round, ray: &Ray<L>) -> Root<L> {
    let cpu = cx.proof();
    let zero = L::splat(cpu, 0.0);
    let (vx, vy) = (ray.vx, ray.vy);
    let dx = ray.x - cx;
    let dy = ray.y - cy;
    let b = dx * vx + dy * vy;
    let a = ray.a;
    let c = (dx * dx + dy * dy) - k.r2;
    let disc = b * b - a * c;
    Root {
        ok: disc.test::<{ cmp::GT }>(zero, b.lt(zero)),
        num: -b - disc.sqrt(),
        dx,
        dy,
        c,
        inside: zero.ne(zero),
    }
}

/// The contact of a root after flying for `time`: `contact` at
/// `d + v·time`, as the scalar `cast_*_circle` and the one-division casts
/// of the stadium and the Sinai table compute it.
#[inline(always)]
pub(super) fn contact_at<L: Lanes, const UNIT: bool>(
    cx: L,
    cy: L,
    root: &Root<L>,
    ray: &Ray<L>,
    time: L,
    k: &Round,
    care: L::Mask,
) -> (L, L, L, L) {
    let cpu = time.proof();
    contact::<L, UNIT>(
        cx,
        cy,
        root.dx + ray.vx * time,
        root.dy + ray.vy * time,
        L::splat(cpu, k.r),
        L::splat(cpu, k.inv_r),
        care,
    )
}
