//! # spinball
//!
//! Spinning billiards: a ball that carries spin `u = rω` moves freely inside a
//! table and, at every wall, trades tangential velocity for spin through
//! `α = I/(m r²)` (Lund, Murugan & Shock, *Spinning Billiards and Chaos*,
//! eqs. 1–3). spinball gives you the tables (circle, rectangle, Bunimovich
//! stadium, Sinai, and any table you build from segments), the exact collision
//! map and its tangent map, and the chaos indicators (Lyapunov exponents by the
//! paper's finite-difference method and by exact tangent dynamics, FTLE
//! distributions, chaotic fraction, the full spectrum) over reproducible
//! parallel ensembles with error bars.
//!
//! This crate is a facade: it re-exports
//! - [`geometry`] (`spinball-geometry`): the [`Boundary`](geometry::Boundary)
//!   trait and the tables;
//! - [`dynamics`] (`spinball-core`): [`SpinLaw`](dynamics::SpinLaw),
//!   [`Billiard`](dynamics::Billiard), observers, samplers, the tangent map;
//! - [`analysis`] (`spinball-analysis`): Lyapunov exponents, spectra,
//!   FTLE statistics, ensembles, error budgets, phase space and diagnostics,
//!   each in its group ([`analysis::estimators`], [`analysis::run`],
//!   [`analysis::precision`], [`analysis::phase_space`],
//!   [`analysis::diagnostics`], [`analysis::report`]);
//!
//! and a [`prelude`] with the names most programs need.
//!
//! ```
//! use spinball::analysis::estimators::{LyapunovOptions, largest_lyapunov};
//! use spinball::prelude::*;
//!
//! // A solid sphere (α = 2/5) in the Bunimovich stadium with a = 1.
//! let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.4)?);
//! let mut rng = ic_rng(2024, 0); // initial condition 0 of seed 2024
//! let start = Sampler::Paper.sample(billiard.table(), billiard.law(), &mut rng);
//! let lyap = largest_lyapunov(
//!     &billiard,
//!     start,
//!     &LyapunovOptions::new(20_000, Method::Tangent),
//!     &mut rng,
//! )?;
//! assert!(lyap.exponent > 0.0 && lyap.exponent < 0.43); // spin reduces chaos
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Feature flags
//! | feature | what it adds |
//! |---|---|
//! | `serde` | `Serialize`/`Deserialize` for tables, states, collisions and results |
//! | `rayon` | ensembles run on all cores (results stay bitwise identical for any thread count) |
//!
//! # Minimum supported Rust version
//! Rust 1.89 (edition 2024; the lane kernels use AVX-512 intrinsics stabilised in 1.89). Raising it is a minor-version change.
//!
//! # Conventions
//! Every convention (inward normals, `t × n = +z`, curvature signs, Birkhoff
//! arc length, the exponent per unit time) is the paper's, restated in
//! [`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#units-and-conventions); each table's
//! documentation says where its arc length starts.
#![cfg_attr(docsrs, feature(doc_cfg))]
#![forbid(unsafe_code)]

pub use spinball_analysis as analysis;
pub use spinball_core as dynamics;
pub use spinball_geometry as geometry;

/// The names a typical program needs, `use spinball::prelude::*;`: the
/// tables, the spin law and the billiard, the samplers and their seeded
/// streams, and an [`Ensemble`](analysis::run::Ensemble) with what it
/// returns. Everything else is imported from its module, e.g.
/// `spinball::analysis::estimators::largest_lyapunov`.
pub mod prelude {
    #[doc(no_inline)]
    pub use spinball_analysis::AnalysisError;
    #[doc(no_inline)]
    pub use spinball_analysis::estimators::Method;
    #[doc(no_inline)]
    pub use spinball_analysis::run::{Ensemble, LyapunovEstimate, StopRule};
    #[doc(no_inline)]
    pub use spinball_core::{Billiard, Sampler, SpinLaw, State, ic_rng};
    #[doc(no_inline)]
    pub use spinball_geometry::{Boundary, Circle, Rectangle, SegmentTable, Sinai, Stadium, Table};
}
