//! What a wall does to a ball that reaches it: reflect it, let it out, or
//! pass it into the neighbouring cell of a periodic table.
//!
//! Every table used to be closed. Escape problems need **holes** (a ball
//! reaching one leaves the table) and transport problems need **periodic**
//! walls (a ball leaving through one re-enters at its partner, one lattice
//! cell further on). A table says which wall is which through
//! [`Boundary::wall_kind`](crate::Boundary::wall_kind); the default is
//! [`WallKind::Reflecting`] for every wall, so closed tables are unchanged.

use glam::DVec2;

use crate::hit::WallId;

/// Which cell of a periodic table a ball is in, as integer coordinates in
/// the table's lattice basis ([`Boundary::lattice`](crate::Boundary::lattice)):
/// the unwrapped position is `i·b₁ + j·b₂ +` the position in the cell.
///
/// Integers, so that the cell of a ball that has crossed walls 10⁷ times is
/// exact (a position unwrapped by adding floats would drift by rounding).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Cell {
    /// Coordinate along the first lattice vector.
    pub i: i64,
    /// Coordinate along the second lattice vector.
    pub j: i64,
}

impl Cell {
    /// The home cell `(0, 0)`.
    pub const ORIGIN: Cell = Cell { i: 0, j: 0 };

    /// The cell `(i, j)`.
    #[must_use]
    pub const fn new(i: i64, j: i64) -> Self {
        Cell { i, j }
    }

    /// This cell moved by `step` (wrapping never happens below 2⁶³ crossings).
    #[must_use]
    #[inline]
    pub fn moved(self, step: Cell) -> Self {
        Cell {
            i: self.i + step.i,
            j: self.j + step.j,
        }
    }

    /// The cell's offset `i·b₁ + j·b₂` in the plane, for the lattice basis
    /// `basis`. Exact to the rounding of one product and one sum (the
    /// integers are exact below 2⁵³).
    #[must_use]
    pub fn offset(self, basis: [DVec2; 2]) -> DVec2 {
        basis[0] * self.i as f64 + basis[1] * self.j as f64
    }
}

/// What a wall does to a ball that reaches it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum WallKind {
    /// The ball collides (the spin law applies). Every wall of a closed table.
    #[default]
    Reflecting,
    /// The ball leaves the table: the run ends with an exit record.
    Hole,
    /// The ball passes into the next cell: it re-enters at `partner`, its
    /// position moved by `−shift`, its velocity and spin unchanged, and no
    /// collision is counted.
    Periodic {
        /// The partner wall, a translate of this one by `−shift`.
        partner: WallId,
        /// From the partner to this wall: the lattice vector of the cell
        /// the ball moves into.
        shift: DVec2,
        /// `shift` in the table's lattice basis: what the ball's [`Cell`]
        /// gains on crossing.
        step: Cell,
    },
}

impl WallKind {
    /// Whether the ball collides here.
    #[must_use]
    #[inline]
    pub fn is_reflecting(&self) -> bool {
        matches!(self, WallKind::Reflecting)
    }
    /// Whether this wall is a hole.
    #[must_use]
    #[inline]
    pub fn is_hole(&self) -> bool {
        matches!(self, WallKind::Hole)
    }
    /// Whether this wall is periodic.
    #[must_use]
    #[inline]
    pub fn is_periodic(&self) -> bool {
        matches!(self, WallKind::Periodic { .. })
    }
}
