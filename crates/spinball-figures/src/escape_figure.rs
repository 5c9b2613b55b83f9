//! Figures of escape from an open table ([`EscapeFit`]): the survival
//! curve with its band, the fitted exponential regime on its window and
//! the algebraic tail where the tail test finds one; the escape rate
//! against α with the points whose escape is not exponential marked as
//! such; and the CSV rows of both.

use spinball_analysis::escape::{
    AlgebraicTail, EscapeError, EscapeLaw, EscapeRate, KacPrediction, KacRatio, RateWindow,
    Survival, TailLaw, TailWindow,
};
use spinball_analysis::estimators::PlusMinus;
use spinball_analysis::precision::Measurement;
use spinball_plot::{Legend, LineKind, LinePlot, RGBColor, Series, palette};

use crate::csv::{Csv, optional};
use crate::measured::{ALPHA_LABEL, measured};

/// One escape sample analysed with the default windows: the survival
/// curve, the rate of the exponential regime and the tail (each `None`
/// where the sample holds too few escapes for it), the verdict on the
/// rate, and the mean escape time against Kac's prediction.
#[derive(Debug, Clone)]
pub struct EscapeFit {
    /// The spin parameter.
    pub alpha: f64,
    /// Kaplan–Meier `P(t)` with its 95 % band.
    pub survival: Survival,
    /// The rate on [`RateWindow::default`].
    pub rate: Option<EscapeRate>,
    /// The tail on [`TailWindow::default`].
    pub tail: Option<AlgebraicTail>,
    /// What the drift check and the tail test say (`None` without a rate).
    pub law: Option<EscapeLaw>,
    /// The mean escape time (a lower bound with censored balls) over Kac's.
    pub kac: KacRatio,
}

impl EscapeFit {
    /// Analyse the escape `times` (`censored[i]` for a ball still inside
    /// at `times[i]`) of a table whose Kac prediction is `kac`.
    ///
    /// # Errors
    /// As [`Survival::kaplan_meier`] (empty sample, no escape, ...). Too
    /// few escapes for the rate or the tail leave them `None`.
    pub fn new(
        alpha: f64,
        times: &[f64],
        censored: &[bool],
        kac: &KacPrediction,
    ) -> Result<Self, EscapeError> {
        let survival = Survival::kaplan_meier(times, censored)?;
        let rate = EscapeRate::fit(times, censored, RateWindow::default()).ok();
        let tail = AlgebraicTail::fit(times, censored, TailWindow::default()).ok();
        let law = rate.map(|r| EscapeLaw::judge(&r, tail.as_ref()));
        let kac = kac.compare(survival.mean_escape());
        Ok(EscapeFit {
            alpha,
            survival,
            rate,
            tail,
            law,
            kac,
        })
    }

    /// Whether the tail test called the tail algebraic.
    #[must_use]
    pub fn algebraic(&self) -> Option<&AlgebraicTail> {
        self.tail.as_ref().filter(|t| t.law == TailLaw::Algebraic)
    }
}

/// At most this many points of a survival curve are drawn (evenly by
/// index; the curve has one point per distinct escape time).
const CURVE_POINTS: usize = 600;

/// `n` points from `a` to `b`, evenly in `ln t` when `log` (and `a > 0`).
fn span(a: f64, b: f64, n: usize, log: bool) -> Vec<f64> {
    (0..n)
        .map(|k| {
            let s = k as f64 / (n - 1) as f64;
            if log && a > 0.0 {
                a * (b / a).powf(s)
            } else {
                a + s * (b - a)
            }
        })
        .collect()
}

