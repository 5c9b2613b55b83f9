//! The paper's other diagnostics: how fast neighbours separate, how often the
//! ball hits a wall, what kind of wall, what `Q` does between walls, and
//! whether energy stays put.
//!
//! The Lyapunov exponent is one number; these diagnostics are the evidence
//! behind the paper's explanation of it (§V "Phase space analysis", §VI
//! "Conserved quantity and mechanism", and the appendices on energy,
//! collision rate and the conserved quantity). Each is an [`Observer`] where
//! that is natural, so it rides along any run, plus a convenience function
//! for one trajectory and one for an ensemble (deterministic: initial
//! condition `i` from its own stream, results combined in index order, so the
//! numbers do not depend on the thread count).
//!
//! - [`phase_space_separation`]: `⟨ln(δ_n/δ0)⟩` over pairs, per collision,
//!   without renormalisation (paper §V.A: 50 collisions, 8000 pairs,
//!   `δ0 = 1e-7`, random 5-D direction). Linear growth means exponential
//!   divergence (chaos), logarithmic growth means shear (integrable tables).
//! - [`CollisionRate`], [`per_collision_exponent`],
//!   [`collision_rate_summary`]: `ν = collisions / time` and `λ/ν`
//!   (paper, appendix "Collision rate").
//! - [`WallStatistics`]: wall-transition fractions, the `|ΔQ|` populations
//!   and the share of collisions on curved walls (paper §VI, §VIII, appendix
//!   "Conserved quantity verification").
//! - [`EnergyTrace`]: `|E_n − E_0|` along a run, downsampled (paper,
//!   appendix "Energy conservation").
//!
//! What counts as a wall transition, and why no consecutive pair keeps `Q`,
//! is documented on [`WallStatistics`]; the curved share against theory and
//! the paper on [`WallStatistics::curved_fraction`].

use std::ops::{Range, RangeInclusive};

use spinball_core::{
    Ball, Billiard, Collision, Observer, Sampler, SpinLaw, State, TangentVector, ic_rng,
};
use spinball_geometry::{Boundary, WallId};

use crate::error::AnalysisError;
use crate::lyapunov::{Lyapunov, PAPER_DELTA0, random_direction};
use crate::parallel::{Threads, map_indices};
use crate::stats::{Accumulator, Histogram};

// ---------------------------------------------------------------------------
// Phase-space separation (paper §V.A)
// ---------------------------------------------------------------------------

/// What to compute for [`phase_space_separation`]. The default is the
/// paper's set-up: 50 collisions, 8000 pairs, `δ0 = 1e-7`, paper sampler.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SeparationOptions {
    /// Collisions per pair.
    pub collisions: usize,
    /// Number of pairs (initial conditions `0..pairs`), at least 2.
    pub pairs: u64,
    /// Initial separation in the 5-D state.
    pub delta0: f64,
    /// How the reference initial conditions are drawn.
    pub sampler: Sampler,
    /// Seed of the initial conditions (pair `i` uses `ic_rng(seed, i)`: the
    /// reference state first, then the direction).
    pub seed: u64,
    /// Threads to use (the result does not depend on it).
    pub threads: Threads,
}

impl Default for SeparationOptions {
    fn default() -> Self {
        SeparationOptions {
            collisions: 50,
            pairs: 8000,
            delta0: PAPER_DELTA0,
            sampler: Sampler::Paper,
            seed: 0,
            threads: Threads::All,
        }
    }
}

impl SeparationOptions {
    /// Check the options.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for zero collisions, fewer than two
    /// pairs (no standard error) or `δ0` not finite and positive.
    pub fn validate(&self) -> Result<(), AnalysisError> {
        if self.collisions == 0 {
            return Err(AnalysisError::invalid("collisions", "must be > 0"));
        }
        if self.pairs < 2 {
            return Err(AnalysisError::invalid(
                "pairs",
                format!("need at least 2 for a standard error, got {}", self.pairs),
            ));
        }
        check_delta0(self.delta0)
    }
}

fn check_delta0(delta0: f64) -> Result<(), AnalysisError> {
    if !(delta0.is_finite() && delta0 > 0.0) {
        return Err(AnalysisError::invalid(
            "delta0",
            format!("must be finite and > 0, got {delta0}"),
        ));
    }
    Ok(())
}

