//! Who sits on the regular islands? Regular and chaotic trajectories
//! compared by where they collide and how they start (paper §V).
//!
//! Documented in the group docs (`phase_space/mod.rs`), section "Who sits on the islands".

use std::ops::Range;

use spinball_core::{Billiard, Sampler, ic_rng};
use spinball_geometry::Boundary;

use crate::error::AnalysisError;
use crate::estimators::Accumulator;
use crate::run::{Threads, TrajectoryStats, map_indices};

/// Where one trajectory collides and how it starts.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TrajectoryProfile {
    /// Index of the initial condition.
    pub index: u64,
    /// Collisions run.
    pub collisions: u64,
    /// Collisions on curved walls (curvature ≠ 0).
    pub curved: u64,
    /// Launch velocity `(v_x, v_y)`.
    pub initial_velocity: [f64; 2],
    /// Launch spin `u`.
    pub initial_spin: f64,
    /// `v∥ = v·t̂` just before the first collision, with the tangent of the
    /// wall hit.
    pub first_v_par: f64,
}

impl TrajectoryProfile {
    /// Share of collisions on flat walls.
    pub fn flat_share(&self) -> f64 {
        1.0 - self.curved as f64 / self.collisions as f64
    }
}

/// The profile of initial condition `index` (state drawn by `sampler` from
/// [`ic_rng(seed, index)`](ic_rng), as in an ensemble) over `collisions`
/// collisions.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for zero collisions; launch and step
/// errors tagged with `index`.
pub fn trajectory_profile<B: Boundary>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    index: u64,
    collisions: u64,
) -> Result<TrajectoryProfile, AnalysisError> {
    if collisions == 0 {
        return Err(AnalysisError::invalid("collisions", "must be > 0"));
    }
    let start = sampler.try_sample(billiard.table(), billiard.law(), &mut ic_rng(seed, index))?;
    let tag = |e: AnalysisError| e.at_index(index);
    let mut ball = billiard.launch(start).map_err(|e| tag(e.into()))?;
    let first = billiard.step(&mut ball).map_err(|e| tag(e.into()))?;
    let mut curved = u64::from(first.hit.is_curved());
    billiard
        .run(
            &mut ball,
            collisions - 1,
            &mut |c: &spinball_core::Collision, _: &spinball_core::State| {
                curved += u64::from(c.hit.is_curved());
            },
        )
        .map_err(|e| tag(e.into()))?;
    Ok(TrajectoryProfile {
        index,
        collisions,
        curved,
        initial_velocity: [start.velocity.x, start.velocity.y],
        initial_spin: start.spin,
        first_v_par: first.v_par_before,
    })
}

/// [`trajectory_profile`] for every index in `indices`, in index order.
///
/// # Errors
/// As [`trajectory_profile`].
pub fn trajectory_profiles<B: Boundary + Sync>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    indices: Range<u64>,
    collisions: u64,
    threads: Threads,
) -> Result<Vec<TrajectoryProfile>, AnalysisError> {
    map_indices(indices, threads, |i| {
        trajectory_profile(billiard, sampler, seed, i, collisions)
    })
}

/// A mean with its standard error (`sem` is NaN for fewer than two values,
/// `mean` is NaN for none).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MeanSem {
    /// Mean.
    pub mean: f64,
    /// Standard error of the mean.
    pub sem: f64,
}

impl MeanSem {
    fn of(acc: &Accumulator) -> Self {
        MeanSem {
            mean: acc.mean().unwrap_or(f64::NAN),
            sem: acc.sem().unwrap_or(f64::NAN),
        }
    }
}

/// One class of trajectories (regular or chaotic).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ClassSummary {
    /// Number of trajectories in the class.
    pub n: u64,
    /// Their FTLE.
    pub ftle: MeanSem,
    /// Their share of collisions on flat walls.
    pub flat_share: MeanSem,
    /// `|v_x(0)|`, the launch velocity along the x axis (the direction of
    /// the stadium's flat walls).
    pub abs_initial_vx: MeanSem,
    /// `|v∥|` at the first collision.
    pub abs_first_v_par: MeanSem,
    /// `|u(0)|`, the launch spin.
    pub abs_initial_spin: MeanSem,
}

/// Regular against chaotic trajectories at one threshold.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ClassComparison {
    /// FTLE at or below which a trajectory counts as regular.
    pub threshold: f64,
    /// FTLE ≤ threshold.
    pub regular: ClassSummary,
    /// FTLE > threshold.
    pub chaotic: ClassSummary,
}

