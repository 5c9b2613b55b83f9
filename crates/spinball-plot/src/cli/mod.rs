//! The command line of every example, read by one parser.
//!
//! - [`options`]: the reader — an option list as data ([`Opt`]), the
//!   options found ([`Matches`]), one error type ([`ArgError`]) and one way
//!   to fail ([`exit_on_error`]: message and usage on stderr, exit code 2);
//! - [`figure`]: the arguments the figure examples share ([`FigureArgs`]:
//!   `--out`, `--quick`, `--paper`, `--seed`, `--threads`) plus an example's
//!   own options;
//! - [`sweep`]: the `sweep` machine interface ([`SweepArgs`]).
//!
//! Command-line parsing lives here, in the figures crate, because only the
//! examples need it: the library crates take typed values.

pub mod figure;
pub mod options;
pub mod sweep;

pub use figure::{DEFAULT_SEED, FIGURE_OPTIONS, FigureArgs, Mode, usage, usage_with};
pub use options::{ArgError, Matches, Opt, Parsed, exit_on_error, parse_options, usage_text};
pub use sweep::{SWEEP_OPTIONS, SweepArgs, sweep_usage};
