//! FTLE-map figures of the bouncing-ball island: a panel of the map with
//! the predicted cells outlined, and a CSV row comparing the map, the
//! paper's sampler and the prediction ([`IslandMap`]).

use spinball_analysis::phase_space::{IslandMap, Slice};

use crate::csv::{Csv, optional};
use spinball_plot::MapPlot;

/// The columns of [`island_row`].
pub const ISLAND_COLUMNS: [&str; 13] = [
    "table",
    "alpha",
    "spin",
    "cells",
    "collisions",
    "map_regular_fraction",
    "sampler_chaotic_fraction",
    "sampler_chaotic_fraction_sem",
    "predicted_cells",
    "predicted_cells_regular",
    "sampler_regular",
    "sampler_regular_predicted",
    "sampler_chaotic_predicted",
];

/// Append the row of `island`, a map of `table`, to `csv` (made with
/// [`ISLAND_COLUMNS`]); `spin` is the slice's spin (empty for a slice at
/// fixed `Q`).
pub fn island_row(csv: &mut Csv, table: &str, island: &IslandMap) {
    let (map, sampled) = (&island.map, &island.sampled);
    let spin = match map.options.slice {
        Slice::Spin(u) => Some(u),
        Slice::Q(_) => None,
    };
    let (regular, regular_in, chaotic_in) = island.sampler_counts();
    csv.row(&[
        &table,
        &map.alpha,
        &optional(spin),
        &map.exponents.len(),
        &map.options.collisions,
        &map.regular_fraction(),
        &sampled.chaotic_fraction(),
        &sampled.chaotic_fraction_sem(),
        &island.predicted_cells,
        &island.predicted_regular,
        &regular,
        &regular_in,
        &chaotic_in,
    ]);
}

/// The map of `island` (a map of `table`) coloured over `[0, ftle_max]`,
/// the predicted cells outlined in red, titled with α and the regular
/// share.
#[must_use]
pub fn island_panel(table: &str, island: &IslandMap, ftle_max: f64) -> MapPlot {
    let map = &island.map;
    let row = match map.options.slice {
        Slice::Spin(_) => "sin θ",
        Slice::Q(_) => "v∥/|V|",
    };
    let title = format!(
        "{table} α = {}: regular {:.1} %",
        map.alpha,
        100.0 * map.regular_fraction()
    );
    MapPlot::new((0.0, map.perimeter), (-1.0, 1.0), (0.0, ftle_max))
        .cells(map.options.columns, map.options.rows, map.exponents.clone())
        .outline(island.predicted.clone())
        .labels("s", row)
        .title(title)
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_analysis::phase_space::{FacingFlats, FtleMapOptions, island_map};
    use spinball_analysis::run::Threads;
    use spinball_core::SpinLaw;
    use spinball_geometry::Table;
    use spinball_plot::Plot;

    #[test]
    fn row_and_panel_of_a_stadium_map() {
        let table: Table = "stadium:a=1".parse().unwrap();
        let law = SpinLaw::new(0.5).unwrap();
        let options = FtleMapOptions::new(16, 12, Slice::Spin(0.0))
            .with_collisions(500)
            .with_threads(Threads::Fixed(1));
        let flats = FacingFlats::of_table(&table);
        let island = island_map(table, law, flats, &options, 40).unwrap();
        let mut csv = Csv::new(&ISLAND_COLUMNS);
        island_row(&mut csv, "stadium", &island);
        let row: Vec<&str> = csv.as_str().lines().nth(1).unwrap().split(',').collect();
        assert_eq!(row[..5], ["stadium", "0.5", "0", "192", "500"]);
        assert_eq!(
            row[5].parse::<f64>().unwrap(),
            island.map.regular_fraction()
        );
        assert_eq!(row[8].parse::<usize>().unwrap(), island.predicted_cells);
        assert!(island.predicted_cells > 0);
        let bouncing = island.bouncing.unwrap();
        assert_eq!(row[10].parse::<u64>().unwrap(), bouncing.regular);
        let panel = island_panel("stadium", &island, 0.6);
        assert!(panel.validate().is_ok());
        let q = FtleMapOptions::new(8, 8, Slice::Q(0.3)).with_collisions(200);
        let island = island_map(table, law, None, &q, 4).unwrap();
        let mut csv = Csv::new(&ISLAND_COLUMNS);
        island_row(&mut csv, "stadium", &island);
        assert!(
            csv.as_str()
                .lines()
                .nth(1)
                .unwrap()
                .starts_with("stadium,0.5,,64,200,")
        );
    }
}
