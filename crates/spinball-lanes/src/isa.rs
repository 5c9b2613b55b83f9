//! Choosing the instruction set at run time.
//!
//! A library cannot ask its users to build with `-C target-cpu=native`, and a
//! binary built on one machine runs on others. So every kernel is compiled
//! three times from the same generic source, each copy inside a function
//! carrying `#[target_feature(enable = ...)]` for one level:
//!
//! | [`Isa`] | features enabled | vector width | used on |
//! |---|---|---|---|
//! | [`Isa::Avx512`] | `avx512f, avx512dq, avx512vl, avx512bw` | 8 × f64 | Zen 4/5, Xeon since Skylake-SP |
//! | [`Isa::Avx2`] | `avx2` | 4 × f64 | x86-64 since Haswell / Zen 1 |
//! | [`Isa::Baseline`] | what the target has by default (SSE2; NEON on aarch64) | 2 × f64 | everything |
//!
//! [`Isa::detect`] asks the CPU once (`is_x86_feature_detected!`) and a run
//! dispatches once per call, outside every loop. The lane code uses no fused
//! multiply-add and no approximate reciprocal, so all three levels give
//! **bitwise identical** results (tested): the choice changes the speed only.

use std::fmt;
use std::str::FromStr;

use crate::error::LanesError;

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
            Isa::Avx512 => {
                std::arch::is_x86_feature_detected!("avx512f")
                    && std::arch::is_x86_feature_detected!("avx512dq")
                    && std::arch::is_x86_feature_detected!("avx512vl")
                    && std::arch::is_x86_feature_detected!("avx512bw")
            }
            #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
            Isa::Avx2 => std::arch::is_x86_feature_detected!("avx2"),
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
    /// [`LanesError::IsaUnavailable`].
    pub fn checked(self) -> Result<Isa, LanesError> {
        if self.is_available() {
            Ok(self)
        } else {
            Err(LanesError::IsaUnavailable(self))
        }
    }
}

impl fmt::Display for Isa {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Isa {
    type Err = LanesError;
    /// `avx512`, `avx2`, `baseline` (or `scalar`, `sse2`), or `auto` for
    /// [`Isa::detect`]. Does not check availability (see [`Isa::checked`]).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.trim().to_ascii_lowercase().as_str() {
            "avx512" | "avx-512" => Ok(Isa::Avx512),
            "avx2" => Ok(Isa::Avx2),
            "baseline" | "scalar" | "sse2" => Ok(Isa::Baseline),
            "auto" | "detect" => Ok(Isa::detect()),
            other => Err(LanesError::invalid(
                "isa",
                format!(
                    "unknown instruction set `{other}` (expected avx512, avx2, baseline or auto)"
                ),
            )),
        }
    }
}

/// Compile `run_chunks` for one instruction-set level.
///
/// The generic kernel is `#[inline(always)]` all the way down, so its whole
/// body is compiled inside this function, with the level's features.
macro_rules! isa_entry {
    ($(#[$m:meta])* $name:ident, $features:literal) => {
        $(#[$m])*
        #[target_feature(enable = $features)]
        pub(crate) fn $name<G: crate::geom::Geom, K: crate::kernels::Kernel, L: crate::lanes::Lanes>(
            g: &G,
            law: &crate::dynamics::Law,
            k: &K,
            ins: &[K::In],
        ) -> Vec<K::Out> {
            crate::kernels::run_chunks::<G, K, L>(g, law, k, ins)
        }
    };
}

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
isa_entry!(
    /// The kernels compiled for AVX-512. Call only when
    /// [`Isa::Avx512`]`.is_available()`.
    on_avx512,
    "avx512f,avx512dq,avx512vl,avx512bw"
);
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
isa_entry!(
    /// The kernels compiled for AVX2. Call only when
    /// [`Isa::Avx2`]`.is_available()`.
    on_avx2,
    "avx2"
);

/// The kernels compiled for the target's baseline.
pub(crate) fn on_baseline<
    G: crate::geom::Geom,
    K: crate::kernels::Kernel,
    L: crate::lanes::Lanes,
>(
    g: &G,
    law: &crate::dynamics::Law,
    k: &K,
    ins: &[K::In],
) -> Vec<K::Out> {
    crate::kernels::run_chunks::<G, K, L>(g, law, k, ins)
}

/// Run kernel `$k` on `$ins` at level `$isa` with the given lane type per
/// level (the results do not depend on it; it only sets how many
/// trajectories share the registers).
macro_rules! dispatch {
    ($isa:expr, $g:expr, $law:expr, $k:expr, $ins:expr;
     avx512 = $l512:ty, avx2 = $l2:ty, sse2 = $lsse:ty, portable = $lp:ty) => {{
        #[allow(unused_imports)]
        use crate::lanes::*;
        match $isa {
            #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
            crate::isa::Isa::Avx512 => {
                debug_assert!(crate::isa::Isa::Avx512.is_available());
                // SAFETY: `on_avx512` is unsafe to call only because it is
                // compiled for AVX-512. Every `Isa` that reaches a dispatch
                // came from `Isa::detect` or went through `Isa::checked`
                // (`LaneBilliard::with_isa`), both of which confirmed with
                // `is_x86_feature_detected!` that this CPU has avx512f, dq,
                // vl and bw.
                unsafe { crate::isa::on_avx512::<_, _, $l512>($g, $law, $k, $ins) }
            }
            #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
            crate::isa::Isa::Avx2 => {
                debug_assert!(crate::isa::Isa::Avx2.is_available());
                // SAFETY: as above; the CPU was checked for avx2.
                unsafe { crate::isa::on_avx2::<_, _, $l2>($g, $law, $k, $ins) }
            }
            #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
            _ => crate::isa::on_baseline::<_, _, $lsse>($g, $law, $k, $ins),
            #[cfg(not(any(target_arch = "x86", target_arch = "x86_64")))]
            _ => crate::isa::on_baseline::<_, _, $lp>($g, $law, $k, $ins),
        }
    }};
}
pub(crate) use dispatch;

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
