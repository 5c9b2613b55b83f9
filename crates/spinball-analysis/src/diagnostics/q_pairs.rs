//! `Q` between consecutive collisions, sorted by what the two walls have in
//! common (paper §VI and appendix "Conserved quantity verification").
//!
//! Documented in the group docs (`diagnostics/mod.rs`), section "Q between collisions".

use spinball_core::{Billiard, Collision, Observer, SpinLaw, State};
use spinball_geometry::{Boundary, WallId};

use super::wall_statistics::DeltaQPopulation;
use crate::error::AnalysisError;

/// What two consecutive collisions have in common. See the [module docs](crate::diagnostics#q-between-collisions).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum PairClass {
    /// The same wall twice (a concave arc): `ΔQ = 0` up to rounding.
    SameWall,
    /// Different walls with opposite tangents: `ΔQ = −2v∥`.
    FacingWalls,
    /// Any other pair: the tangent line turns, `ΔQ = O(1)`.
    Turned,
}

impl PairClass {
    /// All classes, in the order of [`QPairStatistics::populations`].
    pub const ALL: [PairClass; 3] = [
        PairClass::SameWall,
        PairClass::FacingWalls,
        PairClass::Turned,
    ];

    /// `same_wall`, `facing_walls` or `turned`.
    pub fn name(&self) -> &'static str {
        match self {
            PairClass::SameWall => "same_wall",
            PairClass::FacingWalls => "facing_walls",
            PairClass::Turned => "turned",
        }
    }

    fn slot(self) -> usize {
        match self {
            PairClass::SameWall => 0,
            PairClass::FacingWalls => 1,
            PairClass::Turned => 2,
        }
    }
}

/// One consecutive pair of collisions.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct QPair {
    /// Number of the second collision of the pair (the first collision of a
    /// run is 1).
    pub collision: u64,
    /// Its class.
    pub class: PairClass,
    /// `ΔQ = Q_{k+1} − Q_k` (signed).
    pub dq: f64,
    /// `v∥` after collision `k`, with the tangent of wall `k`.
    pub v_par: f64,
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct Last {
    tangent: [f64; 2],
    wall: WallId,
    q_after: f64,
    v_par_after: f64,
}

/// An [`Observer`] of `ΔQ` between consecutive collisions by [`PairClass`],
/// with the `|Q_after − Q_before|` of each collision for comparison.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct QPairStatistics {
    alpha: f64,
    tolerance: f64,
    record: bool,
    #[cfg_attr(feature = "serde", serde(skip))]
    last: Option<Last>,
    /// Collisions seen.
    pub collisions: u64,
    /// `|ΔQ|` of the pairs of each class, in the order of [`PairClass::ALL`].
    pub populations: [DeltaQPopulation; 3],
    /// `|Q_after − Q_before|` through each collision (paper eq. 13).
    pub through_collision: DeltaQPopulation,
    /// `|ΔQ + 2 v∥|` of the facing-wall pairs (zero up to rounding).
    pub facing_residual: DeltaQPopulation,
    /// Every pair, if recording was asked for.
    pub pairs: Vec<QPair>,
}

impl QPairStatistics {
    /// Tolerance on `|t̂_k × t̂_{k+1}|` and `t̂_k·t̂_{k+1} + 1` for "opposite
    /// tangents".
    pub const TOLERANCE: f64 = 1e-9;

    /// Empty statistics for runs under `law`; `record` keeps every pair in
    /// [`pairs`](Self::pairs) (for plots of single runs; the populations are
    /// kept either way).
    pub fn new(law: &SpinLaw, record: bool) -> Self {
        QPairStatistics {
            alpha: law.alpha(),
            tolerance: Self::TOLERANCE,
            record,
            last: None,
            collisions: 0,
            populations: Default::default(),
            through_collision: DeltaQPopulation::default(),
            facing_residual: DeltaQPopulation::default(),
            pairs: Vec::new(),
        }
    }

    /// The population of one class.
    pub fn population(&self, class: PairClass) -> &DeltaQPopulation {
        &self.populations[class.slot()]
    }

    /// Number of pairs seen.
    pub fn pair_count(&self) -> u64 {
        self.populations.iter().map(|p| p.count).sum()
    }

    /// Share of pairs in `class` (`None` before any pair).
    pub fn share(&self, class: PairClass) -> Option<f64> {
        let n = self.pair_count();
        (n > 0).then(|| self.population(class).count as f64 / n as f64)
    }

    /// The share of each class, in the order of [`PairClass::ALL`] (`None`
    /// before any pair).
    #[must_use]
    pub fn shares(&self) -> [(PairClass, Option<f64>); 3] {
        PairClass::ALL.map(|c| (c, self.share(c)))
    }

    /// These statistics without the recorded pairs (for a compact record;
    /// every population is kept).
    #[must_use]
    pub fn without_pairs(&self) -> QPairStatistics {
        QPairStatistics {
            pairs: Vec::new(),
            ..self.clone()
        }
    }

    /// Forget the last collision (call between trajectories).
    pub fn end_trajectory(&mut self) {
        self.last = None;
    }

