//! The Birkhoff section of a spinning billiard: where each collision happens
//! and how the ball arrives, the coordinates in which islands are drawn.
//!
//! Documented in the group docs (`phase_space/mod.rs`), section "The Birkhoff section".

use std::ops::Range;

use spinball_core::{Billiard, Collision, Observer, Sampler, SpinLaw, State};
use spinball_geometry::{Boundary, WallId};

use crate::error::AnalysisError;
use crate::run::{Threads, map_indices};

/// One collision as a point of the section.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SectionPoint {
    /// Birkhoff arc length of the contact.
    pub s: f64,
    /// The wall hit.
    pub wall: WallId,
    /// Tangential velocity `v∥ = v·t̂` just before the collision.
    pub v_par: f64,
    /// Translational speed `|v|` just before the collision.
    pub speed: f64,
    /// Spin `u` just before the collision.
    pub spin: f64,
    /// `Q = v∥ − αu` (unchanged by the collision).
    pub q: f64,
}

impl SectionPoint {
    /// The point of `collision`, which left the ball in `after` (the normal
    /// velocity only changes sign, so `after` gives `|v|` before).
    #[must_use]
    #[inline]
    pub fn of(collision: &Collision, after: &State) -> Self {
        let v_perp = after.velocity.dot(collision.hit.normal);
        let v_par = collision.v_par_before;
        SectionPoint {
            s: collision.hit.s(),
            wall: collision.wall(),
            v_par,
            speed: (v_par * v_par + v_perp * v_perp).sqrt(),
            spin: collision.spin_before,
            q: collision.q,
        }
    }

    /// `sin θ = v∥/|v|`, the sine of the angle of incidence (the vertical
    /// coordinate of the classical Birkhoff section).
    #[must_use]
    #[inline]
    pub fn sin_theta(&self) -> f64 {
        self.v_par / self.speed
    }

    /// `w = √α u`, the spin in the units where the collision is a rotation
    /// of `V = (v, w)` and `|V|² = 2E`.
    #[must_use]
    #[inline]
    pub fn w(&self, alpha: f64) -> f64 {
        alpha.sqrt() * self.spin
    }

    /// `(v∥, w)/|V|`: the point in the unit disk on which the invariant
    /// measure is uniform ([`InvariantMeasure`](crate::phase_space::InvariantMeasure)).
    #[must_use]
    #[inline]
    pub fn disk(&self, alpha: f64) -> (f64, f64) {
        let w = self.w(alpha);
        let norm = (self.speed * self.speed + w * w).sqrt();
        (self.v_par / norm, w / norm)
    }
}

/// An [`Observer`] that hands each collision to `sink` as a
/// [`SectionPoint`]; it keeps nothing itself.
///
/// ```
/// use spinball_analysis::phase_space::{Section, SectionPoint};
/// use spinball_core::{Billiard, SpinLaw, State};
/// use spinball_geometry::{DVec2, Stadium};
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?);
/// let mut ball = billiard.launch(State::new(DVec2::ZERO, DVec2::new(0.6, 0.7), 0.3))?;
/// // Count the collisions that arrive at less than 30° from the normal.
/// let mut steep = 0;
/// let mut section = Section::new(|p: SectionPoint| steep += usize::from(p.sin_theta().abs() < 0.5));
/// billiard.run(&mut ball, 1000, &mut section)?;
/// assert!(steep > 0 && steep < 1000);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Section<F> {
    sink: F,
}

impl<F: FnMut(SectionPoint)> Section<F> {
    /// An observer that calls `sink` with every collision's point.
    #[must_use]
    pub fn new(sink: F) -> Self {
        Section { sink }
    }
}

impl<F: FnMut(SectionPoint)> Observer for Section<F> {
    #[inline]
    fn observe(&mut self, collision: &Collision, after: &State) {
        (self.sink)(SectionPoint::of(collision, after));
    }
}

/// The section points of the first `collisions` collisions from `start`.
///
/// # Errors
/// The launch error, or the first step error.
pub fn section_points<B: Boundary>(
    billiard: &Billiard<B>,
    start: State,
    collisions: u64,
) -> Result<Vec<SectionPoint>, AnalysisError> {
    let mut ball = billiard.launch(start)?;
    let mut points = Vec::with_capacity(usize::try_from(collisions).unwrap_or(0).min(1 << 24));
    billiard.run(&mut ball, collisions, &mut Section::new(|p| points.push(p)))?;
    Ok(points)
}

