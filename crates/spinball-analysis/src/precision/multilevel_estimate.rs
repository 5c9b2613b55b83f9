//! What a multilevel run answers: `λ_T` at every level's run length, the
//! extrapolated `λ_∞`, the total error budget, and the chaotic fraction
//! with the mean exponent of the chaotic initial conditions.
//!
//! Documented in the group docs (`precision/mod.rs`), section "Multilevel
//! ensembles".

use std::fmt;

use super::error_budget::ErrorBudget;
use super::finite_time_bias::BiasRegime;
use super::level_extrapolation::LevelExtrapolation;
use super::measurement::Measurement;
use super::multilevel::{LevelSamples, LevelStats, Multilevel};
use crate::error::AnalysisError;
use crate::estimators::Accumulator;

/// The result of a multilevel run ([`Multilevel::run`], or
/// [`from_levels`](Self::from_levels) over merged shards).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct MultilevelEstimate {
    /// Per level: run length, initial conditions, mean and variance of the
    /// correction, cost, wall time.
    pub levels: Vec<LevelStats>,
    /// `λ_T` at each level's run length `T_l` (the telescoped sum of the
    /// level means up to `l`), with its standard error.
    pub means: Vec<Measurement>,
    /// The bias laws fitted to `means` with their correlated errors.
    pub extrapolation: LevelExtrapolation,
    /// The error budget of `λ_TL`: SEM, finite-time bias (from
    /// `extrapolation`), method bias and total. Its `n_ics` is the
    /// effective count of the SEM (Welch–Satterthwaite over the levels).
    pub budget: ErrorBudget,
    /// Share of initial conditions with `λ_T0` above the threshold (the
    /// shortest level classifies), from level 0, with its standard error.
    pub chaotic_fraction: Measurement,
    /// Mean `λ_TL` of the initial conditions classified chaotic, with its
    /// standard error; `None` if level 0 has none.
    pub chaotic_mean: Option<Measurement>,
    /// The chaos threshold used.
    pub threshold: f64,
    /// The target relative total error.
    pub target_rel: f64,
    /// Rounds of top-ups after the pilot.
    pub rounds: u32,
}

impl MultilevelEstimate {
    /// The estimate of the draws `samples` (one entry per level, in level
    /// order, each the merge of all its pieces) with the top level's
    /// `method_bias`, under `options`' threshold and target.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if the levels are not `0..=L` in
    /// order, a level has fewer than two draws, or the bias fit fails (see
    /// [`LevelExtrapolation::fit`]).
    pub fn from_levels(
        samples: &[LevelSamples],
        method_bias: Measurement,
        options: &Multilevel,
    ) -> Result<Self, AnalysisError> {
        if samples.iter().enumerate().any(|(l, s)| s.level != l) || samples.is_empty() {
            return Err(AnalysisError::invalid(
                "levels",
                "need the samples of levels 0, 1, …, L in order",
            ));
        }
        if let Some(s) = samples.iter().find(|s| s.draws.len() < 2) {
            return Err(AnalysisError::invalid(
                "levels",
                format!(
                    "level {} has {} draws; every level needs at least 2 for a variance",
                    s.level,
                    s.draws.len()
                ),
            ));
        }
        let levels: Vec<LevelStats> = samples.iter().map(LevelSamples::stats).collect();
        let mut means = Vec::with_capacity(levels.len());
        let (mut sum, mut var) = (0.0, 0.0);
        for s in &levels {
            sum += s.mean;
            var += s.sem2();
            means.push(Measurement::new(sum, var.sqrt()));
        }
        // Cov(λ_Tj, λ_Tk) = Σ_{l ≤ min(j,k)} V_l/N_l: the means share levels.
        let cumulative: Vec<f64> = means.iter().map(|m| m.sem * m.sem).collect();
        let cov: Vec<Vec<f64>> = (0..levels.len())
            .map(|j| (0..levels.len()).map(|k| cumulative[j.min(k)]).collect())
            .collect();
        let collisions: Vec<u64> = levels.iter().map(|s| s.collisions).collect();
        let values: Vec<f64> = means.iter().map(|m| m.value).collect();
        let extrapolation = LevelExtrapolation::fit(&collisions, &values, &cov)?;
        let top = *means.last().expect("non-empty");
        let budget = ErrorBudget::assemble(
            top,
            effective_ics(&levels),
            *collisions.last().expect("non-empty"),
            extrapolation.regime,
            extrapolation.bias(),
            method_bias,
        )?;
        let (chaotic_fraction, chaotic_mean) = chaotic_part(samples, options.threshold);
        Ok(MultilevelEstimate {
            levels,
            means,
            extrapolation,
            budget,
            chaotic_fraction,
            chaotic_mean,
            threshold: options.threshold,
            target_rel: options.target_rel,
            rounds: 0,
        })
    }

    /// `λ_TL`, the mean exponent at the top level's run length, with its
    /// standard error.
    #[must_use]
    pub fn lambda(&self) -> Measurement {
        *self.means.last().expect("an estimate has levels")
    }

    /// `λ_∞`, extrapolated from the level means in the law they follow,
    /// with its standard error (and the spread between the laws where
    /// neither fits).
    #[must_use]
    pub fn limit(&self) -> Measurement {
        self.extrapolation.limit()
    }

