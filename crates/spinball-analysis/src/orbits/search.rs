//! All periodic orbits of one period a set of starts leads to: seeds from
//! normal incidence and from a grid, Newton from each, duplicates removed.
//!
//! Documented in the group docs (`orbits/mod.rs`), section "Seeds".

use spinball_core::Billiard;
use spinball_geometry::Boundary;

use super::birkhoff_map::{BirkhoffPoint, iterate};
use super::finder::{NewtonOptions, PeriodicOrbit, find_orbit};
use crate::error::AnalysisError;

/// Which starts the search runs Newton from.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SearchOptions {
    /// Arc-length samples of the normal-incidence scan (0: no such seeds).
    /// Default 4096.
    pub normal_samples: u32,
    /// Grid of starts `(s, sin θ, √α u)`: samples of `s`, of `sin θ` in
    /// `(−1, 1)`, of `√α u` in `(−½, ½)` (one sample, `u = 0`, at α = 0).
    /// Default `[0, 0, 0]`: normal-incidence seeds only.
    pub grid: [u32; 3],
    /// Two orbits are the same when all their points agree to this.
    /// Default `1e-8`.
    pub dedup_tolerance: f64,
    /// The Newton iteration.
    pub newton: NewtonOptions,
}

impl Default for SearchOptions {
    fn default() -> Self {
        SearchOptions {
            normal_samples: 4096,
            grid: [0, 0, 0],
            dedup_tolerance: 1e-8,
            newton: NewtonOptions::default(),
        }
    }
}

/// Starts `(s, 0, 0)` of orbits that leave a wall along its normal and,
/// `period/2` collisions later, arrive with `Q = v∥ − αu = 0`: by
/// time-reversal symmetry such an orbit retraces itself, so it is periodic
/// with `period` collisions (for `period = 2`: it hits the second wall along
/// its normal too). Found by scanning `s` on `samples` points for a change of
/// sign of that `Q` between neighbours that hit the same walls, refined by
/// bisection; a run of samples where `Q` vanishes identically (a family of
/// normal orbits, as between two facing flats) gives one seed, at its
/// middle, once for the two walls the family joins.
/// Empty for odd periods.
///
/// # Errors
/// A table without [`Boundary::hit_at`].
pub fn normal_seeds<B: Boundary>(
    billiard: &Billiard<B>,
    period: u32,
    samples: u32,
) -> Result<Vec<BirkhoffPoint>, AnalysisError> {
    if period % 2 == 1 || period == 0 || samples == 0 {
        return Ok(Vec::new());
    }
    let half = period / 2;
    let perimeter = billiard.table().perimeter();
    let alpha = billiard.law().alpha();
    // Q on arrival at the half-period collision, and the walls on the way.
    let probe = |s: f64| -> Option<(f64, Vec<u32>)> {
        let it = iterate(billiard, BirkhoffPoint::normal(s), half).ok()?;
        let last = it.points[it.points.len() - 1];
        // Q is the same before and after a collision.
        Some((last.v_par - alpha * last.spin, it.walls))
    };
    let ds = perimeter / f64::from(samples);
    let scan: Vec<Option<(f64, Vec<u32>)>> = (0..samples)
        .map(|i| probe((f64::from(i) + 0.5) * ds))
        .collect();
    // |Q| below this counts as zero (the rounding of a cast is ~1e-15).
    let zero = 1e-11;
    let mut seeds = Vec::new();
    let mut runs: Vec<(f64, f64)> = Vec::new();
    let mut i = 0usize;
    let n = scan.len();
    while i < n {
        let Some((q, walls)) = &scan[i] else {
            i += 1;
            continue;
        };
        if q.abs() <= zero {
            // A run of exact zeros: one seed at its middle.
            let mut j = i;
            while j + 1 < n
                && matches!(&scan[j + 1], Some((q2, w2)) if q2.abs() <= zero && w2 == walls)
            {
                j += 1;
            }
            let (lo, hi) = (i as f64 * ds, (j + 1) as f64 * ds);
            let seed = BirkhoffPoint::normal(0.5 * (lo + hi));
            // The same family seen from its other wall: skip it.
            let seen = iterate(billiard, seed, period).is_ok_and(|it| {
                it.points
                    .iter()
                    .any(|p| runs.iter().any(|&(a, b)| (a..=b).contains(&p.s)))
            });
            if !seen {
                seeds.push(seed);
            }
            runs.push((lo, hi));
            i = j + 1;
            continue;
        }
        if let Some(Some((q2, walls2))) = scan.get(i + 1)
            && walls2 == walls
            && q2.abs() > zero
            && q.signum() != q2.signum()
        {
            let (mut lo, mut hi) = ((i as f64 + 0.5) * ds, (i as f64 + 1.5) * ds);
            let q_lo = *q;
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                match probe(mid) {
                    Some((qm, wm)) if wm == *walls => {
                        if qm.signum() == q_lo.signum() {
                            lo = mid;
                        } else {
                            hi = mid;
                        }
                    }
                    _ => break,
                }
            }
            seeds.push(BirkhoffPoint::normal(0.5 * (lo + hi)));
        }
        i += 1;
    }
    Ok(seeds)
}

