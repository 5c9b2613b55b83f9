//! λ(α) curves of a figure: labelled sweeps run one after another, each
//! printing a section with a row per point on stdout as the points finish
//! (and [`Progress`] on stderr), then kept as [`Curve`]s that give plot
//! series, a summary, and the CSV and JSON files.
//!
//! Most figures of the paper are a few λ(α) curves. What differs between
//! them is which tables, methods and samplers they sweep and how they plot
//! the results; running the sweeps, showing that they are alive and writing
//! the records is the same every time and lives here.
//!
//! ```no_run
//! use spinball_figures::{FigureArgs, Job, Plan, Report, run_jobs, template, write_curves};
//!
//! let args = FigureArgs::parse_or_exit("fig_demo", "λ(α) of the stadium.");
//! let plan = args.pick(Plan::fixed(48, 2_000), Plan::fixed(1_000, 10_000), Plan::fixed(100_000, 50_000));
//! let job = Job::new("stadium a = 1", &plan, template(&args, "stadium:a=1")?, &[0.0, 0.5, 1.0])?;
//! let curves = run_jobs(vec![job])?;
//! println!("{}", curves[0].summary());
//! let mut report = Report::new("fig_demo", &args);
//! write_curves(&mut report, "demo", &curves, &())?;
//! # Ok::<(), spinball_figures::BoxError>(())
//! ```

use std::fmt;

use serde::Serialize;
use spinball_analysis::AnalysisError;
use spinball_analysis::precision::Measurement;
use spinball_analysis::report::SweepRow;
use spinball_analysis::run::{
    AlphaSweep, Control, Ensemble, LyapunovEstimate, RunEvent, RunObserver,
};
use spinball_core::SpinLaw;
use spinball_geometry::{Table, TableSpecError};

use crate::args::FigureArgs;
use crate::error::FigureError;
use crate::measured::measured;
use crate::plan::Plan;
use crate::progress::Progress;
use crate::report::Report;
use spinball_plot::Series;

/// The ensemble template of a figure on the table `spec` (e.g.
/// `stadium:a=1`): paper sampler, finite differences, the command line's
/// seed and threads.
///
/// # Errors
/// A spec that does not name a table.
pub fn template(args: &FigureArgs, spec: &str) -> Result<Ensemble, TableSpecError> {
    let table: Table = spec.parse()?;
    Ok(Ensemble::new(table, SpinLaw::specular())
        .with_seed(args.seed)
        .with_threads(args.threads))
}

/// One labelled sweep of a figure.
#[derive(Debug, Clone)]
pub struct Job {
    /// Legend label and section title (e.g. `stadium a = 1, fd`).
    pub label: String,
    /// The plan the sweep was sized by.
    pub plan: Plan,
    /// The sweep.
    pub sweep: AlphaSweep,
}

impl Job {
    /// The sweep of `template` sized by `plan` over `alphas`.
    ///
    /// # Errors
    /// As [`AlphaSweep::new`].
    pub fn new(
        label: impl Into<String>,
        plan: &Plan,
        template: Ensemble,
        alphas: &[f64],
    ) -> Result<Job, AnalysisError> {
        let sweep = plan.sweep(template, alphas)?;
        Ok(Job::of(label, plan, sweep))
    }

    fn of(label: impl Into<String>, plan: &Plan, sweep: AlphaSweep) -> Job {
        Job {
            label: label.into(),
            plan: *plan,
            sweep,
        }
    }

    /// As [`new`](Self::new) over any `α >= 0`, including α > 1.
    ///
    /// # Errors
    /// As [`Plan::sweep_extended`].
    pub fn extended(
        label: impl Into<String>,
        plan: &Plan,
        template: Ensemble,
        alphas: &[f64],
    ) -> Result<Job, AnalysisError> {
        let sweep = plan.sweep_extended(template, alphas)?;
        Ok(Job::of(label, plan, sweep))
    }
}

/// The results of one [`Job`].
#[derive(Debug, Clone)]
pub struct Curve {
    /// Its label.
    pub label: String,
    /// The plan it was run with.
    pub plan: Plan,
    /// One estimate per α, in order.
    pub estimates: Vec<LyapunovEstimate>,
    /// The record of each estimate.
    pub rows: Vec<SweepRow>,
}

impl Curve {
    /// The curve of `estimates` (their records are computed here).
    ///
    /// # Errors
    /// As [`SweepRow::from_estimate`].
    pub fn new(
        label: impl Into<String>,
        plan: Plan,
        estimates: Vec<LyapunovEstimate>,
    ) -> Result<Curve, AnalysisError> {
        let rows = spinball_analysis::report::sweep_rows(&estimates)?;
        Ok(Curve {
            label: label.into(),
            plan,
            estimates,
            rows,
        })
    }

