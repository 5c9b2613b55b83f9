//! Our Table I beside the paper's: ensemble-averaged λ ± SEM after several
//! numbers of collisions, as CSV, Markdown (the paper's `mean(SEM)`
//! notation), JSON records and a plot of the differences, each entry next
//! to the paper's ([`spinball_analysis::diagnostics::TABLE_I`]).
//!
//! The paper's convergence table is the one result a reader checks digit by
//! digit, so the comparison is written in the paper's own notation and
//! kept out of the example, which only runs the ensembles
//! ([`convergence_estimates`](spinball_analysis::precision::convergence_estimates)).
//!
//! ```
//! use spinball_figures::table_i_paper;
//! assert_eq!(table_i_paper("stadium:a=1", 0.5, 50_000).as_deref(), Some("0.183(1)"));
//! assert_eq!(table_i_paper("stadium:a=1", 0.5, 2_000), None);
//! ```

use std::fmt::{self, Write as _};
use std::time::Instant;

use serde::Serialize;
use spinball_analysis::precision::{Measurement, convergence_estimates, format_mean_sem};
use spinball_analysis::run::{Ensemble, LyapunovEstimate};
use spinball_analysis::{AnalysisError, diagnostics};

use spinball_core::SpinLaw;

use crate::args::FigureArgs;
use crate::csv::Csv;
use crate::curves::template;
use crate::figure::BoxError;
use crate::measured::measured;
use spinball_plot::viridis;
use spinball_plot::{Grid, LinePlot};

/// One table at one α: our estimates after each number of collisions.
#[derive(Debug, Clone)]
pub struct TableIRow {
    /// Table spec (`stadium:a=1`), as in [`diagnostics::TableIEntry::table`].
    pub table: String,
    /// Name in the Markdown table (`Stadium`).
    pub name: String,
    /// Spin parameter.
    pub alpha: f64,
    /// One estimate per number of collisions, in increasing order.
    pub columns: Vec<LyapunovEstimate>,
    /// Wall-clock seconds for the row.
    pub wall_time_s: f64,
}

impl TableIRow {
    /// Run `ensemble` (a table and α of Table I) to each of `checkpoints`
    /// collisions on the same initial conditions
    /// ([`convergence_estimates`]), timing it.
    ///
    /// # Errors
    /// As [`convergence_estimates`].
    pub fn measure(
        table: &str,
        name: &str,
        ensemble: &Ensemble,
        checkpoints: &[u64],
    ) -> Result<Self, AnalysisError> {
        let clock = Instant::now();
        let columns = convergence_estimates(ensemble, checkpoints)?;
        Ok(TableIRow {
            table: table.to_string(),
            name: name.to_string(),
            alpha: ensemble.alpha(),
            columns,
            wall_time_s: clock.elapsed().as_secs_f64(),
        })
    }
}

impl fmt::Display for TableIRow {
    /// `Stadium α = 0.5: 0.1866(17)  0.1864(17)  (3.2 s)`
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let entries: Vec<String> = self
            .columns
            .iter()
            .map(|e| format_mean_sem(e.mean(), e.sem(), 4))
            .collect();
        write!(
            f,
            "{:<7} α = {:<3}: {}  ({:.1} s)",
            self.name,
            self.alpha,
            entries.join("  "),
            self.wall_time_s
        )
    }
}

/// The rows of Table I: every table of `tables` (spec, name) at every α of
/// `alphas`, `ics` initial conditions of the command line's seed (the
/// same in every column) run to each of `checkpoints` collisions
/// ([`TableIRow::measure`]), each row printed as it is measured.
///
/// # Errors
/// A spec that does not name a table, an invalid α, and as
/// [`convergence_estimates`].
pub fn table_i_rows(
    args: &FigureArgs,
    tables: &[(&str, &str)],
    alphas: &[f64],
    ics: u64,
    checkpoints: &[u64],
) -> Result<Vec<TableIRow>, BoxError> {
    let mut rows = Vec::with_capacity(tables.len() * alphas.len());
    for (spec, name) in tables {
        for &alpha in alphas {
            let ensemble = template(args, spec)?
                .with_law(SpinLaw::new(alpha)?)
                .with_ics(ics);
            let row = TableIRow::measure(spec, name, &ensemble, checkpoints)?;
            println!("  {row}");
            rows.push(row);
        }
    }
    Ok(rows)
}

