//! Initial conditions, reproducible one by one.
//!
//! Initial condition `i` of a run with seed `S` is drawn from its own
//! [`Pcg64`] stream ([`ic_rng`]), so an ensemble gives the same numbers
//! whatever the thread count, chunking or sharding.
//!
//! Two samplers ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#initial-conditions), "Initial conditions"):
//! - [`Sampler::Paper`]: the paper's convention, needed to reproduce its
//!   numbers. Energy ½, position uniform in the table shrunk by 0.99 (Sinai:
//!   outside 1.01 R), direction uniform, spin uniform in `±½/√α`, speed
//!   `√(1 − αu²)`. Its speed distribution jumps at α = 0⁺ (|v| = 1 at α = 0,
//!   `|v|² ∈ [¾, 1]` for any α > 0).
//! - [`Sampler::Microcanonical`]: the invariant (Liouville) measure on the
//!   energy shell: position uniform in the table, `V = (v, √α u)` uniform on
//!   the sphere `|V| = 1`. Continuous in α at fixed shape, but at small α it
//!   puts trajectories with little translational energy (slow balls, long
//!   flights) in, which lowers the collision rate and λ per unit time compared
//!   with the paper's sampler.

use std::f64::consts::TAU;
use std::fmt;
use std::str::FromStr;

use glam::DVec2;
use rand::Rng;
use rand_pcg::Pcg64;
use spinball_geometry::Boundary;
use thiserror::Error;

use crate::error::NoRoom;
use crate::spin_law::SpinLaw;
use crate::state::State;

/// The random stream of initial condition `index` of a run with `seed`.
///
/// Seeds the 128-bit PCG state from `seed` (through SplitMix64) and uses
/// `index` as the stream selector, so different indices are independent
/// streams rather than offsets of one.
pub fn ic_rng(seed: u64, index: u64) -> Pcg64 {
    let a = splitmix64(seed);
    let b = splitmix64(a ^ 0x6a09_e667_f3bc_c909);
    Pcg64::new(((a as u128) << 64) | b as u128, index as u128)
}

fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// How initial conditions are drawn. See the [module docs](self).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum Sampler {
    /// The paper's convention (the default: it is what the paper's numbers mean).
    #[default]
    Paper,
    /// The microcanonical (Liouville) measure on the energy shell E = ½.
    Microcanonical,
}

/// Shrink factor of the paper's position draw.
pub const PAPER_SHRINK: f64 = 0.99;
/// Spin range of the paper's draw, as a fraction of `u_max = 1/√α`.
pub const PAPER_SPIN_FRACTION: f64 = 0.5;

impl Sampler {
    /// Draw one state (energy ½) for `table` and `law` from `rng`.
    ///
    /// Order of draws: position (rejection), then direction, then spin.
    ///
    /// # Errors
    /// [`NoRoom`] if no position of
    /// [`MAX_INTERIOR_DRAWS`](spinball_geometry::MAX_INTERIOR_DRAWS) drawn
    /// from the table's bounding box was inside (for the paper sampler:
    /// inside the table shrunk by [`PAPER_SHRINK`], which a ring or a
    /// corridor narrower than 1% of the table's size does not have).
    pub fn try_sample<B: Boundary, R: Rng + ?Sized>(
        &self,
        table: &B,
        law: &SpinLaw,
        rng: &mut R,
    ) -> Result<State, NoRoom> {
        let alpha = law.alpha();
        let shrink = match self {
            Sampler::Paper => PAPER_SHRINK,
            Sampler::Microcanonical => 1.0,
        };
        let position = table
            .try_sample_interior(rng, shrink)
            .ok_or_else(|| self.no_room())?;
        Ok(match self {
            Sampler::Paper => {
                let theta = TAU * rng.random::<f64>();
                let (spin, speed) = if alpha > 0.0 {
                    let u_max = PAPER_SPIN_FRACTION / alpha.sqrt();
                    let u = u_max * (2.0 * rng.random::<f64>() - 1.0);
                    (u, (1.0 - alpha * u * u).sqrt())
                } else {
                    (0.0, 1.0)
                };
                State::new(position, DVec2::from_angle(theta) * speed, spin)
            }
            Sampler::Microcanonical => {
                let phi = TAU * rng.random::<f64>();
                let (z, spin) = if alpha > 0.0 {
                    let z = 2.0 * rng.random::<f64>() - 1.0;
                    (z, z / alpha.sqrt())
                } else {
                    (0.0, 0.0)
                };
                let speed = (1.0 - z * z).sqrt();
                State::new(position, DVec2::from_angle(phi) * speed, spin)
            }
        })
    }

    fn no_room(&self) -> NoRoom {
        let (region, hint) = match self {
            Sampler::Paper => (
                "the table shrunk by 0.99 about its box centre",
                "; the paper sampler needs a region 1% of the table's size deep; try the microcanonical sampler or explicit states",
            ),
            Sampler::Microcanonical => ("the table", "; give explicit states instead"),
        };
        NoRoom {
            sampler: self.name(),
            region,
            draws: spinball_geometry::MAX_INTERIOR_DRAWS,
            hint,
        }
    }

    /// [`try_sample`](Self::try_sample) for a table known to have room (every
    /// built-in table has).
    ///
    /// # Panics
    /// With [`NoRoom`]'s message where `try_sample` returns it.
    #[must_use]
    pub fn sample<B: Boundary, R: Rng + ?Sized>(
        &self,
        table: &B,
        law: &SpinLaw,
        rng: &mut R,
    ) -> State {
        self.try_sample(table, law, rng)
            .unwrap_or_else(|e| panic!("{e}"))
    }

    /// Initial condition `index` of the run with `seed` (from [`ic_rng`]).
    pub fn initial_state<B: Boundary>(
        &self,
        table: &B,
        law: &SpinLaw,
        seed: u64,
        index: u64,
    ) -> State {
        self.sample(table, law, &mut ic_rng(seed, index))
    }

    /// [`initial_state`](Self::initial_state), fallibly.
    ///
    /// # Errors
    /// [`NoRoom`] as [`try_sample`](Self::try_sample).
    pub fn try_initial_state<B: Boundary>(
        &self,
        table: &B,
        law: &SpinLaw,
        seed: u64,
        index: u64,
    ) -> Result<State, NoRoom> {
        self.try_sample(table, law, &mut ic_rng(seed, index))
    }

    /// `paper` or `microcanonical`.
    pub fn name(&self) -> &'static str {
        match self {
            Sampler::Paper => "paper",
            Sampler::Microcanonical => "microcanonical",
        }
    }
}

impl fmt::Display for Sampler {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An unknown sampler name.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("unknown sampler `{0}` (expected paper or microcanonical)")]
pub struct UnknownSampler(pub String);

impl FromStr for Sampler {
    type Err = UnknownSampler;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.trim().to_ascii_lowercase().as_str() {
            "paper" => Ok(Sampler::Paper),
            "microcanonical" | "liouville" => Ok(Sampler::Microcanonical),
            _ => Err(UnknownSampler(s.to_string())),
        }
    }
}
