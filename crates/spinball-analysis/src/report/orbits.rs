//! The document of `spinball orbits`: the stability diagram of the
//! periodic orbits of one period, with the table it is of.
//!
//! Documented in the group docs (`report/mod.rs`), section "Documents".

use serde::{Deserialize, Serialize};

use crate::orbits::{IslandPoint, StabilityDiagram};

/// A stability diagram (kind `spinball.orbits`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct OrbitsDocument {
    /// The table, as given on the command line (e.g. `stadium:a=1`).
    pub table: String,
    /// The orbits followed in α and where their stability changes.
    pub diagram: StabilityDiagram,
    /// With `spinball orbits --islands`: the island of each orbit of
    /// `diagram.branches` at each α (same order), measured where the orbit
    /// is elliptic; absent otherwise.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub islands: Option<Vec<Vec<IslandPoint>>>,
}
