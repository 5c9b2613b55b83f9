//! The scene of an open-table ensemble: what runs, from where, on how many
//! threads.

use std::ops::Range;

use spinball_core::{Ball, Billiard, Sampler, State};
use spinball_geometry::Boundary;

use crate::error::AnalysisError;
use crate::run::{Engine, Shard, Starts, Threads};

/// Many initial conditions on one open or periodic table. See the
/// [group docs](super).
#[derive(Debug, Clone)]
pub struct OpenEnsemble<B> {
    billiard: Billiard<B>,
    starts: Starts,
    seed: u64,
    indices: Range<u64>,
    threads: Threads,
    engine: Engine,
}

impl<B: Boundary + Sync> OpenEnsemble<B> {
    /// Initial conditions `0..1000` of seed 0, drawn by the paper's
    /// sampler, on every core.
    #[must_use]
    pub fn new(billiard: Billiard<B>) -> Self {
        OpenEnsemble {
            billiard,
            starts: Starts::Sampled(Sampler::Paper),
            seed: 0,
            indices: 0..1000,
            threads: Threads::All,
            engine: Engine::default(),
        }
    }

    /// Draw (or take) the initial conditions from `starts`.
    #[must_use]
    pub fn with_starts(mut self, starts: impl Into<Starts>) -> Self {
        self.starts = starts.into();
        self
    }

    /// Use `seed` for the per-index streams.
    #[must_use]
    pub fn with_seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// Run initial conditions `indices`.
    #[must_use]
    pub fn with_indices(mut self, indices: Range<u64>) -> Self {
        self.indices = indices;
        self
    }

    /// Run only `shard`'s block of the index range (records of the shards,
    /// concatenated in order, are those of the whole range).
    #[must_use]
    pub fn with_shard(mut self, shard: Shard) -> Self {
        self.indices = shard.range(self.indices.clone());
        self
    }

    /// Run on `threads`.
    #[must_use]
    pub fn with_threads(mut self, threads: Threads) -> Self {
        self.threads = threads;
        self
    }

    /// Run escapes with `engine` ([`Engine::Lanes`] by default; the
    /// records are bitwise the same on either). See
    /// [`engine_used`](Self::engine_used).
    #[must_use]
    pub fn with_engine(mut self, engine: Engine) -> Self {
        self.engine = engine;
        self
    }

    /// The engine [`escape_times`](Self::escape_times) runs on:
    /// [`Engine::Lanes`] if asked for and the table has an escape lane
    /// form (a table built from segments whose walls reflect or are holes:
    /// [`has_escape_lane_form`](spinball_lanes::has_escape_lane_form)),
    /// else [`Engine::Scalar`] (the built-in tables, tables of your own
    /// without a shape, periodic tables). The instruction set is chosen at
    /// run time, as for the λ ensembles. Displacements always run on the
    /// scalar engine.
    #[must_use]
    pub fn engine_used(&self) -> Engine {
        match self.engine {
            Engine::Lanes if spinball_lanes::has_escape_lane_form(self.billiard.table()) => {
                Engine::Lanes
            }
            _ => Engine::Scalar,
        }
    }

    /// The billiard.
    #[must_use]
    pub fn billiard(&self) -> &Billiard<B> {
        &self.billiard
    }

    /// The index range run.
    #[must_use]
    pub fn indices(&self) -> Range<u64> {
        self.indices.clone()
    }

    /// The threads.
    pub(super) fn threads(&self) -> Threads {
        self.threads
    }

    /// The initial state of initial condition `index`.
    pub(super) fn start(&self, index: u64) -> Result<State, AnalysisError> {
        let (state, _) =
            self.starts
                .draw(self.billiard.table(), self.billiard.law(), self.seed, index)?;
        Ok(state)
    }

    /// The launched ball of initial condition `index`.
    pub(super) fn launch(&self, index: u64) -> Result<Ball, AnalysisError> {
        let state = self.start(index)?;
        self.billiard
            .launch(state)
            .map_err(|source| AnalysisError::Launch { index, source })
    }
}
