//! The kernels: plain trajectory, finite-difference Benettin, exact
//! tangent, exact spectrum, and escape from a table with holes (in
//! [`escape`]). Each runs `N` initial conditions in lockstep.
//!
//! A kernel loads `L::N` initial conditions into structure-of-arrays [`Lanes`],
//! runs all collisions with the state in registers, and writes `N` outcomes.
//! [`run_chunks`] feeds it a slice of any length: the last, partial chunk is
//! padded with copies of its last initial condition whose results are
//! dropped. Lanes never interact, so an outcome depends only on its own
//! initial condition — not on the lane count, the chunking, the thread count
//! or the instruction set.
//!
//! This module knows nothing of instruction sets beyond the lane types each
//! kernel prefers per level and per table footprint ([`Kernel::Groups`],
//! [`Kernel::BulkyGroups`], [`Kernel::ArcGroups`]); choosing the level and entering the code
//! compiled for it is the `dispatch` module's job, one layer up.

use spinball_core::{State, TangentVector, Units};

use crate::dynamics::{
    Balls, Law, LogProduct, Shell, TangentStep, ZeroRun, collide, pow2_renormalise, step,
};
use crate::geom::Geom;
use crate::isa::ProvenBy;
use crate::lanes::{BitsOps, Groups, Lanes, MAX_LANES, MaskOps, PerIsa};
use crate::outcome::{Flight, SpectrumStretch};
use crate::paused::Paused;

/// A computation over `N` trajectories at once.
pub(crate) trait Kernel: Sync {
    /// Per-initial-condition input.
    type In: Copy + Send + Sync;
    /// Per-initial-condition output.
    type Out: Copy + Send;
    /// The lane type at each instruction-set level on a table with a
    /// [`LeanCast`](crate::lanes::LeanCast) (the results do not depend on
    /// it; it only sets how many trajectories share the registers).
    type Groups: PerIsa;
    /// The same on a table with a [`BulkyCast`](crate::lanes::BulkyCast),
    /// whose cast leaves fewer registers free (docs/PERFORMANCE.md,
    /// "Register groups per table").
    type BulkyGroups: PerIsa;
    /// The same on a table with an [`ArcCast`](crate::lanes::ArcCast).
    type ArcGroups: PerIsa;
    /// Independent streams of `L::N` trajectories a chunk steps in turn
    /// (each stream's landing then covers the other's division: see
    /// docs/PERFORMANCE.md, "Latency, not operations").
    const STREAMS: usize = 1;
    /// Whether [`run_chunks`] hands the kernel the whole slice at once (a
    /// kernel that refills its lanes as trajectories end) instead of
    /// chunks of `STREAMS · L::N`.
    const WHOLE: bool = false;
    /// Run `STREAMS · L::N` initial conditions (`ins.len()`; any number
    /// if [`WHOLE`](Self::WHOLE)), pushing their outcomes onto `out` in
    /// input order; `cpu` proves this CPU runs `L`.
    fn chunk<G: Geom, L: Lanes>(
        &self,
        cpu: L::Needs,
        g: &G,
        law: &Law,
        ins: &[Self::In],
        out: &mut Vec<Self::Out>,
    );
    /// Whether an output is sound (finite throughout).
    fn is_sound(out: &Self::Out) -> bool;
}

/// Run `k` over `ins` in chunks of `K::STREAMS · L::N` lanes, results in
/// input order.
///
/// The only way the crate runs a kernel. `cpu` proves that this CPU has the
/// features `L`'s instructions need (`L::Needs: ProvenBy<C>`, checked by the
/// compiler), and becomes the proof the kernel builds its lanes with.
#[inline(always)]
pub(crate) fn run_chunks<G: Geom, K: Kernel, L: Lanes<Needs: ProvenBy<C>>, C>(
    cpu: C,
    g: &G,
    law: &Law,
    k: &K,
    ins: &[K::In],
) -> Vec<K::Out> {
    const { assert!(L::N <= MAX_LANES) };
    let cpu = L::Needs::from_proof(cpu);
    let n = L::N * K::STREAMS;
    let mut out = Vec::with_capacity(ins.len() + n);
    if K::WHOLE {
        k.chunk::<G, L>(cpu, g, law, ins, &mut out);
        return out;
    }
    for c in ins.chunks(n) {
        if c.len() == n {
            k.chunk::<G, L>(cpu, g, law, c, &mut out);
        } else {
            let last = c[c.len() - 1];
            let padded: Vec<K::In> = (0..n).map(|j| c.get(j).copied().unwrap_or(last)).collect();
            k.chunk::<G, L>(cpu, g, law, &padded, &mut out);
            out.truncate(out.len() - (n - c.len()));
        }
    }
    out
}

