//! The paper's collision-rate figure (App. A.3) of several λ(α) curves:
//! 2 × 2 panels of ν(α) relative to Santaló's α = 0 rate on linear and
//! logarithmic α axes, the exponent per collision λ/ν and λ per unit time,
//! with the mean speeds of the paper's initial conditions and of the
//! invariant measure at α > 0 as reference lines.
//!
//! On the log axis α = 0 has no place; its values are drawn at half the
//! smallest α > 0, at the left edge.

use spinball_analysis::diagnostics::initial_mean_speed;
use spinball_core::Sampler;

use crate::curves::Curve;
use crate::figure::BoxError;
use crate::measured::{ALPHA_LABEL, LAMBDA_LABEL, measured};
use crate::rates::CurveRates;
use spinball_plot::{Grid, Legend, LineKind, LinePlot, Series};
use spinball_plot::{RGBColor, palette};

/// The y label of the ν panels.
const RELATIVE: &str = "ν / ν_Santaló(α = 0)";

/// A dotted horizontal line at the mean speed of `sampler`'s initial
/// conditions at α > 0 (the rate relative to Santaló's if only the speed
/// changed), from `from` to `to`.
fn speed_guide(label: &str, sampler: Sampler, from: f64, to: f64, color: RGBColor) -> Series {
    let y = initial_mean_speed(sampler, 1.0);
    let line = Series::new(label, [(from, y), (to, y)]).line_only();
    line.kind(LineKind::Dotted).color(color)
}

/// The collision-rate figure of `curves` (run over `alphas`, one of them
/// positive): curve `i` drawn in `palette(i)`, solid for even `i` and
/// dashed for odd `i` (pairs of samplers on one table); and the rates of
/// each curve ([`CurveRates::of`]).
///
/// # Errors
/// No α > 0 (nothing to put on the log axis), and as [`CurveRates::of`].
pub fn collision_rate_grid(
    curves: &[Curve],
    alphas: &[f64],
) -> Result<(Grid, Vec<CurveRates>), BoxError> {
    let positive = alphas.iter().copied().filter(|&a| a > 0.0);
    let lo = positive.clone().fold(f64::INFINITY, f64::min);
    let hi = positive.fold(f64::NEG_INFINITY, f64::max);
    if !(lo.is_finite() && hi.is_finite()) {
        return Err("a collision-rate figure needs an α > 0 for its log axis".into());
    }
    let zero_x = lo / 2.0; // where the α = 0 values sit on the log axis
    let title = "Collision rate (relative to Santaló's α = 0 rate)";
    let mut nu_lin = LinePlot::with_axes(title, ALPHA_LABEL, RELATIVE);
    let title = "Near α = 0⁺ (log α; α = 0 values at left)";
    let mut nu_log = LinePlot::with_axes(title, "spin parameter α (log scale)", RELATIVE)
        .log_x(true)
        .legend(Legend::Hidden);
    let title = "Exponent per collision λ/ν";
    let mut per_coll = LinePlot::with_axes(title, ALPHA_LABEL, "λ/ν (per collision)");
    let title = "Exponent per unit time λ";
    let mut lambda = LinePlot::with_axes(title, ALPHA_LABEL, LAMBDA_LABEL);
    let mut rates = Vec::with_capacity(curves.len());
    for (i, c) in curves.iter().enumerate() {
        let r = CurveRates::of(c)?;
        let kind = [LineKind::Solid, LineKind::Dashed][i % 2];
        let style = |s: Series| s.kind(kind).color(palette(i));
        let relative = r.relative_nu();
        let log_x = relative
            .iter()
            .map(|&(a, m)| (if a > 0.0 { a } else { zero_x }, m));
        nu_lin = nu_lin.series(style(measured(c.label.clone(), relative.clone())));
        nu_log = nu_log.series(style(measured(c.label.clone(), log_x)));
        per_coll = per_coll.series(style(measured(c.label.clone(), r.per_collision.clone())));
        lambda = lambda.series(style(c.lambda_series()));
        rates.push(r);
    }
    let (paper, micro) = (Sampler::Paper, Sampler::Microcanonical);
    let (black, grey) = (palette(6), RGBColor(0x70, 0x70, 0x70));
    let nu_lin = nu_lin
        .series(speed_guide(
            "paper ICs, α > 0: ⟨|v|⟩ = 0.957",
            paper,
            0.0,
            hi,
            black,
        ))
        .series(speed_guide(
            "invariant measure, α > 0: ⟨|v|⟩ = π/4",
            micro,
            0.0,
            hi,
            grey,
        ))
        .legend(Legend::UpperRight);
    let nu_log = nu_log
        .series(speed_guide("", paper, zero_x, hi, black))
        .series(speed_guide("", micro, zero_x, hi, grey));
    let plots = [nu_lin, nu_log, per_coll, lambda];
    let grid = plots.into_iter().fold(Grid::new(2, 2), Grid::panel);
    Ok((grid, rates))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::Plan;
    use spinball_analysis::run::{AlphaSweep, Ensemble, Threads};
    use spinball_core::SpinLaw;
    use spinball_geometry::Table;
    use spinball_plot::Plot;

    #[test]
    fn grid_and_rates_of_two_samplers() {
        let table: Table = "stadium:a=1".parse().unwrap();
        let alphas = [0.0, 0.01, 1.0];
        let curve = |sampler| {
            let template = Ensemble::new(table, SpinLaw::specular())
                .with_sampler(sampler)
                .with_ics(6)
                .with_collisions(400)
                .with_threads(Threads::Fixed(1));
            let estimates = AlphaSweep::new(template, &alphas).unwrap().run().unwrap();
            Curve::new(format!("{sampler}"), Plan::fixed(6, 400), estimates).unwrap()
        };
        let curves = [curve(Sampler::Paper), curve(Sampler::Microcanonical)];
        let (grid, rates) = collision_rate_grid(&curves, &alphas).unwrap();
        assert!(grid.validate().is_ok());
        assert_eq!(rates.len(), 2);
        assert_eq!(rates[1], CurveRates::of(&curves[1]).unwrap());
        assert_eq!(rates[1].sampler, "microcanonical");
        // At α = 0 the paper's ICs (speed 1, uniform position and
        // direction) are the invariant measure: ν is Santaló's rate, here
        // from 2400 collisions to a few per cent.
        let nu0 = rates[0].relative_nu()[0];
        assert_eq!(nu0.0, 0.0);
        assert!((nu0.1.value - 1.0).abs() < 0.1, "{:?}", nu0.1);
        assert!(collision_rate_grid(&curves, &[0.0]).is_err());
    }
}
