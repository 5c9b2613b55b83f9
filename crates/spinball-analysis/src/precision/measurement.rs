//! Values with errors: a [`Measurement`] (value ± SEM) with the rules for
//! ratios and differences, and the derived quantities the paper's figures
//! plot from estimates: the Datseris–Hupe–Fleischmann product, λ(α)/λ(α₀),
//! paired differences on common initial conditions.
//!
//! Documented in the group docs (`precision/mod.rs`), section "Values with errors".

use crate::error::AnalysisError;
use crate::estimators::Accumulator;
use crate::run::LyapunovEstimate;

// ---------------------------------------------------------------------------
// Values with errors
// ---------------------------------------------------------------------------

/// A value with its standard error.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Measurement {
    /// The value.
    pub value: f64,
    /// Its standard error (first-order propagation where derived).
    pub sem: f64,
}

impl Measurement {
    /// `value ± sem`.
    pub fn new(value: f64, sem: f64) -> Self {
        Measurement { value, sem }
    }

    /// The mean exponent of an estimate with its SEM.
    pub fn lambda(estimate: &LyapunovEstimate) -> Self {
        Measurement::new(estimate.mean, estimate.sem)
    }

    /// `self / other` for **independent** measurements (relative errors
    /// added in quadrature). Positively correlated inputs (for example the
    /// same initial positions at two α) make this an overestimate.
    pub fn ratio(self, other: Measurement) -> Measurement {
        let r = self.value / other.value;
        let rel = (self.sem / self.value).hypot(other.sem / other.value);
        Measurement::new(r, (r * rel).abs())
    }

    /// `value − other.value` for independent measurements.
    pub fn difference(self, other: Measurement) -> Measurement {
        Measurement::new(self.value - other.value, self.sem.hypot(other.sem))
    }

    /// `sem / |value|`.
    pub fn rel_sem(&self) -> f64 {
        self.sem / self.value.abs()
    }
}

/// The Datseris–Hupe–Fleischmann product `λ · f_ch` of an estimate (at its
/// threshold) with its standard error.
///
/// Both factors are means over the same trajectories (`x_i` and the
/// indicator `c_i = [x_i > threshold]`), so the error is propagated with
/// their covariance: `Var(λ f) ≈ (f² s_x² + λ² s_c² + 2 λ f s_xc) / n`.
/// DH scaling (`λ ∝ 1/f_ch`) predicts the product constant in α; the paper
/// finds it falls by a factor 2–3 (its appendix on DH scaling).
pub fn dhf_product(estimate: &LyapunovEstimate) -> Measurement {
    let t = &estimate.trajectories;
    let n = t.len() as f64;
    let (lam, f) = (estimate.mean, estimate.chaotic_fraction);
    let value = lam * f;
    if t.len() < 2 {
        return Measurement::new(value, f64::NAN);
    }
    let (mut sxx, mut scc, mut sxc) = (0.0, 0.0, 0.0);
    for s in t {
        let dx = s.exponent - lam;
        let dc = f64::from(u8::from(s.exponent > estimate.threshold)) - f;
        sxx += dx * dx;
        scc += dc * dc;
        sxc += dx * dc;
    }
    let var = (f * f * sxx + lam * lam * scc + 2.0 * lam * f * sxc) / ((n - 1.0) * n);
    Measurement::new(value, var.max(0.0).sqrt())
}

/// `λ(α)/λ(α₀)` for every estimate, with `α₀` the first one's (a sweep that
/// starts at α = 0 gives the paper's normalised curve). Errors combine the
/// two SEMs as for independent runs ([`Measurement::ratio`]).
pub fn normalised(estimates: &[LyapunovEstimate]) -> Vec<Measurement> {
    let Some(first) = estimates.first() else {
        return Vec::new();
    };
    let reference = Measurement::lambda(first);
    estimates
        .iter()
        .enumerate()
        .map(|(i, e)| {
            if i == 0 {
                // Exactly 1; its own error is carried by the other points.
                Measurement::new(1.0, 0.0)
            } else {
                Measurement::lambda(e).ratio(reference)
            }
        })
        .collect()
}