    /// The α values.
    pub fn alphas(&self) -> Vec<f64> {
        self.estimates.iter().map(|e| e.alpha()).collect()
    }

    /// `(α, value(estimate))` per point.
    pub fn points(
        &self,
        value: impl Fn(&LyapunovEstimate) -> Measurement,
    ) -> Vec<(f64, Measurement)> {
        self.estimates
            .iter()
            .map(|e| (e.alpha(), value(e)))
            .collect()
    }

    /// `(α, value(estimate))` per point, for a value that can fail.
    ///
    /// # Errors
    /// The first error of `value`.
    pub fn try_points<E>(
        &self,
        value: impl Fn(&LyapunovEstimate) -> Result<Measurement, E>,
    ) -> Result<Vec<(f64, Measurement)>, E> {
        self.estimates
            .iter()
            .map(|e| Ok((e.alpha(), value(e)?)))
            .collect()
    }

    /// `value(estimate)` against α with error bars, labelled `label`.
    pub fn series(
        &self,
        label: impl Into<String>,
        value: impl Fn(&LyapunovEstimate) -> Measurement,
    ) -> Series {
        measured(label, self.points(value))
    }

    /// λ(α) ± SEM labelled with the curve's label.
    pub fn lambda_series(&self) -> Series {
        self.series(self.label.clone(), Measurement::lambda)
    }

    /// First and last point, smallest and largest λ.
    ///
    /// # Panics
    /// For a curve without points (a sweep always has one).
    pub fn summary(&self) -> CurveSummary {
        let e = &self.estimates;
        let point = |e: &LyapunovEstimate| (e.alpha(), Measurement::lambda(e));
        let by_mean = |a: &&LyapunovEstimate, b: &&LyapunovEstimate| a.mean().total_cmp(&b.mean());
        let (first, last) = (point(&e[0]), point(&e[e.len() - 1]));
        CurveSummary {
            label: self.label.clone(),
            first,
            last,
            relative_drop: 1.0 - last.1.value / first.1.value,
            min: point(e.iter().min_by(by_mean).expect("a point")),
            max: point(e.iter().max_by(by_mean).expect("a point")),
        }
    }
}

/// The shape of a λ(α) curve in a few numbers, as `(α, λ ± SEM)` pairs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurveSummary {
    /// The curve's label.
    pub label: String,
    /// The first point (α = 0 in the paper's sweeps).
    pub first: (f64, Measurement),
    /// The last point (α = 1).
    pub last: (f64, Measurement),
    /// `1 − λ(last)/λ(first)`: the paper's "66% reduction".
    pub relative_drop: f64,
    /// The point of smallest λ.
    pub min: (f64, Measurement),
    /// The point of largest λ.
    pub max: (f64, Measurement),
}

impl fmt::Display for CurveSummary {
    /// `label: lambda(0) = 0.4297 ± 0.0005, lambda(1) = 0.1467 ± 0.0014 (drop 65.9%), min 0.1467 ± 0.0014 at alpha 1`
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let p = |(a, m): (f64, Measurement)| format!("lambda({a}) = {:.4} ± {:.4}", m.value, m.sem);
        write!(
            f,
            "{}: {}, {} (drop {:.1}%), min {:.4} ± {:.4} at alpha {}",
            self.label,
            p(self.first),
            p(self.last),
            100.0 * self.relative_drop,
            self.min.1.value,
            self.min.1.sem,
            self.min.0
        )
    }
}

/// Run `jobs` in order: a section per job on stdout (label, table, method,
/// sampler, seed, threads, then [`SweepRow::table_line`] per point as it
/// finishes) and one [`Progress`] over all points on stderr.
///
/// # Errors
/// The first error of a sweep.
pub fn run_jobs(jobs: Vec<Job>) -> Result<Vec<Curve>, AnalysisError> {
    let total = jobs.iter().map(|j| j.sweep.laws.len()).sum();
    let mut progress = Progress::stderr(total);
    let mut curves = Vec::with_capacity(jobs.len());
    for job in jobs {
        let t = &job.sweep.template;
        println!(
            "\n{} | {} | {} | sampler {} | seed {} | {} threads",
            job.label,
            t.table,
            t.method.name(),
            t.sampler().map_or("states", |s| s.name()),
            t.seed,
            t.threads.count()
        );
        println!("{}", SweepRow::table_header());
        progress.set_label(job.label.clone());
        let estimates = job.sweep.run_observed(&mut |event: &RunEvent<'_>| {
            progress.observe(event);
            if let RunEvent::Finished { estimate, .. } = event
                && let Ok(row) = SweepRow::from_estimate(estimate)
            {
                progress.clear();
                println!("{}", row.table_line());
            }
            Control::Continue
        })?;
        curves.push(Curve::new(job.label, job.plan, estimates)?);
    }
    progress.finish();
    Ok(curves)
}

