//! The horizon of a periodic table: whether a ball can fly forever without
//! meeting a wall.
//!
//! Diffusion through a lattice of scatterers is normal (`⟨Δr²⟩ ≈ 4Dt`)
//! when every free flight is bounded (a **finite horizon**), and marginally
//! anomalous (`⟨Δr²⟩ ~ t ln t`, no finite `D`) when a **corridor** (a strip
//! of the plane that misses every scatterer) lets flights of any length
//! through. An estimator of `D` must know which, so the horizon is read from
//! the geometry, never assumed.
//!
//! [`SegmentTable::horizon`] decides it for any table with periodic walls:
//!
//! - A corridor runs along a lattice direction `d = p b₁ + q b₂` (`p`, `q`
//!   coprime). Seen along `d`, the copies of the cell repeat across the
//!   corridor's normal with period `P = |b₁ × b₂| / |d|`, so the lines along
//!   `d` that miss every wall are the gaps in the union of the walls'
//!   shadows (their projections on the normal) taken modulo `P`.
//! - A scatterer whose shadow is at least `P` wide covers every line, so only
//!   directions with `|d| ≤ |b₁ × b₂| / W` can hold a corridor, where `W` is
//!   the smallest width of the widest connected piece of wall (a disk's
//!   `2R`). The search visits every one of them: when none has a gap the
//!   horizon is finite, not merely "no corridor found".
//! - A channel (periodic in one direction only) has its corridor, if any,
//!   along the channel.
//!
//! Holes count as walls (a flight that reaches one ends), periodic walls do
//! not. A corridor narrower than [`MIN_CORRIDOR`] of the cell's size counts
//! as closed: a ball flying through it grazes the walls' rounding.
//! [`LorentzGas::horizon`](crate::LorentzGas::horizon) gives the same answer
//! for the two lattices in closed form.

use glam::DVec2;

use crate::boundary::Boundary;
use crate::error::GeometryError;
use crate::segment::Segment;
use crate::segment_table::SegmentTable;
use crate::table::Built;
use crate::wall_kind::WallKind;

/// Whether free flights are bounded.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Horizon {
    /// Every straight line meets a wall: free flights are bounded and
    /// diffusion is normal.
    Finite,
    /// A corridor free of walls runs along `direction`: free flights are
    /// unbounded and the mean-square displacement grows as `t ln t`
    /// (marginally anomalous), so no finite diffusion coefficient exists.
    Infinite {
        /// Unit vector along the widest corridor.
        direction: DVec2,
        /// The corridor's width (distance between the walls that bound it).
        width: f64,
    },
}

impl Horizon {
    /// Whether the horizon is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        matches!(self, Horizon::Finite)
    }
}

/// Corridors narrower than this fraction of the cell's size (its longer
/// lattice vector) count as closed.
pub const MIN_CORRIDOR: f64 = 1e-9;

/// Most lattice directions [`SegmentTable::horizon`] examines before it
/// gives up with [`GeometryError::HorizonUndecided`] (scatterers so thin
/// against the cell that corridors could run along very long lattice
/// vectors).
pub const MAX_DIRECTIONS: usize = 200_000;

/// Directions sampled to bound a scatterer's smallest width.
const WIDTH_SAMPLES: usize = 720;

