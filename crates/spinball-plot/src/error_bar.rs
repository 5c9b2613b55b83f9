//! Error bars that stay visible over their markers.
//!
//! A standard error is often smaller than the marker of its point (λ known
//! to 0.3 % on a plot spanning a factor 3): a bar drawn in the marker's
//! colour under the marker then vanishes, and the reader cannot tell a
//! tiny error from a missing one. So the bar is drawn *over* the marker, in
//! a darker shade of the series colour on a thin white halo, with caps
//! wider than the marker: a bar shorter than the marker shows as its two
//! caps sticking out on both sides (one line when the error is below a
//! pixel), never as nothing.

use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

use crate::error::PlotError;

/// Where an error bar's strokes go, in pixels relative to its point (y
/// grows downwards, as on the screen).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[must_use]
pub struct ErrorBarPixels {
    /// Offset of the upper end (`y + e`), ≤ 0.
    pub top: i32,
    /// Offset of the lower end (`y − e`), ≥ 0.
    pub bottom: i32,
    /// Half the width of a cap: always beyond the marker's edge.
    pub cap_half: i32,
}

/// How far a cap reaches beyond the marker's edge (pixels).
pub const CAP_OVERHANG: u32 = 3;

impl ErrorBarPixels {
    /// The bar of a point drawn at pixel row `at`, whose ends `y ± e` fall
    /// on pixel rows `upper` and `lower`, over a marker of radius
    /// `marker_radius`. The rows may come in either order.
    pub fn new(at: i32, upper: i32, lower: i32, marker_radius: u32) -> Self {
        let (a, b) = (upper.min(lower) - at, upper.max(lower) - at);
        ErrorBarPixels {
            top: a.min(0),
            bottom: b.max(0),
            cap_half: (marker_radius + CAP_OVERHANG) as i32,
        }
    }

    /// Whether the whole bar hides inside the marker (the caps still
    /// show).
    #[must_use]
    pub fn inside_marker(&self, marker_radius: u32) -> bool {
        let r = marker_radius as i32;
        self.top >= -r && self.bottom <= r
    }

    /// The strokes: the vertical bar, then the upper and lower caps.
    #[must_use]
    pub fn strokes(&self) -> [[(i32, i32); 2]; 3] {
        let c = self.cap_half;
        [
            [(0, self.top), (0, self.bottom)],
            [(-c, self.top), (c, self.top)],
            [(-c, self.bottom), (c, self.bottom)],
        ]
    }
}

/// The shade an error bar of a series of colour `c` is drawn in: the same
/// hue at 45 % of its brightness, dark enough to read over a marker of `c`.
#[must_use]
pub fn bar_shade(c: RGBColor) -> RGBColor {
    let d = |v: u8| (f64::from(v) * 0.45).round() as u8;
    RGBColor(d(c.0), d(c.1), d(c.2))
}

/// Draw error bars over what `chart` holds: for each `(point, pixels)` a
/// white halo, then the strokes in `color` (already [`bar_shade`]d),
/// `width` pixels wide.
pub(crate) fn draw_error_bars<'a, DB: DrawingBackend + 'a>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
    bars: &[((f64, f64), ErrorBarPixels)],
    color: RGBColor,
    width: u32,
) -> Result<(), PlotError> {
    for (stroke, w) in [(WHITE, width + 2), (color, width)] {
        let st = stroke.stroke_width(w);
        chart.draw_series(bars.iter().map(|&(at, px)| {
            let [bar, upper, lower] = px.strokes().map(|s| PathElement::new(s.to_vec(), st));
            EmptyElement::at(at) + bar + upper + lower
        }))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_bar_reaches_its_ends() {
        // Point at row 300, y + e at row 250, y − e at row 350.
        let b = ErrorBarPixels::new(300, 250, 350, 5);
        assert_eq!((b.top, b.bottom), (-50, 50));
        assert_eq!(b.cap_half, 8);
        assert!(!b.inside_marker(5));
        assert_eq!(b.strokes()[1], [(-8, -50), (8, -50)]);
    }

    #[test]
    fn a_bar_shorter_than_the_marker_keeps_caps_beyond_it() {
        let b = ErrorBarPixels::new(300, 302, 298, 6);
        assert_eq!(
            (b.top, b.bottom),
            (-2, 2),
            "order of the rows does not matter"
        );
        assert!(b.inside_marker(6));
        // The caps stick out CAP_OVERHANG pixels on each side of the marker.
        assert!(b.cap_half > 6);
        assert_eq!(b.cap_half - 6, CAP_OVERHANG as i32);
        // A zero error is still one visible line through the marker.
        let z = ErrorBarPixels::new(300, 300, 300, 6);
        assert_eq!((z.top, z.bottom), (0, 0));
        assert_eq!(z.strokes()[1], [(-9, 0), (9, 0)]);
    }

    #[test]
    fn the_shade_is_darker_in_every_channel() {
        let c = RGBColor(0x00, 0x72, 0xB2);
        let d = bar_shade(c);
        assert!(d.0 <= c.0 && d.1 < c.1 && d.2 < c.2);
        assert_eq!(d, RGBColor(0, 51, 80));
    }

    /// Drawn: a series whose errors are far below a pixel still shows its
    /// caps, a run of bar-shade pixels wider than the marker.
    #[test]
    fn tiny_errors_show_caps_wider_than_the_marker() {
        use crate::{LinePlot, Plot, Series, Style, palette};
        let (w, h) = (400u32, 300u32);
        let mut buf = vec![0u8; (w * h * 3) as usize];
        let style = Style::for_size(w, h);
        {
            let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
            root.fill(&WHITE).unwrap();
            LinePlot::new()
                .series(Series::new("λ", [(0.0, 1.0), (0.5, 2.0), (1.0, 3.0)]).errors([1e-9; 3]))
                .draw(&root, &style)
                .unwrap();
            root.present().unwrap();
        }
        let shade = bar_shade(palette(0));
        let is_shade = |x: u32, y: u32| {
            let i = ((y * w + x) * 3) as usize;
            (buf[i], buf[i + 1], buf[i + 2]) == (shade.0, shade.1, shade.2)
        };
        // The longest horizontal run of shade pixels: a cap.
        let mut longest = 0;
        for y in 0..h {
            let mut run = 0;
            for x in 0..w {
                run = if is_shade(x, y) { run + 1 } else { 0 };
                longest = longest.max(run);
            }
        }
        let r = style.marker_radius as i32;
        assert!(
            longest >= 2 * (r + CAP_OVERHANG as i32),
            "longest cap run {longest} px, marker diameter {} px",
            2 * r + 1
        );
    }
}
