//! `--estimator plain|multilevel` and `--target-error`: which estimator a
//! λ command runs, shared by `spinball lyapunov` and `spinball sweep`.
//!
//! A multilevel run takes its top run length from `--collisions` and the
//! levels below it from the library's `default_levels`; the numbers of
//! initial conditions per level are chosen by the estimator for
//! `--target-error`, so `--ics` does not apply.

use std::fs;
use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};
use spinball_analysis::precision::{EnsembleLevels, LevelAllocation, LevelSource, Multilevel};
use spinball_analysis::report::{
    Document, MultilevelDocument, MultilevelPartialDocument, MultilevelPoint, MultilevelShardPoint,
};
use spinball_analysis::run::{Ensemble, Shard};
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
    /// Run this multilevel allocation (levels and initial conditions per
    /// level, fixed from a pilot) instead of planning one as the run goes:
    /// `spinball slurm --estimator multilevel` writes one per table and α,
    /// and each task runs its --shard of it for `spinball merge`. One α.
    #[arg(long, value_name = "FILE")]
    pub allocation: Option<PathBuf>,
}

impl EstimatorArgs {
    /// The multilevel estimator asked for, `None` for a plain run.
    ///
    /// # Errors
    /// [`CliError::Usage`] for multilevel without `--target-error`, a
    /// target out of range, or `--target-error` with the plain estimator.
    pub fn multilevel(&self) -> Result<Option<Multilevel>, CliError> {
        if self.allocation.is_some() && self.estimator != EstimatorArg::Multilevel {
            return Err(CliError::Usage(
                "--allocation applies to --estimator multilevel".into(),
            ));
        }
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
    let source = levels_of(ensemble)?;
    let estimate = options
        .run(&source)
        .map_err(|e| CliError::Failed(format!("alpha = {}: {e}", ensemble.alpha())))?;
    Ok(MultilevelPoint {
        alpha: ensemble.alpha(),
        estimate,
    })
}

/// The levels of `ensemble` up to its collisions, as a multilevel run
/// makes them.
fn levels_of<B: Boundary + Clone + Sync>(
    ensemble: &Ensemble<B>,
) -> Result<EnsembleLevels<B>, CliError> {
    EnsembleLevels::up_to(ensemble.clone(), ensemble.collisions)
        .map_err(|e| CliError::Usage(format!("--estimator multilevel: {e}")))
}

/// The allocation of `options` for `ensemble`'s levels, from a pilot (what
/// `spinball slurm` fixes for its tasks).
///
/// # Errors
/// As [`run_multilevel`].
pub fn allocate_multilevel<B: Boundary + Clone + Sync>(
    ensemble: &Ensemble<B>,
    options: &Multilevel,
) -> Result<LevelAllocation, CliError> {
    options
        .allocate(&levels_of(ensemble)?)
        .map_err(|e| CliError::Failed(format!("alpha = {}: {e}", ensemble.alpha())))
}

/// The allocation in `path` (written by `spinball slurm`).
///
/// # Errors
/// [`CliError::Usage`] for a file that cannot be read or is not one.
pub fn read_allocation(path: &Path) -> Result<LevelAllocation, CliError> {
    let text = fs::read_to_string(path)
        .map_err(|e| CliError::Usage(format!("cannot read {}: {e}", path.display())))?;
    serde_json::from_str(&text).map_err(|e| {
        CliError::Usage(format!(
            "{} is not a multilevel allocation: {e}",
            path.display()
        ))
    })
}

/// Shard `shard` of `allocation` on `ensemble`'s levels.
///
/// # Errors
/// [`CliError::Usage`] for an allocation of other levels; [`CliError::Failed`]
/// for a failed run.
pub fn run_allocation_shard<B: Boundary + Clone + Sync>(
    ensemble: &Ensemble<B>,
    allocation: &LevelAllocation,
    shard: Shard,
) -> Result<MultilevelShardPoint, CliError> {
    let source = levels_of(ensemble)?;
    if source.levels() != allocation.levels.as_slice() {
        return Err(CliError::Usage(format!(
            "--allocation is for levels {:?}; --collisions {} makes {:?}",
            allocation.levels,
            ensemble.collisions,
            source.levels()
        )));
    }
    let shard = allocation
        .run_shard(&source, shard)
        .map_err(|e| CliError::Failed(format!("alpha = {}: {e}", ensemble.alpha())))?;
    Ok(MultilevelShardPoint {
        alpha: ensemble.alpha(),
        provenance: ensemble.provenance(),
        shard,
    })
}

/// Write `points` to `path` as a `spinball.multilevel.partial` document.
///
/// # Errors
/// [`CliError::Failed`] if it cannot be written.
pub fn write_multilevel_partial(
    path: &Path,
    points: Vec<MultilevelShardPoint>,
) -> Result<(), CliError> {
    let doc = Document::MultilevelPartial(MultilevelPartialDocument { points });
    write_document(path, &doc, false)
}

/// Write `points` to `path` as a `spinball.multilevel` document.
///
/// # Errors
/// [`CliError::Failed`] if it cannot be written.
pub fn write_multilevel(path: &Path, points: &[MultilevelPoint]) -> Result<(), CliError> {
    let doc = Document::Multilevel(MultilevelDocument::new(points.to_vec()));
    write_document(path, &doc, false)
}
