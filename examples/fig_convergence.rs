//! The paper's convergence checks (App. A.1): single-trajectory LCN traces
//! λ(t) for the four tables at five α, and its Table I, the ensemble λ of
//! the stadium and Sinai tables against the number of collisions.
//!
//! ```text
//! cargo run --release --example fig_convergence -- [--quick | --paper] [--out DIR] [--seed N]
//! ```
//!
//! | mode      | traces            | Table I: ICs × collisions                 |
//! |-----------|-------------------|-------------------------------------------|
//! | `--quick` | 10⁴ collisions    | 20 × {500, 10³, 2·10³, 5·10³}             |
//! | default   | 10⁵ (paper)       | 2000 × {10⁴, 5·10⁴, 10⁵, 5·10⁵}           |
//! | `--paper` | 10⁵               | 10⁴ × {10⁴, 5·10⁴, 10⁵, 5·10⁵} (paper)    |
//!
//! Traces start at (0.3, 0.2) (Sinai: (−1.5, 0.2)) with θ0 = 0.8, u0 = 0,
//! speed 1; the rectangle is L = H = 1. Table I: paper sampler, the same
//! initial conditions in every column. Finite differences, δ0 = 1e-7.
//! Writes `lcn_traces.png`/`.csv`, `convergence_table.png` (ours minus the
//! paper's), `convergence_table.csv`/`.md` (ours beside theirs, mean(SEM))
//! and `convergence.json`.

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::diagnostics;
use spinball_analysis::estimators::Method;
use spinball_analysis::precision::lcn_traces;
use spinball_core::State;
use spinball_figures::{
    Csv, LCN_TRACE_COLUMNS, TableIRecord, lcn_finals, lcn_trace_panel, lcn_trace_rows, run_figure,
    table_i_csv, table_i_grid, table_i_markdown, table_i_rows,
};
use spinball_geometry::{DVec2, Table};
use spinball_plot::Grid;

const NAME: &str = "fig_convergence";
const ABOUT: &str = "LCN traces λ(t) for four tables at five α, and the paper's Table I (λ vs number of collisions).";
const TRACE_ALPHAS: [f64; 5] = [0.0, 0.1, 0.3, 0.5, 1.0];
const THETA0: f64 = 0.8;
const U0: f64 = 0.0;
const TRACE_TABLES: [(&str, &str, [f64; 2]); 4] = [
    ("circle:R=1", "circle R = 1", [0.3, 0.2]),
    ("rectangle:L=1,H=1", "rectangle L = H = 1", [0.3, 0.2]),
    ("stadium:a=1", "stadium a = 1", [0.3, 0.2]),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1", [-1.5, 0.2]),
];
const TABLE_ALPHAS: [f64; 3] = [0.1, 0.5, 1.0];
const TABLE_TABLES: [(&str, &str); 2] = [("stadium:a=1", "Stadium"), ("sinai:L=2,R=1", "Sinai")];

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let trace_len: u64 = args.pick(10_000, 100_000, 100_000);
        let ics: u64 = args.pick(20, 2_000, 10_000);
        let paper_columns = diagnostics::TABLE_I_COLLISIONS.to_vec();
        let quick_columns = vec![500, 1_000, 2_000, 5_000];
        let checkpoints = args.pick(quick_columns, paper_columns.clone(), paper_columns);

        // 1. LCN traces, the shadow direction from initial condition 0 of the seed.
        let mut grid = Grid::new(2, 2).title(format!(
            "Single-trajectory LCN traces ({trace_len} collisions, θ₀ = {THETA0}, u₀ = {U0}, finite differences)"
        ));
        let mut csv = Csv::new(&LCN_TRACE_COLUMNS);
        let mut finals = Vec::new();
        for (spec, title, p) in TRACE_TABLES {
            let table: Table = spec.parse()?;
            let start = State::new(DVec2::from(p), DVec2::from_angle(THETA0), U0);
            let (method, seed) = (Method::default(), args.seed);
            let traces = lcn_traces(&table, start, &TRACE_ALPHAS, trace_len, method, 40, seed)?;
            lcn_trace_rows(&mut csv, spec, &traces);
            finals.extend(lcn_finals(spec, &traces));
            // Integrable tables get a 1/t guide.
            let integrable = matches!(table, Table::Circle(_) | Table::Rectangle(_));
            grid.push(lcn_trace_panel(title, &traces, integrable));
        }
        let size = args.pick((1400, 1050), (1800, 1350), (2200, 1650));
        report.png("lcn_traces.png", &grid, size)?;
        report.csv("lcn_traces.csv", &csv)?;

        // 2. Table I: the same initial conditions in every column.
        let rows = table_i_rows(args, &TABLE_TABLES, &TABLE_ALPHAS, ics, &checkpoints)?;
        let md = table_i_markdown(&rows, ics, args.seed);
        report.csv("convergence_table.csv", &table_i_csv(&rows))?;
        report.text("convergence_table.md", &md)?;
        let size = args.pick((1400, 650), (1800, 800), (2200, 1000));
        report.png(
            "convergence_table.png",
            &table_i_grid(&rows, &TABLE_TABLES, ics),
            size,
        )?;
        let traces = json!({"collisions": trace_len, "theta0": THETA0, "u0": U0, "alphas": TRACE_ALPHAS, "final": finals});
        let records: Vec<TableIRecord> = rows.iter().map(TableIRecord::from).collect();
        let table_i = json!({"ics": ics, "checkpoints": checkpoints, "method": Method::default(), "sampler": "paper", "rows": records});
        let doc = json!({"traces": traces, "table_i": table_i});
        report.json("convergence.json", &doc)?;
        print!("\n{md}");
        Ok(())
    })
}
