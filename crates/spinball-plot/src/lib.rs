//! Plots for [spinball](https://docs.rs/spinball): the pictures a physicist
//! puts in a talk, drawn to PNG with a bundled font and no system libraries.
//!
//! The crate is small on purpose. It draws these things, each a [`Plot`]
//! (but the film, which has its own `save`):
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
//! - [`Animation`]: balls moving on a table, each with a rotating spin
//!   marker, written as an animated GIF (or an MP4 where `ffmpeg` is
//!   installed);
//! - [`Grid`]: panels side by side (for example 4 tables × 4 values of α),
//!   with an optional shared [`Colorbar`].
//!
//! That is all it does: it draws arrays and tables it is given. It parses
//! no arguments, writes no CSV or JSON documents and runs no estimates;
//! the paper's figures, their command line and the files they write live in
//! the unpublished `spinball-figures` crate beside the examples, and
//! [`spinball_geometry`] is its only spinball dependency (for table outlines).
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

mod animation;
mod colormap;
mod error;
mod error_bar;
mod fixed_palette;
pub mod font;
mod format;
mod gif_writer;
mod grid;
mod histogram;
mod lines;
mod mp4_writer;
mod phase_plot;
mod plot;
mod style;
mod table_plot;
mod x_band;

pub use animation::{Animation, DEFAULT_FILM_SIZE, FilmFormat, MAX_GIF_FPS};
pub use colormap::{PALETTE, palette, value_range, viridis};
pub use error::PlotError;
pub use error_bar::{CAP_OVERHANG, ErrorBarPixels, bar_shade};
pub use format::{format_tick, format_tick_on, snap_tick, two_digits};
pub use grid::{Colorbar, Grid, Panel};
pub use histogram::{HistogramPlot, Marker};
pub use lines::{Legend, LineKind, LinePlot, Series};
pub use mp4_writer::FFMPEG;
pub use phase_plot::{MapPlot, Scatter3d};
pub use plot::{Plot, render_png};
pub use style::Style;
pub use table_plot::TablePlot;
pub use x_band::XBand;

pub use plotters;
pub use plotters::style::RGBColor;
pub use spinball_geometry::{
    ARC_POINTS_PER_TURN, DVec2, Loop, Outline, SegmentTable, Table, ToOutline,
};