    /// Which law the finite-time bias follows.
    #[must_use]
    pub fn regime(&self) -> BiasRegime {
        self.extrapolation.regime
    }

    /// The total error of `λ_TL` relative to `|λ_TL|`.
    #[must_use]
    pub fn rel_total(&self) -> f64 {
        self.budget.rel_total()
    }

    /// Whether the total error meets the target.
    #[must_use]
    pub fn target_met(&self) -> bool {
        self.rel_total() <= self.target_rel
    }

    /// Initial conditions over all levels.
    #[must_use]
    pub fn total_ics(&self) -> u64 {
        self.levels.iter().map(|s| s.n_ics).sum()
    }

    /// Work over all levels, in IC-steps (as the source counts them).
    #[must_use]
    pub fn ic_steps(&self) -> f64 {
        self.levels.iter().map(|s| s.n_ics as f64 * s.cost).sum()
    }

    /// Wall-clock seconds over all levels.
    #[must_use]
    pub fn wall_time_s(&self) -> f64 {
        self.levels.iter().map(|s| s.wall_time_s).sum()
    }
}

impl fmt::Display for MultilevelEstimate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (l, lim) = (self.lambda(), self.limit());
        let top = self.levels.last().map_or(0, |s| s.collisions);
        writeln!(
            f,
            "λ_T (T = {top}) = {:.6} ± {:.6} (total error {:.6}, {:.3}% of λ; target {:.3}%{})",
            l.value,
            l.sem,
            self.budget.total.value,
            100.0 * self.rel_total(),
            100.0 * self.target_rel,
            if self.target_met() {
                ", met"
            } else {
                ", NOT met"
            }
        )?;
        writeln!(
            f,
            "λ_∞ = {:.6} ± {:.6} (bias law {})",
            lim.value,
            lim.sem,
            self.regime().name()
        )?;
        write!(
            f,
            "chaotic fraction {:.4} ± {:.4}",
            self.chaotic_fraction.value, self.chaotic_fraction.sem
        )?;
        if let Some(m) = self.chaotic_mean {
            write!(f, ", chaotic mean {:.6} ± {:.6}", m.value, m.sem)?;
        }
        writeln!(f)?;
        writeln!(
            f,
            "level        T        N     mean corr.      variance   wall s"
        )?;
        for s in &self.levels {
            writeln!(
                f,
                "{:>5} {:>8} {:>8} {:>14.6e} {:>13.4e} {:>8.3}",
                s.level, s.collisions, s.n_ics, s.mean, s.variance, s.wall_time_s
            )?;
        }
        Ok(())
    }
}

/// Welch–Satterthwaite: the count of one sample whose SEM would be as
/// uncertain as the multilevel SEM, `ν + 1` with
/// `ν = (Σ s_l²)² / Σ s_l⁴/(N_l − 1)`.
fn effective_ics(levels: &[LevelStats]) -> u64 {
    let total: f64 = levels.iter().map(LevelStats::sem2).sum();
    let spread: f64 = levels
        .iter()
        .map(|s| s.sem2().powi(2) / (s.n_ics.max(2) - 1) as f64)
        .sum();
    if spread > 0.0 {
        (total * total / spread).round() as u64 + 1
    } else {
        levels.iter().map(|s| s.n_ics).min().unwrap_or(2)
    }
}

/// Chaotic fraction from level 0, and the mean `λ_TL` of the chaotic
/// initial conditions as the ratio `Σ_l E[χ·Y_l] / E[χ]` (`χ`: chaotic at
/// `T_0`, `Y_l`: the level's correction), its error by first-order
/// propagation (level 0 carries numerator and denominator together).
fn chaotic_part(samples: &[LevelSamples], threshold: f64) -> (Measurement, Option<Measurement>) {
    let chaotic = |d: &super::multilevel::LevelDraw| d.short > threshold;
    let level0 = &samples[0].draws;
    let flags: Accumulator = level0
        .iter()
        .map(|d| if chaotic(d) { 1.0 } else { 0.0 })
        .collect();
    let f = flags.mean().unwrap_or(0.0);
    let fraction = Measurement::new(f, flags.sem().unwrap_or(0.0));
    if f == 0.0 {
        return (fraction, None);
    }
    let masked = |s: &LevelSamples| -> Accumulator {
        s.draws
            .iter()
            .map(|d| if chaotic(d) { d.correction() } else { 0.0 })
            .collect()
    };
    let parts: Vec<Accumulator> = samples.iter().map(masked).collect();
    let mean = parts.iter().map(|a| a.mean().unwrap_or(0.0)).sum::<f64>() / f;
    let residual: Accumulator = level0
        .iter()
        .map(|d| if chaotic(d) { d.fine - mean } else { 0.0 })
        .collect();
    let var = residual.variance().unwrap_or(0.0) / level0.len() as f64
        + parts[1..]
            .iter()
            .map(|a| a.variance().unwrap_or(0.0) / a.count() as f64)
            .sum::<f64>();
    (fraction, Some(Measurement::new(mean, var.sqrt() / f)))
}
