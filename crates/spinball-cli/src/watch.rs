//! What watches a run from the command line: a progress bar on a
//! terminal, the signals and time limit that stop it, and the checkpoint
//! that keeps its finished trajectories.

use std::io::IsTerminal;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};
use spinball_analysis::estimators::PlusMinus;
use spinball_analysis::run::{Control, RunEvent, RunObserver, TrajectoryStats};

use crate::error::CliError;

/// Set when SIGINT, SIGTERM or SIGHUP arrives (SLURM sends SIGTERM before
/// it kills a job at its time limit).
pub fn stop_flag() -> Arc<AtomicBool> {
    let flag = Arc::new(AtomicBool::new(false));
    let set = Arc::clone(&flag);
    // A second handler cannot be installed; one process runs one command,
    // so a failure here only means a test installed it before.
    let _ = ctrlc::set_handler(move || set.store(true, Ordering::SeqCst));
    flag
}

/// A progress bar on stderr if it is a terminal and not `quiet`, else
/// nothing.
pub fn progress_bar(quiet: bool) -> ProgressBar {
    progress_bar_counting(quiet, "ICs")
}

/// [`progress_bar`] counting `unit` ("ICs", "frames").
pub fn progress_bar_counting(quiet: bool, unit: &str) -> ProgressBar {
    if quiet || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(0);
    bar.set_style(
        ProgressStyle::with_template(&format!(
            "{{prefix}} [{{bar:30}}] {{pos}}/{{len}} {unit} {{msg}} ({{elapsed}}, ~{{eta}} left)"
        ))
        .expect("the template is valid")
        .progress_chars("=> "),
    );
    bar
}

/// The observer of one ensemble run.
pub struct Watch<'a> {
    bar: &'a ProgressBar,
    stop: &'a AtomicBool,
    deadline: Option<Instant>,
    on_trajectories: &'a mut dyn FnMut(&[TrajectoryStats]) -> Result<(), CliError>,
    /// Which of the command's α this run is, and of how many.
    of: Option<(usize, usize)>,
    /// Why the run was stopped, if it was.
    pub stopped: Option<CliError>,
}

impl<'a> Watch<'a> {
    /// Watch with `bar`, stop on `stop` or after `deadline`, hand every
    /// batch of finished trajectories to `on_trajectories`.
    pub fn new(
        bar: &'a ProgressBar,
        stop: &'a AtomicBool,
        deadline: Option<Instant>,
        on_trajectories: &'a mut dyn FnMut(&[TrajectoryStats]) -> Result<(), CliError>,
    ) -> Self {
        Watch {
            bar,
            stop,
            deadline,
            on_trajectories,
            of: None,
            stopped: None,
        }
    }

    /// This run is α number `point` (from 0) of the command's `points`:
    /// the bar shows `(point + 1)/points`, not the run's own `1/1`.
    #[must_use]
    pub fn of(mut self, point: usize, points: usize) -> Self {
        self.of = Some((point, points));
        self
    }

    /// The bar's prefix for α = `alpha`, point `point` of `points` of the
    /// run (replaced by the command's count when [`of`](Self::of) gave one).
    fn prefix(&self, alpha: f64, point: usize, points: usize) -> String {
        let (k, n) = self.of.unwrap_or((point, points));
        format!("α = {alpha} ({}/{n})", k + 1)
    }
}

impl RunObserver for Watch<'_> {
    fn observe(&mut self, event: &RunEvent<'_>) -> Control {
        match event {
            RunEvent::Started {
                point,
                points,
                alpha,
            } => {
                self.bar.set_prefix(self.prefix(*alpha, *point, *points));
                self.bar.set_position(0);
            }
            RunEvent::Trajectories(done) => {
                if let Err(e) = (self.on_trajectories)(done) {
                    self.stopped = Some(e);
                    return Control::Stop;
                }
            }
            RunEvent::Batch(p) => {
                self.bar.set_length(p.ics_max);
                self.bar.set_position(p.ics_done);
                self.bar
                    .set_message(format!("λ = {}", PlusMinus::new(p.mean, p.sem)));
            }
            _ => {}
        }
        let late = self.deadline.is_some_and(|d| Instant::now() >= d);
        if self.stop.load(Ordering::SeqCst) || late {
            self.stopped
                .get_or_insert(CliError::Interrupted { checkpoint: None });
            return Control::Stop;
        }
        Control::Continue
    }
}

