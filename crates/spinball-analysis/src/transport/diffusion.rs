//! The diffusion coefficient of a periodic table from the Einstein relation,
//! its error from the spread over initial conditions, how it depends on the
//! fit window, and the refusal of a finite `D` when the horizon is
//! infinite.
//!
//! Documented in the group docs (`transport/mod.rs`) and `docs/TRANSPORT.md`,
//! sections "Diffusion coefficient" and "Horizon".

use std::fmt;

use super::ballistic::ballistic_balls;
use super::{Ballistic, Displacements, Horizon, TransportError};
use crate::estimators::{Accumulator, LinearFit, PlusMinus};

/// The fewest checkpoints a fit window must hold.
pub const MIN_POINTS: usize = 3;

/// The time window `[t0, t1]` a growth law is fitted on (checkpoints with
/// `t0 <= t <= t1`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FitWindow {
    /// Start.
    pub t0: f64,
    /// End.
    pub t1: f64,
}

impl FitWindow {
    /// `[t0, t1]`.
    ///
    /// # Errors
    /// [`TransportError::BadWindow`] unless `0 <= t0 < t1` are finite.
    pub fn new(t0: f64, t1: f64) -> Result<Self, TransportError> {
        if t0.is_finite() && t1.is_finite() && 0.0 <= t0 && t0 < t1 {
            Ok(FitWindow { t0, t1 })
        } else {
            Err(TransportError::BadWindow { t0, t1 })
        }
    }

    /// The default: the later half of the run, `[T/2, T]` with `T` the last
    /// checkpoint (the ballistic start and the transient left out).
    #[must_use]
    pub fn later_half(times: &[f64]) -> Self {
        let t = times.last().copied().unwrap_or(0.0);
        FitWindow { t0: t / 2.0, t1: t }
    }

    fn indices(&self, times: &[f64]) -> Result<std::ops::Range<usize>, TransportError> {
        let lo = times.partition_point(|&t| t < self.t0);
        let hi = times.partition_point(|&t| t <= self.t1);
        if hi.saturating_sub(lo) < MIN_POINTS {
            return Err(TransportError::TooFewPoints {
                points: hi.saturating_sub(lo),
                min: MIN_POINTS,
                t0: self.t0,
                t1: self.t1,
            });
        }
        Ok(lo..hi)
    }
}

/// A growth coefficient fitted on a window, with its error.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct DiffusionFit {
    /// The coefficient (`D`, or `D_m` for marginal growth).
    pub coefficient: f64,
    /// Its standard error, from the spread of the per-IC slopes.
    pub sem: f64,
    /// The window.
    pub window: FitWindow,
    /// Checkpoints in the window.
    pub points: usize,
    /// Initial conditions.
    pub n_ics: usize,
}

/// The diffusion estimate: normal with a finite `D`, or marginal.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub enum Diffusion {
    /// Finite horizon: `⟨Δr²⟩ ≈ 4Dt + c`; the coefficient is `D`.
    Normal(DiffusionFit),
    /// Infinite horizon: `⟨Δr²⟩ ≈ 4 D_m t ln t + c`, so `⟨Δr²⟩/(4t)` grows
    /// without bound and there is no finite `D`; the coefficient is `D_m`
    /// (`⟨Δr²⟩/(4 t ln t) → D_m`). Its value depends on the time unit at
    /// finite `t` (corrections are of relative order `1/ln t`).
    Marginal(DiffusionFit),
    /// Finite horizon, but some balls travel ballistically through the
    /// lattice ([`Ballistic`]): `⟨Δr²⟩` grows like `t²` and there is no
    /// finite `D`. The fit over all balls is kept for inspection only.
    Ballistic(DiffusionFit, Ballistic),
}

impl Diffusion {
    /// The fit, whichever the law.
    pub fn fit(&self) -> DiffusionFit {
        match *self {
            Diffusion::Normal(f) | Diffusion::Marginal(f) | Diffusion::Ballistic(f, _) => f,
        }
    }

    /// `D` if the diffusion is normal, `None` if it is marginal or
    /// ballistic.
    #[must_use]
    pub fn finite_d(&self) -> Option<PlusMinus> {
        match *self {
            Diffusion::Normal(f) => Some(PlusMinus::new(f.coefficient, f.sem)),
            Diffusion::Marginal(_) | Diffusion::Ballistic(..) => None,
        }
    }
}

impl fmt::Display for Diffusion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let fit = self.fit();
        let value = PlusMinus::new(fit.coefficient, fit.sem);
        let (t0, t1) = (fit.window.t0, fit.window.t1);
        match self {
            Diffusion::Normal(_) => write!(f, "D = {value} on [{t0}, {t1}]"),
            Diffusion::Marginal(_) => write!(
                f,
                "marginal (infinite horizon, no finite D): ⟨Δr²⟩/(4 t ln t) → D_m = {value} on [{t0}, {t1}]"
            ),
            Diffusion::Ballistic(_, b) => write!(
                f,
                "ballistic (no finite D): {} of {} balls fly straight through the lattice on [{t0}, {t1}], the fastest (ball {}) at {:.4} per unit time",
                b.balls, fit.n_ics, b.fastest, b.speed
            ),
        }
    }
}

