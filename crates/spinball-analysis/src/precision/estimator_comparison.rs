//! Plain against multilevel at one target: the processor time each
//! estimator spends to reach the same stated total error on one scene, how
//! far each lands from an independent reference, what the planner chose and
//! what its choice cost, and the prediction for smaller targets from the
//! measured level variances and costs. It is the measurement behind the
//! multilevel column of docs/ACCURACY.md.
//!
//! Documented in the group docs (`precision/mod.rs`), section "Multilevel
//! ensembles".

use std::fmt;
use std::ops::Range;
use std::time::Instant;

use spinball_geometry::Boundary;

use super::ensemble_levels::{EnsembleLevels, default_levels};
use super::estimator_choice::{EstimatorKind, EstimatorPlan};
use super::measurement::Measurement;
use super::multilevel::LevelStats;
use super::multilevel_estimate::MultilevelEstimate;
use super::planner::{PlannedRun, Planner};
use crate::error::AnalysisError;
use crate::run::Ensemble;

/// Processor seconds this process has used so far, all threads, user and
/// system (`/proc/self/stat`, in clock ticks of 1/100 s); `None` where that
/// file does not exist (off Linux). On a machine shared with other work the
/// processor time of a run moves far less than its wall time.
#[must_use]
pub fn process_cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // The fields after the command name, which may hold spaces, in parentheses.
    let rest = stat.get(stat.rfind(')')? + 2..)?;
    let fields: Vec<&str> = rest.split(' ').collect();
    let utime: f64 = fields.get(11)?.parse().ok()?;
    let stime: f64 = fields.get(12)?.parse().ok()?;
    Some((utime + stime) / 100.0)
}

/// Processor seconds `f` takes (its wall seconds where processor time
/// cannot be read), with its result.
fn timed<T>(f: impl FnOnce() -> T) -> (T, f64, f64) {
    let (cpu, wall) = (process_cpu_seconds(), Instant::now());
    let out = f();
    let wall = wall.elapsed().as_secs_f64();
    let cpu = process_cpu_seconds().zip(cpu).map_or(wall, |(b, a)| b - a);
    (out, cpu, wall)
}

/// One estimator's run toward a target: what it cost and what it gave.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct EstimatorRun {
    /// Plain or multilevel.
    pub kind: EstimatorKind,
    /// Seed of the run's initial conditions.
    pub seed: u64,
    /// Run length of the (top-level) trajectories.
    pub collisions: u64,
    /// Initial conditions, summed over the levels.
    pub ics: u64,
    /// Work, IC-steps (summed over the levels).
    pub ic_steps: f64,
    /// Processor seconds of the run, all threads ([`process_cpu_seconds`]).
    pub cpu_s: f64,
    /// Wall-clock seconds of the run.
    pub wall_s: f64,
    /// `λ_T` at the run length with its SEM.
    pub value: Measurement,
    /// The stated total error (absolute): SEM and biases in quadrature.
    pub total: f64,
    /// `λ_T − λ_ref` against the reference, with the stated total error
    /// and the reference's SEM in quadrature as its standard error.
    pub deviation: Measurement,
}

impl EstimatorRun {
    /// The stated total error relative to `|λ_T|`.
    #[must_use]
    pub fn rel_total(&self) -> f64 {
        self.total / self.value.value.abs()
    }

    /// `(λ_T − λ_ref) / (total ⊕ σ_ref)`: within about ±2 where the stated
    /// error is honest.
    #[must_use]
    pub fn pull(&self) -> f64 {
        self.deviation.value / self.deviation.sem
    }

    /// The processor time scaled to a stated relative total error of
    /// exactly `target_rel`, `cpu · (error/target)²` (both estimators'
    /// work goes like `1/error²` at a fixed run length): the time to
    /// compare at equal error.
    #[must_use]
    pub fn cpu_at_target(&self, target_rel: f64) -> f64 {
        self.cpu_s * (self.rel_total() / target_rel).powi(2)
    }

    /// Processor seconds per IC-step.
    #[must_use]
    pub fn cpu_per_step(&self) -> f64 {
        self.cpu_s / self.ic_steps
    }
}

/// Median of `values` (NaN for none).
fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    match n {
        0 => f64::NAN,
        _ if n % 2 == 1 => values[n / 2],
        _ => 0.5 * (values[n / 2 - 1] + values[n / 2]),
    }
}

