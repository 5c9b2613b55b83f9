//! Finite-time bias: how far the exponent of `T` collisions, `λ_T`, still is
//! from its limit `λ`, measured from the same initial conditions read at
//! nested run lengths.
//!
//! Documented in the group docs (`precision/mod.rs`), section "Finite-time bias".

use super::measurement::Measurement;
use crate::error::AnalysisError;
use crate::estimators::Accumulator;
use crate::run::LyapunovEstimate;

/// The law of the finite-time bias, `λ_T − λ ∝ g(T)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum BiasLaw {
    /// `g(T) = 1/T`: the transient of a chaotic orbit.
    InverseT,
    /// `g(T) = ln T / T`: the linear shear of a regular orbit (`λ = 0`).
    LogTOverT,
}

impl BiasLaw {
    /// `g(T)` for `T` collisions.
    #[must_use]
    pub fn g(self, collisions: f64) -> f64 {
        match self {
            BiasLaw::InverseT => 1.0 / collisions,
            BiasLaw::LogTOverT => collisions.ln() / collisions,
        }
    }

    /// `1/T` or `ln T / T`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            BiasLaw::InverseT => "1/T",
            BiasLaw::LogTOverT => "ln T / T",
        }
    }
}

/// Which bias law the nested checkpoints are consistent with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum BiasRegime {
    /// `1/T` fits (the chaotic transient; the extrapolation in `1/T` holds).
    InverseT,
    /// `1/T` is rejected, `ln T / T` fits and its coefficient is resolved
    /// and positive: regular orbits (all of them on an integrable table,
    /// the islands in a mixed phase space) shape the bias; the `1/T`
    /// extrapolation is not to be trusted and `λ_T` approaches its limit
    /// only like `ln T / T`.
    LogTOverT,
    /// Neither law fits (too short runs, a mixture of both, or
    /// checkpoints too close to the transient): the bias estimate is a
    /// lower bound.
    Neither,
}

impl BiasRegime {
    /// `1/T`, `ln T / T` or `neither`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            BiasRegime::InverseT => BiasLaw::InverseT.name(),
            BiasRegime::LogTOverT => BiasLaw::LogTOverT.name(),
            BiasRegime::Neither => "neither",
        }
    }
}

/// A fit `λ_T = a + b·g(T)` of one [`BiasLaw`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct BiasFit {
    /// The law fitted.
    pub law: BiasLaw,
    /// `a`: the extrapolated exponent `λ_∞`, with its standard error.
    pub limit: Measurement,
    /// `b`: the coefficient of `g(T)`, with its standard error.
    pub coefficient: Measurement,
    /// `c`: for `ln T / T`, the coefficient of the `1/T` term that comes
    /// with it (`λ_T = a + (b ln T + c)/T`: the separation of a regular
    /// orbit grows like `c'·T`); zero for `1/T`.
    pub shift: Measurement,
    /// The bias of the last checkpoint, `λ_T − λ_∞ = b·g(T_last)`.
    pub bias: Measurement,
    /// `χ²` of the mean series against the fit (residuals over their
    /// per-IC standard errors).
    pub chi2: f64,
    /// Degrees of freedom, checkpoints − parameters (2 for `1/T`, 3 for
    /// `ln T / T`).
    pub dof: usize,
}

impl BiasFit {
    /// Whether the fit is acceptable for a large ensemble: `χ²` below the
    /// 99.9% point of a `χ²` law with `dof` degrees of freedom
    /// (Wilson–Hilferty).
    #[must_use]
    pub fn consistent(&self) -> bool {
        self.chi2 <= chi2_quantile_999(self.dof)
    }

    /// As [`consistent`](Self::consistent) for a fit over `n_ics` initial
    /// conditions: each term of `χ²` divides by a variance estimated from
    /// `n_ics` values (a Student `t` with `n − 1` degrees of freedom, of
    /// variance `(n − 1)/(n − 3)`), so the critical value is scaled by that
    /// factor; with 3 or fewer initial conditions nothing is rejected.
    #[must_use]
    pub fn consistent_for(&self, n_ics: usize) -> bool {
        if n_ics <= 3 {
            return true;
        }
        let inflation = (n_ics - 1) as f64 / (n_ics - 3) as f64;
        self.chi2 <= inflation * chi2_quantile_999(self.dof)
    }

