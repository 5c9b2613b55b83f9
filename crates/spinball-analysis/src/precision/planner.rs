//! How long to run, and with which method: the cheapest `(method, N, T)`
//! for a target total error, planned from a short pilot run.
//!
//! Documented in the group docs (`precision/mod.rs`), section "Planning a run".

use spinball_geometry::Boundary;

use super::convergence::convergence_estimates;
use super::finite_time_bias::{BiasFit, BiasLaw, BiasRegime, FiniteTimeBias};
use super::measurement::Measurement;
use super::method_bias::MethodBias;
use crate::error::AnalysisError;
use crate::estimators::{LinearFit, Method};
use crate::run::{Engine, Ensemble, LyapunovEstimate, StopRule};

/// The per-trajectory variance of the exponent against run length,
/// `σ²(T) = at_infinity + per_inverse_t / T`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct VarianceModel {
    /// `v_∞ ≥ 0`: the spread that longer runs do not remove.
    pub at_infinity: f64,
    /// `v_1 ≥ 0`: the spread that falls like `1/T`.
    pub per_inverse_t: f64,
}

impl VarianceModel {
    /// Least-squares fit of `variances[k]` at `checkpoints[k]`, with both
    /// coefficients kept non-negative.
    #[must_use]
    pub fn fit(checkpoints: &[u64], variances: &[f64]) -> Self {
        let x: Vec<f64> = checkpoints.iter().map(|&c| 1.0 / c as f64).collect();
        let my = variances.iter().sum::<f64>() / x.len() as f64;
        let points: Vec<(f64, f64)> = x.iter().copied().zip(variances.iter().copied()).collect();
        let LinearFit { slope, intercept } = LinearFit::through(&points).unwrap_or(LinearFit {
            slope: 0.0,
            intercept: my,
        });
        if slope < 0.0 {
            VarianceModel {
                at_infinity: my.max(0.0),
                per_inverse_t: 0.0,
            }
        } else if intercept < 0.0 {
            // Through the origin: σ² = v_1/T.
            let sxx0: f64 = x.iter().map(|x| x * x).sum();
            let sxy0: f64 = x.iter().zip(variances).map(|(x, y)| x * y).sum();
            VarianceModel {
                at_infinity: 0.0,
                per_inverse_t: (sxy0 / sxx0).max(0.0),
            }
        } else {
            VarianceModel {
                at_infinity: intercept,
                per_inverse_t: slope,
            }
        }
    }

    /// `σ²(T)` at `collisions` collisions.
    #[must_use]
    pub fn at(&self, collisions: f64) -> f64 {
        self.at_infinity + self.per_inverse_t / collisions
    }
}

/// What a pilot measured for one method.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct MethodPilot {
    /// The method.
    pub method: Method,
    /// The engine that ran it.
    pub engine: Engine,
    /// Wall-clock seconds per IC-step.
    pub seconds_per_step: f64,
    /// Variance of one trajectory's exponent against `T`.
    pub variance: VarianceModel,
    /// The finite-time bias fit (of the regime the pilot found).
    pub finite_time: BiasFit,
    /// The regime the pilot found. A plan is an extrapolation of the
    /// pilot: trust it where this is `1/T`; `ln T / T` or `neither` (a
    /// near-integrable table, long-lived regular motion) means the bias
    /// can fall more slowly than the pilot shows, so check the planned
    /// run's own [`ErrorBudget`](crate::precision::ErrorBudget).
    pub regime: BiasRegime,
    /// The method bias against the tangent method at the pilot's longest
    /// run (zero for tangent).
    pub method_bias: Measurement,
    /// The pilot's longest run, where `method_bias` was measured.
    pub pilot_collisions: u64,
    /// The pilot's mean exponent at its longest run.
    pub lambda: Measurement,
}

impl MethodPilot {
    /// Predicted total error (absolute) of `ics × collisions`.
    #[must_use]
    pub fn predicted_error(&self, ics: f64, collisions: f64) -> f64 {
        (self.variance.at(collisions) / ics
            + self.bias_at(collisions).powi(2)
            + self.method_bias_at(collisions).powi(2))
        .sqrt()
    }

    /// Predicted wall time of `ics × collisions` on the pilot's machine.
    #[must_use]
    pub fn predicted_wall_s(&self, ics: f64, collisions: f64) -> f64 {
        ics * collisions * self.seconds_per_step
    }

