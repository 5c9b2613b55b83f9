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
//! use spinball_analysis::{AlphaSweep, Ensemble, StopRule, SweepEvent, SweepRow, Threads};
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
//! assert!(estimates.iter().all(|e| e.sem <= 0.05 * e.mean));
//! print!("{}", spinball_analysis::csv_string(&estimates)?);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Besides the sweep, the module holds the small pieces of statistics the
//! paper's figures need on top of an estimate: a [`Measurement`] (value ±
//! SEM) with ratio rules, the Datseris–Hupe–Fleischmann product with its
//! error ([`dhf_product`]), the collision rate and per-collision exponent of
//! an estimate ([`rate_summary`]), λ(α)/λ(α₀) ([`normalised`]), and the
//! share of collisions on curved walls of a built-in table with its error
//! ([`curved_share`], with the α = 0 theory [`perimeter_curved_share`]).

use std::fmt::Write as _;
use std::io;
use std::ops::Range;
use std::time::Instant;

use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_geometry::{Boundary, Table, TableVisitor};

use crate::diagnostics::{RateSummary, WallStatistics, collision_rate_summary, wall_statistics};
use crate::ensemble::{Ensemble, StopRule, TrajectoryStats};
use crate::error::AnalysisError;
use crate::ftle::THRESHOLD_BAND;
use crate::lyapunov::Lyapunov;
use crate::parallel::{Threads, map_indices};
use crate::result::{LyapunovEstimate, StopReason};
use crate::stats::Accumulator;

// ---------------------------------------------------------------------------
// The sweep
// ---------------------------------------------------------------------------

/// A sweep over the spin parameter α: the ensemble `template` run at each
/// law of `laws`, in order.
///
/// Every point uses the template's table, sampler, seed, index range,
/// collisions, method, threads and threshold; only the spin law changes.
/// Without a stop rule each point runs the whole index range (bitwise the
/// numbers of [`Ensemble::run`]); with one, batches from the start of the
/// range until the rule stops (bitwise the numbers of
/// [`Ensemble::run_until`]), the range's end capping the count.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct AlphaSweep {
    /// The ensemble run at every α (its own law is ignored).
    pub template: Ensemble,
    /// The spin laws, in sweep order.
    pub laws: Vec<SpinLaw>,
    /// Batches until this rule stops each point (`None`: whole range).
    pub stop: Option<StopRule>,
}

/// What an [`AlphaSweep`] reports while it runs.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum SweepEvent<'a> {
    /// Point `point` (of `points`) at `alpha` starts.
    Started {
        /// Index of the point in the sweep.
        point: usize,
        /// Number of points in the sweep.
        points: usize,
        /// Its α.
        alpha: f64,
    },
    /// A batch of initial conditions of the current point finished.
    Batch(&'a BatchProgress),
    /// Point `point` finished with `estimate`.
    Finished {
        /// Index of the point in the sweep.
        point: usize,
        /// Number of points in the sweep.
        points: usize,
        /// Its result.
        estimate: &'a LyapunovEstimate,
    },
}

/// Where a point of a sweep stands after a batch.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct BatchProgress {
    /// Index of the point in the sweep.
    pub point: usize,
    /// Number of points in the sweep.
    pub points: usize,
    /// Its α.
    pub alpha: f64,
    /// Initial conditions done so far at this point.
    pub ics_done: u64,
    /// Most initial conditions this point can take (the index range).
    pub ics_max: u64,
    /// Running mean FTLE.
    pub mean: f64,
    /// Running standard error (NaN before two trajectories).
    pub sem: f64,
    /// The stop rule's target `SEM/|mean|`, if there is a rule.
    pub target_rel_sem: Option<f64>,
    /// Wall-clock seconds spent on this point so far.
    pub elapsed_s: f64,
}

impl BatchProgress {
    /// Running `SEM/|mean|`.
    pub fn rel_sem(&self) -> f64 {
        self.sem / self.mean.abs()
    }
}

impl AlphaSweep {
    /// A sweep of `template` over the physical `alphas` (each in `[0, 1]`).
    ///
    /// # Errors
    /// [`AnalysisError::SpinLaw`] for an α outside `[0, 1]` (build the laws
    /// with [`SpinLaw::extended`] and use [`AlphaSweep::from_laws`] for
    /// α > 1); [`AnalysisError::InvalidOption`] for an empty list.
    pub fn new(template: Ensemble, alphas: &[f64]) -> Result<Self, AnalysisError> {
        let laws = alphas
            .iter()
            .map(|&a| SpinLaw::new(a))
            .collect::<Result<Vec<_>, _>>()?;
        if laws.is_empty() {
            return Err(AnalysisError::invalid("alphas", "the sweep has no points"));
        }
        Ok(Self::from_laws(template, laws))
    }

    /// A sweep of `template` over `laws` (any α the laws allow).
    pub fn from_laws(template: Ensemble, laws: Vec<SpinLaw>) -> Self {
        AlphaSweep {
            template,
            laws,
            stop: None,
        }
    }

    /// Run each point in batches until `rule` stops it (`None`: run each
    /// point's whole index range).
    pub fn with_stop(mut self, rule: impl Into<Option<StopRule>>) -> Self {
        self.stop = rule.into();
        self
    }

    /// The α of each point.
    pub fn alphas(&self) -> Vec<f64> {
        self.laws.iter().map(SpinLaw::alpha).collect()
    }

    /// The ensemble of point `point` (the template with its law).
    ///
    /// # Panics
    /// If `point` is out of range.
    pub fn ensemble(&self, point: usize) -> Ensemble {
        let mut e = self.template.clone();
        e.law = self.laws[point];
        e
    }

