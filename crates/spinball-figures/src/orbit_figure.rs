//! Figures of periodic orbits and their islands: orbit markers coloured by
//! stability class over an FTLE map, the window an island was measured in
//! with the island outlined, and island area against α.

use spinball_analysis::orbits::{Island, IslandCurve, PeriodicOrbit, StabilityClass};
use spinball_analysis::phase_space::FtleMap;
use spinball_plot::{Legend, LinePlot, MapPlot, RGBColor, Series, palette};

use crate::measured::ALPHA_LABEL;

/// The colour of a stability class: elliptic white, hyperbolic red,
/// parabolic orange, loxodromic magenta.
#[must_use]
pub fn class_colour(class: &StabilityClass) -> RGBColor {
    match class {
        StabilityClass::Elliptic { .. } => RGBColor(0xFF, 0xFF, 0xFF),
        StabilityClass::Hyperbolic { .. } => RGBColor(0xE0, 0x1A, 0x1A),
        StabilityClass::Parabolic { .. } => RGBColor(0xFF, 0x99, 0x00),
        StabilityClass::Loxodromic { .. } => RGBColor(0xD0, 0x2C, 0xD0),
    }
}

/// One marker per point of every orbit at `(s, sin θ)` (just after the
/// collision, the coordinates of an FTLE map's starts), coloured by the
/// orbit's class.
#[must_use]
pub fn orbit_markers(orbits: &[PeriodicOrbit]) -> Vec<(f64, f64, RGBColor)> {
    orbits
        .iter()
        .flat_map(|o| {
            let colour = class_colour(&o.stability.class);
            o.points
                .iter()
                .map(move |p| (p.s, p.sin_theta(o.alpha), colour))
        })
        .collect()
}

/// The FTLE map `map` of `table` over `[0, ftle_max]` with the points of
/// `orbits` marked by class.
#[must_use]
pub fn orbits_map_panel(
    table: &str,
    map: &FtleMap,
    orbits: &[PeriodicOrbit],
    ftle_max: f64,
) -> MapPlot {
    MapPlot::new((0.0, map.perimeter), (-1.0, 1.0), (0.0, ftle_max))
        .cells(map.options.columns, map.options.rows, map.exponents.clone())
        .markers(orbit_markers(orbits))
        .labels("s", "sin θ")
        .title(format!(
            "{table}, α = {}: white elliptic, red hyperbolic",
            map.alpha
        ))
}

/// The window of `island` over `[0, ftle_max]`, the island outlined and
/// the orbit's point marked, titled with its area.
#[must_use]
pub fn island_window_panel(table: &str, island: &Island, ftle_max: f64) -> MapPlot {
    let (w, size) = (&island.window, &island.size);
    MapPlot::new(
        (w.s_range[0], w.s_range[1]),
        (w.sin_theta_range[0], w.sin_theta_range[1]),
        (0.0, ftle_max),
    )
    .cells(w.cells, w.cells, w.exponents.clone())
    .outline(w.island.clone())
    .markers(vec![(
        size.centre.s,
        size.centre_sin_theta,
        RGBColor(0xFF, 0xFF, 0xFF),
    )])
    .labels("s", "sin θ")
    .title(format!(
        "{table} α = {}: island {:.2e} ± {:.1e}",
        size.alpha, size.area, size.error
    ))
}

/// Island area (± its error) against α for each `(label, curve, onset)`,
/// with a vertical line at each onset (the α where the orbit turns
/// elliptic).
#[must_use]
pub fn island_area_panel(curves: &[(String, IslandCurve, f64)]) -> LinePlot {
    let top = curves
        .iter()
        .flat_map(|(_, c, _)| c.areas())
        .map(|(_, a, e)| a + e)
        .fold(0.0, f64::max)
        .max(1e-6)
        * 1.1;
    let mut plot = LinePlot::new()
        .title("island around the axis orbit (slice u = 0)")
        .x_label(ALPHA_LABEL)
        .y_label("area in (s, sin θ)")
        .y_range(0.0, top)
        .legend(Legend::UpperLeft);
    for (i, (label, curve, onset)) in curves.iter().enumerate() {
        let areas = curve.areas();
        plot = plot
            .series(
                Series::new(label.clone(), areas.iter().map(|&(a, x, _)| (a, x)))
                    .errors(areas.iter().map(|&(_, _, e)| e))
                    .color(palette(i)),
            )
            .series(
                Series::unlabelled([(*onset, 0.0), (*onset, top)])
                    .color(palette(i))
                    .line_only(),
            );
    }
    plot
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_analysis::orbits::{
        BirkhoffPoint, IslandOptions, NewtonOptions, find_orbit, island_sizes,
    };
    use spinball_analysis::run::Threads;
    use spinball_core::{Billiard, SpinLaw};
    use spinball_geometry::Sinai;
    use spinball_plot::Plot;

    #[test]
    fn panels_of_the_sinai_axis_orbit() {
        let table = Sinai::new(2.0, 1.0).unwrap();
        let billiard = Billiard::new(&table, SpinLaw::new(0.1).unwrap());
        let newton = NewtonOptions::default();
        let orbit = find_orbit(&billiard, BirkhoffPoint::normal(2.0), 2, &newton).unwrap();
        // Hyperbolic at α = 0.1: red markers at both points.
        let markers = orbit_markers(std::slice::from_ref(&orbit));
        assert_eq!(markers.len(), 2);
        assert!(
            markers
                .iter()
                .all(|m| m.2 == class_colour(&orbit.stability.class))
        );
        assert_eq!(markers[0].2, RGBColor(0xE0, 0x1A, 0x1A));
        let options = IslandOptions::default()
            .with_cells(11)
            .with_threads(Threads::Fixed(1));
        let curve = island_sizes(&table, &orbit, &[0.1, 0.5], 1e-6, &newton, &options).unwrap();
        assert_eq!(curve.areas()[0], (0.1, 0.0, 0.0));
        let panel = island_area_panel(&[("R = 1".into(), curve, 0.2)]);
        assert!(panel.validate().is_ok());
    }
}
