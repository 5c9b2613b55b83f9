//! Poincaré-section figures: the points of sampled orbits on `(s, sin θ)`
//! coloured by the spin `u`, as panels, as a 3-D cloud `(s, sin θ, u)`,
//! and as CSV rows.
//!
//! A section figure of every table shares its axes (the whole perimeter
//! along `s`, `sin θ` in `[−1, 1]`, spin over the shell's range), so they
//! are set here once.

use spinball_analysis::phase_space::SectionPoint;

use crate::csv::Csv;
use spinball_plot::{MapPlot, Scatter3d};

/// The columns of [`section_rows`].
pub const SECTION_COLUMNS: [&str; 7] = ["table", "orbit", "s", "sin_theta", "u", "wall", "q"];

/// The largest spin on the paper's shell `|V|² = |v|² + αu² = 1`:
/// `1/√α`, or 1 at α = 0 (where the spin does not move and any range
/// shows it), the range a section's spin colour covers.
#[must_use]
pub fn shell_spin(alpha: f64) -> f64 {
    if alpha > 0.0 { 1.0 / alpha.sqrt() } else { 1.0 }
}

/// Append one row per point of each orbit of `table` to `csv` (made with
/// [`SECTION_COLUMNS`]): the orbit's index, `s`, `sin θ`, `u`, the wall
/// and `Q`.
pub fn section_rows(csv: &mut Csv, table: &str, orbits: &[Vec<SectionPoint>]) {
    for (i, orbit) in orbits.iter().enumerate() {
        for p in orbit {
            csv.row(&[&table, &i, &p.s, &p.sin_theta(), &p.spin, &p.wall, &p.q]);
        }
    }
}

/// A panel of `points` at `(s, sin θ)` coloured by the spin over
/// `[−u_max, u_max]`, for a table of `perimeter`.
#[must_use]
pub fn section_panel<'a>(
    perimeter: f64,
    u_max: f64,
    points: impl IntoIterator<Item = &'a SectionPoint>,
) -> MapPlot {
    let points = points
        .into_iter()
        .map(|p| (p.s, p.sin_theta(), p.spin))
        .collect();
    MapPlot::new((0.0, perimeter), (-1.0, 1.0), (-u_max, u_max))
        .points(points)
        .labels("s", "sin θ")
}

/// The 3-D section `(s, sin θ, u)` of `points`, coloured by `u` over
/// `[−u_max, u_max]`, for a table of `perimeter`.
#[must_use]
pub fn section_cloud<'a>(
    perimeter: f64,
    u_max: f64,
    points: impl IntoIterator<Item = &'a SectionPoint>,
) -> Scatter3d {
    let points = points
        .into_iter()
        .map(|p| ([p.s, p.sin_theta(), p.spin], p.spin))
        .collect();
    let box_ = [(0.0, perimeter), (-1.0, 1.0), (-u_max, u_max)];
    Scatter3d::new(points, box_, (-u_max, u_max)).labels("s", "sin θ", "u")
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_analysis::phase_space::sampled_sections;
    use spinball_analysis::run::Threads;
    use spinball_core::{Billiard, Sampler, SpinLaw};
    use spinball_geometry::{Boundary, Stadium};
    use spinball_plot::Plot;

    #[test]
    fn rows_and_panels_of_sampled_orbits() {
        assert_eq!(shell_spin(0.25), 2.0);
        assert_eq!(shell_spin(0.0), 1.0);
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let orbits =
            sampled_sections(&billiard, Sampler::Paper, 1, 0..2, 30, Threads::Fixed(1)).unwrap();
        let mut csv = Csv::new(&SECTION_COLUMNS);
        section_rows(&mut csv, "stadium", &orbits);
        assert_eq!(csv.rows(), 60);
        let line: Vec<&str> = csv.as_str().lines().nth(32).unwrap().split(',').collect();
        let p = orbits[1][1];
        assert_eq!(line[..2], ["stadium", "1"]);
        assert_eq!(line[2].parse::<f64>().unwrap(), p.s);
        assert_eq!(line[3].parse::<f64>().unwrap(), p.sin_theta());
        assert_eq!(line[6].parse::<f64>().unwrap(), p.q);
        let perimeter = billiard.table().perimeter();
        let panel = section_panel(perimeter, shell_spin(0.5), orbits.iter().flatten());
        let by_hand = MapPlot::new(
            (0.0, perimeter),
            (-1.0, 1.0),
            (-1.0 / 0.5f64.sqrt(), 1.0 / 0.5f64.sqrt()),
        )
        .points(
            orbits
                .iter()
                .flatten()
                .map(|p| (p.s, p.v_par / p.speed, p.spin))
                .collect(),
        )
        .labels("s", "sin θ");
        assert_eq!(panel, by_hand);
        assert!(section_cloud(perimeter, 1.0, &orbits[0]).validate().is_ok());
    }
}
