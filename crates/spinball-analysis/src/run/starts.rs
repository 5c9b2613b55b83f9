//! Where an ensemble's initial conditions come from: drawn by a sampler, or
//! given as a list of states.
//!
//! Documented in the group docs (`run/mod.rs`), section "Initial conditions".

use rand_pcg::Pcg64;
use spinball_core::{Sampler, SpinLaw, State, ic_rng};
use spinball_geometry::Boundary;

use crate::error::AnalysisError;

/// The initial conditions of an ensemble.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Starts {
    /// Drawn with a sampler from the per-index streams.
    Sampled(Sampler),
    /// Given: initial condition `i` is `states[i]`.
    States(Vec<State>),
}

impl Starts {
    /// The sampler, if the states are drawn.
    #[must_use]
    pub fn sampler(&self) -> Option<Sampler> {
        match self {
            Starts::Sampled(s) => Some(*s),
            Starts::States(_) => None,
        }
    }

    /// How many initial conditions there are (`None`: unlimited).
    #[must_use]
    pub fn count(&self) -> Option<u64> {
        match self {
            Starts::Sampled(_) => None,
            Starts::States(s) => Some(s.len() as u64),
        }
    }

    /// Initial condition `index` of the run with `seed` on `table` under
    /// `law`, and its stream positioned after the state (for the direction).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for an index past the end of a list;
    /// [`AnalysisError::NoRoom`] if the sampler finds no room in the table.
    pub fn draw<B: Boundary>(
        &self,
        table: &B,
        law: &SpinLaw,
        seed: u64,
        index: u64,
    ) -> Result<(State, Pcg64), AnalysisError> {
        let mut rng = ic_rng(seed, index);
        let state = match self {
            Starts::Sampled(sampler) => sampler.try_sample(table, law, &mut rng)?,
            Starts::States(states) => *usize::try_from(index)
                .ok()
                .and_then(|i| states.get(i))
                .ok_or_else(|| {
                    AnalysisError::invalid(
                        "indices",
                        format!(
                            "initial condition {index} asked for, but only {} states were given",
                            states.len()
                        ),
                    )
                })?,
        };
        Ok((state, rng))
    }
}

impl From<Sampler> for Starts {
    fn from(s: Sampler) -> Self {
        Starts::Sampled(s)
    }
}

impl From<Vec<State>> for Starts {
    fn from(s: Vec<State>) -> Self {
        Starts::States(s)
    }
}