#[derive(Serialize)]
struct CurveRecord<'a> {
    label: &'a str,
    plan: &'a Plan,
    points: &'a [SweepRow],
}

#[derive(Serialize)]
struct CurvesBody<'a, E: ?Sized> {
    total_wall_time_s: f64,
    series: Vec<CurveRecord<'a>>,
    #[serde(flatten)]
    extra: &'a E,
}

/// Write every curve's rows to `<stem>.csv` (the columns of [`SweepRow`]) and the JSON document `<stem>.json`: the report's header, the
/// total wall time, `series` (label, plan and points of each curve) and the
/// fields of `extra` (a struct or map; `&()` for none).
///
/// # Errors
/// As [`Report::sweep_rows`] and [`Report::json`].
pub fn write_curves<E: Serialize + ?Sized>(
    report: &mut Report,
    stem: &str,
    curves: &[Curve],
    extra: &E,
) -> Result<(), FigureError> {
    let rows: Vec<SweepRow> = curves.iter().flat_map(|c| c.rows.clone()).collect();
    report.sweep_rows(&format!("{stem}.csv"), &rows)?;
    let body = CurvesBody {
        total_wall_time_s: curves
            .iter()
            .flat_map(|c| &c.estimates)
            .map(|e| e.wall_time_s())
            .sum(),
        series: curves
            .iter()
            .map(|c| CurveRecord {
                label: &c.label,
                plan: &c.plan,
                points: &c.rows,
            })
            .collect(),
        extra,
    };
    report.json(&format!("{stem}.json"), &body)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(out: &std::path::Path) -> FigureArgs {
        let out = out.to_str().unwrap().to_string();
        FigureArgs::try_parse_from(
            "fig_t",
            "",
            ["--quick", "--seed", "3", "--threads", "1", "--out", &out],
        )
        .unwrap()
    }

    #[test]
    fn jobs_run_into_curves_and_files() {
        let dir = std::env::temp_dir().join(format!("spinball-curves-{}", std::process::id()));
        let args = args(&dir);
        let plan = Plan::fixed(8, 500);
        let t = template(&args, "stadium:a=1").unwrap();
        assert_eq!(
            (t.seed, t.threads),
            (3, spinball_analysis::run::Threads::Fixed(1))
        );
        assert!(template(&args, "oval").is_err());
        let jobs = vec![
            Job::new("a", &plan, t.clone(), &[0.0, 1.0]).unwrap(),
            Job::new(
                "b",
                &plan,
                t.with_method(spinball_analysis::estimators::Method::Tangent),
                &[0.5],
            )
            .unwrap(),
        ];
        let curves = run_jobs(jobs).unwrap();
        assert_eq!(curves.len(), 2);
        let c = &curves[0];
        assert_eq!((c.alphas(), c.rows.len()), (vec![0.0, 1.0], 2));
        assert_eq!(c.rows[1].mean, c.estimates[1].mean());
        assert_eq!(c.estimates[0].n_ics(), 8);
        let fraction = |e: &LyapunovEstimate| Measurement::new(e.chaotic_fraction(), 0.0);
        assert_eq!(c.points(fraction)[1], (1.0, fraction(&c.estimates[1])));
        let fallible = |e: &LyapunovEstimate| {
            if e.alpha() == 0.0 {
                Ok(Measurement::lambda(e))
            } else {
                Err("no")
            }
        };
        assert_eq!(c.try_points(fallible), Err("no"));
        assert_eq!(
            curves[1]
                .try_points(|e| Ok::<_, ()>(Measurement::lambda(e)))
                .unwrap()
                .len(),
            1
        );
        let s = c.summary();
        assert_eq!((s.first.0, s.last.0), (0.0, 1.0));
        assert_eq!(
            s.relative_drop,
            1.0 - c.estimates[1].mean() / c.estimates[0].mean()
        );
        assert!(s.min.1.value <= s.max.1.value);
        assert!(s.to_string().starts_with("a: lambda(0) = "), "{s}");

        let mut report = Report::new("fig_t", &args);
        #[derive(Serialize)]
        struct Extra {
            note: &'static str,
        }
        write_curves(&mut report, "t", &curves, &Extra { note: "hi" }).unwrap();
        let csv = std::fs::read_to_string(dir.join("t.csv")).unwrap();
        assert_eq!(csv.lines().count(), 4); // header + 3 points
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("t.json")).unwrap()).unwrap();
        assert_eq!(v["figure"], "fig_t");
        assert_eq!(v["note"], "hi");
        assert_eq!(v["series"][1]["label"], "b");
        assert_eq!(v["series"][1]["plan"]["max_ics"], 8);
        assert_eq!(v["series"][0]["points"][1]["alpha"], 1.0);
        assert_eq!(v["series"][1]["points"][0]["method"], "tangent");
        write_curves(&mut report, "u", &curves, &()).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