    fn classify(&self, last: &Last, c: &Collision) -> PairClass {
        if last.wall == c.wall() {
            return PairClass::SameWall;
        }
        let t = c.tangent();
        let cross = last.tangent[0] * t.y - last.tangent[1] * t.x;
        let dot = last.tangent[0] * t.x + last.tangent[1] * t.y;
        if cross.abs() <= self.tolerance && dot + 1.0 <= self.tolerance {
            PairClass::FacingWalls
        } else {
            PairClass::Turned
        }
    }
}

impl Observer for QPairStatistics {
    #[inline]
    fn observe(&mut self, c: &Collision, _after: &State) {
        self.collisions += 1;
        let q_after = c.q_after(self.alpha);
        self.through_collision.push(q_after - c.q);
        if let Some(last) = self.last {
            let class = self.classify(&last, c);
            let dq = c.q - last.q_after;
            self.populations[class.slot()].push(dq);
            if class == PairClass::FacingWalls {
                self.facing_residual.push(dq + 2.0 * last.v_par_after);
            }
            if self.record {
                self.pairs.push(QPair {
                    collision: self.collisions,
                    class,
                    dq,
                    v_par: last.v_par_after,
                });
            }
        }
        let t = c.tangent();
        self.last = Some(Last {
            tangent: [t.x, t.y],
            wall: c.wall(),
            q_after,
            v_par_after: c.v_par_after,
        });
    }
}

/// [`QPairStatistics`] of the trajectory from `start` over `collisions`
/// collisions, recording every pair if `record`.
///
/// ```
/// use spinball_analysis::diagnostics::{PairClass, q_pair_statistics};
/// use spinball_core::{Billiard, Sampler, SpinLaw};
/// use spinball_geometry::Stadium;
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?);
/// let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 1, 0);
/// let q = q_pair_statistics(&billiard, start, 10_000, false)?;
/// assert!(q.population(PairClass::SameWall).max < 1e-13); // same cap: Q kept
/// assert!(q.population(PairClass::Turned).median().unwrap() > 1e-3); // jumps
/// assert!(q.facing_residual.max < 1e-13); // facing flats: ΔQ = −2 v∥
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for zero collisions; launch and step
/// errors.
pub fn q_pair_statistics<B: Boundary>(
    billiard: &Billiard<B>,
    start: State,
    collisions: u64,
    record: bool,
) -> Result<QPairStatistics, AnalysisError> {
    if collisions == 0 {
        return Err(AnalysisError::invalid("collisions", "must be > 0"));
    }
    let mut ball = billiard.launch(start)?;
    let mut stats = QPairStatistics::new(billiard.law(), record);
    billiard.run(&mut ball, collisions, &mut stats)?;
    stats.end_trajectory();
    Ok(stats)
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_core::Sampler;
    use spinball_geometry::{Circle, DVec2, Sinai, Stadium};

    #[test]
    fn circle_pairs_are_all_same_wall_and_keep_q() {
        let billiard = Billiard::new(Circle::new(1.0).unwrap(), SpinLaw::new(0.7).unwrap());
        let start = State::new(DVec2::new(0.3, 0.2), DVec2::from_angle(0.8), 0.1);
        let q = q_pair_statistics(&billiard, start, 5_000, true).unwrap();
        assert_eq!(q.share(PairClass::SameWall), Some(1.0));
        assert_eq!(q.pairs.len(), 4_999);
        assert!(q.population(PairClass::SameWall).max < 1e-13);
    }

    #[test]
    fn sinai_has_no_same_wall_pairs() {
        let billiard = Billiard::new(Sinai::new(2.0, 1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 2, 3);
        let q = q_pair_statistics(&billiard, start, 5_000, false).unwrap();
        assert_eq!(q.population(PairClass::SameWall).count, 0);
        assert!(q.pairs.is_empty());
        assert!(q.population(PairClass::FacingWalls).count > 0);
        assert!(q.facing_residual.max < 1e-13);
        assert!(q.through_collision.max < 1e-13);
    }

    #[test]
    fn stadium_shares_and_zero_collisions() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 1, 0);
        let q = q_pair_statistics(&billiard, start, 20_000, false).unwrap();
        let total: f64 = PairClass::ALL.iter().map(|c| q.share(*c).unwrap()).sum();
        assert!((total - 1.0).abs() < 1e-12);
        assert!(q.share(PairClass::SameWall).unwrap() > 0.05);
        assert!(q_pair_statistics(&billiard, start, 0, false).is_err());
    }

    #[test]
    fn shares_and_compact_record_of_a_recorded_run() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 1, 0);
        let q = q_pair_statistics(&billiard, start, 2_000, true).unwrap();
        let shares = q.shares();
        assert_eq!(shares.map(|(c, _)| c), PairClass::ALL);
        // Each share counts the recorded pairs of its class.
        for (class, share) in shares {
            let n = q.pairs.iter().filter(|p| p.class == class).count();
            assert_eq!(share, Some(n as f64 / 1_999.0), "{class:?}");
        }
        let compact = q.without_pairs();
        assert!(compact.pairs.is_empty() && q.pairs.len() == 1_999);
        assert_eq!(compact.populations, q.populations);
        assert_eq!(compact.through_collision, q.through_collision);
        let empty = QPairStatistics::new(billiard.law(), false);
        assert_eq!(empty.shares()[0], (PairClass::SameWall, None));
    }
}
