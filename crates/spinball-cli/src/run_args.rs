//! The options every ensemble command shares: what to run (table, α,
//! initial conditions, collisions, method) and how (engine, threads, shard).

use clap::{Args, ValueEnum};
use spinball_analysis::estimators::{Method, PAPER_DELTA0};
use spinball_analysis::run::{Engine, Ensemble, RunDefaults, Shard, Threads};
use spinball_core::{Sampler, SpinLaw, SpinLawError};
use spinball_geometry::Built;

use crate::error::CliError;
use crate::table_arg::read_table;

/// How exponents are measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    /// Exact tangent dynamics.
    Tangent,
    /// The paper's finite-difference Benettin method (`--delta0`).
    Fd,
}

impl MethodArg {
    /// The option's value: `tangent` or `fd`.
    pub fn name(self) -> &'static str {
        match self {
            MethodArg::Tangent => "tangent",
            MethodArg::Fd => "fd",
        }
    }
}

impl From<Method> for MethodArg {
    fn from(m: Method) -> Self {
        match m {
            Method::Tangent => MethodArg::Tangent,
            Method::FiniteDifference { .. } => MethodArg::Fd,
        }
    }
}

/// Which engine runs the trajectories.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum EngineArg {
    /// Vector-lane kernels where the table has a lane form (default).
    Lanes,
    /// One trajectory at a time.
    Scalar,
}

impl From<Engine> for EngineArg {
    fn from(e: Engine) -> Self {
        match e {
            Engine::Lanes => EngineArg::Lanes,
            Engine::Scalar => EngineArg::Scalar,
        }
    }
}

/// How initial conditions are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SamplerArg {
    /// The paper's sampler.
    Paper,
    /// Uniform on the energy shell.
    Microcanonical,
}

impl From<Sampler> for SamplerArg {
    fn from(s: Sampler) -> Self {
        match s {
            Sampler::Paper => SamplerArg::Paper,
            Sampler::Microcanonical => SamplerArg::Microcanonical,
        }
    }
}

impl From<SamplerArg> for Sampler {
    fn from(s: SamplerArg) -> Self {
        match s {
            SamplerArg::Paper => Sampler::Paper,
            SamplerArg::Microcanonical => Sampler::Microcanonical,
        }
    }
}

/// Parse `--threads`: a whole number in `1..=`[`Threads::MAX`], checked
/// before any thread is made.
///
/// # Errors
/// The range that works, for anything else.
pub fn parse_threads(s: &str) -> Result<usize, String> {
    let range = format!(
        "the thread count must be a whole number in 1..={} (results do not depend on it; leave --threads out to use all cores)",
        Threads::MAX
    );
    match s.trim().parse::<usize>() {
        Ok(n) if (1..=Threads::MAX).contains(&n) => Ok(n),
        _ => Err(range),
    }
}

/// What to run and how.
#[derive(Debug, Clone, Args)]
pub struct RunArgs {
    /// The table: a built-in spec (`stadium:a=1`, `sinai:L=2,R=1`, `circle`,
    /// `rectangle:L=1,H=1`) or a table file (`.toml` or `.json`, see
    /// docs/TABLE_FILES.md).
    #[arg(long)]
    pub table: String,
    /// Spin parameters α = I/(m r²), comma-separated (in [0, 1] unless
    /// --extended).
    #[arg(
        long,
        value_delimiter = ',',
        required = true,
        allow_negative_numbers = true
    )]
    pub alpha: Vec<f64>,
    /// Allow α > 1 (the mathematical extension of the law).
    #[arg(long)]
    pub extended: bool,
    /// Initial conditions per α (indices 0..ICS of the seed's streams).
    #[arg(long, default_value_t = RunDefaults::ICS)]
    pub ics: u64,
    /// Collisions per initial condition.
    #[arg(long, default_value_t = RunDefaults::COLLISIONS)]
    pub collisions: u64,
    /// How exponents are measured.
    #[arg(long, value_enum, default_value_t = RunDefaults::METHOD.into())]
    pub method: MethodArg,
    /// Initial separation of the finite-difference method.
    #[arg(long, default_value_t = PAPER_DELTA0)]
    pub delta0: f64,
    /// Seed of the initial conditions.
    #[arg(long, default_value_t = RunDefaults::SEED)]
    pub seed: u64,
    /// How initial conditions are drawn.
    #[arg(long, value_enum, default_value_t = RunDefaults::SAMPLER.into())]
    pub sampler: SamplerArg,
    /// FTLE above which a trajectory counts as chaotic.
    #[arg(long, default_value_t = RunDefaults::THRESHOLD)]
    pub threshold: f64,
    /// Engine.
    #[arg(long, value_enum, default_value_t = RunDefaults::ENGINE.into())]
    pub engine: EngineArg,
    /// Worker threads, 1..=1024 (default: all cores); results do not
    /// depend on it.
    #[arg(long, value_name = "T", value_parser = parse_threads)]
    pub threads: Option<usize>,
    /// Run only shard K of N (0-based, `K/N`): a contiguous block of the
    /// initial conditions; the output is a partial result for `spinball merge`.
    #[arg(long)]
    pub shard: Option<Shard>,
}

