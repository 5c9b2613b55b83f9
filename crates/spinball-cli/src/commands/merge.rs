//! `spinball merge`: the shards of a run, combined into the result one
//! unsharded run gives, bitwise. The comparison and the joining are the
//! library's (`PartialDocument::merge`, `SpectrumDocument::merge`,
//! `FtleMapPart::merge`, `SectionPartialDocument::merge`,
//! `KacPartialDocument::merge`, `EscapePartialDocument::merge`,
//! `DiffusionPartialDocument::merge`); this
//! command reads the files and names them in every refusal.

use std::path::{Path, PathBuf};

use clap::Args;
use spinball_analysis::report::{
    DiffusionPartialDocument, Document, EscapePartialDocument, KacPartialDocument,
    MultilevelPartialDocument, PartialDocument, SectionPartialDocument, SpectrumDocument,
};
use spinball_analysis::run::MergeError;

use crate::commands::diffuse::write_diffusion;
use crate::commands::escape::write_escape;
use crate::commands::ftle_map::merge_maps;
use crate::commands::kac::write_kac;
use crate::commands::section::write_section;
use crate::commands::spectrum::write_spectrum;
use crate::documents::read_document;
use crate::error::CliError;
use crate::estimator_args::write_multilevel;
use crate::output::OutputArgs;
use crate::stdout::print;

/// The arguments of `spinball merge`.
#[derive(Debug, Clone, Args)]
pub struct MergeArgs {
    /// The partial results (the --json files of every shard of a
    /// `lyapunov`, `ftle`, `spectrum`, `ftle-map`, `section`, `kac`,
    /// `escape` or `diffuse` run,
    /// or of a multilevel campaign), in any order.
    #[arg(required = true)]
    pub parts: Vec<PathBuf>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The refusal of `path` against the first file `first`: a field that
/// differs is named with its value in each file.
fn different(first: &Path, path: &Path, e: MergeError) -> CliError {
    match e {
        MergeError::DifferentRuns {
            what,
            first: a,
            other: b,
        } => CliError::Usage(format!(
            "{} and {} are shards of different runs: {what} {a} in {}, {b} in {}; merge only the shards of one command",
            first.display(),
            path.display(),
            first.display(),
            path.display()
        )),
        e => CliError::Usage(format!(
            "cannot merge {} and {}: {e}",
            first.display(),
            path.display()
        )),
    }
}

/// The shards of one kind: `first` (read from the first file) and those of
/// the other files, each of which must be of `first`'s kind (`pick`).
///
/// # Errors
/// [`CliError::Usage`] naming a file that cannot be read or is of another
/// kind.
fn gather<T>(
    args: &MergeArgs,
    first: T,
    pick: impl Fn(Document) -> Result<T, &'static str>,
) -> Result<Vec<T>, CliError> {
    let mut parts = vec![first];
    for path in &args.parts[1..] {
        let part = pick(read_document(path)?).map_err(|kind| {
            CliError::Usage(format!(
                "{} is a `{kind}`, not a shard like {}",
                path.display(),
                args.parts[0].display()
            ))
        })?;
        parts.push(part);
    }
    Ok(parts)
}

/// A refused merge of the files of `args`, with the library's reason.
fn refused(args: &MergeArgs, e: &MergeError) -> CliError {
    let files: Vec<String> = args.parts.iter().map(|p| p.display().to_string()).collect();
    CliError::Usage(format!("cannot merge {}: {e}", files.join(", ")))
}

/// `spinball merge`.
///
/// # Errors
/// [`CliError::Usage`] for files that are not partial results of one run,
/// or whose ranges overlap or leave indices out.
pub fn merge(args: &MergeArgs) -> Result<(), CliError> {
    args.out.check()?;
    let first_path = &args.parts[0];
    match read_document(first_path)? {
        Document::LyapunovPartial(first) => {
            let mut docs = vec![first];
            for path in &args.parts[1..] {
                let doc = read_document(path)?.into_partial().map_err(|e| {
                    CliError::Usage(format!(
                        "{} is {e}, like {}",
                        path.display(),
                        first_path.display()
                    ))
                })?;
                docs[0]
                    .same_run(&doc)
                    .map_err(|e| different(first_path, path, e))?;
                docs.push(doc);
            }
            let merged = PartialDocument::merge(&docs).map_err(CliError::usage)?;
            args.out.write_results(&merged.points)
        }
        Document::SpectrumPartial(first) => {
            let mut docs = vec![first];
            for path in &args.parts[1..] {
                let doc = match read_document(path)? {
                    Document::SpectrumPartial(d) => d,
                    other => {
                        return Err(CliError::Usage(format!(
                            "{} is a `{}`, not a shard of a spectrum run like {}",
                            path.display(),
                            other.kind(),
                            first_path.display()
                        )));
                    }
                };
                docs[0]
                    .same_run(&doc)
                    .map_err(|e| different(first_path, path, e))?;
                docs.push(doc);
            }
            let merged = SpectrumDocument::merge(&docs).map_err(CliError::usage)?;
            write_spectrum(&merged, &args.out)
        }
        Document::MultilevelPartial(first) => {
            if args.out.csv.is_some() || args.out.npy.is_some() {
                return Err(CliError::Usage(
                    "multilevel shards merge into --json only (their levels have different numbers of initial conditions)".into(),
                ));
            }
            let docs = gather(args, first, |d| match d {
                Document::MultilevelPartial(p) => Ok(p),
                other => Err(other.kind()),
            })?;
            let merged = MultilevelPartialDocument::merge(&docs).map_err(CliError::usage)?;
            if !args.out.quiet {
                for p in &merged.points {
                    print(&format!("alpha = {}\n{}\n", p.alpha, p.estimate))?;
                }
            }
            match &args.out.json {
                Some(path) => write_multilevel(path, &merged.points),
                None => Ok(()),
            }
        }
        Document::FtleMapPartial(first) => merge_maps(first.part, &args.parts[1..], &args.out),
        Document::SectionPartial(first) => {
            let parts = gather(args, first, |d| match d {
                Document::SectionPartial(p) => Ok(p),
                other => Err(other.kind()),
            })?;
            let doc = SectionPartialDocument::merge(parts).map_err(|e| refused(args, &e))?;
            write_section(&doc, &args.out)
        }
        Document::KacPartial(first) => {
            let parts = gather(args, first, |d| match d {
                Document::KacPartial(p) => Ok(p),
                other => Err(other.kind()),
            })?;
            let doc = KacPartialDocument::merge(parts).map_err(|e| refused(args, &e))?;
            write_kac(&doc, &args.out)
        }
        Document::EscapePartial(first) => {
            let parts = gather(args, first, |d| match d {
                Document::EscapePartial(p) => Ok(p),
                other => Err(other.kind()),
            })?;
            let doc = EscapePartialDocument::merge(parts).map_err(|e| refused(args, &e))?;
            write_escape(&doc, &args.out)
        }
        Document::DiffusionPartial(first) => {
            let parts = gather(args, first, |d| match d {
                Document::DiffusionPartial(p) => Ok(p),
                other => Err(other.kind()),
            })?;
            let doc = DiffusionPartialDocument::merge(parts).map_err(|e| refused(args, &e))?;
            write_diffusion(&doc, &args.out)
        }
        other => Err(CliError::Usage(format!(
            "{} is not a partial result (its kind is `{}`); merge the --json files of sharded runs",
            first_path.display(),
            other.kind()
        ))),
    }
}