/// The regressor of a growth law: `t` (normal) or `t ln t` (marginal).
fn regressor(horizon: Horizon) -> fn(f64) -> f64 {
    match horizon {
        Horizon::Finite => |t| t,
        Horizon::Infinite => |t| t * t.ln(),
    }
}

/// The least-squares slope of `|Δr_i|²` against `x(t)` over the
/// checkpoints `range`, over 4, for every IC. Least squares is linear in
/// the data, so their mean is the slope of `⟨Δr²⟩` itself.
fn per_ic_slopes(
    d: &Displacements<'_>,
    range: std::ops::Range<usize>,
    x: fn(f64) -> f64,
) -> Vec<f64> {
    let xs: Vec<f64> = d.times()[range.clone()].iter().map(|&t| x(t)).collect();
    (0..d.n_ics())
        .map(|i| {
            let pts: Vec<(f64, f64)> = xs
                .iter()
                .zip(range.clone())
                .map(|(&x, j)| (x, d.squared(i, j)))
                .collect();
            LinearFit::through(&pts).map_or(0.0, |f| f.slope / 4.0)
        })
        .collect()
}

/// Mean and SEM of per-IC values.
fn mean_sem(values: &[f64]) -> (f64, f64) {
    let acc = Accumulator::from_slice(values);
    (acc.mean().unwrap_or(0.0), acc.sem().unwrap_or(0.0))
}

fn fit_window(
    d: &Displacements<'_>,
    horizon: Horizon,
    window: FitWindow,
) -> Result<(Diffusion, Vec<f64>), TransportError> {
    let range = window.indices(d.times())?;
    let points = range.len();
    let slopes = per_ic_slopes(d, range.clone(), regressor(horizon));
    let (coefficient, sem) = mean_sem(&slopes);
    let fit = DiffusionFit {
        coefficient,
        sem,
        window,
        points,
        n_ics: d.n_ics(),
    };
    let out = match horizon {
        Horizon::Finite => match ballistic_balls(d, range) {
            Some(b) => Diffusion::Ballistic(fit, b),
            None => Diffusion::Normal(fit),
        },
        Horizon::Infinite => Diffusion::Marginal(fit),
    };
    Ok((out, slopes))
}

/// The diffusion estimate of `d` on a table of the given `horizon`, fitted
/// on `window` ([`FitWindow::later_half`] if `None`): the slope of
/// `⟨Δr²⟩` against `4t` (finite horizon) or `4 t ln t` (infinite), by least
/// squares with an intercept, its error the SEM of the same slope fitted to
/// each initial condition alone (the ICs are independent; the checkpoints
/// of one IC are not).
///
/// ```
/// use spinball_analysis::transport::{Diffusion, Displacements, Horizon, diffusion};
/// // Two ICs on a deterministic path with |Δr|² = 4t: D = 1.
/// let times: Vec<f64> = (1..=8).map(f64::from).collect();
/// let dr: Vec<[f64; 2]> = (0..2)
///     .flat_map(|_| times.iter().map(|t| [2.0 * t.sqrt(), 0.0]))
///     .collect();
/// let d = Displacements::new(&times, &dr)?;
/// let est = diffusion(&d, Horizon::Finite, None)?;
/// assert!((est.fit().coefficient - 1.0).abs() < 1e-12);
/// // The same data on an infinite-horizon table: no finite D.
/// assert!(diffusion(&d, Horizon::Infinite, None)?.finite_d().is_none());
/// # Ok::<(), spinball_analysis::transport::TransportError>(())
/// ```
///
/// # Errors
/// [`TransportError::TooFewPoints`] for fewer than [`MIN_POINTS`]
/// checkpoints in the window.
pub fn diffusion(
    d: &Displacements<'_>,
    horizon: Horizon,
    window: Option<FitWindow>,
) -> Result<Diffusion, TransportError> {
    let window = window.unwrap_or_else(|| FitWindow::later_half(d.times()));
    Ok(fit_window(d, horizon, window)?.0)
}

/// The trend of the running coefficient `⟨Δr²⟩/(4t)` (window slopes of
/// `⟨Δr²⟩` against `4t`) in `ln t`: zero for normal diffusion, `D_m` for
/// marginal growth `4 D_m t ln t`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct Trend {
    /// Change of the apparent `D` per unit of `ln t`.
    pub per_ln_t: f64,
    /// Its standard error (from the per-IC trends).
    pub sem: f64,
}

