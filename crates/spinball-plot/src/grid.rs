//! Several plots in one image, for example 4 tables × 4 values of α.

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::colormap::viridis;
use crate::error::PlotError;
use crate::font;
use crate::format::format_tick_on;
use crate::histogram::HistogramPlot;
use crate::lines::LinePlot;
use crate::phase_plot::{MapPlot, Scatter3d};
use crate::plot::{Plot, titled};
use crate::style::Style;
use crate::table_plot::TablePlot;

/// Any plot of this crate, so that a [`Grid`] can hold a mix of them.
#[derive(Debug, Clone)]
pub enum Panel {
    /// A table (and trajectory).
    Table(TablePlot),
    /// Curves.
    Lines(LinePlot),
    /// A histogram.
    Histogram(HistogramPlot),
    /// A nested grid.
    Grid(Grid),
    /// A map of values over a plane.
    Map(MapPlot),
    /// A 3-D scatter.
    Scatter3d(Scatter3d),
    /// An empty cell.
    Empty,
}

impl From<TablePlot> for Panel {
    fn from(p: TablePlot) -> Self {
        Panel::Table(p)
    }
}
impl From<LinePlot> for Panel {
    fn from(p: LinePlot) -> Self {
        Panel::Lines(p)
    }
}
impl From<HistogramPlot> for Panel {
    fn from(p: HistogramPlot) -> Self {
        Panel::Histogram(p)
    }
}
impl From<Grid> for Panel {
    fn from(p: Grid) -> Self {
        Panel::Grid(p)
    }
}
impl From<MapPlot> for Panel {
    fn from(p: MapPlot) -> Self {
        Panel::Map(p)
    }
}
impl From<Scatter3d> for Panel {
    fn from(p: Scatter3d) -> Self {
        Panel::Scatter3d(p)
    }
}

impl Plot for Panel {
    fn validate(&self) -> Result<(), PlotError> {
        match self {
            Panel::Table(p) => p.validate(),
            Panel::Lines(p) => p.validate(),
            Panel::Histogram(p) => p.validate(),
            Panel::Grid(p) => p.validate(),
            Panel::Map(p) => p.validate(),
            Panel::Scatter3d(p) => p.validate(),
            Panel::Empty => Ok(()),
        }
    }
    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        style: &Style,
    ) -> Result<(), PlotError> {
        match self {
            Panel::Table(p) => p.draw(area, style),
            Panel::Lines(p) => p.draw(area, style),
            Panel::Histogram(p) => p.draw(area, style),
            Panel::Grid(p) => p.draw(area, style),
            Panel::Map(p) => p.draw(area, style),
            Panel::Scatter3d(p) => p.draw(area, style),
            Panel::Empty => Ok(()),
        }
    }
}

/// A horizontal colour bar for the [`viridis`] map, labelled from `min` to
/// `max` (for a trajectory: collision number 0 to n).
#[derive(Debug, Clone, PartialEq)]
pub struct Colorbar {
    label: String,
    min: f64,
    max: f64,
}

impl Colorbar {
    /// A bar from `min` (dark) to `max` (light) with an axis label.
    pub fn new(label: impl Into<String>, min: f64, max: f64) -> Self {
        Colorbar {
            label: label.into(),
            min,
            max,
        }
    }

    fn validate(&self) -> Result<(), PlotError> {
        if self.min.is_finite() && self.max.is_finite() && self.min < self.max {
            Ok(())
        } else {
            Err(PlotError::Invalid {
                what: "colour bar range",
                why: format!(
                    "[{}, {}] is not an increasing finite range",
                    self.min, self.max
                ),
            })
        }
    }