/// A straight line `y = slope·n + intercept` fitted by least squares.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LinearFit {
    /// Slope per collision.
    pub slope: f64,
    /// Value at `n = 0`.
    pub intercept: f64,
}

/// `⟨ln(δ_n/δ0)⟩` over an ensemble of pairs, per collision (paper §V.A).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Separation {
    /// `mean[n − 1]` is `⟨ln(δ_n/δ0)⟩` after collision `n`.
    pub mean: Vec<f64>,
    /// Standard error of each mean.
    pub sem: Vec<f64>,
    /// Number of pairs.
    pub pairs: u64,
    /// Initial separation.
    pub delta0: f64,
    /// Seed of the initial conditions.
    pub seed: u64,
    /// Sampler of the initial conditions.
    pub sampler: Sampler,
}

impl Separation {
    /// Least-squares line through `mean` over the collisions `collisions`
    /// (1-based, inclusive, e.g. `5..=15`). For a chaotic table, fit before
    /// the separation saturates at the table size (`ln(δ/δ0) ≈ ln(1/δ0)`,
    /// about 16 for `δ0 = 1e-7`); the slope is then close to the Lyapunov
    /// exponent **per collision**, `λ/ν` (the paper's remark that 50
    /// collisions reach only `e^15` uses λ per unit time).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] unless the range holds at least two
    /// recorded collisions.
    pub fn fit(&self, collisions: RangeInclusive<usize>) -> Result<LinearFit, AnalysisError> {
        let (a, b) = (*collisions.start(), *collisions.end());
        if a == 0 || b > self.mean.len() || b <= a {
            return Err(AnalysisError::invalid(
                "collisions",
                format!(
                    "fit range {a}..={b} must lie in 1..={} and hold two points",
                    self.mean.len()
                ),
            ));
        }
        let n = (b - a + 1) as f64;
        let xs = || (a..=b).map(|k| k as f64);
        let x_mean = xs().sum::<f64>() / n;
        let y_mean = self.mean[a - 1..b].iter().sum::<f64>() / n;
        let (mut sxy, mut sxx) = (0.0, 0.0);
        for (x, y) in xs().zip(&self.mean[a - 1..b]) {
            sxy += (x - x_mean) * (y - y_mean);
            sxx += (x - x_mean) * (x - x_mean);
        }
        let slope = sxy / sxx;
        Ok(LinearFit {
            slope,
            intercept: y_mean - slope * x_mean,
        })
    }
}

/// `ln(δ_n/δ0)` for `n = 1..=collisions` of one pair: the reference from
/// `start` and a shadow `δ0·direction` away (`direction` is normalised), each
/// taking its own collisions, the 5-D separation measured after each, never
/// renormalised.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for bad `δ0`, zero collisions, a zero
/// direction or a separation that becomes exactly zero; `Launch`/`Step`
/// errors from the dynamics.
pub fn separation_growth<B: Boundary>(
    billiard: &Billiard<B>,
    start: State,
    direction: TangentVector,
    delta0: f64,
    collisions: usize,
) -> Result<Vec<f64>, AnalysisError> {
    check_delta0(delta0)?;
    if collisions == 0 {
        return Err(AnalysisError::invalid("collisions", "must be > 0"));
    }
    let norm = direction.norm();
    if !(norm > 0.0 && norm.is_finite()) {
        return Err(AnalysisError::invalid(
            "direction",
            format!("must be finite and nonzero, has norm {norm}"),
        ));
    }
    let mut ball = billiard.launch(start)?;
    let z = start.to_array();
    let d = (direction * (delta0 / norm)).to_array();
    let mut shadow = Ball::new(
        State::from_array(std::array::from_fn(|i| z[i] + d[i])),
        billiard.law(),
    )?;
    let mut out = Vec::with_capacity(collisions);
    for n in 1..=collisions {
        billiard.step(&mut ball)?;
        billiard.step(&mut shadow)?;
        let a = ball.state().to_array();
        let b = shadow.state().to_array();
        let dist = (0..5).map(|i| (b[i] - a[i]).powi(2)).sum::<f64>().sqrt();
        if !(dist > 0.0 && dist.is_finite()) {
            return Err(AnalysisError::invalid(
                "delta0",
                format!("the separation became {dist} at collision {n}"),
            ));
        }
        out.push((dist / delta0).ln());
    }
    Ok(out)
}