/// `[f(0), …, f(4)]`, spelt out (see `lanes::each!` on `std::array::from_fn`).
#[inline(always)]
fn five<T>(f: impl Fn(usize) -> T) -> [T; 5] {
    [f(0), f(1), f(2), f(3), f(4)]
}

/// `(x, y, vx, vy, u)` of `L::N` states.
#[inline(always)]
fn load_states<L: Lanes>(cpu: L::Needs, s: impl Fn(usize) -> State) -> [L; 5] {
    let mut z = [[0.0; MAX_LANES]; 5];
    for i in 0..L::N {
        for (zc, x) in z.iter_mut().zip(s(i).to_array()) {
            zc[i] = x;
        }
    }
    five(|c| L::load(cpu, &z[c]))
}

/// One number per lane.
#[inline(always)]
fn load_lane<L: Lanes>(cpu: L::Needs, x: impl Fn(usize) -> f64) -> L {
    let mut z = [0.0; MAX_LANES];
    for (i, zi) in z.iter_mut().enumerate().take(L::N) {
        *zi = x(i);
    }
    L::load(cpu, &z)
}

/// The five components of `L::N` tangent vectors.
#[inline(always)]
fn load_vectors<L: Lanes>(cpu: L::Needs, v: impl Fn(usize) -> TangentVector) -> [L; 5] {
    load_states(cpu, |i| State::from_array(v(i).to_array()))
}

/// Lane `i` of a state.
fn state_of<L: Lanes>(z: &[L; 5], i: usize) -> State {
    State::from_array(z.map(|c| c.lane(i)))
}

/// Lanes where all of `z` is finite.
#[inline(always)]
fn all_finite<L: Lanes>(z: &[L; 5]) -> L::Mask {
    let zero = L::splat(z[0].proof(), 0.0);
    z.iter().fold(zero.eq(zero), |m, c| m.and(c.is_finite()))
}

/// Whether lane `i` of a mask is set (outside hot loops).
fn mask_lane<L: Lanes>(cpu: L::Needs, m: L::Mask, i: usize) -> bool {
    L::select(m, L::splat(cpu, 1.0), L::splat(cpu, 0.0)).lane(i) == 1.0
}

/// `TangentVector::dot`, in its order.
#[inline(always)]
fn dot<L: Lanes>(a: &[L; 5], b: &[L; 5]) -> L {
    ((a[0] * b[0] + a[1] * b[1]) + (a[2] * b[2] + a[3] * b[3])) + a[4] * b[4]
}

/// The plain collision map (`Billiard::step`, repeated).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Plain {
    pub collisions: u64,
}

impl Kernel for Plain {
    type In = State;
    type Out = Flight;
    /// Registers per group and stream: AVX-512 3, AVX2 2, SSE2 2, portable
    /// `f64` 2, in two streams.
    type Groups = Groups<3, 2, 2, 2>;
    /// As on the built-in tables.
    type BulkyGroups = <Self as Kernel>::Groups;
    /// As on the built-in tables.
    type ArcGroups = <Self as Kernel>::Groups;
    const STREAMS: usize = 2;

    #[inline(always)]
    fn chunk<G: Geom, L: Lanes>(
        &self,
        cpu: L::Needs,
        g: &G,
        law: &Law,
        ins: &[State],
        out: &mut Vec<Flight>,
    ) {
        let mut a = PlainStream::<L>::new(cpu, law, |i| ins[i]);
        let mut b = PlainStream::<L>::new(cpu, law, |i| ins[L::N + i]);
        // Stream `b` runs half a step behind `a`: each stream's search is
        // followed in program order by the other's landing and collision,
        // which cover its division. The last search of `b` is not landed.
        let mut found_b = b.balls.search(g);
        for _ in 0..self.collisions {
            let found_a = a.balls.search(g);
            b.land(g, law, found_b);
            found_b = b.balls.search(g);
            a.land(g, law, found_a);
        }
        out.extend(a.flights(self.collisions));
        out.extend(b.flights(self.collisions));
    }

    fn is_sound(o: &Flight) -> bool {
        o.time.is_finite() && o.end.to_array().iter().all(|x| x.is_finite())
    }
}

