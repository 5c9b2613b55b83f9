//! The finite-difference perturbation, scaled to the table and the ball.
//!
//! The paper's Benettin method puts a shadow `δ0 = 1e-7` away in the five
//! coordinates `(x, y, v_x, v_y, u)`. An absolute `δ0` only means something
//! for the paper's tables (size 1) and energy (speed 1): on a table of size
//! `1e8` it is below the rounding of the coordinates (the separation measured
//! is noise), on one of size `1e-8` it is larger than the table. So the
//! position part is scaled by the table's unit length
//! ([`Boundary::unit_length`]) and the velocity and spin parts by the ball's
//! speed `|V| = √(|v|² + αu²)`, each rounded to the **nearest power of two**:
//!
//! - the paper's tables have unit length 1 and its samplers speed 1 (energy
//!   ½), so both factors are exactly 1 and every published comparison is
//!   bitwise what it was;
//! - a power of two scales exactly, so a table scaled by `2^k` runs the
//!   scaled trajectory and its shadow bit for bit (and any other scale `s`
//!   gets a perturbation within a factor `√2` of `s δ0`, well inside the
//!   plateau where the exponent does not depend on `δ0`).
//!
//! The separation is measured in the same units, `|δ ⊘ units|`, and the
//! shadow is pulled back along it to `δ0` in those units.
//!
//! `δ0` must lie in `[MIN_DELTA0, MAX_DELTA0]`, and the position part must be
//! at least `1e4` ulps of the table's coordinates (an elongated table such as
//! a `1e6 × 1e-6` rectangle cannot resolve it: use the tangent method there).

use spinball_geometry::Boundary;

use crate::error::PerturbationError;
use crate::spin_law::SpinLaw;
use crate::state::State;
use crate::tangent::TangentVector;
use crate::units::Units;

/// Smallest accepted `δ0` (relative to the units): the separation must be
/// at least `2.2e-16 / 1e-11 ≈ 2e-5` above the rounding of the speed.
pub const MIN_DELTA0: f64 = 1e-11;
/// Largest accepted `δ0`: beyond it the shadow is no longer a linear
/// neighbour on the paper's tables (separations saturate at the table size).
pub const MAX_DELTA0: f64 = 1e-3;
/// The position separation must be at least this many ulps of the largest
/// coordinate of the table.
const MIN_ULPS: f64 = 1e4;

/// A finite-difference perturbation for one table and one start. See the
/// [module docs](self).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Perturbation {
    delta0: f64,
    /// `δ0` times the unit of each coordinate.
    scaled: [f64; 5],
    /// The units the separation is measured in.
    units: Units,
}

impl Perturbation {
    /// The perturbation `delta0` for a ball launched in `state` on `table`
    /// under `law`.
    ///
    /// # Errors
    /// [`PerturbationError::OutOfRange`] for `delta0` outside
    /// `[MIN_DELTA0, MAX_DELTA0]` = `[1e-11, 1e-3]` (or not finite),
    /// [`PerturbationError::Unresolved`] if the position part is below
    /// `1e4` ulps of the table's coordinates.
    pub fn new<B: Boundary + ?Sized>(
        table: &B,
        state: &State,
        law: &SpinLaw,
        delta0: f64,
    ) -> Result<Self, PerturbationError> {
        check_delta0(delta0)?;
        let units = Units::new(table, state, law);
        let length = units.units()[0];
        let b = table.aabb();
        let extent = b.min.abs().max(b.max.abs()).max_element();
        let separation = delta0 * length;
        if !(MIN_ULPS * f64::EPSILON * extent <= separation) {
            return Err(PerturbationError::Unresolved { separation, extent });
        }
        Ok(Perturbation {
            delta0,
            scaled: units.units().map(|u| delta0 * u),
            units,
        })
    }

    /// `δ0`, in units.
    #[must_use]
    pub fn delta0(&self) -> f64 {
        self.delta0
    }

    /// `δ0` times the unit of each coordinate `(x, y, v_x, v_y, u)`.
    #[must_use]
    pub fn scaled(&self) -> [f64; 5] {
        self.scaled
    }

    /// `1 / unit` of each coordinate (powers of two).
    #[must_use]
    pub fn inv_units(&self) -> [f64; 5] {
        self.units.inv_units()
    }

    /// The initial shadow offset along the unit 5-vector `direction`:
    /// component `c` is `direction[c] · (δ0 · unit[c])`.
    #[must_use]
    pub fn offset(&self, direction: TangentVector) -> TangentVector {
        let d = direction.to_array();
        TangentVector::from_array(std::array::from_fn(|c| d[c] * self.scaled[c]))
    }

    /// The separation `d` measured in units, `|d ⊘ units|`.
    #[must_use]
    pub fn distance(&self, d: &TangentVector) -> f64 {
        self.units.measure(d)
    }
}

/// Reject `δ0` outside `[MIN_DELTA0, MAX_DELTA0]`.
///
/// # Errors
/// [`PerturbationError::OutOfRange`].
pub fn check_delta0(delta0: f64) -> Result<(), PerturbationError> {
    if (MIN_DELTA0..=MAX_DELTA0).contains(&delta0) {
        Ok(())
    } else {
        Err(PerturbationError::OutOfRange {
            delta0,
            min: MIN_DELTA0,
            max: MAX_DELTA0,
        })
    }
}