/// The phase-space separation of paper §V.A over an ensemble of pairs.
///
/// Pair `i` draws its reference state from `ic_rng(seed, i)` with the
/// sampler, then a uniformly random 5-D direction from the same stream; see
/// [`separation_growth`]. Means and standard errors are accumulated in index
/// order, so the result is the same for any thread count.
///
/// ```
/// use spinball_analysis::{SeparationOptions, phase_space_separation};
/// use spinball_core::{Billiard, SpinLaw};
/// use spinball_geometry::Stadium;
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.0)?);
/// let options = SeparationOptions { pairs: 200, collisions: 20, ..Default::default() };
/// let sep = phase_space_separation(&billiard, &options)?;
/// let fit = sep.fit(3..=12)?;
/// assert!(fit.slope > 0.5); // exponential divergence, ≈ λ/ν ≈ 0.94 per collision
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// As [`SeparationOptions::validate`] and [`separation_growth`], with the
/// failing pair's index.
pub fn phase_space_separation<B: Boundary + Sync>(
    billiard: &Billiard<B>,
    options: &SeparationOptions,
) -> Result<Separation, AnalysisError> {
    options.validate()?;
    let runs = map_indices(0..options.pairs, options.threads, |i| {
        let mut rng = ic_rng(options.seed, i);
        let start = options
            .sampler
            .sample(billiard.table(), billiard.law(), &mut rng);
        let direction = random_direction(&mut rng);
        separation_growth(
            billiard,
            start,
            direction,
            options.delta0,
            options.collisions,
        )
        .map_err(|e| e.at_index(i))
    })?;
    let mut accs = vec![Accumulator::new(); options.collisions];
    for run in &runs {
        for (acc, &x) in accs.iter_mut().zip(run) {
            acc.push(x);
        }
    }
    let mean = accs.iter().map(|a| a.mean().unwrap_or(0.0)).collect();
    let sem = accs.iter().map(|a| a.sem().unwrap_or(0.0)).collect();
    Ok(Separation {
        mean,
        sem,
        pairs: options.pairs,
        delta0: options.delta0,
        seed: options.seed,
        sampler: options.sampler,
    })
}

// ---------------------------------------------------------------------------
// Collision rate (paper, appendix "Collision rate")
// ---------------------------------------------------------------------------

/// Collisions per unit time, `ν = N / T`, of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CollisionRate {
    /// Collisions counted.
    pub collisions: u64,
    /// Flight time they took.
    pub time: f64,
    /// `ν = collisions / time`.
    pub rate: f64,
}

impl CollisionRate {
    /// The rate of `collisions` collisions in `time`.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for zero collisions or a time that is
    /// not finite and positive.
    pub fn new(collisions: u64, time: f64) -> Result<Self, AnalysisError> {
        if collisions == 0 {
            return Err(AnalysisError::invalid("collisions", "must be > 0"));
        }
        if !(time.is_finite() && time > 0.0) {
            return Err(AnalysisError::invalid(
                "time",
                format!("must be finite and > 0, got {time}"),
            ));
        }
        Ok(CollisionRate {
            collisions,
            time,
            rate: collisions as f64 / time,
        })
    }

    /// The collision rate of the trajectory behind a Lyapunov result.
    ///
    /// # Errors
    /// As [`CollisionRate::new`] (only for a hand-made, empty result).
    pub fn of(lyapunov: &Lyapunov) -> Result<Self, AnalysisError> {
        Self::new(lyapunov.collisions, lyapunov.time)
    }
}

/// The exponent per collision, `λ_coll = λ/ν` (paper, appendix "Collision
/// rate"). Equal to [`Lyapunov::per_collision`]; written out here because it
/// is how the paper separates "less chaos" from "fewer collisions".
pub fn per_collision_exponent(lyapunov: &Lyapunov) -> f64 {
    lyapunov.exponent * lyapunov.time / lyapunov.collisions as f64
}

