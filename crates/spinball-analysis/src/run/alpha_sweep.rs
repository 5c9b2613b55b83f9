//! λ(α): one [`Ensemble`] per spin parameter, with progress as it goes, and
//! the results as table rows, CSV and serde records.
//!
//! Documented in the group docs (`run/mod.rs`), section "λ(α) sweeps".

use spinball_core::SpinLaw;
use spinball_geometry::{Boundary, Table};

use super::driver::{Control, Point, RunEvent, RunObserver};
use super::ensemble::Ensemble;
use super::result::LyapunovEstimate;
use super::stop_rule::StopRule;
use crate::error::AnalysisError;

/// What an [`AlphaSweep`] reports while it runs (the driver's events, with
/// the point of the sweep).
pub type SweepEvent<'a> = RunEvent<'a>;

/// A sweep over the spin parameter α: the ensemble `template` run at each
/// law of `laws`, in order.
///
/// Every point uses the template's table, sampler, seed, index range,
/// collisions, method, threads and threshold; only the spin law changes.
/// Without a stop rule each point runs the whole index range (bitwise the
/// numbers of [`Ensemble::run`]); with one, batches from the start of the
/// range until the rule stops (bitwise the numbers of
/// [`Ensemble::run_until`]), the range's end capping the count.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct AlphaSweep<B = Table> {
    /// The ensemble run at every α (its own law is ignored).
    pub template: Ensemble<B>,
    /// The spin laws, in sweep order.
    pub laws: Vec<SpinLaw>,
    /// Batches until this rule stops each point (`None`: whole range).
    pub stop: Option<StopRule>,
}

impl<B: Boundary + Clone + Sync> AlphaSweep<B> {
    /// A sweep of `template` over the physical `alphas` (each in `[0, 1]`).
    ///
    /// # Errors
    /// [`AnalysisError::SpinLaw`] for an α outside `[0, 1]` (build the laws
    /// with [`SpinLaw::extended`] and use [`AlphaSweep::from_laws`] for
    /// α > 1); [`AnalysisError::InvalidOption`] for an empty list.
    pub fn new(template: Ensemble<B>, alphas: &[f64]) -> Result<Self, AnalysisError> {
        let laws = alphas
            .iter()
            .map(|&a| SpinLaw::new(a))
            .collect::<Result<Vec<_>, _>>()?;
        if laws.is_empty() {
            return Err(AnalysisError::invalid("alphas", "the sweep has no points"));
        }
        Ok(Self::from_laws(template, laws))
    }

    /// A sweep of `template` over `laws` (any α the laws allow).
    pub fn from_laws(template: Ensemble<B>, laws: Vec<SpinLaw>) -> Self {
        AlphaSweep {
            template,
            laws,
            stop: None,
        }
    }

    /// Run each point in batches until `rule` stops it (`None`: run each
    /// point's whole index range).
    #[must_use]
    pub fn with_stop(mut self, rule: impl Into<Option<StopRule>>) -> Self {
        self.stop = rule.into();
        self
    }

    /// The α of each point.
    pub fn alphas(&self) -> Vec<f64> {
        self.laws.iter().map(SpinLaw::alpha).collect()
    }

    /// The ensemble of point `point` (the template with its law).
    ///
    /// # Panics
    /// If `point` is out of range.
    #[must_use]
    pub fn ensemble(&self, point: usize) -> Ensemble<B> {
        self.template.clone().with_law(self.laws[point])
    }

    /// Check the sweep before running it.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for no points, and as
    /// [`Ensemble::validate`] and [`StopRule::validate`].
    pub fn validate(&self) -> Result<(), AnalysisError> {
        if self.laws.is_empty() {
            return Err(AnalysisError::invalid("alphas", "the sweep has no points"));
        }
        self.template.validate()?;
        if let Some(rule) = &self.stop {
            rule.validate()?;
        }
        Ok(())
    }

    /// Run every point, silently.
    ///
    /// # Errors
    /// As [`AlphaSweep::validate`], then the first trajectory error.
    pub fn run(&self) -> Result<Vec<LyapunovEstimate>, AnalysisError> {
        self.run_with(|_| {})
    }

    /// Run every point, calling `observer` when a point starts, after every
    /// batch and when a point finishes (with its estimate); every point goes
    /// through the ensemble driver ([`Ensemble::run_observed`]). The
    /// estimates come back in sweep order. An observer that answers
    /// [`Control::Stop`] ends the current point early
    /// ([`StopReason::Cancelled`](crate::run::StopReason::Cancelled)) and the sweep
    /// after it.
    ///
    /// # Errors
    /// As [`AlphaSweep::validate`], then the first trajectory error (the
    /// points finished before it were reported to the observer).
    pub fn run_observed<O: RunObserver + ?Sized>(
        &self,
        observer: &mut O,
    ) -> Result<Vec<LyapunovEstimate>, AnalysisError> {
        self.validate()?;
        let points = self.laws.len();
        let mut out = Vec::with_capacity(points);
        let stopped = std::cell::Cell::new(false);
        // Remember a stop asked for at any event of a point: the sweep ends
        // after that point.
        let mut watch = |event: &RunEvent<'_>| {
            let answer = observer.observe(event);
            stopped.set(stopped.get() || answer == Control::Stop);
            answer
        };
        for index in 0..points {
            let ensemble = self.ensemble(index);
            let point = Point { index, of: points };
            out.push(ensemble.drive(self.stop.as_ref(), point, &mut watch)?);
            if stopped.get() {
                break;
            }
        }
        Ok(out)
    }

    /// [`run_observed`](Self::run_observed) with a callback that never stops
    /// the sweep.
    ///
    /// # Errors
    /// As [`run_observed`](Self::run_observed).
    pub fn run_with<F>(&self, mut on_event: F) -> Result<Vec<LyapunovEstimate>, AnalysisError>
    where
        F: FnMut(&SweepEvent<'_>),
    {
        self.run_observed(&mut |event: &RunEvent<'_>| {
            on_event(event);
            Control::Continue
        })
    }
}

