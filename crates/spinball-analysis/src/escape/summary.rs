//! The summary of an escape run: every number the fronts print and save
//! (how many balls escaped, `P(t)` with its band, the escape rate, the
//! tail, the mean escape time against Kac), in time and in collisions,
//! computed once from the per-ball records so that the command line, the
//! Python package and the examples report the same thing.
//!
//! Documented in the group docs (`escape/mod.rs`) and `docs/TRANSPORT.md`.

use std::fmt;

use super::{
    AlgebraicTail, Clock, EscapeError, EscapeRate, KacPrediction, KacRatio, MeanEscape, RateWindow,
    Survival, TailWindow, Z95,
};
use crate::estimators::{Fitted, PlusMinus, Significant};
use crate::open::EscapeRecord;

/// The windows and band of an escape summary.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EscapeOptions {
    /// The escape-rate window in time ([`RateWindow::default`]: the later
    /// half of the escapes, while 20 balls remain).
    pub time_window: RateWindow,
    /// The escape-rate window in collisions.
    pub collision_window: RateWindow,
    /// The tail in time ([`TailWindow::default`]: the latest fifth of the
    /// escapes).
    pub time_tail: TailWindow,
    /// The tail in collisions.
    pub collision_tail: TailWindow,
    /// Half-width of the bands of `P`, in standard errors ([`Z95`]).
    pub z: f64,
}

impl Default for EscapeOptions {
    fn default() -> Self {
        EscapeOptions {
            time_window: RateWindow::default(),
            collision_window: RateWindow::default(),
            time_tail: TailWindow::default(),
            collision_tail: TailWindow::default(),
            z: Z95,
        }
    }
}

/// What one clock (time, or collisions) says about the escape.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct ClockSummary {
    /// `P(t)` (Kaplan–Meier) with Greenwood errors and its band.
    pub survival: Survival,
    /// The mean escape time (a lower bound when balls were censored).
    pub mean: MeanEscape,
    /// The mean against Kac's prediction, where the table has one.
    pub kac: Option<KacRatio>,
    /// The escape rate of the exponential regime, its error, window and
    /// drift check.
    pub rate: Fitted<EscapeRate>,
    /// The tail fitted by a power law and an exponential, and the decision.
    pub tail: Fitted<AlgebraicTail>,
}

/// The summary of an escape run: counts, and per clock `P(t)`, the mean
/// against Kac, the escape rate and the tail ([`ClockSummary`]).
///
/// Escape collision counts count the hole: a ball that escaped after `k`
/// collisions has `N = k + 1`; a censored one that survived `k` collisions
/// is censored at `N > k`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct EscapeSummary {
    /// Balls.
    pub n: u64,
    /// Balls that escaped.
    pub escaped: u64,
    /// Balls still inside at the budget.
    pub censored: u64,
    /// Kac's prediction (a table with holes and no periodic walls).
    pub kac: Option<KacPrediction>,
    /// The options.
    pub options: EscapeOptions,
    /// In flight time (refused if no ball escaped).
    pub time: Fitted<ClockSummary>,
    /// In collisions, the hole counted (refused if no ball escaped).
    pub collisions: Fitted<ClockSummary>,
}

impl EscapeSummary {
    /// The summary of `records` (one per ball, any order), with Kac's
    /// prediction `kac` if the table has one.
    ///
    /// # Errors
    /// [`EscapeError::Empty`] for no records, [`EscapeError::NotFinite`]
    /// for a time that is not a number `>= 0`, [`EscapeError::InvalidOption`]
    /// for a band half-width that is not finite and positive. Estimates
    /// that cannot be made (no escape, too few escapes in a window) are
    /// [`Fitted::Refused`] with the reason, not errors.
    pub fn new(
        records: &[EscapeRecord],
        kac: Option<KacPrediction>,
        options: EscapeOptions,
    ) -> Result<Self, EscapeError> {
        let times: Vec<f64> = records.iter().map(|r| r.time).collect();
        let counts: Vec<u64> = records
            .iter()
            .map(|r| r.collisions + u64::from(!r.censored))
            .collect();
        let censored: Vec<bool> = records.iter().map(|r| r.censored).collect();
        EscapeSummary::of_samples(&times, &counts, &censored, kac, options)
    }

