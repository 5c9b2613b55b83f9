//! Reports: estimates as flat records, for CSV files, JSON documents and
//! terminal tables.
//!
//! A [`SweepRow`] holds one estimate with the derived quantities the paper's
//! figures plot (chaotic-fraction band, DHF product, collision rate), so it
//! reads from [`run`](crate::run), [`precision`](crate::precision) and
//! [`diagnostics`](crate::diagnostics) and is the top layer of the crate. A
//! [`BudgetRow`] holds one estimate's
//! [`ErrorBudget`](crate::precision::ErrorBudget).
//!
//! # Rows
//!
//! Estimates as flat records: CSV rows, serde records and text tables.

mod rows;

pub use rows::{BudgetRow, CSV_HEADER, SweepRow, csv_string, sweep_rows, write_csv};
