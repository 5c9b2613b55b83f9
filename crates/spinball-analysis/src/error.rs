//! Why an analysis could not run.

use spinball_core::{LaunchError, NoRoom, PerturbationError, SpinLawError, StepError};
use spinball_geometry::GeometryError;
use spinball_lanes::LanesError;
use thiserror::Error;

/// An analysis that could not run or finish.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum AnalysisError {
    /// An option is out of range (zero collisions, `δ0 <= 0`, empty ensemble, ...).
    #[error("invalid option `{name}`: {reason}")]
    InvalidOption {
        /// Name of the option.
        name: &'static str,
        /// What is wrong with it.
        reason: String,
    },
    /// The initial state could not be launched.
    #[error("initial condition {index}: {source}")]
    Launch {
        /// Index of the initial condition (0 for single trajectories).
        index: u64,
        /// The launch error.
        source: LaunchError,
    },
    /// A collision step failed.
    #[error("initial condition {index}: {source}")]
    Step {
        /// Index of the initial condition (0 for single trajectories).
        index: u64,
        /// The step error.
        source: StepError,
    },
    /// The finite-difference perturbation cannot measure anything for this
    /// initial condition on this table (the same on both engines).
    #[error("initial condition {index}: {source}")]
    Perturbation {
        /// Index of the initial condition (0 for single trajectories).
        index: u64,
        /// Why.
        source: PerturbationError,
    },
    /// The lane engine refused the run for a reason the scalar path does
    /// not have (an instruction set this CPU lacks, a table without a lane
    /// form).
    #[error("lane engine: {0}")]
    Lanes(LanesError),
    /// The lane kernels found a trajectory going non-finite where the scalar
    /// path, rerun on the same initial condition, did not fail. Never seen;
    /// report it, and run the ensemble with `Engine::Scalar` meanwhile.
    #[error(
        "initial condition {index}: the lane kernels went non-finite but the scalar path did not (run with Engine::Scalar and report this)"
    )]
    EngineMismatch {
        /// Index of the initial condition.
        index: u64,
    },
    /// No method reaches a target error within the run lengths allowed:
    /// the bias (finite-time and method) is above the target everywhere.
    #[error(
        "target total error {target:.3e} cannot be reached: the smallest bias of any method is {floor:.3e} (allow longer runs or the tangent method, or aim higher)"
    )]
    TargetUnreachable {
        /// The target, absolute.
        target: f64,
        /// The smallest bias floor found.
        floor: f64,
    },
    /// An observer stopped the run before any estimate could be formed.
    #[error("the run was cancelled before two initial conditions finished")]
    Cancelled,
    /// Invalid table.
    #[error(transparent)]
    Geometry(#[from] GeometryError),
    /// Invalid spin parameter.
    #[error(transparent)]
    SpinLaw(#[from] SpinLawError),
    /// The sampler cannot draw initial conditions in this table.
    #[error(transparent)]
    NoRoom(#[from] NoRoom),
    /// Newton's method for a periodic orbit did not close it: the distance
    /// between the start and its `period`-th image is still `residual`.
    #[error(
        "no periodic orbit of period {period} found: after {iterations} Newton steps the orbit misses closing by {residual:.3e} (tolerance {tolerance:.1e}); start nearer an orbit, allow more iterations or loosen the tolerance"
    )]
    NotClosed {
        /// The period sought (collisions).
        period: u32,
        /// Newton steps taken.
        iterations: u32,
        /// Largest component of `F^p(z) − z` at the best point reached
        /// (`s` in units of the table's `unit_length`).
        residual: f64,
        /// The tolerance asked for.
        tolerance: f64,
    },
    /// An escape sample that cannot be analysed.
    #[error(transparent)]
    Escape(#[from] crate::escape::EscapeError),
    /// A transport (displacement) sample that cannot be analysed.
    #[error(transparent)]
    Transport(#[from] crate::transport::TransportError),
    /// An island was asked of a periodic orbit that is not elliptic: no
    /// island is centred on it.
    #[error(
        "the orbit is {class} (pair trace T = {pair_trace}), not elliptic (|T| < 2): no island is centred on it; follow it to an α where it is elliptic"
    )]
    NotElliptic {
        /// Its class: `hyperbolic`, `parabolic` or `loxodromic`.
        class: &'static str,
        /// The trace of its multiplier pair.
        pair_trace: f64,
    },
    /// The start on an elliptic orbit itself came out chaotic: the island
    /// is smaller than the run resolves, or the run too short.
    #[error(
        "the cell of the orbit's point has FTLE {ftle:.3e} above the threshold {threshold}: no island is resolved around it (run more collisions, or the island is below the cell size)"
    )]
    OrbitCellChaotic {
        /// The FTLE of the orbit's own start.
        ftle: f64,
        /// The threshold of a regular cell.
        threshold: f64,
    },
    /// The regular cells around an orbit reach the edge of every window
    /// tried, so no bounded island was measured.
    #[error(
        "the regular region around the orbit reaches the edge of the window along {axis} (half-width {half_width}): it is not bounded there (a band round the whole table, or more windows needed: raise max_windows or the first half-width)"
    )]
    IslandUnbounded {
        /// `s` or `sin θ`.
        axis: &'static str,
        /// The half-width of the window along it.
        half_width: f64,
    },
}

impl AnalysisError {
    /// Shorthand for [`AnalysisError::InvalidOption`].
    pub fn invalid(name: &'static str, reason: impl Into<String>) -> Self {
        AnalysisError::InvalidOption {
            name,
            reason: reason.into(),
        }
    }

    /// Attach an initial-condition index to a launch or step error.
    pub fn at_index(self, index: u64) -> Self {
        match self {
            AnalysisError::Launch { source, .. } => AnalysisError::Launch { index, source },
            AnalysisError::Step { source, .. } => AnalysisError::Step { index, source },
            AnalysisError::Perturbation { source, .. } => {
                AnalysisError::Perturbation { index, source }
            }
            other => other,
        }
    }
}

impl From<LaunchError> for AnalysisError {
    fn from(source: LaunchError) -> Self {
        AnalysisError::Launch { index: 0, source }
    }
}

impl From<StepError> for AnalysisError {
    fn from(source: StepError) -> Self {
        AnalysisError::Step { index: 0, source }
    }
}
