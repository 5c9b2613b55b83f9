//! The documents of an escape run: one shard's records
//! (`spinball.escape.partial`) and the finished run with its summary
//! (`spinball.escape`), and the one way to join the shards.
//!
//! Documented in the group docs (`report/mod.rs`), sections "Documents"
//! and "Merging".

use std::ops::Range;

use serde::{Deserialize, Serialize};
use spinball_geometry::Boundary;

use super::open_run::{OpenPart, OpenRun, OpenRunHead, differ, joined, whole};
use crate::error::AnalysisError;
use crate::escape::{EscapeError, EscapeOptions, EscapeSummary, KacPrediction};
use crate::open::{Budget, EscapeRecord};
use crate::run::{MergeError, Shard};

/// A [`Budget`] as a document writes it: `null` for no limit (JSON has no
/// infinity).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct BudgetRecord {
    /// Most collisions, if limited.
    pub collisions: Option<u64>,
    /// Longest time, if limited.
    pub time: Option<f64>,
}

impl From<Budget> for BudgetRecord {
    fn from(b: Budget) -> Self {
        BudgetRecord {
            collisions: (b.collisions != u64::MAX).then_some(b.collisions),
            time: b.time.is_finite().then_some(b.time),
        }
    }
}

impl From<BudgetRecord> for Budget {
    fn from(b: BudgetRecord) -> Self {
        Budget {
            collisions: b.collisions.unwrap_or(u64::MAX),
            time: b.time.unwrap_or(f64::INFINITY),
        }
    }
}

/// One shard of an escape run (kind `spinball.escape.partial`): the
/// records of its block of initial conditions.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EscapePartialDocument {
    /// Which shard this is.
    pub shard: Shard,
    /// The run.
    #[serde(flatten)]
    pub head: OpenRunHead,
    /// When a ball still inside counts as censored.
    pub budget: BudgetRecord,
    /// The windows of the summary.
    pub options: EscapeOptions,
    /// Kac's prediction for the table, if it has one.
    pub kac: Option<KacPrediction>,
    /// The initial conditions of this shard.
    pub indices: Range<u64>,
    /// One record per initial condition, in index order.
    pub records: Vec<EscapeRecord>,
}

/// A finished escape run (kind `spinball.escape`): the summary and every
/// ball's record.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EscapeDocument {
    /// The run.
    #[serde(flatten)]
    pub head: OpenRunHead,
    /// When a ball still inside counts as censored.
    pub budget: BudgetRecord,
    /// The summary of the records (boxed: it is large, and a document is
    /// moved around whole).
    pub summary: Box<EscapeSummary>,
    /// One record per initial condition, in index order.
    pub records: Vec<EscapeRecord>,
}

impl OpenPart for EscapePartialDocument {
    type Record = EscapeRecord;
    fn head(&self) -> &OpenRunHead {
        &self.head
    }
    fn same_run(&self, other: &Self) -> Result<(), MergeError> {
        EscapePartialDocument::same_run(self, other)
    }
    fn block(&self) -> (&Range<u64>, &[EscapeRecord]) {
        (&self.indices, &self.records)
    }
}