/// Collision rate and exponents over an ensemble of trajectories.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RateSummary {
    /// Number of trajectories.
    pub n: u64,
    /// Mean collision rate `ν̄` over trajectories.
    pub rate_mean: f64,
    /// Its standard error.
    pub rate_sem: f64,
    /// Mean exponent per unit time `λ̄`.
    pub exponent_mean: f64,
    /// Its standard error.
    pub exponent_sem: f64,
    /// The paper's per-collision exponent `λ̄/ν̄` (ratio of the means).
    pub per_collision: f64,
    /// Its standard error (first-order error propagation with the covariance
    /// of `λ` and `ν` over trajectories).
    pub per_collision_sem: f64,
    /// Mean of the per-trajectory `λ_i/ν_i` (differs from `λ̄/ν̄` when `λ`
    /// and `ν` are correlated).
    pub mean_per_collision: f64,
    /// Its standard error.
    pub mean_per_collision_sem: f64,
}

/// [`RateSummary`] of Lyapunov results (in the order given; pass them in
/// index order for bitwise reproducibility).
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for fewer than two results or a result
/// with zero collisions or time.
pub fn collision_rate_summary(results: &[Lyapunov]) -> Result<RateSummary, AnalysisError> {
    if results.len() < 2 {
        return Err(AnalysisError::invalid(
            "results",
            format!("need at least 2 trajectories, got {}", results.len()),
        ));
    }
    let (mut nu, mut lam, mut per) = (Accumulator::new(), Accumulator::new(), Accumulator::new());
    for r in results {
        let rate = CollisionRate::of(r)?.rate;
        nu.push(rate);
        lam.push(r.exponent);
        per.push(r.exponent / rate);
    }
    let (nu_m, lam_m) = (nu.mean().unwrap_or(0.0), lam.mean().unwrap_or(0.0));
    let n = results.len() as f64;
    let cov = results
        .iter()
        .map(|r| (r.exponent - lam_m) * (r.collisions as f64 / r.time - nu_m))
        .sum::<f64>()
        / (n - 1.0);
    let ratio = lam_m / nu_m;
    let (var_l, var_n) = (lam.variance().unwrap_or(0.0), nu.variance().unwrap_or(0.0));
    let var_ratio = (var_l + ratio * ratio * var_n - 2.0 * ratio * cov) / (nu_m * nu_m * n);
    Ok(RateSummary {
        n: results.len() as u64,
        rate_mean: nu_m,
        rate_sem: nu.sem().unwrap_or(0.0),
        exponent_mean: lam_m,
        exponent_sem: lam.sem().unwrap_or(0.0),
        per_collision: ratio,
        per_collision_sem: var_ratio.max(0.0).sqrt(),
        mean_per_collision: per.mean().unwrap_or(0.0),
        mean_per_collision_sem: per.sem().unwrap_or(0.0),
    })
}

// ---------------------------------------------------------------------------
// Wall statistics (paper §VI, §VIII, appendix "Conserved quantity")
// ---------------------------------------------------------------------------

/// When two consecutive collisions count as a wall transition. See
/// [`WallStatistics`] for what each gives.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum TransitionRule {
    /// The oriented tangent changes (`|t̂_k × t̂_{k+1}| > tol` or
    /// `t̂_k·t̂_{k+1} < 1 − tol`): exactly the pairs where `ΔQ ≠ 0`. Every
    /// consecutive pair, in every table.
    Tangent,
    /// The tangent *line* turns (`|t̂_k × t̂_{k+1}| > tol`): facing parallel
    /// walls (stadium flats, opposite box walls) count as the same direction.
    /// Reproduces the paper's stadium band (0.80–0.84).
    Direction,
    /// The wall id changes (consecutive hits on one stadium cap count as the
    /// same wall). Gives the paper's Sinai `f_trans = 1`.
    Wall,
}

/// A population of `|ΔQ|` values, binned in `log10` (quarter decades from
/// `1e-20` to `1e2`; zeros and smaller values go to the underflow count),
/// with the exact count and maximum.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct DeltaQPopulation {
    /// Histogram of `log10 |ΔQ|`.
    pub log10: Histogram,
    /// Number of values.
    pub count: u64,
    /// Largest `|ΔQ|` (0 when empty).
    pub max: f64,
}