/// Plain and multilevel runs of one scene toward one target, repeated on
/// several seeds in alternating order ([`compare_estimators`]).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct EstimatorComparison {
    /// The target relative total error.
    pub target_rel: f64,
    /// The independent reference `λ_ref ± SEM`.
    pub reference: Measurement,
    /// The planner's choice, with both plans and its reason.
    pub choice: EstimatorPlan,
    /// Processor seconds of that choice (the plain plan and the pilot of
    /// the multilevel levels; the method pilot both share is not counted).
    pub choice_cpu_s: f64,
    /// The plain runs, one per seed.
    pub plain: Vec<EstimatorRun>,
    /// The multilevel runs, one per seed (none where the plain run is too
    /// short for four levels).
    pub multilevel: Vec<EstimatorRun>,
    /// The first multilevel run's estimate: its levels' variances `V_l`,
    /// costs and the bias fit.
    pub levels: Option<MultilevelEstimate>,
}

/// How many times a multilevel run may lengthen its levels fourfold when
/// its own bias fit finds the bias at the top level above the target.
const MAX_LENGTHENINGS: u32 = 2;

/// Plain against multilevel on `scene` (its table, law, sampler, threads;
/// the seed is replaced by each of `seeds`) at relative total error
/// `target_rel`, measured against `reference` (an independent value of
/// `λ`, e.g. a [`Reference`](crate::precision::Reference)'s).
///
/// The planner chooses ([`Planner::plan_estimator`], with pilots of
/// `ml_pilot_ics` per level), then each seed runs both estimators in
/// alternating order (multilevel first on even repeats): the multilevel
/// plan adaptively; where its level fit finds the bias at the top level
/// above the target (the method pilot saw only short runs) its levels are
/// lengthened fourfold, at most twice. The plain run then uses the same
/// top run length and the same bias (the multilevel fit's, counted at
/// `√(b² + σ_b²)`, where it is larger than the pilot's), and stops on the
/// total error ([`PlannedRun::stop_rule`]): the two aim at equal stated
/// total error with equal bias, so their times compare at equal error.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for an empty `seeds` or a reference
/// that is not finite and non-zero; as [`Planner::plan_estimator`] and the
/// runs.
pub fn compare_estimators<B: Boundary + Clone + Sync>(
    scene: &Ensemble<B>,
    planner: &Planner,
    reference: Measurement,
    target_rel: f64,
    ml_pilot_ics: u64,
    seeds: Range<u64>,
) -> Result<EstimatorComparison, AnalysisError> {
    if seeds.is_empty() {
        return Err(AnalysisError::invalid("seeds", "need at least one seed"));
    }
    if !(reference.value.is_finite() && reference.value != 0.0) {
        return Err(AnalysisError::invalid(
            "reference",
            format!("needs a finite non-zero value, got {}", reference.value),
        ));
    }
    let (choice, choice_cpu_s, _) =
        timed(|| planner.plan_estimator(scene, target_rel, ml_pilot_ics));
    let choice = choice?;
    // Where the planner did not pilot the levels (they alone would cost
    // more than the plain run), plan them anyway: the comparison measures
    // what multilevel would have cost.
    let ml_plan = match &choice.multilevel {
        Some(plan) => Some(plan.clone()),
        None => match default_levels(choice.plain.collisions) {
            Some(levels) => {
                Some(planner.plan_multilevel(scene, &choice.plain, levels, ml_pilot_ics)?)
            }
            None => None,
        },
    };
    let deviation = |value: f64, total: f64| {
        Measurement::new(value - reference.value, total.hypot(reference.sem))
    };
    let mut top = choice.plain.collisions;
    let mut plain_bias = choice.plain.bias;
    let (mut plain, mut multilevel, mut levels) = (Vec::new(), Vec::new(), None);
    for (r, seed) in seeds.enumerate() {
        let seeded = scene.clone().with_seed(seed);
        let mut run_multilevel = |top: &mut u64, bias: &mut f64| -> Result<(), AnalysisError> {
            let Some(plan) = &ml_plan else {
                return Ok(());
            };
            let scene = seeded
                .clone()
                .with_method(plan.method)
                .with_engine(plan.engine);
            let mut lengthened = 0;
            let (estimate, cpu_s, wall_s) = loop {
                let source = if *top == plan.levels[plan.levels.len() - 1] {
                    EnsembleLevels::new(scene.clone(), plan.levels.clone())?
                } else {
                    EnsembleLevels::up_to(scene.clone(), *top)?
                };
                let (run, cpu, wall) = timed(|| plan.estimator().run(&source));
                match run {
                    Err(AnalysisError::TargetUnreachable { .. })
                        if lengthened < MAX_LENGTHENINGS =>
                    {
                        lengthened += 1;
                        *top *= 4;
                    }
                    other => break (other?, cpu, wall),
                }
            };
            let b = estimate.budget.finite_time_bias;
            *bias = bias.max(b.value.hypot(b.sem));
            let ic_steps = estimate
                .levels
                .iter()
                .map(|l: &LevelStats| l.n_ics as f64 * l.cost)
                .sum();
            let value = estimate.lambda();
            let total = estimate.budget.total.value;
            multilevel.push(EstimatorRun {
                kind: EstimatorKind::Multilevel,
                seed,
                collisions: *top,
                ics: estimate.levels.iter().map(|l| l.n_ics).sum(),
                ic_steps,
                cpu_s,
                wall_s,
                value,
                total,
                deviation: deviation(value.value, total),
            });
            if levels.is_none() {
                levels = Some(estimate);
            }
            Ok(())
        };
        if r % 2 == 0 {
            run_multilevel(&mut top, &mut plain_bias)?;
        }
        let planned = PlannedRun {
            collisions: top,
            bias: plain_bias,
            ..choice.plain
        };
        let (run, cpu_s, wall_s) = timed(|| {
            planned
                .ensemble(seeded.clone(), 4 * planned.ics)
                .run_until(&planned.stop_rule(planned.ics.div_ceil(8).max(64)))
        });
        let run = run?;
        let value = Measurement::new(run.mean(), run.sem());
        let total = run.sem().hypot(planned.bias);
        plain.push(EstimatorRun {
            kind: EstimatorKind::Plain,
            seed,
            collisions: top,
            ics: run.n_ics(),
            ic_steps: run.n_ics() as f64 * top as f64,
            cpu_s,
            wall_s,
            value,
            total,
            deviation: deviation(value.value, total),
        });
        if r % 2 == 1 {
            run_multilevel(&mut top, &mut plain_bias)?;
        }
    }
    Ok(EstimatorComparison {
        target_rel,
        reference,
        choice,
        choice_cpu_s,
        plain,
        multilevel,
        levels,
    })
}

