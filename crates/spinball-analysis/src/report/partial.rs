//! The pieces of a Lyapunov run as one document (a shard's share of every
//! α, or what an interrupted run finished) and the one way to join them.
//!
//! Documented in the group docs (`report/mod.rs`), section "Merging".

use std::ops::Range;

use super::lyapunov::LyapunovDocument;
use crate::run::{MergeError, PartialRun, Shard, merge_partials};

/// A piece of a Lyapunov run: a shard's share of every α, or what an
/// interrupted run finished (a checkpoint). Its JSON is the
/// `spinball.lyapunov.partial` kind of [`Document`](super::Document).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct PartialDocument {
    /// Which shard this is.
    pub shard: Shard,
    /// The initial conditions of the whole run (all shards).
    pub total: Range<u64>,
    /// One partial run per α, in the order asked (those not started yet
    /// are absent).
    pub points: Vec<PartialRun>,
}

impl PartialDocument {
    /// An empty piece: `shard` of a run over `total`.
    #[must_use]
    pub fn new(shard: Shard, total: Range<u64>) -> Self {
        PartialDocument {
            shard,
            total,
            points: Vec::new(),
        }
    }

    /// Whether `self` and `other` are pieces of one run: the same initial
    /// conditions in all, the same number of α, and at every α the same
    /// parameters (table by its geometry) and version.
    ///
    /// # Errors
    /// [`MergeError::DifferentRuns`] naming the first field that differs
    /// (its value in `self`, then in `other`); [`MergeError::Table`] for a
    /// table without a shape.
    pub fn same_run(&self, other: &PartialDocument) -> Result<(), MergeError> {
        same_extent(
            (&self.total, self.points.len()),
            (&other.total, other.points.len()),
        )?;
        for (a, b) in self.points.iter().zip(&other.points) {
            a.provenance.difference(&b.provenance)?;
            if a.version != b.version {
                return Err(MergeError::DifferentRuns {
                    what: "version",
                    first: a.version.clone(),
                    other: b.version.clone(),
                });
            }
        }
        Ok(())
    }

    /// Join the pieces of one run (in any order) into its finished result:
    /// at every α the estimate one unsharded run gives, bitwise, except
    /// the wall time (the sum of the pieces').
    ///
    /// # Errors
    /// [`MergeError`]: no pieces, pieces of different runs
    /// ([`PartialDocument::same_run`]), overlapping or missing initial
    /// conditions, an unfinished piece, a piece that does not hold
    /// together.
    pub fn merge(parts: &[PartialDocument]) -> Result<LyapunovDocument, MergeError> {
        let first = parts.first().ok_or(MergeError::Empty)?;
        for p in &parts[1..] {
            first.same_run(p)?;
        }
        let points = (0..first.points.len())
            .map(|k| {
                let pieces = parts.iter().map(|d| d.points[k].clone()).collect();
                merge_partials(pieces, Some(first.total.clone()))
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(LyapunovDocument::new(points))
    }
}

/// Whether two pieces (their whole run's initial conditions and their
/// number of α) can be of one run.
///
/// # Errors
/// [`MergeError::DifferentRuns`] naming the initial conditions or the
/// number of α, with the first piece's value first.
pub(super) fn same_extent(
    first: (&Range<u64>, usize),
    other: (&Range<u64>, usize),
) -> Result<(), MergeError> {
    let (what, a, b) = if first.0 != other.0 {
        (
            "initial conditions",
            format!("{:?}", first.0),
            format!("{:?}", other.0),
        )
    } else if first.1 != other.1 {
        (
            "number of α values",
            first.1.to_string(),
            other.1.to_string(),
        )
    } else {
        return Ok(());
    };
    Err(MergeError::DifferentRuns {
        what,
        first: a,
        other: b,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::run::Ensemble;
    use crate::test_support::template;

    /// The two halves of `template()` over 0..8 (one α), as documents.
    fn halves(seed: u64) -> Vec<PartialDocument> {
        (0..2)
            .map(|k| {
                let shard = Shard::new(k, 2).unwrap();
                let indices = shard.range(0..8);
                let e: Ensemble<_> = template().with_seed(seed).with_indices(indices.clone());
                let part = e.run_partial(None, &mut crate::run::Silent).unwrap();
                let mut d = PartialDocument::new(shard, 0..8);
                d.points.push(part);
                d
            })
            .collect()
    }

    #[test]
    fn merged_halves_are_the_whole_run_bit_for_bit() {
        let parts = halves(7);
        let whole = template().with_seed(7).with_indices(0..8).run().unwrap();
        for order in [[0, 1], [1, 0]] {
            let docs = [parts[order[0]].clone(), parts[order[1]].clone()];
            let merged = PartialDocument::merge(&docs).unwrap();
            let m = &merged.points[0];
            assert_eq!(m.mean().to_bits(), whole.mean().to_bits());
            assert_eq!(m.sem().to_bits(), whole.sem().to_bits());
            assert_eq!(m.trajectories(), whole.trajectories());
        }
    }

    #[test]
    fn pieces_of_different_runs_name_the_field() {
        let a = halves(7);
        let b = halves(8);
        let e = PartialDocument::merge(&[a[0].clone(), b[1].clone()]).unwrap_err();
        assert_eq!(
            e,
            MergeError::DifferentRuns {
                what: "seed",
                first: "7".into(),
                other: "8".into()
            }
        );
        let mut wider = a[1].clone();
        wider.total = 0..9;
        let e = a[0].same_run(&wider).unwrap_err();
        assert!(
            e.to_string()
                .contains("initial conditions 0..8 in one, 0..9 in another"),
            "{e}"
        );
        assert_eq!(PartialDocument::merge(&[]), Err(MergeError::Empty));
        assert!(matches!(
            PartialDocument::merge(&a[..1]),
            Err(MergeError::Missing { .. })
        ));
    }
}
