//! The defaults of every run, in one place. The library's builders
//! ([`Ensemble::new`](super::Ensemble::new),
//! [`Method::default`](crate::estimators::Method), the phase-space options)
//! take them from here, and so do the fronts (the command line's option
//! defaults, the Python keyword defaults, checked against these constants
//! when the package is compiled): the same call without options gives the
//! same numbers from Rust, from the shell and from Python.
//!
//! Documented in the group docs (`run/mod.rs`), section "Defaults".

use spinball_core::Sampler;

use super::engine::Engine;
use super::parallel::Threads;
use crate::estimators::{CHAOS_THRESHOLD, Method, PAPER_DELTA0};

/// The defaults of an ensemble run: λ, its FTLE distribution, a sweep of
/// α (`spinball lyapunov`, `ftle`; Python `lyapunov`, `alpha_sweep`,
/// `ftle`).
#[derive(Debug, Clone, Copy)]
pub enum RunDefaults {}

impl RunDefaults {
    /// Seed of the initial conditions and perturbation directions: 0.
    pub const SEED: u64 = 0;
    /// Initial conditions (indices `0..1000`).
    pub const ICS: u64 = 1000;
    /// Collisions per initial condition: 10⁴, converged to the paper's three
    /// digits (its Table I).
    pub const COLLISIONS: u64 = 10_000;
    /// The paper's finite-difference Benettin method, δ0 = 1e-7.
    pub const METHOD: Method = Method::FiniteDifference {
        delta0: PAPER_DELTA0,
    };
    /// The paper's sampler of initial conditions.
    pub const SAMPLER: Sampler = Sampler::Paper;
    /// FTLE above which a trajectory counts as chaotic: the paper's 0.01.
    pub const THRESHOLD: f64 = CHAOS_THRESHOLD;
    /// Vector-lane kernels where the table has a lane form.
    pub const ENGINE: Engine = Engine::Lanes;
    /// All cores (results do not depend on it).
    pub const THREADS: Threads = Threads::All;
}

/// The defaults of a Lyapunov spectrum (`spinball spectrum`, Python
/// `spectrum`): the paper's appendix, 50 initial conditions of 5·10⁴
/// collisions; seed, sampler and threads as [`RunDefaults`].
#[derive(Debug, Clone, Copy)]
pub enum SpectrumDefaults {}

impl SpectrumDefaults {
    /// Initial conditions.
    pub const ICS: u64 = 50;
    /// Collisions per initial condition.
    pub const COLLISIONS: u64 = 50_000;
    /// Exact tangent dynamics (the finite-difference spectrum's fifth
    /// exponent is an artefact of the method).
    pub const METHOD: Method = Method::Tangent;
    /// Re-orthonormalise after every collision.
    pub const QR_INTERVAL: u32 = 1;
}

/// The defaults of a Birkhoff section (`spinball section`, Python
/// `section`): a few orbits drawn by [`RunDefaults::SAMPLER`] from
/// [`RunDefaults::SEED`].
#[derive(Debug, Clone, Copy)]
pub enum SectionDefaults {}

impl SectionDefaults {
    /// Orbits.
    pub const ORBITS: u64 = 8;
    /// Collisions per orbit.
    pub const COLLISIONS: u64 = 1000;
}

/// The defaults of a return-time test against Kac's lemma (`spinball kac`,
/// Python `kac`), orbits from the invariant measure and
/// [`RunDefaults::SEED`].
#[derive(Debug, Clone, Copy)]
pub enum KacDefaults {}

impl KacDefaults {
    /// Orbits.
    pub const ORBITS: u64 = 16;
    /// Collisions per orbit.
    pub const COLLISIONS: u64 = 10_000;
}

/// The defaults of an FTLE map (`spinball ftle-map`, Python `ftle_map`,
/// [`FtleMapOptions::new`](crate::phase_space::FtleMapOptions::new)): the
/// exact tangent method, [`RunDefaults::SEED`] and
/// [`RunDefaults::THRESHOLD`].
#[derive(Debug, Clone, Copy)]
pub enum FtleMapDefaults {}

impl FtleMapDefaults {
    /// Cells along the arc length.
    pub const COLUMNS: u32 = 64;
    /// Cells along the row coordinate.
    pub const ROWS: u32 = 64;
    /// Collisions per start.
    pub const COLLISIONS: u64 = 2_000;
}

/// The defaults of an escape run (`spinball escape`, Python `escape`):
/// starts from [`RunDefaults::SAMPLER`] and [`RunDefaults::SEED`], the
/// summary's windows as
/// [`EscapeOptions::default`](crate::escape::EscapeOptions).
#[derive(Debug, Clone, Copy)]
pub enum EscapeDefaults {}

impl EscapeDefaults {
    /// Balls (indices `0..1000`).
    pub const ICS: u64 = 1_000;
    /// Collisions before a ball still inside counts as censored.
    pub const COLLISIONS: u64 = 100_000;
}

/// The defaults of a diffusion run (`spinball diffuse`, Python `diffuse`):
/// starts from [`RunDefaults::SAMPLER`] and [`RunDefaults::SEED`], the fit
/// window the later half of the run.
#[derive(Debug, Clone, Copy)]
pub enum DiffusionDefaults {}

impl DiffusionDefaults {
    /// Initial conditions (indices `0..1000`).
    pub const ICS: u64 = 1_000;
    /// The last checkpoint time.
    pub const UNTIL: f64 = 1_000.0;
    /// Checkpoints, evenly spaced up to [`DiffusionDefaults::UNTIL`].
    pub const CHECKPOINTS: u32 = 20;
}
