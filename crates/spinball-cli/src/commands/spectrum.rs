//! `spinball spectrum`: the full Lyapunov spectrum (five exponents) of an
//! ensemble, at one α or a list, whole or one shard at a time.

use std::ops::Range;

use clap::Args;
use serde::{Deserialize, Serialize};
use spinball_analysis::AnalysisError;
use spinball_analysis::estimators::SpectrumOptions;
use spinball_analysis::run::{Shard, SpectrumEstimate, TableRecord, spectrum_ensemble};
use spinball_core::Billiard;

use crate::documents::write_json;
use crate::error::CliError;
use crate::output::{OutputArgs, write_npy, write_text};
use crate::run_args::RunArgs;
use crate::stdout::print;

/// The `kind` of a finished spectrum result.
pub const SPECTRUM_KIND: &str = "spinball.spectrum";
/// The `kind` of a shard's spectrum result.
pub const SPECTRUM_PARTIAL_KIND: &str = "spinball.spectrum.partial";

/// The arguments of `spinball spectrum`.
#[derive(Debug, Clone, Args)]
pub struct SpectrumArgs {
    #[command(flatten)]
    pub run: RunArgs,
    /// Re-orthonormalise the tangent vectors every this many collisions.
    #[arg(long, default_value_t = 1)]
    pub qr_interval: u32,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The JSON of `spinball spectrum`: one estimate per α, of the whole run
/// or (partial) of one shard.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpectrumDocument {
    /// [`SPECTRUM_KIND`] or [`SPECTRUM_PARTIAL_KIND`].
    pub kind: String,
    /// The table.
    pub table: TableRecord,
    /// The α of each point.
    pub alphas: Vec<f64>,
    /// The shard, for a partial result.
    pub shard: Option<Shard>,
    /// The initial conditions of the whole run.
    pub total: Range<u64>,
    /// One estimate per α.
    pub points: Vec<SpectrumEstimate>,
}

impl SpectrumDocument {
    /// Write the finished spectra to every output asked for, and print
    /// them unless quiet.
    ///
    /// # Errors
    /// [`CliError::Failed`] for an output that cannot be written.
    pub fn write_results(&self, out: &OutputArgs) -> Result<(), CliError> {
        let shown = if out.quiet {
            Ok(())
        } else {
            let mut table = format!(
                "{:>10}  {:>11} {:>11} {:>11} {:>11} {:>11}\n",
                "alpha", "l1", "l2", "l3", "l4", "l5"
            );
            for (a, p) in self.alphas.iter().zip(&self.points) {
                let m = p.mean;
                table.push_str(&format!(
                    "{a:>10}  {:>11.6} {:>11.6} {:>11.6} {:>11.6} {:>11.6}\n",
                    m[0], m[1], m[2], m[3], m[4]
                ));
            }
            print(&table)
        };
        // The files are written even if stdout failed: they are the result.
        if let Some(path) = &out.json {
            write_json(path, self)?;
        }
        if let Some(path) = &out.csv {
            let mut csv = String::from("alpha,l1,l2,l3,l4,l5,sem1,sem2,sem3,sem4,sem5,n_ics\n");
            for (a, p) in self.alphas.iter().zip(&self.points) {
                let v: Vec<String> = p.mean.iter().chain(&p.sem).map(f64::to_string).collect();
                csv.push_str(&format!("{a},{},{}\n", v.join(","), p.n_ics));
            }
            write_text(path, &csv)?;
        }
        if let Some(path) = &out.npy {
            let n = self.points.first().map_or(0, |p| p.spectra.len()) as u64;
            let values: Vec<f64> = self
                .points
                .iter()
                .flat_map(|p| p.spectra.iter().flat_map(|s| s.exponents))
                .collect();
            write_npy(path, &[self.points.len() as u64, n, 5], &values)?;
        }
        shown
    }

    /// Whether `self` is a shard of the same run as `first`.
    ///
    /// # Errors
    /// What differs, first field first (`kind`, table by its geometry,
    /// α, initial conditions, number of points).
    pub fn same_run(&self, first: &SpectrumDocument) -> Result<(), String> {
        if self.kind != SPECTRUM_PARTIAL_KIND {
            return Err(format!(
                "its kind is `{}`, not `{SPECTRUM_PARTIAL_KIND}`",
                self.kind
            ));
        }
        first
            .table
            .same_table(&self.table)
            .map_err(|e| e.to_string())?;
        if self
            .alphas
            .iter()
            .map(|a| a.to_bits())
            .ne(first.alphas.iter().map(|a| a.to_bits()))
        {
            return Err(format!(
                "alpha {:?} in one, {:?} in the other",
                first.alphas, self.alphas
            ));
        }
        if self.total != first.total {
            return Err(format!(
                "initial conditions {:?} in one, {:?} in the other",
                first.total, self.total
            ));
        }
        if self.points.len() != first.points.len() {
            return Err(format!(
                "{} point(s) in one, {} in the other",
                first.points.len(),
                self.points.len()
            ));
        }
        Ok(())
    }

