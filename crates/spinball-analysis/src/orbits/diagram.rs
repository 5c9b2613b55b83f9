//! Every orbit of one period followed through a range of α: the stability
//! diagram, as flat rows for CSV and JSON.
//!
//! Documented in the group docs (`orbits/mod.rs`), section "Stability diagram".

use spinball_core::{Billiard, SpinLaw};
use spinball_geometry::Boundary;

use super::continuation::{Continuation, follow_in_alpha};
use super::finder::PeriodicOrbit;
use super::search::{SearchOptions, periodic_orbits};
use super::stability::StabilityClass;
use crate::error::AnalysisError;

/// The orbits of one period found at the first α of a list, each followed
/// through the list.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct StabilityDiagram {
    /// Collisions per period.
    pub period: u32,
    /// The α of the list.
    pub alphas: Vec<f64>,
    /// The precision asked of each stability change.
    pub precision: f64,
    /// One continuation per orbit found at `alphas[0]` and followed to the end.
    pub branches: Vec<Continuation>,
    /// Seeds from which Newton did not close at `alphas[0]`.
    pub seeds_failed: usize,
    /// Orbits found at `alphas[0]` but lost on the way (where one meets a
    /// corner or turns grazing): the `s` of its first point at `alphas[0]`,
    /// and why (the error, with Newton's residual).
    pub lost: Vec<(f64, String)>,
}

impl StabilityDiagram {
    /// One [`OrbitRow`] per orbit and α, orbit by orbit.
    #[must_use]
    pub fn rows(&self) -> Vec<OrbitRow> {
        self.branches
            .iter()
            .enumerate()
            .flat_map(|(i, b)| b.orbits.iter().map(move |o| OrbitRow::new(i, o)))
            .collect()
    }
}

/// The periodic orbits of `period` collisions at `alphas[0]`
/// ([`periodic_orbits`]), each followed through `alphas` with its
/// stability changes located to `precision` ([`follow_in_alpha`]).
///
/// # Errors
/// As [`periodic_orbits`] and [`follow_in_alpha`] for bad options; an orbit
/// lost on the way is listed in [`StabilityDiagram::lost`], not an error.
pub fn stability_diagram<B: Boundary>(
    table: &B,
    period: u32,
    alphas: &[f64],
    precision: f64,
    search: &SearchOptions,
) -> Result<StabilityDiagram, AnalysisError> {
    let first = *alphas
        .first()
        .ok_or_else(|| AnalysisError::invalid("alphas", "need at least one α"))?;
    let billiard = Billiard::new(table, SpinLaw::extended(first)?);
    let (orbits, seeds_failed) = periodic_orbits(&billiard, period, search)?;
    let mut branches = Vec::with_capacity(orbits.len());
    let mut lost = Vec::new();
    for orbit in &orbits {
        match follow_in_alpha(table, orbit, alphas, precision, &search.newton) {
            Ok(c) => branches.push(c),
            Err(e @ AnalysisError::InvalidOption { .. }) => return Err(e),
            Err(e) => lost.push((orbit.points[0].s, e.to_string())),
        }
    }
    Ok(StabilityDiagram {
        period,
        alphas: alphas.to_vec(),
        precision,
        branches,
        seeds_failed,
        lost,
    })
}

/// The CSV header matching [`OrbitRow::csv_line`].
pub const ORBIT_CSV_HEADER: &str =
    "orbit,alpha,period,s,v_par,spin,walls,class,pair_trace,residue,rotation,multiplier,residual";

/// One orbit at one α, flat.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrbitRow {
    /// Index of the orbit in its diagram.
    pub orbit: usize,
    /// Spin parameter.
    pub alpha: f64,
    /// Collisions per period.
    pub period: u32,
    /// First point (smallest `s`): arc length.
    pub s: f64,
    /// First point: outgoing `v∥`.
    pub v_par: f64,
    /// First point: outgoing spin.
    pub spin: f64,
    /// Walls of the period, from the first point's, joined by `-`.
    pub walls: String,
    /// `hyperbolic`, `elliptic`, `parabolic` or `loxodromic`.
    pub class: String,
    /// Trace `T` of the multiplier pair.
    pub pair_trace: f64,
    /// Greene's residue `(2 − T)/4`.
    pub residue: f64,
    /// Rotation number per period (elliptic and loxodromic; else `None`:
    /// empty in CSV, `null` in JSON).
    pub rotation: Option<f64>,
    /// Largest real multiplier, signed (hyperbolic; else `None`).
    pub multiplier: Option<f64>,
    /// Closing residual.
    pub residual: f64,
}

impl OrbitRow {
    /// The row of `orbit`, number `index` in its diagram.
    #[must_use]
    pub fn new(index: usize, orbit: &PeriodicOrbit) -> Self {
        let st = &orbit.stability;
        let (rotation, multiplier) = match st.class {
            StabilityClass::Elliptic { rotation } | StabilityClass::Loxodromic { rotation, .. } => {
                (Some(rotation), None)
            }
            StabilityClass::Hyperbolic { multiplier } => (None, Some(multiplier)),
            StabilityClass::Parabolic { .. } => (None, None),
        };
        let p = orbit.points[0];
        OrbitRow {
            orbit: index,
            alpha: orbit.alpha,
            period: orbit.period,
            s: p.s,
            v_par: p.v_par,
            spin: p.spin,
            walls: orbit
                .walls
                .iter()
                .map(u32::to_string)
                .collect::<Vec<_>>()
                .join("-"),
            class: st.class.name().to_owned(),
            pair_trace: st.pair_trace,
            residue: st.residue,
            rotation,
            multiplier,
            residual: orbit.residual,
        }
    }

    /// The row as CSV (full precision; an absent value is empty).
    #[must_use]
    pub fn csv_line(&self) -> String {
        let opt = |x: Option<f64>| x.map_or(String::new(), |x| x.to_string());
        format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{}",
            self.orbit,
            self.alpha,
            self.period,
            self.s,
            self.v_par,
            self.spin,
            self.walls,
            self.class,
            self.pair_trace,
            self.residue,
            opt(self.rotation),
            opt(self.multiplier),
            self.residual
        )
    }
}
