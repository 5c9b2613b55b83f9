//! Sizes of text and lines, chosen from the image size.

/// Font sizes (pixels) and line widths used by every plot.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Style {
    /// Plot titles.
    pub title_px: f64,
    /// Axis labels (with units).
    pub label_px: f64,
    /// Tick labels.
    pub tick_px: f64,
    /// Legend entries.
    pub legend_px: f64,
    /// Curves and outlines.
    pub line_width: u32,
    /// Radius of point markers.
    pub marker_radius: u32,
    /// Blank margin around a plot.
    pub margin: u32,
}

/// No text smaller than this (pixels).
pub const MIN_TEXT_PX: f64 = 16.0;

impl Style {
    /// Sizes for a plot of `width × height` pixels: at 1200 × 700 px titles
    /// 30 px, axis labels 26 px, ticks and legend 22 px, lines 2 px. Other
    /// sizes scale with the square root of the size ratio (up to 2×), and no
    /// text goes below 16 px.
    pub fn for_size(width: u32, height: u32) -> Style {
        // Text shrinks more slowly than the image (square root), so the
        // panels of a grid stay readable.
        let s = (width as f64 / 1200.0)
            .min(height as f64 / 700.0)
            .sqrt()
            .clamp(0.75, 2.0);
        let px = |base: f64| (base * s).max(MIN_TEXT_PX).round();
        Style {
            title_px: px(30.0),
            label_px: px(26.0),
            tick_px: px(22.0),
            legend_px: px(22.0),
            line_width: (2.0 * s).round().max(1.0) as u32,
            marker_radius: (4.5 * s).round().max(3.0) as u32,
            margin: (14.0 * s).round() as u32,
        }
    }

    /// The size of an axis description area holding tick labels of about
    /// `chars` characters (pixels): used for the y axis.
    pub(crate) fn y_label_area(&self, chars: usize) -> u32 {
        (self.tick_px * (0.62 * chars as f64 + 0.8) + self.label_px * 1.6).round() as u32
    }

    /// Height of the x axis description area (pixels).
    pub(crate) fn x_label_area(&self) -> u32 {
        (self.tick_px * 1.6 + self.label_px * 1.6).round() as u32
    }
}

impl Default for Style {
    /// The sizes for a 1200 × 800 px image.
    fn default() -> Self {
        Style::for_size(1200, 800)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_never_below_16_px() {
        for (w, h) in [(100, 100), (400, 300), (1200, 800), (3000, 2000)] {
            let s = Style::for_size(w, h);
            for px in [s.title_px, s.label_px, s.tick_px, s.legend_px] {
                assert!(px >= MIN_TEXT_PX, "{px} px at {w}×{h}");
            }
        }
        let s = Style::for_size(1200, 800);
        assert!(s.tick_px >= 20.0 && s.title_px >= 28.0);
    }
}
