//! Curves: λ(α) with error bars, shaded min–max bands, reference lines,
//! energy traces on a log axis.

use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::element::IntoDynElement;
use plotters::prelude::*;

use crate::colormap::palette;
use crate::error::PlotError;
use crate::error_bar::{ErrorBarPixels, bar_shade, draw_error_bars};
use crate::font;
use crate::format::{format_tick, snap_tick, superscript, two_digits};
use crate::plot::{Plot, inner_size, titled};
use crate::style::Style;

/// How a line is stroked.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LineKind {
    /// Continuous.
    #[default]
    Solid,
    /// Long dashes.
    Dashed,
    /// Short dots.
    Dotted,
}

/// Where the legend goes (inside the plotting area).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Legend {
    /// Top left corner.
    UpperLeft,
    /// Top right corner.
    #[default]
    UpperRight,
    /// Bottom left corner.
    LowerLeft,
    /// Bottom right corner.
    LowerRight,
    /// Centre of the top edge.
    UpperMiddle,
    /// No legend.
    Hidden,
}

impl Legend {
    pub(crate) fn position(self) -> Option<SeriesLabelPosition> {
        Some(match self {
            Legend::UpperLeft => SeriesLabelPosition::UpperLeft,
            Legend::UpperRight => SeriesLabelPosition::UpperRight,
            Legend::LowerLeft => SeriesLabelPosition::LowerLeft,
            Legend::LowerRight => SeriesLabelPosition::LowerRight,
            Legend::UpperMiddle => SeriesLabelPosition::UpperMiddle,
            Legend::Hidden => return None,
        })
    }
}

/// One curve of a [`LinePlot`]: points, optional symmetric error bars and an
/// optional shaded band (for example the min–max over thresholds).
///
/// Points with a non-finite coordinate (or a non-positive one on a log axis)
/// are skipped and break the line; an error bar or band entry that is not
/// finite is left out.
#[derive(Debug, Clone)]
pub struct Series {
    label: Option<String>,
    points: Vec<(f64, f64)>,
    errors: Option<Vec<f64>>,
    band: Option<(Vec<f64>, Vec<f64>)>,
    band_label: Option<String>,
    color: Option<RGBColor>,
    line: bool,
    markers: bool,
    kind: LineKind,
    marker_radius: Option<u32>,
    line_width: Option<u32>,
}

impl Series {
    /// A labelled curve drawn as a line with point markers, in the next
    /// palette colour.
    pub fn new(label: impl Into<String>, points: impl IntoIterator<Item = (f64, f64)>) -> Self {
        let mut s = Series::unlabelled(points);
        s.label = Some(label.into());
        s
    }

    /// A curve without a legend entry.
    pub fn unlabelled(points: impl IntoIterator<Item = (f64, f64)>) -> Self {
        Series {
            label: None,
            points: points.into_iter().collect(),
            errors: None,
            band: None,
            band_label: None,
            color: None,
            line: true,
            markers: true,
            kind: LineKind::Solid,
            marker_radius: None,
            line_width: None,
        }
    }

    /// Symmetric error bars `y ± e`, one per point (for example the standard
    /// error of the mean).
    pub fn errors(mut self, errors: impl IntoIterator<Item = f64>) -> Self {
        self.errors = Some(errors.into_iter().collect());
        self
    }

    /// A shaded band from `lower` to `upper`, one pair per point, drawn behind
    /// all curves in the series colour.
    pub fn band(
        mut self,
        lower: impl IntoIterator<Item = f64>,
        upper: impl IntoIterator<Item = f64>,
    ) -> Self {
        self.band = Some((lower.into_iter().collect(), upper.into_iter().collect()));
        self
    }

    /// A legend entry for the band (by default the band has none).
    pub fn band_label(mut self, label: impl Into<String>) -> Self {
        self.band_label = Some(label.into());
        self
    }

    /// The colour (default: the plot's palette colour for this series).
    pub fn color(mut self, color: RGBColor) -> Self {
        self.color = Some(color);
        self
    }

    /// Draw the line only, no point markers.
    pub fn line_only(mut self) -> Self {
        self.line = true;
        self.markers = false;
        self
    }

    /// Draw point markers only, no line (scatter).
    pub fn markers_only(mut self) -> Self {
        self.line = false;
        self.markers = true;
        self
    }

