//! How long an escape run may go on before a ball still inside counts as
//! censored.

use crate::error::AnalysisError;

/// The limits of one trajectory of an escape run: it stops at whichever
/// comes first, and a ball still inside then is censored.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Budget {
    /// Most collisions (crossings of periodic walls do not count).
    pub collisions: u64,
    /// Longest time (`f64::INFINITY`: no time limit).
    pub time: f64,
}

impl Budget {
    /// At most `collisions` collisions, no time limit.
    #[must_use]
    pub fn collisions(collisions: u64) -> Self {
        Budget {
            collisions,
            time: f64::INFINITY,
        }
    }

    /// At most time `time`, and at most `u64::MAX` collisions.
    #[must_use]
    pub fn time(time: f64) -> Self {
        Budget {
            collisions: u64::MAX,
            time,
        }
    }

    /// Check the budget can run.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for zero collisions or a time that
    /// is not positive (or NaN).
    pub fn validate(&self) -> Result<(), AnalysisError> {
        if self.collisions == 0 {
            return Err(AnalysisError::invalid(
                "budget",
                "a budget of 0 collisions runs nothing: give at least 1",
            ));
        }
        if !(self.time > 0.0) {
            return Err(AnalysisError::invalid(
                "budget",
                format!(
                    "the time budget must be > 0 (or infinite), got {}",
                    self.time
                ),
            ));
        }
        Ok(())
    }
}
