//! The Lyapunov spectrum averaged over initial conditions (paper, appendix
//! "Full Lyapunov spectrum": 50 initial conditions × 5·10⁴ collisions).
//!
//! Documented in the group docs (`run/mod.rs`), section "The spectrum over an ensemble".

use std::{ops::Range, time::Instant};

use spinball_core::{Billiard, Sampler, ic_rng};
use spinball_geometry::Boundary;
use spinball_lanes::{CHUNK, LaneBilliard, LanesError};

#[cfg(feature = "serde")]
use super::checksum::Fnv1a;
use super::checksum::{IntegrityError, finite};
use super::parallel::{Threads, map_chunks, map_indices};
use super::result::in_order;
use crate::error::AnalysisError;
use crate::estimators::{
    Accumulator, Method, Spectrum, SpectrumOptions, lyapunov_spectrum, random_frame,
};

/// The spectrum of an ensemble: mean and standard error of each ordered
/// exponent over initial conditions, and every trajectory's spectrum.
///
/// As JSON (feature `serde`) it carries, besides its fields, `n_spectra`
/// (the count of per-IC spectra: `n_ics`, or 0 for a record
/// [without spectra](SpectrumEstimate::without_spectra)) and `checksum`
/// (FNV-1a over the exact bits of every field and every spectrum, see the
/// group docs, "Checksums"). Reading one back checks both, and that every
/// value is finite ([`IntegrityError`]); writing one with a non-finite
/// value fails.
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumEstimate {
    /// Mean of each exponent (per unit time, descending order within each
    /// trajectory) over the initial conditions.
    pub mean: [f64; 5],
    /// Standard error of each mean.
    pub sem: [f64; 5],
    /// Mean per-collision exponents.
    pub per_collision_mean: [f64; 5],
    /// Mean of the per-trajectory sums (zero to rounding for the exact method).
    pub sum_mean: f64,
    /// Largest `|sum|` over trajectories.
    pub sum_max_abs: f64,
    /// Finite differences: separations floored at `ε·δ0`, summed over
    /// trajectories (see [`Spectrum::floored`]).
    pub floored: u64,
    /// Number of initial conditions.
    pub n_ics: u64,
    /// First initial-condition index.
    pub first_index: u64,
    /// Options of every trajectory.
    pub options: SpectrumOptions,
    /// Sampler of the initial conditions.
    pub sampler: Sampler,
    /// Seed of the initial conditions.
    pub seed: u64,
    /// Wall-clock seconds.
    pub wall_time_s: f64,
    /// Each trajectory's spectrum, in index order.
    pub spectra: Vec<Spectrum>,
}

impl SpectrumEstimate {
    /// The statistics of `spectra` (in index order, starting at
    /// `first_index`).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for fewer than two spectra.
    pub fn from_spectra(
        spectra: Vec<Spectrum>,
        first_index: u64,
        options: SpectrumOptions,
        sampler: Sampler,
        seed: u64,
        wall_time_s: f64,
    ) -> Result<Self, AnalysisError> {
        if spectra.len() < 2 {
            return Err(AnalysisError::invalid(
                "initial conditions",
                format!(
                    "a spectrum estimate needs at least 2 trajectories, got {}",
                    spectra.len()
                ),
            ));
        }
        let column =
            |f: &dyn Fn(&Spectrum) -> f64| -> Accumulator { spectra.iter().map(f).collect() };
        let mut mean = [0.0; 5];
        let mut sem = [0.0; 5];
        let mut per_collision_mean = [0.0; 5];
        for k in 0..5 {
            let acc = column(&|s| s.exponents[k]);
            mean[k] = acc.mean().unwrap_or(f64::NAN);
            sem[k] = acc.sem().unwrap_or(f64::NAN);
            per_collision_mean[k] = column(&|s| s.per_collision[k]).mean().unwrap_or(f64::NAN);
        }
        Ok(SpectrumEstimate {
            mean,
            sem,
            per_collision_mean,
            sum_mean: column(&|s| s.sum).mean().unwrap_or(f64::NAN),
            sum_max_abs: spectra.iter().fold(0.0, |m, s| m.max(s.sum.abs())),
            floored: spectra.iter().map(|s| s.floored).sum(),
            n_ics: spectra.len() as u64,
            first_index,
            options,
            sampler,
            seed,
            wall_time_s,
            spectra,
        })
    }

