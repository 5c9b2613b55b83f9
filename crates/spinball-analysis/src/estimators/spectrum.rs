//! The full Lyapunov spectrum of one trajectory (paper, appendix "Full
//! Lyapunov spectrum").
//!
//! Documented in the group docs (`estimators/mod.rs`), section "The full spectrum".

use rand::Rng;
use spinball_core::{
    Ball, Billiard, MAX_QR_INTERVAL, Perturbation, State, TangentVector, random_direction,
};
use spinball_geometry::Boundary;

use super::lyapunov::{LogSum, Method};
use crate::error::AnalysisError;

/// What to compute for one trajectory.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SpectrumOptions {
    /// Number of collisions.
    pub collisions: u64,
    /// Exact tangent vectors or the paper's five shadows.
    pub method: Method,
    /// Re-orthonormalise every this many collisions (`1..=`[`MAX_QR_INTERVAL`];
    /// must be 1 for finite differences, whose shadows must stay `δ0` close).
    /// The run always ends with a QR step, so the last partial interval counts.
    pub qr_interval: u32,
}

impl SpectrumOptions {
    /// `collisions` collisions with `method`, QR after every collision.
    pub fn new(collisions: u64, method: Method) -> Self {
        SpectrumOptions {
            collisions,
            method,
            qr_interval: 1,
        }
    }

    /// Re-orthonormalise only every `interval` collisions (exact tangent vectors).
    pub fn with_qr_interval(mut self, interval: u32) -> Self {
        self.qr_interval = interval;
        self
    }

    /// Check the options.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for zero collisions, a QR interval
    /// outside `1..=MAX_QR_INTERVAL` (or other than 1 with finite
    /// differences), or a bad `δ0`.
    pub fn validate(&self) -> Result<(), AnalysisError> {
        if self.collisions == 0 {
            return Err(AnalysisError::invalid("collisions", "must be > 0"));
        }
        if !(1..=MAX_QR_INTERVAL).contains(&self.qr_interval) {
            return Err(AnalysisError::invalid(
                "qr_interval",
                format!("must be in 1..={MAX_QR_INTERVAL}, got {}", self.qr_interval),
            ));
        }
        if matches!(self.method, Method::FiniteDifference { .. }) && self.qr_interval != 1 {
            return Err(AnalysisError::invalid(
                "qr_interval",
                format!(
                    "finite differences renormalise the shadows every collision; got {}",
                    self.qr_interval
                ),
            ));
        }
        self.method.validate()
    }
}

/// The Lyapunov spectrum of one trajectory.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Spectrum {
    /// The five exponents per unit time, `Σ ln R_ii / Σ Δt`, sorted descending.
    pub exponents: [f64; 5],
    /// The same per collision, `Σ ln R_ii / collisions` (same order).
    pub per_collision: [f64; 5],
    /// Sum of the exponents per unit time (zero to rounding for the exact
    /// method: the step Jacobian has `|det| = 1`, [`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#exact-tangent-dynamics)).
    pub sum: f64,
    /// Total flight time of the reference trajectory.
    pub time: f64,
    /// Collisions taken.
    pub collisions: u64,
    /// How it was measured.
    pub method: Method,
    /// Finite differences only: how many separations (over all collisions
    /// and all five slots) came out below `ε·δ0`, the resolution of the
    /// Gram–Schmidt arithmetic on vectors of size `δ0`, and were counted at
    /// that value (always 0 for the exact method). In practice only the
    /// collapsing fifth slot, after about half of the flat-wall collisions
    /// (a quarter of all collisions in the stadium `a = 1`).
    pub floored: u64,
}

impl Spectrum {
    /// The largest exponent per unit time.
    pub fn largest(&self) -> f64 {
        self.exponents[0]
    }

    /// The three middle exponents per unit time (`≈ 0` for the exact method).
    pub fn middle(&self) -> [f64; 3] {
        [self.exponents[1], self.exponents[2], self.exponents[3]]
    }

    /// Collisions per unit time of the reference trajectory.
    pub fn collision_rate(&self) -> f64 {
        self.collisions as f64 / self.time
    }
}

