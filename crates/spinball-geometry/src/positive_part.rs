//! The positive part of a distance, a flight time or a discriminant, as
//! every cast clamps it at zero.
//!
//! `f64::max(x, 0.0)` leaves the sign of a zero result unspecified (`-0.0`
//! or `+0.0` for `x = -0.0`), so whether the scalar casts agreed bitwise
//! with the lane kernels, which clamp with `maxpd` (`+0.0` for either
//! zero, `0.0` for NaN), depended on how the compiler lowered it. The casts
//! clamp with [`positive_part`] instead, which states that rule.

/// `x` if it is greater than zero, else `+0.0` (for `-0.0`, a negative `x`
/// and NaN alike): what `maxpd(x, 0)` computes.
#[inline]
#[must_use]
pub(crate) fn positive_part(x: f64) -> f64 {
    if x > 0.0 { x } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::positive_part;

    #[test]
    fn zeros_negatives_and_nan_clamp_to_plus_zero() {
        for x in [
            -0.0,
            0.0,
            -1.0,
            f64::NEG_INFINITY,
            f64::NAN,
            -f64::MIN_POSITIVE,
        ] {
            assert_eq!(positive_part(x).to_bits(), 0.0f64.to_bits(), "{x}");
        }
        for x in [f64::MIN_POSITIVE, 5e-324, 1.0, f64::INFINITY] {
            assert_eq!(positive_part(x).to_bits(), x.to_bits(), "{x}");
        }
    }
}