    /// Check the sweep before running it.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for no points, and as
    /// [`Ensemble::validate`] and [`StopRule::validate`].
    pub fn validate(&self) -> Result<(), AnalysisError> {
        if self.laws.is_empty() {
            return Err(AnalysisError::invalid("alphas", "the sweep has no points"));
        }
        self.template.validate()?;
        if let Some(rule) = &self.stop {
            rule.validate()?;
        }
        Ok(())
    }

    /// Run every point, silently.
    ///
    /// # Errors
    /// As [`AlphaSweep::validate`], then the first trajectory error.
    pub fn run(&self) -> Result<Vec<LyapunovEstimate>, AnalysisError> {
        self.run_with(|_| {})
    }

    /// Run every point, calling `on_event` when a point starts, after every
    /// batch and when a point finishes (with its estimate). The estimates
    /// come back in sweep order.
    ///
    /// # Errors
    /// As [`AlphaSweep::validate`], then the first trajectory error (the
    /// points finished before it were reported through `on_event`).
    pub fn run_with<F>(&self, mut on_event: F) -> Result<Vec<LyapunovEstimate>, AnalysisError>
    where
        F: FnMut(&SweepEvent<'_>),
    {
        self.validate()?;
        let points = self.laws.len();
        let mut out = Vec::with_capacity(points);
        for point in 0..points {
            let ensemble = self.ensemble(point);
            let alpha = ensemble.alpha();
            on_event(&SweepEvent::Started {
                point,
                points,
                alpha,
            });
            let estimate = run_ensemble(&ensemble, self.stop.as_ref(), |mut progress| {
                progress.point = point;
                progress.points = points;
                on_event(&SweepEvent::Batch(&progress));
            })?;
            on_event(&SweepEvent::Finished {
                point,
                points,
                estimate: &estimate,
            });
            out.push(estimate);
        }
        Ok(out)
    }
}

/// Run one ensemble in batches, calling `on_batch` after each.
///
/// With a `stop` rule this is [`Ensemble::run_until`] (same batches, same
/// stopping point, bitwise the same numbers); without one, the whole index
/// range in about 20 batches, bitwise the numbers of [`Ensemble::run`]
/// (batches do not change results, only how often progress is reported).
/// The `point`/`points` fields of the progress are 0 and 1.
///
/// # Errors
/// As [`Ensemble::run`] and [`Ensemble::run_until`].
pub fn run_ensemble<F>(
    ensemble: &Ensemble,
    stop: Option<&StopRule>,
    mut on_batch: F,
) -> Result<LyapunovEstimate, AnalysisError>
where
    F: FnMut(BatchProgress),
{
    if let Some(rule) = stop {
        rule.validate()?;
    }
    ensemble.validate()?;
    let clock = Instant::now();
    let Range { start, end } = ensemble.indices;
    let n = end - start;
    let batch = match stop {
        Some(rule) => rule.batch,
        None => n.div_ceil(20).max(64),
    };
    let mut trajectories: Vec<TrajectoryStats> = Vec::new();
    let mut acc = Accumulator::new();
    let mut next = start;
    let reason = loop {
        let hi = next.saturating_add(batch).min(end);
        let part = ensemble.trajectories(next..hi)?;
        for t in &part {
            acc.push(t.exponent);
        }
        trajectories.extend(part);
        next = hi;
        let (mean, sem) = (
            acc.mean().unwrap_or(f64::NAN),
            acc.sem().unwrap_or(f64::NAN),
        );
        on_batch(BatchProgress {
            point: 0,
            points: 1,
            alpha: ensemble.alpha(),
            ics_done: acc.count(),
            ics_max: n,
            mean,
            sem,
            target_rel_sem: stop.map(|r| r.target_rel_sem),
            elapsed_s: clock.elapsed().as_secs_f64(),
        });
        // The same order of checks as `Ensemble::run_until`.
        if let Some(rule) = stop {
            if acc.count() >= rule.min_ics
                && acc.count() >= 2
                && sem <= rule.target_rel_sem * mean.abs()
            {
                break StopReason::TargetReached;
            }
            if rule.time_budget.is_some_and(|b| clock.elapsed() >= b) {
                break StopReason::TimeBudget;
            }
            if next >= end {
                break StopReason::RangeExhausted;
            }
        } else if next >= end {
            break StopReason::Completed;
        }
    };
    let wall = clock.elapsed().as_secs_f64();
    LyapunovEstimate::from_trajectories(ensemble, trajectories, wall, reason)
}

// ---------------------------------------------------------------------------
// Values with errors
// ---------------------------------------------------------------------------

/// A value with its standard error.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Measurement {
    /// The value.
    pub value: f64,
    /// Its standard error (first-order propagation where derived).
    pub sem: f64,
}

impl Measurement {
    /// `value ± sem`.
    pub fn new(value: f64, sem: f64) -> Self {
        Measurement { value, sem }
    }

    /// The mean exponent of an estimate with its SEM.
    pub fn lambda(estimate: &LyapunovEstimate) -> Self {
        Measurement::new(estimate.mean, estimate.sem)
    }

    /// `self / other` for **independent** measurements (relative errors
    /// added in quadrature). Positively correlated inputs (for example the
    /// same initial positions at two α) make this an overestimate.
    pub fn ratio(self, other: Measurement) -> Measurement {
        let r = self.value / other.value;
        let rel = (self.sem / self.value).hypot(other.sem / other.value);
        Measurement::new(r, (r * rel).abs())
    }

