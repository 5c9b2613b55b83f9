//! The `main` of a figure example: read the command line, run the body
//! with a [`Report`], print the closing line or the error.
//!
//! Every figure example starts and ends the same way — arguments (exit 2
//! on bad ones), a clock, files in `--out`, a line naming them, exit 1 with
//! `name: error` if anything fails — so an example is only its body.
//!
//! ```no_run
//! use std::process::ExitCode;
//! use spinball_figures::{Csv, run_figure};
//!
//! fn main() -> ExitCode {
//!     run_figure("fig_demo", "A demo figure.", |args, report| {
//!         let mut csv = Csv::new(&["seed"]);
//!         csv.row(&[&args.seed]);
//!         report.csv("demo.csv", &csv)?;
//!         Ok(())
//!     })
//! }
//! ```

use std::error::Error;
use std::process::ExitCode;

use clap::{Args, FromArgMatches};

use crate::args::FigureArgs;
use crate::report::Report;

/// The error of an example's body.
pub type BoxError = Box<dyn Error + Send + Sync>;

/// Run the figure example `name` (`about`: one line for `--help`): parse the
/// arguments (exit 2 on bad ones), call `body`, then print the report's
/// closing line (exit 0) or `name: error` on stderr (exit 1).
pub fn run_figure<F>(name: &str, about: &str, body: F) -> ExitCode
where
    F: FnOnce(&FigureArgs, &mut Report) -> Result<(), BoxError>,
{
    let args = FigureArgs::parse_or_exit(name, about);
    run_body(name, &args, |report| body(&args, report))
}

/// [`run_figure`] for an example with options of its own: `E`, a
/// `#[derive(clap::Args)]` struct read beside the shared options and handed
/// to `body`.
pub fn run_figure_with<E, F>(name: &str, about: &str, body: F) -> ExitCode
where
    E: Args + FromArgMatches,
    F: FnOnce(&FigureArgs, &E, &mut Report) -> Result<(), BoxError>,
{
    let (args, own) = FigureArgs::parse_or_exit_with::<E>(name, about);
    run_body(name, &args, |report| body(&args, &own, report))
}

/// Run `body` with a fresh report and turn its result into the exit code.
fn run_body(
    name: &str,
    args: &FigureArgs,
    body: impl FnOnce(&mut Report) -> Result<(), BoxError>,
) -> ExitCode {
    let mut report = Report::new(name, args);
    let result = body(&mut report);
    finish(name, &report, result)
}

/// The exit code of a finished body (the closing line or the error printed).
fn finish(name: &str, report: &Report, result: Result<(), BoxError>) -> ExitCode {
    match result {
        Ok(()) => {
            if !report.files().is_empty() {
                report.finish();
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{name}: {e}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_exit_with_failure() {
        let args = FigureArgs::try_parse_from("fig_x", "", ["--out", "/nonexistent/x"]).unwrap();
        let report = Report::new("fig_x", &args);
        assert_eq!(finish("fig_x", &report, Ok(())), ExitCode::SUCCESS);
        assert_eq!(
            finish("fig_x", &report, Err("boom".into())),
            ExitCode::FAILURE
        );
    }
}
