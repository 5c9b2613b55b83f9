//! What kind of wall the ball hits and what `Q` does between walls (paper,
//! the mechanism of the conserved quantity and its appendix): wall-transition
//! fractions, the `|ΔQ|` populations by pair class, and the share of
//! collisions on curved walls, as an [`Observer`] that rides along any run.
//!
//! Documented in the group docs (`diagnostics/mod.rs`), section "Wall statistics".

use std::ops::Range;

use spinball_core::{Billiard, Collision, Observer, Sampler, SpinLaw, State};
use spinball_geometry::{Boundary, WallId};

use crate::error::AnalysisError;
use crate::estimators::Histogram;
use crate::run::{Threads, map_indices};

/// When two consecutive collisions count as a wall transition. See
/// [`WallStatistics`] for what each gives.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum TransitionRule {
    /// The oriented tangent changes (`|t̂_k × t̂_{k+1}| > tol` or
    /// `t̂_k·t̂_{k+1} < 1 − tol`): exactly the pairs where `ΔQ ≠ 0`. Every
    /// consecutive pair, in every table.
    Tangent,
    /// The tangent *line* turns (`|t̂_k × t̂_{k+1}| > tol`): facing parallel
    /// walls (stadium flats, opposite box walls) count as the same direction.
    /// Reproduces the paper's stadium band (0.80–0.84).
    Direction,
    /// The wall id changes (consecutive hits on one stadium cap count as the
    /// same wall). Gives the paper's Sinai `f_trans = 1`.
    Wall,
}

/// `f_trans` under each [`TransitionRule`] (`None` before any pair), from
/// [`WallStatistics::transition_fractions`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TransitionFractions {
    /// Under [`TransitionRule::Direction`] (the paper's stadium band).
    pub direction: Option<f64>,
    /// Under [`TransitionRule::Tangent`] (1 in every table).
    pub tangent: Option<f64>,
    /// Under [`TransitionRule::Wall`] (the paper's Sinai `f_trans = 1`).
    pub wall: Option<f64>,
}

/// A population of `|ΔQ|` values, binned in `log10` (quarter decades from
/// `1e-20` to `1e2`; zeros and smaller values go to the underflow count),
/// with the exact count and maximum.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct DeltaQPopulation {
    /// Histogram of `log10 |ΔQ|`.
    pub log10: Histogram,
    /// Number of values.
    pub count: u64,
    /// Largest `|ΔQ|` (0 when empty).
    pub max: f64,
}

impl Default for DeltaQPopulation {
    fn default() -> Self {
        DeltaQPopulation {
            log10: Histogram::new(-20.0, 2.0, 88).expect("valid bins"),
            count: 0,
            max: 0.0,
        }
    }
}

impl DeltaQPopulation {
    /// Add `|ΔQ|`.
    #[inline]
    pub fn push(&mut self, dq: f64) {
        let a = dq.abs();
        self.count += 1;
        self.max = self.max.max(a);
        self.log10.push(a.log10());
    }

    /// The `p`-quantile of `|ΔQ|` to the resolution of the bins (a quarter
    /// decade): the geometric centre of the bin where the cumulative count
    /// reaches `p`. `Some(0.0)` if it falls in the underflow (`< 1e-20`,
    /// zeros included), `None` for an empty population or `p` outside `[0, 1]`.
    pub fn quantile(&self, p: f64) -> Option<f64> {
        if self.count == 0 || !(0.0..=1.0).contains(&p) {
            return None;
        }
        let target = (p * self.count as f64).ceil().max(1.0) as u64;
        let mut seen = self.log10.underflow();
        if seen >= target {
            return Some(0.0);
        }
        for (i, &c) in self.log10.counts().iter().enumerate() {
            seen += c;
            if seen >= target {
                return Some(10f64.powf(self.log10.center(i)));
            }
        }
        Some(self.max)
    }

    /// The median `|ΔQ|` to a quarter decade (see [`quantile`](Self::quantile)).
    pub fn median(&self) -> Option<f64> {
        self.quantile(0.5)
    }