/// Grid starts `(s, sin θ, √α u)` at cell centres (see
/// [`SearchOptions::grid`]), on the shell `|V| = 1`.
#[must_use]
pub fn grid_seeds<B: Boundary>(billiard: &Billiard<B>, grid: [u32; 3]) -> Vec<BirkhoffPoint> {
    let perimeter = billiard.table().perimeter();
    let alpha = billiard.law().alpha();
    let [ns, nv, nw] = grid;
    let nw = if alpha > 0.0 { nw } else { nw.min(1) };
    let centre = |i: u32, n: u32| (f64::from(i) + 0.5) / f64::from(n);
    let mut seeds = Vec::new();
    for iw in 0..nw {
        let w = if alpha > 0.0 {
            centre(iw, nw) - 0.5
        } else {
            0.0
        };
        let speed = (1.0 - w * w).sqrt();
        for iv in 0..nv {
            let sin_theta = 2.0 * centre(iv, nv) - 1.0;
            for is in 0..ns {
                let spin = if alpha > 0.0 { w / alpha.sqrt() } else { 0.0 };
                seeds.push(BirkhoffPoint::new(
                    centre(is, ns) * perimeter,
                    sin_theta * speed,
                    spin,
                ));
            }
        }
    }
    seeds
}

/// The periodic orbits of `period` collisions reached by Newton's method
/// from [`normal_seeds`] and [`grid_seeds`], each once (found from
/// several starts or phases, kept once: [`PeriodicOrbit::same_as`]; an
/// orbit of a shorter period run several times is left out), in the
/// order of their first `s`. Starts from which Newton does not close are
/// skipped; the count of them is returned beside the orbits.
///
/// At α > 0 symmetric orbits of even period come in one-parameter families
/// (see the group docs), so grid starts may land on several members of one
/// family; the normal-incidence seeds land on the member with `v∥ = u = 0`.
///
/// # Errors
/// A bad option or a table without [`Boundary::hit_at`].
pub fn periodic_orbits<B: Boundary>(
    billiard: &Billiard<B>,
    period: u32,
    options: &SearchOptions,
) -> Result<(Vec<PeriodicOrbit>, usize), AnalysisError> {
    if period == 0 {
        return Err(AnalysisError::invalid("period", "must be at least 1"));
    }
    if !(options.dedup_tolerance > 0.0 && options.dedup_tolerance < 1.0) {
        return Err(AnalysisError::invalid(
            "dedup_tolerance",
            format!("must be in (0, 1), got {}", options.dedup_tolerance),
        ));
    }
    if billiard.table().hit_at(0.0).is_none() {
        return Err(AnalysisError::invalid(
            "table",
            "cannot place a point by arc length (Boundary::hit_at is None); use a built-in table or a SegmentTable",
        ));
    }
    let mut seeds = normal_seeds(billiard, period, options.normal_samples)?;
    seeds.extend(grid_seeds(billiard, options.grid));
    let perimeter = billiard.table().perimeter();
    let mut orbits: Vec<PeriodicOrbit> = Vec::new();
    let mut failed = 0;
    for seed in seeds {
        match find_orbit(billiard, seed, period, &options.newton) {
            // A shorter orbit run several times: not of this period.
            Ok(orbit) if orbit.prime_period(perimeter, options.dedup_tolerance) < period => {}
            Ok(orbit) => {
                if !orbits
                    .iter()
                    .any(|o| o.same_as(&orbit, perimeter, options.dedup_tolerance))
                {
                    orbits.push(orbit);
                }
            }
            Err(AnalysisError::InvalidOption { name, reason }) if name != "section point" => {
                return Err(AnalysisError::InvalidOption { name, reason });
            }
            Err(_) => failed += 1,
        }
    }
    orbits.sort_by(|a, b| a.points[0].s.total_cmp(&b.points[0].s));
    Ok((orbits, failed))
}
