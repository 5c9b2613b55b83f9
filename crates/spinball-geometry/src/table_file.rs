//! Tables as files: a user describes a table built from segments in TOML
//! or JSON and runs it without writing Rust (the `spinball` command line,
//! the Python package).
//!
//! A file gives the outer loop of walls (counter-clockwise, each wall
//! starting where the previous ends) or a polygon's vertices, and any
//! number of holes (clockwise loops). A wall is a `line` from one point to
//! another, or an `arc` of a circle: centre, radius, start angle and signed
//! sweep, in radians (`start`, `sweep`) or degrees (`start_deg`,
//! `sweep_deg`; multiples of 45° give the exact multiples of π/4). Instead
//! of a polygon or walls, a file may name a built-in table (`builtin =
//! "stadium:a=1"`). The file is validated as [`SegmentTable::with_holes`]
//! validates its walls.
//!
//! ```toml
//! # The mushroom: a half-disk cap of radius 1 on a stem 0.6 wide, 1 tall.
//! name = "mushroom"
//! outer = [
//!   { line = { from = [-0.3, -1.0], to = [0.3, -1.0] } },
//!   { line = { from = [0.3, -1.0], to = [0.3, 0.0] } },
//!   { line = { from = [0.3, 0.0], to = [1.0, 0.0] } },
//!   { arc = { center = [0.0, 0.0], radius = 1.0, start_deg = 0.0, sweep_deg = 180.0 } },
//!   { line = { from = [-1.0, 0.0], to = [-0.3, 0.0] } },
//!   { line = { from = [-0.3, 0.0], to = [-0.3, -1.0] } },
//! ]
//! ```

use std::f64::consts::PI;
use std::path::Path;

use glam::DVec2;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::arc::ArcSegment;
use crate::error::GeometryError;
use crate::line::LineSegment;
use crate::segment::Segment;
use crate::segment_table::SegmentTable;
use crate::table::{Built, Table, TableSpecError};

/// One wall of a table file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum WallSpec {
    /// A straight wall from `from` to `to`.
    Line {
        /// Start point.
        from: [f64; 2],
        /// End point.
        to: [f64; 2],
    },
    /// An arc of the circle of `radius` about `center`, from angle `start`
    /// (from the +x axis) through the signed angle `sweep`
    /// (counter-clockwise positive). Angles in radians, or in degrees with
    /// the `_deg` keys.
    Arc {
        /// Centre.
        center: [f64; 2],
        /// Radius.
        radius: f64,
        /// Start angle in radians.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        start: Option<f64>,
        /// Sweep in radians.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        sweep: Option<f64>,
        /// Start angle in degrees.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        start_deg: Option<f64>,
        /// Sweep in degrees.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        sweep_deg: Option<f64>,
    },
}

/// A table file's contents: a built-in table, a polygon, or loops of walls.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TableFile {
    /// A name for the table (shown in outputs).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// A built-in table's spec (`stadium:a=1`), instead of walls.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub builtin: Option<String>,
    /// The vertices of a polygon, counter-clockwise, instead of `outer`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub polygon: Option<Vec<[f64; 2]>>,
    /// The outer loop of walls, counter-clockwise.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub outer: Vec<WallSpec>,
    /// Holes: clockwise loops of walls.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub holes: Vec<Vec<WallSpec>>,
    /// Wall ids (in the order the walls are listed: outer loop, then each
    /// hole loop) through which a ball leaves the table.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub exits: Vec<u32>,
    /// Pairs of wall ids that are periodic partners (straight walls, each
    /// the other's translate, facing each other).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub periodic: Vec<[u32; 2]>,
    /// Stretches of wall opened as holes, each by its centre's Birkhoff
    /// coordinate `s` and its arc length `size` (applied after `exits` and
    /// `periodic`, in order; each splits a wall, so later wall ids move up).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub openings: Vec<Opening>,
}

/// A stretch of wall opened as a hole (see [`SegmentTable::with_hole_at`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Opening {
    /// Birkhoff coordinate of the stretch's centre.
    pub s: f64,
    /// Its arc length.
    pub size: f64,
}

