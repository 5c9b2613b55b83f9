//! A shaded interval of the x axis: where a quantity is uncertain by
//! convention, such as the range of chaos thresholds (0.001–0.05) over
//! which an FTLE histogram's chaotic fraction is quoted.

use plotters::style::RGBColor;

/// A vertical band from `lo` to `hi` across a chart, shaded behind the
/// data, with a legend entry.
#[derive(Debug, Clone, PartialEq)]
pub struct XBand {
    pub(crate) label: String,
    pub(crate) lo: f64,
    pub(crate) hi: f64,
    pub(crate) color: RGBColor,
}

/// Default shade of a band: a light orange that reads behind blue bars.
const BAND: RGBColor = RGBColor(0xE6, 0x9F, 0x00);

impl XBand {
    /// A band over `[lo, hi]` (either order) labelled `label`.
    pub fn new(label: impl Into<String>, lo: f64, hi: f64) -> Self {
        // A NaN end stays (and hides the band), where min/max would drop it.
        let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
        XBand {
            label: label.into(),
            lo,
            hi,
            color: BAND,
        }
    }

    /// The shade (drawn at 25 % opacity).
    pub fn color(mut self, color: RGBColor) -> Self {
        self.color = color;
        self
    }

    /// The part of the band inside the visible `range`, if any: what is
    /// shaded (a band wholly outside the axis is not drawn; one with a
    /// non-finite end neither).
    #[must_use]
    pub fn visible_in(&self, (a, b): (f64, f64)) -> Option<(f64, f64)> {
        if !(self.lo.is_finite() && self.hi.is_finite()) {
            return None;
        }
        let (lo, hi) = (self.lo.max(a), self.hi.min(b));
        (lo < hi || (lo == hi && self.lo == self.hi && (a..=b).contains(&lo))).then_some((lo, hi))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_band_is_clipped_to_the_axis() {
        let b = XBand::new("thresholds", 0.05, 0.001);
        assert_eq!((b.lo, b.hi), (0.001, 0.05));
        assert_eq!(b.visible_in((0.0, 1.0)), Some((0.001, 0.05)));
        assert_eq!(b.visible_in((0.01, 1.0)), Some((0.01, 0.05)));
        assert_eq!(b.visible_in((0.1, 1.0)), None);
        assert_eq!(XBand::new("x", f64::NAN, 1.0).visible_in((0.0, 2.0)), None);
    }
}
