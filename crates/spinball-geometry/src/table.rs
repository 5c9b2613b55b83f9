//! Choosing a table at run time (from a command line or a config file).
//!
//! Hot loops are generic over the table type; [`Table`] is the enum of the
//! built-in tables that a program picks from a string such as `stadium:a=1`,
//! and [`Table::visit`] dispatches **once**, handing the concrete table to a
//! generic [`TableVisitor`], so the loop inside runs with static dispatch.

use std::fmt;
use std::str::FromStr;

use glam::DVec2;
use thiserror::Error;

use crate::boundary::{Aabb, Boundary};
use crate::error::GeometryError;
use crate::hit::{Hit, WallId};
use crate::shape::Shape;
use crate::wall_kind::WallKind;
use crate::{Circle, Rectangle, SegmentTable, Sinai, Stadium};

/// One of the built-in tables.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Table {
    /// [`Circle`].
    Circle(Circle),
    /// [`Rectangle`].
    Rectangle(Rectangle),
    /// [`Stadium`].
    Stadium(Stadium),
    /// [`Sinai`].
    Sinai(Sinai),
}

/// A computation generic over the table type, run by [`Table::visit`].
pub trait TableVisitor {
    /// What the computation returns.
    type Output;
    /// Run with the concrete table.
    fn visit<B: Boundary + Clone + Send + Sync>(self, table: &B) -> Self::Output;
}

impl Table {
    /// Run `visitor` with the concrete table (one dispatch, then static).
    pub fn visit<V: TableVisitor>(&self, visitor: V) -> V::Output {
        match self {
            Table::Circle(t) => visitor.visit(t),
            Table::Rectangle(t) => visitor.visit(t),
            Table::Stadium(t) => visitor.visit(t),
            Table::Sinai(t) => visitor.visit(t),
        }
    }

    /// Short name: `circle`, `rectangle`, `stadium` or `sinai`.
    pub fn name(&self) -> &'static str {
        match self {
            Table::Circle(_) => "circle",
            Table::Rectangle(_) => "rectangle",
            Table::Stadium(_) => "stadium",
            Table::Sinai(_) => "sinai",
        }
    }
}

impl From<Circle> for Table {
    fn from(t: Circle) -> Self {
        Table::Circle(t)
    }
}
impl From<Rectangle> for Table {
    fn from(t: Rectangle) -> Self {
        Table::Rectangle(t)
    }
}
impl From<Stadium> for Table {
    fn from(t: Stadium) -> Self {
        Table::Stadium(t)
    }
}
impl From<Sinai> for Table {
    fn from(t: Sinai) -> Self {
        Table::Sinai(t)
    }
}

