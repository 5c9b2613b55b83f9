//! `spinball slurm`: the scripts of a campaign (tables × α × shards) as a
//! SLURM job array, and the merge job that waits for it.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use clap::Args;
use serde::Serialize;
use spinball_analysis::precision::Multilevel;

use crate::documents::write_json;
use crate::error::CliError;
use crate::estimator_args::{EstimatorArgs, allocate_multilevel};
use crate::output::write_text;
use crate::run_args::RunArgs;
use crate::stdout::print;
use crate::table_arg::read_table;

/// The arguments of `spinball slurm`.
#[derive(Debug, Clone, Args)]
pub struct SlurmArgs {
    #[command(flatten)]
    pub run: RunArgs,
    /// `--estimator multilevel --target-error E`: the allocation (levels,
    /// initial conditions per level) is planned from a pilot once, now,
    /// for every table and α; each task runs its shard of every level.
    #[command(flatten)]
    pub estimator: EstimatorArgs,
    /// More tables for the campaign (repeat the option).
    #[arg(long = "and-table", value_name = "TABLE")]
    pub more_tables: Vec<String>,
    /// Shards per (table, α): the array has tables × α × shards tasks.
    #[arg(long, default_value_t = 4)]
    pub shards: u64,
    /// Directory for the scripts, the partial results, the logs and the
    /// merged results (created). One that exists and is not empty is
    /// refused unless --force.
    #[arg(long)]
    pub dir: PathBuf,
    /// Write the scripts into a --dir that is not empty (an earlier
    /// campaign's scripts and campaign.json are replaced; its partial
    /// results are kept, and a task resumes from one only if it is of the
    /// same run).
    #[arg(long)]
    pub force: bool,
    /// SLURM partition.
    #[arg(long)]
    pub partition: Option<String>,
    /// Time limit of each task (`MM`, `MM:SS`, `HH:MM:SS` or `D-HH:MM:SS`);
    /// a task stops a minute before it (or at 90%), saves what it finished
    /// and resumes when resubmitted.
    #[arg(long, default_value = "01:00:00")]
    pub time: String,
    /// CPUs per task (its threads), 1..=1024.
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub cpus_per_task: u32,
    /// The `spinball` binary the jobs run (default: this one).
    #[arg(long)]
    pub spinball: Option<PathBuf>,
}

/// Refuse a `--dir` that exists and holds anything, unless `force`: a
/// second campaign written over a first would mix their files silently.
fn refuse_occupied(dir: &Path, force: bool) -> Result<(), CliError> {
    if force {
        return Ok(());
    }
    let Ok(mut entries) = fs::read_dir(dir) else {
        return Ok(());
    };
    if entries.next().is_none() {
        return Ok(());
    }
    let what = if dir.join("campaign.json").exists() {
        "holds a campaign already (campaign.json)"
    } else {
        "is not empty"
    };
    Err(CliError::Usage(format!(
        "--dir {} {what}: choose a new directory, or pass --force to write the scripts over it",
        dir.display()
    )))
}

/// What the campaign is, for the user and for scripts: which file holds
/// which (table, α).
#[derive(Debug, Clone, Serialize)]
struct Campaign {
    tables: Vec<String>,
    alphas: Vec<f64>,
    shards: u64,
    tasks: u64,
    results: Vec<CampaignResult>,
}

#[derive(Debug, Clone, Serialize)]
struct CampaignResult {
    table: String,
    alpha: f64,
    json: PathBuf,
}

/// Seconds of a SLURM time limit.
fn seconds(limit: &str) -> Option<u64> {
    let (days, rest) = match limit.split_once('-') {
        Some((d, r)) => (d.parse::<u64>().ok()?, r),
        None => (0, limit),
    };
    let parts: Vec<u64> = rest
        .split(':')
        .map(|p| p.parse().ok())
        .collect::<Option<_>>()?;
    let s = match (limit.contains('-'), parts.as_slice()) {
        (false, [m]) => m * 60,
        (false, [m, s]) => m * 60 + s,
        (_, [h, m, s]) => h * 3600 + m * 60 + s,
        (true, [h]) => h * 3600,
        (true, [h, m]) => h * 3600 + m * 60,
        _ => return None,
    };
    Some(days * 86_400 + s)
}

/// `s` in single quotes for bash.
fn quote(s: &str) -> String {
    format!("'{}'", s.replace('\'', r"'\''"))
}

/// A table argument the jobs can read from any directory.
fn absolute_table(arg: &str) -> Result<String, CliError> {
    read_table(arg)?;
    let p = Path::new(arg);
    if p.extension().is_some_and(|e| e == "toml" || e == "json") {
        let abs =
            fs::canonicalize(p).map_err(|e| CliError::Usage(format!("table file {arg}: {e}")))?;
        Ok(abs.display().to_string())
    } else {
        Ok(arg.to_string())
    }
}

