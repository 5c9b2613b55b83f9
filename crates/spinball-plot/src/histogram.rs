//! Histograms with vertical marker lines: FTLE distributions with their mean,
//! median and conditional mean, |ΔQ| distributions.

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::colormap::palette;
use crate::error::PlotError;
use crate::font;
use crate::format::format_tick_on;
use crate::lines::{
    Legend, LineKind, axis_tick, dash, legend_glyph, legend_width, log_label_count, pad,
};
use crate::plot::{Plot, inner_size, titled};
use crate::style::Style;
use crate::x_band::XBand;

/// A vertical line across a [`HistogramPlot`] at `x`, with a legend entry.
#[derive(Debug, Clone)]
pub struct Marker {
    label: String,
    x: f64,
    color: Option<RGBColor>,
    kind: LineKind,
}

impl Marker {
    /// A solid line at `x` labelled `label` (a non-finite `x` is not drawn).
    pub fn new(label: impl Into<String>, x: f64) -> Self {
        Marker {
            label: label.into(),
            x,
            color: None,
            kind: LineKind::Solid,
        }
    }
    /// The colour (default: black for the first marker, then the palette).
    pub fn color(mut self, color: RGBColor) -> Self {
        self.color = Some(color);
        self
    }
    /// Solid, dashed or dotted.
    pub fn kind(mut self, kind: LineKind) -> Self {
        self.kind = kind;
        self
    }
}

/// A histogram of values with optional marker lines.
///
/// Non-finite values are skipped; values outside an explicit
/// [`range`](HistogramPlot::range) are not counted. With
/// [`density`](HistogramPlot::density) the bars are normalised so that their area
/// is the share of values in the range.
///
/// ```no_run
/// use spinball_plot::{HistogramPlot, LineKind, Marker, Plot};
/// let ftle = vec![0.41, 0.43, 0.44, 0.02, 0.42, f64::NAN, 0.45];
/// HistogramPlot::new(ftle)
///     .bins(40)
///     .density(true)
///     .x_label("FTLE λ (1/time)")
///     .marker(Marker::new("mean 0.36", 0.36))
///     .marker(Marker::new("median 0.42", 0.42).kind(LineKind::Dashed))
///     .save_png("out/ftle.png", 1200, 800)?;
/// # Ok::<(), spinball_plot::PlotError>(())
/// ```
#[derive(Debug, Clone)]
pub struct HistogramPlot {
    values: Vec<f64>,
    bins: usize,
    range: Option<(f64, f64)>,
    density: bool,
    log_y: bool,
    title: Option<String>,
    x_label: Option<String>,
    y_label: Option<String>,
    label: Option<String>,
    color: Option<RGBColor>,
    markers: Vec<Marker>,
    bands: Vec<XBand>,
    legend: Legend,
}

