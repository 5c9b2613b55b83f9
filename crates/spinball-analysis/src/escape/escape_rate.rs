//! The escape rate `γ` of the exponential regime `P(t) ≈ A e^{−γt}`: the
//! number a chaotic open table is summarised by, with its error and the
//! window it was measured on.
//!
//! Documented in the group docs (`escape/mod.rs`) and `docs/TRANSPORT.md`,
//! section "Escape rate".

use std::fmt;

use super::survival::{Clock, Survival};
use super::{EscapeError, Sample};

/// The fewest escapes a fit window (and each half of it, for the drift
/// check) must hold: below 10 the error `γ/√D` is
/// itself uncertain by more than 30 %.
pub const MIN_EVENTS: u64 = 10;

/// Which part of the sample a rate is fitted on.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum RateWindow {
    /// The default rule: skip the earliest `skip` share of the observed
    /// escapes (the transient: `t0` is the time of escape number
    /// `⌈skip·D⌉` of `D`), and stop at `t1`, the last time at which at
    /// least `min_at_risk` balls were still at risk.
    Rule {
        /// Share of the escapes counted as transient, in `[0, 1)`.
        skip: f64,
        /// Fewest balls at risk at the end of the window (`>= 1`).
        min_at_risk: u64,
    },
    /// An explicit window `[t0, t1]`.
    Range {
        /// Start.
        t0: f64,
        /// End.
        t1: f64,
    },
}

impl Default for RateWindow {
    /// `Rule { skip: 0.5, min_at_risk: 20 }`: fit the second half of the
    /// escapes, until fewer than 20 balls remain.
    fn default() -> Self {
        RateWindow::Rule {
            skip: 0.5,
            min_at_risk: 20,
        }
    }
}

/// An escape rate fitted on `[t0, t1]`: the maximum-likelihood rate of an
/// exponential law restricted to the window (escapes in the window over
/// the time the balls spent in it), so that censored balls count with the
/// time they were seen.
///
/// ```
/// use spinball_analysis::escape::{EscapeRate, RateWindow};
/// // Escape times of a rate-2 law (quantiles), none censored.
/// let n = 400;
/// let t: Vec<f64> = (0..n).map(|i| -(1.0 - (i as f64 + 0.5) / n as f64).ln() / 2.0).collect();
/// let fit = EscapeRate::fit(&t, &vec![false; n], RateWindow::default())?;
/// assert!((fit.gamma - 2.0).abs() < 3.0 * fit.sem);
/// # Ok::<(), spinball_analysis::escape::EscapeError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct EscapeRate {
    /// What the times count (`γ` per time unit or per collision).
    pub clock: Clock,
    /// The rate `γ`.
    pub gamma: f64,
    /// Its standard error (from the Fisher information).
    pub sem: f64,
    /// Window start.
    pub t0: f64,
    /// Window end.
    pub t1: f64,
    /// The amplitude `A = P(t0) e^{γ t0}` (Kaplan–Meier `P`).
    pub amplitude: f64,
    /// Escapes in `(t0, t1]`.
    pub escaped: u64,
    /// Time (or collisions) the balls spent in the window.
    pub exposure: f64,
    /// Balls still inside just after `t0`.
    pub at_risk_start: u64,
    /// Balls at risk at `t1`.
    pub at_risk_end: u64,
    /// The rate on the second half of the window minus that on the first
    /// half (halves holding equal numbers of escapes), in standard errors.
    /// Beyond ±3 the rate is not constant on the window: the transient is
    /// not over, or the tail is not exponential. `None` when a half holds
    /// fewer than [`MIN_EVENTS`] escapes (fewer than 20 in the window).
    pub drift: Option<f64>,
    /// The window asked for.
    pub window: RateWindow,
}

impl EscapeRate {
    /// Fit `γ` per unit time from escape times (`censored[i]` true for a
    /// ball still inside at `times[i]`).
    ///
    /// # Errors
    /// As [`Survival::kaplan_meier`], [`EscapeError::InvalidOption`] for a
    /// window out of range and [`EscapeError::TooFewEvents`] for fewer than
    /// [`MIN_EVENTS`] escapes in it.
    pub fn fit(times: &[f64], censored: &[bool], window: RateWindow) -> Result<Self, EscapeError> {
        EscapeRate::fit_sample(&Sample::new(times, censored)?, Clock::Time, window)
    }