/// `spinball slurm`.
///
/// # Errors
/// [`CliError::Usage`] for a bad table, α, time or shard count;
/// [`CliError::Failed`] if the scripts cannot be written.
pub fn slurm(args: &SlurmArgs) -> Result<(), CliError> {
    let run = &args.run;
    if run.shard.is_some() {
        return Err(CliError::Usage(
            "spinball slurm assigns the shards itself; drop --shard".into(),
        ));
    }
    run.ensembles()?;
    let multilevel = args.estimator.multilevel()?;
    if args.estimator.allocation.is_some() {
        return Err(CliError::Usage(
            "spinball slurm plans the multilevel allocations itself; drop --allocation".into(),
        ));
    }
    if args.shards == 0 || (multilevel.is_none() && args.shards > run.ics) {
        return Err(CliError::Usage(format!(
            "--shards {}: must be between 1 and --ics ({})",
            args.shards, run.ics
        )));
    }
    let limit = seconds(&args.time).ok_or_else(|| {
        CliError::Usage(format!(
            "--time {}: expected MM, MM:SS, HH:MM:SS or D-HH:MM:SS",
            args.time
        ))
    })?;
    if limit == 0 {
        return Err(CliError::Usage("--time must be more than zero".into()));
    }
    let stop_after = (limit.saturating_sub(60)).max(limit * 9 / 10).max(1);
    let tables = std::iter::once(&run.table)
        .chain(&args.more_tables)
        .map(|t| absolute_table(t))
        .collect::<Result<Vec<_>, _>>()?;
    let exe = match &args.spinball {
        Some(p) => p.clone(),
        None => std::env::current_exe().map_err(CliError::failed)?,
    };
    refuse_occupied(&args.dir, args.force)?;
    fs::create_dir_all(args.dir.join("parts"))
        .and_then(|()| fs::create_dir_all(args.dir.join("logs")))
        .and_then(|()| fs::create_dir_all(args.dir.join("results")))
        .map_err(|e| CliError::Failed(format!("cannot create {}: {e}", args.dir.display())))?;
    let dir = fs::canonicalize(&args.dir).map_err(CliError::failed)?;
    if let Some(options) = &multilevel {
        write_allocations(run, &tables, options, &dir)?;
    }
    let d = quote(&dir.display().to_string());
    let exe = quote(&exe.display().to_string());
    let n_tables = tables.len() as u64;
    let n_alphas = run.alpha.len() as u64;
    let tasks = n_tables * n_alphas * args.shards;
    let tables_sh: Vec<String> = tables.iter().map(|t| quote(t)).collect();
    let alphas_sh: Vec<String> = run.alpha.iter().map(|a| format!("{a}")).collect();
    let options = run.options_for_jobs().join(" ");
    let partition = args
        .partition
        .as_ref()
        .map(|p| format!("#SBATCH --partition={p}\n"))
        .unwrap_or_default();

    let task = match (&multilevel, args.estimator.target_error) {
        (Some(_), Some(target)) => format!(
            "exec {exe} lyapunov --table \"${{TABLES[$t]}}\" --alpha \"${{ALPHAS[$a]}}\" \\
  --shard \"$shard/$SHARDS\" --threads \"${{SLURM_CPUS_PER_TASK:-1}}\" \\
  {options} --estimator multilevel --target-error {target} \\
  --allocation {d}/plans/t${{t}}_a${{a}}.json --quiet --json \"$out\"
"
        ),
        _ => format!(
            "# A task stopped at its time limit saved its checkpoint: resubmitted, it resumes.
resume=()
if [ -f \"$out.partial\" ]; then resume=(--resume); fi
exec {exe} lyapunov --table \"${{TABLES[$t]}}\" --alpha \"${{ALPHAS[$a]}}\" \\
  --shard \"$shard/$SHARDS\" --threads \"${{SLURM_CPUS_PER_TASK:-1}}\" \\
  {options} --time-limit {stop_after} --quiet --json \"$out\" \"${{resume[@]}}\"
"
        ),
    };
    // Multilevel results are --json only.
    let csv = if multilevel.is_some() {
        String::new()
    } else {
        format!(" --csv {d}/results/t${{t}}_a${{a}}.csv")
    };
    let mut array = String::new();
    let _ = write!(
        array,
        "#!/bin/bash
# A spinball campaign as a job array: {tasks} tasks = {n_tables} table(s) x {n_alphas} alpha(s) x {shards} shard(s).
# Written by `spinball slurm`; submit with submit.sh (the merge job waits for the array).
#SBATCH --job-name=spinball
#SBATCH --array=0-{last}
#SBATCH --cpus-per-task={cpus}
#SBATCH --time={time}
#SBATCH --output={dir}/logs/%A_%a.out
{partition}set -euo pipefail
TABLES=({tables})
ALPHAS=({alphas})
SHARDS={shards}
id=$SLURM_ARRAY_TASK_ID
shard=$(( id % SHARDS ))
rest=$(( id / SHARDS ))
a=$(( rest % ${{#ALPHAS[@]}} ))
t=$(( rest / ${{#ALPHAS[@]}} ))
out={d}/parts/t${{t}}_a${{a}}_s${{shard}}.json
{task}",
        last = tasks - 1,
        shards = args.shards,
        cpus = args.cpus_per_task,
        time = args.time,
        dir = dir.display(),
        tables = tables_sh.join(" "),
        alphas = alphas_sh.join(" "),
    );

    let mut merge = String::new();
    let _ = write!(
        merge,
        "#!/bin/bash
# Merge the shards of every (table, alpha) of the campaign into one result each.
#SBATCH --job-name=spinball-merge
#SBATCH --cpus-per-task=1
#SBATCH --time=00:30:00
#SBATCH --output={dir}/logs/merge_%j.out
{partition}set -euo pipefail
for t in $(seq 0 {tl}); do
  for a in $(seq 0 {al}); do
    {exe} merge --quiet {d}/parts/t${{t}}_a${{a}}_s*.json \\
      --json {d}/results/t${{t}}_a${{a}}.json{csv}
  done
done
",
        dir = dir.display(),
        tl = n_tables - 1,
        al = n_alphas - 1,
    );

    let submit = format!(
        "#!/bin/bash
# Submit the campaign: the array, then the merge job once every task succeeded.
set -euo pipefail
cd {d}
array=$(sbatch --parsable \"$@\" array.sbatch)
merge=$(sbatch --parsable --dependency=afterok:${{array%%;*}} merge.sbatch)
echo \"array job $array, merge job $merge\"
"
    );

    let results = tables
        .iter()
        .enumerate()
        .flat_map(|(t, table)| {
            let dir = &dir;
            run.alpha
                .iter()
                .enumerate()
                .map(move |(a, &alpha)| CampaignResult {
                    table: table.clone(),
                    alpha,
                    json: dir.join("results").join(format!("t{t}_a{a}.json")),
                })
        })
        .collect();
    let campaign = Campaign {
        tables,
        alphas: run.alpha.clone(),
        shards: args.shards,
        tasks,
        results,
    };
    for (name, text) in [
        ("array.sbatch", &array),
        ("merge.sbatch", &merge),
        ("submit.sh", &submit),
    ] {
        write_text(&dir.join(name), text)?;
    }
    make_executable(&dir.join("submit.sh"))?;
    write_json(&dir.join("campaign.json"), &campaign)?;
    print(&format!(
        "wrote {}/{{array.sbatch,merge.sbatch,submit.sh,campaign.json}}: {tasks} tasks; run {}/submit.sh\n",
        dir.display(),
        dir.display()
    ))
}

/// The multilevel allocation of every (table, α) from a pilot, written to
/// `dir/plans/t{t}_a{a}.json` for the tasks (planned once, so every shard
/// runs its block of the same levels).
fn write_allocations(
    run: &RunArgs,
    tables: &[String],
    options: &Multilevel,
    dir: &Path,
) -> Result<(), CliError> {
    fs::create_dir_all(dir.join("plans"))
        .map_err(|e| CliError::Failed(format!("cannot create {}/plans: {e}", dir.display())))?;
    for (t, table) in tables.iter().enumerate() {
        let mut one = run.clone();
        one.table.clone_from(table);
        for (a, ensemble) in one.ensembles()?.iter().enumerate() {
            let allocation = allocate_multilevel(ensemble, options)?;
            print(&format!(
                "table {t}, alpha = {}: levels {:?}, initial conditions {:?}\n",
                ensemble.alpha(),
                allocation.levels,
                allocation.ics
            ))?;
            write_json(
                &dir.join("plans").join(format!("t{t}_a{a}.json")),
                &allocation,
            )?;
        }
    }
    Ok(())
}

#[cfg(unix)]
fn make_executable(path: &Path) -> Result<(), CliError> {
    use std::os::unix::fs::PermissionsExt;
    fs::set_permissions(path, fs::Permissions::from_mode(0o755)).map_err(CliError::failed)
}

#[cfg(not(unix))]
fn make_executable(_: &Path) -> Result<(), CliError> {
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slurm_times() {
        assert_eq!(seconds("30"), Some(1800));
        assert_eq!(seconds("30:15"), Some(1815));
        assert_eq!(seconds("01:00:00"), Some(3600));
        assert_eq!(seconds("2-00:00:10"), Some(172_810));
        assert_eq!(seconds("1-2"), Some(93_600));
        assert_eq!(seconds("1:2:3:4"), None);
        assert_eq!(seconds("an hour"), None);
    }

    #[test]
    fn quoting_survives_quotes() {
        assert_eq!(quote("it's"), r"'it'\''s'");
    }
}