impl Default for DeltaQPopulation {
    fn default() -> Self {
        DeltaQPopulation {
            log10: Histogram::new(-20.0, 2.0, 88).expect("valid bins"),
            count: 0,
            max: 0.0,
        }
    }
}

impl DeltaQPopulation {
    /// Add `|ΔQ|`.
    #[inline]
    pub fn push(&mut self, dq: f64) {
        let a = dq.abs();
        self.count += 1;
        self.max = self.max.max(a);
        self.log10.push(a.log10());
    }

    /// The `p`-quantile of `|ΔQ|` to the resolution of the bins (a quarter
    /// decade): the geometric centre of the bin where the cumulative count
    /// reaches `p`. `Some(0.0)` if it falls in the underflow (`< 1e-20`,
    /// zeros included), `None` for an empty population or `p` outside `[0, 1]`.
    pub fn quantile(&self, p: f64) -> Option<f64> {
        if self.count == 0 || !(0.0..=1.0).contains(&p) {
            return None;
        }
        let target = (p * self.count as f64).ceil().max(1.0) as u64;
        let mut seen = self.log10.underflow();
        if seen >= target {
            return Some(0.0);
        }
        for (i, &c) in self.log10.counts().iter().enumerate() {
            seen += c;
            if seen >= target {
                return Some(10f64.powf(self.log10.center(i)));
            }
        }
        Some(self.max)
    }

    /// The median `|ΔQ|` to a quarter decade (see [`quantile`](Self::quantile)).
    pub fn median(&self) -> Option<f64> {
        self.quantile(0.5)
    }

