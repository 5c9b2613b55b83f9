//! Algebraic tails `P(t) ∝ t^{−β}`: what regular islands and bouncing-ball
//! orbits do to escape (balls stick near them and leave late), and a stated
//! rule for telling such a tail from an exponential one.
//!
//! Documented in the group docs (`escape/mod.rs`) and `docs/TRANSPORT.md`,
//! section "Algebraic tail".

use std::fmt;

use super::escape_rate::MIN_EVENTS;
use super::{EscapeError, Sample};

/// The default decision threshold: the Vuong statistic must pass ±3 for a
/// tail to be called algebraic or exponential.
pub const DECISION_Z: f64 = 3.0;

/// Where the tail starts.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum TailWindow {
    /// The default rule: the tail holds the latest `share` of the observed
    /// escapes and every censored ball; `t_min` is the escape time before
    /// them.
    Latest {
        /// Share of the escapes in the tail, in `(0, 1)`.
        share: f64,
    },
    /// The tail is everything after `t_min` (`> 0`).
    From {
        /// Start of the tail.
        t_min: f64,
    },
}

impl Default for TailWindow {
    /// `Latest { share: 0.2 }`: the last fifth of the escapes.
    fn default() -> Self {
        TailWindow::Latest { share: 0.2 }
    }
}

/// What the tail looks like.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum TailLaw {
    /// An exponential fits the tail better, by more than the threshold.
    Exponential,
    /// A power law fits the tail better, by more than the threshold.
    Algebraic,
    /// The data cannot tell them apart at this threshold.
    Undecided,
}

impl fmt::Display for TailLaw {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            TailLaw::Exponential => "exponential",
            TailLaw::Algebraic => "algebraic",
            TailLaw::Undecided => "undecided",
        })
    }
}

/// The tail `t > t_min` of an escape sample fitted twice, by the censored
/// maximum likelihood of a power law `P(t | t > t_min) = (t/t_min)^{−β}`
/// and of an exponential `e^{−γ(t − t_min)}`, and the two compared by
/// Vuong's test (the log-likelihood difference per ball, in standard
/// errors): [`AlgebraicTail::law`] says which fits.
///
/// ```
/// use spinball_analysis::escape::{AlgebraicTail, TailLaw, TailWindow};
/// // A power law with β = 1.5 (quantiles), censored at t = 1000.
/// let n = 2000;
/// let (mut t, mut c) = (Vec::new(), Vec::new());
/// for i in 0..n {
///     let x = (1.0 - (i as f64 + 0.5) / n as f64).powf(-1.0 / 1.5);
///     t.push(x.min(1000.0));
///     c.push(x > 1000.0);
/// }
/// let tail = AlgebraicTail::fit(&t, &c, TailWindow::default())?;
/// assert_eq!(tail.law, TailLaw::Algebraic);
/// assert!((tail.beta - 1.5).abs() < 3.0 * tail.beta_sem);
/// # Ok::<(), spinball_analysis::escape::EscapeError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct AlgebraicTail {
    /// The power-law exponent `β`.
    pub beta: f64,
    /// Its standard error `β/√D`.
    pub beta_sem: f64,
    /// The exponential rate fitted to the same tail.
    pub gamma: f64,
    /// Its standard error `γ/√D`.
    pub gamma_sem: f64,
    /// Start of the tail.
    pub t_min: f64,
    /// The largest observed time.
    pub t_max: f64,
    /// Balls observed beyond `t_min`.
    pub in_tail: u64,
    /// Escapes beyond `t_min` (`D`).
    pub escaped: u64,
    /// Vuong's statistic: positive when the power law fits better.
    pub vuong_z: f64,
    /// The decision at [`DECISION_Z`].
    pub law: TailLaw,
    /// The window asked for.
    pub window: TailWindow,
}

