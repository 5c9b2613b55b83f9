//! Balls that fly through a finite-horizon lattice in a straight line.
//!
//! A finite horizon bounds every free flight, but not every trajectory: a
//! stable periodic orbit that comes back to itself one lattice vector on
//! (an "accelerator mode"; the rough ball's spin makes them) carries its
//! ball ballistically, `|Δr| ∝ t`. One such ball in an ensemble makes
//! `⟨Δr²⟩` grow like `t²`: there is no finite diffusion coefficient, and a
//! fitted `D` (with its large error) would be a number that is not one.
//!
//! The check asks each ball's own path whether it moves at a constant
//! velocity over the fit window. With the window's checkpoints `t_0 < … <
//! t_K`, the increments `Δ_k = Δr(t_k) − Δr(t_{k−1})` over `τ_k = t_k −
//! t_{k−1}`, the velocity `v = ΣΔ_k / Στ_k` and the residual
//! `ρ = Σ |Δ_k − v τ_k|² / τ_k`, the statistic is
//!
//! `R = ρ / (|v|² Στ_k)`.
//!
//! A ballistic ball's increments differ only by where in the cell it sits
//! (`ρ` bounded while `|v|² Στ` grows with the window): `R → 0`. A
//! diffusing ball's increments are independent with variance `∝ τ_k`, so
//! `R` is a ratio of a `χ²` with `2(K − 1)` degrees of freedom to one with
//! 2, and `P(R < r) ≈ r^{K−1}` for small `r`: below [`MAX_RESIDUAL`]
//! (`0.02`) with at least [`MIN_INCREMENTS`] increments a diffusing ball
//! is called ballistic with probability below `1e-5` (`4·10⁻⁹` at the
//! default windows' six increments). Windows with fewer increments are not
//! checked.
//!
//! It is applied to finite-horizon tables only: with an infinite horizon a
//! ball flying along a corridor is ballistic for as long as its flight, and
//! the marginal law already accounts for such flights.

use super::Displacements;

/// Largest `R` (residual of the constant-velocity fit over its explained
/// part) of a ballistic ball.
pub const MAX_RESIDUAL: f64 = 0.02;

/// Fewest increments (checkpoints in the window, less one) for the check.
pub const MIN_INCREMENTS: usize = 4;

/// The balls of an ensemble that travel ballistically over a fit window.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct Ballistic {
    /// How many balls travel ballistically.
    pub balls: usize,
    /// Position (in the ensemble's order) of the fastest of them.
    pub fastest: usize,
    /// Its speed through the lattice, `|v|` over the window.
    pub speed: f64,
}

/// The statistic `R` of ball `i` over the checkpoints `range`, and its
/// speed `|v|` (`None` for a ball that did not move).
fn residual(d: &Displacements<'_>, i: usize, range: &std::ops::Range<usize>) -> Option<(f64, f64)> {
    let times = d.times();
    let (a, b) = (range.start, range.end - 1);
    let total = times[b] - times[a];
    let [dx, dy] = d.increment(i, a, b);
    let v = [dx / total, dy / total];
    let speed2 = v[0] * v[0] + v[1] * v[1];
    if speed2 == 0.0 {
        return None;
    }
    let rho: f64 = (a + 1..=b)
        .map(|k| {
            let tau = times[k] - times[k - 1];
            let [x, y] = d.increment(i, k - 1, k);
            let (rx, ry) = (x - v[0] * tau, y - v[1] * tau);
            (rx * rx + ry * ry) / tau
        })
        .sum();
    Some((rho / (speed2 * total), speed2.sqrt()))
}