    fn merge(&mut self, other: &DeltaQPopulation) -> Result<(), AnalysisError> {
        self.log10.merge(&other.log10)?;
        self.count += other.count;
        self.max = self.max.max(other.max);
        Ok(())
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct Previous {
    tangent: [f64; 2],
    wall: WallId,
    q_after: f64,
}

/// An [`Observer`] of wall statistics: collision rate, curved share, the
/// three kinds of consecutive pairs and the `|ΔQ|` populations (paper §VI).
///
/// # `Q` between collisions, and what "transition" means
/// `Q = v∥ − αu` (paper eq. 12) is unchanged *through* every collision
/// (eq. 13), but `v∥ = v·t̂` is measured with the tangent of the wall being
/// hit, so from one collision to the next it changes by
/// `ΔQ = Q_{k+1} − Q_k^after = v·(t̂_{k+1} − t̂_k)` (free flight keeps `v`
/// and `u`). It is exactly zero only if the two tangents are equal, and that
/// never happens for consecutive collisions: leaving wall `k` means
/// `v·n̂_k > 0`, reaching wall `k+1` needs `v·n̂_{k+1} < 0`, so
/// `n̂_{k+1} ≠ n̂_k` (any table, any α). [`WallStatistics`] therefore sorts
/// consecutive pairs three ways:
///
/// | kind | tangents | `ΔQ` | examples |
/// |---|---|---|---|
/// | same tangent | `t̂_{k+1} = t̂_k` | `0` | impossible for consecutive collisions (counted, for completeness) |
/// | reversed tangent | `t̂_{k+1} = −t̂_k` | `−2 v∥`, O(1) | stadium top ↔ bottom flat wall, opposite box walls |
/// | turned | anything else | O(1) | flat ↔ cap, cap → cap, adjacent box walls, the Sinai disk |
///
/// and reports `f_trans` under three rules ([`TransitionRule`]). Measured
/// with 200 paper-sampler initial conditions × 10⁴ collisions (the paper:
/// 1000): in the stadium `a = 1`, the share of pairs whose tangent *line*
/// turns ([`TransitionRule::Direction`], top ↔ bottom counted as "same
/// direction") is 0.838, 0.846, 0.824, 0.817 at α = 0, 0.1, 0.5, 1, which is
/// the paper's "≈ 80–84 %"; the share of pairs on different walls
/// ([`TransitionRule::Wall`]) is 0.78–0.81; the share whose oriented tangent
/// changes ([`TransitionRule::Tangent`]) is 1 exactly. In the Sinai billiard
/// (`L = 2, R = 1`) the rules give about 0.90–0.92, 1, 1: the paper's "`f_trans = 1`
/// identically" is the wall or tangent rule, its stadium band the direction
/// rule. The paper's "same-wall pairs at `~1e-16`" are the pairs on the
/// same wall *id*: two hits in a row on one stadium cap, where the chord
/// makes equal angles with both tangents, so `ΔQ = 0` up to rounding even
/// though the tangent turns (they are counted as `turned` here; see
/// [`QPairStatistics`](crate::diagnostics::QPairStatistics), which sorts pairs by wall
/// first). Flat walls never give such a population under the physical
/// tangent convention of [`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#units-and-conventions) (`t̂ = (n_y, −n_x)`: the two stadium
/// flats have opposite tangents and `Q` jumps by `−2v∥` between them). `Q`
/// through each collision is at machine precision too:
/// [`WallStatistics::dq_collision`].
///
/// ```
/// use spinball_analysis::diagnostics::{TransitionRule, wall_statistics};
/// use spinball_core::{Billiard, Sampler, SpinLaw};
/// use spinball_geometry::Sinai;
///
/// let billiard = Billiard::new(Sinai::new(2.0, 1.0)?, SpinLaw::new(0.5)?);
/// let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 1, 0);
/// let stats = wall_statistics(&billiard, start, 10_000)?;
/// assert_eq!(stats.transition_fraction(TransitionRule::Wall), Some(1.0));
/// assert!(stats.dq_collision.max < 1e-14); // Q through each collision
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct WallStatistics {
    alpha: f64,
    tolerance: f64,
    #[cfg_attr(feature = "serde", serde(skip))]
    previous: Option<Previous>,
    /// Collisions seen.
    pub collisions: u64,
    /// Their total flight time.
    pub time: f64,
    /// Collisions on curved walls (curvature ≠ 0).
    pub curved: u64,
    /// Consecutive pairs seen (within one trajectory).
    pub pairs: u64,
    /// Pairs with the same oriented tangent (`ΔQ = 0`; zero for consecutive
    /// collisions, see above).
    pub same_tangent: u64,
    /// Pairs with opposite tangents (facing parallel walls).
    pub reversed_tangent: u64,
    /// Pairs whose tangent line turns.
    pub turned: u64,
    /// Pairs on different walls (by wall id).
    pub wall_changes: u64,
    /// `|Q_after − Q_before|` through each collision (paper eq. 13: zero up
    /// to rounding).
    pub dq_collision: DeltaQPopulation,
    /// `|ΔQ|` between consecutive collisions with the same tangent.
    pub dq_same_tangent: DeltaQPopulation,
    /// `|ΔQ|` between consecutive collisions with opposite tangents
    /// (`= 2|v∥|`).
    pub dq_reversed_tangent: DeltaQPopulation,
    /// `|ΔQ|` between consecutive collisions whose tangent line turns.
    pub dq_turned: DeltaQPopulation,
}

impl WallStatistics {
    /// Default tolerance for comparing unit tangents.
    pub const DEFAULT_TOLERANCE: f64 = 1e-9;

    /// Empty statistics for runs under `law`.
    pub fn new(law: &SpinLaw) -> Self {
        WallStatistics {
            alpha: law.alpha(),
            tolerance: Self::DEFAULT_TOLERANCE,
            previous: None,
            collisions: 0,
            time: 0.0,
            curved: 0,
            pairs: 0,
            same_tangent: 0,
            reversed_tangent: 0,
            turned: 0,
            wall_changes: 0,
            dq_collision: DeltaQPopulation::default(),
            dq_same_tangent: DeltaQPopulation::default(),
            dq_reversed_tangent: DeltaQPopulation::default(),
            dq_turned: DeltaQPopulation::default(),
        }
    }

    /// Use `tolerance` (in `(0, 0.1]`) when comparing tangents.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] outside that range.
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self, AnalysisError> {
        if !(tolerance > 0.0 && tolerance <= 0.1) {
            return Err(AnalysisError::invalid(
                "tolerance",
                format!("must be in (0, 0.1], got {tolerance}"),
            ));
        }
        self.tolerance = tolerance;
        Ok(self)
    }

    /// α of the law the statistics were taken under.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// The tangent tolerance.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// Forget the last collision, so the next one does not form a pair with
    /// it (call between trajectories when reusing one observer).
    pub fn end_trajectory(&mut self) {
        self.previous = None;
    }

    /// `f_trans`: share of consecutive pairs that are transitions under
    /// `rule` (`None` before any pair).
    pub fn transition_fraction(&self, rule: TransitionRule) -> Option<f64> {
        if self.pairs == 0 {
            return None;
        }
        let k = match rule {
            TransitionRule::Tangent => self.pairs - self.same_tangent,
            TransitionRule::Direction => self.turned,
            TransitionRule::Wall => self.wall_changes,
        };
        Some(k as f64 / self.pairs as f64)
    }

    /// `f_trans` under all three rules at once.
    #[must_use]
    pub fn transition_fractions(&self) -> TransitionFractions {
        TransitionFractions {
            direction: self.transition_fraction(TransitionRule::Direction),
            tangent: self.transition_fraction(TransitionRule::Tangent),
            wall: self.transition_fraction(TransitionRule::Wall),
        }
    }

    /// Share of collisions on curved walls (`None` before any collision).
    ///
    /// # Theory and the paper
    /// For α = 0 and the invariant measure, the share of collisions on a wall is
    /// its share of the perimeter: `2π/(4 + 2π) = 0.611` for the stadium `a = 1`,
    /// `2πR/(8L + 2πR)` for Sinai (`0.282` at `R = 1`, `0.105` at `R = 0.3`,
    /// `0.371` at `R = 1.5`). The paper quotes "~50 %" (stadium), "~30 %",
    /// "~15 %", "~50 %" (Sinai `R = 1, 0.3, 1.5`); its Sinai `R ≤ 1` values agree,
    /// the stadium and `R = 1.5` values do not (see `tests/diagnostics.rs`).
    pub fn curved_fraction(&self) -> Option<f64> {
        (self.collisions > 0).then(|| self.curved as f64 / self.collisions as f64)
    }

    /// Pooled collision rate, total collisions over total time.
    pub fn collision_rate(&self) -> Option<f64> {
        (self.collisions > 0 && self.time > 0.0).then(|| self.collisions as f64 / self.time)
    }

    /// Add the counts of `other` (another trajectory or batch). Pairs never
    /// span the two.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if α or the tolerance differ.
    pub fn merge(&mut self, other: &WallStatistics) -> Result<(), AnalysisError> {
        if self.alpha != other.alpha || self.tolerance != other.tolerance {
            return Err(AnalysisError::invalid(
                "wall statistics",
                "cannot merge statistics taken with a different alpha or tolerance",
            ));
        }
        self.collisions += other.collisions;
        self.time += other.time;
        self.curved += other.curved;
        self.pairs += other.pairs;
        self.same_tangent += other.same_tangent;
        self.reversed_tangent += other.reversed_tangent;
        self.turned += other.turned;
        self.wall_changes += other.wall_changes;
        self.dq_collision.merge(&other.dq_collision)?;
        self.dq_same_tangent.merge(&other.dq_same_tangent)?;
        self.dq_reversed_tangent.merge(&other.dq_reversed_tangent)?;
        self.dq_turned.merge(&other.dq_turned)?;
        self.previous = None;
        Ok(())
    }
}

impl Observer for WallStatistics {
    #[inline]
    fn observe(&mut self, c: &Collision, _after: &State) {
        self.collisions += 1;
        self.time += c.time();
        if c.hit.is_curved() {
            self.curved += 1;
        }
        let t = c.tangent();
        let q_after = c.q_after(self.alpha);
        self.dq_collision.push(q_after - c.q);
        if let Some(p) = self.previous {
            self.pairs += 1;
            if p.wall != c.wall() {
                self.wall_changes += 1;
            }
            let cross = p.tangent[0] * t.y - p.tangent[1] * t.x;
            let dot = p.tangent[0] * t.x + p.tangent[1] * t.y;
            let dq = c.q - p.q_after;
            if cross.abs() > self.tolerance {
                self.turned += 1;
                self.dq_turned.push(dq);
            } else if dot > 0.0 {
                self.same_tangent += 1;
                self.dq_same_tangent.push(dq);
            } else {
                self.reversed_tangent += 1;
                self.dq_reversed_tangent.push(dq);
            }
        }
        self.previous = Some(Previous {
            tangent: [t.x, t.y],
            wall: c.wall(),
            q_after,
        });
    }
}

/// [`WallStatistics`] of the trajectory from `start` over `collisions`
/// collisions.
///
/// # Errors
/// `Launch`/`Step` errors from the dynamics.
pub fn wall_statistics<B: Boundary>(
    billiard: &Billiard<B>,
    start: State,
    collisions: u64,
) -> Result<WallStatistics, AnalysisError> {
    let mut ball = billiard.launch(start)?;
    let mut stats = WallStatistics::new(billiard.law());
    billiard.run(&mut ball, collisions, &mut stats)?;
    stats.end_trajectory();
    Ok(stats)
}

/// [`WallStatistics`] pooled over initial conditions `ics` (IC `i` from
/// `sampler` with `ic_rng(seed, i)`), `collisions` each, merged in index
/// order.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for an empty range; dynamics errors with
/// the failing index.
pub fn wall_statistics_ensemble<B: Boundary + Sync>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    ics: Range<u64>,
    collisions: u64,
    threads: Threads,
) -> Result<WallStatistics, AnalysisError> {
    if ics.is_empty() {
        return Err(AnalysisError::invalid(
            "ics",
            "empty range of initial conditions",
        ));
    }
    let parts = map_indices(ics, threads, |i| {
        let start = sampler.try_initial_state(billiard.table(), billiard.law(), seed, i)?;
        wall_statistics(billiard, start, collisions).map_err(|e| e.at_index(i))
    })?;
    let mut total = WallStatistics::new(billiard.law());
    for part in &parts {
        total.merge(part)?;
    }
    Ok(total)
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_geometry::{Sinai, Stadium};

    #[test]
    fn transition_fractions_under_the_three_rules() {
        // Sinai: every consecutive pair changes wall and oriented tangent
        // (the type docs: the wall and tangent rules give 1 exactly).
        let billiard = Billiard::new(Sinai::new(2.0, 1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 1, 0);
        let f = wall_statistics(&billiard, start, 5_000)
            .unwrap()
            .transition_fractions();
        assert_eq!((f.tangent, f.wall), (Some(1.0), Some(1.0)));
        assert!(f.direction.unwrap() < 1.0);
        // Stadium: two hits in a row on one cap keep the wall id, so the
        // wall rule counts fewer transitions than the tangent rule.
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 1, 0);
        let stats = wall_statistics(&billiard, start, 5_000).unwrap();
        let f = stats.transition_fractions();
        assert_eq!(f.tangent, Some(1.0));
        assert_eq!(f.wall, stats.transition_fraction(TransitionRule::Wall));
        assert_eq!(
            f.direction,
            stats.transition_fraction(TransitionRule::Direction)
        );
        assert!(f.wall.unwrap() < 1.0);
        let empty = WallStatistics::new(billiard.law()).transition_fractions();
        assert_eq!(
            (empty.direction, empty.tangent, empty.wall),
            (None, None, None)
        );
    }
}
