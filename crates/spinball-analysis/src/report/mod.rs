//! Reports: estimates as flat records, for CSV files, JSON documents and
//! terminal tables.
//!
//! A [`SweepRow`] holds one estimate with the derived quantities the paper's
//! figures plot (chaotic-fraction band, DHF product, collision rate), so it
//! reads from [`run`](crate::run), [`precision`](crate::precision) and
//! [`diagnostics`](crate::diagnostics) and is the top layer of the crate. A
//! [`BudgetRow`] holds one estimate's
//! [`ErrorBudget`](crate::precision::ErrorBudget). A [`SweepDocument`] is
//! the JSON document of `spinball sweep`: the settings and one
//! [`SweepPoint`] per α.
//!
//! # Rows
//!
//! Estimates as flat records: CSV rows, serde records and text tables.
//!
//! # The sweep document
//!
//! The machine interface's record, fixed because scripts read it: the
//! table spec, method, sampler, seed, `delta0`, chaos threshold and crate
//! version, then one point per finished α (λ, SEM, median, chaotic
//! fraction, sizes, wall time, stop reason and, when measured, the point's
//! [`BudgetRow`]). It lives here, beside the rows, so that every front
//! (the command line, the examples, the Python package) can write it; the
//! command line writes it to a file after every point.

mod rows;
mod sweep;

pub use rows::{BudgetRow, CSV_HEADER, SweepRow, csv_string, sweep_rows, write_csv};
pub use sweep::{SweepDocument, SweepPoint};
