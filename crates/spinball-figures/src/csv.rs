//! CSV text built row by row, for the figure data that is not a result
//! table ([`SweepRow`](spinball_analysis::report::SweepRow)s and
//! per-trajectory rows are written through serde by
//! [`write_csv`](spinball_analysis::report::write_csv)).
//!
//! Every figure writes its numbers next to its picture; the rules for a
//! field (quoting, numbers) belong in one place rather than in a format
//! string per example. A field is written with its `Display` form — for
//! `f64` Rust's shortest form that reads back to the same number — and
//! quoted (RFC 4180) when it holds a comma, a quote or a line break, as a
//! table spec like `rectangle:L=1,H=1` does.
//!
//! ```
//! use spinball_figures::Csv;
//! let mut csv = Csv::new(&["table", "alpha", "lambda"]);
//! csv.row(&[&"rectangle:L=1,H=1", &0.5, &1e-5]);
//! assert_eq!(csv.as_str(), "table,alpha,lambda\n\"rectangle:L=1,H=1\",0.5,0.00001\n");
//! ```

use std::fmt::{Display, Write as _};

/// A CSV document: a header and rows with as many fields.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Csv {
    columns: usize,
    rows: usize,
    text: String,
}

impl Csv {
    /// A document with the column names `header`.
    pub fn new(header: &[&str]) -> Self {
        let mut csv = Csv {
            columns: header.len(),
            rows: 0,
            text: String::new(),
        };
        csv.push_line(header.iter().map(|h| field(h)));
        csv
    }

    /// A document whose header is `columns`, comma-separated names
    /// (`"table,alpha,n"`).
    pub fn with_columns(columns: &str) -> Self {
        Csv::new(&columns.split(',').map(str::trim).collect::<Vec<_>>())
    }

    /// Add a row.
    ///
    /// # Panics
    /// If `fields` does not have one value per column (a bug in the caller).
    pub fn row(&mut self, fields: &[&dyn Display]) -> &mut Self {
        assert_eq!(
            fields.len(),
            self.columns,
            "a CSV row needs one field per column"
        );
        self.push_line(fields.iter().map(|f| field(&f.to_string())));
        self.rows += 1;
        self
    }

    /// Add a row of values of one type (for example numbers, or fields
    /// already written as strings).
    ///
    /// # Panics
    /// If there is not one value per column (a bug in the caller).
    pub fn row_from<I>(&mut self, fields: I) -> &mut Self
    where
        I: IntoIterator,
        I::Item: Display,
    {
        let fields: Vec<String> = fields.into_iter().map(|f| f.to_string()).collect();
        let refs: Vec<&dyn Display> = fields.iter().map(|f| f as &dyn Display).collect();
        self.row(&refs)
    }

    /// Number of rows (without the header).
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// The text, one line per row, each ending in `\n`.
    pub fn as_str(&self) -> &str {
        &self.text
    }

    fn push_line(&mut self, fields: impl Iterator<Item = String>) {
        let line: Vec<String> = fields.collect();
        let _ = writeln!(self.text, "{}", line.join(","));
    }
}

/// An optional value as a field: the value, or empty.
pub fn optional<T: Display>(x: Option<T>) -> String {
    x.map_or(String::new(), |v| v.to_string())
}

/// `s` quoted if it needs to be.
fn field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quoting_and_numbers() {
        let mut csv = Csv::new(&["a", "b,c"]);
        csv.row(&[&"say \"hi\"", &0.1])
            .row(&[&optional(None::<f64>), &optional(Some(2.5))]);
        csv.row_from([1.5, -2.0]);
        assert_eq!(Csv::with_columns("x, y,z"), Csv::new(&["x", "y", "z"]));
        assert_eq!(csv.rows(), 3);
        assert_eq!(
            csv.as_str(),
            "a,\"b,c\"\n\"say \"\"hi\"\"\",0.1\n,2.5\n1.5,-2\n"
        );
        // Numbers read back exactly.
        let x = 0.1 + 0.2;
        let mut one = Csv::new(&["x"]);
        one.row(&[&x]);
        let back: f64 = one.as_str().lines().nth(1).unwrap().parse().unwrap();
        assert_eq!(back, x);
    }

    #[test]
    #[should_panic(expected = "one field per column")]
    fn wrong_width_is_a_bug() {
        Csv::new(&["a", "b"]).row(&[&1]);
    }
}
