//! `spinball kac`: mean return times to a region of the section, orbit by
//! orbit from the invariant measure, against Kac's lemma `1/μ(A)`.

use clap::Args;
use spinball_analysis::AnalysisError;
use spinball_analysis::estimators::PlusMinus;
use spinball_analysis::phase_space::{SectionBox, kac_part};
use spinball_analysis::report::{Document, KacDocument, KacPartialDocument};
use spinball_analysis::run::{KacDefaults, Shard};
use spinball_core::Billiard;

use crate::error::CliError;
use crate::output::OutputArgs;
use crate::phase_args::{PhaseArgs, parse_range};
use crate::stdout::print;

/// The arguments of `spinball kac`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "Outputs: `--csv` has `index,collisions,visits,mean_return,ratio` per orbit (empty mean and ratio for an orbit with fewer than two visits); `--npy` is (orbits, 4) float64: index, visits, mean return, ratio (NaN without a return); `--json` the whole comparison."
)]
pub struct KacArgs {
    #[command(flatten)]
    pub phase: PhaseArgs,
    /// The region's arc lengths `LO,HI` (s in [LO, HI), within the
    /// perimeter; e.g. the stadium's right cap is `2,5.14159`).
    #[arg(long, value_name = "LO,HI", value_parser = parse_range, allow_hyphen_values = true)]
    pub s: (f64, f64),
    /// The region's `v∥/|V|` range `LO,HI` (default −1,1: every velocity).
    #[arg(long, value_name = "LO,HI", value_parser = parse_range, allow_hyphen_values = true)]
    pub v_par: Option<(f64, f64)>,
    /// The region's `√α u/|V|` range `LO,HI` (default: every spin); at
    /// α = 0 it must contain 0.
    #[arg(long, value_name = "LO,HI", value_parser = parse_range, allow_hyphen_values = true)]
    pub w: Option<(f64, f64)>,
    /// Orbits, started from the invariant measure (streams `0..ORBITS` of
    /// the seed), 2..=10000000.
    #[arg(long, default_value_t = KacDefaults::ORBITS, value_parser = clap::value_parser!(u64).range(2..=10_000_000))]
    pub orbits: u64,
    /// Collisions per orbit, 1..=10000000000.
    #[arg(long, default_value_t = KacDefaults::COLLISIONS, value_parser = clap::value_parser!(u64).range(1..=10_000_000_000))]
    pub collisions: u64,
    /// Run only shard K of N (0-based, `K/N`): a block of the orbits; the
    /// partial result goes to --json, for `spinball merge`.
    #[arg(long)]
    pub shard: Option<Shard>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// `spinball kac`.
///
/// # Errors
/// [`CliError::Usage`] for a bad table, α, region or option;
/// [`CliError::Failed`] if an orbit fails or an output cannot be written.
pub fn kac(args: &KacArgs) -> Result<(), CliError> {
    let p = &args.phase;
    let (table, law, threads) = p.setup()?;
    let shard = args.shard.unwrap_or(Shard::WHOLE);
    let shard_path = args.out.shard_path(shard)?;
    args.out.check()?;
    let (v0, v1) = args.v_par.unwrap_or((-1.0, 1.0));
    let mut region = SectionBox::new(args.s.0..args.s.1, v0..v1);
    if let Some((w0, w1)) = args.w {
        region = region.with_w(w0..w1);
    }
    let billiard = Billiard::new(table, law);
    let part = kac_part(
        &billiard,
        &region,
        args.orbits,
        args.collisions,
        p.seed,
        threads,
        shard,
    )
    .map_err(|e| match e {
        AnalysisError::InvalidOption { .. } => CliError::usage(e),
        e => CliError::failed(e),
    })?;
    let Some(path) = shard_path else {
        let doc = KacPartialDocument::merge(vec![KacPartialDocument { part }])
            .map_err(CliError::failed)?;
        return write_kac(&doc, &args.out);
    };
    let done = format!("orbits {:?} of {}", part.starts, args.orbits);
    let doc = Document::KacPartial(KacPartialDocument { part });
    args.out.write_shard(path, &doc, shard, &done)
}

/// Write the finished comparison `doc` to the outputs asked for and print
/// a summary unless quiet: the one way a whole run and `spinball merge`
/// write it.
///
/// # Errors
/// [`CliError::Failed`] for an output that cannot be written.
pub fn write_kac(doc: &KacDocument, out: &OutputArgs) -> Result<(), CliError> {
    let kac = &doc.comparison;
    let rows: Vec<[f64; 4]> = kac
        .orbits
        .iter()
        .map(|o| {
            let m = o.mean_return.unwrap_or(f64::NAN);
            [o.index as f64, o.visits as f64, m, m / kac.expected]
        })
        .collect();
    let csv = || {
        let mut out = String::from("index,collisions,visits,mean_return,ratio\n");
        for o in &kac.orbits {
            let (m, r) = o.mean_return.map_or((String::new(), String::new()), |m| {
                (m.to_string(), (m / kac.expected).to_string())
            });
            out.push_str(&format!(
                "{},{},{},{m},{r}\n",
                o.index, o.collisions, o.visits
            ));
        }
        out
    };
    let npy = || {
        (
            vec![rows.len() as u64, 4],
            rows.iter().flatten().copied().collect(),
        )
    };
    out.write(|| Document::Kac(doc.clone()), csv, npy)?;
    if out.quiet {
        return Ok(());
    }
    let ratio = kac
        .ratio()
        .map_or("-".into(), |r| PlusMinus::new(r.value, r.sem).to_string());
    print(&format!(
        "α = {}: μ(A) = {:.6}, Kac 1/μ(A) = {:.4}, mean return / Kac = {ratio}, never returned {} of {}\n",
        kac.alpha,
        kac.probability,
        kac.expected,
        kac.never_returned,
        kac.orbits.len()
    ))
}
