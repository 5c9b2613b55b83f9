//! Is a finite-time exponent converged? Running-exponent (LCN) traces of one
//! trajectory and ensemble estimates at several run lengths (paper, appendix
//! "Convergence of LCN estimates", its Fig. of LCN traces and Table I).
//!
//! Documented in the group docs (`precision/mod.rs`), section "Convergence".

use std::{fmt::Write as _, time::Instant};

use rand::Rng;
use spinball_core::{Billiard, Sampler, SpinLaw, State, ic_rng};
use spinball_geometry::Boundary;

use crate::error::AnalysisError;
use crate::estimators::{HistoryPoint, LyapunovOptions, Method, largest_lyapunov};
use crate::run::{
    Engine, Ensemble, LyapunovEstimate, Starts, StopReason, TrajectoryStats, map_indices,
};

/// The running exponent of one trajectory at log-spaced collision counts.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LcnTrace {
    /// Running exponent per unit time after `collisions` collisions, at
    /// roughly `points_per_decade` counts per decade (always including the
    /// last collision).
    pub points: Vec<HistoryPoint>,
    /// The final exponent (the last point's).
    pub exponent: f64,
    /// Collisions run.
    pub collisions: u64,
    /// How it was measured.
    pub method: Method,
}

/// The running Lyapunov exponent of the trajectory from `start` over
/// `collisions` collisions, kept at about `points_per_decade` log-spaced
/// collision counts (paper: 10⁵ collisions, `θ0 = 0.8`, `u0 = 0`, four
/// tables, five α). `rng` draws the initial perturbation direction, as in
/// [`largest_lyapunov`].
///
/// The running exponent is recorded at every collision up to `10⁵`
/// collisions and every `⌈collisions/10⁵⌉` beyond, then thinned; the memory
/// used is bounded by that.
///
/// ```
/// use spinball_analysis::estimators::Method;
/// use spinball_analysis::precision::lcn_trace;
/// use spinball_core::{Billiard, SpinLaw, State, ic_rng};
/// use spinball_geometry::{Circle, DVec2, Stadium};
///
/// let start = State::new(DVec2::new(0.3, 0.2), DVec2::from_angle(0.8), 0.0);
/// let chaotic = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.0)?);
/// let trace = lcn_trace(&chaotic, start, 20_000, Method::default(), 20, &mut ic_rng(1, 0))?;
/// assert!(trace.exponent > 0.3); // plateau at λ ≈ 0.43
/// let integrable = Billiard::new(Circle::new(1.0)?, SpinLaw::new(0.0)?);
/// let trace = lcn_trace(&integrable, start, 20_000, Method::default(), 20, &mut ic_rng(1, 0))?;
/// assert!(trace.exponent < 0.01); // decays like ln t / t
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for zero collisions or
/// `points_per_decade = 0`; otherwise as [`largest_lyapunov`].
pub fn lcn_trace<B: Boundary, R: Rng + ?Sized>(
    billiard: &Billiard<B>,
    start: State,
    collisions: u64,
    method: Method,
    points_per_decade: u32,
    rng: &mut R,
) -> Result<LcnTrace, AnalysisError> {
    if points_per_decade == 0 {
        return Err(AnalysisError::invalid("points_per_decade", "must be > 0"));
    }
    let stride = collisions.div_ceil(100_000).max(1);
    let options = LyapunovOptions::new(collisions, method).with_history(stride);
    let lyap = largest_lyapunov(billiard, start, &options, rng)?;
    let step = 10f64.powf(1.0 / f64::from(points_per_decade));
    let mut points: Vec<HistoryPoint> = Vec::new();
    let mut next = 1.0;
    for p in &lyap.history {
        if p.collisions as f64 >= next {
            points.push(*p);
            while next <= p.collisions as f64 {
                next *= step;
            }
        }
    }
    if points.last().map(|p| p.collisions) != Some(collisions) {
        points.push(HistoryPoint {
            collisions,
            time: lyap.time,
            exponent: lyap.exponent,
        });
    }
    Ok(LcnTrace {
        points,
        exponent: lyap.exponent,
        collisions,
        method,
    })
}

