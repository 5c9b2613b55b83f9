//! The documents of the phase-space commands: a Birkhoff section, Kac's
//! return times, an FTLE map and one shard of it. Each names the table as
//! data and the spinball version that wrote it, so a file can be read
//! back (and a map's shards merged) without the command that made it.
//!
//! Documented in the group docs (`report/mod.rs`), section "Documents".

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};
use spinball_core::SpinLaw;
use spinball_geometry::{Boundary, Built};

use crate::estimators::ChaoticFraction;
use crate::phase_space::{FacingFlats, FtleMap, FtleMapPart, KacComparison};
use crate::precision::Measurement;
use crate::run::TableRecord;

/// What every section and Kac document starts with: who wrote it, the
/// table and α.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PhaseHead {
    /// The version of spinball that wrote it.
    pub version: String,
    /// The table, as data.
    pub table: TableRecord,
    /// Spin parameter α.
    pub alpha: f64,
}

impl PhaseHead {
    /// The head of a document of `table` at `law`, written by this build.
    #[must_use]
    pub fn new<B: Boundary>(table: &B, law: &SpinLaw) -> Self {
        PhaseHead {
            version: env!("CARGO_PKG_VERSION").into(),
            table: TableRecord::of(table),
            alpha: law.alpha(),
        }
    }
}

/// The Birkhoff section of a few orbits (`spinball section`,
/// kind `spinball.section`): every kept collision, column by column.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SectionDocument {
    /// Version, table and α.
    #[serde(flatten)]
    pub head: PhaseHead,
    /// How the orbits started (`paper`, `microcanonical`, `invariant`).
    pub sampler: String,
    /// The seed of the starts.
    pub seed: u64,
    /// Orbits.
    pub orbits: u64,
    /// Collisions per orbit.
    pub collisions: u64,
    /// The half-width `W` of the kept slice `|√α u| < W`, if one.
    pub spin_slice: Option<f64>,
    /// Column name (`s`, `sin_theta`, …) → one value per kept point.
    pub columns: BTreeMap<String, Vec<f64>>,
}

/// Mean return times to a region against Kac's lemma (`spinball kac`,
/// kind `spinball.kac`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct KacDocument {
    /// Version, table and α.
    #[serde(flatten)]
    pub head: PhaseHead,
    /// The seed of the starts.
    pub seed: u64,
    /// Collisions per orbit.
    pub collisions: u64,
    /// `mean_return / expected` with its SEM (`null` if fewer than two
    /// orbits returned).
    pub ratio: Option<Measurement>,
    /// The comparison, orbit by orbit.
    pub comparison: KacComparison,
}

impl KacDocument {
    /// The document of `comparison` on `table` at `law`.
    #[must_use]
    pub fn new<B: Boundary>(
        table: &B,
        law: &SpinLaw,
        seed: u64,
        collisions: u64,
        comparison: KacComparison,
    ) -> Self {
        KacDocument {
            head: PhaseHead::new(table, law),
            seed,
            collisions,
            ratio: comparison.ratio(),
            comparison,
        }
    }
}

/// A finished FTLE map with what it shows (`spinball ftle-map`, `merge`;
/// kind `spinball.ftle_map`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FtleMapDocument {
    /// The version of spinball that wrote it.
    pub version: String,
    /// The table.
    pub table: TableRecord,
    /// The map: options, α, perimeter, exponents (row-major, `null` off
    /// the shell).
    pub map: FtleMap,
    /// The chaotic share of the cells on the shell, with its binomial error.
    pub chaotic_fraction: ChaoticFraction,
    /// The cells the bouncing-ball rotation predicts trapped between two
    /// facing flats (row-major); `null` for a table without them.
    pub predicted: Option<Vec<bool>>,
    /// Predicted cells on the shell.
    pub predicted_cells: usize,
    /// How many of the predicted cells the map finds regular.
    pub predicted_regular: usize,
}

impl FtleMapDocument {
    /// The document of `map` of `table` (described by `record`) under
    /// `law`, with the bouncing-ball prediction where the table has
    /// facing flats.
    #[must_use]
    pub fn new(table: &Built, law: &SpinLaw, record: TableRecord, map: FtleMap) -> Self {
        let flats = match table {
            Built::Table(t) => FacingFlats::of_table(t),
            Built::Segments(_) => None,
        };
        let predicted = flats.map(|f| f.trapped_cells(law, &map));
        let (predicted_cells, predicted_regular) = predicted
            .as_ref()
            .map_or((0, 0), |mask| map.regular_among(mask));
        FtleMapDocument {
            version: env!("CARGO_PKG_VERSION").into(),
            table: record,
            chaotic_fraction: map.chaotic_fraction(),
            map,
            predicted,
            predicted_cells,
            predicted_regular,
        }
    }
}

/// One shard of an FTLE map, for `spinball merge` (kind
/// `spinball.ftle_map.partial`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FtleMapPartialDocument {
    /// The shard.
    pub part: FtleMapPart,
}