    /// The finite-time bias magnitude counted at `collisions`, each
    /// coefficient at `√(value² + sem²)` ([`BiasFit::bias_bound`]).
    #[must_use]
    pub fn bias_at(&self, collisions: f64) -> f64 {
        self.finite_time.bias_bound(collisions)
    }

    /// The method bias magnitude counted at `collisions`: `√(m² + σ_m²)`
    /// from the pilot, carried to `T` like `ln T / T`. The difference is a
    /// finite-time effect (an offset of order one in the summed logarithms,
    /// and on regular orbits the shear that finite differences do not see),
    /// so it falls at least that fast; `ln T / T` is the slower of the two
    /// and the conservative choice.
    #[must_use]
    pub fn method_bias_at(&self, collisions: f64) -> f64 {
        let g = BiasLaw::LogTOverT;
        let scale = g.g(collisions) / g.g(self.pilot_collisions.max(3) as f64);
        self.method_bias.value.hypot(self.method_bias.sem) * scale
    }
}

/// A planned run and what it is predicted to give.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct PlannedRun {
    /// The method to use.
    pub method: Method,
    /// The engine the pilot measured it with.
    pub engine: Engine,
    /// Initial conditions.
    pub ics: u64,
    /// Collisions per initial condition.
    pub collisions: u64,
    /// The target relative total error.
    pub target_rel: f64,
    /// Predicted total error (absolute).
    pub predicted_error: f64,
    /// Predicted work, `ics × collisions` IC-steps.
    pub predicted_ic_steps: u64,
    /// Predicted wall time on the pilot's machine and thread count.
    pub predicted_wall_s: f64,
    /// The bias magnitude at this `T` (finite-time and method, in
    /// quadrature) that the stop rule adds to the SEM.
    pub bias: f64,
}

impl PlannedRun {
    /// `template` with this run's method, engine, collisions and initial
    /// conditions `0..max_ics` (room for the stop rule to go past the
    /// planned count if the pilot underestimated the spread).
    #[must_use]
    pub fn ensemble<B: Boundary>(&self, template: Ensemble<B>, max_ics: u64) -> Ensemble<B> {
        template
            .with_method(self.method)
            .with_engine(self.engine)
            .with_collisions(self.collisions)
            .with_ics(max_ics.max(self.ics))
    }

    /// The stop rule on total error for this run: batches of `batch`, stop
    /// once `√(SEM² + bias²) ≤ target · |mean|`.
    #[must_use]
    pub fn stop_rule(&self, batch: u64) -> StopRule {
        StopRule::total_error(batch, self.target_rel, self.bias)
    }
}

/// The planner: pilots of several methods on one scene.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Planner {
    /// One pilot per candidate method.
    pub pilots: Vec<MethodPilot>,
    /// Fewest initial conditions a plan uses (a SEM from fewer is itself
    /// too uncertain). Default 16.
    pub min_ics: u64,
    /// Shortest run a plan considers (default: the pilot's first checkpoint).
    pub min_collisions: u64,
    /// Longest run a plan considers (default 10⁷ collisions).
    pub max_collisions: u64,
}

impl Planner {
    /// Pilot `methods` on `ensemble` (its table, law, sampler, seed, index
    /// range, engine, threads) at `checkpoints`. Each method runs
    /// [`convergence_estimates`]; a finite-difference method is paired with
    /// the tangent pilot (run once, whether listed or not) for its method
    /// bias.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for no methods; as
    /// [`convergence_estimates`] and [`FiniteTimeBias::fit`].
    pub fn pilot<B: Boundary + Clone + Sync>(
        ensemble: &Ensemble<B>,
        methods: &[Method],
        checkpoints: &[u64],
    ) -> Result<Self, AnalysisError> {
        if methods.is_empty() {
            return Err(AnalysisError::invalid("methods", "need at least one"));
        }
        let tangent =
            convergence_estimates(&ensemble.clone().with_method(Method::Tangent), checkpoints)?;
        let mut pilots = Vec::with_capacity(methods.len());
        for &method in methods {
            let columns = match method {
                Method::Tangent => tangent.clone(),
                Method::FiniteDifference { .. } => {
                    convergence_estimates(&ensemble.clone().with_method(method), checkpoints)?
                }
            };
            let bias = FiniteTimeBias::from_columns(&columns)?;
            let last = columns.last().expect("checked non-empty");
            let method_bias = match method {
                Method::Tangent => Measurement::new(0.0, 0.0),
                Method::FiniteDifference { .. } => {
                    let t_last = tangent.last().expect("checked non-empty");
                    MethodBias::from_estimates(last, t_last)?.difference
                }
            };
            pilots.push(MethodPilot {
                method,
                engine: last.engine,
                seconds_per_step: seconds_per_step(&columns),
                variance: VarianceModel::fit(
                    checkpoints,
                    &columns.iter().map(|c| c.std * c.std).collect::<Vec<_>>(),
                ),
                finite_time: *bias.preferred(),
                regime: bias.regime,
                method_bias,
                pilot_collisions: last.collisions_per_ic,
                lambda: Measurement::lambda(last),
            });
        }
        Ok(Planner {
            pilots,
            min_ics: 16,
            min_collisions: checkpoints[0],
            max_collisions: 10_000_000,
        })
    }

