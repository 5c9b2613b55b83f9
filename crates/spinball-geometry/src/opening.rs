//! Opening a hole in a wall: the tables of escape problems.
//!
//! A hole is a whole wall of a [`SegmentTable`] (see
//! [`SegmentTable::with_hole`]). To open a stretch of a wall, that wall is
//! split where the stretch begins and ends and the middle piece made a
//! hole: [`SegmentTable::with_hole_at`] does it from the Birkhoff
//! coordinate of the stretch's centre and its length, and the stadium,
//! Sinai and circle tables with a hole are built that way.

use std::f64::consts::PI;

use glam::DVec2;

use crate::arc::ArcSegment;
use crate::boundary::Boundary;
use crate::error::{GeometryError, finite, length};
use crate::hit::WallId;
use crate::line::LineSegment;
use crate::segment::Segment;
use crate::segment_table::SegmentTable;
use crate::wall_kind::WallKind;

/// The piece of wall `w` between arc lengths `from` and `to` along it.
fn piece(w: &Segment, from: f64, to: f64) -> Result<Segment, GeometryError> {
    Ok(match w {
        Segment::Line(l) => Segment::Line(LineSegment::new(
            l.start() + l.direction() * from,
            if to >= l.length() {
                l.end()
            } else {
                l.start() + l.direction() * to
            },
        )?),
        Segment::Arc(a) => {
            let turn = a.sweep().signum() / a.radius();
            Segment::Arc(ArcSegment::new(
                a.center(),
                a.radius(),
                a.start_angle() + turn * from,
                turn * (to - from),
            )?)
        }
    })
}

impl SegmentTable {
    /// The same table with a hole of arc length `size` centred at Birkhoff
    /// coordinate `s` (this table's parametrisation): the wall holding the
    /// stretch is split at its ends and the middle piece is a hole. The
    /// walls after the split one move up by one id per new piece; the other
    /// walls keep their kinds and Birkhoff `s` is unchanged.
    ///
    /// # Errors
    /// [`GeometryError::NonFinite`], [`GeometryError::NonPositive`],
    /// [`GeometryError::OutOfRange`] unless the stretch lies within one
    /// wall, [`GeometryError::KindOverlap`] if that wall is already a hole
    /// or periodic, and the constructor's errors for pieces too short for a
    /// table (an arc piece sweeping under 1.8°, see
    /// [`GeometryError::ArcRadius`]).
    pub fn with_hole_at(&self, s: f64, size: f64) -> Result<SegmentTable, GeometryError> {
        let s = finite("s", s)?;
        let size = length("size", size)?;
        let perimeter = self.perimeter();
        let s0 = (s - 0.5 * size).rem_euclid(perimeter);
        let walls = self.walls();
        let mut base = 0.0;
        let mut found = None;
        for (i, w) in walls.iter().enumerate() {
            if s0 >= base && s0 + size <= base + w.length() + self.slack() {
                found = Some((i, s0 - base));
                break;
            }
            base += w.length();
        }
        let Some((split, from)) = found else {
            return Err(GeometryError::OutOfRange {
                name: "hole",
                value: s,
                min: 0.0,
                max: perimeter,
                why: "a hole must lie within one wall: move its centre or shrink it, or split the wall yourself and make each piece a hole",
            });
        };
        if !self.wall_kind(split as WallId).is_reflecting() {
            return Err(GeometryError::KindOverlap {
                wall: split as WallId,
                wanted: "a hole",
                current: if self.wall_kind(split as WallId).is_hole() {
                    "a hole"
                } else {
                    "periodic"
                },
            });
        }
        let w = &walls[split];
        let to = (from + size).min(w.length());
        // Pieces shorter than the walls' tolerance are not kept.
        let tiny = self.slack();
        let mut pieces = Vec::with_capacity(3);
        if from > tiny {
            pieces.push((piece(w, 0.0, from)?, false));
        }
        pieces.push((piece(w, from, to)?, true));
        if w.length() - to > tiny {
            pieces.push((piece(w, to, w.length())?, false));
        }
        let added = pieces.len() - 1;
        let hole_id = split + pieces.iter().position(|p| p.1).unwrap_or(0);
        let new_id = |j: usize| (if j > split { j + added } else { j }) as WallId;
        // Rebuild the loops with the split wall replaced by its pieces.
        let mut loops: Vec<Vec<Segment>> = Vec::new();
        let mut start = 0;
        for len in std::iter::once(self.outer().len()).chain(self.holes().iter().map(|h| h.len())) {
            let mut lp = Vec::with_capacity(len + added);
            for (j, w) in walls.iter().enumerate().skip(start).take(len) {
                if j == split {
                    lp.extend(pieces.iter().map(|p| p.0));
                } else {
                    lp.push(*w);
                }
            }
            loops.push(lp);
            start += len;
        }
        let outer = loops.remove(0);
        let mut table = SegmentTable::with_holes(outer, loops)?;
        for (j, kind) in self.kinds().into_iter().enumerate() {
            table = match kind {
                WallKind::Hole => table.with_hole(new_id(j))?,
                WallKind::Periodic { partner, .. } if partner as usize > j => {
                    table.with_periodic(new_id(j), new_id(partner as usize))?
                }
                _ => table,
            };
        }
        table = table.with_hole(hole_id as WallId)?;
        Ok(match self.name() {
            Some(name) => table.with_name(format!("{name} with a hole at s={s},size={size}")),
            None => table,
        })
    }

