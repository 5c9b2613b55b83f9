//! The horizon of a table given as a table: the geometry decides whether
//! diffusion can have a finite coefficient, and an unknown horizon is
//! refused rather than guessed.
//!
//! Today the horizon is known in closed form for the Lorentz gases
//! ([`LorentzGas::horizon`]): a periodic table is recognised as one when
//! its name is a Lorentz gas's and its walls are that gas's cell, wall for
//! wall. Any other periodic table is refused with
//! [`TransportError::UnknownHorizon`].

use spinball_geometry::{Boundary, LorentzGas};

use super::{Horizon, TransportError};

/// The Lorentz gas whose cell `table` is, if it is one.
fn lorentz_cell<B: Boundary + ?Sized>(table: &B) -> Option<LorentzGas> {
    let shape = table.shape()?;
    let spinball_geometry::Shape::Segments {
        name: Some(name), ..
    } = &shape
    else {
        return None;
    };
    let (lattice, rest) = name.split_once(" Lorentz gas ")?;
    let (w, r) = rest.strip_prefix("w=")?.split_once(",R=")?;
    let (w, r): (f64, f64) = (w.parse().ok()?, r.parse().ok()?);
    let gas = match lattice {
        "square" => LorentzGas::square(w, r).ok()?,
        "triangular" => LorentzGas::triangular(w, r).ok()?,
        _ => return None,
    };
    (gas.table().ok()?.shape() == Some(shape)).then_some(gas)
}

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
/// [`TransportError::UnknownHorizon`] for a periodic table whose horizon is
/// not known (not a Lorentz gas's cell).
pub fn horizon_of<B: Boundary + ?Sized>(table: &B) -> Result<Horizon, TransportError> {
    if table.lattice().is_none() {
        return Err(TransportError::NotPeriodic);
    }
    lorentz_cell(table)
        .map(|gas| gas.horizon().into())
        .ok_or(TransportError::UnknownHorizon)
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_geometry::Stadium;

    #[test]
    fn lorentz_cells_have_their_horizon_and_others_are_refused() {
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
        // The square cell renamed: periodic, horizon not known here.
        let renamed = sq.clone().with_name("my cell");
        assert_eq!(horizon_of(&renamed), Err(TransportError::UnknownHorizon));
        // A name that lies about the walls is not believed.
        let liar = LorentzGas::square(1.0, 0.3)
            .unwrap()
            .table()
            .unwrap()
            .with_name("square Lorentz gas w=1,R=0.4");
        assert_eq!(horizon_of(&liar), Err(TransportError::UnknownHorizon));
    }
}
