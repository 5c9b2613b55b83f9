//! Statistics with their errors: a mergeable running [`Accumulator`], a
//! fixed-bin [`Histogram`], and exact order statistics over a slice.
//!
//! Documented in the group docs (`estimators/mod.rs`), section "Statistics".

use crate::error::AnalysisError;

/// Fixed, equal-width bins over `[lo, hi)` with underflow, overflow and NaN
/// counts, so that no sample is ever silently dropped.
///
/// ```
/// use spinball_analysis::estimators::Histogram;
/// let mut h = Histogram::new(0.0, 1.0, 4)?;
/// for x in [0.1, 0.3, 0.35, 0.99, 1.0, -0.5] {
///     h.push(x);
/// }
/// assert_eq!(h.counts(), &[1, 2, 0, 1]);
/// assert_eq!((h.underflow(), h.overflow()), (1, 1));
/// # Ok::<(), spinball_analysis::AnalysisError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Histogram {
    lo: f64,
    hi: f64,
    counts: Vec<u64>,
    underflow: u64,
    overflow: u64,
    nan: u64,
}

impl Histogram {
    /// The most bins a histogram may have: 2²⁰ = 1 048 576 (8 MiB of
    /// counts), far more than any sample of initial conditions fills. More
    /// is refused with a typed error, never an allocation failure.
    pub const MAX_BINS: usize = 1 << 20;

    /// `bins` equal bins over `[lo, hi)`.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] unless `lo < hi` are finite and
    /// `1 <= bins <= `[`Histogram::MAX_BINS`].
    pub fn new(lo: f64, hi: f64, bins: usize) -> Result<Self, AnalysisError> {
        if !(lo.is_finite() && hi.is_finite() && lo < hi) {
            return Err(AnalysisError::invalid(
                "histogram range",
                format!("need finite lo < hi, got [{lo}, {hi})"),
            ));
        }
        if bins == 0 || bins > Self::MAX_BINS {
            return Err(AnalysisError::invalid(
                "histogram bins",
                format!("{bins}: must be in 1..={}", Self::MAX_BINS),
            ));
        }
        Ok(Histogram {
            lo,
            hi,
            counts: vec![0; bins],
            underflow: 0,
            overflow: 0,
            nan: 0,
        })
    }

    /// Count `x`: in its bin if `lo <= x < hi`, else in underflow (`x < lo`),
    /// overflow (`x >= hi`) or the NaN count.
    #[inline]
    pub fn push(&mut self, x: f64) {
        if x.is_nan() {
            self.nan += 1;
        } else if x < self.lo {
            self.underflow += 1;
        } else if x >= self.hi {
            self.overflow += 1;
        } else {
            let bins = self.counts.len();
            let i = ((x - self.lo) / (self.hi - self.lo) * bins as f64) as usize;
            // Rounding can put x just below hi into bin `bins`.
            self.counts[i.min(bins - 1)] += 1;
        }
    }

    /// Add the counts of `other` (exact: integer counts).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if the binnings differ.
    pub fn merge(&mut self, other: &Histogram) -> Result<(), AnalysisError> {
        if !self.same_bins(other) {
            return Err(AnalysisError::invalid(
                "histogram",
                format!(
                    "cannot merge [{}, {}) in {} bins with [{}, {}) in {} bins",
                    self.lo,
                    self.hi,
                    self.counts.len(),
                    other.lo,
                    other.hi,
                    other.counts.len()
                ),
            ));
        }
        for (a, b) in self.counts.iter_mut().zip(&other.counts) {
            *a += b;
        }
        self.underflow += other.underflow;
        self.overflow += other.overflow;
        self.nan += other.nan;
        Ok(())
    }

    /// Whether `other` has the same range and number of bins.
    pub fn same_bins(&self, other: &Histogram) -> bool {
        self.lo.to_bits() == other.lo.to_bits()
            && self.hi.to_bits() == other.hi.to_bits()
            && self.counts.len() == other.counts.len()
    }

