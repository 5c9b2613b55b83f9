//! Running a kernel at an instruction-set level: the entry points compiled
//! for each level, and the one `match` on the level per run.
//!
//! The generic kernels are `#[inline(always)]` all the way down, so each
//! entry point below is a complete copy of a kernel compiled with its
//! level's features. Calling an entry point compiled for AVX2 or AVX-512 is
//! `unsafe` (the CPU must have the features); the entry points here take the
//! zero-sized proofs of [`isa`](crate::isa), which only detection makes, so
//! the one `unsafe` call per level is justified by a value the caller cannot
//! forge, and the lane type they run with must be one that proof allows.
//!
//! This module sits above both [`kernels`](crate::kernels) (what to run) and
//! [`isa`](crate::isa) (which levels exist and how to prove them).

use crate::dynamics::Law;
use crate::geom::Geom;
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
use crate::isa::{Avx2Cpu, Avx512Cpu};
use crate::isa::{Baseline, Isa, ProvenBy};
use crate::kernels::{Kernel, run_chunks};
use crate::lanes::{Footprint, Lanes, PerIsa};

/// The kernels compiled for AVX-512 F, DQ, VL and BW; `cpu` proves this CPU
/// has them.
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
fn on_avx512<G: Geom, K: Kernel, L: Lanes<Needs: ProvenBy<Avx512Cpu>>>(
    cpu: Avx512Cpu,
    g: &G,
    law: &Law,
    k: &K,
    ins: &[K::In],
) -> Vec<K::Out> {
    #[target_feature(enable = "avx512f,avx512dq,avx512vl,avx512bw")]
    fn compiled<G: Geom, K: Kernel, L: Lanes<Needs: ProvenBy<Avx512Cpu>>>(
        cpu: Avx512Cpu,
        g: &G,
        law: &Law,
        k: &K,
        ins: &[K::In],
    ) -> Vec<K::Out> {
        run_chunks::<G, K, L, _>(cpu, g, law, k, ins)
    }
    // SAFETY: `compiled` is compiled with AVX-512 F, DQ, VL and BW enabled,
    // so calling it requires a CPU with them. `cpu` is an `Avx512Cpu`, whose
    // only constructor, `Avx512Cpu::detect`, returns one after
    // `is_x86_feature_detected!` confirmed all four.
    unsafe { compiled::<G, K, L>(cpu, g, law, k, ins) }
}

/// The kernels compiled for AVX2; `cpu` proves this CPU has it.
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
fn on_avx2<G: Geom, K: Kernel, L: Lanes<Needs: ProvenBy<Avx2Cpu>>>(
    cpu: Avx2Cpu,
    g: &G,
    law: &Law,
    k: &K,
    ins: &[K::In],
) -> Vec<K::Out> {
    #[target_feature(enable = "avx2")]
    fn compiled<G: Geom, K: Kernel, L: Lanes<Needs: ProvenBy<Avx2Cpu>>>(
        cpu: Avx2Cpu,
        g: &G,
        law: &Law,
        k: &K,
        ins: &[K::In],
    ) -> Vec<K::Out> {
        run_chunks::<G, K, L, _>(cpu, g, law, k, ins)
    }
    // SAFETY: `compiled` is compiled with AVX2 enabled, so calling it
    // requires a CPU with AVX2. `cpu` is an `Avx2Cpu`, whose only
    // constructor, `Avx2Cpu::detect`, returns one after
    // `is_x86_feature_detected!("avx2")` confirmed it.
    unsafe { compiled::<G, K, L>(cpu, g, law, k, ins) }
}

/// The kernels compiled for the target's baseline (no proof needed).
fn on_baseline<G: Geom, K: Kernel, L: Lanes<Needs: ProvenBy<Baseline>>>(
    g: &G,
    law: &Law,
    k: &K,
    ins: &[K::In],
) -> Vec<K::Out> {
    run_chunks::<G, K, L, _>(Baseline, g, law, k, ins)
}

/// The register groups kernel `K` runs with on table `G`: its
/// [`Kernel::Groups`], [`Kernel::BulkyGroups`] or [`Kernel::ArcGroups`], as
/// `G`'s [`Footprint`] picks.
type GroupsOn<K, G> = <<G as Geom>::Footprint as Footprint>::Pick<
    <K as Kernel>::Groups,
    <K as Kernel>::BulkyGroups,
    <K as Kernel>::ArcGroups,
>;

/// Running any [`Kernel`] at an instruction-set level.
pub(crate) trait Dispatch: Kernel {
    /// Run over a slice at level `isa`, with this kernel's lane type for the
    /// level and table ([`GroupsOn`]). A level this CPU lacks (only possible for
    /// an `isa` that did not go through [`Isa::checked`]) runs at the
    /// baseline instead, with the same results.
    fn dispatch<G: Geom>(&self, isa: Isa, g: &G, law: &Law, ins: &[Self::In]) -> Vec<Self::Out>;
}

impl<K: Kernel> Dispatch for K {
    fn dispatch<G: Geom>(&self, isa: Isa, g: &G, law: &Law, ins: &[K::In]) -> Vec<K::Out> {
        match isa {
            #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
            Isa::Avx512 => {
                if let Some(cpu) = Avx512Cpu::detect() {
                    return on_avx512::<G, K, <GroupsOn<K, G> as PerIsa>::Avx512>(
                        cpu, g, law, self, ins,
                    );
                }
            }
            #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
            Isa::Avx2 => {
                if let Some(cpu) = Avx2Cpu::detect() {
                    return on_avx2::<G, K, <GroupsOn<K, G> as PerIsa>::Avx2>(
                        cpu, g, law, self, ins,
                    );
                }
            }
            _ => {}
        }
        on_baseline::<G, K, <GroupsOn<K, G> as PerIsa>::Baseline>(g, law, self, ins)
    }
}