    /// Plans use at least `min_ics` initial conditions.
    #[must_use]
    pub fn with_min_ics(mut self, min_ics: u64) -> Self {
        self.min_ics = min_ics;
        self
    }

    /// Plans consider runs of `min..=max` collisions.
    #[must_use]
    pub fn with_collision_range(mut self, min: u64, max: u64) -> Self {
        self.min_collisions = min;
        self.max_collisions = max;
        self
    }

    /// The exponent the relative target refers to: the first pilot's.
    #[must_use]
    pub fn lambda(&self) -> Measurement {
        self.pilots
            .first()
            .map_or(Measurement::new(f64::NAN, f64::NAN), |p| p.lambda)
    }

    /// The cheapest planned run (least predicted wall time) of any pilot
    /// method whose predicted total error is at most `target_rel · |λ|`.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for a target that is not finite
    /// and > 0, no pilots, `min_ics < 2`, an empty collision range, or a
    /// pilot `λ` within two SEM of zero (a relative target needs `λ ≠ 0`);
    /// [`AnalysisError::TargetUnreachable`] if no method reaches the target
    /// within the collision range (a bias floor above it).
    pub fn plan(&self, target_rel: f64) -> Result<PlannedRun, AnalysisError> {
        let mut best: Option<PlannedRun> = None;
        let mut floor = f64::INFINITY;
        for planned in self.plans(target_rel)? {
            match planned {
                Ok(run) if best.is_none_or(|b| run.predicted_wall_s < b.predicted_wall_s) => {
                    best = Some(run);
                }
                Err(AnalysisError::TargetUnreachable { floor: f, .. }) => floor = floor.min(f),
                _ => {}
            }
        }
        best.ok_or(AnalysisError::TargetUnreachable {
            target: target_rel * self.lambda().value.abs(),
            floor,
        })
    }

    /// The cheapest run of **each** pilot method for `target_rel` (in the
    /// pilots' order): what reaching the target costs per method.
    ///
    /// # Errors
    /// The input errors of [`plan`](Self::plan) for the whole call; each
    /// method's [`AnalysisError::TargetUnreachable`] in its own entry.
    pub fn plans(
        &self,
        target_rel: f64,
    ) -> Result<Vec<Result<PlannedRun, AnalysisError>>, AnalysisError> {
        if !(target_rel.is_finite() && target_rel > 0.0) {
            return Err(AnalysisError::invalid(
                "target",
                format!("the relative total error must be finite and > 0, got {target_rel}"),
            ));
        }
        if self.pilots.is_empty() {
            return Err(AnalysisError::invalid("pilots", "need at least one"));
        }
        if self.min_ics < 2 || self.min_collisions == 0 || self.min_collisions > self.max_collisions
        {
            return Err(AnalysisError::invalid(
                "planner",
                format!(
                    "need min_ics >= 2 and 1 <= min_collisions <= max_collisions, got {}, {}..{}",
                    self.min_ics, self.min_collisions, self.max_collisions
                ),
            ));
        }
        let lambda = self.lambda();
        if !(lambda.value.abs() > 2.0 * lambda.sem) {
            return Err(AnalysisError::invalid(
                "target",
                format!(
                    "a relative target needs the pilot's λ resolved from zero, got {} ± {}",
                    lambda.value, lambda.sem
                ),
            ));
        }
        let eps = target_rel * lambda.value.abs();
        let grid = log_grid(self.min_collisions, self.max_collisions);
        Ok(self
            .pilots
            .iter()
            .map(|pilot| self.plan_pilot(pilot, target_rel, eps, &grid))
            .collect())
    }

