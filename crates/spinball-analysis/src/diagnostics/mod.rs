//! Diagnostics: the paper's checks of its mechanism, and its published
//! numbers to hold them against.
//!
//! Built on [`run`](crate::run) and [`precision`](crate::precision), each
//! diagnostic answers one question the paper asks of a table:
//!
//! - how fast do neighbours separate? [`phase_space_separation`]
//!   ([`Separation`], its fit and [`summarize_separation`]: where the growth
//!   saturates);
//! - which walls does the ball hit, and what does `Q` do between them?
//!   [`WallStatistics`] (transition fractions, `|ΔQ|` populations),
//!   [`QPairStatistics`], and the share of collisions on curved walls
//!   ([`curved_share()`]);
//! - how often does it hit a wall? [`CollisionRate`], the exponent per
//!   collision and the Liouville prediction
//!   ([`liouville_collision_rate`]);
//! - is energy conserved over long runs? [`energy_conservation`],
//!   [`energy_trace`];
//! - one trajectory's collisions as columns: [`collision_log()`];
//! - the paper's published values ([`TABLE_I`], [`STADIUM_LAMBDA`], ...),
//!   each with the place it comes from.
//!
//! # Separation of neighbours
//!
//! How fast neighbours separate (paper, phase-space analysis): `⟨ln(δ_n/δ0)⟩`
//! over pairs, per collision, without renormalisation (the paper: 50
//! collisions, 8000 pairs, `δ0 = 1e-7`, a random 5-D direction). Linear
//! growth means exponential divergence (chaos), logarithmic growth means
//! shear (integrable tables). Initial condition `i` comes from its own
//! stream and results combine in index order, so the numbers do not depend
//! on the thread count.
//!
//! # Saturation of the separation
//!
//! Where short-time separation growth stops: the saturation of
//! `⟨ln(δ_n/δ0)⟩` at the size of the table (paper §V.A).
//!
//! Without renormalisation two neighbours of a chaotic table separate like
//! `δ0·e^{λ_c n}` (`λ_c = λ/ν`, the exponent per collision) only until `δ_n`
//! is as large as the table and the state space allow: then
//! `⟨ln(δ_n/δ0)⟩` levels off near `ln(D/δ0)` (`D` a few units: positions
//! differ by up to the table's diameter, velocities by up to 2), about 16 for
//! `δ0 = 1e-7`. The paper argues from λ *per unit time* (`λ ≈ 0.3`,
//! "the separation after 50 collisions is `~1e-7·e^15 ≈ 1e-1`, far from the
//! billiard diameter"); per collision the stadium's exponent is about 0.9 at
//! α = 0, so the plateau is reached after 15–20 collisions and most of the
//! 50-collision window shows saturation, not growth.
//! [`summarize_separation`] measures the plateau, when it is reached, and the
//! slope of the growth before it.
//!
//! # Wall statistics
//!
//! What kind of wall the ball hits and what `Q` does between walls (paper,
//! the mechanism of the conserved quantity and its appendix): wall-transition
//! fractions, the `|ΔQ|` populations by pair class, and the share of
//! collisions on curved walls, as an [`Observer`](spinball_core::Observer) that rides along any run.
//!
//! # Q between collisions
//!
//! `Q` between consecutive collisions, sorted by what the two walls have in
//! common (paper §VI and appendix "Conserved quantity verification").
//!
//! `Q = v∥ − αu` (paper eq. 12) is unchanged *through* every collision, and
//! free flight keeps `v` and `u`, so between collision `k` (after it) and
//! collision `k+1` (before it)
//!
//! ```text
//! ΔQ = Q_{k+1} − Q_k = v·(t̂_{k+1} − t̂_k)
//! ```
//!
//! with `v` the velocity of the flight between them. Three kinds of pairs
//! ([`PairClass`]):
//!
//! - **same wall** (same wall id; possible only on a concave arc, e.g. two
//!   hits in a row on one stadium cap): the chord between two points of a
//!   circle makes equal angles with the tangents at its ends, so
//!   `v·t̂_{k+1} = v·t̂_k` and `ΔQ = 0` up to rounding, about `1e-16`. This
//!   is the circle's angular momentum about the cap centre; it is the
//!   paper's machine-precision "same-wall" population.
//! - **facing walls** (different walls with opposite tangents, e.g. the
//!   stadium's bottom and top flats, whose oriented tangents are `+x̂` and
//!   `−x̂` under `t̂ = (n_y, −n_x)`): `ΔQ = −2 v∥` exactly, an `O(1)` jump.
//!   [`QPairStatistics::facing_residual`] checks `|ΔQ + 2v∥|` at rounding
//!   level. Two consecutive collisions never share an oriented tangent (the
//!   ball leaves wall `k` along `+n̂_k` and must meet wall `k+1` against
//!   `n̂_{k+1}`), so "a run of flat-wall collisions with the same tangent"
//!   does not occur; between the facing flats each collision conserves its
//!   own `Q` (`v_x − αu` at the bottom, `−v_x − αu` at the top), and the two
//!   reflections compose to a rotation of `(v_x, √α u)`: regular, but not by
//!   a conserved `Q`.
//! - **turned** (the tangent line turns: flat ↔ cap, cap → other cap,
//!   adjacent box walls, the Sinai disk): `ΔQ = O(1)`.
//!
//! Unlike [`WallStatistics`], which sorts pairs by
//! tangent alone (same-cap pairs fall among the turned ones there), this
//! observer puts the wall id first, which is what separates the two
//! populations of the paper's figure.
//!
//! # Curved share
//!
//! The share of collisions on curved walls: where the chaos of a billiard
//! comes from, measured over an ensemble and set against the α = 0 theory
//! (each wall's share of the perimeter).
//!
//! # Collision rate
//!
//! How often the ball hits a wall (paper, appendix "Collision rate"):
//! `ν = collisions / time`, the exponent per collision `λ/ν`, their
//! ensemble summaries with errors, and what to expect: the mean speed each
//! sampler draws and the rate of the invariant (Liouville) measure from
//! Santaló's mean free path.
//!
//! # Energy conservation
//!
//! Energy conservation over long runs (paper, appendix "Energy
//! conservation"), and the same measurement for the paper's collision
//! formulas evaluated literally in components.
//!
//! The paper states that energy is conserved "to machine precision (~1e-15)"
//! and shows `|E_n − E_0|` over 5000 collisions. Over that window any sound
//! implementation looks like that; what separates implementations is what
//! happens over 10⁶–10⁷ collisions. [`energy_history`] records the running
//! maximum of `|E_n − E_0|/E_0` at checkpoints `1, 2, 5, 10, 20, …`
//! ([`log_checkpoints`]) for the library's collision map (the half-turn with
//! the energy-shell restore of `spinball_core::Billiard::step`), and
//! [`component_law_energy_history`] does the same for paper eqs. (1)–(3)
//! written out in components with `β, γ, δ` computed in floating point and
//! no restore, a straightforward reading of the paper. The first stays at a
//! few ulps at any length; the second drifts (about linearly: its rounding is
//! biased), which `tests/energy.rs` of `spinball-core` measures at ≈ 7e-11
//! after 10⁶ collisions in the stadium.
//!
//! [`energy_trace`] is the per-collision view (every
//! `|E_n − E_0|`, downsampled by windows) for the short-run figure.
//!
//! # Collision logs
//!
//! One trajectory's collisions as columns of numbers: what a user plots,
//! saves as CSV or NPY, or hands to NumPy.
//!
//! Each row is one collision: the time it happens (from the start), the
//! contact point, the velocity and spin just after it, the wall, the
//! Birkhoff coordinates `s` and `v∥` (the tangential velocity just before
//! it), and `Q = v∥ − αu`, which the collision leaves unchanged (paper
//! eq. 12).
//!
//! # The paper's numbers
//!
//! The paper's published numbers as plain data, each with the place it
//! comes from.
//!
//! Figures, tests and documents compare our results with the paper; this
//! module is the one copy of the numbers they compare with, so a figure
//! cannot quote a value that differs from the one a test checks.
//!
//! "The paper" is J. S. Lund, J. Murugan and J. P. Shock, *Spinning
//! Billiards and Chaos*, arXiv:2505.15335, version 2. Section, figure and
//! table numbers are those of that version (`docs/PHYSICS.md`, "Published
//! numbers", lists them all). Unless stated otherwise the paper uses its own
//! sampler ([`Sampler::Paper`](spinball_core::Sampler::Paper)) and finite
//! differences with δ0 = 1e-7. Values the paper gives as "≈" are stored as
//! printed; exponents are per unit time at E = ½.
//!
//! ```
//! use spinball_analysis::diagnostics::table_i;
//! use spinball_analysis::precision::format_mean_sem;
//!
//! let entry = table_i("stadium:a=1", 0.5, 50_000).unwrap();
//! assert_eq!(format_mean_sem(entry.value, entry.sem, 3), "0.183(1)");
//! ```