/// Modified Gram–Schmidt on five vectors, in place: `v` becomes orthonormal
/// and the diagonal of `R` is returned. A vector whose remainder after the
/// projections is not positive and finite makes it fail with its index.
#[inline]
fn gram_schmidt(v: &mut [TangentVector; 5]) -> Result<[f64; 5], usize> {
    let mut r = [0.0; 5];
    for i in 0..5 {
        for j in 0..i {
            let p = v[i].dot(&v[j]);
            v[i] = v[i] - v[j] * p;
        }
        let n = v[i].norm();
        if !(n > 0.0 && n.is_finite()) {
            return Err(i);
        }
        r[i] = n;
        v[i] = v[i] * (1.0 / n);
    }
    Ok(r)
}

/// Gram–Schmidt for shadow separations, which may vanish: a separation
/// smaller than `floor` (`ε·δ0`, the resolution of the arithmetic) is measured as
/// `floor`, and if nothing of it is left after the projections its direction
/// is completed by the coordinate axis most orthogonal to the earlier ones.
/// Returns the diagonal of `R` and how many entries were floored.
#[inline]
fn gram_schmidt_floored(v: &mut [TangentVector; 5], floor: f64) -> Result<([f64; 5], u32), usize> {
    let mut r = [0.0; 5];
    let mut floored = 0;
    for i in 0..5 {
        for j in 0..i {
            let p = v[i].dot(&v[j]);
            v[i] = v[i] - v[j] * p;
        }
        let mut n = v[i].norm();
        if !n.is_finite() {
            return Err(i);
        }
        if n < floor {
            floored += 1;
            r[i] = floor;
            if n <= 1e-3 * floor {
                // No usable direction left: complete the basis.
                let (axis, rest) = (0..5)
                    .map(|k| {
                        let mut e = [0.0; 5];
                        e[k] = 1.0;
                        let mut e = TangentVector::from_array(e);
                        for q in &v[..i] {
                            e = e - *q * e.dot(q);
                        }
                        (e, e.norm())
                    })
                    .max_by(|a, b| a.1.total_cmp(&b.1))
                    .expect("five axes");
                v[i] = axis;
                n = rest;
            }
        } else {
            r[i] = n;
        }
        v[i] = v[i] * (1.0 / n);
    }
    Ok((r, floored))
}

fn collapsed(i: usize, n: u64, what: &str) -> AnalysisError {
    AnalysisError::invalid(
        "spectrum",
        format!(
            "{what} {} collapsed (zero or non-finite norm) at collision {n}",
            i + 1
        ),
    )
}

/// A random orthonormal frame of the 5-D state space.
pub(crate) fn random_frame<R: Rng + ?Sized>(rng: &mut R) -> [TangentVector; 5] {
    loop {
        let mut frame: [TangentVector; 5] = std::array::from_fn(|_| random_direction(rng));
        // Five random unit vectors are independent with probability 1; redraw
        // in the (never seen) case that one is numerically dependent.
        if let Ok(r) = gram_schmidt(&mut frame)
            && r.iter().all(|&x| x > 1e-6)
        {
            return frame;
        }
    }
}

