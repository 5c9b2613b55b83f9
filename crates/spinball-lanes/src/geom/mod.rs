//! Tables cast in lanes: what a kernel asks of a table.
//!
//! A kernel needs the table's answer to [`Boundary::cast`] for `N` balls at
//! once, without a branch per ball. Each table here computes every candidate
//! wall for every lane (the flat crossing *and* the cap, the box *and* the
//! disk, every wall of a table built from segments) and keeps the right one
//! with compare-and-select. The arithmetic is the scalar cast's, operation
//! for operation (same divisions, same square roots, same clamps, same tie
//! rules), so a lane finds bitwise the hit that [`Boundary::cast`] finds.
//! Where the scalar cast returns `None` (no wall ahead), the lane's flight
//! time becomes NaN, which then sticks to that lane's state and is reported
//! as an error at the end of the run.
//!
//! A cast comes in two halves, [`Geom::search`] (which wall, and when: the
//! cast's square roots and its one division) and [`Geom::land`] (where on
//! it, and its normal). A kernel that steps two independent trajectories
//! per lane (finite differences: the reference and its shadow) searches for
//! both before landing either, so that in program order the second search
//! fills the wait on the first one's division: the processor overlaps only
//! what lies within its scheduling window, and a cast's latencies, not its
//! operation count, bound the step on current x86 cores.
//!
//! One file per table ([`circle`], [`rectangle`], [`stadium`], [`sinai`],
//! [`segments`], whose flat walls are cast in [`flat_walls`]), the circle
//! arithmetic they share in [`round`], and the test harness that holds
//! each of them to its scalar cast in `agree`.
//!
//! [`Boundary::cast`]: spinball_geometry::Boundary::cast

mod circle;
mod flat_walls;
mod rectangle;
mod round;
mod segments;
mod sinai;
mod stadium;

#[cfg(test)]
mod agree;

pub(crate) use circle::LaneCircle;
pub(crate) use rectangle::LaneRectangle;
pub(crate) use segments::LaneSegments;
#[cfg(test)]
pub(crate) use segments::tests as segment_tables;
pub(crate) use sinai::LaneSinai;
pub(crate) use stadium::LaneStadium;

use crate::lanes::{Footprint, Lanes};

/// The next wall hit of `N` balls.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LaneHit<L: Lanes> {
    /// Flight time (NaN where the scalar cast has no hit).
    pub time: L,
    /// Contact point.
    pub px: L,
    /// Contact point.
    pub py: L,
    /// Unit inward normal.
    pub nx: L,
    /// Unit inward normal.
    pub ny: L,
    /// Signed curvature (`-1/R` concave, `+1/R` convex, 0 flat).
    pub curvature: L,
    /// Wall id, as in the scalar table (as `f64`; for diagnostics and tests).
    pub wall: L,
}

/// A table the kernels can cast against in lanes.
pub(crate) trait Geom: Copy + Send + Sync {
    /// Whether the table has curved walls (the tangent map then needs its
    /// curvature term; flat-only tables skip it).
    const CURVED: bool;
    /// How many registers the cast keeps live, which picks the register
    /// groups a kernel runs this table with (never its results).
    type Footprint: Footprint;
    /// What [`search`](Self::search) leaves for [`land`](Self::land).
    type Found<L: Lanes>: Copy;
    /// The first half of the cast: which wall each lane meets and when
    /// (the cast's division included).
    fn search<L: Lanes>(&self, x: L, y: L, vx: L, vy: L) -> Self::Found<L>;
    /// The second half: the contact on the wall found and its normal.
    fn land<L: Lanes>(&self, found: Self::Found<L>) -> LaneHit<L>;
    /// Both landings of two searches whose walls are usually the same (a
    /// finite-difference reference and its shadow): bitwise
    /// `(self.land(a), self.land(b))`. A table that fetches a wall's
    /// constants by its id fetches them once when every lane's walls agree.
    #[inline(always)]
    fn land_both<L: Lanes>(
        &self,
        a: Self::Found<L>,
        b: Self::Found<L>,
    ) -> (LaneHit<L>, LaneHit<L>) {
        (self.land(a), self.land(b))
    }
    /// The next wall hit from `(x, y)` along `(vx, vy)`, lane by lane.
    #[inline(always)]
    fn cast<L: Lanes>(&self, x: L, y: L, vx: L, vy: L) -> LaneHit<L> {
        self.land(self.search(x, y, vx, vy))
    }
}
