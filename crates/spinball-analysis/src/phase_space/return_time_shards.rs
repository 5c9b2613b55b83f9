//! Return times in shards: the orbits of a comparison with Kac's lemma run
//! a block at a time (on several machines, or as the tasks of a job array)
//! and joined into the comparison one run gives, bitwise.
//!
//! Orbit `i` starts from the stream `ic_rng(seed, i)` whichever shard runs
//! it, and the comparison's statistics are reduced over the orbits in
//! index order, so joining the blocks in order gives the same numbers as
//! one run. [`kac_comparison`](super::kac_comparison) is the whole run as
//! one shard.

use std::ops::Range;

use spinball_core::{Billiard, ic_rng};
use spinball_geometry::Boundary;

use super::invariant_measure::{InvariantMeasure, SectionBox};
use super::return_time::{KacComparison, OrbitReturns, invariant_start, orbit_returns};
use crate::error::AnalysisError;
use crate::run::{MergeError, RunDifference, Shard, TableRecord, Threads, map_indices, tile};

/// One shard of a comparison with Kac's lemma: the orbits of its block.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct KacPart {
    /// The table (merging checks that every part is of the same one).
    pub table: TableRecord,
    /// The version of spinball that computed it.
    pub version: String,
    /// Which shard this is.
    pub shard: Shard,
    /// The orbits this part ran (indices of the whole run's `0..orbits`).
    pub starts: Range<u64>,
    /// Orbits of the whole run.
    pub orbits: u64,
    /// Collisions per orbit.
    pub collisions: u64,
    /// The seed of the starts.
    pub seed: u64,
    /// α of the run.
    pub alpha: f64,
    /// The region.
    pub region: SectionBox,
    /// `μ(A)`, the region's share of the invariant measure.
    pub probability: f64,
    /// This part's orbits, in index order.
    pub runs: Vec<OrbitReturns>,
}

/// The orbits of shard `shard` of [`kac_comparison`](super::kac_comparison)
/// with the same arguments.
///
/// ```
/// use spinball_analysis::phase_space::{KacPart, SectionBox, kac_comparison, kac_part};
/// use spinball_analysis::run::{Shard, Threads};
/// use spinball_core::{Billiard, SpinLaw};
/// use spinball_geometry::Stadium;
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?);
/// let region = SectionBox::new(0.0..2.0, -0.5..0.5);
/// let parts = (0..3)
///     .map(|k| kac_part(&billiard, &region, 7, 2_000, 1, Threads::All, Shard::new(k, 3)?))
///     .collect::<Result<Vec<_>, _>>()?;
/// let whole = kac_comparison(&billiard, &region, 7, 2_000, 1, Threads::All)?;
/// assert_eq!(KacPart::merge(parts)?, whole);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// As [`kac_comparison`](super::kac_comparison).
pub fn kac_part<B: Boundary + Sync>(
    billiard: &Billiard<B>,
    region: &SectionBox,
    orbits: u64,
    collisions: u64,
    seed: u64,
    threads: Threads,
    shard: Shard,
) -> Result<KacPart, AnalysisError> {
    if orbits < 2 {
        return Err(AnalysisError::invalid(
            "orbits",
            format!("need at least 2 for a standard error, got {orbits}"),
        ));
    }
    if collisions == 0 {
        return Err(AnalysisError::invalid("collisions", "must be > 0"));
    }
    let (table, law) = (billiard.table(), billiard.law());
    let measure = InvariantMeasure::new(table, law)?;
    let probability = measure.probability(region)?;
    let starts = shard.range(0..orbits);
    let runs = map_indices(starts.clone(), threads, |i| {
        let start = invariant_start(table, law, &measure, &mut ic_rng(seed, i))?;
        let r = orbit_returns(billiard, start, collisions, region).map_err(|e| e.at_index(i))?;
        Ok(OrbitReturns { index: i, ..r })
    })?;
    Ok(KacPart {
        table: TableRecord::of(table),
        version: env!("CARGO_PKG_VERSION").to_string(),
        shard,
        starts,
        orbits,
        collisions,
        seed,
        alpha: law.alpha(),
        region: region.clone(),
        probability,
        runs,
    })
}

