//! One collision step, its tangent map and the running sum of logarithms, in
//! lanes.
//!
//! [`step`] is `Billiard::step` of `spinball-core` (cast, half-turn collision,
//! energy-shell restore) written over [`Lanes`], operation for operation, so
//! the reference trajectory of every kernel is bitwise the scalar one;
//! [`TangentStep`] is `TangentFrame` likewise. The bookkeeping of the growth
//! ([`LogProduct`], [`pow2_renormalise`]) is where the lanes take a cheaper
//! road than the scalar code: no logarithm and no square root in the loop.
//! Its rounding does not feed back into the trajectory.

use spinball_core::{MAX_ZERO_TIME_RUN, SpinLaw};

use crate::geom::{Geom, LaneHit};
use crate::lanes::{BitsOps, Lanes, MaskOps};

/// The spin law's coefficients, as the kernels use them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Law {
    pub alpha: f64,
    /// `-(1 + β)`.
    pub neg_one_beta: f64,
    pub gamma: f64,
    pub delta: f64,
    /// α > 0: the spin takes part in the collision.
    pub coupled: bool,
}

impl Law {
    pub fn new(law: &SpinLaw) -> Self {
        Law {
            alpha: law.alpha(),
            neg_one_beta: -(1.0 + law.beta()),
            gamma: law.gamma(),
            delta: law.delta(),
            coupled: law.is_coupled(),
        }
    }

    /// All lanes set if α > 0. The spin updates are selected with it rather
    /// than branched on, which keeps a step one basic block for the
    /// compiler's scheduler (the mask is loop-invariant and hoisted).
    #[inline(always)]
    pub fn coupled<L: Lanes>(&self, cpu: L::Needs) -> L::Mask {
        let flag = if self.coupled { 1.0 } else { 0.0 };
        L::splat(cpu, flag).gt(L::splat(cpu, 0.0))
    }

    /// `|V|² = |v|² + α u²`, in `SpinLaw::norm2`'s order.
    #[inline(always)]
    pub fn norm2<L: Lanes>(&self, vx: L, vy: L, u: L) -> L {
        (vx * vx + vy * vy) + u * self.alpha * u
    }
}

/// `L::N` balls (lane by lane).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Balls<L: Lanes> {
    pub x: L,
    pub y: L,
    pub vx: L,
    pub vy: L,
    pub u: L,
}

/// Which energy shell a step pulls `V` back onto.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Shell<L> {
    /// `1/|V₀|²` of a ball launched earlier (`Ball::new` at launch).
    Fixed(L),
    /// The shell of the state the step starts from: a ball launched just
    /// before this step (the finite-difference shadow, re-launched every
    /// step). Computed inside the step, after the cast, so it does not
    /// occupy a register across it.
    Own,
}

impl<L: Lanes> Balls<L> {
    /// Balls in `z = (x, y, vx, vy, u)`.
    #[inline(always)]
    pub fn new(z: [L; 5]) -> Self {
        let [x, y, vx, vy, u] = z;
        Balls { x, y, vx, vy, u }
    }

    /// `1/|V|²` of the current state (what `Ball::new` stores).
    #[inline(always)]
    pub fn inv_shell(&self, law: &Law) -> L {
        L::splat(self.x.proof(), 1.0) / law.norm2(self.vx, self.vy, self.u)
    }

    /// The first half of the cast from the current state ([`Geom::search`]).
    #[inline(always)]
    pub fn search<G: Geom>(&self, g: &G) -> G::Found<L> {
        g.search(self.x, self.y, self.vx, self.vy)
    }

    /// The state as `(x, y, vx, vy, u)`.
    #[inline(always)]
    pub fn coords(&self) -> [L; 5] {
        [self.x, self.y, self.vx, self.vy, self.u]
    }
}

/// What a step leaves for the tangent map: the hit and the velocity and spin
/// just before the collision.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Stepped<L: Lanes> {
    pub hit: LaneHit<L>,
    pub vx: L,
    pub vy: L,
    pub u: L,
}

