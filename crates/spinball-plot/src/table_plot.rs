//! A table, and optionally a trajectory on it coloured from early to late.

use glam::DVec2;
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::colormap::viridis;
use crate::error::PlotError;
use crate::font;
use crate::format::format_tick_on;
use crate::plot::{Plot, inner_size, titled};
use crate::style::Style;
use spinball_geometry::{Outline, ToOutline};

/// Fill of the table's interior.
pub(crate) const TABLE_FILL: RGBColor = RGBColor(0xF4, 0xF5, 0xF8);
/// Fill of obstacles (holes).
pub(crate) const OBSTACLE_FILL: RGBColor = RGBColor(0xC8, 0xCB, 0xD2);

/// A table drawn to scale (equal aspect), with an optional trajectory.
///
/// The trajectory is the polyline through the given points (the start and
/// the collision points, in order); the leg from point `i` to `i + 1` is
/// coloured [`viridis`]`(i / (n − 2))`, dark early and light late (or by a
/// value per leg, [`leg_values`](Self::leg_values)), and the start is
/// marked with a black dot. Legs with a non-finite end are skipped.
///
/// ```no_run
/// use spinball_geometry::{DVec2, Sinai};
/// use spinball_plot::{Plot, TablePlot};
/// let path = [DVec2::new(-1.5, -1.5), DVec2::new(2.0, 0.3), DVec2::new(0.5, 2.0)];
/// TablePlot::new(&Sinai::new(2.0, 1.0)?)
///     .title("Sinai L = 2, R = 1")
///     .trajectory(path)
///     .axes(true)
///     .save_png("out/sinai.png", 900, 900)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct TablePlot {
    outline: Outline,
    trajectory: Option<Vec<DVec2>>,
    leg_values: Option<(Vec<f64>, (f64, f64))>,
    title: Option<String>,
    axes: bool,
}

impl TablePlot {
    /// The outline of `table` (a built-in table, a `Table`, a `SegmentTable`
    /// or an [`Outline`]).
    pub fn new(table: &impl ToOutline) -> Self {
        TablePlot {
            outline: table.outline(),
            trajectory: None,
            leg_values: None,
            title: None,
            axes: false,
        }
    }

    /// A title above the table.
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    /// The trajectory: start point then collision points, in order.
    pub fn trajectory(mut self, points: impl IntoIterator<Item = DVec2>) -> Self {
        self.trajectory = Some(points.into_iter().collect());
        self
    }

    /// Colour the legs of the trajectory by a value instead of by time:
    /// leg `i` (from point `i` to `i + 1`) gets [`viridis`] of `values[i]`
    /// over `range` (for example the spin `u` during that flight, with the
    /// range of a [`Colorbar`](crate::Colorbar) beside the table). One
    /// value per leg; a non-finite one draws grey.
    pub fn leg_values(mut self, values: impl IntoIterator<Item = f64>, range: (f64, f64)) -> Self {
        self.leg_values = Some((values.into_iter().collect(), range));
        self
    }

    /// The colour of leg `i` of `legs`: by value if
    /// [`leg_values`](Self::leg_values) were given, else by time (dark
    /// early, light late).
    #[must_use]
    pub fn leg_colour(&self, i: usize, legs: usize) -> RGBColor {
        match &self.leg_values {
            Some((v, (lo, hi))) => {
                viridis((v.get(i).copied().unwrap_or(f64::NAN) - lo) / (hi - lo))
            }
            None => viridis(i as f64 / legs.saturating_sub(1).max(1) as f64),
        }
    }

    /// Draw x and y axes with ticks (off by default: a table needs none).
    pub fn axes(mut self, on: bool) -> Self {
        self.axes = on;
        self
    }

    fn finite_trajectory_points(&self) -> usize {
        self.trajectory
            .as_ref()
            .map_or(0, |t| t.iter().filter(|p| p.is_finite()).count())
    }
}

