//! Plain or multilevel: which estimator reaches a target total error in
//! less time on this scene, predicted from pilots, with the reason.
//!
//! Documented in the group docs (`precision/mod.rs`), section "Multilevel
//! ensembles".

use std::fmt;

use spinball_geometry::Boundary;

use super::ensemble_levels::{EnsembleLevels, SHORTEST_LEVEL, default_levels};
use super::multilevel::{LevelSamples, Multilevel, giles_allocation};
use super::planner::{PlannedRun, Planner};
use crate::error::AnalysisError;
use crate::estimators::Method;
use crate::run::{Engine, Ensemble};

/// Which estimator a plan uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum EstimatorKind {
    /// One ensemble of `N × T` ([`PlannedRun`]).
    Plain,
    /// Levels of run lengths with their own counts ([`Multilevel`]).
    Multilevel,
}

impl EstimatorKind {
    /// `plain` or `multilevel`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            EstimatorKind::Plain => "plain",
            EstimatorKind::Multilevel => "multilevel",
        }
    }
}

/// A multilevel run planned from a pilot of its levels.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct MultilevelPlan {
    /// The method.
    pub method: Method,
    /// The engine.
    pub engine: Engine,
    /// Run lengths `T_0 < … < T_L` (the top one the plain plan's `T`).
    pub levels: Vec<u64>,
    /// Predicted initial conditions per level (Giles' allocation from the
    /// pilot's variances and costs).
    pub ics: Vec<u64>,
    /// Initial conditions of each level's pilot.
    pub pilot_ics: u64,
    /// The target relative total error.
    pub target_rel: f64,
    /// Predicted work, IC-steps.
    pub predicted_ic_steps: f64,
    /// Predicted wall time at the planner's cost per IC-step.
    pub predicted_wall_s: f64,
}

impl MultilevelPlan {
    /// The levels of `scene` with this plan's method and engine.
    ///
    /// # Errors
    /// As [`EnsembleLevels::new`].
    pub fn source<B: Boundary + Clone + Sync>(
        &self,
        scene: Ensemble<B>,
    ) -> Result<EnsembleLevels<B>, AnalysisError> {
        EnsembleLevels::new(
            scene.with_method(self.method).with_engine(self.engine),
            self.levels.clone(),
        )
    }

    /// The estimator that runs the plan (adaptive: it measures the
    /// variances again and tops up until the target is met).
    #[must_use]
    pub fn estimator(&self) -> Multilevel {
        Multilevel::new(self.target_rel).with_pilot_ics(self.pilot_ics)
    }
}

/// The choice between a plain and a multilevel run for one target.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct EstimatorPlan {
    /// The estimator chosen.
    pub kind: EstimatorKind,
    /// The plain plan ([`Planner::plan`]).
    pub plain: PlannedRun,
    /// The multilevel plan, where the plain run is long enough for four
    /// levels and their pilots cost less than the plain run.
    pub multilevel: Option<MultilevelPlan>,
    /// Why, in one sentence with the predicted times.
    pub reason: String,
}

impl fmt::Display for EstimatorPlan {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.kind.name(), self.reason)
    }
}

/// Multilevel is chosen only if predicted at most this share of the plain
/// run's time: the prediction is an extrapolation of small pilots, and a
/// tie should go to the simpler estimator.
pub const MULTILEVEL_MARGIN: f64 = 0.8;