/// [`lcn_trace`] of the trajectory from `start` on `table` at each of
/// `alphas` (the paper's figure of LCN traces: one start, five α), as
/// `(α, trace)`. Every α draws its perturbation direction from a fresh
/// `ic_rng(seed, 0)`, so the traces differ only by the spin law.
///
/// # Errors
/// [`AnalysisError::SpinLaw`] for an α outside `[0, ∞)`; otherwise as
/// [`lcn_trace`].
pub fn lcn_traces<B: Boundary + Clone>(
    table: &B,
    start: State,
    alphas: &[f64],
    collisions: u64,
    method: Method,
    points_per_decade: u32,
    seed: u64,
) -> Result<Vec<(f64, LcnTrace)>, AnalysisError> {
    alphas
        .iter()
        .map(|&alpha| {
            let billiard = Billiard::new(table.clone(), SpinLaw::new(alpha)?);
            let mut rng = ic_rng(seed, 0);
            let trace = lcn_trace(
                &billiard,
                start,
                collisions,
                method,
                points_per_decade,
                &mut rng,
            )?;
            Ok((alpha, trace))
        })
        .collect()
}

/// Per-trajectory results of initial condition `index` after each of
/// `checkpoints` collisions (increasing), from one run to the last.
/// Element `k` equals [`trajectory_ftle`](crate::run::trajectory_ftle) with
/// `checkpoints[k]` collisions in `exponent`, `time` and `collisions`
/// (bitwise); `per_collision` is `exponent · time / collisions`, equal to
/// rounding.
///
/// # Errors
/// As [`largest_lyapunov`], tagged with `index`.
pub fn trajectory_checkpoints<B: Boundary>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    index: u64,
    checkpoints: &[u64],
    method: Method,
) -> Result<Vec<TrajectoryStats>, AnalysisError> {
    start_checkpoints(
        billiard,
        &Starts::Sampled(sampler),
        seed,
        index,
        checkpoints,
        method,
    )
}

/// [`trajectory_checkpoints`] for initial condition `index` of `starts`.
pub(crate) fn start_checkpoints<B: Boundary>(
    billiard: &Billiard<B>,
    starts: &Starts,
    seed: u64,
    index: u64,
    checkpoints: &[u64],
    method: Method,
) -> Result<Vec<TrajectoryStats>, AnalysisError> {
    check_checkpoints(checkpoints)?;
    let last = *checkpoints.last().expect("checked non-empty");
    let stride = checkpoints.iter().fold(0, |g, &c| gcd(g, c));
    let (start, mut rng) = starts.draw(billiard.table(), billiard.law(), seed, index)?;
    let options = LyapunovOptions::new(last, method).with_history(stride);
    let lyap =
        largest_lyapunov(billiard, start, &options, &mut rng).map_err(|e| e.at_index(index))?;
    checkpoints
        .iter()
        .map(|&c| {
            let p = lyap.history[(c / stride - 1) as usize];
            debug_assert_eq!(p.collisions, c);
            Ok(TrajectoryStats {
                index,
                exponent: p.exponent,
                per_collision: p.exponent * p.time / c as f64,
                time: p.time,
                collisions: c,
            })
        })
        .collect()
}

fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 { a } else { gcd(b, a % b) }
}

fn check_checkpoints(checkpoints: &[u64]) -> Result<(), AnalysisError> {
    if checkpoints.is_empty() {
        return Err(AnalysisError::invalid("checkpoints", "need at least one"));
    }
    if checkpoints[0] == 0 || checkpoints.windows(2).any(|w| w[1] <= w[0]) {
        return Err(AnalysisError::invalid(
            "checkpoints",
            format!("must be positive and strictly increasing, got {checkpoints:?}"),
        ));
    }
    Ok(())
}

