//! The mean escape time the invariant measure predicts (Kac's lemma): the
//! reference every measured mean escape time is held against.
//!
//! Documented in the group docs (`escape/mod.rs`) and `docs/TRANSPORT.md`,
//! section "Kac prediction", where the formulas are derived.
//!
//! The hole is a piece of wall of arc length `h`; every ball reaching it
//! leaves, whatever its velocity and spin. The invariant measure of the
//! spinning billiard map is uniform in arc length for every α (`ds dv∥ dw`,
//! see [`InvariantMeasure`](crate::phase_space::InvariantMeasure)), so the
//! hole carries the share `μ(hole) = h/|∂Q|`, and by Kac's lemma a ball
//! started on the hole from the invariant measure of the closed table comes
//! back to it after `|∂Q|/h` collisions on average: exactly, if the closed
//! table is ergodic. In time, the flow's version of the same lemma gives the
//! mean free time of the invariant measure times that: `π|Q|/|∂Q|` per
//! collision at α = 0, `4|Q|/|∂Q|` at every α > 0 (the translational speed
//! averages π/4 there). For balls started anywhere from the invariant
//! measure the same numbers hold in the small-hole limit.

use std::fmt;

use crate::estimators::Significant;

use spinball_core::Sampler;
use spinball_geometry::Boundary;

use super::EscapeError;
use super::survival::{Clock, MeanEscape};
use crate::diagnostics::initial_mean_speed;

/// The Kac prediction for one table, hole and α.
///
/// ```
/// use spinball_analysis::escape::KacPrediction;
/// use std::f64::consts::PI;
/// // The unit circle with a hole of arc length 0.1, no spin.
/// let kac = KacPrediction::new(2.0 * PI, PI, 0.1, 0.0)?;
/// assert!((kac.mean_collisions - 20.0 * PI).abs() < 1e-12);
/// assert!((kac.mean_time - PI * PI / 0.1).abs() < 1e-9); // π|Q|/h
/// # Ok::<(), spinball_analysis::escape::EscapeError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct KacPrediction {
    /// Perimeter `|∂Q|` of the closed table (hole included).
    pub perimeter: f64,
    /// Area `|Q|`.
    pub area: f64,
    /// Total arc length `h` of the holes.
    pub hole: f64,
    /// Spin parameter α.
    pub alpha: f64,
    /// `μ(hole) = h/|∂Q|`, the hole's share of the invariant measure.
    pub hole_measure: f64,
    /// Mean escape collisions `|∂Q|/h` (the escaping hit counted).
    pub mean_collisions: f64,
    /// Mean free time of the invariant measure: `π|Q|/|∂Q|` at α = 0,
    /// `4|Q|/|∂Q|` at α > 0.
    pub mean_free_time: f64,
    /// Mean escape time `mean_collisions · mean_free_time`: `π|Q|/h` at
    /// α = 0, `4|Q|/h` at α > 0.
    pub mean_time: f64,
}

