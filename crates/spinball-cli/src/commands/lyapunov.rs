//! `spinball lyapunov`: λ at one α or a list, over the whole ensemble or
//! one shard, with checkpoints and resumption.

use std::fmt::Display;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use clap::Args;
use spinball_analysis::precision::LevelShard;
use spinball_analysis::report::{MultilevelPoint, PartialDocument};
use spinball_analysis::run::{
    Ensemble, LyapunovEstimate, PartialRun, RunDifference, Shard, TrajectoryStats,
};
use spinball_geometry::Built;

use crate::documents::{read_partial, write_partial};
use crate::error::CliError;
use crate::estimator_args::{
    EstimatorArgs, read_allocation, run_allocation_shard, run_multilevel, write_multilevel,
    write_multilevel_partial,
};
use crate::files::{check_writable, remove_regular};
use crate::output::OutputArgs;
use crate::pictures::{check_whole_png, lyapunov_png};
use crate::run_args::RunArgs;
use crate::stdout::print;
use crate::watch::{
    TimeLimit, Watch, deadline, parse_checkpoint_every, parse_time_limit, progress_bar, stop_flag,
};

/// Checkpoint and resumption options.
#[derive(Debug, Clone, Args)]
pub struct CheckpointArgs {
    /// Where finished trajectories are saved while the run goes (default:
    /// the --json path with `.partial` appended); a regular file, a link to
    /// one or a new path (it is replaced through a temporary file, and
    /// removed once the result is written).
    #[arg(long)]
    pub checkpoint: Option<PathBuf>,
    /// Continue the run saved in the checkpoint instead of starting over.
    #[arg(long)]
    pub resume: bool,
    /// Stop (and save) after this many seconds, e.g. shortly before a
    /// job's time limit. Any number > 0; a limit beyond what the clock can
    /// count (about 9.2e18 s, 292 billion years) or `inf` is no limit.
    #[arg(long, value_name = "SECONDS", value_parser = parse_time_limit)]
    pub time_limit: Option<TimeLimit>,
    /// Save the checkpoint at most this often while running (0: after
    /// every batch). Any number >= 0; above about 1.8e19 s, or `inf`, it is
    /// saved only when the run stops.
    #[arg(
        long,
        value_name = "SECONDS",
        default_value = "60",
        value_parser = parse_checkpoint_every
    )]
    pub checkpoint_every: Duration,
}

/// The arguments of `spinball lyapunov`.
#[derive(Debug, Clone, Args)]
pub struct LyapunovArgs {
    #[command(flatten)]
    pub run: RunArgs,
    #[command(flatten)]
    pub out: OutputArgs,
    #[command(flatten)]
    pub checkpoint: CheckpointArgs,
    #[command(flatten)]
    pub estimator: EstimatorArgs,
    /// Draw the result to this PNG, 1200 × 800 px (checked before the
    /// run): `lyapunov` draws λ(α) with its standard errors; `ftle` the
    /// histogram of the exponents with the band of chaos thresholds, one
    /// file per α named as `--per-ic`'s.
    #[arg(long)]
    pub png: Option<PathBuf>,
}

/// What a run gave: the estimates of a whole run, or a shard's partial
/// result (already written).
pub enum Outcome {
    /// One estimate per α.
    Finished(Vec<LyapunovEstimate>),
    /// A shard's pieces, written to --json.
    Shard,
}

