//! `spinball ftle-map`: the finite-time Lyapunov exponent of every start on
//! a grid of the Birkhoff section, at fixed spin or fixed `Q`, with the
//! bouncing-ball island predicted on a stadium; whole, or one shard at a
//! time for `spinball merge`.

use std::path::{Path, PathBuf};

use clap::Args;
use spinball_analysis::AnalysisError;
use spinball_analysis::phase_space::{FtleMapOptions, FtleMapPart, Slice, ftle_map_part};
use spinball_analysis::report::{Document, FtleMapDocument, FtleMapPartialDocument};
use spinball_analysis::run::{FtleMapDefaults, RunDefaults, Shard};
use spinball_core::SpinLaw;

use crate::documents::read_document;
use crate::error::CliError;
use crate::output::OutputArgs;
use crate::phase_args::PhaseArgs;
use crate::pictures::{check_whole_png, ftle_map_png};
use crate::stdout::print;

/// The arguments of `spinball ftle-map`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "Outputs: `--npy` is the map, (rows, columns) float64, row 0 at the bottom (row coordinate −1), NaN off the shell; `--csv` has `s,row,ftle` per cell on the shell; `--json` the map, its options, counts and (stadium) the predicted bouncing-ball cells."
)]
pub struct FtleMapArgs {
    #[command(flatten)]
    pub phase: PhaseArgs,
    /// Cells along the arc length s, 1..=65536 (columns × rows ≤ 2^32).
    #[arg(long, default_value_t = FtleMapDefaults::COLUMNS, value_parser = clap::value_parser!(u32).range(1..=65_536))]
    pub columns: u32,
    /// Cells along the row coordinate (sin θ at fixed spin, v∥/|V| at
    /// fixed Q), 1..=65536.
    #[arg(long, default_value_t = FtleMapDefaults::ROWS, value_parser = clap::value_parser!(u32).range(1..=65_536))]
    pub rows: u32,
    /// The slice at fixed spin u (needs αu² < 1); the default slice is
    /// u = 0.
    #[arg(
        long,
        value_name = "U",
        allow_negative_numbers = true,
        conflicts_with = "q"
    )]
    pub spin: Option<f64>,
    /// The slice at fixed Q = v∥ − αu instead (needs α > 0); cells off the
    /// energy shell have no exponent.
    #[arg(long, value_name = "Q", allow_negative_numbers = true)]
    pub q: Option<f64>,
    /// Collisions per start (exact tangent method), 1..=100000000.
    #[arg(long, default_value_t = FtleMapDefaults::COLLISIONS, value_parser = clap::value_parser!(u64).range(1..=100_000_000))]
    pub collisions: u64,
    /// FTLE at or below which a cell is regular.
    #[arg(long, default_value_t = RunDefaults::THRESHOLD)]
    pub threshold: f64,
    /// Run only shard K of N (0-based, `K/N`): a block of the cells; the
    /// partial map goes to --json, for `spinball merge`.
    #[arg(long)]
    pub shard: Option<Shard>,
    #[command(flatten)]
    pub out: OutputArgs,
    /// Draw the map to this PNG, 1200 × 800 px: the FTLE of each cell as
    /// an image (white off the shell), the predicted bouncing-ball cells
    /// outlined in red, with a colour bar (checked before the run).
    #[arg(long)]
    pub png: Option<PathBuf>,
}

/// Write the outputs of the finished map `doc` asked for and print a
/// summary unless quiet.
///
/// # Errors
/// [`CliError::Failed`] for an output that cannot be written.
fn write_results(doc: &FtleMapDocument, out: &OutputArgs) -> Result<(), CliError> {
    let map = &doc.map;
    out.write(
        || Document::FtleMap(doc.clone()),
        || map.to_csv(),
        || {
            let shape = vec![map.options.rows as u64, map.options.columns as u64];
            (shape, map.to_array())
        },
    )?;
    if out.quiet {
        return Ok(());
    }
    let (regular, on_shell) = map.counts();
    let f = &doc.chaotic_fraction;
    let mut line = format!(
        "{} × {} map at α = {}, {:?}: {regular} of {on_shell} cells regular (FTLE ≤ {}); chaotic fraction {}",
        map.options.columns,
        map.options.rows,
        map.alpha,
        map.options.slice,
        map.options.threshold,
        spinball_analysis::estimators::PlusMinus::new(f.fraction, f.sem),
    );
    if doc.predicted.is_some() {
        line.push_str(&format!(
            "; bouncing-ball cells predicted {}, of which regular {}",
            doc.predicted_cells, doc.predicted_regular
        ));
    }
    line.push('\n');
    print(&line)
}

