//! Pictures of phase space: a value per cell of a grid (an FTLE map) or per
//! point (a section coloured by spin), on the same axes, with an outline of
//! a region drawn over them; and a 3-D cloud of points seen from an angle.

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::colormap::viridis;
use crate::error::PlotError;
use crate::font;
use crate::format::format_tick_on;
use crate::plot::{Plot, inner_size, titled};
use crate::style::Style;

/// Colour of cells without a value.
const MISSING: RGBColor = RGBColor(0xFF, 0xFF, 0xFF);
/// Colour of outlines drawn over a map.
const OUTLINE: RGBColor = RGBColor(0xE0, 0x1A, 0x1A);

/// A value per cell of a `rows × columns` grid over a rectangle.
#[derive(Debug, Clone, PartialEq)]
struct Cells {
    columns: usize,
    rows: usize,
    /// Row-major, row 0 at the bottom; `None` draws white.
    values: Vec<Option<f64>>,
}

/// Values on a plane: a colour map of grid cells and/or points coloured by a
/// value (both through [`viridis`] over one value range), and outlines of
/// regions of the grid drawn in red.
///
/// ```no_run
/// use spinball_plot::{MapPlot, Plot};
/// // A 2 × 2 map with one cell missing, and two coloured points.
/// MapPlot::new((0.0, 2.0), (-1.0, 1.0), (0.0, 1.0))
///     .cells(2, 2, vec![Some(0.1), Some(0.5), None, Some(0.9)])
///     .points(vec![(0.5, 0.5, 0.3), (1.5, -0.5, 0.8)])
///     .labels("s", "sin θ")
///     .save_png("out/map.png", 900, 700)?;
/// # Ok::<(), spinball_plot::PlotError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct MapPlot {
    x_range: (f64, f64),
    y_range: (f64, f64),
    value_range: (f64, f64),
    cells: Option<Cells>,
    points: Vec<(f64, f64, f64)>,
    markers: Vec<(f64, f64, RGBColor)>,
    outline: Option<Vec<bool>>,
    title: Option<String>,
    x_label: String,
    y_label: String,
}

impl MapPlot {
    /// A plot of `x_range × y_range`; values map to colours over
    /// `value_range` (dark at its start, light at its end, clamped).
    pub fn new(x_range: (f64, f64), y_range: (f64, f64), value_range: (f64, f64)) -> Self {
        MapPlot {
            x_range,
            y_range,
            value_range,
            cells: None,
            points: Vec::new(),
            markers: Vec::new(),
            outline: None,
            title: None,
            x_label: String::new(),
            y_label: String::new(),
        }
    }
    /// A grid of `columns × rows` cells covering the plot, row-major with
    /// row 0 at the bottom; `None` cells are left white.
    pub fn cells(mut self, columns: usize, rows: usize, values: Vec<Option<f64>>) -> Self {
        self.cells = Some(Cells {
            columns,
            rows,
            values,
        });
        self
    }
    /// Points `(x, y, value)` coloured by value (non-finite ones skipped).
    pub fn points(mut self, points: Vec<(f64, f64, f64)>) -> Self {
        self.points = points;
        self
    }
    /// Markers `(x, y, colour)` drawn over everything, each a filled circle
    /// ringed in black (positions of special points, such as periodic
    /// orbits coloured by their stability; non-finite ones skipped).
    pub fn markers(mut self, markers: Vec<(f64, f64, RGBColor)>) -> Self {
        self.markers = markers;
        self
    }
    /// Outline, in red, the region of the grid's cells where `mask` is true
    /// (same layout as [`cells`](Self::cells)).
    pub fn outline(mut self, mask: Vec<bool>) -> Self {
        self.outline = Some(mask);
        self
    }
    /// A title.
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }
    /// Axis labels.
    pub fn labels(mut self, x: impl Into<String>, y: impl Into<String>) -> Self {
        self.x_label = x.into();
        self.y_label = y.into();
        self
    }

    fn colour(&self, v: f64) -> RGBColor {
        let (lo, hi) = self.value_range;
        viridis((v - lo) / (hi - lo))
    }
}

fn increasing(what: &'static str, (a, b): (f64, f64)) -> Result<(), PlotError> {
    if a.is_finite() && b.is_finite() && a < b {
        Ok(())
    } else {
        Err(PlotError::Invalid {
            what,
            why: format!("[{a}, {b}] is not an increasing finite range"),
        })
    }
}