/// Run the ensembles of `run`, saving to the checkpoint as they go.
///
/// # Errors
/// [`CliError`]: bad options (2), a failed run (1), an interruption (3).
pub fn run_ensembles(
    run: &RunArgs,
    out: &OutputArgs,
    ck: &CheckpointArgs,
) -> Result<Outcome, CliError> {
    let ensembles = run.ensembles()?;
    let shard = run.shard();
    let total = 0..run.ics;
    if shard.count > 1 && out.json.is_none() {
        return Err(CliError::Usage(
            "--shard needs --json: the partial result goes there for `spinball merge`".into(),
        ));
    }
    let checkpoint = ck.checkpoint.clone().or_else(|| {
        out.json.as_ref().map(|p| {
            let mut s = p.as_os_str().to_owned();
            s.push(".partial");
            PathBuf::from(s)
        })
    });
    // Both are replaced through a temporary file: refuse a device, a FIFO
    // or a directory before the run, not after it.
    out.check()?;
    if let Some(path) = &checkpoint {
        check_writable("checkpoint", path)?;
    }
    let mut doc = if ck.resume {
        let path = checkpoint.as_ref().ok_or_else(|| {
            CliError::Usage("--resume needs --checkpoint or --json (to find the checkpoint)".into())
        })?;
        let doc = read_partial(path)?;
        check_resume(path, &doc, &ensembles, shard, &total)?;
        doc
    } else {
        PartialDocument::new(shard, total)
    };
    let deadline = deadline(ck.time_limit);
    let stop = stop_flag();
    let bar = progress_bar(out.quiet);
    let every = ck.checkpoint_every;
    for (i, ensemble) in ensembles.iter().enumerate() {
        let resume = doc.points.get(i).cloned();
        let mut current = resume
            .clone()
            .unwrap_or_else(|| PartialRun::new(ensemble.provenance(), ensemble.indices.clone()));
        let mut saved = Instant::now();
        let result = {
            let doc = &mut doc;
            let current = &mut current;
            let checkpoint = checkpoint.as_deref();
            let mut keep = |done: &[TrajectoryStats]| -> Result<(), CliError> {
                current.extend(done).map_err(CliError::failed)?;
                if let Some(path) = checkpoint
                    && saved.elapsed() >= every
                {
                    save(doc, i, current, path)?;
                    saved = Instant::now();
                }
                Ok(())
            };
            let mut watch = Watch::new(&bar, &stop, deadline, &mut keep).of(i, ensembles.len());
            let result = ensemble.run_partial(resume, &mut watch);
            (result, watch.stopped)
        };
        match result {
            (Ok(part), None) => {
                set_point(&mut doc, i, part);
            }
            (Ok(part), Some(why)) => {
                set_point(&mut doc, i, part);
                bar.abandon();
                return Err(interrupted(why, &doc, checkpoint));
            }
            (Err(e), why) => {
                // Keep what finished before the failure.
                set_point(&mut doc, i, current);
                bar.abandon();
                if let Some(path) = &checkpoint {
                    write_partial(path, &doc)?;
                }
                return Err(why.unwrap_or_else(|| CliError::failed(e)));
            }
        }
    }
    bar.finish_and_clear();
    if shard.count > 1 {
        let path = out.json.as_ref().expect("checked above");
        write_partial(path, &doc)?;
        remove_checkpoint(checkpoint.as_deref(), path);
        if !out.quiet {
            print(&format!(
                "shard {shard}: initial conditions {:?} of {:?} done; wrote {} (combine the shards with `spinball merge`)\n",
                shard.range(doc.total.clone()),
                doc.total,
                path.display()
            ))?;
        }
        return Ok(Outcome::Shard);
    }
    let estimates = doc
        .points
        .iter()
        .map(PartialRun::estimate)
        .collect::<Result<Vec<_>, _>>()
        .map_err(CliError::failed)?;
    if let Some(path) = &out.json {
        remove_checkpoint(checkpoint.as_deref(), path);
    }
    Ok(Outcome::Finished(estimates))
}

/// Refuse a checkpoint of another run, naming the checkpoint and the
/// first field that differs (`seed 7 in the checkpoint, 8 asked`).
fn check_resume(
    path: &Path,
    doc: &PartialDocument,
    ensembles: &[Ensemble<Built>],
    shard: Shard,
    total: &Range<u64>,
) -> Result<(), CliError> {
    let another = |what: &str, saved: &dyn Display, asked: &dyn Display| {
        CliError::Usage(format!(
            "{} is the checkpoint of another run: {what} {saved} in the checkpoint, {asked} asked; resume with the command that wrote it",
            path.display()
        ))
    };
    if doc.shard != shard {
        return Err(another("shard", &doc.shard, &shard));
    }
    if doc.total != *total {
        return Err(another(
            "initial conditions",
            &format_args!("{:?}", doc.total),
            &format_args!("{total:?}"),
        ));
    }
    if doc.points.len() > ensembles.len() {
        return Err(another(
            "number of α values",
            &format_args!("at least {}", doc.points.len()),
            &ensembles.len(),
        ));
    }
    for (p, e) in doc.points.iter().zip(ensembles) {
        match p.provenance.difference(&e.provenance()) {
            Ok(()) => {}
            Err(RunDifference::Field { what, first, other }) => {
                return Err(another(what, &first, &other));
            }
            Err(err) => {
                return Err(CliError::Usage(format!(
                    "cannot resume from {}: {err}",
                    path.display()
                )));
            }
        }
        if p.indices != e.indices {
            return Err(another(
                "initial conditions",
                &format_args!("{:?}", p.indices),
                &format_args!("{:?}", e.indices),
            ));
        }
    }
    Ok(())
}

fn set_point(doc: &mut PartialDocument, i: usize, part: PartialRun) {
    if i < doc.points.len() {
        doc.points[i] = part;
    } else {
        doc.points.push(part);
    }
}

/// Save the document with point `i` as `current`.
fn save(
    doc: &PartialDocument,
    i: usize,
    current: &PartialRun,
    path: &std::path::Path,
) -> Result<(), CliError> {
    let mut snapshot = doc.clone();
    set_point(&mut snapshot, i, current.clone());
    write_partial(path, &snapshot)
}

