//! Deterministic escape samples with a known survival law, for the tests
//! of escape estimators and of the figures drawn from them.

/// `n` escape times at the quantiles of the survival law whose inverse is
/// `inv` (`inv(u)` is the time at which `P = u`), evaluated at
/// `u = 1 − (i + ½)/n`, and censored at `budget`: the times (at most
/// `budget`) and a censored flag per ball.
pub fn censored_quantiles(
    n: usize,
    budget: f64,
    inv: impl Fn(f64) -> f64,
) -> (Vec<f64>, Vec<bool>) {
    (0..n)
        .map(|i| {
            let x = inv(1.0 - (i as f64 + 0.5) / n as f64);
            (x.min(budget), x > budget)
        })
        .unzip()
}
