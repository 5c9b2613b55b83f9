//! Scans over a family of tables (stadium flat length, Sinai obstacle
//! radius): one λ(α) curve per table, with each table's share of collisions
//! on curved walls at every α in its legend label.
//!
//! The paper explains how much spin reduces chaos by where the ball hits:
//! its geometry figures quote each table's curved share next to its curve.
//! The shares are measured here ([`curved_share()`] at each α) and written as
//! flat records ([`ShareRow`]: one CSV line or JSON object per table and
//! α, without the full wall statistics).
//!
//! ```no_run
//! use spinball_figures::{FigureArgs, Plan, Report, run_scan, unit_grid, write_shares};
//!
//! let args = FigureArgs::parse_or_exit("fig_demo", "Stadiums.");
//! let tables = [("stadium:a=1".to_string(), "a = 1".to_string())];
//! let scan = run_scan(&args, &tables, &unit_grid(3), &Plan::fixed(48, 2_000), (8, 1_000))?;
//! println!("{}", scan.curves[0].label); // "a = 1 (61% curved)"
//! write_shares(&mut Report::new("fig_demo", &args), "demo", &scan)?;
//! # Ok::<(), spinball_figures::BoxError>(())
//! ```

use serde::Serialize;
use spinball_analysis::diagnostics::{CurvedShare, curved_share};
use spinball_analysis::run::Threads;
use spinball_core::{Sampler, SpinLaw};
use spinball_geometry::Table;

use crate::args::FigureArgs;
use crate::csv::Csv;
use crate::curves::{Curve, Job, run_jobs, template};
use crate::error::FigureError;
use crate::figure::BoxError;
use crate::plan::Plan;
use crate::report::Report;

/// The share of collisions on curved walls of one table at one α, flat.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ShareRow {
    /// Table spec.
    pub table: String,
    /// Spin parameter.
    pub alpha: f64,
    /// Mean over initial conditions of each trajectory's curved share.
    pub curved_share: f64,
    /// Its standard error.
    pub curved_share_sem: f64,
    /// Curved collisions over all collisions.
    pub pooled: f64,
    /// The curved walls' share of the perimeter (the α = 0 theory).
    pub perimeter_share: f64,
    /// Initial conditions.
    pub n_ics: u64,
    /// Collisions per initial condition.
    pub collisions_per_ic: u64,
    /// Wall-clock seconds.
    pub wall_time_s: f64,
}

impl From<&CurvedShare> for ShareRow {
    fn from(s: &CurvedShare) -> Self {
        ShareRow {
            table: s.table.to_string(),
            alpha: s.alpha,
            curved_share: s.per_ic.value,
            curved_share_sem: s.per_ic.sem,
            pooled: s.pooled,
            perimeter_share: s.perimeter_share,
            n_ics: s.n_ics,
            collisions_per_ic: s.collisions_per_ic,
            wall_time_s: s.wall_time_s,
        }
    }
}

/// The rows as CSV (every field but the wall time).
pub fn shares_csv(rows: &[ShareRow]) -> Csv {
    let mut csv = Csv::new(&[
        "table",
        "alpha",
        "curved_share",
        "curved_share_sem",
        "pooled",
        "perimeter_share",
        "n_ics",
        "collisions_per_ic",
    ]);
    for r in rows {
        csv.row(&[
            &r.table,
            &r.alpha,
            &r.curved_share,
            &r.curved_share_sem,
            &r.pooled,
            &r.perimeter_share,
            &r.n_ics,
            &r.collisions_per_ic,
        ]);
    }
    csv
}

/// The curved share of `table` at each of `alphas` (paper sampler, initial
/// conditions `0..ics` of `seed`, `collisions` each).
///
/// # Errors
/// As [`curved_share()`]; an α outside `[0, 1]`.
pub fn curved_shares(
    table: &Table,
    alphas: &[f64],
    seed: u64,
    (ics, collisions): (u64, u64),
    threads: Threads,
) -> Result<Vec<CurvedShare>, BoxError> {
    alphas
        .iter()
        .map(|&a| {
            let law = SpinLaw::new(a)?;
            Ok(curved_share(
                table,
                law,
                Sampler::Paper,
                seed,
                0..ics,
                collisions,
                threads,
            )?)
        })
        .collect()
}

/// `"61%"`, or `"58–63%"`: the range over α of the per-IC mean curved share,
/// in whole percent.
pub fn share_range(shares: &[CurvedShare]) -> String {
    let v: Vec<f64> = shares.iter().map(|s| 100.0 * s.per_ic.value).collect();
    let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if hi.round() == lo.round() {
        format!("{lo:.0}%")
    } else {
        format!("{lo:.0}–{hi:.0}%")
    }
}

