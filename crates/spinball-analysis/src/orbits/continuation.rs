//! Following a periodic orbit as α changes, and the α where its stability
//! changes, found to a requested precision.
//!
//! Documented in the group docs (`orbits/mod.rs`), section "Continuation in α".

use spinball_core::{Billiard, SpinLaw};
use spinball_geometry::Boundary;

use super::finder::{NewtonOptions, PeriodicOrbit, find_orbit};
use super::stability::StabilityClass;
use crate::error::AnalysisError;

/// How many times a step in α is halved when Newton loses the orbit.
const MAX_HALVINGS: u32 = 20;

/// Where the stability of a followed orbit changes: the pair trace `T`
/// crosses `+2` (residue 0) or `−2` (residue 1).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct StabilityChange {
    /// The α of the crossing, the middle of the final bracket.
    pub alpha: f64,
    /// Half the width of the final bracket: the crossing lies within
    /// `alpha ± error` (for a continuous trace; the bracket's ends have
    /// traces on either side of `crossing`). Zero where the orbit is
    /// parabolic at an α of the list itself (`|T ∓ 2|` within the class
    /// tolerance there, as for the bouncing ball at α = 0 and α = 1).
    pub error: f64,
    /// `+2` or `−2`: which boundary of the elliptic band `|T| < 2` is crossed.
    pub crossing: f64,
    /// The class at the α of the list just below the crossing (at the
    /// bracket's own ends the orbit is parabolic within the tolerance).
    pub before: StabilityClass,
    /// The class at the α of the list just above it.
    pub after: StabilityClass,
}

/// An orbit followed through a list of α, and where its stability changes.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Continuation {
    /// The orbit at each α asked for, in that order.
    pub orbits: Vec<PeriodicOrbit>,
    /// Every crossing of `T = ±2` between neighbouring α, in order.
    pub changes: Vec<StabilityChange>,
}

/// The same orbit under spin parameter `alpha`, by Newton's method from
/// `near` (an orbit of the same table at a nearby α).
///
/// # Errors
/// An α that is negative or not finite, or Newton's errors.
pub fn orbit_at<B: Boundary>(
    table: &B,
    alpha: f64,
    near: &PeriodicOrbit,
    options: &NewtonOptions,
) -> Result<PeriodicOrbit, AnalysisError> {
    let billiard = Billiard::new(table, SpinLaw::extended(alpha)?);
    find_orbit(&billiard, near.points[0], near.period, options)
}

/// Follow `orbit` through `alphas` (each Newton starts from the orbit at the
/// previous α; a step that loses it is halved up to 20 times), then locate
/// every change of stability between neighbours to `precision` in α by
/// bisection on the sign of `T ∓ 2`; an α of the list where the orbit is
/// parabolic is a change of its own (error 0).
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for an empty list, a non-finite or
/// negative α, or `precision` not in `(0, 1)`; [`AnalysisError::NotClosed`]
/// (with its residual) if the orbit is lost, for instance where it meets a
/// corner or turns grazing.
pub fn follow_in_alpha<B: Boundary>(
    table: &B,
    orbit: &PeriodicOrbit,
    alphas: &[f64],
    precision: f64,
    options: &NewtonOptions,
) -> Result<Continuation, AnalysisError> {
    if alphas.is_empty() {
        return Err(AnalysisError::invalid("alphas", "need at least one α"));
    }
    if let Some(bad) = alphas.iter().find(|a| !(a.is_finite() && **a >= 0.0)) {
        return Err(AnalysisError::invalid(
            "alphas",
            format!("every α must be finite and >= 0, got {bad}"),
        ));
    }
    if !(precision > 0.0 && precision < 1.0) {
        return Err(AnalysisError::invalid(
            "precision",
            format!("must be in (0, 1), got {precision}"),
        ));
    }
    let mut orbits: Vec<PeriodicOrbit> = Vec::with_capacity(alphas.len());
    let mut current = orbit.clone();
    for &alpha in alphas {
        current = step_to(table, &current, alpha, options)?;
        orbits.push(current.clone());
    }
    let mut changes = Vec::new();
    for crossing in [2.0, -2.0] {
        // −1, +1, or 0 where the orbit is parabolic at this crossing.
        let side = |o: &PeriodicOrbit| {
            let d = o.stability.pair_trace - crossing;
            if d.abs() <= o.stability.tolerance {
                0.0
            } else {
                d.signum()
            }
        };
        let sides: Vec<f64> = orbits.iter().map(side).collect();
        for i in 0..orbits.len() {
            // Parabolic at an α of the list (and not just before): the
            // change is there, to the class tolerance on T.
            if sides[i] == 0.0 && (i == 0 || sides[i - 1] != 0.0) {
                let class = |j: usize| orbits[j].stability.class;
                changes.push(StabilityChange {
                    alpha: orbits[i].alpha,
                    error: 0.0,
                    crossing,
                    before: class(i.saturating_sub(1)),
                    after: class((i + 1).min(orbits.len() - 1)),
                });
            }
            if i + 1 < orbits.len() && sides[i] * sides[i + 1] < 0.0 {
                changes.push(bisect(
                    table,
                    &orbits[i],
                    &orbits[i + 1],
                    crossing,
                    precision,
                    options,
                )?);
            }
        }
    }
    changes.sort_by(|a, b| a.alpha.total_cmp(&b.alpha));
    Ok(Continuation { orbits, changes })
}

/// The orbit at `alpha` from the one at `from.alpha`, halving the step in α
/// while Newton loses it.
fn step_to<B: Boundary>(
    table: &B,
    from: &PeriodicOrbit,
    alpha: f64,
    options: &NewtonOptions,
) -> Result<PeriodicOrbit, AnalysisError> {
    let mut current = from.clone();
    let mut halvings = 0;
    while current.alpha != alpha {
        let mut target = alpha;
        loop {
            match orbit_at(table, target, &current, options) {
                Ok(next) => {
                    current = next;
                    break;
                }
                Err(e) if halvings >= MAX_HALVINGS => return Err(e),
                Err(_) => {
                    halvings += 1;
                    target = 0.5 * (current.alpha + target);
                }
            }
        }
    }
    Ok(current)
}

/// Bisection between `lo` and `hi` on the sign of `T − crossing`.
fn bisect<B: Boundary>(
    table: &B,
    lo: &PeriodicOrbit,
    hi: &PeriodicOrbit,
    crossing: f64,
    precision: f64,
    options: &NewtonOptions,
) -> Result<StabilityChange, AnalysisError> {
    let side = |o: &PeriodicOrbit| (o.stability.pair_trace - crossing).signum();
    let (before, after) = if lo.alpha < hi.alpha {
        (lo.stability.class, hi.stability.class)
    } else {
        (hi.stability.class, lo.stability.class)
    };
    let (mut lo, mut hi) = (lo.clone(), hi.clone());
    while (hi.alpha - lo.alpha).abs() > 2.0 * precision {
        let mid_alpha = 0.5 * (lo.alpha + hi.alpha);
        if mid_alpha == lo.alpha || mid_alpha == hi.alpha {
            break;
        }
        let mid = step_to(table, &lo, mid_alpha, options)?;
        if side(&mid) == side(&lo) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(StabilityChange {
        alpha: 0.5 * (lo.alpha + hi.alpha),
        error: 0.5 * (hi.alpha - lo.alpha).abs(),
        crossing,
        before,
        after,
    })
}