impl HistogramPlot {
    /// A histogram of `values` with 50 bins over their range.
    pub fn new(values: impl IntoIterator<Item = f64>) -> Self {
        HistogramPlot {
            values: values.into_iter().collect(),
            bins: 50,
            range: None,
            density: false,
            log_y: false,
            title: None,
            x_label: None,
            y_label: None,
            label: None,
            color: None,
            markers: Vec::new(),
            bands: Vec::new(),
            legend: Legend::UpperRight,
        }
    }
    /// Number of bins (at least 1).
    pub fn bins(mut self, bins: usize) -> Self {
        self.bins = bins;
        self
    }
    /// Bin over `[lo, hi]` instead of the data range.
    pub fn range(mut self, lo: f64, hi: f64) -> Self {
        self.range = Some((lo, hi));
        self
    }
    /// Normalise to a probability density (default: counts).
    pub fn density(mut self, on: bool) -> Self {
        self.density = on;
        self
    }
    /// Logarithmic y axis (empty bins are not drawn).
    pub fn log_y(mut self, on: bool) -> Self {
        self.log_y = on;
        self
    }
    /// Title above the chart.
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }
    /// Label of the x axis, with units.
    pub fn x_label(mut self, label: impl Into<String>) -> Self {
        self.x_label = Some(label.into());
        self
    }
    /// Label of the y axis (default: "count" or "probability density").
    pub fn y_label(mut self, label: impl Into<String>) -> Self {
        self.y_label = Some(label.into());
        self
    }
    /// Legend entry for the bars.
    pub fn label(mut self, label: impl Into<String>) -> Self {
        self.label = Some(label.into());
        self
    }
    /// Bar colour (default: the first palette colour).
    pub fn color(mut self, color: RGBColor) -> Self {
        self.color = Some(color);
        self
    }
    /// Add a vertical marker line.
    pub fn marker(mut self, marker: Marker) -> Self {
        self.markers.push(marker);
        self
    }
    /// Shade an interval of the x axis behind the bars (the axis widens
    /// to show it).
    pub fn band(mut self, band: XBand) -> Self {
        self.bands.push(band);
        self
    }
    /// Where the legend goes.
    pub fn legend(mut self, legend: Legend) -> Self {
        self.legend = legend;
        self
    }

    /// The bin edges' range and the bar heights (counts or density).
    pub fn heights(&self) -> Result<((f64, f64), Vec<f64>), PlotError> {
        if self.bins == 0 {
            return Err(PlotError::Invalid {
                what: "bins",
                why: "a histogram needs at least one bin".into(),
            });
        }
        let finite = self.values.iter().copied().filter(|v| v.is_finite());
        let (lo, hi) = match self.range {
            Some((lo, hi)) => {
                if !(lo.is_finite() && hi.is_finite() && lo < hi) {
                    return Err(PlotError::Invalid {
                        what: "histogram range",
                        why: format!("[{lo}, {hi}] is not an increasing finite range"),
                    });
                }
                (lo, hi)
            }
            None => {
                let (lo, hi) = finite
                    .clone()
                    .fold(None, |acc: Option<(f64, f64)>, v| {
                        Some(acc.map_or((v, v), |(a, b)| (a.min(v), b.max(v))))
                    })
                    .ok_or_else(|| PlotError::EmptyData("histogram".into()))?;
                if hi > lo {
                    (lo, hi)
                } else {
                    pad((lo, hi), false)
                }
            }
        };
        let width = (hi - lo) / self.bins as f64;
        let mut counts = vec![0.0; self.bins];
        let mut n = 0usize;
        for v in finite.filter(|v| (lo..=hi).contains(v)) {
            let i = (((v - lo) / width) as usize).min(self.bins - 1);
            counts[i] += 1.0;
            n += 1;
        }
        if n == 0 {
            return Err(PlotError::EmptyData("histogram (range)".into()));
        }
        if self.density {
            for c in &mut counts {
                *c /= n as f64 * width;
            }
        }
        Ok(((lo, hi), counts))
    }
}

