//! Periodic orbits of the spinning billiard map and their linear stability:
//! where spin turns an unstable orbit into the centre of an island.
//!
//! FTLE maps ([`phase_space`](crate::phase_space)) show islands of regular
//! motion; the orbits at their centres are periodic orbits whose
//! linearisation is elliptic. This group finds periodic orbits of any
//! period on any table with [`Boundary::hit_at`](spinball_geometry::Boundary::hit_at),
//! says how stable they are, and follows them in α to the value where their
//! stability changes:
//!
//! - [`find_orbit`]: Newton's method from one start ([`NewtonOptions`]);
//! - [`periodic_orbits`]: every orbit reached from [`normal_seeds`] and
//!   [`grid_seeds`], each once ([`SearchOptions`]);
//! - [`Stability`]: monodromy, multipliers, [`StabilityClass`], Greene's
//!   residue;
//! - [`follow_in_alpha`]: continuation in α and the [`StabilityChange`]s;
//! - [`stability_diagram`]: every orbit of a period followed through a list
//!   of α, with flat [`OrbitRow`]s for CSV and JSON;
//! - [`island_around`]: the regular island around an elliptic orbit, its
//!   area with an error and its extent ([`IslandOptions`], [`Island`]), and
//!   [`island_sizes`]: that area against α along a continuation.
//!
//! # The map
//!
//! A point of the section is `z = (s, v∥, u)` **just after** a collision
//! ([`BirkhoffPoint`]; [`phase_space`](crate::phase_space) records points
//! just before, the two are conjugate by the collision, so orbits and
//! multipliers are the same), on the shell `|V|² = |v|² + αu² = 1`. The
//! collision map `F` flies to the next wall and collides. Its Jacobian is
//! exact: three tangent vectors of the flow, one per coordinate (moving the
//! contact by `δs` moves the point by `t̂ δs` and turns the wall's frame,
//! `dn̂/ds = k t̂`; changing `v∥` or `u` changes `v⊥` so as to stay on the
//! shell), are carried by the exact tangent map of
//! [`Billiard::step_tangent`](spinball_core::Billiard::step_tangent) and
//! projected back onto the wall at the end (flown by `δτ = n̂·δx/(n̂·v)`).
//! The flow direction is carried into itself, so projecting once after `p`
//! collisions is the product of the `p` one-step Jacobians.
//!
//! # Structure of the monodromy
//!
//! The billiard map preserves `ds dv∥ d(√α u)` (docs/PHASE_SPACE.md) and
//! each collision reflects `(v∥, √α u)`, so `det M = (−1)^p` for α > 0 and
//! `+1` at α = 0 (the law then leaves `u` alone). The flow is reversible:
//! `(x, V) → (x, −V)` maps orbits to orbits (the half-turn commutes with
//! `V → −V`). On the section its fixed points are the collisions with
//! `Q = v∥ − αu = 0` (there the collision maps `(v∥, √α u)` to minus
//! itself), a surface. An orbit that meets it twice retraces itself; such
//! **symmetric** orbits come in one-parameter families (two surfaces meet
//! in a curve), and along the family the monodromy has the multiplier
//! `σ = sign(det M)`. [`Stability`] divides that multiplier out and
//! classifies the other two, `λ² − Tλ + D = 0` with `D = 1`: **hyperbolic**
//! `|T| > 2`, **elliptic** `|T| < 2` with rotation number
//! `ν = arccos(T/2)/2π`, **parabolic** `T = ±2` within the tolerance
//! ([`DEFAULT_CLASS_TOLERANCE`] = 1e-9 on `T`). Greene's residue is
//! `R = (2 − T)/4`, elliptic for `0 < R < 1`. At α = 0 the spin decouples,
//! `σ = 1` is its direction and the pair is the classical monodromy of
//! `(s, v∥)`.
//!
//! # Newton's method
//!
//! [`find_orbit`] solves `F^p(z) − z = 0` (`s` modulo the perimeter) with
//! the Jacobian `M − I`. On a family `M − I` is singular, so each step is
//! the minimum-norm least-squares solution (singular values below
//! `singular_cutoff` of the largest dropped): it moves to the nearest
//! member. A step that does not reduce the largest residual component is
//! halved (up to 30 times). The orbit is closed when the residual is at
//! most `tolerance` (1e-12 by default, `s` in units of the table's
//! `unit_length`); if not, [`AnalysisError::NotClosed`](crate::AnalysisError::NotClosed) carries the
//! residual reached. An orbit with a near-grazing collision (`|v⊥|/|v|`
//! below `min_cos`) is refused the same way: the map is not smooth there.
//!
//! # Seeds
//!
//! [`normal_seeds`]: an orbit that leaves a wall along its normal
//! (`v∥ = u = 0`, a point with `Q = 0`) and arrives `p/2` collisions later
//! with `Q = 0` is symmetric, hence periodic with period `p`. Scanning the
//! arc length finds these from the geometry alone; for `p = 2` they are
//! the chords normal to the wall at both ends (a stadium's axes, a Sinai
//! table's orbits from the disk to the box along an axis or a diagonal),
//! and since a normal collision creates no spin they are orbits at every α.
//! [`grid_seeds`] add a grid of `(s, sin θ, √α u)`. Newton runs from each
//! seed; an orbit found again (from another start, or at another phase: the
//! points are stored from the smallest `s`) is kept once
//! ([`PeriodicOrbit::same_as`]).
//!
//! # Continuation in α
//!
//! [`follow_in_alpha`] runs Newton at each α of a list from the orbit at the
//! previous one (halving the step when the orbit is lost), then, between
//! neighbours where `T − 2` or `T + 2` changes sign, bisects in α until the
//! bracket is at most twice the requested precision:
//! [`StabilityChange::alpha`] is its middle and [`StabilityChange::error`]
//! its half-width. An α of the list where the orbit is parabolic (`T`
//! within the class tolerance of ±2, as the bouncing ball at α = 0 and 1)
//! is reported as a change there, with error 0.
//!
//! # Stability diagram
//!
//! [`stability_diagram`] finds the orbits at the first α of a list and
//! follows each through the list: the trace or residue of every orbit
//! against α, and the α of each change of stability. An orbit lost on the
//! way (it meets a corner or turns grazing) is listed, not an error.
//!
//! # Islands
//!
//! [`island_around`] measures the island of an elliptic orbit on the slice
//! of the section at the spin `u₀` of one of its points (the point of
//! smallest `s` by default), in the coordinates of an FTLE map:
//! `(s, sin θ)`, `s` in the table's length and `sin θ = v∥/|v|` just after
//! the collision (at `u₀ = 0`, as for the orbits along normals, this is
//! `(s, v∥)`, the invariant measure's own coordinates). A window of
//! `cells × cells` starts centred on the point (the middle cell's start is
//! the orbit itself) is run as an FTLE map; the island is the set of
//! regular cells (FTLE ≤ 0.01 per unit time, the paper's threshold) joined
//! to the middle cell through cells sharing a side. Its area is their
//! count times a cell's area, with the error of the grid: the count of the
//! island's boundary cells (a side on a cell outside) times a cell's area,
//! since the true edge passes through them. The window is refitted until
//! the island fills about half of it: doubled along an axis where the
//! island reaches the window's edge, shrunk where it spans less than a
//! quarter.
//!
//! What is measured is the slice of a three-dimensional island through the
//! orbit's point; regular cells cut off from the middle one (a chain of
//! islands of a resonance around it) are not counted, and chaotic holes
//! inside it are left out. Orbits that stick to the island's edge for the
//! whole run count as regular: the area is an upper estimate by that much,
//! which longer runs reduce.
//!
//! [`island_sizes`] follows an orbit through a list of α
//! ([`follow_in_alpha`]) and measures its island at each: zero where the
//! orbit is hyperbolic, measured where elliptic, `None` where parabolic.

mod birkhoff_map;
mod continuation;
mod diagram;
mod finder;
mod island;
mod island_sizes;
mod matrix;
mod search;
mod stability;

pub use birkhoff_map::BirkhoffPoint;
pub use continuation::{Continuation, StabilityChange, follow_in_alpha, orbit_at};
pub use diagram::{ORBIT_CSV_HEADER, OrbitRow, StabilityDiagram, stability_diagram};
pub use finder::{NewtonOptions, PeriodicOrbit, find_orbit};
pub use island::{Island, IslandOptions, IslandSize, IslandWindow, island_around};
pub use island_sizes::{IslandCurve, IslandPoint, island_point, island_sizes, islands_along};
pub use search::{SearchOptions, grid_seeds, normal_seeds, periodic_orbits};
pub use stability::{DEFAULT_CLASS_TOLERANCE, Multiplier, Stability, StabilityClass};
