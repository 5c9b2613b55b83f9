//! Distributions of finite-time Lyapunov exponents (FTLE) over an ensemble,
//! and the chaotic fraction.
//!
//! Documented in the group docs (`estimators/mod.rs`), section "FTLE distributions and the chaotic fraction".

use super::stats::{self, Accumulator, Histogram};
use crate::error::AnalysisError;

/// The paper's threshold between regular and chaotic trajectories: an FTLE
/// strictly above `0.01` (per unit time) counts as chaotic (paper §VI).
pub const CHAOS_THRESHOLD: f64 = 0.01;

/// The band of thresholds over which the paper checks that the chaotic
/// fraction is robust (0.001 to 0.05, paper §VI and its Fig. of `f_ch`).
pub const THRESHOLD_BAND: [f64; 6] = [0.001, 0.002, 0.005, 0.01, 0.02, 0.05];

/// The chaotic fraction at one threshold, with its binomial standard error.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ChaoticFraction {
    /// Trajectories with FTLE strictly above this count as chaotic.
    pub threshold: f64,
    /// Number of chaotic trajectories.
    pub chaotic: u64,
    /// Number of trajectories.
    pub total: u64,
    /// `chaotic / total`.
    pub fraction: f64,
    /// Binomial standard error `√(f (1 − f) / total)` (0 when `f` is 0 or 1:
    /// then read it as "less than about `1/total`").
    pub sem: f64,
}

/// The chaotic fraction over a band of thresholds (see [`THRESHOLD_BAND`]).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ChaoticBand {
    /// One entry per threshold, in the order given.
    pub points: Vec<ChaoticFraction>,
    /// Smallest fraction over the band.
    pub min: f64,
    /// Largest fraction over the band.
    pub max: f64,
}

impl ChaoticBand {
    /// Width of the band, `max − min`: how much the threshold choice matters.
    pub fn spread(&self) -> f64 {
        self.max - self.min
    }
}

/// Finite-time Lyapunov exponents of an ensemble, one per trajectory, in
/// initial-condition index order.
///
/// ```
/// use spinball_analysis::estimators::FtleDistribution;
/// // two regular trajectories (FTLE <= 0.01) and three chaotic ones
/// let d = FtleDistribution::new(vec![0.0, 0.25, 0.5, 0.005, 0.75])?;
/// assert_eq!(d.median(), 0.25);
/// assert_eq!(d.chaotic_fraction(0.01), 0.6);
/// assert_eq!(d.conditional_mean(0.01), Some(0.5)); // the chaotic part only
/// # Ok::<(), spinball_analysis::AnalysisError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FtleDistribution {
    exponents: Vec<f64>,
}

impl FtleDistribution {
    /// A distribution from per-trajectory exponents (keep them in index order
    /// so that sums are reproducible).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if `exponents` is empty or holds a
    /// value that is not finite.
    pub fn new(exponents: Vec<f64>) -> Result<Self, AnalysisError> {
        if exponents.is_empty() {
            return Err(AnalysisError::invalid(
                "exponents",
                "an FTLE distribution needs at least one trajectory",
            ));
        }
        if let Some((i, x)) = exponents.iter().enumerate().find(|(_, x)| !x.is_finite()) {
            return Err(AnalysisError::invalid(
                "exponents",
                format!("exponent {i} is not finite ({x})"),
            ));
        }
        Ok(FtleDistribution { exponents })
    }

    /// The exponents, in the order given.
    pub fn exponents(&self) -> &[f64] {
        &self.exponents
    }

    /// Number of trajectories.
    pub fn len(&self) -> usize {
        self.exponents.len()
    }

    /// Always `false` (a distribution has at least one exponent); here for
    /// the `len`/`is_empty` convention.
    pub fn is_empty(&self) -> bool {
        self.exponents.is_empty()
    }

    /// Append the exponents of `other` (the next index range), as if both had
    /// been one run.
    pub fn extend_from(&mut self, other: &FtleDistribution) {
        self.exponents.extend_from_slice(&other.exponents);
    }

    /// Running statistics of the exponents, pushed in order.
    pub fn accumulator(&self) -> Accumulator {
        Accumulator::from_slice(&self.exponents)
    }

    /// Mean exponent (Welford, in order).
    pub fn mean(&self) -> f64 {
        self.accumulator().mean().unwrap_or(0.0)
    }

    /// Median exponent (robust to the regular islands near zero).
    pub fn median(&self) -> f64 {
        stats::median(&self.exponents).unwrap_or(0.0)
    }