/// Side by side, one [`table_i_plot`] per table of `tables` (spec, name),
/// under a title saying that each point has `ics` initial conditions.
#[must_use]
pub fn table_i_grid(rows: &[TableIRow], tables: &[(&str, &str)], ics: u64) -> Grid {
    let title = format!(
        "Table I: our λ minus the paper's ({ics} ICs per point, ± our SEM; paper rounds to ±0.0005)"
    );
    let grid = Grid::new(1, tables.len()).title(title);
    let plots = tables
        .iter()
        .map(|(spec, name)| table_i_plot(rows, spec, name));
    plots.fold(grid, Grid::panel)
}

/// The paper's entry as printed (`0.183(1)`), if it lists one.
pub fn table_i_paper(table: &str, alpha: f64, collisions: u64) -> Option<String> {
    diagnostics::table_i(table, alpha, collisions)
        .map(|m| format_mean_sem(m.value, m.sem, diagnostics::TABLE_I_DECIMALS))
}

/// The paper's value to compare with after `collisions` collisions: its
/// entry there, or (for a length it does not list) its longest column.
pub fn table_i_reference(table: &str, alpha: f64, collisions: u64) -> Option<f64> {
    let longest = diagnostics::TABLE_I_COLLISIONS[diagnostics::TABLE_I_COLLISIONS.len() - 1];
    diagnostics::table_i(table, alpha, collisions)
        .or_else(|| diagnostics::table_i(table, alpha, longest))
        .map(|m| m.value)
}

/// One entry per row and column: table, α, collisions, ICs, mean, SEM,
/// median, chaotic fraction and the paper's entry (empty where it has none).
pub fn table_i_csv(rows: &[TableIRow]) -> Csv {
    let mut csv = Csv::new(&[
        "table",
        "alpha",
        "collisions",
        "ics",
        "mean",
        "sem",
        "median",
        "chaotic_fraction",
        "paper",
    ]);
    for r in rows {
        for e in &r.columns {
            let paper = table_i_paper(&r.table, r.alpha, e.collisions_per_ic()).unwrap_or_default();
            csv.row(&[
                &r.table,
                &r.alpha,
                &e.collisions_per_ic(),
                &e.n_ics(),
                &e.mean(),
                &e.sem(),
                &e.median(),
                &e.chaotic_fraction(),
                &paper,
            ]);
        }
    }
    csv
}

/// A Markdown table: per row our values with three decimals (the paper's
/// notation), with four, and the paper's, under a line saying how ours were
/// run (`ics` initial conditions, `seed`).
pub fn table_i_markdown(rows: &[TableIRow], ics: u64, seed: u64) -> String {
    let checkpoints: Vec<u64> = rows
        .first()
        .map(|r| r.columns.iter().map(|e| e.collisions_per_ic()).collect())
        .unwrap_or_default();
    let header: Vec<String> = checkpoints.iter().map(u64::to_string).collect();
    let mut md = format!(
        "Ensemble-averaged LCN ± SEM (in units of the last digit) vs number of collisions; \
         ours: {ics} ICs per entry, seed {seed}, finite differences δ0 = 1e-7, paper sampler; \
         paper: {} ICs per entry.\n\n\
         | Geometry | α | source | {} |\n|---|---|---|{}\n",
        diagnostics::TABLE_I_ICS,
        header.join(" | "),
        "---|".repeat(checkpoints.len())
    );
    for r in rows {
        let ours = |decimals: usize| -> Vec<String> {
            r.columns
                .iter()
                .map(|e| format_mean_sem(e.mean(), e.sem(), decimals))
                .collect()
        };
        let theirs: Vec<String> = r
            .columns
            .iter()
            .map(|e| table_i_paper(&r.table, r.alpha, e.collisions_per_ic()).unwrap_or("–".into()))
            .collect();
        let _ = writeln!(
            md,
            "| {} | {} | ours | {} |",
            r.name,
            r.alpha,
            ours(3).join(" | ")
        );
        let _ = writeln!(md, "| | | ours (4 d.) | {} |", ours(4).join(" | "));
        let _ = writeln!(md, "| | | paper | {} |", theirs.join(" | "));
    }
    md
}

