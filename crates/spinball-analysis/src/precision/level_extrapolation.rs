//! The finite-time bias of a multilevel estimate: the law `λ_T = λ_∞ +
//! b·g(T)` fitted to the level means, whose errors are correlated.
//!
//! Documented in the group docs (`precision/mod.rs`), section "Multilevel
//! ensembles".

use super::finite_time_bias::{
    BiasFit, BiasLaw, BiasRegime, MIN_CHECKPOINTS, preferred_fit, select_regime, solve_augmented,
};
use super::measurement::Measurement;
use crate::error::AnalysisError;

/// Both bias laws fitted to telescoped level means, the regime they are
/// consistent with and the model uncertainty where neither fits (as
/// [`FiniteTimeBias`](crate::precision::FiniteTimeBias) does for nested
/// checkpoints of one ensemble).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct LevelExtrapolation {
    /// The fit in `1/T`.
    pub inverse_t: BiasFit,
    /// The fit in `ln T / T`.
    pub log_t: BiasFit,
    /// Which law the level means are consistent with.
    pub regime: BiasRegime,
    /// Where neither law fits, the distance between their limits.
    pub systematic: f64,
}

impl LevelExtrapolation {
    /// Generalised least squares of both laws to `means[k]`, the estimate
    /// of `λ_T` at `collisions[k]`, with covariance `cov[j][k]` (for a
    /// multilevel estimate `Σ_{l ≤ min(j, k)} V_l/N_l`: the means share
    /// their coarser levels).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for fewer than
    /// [`MIN_CHECKPOINTS`] levels, sizes that do not match, a non-finite
    /// input or a covariance that is not positive definite.
    pub fn fit(collisions: &[u64], means: &[f64], cov: &[Vec<f64>]) -> Result<Self, AnalysisError> {
        let k = collisions.len();
        if k < MIN_CHECKPOINTS
            || means.len() != k
            || cov.len() != k
            || cov.iter().any(|r| r.len() != k)
        {
            return Err(AnalysisError::invalid(
                "levels",
                format!(
                    "a bias fit needs at least {MIN_CHECKPOINTS} levels with one mean and one covariance row each, got {k}"
                ),
            ));
        }
        if means
            .iter()
            .chain(cov.iter().flatten())
            .any(|x| !x.is_finite())
        {
            return Err(AnalysisError::invalid(
                "levels",
                "the level means and their covariance must be finite",
            ));
        }
        let chol = cholesky(cov)?;
        let inverse_t = gls(BiasLaw::InverseT, collisions, means, &chol)?;
        let log_t = gls(BiasLaw::LogTOverT, collisions, means, &chol)?;
        let (regime, systematic) = select_regime(
            &inverse_t,
            &log_t,
            inverse_t.consistent(),
            log_t.consistent(),
        );
        Ok(LevelExtrapolation {
            inverse_t,
            log_t,
            regime,
            systematic,
        })
    }

    /// The fit of the regime (where neither law fits, the one with the
    /// smaller `χ²/dof`).
    #[must_use]
    pub fn preferred(&self) -> &BiasFit {
        preferred_fit(self.regime, &self.inverse_t, &self.log_t)
    }

    /// `λ_∞`, its standard error combined with the systematic one.
    #[must_use]
    pub fn limit(&self) -> Measurement {
        let l = self.preferred().limit;
        Measurement::new(l.value, l.sem.hypot(self.systematic))
    }

    /// The bias of the top level, `λ_TL − λ_∞`, its standard error
    /// combined with the systematic one.
    #[must_use]
    pub fn bias(&self) -> Measurement {
        let b = self.preferred().bias;
        Measurement::new(b.value, b.sem.hypot(self.systematic))
    }
}

/// Lower-triangular `L` with `L Lᵀ = cov`.
fn cholesky(cov: &[Vec<f64>]) -> Result<Vec<Vec<f64>>, AnalysisError> {
    let n = cov.len();
    let mut l = vec![vec![0.0; n]; n];
    for i in 0..n {
        for j in 0..=i {
            let s: f64 = cov[i][j] - (0..j).map(|m| l[i][m] * l[j][m]).sum::<f64>();
            if i == j {
                if !(s > 0.0) {
                    return Err(AnalysisError::invalid(
                        "levels",
                        "the covariance of the level means is not positive definite (a level without spread?)",
                    ));
                }
                l[i][i] = s.sqrt();
            } else {
                l[i][j] = s / l[j][j];
            }
        }
    }
    Ok(l)
}

/// `L⁻¹ v` by forward substitution.
fn whiten(l: &[Vec<f64>], v: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; v.len()];
    for i in 0..v.len() {
        let s: f64 = (0..i).map(|m| l[i][m] * out[m]).sum();
        out[i] = (v[i] - s) / l[i][i];
    }
    out
}

/// Inverse of a small symmetric positive-definite matrix.
fn invert(a: &[Vec<f64>]) -> Result<Vec<Vec<f64>>, AnalysisError> {
    let p = a.len();
    let augmented = a
        .iter()
        .enumerate()
        .map(|(i, row)| {
            let mut r = row.clone();
            r.extend((0..p).map(|j| if i == j { 1.0 } else { 0.0 }));
            r
        })
        .collect();
    solve_augmented(augmented, p)
}