impl SegmentTable {
    /// The table's horizon: [`Horizon::Finite`] for a table without
    /// periodic walls (a flight is never longer than the table), else
    /// decided as the [module docs](crate::horizon) say.
    ///
    /// # Errors
    /// [`GeometryError::HorizonUndecided`] when the search cannot be
    /// bounded: every connected run of wall is straight (a chain of
    /// segments crossing the cell's sides has no width the search can
    /// use), or more than [`MAX_DIRECTIONS`] lattice directions would need
    /// checking.
    pub fn horizon(&self) -> Result<Horizon, GeometryError> {
        let kinds = self.kinds();
        let shifts: Vec<DVec2> = kinds
            .iter()
            .filter_map(|k| match k {
                WallKind::Periodic { shift, .. } => Some(*shift),
                _ => None,
            })
            .collect();
        let Some([b1, b2]) = self.lattice() else {
            return Ok(Horizon::Finite);
        };
        let walls: Vec<Segment> = self
            .walls()
            .iter()
            .zip(kinds.iter().chain(std::iter::repeat(&WallKind::Reflecting)))
            .filter(|(_, k)| !k.is_periodic())
            .map(|(w, _)| *w)
            .collect();
        let size = b1.length().max(b2.length());
        let tol = MIN_CORRIDOR * size;
        let two_d = shifts
            .iter()
            .any(|s| b1.perp_dot(*s).abs() > 1e-6 * b1.length() * s.length());
        if !two_d {
            return Ok(channel(&walls, b1, tol));
        }
        lattice(&walls, b1, b2, self.slack(), tol)
    }
}

impl Built {
    /// The table's horizon: [`SegmentTable::horizon`] for a table built
    /// from segments; the built-in tables are closed, so
    /// [`Horizon::Finite`].
    ///
    /// # Errors
    /// As [`SegmentTable::horizon`].
    pub fn horizon(&self) -> Result<Horizon, GeometryError> {
        match self {
            Built::Table(_) => Ok(Horizon::Finite),
            Built::Segments(t) => t.horizon(),
        }
    }
}

/// A table periodic along `b` only: the corridor, if any, runs along `b`,
/// in a gap between the walls' shadows (the outermost walls bound the
/// channel, so only gaps between them count).
fn channel(walls: &[Segment], b: DVec2, tol: f64) -> Horizon {
    let along = b.normalize();
    let n = along.perp();
    let mut shadows: Vec<(f64, f64)> = walls.iter().map(|w| shadow(w, n)).collect();
    shadows.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut widest = 0.0f64;
    let mut reach = f64::NEG_INFINITY;
    for &(lo, hi) in &shadows {
        if reach > f64::NEG_INFINITY {
            widest = widest.max(lo - reach);
        }
        reach = reach.max(hi);
    }
    if widest > tol {
        Horizon::Infinite {
            direction: along,
            width: widest,
        }
    } else {
        Horizon::Finite
    }
}

/// A table periodic along two independent vectors: search every lattice
/// direction short enough to hold a corridor; report the widest.
fn lattice(
    walls: &[Segment],
    b1: DVec2,
    b2: DVec2,
    slack: f64,
    tol: f64,
) -> Result<Horizon, GeometryError> {
    let area = b1.perp_dot(b2).abs();
    if walls.is_empty() {
        return Err(GeometryError::HorizonUndecided {
            why: "every wall is periodic: with no scatterer a ball flies straight for ever and there is nothing to diffuse".into(),
        });
    }
    let width = widest_scatterer(walls, slack);
    if width <= tol {
        return Err(GeometryError::HorizonUndecided {
            why: "every connected run of wall is straight, so no scatterer's width bounds the lattice directions to search (give the scatterers some curvature or close them inside the cell)".into(),
        });
    }
    // Shadows at least P = area / |d| wide cover every line along d.
    let longest = area / width;
    let (pmax, qmax) = (
        (longest * b2.length() / area).floor(),
        (longest * b1.length() / area).floor(),
    );
    let count = (2.0 * pmax + 1.0) * (qmax + 1.0);
    if count > MAX_DIRECTIONS as f64 {
        return Err(GeometryError::HorizonUndecided {
            why: format!(
                "corridors could run along lattice vectors up to {longest:.3e} long (the widest scatterer is only {width:.3e} wide); that is about {count:.0} directions, more than {MAX_DIRECTIONS}"
            ),
        });
    }
    let (pmax, qmax) = (pmax as i64, qmax as i64);
    let mut best: Option<(DVec2, f64)> = None;
    for q in 0..=qmax {
        for p in -pmax..=pmax {
            // One of ±d: q > 0, or q = 0 and p = 1.
            if (q == 0 && p != 1) || gcd(p.unsigned_abs(), q.unsigned_abs()) != 1 {
                continue;
            }
            let d = p as f64 * b1 + q as f64 * b2;
            let len = d.length();
            if len > longest {
                continue;
            }
            let gap = widest_gap(walls, d.perp() / len, area / len);
            if gap > tol && best.is_none_or(|(_, w)| gap > w) {
                best = Some((d / len, gap));
            }
        }
    }
    Ok(match best {
        Some((direction, width)) => Horizon::Infinite { direction, width },
        None => Horizon::Finite,
    })
}

