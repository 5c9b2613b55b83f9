//! Work–precision figures and tables: error against wall time per method
//! and engine, finite-time bias against `T`, SEM against `N`, planned time
//! to a target, plain against multilevel estimators, and the CSV rows of
//! a work–precision set (the `work_precision` example and
//! docs/ACCURACY.md).

use spinball_analysis::estimators::Method;
use spinball_analysis::precision::{
    EstimatorComparison, EstimatorKind, EstimatorRun, MultilevelEstimate, Planner, Reference,
    WorkPoint,
};
use spinball_analysis::run::Engine;

use crate::csv::{Csv, optional};
use spinball_plot::palette;
use spinball_plot::{LineKind, LinePlot, RGBColor, Series};

/// `FD δ0=1e-7, lanes` or `tangent, scalar`.
#[must_use]
pub fn method_label(method: Method, engine: Engine) -> String {
    match method.delta0() {
        Some(d) => format!("FD δ0={d:e}, {}", engine.name()),
        None => format!("tangent, {}", engine.name()),
    }
}

/// The columns of [`work_rows`].
pub const WORK_COLUMNS: [&str; 14] = [
    "table",
    "alpha",
    "method",
    "delta0",
    "engine",
    "ics",
    "collisions",
    "wall_time_s",
    "ns_per_step",
    "mean",
    "sem",
    "error",
    "error_sem",
    "rel_error",
];

/// Append one row per point of the scene `table` at `alpha` to `csv`
/// (made with [`WORK_COLUMNS`]).
pub fn work_rows(csv: &mut Csv, table: &str, alpha: f64, points: &[WorkPoint]) {
    for p in points {
        csv.row(&[
            &table,
            &alpha,
            &p.method.name(),
            &optional(p.method.delta0()),
            &p.engine.name(),
            &p.budget.ics,
            &p.budget.collisions,
            &p.wall_time_s,
            &p.ns_per_step,
            &p.estimate.value,
            &p.estimate.sem,
            &p.error.value,
            &p.error.sem,
            &p.rel_error,
        ]);
    }
}

/// `plot` with one curve per method and engine of `points` (in order of
/// appearance): relative error against wall time, one point per budget;
/// colour per method, dashed for the scalar engine.
#[must_use]
pub fn error_vs_time(mut plot: LinePlot, points: &[WorkPoint]) -> LinePlot {
    let mut methods: Vec<Method> = Vec::new();
    let mut curves: Vec<(Method, Engine)> = Vec::new();
    for p in points {
        if !methods.contains(&p.method) {
            methods.push(p.method);
        }
        if !curves.contains(&(p.method, p.engine)) {
            curves.push((p.method, p.engine));
        }
    }
    for (m, e) in curves {
        let line = points
            .iter()
            .filter(|p| p.method == m && p.engine == e)
            .map(|p| (p.wall_time_s, p.rel_error));
        let kind = match e {
            Engine::Scalar => LineKind::Dashed,
            Engine::Lanes => LineKind::Solid,
        };
        let color = palette(methods.iter().position(|&x| x == m).unwrap_or(0));
        plot = plot.series(
            Series::new(method_label(m, e), line)
                .kind(kind)
                .color(color),
        );
    }
    plot
}

/// The finite-time bias `|λ_T − λ_ref| / λ_ref` of `reference`'s own
/// checkpoints against `T`.
#[must_use]
pub fn bias_vs_t(label: impl Into<String>, reference: &Reference) -> Series {
    let lam = reference.value.value;
    let b = &reference.bias;
    let points = b.checkpoints.iter().zip(&b.means);
    Series::new(
        label,
        points.map(|(&t, m)| (t as f64, ((m.value - lam) / lam).abs())),
    )
}

