//! Newton's method on `F^p(z) − z` in Birkhoff coordinates, with the exact
//! tangent map as its Jacobian: one periodic orbit from one start.
//!
//! Documented in the group docs (`orbits/mod.rs`), section "Newton's method".

use spinball_core::Billiard;
use spinball_geometry::{Boundary, WallId};

use super::birkhoff_map::{BirkhoffPoint, Iterate, iterate};
use super::matrix::{IDENTITY, solve_least_squares};
use super::stability::{DEFAULT_CLASS_TOLERANCE, Stability};
use crate::error::AnalysisError;

/// Options of the Newton iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NewtonOptions {
    /// The orbit is closed when every component of `F^p(z) − z` is at most
    /// this (`s` in units of the table's `unit_length`). Default `1e-12`.
    pub tolerance: f64,
    /// Newton steps before giving up. Default 60.
    pub max_iterations: u32,
    /// Singular values of `M − I` below this times the largest are treated
    /// as zero (the direction along a family of orbits). Default `1e-9`.
    pub singular_cutoff: f64,
    /// Orbits with a collision at `|v⊥|/|v|` below this, or a flight
    /// shorter than this times the table's `unit_length` (through a corner),
    /// are refused (the map is not smooth there). Default `1e-6`.
    pub min_cos: f64,
    /// Tolerance of the stability class ([`Stability::classify`]).
    pub class_tolerance: f64,
}

impl Default for NewtonOptions {
    fn default() -> Self {
        NewtonOptions {
            tolerance: 1e-12,
            max_iterations: 60,
            singular_cutoff: 1e-9,
            min_cos: 1e-6,
            class_tolerance: DEFAULT_CLASS_TOLERANCE,
        }
    }
}

impl NewtonOptions {
    fn validate(&self) -> Result<(), AnalysisError> {
        let positive = |name: &'static str, x: f64, max: f64| {
            if x > 0.0 && x < max {
                Ok(())
            } else {
                Err(AnalysisError::invalid(
                    name,
                    format!("must be in (0, {max}), got {x}"),
                ))
            }
        };
        positive("tolerance", self.tolerance, 1e-2)?;
        positive("singular_cutoff", self.singular_cutoff, 1e-2)?;
        positive("min_cos", self.min_cos, 1.0)?;
        positive("class_tolerance", self.class_tolerance, 1.0)?;
        if self.max_iterations == 0 {
            return Err(AnalysisError::invalid(
                "max_iterations",
                "must be at least 1",
            ));
        }
        Ok(())
    }
}

/// A periodic orbit of the collision map with its stability.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PeriodicOrbit {
    /// The spin parameter.
    pub alpha: f64,
    /// Collisions per period.
    pub period: u32,
    /// The `period` points after each collision, starting from the one with
    /// the smallest `s` (so the same orbit found from any phase reads the same).
    pub points: Vec<BirkhoffPoint>,
    /// The wall of each collision, in the same order.
    pub walls: Vec<WallId>,
    /// Largest component of `F^p(z) − z` at `points[0]`.
    pub residual: f64,
    /// Newton steps taken.
    pub iterations: u32,
    /// Smallest `|v⊥|/|v|` of its collisions.
    pub min_cos: f64,
    /// The monodromy, multipliers and class.
    pub stability: Stability,
}

impl PeriodicOrbit {
    /// Whether `other` is the same orbit to `tolerance` in every coordinate
    /// of every point (`s` modulo `perimeter`), whatever phase either starts at.
    #[must_use]
    pub fn same_as(&self, other: &PeriodicOrbit, perimeter: f64, tolerance: f64) -> bool {
        self.period == other.period
            && (0..self.points.len()).any(|shift| {
                self.points.iter().enumerate().all(|(i, a)| {
                    let b = other.points[(i + shift) % other.points.len()];
                    close(a, &b, perimeter, tolerance)
                })
            })
    }
}

impl PeriodicOrbit {
    /// The smallest `q` dividing the period after which the orbit repeats
    /// its points to `tolerance`.
    #[must_use]
    pub fn prime_period(&self, perimeter: f64, tolerance: f64) -> u32 {
        let p = self.points.len();
        (1..p)
            .filter(|&q| p.is_multiple_of(q))
            .find(|&q| {
                (0..p).all(|i| {
                    close(
                        &self.points[i],
                        &self.points[(i + q) % p],
                        perimeter,
                        tolerance,
                    )
                })
            })
            .map_or(self.period, |q| q as u32)
    }
}

/// Whether two points agree to `tolerance` in every coordinate (`s`
/// modulo `perimeter`).
fn close(a: &BirkhoffPoint, b: &BirkhoffPoint, perimeter: f64, tolerance: f64) -> bool {
    wrap(a.s - b.s, perimeter).abs() <= tolerance
        && (a.v_par - b.v_par).abs() <= tolerance
        && (a.spin - b.spin).abs() <= tolerance
}

/// `d` wrapped into `[−P/2, P/2)`.
fn wrap(d: f64, perimeter: f64) -> f64 {
    d - perimeter * (d / perimeter).round()
}

