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

use std::ops::Range;

use crate::estimators::ChaoticFraction;
use crate::phase_space::{FacingFlats, FtleMap, FtleMapPart, KacComparison, KacPart};
use crate::precision::Measurement;
use crate::run::{MergeError, RunDifference, Shard, TableRecord, tile};

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

/// One shard of a Birkhoff section (`spinball section --shard`, kind
/// `spinball.section.partial`): the points of the orbits `starts` of the
/// run `section` describes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SectionPartialDocument {
    /// Which shard this is.
    pub shard: Shard,
    /// The orbits this shard ran (of the whole run's `0..section.orbits`).
    pub starts: Range<u64>,
    /// The whole run's parameters, with the points of these orbits only
    /// (the `orbit` column holds the run's orbit indices).
    pub section: SectionDocument,
}

impl SectionPartialDocument {
    /// Whether `other` is a shard of the same section: the first field
    /// that differs (table by its geometry, version, α, sampler, seed,
    /// orbits, collisions, slice; numbers bit for bit).
    ///
    /// # Errors
    /// [`MergeError::DifferentRuns`] naming the field and both values;
    /// [`MergeError::Table`] for a table without a shape.
    pub fn same_run(&self, other: &SectionPartialDocument) -> Result<(), MergeError> {
        let (a, b) = (&self.section, &other.section);
        a.head.table.same_table(&b.head.table)?;
        let fields: [(&'static str, String, String); 8] = [
            ("version", a.head.version.clone(), b.head.version.clone()),
            (
                "alpha",
                format!("{:?}", a.head.alpha),
                format!("{:?}", b.head.alpha),
            ),
            ("sampler", a.sampler.clone(), b.sampler.clone()),
            ("seed", a.seed.to_string(), b.seed.to_string()),
            ("orbits", a.orbits.to_string(), b.orbits.to_string()),
            (
                "collisions per orbit",
                a.collisions.to_string(),
                b.collisions.to_string(),
            ),
            (
                "spin slice",
                format!("{:?}", a.spin_slice),
                format!("{:?}", b.spin_slice),
            ),
            (
                "columns",
                format!("{:?}", a.columns.keys().collect::<Vec<_>>()),
                format!("{:?}", b.columns.keys().collect::<Vec<_>>()),
            ),
        ];
        match fields.into_iter().find(|(_, x, y)| x != y) {
            Some((what, first, other)) => Err(RunDifference::Field { what, first, other }.into()),
            None => Ok(()),
        }
    }

    /// Join the shards of one section (in any order) into the section one
    /// unsharded run gives, bitwise: the points orbit by orbit.
    ///
    /// # Errors
    /// [`MergeError`]: no shards, shards of different runs
    /// ([`SectionPartialDocument::same_run`]), blocks of orbits that overlap
    /// or leave orbits out.
    pub fn merge(parts: Vec<SectionPartialDocument>) -> Result<SectionDocument, MergeError> {
        let first = parts.first().ok_or(MergeError::Empty)?;
        for p in &parts[1..] {
            first.same_run(p)?;
        }
        let blocks: Vec<Range<u64>> = parts.iter().map(|p| p.starts.clone()).collect();
        let order = tile(&blocks, &(0..first.section.orbits))?;
        let mut section = SectionDocument {
            columns: BTreeMap::new(),
            ..first.section.clone()
        };
        for k in order {
            for (name, values) in &parts[k].section.columns {
                section
                    .columns
                    .entry(name.clone())
                    .or_default()
                    .extend_from_slice(values);
            }
        }
        Ok(section)
    }
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

/// One shard of a comparison with Kac's lemma (`spinball kac --shard`,
/// kind `spinball.kac.partial`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct KacPartialDocument {
    /// The shard.
    pub part: KacPart,
}

impl KacPartialDocument {
    /// Join the shards of one run (in any order) into the document one
    /// unsharded run writes, bitwise ([`KacPart::merge`]).
    ///
    /// # Errors
    /// As [`KacPart::merge`].
    pub fn merge(parts: Vec<KacPartialDocument>) -> Result<KacDocument, MergeError> {
        let first = parts.first().ok_or(MergeError::Empty)?;
        let head = PhaseHead {
            version: first.part.version.clone(),
            table: first.part.table.clone(),
            alpha: first.part.alpha,
        };
        let (seed, collisions) = (first.part.seed, first.part.collisions);
        let comparison = KacPart::merge(parts.into_iter().map(|d| d.part).collect())?;
        Ok(KacDocument {
            head,
            seed,
            collisions,
            ratio: comparison.ratio(),
            comparison,
        })
    }
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