    /// Height the bar needs (pixels).
    fn height(&self, style: &Style) -> u32 {
        (style.tick_px * 1.6 + style.label_px * 1.8).round() as u32 + 28 + style.margin
    }

    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        style: &Style,
    ) -> Result<(), PlotError> {
        let (w, _) = area.dim_in_pixel();
        let side = w / 5;
        let mut chart = ChartBuilder::on(area)
            .margin_left(side)
            .margin_right(side)
            .margin_top(style.margin / 2)
            .margin_bottom(style.margin / 2)
            .x_label_area_size((style.tick_px * 1.6 + style.label_px * 1.8).round() as u32)
            .build_cartesian_2d(self.min..self.max, 0.0..1.0)?;
        let fmt = |v: &f64| format_tick_on(*v, self.max - self.min);
        chart
            .configure_mesh()
            .disable_mesh()
            .disable_y_axis()
            .x_desc(self.label.clone())
            .label_style((font::FAMILY, style.tick_px).into_font())
            .axis_desc_style((font::FAMILY, style.label_px).into_font())
            .x_label_formatter(&fmt)
            .x_labels(6)
            .draw()?;
        const N: usize = 256;
        let step = (self.max - self.min) / N as f64;
        chart.draw_series((0..N).map(|i| {
            let x = self.min + i as f64 * step;
            Rectangle::new(
                [(x, 0.0), (x + step * 1.01, 1.0)],
                viridis((i as f64 + 0.5) / N as f64).filled(),
            )
        }))?;
        chart.draw_series(std::iter::once(Rectangle::new(
            [(self.min, 0.0), (self.max, 1.0)],
            BLACK.stroke_width(1),
        )))?;
        Ok(())
    }
}

/// Panels in `rows × cols` cells, filled row by row, with an optional title
/// and a shared [`Colorbar`] at the bottom. Each panel is drawn with the
/// [`Style`] for the size of its cell, so text stays readable.
///
/// ```no_run
/// use spinball_geometry::{Circle, Stadium};
/// use spinball_plot::{Colorbar, Grid, Plot, TablePlot};
/// Grid::new(1, 2)
///     .title("Two tables")
///     .panel(TablePlot::new(&Circle::unit()).title("circle"))
///     .panel(TablePlot::new(&Stadium::new(1.0)?).title("stadium"))
///     .colorbar(Colorbar::new("collision number", 0.0, 500.0))
///     .save_png("out/two.png", 1600, 700)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Grid {
    rows: usize,
    cols: usize,
    panels: Vec<Panel>,
    title: Option<String>,
    colorbar: Option<Colorbar>,
}

impl Grid {
    /// An empty grid of `rows × cols` cells.
    pub fn new(rows: usize, cols: usize) -> Self {
        Grid {
            rows,
            cols,
            panels: Vec::new(),
            title: None,
            colorbar: None,
        }
    }
    /// Title above all panels.
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }
    /// Add a panel in the next cell.
    pub fn panel(mut self, panel: impl Into<Panel>) -> Self {
        self.panels.push(panel.into());
        self
    }
    /// Add a panel in the next cell (by reference, for loops).
    pub fn push(&mut self, panel: impl Into<Panel>) -> &mut Self {
        self.panels.push(panel.into());
        self
    }
    /// A colour bar under the panels.
    pub fn colorbar(mut self, colorbar: Colorbar) -> Self {
        self.colorbar = Some(colorbar);
        self
    }
}

impl Plot for Grid {
    fn validate(&self) -> Result<(), PlotError> {
        if self.rows == 0 || self.cols == 0 {
            return Err(PlotError::Invalid {
                what: "grid shape",
                why: format!("{}×{} has no cells", self.rows, self.cols),
            });
        }
        if self.panels.len() > self.rows * self.cols {
            return Err(PlotError::GridFull {
                rows: self.rows,
                cols: self.cols,
                panels: self.panels.len(),
            });
        }
        if self.panels.iter().all(|p| matches!(p, Panel::Empty)) {
            return Err(PlotError::EmptyData("grid (no panels)".into()));
        }
        if let Some(c) = &self.colorbar {
            c.validate()?;
        }
        self.panels.iter().try_for_each(Plot::validate)
    }

    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        style: &Style,
    ) -> Result<(), PlotError> {
        self.validate()?;
        font::ensure()?;
        let area = titled(area, self.title.as_deref(), style.title_px)?;
        let (w, h) = area.dim_in_pixel();
        let cell_style = Style::for_size(w / self.cols as u32, h / self.rows as u32);
        let (body, bar) = match &self.colorbar {
            Some(c) => {
                let bh = c.height(&cell_style).min(h / 3);
                let (a, b) = area.split_vertically(h - bh);
                (a, Some((b, c)))
            }
            None => (area, None),
        };
        let (bw, bh) = body.dim_in_pixel();
        let cell_style = Style::for_size(bw / self.cols as u32, bh / self.rows as u32);
        for (cell, panel) in body
            .split_evenly((self.rows, self.cols))
            .iter()
            .zip(&self.panels)
        {
            panel.draw(cell, &cell_style)?;
        }
        if let Some((bar_area, c)) = bar {
            c.draw(&bar_area, &cell_style)?;
        }
        Ok(())
    }
}
