//! The spectrum document: the Lyapunov spectra of a run at one α or a
//! list, whole or one shard, and the one way to join the shards.
//!
//! Documented in the group docs (`report/mod.rs`), section "Merging".

use std::ops::Range;

use super::partial::same_extent;
use crate::run::{MergeError, Shard, SpectrumEstimate, TableRecord};

/// The spectra of a run: one estimate per α, of the whole run or of one
/// shard. Its JSON is the `spinball.spectrum` or
/// `spinball.spectrum.partial` kind of [`Document`](super::Document).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct SpectrumDocument {
    /// The table.
    pub table: TableRecord,
    /// The α of each point.
    pub alphas: Vec<f64>,
    /// The shard, for a partial result.
    pub shard: Option<Shard>,
    /// The initial conditions of the whole run.
    pub total: Range<u64>,
    /// One estimate per α.
    pub points: Vec<SpectrumEstimate>,
}

impl SpectrumDocument {
    /// The spectra `points` (one per α of `alphas`) of a run over `total`
    /// on `table`; `shard`: the piece of a sharded run they are.
    #[must_use]
    pub fn new(
        table: TableRecord,
        alphas: Vec<f64>,
        shard: Option<Shard>,
        total: Range<u64>,
        points: Vec<SpectrumEstimate>,
    ) -> Self {
        SpectrumDocument {
            table,
            alphas,
            shard,
            total,
            points,
        }
    }

    /// Whether `self` and `other` are shards of one run: the same table
    /// (by its geometry), α, initial conditions and number of points.
    ///
    /// # Errors
    /// [`MergeError::DifferentRuns`] naming the first field that differs;
    /// [`MergeError::Table`] for a table without a shape.
    pub fn same_run(&self, other: &SpectrumDocument) -> Result<(), MergeError> {
        self.table.same_table(&other.table)?;
        if self
            .alphas
            .iter()
            .map(|a| a.to_bits())
            .ne(other.alphas.iter().map(|a| a.to_bits()))
        {
            return Err(MergeError::DifferentRuns {
                what: "alpha",
                first: format!("{:?}", self.alphas),
                other: format!("{:?}", other.alphas),
            });
        }
        same_extent(
            (&self.total, self.points.len()),
            (&other.total, other.points.len()),
        )
    }

    /// Join the shards of one spectrum run (in any order) into the whole
    /// result: bitwise that of one unsharded run, bar the wall times.
    ///
    /// # Errors
    /// [`MergeError`]: no shards, shards of different runs
    /// ([`SpectrumDocument::same_run`]), overlapping or missing initial
    /// conditions, a shard that does not hold together.
    pub fn merge(parts: &[SpectrumDocument]) -> Result<SpectrumDocument, MergeError> {
        let first = parts.first().ok_or(MergeError::Empty)?;
        for p in &parts[1..] {
            first.same_run(p)?;
        }
        let mut parts: Vec<&SpectrumDocument> = parts.iter().collect();
        parts.sort_by_key(|p| p.points.first().map_or(0, |e| e.first_index));
        let range = |e: &SpectrumEstimate| e.first_index..e.first_index + e.n_ics;
        let points = (0..first.points.len())
            .map(|k| {
                let mut pieces = parts.iter().map(|p| &p.points[k]);
                let head = pieces.next().expect("at least one part");
                if head.first_index > first.total.start {
                    return Err(MergeError::Missing {
                        missing: first.total.start..head.first_index,
                    });
                }
                let joined = pieces.try_fold(head.clone(), |acc, e| {
                    let end = range(&acc).end;
                    if e.first_index > end {
                        return Err(MergeError::Missing {
                            missing: end..e.first_index,
                        });
                    }
                    if e.first_index < end {
                        return Err(MergeError::Overlap {
                            first: range(&acc),
                            second: range(e),
                        });
                    }
                    Ok(acc.merge(e)?)
                })?;
                let end = range(&joined).end;
                if end < first.total.end {
                    return Err(MergeError::Missing {
                        missing: end..first.total.end,
                    });
                }
                Ok(joined)
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(SpectrumDocument {
            shard: None,
            points,
            ..first.clone()
        })
    }
}

/// One α of a spectrum document as a flat record: the five mean exponents
/// (`l1` largest), their standard errors and the number of initial
/// conditions; the CSV of `spinball spectrum --csv`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct SpectrumRow {
    /// Spin parameter.
    pub alpha: f64,
    /// Mean of the largest exponent.
    pub l1: f64,
    /// Mean of the second exponent.
    pub l2: f64,
    /// Mean of the third exponent.
    pub l3: f64,
    /// Mean of the fourth exponent.
    pub l4: f64,
    /// Mean of the smallest exponent.
    pub l5: f64,
    /// Standard error of `l1`.
    pub sem1: f64,
    /// Standard error of `l2`.
    pub sem2: f64,
    /// Standard error of `l3`.
    pub sem3: f64,
    /// Standard error of `l4`.
    pub sem4: f64,
    /// Standard error of `l5`.
    pub sem5: f64,
    /// Initial conditions.
    pub n_ics: u64,
}

impl SpectrumDocument {
    /// One [`SpectrumRow`] per α.
    #[must_use]
    pub fn rows(&self) -> Vec<SpectrumRow> {
        self.alphas
            .iter()
            .zip(&self.points)
            .map(|(&alpha, p)| {
                let [l1, l2, l3, l4, l5] = p.mean;
                let [sem1, sem2, sem3, sem4, sem5] = p.sem;
                SpectrumRow {
                    alpha,
                    l1,
                    l2,
                    l3,
                    l4,
                    l5,
                    sem1,
                    sem2,
                    sem3,
                    sem4,
                    sem5,
                    n_ics: p.n_ics,
                }
            })
            .collect()
    }
}