impl Plot for HistogramPlot {
    fn validate(&self) -> Result<(), PlotError> {
        self.heights().map(|_| ())
    }

    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        style: &Style,
    ) -> Result<(), PlotError> {
        font::ensure()?;
        let ((lo, hi), heights) = self.heights()?;
        let area = titled(area, self.title.as_deref(), style.title_px)?;
        let left = style.y_label_area(4);
        let bottom = style.x_label_area();
        inner_size(&area, style.margin, left, bottom)?;
        let top = heights.iter().copied().fold(0.0, f64::max);
        let mut builder = ChartBuilder::on(&area);
        builder
            .margin(style.margin)
            .margin_right(style.margin * 2)
            .x_label_area_size(bottom)
            .y_label_area_size(left);
        let default_y = if self.density {
            "probability density"
        } else {
            "count"
        };
        let y_desc = self
            .y_label
            .clone()
            .unwrap_or_else(|| default_y.to_string());
        let bar = self.color.unwrap_or_else(|| palette(0));
        let width = (hi - lo) / heights.len() as f64;
        let xs = (lo, hi);
        let markers: Vec<&Marker> = self.markers.iter().filter(|m| m.x.is_finite()).collect();
        let x_range = markers
            .iter()
            .map(|m| (m.x, m.x))
            .chain(
                self.bands
                    .iter()
                    .filter_map(|b| b.visible_in((f64::MIN, f64::MAX))),
            )
            .fold(xs, |(a, b), (lo, hi)| (a.min(lo), b.max(hi)));
        let x_range = pad(x_range, false);

        // On a log axis the chart coordinate is log10 of the height.
        let (y0, y1, ty): (f64, f64, fn(f64) -> f64) = if self.log_y {
            let min_pos = heights
                .iter()
                .copied()
                .filter(|h| *h > 0.0)
                .fold(f64::INFINITY, f64::min);
            let (a, b) = pad((min_pos / 2.0, top), true);
            (a.log10(), b.log10(), f64::log10)
        } else {
            (0.0, top * 1.08, |h| h)
        };
        let mut chart = builder.build_cartesian_2d(x_range.0..x_range.1, y0..y1)?;
        let fmt = |v: &f64| format_tick_on(*v, x_range.1 - x_range.0);
        let fmt_y = |v: &f64| axis_tick(*v, self.log_y);
        chart
            .configure_mesh()
            .x_desc(self.x_label.clone().unwrap_or_default())
            .y_desc(y_desc)
            .label_style((font::FAMILY, style.tick_px).into_font())
            .axis_desc_style((font::FAMILY, style.label_px).into_font())
            .x_label_formatter(&fmt)
            .y_label_formatter(&fmt_y)
            .x_labels(7)
            .y_labels(if self.log_y {
                log_label_count(y0, y1)
            } else {
                6
            })
            .disable_x_mesh()
            .bold_line_style(RGBColor(0xE3, 0xE3, 0xE3).stroke_width(1))
            .light_line_style(TRANSPARENT)
            .axis_style(BLACK.stroke_width(1))
            .draw()?;
        let side = (style.legend_px * 0.7) as i32;
        for band in &self.bands {
            let Some((a, b)) = band.visible_in(x_range) else {
                continue;
            };
            let shade = band.color.mix(0.25);
            chart
                .draw_series(std::iter::once(Rectangle::new(
                    [(a, y0), (b, y1)],
                    shade.filled(),
                )))?
                .label(band.label.clone())
                .legend(move |(x, y)| {
                    Rectangle::new(
                        [(x, y - side / 2), (x + 2 * side, y + side / 2)],
                        shade.filled(),
                    )
                });
        }
        let bars: Vec<(f64, f64)> = heights
            .iter()
            .enumerate()
            .filter(|(_, h)| **h > 0.0)
            .map(|(i, h)| (lo + i as f64 * width, ty(*h)))
            .collect();
        let anno = chart
            .draw_series(bars.iter().map(|&(x, h)| {
                Rectangle::new([(x, y0), (x + width, h)], bar.mix(0.55).filled())
            }))?;
        if let Some(label) = &self.label {
            anno.label(label.clone()).legend(move |(x, y)| {
                Rectangle::new(
                    [(x, y - side / 2), (x + 2 * side, y + side / 2)],
                    bar.mix(0.55).filled(),
                )
            });
        }
        chart.draw_series(
            bars.iter()
                .map(|&(x, h)| Rectangle::new([(x, y0), (x + width, h)], bar.stroke_width(1))),
        )?;
        let lw = style.line_width.max(2) + 1;
        let w = legend_width(style);
        for (k, m) in markers.iter().enumerate() {
            let color = m.color.unwrap_or(if k == 0 { BLACK } else { palette(k) });
            let st = color.stroke_width(lw);
            let pts = [(m.x, y0), (m.x, y1)];
            let anno = match m.kind {
                LineKind::Solid => chart.draw_series(LineSeries::new(pts, st))?,
                kind => {
                    let (d, g) = dash(kind, lw);
                    chart.draw_series(DashedLineSeries::new(pts, d, g, st))?
                }
            };
            let kind = m.kind;
            anno.label(m.label.clone())
                .legend(move |c| legend_glyph(c, kind, color, lw, None, w));
        }
        let labelled = self.label.is_some() || !markers.is_empty() || !self.bands.is_empty();
        if let (Some(pos), true) = (self.legend.position(), labelled) {
            chart
                .configure_series_labels()
                .position(pos)
                .margin(style.margin)
                .legend_area_size(w + 8)
                .label_font((font::FAMILY, style.legend_px).into_font())
                .background_style(WHITE.mix(0.88))
                .border_style(RGBColor(0xA0, 0xA0, 0xA0))
                .draw()?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_and_density() {
        let h = HistogramPlot::new([0.0, 0.1, 0.9, 1.0, f64::NAN, f64::INFINITY]).bins(2);
        let ((lo, hi), c) = h.heights().unwrap();
        assert_eq!((lo, hi), (0.0, 1.0));
        assert_eq!(c, vec![2.0, 2.0]);
        let (_, d) = h.clone().density(true).heights().unwrap();
        let area: f64 = d.iter().map(|x| x * 0.5).sum();
        assert!((area - 1.0).abs() < 1e-12);
    }

    #[test]
    fn bad_input_is_an_error() {
        assert!(matches!(
            HistogramPlot::new([f64::NAN]).heights(),
            Err(PlotError::EmptyData(_))
        ));
        assert!(matches!(
            HistogramPlot::new([1.0]).bins(0).heights(),
            Err(PlotError::Invalid { .. })
        ));
        assert!(matches!(
            HistogramPlot::new([1.0]).range(2.0, 3.0).heights(),
            Err(PlotError::EmptyData(_))
        ));
        // A single value still gets a visible range.
        assert!(HistogramPlot::new([1.0]).heights().is_ok());
    }
}
