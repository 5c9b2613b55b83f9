//! Between batches: Ctrl-C and progress.
//!
//! A run releases the GIL; between batches of initial conditions the
//! driver calls a [`RunObserver`]. [`Watch`] is that observer: it attaches
//! to the interpreter for a moment, runs Python's signal handlers (so
//! Ctrl-C raises `KeyboardInterrupt` there) and calls the progress
//! callback; either failing stops the run ([`Control::Stop`]) and the
//! Python exception is raised when the run returns.

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict};
use spinball_analysis::run::{Control, RunEvent, RunObserver};

/// The observer of a run started from Python.
pub struct Watch {
    callback: Option<Py<PyAny>>,
    error: Option<PyErr>,
}

impl Watch {
    /// A watch calling `progress`: `None` or `False` (signals only), `True`
    /// (a text line on stderr, `spinball._progress.TextProgress`) or a
    /// callable taking one dict per event.
    ///
    /// # Errors
    /// `TypeError` for anything else.
    pub fn new(progress: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let callback = match progress {
            None => None,
            Some(p) if p.is_none() => None,
            Some(p) => match p.cast::<PyBool>() {
                Ok(b) if b.is_true() => Some(
                    p.py()
                        .import("spinball._progress")?
                        .getattr("TextProgress")?
                        .call0()?
                        .unbind(),
                ),
                Ok(_) => None,
                Err(_) if p.is_callable() => Some(p.clone().unbind()),
                Err(_) => {
                    return Err(PyTypeError::new_err(format!(
                        "progress: expected True, False, None or a callable, got {}",
                        p.get_type().name()?
                    )));
                }
            },
        };
        Ok(Watch {
            callback,
            error: None,
        })
    }

    /// Check for signals, then show the event `make` builds to the callback.
    pub fn report(
        &mut self,
        make: impl FnOnce(Python<'_>) -> PyResult<Bound<'_, PyDict>>,
    ) -> Control {
        if self.error.is_some() {
            return Control::Stop;
        }
        let outcome = Python::attach(|py| {
            py.check_signals()?;
            if let Some(cb) = &self.callback {
                cb.call1(py, (make(py)?,))?;
            }
            Ok::<(), PyErr>(())
        });
        match outcome {
            Ok(()) => Control::Continue,
            Err(e) => {
                self.error = Some(e);
                Control::Stop
            }
        }
    }

    /// The run's outcome, unless a signal handler or the callback raised:
    /// then that exception.
    ///
    /// # Errors
    /// The exception raised between batches, else `result`'s.
    pub fn finish<T>(self, result: PyResult<T>) -> PyResult<T> {
        match self.error {
            Some(e) => Err(e),
            None => result,
        }
    }
}

/// The dict a callback receives for a driver event.
fn event_dict<'py>(py: Python<'py>, event: &RunEvent<'_>) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    match event {
        RunEvent::Started {
            point,
            points,
            alpha,
        } => {
            d.set_item("event", "started")?;
            d.set_item("point", point)?;
            d.set_item("points", points)?;
            d.set_item("alpha", alpha)?;
        }
        RunEvent::Batch(p) => {
            d.set_item("event", "batch")?;
            d.set_item("point", p.point)?;
            d.set_item("points", p.points)?;
            d.set_item("alpha", p.alpha)?;
            d.set_item("ics_done", p.ics_done)?;
            d.set_item("ics_max", p.ics_max)?;
            d.set_item("mean", p.mean)?;
            d.set_item("sem", p.sem)?;
            d.set_item("target_rel_sem", p.target_rel_sem)?;
            d.set_item("elapsed_s", p.elapsed_s)?;
        }
        RunEvent::Finished {
            point,
            points,
            estimate,
        } => {
            d.set_item("event", "finished")?;
            d.set_item("point", point)?;
            d.set_item("points", points)?;
            d.set_item("alpha", estimate.alpha())?;
            d.set_item("ics_done", estimate.n_ics())?;
            d.set_item("mean", estimate.mean())?;
            d.set_item("sem", estimate.sem())?;
            d.set_item("elapsed_s", estimate.wall_time_s())?;
        }
        _ => d.set_item("event", "other")?,
    }
    Ok(d)
}

impl RunObserver for Watch {
    fn observe(&mut self, event: &RunEvent<'_>) -> Control {
        // A batch's trajectories are for checkpoint writers; callbacks see
        // started, batch and finished (signals are checked at the batch
        // event that follows).
        if matches!(event, RunEvent::Trajectories(_)) {
            return Control::Continue;
        }
        self.report(|py| event_dict(py, event))
    }
}
