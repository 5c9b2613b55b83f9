//! Accumulator, histogram and order statistics against hand-computed values,
//! and Chan merging against sequential pushing.

use proptest::prelude::*;
use spinball_analysis::estimators::{
    Accumulator, Histogram, conditional_mean, fraction_above, median, quantile, quantiles,
};

#[test]
fn accumulator_hand_computed() {
    // x = 2, 4, 4, 4, 5, 5, 7, 9: mean 5, Σ(x − 5)² = 32.
    let acc = Accumulator::from_slice(&[2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0]);
    assert_eq!(acc.count(), 8);
    assert_eq!(acc.mean(), Some(5.0));
    assert_eq!(acc.m2(), 32.0);
    assert_eq!(acc.variance(), Some(32.0 / 7.0));
    assert_eq!(acc.std(), Some((32.0f64 / 7.0).sqrt()));
    assert_eq!(acc.sem(), Some((32.0f64 / 7.0 / 8.0).sqrt()));
    assert_eq!((acc.min(), acc.max()), (Some(2.0), Some(9.0)));
}

#[test]
fn accumulator_small_counts() {
    let empty = Accumulator::new();
    assert_eq!(empty.count(), 0);
    assert_eq!(empty.mean(), None);
    assert_eq!(empty.min(), None);
    assert_eq!(empty.sem(), None);
    let one = Accumulator::from_slice(&[3.5]);
    assert_eq!(one.mean(), Some(3.5));
    assert_eq!((one.min(), one.max()), (Some(3.5), Some(3.5)));
    assert_eq!(one.variance(), None);
    assert_eq!(one.sem(), None);
}

#[test]
fn accumulator_is_stable_for_large_offsets() {
    // Naive Σx² − n·mean² loses everything here; Welford keeps it.
    let xs: Vec<f64> = (0..1000).map(|i| 1e9 + (i % 2) as f64).collect();
    let acc = Accumulator::from_slice(&xs);
    assert_eq!(acc.mean(), Some(1e9 + 0.5));
    let expected = 1000.0 * 0.25 / 999.0;
    assert!((acc.variance().unwrap() - expected).abs() < 1e-12);
}

#[test]
fn merge_with_empty_is_identity() {
    let a = Accumulator::from_slice(&[1.0, 2.0, 4.0]);
    let mut b = Accumulator::new();
    b.merge(&a).unwrap();
    assert_eq!(b, a);
    let mut c = a.clone();
    c.merge(&Accumulator::new()).unwrap();
    assert_eq!(c, a);
}

#[test]
fn merge_hand_computed() {
    // [1, 2, 3] and [10, 20]: n = 5, mean 7.2, M2 = Σx² − n·mean² = 514 − 259.2.
    let mut a = Accumulator::from_slice(&[1.0, 2.0, 3.0]);
    a.merge(&Accumulator::from_slice(&[10.0, 20.0])).unwrap();
    assert_eq!(a.count(), 5);
    assert!((a.mean().unwrap() - 7.2).abs() < 1e-15);
    assert!((a.m2() - 254.8).abs() < 1e-12);
    assert_eq!((a.min(), a.max()), (Some(1.0), Some(20.0)));
}

#[test]
fn histogram_bins_and_edges() {
    let mut h = Histogram::new(-1.0, 1.0, 4).unwrap();
    for x in [
        -1.0,
        -0.75,
        -0.5,
        0.0,
        0.49,
        0.5,
        0.999,
        1.0,
        2.0,
        -1.5,
        f64::NAN,
    ] {
        h.push(x);
    }
    assert_eq!(h.counts(), &[2, 1, 2, 2]);
    assert_eq!((h.underflow(), h.overflow(), h.nan()), (1, 2, 1));
    assert_eq!(h.total(), 11);
    assert_eq!(h.edges(), vec![-1.0, -0.5, 0.0, 0.5, 1.0]);
    assert_eq!(h.center(0), -0.75);
    assert_eq!(h.bin_width(), 0.5);
    let d = h.density();
    assert_eq!(d[0], 2.0 / (11.0 * 0.5));
}

