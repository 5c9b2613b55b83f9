//! Transport on periodic tables: how far a ball wanders, and whether it
//! diffuses.
//!
//! On a periodic table (a Lorentz gas: scatterers in a lattice, the ball
//! re-entering each cell through its partner wall) a ball's unwrapped
//! displacement `Δr(t)` grows without bound. Over an ensemble of initial
//! conditions its mean square `⟨Δr²⟩(t)` grows linearly, `⟨Δr²⟩ ≈ 4Dt` in
//! the plane (Einstein), when every free flight is bounded (**finite
//! horizon**), and marginally faster, `⟨Δr²⟩ ∝ t ln t`, when straight
//! corridors let flights be arbitrarily long (**infinite horizon**, the
//! square lattice). This group takes the displacements as plain data
//! (checkpoint times, one `[Δx, Δy]` per initial condition and checkpoint)
//! and gives:
//!
//! - [`MeanSquareDisplacement`]: `⟨Δr²⟩(t)` with its SEM per checkpoint;
//! - [`diffusion`]: the diffusion coefficient from the Einstein relation
//!   over a stated [`FitWindow`], with its error from the per-IC
//!   statistics: a [`Diffusion::Normal`] `D` for a [`Horizon::Finite`]
//!   table, a [`Diffusion::Marginal`] coefficient of `t ln t` growth for
//!   [`Horizon::Infinite`], and [`Diffusion::Ballistic`] when a
//!   finite-horizon ensemble holds balls that fly straight through the
//!   lattice ([`Ballistic`]): never a finite `D` that is not one;
//! - [`WindowScan`]: the estimate over successive windows (each twice as
//!   late as the one before) and its trend in `ln t`, the diagnostic of
//!   normal against marginal growth;
//! - [`horizon_of`]: the horizon of a periodic table, decided by the
//!   geometry (refused, never guessed, where it cannot be);
//! - [`DiffusionSummary`]: all of the above for the records of a run
//!   ([`DisplacementRecord`](crate::open::DisplacementRecord)s): what the
//!   command line, Python and the examples report.
//!
//! The definitions, estimators and their errors are in `docs/TRANSPORT.md`.

mod ballistic;
mod diffusion;
mod displacements;
mod horizon;
mod summary;
mod table_horizon;

pub use ballistic::{Ballistic, MAX_RESIDUAL, MIN_INCREMENTS};
pub use diffusion::{
    Diffusion, DiffusionFit, FitWindow, MIN_POINTS, Trend, WindowScan, diffusion, window_scan,
};
pub use displacements::{Displacements, MeanSquareDisplacement, MsdPoint};
pub use horizon::Horizon;
pub use summary::DiffusionSummary;
pub use table_horizon::horizon_of;

use thiserror::Error;

/// Why a displacement sample could not be analysed.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum TransportError {
    /// No checkpoint times.
    #[error("no checkpoint times: give at least one")]
    NoCheckpoints,
    /// Checkpoint times that are not finite, positive and increasing.
    #[error(
        "checkpoint time {index} is {value}: times must be finite, > 0 and strictly increasing"
    )]
    BadTimes {
        /// Index of the checkpoint.
        index: usize,
        /// The value found.
        value: f64,
    },
    /// Displacements that are not one per initial condition and checkpoint.
    #[error(
        "{len} displacements for {checkpoints} checkpoints: give n_ics × checkpoints (IC-major), n_ics >= 2"
    )]
    Shape {
        /// Displacements given.
        len: usize,
        /// Checkpoints.
        checkpoints: usize,
    },
    /// A displacement that is NaN or infinite.
    #[error("displacement of initial condition {ic} at checkpoint {checkpoint} is not finite")]
    NotFinite {
        /// Initial condition.
        ic: usize,
        /// Checkpoint.
        checkpoint: usize,
    },
    /// Too few checkpoints in a fit window.
    #[error(
        "{points} checkpoints in the fit window [{t0}, {t1}], at least {min} are needed: widen the window or record more checkpoints"
    )]
    TooFewPoints {
        /// Checkpoints in the window.
        points: usize,
        /// The least accepted.
        min: usize,
        /// Window start.
        t0: f64,
        /// Window end.
        t1: f64,
    },
    /// Diffusion asked of a table without periodic walls.
    #[error(
        "the table has no periodic walls, so a ball cannot spread: use a periodic table (e.g. `lorentz:lattice=triangular,w=1,R=0.45`, or `periodic` pairs in a table file)"
    )]
    NotPeriodic,
    /// A periodic table whose horizon is not known.
    #[error(
        "the horizon of this periodic table cannot be decided (a table without a shape, or one the geometry's horizon detection refuses): without it no diffusion coefficient is reported"
    )]
    UnknownHorizon,
    /// A window that is not a finite interval.
    #[error("fit window [{t0}, {t1}] is not a finite interval with 0 <= t0 < t1")]
    BadWindow {
        /// Start.
        t0: f64,
        /// End.
        t1: f64,
    },
}