    /// The same from plain data: escape times, escape collision counts
    /// (the hole counted) and censored flags, one per ball.
    ///
    /// # Errors
    /// As [`EscapeSummary::new`], and [`EscapeError::LengthMismatch`].
    pub fn of_samples(
        times: &[f64],
        counts: &[u64],
        censored: &[bool],
        kac: Option<KacPrediction>,
        options: EscapeOptions,
    ) -> Result<Self, EscapeError> {
        if counts.len() != times.len() {
            return Err(EscapeError::LengthMismatch {
                times: counts.len(),
                flags: times.len(),
            });
        }
        let time = clock_summary(
            Survival::kaplan_meier(times, censored),
            || EscapeRate::fit(times, censored, options.time_window),
            || AlgebraicTail::fit(times, censored, options.time_tail),
            kac,
            options.z,
        )?;
        let as_f64: Vec<f64> = counts.iter().map(|&n| n as f64).collect();
        let collisions = clock_summary(
            Survival::by_collisions(counts, censored),
            || EscapeRate::fit_collisions(counts, censored, options.collision_window),
            || AlgebraicTail::fit(&as_f64, censored, options.collision_tail),
            kac,
            options.z,
        )?;
        let escaped = censored.iter().filter(|c| !**c).count() as u64;
        Ok(EscapeSummary {
            n: times.len() as u64,
            escaped,
            censored: times.len() as u64 - escaped,
            kac,
            options,
            time,
            collisions,
        })
    }
}

/// One clock's summary from its survival curve; the fits are only tried
/// when there is a curve. Input errors other than "nobody escaped" are
/// returned.
fn clock_summary(
    survival: Result<Survival, EscapeError>,
    rate: impl FnOnce() -> Result<EscapeRate, EscapeError>,
    tail: impl FnOnce() -> Result<AlgebraicTail, EscapeError>,
    kac: Option<KacPrediction>,
    z: f64,
) -> Result<Fitted<ClockSummary>, EscapeError> {
    let survival = match survival {
        Ok(s) => s.with_z(z)?,
        Err(e @ EscapeError::AllCensored { .. }) => return Ok(Fitted::Refused(e.to_string())),
        Err(e) => return Err(e),
    };
    let mean = survival.mean_escape();
    Ok(Fitted::Fit(ClockSummary {
        kac: kac.map(|k| k.compare(mean)),
        mean,
        survival,
        rate: Fitted::from_result(rate()),
        tail: Fitted::from_result(tail()),
    }))
}

impl fmt::Display for ClockSummary {
    /// A few lines: the mean (and Kac), the rate, the tail.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let m = &self.mean;
        let bound = if m.complete { "" } else { ">= " };
        write!(f, "  mean     {bound}{}", PlusMinus::new(m.mean, m.sem))?;
        if let Some(median) = self.survival.median() {
            write!(f, ", median {}", Significant(median, 4))?;
        }
        if let Some(k) = &self.kac {
            write!(
                f,
                "; Kac {}, ratio {bound}{}",
                Significant(k.predicted, 5),
                PlusMinus::new(k.ratio, k.ratio_sem)
            )?;
        }
        writeln!(f)?;
        writeln!(f, "  rate     {}", self.rate)?;
        writeln!(f, "  tail     {}", self.tail)
    }
}

