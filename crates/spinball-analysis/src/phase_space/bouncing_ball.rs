//! The bouncing-ball island of the spinning stadium, explained: between the
//! two flat walls a pair of collisions is a rotation by `4·arctan √α`.
//!
//! Documented in the group docs (`phase_space/mod.rs`), section "The bouncing-ball island".

use std::f64::consts::PI;

use spinball_core::{Sampler, SpinLaw, State};
use spinball_geometry::{Boundary, DVec2, Stadium, Table};

use super::ftle_map::FtleMap;
use crate::run::TrajectoryStats;

/// The rotation of `(v_x, √α u)` by a bottom–top pair of collisions on two
/// facing flat walls: `4·arctan √α` (see the [module docs](crate::phase_space#the-bouncing-ball-island)).
#[must_use]
pub fn pair_rotation(alpha: f64) -> f64 {
    4.0 * alpha.sqrt().atan()
}

/// The band of x the flat-wall contacts of a bouncing ball sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FlatBand {
    /// Centre `c` of the band.
    pub center: f64,
    /// Half-width `A` of the band.
    pub amplitude: f64,
    /// Phase `θ₀` of the first contact.
    pub phase: f64,
    /// Phase step `Δ = 2 arctan √α` per flight.
    pub step: f64,
}

impl FlatBand {
    /// The x of contact `n` on the flats (`n = 0`: the first),
    /// `c − A sin(θ₀ − nΔ)`, while the ball stays between them.
    #[must_use]
    pub fn contact(&self, n: u64) -> f64 {
        self.center - self.amplitude * (self.phase - n as f64 * self.step).sin()
    }
    /// Whether the band fits on flats of half-length `a`.
    #[must_use]
    pub fn fits(&self, a: f64) -> bool {
        self.center.abs() + self.amplitude <= a
    }
    /// How far inside (positive) or outside (negative) the flats the band
    /// ends: `a − |c| − A`.
    #[must_use]
    pub fn margin(&self, a: f64) -> f64 {
        a - self.center.abs() - self.amplitude
    }
}

/// The two facing flat walls `y = ±1`, `|x| ≤ a` of a stadium with unit
/// caps, and the predictions of the rotation there.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FacingFlats {
    a: f64,
}

impl FacingFlats {
    /// The flats of `stadium`.
    #[must_use]
    pub fn of(stadium: &Stadium) -> Self {
        FacingFlats { a: stadium.a() }
    }

    /// The flats of `table` if it is a stadium, `None` for the other
    /// built-in tables (which have no two facing flats with caps beside
    /// them).
    #[must_use]
    pub fn of_table(table: &Table) -> Option<Self> {
        match table {
            Table::Stadium(s) => Some(FacingFlats::of(s)),
            _ => None,
        }
    }

    /// Half-length `a` of the flats.
    #[must_use]
    pub fn a(&self) -> f64 {
        self.a
    }

    /// The band of the contacts of a ball in `state` under `law`, if the
    /// ball is in the strip between the flats (`|x| ≤ a`, `|y| ≤ 1`),
    /// moves across it (`v_y ≠ 0`), and the band is bounded (α > 0, or
    /// `v_x = 0` at α = 0). The first contact counts.
    #[must_use]
    pub fn band(&self, law: &SpinLaw, state: &State) -> Option<FlatBand> {
        let (p, v) = (state.position, state.velocity);
        if p.x.abs() > self.a || p.y.abs() > 1.0 || v.y == 0.0 {
            return None;
        }
        let sigma = v.y.signum();
        let x1 = p.x + v.x * (sigma - p.y) / v.y;
        let alpha = law.alpha();
        if alpha == 0.0 {
            return (v.x == 0.0).then_some(FlatBand {
                center: x1,
                amplitude: 0.0,
                phase: 0.0,
                step: 0.0,
            });
        }
        let w = alpha.sqrt() * state.spin;
        let r = v.x.hypot(w);
        let half = alpha.sqrt().atan(); // Δ/2 = ψ
        let theta0 = sigma * w.atan2(v.x) - half;
        let amplitude = r / (v.y.abs() * half.sin());
        Some(FlatBand {
            center: x1 + amplitude * theta0.sin(),
            amplitude,
            phase: theta0,
            step: 2.0 * half,
        })
    }

    /// Whether a ball in `state` stays between the flats for ever (its band
    /// fits; see the [module docs](crate::phase_space#the-bouncing-ball-island) for when this is exact).
    #[must_use]
    pub fn trapped(&self, law: &SpinLaw, state: &State) -> bool {
        self.band(law, state).is_some_and(|b| b.fits(self.a))
    }

    /// [`trapped`](Self::trapped) for a ball leaving the wall at arc length
    /// `s` with tangential velocity `v_par` and spin `spin` on the shell
    /// `|V| = 1` (the coordinates of an FTLE map); `false` off the flats or
    /// off the shell.
    #[must_use]
    pub fn trapped_at(&self, law: &SpinLaw, s: f64, v_par: f64, spin: f64) -> bool {
        let a = self.a;
        let rest = 1.0 - v_par * v_par - law.alpha() * spin * spin;
        if rest <= 0.0 {
            return false;
        }
        let (x, y, t) = if (0.0..=2.0 * a).contains(&s) {
            (s - a, -1.0, 1.0)
        } else if (2.0 * a + PI..=4.0 * a + PI).contains(&s) {
            (a - (s - 2.0 * a - PI), 1.0, -1.0)
        } else {
            return false;
        };
        // Tangent (t, 0), inward normal (0, −y).
        let velocity = DVec2::new(t * v_par, -y * rest.sqrt());
        self.trapped(law, &State::new(DVec2::new(x, y), velocity, spin))
    }

