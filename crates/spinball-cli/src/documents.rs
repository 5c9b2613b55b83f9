//! What the ensemble commands write: a finished result, or a partial one
//! (a shard, or a checkpoint of an interrupted run) that `spinball merge`
//! and `--resume` read back.

use std::fs;
use std::ops::Range;
use std::path::Path;

use serde::{Deserialize, Serialize};
use spinball_analysis::run::{LyapunovEstimate, PartialRun, Shard};

use crate::error::CliError;
use crate::files::write_atomic;

/// The `kind` of a finished Lyapunov result.
pub const RESULT_KIND: &str = "spinball.lyapunov";
/// The `kind` of a partial result.
pub const PARTIAL_KIND: &str = "spinball.lyapunov.partial";

/// A finished run: one estimate per α, each with its provenance and its
/// per-initial-condition values.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ResultDocument {
    /// Always [`RESULT_KIND`].
    pub kind: String,
    /// One estimate per α, in the order asked.
    pub points: Vec<LyapunovEstimate>,
}

/// A piece of a run: a shard's share of every α, or what an interrupted
/// run finished.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PartialDocument {
    /// Always [`PARTIAL_KIND`].
    pub kind: String,
    /// Which shard this is.
    pub shard: Shard,
    /// The initial conditions of the whole run (all shards).
    pub total: Range<u64>,
    /// One partial run per α, in the order asked (those not started yet
    /// are absent).
    pub points: Vec<PartialRun>,
}

impl ResultDocument {
    /// A result of `points`.
    pub fn new(points: Vec<LyapunovEstimate>) -> Self {
        ResultDocument {
            kind: RESULT_KIND.into(),
            points,
        }
    }
}

impl PartialDocument {
    /// An empty partial result of `shard` of `total`.
    pub fn new(shard: Shard, total: Range<u64>) -> Self {
        PartialDocument {
            kind: PARTIAL_KIND.into(),
            shard,
            total,
            points: Vec::new(),
        }
    }

    /// Read a partial result.
    ///
    /// # Errors
    /// [`CliError::Usage`] if the file cannot be read or is not a partial
    /// result.
    pub fn read(path: &Path) -> Result<Self, CliError> {
        let text = fs::read_to_string(path)
            .map_err(|e| CliError::Usage(format!("cannot read {}: {e}", path.display())))?;
        // An edited or damaged file (checksum, count, a non-finite value)
        // is refused here, naming it.
        let doc: PartialDocument = serde_json::from_str(&text).map_err(|e| {
            CliError::Usage(format!(
                "{} is not a valid spinball partial result: {e}",
                path.display()
            ))
        })?;
        if doc.kind != PARTIAL_KIND {
            return Err(CliError::Usage(format!(
                "{} is a `{}`, not a partial result (`{PARTIAL_KIND}`)",
                path.display(),
                doc.kind
            )));
        }
        Ok(doc)
    }
}

/// Write `value` as JSON to `path`, atomically (a temporary file renamed
/// over it), so a kill while writing never leaves a torn file; a path that
/// exists and is not a regular file is refused, never replaced (see
/// [`write_atomic`]).
///
/// # Errors
/// [`CliError::Failed`] if the file cannot be written or `path` is not a
/// regular file.
pub fn write_json<T: Serialize>(path: &Path, value: &T) -> Result<(), CliError> {
    let text = serde_json::to_string(value).map_err(CliError::failed)?;
    write_atomic(path, (text + "\n").as_bytes())
}
