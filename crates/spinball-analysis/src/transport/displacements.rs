//! The unwrapped displacements of an ensemble at checkpoint times, and
//! their mean square `⟨Δr²⟩(t)`.
//!
//! Documented in the group docs (`transport/mod.rs`) and `docs/TRANSPORT.md`,
//! section "Mean-square displacement".

use super::TransportError;
use crate::estimators::Accumulator;

/// Displacements `Δr = r(t) − r(0)` of `n_ics` initial conditions at the
/// same checkpoint times, checked: times finite, positive and strictly
/// increasing; one finite `[Δx, Δy]` per initial condition and checkpoint,
/// IC-major (`dr[i·checkpoints + j]` is IC `i` at `times[j]`); at least two
/// initial conditions (an error needs a spread).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Displacements<'a> {
    times: &'a [f64],
    dr: &'a [[f64; 2]],
}

impl<'a> Displacements<'a> {
    /// Check and wrap `times` and `dr`.
    ///
    /// # Errors
    /// [`TransportError::NoCheckpoints`], [`TransportError::BadTimes`],
    /// [`TransportError::Shape`] (not a whole number of ICs, or fewer than
    /// two) and [`TransportError::NotFinite`].
    pub fn new(times: &'a [f64], dr: &'a [[f64; 2]]) -> Result<Self, TransportError> {
        if times.is_empty() {
            return Err(TransportError::NoCheckpoints);
        }
        for (index, &value) in times.iter().enumerate() {
            let after = index == 0 || value > times[index - 1];
            if !(value.is_finite() && value > 0.0 && after) {
                return Err(TransportError::BadTimes { index, value });
            }
        }
        let m = times.len();
        if !dr.len().is_multiple_of(m) || dr.len() / m < 2 {
            return Err(TransportError::Shape {
                len: dr.len(),
                checkpoints: m,
            });
        }
        if let Some(k) = dr
            .iter()
            .position(|d| !(d[0].is_finite() && d[1].is_finite()))
        {
            return Err(TransportError::NotFinite {
                ic: k / m,
                checkpoint: k % m,
            });
        }
        Ok(Displacements { times, dr })
    }

    /// The checkpoint times.
    #[must_use]
    pub fn times(&self) -> &'a [f64] {
        self.times
    }

    /// Number of initial conditions.
    #[must_use]
    pub fn n_ics(&self) -> usize {
        self.dr.len() / self.times.len()
    }

    /// How far IC `ic` moved between checkpoints `j0` and `j1`:
    /// `Δr(t_j1) − Δr(t_j0)`.
    #[must_use]
    #[inline]
    pub fn increment(&self, ic: usize, j0: usize, j1: usize) -> [f64; 2] {
        let m = self.times.len();
        let (a, b) = (self.dr[ic * m + j0], self.dr[ic * m + j1]);
        [b[0] - a[0], b[1] - a[1]]
    }

    /// `|Δr|²` of IC `ic` at checkpoint `j`.
    #[must_use]
    #[inline]
    pub fn squared(&self, ic: usize, j: usize) -> f64 {
        let d = self.dr[ic * self.times.len() + j];
        d[0] * d[0] + d[1] * d[1]
    }
}

/// `⟨Δr²⟩` at one checkpoint.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MsdPoint {
    /// Checkpoint time.
    pub t: f64,
    /// `⟨Δr²⟩` over the ensemble.
    pub msd: f64,
    /// Its standard error (spread of `|Δr|²` over the ICs, over `√n`).
    pub sem: f64,
}

impl MsdPoint {
    /// `⟨Δr²⟩/(4t)`: the running diffusion coefficient, flat in `t` for
    /// normal diffusion and growing like `ln t` for marginal diffusion.
    #[must_use]
    pub fn apparent_d(&self) -> f64 {
        self.msd / (4.0 * self.t)
    }
}

/// The mean-square displacement of an ensemble at every checkpoint.
///
/// ```
/// use spinball_analysis::transport::{Displacements, MeanSquareDisplacement};
/// let times = [1.0, 2.0];
/// // Two ICs: (1, 0) then (2, 0); (0, 1) then (0, 0).
/// let dr = [[1.0, 0.0], [2.0, 0.0], [0.0, 1.0], [0.0, 0.0]];
/// let msd = MeanSquareDisplacement::new(&Displacements::new(&times, &dr)?);
/// assert_eq!(msd.points()[0].msd, 1.0);
/// assert_eq!(msd.points()[1].msd, 2.0);
/// # Ok::<(), spinball_analysis::transport::TransportError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct MeanSquareDisplacement {
    n_ics: usize,
    points: Vec<MsdPoint>,
}

impl MeanSquareDisplacement {
    /// `⟨Δr²⟩(t)` of `d`.
    pub fn new(d: &Displacements<'_>) -> Self {
        let points = d
            .times()
            .iter()
            .enumerate()
            .map(|(j, &t)| {
                let acc: Accumulator = (0..d.n_ics()).map(|i| d.squared(i, j)).collect();
                MsdPoint {
                    t,
                    msd: acc.mean().unwrap_or(0.0),
                    sem: acc.sem().unwrap_or(0.0),
                }
            })
            .collect();
        MeanSquareDisplacement {
            n_ics: d.n_ics(),
            points,
        }
    }

    /// One point per checkpoint.
    #[must_use]
    pub fn points(&self) -> &[MsdPoint] {
        &self.points
    }

    /// Initial conditions averaged.
    #[must_use]
    pub fn n_ics(&self) -> usize {
        self.n_ics
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_and_values_are_checked() {
        let dr = [[1.0, 0.0]; 4];
        assert_eq!(
            Displacements::new(&[], &dr),
            Err(TransportError::NoCheckpoints)
        );
        assert!(matches!(
            Displacements::new(&[1.0, 1.0], &dr),
            Err(TransportError::BadTimes { index: 1, .. })
        ));
        assert!(matches!(
            Displacements::new(&[0.0, 1.0], &dr),
            Err(TransportError::BadTimes { index: 0, .. })
        ));
        assert!(matches!(
            Displacements::new(&[1.0, 2.0, 3.0], &dr),
            Err(TransportError::Shape { .. })
        ));
        assert!(matches!(
            Displacements::new(&[1.0, 2.0, 3.0, 4.0], &dr),
            Err(TransportError::Shape { .. })
        ));
        let mut bad = dr;
        bad[3][1] = f64::NAN;
        assert_eq!(
            Displacements::new(&[1.0, 2.0], &bad),
            Err(TransportError::NotFinite {
                ic: 1,
                checkpoint: 1
            })
        );
    }

    #[test]
    fn sem_is_the_spread_over_ics() {
        // |Δr|² = 1, 3 at t = 1: mean 2, sd √2, SEM 1.
        let times = [1.0];
        let dr = [[1.0, 0.0], [1.0, 2f64.sqrt()]];
        let msd = MeanSquareDisplacement::new(&Displacements::new(&times, &dr).unwrap());
        let p = msd.points()[0];
        assert!((p.msd - 2.0).abs() < 1e-12 && (p.sem - 1.0).abs() < 1e-12);
        assert!((p.apparent_d() - 0.5).abs() < 1e-12);
    }
}