    /// Check that the estimate holds together: its spectra (if kept) are
    /// `n_ics` of them, and every statistic and per-IC value is finite.
    ///
    /// # Errors
    /// [`IntegrityError::Count`] or [`IntegrityError::NonFinite`].
    pub fn check(&self) -> Result<(), IntegrityError> {
        let found = self.spectra.len() as u64;
        if found != 0 && found != self.n_ics {
            return Err(IntegrityError::Count {
                stated: self.n_ics,
                found,
            });
        }
        for (index, s) in (self.first_index..).zip(&self.spectra) {
            for &x in s.exponents.iter().chain(&s.per_collision) {
                finite(index, "spectrum", x)?;
            }
            finite(index, "sum of exponents", s.sum)?;
            finite(index, "time", s.time)?;
        }
        let stats = self
            .mean
            .iter()
            .chain(&self.sem)
            .chain(&self.per_collision_mean);
        for &x in stats.chain([&self.sum_mean, &self.sum_max_abs]) {
            finite(self.first_index, "ensemble statistic", x)?;
        }
        Ok(())
    }

    /// The checksum of the content (written and checked with the JSON).
    #[cfg(feature = "serde")]
    fn checksum(&self) -> Fnv1a {
        let mut h = Fnv1a::new("spinball.spectrum_estimate");
        h.f64s(&self.mean);
        h.f64s(&self.sem);
        h.f64s(&self.per_collision_mean);
        h.f64s(&[self.sum_mean, self.sum_max_abs]);
        h.u64(self.floored);
        h.u64(self.n_ics);
        h.u64(self.first_index);
        h.spectrum_options(&self.options);
        h.sampler(Some(self.sampler));
        h.u64(self.seed);
        h.f64(self.wall_time_s);
        h.u64(self.spectra.len() as u64);
        for s in &self.spectra {
            h.spectrum(s);
        }
        h
    }

    /// Combine the spectra of two adjacent index ranges (in either order)
    /// into the estimate over both: the statistics are recomputed from the
    /// per-trajectory spectra in index order, so they are **bitwise** those
    /// of one run over the joined range; `wall_time_s` is the sum.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if the ranges are not adjacent,
    /// the options, sampler or seed differ, or either does not hold
    /// together ([`SpectrumEstimate::check`]) or has no spectra.
    pub fn merge(&self, other: &SpectrumEstimate) -> Result<SpectrumEstimate, AnalysisError> {
        for e in [self, other] {
            e.check().map_err(|err| {
                AnalysisError::invalid(
                    "merge",
                    format!(
                        "the spectrum estimate over {:?} is refused: {err}",
                        e.first_index..e.first_index.saturating_add(e.n_ics)
                    ),
                )
            })?;
            if e.spectra.is_empty() {
                return Err(AnalysisError::invalid(
                    "merge",
                    "an estimate without its spectra cannot be merged (the statistics are recomputed from them)",
                ));
            }
        }
        if self.options != other.options || self.sampler != other.sampler || self.seed != other.seed
        {
            return Err(AnalysisError::invalid(
                "merge",
                format!(
                    "cannot merge spectra of different runs: {:?}, {:?}, seed {} vs {:?}, {:?}, seed {}",
                    self.options, self.sampler, self.seed, other.options, other.sampler, other.seed
                ),
            ));
        }
        let range = |e: &SpectrumEstimate| e.first_index..e.first_index + e.n_ics;
        let (first, second) = if in_order(&range(self), &range(other))? {
            (self, other)
        } else {
            (other, self)
        };
        let mut spectra = first.spectra.clone();
        spectra.extend_from_slice(&second.spectra);
        Self::from_spectra(
            spectra,
            first.first_index,
            first.options,
            first.sampler,
            first.seed,
            first.wall_time_s + second.wall_time_s,
        )
    }

