//! The paper's published numbers as plain data, each with the place it
//! comes from.
//!
//! Documented in the group docs (`diagnostics/mod.rs`), section "The paper's numbers".

use crate::precision::Measurement;

/// λ(α) of the stadium `a = 1`, as `(α, λ)`:
/// - α = 0: ≈ 0.43 (§IV, Fig. 2);
/// - α = 0.1, 0.5, 1: 0.280, 0.183, 0.147 (Table I, 5·10⁵ collisions);
/// - α = 0.4 (solid sphere, α = 2/5): ≈ 0.20 (§IV).
pub const STADIUM_LAMBDA: [(f64, f64); 5] = [
    (0.0, 0.43),
    (0.1, 0.280),
    (0.4, 0.20),
    (0.5, 0.183),
    (1.0, 0.147),
];

/// λ(α) of the Sinai table `L = 2, R = 1`, as `(α, λ)`:
/// - α = 0: ≈ 0.43 (§IV, Fig. 2);
/// - α = 0.1: 0.211 (Table I, 10⁴ and 5·10⁴ collisions);
/// - α = 0.4 (solid sphere): ≈ 0.12 (§IV);
/// - α = 0.5: 0.119 (Table I, 5·10⁴ to 5·10⁵ collisions);
/// - α = 1: 0.102 (Table I, 10⁵ and 5·10⁵ collisions).
pub const SINAI_LAMBDA: [(f64, f64); 5] = [
    (0.0, 0.43),
    (0.1, 0.211),
    (0.4, 0.12),
    (0.5, 0.119),
    (1.0, 0.102),
];

/// Circle and rectangle: "the LCN is consistent with zero (≲ 10⁻⁴) for
/// all α" (§IV, Fig. 2) — a statement about the paper's run length, since a
/// regular trajectory's finite-time exponent decays like `ln t / t`.
pub const INTEGRABLE_LAMBDA_BOUND: f64 = 1e-4;

/// One row of Table I: the ensemble-averaged exponent of one table at one
/// α after each of [`TABLE_I_COLLISIONS`] collisions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableIEntry {
    /// Table spec (`stadium:a=1` or `sinai:L=2,R=1`).
    pub table: &'static str,
    /// Spin parameter.
    pub alpha: f64,
    /// λ ± SEM per column, the SEM as printed in units of the last digit
    /// (`0.183(1)` is `0.183 ± 0.001`, `0.281(0)` is `0.281 ± 0`).
    pub lambda: [Measurement; 4],
}

/// The collision counts of Table I's columns (App. A.1).
pub const TABLE_I_COLLISIONS: [u64; 4] = [10_000, 50_000, 100_000, 500_000];

/// Initial conditions per entry of Table I (App. A.1).
pub const TABLE_I_ICS: u64 = 10_000;

/// Decimals Table I prints.
pub const TABLE_I_DECIMALS: usize = 3;

const fn m(value: f64, sem: f64) -> Measurement {
    Measurement { value, sem }
}

/// Table I (App. A.1): "ensemble-averaged LCN ± SEM … stable to three
/// significant figures across all collision counts".
pub const TABLE_I: [TableIEntry; 6] = [
    TableIEntry {
        table: "stadium:a=1",
        alpha: 0.1,
        lambda: [m(0.281, 0.0), m(0.280, 0.0), m(0.279, 0.0), m(0.280, 0.0)],
    },
    TableIEntry {
        table: "stadium:a=1",
        alpha: 0.5,
        lambda: [
            m(0.183, 0.001),
            m(0.183, 0.001),
            m(0.183, 0.001),
            m(0.183, 0.001),
        ],
    },
    TableIEntry {
        table: "stadium:a=1",
        alpha: 1.0,
        lambda: [
            m(0.147, 0.001),
            m(0.147, 0.001),
            m(0.146, 0.001),
            m(0.147, 0.001),
        ],
    },
    TableIEntry {
        table: "sinai:L=2,R=1",
        alpha: 0.1,
        lambda: [m(0.211, 0.0), m(0.211, 0.0), m(0.210, 0.0), m(0.210, 0.0)],
    },
    TableIEntry {
        table: "sinai:L=2,R=1",
        alpha: 0.5,
        lambda: [m(0.120, 0.0), m(0.119, 0.0), m(0.119, 0.0), m(0.119, 0.0)],
    },
    TableIEntry {
        table: "sinai:L=2,R=1",
        alpha: 1.0,
        lambda: [m(0.103, 0.0), m(0.103, 0.0), m(0.102, 0.0), m(0.102, 0.0)],
    },
];

