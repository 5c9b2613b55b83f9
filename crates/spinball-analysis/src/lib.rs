//! Chaos indicators for spinning billiards.
#![cfg_attr(docsrs, feature(doc_cfg))]

pub mod diagnostics;
pub mod ensemble;
pub mod error;
pub mod ftle;
pub mod lyapunov;
pub mod parallel;
pub mod result;
pub mod spectrum;
pub mod stats;

#[allow(unused_imports)]
pub use diagnostics::*;
#[allow(unused_imports)]
pub use ensemble::*;
pub use error::AnalysisError;
#[allow(unused_imports)]
pub use ftle::*;
pub use parallel::{Threads, map_indices};
pub use lyapunov::{
    HistoryPoint, Lyapunov, LyapunovOptions, Method, PAPER_DELTA0, largest_lyapunov,
    random_direction,
};
#[allow(unused_imports)]
pub use result::*;
#[allow(unused_imports)]
pub use spectrum::*;
#[allow(unused_imports)]
pub use stats::*;
