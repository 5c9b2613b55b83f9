//! Balls that fly through a finite-horizon lattice in a straight line.
//!
//! A finite horizon bounds every free flight, but not every trajectory: a
//! stable periodic orbit that comes back to itself one lattice vector on
//! (an "accelerator mode"; the rough ball's spin makes them) carries its
//! ball ballistically, `|Δr| ∝ t`. One such ball in an ensemble makes
//! `⟨Δr²⟩` grow like `t²`: there is no finite diffusion coefficient, and a
//! fitted `D` (with its large error) would be a number that is not one.
//!
//! The check looks at each ball's displacement over the fit window `[t_a,
//! t_b]` (its first and last checkpoints): `Δ = Δr(t_b) − Δr(t_a)`. For
//! diffusion, `|Δ|² / (4 D τ)` is close to an exponential variable of mean
//! 1 (a sum of many bounded flights), so the ensemble's own diffusive scale
//! is `s² = median |Δ|² / ln 2`, robust to a few outliers. A ball is
//! ballistic when both
//!
//! - its `|Δ|²` exceeds `s² (ln n + `[`BALLISTIC_EXCESS`]`)` (for `n`
//!   diffusing balls the chance that any one does is about
//!   `e^{−BALLISTIC_EXCESS}`), and
//! - its path is straight: at the window's middle checkpoint it lies within
//!   [`STRAIGHTNESS`]`·|Δ|` of the chord from `Δr(t_a)` to `Δr(t_b)`, at
//!   the point a constant velocity would put it.
//!
//! It is applied to finite-horizon tables only: with an infinite horizon a
//! ball flying along a corridor is ballistic for as long as its flight, and
//! the marginal law already accounts for such flights.

use super::Displacements;

/// Excess (in e-folds of the exponential tail) of a ball's squared window
/// displacement over the ensemble's diffusive scale, beyond `ln n`, for it
/// to count as ballistic.
pub const BALLISTIC_EXCESS: f64 = 12.0;

/// Largest distance of a ballistic ball's middle checkpoint from its
/// constant-velocity chord, as a fraction of its window displacement.
pub const STRAIGHTNESS: f64 = 0.1;

/// The balls of an ensemble that travel ballistically over a fit window.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct Ballistic {
    /// How many balls travel ballistically.
    pub balls: usize,
    /// Position (in the ensemble's order) of the fastest of them.
    pub fastest: usize,
    /// Its speed through the lattice, `|Δ| / τ` over the window.
    pub speed: f64,
}

/// The ballistic balls among `d`'s over the checkpoints `range` (a fit
/// window's, at least three), `None` if there are none.
pub(crate) fn ballistic_balls(
    d: &Displacements<'_>,
    range: std::ops::Range<usize>,
) -> Option<Ballistic> {
    let (a, b) = (range.start, range.end - 1);
    let m = (a + b) / 2;
    if m == a || m == b {
        return None;
    }
    let times = d.times();
    let tau = times[b] - times[a];
    let frac = (times[m] - times[a]) / tau;
    let n = d.n_ics();
    let sq: Vec<f64> = (0..n)
        .map(|i| {
            let [x, y] = d.increment(i, a, b);
            x * x + y * y
        })
        .collect();
    let mut sorted = sq.clone();
    sorted.sort_by(f64::total_cmp);
    let median = if n % 2 == 1 {
        sorted[n / 2]
    } else {
        0.5 * (sorted[n / 2 - 1] + sorted[n / 2])
    };
    let scale = median / std::f64::consts::LN_2;
    let threshold = scale * ((n as f64).ln() + BALLISTIC_EXCESS);
    let mut found: Option<Ballistic> = None;
    for (i, &s) in sq.iter().enumerate() {
        if s <= threshold || s == 0.0 {
            continue;
        }
        let [dx, dy] = d.increment(i, a, b);
        let [mx, my] = d.increment(i, a, m);
        let off = (mx - frac * dx).hypot(my - frac * dy);
        if off > STRAIGHTNESS * s.sqrt() {
            continue;
        }
        let speed = s.sqrt() / tau;
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

    #[test]
    fn diffusing_balls_are_never_ballistic() {
        // 20 ensembles of 500 unit-step walks: the chance of a false call
        // is about e^-12 per ensemble.
        let times: Vec<f64> = (1..=400).map(f64::from).collect();
        for seed in 0..20 {
            let dr = walks(500, 400, seed, None);
            let d = Displacements::new(&times, &dr).unwrap();
            assert_eq!(ballistic_balls(&d, 199..400), None, "seed {seed}");
        }
    }

    #[test]
    fn one_straight_flyer_is_found_with_its_speed() {
        // 500 unit-step walkers: over the window [200, 400] (τ = 200) their
        // |Δ|² is about exponential with mean 200, so the threshold is
        // about 200·(ln 500 + 12) ≈ 3600. A flyer at 0.2 per step
        // (|Δ|² = 1600) cannot be told from diffusion here; one at 0.5
        // (|Δ|² = 10⁴) is found, with its speed.
        let times: Vec<f64> = (1..=400).map(f64::from).collect();
        let slow = walks(500, 400, 7, Some((123, 0.2)));
        let d = Displacements::new(&times, &slow).unwrap();
        assert_eq!(ballistic_balls(&d, 199..400), None);
        let fast = walks(500, 400, 7, Some((123, 0.5)));
        let d = Displacements::new(&times, &fast).unwrap();
        let b = ballistic_balls(&d, 199..400).expect("the flyer");
        assert_eq!((b.balls, b.fastest), (1, 123));
        assert!((b.speed - 0.5).abs() < 1e-12, "{}", b.speed);
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
