//! The horizon of a table given as a table: the geometry decides whether
//! diffusion can have a finite coefficient, and a horizon that cannot be
//! decided is refused rather than guessed.
//!
//! The geometry's general detection ([`Built::horizon`](spinball_geometry::Built::horizon),
//! any periodic table rebuilt from its shape) decides it.

use spinball_geometry::Boundary;

use super::{Horizon, TransportError};

/// The horizon of a periodic `table`.
///
/// ```
/// use spinball_analysis::transport::{Horizon, horizon_of};
/// use spinball_geometry::LorentzGas;
/// let gas = LorentzGas::triangular(1.0, 0.45)?.table()?;
/// assert_eq!(horizon_of(&gas)?, Horizon::Finite);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`TransportError::NotPeriodic`] for a table without periodic walls;
/// [`TransportError::UnknownHorizon`] for a periodic table without a shape
/// to rebuild it from, or whose horizon the geometry cannot decide.
pub fn horizon_of<B: Boundary + ?Sized>(table: &B) -> Result<Horizon, TransportError> {
    if table.lattice().is_none() {
        return Err(TransportError::NotPeriodic);
    }
    let built = table
        .shape()
        .and_then(|s| s.build().ok())
        .ok_or(TransportError::UnknownHorizon)?;
    built
        .horizon()
        .map(Horizon::from)
        .map_err(|_| TransportError::UnknownHorizon)
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_geometry::{LorentzGas, Stadium};

    #[test]
    fn periodic_tables_have_their_horizon_and_others_are_refused() {
        let sq = LorentzGas::square(1.0, 0.4).unwrap().table().unwrap();
        assert_eq!(horizon_of(&sq), Ok(Horizon::Infinite));
        let tri = LorentzGas::triangular(2.0, 0.9).unwrap().table().unwrap();
        assert_eq!(horizon_of(&tri), Ok(Horizon::Finite));
        let open = LorentzGas::triangular(1.0, 0.4).unwrap().table().unwrap();
        assert_eq!(horizon_of(&open), Ok(Horizon::Infinite));
        assert_eq!(
            horizon_of(&Stadium::new(1.0).unwrap()),
            Err(TransportError::NotPeriodic)
        );
        // A renamed cell is the same geometry: the same horizon.
        assert_eq!(
            horizon_of(&sq.clone().with_name("my cell")),
            Ok(Horizon::Infinite)
        );
    }
}