    /// Fit `γ` per collision from collision counts: the escape probability
    /// per collision `p` by the geometric law's maximum likelihood
    /// (escapes over collisions at risk), reported as `γ = −ln(1 − p)` so
    /// that `P(n) ≈ A e^{−γn}` as in continuous time.
    ///
    /// # Errors
    /// As [`EscapeRate::fit`]; [`EscapeError::InvalidOption`] if every ball
    /// in the window escaped at its first collision there (`p = 1`).
    pub fn fit_collisions(
        counts: &[u64],
        censored: &[bool],
        window: RateWindow,
    ) -> Result<Self, EscapeError> {
        EscapeRate::fit_sample(
            &Sample::from_collisions(counts, censored)?,
            Clock::Collisions,
            window,
        )
    }

    fn fit_sample(sample: &Sample, clock: Clock, window: RateWindow) -> Result<Self, EscapeError> {
        let (t0, t1) = resolve_window(sample, window)?;
        let whole = window_rate(sample, clock, t0, t1)?;
        // Split at the middle escape of the window for the drift check.
        let events: Vec<f64> = sample
            .obs
            .iter()
            .filter(|o| !o.censored && o.t > t0 && o.t <= t1)
            .map(|o| o.t)
            .collect();
        let tm = events[events.len() / 2 - 1];
        let drift = match (
            window_rate(sample, clock, t0, tm),
            window_rate(sample, clock, tm, t1),
        ) {
            (Ok(a), Ok(b)) => Some((b.gamma - a.gamma) / a.sem.hypot(b.sem)),
            _ => None,
        };
        let p0 = Survival::from_sample(sample, clock).at(t0);
        Ok(EscapeRate {
            clock,
            gamma: whole.gamma,
            sem: whole.sem,
            t0,
            t1,
            amplitude: p0 * (whole.gamma * t0).exp(),
            escaped: whole.escaped,
            exposure: whole.exposure,
            at_risk_start: sample.beyond(t0) as u64,
            at_risk_end: sample.at_risk(t1) as u64,
            drift,
            window,
        })
    }

    /// The mean lifetime `1/γ` of the exponential regime.
    #[must_use]
    pub fn lifetime(&self) -> f64 {
        1.0 / self.gamma
    }
}

impl fmt::Display for EscapeRate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "γ = {} per {} on [{}, {}] ({} escapes, drift {})",
            crate::estimators::PlusMinus::new(self.gamma, self.sem),
            match self.clock {
                Clock::Time => "unit time",
                Clock::Collisions => "collision",
            },
            crate::estimators::Significant(self.t0, 4),
            crate::estimators::Significant(self.t1, 4),
            self.escaped,
            self.drift
                .map_or_else(|| "not measured".to_string(), |z| format!("{z:.1} SE"))
        )
    }
}

/// The window `[t0, t1]` a rule or range gives on `sample`.
fn resolve_window(sample: &Sample, window: RateWindow) -> Result<(f64, f64), EscapeError> {
    let (t0, t1) = match window {
        RateWindow::Rule { skip, min_at_risk } => {
            if !((0.0..1.0).contains(&skip)) {
                return Err(EscapeError::invalid(
                    "skip",
                    format!("{skip}: the transient share of escapes must be in [0, 1)"),
                ));
            }
            if min_at_risk == 0 || min_at_risk as usize > sample.len() {
                return Err(EscapeError::invalid(
                    "min_at_risk",
                    format!(
                        "{min_at_risk}: must be in 1..={} (the number of balls)",
                        sample.len()
                    ),
                ));
            }
            let k = (skip * sample.escaped as f64).ceil() as usize;
            let t0 = if k == 0 {
                0.0
            } else {
                sample.escape_time(k - 1).unwrap_or(0.0)
            };
            let t1 = sample.obs[sample.len() - min_at_risk as usize].t;
            (t0, t1)
        }
        RateWindow::Range { t0, t1 } => {
            if !(t0.is_finite() && t1.is_finite() && 0.0 <= t0 && t0 < t1) {
                return Err(EscapeError::invalid(
                    "window",
                    format!("[{t0}, {t1}]: need finite 0 <= t0 < t1"),
                ));
            }
            (t0, t1)
        }
    };
    if t0 >= t1 {
        return Err(EscapeError::TooFewEvents {
            events: 0,
            min: MIN_EVENTS,
            t0,
            t1,
        });
    }
    Ok((t0, t1))
}

