//! The invariant measure of the spinning billiard map, and boxes of the
//! section measured with it.
//!
//! Documented in the group docs (`phase_space/mod.rs`), section "The invariant measure".

use std::{f64::consts::PI, ops::Range};

use rand::Rng;
use spinball_core::SpinLaw;
use spinball_geometry::Boundary;

use super::section::SectionPoint;
use crate::error::AnalysisError;

/// A box of the section in the coordinates in which the invariant measure is
/// uniform: arc length `s`, and `v∥/|V|`, `w/|V|` (`w = √α u`).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SectionBox {
    /// Arc lengths `[s0, s1)`.
    pub s: Range<f64>,
    /// `v∥/|V|` in `[lo, hi)`.
    pub v_par: Range<f64>,
    /// `√α u/|V|` in `[lo, hi)`; at α = 0 (`w ≡ 0`) the box holds points
    /// only if this range contains 0.
    pub w: Range<f64>,
}

impl SectionBox {
    /// A box with every `w` (the range `[−2, 2)` covers the unit disk).
    #[must_use]
    pub fn new(s: Range<f64>, v_par: Range<f64>) -> Self {
        SectionBox {
            s,
            v_par,
            w: -2.0..2.0,
        }
    }

    /// The same box restricted to `w ∈ [lo, hi)`.
    #[must_use]
    pub fn with_w(mut self, w: Range<f64>) -> Self {
        self.w = w;
        self
    }

    /// Whether the section point `p` of a ball with spin parameter `alpha`
    /// lies in the box.
    #[must_use]
    #[inline]
    pub fn contains(&self, p: &SectionPoint, alpha: f64) -> bool {
        let (v, w) = p.disk(alpha);
        self.s.contains(&p.s) && self.v_par.contains(&v) && self.w.contains(&w)
    }

    fn validate(&self) -> Result<(), AnalysisError> {
        for (name, r) in [("s", &self.s), ("v_par", &self.v_par), ("w", &self.w)] {
            if !(r.start.is_finite() && r.end.is_finite() && r.start < r.end) {
                return Err(AnalysisError::invalid(
                    "section box",
                    format!("{name} range {r:?} is not a finite increasing interval"),
                ));
            }
        }
        Ok(())
    }
}

/// The invariant measure `ds dv∥ dw` of a table's collision map at one α
/// (see the [module docs](crate::phase_space#the-invariant-measure) for the derivation), normalised to a
/// probability: `s` uniform on the perimeter and `(v∥, w)/|V|` uniform in
/// the unit disk (uniform in `v∥/|V|` on `[−1, 1]` at α = 0).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct InvariantMeasure {
    perimeter: f64,
    coupled: bool,
}

/// Panels of the Simpson rule for the disk area of a box: the integrand is
/// continuous and piecewise smooth, and the area error stays below 1e-8.
const SIMPSON_PANELS: usize = 20_000;

impl InvariantMeasure {
    /// The measure of the collision map of `table` under `law`.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for a perimeter that is not positive
    /// and finite.
    pub fn new<B: Boundary + ?Sized>(table: &B, law: &SpinLaw) -> Result<Self, AnalysisError> {
        let perimeter = table.perimeter();
        if !(perimeter.is_finite() && perimeter > 0.0) {
            return Err(AnalysisError::invalid(
                "table",
                format!("perimeter {perimeter} is not positive and finite"),
            ));
        }
        Ok(InvariantMeasure {
            perimeter,
            coupled: law.is_coupled(),
        })
    }

    /// The perimeter, the range of `s`.
    #[must_use]
    pub fn perimeter(&self) -> f64 {
        self.perimeter
    }

    /// Total mass of `ds dv∥ dw` at `|V| = 1`: `π |∂Q|` (α > 0) or `2|∂Q|`
    /// (α = 0).
    #[must_use]
    pub fn total(&self) -> f64 {
        if self.coupled {
            PI * self.perimeter
        } else {
            2.0 * self.perimeter
        }
    }

