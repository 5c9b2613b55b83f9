//! A number printed to a few significant digits: the fit windows, medians
//! and predictions of the summaries read `104.5`, not `104.51918840857512`.

use std::fmt;

/// `value` rounded to `digits` significant digits and printed in Rust's
/// shortest form (`Significant(41562.49, 4)` prints `41560`,
/// `Significant(0.19999999999999996, 4)` prints `0.2`). Zero, NaN and the
/// infinities print as they are.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Significant(pub f64, pub u8);

impl Significant {
    /// The rounded value.
    #[must_use]
    pub fn rounded(self) -> f64 {
        let Significant(x, digits) = self;
        if x == 0.0 || !x.is_finite() {
            return x;
        }
        // Scale by an exact power of ten so that the rounding adds no
        // binary noise (0.3 stays 0.3, not 0.30000000000000004).
        let k = i32::from(digits.max(1)) - 1 - x.abs().log10().floor() as i32;
        if k >= 0 {
            let p = 10f64.powi(k);
            (x * p).round() / p
        } else {
            let p = 10f64.powi(-k);
            (x / p).round() * p
        }
    }
}

impl fmt::Display for Significant {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.rounded())
    }
}

#[cfg(test)]
mod tests {
    use super::Significant;

    #[test]
    fn prints_the_digits_asked_for() {
        let cases = [
            (41562.49291237783, 4, "41560"),
            (104.51918840857512, 4, "104.5"),
            (0.19999999999999996, 4, "0.2"),
            (3.5707963267948966, 6, "3.5708"),
            (0.000116549, 3, "0.000117"),
            (-257.31198761501633, 4, "-257.3"),
            (0.0, 4, "0"),
        ];
        for (x, d, want) in cases {
            assert_eq!(Significant(x, d).to_string(), want, "{x} to {d}");
        }
        assert!(Significant(f64::NAN, 4).rounded().is_nan());
    }
}
