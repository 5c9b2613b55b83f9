//! Where results go: JSON (a `spinball.lyapunov` document, with full
//! provenance), CSV (one `SweepRow` per α) and NPY (per-initial-condition exponents, for `numpy.load`).

use std::fs;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use clap::Args;
use npyz::WriterBuilder;
use spinball_analysis::estimators::PlusMinus;
use spinball_analysis::report::{Document, LyapunovDocument, csv_string};
use spinball_analysis::run::LyapunovEstimate;

use crate::documents::write_document;
use crate::error::CliError;
use crate::files::check_outputs;
use crate::stdout::print;

/// Output options.
#[derive(Debug, Clone, Args)]
pub struct OutputArgs {
    /// Write the result as JSON (every statistic, the provenance and the
    /// per-initial-condition values). A sharded run writes its partial
    /// result here. It is replaced atomically (through a temporary file),
    /// so it must be a regular file, a link to one, or a new path.
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write one CSV row per α.
    #[arg(long)]
    pub csv: Option<PathBuf>,
    /// Write the per-initial-condition exponents as an NPY array of shape
    /// (number of α, ICs), float64.
    #[arg(long)]
    pub npy: Option<PathBuf>,
    /// No progress bar and no table on stdout.
    #[arg(long, short)]
    pub quiet: bool,
}

/// Write `values` (row-major, `shape`) as a float64 NPY file.
///
/// # Errors
/// [`CliError::Failed`] if it cannot be written.
pub fn write_npy(path: &Path, shape: &[u64], values: &[f64]) -> Result<(), CliError> {
    let fail =
        |e: std::io::Error| CliError::Failed(format!("cannot write {}: {e}", path.display()));
    let file = fs::File::create(path).map_err(fail)?;
    let mut w = npyz::WriteOptions::new()
        .default_dtype()
        .shape(shape)
        .writer(BufWriter::new(file))
        .begin_nd()
        .map_err(fail)?;
    w.extend(values.iter().copied()).map_err(fail)?;
    w.finish().map_err(fail)
}

/// Write text to `path`.
///
/// # Errors
/// [`CliError::Failed`] if it cannot be written.
pub fn write_text(path: &Path, text: &str) -> Result<(), CliError> {
    fs::write(path, text)
        .map_err(|e| CliError::Failed(format!("cannot write {}: {e}", path.display())))
}

impl OutputArgs {
    /// Check, before a run, that every output can be written: `--json` can
    /// be replaced (it is written through a temporary file renamed over
    /// it), and `--csv` and `--npy` exist or can be made in their
    /// directory.
    ///
    /// # Errors
    /// [`CliError::Usage`] naming the flag and what is wrong.
    pub fn check(&self) -> Result<(), CliError> {
        check_outputs(
            self.json.as_deref(),
            &[("csv", self.csv.as_deref()), ("npy", self.npy.as_deref())],
        )
    }

    /// Write finished estimates to every output asked for, and print a
    /// table on stdout unless quiet.
    ///
    /// # Errors
    /// [`CliError::Failed`] for an output that cannot be written (stdout
    /// included); [`CliError::StdoutClosed`] if stdout's reader went away
    /// (the files are written all the same).
    pub fn write_results(&self, estimates: &[LyapunovEstimate]) -> Result<(), CliError> {
        let shown = self.show(estimates);
        // The files are written even if stdout failed (full, or closed by
        // `| head`): they are the result.
        self.write_files(estimates)?;
        shown
    }

    /// Print the table of `estimates` on stdout unless quiet.
    ///
    /// # Errors
    /// [`CliError::Failed`] if stdout cannot take it,
    /// [`CliError::StdoutClosed`] if its reader went away.
    pub fn show(&self, estimates: &[LyapunovEstimate]) -> Result<(), CliError> {
        if self.quiet {
            Ok(())
        } else {
            // λ with the digits its SEM shows; the median to λ's decimals.
            let mut table = format!(
                "{:>10} {:>24} {:>12} {:>7} {:>8} {:>9}\n",
                "alpha", "lambda ± SEM", "median", "f_ch", "ICs", "time/s"
            );
            for e in estimates {
                let lambda = PlusMinus::new(e.mean(), e.sem());
                let d = lambda.decimals().unwrap_or(6);
                table.push_str(&format!(
                    "{:>10} {:>24} {:>12.d$} {:>7.3} {:>8} {:>9.2}\n",
                    e.alpha(),
                    lambda.to_string(),
                    e.median(),
                    e.chaotic_fraction(),
                    e.n_ics(),
                    e.wall_time_s()
                ));
            }
            print(&table)
        }
    }

    /// Write `estimates` to the files asked for (`--json`, `--csv`,
    /// `--npy`).
    ///
    /// # Errors
    /// [`CliError::Failed`] for a file that cannot be written.
    pub fn write_files(&self, estimates: &[LyapunovEstimate]) -> Result<(), CliError> {
        if let Some(path) = &self.json {
            write_document(
                path,
                &Document::Lyapunov(LyapunovDocument::new(estimates.to_vec())),
                false,
            )?;
        }
        if let Some(path) = &self.csv {
            write_text(path, &csv_string(estimates).map_err(CliError::failed)?)?;
        }
        if let Some(path) = &self.npy {
            let n = estimates.first().map_or(0, |e| e.trajectories().len());
            if estimates.iter().any(|e| e.trajectories().len() != n) {
                return Err(CliError::Failed(
                    "--npy needs the same number of initial conditions at every α".into(),
                ));
            }
            let values: Vec<f64> = estimates
                .iter()
                .flat_map(|e| e.trajectories().iter().map(|t| t.exponent))
                .collect();
            write_npy(path, &[estimates.len() as u64, n as u64], &values)?;
        }
        Ok(())
    }
}
