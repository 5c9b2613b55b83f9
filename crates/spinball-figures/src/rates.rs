//! The collision-rate view of a λ(α) curve (the paper's App. A.3): the
//! mean collision rate ν(α) and the exponent per collision λ/ν(α) with their
//! errors, and the numbers the paper quotes about them — how much ν, λ/ν and
//! λ drop from the first α to the last, and how much ν varies over α > 0.
//!
//! The paper separates "less chaos" from "fewer collisions" with these
//! numbers; computing them belongs with the curve, not in a figure's
//! `main`.
//!
//! ```no_run
//! # use spinball_figures::{Curve, CurveRates};
//! # fn demo(curve: &Curve) -> Result<(), Box<dyn std::error::Error + Send + Sync>> {
//! let rates = CurveRates::of(curve)?;
//! println!("{rates}"); // "stadium: nu falls 9.8% from alpha 0 to 1; …"
//! # Ok(()) }
//! ```

use std::fmt;

use serde::Serialize;
use spinball_analysis::diagnostics::{initial_mean_speed, liouville_collision_rate, rate_summary};
use spinball_analysis::precision::Measurement;
use spinball_core::Sampler;
use spinball_geometry::Table;

use crate::curves::Curve;
use crate::figure::BoxError;

/// ν(α) and λ/ν(α) of one curve, and the paper's claims about them.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurveRates {
    /// The curve's label.
    pub label: String,
    /// How its initial conditions were drawn (`paper`, `microcanonical`).
    pub sampler: String,
    /// Santaló's rate at α = 0, `|∂Q|/(π|Q|)` (the α = 0 rate of the
    /// invariant measure at speed 1).
    pub santalo_rate_alpha0: f64,
    /// The invariant measure's rate at α > 0 (mean speed π/4).
    pub liouville_rate_alpha_positive: f64,
    /// Mean speed of this sampler's initial conditions at α > 0.
    pub initial_mean_speed_alpha_positive: f64,
    /// Mean collision rate per point, `(α, ν ± SEM)`.
    pub nu: Vec<(f64, Measurement)>,
    /// The exponent per collision per point, `(α, λ/ν ± SEM)` (ratio of the
    /// means, error with their covariance).
    pub per_collision: Vec<(f64, Measurement)>,
    /// `1 − ν(last)/ν(first)`.
    pub nu_drop: f64,
    /// `1 − (λ/ν)(last)/(λ/ν)(first)` (the paper: 57% stadium, 70% Sinai).
    pub per_collision_drop: f64,
    /// `1 − λ(last)/λ(first)`.
    pub lambda_drop: f64,
    /// Relative spread `(max − min)/max` of ν over the α > 0 points.
    pub nu_spread_alpha_positive: f64,
    /// The same over α ≥ 0.1.
    pub nu_spread_alpha_ge_0_1: f64,
}

impl CurveRates {
    /// The rates of `curve` (its estimates keep every trajectory's
    /// collisions and time; the table comes from their provenance).
    ///
    /// # Errors
    /// A curve whose table has no spec (not a built-in table), and as
    /// [`rate_summary`].
    pub fn of(curve: &Curve) -> Result<Self, BoxError> {
        let first = curve.estimates.first().ok_or("a curve without points")?;
        let table: Table = first.table().name.parse()?;
        let sampler = first.sampler().unwrap_or(Sampler::Paper);
        let nu = curve
            .try_points(|e| rate_summary(e).map(|r| Measurement::new(r.rate_mean, r.rate_sem)))?;
        let per_collision = curve.try_points(|e| {
            rate_summary(e).map(|r| Measurement::new(r.per_collision, r.per_collision_sem))
        })?;
        Ok(CurveRates {
            label: curve.label.clone(),
            sampler: sampler.name().to_string(),
            santalo_rate_alpha0: liouville_collision_rate(&table, 0.0),
            liouville_rate_alpha_positive: liouville_collision_rate(&table, 1.0),
            initial_mean_speed_alpha_positive: initial_mean_speed(sampler, 1.0),
            nu_drop: relative_drop(&nu),
            per_collision_drop: relative_drop(&per_collision),
            lambda_drop: curve.summary().relative_drop,
            nu_spread_alpha_positive: relative_spread(&nu, f64::MIN_POSITIVE),
            nu_spread_alpha_ge_0_1: relative_spread(&nu, 0.1),
            nu,
            per_collision,
        })
    }

