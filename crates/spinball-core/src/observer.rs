//! Observers: what a caller wants to watch of a run, and nothing more.
//!
//! A run stores nothing by itself. An [`Observer`] sees each [`Collision`] and
//! the state after it and keeps what it needs: a closure, a [`Recorder`] of
//! every collision, an [`EnergyMonitor`], or a pair of them.

use crate::collision::Collision;
use crate::spin_law::SpinLaw;
use crate::state::State;

/// Sees every collision of a run.
pub trait Observer {
    /// Called after each collision with its record and the state after it.
    fn observe(&mut self, collision: &Collision, after: &State);
}

/// Watch nothing.
impl Observer for () {
    #[inline]
    fn observe(&mut self, _: &Collision, _: &State) {}
}

/// Any closure `FnMut(&Collision, &State)` is an observer.
impl<F: FnMut(&Collision, &State)> Observer for F {
    #[inline]
    fn observe(&mut self, c: &Collision, s: &State) {
        self(c, s)
    }
}

/// Two observers at once.
impl<A: Observer, B: Observer> Observer for (A, B) {
    #[inline]
    fn observe(&mut self, c: &Collision, s: &State) {
        self.0.observe(c, s);
        self.1.observe(c, s);
    }
}

/// Keeps every collision (and optionally every state after it).
#[derive(Debug, Clone, Default)]
pub struct Recorder {
    /// The collisions, in order.
    pub collisions: Vec<Collision>,
    /// The states after each collision, if `with_states` was asked for.
    pub states: Vec<State>,
    with_states: bool,
}

impl Recorder {
    /// Record collisions only.
    pub fn new() -> Self {
        Self::default()
    }
    /// Record collisions and the states after them (for drawing trajectories).
    pub fn with_states() -> Self {
        Recorder {
            with_states: true,
            ..Self::default()
        }
    }
}

impl Observer for Recorder {
    fn observe(&mut self, c: &Collision, s: &State) {
        self.collisions.push(*c);
        if self.with_states {
            self.states.push(*s);
        }
    }
}

/// Tracks the largest relative energy deviation `|E_n − E_0|/E_0` of a run.
#[derive(Debug, Clone, Copy)]
pub struct EnergyMonitor {
    law: SpinLaw,
    e0: f64,
    /// Largest `|E_n − E_0|/E_0` seen.
    pub max_relative_deviation: f64,
    /// `(E_n − E_0)/E_0` after the last collision.
    pub last_relative_deviation: f64,
}

impl EnergyMonitor {
    /// Compare against the energy of `start` under `law`.
    pub fn new(law: SpinLaw, start: &State) -> Self {
        EnergyMonitor {
            law,
            e0: start.energy(&law),
            max_relative_deviation: 0.0,
            last_relative_deviation: 0.0,
        }
    }
}

impl Observer for EnergyMonitor {
    #[inline]
    fn observe(&mut self, _: &Collision, s: &State) {
        let d = (s.energy(&self.law) - self.e0) / self.e0;
        self.last_relative_deviation = d;
        self.max_relative_deviation = self.max_relative_deviation.max(d.abs());
    }
}
