//! The horizon of a periodic table: whether free flights are bounded,
//! which decides the law of diffusion.
//!
//! Documented in the group docs (`transport/mod.rs`) and `docs/TRANSPORT.md`,
//! section "Horizon".

use std::fmt;

/// Whether a periodic table has a longest free flight.
///
/// The geometry decides it (a corridor, a strip of the plane that misses
/// every scatterer, makes the horizon infinite); here it is an input, so
/// that the estimator knows which growth law to fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum Horizon {
    /// Every free flight is shorter than some length: normal diffusion,
    /// `⟨Δr²⟩ ≈ 4Dt`.
    Finite,
    /// Corridors allow flights of any length: marginal (superdiffusive)
    /// growth `⟨Δr²⟩ ≈ 4 D_m t ln t`; there is no finite `D`.
    Infinite,
}

impl fmt::Display for Horizon {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Horizon::Finite => "finite",
            Horizon::Infinite => "infinite",
        })
    }
}