impl KacPrediction {
    /// The prediction for a table of `perimeter` and `area` with holes of
    /// total arc length `hole`, at spin parameter `alpha`.
    ///
    /// # Errors
    /// [`EscapeError::InvalidOption`] unless perimeter and area are positive
    /// and finite, `0 < hole <= perimeter` and `alpha >= 0` is finite.
    pub fn new(perimeter: f64, area: f64, hole: f64, alpha: f64) -> Result<Self, EscapeError> {
        for (name, v) in [("perimeter", perimeter), ("area", area)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(EscapeError::invalid(
                    name,
                    format!("{v}: must be positive and finite"),
                ));
            }
        }
        if !(hole > 0.0 && hole <= perimeter) {
            return Err(EscapeError::invalid(
                "hole",
                format!(
                    "{hole}: the hole's arc length must be in (0, {perimeter}] (the perimeter)"
                ),
            ));
        }
        if !(alpha.is_finite() && alpha >= 0.0) {
            return Err(EscapeError::invalid(
                "alpha",
                format!("{alpha}: must be finite and >= 0"),
            ));
        }
        let mean_path = std::f64::consts::PI * area / perimeter;
        let mean_free_time = mean_path / initial_mean_speed(Sampler::Microcanonical, alpha);
        let mean_collisions = perimeter / hole;
        Ok(KacPrediction {
            perimeter,
            area,
            hole,
            alpha,
            hole_measure: hole / perimeter,
            mean_collisions,
            mean_free_time,
            mean_time: mean_collisions * mean_free_time,
        })
    }

    /// The prediction for `table` (its perimeter, holes included, and its
    /// area) with holes of total arc length `hole`, at `alpha`.
    ///
    /// # Errors
    /// As [`KacPrediction::new`].
    pub fn for_table<B: Boundary + ?Sized>(
        table: &B,
        hole: f64,
        alpha: f64,
    ) -> Result<Self, EscapeError> {
        KacPrediction::new(table.perimeter(), table.area(), hole, alpha)
    }

    /// The prediction for an open `table` at `alpha`, its hole the total
    /// arc length of its hole walls ([`WallKind::Hole`](spinball_geometry::WallKind)):
    /// `None` for a table without holes, with periodic walls (its
    /// "perimeter" is not a wall) or without a shape to read the walls
    /// from.
    ///
    /// # Errors
    /// As [`KacPrediction::new`].
    pub fn for_open_table<B: Boundary + ?Sized>(
        table: &B,
        alpha: f64,
    ) -> Result<Option<Self>, EscapeError> {
        let Some(spinball_geometry::Shape::Segments {
            outer,
            holes,
            kinds,
            ..
        }) = table.shape()
        else {
            return Ok(None);
        };
        if kinds.iter().any(|k| k.is_periodic()) {
            return Ok(None);
        }
        let hole: f64 = outer
            .iter()
            .chain(holes.iter().flatten())
            .zip(&kinds)
            .filter(|(_, k)| k.is_hole())
            .map(|(w, _)| w.length())
            .sum();
        if hole > 0.0 {
            KacPrediction::for_table(table, hole, alpha).map(Some)
        } else {
            Ok(None)
        }
    }

    /// The predicted mean on `clock`.
    #[must_use]
    pub fn mean(&self, clock: Clock) -> f64 {
        match clock {
            Clock::Time => self.mean_time,
            Clock::Collisions => self.mean_collisions,
        }
    }

    /// A measured mean escape time against this prediction.
    pub fn compare(&self, measured: MeanEscape) -> KacRatio {
        let predicted = self.mean(measured.clock);
        KacRatio {
            predicted,
            measured,
            ratio: measured.mean / predicted,
            ratio_sem: measured.sem / predicted,
        }
    }
}

impl fmt::Display for KacPrediction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "Kac: hole {} of {} (μ = {:.4e}) at α = {}: {} collisions, time {}",
            Significant(self.hole, 6),
            Significant(self.perimeter, 6),
            self.hole_measure,
            self.alpha,
            Significant(self.mean_collisions, 5),
            Significant(self.mean_time, 5)
        )
    }
}

/// A measured mean escape time over its Kac prediction.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct KacRatio {
    /// The prediction on the measurement's clock.
    pub predicted: f64,
    /// The measurement.
    pub measured: MeanEscape,
    /// Measured over predicted.
    pub ratio: f64,
    /// Standard error of the ratio (the prediction is exact).
    pub ratio_sem: f64,
}