impl KacPart {
    /// Whether `other` is a part of the same run as `self`: the first field
    /// that differs (table by its geometry, version, α, region, orbits,
    /// collisions, seed; numbers bit for bit).
    ///
    /// # Errors
    /// [`RunDifference::Field`] naming the field and both values;
    /// [`RunDifference::NoShape`] for a table without a shape.
    pub fn same_run(&self, other: &KacPart) -> Result<(), RunDifference> {
        self.table.same_table(&other.table)?;
        let fields: [(&'static str, String, String); 7] = [
            ("version", self.version.clone(), other.version.clone()),
            (
                "alpha",
                format!("{:?}", self.alpha),
                format!("{:?}", other.alpha),
            ),
            (
                "region",
                format!("{:?}", self.region),
                format!("{:?}", other.region),
            ),
            ("orbits", self.orbits.to_string(), other.orbits.to_string()),
            (
                "collisions per orbit",
                self.collisions.to_string(),
                other.collisions.to_string(),
            ),
            ("seed", self.seed.to_string(), other.seed.to_string()),
            (
                "probability",
                format!("{:?}", self.probability),
                format!("{:?}", other.probability),
            ),
        ];
        match fields.into_iter().find(|(_, x, y)| x != y) {
            Some((what, first, other)) => Err(RunDifference::Field { what, first, other }),
            None => Ok(()),
        }
    }

    /// Join the parts of one run (in any order) into the comparison
    /// [`kac_comparison`](super::kac_comparison) gives in one run, bitwise.
    ///
    /// # Errors
    /// [`MergeError`]: no parts, parts of different runs (naming the field
    /// and both values), blocks that overlap or leave orbits out, a part
    /// whose orbits do not match its block (damaged or edited).
    pub fn merge(parts: Vec<KacPart>) -> Result<KacComparison, MergeError> {
        let first = parts.first().ok_or(MergeError::Empty)?;
        for p in &parts[1..] {
            first.same_run(p)?;
        }
        for p in &parts {
            let indices: Vec<u64> = p.runs.iter().map(|o| o.index).collect();
            if !indices.iter().copied().eq(p.starts.clone()) {
                return Err(MergeError::Estimate(AnalysisError::invalid(
                    "shards",
                    format!(
                        "shard {} holds {} orbits for its block {:?}: damaged or edited",
                        p.shard,
                        indices.len(),
                        p.starts
                    ),
                )));
            }
        }
        let blocks: Vec<Range<u64>> = parts.iter().map(|p| p.starts.clone()).collect();
        let order = tile(&blocks, &(0..first.orbits))?;
        let (alpha, region, probability) = (first.alpha, first.region.clone(), first.probability);
        let mut parts: Vec<Option<KacPart>> = parts.into_iter().map(Some).collect();
        let runs = order
            .into_iter()
            .filter_map(|k| parts[k].take())
            .flat_map(|p| p.runs)
            .collect();
        Ok(KacComparison::from_orbits(alpha, region, probability, runs))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::phase_space::kac_comparison;
    use spinball_core::SpinLaw;
    use spinball_geometry::{Sinai, Stadium};

    #[test]
    fn shards_join_bitwise_and_refuse_gaps_overlaps_and_other_runs() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let region = SectionBox::new(0.0..2.0, -0.5..0.5);
        let part = |k, n, seed| {
            kac_part(
                &billiard,
                &region,
                9,
                1_000,
                seed,
                Threads::Fixed(1),
                Shard::new(k, n).unwrap(),
            )
            .unwrap()
        };
        let whole = kac_comparison(&billiard, &region, 9, 1_000, 3, Threads::Fixed(2)).unwrap();
        let parts: Vec<_> = (0..4).map(|k| part(k, 4, 3)).collect();
        let reversed: Vec<_> = parts.iter().rev().cloned().collect();
        assert_eq!(KacPart::merge(reversed).unwrap(), whole);
        let e = KacPart::merge(parts[..3].to_vec()).unwrap_err();
        assert!(e.to_string().contains("missing"), "{e}");
        let twice = vec![parts[0].clone(), parts[0].clone(), parts[1].clone()];
        assert!(matches!(
            KacPart::merge(twice),
            Err(MergeError::Overlap { .. })
        ));
        let e = KacPart::merge(vec![parts[0].clone(), part(1, 4, 4)]).unwrap_err();
        assert!(e.to_string().contains("seed 3 in one, 4 in another"), "{e}");
        let sinai = Billiard::new(Sinai::new(2.0, 1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let other = kac_part(
            &sinai,
            &region,
            9,
            1_000,
            3,
            Threads::Fixed(1),
            Shard::new(1, 4).unwrap(),
        )
        .unwrap();
        let e = KacPart::merge(vec![parts[0].clone(), other]).unwrap_err();
        assert!(e.to_string().contains("table"), "{e}");
        let mut edited = parts[2].clone();
        edited.runs.pop();
        let mut all = parts.clone();
        all[2] = edited;
        assert!(KacPart::merge(all).is_err());
        assert!(matches!(KacPart::merge(Vec::new()), Err(MergeError::Empty)));
    }
}
