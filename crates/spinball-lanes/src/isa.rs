//! The instruction-set levels, and the proofs that this CPU has them.
//!
//! A library cannot ask its users to build with `-C target-cpu=native`, and a
//! binary built on one machine runs on others. So every kernel is compiled
//! three times from the same generic source, each copy inside a function
//! carrying `#[target_feature(enable = ...)]` for one level (the entry points
//! of the crate's `dispatch` module):
//!
//! | [`Isa`] | features enabled | vector width | used on |
//! |---|---|---|---|
//! | [`Isa::Avx512`] | `avx512f, avx512dq, avx512vl, avx512bw` | 8 × f64 | Zen 4/5, Xeon since Skylake-SP |
//! | [`Isa::Avx2`] | `avx2` | 4 × f64 | x86-64 since Haswell / Zen 1 |
//! | [`Isa::Baseline`] | what the target has by default: SSE2 on x86-64 (and 32-bit x86 built with SSE2), plain `f64` lanes elsewhere | 2 × f64 (SSE2) | everything |
//!
//! [`Isa::detect`] asks the CPU once (`is_x86_feature_detected!`) and a run
//! dispatches once per call, outside every loop. The lane code uses no fused
//! multiply-add and no approximate reciprocal, so all three levels give
//! **bitwise identical** results (tested): the choice changes the speed only.
//!
//! Running code compiled for a feature on a CPU without it is undefined
//! behaviour. So the crate holds the fact "this CPU has AVX2" as a value: the
//! zero-sized proofs `Avx2Cpu` and `Avx512Cpu` (crate-private) can only be
//! made by detecting the features, the entry points compiled for a level
//! take the level's proof, and the trait `ProvenBy` tells the compiler which
//! lane types a proof allows (each lane type names the proof it needs). The
//! lane values hold their proof too, so none is made without one (the
//! crate's `lanes` module).
//!
//! This module is the bottom layer of the crate: it uses no other module.

use std::fmt;
use std::str::FromStr;

use thiserror::Error;

/// An instruction-set level the kernels are compiled for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Isa {
    /// AVX-512 (F, DQ, VL, BW): 8 `f64` per register, 32 registers, mask registers.
    Avx512,
    /// AVX2: 4 `f64` per register, 16 registers.
    Avx2,
    /// The target's default instruction set (SSE2 on x86-64): always available.
    Baseline,
}

/// Why an [`Isa`] cannot be used (converts into
/// [`LanesError`](crate::LanesError)).
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum IsaError {
    /// The instruction set asked for is not supported by this CPU.
    #[error("instruction set `{0}` is not available on this CPU (available: {avail})", avail = available_names())]
    Unavailable(Isa),
    /// A name `str::parse::<Isa>` does not know.
    #[error("unknown instruction set `{0}` (expected avx512, avx2, baseline or auto)")]
    Unknown(String),
}

fn available_names() -> String {
    Isa::available()
        .iter()
        .map(|i| i.name())
        .collect::<Vec<_>>()
        .join(", ")
}

impl Isa {
    /// All levels, fastest first.
    pub const ALL: [Isa; 3] = [Isa::Avx512, Isa::Avx2, Isa::Baseline];

    /// The fastest level this CPU supports.
    pub fn detect() -> Isa {
        Isa::ALL
            .into_iter()
            .find(|isa| isa.is_available())
            .unwrap_or(Isa::Baseline)
    }

    /// Every level this CPU supports, fastest first.
    pub fn available() -> Vec<Isa> {
        Isa::ALL
            .into_iter()
            .filter(|isa| isa.is_available())
            .collect()
    }

    /// Whether this CPU can run the level.
    pub fn is_available(self) -> bool {
        match self {
            Isa::Baseline => true,
            #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
            Isa::Avx512 => Avx512Cpu::detect().is_some(),
            #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
            Isa::Avx2 => Avx2Cpu::detect().is_some(),
            #[cfg(not(any(target_arch = "x86", target_arch = "x86_64")))]
            _ => false,
        }
    }

    /// `avx512`, `avx2` or `baseline`.
    pub fn name(self) -> &'static str {
        match self {
            Isa::Avx512 => "avx512",
            Isa::Avx2 => "avx2",
            Isa::Baseline => "baseline",
        }
    }

    /// `Ok(self)` if this CPU can run it.
    ///
    /// # Errors
    /// [`IsaError::Unavailable`] (which `?` turns into
    /// [`LanesError::IsaUnavailable`](crate::LanesError::IsaUnavailable)).
    pub fn checked(self) -> Result<Isa, IsaError> {
        if self.is_available() {
            Ok(self)
        } else {
            Err(IsaError::Unavailable(self))
        }
    }
}

