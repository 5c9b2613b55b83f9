//! What an estimate was computed from: table, spin, method, initial
//! conditions, seed, engine. Typed (enums with serde), so a result can be
//! checked, merged and rerun, not just read.
//!
//! Documented in the group docs (`run/mod.rs`), section "Provenance".

use std::fmt;

use spinball_core::Sampler;
use spinball_geometry::{Boundary, Shape};
use thiserror::Error;

use super::checksum::{CHECKSUM_PREFIX, shape_fingerprint};
use super::engine::Engine;
use crate::estimators::Method;

/// The table of a run: its [`Shape`] when it has one (every built-in table
/// and every segment table: enough to rebuild it), and a name.
///
/// A table is **identified by its geometry**: its kind and the exact bits
/// of its parameters (every wall of a segment table), see
/// [`identity`](TableRecord::identity). The name is a label for people; a
/// table made through `T` and through `&T` has the same record. A table
/// without a shape (your own [`Boundary`] whose `shape()` is `None`) has no
/// identity: merging and resuming its runs is refused
/// ([`RunDifference::NoShape`]), since nothing in a file shows that two
/// results are of the same such table.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TableRecord {
    /// The spec string of a built-in table (`stadium:a=1`, which
    /// `spinball_geometry::Table` parses back), `segments(N walls)`, or,
    /// for a table without a shape, the Rust type name (a label only: it
    /// identifies nothing, see [`TableRecord::identity`]).
    pub name: String,
    /// The table as data, if it has a closed form.
    pub shape: Option<Shape>,
}

impl TableRecord {
    /// The record of `table`.
    #[must_use]
    pub fn of<B: Boundary>(table: &B) -> Self {
        let shape = table.shape();
        let name = match &shape {
            Some(s) => s.to_string(),
            None => std::any::type_name::<B>().to_string(),
        };
        TableRecord { name, shape }
    }
}

impl TableRecord {
    /// The table's identity: a 64-bit FNV-1a hash of its kind and the exact
    /// bits of its parameters (for a segment table, of every wall: end
    /// points, centre, radius, angles), the same on every platform and
    /// build. `None` for a table without a shape.
    #[must_use]
    pub fn identity(&self) -> Option<u64> {
        self.shape.as_ref().map(shape_fingerprint)
    }

    /// Whether `self` and `other` are the same table (same geometry, bit
    /// for bit).
    ///
    /// # Errors
    /// [`RunDifference::Field`] naming the two tables if they differ,
    /// [`RunDifference::NoShape`] if either has no shape.
    pub fn same_table(&self, other: &TableRecord) -> Result<(), RunDifference> {
        match (self.identity(), other.identity()) {
            (Some(a), Some(b)) if a == b => Ok(()),
            (Some(a), Some(b)) => {
                let label = |r: &TableRecord, id: u64| {
                    if self.name == other.name {
                        format!("{} [{CHECKSUM_PREFIX}{id:016x}]", r.name)
                    } else {
                        r.name.clone()
                    }
                };
                Err(RunDifference::Field {
                    what: "table",
                    first: label(self, a),
                    other: label(other, b),
                })
            }
            (None, _) => Err(RunDifference::NoShape(self.name.clone())),
            (_, None) => Err(RunDifference::NoShape(other.name.clone())),
        }
    }
}

/// How two runs' parameters differ: the first field that does, or a table
/// that cannot be identified.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum RunDifference {
    /// A parameter differs.
    #[error("{what} {first} in one, {other} in the other")]
    Field {
        /// The parameter (`table`, `alpha`, `method`, `sampler`, `seed`,
        /// `collisions per IC`, `threshold`, `engine`).
        what: &'static str,
        /// Its value in the first run (as written in a result).
        first: String,
        /// Its value in the other.
        other: String,
    },
    /// A table without a shape: nothing identifies it.
    #[error(
        "the table `{0}` has no shape (its `Boundary::shape` is `None`), so nothing shows that two results are of the same table: merging and resuming need a table with a shape (a built-in table, a `SegmentTable`, or a wrapper that forwards `shape()`)"
    )]
    NoShape(String),
}

