//! Energy conservation over long runs (paper, appendix "Energy
//! conservation"), and the same measurement for the paper's collision
//! formulas evaluated literally in components.
//!
//! Documented in the group docs (`diagnostics/mod.rs`), section "Energy conservation".

use spinball_core::{Billiard, Collision, EnergyMonitor, Observer, SpinLaw, State, StepError};
use spinball_geometry::{Boundary, DVec2};

use crate::error::AnalysisError;

/// `1, 2, 5, 10, 20, 50, …` below `n`, then `n` itself: log-spaced points
/// at which a long run is looked at. Empty for `n = 0`.
///
/// ```
/// assert_eq!(spinball_analysis::diagnostics::log_checkpoints(30), vec![1, 2, 5, 10, 20, 30]);
/// ```
pub fn log_checkpoints(n: u64) -> Vec<u64> {
    let mut out = Vec::new();
    if n == 0 {
        return out;
    }
    let mut decade: u64 = 1;
    'outer: loop {
        for m in [1, 2, 5] {
            match decade.checked_mul(m) {
                Some(c) if c < n => out.push(c),
                _ => break 'outer,
            }
        }
        match decade.checked_mul(10) {
            Some(d) => decade = d,
            None => break,
        }
    }
    out.push(n);
    out
}

/// The energy error of a run at one checkpoint.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnergyCheckpoint {
    /// Collisions so far.
    pub collisions: u64,
    /// Largest `|E_n − E_0|/E_0` over collisions `1..=collisions`.
    pub max_relative_deviation: f64,
    /// `(E_n − E_0)/E_0` after this collision (signed: a drift shows as a
    /// steady sign).
    pub relative_deviation: f64,
}

/// The energy error of one long run at log-spaced checkpoints.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnergyHistory {
    /// The energy `E_0` of the start.
    pub initial_energy: f64,
    /// One point per checkpoint of [`log_checkpoints`]`(collisions)`.
    pub points: Vec<EnergyCheckpoint>,
}

impl EnergyHistory {
    /// Largest `|E_n − E_0|/E_0` over the whole run (0 for an empty run).
    pub fn max_relative_deviation(&self) -> f64 {
        self.points.last().map_or(0.0, |p| p.max_relative_deviation)
    }

    /// `(E_N − E_0)/E_0` at the end of the run.
    pub fn final_relative_deviation(&self) -> f64 {
        self.points.last().map_or(0.0, |p| p.relative_deviation)
    }

    /// Collisions run.
    pub fn collisions(&self) -> u64 {
        self.points.last().map_or(0, |p| p.collisions)
    }
}

/// The energy error of the library's collision map over `collisions`
/// collisions from `start`, at [`log_checkpoints`].
///
/// ```
/// use spinball_analysis::diagnostics::energy_history;
/// use spinball_core::{Billiard, Sampler, SpinLaw};
/// use spinball_geometry::Stadium;
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?);
/// let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 1, 0);
/// let history = energy_history(&billiard, start, 100_000)?;
/// assert!(history.max_relative_deviation() < 1e-14);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for zero collisions; launch and step
/// errors of the dynamics.
pub fn energy_history<B: Boundary>(
    billiard: &Billiard<B>,
    start: State,
    collisions: u64,
) -> Result<EnergyHistory, AnalysisError> {
    if collisions == 0 {
        return Err(AnalysisError::invalid("collisions", "must be > 0"));
    }
    let mut ball = billiard.launch(start)?;
    let mut monitor = EnergyMonitor::new(*billiard.law(), &start);
    let mut done = 0;
    let mut points = Vec::new();
    for cp in log_checkpoints(collisions) {
        billiard.run(&mut ball, cp - done, &mut monitor)?;
        done = cp;
        points.push(EnergyCheckpoint {
            collisions: cp,
            max_relative_deviation: monitor.max_relative_deviation,
            relative_deviation: monitor.last_relative_deviation,
        });
    }
    Ok(EnergyHistory {
        initial_energy: start.energy(billiard.law()),
        points,
    })
}

