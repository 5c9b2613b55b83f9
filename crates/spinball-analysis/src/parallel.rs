//! Deterministic parallel map over initial-condition indices.
//!
//! Every per-trajectory result depends only on its index (its own random
//! stream, see [`spinball_core::ic_rng`]), and results come back **in index
//! order**; reductions then run sequentially over that order. So an ensemble
//! gives bitwise the same numbers for any thread count and any split of the
//! index range (float sums are not associative, and rayon's work splitting is
//! not deterministic, so nothing is ever summed inside the parallel part).

use std::ops::Range;

use crate::error::AnalysisError;

/// How many threads an ensemble may use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Threads {
    /// All cores (rayon's global pool) when the `rayon` feature is on; one thread otherwise.
    #[default]
    All,
    /// Exactly this many threads (`1` runs on the calling thread).
    Fixed(usize),
}

impl Threads {
    /// Check the setting.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for `Fixed(0)`.
    pub fn validate(&self) -> Result<(), AnalysisError> {
        if *self == Threads::Fixed(0) {
            return Err(AnalysisError::invalid("threads", "must be at least 1"));
        }
        Ok(())
    }

    /// Number of threads this setting means on this machine.
    pub fn count(&self) -> usize {
        match *self {
            Threads::Fixed(n) => n.max(1),
            Threads::All => {
                #[cfg(feature = "rayon")]
                {
                    rayon::current_num_threads()
                }
                #[cfg(not(feature = "rayon"))]
                {
                    1
                }
            }
        }
    }
}

/// `f(i)` for every `i` in `indices`, in index order, on up to `threads`
/// threads. Stops at the first error (the error of the lowest failing index
/// is reported when running sequentially; in parallel, some failing index).
///
/// # Errors
/// The first error returned by `f`, or [`AnalysisError::InvalidOption`] if a
/// thread pool cannot be built.
pub fn map_indices<T, F>(
    indices: Range<u64>,
    threads: Threads,
    f: F,
) -> Result<Vec<T>, AnalysisError>
where
    T: Send,
    F: Fn(u64) -> Result<T, AnalysisError> + Sync + Send,
{
    #[cfg(feature = "rayon")]
    {
        use rayon::prelude::*;
        let run = || {
            indices
                .clone()
                .into_par_iter()
                .map(&f)
                .collect::<Result<Vec<T>, AnalysisError>>()
        };
        match threads {
            Threads::Fixed(1) => indices.map(&f).collect(),
            Threads::All => run(),
            Threads::Fixed(n) => rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| AnalysisError::invalid("threads", e.to_string()))?
                .install(run),
        }
    }
    #[cfg(not(feature = "rayon"))]
    {
        let _ = threads;
        indices.map(&f).collect()
    }
}

/// `f` over consecutive chunks of `indices` (each at most `chunk` long), in
/// index order, on up to `threads` threads, with the chunks' results
/// concatenated. Chunk size only balances the load (and lets a lane kernel
/// fill its registers); when `f` treats each index on its own the result does
/// not depend on it.
///
/// # Errors
/// As [`map_indices`].
pub fn map_chunks<T, F>(
    indices: Range<u64>,
    chunk: u64,
    threads: Threads,
    f: F,
) -> Result<Vec<T>, AnalysisError>
where
    T: Send,
    F: Fn(Range<u64>) -> Result<Vec<T>, AnalysisError> + Sync + Send,
{
    let n = indices.end.saturating_sub(indices.start);
    if n == 0 {
        return Ok(Vec::new());
    }
    let chunk = chunk.max(1);
    let parts = map_indices(0..n.div_ceil(chunk), threads, |c| {
        let lo = indices.start + c * chunk;
        f(lo..(lo + chunk).min(indices.end))
    })?;
    Ok(parts.into_iter().flatten().collect())
}
