//! One trajectory of an ensemble: its finite-time exponent and what it cost.
//!
//! Documented in the group docs (`run/mod.rs`), section "Trajectories".

use std::ops::Range;

use rand::Rng;
use spinball_core::{Billiard, Sampler, State};
use spinball_geometry::Boundary;

use super::parallel::{Threads, map_chunks};
use super::starts::Starts;
use crate::error::AnalysisError;
use crate::estimators::{LyapunovOptions, Method, largest_lyapunov};

/// What one trajectory of an ensemble produced.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TrajectoryStats {
    /// Index of the initial condition.
    pub index: u64,
    /// Finite-time exponent per unit time, `Σ ln(stretch) / time`.
    pub exponent: f64,
    /// Finite-time exponent per collision, `Σ ln(stretch) / collisions`.
    pub per_collision: f64,
    /// Total flight time of the reference trajectory.
    pub time: f64,
    /// Collisions taken.
    pub collisions: u64,
}

/// The finite-time Lyapunov exponent of initial condition `index` of the run
/// with `seed`: draws the state with `sampler` from
/// [`ic_rng(seed, index)`](spinball_core::ic_rng), then runs
/// [`largest_lyapunov`] for `collisions` collisions with `method`, drawing
/// the perturbation direction from the same stream.
///
/// ```
/// use spinball_analysis::estimators::Method;
/// use spinball_analysis::run::trajectory_ftle;
/// use spinball_core::{Billiard, Sampler, SpinLaw};
/// use spinball_geometry::Stadium;
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.0)?);
/// let t = trajectory_ftle(&billiard, Sampler::Paper, 7, 3, 5_000, Method::default())?;
/// assert_eq!((t.index, t.collisions), (3, 5_000));
/// assert!(t.exponent > 0.3 && t.exponent < 0.6); // specular stadium: λ ≈ 0.43
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// As [`largest_lyapunov`], with launch and step errors tagged with `index`.
pub fn trajectory_ftle<B: Boundary>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    index: u64,
    collisions: u64,
    method: Method,
) -> Result<TrajectoryStats, AnalysisError> {
    start_ftle(
        billiard,
        &Starts::Sampled(sampler),
        seed,
        index,
        collisions,
        method,
    )
}

/// [`trajectory_ftle`] for initial condition `index` of `starts`.
pub(crate) fn start_ftle<B: Boundary>(
    billiard: &Billiard<B>,
    starts: &Starts,
    seed: u64,
    index: u64,
    collisions: u64,
    method: Method,
) -> Result<TrajectoryStats, AnalysisError> {
    let (start, mut rng) = starts.draw(billiard.table(), billiard.law(), seed, index)?;
    ftle_from(billiard, start, &mut rng, index, collisions, method)
}

fn ftle_from<B: Boundary, R: Rng>(
    billiard: &Billiard<B>,
    start: State,
    rng: &mut R,
    index: u64,
    collisions: u64,
    method: Method,
) -> Result<TrajectoryStats, AnalysisError> {
    let options = LyapunovOptions::new(collisions, method);
    let lyap = largest_lyapunov(billiard, start, &options, rng).map_err(|e| e.at_index(index))?;
    Ok(TrajectoryStats {
        index,
        exponent: lyap.exponent,
        per_collision: lyap.per_collision,
        time: lyap.time,
        collisions: lyap.collisions,
    })
}

/// [`trajectory_ftle`] for every index in `indices`, in index order, on
/// `threads`, on the scalar path. Works for any table type; the result is
/// the same for any thread count. For estimates with errors use
/// [`Ensemble`](crate::run::Ensemble), which also runs in lanes.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for zero collisions, a bad method or
/// `Threads::Fixed(0)`; otherwise the first trajectory error.
pub fn ftle_trajectories<B: Boundary + Sync>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    indices: Range<u64>,
    collisions: u64,
    method: Method,
    threads: Threads,
) -> Result<Vec<TrajectoryStats>, AnalysisError> {
    LyapunovOptions::new(collisions, method).validate()?;
    threads.validate()?;
    scalar_chunked(
        billiard,
        &Starts::Sampled(sampler),
        seed,
        indices,
        collisions,
        method,
        threads,
    )
}

/// The scalar engine: [`start_ftle`] over `indices` in load-balancing
/// chunks on `threads`, in index order.
pub(crate) fn scalar_chunked<B: Boundary + Sync>(
    billiard: &Billiard<B>,
    starts: &Starts,
    seed: u64,
    indices: Range<u64>,
    collisions: u64,
    method: Method,
    threads: Threads,
) -> Result<Vec<TrajectoryStats>, AnalysisError> {
    let n = indices.end.saturating_sub(indices.start);
    // Chunks only balance the load; results do not depend on their size.
    let chunk = (n / (8 * threads.count() as u64)).clamp(1, 64);
    map_chunks(indices, chunk, threads, |range| {
        range
            .map(|i| start_ftle(billiard, starts, seed, i, collisions, method))
            .collect()
    })
}