/// What a smaller target is predicted to cost, from a comparison's
/// measured level variances, costs and processor time per step
/// ([`EstimatorComparison::predict`]).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct TargetPrediction {
    /// The target relative total error.
    pub target_rel: f64,
    /// Top run length: the first fourfold lengthening of the measured top
    /// level at which the fitted bias bound is at most half the target.
    pub collisions: u64,
    /// The bias bound counted there (absolute).
    pub bias: f64,
    /// Multilevel run lengths (the measured levels, lengthened fourfold up
    /// to `collisions`).
    pub levels: Vec<u64>,
    /// Their correction variances `V_l` (measured; past the measured top,
    /// extrapolated with [`variance_decay`]).
    pub variances: Vec<f64>,
    /// Predicted initial conditions per level (Giles' allocation).
    pub multilevel_ics: Vec<f64>,
    /// Predicted plain initial conditions at `collisions`.
    pub plain_ics: f64,
    /// Predicted work, IC-steps.
    pub multilevel_ic_steps: f64,
    /// Predicted work, IC-steps.
    pub plain_ic_steps: f64,
    /// Predicted processor seconds (median measured seconds per IC-step).
    pub multilevel_cpu_s: f64,
    /// Predicted processor seconds (median measured seconds per IC-step).
    pub plain_cpu_s: f64,
}

impl TargetPrediction {
    /// Plain over multilevel predicted processor time.
    #[must_use]
    pub fn speedup(&self) -> f64 {
        self.plain_cpu_s / self.multilevel_cpu_s
    }
}