/// [`section_points`] for each of `starts` (in order) on `threads`.
///
/// # Errors
/// The first failing start's error, tagged with its position in `starts`.
pub fn sections<B: Boundary + Sync>(
    billiard: &Billiard<B>,
    starts: &[State],
    collisions: u64,
    threads: Threads,
) -> Result<Vec<Vec<SectionPoint>>, AnalysisError> {
    let range: Range<u64> = 0..starts.len() as u64;
    map_indices(range, threads, |i| {
        section_points(billiard, starts[i as usize], collisions).map_err(|e| e.at_index(i))
    })
}

/// [`sections`] of the orbits `indices` drawn by `sampler`, orbit `i` from
/// `ic_rng(seed, i)` as [`Ensemble`](crate::run::Ensemble) draws its initial
/// conditions: the section points of a few typical orbits, as a
/// Poincaré-section figure shows them.
///
/// # Errors
/// As [`sections`].
pub fn sampled_sections<B: Boundary + Sync>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    indices: Range<u64>,
    collisions: u64,
    threads: Threads,
) -> Result<Vec<Vec<SectionPoint>>, AnalysisError> {
    let (table, law) = (billiard.table(), billiard.law());
    let starts = indices
        .map(|i| sampler.try_initial_state(table, law, seed, i))
        .collect::<Result<Vec<State>, _>>()?;
    sections(billiard, &starts, collisions, threads)
}

/// The names of the columns of [`section_rows`]: the orbit, then the
/// coordinates of the point (`sin_theta = v∥/|v|`, `u` the spin, `wall`
/// the index of the wall hit), all just before the collision.
pub const SECTION_COLUMNS: [&str; 8] = [
    "orbit",
    "s",
    "sin_theta",
    "v_par",
    "speed",
    "u",
    "wall",
    "q",
];

/// The points of `orbits` (orbit indices `first`, `first + 1`, …) as rows
/// of [`SECTION_COLUMNS`], orbit by orbit in collision order; `keep`
/// selects the points (`|_| true` for all, or a spin slice, as
/// [`spin_slice`]). The table a front writes as CSV or NPY, or hands to
/// NumPy; the rows of a shard's orbits are those of the whole run.
#[must_use]
pub fn section_rows(
    orbits: &[Vec<SectionPoint>],
    first: u64,
    keep: impl Fn(&SectionPoint) -> bool,
) -> Vec<[f64; 8]> {
    orbits
        .iter()
        .zip(first..)
        .flat_map(|(orbit, k)| orbit.iter().map(move |p| (k, p)))
        .filter(|(_, p)| keep(p))
        .map(|(k, p)| {
            [
                k as f64,
                p.s,
                p.sin_theta(),
                p.v_par,
                p.speed,
                p.spin,
                f64::from(p.wall),
                p.q,
            ]
        })
        .collect()
}

/// The points of `orbits` in the slice `|√α u| < half_width` of the spin
/// (`√α u` is the spin's share of `|V|`, so the slice is the same fraction
/// of the shell at every α), in orbit order: the two-dimensional section
/// near zero spin, where the specular billiard's section is.
#[must_use]
pub fn spin_slice(orbits: &[Vec<SectionPoint>], alpha: f64, half_width: f64) -> Vec<SectionPoint> {
    orbits
        .iter()
        .flatten()
        .filter(|p| p.w(alpha).abs() < half_width)
        .copied()
        .collect()
}