/// `SEM / λ_ref` against `N` for the points of `method` and `engine`.
#[must_use]
pub fn sem_vs_n(
    label: impl Into<String>,
    points: &[WorkPoint],
    reference: &Reference,
    method: Method,
    engine: Engine,
) -> Series {
    let lam = reference.value.value.abs();
    let mine = points
        .iter()
        .filter(|p| p.method == method && p.engine == engine);
    Series::new(
        label,
        mine.map(|p| (p.budget.ics as f64, p.estimate.sem / lam)),
    )
}

/// `plot` with one curve per pilot method of `planner`: predicted wall
/// time against each reachable target of `targets` (relative total
/// errors).
#[must_use]
pub fn time_to_target(mut plot: LinePlot, planner: &Planner, targets: &[f64]) -> LinePlot {
    let plans: Vec<_> = targets.iter().map(|&t| (t, planner.plans(t))).collect();
    for (i, pilot) in planner.pilots.iter().enumerate() {
        let line = plans.iter().filter_map(|(t, runs)| {
            let run = runs.as_ref().ok()?.get(i)?.as_ref().ok()?;
            Some((*t, run.predicted_wall_s))
        });
        let label = method_label(pilot.method, pilot.engine);
        plot = plot.series(Series::new(label, line).color(palette(i)));
    }
    plot
}

/// The columns of [`estimator_rows`].
pub const ESTIMATOR_COLUMNS: [&str; 16] = [
    "table",
    "alpha",
    "target",
    "estimator",
    "seed",
    "collisions",
    "ics",
    "ic_steps",
    "cpu_s",
    "wall_s",
    "mean",
    "sem",
    "total",
    "deviation",
    "deviation_sem",
    "pull",
];

/// Append one row per run (plain, then multilevel) of `comparison` on the
/// scene `table` at `alpha` to `csv` (made with [`ESTIMATOR_COLUMNS`]).
pub fn estimator_rows(csv: &mut Csv, table: &str, alpha: f64, comparison: &EstimatorComparison) {
    let runs = comparison.plain.iter().chain(&comparison.multilevel);
    for r in runs {
        csv.row(&[
            &table,
            &alpha,
            &comparison.target_rel,
            &r.kind.name(),
            &r.seed,
            &r.collisions,
            &r.ics,
            &r.ic_steps,
            &r.cpu_s,
            &r.wall_s,
            &r.value.value,
            &r.value.sem,
            &r.total,
            &r.deviation.value,
            &r.deviation.sem,
            &r.pull(),
        ]);
    }
}

/// `plot` with the plain (solid) and multilevel (dashed) curves of one
/// scene in `color`: median stated relative total error against median
/// processor time, one point per comparison (target).
#[must_use]
pub fn estimator_curves(
    mut plot: LinePlot,
    scene: &str,
    color: RGBColor,
    comparisons: &[EstimatorComparison],
) -> LinePlot {
    for (kind, line) in [
        (EstimatorKind::Plain, LineKind::Solid),
        (EstimatorKind::Multilevel, LineKind::Dashed),
    ] {
        let points: Vec<(f64, f64)> = comparisons
            .iter()
            .filter(|c| !runs_of(c, kind).is_empty())
            .map(|c| (c.median_cpu(kind), c.median_rel_total(kind)))
            .collect();
        if !points.is_empty() {
            let label = format!("{scene}, {}", kind.name());
            plot = plot.series(Series::new(label, points).kind(line).color(color));
        }
    }
    plot
}

fn runs_of(c: &EstimatorComparison, kind: EstimatorKind) -> &[EstimatorRun] {
    match kind {
        EstimatorKind::Plain => &c.plain,
        EstimatorKind::Multilevel => &c.multilevel,
    }
}

/// The correction variances `V_l` of a multilevel estimate against the
/// run lengths `T_l` of its correction levels (`l ≥ 1`).
#[must_use]
pub fn level_variances(label: impl Into<String>, estimate: &MultilevelEstimate) -> Series {
    let points = estimate
        .levels
        .iter()
        .skip(1)
        .map(|l| (l.collisions as f64, l.variance));
    Series::new(label, points)
}