impl fmt::Display for EscapeSummary {
    /// The table a front prints: counts, then each clock.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{} balls: {} escaped, {} censored at the budget",
            self.n, self.escaped, self.censored
        )?;
        if let Some(k) = &self.kac {
            writeln!(f, "{k}")?;
        }
        for (clock, s) in [
            (Clock::Time, &self.time),
            (Clock::Collisions, &self.collisions),
        ] {
            let name = match clock {
                Clock::Time => "in time",
                Clock::Collisions => "in collisions (the hole counted)",
            };
            match s {
                Fitted::Fit(s) => write!(f, "{name}:\n{s}")?,
                Fitted::Refused(why) => writeln!(f, "{name}: no estimate ({why})")?,
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(index: u64, time: f64, collisions: u64, censored: bool) -> EscapeRecord {
        EscapeRecord {
            index,
            time,
            collisions,
            censored,
            exit: None,
        }
    }

    #[test]
    fn the_summary_is_the_blocks_applied_to_the_records() {
        // 200 balls with quantiles of a rate-0.5 law, those beyond t = 5
        // (200·e^{−2.5} ≈ 16) censored there; collisions ~ 2t.
        let n: u32 = 200;
        let records: Vec<EscapeRecord> = (0..n)
            .map(|i| {
                let t = -(1.0 - (f64::from(i) + 0.5) / f64::from(n)).ln() / 0.5;
                let c = t > 5.0;
                record(u64::from(i), t.min(5.0), (2.0 * t.min(5.0)) as u64, c)
            })
            .collect();
        let kac = KacPrediction::new(10.0, 5.0, 0.5, 0.0).unwrap();
        let s = EscapeSummary::new(&records, Some(kac), EscapeOptions::default()).unwrap();
        let times: Vec<f64> = records.iter().map(|r| r.time).collect();
        let cens: Vec<bool> = records.iter().map(|r| r.censored).collect();
        let counts: Vec<u64> = records
            .iter()
            .map(|r| r.collisions + u64::from(!r.censored))
            .collect();
        let t = s.time.fit().unwrap();
        assert_eq!(t.survival, Survival::kaplan_meier(&times, &cens).unwrap());
        assert_eq!(
            t.rate,
            Fitted::Fit(EscapeRate::fit(&times, &cens, RateWindow::default()).unwrap())
        );
        assert_eq!(
            t.tail,
            Fitted::Fit(AlgebraicTail::fit(&times, &cens, TailWindow::default()).unwrap())
        );
        assert_eq!(t.kac, Some(kac.compare(t.survival.mean_escape())));
        let c = s.collisions.fit().unwrap();
        assert_eq!(c.survival, Survival::by_collisions(&counts, &cens).unwrap());
        assert_eq!(
            c.rate,
            Fitted::Fit(EscapeRate::fit_collisions(&counts, &cens, RateWindow::default()).unwrap())
        );
        assert_eq!((s.n, s.escaped, s.censored), (200, 184, 16));
        assert!(s.to_string().contains("184 escaped"), "{s}");
    }

    #[test]
    fn what_cannot_be_fitted_is_refused_with_the_reason() {
        let all_in: Vec<EscapeRecord> = (0..5).map(|i| record(i, 3.0, 7, true)).collect();
        let s = EscapeSummary::new(&all_in, None, EscapeOptions::default()).unwrap();
        assert!(s.time.refused().unwrap().contains("none of the 5 balls"));
        assert!(s.collisions.refused().is_some());
        // Three escapes: a curve, but too few balls for the default window
        // (20 at risk at its end).
        let few: Vec<EscapeRecord> = (0..3)
            .map(|i| record(i, 1.0 + i as f64, 2, false))
            .collect();
        let s = EscapeSummary::new(&few, None, EscapeOptions::default()).unwrap();
        let t = s.time.fit().unwrap();
        let why = t.rate.refused().unwrap();
        assert!(why.contains("min_at_risk"), "{why}");
        assert_eq!(
            EscapeSummary::new(&[], None, EscapeOptions::default()),
            Err(EscapeError::Empty)
        );
    }
}
