//! `--estimator plain|multilevel` and `--target-error`: which estimator a
//! λ command runs, shared by `spinball lyapunov` and `spinball sweep`.
//!
//! A multilevel run takes its top run length from `--collisions` and the
//! levels below it from the library's `default_levels`; the numbers of
//! initial conditions per level are chosen by the estimator for
//! `--target-error`, so `--ics` does not apply.

use std::path::Path;

use clap::{Args, ValueEnum};
use spinball_analysis::precision::{EnsembleLevels, Multilevel};
use spinball_analysis::report::{Document, MultilevelDocument, MultilevelPoint};
use spinball_analysis::run::Ensemble;
use spinball_geometry::Boundary;

use crate::documents::write_document;
use crate::error::CliError;

/// Which estimator runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, ValueEnum)]
pub enum EstimatorArg {
    /// One ensemble of `--ics` × `--collisions`.
    #[default]
    Plain,
    /// Levels of run lengths up to `--collisions`, each with the initial
    /// conditions that reach `--target-error` at the least work.
    Multilevel,
}

/// The estimator options.
#[derive(Debug, Clone, Args)]
pub struct EstimatorArgs {
    /// `plain` or `multilevel` (Giles' multilevel ensembles over run
    /// length, up to --collisions; --ics does not apply).
    #[arg(long, value_enum, default_value_t = EstimatorArg::Plain)]
    pub estimator: EstimatorArg,
    /// Relative total error a multilevel run aims at (SEM, finite-time and
    /// method bias together), e.g. 1e-3; required with --estimator
    /// multilevel.
    #[arg(long, value_name = "REL")]
    pub target_error: Option<f64>,
}

impl EstimatorArgs {
    /// The multilevel estimator asked for, `None` for a plain run.
    ///
    /// # Errors
    /// [`CliError::Usage`] for multilevel without `--target-error`, a
    /// target out of range, or `--target-error` with the plain estimator.
    pub fn multilevel(&self) -> Result<Option<Multilevel>, CliError> {
        match (self.estimator, self.target_error) {
            (EstimatorArg::Plain, None) => Ok(None),
            (EstimatorArg::Plain, Some(_)) => Err(CliError::Usage(
                "--target-error applies to --estimator multilevel".into(),
            )),
            (EstimatorArg::Multilevel, None) => Err(CliError::Usage(
                "--estimator multilevel needs --target-error (e.g. 1e-3)".into(),
            )),
            (EstimatorArg::Multilevel, Some(t)) if t.is_finite() && t > 0.0 && t < 1.0 => {
                Ok(Some(Multilevel::new(t)))
            }
            (EstimatorArg::Multilevel, Some(t)) => Err(CliError::Usage(format!(
                "--target-error {t}: must be a relative error in (0, 1)"
            ))),
        }
    }
}

/// Run `options` on the levels of `ensemble` up to its collisions.
///
/// # Errors
/// [`CliError::Usage`] for levels that cannot be made (too few
/// collisions, explicit states); [`CliError::Failed`] for a failed run or
/// an unreachable target.
pub fn run_multilevel<B: Boundary + Clone + Sync>(
    ensemble: &Ensemble<B>,
    options: &Multilevel,
) -> Result<MultilevelPoint, CliError> {
    let source = EnsembleLevels::up_to(ensemble.clone(), ensemble.collisions)
        .map_err(|e| CliError::Usage(format!("--estimator multilevel: {e}")))?;
    let estimate = options
        .run(&source)
        .map_err(|e| CliError::Failed(format!("alpha = {}: {e}", ensemble.alpha())))?;
    Ok(MultilevelPoint {
        alpha: ensemble.alpha(),
        estimate,
    })
}

/// Write `points` to `path` as a `spinball.multilevel` document.
///
/// # Errors
/// [`CliError::Failed`] if it cannot be written.
pub fn write_multilevel(path: &Path, points: &[MultilevelPoint]) -> Result<(), CliError> {
    let doc = Document::Multilevel(MultilevelDocument::new(points.to_vec()));
    write_document(path, &doc, false)
}
