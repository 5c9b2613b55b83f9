//! The `main` of a figure example: read the command line, run the body
//! with a [`Report`], print the closing line or the error.
//!
//! Every figure example starts and ends the same way — arguments (exit 2
//! on bad ones), a clock, files in `--out`, a line naming them, exit 1 with
//! `name: error` if anything fails — so an example is only its body.
//!
//! ```no_run
//! use std::process::ExitCode;
//! use spinball_plot::{Csv, run_figure};
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

use crate::cli::{ArgError, FigureArgs, Opt, usage_with};
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
    run_figure_with(name, about, &[], body)
}

/// [`run_figure`] for an example with options of its own (`extra`, read
/// into [`FigureArgs::extra`]). A body that fails on reading one of them
/// (an [`ArgError`], e.g. from [`Matches::get`](crate::cli::Matches::get))
/// exits like a bad argument: message, usage, exit code 2.
pub fn run_figure_with<F>(name: &str, about: &str, extra: &[Opt], body: F) -> ExitCode
where
    F: FnOnce(&FigureArgs, &mut Report) -> Result<(), BoxError>,
{
    let args = FigureArgs::parse_or_exit_with(name, about, extra);
    let mut report = Report::new(name, &args);
    let result = body(&args, &mut report);
    finish(name, &usage_with(name, about, extra), &report, result)
}

/// The exit code of a finished body (the closing line or the error printed).
fn finish(name: &str, usage: &str, report: &Report, result: Result<(), BoxError>) -> ExitCode {
    match result {
        Ok(()) => {
            if !report.files().is_empty() {
                report.finish();
            }
            ExitCode::SUCCESS
        }
        Err(e) if e.downcast_ref::<ArgError>().is_some() => {
            eprintln!("{name}: {e}\n\n{usage}");
            ExitCode::from(2)
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
    use crate::cli::Parsed;

    #[test]
    fn errors_exit_with_failure() {
        let Parsed::Run(args) =
            FigureArgs::try_parse_from("fig_x", ["--out", "/nonexistent/x"]).unwrap()
        else {
            panic!("help")
        };
        let report = Report::new("fig_x", &args);
        assert_eq!(finish("fig_x", "", &report, Ok(())), ExitCode::SUCCESS);
        assert_eq!(
            finish("fig_x", "", &report, Err("boom".into())),
            ExitCode::FAILURE
        );
        let bad = ArgError::invalid("alpha", "x", "not a number");
        assert_eq!(
            finish("fig_x", "", &report, Err(bad.into())),
            ExitCode::from(2)
        );
    }
}
