//! Progress of long runs on stderr, as a [`RunObserver`].
//!
//! A default-size figure runs for minutes; without a sign of life it looks
//! hung, and a log full of redrawn bars is unreadable. So [`Progress`]
//! draws one line redrawn in place (bar, point, running SEM/λ, elapsed and
//! estimated time left) when stderr is a terminal, and otherwise writes one
//! plain line per finished point. It only watches: it never stops a run,
//! and stdout (the results) stays free of it.
//!
//! ```
//! use spinball_analysis::run::{AlphaSweep, Ensemble};
//! use spinball_core::SpinLaw;
//! use spinball_geometry::Stadium;
//! use spinball_figures::Progress;
//!
//! let template = Ensemble::new(Stadium::new(1.0)?, SpinLaw::specular())
//!     .with_ics(8)
//!     .with_collisions(500);
//! let sweep = AlphaSweep::new(template, &[0.0, 1.0])?;
//! let mut progress = Progress::new(Vec::new(), false, 2); // as in a log file
//! sweep.run_observed(&mut progress)?;
//! progress.finish();
//! let log = String::from_utf8(progress.into_inner())?;
//! assert_eq!(log.lines().count(), 3); // one line per point, one at the end
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::io::{IsTerminal, Stderr, Write};
use std::time::Instant;

use spinball_analysis::run::{BatchProgress, Control, RunEvent, RunObserver};

/// Width of the bar in characters.
const BAR: usize = 24;

/// A progress display over `total` points (of one or several sweeps).
#[derive(Debug)]
pub struct Progress<W: Write = Stderr> {
    out: W,
    tty: bool,
    total: usize,
    done: usize,
    label: String,
    start: Instant,
    drawn: bool,
}

impl Progress<Stderr> {
    /// Progress over `total` points on stderr, redrawn in place only if
    /// stderr is a terminal.
    pub fn stderr(total: usize) -> Self {
        let err = std::io::stderr();
        let tty = err.is_terminal();
        Progress::new(err, tty, total)
    }
}

impl<W: Write> Progress<W> {
    /// Progress over `total` points written to `out`; `tty` redraws one line
    /// after every batch, otherwise one line is written per finished point.
    pub fn new(out: W, tty: bool, total: usize) -> Self {
        Progress {
            out,
            tty,
            total,
            done: 0,
            label: String::new(),
            start: Instant::now(),
            drawn: false,
        }
    }

    /// Name the sweep that runs now (shown on the redrawn line).
    pub fn set_label(&mut self, label: impl Into<String>) {
        self.label = label.into();
    }

    /// Points finished so far.
    pub fn done(&self) -> usize {
        self.done
    }

    /// Erase the redrawn line, so that other output (a result row on stdout)
    /// does not tear it; the next batch draws it again.
    pub fn clear(&mut self) {
        if self.drawn {
            let _ = write!(self.out, "\r\x1b[2K");
            let _ = self.out.flush();
            self.drawn = false;
        }
    }

    /// End the display with a summary line (points and total time).
    pub fn finish(&mut self) {
        self.clear();
        let line = format!(
            "{} {} points in {:.1} s",
            bar(1.0),
            self.total,
            self.start.elapsed().as_secs_f64()
        );
        let _ = writeln!(self.out, "{line}");
    }

    /// The writer (for tests and logs).
    pub fn into_inner(self) -> W {
        self.out
    }

    fn fraction(&self, within: f64) -> f64 {
        (self.done as f64 + within) / self.total.max(1) as f64
    }

    fn batch(&mut self, p: &BatchProgress) {
        if !self.tty {
            return;
        }
        // Initial conditions against the cap: a stop rule usually ends a
        // point earlier, so this is a lower bound on progress.
        let fraction = self.fraction(p.ics_done as f64 / p.ics_max.max(1) as f64);
        let target = p
            .target_rel_sem
            .map_or(String::new(), |t| format!(" (target {:.1}%)", 100.0 * t));
        let line = format!(
            "{} {}/{} {} α={:.3}: {} ICs, SEM/λ {:.2}%{target} | {}",
            bar(fraction),
            (self.done + 1).min(self.total),
            self.total,
            self.label,
            p.alpha,
            p.ics_done,
            100.0 * p.rel_sem(),
            eta(self.start.elapsed().as_secs_f64(), fraction)
        );
        let _ = write!(self.out, "\r\x1b[2K{line}");
        let _ = self.out.flush();
        self.drawn = true;
    }

