//! `spinball section`: the Birkhoff section of a few orbits, every
//! collision as a point `(s, sin θ, v∥, |v|, u, wall, Q)`.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use spinball_analysis::AnalysisError;
use spinball_analysis::phase_space::{
    SECTION_COLUMNS, invariant_starts, sampled_sections, section_rows, sections,
};
use spinball_analysis::report::{Document, PhaseHead, SectionDocument};
use spinball_core::{Billiard, Sampler};
use spinball_geometry::Boundary;

use crate::error::CliError;
use crate::phase_args::{PhaseArgs, PhaseOutput, csv_rows};
use crate::pictures::{check_png, section_png};
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
    #[arg(long, default_value_t = 8, value_parser = clap::value_parser!(u64).range(1..=1_000_000))]
    pub orbits: u64,
    /// Collisions per orbit, 1..=100000000.
    #[arg(long, default_value_t = 1000, value_parser = clap::value_parser!(u64).range(1..=100_000_000))]
    pub collisions: u64,
    /// How the orbits start.
    #[arg(long, value_enum, default_value_t = StartsArg::Paper)]
    pub sampler: StartsArg,
    /// Keep only the points with |√α u| < W (0 < W; the shell has
    /// |√α u| ≤ 1): the slice of the section near zero spin.
    #[arg(long, value_name = "W", value_parser = parse_half_width)]
    pub spin_slice: Option<f64>,
    #[command(flatten)]
    pub out: PhaseOutput,
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

/// `spinball section`.
///
/// # Errors
/// [`CliError::Usage`] for a bad table, α or option; [`CliError::Failed`]
/// if an orbit fails or an output cannot be written.
pub fn section(args: &SectionArgs) -> Result<(), CliError> {
    let p = &args.phase;
    let (table, law, threads) = p.setup()?;
    args.out.check()?;
    if let Some(path) = &args.png {
        check_png(path)?;
    }
    let billiard = Billiard::new(table, law);
    let sampler = match args.sampler {
        StartsArg::Paper => Some(Sampler::Paper),
        StartsArg::Microcanonical => Some(Sampler::Microcanonical),
        StartsArg::Invariant => None,
    };
    let (n, seed) = (args.orbits, p.seed);
    let orbits = match sampler {
        Some(sampler) => sampled_sections(&billiard, sampler, seed, n, args.collisions, threads),
        None => invariant_starts(billiard.table(), &law, seed, 0..n)
            .and_then(|starts| sections(&billiard, &starts, args.collisions, threads)),
    }
    .map_err(|e| match e {
        AnalysisError::InvalidOption { .. } | AnalysisError::NoRoom(_) => CliError::usage(e),
        e => CliError::failed(e),
    })?;
    let alpha = law.alpha();
    let rows = match args.spin_slice {
        Some(w) => section_rows(&orbits, |q| q.w(alpha).abs() < w),
        None => section_rows(&orbits, |_| true),
    };
    let csv = || csv_rows(&SECTION_COLUMNS, &rows);
    if let Some(path) = &args.png {
        let title = format!(
            "{} at α = {alpha}: {} orbits × {} collisions",
            billiard.table(),
            args.orbits,
            args.collisions
        );
        let points = rows.iter().map(|r| (r[1], r[2], r[5])).collect();
        section_png(path, title, billiard.table().perimeter(), points)?;
    }
    if !args.out.any_file() && args.png.is_none() {
        return print(&csv());
    }
    let columns = SECTION_COLUMNS
        .iter()
        .enumerate()
        .map(|(k, name)| {
            let values: Vec<f64> = rows.iter().map(|r| r[k]).collect();
            ((*name).to_string(), values)
        })
        .collect();
    let doc = || {
        Document::Section(SectionDocument {
            head: PhaseHead::new(billiard.table(), &law),
            sampler: args.sampler.name().into(),
            seed: p.seed,
            orbits: args.orbits,
            collisions: args.collisions,
            spin_slice: args.spin_slice,
            columns,
        })
    };
    args.out.write(doc, csv, || {
        (
            vec![rows.len() as u64, SECTION_COLUMNS.len() as u64],
            rows.iter().flatten().copied().collect(),
        )
    })?;
    if args.out.quiet {
        return Ok(());
    }
    print(&format!(
        "{} points of {} orbits × {} collisions at α = {alpha}\n",
        rows.len(),
        args.orbits,
        args.collisions
    ))
}