/// One stream of the plain kernel: `L::N` balls, their energy shell, their
/// summed flight time and their runs of zero-time collisions.
#[derive(Clone, Copy)]
struct PlainStream<L: Lanes> {
    balls: Balls<L>,
    shell: Shell<L>,
    time: L,
    zero_run: ZeroRun<L>,
}

impl<L: Lanes> PlainStream<L> {
    #[inline(always)]
    fn new(cpu: L::Needs, law: &Law, s: impl Fn(usize) -> State) -> Self {
        let balls = Balls::new(load_states(cpu, s));
        PlainStream {
            shell: Shell::Fixed(balls.inv_shell(law)),
            balls,
            time: L::splat(cpu, 0.0),
            zero_run: ZeroRun::new(cpu),
        }
    }

    /// The second half of the step: land where `found` says, collide, and
    /// count the flight.
    #[inline(always)]
    fn land<G: Geom>(&mut self, g: &G, law: &Law, found: G::Found<L>) {
        let t = collide(law, &mut self.balls, g.land(found), self.shell)
            .hit
            .time;
        self.zero_run.watch(t);
        self.time = self.time + t;
    }

    /// The outcomes, lane by lane. A stuck lane reports a NaN time (rerun it
    /// on the scalar path).
    fn flights(&self, collisions: u64) -> impl Iterator<Item = Flight> {
        let time = L::select(
            self.zero_run.moving(),
            self.time,
            L::splat(self.time.proof(), f64::NAN),
        );
        let z = self.balls.coords();
        (0..L::N).map(move |i| Flight {
            end: state_of(&z, i),
            time: time.lane(i),
            collisions,
        })
    }
}

/// The paper's finite-difference Benettin method (`largest_lyapunov` with
/// `Method::FiniteDifference`): reference and shadow each take their own
/// collision (bitwise the scalar steps), the 5-D separation is measured and
/// the shadow put back `δ0` from the reference along it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct FiniteDifference {
    pub collisions: u64,
    pub delta0: f64,
    /// `1 / unit` of each coordinate (powers of two).
    pub inv_units: [f64; 5],
}

impl Kernel for FiniteDifference {
    type In = Paused;
    type Out = Paused;
    /// Registers per group: AVX-512 3, AVX2 4, SSE2 4, portable `f64` 4.
    type Groups = Groups<3, 4, 4, 4>;
    /// Two AVX2 and two SSE2 registers per group instead of four.
    type BulkyGroups = Groups<3, 2, 2, 4>;
    /// As without arcs.
    type ArcGroups = <Self as Kernel>::BulkyGroups;

    #[inline(always)]
    fn chunk<G: Geom, L: Lanes>(
        &self,
        cpu: L::Needs,
        g: &G,
        law: &Law,
        ins: &[Paused],
        out: &mut Vec<Paused>,
    ) {
        let delta0 = self.delta0;
        let inv_delta0 = 1.0 / delta0;
        let mut r = Balls::new(load_states::<L>(cpu, |i| ins[i].reference));
        // The shell of the launch state, as `Ball::new` stored it.
        let shell =
            Shell::Fixed(Balls::new(load_states::<L>(cpu, |i| ins[i].launch)).inv_shell(law));
        let inv_units = self.inv_units;
        let mut s = Balls::new(load_vectors::<L>(cpu, |i| ins[i].partner_vector()));
        let mut logs = LogProduct::resume(load_lane(cpu, |i| ins[i].log_mantissa));
        let mut time = load_lane::<L>(cpu, |i| ins[i].time);
        let mut zero_run = ZeroRun::resume(load_lane::<L>(cpu, |i| ins[i].zero_run));
        for _ in 0..self.collisions {
            // Both searches before either landing: the shadow's search (the
            // bulk of the work, independent of the reference) then fills the
            // wait on the reference's division in program order.
            let found_r = r.search(g);
            let found_s = s.search(g);
            // The two usually meet the same wall, whose constants a table
            // may then fetch once.
            let (hit_r, hit_s) = g.land_both(found_r, found_s);
            let t = collide(law, &mut r, hit_r, shell).hit.time;
            zero_run.watch(t);
            time = time + t;
            collide(law, &mut s, hit_s, Shell::Own);
            let zr = r.coords();
            let zs = s.coords();
            let d: [L; 5] = five(|c| zs[c] - zr[c]);
            // The separation in units (the scalar's `Perturbation::distance`).
            let w: [L; 5] = five(|c| d[c] * inv_units[c]);
            let dist = dot(&w, &w).sqrt();
            // Σ ln(δ/δ0), one `ln` at the end; the scalar divides by δ0.
            logs.push(dist * inv_delta0);
            let k = L::splat(cpu, delta0) / dist;
            s = Balls::new(five(|c| zr[c] + d[c] * k));
        }
        let zs = s.coords();
        let ok = all_finite(&zs).and(time.is_finite()).and(zero_run.moving());
        let z = r.coords();
        out.extend((0..L::N).map(|i| {
            let (e, m) = logs.parts(i);
            let log_exponent = ins[i].log_exponent.wrapping_add(e);
            Paused {
                reference: state_of(&z, i),
                partner: state_of(&zs, i).to_array(),
                log_mantissa: m,
                log_exponent,
                log_stretch: if mask_lane::<L>(cpu, ok, i) {
                    log_exponent as f64 * std::f64::consts::LN_2 + m.ln()
                } else {
                    f64::NAN
                },
                time: time.lane(i),
                zero_run: zero_run.run(i),
                collisions: ins[i].collisions + self.collisions,
                ..ins[i]
            }
        }));
    }

