//! The island around a periodic orbit against α: the orbit followed in α,
//! its island measured wherever it is elliptic.
//!
//! Documented in the group docs (`orbits/mod.rs`), section "Islands".

use spinball_geometry::Boundary;

use super::continuation::{Continuation, StabilityChange, follow_in_alpha};
use super::finder::{NewtonOptions, PeriodicOrbit};
use super::island::{IslandOptions, IslandSize, island_around};
use super::stability::StabilityClass;
use crate::error::AnalysisError;

/// The island of one orbit at one α.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct IslandPoint {
    /// The spin parameter.
    pub alpha: f64,
    /// The orbit's stability there.
    pub class: StabilityClass,
    /// The trace of its multiplier pair.
    pub pair_trace: f64,
    /// Island area in `(s, sin θ)`: measured where the orbit is elliptic,
    /// `0` where it is hyperbolic (no island is centred on an unstable
    /// orbit), `None` where it is parabolic or loxodromic (linear stability
    /// does not decide) or the measurement failed (see `failure`).
    pub area: Option<f64>,
    /// Error of `area` (0 where hyperbolic).
    pub error: Option<f64>,
    /// The whole measurement, where there is one.
    pub size: Option<IslandSize>,
    /// Why an elliptic orbit's island was not measured (the error: the
    /// orbit's cell chaotic, or the island unbounded).
    pub failure: Option<String>,
}

/// An orbit followed in α with its island at each α.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct IslandCurve {
    /// The island at each α of the list.
    pub points: Vec<IslandPoint>,
    /// Where the orbit's stability changes ([`follow_in_alpha`]).
    pub changes: Vec<StabilityChange>,
}

impl IslandCurve {
    /// `(α, area, error)` where the area is known, in the order of the list.
    #[must_use]
    pub fn areas(&self) -> Vec<(f64, f64, f64)> {
        self.points
            .iter()
            .filter_map(|p| Some((p.alpha, p.area?, p.error?)))
            .collect()
    }
}

/// The island of one orbit ([`island_around`] where it is elliptic).
///
/// # Errors
/// Bad options, and errors of the runs other than
/// [`AnalysisError::OrbitCellChaotic`] and
/// [`AnalysisError::IslandUnbounded`] (recorded in
/// [`IslandPoint::failure`]).
pub fn island_point<B: Boundary + Sync>(
    table: &B,
    orbit: &PeriodicOrbit,
    options: &IslandOptions,
) -> Result<IslandPoint, AnalysisError> {
    let st = &orbit.stability;
    let mut point = IslandPoint {
        alpha: orbit.alpha,
        class: st.class,
        pair_trace: st.pair_trace,
        area: None,
        error: None,
        size: None,
        failure: None,
    };
    match st.class {
        StabilityClass::Hyperbolic { .. } => {
            point.area = Some(0.0);
            point.error = Some(0.0);
        }
        StabilityClass::Elliptic { .. } => match island_around(table, orbit, options) {
            Ok(island) => {
                point.area = Some(island.size.area);
                point.error = Some(island.size.error);
                point.size = Some(island.size);
            }
            Err(
                e
                @ (AnalysisError::OrbitCellChaotic { .. } | AnalysisError::IslandUnbounded { .. }),
            ) => point.failure = Some(e.to_string()),
            Err(e) => return Err(e),
        },
        StabilityClass::Parabolic { .. } | StabilityClass::Loxodromic { .. } => {}
    }
    Ok(point)
}

/// The island of every orbit of a continuation, in its order.
///
/// # Errors
/// As [`island_point`].
pub fn islands_along<B: Boundary + Sync>(
    table: &B,
    continuation: &Continuation,
    options: &IslandOptions,
) -> Result<Vec<IslandPoint>, AnalysisError> {
    continuation
        .orbits
        .iter()
        .map(|o| island_point(table, o, options))
        .collect()
}

/// Follow `orbit` through `alphas` ([`follow_in_alpha`], stability changes
/// to `precision`) and measure its island at each α ([`island_point`]):
/// the island area against α, zero where the orbit is hyperbolic.
///
/// ```no_run
/// use spinball_analysis::orbits::{IslandOptions, NewtonOptions, SearchOptions, island_sizes, periodic_orbits};
/// use spinball_core::{Billiard, SpinLaw};
/// use spinball_geometry::Sinai;
///
/// let table = Sinai::new(2.0, 1.0)?;
/// let (orbits, _) = periodic_orbits(&Billiard::new(&table, SpinLaw::new(0.0)?), 2, &SearchOptions::default())?;
/// let curve = island_sizes(&table, &orbits[0], &[0.1, 0.3, 0.5], 1e-8, &NewtonOptions::default(), &IslandOptions::default())?;
/// for (alpha, area, error) in curve.areas() {
///     println!("α = {alpha}: island area {area} ± {error}");
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// As [`follow_in_alpha`] (an orbit lost on the way) and [`island_point`].
pub fn island_sizes<B: Boundary + Sync>(
    table: &B,
    orbit: &PeriodicOrbit,
    alphas: &[f64],
    precision: f64,
    newton: &NewtonOptions,
    options: &IslandOptions,
) -> Result<IslandCurve, AnalysisError> {
    let continuation = follow_in_alpha(table, orbit, alphas, precision, newton)?;
    Ok(IslandCurve {
        points: islands_along(table, &continuation, options)?,
        changes: continuation.changes,
    })
}
