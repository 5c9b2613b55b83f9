//! A value with its error, printed so that the error shows.
//!
//! `λ = 0.0003 ± 0.0000` says nothing about either number: a fixed number
//! of decimals hides a small error and pads a large one. The convention of
//! measured quantities is to round the error to two significant digits
//! and the value to the same decimal place, which is what [`PlusMinus`]
//! prints: `0.000312 ± 0.000041`, `0.1865 ± 0.0038`, `12.4 ± 1.3`.

use std::fmt;

/// Most decimals ever printed (past this an `f64` has no more digits).
const MAX_DECIMALS: i32 = 17;

/// `value ± error`, printed with the error to two significant digits and
/// the value to the same decimal place. An error of zero or one that is
/// not finite prints the value in full (`0.5 ± 0`, `0.5 ± NaN`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[must_use]
pub struct PlusMinus {
    /// The value.
    pub value: f64,
    /// Its error (a standard error, a total error bound).
    pub error: f64,
}

impl PlusMinus {
    /// `value ± error`.
    pub const fn new(value: f64, error: f64) -> Self {
        PlusMinus { value, error }
    }

    /// The decimal places that show two significant digits of the error,
    /// or `None` if the error has none (zero, NaN, infinite).
    #[must_use]
    pub fn decimals(self) -> Option<usize> {
        let e = self.error.abs();
        if !(e.is_finite() && e > 0.0) {
            return None;
        }
        // Round first: 0.0996 shows as 0.10 (two digits of 0.1), not 0.0996.
        let mut places = 1 - e.log10().floor() as i32;
        let scale = 10f64.powi(places.clamp(-300, 300));
        if (e * scale).round() >= 100.0 {
            places -= 1;
        }
        Some(places.clamp(0, MAX_DECIMALS) as usize)
    }
}

impl fmt::Display for PlusMinus {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.decimals() {
            Some(d) => write!(f, "{:.d$} ± {:.d$}", self.value, self.error.abs()),
            None => write!(f, "{} ± {}", self.value, self.error),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_error_keeps_two_significant_digits() {
        let cases = [
            (0.000_312_4, 0.000_041_2, "0.000312 ± 0.000041"),
            (0.186_54, 0.003_81, "0.1865 ± 0.0038"),
            (12.43, 1.27, "12.4 ± 1.3"),
            (1234.5, 56.0, "1234 ± 56"),
            (1234.5, 560.0, "1234 ± 560"),
            // Rounding up to the next decade: two digits of 0.10.
            (0.5, 0.0996, "0.50 ± 0.10"),
            (0.5, 0.0, "0.5 ± 0"),
            (-2.5e-7, 3.3e-9, "-0.0000002500 ± 0.0000000033"),
        ];
        for (v, e, want) in cases {
            assert_eq!(PlusMinus::new(v, e).to_string(), want, "{v} ± {e}");
        }
        assert_eq!(PlusMinus::new(0.5, f64::NAN).to_string(), "0.5 ± NaN");
        assert_eq!(PlusMinus::new(1.0, 1e-300).decimals(), Some(17));
    }
}
