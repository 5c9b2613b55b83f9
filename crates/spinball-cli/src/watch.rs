//! What watches a run from the command line: a progress bar on a
//! terminal, the signals and time limit that stop it, and the checkpoint
//! that keeps its finished trajectories.

use std::io::IsTerminal;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};
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
    if quiet || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(0);
    bar.set_style(
        ProgressStyle::with_template(
            "{prefix} [{bar:30}] {pos}/{len} ICs {msg} ({elapsed}, ~{eta} left)",
        )
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
            stopped: None,
        }
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
                self.bar
                    .set_prefix(format!("α = {alpha} ({}/{points})", point + 1));
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
                    .set_message(format!("λ = {:.5} ± {:.5}", p.mean, p.sem));
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

/// The instant a run of at most `seconds` that started now must stop.
pub fn deadline(seconds: Option<f64>) -> Result<Option<Instant>, CliError> {
    match seconds {
        None => Ok(None),
        Some(s) if s.is_finite() && s > 0.0 => {
            Ok(Some(Instant::now() + Duration::from_secs_f64(s)))
        }
        Some(s) => Err(CliError::Usage(format!(
            "--time-limit {s}: must be a positive number of seconds"
        ))),
    }
}