#[test]
fn histogram_rejects_bad_binning() {
    assert!(Histogram::new(1.0, 1.0, 3).is_err());
    assert!(Histogram::new(0.0, f64::INFINITY, 3).is_err());
    assert!(Histogram::new(0.0, 1.0, 0).is_err());
    let mut a = Histogram::new(0.0, 1.0, 4).unwrap();
    let b = Histogram::new(0.0, 1.0, 5).unwrap();
    assert!(a.merge(&b).is_err());
    let mut acc = Accumulator::with_histogram(Histogram::new(0.0, 1.0, 4).unwrap());
    assert!(acc.merge(&Accumulator::new()).is_err());
    assert!(acc.merge(&Accumulator::with_histogram(b)).is_err());
}

#[test]
fn order_statistics_hand_computed() {
    let x = [5.0, 1.0, 4.0, 2.0, 3.0];
    assert_eq!(median(&x), Some(3.0));
    assert_eq!(median(&[1.0, 2.0, 3.0, 10.0]), Some(2.5));
    assert_eq!(median(&[]), None);
    // type 7: h = 4q
    assert_eq!(quantile(&x, 0.0), Some(1.0));
    assert_eq!(quantile(&x, 0.5), Some(3.0));
    assert_eq!(quantile(&x, 0.625), Some(3.5));
    assert_eq!(quantile(&x, 1.0), Some(5.0));
    assert_eq!(quantile(&x, 1.5), None);
    assert_eq!(
        quantiles(&x, &[0.25, 0.75]).unwrap(),
        vec![2.0, 4.0],
        "quartiles of 1..5"
    );
    assert_eq!(conditional_mean(&[0.0, 0.005, 0.25, 0.75], 0.01), Some(0.5));
    assert_eq!(conditional_mean(&[0.0, 0.01], 0.01), None, "strictly above");
    assert_eq!(fraction_above(&[0.0, 0.005, 0.25, 0.75], 0.01), 0.5);
    assert_eq!(fraction_above(&[], 0.01), 0.0);
}

proptest! {
    /// Chan's merge of [0, k) and [k, n) equals pushing all n to rounding;
    /// count, min, max and histogram counts exactly.
    #[test]
    fn merge_matches_sequential(
        xs in prop::collection::vec(-1e3f64..1e3, 2..200),
        split in 0usize..200,
    ) {
        let k = split % (xs.len() + 1);
        let h = || Histogram::new(-1e3, 1e3, 17).unwrap();
        let mut all = Accumulator::with_histogram(h());
        all.extend(xs.iter().copied());
        let mut a = Accumulator::with_histogram(h());
        a.extend(xs[..k].iter().copied());
        let mut b = Accumulator::with_histogram(h());
        b.extend(xs[k..].iter().copied());
        a.merge(&b).unwrap();
        prop_assert_eq!(a.count(), all.count());
        prop_assert_eq!(a.min(), all.min());
        prop_assert_eq!(a.max(), all.max());
        prop_assert_eq!(a.histogram(), all.histogram());
        let scale = xs.iter().map(|x| x.abs()).fold(1.0, f64::max);
        prop_assert!((a.mean().unwrap() - all.mean().unwrap()).abs() <= 1e-12 * scale);
        prop_assert!((a.m2() - all.m2()).abs() <= 1e-10 * (all.m2() + scale * scale));
    }

    /// Pushing in the same order always gives the same bits.
    #[test]
    fn sequential_push_is_bitwise_reproducible(xs in prop::collection::vec(-1.0f64..1.0, 1..100)) {
        let a = Accumulator::from_slice(&xs);
        let b: Accumulator = xs.iter().copied().collect();
        prop_assert_eq!(a.mean().unwrap().to_bits(), b.mean().unwrap().to_bits());
        prop_assert_eq!(a.m2().to_bits(), b.m2().to_bits());
    }
}

#[cfg(feature = "serde")]
#[test]
fn accumulator_round_trips_through_json() {
    let mut acc = Accumulator::with_histogram(Histogram::new(0.0, 1.0, 3).unwrap());
    acc.extend([0.1, 0.5, 0.7, 2.0]);
    let json = serde_json::to_string(&acc).unwrap();
    let back: Accumulator = serde_json::from_str(&json).unwrap();
    assert_eq!(back, acc);
}
