//! What happens when a ball reaches a wall of an open or periodic table:
//! a collision, a crossing into the next cell, or an escape.
//!
//! On a closed table every wall reflects and [`Billiard::step`](crate::Billiard::step)
//! is the whole story. A table with holes or periodic walls
//! ([`WallKind`](spinball_geometry::WallKind)) has two more outcomes, and
//! [`Billiard::advance`](crate::Billiard::advance) reports each wall
//! reached as one [`Event`]; a hole-free table never reports
//! [`Event::Escape`], a table without periodic walls never reports
//! [`Event::Crossing`].

use glam::DVec2;
use spinball_geometry::{Cell, WallId};

use crate::collision::Collision;

/// One wall reached: see the [module docs](self).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Event {
    /// The ball hit a reflecting wall and collided.
    Collision(Collision),
    /// The ball passed through a periodic wall into the next cell.
    Crossing(Crossing),
    /// The ball reached a hole and left the table.
    Escape(Exit),
}

impl Event {
    /// Flight time since the previous event.
    #[must_use]
    #[inline]
    pub fn time(&self) -> f64 {
        match self {
            Event::Collision(c) => c.time(),
            Event::Crossing(c) => c.time,
            Event::Escape(e) => e.time,
        }
    }
}

/// A pass through a periodic wall: the ball left through `wall` and
/// re-entered through `partner`, its position moved by the wall's `−shift`,
/// its velocity and spin unchanged. Not a collision.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Crossing {
    /// Flight time since the previous event.
    pub time: f64,
    /// The wall the ball left through.
    pub wall: WallId,
    /// The wall it re-entered through.
    pub partner: WallId,
    /// The point where it re-entered (on `partner`).
    pub point: DVec2,
    /// The ball's cell after the crossing.
    pub cell: Cell,
}

/// Where and how a ball left the table through a hole.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Exit {
    /// Flight time since the previous event.
    pub time: f64,
    /// The hole's wall id.
    pub wall: WallId,
    /// The point of the hole the ball passed through.
    pub point: DVec2,
    /// Birkhoff arc length `s` of that point.
    pub s: f64,
    /// Tangential velocity `v∥ = v·t` there (`t` the hole wall's tangent).
    pub v_par: f64,
    /// The spin `u` the ball left with.
    pub spin: f64,
}