impl Plot for TablePlot {
    fn validate(&self) -> Result<(), PlotError> {
        let outline_ok = self
            .outline
            .loops()
            .iter()
            .any(|l| l.points().len() >= 2 && l.points().iter().all(|p| p.is_finite()));
        if !outline_ok {
            return Err(PlotError::EmptyData("table outline".into()));
        }
        if self.trajectory.is_some() && self.finite_trajectory_points() < 2 {
            return Err(PlotError::EmptyData("trajectory".into()));
        }
        if let Some((values, (lo, hi))) = &self.leg_values {
            let legs = self
                .trajectory
                .as_ref()
                .map_or(0, |t| t.len().saturating_sub(1));
            if values.len() != legs {
                return Err(PlotError::LengthMismatch {
                    what: "leg values of the trajectory".into(),
                    expected: legs,
                    got: values.len(),
                });
            }
            if !(lo.is_finite() && hi.is_finite() && lo < hi) {
                return Err(PlotError::Invalid {
                    what: "leg value range",
                    why: format!("[{lo}, {hi}] is not an increasing finite range"),
                });
            }
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
        let also = self.trajectory.iter().flatten().copied();
        let mut chart = table_chart(&area, &self.outline, also, self.axes, style)?;
        let xy = |p: &DVec2| (p.x, p.y);
        if let Some(path) = &self.trajectory {
            let legs = path.len().saturating_sub(1);
            let width = style.line_width.div_ceil(2);
            chart.draw_series(
                path.windows(2)
                    .enumerate()
                    .filter(|(_, w)| w[0].is_finite() && w[1].is_finite())
                    .map(|(i, w)| {
                        PathElement::new(
                            vec![xy(&w[0]), xy(&w[1])],
                            self.leg_colour(i, legs).stroke_width(width),
                        )
                    }),
            )?;
        }
        draw_walls(&mut chart, &self.outline, style)?;
        if let Some(start) = self.trajectory.iter().flatten().find(|p| p.is_finite()) {
            let r = style.marker_radius;
            chart.draw_series(std::iter::once(Circle::new(
                xy(start),
                r + 2,
                WHITE.filled(),
            )))?;
            chart.draw_series(std::iter::once(Circle::new(xy(start), r, BLACK.filled())))?;
        }
        Ok(())
    }
}

/// The chart of a table drawn to scale: equal aspect, framing the outline
/// and the finite points of `also`, with axes if asked, the interior and the
/// obstacles filled (the walls are drawn by [`draw_walls`], after whatever
/// goes on the table).
pub(crate) fn table_chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    outline: &Outline,
    also: impl Iterator<Item = DVec2>,
    axes: bool,
    style: &Style,
) -> Result<TableChart<'a, DB>, PlotError> {
    let (mut lo, mut hi) = outline
        .bounds()
        .ok_or_else(|| PlotError::EmptyData("table outline".into()))?;
    for p in also.filter(|p| p.is_finite()) {
        lo = lo.min(p);
        hi = hi.max(p);
    }
    let pad = 0.03 * (hi - lo).max_element().max(f64::MIN_POSITIVE);
    let (lo, hi) = (lo - pad, hi + pad);
    let (left, bottom) = if axes {
        (style.y_label_area(4), style.x_label_area())
    } else {
        (0, 0)
    };
    let margin = style.margin / 2;
    let (pw, ph) = inner_size(area, margin, left, bottom)?;
    // Equal aspect: one length unit is the same number of pixels on both axes.
    let scale = (pw as f64 / (hi.x - lo.x)).min(ph as f64 / (hi.y - lo.y));
    let c = 0.5 * (lo + hi);
    let half = 0.5 * DVec2::new(pw as f64, ph as f64) / scale;
    let mut chart = ChartBuilder::on(area)
        .margin(margin)
        .x_label_area_size(bottom)
        .y_label_area_size(left)
        .build_cartesian_2d(c.x - half.x..c.x + half.x, c.y - half.y..c.y + half.y)?;
    if axes {
        let tick = (font::FAMILY, style.tick_px).into_font();
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x")
            .y_desc("y")
            .label_style(tick)
            .axis_desc_style((font::FAMILY, style.label_px).into_font())
            .x_label_formatter(&|v| format_tick_on(*v, 2.0 * half.x))
            .y_label_formatter(&|v| format_tick_on(*v, 2.0 * half.y))
            .axis_style(BLACK.stroke_width(1))
            .draw()?;
    }
    let xy = |p: &DVec2| (p.x, p.y);
    for lp in outline.loops().iter().filter(|l| !l.is_hole()) {
        chart.draw_series(std::iter::once(Polygon::new(
            lp.points().iter().map(xy).collect::<Vec<_>>(),
            TABLE_FILL.filled(),
        )))?;
    }
    for lp in outline.loops().iter().filter(|l| l.is_hole()) {
        chart.draw_series(std::iter::once(Polygon::new(
            lp.points().iter().map(xy).collect::<Vec<_>>(),
            OBSTACLE_FILL.filled(),
        )))?;
    }
    Ok(chart)
}

/// A chart in table coordinates.
pub(crate) type TableChart<'a, DB> = ChartContext<
    'a,
    DB,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// The walls of `outline`, in black, on top of what the chart holds.
pub(crate) fn draw_walls<DB: DrawingBackend>(
    chart: &mut TableChart<'_, DB>,
    outline: &Outline,
    style: &Style,
) -> Result<(), PlotError> {
    for lp in outline.loops() {
        chart.draw_series(std::iter::once(PathElement::new(
            lp.points().iter().map(|p| (p.x, p.y)).collect::<Vec<_>>(),
            BLACK.stroke_width(style.line_width.max(2)),
        )))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_geometry::Circle;

    #[test]
    fn legs_are_coloured_by_time_or_by_value() {
        let path = [DVec2::ZERO, DVec2::X * 0.5, DVec2::Y * 0.5, -DVec2::X * 0.5];
        let by_time = TablePlot::new(&Circle::unit()).trajectory(path);
        assert_eq!(by_time.leg_colour(0, 3), viridis(0.0));
        assert_eq!(by_time.leg_colour(2, 3), viridis(1.0));
        let by_spin = by_time.clone().leg_values([-1.0, 0.0, 1.0], (-1.0, 1.0));
        assert!(by_spin.validate().is_ok());
        assert_eq!(by_spin.leg_colour(0, 3), viridis(0.0));
        assert_eq!(by_spin.leg_colour(1, 3), viridis(0.5));
        assert_eq!(by_spin.leg_colour(2, 3), viridis(1.0));
        // One value per leg, over an increasing range.
        let short = by_time.clone().leg_values([0.0, 1.0], (0.0, 1.0));
        assert!(matches!(
            short.validate(),
            Err(PlotError::LengthMismatch {
                expected: 3,
                got: 2,
                ..
            })
        ));
        let flat = by_time.leg_values([0.0; 3], (0.0, 0.0));
        assert!(matches!(flat.validate(), Err(PlotError::Invalid { .. })));
    }
}
