//! How often the ball hits a wall (paper, appendix "Collision rate"):
//! `ν = collisions / time`, the exponent per collision `λ/ν`, their
//! ensemble summaries with errors, and what to expect: the mean speed each
//! sampler draws and the rate of the invariant (Liouville) measure from
//! Santaló's mean free path.
//!
//! Documented in the group docs (`diagnostics/mod.rs`), section "Collision rate".

use spinball_core::Sampler;
use spinball_geometry::Boundary;

use crate::error::AnalysisError;
use crate::estimators::{Accumulator, Lyapunov};
use crate::run::LyapunovEstimate;

/// Collisions per unit time, `ν = N / T`, of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CollisionRate {
    /// Collisions counted.
    pub collisions: u64,
    /// Flight time they took.
    pub time: f64,
    /// `ν = collisions / time`.
    pub rate: f64,
}

impl CollisionRate {
    /// The rate of `collisions` collisions in `time`.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for zero collisions or a time that is
    /// not finite and positive.
    pub fn new(collisions: u64, time: f64) -> Result<Self, AnalysisError> {
        if collisions == 0 {
            return Err(AnalysisError::invalid("collisions", "must be > 0"));
        }
        if !(time.is_finite() && time > 0.0) {
            return Err(AnalysisError::invalid(
                "time",
                format!("must be finite and > 0, got {time}"),
            ));
        }
        Ok(CollisionRate {
            collisions,
            time,
            rate: collisions as f64 / time,
        })
    }

    /// The collision rate of the trajectory behind a Lyapunov result.
    ///
    /// # Errors
    /// As [`CollisionRate::new`] (only for a hand-made, empty result).
    pub fn of(lyapunov: &Lyapunov) -> Result<Self, AnalysisError> {
        Self::new(lyapunov.collisions, lyapunov.time)
    }
}

/// The exponent per collision, `λ_coll = λ/ν` (paper, appendix "Collision
/// rate"). Equal to [`Lyapunov::per_collision`]; written out here because it
/// is how the paper separates "less chaos" from "fewer collisions".
pub fn per_collision_exponent(lyapunov: &Lyapunov) -> f64 {
    lyapunov.exponent * lyapunov.time / lyapunov.collisions as f64
}

/// Collision rate and exponents over an ensemble of trajectories.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RateSummary {
    /// Number of trajectories.
    pub n: u64,
    /// Mean collision rate `ν̄` over trajectories.
    pub rate_mean: f64,
    /// Its standard error.
    pub rate_sem: f64,
    /// Mean exponent per unit time `λ̄`.
    pub exponent_mean: f64,
    /// Its standard error.
    pub exponent_sem: f64,
    /// The paper's per-collision exponent `λ̄/ν̄` (ratio of the means).
    pub per_collision: f64,
    /// Its standard error (first-order error propagation with the covariance
    /// of `λ` and `ν` over trajectories).
    pub per_collision_sem: f64,
    /// Mean of the per-trajectory `λ_i/ν_i` (differs from `λ̄/ν̄` when `λ`
    /// and `ν` are correlated).
    pub mean_per_collision: f64,
    /// Its standard error.
    pub mean_per_collision_sem: f64,
}

/// [`RateSummary`] of Lyapunov results (in the order given; pass them in
/// index order for bitwise reproducibility).
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for fewer than two results or a result
/// with zero collisions or time.
pub fn collision_rate_summary(results: &[Lyapunov]) -> Result<RateSummary, AnalysisError> {
    if results.len() < 2 {
        return Err(AnalysisError::invalid(
            "results",
            format!("need at least 2 trajectories, got {}", results.len()),
        ));
    }
    let (mut nu, mut lam, mut per) = (Accumulator::new(), Accumulator::new(), Accumulator::new());
    for r in results {
        let rate = CollisionRate::of(r)?.rate;
        nu.push(rate);
        lam.push(r.exponent);
        per.push(r.exponent / rate);
    }
    let (nu_m, lam_m) = (nu.mean().unwrap_or(0.0), lam.mean().unwrap_or(0.0));
    let n = results.len() as f64;
    let cov = results
        .iter()
        .map(|r| (r.exponent - lam_m) * (r.collisions as f64 / r.time - nu_m))
        .sum::<f64>()
        / (n - 1.0);
    let ratio = lam_m / nu_m;
    let (var_l, var_n) = (lam.variance().unwrap_or(0.0), nu.variance().unwrap_or(0.0));
    let var_ratio = (var_l + ratio * ratio * var_n - 2.0 * ratio * cov) / (nu_m * nu_m * n);
    Ok(RateSummary {
        n: results.len() as u64,
        rate_mean: nu_m,
        rate_sem: nu.sem().unwrap_or(0.0),
        exponent_mean: lam_m,
        exponent_sem: lam.sem().unwrap_or(0.0),
        per_collision: ratio,
        per_collision_sem: var_ratio.max(0.0).sqrt(),
        mean_per_collision: per.mean().unwrap_or(0.0),
        mean_per_collision_sem: per.sem().unwrap_or(0.0),
    })
}