/// The error of a stopped run, after saving what it finished.
fn interrupted(why: CliError, doc: &PartialDocument, checkpoint: Option<PathBuf>) -> CliError {
    match why {
        CliError::Interrupted { .. } => match checkpoint {
            Some(path) => match write_partial(&path, doc) {
                Ok(()) => CliError::Interrupted {
                    checkpoint: Some(path),
                },
                Err(e) => e,
            },
            None => CliError::Interrupted { checkpoint: None },
        },
        other => other,
    }
}

/// The checkpoint is not needed once the result is written (unless it is
/// the result's own path); only a regular file (or a link to one) is
/// removed.
fn remove_checkpoint(checkpoint: Option<&std::path::Path>, result: &std::path::Path) {
    if let Some(c) = checkpoint
        && c != result
    {
        remove_regular(c);
    }
}

/// `spinball lyapunov`.
///
/// # Errors
/// As [`run_ensembles`]; an output that cannot be written.
pub fn lyapunov(args: &LyapunovArgs) -> Result<(), CliError> {
    if let Some(options) = args.estimator.multilevel()? {
        return lyapunov_multilevel(args, &options);
    }
    if let Some(path) = &args.png {
        check_whole_png(
            path,
            args.run.shard(),
            "run: a shard has no λ yet (draw after `spinball merge`)",
        )?;
    }
    match run_ensembles(&args.run, &args.out, &args.checkpoint)? {
        Outcome::Finished(estimates) => {
            let written = args.out.write_results(&estimates);
            if let Some(path) = &args.png {
                lyapunov_png(path, &estimates)?;
            }
            written
        }
        Outcome::Shard => Ok(()),
    }
}

/// `spinball lyapunov --estimator multilevel`: one multilevel estimate per
/// α, printed, and written to --json if asked.
fn lyapunov_multilevel(
    args: &LyapunovArgs,
    options: &spinball_analysis::precision::Multilevel,
) -> Result<(), CliError> {
    if let Some(path) = &args.estimator.allocation {
        return lyapunov_allocation(args, path);
    }
    if args.run.shard.is_some() || args.checkpoint.resume {
        return Err(CliError::Usage(
            "--estimator multilevel plans its levels as it goes: it takes no --shard or --resume (a campaign fixes them with --allocation; see spinball slurm)"
                .into(),
        ));
    }
    if args.out.csv.is_some() || args.out.npy.is_some() || args.png.is_some() {
        return Err(CliError::Usage(
            "--estimator multilevel writes --json only (its levels have different numbers of initial conditions; no --png)".into(),
        ));
    }
    args.out.check()?;
    let mut points = Vec::new();
    for ensemble in args.run.ensembles()? {
        let point = run_multilevel(&ensemble, options)?;
        if !args.out.quiet {
            print(&format!("alpha = {}\n{}\n", point.alpha, point.estimate))?;
        }
        points.push(point);
    }
    match &args.out.json {
        Some(path) => write_multilevel(path, &points),
        None => Ok(()),
    }
}

/// `spinball lyapunov --estimator multilevel --allocation FILE`: the
/// allocation run whole (a `spinball.multilevel` result), or with --shard
/// that shard's block of every level (a `spinball.multilevel.partial` for
/// `spinball merge`).
fn lyapunov_allocation(args: &LyapunovArgs, path: &Path) -> Result<(), CliError> {
    if args.checkpoint.resume || args.out.csv.is_some() || args.out.npy.is_some() {
        return Err(CliError::Usage(
            "--allocation writes --json only and takes no --resume".into(),
        ));
    }
    let allocation = read_allocation(path)?;
    let ensembles = args.run.ensembles()?;
    let [ensemble] = ensembles.as_slice() else {
        return Err(CliError::Usage(format!(
            "--allocation is made for one alpha, got {}",
            ensembles.len()
        )));
    };
    args.out.check()?;
    match args.run.shard {
        Some(shard) => {
            let Some(json) = &args.out.json else {
                return Err(CliError::Usage(
                    "a shard of an --allocation needs --json for its partial result".into(),
                ));
            };
            let point = run_allocation_shard(ensemble, &allocation, shard)?;
            write_multilevel_partial(json, vec![point])
        }
        None => {
            let point = run_allocation_shard(ensemble, &allocation, Shard::WHOLE)?;
            let estimate = LevelShard::merge(std::slice::from_ref(&point.shard))
                .map_err(|e| CliError::Failed(format!("alpha = {}: {e}", point.alpha)))?;
            let point = MultilevelPoint {
                alpha: point.alpha,
                estimate,
            };
            if !args.out.quiet {
                print(&format!("alpha = {}\n{}\n", point.alpha, point.estimate))?;
            }
            match &args.out.json {
                Some(json) => write_multilevel(json, &[point]),
                None => Ok(()),
            }
        }
    }
}