    /// `value − other.value` for independent measurements.
    pub fn difference(self, other: Measurement) -> Measurement {
        Measurement::new(self.value - other.value, self.sem.hypot(other.sem))
    }

    /// `sem / |value|`.
    pub fn rel_sem(&self) -> f64 {
        self.sem / self.value.abs()
    }
}

/// The Datseris–Hupe–Fleischmann product `λ · f_ch` of an estimate (at its
/// threshold) with its standard error.
///
/// Both factors are means over the same trajectories (`x_i` and the
/// indicator `c_i = [x_i > threshold]`), so the error is propagated with
/// their covariance: `Var(λ f) ≈ (f² s_x² + λ² s_c² + 2 λ f s_xc) / n`.
/// DH scaling (`λ ∝ 1/f_ch`) predicts the product constant in α; the paper
/// finds it falls by a factor 2–3 (its appendix on DH scaling).
pub fn dhf_product(estimate: &LyapunovEstimate) -> Measurement {
    let t = &estimate.trajectories;
    let n = t.len() as f64;
    let (lam, f) = (estimate.mean, estimate.chaotic_fraction);
    let value = lam * f;
    if t.len() < 2 {
        return Measurement::new(value, f64::NAN);
    }
    let (mut sxx, mut scc, mut sxc) = (0.0, 0.0, 0.0);
    for s in t {
        let dx = s.exponent - lam;
        let dc = f64::from(u8::from(s.exponent > estimate.threshold)) - f;
        sxx += dx * dx;
        scc += dc * dc;
        sxc += dx * dc;
    }
    let var = (f * f * sxx + lam * lam * scc + 2.0 * lam * f * sxc) / ((n - 1.0) * n);
    Measurement::new(value, var.max(0.0).sqrt())
}

/// Collision rate `ν` and exponent per collision `λ/ν` of an estimate, from
/// its per-trajectory times (see [`collision_rate_summary`]: mean of the
/// per-trajectory rates, and the paper's `λ̄/ν̄` with an error that accounts
/// for the correlation of `λ` and `ν` over trajectories).
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for an estimate with fewer than two
/// trajectories or one with zero time.
pub fn rate_summary(estimate: &LyapunovEstimate) -> Result<RateSummary, AnalysisError> {
    let runs: Vec<Lyapunov> = estimate
        .trajectories
        .iter()
        .map(|s| Lyapunov {
            exponent: s.exponent,
            per_collision: s.per_collision,
            time: s.time,
            collisions: s.collisions,
            history: Vec::new(),
        })
        .collect();
    collision_rate_summary(&runs)
}

/// `λ(α)/λ(α₀)` for every estimate, with `α₀` the first one's (a sweep that
/// starts at α = 0 gives the paper's normalised curve). Errors combine the
/// two SEMs as for independent runs ([`Measurement::ratio`]).
pub fn normalised(estimates: &[LyapunovEstimate]) -> Vec<Measurement> {
    let Some(first) = estimates.first() else {
        return Vec::new();
    };
    let reference = Measurement::lambda(first);
    estimates
        .iter()
        .enumerate()
        .map(|(i, e)| {
            if i == 0 {
                // Exactly 1; its own error is carried by the other points.
                Measurement::new(1.0, 0.0)
            } else {
                Measurement::lambda(e).ratio(reference)
            }
        })
        .collect()
}

/// The paired difference `b − a` of the per-trajectory exponents of two
/// estimates over their common initial conditions (same seed, table, α and
/// sampler; for example the finite-difference and exact-tangent methods),
/// with the standard error of the mean difference. Pairs remove the
/// trajectory-to-trajectory spread that dominates each SEM alone.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] if the estimates do not share a seed,
/// table, α, sampler, first index and collisions, or share fewer than two
/// initial conditions.
pub fn paired_difference(
    a: &LyapunovEstimate,
    b: &LyapunovEstimate,
) -> Result<Measurement, AnalysisError> {
    if a.seed != b.seed
        || a.table != b.table
        || a.alpha.to_bits() != b.alpha.to_bits()
        || a.sampler != b.sampler
        || a.first_index != b.first_index
        || a.collisions_per_ic != b.collisions_per_ic
    {
        return Err(AnalysisError::invalid(
            "paired difference",
            "the estimates must share seed, table, alpha, sampler, first index and collisions",
        ));
    }
    let d: Accumulator = a
        .trajectories
        .iter()
        .zip(&b.trajectories)
        .map(|(x, y)| y.exponent - x.exponent)
        .collect();
    match (d.mean(), d.sem()) {
        (Some(m), Some(s)) => Ok(Measurement::new(m, s)),
        _ => Err(AnalysisError::invalid(
            "paired difference",
            "need at least two common initial conditions",
        )),
    }
}

// ---------------------------------------------------------------------------
// Curved share
// ---------------------------------------------------------------------------

/// Share of the boundary length on curved walls: the share of collisions on
/// curved walls at α = 0 under the invariant measure (the billiard map's
/// measure `cos θ ds dθ` gives each wall its share of the perimeter).
/// Stadium `2π/(4a + 2π)` (0.611 at `a = 1`); Sinai `2πR/(8L + 2πR)`
/// (0.282 at `L = 2, R = 1`); circle 1; rectangle 0.
pub fn perimeter_curved_share(table: &Table) -> f64 {
    use std::f64::consts::TAU;
    match table {
        Table::Circle(_) => 1.0,
        Table::Rectangle(_) => 0.0,
        Table::Stadium(s) => TAU / (4.0 * s.a() + TAU),
        Table::Sinai(s) => TAU * s.r() / (8.0 * s.l() + TAU * s.r()),
    }
}