    /// Join the shards of one spectrum run into the whole result
    /// (bitwise that of one unsharded run, bar the wall times).
    ///
    /// # Errors
    /// [`CliError::Usage`] for shards of different runs, overlapping or
    /// missing indices.
    pub fn merge(mut parts: Vec<SpectrumDocument>) -> Result<SpectrumDocument, CliError> {
        let first = parts[0].clone();
        for p in &parts {
            p.same_run(&first).map_err(|why| {
                CliError::Usage(format!(
                    "the spectrum results are not shards of one run: {why}"
                ))
            })?;
        }
        parts.sort_by_key(|p| p.points.first().map_or(0, |e| e.first_index));
        let points = (0..first.points.len())
            .map(|k| {
                let mut pieces = parts.iter().map(|p| &p.points[k]);
                let head = pieces.next().expect("at least one part");
                if head.first_index != first.total.start {
                    return Err(CliError::Usage(format!(
                        "initial conditions {:?} are missing",
                        first.total.start..head.first_index
                    )));
                }
                let joined = pieces.try_fold(head.clone(), |acc, e| {
                    let end = acc.first_index + acc.n_ics;
                    if e.first_index > end {
                        return Err(CliError::Usage(format!(
                            "initial conditions {:?} are missing",
                            end..e.first_index
                        )));
                    }
                    if e.first_index < end {
                        return Err(CliError::Usage(format!(
                            "initial conditions from {} overlap: each index must come from one shard",
                            e.first_index
                        )));
                    }
                    acc.merge(e).map_err(CliError::usage)
                })?;
                let end = joined.first_index + joined.n_ics;
                if end < first.total.end {
                    return Err(CliError::Usage(format!(
                        "initial conditions {:?} are missing",
                        end..first.total.end
                    )));
                }
                Ok(joined)
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(SpectrumDocument {
            kind: SPECTRUM_KIND.into(),
            shard: None,
            points,
            ..first
        })
    }
}

/// `spinball spectrum`.
///
/// # Errors
/// [`CliError::Usage`] for bad options; [`CliError::Failed`] for a failed
/// trajectory.
pub fn spectrum(args: &SpectrumArgs) -> Result<(), CliError> {
    let run = &args.run;
    let ensembles = run.ensembles()?;
    let sharded = run.shard().count > 1;
    if sharded && args.out.json.is_none() {
        return Err(CliError::Usage(
            "--shard needs --json: the partial result goes there for `spinball merge`".into(),
        ));
    }
    args.out.check()?;
    let mut options = SpectrumOptions::new(run.collisions, run.method());
    options.qr_interval = args.qr_interval;
    let mut points = Vec::new();
    for e in &ensembles {
        let billiard = Billiard::new(e.table.clone(), e.law);
        let sampler = e.sampler().unwrap_or_default();
        let est = spectrum_ensemble(
            &billiard,
            sampler,
            e.seed,
            e.indices.clone(),
            &options,
            e.threads,
        )
        .map_err(|err| match err {
            AnalysisError::InvalidOption { .. } if sharded => CliError::Usage(format!(
                "{err} (every spectrum shard needs at least 2 initial conditions: use fewer shards)"
            )),
            AnalysisError::InvalidOption { .. } => CliError::usage(err),
            err => CliError::failed(err),
        })?;
        points.push(est);
    }
    let doc = SpectrumDocument {
        kind: if sharded {
            SPECTRUM_PARTIAL_KIND
        } else {
            SPECTRUM_KIND
        }
        .into(),
        table: TableRecord::of(&ensembles[0].table),
        alphas: ensembles.iter().map(|e| e.alpha()).collect(),
        shard: run.shard,
        total: 0..run.ics,
        points,
    };
    if sharded {
        let path = args.out.json.as_ref().expect("checked above");
        write_json(path, &doc)?;
        if !args.out.quiet {
            print(&format!(
                "shard {}: wrote {} (combine the shards with `spinball merge`)\n",
                run.shard(),
                path.display()
            ))?;
        }
        return Ok(());
    }
    doc.write_results(&args.out)
}
