//! The sweep document: the settings of `spinball sweep` and one point
//! per α, rewritten after every point so that a long sweep leaves its
//! finished points behind.
//!
//! Documented in the group docs (`report/mod.rs`), section "Documents".

use std::fmt::Display;

use spinball_core::Sampler;

use super::names::MethodName;
use super::rows::BudgetRow;
use crate::estimators::{CHAOS_THRESHOLD, Method};
use crate::run::{LyapunovEstimate, StopReason};

/// One α of a sweep. Serialisable with the `serde` feature.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
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
    pub stop: StopReason,
    /// The point's error budget (SEM, finite-time and method bias, total),
    /// if it was measured.
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
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
            stop: e.stop,
            error_budget: None,
        }
    }
}

/// The whole document: settings and the points so far. Serialisable with
/// the `serde` feature.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct SweepDocument {
    /// Table spec.
    pub table: String,
    /// `fd` or `tangent`.
    pub method: MethodName,
    /// `paper` or `microcanonical`.
    pub sampler: Sampler,
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
}

impl SweepDocument {
    /// An empty document: a sweep on `table` (its spec) by `method`, from
    /// `sampler`'s initial conditions of `seed`.
    #[must_use]
    pub fn new(table: &impl Display, method: Method, sampler: Sampler, seed: u64) -> Self {
        SweepDocument {
            table: table.to_string(),
            method: method.into(),
            sampler,
            seed,
            delta0: match method {
                Method::FiniteDifference { delta0 } => Some(delta0),
                Method::Tangent => None,
            },
            threshold: CHAOS_THRESHOLD,
            version: env!("CARGO_PKG_VERSION").to_string(),
            points: Vec::new(),
        }
    }

    /// Add the point of `estimate`.
    pub fn push(&mut self, estimate: &LyapunovEstimate) {
        self.points.push(SweepPoint::from(estimate));
    }

    /// Add the point of `estimate` with its error budget.
    pub fn push_with_budget(&mut self, estimate: &LyapunovEstimate, budget: BudgetRow) {
        self.points.push(SweepPoint {
            error_budget: Some(budget),
            ..SweepPoint::from(estimate)
        });
    }
}

#[cfg(all(test, feature = "serde"))]
mod tests {
    use spinball_core::SpinLaw;
    use spinball_geometry::Table;

    use super::*;
    use crate::run::Ensemble;

    #[test]
    fn document_has_the_settings_and_a_field_per_point() {
        let table: Table = "stadium:a=1".parse().unwrap();
        let mut doc = SweepDocument::new(&table, Method::default(), Sampler::Paper, 2);
        let empty = serde_json::to_value(&doc).unwrap();
        assert_eq!(empty["table"], "stadium:a=1");
        assert_eq!(
            (empty["method"].as_str(), empty["delta0"].as_f64()),
            (Some("fd"), Some(1e-7))
        );
        assert_eq!(
            (empty["sampler"].as_str(), empty["seed"].as_u64()),
            (Some("paper"), Some(2))
        );
        assert_eq!(empty["points"].as_array().unwrap().len(), 0);
        let e = Ensemble::new(table, SpinLaw::new(0.5).unwrap())
            .with_seed(2)
            .with_ics(4)
            .with_collisions(300)
            .run()
            .unwrap();
        doc.push(&e);
        let one = serde_json::to_value(&doc).unwrap();
        let p = &one["points"][0];
        assert_eq!(
            (p["alpha"].as_f64(), p["mean"].as_f64()),
            (Some(0.5), Some(e.mean))
        );
        assert_eq!(
            (p["n_ics"].as_u64(), p["n_collisions"].as_u64()),
            (Some(4), Some(300))
        );
        assert!(p.get("error_budget").is_none());
        let tangent = SweepDocument::new(&table, Method::Tangent, Sampler::Microcanonical, 0);
        let t = serde_json::to_value(&tangent).unwrap();
        assert!(t["delta0"].is_null());
        assert_eq!(t["sampler"], "microcanonical");
    }
}
