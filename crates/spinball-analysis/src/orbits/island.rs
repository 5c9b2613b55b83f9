//! The regular island around an elliptic periodic orbit: its area and
//! extent on the section, measured from an FTLE map of a window centred on
//! the orbit.
//!
//! Documented in the group docs (`orbits/mod.rs`), section "Islands".

use spinball_core::{SpinLaw, State};
use spinball_geometry::Boundary;

use super::birkhoff_map::BirkhoffPoint;
use super::finder::PeriodicOrbit;
use crate::error::AnalysisError;
use crate::estimators::{CHAOS_THRESHOLD, Method};
use crate::phase_space::state_on_section;
use crate::run::{Ensemble, Threads};

/// How to measure an island.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct IslandOptions {
    /// Cells per side of the window (odd, so that the orbit's point is the
    /// centre of the middle cell). Default 41.
    pub cells: usize,
    /// Half-widths of the first window: in `s` (units of the table's
    /// `unit_length`) and in `sin θ`. Default `[0.5, 0.25]`.
    pub half_width: [f64; 2],
    /// Windows tried at most (each refits the window to the island found
    /// in the last). Default 6.
    pub max_windows: u32,
    /// Collisions per cell. Default 2000.
    pub collisions: u64,
    /// Seed of the tangent vectors' directions. Default 0.
    pub seed: u64,
    /// FTLE (per unit time) at or below which a cell is regular. Default
    /// the paper's 0.01.
    pub threshold: f64,
    /// Which point of the orbit the window is centred on. Default 0 (the
    /// point of smallest `s`).
    pub point: usize,
    /// Threads (results do not depend on it).
    pub threads: Threads,
}

impl Default for IslandOptions {
    fn default() -> Self {
        IslandOptions {
            cells: 41,
            half_width: [0.5, 0.25],
            max_windows: 6,
            collisions: 2_000,
            seed: 0,
            threshold: CHAOS_THRESHOLD,
            point: 0,
            threads: Threads::All,
        }
    }
}

impl IslandOptions {
    /// `cells` per side (odd, at least 5).
    #[must_use]
    pub fn with_cells(mut self, cells: usize) -> Self {
        self.cells = cells;
        self
    }
    /// `collisions` per cell.
    #[must_use]
    pub fn with_collisions(mut self, collisions: u64) -> Self {
        self.collisions = collisions;
        self
    }
    /// Seed of the tangent directions.
    #[must_use]
    pub fn with_seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }
    /// Run on `threads`.
    #[must_use]
    pub fn with_threads(mut self, threads: Threads) -> Self {
        self.threads = threads;
        self
    }

    fn validate(&self, orbit: &PeriodicOrbit) -> Result<(), AnalysisError> {
        if self.cells < 5 || self.cells.is_multiple_of(2) || self.cells > 4097 {
            return Err(AnalysisError::invalid(
                "cells",
                format!("must be odd, in [5, 4097], got {}", self.cells),
            ));
        }
        if !self.half_width.iter().all(|h| h.is_finite() && *h > 0.0) {
            return Err(AnalysisError::invalid(
                "half_width",
                format!("must be finite and > 0, got {:?}", self.half_width),
            ));
        }
        if self.max_windows == 0 {
            return Err(AnalysisError::invalid("max_windows", "must be at least 1"));
        }
        if self.collisions == 0 {
            return Err(AnalysisError::invalid("collisions", "must be > 0"));
        }
        if !(self.threshold.is_finite() && self.threshold > 0.0) {
            return Err(AnalysisError::invalid(
                "threshold",
                format!("must be finite and > 0, got {}", self.threshold),
            ));
        }
        if self.point >= orbit.points.len() {
            return Err(AnalysisError::invalid(
                "point",
                format!(
                    "the orbit has {} points (0 to {}), got {}",
                    orbit.points.len(),
                    orbit.points.len() - 1,
                    self.point
                ),
            ));
        }
        Ok(())
    }
}