/// The survival curve of `fit` on a log `P` axis (and a log `t` axis if
/// `log_t`): the Kaplan–Meier curve in `color` with its 95 % band, the
/// fitted exponential `A e^{−γt}` dashed over its window (labelled a
/// window rate only when the escape is not exponential), the power law
/// `P(t_min)(t/t_min)^{−β}` dotted over the tail when it is algebraic.
#[must_use]
pub fn survival_panel(title: &str, fit: &EscapeFit, log_t: bool, color: RGBColor) -> LinePlot {
    let curve = survival_steps(&fit.survival);
    let km = Series::new("Kaplan–Meier", curve.iter().map(|p| (p.0, p.1)))
        .line_only()
        .color(color)
        .band(curve.iter().map(|p| p.2), curve.iter().map(|p| p.3))
        .band_label("95 % band");
    let mut plot = LinePlot::with_axes(title, "time t", "survival P(t)")
        .log_y(true)
        .log_x(log_t)
        // Log–log: the curve runs from upper left to lower right. Log–lin:
        // it falls along the left edge, then runs right low (most balls
        // escape) or high (a plateau of balls that stay).
        .legend(
            if log_t || fit.survival.at(fit.survival.last_time()) > 0.05 {
                Legend::LowerLeft
            } else {
                Legend::UpperRight
            },
        )
        .series(km);
    if let Some(rate) = fit.rate {
        let (what, note) = if fit.law.is_some_and(|l| l.is_exponential()) {
            ("exp. fit", "")
        } else {
            ("window rate", " (not exp.)")
        };
        let label = format!(
            "{what} γ = {} on [{}, {}]{note}",
            PlusMinus::new(rate.gamma, rate.sem),
            short(rate.t0),
            short(rate.t1)
        );
        let ts = span(rate.t0.max(1e-9), rate.t1, 60, log_t);
        plot = plot.series(
            Series::new(
                label,
                ts.iter()
                    .map(|&t| (t, rate.amplitude * (-rate.gamma * t).exp())),
            )
            .line_only()
            .kind(LineKind::Dashed)
            .color(RGBColor(0x40, 0x40, 0x40)),
        );
    }
    if let Some(tail) = fit.algebraic() {
        let p0 = fit.survival.at(tail.t_min);
        let label = format!(
            "tail t^−β, β = {}",
            PlusMinus::new(tail.beta, tail.beta_sem)
        );
        let ts = span(tail.t_min, tail.t_max, 60, log_t);
        plot = plot.series(
            Series::new(
                label,
                ts.iter()
                    .map(|&t| (t, p0 * (t / tail.t_min).powf(-tail.beta))),
            )
            .line_only()
            .kind(LineKind::Dotted)
            .color(RGBColor(0xD5, 0x5E, 0x00)),
        );
    }
    plot
}

/// The step function of `survival` as a polyline `(t, P, lower, upper)`:
/// at each drawn escape time the value before it, then after it (at most
/// [`CURVE_POINTS`] escape times, evenly by index, the last one always),
/// held flat to the last observed time (the censored balls).
fn survival_steps(survival: &Survival) -> Vec<(f64, f64, f64, f64)> {
    let points = survival.points();
    let step = points.len().div_ceil(CURVE_POINTS).max(1);
    let mut drawn: Vec<_> = points.iter().step_by(step).collect();
    if let (Some(last), Some(kept)) = (points.last(), drawn.last())
        && !std::ptr::eq(last, *kept)
    {
        drawn.push(last);
    }
    let mut out = Vec::with_capacity(2 * drawn.len() + 1);
    let mut before = (1.0, 1.0, 1.0);
    for p in drawn {
        out.push((p.t, before.0, before.1, before.2));
        out.push((p.t, p.survival, p.lower, p.upper));
        before = (p.survival, p.lower, p.upper);
    }
    if let Some(&(t, ..)) = out.last()
        && survival.last_time() > t
    {
        out.push((survival.last_time(), before.0, before.1, before.2));
    }
    out
}

/// A time for a legend: three significant digits.
fn short(t: f64) -> String {
    spinball_plot::two_digits(t)
}