impl Plot for MapPlot {
    fn validate(&self) -> Result<(), PlotError> {
        increasing("x range", self.x_range)?;
        increasing("y range", self.y_range)?;
        increasing("value range", self.value_range)?;
        let cells = self.cells.as_ref().map_or(0, |c| c.values.len());
        if let Some(c) = &self.cells
            && (c.columns == 0 || c.rows == 0 || c.values.len() != c.columns * c.rows)
        {
            return Err(PlotError::LengthMismatch {
                what: "map cells".into(),
                expected: c.columns * c.rows,
                got: c.values.len(),
            });
        }
        if let Some(mask) = &self.outline
            && mask.len() != cells
        {
            return Err(PlotError::LengthMismatch {
                what: "outline mask".into(),
                expected: cells,
                got: mask.len(),
            });
        }
        let drawn = self
            .cells
            .as_ref()
            .is_some_and(|c| c.values.iter().flatten().any(|v| v.is_finite()))
            || self
                .points
                .iter()
                .any(|p| p.0.is_finite() && p.1.is_finite());
        if !drawn {
            return Err(PlotError::EmptyData("map (no finite cell or point)".into()));
        }
        Ok(())
    }

    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        style: &Style,
    ) -> Result<(), PlotError> {
        self.validate()?;
        font::ensure()?;
        let area = titled(area, self.title.as_deref(), style.title_px)?;
        let (left, bottom) = (style.y_label_area(4), style.x_label_area());
        inner_size(&area, style.margin, left, bottom)?;
        let (x0, x1) = self.x_range;
        let (y0, y1) = self.y_range;
        let mut chart = ChartBuilder::on(&area)
            .margin(style.margin)
            .x_label_area_size(bottom)
            .y_label_area_size(left)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        let fmt_x = |v: &f64| format_tick_on(*v, x1 - x0);
        let fmt_y = |v: &f64| format_tick_on(*v, y1 - y0);
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(self.x_label.clone())
            .y_desc(self.y_label.clone())
            .label_style((font::FAMILY, style.tick_px).into_font())
            .axis_desc_style((font::FAMILY, style.label_px).into_font())
            .x_label_formatter(&fmt_x)
            .y_label_formatter(&fmt_y)
            .x_labels(7)
            .y_labels(5)
            .draw()?;
        if let Some(c) = &self.cells {
            let (dx, dy) = ((x1 - x0) / c.columns as f64, (y1 - y0) / c.rows as f64);
            let corner = |i: usize, j: usize| (x0 + i as f64 * dx, y0 + j as f64 * dy);
            chart.draw_series((0..c.rows).flat_map(|j| {
                (0..c.columns).map(move |i| {
                    let colour = match c.values[j * c.columns + i] {
                        Some(v) if v.is_finite() => self.colour(v),
                        _ => MISSING,
                    };
                    Rectangle::new([corner(i, j), corner(i + 1, j + 1)], colour.filled())
                })
            }))?;
            if let Some(mask) = &self.outline {
                let at = |i: usize, j: usize| mask[j * c.columns + i];
                let mut edges = Vec::new();
                for j in 0..c.rows {
                    for i in 0..c.columns {
                        if !at(i, j) {
                            continue;
                        }
                        // Edges to cells outside the region (or the border).
                        if i == 0 || !at(i - 1, j) {
                            edges.push([corner(i, j), corner(i, j + 1)]);
                        }
                        if i + 1 == c.columns || !at(i + 1, j) {
                            edges.push([corner(i + 1, j), corner(i + 1, j + 1)]);
                        }
                        if j == 0 || !at(i, j - 1) {
                            edges.push([corner(i, j), corner(i + 1, j)]);
                        }
                        if j + 1 == c.rows || !at(i, j + 1) {
                            edges.push([corner(i, j + 1), corner(i + 1, j + 1)]);
                        }
                    }
                }
                let stroke = OUTLINE.stroke_width(style.line_width.max(2));
                chart.draw_series(
                    edges
                        .into_iter()
                        .map(|e| PathElement::new(e.to_vec(), stroke)),
                )?;
            }
        }
        let radius = (style.marker_radius / 2).max(1);
        chart.draw_series(
            self.points
                .iter()
                .filter(|p| p.0.is_finite() && p.1.is_finite())
                .map(|&(x, y, v)| Circle::new((x, y), radius, self.colour(v).filled())),
        )?;
        let big = style.marker_radius.max(3) + 1;
        for &(x, y, colour) in self
            .markers
            .iter()
            .filter(|m| m.0.is_finite() && m.1.is_finite())
        {
            chart.draw_series([
                Circle::new((x, y), big + 1, BLACK.filled()),
                Circle::new((x, y), big, colour.filled()),
            ])?;
        }
        Ok(())
    }
}

/// Points in 3-D coloured by a value, seen from an azimuth and an
/// elevation, inside the wire frame of their bounding box (each axis scaled
/// to the box's side): the 3-D section `(s, sin θ, u)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Scatter3d {
    points: Vec<([f64; 3], f64)>,
    ranges: [(f64, f64); 3],
    value_range: (f64, f64),
    labels: [String; 3],
    azimuth: f64,
    elevation: f64,
    title: Option<String>,
}