/// The size of the island around one point of an elliptic orbit, on the
/// slice `u = u₀` (the point's spin) of the section, in the coordinates
/// `(s, sin θ)` of an FTLE map.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct IslandSize {
    /// The spin parameter.
    pub alpha: f64,
    /// The orbit's point the island is centred on.
    pub centre: BirkhoffPoint,
    /// Its `sin θ`.
    pub centre_sin_theta: f64,
    /// Area in `(s, sin θ)` (`s` in the table's own length): the regular
    /// cells connected to the centre's, times the area of a cell.
    pub area: f64,
    /// Error of `area` from the grid: the island's boundary cells (those
    /// with a side on a cell outside it) times the area of a cell.
    pub error: f64,
    /// Cells of the island.
    pub cells: usize,
    /// Of those, on its boundary.
    pub boundary_cells: usize,
    /// Area of one cell.
    pub cell_area: f64,
    /// Extent in `s`: the edges of the outermost island cells, `s` of the
    /// window (may pass below 0 or above the perimeter).
    pub s_extent: [f64; 2],
    /// Extent in `sin θ`.
    pub sin_theta_extent: [f64; 2],
    /// Windows run before this one fitted.
    pub windows: u32,
}

impl IslandSize {
    /// The relative error `error / area`.
    #[must_use]
    pub fn relative_error(&self) -> f64 {
        self.error / self.area
    }
}

/// The last window of an island measurement: its FTLE map and which of its
/// cells are the island.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct IslandWindow {
    /// Cells per side.
    pub cells: usize,
    /// `s` range of the window.
    pub s_range: [f64; 2],
    /// `sin θ` range of the window.
    pub sin_theta_range: [f64; 2],
    /// The spin of the slice.
    pub spin: f64,
    /// Row-major (row 0 at the smallest `sin θ`): the FTLE of each cell,
    /// `None` off the energy shell (`|sin θ| ≥ 1`).
    pub exponents: Vec<Option<f64>>,
    /// Row-major: the island's cells.
    pub island: Vec<bool>,
    /// The threshold used.
    pub threshold: f64,
}

/// An island: its size and the window it was measured in.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Island {
    /// Area, error, extent.
    pub size: IslandSize,
    /// The last window.
    pub window: IslandWindow,
}

/// The island around the elliptic periodic orbit `orbit` of `table` (at
/// the orbit's α), on the slice of the section at the spin of the orbit's
/// point `options.point`, in `(s, sin θ)`.
///
/// A window of `cells × cells` starts centred on the point is run for
/// `collisions` collisions each (exact tangent method, as an FTLE map);
/// the island is the set of cells with FTLE ≤ `threshold` joined to the
/// centre cell through cells sharing a side (a flood fill). The window is
/// then refitted: doubled along an axis where the island reaches its edge,
/// shrunk to twice the island's extent along an axis where the island
/// spans less than a quarter of it, until it fits (at most `max_windows`
/// windows; the last one that does not reach its edge is kept).
///
/// # Errors
/// [`AnalysisError::NotElliptic`] if the orbit is not elliptic;
/// [`AnalysisError::OrbitCellChaotic`] if the centre cell's FTLE is above
/// the threshold; [`AnalysisError::IslandUnbounded`] if the island still
/// reaches the edge of the largest window (the whole perimeter in `s`, or
/// the last window tried); [`AnalysisError::InvalidOption`] for bad
/// options; a step error of a cell's run.
pub fn island_around<B: Boundary + Sync>(
    table: &B,
    orbit: &PeriodicOrbit,
    options: &IslandOptions,
) -> Result<Island, AnalysisError> {
    options.validate(orbit)?;
    if !orbit.stability.class.is_elliptic() {
        return Err(AnalysisError::NotElliptic {
            class: orbit.stability.class.name(),
            pair_trace: orbit.stability.pair_trace,
        });
    }
    let law = SpinLaw::extended(orbit.alpha)?;
    let centre = orbit.points[options.point];
    let sin0 = centre.sin_theta(orbit.alpha);
    let perimeter = table.perimeter();
    let unit = table.unit_length();
    // Largest half-widths: the whole perimeter, all of (−1, 1).
    let max_half = [0.5 * perimeter, 1.0 + sin0.abs()];
    let mut half = [
        (options.half_width[0] * unit).min(max_half[0]),
        options.half_width[1].min(max_half[1]),
    ];
    let mut last_fit: Option<Island> = None;
    for window in 0..options.max_windows {
        let measured = measure(table, &law, centre, half, options)?;
        let reach = measured.reach;
        let n = options.cells as f64;
        let mut next = half;
        let mut at_edge = false;
        for axis in 0..2 {
            if reach[axis].edge {
                at_edge = true;
                if half[axis] >= max_half[axis] {
                    return Err(AnalysisError::IslandUnbounded {
                        axis: AXES[axis],
                        half_width: half[axis],
                    });
                }
                next[axis] = (2.0 * half[axis]).min(max_half[axis]);
            } else {
                // The island's half-extent in cells, from the centre.
                let k = reach[axis].cells as f64 + 0.5;
                if k < 0.125 * n {
                    next[axis] = half[axis] * 4.0 * k / n;
                }
            }
        }
        if !at_edge {
            let island = measured.into_island(window);
            if next == half {
                return Ok(island);
            }
            last_fit = Some(island);
        }
        if at_edge && window + 1 == options.max_windows && last_fit.is_none() {
            let axis = usize::from(!reach[0].edge);
            return Err(AnalysisError::IslandUnbounded {
                axis: AXES[axis],
                half_width: half[axis],
            });
        }
        half = next;
    }
    last_fit.ok_or(AnalysisError::invalid("max_windows", "must be at least 1"))
}

