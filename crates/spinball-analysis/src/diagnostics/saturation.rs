//! Where short-time separation growth stops: the saturation of
//! `⟨ln(δ_n/δ0)⟩` at the size of the table (paper §V.A).
//!
//! Documented in the group docs (`diagnostics/mod.rs`), section "Saturation of the separation".

use super::separation::Separation;
use crate::error::AnalysisError;
use crate::estimators::LinearFit;

/// Growth and saturation of one [`Separation`] curve.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SeparationSummary {
    /// `⟨ln(δ_N/δ0)⟩` averaged over the last `tail` collisions (the plateau,
    /// for a saturated chaotic curve).
    pub plateau: f64,
    /// Collisions averaged for the plateau.
    pub tail: usize,
    /// First collision at which the curve is within 1 (a factor `e`) of the
    /// plateau.
    pub reach: usize,
    /// Least-squares line over collisions `fit_range.0..=fit_range.1`, the
    /// growth before saturation: from collision 1 to the first collision
    /// where the curve passes half the plateau (at least two points). Its
    /// slope estimates the exponent per collision for a chaotic table.
    pub growth: LinearFit,
    /// The collisions of the growth fit (1-based, inclusive).
    pub fit_range: (usize, usize),
    /// Slope of a line through the last `tail` collisions: near zero once
    /// saturated, positive while still growing (integrable tables grow like
    /// `ln n` and never saturate in 50 collisions).
    pub tail_slope: f64,
}

/// Plateau, time to reach it and early slope of `separation` (see
/// [`SeparationSummary`]); the plateau is the mean of the last `tail`
/// collisions.
///
/// ```
/// use spinball_analysis::diagnostics::{
///     SeparationOptions, phase_space_separation, summarize_separation,
/// };
/// use spinball_core::{Billiard, SpinLaw};
/// use spinball_geometry::Stadium;
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.0)?);
/// let options = SeparationOptions { pairs: 300, ..Default::default() }; // 50 collisions
/// let s = summarize_separation(&phase_space_separation(&billiard, &options)?, 10)?;
/// assert!(s.plateau > 14.0 && s.plateau < 18.0); // ln(D/δ0), not e^50·λ
/// assert!(s.reach < 30 && s.tail_slope.abs() < 0.05);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnalysisError::InvalidOption`] unless `2 ≤ tail ≤` the number of
/// collisions recorded.
pub fn summarize_separation(
    separation: &Separation,
    tail: usize,
) -> Result<SeparationSummary, AnalysisError> {
    let n = separation.mean.len();
    if tail < 2 || tail > n {
        return Err(AnalysisError::invalid(
            "tail",
            format!("must be in 2..={n}, got {tail}"),
        ));
    }
    let plateau = separation.mean[n - tail..].iter().sum::<f64>() / tail as f64;
    let reach = separation
        .mean
        .iter()
        .position(|&m| m >= plateau - 1.0)
        .map_or(n, |i| i + 1);
    let half = separation
        .mean
        .iter()
        .position(|&m| m >= 0.5 * plateau)
        .map_or(n, |i| i + 1);
    let fit_end = half.clamp(2, n);
    let growth = separation.fit(1..=fit_end)?;
    let tail_slope = separation.fit(n - tail + 1..=n)?.slope;
    Ok(SeparationSummary {
        plateau,
        tail,
        reach,
        growth,
        fit_range: (1, fit_end),
        tail_slope,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_core::Sampler;

    fn curve(mean: Vec<f64>) -> Separation {
        Separation {
            sem: vec![0.0; mean.len()],
            mean,
            pairs: 2,
            delta0: 1e-7,
            seed: 0,
            sampler: Sampler::Paper,
        }
    }

    #[test]
    fn saturating_curve() {
        // slope 1 up to 16, then flat
        let s = curve((1..=50).map(|n| (n as f64).min(16.0)).collect());
        let sum = summarize_separation(&s, 10).unwrap();
        assert_eq!(sum.plateau, 16.0);
        assert_eq!(sum.reach, 15);
        assert_eq!(sum.fit_range, (1, 8));
        assert!((sum.growth.slope - 1.0).abs() < 1e-12);
        assert!(sum.tail_slope.abs() < 1e-12);
        assert!(summarize_separation(&s, 1).is_err());
        assert!(summarize_separation(&s, 51).is_err());
    }
}
