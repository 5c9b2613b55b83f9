//! Writing what a figure example computed: PNG, CSV, JSON and text files
//! in its output directory, and one closing line naming them.
//!
//! Every figure example ends the same way — files in `--out`, a JSON
//! document saying which example, mode, seed, thread count and crate version
//! made them, and a line on stdout listing what was written and how long it
//! took — so that is written once, here. JSON documents are the serde form
//! of typed values (the analysis results derive `Serialize`), never text
//! put together by hand.
//!
//! ```no_run
//! use spinball_analysis::precision::Measurement;
//! use spinball_figures::{FigureArgs, Csv, Report};
//!
//! let args = FigureArgs::parse_or_exit("fig_demo", "A demo.");
//! let mut report = Report::new("fig_demo", &args);
//! let mut csv = Csv::new(&["alpha", "lambda"]);
//! csv.row(&[&0.5, &0.183]);
//! report.csv("demo.csv", &csv)?;
//! report.json("demo.json", &serde_json::json!({"lambda": Measurement::new(0.183, 0.001)}))?;
//! report.finish(); // "fig_demo (default mode, 2 threads): wrote out/fig_demo/demo.csv, … in 0.0 s"
//! # Ok::<(), spinball_figures::FigureError>(())
//! ```

use std::path::{Path, PathBuf};
use std::time::Instant;

use npyz::WriterBuilder;
use serde::Serialize;
use spinball_analysis::report::{Document, DocumentError, FigureDocument, SweepRow, csv_text};

use crate::args::FigureArgs;
use crate::csv::Csv;
use crate::error::FigureError;
use spinball_plot::Plot;

/// What every JSON document of a figure starts with.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Header {
    /// The example that wrote it.
    pub figure: String,
    /// `quick`, `default` or `paper`.
    pub mode: String,
    /// Seed of the initial conditions.
    pub seed: u64,
    /// Worker threads used (results do not depend on it).
    pub threads: usize,
    /// Version of the crates that computed it.
    pub version: String,
}

/// The files of one figure run.
#[derive(Debug)]
pub struct Report {
    out: PathBuf,
    header: Header,
    files: Vec<PathBuf>,
    start: Instant,
}

impl Report {
    /// A report of the example `name` run with `args` (its output directory
    /// and what its JSON header says); the clock starts now.
    pub fn new(name: &str, args: &FigureArgs) -> Self {
        Report {
            out: args.out.clone(),
            header: Header {
                figure: name.to_string(),
                mode: args.mode.to_string(),
                seed: args.seed,
                threads: args.thread_count(),
                version: env!("CARGO_PKG_VERSION").to_string(),
            },
            files: Vec::new(),
            start: Instant::now(),
        }
    }

    /// The JSON header of this run.
    pub fn header(&self) -> &Header {
        &self.header
    }

    /// The files written so far, in order.
    pub fn files(&self) -> &[PathBuf] {
        &self.files
    }

    /// The path of `file` in the output directory (created), listed in the
    /// closing line; for files written by other means.
    ///
    /// # Errors
    /// [`FigureError::Io`] if the directory cannot be created.
    pub fn path(&mut self, file: &str) -> Result<PathBuf, FigureError> {
        std::fs::create_dir_all(&self.out).map_err(|source| io(&self.out, source))?;
        let path = self.out.join(file);
        if !self.files.contains(&path) {
            self.files.push(path.clone());
        }
        Ok(path)
    }

    /// Draw `plot` into the PNG `file` of `width × height` pixels.
    ///
    /// # Errors
    /// As [`Plot::save_png`].
    pub fn png<P: Plot>(
        &mut self,
        file: &str,
        plot: &P,
        (width, height): (u32, u32),
    ) -> Result<PathBuf, FigureError> {
        let path = self.path(file)?;
        plot.save_png(&path, width, height)?;
        Ok(path)
    }

    /// Write `text` to `file`.
    ///
    /// # Errors
    /// [`FigureError::Io`].
    pub fn text(&mut self, file: &str, text: &str) -> Result<PathBuf, FigureError> {
        let path = self.path(file)?;
        std::fs::write(&path, text).map_err(|source| io(&path, source))?;
        Ok(path)
    }

    /// Write `csv` to `file`.
    ///
    /// # Errors
    /// [`FigureError::Io`].
    pub fn csv(&mut self, file: &str, csv: &Csv) -> Result<PathBuf, FigureError> {
        self.text(file, csv.as_str())
    }

    /// Write `rows` to `file` as CSV (the columns of
    /// [`SweepRow`], see [`csv_columns`](spinball_analysis::report::csv_columns)).
    ///
    /// # Errors
    /// [`FigureError::Io`].
    pub fn sweep_rows(&mut self, file: &str, rows: &[SweepRow]) -> Result<PathBuf, FigureError> {
        let text = csv_text(rows).map_err(|e| io(Path::new(file), std::io::Error::other(e)))?;
        self.text(file, &text)
    }

    /// Write `values` (row-major, of `shape`) to `file` as a float64 NPY
    /// array, for `numpy.load`.
    ///
    /// # Errors
    /// [`FigureError::Invalid`] if the shape does not hold `values.len()`
    /// numbers, [`FigureError::Io`].
    pub fn npy(
        &mut self,
        file: &str,
        shape: &[u64],
        values: &[f64],
    ) -> Result<PathBuf, FigureError> {
        if shape.iter().product::<u64>() != values.len() as u64 {
            return Err(FigureError::Invalid {
                what: "NPY shape",
                why: format!("{shape:?} does not hold {} values", values.len()),
            });
        }
        let path = self.path(file)?;
        let fail = |source| io(&path, source);
        let out = std::io::BufWriter::new(std::fs::File::create(&path).map_err(fail)?);
        let mut w = npyz::WriteOptions::new()
            .default_dtype()
            .shape(shape)
            .writer(out)
            .begin_nd()
            .map_err(fail)?;
        w.extend(values.iter().copied()).map_err(fail)?;
        w.finish().map_err(fail)?;
        Ok(path)
    }

