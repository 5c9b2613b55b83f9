//! Escape times: per initial condition, when and how the ball left through
//! a hole, or that it was still inside when the budget ran out.

use spinball_core::{Event, Exit};
use spinball_geometry::Boundary;
use spinball_lanes::{CHUNK, LaneBilliard, LanesError};

use super::budget::Budget;
use super::scene::OpenEnsemble;
use crate::error::AnalysisError;
use crate::run::{Engine, map_chunks, map_indices};

/// One trajectory of an escape run.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EscapeRecord {
    /// Index of the initial condition.
    pub index: u64,
    /// Escape time, or for a censored ball the time it was last seen
    /// inside (the time budget, or the time of its last collision when
    /// the collision budget ran out).
    pub time: f64,
    /// Collisions before the escape (or before the run stopped).
    pub collisions: u64,
    /// Whether the ball was still inside when the budget ran out: its true
    /// escape time is longer than `time`.
    pub censored: bool,
    /// Where and how it left (`None` for a censored ball). `exit.time` is
    /// the last flight only; the escape time is `time`.
    pub exit: Option<Exit>,
}

impl<B: Boundary + Sync> OpenEnsemble<B> {
    /// Run each initial condition until it escapes or the `budget` runs
    /// out. One record per index, in index order: a ball still inside at
    /// the budget is censored, never dropped; on a table without holes
    /// every record is censored.
    ///
    /// Runs in vector lanes where [`engine_used`](Self::engine_used) says
    /// so (a table built from segments without periodic walls), else one
    /// ball at a time ([`Billiard::advance`](spinball_core::Billiard::advance));
    /// the records are bitwise the same either way, on any number of
    /// threads and in any split into shards.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for an empty index range or a
    /// budget [`Budget::validate`] refuses; [`AnalysisError::Launch`] and
    /// [`AnalysisError::Step`] (with the lowest failing index) for a start
    /// that cannot launch or a step that fails, the same on both engines.
    pub fn escape_times(&self, budget: Budget) -> Result<Vec<EscapeRecord>, AnalysisError> {
        budget.validate()?;
        if self.indices().is_empty() {
            return Err(AnalysisError::invalid(
                "indices",
                "the index range is empty: give at least one initial condition",
            ));
        }
        match self.engine_used() {
            Engine::Lanes => self.lane_escapes(budget),
            Engine::Scalar => map_indices(self.indices(), self.threads(), |index| {
                self.scalar_escape(index, budget)
            }),
        }
    }

    /// The lane path of [`escape_times`](Self::escape_times): chunks of
    /// [`CHUNK`] indices, each drawn as the scalar path draws them and run
    /// in lanes; chunks on the threads, back in index order. A chunk the
    /// lanes cannot run (a start that does not launch, a ball that fails)
    /// is run on the scalar path for its error, so errors are the scalar
    /// path's, lowest index first.
    fn lane_escapes(&self, budget: Budget) -> Result<Vec<EscapeRecord>, AnalysisError> {
        let billiard = self.billiard();
        let lanes = LaneBilliard::new_open(billiard.table(), *billiard.law())
            .map_err(AnalysisError::Lanes)?;
        map_chunks(self.indices(), CHUNK as u64, self.threads(), |range| {
            let run = range
                .clone()
                .map(|index| self.start(index))
                .collect::<Result<Vec<_>, _>>()
                .map_err(|_| 0)
                .and_then(|starts| {
                    lanes
                        .escape_times(&starts, budget.collisions, budget.time)
                        .map_err(|e| match e {
                            LanesError::NonFinite { index } | LanesError::Launch { index, .. } => {
                                index as u64
                            }
                            _ => 0,
                        })
                });
            match run {
                Ok(escapes) => Ok(range
                    .zip(escapes)
                    .map(|(index, e)| EscapeRecord {
                        index,
                        time: e.time,
                        collisions: e.collisions,
                        censored: e.is_censored(),
                        exit: e.exit,
                    })
                    .collect()),
                Err(at) => {
                    for index in range.clone() {
                        self.scalar_escape(index, budget)?;
                    }
                    Err(AnalysisError::EngineMismatch {
                        index: range.start + at,
                    })
                }
            }
        })
    }

    /// Initial condition `index` on the scalar path.
    fn scalar_escape(&self, index: u64, budget: Budget) -> Result<EscapeRecord, AnalysisError> {
        let billiard = self.billiard();
        let mut ball = self.launch(index)?;
        let mut record = EscapeRecord {
            index,
            time: 0.0,
            collisions: 0,
            censored: true,
            exit: None,
        };
        while record.collisions < budget.collisions {
            let event = billiard
                .advance(&mut ball)
                .map_err(|source| AnalysisError::Step { index, source })?;
            let t = record.time + event.time();
            if t > budget.time {
                // Still inside at the time budget.
                record.time = budget.time;
                break;
            }
            record.time = t;
            match event {
                Event::Collision(_) => record.collisions += 1,
                Event::Crossing(_) => {}
                Event::Escape(exit) => {
                    record.censored = false;
                    record.exit = Some(exit);
                    break;
                }
            }
        }
        Ok(record)
    }
}