    fn is_sound(o: &Paused) -> bool {
        o.is_sound()
    }
}

/// Steps between exact power-of-two renormalisations of a tangent vector.
/// A vector grows by `e^λτ` per step, by more at near-grazing hits on curved
/// walls; eight steps stay far inside the `f64` range.
const RENORM_EVERY: u64 = 8;

/// Exact tangent dynamics for the largest exponent (`largest_lyapunov` with
/// `Method::Tangent`): one tangent vector, renormalised rarely and by powers
/// of two; `Σ ln` is `ln |δ_final|` plus the powers taken off, less
/// `ln |δ_0|`, both lengths in units (`spinball_core::Units`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Tangent {
    pub collisions: u64,
    /// The units the start and end vectors are measured in.
    pub units: Units,
}

impl Kernel for Tangent {
    type In = Paused;
    type Out = Paused;
    /// Registers per group: AVX-512 3, AVX2 4, SSE2 4, portable `f64` 4.
    type Groups = Groups<3, 4, 4, 4>;
    /// Two AVX2 and two SSE2 registers per group instead of four.
    type BulkyGroups = Groups<3, 2, 2, 4>;
    /// Two AVX-512 registers per group instead of three: with the arcs'
    /// values live in its loop the third register group costs more than it
    /// overlaps on Zen 4 (docs/PERFORMANCE.md, "Register groups per table").
    type ArcGroups = Groups<2, 2, 2, 4>;

    #[inline(always)]
    fn chunk<G: Geom, L: Lanes>(
        &self,
        cpu: L::Needs,
        g: &G,
        law: &Law,
        ins: &[Paused],
        out: &mut Vec<Paused>,
    ) {
        let mut r = Balls::<L>::new(load_states(cpu, |i| ins[i].reference));
        // The shell of the launch state, as `Ball::new` stored it.
        let shell =
            Shell::Fixed(Balls::new(load_states::<L>(cpu, |i| ins[i].launch)).inv_shell(law));
        // A vector that stopped was renormalised at the stop; it differs
        // from the uninterrupted run's only by a power of two, which the
        // tangent map (linear) carries exactly and the next
        // renormalisation takes off again.
        let mut v = load_vectors::<L>(cpu, |i| ins[i].partner_vector());
        let mut time = load_lane::<L>(cpu, |i| ins[i].time);
        let mut e = L::Bits::splat(cpu, 0);
        let mut renorms = 0u64;
        let mut zero_run = ZeroRun::resume(load_lane::<L>(cpu, |i| ins[i].zero_run));
        let mut left = self.collisions;
        while left > 0 {
            let run = left.min(RENORM_EVERY);
            for _ in 0..run {
                let st = step(g, law, &mut r, shell);
                zero_run.watch(st.hit.time);
                time = time + st.hit.time;
                TangentStep::new::<G>(law, &st, &r).apply::<G>(law, &mut v);
            }
            e = e.add(pow2_renormalise(&mut v));
            renorms += 1;
            left -= run;
        }
        let ok = all_finite(&v).and(time.is_finite()).and(zero_run.moving());
        let inv_units = self.units.inv_units();
        let w: [L; 5] = five(|c| v[c] * inv_units[c]);
        let norm = dot(&w, &w).sqrt();
        let z = r.coords();
        out.extend((0..L::N).map(|i| {
            let k = e.lane(i).wrapping_sub(1023u64.wrapping_mul(renorms)) as i64;
            let log_exponent = ins[i].log_exponent.wrapping_add(k);
            Paused {
                reference: state_of(&z, i),
                partner: state_of(&v, i).to_array(),
                log_exponent,
                log_stretch: if mask_lane::<L>(cpu, ok, i) {
                    (norm.lane(i) / ins[i].tangent_from()).ln()
                        + log_exponent as f64 * std::f64::consts::LN_2
                } else {
                    f64::NAN
                },
                time: time.lane(i),
                zero_run: zero_run.run(i),
                collisions: ins[i].collisions + self.collisions,
                ..ins[i]
            }
        }));
    }

