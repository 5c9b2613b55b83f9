//! Phase space: where the chaos is, not only how much of it there is.
//!
//! Built on [`run`](crate::run) and [`precision`](crate::precision), this
//! layer looks at the Birkhoff section of a spinning billiard:
//!
//! - the section itself: [`SectionPoint`]s of every collision, a [`Section`]
//!   observer, [`section_points`], [`sections`] and spin slices
//!   ([`spin_slice`], [`state_on_section`]);
//! - the invariant measure ([`InvariantMeasure`], [`SectionBox`]) and return
//!   times against Kac's lemma ([`orbit_returns`], [`kac_comparison`]), a
//!   test of ergodicity without a Lyapunov exponent, whole or in shards
//!   that join bitwise ([`kac_part`], [`KacPart::merge`]);
//! - FTLE maps over a grid of the section ([`ftle_map`], [`FtleMap`],
//!   [`Slice`]), which show the regular islands, computed whole or in
//!   shards that join bitwise ([`ftle_map_part`], [`FtleMapPart::merge`]);
//! - the islands explained: the bouncing-ball island of two facing flats
//!   ([`FacingFlats`], [`pair_rotation`], [`BouncingShare`]), one table seen
//!   three ways ([`island_map`]), and who sits on the islands
//!   ([`trajectory_profiles`], [`compare_classes`]).
//!
//! # The Birkhoff section
//!
//! The Birkhoff section of a spinning billiard: where each collision happens
//! and how the ball arrives, the coordinates in which islands are drawn.
//!
//! Without spin the billiard map lives on the cylinder `(s, sin θ)`: arc
//! length of the contact and the sine of the angle of incidence to the
//! normal (`sin θ = v∥/|v|`). With spin the ball also carries `u`, and the
//! map lives on `(s, v∥, u)` at fixed energy (paper §II.B). A
//! [`SectionPoint`] is that triple at one collision, with the wall and `Q`;
//! a [`Section`] observer turns every collision of a run into one and hands
//! it to a closure, so nothing is stored unless the caller keeps it.
//!
//! The other direction, a ball *at* given section coordinates, is
//! [`state_on_section`]: the wall point at `s`
//! ([`Boundary::hit_at`](spinball_geometry::Boundary::hit_at)) with the outgoing velocity and spin, on the energy
//! shell `E = ½` of the paper's sampler. This is how FTLE maps and the
//! invariant-measure tests put balls on the section.
//!
//! All values are taken **just before** the collision (incoming `v∥`, spin
//! and speed), as in [`CollisionLog`](crate::diagnostics::CollisionLog)'s `v_par` column;
//! the collision itself maps `(v∥, √α u)` by a reflection, so either choice
//! gives the same invariant measure (see
//! [`InvariantMeasure`]).
//!
//! # The invariant measure
//!
//! The invariant measure of the spinning billiard map, and boxes of the
//! section measured with it.
//!
//! ## Derivation
//! Write the state as `(x, V)` with `V = (v_x, v_y, w)`, `w = √α u`, so that
//! `|V|² = 2E`. Free flight moves `x` at constant `V`, and the collision is
//! the half-turn `V' = 2(V·a)a − V` (docs/PHYSICS.md): the flow preserves
//! the Liouville measure `dx dy d³V`, hence on the energy shell `|V| = 1`
//! the measure `dx dy dσ(V)` (σ the area on the unit sphere). The billiard
//! map is the return map of this flow to the wall, and the measure it
//! preserves is the flux of the flow's measure through the wall:
//! `|v⊥| ds dσ(V)` (the standard cross-section construction). Parametrise
//! the outgoing hemisphere `v⊥ > 0` by `(v∥, w)`: `dσ = dv∥ dw / |v⊥|`. The
//! two `|v⊥|` cancel, and the invariant measure of the map is
//!
//! ```text
//!     dμ = ds dv∥ dw   on [0, |∂Q|) × {v∥² + w² < |V|²}
//! ```
//!
//! uniform in arc length and in the disk of `(v∥, √α u)`; total mass
//! `π |∂Q|` at `|V| = 1`. At α = 0 the spin decouples, `w = 0`, and this is
//! the classical `ds dv∥ = cos θ ds dθ` on `[0, |∂Q|) × [−1, 1]` (total
//! `2|∂Q|`). The collision at fixed `s` is a reflection of `(v∥, w)` in a
//! line (docs/PHYSICS.md, half-turn form), so incoming and outgoing
//! coordinates carry the same measure.
//!
//! The measure is tested against the collision map in
//! `tests/phase_space.rs`: samples drawn from it and pushed one collision
//! forward keep their histogram, samples from the hemisphere's area
//! measure do not.
//!
//! # Return times and Kac's lemma
//!
//! Return times to a region of the section, against Kac's lemma: a test of
//! ergodicity that needs no Lyapunov exponent.
//!
//! For a map preserving a probability measure μ, Kac's lemma says the mean
//! return time to a set `A` (in map steps, averaged over `A` with μ) is
//! `1/μ(A)` when the map is ergodic. Along one long orbit of an ergodic map,
//! the mean gap between visits to `A` tends to the same `1/μ(A)` (Birkhoff's
//! theorem applied to the indicator of `A`). So per orbit, on an ergodic
//! table every estimate clusters at `1/μ(A)`; on a mixed phase space the
//! orbits of an island return at their own rate (or never: an island that
//! misses `A`), and the estimates split into groups.
//!
//! μ is the invariant measure of the spinning billiard map,
//! `ds dv∥ d(√α u)` ([`InvariantMeasure`], derived there), and the starts
//! are drawn from it, so the orbits sample phase space as μ weighs it.
//!
//! # FTLE maps
//!
//! FTLE maps: the finite-time Lyapunov exponent of every start on a grid of
//! the section, which shows where the regular islands are.
//!
//! A histogram of FTLEs (paper §V) says *how many* starts are regular; a map
//! says *which*. The grid covers the Birkhoff section at one slice of the
//! spin: columns are the arc length `s` of the start, rows its tangential
//! velocity, and the third coordinate is held fixed,
//! - [`Slice::Spin`]: fixed spin `u`, rows `sin θ = v∥/|v|` in `(−1, 1)`;
//! - [`Slice::Q`]: fixed `Q = v∥ − αu` (the quantity the flat walls
//!   conserve, paper eq. 12), rows `v∥/|V|` in `(−1, 1)`, spin
//!   `u = (v∥ − Q)/α`; cells where that leaves no normal velocity are off
//!   the energy shell and have no exponent.
//!
//! Every start is on the paper's shell `E = ½` ([`state_on_section`]) and is
//! run with the exact tangent method ([`Method::Tangent`](crate::estimators::Method::Tangent)) through an
//! [`Ensemble`](crate::run::Ensemble) over explicit states, hence in vector lanes when the table
//! has a lane form. A cell counts as regular when its FTLE is at most the
//! threshold (the paper's 0.01 per unit time).
//!
//! # The bouncing-ball island
//!
//! The bouncing-ball island of the spinning stadium, explained: between the
//! two flat walls a pair of collisions is a rotation by `4·arctan √α`.
//!
//! ## Derivation
//! Carry the spin as `w = √α u`. A collision at a wall with unit tangent
//! `t̂` is the half-turn `V' = 2(V·a)a − V` of `V = (v, w)` about
//! `a = (t̂, −√α)/√(1+α)` (docs/PHYSICS.md). On the stadium's flats
//! `y = ±1` the tangents are `t̂ = (1, 0)` (bottom, inward normal `+ŷ`) and
//! `(−1, 0)` (top), so `v_y` only changes sign and the pair `(v_x, w)` is
//! mapped by `x ↦ 2(x·â)â − x` with `â ∝ (t̂_x, −√α)`: the **reflection** of
//! the `(v_x, w)` plane in the line along `â`. That line makes the angle
//! `−ψ` with the `v_x` axis on the bottom wall and `+ψ` on the top wall,
//! `ψ = arctan √α`. Two reflections in lines at angle `2ψ` to each other
//! compose to a rotation by twice that angle, so a bottom–top pair of
//! collisions rotates `(v_x, w)` by
//!
//! ```text
//!     Θ = 4 arctan √α        (bottom then top: by +Θ; top then bottom: by −Θ)
//! ```
//!
//! keeping `R = √(v_x² + w²)` and `|v_y| = √(2E − R²)`. Unfolding the
//! reflections (`cos` is even), the `v_x` of the k-th flight after the first
//! flat hit is `R cos(σφ − kΔ)` with `Δ = Θ/2 = 2ψ`, `φ = atan2(w, v_x)`
//! before that hit and `σ = sign v_y`. Each flight between the flats lasts
//! `2/|v_y|`, and the sum of the cosines telescopes
//! (`Σ_{k<n} cos(θ − kΔ) = [sin(θ + Δ/2) − sin(θ + Δ/2 − nΔ)]/(2 sin(Δ/2))`),
//! so the contact points on the flats are
//!
//! ```text
//!     x_n = c − A sin(θ₀ − nΔ),   A = R / (|v_y| sin(Δ/2)) = R √((1+α)/α) / |v_y|
//! ```
//!
//! with `θ₀ = σφ − Δ/2` and the centre `c` fixed by the first hit. The
//! contact points stay in the band `[c − A, c + A]`, and fill it densely
//! when `Δ/2π` is irrational. A ball stays between the flats for ever if and
//! only if every contact lies on a flat, `|x_n| ≤ a`: the band must fit,
//! `|c| + A ≤ a` (exact for irrational `Δ/2π`; for rational ones a
//! sufficient condition). A contact past `|x| = a` lies outside the cap's
//! circle, so the flight there meets the cap first: the ball escapes.
//!
//! At α = 0 (`Δ = 0`) the band is infinite unless `v_x = 0`: only the
//! measure-zero bouncing-ball family of the specular stadium stays. With
//! spin, `A` is finite, so a positive-measure set of starts near the
//! bouncing-ball orbits (small `R = |(v_x, √α u)|`) is trapped: the
//! bouncing-ball island.
//!
//! # Island maps
//!
//! One table at one α seen three ways: its FTLE map on a slice of the
//! section, the paper's sampler run for the same collisions, and, where the
//! table has two facing flats, the bouncing-ball island the rotation
//! `4·arctan √α` predicts ([`FacingFlats`]).
//!
//! The map says where the regular starts are, the sampler how much of the
//! measure they hold (the paper's chaotic fraction), and the prediction why
//! they are regular: a predicted cell should be regular on the map, and a
//! sampler orbit the rotation traps should never be chaotic. Setting the
//! three side by side is what `fig_ftle_map` shows and what the
//! phase-space tests check, so it is computed once, here.
//!
//! # Who sits on the islands
//!
//! Who sits on the regular islands? Regular and chaotic trajectories
//! compared by where they collide and how they start (paper §V).
//!
//! With spin the FTLE distribution is bimodal: a chaotic bulk and a peak near
//! zero. The paper characterises the peak in the stadium at α = 0.5: regular
//! orbits (FTLE < 0.01) have "~88 % of their collisions on the flat walls
//! versus ~37 % for chaotic orbits, and their initial `|v∥|` is on average
//! 2.4× smaller (0.27 vs 0.65)": near-bouncing-ball orbits, for which long
//! runs between the facing flats let `Q` conservation constrain the
//! dynamics.
//!
//! [`trajectory_profile`] re-runs initial condition `i` of an ensemble (same
//! sampler, seed and index, hence the same start as
//! [`trajectory_ftle`](crate::run::trajectory_ftle)) without a shadow and records
//! its share of collisions on curved walls, its initial velocity and the
//! tangential velocity of its first collision. [`compare_classes`] splits
//! profiles by FTLE at a threshold and summarises each class with standard
//! errors.
//!
//! Which "initial `|v∥|`" the paper means is not stated. Two candidates are
//! reported: `|v_x(0)|`, the launch velocity along the direction of the
//! stadium's flat walls (for uniform launch directions its mean is
//! `(2/π)·⟨|v|⟩ ≈ 0.61`), and `|v∥|` at the first collision relative to the
//! wall hit (mean about `½⟨|v|⟩`, the cosine law of first hits).

mod bouncing_ball;
mod ftle_map;
mod ftle_map_shards;
mod invariant_measure;
mod island_map;
mod islands;
mod return_time;
mod return_time_shards;
mod section;

pub use bouncing_ball::{BouncingShare, FacingFlats, FlatBand, pair_rotation};
pub use ftle_map::{FtleMap, FtleMapOptions, Slice, ftle_map};
pub use ftle_map_shards::{FtleMapPart, ftle_map_part};
pub use invariant_measure::{InvariantMeasure, SectionBox};
pub use island_map::{IslandMap, island_map};
pub use islands::{
    ClassComparison, ClassSummary, MeanSem, TrajectoryProfile, compare_classes, trajectory_profile,
    trajectory_profiles,
};
pub use return_time::{
    KacComparison, OrbitReturns, invariant_start, invariant_starts, kac_comparison, orbit_returns,
};
pub use return_time_shards::{KacPart, kac_part};
pub use section::{
    SECTION_COLUMNS, Section, SectionPoint, sampled_sections, section_points, section_rows,
    sections, spin_slice, state_on_section,
};