    /// The bias the fit predicts at `collisions` collisions, `b·g(T) +
    /// c/T`, with an uncertainty that treats `b` and `c` as independent.
    #[must_use]
    pub fn bias_at(&self, collisions: f64) -> Measurement {
        let (g, h) = (self.law.g(collisions), 1.0 / collisions);
        let (b, c) = (self.coefficient, self.shift);
        Measurement::new(b.value * g + c.value * h, (b.sem * g).hypot(c.sem * h))
    }

    /// An upper estimate of the bias magnitude at `collisions`: each term
    /// at `√(value² + sem²)`.
    #[must_use]
    pub fn bias_bound(&self, collisions: f64) -> f64 {
        let (b, c) = (self.coefficient, self.shift);
        b.value.hypot(b.sem) * self.law.g(collisions) + c.value.hypot(c.sem) / collisions
    }
}

/// The finite-time bias of an ensemble from nested checkpoints: both fits,
/// the regime, and the estimate at the last checkpoint.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct FiniteTimeBias {
    /// The checkpoints (collisions per trajectory), increasing.
    pub checkpoints: Vec<u64>,
    /// Ensemble mean `λ_T` at each checkpoint with its SEM.
    pub means: Vec<Measurement>,
    /// Initial conditions.
    pub n_ics: u64,
    /// The fit in `1/T`.
    pub inverse_t: BiasFit,
    /// The fit in `ln T / T`.
    pub log_t: BiasFit,
    /// Which law the data are consistent with.
    pub regime: BiasRegime,
    /// Model uncertainty: where neither law fits, the distance between the
    /// two laws' limits (zero otherwise). [`limit`](Self::limit) and
    /// [`bias`](Self::bias) add it to their standard errors.
    pub systematic: f64,
}

/// Fewest checkpoints a bias fit takes (three parameters of the `ln T / T`
/// law and one degree of freedom for its goodness of fit).
pub const MIN_CHECKPOINTS: usize = 4;

impl FiniteTimeBias {
    /// Fit the bias laws to `per_ic[i][k]`, the exponent of initial
    /// condition `i` after `checkpoints[k]` collisions.
    ///
    /// ```
    /// use spinball_analysis::precision::{BiasRegime, FiniteTimeBias};
    /// // Three ICs with λ_T = 0.4 + (5 + i)/T exactly.
    /// let t = [1_000u64, 2_000, 4_000, 16_000];
    /// let rows: Vec<Vec<f64>> = (0..3)
    ///     .map(|i| t.iter().map(|&c| 0.4 + (5.0 + i as f64) / c as f64).collect())
    ///     .collect();
    /// let bias = FiniteTimeBias::fit(&t, &rows)?;
    /// assert!((bias.inverse_t.limit.value - 0.4).abs() < 1e-12);
    /// assert!((bias.inverse_t.coefficient.value - 6.0).abs() < 1e-9);
    /// assert_eq!(bias.regime, BiasRegime::InverseT);
    /// # Ok::<(), spinball_analysis::AnalysisError>(())
    /// ```
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for fewer than [`MIN_CHECKPOINTS`]
    /// checkpoints, checkpoints not positive and increasing, fewer than two
    /// initial conditions, rows of the wrong length or a non-finite value.
    pub fn fit(checkpoints: &[u64], per_ic: &[Vec<f64>]) -> Result<Self, AnalysisError> {
        check_series(checkpoints, per_ic)?;
        let k = checkpoints.len();
        let column = |j: usize| -> Accumulator { per_ic.iter().map(|row| row[j]).collect() };
        let means: Vec<Measurement> = (0..k).map(|j| mean_sem(&column(j))).collect();
        // Weights from the scatter at each checkpoint; equal weights if any
        // checkpoint has none (identical trajectories).
        let weights: Vec<f64> = if means.iter().all(|m| m.sem > 0.0) {
            means.iter().map(|m| 1.0 / (m.sem * m.sem)).collect()
        } else {
            vec![1.0; k]
        };
        let inverse_t = fit_law(BiasLaw::InverseT, checkpoints, per_ic, &weights)?;
        let log_t = fit_law(BiasLaw::LogTOverT, checkpoints, per_ic, &weights)?;
        // ln T / T only where 1/T fails (the log law has a parameter more
        // and fits 1/T data as well) and the ln T / T term is resolved and
        // positive: regular orbits approach their limit from above.
        let n = per_ic.len();
        let (regime, systematic) = select_regime(
            &inverse_t,
            &log_t,
            inverse_t.consistent_for(n),
            log_t.consistent_for(n),
        );
        Ok(FiniteTimeBias {
            checkpoints: checkpoints.to_vec(),
            means,
            n_ics: per_ic.len() as u64,
            inverse_t,
            log_t,
            regime,
            systematic,
        })
    }

