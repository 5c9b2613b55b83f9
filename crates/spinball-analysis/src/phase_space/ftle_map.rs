//! FTLE maps: the finite-time Lyapunov exponent of every start on a grid of
//! the section, which shows where the regular islands are.
//!
//! Documented in the group docs (`phase_space/mod.rs`), section "FTLE maps".

use spinball_core::{SpinLaw, State};
use spinball_geometry::Boundary;

use super::ftle_map_shards::ftle_map_part;
use super::section::state_on_section;
use crate::error::AnalysisError;
use crate::estimators::ChaoticFraction;
use crate::run::{FtleMapDefaults, RunDefaults, Shard, Threads};

/// Which slice of the three-dimensional section a map covers.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Slice {
    /// Fixed spin `u` (needs `αu² < 1`); rows are `sin θ`.
    Spin(f64),
    /// Fixed `Q = v∥ − αu` (needs α > 0); rows are `v∥/|V|`.
    Q(f64),
}

impl Slice {
    /// `(v∥, u)` of a start at row coordinate `row` of this slice, on the
    /// shell `|V| = 1`, under spin law parameter `alpha`.
    #[must_use]
    pub fn coordinates(&self, alpha: f64, row: f64) -> (f64, f64) {
        match *self {
            Slice::Spin(u) => (row * (1.0 - alpha * u * u).sqrt(), u),
            Slice::Q(q) => (row, (row - q) / alpha),
        }
    }

    /// The name of the row coordinate.
    #[must_use]
    pub fn row_label(&self) -> &'static str {
        match self {
            Slice::Spin(_) => "sin θ = v∥/|v|",
            Slice::Q(_) => "v∥/|V|",
        }
    }
}

/// How to draw an FTLE map.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FtleMapOptions {
    /// Cells along `s` (columns).
    pub columns: usize,
    /// Cells along the row coordinate.
    pub rows: usize,
    /// The slice.
    pub slice: Slice,
    /// Collisions per start.
    pub collisions: u64,
    /// Seed of the tangent vectors' directions.
    pub seed: u64,
    /// FTLE at or below which a cell is regular.
    pub threshold: f64,
    /// Threads (results do not depend on it).
    pub threads: Threads,
}

impl FtleMapOptions {
    /// A `columns × rows` map at `slice`, 2000 collisions, seed 0, the
    /// paper's threshold, all threads ([`FtleMapDefaults`],
    /// [`RunDefaults`]).
    #[must_use]
    pub fn new(columns: usize, rows: usize, slice: Slice) -> Self {
        FtleMapOptions {
            columns,
            rows,
            slice,
            collisions: FtleMapDefaults::COLLISIONS,
            seed: RunDefaults::SEED,
            threshold: RunDefaults::THRESHOLD,
            threads: RunDefaults::THREADS,
        }
    }
    /// `collisions` per start.
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
    /// Regular at FTLE ≤ `threshold`.
    #[must_use]
    pub fn with_threshold(mut self, threshold: f64) -> Self {
        self.threshold = threshold;
        self
    }
    /// Run on `threads`.
    #[must_use]
    pub fn with_threads(mut self, threads: Threads) -> Self {
        self.threads = threads;
        self
    }
}

/// The exponents of a grid of starts on the section.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FtleMap {
    /// What was run.
    pub options: FtleMapOptions,
    /// α of the run.
    pub alpha: f64,
    /// The perimeter (the range of `s`).
    pub perimeter: f64,
    /// Row-major (`rows × columns`, row 0 at the bottom): the FTLE per unit
    /// time of each cell's start, `None` off the energy shell.
    pub exponents: Vec<Option<f64>>,
}

impl FtleMap {
    /// `s` at the centre of column `i`.
    #[must_use]
    pub fn s(&self, i: usize) -> f64 {
        self.perimeter * (i as f64 + 0.5) / self.options.columns as f64
    }
    /// The row coordinate at the centre of row `j`.
    #[must_use]
    pub fn row(&self, j: usize) -> f64 {
        -1.0 + 2.0 * (j as f64 + 0.5) / self.options.rows as f64
    }
    /// The exponent of cell `(column i, row j)`.
    #[must_use]
    pub fn get(&self, i: usize, j: usize) -> Option<f64> {
        self.exponents[j * self.options.columns + i]
    }
    /// Regular cells (FTLE ≤ threshold) and cells on the shell.
    #[must_use]
    pub fn counts(&self) -> (u64, u64) {
        let t = self.options.threshold;
        let on: Vec<f64> = self.exponents.iter().flatten().copied().collect();
        (
            on.iter().filter(|&&x| x <= t).count() as u64,
            on.len() as u64,
        )
    }
    /// Of the cells where `mask` is set (row-major, like
    /// [`exponents`](Self::exponents)), how many there are on the shell and
    /// how many of those are regular.
    #[must_use]
    pub fn regular_among(&self, mask: &[bool]) -> (usize, usize) {
        let t = self.options.threshold;
        let inside = || {
            self.exponents
                .iter()
                .zip(mask)
                .filter_map(|(x, &m)| if m { *x } else { None })
        };
        (inside().count(), inside().filter(|&x| x <= t).count())
    }
    /// Share of the cells on the shell that are regular. For a uniform grid
    /// in `(s, sin θ)` at α = 0 this is the share of the invariant measure
    /// `ds d(sin θ)` on regular orbits (to the grid's resolution).
    #[must_use]
    pub fn regular_fraction(&self) -> f64 {
        let (regular, total) = self.counts();
        regular as f64 / total as f64
    }
    /// The chaotic share of the cells with its binomial error, as the
    /// paper's chaotic fraction is reported.
    #[must_use]
    pub fn chaotic_fraction(&self) -> ChaoticFraction {
        let (regular, total) = self.counts();
        let fraction = (total - regular) as f64 / total as f64;
        ChaoticFraction {
            threshold: self.options.threshold,
            chaotic: total - regular,
            total,
            fraction,
            sem: (fraction * (1.0 - fraction) / total as f64).sqrt(),
        }
    }
    /// The grid as `rows × columns` numbers for NumPy (`NaN` marks the cells
    /// off the energy shell, which have no exponent).
    #[must_use]
    pub fn to_array(&self) -> Vec<f64> {
        self.exponents
            .iter()
            .map(|x| x.unwrap_or(f64::NAN))
            .collect()
    }
    /// CSV with a header: `s,row,ftle` per cell on the shell.
    #[must_use]
    pub fn to_csv(&self) -> String {
        let mut out = String::from("s,row,ftle\n");
        for j in 0..self.options.rows {
            for i in 0..self.options.columns {
                if let Some(x) = self.get(i, j) {
                    out.push_str(&format!("{},{},{}\n", self.s(i), self.row(j), x));
                }
            }
        }
        out
    }
}

