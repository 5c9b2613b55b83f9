//! `spinball spectrum`: the full Lyapunov spectrum (five exponents) of an
//! ensemble, at one α or a list, whole or one shard at a time.

use clap::Args;
use spinball_analysis::AnalysisError;
use spinball_analysis::estimators::SpectrumOptions;
use spinball_analysis::report::{Document, SpectrumDocument, csv_text};
use spinball_analysis::run::{SpectrumDefaults, TableRecord, spectrum_ensemble};
use spinball_core::Billiard;

use crate::documents::write_document;
use crate::error::CliError;
use crate::output::{OutputArgs, write_npy, write_text};
use crate::run_args::RunArgs;
use crate::stdout::print;

/// The arguments of `spinball spectrum`.
#[derive(Debug, Clone, Args)]
pub struct SpectrumArgs {
    #[command(flatten)]
    pub run: RunArgs,
    /// Re-orthonormalise the tangent vectors every this many collisions.
    #[arg(long, default_value_t = SpectrumDefaults::QR_INTERVAL)]
    pub qr_interval: u32,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// Write the finished spectra to every output asked for, and print
/// them unless quiet.
///
/// # Errors
/// [`CliError::Failed`] for an output that cannot be written.
pub fn write_spectrum(doc: &SpectrumDocument, out: &OutputArgs) -> Result<(), CliError> {
    let shown = if out.quiet {
        Ok(())
    } else {
        let mut table = format!(
            "{:>10}  {:>11} {:>11} {:>11} {:>11} {:>11}\n",
            "alpha", "l1", "l2", "l3", "l4", "l5"
        );
        for (a, p) in doc.alphas.iter().zip(&doc.points) {
            let m = p.mean;
            table.push_str(&format!(
                "{a:>10}  {:>11.6} {:>11.6} {:>11.6} {:>11.6} {:>11.6}\n",
                m[0], m[1], m[2], m[3], m[4]
            ));
        }
        print(&table)
    };
    // The files are written even if stdout failed: they are the result.
    if let Some(path) = &out.json {
        write_document(path, &Document::Spectrum(doc.clone()), false)?;
    }
    if let Some(path) = &out.csv {
        let csv = csv_text(&doc.rows()).map_err(CliError::failed)?;
        write_text(path, &csv)?;
    }
    if let Some(path) = &out.npy {
        let n = doc.points.first().map_or(0, |p| p.spectra.len()) as u64;
        let values: Vec<f64> = doc
            .points
            .iter()
            .flat_map(|p| p.spectra.iter().flat_map(|s| s.exponents))
            .collect();
        write_npy(path, &[doc.points.len() as u64, n, 5], &values)?;
    }
    shown
}

/// `spinball spectrum`.
///
/// # Errors
/// [`CliError::Usage`] for bad options; [`CliError::Failed`] for a failed
/// trajectory.
pub fn spectrum(args: &SpectrumArgs) -> Result<(), CliError> {
    let run = &args.run;
    let ensembles = run.ensembles()?;
    let sharded = run.shard().count > 1;
    if sharded && args.out.json.is_none() {
        return Err(CliError::Usage(
            "--shard needs --json: the partial result goes there for `spinball merge`".into(),
        ));
    }
    args.out.check()?;
    let mut options = SpectrumOptions::new(run.collisions, run.method());
    options.qr_interval = args.qr_interval;
    let mut points = Vec::new();
    for e in &ensembles {
        let billiard = Billiard::new(e.table.clone(), e.law);
        let sampler = e.sampler().unwrap_or_default();
        let est = spectrum_ensemble(
            &billiard,
            sampler,
            e.seed,
            e.indices.clone(),
            &options,
            e.threads,
        )
        .map_err(|err| match err {
            AnalysisError::InvalidOption { .. } if sharded => CliError::Usage(format!(
                "{err} (every spectrum shard needs at least 2 initial conditions: use fewer shards)"
            )),
            AnalysisError::InvalidOption { .. } => CliError::usage(err),
            err => CliError::failed(err),
        })?;
        points.push(est);
    }
    let doc = SpectrumDocument::new(
        TableRecord::of(&ensembles[0].table),
        ensembles.iter().map(|e| e.alpha()).collect(),
        run.shard,
        0..run.ics,
        points,
    );
    if sharded {
        let path = args.out.json.as_ref().expect("checked above");
        write_document(path, &Document::SpectrumPartial(doc), false)?;
        if !args.out.quiet {
            print(&format!(
                "shard {}: wrote {} (combine the shards with `spinball merge`)\n",
                run.shard(),
                path.display()
            ))?;
        }
        return Ok(());
    }
    write_spectrum(&doc, &args.out)
}
