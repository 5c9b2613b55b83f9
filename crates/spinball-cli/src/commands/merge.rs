//! `spinball merge`: the shards of a run, combined into the result one
//! unsharded run gives, bitwise.

use std::path::PathBuf;

use clap::Args;
use spinball_analysis::merge_partials;

use crate::documents::PartialDocument;
use crate::error::CliError;
use crate::output::OutputArgs;

/// The arguments of `spinball merge`.
#[derive(Debug, Clone, Args)]
pub struct MergeArgs {
    /// The partial results (the --json files of every shard), in any order.
    #[arg(required = true)]
    pub parts: Vec<PathBuf>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// `spinball merge`.
///
/// # Errors
/// [`CliError::Usage`] for files that are not partial results of one run,
/// or whose ranges overlap or leave indices out.
pub fn merge(args: &MergeArgs) -> Result<(), CliError> {
    let docs = args
        .parts
        .iter()
        .map(|p| PartialDocument::read(p).map(|d| (p, d)))
        .collect::<Result<Vec<_>, _>>()?;
    let (first_path, first) = &docs[0];
    for (path, d) in &docs[1..] {
        if d.total != first.total || d.points.len() != first.points.len() {
            return Err(CliError::Usage(format!(
                "{} and {} are shards of different runs ({} point(s) over {:?} vs {} over {:?})",
                first_path.display(),
                path.display(),
                first.points.len(),
                first.total,
                d.points.len(),
                d.total
            )));
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