// ---------------------------------------------------------------------------
// Grids
// ---------------------------------------------------------------------------

/// `n` equally spaced values from `lo` to `hi` inclusive (`numpy.linspace`;
/// the ends are exact). `n = 1` gives `[lo]`, `n = 0` nothing.
pub fn linspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    match n {
        0 => Vec::new(),
        1 => vec![lo],
        _ => (0..n)
            .map(|i| {
                if i == n - 1 {
                    hi
                } else {
                    lo + (hi - lo) * i as f64 / (n - 1) as f64
                }
            })
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::run::result::StopReason;
    use crate::test_support::{same_numbers, template};

    #[test]
    fn sweep_without_rule_equals_plain_runs() {
        let sweep = AlphaSweep::new(template().with_ics(150), &[0.0, 0.5]).unwrap();
        let got = sweep.run().unwrap();
        assert_eq!(got.len(), 2);
        for (i, e) in got.iter().enumerate() {
            assert_eq!(e.stop, StopReason::Completed);
            same_numbers(e, &sweep.ensemble(i).run().unwrap());
        }
    }

    #[test]
    fn sweep_with_rule_equals_run_until() {
        let rule = StopRule::new(8, 0.05).with_min_ics(16);
        let sweep = AlphaSweep::new(template(), &[0.0, 0.3, 1.0])
            .unwrap()
            .with_stop(rule);
        let got = sweep.run().unwrap();
        for (i, e) in got.iter().enumerate() {
            let reference = sweep.ensemble(i).run_until(&rule).unwrap();
            assert_eq!(e.stop, reference.stop);
            same_numbers(e, &reference);
        }
        // α = 0 is uniformly chaotic: the target is reached early.
        assert_eq!(got[0].stop, StopReason::TargetReached);
        assert!(got[0].n_ics < 40);
    }

    #[test]
    fn events_arrive_in_order() {
        let sweep = AlphaSweep::new(template(), &[0.0, 1.0])
            .unwrap()
            .with_stop(StopRule::new(10, 0.0)); // never reached: whole range
        let mut log = Vec::new();
        let got = sweep
            .run_with(|e| match e {
                SweepEvent::Started { point, points, .. } => log.push(format!("S{point}/{points}")),
                SweepEvent::Batch(p) => {
                    assert_eq!(p.ics_max, 40);
                    assert_eq!(p.target_rel_sem, Some(0.0));
                    log.push(format!("B{}:{}", p.point, p.ics_done));
                }
                SweepEvent::Finished {
                    point, estimate, ..
                } => log.push(format!("F{point}:{}", estimate.n_ics)),
                SweepEvent::Trajectories(done) => log.push(format!("T{}", done.len())),
            })
            .unwrap();
        let expect: Vec<String> = [0, 1]
            .iter()
            .flat_map(|p| {
                std::iter::once(format!("S{p}/2"))
                    .chain(
                        (1..=4).flat_map(move |k| ["T10".to_string(), format!("B{p}:{}", 10 * k)]),
                    )
                    .chain(std::iter::once(format!("F{p}:40")))
            })
            .collect();
        assert_eq!(log, expect);
        assert!(got.iter().all(|e| e.stop == StopReason::RangeExhausted));
    }

    #[test]
    fn invalid_sweeps_are_errors() {
        assert!(AlphaSweep::new(template(), &[]).is_err());
        assert!(matches!(
            AlphaSweep::new(template(), &[0.5, 1.5]),
            Err(AnalysisError::SpinLaw(_))
        ));
        let extended = AlphaSweep::from_laws(template(), vec![SpinLaw::extended(2.0).unwrap()]);
        assert_eq!(extended.alphas(), vec![2.0]);
        let bad_rule = AlphaSweep::new(template(), &[0.0])
            .unwrap()
            .with_stop(StopRule::new(1, 0.01));
        assert!(bad_rule.run().is_err());
        let one_ic = AlphaSweep::new(template().with_ics(1), &[0.0]).unwrap();
        assert!(one_ic.run().is_err());
    }

    #[test]
    fn linspace_ends_are_exact() {
        assert_eq!(linspace(0.0, 1.0, 0), Vec::<f64>::new());
        assert_eq!(linspace(0.5, 1.0, 1), vec![0.5]);
        let g = linspace(0.0, 1.0, 50);
        assert_eq!((g.len(), g[0], g[49]), (50, 0.0, 1.0));
        assert!((g[1] - 1.0 / 49.0).abs() < 1e-16);
        assert_eq!(linspace(0.0, 1.0, 11)[3], 0.3);
    }
}
