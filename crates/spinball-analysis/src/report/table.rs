//! CSV tables written and read through serde, so a record's columns are
//! its serde field names in declaration order: one definition for the
//! header, the rows and reading them back.
//!
//! Documented in the group docs (`report/mod.rs`), section "CSV".

use std::io;

use serde::de::{self, DeserializeOwned, Visitor};
use serde::{Deserializer, Serialize};
use thiserror::Error;

use super::rows::SweepRow;
use super::trajectories::trajectory_rows;
use crate::error::AnalysisError;
use crate::run::LyapunovEstimate;

/// Why a CSV table could not be written or read.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum CsvError {
    /// The writer or reader failed, or a field does not parse as its
    /// column's type.
    #[error("CSV: {0}")]
    Csv(#[from] csv::Error),
    /// The estimates do not make rows (see [`SweepRow::from_estimate`]).
    #[error(transparent)]
    Estimate(#[from] AnalysisError),
}

/// The columns of record type `R`: its serde field names, in order.
///
/// ```
/// use spinball_analysis::report::{TrajectoryRow, csv_columns};
///
/// assert_eq!(
///     csv_columns::<TrajectoryRow>().join(","),
///     "alpha,index,exponent,per_collision,time,collisions"
/// );
/// ```
#[must_use]
pub fn csv_columns<R: DeserializeOwned>() -> &'static [&'static str] {
    let mut names = FieldNames(&[]);
    // The derive hands its field names to `deserialize_struct`, which
    // keeps them and stops; the error is expected and carries nothing.
    let _ = R::deserialize(&mut names);
    names.0
}

/// Write `rows` as CSV: the header ([`csv_columns`]), then one line per
/// row (numbers in their shortest round-trip form, an absent value empty,
/// a field with a comma or quote quoted).
///
/// # Errors
/// [`CsvError::Csv`] for the writer's errors.
pub fn write_csv<W, R>(w: W, rows: &[R]) -> Result<(), CsvError>
where
    W: io::Write,
    R: Serialize + DeserializeOwned,
{
    let mut out = csv::WriterBuilder::new().has_headers(false).from_writer(w);
    out.write_record(csv_columns::<R>())?;
    for row in rows {
        out.serialize(row)?;
    }
    out.flush().map_err(csv::Error::from)?;
    Ok(())
}

/// Read CSV text written by [`write_csv`] back into records.
///
/// # Errors
/// [`CsvError::Csv`] for a header or a field that does not parse.
pub fn read_csv<R: DeserializeOwned>(text: &str) -> Result<Vec<R>, CsvError> {
    csv::Reader::from_reader(text.as_bytes())
        .deserialize()
        .map(|r| r.map_err(CsvError::from))
        .collect()
}

/// `rows` as CSV text (see [`write_csv`]).
///
/// # Errors
/// As [`write_csv`].
pub fn csv_text<R: Serialize + DeserializeOwned>(rows: &[R]) -> Result<String, CsvError> {
    let mut out = Vec::new();
    write_csv(&mut out, rows)?;
    Ok(String::from_utf8(out).expect("serde CSV of UTF-8 strings and numbers is UTF-8"))
}

/// The CSV text of `estimates`, one [`SweepRow`] each.
///
/// # Errors
/// As [`SweepRow::from_estimate`].
pub fn csv_string(estimates: &[LyapunovEstimate]) -> Result<String, CsvError> {
    let rows = estimates
        .iter()
        .map(SweepRow::from_estimate)
        .collect::<Result<Vec<_>, _>>()?;
    csv_text(&rows)
}

/// The per-trajectory CSV of `estimates`: one
/// [`TrajectoryRow`](super::TrajectoryRow) per initial condition, α by α.
///
/// # Errors
/// As [`write_csv`] (writing to memory does not fail).
pub fn trajectories_csv(estimates: &[LyapunovEstimate]) -> Result<String, CsvError> {
    csv_text(&trajectory_rows(estimates))
}

/// A deserializer that only records the field names a struct asks for.
struct FieldNames(&'static [&'static str]);

/// The stop signal of [`FieldNames`].
#[derive(Debug)]
struct Stop;

impl std::fmt::Display for Stop {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("field names recorded")
    }
}

impl std::error::Error for Stop {}

impl de::Error for Stop {
    fn custom<T: std::fmt::Display>(_: T) -> Self {
        Stop
    }
}

impl<'de> Deserializer<'de> for &mut FieldNames {
    type Error = Stop;

    fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Stop> {
        Err(Stop)
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _: &'static str,
        fields: &'static [&'static str],
        _: V,
    ) -> Result<V::Value, Stop> {
        self.0 = fields;
        Err(Stop)
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string
        bytes byte_buf option unit unit_struct newtype_struct seq tuple
        tuple_struct map enum identifier ignored_any
    }
}

#[cfg(test)]
mod tests {
    use spinball_core::SpinLaw;
    use spinball_geometry::Table;

    use super::*;
    use crate::report::{IcSource, MethodName, TrajectoryRow};
    use crate::run::{AlphaSweep, Ensemble, StopReason, Threads};
    use crate::test_support::template;

    #[test]
    fn csv_has_header_and_one_row_per_point_that_reads_back() {
        let est = AlphaSweep::new(template().with_ics(20), &[0.0, 0.5])
            .unwrap()
            .run()
            .unwrap();
        let csv = csv_string(&est).unwrap();
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 3);
        let header = csv_columns::<SweepRow>().join(",");
        assert_eq!(lines[0], header);
        assert!(header.starts_with("table,alpha,method,sampler,mean,sem,"));
        assert!(header.ends_with(",seed,wall_time_s,stop,version"));
        let columns = csv_columns::<SweepRow>().len();
        assert_eq!(columns, 27);
        for line in &lines[1..] {
            // The stadium's spec has no comma, so no field is quoted.
            assert_eq!(line.split(',').count(), columns, "{line}");
        }
        // Every field reads back as it was, the numbers bit for bit.
        let rows: Vec<SweepRow> = read_csv(&csv).unwrap();
        for (row, e) in rows.iter().zip(&est) {
            assert_eq!(*row, SweepRow::from_estimate(e).unwrap());
            assert_eq!(row.mean.to_bits(), e.mean().to_bits());
            assert_eq!(row.n_ics, 20);
            assert_eq!(
                (row.method, row.sampler, row.stop),
                (MethodName::Fd, IcSource::Paper, StopReason::Completed)
            );
        }
        let row = &rows[1];
        assert!(row.chaotic_fraction_band_min <= row.chaotic_fraction);
        assert!(row.chaotic_fraction <= row.chaotic_fraction_band_max);
        assert!(row.table_line().len() == SweepRow::table_header().len());
    }

    #[test]
    fn a_spec_with_a_comma_is_quoted_and_an_empty_table_has_its_header() {
        let e = Ensemble::new(
            "rectangle:L=1,H=1".parse::<Table>().unwrap(),
            SpinLaw::new(0.3).unwrap(),
        )
        .with_ics(4)
        .with_collisions(100)
        .with_threads(Threads::Fixed(1))
        .run()
        .unwrap();
        let csv = csv_string(std::slice::from_ref(&e)).unwrap();
        let line = csv.lines().nth(1).unwrap();
        assert!(
            line.starts_with("\"rectangle:L=1,H=1\",0.3,fd,paper,"),
            "{line}"
        );
        // The rectangle is integrable: no chaotic trajectory, an empty field.
        let rows: Vec<SweepRow> = read_csv(&csv).unwrap();
        assert_eq!(rows[0].conditional_mean, e.conditional_mean());
        assert_eq!(
            csv_text::<SweepRow>(&[]).unwrap().trim_end(),
            csv_columns::<SweepRow>().join(",")
        );
    }

    #[test]
    fn trajectories_read_back_bit_for_bit() {
        let e = template().with_ics(6).with_collisions(200).run().unwrap();
        let csv = trajectories_csv(std::slice::from_ref(&e)).unwrap();
        assert!(csv.starts_with("alpha,index,exponent,per_collision,time,collisions\n"));
        let rows: Vec<TrajectoryRow> = read_csv(&csv).unwrap();
        assert_eq!(rows.len(), 6);
        for (r, t) in rows.iter().zip(e.trajectories()) {
            assert_eq!(r.alpha.to_bits(), e.alpha().to_bits());
            assert_eq!((r.index, r.collisions), (t.index, t.collisions));
            assert_eq!(r.exponent.to_bits(), t.exponent.to_bits());
            assert_eq!(r.per_collision.to_bits(), t.per_collision.to_bits());
            assert_eq!(r.time.to_bits(), t.time.to_bits());
        }
    }

    #[test]
    fn a_field_of_the_wrong_type_is_an_error() {
        let bad = "alpha,index,exponent,per_collision,time,collisions\n0.5,x,1,1,1,1\n";
        assert!(matches!(
            read_csv::<TrajectoryRow>(bad),
            Err(CsvError::Csv(_))
        ));
    }
}