/// Our λ minus the paper's, in 10⁻³ per unit time, against the number of
/// collisions (log axis), one series per row of `rows` on `table`, with our
/// SEM as error bars; lengths the paper does not list are compared with its
/// longest column.
pub fn table_i_plot(rows: &[TableIRow], table: &str, title: &str) -> LinePlot {
    let (x, y) = ("collisions per trajectory", "⟨λ⟩ − λ_paper (10⁻³/time)");
    let mut plot = LinePlot::with_axes(title, x, y).log_x(true).hline(0.0, "");
    let rows: Vec<&TableIRow> = rows.iter().filter(|r| r.table == table).collect();
    for (k, r) in rows.iter().enumerate() {
        let diff = r.columns.iter().map(|e| {
            let c = e.collisions_per_ic();
            let reference = table_i_reference(table, r.alpha, c).unwrap_or(f64::NAN);
            let m = Measurement::new(1e3 * (e.mean() - reference), 1e3 * e.sem());
            (c as f64, m)
        });
        let color = viridis(k as f64 / (rows.len().max(2) - 1) as f64 * 0.85);
        plot = plot.series(
            measured(format!("α = {}", r.alpha), diff)
                .color(color)
                .marker_radius(5),
        );
    }
    plot
}

/// One entry as a JSON record.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TableIColumn {
    /// Collisions per initial condition.
    pub collisions: u64,
    /// Initial conditions.
    pub ics: u64,
    /// Mean FTLE.
    pub mean: f64,
    /// Its standard error.
    pub sem: f64,
    /// Median FTLE.
    pub median: f64,
    /// Chaotic fraction.
    pub chaotic_fraction: f64,
    /// The paper's entry as printed, if any.
    pub paper: Option<String>,
}

/// One row as a JSON record.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TableIRecord {
    /// Table spec.
    pub table: String,
    /// Spin parameter.
    pub alpha: f64,
    /// The entries.
    pub columns: Vec<TableIColumn>,
    /// Wall-clock seconds.
    pub wall_time_s: f64,
}

