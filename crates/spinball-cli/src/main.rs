//! `spinball`: spinning billiards from the command line.
//!
//! Lyapunov exponents over ensembles of initial conditions (`lyapunov`),
//! their distribution (`ftle`), the full spectrum (`spectrum`), single
//! trajectories (`trajectory`), films of them (`animate`), tables (`table`), periodic orbits and
//! their stability (`orbits`), phase space (`section`, `ftle-map`, `kac`),
//! open and periodic tables (`escape`, `diffuse`), and campaigns on a
//! cluster: every ensemble command runs one shard with `--shard K/N`,
//! `merge` combines the shards into the unsharded result bitwise, `slurm`
//! writes the job array. Tables are built-in specs or table files (TOML or
//! JSON). Exit codes: 0 done, 1 the run failed, 2 bad usage, 3 interrupted
//! (the checkpoint is saved; rerun with `--resume`). Nothing panics on a
//! full or closed stdout: a full one is exit code 1, a closed one (`| head`)
//! ends the command quietly with 0.

#![forbid(unsafe_code)]

mod commands;
mod documents;
mod error;
mod estimator_args;
mod files;
mod open_args;
mod output;
mod phase_args;
mod pictures;
mod run_args;
mod stdout;
mod table_arg;
mod watch;

#[cfg(test)]
mod defaults_tests;

use std::io::{self, Write};
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use crate::commands::animate::{AnimateArgs, animate};
use crate::commands::diffuse::{DiffuseArgs, diffuse};
use crate::commands::escape::{EscapeArgs, escape};
use crate::commands::ftle::{FtleArgs, ftle};
use crate::commands::ftle_map::{FtleMapArgs, ftle_map};
use crate::commands::kac::{KacArgs, kac};
use crate::commands::lyapunov::{LyapunovArgs, lyapunov};
use crate::commands::merge::{MergeArgs, merge};
use crate::commands::orbits::{OrbitsArgs, orbits};
use crate::commands::section::{SectionArgs, section};
use crate::commands::slurm::{SlurmArgs, slurm};
use crate::commands::spectrum::{SpectrumArgs, spectrum};
use crate::commands::sweep::{SweepArgs, sweep};
use crate::commands::table::{TableArgs, table};
use crate::commands::trajectory::{TrajectoryArgs, trajectory};
use crate::error::CliError;
use crate::run_args::MethodArg;
use crate::stdout::stdout_error;
use spinball_analysis::run::SpectrumDefaults;

/// Spinning billiards: chaos indicators with honest error bars.
#[derive(Debug, Parser)]
#[command(name = "spinball", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// The largest Lyapunov exponent λ at one α or a list (mean, SEM,
    /// median, chaotic fraction, per-IC values).
    Lyapunov(Box<LyapunovArgs>),
    /// The distribution of finite-time exponents: per-IC values and a
    /// histogram, beside λ.
    Ftle(Box<FtleArgs>),
    /// The full Lyapunov spectrum (five exponents) of an ensemble.
    #[command(
        mut_arg("ics", |a| a.default_value(text(SpectrumDefaults::ICS))),
        mut_arg("collisions", |a| a.default_value(text(SpectrumDefaults::COLLISIONS))),
        mut_arg("method", |a| a.default_value(MethodArg::from(SpectrumDefaults::METHOD).name()))
    )]
    Spectrum(Box<SpectrumArgs>),
    /// The collisions of one start, as CSV or NPY.
    Trajectory(Box<TrajectoryArgs>),
    /// Read a table (spec or file): describe it, validate it, draw it.
    Table(TableArgs),
    /// A GIF (or MP4) of balls on a table, the spin shown by a rotating
    /// marker, collisions exact in time.
    Animate(Box<AnimateArgs>),
    /// Combine the partial results of a sharded run into the unsharded
    /// result (bitwise).
    #[command(mut_arg("json", |a| a.help(
        "Write the merged result as JSON: the document one unsharded run writes, \
         bitwise. It is replaced atomically, so it must be a regular file, a link to \
         one, or a new path"
    )))]
    Merge(MergeArgs),
    /// Write the SLURM job array (tables × α × shards) and merge job of a
    /// campaign.
    Slurm(Box<SlurmArgs>),
    /// Periodic orbits of one period, their stability through a range of α
    /// and the α where it changes.
    Orbits(Box<OrbitsArgs>),
    /// λ(α) on one built-in table with every setting explicit, rewriting a
    /// JSON document after each α: the machine interface for scripts.
    Sweep(Box<SweepArgs>),
    /// The Birkhoff section of a few orbits: every collision as
    /// (s, sin θ, v∥, |v|, u, wall, Q).
    Section(Box<SectionArgs>),
    /// The FTLE of every start on a grid of the section (fixed spin or
    /// fixed Q), with the predicted bouncing-ball island; shards merge.
    FtleMap(Box<FtleMapArgs>),
    /// Mean return times to a region of the section against Kac's lemma,
    /// orbits started from the invariant measure.
    Kac(Box<KacArgs>),
    /// Escape from a table with a hole: per-ball escape times (censored at
    /// a budget), survival P(t), escape rate, tail and Kac; shards merge.
    Escape(Box<EscapeArgs>),
    /// Diffusion through a periodic table (a Lorentz gas): mean-square
    /// displacement and the diffusion coefficient; shards merge.
    Diffuse(Box<DiffuseArgs>),
}

/// `n` as the `'static` text clap takes for a default value computed from
/// a library constant (made once, when the command line is built).
fn text(n: u64) -> &'static str {
    Box::leak(n.to_string().into_boxed_str())
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_exit(&e),
    };
    let result = match &cli.command {
        Command::Lyapunov(a) => lyapunov(a),
        Command::Ftle(a) => ftle(a),
        Command::Spectrum(a) => spectrum(a),
        Command::Trajectory(a) => trajectory(a),
        Command::Table(a) => table(a),
        Command::Animate(a) => animate(a),
        Command::Merge(a) => merge(a),
        Command::Slurm(a) => slurm(a),
        Command::Sweep(a) => sweep(a),
        Command::Orbits(a) => orbits(a),
        Command::Section(a) => section(a),
        Command::FtleMap(a) => ftle_map(a),
        Command::Kac(a) => kac(a),
        Command::Escape(a) => escape(a),
        Command::Diffuse(a) => diffuse(a),
    };
    match result {
        Ok(()) | Err(CliError::StdoutClosed) => ExitCode::SUCCESS,
        Err(e) => {
            complain(&e);
            e.code()
        }
    }
}

/// Say what failed on stderr; if even stderr cannot take it, the exit
/// code still says it.
fn complain(e: &impl std::fmt::Display) {
    let _ = writeln!(io::stderr(), "spinball: {e}");
}

/// What clap's own messages end with: usage errors on stderr (exit code
/// 2), `--help` and `--version` on stdout (0, or 1 if stdout is full).
fn clap_exit(e: &clap::Error) -> ExitCode {
    let printed = e.print().and_then(|()| io::stdout().flush());
    if e.use_stderr() {
        return ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2));
    }
    match printed.map_err(|e| stdout_error(&e)) {
        Ok(()) | Err(CliError::StdoutClosed) => ExitCode::SUCCESS,
        Err(e) => {
            complain(&e);
            e.code()
        }
    }
}