impl Trend {
    /// The trend in standard errors (0 if the error is 0 and the trend too).
    #[must_use]
    pub fn z(&self) -> f64 {
        if self.sem > 0.0 {
            self.per_ln_t / self.sem
        } else if self.per_ln_t == 0.0 {
            0.0
        } else {
            f64::INFINITY.copysign(self.per_ln_t)
        }
    }

    /// Whether the apparent `D` grows by more than `z` standard errors:
    /// the sign of marginal (or not yet normal) growth.
    #[must_use]
    pub fn grows(&self, z: f64) -> bool {
        self.z() > z
    }
}

/// The estimate over successive windows `[T/2, T]`, `[T/4, T/2]`, … (each
/// with at least [`MIN_POINTS`] checkpoints), latest first, and the trend
/// of the apparent `D` over them.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct WindowScan {
    /// The horizon the windows were fitted for.
    pub horizon: Horizon,
    /// One estimate per window, latest first.
    pub windows: Vec<Diffusion>,
    /// The apparent `D` (slope against `4t`, whatever the horizon) per
    /// window, latest first.
    pub apparent_d: Vec<DiffusionFit>,
    /// Its trend in `ln t`; `None` with a single window.
    pub trend: Option<Trend>,
}

/// How the estimate of `d` depends on the window: [`diffusion`] on the
/// halving windows `[T/2^{k+1}, T/2^k]`, `k = 0, 1, …`, while a window
/// holds [`MIN_POINTS`] checkpoints, and the [`Trend`] of the apparent `D`
/// across them (per IC, then averaged, so the error counts the windows'
/// correlation).
///
/// # Errors
/// [`TransportError::TooFewPoints`] if even `[T/2, T]` holds fewer than
/// [`MIN_POINTS`] checkpoints.
pub fn window_scan(d: &Displacements<'_>, horizon: Horizon) -> Result<WindowScan, TransportError> {
    let t_last = *d.times().last().expect("checked non-empty");
    let (mut windows, mut apparent_d, mut per_window, mut mids) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut hi = t_last;
    loop {
        let window = FitWindow {
            t0: hi / 2.0,
            t1: hi,
        };
        let (estimate, slopes) = match fit_window(d, horizon, window) {
            Ok(fit) => fit,
            Err(e) if windows.is_empty() => return Err(e),
            Err(_) => break,
        };
        let (apparent, slopes) = match horizon {
            Horizon::Finite => (estimate.fit(), slopes),
            Horizon::Infinite => {
                let (normal, slopes) = fit_window(d, Horizon::Finite, window)?;
                (normal.fit(), slopes)
            }
        };
        windows.push(estimate);
        apparent_d.push(apparent);
        per_window.push(slopes);
        mids.push((window.t0 * window.t1).sqrt().ln());
        hi /= 2.0;
    }
    let trend = (windows.len() >= 2).then(|| {
        let trends: Vec<f64> = (0..d.n_ics())
            .map(|i| {
                let pts: Vec<(f64, f64)> = mids
                    .iter()
                    .zip(&per_window)
                    .map(|(&x, s)| (x, s[i]))
                    .collect();
                LinearFit::through(&pts).map_or(0.0, |f| f.slope)
            })
            .collect();
        let (per_ln_t, sem) = mean_sem(&trends);
        Trend { per_ln_t, sem }
    });
    Ok(WindowScan {
        horizon,
        windows,
        apparent_d,
        trend,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_test_support::normal::Normal;

    /// `n` walks of `steps` unit-time steps, Gaussian increments of
    /// variance `2·var(k)` per component at step `k` (so `⟨Δr²⟩ = 4Σvar`),
    /// recorded every `every` steps.
    fn walks(
        seed: u64,
        n: usize,
        steps: usize,
        every: usize,
        var: impl Fn(f64) -> f64,
    ) -> (Vec<f64>, Vec<[f64; 2]>) {
        let mut rng = Normal(seed);
        let times: Vec<f64> = (1..=steps / every).map(|k| (k * every) as f64).collect();
        let mut dr = Vec::with_capacity(n * times.len());
        for _ in 0..n {
            let (mut x, mut y) = (0.0, 0.0);
            for k in 1..=steps {
                let s = (2.0 * var(k as f64)).sqrt();
                x += s * rng.next();
                y += s * rng.next();
                if k % every == 0 {
                    dr.push([x, y]);
                }
            }
        }
        (times, dr)
    }

    #[test]
    fn gaussian_walks_give_their_d() {
        // Per-component step variance 2D per unit time: ⟨Δr²⟩ = 4Dt exactly.
        // D = 0.3, 2000 walks × 1024 steps, three seeds, within 3 SE.
        for seed in 1..=3 {
            let (times, dr) = walks(seed, 2000, 1024, 16, |_| 0.3);
            let d = Displacements::new(&times, &dr).unwrap();
            let est = diffusion(&d, Horizon::Finite, None).unwrap();
            let fit = est.fit();
            assert!(
                (fit.coefficient - 0.3).abs() < 3.0 * fit.sem,
                "seed {seed}: {est}"
            );
            assert_eq!(
                fit.window,
                FitWindow {
                    t0: 512.0,
                    t1: 1024.0
                }
            );
            assert_eq!(fit.points, 33);
            let scan = window_scan(&d, Horizon::Finite).unwrap();
            assert!(scan.windows.len() >= 4, "{scan:?}");
            for w in &scan.windows {
                let f = w.fit();
                assert!(
                    (f.coefficient - 0.3).abs() < 3.5 * f.sem,
                    "seed {seed}: {w}"
                );
            }
            let trend = scan.trend.unwrap();
            assert!(trend.z().abs() < 3.0, "seed {seed}: {trend:?}");
        }
    }

    #[test]
    fn msd_slope_is_the_mean_of_per_ic_slopes() {
        let (times, dr) = walks(7, 50, 64, 4, |_| 1.0);
        let d = Displacements::new(&times, &dr).unwrap();
        let window = FitWindow::new(16.0, 64.0).unwrap();
        let est = diffusion(&d, Horizon::Finite, Some(window)).unwrap().fit();
        let msd = crate::transport::MeanSquareDisplacement::new(&d);
        let pts: Vec<(f64, f64)> = msd
            .points()
            .iter()
            .filter(|p| p.t >= 16.0)
            .map(|p| (p.t, p.msd))
            .collect();
        let slope = LinearFit::through(&pts).unwrap().slope / 4.0;
        assert!((est.coefficient - slope).abs() < 1e-12 * slope.abs().max(1.0));
    }

    #[test]
    fn t_ln_t_growth_is_marginal() {
        // Step k has variance 2 D_m (ln k + 1) per component, so
        // ⟨Δr²⟩ = 4 D_m Σ (ln k + 1) = 4 D_m (t ln t + ½ ln(2πt) + O(1/t))
        // (Stirling): marginal growth with D_m = 0.25.
        let dm = 0.25;
        let (times, dr) = walks(3, 2000, 2048, 16, |k| dm * (k.ln() + 1.0));
        let d = Displacements::new(&times, &dr).unwrap();
        let est = diffusion(&d, Horizon::Infinite, None).unwrap();
        assert!(matches!(est, Diffusion::Marginal(_)) && est.finite_d().is_none());
        let fit = est.fit();
        assert!((fit.coefficient - dm).abs() < 3.0 * fit.sem, "{est}");
        // The diagnostic: the apparent D grows by D_m per unit ln t
        // (slope of t ln t over a window is ln t + 1), here > 3 SE.
        let scan = window_scan(&d, Horizon::Finite).unwrap();
        let trend = scan.trend.unwrap();
        assert!(trend.grows(3.0), "{trend:?}");
        assert!((trend.per_ln_t - dm).abs() < 3.0 * trend.sem, "{trend:?}");
        // Every window of an infinite-horizon scan is marginal.
        let scan = window_scan(&d, Horizon::Infinite).unwrap();
        assert!(scan.windows.iter().all(|w| w.finite_d().is_none()));
    }

    #[test]
    fn exact_t_ln_t_sequence() {
        // |Δr|² = t ln t exactly for both ICs: D_m = 1/4 with zero spread.
        let times: Vec<f64> = (2..=40).map(f64::from).collect();
        let dr: Vec<[f64; 2]> = [1.0, -1.0]
            .iter()
            .flat_map(|&s| times.iter().map(move |t| [0.0, s * (t * t.ln()).sqrt()]))
            .collect();
        let d = Displacements::new(&times, &dr).unwrap();
        let fit = diffusion(&d, Horizon::Infinite, None).unwrap().fit();
        assert!(
            (fit.coefficient - 0.25).abs() < 1e-12 && fit.sem == 0.0,
            "{fit:?}"
        );
        let trend = window_scan(&d, Horizon::Finite).unwrap().trend.unwrap();
        assert!(trend.grows(3.0) && trend.z().is_infinite());
    }

    #[test]
    fn windows_that_cannot_work_are_refused() {
        let (times, dr) = walks(1, 4, 8, 4, |_| 1.0);
        let d = Displacements::new(&times, &dr).unwrap();
        assert!(matches!(
            diffusion(&d, Horizon::Finite, None),
            Err(TransportError::TooFewPoints { points: 2, .. })
        ));
        assert!(matches!(
            window_scan(&d, Horizon::Finite),
            Err(TransportError::TooFewPoints { .. })
        ));
        assert!(FitWindow::new(2.0, 1.0).is_err());
        assert!(FitWindow::new(f64::NAN, 1.0).is_err());
    }
}