/// A ball on the wall of `table` at arc length `s`, leaving it with
/// tangential velocity `v_par` and spin `spin`, on the paper's energy shell
/// `|V|² = |v|² + αu² = 1` (`E = ½`): the normal velocity is
/// `√(1 − v∥² − αu²)`, pointing into the table. It is the state right after
/// a collision at `s`, so the next step of the collision map starts there.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for a non-finite input, a table that
/// cannot place points by arc length ([`Boundary::hit_at`] is `None`), or
/// `v∥² + αu² >= 1` (no energy left for the normal velocity).
pub fn state_on_section<B: Boundary + ?Sized>(
    table: &B,
    law: &SpinLaw,
    s: f64,
    v_par: f64,
    spin: f64,
) -> Result<State, AnalysisError> {
    if !(s.is_finite() && v_par.is_finite() && spin.is_finite()) {
        return Err(AnalysisError::invalid(
            "section point",
            format!("needs finite (s, v∥, u), got ({s}, {v_par}, {spin})"),
        ));
    }
    let alpha = law.alpha();
    let rest = 1.0 - v_par * v_par - alpha * spin * spin;
    if rest <= 0.0 {
        return Err(AnalysisError::invalid(
            "section point",
            format!(
                "v∥² + αu² = {} leaves no normal velocity on the shell |V| = 1 (need < 1)",
                1.0 - rest
            ),
        ));
    }
    let hit = table.hit_at(s).ok_or_else(|| {
        AnalysisError::invalid(
            "table",
            "cannot place a point by arc length (Boundary::hit_at is None); \
             use a built-in table or a SegmentTable",
        )
    })?;
    let velocity = hit.tangent() * v_par + hit.normal * rest.sqrt();
    Ok(State::new(hit.point, velocity, spin))
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_geometry::{DVec2, Rectangle, Stadium};

    #[test]
    fn off_shell_and_non_finite_points_are_refused() {
        let table = Stadium::new(1.0).unwrap();
        let law = SpinLaw::new(0.5).unwrap();
        assert!(state_on_section(&table, &law, 1.0, 0.9, 0.8).is_err());
        assert!(state_on_section(&table, &law, f64::NAN, 0.1, 0.0).is_err());
        let s = state_on_section(&table, &law, 1.0, 0.3, 0.4).unwrap();
        assert!((s.energy(&law) - 0.5).abs() < 1e-15);
        assert_eq!(s.position, DVec2::new(0.0, -1.0));
        assert!(s.velocity.y > 0.0);
    }

    #[test]
    fn section_points_see_the_incoming_speed() {
        let billiard = Billiard::new(
            Rectangle::new(1.5, 1.0).unwrap(),
            SpinLaw::new(0.4).unwrap(),
        );
        let start = State::new(DVec2::ZERO, DVec2::new(0.5, 0.6), 0.7);
        let points = section_points(&billiard, start, 200).unwrap();
        let shell = start.energy(billiard.law());
        for p in &points {
            let e = 0.5 * (p.speed * p.speed + 0.4 * p.spin * p.spin);
            assert!((e - shell).abs() < 1e-14);
            let (x, y) = p.disk(0.4);
            assert!(x * x + y * y <= 1.0 + 1e-14 && p.sin_theta().abs() <= 1.0);
        }
    }

    #[test]
    fn sampled_circle_orbits_keep_their_angle_and_slices_cut_the_spin() {
        use spinball_geometry::Circle;
        // In the specular circle every collision of an orbit has the same
        // angle of incidence (angular momentum is conserved).
        let billiard = Billiard::new(Circle::unit(), SpinLaw::specular());
        let orbits =
            sampled_sections(&billiard, Sampler::Paper, 4, 0..3, 50, Threads::Fixed(1)).unwrap();
        assert_eq!(orbits.len(), 3);
        for orbit in &orbits {
            assert_eq!(orbit.len(), 50);
            let first = orbit[0].sin_theta();
            assert!(orbit.iter().all(|p| (p.sin_theta() - first).abs() < 1e-12));
        }
        assert_ne!(orbits[0][0].sin_theta(), orbits[1][0].sin_theta());
        // With spin: the slice keeps exactly the points with |√α u| < 0.2.
        let spinning = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let orbits =
            sampled_sections(&spinning, Sampler::Paper, 4, 0..4, 500, Threads::Fixed(1)).unwrap();
        let slice = spin_slice(&orbits, 0.5, 0.2);
        let inside = orbits
            .iter()
            .flatten()
            .filter(|p| (0.5f64.sqrt() * p.spin).abs() < 0.2);
        assert_eq!(slice.len(), inside.count());
        assert!(!slice.is_empty() && slice.len() < 2000);
        // |√α u| ≤ |V| = 1 on the paper's shell: a slice of half-width 1.01
        // keeps every point.
        assert_eq!(spin_slice(&orbits, 0.5, 1.01).len(), 2000);
        // The rows of the slice are its points, tagged by orbit.
        let rows = section_rows(&orbits, 0, |p| (0.5f64.sqrt() * p.spin).abs() < 0.2);
        assert_eq!(rows.len(), slice.len());
        assert!(
            rows.iter()
                .zip(&slice)
                .all(|(r, p)| r[1] == p.s && r[5] == p.spin)
        );
        assert!(
            rows.windows(2).all(|w| w[0][0] <= w[1][0]) && rows[0].len() == SECTION_COLUMNS.len()
        );
    }
}