    fn is_sound(o: &Paused) -> bool {
        o.is_sound()
    }
}

/// Exact tangent dynamics of five vectors with modified Gram–Schmidt every
/// `qr_interval` collisions and after the last (as `lyapunov_spectrum` with
/// `Method::Tangent`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Spectrum {
    pub collisions: u64,
    pub qr_interval: u64,
}

impl Kernel for Spectrum {
    type In = (State, [TangentVector; 5]);
    type Out = SpectrumStretch;
    /// Registers per group: AVX-512 2, AVX2 3, SSE2 4, portable `f64` 2.
    type Groups = Groups<2, 3, 4, 2>;
    /// Two AVX2 registers per group instead of three, two SSE2 instead of
    /// four.
    type BulkyGroups = Groups<2, 2, 2, 2>;
    /// As without arcs.
    type ArcGroups = <Self as Kernel>::BulkyGroups;

    #[inline(always)]
    fn chunk<G: Geom, L: Lanes>(
        &self,
        cpu: L::Needs,
        g: &G,
        law: &Law,
        ins: &[(State, [TangentVector; 5])],
        out: &mut Vec<SpectrumStretch>,
    ) {
        let mut r = Balls::<L>::new(load_states(cpu, |i| ins[i].0));
        let shell = Shell::Fixed(r.inv_shell(law));
        let mut v: [[L; 5]; 5] = five(|j| load_vectors(cpu, |i| ins[i].1[j]));
        let mut logs = [LogProduct::<L>::new(cpu); 5];
        let mut time = L::splat(cpu, 0.0);
        let mut zero_run = ZeroRun::<L>::new(cpu);
        let mut left = self.collisions;
        while left > 0 {
            let run = left.min(self.qr_interval);
            for _ in 0..run {
                let st = step(g, law, &mut r, shell);
                zero_run.watch(st.hit.time);
                time = time + st.hit.time;
                let ts = TangentStep::new::<G>(law, &st, &r);
                for z in v.iter_mut() {
                    ts.apply::<G>(law, z);
                }
            }
            // Modified Gram–Schmidt, as the scalar `gram_schmidt`.
            for i in 0..5 {
                for j in 0..i {
                    let p = dot(&v[i], &v[j]);
                    let vj = v[j];
                    for (a, b) in v[i].iter_mut().zip(vj) {
                        *a = *a - b * p;
                    }
                }
                let n = dot(&v[i], &v[i]).sqrt();
                let inv = L::splat(cpu, 1.0) / n;
                for a in v[i].iter_mut() {
                    *a = *a * inv;
                }
                logs[i].push(n);
            }
            left -= run;
        }
        let ok = v
            .iter()
            .fold(time.is_finite().and(zero_run.moving()), |m, z| {
                m.and(all_finite(z))
            });
        let z = r.coords();
        out.extend((0..L::N).map(|i| SpectrumStretch {
            log_stretch: std::array::from_fn(|j| {
                if mask_lane::<L>(cpu, ok, i) {
                    logs[j].ln(i)
                } else {
                    f64::NAN
                }
            }),
            time: time.lane(i),
            collisions: self.collisions,
            end: state_of(&z, i),
        }));
    }

    fn is_sound(o: &SpectrumStretch) -> bool {
        o.log_stretch.iter().all(|x| x.is_finite())
            && o.time.is_finite()
            && o.end.to_array().iter().all(|x| x.is_finite())
    }
}

mod escape;

pub(crate) use escape::{Ended, Escape};

#[cfg(test)]
mod tests;
