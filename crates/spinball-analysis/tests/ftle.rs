//! FTLE distribution statistics against hand-computed values.

use spinball_analysis::estimators::{CHAOS_THRESHOLD, FtleDistribution, THRESHOLD_BAND};

/// Ten exponents: three regular (≤ 0.01), seven chaotic.
fn sample() -> FtleDistribution {
    FtleDistribution::new(vec![
        0.5, 0.0, 0.25, 0.003, 0.75, 0.5, 0.02, 0.25, 0.5, 0.04,
    ])
    .unwrap()
}

#[test]
fn moments_hand_computed() {
    let d = sample();
    assert_eq!(d.len(), 10);
    // Σ = 2.813 → mean 0.2813
    assert!((d.mean() - 0.2813).abs() < 1e-15);
    // Σ (x − mean)² = Σx² − n·mean² = 1.439509 − 0.7912969
    let m2 = 1.439_509 - 10.0 * 0.2813 * 0.2813;
    assert!((d.std().unwrap() - (m2 / 9.0f64).sqrt()).abs() < 1e-14);
    assert!((d.sem().unwrap() - (m2 / 90.0f64).sqrt()).abs() < 1e-14);
    assert_eq!((d.min(), d.max()), (0.0, 0.75));
}

#[test]
fn order_statistics_hand_computed() {
    let d = sample();
    // sorted: 0, 0.003, 0.02, 0.04, 0.25, 0.25, 0.5, 0.5, 0.5, 0.75
    assert_eq!(d.median(), 0.25);
    assert_eq!(d.quantile(0.0).unwrap(), 0.0);
    assert_eq!(d.quantile(1.0).unwrap(), 0.75);
    // h = 9 · 0.25 = 2.25 → 0.02 + 0.25 · (0.04 − 0.02)
    assert!((d.quantile(0.25).unwrap() - 0.025).abs() < 1e-15);
    assert!(d.quantile(-0.1).is_err());
}

#[test]
fn chaotic_fraction_and_conditional_mean() {
    let d = sample();
    assert_eq!(d.chaotic_fraction(CHAOS_THRESHOLD), 0.8);
    let f = d.chaotic_fraction_at(0.01);
    assert_eq!((f.chaotic, f.total), (8, 10));
    assert!((f.sem - (0.8f64 * 0.2 / 10.0).sqrt()).abs() < 1e-15);
    // chaotic part: 0.5 0.25 0.75 0.5 0.02 0.25 0.5 0.04 → Σ = 2.81, n = 8
    assert!((d.conditional_mean(0.01).unwrap() - 2.81 / 8.0).abs() < 1e-15);
    assert_eq!(d.conditional_mean(1.0), None);
    // DHF product λ · f_ch
    assert!((d.dhf_product(0.01) - 0.2813 * 0.8).abs() < 1e-15);
}

#[test]
fn threshold_band() {
    let d = sample();
    let band = d.chaotic_fraction_band(&THRESHOLD_BAND);
    // 0.001, 0.002: 9/10; 0.005, 0.01: 8/10; 0.02: 7/10 (strictly above); 0.05: 6/10.
    let fractions: Vec<f64> = band.points.iter().map(|p| p.fraction).collect();
    assert_eq!(fractions, vec![0.9, 0.9, 0.8, 0.8, 0.7, 0.6]);
    assert_eq!((band.min, band.max), (0.6, 0.9));
    assert!((band.spread() - 0.3).abs() < 1e-15);
    let empty = d.chaotic_fraction_band(&[]);
    assert_eq!((empty.min, empty.max), (0.8, 0.8));
}

#[test]
fn histograms() {
    let d = sample();
    let h = d.histogram(0.0, 1.0, 4).unwrap();
    assert_eq!(h.counts(), &[4, 2, 3, 1]);
    assert_eq!(h.total(), 10);
    let auto = d.auto_histogram(3).unwrap();
    assert_eq!(
        auto.counts().iter().sum::<u64>(),
        10,
        "min and max fall inside"
    );
    let flat = FtleDistribution::new(vec![0.0, 0.0]).unwrap();
    assert_eq!(
        flat.auto_histogram(5).unwrap().counts().iter().sum::<u64>(),
        2
    );
}

#[test]
fn extend_is_concatenation() {
    let mut a = FtleDistribution::new(vec![0.5, 0.0]).unwrap();
    let b = FtleDistribution::new(vec![0.25]).unwrap();
    a.extend_from(&b);
    assert_eq!(a.exponents(), &[0.5, 0.0, 0.25]);
}

#[test]
fn rejects_empty_and_non_finite() {
    assert!(FtleDistribution::new(vec![]).is_err());
    assert!(FtleDistribution::new(vec![0.1, f64::NAN]).is_err());
    assert!(FtleDistribution::new(vec![f64::INFINITY]).is_err());
}