    /// The histogram as CSV: one row per bin (`lo,hi,count,density`).
    #[must_use]
    pub fn to_csv(&self) -> String {
        let edges = self.edges();
        let mut out = String::from("lo,hi,count,density\n");
        for (i, (c, d)) in self.counts().iter().zip(self.density()).enumerate() {
            out.push_str(&format!("{},{},{c},{d}\n", edges[i], edges[i + 1]));
        }
        out
    }

    /// Lower edge of the first bin.
    pub fn lo(&self) -> f64 {
        self.lo
    }
    /// Upper edge of the last bin.
    pub fn hi(&self) -> f64 {
        self.hi
    }
    /// Number of bins.
    pub fn bins(&self) -> usize {
        self.counts.len()
    }
    /// Width of every bin, `(hi − lo) / bins`.
    pub fn bin_width(&self) -> f64 {
        (self.hi - self.lo) / self.counts.len() as f64
    }
    /// The `bins + 1` bin edges, `lo` to `hi`.
    pub fn edges(&self) -> Vec<f64> {
        let n = self.counts.len();
        (0..=n)
            .map(|i| {
                if i == n {
                    self.hi
                } else {
                    self.lo + (self.hi - self.lo) * (i as f64 / n as f64)
                }
            })
            .collect()
    }
    /// Centre of bin `i`.
    ///
    /// # Panics
    /// If `i >= bins`.
    pub fn center(&self, i: usize) -> f64 {
        assert!(i < self.counts.len(), "bin {i} out of range");
        self.lo + (self.hi - self.lo) * ((i as f64 + 0.5) / self.counts.len() as f64)
    }
    /// Counts per bin.
    pub fn counts(&self) -> &[u64] {
        &self.counts
    }
    /// Samples below `lo`.
    pub fn underflow(&self) -> u64 {
        self.underflow
    }
    /// Samples at or above `hi`.
    pub fn overflow(&self) -> u64 {
        self.overflow
    }
    /// NaN samples.
    pub fn nan(&self) -> u64 {
        self.nan
    }
    /// All samples pushed, including under/overflow and NaN.
    pub fn total(&self) -> u64 {
        self.counts.iter().sum::<u64>() + self.underflow + self.overflow + self.nan
    }
    /// Probability density per bin: `count / (total · width)`, so that the
    /// in-range bins integrate to the in-range share of the samples. Zeros if
    /// nothing was pushed.
    pub fn density(&self) -> Vec<f64> {
        let total = self.total();
        if total == 0 {
            return vec![0.0; self.counts.len()];
        }
        let norm = 1.0 / (total as f64 * self.bin_width());
        self.counts.iter().map(|&c| c as f64 * norm).collect()
    }
}

/// Running count, mean, variance (Welford), min and max of a stream of
/// numbers, optionally with a [`Histogram`]; mergeable (Chan et al.) and
/// serialisable.
///
/// Push finite values: a NaN makes the mean and variance NaN (the histogram
/// counts it separately). Statistics that need at least one (mean, min, max)
/// or two (variance, std, SEM) samples return `None` before that.
///
/// ```
/// use spinball_analysis::estimators::Accumulator;
/// let mut acc = Accumulator::new();
/// for x in [1.0, 2.0, 3.0, 4.0] {
///     acc.push(x);
/// }
/// assert_eq!(acc.mean(), Some(2.5));
/// assert_eq!(acc.variance(), Some(5.0 / 3.0)); // sample variance, n − 1
/// assert_eq!(acc.sem(), Some((5.0f64 / 3.0 / 4.0).sqrt()));
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Accumulator {
    count: u64,
    mean: f64,
    m2: f64,
    min: f64,
    max: f64,
    histogram: Option<Histogram>,
}

impl Accumulator {
    /// An empty accumulator without histogram.
    pub fn new() -> Self {
        Self::default()
    }

    /// An empty accumulator that also fills `histogram` (which may already
    /// hold counts).
    pub fn with_histogram(histogram: Histogram) -> Self {
        Accumulator {
            histogram: Some(histogram),
            ..Self::default()
        }
    }

    /// An accumulator with every value of `values` pushed in order.
    pub fn from_slice(values: &[f64]) -> Self {
        let mut acc = Self::new();
        acc.extend(values.iter().copied());
        acc
    }