/// How fast the correction variances fall with run length: the exponent
/// `β` of `V_l ∝ T_l^−β`, a least-squares line through `ln V_l` against
/// `ln T_l` over the correction levels `l ≥ 1` (level 0 is the spread of
/// the exponents themselves). A chaotic trajectory whose finite-time
/// exponent fluctuates like `1/T` gives `β = 1`; a slower decay means the
/// corrections stay wide and the long levels cost more. `None` for fewer
/// than two correction levels with positive variance.
#[must_use]
pub fn variance_decay(levels: &[LevelStats]) -> Option<f64> {
    let points: Vec<(f64, f64)> = levels
        .iter()
        .skip(1)
        .filter(|l| l.variance > 0.0)
        .map(|l| ((l.collisions as f64).ln(), l.variance.ln()))
        .collect();
    if points.len() < 2 {
        return None;
    }
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let sxy: f64 = points.iter().map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = points.iter().map(|(x, _)| (x - mx) * (x - mx)).sum();
    (sxx > 0.0).then(|| -sxy / sxx)
}

impl EstimatorComparison {
    fn runs(&self, kind: EstimatorKind) -> &[EstimatorRun] {
        match kind {
            EstimatorKind::Plain => &self.plain,
            EstimatorKind::Multilevel => &self.multilevel,
        }
    }

    /// Median processor seconds of `kind`'s runs (NaN for none).
    #[must_use]
    pub fn median_cpu(&self, kind: EstimatorKind) -> f64 {
        median(self.runs(kind).iter().map(|r| r.cpu_s).collect())
    }

    /// Median processor seconds of `kind`'s runs scaled to the target
    /// ([`EstimatorRun::cpu_at_target`]).
    #[must_use]
    pub fn median_cpu_at_target(&self, kind: EstimatorKind) -> f64 {
        let t = self.target_rel;
        median(self.runs(kind).iter().map(|r| r.cpu_at_target(t)).collect())
    }

    /// Median stated relative total error of `kind`'s runs.
    #[must_use]
    pub fn median_rel_total(&self, kind: EstimatorKind) -> f64 {
        median(
            self.runs(kind)
                .iter()
                .map(EstimatorRun::rel_total)
                .collect(),
        )
    }

    /// Median pull against the reference of `kind`'s runs.
    #[must_use]
    pub fn median_pull(&self, kind: EstimatorKind) -> f64 {
        median(self.runs(kind).iter().map(EstimatorRun::pull).collect())
    }

    /// Plain over multilevel median processor time at equal stated error
    /// (NaN without multilevel runs): above 1 where multilevel pays.
    #[must_use]
    pub fn speedup(&self) -> f64 {
        self.median_cpu_at_target(EstimatorKind::Plain)
            / self.median_cpu_at_target(EstimatorKind::Multilevel)
    }

    /// What following the planner costs against running plain directly:
    /// the choice's processor time plus the chosen estimator's median
    /// time at the target, over plain's median time at the target. NaN
    /// where both are below the processor clock's resolution (10 ms).
    #[must_use]
    pub fn planner_overhead(&self) -> f64 {
        let chosen = self.median_cpu_at_target(self.choice.kind);
        (self.choice_cpu_s + chosen) / self.median_cpu_at_target(EstimatorKind::Plain)
    }

