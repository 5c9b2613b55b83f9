//! Precision: what an estimate's error is made of, and what shrinking it
//! costs.
//!
//! An ensemble's SEM is only part of its error. This layer, built on
//! [`run`](crate::run), measures the rest and plans runs against it:
//!
//! - [`Measurement`]: a value with its standard error, with the rules for
//!   ratios and (paired) differences of estimates, and the
//!   Datseris–Hupe–Fleischmann product ([`dhf_product`]);
//! - convergence in run length: running-exponent traces ([`LcnTrace`],
//!   [`lcn_trace`]) and estimates at nested checkpoints
//!   ([`convergence_estimates`]);
//! - the biases: [`FiniteTimeBias`] (fitted `1/T` or `ln T / T` law,
//!   [`BiasRegime`]) and [`MethodBias`] (finite difference against tangent on
//!   the same starts);
//! - [`ErrorBudget`]: SEM, both biases and the total, against a
//!   [`Reference`] value where one is known;
//! - what each budget buys: [`work_precision()`] sets, and a [`Planner`] for
//!   the cheapest run that reaches a target total error.
//!
//! # Values with errors
//!
//! Values with errors: a [`Measurement`] (value ± SEM) with the rules for
//! ratios and differences, and the derived quantities the paper's figures
//! plot from estimates: the Datseris–Hupe–Fleischmann product, λ(α)/λ(α₀),
//! paired differences on common initial conditions.
//!
//! # Convergence
//!
//! Is a finite-time exponent converged? Running-exponent (LCN) traces of one
//! trajectory and ensemble estimates at several run lengths (paper, appendix
//! "Convergence of LCN estimates", its Fig. of LCN traces and Table I).
//!
//! - [`lcn_trace`]: the running exponent `λ(t) = Σ ln(stretch) / t` of one
//!   trajectory, kept at log-spaced collision counts for a log–log plot. On
//!   an integrable table it decays like `ln t / t` (finite differences pick
//!   up the linear shear), on a chaotic one it levels off at `λ`.
//! - [`convergence_estimates`]: the ensemble estimate of `λ` after each of
//!   several collision counts (`10⁴, 5·10⁴, 10⁵, 5·10⁵` in the paper), all
//!   over the **same** initial conditions, so the columns differ only by run
//!   length, not by sampling noise. With the scalar engine every initial
//!   condition is run once, to the largest count, and read at the smaller
//!   ones from its running exponent ([`trajectory_checkpoints`]); that
//!   reading is bitwise the exponent a separate run of that length gives
//!   (same start, same shadow direction, same arithmetic up to that
//!   collision), so the nested run costs what the longest column costs alone.
//!   With the lane engine (the default) each column is its own ensemble run:
//!   it costs the sum of the columns, but the lane kernels are several times
//!   faster per step than one nested scalar run.
//! - [`format_mean_sem`]: the paper's `0.183(1)` notation.
//!
//! # Finite-time bias
//!
//! Finite-time bias: how far the exponent of `T` collisions, `λ_T`, still is
//! from its limit `λ`, measured from the same initial conditions read at
//! nested run lengths.
//!
//! On a chaotic orbit the transient of the first collisions is averaged
//! out like `λ_T − λ ≈ c/T`; on a regular orbit (the islands spin creates,
//! the integrable tables) the running exponent decays like `c ln T / T`
//! towards `λ = 0` (the separation grows linearly, the paper's appendix on
//! convergence). [`FiniteTimeBias::fit`] fits both laws, `λ_T = a + b/T`
//! and `λ_T = a + (b ln T + c)/T` (a regular orbit's separation grows like
//! `c'·T`, so its running exponent is `ln(c'T)/T`), to the ensemble means
//! at the checkpoints and says which one the data are consistent with
//! ([`BiasRegime`]). The log law has one parameter more, so it is preferred
//! only where `1/T` is rejected.
//!
//! The means at the checkpoints come from the **same** initial conditions,
//! so their errors are strongly correlated: the fit is done per initial
//! condition with one common linear estimator (weights from the scatter at
//! each checkpoint), and the uncertainties of `a` (the extrapolated `λ`)
//! and of the bias come from the scatter of the per-IC fits. The goodness
//! of fit compares the residuals of the mean series with the per-IC scatter
//! of the residuals at each checkpoint.
//!
//! # Method bias
//!
//! Method bias: what the finite-difference exponent (the paper's Benettin
//! method with a shadow trajectory at distance `δ0`) differs by from the
//! exact tangent exponent on the **same** initial conditions and directions.
//!
//! Finite differences compare the reference and shadow states after each
//! collision (each leg to its own wall, at its own time), renormalising to
//! `δ0`; tangent dynamics propagates the linearised flow at equal times.
//! The two agree to `O(δ0)` plus rounding `O(ε/δ0)` on a chaotic orbit; on
//! a regular orbit, where the separation grows only linearly, they measure
//! different transients. Pairing trajectory by trajectory removes the
//! spread of the exponents themselves, so the difference is measured far
//! more precisely than either mean ([`paired_difference`]).
//!
//! # Error budget
//!
//! The error budget of an ensemble estimate: statistical error, finite-time
//! bias and method bias, and the total they add up to.
//!
//! The SEM is one of three errors of `λ` and not always the largest:
//! - **statistical**: the SEM over initial conditions, `∝ 1/√N`;
//! - **finite-time bias**: `λ_T − λ`, from the nested checkpoints
//!   ([`FiniteTimeBias`]);
//! - **method bias**: finite differences against exact tangent dynamics
//!   ([`MethodBias`]; zero for the tangent method).
//!
//! The total is `√(SEM² + b_T² + σ_T² + b_m² + σ_m²)`: each bias counted at
//! its estimate and, because an estimate consistent with zero does not
//! show the bias is zero, also at its own uncertainty. Its uncertainty
//! propagates those of the SEM and of both bias estimates.
//!
//! A [`Reference`] is the value errors are measured against: a long
//! exact-tangent ensemble extrapolated in `1/T` (in `ln T / T` where that
//! is the law the checkpoints follow).
//!
//! # Planning a run
//!
//! How long to run, and with which method: the cheapest `(method, N, T)`
//! for a target total error, planned from a short pilot run.
//!
//! A pilot ([`Planner::pilot`]) runs each candidate method on a few initial
//! conditions at nested checkpoints and measures, per method:
//! - the cost of one IC-step (wall time over `N · steps`, on this machine,
//!   with this engine);
//! - the variance of one trajectory's exponent against run length,
//!   `σ²(T) = v_∞ + v_1/T` (chaotic orbits: `σ² ∝ 1/T`; a mixed phase
//!   space keeps a floor `v_∞`, the spread between chaotic and regular
//!   trajectories);
//! - the finite-time bias `b·g(T)` ([`FiniteTimeBias`]);
//! - the method bias `m` against tangent dynamics ([`MethodBias`]), carried
//!   to other run lengths like `ln T / T` (it is a finite-time effect).
//!
//! The predicted total error of `N × T` is then
//! `ε² = σ²(T)/N + (b_eff g(T))² + m_eff(T)²`, each bias counted with its pilot
//! uncertainty (`b_eff² = b² + σ_b²`, as in [`ErrorBudget`]),
//! and [`Planner::plan`] searches run lengths on a log grid for the least
//! predicted wall time `N · T · cost` meeting the target. The planned run
//! comes with a stop rule on total error ([`PlannedRun::stop_rule`]) that
//! stops it once the measured SEM, with the planned bias, meets the target.
//!
//! # Multilevel ensembles
//!
//! With spin the per-trajectory exponents are bimodal (chaotic sea against
//! regular islands) and that spread does not shrink with `T`, so a plain
//! ensemble buys every digit with 100× more full-length trajectories. But
//! which mode a trajectory belongs to is settled after a short run; only
//! the small correction between a short and a long run needs long runs.
//! [`Multilevel`] estimates (Giles' multilevel Monte Carlo)
//! `E[λ_TL] = E[λ_T0] + Σ_l E[λ_Tl − λ_Tl−1]` over geometric run lengths
//! `T_0 < … < T_L`, each correction taken on one trajectory read at two
//! run lengths ([`LevelDraw`]), each level with its own initial conditions
//! ([`LevelSamples`]; level `l`'s stream is `ic_rng(level_seed(seed, l),
//! i)`, so levels are independent and shards of a level merge exactly).
//!
//! A pilot of every level measures the variance `V_l` of its correction
//! and its cost `C_l` (IC-steps, a count, so the allocation and hence the
//! result do not depend on the clock); [`giles_allocation`] gives the
//! initial conditions per level, `N_l ∝ √(V_l/C_l)`, that reach the
//! statistical error left once the biases are counted, and the run tops up
//! until no level needs more. The level means give `λ_T` at every `T_l`
//! at once, with correlated errors (the means share their coarser levels);
//! [`LevelExtrapolation`] fits the finite-time bias laws to them by
//! generalised least squares, which gives the bias at the top level and the
//! extrapolated `λ_∞`. The result, a [`MultilevelEstimate`], carries an
//! [`ErrorBudget`] of `λ_TL` (SEM, finite-time bias, method bias measured
//! by pairing the top level with tangent dynamics, total), the chaotic
//! fraction (classified at `T_0`) and the mean exponent of the chaotic
//! initial conditions, each with its error. The estimator works on any
//! [`LevelSource`]; [`EnsembleLevels`] is the billiard one (any table,
//! both methods, both engines).
//!
//! Multilevel pays where the spread of the exponents has a floor that
//! longer runs do not remove (a mixed phase space, with spin); where the
//! spread falls like `1/T` (uniformly chaotic, α = 0) the corrections are
//! as wide as the runs themselves and a plain ensemble is as cheap.
//! [`Planner::plan_estimator`] predicts both from pilots and picks
//! ([`EstimatorPlan`]: the kind, both plans, and why).
//! [`compare_estimators`] measures both on one scene toward one target,
//! in processor time, in alternating repeats, against an independent
//! reference ([`EstimatorComparison`]: speed-up at equal stated error,
//! pulls, what following the planner cost, and [`TargetPrediction`]s for
//! smaller targets from the measured level variances; [`variance_decay`]
//! is how fast those fall with run length).
//!
//! A campaign of many processes (a SLURM job array) cannot top up
//! adaptively: its tasks never see each other. [`Multilevel::allocate`]
//! fixes the initial conditions per level from a pilot once, when the
//! campaign is written ([`LevelAllocation`]); each task runs its block of
//! every level ([`LevelAllocation::run_shard`]) and [`LevelShard::merge`]
//! joins the blocks into bitwise the estimate of one process running the
//! allocation whole.
//!
//! # Work–precision
//!
//! Work–precision sets: for one scene, what each method and engine buys
//! for each budget of `N` initial conditions × `T` collisions, measured as
//! wall time against the error from a [`Reference`] value.
//!
//! A point's error is `Δ = λ − λ_ref` with its standard error (the point's
//! SEM and the reference's in quadrature). The single number a work–
//! precision chart plots is the root-mean-square error the point stands
//! for, `√(Δ² + SEM²)`: the measured deviation plus the statistical error
//! of a point at that budget, so that a point that happens to land on the
//! reference is not read as infinitely precise.

