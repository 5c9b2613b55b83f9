//! The paper's figure of single-trajectory LCN traces (App. A.1): per
//! table a log–log panel of the running exponent λ(t) at several α (from
//! [`lcn_traces`](spinball_analysis::precision::lcn_traces)), with a `1/t` guide on
//! the integrable tables; and their CSV rows and JSON records.

use serde::Serialize;
use spinball_analysis::precision::LcnTrace;

use crate::csv::Csv;
use spinball_plot::{Legend, LineKind, LinePlot, Series};
use spinball_plot::{RGBColor, viridis};

/// The columns of [`lcn_trace_rows`].
pub const LCN_TRACE_COLUMNS: [&str; 5] = ["table", "alpha", "collisions", "time", "lambda"];

/// Append every point of `traces` (of `table`, as `(α, trace)`) to `csv`
/// (made with [`LCN_TRACE_COLUMNS`]).
pub fn lcn_trace_rows(csv: &mut Csv, table: &str, traces: &[(f64, LcnTrace)]) {
    for (alpha, trace) in traces {
        for p in &trace.points {
            csv.row(&[&table, alpha, &p.collisions, &p.time, &p.exponent]);
        }
    }
}

/// The final exponent of one trace, as a JSON record.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LcnFinal {
    /// Spin parameter.
    pub alpha: f64,
    /// Collisions run.
    pub collisions: u64,
    /// The exponent after the last collision.
    pub final_lambda: f64,
    /// Table spec.
    pub table: String,
}

/// The final exponent of each of `traces` (of `table`).
#[must_use]
pub fn lcn_finals(table: &str, traces: &[(f64, LcnTrace)]) -> Vec<LcnFinal> {
    let finals = traces.iter().map(|(alpha, trace)| LcnFinal {
        alpha: *alpha,
        collisions: trace.collisions,
        final_lambda: trace.exponent,
        table: table.to_string(),
    });
    finals.collect()
}

/// λ(t) of each of `traces` against time on log–log axes, titled `title`,
/// coloured by α (viridis); with `one_over_t`, a dashed `∝ 1/t` guide
/// through λ = 1 at t = 1 (the decay on an integrable table).
#[must_use]
pub fn lcn_trace_panel(title: &str, traces: &[(f64, LcnTrace)], one_over_t: bool) -> LinePlot {
    let (x, y) = ("time t   (speed |v₀| = 1)", "running λ(t) (1/time)");
    let mut plot = LinePlot::with_axes(title, x, y).log_x(true).log_y(true);
    let last = traces.len().saturating_sub(1).max(1) as f64;
    let mut t_max: f64 = 1.0;
    for (k, (alpha, trace)) in traces.iter().enumerate() {
        let points = trace.points.iter().map(|p| (p.time, p.exponent));
        t_max = trace.points.iter().fold(t_max, |t, p| t.max(p.time));
        let line = Series::new(format!("α = {alpha}"), points).line_only();
        let color = viridis(k as f64 / last * 0.9);
        plot = plot.series(line.line_width(3).color(color));
    }
    if one_over_t {
        let guide = Series::new("∝ 1/t", [(1.0, 1.0), (t_max, 1.0 / t_max)]).line_only();
        plot = plot.series(guide.kind(LineKind::Dashed).color(RGBColor(120, 120, 120)));
    }
    plot.legend(Legend::LowerLeft)
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_analysis::estimators::Method;
    use spinball_analysis::precision::lcn_traces;
    use spinball_core::State;
    use spinball_geometry::{Circle, DVec2};
    use spinball_plot::Plot;

    #[test]
    fn rows_records_and_panel_of_circle_traces() {
        let circle = Circle::new(1.0).unwrap();
        let start = State::new(DVec2::new(0.3, 0.2), DVec2::from_angle(0.8), 0.0);
        let traces =
            lcn_traces(&circle, start, &[0.0, 1.0], 2_000, Method::default(), 10, 1).unwrap();
        let mut csv = Csv::new(&LCN_TRACE_COLUMNS);
        lcn_trace_rows(&mut csv, "circle:R=1", &traces);
        let n = traces[0].1.points.len() + traces[1].1.points.len();
        assert_eq!(csv.rows(), n);
        let last: Vec<&str> = csv.as_str().lines().last().unwrap().split(',').collect();
        assert_eq!(last[..3], ["circle:R=1", "1", "2000"]);
        assert_eq!(last[4].parse::<f64>().unwrap(), traces[1].1.exponent);
        let finals = lcn_finals("circle:R=1", &traces);
        assert_eq!(finals.len(), 2);
        assert_eq!((finals[1].alpha, finals[1].collisions), (1.0, 2_000));
        // The circle is integrable: λ(t) decays like ln t / t, far below
        // the stadium's 0.43 after 2000 collisions.
        assert!(finals[0].final_lambda < 0.02, "{}", finals[0].final_lambda);
        let panel = lcn_trace_panel("circle", &traces, true);
        assert!(panel.validate().is_ok());
        assert!(lcn_trace_panel("none", &[], false).validate().is_err());
    }
}