    /// Stroke the line solid, dashed or dotted.
    pub fn kind(mut self, kind: LineKind) -> Self {
        self.kind = kind;
        self
    }

    /// Marker radius in pixels (default from the [`Style`]).
    pub fn marker_radius(mut self, radius: u32) -> Self {
        self.marker_radius = Some(radius);
        self
    }

    /// Line width in pixels (default from the [`Style`]).
    pub fn line_width(mut self, width: u32) -> Self {
        self.line_width = Some(width);
        self
    }

    fn check(&self, index: usize) -> Result<(), PlotError> {
        let n = self.points.len();
        let name = || {
            self.label
                .clone()
                .unwrap_or_else(|| format!("series {index}"))
        };
        if let Some(e) = &self.errors
            && e.len() != n
        {
            return Err(PlotError::LengthMismatch {
                what: format!("error bars of {}", name()),
                expected: n,
                got: e.len(),
            });
        }
        if let Some((lo, hi)) = &self.band {
            for (what, v) in [("lower band", lo), ("upper band", hi)] {
                if v.len() != n {
                    return Err(PlotError::LengthMismatch {
                        what: format!("{what} of {}", name()),
                        expected: n,
                        got: v.len(),
                    });
                }
            }
        }
        Ok(())
    }
}

/// A chart of [`Series`] with labelled axes, a legend and optional log axes.
///
/// ```no_run
/// use spinball_plot::{Legend, LinePlot, Plot, Series};
/// let alpha = [0.0, 0.25, 0.5, 0.75, 1.0];
/// LinePlot::new()
///     .title("Stadium a = 1")
///     .x_label("α = I/(m r²)")
///     .y_label("λ (1/time)")
///     .series(
///         Series::new("λ ± SEM", alpha.iter().copied().zip([0.43, 0.22, 0.18, 0.16, 0.15]))
///             .errors([0.004; 5])
///             .band([0.42, 0.20, 0.17, 0.15, 0.14], [0.44, 0.24, 0.19, 0.17, 0.16])
///             .band_label("spread"),
///     )
///     .hline(0.0, "λ = 0")
///     .legend(Legend::UpperRight)
///     .save_png("out/lambda.png", 1200, 800)?;
/// # Ok::<(), spinball_plot::PlotError>(())
/// ```
#[derive(Debug, Clone, Default)]
pub struct LinePlot {
    title: Option<String>,
    x_label: Option<String>,
    y_label: Option<String>,
    series: Vec<Series>,
    hlines: Vec<(f64, String)>,
    log_x: bool,
    log_y: bool,
    x_range: Option<(f64, f64)>,
    y_range: Option<(f64, f64)>,
    legend: Legend,
}

