//! Colours: one sequential map for "early → late" and one categorical palette
//! for "which table / which α", so every figure of the project looks alike.

use plotters::style::RGBColor;

use crate::lines::pad;

/// The viridis colormap (van der Walt & Smith, matplotlib's default) at ten
/// evenly spaced stops, `t = 0, 1/9, …, 1`; values in between are linear
/// interpolations in sRGB.
const VIRIDIS: [(u8, u8, u8); 10] = [
    (0x44, 0x01, 0x54),
    (0x48, 0x28, 0x78),
    (0x3E, 0x4A, 0x89),
    (0x31, 0x68, 0x8E),
    (0x26, 0x82, 0x8E),
    (0x1F, 0x9E, 0x89),
    (0x35, 0xB7, 0x79),
    (0x6D, 0xCD, 0x59),
    (0xB4, 0xDE, 0x2C),
    (0xFD, 0xE7, 0x25),
];

/// The viridis colour at `t ∈ [0, 1]`: dark purple `#440154` at 0, yellow
/// `#FDE725` at 1, perceptually uniform and readable in grey-scale.
///
/// `t` outside `[0, 1]` is clamped; a NaN `t` gives mid grey `#808080`.
pub fn viridis(t: f64) -> RGBColor {
    if t.is_nan() {
        return RGBColor(0x80, 0x80, 0x80);
    }
    let x = t.clamp(0.0, 1.0) * (VIRIDIS.len() - 1) as f64;
    let i = (x.floor() as usize).min(VIRIDIS.len() - 2);
    let f = x - i as f64;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    let mix = |p: u8, q: u8| (p as f64 + f * (q as f64 - p as f64)).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The range a colour scale of `values` spans: their finite minimum and
/// maximum, widened a little around a single value (so that a constant
/// quantity, such as the spin at α = 0, still gets a scale). `None` if no
/// value is finite.
#[must_use]
pub fn value_range(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    let (lo, hi) = values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(None, |acc: Option<(f64, f64)>, v| {
            Some(acc.map_or((v, v), |(a, b)| (a.min(v), b.max(v))))
        })?;
    Some(if hi > lo {
        (lo, hi)
    } else {
        pad((lo, hi), false)
    })
}

/// The categorical palette: Okabe & Ito's colour-blind-safe colours, ordered
/// for white backgrounds (blue, vermillion, bluish green, reddish purple,
/// orange, sky blue, black, yellow).
pub const PALETTE: [RGBColor; 8] = [
    RGBColor(0x00, 0x72, 0xB2),
    RGBColor(0xD5, 0x5E, 0x00),
    RGBColor(0x00, 0x9E, 0x73),
    RGBColor(0xCC, 0x79, 0xA7),
    RGBColor(0xE6, 0x9F, 0x00),
    RGBColor(0x56, 0xB4, 0xE9),
    RGBColor(0x00, 0x00, 0x00),
    RGBColor(0xF0, 0xE4, 0x42),
];

/// The `i`-th colour of [`PALETTE`], cycling.
pub fn palette(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn viridis_endpoints_and_clamping() {
        assert_eq!(viridis(0.0), RGBColor(0x44, 0x01, 0x54));
        assert_eq!(viridis(1.0), RGBColor(0xFD, 0xE7, 0x25));
        assert_eq!(viridis(-3.0), viridis(0.0));
        assert_eq!(viridis(7.0), viridis(1.0));
        assert_eq!(viridis(f64::NAN), RGBColor(0x80, 0x80, 0x80));
        assert_eq!(viridis(5.0 / 9.0), RGBColor(0x1F, 0x9E, 0x89));
    }

    #[test]
    fn viridis_gets_lighter() {
        let lum = |c: RGBColor| 0.2126 * c.0 as f64 + 0.7152 * c.1 as f64 + 0.0722 * c.2 as f64;
        let mut last = -1.0;
        for i in 0..=100 {
            let l = lum(viridis(i as f64 / 100.0));
            assert!(l >= last, "luminance falls at t = {}", i as f64 / 100.0);
            last = l;
        }
    }

    #[test]
    fn value_ranges_are_never_empty() {
        assert_eq!(value_range([0.2, f64::NAN, -0.4]), Some((-0.4, 0.2)));
        let (lo, hi) = value_range([0.0, 0.0]).unwrap();
        assert!(lo < 0.0 && hi > 0.0);
        assert_eq!(value_range([f64::NAN]), None);
    }

    #[test]
    fn palette_cycles() {
        assert_eq!(palette(0), PALETTE[0]);
        assert_eq!(palette(PALETTE.len() + 2), PALETTE[2]);
    }
}
