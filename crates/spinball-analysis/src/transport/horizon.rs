//! The horizon of a periodic table: whether free flights are bounded,
//! which decides the law of diffusion.
//!
//! Documented in the group docs (`transport/mod.rs`) and `docs/TRANSPORT.md`,
//! section "Horizon".

use std::fmt;

/// Whether a periodic table has a longest free flight.
///
/// The geometry decides it (a corridor, a strip of the plane that misses
/// every scatterer, makes the horizon infinite); here it is an input, so
/// that the estimator knows which growth law to fit. A Lorentz gas's
/// [`LorentzGas::horizon`](spinball_geometry::LorentzGas::horizon) (which
/// also names the corridor's direction) converts into it with `.into()`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum Horizon {
    /// Every free flight is shorter than some length: normal diffusion,
    /// `⟨Δr²⟩ ≈ 4Dt`.
    Finite,
    /// Corridors allow flights of any length: marginal (superdiffusive)
    /// growth `⟨Δr²⟩ ≈ 4 D_m t ln t`; there is no finite `D`.
    Infinite,
}

impl fmt::Display for Horizon {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Horizon::Finite => "finite",
            Horizon::Infinite => "infinite",
        })
    }
}

impl From<spinball_geometry::Horizon> for Horizon {
    fn from(h: spinball_geometry::Horizon) -> Self {
        match h {
            spinball_geometry::Horizon::Finite => Horizon::Finite,
            spinball_geometry::Horizon::Infinite { .. } => Horizon::Infinite,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Horizon;
    use spinball_geometry::LorentzGas;

    #[test]
    fn the_lattice_decides_the_growth_law() {
        // Square lattice: corridors along the axes for every R < w/2.
        let square = LorentzGas::square(1.0, 0.4).unwrap();
        assert_eq!(Horizon::from(square.horizon()), Horizon::Infinite);
        // Triangular lattice: finite for √3/4·w ≤ R < w/2 (√3/4 ≈ 0.433).
        let closed = LorentzGas::triangular(1.0, 0.45).unwrap();
        assert_eq!(Horizon::from(closed.horizon()), Horizon::Finite);
        let open = LorentzGas::triangular(1.0, 0.4).unwrap();
        assert_eq!(Horizon::from(open.horizon()), Horizon::Infinite);
    }
}
