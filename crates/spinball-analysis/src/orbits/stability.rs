//! Linear stability of a periodic orbit from its monodromy matrix: the
//! multipliers, the class (hyperbolic, elliptic with its rotation number,
//! parabolic) and Greene's residue.
//!
//! Documented in the group docs (`orbits/mod.rs`), section "Stability".

use super::matrix::{Mat3, invariants, real_root_near};

/// Default tolerance of the classification: a pair trace within this of ±2
/// is parabolic (see [`Stability::classify`]).
pub const DEFAULT_CLASS_TOLERANCE: f64 = 1e-9;

/// Largest scaled `det(σI − M)` for which `σ = sign(det M)` is taken as an
/// exact multiplier ([`Stability::unit_residual`]).
const UNIT_RESIDUAL_TOLERANCE: f64 = 1e-10;

/// A complex multiplier `re + i·im`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Multiplier {
    /// Real part.
    pub re: f64,
    /// Imaginary part.
    pub im: f64,
}

impl Multiplier {
    /// `|λ|`.
    #[must_use]
    pub fn modulus(self) -> f64 {
        self.re.hypot(self.im)
    }
}

/// What a periodic orbit's linearisation does to its neighbours.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum StabilityClass {
    /// Real multipliers `λ, 1/λ` with `|λ| > 1`: neighbours leave
    /// exponentially (`multiplier < 0`: with reflection).
    Hyperbolic {
        /// The multiplier of largest modulus, signed.
        multiplier: f64,
    },
    /// Multipliers `e^{±2πiν}` on the unit circle: neighbours turn about the
    /// orbit, which an island surrounds.
    Elliptic {
        /// Rotation number `ν ∈ (0, ½)` per period.
        rotation: f64,
    },
    /// A double multiplier `+1` (`sign = 1`) or `−1` (`sign = −1`): the
    /// boundary between the other classes.
    Parabolic {
        /// `+1` or `−1`.
        sign: i8,
    },
    /// A complex pair off the unit circle (not met on the reversible
    /// orbits of the built-in tables; reported, not hidden).
    Loxodromic {
        /// `|λ|` of the pair.
        modulus: f64,
        /// Its argument over `2π`.
        rotation: f64,
    },
}

impl StabilityClass {
    /// Short name: `hyperbolic`, `elliptic`, `parabolic`, `loxodromic`.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            StabilityClass::Hyperbolic { .. } => "hyperbolic",
            StabilityClass::Elliptic { .. } => "elliptic",
            StabilityClass::Parabolic { .. } => "parabolic",
            StabilityClass::Loxodromic { .. } => "loxodromic",
        }
    }

    /// Whether neighbours stay near the orbit to linear order.
    #[must_use]
    pub fn is_elliptic(&self) -> bool {
        matches!(self, StabilityClass::Elliptic { .. })
    }
}

/// The linear stability of a periodic orbit.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Stability {
    /// The monodromy matrix `∂F^p/∂(s, v∥, u)`, rows first.
    pub monodromy: [[f64; 3]; 3],
    /// Its determinant: `(−1)^p` for α > 0, `+1` at α = 0 (to rounding).
    pub determinant: f64,
    /// Its trace.
    pub trace: f64,
    /// The real multiplier nearest `σ = sign(det)`, the direction of the
    /// family of symmetric orbits (or of the decoupled spin at α = 0):
    /// `σ` itself when `|unit_residual|` is at most 1e-10.
    pub unit_multiplier: f64,
    /// The characteristic polynomial `det(σI − M)` at `σ`, over
    /// `1 + |c₁| + |c₂| + |c₃|` (its coefficients): zero when `σ` is a
    /// multiplier, as on a symmetric orbit.
    pub unit_residual: f64,
    /// `T = λ₁ + λ₂`, the trace of the other two multipliers.
    pub pair_trace: f64,
    /// Greene's residue `(2 − T)/4`: elliptic in `(0, 1)`.
    pub residue: f64,
    /// The three multipliers: the unit one, then the pair.
    pub multipliers: [Multiplier; 3],
    /// The class of the pair.
    pub class: StabilityClass,
    /// The tolerance the class was decided with.
    pub tolerance: f64,
}

