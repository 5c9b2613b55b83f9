//! An estimate inside a summary that may have been refused: a summary of a
//! run reports every number it can, and for each one it cannot, the reason
//! (too few escapes in the window, no ball escaped) instead of a NaN or a
//! silently missing field.

use std::fmt;

/// A fitted estimate, or the reason it could not be made (the estimator's
/// typed error, as text).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
#[must_use]
pub enum Fitted<T> {
    /// The estimate.
    Fit(T),
    /// Why there is none: what is wrong and what would work.
    Refused(String),
}

impl<T> Fitted<T> {
    /// `Fit` from `Ok`, `Refused` with the error's message from `Err`.
    pub fn from_result<E: fmt::Display>(result: Result<T, E>) -> Self {
        match result {
            Ok(v) => Fitted::Fit(v),
            Err(e) => Fitted::Refused(e.to_string()),
        }
    }

    /// The estimate, if there is one.
    #[must_use]
    pub fn fit(&self) -> Option<&T> {
        match self {
            Fitted::Fit(v) => Some(v),
            Fitted::Refused(_) => None,
        }
    }

    /// The reason, if the estimate was refused.
    #[must_use]
    pub fn refused(&self) -> Option<&str> {
        match self {
            Fitted::Fit(_) => None,
            Fitted::Refused(why) => Some(why),
        }
    }
}

impl<T: fmt::Display> fmt::Display for Fitted<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Fitted::Fit(v) => v.fmt(f),
            Fitted::Refused(why) => write!(f, "none ({why})"),
        }
    }
}
