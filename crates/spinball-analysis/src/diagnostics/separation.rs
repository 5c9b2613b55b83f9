//! How fast neighbours separate (paper, phase-space analysis): `⟨ln(δ_n/δ0)⟩`
//! over pairs, per collision, without renormalisation (the paper: 50
//! collisions, 8000 pairs, `δ0 = 1e-7`, a random 5-D direction). Linear
//! growth means exponential divergence (chaos), logarithmic growth means
//! shear (integrable tables). Initial condition `i` comes from its own
//! stream and results combine in index order, so the numbers do not depend
//! on the thread count.
//!
//! Documented in the group docs (`diagnostics/mod.rs`), section "Separation of neighbours".

use std::ops::RangeInclusive;

use spinball_core::{Ball, Billiard, Sampler, State, TangentVector, ic_rng, random_direction};
use spinball_geometry::Boundary;

use crate::error::AnalysisError;
use crate::estimators::{Accumulator, LinearFit, PAPER_DELTA0};
use crate::run::{Threads, map_indices};

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
        let points: Vec<(f64, f64)> = (a..=b).map(|k| (k as f64, self.mean[k - 1])).collect();
        LinearFit::through(&points)
            .ok_or_else(|| AnalysisError::invalid("collisions", "fit range holds one point"))
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
/// use spinball_analysis::diagnostics::{SeparationOptions, phase_space_separation};
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