/// The ensemble estimate of the largest exponent after each of
/// `checkpoints` collisions (strictly increasing), for the table, law,
/// sampler, seed, index range, method, engine, threads and threshold of
/// `ensemble` (its own `collisions` is not used). Estimate `k` has
/// `collisions_per_ic = checkpoints[k]` and equals `ensemble` run with that
/// many collisions.
///
/// With [`Engine::Lanes`] (the default) every column is a separate
/// [`Ensemble::run`] with its own `wall_time_s`; cost `n_ics × Σ checkpoints`
/// steps in the lane kernels. With [`Engine::Scalar`] one nested run reads
/// every column (see the [module docs](crate::precision#convergence)); cost `n_ics ×
/// max(checkpoints)` scalar steps, and every estimate carries the wall time
/// of the whole nested run.
///
/// ```
/// use spinball_analysis::run::{Engine, Ensemble};
/// use spinball_analysis::precision::convergence_estimates;
/// use spinball_core::SpinLaw;
/// use spinball_geometry::Sinai;
///
/// let ensemble = Ensemble::new(Sinai::new(2.0, 1.0)?, SpinLaw::new(0.5)?)
///     .with_ics(16)
///     .with_seed(3)
///     .with_engine(Engine::Scalar); // one nested run
/// let columns = convergence_estimates(&ensemble, &[1_000, 4_000])?;
/// assert_eq!(columns[1].collisions_per_ic(), 4_000);
/// let direct = ensemble.with_collisions(1_000).run()?;
/// assert_eq!(columns[0].mean(), direct.mean()); // bitwise
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for empty, non-increasing or zero
/// checkpoints and as [`Ensemble::validate`]; then the first trajectory
/// error.
pub fn convergence_estimates<B: Boundary + Clone + Sync>(
    ensemble: &Ensemble<B>,
    checkpoints: &[u64],
) -> Result<Vec<LyapunovEstimate>, AnalysisError> {
    check_checkpoints(checkpoints)?;
    ensemble.validate()?;
    if ensemble.engine_used() == Engine::Lanes {
        return checkpoints
            .iter()
            .map(|&c| ensemble.clone().with_collisions(c).run())
            .collect();
    }
    let clock = Instant::now();
    let billiard = Billiard::new(&ensemble.table, ensemble.law);
    let per_ic = map_indices(ensemble.indices.clone(), ensemble.threads, |i| {
        start_checkpoints(
            &billiard,
            &ensemble.starts,
            ensemble.seed,
            i,
            checkpoints,
            ensemble.method,
        )
    })?;
    let wall = clock.elapsed().as_secs_f64();
    checkpoints
        .iter()
        .enumerate()
        .map(|(k, &c)| {
            let column = per_ic.iter().map(|row| row[k]).collect();
            LyapunovEstimate::from_trajectories(
                &ensemble.clone().with_collisions(c).provenance(),
                column,
                wall,
                StopReason::Completed,
            )
        })
        .collect()
}

