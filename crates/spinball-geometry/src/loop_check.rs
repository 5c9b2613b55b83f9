//! Whether the loops of a [`SegmentTable`](crate::SegmentTable) bound a
//! table: no wall crosses or runs along another, every hole lies inside the
//! outer loop and outside the other holes.
//!
//! A loop that crosses itself, a zero-width spike, or a hole poking out of
//! the table gives a region whose "inside" is ambiguous: casts would let a
//! ball through a wall or trap it in a slit of no width. These are rejected
//! when the table is built, with the walls named.

use glam::DVec2;

use crate::arc::ArcSegment;
use crate::error::GeometryError;
use crate::segment::Segment;

/// A wall with its place: loop, index in the loop, loop length.
#[derive(Clone, Copy)]
struct Placed {
    lp: usize,
    index: usize,
    len: usize,
    wall: Segment,
}

/// How two walls meet.
enum Meeting {
    /// They share a stretch (collinear lines, or arcs of one circle).
    Overlap,
    /// They meet at these points (0, 1 or 2 of them).
    Points(Vec<DVec2>),
}

/// Check the loops (outer first). `scale` is the table size; meetings are
/// found to `1e-9 scale`, and consecutive walls may meet anywhere within
/// `1e-6 scale` of their shared end (a wall tangent to the next one meets it
/// over a stretch of order `√ε` in rounding).
pub(crate) fn check_loops(loops: &[&Vec<Segment>], scale: f64) -> Result<(), GeometryError> {
    let tol = 1e-9 * scale;
    let near = 1e-6 * scale;
    let walls: Vec<Placed> = loops
        .iter()
        .enumerate()
        .flat_map(|(lp, walls)| {
            walls.iter().enumerate().map(move |(index, &wall)| Placed {
                lp,
                index,
                len: walls.len(),
                wall,
            })
        })
        .collect();
    for (k, a) in walls.iter().enumerate() {
        for b in &walls[k + 1..] {
            let shared = shared_ends(a, b);
            let overlap = || GeometryError::Overlap {
                first_loop: a.lp,
                first_index: a.index,
                second_loop: b.lp,
                second_index: b.index,
            };
            match meet(&a.wall, &b.wall, tol) {
                Meeting::Overlap => return Err(overlap()),
                Meeting::Points(points) => {
                    for p in points {
                        if !shared.iter().any(|s| (p - *s).length() <= near) {
                            return Err(GeometryError::Crossing {
                                first_loop: a.lp,
                                first_index: a.index,
                                second_loop: b.lp,
                                second_index: b.index,
                                x: p.x,
                                y: p.y,
                            });
                        }
                    }
                }
            }
        }
    }
    // No walls cross, so each hole is wholly inside or wholly outside any
    // other loop: one point of it decides.
    for (h, hole) in loops.iter().enumerate().skip(1) {
        let p = hole[0].start();
        if !inside(p, loops[0]) {
            return Err(GeometryError::MisplacedHole {
                hole: h,
                where_: "outside the outer loop".into(),
            });
        }
        for (k, other) in loops.iter().enumerate().skip(1) {
            if k != h && inside(p, other) {
                return Err(GeometryError::MisplacedHole {
                    hole: h,
                    where_: format!("inside hole {k}"),
                });
            }
        }
    }
    Ok(())
}

/// The ends two walls share as consecutive walls of one loop.
fn shared_ends(a: &Placed, b: &Placed) -> Vec<DVec2> {
    let mut out = Vec::new();
    if a.lp != b.lp {
        return out;
    }
    if (a.index + 1) % a.len == b.index {
        out.push(a.wall.end());
    }
    if (b.index + 1) % b.len == a.index {
        out.push(b.wall.end());
    }
    out
}

fn meet(a: &Segment, b: &Segment, tol: f64) -> Meeting {
    match (a, b) {
        (Segment::Line(p), Segment::Line(q)) => lines(p.start(), p.end(), q.start(), q.end(), tol),
        (Segment::Line(p), Segment::Arc(c)) | (Segment::Arc(c), Segment::Line(p)) => {
            Meeting::Points(line_arc(p.start(), p.end(), c, tol))
        }
        (Segment::Arc(c), Segment::Arc(d)) => arcs(c, d, tol),
    }
}

