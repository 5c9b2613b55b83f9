//! What one collision did: the small record a step returns.

use glam::DVec2;
use spinball_geometry::{Hit, WallId};

/// One wall collision: where and after how long, and the tangential velocity,
/// spin and `Q` around it. Nothing is stored unless an observer keeps it.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Collision {
    /// The wall contact (point, normal, curvature, wall id, Birkhoff `s`).
    pub hit: Hit,
    /// Tangential velocity `v∥ = v·t` before the collision.
    pub v_par_before: f64,
    /// Spin before the collision.
    pub spin_before: f64,
    /// Tangential velocity after the collision.
    pub v_par_after: f64,
    /// Spin after the collision.
    pub spin_after: f64,
    /// `Q = v∥ − αu` before the collision (paper eq. 12; unchanged by it).
    pub q: f64,
}

impl Collision {
    /// Flight time since the previous collision.
    #[inline]
    pub fn time(&self) -> f64 {
        self.hit.time
    }
    /// Which wall.
    #[inline]
    pub fn wall(&self) -> WallId {
        self.hit.wall
    }
    /// Contact point.
    #[inline]
    pub fn point(&self) -> DVec2 {
        self.hit.point
    }
    /// Unit tangent of the wall at the contact.
    #[inline]
    pub fn tangent(&self) -> DVec2 {
        self.hit.tangent()
    }
    /// `Q` after the collision, from the post-collision components.
    #[inline]
    pub fn q_after(&self, alpha: f64) -> f64 {
        self.v_par_after - alpha * self.spin_after
    }
}
