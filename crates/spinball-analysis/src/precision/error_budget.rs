//! The error budget of an ensemble estimate: statistical error, finite-time
//! bias and method bias, and the total they add up to.
//!
//! Documented in the group docs (`precision/mod.rs`), section "Error budget".

use spinball_geometry::Boundary;

use super::convergence::convergence_estimates;
use super::finite_time_bias::{BiasRegime, FiniteTimeBias};
use super::measurement::Measurement;
use super::method_bias::MethodBias;
use crate::error::AnalysisError;
use crate::estimators::Method;
use crate::run::{Ensemble, LyapunovEstimate};

/// What the error of one estimate is made of.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct ErrorBudget {
    /// The estimate: mean `λ_T` at the longest run, with its SEM.
    pub value: Measurement,
    /// Collisions per trajectory of `value`.
    pub collisions: u64,
    /// Initial conditions.
    pub n_ics: u64,
    /// Statistical error (the SEM).
    pub sem: f64,
    /// Finite-time bias `λ_T − λ` at `collisions`, with its uncertainty.
    pub finite_time_bias: Measurement,
    /// Which law the finite-time bias follows.
    pub regime: BiasRegime,
    /// Method bias `λ_fd − λ_tangent` (zero for the tangent method).
    pub method_bias: Measurement,
    /// Total error with its uncertainty.
    pub total: Measurement,
}

impl ErrorBudget {
    /// The budget of the longest column of `bias` with the method bias
    /// `method` (`None` for the tangent method).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if the budget would not be finite
    /// (a non-finite input).
    pub fn new(bias: &FiniteTimeBias, method: Option<&MethodBias>) -> Result<Self, AnalysisError> {
        Self::assemble(
            bias.last(),
            bias.n_ics,
            *bias.checkpoints.last().expect("a fit has checkpoints"),
            bias.regime,
            bias.bias(),
            method.map_or(Measurement::new(0.0, 0.0), |m| m.difference),
        )
    }

    /// The budget of `value` (over `n_ics` initial conditions, `collisions`
    /// each) with biases `ft` and `mb` measured on (possibly fewer of) its
    /// initial conditions.
    pub(crate) fn assemble(
        value: Measurement,
        n_ics: u64,
        collisions: u64,
        regime: BiasRegime,
        ft: Measurement,
        mb: Measurement,
    ) -> Result<Self, AnalysisError> {
        let sem = value.sem;
        let sem_of_sem = sem / (2.0 * (n_ics.max(2) - 1) as f64).sqrt();
        let total = combine(sem, sem_of_sem, ft, mb)?;
        Ok(ErrorBudget {
            value,
            collisions,
            n_ics,
            sem,
            finite_time_bias: ft,
            regime,
            method_bias: mb,
            total,
        })
    }

    /// The budget of an existing `estimate` (a point of a sweep) of
    /// `ensemble` (the same table, law, method and seed): its own SEM, and
    /// the biases from its first `bias_ics` initial conditions read at
    /// `T/8, T/4, T/2, T` in one nested scalar run (plus, for finite
    /// differences, a tangent run of them at `T`). Costs about `bias_ics/N`
    /// of the estimate, more for a tangent pairing.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if `ensemble` does not match the
    /// estimate (α, method, seed), `bias_ics < 2`, or fewer than 8
    /// collisions per trajectory; then as [`measure`](Self::measure).
    pub fn for_estimate<B: Boundary + Clone + Sync>(
        ensemble: &Ensemble<B>,
        estimate: &LyapunovEstimate,
        bias_ics: u64,
    ) -> Result<Self, AnalysisError> {
        if ensemble.alpha().to_bits() != estimate.alpha.to_bits()
            || ensemble.method != estimate.method
            || ensemble.seed != estimate.seed
        {
            return Err(AnalysisError::invalid(
                "error budget",
                "the ensemble must have the estimate's alpha, method and seed",
            ));
        }
        let t = estimate.collisions_per_ic;
        if bias_ics < 2 || t < 8 {
            return Err(AnalysisError::invalid(
                "error budget",
                format!(
                    "needs at least 2 initial conditions and 8 collisions for the bias fit, got {bias_ics} and {t}"
                ),
            ));
        }
        let first = estimate.first_index;
        let sub = ensemble
            .clone()
            .with_indices(first..first + bias_ics.min(estimate.n_ics))
            .with_engine(crate::run::Engine::Scalar);
        let (part, _) = Self::measure(&sub, &[t / 8, t / 4, t / 2, t])?;
        Self::assemble(
            Measurement::lambda(estimate),
            estimate.n_ics,
            t,
            part.regime,
            part.finite_time_bias,
            part.method_bias,
        )
    }

