//! Runs: many initial conditions of one scene, turned into one estimate
//! that is bitwise reproducible on any number of threads, in any split.
//!
//! This layer sits on [`estimators`](crate::estimators) and below everything
//! that needs a finished estimate ([`precision`](crate::precision),
//! [`phase_space`](crate::phase_space), [`diagnostics`](crate::diagnostics)).
//!
//! - [`Ensemble`]: the scene (table, spin law, [`Starts`], seed, index range,
//!   collisions, [`Method`](crate::estimators::Method), [`Engine`],
//!   [`Threads`]) and its runs;
//! - the one run driver ([`Ensemble::run_observed`]): batches, a
//!   [`RunObserver`] with [`RunEvent`]s and [`Control`], a [`StopRule`],
//!   and a [`LyapunovEstimate`] that says why it stopped ([`StopReason`]) and
//!   what it was computed from ([`Provenance`], [`TableRecord`]);
//! - runs in pieces: [`Shard`]s of a campaign, [`PartialRun`]s that resume
//!   ([`Ensemble::run_partial`]) and [`merge_partials`] into the estimate of
//!   one unbroken run;
//! - per-trajectory results ([`TrajectoryStats`], [`trajectory_ftle`], the
//!   specification every engine reproduces) and the deterministic parallel
//!   map ([`map_indices`], [`map_chunks`]);
//! - scenes built from ensembles: λ(α) with [`AlphaSweep`], the averaged
//!   spectrum with [`spectrum_ensemble`];
//! - the defaults every front shares ([`RunDefaults`] and its siblings).
//!
//! # Defaults
//! One set of defaults for every front: [`RunDefaults`] (an ensemble run:
//! seed 0, 1000 initial conditions of 10⁴ collisions, the paper's sampler
//! and finite-difference method, threshold 0.01, lanes, all threads),
//! [`SpectrumDefaults`], [`SectionDefaults`], [`KacDefaults`],
//! [`FtleMapDefaults`], [`EscapeDefaults`] and [`DiffusionDefaults`]. [`Ensemble::new`], `Method::default` and
//! `FtleMapOptions::new` read them; the command line's option defaults and
//! the Python keyword defaults are these constants too (the CLI reads them,
//! the Python package checks its literals against them when it is
//! compiled), so a run without options gives the same numbers from every
//! front. docs/DEFAULTS.md is the table for users.
//!
//! # Where `impl Ensemble` lives
//! [`Ensemble`] is one type with three `impl` blocks, each next to what it
//! works with: the builder, its validation and the per-trajectory kernels
//! in `ensemble.rs`; the runs that return an estimate (`run`, `run_until`,
//! `run_observed`) in `driver.rs`, beside the observer, event and batch
//! types they drive; resuming a [`PartialRun`] (`run_partial`) in
//! `partial.rs`, beside the partial-result type and its merge.
//!
//! # Ensembles
//!
//! Ensembles of trajectories: many initial conditions, one estimate with its
//! error, bitwise reproducible on any number of threads, for any table.
//!
//! A single trajectory's exponent is a finite-time estimate that differs from
//! trajectory to trajectory (and, with spin, is bimodal); the paper's numbers
//! are averages over 10⁴–10⁵ initial conditions. An [`Ensemble`] describes
//! such a run — table (any [`Boundary`](spinball_geometry::Boundary): a built-in table, a
//! [`SegmentTable`](spinball_geometry::SegmentTable), your own), spin law,
//! initial conditions ([`Starts`]: a sampler, or explicit states), seed,
//! index range, collisions per trajectory, method, engine, threads — and
//! [`Ensemble::run`] (section [The run driver](#the-run-driver)) returns a
//! [`LyapunovEstimate`].
//!
//! ## Engines
//! A table with a lane form ([`Boundary::shape`](spinball_geometry::Boundary::shape) is `Some`: every built-in
//! table and every closed segment table) runs in the vector-lane kernels by default
//! ([`Engine::Lanes`]); any other table (one with holes or periodic walls
//! among them), or [`Engine::Scalar`], runs on the scalar path. Both give the same trajectories, and the same typed error,
//! with the absolute initial-condition index, for the same failure.
//!
//! ## Reproducibility
//! Initial condition `i` is drawn from its own stream
//! [`ic_rng(seed, i)`](spinball_core::ic_rng), and the same stream then draws
//! the initial perturbation direction, so trajectory `i` does not depend on
//! which thread runs it or on which other indices are in the run. Results come
//! back in index order ([`map_chunks`]) and every statistic is reduced
//! sequentially in that order. Hence an estimate is **bitwise identical for
//! any thread count and for any split of the index range**
//! ([`LyapunovEstimate::merge`](crate::run::LyapunovEstimate::merge) of `[0, k)`
//! and `[k, n)` equals one run over `[0, n)`).
//!
//! # Which engine runs
//!
//! Which implementation runs an ensemble's trajectories.
//!
//! Two engines give the same trajectories: the vector-lane kernels of
//! `spinball-lanes` (fast, for every table with a lane form) and the scalar
//! path (readable, the specification, for every table). A result records
//! the engine that actually ran it.
//!
//! # Initial conditions
//!
//! Where an ensemble's initial conditions come from: drawn by a sampler, or
//! given as a list of states.
//!
//! Either way initial condition `i` owns the random stream
//! [`ic_rng(seed, i)`](spinball_core::ic_rng): a sampler draws the state from
//! it, then the perturbation direction (or frame) of a Lyapunov run is drawn
//! from what follows. An explicit state draws only its direction. So a
//! trajectory depends on its index and the seed alone, never on the thread,
//! the chunk or the engine that runs it.
//!
//! # Trajectories
//!
//! One trajectory of an ensemble: its finite-time exponent and what it cost.
//!
//! [`trajectory_ftle`] is the specification every engine reproduces: the
//! scalar path calls it, the lane kernels must give the same trajectory.
//!
//! # Parallel maps
//!
//! Deterministic parallel map over initial-condition indices.
//!
//! Every per-trajectory result depends only on its index (its own random
//! stream, see [`spinball_core::ic_rng`]), and results come back **in index
//! order**; reductions then run sequentially over that order. So an ensemble
//! gives bitwise the same numbers for any thread count and any split of the
//! index range (float sums are not associative, and rayon's work splitting is
//! not deterministic, so nothing is ever summed inside the parallel part).
//!
//! # The run driver
//!
//! The one run driver: every ensemble run — [`Ensemble::run`],
//! [`Ensemble::run_until`], each point of an
//! [`AlphaSweep`], each column of a convergence table in
//! the lane engine — goes through [`Ensemble::run_observed`].
//!
//! It runs batches of initial conditions from the start of the ensemble's
//! index range, reports each to a [`RunObserver`] ([`RunEvent`]: started,
//! batch done, finished; the pattern of argmin's observers), stops when the
//! [`StopRule`] says so, when the range is used up, or when the observer
//! answers [`Control::Stop`], and says why in the estimate's
//! [`StopReason`]. Batches do not change the numbers: a run over a range is
//! bitwise the same whatever the batch size, the stop rule only decides
//! where it ends.
//!
//! # Stop rules
//!
//! When a batched ensemble run stops: at a target relative standard error,
//! at a target relative **total** error (the SEM and a known bias
//! together), on a wall-time budget, or when its initial conditions run out.
//!
//! # Results
//!
//! What an ensemble run returns: the estimate, how sure it is, what it cost
//! and everything needed to reproduce it.
//!
//! A [`LyapunovEstimate`] is the answer to "what is λ here?": the mean FTLE
//! with its standard error, and — because FTLE distributions with spin are
//! bimodal — the median, the conditional mean of the chaotic part and the
//! chaotic fraction; then the cost (ICs, collisions, wall time) and the
//! parameters (table, α, method, sampler, seed, crate version). It keeps the
//! per-trajectory values in index order, so two runs over adjacent index
//! ranges [merge](LyapunovEstimate::merge) into exactly (bitwise) the result of
//! one run over both, and every statistic can be recomputed later.
//!
//! # Provenance
//!
//! What an estimate was computed from: table, spin, method, initial
//! conditions, seed, engine. Typed (enums with serde), so a result can be
//! checked, merged and rerun, not just read.
//!
//! # Shards
//!
//! Splitting an ensemble's initial conditions across processes.
//!
//! A campaign too big for one machine runs as shards: shard `K` of `N`
//! takes a contiguous block of the index range, so the blocks of all `N`
//! shards tile the range without overlap. Because initial condition `i`
//! depends only on the seed and `i` (see [`Starts`]), the
//! shards' trajectories are exactly those of one unsharded run, and merging
//! them ([`merge_partials`]) gives the unsharded
//! result bitwise.
//!
//! # Partial runs
//!
//! Results that are not finished yet: a shard of a campaign, or a run
//! stopped by a signal or a time limit, kept so that it can be resumed and
//! merged.
//!
//! A [`PartialRun`] holds the parameters of a run ([`Provenance`]), the
//! index range it is responsible for, and the trajectories finished so far
//! (contiguous from the start of that range). [`Ensemble::run_partial`]
//! continues one where it stopped; [`merge_partials`] joins the pieces of a
//! range into the [`LyapunovEstimate`] one uninterrupted, unsharded run would
//! have given, **bitwise** (every statistic is recomputed from the
//! per-trajectory values in index order), and refuses pieces that do not fit.
//!
//! # Checksums
//!
//! Every file a run writes to be read back — a [`PartialRun`] (a shard's
//! share, a checkpoint) and a [`SpectrumEstimate`] — carries the count of
//! its per-initial-condition values and a checksum of its whole content:
//! FNV-1a (64 bits) over a canonical byte encoding (integers and the bits
//! of floats as 8 bytes little-endian, strings as length and bytes, enum
//! variants as a tag byte), written as `fnv1a64:` and 16 hex digits. The
//! algorithm and encoding are spelled out in this crate, so the checksum is
//! the same on every platform and build. Reading a file back checks the
//! count, the checksum and that every value is finite, and refuses the file
//! with an [`IntegrityError`] otherwise: an edited file is never merged or
//! resumed. A file without a checksum (written before they were added) is
//! refused too, with the version that wrote it.
//!
//! The same encoding identifies a table ([`TableRecord::identity`]): its
//! kind and the exact bits of its parameters, never a Rust type name.
//!
//! # λ(α) sweeps
//!
//! λ(α): one [`Ensemble`] per spin parameter, with progress as it goes, and
//! the results as table rows, CSV and serde records.
//!
//! Nearly every figure of the paper is a curve over α (or over a table
//! parameter at a few α). An [`AlphaSweep`] is that curve: an ensemble
//! *template* (table, sampler, seed, initial conditions, collisions, method,
//! threads) run at each α of a list, either over the template's whole index
//! range or in batches under a [`StopRule`] (the same rule, batch for batch,
//! as [`Ensemble::run_until`], so the numbers are the same). A callback sees
//! every point start, every batch finish and every point finish
//! ([`SweepEvent`]), so a caller can draw a progress bar and print or save
//! rows while a long sweep runs.
//!
//! ```
//! use spinball_analysis::run::{AlphaSweep, Ensemble, StopRule, SweepEvent, Threads};
//! use spinball_analysis::report::SweepRow;
//! use spinball_core::SpinLaw;
//! use spinball_geometry::Stadium;
//!
//! let template = Ensemble::new(Stadium::new(1.0)?, SpinLaw::specular())
//!     .with_seed(1)
//!     .with_ics(400) // at most 400 initial conditions per α
//!     .with_collisions(2_000)
//!     .with_threads(Threads::Fixed(1));
//! let sweep = AlphaSweep::new(template, &[0.0, 0.5])?.with_stop(StopRule::new(32, 0.05));
//! let estimates = sweep.run_with(|event| {
//!     if let SweepEvent::Finished { estimate, .. } = event {
//!         println!("{}", SweepRow::from_estimate(estimate).unwrap().table_line());
//!     }
//! })?;
//! assert_eq!(estimates.len(), 2);
//! assert!(estimates.iter().all(|e| e.sem() <= 0.05 * e.mean()));
//! print!("{}", spinball_analysis::report::csv_string(&estimates)?);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//!
//! # The spectrum over an ensemble
//!
//! The Lyapunov spectrum averaged over initial conditions (paper, appendix
//! "Full Lyapunov spectrum": 50 initial conditions × 5·10⁴ collisions).
//!
//! One trajectory's spectrum ([`lyapunov_spectrum`](crate::estimators::lyapunov_spectrum)) is a finite-time
//! estimate; the paper's figure is the mean over an ensemble. The ensemble
//! here follows the rules of [`Ensemble`]: initial condition
//! `i` comes from [`ic_rng(seed, i)`](spinball_core::ic_rng) (the state first, then the
//! initial frame), and every statistic is reduced in index order, so the
//! numbers are the same for any thread count. Exact-tangent spectra of a
//! table with a lane form run in the lane spectrum kernel (same trajectory,
//! tangent map and Gram–Schmidt, bitwise; `Σ ln R_ii` to about `1e-10`
//! relative); finite-difference spectra and other tables run on the scalar
//! path.
//!
//! What the exponents mean, and why the finite-difference variant has a
//! large negative fifth exponent that is not a property of the dynamics, is
//! documented on [`lyapunov_spectrum`](crate::estimators::lyapunov_spectrum).

mod alpha_sweep;
mod checksum;
mod defaults;
mod driver;
mod engine;
mod ensemble;
mod parallel;
mod partial;
mod provenance;
mod result;
mod shard;
mod spectrum_ensemble;
mod starts;
mod stop_rule;
mod trajectory;

pub use alpha_sweep::{AlphaSweep, SweepEvent, linspace};
pub use checksum::IntegrityError;
pub use defaults::{
    DiffusionDefaults, EscapeDefaults, FtleMapDefaults, KacDefaults, RunDefaults, SectionDefaults,
    SpectrumDefaults,
};
pub use driver::{BatchProgress, Control, RunEvent, RunObserver, Silent};
pub use engine::Engine;
pub use ensemble::Ensemble;
pub use parallel::{Threads, map_chunks, map_indices};
pub use partial::{MergeError, PartialRun, merge_partials};
pub use provenance::{Provenance, RunDifference, TableRecord};
pub use result::{LyapunovEstimate, StopReason};
pub use shard::{Shard, tile};
pub use spectrum_ensemble::{SpectrumEstimate, spectrum_ensemble};
pub use starts::Starts;
pub use stop_rule::StopRule;
pub use trajectory::{TrajectoryStats, ftle_trajectories, trajectory_ftle};
