//! The closed form of a table: what a table *is*, as data.
//!
//! [`Boundary::cast`] answers one ray at a time, which is all the scalar
//! collision map needs. Faster engines (the vector-lane kernels of
//! `spinball-lanes`) compile the table themselves and need its walls as
//! data: a [`Shape`]. A table that has one says so through
//! [`Boundary::shape`]; every built-in table and every
//! [`SegmentTable`](crate::SegmentTable) does. A table of your own without
//! one still runs everywhere, on the scalar path.
//!
//! A shape is also the table's provenance in results: it serialises (with
//! the `serde` feature), prints as the spec string that
//! [`Table`](crate::Table) parses back for the built-in tables, and rebuilds
//! the table ([`Shape::build`](crate::Shape::build) in the `table` module).
//!
//! This module is plain data (it sits below the tables in the crate's
//! layers): the parameters of a built-in table, or the loops of walls of a
//! table built from segments.
//!
//! [`Boundary::cast`]: crate::Boundary::cast
//! [`Boundary::shape`]: crate::Boundary::shape

use std::fmt;

use crate::segment::Segment;
use crate::wall_kind::WallKind;

/// A table as data: the parameters of a built-in table or the walls of a
/// table built from segments.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Shape {
    /// [`Circle`](crate::Circle) of radius `radius`.
    Circle {
        /// Radius.
        radius: f64,
    },
    /// [`Rectangle`](crate::Rectangle) `[-l, l] × [-h, h]`.
    Rectangle {
        /// Half-width.
        l: f64,
        /// Half-height.
        h: f64,
    },
    /// [`Stadium`](crate::Stadium) with flat half-length `a` and unit caps.
    Stadium {
        /// Half-length of the flat walls.
        a: f64,
    },
    /// [`Sinai`](crate::Sinai): square of half-side `l` minus a disk of radius `r`.
    Sinai {
        /// Half-side of the square.
        l: f64,
        /// Radius of the obstacle.
        r: f64,
    },
    /// A [`SegmentTable`](crate::SegmentTable): a counter-clockwise outer
    /// loop of walls and clockwise holes.
    Segments {
        /// The outer loop.
        outer: Vec<Segment>,
        /// The holes.
        holes: Vec<Vec<Segment>>,
        /// The table's name, if it has one (shown, not geometry).
        #[cfg_attr(
            feature = "serde",
            serde(default, skip_serializing_if = "Option::is_none")
        )]
        name: Option<String>,
        /// What each wall does, in wall-id order; empty for a closed table
        /// (so a table with a hole or periodic walls is never the same
        /// table as the closed one).
        #[cfg_attr(
            feature = "serde",
            serde(default, skip_serializing_if = "Vec::is_empty")
        )]
        kinds: Vec<WallKind>,
    },
}

impl Shape {
    /// Short name: `circle`, `rectangle`, `stadium`, `sinai` or `segments`.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Shape::Circle { .. } => "circle",
            Shape::Rectangle { .. } => "rectangle",
            Shape::Stadium { .. } => "stadium",
            Shape::Sinai { .. } => "sinai",
            Shape::Segments { .. } => "segments",
        }
    }

    /// Whether every wall reflects (no hole, no periodic wall): the tables
    /// the vector-lane kernels run.
    #[must_use]
    pub fn is_closed(&self) -> bool {
        match self {
            Shape::Segments { kinds, .. } => kinds.iter().all(WallKind::is_reflecting),
            _ => true,
        }
    }

    /// Number of walls.
    #[must_use]
    pub fn walls(&self) -> usize {
        match self {
            Shape::Circle { .. } => 1,
            Shape::Rectangle { .. } | Shape::Stadium { .. } => 4,
            Shape::Sinai { .. } => 5,
            Shape::Segments { outer, holes, .. } => {
                outer.len() + holes.iter().map(Vec::len).sum::<usize>()
            }
        }
    }
}

impl Shape {
    /// `, N holes, M periodic` for a table with such walls, else empty.
    fn open_note(&self) -> String {
        let Shape::Segments { kinds, .. } = self else {
            return String::new();
        };
        let holes = kinds.iter().filter(|k| k.is_hole()).count();
        let periodic = kinds.iter().filter(|k| k.is_periodic()).count();
        let mut note = String::new();
        if holes > 0 {
            note += &format!(", {holes} hole{}", if holes == 1 { "" } else { "s" });
        }
        if periodic > 0 {
            note += &format!(", {periodic} periodic");
        }
        note
    }
}

impl fmt::Display for Shape {
    /// The built-in tables as their spec string (`stadium:a=1`, which
    /// [`Table`](crate::Table) parses back); a segment table as
    /// `segments(N walls)`, or `NAME (segments, N walls)` if it has a name.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Shape::Circle { radius } => write!(f, "circle:R={radius}"),
            Shape::Rectangle { l, h } => write!(f, "rectangle:L={l},H={h}"),
            Shape::Stadium { a } => write!(f, "stadium:a={a}"),
            Shape::Sinai { l, r } => write!(f, "sinai:L={l},R={r}"),
            Shape::Segments {
                name: Some(name), ..
            } => write!(
                f,
                "{name} (segments, {} walls{})",
                self.walls(),
                self.open_note()
            ),
            Shape::Segments { name: None, .. } => {
                write!(f, "segments({} walls{})", self.walls(), self.open_note())
            }
        }
    }
}
