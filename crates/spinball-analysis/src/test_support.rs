//! Small ensembles shared by the unit tests of several modules.

use spinball_core::SpinLaw;
use spinball_geometry::{Stadium, Table};

use crate::run::Ensemble;
use crate::run::LyapunovEstimate;
use crate::run::Threads;

/// `e` at spin `alpha`.
pub(crate) fn at(e: Ensemble, alpha: f64) -> Ensemble {
    e.with_law(SpinLaw::new(alpha).unwrap())
}

/// The stadium (a = 1), specular, seed 5, 40 ICs of 300 collisions, one thread.
pub(crate) fn template() -> Ensemble {
    Ensemble::new(Table::from(Stadium::new(1.0).unwrap()), SpinLaw::specular())
        .with_seed(5)
        .with_ics(40)
        .with_collisions(300)
        .with_threads(Threads::Fixed(1))
}

/// `a` and `b` are the same numbers (wall times aside).
pub(crate) fn same_numbers(a: &LyapunovEstimate, b: &LyapunovEstimate) {
    let mut b = b.clone();
    b.wall_time_s = a.wall_time_s;
    assert_eq!(a, &b);
}