/// The widest gap in the union of the walls' shadows on `n`, taken modulo
/// the period `period` (0 when they cover every line).
fn widest_gap(walls: &[Segment], n: DVec2, period: f64) -> f64 {
    // Each shadow on the circle [0, period): one that runs past the end
    // continues from 0.
    let mut shadows = Vec::with_capacity(walls.len() + 4);
    for w in walls {
        let (lo, hi) = shadow(w, n);
        if hi - lo >= period {
            return 0.0;
        }
        let start = lo.rem_euclid(period);
        let end = start + (hi - lo);
        shadows.push((start, end.min(period)));
        if end > period {
            shadows.push((0.0, end - period));
        }
    }
    shadows.sort_by(|a, b| a.0.total_cmp(&b.0));
    let Some(&(first, _)) = shadows.first() else {
        return period;
    };
    let mut widest = 0.0f64;
    let mut reach = first;
    for &(lo, hi) in &shadows {
        widest = widest.max(lo - reach);
        reach = reach.max(hi);
    }
    // Around the circle: from the furthest reach to the first start, one
    // period on.
    widest.max(first + period - reach)
}

/// The shadow `[min, max]` of a wall on the unit vector `n`.
fn shadow(wall: &Segment, n: DVec2) -> (f64, f64) {
    let (a, b) = (n.dot(wall.start()), n.dot(wall.end()));
    let (mut lo, mut hi) = (a.min(b), a.max(b));
    if let Segment::Arc(arc) = wall {
        // The circle's extreme points along ±n, where the arc holds them.
        for sign in [1.0, -1.0] {
            let dir = sign * n;
            if arc.is_full() || holds_angle(arc.start_angle(), arc.sweep(), dir.to_angle()) {
                let x = n.dot(arc.center() + arc.radius() * dir);
                lo = lo.min(x);
                hi = hi.max(x);
            }
        }
    }
    (lo, hi)
}

/// Whether the angle `phi` lies on the arc from `start` through `sweep`
/// (signed: counter-clockwise when positive).
fn holds_angle(start: f64, sweep: f64, phi: f64) -> bool {
    let turn = std::f64::consts::TAU;
    let past = if sweep >= 0.0 {
        (phi - start).rem_euclid(turn)
    } else {
        (start - phi).rem_euclid(turn)
    };
    past <= sweep.abs()
}

/// A lower bound on the smallest width of the widest connected run of wall
/// (walls joined end to end, within `slack`): every lattice direction
/// longer than `area / width` has every line crossing such a run.
fn widest_scatterer(walls: &[Segment], slack: f64) -> f64 {
    // Join walls that share an end (union–find on indices).
    let mut parent: Vec<usize> = (0..walls.len()).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let ends = |w: &Segment| [w.start(), w.end()];
    for i in 0..walls.len() {
        for j in i + 1..walls.len() {
            let touch = ends(&walls[i]).iter().any(|a| {
                ends(&walls[j])
                    .iter()
                    .any(|b| a.distance(*b) <= 4.0 * slack)
            });
            if touch {
                let (ri, rj) = (root(&mut parent, i), root(&mut parent, j));
                parent[ri] = rj;
            }
        }
    }
    let mut best = 0.0f64;
    for r in 0..walls.len() {
        let run: Vec<&Segment> = (0..walls.len())
            .filter(|&i| root(&mut parent, i) == r)
            .map(|i| &walls[i])
            .collect();
        if run.is_empty() {
            continue;
        }
        best = best.max(smallest_width(&run));
    }
    best
}