/// Names of the two axes of a window.
const AXES: [&str; 2] = ["s", "sin θ"];

/// How far an island reaches from the centre cell along one axis.
#[derive(Debug, Clone, Copy)]
struct Reach {
    /// Largest `|i − centre|` of an island cell along the axis.
    cells: usize,
    /// Whether an island cell is on the window's edge along the axis
    /// (off-shell cells do not count as edge).
    edge: bool,
}

/// One window run and its island.
struct Measured {
    size: IslandSize,
    window: IslandWindow,
    reach: [Reach; 2],
}

impl Measured {
    fn into_island(self, windows: u32) -> Island {
        Island {
            size: IslandSize {
                windows,
                ..self.size
            },
            window: self.window,
        }
    }
}

/// Run the window of half-widths `half` around `centre` and flood-fill the
/// island from its centre cell.
fn measure<B: Boundary + Sync>(
    table: &B,
    law: &SpinLaw,
    centre: BirkhoffPoint,
    half: [f64; 2],
    options: &IslandOptions,
) -> Result<Measured, AnalysisError> {
    let alpha = law.alpha();
    let n = options.cells;
    let c = n / 2;
    let perimeter = table.perimeter();
    let sin0 = centre.sin_theta(alpha);
    let speed = (1.0 - alpha * centre.spin * centre.spin).sqrt();
    let (ds, dv) = (2.0 * half[0] / n as f64, 2.0 * half[1] / n as f64);
    let s_of = |i: usize| centre.s + (i as f64 - c as f64) * ds;
    let sin_of = |j: usize| sin0 + (j as f64 - c as f64) * dv;
    let mut starts: Vec<State> = Vec::new();
    let mut cell_of = Vec::new();
    for j in 0..n {
        let sin_theta = sin_of(j);
        if sin_theta.abs() >= 1.0 {
            continue;
        }
        for i in 0..n {
            let s = s_of(i).rem_euclid(perimeter);
            starts.push(state_on_section(
                table,
                law,
                s,
                sin_theta * speed,
                centre.spin,
            )?);
            cell_of.push(j * n + i);
        }
    }
    let stats = Ensemble::from_states(table, *law, starts)
        .with_method(Method::Tangent)
        .with_collisions(options.collisions)
        .with_seed(options.seed)
        .with_threads(options.threads)
        .trajectories(0..cell_of.len() as u64)?;
    let mut exponents = vec![None; n * n];
    for t in stats {
        exponents[cell_of[t.index as usize]] = Some(t.exponent);
    }
    let regular = |k: usize| exponents[k].is_some_and(|x| x <= options.threshold);
    let middle = c * n + c;
    if !regular(middle) {
        return Err(AnalysisError::OrbitCellChaotic {
            ftle: exponents[middle].unwrap_or(f64::NAN),
            threshold: options.threshold,
        });
    }
    let island = flood_fill(n, middle, regular);
    let (mut count, mut boundary) = (0, 0);
    let mut reach = [Reach {
        cells: 0,
        edge: false,
    }; 2];
    let (mut lo, mut hi) = ([usize::MAX; 2], [0usize; 2]);
    for (k, _) in island.iter().enumerate().filter(|(_, x)| **x) {
        let (i, j) = (k % n, k / n);
        count += 1;
        let inside = |di: isize, dj: isize| {
            let (a, b) = (i as isize + di, j as isize + dj);
            (0..n as isize).contains(&a)
                && (0..n as isize).contains(&b)
                && island[b as usize * n + a as usize]
        };
        if !(inside(-1, 0) && inside(1, 0) && inside(0, -1) && inside(0, 1)) {
            boundary += 1;
        }
        for (axis, x) in [i, j].into_iter().enumerate() {
            reach[axis].cells = reach[axis].cells.max(x.abs_diff(c));
            lo[axis] = lo[axis].min(x);
            hi[axis] = hi[axis].max(x);
        }
        // The window's edge, where the shell continues past it.
        reach[0].edge |= i == 0 || i == n - 1;
        let beyond = |jj: f64| (sin0 + (jj - c as f64) * dv).abs() < 1.0;
        reach[1].edge |= (j == 0 && beyond(-1.0)) || (j == n - 1 && beyond(n as f64));
    }
    let cell_area = ds * dv;
    let edge = |x: usize, d: f64, at: f64| at + (x as f64 - c as f64 - 0.5) * d;
    let size = IslandSize {
        alpha,
        centre,
        centre_sin_theta: sin0,
        area: count as f64 * cell_area,
        error: boundary as f64 * cell_area,
        cells: count,
        boundary_cells: boundary,
        cell_area,
        s_extent: [edge(lo[0], ds, centre.s), edge(hi[0] + 1, ds, centre.s)],
        sin_theta_extent: [edge(lo[1], dv, sin0), edge(hi[1] + 1, dv, sin0)],
        windows: 0,
    };
    let window = IslandWindow {
        cells: n,
        s_range: [s_of(0) - 0.5 * ds, s_of(n - 1) + 0.5 * ds],
        sin_theta_range: [sin_of(0) - 0.5 * dv, sin_of(n - 1) + 0.5 * dv],
        spin: centre.spin,
        exponents,
        island,
        threshold: options.threshold,
    };
    Ok(Measured {
        size,
        window,
        reach,
    })
}

/// The cells of an `n × n` grid joined to `start` through cells sharing a
/// side, all with `inside` true (`start` included).
fn flood_fill(n: usize, start: usize, inside: impl Fn(usize) -> bool) -> Vec<bool> {
    let mut island = vec![false; n * n];
    let mut stack = vec![start];
    island[start] = true;
    while let Some(k) = stack.pop() {
        let (i, j) = (k % n, k / n);
        let neighbours = [
            (i > 0).then(|| k - 1),
            (i + 1 < n).then(|| k + 1),
            (j > 0).then(|| k - n),
            (j + 1 < n).then(|| k + n),
        ];
        for m in neighbours.into_iter().flatten() {
            if !island[m] && inside(m) {
                island[m] = true;
                stack.push(m);
            }
        }
    }
    island
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flood_fill_stays_in_its_component() {
        // 5 × 5: a cross around the centre and a separate corner cell.
        let on = [2, 7, 11, 12, 13, 17, 22, 0];
        let island = flood_fill(5, 12, |k| on.contains(&k));
        let got: Vec<usize> = (0..25).filter(|&k| island[k]).collect();
        assert_eq!(got, vec![2, 7, 11, 12, 13, 17, 22]);
    }
}