/// Convenience: a [`Table`] is itself a boundary (one `match` per call; use
/// [`Table::visit`] in hot loops).
impl Boundary for Table {
    fn cast(&self, origin: DVec2, velocity: DVec2) -> Option<Hit> {
        match self {
            Table::Circle(t) => t.cast(origin, velocity),
            Table::Rectangle(t) => t.cast(origin, velocity),
            Table::Stadium(t) => t.cast(origin, velocity),
            Table::Sinai(t) => t.cast(origin, velocity),
        }
    }
    fn contains(&self, p: DVec2) -> bool {
        match self {
            Table::Circle(t) => t.contains(p),
            Table::Rectangle(t) => t.contains(p),
            Table::Stadium(t) => t.contains(p),
            Table::Sinai(t) => t.contains(p),
        }
    }
    fn contains_shrunk(&self, p: DVec2, shrink: f64) -> bool {
        match self {
            Table::Circle(t) => t.contains_shrunk(p, shrink),
            Table::Rectangle(t) => t.contains_shrunk(p, shrink),
            Table::Stadium(t) => t.contains_shrunk(p, shrink),
            Table::Sinai(t) => t.contains_shrunk(p, shrink),
        }
    }
    fn aabb(&self) -> Aabb {
        match self {
            Table::Circle(t) => t.aabb(),
            Table::Rectangle(t) => t.aabb(),
            Table::Stadium(t) => t.aabb(),
            Table::Sinai(t) => t.aabb(),
        }
    }
    fn perimeter(&self) -> f64 {
        match self {
            Table::Circle(t) => t.perimeter(),
            Table::Rectangle(t) => t.perimeter(),
            Table::Stadium(t) => t.perimeter(),
            Table::Sinai(t) => t.perimeter(),
        }
    }
    fn area(&self) -> f64 {
        match self {
            Table::Circle(t) => t.area(),
            Table::Rectangle(t) => t.area(),
            Table::Stadium(t) => t.area(),
            Table::Sinai(t) => t.area(),
        }
    }
    fn curved_length(&self) -> f64 {
        match self {
            Table::Circle(t) => t.curved_length(),
            Table::Rectangle(t) => t.curved_length(),
            Table::Stadium(t) => t.curved_length(),
            Table::Sinai(t) => t.curved_length(),
        }
    }
    fn unit_length(&self) -> f64 {
        match self {
            Table::Circle(t) => t.unit_length(),
            Table::Rectangle(t) => t.unit_length(),
            Table::Stadium(t) => t.unit_length(),
            Table::Sinai(t) => t.unit_length(),
        }
    }
    fn shape(&self) -> Option<Shape> {
        match self {
            Table::Circle(t) => t.shape(),
            Table::Rectangle(t) => t.shape(),
            Table::Stadium(t) => t.shape(),
            Table::Sinai(t) => t.shape(),
        }
    }
    fn hit_at(&self, s: f64) -> Option<Hit> {
        match self {
            Table::Circle(t) => t.hit_at(s),
            Table::Rectangle(t) => t.hit_at(s),
            Table::Stadium(t) => t.hit_at(s),
            Table::Sinai(t) => t.hit_at(s),
        }
    }
    fn wall_kind(&self, wall: WallId) -> WallKind {
        match self {
            Table::Circle(t) => t.wall_kind(wall),
            Table::Rectangle(t) => t.wall_kind(wall),
            Table::Stadium(t) => t.wall_kind(wall),
            Table::Sinai(t) => t.wall_kind(wall),
        }
    }
    fn lattice(&self) -> Option<[DVec2; 2]> {
        match self {
            Table::Circle(t) => t.lattice(),
            Table::Rectangle(t) => t.lattice(),
            Table::Stadium(t) => t.lattice(),
            Table::Sinai(t) => t.lattice(),
        }
    }
    fn has_holes(&self) -> bool {
        match self {
            Table::Circle(t) => t.has_holes(),
            Table::Rectangle(t) => t.has_holes(),
            Table::Stadium(t) => t.has_holes(),
            Table::Sinai(t) => t.has_holes(),
        }
    }
}

/// Why a table description string could not be read.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum TableSpecError {
    /// The name before `:` is not a built-in table.
    #[error("unknown table `{0}` (expected circle, rectangle, stadium, sinai or lorentz)")]
    UnknownTable(String),
    /// A `key=value` pair names a parameter the table does not have.
    #[error("table `{table}` has no parameter `{key}` (it takes: {allowed})")]
    UnknownKey {
        /// Table name.
        table: &'static str,
        /// The key given.
        key: String,
        /// The keys it takes.
        allowed: &'static str,
    },
    /// A parameter is not written `key=number`.
    #[error("cannot read `{0}` as key=number")]
    BadPair(String),
    /// A parameter that takes a word got another word.
    #[error("`{key}={value}` is not a choice of `{key}` (it takes: {allowed})")]
    BadWord {
        /// The key.
        key: &'static str,
        /// The word given.
        value: String,
        /// The words it takes.
        allowed: &'static str,
    },
    /// The numbers do not make a valid table.
    #[error(transparent)]
    Geometry(#[from] GeometryError),
}

impl FromStr for Table {
    type Err = TableSpecError;

