//! Random directions in the 5-D phase space, for tangent vectors and shadow
//! trajectories.
//!
//! Every Lyapunov computation starts its tangent vector (or its
//! finite-difference shadow) along a random unit direction drawn from the
//! initial condition's own stream, right after the initial state. The
//! scalar path (`spinball-analysis`) and the lane kernels
//! (`spinball-lanes`) must draw the very same direction to agree, so the
//! draw lives here, below both.

use rand::Rng;

use crate::tangent::TangentVector;

/// A uniformly random unit vector in 5-D (rejection sampling in the unit
/// ball, then normalised).
///
/// ```
/// use spinball_core::{ic_rng, random_direction};
///
/// let d = random_direction(&mut ic_rng(1, 0));
/// assert!((d.norm() - 1.0).abs() < 1e-15);
/// ```
pub fn random_direction<R: Rng + ?Sized>(rng: &mut R) -> TangentVector {
    loop {
        let z: [f64; 5] = std::array::from_fn(|_| 2.0 * rng.random::<f64>() - 1.0);
        let n2: f64 = z.iter().map(|x| x * x).sum();
        if n2 > 1e-4 && n2 <= 1.0 {
            return TangentVector::from_array(z) * (1.0 / n2.sqrt());
        }
    }
}
