//! Table outlines as closed polylines, computed from the geometry: what a
//! picture of a table draws (the plot crate, the Python `plot.table`).
//!
//! Drawing needs points, the geometry has walls: [`ToOutline`] turns any
//! built-in table, a [`Table`] or a [`SegmentTable`] into [`Loop`]s of points,
//! flat walls by their end points and arcs sampled every half degree. Loops
//! are told apart by orientation: the outer boundary runs counter-clockwise,
//! holes (obstacles such as the Sinai disk) clockwise.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use crate::{Built, Circle, Rectangle, Segment, SegmentTable, Sinai, Stadium, Table};
use glam::DVec2;

/// Points per full turn when sampling an arc (every half degree).
pub const ARC_POINTS_PER_TURN: usize = 720;

/// A closed polyline of a table's boundary.
#[derive(Debug, Clone, PartialEq)]
pub struct Loop {
    points: Vec<DVec2>,
    hole: bool,
}

impl Loop {
    /// The points; the last equals the first for a closed loop.
    pub fn points(&self) -> &[DVec2] {
        &self.points
    }
    /// Whether the loop bounds an obstacle (runs clockwise) rather than the
    /// outer wall.
    pub fn is_hole(&self) -> bool {
        self.hole
    }
}

/// The walls of a table as closed polylines: flat walls by their end points,
/// arcs sampled every half degree ([`ARC_POINTS_PER_TURN`] per turn); the
/// outer boundary runs counter-clockwise, holes (obstacles) clockwise.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Outline {
    loops: Vec<Loop>,
}

impl Outline {
    /// The loops, outer boundary first.
    pub fn loops(&self) -> &[Loop] {
        &self.loops
    }

    /// Lower-left and upper-right corners of the points, if there are any.
    pub fn bounds(&self) -> Option<(DVec2, DVec2)> {
        let mut it = self.loops.iter().flat_map(|l| l.points.iter().copied());
        let first = it.next()?;
        Some(it.fold((first, first), |(lo, hi), p| (lo.min(p), hi.max(p))))
    }

    /// The outline of a chain of walls listed as a [`SegmentTable`] lists them:
    /// a new loop starts wherever a wall does not begin at the end of the one
    /// before it.
    pub fn from_segments(walls: &[Segment]) -> Outline {
        let pieces: Vec<Piece> = walls.iter().map(Piece::from).collect();
        Outline::from_pieces(&pieces)
    }

    fn from_pieces(pieces: &[Piece]) -> Outline {
        let scale = pieces
            .iter()
            .flat_map(|p| [p.start(), p.end()])
            .fold(0.0_f64, |m, p| m.max(p.abs().max_element()))
            .max(f64::MIN_POSITIVE);
        let tol = 1e-9 * scale;
        let mut loops = Vec::new();
        let mut current: Vec<DVec2> = Vec::new();
        for piece in pieces {
            if let Some(&last) = current.last()
                && (last - piece.start()).length() > tol
            {
                loops.push(close(std::mem::take(&mut current), tol));
            }
            piece.sample_into(&mut current);
        }
        if !current.is_empty() {
            loops.push(close(current, tol));
        }
        Outline { loops }
    }
}

fn close(mut points: Vec<DVec2>, tol: f64) -> Loop {
    if let Some(&first) = points.first()
        && let Some(last) = points.last_mut()
        && (*last - first).length() <= tol
    {
        *last = first;
    }
    // Shoelace: twice the signed area, negative for a clockwise loop.
    let area2: f64 = points.windows(2).map(|w| w[0].perp_dot(w[1])).sum();
    Loop {
        points,
        hole: area2 < 0.0,
    }
}

/// A wall reduced to what drawing needs.
#[derive(Debug, Clone, Copy)]
enum Piece {
    Line(DVec2, DVec2),
    Arc {
        center: DVec2,
        radius: f64,
        start: f64,
        sweep: f64,
    },
}

impl Piece {
    fn point_at(center: DVec2, radius: f64, angle: f64) -> DVec2 {
        center + radius * DVec2::from_angle(angle)
    }
    fn start(&self) -> DVec2 {
        match *self {
            Piece::Line(a, _) => a,
            Piece::Arc {
                center,
                radius,
                start,
                ..
            } => Self::point_at(center, radius, start),
        }
    }
    fn end(&self) -> DVec2 {
        match *self {
            Piece::Line(_, b) => b,
            Piece::Arc {
                center,
                radius,
                start,
                sweep,
            } => Self::point_at(center, radius, start + sweep),
        }
    }
    /// Append the points of this wall, leaving out its start if the polyline
    /// already ends there.
    fn sample_into(&self, out: &mut Vec<DVec2>) {
        let skip_first = out
            .last()
            .is_some_and(|&p| (p - self.start()).length() < 1e-12);
        match *self {
            Piece::Line(a, b) => {
                if !skip_first {
                    out.push(a);
                }
                out.push(b);
            }
            Piece::Arc {
                center,
                radius,
                start,
                sweep,
            } => {
                let n = ((sweep.abs() / TAU * ARC_POINTS_PER_TURN as f64).ceil() as usize).max(8);
                let from = usize::from(skip_first);
                for i in from..=n {
                    out.push(Self::point_at(
                        center,
                        radius,
                        start + sweep * i as f64 / n as f64,
                    ));
                }
            }
        }
    }
}

impl From<&Segment> for Piece {
    fn from(s: &Segment) -> Self {
        match s {
            Segment::Line(l) => Piece::Line(l.start(), l.end()),
            Segment::Arc(a) => Piece::Arc {
                center: a.center(),
                radius: a.radius(),
                start: a.start_angle(),
                sweep: a.sweep(),
            },
        }
    }
}

