//! Ensemble kernels for [spinball](https://docs.rs/spinball): many
//! spinning-billiard trajectories in lockstep vector lanes.
//!
//! The paper's numbers are averages over `1e4`–`1e5` trajectories of `1e4`–`5e5`
//! collisions each; speed decides what can be explored on a laptop. A branchy
//! scalar collision step costs 35–60 ns. Here `N` independent trajectories
//! run in lockstep, structure-of-arrays, branch-free (the next wall chosen by
//! compare-and-select), so the vector units and the pipelines overlap their
//! dependency chains; the instruction set (AVX-512, AVX2 or the baseline) is
//! chosen **at run time** ([`Isa`]), so a plain `cargo run --release` gets the
//! fast path.
//!
//! [`LaneBilliard`] runs four kernels on any closed table with a lane form (a
//! [`Shape`](spinball_geometry::Shape): the built-in `Circle`, `Rectangle`,
//! `Stadium`, `Sinai`, and tables built from segments), and a fifth,
//! escape, on tables built from segments with holes:
//!
//! | method | scalar specification | agreement |
//! |---|---|---|
//! | [`trajectories`](LaneBilliard::trajectories) | `Billiard::step` | bitwise (states, times) |
//! | [`lyapunov_fd`](LaneBilliard::lyapunov_fd) | `largest_lyapunov`, `Method::FiniteDifference` | trajectories bitwise; `Σ ln` to `~1e-13` relative |
//! | [`lyapunov_tangent`](LaneBilliard::lyapunov_tangent) | `largest_lyapunov`, `Method::Tangent` | trajectory and tangent map bitwise; `Σ ln` to rounding (see below) |
//! | [`spectrum`](LaneBilliard::spectrum) | `lyapunov_spectrum`, `Method::Tangent` | trajectory, tangent map and Gram–Schmidt bitwise; `Σ ln R_ii` to `~1e-10` relative |
//! | [`escape_times`](LaneBilliard::escape_times) | `Billiard::advance` until a hole or the budget (`OpenEnsemble::escape_times` of `spinball-analysis`) | bitwise (escape time, collisions, exit) |
//!
//! # Open tables
//! A table with holes is built with [`LaneBilliard::new_open`]; only
//! [`escape_times`](LaneBilliard::escape_times) runs it, the other kernels
//! refuse it ([`LanesError::OpenTable`]), as [`LaneBilliard::new`] does.
//! Holes exist only on tables built from segments (`SegmentTable`), so the
//! escape kernel is compiled for that table form alone (three copies, one
//! per instruction set), and a lane whose ball ends is refilled with the
//! next initial condition, so no lane idles while balls remain. Tables
//! with periodic walls run on the scalar path
//! ([`has_escape_lane_form`] is false for them).
//!
//! Because the reference trajectory is **bitwise** the scalar one (same
//! floating-point operations in the same order; no fused multiply-add, no
//! approximate reciprocal), the agreement holds over runs of any length,
//! chaos notwithstanding: only the bookkeeping of the stretch differs (one
//! `ln` at the end instead of one every `1e±150`; tangent vectors rescaled by
//! exact powers of two every 8 collisions instead of normalised every
//! collision), and its rounding does not feed back into the dynamics. For the
//! tangent method the difference is `1e-16` relative on chaotic orbits and
//! grows slowly on regular ones (`≤ 5e-11` after 5000 collisions); a
//! near-grazing collision amplifies any rounding difference by its condition
//! number `~1/(n·v)`. Results are identical on every instruction set and for
//! any lane count, chunking or thread count.
//!
//! ```
//! use spinball_core::{Sampler, SpinLaw, ic_rng, random_direction};
//! use spinball_geometry::Stadium;
//! use spinball_lanes::LaneBilliard;
//!
//! let (table, law) = (Stadium::new(1.0)?, SpinLaw::new(0.5)?);
//! // Initial condition i of seed 7, drawn as the ensembles draw it.
//! let (starts, dirs): (Vec<_>, Vec<_>) = (0..40)
//!     .map(|i| {
//!         let mut rng = ic_rng(7, i);
//!         let start = Sampler::Paper.sample(&table, &law, &mut rng);
//!         (start, random_direction(&mut rng))
//!     })
//!     .unzip();
//! let lanes = LaneBilliard::new(table, law)?;
//! let fd = lanes.lyapunov_fd(&starts, &dirs, 1e-7, 2_000)?;
//! let mean = fd.iter().map(|s| s.exponent()).sum::<f64>() / fd.len() as f64;
//! assert!(mean > 0.1 && mean < 0.3); // λ(0.5) ≈ 0.18 in the paper
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Safety
//! The `unsafe` code is of two kinds, each block with a `// SAFETY:` comment:
//! the calls of the SIMD intrinsics inside the SSE2, AVX2 and AVX-512 lane
//! types, and one call per level into the copy of the kernels compiled with
//! `#[target_feature]` for it. Both rest on the CPU having the features, and
//! the crate holds that fact as a value the compiler tracks: zero-sized
//! proofs made only by `is_x86_feature_detected!` (see [`isa`]), which the
//! entry points take and which must prove what the lane type a kernel runs
//! with needs.
//! SSE2 is used only where the target itself guarantees it (a 32-bit x86
//! target without SSE2 runs portable `f64` lanes at the baseline). The tests
//! run every kernel on every level the CPU has and check it against the
//! scalar path.
//!
//! # Features
//! - `serde`: `Serialize`/`Deserialize` for the outcomes.
#![cfg_attr(docsrs, feature(doc_cfg))]

// The modules form layers, each using only layers below it:
// `isa` (levels, proofs of CPU features) < `error`, `lanes` (lane types) <
// `geom` < `dynamics` < `kernels` (what to run; `outcome` is what they
// return) < `dispatch` (which copy to run) < `billiard` (the public API).
mod billiard;
mod dispatch;
mod dynamics;
mod error;
mod geom;
pub mod isa;
mod kernels;
mod lanes;
mod outcome;
mod paused;

pub use billiard::{CHUNK, LaneBilliard, has_escape_lane_form, has_lane_form};
pub use error::LanesError;
pub use isa::{Isa, IsaError};
pub use outcome::{Escape, Flight, SpectrumStretch, Stretch};
pub use paused::Paused;