    /// Add one value (Welford's update).
    #[inline]
    pub fn push(&mut self, x: f64) {
        if self.count == 0 {
            self.min = x;
            self.max = x;
        } else {
            self.min = self.min.min(x);
            self.max = self.max.max(x);
        }
        self.count += 1;
        let d = x - self.mean;
        self.mean += d / self.count as f64;
        self.m2 += d * (x - self.mean);
        if let Some(h) = &mut self.histogram {
            h.push(x);
        }
    }

    /// Combine with the statistics of another stream (Chan et al.'s pairwise
    /// update). Count, min, max and histogram are exact; mean and `M2` agree
    /// with pushing the other stream's values one by one only up to rounding
    /// in the last bits. Where bitwise reproducibility matters (ensembles),
    /// keep the samples and push them in index order instead.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if only one side has a histogram or
    /// their binnings differ; `self` is then unchanged.
    pub fn merge(&mut self, other: &Accumulator) -> Result<(), AnalysisError> {
        match (&mut self.histogram, &other.histogram) {
            (Some(a), Some(b)) => a.merge(b)?,
            (None, None) => {}
            _ => {
                return Err(AnalysisError::invalid(
                    "accumulator",
                    "cannot merge an accumulator with a histogram and one without",
                ));
            }
        }
        if other.count == 0 {
            return Ok(());
        }
        if self.count == 0 {
            let histogram = self.histogram.take();
            *self = Accumulator {
                histogram,
                ..other.clone()
            };
            return Ok(());
        }
        let na = self.count as f64;
        let nb = other.count as f64;
        let n = self.count + other.count;
        let d = other.mean - self.mean;
        self.mean += d * (nb / n as f64);
        self.m2 += other.m2 + d * d * (na * nb / n as f64);
        self.count = n;
        self.min = self.min.min(other.min);
        self.max = self.max.max(other.max);
        Ok(())
    }

    /// Number of values pushed.
    pub fn count(&self) -> u64 {
        self.count
    }
    /// Mean, once there is a value.
    pub fn mean(&self) -> Option<f64> {
        (self.count > 0).then_some(self.mean)
    }
    /// Sum of squared deviations from the mean, `M2 = Σ (x − mean)²`.
    pub fn m2(&self) -> f64 {
        self.m2
    }
    /// Sample variance `M2 / (n − 1)`, once there are two values.
    pub fn variance(&self) -> Option<f64> {
        (self.count > 1).then(|| self.m2 / (self.count - 1) as f64)
    }
    /// Sample standard deviation `√variance`.
    pub fn std(&self) -> Option<f64> {
        self.variance().map(f64::sqrt)
    }
    /// Standard error of the mean `√(variance / n)`.
    pub fn sem(&self) -> Option<f64> {
        self.variance().map(|v| (v / self.count as f64).sqrt())
    }
    /// Smallest value.
    pub fn min(&self) -> Option<f64> {
        (self.count > 0).then_some(self.min)
    }
    /// Largest value.
    pub fn max(&self) -> Option<f64> {
        (self.count > 0).then_some(self.max)
    }
    /// The histogram, if one was asked for.
    pub fn histogram(&self) -> Option<&Histogram> {
        self.histogram.as_ref()
    }
}

impl Extend<f64> for Accumulator {
    fn extend<I: IntoIterator<Item = f64>>(&mut self, iter: I) {
        for x in iter {
            self.push(x);
        }
    }
}

impl FromIterator<f64> for Accumulator {
    fn from_iter<I: IntoIterator<Item = f64>>(iter: I) -> Self {
        let mut acc = Accumulator::new();
        acc.extend(iter);
        acc
    }
}

fn sorted(values: &[f64]) -> Vec<f64> {
    let mut v = values.to_vec();
    v.sort_unstable_by(f64::total_cmp);
    v
}

/// The median of `values`: the middle value, or `(a + b) / 2` of the two
/// middle values for an even count. `None` for an empty slice. Values should
/// be finite (NaN sorts last, by [`f64::total_cmp`]).
///
/// ```
/// use spinball_analysis::estimators::median;
/// assert_eq!(median(&[3.0, 1.0, 2.0]), Some(2.0));
/// assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), Some(2.5));
/// assert_eq!(median(&[]), None);
/// ```
pub fn median(values: &[f64]) -> Option<f64> {
    if values.is_empty() {
        return None;
    }
    let v = sorted(values);
    let n = v.len();
    Some(if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    })
}

