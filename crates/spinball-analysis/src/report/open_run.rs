//! What every escape and diffusion document starts with (who wrote it, the
//! table, α, the starts, the initial conditions of the whole run), and the
//! run itself: an open-table ensemble cut into blocks so that a front can
//! show progress, each block's records the same bits as one run's.
//!
//! Documented in the group docs (`report/mod.rs`), sections "Documents"
//! and "Merging".

use std::ops::Range;

use serde::{Deserialize, Serialize};
use spinball_core::{Billiard, Sampler};
use spinball_geometry::Boundary;

use super::names::IcSource;
use crate::error::AnalysisError;
use crate::open::OpenEnsemble;
use crate::run::{MergeError, RunDifference, Shard, TableRecord, Threads, tile};

/// The head of an escape or diffusion document: the run it is (or is a
/// shard of).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct OpenRunHead {
    /// The version of spinball that wrote it.
    pub version: String,
    /// The table, as data.
    pub table: TableRecord,
    /// Spin parameter α.
    pub alpha: f64,
    /// Where the starts come from.
    pub sampler: IcSource,
    /// The seed of the per-IC streams.
    pub seed: u64,
    /// The initial conditions of the whole run (all shards).
    pub ics: Range<u64>,
}

impl OpenRunHead {
    /// Whether `other` is the head of the same run: the first field that
    /// differs (table by its geometry, version, α, sampler, seed, initial
    /// conditions; numbers bit for bit).
    ///
    /// # Errors
    /// [`MergeError::DifferentRuns`] naming the field and both values;
    /// [`MergeError::Table`] for a table without a shape.
    pub fn same_run(&self, other: &OpenRunHead) -> Result<(), MergeError> {
        self.table.same_table(&other.table)?;
        differ(&[
            ("version", self.version.clone(), other.version.clone()),
            (
                "alpha",
                format!("{:?}", self.alpha),
                format!("{:?}", other.alpha),
            ),
            (
                "sampler",
                self.sampler.to_string(),
                other.sampler.to_string(),
            ),
            ("seed", self.seed.to_string(), other.seed.to_string()),
            (
                "initial conditions",
                format!("{:?}", self.ics),
                format!("{:?}", other.ics),
            ),
        ])
    }
}

/// The first of `fields` (name, value in one, value in the other) whose
/// values differ, as a refusal.
///
/// # Errors
/// [`MergeError::DifferentRuns`] for that field.
pub(super) fn differ(fields: &[(&'static str, String, String)]) -> Result<(), MergeError> {
    match fields.iter().find(|(_, x, y)| x != y) {
        Some((what, first, other)) => Err(RunDifference::Field {
            what,
            first: first.clone(),
            other: other.clone(),
        }
        .into()),
        None => Ok(()),
    }
}

/// A shard of an escape or diffusion run, as merging sees it.
pub(super) trait OpenPart {
    /// One initial condition's record.
    type Record: Clone;
    /// The run's head.
    fn head(&self) -> &OpenRunHead;
    /// Whether `other` is a shard of the same run.
    fn same_run(&self, other: &Self) -> Result<(), MergeError>;
    /// The shard's initial conditions and their records.
    fn block(&self) -> (&Range<u64>, &[Self::Record]);
}

/// The first of `parts` (shards of one run, in any order) and the records
/// of all of them in index order.
///
/// # Errors
/// [`MergeError`]: no parts, parts of different runs, blocks that overlap
/// or leave initial conditions out.
pub(super) fn joined<P: OpenPart>(parts: &[P]) -> Result<(&P, Vec<P::Record>), MergeError> {
    let first = parts.first().ok_or(MergeError::Empty)?;
    for p in &parts[1..] {
        first.same_run(p)?;
    }
    let blocks: Vec<Range<u64>> = parts.iter().map(|p| p.block().0.clone()).collect();
    let order = tile(&blocks, &first.head().ics)?;
    let records = order
        .iter()
        .flat_map(|&k| parts[k].block().1.iter().cloned())
        .collect();
    Ok((first, records))
}

/// A whole run's document from the merge of its one part: the summary's
/// error as it is, anything else (which one part cannot cause) as an
/// invalid option.
pub(super) fn whole<T>(merged: Result<T, MergeError>) -> Result<T, AnalysisError> {
    merged.map_err(|e| match e {
        MergeError::Estimate(e) => e,
        e => AnalysisError::invalid("records", e.to_string()),
    })
}

/// An ensemble on an open or periodic table, as the fronts run it: the
/// billiard, starts drawn by `sampler` from the streams of `seed`, the
/// initial conditions `ics` of the whole run, on `threads`.
#[derive(Debug, Clone)]
pub struct OpenRun<B> {
    /// Table and spin law.
    pub billiard: Billiard<B>,
    /// How the starts are drawn.
    pub sampler: Sampler,
    /// The seed of the per-IC streams.
    pub seed: u64,
    /// The initial conditions of the whole run.
    pub ics: Range<u64>,
    /// Worker threads (results do not depend on them).
    pub threads: Threads,
}

impl<B: Boundary + Sync + Clone> OpenRun<B> {
    /// The head of this run's documents.
    #[must_use]
    pub fn head(&self) -> OpenRunHead {
        OpenRunHead {
            version: env!("CARGO_PKG_VERSION").into(),
            table: TableRecord::of(self.billiard.table()),
            alpha: self.billiard.law().alpha(),
            sampler: IcSource::from(self.sampler),
            seed: self.seed,
            ics: self.ics.clone(),
        }
    }

    /// Run `shard`'s block of the initial conditions through `f`, a block
    /// of about a twentieth at a time, calling `progress(done, of)` after
    /// each; the records in index order, the same bits as one call of `f`
    /// on the whole block (each initial condition owns its stream).
    ///
    /// # Errors
    /// `f`'s, for the lowest failing block.
    pub(super) fn in_blocks<T>(
        &self,
        shard: Shard,
        progress: &mut dyn FnMut(u64, u64),
        f: impl Fn(&OpenEnsemble<B>) -> Result<Vec<T>, AnalysisError>,
    ) -> Result<(Range<u64>, Vec<T>), AnalysisError> {
        let indices = shard.range(self.ics.clone());
        if indices.is_empty() {
            return Err(AnalysisError::invalid(
                "ics",
                format!(
                    "shard {shard} of {:?} holds no initial condition: use fewer shards than initial conditions",
                    self.ics
                ),
            ));
        }
        let n = indices.end - indices.start;
        let size = (n / 20).max(64);
        let mut out = Vec::with_capacity(usize::try_from(n).unwrap_or(0));
        let mut start = indices.start;
        progress(0, n);
        while start < indices.end {
            let end = (start + size).min(indices.end);
            let ensemble = OpenEnsemble::new(self.billiard.clone())
                .with_starts(self.sampler)
                .with_seed(self.seed)
                .with_indices(start..end)
                .with_threads(self.threads);
            out.extend(f(&ensemble)?);
            progress(end - indices.start, n);
            start = end;
        }
        Ok((indices, out))
    }
}
