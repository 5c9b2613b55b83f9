//! Ensembles on open and periodic tables: how long balls take to find a
//! hole, and how far they spread through a lattice.
//!
//! A table with holes or periodic walls
//! ([`WallKind`](spinball_geometry::WallKind)) runs one event at a time
//! ([`Billiard::advance`](spinball_core::Billiard::advance)) on the scalar
//! engine; escape runs on a table built from segments without periodic
//! walls go to the vector lanes instead ([`Engine`](crate::run::Engine),
//! [`OpenEnsemble::engine_used`]), with bitwise the same records.
//! An [`OpenEnsemble`] is the scene (billiard, initial conditions, seed,
//! index range, threads), drawn and split as the λ ensembles of
//! [`run`](crate::run) are: initial condition `i` owns the stream
//! [`ic_rng(seed, i)`](spinball_core::ic_rng), results come back in index
//! order, so every record is bitwise the same on any number of threads and
//! in any split into [`Shard`](crate::run::Shard)s.
//!
//! - [`OpenEnsemble::escape_times`]: per initial condition, when and how it
//!   left through a hole, or that it was still inside at the [`Budget`]
//!   (censored, never dropped): [`EscapeRecord`]s.
//! - [`OpenEnsemble::displacements`]: per initial condition, the unwrapped
//!   displacement at given checkpoint times: [`DisplacementRecord`]s.
//!
//! The records are plain data; survival curves, escape rates and
//! diffusion coefficients are computed from their fields.

mod budget;
mod displacement;
mod escape;
mod scene;

pub use budget::Budget;
pub use displacement::DisplacementRecord;
pub use escape::EscapeRecord;
pub use scene::OpenEnsemble;