    /// The probability `μ(A)` of the box (its share of the invariant
    /// measure).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for ranges that are not finite and
    /// increasing, and for a box of zero measure (nothing to return to).
    pub fn probability(&self, region: &SectionBox) -> Result<f64, AnalysisError> {
        region.validate()?;
        let s_share =
            (region.s.end.min(self.perimeter) - region.s.start.max(0.0)).max(0.0) / self.perimeter;
        let velocity_share = if self.coupled {
            disk_box_area(&region.v_par, &region.w) / PI
        } else if region.w.contains(&0.0) {
            (region.v_par.end.min(1.0) - region.v_par.start.max(-1.0)).max(0.0) / 2.0
        } else {
            0.0
        };
        let p = s_share * velocity_share;
        if p > 0.0 {
            Ok(p)
        } else {
            Err(AnalysisError::invalid(
                "section box",
                format!(
                    "{region:?} has zero invariant measure (s must overlap [0, {}), (v∥, w) the unit disk, and at α = 0 w must include 0)",
                    self.perimeter
                ),
            ))
        }
    }

    /// A point `(s, v∥/|V|, w/|V|)` drawn from the measure.
    pub fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> (f64, f64, f64) {
        let s = self.perimeter * rng.random::<f64>();
        if !self.coupled {
            return (s, 2.0 * rng.random::<f64>() - 1.0, 0.0);
        }
        loop {
            let v = 2.0 * rng.random::<f64>() - 1.0;
            let w = 2.0 * rng.random::<f64>() - 1.0;
            if v * v + w * w < 1.0 {
                return (s, v, w);
            }
        }
    }
}

/// Area of the unit disk inside `[v0, v1) × [w0, w1)`, by Simpson's rule on
/// the length of each vertical chord inside the box.
fn disk_box_area(v: &Range<f64>, w: &Range<f64>) -> f64 {
    let (lo, hi) = (v.start.max(-1.0), v.end.min(1.0));
    if lo >= hi {
        return 0.0;
    }
    let chord = |x: f64| {
        let h = (1.0 - x * x).max(0.0).sqrt();
        (w.end.min(h) - w.start.max(-h)).max(0.0)
    };
    let n = SIMPSON_PANELS;
    let step = (hi - lo) / n as f64;
    let inner: f64 = (1..n)
        .map(|i| chord(lo + i as f64 * step) * if i % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    (chord(lo) + chord(hi) + inner) * step / 3.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_geometry::Stadium;

    #[test]
    fn disk_areas_match_closed_forms() {
        // Whole disk, half disk, and the strip |v| < ½: 2(x√(1−x²) + asin x).
        assert!((disk_box_area(&(-1.0..1.0), &(-1.0..1.0)) - PI).abs() < 1e-6);
        assert!((disk_box_area(&(0.0..1.0), &(-1.0..1.0)) - PI / 2.0).abs() < 1e-6);
        let strip = 2.0 * (0.5 * 0.75f64.sqrt() + 0.5f64.asin());
        assert!((disk_box_area(&(-0.5..0.5), &(-2.0..2.0)) - strip).abs() < 1e-8);
        // A box inside the disk is its own area.
        assert!((disk_box_area(&(-0.3..0.2), &(0.1..0.4)) - 0.15).abs() < 1e-12);
    }

    #[test]
    fn boxes_of_zero_measure_are_refused() {
        let table = Stadium::new(1.0).unwrap();
        let spin = InvariantMeasure::new(&table, &SpinLaw::new(0.5).unwrap()).unwrap();
        let flat = InvariantMeasure::new(&table, &SpinLaw::specular()).unwrap();
        let outside = SectionBox::new(0.0..1.0, 1.0..2.0);
        assert!(spin.probability(&outside).is_err());
        let no_w = SectionBox::new(0.0..1.0, -0.5..0.5).with_w(0.2..0.4);
        assert!(flat.probability(&no_w).is_err());
        assert!(spin.probability(&no_w).is_ok());
        let backwards = SectionBox::new(1.0..0.0, -0.5..0.5);
        assert!(spin.probability(&backwards).is_err());
        let p = flat
            .probability(&SectionBox::new(0.0..table.perimeter(), -0.5..0.5))
            .unwrap();
        assert!((p - 0.5).abs() < 1e-15);
    }
}
