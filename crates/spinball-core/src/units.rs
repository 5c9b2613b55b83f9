//! The units a tangent vector or a separation is measured in.
//!
//! The five coordinates `(x, y, v_x, v_y, u)` have two dimensions: lengths
//! and speeds. A plain 5-D norm mixes them, so on a table of size `1e8` the
//! positions outweigh the velocities and a finite-time exponent depends on
//! the table's scale. Measured in units (positions over the table's unit
//! length, [`Boundary::unit_length`], velocities and spin over the ball's
//! speed `|V| = √(|v|² + αu²)`, each rounded to the nearest power of two,
//! so the division is exact) the same dynamics give the same number at
//! every scale. On the paper's tables (unit length 1, speed 1) every unit
//! is exactly 1.

use spinball_geometry::Boundary;

use crate::spin_law::SpinLaw;
use crate::state::State;
use crate::tangent::TangentVector;

/// Units of the coordinates `(x, y, v_x, v_y, u)` for one table and one
/// start. See the [module docs](self).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Units {
    units: [f64; 5],
}

/// The power of two nearest `x > 0` (on a log scale).
fn nearest_pow2(x: f64) -> f64 {
    2f64.powi(x.log2().round() as i32)
}

impl Units {
    /// The units for a ball launched in `state` on `table` under `law`.
    #[must_use]
    pub fn new<B: Boundary + ?Sized>(table: &B, state: &State, law: &SpinLaw) -> Self {
        let length = nearest_pow2(table.unit_length());
        let speed = nearest_pow2(law.norm2(state.velocity, state.spin).sqrt());
        Units {
            units: [length, length, speed, speed, speed],
        }
    }

    /// The unit of each coordinate (powers of two).
    #[must_use]
    pub fn units(&self) -> [f64; 5] {
        self.units
    }

    /// `1 / unit` of each coordinate (exact: powers of two).
    #[must_use]
    pub fn inv_units(&self) -> [f64; 5] {
        self.units.map(|u| 1.0 / u)
    }

    /// `|v ⊘ units|`: the length of `v` in units.
    #[must_use]
    pub fn measure(&self, v: &TangentVector) -> f64 {
        let (z, inv) = (v.to_array(), self.inv_units());
        TangentVector::from_array(std::array::from_fn(|c| z[c] * inv[c])).norm()
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec2;
    use spinball_geometry::Circle;

    use super::*;

    #[test]
    fn units_are_the_nearest_powers_of_two_of_size_and_speed() {
        let law = SpinLaw::new(0.5).unwrap();
        let table = Circle::new(3.0).unwrap();
        let s = State::new(DVec2::ZERO, DVec2::new(0.3, 0.0), 0.4);
        // |V|² = 0.09 + 0.5 · 0.16 = 0.17, |V| = 0.412: nearest 2^-1.
        let u = Units::new(&table, &s, &law);
        assert_eq!(u.units(), [4.0, 4.0, 0.5, 0.5, 0.5]);
        let v = TangentVector::from_array([4.0, 0.0, 0.0, 0.5, 0.0]);
        assert_eq!(u.measure(&v), 2f64.sqrt());
    }
}