impl RunArgs {
    /// The method with its δ0.
    pub fn method(&self) -> Method {
        match self.method {
            MethodArg::Tangent => Method::Tangent,
            MethodArg::Fd => Method::FiniteDifference {
                delta0: self.delta0,
            },
        }
    }

    /// The shard (the whole range if none was asked for).
    pub fn shard(&self) -> Shard {
        self.shard.unwrap_or(Shard::WHOLE)
    }

    /// The spin laws, one per α.
    ///
    /// # Errors
    /// [`CliError::Usage`] for an α the law rejects.
    pub fn laws(&self) -> Result<Vec<SpinLaw>, CliError> {
        self.alpha
            .iter()
            .map(|&a| {
                let law = if self.extended {
                    SpinLaw::extended(a)
                } else {
                    SpinLaw::new(a)
                };
                law.map_err(|e| match e {
                    SpinLawError::Unphysical(_) => CliError::Usage(format!(
                        "--alpha {a}: outside [0, 1]; pass --extended to allow it"
                    )),
                    e => CliError::Usage(format!("--alpha {a}: {e}")),
                })
            })
            .collect()
    }

    /// One ensemble per α over this shard's initial conditions, validated.
    ///
    /// # Errors
    /// [`CliError::Usage`] for a table, α or option that cannot work.
    pub fn ensembles(&self) -> Result<Vec<Ensemble<Built>>, CliError> {
        let table = read_table(&self.table)?;
        if self.ics < 2 {
            return Err(CliError::Usage(format!(
                "--ics {}: an estimate needs at least 2 initial conditions",
                self.ics
            )));
        }
        let indices = self.shard().range(0..self.ics);
        let threads = match self.threads {
            None => RunDefaults::THREADS,
            Some(n) => Threads::Fixed(n),
        };
        let ensembles: Vec<Ensemble<Built>> = self
            .laws()?
            .into_iter()
            .map(|law| {
                Ensemble::new(table.clone(), law)
                    .with_sampler(self.sampler.into())
                    .with_seed(self.seed)
                    .with_indices(indices.clone())
                    .with_collisions(self.collisions)
                    .with_method(self.method())
                    .with_threshold(self.threshold)
                    .with_engine(match self.engine {
                        EngineArg::Lanes => Engine::Lanes,
                        EngineArg::Scalar => Engine::Scalar,
                    })
                    .with_threads(threads)
            })
            .collect();
        for e in &ensembles {
            // A shard may hold fewer than two initial conditions; the
            // merged run may not (checked above).
            e.validate_settings().map_err(CliError::usage)?;
        }
        Ok(ensembles)
    }

    /// The options a job must repeat to run the same ensembles (all but the
    /// table, α, threads and shard), as command-line words.
    pub fn options_for_jobs(&self) -> Vec<String> {
        let mut words = vec![
            format!("--ics {}", self.ics),
            format!("--collisions {}", self.collisions),
            format!(
                "--method {}",
                self.method
                    .to_possible_value()
                    .map_or_else(String::new, |v| v.get_name().to_string())
            ),
            format!("--delta0 {}", self.delta0),
            format!("--seed {}", self.seed),
            format!(
                "--sampler {}",
                self.sampler
                    .to_possible_value()
                    .map_or_else(String::new, |v| v.get_name().to_string())
            ),
            format!("--threshold {}", self.threshold),
            format!(
                "--engine {}",
                self.engine
                    .to_possible_value()
                    .map_or_else(String::new, |v| v.get_name().to_string())
            ),
        ];
        if self.extended {
            words.push("--extended".into());
        }
        words
    }
}
