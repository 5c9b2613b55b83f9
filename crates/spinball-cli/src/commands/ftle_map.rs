//! `spinball ftle-map`: the finite-time Lyapunov exponent of every start on
//! a grid of the Birkhoff section, at fixed spin or fixed `Q`, with the
//! bouncing-ball island predicted on a stadium; whole, or one shard at a
//! time for `spinball merge`.

use std::path::Path;

use clap::Args;
use serde::{Deserialize, Serialize};
use spinball_analysis::AnalysisError;
use spinball_analysis::estimators::{CHAOS_THRESHOLD, ChaoticFraction};
use spinball_analysis::phase_space::{
    FacingFlats, FtleMap, FtleMapOptions, FtleMapPart, Slice, ftle_map_part,
};
use spinball_analysis::run::{Shard, TableRecord};
use spinball_core::SpinLaw;
use spinball_geometry::Built;

use crate::documents::write_json;
use crate::error::CliError;
use crate::phase_args::{PhaseArgs, PhaseOutput};
use crate::stdout::print;

/// The `kind` of a finished FTLE map.
pub const FTLE_MAP_KIND: &str = "spinball.ftle_map";
/// The `kind` of one shard of an FTLE map.
pub const FTLE_MAP_PARTIAL_KIND: &str = "spinball.ftle_map.partial";

/// The arguments of `spinball ftle-map`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "Outputs: `--npy` is the map, (rows, columns) float64, row 0 at the bottom (row coordinate −1), NaN off the shell; `--csv` has `s,row,ftle` per cell on the shell; `--json` the map, its options, counts and (stadium) the predicted bouncing-ball cells."
)]
pub struct FtleMapArgs {
    #[command(flatten)]
    pub phase: PhaseArgs,
    /// Cells along the arc length s, 1..=65536 (columns × rows ≤ 2^32).
    #[arg(long, default_value_t = 64, value_parser = clap::value_parser!(u32).range(1..=65_536))]
    pub columns: u32,
    /// Cells along the row coordinate (sin θ at fixed spin, v∥/|V| at
    /// fixed Q), 1..=65536.
    #[arg(long, default_value_t = 64, value_parser = clap::value_parser!(u32).range(1..=65_536))]
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
    #[arg(long, default_value_t = 2000, value_parser = clap::value_parser!(u64).range(1..=100_000_000))]
    pub collisions: u64,
    /// FTLE at or below which a cell is regular.
    #[arg(long, default_value_t = CHAOS_THRESHOLD)]
    pub threshold: f64,
    /// Run only shard K of N (0-based, `K/N`): a block of the cells; the
    /// partial map goes to --json, for `spinball merge`.
    #[arg(long)]
    pub shard: Option<Shard>,
    #[command(flatten)]
    pub out: PhaseOutput,
}

/// A finished map with what it shows.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct FtleMapDocument {
    /// [`FTLE_MAP_KIND`].
    pub kind: String,
    /// The version of spinball that wrote it.
    pub version: String,
    /// The table.
    pub table: TableRecord,
    /// The map: options, α, perimeter, exponents (row-major, `null` off
    /// the shell).
    pub map: FtleMap,
    /// The chaotic share of the cells on the shell, with its binomial error.
    pub chaotic_fraction: ChaoticFraction,
    /// The cells the bouncing-ball rotation predicts trapped between two
    /// facing flats (row-major); `null` for a table without them.
    pub predicted: Option<Vec<bool>>,
    /// Predicted cells on the shell, and how many of them the map finds
    /// regular.
    pub predicted_cells: usize,
    /// See `predicted_cells`.
    pub predicted_regular: usize,
}

/// One shard's map.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct FtleMapPartialDocument {
    /// [`FTLE_MAP_PARTIAL_KIND`].
    pub kind: String,
    /// The shard.
    pub part: FtleMapPart,
}