impl fmt::Display for TableRecord {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name)
    }
}

/// The parameters of an ensemble run, as a result records them.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Provenance {
    /// The table.
    pub table: TableRecord,
    /// Spin parameter α.
    pub alpha: f64,
    /// How the exponent was measured.
    pub method: Method,
    /// How initial conditions were drawn (`None`: given as explicit states).
    pub sampler: Option<Sampler>,
    /// Seed of the initial conditions (and of the perturbation directions).
    pub seed: u64,
    /// Collisions per initial condition.
    pub collisions_per_ic: u64,
    /// FTLE above which a trajectory counts as chaotic.
    pub threshold: f64,
    /// The engine that ran the trajectories.
    pub engine: Engine,
}

impl Provenance {
    /// A record of the given parameters.
    #[must_use]
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        table: TableRecord,
        alpha: f64,
        method: Method,
        sampler: Option<Sampler>,
        seed: u64,
        collisions_per_ic: u64,
        threshold: f64,
        engine: Engine,
    ) -> Self {
        Provenance {
            table,
            alpha,
            method,
            sampler,
            seed,
            collisions_per_ic,
            threshold,
            engine,
        }
    }

    /// The first parameter in which `other` differs from `self` (the
    /// table by its [identity](TableRecord::identity), numbers bit for
    /// bit), in the order table, α, method (with δ0), sampler, seed,
    /// collisions per IC, threshold, engine.
    ///
    /// ```
    /// use spinball_analysis::run::{Ensemble, RunDifference};
    /// use spinball_core::SpinLaw;
    /// use spinball_geometry::Stadium;
    ///
    /// let e = Ensemble::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?);
    /// let d = e.provenance().difference(&e.clone().with_seed(8).provenance());
    /// assert_eq!(d.unwrap_err().to_string(), "seed 0 in one, 8 in the other");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`RunDifference::Field`] for the first field that differs;
    /// [`RunDifference::NoShape`] for a table without a shape.
    pub fn difference(&self, other: &Provenance) -> Result<(), RunDifference> {
        self.table.same_table(&other.table)?;
        let field = |what, first: String, other: String| {
            if first == other {
                Ok(())
            } else {
                Err(RunDifference::Field { what, first, other })
            }
        };
        let bits = |x: f64| format!("{x:?}");
        let method = |m: Method| match m {
            Method::Tangent => "tangent".to_string(),
            Method::FiniteDifference { delta0 } => format!("fd (delta0 {delta0:?})"),
        };
        let sampler = |s: Option<Sampler>| s.map_or("explicit states", |s| s.name()).to_string();
        if self.alpha.to_bits() != other.alpha.to_bits() {
            field("alpha", bits(self.alpha), bits(other.alpha))?;
            return Err(RunDifference::Field {
                what: "alpha",
                first: format!("{:#x}", self.alpha.to_bits()),
                other: format!("{:#x}", other.alpha.to_bits()),
            });
        }
        field("method", method(self.method), method(other.method))?;
        if self.method != other.method {
            return Err(RunDifference::Field {
                what: "method",
                first: format!("{:?}", self.method),
                other: format!("{:?}", other.method),
            });
        }
        field("sampler", sampler(self.sampler), sampler(other.sampler))?;
        field("seed", self.seed.to_string(), other.seed.to_string())?;
        field(
            "collisions per IC",
            self.collisions_per_ic.to_string(),
            other.collisions_per_ic.to_string(),
        )?;
        if self.threshold.to_bits() != other.threshold.to_bits() {
            field("threshold", bits(self.threshold), bits(other.threshold))?;
            return Err(RunDifference::Field {
                what: "threshold",
                first: format!("{:#x}", self.threshold.to_bits()),
                other: format!("{:#x}", other.threshold.to_bits()),
            });
        }
        field(
            "engine",
            self.engine.name().to_string(),
            other.engine.name().to_string(),
        )
    }
}