impl Stability {
    /// The stability of a monodromy matrix, classified with `tolerance`
    /// ([`DEFAULT_CLASS_TOLERANCE`] unless you have a reason).
    ///
    /// The three multipliers are `σ = sign(det M)` if it is one to rounding
    /// (scaled `det(σI − M)` at most 1e-10: a symmetric orbit, or α = 0),
    /// else the real one nearest `σ`, and the pair
    /// `λ² − Tλ + D = 0` left after dividing it out. The class is that of
    /// the pair: parabolic if `|T ∓ 2| ≤ tolerance`; otherwise elliptic if
    /// the pair is complex with `|D − 1| ≤ tolerance`, loxodromic if complex
    /// off the circle, hyperbolic if real.
    #[must_use]
    pub fn classify(monodromy: [[f64; 3]; 3], tolerance: f64) -> Self {
        let m: Mat3 = monodromy;
        let (c1, c2, c3) = invariants(&m);
        let sigma = if c3 < 0.0 { -1.0 } else { 1.0 };
        // σ is a multiplier when the characteristic polynomial vanishes
        // there to rounding; dividing it out exactly keeps T accurate where
        // all three multipliers meet at 1 (a root finder would lose a third
        // of the digits at a triple root).
        let scale = 1.0 + c1.abs() + c2.abs() + c3.abs();
        let at_sigma = ((sigma - c1) * sigma + c2) * sigma - c3;
        let r = if at_sigma.abs() <= UNIT_RESIDUAL_TOLERANCE * scale {
            sigma
        } else {
            real_root_near(c1, c2, c3, sigma)
        };
        let t = c1 - r;
        let d = if r == 0.0 { 1.0 } else { c3 / r };
        let disc = t * t - 4.0 * d;
        let pair = if disc >= 0.0 {
            // The root of larger modulus without cancellation, then D over it.
            let q = 0.5 * (t + t.signum() * disc.sqrt());
            let (a, b) = if q == 0.0 { (0.0, 0.0) } else { (q, d / q) };
            let big = if a.abs() >= b.abs() { a } else { b };
            let small = if a.abs() >= b.abs() { b } else { a };
            [
                Multiplier { re: big, im: 0.0 },
                Multiplier { re: small, im: 0.0 },
            ]
        } else {
            let im = 0.5 * (-disc).sqrt();
            [
                Multiplier { re: 0.5 * t, im },
                Multiplier {
                    re: 0.5 * t,
                    im: -im,
                },
            ]
        };
        let class = if (t - 2.0).abs() <= tolerance {
            StabilityClass::Parabolic { sign: 1 }
        } else if (t + 2.0).abs() <= tolerance {
            StabilityClass::Parabolic { sign: -1 }
        } else if disc < 0.0 {
            let rotation = pair[0].im.atan2(pair[0].re) / std::f64::consts::TAU;
            if (d - 1.0).abs() <= tolerance {
                StabilityClass::Elliptic { rotation }
            } else {
                StabilityClass::Loxodromic {
                    modulus: d.abs().sqrt(),
                    rotation,
                }
            }
        } else {
            StabilityClass::Hyperbolic {
                multiplier: pair[0].re,
            }
        };
        Stability {
            monodromy,
            determinant: c3,
            trace: c1,
            unit_multiplier: r,
            unit_residual: at_sigma / scale,
            pair_trace: t,
            residue: (2.0 - t) / 4.0,
            multipliers: [Multiplier { re: r, im: 0.0 }, pair[0], pair[1]],
            class,
            tolerance,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rotation(theta: f64) -> [[f64; 3]; 3] {
        let (s, c) = theta.sin_cos();
        [[1.0, 0.3, 0.1], [0.0, c, -s], [0.0, s, c]]
    }

    #[test]
    fn classes_at_and_around_the_tolerance() {
        let e = Stability::classify(rotation(0.5), DEFAULT_CLASS_TOLERANCE);
        match e.class {
            StabilityClass::Elliptic { rotation } => {
                assert!((rotation - 0.5 / std::f64::consts::TAU).abs() < 1e-15);
            }
            other => panic!("{other:?}"),
        }
        assert!((e.residue - (2.0 - 2.0 * 0.5f64.cos()) / 4.0).abs() < 1e-15);
        assert!(e.unit_residual.abs() < 1e-15 && (e.determinant - 1.0).abs() < 1e-15);
        // A rotation by 1e-5 has T = 2 − 1e-10: within the tolerance 1e-9.
        let p = Stability::classify(rotation(1e-5), DEFAULT_CLASS_TOLERANCE);
        assert_eq!(p.class, StabilityClass::Parabolic { sign: 1 });
        // ... but elliptic at the tolerance 1e-11.
        assert!(
            Stability::classify(rotation(1e-5), 1e-11)
                .class
                .is_elliptic()
        );
        let h = Stability::classify(
            [[1.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 0.25]],
            DEFAULT_CLASS_TOLERANCE,
        );
        assert_eq!(h.class, StabilityClass::Hyperbolic { multiplier: 4.0 });
        assert_eq!(h.residue, (2.0 - 4.25) / 4.0);
        let inv = Stability::classify(
            [[-1.0, 0.0, 0.0], [0.0, -3.0, 0.0], [0.0, 0.0, -1.0 / 3.0]],
            DEFAULT_CLASS_TOLERANCE,
        );
        assert_eq!(inv.unit_multiplier, -1.0);
        assert!(
            matches!(inv.class, StabilityClass::Hyperbolic { multiplier } if (multiplier + 3.0).abs() < 1e-15)
        );
        let flip = Stability::classify(rotation(std::f64::consts::PI), DEFAULT_CLASS_TOLERANCE);
        assert_eq!(flip.class, StabilityClass::Parabolic { sign: -1 });
    }
}
