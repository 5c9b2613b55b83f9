//! The survival probability `P(t)` of an open table: the share of balls
//! still inside at `t`, estimated from escape times that may be censored
//! (Kaplan–Meier), with pointwise confidence bands, and the mean escape
//! time it implies.
//!
//! Documented in the group docs (`escape/mod.rs`) and `docs/TRANSPORT.md`,
//! section "Survival".

use std::fmt;

use super::{EscapeError, Sample};

/// The two-sided 95 % point of the standard normal distribution, the
/// default half-width (in standard errors) of every band.
pub const Z95: f64 = 1.959_963_984_540_054;

/// What the times of a sample count.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Clock {
    /// Flight time (continuous).
    Time,
    /// Collisions (discrete: the escape counts as the `n`-th collision).
    Collisions,
}

/// `P(t)` just after one escape time.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SurvivalPoint {
    /// The escape time (or collision count).
    pub t: f64,
    /// Balls at risk at `t` (observed time `>= t`).
    pub at_risk: u64,
    /// Balls that escaped at exactly `t`.
    pub escaped: u64,
    /// Balls censored at exactly `t` (counted at risk at `t`).
    pub censored: u64,
    /// Kaplan–Meier `P(t)`, the probability of being inside after `t`.
    pub survival: f64,
    /// Greenwood's standard error of `P(t)`.
    pub std_error: f64,
    /// Lower end of the log–log band.
    pub lower: f64,
    /// Upper end of the log–log band.
    pub upper: f64,
}

/// The Kaplan–Meier survival curve of an escape sample: a step function,
/// `P = 1` before the first escape, one [`SurvivalPoint`] per distinct
/// escape time, known up to [`Survival::last_time`].
///
/// **Band.** Pointwise, at `±z` standard errors (default [`Z95`]), on the
/// log–log scale (Kalbfleisch–Prentice): with `V = Σ d/(n(n−d))` (the
/// Greenwood variance of `ln P`), `P^{exp(±z√V / ln P)}`, which stays
/// inside `[0, 1]`. Where `P = 0` (every ball at risk escaped) the band is
/// `[0, 0]`.
///
/// ```
/// use spinball_analysis::escape::Survival;
/// // Five balls: escapes at 1, 2, 4; one censored at 3, one at 5.
/// let p = Survival::kaplan_meier(&[1.0, 2.0, 3.0, 4.0, 5.0], &[false, false, true, false, true])?;
/// assert_eq!(p.at(0.5), 1.0);
/// assert!((p.at(2.5) - 0.6).abs() < 1e-12); // 4/5 · 3/4
/// assert!((p.at(4.0) - 0.3).abs() < 1e-12); // · 1/2
/// # Ok::<(), spinball_analysis::escape::EscapeError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Survival {
    clock: Clock,
    z: f64,
    n: u64,
    escaped: u64,
    last_time: f64,
    points: Vec<SurvivalPoint>,
}

impl Survival {
    /// `P(t)` from escape times `times` (flight time), `censored[i]` true
    /// for a ball still inside at `times[i]`; band at [`Z95`].
    ///
    /// # Errors
    /// [`EscapeError::Empty`], [`EscapeError::LengthMismatch`],
    /// [`EscapeError::NotFinite`] (NaN, infinite or negative time) and
    /// [`EscapeError::AllCensored`] (no escape: nothing to estimate).
    pub fn kaplan_meier(times: &[f64], censored: &[bool]) -> Result<Self, EscapeError> {
        Ok(Survival::from_sample(
            &Sample::new(times, censored)?,
            Clock::Time,
        ))
    }

    /// `P(n)` by collision count, the same estimator in discrete time:
    /// `counts[i]` is the collision through the hole, or the collisions
    /// survived when `censored[i]`.
    ///
    /// # Errors
    /// As [`Survival::kaplan_meier`].
    pub fn by_collisions(counts: &[u64], censored: &[bool]) -> Result<Self, EscapeError> {
        Ok(Survival::from_sample(
            &Sample::from_collisions(counts, censored)?,
            Clock::Collisions,
        ))
    }

    pub(crate) fn from_sample(sample: &Sample, clock: Clock) -> Self {
        let n = sample.len();
        let mut points = Vec::new();
        let (mut s, mut greenwood) = (1.0_f64, 0.0_f64);
        let mut i = 0;
        while i < n {
            let t = sample.obs[i].t;
            let at_risk = n - i;
            let mut j = i;
            while j < n && sample.obs[j].t == t {
                j += 1;
            }
            let escaped = sample.obs[i..j].iter().filter(|o| !o.censored).count();
            if escaped > 0 {
                let (nr, d) = (at_risk as f64, escaped as f64);
                s *= (nr - d) / nr;
                if escaped < at_risk {
                    greenwood += d / (nr * (nr - d));
                }
                points.push(SurvivalPoint {
                    t,
                    at_risk: at_risk as u64,
                    escaped: escaped as u64,
                    censored: (j - i - escaped) as u64,
                    survival: s,
                    std_error: s * greenwood.sqrt(),
                    lower: 0.0,
                    upper: 0.0,
                });
            }
            i = j;
        }
        let mut out = Survival {
            clock,
            z: Z95,
            n: n as u64,
            escaped: sample.escaped as u64,
            last_time: sample.obs[n - 1].t,
            points,
        };
        out.set_bands();
        out
    }