/// The paired difference `b − a` of the per-trajectory exponents of two
/// estimates over their common initial conditions (same seed, table, α and
/// sampler; for example the finite-difference and exact-tangent methods),
/// with the standard error of the mean difference. Pairs remove the
/// trajectory-to-trajectory spread that dominates each SEM alone.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] if the estimates do not share a seed,
/// table, α, sampler, first index and collisions, or share fewer than two
/// initial conditions.
pub fn paired_difference(
    a: &LyapunovEstimate,
    b: &LyapunovEstimate,
) -> Result<Measurement, AnalysisError> {
    if a.seed != b.seed
        || a.table != b.table
        || a.alpha.to_bits() != b.alpha.to_bits()
        || a.sampler != b.sampler
        || a.first_index != b.first_index
        || a.collisions_per_ic != b.collisions_per_ic
    {
        return Err(AnalysisError::invalid(
            "paired difference",
            "the estimates must share seed, table, alpha, sampler, first index and collisions",
        ));
    }
    let d: Accumulator = a
        .trajectories
        .iter()
        .zip(&b.trajectories)
        .map(|(x, y)| y.exponent - x.exponent)
        .collect();
    match (d.mean(), d.sem()) {
        (Some(m), Some(s)) => Ok(Measurement::new(m, s)),
        _ => Err(AnalysisError::invalid(
            "paired difference",
            "need at least two common initial conditions",
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimators::Method;
    use crate::test_support::{at, template};
    #[test]
    fn dhf_product_error_matches_bootstrap_scale() {
        let e = at(template(), 1.0)
            .with_ics(300)
            .with_collisions(500)
            .with_seed(9)
            .run()
            .unwrap();
        let p = dhf_product(&e);
        assert_eq!(p.value, e.mean * e.chaotic_fraction);
        // The product's relative error is of the order of λ's.
        assert!(
            p.sem > 0.3 * e.sem * e.chaotic_fraction && p.sem < 3.0 * e.sem,
            "{p:?} {e}"
        );
        // The same number as the FTLE distribution's product.
        assert_eq!(p.value, e.ftle().unwrap().dhf_product(e.threshold));
    }

    #[test]
    fn normalisation_and_pairs() {
        let fd = at(template(), 0.5).with_ics(60).run().unwrap();
        let tangent = at(template(), 0.5)
            .with_ics(60)
            .with_method(Method::Tangent)
            .run()
            .unwrap();
        let d = paired_difference(&fd, &tangent).unwrap();
        // Same initial conditions and directions: the methods agree far
        // better than either SEM.
        assert!(
            d.value.abs() < 0.2 * fd.sem && d.sem < 0.2 * fd.sem,
            "{d:?}"
        );
        let other_alpha = template().with_ics(60).run().unwrap();
        assert!(paired_difference(&fd, &other_alpha).is_err());

        let n = normalised(&[other_alpha.clone(), fd.clone()]);
        assert_eq!(n[0], Measurement::new(1.0, 0.0));
        assert!((n[1].value - fd.mean / other_alpha.mean).abs() < 1e-15);
        assert!(n[1].sem > 0.0);
        assert!(normalised(&[]).is_empty());
    }

    #[test]
    fn measurement_rules() {
        let a = Measurement::new(2.0, 0.2);
        let b = Measurement::new(4.0, 0.4);
        let r = a.ratio(b);
        assert!((r.value - 0.5).abs() < 1e-15);
        assert!((r.sem - 0.5 * 0.1 * 2f64.sqrt()).abs() < 1e-15);
        let d = b.difference(a);
        assert_eq!(d.value, 2.0);
        assert!((d.sem - 0.2 * 5f64.sqrt()).abs() < 1e-15);
        assert!((a.rel_sem() - 0.1).abs() < 1e-15);
    }
}