impl Planner {
    /// The cheaper of a plain and a multilevel run of `scene` for relative
    /// total error `target_rel`, and why. The plain plan is
    /// [`plan`](Self::plan)'s; the multilevel plan tops out at the same
    /// run length (so it has the same bias), with [`default_levels`] below
    /// it,
    /// runs a pilot of `pilot_ics` initial conditions per level and
    /// predicts its work from Giles' allocation for the statistical error
    /// the plain plan's bias leaves. Multilevel wins if predicted at most
    /// [`MULTILEVEL_MARGIN`] of the plain time. Where the level pilots
    /// alone would cost more than that share of the plain run (uniformly
    /// chaotic scenes, whose plain runs are a few dozen initial
    /// conditions), they are not run and plain is chosen: following the
    /// planner then costs what plain costs.
    ///
    /// # Errors
    /// As [`plan`](Self::plan); as [`EnsembleLevels::new`] and the pilot
    /// runs.
    pub fn plan_estimator<B: Boundary + Clone + Sync>(
        &self,
        scene: &Ensemble<B>,
        target_rel: f64,
        pilot_ics: u64,
    ) -> Result<EstimatorPlan, AnalysisError> {
        let plain = self.plan(target_rel)?;
        let Some(levels) = default_levels(plain.collisions) else {
            let reason = format!(
                "the plain run of {} collisions is too short for four levels of at least {SHORTEST_LEVEL} ({})",
                plain.collisions,
                describe_plain(&plain)
            );
            return Ok(EstimatorPlan {
                kind: EstimatorKind::Plain,
                plain,
                multilevel: None,
                reason,
            });
        };
        // A multilevel run costs at least its pilots: where they alone
        // would cost more than the margin of the plain run, do not run them.
        let pilot_work = pilot_ics.max(4) as f64 * levels.iter().sum::<u64>() as f64;
        if pilot_work > MULTILEVEL_MARGIN * plain.predicted_ic_steps as f64 {
            let reason = format!(
                "multilevel cannot pay: its pilots alone ({pilot_work:.3e} IC-steps) would cost more than {MULTILEVEL_MARGIN} of the plain run ({}, {:.3e} IC-steps)",
                describe_plain(&plain),
                plain.predicted_ic_steps as f64
            );
            return Ok(EstimatorPlan {
                kind: EstimatorKind::Plain,
                plain,
                multilevel: None,
                reason,
            });
        }
        let ml = self.plan_multilevel(scene, &plain, levels, pilot_ics)?;
        let ratio = ml.predicted_ic_steps / plain.predicted_ic_steps as f64;
        let (kind, why) = if ratio <= MULTILEVEL_MARGIN {
            (EstimatorKind::Multilevel, "multilevel needs less work")
        } else {
            (
                EstimatorKind::Plain,
                "multilevel does not pay (the spread of the exponents falls with T, or the levels are too few)",
            )
        };
        let reason = format!(
            "{why}: predicted {:.3e} IC-steps ({:.3} s; levels {:?}, ICs {:?}) against plain {} ({:.3} s), ratio {ratio:.2}",
            ml.predicted_ic_steps,
            ml.predicted_wall_s,
            ml.levels,
            ml.ics,
            describe_plain(&plain),
            plain.predicted_wall_s,
        );
        Ok(EstimatorPlan {
            kind,
            plain,
            multilevel: Some(ml),
            reason,
        })
    }

    /// The multilevel run of `scene` with `levels` (topping out at the
    /// `plain` plan's run length) for the statistical error the plain
    /// plan's bias leaves: a pilot of `pilot_ics` per level, then Giles'
    /// allocation from its variances and costs. [`plan_estimator`](Self::plan_estimator)
    /// calls it where the pilots are worth running; a comparison of the two
    /// estimators calls it everywhere.
    ///
    /// # Errors
    /// As [`EnsembleLevels::new`] and the pilot runs.
    pub fn plan_multilevel<B: Boundary + Clone + Sync>(
        &self,
        scene: &Ensemble<B>,
        plain: &PlannedRun,
        levels: Vec<u64>,
        pilot_ics: u64,
    ) -> Result<MultilevelPlan, AnalysisError> {
        let seconds_per_step = self
            .pilots
            .iter()
            .find(|p| p.method == plain.method)
            .map_or(0.0, |p| p.seconds_per_step);
        let pilot_ics = pilot_ics.max(4);
        let source = EnsembleLevels::new(
            scene
                .clone()
                .with_method(plain.method)
                .with_engine(plain.engine),
            levels.clone(),
        )?;
        let stats = (0..levels.len())
            .map(|l| LevelSamples::run(&source, l, 0..pilot_ics).map(|s| s.stats()))
            .collect::<Result<Vec<_>, _>>()?;
        let eps = plain.target_rel * self.lambda().value.abs();
        let eps_s2 = (eps * eps - plain.bias * plain.bias).max(0.1 * eps * eps);
        let variances: Vec<f64> = stats.iter().map(|s| s.variance).collect();
        let costs: Vec<f64> = stats.iter().map(|s| s.cost).collect();
        let ics: Vec<u64> = giles_allocation(&variances, &costs, eps_s2)
            .into_iter()
            .map(|n| (n.ceil() as u64).max(pilot_ics))
            .collect();
        let work: f64 = ics.iter().zip(&costs).map(|(&n, c)| n as f64 * c).sum();
        Ok(MultilevelPlan {
            method: plain.method,
            engine: plain.engine,
            levels,
            ics,
            pilot_ics,
            target_rel: plain.target_rel,
            predicted_ic_steps: work,
            predicted_wall_s: work * seconds_per_step,
        })
    }
}

fn describe_plain(plain: &PlannedRun) -> String {
    format!("{} × {}", plain.ics, plain.collisions)
}