/// The start of cell `(i, j)`, or `None` off the shell.
fn cell_start<B: Boundary>(
    table: &B,
    law: &SpinLaw,
    slice: Slice,
    s: f64,
    row: f64,
) -> Result<Option<State>, AnalysisError> {
    let alpha = law.alpha();
    let (v_par, spin) = slice.coordinates(alpha, row);
    if v_par * v_par + alpha * spin * spin >= 1.0 {
        return Ok(None);
    }
    state_on_section(table, law, s, v_par, spin).map(Some)
}

/// The FTLE map of `table` under `law` (see the [module docs](crate::phase_space#ftle-maps)).
///
/// ```
/// use spinball_analysis::phase_space::{FtleMapOptions, Slice, ftle_map};
/// use spinball_core::SpinLaw;
/// use spinball_geometry::Circle;
///
/// // The circle is integrable at every α: every cell is regular.
/// let options = FtleMapOptions::new(8, 8, Slice::Spin(0.2)).with_collisions(500);
/// let map = ftle_map(Circle::unit(), SpinLaw::new(0.5)?, &options)?;
/// assert_eq!(map.regular_fraction(), 1.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for a grid with no cells (or more than
/// 2³² of them), zero collisions, a non-finite slice, `αu² ≥ 1` for
/// [`Slice::Spin`], α = 0 for [`Slice::Q`] (the spin decouples and `Q = v∥`
/// fixes the row), a slice with fewer than two cells on the shell, a non-finite
/// threshold, a table that cannot place points by arc length; otherwise the
/// first failing start's error with its cell index `j·columns + i`.
pub fn ftle_map<B: Boundary + Sync>(
    table: B,
    law: SpinLaw,
    options: &FtleMapOptions,
) -> Result<FtleMap, AnalysisError> {
    ftle_map_part(table, law, options, Shard::WHOLE).map(|part| part.map)
}

/// The empty map of `options` (every cell `None`), the starts of its cells
/// on the energy shell in row-major order, and the cell of each start.
///
/// # Errors
/// As [`ftle_map`], before any trajectory is run.
pub(super) fn grid_starts<B: Boundary>(
    table: &B,
    law: &SpinLaw,
    options: &FtleMapOptions,
) -> Result<(FtleMap, Vec<State>, Vec<usize>), AnalysisError> {
    let (nc, nr) = (options.columns, options.rows);
    let cells = nc.checked_mul(nr).filter(|&n| n > 0 && n <= 1 << 32);
    let Some(cells) = cells else {
        return Err(AnalysisError::invalid(
            "grid",
            format!("{nc} × {nr} cells: need 1 to 2^32 cells"),
        ));
    };
    if options.collisions == 0 {
        return Err(AnalysisError::invalid("collisions", "must be > 0"));
    }
    if !options.threshold.is_finite() {
        return Err(AnalysisError::invalid(
            "threshold",
            format!("must be finite, got {}", options.threshold),
        ));
    }
    let alpha = law.alpha();
    match options.slice {
        Slice::Spin(u) if !(u.is_finite() && alpha * u * u < 1.0) => {
            return Err(AnalysisError::invalid(
                "slice",
                format!("spin u = {u} needs αu² < 1 (|u| < {})", 1.0 / alpha.sqrt()),
            ));
        }
        Slice::Q(q) if !q.is_finite() || alpha == 0.0 => {
            return Err(AnalysisError::invalid(
                "slice",
                format!("fixed Q = {q} needs a finite Q and α > 0 (at α = 0, Q = v∥)"),
            ));
        }
        _ => {}
    }
    let map = FtleMap {
        options: *options,
        alpha,
        perimeter: table.perimeter(),
        exponents: vec![None; cells],
    };
    let mut starts = Vec::with_capacity(cells);
    let mut cell_of = Vec::with_capacity(cells);
    for j in 0..nr {
        for i in 0..nc {
            if let Some(state) = cell_start(table, law, options.slice, map.s(i), map.row(j))? {
                starts.push(state);
                cell_of.push(j * nc + i);
            }
        }
    }
    if starts.len() < 2 {
        return Err(AnalysisError::invalid(
            "slice",
            format!(
                "{:?} leaves {} cells on the energy shell (need 2)",
                options.slice,
                starts.len()
            ),
        ));
    }
    Ok((map, starts, cell_of))
}