    /// Mean of `λ_i + λ_j` over trajectories with its standard error (for
    /// the pairing rule: `(0, 4)` for the exact spectrum, `(0, 3)` for the
    /// finite-difference one, whose slot 4 is the collapsed flow direction).
    ///
    /// # Panics
    /// If `i` or `j` is not below 5.
    pub fn pair_sum(&self, i: usize, j: usize) -> (f64, f64) {
        let acc: Accumulator = self
            .spectra
            .iter()
            .map(|s| s.exponents[i] + s.exponents[j])
            .collect();
        (
            acc.mean().unwrap_or(f64::NAN),
            acc.sem().unwrap_or(f64::NAN),
        )
    }

    /// Largest `|λ_k|` over the middle exponents `k = 1, 2, 3` (exact
    /// method: the three neutral directions) of the ensemble means.
    pub fn middle_max_abs(&self) -> f64 {
        self.mean[1..4].iter().fold(0.0, |m, x| m.max(x.abs()))
    }

    /// Largest `|λ_k|` of the ensemble means over the exponents that are
    /// zero in the dynamics: `k = 1, 2, 3` for the exact spectrum
    /// ([`middle_max_abs`](Self::middle_max_abs)), `k = 1, 2` for the
    /// finite-difference one (`(λ, 0, 0, −λ, λ₅)`, whose slot 4 is the
    /// collapsed flow direction).
    #[must_use]
    pub fn neutral_max_abs(&self) -> f64 {
        let end = match self.options.method {
            Method::Tangent => 4,
            Method::FiniteDifference { .. } => 3,
        };
        self.mean[1..end].iter().fold(0.0, |m, x| m.max(x.abs()))
    }

    /// This estimate without the per-trajectory spectra (for a compact
    /// record; every statistic is kept).
    #[must_use]
    pub fn without_spectra(&self) -> SpectrumEstimate {
        SpectrumEstimate {
            spectra: Vec::new(),
            ..self.clone()
        }
    }
}

#[cfg(feature = "serde")]
mod file {
    use serde::{Deserialize, Deserializer, Serialize, Serializer, de, ser};

    use super::{IntegrityError, Sampler, Spectrum, SpectrumEstimate, SpectrumOptions};
    use crate::run::checksum::verify;