/// The results of a scan: one curve per table, labelled
/// `"<label> (61–63% curved)"`, and its curved shares, one per α.
#[derive(Debug, Clone)]
pub struct Scan {
    /// One curve per table.
    pub curves: Vec<Curve>,
    /// Curved shares per table, one per α.
    pub shares: Vec<Vec<CurvedShare>>,
}

impl Scan {
    /// The curved shares of table `i` as flat rows.
    pub fn share_rows(&self, i: usize) -> Vec<ShareRow> {
        self.shares[i].iter().map(ShareRow::from).collect()
    }
}

/// Scan `tables` (spec, label) over `alphas`: first the curved shares
/// (`share` = initial conditions × collisions per α, cheap, printed as they
/// finish), then one sweep per table sized by `plan` ([`run_jobs`]).
///
/// # Errors
/// A bad table spec or α, and the errors of the runs.
pub fn run_scan(
    args: &FigureArgs,
    tables: &[(String, String)],
    alphas: &[f64],
    plan: &Plan,
    share: (u64, u64),
) -> Result<Scan, BoxError> {
    println!(
        "\ncurved share (paper sampler, {} ICs x {} collisions per alpha):",
        share.0, share.1
    );
    let mut shares = Vec::new();
    let mut jobs = Vec::new();
    for (spec, label) in tables {
        let template = template(args, spec)?;
        let s = curved_shares(&template.table, alphas, args.seed, share, args.threads)?;
        let (first, last) = (&s[0], &s[s.len() - 1]);
        println!(
            "  {label:<22} perimeter share {:.3} | alpha {}: {:.3} ± {:.3} | alpha {}: {:.3} ± {:.3}",
            first.perimeter_share,
            first.alpha,
            first.per_ic.value,
            first.per_ic.sem,
            last.alpha,
            last.per_ic.value,
            last.per_ic.sem,
        );
        let label = format!("{label} ({} curved)", share_range(&s));
        jobs.push(Job::new(label, plan, template, alphas)?);
        shares.push(s);
    }
    Ok(Scan {
        curves: run_jobs(jobs)?,
        shares,
    })
}

/// Write the curved shares of `scan` to `<stem>_curved.csv`.
///
/// # Errors
/// As [`Report::csv`].
pub fn write_shares(report: &mut Report, stem: &str, scan: &Scan) -> Result<(), FigureError> {
    let rows: Vec<ShareRow> = (0..scan.shares.len())
        .flat_map(|i| scan.share_rows(i))
        .collect();
    report.csv(&format!("{stem}_curved.csv"), &shares_csv(&rows))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shares_of_the_stadium() {
        let table: Table = "stadium:a=1".parse().unwrap();
        let shares = curved_shares(&table, &[0.0, 1.0], 1, (8, 500), Threads::Fixed(1)).unwrap();
        assert_eq!(shares.len(), 2);
        let rows: Vec<ShareRow> = shares.iter().map(ShareRow::from).collect();
        assert_eq!(rows[1].table, "stadium:a=1");
        assert_eq!(
            (rows[1].alpha, rows[1].n_ics, rows[1].collisions_per_ic),
            (1.0, 8, 500)
        );
        assert!((rows[0].perimeter_share - 0.611).abs() < 1e-3);
        let csv = shares_csv(&rows);
        let lines: Vec<&str> = csv.as_str().lines().collect();
        assert_eq!(lines.len(), 3);
        assert!(lines[1].starts_with("stadium:a=1,0,"), "{}", lines[1]);
        assert_eq!(lines[2].split(',').count(), 8);
        let v = serde_json::to_value(&rows[0]).unwrap();
        assert_eq!(v["curved_share"], rows[0].curved_share);
        assert!(curved_shares(&table, &[1.5], 1, (8, 500), Threads::Fixed(1)).is_err());
    }

    #[test]
    fn share_ranges_in_whole_percent() {
        let table: Table = "stadium:a=1".parse().unwrap();
        let mut shares =
            curved_shares(&table, &[0.0, 0.0], 1, (4, 200), Threads::Fixed(1)).unwrap();
        shares[0].per_ic.value = 0.581;
        shares[1].per_ic.value = 0.6349;
        assert_eq!(share_range(&shares), "58–63%");
        shares[1].per_ic.value = 0.584;
        assert_eq!(share_range(&shares), "58%");
    }
}
