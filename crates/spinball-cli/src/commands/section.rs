//! `spinball section`: the Birkhoff section of a few orbits, every
//! collision as a point `(s, sin θ, v∥, |v|, u, wall, Q)`.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use spinball_analysis::AnalysisError;
use spinball_analysis::phase_space::{
    SECTION_COLUMNS, invariant_starts, sampled_sections, section_rows, sections,
};
use spinball_analysis::report::{Document, PhaseHead, SectionDocument, SectionPartialDocument};
use spinball_analysis::run::{SectionDefaults, Shard};
use spinball_core::{Billiard, Sampler};
use spinball_geometry::Boundary;

use crate::error::CliError;
use crate::output::OutputArgs;
use crate::phase_args::{PhaseArgs, csv_rows};
use crate::pictures::{check_whole_png, section_png};
use crate::stdout::print;

/// How the orbits start.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum StartsArg {
    /// The paper's sampler.
    Paper,
    /// Uniform on the energy shell.
    Microcanonical,
    /// The invariant measure of the collision map, `ds dv∥ d(√α u)`
    /// (uniform in arc length and in the disk of `(v∥, √α u)`), on the
    /// shell E = ½.
    Invariant,
}

impl StartsArg {
    /// The name the section document gives the starts.
    fn name(self) -> &'static str {
        match self {
            StartsArg::Paper => "paper",
            StartsArg::Microcanonical => "microcanonical",
            StartsArg::Invariant => "invariant",
        }
    }
}

/// The arguments of `spinball section`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "Outputs: `--csv` has the header `orbit,s,sin_theta,v_par,speed,u,wall,q` (one row per collision); `--npy` is (points, 8) in that order; `--json` holds the same columns as arrays. Without a file, the CSV goes to stdout."
)]
pub struct SectionArgs {
    #[command(flatten)]
    pub phase: PhaseArgs,
    /// Orbits (starts `0..ORBITS` of the seed's streams), 1..=1000000.
    #[arg(long, default_value_t = SectionDefaults::ORBITS, value_parser = clap::value_parser!(u64).range(1..=1_000_000))]
    pub orbits: u64,
    /// Collisions per orbit, 1..=100000000.
    #[arg(long, default_value_t = SectionDefaults::COLLISIONS, value_parser = clap::value_parser!(u64).range(1..=100_000_000))]
    pub collisions: u64,
    /// How the orbits start.
    #[arg(long, value_enum, default_value_t = StartsArg::Paper)]
    pub sampler: StartsArg,
    /// Keep only the points with |√α u| < W (0 < W; the shell has
    /// |√α u| ≤ 1): the slice of the section near zero spin.
    #[arg(long, value_name = "W", value_parser = parse_half_width)]
    pub spin_slice: Option<f64>,
    /// Run only shard K of N (0-based, `K/N`): a block of the orbits; the
    /// partial section goes to --json, for `spinball merge`.
    #[arg(long)]
    pub shard: Option<Shard>,
    #[command(flatten)]
    pub out: OutputArgs,
    /// Draw the section to this PNG, 1200 × 800 px: the points (s, sin θ)
    /// coloured by the spin u, with a colour bar (checked before the run;
    /// with --png and no other file nothing goes to stdout).
    #[arg(long)]
    pub png: Option<PathBuf>,
}

/// Parse `--spin-slice`: a finite number > 0.
fn parse_half_width(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(w) if w.is_finite() && w > 0.0 => Ok(w),
        _ => Err(
            "the slice's half-width must be a finite number > 0 (|√α u| ≤ 1 on the shell)".into(),
        ),
    }
}

/// The rows of `doc`'s points in the order of [`SECTION_COLUMNS`].
fn rows_of(doc: &SectionDocument) -> Vec<[f64; 8]> {
    let columns: Vec<&[f64]> = SECTION_COLUMNS
        .iter()
        .map(|name| doc.columns.get(*name).map_or(&[][..], Vec::as_slice))
        .collect();
    let n = columns.iter().map(|c| c.len()).min().unwrap_or(0);
    (0..n)
        .map(|i| std::array::from_fn(|k| columns[k][i]))
        .collect()
}

