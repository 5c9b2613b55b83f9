//! The paper's figures, for the spinball examples: what a `fig_*` example
//! composes, so that each example is only a short body.
//!
//! # Why this crate exists
//! The figures need a command line, sweeps sized per mode with progress on
//! stderr, figure panels made from analysis results, and CSV, JSON and NPY
//! files beside each PNG. None of that belongs in the libraries a user
//! depends on: `spinball-analysis` computes (it never parses arguments,
//! draws or writes files), `spinball-plot` draws arrays and tables (it never
//! parses arguments, writes documents or runs estimates), and the `spinball`
//! command line (`spinball-cli`) is the interface for scripts, including
//! `spinball sweep`. This crate is where the three meet for the paper's
//! figures. It is unpublished (`publish = false`): its API serves the
//! examples of this repository and changes with them.
//!
//! # Contents
//! - [`run_figure`] and [`run_figure_with`]: the `main` of a figure. The
//!   command line is read by clap ([`FigureArgs`]: `--out`, `--quick`,
//!   `--paper`, `--seed`, `--threads`, plus an example's own
//!   `#[derive(clap::Args)]` options), and a [`Report`] writes PNG, [`Csv`],
//!   NPY and JSON files (serde, with a common [`Header`]);
//! - [`Plan`], [`Job`], [`run_jobs`], [`Curve`]: λ(α) sweeps sized per mode,
//!   run with rows on stdout and [`Progress`] on stderr, written with
//!   [`write_curves`]; [`run_scan`] for families of tables with their curved
//!   share;
//! - figures of one analysis each, with their CSV rows: [`EnergyPanels`]
//!   (energy conservation), [`section_panel`] (Poincaré sections),
//!   [`island_panel`] (FTLE maps with the bouncing-ball island),
//!   [`orbits_map_panel`], [`island_window_panel`] and [`island_area_panel`]
//!   (periodic orbits on an FTLE map, the island around one, its area
//!   against α),
//!   [`kac_histogram`] (return times against Kac's lemma),
//!   [`survival_panel`] and [`escape_rate_panel`] (escape from an open
//!   table: `P(t)` with its fits, `γ(α)` with non-exponential escapes
//!   marked), [`diffusion_panel`], [`window_scan_series`] and
//!   [`apparent_d_series`] (transport on a periodic table),
//!   [`q_class_panel`] and [`q_conserved_panel`] (`ΔQ` between collisions),
//!   [`lcn_trace_panel`] (single-trajectory LCN traces),
//!   [`collision_rate_grid`] (ν and λ/ν against α),
//!   [`ftle_histogram`] and [`spectrum_grid`] (the Lyapunov spectrum against
//!   α), work–precision charts ([`error_vs_time`] and friends);
//! - [`measured`] and [`paper_markers`]: series of values ± SEM and of the
//!   paper's numbers ([`spinball_analysis::diagnostics`]); [`table_i_markdown`]
//!   and friends ([`table_i_rows`], [`table_i_grid`]) set our convergence
//!   table beside the paper's Table I;
//! - CSV tables of results that are not one
//!   [`SweepRow`](spinball_analysis::report::SweepRow) per point
//!   ([`summary_csv`], [`spectra_csv`], ...; the per-trajectory table is
//!   the result schema's, `spinball_analysis::report::trajectories_csv`).
//!
//! ```no_run
//! use std::process::ExitCode;
//! use spinball_figures::{Job, Plan, run_figure, run_jobs, template, write_curves};
//!
//! fn main() -> ExitCode {
//!     run_figure("fig_demo", "λ(α) of the stadium.", |args, report| {
//!         let plan = args.pick(Plan::fixed(48, 2_000), Plan::fixed(1_000, 10_000), Plan::fixed(100_000, 50_000));
//!         let job = Job::new("stadium a = 1", &plan, template(args, "stadium:a=1")?, &[0.0, 0.5, 1.0])?;
//!         let curves = run_jobs(vec![job])?;
//!         write_curves(report, "demo", &curves, &())?;
//!         Ok(())
//!     })
//! }
//! ```
#![forbid(unsafe_code)]

mod args;
mod csv;
mod curves;
mod energy_figure;
mod error;
mod escape_figure;
mod figure;
mod island_figure;
mod kac_figure;
mod lcn_figure;
mod measured;
mod orbit_figure;
mod plan;
mod progress;
mod q_figure;
mod rate_figure;
mod rates;
mod report;
mod result_plots;
mod result_tables;
mod scan;
mod section_figure;
mod table_i;
mod transport_figure;
mod work_plots;

pub use args::{DEFAULT_SEED, FigureArgs, Mode, NoOptions, usage};
pub use csv::{Csv, optional};
pub use curves::{Curve, CurveSummary, Job, run_jobs, template, write_curves};
pub use energy_figure::{
    ENERGY_FLOOR, ENERGY_LONG_COLUMNS, ENERGY_TRACE_COLUMNS, EnergyPanels, energy_long_rows,
    energy_trace_rows,
};
pub use error::FigureError;
pub use escape_figure::{
    ESCAPE_COLUMNS, EscapeFit, SURVIVAL_COLUMNS, escape_rate_panel, escape_rate_series, escape_row,
    survival_panel, survival_rows, tail_exponent_panel,
};
pub use figure::{BoxError, run_figure, run_figure_with};
pub use island_figure::{ISLAND_COLUMNS, island_panel, island_row};
pub use kac_figure::{
    KAC_COLUMNS, KAC_ORBIT_COLUMNS, kac_histogram, kac_orbit_rows, kac_ratio_series, kac_row,
};
pub use lcn_figure::{LCN_TRACE_COLUMNS, LcnFinal, lcn_finals, lcn_trace_panel, lcn_trace_rows};
pub use measured::{ALPHA_LABEL, LAMBDA_LABEL, measured, measured_band, paper_markers, scaled};
pub use orbit_figure::{
    class_colour, island_area_panel, island_window_panel, orbit_markers, orbits_map_panel,
};
pub use plan::{Plan, unit_grid};
pub use progress::Progress;
pub use q_figure::{
    Q_ZERO_AT, q_class_panel, q_class_summaries, q_conserved_panel, q_histograms_csv, q_medians,
};
pub use rate_figure::collision_rate_grid;
pub use rates::{CurveRates, relative_drop, relative_spread};
pub use report::{Header, Report};
pub use result_plots::{SpectrumPair, ftle_histogram, log_counts, spectrum_grid, spectrum_plot};
pub use result_tables::{
    histograms_csv, q_pairs_csv, q_populations, spectra_csv, spectrum_pairs_csv, summary_csv,
};
pub use scan::{Scan, ShareRow, curved_shares, run_scan, share_range, shares_csv, write_shares};
pub use section_figure::{SECTION_COLUMNS, section_cloud, section_panel, section_rows, shell_spin};
pub use table_i::{
    TableIColumn, TableIRecord, TableIRow, table_i_csv, table_i_grid, table_i_markdown,
    table_i_paper, table_i_plot, table_i_reference, table_i_rows,
};
pub use transport_figure::{
    DIFFUSION_COLUMNS, DiffusionRun, MSD_COLUMNS, WINDOW_COLUMNS, apparent_d_series,
    diffusion_panel, diffusion_row, diffusion_series, log_times, msd_rows, window_rows,
    window_scan_series,
};
pub use work_plots::{
    ESTIMATOR_COLUMNS, WORK_COLUMNS, bias_vs_t, error_vs_time, estimator_curves, estimator_rows,
    level_variances, method_label, sem_vs_n, time_to_target, work_rows,
};