/// The bare rate on `(t0, t1]`.
struct WindowRate {
    gamma: f64,
    sem: f64,
    escaped: u64,
    exposure: f64,
}

fn window_rate(sample: &Sample, clock: Clock, t0: f64, t1: f64) -> Result<WindowRate, EscapeError> {
    let (mut escaped, mut exposure) = (0u64, 0.0);
    for o in sample.obs.iter().filter(|o| o.t > t0) {
        exposure += o.t.min(t1) - t0;
        if !o.censored && o.t <= t1 {
            escaped += 1;
        }
    }
    if escaped < MIN_EVENTS {
        return Err(EscapeError::TooFewEvents {
            events: escaped,
            min: MIN_EVENTS,
            t0,
            t1,
        });
    }
    let d = escaped as f64;
    let (gamma, sem) = match clock {
        Clock::Time => {
            let gamma = d / exposure;
            (gamma, gamma / d.sqrt())
        }
        Clock::Collisions => {
            // A ball escaping at collision n > n0 was at risk at collisions
            // n0+1..=n: exposure n − n0 trials, as in continuous time.
            let p = d / exposure;
            if p >= 1.0 {
                return Err(EscapeError::invalid(
                    "window",
                    format!(
                        "every ball in ({t0}, {t1}] escaped at its first collision there: the rate per collision is infinite"
                    ),
                ));
            }
            (-(-p).ln_1p(), (p / (exposure * (1.0 - p))).sqrt())
        }
    };
    Ok(WindowRate {
        gamma,
        sem,
        escaped,
        exposure,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_test_support::normal::Normal;

    /// `n` balls from a mixture of rates (`(weight, rate)`), censored at
    /// `budget`.
    fn sample(seed: u64, n: usize, parts: &[(f64, f64)], budget: f64) -> (Vec<f64>, Vec<bool>) {
        let mut rng = Normal(seed);
        let (mut t, mut c) = (Vec::new(), Vec::new());
        for _ in 0..n {
            let pick = rng.uniform();
            let mut acc = 0.0;
            let mut rate = parts[parts.len() - 1].1;
            for &(w, r) in parts {
                acc += w;
                if pick < acc {
                    rate = r;
                    break;
                }
            }
            let x = -rng.uniform().ln() / rate;
            t.push(x.min(budget));
            c.push(x > budget);
        }
        (t, c)
    }

    #[test]
    fn recovers_the_rate_of_censored_exponentials() {
        // γ = 0.7, 3000 balls, budget 2.5 (P = 0.17 censored); five seeds.
        // The MLE is unbiased to O(1/D); within 3 SE for each seed.
        for seed in 1..=5 {
            let (t, c) = sample(seed, 3000, &[(1.0, 0.7)], 2.5);
            for window in [
                RateWindow::default(),
                RateWindow::Range { t0: 0.0, t1: 2.5 },
            ] {
                let fit = EscapeRate::fit(&t, &c, window).unwrap();
                assert!(
                    (fit.gamma - 0.7).abs() < 3.0 * fit.sem,
                    "seed {seed}: {fit}"
                );
                assert!(fit.drift.unwrap().abs() < 3.0, "seed {seed}: {fit}");
                assert!((fit.amplitude - 1.0).abs() < 0.1, "{fit:?}");
            }
        }
    }

    #[test]
    fn default_window_is_the_stated_rule() {
        let (t, c) = sample(9, 1000, &[(1.0, 1.0)], 3.0);
        let fit = EscapeRate::fit(&t, &c, RateWindow::default()).unwrap();
        let s = Sample::new(&t, &c).unwrap();
        // t0: escape number ⌈D/2⌉; t1: the 20th-largest observed time,
        // which is the budget (more than 20 balls are censored there).
        assert_eq!(fit.t0, s.escape_time(s.escaped.div_ceil(2) - 1).unwrap());
        assert_eq!(fit.t1, 3.0);
        assert!(fit.at_risk_end >= 20);
    }

    #[test]
    fn the_window_matters_for_a_mixture() {
        // 30 % fast (rate 20) and 70 % slow (rate 0.5) balls, budget 6.
        // From t = 0 the fast ones inflate the rate; the default window
        // skips them (by its t0 ≈ 0.5 they are e^{−10} of the sample) and
        // finds the slow rate. Five seeds.
        for seed in 11..=15 {
            let (t, c) = sample(seed, 4000, &[(0.3, 20.0), (0.7, 0.5)], 6.0);
            let late = EscapeRate::fit(&t, &c, RateWindow::default()).unwrap();
            assert!(
                (late.gamma - 0.5).abs() < 3.0 * late.sem,
                "seed {seed}: {late}"
            );
            assert!(late.drift.unwrap().abs() < 3.0, "{late}");
            assert!((late.amplitude - 0.7).abs() < 0.05, "{late:?}");
            let all = EscapeRate::fit(&t, &c, RateWindow::Range { t0: 0.0, t1: 6.0 }).unwrap();
            assert!(all.gamma > 0.5 + 10.0 * all.sem, "seed {seed}: {all}");
            // The drift check sees the transient in the full window.
            assert!(all.drift.unwrap() < -3.0, "{all}");
        }
    }

    #[test]
    fn per_collision_rate_is_geometric() {
        // Escape probability p = 0.05 per collision: γ = −ln(0.95) = 0.05129.
        let p = 0.05_f64;
        let mut rng = Normal(4);
        let (mut n, mut c) = (Vec::new(), Vec::new());
        for _ in 0..3000 {
            let k = (rng.uniform().ln() / (1.0 - p).ln()).ceil().max(1.0) as u64;
            n.push(k.min(60));
            c.push(k > 60);
        }
        let fit = EscapeRate::fit_collisions(&n, &c, RateWindow::default()).unwrap();
        let gamma = -(1.0 - p).ln();
        assert!((fit.gamma - gamma).abs() < 3.0 * fit.sem, "{fit}");
        assert_eq!(fit.clock, Clock::Collisions);
    }

    #[test]
    fn drift_needs_enough_escapes_in_each_half() {
        // 15 escapes: enough for γ (10), not for two halves of 10.
        let t: Vec<f64> = (1..=15).map(f64::from).collect();
        let fit =
            EscapeRate::fit(&t, &[false; 15], RateWindow::Range { t0: 0.0, t1: 100.0 }).unwrap();
        assert_eq!((fit.escaped, fit.drift), (15, None));
        // γ = 15 escapes / Σt = 120 time units.
        assert!((fit.gamma - 15.0 / 120.0).abs() < 1e-15);
    }

    #[test]
    fn windows_that_cannot_work_are_refused() {
        let (t, c) = sample(3, 200, &[(1.0, 1.0)], 5.0);
        assert!(matches!(
            EscapeRate::fit(&t, &c, RateWindow::Range { t0: 2.0, t1: 1.0 }),
            Err(EscapeError::InvalidOption { .. })
        ));
        assert!(matches!(
            EscapeRate::fit(&t, &c, RateWindow::Range { t0: 4.0, t1: 4.001 }),
            Err(EscapeError::TooFewEvents { .. })
        ));
        assert!(matches!(
            EscapeRate::fit(
                &t,
                &c,
                RateWindow::Rule {
                    skip: 1.0,
                    min_at_risk: 5
                }
            ),
            Err(EscapeError::InvalidOption { .. })
        ));
        assert!(matches!(
            EscapeRate::fit(
                &t,
                &c,
                RateWindow::Rule {
                    skip: 0.5,
                    min_at_risk: 0
                }
            ),
            Err(EscapeError::InvalidOption { .. })
        ));
        assert!(matches!(
            EscapeRate::fit(&t[..5], &c[..5], RateWindow::default()),
            Err(EscapeError::InvalidOption { .. })
        ));
        assert!(matches!(
            EscapeRate::fit(&[1.0, 2.0], &[true, true], RateWindow::default()),
            Err(EscapeError::AllCensored { .. })
        ));
    }
}
