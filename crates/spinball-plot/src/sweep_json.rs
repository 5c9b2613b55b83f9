//! The JSON document of the `sweep` example (the machine interface): the
//! settings and one point per α, rewritten after every point so that a long
//! sweep leaves its finished points behind.
//!
//! Scripts read this format, so it is a fixed, typed record
//! ([`SweepDocument`], [`SweepPoint`]) serialised with serde:
//!
//! ```json
//! {"table": "stadium:a=1", "method": "fd", "sampler": "paper", "seed": 1,
//!  "delta0": 1e-7, "threshold": 0.01, "version": "0.1.0",
//!  "points": [{"alpha": 0.5, "mean": 0.18, "sem": 0.002, "median": 0.2,
//!              "chaotic_fraction": 0.9, "n_ics": 1000, "n_collisions": 10000,
//!              "wall_time_s": 1.1, "std": 0.05, "conditional_mean": 0.2,
//!              "collision_rate": 1.2, "stop": "completed",
//!              "error_budget": {"sem": 0.002, "finite_time_bias": 1e-4, "regime": "1/T",
//!                               "method_bias": 2e-5, "total": 0.0021, ...}}]}
//! ```
//!
//! `n_collisions` is the number of collisions per initial condition,
//! `wall_time_s` the time spent on that point; exponents are per unit time.

use std::path::{Path, PathBuf};

use serde::Serialize;
use spinball_analysis::estimators::{CHAOS_THRESHOLD, Method};
use spinball_analysis::report::BudgetRow;
use spinball_analysis::run::LyapunovEstimate;

use crate::cli::SweepArgs;
use crate::error::PlotError;

/// One α of a sweep.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SweepPoint {
    /// Spin parameter.
    pub alpha: f64,
    /// Mean FTLE λ.
    pub mean: f64,
    /// Its standard error.
    pub sem: f64,
    /// Median FTLE.
    pub median: f64,
    /// Share of trajectories with FTLE above the threshold.
    pub chaotic_fraction: f64,
    /// Initial conditions.
    pub n_ics: u64,
    /// Collisions per initial condition.
    pub n_collisions: u64,
    /// Wall-clock seconds for this point.
    pub wall_time_s: f64,
    /// Standard deviation of the FTLEs.
    pub std: f64,
    /// Mean FTLE of the chaotic trajectories.
    pub conditional_mean: Option<f64>,
    /// Collisions per unit time over the ensemble.
    pub collision_rate: f64,
    /// Why the point stopped.
    pub stop: String,
    /// The point's error budget (SEM, finite-time and method bias, total),
    /// if it was measured.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error_budget: Option<BudgetRow>,
}

impl From<&LyapunovEstimate> for SweepPoint {
    fn from(e: &LyapunovEstimate) -> Self {
        SweepPoint {
            alpha: e.alpha,
            mean: e.mean,
            sem: e.sem,
            median: e.median,
            chaotic_fraction: e.chaotic_fraction,
            n_ics: e.n_ics,
            n_collisions: e.collisions_per_ic,
            wall_time_s: e.wall_time_s,
            std: e.std,
            conditional_mean: e.conditional_mean,
            collision_rate: e.collision_rate,
            stop: e.stop.name().to_string(),
            error_budget: None,
        }
    }
}

/// The whole document: settings and the points so far.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SweepDocument {
    /// Table spec.
    pub table: String,
    /// `fd` or `tangent`.
    pub method: String,
    /// `paper` or `microcanonical`.
    pub sampler: String,
    /// Seed of the initial conditions.
    pub seed: u64,
    /// Initial separation of the finite-difference method (`None`: tangent).
    pub delta0: Option<f64>,
    /// Chaos threshold of `chaotic_fraction`.
    pub threshold: f64,
    /// Crate version.
    pub version: String,
    /// One point per finished α.
    pub points: Vec<SweepPoint>,
    #[serde(skip)]
    path: PathBuf,
}

impl SweepDocument {
    /// An empty document for `args`, written to `args.json` at once (so an
    /// unwritable path fails before any computing).
    ///
    /// # Errors
    /// [`PlotError::Io`] if the file cannot be written.
    pub fn create(args: &SweepArgs) -> Result<Self, PlotError> {
        let doc = SweepDocument {
            table: args.table.to_string(),
            method: args.method.name().to_string(),
            sampler: args.sampler.name().to_string(),
            seed: args.seed,
            delta0: match args.method {
                Method::FiniteDifference { delta0 } => Some(delta0),
                Method::Tangent => None,
            },
            threshold: CHAOS_THRESHOLD,
            version: env!("CARGO_PKG_VERSION").to_string(),
            points: Vec::new(),
            path: args.json.clone(),
        };
        doc.write()?;
        Ok(doc)
    }

    /// Add the point of `estimate` and rewrite the file.
    ///
    /// # Errors
    /// [`PlotError::Io`] if the file cannot be written.
    pub fn push(&mut self, estimate: &LyapunovEstimate) -> Result<(), PlotError> {
        self.points.push(SweepPoint::from(estimate));
        self.write()
    }

    /// Add the point of `estimate` with its error budget and rewrite the
    /// file.
    ///
    /// # Errors
    /// [`PlotError::Io`] if the file cannot be written.
    pub fn push_with_budget(
        &mut self,
        estimate: &LyapunovEstimate,
        budget: BudgetRow,
    ) -> Result<(), PlotError> {
        self.points.push(SweepPoint {
            error_budget: Some(budget),
            ..SweepPoint::from(estimate)
        });
        self.write()
    }

    /// Where the document is written.
    pub fn path(&self) -> &Path {
        &self.path
    }

    fn write(&self) -> Result<(), PlotError> {
        let text = serde_json::to_string_pretty(self).map_err(|source| PlotError::Json {
            path: self.path.clone(),
            source,
        })?;
        std::fs::write(&self.path, text + "\n").map_err(|source| PlotError::Io {
            path: self.path.clone(),
            source,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cli::Parsed;

    #[test]
    fn document_is_rewritten_after_every_point() {
        let path = std::env::temp_dir().join(format!("spinball-sweep-{}.json", std::process::id()));
        let line = format!(
            "--table stadium:a=1 --alphas 0.5 --ics 4 --collisions 300 --method fd --seed 2 --json {}",
            path.display()
        );
        let Parsed::Run(args) = SweepArgs::try_parse_from(line.split(' ')).unwrap() else {
            panic!("help")
        };
        let mut doc = SweepDocument::create(&args).unwrap();
        let read = || -> serde_json::Value {
            serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap()
        };
        let empty = read();
        assert_eq!(empty["table"], "stadium:a=1");
        assert_eq!(
            (empty["method"].as_str(), empty["delta0"].as_f64()),
            (Some("fd"), Some(1e-7))
        );
        assert_eq!(empty["seed"], 2);
        assert_eq!(empty["points"].as_array().unwrap().len(), 0);
        let e = args.ensemble(args.laws[0]).run().unwrap();
        doc.push(&e).unwrap();
        let one = read();
        let p = &one["points"][0];
        assert_eq!(
            (p["alpha"].as_f64(), p["mean"].as_f64()),
            (Some(0.5), Some(e.mean))
        );
        assert_eq!(
            (p["n_ics"].as_u64(), p["n_collisions"].as_u64()),
            (Some(4), Some(300))
        );
        assert!(one.get("path").is_none());
        std::fs::remove_file(&path).unwrap();
        let bad = SweepArgs {
            json: PathBuf::from("/nonexistent/dir/s.json"),
            ..args
        };
        assert!(matches!(
            SweepDocument::create(&bad),
            Err(PlotError::Io { .. })
        ));
    }
}
