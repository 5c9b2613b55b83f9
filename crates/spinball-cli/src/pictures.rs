//! The `--png` pictures of the commands: the results handed to the plots of
//! `spinball-plot` (which draws them), with the sizes and labels the
//! command line promises. No drawing here, only which plot shows what.

use std::path::Path;

use spinball_analysis::estimators::{FtleDistribution, PlusMinus, THRESHOLD_BAND};
use spinball_analysis::phase_space::FtleMap;
use spinball_analysis::run::{LyapunovEstimate, Shard};
use spinball_geometry::{Boundary, DVec2, ToOutline};
use spinball_plot::{
    Colorbar, Grid, HistogramPlot, LineKind, LinePlot, MapPlot, Marker, Plot, Series, TablePlot,
    XBand, two_digits, value_range,
};

use crate::error::CliError;
use crate::files::check_writable;

/// Size of every `--png` picture (pixels): width × height.
pub const PNG_SIZE: (u32, u32) = (1200, 800);

/// [`check_png`] for a picture of a whole run: refused on a shard, which
/// holds only part of it (`whole`: what the picture draws and why a shard
/// cannot, e.g. "map: a shard holds only some of its cells").
///
/// # Errors
/// [`CliError::Usage`] saying what is wrong.
pub fn check_whole_png(path: &Path, shard: Shard, whole: &str) -> Result<(), CliError> {
    if shard.count > 1 {
        return Err(CliError::Usage(format!("--png draws a whole {whole}")));
    }
    check_png(path)
}

/// Check, before a run, that `--png path` can be written: it ends in
/// `.png` and can be replaced whole ([`check_writable`]).
///
/// # Errors
/// [`CliError::Usage`] saying what is wrong.
pub fn check_png(path: &Path) -> Result<(), CliError> {
    let is_png = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if !is_png {
        return Err(CliError::Usage(format!(
            "--png {}: the picture's file name must end in .png",
            path.display()
        )));
    }
    check_writable("png", path)
}

fn save(plot: &impl Plot, path: &Path) -> Result<(), CliError> {
    plot.save_png(path, PNG_SIZE.0, PNG_SIZE.1)
        .map_err(|e| CliError::Failed(format!("--png {}: {e}", path.display())))
}

/// λ(α) with its standard errors, one point per estimate; the legend says
/// the largest SEM (the bars may be shorter than the markers).
///
/// # Errors
/// [`CliError::Failed`] if the picture cannot be drawn or written.
pub fn lyapunov_png(path: &Path, estimates: &[LyapunovEstimate]) -> Result<(), CliError> {
    let first = estimates
        .first()
        .ok_or_else(|| CliError::Failed("--png: no estimate to draw".into()))?;
    let max_sem = estimates.iter().map(|e| e.sem()).fold(0.0, f64::max);
    let label = format!("mean λ ± SEM (largest SEM {})", two_digits(max_sem));
    let series = Series::new(label, estimates.iter().map(|e| (e.alpha(), e.mean())))
        .errors(estimates.iter().map(|e| e.sem()));
    let title = format!(
        "{}: {} starts × {} collisions",
        first.table(),
        first.n_ics(),
        first.collisions_per_ic()
    );
    let plot =
        LinePlot::with_axes(title, "spin parameter α = I/(m r²)", "λ (1/time)").series(series);
    save(&plot, path)
}

/// The histogram of the finite-time exponents of `estimate`, with the band
/// of chaos thresholds shaded and the mean and the threshold marked.
///
/// # Errors
/// [`CliError::Failed`] if the picture cannot be drawn or written.
pub fn ftle_png(
    path: &Path,
    estimate: &LyapunovEstimate,
    ftle: &FtleDistribution,
    bins: usize,
) -> Result<(), CliError> {
    let lo = THRESHOLD_BAND.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = THRESHOLD_BAND
        .iter()
        .copied()
        .fold(f64::NEG_INFINITY, f64::max);
    let mean = PlusMinus::new(ftle.mean(), estimate.sem());
    let title = format!(
        "{} at α = {}: {} starts × {} collisions",
        estimate.table(),
        estimate.alpha(),
        estimate.n_ics(),
        estimate.collisions_per_ic()
    );
    let plot = HistogramPlot::new(ftle.exponents().iter().copied())
        .bins(bins)
        .title(title)
        .x_label("finite-time exponent λ (1/time)")
        .label("starts")
        .band(XBand::new(format!("chaos thresholds {lo}–{hi}"), lo, hi))
        .marker(Marker::new(format!("mean {mean}"), ftle.mean()))
        .marker(
            Marker::new(
                format!("threshold {}", estimate.threshold()),
                estimate.threshold(),
            )
            .kind(LineKind::Dashed),
        );
    save(&plot, path)
}

/// Wrap `panel` with a colour bar of `label` over `range` under it.
fn with_colorbar(panel: impl Into<spinball_plot::Panel>, label: &str, range: (f64, f64)) -> Grid {
    Grid::new(1, 1)
        .panel(panel)
        .colorbar(Colorbar::new(label, range.0, range.1))
}

/// The path of a trajectory on its table, each flight coloured by the spin
/// `u` it carries, with a colour bar.
///
/// `points` are the start then the collision points; `spins[i]` is the
/// spin during the flight from point `i` to `i + 1`.
///
/// # Errors
/// [`CliError::Failed`] if the picture cannot be drawn or written.
pub fn trajectory_png(
    path: &Path,
    table: &(impl ToOutline + Boundary),
    title: String,
    points: Vec<DVec2>,
    spins: Vec<f64>,
) -> Result<(), CliError> {
    let range = value_range(spins.iter().copied()).unwrap_or((-1.0, 1.0));
    let plot = TablePlot::new(table)
        .title(title)
        .axes(true)
        .trajectory(points)
        .leg_values(spins, range);
    save(&with_colorbar(plot, "spin u = rω", range), path)
}

/// A Birkhoff section: the points `(s, sin θ)` coloured by the spin `u`,
/// with a colour bar.
///
/// # Errors
/// [`CliError::Failed`] if the picture cannot be drawn or written.
pub fn section_png(
    path: &Path,
    title: String,
    perimeter: f64,
    points: Vec<(f64, f64, f64)>,
) -> Result<(), CliError> {
    let range = value_range(points.iter().map(|p| p.2)).unwrap_or((-1.0, 1.0));
    let plot = MapPlot::new((0.0, perimeter), (-1.0, 1.0), range)
        .points(points)
        .labels("arc length s", "sin θ = v∥/|v|")
        .title(title);
    save(&with_colorbar(plot, "spin u = rω", range), path)
}

/// An FTLE map as an image (white off the energy shell), the predicted
/// bouncing-ball cells outlined, with a colour bar.
///
/// # Errors
/// [`CliError::Failed`] if the picture cannot be drawn or written.
pub fn ftle_map_png(
    path: &Path,
    title: String,
    map: &FtleMap,
    predicted: Option<&[bool]>,
) -> Result<(), CliError> {
    let top = map
        .exponents
        .iter()
        .flatten()
        .copied()
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    let range = if top > 0.0 { (0.0, top) } else { (0.0, 1.0) };
    let mut plot = MapPlot::new((0.0, map.perimeter), (-1.0, 1.0), range)
        .cells(map.options.columns, map.options.rows, map.exponents.clone())
        .labels("arc length s", map.options.slice.row_label())
        .title(title);
    if let Some(mask) = predicted.filter(|m| m.iter().any(|&b| b)) {
        plot = plot.outline(mask.to_vec());
    }
    save(&with_colorbar(plot, "FTLE λ (1/time)", range), path)
}