impl LinePlot {
    /// An empty chart (add at least one series).
    pub fn new() -> Self {
        Self::default()
    }
    /// An empty chart with a title and both axis labels (the usual start).
    pub fn with_axes(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Self::new().title(title).x_label(x_label).y_label(y_label)
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
    /// Label of the y axis, with units.
    pub fn y_label(mut self, label: impl Into<String>) -> Self {
        self.y_label = Some(label.into());
        self
    }
    /// Add a curve.
    pub fn series(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }
    /// A horizontal grey dashed reference line at `y`, with a legend entry
    /// (empty label: none).
    pub fn hline(mut self, y: f64, label: impl Into<String>) -> Self {
        self.hlines.push((y, label.into()));
        self
    }
    /// Logarithmic x axis (non-positive x values are skipped).
    pub fn log_x(mut self, on: bool) -> Self {
        self.log_x = on;
        self
    }
    /// Logarithmic y axis (non-positive y values are skipped).
    pub fn log_y(mut self, on: bool) -> Self {
        self.log_y = on;
        self
    }
    /// Fix the x range instead of fitting the data.
    pub fn x_range(mut self, lo: f64, hi: f64) -> Self {
        self.x_range = Some((lo, hi));
        self
    }
    /// Fix the y range instead of fitting the data.
    pub fn y_range(mut self, lo: f64, hi: f64) -> Self {
        self.y_range = Some((lo, hi));
        self
    }
    /// Where the legend goes.
    pub fn legend(mut self, legend: Legend) -> Self {
        self.legend = legend;
        self
    }

    fn ok_x(&self, x: f64) -> bool {
        x.is_finite() && (!self.log_x || x > 0.0)
    }
    fn ok_y(&self, y: f64) -> bool {
        y.is_finite() && (!self.log_y || y > 0.0)
    }

    /// Data ranges (before padding).
    fn data_ranges(&self) -> Option<(Range, Range)> {
        let mut xs = Span::default();
        let mut ys = Span::default();
        for s in &self.series {
            for (i, &(x, y)) in s.points.iter().enumerate() {
                if !self.ok_x(x) {
                    continue;
                }
                let mut any = false;
                if self.ok_y(y) {
                    ys.add(y);
                    any = true;
                    if let Some(e) = s.errors.as_ref().map(|e| e[i]).filter(|e| e.is_finite()) {
                        for v in [y - e.abs(), y + e.abs()] {
                            if self.ok_y(v) {
                                ys.add(v);
                            }
                        }
                    }
                }
                if let Some((lo, hi)) = &s.band {
                    for v in [lo[i], hi[i]] {
                        if self.ok_y(v) {
                            ys.add(v);
                            any = true;
                        }
                    }
                }
                if any {
                    xs.add(x);
                }
            }
        }
        let (x, y) = (xs.get()?, ys.get()?);
        Some((x, y))
    }

    fn ranges(&self) -> Result<(Range, Range), PlotError> {
        let (dx, dy) = self
            .data_ranges()
            .ok_or_else(|| PlotError::EmptyData("line plot".into()))?;
        let mut dy = dy;
        for &(y, _) in &self.hlines {
            if self.ok_y(y) {
                dy = (dy.0.min(y), dy.1.max(y));
            }
        }
        let x = match self.x_range {
            Some(r) => checked_range("x range", r, self.log_x)?,
            None => pad(dx, self.log_x),
        };
        let y = match self.y_range {
            Some(r) => checked_range("y range", r, self.log_y)?,
            None => pad(dy, self.log_y),
        };
        Ok((x, y))
    }

    /// Map a data x to chart coordinates (log10 on a log axis).
    fn tx(&self, x: f64) -> f64 {
        if self.log_x { x.log10() } else { x }
    }
    /// Map a data y to chart coordinates (log10 on a log axis).
    fn ty(&self, y: f64) -> f64 {
        if self.log_y { y.log10() } else { y }
    }

    fn draw_chart<'a, DB: DrawingBackend + 'a>(
        &self,
        chart: &mut ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
        style: &Style,
        (x0, x1): (f64, f64),
        (y0, y1): (f64, f64),
    ) -> Result<(), PlotError> {
        // A tick that is zero up to the rounding of the tick arithmetic
        // (5.55e-17 on an axis from -0.4 to 0.4) reads 0.
        let (sx, sy) = (
            (self.tx(x1) - self.tx(x0)).abs(),
            (self.ty(y1) - self.ty(y0)).abs(),
        );
        let fmt_x = |v: &f64| axis_tick(snap_tick(*v, sx), self.log_x);
        let fmt_y = |v: &f64| axis_tick(snap_tick(*v, sy), self.log_y);
        chart
            .configure_mesh()
            .x_desc(self.x_label.clone().unwrap_or_default())
            .y_desc(self.y_label.clone().unwrap_or_default())
            .label_style((font::FAMILY, style.tick_px).into_font())
            .axis_desc_style((font::FAMILY, style.label_px).into_font())
            .x_label_formatter(&fmt_x)
            .y_label_formatter(&fmt_y)
            .x_labels(if self.log_x {
                log_label_count(self.tx(x0), self.tx(x1))
            } else {
                7
            })
            .y_labels(if self.log_y {
                log_label_count(self.ty(y0), self.ty(y1))
            } else {
                7
            })
            .bold_line_style(RGBColor(0xE3, 0xE3, 0xE3).stroke_width(1))
            .light_line_style(TRANSPARENT)
            .axis_style(BLACK.stroke_width(1))
            .draw()?;

        let lw_default = style.line_width;
        let color_of = |i: usize, s: &Series| s.color.unwrap_or_else(|| palette(i));
        // Data y to chart y, clipped to the visible range (a non-positive
        // value on a log axis goes to the bottom).
        let clip_y = |v: f64| {
            if self.log_y && v <= 0.0 {
                self.ty(y0)
            } else {
                self.ty(v.clamp(y0, y1))
            }
        };
        let (cx0, cx1) = (self.tx(x0), self.tx(x1));

        // Bands first, behind everything.
        for (i, s) in self.series.iter().enumerate() {
            let Some((lo, hi)) = &s.band else { continue };
            let color = color_of(i, s);
            let rows: Vec<Option<(f64, f64, f64)>> = s
                .points
                .iter()
                .zip(lo.iter().zip(hi))
                .map(|(&(x, _), (&l, &h))| {
                    (self.ok_x(x) && l.is_finite() && h.is_finite())
                        .then(|| (self.tx(x), clip_y(l.min(h)), clip_y(l.max(h))))
                })
                .collect();
            for run in runs(&rows) {
                let mut poly: Vec<(f64, f64)> = run.iter().map(|r| (r.0, r.2)).collect();
                poly.extend(run.iter().rev().map(|r| (r.0, r.1)));
                chart.draw_series(std::iter::once(Polygon::new(
                    poly,
                    color.mix(0.22).filled(),
                )))?;
            }
            if let Some(label) = &s.band_label {
                let side = (style.legend_px * 0.7) as i32;
                chart
                    .draw_series(std::iter::empty::<Circle<(f64, f64), u32>>())?
                    .label(label.clone())
                    .legend(move |(x, y)| {
                        Rectangle::new(
                            [(x, y - side / 2), (x + 2 * side, y + side / 2)],
                            color.mix(0.3).filled(),
                        )
                    });
            }
        }

        // Reference lines.
        for (y, label) in &self.hlines {
            if !self.ok_y(*y) {
                continue;
            }
            let grey = RGBColor(0x70, 0x70, 0x70);
            let st = grey.stroke_width(lw_default);
            let (d, g) = dash(LineKind::Dashed, lw_default);
            let cy = self.ty(*y);
            let anno =
                chart.draw_series(DashedLineSeries::new([(cx0, cy), (cx1, cy)], d, g, st))?;
            if !label.is_empty() {
                let w = legend_width(style);
                anno.label(label.clone())
                    .legend(move |c| legend_glyph(c, LineKind::Dashed, grey, lw_default, None, w));
            }
        }

        for (i, s) in self.series.iter().enumerate() {
            let color = color_of(i, s);
            let lw = s.line_width.unwrap_or(lw_default);
            let r = s.marker_radius.unwrap_or(style.marker_radius);
            let ok: Vec<Option<(f64, f64)>> = s
                .points
                .iter()
                .map(|&(x, y)| (self.ok_x(x) && self.ok_y(y)).then_some((x, y)))
                .collect();
            let chart_pt = |(x, y): (f64, f64)| (self.tx(x), self.ty(y));
            if s.line {
                for run in runs(&ok) {
                    if run.len() < 2 {
                        continue;
                    }
                    let st = color.stroke_width(lw);
                    let pts = run.iter().map(|&p| chart_pt(p));
                    match s.kind {
                        LineKind::Solid => {
                            chart.draw_series(LineSeries::new(pts, st))?;
                        }
                        kind => {
                            let (d, g) = dash(kind, lw);
                            chart.draw_series(DashedLineSeries::new(pts, d, g, st))?;
                        }
                    }
                }
            }
            if s.markers {
                chart.draw_series(
                    ok.iter()
                        .flatten()
                        .map(|&p| Circle::new(chart_pt(p), r, color.filled())),
                )?;
            }
            // Error bars last, over the markers: a bar shorter than its
            // marker still shows its caps (see `error_bar`).
            if let Some(errors) = &s.errors {
                let shade = bar_shade(color);
                let bar_r = if s.markers { r } else { 0 };
                let bars: Vec<_> = ok
                    .iter()
                    .zip(errors)
                    .filter_map(|(p, e)| {
                        let (x, y) = (*p)?;
                        if !e.is_finite() {
                            return None;
                        }
                        let cx = self.tx(x);
                        let at = chart.backend_coord(&(cx, self.ty(y))).1;
                        let up = chart.backend_coord(&(cx, clip_y(y + e.abs()))).1;
                        let down = chart.backend_coord(&(cx, clip_y(y - e.abs()))).1;
                        let px = ErrorBarPixels::new(at, up, down, bar_r);
                        Some(((cx, self.ty(y)), px))
                    })
                    .collect();
                draw_error_bars(chart, &bars, shade, lw.max(1))?;
            }
            if let Some(label) = &s.label {
                let w = legend_width(style);
                let (kind, line, marker) = (s.kind, s.line, s.markers.then_some(r));
                chart
                    .draw_series(std::iter::empty::<Circle<(f64, f64), u32>>())?
                    .label(label.clone())
                    .legend(move |c| {
                        legend_glyph(c, kind, color, if line { lw } else { 0 }, marker, w)
                    });
            }
        }

        let labelled = self
            .series
            .iter()
            .any(|s| s.label.is_some() || s.band_label.is_some())
            || self.hlines.iter().any(|(_, l)| !l.is_empty());
        if let (Some(pos), true) = (self.legend.position(), labelled) {
            chart
                .configure_series_labels()
                .position(pos)
                .margin(style.margin)
                .legend_area_size(legend_width(style) + 8)
                .label_font((font::FAMILY, style.legend_px).into_font())
                .background_style(WHITE.mix(0.88))
                .border_style(RGBColor(0xA0, 0xA0, 0xA0))
                .draw()?;
        }
        Ok(())
    }
}

impl Plot for LinePlot {
    fn validate(&self) -> Result<(), PlotError> {
        if self.series.is_empty() {
            return Err(PlotError::EmptyData("line plot (no series)".into()));
        }
        for (i, s) in self.series.iter().enumerate() {
            s.check(i)?;
        }
        self.ranges().map(|_| ())
    }

    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        style: &Style,
    ) -> Result<(), PlotError> {
        self.validate()?;
        font::ensure()?;
        let (xr, yr) = self.ranges()?;
        let area = titled(area, self.title.as_deref(), style.title_px)?;
        let left = style.y_label_area(4);
        let bottom = style.x_label_area();
        let margin = style.margin;
        inner_size(&area, margin, left, bottom)?;
        let mut builder = ChartBuilder::on(&area);
        builder
            .margin(margin)
            .margin_right(margin * 2)
            .x_label_area_size(bottom)
            .y_label_area_size(left);
        let (cx, cy) = (
            (self.tx(xr.0), self.tx(xr.1)),
            (self.ty(yr.0), self.ty(yr.1)),
        );
        let mut chart = builder.build_cartesian_2d(cx.0..cx.1, cy.0..cy.1)?;
        self.draw_chart(&mut chart, style, xr, yr)
    }
}