impl From<&TableIRow> for TableIRecord {
    fn from(r: &TableIRow) -> Self {
        TableIRecord {
            table: r.table.clone(),
            alpha: r.alpha,
            columns: r
                .columns
                .iter()
                .map(|e| TableIColumn {
                    collisions: e.collisions_per_ic(),
                    ics: e.n_ics(),
                    mean: e.mean(),
                    sem: e.sem(),
                    median: e.median(),
                    chaotic_fraction: e.chaotic_fraction(),
                    paper: table_i_paper(&r.table, r.alpha, e.collisions_per_ic()),
                })
                .collect(),
            wall_time_s: r.wall_time_s,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_analysis::run::Threads;

    fn row() -> TableIRow {
        let table: spinball_geometry::Table = "stadium:a=1".parse().unwrap();
        let ensemble = Ensemble::new(table, SpinLaw::new(0.5).unwrap())
            .with_ics(6)
            .with_threads(Threads::Fixed(1));
        let row = TableIRow::measure("stadium:a=1", "Stadium", &ensemble, &[500, 10_000]).unwrap();
        assert_eq!((row.alpha, row.columns.len()), (0.5, 2));
        assert!(row.to_string().starts_with("Stadium α = 0.5: "), "{row}");
        row
    }

    #[test]
    fn paper_entries_and_references() {
        assert_eq!(
            table_i_paper("sinai:L=2,R=1", 0.1, 10_000).as_deref(),
            Some("0.211(0)")
        );
        assert_eq!(table_i_reference("stadium:a=1", 1.0, 100_000), Some(0.146));
        // Lengths the paper does not list compare with its longest column.
        assert_eq!(table_i_reference("stadium:a=1", 1.0, 2_000), Some(0.147));
        assert_eq!(table_i_reference("circle:R=1", 1.0, 10_000), None);
    }

    #[test]
    fn csv_markdown_and_records() {
        let rows = [row()];
        let csv = table_i_csv(&rows);
        let lines: Vec<&str> = csv.as_str().lines().collect();
        assert_eq!(lines.len(), 3);
        assert!(
            lines[1].starts_with("stadium:a=1,0.5,500,6,") && lines[1].ends_with(','),
            "{}",
            lines[1]
        );
        assert!(
            lines[2].starts_with("stadium:a=1,0.5,10000,6,") && lines[2].ends_with(",0.183(1)")
        );
        let md = table_i_markdown(&rows, 6, 9);
        assert!(md.contains("ours: 6 ICs per entry, seed 9,"));
        assert!(md.contains("| Geometry | α | source | 500 | 10000 |\n|---|---|---|---|---|\n"));
        assert!(md.contains("| | | paper | – | 0.183(1) |\n"), "{md}");
        let e = &rows[0].columns[1];
        let ours = format!(
            "| Stadium | 0.5 | ours | {} | {} |",
            format_mean_sem(rows[0].columns[0].mean(), rows[0].columns[0].sem(), 3),
            format_mean_sem(e.mean(), e.sem(), 3)
        );
        assert!(md.contains(&ours), "{md}");
        let rec = TableIRecord::from(&rows[0]);
        assert_eq!(
            (rec.columns[1].collisions, rec.columns[1].mean),
            (10_000, e.mean())
        );
        assert_eq!(rec.columns[0].paper, None);
        assert_eq!(rec.columns[1].paper.as_deref(), Some("0.183(1)"));
        use spinball_plot::Plot;
        assert!(
            table_i_plot(&rows, "stadium:a=1", "Stadium")
                .validate()
                .is_ok()
        );
        // No rows for that table: nothing to draw.
        assert!(
            table_i_plot(&rows, "sinai:L=2,R=1", "Sinai")
                .validate()
                .is_err()
        );
    }

    #[test]
    fn rows_of_two_tables_and_their_grid() {
        let args =
            FigureArgs::try_parse_from("fig_t", "", ["--seed", "5", "--threads", "1"]).unwrap();
        let tables = [("stadium:a=1", "Stadium"), ("sinai:L=2,R=1", "Sinai")];
        let rows = table_i_rows(&args, &tables, &[0.5, 1.0], 4, &[300, 600]).unwrap();
        let keys: Vec<(&str, f64)> = rows.iter().map(|r| (r.table.as_str(), r.alpha)).collect();
        assert_eq!(
            keys,
            [
                ("stadium:a=1", 0.5),
                ("stadium:a=1", 1.0),
                ("sinai:L=2,R=1", 0.5),
                ("sinai:L=2,R=1", 1.0)
            ]
        );
        // Each row is the ensemble of the command line's seed at that α.
        let table: spinball_geometry::Table = "sinai:L=2,R=1".parse().unwrap();
        let ensemble = Ensemble::new(table, SpinLaw::new(1.0).unwrap())
            .with_ics(4)
            .with_seed(5)
            .with_threads(Threads::Fixed(1));
        let expected = convergence_estimates(&ensemble, &[300, 600]).unwrap();
        let means =
            |e: &[LyapunovEstimate]| e.iter().map(|e| (e.mean(), e.sem())).collect::<Vec<_>>();
        assert_eq!(means(&rows[3].columns), means(&expected));
        assert_eq!(rows[3].columns[1].n_ics(), 4);
        use spinball_plot::Plot;
        assert!(table_i_grid(&rows, &tables, 4).validate().is_ok());
        assert!(table_i_rows(&args, &[("stadium:a=1", "S")], &[-1.0], 4, &[300]).is_err());
    }
}