mod collision_log;
mod collision_rate;
mod curved_share;
mod energy;
mod paper;
mod q_pairs;
mod saturation;
mod separation;
mod wall_statistics;

pub use collision_log::{COLLISION_COLUMNS, CollisionLog, collision_log};
pub use collision_rate::{
    CollisionRate, RateSummary, collision_rate_summary, initial_mean_speed,
    liouville_collision_rate, per_collision_exponent, rate_summary,
};
pub use curved_share::{CurvedShare, curved_share, perimeter_curved_share};
pub use energy::{
    EnergyCheckpoint, EnergyConservation, EnergyHistory, EnergyPoint, EnergyTrace,
    component_law_energy_history, energy_conservation, energy_history, energy_trace,
    log_checkpoints,
};
pub use paper::{
    INTEGRABLE_LAMBDA_BOUND, SEPARATION_LN_RATIO_50, SINAI_CHAOTIC_FRACTION_ALPHA1,
    SINAI_CURVED_SHARE_BY_RADIUS, SINAI_LAMBDA, SINAI_LAMBDA0_BY_RADIUS,
    STADIUM_CHAOTIC_FRACTION_ALPHA1, STADIUM_LAMBDA, TABLE_I, TABLE_I_COLLISIONS, TABLE_I_DECIMALS,
    TABLE_I_ICS, THRESHOLD_BAND_WIDTH, TableIEntry, table_i,
};
pub use q_pairs::{PairClass, QPair, QPairStatistics, q_pair_statistics};
pub use saturation::{SeparationSummary, summarize_separation};
pub use separation::{Separation, SeparationOptions, phase_space_separation, separation_growth};
pub use wall_statistics::{
    DeltaQPopulation, TransitionFractions, TransitionRule, WallStatistics, wall_statistics,
    wall_statistics_ensemble,
};