/// Collision rate `ν` and exponent per collision `λ/ν` of an estimate, from
/// its per-trajectory times (see [`collision_rate_summary`]: mean of the
/// per-trajectory rates, and the paper's `λ̄/ν̄` with an error that accounts
/// for the correlation of `λ` and `ν` over trajectories).
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for an estimate with fewer than two
/// trajectories or one with zero time.
pub fn rate_summary(estimate: &LyapunovEstimate) -> Result<RateSummary, AnalysisError> {
    let runs: Vec<Lyapunov> = estimate
        .trajectories
        .iter()
        .map(|s| Lyapunov {
            exponent: s.exponent,
            per_collision: s.per_collision,
            time: s.time,
            collisions: s.collisions,
            history: Vec::new(),
        })
        .collect();
    collision_rate_summary(&runs)
}

/// Mean translational speed `⟨|v|⟩` of the initial conditions `sampler`
/// draws at `alpha` (energy ½, so `|v|² + αu² = 1`).
///
/// - α = 0: both samplers give `|v| = 1`.
/// - Paper sampler, α > 0: `αu² = s²/4` with `s` uniform in `[−1, 1]`, so
///   `⟨|v|⟩ = ∫₀¹ √(1 − s²/4) ds = √3/4 + π/6 ≈ 0.9566`, the same for
///   every α > 0: the speed distribution jumps at α = 0⁺.
/// - Microcanonical, α > 0: `(v, √α u)` uniform on the unit sphere, so
///   `√α u` is uniform in `[−1, 1]` (Archimedes) and
///   `⟨|v|⟩ = ∫₀¹ √(1 − z²) dz = π/4 ≈ 0.7854`, again for every α > 0.
pub fn initial_mean_speed(sampler: Sampler, alpha: f64) -> f64 {
    use std::f64::consts::PI;
    if alpha <= 0.0 {
        return 1.0;
    }
    match sampler {
        Sampler::Paper => 3f64.sqrt() / 4.0 + PI / 6.0,
        Sampler::Microcanonical => PI / 4.0,
    }
}

/// The collision rate of the invariant (Liouville) measure at `alpha`:
/// `ν = ⟨|v|⟩ · |∂Q| / (π |Q|)`, Santaló's mean free path `π|Q|/|∂Q|`
/// travelled at the mean speed of the microcanonical measure (1 at α = 0,
/// π/4 for every α > 0, see [`initial_mean_speed`]). A long, ergodic run
/// from any start has this rate; regular islands and finite runs from the
/// paper's sampler (which starts faster, at `⟨|v|⟩ ≈ 0.957`, and relaxes
/// slowly when the coupling `γ = 2α/(1+α)` is small) deviate from it.
#[must_use]
pub fn liouville_collision_rate<B: Boundary + ?Sized>(table: &B, alpha: f64) -> f64 {
    use std::f64::consts::PI;
    initial_mean_speed(Sampler::Microcanonical, alpha) * table.perimeter() / (PI * table.area())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::run::{Ensemble, Threads};
    use crate::test_support::{at, template};
    use spinball_core::SpinLaw;
    use spinball_geometry::{Sinai, Stadium};
    #[test]
    fn rate_summary_of_an_estimate() {
        let fd = at(template(), 0.5).with_ics(60).run().unwrap();
        let r = rate_summary(&fd).unwrap();
        assert!(r.rate_mean > 0.2 && r.rate_mean < 2.0 && r.rate_sem > 0.0);
        assert!((r.per_collision - fd.mean / r.rate_mean).abs() < 1e-15);
    }

    #[test]
    fn collision_rate_expectations() {
        let stadium = Stadium::new(1.0).unwrap();
        let nu0 = liouville_collision_rate(&stadium, 0.0);
        assert!((nu0 - 0.4583).abs() < 1e-4, "{nu0}");
        let ratio = liouville_collision_rate(&stadium, 0.5) / nu0;
        assert!((ratio - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        assert!((initial_mean_speed(Sampler::Paper, 0.3) - 0.95661).abs() < 1e-5);
        assert_eq!(initial_mean_speed(Sampler::Microcanonical, 0.0), 1.0);
        // The sampled speeds agree with the formulas.
        let law = SpinLaw::new(0.3).unwrap();
        for sampler in [Sampler::Paper, Sampler::Microcanonical] {
            let n = 20_000;
            let mean = (0..n)
                .map(|i| {
                    sampler
                        .initial_state(&stadium, &law, 1, i)
                        .velocity
                        .length()
                })
                .sum::<f64>()
                / n as f64;
            assert!(
                (mean - initial_mean_speed(sampler, 0.3)).abs() < 0.01,
                "{sampler}"
            );
        }
        // A specular run reproduces Santaló's rate.
        let e = Ensemble::new(Stadium::new(1.0).unwrap(), SpinLaw::specular())
            .with_seed(5)
            .with_threads(Threads::Fixed(1))
            .with_ics(64)
            .with_collisions(2_000)
            .run()
            .unwrap();
        let r = rate_summary(&e).unwrap();
        assert!((r.rate_mean - nu0).abs() < 0.01, "{}", r.rate_mean);
        let sinai = Sinai::new(2.0, 1.0).unwrap();
        assert!((sinai.area() - (16.0 - std::f64::consts::PI)).abs() < 1e-12);
    }
}