/// The escape rate against α of `fits`, in three series: the rates of
/// exponential escapes (`γ ± SE`), the window rates of escapes that are
/// not exponential (drawn apart, labelled as not a rate of the table), and
/// rates whose drift could not be checked. Empty series are left out.
#[must_use]
pub fn escape_rate_series(fits: &[EscapeFit]) -> Vec<Series> {
    let pick = |keep: fn(EscapeLaw) -> bool| -> Vec<(f64, Measurement)> {
        fits.iter()
            .filter_map(|f| {
                let (rate, law) = (f.rate?, f.law?);
                keep(law).then_some((f.alpha, Measurement::new(rate.gamma, rate.sem)))
            })
            .collect()
    };
    let groups = [
        (
            pick(|l| l.is_exponential()),
            "γ ± SE (exponential escape)",
            palette(0),
        ),
        (
            pick(|l| matches!(l, EscapeLaw::NotExponential { .. })),
            "not exponential: rate of the default window only",
            palette(1),
        ),
        (
            pick(|l| l == EscapeLaw::Unchecked),
            "unchecked (too few escapes)",
            palette(6),
        ),
    ];
    groups
        .into_iter()
        .filter(|(points, _, _)| !points.is_empty())
        .map(|(points, label, color)| {
            measured(label, points)
                .markers_only()
                .marker_radius(7)
                .color(color)
        })
        .collect()
}

/// `γ(α)` of `fits` on a log axis ([`escape_rate_series`]).
#[must_use]
pub fn escape_rate_panel(title: &str, fits: &[EscapeFit]) -> LinePlot {
    escape_rate_series(fits).into_iter().fold(
        LinePlot::with_axes(
            title,
            ALPHA_LABEL,
            "escape rate γ of the window (per unit time)",
        )
        .log_y(true),
        LinePlot::series,
    )
}

/// The tail exponent `β ± SE` against α where the tail is algebraic, and
/// the censored share of the balls (in percent) on the same axis.
#[must_use]
pub fn tail_exponent_panel(title: &str, fits: &[EscapeFit]) -> Option<LinePlot> {
    let beta: Vec<(f64, Measurement)> = fits
        .iter()
        .filter_map(|f| {
            f.algebraic()
                .map(|t| (f.alpha, Measurement::new(t.beta, t.beta_sem)))
        })
        .collect();
    (!beta.is_empty()).then(|| {
        LinePlot::with_axes(title, ALPHA_LABEL, "tail exponent β")
            .series(measured("β ± SE where the tail is algebraic", beta).color(palette(1)))
    })
}

/// The columns of [`escape_row`].
pub const ESCAPE_COLUMNS: [&str; 22] = [
    "alpha",
    "balls",
    "escaped",
    "censored",
    "last_time",
    "law",
    "gamma",
    "gamma_sem",
    "t0",
    "t1",
    "window_escapes",
    "drift_se",
    "tail_law",
    "beta",
    "beta_sem",
    "t_min",
    "tail_escapes",
    "vuong_z",
    "mean_escape_time",
    "mean_sem",
    "mean_complete",
    "kac_time",
];

/// Append the row of `fit` to `csv` (made with [`ESCAPE_COLUMNS`]); what
/// was not fitted is empty.
pub fn escape_row(csv: &mut Csv, fit: &EscapeFit) {
    let (s, r, t, m) = (&fit.survival, fit.rate, fit.tail, fit.kac.measured);
    csv.row(&[
        &fit.alpha,
        &s.n(),
        &s.escaped(),
        &s.censored(),
        &s.last_time(),
        &optional(fit.law.map(|l| l.to_string())),
        &optional(r.map(|r| r.gamma)),
        &optional(r.map(|r| r.sem)),
        &optional(r.map(|r| r.t0)),
        &optional(r.map(|r| r.t1)),
        &optional(r.map(|r| r.escaped)),
        &optional(r.and_then(|r| r.drift)),
        &optional(t.map(|t| t.law)),
        &optional(t.map(|t| t.beta)),
        &optional(t.map(|t| t.beta_sem)),
        &optional(t.map(|t| t.t_min)),
        &optional(t.map(|t| t.escaped)),
        &optional(t.map(|t| t.vuong_z)),
        &m.mean,
        &m.sem,
        &m.complete,
        &fit.kac.predicted,
    ]);
}

