//! Estimators: what one trajectory says about chaos, and the statistics
//! that turn many such numbers into one with an error bar.
//!
//! This is the bottom layer of the crate: it knows nothing about ensembles,
//! threads or result records, so each estimator can be read (and tested)
//! on its own.
//!
//! - [`largest_lyapunov`]: the largest exponent of one trajectory, by the
//!   paper's finite-difference Benettin method ([`Method::FiniteDifference`],
//!   δ0 = [`PAPER_DELTA0`]) or by exact tangent dynamics
//!   ([`Method::Tangent`]), with an optional running history
//!   ([`HistoryPoint`]);
//! - [`lyapunov_spectrum`]: all five exponents of one trajectory
//!   ([`Spectrum`], [`SpectrumOptions`]);
//! - [`FtleDistribution`]: the finite-time exponents of an ensemble as a
//!   distribution: moments, histogram, chaotic fraction at
//!   [`CHAOS_THRESHOLD`] and over [`THRESHOLD_BAND`];
//! - statistics computed one way everywhere: the mergeable
//!   [`Accumulator`], the fixed-bin [`Histogram`], exact order statistics
//!   ([`median`], [`quantile`], ...) and the least-squares [`LinearFit`];
//! - [`PlusMinus`]: a value printed with its error to two significant
//!   digits.
//!
//! # The largest exponent of one trajectory
//!
//! The largest Lyapunov exponent of one trajectory, two ways.
//!
//! - [`Method::FiniteDifference`]: the paper's Benettin method (§II.C). A
//!   shadow trajectory starts `δ0` away in a random 5-D direction; both take
//!   their own next collision, the 5-D separation `δ` is measured, `ln(δ/δ0)`
//!   is added up and the shadow is pulled back to `δ0` along the separation.
//!   Time is the reference trajectory's. This is what the paper's numbers mean.
//! - [`Method::Tangent`]: exact tangent dynamics ([`Billiard::step_tangent`](spinball_core::Billiard::step_tangent)).
//!   No `δ0`, no shadow that can hit a different wall; the growth factors are
//!   multiplied up and their logarithm taken only every so often.
//!
//! Both report the exponent per unit time, `λ = Σ ln(stretch) / Σ Δt`
//! ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#lyapunov-exponents)), and per collision. Over a fixed number of collisions this is
//! the finite-time Lyapunov exponent (FTLE) of the trajectory.
//!
//! # The full spectrum
//!
//! The full Lyapunov spectrum of one trajectory (paper, appendix "Full
//! Lyapunov spectrum").
//!
//! The largest exponent says *whether* a trajectory is chaotic; the whole
//! spectrum says *how*: how many directions expand (one: spin creates no
//! hyperchaos, paper appendix, confirmed here to a few `1e-4`), and whether the numerics respect the
//! symmetries of the dynamics (a volume-preserving, time-reversible flow has a
//! spectrum that sums to zero and comes in `±` pairs). Two methods, both with
//! five vectors in the 5-D state `(x, y, v_x, v_y, u)` and QR
//! re-orthonormalisation (modified Gram–Schmidt, Benettin et al.):
//!
//! - [`Method::Tangent`]: five exact tangent vectors carried by
//!   [`Billiard::step_tangent`](spinball_core::Billiard::step_tangent). These are tangent vectors of the **flow**, and
//!   the spectrum is `(λ, 0, 0, 0, −λ)` up to finite-time error: the flow
//!   direction and the energy direction are neutral, the middle exponent of
//!   the volume-preserving, time-reversible 3-D collision map `(s, v∥, u)` is
//!   zero, and the outer pair is `±λ` ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#full-spectrum)). The 5×5 step Jacobian has
//!   `|det| = 1`, so the sum vanishes to rounding at any run length.
//! - [`Method::FiniteDifference`]: the paper's variant. Five shadow
//!   trajectories start `δ0` from the reference along orthonormal directions
//!   `q_i`; every trajectory takes **its own** next collision; the five
//!   separations are QR-decomposed, `ln(R_ii/δ0)` is accumulated, and the
//!   shadows are reset to `reference + δ0 q_i`. Time is the reference's.
//!
//! How the two spectra differ, and what the finite-difference fifth exponent
//! is, is documented on [`lyapunov_spectrum`].
//!
//! ## Cost
//! The inner loop works on fixed arrays (no allocation, static dispatch); the
//! logarithms of the `R` diagonal are taken only when the running products
//! leave `[1e-150, 1e150]`.
//!
//! # FTLE distributions and the chaotic fraction
//!
//! Distributions of finite-time Lyapunov exponents (FTLE) over an ensemble,
//! and the chaotic fraction.
//!
//! With spin the phase space is mixed (paper §V–VI): most trajectories are
//! chaotic, some sit on regular islands with an FTLE near zero, so the FTLE
//! distribution is bimodal and its mean alone hides what is going on. An
//! [`FtleDistribution`] keeps every per-trajectory exponent (in index order)
//! and answers the paper's questions about it exactly: histogram, mean,
//! median, std, SEM, the conditional mean of the chaotic part, the chaotic
//! fraction `f_ch` at a threshold (paper: FTLE > 0.01) and over a band of
//! thresholds (0.001–0.05), and the Datseris–Hupe–Fleischmann product
//! `λ · f_ch` (paper appendix, DH scaling test).
//!
//! # Statistics
//!
//! Statistics with their errors: a mergeable running [`Accumulator`], a
//! fixed-bin [`Histogram`], and exact order statistics over a slice.
//!
//! Every ensemble number the crate returns carries its standard error, so the
//! statistics live in one place and are computed one way:
//!
//! - [`Accumulator`] keeps count, mean and the sum of squared deviations `M2`
//!   with Welford's update, plus min, max and an optional [`Histogram`]. Two
//!   accumulators merge with Chan's formula, so partial results from threads,
//!   batches or machines can be combined without keeping the samples.
//! - [`median`], [`quantile`], [`conditional_mean`] and [`fraction_above`]
//!   need the samples themselves; they are exact for a given slice.
//!
//! ## Floating-point order
//! Float addition is not associative. Pushing the same values in the same
//! order always gives the same bits, but a Chan merge of `[0, k)` and `[k, n)`
//! agrees with pushing all of `[0, n)` only up to the last few bits. The
//! ensembles of this crate therefore keep the per-trajectory values and push
//! them **in index order**, which is what makes their results bitwise
//! independent of the thread count and of how the index range was split. Use
//! [`Accumulator::merge`] when you cannot keep the samples and a difference in
//! the last bits does not matter.

mod fitted;
mod ftle;
mod lyapunov;
mod plus_minus;
mod significant;
mod spectrum;
mod stats;

pub use fitted::Fitted;
pub use ftle::{CHAOS_THRESHOLD, ChaoticBand, ChaoticFraction, FtleDistribution, THRESHOLD_BAND};
pub use lyapunov::{
    HistoryPoint, Lyapunov, LyapunovOptions, Method, PAPER_DELTA0, largest_lyapunov,
};
pub use plus_minus::PlusMinus;
pub use significant::Significant;
pub(crate) use spectrum::random_frame;
pub use spectrum::{Spectrum, SpectrumOptions, lyapunov_spectrum};
pub use stats::{
    Accumulator, Histogram, LinearFit, conditional_mean, count_above, fraction_above, median,
    quantile, quantiles,
};