    /// ν(α) relative to Santaló's rate at α = 0.
    pub fn relative_nu(&self) -> Vec<(f64, Measurement)> {
        let s = self.santalo_rate_alpha0;
        self.nu
            .iter()
            .map(|&(a, m)| (a, Measurement::new(m.value / s, m.sem / s)))
            .collect()
    }
}

impl fmt::Display for CurveRates {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: nu falls {:.1}%, lambda/nu {:.1}%, lambda {:.1}% from the first alpha to the last; \
             nu varies {:.1}% over alpha > 0 and {:.1}% over alpha >= 0.1",
            self.label,
            100.0 * self.nu_drop,
            100.0 * self.per_collision_drop,
            100.0 * self.lambda_drop,
            100.0 * self.nu_spread_alpha_positive,
            100.0 * self.nu_spread_alpha_ge_0_1
        )
    }
}

/// `1 − value(last)/value(first)` of `points` (NaN for none).
pub fn relative_drop(points: &[(f64, Measurement)]) -> f64 {
    match (points.first(), points.last()) {
        (Some(a), Some(b)) => 1.0 - b.1.value / a.1.value,
        _ => f64::NAN,
    }
}

/// `(max − min)/max` of the values at `x ≥ from` (NaN for none).
pub fn relative_spread(points: &[(f64, Measurement)], from: f64) -> f64 {
    let v = points
        .iter()
        .filter(|(x, _)| *x >= from)
        .map(|(_, m)| m.value);
    let (lo, hi) = v.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
        (lo.min(x), hi.max(x))
    });
    if lo > hi { f64::NAN } else { (hi - lo) / hi }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::Plan;
    use spinball_analysis::run::{AlphaSweep, Ensemble, Threads};
    use spinball_core::SpinLaw;
    use spinball_geometry::Boundary;

    #[test]
    fn drops_and_spreads() {
        let m = |v| Measurement::new(v, 0.0);
        let pts = [(0.0, m(2.0)), (0.1, m(1.0)), (0.5, m(1.2)), (1.0, m(1.5))];
        assert_eq!(relative_drop(&pts), 0.25);
        assert!((relative_spread(&pts, f64::MIN_POSITIVE) - (1.5 - 1.0) / 1.5).abs() < 1e-15);
        assert!((relative_spread(&pts, 0.5) - 0.3 / 1.5).abs() < 1e-15);
        assert!(relative_spread(&pts, 2.0).is_nan());
        assert!(relative_drop(&[]).is_nan());
    }

    #[test]
    fn rates_of_a_curve() {
        let table: Table = "stadium:a=1".parse().unwrap();
        let template = Ensemble::new(table, SpinLaw::specular())
            .with_ics(6)
            .with_collisions(400)
            .with_threads(Threads::Fixed(1));
        let plan = Plan::fixed(6, 400);
        let estimates = AlphaSweep::new(template, &[0.0, 0.5, 1.0])
            .unwrap()
            .run()
            .unwrap();
        let curve = Curve::new("stadium", plan, estimates).unwrap();
        let r = CurveRates::of(&curve).unwrap();
        assert_eq!(r.sampler, "paper");
        assert_eq!(r.nu.len(), 3);
        let summary = rate_summary(&curve.estimates[2]).unwrap();
        assert_eq!(
            r.nu[2],
            (1.0, Measurement::new(summary.rate_mean, summary.rate_sem))
        );
        assert_eq!(r.per_collision[2].1.value, summary.per_collision);
        let santalo = table.perimeter() / (std::f64::consts::PI * table.area());
        assert!((r.santalo_rate_alpha0 - santalo).abs() < 1e-12);
        assert!((r.relative_nu()[0].1.value - r.nu[0].1.value / santalo).abs() < 1e-12);
        assert_eq!(r.lambda_drop, curve.summary().relative_drop);
        assert!(r.to_string().starts_with("stadium: nu falls "));
    }
}
