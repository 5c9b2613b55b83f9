//! Estimates as flat records: CSV rows, serde records and text tables.
//!
//! Documented in the group docs (`report/mod.rs`), section "Rows".

use super::names::{IcSource, MethodName};
use crate::diagnostics::rate_summary;
use crate::error::AnalysisError;
use crate::estimators::THRESHOLD_BAND;
use crate::precision::{BiasRegime, ErrorBudget, dhf_product};
use crate::run::{LyapunovEstimate, StopReason};

/// One estimate as a flat record: what a CSV row or a JSON point holds (no
/// per-trajectory data), with the derived quantities the paper's figures
/// plot. Serialisable with the `serde` feature; its CSV (header and rows)
/// comes from the same serde names ([`write_csv`](crate::report::write_csv)).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct SweepRow {
    /// Table spec (e.g. `stadium:a=1`).
    pub table: String,
    /// Spin parameter.
    pub alpha: f64,
    /// `fd` or `tangent`.
    pub method: MethodName,
    /// `paper`, `microcanonical` or `states`.
    pub sampler: IcSource,
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
    pub stop: StopReason,
    /// Crate version that computed it.
    pub version: String,
}

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
            table: estimate.table.to_string(),
            alpha: estimate.alpha,
            method: estimate.method.into(),
            sampler: estimate.sampler.into(),
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
            stop: estimate.stop,
            version: estimate.version.clone(),
        })
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
        let stop = match self.stop {
            StopReason::TargetReached => "target",
            StopReason::TotalErrorReached => "total",
            StopReason::TimeBudget => "budget",
            StopReason::RangeExhausted => "cap",
            StopReason::Completed => "done",
            StopReason::Cancelled => "cancelled",
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

/// One point's error budget as a flat record: the SEM, the finite-time and
/// method bias estimates, the total error and why the point stopped.
/// Serialisable with the `serde` feature.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct BudgetRow {
    /// Spin parameter.
    pub alpha: f64,
    /// Mean FTLE λ.
    pub mean: f64,
    /// Its standard error.
    pub sem: f64,
    /// Finite-time bias estimate `λ_T − λ`.
    pub finite_time_bias: f64,
    /// Its uncertainty.
    pub finite_time_bias_sem: f64,
    /// Which law the finite-time bias follows (`inverse_t`, `log_t_over_t`,
    /// `neither`).
    pub regime: BiasRegime,
    /// Method bias `λ_fd − λ_tangent` (0 for tangent).
    pub method_bias: f64,
    /// Its uncertainty.
    pub method_bias_sem: f64,
    /// Total error.
    pub total: f64,
    /// Its uncertainty.
    pub total_sem: f64,
    /// Why the point stopped.
    pub stop: StopReason,
}

impl BudgetRow {
    /// The record of `estimate` with its `budget`.
    #[must_use]
    pub fn new(estimate: &LyapunovEstimate, budget: &ErrorBudget) -> Self {
        BudgetRow {
            alpha: estimate.alpha,
            mean: estimate.mean,
            sem: budget.sem,
            finite_time_bias: budget.finite_time_bias.value,
            finite_time_bias_sem: budget.finite_time_bias.sem,
            regime: budget.regime,
            method_bias: budget.method_bias.value,
            method_bias_sem: budget.method_bias.sem,
            total: budget.total.value,
            total_sem: budget.total.sem,
            stop: estimate.stop,
        }
    }

    /// The header of [`BudgetRow::table_line`].
    #[must_use]
    pub fn table_header() -> String {
        format!(
            "{:>7} {:>9} {:>9} {:>10} {:>9} {:>10} {:>9} {:>6} {:>19}",
            "alpha", "lambda", "SEM", "bias_T", "law", "bias_fd", "total", "tot%", "stop"
        )
    }

    /// A fixed-width line: α, λ, SEM, finite-time bias, its law, method
    /// bias, total error, total in % of λ, stop reason.
    #[must_use]
    pub fn table_line(&self) -> String {
        format!(
            "{:>7.4} {:>9} {:>9} {:>10} {:>9} {:>10} {:>9} {:>6.2} {:>19}",
            self.alpha,
            fixed_or_sci(self.mean, 5),
            fixed_or_sci(self.sem, 5),
            format!("{:+.2e}", self.finite_time_bias),
            self.regime.name(),
            format!("{:+.2e}", self.method_bias),
            fixed_or_sci(self.total, 5),
            100.0 * self.total / self.mean.abs(),
            self.stop.name()
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::template;
    #[test]
    fn budget_rows_line_up_with_their_header() {
        let e = template().with_ics(16).with_collisions(400).run().unwrap();
        let budget = crate::precision::ErrorBudget::for_estimate(&template(), &e, 8);
        // The budget reads the estimate's 400 collisions, not the template's 300.
        assert!(budget.is_ok());
        let row = BudgetRow::new(&e, &budget.unwrap());
        assert_eq!(row.stop, StopReason::Completed);
        assert_eq!((row.alpha, row.mean, row.sem), (e.alpha, e.mean, e.sem));
        assert!(row.total >= row.sem);
        assert_eq!(row.table_line().len(), BudgetRow::table_header().len());
    }

    #[test]
    fn small_numbers_keep_their_digits() {
        assert_eq!(fixed_or_sci(0.43027, 5), "0.43027");
        assert_eq!(fixed_or_sci(0.00013, 5), "1.30e-4");
        assert_eq!(fixed_or_sci(0.0, 5), "0.00000");
        assert_eq!(fixed_or_sci(-0.00061, 5), "-6.10e-4");
        assert_eq!(fixed_or_sci(0.0012, 5), "0.00120");
    }
}
