//! Plots for [spinball](https://docs.rs/spinball): the pictures a physicist
//! puts in a talk, drawn to PNG with a bundled font and no system libraries.
//!
//! The crate is small on purpose. It draws five things, each a [`Plot`]:
//! - [`TablePlot`]: a table outline (any built-in [`Table`] or a
//!   [`SegmentTable`]), optionally with a trajectory coloured from early to
//!   late by the [`viridis`] colormap;
//! - [`LinePlot`]: curves of [`Series`] with error bars, shaded min–max bands,
//!   reference lines, a legend and linear or logarithmic axes (λ(α) curves,
//!   energy traces, convergence traces);
//! - [`HistogramPlot`]: a histogram with vertical [`Marker`] lines (mean, median,
//!   conditional mean) and a legend;
//! - [`MapPlot`] and [`Scatter3d`]: phase space, a value per grid cell (an
//!   FTLE map) or per point (a section coloured by spin) with outlined
//!   regions, and a 3-D cloud of section points;
//! - [`Grid`]: panels side by side (for example 4 tables × 4 values of α),
//!   with an optional shared [`Colorbar`].
//!
//! Around the plots, the plumbing the figure examples share, so that each
//! example only composes calls:
//! - [`cli`]: the one command-line parser ([`cli::FigureArgs`]: `--out`,
//!   `--quick`, `--paper`, `--seed`, `--threads` plus an example's own
//!   options; [`cli::SweepArgs`] for the `sweep` machine interface);
//! - [`run_figure`]: the `main` of a figure, with a [`Report`] that writes
//!   PNG, [`Csv`] and JSON files (serde, with a common [`Header`]);
//! - [`Plan`], [`Job`], [`run_jobs`], [`Curve`]: λ(α) sweeps sized per mode,
//!   run with rows on stdout and [`Progress`] on stderr, written with
//!   [`write_curves`]; [`run_scan`] for families of tables with their curved
//!   share;
//! - figures of one analysis each, with their CSV rows: [`EnergyPanels`]
//!   (energy conservation), [`section_panel`] (Poincaré sections),
//!   [`island_panel`] (FTLE maps with the bouncing-ball island),
//!   [`kac_histogram`] (return times against Kac's lemma),
//!   [`q_class_panel`] and [`q_conserved_panel`] (`ΔQ` between collisions),
//!   [`lcn_trace_panel`] (single-trajectory LCN traces),
//!   [`collision_rate_grid`] (ν and λ/ν against α) and
//!   [`spectrum_grid`] (the Lyapunov spectrum against α);
//! - [`measured`] and [`paper_markers`]: series of values ± SEM and of the
//!   paper's numbers ([`spinball_analysis::diagnostics`]); [`table_i_markdown`]
//!   and friends ([`table_i_rows`], [`table_i_grid`]) set our convergence
//!   table beside the paper's Table I.
//!
//! These live here, not in the library crates, because only figures need
//! them: the analysis crates never depend on plotting, argument parsing or
//! progress display.
//!
//! ```no_run
//! use spinball_geometry::{DVec2, Stadium};
//! use spinball_plot::{LinePlot, Plot, Series, TablePlot};
//!
//! let stadium = Stadium::new(1.0)?;
//! let path = vec![DVec2::new(0.0, 0.0), DVec2::new(1.5, 0.8), DVec2::new(-1.0, -1.0)];
//! TablePlot::new(&stadium)
//!     .title("stadium a = 1")
//!     .trajectory(path)
//!     .save_png("out/stadium.png", 1200, 700)?;
//!
//! LinePlot::new()
//!     .x_label("spin parameter α = I/(m r²)")
//!     .y_label("λ (1/time)")
//!     .series(Series::new("stadium", [(0.0, 0.43), (0.5, 0.18), (1.0, 0.15)]).errors([0.01, 0.01, 0.01]))
//!     .save_png("out/lambda.png", 1200, 800)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Conventions
//! - Sizes are in pixels. [`Style::for_size`] picks font sizes from the image
//!   size so that text is at least 16 px (titles ~30 px, axis labels ~26 px,
//!   ticks ~22 px at 1200 px width).
//! - Bad data never panics: non-finite points are skipped (and non-positive
//!   ones on a log axis), a line is broken where points are missing, and a
//!   plot with nothing left to draw is a [`PlotError::EmptyData`].
//! - Colours come from one colour-blind-safe [`palette`] (Okabe–Ito) and one
//!   sequential map ([`viridis`]), so figures look alike.
//!
//! # Font
//! Text is rendered with DejaVu Sans, bundled through the `dejavu` crate and
//! registered with plotters' pure-Rust `ab_glyph` renderer (see [`font`]); no
//! fontconfig, freetype or other system library is needed.
#![forbid(unsafe_code)]