    fn point_done(&mut self) {
        self.done += 1;
        if !self.tty {
            let fraction = self.fraction(0.0);
            let line = format!(
                "{} {}/{} points | {}",
                bar(fraction),
                self.done,
                self.total,
                eta(self.start.elapsed().as_secs_f64(), fraction)
            );
            let _ = writeln!(self.out, "{line}");
        }
    }
}

impl<W: Write> RunObserver for Progress<W> {
    fn observe(&mut self, event: &RunEvent<'_>) -> Control {
        match event {
            RunEvent::Batch(p) => self.batch(p),
            RunEvent::Finished { .. } => self.point_done(),
            _ => {}
        }
        Control::Continue
    }
}

/// `[#####-----]` filled to `fraction`.
fn bar(fraction: f64) -> String {
    let filled = ((fraction.clamp(0.0, 1.0) * BAR as f64).round() as usize).min(BAR);
    format!("[{}{}]", "#".repeat(filled), "-".repeat(BAR - filled))
}

/// `12 s, ~30 s left` after `elapsed` seconds at `fraction` done.
fn eta(elapsed: f64, fraction: f64) -> String {
    if fraction <= 0.0 {
        return format!("{elapsed:.0} s");
    }
    let left = elapsed * (1.0 - fraction) / fraction;
    format!("{elapsed:.0} s, ~{left:.0} s left")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn batch(ics_done: u64) -> BatchProgress {
        // BatchProgress is non-exhaustive: take a real one from a run.
        let mut seen = None;
        let ensemble = spinball_analysis::run::Ensemble::new(
            spinball_geometry::Stadium::new(1.0).unwrap(),
            spinball_core::SpinLaw::new(0.5).unwrap(),
        )
        .with_ics(ics_done)
        .with_collisions(200);
        ensemble
            .run_observed(None, &mut |e: &RunEvent<'_>| {
                if let RunEvent::Batch(p) = e {
                    seen = Some(**p);
                }
                Control::Continue
            })
            .unwrap();
        seen.unwrap()
    }

    #[test]
    fn bar_and_eta() {
        assert_eq!(bar(0.0), format!("[{}]", "-".repeat(BAR)));
        assert_eq!(bar(0.5), format!("[{}{}]", "#".repeat(12), "-".repeat(12)));
        assert_eq!(bar(2.0), format!("[{}]", "#".repeat(BAR)));
        assert_eq!(eta(10.0, 0.0), "10 s");
        assert_eq!(eta(10.0, 0.25), "10 s, ~30 s left");
    }

    #[test]
    fn plain_lines_per_point_without_a_terminal() {
        let mut p = Progress::new(Vec::new(), false, 4);
        let b = batch(4);
        p.observe(&RunEvent::Batch(&b));
        assert!(p.out.is_empty(), "no redraws in a log");
        p.point_done();
        p.point_done();
        assert_eq!(p.done(), 2);
        p.finish();
        let text = String::from_utf8(p.into_inner()).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 3);
        assert!(lines[0].starts_with(&format!(
            "[{}{}] 1/4 points | ",
            "#".repeat(6),
            "-".repeat(18)
        )));
        assert!(lines[1].contains(" 2/4 points | "));
        assert!(lines[2].starts_with(&format!("[{}] 4 points in ", "#".repeat(BAR))));
        assert!(!text.contains('\r'));
    }

    #[test]
    fn one_redrawn_line_on_a_terminal() {
        let mut p = Progress::new(Vec::new(), true, 2);
        p.set_label("stadium");
        let b = batch(4);
        p.observe(&RunEvent::Batch(&b));
        p.observe(&RunEvent::Batch(&b));
        let text = String::from_utf8(p.out.clone()).unwrap();
        assert_eq!(text.matches("\r\x1b[2K").count(), 2);
        assert!(
            text.contains(" 1/2 stadium α=0.500: 4 ICs, SEM/λ "),
            "{text}"
        );
        assert!(!text.contains('\n'));
        p.clear();
        p.clear(); // only once
        p.point_done(); // silent on a terminal
        let text = String::from_utf8(p.into_inner()).unwrap();
        assert_eq!(text.matches("\r\x1b[2K").count(), 3);
        assert!(!text.contains('\n'));
    }
}
