//! Exact tangent dynamics: how an infinitesimal neighbour moves.
//!
//! Lyapunov exponents measure how fast neighbours separate. The paper does it
//! with a shadow trajectory `δ0 = 1e-7` away; carrying the *linearised* flow
//! instead needs no `δ0`, never lets the neighbour hit another wall, and is
//! exact to rounding. The rule ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#exact-tangent-dynamics); at α = 0 it is the
//! Dellago–Posch–Hoover hard-disk rule) for a collision at `x_c` with
//! pre-collision `v, u` and post-collision `v'`:
//!
//! ```text
//! δτ  = −(n·δx)/(n·v)
//! δs  = t·δx + (t·v) δτ
//! δx' = δx + (v − v') δτ
//! (δv', δu') = collide(δv, δu) + k δs ( −(1+β)[(t·v) n + (n·v) t] + γ u n ,  δ (n·v) )
//! ```

use std::ops::{Add, Mul, Sub};

use glam::DVec2;
use spinball_geometry::Hit;

use crate::spin_law::SpinLaw;
use crate::state::State;

/// Largest accepted number of collisions between two re-orthonormalisations
/// (QR steps) of the tangent vectors of a Lyapunov spectrum: the
/// `qr_interval` of `spinball_analysis::estimators::SpectrumOptions` and of
/// `spinball_lanes::LaneBilliard::spectrum`.
///
/// A chaotic billiard stretches by about `e` per collision on average and by
/// much more at near-grazing collisions on curved walls; between two QR steps
/// the five vectors collapse towards the most unstable direction and the
/// weakest ones lose about `2·ln(growth)/ln 10` of their 16 digits. The outer
/// pair `±λ` and the sum are unaffected by the interval; the neutral middle
/// exponents get worse with it (stadium `a = 1`, α = 0.5, 10⁶ collisions: a
/// middle pair of `±5.1e-4` at interval 1, `5.4e-4` at 4, `6.0e-4` at 8,
/// `7.6e-4` at 16). Keep the default 1 when the middle exponents matter;
/// more than this constant is refused.
pub const MAX_QR_INTERVAL: u32 = 32;

/// A tangent vector `(δx, δv, δu)`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TangentVector {
    /// Position part.
    pub dx: DVec2,
    /// Velocity part.
    pub dv: DVec2,
    /// Spin part.
    pub du: f64,
}

impl TangentVector {
    /// From `(δx, δy, δv_x, δv_y, δu)`.
    pub fn from_array(z: [f64; 5]) -> Self {
        TangentVector {
            dx: DVec2::new(z[0], z[1]),
            dv: DVec2::new(z[2], z[3]),
            du: z[4],
        }
    }
    /// As `(δx, δy, δv_x, δv_y, δu)`.
    pub fn to_array(&self) -> [f64; 5] {
        [self.dx.x, self.dx.y, self.dv.x, self.dv.y, self.du]
    }
    /// Euclidean inner product in the 5 coordinates.
    #[inline]
    pub fn dot(&self, o: &TangentVector) -> f64 {
        self.dx.dot(o.dx) + self.dv.dot(o.dv) + self.du * o.du
    }
    /// Euclidean norm in the 5 coordinates (the paper's separation measure).
    #[inline]
    pub fn norm(&self) -> f64 {
        self.dot(self).sqrt()
    }
}

impl Add for TangentVector {
    type Output = TangentVector;
    fn add(self, o: TangentVector) -> TangentVector {
        TangentVector {
            dx: self.dx + o.dx,
            dv: self.dv + o.dv,
            du: self.du + o.du,
        }
    }
}
impl Sub for TangentVector {
    type Output = TangentVector;
    fn sub(self, o: TangentVector) -> TangentVector {
        TangentVector {
            dx: self.dx - o.dx,
            dv: self.dv - o.dv,
            du: self.du - o.du,
        }
    }
}
impl Mul<f64> for TangentVector {
    type Output = TangentVector;
    fn mul(self, k: f64) -> TangentVector {
        TangentVector {
            dx: self.dx * k,
            dv: self.dv * k,
            du: self.du * k,
        }
    }
}

/// The 5×5 Jacobian of one flight–collision step, rows and columns in the
/// order `(x, y, v_x, v_y, u)`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Jacobian(pub [[f64; 5]; 5]);

impl Jacobian {
    /// Determinant (LU with partial pivoting).
    pub fn determinant(&self) -> f64 {
        let mut a = self.0;
        let mut det = 1.0;
        for c in 0..5 {
            let p = (c..5)
                .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
                .unwrap_or(c);
            if a[p][c] == 0.0 {
                return 0.0;
            }
            if p != c {
                a.swap(p, c);
                det = -det;
            }
            det *= a[c][c];
            let pivot = a[c];
            for row in a.iter_mut().skip(c + 1) {
                let f = row[c] / pivot[c];
                for (x, p) in row.iter_mut().zip(pivot.iter()).skip(c) {
                    *x -= f * p;
                }
            }
        }
        det
    }

    /// `J δ`.
    pub fn apply(&self, d: &TangentVector) -> TangentVector {
        let z = d.to_array();
        TangentVector::from_array(std::array::from_fn(|r| {
            (0..5).map(|c| self.0[r][c] * z[c]).sum()
        }))
    }
}

/// Everything the tangent map of one collision needs that does not depend on
/// the tangent vector, computed once per collision (one division) and applied
/// to as many vectors as are carried.
#[derive(Debug, Clone, Copy)]
pub struct TangentFrame {
    law: SpinLaw,
    n: DVec2,
    t: DVec2,
    vt: f64,
    inv_vn: f64,
    jump: DVec2,
    curvature_dv: DVec2,
    curvature_du: f64,
}

impl TangentFrame {
    /// The frame of a collision at `hit`; `before` is the state at the contact
    /// before the collision, `v_after` the velocity after it.
    #[inline]
    pub fn new(law: &SpinLaw, hit: &Hit, before: &State, v_after: DVec2) -> Self {
        let n = hit.normal;
        let t = hit.tangent();
        let v = before.velocity;
        let vn = n.dot(v);
        let vt = t.dot(v);
        let k = hit.curvature;
        TangentFrame {
            law: *law,
            n,
            t,
            vt,
            inv_vn: 1.0 / vn,
            jump: v - v_after,
            curvature_dv: k
                * (-(1.0 + law.beta()) * (vt * n + vn * t) + law.gamma() * before.spin * n),
            curvature_du: if law.is_coupled() {
                k * law.delta() * vn
            } else {
                0.0
            },
        }
    }

    /// Apply the collision part of the tangent map in place to a vector that
    /// has already flown to the contact (`δx += τ δv`).
    #[inline]
    pub fn apply(&self, tv: &mut TangentVector) {
        let dtau = -self.n.dot(tv.dx) * self.inv_vn;
        let ds = self.t.dot(tv.dx) + self.vt * dtau;
        tv.dx += self.jump * dtau;
        let (dv, du) = self.law.collide(tv.dv, tv.du, self.t);
        tv.dv = dv + ds * self.curvature_dv;
        tv.du = du + ds * self.curvature_du;
    }
}

/// The collision part of the tangent map for a single vector (see
/// [`TangentFrame`] to apply it to several).
#[inline]
pub fn tangent_collision(
    law: &SpinLaw,
    hit: &Hit,
    before: &State,
    v_after: DVec2,
    tv: &mut TangentVector,
) {
    TangentFrame::new(law, hit, before, v_after).apply(tv);
}