    /// Read `circle`, `circle:R=1`, `rectangle:L=1,H=1`, `stadium:a=1` or
    /// `sinai:L=2,R=1` (keys are case-insensitive; missing keys take the
    /// paper's values).
    fn from_str(spec: &str) -> Result<Self, Self::Err> {
        let (name, params) = spec.trim().split_once(':').unwrap_or((spec.trim(), ""));
        let name = name.trim();
        let mut pairs = Vec::new();
        for pair in params.split(',').map(str::trim).filter(|p| !p.is_empty()) {
            let (k, v) = pair
                .split_once('=')
                .ok_or_else(|| TableSpecError::BadPair(pair.to_string()))?;
            let v: f64 = v
                .trim()
                .parse()
                .map_err(|_| TableSpecError::BadPair(pair.to_string()))?;
            pairs.push((k.trim().to_ascii_lowercase(), v));
        }
        let get = |table: &'static str, allowed: &'static str, key: &str, default: f64| {
            for (k, _) in &pairs {
                if !allowed.split(", ").any(|a| a.eq_ignore_ascii_case(k)) {
                    return Err(TableSpecError::UnknownKey {
                        table,
                        key: k.clone(),
                        allowed,
                    });
                }
            }
            Ok(pairs
                .iter()
                .rev()
                .find(|(k, _)| k == key)
                .map_or(default, |(_, v)| *v))
        };
        Ok(match name.to_ascii_lowercase().as_str() {
            "circle" => Circle::new(get("circle", "R", "r", 1.0)?)?.into(),
            "rectangle" => Rectangle::new(
                get("rectangle", "L, H", "l", 1.0)?,
                get("rectangle", "L, H", "h", 1.0)?,
            )?
            .into(),
            "stadium" => Stadium::new(get("stadium", "a", "a", 1.0)?)?.into(),
            "sinai" => Sinai::new(
                get("sinai", "L, R", "l", 2.0)?,
                get("sinai", "L, R", "r", 1.0)?,
            )?
            .into(),
            _ => return Err(TableSpecError::UnknownTable(name.to_string())),
        })
    }
}

impl fmt::Display for Table {
    /// The spec string that [`FromStr`] reads back.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.shape() {
            Some(shape) => shape.fmt(f),
            None => Ok(()),
        }
    }
}

/// A table rebuilt from its [`Shape`]: a built-in table or a segment table.
#[derive(Debug, Clone, PartialEq)]
pub enum Built {
    /// One of the four built-in tables.
    Table(Table),
    /// A table built from segments.
    Segments(SegmentTable),
}

impl Shape {
    /// Rebuild the table this shape describes (validated as its constructor
    /// validates it).
    ///
    /// # Errors
    /// The constructor's [`GeometryError`].
    pub fn build(&self) -> Result<Built, GeometryError> {
        Ok(match self {
            Shape::Circle { radius } => Built::Table(Circle::new(*radius)?.into()),
            Shape::Rectangle { l, h } => Built::Table(Rectangle::new(*l, *h)?.into()),
            Shape::Stadium { a } => Built::Table(Stadium::new(*a)?.into()),
            Shape::Sinai { l, r } => Built::Table(Sinai::new(*l, *r)?.into()),
            Shape::Segments {
                outer,
                holes,
                name,
                kinds,
            } => {
                let mut table = SegmentTable::with_holes(outer.clone(), holes.clone())?;
                for (i, kind) in kinds.iter().enumerate() {
                    let i = i as WallId;
                    table = match *kind {
                        WallKind::Reflecting => table,
                        WallKind::Hole => table.with_hole(i)?,
                        WallKind::Periodic { partner, .. } if partner > i => {
                            table.with_periodic(i, partner)?
                        }
                        WallKind::Periodic { .. } => table,
                    };
                }
                Built::Segments(match name {
                    Some(name) => table.with_name(name.clone()),
                    None => table,
                })
            }
        })
    }
}

