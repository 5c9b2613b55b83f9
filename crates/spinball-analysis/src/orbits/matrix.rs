//! The 3 × 3 linear algebra the orbit finder needs: products, the
//! characteristic polynomial, and a least-squares solve that survives a
//! singular Newton matrix (a family of orbits makes `M − I` singular).

/// A 3 × 3 matrix, rows first.
pub(crate) type Mat3 = [[f64; 3]; 3];

pub(crate) const IDENTITY: Mat3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// Trace, sum of the principal 2 × 2 minors, determinant: the coefficients
/// of `λ³ − c₁λ² + c₂λ − c₃`.
pub(crate) fn invariants(m: &Mat3) -> (f64, f64, f64) {
    let trace = m[0][0] + m[1][1] + m[2][2];
    let minors = m[0][0] * m[1][1] - m[0][1] * m[1][0] + m[0][0] * m[2][2] - m[0][2] * m[2][0]
        + m[1][1] * m[2][2]
        - m[1][2] * m[2][1];
    let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    (trace, minors, det)
}

/// The real root of `λ³ − c₁λ² + c₂λ − c₃` nearest `start`, by Newton's
/// method with bisection safeguards (a real cubic always has one).
pub(crate) fn real_root_near(c1: f64, c2: f64, c3: f64, start: f64) -> f64 {
    let p = |x: f64| ((x - c1) * x + c2) * x - c3;
    let dp = |x: f64| (3.0 * x - 2.0 * c1) * x + c2;
    // Bracket a root around `start` by doubling steps outwards.
    let mut x = start;
    for _ in 0..100 {
        let d = dp(x);
        if d == 0.0 {
            break;
        }
        let next = x - p(x) / d;
        if !next.is_finite() || (next - x).abs() <= 1e-16 * (1.0 + x.abs()) {
            x = if next.is_finite() { next } else { x };
            break;
        }
        x = next;
    }
    if p(x).abs() <= 1e-12 * (1.0 + c1.abs() + c2.abs() + c3.abs()) {
        return x;
    }
    // Fall back on bisection over a bracket holding every root (Cauchy bound).
    let bound = 1.0 + c1.abs().max(c2.abs()).max(c3.abs());
    let (mut lo, mut hi) = (-bound, bound);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if p(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The minimum-norm least-squares solution of `a x = b`, ignoring singular
/// values below `cutoff` times the largest (one-sided Jacobi SVD). Returns
/// the solution and how many singular values were dropped.
pub(crate) fn solve_least_squares(a: &Mat3, b: [f64; 3], cutoff: f64) -> ([f64; 3], usize) {
    // Columns of `a` are rotated until orthogonal; `v` accumulates the rotations.
    let mut u: [[f64; 3]; 3] = std::array::from_fn(|c| std::array::from_fn(|r| a[r][c]));
    let mut v: [[f64; 3]; 3] = IDENTITY;
    let dot = |x: &[f64; 3], y: &[f64; 3]| x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    for _ in 0..60 {
        let mut rotated = false;
        for (i, j) in [(0, 1), (0, 2), (1, 2)] {
            let alpha = dot(&u[i], &u[i]);
            let beta = dot(&u[j], &u[j]);
            let gamma = dot(&u[i], &u[j]);
            if gamma.abs() <= 1e-17 * (alpha * beta).sqrt() || gamma == 0.0 {
                continue;
            }
            rotated = true;
            let zeta = (beta - alpha) / (2.0 * gamma);
            let t = zeta.signum() / (zeta.abs() + (1.0 + zeta * zeta).sqrt());
            let c = 1.0 / (1.0 + t * t).sqrt();
            let s = c * t;
            for cols in [&mut u, &mut v] {
                let (ci, cj) = (cols[i], cols[j]);
                cols[i] = std::array::from_fn(|k| c * ci[k] - s * cj[k]);
                cols[j] = std::array::from_fn(|k| s * ci[k] + c * cj[k]);
            }
        }
        if !rotated {
            break;
        }
    }
    let sigma2: [f64; 3] = std::array::from_fn(|i| dot(&u[i], &u[i]));
    let largest = sigma2.iter().copied().fold(0.0, f64::max);
    let mut x = [0.0; 3];
    let mut dropped = 0;
    for i in 0..3 {
        if sigma2[i] <= cutoff * cutoff * largest || sigma2[i] == 0.0 {
            dropped += 1;
            continue;
        }
        let k = dot(&u[i], &b) / sigma2[i];
        for (xr, vr) in x.iter_mut().zip(v[i]) {
            *xr += k * vr;
        }
    }
    (x, dropped)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn least_squares_solves_regular_and_singular_systems() {
        let a = [[2.0, 1.0, 0.0], [1.0, 3.0, 1.0], [0.0, 1.0, 4.0]];
        let x0 = [0.3, -1.2, 0.7];
        let b = std::array::from_fn(|r| (0..3).map(|c| a[r][c] * x0[c]).sum());
        let (x, dropped) = solve_least_squares(&a, b, 1e-12);
        assert_eq!(dropped, 0);
        for (x, x0) in x.iter().zip(x0) {
            assert!((x - x0).abs() < 1e-14);
        }
        // Rank 2: the third column repeats the first; the minimum-norm
        // solution splits the weight equally between them.
        let s = [[1.0, 2.0, 1.0], [0.0, 1.0, 0.0], [3.0, 0.0, 3.0]];
        let (x, dropped) = solve_least_squares(&s, [2.0, 0.0, 6.0], 1e-10);
        assert_eq!(dropped, 1);
        assert!((x[0] - 1.0).abs() < 1e-14 && x[1].abs() < 1e-14 && (x[2] - 1.0).abs() < 1e-14);
    }

    #[test]
    fn cubic_root_and_invariants() {
        // diag(2, 0.5, 1): c = (3.5, 3.5, 1).
        let m = [[2.0, 0.0, 0.0], [0.0, 0.5, 0.0], [0.0, 0.0, 1.0]];
        let (c1, c2, c3) = invariants(&m);
        assert_eq!((c1, c2, c3), (3.5, 3.5, 1.0));
        assert!((real_root_near(c1, c2, c3, 1.1) - 1.0).abs() < 1e-14);
        assert!((real_root_near(c1, c2, c3, 3.0) - 2.0).abs() < 1e-14);
    }
}