    /// The fit of the estimates of
    /// [`convergence_estimates`](crate::precision::convergence_estimates): one per
    /// checkpoint, over the same initial conditions.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if the estimates do not share their
    /// initial conditions (seed, first index, count) or their collisions do
    /// not increase; then as [`fit`](Self::fit).
    pub fn from_columns(columns: &[LyapunovEstimate]) -> Result<Self, AnalysisError> {
        let Some(first) = columns.first() else {
            return Err(AnalysisError::invalid(
                "checkpoints",
                format!("need at least {MIN_CHECKPOINTS} columns, got none"),
            ));
        };
        if columns.iter().any(|c| {
            c.seed != first.seed
                || c.first_index != first.first_index
                || c.n_ics != first.n_ics
                || c.method != first.method
        }) {
            return Err(AnalysisError::invalid(
                "checkpoints",
                "the columns must share seed, method and initial conditions",
            ));
        }
        let checkpoints: Vec<u64> = columns.iter().map(|c| c.collisions_per_ic).collect();
        let per_ic: Vec<Vec<f64>> = (0..first.trajectories.len())
            .map(|i| columns.iter().map(|c| c.trajectories[i].exponent).collect())
            .collect();
        Self::fit(&checkpoints, &per_ic)
    }

    /// The fit of the regime: `1/T` or `ln T / T` if that is the law the
    /// data follow; where neither fits, the one with the smaller `χ²/dof`.
    #[must_use]
    pub fn preferred(&self) -> &BiasFit {
        preferred_fit(self.regime, &self.inverse_t, &self.log_t)
    }

    /// The extrapolated exponent `λ_∞` of the preferred fit, its standard
    /// error combined with the [`systematic`](Self::systematic) one.
    #[must_use]
    pub fn limit(&self) -> Measurement {
        let l = self.preferred().limit;
        Measurement::new(l.value, l.sem.hypot(self.systematic))
    }

    /// The ensemble mean at the last checkpoint.
    #[must_use]
    pub fn last(&self) -> Measurement {
        *self.means.last().expect("a fit has checkpoints")
    }

    /// The bias of the last checkpoint under the preferred law, its
    /// standard error combined with the [`systematic`](Self::systematic)
    /// one.
    #[must_use]
    pub fn bias(&self) -> Measurement {
        let b = self.preferred().bias;
        Measurement::new(b.value, b.sem.hypot(self.systematic))
    }
}

/// The regime two fits are consistent with (`ln T / T` only where `1/T`
/// fails and the `ln T / T` term is resolved and positive: the log law has
/// a parameter more and fits `1/T` data as well, and regular orbits
/// approach their limit from above), and the systematic error where
/// neither fits: the distance between their limits.
pub(crate) fn select_regime(
    inverse_t: &BiasFit,
    log_t: &BiasFit,
    inverse_t_fits: bool,
    log_t_fits: bool,
) -> (BiasRegime, f64) {
    let log_resolved = log_t.coefficient.value > 3.0 * log_t.coefficient.sem;
    let regime = match (inverse_t_fits, log_t_fits) {
        (true, _) => BiasRegime::InverseT,
        (false, true) if log_resolved => BiasRegime::LogTOverT,
        (false, _) => BiasRegime::Neither,
    };
    let systematic = if regime == BiasRegime::Neither {
        (inverse_t.limit.value - log_t.limit.value).abs()
    } else {
        0.0
    };
    (regime, systematic)
}

/// The fit of `regime`; where neither law fits, the one with the smaller
/// `χ²/dof`.
pub(crate) fn preferred_fit<'a>(
    regime: BiasRegime,
    inverse_t: &'a BiasFit,
    log_t: &'a BiasFit,
) -> &'a BiasFit {
    match regime {
        BiasRegime::InverseT => inverse_t,
        BiasRegime::LogTOverT => log_t,
        BiasRegime::Neither => {
            let per_dof = |f: &BiasFit| f.chi2 / f.dof.max(1) as f64;
            if per_dof(log_t) < per_dof(inverse_t) {
                log_t
            } else {
                inverse_t
            }
        }
    }
}