impl AlgebraicTail {
    /// Fit the tail of escape times `times` (`censored[i]` true for a ball
    /// still inside at `times[i]`) and decide at [`DECISION_Z`].
    ///
    /// # Errors
    /// As [`Survival::kaplan_meier`](super::Survival::kaplan_meier);
    /// [`EscapeError::InvalidOption`] for a window out of range,
    /// [`EscapeError::TooFewEvents`] for fewer than
    /// [`MIN_EVENTS`](super::MIN_EVENTS) escapes in the tail.
    pub fn fit(times: &[f64], censored: &[bool], window: TailWindow) -> Result<Self, EscapeError> {
        let sample = Sample::new(times, censored)?;
        let t_min = match window {
            TailWindow::Latest { share } => {
                if !(share > 0.0 && share < 1.0) {
                    return Err(EscapeError::invalid(
                        "share",
                        format!("{share}: the tail's share of the escapes must be in (0, 1)"),
                    ));
                }
                let skip = ((1.0 - share) * sample.escaped as f64).floor() as usize;
                if skip == 0 {
                    0.0
                } else {
                    sample.escape_time(skip - 1).unwrap_or(0.0)
                }
            }
            TailWindow::From { t_min } => t_min,
        };
        let t_max = sample.obs[sample.len() - 1].t;
        if !(t_min.is_finite() && t_min > 0.0) {
            return Err(EscapeError::invalid(
                "t_min",
                format!(
                    "{t_min}: a power-law tail needs a start t_min > 0 (escape times start above 0)"
                ),
            ));
        }
        let tail: Vec<_> = sample.obs.iter().filter(|o| o.t > t_min).collect();
        let escaped = tail.iter().filter(|o| !o.censored).count() as u64;
        if escaped < MIN_EVENTS {
            return Err(EscapeError::TooFewEvents {
                events: escaped,
                min: MIN_EVENTS,
                t0: t_min,
                t1: t_max,
            });
        }
        let d = escaped as f64;
        let log_exposure: f64 = tail.iter().map(|o| (o.t / t_min).ln()).sum();
        let exposure: f64 = tail.iter().map(|o| o.t - t_min).sum();
        let (beta, gamma) = (d / log_exposure, d / exposure);
        // Per-ball log-likelihoods: an escape at t has density
        // β t_min^β t^{−β−1} or γ e^{−γ(t−t_min)}; a censored ball the
        // survival (t/t_min)^{−β} or e^{−γ(t−t_min)}.
        let diffs: Vec<f64> = tail
            .iter()
            .map(|o| {
                let power = -beta * (o.t / t_min).ln();
                let expo = -gamma * (o.t - t_min);
                if o.censored {
                    power - expo
                } else {
                    (power + beta.ln() - o.t.ln()) - (expo + gamma.ln())
                }
            })
            .collect();
        let m = diffs.len() as f64;
        let mean = diffs.iter().sum::<f64>() / m;
        let var = diffs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / (m - 1.0);
        let vuong_z = if var > 0.0 {
            mean / (var / m).sqrt()
        } else {
            0.0
        };
        let law = if vuong_z > DECISION_Z {
            TailLaw::Algebraic
        } else if vuong_z < -DECISION_Z {
            TailLaw::Exponential
        } else {
            TailLaw::Undecided
        };
        Ok(AlgebraicTail {
            beta,
            beta_sem: beta / d.sqrt(),
            gamma,
            gamma_sem: gamma / d.sqrt(),
            t_min,
            t_max,
            in_tail: tail.len() as u64,
            escaped,
            vuong_z,
            law,
            window,
        })
    }
}

impl fmt::Display for AlgebraicTail {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "tail t > {} ({} escapes): {} (Vuong z = {:.1}); β = {}, γ = {}",
            crate::estimators::Significant(self.t_min, 4),
            self.escaped,
            self.law,
            self.vuong_z,
            crate::estimators::PlusMinus::new(self.beta, self.beta_sem),
            crate::estimators::PlusMinus::new(self.gamma, self.gamma_sem),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_test_support::normal::Normal;