/// `Billiard::step`: fly to the next wall, collide (half-turn form), pull `V`
/// back onto the shell.
#[inline(always)]
pub(crate) fn step<G: Geom, L: Lanes>(
    g: &G,
    law: &Law,
    b: &mut Balls<L>,
    shell: Shell<L>,
) -> Stepped<L> {
    let hit = g.cast(b.x, b.y, b.vx, b.vy);
    collide(law, b, hit, shell)
}

/// The collision half of [`step`], at the hit `hit` already cast.
#[inline(always)]
pub(crate) fn collide<L: Lanes>(
    law: &Law,
    b: &mut Balls<L>,
    hit: LaneHit<L>,
    shell: Shell<L>,
) -> Stepped<L> {
    let (vx, vy, u) = (b.vx, b.vy, b.u);
    // SpinLaw::collide with t = (n_y, -n_x): k = (v·t − αu) δ.
    let tx = hit.ny;
    let ty = -hit.nx;
    let k = ((vx * tx + vy * ty) - u * law.alpha) * law.delta;
    let vx1 = tx * k - vx;
    let vy1 = ty * k - vy;
    let cpu = vx.proof();
    let coupled = law.coupled::<L>(cpu);
    let u1 = L::select(coupled, -u - k, u);
    // One Newton step back onto the shell.
    let inv_shell = match shell {
        Shell::Fixed(inv) => inv,
        Shell::Own => L::splat(cpu, 1.0) / law.norm2(vx, vy, u),
    };
    let c = L::splat(cpu, 1.5) - law.norm2(vx1, vy1, u1) * 0.5 * inv_shell;
    b.u = L::select(coupled, u1 * c, u1);
    b.vx = vx1 * c;
    b.vy = vy1 * c;
    b.x = hit.px;
    b.y = hit.py;
    Stepped { hit, vx, vy, u }
}

/// `TangentFrame` of `spinball-core`: what the tangent map of one collision
/// needs that does not depend on the tangent vector (one division per
/// collision), in the scalar's order of operations, so [`TangentStep::apply`]
/// is bitwise `TangentFrame::apply` (up to the sign of a zero on flat-only
/// tables, which skip the zero curvature term).
#[derive(Clone, Copy, Debug)]
pub(crate) struct TangentStep<L: Lanes> {
    time: L,
    nx: L,
    ny: L,
    vt: L,
    inv_vn: L,
    /// `v - v'`.
    jump_x: L,
    jump_y: L,
    /// `k (−(1+β)[(t·v) n + (n·v) t] + γ u n)`.
    curvature_dvx: L,
    curvature_dvy: L,
    /// `k δ (n·v)` (0 at α = 0).
    curvature_du: L,
}

impl<L: Lanes> TangentStep<L> {
    /// The frame of the step `s` that left the balls in `after`.
    #[inline(always)]
    pub fn new<G: Geom>(law: &Law, s: &Stepped<L>, after: &Balls<L>) -> Self {
        let h = &s.hit;
        let (nx, ny) = (h.nx, h.ny);
        let (tx, ty) = (ny, -nx);
        let vn = nx * s.vx + ny * s.vy;
        let vt = tx * s.vx + ty * s.vy;
        let k = h.curvature;
        let cpu = vn.proof();
        let (curvature_dvx, curvature_dvy, curvature_du) = if G::CURVED {
            let gu = s.u * law.gamma;
            (
                k * ((vt * nx + vn * tx) * law.neg_one_beta + gu * nx),
                k * ((vt * ny + vn * ty) * law.neg_one_beta + gu * ny),
                L::select(
                    law.coupled::<L>(cpu),
                    k * law.delta * vn,
                    L::splat(cpu, 0.0),
                ),
            )
        } else {
            let z = L::splat(cpu, 0.0);
            (z, z, z)
        };
        TangentStep {
            time: h.time,
            nx,
            ny,
            vt,
            inv_vn: L::splat(cpu, 1.0) / vn,
            jump_x: s.vx - after.vx,
            jump_y: s.vy - after.vy,
            curvature_dvx,
            curvature_dvy,
            curvature_du,
        }
    }

