//! The spin collision law (paper eqs. 1–3), in the half-turn form of
//! [`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#half-turn-form).
//!
//! With `V = (v_x, v_y, √α u)` the collision is the rotation by π about the unit
//! axis `a = (t_x, t_y, -√α)/√(1+α)`: `V' = 2(V·a)a − V`. This is the law the
//! paper writes in components, but as an orthogonal map it conserves
//! `|V|² = 2E` up to rounding, keeps `Q = v∥ − αu = √(1+α) V·a` visibly
//! invariant, and stays well conditioned as α → 0 and α → ∞.

use glam::DVec2;

use crate::error::SpinLawError;

/// The collision law for one value of the spin parameter `α = I/(m r²)`.
///
/// Coefficients (paper eqs. 1–3): `β = (1−α)/(1+α)`, `γ = 2α/(1+α)`,
/// `δ = 2/(1+α)`:
///
/// ```text
/// v∥' = β v∥ − γ u,   v⊥' = −v⊥,   u' = −β u − δ v∥
/// ```
///
/// At α = 0 the spin is decoupled and, as in the paper's reference code, `u`
/// is left unchanged (the component formula would flip its sign).
///
/// ```
/// use spinball_core::SpinLaw;
/// let disk = SpinLaw::new(0.5)?;
/// let (v, u) = disk.collide_components(0.6, 0.2);
/// assert!((disk.q(v, u) - disk.q(0.6, 0.2)).abs() < 1e-15); // Q is conserved
/// # Ok::<(), spinball_core::SpinLawError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SpinLaw {
    alpha: f64,
    beta: f64,
    gamma: f64,
    delta: f64,
}

impl SpinLaw {
    /// The law for a physical ball, `0 <= α <= 1` (0 specular, 2/5 solid
    /// sphere, 1/2 disk, 2/3 hollow sphere, 1 thin ring).
    ///
    /// # Errors
    /// [`SpinLawError::NonFinite`], [`SpinLawError::Negative`], and
    /// [`SpinLawError::Unphysical`] for α > 1 (use [`SpinLaw::extended`]).
    pub fn new(alpha: f64) -> Result<Self, SpinLawError> {
        let law = Self::extended(alpha)?;
        if alpha > 1.0 {
            return Err(SpinLawError::Unphysical(alpha));
        }
        Ok(law)
    }

    /// The law for any finite `α >= 0`, including the mathematical extension
    /// α > 1 towards the no-slip limit (α → ∞, β → −1).
    ///
    /// # Errors
    /// [`SpinLawError::NonFinite`], [`SpinLawError::Negative`].
    pub fn extended(alpha: f64) -> Result<Self, SpinLawError> {
        if !alpha.is_finite() {
            return Err(SpinLawError::NonFinite(alpha));
        }
        if alpha < 0.0 {
            return Err(SpinLawError::Negative(alpha));
        }
        let alpha = alpha + 0.0; // normalise -0.0
        let inv = 1.0 / (1.0 + alpha);
        Ok(SpinLaw {
            alpha,
            beta: (1.0 - alpha) * inv,
            gamma: 2.0 * alpha * inv,
            delta: 2.0 * inv,
        })
    }

    /// Specular reflection, α = 0.
    pub fn specular() -> Self {
        Self::extended(0.0).expect("0 is valid")
    }

    /// α = I/(m r²).
    #[inline]
    pub fn alpha(&self) -> f64 {
        self.alpha
    }
    /// β = (1−α)/(1+α), the tangential restitution.
    #[inline]
    pub fn beta(&self) -> f64 {
        self.beta
    }
    /// γ = 2α/(1+α).
    #[inline]
    pub fn gamma(&self) -> f64 {
        self.gamma
    }
    /// δ = 2/(1+α).
    #[inline]
    pub fn delta(&self) -> f64 {
        self.delta
    }
    /// Whether spin and translation are coupled (α > 0).
    #[inline]
    pub fn is_coupled(&self) -> bool {
        self.alpha > 0.0
    }

    /// The collision for velocity `v` and spin `u` at a wall with unit tangent
    /// `t` (half-turn form): with `k = 2Q/(1+α) = δ Q`,
    /// `v' = k t − v` and `u' = −u − k` (`u' = u` at α = 0).
    ///
    /// `t` is unit only to rounding. Dividing by `a·a = (t·t + α)/(1+α)`
    /// instead of assuming 1 would make this single reflection exact, but costs
    /// a division on the critical path of every collision; the energy error it
    /// removes is instead removed, together with every other rounding error, by
    /// the energy-shell restore of [`Billiard::step`](crate::Billiard::step),
    /// which is what actually stops the drift (a biased or random-walk error
    /// per collision cannot accumulate when each collision puts `|V|` back).
    #[inline]
    pub fn collide(&self, v: DVec2, u: f64, t: DVec2) -> (DVec2, f64) {
        let k = (v.dot(t) - self.alpha * u) * self.delta;
        let v_new = t * k - v;
        let u_new = if self.alpha > 0.0 { -u - k } else { u };
        (v_new, u_new)
    }

    /// Paper eqs. (1) and (3) on the tangential components: `(v∥, u) → (v∥', u')`.
    #[inline]
    pub fn collide_components(&self, v_par: f64, u: f64) -> (f64, f64) {
        let (v, u) = self.collide(DVec2::new(v_par, 0.0), u, DVec2::X);
        (v.x, u)
    }

    /// The conserved quantity `Q = v∥ − α u` (paper eq. 12).
    #[inline]
    pub fn q(&self, v_par: f64, u: f64) -> f64 {
        v_par - self.alpha * u
    }

    /// Kinetic energy `E = ½|v|² + ½ α u²` (paper eq. 4, m = 1).
    #[inline]
    pub fn energy(&self, v: DVec2, u: f64) -> f64 {
        0.5 * self.norm2(v, u)
    }

    /// `|V|² = |v|² + α u² = 2E`.
    #[inline]
    pub(crate) fn norm2(&self, v: DVec2, u: f64) -> f64 {
        v.length_squared() + self.alpha * u * u
    }

    /// The matrix `M` of paper eq. (7) acting on `(v∥, u)`; `det M = −1`
    /// (at α = 0 the reference convention leaves `u` alone, so `M = diag(1, 1)`).
    pub fn matrix(&self) -> [[f64; 2]; 2] {
        if self.alpha > 0.0 {
            [[self.beta, -self.gamma], [-self.delta, -self.beta]]
        } else {
            [[1.0, 0.0], [0.0, 1.0]]
        }
    }
}