mod colormap;
mod csv;
mod curves;
mod energy_figure;
mod error;
mod figure;
pub mod font;
mod format;
mod grid;
mod histogram;
mod island_figure;
mod kac_figure;
mod lcn_figure;
mod lines;
mod measured;
mod outline;
mod phase_plot;
mod plan;
mod plot;
mod progress;
mod q_figure;
mod rate_figure;
mod rates;
mod report;
mod result_plots;
mod result_tables;
mod scan;
mod section_figure;
mod style;
mod sweep_json;
mod table_i;
mod table_plot;
mod work_plots;

pub mod cli;

pub use colormap::{PALETTE, palette, viridis};
pub use csv::{Csv, optional};
pub use curves::{Curve, CurveSummary, Job, run_jobs, template, write_curves};
pub use energy_figure::{
    ENERGY_FLOOR, ENERGY_LONG_COLUMNS, ENERGY_TRACE_COLUMNS, EnergyPanels, energy_long_rows,
    energy_trace_rows,
};
pub use error::PlotError;
pub use figure::{BoxError, run_figure, run_figure_with};
pub use format::format_tick;
pub use grid::{Colorbar, Grid, Panel};
pub use histogram::{HistogramPlot, Marker};
pub use island_figure::{ISLAND_COLUMNS, island_panel, island_row};
pub use kac_figure::{
    KAC_COLUMNS, KAC_ORBIT_COLUMNS, kac_histogram, kac_orbit_rows, kac_ratio_series, kac_row,
};
pub use lcn_figure::{LCN_TRACE_COLUMNS, LcnFinal, lcn_finals, lcn_trace_panel, lcn_trace_rows};
pub use lines::{Legend, LineKind, LinePlot, Series};
pub use measured::{ALPHA_LABEL, LAMBDA_LABEL, measured, measured_band, paper_markers, scaled};
pub use outline::{ARC_POINTS_PER_TURN, Loop, Outline, ToOutline};
pub use phase_plot::{MapPlot, Scatter3d};
pub use plan::{Plan, unit_grid};
pub use plot::{Plot, render_png};
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
    trajectories_csv,
};
pub use scan::{Scan, ShareRow, curved_shares, run_scan, share_range, shares_csv, write_shares};
pub use section_figure::{SECTION_COLUMNS, section_cloud, section_panel, section_rows, shell_spin};
pub use style::Style;
pub use sweep_json::{SweepDocument, SweepPoint};
pub use table_i::{
    TableIColumn, TableIRecord, TableIRow, table_i_csv, table_i_grid, table_i_markdown,
    table_i_paper, table_i_plot, table_i_reference, table_i_rows,
};
pub use table_plot::TablePlot;
pub use work_plots::{
    WORK_COLUMNS, bias_vs_t, error_vs_time, method_label, sem_vs_n, time_to_target, work_rows,
};

pub use plotters;
pub use plotters::style::RGBColor;
pub use spinball_geometry::{DVec2, SegmentTable, Table};