/// Anything whose walls can be drawn.
pub trait ToOutline {
    /// The walls as closed polylines.
    fn outline(&self) -> Outline;
}

impl ToOutline for Outline {
    fn outline(&self) -> Outline {
        self.clone()
    }
}

impl ToOutline for Circle {
    fn outline(&self) -> Outline {
        Outline::from_pieces(&[Piece::Arc {
            center: DVec2::ZERO,
            radius: self.radius(),
            start: 0.0,
            sweep: TAU,
        }])
    }
}

impl ToOutline for Rectangle {
    fn outline(&self) -> Outline {
        let (l, h) = (self.l(), self.h());
        let c = [
            DVec2::new(-l, -h),
            DVec2::new(l, -h),
            DVec2::new(l, h),
            DVec2::new(-l, h),
        ];
        let pieces: Vec<Piece> = (0..4).map(|i| Piece::Line(c[i], c[(i + 1) % 4])).collect();
        Outline::from_pieces(&pieces)
    }
}

impl ToOutline for Stadium {
    fn outline(&self) -> Outline {
        let a = self.a();
        Outline::from_pieces(&[
            Piece::Line(DVec2::new(-a, -1.0), DVec2::new(a, -1.0)),
            Piece::Arc {
                center: DVec2::new(a, 0.0),
                radius: 1.0,
                start: -FRAC_PI_2,
                sweep: PI,
            },
            Piece::Line(DVec2::new(a, 1.0), DVec2::new(-a, 1.0)),
            Piece::Arc {
                center: DVec2::new(-a, 0.0),
                radius: 1.0,
                start: FRAC_PI_2,
                sweep: PI,
            },
        ])
    }
}

impl ToOutline for Sinai {
    fn outline(&self) -> Outline {
        let mut outline = Rectangle::new(self.l(), self.l())
            .map(|r| r.outline())
            .unwrap_or_default();
        let disk = Outline::from_pieces(&[Piece::Arc {
            center: DVec2::ZERO,
            radius: self.r(),
            start: 0.0,
            sweep: -TAU,
        }]);
        outline.loops.extend(disk.loops);
        outline
    }
}

impl ToOutline for Table {
    fn outline(&self) -> Outline {
        match self {
            Table::Circle(t) => t.outline(),
            Table::Rectangle(t) => t.outline(),
            Table::Stadium(t) => t.outline(),
            Table::Sinai(t) => t.outline(),
        }
    }
}

impl ToOutline for Built {
    fn outline(&self) -> Outline {
        match self {
            Built::Table(t) => t.outline(),
            Built::Segments(t) => t.outline(),
        }
    }
}

impl ToOutline for SegmentTable {
    fn outline(&self) -> Outline {
        Outline::from_segments(self.walls())
    }
}

impl ToOutline for [Segment] {
    fn outline(&self) -> Outline {
        Outline::from_segments(self)
    }
}

impl<T: ToOutline + ?Sized> ToOutline for &T {
    fn outline(&self) -> Outline {
        (**self).outline()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{ArcSegment, LineSegment};

    #[test]
    fn stadium_outline_is_closed_and_tight() {
        let st = Stadium::new(1.0).unwrap();
        let o = st.outline();
        assert_eq!(o.loops().len(), 1);
        assert!(!o.loops()[0].is_hole());
        let (lo, hi) = o.bounds().unwrap();
        assert!((lo - DVec2::new(-2.0, -1.0)).length() < 1e-12);
        assert!((hi - DVec2::new(2.0, 1.0)).length() < 1e-12);
        let pts = o.loops()[0].points();
        assert_eq!(pts.first(), pts.last(), "closed loop");
        // Arc points lie on the caps.
        for p in o.loops()[0].points() {
            if p.x > 1.0 {
                assert!(((*p - DVec2::new(1.0, 0.0)).length() - 1.0).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn sinai_has_one_hole() {
        let o = Sinai::new(2.0, 1.0).unwrap().outline();
        assert_eq!(o.loops().len(), 2);
        assert!(!o.loops()[0].is_hole());
        assert!(o.loops()[1].is_hole());
        for p in o.loops()[1].points() {
            assert!((p.length() - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn segment_table_splits_loops_at_gaps() {
        let p = DVec2::new;
        let line = |a, b| Segment::Line(LineSegment::new(a, b).unwrap());
        let table = SegmentTable::with_holes(
            vec![
                line(p(-2.0, -2.0), p(2.0, -2.0)),
                line(p(2.0, -2.0), p(2.0, 2.0)),
                line(p(2.0, 2.0), p(-2.0, 2.0)),
                line(p(-2.0, 2.0), p(-2.0, -2.0)),
            ],
            vec![vec![Segment::Arc(
                ArcSegment::new(DVec2::ZERO, 0.5, 0.0, -TAU).unwrap(),
            )]],
        )
        .unwrap();
        let o = table.outline();
        assert_eq!(o.loops().len(), 2);
        assert_eq!(o.loops()[0].points().len(), 5);
        assert!(o.loops()[1].is_hole());
        assert_eq!(o.loops()[1].points().len(), ARC_POINTS_PER_TURN + 1);
    }

    #[test]
    fn table_enum_matches_concrete() {
        let t: Table = "circle:R=2".parse().unwrap();
        let o = t.outline();
        let (lo, hi) = o.bounds().unwrap();
        assert!((hi.x - 2.0).abs() < 1e-12 && (lo.y + 2.0).abs() < 1e-9);
    }
}