    /// The same curve with bands at `±z` standard errors.
    ///
    /// # Errors
    /// [`EscapeError::InvalidOption`] unless `z` is finite and positive.
    pub fn with_z(mut self, z: f64) -> Result<Self, EscapeError> {
        if !(z.is_finite() && z > 0.0) {
            return Err(EscapeError::invalid(
                "z",
                format!(
                    "{z}: the band half-width must be a finite number of standard errors > 0 (1.96 for 95 %)"
                ),
            ));
        }
        self.z = z;
        self.set_bands();
        Ok(self)
    }

    fn set_bands(&mut self) {
        let z = self.z;
        for p in &mut self.points {
            (p.lower, p.upper) = log_log_band(p.survival, p.std_error, z);
        }
    }

    /// `P(t)`: 1 before the first escape, the step value after. Beyond
    /// [`Survival::last_time`] the curve is not known; this returns its
    /// last value there.
    #[must_use]
    pub fn at(&self, t: f64) -> f64 {
        self.point_at(t).map_or(1.0, |p| p.survival)
    }

    /// The step in force at `t` (the last escape time `<= t`), `None`
    /// before the first escape.
    #[must_use]
    pub fn point_at(&self, t: f64) -> Option<&SurvivalPoint> {
        let k = self.points.partition_point(|p| p.t <= t);
        k.checked_sub(1).map(|k| &self.points[k])
    }

    /// One point per distinct escape time, in time order.
    #[must_use]
    pub fn points(&self) -> &[SurvivalPoint] {
        &self.points
    }

    /// What the times count.
    #[must_use]
    pub fn clock(&self) -> Clock {
        self.clock
    }

    /// Half-width of the bands in standard errors.
    #[must_use]
    pub fn z(&self) -> f64 {
        self.z
    }

    /// Balls in the sample.
    #[must_use]
    pub fn n(&self) -> u64 {
        self.n
    }

    /// Balls that escaped.
    #[must_use]
    pub fn escaped(&self) -> u64 {
        self.escaped
    }

    /// Balls censored.
    #[must_use]
    pub fn censored(&self) -> u64 {
        self.n - self.escaped
    }

    /// The largest observed time: the curve is known up to here.
    #[must_use]
    pub fn last_time(&self) -> f64 {
        self.last_time
    }

    /// The median escape time: the first escape time with `P <= ½`;
    /// `None` if `P` stays above ½ over the observed range.
    #[must_use]
    pub fn median(&self) -> Option<f64> {
        self.points.iter().find(|p| p.survival <= 0.5).map(|p| p.t)
    }

    /// The mean escape time: the area under `P` up to
    /// [`Survival::last_time`] (the restricted mean) with its standard
    /// error. With no ball censored this is the sample mean; otherwise it
    /// is a lower bound of the mean and says so
    /// ([`MeanEscape::complete`] false).
    pub fn mean_escape(&self) -> MeanEscape {
        // Area under the step function from 0 to the last time, and, for
        // the variance, the area A_k after each escape time t_k:
        // Var = Σ A_k² d_k / (n_k (n_k − d_k)).
        let tau = self.last_time;
        let mut area_after = vec![0.0; self.points.len()];
        let mut acc = 0.0;
        for k in (0..self.points.len()).rev() {
            let next = self.points.get(k + 1).map_or(tau, |p| p.t);
            acc += self.points[k].survival * (next - self.points[k].t);
            area_after[k] = acc;
        }
        let first = self.points.first().map_or(tau, |p| p.t);
        let mean = first + acc;
        let mut var = 0.0;
        for (p, a) in self.points.iter().zip(&area_after) {
            let (nr, d) = (p.at_risk as f64, p.escaped as f64);
            if nr > d {
                var += a * a * d / (nr * (nr - d));
            }
        }
        MeanEscape {
            clock: self.clock,
            mean,
            sem: var.sqrt(),
            n: self.n,
            censored: self.censored(),
            horizon: tau,
            complete: self.censored() == 0,
        }
    }
}

/// The log–log band of `s` with standard error `se` at `±z`.
fn log_log_band(s: f64, se: f64, z: f64) -> (f64, f64) {
    if s <= 0.0 {
        return (0.0, 0.0);
    }
    if s >= 1.0 || se == 0.0 {
        return (s, s);
    }
    // se of ln(−ln P) by the delta method: (se/P) / |ln P|.
    let w = z * (se / s) / s.ln().abs();
    (s.powf(w.exp()), s.powf((-w).exp()))
}