impl Scatter3d {
    /// Points `(xyz, value)` in the box `ranges`, coloured over
    /// `value_range`; seen from azimuth 35° and elevation 25°.
    pub fn new(
        points: Vec<([f64; 3], f64)>,
        ranges: [(f64, f64); 3],
        value_range: (f64, f64),
    ) -> Self {
        Scatter3d {
            points,
            ranges,
            value_range,
            labels: Default::default(),
            azimuth: 35f64.to_radians(),
            elevation: 25f64.to_radians(),
            title: None,
        }
    }
    /// The viewing direction (degrees).
    pub fn view(mut self, azimuth_deg: f64, elevation_deg: f64) -> Self {
        self.azimuth = azimuth_deg.to_radians();
        self.elevation = elevation_deg.to_radians();
        self
    }
    /// Names of the three axes.
    pub fn labels(mut self, x: &str, y: &str, z: &str) -> Self {
        self.labels = [x.into(), y.into(), z.into()];
        self
    }
    /// A title.
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    /// Screen coordinates of a point of the unit cube `[0, 1]³` (x to the
    /// right, z up), by an orthographic view.
    fn project(&self, p: [f64; 3]) -> (f64, f64) {
        let (sa, ca) = self.azimuth.sin_cos();
        let (se, ce) = self.elevation.sin_cos();
        let (x, y, z) = (p[0] - 0.5, p[1] - 0.5, p[2] - 0.5);
        (ca * x - sa * y, ce * z + se * (sa * x + ca * y))
    }

    fn unit(&self, p: [f64; 3]) -> [f64; 3] {
        std::array::from_fn(|k| (p[k] - self.ranges[k].0) / (self.ranges[k].1 - self.ranges[k].0))
    }
}

impl Plot for Scatter3d {
    fn validate(&self) -> Result<(), PlotError> {
        for (k, name) in ["x range", "y range", "z range"].into_iter().enumerate() {
            increasing(name, self.ranges[k])?;
        }
        increasing("value range", self.value_range)?;
        if !self
            .points
            .iter()
            .any(|(p, _)| p.iter().all(|c| c.is_finite()))
        {
            return Err(PlotError::EmptyData("3-D scatter (no finite point)".into()));
        }
        Ok(())
    }

    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        style: &Style,
    ) -> Result<(), PlotError> {
        self.validate()?;
        font::ensure()?;
        let area = titled(area, self.title.as_deref(), style.title_px)?;
        inner_size(&area, style.margin, 0, 0)?;
        let r = 1.1;
        let mut chart = ChartBuilder::on(&area)
            .margin(style.margin)
            .build_cartesian_2d(-r..r, -r..r)?;
        // The wire frame: the 12 edges of the unit cube.
        let corner = |c: usize| [(c & 1) as f64, ((c >> 1) & 1) as f64, ((c >> 2) & 1) as f64];
        let mut edges = Vec::new();
        for a in 0..8usize {
            for bit in [1, 2, 4] {
                if a & bit == 0 {
                    edges.push((self.project(corner(a)), self.project(corner(a | bit))));
                }
            }
        }
        let grey = RGBColor(0x90, 0x90, 0x90).stroke_width(1);
        chart.draw_series(
            edges
                .into_iter()
                .map(|(p, q)| PathElement::new(vec![p, q], grey)),
        )?;
        let (lo, hi) = self.value_range;
        let radius = (style.marker_radius / 2).max(1);
        chart.draw_series(
            self.points
                .iter()
                .filter(|(p, _)| p.iter().all(|c| c.is_finite()))
                .map(|&(p, v)| {
                    let colour = viridis((v - lo) / (hi - lo));
                    Circle::new(self.project(self.unit(p)), radius, colour.filled())
                }),
        )?;
        // Axis names beside the middle of three edges from the origin
        // corner (pushed away from the cube), with the range ends.
        let font = (font::FAMILY, style.tick_px).into_font().color(&BLACK);
        let centre = self.project([0.5; 3]);
        for k in 0..3 {
            // x and y on the front edges from the origin corner, z on the
            // left vertical edge (the front one runs through the cloud).
            let mut mid = if k == 2 { [0.0, 1.0, 0.0] } else { [0.0; 3] };
            mid[k] = 0.5;
            let (x, y) = self.project(mid);
            let (dx, dy) = (x - centre.0, y - centre.1);
            let norm = dx.hypot(dy).max(1e-9);
            let at = (x + 0.12 * dx / norm - 0.15, y + 0.08 * dy / norm);
            let (a, b) = self.ranges[k];
            let text = format!("{} [{:.3}, {:.3}]", self.labels[k], a, b);
            chart.draw_series(std::iter::once(Text::new(text, at, font.clone())))?;
        }
        Ok(())
    }
}
