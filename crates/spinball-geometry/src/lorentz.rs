//! The periodic Lorentz gas: a lattice of disks, run as one cell whose
//! sides are periodic walls.
//!
//! Transport (how far a ball spreads through an array of scatterers) is
//! studied on the unit cell of the lattice: a ball leaving the cell through
//! one side re-enters through the opposite side, one cell further on, and
//! the cell count is kept as integers ([`Cell`](crate::Cell)). Two lattices:
//!
//! - **square**: the cell `[0, w]²` with a disk of radius `R` at its centre;
//!   periodic walls 0 (bottom) ↔ 2 (top) and 1 (right) ↔ 3 (left), the disk
//!   is wall 4.
//! - **triangular**: the rhombic cell spanned by `b₁ = (w, 0)` and
//!   `b₂ = (w/2, √3 w/2)` with a piece of a disk at each corner (the four
//!   pieces, 60° + 120° + 60° + 120°, make one disk of radius `R` a cell); walls in order: bottom side 0, the arc about `b₁` 1, right side
//!   2, the arc about `b₁ + b₂` 3, top side 4, the arc about `b₂` 5, left
//!   side 6, the arc about the origin 7; periodic 0 ↔ 4 and 2 ↔ 6.
//!
//! Both need `0 < R < w/2` (at `w/2` neighbouring disks touch and the ball
//! is caged). The **horizon** ([`LorentzGas::horizon`]) is a closed form:
//! the square lattice always has corridors (free flights of unbounded
//! length, along the lattice rows); the triangular one closes them all once
//! `R ≥ √3 w/4`.

use std::f64::consts::PI;
use std::fmt;

use glam::DVec2;

use crate::arc::ArcSegment;
use crate::error::{GeometryError, length};
use crate::horizon::Horizon;
use crate::line::LineSegment;
use crate::segment::Segment;
use crate::segment_table::SegmentTable;

/// Which lattice the disks sit on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Lattice {
    /// Square lattice of spacing `w`.
    Square,
    /// Triangular lattice of spacing `w` (nearest disks `w` apart).
    Triangular,
}

/// A periodic Lorentz gas: a lattice of spacing `w` with disks of radius
/// `R`. See the [module docs](self).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LorentzGas {
    lattice: Lattice,
    w: f64,
    r: f64,
}

impl LorentzGas {
    /// The square lattice of spacing `w` with disks of radius `r`.
    ///
    /// # Errors
    /// [`GeometryError::NonFinite`], [`GeometryError::NonPositive`], and
    /// [`GeometryError::NoRoom`] unless `r < w/2`.
    pub fn square(w: f64, r: f64) -> Result<Self, GeometryError> {
        Self::new(Lattice::Square, w, r)
    }

    /// The triangular lattice of spacing `w` (nearest disks `w` apart) with
    /// disks of radius `r`.
    ///
    /// # Errors
    /// As [`square`](Self::square).
    pub fn triangular(w: f64, r: f64) -> Result<Self, GeometryError> {
        Self::new(Lattice::Triangular, w, r)
    }

    fn new(lattice: Lattice, w: f64, r: f64) -> Result<Self, GeometryError> {
        let w = length("w", w)?;
        let r = length("r", r)?;
        // 1e-9 of w below touching: the corridor between two disks must be
        // wider than the walls' rounding for a ball to pass through it.
        let max = 0.5 * w * (1.0 - 1e-9);
        if r >= max {
            return Err(GeometryError::NoRoom {
                r,
                w,
                max,
                why: "at R = w/2 neighbouring disks touch and the ball is caged in one cell",
            });
        }
        Ok(LorentzGas { lattice, w, r })
    }

    /// The lattice.
    #[must_use]
    pub fn lattice(&self) -> Lattice {
        self.lattice
    }
    /// Lattice spacing `w`.
    #[must_use]
    pub fn w(&self) -> f64 {
        self.w
    }
    /// Disk radius `R`.
    #[must_use]
    pub fn r(&self) -> f64 {
        self.r
    }

    /// The horizon, in closed form: the square lattice has a corridor along
    /// its rows, of width `w − 2R`, for every `R < w/2`; the triangular
    /// lattice's widest corridor (along its rows, of width `√3 w/2 − 2R`)
    /// closes at `R = √3 w/4`, and with it every other.
    /// [`SegmentTable::horizon`] finds the same from the cell's walls.
    #[must_use]
    pub fn horizon(&self) -> Horizon {
        let row = |width| Horizon::Infinite {
            direction: DVec2::X,
            width,
        };
        let (w, r) = (self.w, self.r);
        match self.lattice {
            Lattice::Square => row(w - 2.0 * r),
            Lattice::Triangular if r >= 3f64.sqrt() * w / 4.0 => Horizon::Finite,
            Lattice::Triangular => row(0.5 * 3f64.sqrt() * w - 2.0 * r),
        }
    }

    /// The unit cell as a [`SegmentTable`] with periodic sides (named
    /// `square Lorentz gas w=…,R=…` or `triangular …`).
    ///
    /// # Errors
    /// The [`SegmentTable`] constructor's, for a disk so close to filling
    /// the cell that the walls' rounding cannot resolve the corridors.
    pub fn table(&self) -> Result<SegmentTable, GeometryError> {
        let (w, r) = (self.w, self.r);
        let table = match self.lattice {
            Lattice::Square => {
                let p = DVec2::new;
                let line = |a, b| LineSegment::new(a, b).map(Segment::Line);
                let outer = vec![
                    line(p(0.0, 0.0), p(w, 0.0))?,
                    line(p(w, 0.0), p(w, w))?,
                    line(p(w, w), p(0.0, w))?,
                    line(p(0.0, w), p(0.0, 0.0))?,
                ];
                let disk = ArcSegment::new(p(0.5 * w, 0.5 * w), r, 0.0, -2.0 * PI)?;
                SegmentTable::with_holes(outer, vec![vec![Segment::Arc(disk)]])?
                    .with_periodic(0, 2)?
                    .with_periodic(1, 3)?
            }
            Lattice::Triangular => {
                let b1 = DVec2::new(w, 0.0);
                let b2 = DVec2::new(0.5 * w, 0.5 * 3f64.sqrt() * w);
                // Corners, with the angle of the arc's start and its sweep
                // (clockwise: the table lies outside the disk).
                let corners = [
                    (b1, PI, -2.0 * PI / 3.0),
                    (b1 + b2, 4.0 * PI / 3.0, -PI / 3.0),
                    (b2, 0.0, -2.0 * PI / 3.0),
                    (DVec2::ZERO, PI / 3.0, -PI / 3.0),
                ];
                let arcs = corners
                    .iter()
                    .map(|&(c, start, sweep)| ArcSegment::new(c, r, start, sweep))
                    .collect::<Result<Vec<_>, _>>()?;
                let mut outer = Vec::with_capacity(8);
                for i in 0..4 {
                    let from = arcs[(i + 3) % 4].end();
                    outer.push(Segment::Line(LineSegment::new(from, arcs[i].start())?));
                    outer.push(Segment::Arc(arcs[i]));
                }
                SegmentTable::new(outer)?
                    .with_periodic(0, 4)?
                    .with_periodic(2, 6)?
            }
        };
        Ok(table.with_name(self.to_string()))
    }
}

impl fmt::Display for LorentzGas {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let name = match self.lattice {
            Lattice::Square => "square",
            Lattice::Triangular => "triangular",
        };
        write!(f, "{name} Lorentz gas w={},R={}", self.w, self.r)
    }
}