/// The Table I entry for `table` (a spec as in [`TableIEntry::table`]) at
/// `alpha` after `collisions` collisions, if the paper lists one.
pub fn table_i(table: &str, alpha: f64, collisions: u64) -> Option<Measurement> {
    let column = TABLE_I_COLLISIONS.iter().position(|&c| c == collisions)?;
    TABLE_I
        .iter()
        .find(|e| e.table == table && e.alpha == alpha)
        .map(|e| e.lambda[column])
}

/// Chaotic fraction (FTLE > 0.01) of the stadium `a = 1` at α = 1:
/// "reaching ~90% for the stadium" (§VI, Fig. 4).
pub const STADIUM_CHAOTIC_FRACTION_ALPHA1: f64 = 0.90;

/// Chaotic fraction of the Sinai table `L = 2, R = 1` at α = 1: "~87% for
/// the Sinai at α = 1" (§VI, Fig. 4).
pub const SINAI_CHAOTIC_FRACTION_ALPHA1: f64 = 0.87;

/// Largest shift of the chaotic fraction when the threshold moves within
/// 0.001–0.05: "less than 1 percentage point" (§VI, Fig. 4).
pub const THRESHOLD_BAND_WIDTH: f64 = 0.01;

/// `ln(δ₅₀/δ0)` after 50 collisions without renormalisation: "the
/// separation after 50 collisions is ~10⁻⁷e¹⁵ ≈ 10⁻¹" (§VII.A, Fig. 5).
pub const SEPARATION_LN_RATIO_50: f64 = 15.0;

/// Share of collisions on the obstacle of the Sinai table `L = 2` by
/// radius, as `(R, share)`: "~15% (R = 0.3)", "R = 0.8–1.0 (26–29%
/// curved)", "~50% (R = 1.5)" (§X, Fig. 8).
pub const SINAI_CURVED_SHARE_BY_RADIUS: [(f64, f64); 4] =
    [(0.3, 0.15), (0.8, 0.26), (1.0, 0.29), (1.5, 0.50)];

/// λ(0) of the Sinai table `L = 2` by radius, as `(R, λ)`: "R = 0.3:
/// λ(0) ≈ 0.13", "R = 1.5 … λ(0) ≈ 0.47" (§X, Fig. 8).
pub const SINAI_LAMBDA0_BY_RADIUS: [(f64, f64); 2] = [(0.3, 0.13), (1.5, 0.47)];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::precision::format_mean_sem;

    #[test]
    fn table_i_reads_back_as_printed() {
        let printed = |t: &str, a: f64, c: u64| {
            let e = table_i(t, a, c).unwrap();
            format_mean_sem(e.value, e.sem, TABLE_I_DECIMALS)
        };
        assert_eq!(printed("stadium:a=1", 0.1, 10_000), "0.281(0)");
        assert_eq!(printed("stadium:a=1", 1.0, 100_000), "0.146(1)");
        assert_eq!(printed("sinai:L=2,R=1", 0.5, 10_000), "0.120(0)");
        assert_eq!(printed("sinai:L=2,R=1", 1.0, 500_000), "0.102(0)");
        assert_eq!(table_i("stadium:a=1", 0.3, 10_000), None);
        assert_eq!(table_i("stadium:a=1", 0.5, 20_000), None);
        assert_eq!(table_i("circle:R=1", 0.5, 10_000), None);
    }

    #[test]
    fn lambda_curves_agree_with_table_i() {
        // The (α, λ) points taken from Table I are its 5·10⁵ column for the
        // stadium.
        for (alpha, lambda) in STADIUM_LAMBDA
            .iter()
            .filter(|(a, _)| *a != 0.0 && *a != 0.4)
        {
            let entry = table_i("stadium:a=1", *alpha, 500_000).unwrap();
            assert_eq!(entry.value, *lambda);
        }
        // Every Sinai point from Table I appears in some column.
        for (alpha, lambda) in [SINAI_LAMBDA[1], SINAI_LAMBDA[3], SINAI_LAMBDA[4]] {
            assert!(
                TABLE_I_COLLISIONS
                    .iter()
                    .any(|&c| table_i("sinai:L=2,R=1", alpha, c).unwrap().value == lambda)
            );
        }
        // λ falls with α in both tables, and the quoted shares rise with R.
        for curve in [STADIUM_LAMBDA, SINAI_LAMBDA] {
            assert!(curve.windows(2).all(|w| w[0].0 < w[1].0 && w[0].1 > w[1].1));
        }
        assert!(
            SINAI_CURVED_SHARE_BY_RADIUS
                .windows(2)
                .all(|w| w[0].0 < w[1].0 && w[0].1 < w[1].1)
        );
    }
}