    /// A spectrum estimate as written: its fields, the count and the
    /// checksum.
    #[derive(Serialize)]
    struct Written<'a> {
        mean: &'a [f64; 5],
        sem: &'a [f64; 5],
        per_collision_mean: &'a [f64; 5],
        sum_mean: f64,
        sum_max_abs: f64,
        floored: u64,
        n_ics: u64,
        first_index: u64,
        options: &'a SpectrumOptions,
        sampler: &'a Sampler,
        seed: u64,
        wall_time_s: f64,
        spectra: &'a [Spectrum],
        n_spectra: u64,
        checksum: String,
    }

    /// A spectrum estimate as read, before its checks.
    #[derive(Deserialize)]
    struct Read {
        mean: [f64; 5],
        sem: [f64; 5],
        per_collision_mean: [f64; 5],
        sum_mean: f64,
        sum_max_abs: f64,
        floored: u64,
        n_ics: u64,
        first_index: u64,
        options: SpectrumOptions,
        sampler: Sampler,
        seed: u64,
        wall_time_s: f64,
        spectra: Vec<Spectrum>,
        #[serde(default)]
        n_spectra: Option<u64>,
        #[serde(default)]
        checksum: Option<String>,
    }

    impl Serialize for SpectrumEstimate {
        fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            self.check().map_err(ser::Error::custom)?;
            Written {
                mean: &self.mean,
                sem: &self.sem,
                per_collision_mean: &self.per_collision_mean,
                sum_mean: self.sum_mean,
                sum_max_abs: self.sum_max_abs,
                floored: self.floored,
                n_ics: self.n_ics,
                first_index: self.first_index,
                options: &self.options,
                sampler: &self.sampler,
                seed: self.seed,
                wall_time_s: self.wall_time_s,
                spectra: &self.spectra,
                n_spectra: self.spectra.len() as u64,
                checksum: self.checksum().text(),
            }
            .serialize(s)
        }
    }

    impl<'de> Deserialize<'de> for SpectrumEstimate {
        fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            let r = Read::deserialize(d)?;
            let (Some(stated), Some(checksum)) = (r.n_spectra, r.checksum) else {
                return Err(de::Error::custom(IntegrityError::NoChecksum {
                    version: "0.1.0".into(),
                }));
            };
            let e = SpectrumEstimate {
                mean: r.mean,
                sem: r.sem,
                per_collision_mean: r.per_collision_mean,
                sum_mean: r.sum_mean,
                sum_max_abs: r.sum_max_abs,
                floored: r.floored,
                n_ics: r.n_ics,
                first_index: r.first_index,
                options: r.options,
                sampler: r.sampler,
                seed: r.seed,
                wall_time_s: r.wall_time_s,
                spectra: r.spectra,
            };
            let found = e.spectra.len() as u64;
            if stated != found {
                return Err(de::Error::custom(IntegrityError::Count { stated, found }));
            }
            verify(Some(&checksum), &e.checksum(), "0.1.0")
                .and_then(|()| e.check())
                .map_err(de::Error::custom)?;
            Ok(e)
        }
    }
}

/// The spectrum of initial conditions `indices` (IC `i`: state from
/// `sampler` with `ic_rng(seed, i)`, then the initial frame from the same
/// stream), each with `options`, on `threads`.
///
/// ```
/// use spinball_analysis::estimators::{Method, SpectrumOptions};
/// use spinball_analysis::run::{Threads, spectrum_ensemble};
/// use spinball_core::{Billiard, Sampler, SpinLaw};
/// use spinball_geometry::Sinai;
///
/// let billiard = Billiard::new(Sinai::new(2.0, 1.0)?, SpinLaw::new(0.5)?);
/// let options = SpectrumOptions::new(5_000, Method::Tangent);
/// let est = spectrum_ensemble(&billiard, Sampler::Paper, 1, 0..8, &options, Threads::All)?;
/// assert!(est.mean[0] > 0.05 && (est.mean[0] + est.mean[4]).abs() < 0.01);
/// assert!(est.sum_max_abs < 1e-9);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`SpectrumOptions::validate`], fewer than two initial conditions, then
/// the first trajectory's error (tagged with its index).
pub fn spectrum_ensemble<B: Boundary + Sync>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    indices: Range<u64>,
    options: &SpectrumOptions,
    threads: Threads,
) -> Result<SpectrumEstimate, AnalysisError> {
    options.validate()?;
    threads.validate()?;
    let first = indices.start;
    let clock = Instant::now();
    let lanes = match options.method {
        Method::Tangent => LaneBilliard::new(billiard.table(), *billiard.law()).ok(),
        Method::FiniteDifference { .. } => None,
    };
    let spectra = match lanes {
        Some(lanes) => map_chunks(indices, CHUNK as u64, threads, |range| {
            let lo = range.start;
            let (starts, frames): (Vec<_>, Vec<_>) = range
                .map(|i| {
                    let mut rng = ic_rng(seed, i);
                    let start = sampler.try_sample(billiard.table(), billiard.law(), &mut rng)?;
                    Ok((start, random_frame(&mut rng)))
                })
                .collect::<Result<Vec<_>, AnalysisError>>()?
                .into_iter()
                .unzip();
            match lanes.spectrum(&starts, &frames, options.collisions, options.qr_interval) {
                Ok(out) => Ok(out
                    .into_iter()
                    .map(|s| {
                        Spectrum::from_sums(s.log_stretch, s.time, s.collisions, options.method, 0)
                    })
                    .collect()),
                // The scalar path says what went wrong, with the index.
                Err(LanesError::Launch { index, .. } | LanesError::NonFinite { index }) => {
                    let i = lo + index as u64;
                    Err(scalar_spectrum(billiard, sampler, seed, i, options)
                        .err()
                        .unwrap_or(AnalysisError::EngineMismatch { index: i }))
                }
                Err(other) => Err(AnalysisError::Lanes(other)),
            }
        })?,
        None => map_indices(indices, threads, |i| {
            scalar_spectrum(billiard, sampler, seed, i, options)
        })?,
    };
    let wall = clock.elapsed().as_secs_f64();
    SpectrumEstimate::from_spectra(spectra, first, *options, sampler, seed, wall)
}

