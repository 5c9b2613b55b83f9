//! `spinball escape`: how long balls take to leave a table through a hole —
//! per-ball escape times (censored at a budget, never dropped), the
//! survival curve, the escape rate, the tail and the mean against Kac.

use clap::Args;
use spinball_analysis::escape::{EscapeOptions, RateWindow, TailWindow};
use spinball_analysis::open::Budget;
use spinball_analysis::report::{Document, EscapeDocument, EscapePartialDocument};
use spinball_analysis::run::{EscapeDefaults, Shard};

use crate::error::CliError;
use crate::open_args::{OpenArgs, run_shard};
use crate::output::OutputArgs;
use crate::phase_args::parse_range;
use crate::stdout::print;

/// The arguments of `spinball escape`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "Tables: a table with a hole, e.g. `stadium:a=1,hole=0.2` (centred on the right cap; `at=S` moves it), `sinai:L=2,R=1,hole=0.2`, `circle:R=1,hole=0.3`, or a table file with `exits` or `openings`.\n\nOutputs: `--json` is a `spinball.escape` document (the summary and every ball's record); `--csv` has `index,time,collisions,censored,wall,x,y,s,v_par,spin` per ball (the exit's fields empty for a censored ball); `--npy` is (balls, 10) float64 in that order (NaN for a censored ball's exit). Collisions count the wall hits before the hole; the summary's collision clock counts the hole too."
)]
pub struct EscapeArgs {
    #[command(flatten)]
    pub open: OpenArgs,
    /// Balls (initial conditions `0..ICS` of the seed's streams),
    /// 1..=100000000.
    #[arg(long, default_value_t = EscapeDefaults::ICS, value_parser = clap::value_parser!(u64).range(1..=100_000_000))]
    pub ics: u64,
    /// Budget: most collisions per ball before it counts as censored
    /// (default 100000 when --time is not given).
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..))]
    pub collisions: Option<u64>,
    /// Budget: longest flight time per ball (with --collisions, whichever
    /// comes first).
    #[arg(long, value_name = "T")]
    pub time: Option<f64>,
    /// Escape-rate window in time `T0,T1` (default: from the median escape
    /// to the last time at which 20 balls remain).
    #[arg(long, value_name = "T0,T1", value_parser = parse_range)]
    pub window: Option<(f64, f64)>,
    /// Escape-rate window in collisions `N0,N1` (default: the same rule).
    #[arg(long, value_name = "N0,N1", value_parser = parse_range)]
    pub collision_window: Option<(f64, f64)>,
    /// Start of the tail in time (default: the latest fifth of the
    /// escapes).
    #[arg(long, value_name = "T")]
    pub tail_from: Option<f64>,
    /// Start of the tail in collisions (default: the latest fifth).
    #[arg(long, value_name = "N")]
    pub collision_tail_from: Option<f64>,
    /// Run only shard K of N (0-based, `K/N`): a block of the balls; the
    /// partial result goes to --json, for `spinball merge`.
    #[arg(long)]
    pub shard: Option<Shard>,
    #[command(flatten)]
    pub out: OutputArgs,
}

impl EscapeArgs {
    /// The budget asked for.
    fn budget(&self) -> Budget {
        match (self.collisions, self.time) {
            (Some(n), Some(t)) => Budget {
                collisions: n,
                time: t,
            },
            (None, Some(t)) => Budget::time(t),
            (n, None) => Budget::collisions(n.unwrap_or(EscapeDefaults::COLLISIONS)),
        }
    }

    /// The summary's windows.
    fn options(&self) -> EscapeOptions {
        let range = |w: Option<(f64, f64)>| {
            w.map_or_else(RateWindow::default, |(t0, t1)| RateWindow::Range { t0, t1 })
        };
        let tail =
            |t: Option<f64>| t.map_or_else(TailWindow::default, |t_min| TailWindow::From { t_min });
        EscapeOptions {
            time_window: range(self.window),
            collision_window: range(self.collision_window),
            time_tail: tail(self.tail_from),
            collision_tail: tail(self.collision_tail_from),
            ..EscapeOptions::default()
        }
    }
}

/// `spinball escape`.
///
/// # Errors
/// [`CliError::Usage`] for a table without a hole, a bad α, budget or
/// option; [`CliError::Failed`] if a trajectory fails or an output cannot
/// be written.
pub fn escape(args: &EscapeArgs) -> Result<(), CliError> {
    let run = args.open.run(args.ics)?;
    run_shard(
        &args.out,
        args.shard,
        "escape",
        |shard, progress| {
            EscapePartialDocument::run(&run, shard, args.budget(), args.options(), progress)
        },
        |part| {
            let doc = EscapePartialDocument::merge(vec![part]).map_err(CliError::failed)?;
            write_escape(&doc, &args.out)
        },
        |part| {
            let done = format!("balls {:?} of {:?}", part.indices, part.head.ics);
            (Document::EscapePartial(part), done)
        },
    )
}

/// Write the finished escape run `doc` to the outputs asked for and print
/// its summary unless quiet: the one way a whole run and `spinball merge`
/// write it.
///
/// # Errors
/// [`CliError::Failed`] for an output that cannot be written.
pub fn write_escape(doc: &EscapeDocument, out: &OutputArgs) -> Result<(), CliError> {
    out.write(
        || Document::Escape(doc.clone()),
        || doc.csv(),
        || doc.array(),
    )?;
    if out.quiet {
        return Ok(());
    }
    print(&format!(
        "{} at α = {}, {} balls from seed {}\n{}",
        doc.head.table, doc.head.alpha, doc.summary.n, doc.head.seed, doc.summary
    ))
}