    /// The stadium of flat half-length `a` (unit caps) with a hole of arc
    /// length `size` centred at Birkhoff `s` (the
    /// [`Stadium`](crate::Stadium)'s parametrisation and wall order:
    /// bottom flat, right cap, top flat, left cap, from `(−a, −1)`).
    ///
    /// # Errors
    /// [`GeometryError::NonPositive`] for `a`, and those of
    /// [`with_hole_at`](Self::with_hole_at).
    pub fn stadium_with_hole(a: f64, s: f64, size: f64) -> Result<SegmentTable, GeometryError> {
        let a = length("a", a)?;
        let p = DVec2::new;
        let outer = vec![
            Segment::Line(LineSegment::new(p(-a, -1.0), p(a, -1.0))?),
            Segment::Arc(ArcSegment::new(p(a, 0.0), 1.0, -0.5 * PI, PI)?),
            Segment::Line(LineSegment::new(p(a, 1.0), p(-a, 1.0))?),
            Segment::Arc(ArcSegment::new(p(-a, 0.0), 1.0, 0.5 * PI, PI)?),
        ];
        SegmentTable::new(outer)?
            .with_name(format!("stadium:a={a}"))
            .with_hole_at(s, size)
    }

    /// The Sinai table (square `[−l, l]²` minus the disk of radius `r` at
    /// the origin) with a hole of arc length `size` centred at Birkhoff `s`
    /// (the [`Sinai`](crate::Sinai)'s parametrisation and wall order: box
    /// from `(−l, −l)` counter-clockwise, then the disk).
    ///
    /// # Errors
    /// [`GeometryError::ObstacleTooLarge`] unless `r < l`, and those of
    /// [`with_hole_at`](Self::with_hole_at).
    pub fn sinai_with_hole(
        l: f64,
        r: f64,
        s: f64,
        size: f64,
    ) -> Result<SegmentTable, GeometryError> {
        let l = length("l", l)?;
        let r = length("r", r)?;
        if r >= l {
            return Err(GeometryError::ObstacleTooLarge { r, l });
        }
        let p = DVec2::new;
        let line = |a, b| LineSegment::new(a, b).map(Segment::Line);
        let outer = vec![
            line(p(-l, -l), p(l, -l))?,
            line(p(l, -l), p(l, l))?,
            line(p(l, l), p(-l, l))?,
            line(p(-l, l), p(-l, -l))?,
        ];
        let disk = Segment::Arc(ArcSegment::new(DVec2::ZERO, r, 0.0, -2.0 * PI)?);
        SegmentTable::with_holes(outer, vec![vec![disk]])?
            .with_name(format!("sinai:L={l},R={r}"))
            .with_hole_at(s, size)
    }

    /// The circle of `radius` about the origin with a hole of arc length
    /// `size` centred at polar angle `angle`. Its one wall starts opposite
    /// the hole (Birkhoff `s = 0` at angle `angle + π`, running
    /// counter-clockwise), so the hole is wall 1 and the pieces either side
    /// are walls 0 and 2.
    ///
    /// # Errors
    /// [`GeometryError::NonPositive`] for the radius, and those of
    /// [`with_hole_at`](Self::with_hole_at) (a hole of at least the whole
    /// circle, or so small the pieces cannot be built).
    pub fn circle_with_hole(
        radius: f64,
        angle: f64,
        size: f64,
    ) -> Result<SegmentTable, GeometryError> {
        let radius = length("radius", radius)?;
        let angle = finite("angle", angle)?;
        let wall = ArcSegment::new(DVec2::ZERO, radius, angle + PI, 2.0 * PI)?;
        SegmentTable::new(vec![Segment::Arc(wall)])?
            .with_name(format!("circle:R={radius}"))
            .with_hole_at(PI * radius, size)
    }
}