/// The `q`-quantile of `values`, `0 <= q <= 1`, interpolating linearly between
/// order statistics (Hyndman–Fan type 7, NumPy's and R's default): with the
/// values sorted as `x₀ ≤ … ≤ x_{n−1}` and `h = (n − 1) q`, it is
/// `x_⌊h⌋ + (h − ⌊h⌋)(x_{⌊h⌋+1} − x_⌊h⌋)`. `None` for an empty slice or `q`
/// outside `[0, 1]`.
///
/// ```
/// use spinball_analysis::estimators::quantile;
/// let x = [10.0, 20.0, 30.0, 40.0, 50.0];
/// assert_eq!(quantile(&x, 0.25), Some(20.0));
/// assert_eq!(quantile(&x, 0.1), Some(14.0));
/// assert_eq!(quantile(&x, 1.0), Some(50.0));
/// ```
pub fn quantile(values: &[f64], q: f64) -> Option<f64> {
    quantiles(values, &[q]).map(|v| v[0])
}

/// Several quantiles (as [`quantile`]) with one sort. `None` for an empty
/// slice or any `q` outside `[0, 1]`.
pub fn quantiles(values: &[f64], qs: &[f64]) -> Option<Vec<f64>> {
    if values.is_empty() || qs.iter().any(|q| !(0.0..=1.0).contains(q)) {
        return None;
    }
    let v = sorted(values);
    Some(qs.iter().map(|&q| quantile_sorted(&v, q)).collect())
}

fn quantile_sorted(v: &[f64], q: f64) -> f64 {
    let h = (v.len() - 1) as f64 * q;
    let i = h.floor() as usize;
    if i + 1 >= v.len() {
        return v[v.len() - 1];
    }
    let frac = h - i as f64;
    if frac == 0.0 {
        v[i]
    } else {
        v[i] + frac * (v[i + 1] - v[i])
    }
}

/// Mean of the values strictly above `threshold`, summed in slice order.
/// `None` if no value is above it.
///
/// ```
/// use spinball_analysis::estimators::conditional_mean;
/// assert_eq!(conditional_mean(&[0.0, 0.25, 0.75, 0.005], 0.01), Some(0.5));
/// assert_eq!(conditional_mean(&[0.0, 0.001], 0.01), None);
/// ```
pub fn conditional_mean(values: &[f64], threshold: f64) -> Option<f64> {
    let (sum, n) = values
        .iter()
        .filter(|&&x| x > threshold)
        .fold((0.0, 0u64), |(s, n), &x| (s + x, n + 1));
    (n > 0).then(|| sum / n as f64)
}

/// Number of values strictly above `threshold`.
pub fn count_above(values: &[f64], threshold: f64) -> usize {
    values.iter().filter(|&&x| x > threshold).count()
}

/// Share of values strictly above `threshold` (0 for an empty slice).
pub fn fraction_above(values: &[f64], threshold: f64) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    count_above(values, threshold) as f64 / values.len() as f64
}

/// A straight line `y = slope·n + intercept` fitted by least squares.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LinearFit {
    /// Slope per collision.
    pub slope: f64,
    /// Value at `n = 0`.
    pub intercept: f64,
}

impl LinearFit {
    /// Ordinary least squares through `points` (`(x, y)` pairs); `None`
    /// unless there are two distinct `x`.
    #[must_use]
    pub fn through(points: &[(f64, f64)]) -> Option<Self> {
        let n = points.len() as f64;
        let x_mean = points.iter().map(|p| p.0).sum::<f64>() / n;
        let y_mean = points.iter().map(|p| p.1).sum::<f64>() / n;
        let (mut sxy, mut sxx) = (0.0, 0.0);
        for &(x, y) in points {
            sxy += (x - x_mean) * (y - y_mean);
            sxx += (x - x_mean) * (x - x_mean);
        }
        (sxx > 0.0).then(|| {
            let slope = sxy / sxx;
            LinearFit {
                slope,
                intercept: y_mean - slope * x_mean,
            }
        })
    }
}
