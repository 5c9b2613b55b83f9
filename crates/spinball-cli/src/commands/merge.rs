//! `spinball merge`: the shards of a run, combined into the result one
//! unsharded run gives, bitwise.

use std::fmt::Display;
use std::path::{Path, PathBuf};

use clap::Args;
use spinball_analysis::run::{RunDifference, merge_partials};

use crate::commands::ftle_map::{FTLE_MAP_PARTIAL_KIND, merge_maps};
use crate::commands::spectrum::{SPECTRUM_PARTIAL_KIND, SpectrumDocument};
use crate::documents::{PARTIAL_KIND, PartialDocument};
use crate::error::CliError;
use crate::output::OutputArgs;
use crate::phase_args::PhaseOutput;

/// The arguments of `spinball merge`.
#[derive(Debug, Clone, Args)]
pub struct MergeArgs {
    /// The partial results (the --json files of every shard of a
    /// `lyapunov`, `ftle`, `spectrum` or `ftle-map` run), in any order.
    #[arg(required = true)]
    pub parts: Vec<PathBuf>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The `kind` of a result file.
fn kind(path: &Path) -> Result<String, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Usage(format!("cannot read {}: {e}", path.display())))?;
    let v: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| CliError::Usage(format!("{} is not JSON: {e}", path.display())))?;
    Ok(v["kind"].as_str().unwrap_or_default().to_string())
}

/// `spinball merge`.
///
/// # Errors
/// [`CliError::Usage`] for files that are not partial results of one run,
/// or whose ranges overlap or leave indices out.
pub fn merge(args: &MergeArgs) -> Result<(), CliError> {
    args.out.check()?;
    let first_kind = kind(&args.parts[0])?;
    if first_kind == FTLE_MAP_PARTIAL_KIND {
        let out = PhaseOutput {
            json: args.out.json.clone(),
            csv: args.out.csv.clone(),
            npy: args.out.npy.clone(),
            quiet: args.out.quiet,
        };
        return merge_maps(&args.parts, &out);
    }
    if first_kind == SPECTRUM_PARTIAL_KIND {
        let docs = args
            .parts
            .iter()
            .map(|p| {
                let text = std::fs::read_to_string(p).map_err(CliError::usage)?;
                serde_json::from_str::<SpectrumDocument>(&text).map_err(|e| {
                    CliError::Usage(format!(
                        "{} is not a valid spinball spectrum result: {e}",
                        p.display()
                    ))
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        for (path, d) in args.parts.iter().zip(&docs).skip(1) {
            d.same_run(&docs[0]).map_err(|why| {
                CliError::Usage(format!(
                    "{} and {} are not shards of one spectrum run: {why}",
                    args.parts[0].display(),
                    path.display()
                ))
            })?;
        }
        return SpectrumDocument::merge(docs)?.write_results(&args.out);
    }
    if first_kind != PARTIAL_KIND {
        return Err(CliError::Usage(format!(
            "{} is not a partial result (its kind is `{first_kind}`); merge the --json files of sharded runs",
            args.parts[0].display()
        )));
    }
    let docs = args
        .parts
        .iter()
        .map(|p| PartialDocument::read(p).map(|d| (p, d)))
        .collect::<Result<Vec<_>, _>>()?;
    let (first_path, first) = &docs[0];
    for (path, d) in &docs[1..] {
        let differ = |what: &str, a: &dyn Display, b: &dyn Display| {
            CliError::Usage(format!(
                "{} and {} are shards of different runs: {what} {a} in {}, {b} in {}; merge only the shards of one command",
                first_path.display(),
                path.display(),
                first_path.display(),
                path.display()
            ))
        };
        if d.total != first.total {
            return Err(differ(
                "initial conditions",
                &format_args!("{:?}", first.total),
                &format_args!("{:?}", d.total),
            ));
        }
        if d.points.len() != first.points.len() {
            return Err(differ(
                "number of α values",
                &first.points.len(),
                &d.points.len(),
            ));
        }
        for (a, b) in first.points.iter().zip(&d.points) {
            match a.provenance.difference(&b.provenance) {
                Ok(()) => {}
                Err(RunDifference::Field { what, first, other }) => {
                    return Err(differ(what, &first, &other));
                }
                Err(e) => {
                    return Err(CliError::Usage(format!(
                        "cannot merge {} and {}: {e}",
                        first_path.display(),
                        path.display()
                    )));
                }
            }
            if a.version != b.version {
                return Err(differ("version", &a.version, &b.version));
            }
        }
    }
    let estimates = (0..first.points.len())
        .map(|k| {
            let parts = docs.iter().map(|(_, d)| d.points[k].clone()).collect();
            merge_partials(parts, Some(first.total.clone()))
                .map_err(|e| CliError::Usage(format!("point {k}: {e}")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    args.out.write_results(&estimates)
}
