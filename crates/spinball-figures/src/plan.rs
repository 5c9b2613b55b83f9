//! How big each ensemble of a figure is: a [`Plan`] per mode, and the α
//! grids the figures use.
//!
//! A figure picks a plan per mode (`--quick`, default, `--paper`): a fixed
//! number of initial conditions, or batches until the standard error
//! reaches a target share of λ. The plan is part of the result (it goes
//! into the JSON document), so it is a serialisable value, not a few loose
//! numbers in an example.
//!
//! ```
//! use spinball_figures::{Plan, unit_grid};
//! let plan = Plan::until(0.01, 200, 1_000, 20_000, 10_000);
//! assert_eq!(
//!     plan.to_string(),
//!     "batches of 200 ICs until SEM <= 1% of lambda (1000..20000 ICs) x 10000 collisions"
//! );
//! assert_eq!(unit_grid(11)[3], 0.3);
//! ```

use std::fmt;

use serde::Serialize;
use spinball_analysis::AnalysisError;
use spinball_analysis::run::{AlphaSweep, Ensemble, StopRule};
use spinball_geometry::Boundary;

/// The size of every ensemble of one λ(α) curve.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Plan {
    /// Most initial conditions per point (all of them without a stop rule).
    #[serde(rename = "max_ics")]
    pub ics: u64,
    /// Collisions per initial condition.
    pub collisions: u64,
    /// Batches until SEM/λ reaches a target (`None`: run all `ics`).
    #[serde(rename = "stop_rule")]
    pub stop: Option<StopRule>,
}

impl Plan {
    /// Exactly `ics` initial conditions of `collisions` collisions.
    #[must_use]
    pub fn fixed(ics: u64, collisions: u64) -> Plan {
        Plan {
            ics,
            collisions,
            stop: None,
        }
    }

    /// Batches of `batch` until `SEM ≤ target · λ`, at least `min_ics` and
    /// at most `ics` initial conditions of `collisions` collisions.
    #[must_use]
    pub fn until(target: f64, batch: u64, min_ics: u64, ics: u64, collisions: u64) -> Plan {
        Plan {
            ics,
            collisions,
            stop: Some(StopRule::new(batch, target).with_min_ics(min_ics)),
        }
    }

    /// `template` sized by this plan.
    #[must_use]
    pub fn apply<B: Boundary>(&self, template: Ensemble<B>) -> Ensemble<B> {
        template.with_ics(self.ics).with_collisions(self.collisions)
    }

    /// A sweep of `template` (sized by this plan) over `alphas`.
    ///
    /// # Errors
    /// As [`AlphaSweep::new`].
    pub fn sweep<B: Boundary + Clone + Sync>(
        &self,
        template: Ensemble<B>,
        alphas: &[f64],
    ) -> Result<AlphaSweep<B>, AnalysisError> {
        Ok(AlphaSweep::new(self.apply(template), alphas)?.with_stop(self.stop))
    }

    /// As [`sweep`](Self::sweep) over any `α >= 0`, including the
    /// extension α > 1 ([`SpinLaw::extended`](spinball_core::SpinLaw::extended)).
    ///
    /// # Errors
    /// [`AnalysisError::SpinLaw`] for a negative or non-finite α.
    pub fn sweep_extended<B: Boundary + Clone + Sync>(
        &self,
        template: Ensemble<B>,
        alphas: &[f64],
    ) -> Result<AlphaSweep<B>, AnalysisError> {
        let laws = alphas
            .iter()
            .map(|&a| spinball_core::SpinLaw::extended(a))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(AlphaSweep::from_laws(self.apply(template), laws).with_stop(self.stop))
    }
}

impl fmt::Display for Plan {
    /// One line for the terminal.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.stop {
            Some(r) => write!(
                f,
                "batches of {} ICs until SEM <= {}% of lambda ({}..{} ICs) x {} collisions",
                r.batch,
                100.0 * r.target_rel_sem,
                r.min_ics,
                self.ics,
                self.collisions
            ),
            None => write!(f, "{} ICs x {} collisions", self.ics, self.collisions),
        }
    }
}

/// `points` values from 0 to 1 inclusive, equally spaced, rounded to six
/// decimals so that they read as written (`unit_grid(21)` gives 0, 0.05,
/// 0.1, …, 1 with `0.15`, not `0.15000000000000002`). At least two points.
pub fn unit_grid(points: usize) -> Vec<f64> {
    let n = points.max(2) - 1;
    (0..=n)
        .map(|i| ((i as f64 / n as f64) * 1e6).round() / 1e6)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_core::SpinLaw;
    use spinball_geometry::Stadium;

    #[test]
    fn grids_read_as_written() {
        let g = unit_grid(21);
        assert_eq!(g.len(), 21);
        assert_eq!((g[0], g[3], g[20]), (0.0, 0.15, 1.0));
        assert_eq!(unit_grid(0), vec![0.0, 1.0]);
    }

    #[test]
    fn plans_size_sweeps_and_serialise() {
        let fixed = Plan::fixed(64, 2_000);
        assert_eq!(fixed.to_string(), "64 ICs x 2000 collisions");
        let template = Ensemble::new(Stadium::new(1.0).unwrap(), SpinLaw::specular());
        let sweep = fixed.sweep(template.clone(), &[0.0, 1.0]).unwrap();
        assert_eq!(
            (sweep.template.n_ics(), sweep.template.collisions),
            (64, 2_000)
        );
        assert_eq!((sweep.alphas(), sweep.stop), (vec![0.0, 1.0], None));
        let until = Plan::until(0.02, 200, 400, 3_000, 10_000);
        let sweep = until.sweep(template, &[0.5]).unwrap();
        assert_eq!(sweep.stop.map(|r| (r.batch, r.min_ics)), Some((200, 400)));
        let v = serde_json::to_value(until).unwrap();
        assert_eq!(v["max_ics"], 3_000);
        assert_eq!(v["collisions"], 10_000);
        assert_eq!(v["stop_rule"]["target_rel_sem"], 0.02);
        assert_eq!(v["stop_rule"]["min_ics"], 400);
        assert!(serde_json::to_value(fixed).unwrap()["stop_rule"].is_null());
    }
}
