//! The finished Lyapunov document: what `spinball lyapunov`, `ftle` and
//! `merge` write, every estimate with its provenance and per-trajectory
//! values.
//!
//! Documented in the group docs (`report/mod.rs`), section "Documents".

use crate::run::LyapunovEstimate;

/// A finished Lyapunov run: one estimate per α, each with its provenance
/// and per-initial-condition values (kind `spinball.lyapunov`).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct LyapunovDocument {
    /// One estimate per α, in the order asked.
    pub points: Vec<LyapunovEstimate>,
}

impl LyapunovDocument {
    /// The document of `points`.
    #[must_use]
    pub fn new(points: Vec<LyapunovEstimate>) -> Self {
        LyapunovDocument { points }
    }
}