    /// Write the JSON document `file`, a `spinball.figure` document of the
    /// one result schema ([`FigureDocument`]): `schema`, `kind`, the
    /// [`Header`] fields, then the fields of `body` (a struct or map),
    /// pretty-printed.
    ///
    /// # Errors
    /// [`FigureError::Json`] if `body` is not a struct or map (or fails to
    /// serialise), [`FigureError::Io`].
    pub fn json<T: Serialize + ?Sized>(
        &mut self,
        file: &str,
        body: &T,
    ) -> Result<PathBuf, FigureError> {
        let path = self.out.join(file);
        let json = |source| FigureError::Json {
            path: path.clone(),
            source,
        };
        let data = match serde_json::to_value(body).map_err(json)? {
            serde_json::Value::Object(fields) => fields,
            other => {
                return Err(json(serde::ser::Error::custom(format!(
                    "a figure's JSON body must be a struct or map, not {other}"
                ))));
            }
        };
        let h = &self.header;
        let mut doc = FigureDocument::new(&h.figure, &h.mode, h.seed, h.threads);
        doc.version.clone_from(&h.version);
        doc.data = data;
        let text = Document::Figure(doc)
            .to_json_pretty()
            .map_err(|e| match e {
                DocumentError::Json(source) => json(source),
                other => json(serde::ser::Error::custom(other)),
            })?;
        self.text(file, &(text + "\n"))
    }

    /// The closing line: `name (mode mode, N threads): wrote a, b in 1.2 s`.
    pub fn summary(&self) -> String {
        let files: Vec<String> = self.files.iter().map(|p| p.display().to_string()).collect();
        format!(
            "{} ({} mode, {} threads): wrote {} in {:.1} s",
            self.header.figure,
            self.header.mode,
            self.header.threads,
            files.join(", "),
            self.start.elapsed().as_secs_f64()
        )
    }

    /// Print [`summary`](Self::summary) after a blank line.
    pub fn finish(&self) {
        println!("\n{}", self.summary());
    }
}

fn io(path: &Path, source: std::io::Error) -> FigureError {
    FigureError::Io {
        path: path.to_path_buf(),
        source,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn report(dir: &Path) -> Report {
        let out = dir.to_str().unwrap().to_string();
        let args = FigureArgs::try_parse_from(
            "fig_test",
            "",
            ["--quick", "--seed", "5", "--threads", "2", "--out", &out],
        )
        .unwrap();
        Report::new("fig_test", &args)
    }

    fn temp(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("spinball-report-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    #[test]
    fn json_starts_with_the_header() {
        let dir = temp("json");
        let mut r = report(&dir);
        #[derive(Serialize)]
        struct Body {
            lambda: spinball_analysis::precision::Measurement,
            alphas: Vec<f64>,
        }
        let body = Body {
            lambda: spinball_analysis::precision::Measurement::new(0.25, 0.01),
            alphas: vec![0.0, 1.0],
        };
        let path = r.json("a.json", &body).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        // A document of the one result schema, read back whole.
        assert_eq!(v["kind"], "spinball.figure");
        let doc = Document::from_json(&text).unwrap().into_figure().unwrap();
        assert_eq!((doc.figure.as_str(), doc.seed), ("fig_test", 5));
        assert_eq!(doc.data["alphas"][1], 1.0);
        assert!(!doc.data.contains_key("schema"));
        // Old readers still find the header and the fields at the top.
        assert_eq!(v["figure"], "fig_test");
        assert_eq!(v["mode"], "quick");
        assert_eq!(v["seed"], 5);
        assert_eq!(v["threads"], 2);
        assert_eq!(v["version"], env!("CARGO_PKG_VERSION"));
        assert_eq!(v["lambda"]["value"], 0.25);
        assert_eq!(v["lambda"]["sem"], 0.01);
        assert_eq!(v["alphas"][1], 1.0);
        // A body that is not a struct or map has no fields to merge.
        assert!(matches!(
            r.json("b.json", &3.5),
            Err(FigureError::Json { .. })
        ));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn files_are_listed_once_in_order() {
        let dir = temp("files");
        let mut r = report(&dir);
        let mut csv = Csv::new(&["x"]);
        csv.row(&[&1]);
        r.csv("x.csv", &csv).unwrap();
        r.text("notes.md", "# notes\n").unwrap();
        r.csv("x.csv", &csv).unwrap();
        r.sweep_rows("rows.csv", &[]).unwrap();
        assert_eq!(
            r.files(),
            &[
                dir.join("x.csv"),
                dir.join("notes.md"),
                dir.join("rows.csv")
            ]
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("x.csv")).unwrap(),
            "x\n1\n"
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("rows.csv"))
                .unwrap()
                .trim_end(),
            spinball_analysis::report::csv_columns::<SweepRow>().join(",")
        );
        let s = r.summary();
        assert!(
            s.starts_with("fig_test (quick mode, 2 threads): wrote "),
            "{s}"
        );
        assert!(s.contains("x.csv, ") && s.ends_with(" s"), "{s}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
