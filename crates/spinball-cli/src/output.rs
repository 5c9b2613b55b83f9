//! Where results go, for every command that computes one: JSON (a
//! document of the one result schema, with full provenance), CSV and NPY
//! (for `numpy.load`), checked before the run; for the ensemble commands
//! CSV is one `SweepRow` per α and NPY the per-initial-condition exponents.

use std::fs;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use clap::Args;
use npyz::WriterBuilder;
use spinball_analysis::estimators::PlusMinus;
use spinball_analysis::report::{Document, LyapunovDocument, csv_string};
use spinball_analysis::run::{LyapunovEstimate, Shard};

use crate::documents::write_document;
use crate::error::CliError;
use crate::files::check_outputs;
use crate::stdout::print;

/// Output options, the same for every command that computes a result.
#[derive(Debug, Clone, Args)]
pub struct OutputArgs {
    /// Write the result as a JSON document (`schema`, `kind`, the table as
    /// data, every parameter and every value). A sharded run writes its
    /// partial result here. It is replaced atomically (through a temporary
    /// file), so it must be a regular file, a link to one, or a new path.
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write the values as CSV: one row per α for `lyapunov`, `ftle` and
    /// `spectrum`; the columns of the other commands are in their help.
    #[arg(long)]
    pub csv: Option<PathBuf>,
    /// Write the values as a float64 NPY array: per-initial-condition
    /// exponents of shape (number of α, ICs) for `lyapunov` and `ftle`;
    /// the shapes of the other commands are in their help.
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

    /// The path a shard's partial result goes to: `--json`, which a
    /// sharded run needs (`None` for a whole run).
    ///
    /// # Errors
    /// [`CliError::Usage`] for a shard without `--json`.
    pub fn shard_path(&self, shard: Shard) -> Result<Option<&Path>, CliError> {
        if shard.count <= 1 {
            return Ok(None);
        }
        match &self.json {
            Some(path) => Ok(Some(path)),
            None => Err(CliError::Usage(
                "--shard needs --json: the partial result goes there for `spinball merge`".into(),
            )),
        }
    }

    /// Write the outputs asked for: `doc()` to `--json`, `csv()` to `--csv`,
    /// `npy()` (shape, row-major values) to `--npy`; each is made only if
    /// asked for.
    ///
    /// # Errors
    /// [`CliError::Failed`] for a file that cannot be written.
    pub fn write(
        &self,
        doc: impl FnOnce() -> Document,
        csv: impl FnOnce() -> String,
        npy: impl FnOnce() -> (Vec<u64>, Vec<f64>),
    ) -> Result<(), CliError> {
        if let Some(path) = &self.json {
            write_document(path, &doc(), false)?;
        }
        if let Some(path) = &self.csv {
            write_text(path, &csv())?;
        }
        if let Some(path) = &self.npy {
            let (shape, values) = npy();
            write_npy(path, &shape, &values)?;
        }
        Ok(())
    }

    /// Write a shard's partial result `doc` to `path` (its `--json`) and,
    /// unless quiet, say which block (`done`, e.g. `orbits 0..4 of 8`) it
    /// holds.
    ///
    /// # Errors
    /// [`CliError::Failed`] if the file or stdout cannot be written.
    pub fn write_shard(
        &self,
        path: &Path,
        doc: &Document,
        shard: Shard,
        done: &str,
    ) -> Result<(), CliError> {
        write_document(path, doc, false)?;
        if self.quiet {
            return Ok(());
        }
        print(&format!(
            "shard {shard}: {done} done; wrote {} (combine the shards with `spinball merge`)\n",
            path.display()
        ))
    }

    /// Whether any file is asked for.
    pub fn any_file(&self) -> bool {
        self.json.is_some() || self.csv.is_some() || self.npy.is_some()
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
