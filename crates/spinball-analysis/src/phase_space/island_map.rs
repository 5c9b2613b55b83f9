//! One table at one α seen three ways: its FTLE map on a slice of the
//! section, the paper's sampler run for the same collisions, and, where the
//! table has two facing flats, the bouncing-ball island the rotation
//! `4·arctan √α` predicts ([`FacingFlats`]).
//!
//! Documented in the group docs (`phase_space/mod.rs`), section "Island maps".

use std::fmt;

use spinball_core::{Sampler, SpinLaw};
use spinball_geometry::Boundary;

use super::bouncing_ball::{BouncingShare, FacingFlats};
use super::ftle_map::{FtleMap, FtleMapOptions, ftle_map};
use crate::error::AnalysisError;
use crate::estimators::Method;
use crate::run::{Ensemble, LyapunovEstimate};

/// An FTLE map beside the sampler's estimate and the bouncing-ball
/// prediction (see the [module docs](crate::phase_space#island-maps)).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct IslandMap {
    /// The FTLE map.
    pub map: FtleMap,
    /// Row-major like [`FtleMap::exponents`]: the cells whose starts the
    /// rotation predicts trapped between the flats (all `false` without
    /// flats).
    pub predicted: Vec<bool>,
    /// Predicted cells on the energy shell.
    pub predicted_cells: usize,
    /// Of those, the cells the map finds regular.
    pub predicted_regular: usize,
    /// The paper's sampler run with the map's method, collisions, seed and
    /// threads.
    pub sampled: LyapunovEstimate,
    /// The sampler's regular orbits and how many the rotation predicts
    /// (`None` without flats).
    pub bouncing: Option<BouncingShare>,
}

impl IslandMap {
    /// `(regular, of which predicted, chaotic predicted)` sampler orbits;
    /// zeros without flats.
    #[must_use]
    pub fn sampler_counts(&self) -> (u64, u64, u64) {
        self.bouncing.map_or((0, 0, 0), |s| {
            (s.regular, s.regular_trapped, s.chaotic_trapped)
        })
    }
}

/// One line: the map's regular share, the sampler's chaotic fraction, and
/// the predicted cells and orbits.
impl fmt::Display for IslandMap {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (regular, regular_in, chaotic_in) = self.sampler_counts();
        write!(
            f,
            "map regular {:.4}, sampler chaotic {:.4} ± {:.4}, predicted cells {} ({} regular), \
             sampler regular {regular} of which predicted {regular_in}, chaotic predicted {chaotic_in}",
            self.map.regular_fraction(),
            self.sampled.chaotic_fraction,
            self.sampled.chaotic_fraction_sem,
            self.predicted_cells,
            self.predicted_regular,
        )
    }
}

/// The FTLE map of `table` under `law` with `options`, the paper's sampler
/// over `ics` initial conditions (exact tangent method, the map's
/// collisions, seed and threads), and the predictions of `flats` (the
/// table's facing flats, [`FacingFlats::of_table`], or `None`) for both;
/// an orbit or cell is regular at FTLE ≤ `options.threshold`.
///
/// # Errors
/// As [`ftle_map`], and as [`Ensemble::run`] (for example fewer than two
/// initial conditions).
pub fn island_map<B: Boundary + Sync + Clone>(
    table: B,
    law: SpinLaw,
    flats: Option<FacingFlats>,
    options: &FtleMapOptions,
    ics: u64,
) -> Result<IslandMap, AnalysisError> {
    let map = ftle_map(table.clone(), law, options)?;
    let predicted = flats.map_or_else(
        || vec![false; map.exponents.len()],
        |f| f.trapped_cells(&law, &map),
    );
    let (predicted_cells, predicted_regular) = map.regular_among(&predicted);
    let sampled = Ensemble::new(table.clone(), law)
        .with_method(Method::Tangent)
        .with_collisions(options.collisions)
        .with_ics(ics)
        .with_seed(options.seed)
        .with_threads(options.threads)
        .run()?;
    let bouncing = flats.map(|f| {
        f.share(
            &table,
            &law,
            Sampler::Paper,
            options.seed,
            &sampled.trajectories,
            options.threshold,
        )
    });
    Ok(IslandMap {
        map,
        predicted,
        predicted_cells,
        predicted_regular,
        sampled,
        bouncing,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::phase_space::ftle_map::Slice;
    use crate::run::Threads;
    use spinball_geometry::Table;

    fn options() -> FtleMapOptions {
        FtleMapOptions::new(32, 32, Slice::Spin(0.0))
            .with_collisions(1_000)
            .with_seed(5)
            .with_threads(Threads::Fixed(1))
    }

    #[test]
    fn stadium_island_is_predicted_and_regular() {
        let table: Table = "stadium:a=1".parse().unwrap();
        let law = SpinLaw::new(0.5).unwrap();
        let flats = FacingFlats::of_table(&table);
        let island = island_map(table, law, flats, &options(), 200).unwrap();
        // The same map and mask as computed directly.
        let map = ftle_map(table, law, &options()).unwrap();
        assert_eq!(island.map, map);
        assert_eq!(island.predicted, flats.unwrap().trapped_cells(&law, &map));
        // fig_ftle_map at 64² finds 428 predicted cells of 4096 (10 %), all
        // regular; a 32² grid has a quarter as many cells.
        let share = island.predicted_cells as f64 / (32.0 * 32.0);
        assert!((0.05..0.15).contains(&share), "{share}");
        assert_eq!(island.predicted_regular, island.predicted_cells);
        assert_eq!(island.sampled.n_ics, 200);
        let (regular, regular_in, chaotic_in) = island.sampler_counts();
        assert!(regular > 0 && regular_in <= regular && chaotic_in == 0);
        let line = island.to_string();
        assert!(line.starts_with("map regular 0.") && line.contains(" regular), sampler"));
    }

    #[test]
    fn without_flats_nothing_is_predicted() {
        let table: Table = "sinai:L=2,R=1".parse().unwrap();
        let island = island_map(table, SpinLaw::specular(), None, &options(), 50).unwrap();
        assert!(island.predicted.iter().all(|&p| !p));
        assert_eq!((island.predicted_cells, island.predicted_regular), (0, 0));
        assert_eq!(island.bouncing, None);
        assert_eq!(island.sampler_counts(), (0, 0, 0));
        // The specular Sinai table is fully chaotic.
        assert!(island.sampled.chaotic_fraction > 0.95);
        assert!(island_map(table, SpinLaw::specular(), None, &options(), 1).is_err());
    }
}