/// The share of collisions on curved walls over an ensemble.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct CurvedShare {
    /// Table spec.
    pub table: String,
    /// Spin parameter.
    pub alpha: f64,
    /// Pooled share: curved collisions over all collisions.
    pub pooled: f64,
    /// Mean over initial conditions of each trajectory's share, with its
    /// SEM (the honest error: collisions of one trajectory are correlated).
    pub per_ic: Measurement,
    /// The α = 0 theory, [`perimeter_curved_share`].
    pub perimeter_share: f64,
    /// Initial conditions.
    pub n_ics: u64,
    /// Collisions per initial condition.
    pub collisions_per_ic: u64,
    /// Wall-clock seconds.
    pub wall_time_s: f64,
    /// All wall statistics, pooled in index order.
    pub stats: WallStatistics,
}

/// [`CurvedShare`] of `table` under `law`: initial conditions `ics` of
/// `seed` drawn with `sampler`, `collisions` each, per-trajectory
/// [`WallStatistics`] merged in index order (the same numbers for any
/// thread count).
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for fewer than two initial conditions or
/// zero collisions; dynamics errors with the failing index.
pub fn curved_share(
    table: &Table,
    law: SpinLaw,
    sampler: Sampler,
    seed: u64,
    ics: Range<u64>,
    collisions: u64,
    threads: Threads,
) -> Result<CurvedShare, AnalysisError> {
    if ics.end.saturating_sub(ics.start) < 2 {
        return Err(AnalysisError::invalid(
            "ics",
            format!("need at least 2 initial conditions, got {ics:?}"),
        ));
    }
    if collisions == 0 {
        return Err(AnalysisError::invalid("collisions", "must be > 0"));
    }
    let clock = Instant::now();
    let parts = table.visit(WallRun {
        law,
        sampler,
        seed,
        ics: ics.clone(),
        collisions,
        threads,
    })?;
    let mut pooled = WallStatistics::new(&law);
    let mut per_ic = Accumulator::new();
    for p in &parts {
        pooled.merge(p)?;
        per_ic.push(p.curved_fraction().unwrap_or(0.0));
    }
    Ok(CurvedShare {
        table: table.to_string(),
        alpha: law.alpha(),
        pooled: pooled.curved_fraction().unwrap_or(0.0),
        per_ic: Measurement::new(
            per_ic.mean().unwrap_or(f64::NAN),
            per_ic.sem().unwrap_or(f64::NAN),
        ),
        perimeter_share: perimeter_curved_share(table),
        n_ics: parts.len() as u64,
        collisions_per_ic: collisions,
        wall_time_s: clock.elapsed().as_secs_f64(),
        stats: pooled,
    })
}

struct WallRun {
    law: SpinLaw,
    sampler: Sampler,
    seed: u64,
    ics: Range<u64>,
    collisions: u64,
    threads: Threads,
}

impl TableVisitor for WallRun {
    type Output = Result<Vec<WallStatistics>, AnalysisError>;
    fn visit<B: Boundary + Clone + Send + Sync>(self, table: &B) -> Self::Output {
        let billiard = Billiard::new(table.clone(), self.law);
        map_indices(self.ics, self.threads, |i| {
            let start = self
                .sampler
                .initial_state(billiard.table(), billiard.law(), self.seed, i);
            wall_statistics(&billiard, start, self.collisions).map_err(|e| e.at_index(i))
        })
    }
}

// ---------------------------------------------------------------------------
// Collision rate: what to expect
// ---------------------------------------------------------------------------

/// Mean translational speed `⟨|v|⟩` of the initial conditions `sampler`
/// draws at `alpha` (energy ½, so `|v|² + αu² = 1`).
///
/// - α = 0: both samplers give `|v| = 1`.
/// - Paper sampler, α > 0: `αu² = s²/4` with `s` uniform in `[−1, 1]`, so
///   `⟨|v|⟩ = ∫₀¹ √(1 − s²/4) ds = √3/4 + π/6 ≈ 0.9566`, the same for
///   every α > 0: the speed distribution jumps at α = 0⁺.
/// - Microcanonical, α > 0: `(v, √α u)` uniform on the unit sphere, so
///   `√α u` is uniform in `[−1, 1]` (Archimedes) and
///   `⟨|v|⟩ = ∫₀¹ √(1 − z²) dz = π/4 ≈ 0.7854`, again for every α > 0.
pub fn initial_mean_speed(sampler: Sampler, alpha: f64) -> f64 {
    use std::f64::consts::PI;
    if alpha <= 0.0 {
        return 1.0;
    }
    match sampler {
        Sampler::Paper => 3f64.sqrt() / 4.0 + PI / 6.0,
        Sampler::Microcanonical => PI / 4.0,
    }
}

/// Area of a built-in table: circle `πR²`, rectangle `4LH`, stadium
/// `4a + π` (unit caps), Sinai `4L² − πR²`.
pub fn table_area(table: &Table) -> f64 {
    use std::f64::consts::PI;
    match table {
        Table::Circle(c) => PI * c.radius() * c.radius(),
        Table::Rectangle(r) => 4.0 * r.l() * r.h(),
        Table::Stadium(s) => 4.0 * s.a() + PI,
        Table::Sinai(s) => 4.0 * s.l() * s.l() - PI * s.r() * s.r(),
    }
}

