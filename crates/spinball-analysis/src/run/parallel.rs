//! Deterministic parallel map over initial-condition indices.
//!
//! Documented in the group docs (`run/mod.rs`), section "Parallel maps".

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
    /// The most threads `Fixed(n)` may ask for: 1024. Results do not depend
    /// on the thread count, and more threads than cores only cost memory
    /// and scheduling; a huge count would spawn that many threads (each
    /// with its stack) before any work, so it is refused instead.
    pub const MAX: usize = 1024;

    /// Check the setting.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] unless `Fixed(n)` has
    /// `1 <= n <= `[`Threads::MAX`].
    pub fn validate(&self) -> Result<(), AnalysisError> {
        match *self {
            Threads::Fixed(n) if n == 0 || n > Self::MAX => Err(AnalysisError::invalid(
                "threads",
                format!(
                    "{n}: must be in 1..={} (results do not depend on it; all cores: Threads::All)",
                    Self::MAX
                ),
            )),
            _ => Ok(()),
        }
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
/// threads.
///
/// On failure the error is the one of the **lowest** failing index, on any
/// number of threads, so a failing ensemble reports the same initial
/// condition however its work was split. Indices above a failure already
/// seen are skipped; those below it still run, since one of them may fail
/// too.
///
/// # Errors
/// The error `f` returns for the lowest failing index, or
/// [`AnalysisError::InvalidOption`] for a thread count
/// [`Threads::validate`] refuses (checked before any thread is made) or a
/// thread pool that cannot be built.
pub fn map_indices<T, F>(
    indices: Range<u64>,
    threads: Threads,
    f: F,
) -> Result<Vec<T>, AnalysisError>
where
    T: Send,
    F: Fn(u64) -> Result<T, AnalysisError> + Sync + Send,
{
    threads.validate()?;
    #[cfg(feature = "rayon")]
    {
        use rayon::prelude::*;
        use std::sync::atomic::{AtomicU64, Ordering};
        let run = || {
            // The lowest index seen failing so far (`u64::MAX`: none).
            let failed = AtomicU64::new(u64::MAX);
            let outcomes: Vec<Option<Result<T, AnalysisError>>> = indices
                .clone()
                .into_par_iter()
                .map(|i| {
                    if i > failed.load(Ordering::Relaxed) {
                        return None;
                    }
                    let outcome = f(i);
                    if outcome.is_err() {
                        failed.fetch_min(i, Ordering::Relaxed);
                    }
                    Some(outcome)
                })
                .collect();
            // Every index below the lowest failure ran (an index is skipped
            // only above a failure), so in index order that failure comes
            // before any skipped index.
            outcomes.into_iter().flatten().collect()
        };
        match threads {
            Threads::Fixed(1) => indices.map(&f).collect(),
            Threads::All => run(),
            Threads::Fixed(n) => pool(n)?.install(run),
        }
    }
    #[cfg(not(feature = "rayon"))]
    {
        let _ = threads;
        indices.map(&f).collect()
    }
}

/// The pool of `n` threads, built on first use and kept for the process
/// (as rayon keeps its global pool): an ensemble calls [`map_indices`] once
/// per batch, and a pool built and dropped per call cost a quarter of a
/// 2-thread run's time (the dropped pool's workers still spin while the
/// next one's start). One pool per distinct `n` asked for.
#[cfg(feature = "rayon")]
fn pool(n: usize) -> Result<std::sync::Arc<rayon::ThreadPool>, AnalysisError> {
    use std::sync::{Arc, Mutex, OnceLock, PoisonError};
    /// The pools built so far, by size.
    type Pools = Vec<(usize, Arc<rayon::ThreadPool>)>;
    static POOLS: OnceLock<Mutex<Pools>> = OnceLock::new();
    let mut pools = POOLS
        .get_or_init(Mutex::default)
        .lock()
        .unwrap_or_else(PoisonError::into_inner);
    if let Some((_, p)) = pools.iter().find(|(size, _)| *size == n) {
        return Ok(Arc::clone(p));
    }
    let p = Arc::new(
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map_err(|e| AnalysisError::invalid("threads", e.to_string()))?,
    );
    pools.push((n, Arc::clone(&p)));
    Ok(p)
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

#[cfg(all(test, feature = "rayon"))]
mod tests {
    use std::sync::Arc;

    use super::*;

    #[test]
    fn a_fixed_pool_is_built_once_per_size() {
        let a = pool(3).unwrap();
        assert!(Arc::ptr_eq(&a, &pool(3).unwrap()));
        assert_eq!(a.current_num_threads(), 3);
        assert!(!Arc::ptr_eq(&a, &pool(5).unwrap()));
        // Results in index order on the kept pool, call after call.
        for _ in 0..3 {
            let squares = map_indices(0..100, Threads::Fixed(3), |i| Ok(i * i)).unwrap();
            assert_eq!(squares, (0..100).map(|i| i * i).collect::<Vec<u64>>());
        }
    }

    #[test]
    fn a_huge_thread_count_is_refused_before_any_thread_is_made() {
        for n in [0, Threads::MAX + 1, 100_000, usize::MAX] {
            let err = map_indices(0..10, Threads::Fixed(n), Ok).unwrap_err();
            assert!(
                err.to_string().contains(&format!("1..={}", Threads::MAX)),
                "{err}"
            );
            assert!(Threads::Fixed(n).validate().is_err());
        }
        assert!(Threads::Fixed(Threads::MAX).validate().is_ok());
    }

    #[test]
    fn the_lowest_failing_index_is_reported_on_any_thread_count() {
        // Index 3 fails after its lower neighbours' slow work; every index
        // from 500 on fails at once, so a second thread starting there
        // fails long before the first reaches 3.
        let f = |i: u64| {
            if i < 3 {
                std::thread::sleep(std::time::Duration::from_millis(20));
            }
            if i == 3 || i >= 500 {
                Err(AnalysisError::invalid("index", i.to_string()))
            } else {
                Ok(i)
            }
        };
        for threads in [
            Threads::Fixed(1),
            Threads::Fixed(2),
            Threads::Fixed(4),
            Threads::All,
        ] {
            for _ in 0..3 {
                let err = map_indices(0..1000, threads, f).unwrap_err();
                assert_eq!(err, AnalysisError::invalid("index", "3"), "{threads:?}");
                let err = map_chunks(0..1000, 7, threads, |r| r.map(f).collect()).unwrap_err();
                assert_eq!(err, AnalysisError::invalid("index", "3"), "{threads:?}");
            }
        }
    }
}
