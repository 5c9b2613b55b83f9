//! The state of a spinning ball, and a [`Ball`]: a state bound to its energy
//! shell.

use glam::DVec2;
use spinball_geometry::Cell;

use crate::error::LaunchError;
use crate::spin_law::SpinLaw;

/// Smallest speed (`|V|` and `|v|`) a ball may have: with table sizes of at
/// least `1e-60` (`spinball_geometry::error::MIN_LENGTH`) every square the
/// casts form stays above `1e-240`, far from the subnormal range.
pub const MIN_SPEED: f64 = 1e-60;
/// Largest speed a ball may have: with table sizes of at most `1e60` every
/// square the casts form stays below `1e245`, far from overflow.
pub const MAX_SPEED: f64 = 1e60;

/// Position `x`, velocity `v` and spin `u = rω` (the signed surface speed),
/// the five coordinates of paper §II.C. Mass is 1.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct State {
    /// Position `(x, y)`.
    pub position: DVec2,
    /// Velocity `(v_x, v_y)`.
    pub velocity: DVec2,
    /// Spin `u = rω`.
    pub spin: f64,
}

impl State {
    /// A state from its parts.
    pub fn new(position: DVec2, velocity: DVec2, spin: f64) -> Self {
        State {
            position,
            velocity,
            spin,
        }
    }

    /// The five coordinates `(x, y, v_x, v_y, u)`.
    pub fn to_array(&self) -> [f64; 5] {
        [
            self.position.x,
            self.position.y,
            self.velocity.x,
            self.velocity.y,
            self.spin,
        ]
    }

    /// A state from `(x, y, v_x, v_y, u)`.
    pub fn from_array(z: [f64; 5]) -> Self {
        State::new(DVec2::new(z[0], z[1]), DVec2::new(z[2], z[3]), z[4])
    }

    /// Energy `E = ½|v|² + ½ α u²` under `law`.
    pub fn energy(&self, law: &SpinLaw) -> f64 {
        law.energy(self.velocity, self.spin)
    }

    /// Check every component is finite and the ball moves.
    pub fn validate(&self) -> Result<(), LaunchError> {
        for (name, v) in [
            ("position.x", self.position.x),
            ("position.y", self.position.y),
            ("velocity.x", self.velocity.x),
            ("velocity.y", self.velocity.y),
            ("spin", self.spin),
        ] {
            if !v.is_finite() {
                return Err(LaunchError::NonFinite(name));
            }
        }
        if self.velocity == DVec2::ZERO {
            return Err(LaunchError::AtRest);
        }
        Ok(())
    }
}

/// A ball in flight: its [`State`] and the energy shell it was launched on.
///
/// The collision law conserves `|V|² = 2E` exactly, but rounding does not. A
/// ball remembers `1/|V|²` at launch and every collision rescales `V` back onto
/// that shell with one Newton step (`c = 3/2 − ½ |V'|²/|V₀|²`: a multiply-add,
/// no division or square root), so the energy error stays at a few ulps forever
/// instead of random-walking (see `Billiard::step`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Ball {
    pub(crate) state: State,
    pub(crate) inv_shell: f64,
    /// Zero-time collisions in a row just taken (see `StepError::Stuck`).
    pub(crate) zero_run: u32,
    /// The lattice cell of a ball on a periodic table (the origin on any
    /// other table).
    #[cfg_attr(feature = "serde", serde(default))]
    pub(crate) cell: Cell,
}

impl Ball {
    /// A ball in `state` under `law`. This does not check the table (see
    /// `Billiard::launch`, which does); it is what a shadow trajectory a
    /// hair outside a wall uses.
    ///
    /// # Errors
    /// [`LaunchError::NonFinite`], [`LaunchError::AtRest`], and
    /// [`LaunchError::Speed`] for `|V|` or `|v|` outside
    /// `[MIN_SPEED, MAX_SPEED]` = `[1e-60, 1e60]`.
    pub fn new(state: State, law: &SpinLaw) -> Result<Self, LaunchError> {
        state.validate()?;
        let norm2 = law.norm2(state.velocity, state.spin);
        for (what, square) in [
            ("speed |V|", norm2),
            ("translational speed |v|", state.velocity.length_squared()),
        ] {
            let value = square.sqrt();
            if !(MIN_SPEED..=MAX_SPEED).contains(&value) {
                return Err(LaunchError::Speed {
                    what,
                    value,
                    min: MIN_SPEED,
                    max: MAX_SPEED,
                });
            }
        }
        Ok(Ball {
            state,
            inv_shell: 1.0 / norm2,
            zero_run: 0,
            cell: Cell::ORIGIN,
        })
    }

    /// The current state.
    #[inline]
    pub fn state(&self) -> &State {
        &self.state
    }
    /// Position.
    #[inline]
    pub fn position(&self) -> DVec2 {
        self.state.position
    }
    /// Velocity.
    #[inline]
    pub fn velocity(&self) -> DVec2 {
        self.state.velocity
    }
    /// Spin `u`.
    #[inline]
    pub fn spin(&self) -> f64 {
        self.state.spin
    }
    /// The lattice cell the ball is in on a periodic table (integer
    /// coordinates in the table's lattice basis, counted exactly at every
    /// crossing); the origin cell on any other table. See
    /// [`Billiard::unwrapped`](crate::Billiard::unwrapped).
    #[inline]
    pub fn cell(&self) -> Cell {
        self.cell
    }
    /// The energy the ball was launched with.
    pub fn launch_energy(&self) -> f64 {
        0.5 / self.inv_shell
    }
    /// Move the ball in a straight line for `time` (negative runs backwards),
    /// without looking for walls: the free flight of paper §II.C.
    pub fn drift(&mut self, time: f64) {
        self.state.position += self.state.velocity * time;
    }
}