/// The same measurement as [`energy_history`] for paper eqs. (1)–(3)
/// evaluated literally: `β = (1−α)/(1+α)`, `γ = 2α/(1+α)`, `δ = 2/(1+α)` in
/// floating point, `v∥ = v·t̂`, `v⊥ = v·n̂`, `v' = (β v∥ − γ u) t̂ − v⊥ n̂`,
/// `u' = −β u − δ v∥` (`u` left unchanged at α = 0, as in the paper's
/// reference code), no energy-shell restore. The walls, tangents and normals
/// are the library's, so the only difference from [`energy_history`] is the
/// arithmetic of the collision.
///
/// This is a *reference for comparison*, not a dynamics to use: it shows what
/// "energy conserved to ~1e-15" means for the paper's formulas over long
/// runs.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for zero collisions; a launch error for
/// a bad start; [`StepError::NoWall`] if a cast finds no wall.
pub fn component_law_energy_history<B: Boundary>(
    table: &B,
    law: &SpinLaw,
    start: State,
    collisions: u64,
) -> Result<EnergyHistory, AnalysisError> {
    if collisions == 0 {
        return Err(AnalysisError::invalid("collisions", "must be > 0"));
    }
    start.validate()?;
    let alpha = law.alpha();
    let beta = (1.0 - alpha) / (1.0 + alpha);
    let gamma = 2.0 * alpha / (1.0 + alpha);
    let delta = 2.0 / (1.0 + alpha);
    let energy = |v: DVec2, u: f64| 0.5 * (v.x * v.x + v.y * v.y + alpha * u * u);
    let (mut x, mut v, mut u) = (start.position, start.velocity, start.spin);
    let e0 = energy(v, u);
    let mut max_dev: f64 = 0.0;
    let mut points = Vec::new();
    let mut done = 0;
    for cp in log_checkpoints(collisions) {
        let mut dev = 0.0;
        for _ in done..cp {
            let hit = table.cast(x, v).ok_or(StepError::NoWall {
                position: x,
                velocity: v,
            })?;
            let (n, t) = (hit.normal, hit.tangent());
            let (v_par, v_perp) = (v.dot(t), v.dot(n));
            let v_par_new = beta * v_par - gamma * u;
            if alpha > 0.0 {
                u = -beta * u - delta * v_par;
            }
            v = t * v_par_new - n * v_perp;
            x = hit.point;
            dev = (energy(v, u) - e0) / e0;
            max_dev = max_dev.max(dev.abs());
        }
        done = cp;
        points.push(EnergyCheckpoint {
            collisions: cp,
            max_relative_deviation: max_dev,
            relative_deviation: dev,
        });
    }
    Ok(EnergyHistory {
        initial_energy: e0,
        points,
    })
}

/// One point of an [`EnergyTrace`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnergyPoint {
    /// Collisions so far (the end of the window).
    pub collisions: u64,
    /// Largest `|E_n − E_0|` over the window of `stride` collisions ending
    /// here (the maximum, so downsampling hides no spike).
    pub deviation: f64,
}

/// An [`Observer`] of the absolute energy deviation `|E_n − E_0|` (paper,
/// appendix "Energy conservation", eq. 4), keeping one point per `stride`
/// collisions.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnergyTrace {
    law: SpinLaw,
    e0: f64,
    stride: u64,
    seen: u64,
    window: f64,
    /// One point per `stride` collisions.
    pub points: Vec<EnergyPoint>,
    /// Largest `|E_n − E_0|` over the whole run.
    pub max_deviation: f64,
}

impl EnergyTrace {
    /// Compare with the energy of `start` under `law`, one point every
    /// `stride` collisions.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for `stride = 0`.
    pub fn new(law: SpinLaw, start: &State, stride: u64) -> Result<Self, AnalysisError> {
        if stride == 0 {
            return Err(AnalysisError::invalid("stride", "must be > 0"));
        }
        Ok(EnergyTrace {
            law,
            e0: start.energy(&law),
            stride,
            seen: 0,
            window: 0.0,
            points: Vec::new(),
            max_deviation: 0.0,
        })
    }

    /// The reference energy `E_0`.
    pub fn initial_energy(&self) -> f64 {
        self.e0
    }

    /// Share of the points whose deviation is exactly zero (the collision
    /// map returned the start's energy to the last bit); 0 without points.
    /// On a log axis these points need a floor of their own.
    #[must_use]
    pub fn exact_zero_fraction(&self) -> f64 {
        let zeros = self.points.iter().filter(|p| p.deviation == 0.0).count();
        zeros as f64 / self.points.len().max(1) as f64
    }
}

impl Observer for EnergyTrace {
    #[inline]
    fn observe(&mut self, _: &Collision, after: &State) {
        let d = (after.energy(&self.law) - self.e0).abs();
        self.seen += 1;
        self.window = self.window.max(d);
        self.max_deviation = self.max_deviation.max(d);
        if self.seen.is_multiple_of(self.stride) {
            self.points.push(EnergyPoint {
                collisions: self.seen,
                deviation: self.window,
            });
            self.window = 0.0;
        }
    }
}

/// The [`EnergyTrace`] of the trajectory from `start`.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for `stride = 0`; dynamics errors.
pub fn energy_trace<B: Boundary>(
    billiard: &Billiard<B>,
    start: State,
    collisions: u64,
    stride: u64,
) -> Result<EnergyTrace, AnalysisError> {
    let mut trace = EnergyTrace::new(*billiard.law(), &start, stride)?;
    let mut ball = billiard.launch(start)?;
    billiard.run(&mut ball, collisions, &mut trace)?;
    Ok(trace)
}

