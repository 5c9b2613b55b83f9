//! Return times to a region of the section, against Kac's lemma: a test of
//! ergodicity that needs no Lyapunov exponent.
//!
//! Documented in the group docs (`phase_space/mod.rs`), section "Return times and Kac's lemma".

use std::fmt;

use spinball_core::{Billiard, SpinLaw, State, ic_rng};
use spinball_geometry::Boundary;

use super::invariant_measure::{InvariantMeasure, SectionBox};
use super::return_time_shards::kac_part;
use super::section::{Section, state_on_section};
use crate::error::AnalysisError;
use crate::estimators::Accumulator;
use crate::precision::Measurement;
use crate::run::{Shard, Threads};

/// The visits of one orbit to a region of the section.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrbitReturns {
    /// Index of the orbit (its start is drawn from `ic_rng(seed, index)`).
    pub index: u64,
    /// Collisions run.
    pub collisions: u64,
    /// Collisions that landed in the region.
    pub visits: u64,
    /// Mean number of collisions between consecutive visits; `None` for
    /// fewer than two visits (no return seen).
    pub mean_return: Option<f64>,
}

/// Count the visits to `region` of `collisions` collisions from `start`.
///
/// # Errors
/// The launch or first step error.
pub fn orbit_returns<B: Boundary>(
    billiard: &Billiard<B>,
    start: State,
    collisions: u64,
    region: &SectionBox,
) -> Result<OrbitReturns, AnalysisError> {
    let alpha = billiard.law().alpha();
    let mut ball = billiard.launch(start)?;
    let (mut visits, mut first, mut last, mut n) = (0u64, 0u64, 0u64, 0u64);
    billiard.run(
        &mut ball,
        collisions,
        &mut Section::new(|p| {
            n += 1;
            if region.contains(&p, alpha) {
                if visits == 0 {
                    first = n;
                }
                last = n;
                visits += 1;
            }
        }),
    )?;
    Ok(OrbitReturns {
        index: 0,
        collisions,
        visits,
        mean_return: (visits >= 2).then(|| (last - first) as f64 / (visits - 1) as f64),
    })
}

/// A ball drawn from the invariant measure of `table` under `law`
/// (`|V| = 1`), from `rng`.
///
/// # Errors
/// As [`state_on_section`] (a table that cannot place points by arc
/// length).
pub fn invariant_start<B: Boundary + ?Sized, R: rand::Rng + ?Sized>(
    table: &B,
    law: &SpinLaw,
    measure: &InvariantMeasure,
    rng: &mut R,
) -> Result<State, AnalysisError> {
    let alpha = law.alpha();
    loop {
        let (s, v, w) = measure.sample(rng);
        let u = if alpha > 0.0 { w / alpha.sqrt() } else { 0.0 };
        // Rounding can put a point drawn just inside the disk's rim onto
        // it; draw again then (only the shell check can fail here once the
        // table has answered).
        if v * v + alpha * u * u < 1.0 {
            return state_on_section(table, law, s, v, u);
        }
    }
}

/// The starts `indices` drawn from the invariant measure of `table` under
/// `law` (`|V| = 1`), start `i` from the stream `ic_rng(seed, i)`: the
/// orbits [`kac_comparison`] runs, and a sampler of the measure for any
/// other use (sections, ensembles over explicit states).
///
/// # Errors
/// As [`InvariantMeasure::new`] and [`state_on_section`] (a table that
/// cannot place points by arc length).
pub fn invariant_starts<B: Boundary + ?Sized>(
    table: &B,
    law: &SpinLaw,
    seed: u64,
    indices: std::ops::Range<u64>,
) -> Result<Vec<State>, AnalysisError> {
    let measure = InvariantMeasure::new(table, law)?;
    indices
        .map(|i| invariant_start(table, law, &measure, &mut ic_rng(seed, i)))
        .collect()
}

/// Mean return times per orbit against Kac's `1/μ(A)`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct KacComparison {
    /// α of the run.
    pub alpha: f64,
    /// The region.
    pub region: SectionBox,
    /// `μ(A)`, the region's share of the invariant measure.
    pub probability: f64,
    /// Kac's mean return time `1/μ(A)` (collisions).
    pub expected: f64,
    /// Every orbit, in index order.
    pub orbits: Vec<OrbitReturns>,
    /// Mean over orbits of their mean return times, with its SEM across
    /// orbits (`None` if fewer than two orbits returned).
    pub mean_return: Option<Measurement>,
    /// Orbits that did not return (fewer than two visits).
    pub never_returned: u64,
}

impl KacComparison {
    /// `mean_return / expected` with its SEM: 1 on an ergodic table.
    #[must_use]
    pub fn ratio(&self) -> Option<Measurement> {
        self.mean_return
            .map(|m| Measurement::new(m.value / self.expected, m.sem / self.expected))
    }

    /// Each returning orbit's mean return time over Kac's (1 on an ergodic
    /// table), in index order.
    #[must_use]
    pub fn orbit_ratios(&self) -> Vec<f64> {
        self.orbits
            .iter()
            .filter_map(|o| o.mean_return.map(|m| m / self.expected))
            .collect()
    }
}