/// Write the finished section `doc` to the outputs asked for (its CSV to
/// stdout if none) and print a summary unless quiet: the one way a whole
/// run and `spinball merge` write a section.
///
/// # Errors
/// [`CliError::Failed`] for an output that cannot be written.
pub fn write_section(doc: &SectionDocument, out: &OutputArgs) -> Result<(), CliError> {
    let rows = rows_of(doc);
    let csv = || csv_rows(&SECTION_COLUMNS, &rows);
    if !out.any_file() {
        return print(&csv());
    }
    out.write(
        || Document::Section(doc.clone()),
        csv,
        || {
            (
                vec![rows.len() as u64, SECTION_COLUMNS.len() as u64],
                rows.iter().flatten().copied().collect(),
            )
        },
    )?;
    if out.quiet {
        return Ok(());
    }
    print(&format!(
        "{} points of {} orbits × {} collisions at α = {}\n",
        rows.len(),
        doc.orbits,
        doc.collisions,
        doc.head.alpha
    ))
}

/// `spinball section`.
///
/// # Errors
/// [`CliError::Usage`] for a bad table, α or option; [`CliError::Failed`]
/// if an orbit fails or an output cannot be written.
pub fn section(args: &SectionArgs) -> Result<(), CliError> {
    let p = &args.phase;
    let (table, law, threads) = p.setup()?;
    let shard = args.shard.unwrap_or(Shard::WHOLE);
    let shard_path = args.out.shard_path(shard)?;
    args.out.check()?;
    if let Some(path) = &args.png {
        check_whole_png(
            path,
            shard,
            "section: a shard holds only some of its orbits",
        )?;
    }
    let billiard = Billiard::new(table, law);
    let sampler = match args.sampler {
        StartsArg::Paper => Some(Sampler::Paper),
        StartsArg::Microcanonical => Some(Sampler::Microcanonical),
        StartsArg::Invariant => None,
    };
    let seed = p.seed;
    let starts = shard.range(0..args.orbits);
    let orbits = match sampler {
        Some(sampler) => sampled_sections(
            &billiard,
            sampler,
            seed,
            starts.clone(),
            args.collisions,
            threads,
        ),
        None => invariant_starts(billiard.table(), &law, seed, starts.clone())
            .and_then(|s| sections(&billiard, &s, args.collisions, threads)),
    }
    .map_err(|e| match e {
        AnalysisError::InvalidOption { .. } | AnalysisError::NoRoom(_) => CliError::usage(e),
        e => CliError::failed(e),
    })?;
    let alpha = law.alpha();
    let rows = match args.spin_slice {
        Some(w) => section_rows(&orbits, starts.start, |q| q.w(alpha).abs() < w),
        None => section_rows(&orbits, starts.start, |_| true),
    };
    let columns = SECTION_COLUMNS
        .iter()
        .enumerate()
        .map(|(k, name)| {
            let values: Vec<f64> = rows.iter().map(|r| r[k]).collect();
            ((*name).to_string(), values)
        })
        .collect();
    let doc = SectionDocument {
        head: PhaseHead::new(billiard.table(), &law),
        sampler: args.sampler.name().into(),
        seed,
        orbits: args.orbits,
        collisions: args.collisions,
        spin_slice: args.spin_slice,
        columns,
    };
    let Some(path) = shard_path else {
        if let Some(png) = &args.png {
            let title = format!(
                "{} at α = {alpha}: {} orbits × {} collisions",
                billiard.table(),
                args.orbits,
                args.collisions
            );
            let points = rows.iter().map(|r| (r[1], r[2], r[5])).collect();
            section_png(png, title, billiard.table().perimeter(), points)?;
            if !args.out.any_file() {
                return Ok(());
            }
        }
        return write_section(&doc, &args.out);
    };
    let done = format!("orbits {starts:?} of {}", args.orbits);
    let part = Document::SectionPartial(SectionPartialDocument {
        shard,
        starts,
        section: doc,
    });
    args.out.write_shard(path, &part, shard, &done)
}