/// The columns of [`survival_rows`].
pub const SURVIVAL_COLUMNS: [&str; 6] = ["alpha", "t", "survival", "std_error", "lower", "upper"];

/// Append the survival curve of `fit`, one row per distinct escape time,
/// to `csv` (made with [`SURVIVAL_COLUMNS`]).
pub fn survival_rows(csv: &mut Csv, fit: &EscapeFit) {
    for p in fit.survival.points() {
        csv.row(&[
            &fit.alpha,
            &p.t,
            &p.survival,
            &p.std_error,
            &p.lower,
            &p.upper,
        ]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_plot::Plot;
    use spinball_test_support::censored_quantiles;

    #[test]
    fn panels_and_rows_of_an_exponential_and_a_power_law() {
        let kac = KacPrediction::new(
            4.0 + 2.0 * std::f64::consts::PI,
            4.0 + std::f64::consts::PI,
            0.2,
            0.0,
        )
        .unwrap();
        // Rate 0.5 censored at t = 8; P = t^{-1/2} censored at 10⁴.
        let (t, c) = censored_quantiles(3000, 8.0, |u| -u.ln() / 0.5);
        let exp = EscapeFit::new(0.0, &t, &c, &kac).unwrap();
        let (t, c) = censored_quantiles(3000, 1e4, |u| u.powf(-2.0));
        let power = EscapeFit::new(1.0, &t, &c, &kac).unwrap();
        assert_eq!(exp.law, Some(EscapeLaw::Exponential));
        assert!(!power.law.unwrap().is_exponential());
        assert!(exp.algebraic().is_none() && power.algebraic().is_some());
        // The rates land in two series: the exponential one, and the
        // window rate of the power law, apart.
        let fits = [exp.clone(), power.clone()];
        assert_eq!(escape_rate_series(&fits).len(), 2);
        assert_eq!(escape_rate_series(&fits[..1]).len(), 1);
        assert!(escape_rate_panel("γ", &fits).validate().is_ok());
        assert!(tail_exponent_panel("β", &fits).unwrap().validate().is_ok());
        assert!(tail_exponent_panel("β", &fits[..1]).is_none());
        for fit in &fits {
            for log_t in [false, true] {
                let panel = survival_panel("P", fit, log_t, palette(0));
                assert!(panel.validate().is_ok());
            }
        }
        let mut csv = Csv::new(&ESCAPE_COLUMNS);
        escape_row(&mut csv, &exp);
        escape_row(&mut csv, &power);
        let rows: Vec<Vec<String>> = csv
            .as_str()
            .lines()
            .skip(1)
            .map(|l| l.split(',').map(str::to_string).collect())
            .collect();
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[0][5], "exponential");
        let gamma: f64 = rows[0][6].parse().unwrap();
        assert_eq!(gamma, exp.rate.unwrap().gamma);
        // Quantiles of rate 0.5: γ within 3 SE.
        assert!((gamma - 0.5).abs() < 3.0 * exp.rate.unwrap().sem);
        assert_eq!(rows[1][12], "algebraic");
        // Quantiles of t^{-1/2}: β within 3 SE of 0.5.
        let tail = power.tail.unwrap();
        assert!((tail.beta - 0.5).abs() < 3.0 * tail.beta_sem, "{tail}");
        // The drawn step function ends flat at the last observed time.
        let steps = survival_steps(&power.survival);
        let last = power.survival.points().last().unwrap();
        assert_eq!(steps.last().unwrap().0, power.survival.last_time());
        assert_eq!(steps.last().unwrap().1, last.survival);
        assert!(steps.len() <= 2 * CURVE_POINTS + 3);
        assert!(
            steps
                .windows(2)
                .all(|w| w[0].0 <= w[1].0 && w[0].1 >= w[1].1)
        );
        let mut curve = Csv::new(&SURVIVAL_COLUMNS);
        survival_rows(&mut curve, &exp);
        assert_eq!(curve.rows(), exp.survival.points().len());
    }
}
