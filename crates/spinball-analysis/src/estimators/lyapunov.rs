//! The largest Lyapunov exponent of one trajectory, two ways.
//!
//! Documented in the group docs (`estimators/mod.rs`), section "The largest exponent of one trajectory".

use rand::Rng;
use spinball_core::{
    Ball, Billiard, Perturbation, State, TangentVector, Units, perturbation::check_delta0,
    random_direction,
};
use spinball_geometry::Boundary;

use crate::error::AnalysisError;

/// How the exponent is measured.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Method {
    /// The paper's finite-difference Benettin method with initial separation `delta0`.
    FiniteDifference {
        /// Separation of the shadow trajectory (the paper: `1e-7`), in units
        /// of the table's unit length (positions) and the ball's speed
        /// (velocities and spin), each rounded to a power of two: exactly
        /// `1e-7` on the paper's tables. See [`spinball_core::perturbation`].
        /// Must lie in `[1e-11, 1e-3]`.
        delta0: f64,
    },
    /// Exact tangent dynamics.
    Tangent,
}

/// The paper's separation `δ0 = 1e-7`.
pub const PAPER_DELTA0: f64 = 1e-7;

impl Default for Method {
    /// The paper's method, `FiniteDifference { delta0: 1e-7 }`.
    fn default() -> Self {
        crate::run::RunDefaults::METHOD
    }
}

impl Method {
    /// `fd` or `tangent`.
    pub fn name(&self) -> &'static str {
        match self {
            Method::FiniteDifference { .. } => "fd",
            Method::Tangent => "tangent",
        }
    }

    /// The finite-difference separation `δ0` (`None` for tangent).
    #[must_use]
    pub fn delta0(&self) -> Option<f64> {
        match self {
            Method::FiniteDifference { delta0 } => Some(*delta0),
            Method::Tangent => None,
        }
    }

    /// Check the method's parameters.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for `delta0` outside
    /// `[MIN_DELTA0, MAX_DELTA0]` = `[1e-11, 1e-3]`.
    pub fn validate(&self) -> Result<(), AnalysisError> {
        if let Method::FiniteDifference { delta0 } = *self {
            check_delta0(delta0).map_err(|e| AnalysisError::invalid("delta0", e.to_string()))?;
        }
        Ok(())
    }
}

impl std::str::FromStr for Method {
    type Err = AnalysisError;
    /// `fd` (or `finite-difference`, with the paper's `δ0`) or `tangent`.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.trim().to_ascii_lowercase().as_str() {
            "fd" | "finite-difference" | "benettin" => Ok(Method::default()),
            "tangent" | "exact" => Ok(Method::Tangent),
            other => Err(AnalysisError::invalid(
                "method",
                format!("unknown method `{other}` (expected fd or tangent)"),
            )),
        }
    }
}

/// What to compute for one trajectory.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LyapunovOptions {
    /// Number of collisions.
    pub collisions: u64,
    /// How to measure.
    pub method: Method,
    /// Record the running exponent every this many collisions (`None`: no history).
    pub history_stride: Option<u64>,
}

impl LyapunovOptions {
    /// `collisions` collisions with `method`, no history.
    pub fn new(collisions: u64, method: Method) -> Self {
        LyapunovOptions {
            collisions,
            method,
            history_stride: None,
        }
    }

    /// Also record the running exponent every `stride` collisions.
    pub fn with_history(mut self, stride: u64) -> Self {
        self.history_stride = Some(stride);
        self
    }

    /// Check the options.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`].
    pub fn validate(&self) -> Result<(), AnalysisError> {
        if self.collisions == 0 {
            return Err(AnalysisError::invalid("collisions", "must be > 0"));
        }
        if self.history_stride == Some(0) {
            return Err(AnalysisError::invalid("history_stride", "must be > 0"));
        }
        self.method.validate()
    }
}

/// One point of a running-exponent history.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct HistoryPoint {
    /// Collisions so far.
    pub collisions: u64,
    /// Time so far.
    pub time: f64,
    /// Running exponent per unit time.
    pub exponent: f64,
}

/// The largest Lyapunov exponent of one trajectory.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Lyapunov {
    /// λ per unit time, `Σ ln(stretch) / Σ Δt`.
    pub exponent: f64,
    /// λ per collision, `Σ ln(stretch) / collisions`.
    pub per_collision: f64,
    /// Total flight time.
    pub time: f64,
    /// Collisions taken.
    pub collisions: u64,
    /// Running exponent, if asked for.
    pub history: Vec<HistoryPoint>,
}

/// Running sum of logarithms, taking `ln` only when the product of growth
/// factors gets large or small (or at the end).
#[derive(Debug, Clone, Copy)]
pub(crate) struct LogSum {
    product: f64,
    sum: f64,
}

