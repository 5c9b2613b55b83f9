//! Tick labels that read like a paper: `0.25`, `5000`, `10⁻¹⁵`, `2×10⁶`.

/// Format a tick value: plain decimals between `1e-3` and `1e5` (trailing
/// zeros and rounding noise dropped), powers of ten as `10ⁿ` and other large
/// or small values as `m×10ⁿ`.
pub fn format_tick(v: f64) -> String {
    if !v.is_finite() {
        return String::new();
    }
    if v == 0.0 {
        return "0".to_string();
    }
    let a = v.abs();
    if (1e-3..1e5).contains(&a) {
        let s = format!("{v:.6}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        return if s == "-0" {
            "0".to_string()
        } else {
            s.to_string()
        };
    }
    let mut e = a.log10().floor() as i32;
    let mut m = v / 10f64.powi(e);
    if (m.abs() - 10.0).abs() < 1e-9 {
        e += 1;
        m /= 10.0;
    }
    let pow = format!("10{}", superscript(e));
    if (m.abs() - 1.0).abs() < 1e-9 {
        if m < 0.0 { format!("−{pow}") } else { pow }
    } else {
        let ms = format!("{m:.2}");
        let ms = ms.trim_end_matches('0').trim_end_matches('.');
        format!("{ms}×{pow}")
    }
}

/// A tick that is zero up to the rounding of the tick arithmetic reads 0:
/// `v` is taken as 0 when `|v| < 1e-9 · span`, with `span` the axis'
/// length (plotters places a tick at `-2.22e-16` on an axis from -1 to 1).
#[must_use]
pub fn snap_tick(v: f64, span: f64) -> f64 {
    if v.abs() < 1e-9 * span.abs() { 0.0 } else { v }
}

/// [`format_tick`] of a tick on an axis of length `span`, rounding noise
/// shown as 0 ([`snap_tick`]).
#[must_use]
pub fn format_tick_on(v: f64, span: f64) -> String {
    format_tick(snap_tick(v, span))
}

/// `x` to two significant digits, as a legend or a log-axis tick shows a
/// number: `0.32`, `3.2`, `320`, `3.2×10⁴`, `-0.0012`, `3.1×10⁻⁴`; zero is `0` and a
/// non-finite `x` is empty.
#[must_use]
pub fn two_digits(x: f64) -> String {
    if x == 0.0 {
        return "0".to_string();
    }
    if !x.is_finite() {
        return String::new();
    }
    let sign = if x < 0.0 { "-" } else { "" };
    let x = x.abs();
    let mut e = x.log10().floor() as i32;
    // Rounding to two digits can carry into the next decade (9.96 → 10).
    if (x / 10f64.powi(e - 1)).round() >= 100.0 {
        e += 1;
    }
    if (-3..4).contains(&e) {
        let decimals = (1 - e).max(0) as usize;
        let r = 10f64.powi(e - 1);
        format!("{sign}{:.decimals$}", (x / r).round() * r)
    } else {
        let m = x / 10f64.powi(e);
        format!("{sign}{m:.1}×10{}", superscript(e))
    }
}

/// `n` in superscript digits (`−15` → `⁻¹⁵`).
pub(crate) fn superscript(n: i32) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::new();
    if n < 0 {
        s.push('⁻');
    }
    for c in n.unsigned_abs().to_string().chars() {
        s.push(DIGITS[c.to_digit(10).unwrap_or(0) as usize]);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks() {
        assert_eq!(format_tick(0.0), "0");
        assert_eq!(format_tick(0.1 + 0.2), "0.3");
        assert_eq!(format_tick(0.25), "0.25");
        assert_eq!(format_tick(5000.0), "5000");
        assert_eq!(format_tick(-1.5), "-1.5");
        assert_eq!(format_tick(1e-15), "10⁻¹⁵");
        assert_eq!(format_tick(1e6), "10⁶");
        assert_eq!(format_tick(2.5e6), "2.5×10⁶");
        assert_eq!(format_tick(f64::NAN), "");
    }

    #[test]
    fn two_significant_digits() {
        assert_eq!(two_digits(0.003_12), "0.0031");
        assert_eq!(two_digits(0.000_312), "3.1×10⁻⁴");
        assert_eq!(two_digits(0.0123), "0.012");
        assert_eq!(two_digits(1.234), "1.2");
        assert_eq!(two_digits(320.0), "320");
        assert_eq!(two_digits(9.96), "10");
        assert_eq!(two_digits(-0.0012), "-0.0012");
        assert_eq!(two_digits(3.1e-6), "3.1×10⁻⁶");
        assert_eq!(two_digits(0.0), "0");
        assert_eq!(two_digits(f64::NAN), "");
    }

    #[test]
    fn rounding_noise_on_an_axis_reads_zero() {
        assert_eq!(format_tick(-2.220446049250313e-16), "-2.22×10⁻¹⁶");
        assert_eq!(format_tick_on(-2.220446049250313e-16, 2.0), "0");
        assert_eq!(format_tick_on(5.551115123125783e-17, 0.8), "0");
        // A real small tick on a small axis stays.
        assert_eq!(format_tick_on(1e-15, 4e-15), "10⁻¹⁵");
        assert_eq!(format_tick_on(0.25, 2.0), "0.25");
    }
}