/// The collision rate of the invariant (Liouville) measure at `alpha`:
/// `ν = ⟨|v|⟩ · |∂Q| / (π |Q|)`, Santaló's mean free path `π|Q|/|∂Q|`
/// travelled at the mean speed of the microcanonical measure (1 at α = 0,
/// π/4 for every α > 0, see [`initial_mean_speed`]). A long, ergodic run
/// from any start has this rate; regular islands and finite runs from the
/// paper's sampler (which starts faster, at `⟨|v|⟩ ≈ 0.957`, and relaxes
/// slowly when the coupling `γ = 2α/(1+α)` is small) deviate from it.
pub fn liouville_collision_rate(table: &Table, alpha: f64) -> f64 {
    use std::f64::consts::PI;
    initial_mean_speed(Sampler::Microcanonical, alpha) * table.perimeter()
        / (PI * table_area(table))
}

// ---------------------------------------------------------------------------
// Rows: CSV, serde, text tables
// ---------------------------------------------------------------------------

/// One estimate as a flat record: what a CSV row or a JSON point holds (no
/// per-trajectory data), with the derived quantities the paper's figures
/// plot. Serialisable with the `serde` feature.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct SweepRow {
    /// Table spec (e.g. `stadium:a=1`).
    pub table: String,
    /// Spin parameter.
    pub alpha: f64,
    /// `fd` or `tangent`.
    pub method: String,
    /// `paper` or `microcanonical`.
    pub sampler: String,
    /// Mean FTLE λ (per unit time).
    pub mean: f64,
    /// Its standard error.
    pub sem: f64,
    /// Median FTLE.
    pub median: f64,
    /// Standard deviation of the FTLEs.
    pub std: f64,
    /// Mean FTLE of the chaotic trajectories (`None`: none above threshold).
    pub conditional_mean: Option<f64>,
    /// Chaos threshold.
    pub threshold: f64,
    /// Share of trajectories with FTLE > threshold.
    pub chaotic_fraction: f64,
    /// Its binomial standard error.
    pub chaotic_fraction_sem: f64,
    /// Smallest chaotic fraction over thresholds 0.001–0.05 ([`THRESHOLD_BAND`]).
    pub chaotic_fraction_band_min: f64,
    /// Largest chaotic fraction over thresholds 0.001–0.05.
    pub chaotic_fraction_band_max: f64,
    /// The DH product `λ · f_ch` ([`dhf_product`]).
    pub dhf_product: f64,
    /// Its standard error.
    pub dhf_product_sem: f64,
    /// Collision rate `ν`: mean over trajectories of collisions / time.
    pub collision_rate: f64,
    /// Its standard error.
    pub collision_rate_sem: f64,
    /// Exponent per collision `λ̄/ν̄` (the paper's `λ_coll`).
    pub per_collision: f64,
    /// Its standard error.
    pub per_collision_sem: f64,
    /// Initial conditions.
    pub n_ics: u64,
    /// Collisions per initial condition.
    pub collisions_per_ic: u64,
    /// First initial-condition index.
    pub first_index: u64,
    /// Seed.
    pub seed: u64,
    /// Wall-clock seconds for this point.
    pub wall_time_s: f64,
    /// Why the point stopped (`completed`, `target_reached`, ...).
    pub stop: String,
    /// Crate version that computed it.
    pub version: String,
}

/// The CSV header matching [`SweepRow::csv_line`].
pub const CSV_HEADER: &str = "table,alpha,method,sampler,mean,sem,median,std,conditional_mean,\
threshold,chaotic_fraction,chaotic_fraction_sem,chaotic_fraction_band_min,chaotic_fraction_band_max,\
dhf_product,dhf_product_sem,collision_rate,collision_rate_sem,per_collision,per_collision_sem,\
n_ics,collisions_per_ic,first_index,seed,wall_time_s,stop,version";

impl SweepRow {
    /// The record of `estimate`.
    ///
    /// # Errors
    /// Only for an estimate whose trajectories were emptied or altered
    /// after it was built (fewer than two, zero time, non-finite).
    pub fn from_estimate(estimate: &LyapunovEstimate) -> Result<Self, AnalysisError> {
        let band = estimate.ftle()?.chaotic_fraction_band(&THRESHOLD_BAND);
        let rates = rate_summary(estimate)?;
        let dhf = dhf_product(estimate);
        Ok(SweepRow {
            table: estimate.table.clone(),
            alpha: estimate.alpha,
            method: estimate.method.clone(),
            sampler: estimate.sampler.name().to_string(),
            mean: estimate.mean,
            sem: estimate.sem,
            median: estimate.median,
            std: estimate.std,
            conditional_mean: estimate.conditional_mean,
            threshold: estimate.threshold,
            chaotic_fraction: estimate.chaotic_fraction,
            chaotic_fraction_sem: estimate.chaotic_fraction_sem,
            chaotic_fraction_band_min: band.min,
            chaotic_fraction_band_max: band.max,
            dhf_product: dhf.value,
            dhf_product_sem: dhf.sem,
            collision_rate: rates.rate_mean,
            collision_rate_sem: rates.rate_sem,
            per_collision: rates.per_collision,
            per_collision_sem: rates.per_collision_sem,
            n_ics: estimate.n_ics,
            collisions_per_ic: estimate.collisions_per_ic,
            first_index: estimate.first_index,
            seed: estimate.seed,
            wall_time_s: estimate.wall_time_s,
            stop: estimate.stop.name().to_string(),
            version: estimate.version.clone(),
        })
    }