/// Read the FTLE map shard in `path`.
///
/// # Errors
/// [`CliError::Usage`] for a file that is not one (naming its kind).
fn read_partial(path: &Path) -> Result<FtleMapPart, CliError> {
    read_document(path)?
        .into_ftle_map_partial()
        .map(|doc| doc.part)
        .map_err(|e| CliError::Usage(format!("{} is {e}", path.display())))
}

/// `spinball merge` of FTLE map shards: `first` (read from the first
/// file) and those in `rest`, into the whole map, bitwise that of one run.
///
/// # Errors
/// [`CliError::Usage`] for files that are not shards of one map, or that
/// overlap or leave cells out.
pub fn merge_maps(
    first: FtleMapPart,
    rest: &[std::path::PathBuf],
    out: &OutputArgs,
) -> Result<(), CliError> {
    out.check()?;
    let mut parts = vec![first];
    for path in rest {
        parts.push(read_partial(path)?);
    }
    let record = parts[0].table.clone();
    let table = record
        .shape
        .as_ref()
        .ok_or_else(|| CliError::Usage("the shards' table has no shape".into()))?
        .build()
        .map_err(CliError::usage)?;
    let alpha = parts[0].map.alpha;
    let law = SpinLaw::extended(alpha).map_err(CliError::usage)?;
    let map = FtleMapPart::merge(parts).map_err(CliError::usage)?;
    write_results(&FtleMapDocument::new(&table, &law, record, map), out)
}

/// `spinball ftle-map`.
///
/// # Errors
/// [`CliError::Usage`] for a bad table, α or option; [`CliError::Failed`]
/// if a start fails or an output cannot be written.
pub fn ftle_map(args: &FtleMapArgs) -> Result<(), CliError> {
    let p = &args.phase;
    let (table, law, threads) = p.setup()?;
    let shard = args.shard.unwrap_or(Shard::WHOLE);
    let shard_path = args.out.shard_path(shard)?;
    args.out.check()?;
    if let Some(path) = &args.png {
        check_whole_png(path, shard, "map: a shard holds only some of its cells")?;
    }
    let slice = match args.q {
        Some(q) => Slice::Q(q),
        None => Slice::Spin(args.spin.unwrap_or(0.0)),
    };
    let options = FtleMapOptions::new(args.columns as usize, args.rows as usize, slice)
        .with_collisions(args.collisions)
        .with_seed(p.seed)
        .with_threshold(args.threshold)
        .with_threads(threads);
    let part = ftle_map_part(&table, law, &options, shard).map_err(|e| match e {
        AnalysisError::InvalidOption { .. } => CliError::usage(e),
        e => CliError::failed(e),
    })?;
    if let Some(path) = shard_path {
        let done = format!("on-shell cells {:?} of {}", part.starts, part.on_shell);
        let doc = Document::FtleMapPartial(FtleMapPartialDocument { part });
        return args.out.write_shard(path, &doc, shard, &done);
    }
    let record = part.table.clone();
    let doc = FtleMapDocument::new(&table, &law, record, part.map);
    let written = write_results(&doc, &args.out);
    if let Some(path) = &args.png {
        let title = format!(
            "{} at α = {}: {} collisions per start",
            doc.table, doc.map.alpha, doc.map.options.collisions
        );
        ftle_map_png(path, title, &doc.map, doc.predicted.as_deref())?;
    }
    written
}
