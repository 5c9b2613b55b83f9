//! Estimates as flat records: CSV rows, serde records and text tables.
//!
//! Documented in the group docs (`report/mod.rs`), section "Rows".

use std::{fmt::Write as _, io};

use crate::diagnostics::rate_summary;
use crate::error::AnalysisError;
use crate::estimators::THRESHOLD_BAND;
use crate::precision::{ErrorBudget, dhf_product};
use crate::run::LyapunovEstimate;

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
            table: estimate.table.to_string(),
            alpha: estimate.alpha,
            method: estimate.method.name().to_string(),
            sampler: estimate.sampler.map_or("states", |s| s.name()).to_string(),
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
            "total_error_reached" => "total",
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
    /// Which law the finite-time bias follows (`1/T`, `ln T / T`, `neither`).
    pub regime: String,
    /// Method bias `λ_fd − λ_tangent` (0 for tangent).
    pub method_bias: f64,
    /// Its uncertainty.
    pub method_bias_sem: f64,
    /// Total error.
    pub total: f64,
    /// Its uncertainty.
    pub total_sem: f64,
    /// Why the point stopped.
    pub stop: String,
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
            regime: budget.regime.name().to_string(),
            method_bias: budget.method_bias.value,
            method_bias_sem: budget.method_bias.sem,
            total: budget.total.value,
            total_sem: budget.total.sem,
            stop: estimate.stop.name().to_string(),
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
            self.regime,
            format!("{:+.2e}", self.method_bias),
            fixed_or_sci(self.total, 5),
            100.0 * self.total / self.mean.abs(),
            self.stop
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::run::{AlphaSweep, Ensemble, Threads};
    use crate::test_support::template;
    use spinball_core::SpinLaw;
    use spinball_geometry::Table;
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
    fn budget_rows_line_up_with_their_header() {
        let e = template().with_ics(16).with_collisions(400).run().unwrap();
        let budget = crate::precision::ErrorBudget::for_estimate(&template(), &e, 8);
        // The budget reads the estimate's 400 collisions, not the template's 300.
        assert!(budget.is_ok());
        let row = BudgetRow::new(&e, &budget.unwrap());
        assert_eq!(row.stop, "completed");
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
