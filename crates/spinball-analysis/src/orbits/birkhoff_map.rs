//! The collision map in Birkhoff coordinates `(s, v∥, u)` on the shell
//! `|V| = 1`, and its exact 3 × 3 Jacobian from the tangent map.
//!
//! Documented in the group docs (`orbits/mod.rs`), section "The map".

use spinball_core::{Billiard, TangentVector};
use spinball_geometry::{Boundary, DVec2, WallId};

use super::matrix::Mat3;
use crate::error::AnalysisError;
use crate::phase_space::state_on_section;

/// A point of the section, **just after** a collision: arc length `s`,
/// outgoing tangential velocity `v∥` and spin `u`, on the shell `|V| = 1`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BirkhoffPoint {
    /// Birkhoff arc length of the contact.
    pub s: f64,
    /// Tangential velocity `v∥ = v·t̂` just after the collision.
    pub v_par: f64,
    /// Spin `u` just after the collision.
    pub spin: f64,
}

impl BirkhoffPoint {
    /// A point from its coordinates.
    #[must_use]
    pub fn new(s: f64, v_par: f64, spin: f64) -> Self {
        BirkhoffPoint { s, v_par, spin }
    }

    /// A ball leaving the wall along its normal at `s` (`v∥ = u = 0`).
    #[must_use]
    pub fn normal(s: f64) -> Self {
        BirkhoffPoint::new(s, 0.0, 0.0)
    }

    /// `(s, v∥, u)`.
    #[must_use]
    pub fn to_array(self) -> [f64; 3] {
        [self.s, self.v_par, self.spin]
    }

    /// `sin θ = v∥/|v|` on the shell `|V| = 1` under spin parameter `alpha`.
    #[must_use]
    pub fn sin_theta(self, alpha: f64) -> f64 {
        self.v_par / (1.0 - alpha * self.spin * self.spin).sqrt()
    }
}

/// `p` steps of the collision map from `start`: the points after each
/// collision (the last is `F^p(start)`), the walls hit, and the exact
/// Jacobian `∂F^p/∂(s, v∥, u)`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Iterate {
    pub points: Vec<BirkhoffPoint>,
    pub walls: Vec<WallId>,
    pub jacobian: Mat3,
    /// Smallest `|v⊥|/|v|` of the collisions (grazing when near 0).
    pub min_cos: f64,
    /// Shortest flight, over the table's `unit_length` (0 at a corner).
    pub min_flight: f64,
}

/// The Birkhoff point of a state just after a collision at `s` whose wall
/// has tangent `t`.
fn point_of(s: f64, t: DVec2, velocity: DVec2, spin: f64) -> BirkhoffPoint {
    BirkhoffPoint::new(s, velocity.dot(t), spin)
}

/// Iterate the map `period` times from `start`, carrying three tangent
/// vectors of the flow (one per coordinate) and projecting them back onto
/// the section at the end.
///
/// # Errors
/// `start` off the shell or on a table without `hit_at`
/// ([`AnalysisError::InvalidOption`]), or a failed step.
pub(crate) fn iterate<B: Boundary>(
    billiard: &Billiard<B>,
    start: BirkhoffPoint,
    period: u32,
) -> Result<Iterate, AnalysisError> {
    let (table, law) = (billiard.table(), billiard.law());
    let state = state_on_section(table, law, start.s, start.v_par, start.spin)?;
    let hit0 = table
        .hit_at(start.s)
        .ok_or_else(|| AnalysisError::invalid("table", "cannot place a point by arc length"))?;
    let (n, t, k) = (hit0.normal, hit0.tangent(), hit0.curvature);
    let (v_par, v_perp) = (state.velocity.dot(t), state.velocity.dot(n));
    // Moving the contact by δs moves the point by t̂ δs and turns the frame
    // (dn̂/ds = k t̂, dt̂/ds = −k n̂) at fixed (v∥, v⊥); changing v∥ or u at fixed
    // energy changes v⊥ by −(v∥ δv∥ + α u δu)/v⊥.
    let mut basis = [
        TangentVector {
            dx: t,
            dv: k * (v_perp * t - v_par * n),
            du: 0.0,
        },
        TangentVector {
            dx: DVec2::ZERO,
            dv: t - n * (v_par / v_perp),
            du: 0.0,
        },
        TangentVector {
            dx: DVec2::ZERO,
            dv: -n * (law.alpha() * start.spin / v_perp),
            du: 1.0,
        },
    ];
    let mut ball = billiard.launch(state)?;
    let mut points = Vec::with_capacity(period as usize);
    let mut walls = Vec::with_capacity(period as usize);
    let mut min_cos = f64::INFINITY;
    let mut min_flight = f64::INFINITY;
    let unit = table.unit_length();
    let mut last = None;
    for _ in 0..period {
        let c = billiard.step_tangent(&mut ball, &mut basis)?;
        let after = ball.state();
        let t = c.hit.tangent();
        points.push(point_of(c.hit.s(), t, after.velocity, after.spin));
        walls.push(c.wall());
        min_cos = min_cos.min(after.velocity.dot(c.hit.normal) / after.velocity.length());
        min_flight = min_flight.min(c.time() * after.velocity.length() / unit);
        last = Some((c.hit, after.velocity));
    }
    let (hit, v) = last.ok_or_else(|| AnalysisError::invalid("period", "must be at least 1"))?;
    let (n, t, k) = (hit.normal, hit.tangent(), hit.curvature);
    let vn = v.dot(n);
    let mut jacobian = [[0.0; 3]; 3];
    for (col, tv) in basis.iter().enumerate() {
        // Fly the neighbour back (or on) to the wall: it lies off it by n̂·δx.
        let dtau = n.dot(tv.dx) / vn;
        let ds = t.dot(tv.dx - v * dtau);
        jacobian[0][col] = ds;
        jacobian[1][col] = t.dot(tv.dv) - k * vn * ds;
        jacobian[2][col] = tv.du;
    }
    Ok(Iterate {
        points,
        walls,
        jacobian,
        min_cos,
        min_flight,
    })
}
