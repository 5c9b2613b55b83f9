//! The four kernels: plain trajectory, finite-difference Benettin, exact
//! tangent, exact spectrum. Each runs `N` initial conditions in lockstep.
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
//! [`Kernel::BulkyGroups`]); choosing the level and entering the code
//! compiled for it is the `dispatch` module's job, one layer up.

use spinball_core::{State, TangentVector, Units};

use crate::dynamics::{
    Balls, Law, LogProduct, Shell, TangentStep, ZeroRun, collide, pow2_renormalise, step,
};
use crate::geom::Geom;
use crate::isa::ProvenBy;
use crate::lanes::{BitsOps, Groups, Lanes, MAX_LANES, MaskOps, PerIsa};
use crate::outcome::{Flight, SpectrumStretch, Stretch};

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
    /// Independent streams of `L::N` trajectories a chunk steps in turn
    /// (each stream's landing then covers the other's division: see
    /// docs/PERFORMANCE.md, "Latency, not operations").
    const STREAMS: usize = 1;
    /// Run `STREAMS · L::N` initial conditions (`ins.len()`), pushing their
    /// outcomes onto `out` in input order.
    fn chunk<G: Geom, L: Lanes>(
        &self,
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
/// The only way the crate runs a kernel. `_cpu` proves that this CPU has the
/// features `L`'s instructions need (`L::Needs: ProvenBy<C>`, checked by the
/// compiler): this is what the SIMD lane types' safety rests on.
#[inline(always)]
pub(crate) fn run_chunks<G: Geom, K: Kernel, L: Lanes<Needs: ProvenBy<C>>, C>(
    _cpu: C,
    g: &G,
    law: &Law,
    k: &K,
    ins: &[K::In],
) -> Vec<K::Out> {
    const { assert!(L::N <= MAX_LANES) };
    let n = L::N * K::STREAMS;
    let mut out = Vec::with_capacity(ins.len() + n);
    for c in ins.chunks(n) {
        if c.len() == n {
            k.chunk::<G, L>(g, law, c, &mut out);
        } else {
            let last = c[c.len() - 1];
            let padded: Vec<K::In> = (0..n).map(|j| c.get(j).copied().unwrap_or(last)).collect();
            k.chunk::<G, L>(g, law, &padded, &mut out);
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
fn load_states<L: Lanes>(s: impl Fn(usize) -> State) -> [L; 5] {
    let mut z = [[0.0; MAX_LANES]; 5];
    for i in 0..L::N {
        for (zc, x) in z.iter_mut().zip(s(i).to_array()) {
            zc[i] = x;
        }
    }
    five(|c| L::load(&z[c]))
}

/// The five components of `L::N` tangent vectors.
#[inline(always)]
fn load_vectors<L: Lanes>(v: impl Fn(usize) -> TangentVector) -> [L; 5] {
    load_states(|i| State::from_array(v(i).to_array()))
}

/// Lane `i` of a state.
fn state_of<L: Lanes>(z: &[L; 5], i: usize) -> State {
    State::from_array(z.map(|c| c.lane(i)))
}

/// Lanes where all of `z` is finite.
#[inline(always)]
fn all_finite<L: Lanes>(z: &[L]) -> L::Mask {
    z.iter()
        .fold(L::splat(0.0).eq(L::splat(0.0)), |m, c| m.and(c.is_finite()))
}

/// Whether lane `i` of a mask is set (outside hot loops).
fn mask_lane<L: Lanes>(m: L::Mask, i: usize) -> bool {
    L::select(m, L::splat(1.0), L::splat(0.0)).lane(i) == 1.0
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
    const STREAMS: usize = 2;

    #[inline(always)]
    fn chunk<G: Geom, L: Lanes>(&self, g: &G, law: &Law, ins: &[State], out: &mut Vec<Flight>) {
        let mut a = PlainStream::<L>::new(law, |i| ins[i]);
        let mut b = PlainStream::<L>::new(law, |i| ins[L::N + i]);
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
    fn new(law: &Law, s: impl Fn(usize) -> State) -> Self {
        let balls = Balls::new(load_states(s));
        PlainStream {
            shell: Shell::Fixed(balls.inv_shell(law)),
            balls,
            time: L::splat(0.0),
            zero_run: ZeroRun::new(),
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
        let time = L::select(self.zero_run.moving(), self.time, L::splat(f64::NAN));
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
    /// `δ0` times each coordinate's unit (`spinball_core::Perturbation`).
    pub scaled: [f64; 5],
    /// `1 / unit` of each coordinate (powers of two).
    pub inv_units: [f64; 5],
}

impl Kernel for FiniteDifference {
    type In = (State, TangentVector);
    type Out = Stretch;
    /// Registers per group: AVX-512 3, AVX2 4, SSE2 4, portable `f64` 4.
    type Groups = Groups<3, 4, 4, 4>;
    /// Two AVX2 and two SSE2 registers per group instead of four.
    type BulkyGroups = Groups<3, 2, 2, 4>;

    #[inline(always)]
    fn chunk<G: Geom, L: Lanes>(
        &self,
        g: &G,
        law: &Law,
        ins: &[(State, TangentVector)],
        out: &mut Vec<Stretch>,
    ) {
        let delta0 = self.delta0;
        let inv_delta0 = 1.0 / delta0;
        let z0 = load_states::<L>(|i| ins[i].0);
        let d0 = load_vectors::<L>(|i| ins[i].1);
        let mut r = Balls::new(z0);
        let shell = Shell::Fixed(r.inv_shell(law));
        let (scaled, inv_units) = (self.scaled, self.inv_units);
        let mut s = Balls::new(five(|c| z0[c] + d0[c] * scaled[c]));
        let mut logs = LogProduct::new();
        let mut time = L::splat(0.0);
        let mut zero_run = ZeroRun::<L>::new();
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
            let k = L::splat(delta0) / dist;
            s = Balls::new(five(|c| zr[c] + d[c] * k));
        }
        let ok = all_finite(&s.coords())
            .and(time.is_finite())
            .and(zero_run.moving());
        let z = r.coords();
        out.extend((0..L::N).map(|i| Stretch {
            log_stretch: if mask_lane::<L>(ok, i) {
                logs.ln(i)
            } else {
                f64::NAN
            },
            time: time.lane(i),
            collisions: self.collisions,
            end: state_of(&z, i),
        }));
    }

    fn is_sound(o: &Stretch) -> bool {
        o.log_stretch.is_finite()
            && o.time.is_finite()
            && o.end.to_array().iter().all(|x| x.is_finite())
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
    type In = (State, TangentVector);
    type Out = Stretch;
    /// Registers per group: AVX-512 3, AVX2 4, SSE2 4, portable `f64` 4.
    type Groups = Groups<3, 4, 4, 4>;
    /// Two AVX2 and two SSE2 registers per group instead of four.
    type BulkyGroups = Groups<3, 2, 2, 4>;

    #[inline(always)]
    fn chunk<G: Geom, L: Lanes>(
        &self,
        g: &G,
        law: &Law,
        ins: &[(State, TangentVector)],
        out: &mut Vec<Stretch>,
    ) {
        let mut r = Balls::<L>::new(load_states(|i| ins[i].0));
        let shell = Shell::Fixed(r.inv_shell(law));
        let mut v = load_vectors::<L>(|i| ins[i].1);
        let mut time = L::splat(0.0);
        let mut e = L::Bits::splat(0);
        let mut renorms = 0u64;
        let mut zero_run = ZeroRun::<L>::new();
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
            let from = self.units.measure(&ins[i].1);
            Stretch {
                log_stretch: if mask_lane::<L>(ok, i) {
                    (norm.lane(i) / from).ln() + k as f64 * std::f64::consts::LN_2
                } else {
                    f64::NAN
                },
                time: time.lane(i),
                collisions: self.collisions,
                end: state_of(&z, i),
            }
        }));
    }

    fn is_sound(o: &Stretch) -> bool {
        <FiniteDifference as Kernel>::is_sound(o)
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

    #[inline(always)]
    fn chunk<G: Geom, L: Lanes>(
        &self,
        g: &G,
        law: &Law,
        ins: &[(State, [TangentVector; 5])],
        out: &mut Vec<SpectrumStretch>,
    ) {
        let mut r = Balls::<L>::new(load_states(|i| ins[i].0));
        let shell = Shell::Fixed(r.inv_shell(law));
        let mut v: [[L; 5]; 5] = five(|j| load_vectors(|i| ins[i].1[j]));
        let mut logs = [LogProduct::<L>::new(); 5];
        let mut time = L::splat(0.0);
        let mut zero_run = ZeroRun::<L>::new();
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
                let inv = L::splat(1.0) / n;
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
                if mask_lane::<L>(ok, i) {
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

#[cfg(test)]
mod tests {
    use spinball_core::{Sampler, SpinLaw};
    use spinball_geometry::Stadium;

    use super::*;
    use crate::geom::LaneStadium;
    use crate::isa::Baseline;
    use crate::lanes::Wide;

    /// The portable lane type (used off x86) gives the numbers of the
    /// one-lane reference, tails included.
    #[test]
    fn portable_lanes_match_one_lane() {
        let table = Stadium::new(1.0).unwrap();
        let law = SpinLaw::new(0.4).unwrap();
        let g = LaneStadium::new(table.a());
        let l = Law::new(&law);
        let ins: Vec<(State, TangentVector)> = (0..11)
            .map(|i| {
                let s = Sampler::Paper.initial_state(&table, &law, 3, i);
                (s, TangentVector::from_array([0.6, -0.2, 0.1, 0.7, 0.3]))
            })
            .collect();
        let starts: Vec<State> = ins.iter().map(|x| x.0).collect();
        let unit = |j: usize| {
            let mut z = [0.0; 5];
            z[j] = 1.0;
            TangentVector::from_array(z)
        };
        let frames: Vec<(State, [TangentVector; 5])> = ins
            .iter()
            .map(|x| (x.0, std::array::from_fn(unit)))
            .collect();
        let plain = Plain { collisions: 500 };
        assert_eq!(
            run_chunks::<_, _, Wide<f64, 3>, _>(Baseline, &g, &l, &plain, &starts),
            run_chunks::<_, _, f64, _>(Baseline, &g, &l, &plain, &starts)
        );
        let fd = FiniteDifference {
            collisions: 500,
            delta0: 1e-7,
            scaled: [1e-7; 5],
            inv_units: [1.0; 5],
        };
        assert_eq!(
            run_chunks::<_, _, Wide<f64, 4>, _>(Baseline, &g, &l, &fd, &ins),
            run_chunks::<_, _, f64, _>(Baseline, &g, &l, &fd, &ins)
        );
        let tangent = Tangent {
            collisions: 500,
            units: Units::new(&table, &ins[0].0, &law),
        };
        assert_eq!(
            run_chunks::<_, _, Wide<f64, 4>, _>(Baseline, &g, &l, &tangent, &ins),
            run_chunks::<_, _, f64, _>(Baseline, &g, &l, &tangent, &ins)
        );
        let spectrum = Spectrum {
            collisions: 500,
            qr_interval: 3,
        };
        assert_eq!(
            run_chunks::<_, _, Wide<f64, 2>, _>(Baseline, &g, &l, &spectrum, &frames),
            run_chunks::<_, _, f64, _>(Baseline, &g, &l, &spectrum, &frames)
        );
    }

    /// Operations per collision step of each kernel, counted with a
    /// one-lane counting type over 20 000 steps (α = 0.5): the stadium
    /// `a = 1` and the Sinai table `L = 2, R = 1` built in, and the tables
    /// built from segments of `lanes_speed` (stadium, mushroom, 20-gon). The
    /// numbers behind the "floor" and the division tables of
    /// docs/PERFORMANCE.md; run with `--nocapture` to see them.
    #[test]
    fn operation_counts_per_step() {
        use spinball_geometry::Sinai;

        use crate::geom::{LaneSegments, LaneSinai, segment_tables};

        let law = SpinLaw::new(0.5).unwrap();
        let l = Law::new(&law);
        // [plain, fd, tangent, spectrum] × [div, sqrt] per step.
        let stadium = Stadium::new(1.0).unwrap();
        let c = counts("stadium", &stadium, &LaneStadium::new(1.0), &l, &law);
        // One division per cast (the chosen fraction) and one square root
        // (the cap's discriminant); the fallback of the circle contact never
        // runs. Finite differences add the shadow's cast, its shell and
        // δ0/δ with δ's square root; the tangent map adds 1/(n·v); the
        // spectrum five 1/|v_i| and five |v_i| of Gram–Schmidt.
        assert_eq!(c, [[1.0, 1.0], [4.0, 3.0], [2.0, 1.0], [7.0, 6.0]]);
        let sinai = Sinai::new(2.0, 1.0).unwrap();
        let c = counts("sinai", &sinai, &LaneSinai::new(2.0, 1.0), &l, &law);
        assert_eq!(c, [[1.0, 1.0], [4.0, 3.0], [2.0, 1.0], [7.0, 6.0]]);

        let seg_stadium = segment_tables::stadium(1.0);
        let ls = LaneSegments::new(&seg_stadium);
        let c = counts("seg-stadium", &seg_stadium, &ls.view::<true>(), &l, &law);
        // With arcs too, one division per cast (the chosen wall's fraction:
        // every arc's denominator is |v|²) and a square root per arc; the
        // fallback of the winning arc's contact never runs.
        assert_eq!(c[0], [1.0, 2.0]);
        let mushroom = segment_tables::mushroom(1.0, 0.3, 1.0);
        let lm = LaneSegments::new(&mushroom);
        let c = counts("mushroom", &mushroom, &lm.view::<true>(), &l, &law);
        assert_eq!(c[0], [1.0, 1.0]);
        let gon = segment_tables::alternating_twenty_gon();
        let lg = LaneSegments::new(&gon);
        let c = counts("20-gon", &gon, &lg.view::<false>(), &l, &law);
        // Without arcs: one division per cast, however many walls.
        assert_eq!(c[0], [1.0, 0.0]);
    }

    /// Runs the four kernels on `table` with the counting lane type and
    /// prints every operation per step; returns divisions and square roots
    /// per step of each, to 0.01.
    fn counts<B: spinball_geometry::Boundary, G: Geom>(
        name: &str,
        table: &B,
        g: &G,
        l: &Law,
        law: &SpinLaw,
    ) -> [[f64; 2]; 4] {
        use crate::lanes::counted::{Counted, take};
        const N: u64 = 20_000;
        let s = Sampler::Paper.initial_state(table, law, 1, 0);
        let d = TangentVector::from_array([0.6, -0.2, 0.1, 0.7, 0.3]);
        let unit = |j: usize| {
            let mut z = [0.0; 5];
            z[j] = 1.0;
            TangentVector::from_array(z)
        };
        let names = [
            "add/sub",
            "mul",
            "div",
            "sqrt",
            "cmp/max/abs",
            "select",
            "mask",
            "bits",
        ];
        // Per trajectory: a kernel of several streams runs that many copies
        // of the one state in a chunk.
        let report = |kernel: &str, streams: usize| {
            let c = take().map(|k| k / streams as u64);
            let per: Vec<String> = names
                .iter()
                .zip(c)
                .map(|(n, k)| format!("{n} {:.2}", k as f64 / N as f64))
                .collect();
            println!("{name:<12} {kernel:<9} per step: {}", per.join(", "));
            // To 0.01 per step: the launch's and the end's few operations
            // (1/|V|², the final norm) vanish.
            let per_step = |k: u64| (k as f64 / N as f64 * 100.0).round() / 100.0;
            [per_step(c[2]), per_step(c[3])]
        };
        take();
        run_chunks::<_, _, Counted, _>(Baseline, g, l, &Plain { collisions: N }, &[s]);
        let plain = report("plain", Plain::STREAMS);
        let fd = FiniteDifference {
            collisions: N,
            delta0: 1e-7,
            scaled: [1e-7; 5],
            inv_units: [1.0; 5],
        };
        run_chunks::<_, _, Counted, _>(Baseline, g, l, &fd, &[(s, d)]);
        let fd = report("fd", 1);
        run_chunks::<_, _, Counted, _>(
            Baseline,
            g,
            l,
            &Tangent {
                collisions: N,
                units: Units::new(table, &s, law),
            },
            &[(s, d)],
        );
        let tangent = report("tangent", 1);
        let spectrum = Spectrum {
            collisions: N,
            qr_interval: 1,
        };
        run_chunks::<_, _, Counted, _>(
            Baseline,
            g,
            l,
            &spectrum,
            &[(s, std::array::from_fn(unit))],
        );
        let spectrum = report("spectrum", 1);
        [plain, fd, tangent, spectrum]
    }
}