fn check_series(checkpoints: &[u64], per_ic: &[Vec<f64>]) -> Result<(), AnalysisError> {
    if checkpoints.len() < MIN_CHECKPOINTS {
        return Err(AnalysisError::invalid(
            "checkpoints",
            format!(
                "a bias fit needs at least {MIN_CHECKPOINTS} checkpoints, got {}",
                checkpoints.len()
            ),
        ));
    }
    if checkpoints[0] == 0 || checkpoints.windows(2).any(|w| w[1] <= w[0]) {
        return Err(AnalysisError::invalid(
            "checkpoints",
            format!("must be positive and strictly increasing, got {checkpoints:?}"),
        ));
    }
    if per_ic.len() < 2 {
        return Err(AnalysisError::invalid(
            "initial conditions",
            format!(
                "a bias fit needs at least 2 initial conditions, got {}",
                per_ic.len()
            ),
        ));
    }
    if let Some(i) = per_ic.iter().position(|r| r.len() != checkpoints.len()) {
        return Err(AnalysisError::invalid(
            "series",
            format!(
                "initial condition {i} has {} values for {} checkpoints",
                per_ic[i].len(),
                checkpoints.len()
            ),
        ));
    }
    if per_ic.iter().flatten().any(|x| !x.is_finite()) {
        return Err(AnalysisError::invalid(
            "series",
            "every exponent must be finite",
        ));
    }
    Ok(())
}

/// The basis functions of a law at `collisions`: `[1, g(T)]` for `1/T`,
/// `[1, ln T / T, 1/T]` for `ln T / T`.
fn basis(law: BiasLaw, collisions: f64) -> Vec<f64> {
    match law {
        BiasLaw::InverseT => vec![1.0, 1.0 / collisions],
        BiasLaw::LogTOverT => vec![1.0, collisions.ln() / collisions, 1.0 / collisions],
    }
}

/// Weighted least squares on the design `x[k][j]` as a linear estimator:
/// row `j` of the result gives coefficient `j` as `Σ_k L[j][k] y_k`.
fn estimator(x: &[Vec<f64>], w: &[f64]) -> Result<Vec<Vec<f64>>, AnalysisError> {
    let p = x[0].len();
    let k = x.len();
    // Normal matrix XᵀWX and right-hand sides XᵀW (one per checkpoint).
    let mut a = vec![vec![0.0; p + k]; p];
    for (r, row) in a.iter_mut().enumerate() {
        for c in 0..p {
            row[c] = (0..k).map(|m| w[m] * x[m][r] * x[m][c]).sum();
        }
        for m in 0..k {
            row[p + m] = w[m] * x[m][r];
        }
    }
    solve_augmented(a, p)
}

/// Gauss–Jordan with partial pivoting on the augmented rows `[A | B]` (`A`
/// is `p × p`): returns `A⁻¹B`.
pub(crate) fn solve_augmented(
    mut a: Vec<Vec<f64>>,
    p: usize,
) -> Result<Vec<Vec<f64>>, AnalysisError> {
    for col in 0..p {
        let pivot = (col..p)
            .max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
            .expect("non-empty");
        a.swap(col, pivot);
        let d = a[col][col];
        let scale = a[col][..p].iter().fold(0.0f64, |m, v| m.max(v.abs()));
        if !(d.abs() > 1e-12 * scale && d.is_finite()) {
            return Err(AnalysisError::invalid(
                "checkpoints",
                "too close together to separate the bias from the limit",
            ));
        }
        for v in &mut a[col] {
            *v /= d;
        }
        let pivot_row = a[col].clone();
        for (r, row) in a.iter_mut().enumerate() {
            if r != col {
                let f = row[col];
                for (v, pv) in row.iter_mut().zip(&pivot_row) {
                    *v -= f * pv;
                }
            }
        }
    }
    Ok(a.into_iter().map(|row| row[p..].to_vec()).collect())
}