    fn merge(&mut self, other: &DeltaQPopulation) -> Result<(), AnalysisError> {
        self.log10.merge(&other.log10)?;
        self.count += other.count;
        self.max = self.max.max(other.max);
        Ok(())
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct Previous {
    tangent: [f64; 2],
    wall: WallId,
    q_after: f64,
}

/// An [`Observer`] of wall statistics: collision rate, curved share, the
/// three kinds of consecutive pairs and the `|ΔQ|` populations (paper §VI).
///
/// # `Q` between collisions, and what "transition" means
/// `Q = v∥ − αu` (paper eq. 12) is unchanged *through* every collision
/// (eq. 13), but `v∥ = v·t̂` is measured with the tangent of the wall being
/// hit, so from one collision to the next it changes by
/// `ΔQ = Q_{k+1} − Q_k^after = v·(t̂_{k+1} − t̂_k)` (free flight keeps `v`
/// and `u`). It is exactly zero only if the two tangents are equal, and that
/// never happens for consecutive collisions: leaving wall `k` means
/// `v·n̂_k > 0`, reaching wall `k+1` needs `v·n̂_{k+1} < 0`, so
/// `n̂_{k+1} ≠ n̂_k` (any table, any α). [`WallStatistics`] therefore sorts
/// consecutive pairs three ways:
///
/// | kind | tangents | `ΔQ` | examples |
/// |---|---|---|---|
/// | same tangent | `t̂_{k+1} = t̂_k` | `0` | impossible for consecutive collisions (counted, for completeness) |
/// | reversed tangent | `t̂_{k+1} = −t̂_k` | `−2 v∥`, O(1) | stadium top ↔ bottom flat wall, opposite box walls |
/// | turned | anything else | O(1) | flat ↔ cap, cap → cap, adjacent box walls, the Sinai disk |
///
/// and reports `f_trans` under three rules ([`TransitionRule`]). Measured
/// with 200 paper-sampler initial conditions × 10⁴ collisions (the paper:
/// 1000): in the stadium `a = 1`, the share of pairs whose tangent *line*
/// turns ([`TransitionRule::Direction`], top ↔ bottom counted as "same
/// direction") is 0.838, 0.846, 0.824, 0.817 at α = 0, 0.1, 0.5, 1, which is
/// the paper's "≈ 80–84 %"; the share of pairs on different walls
/// ([`TransitionRule::Wall`]) is 0.78–0.81; the share whose oriented tangent
/// changes ([`TransitionRule::Tangent`]) is 1 exactly. In the Sinai billiard
/// (`L = 2, R = 1`) the rules give about 0.90–0.92, 1, 1: the paper's "`f_trans = 1`
/// identically" is the wall or tangent rule, its stadium band the direction
/// rule. The paper's "same-wall pairs at `~1e-16`" are the pairs on the
/// same wall *id*: two hits in a row on one stadium cap, where the chord
/// makes equal angles with both tangents, so `ΔQ = 0` up to rounding even
/// though the tangent turns (they are counted as `turned` here; see
/// [`QPairStatistics`](crate::QPairStatistics), which sorts pairs by wall
/// first). Flat walls never give such a population under the physical
/// tangent convention of PHYSICS.md (`t̂ = (n_y, −n_x)`: the two stadium
/// flats have opposite tangents and `Q` jumps by `−2v∥` between them). `Q`
/// through each collision is at machine precision too:
/// [`WallStatistics::dq_collision`].
///
/// ```
/// use spinball_analysis::{TransitionRule, wall_statistics};
/// use spinball_core::{Billiard, Sampler, SpinLaw};
/// use spinball_geometry::Sinai;
///
/// let billiard = Billiard::new(Sinai::new(2.0, 1.0)?, SpinLaw::new(0.5)?);
/// let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 1, 0);
/// let stats = wall_statistics(&billiard, start, 10_000)?;
/// assert_eq!(stats.transition_fraction(TransitionRule::Wall), Some(1.0));
/// assert!(stats.dq_collision.max < 1e-14); // Q through each collision
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct WallStatistics {
    alpha: f64,
    tolerance: f64,
    #[cfg_attr(feature = "serde", serde(skip))]
    previous: Option<Previous>,
    /// Collisions seen.
    pub collisions: u64,
    /// Their total flight time.
    pub time: f64,
    /// Collisions on curved walls (curvature ≠ 0).
    pub curved: u64,
    /// Consecutive pairs seen (within one trajectory).
    pub pairs: u64,
    /// Pairs with the same oriented tangent (`ΔQ = 0`; zero for consecutive
    /// collisions, see above).
    pub same_tangent: u64,
    /// Pairs with opposite tangents (facing parallel walls).
    pub reversed_tangent: u64,
    /// Pairs whose tangent line turns.
    pub turned: u64,
    /// Pairs on different walls (by wall id).
    pub wall_changes: u64,
    /// `|Q_after − Q_before|` through each collision (paper eq. 13: zero up
    /// to rounding).
    pub dq_collision: DeltaQPopulation,
    /// `|ΔQ|` between consecutive collisions with the same tangent.
    pub dq_same_tangent: DeltaQPopulation,
    /// `|ΔQ|` between consecutive collisions with opposite tangents
    /// (`= 2|v∥|`).
    pub dq_reversed_tangent: DeltaQPopulation,
    /// `|ΔQ|` between consecutive collisions whose tangent line turns.
    pub dq_turned: DeltaQPopulation,
}

impl WallStatistics {
    /// Default tolerance for comparing unit tangents.
    pub const DEFAULT_TOLERANCE: f64 = 1e-9;

    /// Empty statistics for runs under `law`.
    pub fn new(law: &SpinLaw) -> Self {
        WallStatistics {
            alpha: law.alpha(),
            tolerance: Self::DEFAULT_TOLERANCE,
            previous: None,
            collisions: 0,
            time: 0.0,
            curved: 0,
            pairs: 0,
            same_tangent: 0,
            reversed_tangent: 0,
            turned: 0,
            wall_changes: 0,
            dq_collision: DeltaQPopulation::default(),
            dq_same_tangent: DeltaQPopulation::default(),
            dq_reversed_tangent: DeltaQPopulation::default(),
            dq_turned: DeltaQPopulation::default(),
        }
    }

    /// Use `tolerance` (in `(0, 0.1]`) when comparing tangents.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] outside that range.
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self, AnalysisError> {
        if !(tolerance > 0.0 && tolerance <= 0.1) {
            return Err(AnalysisError::invalid(
                "tolerance",
                format!("must be in (0, 0.1], got {tolerance}"),
            ));
        }
        self.tolerance = tolerance;
        Ok(self)
    }

    /// α of the law the statistics were taken under.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// The tangent tolerance.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// Forget the last collision, so the next one does not form a pair with
    /// it (call between trajectories when reusing one observer).
    pub fn end_trajectory(&mut self) {
        self.previous = None;
    }

    /// `f_trans`: share of consecutive pairs that are transitions under
    /// `rule` (`None` before any pair).
    pub fn transition_fraction(&self, rule: TransitionRule) -> Option<f64> {
        if self.pairs == 0 {
            return None;
        }
        let k = match rule {
            TransitionRule::Tangent => self.pairs - self.same_tangent,
            TransitionRule::Direction => self.turned,
            TransitionRule::Wall => self.wall_changes,
        };
        Some(k as f64 / self.pairs as f64)
    }

    /// Share of collisions on curved walls (`None` before any collision).
    ///
    /// # Theory and the paper
    /// For α = 0 and the invariant measure, the share of collisions on a wall is
    /// its share of the perimeter: `2π/(4 + 2π) = 0.611` for the stadium `a = 1`,
    /// `2πR/(8L + 2πR)` for Sinai (`0.282` at `R = 1`, `0.105` at `R = 0.3`,
    /// `0.371` at `R = 1.5`). The paper quotes "~50 %" (stadium), "~30 %",
    /// "~15 %", "~50 %" (Sinai `R = 1, 0.3, 1.5`); its Sinai `R ≤ 1` values agree,
    /// the stadium and `R = 1.5` values do not (see `tests/diagnostics.rs`).
    pub fn curved_fraction(&self) -> Option<f64> {
        (self.collisions > 0).then(|| self.curved as f64 / self.collisions as f64)
    }

    /// Pooled collision rate, total collisions over total time.
    pub fn collision_rate(&self) -> Option<f64> {
        (self.collisions > 0 && self.time > 0.0).then(|| self.collisions as f64 / self.time)
    }

    /// Add the counts of `other` (another trajectory or batch). Pairs never
    /// span the two.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if α or the tolerance differ.
    pub fn merge(&mut self, other: &WallStatistics) -> Result<(), AnalysisError> {
        if self.alpha != other.alpha || self.tolerance != other.tolerance {
            return Err(AnalysisError::invalid(
                "wall statistics",
                "cannot merge statistics taken with a different alpha or tolerance",
            ));
        }
        self.collisions += other.collisions;
        self.time += other.time;
        self.curved += other.curved;
        self.pairs += other.pairs;
        self.same_tangent += other.same_tangent;
        self.reversed_tangent += other.reversed_tangent;
        self.turned += other.turned;
        self.wall_changes += other.wall_changes;
        self.dq_collision.merge(&other.dq_collision)?;
        self.dq_same_tangent.merge(&other.dq_same_tangent)?;
        self.dq_reversed_tangent.merge(&other.dq_reversed_tangent)?;
        self.dq_turned.merge(&other.dq_turned)?;
        self.previous = None;
        Ok(())
    }
}

impl Observer for WallStatistics {
    #[inline]
    fn observe(&mut self, c: &Collision, _after: &State) {
        self.collisions += 1;
        self.time += c.time();
        if c.hit.is_curved() {
            self.curved += 1;
        }
        let t = c.tangent();
        let q_after = c.q_after(self.alpha);
        self.dq_collision.push(q_after - c.q);
        if let Some(p) = self.previous {
            self.pairs += 1;
            if p.wall != c.wall() {
                self.wall_changes += 1;
            }
            let cross = p.tangent[0] * t.y - p.tangent[1] * t.x;
            let dot = p.tangent[0] * t.x + p.tangent[1] * t.y;
            let dq = c.q - p.q_after;
            if cross.abs() > self.tolerance {
                self.turned += 1;
                self.dq_turned.push(dq);
            } else if dot > 0.0 {
                self.same_tangent += 1;
                self.dq_same_tangent.push(dq);
            } else {
                self.reversed_tangent += 1;
                self.dq_reversed_tangent.push(dq);
            }
        }
        self.previous = Some(Previous {
            tangent: [t.x, t.y],
            wall: c.wall(),
            q_after,
        });
    }
}

/// [`WallStatistics`] of the trajectory from `start` over `collisions`
/// collisions.
///
/// # Errors
/// `Launch`/`Step` errors from the dynamics.
pub fn wall_statistics<B: Boundary>(
    billiard: &Billiard<B>,
    start: State,
    collisions: u64,
) -> Result<WallStatistics, AnalysisError> {
    let mut ball = billiard.launch(start)?;
    let mut stats = WallStatistics::new(billiard.law());
    billiard.run(&mut ball, collisions, &mut stats)?;
    stats.end_trajectory();
    Ok(stats)
}

/// [`WallStatistics`] pooled over initial conditions `ics` (IC `i` from
/// `sampler` with `ic_rng(seed, i)`), `collisions` each, merged in index
/// order.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for an empty range; dynamics errors with
/// the failing index.
pub fn wall_statistics_ensemble<B: Boundary + Sync>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    ics: Range<u64>,
    collisions: u64,
    threads: Threads,
) -> Result<WallStatistics, AnalysisError> {
    if ics.is_empty() {
        return Err(AnalysisError::invalid(
            "ics",
            "empty range of initial conditions",
        ));
    }
    let parts = map_indices(ics, threads, |i| {
        let start = sampler.initial_state(billiard.table(), billiard.law(), seed, i);
        wall_statistics(billiard, start, collisions).map_err(|e| e.at_index(i))
    })?;
    let mut total = WallStatistics::new(billiard.law());
    for part in &parts {
        total.merge(part)?;
    }
    Ok(total)
}

// ---------------------------------------------------------------------------
// Energy (paper, appendix "Energy conservation")
// ---------------------------------------------------------------------------

/// One point of an [`EnergyTrace`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnergyPoint {
    /// Collisions so far (the end of the window).
    pub collisions: u64,
    /// Largest `|E_n − E_0|` over the window of `stride` collisions ending
    /// here (the maximum, so downsampling hides no spike).
    pub deviation: f64,
}