/// Split `profiles` by the FTLE of the same initial conditions (`ftle`,
/// matched by index) at `threshold` (the paper: 0.01) and summarise each
/// class.
///
/// ```
/// use spinball_analysis::run::{Ensemble, Threads};
/// use spinball_analysis::phase_space::{compare_classes, trajectory_profiles};
/// use spinball_core::{Billiard, Sampler, SpinLaw};
/// use spinball_geometry::Stadium;
///
/// let ensemble = Ensemble::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?)
///     .with_ics(40).with_collisions(2_000).with_seed(7);
/// let estimate = ensemble.run()?;
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?);
/// let profiles = trajectory_profiles(&billiard, Sampler::Paper, 7, 0..40, 2_000, Threads::All)?;
/// let split = compare_classes(estimate.trajectories(), &profiles, 0.01)?;
/// assert_eq!(split.regular.n + split.chaotic.n, 40);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnalysisError::InvalidOption`] if the two lists differ in length or in
/// the index at some position.
pub fn compare_classes(
    ftle: &[TrajectoryStats],
    profiles: &[TrajectoryProfile],
    threshold: f64,
) -> Result<ClassComparison, AnalysisError> {
    if ftle.len() != profiles.len() {
        return Err(AnalysisError::invalid(
            "profiles",
            format!("{} FTLE values but {} profiles", ftle.len(), profiles.len()),
        ));
    }
    // Per class (regular, chaotic): FTLE, flat share, |v_x(0)|, |v∥| at the
    // first hit, |u(0)|.
    let mut acc: [[Accumulator; 5]; 2] =
        std::array::from_fn(|_| std::array::from_fn(|_| Accumulator::new()));
    for (t, p) in ftle.iter().zip(profiles) {
        if t.index != p.index {
            return Err(AnalysisError::invalid(
                "profiles",
                format!(
                    "FTLE of index {} paired with the profile of {}",
                    t.index, p.index
                ),
            ));
        }
        let class = &mut acc[usize::from(t.exponent > threshold)];
        class[0].push(t.exponent);
        class[1].push(p.flat_share());
        class[2].push(p.initial_velocity[0].abs());
        class[3].push(p.first_v_par.abs());
        class[4].push(p.initial_spin.abs());
    }
    let summary = |a: &[Accumulator; 5]| ClassSummary {
        n: a[0].count(),
        ftle: MeanSem::of(&a[0]),
        flat_share: MeanSem::of(&a[1]),
        abs_initial_vx: MeanSem::of(&a[2]),
        abs_first_v_par: MeanSem::of(&a[3]),
        abs_initial_spin: MeanSem::of(&a[4]),
    };
    Ok(ClassComparison {
        threshold,
        regular: summary(&acc[0]),
        chaotic: summary(&acc[1]),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_core::SpinLaw;
    use spinball_geometry::{Rectangle, Stadium};

    #[test]
    fn profile_starts_where_the_ensemble_starts() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let p = trajectory_profile(&billiard, Sampler::Paper, 3, 11, 500).unwrap();
        let s = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 3, 11);
        assert_eq!(p.initial_velocity, [s.velocity.x, s.velocity.y]);
        assert_eq!(p.initial_spin, s.spin);
        assert!(p.curved <= 500 && p.flat_share() >= 0.0);
        assert!(trajectory_profile(&billiard, Sampler::Paper, 3, 11, 0).is_err());
        let flat = Billiard::new(
            Rectangle::new(1.0, 1.0).unwrap(),
            SpinLaw::new(0.5).unwrap(),
        );
        let p = trajectory_profile(&flat, Sampler::Paper, 3, 11, 100).unwrap();
        assert_eq!(p.flat_share(), 1.0);
    }

    #[test]
    fn classes_must_match_by_index() {
        let p = TrajectoryProfile {
            index: 1,
            collisions: 10,
            curved: 5,
            initial_velocity: [0.5, 0.5],
            initial_spin: 0.1,
            first_v_par: 0.3,
        };
        let t = TrajectoryStats {
            index: 2,
            exponent: 0.2,
            per_collision: 0.5,
            time: 25.0,
            collisions: 10,
        };
        assert!(compare_classes(&[t], &[p], 0.01).is_err());
        assert!(compare_classes(&[t], &[], 0.01).is_err());
        let t = TrajectoryStats { index: 1, ..t };
        let c = compare_classes(&[t], &[p], 0.01).unwrap();
        assert_eq!((c.regular.n, c.chaotic.n), (0, 1));
        assert_eq!(c.chaotic.flat_share.mean, 0.5);
        assert!(c.regular.flat_share.mean.is_nan());
    }
}
