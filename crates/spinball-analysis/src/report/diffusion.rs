//! The documents of a diffusion run: one shard's displacements
//! (`spinball.diffusion.partial`) and the finished run with its summary
//! (`spinball.diffusion`), and the one way to join the shards.
//!
//! Documented in the group docs (`report/mod.rs`), sections "Documents"
//! and "Merging".

use std::ops::Range;

use serde::{Deserialize, Serialize};
use spinball_geometry::Boundary;

use super::open_run::{OpenPart, OpenRun, OpenRunHead, differ, joined, whole};
use crate::error::AnalysisError;
use crate::open::DisplacementRecord;
use crate::run::{MergeError, Shard};
use crate::transport::{DiffusionSummary, FitWindow, Horizon, horizon_of};

/// One shard of a diffusion run (kind `spinball.diffusion.partial`): the
/// displacements of its block of initial conditions.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DiffusionPartialDocument {
    /// Which shard this is.
    pub shard: Shard,
    /// The run.
    #[serde(flatten)]
    pub head: OpenRunHead,
    /// The checkpoint times.
    pub times: Vec<f64>,
    /// The table's horizon.
    pub horizon: Horizon,
    /// The fit window asked for (`null`: the later half).
    pub window: Option<FitWindow>,
    /// The initial conditions of this shard.
    pub indices: Range<u64>,
    /// One record per initial condition, in index order.
    pub records: Vec<DisplacementRecord>,
}

/// A finished diffusion run (kind `spinball.diffusion`): the summary and
/// every initial condition's displacements.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DiffusionDocument {
    /// The run.
    #[serde(flatten)]
    pub head: OpenRunHead,
    /// The checkpoint times.
    pub times: Vec<f64>,
    /// The fit window asked for (`null`: the later half).
    pub window: Option<FitWindow>,
    /// The summary (horizon, `⟨Δr²⟩`, `D` or `D_m`, the window scan).
    pub summary: DiffusionSummary,
    /// One record per initial condition, in index order.
    pub records: Vec<DisplacementRecord>,
}

impl OpenPart for DiffusionPartialDocument {
    type Record = DisplacementRecord;
    fn head(&self) -> &OpenRunHead {
        &self.head
    }
    fn same_run(&self, other: &Self) -> Result<(), MergeError> {
        DiffusionPartialDocument::same_run(self, other)
    }
    fn block(&self) -> (&Range<u64>, &[DisplacementRecord]) {
        (&self.indices, &self.records)
    }
}

impl DiffusionPartialDocument {
    /// Run `shard` of a diffusion run: the unwrapped displacement of every
    /// initial condition of its block at `times`, `progress(done, of)`
    /// after each block of them.
    ///
    /// # Errors
    /// [`TransportError::NotPeriodic`](crate::transport::TransportError::NotPeriodic)
    /// and [`TransportError::UnknownHorizon`](crate::transport::TransportError::UnknownHorizon)
    /// (as [`AnalysisError::Transport`]) before anything runs; the
    /// [`OpenEnsemble::displacements`](crate::open::OpenEnsemble::displacements)
    /// errors (times, a table with holes).
    pub fn run<B: Boundary + Sync + Clone>(
        run: &OpenRun<B>,
        shard: Shard,
        times: &[f64],
        window: Option<FitWindow>,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<Self, AnalysisError> {
        let horizon = horizon_of(run.billiard.table())?;
        let (indices, records) = run.in_blocks(shard, progress, |e| e.displacements(times))?;
        Ok(DiffusionPartialDocument {
            shard,
            head: run.head(),
            times: times.to_vec(),
            horizon,
            window,
            indices,
            records,
        })
    }

    /// Whether `other` is a shard of the same run.
    ///
    /// # Errors
    /// [`MergeError::DifferentRuns`] naming the first field that differs;
    /// [`MergeError::Table`] for a table without a shape.
    pub fn same_run(&self, other: &DiffusionPartialDocument) -> Result<(), MergeError> {
        self.head.same_run(&other.head)?;
        differ(&[
            (
                "checkpoint times",
                format!("{:?}", self.times),
                format!("{:?}", other.times),
            ),
            (
                "horizon",
                self.horizon.to_string(),
                other.horizon.to_string(),
            ),
            (
                "fit window",
                format!("{:?}", self.window),
                format!("{:?}", other.window),
            ),
        ])
    }

    /// Join the shards of one run (in any order) into the document one
    /// unsharded run writes, bitwise: the records in index order, then the
    /// summary of them.
    ///
    /// # Errors
    /// [`MergeError`]: no shards, shards of different runs, blocks that
    /// overlap or leave initial conditions out; [`MergeError::Estimate`]
    /// for a run of fewer than two initial conditions.
    pub fn merge(parts: Vec<DiffusionPartialDocument>) -> Result<DiffusionDocument, MergeError> {
        let (first, records) = joined(&parts)?;
        let summary = DiffusionSummary::new(&first.times, &records, first.horizon, first.window)
            .map_err(AnalysisError::from)?;
        Ok(DiffusionDocument {
            head: first.head.clone(),
            times: first.times.clone(),
            window: first.window,
            summary,
            records,
        })
    }
}

/// The CSV columns of a diffusion document, one row per initial condition
/// and checkpoint.
pub const DIFFUSION_CSV_COLUMNS: &str = "index,t,dx,dy";

impl DiffusionDocument {
    /// The whole run: [`DiffusionPartialDocument::run`] as one shard,
    /// merged.
    ///
    /// # Errors
    /// As [`DiffusionPartialDocument::run`], and
    /// [`AnalysisError::Transport`] for fewer than two initial conditions.
    pub fn run<B: Boundary + Sync + Clone>(
        run: &OpenRun<B>,
        times: &[f64],
        window: Option<FitWindow>,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<Self, AnalysisError> {
        let part = DiffusionPartialDocument::run(run, Shard::WHOLE, times, window, progress)?;
        whole(DiffusionPartialDocument::merge(vec![part]))
    }

    /// One row per initial condition and checkpoint:
    /// [`DIFFUSION_CSV_COLUMNS`], the unwrapped displacement `(Δx, Δy)`.
    #[must_use]
    pub fn csv(&self) -> String {
        let mut out = format!("{DIFFUSION_CSV_COLUMNS}\n");
        for r in &self.records {
            for (t, d) in self.times.iter().zip(&r.displacement) {
                out.push_str(&format!("{},{t},{},{}\n", r.index, d.x, d.y));
            }
        }
        out
    }

    /// The displacements as a float64 array of shape `(ICs, checkpoints,
    /// 2)`, row-major: the shape and the values.
    #[must_use]
    pub fn array(&self) -> (Vec<u64>, Vec<f64>) {
        let values = self
            .records
            .iter()
            .flat_map(|r| r.displacement.iter().flat_map(|d| [d.x, d.y]))
            .collect();
        (
            vec![self.records.len() as u64, self.times.len() as u64, 2],
            values,
        )
    }
}