/// A `--time-limit`: how long a run may go, or no limit (a limit longer
/// than a [`Duration`] can hold).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TimeLimit(Option<Duration>);

/// A number of seconds from the command line, or `range` (what works) as
/// the error.
fn seconds(s: &str, works: impl Fn(f64) -> bool, range: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(x) if works(x) => Ok(x),
        _ => Err(range.into()),
    }
}

/// Parse `--time-limit`: a number of seconds > 0; one beyond what a
/// [`Duration`] holds (1.8e19 s) or `inf` is no limit.
///
/// # Errors
/// The range that works, for zero, a negative number, NaN or not a number.
pub fn parse_time_limit(s: &str) -> Result<TimeLimit, String> {
    let x = seconds(
        s,
        |x| x > 0.0,
        "the limit must be a number of seconds > 0 (`inf` or anything above 9.2e18 is no limit)",
    )?;
    Ok(TimeLimit(Duration::try_from_secs_f64(x).ok()))
}

/// Parse `--checkpoint-every`: a number of seconds >= 0; one beyond what
/// a [`Duration`] holds (1.8e19 s) or `inf` is never (the checkpoint is
/// saved only when the run stops).
///
/// # Errors
/// The range that works, for a negative number, NaN or not a number.
pub fn parse_checkpoint_every(s: &str) -> Result<Duration, String> {
    let x = seconds(
        s,
        |x| x >= 0.0,
        "the interval must be a number of seconds >= 0 (0 saves after every batch, `inf` only when the run stops)",
    )?;
    Ok(Duration::try_from_secs_f64(x).unwrap_or(Duration::MAX))
}

/// The instant a run limited to `limit` that starts now must stop: none
/// without a limit, or if the limit ends beyond what the clock can count
/// (about 9.2e18 s from boot), which no run reaches.
pub fn deadline(limit: Option<TimeLimit>) -> Option<Instant> {
    limit
        .and_then(|TimeLimit(d)| d)
        .and_then(|d| Instant::now().checked_add(d))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bar_counts_the_commands_alphas() {
        let bar = ProgressBar::hidden();
        let stop = AtomicBool::new(false);
        let mut keep = |_: &[TrajectoryStats]| Ok(());
        let mut watch = Watch::new(&bar, &stop, None, &mut keep).of(1, 3);
        // Each α runs alone (point 0 of 1): the bar says 2/3, not 1/1.
        let started = RunEvent::Started {
            point: 0,
            points: 1,
            alpha: 0.5,
        };
        assert_eq!(watch.observe(&started), Control::Continue);
        assert_eq!(bar.prefix(), "α = 0.5 (2/3)");
        let mut keep = |_: &[TrajectoryStats]| Ok(());
        let alone = Watch::new(&bar, &stop, None, &mut keep);
        assert_eq!(alone.prefix(0.5, 0, 1), "α = 0.5 (1/1)");
    }

    #[test]
    fn time_limits() {
        assert_eq!(
            parse_time_limit("1.5"),
            Ok(TimeLimit(Some(Duration::from_millis(1500))))
        );
        for s in ["1e300", "inf", "1e20"] {
            assert_eq!(parse_time_limit(s), Ok(TimeLimit(None)), "{s}");
        }
        // Fits a Duration, but not the clock: no deadline, no panic.
        let far = parse_time_limit("1e19").unwrap();
        assert!(far.0.is_some());
        assert_eq!(deadline(Some(far)), None);
        assert!(deadline(parse_time_limit("1e-9").ok()).is_some());
        for s in ["0", "-1", "nan", "-inf", "soon", ""] {
            assert!(parse_time_limit(s).is_err(), "{s}");
        }
        assert!(parse_time_limit("0").unwrap_err().contains("> 0"));
    }

    #[test]
    fn checkpoint_intervals() {
        assert_eq!(parse_checkpoint_every("0"), Ok(Duration::ZERO));
        assert_eq!(parse_checkpoint_every("60"), Ok(Duration::from_secs(60)));
        for s in ["1e300", "inf", "1e20"] {
            assert_eq!(parse_checkpoint_every(s), Ok(Duration::MAX), "{s}");
        }
        for s in ["-1", "nan", "-inf", "often"] {
            assert!(parse_checkpoint_every(s).is_err(), "{s}");
        }
        assert!(parse_checkpoint_every("-1").unwrap_err().contains(">= 0"));
    }
}