/// The residual `F^p(z) − z` (`s` wrapped and in units of `unit`) and its
/// largest component.
fn residual(z: &BirkhoffPoint, image: &BirkhoffPoint, perimeter: f64) -> [f64; 3] {
    [
        wrap(image.s - z.s, perimeter),
        image.v_par - z.v_par,
        image.spin - z.spin,
    ]
}

fn size(g: &[f64; 3], unit: f64) -> f64 {
    (g[0] / unit).abs().max(g[1].abs()).max(g[2].abs())
}

/// The periodic orbit of `period` collisions nearest `start`, by Newton's
/// method on `F^p(z) − z` with the exact Jacobian `M − I` (a minimum-norm
/// least-squares step, so a family of orbits, where `M − I` is singular,
/// does not stop it) and step halving when a step does not reduce the
/// residual.
///
/// # Errors
/// [`AnalysisError::NotClosed`] with the residual if it does not close to
/// `options.tolerance`, or closes on a grazing orbit;
/// [`AnalysisError::InvalidOption`] for a bad option, a start off the
/// shell or a table without [`Boundary::hit_at`]; a step error.
pub fn find_orbit<B: Boundary>(
    billiard: &Billiard<B>,
    start: BirkhoffPoint,
    period: u32,
    options: &NewtonOptions,
) -> Result<PeriodicOrbit, AnalysisError> {
    options.validate()?;
    if period == 0 {
        return Err(AnalysisError::invalid("period", "must be at least 1"));
    }
    let (z, it, r, iterations) = newton(billiard, start, period, options, 0)?;
    // Start from the point of smallest s, closed again there: the residual
    // of an image is the start's times the Jacobian of the part of the
    // period in between, so it is polished rather than trusted.
    let perimeter = billiard.table().perimeter();
    let p = period as usize;
    let orbit: Vec<BirkhoffPoint> = (0..p)
        .map(|i| if i == 0 { z } else { it.points[i - 1] })
        .collect();
    let first = (0..p)
        .min_by(|&a, &b| {
            orbit[a]
                .s
                .rem_euclid(perimeter)
                .total_cmp(&orbit[b].s.rem_euclid(perimeter))
        })
        .unwrap_or(0);
    let (z, it, r, iterations) = if first == 0 {
        (z, it, r, iterations)
    } else {
        newton(billiard, orbit[first], period, options, iterations)?
    };
    // A grazing collision or a zero-length flight (through a corner) is
    // where the map is not smooth: what Newton closed there is no orbit.
    if it.min_cos < options.min_cos || it.min_flight < options.min_cos {
        return Err(not_closed(period, iterations, r, options));
    }
    let mut points: Vec<BirkhoffPoint> = (0..p)
        .map(|i| if i == 0 { z } else { it.points[i - 1] })
        .collect();
    for q in &mut points {
        q.s = q.s.rem_euclid(perimeter);
    }
    let walls = (0..p).map(|i| it.walls[(i + p - 1) % p]).collect();
    Ok(PeriodicOrbit {
        alpha: billiard.law().alpha(),
        period,
        points,
        walls,
        residual: r,
        iterations,
        min_cos: it.min_cos,
        stability: Stability::classify(it.jacobian, options.class_tolerance),
    })
}

fn not_closed(
    period: u32,
    iterations: u32,
    residual: f64,
    options: &NewtonOptions,
) -> AnalysisError {
    AnalysisError::NotClosed {
        period,
        iterations,
        residual,
        tolerance: options.tolerance,
    }
}

/// The Newton iteration from `start`: the point reached, its iterate, its
/// residual and the total count of steps (`taken` before this call).
fn newton<B: Boundary>(
    billiard: &Billiard<B>,
    start: BirkhoffPoint,
    period: u32,
    options: &NewtonOptions,
    taken: u32,
) -> Result<(BirkhoffPoint, Iterate, f64, u32), AnalysisError> {
    let table = billiard.table();
    let perimeter = table.perimeter();
    let unit = table.unit_length();
    let mut z = start;
    let mut it = iterate(billiard, z, period)?;
    let mut g = residual(&z, &it.points[it.points.len() - 1], perimeter);
    let mut r = size(&g, unit);
    let mut iterations = taken;
    while r > options.tolerance {
        if iterations >= taken + options.max_iterations {
            return Err(not_closed(period, iterations, r, options));
        }
        iterations += 1;
        let a: [[f64; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|j| it.jacobian[i][j] - IDENTITY[i][j]));
        let (step, _) = solve_least_squares(&a, [-g[0], -g[1], -g[2]], options.singular_cutoff);
        let mut lambda = 1.0;
        let mut accepted = false;
        for _ in 0..30 {
            let trial = BirkhoffPoint::new(
                z.s + lambda * step[0],
                z.v_par + lambda * step[1],
                z.spin + lambda * step[2],
            );
            if let Ok(next) = iterate(billiard, trial, period) {
                let gn = residual(&trial, &next.points[next.points.len() - 1], perimeter);
                let rn = size(&gn, unit);
                if rn < r {
                    (z, it, g, r) = (trial, next, gn, rn);
                    accepted = true;
                    break;
                }
            }
            lambda *= 0.5;
        }
        if !accepted {
            return Err(not_closed(period, iterations, r, options));
        }
    }
    Ok((z, it, r, iterations))
}