impl fmt::Display for Survival {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "P(t) of {} balls ({} escaped, {} censored), known to {} {}",
            self.n,
            self.escaped,
            self.censored(),
            self.last_time,
            match self.clock {
                Clock::Time => "time units",
                Clock::Collisions => "collisions",
            }
        )
    }
}

/// The mean escape time of a sample, with its standard error.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct MeanEscape {
    /// What the times count.
    pub clock: Clock,
    /// The mean (restricted to `[0, horizon]`).
    pub mean: f64,
    /// Its standard error.
    pub sem: f64,
    /// Balls.
    pub n: u64,
    /// Balls censored.
    pub censored: u64,
    /// The largest observed time, the end of the integral.
    pub horizon: f64,
    /// No ball censored: the mean is the full mean, not a lower bound.
    pub complete: bool,
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_test_support::normal::Normal;

    /// The 6-MP arm of the Gehan (1965) leukaemia trial, the classic
    /// Kaplan–Meier example: 21 times, `+` censored:
    /// 6 6 6 6+ 7 9+ 10 10+ 11+ 13 16 17+ 19+ 20+ 22 23 25+ 32+ 32+ 34+ 35+.
    fn gehan() -> (Vec<f64>, Vec<bool>) {
        let data = [
            (6.0, false),
            (6.0, false),
            (6.0, false),
            (6.0, true),
            (7.0, false),
            (9.0, true),
            (10.0, false),
            (10.0, true),
            (11.0, true),
            (13.0, false),
            (16.0, false),
            (17.0, true),
            (19.0, true),
            (20.0, true),
            (22.0, false),
            (23.0, false),
            (25.0, true),
            (32.0, true),
            (32.0, true),
            (34.0, true),
            (35.0, true),
        ];
        // Shuffled order must not matter: reverse it.
        data.iter().rev().map(|&(t, c)| (t, c)).unzip()
    }

    #[test]
    fn gehan_by_hand() {
        // By hand (n at risk, d escapes, P = Π (n−d)/n, V = Σ d/(n(n−d))):
        // t=6:  n=21 d=3  P = 18/21          = 0.857143  V = 3/378  = 0.0079365
        // t=7:  n=17 d=1  P = 0.857143·16/17 = 0.806723  V += 1/272 → 0.0116130
        // t=10: n=15 d=1  P = ·14/15         = 0.752941  V += 1/210 → 0.0163749
        // t=13: n=12 d=1  P = ·11/12         = 0.690196  V += 1/132 → 0.0239507
        // t=16: n=11 d=1  P = ·10/11         = 0.627451  V += 1/110 → 0.0330416
        // t=22: n=7  d=1  P = ·6/7           = 0.537815  V += 1/42  → 0.0568511
        // t=23: n=6  d=1  P = ·5/6           = 0.448179  V += 1/30  → 0.0901845
        // Greenwood SE = P√V: 0.076360 at 6, 0.448179·0.300307 = 0.134591 at 23.
        // Log–log band at 6 (z = 1.96): w = 1.96·√V/|ln P| = 1.96·0.089087/0.154151
        // = 1.132726, lower = P^{e^w} = 0.857143^{3.104129} = 0.619718,
        // upper = P^{e^{−w}} = 0.857143^{0.322152} = 0.951552.
        let (t, c) = gehan();
        let p = Survival::kaplan_meier(&t, &c).unwrap();
        let expect = [
            (6.0, 21, 3, 0.857_143),
            (7.0, 17, 1, 0.806_723),
            (10.0, 15, 1, 0.752_941),
            (13.0, 12, 1, 0.690_196),
            (16.0, 11, 1, 0.627_451),
            (22.0, 7, 1, 0.537_815),
            (23.0, 6, 1, 0.448_179),
        ];
        assert_eq!(p.points().len(), expect.len());
        for (pt, &(tt, n, d, s)) in p.points().iter().zip(&expect) {
            assert_eq!((pt.t, pt.at_risk, pt.escaped), (tt, n, d));
            assert!((pt.survival - s).abs() < 1e-6, "{pt:?}");
        }
        let first = p.points()[0];
        assert!((first.std_error - 0.076_360).abs() < 1e-6);
        assert!((first.lower - 0.619_718).abs() < 2e-6, "{first:?}");
        assert!((first.upper - 0.951_552).abs() < 2e-6, "{first:?}");
        assert!((p.points()[6].std_error - 0.134_591).abs() < 1e-6);
        assert_eq!((p.n(), p.escaped(), p.censored()), (21, 9, 12));
        assert_eq!(p.median(), Some(23.0));
        assert_eq!(p.at(5.9), 1.0);
        assert_eq!(p.at(9.0), p.points()[1].survival);
        assert_eq!(p.last_time(), 35.0);
        // Restricted mean by hand: 6 + 0.857143·1 + 0.806723·3 + 0.752941·3
        // + 0.690196·3 + 0.627451·6 + 0.537815·1 + 0.448179·12 = 23.287 (lower bound).
        let m = p.mean_escape();
        assert!((m.mean - 23.287_395).abs() < 1e-5, "{m:?}");
        assert!(!m.complete && m.sem > 0.0);
    }

    #[test]
    fn collisions_are_the_same_estimator() {
        let counts = [3u64, 1, 4, 1, 5, 9, 2, 6];
        let flags = [false, false, true, false, false, true, false, false];
        let by_n = Survival::by_collisions(&counts, &flags).unwrap();
        let times: Vec<f64> = counts.iter().map(|&n| n as f64).collect();
        let by_t = Survival::kaplan_meier(&times, &flags).unwrap();
        assert_eq!(by_n.points(), by_t.points());
        assert_eq!(by_n.clock(), Clock::Collisions);
        // Uncensored prefix: P(1) = 6/8 (two escapes at 1).
        assert_eq!(by_n.at(1.0), 0.75);
    }

    #[test]
    fn complete_sample_mean_is_the_sample_mean() {
        let t = [0.5, 1.5, 2.0, 4.0];
        let m = Survival::kaplan_meier(&t, &[false; 4])
            .unwrap()
            .mean_escape();
        assert!((m.mean - 2.0).abs() < 1e-12 && m.complete);
        // The KM variance of a complete sample is Σ(t−t̄)²/n².
        let var = t.iter().map(|x| (x - 2.0) * (x - 2.0)).sum::<f64>() / 16.0;
        assert!((m.sem - var.sqrt()).abs() < 1e-12, "{m:?}");
    }

    #[test]
    fn exponential_sample_with_known_rate() {
        // 4000 balls, rate γ = 0.5, censored at a budget t = 3 (P = e^{−1.5}
        // = 0.22 still inside). P(t) must match e^{−γt} within 4 Greenwood
        // SE at every escape time, and the 95 % band must cover the truth
        // at the checkpoints below (the bands are pointwise).
        let (gamma, budget) = (0.5, 3.0);
        let mut rng = Normal(17);
        let (mut t, mut c) = (Vec::new(), Vec::new());
        for _ in 0..4000 {
            let x = -rng.uniform().ln() / gamma;
            t.push(x.min(budget));
            c.push(x > budget);
        }
        let p = Survival::kaplan_meier(&t, &c).unwrap();
        for pt in p.points() {
            let truth = (-gamma * pt.t).exp();
            assert!(
                (pt.survival - truth).abs() < 4.0 * pt.std_error.max(1e-3),
                "{pt:?} vs {truth}"
            );
            assert!(pt.lower <= pt.survival && pt.survival <= pt.upper);
            assert!(pt.lower >= 0.0 && pt.upper <= 1.0);
        }
        for x in [0.5, 1.0, 2.0, 2.9] {
            let pt = p.point_at(x).unwrap();
            let truth = (-gamma * x).exp();
            assert!(
                pt.lower - 2e-3 < truth && truth < pt.upper + 2e-3,
                "{pt:?} {truth}"
            );
        }
        assert_eq!(p.censored(), c.iter().filter(|&&x| x).count() as u64);
    }

    #[test]
    fn bad_samples_are_refused() {
        assert_eq!(Survival::kaplan_meier(&[], &[]), Err(EscapeError::Empty));
        assert!(matches!(
            Survival::kaplan_meier(&[1.0], &[false, true]),
            Err(EscapeError::LengthMismatch { .. })
        ));
        assert!(matches!(
            Survival::kaplan_meier(&[1.0, f64::NAN], &[false, false]),
            Err(EscapeError::NotFinite { index: 1, .. })
        ));
        assert!(matches!(
            Survival::kaplan_meier(&[1.0, -1.0], &[false, false]),
            Err(EscapeError::NotFinite { index: 1, .. })
        ));
        assert!(matches!(
            Survival::kaplan_meier(&[5.0, 5.0], &[true, true]),
            Err(EscapeError::AllCensored { n: 2, .. })
        ));
        let p = Survival::kaplan_meier(&[1.0], &[false]).unwrap();
        assert!(p.clone().with_z(f64::NAN).is_err());
        assert!(p.with_z(0.0).is_err());
    }

    #[test]
    fn everyone_escaping_ends_at_zero() {
        let p = Survival::kaplan_meier(&[1.0, 2.0], &[false, false]).unwrap();
        let last = p.points()[1];
        assert_eq!((last.survival, last.lower, last.upper), (0.0, 0.0, 0.0));
    }
}
