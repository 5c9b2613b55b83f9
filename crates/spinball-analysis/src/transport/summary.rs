//! The summary of a diffusion run: every number the fronts print and save
//! (the horizon, `⟨Δr²⟩(t)` with its errors, `D` or the marginal
//! coefficient with its window, the scan over windows), computed once from
//! the per-IC records so that the command line, the Python package and the
//! examples report the same thing.
//!
//! Documented in the group docs (`transport/mod.rs`) and
//! `docs/TRANSPORT.md`.

use std::fmt;

use super::{
    Diffusion, Displacements, FitWindow, Horizon, MeanSquareDisplacement, TransportError,
    WindowScan, diffusion, window_scan,
};
use crate::estimators::Fitted;
use crate::open::DisplacementRecord;

/// The summary of a diffusion run: the horizon, `⟨Δr²⟩(t)`, the estimate
/// and the window scan.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct DiffusionSummary {
    /// The table's horizon, which decides the growth law fitted.
    pub horizon: Horizon,
    /// `⟨Δr²⟩(t)` with its SEM at every checkpoint.
    pub msd: MeanSquareDisplacement,
    /// `D` (finite horizon) or the marginal coefficient `D_m` (infinite
    /// horizon), with its error, on the window asked for
    /// ([`FitWindow::later_half`] by default).
    pub estimate: Fitted<Diffusion>,
    /// The estimate on the halving windows and its trend in `ln t`.
    pub scan: Fitted<WindowScan>,
}

impl DiffusionSummary {
    /// The summary of `records` (one per initial condition, each with a
    /// displacement at every one of `times`) on a table of `horizon`,
    /// fitted on `window` (`None`: the later half).
    ///
    /// # Errors
    /// The [`Displacements::new`] errors (times, shape, at least two ICs,
    /// finite values). A fit that cannot be made (too few checkpoints in a
    /// window) is [`Fitted::Refused`] with the reason.
    pub fn new(
        times: &[f64],
        records: &[DisplacementRecord],
        horizon: Horizon,
        window: Option<FitWindow>,
    ) -> Result<Self, TransportError> {
        let dr = DisplacementRecord::rows(records);
        let d = Displacements::new(times, &dr)?;
        Ok(DiffusionSummary {
            horizon,
            msd: MeanSquareDisplacement::new(&d),
            estimate: Fitted::from_result(diffusion(&d, horizon, window)),
            scan: Fitted::from_result(window_scan(&d, horizon)),
        })
    }
}

impl fmt::Display for DiffusionSummary {
    /// The table a front prints.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{} initial conditions, {} checkpoints to t = {}; {} horizon",
            self.msd.n_ics(),
            self.msd.points().len(),
            self.msd.points().last().map_or(0.0, |p| p.t),
            self.horizon
        )?;
        writeln!(f, "  estimate {}", self.estimate)?;
        match &self.scan {
            Fitted::Fit(scan) => {
                for (w, a) in scan.windows.iter().zip(&scan.apparent_d) {
                    let fit = w.fit();
                    writeln!(
                        f,
                        "  window [{}, {}]: {} (apparent D {})",
                        fit.window.t0,
                        fit.window.t1,
                        crate::estimators::PlusMinus::new(fit.coefficient, fit.sem),
                        crate::estimators::PlusMinus::new(a.coefficient, a.sem)
                    )?;
                }
                match scan.trend {
                    Some(t) => writeln!(
                        f,
                        "  trend of the apparent D per unit ln t: {} ({:.1} SE)",
                        crate::estimators::PlusMinus::new(t.per_ln_t, t.sem),
                        t.z()
                    ),
                    None => writeln!(f, "  trend: one window only"),
                }
            }
            Fitted::Refused(why) => writeln!(f, "  window scan: none ({why})"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn the_summary_is_the_blocks_applied_to_the_records() {
        let times: Vec<f64> = (1..=12).map(f64::from).collect();
        let records: Vec<DisplacementRecord> = (0..5u32)
            .map(|i| DisplacementRecord {
                index: u64::from(i),
                displacement: times
                    .iter()
                    .map(|t| DVec2::new((t * f64::from(i + 1)).sqrt(), 0.1 * t))
                    .collect(),
                collisions: 0,
                crossings: 0,
            })
            .collect();
        let dr = DisplacementRecord::rows(&records);
        let d = Displacements::new(&times, &dr).unwrap();
        for horizon in [Horizon::Finite, Horizon::Infinite] {
            let s = DiffusionSummary::new(&times, &records, horizon, None).unwrap();
            assert_eq!(s.msd, MeanSquareDisplacement::new(&d));
            assert_eq!(
                s.estimate,
                Fitted::Fit(diffusion(&d, horizon, None).unwrap())
            );
            assert_eq!(s.scan, Fitted::Fit(window_scan(&d, horizon).unwrap()));
        }
        let narrow = FitWindow::new(11.5, 12.0).unwrap();
        let s = DiffusionSummary::new(&times, &records, Horizon::Finite, Some(narrow)).unwrap();
        assert!(
            s.estimate
                .refused()
                .unwrap()
                .contains("checkpoints in the fit window")
        );
        assert!(s.to_string().contains("finite horizon"), "{s}");
    }
}
