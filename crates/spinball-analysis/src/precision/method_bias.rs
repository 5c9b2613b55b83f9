//! Method bias: what the finite-difference exponent (the paper's Benettin
//! method with a shadow trajectory at distance `δ0`) differs by from the
//! exact tangent exponent on the **same** initial conditions and directions.
//!
//! Documented in the group docs (`precision/mod.rs`), section "Method bias".

use spinball_geometry::Boundary;

use super::measurement::{Measurement, paired_difference};
use crate::error::AnalysisError;
use crate::estimators::Method;
use crate::run::{Ensemble, LyapunovEstimate};

/// The paired difference finite differences − tangent on common initial
/// conditions.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct MethodBias {
    /// The finite-difference separation `δ0`.
    pub delta0: f64,
    /// Mean of `λ_fd − λ_tangent` over the pairs, with its paired SEM.
    pub difference: Measurement,
    /// Initial conditions paired.
    pub n_ics: u64,
    /// Collisions per trajectory.
    pub collisions: u64,
}

impl MethodBias {
    /// The bias of the finite-difference estimate `fd` against the tangent
    /// estimate `tangent` over the same initial conditions.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if `fd` is not a finite-difference
    /// run, `tangent` not a tangent run, or they do not share their initial
    /// conditions (see [`paired_difference`]).
    pub fn from_estimates(
        fd: &LyapunovEstimate,
        tangent: &LyapunovEstimate,
    ) -> Result<Self, AnalysisError> {
        let (Method::FiniteDifference { delta0 }, Method::Tangent) = (fd.method, tangent.method)
        else {
            return Err(AnalysisError::invalid(
                "method bias",
                format!(
                    "needs a finite-difference and a tangent estimate, got {} and {}",
                    fd.method.name(),
                    tangent.method.name()
                ),
            ));
        };
        if fd.n_ics != tangent.n_ics {
            return Err(AnalysisError::invalid(
                "method bias",
                format!(
                    "the estimates cover {} and {} initial conditions",
                    fd.n_ics, tangent.n_ics
                ),
            ));
        }
        Ok(MethodBias {
            delta0,
            difference: paired_difference(tangent, fd)?,
            n_ics: fd.n_ics,
            collisions: fd.collisions_per_ic,
        })
    }

    /// Run `ensemble` with finite differences at `delta0` and with the
    /// tangent method (same initial conditions, directions and engine) and
    /// pair them. Returns the bias and both estimates.
    ///
    /// ```
    /// use spinball_analysis::run::Ensemble;
    /// use spinball_analysis::precision::MethodBias;
    /// use spinball_core::SpinLaw;
    /// use spinball_geometry::Stadium;
    ///
    /// let ensemble = Ensemble::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?)
    ///     .with_ics(16)
    ///     .with_collisions(2_000)
    ///     .with_seed(4);
    /// let (bias, fd, tangent) = MethodBias::measure(&ensemble, 1e-7)?;
    /// // Paired: far below the spread of either mean.
    /// assert!(bias.difference.sem < 0.1 * fd.sem().min(tangent.sem()));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// As [`Ensemble::run`] (a bad `delta0` is refused there), then as
    /// [`from_estimates`](Self::from_estimates).
    pub fn measure<B: Boundary + Clone + Sync>(
        ensemble: &Ensemble<B>,
        delta0: f64,
    ) -> Result<(Self, LyapunovEstimate, LyapunovEstimate), AnalysisError> {
        let fd = ensemble
            .clone()
            .with_method(Method::FiniteDifference { delta0 })
            .run()?;
        let tangent = ensemble.clone().with_method(Method::Tangent).run()?;
        Ok((Self::from_estimates(&fd, &tangent)?, fd, tangent))
    }
}