fn fit_law(
    law: BiasLaw,
    checkpoints: &[u64],
    per_ic: &[Vec<f64>],
    weights: &[f64],
) -> Result<BiasFit, AnalysisError> {
    // Columns scaled by their first value so the normal equations stay well
    // conditioned; the coefficients are scaled back below.
    let raw: Vec<Vec<f64>> = checkpoints.iter().map(|&c| basis(law, c as f64)).collect();
    let scale: Vec<f64> = raw[0].clone();
    let x: Vec<Vec<f64>> = raw
        .iter()
        .map(|r| r.iter().zip(&scale).map(|(v, s)| v / s).collect())
        .collect();
    let est = estimator(&x, weights)?;
    let p = scale.len();
    let k = checkpoints.len();
    let last = &raw[k - 1];
    let mut coef_acc: Vec<Accumulator> = vec![Accumulator::new(); p];
    let mut bias_acc = Accumulator::new();
    let mut residuals: Vec<Accumulator> = vec![Accumulator::new(); k];
    let mut coef = vec![0.0; p];
    for row in per_ic {
        for (j, c) in coef.iter_mut().enumerate() {
            *c = est[j].iter().zip(row).map(|(l, y)| l * y).sum::<f64>() / scale[j];
            coef_acc[j].push(*c);
        }
        bias_acc.push((1..p).map(|j| coef[j] * last[j]).sum());
        for (m, r) in residuals.iter_mut().enumerate() {
            let fit: f64 = (0..p).map(|j| coef[j] * raw[m][j]).sum();
            r.push(row[m] - fit);
        }
    }
    // χ² of the mean residuals against their per-IC standard errors; a
    // residual of (nearly) zero with zero scatter counts zero.
    let chi2 = residuals
        .iter()
        .map(|r| {
            let (m, s) = (r.mean().unwrap_or(0.0), r.sem().unwrap_or(0.0));
            if s > 0.0 {
                (m / s).powi(2)
            } else if m.abs() <= 1e-12 {
                0.0
            } else {
                f64::INFINITY
            }
        })
        .sum();
    Ok(BiasFit {
        law,
        limit: mean_sem(&coef_acc[0]),
        coefficient: mean_sem(&coef_acc[1]),
        shift: coef_acc.get(2).map_or(Measurement::new(0.0, 0.0), mean_sem),
        bias: mean_sem(&bias_acc),
        chi2,
        dof: k - p,
    })
}

/// Mean ± SEM of `acc` (which holds at least two values here).
fn mean_sem(acc: &Accumulator) -> Measurement {
    Measurement::new(acc.mean().unwrap_or(0.0), acc.sem().unwrap_or(0.0))
}

/// The 99.9% point of a `χ²` law with `dof` degrees of freedom
/// (Wilson–Hilferty approximation; good to a few percent from `dof = 1`).
pub(crate) fn chi2_quantile_999(dof: usize) -> f64 {
    let k = dof.max(1) as f64;
    let z = 3.090_232; // the standard normal's 99.9% point
    let h = 2.0 / (9.0 * k);
    k * (1.0 - h + z * h.sqrt()).powi(3)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wilson_hilferty_is_close_to_tabulated_points() {
        // Tabulated 99.9% points: dof 1 → 10.83, 2 → 13.82, 5 → 20.52, 10 → 29.59.
        for (dof, q) in [(1, 10.83), (2, 13.82), (5, 20.52), (10, 29.59)] {
            let got = chi2_quantile_999(dof);
            assert!((got / q - 1.0).abs() < 0.06, "{dof}: {got} vs {q}");
        }
    }

    #[test]
    fn bad_series_are_refused() {
        let rows = vec![vec![0.1, 0.2, 0.3, 0.4]; 4];
        assert!(FiniteTimeBias::fit(&[10, 20, 30], &vec![vec![0.1, 0.2, 0.3]; 4]).is_err());
        assert!(FiniteTimeBias::fit(&[10, 20, 20, 40], &rows).is_err());
        assert!(FiniteTimeBias::fit(&[0, 20, 30, 40], &rows).is_err());
        assert!(FiniteTimeBias::fit(&[10, 20, 30, 40], &rows[..1]).is_err());
        assert!(FiniteTimeBias::fit(&[10, 20, 30, 40], &vec![vec![0.1, 0.2]; 4]).is_err());
        let mut nan = rows.clone();
        nan[2][1] = f64::NAN;
        assert!(FiniteTimeBias::fit(&[10, 20, 30, 40], &nan).is_err());
        assert!(FiniteTimeBias::from_columns(&[]).is_err());
    }
}