/// The paper's energy-conservation check of one start (appendix
/// "Energy conservation"): the per-collision trace of a short run, and the
/// long-run histories of the library's collision map and of the paper's
/// formulas in components, from the same start.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnergyConservation {
    /// `|E_n − E_0|` after every collision of the short run.
    pub trace: EnergyTrace,
    /// The library's map over the long run ([`energy_history`]).
    pub library: EnergyHistory,
    /// Paper eqs. (1)–(3) in components over the same run
    /// ([`component_law_energy_history`]).
    pub components: EnergyHistory,
}

/// [`energy_trace`] of `trace_collisions` collisions (every collision) and
/// both long-run histories of `long_collisions` collisions from `start`.
///
/// # Errors
/// As [`energy_history`] and [`component_law_energy_history`] (zero
/// collisions, launch and step errors).
pub fn energy_conservation<B: Boundary>(
    billiard: &Billiard<B>,
    start: State,
    trace_collisions: u64,
    long_collisions: u64,
) -> Result<EnergyConservation, AnalysisError> {
    Ok(EnergyConservation {
        trace: energy_trace(billiard, start, trace_collisions, 1)?,
        library: energy_history(billiard, start, long_collisions)?,
        components: component_law_energy_history(
            billiard.table(),
            billiard.law(),
            start,
            long_collisions,
        )?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_core::Sampler;
    use spinball_geometry::Stadium;

    #[test]
    fn checkpoints_are_one_two_five() {
        assert_eq!(log_checkpoints(0), Vec::<u64>::new());
        assert_eq!(log_checkpoints(1), vec![1]);
        assert_eq!(log_checkpoints(10), vec![1, 2, 5, 10]);
        assert_eq!(log_checkpoints(1000).len(), 10);
        assert_eq!(*log_checkpoints(u64::MAX).last().unwrap(), u64::MAX);
    }

    #[test]
    fn library_map_stays_at_ulps_where_component_formulas_drift() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 1, 0);
        let ours = energy_history(&billiard, start, 200_000).unwrap();
        let paper =
            component_law_energy_history(billiard.table(), billiard.law(), start, 200_000).unwrap();
        assert_eq!(ours.collisions(), 200_000);
        assert_eq!(paper.points.len(), ours.points.len());
        assert!(ours.max_relative_deviation() < 1e-14, "{ours:?}");
        assert!(
            paper.max_relative_deviation() > 100.0 * ours.max_relative_deviation(),
            "{} vs {}",
            paper.max_relative_deviation(),
            ours.max_relative_deviation()
        );
        assert!(component_law_energy_history(billiard.table(), billiard.law(), start, 0).is_err());
    }

    #[test]
    fn one_check_runs_trace_and_both_histories() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.3).unwrap());
        let start = State::new(DVec2::new(0.3, 0.2), DVec2::from_angle(0.8), 0.0);
        let check = energy_conservation(&billiard, start, 400, 20_000).unwrap();
        assert_eq!(check.trace.points.len(), 400);
        assert_eq!(check.trace.points[9].collisions, 10);
        let largest = check
            .trace
            .points
            .iter()
            .map(|p| p.deviation)
            .fold(0.0, f64::max);
        assert_eq!(check.trace.max_deviation, largest);
        // E₀ = ½: a few ulps of ½ at most, and some collisions give it back
        // exactly (fig_energy draws those on its floor).
        assert!(largest < 1e-15, "{largest}");
        let zero = check.trace.exact_zero_fraction();
        assert!(zero > 0.0 && zero < 1.0, "{zero}");
        assert_eq!(
            check.library,
            energy_history(&billiard, start, 20_000).unwrap()
        );
        assert_eq!(check.components.collisions(), 20_000);
        assert!(energy_conservation(&billiard, start, 400, 0).is_err());
    }

    #[test]
    fn exact_zero_share_of_a_trace() {
        let law = SpinLaw::new(0.5).unwrap();
        let start = State::new(DVec2::ZERO, DVec2::new(0.6, 0.8), 0.0);
        let mut trace = EnergyTrace::new(law, &start, 1).unwrap();
        assert_eq!(trace.exact_zero_fraction(), 0.0);
        trace.points = [0.0, 1e-17, 0.0, 2e-17]
            .iter()
            .enumerate()
            .map(|(i, &deviation)| EnergyPoint {
                collisions: i as u64 + 1,
                deviation,
            })
            .collect();
        assert_eq!(trace.exact_zero_fraction(), 0.5);
    }
}