mod convergence;
mod ensemble_levels;
mod error_budget;
mod estimator_choice;
mod estimator_comparison;
mod finite_time_bias;
mod level_allocation;
mod level_extrapolation;
mod measurement;
mod method_bias;
mod multilevel;
mod multilevel_estimate;
mod planner;
mod work_precision;

pub use convergence::{
    LcnTrace, convergence_estimates, format_mean_sem, lcn_trace, lcn_traces, trajectory_checkpoints,
};
pub use ensemble_levels::{
    EnsembleLevels, SHORTEST_LEVEL, default_levels, level_seed, levels_below,
};
pub use error_budget::{ErrorBudget, Reference};
pub use estimator_choice::{EstimatorKind, EstimatorPlan, MULTILEVEL_MARGIN, MultilevelPlan};
pub use estimator_comparison::{
    EstimatorComparison, EstimatorRun, TargetPrediction, compare_estimators, process_cpu_seconds,
    variance_decay,
};
pub use finite_time_bias::{BiasFit, BiasLaw, BiasRegime, FiniteTimeBias, MIN_CHECKPOINTS};
pub use level_allocation::{LevelAllocation, LevelShard};
pub use level_extrapolation::LevelExtrapolation;
pub use measurement::{Measurement, dhf_product, normalised, paired_difference};
pub use method_bias::MethodBias;
pub use multilevel::{
    LevelDraw, LevelSamples, LevelSource, LevelStats, Multilevel, giles_allocation,
};
pub use multilevel_estimate::MultilevelEstimate;
pub use planner::{MethodPilot, PlannedRun, Planner, VarianceModel};
pub use work_precision::{Budget, WorkPoint, work_precision};