    /// Run `ensemble` at each of `checkpoints` (the same initial conditions;
    /// see [`convergence_estimates`]), fit the finite-time bias and, for a
    /// finite-difference method, pair the longest column with a tangent run
    /// on the same initial conditions for the method bias.
    ///
    /// ```
    /// use spinball_analysis::estimators::Method;
    /// use spinball_analysis::run::{Engine, Ensemble};
    /// use spinball_analysis::precision::ErrorBudget;
    /// use spinball_core::SpinLaw;
    /// use spinball_geometry::Stadium;
    ///
    /// let ensemble = Ensemble::new(Stadium::new(1.0)?, SpinLaw::new(0.0)?)
    ///     .with_ics(32)
    ///     .with_seed(2)
    ///     .with_engine(Engine::Scalar); // one nested run
    /// let (budget, _) = ErrorBudget::measure(&ensemble, &[250, 500, 1_000, 2_000])?;
    /// assert!(budget.total.value >= budget.sem);
    /// assert!(budget.method_bias.sem > 0.0); // finite differences by default
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// As [`convergence_estimates`] and [`FiniteTimeBias::fit`].
    pub fn measure<B: Boundary + Clone + Sync>(
        ensemble: &Ensemble<B>,
        checkpoints: &[u64],
    ) -> Result<(Self, Vec<LyapunovEstimate>), AnalysisError> {
        let columns = convergence_estimates(ensemble, checkpoints)?;
        let bias = FiniteTimeBias::from_columns(&columns)?;
        let method = match ensemble.method {
            Method::FiniteDifference { .. } => {
                let last = columns.last().expect("checked non-empty");
                let tangent = ensemble
                    .clone()
                    .with_method(Method::Tangent)
                    .with_collisions(last.collisions_per_ic)
                    .run()?;
                Some(MethodBias::from_estimates(last, &tangent)?)
            }
            Method::Tangent => None,
        };
        Ok((Self::new(&bias, method.as_ref())?, columns))
    }

    /// The total error relative to `|λ|`.
    #[must_use]
    pub fn rel_total(&self) -> f64 {
        self.total.value / self.value.value.abs()
    }

    /// The estimate corrected for both biases, `λ_T − b_T − b_m`, with the
    /// biases' uncertainties added to the SEM.
    #[must_use]
    pub fn corrected(&self) -> Measurement {
        let (ft, mb) = (self.finite_time_bias, self.method_bias);
        Measurement::new(
            self.value.value - ft.value - mb.value,
            self.sem.hypot(ft.sem).hypot(mb.sem),
        )
    }
}

/// `√(s² + b_T² + σ_T² + b_m² + σ_m²)` with its propagated uncertainty.
fn combine(
    sem: f64,
    sem_of_sem: f64,
    ft: Measurement,
    mb: Measurement,
) -> Result<Measurement, AnalysisError> {
    let sq = |m: Measurement| m.value * m.value + m.sem * m.sem;
    let total = (sem * sem + sq(ft) + sq(mb)).sqrt();
    if !total.is_finite() {
        return Err(AnalysisError::invalid(
            "error budget",
            format!(
                "the parts must be finite: SEM {sem}, finite-time bias {ft:?}, method bias {mb:?}"
            ),
        ));
    }
    if total == 0.0 {
        return Ok(Measurement::new(0.0, 0.0));
    }
    // d total / d x = x / total for each part; a bias's own uncertainty
    // enters through its estimate only (the σ² terms are a fixed floor).
    let var =
        (sem * sem_of_sem).powi(2) + (ft.value * ft.sem).powi(2) + (mb.value * mb.sem).powi(2);
    Ok(Measurement::new(total, var.sqrt() / total))
}

/// A high-accuracy value of `λ` for a scene: a long exact-tangent ensemble
/// read at nested checkpoints and extrapolated to `T → ∞`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Reference {
    /// The extrapolated exponent with its standard error.
    pub value: Measurement,
    /// The fit it comes from.
    pub bias: FiniteTimeBias,
    /// Seed of its initial conditions.
    pub seed: u64,
    /// Wall-clock seconds it took.
    pub wall_time_s: f64,
}

impl Reference {
    /// Run `ensemble` with the tangent method at `checkpoints` and
    /// extrapolate (in `1/T`, or `ln T / T` where the checkpoints follow
    /// that law). Give it a seed of its own, so that the errors of other
    /// runs of the same scene are measured against an independent value.
    ///
    /// # Errors
    /// As [`convergence_estimates`] and [`FiniteTimeBias::fit`].
    pub fn measure<B: Boundary + Clone + Sync>(
        ensemble: &Ensemble<B>,
        checkpoints: &[u64],
    ) -> Result<Self, AnalysisError> {
        let tangent = ensemble.clone().with_method(Method::Tangent);
        let columns = convergence_estimates(&tangent, checkpoints)?;
        let bias = FiniteTimeBias::from_columns(&columns)?;
        let wall_time_s = match tangent.engine_used() {
            crate::run::Engine::Lanes => columns.iter().map(|c| c.wall_time_s).sum(),
            crate::run::Engine::Scalar => columns.last().map_or(0.0, |c| c.wall_time_s),
        };
        Ok(Reference {
            value: bias.limit(),
            seed: ensemble.seed,
            wall_time_s,
            bias,
        })
    }

    /// The error of `estimate` against this reference, `λ − λ_ref`, with the
    /// standard errors of both added in quadrature (independent seeds).
    #[must_use]
    pub fn error_of(&self, estimate: Measurement) -> Measurement {
        estimate.difference(self.value)
    }
}
