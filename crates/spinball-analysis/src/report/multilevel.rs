//! The document of a multilevel λ run (`spinball lyapunov` or `sweep` with
//! `--estimator multilevel`): one estimate per α, each with its levels,
//! so the error budget can be read back without rerunning; and the shards
//! of a multilevel campaign, which merge into it.
//!
//! Documented in the group docs (`report/mod.rs`), section "Documents".

use serde::{Deserialize, Serialize};

use crate::precision::{LevelShard, MultilevelEstimate};
use crate::run::{MergeError, Provenance};

/// One α of a multilevel run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MultilevelPoint {
    /// α.
    pub alpha: f64,
    /// The estimate.
    pub estimate: MultilevelEstimate,
}

/// A multilevel run (kind `spinball.multilevel`): `estimator` is
/// `"multilevel"`, then one point per α.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MultilevelDocument {
    /// The estimator, `"multilevel"`.
    pub estimator: String,
    /// One point per α, in the order run.
    pub points: Vec<MultilevelPoint>,
}

impl MultilevelDocument {
    /// The document of `points`.
    #[must_use]
    pub fn new(points: Vec<MultilevelPoint>) -> Self {
        MultilevelDocument {
            estimator: "multilevel".into(),
            points,
        }
    }
}

/// One α of a shard of a multilevel campaign: the shard's block of every
/// level of the allocation planned for that α.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MultilevelShardPoint {
    /// α.
    pub alpha: f64,
    /// The run the shard belongs to (table, α, method, seed, sampler…).
    pub provenance: Provenance,
    /// The shard's draws.
    pub shard: LevelShard,
}

/// A shard of a multilevel campaign (kind `spinball.multilevel.partial`):
/// one [`MultilevelShardPoint`] per α, in the order run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MultilevelPartialDocument {
    /// One point per α.
    pub points: Vec<MultilevelShardPoint>,
}

impl MultilevelPartialDocument {
    /// Join the shards of one campaign (in any order) into the document one
    /// process running each α's allocation whole writes: bitwise the same
    /// estimates, except the levels' wall times (summed over the shards).
    ///
    /// # Errors
    /// [`MergeError::Empty`] for no shards; [`MergeError::DifferentRuns`]
    /// for shards with different numbers of α or of different runs (the
    /// first field that differs); [`MergeError::Estimate`] for shards of
    /// different allocations, a shard missing or given twice.
    pub fn merge(parts: &[MultilevelPartialDocument]) -> Result<MultilevelDocument, MergeError> {
        let first = parts.first().ok_or(MergeError::Empty)?;
        for p in &parts[1..] {
            if p.points.len() != first.points.len() {
                return Err(MergeError::DifferentRuns {
                    what: "number of alpha values",
                    first: first.points.len().to_string(),
                    other: p.points.len().to_string(),
                });
            }
            for (a, b) in first.points.iter().zip(&p.points) {
                a.provenance.difference(&b.provenance)?;
            }
        }
        let points = (0..first.points.len())
            .map(|k| {
                let shards: Vec<LevelShard> =
                    parts.iter().map(|d| d.points[k].shard.clone()).collect();
                Ok(MultilevelPoint {
                    alpha: first.points[k].alpha,
                    estimate: LevelShard::merge(&shards)?,
                })
            })
            .collect::<Result<Vec<_>, MergeError>>()?;
        Ok(MultilevelDocument::new(points))
    }
}
