//! What an estimate was computed from: table, spin, method, initial
//! conditions, seed, engine. Typed (enums with serde), so a result can be
//! checked, merged and rerun, not just read.
//!
//! Documented in the group docs (`run/mod.rs`), section "Provenance".

use std::fmt;

use spinball_core::Sampler;
use spinball_geometry::{Boundary, Shape};

use super::engine::Engine;
use crate::estimators::Method;

/// The table of a run: its [`Shape`] when it has one (every built-in table
/// and every segment table: enough to rebuild it), and a name.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TableRecord {
    /// The spec string of a built-in table (`stadium:a=1`, which
    /// `spinball_geometry::Table` parses back), `segments(N walls)`, or the
    /// Rust type name of a table without a shape.
    pub name: String,
    /// The table as data, if it has a closed form.
    pub shape: Option<Shape>,
}

impl TableRecord {
    /// The record of `table`.
    #[must_use]
    pub fn of<B: Boundary>(table: &B) -> Self {
        let shape = table.shape();
        let name = match &shape {
            Some(s) => s.to_string(),
            None => std::any::type_name::<B>().to_string(),
        };
        TableRecord { name, shape }
    }
}

impl fmt::Display for TableRecord {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name)
    }
}

/// The parameters of an ensemble run, as a result records them.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Provenance {
    /// The table.
    pub table: TableRecord,
    /// Spin parameter α.
    pub alpha: f64,
    /// How the exponent was measured.
    pub method: Method,
    /// How initial conditions were drawn (`None`: given as explicit states).
    pub sampler: Option<Sampler>,
    /// Seed of the initial conditions (and of the perturbation directions).
    pub seed: u64,
    /// Collisions per initial condition.
    pub collisions_per_ic: u64,
    /// FTLE above which a trajectory counts as chaotic.
    pub threshold: f64,
    /// The engine that ran the trajectories.
    pub engine: Engine,
}

impl Provenance {
    /// A record of the given parameters.
    #[must_use]
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        table: TableRecord,
        alpha: f64,
        method: Method,
        sampler: Option<Sampler>,
        seed: u64,
        collisions_per_ic: u64,
        threshold: f64,
        engine: Engine,
    ) -> Self {
        Provenance {
            table,
            alpha,
            method,
            sampler,
            seed,
            collisions_per_ic,
            threshold,
            engine,
        }
    }
}
