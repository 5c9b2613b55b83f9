//! The one error type of the crate.

use std::path::PathBuf;

use spinball_plot::PlotError;
use thiserror::Error;

/// Why a figure's files could not be written.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum FigureError {
    /// A plot could not be drawn or saved.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// A directory or file could not be written.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The path.
        path: PathBuf,
        /// The underlying error.
        #[source]
        source: std::io::Error,
    },
    /// A JSON document could not be made (its body is not a struct or map,
    /// or a value fails to serialise).
    #[error("cannot write {path} as JSON: {source}")]
    Json {
        /// The path.
        path: PathBuf,
        /// The underlying error.
        #[source]
        source: serde_json::Error,
    },
    /// A parameter is out of range (an NPY shape that does not hold its
    /// values, ...).
    #[error("invalid {what}: {why}")]
    Invalid {
        /// Which parameter.
        what: &'static str,
        /// What is wrong with it.
        why: String,
    },
}