/// An [`Observer`] of the absolute energy deviation `|E_n − E_0|` (paper,
/// appendix "Energy conservation", eq. 4), keeping one point per `stride`
/// collisions.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnergyTrace {
    law: SpinLaw,
    e0: f64,
    stride: u64,
    seen: u64,
    window: f64,
    /// One point per `stride` collisions.
    pub points: Vec<EnergyPoint>,
    /// Largest `|E_n − E_0|` over the whole run.
    pub max_deviation: f64,
}

impl EnergyTrace {
    /// Compare with the energy of `start` under `law`, one point every
    /// `stride` collisions.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for `stride = 0`.
    pub fn new(law: SpinLaw, start: &State, stride: u64) -> Result<Self, AnalysisError> {
        if stride == 0 {
            return Err(AnalysisError::invalid("stride", "must be > 0"));
        }
        Ok(EnergyTrace {
            law,
            e0: start.energy(&law),
            stride,
            seen: 0,
            window: 0.0,
            points: Vec::new(),
            max_deviation: 0.0,
        })
    }

    /// The reference energy `E_0`.
    pub fn initial_energy(&self) -> f64 {
        self.e0
    }
}

impl Observer for EnergyTrace {
    #[inline]
    fn observe(&mut self, _: &Collision, after: &State) {
        let d = (after.energy(&self.law) - self.e0).abs();
        self.seen += 1;
        self.window = self.window.max(d);
        self.max_deviation = self.max_deviation.max(d);
        if self.seen.is_multiple_of(self.stride) {
            self.points.push(EnergyPoint {
                collisions: self.seen,
                deviation: self.window,
            });
            self.window = 0.0;
        }
    }
}

/// The [`EnergyTrace`] of the trajectory from `start`.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for `stride = 0`; dynamics errors.
pub fn energy_trace<B: Boundary>(
    billiard: &Billiard<B>,
    start: State,
    collisions: u64,
    stride: u64,
) -> Result<EnergyTrace, AnalysisError> {
    let mut trace = EnergyTrace::new(*billiard.law(), &start, stride)?;
    let mut ball = billiard.launch(start)?;
    billiard.run(&mut ball, collisions, &mut trace)?;
    Ok(trace)
}