/// Why a table file could not be read.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum TableFileError {
    /// The file could not be read.
    #[error("cannot read table file {path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The extension is neither `.toml` nor `.json`.
    #[error("table file {0}: unknown format (use a .toml or .json file)")]
    Format(String),
    /// The text is not valid TOML or JSON of the table-file form.
    #[error("table file{}: {message}", .path.as_deref().map(|p| format!(" {p}")).unwrap_or_default())]
    Parse {
        /// The file, if any.
        path: Option<String>,
        /// The parser's message (with line and column).
        message: String,
    },
    /// The description is incomplete or contradictory.
    #[error("table file: {0}")]
    Invalid(String),
    /// A built-in table's spec is wrong.
    #[error("table file: {0}")]
    Spec(#[from] TableSpecError),
    /// The walls do not make a table.
    #[error("table file: {0}")]
    Geometry(#[from] GeometryError),
    /// A file that was read describes no table ([`TableFile::load`]): which
    /// file, and why.
    #[error("{path}: {source}")]
    InFile {
        /// The file.
        path: String,
        /// Why its description makes no table.
        source: Box<TableFileError>,
    },
}

fn point(p: [f64; 2]) -> DVec2 {
    DVec2::new(p[0], p[1])
}

/// Degrees to radians, exact for multiples of 45°.
fn radians(deg: f64) -> f64 {
    deg / 180.0 * PI
}

impl WallSpec {
    /// The wall.
    ///
    /// # Errors
    /// [`TableFileError::Invalid`] for an arc with its angles missing or
    /// given twice; the segment constructor's [`GeometryError`].
    pub fn segment(&self) -> Result<Segment, TableFileError> {
        match *self {
            WallSpec::Line { from, to } => {
                Ok(Segment::Line(LineSegment::new(point(from), point(to))?))
            }
            WallSpec::Arc {
                center,
                radius,
                start,
                sweep,
                start_deg,
                sweep_deg,
            } => {
                let angle = |rad: Option<f64>, deg: Option<f64>, what: &str| match (rad, deg) {
                    (Some(r), None) => Ok(r),
                    (None, Some(d)) => Ok(radians(d)),
                    (Some(_), Some(_)) => Err(TableFileError::Invalid(format!(
                        "an arc gives both `{what}` and `{what}_deg`; give one"
                    ))),
                    (None, None) => Err(TableFileError::Invalid(format!(
                        "an arc needs `{what}` (radians) or `{what}_deg` (degrees)"
                    ))),
                };
                let start = angle(start, start_deg, "start")?;
                let sweep = angle(sweep, sweep_deg, "sweep")?;
                Ok(Segment::Arc(ArcSegment::new(
                    point(center),
                    radius,
                    start,
                    sweep,
                )?))
            }
        }
    }
}

fn walls(specs: &[WallSpec]) -> Result<Vec<Segment>, TableFileError> {
    specs.iter().map(WallSpec::segment).collect()
}

impl TableFile {
    /// Read TOML text.
    ///
    /// # Errors
    /// [`TableFileError::Parse`] with the parser's line and column.
    pub fn from_toml(text: &str) -> Result<Self, TableFileError> {
        toml::from_str(text).map_err(|e| TableFileError::Parse {
            path: None,
            message: e.to_string(),
        })
    }

    /// Read JSON text.
    ///
    /// # Errors
    /// [`TableFileError::Parse`] with the parser's line and column.
    pub fn from_json(text: &str) -> Result<Self, TableFileError> {
        serde_json::from_str(text).map_err(|e| TableFileError::Parse {
            path: None,
            message: e.to_string(),
        })
    }

    /// Read a `.toml` or `.json` file.
    ///
    /// # Errors
    /// [`TableFileError`]: unreadable, unknown extension, not parseable.
    pub fn read(path: impl AsRef<Path>) -> Result<Self, TableFileError> {
        let path = path.as_ref();
        let shown = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|source| TableFileError::Io {
            path: shown.clone(),
            source,
        })?;
        let parsed = match path.extension().and_then(|e| e.to_str()) {
            Some("toml") => Self::from_toml(&text),
            Some("json") => Self::from_json(&text),
            _ => return Err(TableFileError::Format(shown)),
        };
        parsed.map_err(|e| match e {
            TableFileError::Parse { message, .. } => TableFileError::Parse {
                path: Some(shown),
                message,
            },
            other => other,
        })
    }

    /// The table the file describes.
    ///
    /// # Errors
    /// [`TableFileError::Invalid`] unless exactly one of `builtin`,
    /// `polygon` and `outer` is given (holes only with walls or a polygon);
    /// the table's validation errors.
    pub fn build(&self) -> Result<Built, TableFileError> {
        let given = [
            self.builtin.is_some(),
            self.polygon.is_some(),
            !self.outer.is_empty(),
        ];
        if given.iter().filter(|&&g| g).count() != 1 {
            return Err(TableFileError::Invalid(
                "give exactly one of `builtin` (a spec such as \"stadium:a=1\"), `polygon` \
                 (vertices) or `outer` (walls)"
                    .into(),
            ));
        }
        if let Some(spec) = &self.builtin {
            if !self.holes.is_empty() {
                return Err(TableFileError::Invalid(
                    "a built-in table takes no `holes`".into(),
                ));
            }
            if !(self.exits.is_empty() && self.periodic.is_empty() && self.openings.is_empty()) {
                return Err(TableFileError::Invalid(
                    "a built-in table takes no `exits`, `periodic` or `openings`: describe it by its walls (or polygon) to give it holes or periodic walls".into(),
                ));
            }
            return Ok(Built::Table(spec.parse::<Table>()?));
        }
        let holes = self
            .holes
            .iter()
            .map(|h| walls(h))
            .collect::<Result<Vec<_>, _>>()?;
        let outer = match &self.polygon {
            Some(vertices) => {
                let v: Vec<DVec2> = vertices.iter().copied().map(point).collect();
                SegmentTable::polygon(&v)?.outer().to_vec()
            }
            None => walls(&self.outer)?,
        };
        let mut table = SegmentTable::with_holes(outer, holes)?;
        for &wall in &self.exits {
            table = table.with_hole(wall)?;
        }
        for &[a, b] in &self.periodic {
            table = table.with_periodic(a, b)?;
        }
        for opening in &self.openings {
            table = table.with_hole_at(opening.s, opening.size)?;
        }
        Ok(Built::Segments(match &self.name {
            Some(name) => table.with_name(name.clone()),
            None => table,
        }))
    }

    /// Read a `.toml` or `.json` file and build its table; an error of the
    /// description names the file.
    ///
    /// # Errors
    /// As [`read`](Self::read); what [`build`](Self::build) refuses comes as
    /// [`TableFileError::InFile`] with the file's path.
    pub fn load(path: impl AsRef<Path>) -> Result<Built, TableFileError> {
        let path = path.as_ref();
        Self::read(path)?
            .build()
            .map_err(|e| TableFileError::InFile {
                path: path.display().to_string(),
                source: Box::new(e),
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Boundary;

    const MUSHROOM: &str = r#"
        name = "mushroom"
        outer = [
          { line = { from = [-0.3, -1.0], to = [0.3, -1.0] } },
          { line = { from = [0.3, -1.0], to = [0.3, 0.0] } },
          { line = { from = [0.3, 0.0], to = [1.0, 0.0] } },
          { arc = { center = [0.0, 0.0], radius = 1.0, start_deg = 0.0, sweep_deg = 180.0 } },
          { line = { from = [-1.0, 0.0], to = [-0.3, 0.0] } },
          { line = { from = [-0.3, 0.0], to = [-0.3, -1.0] } },
        ]
    "#;

    #[test]
    fn mushroom_from_toml_has_the_right_area() {
        let t = TableFile::from_toml(MUSHROOM).unwrap().build().unwrap();
        // Half disk of radius 1 plus a 0.6 × 1 stem.
        let area = PI / 2.0 + 0.6;
        assert!((t.area() - area).abs() < 1e-12, "{}", t.area());
        assert!((t.curved_length() - PI).abs() < 1e-12);
    }

    #[test]
    fn the_name_is_kept_and_shown_but_is_not_geometry() {
        let named = TableFile::from_toml(MUSHROOM).unwrap().build().unwrap();
        assert_eq!(named.to_string(), "mushroom (segments, 6 walls)");
        let Built::Segments(table) = &named else {
            panic!("a table of walls")
        };
        assert_eq!(table.name(), Some("mushroom"));
        // Through the shape (what results carry) and back.
        let shape = named.shape().unwrap();
        assert_eq!(shape.to_string(), "mushroom (segments, 6 walls)");
        assert_eq!(shape.build().unwrap(), named);
        // Without the name: the same walls, the unnamed spec.
        let unnamed = TableFile::from_toml(&MUSHROOM.replace("name = \"mushroom\"", ""))
            .unwrap()
            .build()
            .unwrap();
        assert_eq!(unnamed.to_string(), "segments(6 walls)");
        assert_eq!(unnamed.shape().unwrap().walls(), shape.walls());
    }

    #[test]
    fn a_loaded_file_that_makes_no_table_is_named_in_the_error() {
        let dir = std::env::temp_dir().join(format!("spinball-table-file-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("open_triangle.toml");
        std::fs::write(&path, "polygon = [[0,0],[1,0]]").unwrap();
        let err = TableFile::load(&path).unwrap_err();
        assert!(matches!(err, TableFileError::InFile { .. }), "{err:?}");
        let text = err.to_string();
        assert!(text.starts_with(&path.display().to_string()), "{text}");
        assert!(text.contains("wall"), "{text}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn the_lorentz_cell_file_has_periodic_walls_and_the_stadium_file_a_hole() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/tables");
        let cell = TableFile::load(dir.join("square-lorentz-cell.toml")).unwrap();
        assert!(!cell.has_holes());
        assert_eq!(
            cell.lattice(),
            Some([DVec2::new(1.0, 0.0), DVec2::new(0.0, 1.0)])
        );
        let kinds: Vec<bool> = (0..5).map(|w| cell.wall_kind(w).is_periodic()).collect();
        assert_eq!(kinds, [true, true, true, true, false]);
        // The same cell as the built-in convenience.
        let Built::Segments(cell) = cell else {
            panic!("a table of walls")
        };
        let built = crate::LorentzGas::square(1.0, 0.4)
            .unwrap()
            .table()
            .unwrap();
        assert_eq!(cell.kinds(), built.kinds());
        let open = TableFile::load(dir.join("stadium-with-hole.toml")).unwrap();
        assert!(open.has_holes());
        assert!(open.lattice().is_none());
        assert!(!open.shape().unwrap().is_closed());
        // Through the shape (what results carry) and back: kinds kept.
        assert_eq!(open.shape().unwrap().build().unwrap(), open);
    }

    #[test]
    fn wall_kind_keys_are_checked() {
        let square = "polygon = [[0,0],[1,0],[1,1],[0,1]]\n";
        let cases = [
            (format!("{square}exits = [9]"), "does not exist"),
            (format!("{square}exits = [0, 0]"), "already a hole"),
            (format!("{square}periodic = [[0, 1]]"), "periodic partners"),
            (
                format!("{square}periodic = [[0, 2]]\nexits = [2]"),
                "already",
            ),
            (
                "builtin = \"stadium:a=1\"\nexits = [0]".to_string(),
                "no `exits`",
            ),
        ];
        for (text, needle) in cases {
            let err = TableFile::from_toml(&text)
                .and_then(|f| f.build())
                .expect_err(&text)
                .to_string();
            assert!(err.contains(needle), "{text:?}: {err}");
        }
    }

    #[test]
    fn degrees_are_exact_on_quarter_turns() {
        assert_eq!(radians(180.0), PI);
        assert_eq!(radians(90.0), std::f64::consts::FRAC_PI_2);
        assert_eq!(radians(-360.0), -std::f64::consts::TAU);
    }

    #[test]
    fn json_polygon_with_a_disk_hole() {
        let text = r#"{"polygon": [[-2,-2],[2,-2],[2,2],[-2,2]],
            "holes": [[{"arc": {"center": [0,0], "radius": 1, "start": 0, "sweep_deg": -360}}]]}"#;
        let t = TableFile::from_json(text).unwrap().build().unwrap();
        assert!((t.area() - (16.0 - PI)).abs() < 1e-12, "{}", t.area());
    }

    #[test]
    fn builtin_tables_by_spec() {
        let t = TableFile::from_toml("builtin = \"stadium:a=1\"").unwrap();
        assert_eq!(t.build().unwrap().to_string(), "stadium:a=1");
    }

    #[test]
    fn bad_files_say_what_is_wrong() {
        let cases = [
            ("", "exactly one of"),
            (
                "builtin = \"stadium:a=1\"\npolygon = [[0,0],[1,0],[0,1]]",
                "exactly one of",
            ),
            (
                "outer = [ { arc = { center = [0,0], radius = 1, sweep = 1 } } ]",
                "`start`",
            ),
            (
                "outer = [ { arc = { center = [0,0], radius = 1, start = 0, start_deg = 0, sweep = 1 } } ]",
                "both",
            ),
            ("polygon = [[0,0],[1,0]]", "wall"),
            ("outer = [ { wall = 1 } ]", "unknown variant"),
            ("colour = \"red\"", "unknown field"),
            ("builtin = \"hexagon\"", "unknown table"),
        ];
        for (text, needle) in cases {
            let err = TableFile::from_toml(text)
                .and_then(|f| f.build())
                .expect_err(text)
                .to_string();
            assert!(err.contains(needle), "{text:?}: {err}");
        }
    }
}
