//! Splitting an ensemble's initial conditions across processes.
//!
//! Documented in the group docs (`run/mod.rs`), section "Shards".

use std::{fmt, ops::Range, str::FromStr};

use super::partial::MergeError;
use crate::error::AnalysisError;

/// Shard `index` of `count` (0-based: `0/4` … `3/4`, as a SLURM array
/// `--array=0-3` numbers its tasks).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Shard {
    /// Which shard, `0..count`.
    pub index: u64,
    /// How many shards.
    pub count: u64,
}

impl Shard {
    /// The whole range as one shard.
    pub const WHOLE: Shard = Shard { index: 0, count: 1 };

    /// Shard `index` of `count`.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] unless `count >= 1` and
    /// `index < count`.
    pub fn new(index: u64, count: u64) -> Result<Self, AnalysisError> {
        if count == 0 || index >= count {
            return Err(AnalysisError::invalid(
                "shard",
                format!(
                    "shard {index}/{count} does not exist: shards are numbered 0..N with N >= 1"
                ),
            ));
        }
        Ok(Shard { index, count })
    }

    /// This shard's block of `range`: `range` cut into `count` contiguous
    /// blocks whose sizes differ by at most one, in order.
    #[must_use]
    pub fn range(&self, range: Range<u64>) -> Range<u64> {
        let n = u128::from(range.end.saturating_sub(range.start));
        let cut = |k: u64| {
            // k·n/count <= n, which fits in u64.
            range.start + (u128::from(k) * n / u128::from(self.count)) as u64
        };
        cut(self.index)..cut(self.index + 1)
    }
}

/// Check that the blocks (of the shards of one run) tile `total`: each
/// index in exactly one block. Returns the positions of the blocks in
/// `blocks` in index order, the order to join them in.
///
/// # Errors
/// [`MergeError::Empty`] for no blocks, [`MergeError::Overlap`] for two
/// blocks that share indices, [`MergeError::Missing`] for indices of
/// `total` no block holds, or a block outside it.
pub fn tile(blocks: &[Range<u64>], total: &Range<u64>) -> Result<Vec<usize>, MergeError> {
    if blocks.is_empty() {
        return Err(MergeError::Empty);
    }
    let mut order: Vec<usize> = (0..blocks.len()).collect();
    order.sort_by_key(|&k| (blocks[k].start, blocks[k].end));
    let mut next = total.start;
    let mut previous: Option<&Range<u64>> = None;
    for &k in &order {
        let b = &blocks[k];
        if b.start > next {
            return Err(MergeError::Missing {
                missing: next..b.start,
            });
        }
        if b.start < next {
            return Err(MergeError::Overlap {
                first: previous.cloned().unwrap_or(total.start..next),
                second: b.clone(),
            });
        }
        next = b.end;
        previous = Some(b);
    }
    match next.cmp(&total.end) {
        std::cmp::Ordering::Less => Err(MergeError::Missing {
            missing: next..total.end,
        }),
        std::cmp::Ordering::Greater => Err(MergeError::Missing {
            missing: total.end..next,
        }),
        std::cmp::Ordering::Equal => Ok(order),
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl FromStr for Shard {
    type Err = AnalysisError;

    /// `K/N`, e.g. `0/4`.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let bad = || {
            AnalysisError::invalid(
                "shard",
                format!("`{s}` is not a shard: expected K/N with 0 <= K < N, e.g. 0/4"),
            )
        };
        let (k, n) = s.split_once('/').ok_or_else(bad)?;
        let k = k.trim().parse().map_err(|_| bad())?;
        let n = n.trim().parse().map_err(|_| bad())?;
        Shard::new(k, n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_tile_the_range_in_order() {
        for (range, count) in [(0..10, 3), (5..6, 4), (0..0, 2), (7..1007, 7)] {
            let mut next = range.start;
            let mut sizes = Vec::new();
            for index in 0..count {
                let r = Shard::new(index, count).unwrap().range(range.clone());
                assert_eq!(r.start, next, "shard {index}/{count} of {range:?}");
                next = r.end;
                sizes.push(r.end - r.start);
            }
            assert_eq!(next, range.end);
            let (lo, hi) = (sizes.iter().min().unwrap(), sizes.iter().max().unwrap());
            assert!(hi - lo <= 1, "{sizes:?}");
        }
    }

    #[test]
    fn tiles_are_checked_and_ordered() {
        let blocks = [4..7, 0..4, 7..10];
        assert_eq!(tile(&blocks, &(0..10)).unwrap(), vec![1, 0, 2]);
        assert_eq!(
            tile(&[0..4, 5..10], &(0..10)),
            Err(MergeError::Missing { missing: 4..5 })
        );
        assert_eq!(
            tile(&[0..4, 3..10], &(0..10)),
            Err(MergeError::Overlap {
                first: 0..4,
                second: 3..10
            })
        );
        let first_only = [0..4, 4..4];
        assert_eq!(
            tile(&first_only, &(0..10)),
            Err(MergeError::Missing { missing: 4..10 })
        );
        assert_eq!(tile(&[], &(0..10)), Err(MergeError::Empty));
    }

    #[test]
    fn huge_ranges_do_not_overflow() {
        let s = Shard::new(2, 3).unwrap();
        assert_eq!(s.range(0..u64::MAX).end, u64::MAX);
    }

    #[test]
    fn parses_and_rejects() {
        assert_eq!(
            "1/4".parse::<Shard>().unwrap(),
            Shard { index: 1, count: 4 }
        );
        assert_eq!(Shard::new(3, 4).unwrap().to_string(), "3/4");
        for bad in ["4/4", "1/0", "x/2", "2", "-1/3", ""] {
            let e = bad.parse::<Shard>().unwrap_err().to_string();
            assert!(e.contains("shard"), "{bad}: {e}");
        }
    }
}