impl EscapePartialDocument {
    /// Run `shard` of an escape run: every initial condition of its block
    /// until it escapes or `budget` runs out, `progress(done, of)` after
    /// each block of them.
    ///
    /// # Errors
    /// [`EscapeError::NoHole`] for a table without a hole (as
    /// [`AnalysisError::Escape`]); the [`OpenEnsemble::escape_times`](crate::open::OpenEnsemble::escape_times)
    /// errors.
    pub fn run<B: Boundary + Sync + Clone>(
        run: &OpenRun<B>,
        shard: Shard,
        budget: Budget,
        options: EscapeOptions,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<Self, AnalysisError> {
        let table = run.billiard.table();
        if !table.has_holes() {
            return Err(EscapeError::NoHole.into());
        }
        budget.validate()?;
        let kac = KacPrediction::for_open_table(table, run.billiard.law().alpha())?;
        let (indices, records) = run.in_blocks(shard, progress, |e| e.escape_times(budget))?;
        Ok(EscapePartialDocument {
            shard,
            head: run.head(),
            budget: budget.into(),
            options,
            kac,
            indices,
            records,
        })
    }

    /// Whether `other` is a shard of the same run.
    ///
    /// # Errors
    /// [`MergeError::DifferentRuns`] naming the first field that differs;
    /// [`MergeError::Table`] for a table without a shape.
    pub fn same_run(&self, other: &EscapePartialDocument) -> Result<(), MergeError> {
        self.head.same_run(&other.head)?;
        differ(&[
            (
                "budget",
                format!("{:?}", self.budget),
                format!("{:?}", other.budget),
            ),
            (
                "options",
                format!("{:?}", self.options),
                format!("{:?}", other.options),
            ),
            (
                "Kac prediction",
                format!("{:?}", self.kac),
                format!("{:?}", other.kac),
            ),
        ])
    }

    /// Join the shards of one run (in any order) into the document one
    /// unsharded run writes, bitwise: the records in index order, then the
    /// summary of them.
    ///
    /// # Errors
    /// [`MergeError`]: no shards, shards of different runs, blocks that
    /// overlap or leave initial conditions out.
    pub fn merge(parts: Vec<EscapePartialDocument>) -> Result<EscapeDocument, MergeError> {
        let (first, records) = joined(&parts)?;
        let summary =
            EscapeSummary::new(&records, first.kac, first.options).map_err(AnalysisError::from)?;
        Ok(EscapeDocument {
            head: first.head.clone(),
            budget: first.budget,
            summary: Box::new(summary),
            records,
        })
    }
}

/// The CSV columns of an escape document, one row per ball.
pub const ESCAPE_CSV_COLUMNS: &str = "index,time,collisions,censored,wall,x,y,s,v_par,spin";

impl EscapeDocument {
    /// The whole run: [`EscapePartialDocument::run`] as one shard, merged.
    ///
    /// # Errors
    /// As [`EscapePartialDocument::run`].
    pub fn run<B: Boundary + Sync + Clone>(
        run: &OpenRun<B>,
        budget: Budget,
        options: EscapeOptions,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<Self, AnalysisError> {
        let part = EscapePartialDocument::run(run, Shard::WHOLE, budget, options, progress)?;
        whole(EscapePartialDocument::merge(vec![part]))
    }

    /// One row per ball: [`ESCAPE_CSV_COLUMNS`]; `censored` is 1 or 0,
    /// the exit's fields (hole wall, point, Birkhoff `s`, `v∥`, spin) are
    /// empty for a censored ball. Numbers in their shortest round-trip
    /// form.
    #[must_use]
    pub fn csv(&self) -> String {
        let mut out = format!("{ESCAPE_CSV_COLUMNS}\n");
        for r in &self.records {
            let exit = r.exit.map_or_else(
                || ",,,,,".to_string(),
                |e| {
                    format!(
                        "{},{},{},{},{},{}",
                        e.wall, e.point.x, e.point.y, e.s, e.v_par, e.spin
                    )
                },
            );
            out.push_str(&format!(
                "{},{},{},{},{exit}\n",
                r.index,
                r.time,
                r.collisions,
                u8::from(r.censored)
            ));
        }
        out
    }

    /// The same columns as a float64 array of shape `(balls, 10)`,
    /// row-major (NaN for a censored ball's exit): the shape and the
    /// values.
    #[must_use]
    pub fn array(&self) -> (Vec<u64>, Vec<f64>) {
        let values = self
            .records
            .iter()
            .flat_map(|r| {
                let e = r.exit.map_or([f64::NAN; 6], |e| {
                    [
                        f64::from(e.wall),
                        e.point.x,
                        e.point.y,
                        e.s,
                        e.v_par,
                        e.spin,
                    ]
                });
                [
                    r.index as f64,
                    r.time,
                    r.collisions as f64,
                    f64::from(u8::from(r.censored)),
                ]
                .into_iter()
                .chain(e)
            })
            .collect();
        (vec![self.records.len() as u64, 10], values)
    }
}