    /// `n` balls with `P(t) = t^{−β}` for `t >= 1`, censored at `budget`.
    fn pareto(seed: u64, n: usize, beta: f64, budget: f64) -> (Vec<f64>, Vec<bool>) {
        let mut rng = Normal(seed);
        (0..n)
            .map(|_| {
                let x = rng.uniform().powf(-1.0 / beta);
                (x.min(budget), x > budget)
            })
            .unzip()
    }

    #[test]
    fn pareto_tails_are_algebraic_with_their_exponent() {
        // β ∈ {1, 2, 3}, 5000 balls, budget 1e3 (for β = 1, 0.1 % censored).
        // β̂ = D/Σln(t/t_min) is the exact censored MLE: within 3 SE.
        for (seed, beta) in [(1, 1.0), (2, 2.0), (3, 3.0)] {
            let (t, c) = pareto(seed, 5000, beta, 1e3);
            let tail = AlgebraicTail::fit(&t, &c, TailWindow::default()).unwrap();
            assert_eq!(tail.law, TailLaw::Algebraic, "{tail}");
            assert!((tail.beta - beta).abs() < 3.0 * tail.beta_sem, "{tail}");
            let whole = AlgebraicTail::fit(&t, &c, TailWindow::From { t_min: 1.0 }).unwrap();
            assert!((whole.beta - beta).abs() < 3.0 * whole.beta_sem, "{whole}");
        }
    }

    #[test]
    fn exponential_tails_say_exponential() {
        // Rates 0.3 and 2, 5000 balls, censored at a budget where P = e^{−6}.
        for (seed, gamma) in [(5, 0.3), (6, 2.0)] {
            let mut rng = Normal(seed);
            let budget = 6.0 / gamma;
            let (t, c): (Vec<f64>, Vec<bool>) = (0..5000)
                .map(|_| {
                    let x = -rng.uniform().ln() / gamma;
                    (x.min(budget), x > budget)
                })
                .unzip();
            let tail = AlgebraicTail::fit(&t, &c, TailWindow::default()).unwrap();
            assert_eq!(tail.law, TailLaw::Exponential, "{tail}");
            assert!((tail.gamma - gamma).abs() < 3.0 * tail.gamma_sem, "{tail}");
        }
    }

    #[test]
    fn exponential_then_algebraic() {
        // Stadium-like: 90 % chaotic balls (rate 1) and 10 % sticky ones
        // with a t^{−1} tail from t = 1; the tail past the chaotic decay
        // is algebraic.
        let mut rng = Normal(8);
        let (t, c): (Vec<f64>, Vec<bool>) = (0..20_000)
            .map(|_| {
                let x = if rng.uniform() < 0.9 {
                    -rng.uniform().ln()
                } else {
                    1.0 / rng.uniform()
                };
                (x.min(1e4), x > 1e4)
            })
            .unzip();
        let tail = AlgebraicTail::fit(&t, &c, TailWindow::From { t_min: 20.0 }).unwrap();
        assert_eq!(tail.law, TailLaw::Algebraic, "{tail}");
        assert!((tail.beta - 1.0).abs() < 3.0 * tail.beta_sem, "{tail}");
    }

    #[test]
    fn tails_that_cannot_work_are_refused() {
        let (t, c) = pareto(4, 100, 2.0, 1e3);
        assert!(matches!(
            AlgebraicTail::fit(&t, &c, TailWindow::Latest { share: 0.0 }),
            Err(EscapeError::InvalidOption { .. })
        ));
        assert!(matches!(
            AlgebraicTail::fit(&t, &c, TailWindow::From { t_min: 0.0 }),
            Err(EscapeError::InvalidOption { .. })
        ));
        assert!(matches!(
            AlgebraicTail::fit(&t, &c, TailWindow::From { t_min: 1e6 }),
            Err(EscapeError::TooFewEvents { .. })
        ));
    }
}