    /// The cheapest run of `pilot` with total error at most `eps` over the
    /// run lengths `grid`.
    fn plan_pilot(
        &self,
        pilot: &MethodPilot,
        target_rel: f64,
        eps: f64,
        grid: &[u64],
    ) -> Result<PlannedRun, AnalysisError> {
        let mut best: Option<PlannedRun> = None;
        let mut floor = f64::INFINITY;
        for &t in grid {
            let tf = t as f64;
            let bias = pilot.bias_at(tf).hypot(pilot.method_bias_at(tf));
            floor = floor.min(bias);
            let room = eps * eps - bias * bias;
            if room <= 0.0 {
                continue;
            }
            let n = (pilot.variance.at(tf) / room).ceil();
            if !n.is_finite() {
                continue;
            }
            let ics = (n as u64).max(self.min_ics);
            let steps = ics.saturating_mul(t);
            let wall = steps as f64 * pilot.seconds_per_step;
            if best.is_none_or(|b| wall < b.predicted_wall_s) {
                best = Some(PlannedRun {
                    method: pilot.method,
                    engine: pilot.engine,
                    ics,
                    collisions: t,
                    target_rel,
                    predicted_error: pilot.predicted_error(ics as f64, tf),
                    predicted_ic_steps: steps,
                    predicted_wall_s: wall,
                    bias,
                });
            }
        }
        best.ok_or(AnalysisError::TargetUnreachable { target: eps, floor })
    }
}

/// Wall seconds per IC-step of a pilot's columns: the lane engine runs each
/// column on its own, the scalar engine one nested run to the last.
fn seconds_per_step(columns: &[LyapunovEstimate]) -> f64 {
    let last = columns.last().expect("checked non-empty");
    let (wall, steps) = match last.engine {
        Engine::Lanes => (
            columns.iter().map(|c| c.wall_time_s).sum::<f64>(),
            columns.iter().map(|c| c.total_collisions()).sum::<u64>(),
        ),
        Engine::Scalar => (last.wall_time_s, last.total_collisions()),
    };
    wall / steps.max(1) as f64
}

/// Run lengths from `lo` to `hi`, ten per decade, rounded to two
/// significant digits, always including both ends.
fn log_grid(lo: u64, hi: u64) -> Vec<u64> {
    let mut out = vec![lo];
    let (a, b) = ((lo as f64).log10(), (hi as f64).log10());
    let steps = ((b - a) * 10.0).ceil() as usize;
    for k in 1..steps {
        let t = 10f64.powf(a + (b - a) * k as f64 / steps as f64);
        let mag = 10f64.powi(t.log10().floor() as i32 - 1);
        let t = ((t / mag).round() * mag) as u64;
        if t > *out.last().expect("non-empty") && t < hi {
            out.push(t);
        }
    }
    if hi > lo {
        out.push(hi);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_is_increasing_and_covers_the_range() {
        let g = log_grid(500, 10_000_000);
        assert_eq!((g[0], *g.last().unwrap()), (500, 10_000_000));
        assert!(g.windows(2).all(|w| w[1] > w[0]));
        assert!(g.len() > 35 && g.len() < 50, "{}", g.len());
        assert_eq!(log_grid(7, 7), vec![7]);
    }

    #[test]
    fn variance_model_keeps_non_negative_coefficients() {
        let t = [1_000, 2_000, 4_000];
        let chaotic = VarianceModel::fit(&t, &[4e-3, 2e-3, 1e-3]);
        assert!(chaotic.at_infinity.abs() < 1e-12);
        assert!((chaotic.per_inverse_t - 4.0).abs() < 1e-9);
        let flat = VarianceModel::fit(&t, &[1e-3, 2e-3, 3e-3]);
        assert_eq!(flat.per_inverse_t, 0.0);
        assert!((flat.at_infinity - 2e-3).abs() < 1e-15);
        let through_zero = VarianceModel::fit(&t, &[5e-3, 2e-3, 1e-3]);
        assert_eq!(through_zero.at_infinity, 0.0);
        assert!(through_zero.per_inverse_t > 0.0);
    }
}