/// The ballistic balls among `d`'s over the checkpoints `range` (a fit
/// window's), `None` if there are none or the window has fewer than
/// [`MIN_INCREMENTS`] increments.
pub(crate) fn ballistic_balls(
    d: &Displacements<'_>,
    range: std::ops::Range<usize>,
) -> Option<Ballistic> {
    if range.len() < MIN_INCREMENTS + 1 {
        return None;
    }
    let mut found: Option<Ballistic> = None;
    for i in 0..d.n_ics() {
        let Some((r, speed)) = residual(d, i, &range) else {
            continue;
        };
        if r >= MAX_RESIDUAL {
            continue;
        }
        found = Some(match found {
            None => Ballistic {
                balls: 1,
                fastest: i,
                speed,
            },
            Some(f) if speed > f.speed => Ballistic {
                balls: f.balls + 1,
                fastest: i,
                speed,
            },
            Some(f) => Ballistic {
                balls: f.balls + 1,
                ..f
            },
        });
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64Mcg;

    /// `n` walks of unit-variance Gaussian-ish steps (uniform angle, unit
    /// length) at times 1..=steps, IC-major, with ball `fly` (if any)
    /// moving at `v` along x instead.
    fn walks(n: usize, steps: usize, seed: u64, fly: Option<(usize, f64)>) -> Vec<[f64; 2]> {
        let mut rng = Pcg64Mcg::seed_from_u64(seed);
        let mut out = Vec::with_capacity(n * steps);
        for i in 0..n {
            let mut p = [0.0f64; 2];
            for k in 1..=steps {
                match fly {
                    Some((j, v)) if j == i => p = [v * k as f64, 0.0],
                    _ => {
                        let phi: f64 = rng.random_range(0.0..std::f64::consts::TAU);
                        p = [p[0] + phi.cos(), p[1] + phi.sin()];
                    }
                }
                out.push(p);
            }
        }
        out
    }

    /// The checkpoints `picks` of `n` walks of `steps` steps.
    fn pick(dr: &[[f64; 2]], n: usize, steps: usize, picks: &[usize]) -> Vec<[f64; 2]> {
        (0..n)
            .flat_map(|i| picks.iter().map(move |&j| dr[i * steps + j]))
            .collect()
    }

    #[test]
    fn diffusing_balls_are_not_ballistic() {
        // 20 ensembles of 500 unit-step walks, checked on the fewest
        // increments (4, over [200, 400]): a false call has probability
        // about 0.02³ = 8e-6 per ball, 0.08 over the 10⁴ balls.
        let picks = [199, 249, 299, 349, 399];
        let times: Vec<f64> = picks.iter().map(|&j| (j + 1) as f64).collect();
        for seed in 0..20 {
            let dr = pick(&walks(500, 400, seed, None), 500, 400, &picks);
            let d = Displacements::new(&times, &dr).unwrap();
            assert_eq!(ballistic_balls(&d, 0..5), None, "seed {seed}");
            // Fewer increments than the check needs: not checked.
            assert_eq!(ballistic_balls(&d, 1..5), None);
        }
    }

    #[test]
    fn one_straight_flyer_is_found_with_its_speed() {
        // A ball moving at a constant 0.2 per step, jittered by 0.3 each
        // time (as a ball moves about its cell), among 500 unit walkers,
        // checked on 8 checkpoints spread over [200, 400]: R is about
        // 7·2·0.3²/25 / (0.2²·200) ≈ 0.006.
        let times: Vec<f64> = (1..=400).map(f64::from).collect();
        let mut dr = walks(500, 400, 7, Some((123, 0.2)));
        let mut rng = Pcg64Mcg::seed_from_u64(99);
        for k in 0..400 {
            let phi: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            dr[123 * 400 + k][0] += 0.3 * phi.cos();
            dr[123 * 400 + k][1] += 0.3 * phi.sin();
        }
        let picks: Vec<usize> = (0..8)
            .map(|k| 199 + 25 * k + usize::from(k == 7) * 25)
            .collect();
        let sub_times: Vec<f64> = picks.iter().map(|&j| times[j]).collect();
        let sub = pick(&dr, 500, 400, &picks);
        let d = Displacements::new(&sub_times, &sub).unwrap();
        let b = ballistic_balls(&d, 0..8).expect("the flyer");
        assert_eq!((b.balls, b.fastest), (1, 123));
        // 0.2 ± the jitter's 0.6/200 at the window's ends.
        assert!((b.speed - 0.2).abs() < 0.003, "{}", b.speed);
        // Without the flyer nobody is ballistic.
        let sub = pick(&walks(500, 400, 7, None), 500, 400, &picks);
        let d = Displacements::new(&sub_times, &sub).unwrap();
        assert_eq!(ballistic_balls(&d, 0..8), None);
    }

    #[test]
    fn a_far_but_crooked_ball_is_not_ballistic() {
        // A ball that jumps 100 in x at the window's start and 100 in y at
        // its end is far (|Δ|² = 2·10⁴) but its path bends: not ballistic.
        let times: Vec<f64> = (1..=400).map(f64::from).collect();
        let mut dr = walks(500, 400, 3, None);
        let i = 77;
        for k in 0..400 {
            let t = k + 1;
            let mut p = [0.0, 0.0];
            if t > 200 {
                p[0] = 100.0;
            }
            if t >= 400 {
                p[1] = 100.0;
            }
            dr[i * 400 + k] = p;
        }
        let d = Displacements::new(&times, &dr).unwrap();
        assert_eq!(ballistic_balls(&d, 199..400), None);
    }
}
