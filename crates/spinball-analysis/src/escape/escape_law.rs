//! Whether an escape rate is a property of the table: the verdict that
//! joins the rate's drift check and the tail test.
//!
//! [`EscapeRate`] always returns a number for its window, and
//! [`AlgebraicTail`] always returns both fits of the tail; neither alone
//! says whether "the escape rate" of the table exists. A table whose
//! survival bends (islands, bouncing-ball orbits) still gives a `γ` on any
//! window, and quoting it as the rate would be wrong. [`EscapeLaw`] states
//! the verdict a report or a figure needs before it shows a rate: the
//! escape is exponential on the window, or it is not (and which check
//! says so), or the sample is too small to tell.
//!
//! Documented in the group docs (`escape/mod.rs`) and `docs/TRANSPORT.md`,
//! section "Escape rate" (drift check) and "Algebraic tail".

use std::fmt;

use super::{AlgebraicTail, EscapeRate, TailLaw};

/// The drift check fires beyond this many standard errors (the threshold
/// of `docs/TRANSPORT.md`, "Drift check").
pub const DRIFT_Z: f64 = 3.0;

/// What the drift check and the tail test say about an escape sample.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub enum EscapeLaw {
    /// The drift was measured and is within ±[`DRIFT_Z`], and the tail is
    /// not algebraic: `γ` is the rate of the exponential regime on its
    /// window.
    Exponential,
    /// At least one check fired: the rate of the window is not a property
    /// of the table.
    NotExponential {
        /// The rate changed by more than [`DRIFT_Z`] standard errors
        /// between the halves of the window.
        drift: bool,
        /// The tail test called the tail algebraic.
        algebraic_tail: bool,
    },
    /// Neither check fired, but the drift could not be measured (too few
    /// escapes in a half of the window): no verdict.
    Unchecked,
}

impl EscapeLaw {
    /// The verdict on `rate` and, where it could be fitted, `tail` (a
    /// tail that could not be fitted counts as not algebraic).
    ///
    /// ```
    /// use spinball_analysis::escape::{EscapeLaw, EscapeRate, RateWindow};
    /// // Quantiles of a rate-2 exponential: no drift, no tail test.
    /// let n = 2000;
    /// let t: Vec<f64> = (0..n).map(|i| -(1.0 - (i as f64 + 0.5) / n as f64).ln() / 2.0).collect();
    /// let rate = EscapeRate::fit(&t, &vec![false; n], RateWindow::default())?;
    /// assert_eq!(EscapeLaw::judge(&rate, None), EscapeLaw::Exponential);
    /// # Ok::<(), spinball_analysis::escape::EscapeError>(())
    /// ```
    pub fn judge(rate: &EscapeRate, tail: Option<&AlgebraicTail>) -> Self {
        let algebraic_tail = tail.is_some_and(|t| t.law == TailLaw::Algebraic);
        let drift = rate.drift.map(|z| z.abs() > DRIFT_Z);
        match (drift, algebraic_tail) {
            (Some(true), _) | (_, true) => EscapeLaw::NotExponential {
                drift: drift == Some(true),
                algebraic_tail,
            },
            (Some(false), false) => EscapeLaw::Exponential,
            (None, false) => EscapeLaw::Unchecked,
        }
    }

    /// Whether the rate may be quoted as the table's escape rate.
    #[must_use]
    pub fn is_exponential(&self) -> bool {
        *self == EscapeLaw::Exponential
    }
}

impl fmt::Display for EscapeLaw {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            EscapeLaw::Exponential => f.write_str("exponential"),
            EscapeLaw::NotExponential {
                drift,
                algebraic_tail,
            } => {
                let why = match (drift, algebraic_tail) {
                    (true, true) => "drift and algebraic tail",
                    (true, false) => "drift",
                    _ => "algebraic tail",
                };
                write!(f, "not exponential ({why})")
            }
            EscapeLaw::Unchecked => f.write_str("unchecked (too few escapes for the drift check)"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::escape::{RateWindow, TailWindow};
    use spinball_test_support::censored_quantiles;

    #[test]
    fn an_exponential_sample_has_a_rate() {
        // Rate 0.5, 4000 balls, censored at t = 8 (P = e^{-4} ≈ 1.8 %).
        let (t, c) = censored_quantiles(4000, 8.0, |u| -u.ln() / 0.5);
        let rate = EscapeRate::fit(&t, &c, RateWindow::default()).unwrap();
        let tail = AlgebraicTail::fit(&t, &c, TailWindow::default()).unwrap();
        assert_ne!(tail.law, TailLaw::Algebraic);
        let law = EscapeLaw::judge(&rate, Some(&tail));
        assert_eq!(law, EscapeLaw::Exponential, "{rate}; {tail}");
        assert!(law.is_exponential());
        assert_eq!(law.to_string(), "exponential");
    }

    #[test]
    fn a_power_law_is_not_exponential() {
        // P(t) = t^{-0.5} for t > 1, censored at 10⁴ (P = 1 %): the
        // default window's rate falls across it (drift) and the tail test
        // says algebraic.
        let (t, c) = censored_quantiles(4000, 1e4, |u| u.powf(-2.0));
        let rate = EscapeRate::fit(&t, &c, RateWindow::default()).unwrap();
        let tail = AlgebraicTail::fit(&t, &c, TailWindow::default()).unwrap();
        let law = EscapeLaw::judge(&rate, Some(&tail));
        assert_eq!(
            law,
            EscapeLaw::NotExponential {
                drift: true,
                algebraic_tail: true
            },
            "{rate}; {tail}"
        );
        assert!(!law.is_exponential());
        assert_eq!(
            law.to_string(),
            "not exponential (drift and algebraic tail)"
        );
        // Either check alone is enough.
        assert!(!EscapeLaw::judge(&rate, None).is_exponential());
    }

    #[test]
    fn too_few_escapes_give_no_verdict() {
        // 15 escapes in the window: the drift needs 10 in each half.
        let (t, c) = censored_quantiles(30, 100.0, |u| -u.ln());
        let rate = EscapeRate::fit(&t, &c, RateWindow::Range { t0: 0.0, t1: 100.0 }).unwrap();
        let rate = EscapeRate {
            drift: None,
            ..rate
        };
        assert_eq!(EscapeLaw::judge(&rate, None), EscapeLaw::Unchecked);
        // A drift within ±3 with a tail that could not be fitted: exponential.
        let rate = EscapeRate {
            drift: Some(-2.9),
            ..rate
        };
        assert_eq!(EscapeLaw::judge(&rate, None), EscapeLaw::Exponential);
        let rate = EscapeRate {
            drift: Some(3.1),
            ..rate
        };
        assert_eq!(
            EscapeLaw::judge(&rate, None),
            EscapeLaw::NotExponential {
                drift: true,
                algebraic_tail: false
            }
        );
    }
}