    /// The cells of `map`, an FTLE map of this stadium under `law`, whose
    /// starts the rotation predicts trapped between the flats (row-major,
    /// like [`FtleMap::exponents`]); count the regular ones with
    /// [`FtleMap::regular_among`].
    #[must_use]
    pub fn trapped_cells(&self, law: &SpinLaw, map: &FtleMap) -> Vec<bool> {
        let (columns, rows) = (map.options.columns, map.options.rows);
        (0..rows)
            .flat_map(|j| (0..columns).map(move |i| (i, j)))
            .map(|(i, j)| {
                let (v_par, spin) = map.options.slice.coordinates(law.alpha(), map.row(j));
                self.trapped_at(law, map.s(i), v_par, spin)
            })
            .collect()
    }
}

/// How many of an ensemble's regular orbits the rotation explains.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BouncingShare {
    /// FTLE at or below which an orbit counts as regular.
    pub threshold: f64,
    /// Regular orbits.
    pub regular: u64,
    /// Regular orbits whose start the rotation predicts trapped.
    pub regular_trapped: u64,
    /// Chaotic orbits whose start the rotation predicts trapped (0 if the
    /// prediction is right and the run long enough).
    pub chaotic_trapped: u64,
    /// Orbits.
    pub total: u64,
}

impl BouncingShare {
    /// Share of the regular orbits that are predicted bouncing balls
    /// (`None` without regular orbits).
    #[must_use]
    pub fn share(&self) -> Option<f64> {
        (self.regular > 0).then(|| self.regular_trapped as f64 / self.regular as f64)
    }
}

impl FacingFlats {
    /// Which of an ensemble's orbits (`trajectories`, started by `sampler`
    /// from `ic_rng(seed, index)` on `table` under `law`, as
    /// [`Ensemble`](crate::run::Ensemble) draws them) are regular (FTLE ≤
    /// `threshold`), and which of those these flats predict trapped. The
    /// flats must be those of `table` (a stadium, or a table with the same
    /// flats and unit caps, such as the stadium's [`Table`] form).
    #[must_use]
    pub fn share<B: Boundary>(
        &self,
        table: &B,
        law: &SpinLaw,
        sampler: Sampler,
        seed: u64,
        trajectories: &[TrajectoryStats],
        threshold: f64,
    ) -> BouncingShare {
        let mut share = BouncingShare {
            threshold,
            regular: 0,
            regular_trapped: 0,
            chaotic_trapped: 0,
            total: trajectories.len() as u64,
        };
        for t in trajectories {
            let start = sampler.initial_state(table, law, seed, t.index);
            let trapped = u64::from(self.trapped(law, &start));
            if t.exponent <= threshold {
                share.regular += 1;
                share.regular_trapped += trapped;
            } else {
                share.chaotic_trapped += trapped;
            }
        }
        share
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_limits() {
        assert_eq!(pair_rotation(0.0), 0.0);
        assert!((pair_rotation(1.0) - PI).abs() < 1e-15);
        assert!((pair_rotation(1.0 / 3.0) - 2.0 * PI / 3.0).abs() < 1e-15);
    }

    #[test]
    fn bands_need_the_strip_and_spin() {
        let flats = FacingFlats::of(&Stadium::new(1.0).unwrap());
        let law = SpinLaw::new(0.5).unwrap();
        let inside = State::new(DVec2::ZERO, DVec2::new(0.05, 0.9), 0.1);
        assert!(flats.trapped(&law, &inside));
        let in_cap = State::new(DVec2::new(1.5, 0.0), DVec2::new(0.05, 0.9), 0.1);
        assert!(flats.band(&law, &in_cap).is_none());
        let level = State::new(DVec2::ZERO, DVec2::new(1.0, 0.0), 0.0);
        assert!(flats.band(&law, &level).is_none());
        let specular = SpinLaw::specular();
        assert!(flats.band(&specular, &inside).is_none());
        let vertical = State::new(DVec2::ZERO, DVec2::new(0.0, 1.0), 0.0);
        assert!(flats.trapped(&specular, &vertical));
        assert!(!flats.trapped_at(&law, 3.0, 0.0, 0.0)); // on a cap
    }

    #[test]
    fn the_table_form_finds_the_same_flats_and_orbits() {
        use crate::estimators::Method;
        use crate::run::{Ensemble, Threads};
        let stadium = Stadium::new(1.0).unwrap();
        let table = Table::Stadium(stadium);
        assert_eq!(
            FacingFlats::of_table(&table),
            Some(FacingFlats::of(&stadium))
        );
        let sinai: Table = "sinai:L=2,R=1".parse().unwrap();
        assert_eq!(FacingFlats::of_table(&sinai), None);
        let law = SpinLaw::new(0.5).unwrap();
        let run = Ensemble::new(table, law)
            .with_method(Method::Tangent)
            .with_ics(400)
            .with_collisions(1_000)
            .with_seed(3)
            .with_threads(Threads::Fixed(1))
            .run()
            .unwrap();
        let flats = FacingFlats::of_table(&table).unwrap();
        let share = flats.share(&table, &law, Sampler::Paper, 3, &run.trajectories, 0.01);
        // The stadium itself draws the same starts as its Table form.
        let direct = flats.share(&stadium, &law, Sampler::Paper, 3, &run.trajectories, 0.01);
        assert_eq!(share, direct);
        assert_eq!(share.total, 400);
        // About 7 % of the paper sampler's orbits are regular at α = 0.5
        // (fig_ftle_map), most of them predicted bouncing balls; a
        // predicted bouncing ball is never chaotic.
        assert!(
            share.regular >= 5 && share.regular_trapped >= 2,
            "{share:?}"
        );
        assert!(share.regular_trapped <= share.regular);
        assert_eq!(share.chaotic_trapped, 0);
    }
}
