//! `spinball spectrum`: the full Lyapunov spectrum (five exponents) of an
//! ensemble, at one α or a list.

use clap::Args;
use serde::Serialize;
use spinball_analysis::{SpectrumEstimate, SpectrumOptions, spectrum_ensemble};
use spinball_core::Billiard;

use crate::documents::write_json;
use crate::error::CliError;
use crate::output::{OutputArgs, write_npy, write_text};
use crate::run_args::RunArgs;

/// The arguments of `spinball spectrum`.
#[derive(Debug, Clone, Args)]
pub struct SpectrumArgs {
    #[command(flatten)]
    pub run: RunArgs,
    /// Re-orthonormalise the tangent vectors every this many collisions.
    #[arg(long, default_value_t = 1)]
    pub qr_interval: u32,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The JSON of `spinball spectrum`.
#[derive(Debug, Clone, Serialize)]
struct SpectrumDocument {
    kind: &'static str,
    table: String,
    alphas: Vec<f64>,
    points: Vec<SpectrumEstimate>,
}

/// `spinball spectrum`.
///
/// # Errors
/// [`CliError::Usage`] for bad options (and `--shard`, which the spectrum
/// does not take yet); [`CliError::Failed`] for a failed trajectory.
pub fn spectrum(args: &SpectrumArgs) -> Result<(), CliError> {
    let run = &args.run;
    if run.shard.is_some() {
        return Err(CliError::Usage(
            "spinball spectrum runs whole ensembles; --shard is for lyapunov and ftle".into(),
        ));
    }
    let ensembles = run.ensembles()?;
    let mut options = SpectrumOptions::new(run.collisions, run.method());
    options.qr_interval = args.qr_interval;
    let mut points = Vec::new();
    for e in &ensembles {
        let billiard = Billiard::new(e.table.clone(), e.law);
        let sampler = e.sampler().unwrap_or_default();
        let est = spectrum_ensemble(&billiard, sampler, e.seed, e.indices.clone(), &options, e.threads)
            .map_err(|err| match err {
                spinball_analysis::AnalysisError::InvalidOption { .. } => CliError::usage(err),
                err => CliError::failed(err),
            })?;
        points.push(est);
    }
    if !args.out.quiet {
        println!("{:>10}  {:>11} {:>11} {:>11} {:>11} {:>11}", "alpha", "l1", "l2", "l3", "l4", "l5");
        for (e, p) in ensembles.iter().zip(&points) {
            let m = p.mean;
            println!(
                "{:>10}  {:>11.6} {:>11.6} {:>11.6} {:>11.6} {:>11.6}",
                e.alpha(),
                m[0],
                m[1],
                m[2],
                m[3],
                m[4]
            );
        }
    }
    let alphas: Vec<f64> = ensembles.iter().map(|e| e.alpha()).collect();
    if let Some(path) = &args.out.json {
        let doc = SpectrumDocument {
            kind: "spinball.spectrum",
            table: ensembles[0].table.to_string(),
            alphas: alphas.clone(),
            points: points.clone(),
        };
        write_json(path, &doc)?;
    }
    if let Some(path) = &args.out.csv {
        let mut csv = String::from("alpha,l1,l2,l3,l4,l5,sem1,sem2,sem3,sem4,sem5,n_ics\n");
        for (a, p) in alphas.iter().zip(&points) {
            let v: Vec<String> = p.mean.iter().chain(&p.sem).map(f64::to_string).collect();
            csv.push_str(&format!("{a},{},{}\n", v.join(","), p.n_ics));
        }
        write_text(path, &csv)?;
    }
    if let Some(path) = &args.out.npy {
        let n = points[0].spectra.len() as u64;
        let values: Vec<f64> = points
            .iter()
            .flat_map(|p| p.spectra.iter().flat_map(|s| s.exponents))
            .collect();
        write_npy(path, &[points.len() as u64, n, 5], &values)?;
    }
    Ok(())
}