impl KacRatio {
    /// How many standard errors the ratio is from 1.
    #[must_use]
    pub fn deviation(&self) -> f64 {
        (self.ratio - 1.0) / self.ratio_sem
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::escape::Survival;
    use std::f64::consts::PI;

    #[test]
    fn an_open_table_gives_its_hole() {
        let t = spinball_geometry::SegmentTable::stadium_with_hole(1.0, 3.0, 0.2).unwrap();
        let k = KacPrediction::for_open_table(&t, 0.5).unwrap().unwrap();
        assert!((k.hole - 0.2).abs() < 1e-12, "{k}");
        assert_eq!(k, KacPrediction::for_table(&t, k.hole, 0.5).unwrap());
        let gas = spinball_geometry::LorentzGas::square(1.0, 0.4).unwrap();
        assert_eq!(
            KacPrediction::for_open_table(&gas.table().unwrap(), 0.0),
            Ok(None)
        );
        let closed = spinball_geometry::Stadium::new(1.0).unwrap();
        assert_eq!(KacPrediction::for_open_table(&closed, 0.0), Ok(None));
    }

    #[test]
    fn zero_spin_closed_forms() {
        // Unit circle: |∂Q| = 2π, |Q| = π, mean free path π|Q|/|∂Q| = π/2
        // (the mean chord of the circle under the cos θ measure is
        // ∫ 2cos θ · cos θ dθ/2 over (−π/2, π/2) = π/2).
        let circle = KacPrediction::new(2.0 * PI, PI, 0.5, 0.0).unwrap();
        assert!((circle.mean_free_time - PI / 2.0).abs() < 1e-15);
        assert!((circle.mean_collisions - 4.0 * PI).abs() < 1e-12);
        assert!((circle.mean_time - 2.0 * PI * PI).abs() < 1e-12);
        // Unit square: |∂Q| = 4, |Q| = 1, mean free path π/4.
        let square = KacPrediction::new(4.0, 1.0, 0.04, 0.0).unwrap();
        assert!((square.mean_free_time - PI / 4.0).abs() < 1e-15);
        assert!((square.mean_collisions - 100.0).abs() < 1e-12);
        assert!((square.mean_time - 25.0 * PI).abs() < 1e-12);
        assert!((square.hole_measure - 0.01).abs() < 1e-15);
    }

    #[test]
    fn a_table_gives_its_perimeter_and_area() {
        // Stadium a = 1: |∂Q| = 4 + 2π, |Q| = 4 + π.
        let stadium = spinball_geometry::Stadium::new(1.0).unwrap();
        let k = KacPrediction::for_table(&stadium, 0.2, 0.4).unwrap();
        assert!((k.perimeter - (4.0 + 2.0 * PI)).abs() < 1e-12);
        assert!((k.mean_time - 4.0 * (4.0 + PI) / 0.2).abs() < 1e-9);
    }

    #[test]
    fn spin_changes_the_time_not_the_collisions() {
        // For every α > 0: collisions |∂Q|/h as at α = 0, time 4|Q|/h.
        let zero = KacPrediction::new(4.0, 1.0, 0.1, 0.0).unwrap();
        for alpha in [1e-3, 0.4, 1.0] {
            let k = KacPrediction::new(4.0, 1.0, 0.1, alpha).unwrap();
            assert_eq!(k.mean_collisions, zero.mean_collisions);
            assert!((k.mean_time - 4.0 / 0.1).abs() < 1e-12, "{k}");
        }
    }

    #[test]
    fn geometric_escape_matches_its_own_mean() {
        // A sample whose mean is exactly the prediction (collisions
        // 1..=2N−1 once each: mean N) gives ratio 1.
        let kac = KacPrediction::new(4.0, 1.0, 0.04, 0.0).unwrap();
        let counts: Vec<u64> = (1..200).collect();
        let m = Survival::by_collisions(&counts, &vec![false; counts.len()])
            .unwrap()
            .mean_escape();
        let cmp = kac.compare(m);
        assert!((cmp.ratio - 1.0).abs() < 1e-12 && cmp.deviation().abs() < 1e-9);
    }

    /// Escape collisions and times of `n` balls started on the arc
    /// `hole` of the closed `table` at α = 0 from the invariant measure
    /// restricted to it (`s` uniform on the arc, `v∥` uniform in
    /// `(−1, 1)`), run until a collision lands on the arc again or
    /// `budget` collisions pass (censored).
    fn returns_to_arc<B: spinball_geometry::Boundary>(
        table: B,
        hole: std::ops::Range<f64>,
        n: usize,
        budget: u64,
    ) -> (Vec<u64>, Vec<f64>, Vec<bool>) {
        use spinball_core::{Billiard, SpinLaw};
        let law = SpinLaw::specular();
        let mut rng = spinball_test_support::normal::Normal(2024);
        let billiard = Billiard::new(table, law);
        let (mut counts, mut times, mut censored) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..n {
            let s = hole.start + rng.uniform() * (hole.end - hole.start);
            let v = 2.0 * rng.uniform() - 1.0;
            let start =
                crate::phase_space::state_on_section(billiard.table(), &law, s, v, 0.0).unwrap();
            let mut ball = billiard.launch(start).unwrap();
            let (mut k, mut t, mut back) = (0u64, 0.0, false);
            while k < budget {
                let c = billiard.step(&mut ball).unwrap();
                k += 1;
                t += c.time();
                if hole.contains(&c.hit.s()) {
                    back = true;
                    break;
                }
            }
            counts.push(k);
            times.push(t);
            censored.push(!back);
        }
        (counts, times, censored)
    }

    #[test]
    fn stadium_returns_to_a_hole_at_kacs_rate() {
        // The stadium (a = 1) is ergodic at α = 0, so Kac's lemma is exact
        // for starts on the hole: mean return |∂Q|/h collisions and π|Q|/h
        // time, for any h. Hole: h = 0.5 centred on the right cap. 20 000
        // balls, censored at 10⁵ collisions (the bouncing-ball tail
        // P(N > n) ∝ n⁻² leaves a bias of order 10⁻⁵ there). Within 4 SE
        // (the tail makes the SE itself noisy).
        let stadium = spinball_geometry::Stadium::new(1.0).unwrap();
        let h = 0.5;
        let s0 = 2.0 + PI / 2.0 - h / 2.0;
        let kac = KacPrediction::for_table(&stadium, h, 0.0).unwrap();
        let (counts, times, censored) = returns_to_arc(stadium, s0..s0 + h, 20_000, 100_000);
        let by_n = kac.compare(
            Survival::by_collisions(&counts, &censored)
                .unwrap()
                .mean_escape(),
        );
        assert!(by_n.deviation().abs() < 4.0, "{by_n:?}");
        assert!(by_n.ratio_sem < 0.02, "{by_n:?}");
        let by_t = kac.compare(
            Survival::kaplan_meier(&times, &censored)
                .unwrap()
                .mean_escape(),
        );
        assert!(by_t.deviation().abs() < 4.0, "{by_t:?}");
    }

    #[test]
    fn mean_free_time_of_the_invariant_measure() {
        // The time factor of the prediction is exact without ergodicity:
        // one flight from each of 40 000 starts drawn from the invariant
        // measure of the stadium's map averages π|Q|/|∂Q| at α = 0 and
        // 4|Q|/|∂Q| at α = 0.5 (the flow's volume over the wall's flux),
        // within 3 SE.
        use crate::estimators::Accumulator;
        use spinball_core::{Billiard, SpinLaw};
        let stadium = spinball_geometry::Stadium::new(1.0).unwrap();
        for alpha in [0.0, 0.5] {
            let law = SpinLaw::new(alpha).unwrap();
            let kac = KacPrediction::for_table(&stadium, 1.0, alpha).unwrap();
            let starts =
                crate::phase_space::invariant_starts(&stadium, &law, 7, 0..40_000).unwrap();
            let billiard = Billiard::new(stadium, law);
            let flights: Accumulator = starts
                .into_iter()
                .map(|s| {
                    billiard
                        .step(&mut billiard.launch(s).unwrap())
                        .unwrap()
                        .time()
                })
                .collect();
            let (mean, sem) = (flights.mean().unwrap(), flights.sem().unwrap());
            assert!(
                (mean - kac.mean_free_time).abs() < 3.0 * sem,
                "α = {alpha}: {mean} ± {sem} against {}",
                kac.mean_free_time
            );
        }
    }

    #[test]
    fn bad_inputs_are_refused() {
        assert!(KacPrediction::new(4.0, 1.0, 0.0, 0.0).is_err());
        assert!(KacPrediction::new(4.0, 1.0, 5.0, 0.0).is_err());
        assert!(KacPrediction::new(4.0, f64::NAN, 0.1, 0.0).is_err());
        assert!(KacPrediction::new(-4.0, 1.0, 0.1, 0.0).is_err());
        assert!(KacPrediction::new(4.0, 1.0, 0.1, -0.1).is_err());
    }
}