/// `mean(SEM)` with `decimals` decimals and the SEM in units of the last
/// digit, rounded (the paper's notation: `0.183(1)` is `0.183 ± 0.001`;
/// `0.281(0)` a SEM below half a unit of the last digit). A SEM of 100
/// units or more is written out as `(±sem)`.
///
/// ```
/// use spinball_analysis::precision::format_mean_sem;
/// assert_eq!(format_mean_sem(0.18312, 0.0006, 3), "0.183(1)");
/// assert_eq!(format_mean_sem(0.2805, 0.0002, 3), "0.281(0)");
/// assert_eq!(format_mean_sem(0.1466, 0.0031, 4), "0.1466(31)");
/// ```
pub fn format_mean_sem(mean: f64, sem: f64, decimals: usize) -> String {
    let unit = 10f64.powi(-(decimals as i32));
    let units = (sem / unit).round();
    let mut s = format!("{mean:.decimals$}");
    if units.is_finite() && units < 100.0 {
        let _ = write!(s, "({})", units as u64);
    } else {
        let _ = write!(s, "(±{sem:.decimals$})");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::run::trajectory_ftle;
    use spinball_geometry::{Circle, DVec2, Stadium};

    #[test]
    fn checkpoints_match_separate_runs_bitwise() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        for method in [Method::default(), Method::Tangent] {
            let rows =
                trajectory_checkpoints(&billiard, Sampler::Paper, 9, 4, &[300, 1200, 3000], method)
                    .unwrap();
            for row in rows {
                let direct =
                    trajectory_ftle(&billiard, Sampler::Paper, 9, 4, row.collisions, method)
                        .unwrap();
                assert_eq!(row.exponent.to_bits(), direct.exponent.to_bits());
                assert_eq!(row.time.to_bits(), direct.time.to_bits());
                assert!((row.per_collision - direct.per_collision).abs() < 1e-14);
            }
        }
    }

    #[test]
    fn both_engines_give_the_same_columns() {
        let ensemble = Ensemble::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.3).unwrap())
            .with_ics(12)
            .with_seed(5);
        let lanes = convergence_estimates(&ensemble, &[500, 2_000]).unwrap();
        let scalar =
            convergence_estimates(&ensemble.clone().with_engine(Engine::Scalar), &[500, 2_000])
                .unwrap();
        for (a, b) in lanes.iter().zip(&scalar) {
            assert_eq!(a.collisions_per_ic, b.collisions_per_ic);
            assert!(
                (a.mean - b.mean).abs() <= 1e-12 * a.mean.abs(),
                "{} {}",
                a.mean,
                b.mean
            );
        }
        let direct = ensemble
            .clone()
            .with_engine(Engine::Scalar)
            .with_collisions(2_000)
            .run()
            .unwrap();
        assert_eq!(scalar[1].mean.to_bits(), direct.mean.to_bits());
        assert!(convergence_estimates(&ensemble, &[2_000, 500]).is_err());
    }

    #[test]
    fn bad_checkpoints_are_refused() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        for bad in [&[][..], &[0, 10], &[10, 10], &[20, 10]] {
            assert!(
                trajectory_checkpoints(&billiard, Sampler::Paper, 1, 0, bad, Method::Tangent)
                    .is_err()
            );
        }
    }

    #[test]
    fn trace_is_log_spaced_and_ends_at_the_last_collision() {
        let billiard = Billiard::new(Circle::new(1.0).unwrap(), SpinLaw::new(0.3).unwrap());
        let start = State::new(DVec2::new(0.3, 0.2), DVec2::from_angle(0.8), 0.0);
        let trace = lcn_trace(
            &billiard,
            start,
            10_000,
            Method::default(),
            10,
            &mut ic_rng(0, 0),
        )
        .unwrap();
        let n: Vec<u64> = trace.points.iter().map(|p| p.collisions).collect();
        assert_eq!(n[0], 1);
        assert_eq!(*n.last().unwrap(), 10_000);
        assert!(n.windows(2).all(|w| w[1] > w[0]));
        assert!(n.len() > 35 && n.len() <= 42, "{}", n.len());
        assert!(lcn_trace(&billiard, start, 10, Method::Tangent, 0, &mut ic_rng(0, 0)).is_err());
    }

    #[test]
    fn mean_sem_notation() {
        assert_eq!(format_mean_sem(0.147, 0.0012, 3), "0.147(1)");
        assert_eq!(format_mean_sem(0.5, 0.2, 3), "0.500(±0.200)");
    }

    #[test]
    fn traces_per_alpha_repeat_single_traces() {
        let stadium = Stadium::new(1.0).unwrap();
        let start = State::new(DVec2::new(0.3, 0.2), DVec2::from_angle(0.8), 0.0);
        let method = Method::default();
        let traces = lcn_traces(&stadium, start, &[0.0, 0.5], 5_000, method, 10, 3).unwrap();
        assert_eq!(traces.len(), 2);
        for (alpha, trace) in &traces {
            let billiard = Billiard::new(stadium, SpinLaw::new(*alpha).unwrap());
            let single = lcn_trace(&billiard, start, 5_000, method, 10, &mut ic_rng(3, 0)).unwrap();
            assert_eq!(*trace, single, "α = {alpha}");
        }
        // The chaotic stadium at α = 0 levels off near λ ≈ 0.43 (paper §IV,
        // Fig. 2); one trajectory of 5000 collisions is within 0.15 of it.
        assert!(
            (traces[0].1.exponent - 0.43).abs() < 0.15,
            "{}",
            traces[0].1.exponent
        );
        assert!(lcn_traces(&stadium, start, &[-1.0], 100, method, 10, 3).is_err());
    }
}
