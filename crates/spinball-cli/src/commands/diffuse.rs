//! `spinball diffuse`: how balls spread through a periodic table — per-IC
//! unwrapped displacements at checkpoint times, the mean-square
//! displacement, and the diffusion coefficient (or, for an infinite
//! horizon, the marginal coefficient: never a finite `D` that is not one).

use clap::Args;
use spinball_analysis::report::{DiffusionDocument, DiffusionPartialDocument, Document};
use spinball_analysis::run::{DiffusionDefaults, Shard};
use spinball_analysis::transport::FitWindow;

use crate::error::CliError;
use crate::open_args::{OpenArgs, run_shard};
use crate::output::OutputArgs;
use crate::phase_args::parse_range;
use crate::stdout::print;

/// The arguments of `spinball diffuse`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "Tables: the cell of a Lorentz gas, `lorentz:lattice=triangular,w=1,R=0.45` (finite horizon for R >= √3·w/4) or `lorentz:lattice=square,w=1,R=0.4` (infinite horizon: the marginal coefficient of t ln t growth is reported, no finite D). A table file with `periodic` walls works too: the geometry decides its horizon.\n\nOutputs: `--json` is a `spinball.diffusion` document (the summary and every IC's displacements); `--csv` has `index,t,dx,dy` per IC and checkpoint; `--npy` is (ICs, checkpoints, 2) float64, the displacements."
)]
pub struct DiffuseArgs {
    #[command(flatten)]
    pub open: OpenArgs,
    /// Initial conditions (`0..ICS` of the seed's streams), 2..=100000000.
    #[arg(long, default_value_t = DiffusionDefaults::ICS, value_parser = clap::value_parser!(u64).range(2..=100_000_000))]
    pub ics: u64,
    /// The last checkpoint time.
    #[arg(long, value_name = "T", default_value_t = DiffusionDefaults::UNTIL)]
    pub until: f64,
    /// Checkpoints, evenly spaced up to --until, 3..=100000.
    #[arg(long, default_value_t = DiffusionDefaults::CHECKPOINTS, value_parser = clap::value_parser!(u32).range(3..=100_000))]
    pub checkpoints: u32,
    /// The checkpoint times, comma-separated and increasing (instead of
    /// --until and --checkpoints).
    #[arg(long, value_delimiter = ',', conflicts_with_all = ["until", "checkpoints"])]
    pub times: Option<Vec<f64>>,
    /// The fit window `T0,T1` of the Einstein relation (default: the later
    /// half of the run).
    #[arg(long, value_name = "T0,T1", value_parser = parse_range)]
    pub window: Option<(f64, f64)>,
    /// Run only shard K of N (0-based, `K/N`): a block of the initial
    /// conditions; the partial result goes to --json, for `spinball merge`.
    #[arg(long)]
    pub shard: Option<Shard>,
    #[command(flatten)]
    pub out: OutputArgs,
}

impl DiffuseArgs {
    /// The checkpoint times.
    fn times(&self) -> Result<Vec<f64>, CliError> {
        if let Some(times) = &self.times {
            return Ok(times.clone());
        }
        if !(self.until.is_finite() && self.until > 0.0) {
            return Err(CliError::Usage(format!(
                "--until {}: the last checkpoint must be a finite time > 0",
                self.until
            )));
        }
        let n = f64::from(self.checkpoints);
        Ok((1..=self.checkpoints)
            .map(|k| self.until * f64::from(k) / n)
            .collect())
    }
}

/// `spinball diffuse`.
///
/// # Errors
/// [`CliError::Usage`] for a table without periodic walls or of unknown
/// horizon, with holes, a bad α, times or window; [`CliError::Failed`] if a
/// trajectory fails or an output cannot be written.
pub fn diffuse(args: &DiffuseArgs) -> Result<(), CliError> {
    let times = args.times()?;
    let window = args
        .window
        .map(|(t0, t1)| FitWindow::new(t0, t1))
        .transpose()
        .map_err(|e| CliError::Usage(format!("--window: {e}")))?;
    let run = args.open.run(args.ics)?;
    run_shard(
        &args.out,
        args.shard,
        "diffuse",
        |shard, progress| DiffusionPartialDocument::run(&run, shard, &times, window, progress),
        |part| {
            let doc = DiffusionPartialDocument::merge(vec![part]).map_err(CliError::failed)?;
            write_diffusion(&doc, &args.out)
        },
        |part| {
            let done = format!(
                "initial conditions {:?} of {:?}",
                part.indices, part.head.ics
            );
            (Document::DiffusionPartial(part), done)
        },
    )
}

/// Write the finished diffusion run `doc` to the outputs asked for and
/// print its summary unless quiet: the one way a whole run and `spinball
/// merge` write it.
///
/// # Errors
/// [`CliError::Failed`] for an output that cannot be written.
pub fn write_diffusion(doc: &DiffusionDocument, out: &OutputArgs) -> Result<(), CliError> {
    out.write(
        || Document::Diffusion(doc.clone()),
        || doc.csv(),
        || doc.array(),
    )?;
    if out.quiet {
        return Ok(());
    }
    print(&format!(
        "{} at α = {}, seed {}\n{}",
        doc.head.table, doc.head.alpha, doc.head.seed, doc.summary
    ))
}