impl LogSum {
    pub(crate) fn new() -> Self {
        LogSum {
            product: 1.0,
            sum: 0.0,
        }
    }
    #[inline]
    pub(crate) fn push(&mut self, factor: f64) {
        self.product *= factor;
        if !(1e-150..=1e150).contains(&self.product) {
            self.flush();
        }
    }
    #[inline]
    pub(crate) fn flush(&mut self) {
        self.sum += self.product.ln();
        self.product = 1.0;
    }
    #[inline]
    pub(crate) fn total(&self) -> f64 {
        self.sum + self.product.ln()
    }
}

/// The largest Lyapunov exponent of the trajectory from `start`.
///
/// `rng` draws the initial direction of the shadow (finite differences) or of
/// the tangent vector.
///
/// ```
/// use spinball_analysis::estimators::{LyapunovOptions, Method, largest_lyapunov};
/// use spinball_core::{Billiard, Sampler, SpinLaw, ic_rng};
/// use spinball_geometry::Stadium;
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.0)?);
/// let mut rng = ic_rng(1, 0);
/// let start = Sampler::Paper.sample(billiard.table(), billiard.law(), &mut rng);
/// let opts = LyapunovOptions::new(20_000, Method::Tangent);
/// let lyap = largest_lyapunov(&billiard, start, &opts, &mut rng)?;
/// assert!((lyap.exponent - 0.43).abs() < 0.05); // the specular stadium, paper §IV
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for bad options, `Launch`/`Step` errors
/// from the dynamics.
pub fn largest_lyapunov<B: Boundary, R: Rng + ?Sized>(
    billiard: &Billiard<B>,
    start: State,
    options: &LyapunovOptions,
    rng: &mut R,
) -> Result<Lyapunov, AnalysisError> {
    options.validate()?;
    let mut ball = billiard.launch(start)?;
    let direction = random_direction(rng);
    let stride = options.history_stride.unwrap_or(u64::MAX);
    let mut history = Vec::new();
    let mut logs = LogSum::new();
    let mut time = 0.0;
    let record = |n: u64, time: f64, logs: &LogSum, history: &mut Vec<HistoryPoint>| {
        if n.is_multiple_of(stride) {
            history.push(HistoryPoint {
                collisions: n,
                time,
                exponent: logs.total() / time,
            });
        }
    };
    match options.method {
        Method::FiniteDifference { delta0 } => {
            let law = *billiard.law();
            let offset = |ball: &Ball, d: TangentVector| {
                let z = ball.state().to_array();
                let dz = d.to_array();
                State::from_array(std::array::from_fn(|i| z[i] + dz[i]))
            };
            let perturbation = Perturbation::new(billiard.table(), &start, &law, delta0)
                .map_err(|source| AnalysisError::Perturbation { index: 0, source })?;
            let mut shadow = Ball::new(offset(&ball, perturbation.offset(direction)), &law)?;
            for n in 1..=options.collisions {
                let c = billiard.step(&mut ball)?;
                billiard.step(&mut shadow)?;
                time += c.time();
                let a = ball.state().to_array();
                let b = shadow.state().to_array();
                let d = TangentVector::from_array(std::array::from_fn(|i| b[i] - a[i]));
                let dist = perturbation.distance(&d);
                if !(dist > 0.0 && dist.is_finite()) {
                    return Err(AnalysisError::invalid(
                        "delta0",
                        format!("shadow separation became {dist} at collision {n}"),
                    ));
                }
                logs.push(dist / delta0);
                shadow = Ball::new(offset(&ball, d * (delta0 / dist)), &law)?;
                record(n, time, &logs, &mut history);
            }
        }
        Method::Tangent => {
            // The growth is measured in units (`Units`): `Σ ln` of the plain
            // norms taken off telescopes to the plain growth, and the end
            // and start vectors' lengths in units turn it into theirs.
            let units = Units::new(billiard.table(), &start, billiard.law());
            let from = units.measure(&direction);
            let measured = |logs: LogSum, v: &TangentVector| {
                let mut m = logs;
                m.push(units.measure(v) / from);
                m
            };
            let mut tv = [direction];
            for n in 1..=options.collisions {
                let c = billiard.step_tangent(&mut ball, &mut tv)?;
                time += c.time();
                let norm = tv[0].norm();
                logs.push(norm);
                tv[0] = tv[0] * (1.0 / norm);
                if n.is_multiple_of(stride) {
                    record(n, time, &measured(logs, &tv[0]), &mut history);
                }
            }
            logs = measured(logs, &tv[0]);
        }
    }
    let total = logs.total();
    Ok(Lyapunov {
        exponent: total / time,
        per_collision: total / options.collisions as f64,
        time,
        collisions: options.collisions,
        history,
    })
}