/// A closed interval `(lo, hi)`.
type Range = (f64, f64);

/// Running minimum and maximum.
#[derive(Default)]
struct Span(Option<(f64, f64)>);

impl Span {
    fn add(&mut self, v: f64) {
        self.0 = Some(match self.0 {
            Some((lo, hi)) => (lo.min(v), hi.max(v)),
            None => (v, v),
        });
    }
    fn get(&self) -> Option<(f64, f64)> {
        self.0
    }
}

/// Pad a data range a little (multiplicatively on a log axis); widen a
/// single value to a visible range.
pub(crate) fn pad((lo, hi): (f64, f64), log: bool) -> (f64, f64) {
    if log {
        let (a, b) = (lo.ln(), hi.ln());
        let p = if b - a > 1e-12 {
            0.04 * (b - a)
        } else {
            std::f64::consts::LN_10 * 0.5
        };
        ((a - p).exp(), (b + p).exp())
    } else {
        let span = hi - lo;
        let p = if span > 1e-12 * hi.abs().max(lo.abs()) && span > 0.0 {
            0.04 * span
        } else if lo != 0.0 {
            0.1 * lo.abs()
        } else {
            0.5
        };
        (lo - p, hi + p)
    }
}

fn checked_range(
    what: &'static str,
    (lo, hi): (f64, f64),
    log: bool,
) -> Result<(f64, f64), PlotError> {
    if !(lo.is_finite() && hi.is_finite() && lo < hi) || (log && lo <= 0.0) {
        return Err(PlotError::Invalid {
            what,
            why: format!(
                "[{lo}, {hi}] is not an increasing finite range{}",
                if log { " of positive values" } else { "" }
            ),
        });
    }
    Ok((lo, hi))
}

