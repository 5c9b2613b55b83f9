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
//! - [`Ensemble`]: many initial conditions on **any table** (a built-in
//!   one, a [`SegmentTable`](spinball_geometry::SegmentTable), your own
//!   [`Boundary`](spinball_geometry::Boundary)) run in parallel, in vector
//!   lanes when the table has a lane form, giving a
//!   [`LyapunovEstimate`] with mean, SEM, median, conditional mean, chaotic
//!   fraction, collision rate, wall time, seed and every parameter, bitwise
//!   identical for any thread count and any split of the index range, with a
//!   [`StopRule`] that stops at a target relative SEM or a time budget, all
//!   through one observed driver ([`Ensemble::run_observed`]: progress
//!   events, cancellation, stop reasons);
//! - [`AlphaSweep`]: λ(α) curves, with [`SweepRow`] records for CSV/JSON;
//! - what an estimate's error is made of and what shrinking it costs:
//!   [`ErrorBudget`] (SEM, [`FiniteTimeBias`] from nested checkpoints,
//!   [`MethodBias`], total), a [`Reference`] value, [`work_precision()`] sets,
//!   a [`Planner`] for a target total error and [`StopRule::total_error`];
//! - [`FtleDistribution`]: histograms, moments, chaotic fraction over a band of
//!   thresholds, the Datseris–Hupe–Fleischmann product;
//! - diagnostics of the paper's mechanism: phase-space separation
//!   ([`phase_space_separation`]), collision rate ([`CollisionRate`],
//!   [`liouville_collision_rate`]), wall transitions and |ΔQ|
//!   ([`WallStatistics`]), curved share ([`curved_share()`]), energy traces.
//!
//! # Layers
//! Modules build on each other without circles: statistics and FTLE
//! distributions; single trajectories (`lyapunov`, `spectrum`,
//! `trajectory`); results and their provenance; the ensemble and its
//! initial conditions; the run driver; sweeps, convergence tables and the
//! diagnostics on top.
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
#![forbid(unsafe_code)]

pub mod alpha_sweep;
pub mod collision_log;
pub mod collision_rate;
pub mod convergence;
pub mod curved_share;
pub mod driver;
pub mod energy;
pub mod engine;
pub mod ensemble;
pub mod error;
pub mod error_budget;
pub mod finite_time_bias;
pub mod ftle;
pub mod islands;
pub mod lyapunov;
pub mod measurement;
pub mod method_bias;
pub mod paper;
pub mod parallel;
pub mod partial;
pub mod planner;
pub mod provenance;
pub mod q_pairs;
pub mod result;
pub mod rows;
pub mod saturation;
pub mod separation;
pub mod shard;
pub mod spectrum;
pub mod spectrum_ensemble;
pub mod starts;
pub mod stats;
pub mod stop_rule;
#[cfg(test)]
mod test_support;
pub mod trajectory;
pub mod wall_statistics;
pub mod work_precision;

// Phase space: sections, FTLE maps, the bouncing-ball island, return times.
pub mod bouncing_ball;
pub mod ftle_map;
pub mod invariant_measure;
pub mod island_map;
pub mod return_time;
pub mod section;

pub use alpha_sweep::{AlphaSweep, SweepEvent, linspace};
pub use collision_log::{COLLISION_COLUMNS, CollisionLog, collision_log};
pub use collision_rate::{
    CollisionRate, RateSummary, collision_rate_summary, initial_mean_speed,
    liouville_collision_rate, per_collision_exponent, rate_summary,
};
pub use convergence::{
    LcnTrace, convergence_estimates, format_mean_sem, lcn_trace, lcn_traces, trajectory_checkpoints,
};
pub use curved_share::{CurvedShare, curved_share, perimeter_curved_share};
pub use driver::{BatchProgress, Control, RunEvent, RunObserver, Silent};
pub use energy::{
    EnergyCheckpoint, EnergyConservation, EnergyHistory, EnergyPoint, EnergyTrace,
    component_law_energy_history, energy_conservation, energy_history, energy_trace,
    log_checkpoints,
};
pub use engine::Engine;
pub use ensemble::Ensemble;
pub use error::AnalysisError;
pub use error_budget::{ErrorBudget, Reference};
pub use finite_time_bias::{BiasFit, BiasLaw, BiasRegime, FiniteTimeBias, MIN_CHECKPOINTS};
pub use ftle::{CHAOS_THRESHOLD, ChaoticBand, ChaoticFraction, FtleDistribution, THRESHOLD_BAND};
pub use islands::{
    ClassComparison, ClassSummary, MeanSem, TrajectoryProfile, compare_classes, trajectory_profile,
    trajectory_profiles,
};
pub use lyapunov::{
    HistoryPoint, Lyapunov, LyapunovOptions, Method, PAPER_DELTA0, largest_lyapunov,
    random_direction,
};
pub use measurement::{Measurement, dhf_product, normalised, paired_difference};
pub use method_bias::MethodBias;
pub use parallel::{Threads, map_chunks, map_indices};
pub use partial::{MergeError, PartialRun, merge_partials};
pub use planner::{MethodPilot, PlannedRun, Planner, VarianceModel};
pub use provenance::{Provenance, TableRecord};
pub use q_pairs::{PairClass, QPair, QPairStatistics, q_pair_statistics};
pub use result::{LyapunovEstimate, StopReason};
pub use rows::{BudgetRow, CSV_HEADER, SweepRow, csv_string, sweep_rows, write_csv};
pub use saturation::{SeparationSummary, summarize_separation};
pub use separation::{
    LinearFit, Separation, SeparationOptions, phase_space_separation, separation_growth,
};
pub use shard::Shard;
pub use spectrum::{MAX_QR_INTERVAL, Spectrum, SpectrumOptions, lyapunov_spectrum};
pub use spectrum_ensemble::{SpectrumEstimate, spectrum_ensemble};
pub use starts::Starts;
pub use stats::{
    Accumulator, Histogram, conditional_mean, count_above, fraction_above, median, quantile,
    quantiles,
};
pub use stop_rule::StopRule;
pub use trajectory::{TrajectoryStats, ftle_trajectories, trajectories_csv, trajectory_ftle};
pub use wall_statistics::{
    DeltaQPopulation, TransitionFractions, TransitionRule, WallStatistics, wall_statistics,
    wall_statistics_ensemble,
};
pub use work_precision::{Budget, WorkPoint, work_precision};

pub use bouncing_ball::{BouncingShare, FacingFlats, FlatBand, pair_rotation};
pub use ftle_map::{FtleMap, FtleMapOptions, Slice, ftle_map};
pub use invariant_measure::{InvariantMeasure, SectionBox};
pub use island_map::{IslandMap, island_map};
pub use return_time::{
    KacComparison, OrbitReturns, invariant_start, kac_comparison, orbit_returns,
};
pub use section::{
    Section, SectionPoint, sampled_sections, section_points, sections, spin_slice, state_on_section,
};