    /// Carry one tangent vector `z = (δx, δy, δv_x, δv_y, δu)` through the
    /// flight (`δx += τ δv`) and the collision (`TangentFrame::apply`).
    #[inline(always)]
    pub fn apply<G: Geom>(&self, law: &Law, z: &mut [L; 5]) {
        let [dx, dy, dvx, dvy, du] = *z;
        let (nx, ny) = (self.nx, self.ny);
        let (tx, ty) = (ny, -nx);
        // Free flight to the contact.
        let dx = dx + dvx * self.time;
        let dy = dy + dvy * self.time;
        // Shift of the hit time and of the hit point along the wall.
        let dtau = -(nx * dx + ny * dy) * self.inv_vn;
        let ds = (tx * dx + ty * dy) + self.vt * dtau;
        let dx = dx + self.jump_x * dtau;
        let dy = dy + self.jump_y * dtau;
        // The collision law on (δv, δu), then the curvature term.
        let kk = ((dvx * tx + dvy * ty) - du * law.alpha) * law.delta;
        let mut dvx_new = tx * kk - dvx;
        let mut dvy_new = ty * kk - dvy;
        let mut du_new = L::select(law.coupled::<L>(dx.proof()), -du - kk, du);
        if G::CURVED {
            dvx_new = dvx_new + ds * self.curvature_dvx;
            dvy_new = dvy_new + ds * self.curvature_dvy;
            du_new = du_new + ds * self.curvature_du;
        }
        *z = [dx, dy, dvx_new, dvy_new, du_new];
    }
}

/// A running product of positive factors that never overflows: the mantissa
/// `m ∈ [1, 2)` and the sum of the binary exponents split off it.
///
/// Splitting off a power of two is exact, so `m · 2^(e − 1023·pushes)` is
/// exactly the product the scalar `LogSum` would form without its `ln`
/// flushes; one `ln` at the end ([`LogProduct::ln`]) replaces the scalar's
/// `ln` every `1e±150`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LogProduct<L: Lanes> {
    m: L,
    /// Sum of biased exponents (wrapping; the bias is removed at the end).
    e: L::Bits,
    pushes: u64,
}

impl<L: Lanes> LogProduct<L> {
    #[inline(always)]
    pub fn new(cpu: L::Needs) -> Self {
        LogProduct {
            m: L::splat(cpu, 1.0),
            e: L::Bits::splat(cpu, 0),
            pushes: 0,
        }
    }

    /// A product that already stands at `m · 2^e` (`m ∈ [1, 2)` per lane,
    /// from [`parts`](Self::parts); `e` is added back outside the kernel).
    #[inline(always)]
    pub fn resume(m: L) -> Self {
        LogProduct {
            m,
            e: L::Bits::splat(m.proof(), 0),
            pushes: 0,
        }
    }

    /// Multiply by `f > 0` (finite, normal) in every lane.
    #[inline(always)]
    pub fn push(&mut self, f: L) {
        let p = self.m * f;
        self.e = self.e.add(p.exponent());
        self.m = p.mantissa();
        self.pushes += 1;
    }

    /// `ln` of the product in lane `i` (meaningless if a factor was not
    /// positive, finite and normal; the kernels detect that through the
    /// state, which then is not finite either).
    pub fn ln(&self, i: usize) -> f64 {
        let (e, m) = self.parts(i);
        e as f64 * std::f64::consts::LN_2 + m.ln()
    }

    /// The product in lane `i` as `(e, m)`: `m · 2^e`, `m ∈ [1, 2)`.
    pub fn parts(&self, i: usize) -> (i64, f64) {
        let e = self
            .e
            .lane(i)
            .wrapping_sub(1023u64.wrapping_mul(self.pushes)) as i64;
        (e, self.m.lane(i))
    }
}

/// Scale the vector `z` of each lane by a power of two so that its largest
/// component is in `[1, 2)`; returns the biased exponent taken off (`1023 + k`
/// for a scaling by `2^-k`). Exact: no rounding, so the growth the vector
/// has seen is `2^k` times what is left, with nothing lost.
#[inline(always)]
pub(crate) fn pow2_renormalise<L: Lanes>(z: &mut [L; 5]) -> L::Bits {
    let m = z[0]
        .abs()
        .max(z[1].abs())
        .max(z[2].abs())
        .max(z[3].abs())
        .max(z[4].abs());
    let e = m.exponent();
    // 2^(1023 - e): biased exponent 2046 - e.
    let scale = L::pow2(L::Bits::splat(m.proof(), 2046).sub(e));
    for c in z.iter_mut() {
        *c = *c * scale;
    }
    e
}

