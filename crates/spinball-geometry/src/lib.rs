//! Billiard tables for [spinball](https://docs.rs/spinball): where the walls
//! are and which one a ball hits next.
//!
//! Everything a billiard needs from its table is the answer to one question,
//! [`Boundary::cast`]: from this point, moving with this velocity, which wall
//! comes next (flight time, contact point, inward normal, tangent, signed
//! curvature, wall id, Birkhoff arc length). The built-in tables of the paper
//! ([`Circle`], [`Rectangle`], [`Stadium`], [`Sinai`]) answer it in closed form
//! with static dispatch; [`SegmentTable`] builds any other table from
//! [`LineSegment`]s and [`ArcSegment`]s.
//!
//! ```
//! use glam::DVec2;
//! use spinball_geometry::{Boundary, Stadium};
//!
//! let stadium = Stadium::new(1.0)?;
//! let hit = stadium.cast(DVec2::ZERO, DVec2::new(1.0, 0.0)).expect("bounded table");
//! assert_eq!(hit.wall, 1); // the right cap
//! assert!((hit.time - 2.0).abs() < 1e-15);
//! assert_eq!(hit.normal, DVec2::new(-1.0, 0.0)); // pointing into the table
//! assert_eq!(hit.curvature, -1.0); // concave
//! # Ok::<(), spinball_geometry::GeometryError>(())
//! ```
//!
//! # Conventions
//! Normals point into the table; the tangent is `t = (n_y, -n_x)` (`t × n = +z`);
//! curvature is signed by `dn/ds = k t`, negative on concave walls. These are
//! the conventions of [`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#units-and-conventions)
//! and of the paper's eqs. (1)–(3).
//!
//! # Robustness
//! Contacts are snapped onto the wall, flight times are never negative, walls
//! are only hit from the table side, and ties (corners, junctions) go to the
//! lower wall id; each table's docs state its rule. Tolerances scale with the
//! table size (`64 ε` times its length scale).
//!
//! # Features
//! - `serde`: `Serialize`/`Deserialize` for tables, walls and hits.
#![cfg_attr(docsrs, feature(doc_cfg))]
#![forbid(unsafe_code)]

pub mod aabb;
pub mod arc;
pub mod boundary;
pub mod circle;
pub mod error;
pub mod hit;
pub mod horizon;
pub mod line;
mod loop_check;
pub mod lorentz;
mod open_spec;
mod opening;
pub mod outline;
mod positive_part;
pub mod rectangle;
pub mod segment;
pub mod segment_table;
pub mod shape;
pub mod sinai;
pub mod stadium;
pub mod table;
#[cfg(feature = "table-file")]
#[cfg_attr(docsrs, doc(cfg(feature = "table-file")))]
pub mod table_file;
pub mod wall_kind;

pub use aabb::Aabb;
pub use arc::{ArcSegment, cast_concave_circle, cast_convex_circle};
pub use boundary::{Boundary, MAX_INTERIOR_DRAWS};
pub use circle::Circle;
pub use error::GeometryError;
pub use hit::{Hit, WallId, tangent_of};
pub use horizon::Horizon;
pub use line::{Approach, LineSegment, WallHit, cast_line};
pub use lorentz::{Lattice, LorentzGas};
pub use outline::{ARC_POINTS_PER_TURN, Loop, Outline, ToOutline};
pub use rectangle::Rectangle;
pub use segment::Segment;
pub use segment_table::{FlatVisit, SegmentTable};
pub use shape::Shape;
pub use sinai::Sinai;
pub use stadium::Stadium;
pub use table::{Built, Table, TableSpecError, TableVisitor};
#[cfg(feature = "table-file")]
pub use table_file::{Opening, TableFile, TableFileError, WallSpec};
pub use wall_kind::{Cell, WallKind};

pub use glam::DVec2;