/// The spectrum of initial condition `i` on the scalar path (the
/// specification the lane kernel reproduces).
fn scalar_spectrum<B: Boundary>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    i: u64,
    options: &SpectrumOptions,
) -> Result<Spectrum, AnalysisError> {
    let mut rng = ic_rng(seed, i);
    let start = sampler.try_sample(billiard.table(), billiard.law(), &mut rng)?;
    lyapunov_spectrum(billiard, start, options, &mut rng).map_err(|e| e.at_index(i))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimators::Method;
    use spinball_core::SpinLaw;
    use spinball_geometry::Stadium;

    #[test]
    fn same_numbers_on_any_thread_count() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.3).unwrap());
        let options = SpectrumOptions::new(1_000, Method::default());
        let one = spectrum_ensemble(
            &billiard,
            Sampler::Paper,
            5,
            2..6,
            &options,
            Threads::Fixed(1),
        )
        .unwrap();
        let two = spectrum_ensemble(
            &billiard,
            Sampler::Paper,
            5,
            2..6,
            &options,
            Threads::Fixed(2),
        )
        .unwrap();
        assert_eq!(one.spectra, two.spectra);
        assert_eq!(one.mean, two.mean);
        assert_eq!((one.n_ics, one.first_index), (4, 2));
        let (s, e) = one.pair_sum(0, 3);
        assert!(s.abs() < 0.1 && e >= 0.0);
        // Finite differences: the neutral exponents are slots 1 and 2.
        let fd_neutral = one.mean[1].abs().max(one.mean[2].abs());
        assert_eq!(one.neutral_max_abs(), fd_neutral);
        assert!(fd_neutral < 0.05, "{fd_neutral}");
        let compact = one.without_spectra();
        assert!(compact.spectra.is_empty());
        assert_eq!((compact.mean, compact.sem), (one.mean, one.sem));
        assert_eq!(compact.n_ics, 4);
    }

    #[test]
    fn exact_neutral_exponents_are_the_middle_three() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let options = SpectrumOptions::new(2_000, Method::Tangent);
        let est = spectrum_ensemble(
            &billiard,
            Sampler::Paper,
            1,
            0..4,
            &options,
            Threads::Fixed(1),
        )
        .unwrap();
        assert_eq!(est.neutral_max_abs(), est.middle_max_abs());
        // fig_spectrum (4 ICs × 2000 collisions): the middle three within
        // 0.003 of zero, λ₁ ≈ 0.19.
        assert!(est.neutral_max_abs() < 0.01, "{:?}", est.mean);
        assert!(est.mean[0] > 0.1, "{:?}", est.mean);
    }

    #[test]
    fn needs_two_initial_conditions() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.3).unwrap());
        let options = SpectrumOptions::new(100, Method::Tangent);
        assert!(
            spectrum_ensemble(&billiard, Sampler::Paper, 5, 0..1, &options, Threads::All).is_err()
        );
    }
}