    /// The `q`-quantile (type 7, see [`stats::quantile`](crate::estimators::quantile)).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for `q` outside `[0, 1]`.
    pub fn quantile(&self, q: f64) -> Result<f64, AnalysisError> {
        stats::quantile(&self.exponents, q)
            .ok_or_else(|| AnalysisError::invalid("q", format!("must be in [0, 1], got {q}")))
    }

    /// Sample standard deviation (`None` for one trajectory).
    pub fn std(&self) -> Option<f64> {
        self.accumulator().std()
    }

    /// Standard error of the mean (`None` for one trajectory).
    pub fn sem(&self) -> Option<f64> {
        self.accumulator().sem()
    }

    /// Smallest exponent.
    pub fn min(&self) -> f64 {
        self.exponents.iter().copied().fold(f64::INFINITY, f64::min)
    }

    /// Largest exponent.
    pub fn max(&self) -> f64 {
        self.exponents
            .iter()
            .copied()
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Mean over the chaotic trajectories only (FTLE > `threshold`), the
    /// paper's "conditional mean of the chaotic component". `None` if no
    /// trajectory is above the threshold (an integrable table).
    pub fn conditional_mean(&self, threshold: f64) -> Option<f64> {
        stats::conditional_mean(&self.exponents, threshold)
    }

    /// Share of trajectories with FTLE strictly above `threshold`
    /// (the paper: [`CHAOS_THRESHOLD`] = 0.01).
    pub fn chaotic_fraction(&self, threshold: f64) -> f64 {
        stats::fraction_above(&self.exponents, threshold)
    }

    /// The chaotic fraction at `threshold` with its count and binomial error.
    pub fn chaotic_fraction_at(&self, threshold: f64) -> ChaoticFraction {
        let total = self.exponents.len() as u64;
        let chaotic = stats::count_above(&self.exponents, threshold) as u64;
        let fraction = chaotic as f64 / total as f64;
        ChaoticFraction {
            threshold,
            chaotic,
            total,
            fraction,
            sem: (fraction * (1.0 - fraction) / total as f64).sqrt(),
        }
    }

    /// The chaotic fraction at each of `thresholds` (e.g. [`THRESHOLD_BAND`]),
    /// with the band's minimum and maximum. An empty `thresholds` gives an
    /// empty band with `min = max = fraction at` [`CHAOS_THRESHOLD`].
    pub fn chaotic_fraction_band(&self, thresholds: &[f64]) -> ChaoticBand {
        let points: Vec<ChaoticFraction> = thresholds
            .iter()
            .map(|&t| self.chaotic_fraction_at(t))
            .collect();
        let fallback = self.chaotic_fraction(CHAOS_THRESHOLD);
        let min = points.iter().map(|p| p.fraction).reduce(f64::min);
        let max = points.iter().map(|p| p.fraction).reduce(f64::max);
        ChaoticBand {
            min: min.unwrap_or(fallback),
            max: max.unwrap_or(fallback),
            points,
        }
    }

    /// The Datseris–Hupe–Fleischmann product `λ · f_ch`: the mean exponent
    /// times the chaotic fraction at `threshold`. DH scaling
    /// (`λ ∝ 1/f_ch`) predicts it constant in a parameter; the paper finds
    /// it falls by a factor 2–3 over α ∈ [0, 1].
    pub fn dhf_product(&self, threshold: f64) -> f64 {
        self.mean() * self.chaotic_fraction(threshold)
    }

    /// Histogram of the exponents in `bins` equal bins over `[lo, hi)`
    /// (values outside land in under/overflow).
    ///
    /// # Errors
    /// As [`Histogram::new`].
    pub fn histogram(&self, lo: f64, hi: f64, bins: usize) -> Result<Histogram, AnalysisError> {
        let mut h = Histogram::new(lo, hi, bins)?;
        for &x in &self.exponents {
            h.push(x);
        }
        Ok(h)
    }

    /// Histogram over `[min, max]` of the data (widened slightly so the
    /// maximum falls inside; a little width around a single value), in
    /// `bins` bins.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] unless `1 <= bins <=`
    /// [`Histogram::MAX_BINS`].
    pub fn auto_histogram(&self, bins: usize) -> Result<Histogram, AnalysisError> {
        let (lo, hi) = (self.min(), self.max());
        let span = if hi > lo {
            hi - lo
        } else {
            lo.abs().max(1.0) * 1e-6
        };
        self.histogram(lo, (lo + span * (1.0 + 1e-9)).max(hi.next_up()), bins)
    }
}