    /// The row as CSV (fields in [`CSV_HEADER`] order, numbers in Rust's
    /// shortest round-trip form, the table spec quoted, an absent
    /// conditional mean empty), without a newline.
    pub fn csv_line(&self) -> String {
        let opt = |x: Option<f64>| x.map_or(String::new(), |v| v.to_string());
        let mut s = String::new();
        let _ = write!(
            s,
            "\"{}\",{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            self.table.replace('"', "\"\""),
            self.alpha,
            self.method,
            self.sampler,
            self.mean,
            self.sem,
            self.median,
            self.std,
            opt(self.conditional_mean),
            self.threshold,
            self.chaotic_fraction,
            self.chaotic_fraction_sem,
            self.chaotic_fraction_band_min,
            self.chaotic_fraction_band_max,
            self.dhf_product,
            self.dhf_product_sem,
            self.collision_rate,
            self.collision_rate_sem,
            self.per_collision,
            self.per_collision_sem,
            self.n_ics,
            self.collisions_per_ic,
            self.first_index,
            self.seed,
            self.wall_time_s,
            self.stop,
            self.version
        );
        s
    }

    /// The header of [`SweepRow::table_line`].
    pub fn table_header() -> String {
        format!(
            "{:>7} {:>9} {:>8} {:>6} {:>6} {:>9} {:>7} {:>8} {:>8}",
            "alpha", "lambda", "SEM", "rel%", "f_ch", "median", "ICs", "time/s", "stop"
        )
    }

    /// A fixed-width line for a terminal table: α, λ, SEM, SEM/λ in %,
    /// chaotic fraction, median, ICs, time, stop reason.
    pub fn table_line(&self) -> String {
        let stop = match self.stop.as_str() {
            "target_reached" => "target",
            "time_budget" => "budget",
            "range_exhausted" => "cap",
            "completed" => "done",
            other => other,
        };
        format!(
            "{:>7.4} {:>9} {:>8} {:>6.2} {:>6.3} {:>9} {:>7} {:>8.2} {:>8}",
            self.alpha,
            fixed_or_sci(self.mean, 5),
            fixed_or_sci(self.sem, 5),
            100.0 * self.sem / self.mean.abs(),
            self.chaotic_fraction,
            fixed_or_sci(self.median, 5),
            self.n_ics,
            self.wall_time_s,
            stop
        )
    }
}

/// `x` with `decimals` decimals, or in scientific notation with 2 when that
/// would show fewer than three significant digits.
fn fixed_or_sci(x: f64, decimals: i32) -> String {
    if x != 0.0 && x.abs() < 10f64.powi(2 - decimals) {
        format!("{x:.2e}")
    } else {
        format!("{x:.prec$}", prec = decimals as usize)
    }
}

/// The records of `estimates`, in order.
///
/// # Errors
/// As [`SweepRow::from_estimate`].
pub fn sweep_rows(estimates: &[LyapunovEstimate]) -> Result<Vec<SweepRow>, AnalysisError> {
    estimates.iter().map(SweepRow::from_estimate).collect()
}

/// Write `rows` as CSV with the [`CSV_HEADER`] line.
///
/// # Errors
/// The writer's errors.
pub fn write_csv<W: io::Write>(mut w: W, rows: &[SweepRow]) -> io::Result<()> {
    writeln!(w, "{CSV_HEADER}")?;
    for r in rows {
        writeln!(w, "{}", r.csv_line())?;
    }
    Ok(())
}

/// The CSV text (header and one line per estimate) of `estimates`.
///
/// # Errors
/// As [`SweepRow::from_estimate`].
pub fn csv_string(estimates: &[LyapunovEstimate]) -> Result<String, AnalysisError> {
    let mut out = Vec::new();
    write_csv(&mut out, &sweep_rows(estimates)?).expect("writing to a Vec cannot fail");
    Ok(String::from_utf8(out).expect("the CSV is UTF-8"))
}

// ---------------------------------------------------------------------------
// Grids
// ---------------------------------------------------------------------------

