//! Chaos indicators for spinning billiards, each with its error bar and its cost.
//!
//! What a physicist asks of a spinning billiard is how chaotic it is, and how
//! sure the answer is. This crate answers with:
//! - [`largest_lyapunov`]: the largest exponent of one trajectory, by the
//!   paper's finite-difference Benettin method ([`Method::FiniteDifference`],
//!   δ0 = 1e-7) or by exact tangent dynamics ([`Method::Tangent`]), per unit
//!   time and per collision, with an optional running history;
//! - [`lyapunov_spectrum`]: all five exponents (exact, or the paper's
//!   finite-difference variant, whose fifth exponent is explained there);
//! - [`Ensemble`]: many initial conditions run in parallel, giving a
//!   [`LyapunovEstimate`] with mean, SEM, median, conditional mean, chaotic
//!   fraction, collision rate, wall time, seed and every parameter, bitwise
//!   identical for any thread count and any split of the index range, with a
//!   [`StopRule`] that stops at a target relative SEM or a time budget;
//! - [`FtleDistribution`]: histograms, moments, chaotic fraction over a band of
//!   thresholds, the Datseris–Hupe–Fleischmann product;
//! - diagnostics of the paper's mechanism: phase-space separation,
//!   collision rate, wall transitions and |ΔQ| ([`WallStatistics`]), curved
//!   share, energy traces.
//!
//! ```
//! use spinball_analysis::{Ensemble, Method};
//! use spinball_core::SpinLaw;
//! use spinball_geometry::Stadium;
//!
//! // λ of the stadium (a = 1) for a solid sphere, 64 initial conditions.
//! let estimate = Ensemble::new(Stadium::new(1.0)?, SpinLaw::new(0.4)?)
//!     .with_ics(64)
//!     .with_collisions(5_000)
//!     .with_method(Method::Tangent)
//!     .with_seed(1)
//!     .run()?;
//! println!("{estimate}");
//! assert!(estimate.mean > 0.1 && estimate.mean < 0.3); // paper §IV: ≈ 0.20
//! assert!(estimate.sem > 0.0 && estimate.n_ics == 64);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Features
//! - `rayon`: ensembles use all cores ([`Threads`]); without it they run on
//!   the calling thread. Results do not depend on it.
//! - `serde`: `Serialize`/`Deserialize` for options, results and accumulators.
#![cfg_attr(docsrs, feature(doc_cfg))]

pub mod convergence;
pub mod diagnostics;
pub mod energy;
pub mod ensemble;
pub mod error;
pub mod ftle;
pub mod islands;
pub mod lyapunov;
pub mod parallel;
pub mod q_pairs;
pub mod result;
pub mod saturation;
pub mod spectrum;
pub mod spectrum_ensemble;
pub mod stats;
pub mod sweep;

pub use convergence::*;
#[allow(unused_imports)]
pub use diagnostics::*;
pub use energy::*;
#[allow(unused_imports)]
pub use ensemble::*;
pub use error::AnalysisError;
#[allow(unused_imports)]
pub use ftle::*;
pub use islands::*;
pub use lyapunov::{
    HistoryPoint, Lyapunov, LyapunovOptions, Method, PAPER_DELTA0, largest_lyapunov,
    random_direction,
};
pub use parallel::{Threads, map_chunks, map_indices};
pub use q_pairs::*;
#[allow(unused_imports)]
pub use result::*;
pub use saturation::*;
#[allow(unused_imports)]
pub use spectrum::*;
pub use spectrum_ensemble::*;
#[allow(unused_imports)]
pub use stats::*;
pub use sweep::*;
