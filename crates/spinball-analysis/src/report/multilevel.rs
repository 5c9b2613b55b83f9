//! The document of a multilevel λ run (`spinball lyapunov` or `sweep` with
//! `--estimator multilevel`): one estimate per α, each with its levels,
//! so the error budget can be read back without rerunning.
//!
//! Documented in the group docs (`report/mod.rs`), section "Documents".

use serde::{Deserialize, Serialize};

use crate::precision::MultilevelEstimate;

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