/// One line: `μ(A)`, Kac's `1/μ(A)`, the mean return time and its ratio to
/// Kac's with their SEMs (`-` when fewer than two orbits returned), and
/// how many orbits never returned.
impl fmt::Display for KacComparison {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mean = self
            .mean_return
            .map_or("-".into(), |m| format!("{:.3} ± {:.3}", m.value, m.sem));
        let ratio = self
            .ratio()
            .map_or("-".into(), |r| format!("{:.4} ± {:.4}", r.value, r.sem));
        write!(
            f,
            "μ(A) = {:.4}, Kac {:.3}, mean return {mean}, ratio {ratio}, never returned {} of {}",
            self.probability,
            self.expected,
            self.never_returned,
            self.orbits.len()
        )
    }
}

/// Run `orbits` orbits of `collisions` collisions, started from the
/// invariant measure with streams `ic_rng(seed, i)`, and compare their mean
/// return times to `region` with Kac's lemma.
///
/// ```
/// use spinball_analysis::run::Threads;
/// use spinball_analysis::phase_space::{SectionBox, kac_comparison};
/// use spinball_core::{Billiard, SpinLaw};
/// use spinball_geometry::Stadium;
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::specular());
/// // The bottom flat wall (s in [0, 2)), arriving within 30° of the normal.
/// let region = SectionBox::new(0.0..2.0, -0.5..0.5);
/// let kac = kac_comparison(&billiard, &region, 8, 20_000, 1, Threads::All)?;
/// assert!((kac.expected - 2.0 * (4.0 + 2.0 * std::f64::consts::PI) / 2.0).abs() < 1e-12);
/// let ratio = kac.ratio().expect("the orbits return");
/// assert!((ratio.value - 1.0).abs() < 0.1);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for fewer than 2 orbits, zero
/// collisions or a region of zero measure; a table that cannot place
/// points by arc length; the first failing orbit's error with its index.
pub fn kac_comparison<B: Boundary + Sync>(
    billiard: &Billiard<B>,
    region: &SectionBox,
    orbits: u64,
    collisions: u64,
    seed: u64,
    threads: Threads,
) -> Result<KacComparison, AnalysisError> {
    let whole = kac_part(
        billiard,
        region,
        orbits,
        collisions,
        seed,
        threads,
        Shard::WHOLE,
    )?;
    Ok(KacComparison::from_orbits(
        whole.alpha,
        whole.region,
        whole.probability,
        whole.runs,
    ))
}

impl KacComparison {
    /// The comparison of `runs` (every orbit of a run, in index order) with
    /// Kac's `1/probability`: the one reduction of the orbits, whole or
    /// joined from shards.
    pub(super) fn from_orbits(
        alpha: f64,
        region: SectionBox,
        probability: f64,
        runs: Vec<OrbitReturns>,
    ) -> KacComparison {
        let mut acc = Accumulator::new();
        for m in runs.iter().filter_map(|o| o.mean_return) {
            acc.push(m);
        }
        let mean_return = acc
            .mean()
            .zip(acc.sem())
            .map(|(m, e)| Measurement::new(m, e));
        KacComparison {
            alpha,
            region,
            probability,
            expected: 1.0 / probability,
            never_returned: runs.iter().filter(|o| o.mean_return.is_none()).count() as u64,
            orbits: runs,
            mean_return,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn comparison(returns: &[Option<f64>]) -> KacComparison {
        let orbits: Vec<OrbitReturns> = returns
            .iter()
            .enumerate()
            .map(|(i, &mean_return)| OrbitReturns {
                index: i as u64,
                collisions: 100,
                visits: if mean_return.is_some() { 20 } else { 1 },
                mean_return,
            })
            .collect();
        KacComparison {
            alpha: 0.5,
            region: SectionBox::new(0.0..1.0, -1.0..1.0),
            probability: 0.25,
            expected: 4.0,
            never_returned: returns.iter().filter(|r| r.is_none()).count() as u64,
            orbits,
            mean_return: Some(Measurement::new(4.4, 0.2)),
        }
    }

    #[test]
    fn invariant_starts_are_on_the_shell_and_depend_only_on_their_index() {
        use spinball_geometry::Stadium;
        let (table, law) = (Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let all = invariant_starts(&table, &law, 4, 0..6).unwrap();
        assert_eq!(invariant_starts(&table, &law, 4, 3..6).unwrap(), all[3..]);
        for s in &all {
            assert!((s.energy(&law) - 0.5).abs() < 1e-14);
        }
        assert_ne!(all[0], all[1]);
    }

    #[test]
    fn summary_line_gives_the_ratio_to_kac() {
        let kac = comparison(&[Some(4.0), Some(4.8), None]);
        assert_eq!(kac.orbit_ratios(), vec![1.0, 1.2]);
        assert_eq!(
            kac.to_string(),
            "μ(A) = 0.2500, Kac 4.000, mean return 4.400 ± 0.200, \
             ratio 1.1000 ± 0.0500, never returned 1 of 3"
        );
        let none = KacComparison {
            mean_return: None,
            ..comparison(&[None, None])
        };
        assert!(
            none.to_string()
                .ends_with("mean return -, ratio -, never returned 2 of 2")
        );
    }
}