/// The basis of a law at `t` collisions scaled by its value at `t0` (so the
/// normal matrix stays well conditioned).
fn scaled_basis(law: BiasLaw, t: f64, t0: f64) -> Vec<f64> {
    match law {
        BiasLaw::InverseT => vec![1.0, t0 / t],
        BiasLaw::LogTOverT => vec![1.0, (t.ln() / t) / (t0.ln() / t0), t0 / t],
    }
}

fn gls(
    law: BiasLaw,
    collisions: &[u64],
    means: &[f64],
    chol: &[Vec<f64>],
) -> Result<BiasFit, AnalysisError> {
    let t0 = collisions[0] as f64;
    let rows: Vec<Vec<f64>> = collisions
        .iter()
        .map(|&t| scaled_basis(law, t as f64, t0))
        .collect();
    let p = rows[0].len();
    let k = rows.len();
    // Whitened design columns and data.
    let cols: Vec<Vec<f64>> = (0..p)
        .map(|j| whiten(chol, &rows.iter().map(|r| r[j]).collect::<Vec<_>>()))
        .collect();
    let y = whiten(chol, means);
    let normal: Vec<Vec<f64>> = (0..p)
        .map(|a| {
            (0..p)
                .map(|b| (0..k).map(|m| cols[a][m] * cols[b][m]).sum())
                .collect()
        })
        .collect();
    let cov = invert(&normal)?;
    let rhs: Vec<f64> = (0..p)
        .map(|a| (0..k).map(|m| cols[a][m] * y[m]).sum())
        .collect();
    let beta: Vec<f64> = (0..p)
        .map(|a| (0..p).map(|b| cov[a][b] * rhs[b]).sum())
        .collect();
    let chi2: f64 = (0..k)
        .map(|m| {
            let fit: f64 = (0..p).map(|j| cols[j][m] * beta[j]).sum();
            (y[m] - fit).powi(2)
        })
        .sum();
    // Back to unscaled coefficients: basis j was divided by its value at t0.
    let unscale = |j: usize| match (law, j) {
        (_, 0) => 1.0,
        (BiasLaw::InverseT, _) | (BiasLaw::LogTOverT, 2) => t0,
        (BiasLaw::LogTOverT, _) => t0 / t0.ln(),
    };
    let coef =
        |j: usize| Measurement::new(beta[j] * unscale(j), cov[j][j].max(0.0).sqrt() * unscale(j));
    // Bias at the top level: the scaled basis there without its constant.
    let top = &rows[k - 1];
    let bias_value: f64 = (1..p).map(|j| top[j] * beta[j]).sum();
    let bias_var: f64 = (1..p)
        .flat_map(|a| (1..p).map(move |b| (a, b)))
        .map(|(a, b)| top[a] * cov[a][b] * top[b])
        .sum();
    Ok(BiasFit {
        law,
        limit: coef(0),
        coefficient: coef(1),
        shift: if p > 2 {
            coef(2)
        } else {
            Measurement::new(0.0, 0.0)
        },
        bias: Measurement::new(bias_value, bias_var.max(0.0).sqrt()),
        chi2,
        dof: k - p,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn diagonal(v: &[f64]) -> Vec<Vec<f64>> {
        (0..v.len())
            .map(|i| {
                (0..v.len())
                    .map(|j| if i == j { v[i] } else { 0.0 })
                    .collect()
            })
            .collect()
    }

    #[test]
    fn exact_inverse_t_data_are_recovered() {
        let t = [250u64, 500, 1000, 2000, 4000];
        let means: Vec<f64> = t.iter().map(|&c| 0.4 + 7.0 / c as f64).collect();
        let fit = LevelExtrapolation::fit(&t, &means, &diagonal(&[1e-8; 5])).unwrap();
        assert_eq!(fit.regime, BiasRegime::InverseT);
        assert!((fit.limit().value - 0.4).abs() < 1e-12, "{fit:?}");
        assert!((fit.inverse_t.coefficient.value - 7.0).abs() < 1e-8);
        assert!((fit.bias().value - 7.0 / 4000.0).abs() < 1e-12);
    }

    #[test]
    fn log_law_is_found_where_inverse_t_fails() {
        let t = [250u64, 500, 1000, 2000, 4000, 8000];
        let means: Vec<f64> = t
            .iter()
            .map(|&c| {
                let c = c as f64;
                0.2 + (3.0 * c.ln() + 1.0) / c
            })
            .collect();
        let fit = LevelExtrapolation::fit(&t, &means, &diagonal(&[1e-12; 6])).unwrap();
        assert_eq!(fit.regime, BiasRegime::LogTOverT);
        assert!((fit.limit().value - 0.2).abs() < 1e-9, "{fit:?}");
        assert!((fit.log_t.coefficient.value - 3.0).abs() < 1e-6);
        assert!((fit.log_t.shift.value - 1.0).abs() < 1e-4);
    }

    #[test]
    fn bad_inputs_are_refused() {
        let t = [250u64, 500, 1000, 2000];
        let m = [0.1, 0.1, 0.1, 0.1];
        assert!(LevelExtrapolation::fit(&t[..3], &m[..3], &diagonal(&[1.0; 3])).is_err());
        assert!(LevelExtrapolation::fit(&t, &m, &diagonal(&[1.0, 0.0, 1.0, 1.0])).is_err());
        assert!(
            LevelExtrapolation::fit(&t, &[0.1, f64::NAN, 0.1, 0.1], &diagonal(&[1.0; 4])).is_err()
        );
    }
}