impl FtleMapDocument {
    /// The document of `map` of `table` under `law`.
    fn new(table: &Built, law: &SpinLaw, record: TableRecord, map: FtleMap) -> Self {
        let flats = match table {
            Built::Table(t) => FacingFlats::of_table(t),
            Built::Segments(_) => None,
        };
        let predicted = flats.map(|f| f.trapped_cells(law, &map));
        let (predicted_cells, predicted_regular) = predicted
            .as_ref()
            .map_or((0, 0), |mask| map.regular_among(mask));
        FtleMapDocument {
            kind: FTLE_MAP_KIND.into(),
            version: env!("CARGO_PKG_VERSION").into(),
            table: record,
            chaotic_fraction: map.chaotic_fraction(),
            map,
            predicted,
            predicted_cells,
            predicted_regular,
        }
    }

    /// Write the outputs asked for and print a summary unless quiet.
    ///
    /// # Errors
    /// [`CliError::Failed`] for an output that cannot be written.
    pub fn write_results(&self, out: &PhaseOutput) -> Result<(), CliError> {
        let map = &self.map;
        out.write(
            self,
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
        let f = &self.chaotic_fraction;
        let mut line = format!(
            "{} × {} map at α = {}, {:?}: {regular} of {on_shell} cells regular (FTLE ≤ {}); chaotic fraction {}",
            map.options.columns,
            map.options.rows,
            map.alpha,
            map.options.slice,
            map.options.threshold,
            spinball_analysis::estimators::PlusMinus::new(f.fraction, f.sem),
        );
        if self.predicted.is_some() {
            line.push_str(&format!(
                "; bouncing-ball cells predicted {}, of which regular {}",
                self.predicted_cells, self.predicted_regular
            ));
        }
        line.push('\n');
        print(&line)
    }
}

/// Read a shard's map.
///
/// # Errors
/// [`CliError::Usage`] for a file that is not one.
pub fn read_partial(path: &Path) -> Result<FtleMapPart, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Usage(format!("cannot read {}: {e}", path.display())))?;
    let doc: FtleMapPartialDocument = serde_json::from_str(&text).map_err(|e| {
        CliError::Usage(format!(
            "{} is not a valid spinball FTLE map shard: {e}",
            path.display()
        ))
    })?;
    if doc.kind != FTLE_MAP_PARTIAL_KIND {
        return Err(CliError::Usage(format!(
            "{} is a `{}`, not an FTLE map shard (`{FTLE_MAP_PARTIAL_KIND}`)",
            path.display(),
            doc.kind
        )));
    }
    Ok(doc.part)
}

/// `spinball merge` of FTLE map shards: the whole map, bitwise that of one
/// run.
///
/// # Errors
/// [`CliError::Usage`] for files that are not shards of one map, or that
/// overlap or leave cells out.
pub fn merge_maps(paths: &[std::path::PathBuf], out: &PhaseOutput) -> Result<(), CliError> {
    out.check()?;
    let parts = paths
        .iter()
        .map(|p| read_partial(p))
        .collect::<Result<Vec<_>, _>>()?;
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
    FtleMapDocument::new(&table, &law, record, map).write_results(out)
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
    if shard.count > 1 && args.out.json.is_none() {
        return Err(CliError::Usage(
            "--shard needs --json: the partial map goes there for `spinball merge`".into(),
        ));
    }
    args.out.check()?;
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
    if shard.count > 1 {
        let path = args.out.json.as_ref().expect("checked above");
        let starts = part.starts.clone();
        let on_shell = part.on_shell;
        let doc = FtleMapPartialDocument {
            kind: FTLE_MAP_PARTIAL_KIND.into(),
            part,
        };
        write_json(path, &doc)?;
        if args.out.quiet {
            return Ok(());
        }
        return print(&format!(
            "shard {shard}: on-shell cells {starts:?} of {on_shell} done; wrote {} (combine the shards with `spinball merge`)\n",
            path.display()
        ));
    }
    let record = part.table.clone();
    FtleMapDocument::new(&table, &law, record, part.map).write_results(&args.out)
}