/// The full Lyapunov spectrum of the trajectory from `start`.
///
/// `rng` draws the initial orthonormal frame. Two methods ([`Method`]):
/// five exact tangent vectors of the flow, or the paper's five shadow
/// trajectories `δ0` away; both re-orthonormalised by modified Gram–Schmidt,
/// the logarithms of the `R` diagonal summed and divided by the reference's
/// flight time.
///
/// # The exact spectrum in practice
/// The 5×5 step Jacobian has `|det| = 1`, so the sum is zero to rounding
/// (`~1e-16`) at any length, and `λ₁ + λ₅ → 0`. The three neutral exponents
/// converge like `ln T / T` at α = 0 (`~1e-5` after `1e6` collisions). At
/// α > 0 they are resolved only to a few `1e-4` per unit time: in the stadium
/// `a = 1`, α = 0.5, the middle pair sits at `≈ ±5e-4` from `1e5` up to `1e7`
/// collisions instead of shrinking. That split is not the dynamics (theory
/// gives exactly zero, [`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#full-spectrum)) but the arithmetic: it changes with the QR interval (`5.1e-4` at 1, `7.6e-4` at 16 collisions,
/// where exact arithmetic gives identical products), and projecting the two
/// exactly known neutral directions (the flow `(v, 0, 0)` and the energy
/// direction `(0, v, u)`) out of the frame leaves a middle exponent of the
/// 3-D collision map of `≲ 5e-5` that changes sign as the run grows. So
/// "three exponents within `1e-3` of zero" needs `≳ 1e5` collisions (at
/// `1e4` a value of `1.3e-3` occurs) and is about as far as five flow tangent
/// vectors go at α > 0.
///
/// # What the finite-difference fifth exponent is
/// The paper reports "four on-shell exponents plus one strongly negative
/// off-shell one". Measured here, the finite-difference spectrum is
/// `(λ, ≈0, ≈0, −λ, λ₅)`: the four leading exponents are the exact spectrum
/// with one zero removed, and `λ₅` is neither an off-shell direction nor a
/// property of the dynamics. It is the **flow direction**, annihilated by the
/// way the method compares states (the energy direction, which *is* off-shell,
/// stays neutral in both methods):
///
/// 1. Each trajectory is sampled at *its own* collision, so states are
///    compared on the Poincaré section "at the wall", not at equal times. A
///    shadow displaced along the flow, `δx ∝ v`, is on the same ray: it hits
///    the same wall point with the same velocity and spin, earlier, and after
///    the collision it coincides with the reference up to rounding. The
///    section map, read in the 5 ambient coordinates, has rank 4 (kernel: the
///    flow direction).
/// 2. After the QR step the first four separations span the image, and what
///    is left for the fifth is what the linearisation misses: on a **curved**
///    wall the second-order term, `R₅₅ ≈ c·δ0²` (`c = O(1)`: curvature and
///    flight-time differences); on a **flat** wall the flight–reflection is
///    linear enough that nothing but the rounding of the Gram–Schmidt itself
///    is left, `R₅₅ ≈ ε·δ0` (`ε = 2.2e-16`; separations below `ε·δ0`,
///    including exact zeros, are counted at `ε·δ0`, see
///    [`Spectrum::floored`]). Hence, per collision,
///
///    ```text
///    λ₅ / ν ≈ f_c · ln(c δ0) + (1 − f_c) · ln ε        (δ0 ≳ 1e-8)
///    ```
///
///    with `ν` the collision rate and `f_c` the share of collisions on curved
///    walls: `λ₅` falls by `f_c·ln 10` per collision for every decade `δ0`
///    shrinks, bottoms out near `δ0 ≈ √ε ≈ 1e-8` (where `c δ0²` reaches the
///    rounding of the states) and rises again below. It does not converge to
///    anything as the run grows; it measures `δ0` and the floating-point
///    format, not chaos.
///
/// Stadium `a = 1`, α = 0.5, one trajectory of `2·10⁴` collisions
/// (`ν = 0.354`, `f_c = 0.66`; predicted slope `f_c·ln 10 = 1.523` per
/// collision per decade, measured `1.523` between `δ0 = 1e-5` and `1e-7`):
/// `λ₅ = −6.5, −7.0, −7.5, −8.1, −8.5, −8.1, −7.6` per unit time for `δ0 = 1e-4 … 1e-10`, i.e. `−18` to `−24` per collision,
/// against `λ₁ = 0.196`; the four leading exponents are
/// `(0.196, 0.0002, −0.0007, −0.195)` at every `δ0`. The tests
/// `fd_fifth_exponent_is_the_annihilated_flow_direction` and
/// `fd_fifth_exponent_scales_with_ln_delta0` assert the one-collision
/// collapse of a flow-direction shadow and the `f_c·ln 10` slope.
///
/// ```
/// use spinball_analysis::estimators::{Method, SpectrumOptions, lyapunov_spectrum};
/// use spinball_core::{Billiard, Sampler, SpinLaw, ic_rng};
/// use spinball_geometry::Stadium;
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?);
/// let mut rng = ic_rng(3, 0);
/// let start = Sampler::Paper.sample(billiard.table(), billiard.law(), &mut rng);
/// let options = SpectrumOptions::new(20_000, Method::Tangent);
/// let spectrum = lyapunov_spectrum(&billiard, start, &options, &mut rng)?;
/// let [l1, .., l5] = spectrum.exponents;
/// assert!(l1 > 0.1 && (l1 + l5).abs() < 0.01); // ±λ pairing
/// assert!(spectrum.sum.abs() < 1e-9); // |det J| = 1
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for bad options or if a vector's norm
/// turns zero or non-finite (exact method) or non-finite (finite
/// differences, where vanishing separations are floored, see
/// [`Spectrum::floored`]); `Launch`/`Step` errors from the dynamics (a shadow
/// that finds no wall, for a `δ0` so large it starts outside the table).
pub fn lyapunov_spectrum<B: Boundary, R: Rng + ?Sized>(
    billiard: &Billiard<B>,
    start: State,
    options: &SpectrumOptions,
    rng: &mut R,
) -> Result<Spectrum, AnalysisError> {
    options.validate()?;
    let mut ball = billiard.launch(start)?;
    let mut frame = random_frame(rng);
    let mut logs = [LogSum::new(); 5];
    let mut time = 0.0;
    let mut floored = 0u64;
    match options.method {
        Method::Tangent => {
            let every = u64::from(options.qr_interval);
            for n in 1..=options.collisions {
                let c = billiard.step_tangent(&mut ball, &mut frame)?;
                time += c.time();
                if n.is_multiple_of(every) || n == options.collisions {
                    let r =
                        gram_schmidt(&mut frame).map_err(|i| collapsed(i, n, "tangent vector"))?;
                    for (log, r) in logs.iter_mut().zip(r) {
                        log.push(r);
                    }
                }
            }
        }
        Method::FiniteDifference { delta0 } => {
            let law = *billiard.law();
            // Separations live in the table's and the ball's units (exactly
            // 1 on the paper's tables, so their numbers are unchanged).
            let units = Perturbation::new(billiard.table(), &start, &law, delta0)
                .map_err(|source| AnalysisError::Perturbation { index: 0, source })?;
            let (scaled, inv_units) = (units.scaled(), units.inv_units());
            let offset = |z: &[f64; 5], d: &TangentVector| -> Result<Ball, AnalysisError> {
                let dz = d.to_array();
                Ok(Ball::new(
                    State::from_array(std::array::from_fn(|i| z[i] + dz[i] * scaled[i])),
                    &law,
                )?)
            };
            let z0 = ball.state().to_array();
            let mut shadows = [ball; 5];
            for (s, q) in shadows.iter_mut().zip(&frame) {
                *s = offset(&z0, q)?;
            }
            let inv_delta0 = 1.0 / delta0;
            // The arithmetic resolution of a QR of separations of size δ0.
            let floor = f64::EPSILON * delta0;
            for n in 1..=options.collisions {
                let c = billiard.step(&mut ball)?;
                time += c.time();
                let z = ball.state().to_array();
                for (s, d) in shadows.iter_mut().zip(frame.iter_mut()) {
                    billiard.step(s)?;
                    let zs = s.state().to_array();
                    *d = TangentVector::from_array(std::array::from_fn(|i| {
                        (zs[i] - z[i]) * inv_units[i]
                    }));
                }
                let (r, below) = gram_schmidt_floored(&mut frame, floor)
                    .map_err(|i| collapsed(i, n, "shadow separation"))?;
                floored += u64::from(below);
                for ((log, r), (s, q)) in logs.iter_mut().zip(r).zip(shadows.iter_mut().zip(&frame))
                {
                    log.push(r * inv_delta0);
                    *s = offset(&z, q)?;
                }
            }
        }
    }
    let totals: [f64; 5] = std::array::from_fn(|i| logs[i].total());
    Ok(Spectrum::from_sums(
        totals,
        time,
        options.collisions,
        options.method,
        floored,
    ))
}

impl Spectrum {
    /// The spectrum from the five summed logarithms `Σ ln R_ii` (in
    /// Gram–Schmidt order), the total time and the collisions: what every
    /// engine returns.
    pub(crate) fn from_sums(
        totals: [f64; 5],
        time: f64,
        collisions: u64,
        method: Method,
        floored: u64,
    ) -> Self {
        let mut exponents: [f64; 5] = std::array::from_fn(|i| totals[i] / time);
        let mut per_collision: [f64; 5] = std::array::from_fn(|i| totals[i] / collisions as f64);
        exponents.sort_by(|a, b| b.total_cmp(a));
        per_collision.sort_by(|a, b| b.total_cmp(a));
        Spectrum {
            exponents,
            per_collision,
            sum: totals.iter().sum::<f64>() / time,
            time,
            collisions,
            method,
            floored,
        }
    }
}