/// A rebuilt table is a table: results and ensembles over a table read
/// from data (a [`Shape`], a table file) run whichever kind it is. Every
/// method forwards, so exact overrides are kept.
impl Boundary for Built {
    fn cast(&self, origin: DVec2, velocity: DVec2) -> Option<Hit> {
        match self {
            Built::Table(t) => t.cast(origin, velocity),
            Built::Segments(t) => t.cast(origin, velocity),
        }
    }
    fn contains(&self, p: DVec2) -> bool {
        match self {
            Built::Table(t) => t.contains(p),
            Built::Segments(t) => t.contains(p),
        }
    }
    fn contains_shrunk(&self, p: DVec2, shrink: f64) -> bool {
        match self {
            Built::Table(t) => t.contains_shrunk(p, shrink),
            Built::Segments(t) => t.contains_shrunk(p, shrink),
        }
    }
    fn aabb(&self) -> Aabb {
        match self {
            Built::Table(t) => t.aabb(),
            Built::Segments(t) => t.aabb(),
        }
    }
    fn reference_point(&self) -> DVec2 {
        match self {
            Built::Table(t) => t.reference_point(),
            Built::Segments(t) => t.reference_point(),
        }
    }
    fn perimeter(&self) -> f64 {
        match self {
            Built::Table(t) => t.perimeter(),
            Built::Segments(t) => t.perimeter(),
        }
    }
    fn area(&self) -> f64 {
        match self {
            Built::Table(t) => t.area(),
            Built::Segments(t) => t.area(),
        }
    }
    fn unit_length(&self) -> f64 {
        match self {
            Built::Table(t) => t.unit_length(),
            Built::Segments(t) => t.unit_length(),
        }
    }
    fn curved_length(&self) -> f64 {
        match self {
            Built::Table(t) => t.curved_length(),
            Built::Segments(t) => t.curved_length(),
        }
    }
    fn shape(&self) -> Option<Shape> {
        match self {
            Built::Table(t) => t.shape(),
            Built::Segments(t) => t.shape(),
        }
    }
    fn hit_at(&self, s: f64) -> Option<Hit> {
        match self {
            Built::Table(t) => t.hit_at(s),
            Built::Segments(t) => t.hit_at(s),
        }
    }
    fn length_scale(&self) -> f64 {
        match self {
            Built::Table(t) => t.length_scale(),
            Built::Segments(t) => t.length_scale(),
        }
    }
    fn wall_kind(&self, wall: WallId) -> WallKind {
        match self {
            Built::Table(t) => t.wall_kind(wall),
            Built::Segments(t) => t.wall_kind(wall),
        }
    }
    fn lattice(&self) -> Option<[DVec2; 2]> {
        match self {
            Built::Table(t) => t.lattice(),
            Built::Segments(t) => t.lattice(),
        }
    }
    fn has_holes(&self) -> bool {
        match self {
            Built::Table(t) => t.has_holes(),
            Built::Segments(t) => t.has_holes(),
        }
    }
}

impl fmt::Display for Built {
    /// The table's spec string, or `segments(N walls)` (with its name
    /// first if it has one: `mushroom (segments, 6 walls)`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.shape() {
            Some(shape) => shape.fmt(f),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn built_tables_keep_the_unit_length_of_what_they_wrap() {
        // A tangent vector is measured in the table's unit length; a
        // `Built` that fell back to the default (half its diagonal) would
        // measure the stadium in units of 2, not 1.
        for spec in [
            "stadium:a=1",
            "sinai:L=2,R=1",
            "circle:R=3",
            "rectangle:L=1.5,H=1",
        ] {
            let table: Table = spec.parse().unwrap();
            assert_eq!(
                Built::Table(table).unit_length(),
                table.unit_length(),
                "{spec}"
            );
        }
        let square = SegmentTable::polygon(&[
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(0.0, 1.0),
        ])
        .unwrap();
        let unit = square.unit_length();
        assert_eq!(Built::Segments(square).unit_length(), unit);
    }
}
