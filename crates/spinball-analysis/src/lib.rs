//! Chaos indicators for spinning billiards, each with its error bar and its cost.
//!
//! What a physicist asks of a spinning billiard is how chaotic it is, and how
//! sure the answer is. This crate answers in groups, one module each:
//!
//! - [`estimators`]: what one trajectory says.
//!   [`largest_lyapunov`](estimators::largest_lyapunov) gives the largest
//!   exponent by the paper's finite-difference Benettin method
//!   ([`Method::FiniteDifference`](estimators::Method::FiniteDifference),
//!   δ0 = 1e-7) or by exact tangent dynamics
//!   ([`Method::Tangent`](estimators::Method::Tangent)), per unit time and
//!   per collision, with an optional running history;
//!   [`lyapunov_spectrum`](estimators::lyapunov_spectrum) all five exponents
//!   (exact, or the paper's finite-difference variant, whose fifth exponent
//!   is explained there); [`FtleDistribution`](estimators::FtleDistribution)
//!   histograms, moments, chaotic fraction over a band of thresholds; and the
//!   statistics behind every error bar.
//! - [`run`]: many initial conditions. An [`Ensemble`](run::Ensemble) on
//!   **any table** (a built-in one, a
//!   [`SegmentTable`](spinball_geometry::SegmentTable), your own
//!   [`Boundary`](spinball_geometry::Boundary)) runs in parallel, in vector
//!   lanes when the table has a lane form, giving a
//!   [`LyapunovEstimate`](run::LyapunovEstimate) with mean, SEM, median,
//!   conditional mean, chaotic fraction, collision rate, wall time, seed and
//!   every parameter, bitwise identical for any thread count and any split of
//!   the index range, with a [`StopRule`](run::StopRule) that stops at a
//!   target relative SEM or a time budget, all through one observed driver
//!   ([`Ensemble::run_observed`](run::Ensemble::run_observed): progress
//!   events, cancellation, stop reasons); shards and resumable partial runs;
//!   λ(α) curves with [`AlphaSweep`](run::AlphaSweep).
//! - [`precision`]: what an estimate's error is made of and what shrinking
//!   it costs: [`ErrorBudget`](precision::ErrorBudget) (SEM,
//!   [`FiniteTimeBias`](precision::FiniteTimeBias) from nested checkpoints,
//!   [`MethodBias`](precision::MethodBias), total), a
//!   [`Reference`](precision::Reference) value,
//!   [`work_precision()`](precision::work_precision()) sets, a
//!   [`Planner`](precision::Planner) for a target total error,
//!   [`StopRule::total_error`](run::StopRule::total_error), and
//!   [`Multilevel`](precision::Multilevel) ensembles over run length.
//! - [`phase_space`]: the Birkhoff section, FTLE maps, the invariant measure
//!   and return times, the regular islands and who sits on them.
//! - [`orbits`]: periodic orbits of any period (Newton's method with the
//!   exact tangent map), their stability (multipliers, class, Greene's
//!   residue) and the α where it changes.
//! - [`diagnostics`]: the paper's checks of its mechanism: phase-space
//!   separation, collision rate, wall transitions and |ΔQ|, curved share,
//!   energy conservation, and the paper's published numbers.
//! - [`open`]: ensembles on tables with holes or periodic walls: per
//!   initial condition, when and how a ball escaped (or that it was still
//!   inside, censored) and its unwrapped displacement through a lattice.
//! - [`escape`]: what escape times say: the survival probability
//!   (Kaplan–Meier with its band), the escape rate of the exponential
//!   regime, an algebraic tail and its exponent, and the mean escape time
//!   the invariant measure predicts (Kac).
//! - [`transport`]: what displacements say: the mean-square displacement,
//!   the diffusion coefficient over a stated window, and the marginal
//!   `t ln t` growth of an infinite horizon.
//! - [`animation`]: balls at the frame times of a film (positions, spin
//!   angles, the exact collisions between frames), what the GIF and MP4
//!   writers draw.
//! - [`report`]: estimates as flat records
//!   ([`SweepRow`](report::SweepRow)) for CSV and JSON.
//!
//! Every item has one path, `spinball_analysis::<group>::<item>`; the error
//! type [`AnalysisError`] is at the root.
//!
//! # Layers
//! The groups build on each other without circles, each importing only from
//! groups below it:
//!
//! ```text
//! report
//! orbits
//! phase_space   diagnostics   escape
//! precision                   transport
//! run           animation     open
//! estimators
//! ```
//!
//! `phase_space` and `diagnostics` sit side by side on `precision` and do
//! not import each other; `orbits` builds on `phase_space`; `animation`
//! and `open` need only the initial conditions of `run`; `transport`
//! builds on `estimators` alone and `escape` on `diagnostics` (the mean
//! speed of the Kac time). The statistics of `escape` and `transport` take
//! plain numbers, so they serve any source of escape times or
//! displacements, `open` among them.
//!
//! ```
//! use spinball_analysis::estimators::Method;
//! use spinball_analysis::run::Ensemble;
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
//! assert!(estimate.mean() > 0.1 && estimate.mean() < 0.3); // paper §IV: ≈ 0.20
//! assert!(estimate.sem() > 0.0 && estimate.n_ics() == 64);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Features
//! - `rayon`: ensembles use all cores ([`Threads`](run::Threads)); without it
//!   they run on the calling thread. Results do not depend on it.
//! - `serde`: `Serialize`/`Deserialize` for options, results and accumulators.
#![cfg_attr(docsrs, feature(doc_cfg))]
#![forbid(unsafe_code)]

pub mod animation;
pub mod diagnostics;
pub mod escape;
pub mod estimators;
pub mod open;
pub mod orbits;
pub mod phase_space;
pub mod precision;
pub mod report;
pub mod run;
pub mod transport;

mod error;
#[cfg(test)]
mod test_support;

pub use error::AnalysisError;