/// Maximal runs of `Some` values.
pub(crate) fn runs<T: Copy>(items: &[Option<T>]) -> Vec<Vec<T>> {
    let mut out = Vec::new();
    let mut cur = Vec::new();
    for it in items {
        match it {
            Some(v) => cur.push(*v),
            None if !cur.is_empty() => out.push(std::mem::take(&mut cur)),
            None => {}
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

/// Dash and gap lengths for a line kind and width.
pub(crate) fn dash(kind: LineKind, lw: u32) -> (u32, u32) {
    match kind {
        LineKind::Solid => (1000, 0),
        LineKind::Dashed => (5 * lw + 8, 3 * lw + 5),
        LineKind::Dotted => (lw + 2, 2 * lw + 4),
    }
}

pub(crate) fn legend_width(style: &Style) -> u32 {
    (style.legend_px * 2.0).round() as u32
}

/// The legend symbol of a line of `kind` (width `lw`, 0 for none) with an
/// optional marker of radius `marker`, `w` pixels wide, at `(x, y)`.
pub(crate) fn legend_glyph<'a, DB: DrawingBackend + 'a>(
    (x, y): (i32, i32),
    kind: LineKind,
    color: RGBColor,
    lw: u32,
    marker: Option<u32>,
    w: u32,
) -> impl IntoDynElement<'a, DB, (i32, i32)> + use<'a, DB> {
    let w = w as i32;
    let line_style = if lw == 0 {
        TRANSPARENT.stroke_width(1)
    } else {
        color.stroke_width(lw)
    };
    let (d, g) = match kind {
        LineKind::Solid => (w, 0),
        other => {
            let (d, g) = dash(other, lw.max(1));
            (d as i32, g as i32)
        }
    };
    // Up to four dashes cover the symbol.
    let seg = |k: i32| {
        let a = (k * (d + g)).min(w);
        let b = (a + d).min(w);
        PathElement::new(vec![(a, 0), (b, 0)], line_style)
    };
    let dot = match marker {
        Some(r) => Circle::new((w / 2, 0), r, color.filled()),
        None => Circle::new((w / 2, 0), 0, TRANSPARENT.filled()),
    };
    EmptyElement::at((x, y)) + seg(0) + seg(1) + seg(2) + seg(3) + dot
}

/// How many tick labels to ask for on a log axis spanning `lo..hi` (in
/// log10 units): over two decades or more, at most one per decade, so that
/// the ticks fall on whole decades (asking for more makes plotters place
/// them at half decades, `10^0.5 = 3.16…`); over less, the usual nine.
pub(crate) fn log_label_count(lo: f64, hi: f64) -> usize {
    let span = hi - lo;
    if span.is_finite() && span >= 2.0 {
        (span.floor() as usize + 1).min(9)
    } else {
        9
    }
}

/// A tick label: on a log axis the chart coordinate is log10 of the value,
/// whole decades read `10ⁿ` and other ticks two significant digits.
pub(crate) fn axis_tick(v: f64, log: bool) -> String {
    if !log {
        return format_tick(v);
    }
    let k = v.round();
    if (v - k).abs() < 1e-9 && k.abs() < 400.0 {
        match k as i32 {
            -1 => "0.1".to_string(),
            0 => "1".to_string(),
            1 => "10".to_string(),
            n => format!("10{}", superscript(n)),
        }
    } else {
        two_digits(10f64.powf(v))
    }
}

#[cfg(test)]
mod tick_tests {
    use super::*;

    #[test]
    fn log_ticks_read_well() {
        assert_eq!(axis_tick(0.5, true), "3.2");
        assert_eq!(axis_tick(-0.5, true), "0.32");
        assert_eq!(axis_tick(4.5, true), "3.2×10⁴");
        assert_eq!(axis_tick(2.5, true), "320");
        assert_eq!(axis_tick(3.0, true), "10³");
        assert_eq!(log_label_count(0.0, 4.5), 5);
        assert_eq!(log_label_count(-18.0, -13.0), 6);
        assert_eq!(log_label_count(-20.0, 2.0), 9);
        assert_eq!(log_label_count(0.0, 1.5), 9);
    }
}