    /// The predicted cost of both estimators at `target_rel` (smaller than
    /// this comparison's), from the first multilevel run's level variances
    /// and bias fit, the planner's variance model for plain runs, and the
    /// median processor seconds per IC-step each estimator measured here.
    /// Levels past the measured top get variances extrapolated with
    /// [`variance_decay`]. `None` without a multilevel run, or where the
    /// bias bound stays above half the target up to 10⁹ collisions.
    #[must_use]
    pub fn predict(&self, planner: &Planner, target_rel: f64) -> Option<TargetPrediction> {
        let estimate = self.levels.as_ref()?;
        let pilot = planner
            .pilots
            .iter()
            .find(|p| p.method == self.choice.plain.method)?;
        let eps = target_rel * estimate.lambda().value.abs();
        let fit = estimate.extrapolation.preferred();
        let mut levels: Vec<u64> = estimate.levels.iter().map(|l| l.collisions).collect();
        let mut variances: Vec<f64> = estimate.levels.iter().map(|l| l.variance).collect();
        let beta = variance_decay(&estimate.levels)?;
        let (t_top, v_top) = (*levels.last()?, *variances.last()?);
        while fit.bias_bound(*levels.last()? as f64) > 0.5 * eps {
            let next = levels.last()? * 4;
            if next > 1_000_000_000 {
                return None;
            }
            levels.push(next);
            variances.push(v_top * (next as f64 / t_top as f64).powf(-beta));
        }
        let collisions = *levels.last()?;
        let bias = fit.bias_bound(collisions as f64);
        let eps_s2 = eps * eps - bias * bias;
        let costs: Vec<f64> = levels.iter().map(|&t| t as f64).collect();
        let multilevel_ics = super::multilevel::giles_allocation(&variances, &costs, eps_s2);
        let multilevel_ic_steps: f64 = multilevel_ics.iter().zip(&costs).map(|(n, c)| n * c).sum();
        let plain_ics = pilot.variance.at(collisions as f64) / eps_s2;
        let plain_ic_steps = plain_ics * collisions as f64;
        let per_step = |kind| {
            median(
                self.runs(kind)
                    .iter()
                    .map(EstimatorRun::cpu_per_step)
                    .collect(),
            )
        };
        Some(TargetPrediction {
            target_rel,
            collisions,
            bias,
            levels,
            variances,
            multilevel_ics,
            plain_ics,
            multilevel_ic_steps,
            plain_ic_steps,
            multilevel_cpu_s: multilevel_ic_steps * per_step(EstimatorKind::Multilevel),
            plain_cpu_s: plain_ic_steps * per_step(EstimatorKind::Plain),
        })
    }
}

/// One line for the choice, one per estimator (medians of the repeats),
/// one for the speed-up.
impl fmt::Display for EstimatorComparison {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "target {:.2}%: planner {} (its choice {:.2} s processor time)",
            100.0 * self.target_rel,
            self.choice,
            self.choice_cpu_s
        )?;
        for kind in [EstimatorKind::Plain, EstimatorKind::Multilevel] {
            let runs = self.runs(kind);
            let Some(first) = runs.first() else { continue };
            writeln!(
                f,
                "  {:<10} T = {:>7}, ICs {:>9} (first), processor {:8.2} s (at target {:8.2} s), wall {:7.2} s (first), stated {:.3}%, pull {:+.2} (medians of {})",
                kind.name(),
                first.collisions,
                first.ics,
                self.median_cpu(kind),
                self.median_cpu_at_target(kind),
                first.wall_s,
                100.0 * self.median_rel_total(kind),
                self.median_pull(kind),
                runs.len()
            )?;
        }
        if self.multilevel.is_empty() {
            write!(
                f,
                "  no multilevel run (the plain run is too short for four levels)"
            )
        } else {
            write!(
                f,
                "  plain/multilevel at equal stated error {:.2}; following the planner costs {:.2}x plain",
                self.speedup(),
                self.planner_overhead()
            )
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn level(collisions: u64, variance: f64) -> LevelStats {
        LevelStats {
            level: 0,
            collisions,
            n_ics: 100,
            mean: 0.0,
            variance,
            cost: collisions as f64,
            wall_time_s: 0.0,
        }
    }

    /// `V_l = T_l^−β` exactly gives back `β`; level 0 (the spread of the
    /// exponents, not a correction) is left out; one correction is too
    /// few.
    #[test]
    fn variance_decay_reads_the_exponent() {
        for beta in [0.5, 1.0] {
            let mut levels = vec![level(100, 7.0)];
            levels.extend([400, 1600, 6400].map(|t| level(t, (t as f64).powf(-beta))));
            let b = variance_decay(&levels).unwrap();
            assert!((b - beta).abs() < 1e-12, "{b} vs {beta}");
        }
        assert_eq!(variance_decay(&[level(100, 1.0), level(400, 0.1)]), None);
    }

    #[test]
    fn median_of_odd_even_and_none() {
        assert_eq!(median(vec![3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(vec![4.0, 1.0, 2.0, 3.0]), 2.5);
        assert!(median(Vec::new()).is_nan());
    }

    #[test]
    fn processor_time_is_read_on_linux() {
        if cfg!(target_os = "linux") {
            let t = process_cpu_seconds().expect("/proc/self/stat");
            assert!(t >= 0.0 && t.is_finite());
        }
    }
}