/// `n` equally spaced values from `lo` to `hi` inclusive (`numpy.linspace`;
/// the ends are exact). `n = 1` gives `[lo]`, `n = 0` nothing.
pub fn linspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    match n {
        0 => Vec::new(),
        1 => vec![lo],
        _ => (0..n)
            .map(|i| {
                if i == n - 1 {
                    hi
                } else {
                    lo + (hi - lo) * i as f64 / (n - 1) as f64
                }
            })
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Method;
    use spinball_geometry::{Sinai, Stadium};

    fn at(e: Ensemble, alpha: f64) -> Ensemble {
        let mut e = e;
        e.law = SpinLaw::new(alpha).unwrap();
        e
    }

    fn template() -> Ensemble {
        Ensemble::new(Stadium::new(1.0).unwrap(), SpinLaw::specular())
            .with_seed(5)
            .with_ics(40)
            .with_collisions(300)
            .with_threads(Threads::Fixed(1))
    }

    fn same_numbers(a: &LyapunovEstimate, b: &LyapunovEstimate) {
        let mut b = b.clone();
        b.wall_time_s = a.wall_time_s;
        assert_eq!(a, &b);
    }

    #[test]
    fn sweep_without_rule_equals_plain_runs() {
        let sweep = AlphaSweep::new(template().with_ics(150), &[0.0, 0.5]).unwrap();
        let got = sweep.run().unwrap();
        assert_eq!(got.len(), 2);
        for (i, e) in got.iter().enumerate() {
            assert_eq!(e.stop, StopReason::Completed);
            same_numbers(e, &sweep.ensemble(i).run().unwrap());
        }
    }

    #[test]
    fn sweep_with_rule_equals_run_until() {
        let rule = StopRule::new(8, 0.05).with_min_ics(16);
        let sweep = AlphaSweep::new(template(), &[0.0, 0.3, 1.0])
            .unwrap()
            .with_stop(rule);
        let got = sweep.run().unwrap();
        for (i, e) in got.iter().enumerate() {
            let reference = sweep.ensemble(i).run_until(&rule).unwrap();
            assert_eq!(e.stop, reference.stop);
            same_numbers(e, &reference);
        }
        // α = 0 is uniformly chaotic: the target is reached early.
        assert_eq!(got[0].stop, StopReason::TargetReached);
        assert!(got[0].n_ics < 40);
    }

    #[test]
    fn events_arrive_in_order() {
        let sweep = AlphaSweep::new(template(), &[0.0, 1.0])
            .unwrap()
            .with_stop(StopRule::new(10, 0.0)); // never reached: whole range
        let mut log = Vec::new();
        let got = sweep
            .run_with(|e| match e {
                SweepEvent::Started { point, points, .. } => log.push(format!("S{point}/{points}")),
                SweepEvent::Batch(p) => {
                    assert_eq!(p.ics_max, 40);
                    assert_eq!(p.target_rel_sem, Some(0.0));
                    log.push(format!("B{}:{}", p.point, p.ics_done));
                }
                SweepEvent::Finished {
                    point, estimate, ..
                } => log.push(format!("F{point}:{}", estimate.n_ics)),
            })
            .unwrap();
        let expect: Vec<String> = [0, 1]
            .iter()
            .flat_map(|p| {
                std::iter::once(format!("S{p}/2"))
                    .chain((1..=4).map(move |k| format!("B{p}:{}", 10 * k)))
                    .chain(std::iter::once(format!("F{p}:40")))
            })
            .collect();
        assert_eq!(log, expect);
        assert!(got.iter().all(|e| e.stop == StopReason::RangeExhausted));
    }

    #[test]
    fn invalid_sweeps_are_errors() {
        assert!(AlphaSweep::new(template(), &[]).is_err());
        assert!(matches!(
            AlphaSweep::new(template(), &[0.5, 1.5]),
            Err(AnalysisError::SpinLaw(_))
        ));
        let extended = AlphaSweep::from_laws(template(), vec![SpinLaw::extended(2.0).unwrap()]);
        assert_eq!(extended.alphas(), vec![2.0]);
        let bad_rule = AlphaSweep::new(template(), &[0.0])
            .unwrap()
            .with_stop(StopRule::new(1, 0.01));
        assert!(bad_rule.run().is_err());
        let one_ic = AlphaSweep::new(template().with_ics(1), &[0.0]).unwrap();
        assert!(one_ic.run().is_err());
    }

    #[test]
    fn csv_has_header_and_one_line_per_point() {
        let est = AlphaSweep::new(template().with_ics(20), &[0.0, 0.5])
            .unwrap()
            .run()
            .unwrap();
        let csv = csv_string(&est).unwrap();
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 3);
        assert_eq!(lines[0], CSV_HEADER);
        let columns = CSV_HEADER.split(',').count();
        for (line, e) in lines[1..].iter().zip(&est) {
            // The quoted table spec has no comma for the stadium.
            let fields: Vec<&str> = line.split(',').collect();
            assert_eq!(fields.len(), columns, "{line}");
            assert_eq!(fields[0], "\"stadium:a=1\"");
            assert_eq!(fields[1].parse::<f64>().unwrap(), e.alpha);
            assert_eq!(fields[4].parse::<f64>().unwrap(), e.mean); // round trip
            assert_eq!(fields[20].parse::<u64>().unwrap(), 20);
        }
        let row = SweepRow::from_estimate(&est[1]).unwrap();
        assert!(row.chaotic_fraction_band_min <= row.chaotic_fraction);
        assert!(row.chaotic_fraction <= row.chaotic_fraction_band_max);
        assert!(row.table_line().len() == SweepRow::table_header().len());
    }

    #[test]
    fn rectangle_spec_is_quoted_in_csv() {
        let e = Ensemble::new(
            "rectangle:L=1,H=1".parse::<Table>().unwrap(),
            SpinLaw::new(0.3).unwrap(),
        )
        .with_ics(4)
        .with_collisions(100)
        .with_threads(Threads::Fixed(1))
        .run()
        .unwrap();
        let csv = csv_string(&[e]).unwrap();
        assert!(
            csv.lines()
                .nth(1)
                .unwrap()
                .starts_with("\"rectangle:L=1,H=1\",0.3,fd,paper,")
        );
    }

    #[test]
    fn dhf_product_error_matches_bootstrap_scale() {
        let e = at(template(), 1.0)
            .with_ics(300)
            .with_collisions(500)
            .with_seed(9)
            .run()
            .unwrap();
        let p = dhf_product(&e);
        assert_eq!(p.value, e.mean * e.chaotic_fraction);
        // The product's relative error is of the order of λ's.
        assert!(
            p.sem > 0.3 * e.sem * e.chaotic_fraction && p.sem < 3.0 * e.sem,
            "{p:?} {e}"
        );
        // The same number as the FTLE distribution's product.
        assert_eq!(p.value, e.ftle().unwrap().dhf_product(e.threshold));
    }

    #[test]
    fn rates_normalisation_and_pairs() {
        let fd = at(template(), 0.5).with_ics(60).run().unwrap();
        let tangent = at(template(), 0.5)
            .with_ics(60)
            .with_method(Method::Tangent)
            .run()
            .unwrap();
        let r = rate_summary(&fd).unwrap();
        assert!(r.rate_mean > 0.2 && r.rate_mean < 2.0 && r.rate_sem > 0.0);
        assert!((r.per_collision - fd.mean / r.rate_mean).abs() < 1e-15);
        let d = paired_difference(&fd, &tangent).unwrap();
        // Same initial conditions and directions: the methods agree far
        // better than either SEM.
        assert!(
            d.value.abs() < 0.2 * fd.sem && d.sem < 0.2 * fd.sem,
            "{d:?}"
        );
        let other_alpha = template().with_ics(60).run().unwrap();
        assert!(paired_difference(&fd, &other_alpha).is_err());

        let n = normalised(&[other_alpha.clone(), fd.clone()]);
        assert_eq!(n[0], Measurement::new(1.0, 0.0));
        assert!((n[1].value - fd.mean / other_alpha.mean).abs() < 1e-15);
        assert!(n[1].sem > 0.0);
        assert!(normalised(&[]).is_empty());
    }

    #[test]
    fn measurement_rules() {
        let a = Measurement::new(2.0, 0.2);
        let b = Measurement::new(4.0, 0.4);
        let r = a.ratio(b);
        assert!((r.value - 0.5).abs() < 1e-15);
        assert!((r.sem - 0.5 * 0.1 * 2f64.sqrt()).abs() < 1e-15);
        let d = b.difference(a);
        assert_eq!(d.value, 2.0);
        assert!((d.sem - 0.2 * 5f64.sqrt()).abs() < 1e-15);
        assert!((a.rel_sem() - 0.1).abs() < 1e-15);
    }

    #[test]
    fn curved_share_of_tables() {
        let stadium: Table = Stadium::new(1.0).unwrap().into();
        let theory = perimeter_curved_share(&stadium);
        assert!((theory - 0.6110).abs() < 1e-4);
        let sinai: Table = Sinai::new(2.0, 1.0).unwrap().into();
        assert!((perimeter_curved_share(&sinai) - 0.2820).abs() < 1e-4);
        let share = curved_share(
            &stadium,
            SpinLaw::specular(),
            Sampler::Paper,
            3,
            0..40,
            2_000,
            Threads::Fixed(2),
        )
        .unwrap();
        assert_eq!((share.n_ics, share.collisions_per_ic), (40, 2_000));
        assert_eq!(share.stats.collisions, 80_000);
        assert!((share.pooled - theory).abs() < 0.03, "{}", share.pooled);
        assert!((share.per_ic.value - share.pooled).abs() < 1e-12); // equal lengths
        assert!(share.per_ic.sem > 0.0 && share.per_ic.sem < 0.02);
        let again = curved_share(
            &stadium,
            SpinLaw::specular(),
            Sampler::Paper,
            3,
            0..40,
            2_000,
            Threads::Fixed(1),
        )
        .unwrap();
        assert_eq!(again.stats, share.stats);
        assert!(
            curved_share(
                &stadium,
                SpinLaw::specular(),
                Sampler::Paper,
                3,
                0..1,
                10,
                Threads::All
            )
            .is_err()
        );
    }

    #[test]
    fn collision_rate_expectations() {
        let stadium: Table = Stadium::new(1.0).unwrap().into();
        let nu0 = liouville_collision_rate(&stadium, 0.0);
        assert!((nu0 - 0.4583).abs() < 1e-4, "{nu0}");
        let ratio = liouville_collision_rate(&stadium, 0.5) / nu0;
        assert!((ratio - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        assert!((initial_mean_speed(Sampler::Paper, 0.3) - 0.95661).abs() < 1e-5);
        assert_eq!(initial_mean_speed(Sampler::Microcanonical, 0.0), 1.0);
        // The sampled speeds agree with the formulas.
        let law = SpinLaw::new(0.3).unwrap();
        for sampler in [Sampler::Paper, Sampler::Microcanonical] {
            let n = 20_000;
            let mean = (0..n)
                .map(|i| {
                    sampler
                        .initial_state(&stadium, &law, 1, i)
                        .velocity
                        .length()
                })
                .sum::<f64>()
                / n as f64;
            assert!(
                (mean - initial_mean_speed(sampler, 0.3)).abs() < 0.01,
                "{sampler}"
            );
        }
        // A specular run reproduces Santaló's rate.
        let e = template()
            .with_ics(64)
            .with_collisions(2_000)
            .run()
            .unwrap();
        let r = rate_summary(&e).unwrap();
        assert!((r.rate_mean - nu0).abs() < 0.01, "{}", r.rate_mean);
        let sinai: Table = Sinai::new(2.0, 1.0).unwrap().into();
        assert!((table_area(&sinai) - (16.0 - std::f64::consts::PI)).abs() < 1e-12);
    }

    #[test]
    fn small_numbers_keep_their_digits() {
        assert_eq!(fixed_or_sci(0.43027, 5), "0.43027");
        assert_eq!(fixed_or_sci(0.00013, 5), "1.30e-4");
        assert_eq!(fixed_or_sci(0.0, 5), "0.00000");
        assert_eq!(fixed_or_sci(-0.00061, 5), "-6.10e-4");
        assert_eq!(fixed_or_sci(0.0012, 5), "0.00120");
    }

    #[test]
    fn linspace_ends_are_exact() {
        assert_eq!(linspace(0.0, 1.0, 0), Vec::<f64>::new());
        assert_eq!(linspace(0.5, 1.0, 1), vec![0.5]);
        let g = linspace(0.0, 1.0, 50);
        assert_eq!((g.len(), g[0], g[49]), (50, 0.0, 1.0));
        assert!((g[1] - 1.0 / 49.0).abs() < 1e-16);
        assert_eq!(linspace(0.0, 1.0, 11)[3], 0.3);
    }
}
