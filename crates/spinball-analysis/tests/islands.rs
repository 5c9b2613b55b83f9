//! Islands around elliptic periodic orbits (docs/PHASE_SPACE.md, "Island
//! sizes"): none around a hyperbolic orbit, one as soon as the Sinai axis
//! orbit turns elliptic, the same numbers on any thread count, a grid error
//! that covers the change of resolution, and the stadium's bouncing-ball
//! island against the rotation's prediction.

use spinball_analysis::AnalysisError;
use spinball_analysis::orbits::{
    BirkhoffPoint, IslandOptions, NewtonOptions, PeriodicOrbit, find_orbit, island_around,
    island_sizes,
};
use spinball_analysis::phase_space::FacingFlats;
use spinball_analysis::run::Threads;
use spinball_core::{Billiard, SpinLaw};
use spinball_geometry::{Boundary, Sinai, Stadium};

/// The period-2 orbit leaving the wall along its normal at `s` (for the
/// Sinai table at `s = L`: the middle of the bottom box wall, the orbit up
/// the axis to the disk and back).
fn normal_orbit<B: Boundary>(table: &B, alpha: f64, s: f64) -> PeriodicOrbit {
    let billiard = Billiard::new(table, SpinLaw::new(alpha).unwrap());
    find_orbit(
        &billiard,
        BirkhoffPoint::normal(s),
        2,
        &NewtonOptions::default(),
    )
    .unwrap()
}

fn options() -> IslandOptions {
    IslandOptions::default().with_threads(Threads::Fixed(2))
}

#[test]
fn no_island_below_the_onset_one_just_above() {
    // Sinai L = 2, R = 1: the axis orbit is hyperbolic below α* = 1/5 and
    // elliptic above (closed form in docs/PHASE_SPACE.md).
    let table = Sinai::new(2.0, 1.0).unwrap();
    let below = normal_orbit(&table, 0.1, 2.0);
    match island_around(&table, &below, &options()) {
        Err(AnalysisError::NotElliptic { class, pair_trace }) => {
            assert_eq!(class, "hyperbolic");
            assert!(pair_trace > 2.0);
        }
        other => panic!("{other:?}"),
    }
    let curve = island_sizes(
        &table,
        &below,
        &[0.1, 0.5],
        1e-6,
        &NewtonOptions::default(),
        &options(),
    )
    .unwrap();
    let areas = curve.areas();
    assert_eq!(areas[0], (0.1, 0.0, 0.0));
    let (alpha, area, error) = areas[1];
    assert_eq!(alpha, 0.5);
    // At α = 0.5 the island spans about ±0.5 in s and in sin θ (measured
    // 0.55 ± 0.10 at 41 cells, docs/PHASE_SPACE.md).
    assert!(area > 0.2 && error < 0.5 * area, "{area} ± {error}");
    // The change found on the way is the onset.
    let onset = curve.changes.iter().find(|c| c.crossing == 2.0).unwrap();
    assert!((onset.alpha - 0.2).abs() <= onset.error + 1e-12);
    // The island is symmetric about the orbit (the table is symmetric
    // about its axis, and the reversal maps sin θ to −sin θ at s = L).
    let size = curve.points[1].size.unwrap();
    assert!((size.s_extent[0] + size.s_extent[1] - 4.0).abs() < 1e-12);
    assert!((size.sin_theta_extent[0] + size.sin_theta_extent[1]).abs() < 1e-12);
}

#[test]
fn the_area_is_deterministic_and_its_error_covers_a_finer_grid() {
    let table = Sinai::new(2.0, 1.0).unwrap();
    let orbit = normal_orbit(&table, 0.5, 2.0);
    let a = island_around(&table, &orbit, &options()).unwrap();
    let b = island_around(&table, &orbit, &options().with_threads(Threads::Fixed(1))).unwrap();
    assert_eq!(a, b);
    let fine = island_around(&table, &orbit, &options().with_cells(81)).unwrap();
    let (coarse, fine) = (a.size, fine.size);
    assert!(
        (coarse.area - fine.area).abs() <= coarse.error,
        "41 cells {} ± {}, 81 cells {} ± {}",
        coarse.area,
        coarse.error,
        fine.area,
        fine.error
    );
    assert!(fine.error < coarse.error);
    assert_eq!(a.window.island.iter().filter(|&&x| x).count(), coarse.cells);
}

#[test]
fn the_bouncing_ball_island_matches_the_rotation_on_the_flats() {
    // Stadium a = 1: a start on a flat stays between the flats for ever
    // iff its band of contacts fits on them (docs/PHASE_SPACE.md, "The
    // bouncing-ball island explained"). On the flats the island around the
    // bouncing-ball orbit should be those starts: counted over the
    // window's cells on the bottom flat, the two agree within the island's
    // grid error (its boundary cells).
    let table = Stadium::new(1.0).unwrap();
    let flats = FacingFlats::of(&table);
    for alpha in [0.3, 0.5] {
        let law = SpinLaw::new(alpha).unwrap();
        let orbit = normal_orbit(&table, alpha, 1.0);
        let island = island_around(&table, &orbit, &options()).unwrap();
        let w = &island.window;
        let n = w.cells;
        let ds = (w.s_range[1] - w.s_range[0]) / n as f64;
        let dv = (w.sin_theta_range[1] - w.sin_theta_range[0]) / n as f64;
        let (mut on_flat, mut predicted) = (0, 0);
        for j in 0..n {
            let sin_theta = w.sin_theta_range[0] + (j as f64 + 0.5) * dv;
            for i in 0..n {
                let s = w.s_range[0] + (i as f64 + 0.5) * ds;
                if !(0.0..=2.0).contains(&s) {
                    continue;
                }
                on_flat += usize::from(w.island[j * n + i]);
                predicted += usize::from(flats.trapped_at(&law, s, sin_theta, 0.0));
            }
        }
        let tolerance = island.size.boundary_cells;
        assert!(
            predicted > 100 && on_flat.abs_diff(predicted) <= tolerance,
            "α {alpha}: island {on_flat} cells on the flat, predicted {predicted}, tolerance {tolerance}"
        );
    }
}

#[test]
fn failures_are_typed() {
    let table = Sinai::new(2.0, 1.0).unwrap();
    let orbit = normal_orbit(&table, 0.5, 2.0);
    // A threshold below the orbit's own finite-time exponent (≈ ln t / t).
    let strict = IslandOptions {
        threshold: 1e-9,
        ..options()
    };
    assert!(matches!(
        island_around(&table, &orbit, &strict),
        Err(AnalysisError::OrbitCellChaotic { .. })
    ));
    // One small window, which the island overflows.
    let small = IslandOptions {
        half_width: [0.01, 0.01],
        max_windows: 1,
        ..options()
    };
    match island_around(&table, &orbit, &small) {
        Err(AnalysisError::IslandUnbounded { axis, half_width }) => {
            assert_eq!((axis, half_width), ("s", 0.01 * table.unit_length()));
        }
        other => panic!("{other:?}"),
    }
    for bad in [
        options().with_cells(40),
        options().with_collisions(0),
        IslandOptions {
            point: 2,
            ..options()
        },
    ] {
        assert!(matches!(
            island_around(&table, &orbit, &bad),
            Err(AnalysisError::InvalidOption { .. })
        ));
    }
}