/// Runs of zero-time collisions, as `Billiard::step` counts them: a lane
/// whose run exceeds [`MAX_ZERO_TIME_RUN`] is stuck (a ball moving along a
/// wall into a tangent curved wall). Its outcome is made non-finite, and the
/// caller's rerun on the scalar path gives `StepError::Stuck`.
#[derive(Clone, Copy)]
pub(crate) struct ZeroRun<L: Lanes> {
    run: L,
    stuck: L::Mask,
}

impl<L: Lanes> ZeroRun<L> {
    #[inline(always)]
    pub fn new(cpu: L::Needs) -> Self {
        let zero = L::splat(cpu, 0.0);
        ZeroRun {
            run: zero,
            stuck: zero.ne(zero),
        }
    }

    /// A count that stands at `run` zero-time collisions in a row (lane by
    /// lane, none stuck: a stuck lane's run is not resumed).
    #[inline(always)]
    pub fn resume(run: L) -> Self {
        let zero = L::splat(run.proof(), 0.0);
        ZeroRun {
            run,
            stuck: zero.ne(zero),
        }
    }

    /// The current run of zero-time collisions in lane `i`.
    pub fn run(&self, i: usize) -> f64 {
        self.run.lane(i)
    }

    /// The current runs of zero-time collisions.
    #[inline(always)]
    pub fn runs(&self) -> L {
        self.run
    }

    /// Count a collision that took `time`.
    #[inline(always)]
    pub fn watch(&mut self, time: L) {
        let cpu = time.proof();
        let zero = L::splat(cpu, 0.0);
        self.run = L::select(time.eq(zero), self.run + 1.0, zero);
        self.stuck = self
            .stuck
            .or(self.run.gt(L::splat(cpu, f64::from(MAX_ZERO_TIME_RUN))));
    }

    /// Count a collision that took `time` in the lanes of `live` only (the
    /// others' runs are held).
    #[inline(always)]
    pub fn watch_where(&mut self, time: L, live: L::Mask) {
        let cpu = time.proof();
        let zero = L::splat(cpu, 0.0);
        let run = L::select(time.eq(zero), self.run + 1.0, zero);
        self.run = L::select(live, run, self.run);
        self.stuck = self
            .stuck
            .or(self.run.gt(L::splat(cpu, f64::from(MAX_ZERO_TIME_RUN))));
    }

    /// Lanes that never got stuck.
    #[inline(always)]
    pub fn moving(&self) -> L::Mask {
        self.stuck.not()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_product_is_exact_up_to_the_final_ln() {
        let mut p = LogProduct::<f64>::new(crate::isa::Baseline);
        let mut q = LogProduct::<f64>::new(crate::isa::Baseline);
        let (mut sp, mut sq) = (0.0f64, 0.0f64);
        for k in 0..2000 {
            let f = 1e-7 * (1.0 + 0.001 * k as f64);
            p.push(f);
            sp += f.ln();
            q.push(3.0e5);
            sq += 3.0e5f64.ln();
        }
        assert!(
            (p.ln(0) - sp).abs() < 1e-12 * sp.abs(),
            "{} vs {sp}",
            p.ln(0)
        );
        assert!(
            (q.ln(0) - sq).abs() < 1e-12 * sq.abs(),
            "{} vs {sq}",
            q.ln(0)
        );
    }

    #[test]
    fn pow2_renormalise_is_exact() {
        let v = [1.0e-30, -3.0e-31, 7.5e-31, 0.0, -2.0e-32];
        let mut z = v;
        let e = pow2_renormalise(&mut z);
        let k = e as i64 - 1023;
        assert_eq!(k, -100); // 2^-100 <= 1e-30 < 2^-99
        for (c, x) in z.iter().zip(v) {
            assert_eq!(*c, x * 2f64.powi(-k as i32));
        }
        let m = z.iter().map(|c| c.abs()).fold(0.0, f64::max);
        assert!((1.0..2.0).contains(&m));
    }
}