impl fmt::Display for Isa {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Isa {
    type Err = IsaError;
    /// `avx512`, `avx2`, `baseline` (or `scalar`, `sse2`), or `auto` for
    /// [`Isa::detect`]. Does not check availability (see [`Isa::checked`]).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.trim().to_ascii_lowercase().as_str() {
            "avx512" | "avx-512" => Ok(Isa::Avx512),
            "avx2" => Ok(Isa::Avx2),
            "baseline" | "scalar" | "sse2" => Ok(Isa::Baseline),
            "auto" | "detect" => Ok(Isa::detect()),
            other => Err(IsaError::Unknown(other.to_string())),
        }
    }
}

/// The features `Self` stands for are proven present by a `C`.
///
/// Every lane type names the proof its instructions need
/// (`Lanes::Needs`); code that runs lanes takes a proof `C` and requires
/// `L::Needs: ProvenBy<C>`, so the compiler refuses, say, AVX2 lanes in the
/// baseline entry point. The relation is the features' implication: AVX-512F
/// implies AVX2, and both imply the baseline; [`from_proof`](Self::from_proof)
/// turns the stronger proof into the weaker one (the lane constructors take
/// the weaker one, `Lanes::Needs`).
pub(crate) trait ProvenBy<C>: Copy {
    /// The proof of `Self`'s features, from the proof `c` of features that
    /// imply them.
    fn from_proof(c: C) -> Self;
}

/// The target's default instruction set, which every CPU the binary runs on
/// has (the rest of the binary is compiled for it too): needs no detection.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Baseline;

impl ProvenBy<Baseline> for Baseline {
    #[inline(always)]
    fn from_proof(c: Baseline) -> Baseline {
        c
    }
}

/// Proof that this CPU has AVX2: made only by [`Avx2Cpu::detect`] (and from
/// an [`Avx512Cpu`], whose features imply AVX2).
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
#[derive(Debug, Clone, Copy)]
pub(crate) struct Avx2Cpu(());

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
impl Avx2Cpu {
    /// `Some` if and only if the CPU (and the OS, for the register state)
    /// supports AVX2.
    #[inline]
    pub(crate) fn detect() -> Option<Avx2Cpu> {
        std::arch::is_x86_feature_detected!("avx2").then_some(Avx2Cpu(()))
    }
}

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
impl ProvenBy<Avx2Cpu> for Baseline {
    #[inline(always)]
    fn from_proof(_: Avx2Cpu) -> Baseline {
        Baseline
    }
}
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
impl ProvenBy<Avx2Cpu> for Avx2Cpu {
    #[inline(always)]
    fn from_proof(c: Avx2Cpu) -> Avx2Cpu {
        c
    }
}

/// Proof that this CPU has AVX-512 F, DQ, VL and BW: made only by
/// [`Avx512Cpu::detect`].
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
#[derive(Debug, Clone, Copy)]
pub(crate) struct Avx512Cpu(());

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
impl Avx512Cpu {
    /// `Some` if and only if the CPU (and the OS, for the register state)
    /// supports AVX-512 F, DQ, VL and BW.
    #[inline]
    pub(crate) fn detect() -> Option<Avx512Cpu> {
        (std::arch::is_x86_feature_detected!("avx512f")
            && std::arch::is_x86_feature_detected!("avx512dq")
            && std::arch::is_x86_feature_detected!("avx512vl")
            && std::arch::is_x86_feature_detected!("avx512bw"))
        .then_some(Avx512Cpu(()))
    }
}

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
impl ProvenBy<Avx512Cpu> for Baseline {
    #[inline(always)]
    fn from_proof(_: Avx512Cpu) -> Baseline {
        Baseline
    }
}
// AVX-512F implies AVX2 (a CPU with the former has the latter, and
// `target_feature(enable = "avx512f")` enables "avx2" too): the one place
// besides `Avx2Cpu::detect` that makes an `Avx2Cpu`.
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
impl ProvenBy<Avx512Cpu> for Avx2Cpu {
    #[inline(always)]
    fn from_proof(_: Avx512Cpu) -> Avx2Cpu {
        Avx2Cpu(())
    }
}
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
impl ProvenBy<Avx512Cpu> for Avx512Cpu {
    #[inline(always)]
    fn from_proof(c: Avx512Cpu) -> Avx512Cpu {
        c
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn detect_is_available_and_names_round_trip() {
        let best = Isa::detect();
        assert!(best.is_available());
        assert_eq!(Isa::available()[0], best);
        assert!(Isa::Baseline.is_available());
        for isa in Isa::ALL {
            assert_eq!(isa.name().parse::<Isa>().unwrap(), isa);
            assert_eq!(isa.checked().is_ok(), isa.is_available());
        }
        assert!("mmx".parse::<Isa>().is_err());
    }
}
