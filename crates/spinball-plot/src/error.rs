//! The one error type of the crate.

use std::path::PathBuf;

use thiserror::Error;

/// Why a plot could not be drawn or written.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum PlotError {
    /// Nothing finite is left to draw (after skipping NaN and infinite values,
    /// and non-positive values on a log axis).
    #[error("nothing to draw: {0} has no finite data")]
    EmptyData(String),
    /// Two inputs that go together have different lengths (error bars and
    /// points, band limits and points).
    #[error("{what}: {got} values given for {expected} points")]
    LengthMismatch {
        /// Which input.
        what: String,
        /// How many points there are.
        expected: usize,
        /// How many values were given.
        got: usize,
    },
    /// A parameter is out of range (a histogram with zero bins, an empty
    /// range, a file name that is not `.png`, ...).
    #[error("invalid {what}: {why}")]
    Invalid {
        /// Which parameter.
        what: &'static str,
        /// What is wrong with it.
        why: String,
    },
    /// The image or a panel of it is too small to hold the plot.
    #[error("{what} of {width}×{height} px is too small")]
    TooSmall {
        /// Image, panel or plotting area.
        what: &'static str,
        /// Width in pixels.
        width: u32,
        /// Height in pixels.
        height: u32,
    },
    /// A grid was given more panels than it has cells.
    #[error("a {rows}×{cols} grid has no room for {panels} panels")]
    GridFull {
        /// Rows.
        rows: usize,
        /// Columns.
        cols: usize,
        /// Panels given.
        panels: usize,
    },
    /// The bundled font could not be registered (never expected).
    #[error("the bundled DejaVu Sans font could not be loaded")]
    Font,
    /// A directory or file could not be written.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The path.
        path: PathBuf,
        /// The underlying error.
        #[source]
        source: std::io::Error,
    },
    /// An MP4 was asked for but `ffmpeg` is not on `PATH`.
    #[error(
        "writing an MP4 needs ffmpeg, which is not on PATH: install ffmpeg (for example `apt-get install ffmpeg`), or write a .gif"
    )]
    FfmpegMissing,
    /// A film could not be encoded (the GIF encoder or `ffmpeg` failed).
    #[error("cannot encode {path}: {why}")]
    Encoding {
        /// The film being written.
        path: PathBuf,
        /// What the encoder said.
        why: String,
    },
    /// The drawing backend failed (includes PNG encoding errors).
    #[error("drawing failed: {0}")]
    Drawing(String),
}

impl<E: std::error::Error + Send + Sync> From<plotters::drawing::DrawingAreaErrorKind<E>>
    for PlotError
{
    fn from(e: plotters::drawing::DrawingAreaErrorKind<E>) -> Self {
        PlotError::Drawing(e.to_string())
    }
}
