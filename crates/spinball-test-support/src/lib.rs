//! Helpers shared by the tests of several spinball crates: one copy of each,
//! where the crates' `tests/` directories had one apiece.
//!
//! Unpublished (`publish = false`) and only ever a dev-dependency: nothing
//! here is API. It depends on the crates whose tests use it; Cargo allows
//! that cycle for dev-dependencies, and the integration tests that use it
//! link the same library it does.
//!
//! - [`censored`]: escape samples at the quantiles of a known survival
//!   law, censored at a budget.
//! - [`lanes`]: the tables, laws and starts the lane kernels are held to the
//!   scalar path with (`spinball-lanes/tests/agreement.rs` and
//!   `spinball-analysis/tests/lane_agreement.rs`), and the scalar reference
//!   runs.
//! - [`normal`]: standard normal numbers from a fixed seed, for synthetic
//!   data with known answers.
//! - [`tables`]: independent descriptions of tables (signed distance) and
//!   tables built from segments that several crates test on.

pub mod censored;
pub mod lanes;
pub mod normal;
pub mod tables;

pub use censored::censored_quantiles;
pub use normal::Normal;
pub use tables::{mushroom, segment_sinai, signed_distance};
