//! The dynamics of a spinning billiard ball: the collision law, the collision
//! map over any [`Boundary`], its exact tangent map, observers and seeded
//! initial conditions.
//!
//! A ball of mass 1 carries spin `u = rω`; at every wall the tangential
//! velocity and the spin trade through `α = I/(m r²)` (paper eqs. 1–3, in the
//! half-turn form of [`SpinLaw`]). A [`Billiard`] pairs a table with a law and
//! steps a [`Ball`] from collision to collision, returning a small
//! [`Collision`] record; [`Observer`]s keep what the caller wants.
//!
//! ```
//! use spinball_core::{Billiard, EnergyMonitor, Sampler, SpinLaw};
//! use spinball_geometry::Stadium;
//!
//! let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.4)?);
//! let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 42, 0);
//! let mut ball = billiard.launch(start)?;
//! let mut energy = EnergyMonitor::new(*billiard.law(), &start);
//! let run = billiard.run(&mut ball, 10_000, &mut energy)?;
//! assert_eq!(run.collisions, 10_000);
//! assert!(energy.max_relative_deviation < 1e-15);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Energy
//! The half-turn is orthogonal, so it conserves `|V|² = 2E` up to rounding;
//! a [`Ball`] also remembers its launch shell and each collision pulls `V`
//! back onto it with one Newton step, so the energy error does not accumulate
//! (no linear drift, no random walk) over any number of collisions.
//!
//! # Features
//! - `serde`: `Serialize`/`Deserialize` for the law, states, balls, collisions
//!   and samplers.
#![cfg_attr(docsrs, feature(doc_cfg))]
#![forbid(unsafe_code)]

pub mod billiard;
pub mod collision;
pub mod direction;
pub mod error;
pub mod event;
pub mod observer;
pub mod perturbation;
pub mod sampler;
pub mod spin_law;
pub mod state;
pub mod stuck;
pub mod tangent;
pub mod units;

pub use billiard::{Billiard, Run};
pub use collision::Collision;
pub use direction::random_direction;
pub use error::{LaunchError, NoRoom, PerturbationError, SpinLawError, StepError};
pub use event::{Crossing, Event, Exit};
pub use observer::{EnergyMonitor, Observer, Recorder};
pub use perturbation::{MAX_DELTA0, MIN_DELTA0, Perturbation};
pub use sampler::{PAPER_SHRINK, PAPER_SPIN_FRACTION, Sampler, UnknownSampler, ic_rng};
pub use spin_law::SpinLaw;
pub use state::{Ball, MAX_SPEED, MIN_SPEED, State};
pub use stuck::MAX_ZERO_TIME_RUN;
pub use tangent::{Jacobian, MAX_QR_INTERVAL, TangentFrame, TangentVector, tangent_collision};
pub use units::Units;

pub use rand_pcg::Pcg64;
pub use spinball_geometry::{Boundary, Cell, Hit, WallKind};