/// A lower bound on the smallest width of a connected run of walls over all
/// directions: sampled widths less the most a width can change between
/// samples (a width changes no faster than the run's diameter per radian).
fn smallest_width(run: &[&Segment]) -> f64 {
    let step = std::f64::consts::PI / WIDTH_SAMPLES as f64;
    let mut smallest = f64::INFINITY;
    let mut diameter = 0.0f64;
    for k in 0..WIDTH_SAMPLES {
        let n = DVec2::from_angle(k as f64 * step);
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for w in run {
            let (a, b) = shadow(w, n);
            lo = lo.min(a);
            hi = hi.max(b);
        }
        smallest = smallest.min(hi - lo);
        diameter = diameter.max(hi - lo);
    }
    (smallest - diameter * step).max(0.0)
}

fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{LorentzGas, line::LineSegment};

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-9
    }

    /// The closed loop of straight walls through `corners`, in order.
    fn loop_of(corners: &[(f64, f64)]) -> Vec<Segment> {
        let p = |i: usize| {
            let (x, y) = corners[i % corners.len()];
            DVec2::new(x, y)
        };
        (0..corners.len())
            .map(|i| Segment::Line(LineSegment::new(p(i), p(i + 1)).unwrap()))
            .collect()
    }

    const UNIT_SQUARE: [(f64, f64); 4] = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];

    #[test]
    fn the_square_gas_has_its_rows_and_for_small_disks_its_diagonals() {
        // Rows and columns: width w − 2R (the disks' shadows are 2R of the
        // period w); diagonals (1, 1): period w/√2, open while 2R < w/√2.
        for r in [0.1, 0.3, 0.34, 0.36, 0.45, 0.499] {
            let gas = LorentzGas::square(1.0, r).unwrap();
            let h = gas.table().unwrap().horizon().unwrap();
            let Horizon::Infinite { direction, width } = h else {
                panic!("square gas R = {r}: {h:?}");
            };
            assert!(close(width, 1.0 - 2.0 * r), "R = {r}: width {width}");
            assert!(close(direction.x.abs().max(direction.y.abs()), 1.0));
        }
        // The diagonal corridor alone, in the search's gap function.
        let table = LorentzGas::square(1.0, 0.3).unwrap().table().unwrap();
        let walls: Vec<Segment> = table
            .walls()
            .iter()
            .zip(table.kinds())
            .filter(|(_, k)| !k.is_periodic())
            .map(|(w, _)| *w)
            .collect();
        let d = DVec2::new(1.0, 1.0);
        let gap = widest_gap(&walls, d.perp() / d.length(), 1.0 / d.length());
        assert!(close(gap, 0.5f64.sqrt() - 0.6), "diagonal gap {gap}");
        let table = LorentzGas::square(1.0, 0.36).unwrap().table().unwrap();
        let walls: Vec<Segment> = table.walls()[4..].to_vec();
        assert_eq!(
            widest_gap(&walls, d.perp() / d.length(), 1.0 / d.length()),
            0.0
        );
    }

    #[test]
    fn the_triangular_gas_agrees_with_the_closed_form() {
        // Closed form (LorentzGas::horizon): rows of width √3/2·w − 2R,
        // closed from R = √3/4·w ≈ 0.4330; checked away from the boundary
        // by more than the corridor tolerance.
        for i in 1..50 {
            let r = 0.01 * i as f64;
            let gas = LorentzGas::triangular(1.0, r).unwrap();
            let found = gas.table().unwrap().horizon().unwrap();
            match (gas.horizon(), found) {
                (Horizon::Finite, Horizon::Finite) => {}
                (
                    Horizon::Infinite { width: w0, .. },
                    Horizon::Infinite {
                        direction, width, ..
                    },
                ) => {
                    assert!(close(width, w0), "R = {r}: {width} against {w0}");
                    // One of the three row directions (0°, 60°, 120°).
                    let angle = direction.to_angle().rem_euclid(std::f64::consts::PI / 3.0);
                    assert!(!(1e-9..=std::f64::consts::PI / 3.0 - 1e-9).contains(&angle));
                }
                (want, got) => panic!("R = {r}: closed form {want:?}, detected {got:?}"),
            }
        }
    }

    #[test]
    fn a_channel_has_its_corridor_along_it_unless_a_baffle_closes_it() {
        let p = DVec2::new;
        // A strip 0 ≤ y ≤ 1 with a disk of radius 0.2 at (0.5, 0.5): two
        // corridors of width 0.3 along x.
        let outer = loop_of(&UNIT_SQUARE);
        let disk = crate::ArcSegment::new(p(0.5, 0.5), 0.2, 0.0, -std::f64::consts::TAU).unwrap();
        let strip = SegmentTable::with_holes(outer.clone(), vec![vec![Segment::Arc(disk)]])
            .unwrap()
            .with_periodic(1, 3)
            .unwrap();
        let Horizon::Infinite { direction, width } = strip.horizon().unwrap() else {
            panic!("the strip has corridors");
        };
        assert!(close(width, 0.3) && close(direction.y, 0.0));
        // A disk of radius 0.45 leaves gaps of 0.05: still open; closed
        // tables are finite.
        let big = crate::ArcSegment::new(p(0.5, 0.5), 0.45, 0.0, -std::f64::consts::TAU).unwrap();
        let narrow = SegmentTable::with_holes(outer.clone(), vec![vec![Segment::Arc(big)]])
            .unwrap()
            .with_periodic(1, 3)
            .unwrap();
        assert!(
            matches!(narrow.horizon().unwrap(), Horizon::Infinite { width, .. } if close(width, 0.05))
        );
        let closed = SegmentTable::with_holes(outer, vec![vec![Segment::Arc(big)]]).unwrap();
        assert_eq!(closed.horizon().unwrap(), Horizon::Finite);
        assert_eq!(
            Built::Table(crate::Table::Circle(crate::Circle::unit()))
                .horizon()
                .unwrap(),
            Horizon::Finite
        );
    }

    #[test]
    fn a_square_scatterer_in_a_square_cell() {
        // Cell [0, 1]² with an axis-aligned square obstacle of side s at its
        // centre: rows open (width 1 − s); a straight-walled obstacle closed
        // inside the cell has a width (s), so the search is bounded.
        let outer = loop_of(&UNIT_SQUARE);
        let (a, b) = (0.3, 0.7);
        // Clockwise: the table lies outside the obstacle.
        let obstacle = loop_of(&[(a, a), (a, b), (b, b), (b, a)]);
        let table = SegmentTable::with_holes(outer, vec![obstacle])
            .unwrap()
            .with_periodic(0, 2)
            .unwrap()
            .with_periodic(1, 3)
            .unwrap();
        let Horizon::Infinite { width, .. } = table.horizon().unwrap() else {
            panic!("rows are open");
        };
        assert!(close(width, 0.6), "width {width}");
    }

    #[test]
    fn straight_walls_crossing_the_cell_leave_the_search_unbounded() {
        // A cell whose scatterers are two straight cuts at its corners,
        // each ending on a periodic side (in the plane they join their
        // neighbours' cuts): no run of wall inside the cell has a width to
        // bound the search, so an error, never a guess.
        let cell = loop_of(&[
            (0.0, 0.0),
            (0.8, 0.0),
            (1.0, 0.2),
            (1.0, 1.0),
            (0.2, 1.0),
            (0.0, 0.8),
        ]);
        let table = SegmentTable::new(cell)
            .unwrap()
            .with_periodic(0, 3)
            .unwrap()
            .with_periodic(2, 5)
            .unwrap();
        let err = table.horizon().unwrap_err();
        assert!(
            matches!(&err, GeometryError::HorizonUndecided { why } if why.contains("straight")),
            "{err}"
        );
    }
}