fn lines(p0: DVec2, p1: DVec2, q0: DVec2, q1: DVec2, tol: f64) -> Meeting {
    let (r, s) = (p1 - p0, q1 - q0);
    let (lr, ls) = (r.length(), s.length());
    let denom = r.perp_dot(s);
    let w = q0 - p0;
    if denom.abs() <= 1e-12 * lr * ls {
        // Parallel: they meet only if collinear, along the overlap of their
        // projections onto p.
        if w.perp_dot(r).abs() > tol * lr {
            return Meeting::Points(Vec::new());
        }
        let t0 = w.dot(r) / (lr * lr);
        let t1 = (q1 - p0).dot(r) / (lr * lr);
        let (lo, hi) = (t0.min(t1).max(0.0), t0.max(t1).min(1.0));
        if (hi - lo) * lr > tol {
            return Meeting::Overlap;
        }
        if hi - lo >= -tol / lr {
            return Meeting::Points(vec![p0 + r * lo.clamp(0.0, 1.0)]);
        }
        return Meeting::Points(Vec::new());
    }
    let t = w.perp_dot(s) / denom;
    let u = w.perp_dot(r) / denom;
    let (et, eu) = (tol / lr, tol / ls);
    if (-et..=1.0 + et).contains(&t) && (-eu..=1.0 + eu).contains(&u) {
        Meeting::Points(vec![p0 + r * t])
    } else {
        Meeting::Points(Vec::new())
    }
}

fn line_arc(p0: DVec2, p1: DVec2, c: &ArcSegment, tol: f64) -> Vec<DVec2> {
    let r = p1 - p0;
    let d = p0 - c.center();
    let a = r.length_squared();
    let b = d.dot(r);
    let cc = d.length_squared() - c.radius() * c.radius();
    let disc = b * b - a * cc;
    // A line within `tol` of tangency touches.
    if disc < -2.0 * tol * c.radius() * a {
        return Vec::new();
    }
    let root = disc.max(0.0).sqrt();
    let e = tol / a.sqrt();
    [(-b - root) / a, (-b + root) / a]
        .into_iter()
        .filter(|t| (-e..=1.0 + e).contains(t))
        .map(|t| p0 + r * t.clamp(0.0, 1.0))
        .filter(|p| c.covers(*p, tol))
        .collect()
}

fn arcs(c: &ArcSegment, d: &ArcSegment, tol: f64) -> Meeting {
    let between = d.center() - c.center();
    let dist = between.length();
    let (r1, r2) = (c.radius(), d.radius());
    if dist <= tol && (r1 - r2).abs() <= tol {
        // One circle: they overlap if either's midpoint lies on the other.
        if d.covers(midpoint(c), -tol) || c.covers(midpoint(d), -tol) {
            return Meeting::Overlap;
        }
        let ends = [c.start(), c.end(), d.start(), d.end()];
        return Meeting::Points(
            ends.into_iter()
                .filter(|p| c.covers(*p, tol) && d.covers(*p, tol))
                .collect(),
        );
    }
    if dist > r1 + r2 + tol || dist < (r1 - r2).abs() - tol || dist == 0.0 {
        return Meeting::Points(Vec::new());
    }
    let e = between / dist;
    let x = (dist * dist + r1 * r1 - r2 * r2) / (2.0 * dist);
    let h = (r1 * r1 - x * x).max(0.0).sqrt();
    let base = c.center() + e * x;
    Meeting::Points(
        [base + e.perp() * h, base - e.perp() * h]
            .into_iter()
            .filter(|p| c.covers(*p, tol) && d.covers(*p, tol))
            .collect(),
    )
}

fn midpoint(c: &ArcSegment) -> DVec2 {
    c.center() + DVec2::from_angle(c.start_angle() + 0.5 * c.sweep()) * c.radius()
}

/// Whether `p` lies inside the closed loop `walls` (either orientation): the
/// parity of the crossings of a ray from `p` in a fixed irrational direction.
fn inside(p: DVec2, walls: &[Segment]) -> bool {
    const RAY: DVec2 = DVec2::new(0.754_877_666_246_692_7, 0.569_840_290_998_053_2);
    let mut crossings = 0usize;
    for w in walls {
        match w {
            Segment::Line(l) => {
                let s = l.end() - l.start();
                let denom = RAY.perp_dot(s);
                if denom == 0.0 {
                    continue;
                }
                let w0 = l.start() - p;
                let t = w0.perp_dot(s) / denom;
                let u = w0.perp_dot(RAY) / denom;
                if t > 0.0 && (0.0..1.0).contains(&u) {
                    crossings += 1;
                }
            }
            Segment::Arc(c) => {
                let d = p - c.center();
                let b = d.dot(RAY);
                let cc = d.length_squared() - c.radius() * c.radius();
                let disc = b * b - cc;
                if disc <= 0.0 {
                    continue;
                }
                let root = disc.sqrt();
                for t in [-b - root, -b + root] {
                    if t > 0.0 && c.covers(p + RAY * t, 0.0) {
                        crossings += 1;
                    }
                }
            }
        }
    }
    crossings % 2 == 1
}
